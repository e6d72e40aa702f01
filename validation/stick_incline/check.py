"""Exact stick (TYPE6 Istick = 1) of a block on an inclined plane.

A sphere with locked rotations (a "block") on a plane tilted by theta about
a horizontal axis at azimuth phi = 30 deg (the fall line along no global
axis), gravity -z, at rest at its static normal penetration. Reference
(README.md): the textbook block on an incline with rigid Coulomb friction:
with tan(theta) <= mu_s it stays where it is and the friction force is
m g sin(theta) up the slope; with tan(theta) > mu_s it slides down the fall
line at a = g (sin theta - mu cos theta) from t = 0.
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
PHI = math.radians(30.0)


def deck(tan_th, tend, dtout, fric_s=None, card=False, rolling=False, v0=None, drop=0.0):
    """card: the friction of a /FRICTION card (Iform 3, Coulomb Fric) instead
    of TYPE6's own; rolling: the rotations free (a ball); v0: initial
    velocity; drop: the centre that much higher than at rest [m]."""
    th, n, s, u = incline.frame(tan_th, PHI)
    p = M * G * math.cos(th) / K - drop  # the static normal penetration
    c = tuple((R - p) * n)
    d = Deck(f"exact stick: block on a plane tilted by atan({tan_th:g}), Fric {MU:g}"
             + ("" if fric_s is None else f", Fric_s {fric_s:g}"))
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, *c)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, c, R)
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title="inclined plane through the origin")
    d.grnod(1, [1])
    if not rolling:
        d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    if v0 is not None:
        d.inivel(1, tuple(v0), 1)
    d.grav(1, "Z", -G, 1)
    if card:
        d.type6(1, 1, 2, 1, visc=VISC, title="contact, the friction of /FRICTION/1")
        d.friction(1, iform=3, fric=MU, title="Coulomb, exact stick (Iform 3)")
    else:
        d.type6(1, 1, 2, 1, visc=VISC, fric=MU, istick=1, fric_s=fric_s, title="exact stick")
    d.run(tend, dtout)
    return d


def stuck(name, r, tan_th, what):
    th, n, s, u = incline.frame(tan_th, PHI)
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    drift = max(np.max(np.abs(xs)), np.max(np.abs(xu)))
    rcval.check(f"{name}.drift", drift < 1e-9 and len(r.ev_t) == 0 and np.all(r.slip[:, 0] == 0),
                f"{what}: over {r.t[-1]:g} s, max tangential displacement {drift:.2e} m (< 1e-9), "
                f"{len(r.ev_t)} events (expected 0), always sticking: {bool(np.all(r.slip[:, 0] == 0))}")
    f_ref = -M * G * math.sin(th) * s  # up the slope, on the block (body a)
    err = np.max(np.linalg.norm(r.ffric[:, 0, :] - f_ref, axis=1)) / (M * G * math.sin(th))
    rcval.check(f"{name}.force", err < 1e-9,
                f"friction force = m g sin(theta) = {M * G * math.sin(th):.12g} N up the fall line: max "
                f"|F - F_ref| / |F_ref| = {err:.2e} (< 1e-9); |F| at the end {np.linalg.norm(r.ffric[-1, 0]):.12g} N")
    fw = np.max(np.abs(r.energy["energy_friction_work"]))
    et = r.energy["energy_total"]
    rcval.check(f"{name}.energy", fw < 1e-12 and np.max(np.abs(et - et[0])) < 1e-9,
                f"friction work {fw:.1e} J (< 1e-12), max |E_total(t) - E_total(0)| = "
                f"{np.max(np.abs(et - et[0])):.1e} J (< 1e-9)")


def main():
    # 1. stuck, tan(theta) = 0.9 mu, 100 s (case.rad)
    tan_th = 0.9 * MU
    r = rcval.Result(rcval.run_case())
    stuck("stick_incline.stuck", r, tan_th, f"tan(theta) = 0.9 mu = {tan_th:g}")

    # 2. static coefficient: tan(theta) = 0.5 > Fric = 0.3 but < Fric_s = 0.6
    tan_th = 0.5
    r = rcval.Result(rcval.run(deck(tan_th, 100.0, 1.0, fric_s=0.6)))
    stuck("stick_incline.static", r, tan_th, "tan(theta) = 0.5 between Fric 0.3 and Fric_s 0.6")

    # 3. sliding from t = 0: tan(theta) = 0.5 > mu = 0.3 (Fric_s blank: Fric)
    th = math.atan(tan_th)
    a_ref = G * (math.sin(th) - MU * math.cos(th))
    r = rcval.Result(rcval.run(deck(tan_th, 1.5, 0.01)))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    rcval.check("stick_incline.slide.events", r.ev_kind == ["fric_slip"] and abs(r.ev_t[0]) == 0.0,
                f"events {list(zip(np.round(r.ev_t, 12), r.ev_kind))} (expected one fric_slip at t = 0: the force "
                f"that would hold it, m g sin(theta), is beyond mu m g cos(theta))")
    sl = r.t >= 0.1
    a, b = np.polyfit(r.t[sl], vs[sl], 1)
    e = rcval.rel(a, a_ref)
    x_ref = 0.5 * a_ref * r.t[-1] ** 2
    ex = rcval.rel(xs[-1], x_ref)
    rcval.check("stick_incline.slide.acceleration", e < 1e-6 and ex < 1e-6,
                f"fit of v_s over [0.1, 1.5] s: a = {a:.10f} m/s^2, g (sin theta - mu cos theta) = {a_ref:.10f}, "
                f"rel. error {e:.1e} (< 1e-6); x_s(1.5 s) = {xs[-1]:.10f} m, a t^2 / 2 = {x_ref:.10f}, "
                f"rel. error {ex:.1e} (< 1e-6)")
    fm = np.linalg.norm(r.ffric[sl, 0, :], axis=1)
    ef = np.max(np.abs(fm - MU * M * G * math.cos(th))) / (MU * M * G * math.cos(th))
    rcval.check("stick_incline.slide.force", ef < 1e-6 and np.all(r.slip[sl, 0] == 1),
                f"sliding force |F| = mu m g cos(theta) = {MU * M * G * math.cos(th):.10f} N: max rel. error "
                f"{ef:.1e} (< 1e-6), mode slip throughout")
    rcval.check_ledger("stick_incline.slide.energy", r, 1e-6)

    # 4. the same through /FRICTION Iform 3: stuck at 0.9 mu, sliding at 0.5
    tan_th = 0.9 * MU
    r = rcval.Result(rcval.run(deck(tan_th, 100.0, 1.0, card=True)))
    stuck("stick_incline.card_stuck", r, tan_th, f"/FRICTION Iform 3, tan(theta) = 0.9 mu = {tan_th:g}")
    tan_th = 0.5
    r = rcval.Result(rcval.run(deck(tan_th, 1.5, 0.01, card=True)))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    a, b = np.polyfit(r.t[sl], vs[sl], 1)
    e = rcval.rel(a, a_ref)
    rcval.check("stick_incline.card_slide", e < 1e-6 and r.ev_kind == ["fric_slip"],
                f"/FRICTION Iform 3, tan(theta) = 0.5: events {r.ev_kind} (one fric_slip at t = 0), a = {a:.10f} "
                f"m/s^2, g (sin theta - mu cos theta) = {a_ref:.10f}, rel. error {e:.1e} (< 1e-6)")

    # 5. a ball (rotations free) rolls without slipping: the contact point
    #    sticks, a = (5/7) g sin(theta) (solid sphere, J = 2/5 m R^2), the
    #    friction force (2/7) m g sin(theta) < mu m g cos(theta) (tan(theta) = 0.5 < 3.5 mu)
    r = rcval.Result(rcval.run(deck(tan_th, 1.0, 0.01, rolling=True)))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    sl = r.t >= 0.1
    a, b = np.polyfit(r.t[sl], vs[sl], 1)
    a_roll = 5.0 / 7.0 * G * math.sin(th)
    e = rcval.rel(a, a_roll)
    fe = np.max(np.abs(np.linalg.norm(r.ffric[sl, 0, :], axis=1) - 2.0 / 7.0 * M * G * math.sin(th))) / (M * G)
    rcval.check("stick_incline.rolling", e < 1e-6 and fe < 1e-6 and len(r.ev_t) == 0 and np.all(r.slip[:, 0] == 0),
                f"ball, rotations free: rolls without slipping, a = {a:.10f} m/s^2, (5/7) g sin(theta) = {a_roll:.10f}, "
                f"rel. error {e:.1e} (< 1e-6); friction force (2/7) m g sin(theta) to {fe:.1e} m g (< 1e-6); "
                f"{len(r.ev_t)} events (expected 0)")

    # 6. the ball dropped from 1 mm with a speed of 0.5 m/s across the slope:
    #    it lands sliding (fric_slip at the contact), bounces, slides, and
    #    once the contact point stops it rolls: then a = (5/7) g sin(theta)
    #    down the slope and the speed across the slope constant
    th, n, s, u = incline.frame(tan_th, PHI)
    r = rcval.Result(rcval.run(deck(tan_th, 1.0, 0.01, rolling=True, v0=0.5 * u, drop=1e-3)))
    xs, xu, vs, vu, vn = incline.along(r, tan_th, PHI)
    t_roll = r.ev_t[-1] if len(r.ev_t) else float("nan")
    sl = r.t >= t_roll + 0.05
    a, b = np.polyfit(r.t[sl], vs[sl], 1)
    e = rcval.rel(a, a_roll)
    du = np.max(np.abs(vu[sl] - vu[sl][0]))
    # across the slope the angular momentum about the contact point is kept
    # (friction acts there, the normal impulses and gravity's slope
    # component have no moment along s): rolling sets in at (5/7) v_u0
    eu = rcval.rel(vu[sl][0], 5.0 / 7.0 * 0.5)
    ok = (len(r.ev_t) > 0 and r.ev_kind[0] == "contact_close" and r.ev_kind[-1] == "fric_stick"
          and np.all(r.slip[sl, 0] == 0) and e < 1e-6 and du < 1e-9 and eu < 1e-6)
    rcval.check("stick_incline.landing", ok,
                f"lands at {r.ev_t[0] if len(r.ev_t) else float('nan'):.6f} s sliding, {len(r.ev_t)} events, the last "
                f"fric_stick at {t_roll:.6f} s (events: {sorted(set(r.ev_kind))}); then rolling: a = {a:.10f} m/s^2, "
                f"(5/7) g sin(theta) = {a_roll:.10f}, rel. error {e:.1e} (< 1e-6); speed across the slope "
                f"{vu[sl][0]:.10f} m/s, (5/7) 0.5 = {2.5 / 7.0:.10f}, rel. error {eu:.1e} (< 1e-6), constant to "
                f"{du:.1e} m/s (< 1e-9)")
    rcval.check_ledger("stick_incline.landing.energy", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.9 * MU, 100.0, 1.0))
