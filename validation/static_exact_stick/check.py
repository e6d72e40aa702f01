"""Static analysis (/SOLVER Method 3) with exact stick (TYPE6 Istick 1, /FRICTION Iform 3).

A sphere (m = 1 kg, R = 0.05 m) exactly touching the fixed plane z = 0, its
rotations held by /BCS (a sphere rolls: without it a tangential load has no
static equilibrium), TYPE6 linear contact k = 1e5 N/m, friction Fric = mu =
0.3 with exact stick: no stick spring; the friction force is an unknown of
the equilibrium and the contact point's tangential displacement since it
stuck is held at zero (docs/theory.md 7.8, "Exact stick"). Gravity is tilted
from the vertical by theta (/GRAV X and Z, both times one /FUNCT f(t)).

case.rad: theta = 0.4 rad > atan(mu), Sfric = 1 N, f = t / t_end: the sphere
sticks with no tangential displacement at all (F_t = m g sin(theta) f, F_n =
m g cos(theta) f, x = 0) until m g f (sin(theta) - mu cos(theta)) reaches
Sfric; then no static equilibrium exists: the run ends with an error naming
the sliding interface and the load time, which must bracket the closed-form
onset within the load-step resolution.
case_iform3.rad: the same with /FRICTION Iform 3 (Coulomb, Fric 0.3) on the
contact and Sfric = 0, theta = atan(mu) - 0.01, and the sphere's y held by
/BCS as well (a support that holds a tangential direction of the contact:
there the support carries the load, the friction force's y part is 0):
sticks through the ramp, x = 0.
case_static.rad: a static coefficient Fric_s = 0.4 above Fric = 0.2, theta
= 0.3 rad (mu < tan(theta) = 0.309 < mu_s): the static coefficient holds it
through the ramp (F_t = m g sin(theta) f, x = 0); case_static_above.rad:
theta = atan(0.4) + 0.01: no equilibrium from the first load on.
case_cylinder.rad: a cylinder (2 kg, R = 0.05 m, length 0.3 m, rotations
held) lying across a real incline of alpha = 0.25 rad < atan(mu) (the plane
through the origin with normal (-sin(alpha), 0, cos(alpha)); its contact
plane is not a coordinate plane), vertical gravity ramped: stuck, its
centre moves only along the normal, by m g cos(alpha) f / k, not at all
along the slope; the friction force m g sin(alpha) f up the slope.
case_slide.rad: theta = 0.4, Sfric = 0.5 N, a horizontal spring (k_s = 100
N/m) to a fixed point: f rises to 1 (the sphere slides, held by the spring:
equilibria in slip at F = Sfric + mu F_n) and falls to 0.2 (it sticks again,
where it is). Reference: the mapping solved per record in closed form
(slide_reference: stuck, x stays; where the force that holds it exceeds the
limit, slip at the limit); the fric_slip and fric_stick events at the first
load steps that slide and stick again.
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e5, 9.81
MU = 0.3
T_END, DT_OUT = 1.0, 0.05
TOL = 1e-9
THETA = 0.4                      # case.rad, case_slide.rad: tilt of gravity [rad]
SFRIC = 1.0                      # case.rad: Sfric [N]
DTH = 0.01
ATAN = math.atan(MU)
MU_K, MU_S, THETA_S = 0.2, 0.4, 0.3   # case_static: sliding and static coefficients, tilt [rad]


def sphere_on_floor(d, bcs="000 111"):
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    add_sphere_over_plane(d, M, R, R, title="sphere")
    d.bcs(1, 1, bcs, title="rotations held" if bcs == "000 111" else "rotations and y held")


def tilted(theta):
    """gravity's components per unit f, as read from the deck (12 digits)."""
    return float(f"{G * math.sin(theta):.12g}"), float(f"{-G * math.cos(theta):.12g}")


def deck_tilt(theta, sfric, fx, fy, title, fric=MU, fric_s=None, card=False, run=(T_END, DT_OUT), method=3, preload=0):
    d = Deck(title)
    sphere_on_floor(d, "010 111" if card else "000 111")
    d.funct(2, fx, fy, title="load factor f(t)")
    gx, gz = tilted(theta)
    d.grav_fct(1, "X", gx, 2)
    d.grav_fct(2, "Z", gz, 2)
    if card:
        d.friction(1, iform=3, fric=fric, title="Coulomb, exact stick (Iform 3)")
        d.type6(1, 1, 2, 1, fric=fric, title="sphere - floor")
    else:
        d.type6(1, 1, 2, 1, sfric=sfric if sfric else None, fric=fric, istick=1, fric_s=fric_s,
                title="sphere - floor, exact stick")
    d.run(*run)
    d.solver(method=method, preload=preload)
    return d


RAMP = ([0.0, T_END], [0.0, 1.0])
SLIDE = ([0.0, 0.5, 1.0], [0.0, 1.0, 0.2])                           # case_slide: load past the limit, unload
SF_SLIDE, KS, XA = 0.5, 100.0, -1.0      # case_slide: Sfric [N], spring [N/m], its fixed point's x [m]


ALPHA, MC, RC, LC = 0.25, 2.0, 0.05, 0.3   # case_cylinder: incline [rad], mass [kg], radius, length [m]


def incline_geometry():
    """the incline's unit normal n and its fall line's upward tangent t (read from the deck: 12 digits)."""
    n = np.array([float(f"{-math.sin(ALPHA):.12g}"), 0.0, float(f"{math.cos(ALPHA):.12g}")])
    n /= np.linalg.norm(n)
    return n, np.array([n[2], 0.0, -n[0]])


def deck_cylinder():
    """a cylinder lying across a real incline (its axis along y), vertical gravity ramped."""
    d = Deck("static exact stick: a cylinder lying across an incline of 0.25 rad, gravity ramped")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    n, _ = incline_geometry()
    c = RC * n
    d.nodes([(1, c[0], c[1], c[2])])
    j = MC * (3 * RC * RC + LC * LC) / 12
    d.rbody(1, 1, MC, [j, 0.5 * MC * RC * RC, j], title="cylinder")
    d.cylinder(1, 1, tuple(c), (0.0, 1.0, 0.0), RC, LC, title="cylinder, axis y")
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title="incline through the origin")
    d.grnod(1, [1])
    d.bcs(1, 1, "000 111", title="rotations held")
    d.funct(2, *RAMP, title="load factor f(t)")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, fric=MU, istick=1, title="cylinder - incline, exact stick")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


HOLD = ([0.0, T_END], [1.0, 1.0])        # case_preload: the full load from t = 0
T_PRE = 0.2                              # case_preload: the dynamic run's end [s]


def deck_preload():
    return deck_tilt(ATAN - DTH, 0.0, *HOLD, "static exact stick: preloaded, then IDA at rest", run=(T_PRE, 0.01),
                     method=2, preload=1)


def deck_slide(fric=MU, fric_s=None, title="static exact stick: slides against a spring, sticks where it is"):
    d = deck_tilt(THETA, SF_SLIDE, *SLIDE, title, fric=fric, fric_s=fric_s)
    d.spring(3, 1, (0.0, 0.0, R), 0, (XA, 0.0, R), iform=1, a=KS, title="horizontal spring")
    return d


MU_SK, MU_SS = 0.25, 0.35        # case_slide_static: sliding and static coefficients


def slide_reference(ts, mu=MU, mu_s=None):
    """The equilibria at the times ts: stuck, the sphere's x stays where it
    stuck (z and the friction force F from the balance, Newton to rounding);
    where |F| would exceed L = Sfric + mu F_n, slip: F = L along it (x, z
    from the balance). Returns per time (x, z, F, F_n, L, mode)."""
    gx, gz = tilted(THETA)
    L0 = -XA
    mu_s = mu if mu_s is None else mu_s
    x0, z0, out, slid = 0.0, R, [], False
    for t in ts:
        f = float(np.interp(t, *SLIDE))

        def forces(x, z):
            dx, dz = x - XA, z - R
            ln = math.hypot(dx, dz)
            fs, Fn = -KS * (ln - L0), K * (R - z)
            return M * gx * f + fs * dx / ln, M * gz * f + Fn + fs * dz / ln, Fn

        # stuck: x = x0, z from the normal balance, F = -(the other x forces)
        z, h = z0, 1e-7
        for _ in range(100):
            dz = -forces(x0, z)[1] / ((forces(x0, z + h)[1] - forces(x0, z - h)[1]) / (2 * h))
            z += dz
            if abs(dz) < 1e-17:
                break
        fx, _, Fn = forces(x0, z)
        # the test: the stick limit, or the sliding one for a contact that slid at the last equilibrium
        q = (x0, z, -fx, Fn, SF_SLIDE + (mu if slid else mu_s) * Fn, "stick")
        if abs(q[2]) > q[4]:
            sg = math.copysign(1.0, q[2])

            def res(x, z):
                fx, fz, Fn = forces(x, z)
                return np.array([fx + sg * (SF_SLIDE + mu * Fn), fz])
            x, z = x0, z
            for _ in range(100):
                J = np.column_stack([(res(x + h, z) - res(x - h, z)) / (2 * h), (res(x, z + h) - res(x, z - h)) / (2 * h)])
                dxz = np.linalg.solve(J, -res(x, z))
                x, z = x + dxz[0], z + dxz[1]
                if abs(dxz).max() < 1e-16:
                    break
            Fn = K * (R - z)
            q = (x, z, sg * (SF_SLIDE + mu * Fn), Fn, SF_SLIDE + mu * Fn, "slip")
        x0, z0, slid = q[0], q[1], q[5] == "slip"
        out.append(q)
    return out


def cases():
    return {"case.rad": deck_tilt(THETA, SFRIC, *RAMP, "static exact stick: gravity tilted by 0.4 rad, ramped; Sfric holds it until the onset"),
            "case_iform3.rad": deck_tilt(ATAN - DTH, 0.0, *RAMP, "static exact stick (/FRICTION Iform 3): below atan(mu): sticks", card=True),
            "case_static.rad": deck_tilt(THETA_S, 0.0, *RAMP, "static exact stick: the static coefficient 0.4 holds it at tan(theta) = 0.309 > mu",
                                         fric=MU_K, fric_s=MU_S),
            "case_static_above.rad": deck_tilt(math.atan(MU_S) + DTH, 0.0, *RAMP, "static exact stick: above atan(mu_s): slides at once",
                                               fric=MU_K, fric_s=MU_S),
            "case_slide.rad": deck_slide(),
            "case_slide_static.rad": deck_slide(MU_SK, MU_SS, "static exact stick: Fric_s 0.35 > Fric 0.25: sticks "
                                                "to the static limit, slides at the sliding one"),
            "case_preload.rad": deck_preload(),
            "case_cylinder.rad": deck_cylinder()}


def run_expect_failure(name):
    d = rcval.tmpdir()
    out = os.path.join(d, name.replace(".rad", ".nc"))
    cmd = [rcval.RICOCHET, "run", os.path.join(HERE, name), "-o", out, "-q", "--method", "static"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stderr, out


def failure(err):
    mt = re.search(r"no static equilibrium at the load time t = ([0-9.eE+-]+) s", err)
    ml = re.search(r"the last equilibrium at t = ([0-9.eE+-]+) s, load substeps down to ([0-9.eE+-]+) s", err)
    named = "/INTER/TYPE6/1" in err and "friction can hold" in err and "slides" in err
    return (float(mt.group(1)), float(ml.group(1)), float(ml.group(2))) if (mt and ml and named) else None


def stick_errors(r, theta, f):
    """max errors of the friction force, normal force (of m g) and the tangential displacement [m] against the closed forms."""
    gx, gz = tilted(theta)
    Ft, Fn = M * gx * f, -M * gz * f
    eF = float(np.abs(r.ffric[:, 0, 0] + Ft).max() / (M * G))
    eFo = float(np.abs(r.ffric[:, 0, 1:]).max() / (M * G))
    eN = float(np.abs(r.fn[:, 0] - Fn).max() / (M * G))
    ex = float(np.abs(r.pos[:, 0, :2]).max())
    return max(eF, eFo), eN, ex


XTOL = 1e-15                     # the stuck displacement [m]: exact to the solver's rounding


def main():
    rcval.METHOD = "static" if rcval.METHOD else ""
    # (a) theta > atan(mu), ramped: Sfric + mu F_n holds it, x = 0, until f* (closed form)
    gx, gz = tilted(THETA)
    ts = SFRIC / (M * (gx + MU * gz)) * T_END
    rc, err, out = run_expect_failure("case.rad")
    fl = failure(err)
    rcval.check("static_exact_stick.onset_refused", rc != 0 and fl is not None,
                f"exit code {rc}; message: {err.strip()[:500]!r}")
    if fl:
        t_fail, t_last, dts = fl
        rcval.check("static_exact_stick.onset_time", t_last <= ts <= t_fail and t_fail - t_last <= 2.0 * dts * (1 + 1e-9),
                    f"onset f* = Sfric / (m g (sin(theta) - mu cos(theta))) at t* = {ts:.9f} s: last equilibrium "
                    f"{t_last:.9f} s ({ts - t_last:.2e} s before), no equilibrium at {t_fail:.9f} s (load substep "
                    f"{dts:.3g} s)")
    r = rcval.Result(out)
    eF, eN, ex = stick_errors(r, THETA, r.t / T_END)
    rcval.check("static_exact_stick.onset_stick", (r.t < ts).all() and max(eF, eN) < TOL and ex < XTOL and not r.slip.any(),
                f"{len(r.t)} records up to t = {r.t[-1]:g} s: max |F_t - m g sin(theta) f| / (m g) {eF:.2e}, "
                f"|F_n - m g cos(theta) f| / (m g) {eN:.2e} (< {TOL:g}); tangential displacement max |x|, |y| "
                f"{ex:.2e} m (< {XTOL:g} m; a stick spring K_t would give F_t / K_t)")
    # (b) /FRICTION Iform 3 below atan(mu): sticks through the ramp, x = 0
    r = rcval.Result(rcval.run_case("case_iform3.rad", keep_solver=True))
    eF, eN, ex = stick_errors(r, ATAN - DTH, r.t / T_END)
    rcval.check("static_exact_stick.iform3_sticks", len(r.t) == 21 and max(eF, eN) < TOL and ex < XTOL and not r.slip.any(),
                f"theta = atan(mu) - {DTH:g}: {len(r.t)} records; max rel. errors of F_t {eF:.2e}, F_n {eN:.2e}; "
                f"max |x|, |y| {ex:.2e} m; F_t at the end {r.ffric[-1, 0, 0]:.12g} N "
                f"(closed form {-M * tilted(ATAN - DTH)[0]:.12g} N)")
    # (c) the static coefficient holds it where the sliding one would not
    r = rcval.Result(rcval.run_case("case_static.rad", keep_solver=True))
    eF, eN, ex = stick_errors(r, THETA_S, r.t / T_END)
    rcval.check("static_exact_stick.static_coefficient", len(r.t) == 21 and max(eF, eN) < TOL and ex < XTOL and not r.slip.any(),
                f"mu = {MU_K:g} < tan(theta) = {math.tan(THETA_S):.4f} < mu_s = {MU_S:g}: {len(r.t)} records; max rel. "
                f"errors of F_t {eF:.2e}, F_n {eN:.2e}; max |x|, |y| {ex:.2e} m")
    rc, err, out = run_expect_failure("case_static_above.rad")
    fl = failure(err)
    rcval.check("static_exact_stick.static_above", rc != 0 and fl is not None and fl[0] <= 1e-6 * DT_OUT * 2,
                f"theta = atan(mu_s) + {DTH:g}: exit code {rc}, first load time without equilibrium "
                f"{fl[0] if fl else float('nan'):.3g} s; message: {err.strip()[:300]!r}")
    # (d) slides against the spring (equilibria in slip), sticks where it is on unloading
    r = rcval.Result(rcval.run_case("case_slide.rad", keep_solver=True))
    ref = slide_reference(r.t)
    ex = max(abs(float(r.pos[k, 0, 0]) - ref[k][0]) for k in range(len(r.t)))
    eF = max(max(abs(float(r.ffric[k, 0, 0]) - ref[k][2]), abs(float(r.fn[k, 0]) - ref[k][3])) for k in range(len(r.t))) / (M * G)
    modes = [int(x) for x in r.slip[:, 0]]
    want = [1 if q[5] == "slip" else 0 for q in ref]
    first_slip = next(float(r.t[k]) for k in range(len(r.t)) if want[k])
    first_stick = next(float(r.t[k]) for k in range(len(r.t)) if r.t[k] > first_slip and not want[k])
    evs = [(round(float(t), 12), k) for t, k in zip(r.ev_t, r.ev_kind) if k.startswith("fric")]
    # the load level of the onset: the first record that slides carries F = Sfric + mu F_n
    k1 = next(k for k in range(len(r.t)) if want[k])
    eL = abs(abs(float(r.ffric[k1, 0, 0])) - (SF_SLIDE + MU * float(r.fn[k1, 0]))) / (M * G)
    rcval.check("static_exact_stick.slide_equilibria", len(r.t) == 21 and ex < 1e-12 and eF < TOL and modes == want,
                f"max |x - x_ref| {ex:.2e} m (< 1e-12 m), max |F_t - F_ref|, |F_n - F_ref| / (m g) {eF:.2e} (< {TOL:g}); "
                f"slip flags {''.join(map(str, modes))} (reference {''.join(map(str, want))}); x at the peak "
                f"{float(r.pos[10, 0, 0]):.12e} m (reference {ref[10][0]:.12e} m); sliding from t = {first_slip:g} s at "
                f"|F_t| = Sfric + mu F_n to {eL:.1e} of m g")
    rcval.check("static_exact_stick.slide_events", evs == [(first_slip, "fric_slip"), (first_stick, "fric_stick")],
                f"events {evs} (expected fric_slip at {first_slip:g} s, the first load step that slides, fric_stick at "
                f"{first_stick:g} s, the first after the peak)")
    # (d') a static coefficient above the sliding one: stuck to L_s, then sliding at L (the spring takes the drop)
    r = rcval.Result(rcval.run_case("case_slide_static.rad", keep_solver=True))
    ref = slide_reference(r.t, MU_SK, MU_SS)
    ex = max(abs(float(r.pos[k, 0, 0]) - ref[k][0]) for k in range(len(r.t)))
    eF = max(max(abs(float(r.ffric[k, 0, 0]) - ref[k][2]), abs(float(r.fn[k, 0]) - ref[k][3])) for k in range(len(r.t))) / (M * G)
    modes = [int(x) for x in r.slip[:, 0]]
    want = [1 if q[5] == "slip" else 0 for q in ref]
    rcval.check("static_exact_stick.slide_static_coefficient", len(r.t) == 21 and ex < 1e-12 and eF < TOL and modes == want,
                f"Fric_s {MU_SS:g}, Fric {MU_SK:g}: max |x - x_ref| {ex:.2e} m, forces {eF:.2e} of m g; slip flags "
                f"{''.join(map(str, modes))} (reference {''.join(map(str, want))}); x at the peak "
                f"{float(r.pos[10, 0, 0]):.12e} m (reference {ref[10][0]:.12e} m)")
    # (d'') a cylinder across a real incline: the contact plane not a coordinate plane
    r = rcval.Result(rcval.run_case("case_cylinder.rad", keep_solver=True))
    n, tv = incline_geometry()
    f = r.t / T_END
    dx = r.pos[:, 0, :] - r.pos[0, 0, :]
    eT = float(np.abs(dx @ tv).max())
    eY = float(np.abs(dx[:, 1]).max())
    eP = float(np.abs(dx @ n + MC * G * n[2] * f / K).max())
    # the contact's friction force on the cylinder: m g sin(alpha) f up the slope, in the plane
    eF = float(np.abs(r.ffric[:, 0, :] - np.outer(MC * G * math.sin(ALPHA) * f, tv)).max() / (MC * G))
    eN = float(np.abs(r.fn[:, 0] - MC * G * n[2] * f).max() / (MC * G))
    rcval.check("static_exact_stick.cylinder_incline", len(r.t) == 21 and eT < 1e-14 and eY < 1e-14 and eP < 1e-9 * MC * G / K
                and max(eF, eN) < TOL and not r.slip.any(),
                f"alpha = {ALPHA:g} rad < atan(mu): {len(r.t)} records; the centre's slide along the fall line "
                f"{eT:.2e} m, across it {eY:.2e} m (< 1e-14 m), its move along the normal against -m g cos(alpha) f / k "
                f"{eP:.2e} m; the friction force against m g sin(alpha) f up the slope {eF:.2e}, F_n against "
                f"m g cos(alpha) f {eN:.2e} (of m g)")
    # (e) preloaded (/SOLVER Preload 1), the dynamic run on IDA (exact stick's constraint) stays at rest
    rcval.METHOD = ""
    r = rcval.Result(rcval.run_case("case_preload.rad", keep_solver=True))
    eF, eN, ex = stick_errors(r, ATAN - DTH, np.ones_like(r.t))
    vmax = float(np.abs(r.vel).max()) if getattr(r, "vel", None) is not None else float("nan")
    rcval.check("static_exact_stick.preload_at_rest", max(eF, eN) < 1e-9 and ex < 1e-12 and vmax < 1e-12,
                f"preloaded, IDA to {r.t[-1]:g} s: max |v| {vmax:.2e} m/s, max |x|, |y| {ex:.2e} m, F_t against "
                f"m g sin(theta) {eF:.2e}, F_n against m g cos(theta) {eN:.2e} of m g")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cases)
