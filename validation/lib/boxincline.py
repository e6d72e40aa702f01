"""A box on an inclined plane with friction per contact point, shared by
box_plane_incline (the analytic /SURF/BOX) and seg_box_incline (a meshed
brick): the plane's frame, the motion along the fall line, and the checks
against the closed forms of both problems' README.md.

The plane is tilted by theta about a horizontal axis at azimuth phi (the
fall line along no global axis), gravity -z; the box a x b x c, mass m,
rests on it with its four bottom corners (nodes) in contact, linear contact
stiffness k (the stick spring K_t = k), Coulomb mu.
"""
import math
import os

import numpy as np

import rcval


def rotation(tan_th, phi):
    """R = Rz(phi) Ry(theta): the plane's frame (fall line s = R e_x, across
    u = R e_y, normal n = R e_z) in global axes."""
    th = math.atan(tan_th)
    ry = np.array([[math.cos(th), 0, math.sin(th)], [0, 1, 0], [-math.sin(th), 0, math.cos(th)]])
    rz = np.array([[math.cos(phi), -math.sin(phi), 0], [math.sin(phi), math.cos(phi), 0], [0, 0, 1]])
    return rz @ ry


def along(r, tan_th, phi):
    """Displacement and velocity of the centre of mass (body 0) along the
    fall line s and across it (u), from the start."""
    R = rotation(tan_th, phi)
    s, u = R[:, 0], R[:, 1]
    x = r.pos[:, 0] - r.pos[0, 0]
    v = r.vel[:, 0]
    return x @ s, x @ u, v @ s, v @ u


def check_stick(name, r, tan_th, phi_az, m, g, k, a, c):
    """tan(theta) < mu: no slip event, the drift along the fall line within
    the elastic displacement plus twice the static tilt, the rest position
    m g sin(theta) / K_t + phi c/2, the friction force m g sin(theta)."""
    th = math.atan(tan_th)
    xs, xu, vs, vu = along(r, tan_th, phi_az)
    x_el = m * g * math.sin(th) / k  # elastic displacement of the stick spring K_t = k
    # the friction at the base tips the box downhill by phi, balanced by the
    # normal forces shared as p_j / sum p (README.md): the centre of mass
    # moves by phi c/2 along the fall line beyond the base corners (nodes)
    p0 = m * g * math.cos(th) / k
    phi = 2 * tan_th * c * p0 / (a * a * (1 + tan_th * c / a))
    x_ref = x_el + phi * c / 2
    slips = [t for t, kd in zip(r.ev_t, r.ev_kind) if kd == "fric_slip"]
    rcval.check(f"{name}.stick.events", not slips,
                f"tan(theta) = mu/3: {len(slips)} fric_slip events (expected none); events {sorted(set(r.ev_kind))}")
    bound = x_el + phi * c  # a step load: at most twice the static tilt
    rcval.check(f"{name}.stick.drift", xs.max() <= bound and xs.min() > -1e-3 * x_el,
                f"x_s(t) of the centre along the fall line in [{xs.min():.3e}, {xs.max():.6e}] m, bound m g sin(theta)/K_t "
                f"+ 2 phi c/2 = {x_el:.6e} + {phi * c:.3e} = {bound:.6e} m")
    e = rcval.rel(xs[-1], x_ref)
    rcval.check(f"{name}.stick.rest", e < 2e-2 and abs(vs[-1]) < 1e-6,
                f"x_s at {r.t[-1]:g} s = {xs[-1]:.6e} m, m g sin(theta)/K_t + phi c/2 = {x_el:.6e} + {phi * c / 2:.3e} = "
                f"{x_ref:.6e} m (phi = {phi:.4e} rad), rel. error {e:.2e} (< 2e-2: terms of order phi, and the node "
                f"springs scaled down with their shrinking shares as the box tips, theory 2.7); "
                f"v_s = {vs[-1]:.1e} m/s (< 1e-6)")
    ft = np.linalg.norm(r.ffric[-1, 0])
    e = rcval.rel(ft, m * g * math.sin(th))
    rcval.check(f"{name}.stick.force", e < 1e-6,
                f"friction force at rest {ft:.9g} N, m g sin(theta) = {m * g * math.sin(th):.9g} N, rel. error {e:.2e} "
                f"(< 1e-6)")


def _slide(r, tan_th, phi_az, g, mu):
    """Quadratic fit of x_s over the steady slide t >= 0.2 s against
    a = g (sin theta - mu cos theta): x_s, v_u, the mask, the fitted and
    the reference acceleration, the largest fit residual, the relative error.
    (The pitch after the slip onset is damped by the damping per contact
    point, docs/theory.md 2.7; a remaining pitch would enter the position
    divided by its frequency.)"""
    th = math.atan(tan_th)
    a_ref = g * (math.sin(th) - mu * math.cos(th))
    xs, xu, vs, vu = along(r, tan_th, phi_az)
    sl = r.t >= 0.2
    cf = np.polyfit(r.t[sl], xs[sl], 2)
    a = 2 * cf[0]
    resid = np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl])))
    return xs, vu, sl, a, a_ref, resid, rcval.rel(a, a_ref)


def check_slide(name, r, tan_th, phi_az, m, g, mu):
    """tan(theta) > mu, over [0.2, 1] s: a = g (sin theta - mu cos theta),
    no motion across the fall line, |F_t| / F_n = mu with every point
    slipping, the energy ledger."""
    th = math.atan(tan_th)
    xs, vu, sl, a, a_ref, resid, e = _slide(r, tan_th, phi_az, g, mu)
    rcval.check(f"{name}.slide.acceleration", e < 1e-5 and resid < 1e-5,
                f"quadratic fit of x_s over [0.2, 1] s: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) = {a_ref:.9f}, "
                f"rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m (< 1e-5: the pitch, about 2e-4 rad, "
                f"moves the centre by c/2 phi)")
    side = np.max(np.abs(vu))
    rcval.check(f"{name}.slide.fall_line", side < 1e-5,
                f"max |v_u| across the fall line = {side:.1e} m/s (< 1e-5) after {xs[-1]:.3f} m along it")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - mu)))
    slipping = bool(np.all(r.slip[sl, 0] == 1))
    rcval.check(f"{name}.slide.friction", e < 1e-9 and slipping,
                f"|F_t| / F_n over [0.2, 1] s in [{ratio.min():.12f}, {ratio.max():.12f}], mu = {mu:g} (the point limits "
                f"mu f_j add up to mu F_n while every point slips), max error {e:.1e} (< 1e-9); F_n in "
                f"[{r.fn[sl, 0].min():.4g}, {r.fn[sl, 0].max():.4g}] N about m g cos(theta) = {m * g * math.cos(th):.4g} N "
                f"(the pitch)")
    rcval.check_ledger(f"{name}.slide.ledger", r, 1e-5)


def check_slide_variant(name, r, tan_th, phi_az, g, mu, what):
    """The sliding references of check_slide for a variant of the deck (name:
    the full check prefix; what: the variant, for the message)."""
    xs, vu, sl, a, a_ref, resid, e = _slide(r, tan_th, phi_az, g, mu)
    rcval.check(f"{name}.acceleration", e < 1e-5 and resid < 1e-5,
                f"{what}: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) "
                f"= {a_ref:.9f}, rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m (< 1e-5), {xs[-1]:.3f} m "
                f"down, across {np.max(np.abs(vu)):.1e} m/s")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - mu)))
    rcval.check(f"{name}.friction", e < 1e-9 and bool(np.all(r.slip[sl, 0] == 1)),
                f"|F_t| / F_n over [0.2, 1] s: max |ratio - mu| = {e:.1e} (< 1e-9), every record slipping")
    rcval.check_ledger(f"{name}.ledger", r, 1e-5)


def run_checks(name, here, deck, variant, what, phi_az, m, g, k, mu, a, c):
    """Both problems' runs: 1. sticking at tan(theta) = mu / 3 (here/case.rad);
    2. sliding at tan(theta) = 0.5 > mu, deck(0.5, 1.0, 0.01); 3. the same
    with deck's flag variant set (checks name.variant; what: the variant,
    for the messages)."""
    r = rcval.Result(rcval.run_file(os.path.join(here, "case.rad")))
    check_stick(name, r, mu / 3, phi_az, m, g, k, a, c)
    r = rcval.Result(rcval.run(deck(0.5, 1.0, 0.01), name="slide"))
    check_slide(name, r, 0.5, phi_az, m, g, mu)
    r = rcval.Result(rcval.run(deck(0.5, 1.0, 0.01, **{variant: True}), name=variant))
    check_slide_variant(f"{name}.{variant}", r, 0.5, phi_az, g, mu, what)
    rcval.finish()
