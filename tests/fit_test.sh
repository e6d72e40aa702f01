#!/usr/bin/env bash
# `ricochet fit` (docs/calibration.md): a small fit end to end, the report
# and the fitted-signals file; input errors of the data file (file:line,
# what was expected) and of the options: exit 2, nothing run or written.
# Prints PASS/FAIL lines (counted by scripts/check.sh).
set -u
bin=${1:-build/ricochet}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
slide=validation/fit_drop/slide.rad
free=/INTER/TYPE6/1:Fric=0.1,0:1

expect() { # name, expected exit code, actual exit code, detail
    if [ "$2" -eq "$3" ]; then echo "PASS fit.$1: exit $3 $4"; else echo "FAIL fit.$1: expected exit $2, got $3 $4"; fi
}

"$bin" --help | grep -q "ricochet fit CASE --data FILE.csv --free" && echo "PASS fit.usage_line: in ricochet --help" ||
    echo "FAIL fit.usage_line: ricochet --help does not list fit"
"$bin" fit --help > "$tmp/h" 2>&1; rc=$?
grep -q "^usage: ricochet fit CASE --data FILE.csv" "$tmp/h" && expect help 0 $rc "" || expect help 0 99 "(no usage)"

# measurements of the slide at mu = 0.3 (no noise), every 20 ms, in ms and mm
"$bin" run "$slide" -o "$tmp/truth.nc" -q --dt-out 0.02 --set /INTER/TYPE6/1:Fric=0.3 > /dev/null 2>&1
/usr/bin/python3 - "$tmp/truth.nc" "$tmp/slide.csv" <<'PY'
import sys, numpy as np
from netCDF4 import Dataset
with Dataset(sys.argv[1]) as nc:
    keep = np.array(nc["at_event"][:]) == 0
    t, x = np.array(nc["time"][:])[keep], np.array(nc["body_position"][:])[keep, 0, 0]
with open(sys.argv[2], "w") as f:
    f.write("# a comment line\nt [ms], body 1 x [mm], body 1 vx [m/s]\n")
    for k, (ti, xi) in enumerate(zip(t, x)):
        f.write(f"{ti * 1e3:.12g}, {xi * 1e3:.12g}, {'' if k % 3 else '%.12g' % (1.0 - 0.3 * 9.81 * min(ti, 1 / 2.943))}\n")
PY
(cd "$tmp" && "$OLDPWD/$bin" fit "$OLDPWD/$slide" --data slide.csv --free $free -o report.txt -q > out.txt 2> err.txt); rc=$?
if grep -q "status: converged" "$tmp/out.txt" && grep -qE "fitted 0\.(3 |2999999|3000000)" "$tmp/out.txt" && cmp -s "$tmp/out.txt" <(cat "$tmp/report.txt"; echo "measured against fitted signals: slide_fit.csv") &&
   [ -s "$tmp/slide_fit.csv" ] && head -1 "$tmp/slide_fit.csv" | grep -q "^t \[ms\], measured body 1 x \[mm\], fitted body 1 x \[mm\], measured body 1 vx \[m/s\], fitted body 1 vx \[m/s\]$" &&
   grep -qE "the deck with the fitted values: ricochet run .*--set /INTER/TYPE6/1:Fric=0\.(3$|2999999|3000000)" "$tmp/out.txt"; then
    expect slide 0 $rc "($(grep -m1 "fitted" "$tmp/out.txt" | sed 's/^ *//'); $(grep -o '^cost: [0-9]* iterations' "$tmp/out.txt"))"
else expect slide 0 99 "(exit $rc: $(head -c 600 "$tmp/out.txt") $(head -c 300 "$tmp/err.txt"))"; fi
# the same fit again: the same report (the threads' results are placed by
# column, not by arrival), but for the wall times
(cd "$tmp" && "$OLDPWD/$bin" fit "$OLDPWD/$slide" --data slide.csv --free $free -q --jobs 3 --fitted f2.csv > out2.txt 2>&1)
if diff <(grep -v '^cost:' "$tmp/out.txt" | sed 's/slide_fit.csv/X/') <(grep -v '^cost:' "$tmp/out2.txt" | sed 's/f2.csv/X/') > /dev/null &&
    cmp -s "$tmp/slide_fit.csv" "$tmp/f2.csv"; then echo "PASS fit.deterministic: the same report and fitted signals with 3 threads"
else echo "FAIL fit.deterministic: $(diff "$tmp/out.txt" "$tmp/out2.txt" | head -c 300)"; fi
# the plot of measured against fitted signals (scripts/plot_fit.py)
if /usr/bin/python3 -c 'import matplotlib' 2>/dev/null; then
    /usr/bin/python3 scripts/plot_fit.py "$tmp/slide_fit.csv" -o "$tmp/slide_fit.png" > "$tmp/p" 2>&1; rc=$?
    if [ "$rc" -eq 0 ] && [ "$(head -c 4 "$tmp/slide_fit.png" | od -An -c | tr -d ' ')" = "211PNG" ]; then
        echo "PASS fit.plot: scripts/plot_fit.py wrote a PNG of the two signals"
    else echo "FAIL fit.plot: exit $rc: $(head -c 200 "$tmp/p")"; fi
else echo "SKIP fit.plot: python3-matplotlib not installed"; fi
# a blank cell is no measurement: 26 times, 26 + 9 values
grep -q "26 times from 0 to 0.5 s, 2 signals, 35 measured values" "$tmp/out.txt" && echo "PASS fit.blank_cells: blank cells not measured (35 values)" ||
    echo "FAIL fit.blank_cells: $(grep -m1 '^data:' "$tmp/out.txt")"
# not converged within --max-iter: exit 1, the report still written
"$bin" fit "$slide" --data "$tmp/slide.csv" --free $free --max-iter 1 -q --fitted "$tmp/f1.csv" > "$tmp/o" 2>&1; rc=$?
grep -q "NOT CONVERGED within 1 iterations" "$tmp/o" && expect not_converged 1 $rc "" || expect not_converged 1 99 "($(head -c 300 "$tmp/o"))"

# a parameter pushed to its bound (mu = 0.3 measured, kept below 0.1): UNIDENTIFIABLE, no number
"$bin" fit "$slide" --data "$tmp/slide.csv" --free /INTER/TYPE6/1:Fric=0.05,0:0.1 -q --fitted "$tmp/fb.csv" > "$tmp/o" 2>&1; rc=$?
grep -q "UNIDENTIFIABLE: at its bound HI = 0.1 " "$tmp/o" && ! grep -q -- "--set /INTER/TYPE6/1:Fric" "$tmp/o" &&
    expect at_bound 0 $rc "($(grep -m1 UNIDENTIFIABLE "$tmp/o" | sed 's/^ *//'))" || expect at_bound 0 99 "(exit $rc: $(head -c 400 "$tmp/o"))"

# input errors: exit 2, the message, nothing written
bad() { # name, expected message (grep -E), the data file's text, extra options...
    local name=$1 msg=$2 text=$3
    shift 3
    printf "%b" "$text" > "$tmp/bad.csv"
    rm -f "$tmp/bad_fit.csv"
    "$bin" fit "$slide" --data "$tmp/bad.csv" --fitted "$tmp/bad_fit.csv" -q "$@" > "$tmp/o" 2>&1
    local rc=$?
    if grep -qE -- "$msg" "$tmp/o" && [ ! -e "$tmp/bad_fit.csv" ]; then expect "$name" 2 $rc "($(head -1 "$tmp/o"))"
    else expect "$name" 2 99 "(exit $rc: $(head -c 300 "$tmp/o"))"; fi
}
ok='t [s], body 1 x [m]\n0, 0\n0.1, 0.08\n0.2, 0.14\n'
bad csv_no_unit "bad.csv:1: column 1: expected the time column 't \[s\]'" 't, body 1 x [m]\n0, 0\n' --free $free
bad csv_time_unit "bad.csv:2: column 1: expected the unit s or ms, got \[h\]" '# c\nt [h], body 1 x [m]\n0, 0\n' --free $free
bad csv_signal "bad.csv:1: column 2: expected 'body ID Q \[UNIT\]'" 't [s], ball x [m]\n0, 0\n' --free $free
bad csv_quantity "bad.csv:1: column 2: quantity 'w': expected one of x, y, z" 't [s], body 1 w [m]\n0, 0\n' --free $free
bad csv_unit "bad.csv:1: column 3: expected the unit m/s or mm/s, got \[m\]" 't [s], body 1 x [m], body 1 vx [m]\n0, 0, 0\n' --free $free
bad csv_twice "bad.csv:1: column 3: body 1 x measured twice" 't [s], body 1 x [m], body 1 x [mm]\n0, 0, 0\n' --free $free
bad csv_number "bad.csv:3: column 2 \(body 1 x \[m\]\): expected a number \[m\] or a blank cell, got '0.1q'" 't [s], body 1 x [m]\n0, 0\n0.1, 0.1q\n' --free $free
bad csv_cells "bad.csv:3: expected 2 values \(the time and 1 signal, as the header\), got 3" 't [s], body 1 x [m]\n0, 0\n0.1, 0.1, 3\n' --free $free
bad csv_time_order "bad.csv:4: column 1 \(time\): expected times increasing, got 0.1 after 0.1 s" 't [s], body 1 x [m]\n0, 0\n0.1, 0.1\n0.1, 0.2\n' --free $free
bad csv_negative_time "bad.csv:2: column 1 \(time\): expected a number >= 0" 't [s], body 1 x [m]\n-1, 0\n' --free $free
bad csv_empty "bad.csv:1: expected a header and at least one row of values, got no row" 't [s], body 1 x [m]\n' --free $free
bad csv_body "bad.csv: column 2 \(body 7 x \[m\]\): the deck has no /RBODY/7" 't [s], body 7 x [m]\n0, 0\n0.1, 0.1\n' --free $free
bad too_few_values "2 measured values for 2 free parameters" 't [s], body 1 x [m]\n0, 0\n0.1, 0.1\n' --free $free --free /INTER/TYPE6/1:Sfric=1
bad free_syntax "--free /INTER/TYPE6/1:Fric: expected CARD:FIELD=START" "$ok" --free /INTER/TYPE6/1:Fric
bad free_bounds "expected START strictly inside \(LO, HI\) = \(0, 1\), got 2" "$ok" --free /INTER/TYPE6/1:Fric=2,0:1
bad free_order "bounds: expected LO < HI, got 1:0" "$ok" --free /INTER/TYPE6/1:Fric=0.5,1:0
bad log_positive "a log-scaled parameter needs START > 0" "$ok" --log /INTER/TYPE6/1:Fric=0
bad free_field "--set /INTER/TYPE6/1:Frc=0.1: card /INTER/TYPE6/1: no numeric field Frc: did you mean Fric" "$ok" --free /INTER/TYPE6/1:Frc=0.1
bad free_twice "/INTER/TYPE6/1:Fric is already free" "$ok" --free $free --free /inter/type6/1:fric=0.2
bad no_free "missing --free" "$ok"
bad bad_option "unknown option '--frees'" "$ok" --frees $free
bad bad_rtol "--rtol: expected a number in \(0, 1\), got '2'" "$ok" --free $free --rtol 2
# uncertainties in the header, the impacts file
bad csv_sigma "bad.csv:1: column 2: expected '\+- SIGMA' after the unit" 't [s], body 1 x [m] +- -1\n0, 0\n' --free $free
bad csv_sigma_some "bad.csv:1: column 3: has no uncertainty '\+- SIGMA' while column 2 has one" 't [s], body 1 x [m] +- 0.001, body 1 vx [m/s]\n0, 0, 1\n' --free $free
okw='t [s], body 1 x [m] +- 0.001\n0, 0\n0.1, 0.08\n0.2, 0.14\n'
imp() { printf "%b" "$1" > "$tmp/imp.csv"; }
imp 'inter, impact, quantity, value, sigma\n1, 1, v_out [m/s], 1, 0.1\n'
bad impacts_need_sigma "--impacts: expected the signals' uncertainties in the header" "$ok" --free $free --impacts "$tmp/imp.csv"
imp 'inter, impact, what, value, sigma\n'
bad impacts_header "imp.csv:1: expected the header 'inter, impact, quantity, value, sigma'" "$okw" --free $free --impacts "$tmp/imp.csv"
imp '# c\ninter, impact, quantity, value, sigma\n1, 1, speed [m/s], 1, 0.1\n'
bad impacts_quantity "imp.csv:3: quantity: expected 'NAME \[UNIT\]', NAME one of t_close, duration" "$okw" --free $free --impacts "$tmp/imp.csv"
imp 'inter, impact, quantity, value, sigma\n1, 1, fn_max [lbf], 1, 0.1\n'
bad impacts_unit "imp.csv:2: quantity fn_max: expected the unit N or kN, got \[lbf\]" "$okw" --free $free --impacts "$tmp/imp.csv"
imp 'inter, impact, quantity, value, sigma\n1, 6, v_out [m/s], 1, 0.1\n'
bad impacts_number "imp.csv:2: expected an /INTER id .* at most 5" "$okw" --free $free --impacts "$tmp/imp.csv"
imp 'inter, impact, quantity, value, sigma\n1, 1, v_out [m/s], 1, 0\n'
bad impacts_sigma "imp.csv:2: expected the measured value and its standard uncertainty sigma > 0 \[m/s\]" "$okw" --free $free --impacts "$tmp/imp.csv"
imp 'inter, impact, quantity, value, sigma\n1, 1, v_out [m/s], 1, 0.1\n1, 1, v_out [mm/s], 1000, 100\n'
bad impacts_twice "imp.csv:3: inter 1 impact 1 v_out measured twice" "$okw" --free $free --impacts "$tmp/imp.csv"
# a slide has no impact: the start simulation fails, exit 3, saying why
imp 'inter, impact, quantity, value, sigma\n1, 1, v_out [m/s], 1, 0.1\n'
printf "%b" "$okw" > "$tmp/okw.csv"
"$bin" fit "$slide" --data "$tmp/okw.csv" --impacts "$tmp/imp.csv" --free $free -q --fitted "$tmp/x.csv" > "$tmp/o" 2>&1; rc=$?
grep -q "inter 1 impact 1 v_out \[m/s\]: no such impact" "$tmp/o" && expect impacts_missing 3 $rc "($(head -c 200 "$tmp/o"))" ||
    expect impacts_missing 3 99 "(exit $rc: $(head -c 300 "$tmp/o"))"
bad output_is_input "--fitted .*bad.csv: expected an output file, got the data file" "$ok" --free $free --fitted "$tmp/bad.csv"
"$bin" fit "$slide" --data "$tmp/none.csv" --free $free -q > "$tmp/o" 2>&1; rc=$?
grep -q "none.csv: cannot open the data file" "$tmp/o" && expect missing_data 4 $rc "($(head -1 "$tmp/o"))" || expect missing_data 4 99 "($(head -c 200 "$tmp/o"))"
