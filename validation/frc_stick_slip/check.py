"""Stick-slip oscillator: a block on a belt, held by a spring to a fixed point.

A sphere with locked rotations (a "block", m = 1 kg, R = 0.05 m), free along
x (the belt direction) and z, held in y, rests at its static penetration on a
plane carried by a 1e12 kg body (the "belt") moving at V = 0.05 m/s along x.
A linear spring k = 100 N/m (/COUPLING/SPRING, relaxed at t = 0) ties it to a
fixed point behind it along x. The block starts moving with the belt.
Friction: /FRICTION Renard (Ifric 3) with mu_max = mu_s = 0.4 and
mu_min = mu_d = mu_k = 0.25, i.e. mu = mu_s up to V_cr1, a smooth drop to
mu_k by V_cr2, mu_k beyond: a two-level law with a steep drop (V_cr1, V_cr2
a few um/s), in the viscous (total) form (Iform 1) with a stiff adhesion
(VISF = 1e6), so that sticking is an overdamped creep at under 3 um/s.

References (README.md):
1. an independent scipy solve_ivp (Radau, rtol 1e-11) of the same law with
   its two modes (adhesion F = -C u, saturated F = mu(|u|) m g) and events
   at the switches and at the breakpoints of mu: period, slip duration,
   extreme positions within 1e-5 relative;
2. the classical limit cycle of the two-level Coulomb law (slip harmonic about
   x_k = mu_k m g/k from x_s = mu_s m g/k at the belt speed, stick carried by
   the belt): within 1e-3, the size of the law's departure from two levels.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import belt  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81
VISC = 2.0 * 0.5 * math.sqrt(K * M)       # normal damping ratio 0.5
MBELT = 1.0e12
KS, V = 100.0, 0.05                       # spring [N/m], belt speed [m/s]
MUS, MUK = 0.4, 0.25                      # static and kinetic levels
VISF = 1.0e6                              # adhesion C = sqrt(2 VISF K m_red)
MRED = 1.0 / (1.0 / M + 1.0 / MBELT)      # reduced mass of block and belt
C = math.sqrt(2.0 * VISF * K * MRED)      # 1.414e6 N s/m
USAT = MUS * M * G / C                    # creep speed at which adhesion saturates, 2.77e-6 m/s
VCR1, VCR2 = 2.8e-6, 5.6e-6               # Renard breakpoints, just above USAT
TEND = 5.0
L0 = 1.0                                  # spring length [m]


# Renard's coefficients C1..C6: mu_s, mu_d, mu_max, mu_min, V_cr1, V_cr2
RENARD = (MUS, MUK, MUS, MUK, VCR1, VCR2)


def mu(s, c=RENARD):
    """Renard's law (docs/theory.md 6.1); with mu_max = mu_s and mu_min = mu_d = mu_k
    it is mu_s up to V_cr1, a cubic drop to mu_k by V_cr2, mu_k beyond."""
    mus, mud, mumax, mumin, v1, v2 = c
    if s <= v1:
        x = s / v1
        return mus + (mumax - mus) * x * (2.0 - x)
    if s < v2:
        w = (s - v1) / (v2 - v1)
        return mumax + (mumin - mumax) * (3.0 - 2.0 * w) * w * w
    return mud - (mud - mumin) / (1.0 + (mud - mumin) * (s - v2) ** 2)


def reference(tend=TEND, rtol=1e-11):
    """Independent integration of m x'' = -k x + F, u = x' - V (block relative
    to the belt, <= 0 here). Adhesion (unsaturated): F = -C u, until
    C |u| reaches mu(|u|) m g (= mu_s m g: |u| < V_cr1 there). Saturated:
    F = mu(|u|) m g along the belt, in three regions of |u| (below V_cr1,
    between, above V_cr2) so that no step crosses a breakpoint, until C |u|
    falls back to mu_s m g. Returns the switch events and the dense pieces."""
    def rhs_stick(t, y):
        return [y[1], (-KS * y[0] - C * (y[1] - V)) / M]

    def rhs_slip(t, y):
        return [y[1], (-KS * y[0] + mu(V - y[1]) * M * G) / M]

    def ev(fun, direction):
        fun.terminal, fun.direction = True, direction
        return fun

    t, y, phase, region = 0.0, np.array([0.0, V]), "stick", 0
    events, segs = [], []
    while t < tend:
        if phase == "stick":
            evs, f = [ev(lambda tt, yy: C * (V - yy[1]) - mu(V - yy[1]) * M * G, 1)], rhs_stick
        elif region == 0:
            evs, f = [ev(lambda tt, yy: C * (V - yy[1]) - mu(V - yy[1]) * M * G, -1),
                      ev(lambda tt, yy: (V - yy[1]) - VCR1, 1)], rhs_slip
        elif region == 1:
            evs, f = [ev(lambda tt, yy: (V - yy[1]) - VCR1, -1), ev(lambda tt, yy: (V - yy[1]) - VCR2, 1)], rhs_slip
        else:
            evs, f = [ev(lambda tt, yy: (V - yy[1]) - VCR2, -1)], rhs_slip
        s = solve_ivp(f, (t, tend), y, method="Radau", rtol=rtol, atol=[1e-14, 1e-14], events=evs, dense_output=True)
        segs.append((t, s.t[-1], s.sol))
        if s.status != 1:
            break
        k = [j for j in range(len(evs)) if len(s.t_events[j])][0]
        t, y = s.t_events[k][0], s.y_events[k][0].copy()
        if phase == "stick":
            phase, region = "slip", 0
            events.append((t, "fric_saturate"))
        elif region == 0:
            if k == 0:
                phase = "stick"
                events.append((t, "fric_unsaturate"))
            else:
                region = 1
        elif region == 1:
            region = 0 if k == 0 else 2
        else:
            region = 1
    return events, segs


def ref_x(segs, t):
    out = np.empty_like(t)
    for a, b, sol in segs:
        sel = (t >= a) & (t <= b)
        if sel.any():
            out[sel] = sol(t[sel])[0]
    return out


def classical():
    """Two-level Coulomb law, rigid stick (e.g. B. N. J. Persson, Sliding
    friction, Springer 2000, ch. 13; the spring-block model): slip from
    x_s = mu_s m g/k at the belt speed V, harmonic about x_k = mu_k m g/k
    with w = sqrt(k/m) and amplitude A = sqrt(D^2 + (V/w)^2), D = x_s - x_k,
    until the block is back at the belt speed (x = x_k - D); stick from
    x_k - D to x_s at speed V. Period (pi + 2 atan(V/(w D)))/w + 2 D/V."""
    w = math.sqrt(KS / M)
    xk, d = MUK * M * G / KS, (MUS - MUK) * M * G / KS
    a = math.sqrt(d * d + (V / w) ** 2)
    t_slip = (math.pi + 2.0 * math.atan(V / (w * d))) / w
    return dict(period=t_slip + 2.0 * d / V, slip=t_slip, xmax=xk + a, xmin=xk - a)


def deck(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-12, dtout=1e-3):
    d = Deck("stick-slip oscillator: block on a belt, spring to a fixed point, /FRICTION Renard two-level")
    z0 = belt.add_block_on_belt(d, R, M, K, G, MBELT, V)
    d.type6(1, 1, 2, 1, visc=VISC, title="contact (no TYPE6 friction)")
    d.friction(1, ifric=3, iform=1, c=RENARD, visf=VISF,
               title="Renard two-level: mu_s = mu_max 0.4, mu_k = mu_d = mu_min 0.25, V_cr 2.8, 5.6 um/s; viscous VISF 1e6")
    d.spring(1, 0, (-L0, 0.0, z0), 1, (0.0, 0.0, z0), a=KS, title="spring k = 100 N/m to a fixed point, relaxed at t = 0")
    d.run(TEND, dtout)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel)
    return d


def cycle(ev):
    """Period, slip duration from the last two saturations; times."""
    sat = [t for t, k in ev if k == "fric_saturate"]
    uns = [t for t, k in ev if k == "fric_unsaturate"]
    return sat, uns


def main():
    r = rcval.Result(rcval.run_case())
    ev_m = list(zip(r.ev_t, r.ev_kind))
    ev_r, segs = reference()
    cl = classical()
    sat_m, uns_m = cycle(ev_m)
    sat_r, uns_r = cycle(ev_r)
    kinds_ok = [k for _, k in ev_m] == [k for _, k in ev_r] and len(sat_m) >= 4
    rcval.check("frc_stick_slip.events", kinds_ok,
                f"{len(sat_m)} fric_saturate and {len(uns_m)} fric_unsaturate, alternating as in the reference "
                f"({len(ev_r)} switches); no other event: {set(k for _, k in ev_m)}")
    if not kinds_ok:
        rcval.finish()
    # switch times (every one): the reference is the same law
    et = max(abs(a - b) for (a, _), (b, _) in zip(ev_m, ev_r))
    rcval.check("frc_stick_slip.switch_times", et < 1e-5,
                f"max |t_switch - t_switch,ref| over {len(ev_m)} switches = {et:.1e} s (< 1e-5 s)")
    # last complete cycle: saturation k-1 -> k
    T_m, T_r = sat_m[-1] - sat_m[-2], sat_r[-1] - sat_r[-2]
    S_m, S_r = uns_m[-1] - sat_m[-2], uns_r[-1] - sat_r[-2]
    e1, e2 = rcval.rel(T_m, T_r), rcval.rel(S_m, S_r)
    rcval.check("frc_stick_slip.period_vs_solve_ivp", e1 < 1e-5 and e2 < 1e-5,
                f"period {T_m:.9f} s, reference {T_r:.9f} s, rel. error {e1:.1e}; slip phase {S_m:.9f} s, "
                f"reference {S_r:.9f} s, rel. error {e2:.1e} (< 1e-5)")
    cyc = (r.t >= sat_m[-2]) & (r.t <= sat_m[-1])
    xmax_m, xmin_m = rcval.refined_extreme(r.pos[cyc, 0, 0], 1), rcval.refined_extreme(r.pos[cyc, 0, 0], -1)
    tt = np.linspace(sat_r[-2], sat_r[-1], 400001)
    xr = ref_x(segs, tt)
    xmax_r, xmin_r = xr.max(), xr.min()
    amp_m, amp_r = 0.5 * (xmax_m - xmin_m), 0.5 * (xmax_r - xmin_r)
    e1, e2, e3 = rcval.rel(amp_m, amp_r), abs(xmax_m - xmax_r) / amp_r, abs(xmin_m - xmin_r) / amp_r
    rcval.check("frc_stick_slip.amplitude_vs_solve_ivp", max(e1, e2, e3) < 1e-5,
                f"last cycle: x in [{xmin_m:.9f}, {xmax_m:.9f}] m, reference [{xmin_r:.9f}, {xmax_r:.9f}]; "
                f"half amplitude {amp_m:.9f} m, reference {amp_r:.9f}, rel. error {e1:.1e}; extremes off by "
                f"{e2:.1e}, {e3:.1e} of it (< 1e-5)")
    # against the classical two-level limit cycle
    e1, e2 = rcval.rel(T_m, cl["period"]), rcval.rel(S_m, cl["slip"])
    e3 = rcval.rel(amp_m, 0.5 * (cl["xmax"] - cl["xmin"]))
    e4 = max(abs(xmax_m - cl["xmax"]), abs(xmin_m - cl["xmin"])) / (0.5 * (cl["xmax"] - cl["xmin"]))
    rcval.check("frc_stick_slip.classical", max(e1, e2, e3, e4) < 1e-3,
                f"classical two-level cycle: period {cl['period']:.9f} s (rel. error {e1:.1e}), slip {cl['slip']:.9f} s "
                f"({e2:.1e}), x in [{cl['xmin']:.9f}, {cl['xmax']:.9f}] m (half amplitude {e3:.1e}, extremes {e4:.1e}); "
                f"< 1e-3")
    # stick phases: the block creeps behind the belt at under the saturation speed
    st = (r.slip[:, 0] == 0) & (r.t > 0.01)
    creep = np.max(V - r.vel[st, 0, 0])
    rcval.check("frc_stick_slip.stick_creep", 0 <= creep <= USAT * (1 + 1e-5),
                f"while adhering, max (V - x') = {creep:.6e} m/s <= mu_s m g / C = {USAT:.6e} m/s (to 1e-5; it reaches it at the switches)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
