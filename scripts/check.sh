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

# command-line behaviour
bash tests/cli_test.sh "$build/ricochet" > "$log" 2>&1
cat "$log"
pass=$((pass + $(grep -c '^PASS ' "$log")))
fail=$((fail + $(grep -c '^FAIL ' "$log")))

# validation problems: each check.py prints PASS/FAIL lines
for chk in validation/*/check.py; do
    dir=$(dirname "$chk")
    if [ "$mode" = fast ] && [ -f "$dir/SLOW" ]; then continue; fi
    echo "== $dir"
    RICOCHET="$PWD/$build/ricochet" /usr/bin/python3 "$chk" --"$mode" > "$log" 2>&1
    status=$?
    cat "$log"
    p=$(grep -c '^PASS ' "$log")
    f=$(grep -c '^FAIL ' "$log")
    if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $dir: check script exited with status $status"
        f=1
    fi
    pass=$((pass + p))
    fail=$((fail + f))
done
rm -f "$log"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
