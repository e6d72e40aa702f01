"""Block on an inclined plane with Coulomb friction (TYPE6 Fric).

A sphere with locked rotations (a "block") on a plane tilted by theta about a
horizontal axis at azimuth phi = 30 deg (so the fall line is along no global
axis), under gravity -z. Reference (README.md): with tan(theta) < mu the
block stays stuck; with tan(theta) > mu it slides down the fall line at
a = g (sin theta - mu cos theta). The stick phase is that of ricochet's
critically damped stick spring (lib/stick.py).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import incline  # noqa: E402
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck, r20  # noqa: E402

M, R, K, G, MU = 1.0, 0.05, 1.0e6, 9.81, 0.3
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
PHI = math.radians(30.0)             # azimuth of the fall line
TR = 0.5                             # ramp duration of the ramped-gravity variant [s]
P0 = 0.0                             # the ramped variant starts touching at zero gap [m]


def frame(tan_th):
    return incline.frame(tan_th, PHI)


def ramp_table(n=501):
    return incline.ramp_table(TR, n)


def along(r, tan_th):
    return incline.along(r, tan_th, PHI)


def deck(tan_th, tend, ramped=False, dtout=0.01, rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, atol_energy=1e-6):
    """ramped: gravity ramped from 0 (block starting at P0, touching); else
    constant gravity, block at its static normal penetration m g cos(theta)/k."""
    th, n, s, u = frame(tan_th)
    p = P0 if ramped else M * G * math.cos(th) / K
    c = tuple((R - p) * n)
    d = Deck(f"block on a plane tilted by atan({tan_th:g}) (TYPE6 Fric)")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, *c)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, c, R)
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title="inclined plane through the origin")
    d.grnod(1, [1])
    d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    if ramped:
        xs, ys = ramp_table()
        d.funct(2, xs, ys, title="smooth ramp 0 -> 1 over 0.5 s (quintic smoothstep)")
        d.add("/GRAV/1", f"{2:>10d}{'Z':>10s}{0:>10d}{0:>10d}{1:>10d}" + " " * 10 + r20(1.0) + r20(-G), title="gravity, ramped")
    else:
        d.grav(1, "Z", -G, 1)
    d.type6(1, 1, 2, 1, visc=VISC, fric=MU, title="Fric 0.3")
    d.run(tend, dtout)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_energy)
    return d


def main():

    # 1. stuck, tan(theta) = 0.9 mu, gravity ramped (case.rad)
    tan_th = 0.9 * MU
    th = math.atan(tan_th)
    r = rcval.Result(rcval.run_case())
    # the reference of the damped model (lib/block_ref.py) at the force band
    # of the run's tolerances: the deck's /SOLVER card, or the derived ones
    tol = (incline.tolerances(M, G, K) if rcval.DEFAULTS else
           incline.tolerances(M, G, K, rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, coord=R))
    xs, xu, x_err, x_end, u_tol = incline.check_stuck("fric_incline.stuck", r, M, K, VISC, MU, G, tan_th, TR, PHI, tol, rcval)
    last = r.t >= r.t[-1] - 10.0 - 1e-12
    drift = np.max(np.abs(xs[last] - xs[last][0]))
    rcval.check("fric_incline.stuck.drift", drift < 1e-9,
                f"max |x_s(t) - x_s({r.t[last][0]:g} s)| along the fall line over the last 10 s = {drift:.2e} m (< 1e-9)")
    x_ref = M * G * math.sin(th) / K
    rcval.check("fric_incline.stuck.stick_spring", x_err < 1e-6 and abs(xu[-1]) < u_tol,
                f"x_s = {xs[-1]:.9e} m, reference x_pl + m g sin(theta)/K_t = {x_end:.9e} m "
                f"(m g sin(theta)/K_t = {x_ref:.9e}), rel. error {x_err:.2e} (< 1e-6); across the fall line {xu[-1]:.1e} m (< {u_tol:.1e})")

    # 2. stuck under a constant gravity (a step load): the critically damped
    #    stick spring takes the load without ringing, x_s = x_ref (1 - (1 + w t) e^(-w t)),
    #    x_ref = m g sin(theta)/K_t (lib/stick.py); its force peaks at
    #    (1 + e^-2) m g sin(theta) (w t = 2), below mu m g cos(theta) for
    #    tan(theta) = mu/3. Tight tolerances, records every 1 ms.
    tan_th = MU / 3.0
    th = math.atan(tan_th)
    r = rcval.Result(rcval.run(deck(tan_th, 10.0, dtout=1e-3, rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10,
                                    atol_energy=1e-10)))
    xs, xu, vs, vu, vn = along(r, tan_th)
    load = M * G * math.sin(th)
    x_ref = load / K
    x_ex = np.array([stick.step_stick(K, M, load, t) for t in r.t])
    e_path = np.max(np.abs(xs - x_ex)) / x_ref
    e_end = abs(xs[-1] - x_ref) / x_ref
    n_ev = len(r.ev_t)
    ok = (n_ev == 0 and xs.min() > -1e-12 and xs.max() < x_ref * (1 + 1e-6) and np.max(np.abs(xu)) < 1e-15
          and e_path < 1e-5 and e_end < 1e-6)
    rcval.check("fric_incline.step_load.settle", ok,
                f"tan(theta) = mu/3, constant gravity, rtol 1e-10, 10 s: {n_ev} events (expected 0), x_s in "
                f"[{xs.min():.2e}, {xs.max():.9e}] m within [0, (1 + 1e-6) m g sin(theta)/K_t], x_ref = {x_ref:.9e} (no "
                f"overshoot); max |x_s - x_ref (1 - (1 + w t) e^(-w t))| / x_ref = {e_path:.1e} (< 1e-5); at the end "
                f"{xs[-1]:.9e} m, rel. error {e_end:.1e} (< 1e-6); across the fall line {np.max(np.abs(xu)):.1e} m")

    # 3. sliding, tan(theta) = 0.5 > mu, constant gravity
    tan_th = 0.5
    r = rcval.Result(rcval.run(deck(tan_th, 1.5)))
    xs, xu, vs, vu, vn, sl = incline.check_slide("fric_incline.slide", r, M, K, MU, G, tan_th, PHI, rcval)
    # across the fall line: only the integration error (the law damps a lateral
    # velocity at the rate F_lim/(m |v|), README.md), bounded by atol_vel = 1e-6 m/s
    side = np.max(np.abs(vu))
    rcval.check("fric_incline.slide.fall_line", side < 1e-6,
                f"max |v_u| across the fall line = {side:.1e} m/s (< atol_vel 1e-6), max |x_u| = {np.max(np.abs(xu)):.1e} m "
                f"after {xs[-1]:.3f} m; max |v_n| after 0.2 s = {np.max(np.abs(vn[sl])):.1e} m/s")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.9 * MU, 11.0, ramped=True))
