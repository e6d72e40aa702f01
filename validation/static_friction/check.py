"""Static analysis (/SOLVER Method 3) with friction: the return mapping of the stick spring.

A sphere (m = 1 kg, R = 0.05 m) on the fixed plane z = 0, its rotations held
by /BCS (a sphere rolls: without it a tangential load has no static
equilibrium), TYPE6 linear contact k = 1e5 N/m, friction Fric = mu = 0.3
with the stick spring K_t = Stiff = 2e4 N/m. The static analysis solves the
equilibrium at each output time (docs/theory.md 7.8: the trial force
F_t0 - K_t (relative displacement of the contact's material points since
the load substep's start), sticking while within Sfric + mu F_n, else the
limit along it). Gravity is tilted from the vertical by theta (/GRAV X and
Z, both times the one /FUNCT f(t) that every /GRAV card shares in this
version: the direction cannot turn during a run, the load grows along it):

case.rad: theta = 0.4 rad > atan(mu), Sfric = 1 N, f = t / t_end: the
sphere sticks (F_t = m g sin(theta) f, F_n = m g cos(theta) f, the stick
spring's displacement F_t / K_t) until m g f (sin(theta) - mu cos(theta))
reaches Sfric; then no static equilibrium exists: the run ends with an error
naming the sliding interface and the load time, which must bracket the
closed-form onset within the load-step resolution.
case_below.rad, case_above.rad: Sfric = 0, theta = atan(mu) -/+ 0.01: below
it sticks through the ramp (the same closed forms); above it has no
equilibrium from the first load on (refused at the smallest load substep).
case_cycle.rad: theta below atan(mu), f up, down, up, down to 0: it sticks,
the friction force equals the load's tangential part, and the displacement
F / K_t closes back to 0 (elastic; no fric_slip event).
case_slide.rad: theta = 0.4, Sfric = 0.5 N, a horizontal spring (k_s = 100
N/m) to a fixed point: f rises to 1 (the sphere slides, held by the spring:
equilibria in slip) and falls to 0.2 (it sticks again). Reference: the
return mapping solved per record in closed form (slide_reference); the
fric_slip and fric_stick events at the first load steps that slide and
stick again.
case_wedge.rad: a press fit. The sphere (rotations held) in a V-groove of
two fixed planes, each at PHI from the horizontal (outward normals (-+sin
PHI, 0, cos PHI)), touching both at zero load; vertical gravity ramped
(f = t / t_end), each wall TYPE6 linear k with Fric = mu, Sfric = 0 and a
stick spring K_t = k: under a growing load the sphere is pressed deeper
into the groove and slides down both walls (the stick spring alone would
hold it only while K_t tan(PHI) / k < mu), so friction is at its limit
mu F_n, up the walls, throughout. Closed form: the walls' normal forces
F_n = m g f / (2 (cos PHI + mu sin PHI)), each friction force mu F_n, the
penetrations F_n / k and the sphere's descent F_n / (k cos PHI).
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
MU, KT = 0.3, 2.0e4              # friction coefficient, stick stiffness [N/m]
T_END, DT_OUT = 1.0, 0.05
TOL = 1e-9


THETA = 0.4                      # case.rad: tilt of gravity [rad], tan(0.4) = 0.423 > MU
SFRIC = 1.0                      # case.rad: Sfric [N]: holds the sphere up to f* below
DTH = 0.01                       # case_below / case_above: atan(MU) -/+ DTH, Sfric = 0
ATAN = math.atan(MU)


def sphere_on_floor(d):
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    add_sphere_over_plane(d, M, R, R, title="sphere")
    d.bcs(1, 1, "000 111", title="rotations held")


def tilted(theta):
    """gravity's components per unit f, as read from the deck (12 digits)."""
    return float(f"{G * math.sin(theta):.12g}"), float(f"{-G * math.cos(theta):.12g}")


def deck_tilt(theta, sfric, fx, fy, title):
    d = Deck(title)
    sphere_on_floor(d)
    d.funct(2, fx, fy, title="load factor f(t)")
    gx, gz = tilted(theta)
    d.grav_fct(1, "X", gx, 2)
    d.grav_fct(2, "Z", gz, 2)
    d.type6(1, 1, 2, 1, sfric=sfric if sfric else None, fric=MU, stiff=KT, title="sphere - floor")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


RAMP = ([0.0, T_END], [0.0, 1.0])
CYCLE = ([0.0, 0.3, 0.5, 0.8, 1.0], [0.0, 1.0, 0.25, 0.75, 0.0])   # load, unload, reload, unload
SLIDE = ([0.0, 0.5, 1.0], [0.0, 1.0, 0.2])                           # case_slide: load past the limit, unload
SF_SLIDE, KS, XA = 0.5, 100.0, -1.0      # case_slide: Sfric [N], spring [N/m], its fixed point's x [m]


def deck_slide():
    d = deck_tilt(THETA, SF_SLIDE, *SLIDE, "static friction: elastic-plastic: slides against a spring, sticks, slides back")
    d.spring(3, 1, (0.0, 0.0, R), 0, (XA, 0.0, R), iform=1, a=KS, title="horizontal spring")
    return d


def slide_reference(ts):
    """The equilibria at the times ts (closed form of the return mapping, solved
    to rounding for the spring's geometry by Newton on the centre's x, z):
    stick F = F0 - K_t (x - x0) from the previous equilibrium (the friction
    force along x; the sticking spring is linear, so the load steps between
    the records do not matter); where |F| would exceed L = Sfric + mu F_n,
    slip: F = L along the trial force (a state that depends on no history).
    Returns per time (x, z, F, F_n, L, mode)."""
    gx, gz = tilted(THETA)
    L0 = -XA
    x0, z0, F0, out = 0.0, R, 0.0, []
    for t in ts:
        f = float(np.interp(t, *SLIDE))

        def solve(friction):
            def res(x, z):
                dx, dz = x - XA, z - R
                ln = math.hypot(dx, dz)
                fs, Fn = -KS * (ln - L0), K * (R - z)
                return np.array([M * gx * f + friction(x, Fn) + fs * dx / ln, M * gz * f + Fn + fs * dz / ln])
            x, z, h = x0, z0, 1e-7
            for _ in range(100):
                J = np.column_stack([(res(x + h, z) - res(x - h, z)) / (2 * h), (res(x, z + h) - res(x, z - h)) / (2 * h)])
                dxz = np.linalg.solve(J, -res(x, z))
                x, z = x + dxz[0], z + dxz[1]
                if abs(dxz).max() < 1e-16:
                    break
            Fn = K * (R - z)
            return x, z, friction(x, Fn), Fn, SF_SLIDE + MU * Fn

        q = solve(lambda x, Fn: F0 - KT * (x - x0)) + ("stick",)
        if abs(q[2]) > q[4]:
            sg = math.copysign(1.0, q[2])
            q = solve(lambda x, Fn: sg * (SF_SLIDE + MU * Fn)) + ("slip",)
        x0, z0, F0 = q[0], q[1], q[2]
        out.append(q)
    return out


PHI, KT_W = 1.0, 1.0e5           # case_wedge: the walls' angle from the horizontal [rad], stick spring [N/m]


def deck_wedge():
    d = Deck("static friction: a press fit: a sphere pressed into a V-groove with friction")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    d.nodes([(1, 0.0, 0.0, 0.0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, title="sphere")
    d.sphere(1, 1, (0.0, 0.0, 0.0), R)
    d.grnod(1, [1])
    d.bcs(1, 1, "000 111", title="rotations held")
    s, c = math.sin(PHI), math.cos(PHI)
    # each wall touches the sphere at zero load: its point R along -n from the centre
    d.plane(2, (R * s, 0.0, -R * c), (R * s - s, 0.0, -R * c + c), title="left wall, normal (-sin, 0, cos)")
    d.plane(3, (-R * s, 0.0, -R * c), (-R * s + s, 0.0, -R * c + c), title="right wall, normal (sin, 0, cos)")
    d.funct(2, *RAMP, title="load factor f(t)")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, fric=MU, stiff=KT_W, title="sphere - left wall")
    d.type6(2, 1, 3, 1, fric=MU, stiff=KT_W, title="sphere - right wall")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def cases():
    return {"case.rad": deck_tilt(THETA, SFRIC, *RAMP, "static friction: gravity tilted by 0.4 rad, ramped; Sfric holds it until the onset"),
            "case_below.rad": deck_tilt(ATAN - DTH, 0.0, *RAMP, "static friction: gravity tilted below atan(mu): sticks"),
            "case_above.rad": deck_tilt(ATAN + DTH, 0.0, *RAMP, "static friction: gravity tilted above atan(mu): slides at once"),
            "case_cycle.rad": deck_tilt(ATAN - DTH, 0.0, *CYCLE, "static friction: a load-unload cycle below the limit"),
            "case_slide.rad": deck_slide(),
            "case_wedge.rad": deck_wedge()}


def run_expect_failure(name):
    d = rcval.tmpdir()
    out = os.path.join(d, name.replace(".rad", ".nc"))
    cmd = [rcval.RICOCHET, "run", os.path.join(HERE, name), "-o", out, "-q", "--method", "static"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p.returncode, p.stderr, out


def failure(name, err):
    mt = re.search(r"no static equilibrium at the load time t = ([0-9.eE+-]+) s", err)
    ml = re.search(r"the last equilibrium at t = ([0-9.eE+-]+) s, load substeps down to ([0-9.eE+-]+) s", err)
    named = "/INTER/TYPE6/1" in err and "friction can hold" in err and "slides" in err
    return (float(mt.group(1)), float(ml.group(1)), float(ml.group(2))) if (mt and ml and named) else None


def stick_errors(r, theta, f):
    """max errors of the friction force, normal force and stick-spring displacement against the closed forms."""
    gx, gz = tilted(theta)
    Ft, Fn = M * gx * f, -M * gz * f
    eF = float(np.abs(r.ffric[:, 0, 0] + Ft).max() / (M * G))
    eFo = float(np.abs(r.ffric[:, 0, 1:]).max() / (M * G))
    eN = float(np.abs(r.fn[:, 0] - Fn).max() / (M * G))
    ex = float(np.abs(r.pos[:, 0, 0] - Ft / KT).max() / (M * G / KT))
    return max(eF, eFo), eN, ex


def main():
    rcval.METHOD = "static" if rcval.METHOD else ""
    # (a) gravity tilted by THETA > atan(mu), ramped: Sfric + mu F_n holds it until f* (closed form)
    gx, gz = tilted(THETA)
    fstar = SFRIC / (M * (gx + MU * gz))
    ts = fstar * T_END
    rc, err, out = run_expect_failure("case.rad")
    fl = failure("case.rad", err)
    rcval.check("static_friction.onset_refused", rc != 0 and fl is not None,
                f"exit code {rc}; message: {err.strip()[:500]!r}")
    if fl:
        t_fail, t_last, dts = fl
        rcval.check("static_friction.onset_time", t_last <= ts <= t_fail and t_fail - t_last <= 2.0 * dts * (1 + 1e-9),
                    f"onset f* = Sfric / (m g (sin(theta) - mu cos(theta))) at t* = {ts:.9f} s: last equilibrium "
                    f"{t_last:.9f} s, no equilibrium at {t_fail:.9f} s (load substep {dts:.3g} s); "
                    f"|t_fail - t*| = {abs(t_fail - ts):.2e} s")
    r = rcval.Result(out)
    eF, eN, ex = stick_errors(r, THETA, r.t / T_END)
    rcval.check("static_friction.onset_stick", (r.t < ts).all() and max(eF, eN, ex) < TOL and not r.slip.any(),
                f"{len(r.t)} records up to t = {r.t[-1]:g} s: max |F_t - m g sin(theta) f| / (m g) {eF:.2e}, "
                f"|F_n - m g cos(theta) f| / (m g) {eN:.2e}, |x - F_t / K_t| / (m g / K_t) {ex:.2e} (< {TOL:g})")
    # (a') below atan(mu), Sfric = 0: sticks through the ramp
    r = rcval.Result(rcval.run_case("case_below.rad", keep_solver=True))
    eF, eN, ex = stick_errors(r, ATAN - DTH, r.t / T_END)
    rcval.check("static_friction.below_sticks", len(r.t) == 21 and max(eF, eN, ex) < TOL and not r.slip.any(),
                f"theta = atan(mu) - {DTH:g}: {len(r.t)} records; max rel. errors of F_t {eF:.2e}, F_n {eN:.2e}, "
                f"x {ex:.2e} (< {TOL:g}); F_t at the end {r.ffric[-1, 0, 0]:.12g} N "
                f"(closed form {-M * tilted(ATAN - DTH)[0]:.12g} N)")
    # (a'') above atan(mu), Sfric = 0: no equilibrium from the first load on
    rc, err, out = run_expect_failure("case_above.rad")
    fl = failure("case_above.rad", err)
    rcval.check("static_friction.above_slides", rc != 0 and fl is not None and fl[0] <= 1e-6 * DT_OUT * 2,
                f"theta = atan(mu) + {DTH:g}: exit code {rc}, first load time without equilibrium "
                f"{fl[0] if fl else float('nan'):.3g} s; message: {err.strip()[:300]!r}")
    # (b) the load-unload cycle below the limit: elastic, closes back
    r = rcval.Result(rcval.run_case("case_cycle.rad", keep_solver=True))
    f = np.interp(r.t, *CYCLE)
    eF, eN, ex = stick_errors(r, ATAN - DTH, f)
    kinds = sorted(set(r.ev_kind))
    xend = abs(float(r.pos[-1, 0, 0]))
    rcval.check("static_friction.cycle", len(r.t) == 21 and max(eF, eN, ex) < TOL and not r.slip.any()
                and "fric_slip" not in kinds and xend < TOL * M * G / KT,
                f"{len(r.t)} records; max rel. errors of F_t {eF:.2e}, F_n {eN:.2e}, x {ex:.2e} (< {TOL:g}); "
                f"x at the end {xend:.2e} m (closes back); event kinds {kinds}")
    # (c) elastic-plastic: slides against the spring (equilibria in slip), sticks on unloading
    r = rcval.Result(rcval.run_case("case_slide.rad", keep_solver=True))
    ref = slide_reference(r.t)
    ex = max(abs(float(r.pos[k, 0, 0]) - ref[k][0]) for k in range(len(r.t))) / (SF_SLIDE / KS)
    eF = max(max(abs(float(r.ffric[k, 0, 0]) - ref[k][2]), abs(float(r.fn[k, 0]) - ref[k][3])) for k in range(len(r.t))) / (M * G)
    modes = [int(x) for x in r.slip[:, 0]]
    want = [1 if q[5] == "slip" else 0 for q in ref]
    first_slip = next(float(r.t[k]) for k in range(len(r.t)) if want[k])
    first_stick = next(float(r.t[k]) for k in range(len(r.t)) if r.t[k] > first_slip and not want[k])
    evs = [(round(float(t), 12), k) for t, k in zip(r.ev_t, r.ev_kind)]
    rcval.check("static_friction.slide_equilibria", len(r.t) == 21 and max(ex, eF) < TOL and modes == want,
                f"max |x - x_ref| / (Sfric / k_s) {ex:.2e}, max |F_t - F_ref|, |F_n - F_ref| / (m g) {eF:.2e} (< {TOL:g}); "
                f"slip flags {''.join(map(str, modes))} (reference {''.join(map(str, want))}); x at the peak "
                f"{float(r.pos[10, 0, 0]):.12e} m (reference {ref[10][0]:.12e} m)")
    rcval.check("static_friction.slide_events", evs == [(first_slip, "fric_slip"), (first_stick, "fric_stick")],
                f"events {evs} (expected fric_slip at {first_slip:g} s, the first load step that slides, fric_stick at "
                f"{first_stick:g} s, the first after the peak)")
    # (d) a press fit: the sphere pressed into a V-groove slides down both walls, friction at mu F_n
    r = rcval.Result(rcval.run_case("case_wedge.rad", keep_solver=True))
    f = np.interp(r.t, *RAMP)
    Nref = M * G * f / (2 * (math.cos(PHI) + MU * math.sin(PHI)))
    eN = float(np.abs(r.fn - Nref[:, None]).max() / (M * G))
    ratio = np.linalg.norm(r.ffric, axis=2)
    eF = float(np.abs(ratio - MU * Nref[:, None]).max() / (M * G))
    # friction on the sphere up each wall: along (+-cos PHI, 0, sin PHI), its z part mu F_n sin PHI
    eZ = float(np.abs(r.ffric[:, :, 2] - MU * Nref[:, None] * math.sin(PHI)).max() / (M * G))
    dz = -Nref / (K * math.cos(PHI))
    ez = float(np.abs(r.pos[:, 0, 2] - dz).max() / (M * G / K))
    slips = [k for k in r.ev_kind if k == "fric_slip"]
    rcval.check("static_friction.wedge", max(eN, eF, eZ) < 1e-9 and ez < 1e-6 and len(slips) == 2 and len(r.t) == 21,
                f"{len(r.t)} records: walls' F_n against m g f / (2 (cos phi + mu sin phi)) max error {eN:.1e}, "
                f"|F_t| against mu F_n {eF:.1e}, its z part against mu F_n sin phi {eZ:.1e} (of m g, < 1e-9); the "
                f"descent against F_n / (k cos phi) {ez:.1e} of m g / k (< 1e-6); fric_slip events {len(slips)} "
                f"(expected 2: both walls slide from the first load step)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cases)
