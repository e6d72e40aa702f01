"""Newton's cradle of n equal steel balls with Hertz contacts (cradle3, cradle5).

The balls lie on the x axis, touching with zero gaps (centres exactly 2R
apart: R = 2^-7 m, so every centre and every gap is an exact binary number),
no gravity; ball 1 is launched at v0 towards the others. Ball-ball contacts
are /INTER/POWER with F = K delta^1.5, C = 0 (Hertz, R_eff = R/2).
Reference: scipy solve_ivp (DOP853, rtol 1e-12) of the 1-D chain with
unilateral Hertz contacts, restarted at every contact opening or closing
(event location).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

import rcval
from deck import Deck

R = 2.0**-7                      # 7.8125 mm
RHO = 7850.0
E, NU = 210.0e9, 0.3
ESTAR = E / (2.0 * (1.0 - NU**2))  # steel on steel: 1/E* = 2 (1 - nu^2) / E
M = RHO * 4.0 / 3.0 * math.pi * R**3
K = 4.0 / 3.0 * ESTAR * math.sqrt(R / 2.0)  # R_eff = R R / (R + R) = R / 2


def hertz_pair(v0):
    """Two-ball Hertz impact (m_eff = m/2) at approach speed v0: maximum
    approach and contact duration (Johnson, Contact Mechanics, 11.4)."""
    meff = 0.5 * M
    dmax = (5.0 * meff * v0**2 / (4.0 * K)) ** 0.4
    from scipy.special import gamma
    return dmax, 2.0 * dmax / v0 * math.sqrt(math.pi) * gamma(1.4) / gamma(0.9)


def reference(n, v0, t_end):
    """Chain ODE m x_i'' = F_{i-1} - F_i, F_j = K max(delta_j, 0)^1.5,
    delta_j = 2R - (x_{j+1} - x_j), in displacements u_i = x_i - x_i(0).
    Integrated piecewise between contact events (delta_j crossing zero), so
    that every piece has a smooth right-hand side. Returns the final
    velocities, the maximum overlap of each contact, the event list
    [(t, j, 'open'|'close')] and the time of the last event."""
    closed = [True] * (n - 1)    # at t = 0: delta = 0 with delta' >= 0 (1-2) or delta'' > 0 just after (the rest)

    def rhs(t, y):
        u, v = y[:n], y[n:]
        d = u[:-1] - u[1:]
        f = np.where(np.array(closed), K * np.maximum(d, 0.0) ** 1.5, 0.0)
        a = np.zeros(n)
        a[:-1] -= f / M
        a[1:] += f / M
        return np.concatenate([v, a])

    def make_event(j):
        def ev(t, y):
            return y[j] - y[j + 1]
        ev.terminal = True
        ev.direction = -1.0 if closed[j] else 1.0
        return ev

    y = np.zeros(2 * n)
    y[n] = v0
    t = 0.0
    dmax = np.zeros(n - 1)
    events = []
    while t < t_end:
        evs = [make_event(j) for j in range(n - 1)]
        s = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=1e-12, atol=1e-20, events=evs, dense_output=True)
        # maximum overlaps on this piece: dense output on a fine grid, then polished
        tt = np.linspace(t, s.t[-1], 2001)
        yy = s.sol(tt)
        for j in range(n - 1):
            if closed[j]:
                dj = yy[j] - yy[j + 1]
                k = int(np.argmax(dj))
                if 0 < k < len(tt) - 1:
                    from scipy.optimize import minimize_scalar
                    res = minimize_scalar(lambda x: -(s.sol(x)[j] - s.sol(x)[j + 1]), bounds=(tt[k - 1], tt[k + 1]),
                                          method="bounded", options={"xatol": 1e-15})
                    dmax[j] = max(dmax[j], -res.fun)
                dmax[j] = max(dmax[j], dj.max())
        t, y = s.t[-1], s.y[:, -1]
        if s.status == 1:
            hit = [j for j in range(n - 1) if len(s.t_events[j])]
            for j in hit:
                events.append((t, j, "open" if closed[j] else "close"))
                closed[j] = not closed[j]
    return y[n:], dmax, events


def deck(n, v0, t_end, dt_out):
    d = Deck(f"Newton's cradle, {n} steel balls, Hertz power-law contacts")
    nodes = [(i + 1, 2.0 * R * i, 0.0, 0.0) for i in range(n)]
    d.nodes(nodes)
    for i in range(n):
        d.rbody(i + 1, i + 1, M, [0.4 * M * R * R] * 3, grnod=i + 1, title=f"ball {i + 1}")
    for i in range(n):
        d.sphere(i + 1, i + 1, nodes[i][1:], R, title=f"ball {i + 1} R = 7.8125 mm")
    for i in range(n):
        d.grnod(i + 1, [i + 1], title=f"ball {i + 1}")
    d.inivel(1, (v0, 0.0, 0.0), 1)
    for j in range(n - 1):
        d.power(j + 1, j + 1, j + 2, k=K, m1=1.5, c=0.0, title=f"Hertz {j + 1}-{j + 2}: K delta^1.5, no damping")
    d.run(t_end, dt_out)
    d.solver(rtol=1e-10, atol_pos=1e-14, atol_vel=1e-10, atol_energy=1e-12)
    return d


def check(name, n, v0, t_end, case):
    """The checks of one cradle: final velocities, kinetic energy, ledger,
    peak overlaps against the reference, and no ball passing into the next."""
    vref, dref, evref = reference(n, v0, t_end)
    dpair, tc = hertz_pair(v0)
    t_last = evref[-1][0]
    print(f"reference: final velocities / v0 = {', '.join(f'{x:+.9f}' for x in vref / v0)}; "
          f"{len(evref)} contact events, last opening at {t_last:.6e} s; peak overlaps "
          f"{', '.join(f'{x:.6e}' for x in dref)} m (two-ball Hertz {dpair:.6e} m, tc {tc:.3e} s)")
    r = rcval.Result(rcval.run_file(case))
    v = r.vel[-1, :, 0]
    err = np.abs(v - vref) / v0
    rcval.check(f"{name}.final_velocities", err.max() < 1e-4,
                f"v(t_end) / v0 = {', '.join(f'{x:+.9f}' for x in v / v0)}; solve_ivp "
                f"{', '.join(f'{x:+.9f}' for x in vref / v0)}; max error {err.max():.2e} v0 (< 1e-4)")
    ek = 0.5 * M * np.sum(r.vel[-1] ** 2)
    e0 = 0.5 * M * v0**2
    e = abs(ek - e0) / e0
    rcval.check(f"{name}.kinetic_energy", e < 1e-5,
                f"kinetic energy at t_end {ek:.9e} J, 1/2 m v0^2 {e0:.9e} J, rel. error {e:.2e} (< 1e-5)")
    rcval.check_ledger(f"{name}.ledger", r, 1e-5)
    # peak overlaps: the series (dt_out), refined by a parabola through the records around the maximum
    pm = []
    for j in range(n - 1):
        p = r.pen[:, j]
        k = int(np.argmax(p))
        if 0 < k < len(p) - 1 and 2 * p[k] - p[k - 1] - p[k + 1] != 0:
            a, b, c = p[k - 1], p[k], p[k + 1]
            pm.append(b + 0.125 * (a - c) ** 2 / (2 * b - a - c))
        else:
            pm.append(p[k])
    pm = np.array(pm)
    e = np.max(np.abs(pm - dref) / dref)
    rcval.check(f"{name}.peak_overlaps", e < 1e-3,
                f"max overlap per contact {', '.join(f'{x:.6e}' for x in pm)} m; solve_ivp "
                f"{', '.join(f'{x:.6e}' for x in dref)} m; max rel. error {e:.2e} (< 1e-3)")
    pmax = float(r.pen.max())
    gap = np.diff(r.pos[:, :, 0], axis=1) - 2 * R
    deepest = float(-gap.min())
    ok = pmax < 3 * dpair and deepest < 3 * dpair
    rcval.check(f"{name}.no_pass_through", ok,
                f"deepest overlap / two-ball Hertz approach = {max(pmax, deepest) / dpair:.3e} (< 3): "
                f"{max(pmax, deepest):.3e} m (penetration output {pmax:.3e} m, from the centres {deepest:.3e} m), "
                f"dmax {dpair:.3e} m")
    return r


def main(name, n, v0, t_end, dt_out):
    """The whole of a cradle problem's check.py: n balls, ball 1 launched at
    v0 [m/s], run to t_end [s] with records every dt_out [s]. Runs the
    checks on case.rad in the problem's folder, or with --write-case writes
    that deck there."""
    here = os.path.dirname(os.path.abspath(sys.argv[0]))

    def run_checks():
        check(name, n, v0, t_end, os.path.join(here, "case.rad"))
        rcval.finish()

    rcval.entry(run_checks, lambda: deck(n, v0, t_end, dt_out))
