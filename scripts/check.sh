#!/usr/bin/env bash
# Run the unit tests and the validation problems; print one closing tally.
#   scripts/check.sh BUILD_DIR fast|all
set -u
build=${1:-build}
mode=${2:-fast}
pass=0
fail=0
log=$(mktemp)

# unit tests: the runner ends with "N passed, N failed"
"$build"/run_tests | tee "$log"
read -r up uf < <(tail -n 1 "$log" | sed -E 's/^([0-9]+) passed, ([0-9]+) failed$/\1 \2/')
pass=$((pass + ${up:-0}))
fail=$((fail + ${uf:-1}))

# layering: includes and calls between files follow the rules in the
# folders' README.md files, no call cycle (scripts/check-layers.py)
/usr/bin/python3 scripts/check-layers.py "$build" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))
grep -qE '^(PASS|FAIL) ' "$log" || { echo "FAIL layers: scripts/check-layers.py printed no verdict"; fail=$((fail + 1)); }

# command-line behaviour
bash tests/cli_test.sh "$build/ricochet" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# ricochet fit: a small fit, the report, the data file's input errors
# (tests/fit_test.sh)
bash tests/fit_test.sh "$build/ricochet" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# ricochet sens: derivatives against whole runs, the events, input errors
# (tests/sens_test.sh)
bash tests/sens_test.sh "$build/ricochet" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# animations of results files (scripts/animate.py): frames, exit codes
bash tests/animate_test.sh "$build/ricochet" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# malformed decks: exit 2 and a message naming file:line, card and field
bash tests/malformed_test.sh "$build/ricochet" > "$log" 2>&1
grep -E '^(PASS|FAIL) ' "$log" | grep -v '^PASS ' ; echo "malformed decks: $(grep -c '^PASS ' "$log") passed, $(grep -c '^FAIL ' "$log") failed"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))
[ "$(grep -c '^PASS ' "$log")" -gt 100 ] || { echo "FAIL malformed: the catalogue ran fewer than 100 decks"; fail=$((fail + 1)); }

# fuzz regressions (every crash or hang input the fuzzer found) and the
# seed corpus, replayed through the reader and compiler (fuzz/README.md)
if [ -x "$build"/fuzz_replay ]; then
    "$build"/fuzz_replay fuzz/regressions/* > "$log" 2>&1
    "$build"/fuzz_replay -q fuzz/corpus/* >> "$log" 2>&1
else echo "FAIL fuzz: $build/fuzz_replay is missing" > "$log"; fi
# field sweep, one variant in 50 (fuzz/sweep.py): hostile values in every field
if /usr/bin/python3 fuzz/sweep.py --every 50 --replay "$build"/fuzz_replay --out "$build"/sweep-failures > "$log.sweep" 2>&1; then
    echo "PASS fuzz.sweep: $(tail -n 1 "$log.sweep")" >> "$log"
else echo "FAIL fuzz.sweep: $(tail -n 1 "$log.sweep")" >> "$log"; fi
rm -f "$log.sweep"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))
cat "$log"

# ThreadSanitizer: the library built with -fsanitize=thread (build-tsan),
# two simulations in two threads writing two files and a session stepped
# from another thread; any report fails (make tsan, scripts/tsan.sh)
make --no-print-directory tsan > "$log" 2>&1
st=$?
grep -E '^(PASS|FAIL) ' "$log"
if [ "$(grep -c '^PASS ' "$log")" -eq 0 ] || { [ "$st" -ne 0 ] && [ "$(grep -c '^FAIL ' "$log")" -eq 0 ]; }; then
    echo "FAIL tsan.build: make tsan exited with status $st:"; grep -v '^HDF5-DIAG\|^  #\|^    ' "$log" | tail -n 30
    fail=$((fail + 1))
fi
# physics scene fuzzer (fuzz/physics/README.md): a fixed sample of seeded
# scenes and the regression decks, one line each, checked against the
# physical invariants. Tolerant while the engine fixes land:
# PHYSFUZZ_STRICT=0 (the default) prints a violating scene as XFAIL, which
# is not counted; PHYSFUZZ_STRICT=1 prints it as FAIL.
PHYSFUZZ_STRICT=${PHYSFUZZ_STRICT:-0} /usr/bin/python3 fuzz/physics/scenefuzz.py check --scenes 40 --seed 7 \
    --jobs 2 --timeout 20 --ricochet "$build/ricochet" --out "$build/physfuzz-check" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# installation: make install into a staging root, the embedding example
# built through pkg-config and run, the Python module as installed
bash tests/install_test.sh "$build" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# the Python module running simulations through this build's library
# (python/ricochet over $build/libricochet.so via RICOCHET_LIB: the ctypes
# structs, run, set=, errors, sessions, the event callback, threads, pip
# install, a study on a LocalCluster of 2 worker processes)
# py_suite NAME SCRIPT: a Python test script over this build's library
# (RICOCHET_LIB, the source tree's module), its PASS/FAIL/SKIP lines
# counted; a script that fails without a FAIL line counts as one
py_suite() {
    RICOCHET_LIB="$(cd "$build" && pwd)/libricochet.so" PYTHONPATH="$PWD/python" \
        timeout 300 /usr/bin/python3 "$2" "$build" > "$log" 2>&1
    local st=$?
    grep -E '^(PASS|FAIL|SKIP) ' "$log"
    pass=$((pass + $(grep -c '^PASS ' "$log")))
    fail=$((fail + $(grep -c '^FAIL ' "$log")))
    if [ "$st" -ne 0 ] && [ "$(grep -c '^FAIL ' "$log")" -eq 0 ]; then
        echo "FAIL $1: $2 exited with status $st:"; tail -n 20 "$log"
        fail=$((fail + 1))
    fi
}
py_suite pyrun tests/python_run_test.py
# ricochet.fit: the program's `ricochet fit` from Python (its JSON report)
py_suite pyfit tests/python_fit_test.py

# studies on a real Dask cluster: a scheduler and two worker processes
# started by the test (killed at its end), results against serial runs bit
# for bit, a worker killed mid-study, an interrupted study resumed from its
# study_dir (tests/python_study_test.py; SKIP without python3-distributed)
py_suite pystudy tests/python_study_test.py

# validation problems: each check.py prints PASS/FAIL lines; every problem
# runs twice, first with the solver settings of its decks, then at ricochet's
# default settings (RICOCHET_VAL_SOLVER=default: the /SOLVER cards removed,
# except in the convergence studies over rtol; check names prefixed "default:"),
# then once more on the IDA path (RICOCHET_VAL_METHOD=ida: ricochet run
# --method ida at the decks' settings; check names prefixed "ida:")
for solver in deck default ida; do
    method=""
    if [ "$solver" = default ]; then
        echo "==== validation at the default solver settings (/SOLVER removed)"
    elif [ "$solver" = ida ]; then
        echo "==== validation on the IDA path (--method ida)"
        method=ida
    else
        echo "==== validation at the decks' solver settings"
    fi
    for chk in validation/*/check.py; do
        dir=$(dirname "$chk")
        if [ "$mode" = fast ] && [ -f "$dir/SLOW" ]; then continue; fi
        case $solver in deck) echo "== $dir" ;; default) echo "== $dir (defaults)" ;; *) echo "== $dir ($solver)" ;; esac
        RICOCHET="$PWD/$build/ricochet" RICOCHET_VAL_SOLVER="$solver" RICOCHET_VAL_METHOD="$method" \
            /usr/bin/python3 "$chk" --"$mode" > "$log" 2>&1
        status=$?
        cat "$log"
        p=$(grep -c '^PASS ' "$log")
        f=$(grep -c '^FAIL ' "$log")
        if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
            if [ "$solver" = deck ]; then
                echo "FAIL $dir: check script exited with status $status"
            else
                echo "FAIL $solver:$dir: check script exited with status $status"
            fi
            f=1
        fi
        pass=$((pass + p))
        fail=$((fail + f))
    done
done
rm -f "$log"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
