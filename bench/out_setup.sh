#!/usr/bin/env bash
# Output and set-up measurements (bench/README.md, "Output and set-up").
#   bash bench/out_setup.sh [BUILD] [SIZES]
# BUILD: build directory with ricochet and rc_time (default build; rc_time is
# built here from bench/rc_time.c when missing). SIZES: body counts for
# `ricochet check` (default "10000 100000"). Decks go to BUILD/bench/many/.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
SIZES=${2:-"10000 100000"}
PY=/usr/bin/python3
RC=$BUILD/ricochet
D=$BUILD/bench/many
mkdir -p "$D" out
if [ ! -x "$BUILD/rc_time" ]; then
    LDLIBS=$(printf 'p:\n\t@echo $(LDLIBS)\n' | make --no-print-directory -s -f Makefile -f - p)
    cc -std=c11 -O2 -Iinclude -o "$BUILD/rc_time" bench/rc_time.c "$BUILD/libricochet.a" $LDLIBS
fi
now() { date +%s.%N; }

echo "== demo: whole process against integration alone (best of 10)"
best=1e9
for _ in $(seq 10); do
    t0=$(now); "$RC" run cases/demo_sphere_drop.rad -o out/demo.nc -q; t1=$(now)
    best=$(echo "$t1 $t0 $best" | awk '{d = $1 - $2; print (d < $3 ? d : $3)}')
done
integ=$("$BUILD/rc_time" cases/demo_sphere_drop.rad 10 | sed -n 's/^wall_time=//p')
wall=$(ncdump -h out/demo.nc | sed -n 's/.*:stats_wall_time = \([0-9.e+-]*\).*/\1/p')
echo "process $best s, stats_wall_time (open + integration + records) $wall s, integration without output $integ s"
echo "ratio process / integration: $(echo "$best $integ" | awk '{printf "%.2f", $1 / $2}'), file $(stat -c %s out/demo.nc) bytes"

echo "== column of 1000 spheres over 0.2 s: file size"
$PY bench/gen_many.py 1000 "$D/col1000.rad" --tend 0.2
t0=$(now); "$RC" run "$D/col1000.rad" -o "$D/col1000.nc" -q || true; t1=$(now)
echo "wall $(echo "$t1 $t0" | awk '{printf "%.1f", $1 - $2}') s, file $(stat -c %s "$D/col1000.nc") bytes," \
     "events $(ncdump -h "$D/col1000.nc" | sed -n 's/.*event = UNLIMITED ; \/\/ (\([0-9]*\) currently)/\1/p')," \
     "records $(ncdump -h "$D/col1000.nc" | sed -n 's/.*time = UNLIMITED ; \/\/ (\([0-9]*\) currently)/\1/p')"

echo "== ricochet check: N spheres, each with a TYPE6 contact (and --no-contacts: the floor contact only)"
for n in $SIZES; do
    for opt in "" --no-contacts; do
        f="$D/n$n${opt:+_nc}.rad"
        [ -f "$f" ] || $PY bench/gen_many.py "$n" "$f" $opt
        t0=$(now); "$RC" check "$f" > "$f.check.txt"; t1=$(now)
        echo "N = $n ${opt:-(contacts)}: $(echo "$t1 $t0" | awk '{printf "%.2f", $1 - $2}') s, summary $(wc -l < "$f.check.txt") lines"
    done
done
