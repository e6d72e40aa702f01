#!/usr/bin/env bash
# Command-line behaviour: exit codes 0/2/3/4, messages, partial output on
# solver failure. Prints PASS/FAIL lines (counted by scripts/check.sh).
set -u
bin=${1:-build/ricochet}
tmp=$(mktemp -d)
# RICOCHET_DELAY: seconds a run is given before it is interrupted or its
# disk filled (1; more under valgrind, whose start takes seconds)
delay=${RICOCHET_DELAY:-1}
# RICOCHET_WRAP: a command to run the program under (valgrind, for the
# failure paths); exec keeps the process id, so the signal tests still work
if [ -n "${RICOCHET_WRAP:-}" ]; then
    real=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
    printf '#!/bin/sh\nexec %s %s "$@"\n' "$RICOCHET_WRAP" "$real" > "$tmp/wrapped"
    chmod +x "$tmp/wrapped"
    bin=$tmp/wrapped
fi
trap 'umount "$tmp/fs" 2>/dev/null; rm -rf "$tmp"' EXIT
demo=cases/demo_sphere_drop.rad

expect() { # name, expected exit code, actual exit code, detail
    if [ "$2" -eq "$3" ]; then echo "PASS cli.$1: exit $3 $4"; else echo "FAIL cli.$1: expected exit $2, got $3 $4"; fi
}

"$bin" --help > "$tmp/h" 2>&1; expect help 0 $? ""
"$bin" --version > "$tmp/v" 2>&1; rc=$?
if grep -q "^ricochet [0-9][0-9.]* (commit [0-9a-z.+-]*)$" "$tmp/v" && grep -q "^SUNDIALS [0-9]" "$tmp/v" && grep -q "^KLU [0-9]" "$tmp/v" &&
   grep -q "^GSL [0-9]" "$tmp/v" && grep -q "^netCDF [0-9]" "$tmp/v"; then expect version 0 $rc "($(tr '\n' '|' < "$tmp/v"))"
else expect version 0 99 "(version lines wrong: $(tr '\n' '|' < "$tmp/v"))"; fi
"$bin" frobnicate "$demo" > "$tmp/e" 2>&1; rc=$?
grep -q "^ricochet: unknown command 'frobnicate'$" "$tmp/e" && expect bad_command 2 $rc "($(head -1 "$tmp/e"))" ||
    expect bad_command 2 99 "(no message naming the command: $(head -c 120 "$tmp/e"))"
for c in run check; do
    "$bin" $c --help > "$tmp/h" 2>&1; rc=$?
    grep -q "^usage: ricochet $c CASE" "$tmp/h" && expect "${c}_help" 0 $rc "" || expect "${c}_help" 0 99 "(no usage of $c)"
done
grep -q -- "--rtol R" "$tmp/h" && echo "FAIL cli.check_help_options: check lists run's options" || true
"$bin" run --help | grep -q -- "--t-end T" && "$bin" run --help | grep -q -- "--dt-out DT" && "$bin" run --help | grep -q -- "--rtol R" &&
    echo "PASS cli.run_help_options: --t-end, --dt-out, --rtol listed" || echo "FAIL cli.run_help_options: options missing"

# overrides of the end time, output interval and relative tolerance
"$bin" run "$demo" -o "$tmp/ov.nc" --t-end 0.25 --dt-out=0.01 --rtol 1e-7 > "$tmp/o" 2>"$tmp/e"; rc=$?
nrec=$(ncdump -h "$tmp/ov.nc" 2>/dev/null | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')
last=$(ncdump -v time "$tmp/ov.nc" 2>/dev/null | sed -n '/^ time =/,/;/p' | tr -d ' ;\n' | awk -F, '{print $NF}')
# (26 output records, the event records, and about 20 records inside each
# contact: Dt_out = 10 ms cannot resolve the 3 ms contacts)
if grep -q "simulated 0.25 s" "$tmp/o" && ncdump -h "$tmp/ov.nc" | grep -q ":rtol = 1.e-07 ;" && [ "${nrec:-0}" -ge 26 ] &&
   [ "${nrec:-0}" -le 90 ] && [ "$last" = "0.25" ]; then
    expect overrides 0 $rc "(simulated 0.25 s, $nrec records, last at $last s, rtol 1e-07 in the file)"
else expect overrides 0 99 "(exit $rc, records ${nrec:-none}, last ${last:-none}: $(head -c 200 "$tmp/o") $(head -c 200 "$tmp/e"))"; fi
for bad in "--t-end -1" "--t-end abc" "--dt-out 0" "--dt-out inf" "--rtol nan" "--rtol 1e-3x" "--rtol 2" "--t-end"; do
    # shellcheck disable=SC2086
    "$bin" run "$demo" -o "$tmp/bad_ov.nc" $bad > "$tmp/e" 2>&1; rc=$?
    name=$(echo "$bad" | tr -c 'a-z0-9\n' '_')
    if grep -q "^ricochet: ${bad%% *}: expected a" "$tmp/e" && [ ! -e "$tmp/bad_ov.nc" ]; then expect "bad_override$name" 2 $rc "($(head -1 "$tmp/e"))"
    else expect "bad_override$name" 2 99 "(exit $rc: $(head -c 160 "$tmp/e"))"; fi
done
# --set CARD:FIELD=VALUE: fields set by name, read as deck input before the
# compile; recorded in the results file; a bad one is exit 2, nothing written
"$bin" run --help | grep -q -- "--set CARD:FIELD=VALUE" && "$bin" check --help | grep -q -- "--set CARD:FIELD=VALUE" &&
    echo "PASS cli.set_help: --set listed by run and check" || echo "FAIL cli.set_help: --set missing from a usage"
"$bin" check "$demo" -q --set /RBODY/1:Mass=1.4837 --set=/inter/type6/1:fric=0.3719 > "$tmp/o" 2>"$tmp/e"; rc=$?
if grep -q "/RBODY/1 *mass 1.4837 " "$tmp/o" && grep -q "/INTER/TYPE6/1 .*Fric 0.3719," "$tmp/o"; then
    expect set_check 0 $rc "(mass 1.4837, Fric 0.3719 in the summary)"
else expect set_check 0 99 "(exit $rc: $(grep -i 'mass\|fric' "$tmp/o" | head -c 200) $(head -c 200 "$tmp/e"))"; fi
"$bin" run "$demo" -q -o "$tmp/set.nc" --t-end 0.05 --set /RBODY/1:Mass=1.4837 --set /INTER/TYPE6/1:Fric=0.3719 > "$tmp/o" 2>"$tmp/e"; rc=$?
if ncdump -h "$tmp/set.nc" 2>/dev/null | grep -q ':overrides = "/RBODY/1:Mass=1.4837; /INTER/TYPE6/1:Fric=0.3719" ;'; then
    expect set_run 0 $rc "(overrides attribute in the results file)"
else expect set_run 0 99 "(exit $rc: $(ncdump -h "$tmp/set.nc" 2>&1 | grep overrides) $(head -c 200 "$tmp/e"))"; fi
"$bin" run "$demo" -q -o "$tmp/noset.nc" --t-end 0.01 > /dev/null 2>&1
ncdump -h "$tmp/noset.nc" 2>/dev/null | grep -q ":overrides" && echo "FAIL cli.set_none: overrides attribute without --set" ||
    echo "PASS cli.set_none: no overrides attribute without --set"
"$bin" run "$demo" -o "$tmp/bad_set.nc" --set /INTER/TYPE6/1:Fric=abc > "$tmp/e" 2>&1; rc=$?
if grep -qx 'ricochet: input error: --set /INTER/TYPE6/1:Fric=abc: card /INTER/TYPE6/1, field Fric: expected a finite real number, got "abc"' "$tmp/e" &&
   [ ! -e "$tmp/bad_set.nc" ]; then expect set_bad_value 2 $rc "($(head -1 "$tmp/e"))"
else expect set_bad_value 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"; fi
for bad in "/RBODY/9:Mass=1|no card /RBODY/9 in the deck" "/RBODY/1:Mas=1|no numeric field Mas: did you mean Mass?" \
           "/GRAV/1:DIR=X|a text field" "/RBODY/1:Mass|expected /KEYWORD"; do
    "$bin" check "$demo" --set "${bad%%|*}" > "$tmp/e" 2>&1; rc=$?
    name=$(echo "${bad%%|*}" | tr -c 'A-Za-z0-9\n' '_')
    grep -q "^ricochet: input error: --set ${bad%%|*}: .*${bad#*|}" "$tmp/e" && expect "set_error$name" 2 $rc "($(head -1 "$tmp/e"))" ||
        expect "set_error$name" 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
done
"$bin" check "$demo" --set /RBODY/1:Mass=2 --set /RBODY/1:MASS=3 > "$tmp/e" 2>&1; rc=$?
grep -q "^ricochet: input error: --set /RBODY/1:MASS=3: card /RBODY/1, field MASS: set twice (also by --set /RBODY/1:Mass=2)" "$tmp/e" &&
    expect set_twice 2 $rc "($(head -1 "$tmp/e"))" || expect set_twice 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
"$bin" check "$demo" --set > "$tmp/e" 2>&1; rc=$?
grep -q "^ricochet: --set: expected CARD:FIELD=VALUE" "$tmp/e" && expect set_missing 2 $rc "" || expect set_missing 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
# the integration backend: --method ida runs the demo on IDA (the file says
# so, the same impacts happen); a bad name and cvode on a model with joints
# are input errors
"$bin" run "$demo" -o "$tmp/ida.nc" --method ida > "$tmp/o" 2>"$tmp/e"; rc=$?
if ncdump -h "$tmp/ida.nc" 2>/dev/null | grep -q ':solver = "IDA BDF' && grep -q "simulated 1 s in" "$tmp/o" &&
   grep -q "^impacts [1-9]" "$tmp/o"; then expect method_ida 0 $rc "($(grep -o 'impacts [0-9]*' "$tmp/o") on IDA)"
else expect method_ida 0 99 "(exit $rc: $(head -c 200 "$tmp/o") $(head -c 200 "$tmp/e"))"; fi
"$bin" run "$demo" -o "$tmp/bad_m.nc" --method rk4 > "$tmp/e" 2>&1; rc=$?
grep -q "^ricochet: --method: expected cvode, ida or static" "$tmp/e" && [ ! -e "$tmp/bad_m.nc" ] &&
    expect bad_method 2 $rc "($(head -1 "$tmp/e"))" || expect bad_method 2 99 "(exit $rc: $(head -c 160 "$tmp/e"))"
# the static analysis (/SOLVER Method 3): --method static runs an equilibrium
# deck; a deck outside its scope is refused at the card, exit 2, nothing written
"$bin" run validation/stack10_rest/case.rad -o "$tmp/st.nc" --method static --t-end 0.5 --dt-out 0.25 > "$tmp/e" 2>&1; rc=$?
if [ $rc -ne 0 ] && grep -q "no support" "$tmp/e" && grep -q "/RBODY/" "$tmp/e"; then
    expect static_singular 3 $rc "($(head -c 200 "$tmp/e"))"
else expect static_singular 3 99 "(exit $rc: $(head -c 200 "$tmp/e"))"; fi
"$bin" run validation/static_column/case.rad -o "$tmp/sc.nc" -q --method static > "$tmp/e" 2>&1; rc=$?
[ -s "$tmp/sc.nc" ] && expect method_static 0 $rc "" || expect method_static 0 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
# friction in statics: the stick spring of TYPE6 Fric (the block on its
# incline sticks, tan(theta) = 0.27 < mu = 0.3); a law with a speed (Renard)
# is taken at rest (mu_s); viscous friction (F = -C v_t, zero at rest) is
# refused
"$bin" run validation/fric_incline/case.rad -o "$tmp/sf.nc" --method static > "$tmp/e" 2>&1; rc=$?
[ -s "$tmp/sf.nc" ] && expect static_friction_sticks 0 $rc "" ||
    expect static_friction_sticks 0 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
"$bin" run validation/frc_renard_decel/case.rad -o "$tmp/sr.nc" --method static > "$tmp/e" 2>&1; rc=$?
[ -s "$tmp/sr.nc" ] && expect static_friction_at_rest 0 $rc "" ||
    expect static_friction_at_rest 0 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
"$bin" run validation/seg_box_viscous/case.rad -o "$tmp/sv.nc" --method static > "$tmp/e" 2>&1; rc=$?
grep -q "static analysis" "$tmp/e" && grep -q "viscous friction" "$tmp/e" && grep -q "zero at rest" "$tmp/e" &&
    grep -q "/INTER/" "$tmp/e" &&
    [ ! -e "$tmp/sv.nc" ] && expect static_refuses_friction 2 $rc "($(head -c 200 "$tmp/e"))" ||
    expect static_refuses_friction 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
# joints in statics: their constraint rows and reactions (a lever on its
# stop, a slider); a pendulum started 30 degrees off upright finds the
# upright equilibrium, which is refused as unstable (exit 3)
"$bin" run validation/static_joints/case.rad -o "$tmp/sj.nc" -q > "$tmp/e" 2>&1; rc=$?
[ -s "$tmp/sj.nc" ] && expect static_joints 0 $rc "" || expect static_joints 0 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
"$bin" run validation/joint_pendulum/case.rad -o "$tmp/su.nc" --method static --t-end 1 --dt-out 0.5 > "$tmp/e" 2>&1; rc=$?
grep -q "is unstable" "$tmp/e" && expect static_unstable 3 $rc "($(head -c 200 "$tmp/e"))" ||
    expect static_unstable 3 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
"$bin" run validation/joint_pendulum/case.rad -o "$tmp/jc.nc" --method cvode > "$tmp/e" 2>&1; rc=$?
grep -q "joints" "$tmp/e" && grep -q "IDA" "$tmp/e" && [ ! -e "$tmp/jc.nc" ] &&
    expect joints_on_cvode 2 $rc "($(head -c 160 "$tmp/e"))" || expect joints_on_cvode 2 99 "(exit $rc: $(head -c 160 "$tmp/e"))"
# settles on stderr: the run's first ten listed, then one line for the rest
# (17 settle here, every one an event in the file and counted in the summary)
"$bin" run tests/data/settle_many.rad -o "$tmp/sm.nc" > "$tmp/o" 2>"$tmp/e"; rc=$?
n=$(grep -c "settled into persistent contact at t = .* (bounces accumulated" "$tmp/e")
[ "$n" = 10 ] && grep -q "further settles of this run are not listed here" "$tmp/e" &&
    grep -q "^settled contacts 1[1-9] " "$tmp/o" && expect settle_lines_capped 0 $rc "" ||
    expect settle_lines_capped 0 99 "(exit $rc, $n lines: $(grep '^settled' "$tmp/o"))"
# method switching (--switch, --no-switch): the summary's line of switches
"$bin" run validation/bounce_settle/case.rad -o "$tmp/sw.nc" --switch > "$tmp/o" 2>&1; rc=$?
grep -q "^method switches [1-9][0-9]* to explicit, [1-9][0-9]* to implicit; explicit steps [1-9]" "$tmp/o" &&
    expect switch_runs 0 $rc "($(grep '^method' "$tmp/o"))" || expect switch_runs 0 99 "(exit $rc: $(head -c 200 "$tmp/o"))"
"$bin" run validation/bounce_settle/case.rad -o "$tmp/sn.nc" --switch --no-switch > "$tmp/o" 2>&1; rc=$?
! grep -q "^method switches" "$tmp/o" && expect no_switch 0 $rc "" || expect no_switch 0 99 "(exit $rc: $(head -c 200 "$tmp/o"))"
# the preload (/SOLVER Preload, --preload): a dynamic run from the static
# equilibrium says so; a model outside the static scope is refused at its card
"$bin" run validation/preload_column/case.rad -o "$tmp/pl.nc" --t-end 0.1 --dt-out 0.05 > "$tmp/o" 2>&1; rc=$?
grep -q "^preload: static equilibrium at t = 0" "$tmp/o" && [ -s "$tmp/pl.nc" ] &&
    expect preload_runs 0 $rc "($(grep '^preload' "$tmp/o" | head -c 120))" ||
    expect preload_runs 0 99 "(exit $rc: $(head -c 200 "$tmp/o"))"
"$bin" run validation/preload_column/case.rad -o "$tmp/pn.nc" --t-end 0.1 --dt-out 0.05 --no-preload > "$tmp/o" 2>&1; rc=$?
! grep -q "^preload:" "$tmp/o" && expect no_preload 0 $rc "" || expect no_preload 0 99 "(exit $rc: $(head -c 200 "$tmp/o"))"
"$bin" run validation/seg_box_viscous/case.rad -o "$tmp/pj.nc" --preload > "$tmp/e" 2>&1; rc=$?
grep -q "card /INTER/" "$tmp/e" && grep -q "preload" "$tmp/e" && [ ! -e "$tmp/pj.nc" ] &&
    expect preload_refuses_scope 2 $rc "($(head -c 160 "$tmp/e"))" ||
    expect preload_refuses_scope 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
# the demo ends at its end time exactly (the end time is the integrator's stop time)
"$bin" run "$demo" -o "$tmp/end.nc" > "$tmp/o" 2>&1; rc=$?
grep -q "simulated 1 s in" "$tmp/o" && expect end_time_exact 0 $rc "($(grep -o 'simulated [^,]*' "$tmp/o"))" ||
    expect end_time_exact 0 99 "($(grep -o 'simulated [^,]*' "$tmp/o"))"

# the shared library exports the functions of the public header, only those
lib=$(dirname "$bin")/libricochet.so
if [ -e "$lib" ] && [ -z "${RICOCHET_WRAP:-}" ]; then
    hdr=$(grep -oE '\brc_[a-z_]+\(' include/ricochet/ricochet.h | tr -d '(' | sort -u)
    exp=$(nm -D --defined-only "$lib" | awk '$2 == "T" {sub(/@.*/, "", $3); print $3}' | sort -u)
    soname=$(objdump -p "$lib" | awk '/SONAME/ {print $2}')
    if [ "$hdr" = "$exp" ] && [ "$soname" = "libricochet.so.$(sed -n 's/^#define RICOCHET_VERSION "\([0-9]*\)\..*/\1/p' include/ricochet/ricochet.h)" ]; then
        echo "PASS cli.shared_library_symbols: $(echo "$exp" | wc -l) functions exported, as declared; soname $soname"
    else echo "FAIL cli.shared_library_symbols: soname $soname; header vs exported: $(diff <(echo "$hdr") <(echo "$exp") | tr '\n' ' ')"; fi
fi
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

# the output path is the case file through a symbolic link: refused too
ln -s self.rad "$tmp/self_link.nc"
"$bin" run "$tmp/self.rad" -o "$tmp/self_link.nc" > "$tmp/e" 2>&1; rc=$?
if cmp -s "$demo" "$tmp/self.rad" && grep -q "refusing to overwrite" "$tmp/e" && ! grep -q "^steps" "$tmp/e"; then
    expect output_is_input_link 2 $rc "($(head -c 160 "$tmp/e"))"
else expect output_is_input_link 2 99 "(deck changed or no message: $(head -c 200 "$tmp/e"))"; fi

# a named pipe as the case file or as an included file: refused at once
# (not opened for reading, which would wait for a writer), exit 2
mkdir -p "$tmp/inc"
mkfifo "$tmp/pipe.rad" "$tmp/inc/pipe.inc"
timeout 20 "$bin" run "$tmp/pipe.rad" -o "$tmp/pipe.nc" > "$tmp/e" 2>&1; rc=$?
grep -q "pipe.rad: cannot read the case file: not a regular file (a named pipe)" "$tmp/e" && [ ! -e "$tmp/pipe.nc" ] &&
    expect fifo_case 2 $rc "($(head -c 160 "$tmp/e"))" || expect fifo_case 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"
awk '/^\/RUN/{print "#include pipe.inc"} {print}' "$demo" > "$tmp/inc/pipe_main.rad"
timeout 20 "$bin" check "$tmp/inc/pipe_main.rad" > "$tmp/e" 2>&1; rc=$?
grep -q "pipe_main.rad:[0-9]*: #include \"$tmp/inc/pipe.inc\": cannot read it: not a regular file (a named pipe)" "$tmp/e" &&
    expect fifo_include 2 $rc "($(head -c 200 "$tmp/e"))" || expect fifo_include 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"

# an output interval giving more records than the limit (RC_MAX_RECORDS):
# exit 2 with the count, nothing written
"$bin" run "$demo" -o "$tmp/many.nc" --dt-out 1e-300 > "$tmp/e" 2>&1; rc=$?
grep -q "gives 1e+300 records, more than the limit of 10000000" "$tmp/e" && [ ! -e "$tmp/many.nc" ] &&
    expect too_many_records 2 $rc "($(head -c 200 "$tmp/e"))" || expect too_many_records 2 99 "(exit $rc: $(head -c 200 "$tmp/e"))"

# the output path is a file the case includes: refused, the file untouched
mkdir -p "$tmp/inc"
awk '/^\/RUN/{print "#include run.inc"; skip=1; next} skip && /^\//{skip=0} !skip{print}' "$demo" > "$tmp/inc/main.rad"
awk '/^\/RUN/{p=1} p && /^\/(SOLVER|END)/{p=0} p{print}' "$demo" > "$tmp/inc/run.inc"
cp "$tmp/inc/run.inc" "$tmp/inc/run.orig"
"$bin" run "$tmp/inc/main.rad" -o "$tmp/inc/run.inc" > "$tmp/e" 2>&1; rc=$?
if cmp -s "$tmp/inc/run.orig" "$tmp/inc/run.inc" && grep -q "included by the case" "$tmp/e"; then expect output_is_include 2 $rc "($(head -c 160 "$tmp/e"))"
else expect output_is_include 2 99 "(include changed or no message: $(head -c 200 "$tmp/e"))"; fi

# solver failure: too few steps allowed; partial results kept, marked incomplete
awk '/^\/SOLVER/{print; getline; print "         1         5         5               1e-06"; next} {print}' "$demo" > "$tmp/fail.rad"
"$bin" run "$tmp/fail.rad" -o "$tmp/fail.nc" > "$tmp/e" 2>&1; rc=$?
if [ -e "$tmp/fail.nc" ] && ncdump -h "$tmp/fail.nc" | grep -q ':complete = "no"' &&
   grep -q "CVODE failed at t = [0-9.e+-]* s (step h = .*CV_TOO_MUCH_WORK.*largest local error in /\(INTER\|RBODY\)/.*Likely cause: .*raise Max_steps" "$tmp/e"; then
    expect solver_failure 3 $rc "(partial file kept, complete = no; $(head -c 200 "$tmp/e"))"
else expect solver_failure 3 99 "(no partial file marked incomplete: $(head -c 200 "$tmp/e"))"; fi

# physics checks (docs/theory.md 13): a 1000 kg sphere on a soft floor
# (k = 1e3 N/m) sinks through it: exit 5, the message names the check, the
# interface, the time and the numbers; the file is kept, its status says so
sed -e 's/^                   1             1000000$/                   1                1000/' \
    -e 's/^         1                                                 1$/         1                                              1000/' "$demo" > "$tmp/soft.rad"
"$bin" run "$tmp/soft.rad" -o "$tmp/soft.nc" > "$tmp/o" 2>"$tmp/e"; rc=$?
if grep -q "^ricochet: physics check failed: penetration of /INTER/TYPE6/1 is [0-9.e+-]* m at t = [0-9.e+-]* s, beyond its bound 0.05 m" "$tmp/e" &&
   ncdump -h "$tmp/soft.nc" | grep -q ':status = "physics check failed: penetration of /INTER/TYPE6/1' &&
   ncdump -h "$tmp/soft.nc" | grep -q ':complete = "no"' && ncdump -h "$tmp/soft.nc" | grep -q 'violation = UNLIMITED ; // (1 currently)' &&
   grep -q "^physics checks: failed: penetration" "$tmp/o"; then
    expect physics_stop 5 $rc "(file kept, status physics check failed; $(head -c 200 "$tmp/e"))"
else expect physics_stop 5 99 "(exit $rc: $(head -c 300 "$tmp/e") $(grep physics "$tmp/o"))"; fi
# --on-violation warn: the run goes on to its end, exit 0, never in silence
# (a warning on stderr even with -q), every violation in the file
"$bin" run "$tmp/soft.rad" -o "$tmp/soft_w.nc" -q --on-violation warn > "$tmp/o" 2>"$tmp/e"; rc=$?
if grep -q "^ricochet: warning: physics checks: 1 violation (the run went on: on-violation warn); the first: penetration of /INTER/TYPE6/1" "$tmp/e" &&
   ncdump -h "$tmp/soft_w.nc" | grep -q ':status = "complete"' && ncdump -h "$tmp/soft_w.nc" | grep -q ':physics_violations = 1LL' &&
   ncdump -v violation_check "$tmp/soft_w.nc" | grep -q 'violation_check = "penetration"'; then
    expect physics_warn 0 $rc "($(head -c 200 "$tmp/e"))"
else expect physics_warn 0 99 "(exit $rc: $(head -c 300 "$tmp/e"))"; fi
"$bin" run "$tmp/soft.rad" -o "$tmp/soft_b.nc" --on-violation=ignore > "$tmp/e" 2>&1; rc=$?
grep -q "^ricochet: --on-violation: expected stop or warn, got ignore" "$tmp/e" && [ ! -e "$tmp/soft_b.nc" ] &&
    expect bad_on_violation 2 $rc "($(head -1 "$tmp/e"))" || expect bad_on_violation 2 99 "(exit $rc: $(head -c 160 "$tmp/e"))"
"$bin" run "$demo" -o "$tmp/pass.nc" > "$tmp/o" 2>&1; rc=$?
grep -q "^physics checks: passed" "$tmp/o" && ncdump -h "$tmp/pass.nc" | grep -q ':physics_checks = "passed' &&
    ncdump -h "$tmp/pass.nc" | grep -q 'int inter_contact_history(inter)' &&
    expect physics_passed 0 $rc "($(grep '^physics checks' "$tmp/o"))" || expect physics_passed 0 99 "(exit $rc: $(grep physics "$tmp/o"))"
# the start: a sphere 4 cm inside the floor is an input error naming both
# surfaces, the interface and the depth; nothing runs
sed -e 's/^         1                   0                   0                0.15$/         1                   0                   0                0.01/' \
    -e 's/^                   0                   0                0.15$/                   0                   0                0.01/' "$demo" > "$tmp/inside.rad"
"$bin" run "$tmp/inside.rad" -o "$tmp/inside.nc" > "$tmp/e" 2>&1; rc=$?
if grep -q "^ricochet: input error: .*inside.rad:36: card /INTER/TYPE6/1: the surfaces /SURF/ELLIPS/1 and /SURF/PLANE/2 overlap at t = 0: penetration 0.04 m" "$tmp/e" &&
   [ ! -e "$tmp/inside.nc" ]; then expect start_overlap 2 $rc "($(head -c 200 "$tmp/e"))"
else expect start_overlap 2 99 "(exit $rc: $(head -c 300 "$tmp/e"))"; fi
# a meshed box on a meshed box whose normals are reversed (IRm 1): the
# message says that the surfaces do not face each other and what to set
awk '/^\/INTER\/TYPE6\/1$/{n=NR} n && NR == n + 4 {$0 = substr($0, 1, 20) "         1" substr($0, 31)} {print}' \
    validation/seg_seg_collide/case.rad > "$tmp/irm.rad"
"$bin" check "$tmp/irm.rad" > "$tmp/e" 2>&1; rc=$?
if grep -q "the segment normals of /SURF/PART/32 point away from /SURF/PART/31 (IRm = 1: reversed), so the surfaces do not face each other: with IRm = 0 (as built) they start apart" "$tmp/e"; then
    expect start_facing 2 $rc "($(head -c 160 "$tmp/e"))"
else expect start_facing 2 99 "(exit $rc: $(head -c 300 "$tmp/e"))"; fi

# interrupted (SIGINT, SIGTERM, SIGHUP: the terminal closed): the run ends
# at the next step, keeps what it computed (records flushed, marked
# incomplete, statistics written, the file readable), exit 128 + signal
awk '/^\/RUN/{print; getline; print "              100000                   1"; next} {print}' \
    validation/cpl_spring_cubic/case.rad > "$tmp/long.rad"
for sig in INT TERM HUP; do
    case $sig in INT) want=130 ;; TERM) want=143 ;; *) want=129 ;; esac
    # one signal, sent to the run alone (timeout(1) would also signal its
    # process group, and a second signal kills at once by design)
    # the SIGINT run shows its progress: stderr is a file, so a line every 10 s
    # (under valgrind the start is slower: wait for that line, 60 s at most)
    # (SIGHUP restored to its default: a signal ignored when this script
    # started, as under nohup, stays ignored in its children, and ricochet
    # keeps an ignored SIGHUP ignored by design)
    /usr/bin/python3 -c 'import os, signal, sys; signal.signal(signal.SIGHUP, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
        "$bin" run "$tmp/long.rad" -o "$tmp/long_$sig.nc" $([ $sig != INT ] && echo -q) > "$tmp/e" 2>&1 &
    pid=$!
    # the run has started (the file is created after the compile; slower
    # under valgrind), then 2 s of integration
    for _ in $(seq 60); do [ -e "$tmp/long_$sig.nc" ] && break; sleep 1; done
    sleep $((2 * delay))
    if [ $sig = INT ]; then
        for _ in $(seq 60); do grep -q "^ricochet: t = " "$tmp/e" && break; sleep 1; done
    fi
    kill -s $sig $pid
    wait $pid; rc=$?
    if [ -e "$tmp/long_$sig.nc" ] && ncdump -h "$tmp/long_$sig.nc" | grep -q ':complete = "no"' &&
       ncdump -h "$tmp/long_$sig.nc" | grep -q 'interrupted at t' && ncdump -h "$tmp/long_$sig.nc" | grep -q 'stats_steps' &&
       [ "$(ncdump -h "$tmp/long_$sig.nc" | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')" -gt 1 ] &&
       ncdump -v time "$tmp/long_$sig.nc" > /dev/null 2>&1 && ! ncdump -h "$tmp/long_$sig.nc" | grep -q 'status = "running"' &&
       grep -q "interrupted" "$tmp/e"; then
        expect "interrupt_$sig" $want $rc "(records kept, complete = no, statistics written: $(head -c 120 "$tmp/e"))"
    else expect "interrupt_$sig" $want 99 "(exit $rc; file or message wrong: $(head -c 200 "$tmp/e"))"; fi
    if [ $sig = INT ]; then
        if grep -q "^ricochet: t = [0-9.e+-]* of 100000 s ([0-9.]*%), steps [0-9]*, events [0-9]*, wall [0-9.]* s, about [0-9.]* [a-z]* left$" "$tmp/e" &&
           ! grep -q $'\r' "$tmp/e" &&
           grep -m1 "^ricochet: t = " "$tmp/e" | sed 's/.*wall \([0-9.]*\) s.*/\1/' | awk '{exit !($1 >= 10)}'; then echo "PASS cli.progress_log: $(grep -m1 '^ricochet: t = ' "$tmp/e")"
        else echo "FAIL cli.progress_log: no progress line after 10 s in a log: $(head -c 300 "$tmp/e")"; fi
    fi
done

# progress on a terminal (script(1) gives the run a pseudo-terminal): one
# line rewritten (carriage returns), the time remaining, a newline at the end
# (600 s of this deck take about 2 s; 60 s under a slow wrapper)
if command -v script > /dev/null 2>&1; then
    tt=$([ "$delay" -gt 1 ] && echo 60 || echo 600)
    script -qec "$bin run $tmp/long.rad -o $tmp/tty.nc --t-end $tt" /dev/null > "$tmp/tty" 2>&1; rc=$?
    if grep -q $'\r'"ricochet: t = [0-9.e+-]* of $tt s ([0-9.]*%), steps [0-9]*, events 0, wall [0-9.]* s, about [0-9.]* [a-z]* left" "$tmp/tty" &&
       grep -q "simulated $tt s" "$tmp/tty"; then
        expect progress_terminal 0 $rc "($(grep -o $'\r' "$tmp/tty" | wc -l) updates of one line)"
    else expect progress_terminal 0 99 "(exit $rc: $(tr '\r' '|' < "$tmp/tty" | head -c 300))"; fi
fi

# After a failed write the message says what the file keeps, as read back:
# "it keeps records 0 to N" of a file that ncdump reads with at least N + 1
# records, or "it was removed" of a file that is gone.
write_failure_honest() { # results file, message file
    local n last
    if grep -q "it was removed; no results were kept" "$2"; then [ ! -e "$1" ]; return; fi
    last=$(sed -n 's/.*it keeps records 0 to \([0-9]*\).*/\1/p' "$2" | head -1)
    [ -n "$last" ] || return 1
    n=$(ncdump -h "$1" 2>/dev/null | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')
    [ "${n:-0}" -gt "$last" ]
}
# a write that fails in the middle of the run (a file size limit, SIGXFSZ
# ignored: the write fails with EFBIG after ricochet found room on the file
# system, as when another program fills it): exit 4, the message true of
# the file, no crash
(trap '' XFSZ; ulimit -f 2048; exec "$bin" run "$demo" -o "$tmp/fsize.nc" -q --t-end 3) > "$tmp/e" 2>&1; rc=$?
if grep -q "I/O error: .*fsize.nc: .*record [0-9]" "$tmp/e" && write_failure_honest "$tmp/fsize.nc" "$tmp/e"; then
    expect write_fails_mid_run 4 $rc "($(grep -v '^HDF5-DIAG\|^  ' "$tmp/e" | head -c 300))"
else expect write_fails_mid_run 4 99 "(exit $rc: $(grep -v '^HDF5-DIAG\|^  ' "$tmp/e" | head -c 300))"; fi

# I/O faults: a full file system (small tmpfs, needs root and mount; skipped
# otherwise), a directory removed during the run: exit 4 with a message naming
# the file and the record, never a crash; what was written stays readable
awk '/^\/RUN/{print; getline; print "                3000                   1"; next} {print}' \
    validation/cpl_spring_cubic/case.rad > "$tmp/mid.rad"
mkdir -p "$tmp/fs"
if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=16k tmpfs "$tmp/fs" 2>/dev/null; then
    "$bin" run "$tmp/mid.rad" -o "$tmp/fs/out.nc" -q > "$tmp/e" 2>&1; rc=$?
    if grep -q "out.nc: file system full" "$tmp/e" && [ ! -e "$tmp/fs/out.nc" ]; then expect disk_full_16k 4 $rc "($(head -c 160 "$tmp/e"))"
    else expect disk_full_16k 4 99 "(exit $rc: $(head -c 200 "$tmp/e"))"; fi
    umount "$tmp/fs"
    mount -t tmpfs -o size=1m tmpfs "$tmp/fs" && mountpoint -q "$tmp/fs" || { echo "FAIL cli.disk_full_1m: the 1m tmpfs did not mount"; exit 1; }
    "$bin" run "$tmp/mid.rad" -o "$tmp/fs/out.nc" -q > "$tmp/e" 2>&1; rc=$?
    n=$(ncdump -h "$tmp/fs/out.nc" 2>/dev/null | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')
    if grep -q "file system full.*the file keeps records 0 to [0-9]" "$tmp/e" && [ "${n:-0}" -gt 100 ] &&
       ncdump -h "$tmp/fs/out.nc" | grep -q 'status = "incomplete: .*file system full' &&
       ncdump -v time "$tmp/fs/out.nc" > /dev/null 2>&1; then expect disk_full_1m 4 $rc "($n records readable; $(head -c 140 "$tmp/e"))"
    else expect disk_full_1m 4 99 "(exit $rc, records ${n:-none}: $(head -c 200 "$tmp/e"))"; fi
    umount "$tmp/fs"
    # the file system filled by another program during the run (the run in
    # the foreground, its exit status read directly). The filler may win the
    # race between ricochet's check of the room and HDF5's write: then the
    # write fails, the handle is abandoned, exit 4 naming the file, no crash
    # (the filler writes at most 16 MB: never a real disk full, whatever the mount did)
    mount -t tmpfs -o size=8m tmpfs "$tmp/fs" && mountpoint -q "$tmp/fs" || { echo "FAIL cli.disk_filled_during_run: the 8m tmpfs did not mount"; exit 1; }
    (sleep $delay; dd if=/dev/zero of="$tmp/fs/fill" bs=64k count=256 > /dev/null 2>&1) &
    filler=$!
    "$bin" run "$tmp/long.rad" -o "$tmp/fs/out.nc" -q > "$tmp/e" 2>&1; rc=$?
    wait $filler
    if grep -q "out.nc: file system full" "$tmp/e" && ncdump -v time "$tmp/fs/out.nc" > /dev/null 2>&1; then
        expect disk_filled_during_run 4 $rc "(file readable; $(head -c 140 "$tmp/e"))"
    elif grep -q "I/O error: .*out.nc: " "$tmp/e" && write_failure_honest "$tmp/fs/out.nc" "$tmp/e"; then
        # (at a record or at the closing definitions: either way the message is true of the file)
        expect disk_filled_during_run 4 $rc "(write failed in HDF5, no crash, the message true of the file; $(head -c 200 "$tmp/e"))"
    else expect disk_filled_during_run 4 99 "(exit $rc: $(head -c 300 "$tmp/e"))"; fi
    umount "$tmp/fs"
else
    echo "SKIP cli.disk_full: needs root and a tmpfs mount"
fi
mkdir -p "$tmp/gone/sub"
(sleep $delay; rm -rf "$tmp/gone/sub") &
remover=$!
"$bin" run "$tmp/long.rad" -o "$tmp/gone/sub/out.nc" -q > "$tmp/e" 2>&1; rc=$?
wait $remover
if grep -q "out.nc: the output file is gone.*before record [0-9]" "$tmp/e"; then expect directory_removed 4 $rc "($(head -c 160 "$tmp/e"))"
else expect directory_removed 4 99 "(exit $rc: $(head -c 200 "$tmp/e"))"; fi

# records inside contacts: at Dt_out = 1 ms the demo's 3 ms contacts get
# records (at_event = 2) at step ends at least 3 ms / 20 apart, so 150 to
# 220 us apart with its steps: 14 to 16 of them (their count moves with the
# step placement); the time axis stays increasing
awk '/^\/RUN/{print; getline; print "                   1               0.001"; next} {print}' "$demo" > "$tmp/d1ms.rad"
"$bin" run "$tmp/d1ms.rad" -o "$tmp/d1ms.nc" -q > /dev/null 2>&1
res=$(/usr/bin/python3 - "$tmp/d1ms.nc" <<'PY'
import sys, netCDF4, numpy as np
d = netCDF4.Dataset(sys.argv[1])
a = np.array(d["at_event"][:]); t = np.array(d["time"][:])
k = np.array(d["event_kind"][:]).astype(str); te = np.array(d["event_time"][:])
t0, t1 = te[list(k).index("contact_close")], te[list(k).index("contact_open")]
inside = ((a == 2) & (t > t0) & (t < t1)).sum()
print(inside, int((np.diff(t) > 0).all()))
PY
)
set -- $res
if [ "${1:-0}" -ge 12 ] && [ "${2:-0}" = 1 ]; then echo "PASS cli.contact_records: $1 records inside the first contact at Dt_out 1 ms, time increasing"
else echo "FAIL cli.contact_records: got '$res'"; fi

# a whole Radioss rigid-body deck, starter and engine files
# (tests/data/wholedeck_0000.rad, _0001.rad: a /BRICK block dropped and
# sliding onto a /SHELL pallet on an /RWALL/PLANE, /INTER/TYPE7 with
# /FRICTION turned on by a /SENSOR/TIME, /GRAV, /INIVEL), run end to end:
# the interface inactive until its sensor's 20 ms; both bodies at rest at
# the end, the block on the pallet with F = m g, P = m g / k, the floor
# carrying both; the block slid less than v0 to its stop; no energy created
"$bin" run tests/data/wholedeck_0000.rad -o "$tmp/whole.nc" > "$tmp/o" 2> "$tmp/e"; rc=$?
res=$(/usr/bin/python3 - "$tmp/whole.nc" <<'PY' 2>&1
import sys, netCDF4, numpy as np
d = netCDF4.Dataset(sys.argv[1])
g, k, mb, mp, v0 = 9.81, 1e6, 31.2, 56.16, 0.3
t = np.array(d["time"][:]); ids = list(d["inter_id"][:])
iw, i7 = ids.index(-9), ids.index(7)
F, P, mode = d["inter_force_normal"][:], d["inter_penetration"][:], d["inter_mode"][:]
x, v, w = d["body_position"][:], d["body_velocity"][:], d["body_angular_velocity"][:]
ev = list(zip(np.array(d["event_kind"][:]).astype(str), d["event_time"][:]))
start = [te for kd, te in ev if kd == "inter_start"]
stick = [te for kd, te in ev if kd == "fric_stick"]
land = [te for kd, te in ev if kd == "contact_close" and te > 0.02][0]
em = d["energy_kinetic"][:] + d["energy_potential"][:] + d["energy_contact_stored"][:]
rel = lambda a, b: abs(a - b) / abs(b)
checks = {
    "complete": d.getncattr("status") == "complete",
    "sensor": len(start) == 1 and abs(start[0] - 0.02) < 1e-12 and abs(F[t < 0.02, i7]).max() == 0 and (mode[t < 0.02, i7] == 0).all(),
    "rest": abs(v[-1]).max() < 1e-6 and abs(w[-1]).max() < 1e-6,
    "block_force": rel(F[-1, i7], mb * g) < 1e-6 and rel(P[-1, i7], mb * g / k) < 1e-4,
    "floor_force": rel(F[-1, iw], (mb + mp) * g) < 1e-6,
    "slide": v0 * land < x[-1, 1, 0] - x[0, 1, 0] < v0 * stick[-1] and abs(x[-1, 0, 0] - x[0, 0, 0]) < 1e-5,
    "energy": (em - em[0]).max() <= 1e-9 * abs(em[0]) and em[-1] < em[0],
}
bad = [n for n, ok in checks.items() if not ok]
print("ok" if not bad else "bad " + ",".join(bad), "F7 %.6f N (m g %.6f) P7 %.6e m (m g/k %.6e) floor %.4f N slid %.5f m energy %.4f -> %.4f J"
      % (F[-1, i7], mb * g, P[-1, i7], mb * g / k, F[-1, iw], x[-1, 1, 0] - x[0, 1, 0], em[0], em[-1]))
PY
)
if [ "$rc" -eq 0 ] && [ "${res%% *}" = "ok" ] && grep -q "Radioss engine file read after its starter file" "$tmp/e"; then
    echo "PASS cli.whole_radioss_deck: starter and engine files run to the end: ${res#ok }"
else echo "FAIL cli.whole_radioss_deck: exit $rc: $res $(head -c 300 "$tmp/e")"; fi

# determinism: two runs give identical time series
"$bin" run "$demo" -o "$tmp/a.nc" -q && "$bin" run "$demo" -o "$tmp/b.nc" -q
if cmp -s <(ncdump -v body_position "$tmp/a.nc" | sed -n '/data:/,$p') <(ncdump -v body_position "$tmp/b.nc" | sed -n '/data:/,$p'); then
    echo "PASS cli.determinism: two runs of the demo give identical body_position"
else echo "FAIL cli.determinism: runs differ"; fi

# export-vtk: a ParaView series of the demo's first bounces, read back with
# VTK (python3-vtk9) and compared with the results file; one record
# rendered off screen (xvfb-run when there is no display)
sed 's/^                   1              0.0001$/                 0.3               0.001/' "$demo" > "$tmp/short.rad"
"$bin" run "$tmp/short.rad" -o "$tmp/short.nc" -q > "$tmp/e" 2>&1
# (the default: the 301 records at the output times, binary)
"$bin" export-vtk "$tmp/short.nc" -o "$tmp/vtk" > "$tmp/x" 2>&1; rc=$?
n=$(ls "$tmp/vtk" 2>/dev/null | grep -c '\.vtp$')
if [ -f "$tmp/vtk/short.pvd" ] && [ "$n" -eq 602 ] && grep -q '(301 frames, 603 files, .* MB binary, the output times (default))' "$tmp/x" &&
   head -c 300 "$tmp/vtk/short_bodies_000000.vtp" | grep -q 'byte_order="LittleEndian" header_type="UInt64"' &&
   grep -q '<AppendedData encoding="raw">' "$tmp/vtk/short_bodies_000000.vtp"; then
    expect export_vtk 0 $rc "($n .vtp files, appended raw binary; $(head -c 160 "$tmp/x"))"
else expect export_vtk 0 99 "(exit $rc, $n .vtp files: $(head -c 200 "$tmp/x"))"; fi
# check shows the gravity in SI; a deck in mm with gravity left at -9.81
# (9.81 mm/s^2) is warned about, the demo (in m) is not
sed 's/^                  kg                   m                   s$/                  kg                  mm                   s/' "$demo" > "$tmp/mm.rad"
"$bin" check "$tmp/mm.rad" > "$tmp/x" 2>/dev/null; rc=$?
"$bin" check "$demo" > "$tmp/y" 2>/dev/null
if [ "$rc" -eq 0 ] && grep -q "^gravity     (0, 0, -0.00981) m/s^2" "$tmp/x" && grep -q "is 0.001 times the Earth's 9.81 m/s^2" "$tmp/x" &&
   grep -q "^gravity     (0, 0, -9.81) m/s^2" "$tmp/y" && ! grep -q "times the Earth's" "$tmp/y"; then
    echo "PASS cli.check_gravity: $(grep '^warning' "$tmp/x" | head -c 120)"
else echo "FAIL cli.check_gravity: exit $rc: $(grep -E '^gravity|^warning' "$tmp/x" "$tmp/y" | head -c 300)"; fi
# a run in which no contact ever closes (the demo cut at 0.1 s, before the
# sphere reaches the floor) says so plainly
sed 's/^                   1              0.0001$/                 0.1               0.001/' "$demo" > "$tmp/noclose.rad"
"$bin" run "$tmp/noclose.rad" -o "$tmp/noclose.nc" > "$tmp/x" 2>&1; rc=$?
if [ "$rc" -eq 0 ] && grep -q "^contacts: 1 never closed (/INTER/TYPE6/1) - no contact closed in the whole run: the bodies never touched" "$tmp/x"; then
    echo "PASS cli.no_contact_note: $(grep '^contacts:' "$tmp/x" | head -c 140)"
else echo "FAIL cli.no_contact_note: exit $rc: $(grep '^contacts:' "$tmp/x" | head -c 200)"; fi
# check's plausibility warnings, each provoked by the demo changed in one
# field (gravity 9810 in the metre deck, a 2e6 kg sphere, a 60 m sphere, a
# load curve of 10 N/m: the weight sinks it 0.98 m, of 400 N/m: the impact
# from 0.1 m sinks it 0.07 m, more than its 0.05 m radius); the mm deck
# with its gravity in mm/s^2 (9810) is not warned about
sed 's/-9.81$/-9810/' "$demo" > "$tmp/g9810.rad"
sed 's/^                  kg                   m                   s$/                  kg                  mm                   s/; s/-9.81$/-9810/' "$demo" > "$tmp/mmok.rad"
sed '/^sphere, 1 kg$/{n;s/         1$/     2.0e6/}' "$demo" > "$tmp/heavy.rad"
sed 's/^                0.05                0.05                0.05$/                  60                  60                  60/; s/0.15$/100/' "$demo" > "$tmp/big.rad"
sed 's/^                   1             1000000$/                   1                  10/' "$demo" > "$tmp/soft.rad"
sed 's/^                   1             1000000$/                   1                 400/' "$demo" > "$tmp/softimp.rad"
for w in "g9810|is 1e+03 times the Earth's 9.81 m/s^2: .*the deck's length unit is m: the Earth's gravity is 9.80665 m/s^2, the deck gives 9810 m/s^2" \
         "mm|the deck's length unit is mm: the Earth's gravity is 9806.65 mm/s^2, the deck gives 9.81 mm/s^2" \
         "heavy|/RBODY/1 has a mass of 2e+06 kg, above 1e+06 kg" \
         "big|/RBODY/1 is 60 m from its centre to the far side of its surfaces, above 50 m" \
         "soft|/INTER/TYPE6/1: the static penetration under the weight, 0.981 m, is larger than the body's size 0.05 m" \
         "softimp|/INTER/TYPE6/1: the penetration of an impact (at the model's speed scale, or the fall over the gap), 0.07004 m, is larger than the body's size 0.05 m"; do
    "$bin" check "$tmp/${w%%|*}.rad" > "$tmp/x" 2>/dev/null; rc=$?
    if [ "$rc" -eq 0 ] && grep "^warning" "$tmp/x" | grep -q -- "${w#*|}"; then
        echo "PASS cli.check_warns_${w%%|*}: $(grep '^warning' "$tmp/x" | head -1 | head -c 160)"
    else echo "FAIL cli.check_warns_${w%%|*}: exit $rc: $(grep '^warning' "$tmp/x" | head -c 300)"; fi
done
"$bin" check "$tmp/mmok.rad" > "$tmp/x" 2>/dev/null; rc=$?
if [ "$rc" -eq 0 ] && grep -q "^            in the deck's units: (0, 0, -9810) mm/s^2, |g| 9810 mm/s^2" "$tmp/x" &&
   grep -q "^gravity     (0, 0, -9.81) m/s^2" "$tmp/x" && ! grep -q "^warning" "$tmp/x"; then
    echo "PASS cli.check_gravity_deck_units: the mm deck's -9810 mm/s^2 shown in SI and in mm/s^2, no warning"
else echo "FAIL cli.check_gravity_deck_units: exit $rc: $(grep -E '^gravity|^ *in the deck|^warning' "$tmp/x" | head -c 300)"; fi
# no false positive: no deck of cases/ or validation/ is warned about
bad=""
for c in cases/*.rad validation/*/*.rad; do
    [ -f "$c" ] || continue
    "$bin" check "$c" 2>/dev/null | grep -q "^warning" && bad="$bad $c"
done
if [ -z "$bad" ]; then echo "PASS cli.check_no_false_warning: $(ls cases/*.rad validation/*/*.rad | wc -l) decks of cases/ and validation/ without a warning"
else echo "FAIL cli.check_no_false_warning: warned about:$bad"; fi
# the estimate: printed, and within 10x of the run's steps on the demo
"$bin" check "$demo" > "$tmp/x" 2>/dev/null
est=$(sed -n 's/.*; ~\([0-9.e+]*\) integrator steps; ~\([0-9.e+-]*\) s wall time.*/\1/p' "$tmp/x")
"$bin" run "$demo" -o "$tmp/est.nc" > "$tmp/y" 2>&1
steps=$(sed -n 's/^steps \([0-9]*\),.*/\1/p' "$tmp/y")
if [ -n "$est" ] && [ -n "$steps" ] && awk -v e="$est" -v s="$steps" 'BEGIN { exit !(e < 10 * s && s < 10 * e) }' &&
   grep -q "^estimate    an order of magnitude, within ~10x" "$tmp/x"; then
    echo "PASS cli.check_estimate: the demo: ~$est steps estimated, $steps run"
else echo "FAIL cli.check_estimate: estimate '${est:-none}', run '${steps:-none}': $(grep -A1 '^estimate' "$tmp/x" | head -c 300)"; fi
# export-vtk --dt: one frame per 0.05 s of the short run (0.3 s: 7 frames,
# 14 .vtp files, the times 0, 0.05, ..., 0.3 in the .pvd), the options in
# any order; --help on stdout with exit 0; a bad --dt is a usage error
"$bin" export-vtk --dt 0.05 "$tmp/short.nc" -o "$tmp/vtkdt" > "$tmp/x" 2>&1; rc=$?
n=$(ls "$tmp/vtkdt" 2>/dev/null | grep -c '\.vtp$')
times=$(grep -o 'part="0" file' "$tmp/vtkdt/short.pvd" 2>/dev/null | wc -l)
if [ "$rc" -eq 0 ] && [ "$n" -eq 14 ] && [ "$times" -eq 7 ] && grep -q '(7 frames, 15 files, ' "$tmp/x"; then
    echo "PASS cli.export_vtk_dt: --dt 0.05 on a 0.3 s run: $n .vtp files, $times frames ($(head -c 100 "$tmp/x"))"
else echo "FAIL cli.export_vtk_dt: exit $rc, $n .vtp files, $times frames ($(head -c 200 "$tmp/x"))"; fi
"$bin" export-vtk --help > "$tmp/x" 2>&1; rc=$?
if [ "$rc" -eq 0 ] && grep -q "^usage: ricochet export-vtk RESULTS.nc \[options\]" "$tmp/x" && grep -q -- "--dt T *one frame per T seconds" "$tmp/x" &&
   grep -q -- "--every N *every N-th record" "$tmp/x" && grep -q -- "--ascii *ASCII data arrays" "$tmp/x" && grep -q "at most 1000 frames" "$tmp/x"; then
    echo "PASS cli.export_vtk_help: exit 0, its own usage with --dt (seconds), --every, --ascii and the default"
else echo "FAIL cli.export_vtk_help: exit $rc: $(head -c 200 "$tmp/x")"; fi
# export-vtk --every 10: records 0, 10, 20, ...: ceil(records / 10) frames
nrec=$(ncdump -h "$tmp/short.nc" 2>/dev/null | sed -n 's/^[[:space:]]*time = UNLIMITED ; \/\/ (\([0-9]*\) currently).*/\1/p')
"$bin" export-vtk "$tmp/short.nc" --every 10 -o "$tmp/vtk10" > "$tmp/x" 2>&1; rc=$?
want=$(( (${nrec:-0} + 9) / 10 ))
times=$(grep -c 'part="0" file' "$tmp/vtk10/short.pvd" 2>/dev/null)
if [ "$rc" -eq 0 ] && [ "${nrec:-0}" -gt 0 ] && [ "$times" = "$want" ] && grep -q "($want frames, " "$tmp/x" &&
   grep -q 'file="short_bodies_000010.vtp"' "$tmp/vtk10/short.pvd" && ! grep -q 'short_bodies_000001.vtp' "$tmp/vtk10/short.pvd"; then
    echo "PASS cli.export_vtk_every: --every 10 on $nrec records: $times frames (ceil($nrec / 10))"
else echo "FAIL cli.export_vtk_every: exit $rc, $times frames for $nrec records, want $want ($(head -c 200 "$tmp/x"))"; fi
"$bin" export-vtk "$tmp/short.nc" --every 0 > "$tmp/x" 2>&1; rc=$?
"$bin" export-vtk "$tmp/short.nc" --every 2 --dt 0.1 > "$tmp/y" 2>&1; rc2=$?
if [ "$rc" -eq 2 ] && grep -q "expected a whole number of records >= 1" "$tmp/x" && [ "$rc2" -eq 2 ] && grep -q "expected one of them" "$tmp/y"; then
    echo "PASS cli.export_vtk_bad_every: --every 0 and --every with --dt: exit 2 ($(head -c 80 "$tmp/x"))"
else echo "FAIL cli.export_vtk_bad_every: exit $rc / $rc2: $(head -c 200 "$tmp/x") $(head -c 200 "$tmp/y")"; fi
# export-vtk --ascii: the same frames in ASCII, read back by VTK equal to
# the binary ones (every record: the event records' too)
"$bin" export-vtk "$tmp/short.nc" --every 1 --ascii -o "$tmp/vtka" > "$tmp/x" 2>&1; rc=$?
"$bin" export-vtk "$tmp/short.nc" --every 1 -o "$tmp/vtkb" > "$tmp/y" 2>&1; rc2=$?
if [ "$rc" -eq 0 ] && [ "$rc2" -eq 0 ] && grep -q "MB ASCII" "$tmp/x" && grep -q 'format="ascii"' "$tmp/vtka/short_bodies_000000.vtp" &&
   ! grep -q 'AppendedData' "$tmp/vtka/short_bodies_000000.vtp" && /usr/bin/python3 -c 'import vtk' 2>/dev/null; then
    res=$(/usr/bin/python3 - "$tmp/vtka" "$tmp/vtkb" <<'PY' 2>&1
import glob, os, sys
import numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy
def read(p):
    r = vtk.vtkXMLPolyDataReader(); r.SetFileName(p); r.Update(); return r.GetOutput()
def arrays(p):
    d = read(p); out = {}
    if d.GetPoints() is not None: out["Points"] = vtk_to_numpy(d.GetPoints().GetData())
    for kind in ("GetPointData", "GetCellData", "GetFieldData"):
        a = getattr(d, kind)()
        for i in range(a.GetNumberOfArrays()):
            x = a.GetAbstractArray(i)
            out[kind + x.GetName()] = ([x.GetValue(j) for j in range(x.GetNumberOfValues())]
                                       if isinstance(x, vtk.vtkStringArray) else vtk_to_numpy(x))
    out["polys"] = vtk_to_numpy(d.GetPolys().GetData()) if d.GetNumberOfPolys() else None
    return out
files = sorted(os.path.basename(f) for f in glob.glob(sys.argv[1] + "/*.vtp"))
bad, n = 0, 0
for f in files[:: max(1, len(files) // 40)] + [f for f in files if "contacts" in f][:5]:
    a, b = arrays(os.path.join(sys.argv[1], f)), arrays(os.path.join(sys.argv[2], f))
    n += 1
    bad += a.keys() != b.keys() or any(not np.array_equal(np.asarray(a[k], dtype=object), np.asarray(b[k], dtype=object)) for k in a)
print(n, bad, len(files))
PY
)
    set -- $res
    if [ "${1:-0}" -gt 10 ] && [ "${2:-1}" = 0 ]; then
        echo "PASS cli.export_vtk_ascii: --ascii: $3 .vtp files; $1 of them read back by VTK equal to the binary ones ($(head -c 90 "$tmp/x"))"
    else echo "FAIL cli.export_vtk_ascii: got '$res'"; fi
elif [ "$rc" -ne 0 ] || [ "$rc2" -ne 0 ] || ! grep -q 'format="ascii"' "$tmp/vtka/short_bodies_000000.vtp"; then
    echo "FAIL cli.export_vtk_ascii: exit $rc / $rc2: $(head -c 200 "$tmp/x")"
else echo "SKIP cli.export_vtk_ascii: python3-vtk9 not installed (the ASCII files written)"; fi
# export-vtk of the 1 s demo with the defaults ($tmp/a.nc above: 10 001
# output times at Dt_out 0.1 ms, more than 1000, so one frame per 2 ms): 501
# frames, under 20 MB
start=$(date +%s.%N)
"$bin" export-vtk "$tmp/a.nc" -o "$tmp/demovtk" > "$tmp/x" 2>&1; rc=$?
secs=$(echo "$(date +%s.%N) $start" | awk '{printf "%.2f", $1 - $2}')
bytes=$(cat "$tmp/demovtk"/* 2>/dev/null | wc -c)
times=$(grep -c 'part="0" file' "$tmp/demovtk/a.pvd" 2>/dev/null)
if [ "$rc" -eq 0 ] && [ "$times" = 501 ] && [ "$bytes" -lt 20000000 ] && grep -q "(501 frames, 1003 files, .* MB binary, one per 0.002 s (default))" "$tmp/x"; then
    echo "PASS cli.export_vtk_demo_size: the 1 s demo by default: $times frames, $bytes bytes (< 20 MB), $secs s"
else echo "FAIL cli.export_vtk_demo_size: exit $rc, $times frames, $bytes bytes ($(head -c 200 "$tmp/x"))"; fi
# the command line on getopt_long: options in any position, --opt=VALUE and
# -oFILE, a misspelt option answered with the closest one, a run option
# given to check named as such
"$bin" run -q "$demo" --t-end=0.01 -o"$tmp/anypos.nc" --rtol 1e-6 > "$tmp/x" 2>&1; rc=$?
[ "$rc" -eq 0 ] && [ -s "$tmp/anypos.nc" ] && echo "PASS cli.options_any_position: options after the case file, --t-end=0.01, -oFILE" ||
    echo "FAIL cli.options_any_position: exit $rc: $(head -c 200 "$tmp/x")"
# the results file's t_end and dt_out are the run's (the overrides), not the deck's
"$bin" run -q "$demo" --t-end 0.02 --dt-out 0.005 -o "$tmp/ovattr.nc" > "$tmp/x" 2>&1; rc=$?
att=$(/usr/bin/python3 -c "import netCDF4; d = netCDF4.Dataset('$tmp/ovattr.nc'); print(d.t_end, d.dt_out)" 2>&1)
[ "$rc" -eq 0 ] && [ "$att" = "0.02 0.005" ] && echo "PASS cli.override_attributes: t_end, dt_out = $att (the overrides)" ||
    echo "FAIL cli.override_attributes: exit $rc, t_end dt_out = $att (expected 0.02 0.005)"
"$bin" run --t-ned 0.01 "$demo" > "$tmp/x" 2>&1; rc=$?
[ "$rc" -eq 2 ] && grep -q "unknown option '--t-ned': did you mean --t-end?" "$tmp/x" &&
    echo "PASS cli.option_did_you_mean: exit 2, $(head -1 "$tmp/x")" || echo "FAIL cli.option_did_you_mean: exit $rc: $(head -c 200 "$tmp/x")"
"$bin" check "$demo" --rtol 1e-6 > "$tmp/x" 2>&1; rc=$?
[ "$rc" -eq 2 ] && grep -q "option '--rtol' is an option of \`ricochet run\`" "$tmp/x" &&
    echo "PASS cli.check_run_option: exit 2, $(head -1 "$tmp/x")" || echo "FAIL cli.check_run_option: exit $rc: $(head -c 200 "$tmp/x")"
"$bin" run "$demo" "$demo" > "$tmp/x" 2>&1; rc=$?
[ "$rc" -eq 2 ] && grep -q "unexpected argument" "$tmp/x" &&
    echo "PASS cli.two_cases: exit 2, $(head -1 "$tmp/x")" || echo "FAIL cli.two_cases: exit $rc: $(head -c 200 "$tmp/x")"
# ricochet study: the Python module's study runner on Dask (two friction
# coefficients, two worker processes), from the program
if /usr/bin/python3 -c "import distributed, xarray" 2>/dev/null; then
    echo '{"/INTER/TYPE6/1:Fric": [0.1, 0.3]}' > "$tmp/grid.json"
    abin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
    root=$(pwd)
    (cd "$tmp" && "$abin" study "$root/cases/t6_hysteresis_drop.rad" --grid grid.json --workers 2 -o study.nc) > "$tmp/x" 2>&1; rc=$?
    if [ "$rc" -eq 0 ] && /usr/bin/python3 -c "
import sys, xarray as xr
d = xr.open_dataset('$tmp/study.nc')
sys.exit(not (list(d['status'].values) == [0, 0] and list(d['INTER_TYPE6_1_Fric'].values) == [0.1, 0.3]))"; then
        echo "PASS cli.study: ricochet study ran 2 cases on Dask, status 0 0, Fric 0.1 0.3"
    else echo "FAIL cli.study: exit $rc: $(tail -c 300 "$tmp/x")"; fi
    RICOCHET_PYTHON=/nonexistent/python "$bin" study x > "$tmp/x" 2>&1; rc=$?
    if [ "$rc" -eq 2 ] && grep -q "cannot start /nonexistent/python" "$tmp/x"; then
        echo "PASS cli.study_no_python: exit 2, $(head -c 100 "$tmp/x")"
    else echo "FAIL cli.study_no_python: exit $rc: $(head -c 200 "$tmp/x")"; fi
else
    echo "SKIP cli.study: python3-distributed not installed (scripts/install-deps.sh test installs it)"
fi
"$bin" export-vtk "$tmp/short.nc" --dt -1 > "$tmp/x" 2>&1; rc=$?
if [ "$rc" -eq 2 ] && grep -q "expected a positive number of seconds" "$tmp/x"; then
    echo "PASS cli.export_vtk_bad_dt: exit 2, $(head -c 100 "$tmp/x")"
else echo "FAIL cli.export_vtk_bad_dt: exit $rc: $(head -c 200 "$tmp/x")"; fi
# guidance: a restitution asked of a contact off the line of the centres of
# mass (the sphere moved 0.03 m sideways from the body's centre: the contact
# drives 1 / (1/m + 0.03^2 / J) = 0.5263 kg, not m = 1 kg) or on a jointed body
awk 'NR == 21 {print "                0.03                   0               0.052"; next} {print}' \
    validation/t6_restitution/case.rad > "$tmp/offc.rad"
"$bin" check "$tmp/offc.rad" > "$tmp/x" 2>&1; rc=$?
grep -q "m_eff 0.5263 kg" "$tmp/x" && grep -q "m_eff includes the rotations: .* (the translations alone: 1 kg)" "$tmp/x" &&
    ! "$bin" check validation/t6_restitution/case.rad 2>&1 | grep -q "includes the rotations" &&
    "$bin" check validation/joint_flap_stop/case.rad 2>&1 | grep -q "WARNING: a body of this contact is on a joint" &&
    expect guidance_effective_mass 0 $rc "(off-centre contact: m_eff with the rotations; jointed contact warned; the centred one plain)" ||
    expect guidance_effective_mass 0 99 "($(grep -i warning "$tmp/x" | head -c 200))"
# a box against a plane or a box: check names the pair and its corners
"$bin" check validation/box_box/case.rad > "$tmp/x" 2>&1; rc=$?
grep -q "^  /INTER/TYPE6/1 *box-box (the 8 corners of each box against the 6 faces of the other, the 12 edges of each against those of the other)" "$tmp/x" &&
    grep -q "^  /INTER/TYPE6/2 *box-plane (the box's 8 corners are the contact points)" "$tmp/x" &&
    expect check_box_pairs 0 $rc "(box-box and box-plane listed with their corners)" ||
    expect check_box_pairs 0 99 "($(grep "/INTER/TYPE6/[12] " "$tmp/x" | head -c 200))"
# the integrator's warnings: ricochet's own line format, at most 3 per run
# and one line saying the others are not shown (a cylinder sliding along
# its axis over a box's edge, held beyond it by the face's plane past the
# physics check that stops it there (support_beyond_edge, asked to warn):
# its step collapses, CVODE warns "t + h = t" ten times, then stops with
# exit 3)
"$bin" run tests/data/cylinder_rim_step_collapse.rad -o "$tmp/warn.nc" -q --on-violation warn > "$tmp/x" 2>&1; rc=$?
nw=$(grep -c '^ricochet: warning: CVODE (CVode): Internal t' "$tmp/x")
if [ "$nw" -eq 3 ] && grep -q '^ricochet: warning: CVODE: further warnings of the integrator in this run are not shown' "$tmp/x" &&
    ! grep -q 'CVODE WARNING' "$tmp/x" && grep -q 'solver failure: CVODE failed' "$tmp/x"; then
    expect integrator_warnings 3 $rc "($nw warnings shown, the rest announced)"
else
    expect integrator_warnings 3 99 "($nw warnings; $(grep -m2 -i warn "$tmp/x" | head -c 200))"
fi
# a missing results file: exit 4 with its name, and no output directory left behind
babs=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
(cd "$tmp" && "$babs" export-vtk none.nc) > "$tmp/x" 2>&1; rc=$?
if grep -q "none.nc" "$tmp/x" && [ ! -e "$tmp/none_vtk" ]; then
    expect export_vtk_missing 4 $rc "($(head -c 120 "$tmp/x"))"
else
    expect export_vtk_missing 4 99 "(no message, or the directory none_vtk created)"
fi
printf 'netcdf x {\ndimensions:\n  n = 1 ;\nvariables:\n  int n(n) ;\n}\n' | ncgen -4 -o "$tmp/other.nc" 2>/dev/null
"$bin" export-vtk "$tmp/other.nc" -o "$tmp/vtk2" > "$tmp/x" 2>&1; rc=$?
grep -q "not a ricochet results file" "$tmp/x" && expect export_vtk_not_results 2 $rc "($(head -c 120 "$tmp/x"))" || expect export_vtk_not_results 2 99 "($(head -c 120 "$tmp/x"))"
"$bin" export-vtk > /dev/null 2>&1; expect export_vtk_usage 2 $? ""
# export-vtk draws segment surfaces: the meshed boxes of seg_box_rest, their
# nodes placed by the body poses of the results file
"$bin" run validation/seg_box_rest/case.rad --t-end 0.05 -o "$tmp/seg.nc" -q > "$tmp/e" 2>&1 &&
    "$bin" export-vtk "$tmp/seg.nc" -o "$tmp/segvtk" > "$tmp/x" 2>&1; rc=$?
if [ $rc -eq 0 ] && /usr/bin/python3 -c 'import vtk, netCDF4' 2>/dev/null; then
    res=$(/usr/bin/python3 - "$tmp/seg.nc" "$tmp/segvtk" <<'PY' 2>&1
import glob, sys
import numpy as np, vtk
from netCDF4 import Dataset
from vtk.util.numpy_support import vtk_to_numpy
nc = Dataset(sys.argv[1])
f = sorted(glob.glob(sys.argv[2] + "/*_bodies_*.vtp"))[-1]
r = vtk.vtkXMLPolyDataReader(); r.SetFileName(f); r.Update(); p = r.GetOutput()
pts = vtk_to_numpy(p.GetPoints().GetData())
kind = list(nc["surface_kind"][:]); node0 = nc["surface_first_node"][:]; sb = nc["surface_body"][:]
xyz = nc["segment_node_position"][:]; bid = list(nc["body"][:])
pos = nc["body_position"][-1]; q = nc["body_quaternion"][-1]
err, n = 0.0, 0
for j, k in enumerate(kind):
    if k != "SEGMENTS":
        continue
    b = bid.index(sb[j]); w, x, y, z = q[b] / np.linalg.norm(q[b])
    R = np.array([[1-2*(y*y+z*z), 2*(x*y-w*z), 2*(x*z+w*y)], [2*(x*y+w*z), 1-2*(x*x+z*z), 2*(y*z-w*x)], [2*(x*z-w*y), 2*(y*z+w*x), 1-2*(x*x+y*y)]])
    n1 = node0[j + 1] if j + 1 < len(kind) and kind[j + 1] == "SEGMENTS" else len(xyz)
    for v in xyz[node0[j]:n1]:
        g = pos[b] + R @ v
        err = max(err, float(np.min(np.linalg.norm(pts - g, axis=1)))); n += 1
print(n, p.GetNumberOfPolys(), f"{err:.1e}")
PY
)
    set -- $res
    if [ "${1:-0}" = 24 ] && [ "${2:-0}" = 25 ] && /usr/bin/python3 -c "import sys; sys.exit(0 if float('${3:-1}') < 1e-9 else 1)"; then
        echo "PASS cli.export_vtk_segments: $1 segment nodes drawn at the body poses (max distance $3 m), $2 polygons"
    else echo "FAIL cli.export_vtk_segments: got '$res'"; fi
elif [ $rc -ne 0 ]; then echo "FAIL cli.export_vtk_segments: exit $rc ($(head -c 200 "$tmp/x"))"
else echo "SKIP cli.export_vtk_segments: python3-vtk9 not installed"; fi
if /usr/bin/python3 -c 'import vtk, netCDF4' 2>/dev/null; then
    render=""
    if [ -n "${DISPLAY:-}" ]; then render="$tmp/frame.png"; pre=""
    elif command -v xvfb-run > /dev/null; then render="$tmp/frame.png"; pre="xvfb-run -a"
    else echo "SKIP vtk.render: no display and no xvfb-run (package xvfb)"; pre=""; fi
    $pre /usr/bin/python3 tests/vtk_readback.py "$tmp/short.nc" "$tmp/vtk" $render 2>&1 | grep -E '^(PASS|FAIL|SKIP) |Error'
else
    echo "SKIP vtk.readback: python3-vtk9 not installed (scripts/install-deps.sh test installs it)"
fi

# the results file in xarray: ids as coordinates, the CF time axis decoded,
# plain seconds without decoding
if /usr/bin/python3 -c 'import xarray' 2>/dev/null; then
    /usr/bin/python3 - "$tmp/short.nc" <<'PY'
import sys, numpy as np, xarray as xr, netCDF4
f = sys.argv[1]
ds = xr.open_dataset(f)
z = ds["body_position"].sel(body=1, vec3=2) if "vec3" in ds.coords else ds["body_position"].sel(body=1)[:, 2]
raw = netCDF4.Dataset(f)["time"][:]
secs = (ds["time"] - ds["time"][0]) / np.timedelta64(1, "s")
ok = (ds["time"].dtype.kind == "M" and np.allclose(secs.values, raw - raw[0], rtol=0, atol=1e-9)
      and float(z[0]) == float(netCDF4.Dataset(f)["body_position"][0, 0, 2])
      and int(ds["impact_inter"].sel(impact=0) if "impact" in ds.coords else ds["impact_inter"][0]) == 1)
plain = xr.open_dataset(f, decode_times=False)["time"].values
ok = ok and np.array_equal(plain, raw)
print(("PASS" if ok else "FAIL") + " cli.xarray: open_dataset decodes time as datetime64 (seconds since the start "
      f"within 1 ns), .sel(body=1) by /RBODY id, decode_times=False gives the stored seconds; "
      f"{ds.sizes['impact']} impacts")
PY
else
    echo "SKIP cli.xarray: python3-xarray not installed (scripts/install-deps.sh test installs it)"
fi
