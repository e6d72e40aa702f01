"""A sphere on a meshed incline with friction (sphere against segments).

A sphere (m = 1 kg, R = 0.05 m) on a fixed /SURF/SEG plate of triangles
tilted by theta about a horizontal axis at azimuth phi = 30 deg (the fall
line along no global axis), TYPE6 with a linear load curve k = 1e6 N/m,
normal damping ratio 0.5 and Fric = mu = 0.3; g = 9.81 m/s^2. The friction
of a sphere against segments is the interface's tangential state at its
deepest kept point (docs/theory.md 2.7). Default solver settings. References
(README.md), closed forms:
  - rotations locked (/BCS 000 111), tan(theta) = 0.5 > mu: it slides down
    the fall line at a = g (sin theta - mu cos theta), crossing the
    triangles' edges;
  - rotations locked, tan(theta) = 0.2 (below mu / (1 + e^-2): the
    critically damped stick spring takes the step load without reaching the
    limit): it sticks, friction m g sin(theta), no slip event;
  - rotations free (a solid sphere, J = 2/5 m R^2), tan(theta) = 0.5 < 7/2 mu:
    it rolls without slipping on the radius R - p0 of its contact point
    (p0 = m g cos(theta) / k): a = g sin(theta) / (1 + J / (m (R - p0)^2))
    (5/7 g sin(theta) less 1e-4), friction J a / (R - p0)^2, no slip event.
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import incline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, MU = 1.0, 0.05, 1.0e6, 9.81, 0.3
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
PHI = math.radians(30.0)             # azimuth of the fall line
S0, S1, NS, W = -0.3, 2.2, 25, 0.4   # plate along the fall line [m], strips, width [m]


def deck(tan_th, tend, locked=True, dtout=0.01):
    th, n, s, u = incline.frame(tan_th, PHI)
    p0 = M * G * math.cos(th) / K  # static penetration
    c = tuple((R - p0) * n)
    d = Deck(f"sphere on a meshed plate tilted by atan({tan_th:g}), Fric {MU:g}, rotations "
             f"{'locked' if locked else 'free'}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    incline.add_sphere(d, c, M, R, locked)
    # the plate: strips of 0.1 m along s, each split into two triangles by a
    # diagonal that the sphere's path (u = 0) crosses; normals up the plate
    incline.add_strip_plate(d, s, u, S0, S1, NS, W)
    d.type6(1, 1, 10, 1, visc=VISC, fric=MU, title="sphere on the plate, Fric 0.3")
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def fit_acc(r, xs, t0):
    sl = r.t >= t0
    cf = np.polyfit(r.t[sl], xs[sl], 2)
    return 2 * cf[0], float(np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl])))), sl


def main():
    # 1. sliding, rotations locked (case.rad): tan(theta) = 0.5 > mu
    tan_th = 0.5
    th, n, s, u = incline.frame(tan_th, PHI)
    a_ref = G * (math.sin(th) - MU * math.cos(th))
    r = rcval.Result(rcval.run_case())
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    a, resid, sl = fit_acc(r, xs, 0.1)
    e = rcval.rel(a, a_ref)
    rcval.check("seg_sphere_incline.slide.acceleration", e < 1e-6 and resid < 1e-6,
                f"quadratic fit of x_s over [0.1, {r.t[-1]:g}] s: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) = "
                f"{a_ref:.9f}, rel. error {e:.2e} (< 1e-6), max residual {resid:.1e} m (< 1e-6), {xs[-1]:.3f} m down "
                f"the plate ({int(xs[-1] / 0.1)} strips of two triangles crossed)")
    rcval.check("seg_sphere_incline.slide.fall_line", np.max(np.abs(vu)) < 1e-6,
                f"max |v_u| across the fall line = {np.max(np.abs(vu)):.1e} m/s (< 1e-6)")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - MU)))
    rcval.check("seg_sphere_incline.slide.friction", e < 1e-9 and bool(np.all(r.slip[sl, 0] == 1)),
                f"|F_t| / F_n over [0.1, {r.t[-1]:g}] s in [{ratio.min():.12f}, {ratio.max():.12f}], mu = {MU:g}, "
                f"max error {e:.1e} (< 1e-9), every record slipping")
    rcval.check_ledger("seg_sphere_incline.slide.ledger", r, 1e-5)

    # 2. sticking, rotations locked: tan(theta) = 0.2
    tan_th = 0.2
    th, n, s, u = incline.frame(tan_th, PHI)
    r = rcval.Result(rcval.run(deck(tan_th, 1.0), name="stick"))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    slips = [t for t, k in zip(r.ev_t, r.ev_kind) if k == "fric_slip"]
    x_el = M * G * math.sin(th) / K  # the stick spring K_t = k (the load curve's slope)
    rcval.check("seg_sphere_incline.stick.events", not slips,
                f"tan(theta) = 0.2: {len(slips)} fric_slip events (expected none)")
    rcval.check("seg_sphere_incline.stick.drift", xs.max() <= 2 * x_el and abs(vs[-1]) < 1e-6,
                f"x_s(t) in [{xs.min():.3e}, {xs.max():.4e}] m (<= twice m g sin(theta) / K_t = {2 * x_el:.4e} m: a step "
                f"load), at {r.t[-1]:g} s x_s = {xs[-1]:.4e} m, v_s = {vs[-1]:.1e} m/s (< 1e-6)")
    ft = np.linalg.norm(r.ffric[-1, 0])
    e = rcval.rel(ft, M * G * math.sin(th))
    rcval.check("seg_sphere_incline.stick.force", e < 1e-6,
                f"friction force at rest {ft:.9g} N, m g sin(theta) = {M * G * math.sin(th):.9g} N, rel. error {e:.2e} "
                f"(< 1e-6)")

    # 3. rolling, rotations free: tan(theta) = 0.5 < 7/2 mu
    tan_th = 0.5
    th, n, s, u = incline.frame(tan_th, PHI)
    # the contact point lies on the plate, R - p0 from the centre (p0 = m g
    # cos(theta) / k, the static penetration): the rolling radius
    rr = R - M * G * math.cos(th) / K
    J = 0.4 * M * R * R
    a_ref = G * math.sin(th) / (1.0 + J / (M * rr * rr))
    r = rcval.Result(rcval.run(deck(tan_th, 0.8, locked=False), name="roll"))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    a, resid, sl = fit_acc(r, xs, 0.1)
    e = rcval.rel(a, a_ref)
    rcval.check("seg_sphere_incline.roll.acceleration", e < 1e-6 and resid < 1e-6,
                f"rolling (J = 2/5 m R^2, radius R - p0 = {rr:.8f} m): a = {a:.9f} m/s^2, g sin(theta) / (1 + J / (m (R - p0)^2)) "
                f"= {a_ref:.9f} (5/7 g sin(theta) = {5 / 7 * G * math.sin(th):.9f}), rel. error {e:.2e} "
                f"(< 1e-6), max residual {resid:.1e} m (< 1e-6), {xs[-1]:.3f} m down")
    slips = [t for t, k in zip(r.ev_t, r.ev_kind) if k == "fric_slip"]
    ft = np.linalg.norm(r.ffric[sl, 0], axis=1)
    f_ref = J * a_ref / (rr * rr)
    e = float(np.max(np.abs(ft - f_ref))) / f_ref
    rcval.check("seg_sphere_incline.roll.friction", not slips and e < 1e-6,
                f"{len(slips)} fric_slip events (expected none); |F_t| over [0.1, {r.t[-1]:g}] s in [{ft.min():.9f}, "
                f"{ft.max():.9f}] N, J a / (R - p0)^2 = {f_ref:.9f} N, max rel. error {e:.1e} (< 1e-6)")
    rcval.check_ledger("seg_sphere_incline.roll.ledger", r, 1e-5)

    # 4. the static analysis (/SOLVER Method 3), rotations locked: held by
    # friction at tan(theta) = 0.2, the friction force m g sin(theta) at the
    # deepest kept point; at tan(theta) = 0.5 > mu no equilibrium, the
    # limit mu m g cos(theta) named
    tan_th = 0.2
    th, n, s, u = incline.frame(tan_th, PHI)
    d = deck(tan_th, 0.2, dtout=0.1)
    d.solver(method=3)
    # the 'ida' mode runs every deck with --method ida: a static deck runs
    # with --method static all the same (the static analysis is the point)
    method, rcval.METHOD = rcval.METHOD, ("static" if rcval.METHOD else "")
    r = rcval.Result(rcval.run(d, name="static_stick", keep_solver=True))
    rcval.METHOD = method
    ft = np.linalg.norm(r.ffric[:, 0], axis=1)
    eF = float(np.max(np.abs(ft - M * G * math.sin(th)))) / (M * G)
    eN = float(np.max(np.abs(r.fn[:, 0] - M * G * math.cos(th)))) / (M * G)
    p0 = M * G * math.cos(th) / K
    x_el = M * G * math.sin(th) / K  # the stick spring's slide down the plate
    xs0 = float((r.pos[-1, 0, :] - (R - p0) * n) @ s)
    ex = abs(abs(xs0) - x_el) / x_el
    rcval.check("seg_sphere_incline.static.stick", eF < 1e-9 and eN < 1e-9 and ex < 1e-6 and
                bool(np.all(r.slip[:, 0] == 0)),
                f"static, tan(theta) = 0.2: |F_t| = {ft[-1]:.12f} N against m g sin(theta) = "
                f"{M * G * math.sin(th):.12f} N, error {eF:.1e} of m g (< 1e-9); F_n against m g cos(theta) "
                f"{eN:.1e} (< 1e-9); slide along the fall line {abs(xs0):.6e} m against m g sin(theta) / K_t = "
                f"{x_el:.6e} m, rel. error {ex:.1e} (< 1e-6); sticking")
    tan_th = 0.5
    th, n, s, u = incline.frame(tan_th, PHI)
    d = deck(tan_th, 0.2, dtout=0.1)
    d.solver(method=3)
    tmp = rcval.tmpdir()
    case = os.path.join(tmp, "static_slide.rad")
    with open(case, "w") as f:
        f.write(d.text())
    p = subprocess.run([rcval.RICOCHET, "run", case, "-o", os.path.join(tmp, "static_slide.nc"), "-q"],
                       capture_output=True, text=True)
    m = re.search(r"limit Sfric \+ mu F_n = ([0-9.eE+-]+) N", p.stderr)
    lim = MU * M * G * math.cos(th)
    e = abs(float(m.group(1)) - lim) / lim if m else float("inf")
    rcval.check("seg_sphere_incline.static.slide", p.returncode == 3 and "friction can hold" in p.stderr and e < 1e-5,
                f"static, tan(theta) = 0.5 > mu: exit {p.returncode} (expected 3, no equilibrium), the limit named "
                f"{m.group(1) if m else '?'} N against mu m g cos(theta) = {lim:.6f} N (printed to 6 digits: rel. "
                f"error {e:.1e} < 1e-5)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.5, 1.0))
