#!/usr/bin/env bash
# Benchmarks (bench/README.md): `make bench` runs `bash bench/run.sh build`.
# Builds the bench programs into BUILD (default build/) after `make all`,
# then runs bench/bench.py. Extra arguments go to bench.py
# (e.g. --only drop, --only quasi, --sizes 10,100, --quick).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
shift || true
CC=${CC:-cc}
PY=/usr/bin/python3   # Debian's python3 (numpy, scipy, netCDF4)

if [ ! -x "$BUILD/ricochet" ] || [ ! -f "$BUILD/libricochet.a" ]; then
    echo "bench: $BUILD/ricochet or $BUILD/libricochet.a missing: run 'make all' first" >&2
    exit 1
fi
mkdir -p "$BUILD/bench"
# the link libraries of ricochet, from the Makefile (one source of truth)
LDLIBS=$(printf 'bench-print-ldlibs:\n\t@echo $(LDLIBS)\n' |
         make --no-print-directory -s -f Makefile -f - bench-print-ldlibs)
CFLAGS_BENCH="-std=c11 -O2 -Wall -Wextra -pedantic"
set -x
$CC $CFLAGS_BENCH -o "$BUILD/explicit_ref" bench/explicit_ref.c -lm
$CC $CFLAGS_BENCH -o "$BUILD/peakrss" bench/peakrss.c
$CC $CFLAGS_BENCH -I/usr/include/suitesparse -o "$BUILD/cvode_ref" bench/cvode_ref.c \
    -lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixsparse -lsundials_sunlinsolklu -lklu -lm
$CC $CFLAGS_BENCH -Iinclude -o "$BUILD/rc_time" bench/rc_time.c "$BUILD/libricochet.a" $LDLIBS
{ set +x; } 2>/dev/null
exec "$PY" bench/bench.py --build "$BUILD" "$@"
