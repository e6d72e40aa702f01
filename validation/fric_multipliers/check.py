"""Friction multiplier curves fct_IDfv (sliding speed) and fct_IDff (normal force).

A sphere with locked rotations (a "block") at its static penetration on a
floor is launched horizontally at v0 and slides to a stop. TYPE6 with
F_lim = Sfric + mu F_n, mu = Fric f_ff(F_n / Ascalef) f_fv(v / Ascalev),
F_n = m g. Reference (README.md): an independent integration of the 1-D
equation of motion m dv/dt = -F_lim(v) (scipy solve_ivp, rtol 1e-11, event
at v = 0) on the piecewise-linear interpolant of the same table points
(np.interp), started from the exact end of the stick onset (the stick
damper's force c_t v0 exceeds the limit: slip at t = 0); cross-checked by
quadrature t = int m dv / F_lim(v), x = int m v dv / F_lim(v).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import quad, solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck  # noqa: E402

R, K, G, V0, FRIC = 0.05, 1.0e6, 9.81, 1.0, 0.3
ASCALEV, ASCALEF = 0.5, 10.0
# f_fv(v / Ascalev): rises to 1.3 at 0.05 m/s, then falls to 0.6 at 1 m/s
FV_X, FV_Y = [0.0, 0.1, 0.4, 1.0, 2.0, 3.0], [1.0, 1.3, 1.1, 0.8, 0.6, 0.55]
# f_ff(F_n / Ascalef): falls with the normal force
FF_X, FF_Y = [0.0, 0.5, 1.0, 2.0, 4.0], [1.2, 1.1, 0.9, 0.7, 0.6]
TOL = 1e-5

# name, mass, Sfric, f_fv used, f_ff used
VARIANTS = [("fv", 1.0, 0.0, True, False), ("ff_m1", 1.0, 0.0, False, True), ("ff_m2", 2.0, 0.0, False, True),
            ("fv_ff_sfric", 2.0, 0.5, True, True)]


def flim_fn(m, sfric, use_fv, use_ff):
    """F_lim(v) = Sfric + Fric f_ff(m g / Ascalef) f_fv(v / Ascalev) m g (tables within range)."""
    fn = m * G
    assert fn / ASCALEF <= FF_X[-1] and V0 / ASCALEV <= FV_X[-1]
    fff = np.interp(fn / ASCALEF, FF_X, FF_Y) if use_ff else 1.0

    def flim(v):
        fv = np.interp(v / ASCALEV, FV_X, FV_Y) if use_fv else 1.0
        return sfric + FRIC * fff * fv * fn
    return flim


def onset(m, flim):
    """Stick onset: sticking from x = 0, x' = v0 with a zero state, the force
    that acts is the critically damped stick spring's, -m w v0 (2 - w t) e^(-w t),
    c_t v0 = 2 sqrt(K_t m) v0 at the launch, against (1 + band) F_lim(0)
    (sliding speed 0): beyond it, so the contact slips at t = 0
    (lib/stick.py). Returns t1, x1, v1 = 0, 0, v0."""
    return stick.launch_onset(K, m, V0, flim(0.0))


def reference(m, flim):
    """solve_ivp of m v' = -F_lim(v), x' = v from the end of the stick onset to v = 0."""
    t1, x1, v1 = onset(m, flim)

    def rhs(t, y):
        return [y[1], -flim(max(y[1], 0.0)) / m]

    def stop(t, y):
        return y[1]
    stop.terminal, stop.direction = True, -1
    s = solve_ivp(rhs, (t1, t1 + 10.0), [x1, v1], method="DOP853", rtol=1e-11, atol=1e-14, events=stop)
    t_stop, x_stop = s.t_events[0][0], s.y_events[0][0][0]
    # cross-check by quadrature over v, split at the table breakpoints
    brk = sorted({0.0, v1, *[x * ASCALEV for x in FV_X if 0 < x * ASCALEV < v1]})
    tq = t1 + sum(quad(lambda v: m / flim(v), a, b, epsabs=0, epsrel=1e-13)[0] for a, b in zip(brk, brk[1:]))
    xq = x1 + sum(quad(lambda v: m * v / flim(v), a, b, epsabs=0, epsrel=1e-13)[0] for a, b in zip(brk, brk[1:]))
    return t_stop, x_stop, tq, xq


def deck(m, sfric, use_fv, use_ff, rtol=1e-8, atol_pos=1e-11, atol_vel=1e-8, atol_energy=1e-8, tend=None):
    z0 = R - m * G / K  # static penetration
    d = Deck("block sliding to a stop, friction multiplier curves (TYPE6)")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.funct(2, FV_X, FV_Y, title="f_fv: mu multiplier vs sliding speed / Ascalev")
    d.funct(3, FF_X, FF_Y, title="f_ff: mu multiplier vs normal force / Ascalef")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, m, [0.4 * m * R * R] * 3, grnod=1, title=f"block {m:g} kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1])
    d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    d.inivel(1, (V0, 0.0, 0.0), 1)
    d.grav(1, "Z", -G, 1)
    d.type6(1, 1, 2, 1, visc=2.0 * 0.5 * math.sqrt(K * m), sfric=sfric if sfric > 0 else None, fric=FRIC,
            fct_fv=2 if use_fv else 0, fct_ff=3 if use_ff else 0, ascalev=ASCALEV, ascalef=ASCALEF,
            title="Fric 0.3 with multiplier curves")
    if tend is None:
        tend = 1.1 * reference(m, flim_fn(m, sfric, use_fv, use_ff))[0]
    d.run(tend, 0.01)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_energy)
    return d


def measure(path):
    r = rcval.Result(path)
    t_stop = r.events("fric_stick")[0]
    i = r.state_at(t_stop)
    return t_stop, r.pos[i, 0, 0], [k for t, k in zip(r.ev_t, r.ev_kind) if t <= t_stop]


def main():
    errs = {}
    for name, m, sfric, use_fv, use_ff in VARIANTS:
        flim = flim_fn(m, sfric, use_fv, use_ff)
        t_ref, x_ref, tq, xq = reference(m, flim)
        eq = max(rcval.rel(tq, t_ref), rcval.rel(xq, x_ref))
        if name == VARIANTS[-1][0]:
            path = rcval.run_case()  # the case deck is the combined variant
        else:
            path = rcval.run(deck(m, sfric, use_fv, use_ff))
        t_stop, x_stop, before = measure(path)
        e = max(rcval.rel(x_stop, x_ref), rcval.rel(t_stop, t_ref))
        # without the curves (constant mu = Fric): how much the curves change the stop
        x_const = V0**2 * m / (2 * (sfric + FRIC * m * G))
        errs[name] = e
        ok = e < TOL and eq < 1e-9 and before == ["fric_slip", "fric_stick"]
        rcval.check(f"fric_multipliers.{name}", ok,
                    f"m = {m:g} kg, Sfric = {sfric:g} N, f_fv {'on' if use_fv else 'off'}, f_ff {'on' if use_ff else 'off'}: "
                    f"x_stop = {x_stop:.9f} m (reference {x_ref:.9f}), t_stop = {t_stop:.9f} s (reference {t_ref:.9f}), "
                    f"max rel. error {e:.2e} (< {TOL:g}); constant mu would stop at {x_const:.6f} m; "
                    f"solve_ivp vs quadrature {eq:.1e} (< 1e-9); events {before}")

    # convergence of the combined case: rtol 1e-6 (default), 1e-8 (above), 1e-10
    name, m, sfric, use_fv, use_ff = VARIANTS[-1]
    t_ref, x_ref, _, _ = reference(m, flim_fn(m, sfric, use_fv, use_ff))
    conv = []
    for rtol in (1e-6, 1e-10):
        t_stop, x_stop, _ = measure(rcval.run(deck(m, sfric, use_fv, use_ff, rtol, 1e-3 * rtol, rtol, rtol),
                                              keep_solver=True))
        conv.append(max(rcval.rel(x_stop, x_ref), rcval.rel(t_stop, t_ref)))
    if rcval.DEFAULTS:  # the study's rtol 1e-8 point is case.rad with its /SOLVER card
        t_stop, x_stop, _ = measure(rcval.run_case(keep_solver=True))
        errs[name] = max(rcval.rel(x_stop, x_ref), rcval.rel(t_stop, t_ref))
    conv.insert(1, errs[name])
    ok = conv[2] < conv[1] < conv[0] and conv[2] < 1e-8
    rcval.check("fric_multipliers.convergence", ok,
                f"{name}: max rel. error at rtol 1e-6 (default), 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in conv)
                + " (decreasing, last < 1e-8; the curves' kinks are not events, README.md)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(*VARIANTS[-1][1:]))  # (m, sfric, use_fv, use_ff) of the last variant
