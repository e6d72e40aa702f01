#!/usr/bin/env bash
# Command-line behaviour: exit codes 0/2/3/4, messages, partial output on
# solver failure. Prints PASS/FAIL lines (counted by scripts/check.sh).
set -u
bin=${1:-build/ricochet}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
demo=cases/demo_sphere_drop.rad

expect() { # name, expected exit code, actual exit code, detail
    if [ "$2" -eq "$3" ]; then echo "PASS cli.$1: exit $3 $4"; else echo "FAIL cli.$1: expected exit $2, got $3 $4"; fi
}

"$bin" --help > "$tmp/h" 2>&1; expect help 0 $? ""
"$bin" --version > "$tmp/v" 2>&1; rc=$?
grep -q "^ricochet [0-9]" "$tmp/v" && expect version 0 $rc "($(cat "$tmp/v"))" || expect version 0 1 "(no version line)"
"$bin" frobnicate "$demo" > /dev/null 2>&1; expect bad_command 2 $? ""
"$bin" check "$demo" > "$tmp/c" 2>&1; rc=$?
grep -q "interfaces  1" "$tmp/c" && expect check_summary 0 $rc "" || expect check_summary 0 1 "(no summary)"

# input error: message names file:line, card and field; no output file written
sed 's/^         1                                                 1$/         1                                                -1/' "$demo" > "$tmp/bad.rad"
"$bin" run "$tmp/bad.rad" -o "$tmp/bad.nc" > "$tmp/e" 2>&1; rc=$?
if grep -q "bad.rad:[0-9]*:.*RBODY.*Mass" "$tmp/e" && [ ! -e "$tmp/bad.nc" ]; then expect input_error 2 $rc "($(head -c 160 "$tmp/e"))"
else expect input_error 2 99 "(message or output wrong: $(head -c 200 "$tmp/e"))"; fi

# several input errors: all reported (first one first), exit 2, nothing written
printf '/GRAV/1\ng\n         0         W\n/RUN\n                -1.0\n' > "$tmp/two.rad"
"$bin" run "$tmp/two.rad" -o "$tmp/two.nc" > "$tmp/e" 2>&1; rc=$?
if head -1 "$tmp/e" | grep -q "two.rad:3:.*GRAV.*DIR" && grep -q "two.rad:5:.*RUN.*Tend" "$tmp/e" && grep -q "2 input errors" "$tmp/e" &&
   [ ! -e "$tmp/two.nc" ]; then expect several_input_errors 2 $rc "($(tr '\n' '|' < "$tmp/e" | head -c 200))"
else expect several_input_errors 2 99 "(messages wrong: $(head -c 300 "$tmp/e"))"; fi

# a Radioss starter + engine pair: NAME_0000.rad reads NAME_0001.rad (said in a warning)
awk '/^\/RUN$/{getline; next} {print}' "$demo" > "$tmp/pair_0000.rad"
printf '#RADIOSS ENGINE\n/RUN/pair/1\n                 0.2\n/ANIM/DT\n0 0.01\n/TFILE/0\n1e-4\n/END\n' > "$tmp/pair_0001.rad"
"$bin" run "$tmp/pair_0000.rad" -o "$tmp/pair.nc" -q > "$tmp/e" 2>&1; rc=$?
if grep -q "pair_0001.rad:1: Radioss engine file read" "$tmp/e" && grep -q "Tend = Tstop = 0.2" "$tmp/e" &&
   [ "$(ncdump -h "$tmp/pair.nc" | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')" -ge 21 ]; then
    expect starter_engine_pair 0 $rc "(engine file read, Tend 0.2 s, Dt_out 0.01 s)"
else expect starter_engine_pair 0 99 "(exit $rc: $(head -c 300 "$tmp/e"))"; fi

"$bin" run "$tmp/missing.rad" > "$tmp/e" 2>&1; expect missing_case 4 $? "($(head -c 120 "$tmp/e"))"
"$bin" run "$demo" -o "$tmp/no/such/dir/out.nc" > "$tmp/e" 2>&1; expect unwritable_output 4 $? "($(head -c 120 "$tmp/e"))"

# the output path is the case file itself: refused, the deck untouched
cp "$demo" "$tmp/self.rad"
"$bin" run "$tmp/self.rad" -o "$tmp/self.rad" > "$tmp/e" 2>&1; rc=$?
if cmp -s "$demo" "$tmp/self.rad" && grep -q "refusing to overwrite" "$tmp/e"; then expect output_is_input 2 $rc "($(head -c 160 "$tmp/e"))"
else expect output_is_input 2 99 "(deck changed or no message: $(head -c 200 "$tmp/e"))"; fi

# solver failure: too few steps allowed; partial results kept, marked incomplete
awk '/^\/SOLVER/{print; getline; print "         1         5         5               1e-06"; next} {print}' "$demo" > "$tmp/fail.rad"
"$bin" run "$tmp/fail.rad" -o "$tmp/fail.nc" > "$tmp/e" 2>&1; rc=$?
if [ -e "$tmp/fail.nc" ] && ncdump -h "$tmp/fail.nc" | grep -q ':complete = "no"'; then expect solver_failure 3 $rc "(partial file kept, complete = no)"
else expect solver_failure 3 99 "(no partial file marked incomplete: $(head -c 200 "$tmp/e"))"; fi

# interrupted (SIGINT, SIGTERM): the run ends at the next step, keeps what it
# computed (records flushed, marked incomplete, statistics written), exit 130
awk '/^\/RUN/{print; getline; print "              100000                   1"; next} {print}' \
    validation/cpl_spring_cubic/case.rad > "$tmp/long.rad"
for sig in INT TERM; do
    # one signal, sent to the run alone (timeout(1) would also signal its
    # process group, and a second signal kills at once by design)
    "$bin" run "$tmp/long.rad" -o "$tmp/long_$sig.nc" -q > "$tmp/e" 2>&1 &
    pid=$!
    sleep 2
    kill -s $sig $pid
    wait $pid; rc=$?
    if [ -e "$tmp/long_$sig.nc" ] && ncdump -h "$tmp/long_$sig.nc" | grep -q ':complete = "no"' &&
       ncdump -h "$tmp/long_$sig.nc" | grep -q 'interrupted at t' && ncdump -h "$tmp/long_$sig.nc" | grep -q 'stats_steps' &&
       [ "$(ncdump -h "$tmp/long_$sig.nc" | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')" -gt 1 ] &&
       grep -q "interrupted" "$tmp/e"; then
        expect "interrupt_$sig" 130 $rc "(records kept, complete = no, statistics written: $(head -c 120 "$tmp/e"))"
    else expect "interrupt_$sig" 130 99 "(exit $rc; file or message wrong: $(head -c 200 "$tmp/e"))"; fi
done

# determinism: two runs give identical time series
"$bin" run "$demo" -o "$tmp/a.nc" -q && "$bin" run "$demo" -o "$tmp/b.nc" -q
if cmp -s <(ncdump -v body_position "$tmp/a.nc" | sed -n '/data:/,$p') <(ncdump -v body_position "$tmp/b.nc" | sed -n '/data:/,$p'); then
    echo "PASS cli.determinism: two runs of the demo give identical body_position"
else echo "FAIL cli.determinism: runs differ"; fi
