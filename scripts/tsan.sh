#!/usr/bin/env bash
# Run the ThreadSanitizer test program (make tsan): PASS/FAIL lines, counted
# by scripts/check.sh. Any ThreadSanitizer report is a failure, whatever the
# program's own checks say.
#   scripts/tsan.sh build-tsan/tsan_threads build-tsan/libricochet.a
set -u
bin=${1:-build-tsan/tsan_threads}
lib=${2:-build-tsan/libricochet.a}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0

# every netCDF function the library calls is wrapped by the test program
# (its calls are then visible to ThreadSanitizer, tests/tsan/threads.c)
used=$(nm -u "$lib" 2>/dev/null | awk '{print $NF}' | grep '^nc_' | grep -v '^nc_strerror$' | sort -u)
wrapped=$(sed -n 's/^WRAP([^,]*, *\(nc_[a-z_]*\),.*/\1/p' tests/tsan/threads.c | sort -u)
missing=$(comm -23 <(echo "$used") <(echo "$wrapped"))
if [ -z "$used" ]; then
    echo "FAIL tsan.wrapped: no netCDF symbol found in $lib"; fail=1
elif [ -n "$missing" ]; then
    echo "FAIL tsan.wrapped: netCDF functions the library calls without a wrapper in tests/tsan/threads.c:" $missing; fail=1
else
    echo "PASS tsan.wrapped: the $(echo "$used" | wc -l) netCDF functions the library calls are wrapped"
fi
TSAN_OPTIONS="halt_on_error=0 exitcode=66 second_deadlock_stack=1 history_size=4" \
    "$bin" cases/demo_sphere_drop.rad "$tmp" > "$tmp/out" 2> "$tmp/err"
rc=$?
cat "$tmp/out"
nrep=$(grep -c '^WARNING: ThreadSanitizer' "$tmp/err")
if [ "$rc" -eq 0 ] && [ "$nrep" -eq 0 ]; then
    echo "PASS tsan.clean: no ThreadSanitizer report"
else
    echo "FAIL tsan.clean: exit $rc, $nrep ThreadSanitizer reports; the first:"
    awk '/^WARNING: ThreadSanitizer/{p=1} p{print; if (++n > 40) exit}' "$tmp/err"
    grep -v '^HDF5-DIAG\|^  #\|^    ' "$tmp/err" | grep -v '^$' | head -5
fi
[ "$rc" -eq 0 ] && [ "$nrep" -eq 0 ] && [ "$fail" -eq 0 ]
