#!/usr/bin/env bash
# `ricochet sens` (docs/calibration.md, "Sensitivities"): the derivatives
# of a drop through its impact against the whole runs' central differences
# (--check-fd), the events' list, and the input errors (exit 2, nothing
# run). Prints PASS/FAIL lines (counted by scripts/check.sh).
set -u
bin=${1:-build/ricochet}
export RC_BIN=$bin
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
drop=validation/fit_drop/drop.rad

expect() { # name, expected exit code, actual exit code, detail
    if [ "$2" -eq "$3" ]; then echo "PASS sens.$1: exit $3 $4"; else echo "FAIL sens.$1: expected exit $2, got $3 $4"; fi
}

"$bin" --help | grep -q "ricochet sens CASE --param CARD:FIELD=VALUE" && echo "PASS sens.usage_line: in ricochet --help" ||
    echo "FAIL sens.usage_line: ricochet --help does not list sens"
"$bin" sens --help > "$tmp/h" 2>&1; rc=$?
grep -q "^usage: ricochet sens CASE --param" "$tmp/h" && expect help 0 $rc "" || expect help 0 99 "(no usage)"

# translations held along a skew's axes (/BCS skew_ID): the derivative of
# a thrown ball's x at 0.5 s with respect to its initial Vx is t (u.e_x)^2
# on a rail along u = (cos 30 cos 40, cos 30 sin 40, sin 30) and
# t (1 - (n.e_x)^2) in a plane of normal n = Z' (validation/bcs_skew_rail)
"$bin" sens validation/bcs_skew_rail/case.rad --param /INIVEL/TRA/1:Vx=1.0 --param /INIVEL/TRA/2:Vx=1.0 --at 0.5 \
    --out 1:x --out 2:x > "$tmp/o" 2>&1; rc=$?
d1=$(grep -A1 "body 1 x" "$tmp/o" | sed -n 's/.*TRA\/1:Vx = \([^ ]*\) m.*/\1/p')
d2=$(grep -A2 "body 2 x" "$tmp/o" | sed -n 's/.*TRA\/2:Vx = \([^ ]*\) m.*/\1/p')
if [ $rc -eq 0 ] && awk -v a="$d1" -v b="$d2" 'BEGIN { p = atan2(1, 1) / 45; c = cos(30 * p) * cos(40 * p);
        e1 = 0.5 * c * c; s = 0.5 * cos(40 * p); e2 = 0.5 * (1 - s * s);
        exit !(a != "" && b != "" && (a - e1)^2 < (1e-8 * e1)^2 && (b - e2)^2 < (1e-8 * e2)^2) }'; then
    echo "PASS sens.bcs_skew: dx/dVx $d1 on the rail, $d2 in the plane (closed forms to 1e-8)"
else echo "FAIL sens.bcs_skew: exit $rc, dx/dVx $d1, $d2: $(head -c 300 "$tmp/o")"; fi

# the drop: z and vz after the rebound in the damping, the load curve's
# scale and gravity, each beside the whole runs' difference
"$bin" sens "$drop" --param /INTER/TYPE6/1:Visc=30 --param /INTER/TYPE6/1:FscaleId=20000 \
    --param /GRAV/1:Fscale_y=-9.81 --at 0.3,0.5 --out 1:z --out 1:vz --check-fd > "$tmp/o" 2>&1; rc=$?
n=$(grep -c "relative difference" "$tmp/o")
worst=$(sed -n 's/.*relative difference \([^)]*\)).*/\1/p' "$tmp/o" | sort -g | tail -1)
if [ $rc -eq 0 ] && [ "$n" -eq 12 ] && awk -v w="$worst" 'BEGIN { exit !(w < 1e-4) }'; then
    echo "PASS sens.drop_check_fd: 12 derivatives, worst relative difference to the whole runs $worst (tolerance 1e-4)"
else echo "FAIL sens.drop_check_fd: exit $rc, $n derivatives, worst $worst: $(head -c 400 "$tmp/o")"; fi
grep -q "^t = 0.22576.* s  contact_close /INTER 1" "$tmp/o" && grep -q "contact_separate /INTER 1" "$tmp/o" &&
    grep -q "^ricochet sens: $drop: 3 parameters, 2 times; 3 events with a jump" "$tmp/o" &&
    echo "PASS sens.events: the close, open and separation listed with their derivatives" ||
    echo "FAIL sens.events: $(head -c 400 "$tmp/o")"

# a power-law contact (Hunt-Crossley damping): K, the exponent m1 and C
"$bin" sens validation/fit_drop/power.rad --param /INTER/POWER/1:K=600000 --param /INTER/POWER/1:m1=1.5 \
    --param /INTER/POWER/1:C=200000 --at 0.5 --out 1:z --out 1:vz --check-fd > "$tmp/o" 2>&1; rc=$?
n=$(grep -c "relative difference" "$tmp/o")
worst=$(sed -n 's/.*relative difference \([^)]*\)).*/\1/p' "$tmp/o" | sort -g | tail -1)
if [ $rc -eq 0 ] && [ "$n" -eq 6 ] && awk -v w="$worst" 'BEGIN { exit !(w < 1e-4) }'; then
    echo "PASS sens.power_check_fd: K, m1, C: worst relative difference to the whole runs $worst (tolerance 1e-4)"
else echo "FAIL sens.power_check_fd: exit $rc, $n derivatives, worst $worst: $(head -c 400 "$tmp/o")"; fi

# input errors: exit 2 with a message, nothing run
bad() { # name, needle, args...
    local name=$1 needle=$2
    shift 2
    "$bin" sens "$@" > "$tmp/e" 2>&1; local rc=$?
    grep -q -- "$needle" "$tmp/e" && expect "$name" 2 $rc "" || expect "$name" 2 99 "($(head -c 200 "$tmp/e"))"
}
bad no_at "expected CASE, at least one --param and --at" "$drop" --param /INTER/TYPE6/1:Visc=30
bad param_form "expected CARD:FIELD=VALUE" "$drop" --param Visc=30 --at 0.1
bad param_value "VALUE: expected a finite number" "$drop" --param /INTER/TYPE6/1:Visc=abc --at 0.1
bad times "expected times \[s\] > 0, increasing" "$drop" --param /INTER/TYPE6/1:Visc=30 --at 0.2,0.1
bad out "expected ID:Q" "$drop" --param /INTER/TYPE6/1:Visc=30 --at 0.1 --out 1:w
bad field "no numeric field Fscale" "$drop" --param /INTER/TYPE6/1:Fscale=1 --at 0.1
bad method "only /SOLVER Method 1 (CVODE)" validation/joint_pendulum/case.rad --param /GRAV/1:Fscale_y=-9.81 --at 0.1
bad impvel_tstart "an /IMPVEL that starts after t = 0 (Tstart 0.15 s" validation/impvel_window/case.rad --param /IMPVEL/1:Fscale_y=0.55 --at 0.3

# ricochet fit --jacobian sens: the drop's stiffness scale and damping from
# a noisy trace, started 3x off: the same fit as with finite differences
/usr/bin/python3 - "$tmp/drop.csv" <<'PY' || echo "FAIL sens.fit_data: no data"
import sys, subprocess, tempfile, os
import numpy as np
from netCDF4 import Dataset
d = tempfile.mkdtemp()
nc = os.path.join(d, "t.nc")
subprocess.run([os.environ.get("RC_BIN", "build/ricochet"), "run", "validation/fit_drop/drop.rad", "-o", nc, "-q",
                "--dt-out", "0.002"], check=True)
with Dataset(nc) as f:
    keep = np.array(f["at_event"][:]) == 0
    t, z = np.array(f["time"][:])[keep], np.array(f["body_position"][:])[keep, 0, 2]
os.remove(nc)
os.rmdir(d)
rng = np.random.default_rng(3)
with open(sys.argv[1], "w") as out:
    out.write("t [s], body 1 z [m] +- 0.0005\n")
    for ti, zi in zip(t, z):
        out.write(f"{ti:.12g}, {zi + 0.0005 * rng.standard_normal():.12g}\n")
PY
for J in fd sens; do
    "$bin" fit "$drop" --data "$tmp/drop.csv" --log /INTER/TYPE6/1:FscaleId=60000 --log /INTER/TYPE6/1:Visc=10 -q \
        --jacobian $J --jobs 1 --fitted "$tmp/f_$J.csv" > "$tmp/fit_$J.txt" 2>&1
    echo $? > "$tmp/rc_$J"
done
fd_vals=$(grep "^    fitted" "$tmp/fit_fd.txt" | awk '{print $2, $5}')
sens_vals=$(grep "^    fitted" "$tmp/fit_sens.txt" | awk '{print $2, $5}')
# the same fit: values to 1e-6 and standard errors to 1e-3 (the finite
# differences of whole runs carry the integrator's step sequence; the
# printed digits of two fits at 6e-8 of each other differ)
same=$(paste <(echo "$fd_vals") <(echo "$sens_vals") |
    awk 'NF == 4 { n++; if (($1 - $3) > 1e-6 * $1 || ($3 - $1) > 1e-6 * $1 || ($2 - $4) > 1e-3 * $2 || ($4 - $2) > 1e-3 * $2) bad++ }
         END { print (n == 2 && !bad) ? "yes" : "no" }')
if [ "$(cat "$tmp/rc_sens")" = 0 ] && [ -n "$sens_vals" ] && [ "$same" = yes ] &&
    grep -q "forward sensitivities, one run each" "$tmp/fit_sens.txt"; then
    echo "PASS sens.fit_jacobian: the same fitted values (1e-6) and standard errors (1e-3) as with finite differences ($(echo $sens_vals | tr '\n' ' ') against $(echo $fd_vals | tr '\n' ' ')); $(grep -o '[0-9]* simulations' "$tmp/fit_fd.txt") (fd) against $(grep -o '[0-9]* simulations' "$tmp/fit_sens.txt") (sens)"
else echo "FAIL sens.fit_jacobian: fd [$fd_vals] sens [$sens_vals] (exit $(cat "$tmp/rc_sens")): $(head -c 300 "$tmp/fit_sens.txt")"; fi
# with measured impact quantities (the events' derivatives): the same fit
printf 'inter, impact, quantity, value, sigma\n1, 1, duration [ms], 21.36, 0.2\n1, 1, v_out [m/s], 1.594, 0.01\n1, 1, v_in [m/s], 2.215, 0.01\n1, 1, t_close [s], 0.22576, 0.0005\n' > "$tmp/imp.csv"
for J in fd sens; do
    "$bin" fit "$drop" --data "$tmp/drop.csv" --impacts "$tmp/imp.csv" --log /INTER/TYPE6/1:FscaleId=60000 \
        --log /INTER/TYPE6/1:Visc=10 -q --jacobian $J --jobs 1 --fitted "$tmp/fi_$J.csv" > "$tmp/fiti_$J.txt" 2>&1
    echo $? > "$tmp/rci_$J"
done
same=$(paste <(grep "^    fitted" "$tmp/fiti_fd.txt" | awk '{print $2, $5}') <(grep "^    fitted" "$tmp/fiti_sens.txt" | awk '{print $2, $5}') |
    awk 'NF == 4 { n++; if (($1 - $3) > 1e-6 * $1 || ($3 - $1) > 1e-6 * $1 || ($2 - $4) > 1e-3 * $2 || ($4 - $2) > 1e-3 * $2) bad++ }
         END { print (n == 2 && !bad) ? "yes" : "no" }')
if [ "$(cat "$tmp/rci_sens")" = 0 ] && [ "$same" = yes ]; then
    echo "PASS sens.fit_impacts: with t_close, duration, v_in and v_out measured, the same fitted values (1e-6) and standard errors as with finite differences"
else echo "FAIL sens.fit_impacts: $(grep "^    fitted" "$tmp/fiti_fd.txt" | tr '\n' ' ') against $(grep "^    fitted" "$tmp/fiti_sens.txt" | tr '\n' ' ') (exit $(cat "$tmp/rci_sens"))"; fi
printf 'inter, impact, quantity, value, sigma\n1, 1, fn_max [N], 280, 3\n' > "$tmp/imp2.csv"
"$bin" fit "$drop" --data "$tmp/drop.csv" --free /INTER/TYPE6/1:Visc=10 --impacts "$tmp/imp2.csv" --jacobian sens -q > "$tmp/e" 2>&1; rc=$?
grep -q "covers the impacts' t_close, duration, v_in and v_out, not fn_max" "$tmp/e" && expect fit_impacts_peak 2 $rc "" ||
    expect fit_impacts_peak 2 99 "($(head -c 200 "$tmp/e"))"
"$bin" fit "$drop" --data "$tmp/drop.csv" --free /INTER/TYPE6/1:Visc=10 --jacobian adjoint -q > "$tmp/e" 2>&1; rc=$?
grep -q "expected fd or sens" "$tmp/e" && expect fit_jacobian_name 2 $rc "" || expect fit_jacobian_name 2 99 "($(head -c 200 "$tmp/e"))"
