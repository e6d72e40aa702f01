"""Geometry shared by the inclined-plane problems (fric_incline, frc_incline,
seg_sphere_incline, pw_seg_sphere_step5 ...).

The plane is tilted by theta about a horizontal axis at azimuth phi, so the
fall line is along no global axis; gravity is -z.
"""
import math

import numpy as np

import stick
from deck import line


def frame(tan_th, phi):
    """theta, plane normal n, fall-line direction s (down the slope), in-plane u = n x s."""
    th = math.atan(tan_th)
    n = np.array([math.sin(th) * math.cos(phi), math.sin(th) * math.sin(phi), math.cos(th)])
    s = np.array([math.cos(th) * math.cos(phi), math.cos(th) * math.sin(phi), -math.sin(th)])
    return th, n, s, np.cross(n, s)


def add_strip_plate(d, s, u, s0, s1, ns, width, sid=10, node0=1000, title="inclined plate: fixed triangles"):
    """A fixed /SURF/SEG plate in the plane through the origin spanned by s
    (along the strips) and u: ns strips from s0 to s1 [m], width [m], each
    split into two triangles by a diagonal that a path along u = 0 crosses;
    normals along s x u. Nodes from node0 on."""
    xs = np.linspace(s0, s1, ns + 1)
    pn = [(node0 + 2 * k + e, *(xs[k] * s + (-width / 2 if e == 0 else width / 2) * u))
          for k in range(ns + 1) for e in (0, 1)]
    d.nodes(pn)
    segs = []
    for k in range(ns):
        # (s_k,-), (s_k+1,-), (s_k+1,+), (s_k,+)
        a, b, cc, dd = node0 + 2 * k, node0 + 2 + 2 * k, node0 + 3 + 2 * k, node0 + 1 + 2 * k
        segs.append(line(*[("i", v) for v in (2 * k + 1, a, b, cc)]))
        segs.append(line(*[("i", v) for v in (2 * k + 2, a, cc, dd)]))
    d.add(f"/SURF/SEG/{sid}", *segs, title=title)


def add_sphere(d, c, m, r, locked):
    """A solid sphere of mass m [kg] and radius r [m] centred at c [m]: node
    1, body 1 (inertia 2/5 m r^2), /SURF/SPHERE 1 and node group 1; locked:
    its rotations fixed by /BCS 1."""
    d.nodes([(1, *c)])
    d.rbody(1, 1, m, [0.4 * m * r * r] * 3, grnod=1, title=f"sphere {m:g} kg")
    d.sphere(1, 1, c, r, title="sphere")
    d.grnod(1, [1], title="sphere node")
    if locked:
        d.bcs(1, 1, "000 111", title="no rotation")


def ramp_table(tr, n=501):
    """Quintic smoothstep 0 -> 1 on [0, tr] (f', f'' zero at both ends), then
    a far point at 1 so that the linear extension beyond the table stays flat."""
    t = np.linspace(0.0, tr, n)
    x = t / tr
    return list(t) + [1.0e4], list(x**3 * (10.0 - 15.0 * x + 6.0 * x * x)) + [1.0]


def along(r, tan_th, phi):
    """Positions along s and u relative to the start, velocities along s, u, n."""
    th, n, s, u = frame(tan_th, phi)
    dp = r.pos[:, 0, :] - r.pos[0, 0, :]
    return dp @ s, dp @ u, r.vel[:, 0, :] @ s, r.vel[:, 0, :] @ u, r.vel[:, 0, :] @ n


def tolerances(m, g, k, rtol=None, atol_pos=None, atol_vel=None, coord=0.0):
    """The engine's tolerance setting for a block of mass m on a linear
    contact k under gravity of magnitude g (docs/theory.md 7, 7.1), as the
    force band of the slip test and the local error allowances the
    validation windows use: dict(rtol, fband, dpos, dvel).
    Derived (rtol None: no /SOLVER card or the defaults mode): rtol 1e-8,
    F_s = m g (p_F; no speed and no gap, so no p_E), p_s = F_s/k,
    v_s = p_s sqrt(k/m); positions rtol p_s (absolute only), velocities
    rtol v_s, F_t rtol F_s; f_band = max(tolerance of F_t, 1e-6 F_s) (the
    slip test's band, docs/theory.md 3.5). Given on /SOLVER: f_band = K_t atol_pos
    (K_t = k), positions rtol |X| + atol_pos (|X| = coord, the largest
    coordinate of the centre), velocities atol_vel."""
    if rtol is None:
        rtol = 1e-8
        fs = m * g
        ps = fs / k
        return dict(rtol=rtol, fband=max(rtol, 1e-6) * fs, dpos=rtol * ps, dvel=rtol * ps * math.sqrt(k / m))
    return dict(rtol=rtol, fband=max(k * atol_pos, 1e-6 * m * g), dpos=rtol * coord + atol_pos, dvel=atol_vel)


def force_resolution(b, tol, flim):
    """Local error allowance of the slip function |F_t - c_t v| - (1 + 1e-6)
    (Sfric + mu (k p + c_n p')) - f_band from the tolerances of its states:
    F_t (f_band + rtol F_lim), c_t times the velocity's, mu k times the
    position's and mu c_n times the velocity's [N]."""
    return (tol["fband"] + tol["rtol"] * flim + b.ct * tol["dvel"]
            + b.mu * (b.k * tol["dpos"] + b.cn * tol["dvel"]))


def stuck_reference(m, k, cn, mu, g, tan_th, tr, tol, tend):
    """The stuck case of fric_incline / frc_incline by lib/block_ref.py: a
    block starting at rest touching the plane at zero gap, gravity ramped by
    ramp_table(tr). Returns (ref, exact, block): the solve_ivp (LSODA, rtol
    1e-12) and exact-flow solutions and the model."""
    import block_ref
    th = math.atan(tan_th)
    b = block_ref.Block(m, k, cn, k, mu, 0.0, tol["fband"], g * math.cos(th), g * math.sin(th), ramp_table(tr))
    ex = b.solve_exact(tend, nsample=32)
    ex["before"] = b.before
    ref = b.solve(tend, method="LSODA")
    ref["before"] = b.before
    return ref, ex, b


def check_stuck(name, r, m, k, cn, mu, g, tan_th, tr, phi, tol, rcval):
    """The checks `name`.events and .slipped of the stuck case against the
    reference (README.md of fric_incline). Returns x_s(t), x_u(t), the
    relative error of the final x_s against x_pl + m g sin(theta)/K_t, that
    value, and the tolerance across the fall line."""
    th, n, s, u = frame(tan_th, phi)
    ref, ex, b = stuck_reference(m, k, cn, mu, g, tan_th, tr, tol, tr + 0.1)
    load = m * g * math.sin(th)
    flim = mu * m * g * math.cos(th)
    dF = force_resolution(b, tol, flim)
    kinds = [kd for _, kd in ref["events"]]
    ok = [kd for kd in r.ev_kind] == kinds and [kd for _, kd in ex["events"]] == kinds
    parts = []
    t_prev = 0.0
    for i, ((t_ref, kd), y) in enumerate(zip(ref["events"], ref["before"])):
        acc = abs(ex["events"][i][0] - t_ref) if i < len(ex["events"]) else float("inf")
        rate = b.rates(t_ref, y, kd)
        if kd == "fric_slip":
            win = dF / abs(rate)
        else:  # a force error dF held over the slip builds a speed error dF (t - t_slip)/m
            win = dF * (t_ref - t_prev) / m / abs(rate)
        win += 10.0 * acc
        t_prev = t_ref
        t_ric = r.ev_t[i] if i < len(r.ev_t) else float("nan")
        e = abs(t_ric - t_ref)
        ok = ok and e < win
        parts.append(f"{kd} at {t_ric:.9e} s, reference {t_ref:.9e} s (exact flow {acc:.1e} s away), "
                     f"error {e:.1e} s (< {win:.1e} s: {dF:.2e} N over {'dg/dt' if kd == 'fric_slip' else 'm |dv/dt|'} "
                     f"{abs(rate):.3e})")
    rcval.check(f"{name}.events", ok,
                f"f_band {tol['fband']:.3g} N: ricochet {len(r.ev_t)} events, reference {kinds}; " + "; ".join(parts))
    # slipped (plastic) displacement x_pl = x + F_t/K_t at the stick event
    xs, xu, vs, vu, vn = along(r, tan_th, phi)
    x_pl_ref = b.plastic(ref["y"])
    if len(r.ev_t) and r.ev_kind[-1] == "fric_stick":
        j = r.state_at(r.ev_t[-1])
        x_pl = xs[j] + (r.ffric[j, 0] @ s) / k
    else:
        x_pl = 0.0
    x_ref = load / k
    e = abs(x_pl - x_pl_ref)
    rcval.check(f"{name}.slipped", e < 1e-6 * x_ref,
                f"slipped distance x + F_t/K_t at the stick = {x_pl:.6e} m, reference {x_pl_ref:.6e} m (exact flow "
                f"{b.plastic(ex['y']):.6e}), error {e:.1e} m (< 1e-6 m g sin(theta)/K_t = {1e-6 * x_ref:.1e})")
    x_end = x_pl_ref + x_ref
    e = abs(xs[-1] - x_end) / x_ref
    # across the fall line: nothing without a slip (1e-15 m, rounding); with
    # one, the direction of the slip is that of the applied force at the
    # onset, whose lateral part is integration error: the lateral slip gets
    # the tolerance of the slipped distance
    u_tol = 1e-6 * x_ref if kinds else 1e-15
    return xs, xu, e, x_end, u_tol


def check_slide(name, r, m, k, mu, g, tan_th, phi, rcval, accel_note=""):
    """The checks `name`.events, .onset and .acceleration of a block sliding
    from rest down a plane with tan(theta) > mu under constant gravity g
    [m/s^2] (mass m [kg], stick stiffness k [N/m]; records from 0 to 1.5 s):
    a single fric_slip at the stick onset of the damped stick spring
    (stick.step_onset, within 1e-6 s), then v_s(t) linear from 0.2 s with
    a = g (sin theta - mu cos theta) [m/s^2] (rel. error < 1e-5, fit residual
    < 1e-6 m/s). accel_note is appended to the acceleration line. Returns
    x_s, x_u, v_s, v_u, v_n (incline.along) and the fit window (t >= 0.2 s)."""
    th = math.atan(tan_th)
    a_ref = g * (math.sin(th) - mu * math.cos(th))
    xs, xu, vs, vu, vn = along(r, tan_th, phi)
    kinds = [kd for kd in r.ev_kind]
    rcval.check(f"{name}.events", kinds == ["fric_slip"],
                f"events {list(zip(np.round(r.ev_t, 9), kinds))} (expected a single fric_slip at the stick onset)")
    # stick onset from rest under the step load P = m g sin(theta): the applied
    # force of the critically damped stick spring, P (1 - (1 - w t) e^(-w t)),
    # reaches (1 + 1e-6) mu m g cos(theta) at w t = 1 - W((1 - r) e), r = (1 + 1e-6) mu/tan(theta)
    t_on = stick.step_onset(k, m, m * g * math.sin(th), mu * m * g * math.cos(th))
    e = abs(r.ev_t[0] - t_on) if len(r.ev_t) else float("inf")
    rcval.check(f"{name}.onset", e < 1e-6,
                f"fric_slip at {r.ev_t[0] if len(r.ev_t) else float('nan'):.9e} s, damped stick spring from rest: "
                f"(1 - W((1 - r) e))/w = {t_on:.9e} s, error {e:.1e} s (< 1e-6)")
    sl = r.t >= 0.2
    a, b = np.polyfit(r.t[sl], vs[sl], 1)
    resid = np.max(np.abs(vs[sl] - (a * r.t[sl] + b)))
    e = rcval.rel(a, a_ref)
    rcval.check(f"{name}.acceleration", e < 1e-5 and resid < 1e-6,
                f"fit of v_s over [0.2, 1.5] s: a = {a:.9f} m/s^2, g (sin theta - mu cos theta) = {a_ref:.9f}, "
                f"rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m/s (< 1e-6)" + accel_note)
    return xs, xu, vs, vu, vn, sl
