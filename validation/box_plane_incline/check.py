"""An analytic box (/SURF/BOX) on an inclined plane with friction: the box's
8 corners are its contact points, each with its own tangential force and
stick/slip mode (docs/theory.md 2.7).

The box a x b x c, mass M, inertia of a homogeneous box, rests on a fixed
plane tilted by theta about a horizontal axis at azimuth phi = 30 deg (the
fall line along no global axis). References (README.md), closed forms:
  - tan(theta) > mu: the box slides down the fall line at
    a = g (sin theta - mu cos theta) (the four bottom corners all slip; the
    limits mu f_j add up to mu F_n = mu M g cos theta); with TYPE6's Fric
    (box first on the card) and with a /FRICTION card (plane first);
  - tan(theta) = mu / 3 < mu: it sticks, no slip event; the friction force
    is M g sin(theta); the centre moves down the slope by the stick springs'
    elastic displacement M g sin(theta) / K_t plus the tilt the base friction
    gives (README.md).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, K, ZETA, MU = 9.81, 1.0e6, 0.7, 0.3
A, B, C, M = 0.2, 0.12, 0.08, 15.0  # box sizes [m], mass [kg]
JD = (M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12)
PHI = math.radians(30.0)            # azimuth of the fall line


def rotation(tan_th):
    """R = Rz(phi) Ry(theta): the plane's frame (fall line s = R e_x, across
    u = R e_y, normal n = R e_z) in global axes."""
    th = math.atan(tan_th)
    ry = np.array([[math.cos(th), 0, math.sin(th)], [0, 1, 0], [-math.sin(th), 0, math.cos(th)]])
    rz = np.array([[math.cos(PHI), -math.sin(PHI), 0], [math.sin(PHI), math.cos(PHI), 0], [0, 0, 1]])
    return rz @ ry


def deck(tan_th, tend, dtout, card=False):
    """card: friction from a /FRICTION card (Coulomb Fric = mu, incremental
    Iform 2) instead of TYPE6's Fric, and the plane first on the TYPE6 card."""
    R = rotation(tan_th)
    th = math.atan(tan_th)
    p0 = M * G * math.cos(th) / K  # static penetration of the four bottom corners
    d = Deck(f"analytic box on a plane tilted by atan({tan_th:g}), friction per corner")
    centre = R @ np.array([0.0, 0.0, C / 2 - p0])
    d.nodes([(1, *centre)])
    d.grnod(1, [1], title="box")
    J = R @ np.diag(JD) @ R.T
    d.rbody(1, 1, M, (J[0, 0], J[1, 1], J[2, 2]), Joff=(J[0, 1], J[1, 2], J[0, 2]), grnod=1, title="box")
    d.box(31, 1, tuple(centre), (A / 2, B / 2, C / 2), u=tuple(R[:, 0]), v=tuple(R[:, 1]), title="box surface")
    d.plane(10, (0, 0, 0), tuple(R @ np.array([0.0, 0.0, 1.0])), title="inclined plane through the origin")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    visc = 2 * ZETA * math.sqrt(K * M)
    if card:
        d.type6(1, 10, 31, 1, visc=visc, title="the incline and the box (plane first), no TYPE6 friction")
        d.friction(1, ifric=0, iform=2, fric=MU, title="Coulomb mu = 0.3, incremental (every interface)")
    else:
        d.type6(1, 31, 10, 1, visc=visc, fric=MU, title="box on the incline, Fric 0.3")
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def along(r, tan_th):
    """Displacement and velocity of the centre of mass along the fall line s
    and across it (u), from the start."""
    R = rotation(tan_th)
    s, u = R[:, 0], R[:, 1]
    x = r.pos[:, 0] - r.pos[0, 0]
    v = r.vel[:, 0]
    return x @ s, x @ u, v @ s, v @ u


def main():
    # 1. sticking: tan(theta) = mu / 3 (case.rad)
    tan_th = MU / 3
    th = math.atan(tan_th)
    r = rcval.Result(rcval.run_file(os.path.join(HERE, "case.rad")))
    xs, xu, vs, vu = along(r, tan_th)
    x_el = M * G * math.sin(th) / K  # elastic displacement of the stick spring K_t = k
    # the friction at the base tips the box downhill by phi, balanced by the
    # normal forces shared as p_j / sum p (README.md): the centre of mass
    # moves by phi c/2 along the fall line beyond the base corners
    p0 = M * G * math.cos(th) / K
    phi = 2 * tan_th * C * p0 / (A * A * (1 + tan_th * C / A))
    x_ref = x_el + phi * C / 2
    slips = [t for t, k in zip(r.ev_t, r.ev_kind) if k == "fric_slip"]
    rcval.check("box_plane_incline.stick.events", not slips,
                f"tan(theta) = mu/3: {len(slips)} fric_slip events (expected none); events {sorted(set(r.ev_kind))}")
    bound = x_el + phi * C  # a step load: at most twice the static tilt
    rcval.check("box_plane_incline.stick.drift", xs.max() <= bound and xs.min() > -1e-3 * x_el,
                f"x_s(t) of the centre along the fall line in [{xs.min():.3e}, {xs.max():.6e}] m, bound m g sin(theta)/K_t "
                f"+ 2 phi c/2 = {x_el:.6e} + {phi * C:.3e} = {bound:.6e} m")
    e = rcval.rel(xs[-1], x_ref)
    rcval.check("box_plane_incline.stick.rest", e < 1e-3 and abs(vs[-1]) < 1e-6,
                f"x_s at {r.t[-1]:g} s = {xs[-1]:.6e} m, m g sin(theta)/K_t + phi c/2 = {x_el:.6e} + {phi * C / 2:.3e} = "
                f"{x_ref:.6e} m (phi = {phi:.4e} rad), rel. error {e:.2e} (< 1e-3, terms of order phi); "
                f"v_s = {vs[-1]:.1e} m/s (< 1e-6)")
    ft = np.linalg.norm(r.ffric[-1, 0])
    e = rcval.rel(ft, M * G * math.sin(th))
    rcval.check("box_plane_incline.stick.force", e < 1e-6,
                f"friction force at rest {ft:.9g} N, m g sin(theta) = {M * G * math.sin(th):.9g} N, rel. error {e:.2e} "
                f"(< 1e-6)")

    # 2. sliding: tan(theta) = 0.5 > mu
    tan_th = 0.5
    th = math.atan(tan_th)
    a_ref = G * (math.sin(th) - MU * math.cos(th))
    r = rcval.Result(rcval.run(deck(tan_th, 1.0, 0.01), name="slide"))
    xs, xu, vs, vu = along(r, tan_th)
    # fit the position over the steady slide (the pitch after the slip onset
    # is damped by the damping per contact point, docs/theory.md 2.7; a
    # remaining pitch would enter the position divided by its frequency)
    sl = r.t >= 0.2
    cf = np.polyfit(r.t[sl], xs[sl], 2)
    a = 2 * cf[0]
    resid = np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl])))
    e = rcval.rel(a, a_ref)
    rcval.check("box_plane_incline.slide.acceleration", e < 1e-5 and resid < 1e-5,
                f"quadratic fit of x_s over [0.2, 1] s: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) = {a_ref:.9f}, "
                f"rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m (< 1e-5: the pitch, about 2e-4 rad, "
                f"moves the centre by c/2 phi)")
    side = np.max(np.abs(vu))
    rcval.check("box_plane_incline.slide.fall_line", side < 1e-5,
                f"max |v_u| across the fall line = {side:.1e} m/s (< 1e-5) after {xs[-1]:.3f} m along it")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - MU)))
    slipping = bool(np.all(r.slip[sl, 0] == 1))
    rcval.check("box_plane_incline.slide.friction", e < 1e-9 and slipping,
                f"|F_t| / F_n over [0.2, 1] s in [{ratio.min():.12f}, {ratio.max():.12f}], mu = {MU:g} (the point limits "
                f"mu f_j add up to mu F_n while every point slips), max error {e:.1e} (< 1e-9); F_n in "
                f"[{r.fn[sl, 0].min():.4g}, {r.fn[sl, 0].max():.4g}] N about m g cos(theta) = {M * G * math.cos(th):.4g} N "
                f"(the pitch)")
    rcval.check_ledger("box_plane_incline.slide.ledger", r, 1e-5)

    # 3. sliding, friction from a /FRICTION card, the plane first on the card
    r = rcval.Result(rcval.run(deck(tan_th, 1.0, 0.01, card=True), name="card"))
    xs, xu, vs, vu = along(r, tan_th)
    cf = np.polyfit(r.t[sl], xs[sl], 2)
    a = 2 * cf[0]
    resid = np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl])))
    e = rcval.rel(a, a_ref)
    rcval.check("box_plane_incline.card.acceleration", e < 1e-5 and resid < 1e-5,
                f"/FRICTION Fric {MU:g}, plane first on the card: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) "
                f"= {a_ref:.9f}, rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m (< 1e-5), {xs[-1]:.3f} m "
                f"down, across {np.max(np.abs(vu)):.1e} m/s")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - MU)))
    rcval.check("box_plane_incline.card.friction", e < 1e-9 and bool(np.all(r.slip[sl, 0] == 1)),
                f"|F_t| / F_n over [0.2, 1] s: max |ratio - mu| = {e:.1e} (< 1e-9), every record slipping")
    rcval.check_ledger("box_plane_incline.card.ledger", r, 1e-5)
    rcval.finish()


if __name__ == "__main__":
    if "--write-case" in sys.argv:
        deck(MU / 3, 2.0, 0.01).write(os.path.join(HERE, "case.rad"))
    else:
        main()
