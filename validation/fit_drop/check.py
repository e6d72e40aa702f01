"""Calibration by `ricochet fit` against synthetic measurements (README.md).

The measurements are simulated by ricochet itself at known parameter values
(`ricochet run --set`), read from the output records and given Gaussian
noise of a known standard deviation (numpy, fixed seed). Each fit starts a
factor 3 away from the answer. Checked:

(a) drop.rad: a ball dropped on a soft TYPE6 floor, z(t) every 2 ms with
    0.5 mm noise: the floor's stiffness (FscaleId, log-scaled) and damping
    (Visc, log-scaled) recovered within their reported 95 % intervals and
    within 2 %; the friction coefficient Fric, free in the same fit, is
    reported UNIDENTIFIABLE (a vertical drop has no sliding: the signal
    does not depend on it).
(b) slide.rad: a block launched at 1 m/s and stopped by Coulomb friction,
    x(t) every 5 ms with 0.5 mm noise, in a file in ms and mm: Fric
    recovered within its 95 % interval and within 2 %.
(c) slide.rad with Fric and the static friction force Sfric both free: on a
    flat floor the friction force is Sfric + Fric m g, so only that sum is
    seen; both are reported UNIDENTIFIABLE (correlation -1), not returned
    as numbers, and the fitted friction force matches the true one.
(f) slide.rad, x(t) at three times only (+- 2 mm) and the stopping
    distance (the persistent contact's slip, contact_slip, +- 0.5 mm):
    Fric within its 95 % interval and within 2 %.
(d) power.rad: the same drop on an /INTER/POWER floor F = K P^m1 +
    C v P^m3 (Hunt-Crossley damping, fixed), z(t) every 1 ms: K
    (log-scaled) and m1 (bounded to 1..2.5) within their 95 % intervals; m1
    within 2 %; K, which trades off against m1 (correlation 0.999), within
    15 %, and the force at the peak penetration, K P^m1, within 2 %.
(e) drop.rad again, z(t) only every 10 ms (too coarse to resolve the
    21 ms contact) with its uncertainty stated, and the impact's measured
    duration, rebound speed and peak force (--impacts, each with its
    uncertainty): stiffness and damping within their 95 % intervals and
    within 2 %.
"""
import os
import re
import subprocess
import sys
import time

import numpy as np
from netCDF4 import Dataset

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
G, M = 9.81, 1.0
K_TRUE, C_TRUE, MU_DROP = 2.0e4, 30.0, 0.2     # drop.rad: N/m, N s/m, -
MU_TRUE = 0.3                                   # slide.rad
KP_TRUE, M1_TRUE, P_PEAK = 6.0e5, 1.5, 0.0087584  # power.rad: N/m^m1, -, peak penetration [m]
SIGMA = 5e-4                                    # noise standard deviation [m]
# one seed per measurement; over seeds 0..29 the true values fell inside the
# reported 95 % intervals in 29 of 30 fits for each parameter (README.md)
SEED_DROP, SEED_SLIDE, SEED_POWER, SEED_IMPACTS, SEED_STOP = 1, 2, 3, 5, 6
IMPACT_SIGMA = {"duration [ms]": 0.2, "v_out [m/s]": 0.01, "fn_max [N]": 3.0}  # the impacts' uncertainties
# the decks' own tolerance, tight enough that the integrator's error (rtol
# 1e-9 of the signals) stays far below the noise; ricochet's default (1e-8)
# in the defaults mode
RTOL = [] if rcval.DEFAULTS else ["--rtol", "1e-9"]
METHOD = ["--method", rcval.METHOD] if rcval.METHOD else []


def simulate(deck, sets, dt_out, impacts=False):
    """The deck run at the --set values; (times, positions [n, 3]) of the
    records at the output times (not the event records), and with impacts
    the first impact's duration [ms], rebound speed [m/s], peak force [N]."""
    out = os.path.join(rcval.tmpdir(), "truth.nc")
    cmd = [rcval.RICOCHET, "run", os.path.join(HERE, deck), "-o", out, "-q", "--dt-out", str(dt_out)] + RTOL + METHOD
    for s in sets:
        cmd += ["--set", s]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"ricochet run failed ({p.returncode}): {p.stderr.strip()}")
    with Dataset(out) as nc:
        keep = np.array(nc["at_event"][:]) == 0
        t, x = np.array(nc["time"][:])[keep], np.array(nc["body_position"][:])[keep, 0, :]
        if impacts:
            return t, x, {"duration [ms]": 1e3 * float(nc["impact_duration"][0]),
                          "v_out [m/s]": float(nc["impact_speed_out"][0]),
                          "fn_max [N]": float(nc["impact_peak_force"][0])}
        return t, x


def write_csv(path, header, t, v, rng, t_unit=1.0, v_unit=1.0):
    """Measured-looking data: v + N(0, SIGMA), in the units of the header."""
    noisy = v + rng.normal(0.0, SIGMA, size=v.shape)
    with open(path, "w") as f:
        f.write("# synthetic measurement: ricochet at known parameters + Gaussian noise (validation/fit_drop)\n")
        f.write(header + "\n")
        for ti, vi in zip(t, noisy):
            f.write(f"{ti / t_unit:.9g}, {vi / v_unit:.9g}\n")


def fit(deck, data, free, extra=()):
    """Run ricochet fit; (exit code, report text, wall time [s])."""
    d = rcval.tmpdir()
    cmd = [rcval.RICOCHET, "fit", os.path.join(HERE, deck), "--data", data, "-q", "--fitted",
           os.path.join(d, "fitted.csv"), "-o", os.path.join(d, "report.txt")] + RTOL + METHOD + list(extra)
    for kind, arg in free:
        cmd += [kind, arg]
    t0 = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode not in (0, 1):
        raise RuntimeError(f"ricochet fit failed ({p.returncode}): {p.stderr.strip()}")
    return p.returncode, p.stdout, wall, os.path.join(d, "fitted.csv")


def parameters(report):
    """{CARD:FIELD: (value, se, lo95, hi95) or 'UNIDENTIFIABLE ...'} from the report."""
    out, name = {}, None
    for ln in report.splitlines():
        m = re.match(r"^  (/\S+)", ln)
        if m:
            name = m.group(1)
            continue
        m = re.match(r"^    fitted (\S+)  standard error (\S+) .*95% interval \[(\S+), (\S+)\]", ln)
        if m and name:
            out[name] = tuple(float(x) for x in m.groups())
        elif name and ln.startswith("    UNIDENTIFIABLE"):
            out[name] = ln.strip()
    return out


def cost(report):
    m = re.search(r"^cost: (\d+) iterations.* (\d+) simulations", report, re.M)
    return f"{m.group(1)} iterations, {m.group(2)} simulations" if m else "?"


def recovered(name, got, truth, tol=0.02):
    if not isinstance(got, tuple):
        rcval.check(name, False, f"not identified: {got}")
        return
    v, se, lo, hi = got
    ok = lo <= truth <= hi and abs(v - truth) <= tol * abs(truth)
    rcval.check(name, ok, f"fitted {v:.6g} +- {se:.3g} (95 % [{lo:.6g}, {hi:.6g}]), true {truth:g}: "
                f"{'inside' if lo <= truth <= hi else 'OUTSIDE'} the interval, error {abs(v - truth) / truth:.2e} "
                f"(< {tol:g})")


def main():
    # (a) drop: stiffness and damping from z(t); Fric unidentifiable
    t, x = simulate("drop.rad", [f"/INTER/TYPE6/1:FscaleId={K_TRUE:g}", f"/INTER/TYPE6/1:Visc={C_TRUE:g}"], 0.002)
    data = os.path.join(rcval.tmpdir(), "drop.csv")
    write_csv(data, "t [s], body 1 z [m]", t, x[:, 2], np.random.default_rng(SEED_DROP))
    rc, rep, wall, _ = fit("drop.rad", data, [("--log", f"/INTER/TYPE6/1:FscaleId={3 * K_TRUE:g}"),
                                               ("--log", f"/INTER/TYPE6/1:Visc={C_TRUE / 3:g}"),
                                               ("--free", "/INTER/TYPE6/1:Fric=0.5,0:1")])
    p = parameters(rep)
    rcval.check("fit_drop.drop_converged", rc == 0 and "status: converged" in rep,
                f"{len(t)} samples of z, started 3x off: {cost(rep)}, {wall:.2f} s wall")
    recovered("fit_drop.drop_stiffness", p.get("/INTER/TYPE6/1:FscaleId"), K_TRUE)
    recovered("fit_drop.drop_damping", p.get("/INTER/TYPE6/1:Visc"), C_TRUE)
    u = p.get("/INTER/TYPE6/1:Fric")
    rcval.check("fit_drop.drop_friction_unidentifiable", isinstance(u, str) and "UNIDENTIFIABLE" in u,
                f"Fric in a vertical drop: {u}")

    # (b) slide: the Coulomb coefficient from x(t), the file in ms and mm
    t, x = simulate("slide.rad", [f"/INTER/TYPE6/1:Fric={MU_TRUE:g}"], 0.005)
    data = os.path.join(rcval.tmpdir(), "slide.csv")
    write_csv(data, "t [ms], body 1 x [mm]", t, x[:, 0], np.random.default_rng(SEED_SLIDE), 1e-3, 1e-3)
    rc, rep, wall, fitted = fit("slide.rad", data, [("--free", f"/INTER/TYPE6/1:Fric={MU_TRUE / 3:g},0:1")])
    p = parameters(rep)
    rcval.check("fit_drop.slide_converged", rc == 0 and "status: converged" in rep,
                f"{len(t)} samples of x (ms, mm), started 3x off: {cost(rep)}, {wall:.2f} s wall")
    recovered("fit_drop.slide_friction", p.get("/INTER/TYPE6/1:Fric"), MU_TRUE)
    # the fitted signals file: measured and fitted columns, residual at the noise level
    f = np.genfromtxt(fitted, delimiter=",", skip_header=1)
    rms = np.sqrt(np.mean((f[:, 2] - f[:, 1]) ** 2)) * 1e-3
    rcval.check("fit_drop.slide_fitted_csv", f.shape == (len(t), 3) and 0.7 * SIGMA < rms < 1.3 * SIGMA,
                f"measured against fitted x: RMS {rms:.3g} m, noise {SIGMA:g} m")

    # (d) power law: K and m1 from z(t)
    t, x = simulate("power.rad", [f"/INTER/POWER/1:K={KP_TRUE:g}", f"/INTER/POWER/1:m1={M1_TRUE:g}"], 0.001)
    data_p = os.path.join(rcval.tmpdir(), "power.csv")
    write_csv(data_p, "t [s], body 1 z [m]", t, x[:, 2], np.random.default_rng(SEED_POWER))
    rc, rep, wall, _ = fit("power.rad", data_p, [("--log", f"/INTER/POWER/1:K={3 * KP_TRUE:g}"),
                                                ("--free", "/INTER/POWER/1:m1=1.2,1:2.5")])
    p = parameters(rep)
    rcval.check("fit_drop.power_converged", rc == 0 and "status: converged" in rep,
                f"{len(t)} samples of z, K started 3x off, m1 at 1.2: {cost(rep)}, {wall:.2f} s wall")
    recovered("fit_drop.power_exponent", p.get("/INTER/POWER/1:m1"), M1_TRUE)
    recovered("fit_drop.power_stiffness", p.get("/INTER/POWER/1:K"), KP_TRUE, tol=0.15)
    kp, mp = p.get("/INTER/POWER/1:K"), p.get("/INTER/POWER/1:m1")
    if isinstance(kp, tuple) and isinstance(mp, tuple):
        f_fit, f_true = kp[0] * P_PEAK ** mp[0], KP_TRUE * P_PEAK ** M1_TRUE
        rcval.check("fit_drop.power_peak_force", abs(f_fit - f_true) < 0.02 * f_true,
                    f"K P^m1 at the peak penetration {P_PEAK * 1e3:.2f} mm: {f_fit:.1f} N, true {f_true:.1f} N, "
                    f"error {abs(f_fit - f_true) / f_true:.2e} (< 0.02)")
    else:
        rcval.check("fit_drop.power_peak_force", False, f"K {kp}, m1 {mp}")

    # (e) impacts: a coarse z(t) and the impact's duration, rebound speed and
    # peak force, each with its uncertainty
    t, x, imp = simulate("drop.rad", [f"/INTER/TYPE6/1:FscaleId={K_TRUE:g}", f"/INTER/TYPE6/1:Visc={C_TRUE:g}"],
                         0.01, impacts=True)
    rng = np.random.default_rng(SEED_IMPACTS)
    data_i = os.path.join(rcval.tmpdir(), "coarse.csv")
    write_csv(data_i, f"t [s], body 1 z [m] +- {SIGMA:g}", t, x[:, 2], rng)
    imp_csv = os.path.join(rcval.tmpdir(), "impacts.csv")
    with open(imp_csv, "w") as f:
        f.write("# the first impact of the drop, measured\ninter, impact, quantity, value, sigma\n")
        for q, v in imp.items():
            f.write(f"1, 1, {q}, {v + rng.normal(0.0, IMPACT_SIGMA[q]):.6g}, {IMPACT_SIGMA[q]:g}\n")
    rc, rep, wall, _ = fit("drop.rad", data_i, [("--log", f"/INTER/TYPE6/1:FscaleId={3 * K_TRUE:g}"),
                                                 ("--log", f"/INTER/TYPE6/1:Visc={C_TRUE / 3:g}")],
                           ["--impacts", imp_csv])
    p = parameters(rep)
    chi = re.search(r"chi-square / dof = (\S+)", rep)
    rcval.check("fit_drop.impacts_converged", rc == 0 and "status: converged" in rep and chi is not None,
                f"{len(t)} samples of z (10 ms) and 3 impact quantities, started 3x off: {cost(rep)}, {wall:.2f} s "
                f"wall, chi-square / dof {chi.group(1) if chi else '?'}")
    recovered("fit_drop.impacts_stiffness", p.get("/INTER/TYPE6/1:FscaleId"), K_TRUE)
    recovered("fit_drop.impacts_damping", p.get("/INTER/TYPE6/1:Visc"), C_TRUE)

    # (f) the stopping distance and three positions
    out = os.path.join(rcval.tmpdir(), "stop.nc")
    subprocess.run([rcval.RICOCHET, "run", os.path.join(HERE, "slide.rad"), "-o", out, "-q", "--dt-out", "0.1",
                    "--set", f"/INTER/TYPE6/1:Fric={MU_TRUE:g}"] + RTOL + METHOD, check=True)
    with Dataset(out) as nc:
        keep = np.array(nc["at_event"][:]) == 0
        t, x = np.array(nc["time"][:])[keep], np.array(nc["body_position"][:])[keep, 0, 0]
        slip = float(nc["persistent_slip_distance"][0])
    rng = np.random.default_rng(SEED_STOP)
    pick = [1, 2, 5]  # 0.1, 0.2 and 0.5 s: before and after the stop at 0.34 s
    data_s = os.path.join(rcval.tmpdir(), "stop.csv")
    with open(data_s, "w") as f:
        f.write("t [s], body 1 x [m] +- 0.002\n")
        for k in pick:
            f.write(f"{t[k]:.9g}, {x[k] + rng.normal(0.0, 0.002):.9g}\n")
    stop_csv = os.path.join(rcval.tmpdir(), "stop_contact.csv")
    with open(stop_csv, "w") as f:
        f.write(f"inter, number, quantity, value, sigma\n1, 1, contact_slip [mm], "
                f"{1e3 * slip + rng.normal(0.0, 0.5):.6g}, 0.5\n")
    rc, rep, wall, _ = fit("slide.rad", data_s, [("--free", f"/INTER/TYPE6/1:Fric={MU_TRUE / 3:g},0:1")],
                           ["--impacts", stop_csv])
    p = parameters(rep)
    rcval.check("fit_drop.stop_converged", rc == 0 and "status: converged" in rep,
                f"3 positions and the stopping distance {slip * 1e3:.2f} mm (+- 0.5 mm): {cost(rep)}, {wall:.2f} s wall")
    recovered("fit_drop.stop_friction", p.get("/INTER/TYPE6/1:Fric"), MU_TRUE)

    # (c) Fric and Sfric together: only Sfric + Fric m g is seen
    rc, rep, wall, _ = fit("slide.rad", data, [("--free", f"/INTER/TYPE6/1:Fric={MU_TRUE / 3:g},0:1"),
                                                ("--free", "/INTER/TYPE6/1:Sfric=0.5,0:5")])
    p = parameters(rep)
    both = [p.get("/INTER/TYPE6/1:Fric"), p.get("/INTER/TYPE6/1:Sfric")]
    ok = all(isinstance(u, str) and "UNIDENTIFIABLE" in u and "correlation -1.0" in u for u in both)
    # the friction force they give together
    m = re.search(r"--set /INTER/TYPE6/1:Fric=\S+", rep)
    vals = [float(re.search(r"left at (\S+)", u).group(1)) if isinstance(u, str) else np.nan for u in both]
    force = vals[1] + vals[0] * M * G
    ok = ok and m is None and abs(force - MU_TRUE * M * G) < 0.01 * MU_TRUE * M * G
    rcval.check("fit_drop.slide_sfric_fric_unidentifiable", ok,
                f"Fric and Sfric both free: both UNIDENTIFIABLE (correlation -1), Sfric + Fric m g = {force:.4g} N "
                f"against {MU_TRUE * M * G:.4g} N; {cost(rep)}, {wall:.2f} s wall")
    rcval.finish()


def coverage(n=30):
    """The intervals' coverage over seeds 0..n-1 (not part of the checks:
    `python3 check.py --coverage`): how often the true values fall inside
    the reported 95 % intervals, and the mean and spread of (fitted - true)
    / standard error (0 and 1 for honest intervals)."""
    runs = [("drop.rad", 2, "t [s], body 1 z [m]", 1.0, 0.002,
             [f"/INTER/TYPE6/1:FscaleId={K_TRUE:g}", f"/INTER/TYPE6/1:Visc={C_TRUE:g}"],
             [("--log", f"/INTER/TYPE6/1:FscaleId={3 * K_TRUE:g}"), ("--log", f"/INTER/TYPE6/1:Visc={C_TRUE / 3:g}")],
             {"/INTER/TYPE6/1:FscaleId": K_TRUE, "/INTER/TYPE6/1:Visc": C_TRUE}),
            ("power.rad", 2, "t [s], body 1 z [m]", 1.0, 0.001,
             [f"/INTER/POWER/1:K={KP_TRUE:g}", f"/INTER/POWER/1:m1={M1_TRUE:g}"],
             [("--log", f"/INTER/POWER/1:K={3 * KP_TRUE:g}"), ("--free", "/INTER/POWER/1:m1=1.2,1:2.5")],
             {"/INTER/POWER/1:K": KP_TRUE, "/INTER/POWER/1:m1": M1_TRUE}),
            ("slide.rad", 0, "t [ms], body 1 x [mm]", 1e-3, 0.005, [f"/INTER/TYPE6/1:Fric={MU_TRUE:g}"],
             [("--free", f"/INTER/TYPE6/1:Fric={MU_TRUE / 3:g},0:1")], {"/INTER/TYPE6/1:Fric": MU_TRUE})]
    for deck, axis, header, unit, dt, sets, free, truth in runs:
        t, x = simulate(deck, sets, dt)
        z = {k: [] for k in truth}
        inside = {k: 0 for k in truth}
        for seed in range(n):
            data = os.path.join(rcval.tmpdir(), "data.csv")
            write_csv(data, header, t, x[:, axis], np.random.default_rng(seed), unit, unit)
            p = parameters(fit(deck, data, free)[1])
            for k, v in truth.items():
                z[k].append((p[k][0] - v) / p[k][1])
                inside[k] += p[k][2] <= v <= p[k][3]
        for k, zz in z.items():
            zz = np.array(zz)
            print(f"{deck} {k}: inside the reported 95 % interval {inside[k]} of {n}; "
                  f"(fitted - true) / se: mean {zz.mean():.2f}, std {zz.std():.2f}")


if __name__ == "__main__":
    if "--coverage" in sys.argv:
        coverage()
    elif "--write-case" in sys.argv:
        print("fit_drop: drop.rad and slide.rad are written by hand (README.md)")
    else:
        main()
