"""Block on an inclined plane with /FRICTION Coulomb (Ifric 0, Iform 2).

The design of validation/fric_incline (a sphere with locked rotations, a
plane tilted by theta about a horizontal axis at azimuth 30 deg) with the
friction given by a /FRICTION card instead of TYPE6's Fric, selected through
/PART and /GRPART (README.md). Reference: with tan(theta) < mu the block
stays stuck; with tan(theta) > mu it slides down the fall line at
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
from deck import Deck  # noqa: E402

M, R, K, G, MU = 1.0, 0.05, 1.0e6, 9.81, 0.3
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
PHI = math.radians(30.0)             # azimuth of the fall line
TR = 0.5                             # ramp duration of the stuck case [s]
P0 = 0.0                             # the ramped case starts touching at zero gap [m]
# friction values that must NOT apply (README.md): TYPE6's own Fric, the
# first /FRICTION card (no groups, overridden by the later one), the default
# set of the second card (its group names the block-plane pair)
MU_T6, MU_CARD1, MU_DEFAULT = 0.6, 0.9, 0.05


def frame(tan_th):
    return incline.frame(tan_th, PHI)


def ramp_table(n=501):
    return incline.ramp_table(TR, n)


def along(r, tan_th):
    return incline.along(r, tan_th, PHI)


def deck(tan_th, tend, ramped=False, dtout=0.01):
    """ramped: gravity ramped from 0, block starting at P0 (touching); else
    constant gravity, block at its static normal penetration m g cos(theta)/k."""
    th, n, s, u = frame(tan_th)
    p = P0 if ramped else M * G * math.cos(th) / K
    c = tuple((R - p) * n)
    d = Deck(f"block on a plane tilted by atan({tan_th:g}), /FRICTION Coulomb Iform 2")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, *c)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, c, R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title="inclined plane through the origin")
    d.grnod(1, [1], title="block")
    d.bcs(1, 1, "000 111", title="no rotation")
    if ramped:
        xs, ys = ramp_table()
        d.funct(2, xs, ys, title="smooth ramp 0 -> 1 over 0.5 s (quintic smoothstep)")
        d.grav_fct(1, "Z", -G, 2, grnod=1)
    else:
        d.grav(1, "Z", -G, 1)
    d.type6(1, 1, 2, 1, visc=VISC, fric=MU_T6, title="TYPE6 Fric 0.6 (overridden)")
    d.part(11, 1, title="the block (whole body)")
    d.part(12, 0, [2], title="the inclined plane (fixed surface 2)")
    d.grpart(21, [12], title="ground parts")
    d.friction(1, ifric=0, iform=2, fric=MU_CARD1, title="first card, every pair: Fric 0.9 (overridden)")
    d.friction(2, ifric=0, iform=2, fric=MU_DEFAULT,
               pairs=[dict(part1=11, grpart2=21, sets=[((), MU, None)])],
               title="last card: defaults Fric 0.05, block/ground pair Fric 0.3")
    d.run(tend, dtout)
    return d


def main():

    # 1. stuck, tan(theta) = 0.9 mu, gravity ramped (case.rad)
    tan_th = 0.9 * MU
    th = math.atan(tan_th)
    r = rcval.Result(rcval.run_case())
    # the reference of the damped model (lib/block_ref.py) at the force band
    # of the derived tolerances (no /SOLVER card: both modes run them)
    tol = incline.tolerances(M, G, K)
    xs, xu, x_err, x_end, u_tol = incline.check_stuck("frc_incline.stuck", r, M, K, VISC, MU, G, tan_th, TR, PHI, tol, rcval)
    last = r.t >= r.t[-1] - 10.0 - 1e-12
    drift = np.max(np.abs(xs[last] - xs[last][0]))
    rcval.check("frc_incline.stuck.drift", drift < 1e-9,
                f"max |x_s(t) - x_s({r.t[last][0]:g} s)| along the fall line over the last 10 s = {drift:.2e} m (< 1e-9)")
    x_ref = M * G * math.sin(th) / K
    ft = r.ffric[-1, 0]
    fe = np.linalg.norm(ft + M * G * math.sin(th) * frame(tan_th)[2]) / (M * G * math.sin(th))
    rcval.check("frc_incline.stuck.stick_spring", x_err < 1e-6 and abs(xu[-1]) < u_tol and fe < 1e-6,
                f"x_s = {xs[-1]:.9e} m, reference x_pl + m g sin(theta)/K_t = {x_end:.9e} m "
                f"(m g sin(theta)/K_t = {x_ref:.9e}), rel. error {x_err:.2e} (< 1e-6); "
                f"across the fall line {xu[-1]:.1e} m (< {u_tol:.1e}); friction force = -m g sin(theta) s to {fe:.1e}")

    # 2. sliding, tan(theta) = 0.5 > mu, constant gravity
    tan_th = 0.5
    th = math.atan(tan_th)
    r = rcval.Result(rcval.run(deck(tan_th, 1.5)))
    others = ", ".join(f"mu {m:g}: {G * (math.sin(th) - m * math.cos(th)):.4f}" for m in (MU_DEFAULT,))
    xs, xu, vs, vu, vn, sl = incline.check_slide(
        "frc_incline.slide", r, M, K, MU, G, tan_th, PHI, rcval,
        accel_note=f" (the sets that must not apply would give {others}, or stick: mu 0.6, 0.9)")
    mu_meas = np.linalg.norm(r.ffric[-1, 0]) / r.fn[-1, 0]
    e = rcval.rel(mu_meas, MU)
    rcval.check("frc_incline.slide.limit", e < 1e-9 and r.slip[-1, 0] == 1,
                f"|F_t|/F_n at the end = {mu_meas:.12f} (mu = {MU}), rel. error {e:.1e} (< 1e-9), mode slip")
    side = np.max(np.abs(vu))
    rcval.check("frc_incline.slide.fall_line", side < 1e-6,
                f"max |v_u| across the fall line = {side:.1e} m/s (< atol_vel 1e-6), max |x_u| = {np.max(np.abs(xu)):.1e} m "
                f"after {xs[-1]:.3f} m")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.9 * MU, 11.0, ramped=True))
