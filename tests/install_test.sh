#!/usr/bin/env bash
# `make install` into a staging root (DESTDIR), then what a user of the
# installed ricochet does: build examples/embed.c through pkg-config against
# the shared and the static library, run it, and use the Python module.
# Prints PASS/FAIL lines (counted by scripts/check.sh).
#   tests/install_test.sh [BUILD_DIR]
set -u
build=${1:-build}
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
prefix=/usr/local
pass() { echo "PASS install.$1: $2"; }
fail() { echo "FAIL install.$1: $2"; }

if make --no-print-directory -s install BUILD="$build" PREFIX=$prefix DESTDIR="$stage" > "$stage.log" 2>&1; then
    pass make_install "DESTDIR staging root, PREFIX $prefix"
else fail make_install "$(tail -5 "$stage.log" | tr '\n' ' ')"; fi
rm -f "$stage.log"
root=$stage$prefix
pyver=$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')
pydir=lib/python$pyver/dist-packages
version=$(sed -n 's/^#define RICOCHET_VERSION "\(.*\)"/\1/p' include/ricochet/ricochet.h)
missing=""
for f in bin/ricochet include/ricochet/ricochet.h lib/libricochet.a "lib/libricochet.so.$version" "lib/libricochet.so.${version%%.*}" \
         lib/libricochet.so lib/pkgconfig/ricochet.pc $pydir/ricochet/__init__.py \
         $pydir/ricochet/deck.py $pydir/ricochet/results.py $pydir/ricochet/_lib.py $pydir/ricochet/sim.py \
         $pydir/ricochet/errors.py $pydir/ricochet/study.py $pydir/ricochet/__main__.py; do
    [ -e "$root/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] && pass files "bin, header, libricochet.a, libricochet.so.$version (+ soname link), ricochet.pc, python module in $pydir" ||
    fail files "missing:$missing"

# pkg-config as for an installed library; the sysroot maps the staged paths
export PKG_CONFIG_PATH=$root/lib/pkgconfig PKG_CONFIG_SYSROOT_DIR=$stage
flags=$(pkg-config --cflags --libs ricochet 2>&1); rc=$?
if [ $rc -eq 0 ] && [ "$(pkg-config --modversion ricochet)" = "$version" ] && echo "$flags" | grep -q -- "-lricochet"; then
    pass pkg_config "$flags (version $(pkg-config --modversion ricochet))"
else fail pkg_config "exit $rc: $flags"; fi
static=$(pkg-config --static --libs ricochet 2>&1)
ok=1
for lib in -lsundials_cvodes -lsundials_sunlinsolklu -lklu -lgsl -lnetcdf; do
    echo "$static" | grep -q -- "$lib" || { fail pkg_config_static "no $lib in: $static"; ok=0; }
done
[ $ok = 1 ] && pass pkg_config_static "Libs.private: $static"

# the embedding example, against the shared library
want_first="impact 1 at t = 0.142784 s on /INTER/TYPE6/1, approach speed 1.4007 m/s"
want_last="7 impacts, 21 events, simulated 1 s (ricochet $version)"
# shellcheck disable=SC2086
if cc -std=c11 -Wall -Wextra -pedantic -Werror examples/embed.c $(pkg-config --cflags --libs ricochet) -o "$stage/embed" 2> "$stage/cc.log"; then
    LD_LIBRARY_PATH=$root/lib "$stage/embed" cases/demo_sphere_drop.rad "$stage/embed.nc" > "$stage/out" 2>&1; rc=$?
    if [ $rc -eq 0 ] && grep -qxF "$want_first" "$stage/out" && [ "$(tail -1 "$stage/out")" = "$want_last" ] &&
       [ "$(grep -c '^impact ' "$stage/out")" -eq 7 ] && [ "$(grep -c '^t = ' "$stage/out")" -eq 10 ] &&
       LD_LIBRARY_PATH=$root/lib ldd "$stage/embed" | grep -q "libricochet.so.${version%%.*} => $root/lib/"; then
        pass embed_shared "$(tail -1 "$stage/out"); linked to $root/lib/libricochet.so.${version%%.*}"
    else fail embed_shared "exit $rc: $(head -c 300 "$stage/out")"; fi
    # the same events as the command line's events table
    if [ "$(ncdump -h "$stage/embed.nc" | sed -n 's/^[[:space:]]*event = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')" = 21 ]; then
        pass embed_events_table "21 rows, as the callbacks"
    else fail embed_events_table "$(ncdump -h "$stage/embed.nc" | grep 'event = ')"; fi
else fail embed_shared "compile: $(head -c 300 "$stage/cc.log")"; fi
# and statically
# shellcheck disable=SC2086
if cc -std=c11 examples/embed.c $(pkg-config --cflags ricochet) "$root/lib/libricochet.a" \
       $(pkg-config --static --libs ricochet | sed 's/-lricochet//') -o "$stage/embed_static" 2> "$stage/cc.log" &&
   "$stage/embed_static" cases/demo_sphere_drop.rad > "$stage/out_static" 2>&1 && cmp -s "$stage/out" "$stage/out_static"; then
    pass embed_static "same output from libricochet.a"
else fail embed_static "$(head -c 300 "$stage/cc.log") $(head -c 200 "$stage/out_static" 2>/dev/null)"; fi

# the Python module, as installed
# the module's directory for PREFIX /usr/local is on Debian python3's path
if /usr/bin/python3 -c "import sys; sys.exit('$prefix/$pydir' not in sys.path)"; then
    pass python_path "$prefix/$pydir is on /usr/bin/python3's sys.path"
else fail python_path "$prefix/$pydir is not on /usr/bin/python3's sys.path"; fi
PYTHONPATH=$root/$pydir /usr/bin/python3 tests/python_test.py "$root/bin/ricochet" > "$stage/py" 2>&1; rc=$?
cat "$stage/py"
grep -q "^PASS python.module_location: $root/$pydir/ricochet/__init__.py" "$stage/py" &&
    pass python_installed "imported from the staged install" || fail python_installed "exit $rc, not imported from $root"

# the installed module runs a simulation with the installed library, found
# next to it (<prefix>/lib) without RICOCHET_LIB
if ldconfig -p 2>/dev/null | grep -q 'libricochet\.so\.0 '; then
    echo "SKIP install.python_run: a libricochet.so.0 is installed system-wide (the loader would find it first)"
else
    demo=$PWD/cases/demo_sphere_drop.rad
    out=$(cd "$stage" && env -u RICOCHET_LIB PYTHONPATH=$root/$pydir /usr/bin/python3 -c '
import math, ricochet, sys
ds = ricochet.run(sys.argv[1], t_end=0.2)
t = float(ds.impact_close_time[0])
print(ricochet.library_path(), t, abs(t - math.sqrt(2 * 0.1 / 9.81)) < 1e-6)' "$demo" 2>&1)
    case $out in
        "$root/lib/libricochet.so.0 (the prefix the module is installed in) "*" True")
            pass python_run "ricochet.run with the staged library: $out" ;;
        *) fail python_run "$out" ;;
    esac
fi

# uninstall removes every file install wrote
make --no-print-directory -s uninstall BUILD="$build" PREFIX=$prefix DESTDIR="$stage" > /dev/null 2>&1
left=$(find "$stage" \( -type f -o -type l \) ! -path "$stage/embed*" ! -path "$stage/out*" ! -path "$stage/py" ! -path "$stage/cc.log" \
       ! -name '*.pyc' | sed "s|^$stage||")
[ -z "$left" ] && pass uninstall "nothing left of the install" || fail uninstall "left: $(echo $left)"
