"""A ball on a meshed floor and a meshed incline with step5 friction (power law).

A sphere (m = 1 kg, R = 0.05 m, J = 2/5 m R^2) on a fixed /SURF/SEG plate of
triangles (the plate of validation/seg_sphere_incline: 25 strips of 0.1 m,
each split by a diagonal the ball's path crosses), tilted by theta about a
horizontal axis at azimuth 30 deg, or flat (theta = 0, the floor);
/INTER/POWER linear (K = 1e6 N/m, m1 = 1) with damping at ratio 0.5, step5
friction mu_s = 0.35 at v_s = 0.01 m/s, mu_d = 0.25 beyond v_d = 0.05 m/s;
g = 9.81 m/s^2. The step5 friction of a sphere against segments is the
interface's law at the deepest kept point with the whole normal force
(docs/theory.md 2.7). Default solver settings. References (README.md),
closed forms:
  - floor, rotations locked, v0 = 1 m/s: decelerates at mu_d g while the
    speed is beyond v_d;
  - floor, f_max = 0.5 N (below mu_d m g): decelerates at f_max / m;
  - incline tan(theta) = 0.5, rotations locked, v0 = 0.5 m/s down the fall
    line: a = g (sin theta - mu_d cos theta);
  - incline tan(theta) = 0.5, rotations free, from rest: after the creep
    settles it rolls at a = g sin(theta) / (1 + J / (m (R - p0)^2)) (the
    contact point on the plate, p0 = m g cos(theta) / K), with the friction
    J a / (R - p0)^2 below mu_s F_n (tan(theta) < 7/2 mu_s).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import incline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81
C = 2.0 * 0.5 * math.sqrt(K * M)      # damping ratio 0.5 (m2 = 1, m3 = 0: C v)
MUS, VS, MUD, VD = 0.35, 0.01, 0.25, 0.05
PHI = math.radians(30.0)
S0, S1, NS, W = -0.3, 2.2, 25, 0.4


def deck(tan_th, tend, v0=0.0, locked=True, fmax=None, dtout=0.01):
    th, n, s, u = incline.frame(tan_th, PHI)
    p0 = M * G * math.cos(th) / K
    c = tuple((R - p0) * n)
    d = Deck(f"sphere on a meshed plate tilted by atan({tan_th:g}), power law, step5 friction, rotations "
             f"{'locked' if locked else 'free'}{'' if fmax is None else f', f_max {fmax:g} N'}")
    incline.add_sphere(d, c, M, R, locked)
    if v0:
        d.inivel(1, tuple(v0 * s), 1)
    incline.add_strip_plate(d, s, u, S0, S1, NS, W, title="meshed plate: fixed triangles")
    d.power(1, 1, 10, k=K, m1=1.0, c=C, m2=1.0, m3=0.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD, fmax=fmax,
            title="linear power law, step5 friction")
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def fit_acc(r, xs, t0, t1):
    sl = (r.t >= t0) & (r.t <= t1)
    cf = np.polyfit(r.t[sl], xs[sl], 2)
    return 2 * cf[0], float(np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl])))), sl


def slide(name, tan_th, v0, tend, t1, a_ref, what, fmax=None, path=None):
    th, n, s, u = incline.frame(tan_th, PHI)
    r = rcval.Result(path or rcval.run(deck(tan_th, tend, v0=v0, fmax=fmax), name=name))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    a, resid, sl = fit_acc(r, xs, 0.05, t1)
    e = abs(a - a_ref) / abs(a_ref)
    rcval.check(f"pw_seg_sphere_step5.{name}.acceleration", e < 1e-6 and resid < 1e-6 and vs[sl].min() > VD,
                f"quadratic fit of x_s over [0.05, {t1:g}] s (speeds {vs[sl].min():.3f}..{vs[sl].max():.3f} m/s > "
                f"v_d): a = {a:.9f} m/s^2, {what} = {a_ref:.9f}, rel. error {e:.2e} (< 1e-6), max residual "
                f"{resid:.1e} m (< 1e-6), {xs[-1]:.3f} m along the plate")
    rcval.check(f"pw_seg_sphere_step5.{name}.straight", np.max(np.abs(vu)) < 1e-6,
                f"max |v_u| across the path = {np.max(np.abs(vu)):.1e} m/s (< 1e-6)")
    rcval.check_ledger(f"pw_seg_sphere_step5.{name}.ledger", r, 1e-5)
    return r


def main():
    # 1. floor, rotations locked, v0 = 1 m/s: mu_d g while beyond v_d
    slide("floor", 0.0, 1.0, 0.4, 0.35, -MUD * G, "-mu_d g")
    # 2. floor, capped: f_max / m
    r = slide("floor_cap", 0.0, 1.0, 0.6, 0.6, -0.5 / M, "-f_max / m", fmax=0.5)
    ft = np.linalg.norm(r.ffric[r.t >= 0.05, 0], axis=1)
    rcval.check("pw_seg_sphere_step5.floor_cap.force", float(np.max(np.abs(ft - 0.5))) < 1e-9,
                f"|F_t| over [0.05, {r.t[-1]:g}] s in [{ft.min():.12f}, {ft.max():.12f}] N, f_max = 0.5 N")
    # 3. incline (case.rad), rotations locked, v0 = 0.5 m/s down the slope
    th = math.atan(0.5)
    slide("incline", 0.5, 0.5, 0.5, 0.5, G * (math.sin(th) - MUD * math.cos(th)), "g (sin theta - mu_d cos theta)",
          path=rcval.run_case())
    # 4. rolling with creep, rotations free, from rest
    r = rcval.Result(rcval.run(deck(0.5, 0.6, locked=False), name="roll"))
    xs, xu, vs, vu, vn = incline.along(r, 0.5, PHI)
    rr = R - M * G * math.cos(th) / K
    J = 0.4 * M * R * R
    a_ref = G * math.sin(th) / (1.0 + J / (M * rr * rr))
    a, resid, sl = fit_acc(r, xs, 0.1, 0.6)
    e = rcval.rel(a, a_ref)
    ft = np.linalg.norm(r.ffric[sl, 0], axis=1)
    ef = float(np.max(np.abs(ft - J * a_ref / rr**2))) / (J * a_ref / rr**2)
    vsl = float(np.max(r.vslip[sl, 0]))
    rcval.check("pw_seg_sphere_step5.roll.acceleration", e < 1e-6 and resid < 1e-6 and ef < 1e-6 and vsl < VS,
                f"rolling with creep (slip speed <= {vsl:.2e} m/s < v_s): a = {a:.9f} m/s^2, g sin(theta) / (1 + J / "
                f"(m (R - p0)^2)) = {a_ref:.9f}, rel. error {e:.2e} (< 1e-6), residual {resid:.1e} m; friction vs "
                f"J a / (R - p0)^2: {ef:.1e} (< 1e-6)")
    rcval.check_ledger("pw_seg_sphere_step5.roll.ledger", r, 1e-5)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.5, 0.5, v0=0.5))
