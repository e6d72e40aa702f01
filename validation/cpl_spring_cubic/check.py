"""Undamped cubic spring (/COUPLING/SPRING, Iform 2: polynomial k_eff) period by quadrature.

k_eff = a + c (x - x0)^2, so f = a u + c u^3 with u = x - x0 and
V(u) = a u^2/2 + c u^4/4. Released from rest at u = A, the period is
T = 4 int_0^A du / sqrt(2 (E - V(u)) / m), E = V(A) (README.md), evaluated by
scipy quadrature. Checks the period measured over 100 periods, and that the
energy is conserved over them (the integrated ledger and the analytic
potential) at the level of the tolerances, shrinking with rtol.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import quad

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, A_LIN, C3, X0, AMP = 1.3, 250.0, 4.0e4, 0.5, 0.08
NPER = 100


def V(u):
    return 0.5 * A_LIN * u**2 + 0.25 * C3 * u**4


def period():
    """T = 4 int_0^A du / sqrt(2 (E - V) / m); with u = A sin(th) the
    integrand is smooth: E - V = cos^2(th) (a A^2/2 + c A^4 (1 + sin^2 th)/4)."""
    f = lambda th: AMP / math.sqrt(2.0 / M * (0.5 * A_LIN * AMP**2 + 0.25 * C3 * AMP**4 * (1 + math.sin(th) ** 2)))
    val, err = quad(f, 0.0, 0.5 * math.pi, epsabs=0, epsrel=1e-13)
    return 4.0 * val


T_REF = period()


def deck(rtol=1e-11):
    d = Deck("undamped cubic spring")
    d.nodes([(1, X0 + AMP, 0.0, 0.0)])
    d.rbody(1, 1, M, [0.01, 0.01, 0.01], title="mass 1.3 kg")
    d.spring(1, 0, (0.0, 0.0, 0.0), 1, (X0 + AMP, 0.0, 0.0), iform=2, x0=X0, a=A_LIN, b=0.0, c=C3,
             title="k_eff = 250 + 4e4 (x - x0)^2")
    d.run((NPER + 1) * T_REF, T_REF / 40)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_vel=rtol, atol_energy=1e-2 * rtol)
    return d


def measure(path):
    """Upward zero crossings of u by cubic Hermite interpolation (u, u')."""
    r = rcval.Result(path)
    u, v, t = r.pos[:, 0, 0] - X0, r.vel[:, 0, 0], r.t
    cross = []
    for i in np.where((u[:-1] < 0) & (u[1:] >= 0))[0]:
        h = t[i + 1] - t[i]
        s = -u[i] / (u[i + 1] - u[i])
        for _ in range(20):  # Newton on the Hermite cubic in s in [0, 1]
            h00, h10, h01, h11 = 2*s**3 - 3*s**2 + 1, s**3 - 2*s**2 + s, -2*s**3 + 3*s**2, s**3 - s**2
            p = h00 * u[i] + h10 * h * v[i] + h01 * u[i + 1] + h11 * h * v[i + 1]
            d00, d10, d01, d11 = 6*s**2 - 6*s, 3*s**2 - 4*s + 1, -6*s**2 + 6*s, 3*s**2 - 2*s
            dp = d00 * u[i] + d10 * h * v[i] + d01 * u[i + 1] + d11 * h * v[i + 1]
            s -= p / dp
        cross.append(t[i] + s * h)
    cross = np.array(cross)
    T = (cross[-1] - cross[0]) / (len(cross) - 1)
    E0 = V(AMP)
    ledger = np.max(np.abs(r.energy["energy_total"] - r.energy["energy_total"][0])) / E0
    physical = np.max(np.abs(0.5 * M * np.sum(r.vel[:, 0, :] ** 2, axis=1) + V(u) - E0)) / E0
    return T, len(cross) - 1, ledger, physical, r.attrs.get("stats_steps", 0), r.attrs.get("rtol", 1e-11)


def main():
    T, n, ledger, physical, steps, rtol_run = measure(rcval.run_case())
    e = rcval.rel(T, T_REF)
    rcval.check("cpl_spring_cubic.period", e < 1e-6,
                f"T = {T:.12f} s over {n} periods, quadrature {T_REF:.12f} s, rel. error {e:.2e} (< 1e-6); "
                f"linear spring alone: {2 * math.pi * math.sqrt(M / A_LIN):.6f} s")
    # BDF is not symplectic: each step may leave an energy error up to the
    # local tolerance, so the drift bound is (steps) x rtol (the run's rtol:
    # 1e-11 on the card, the default at the default settings)
    bound = min(1e-6, steps * rtol_run)
    rcval.check("cpl_spring_cubic.energy", ledger < bound and physical < bound,
                f"over {n} periods: max |E_total - E0| / E0 = {ledger:.2e} (ledger), "
                f"|m v^2/2 + V(u) - E0| / E0 = {physical:.2e} (analytic potential); rtol {rtol_run:g}, "
                f"{steps} steps (< min(1e-6, steps x rtol) = {bound:.1e})")
    res = [measure(rcval.run(deck(rtol), keep_solver=True))[3] for rtol in (1e-8, 1e-10)]
    if rcval.DEFAULTS:  # the study's rtol 1e-11 point is case.rad with its /SOLVER card
        physical = measure(rcval.run_case(keep_solver=True))[3]
    rcval.check("cpl_spring_cubic.energy_convergence", res[1] < res[0] and physical < res[1],
                f"energy drift over {NPER} periods at rtol 1e-8, 1e-10, 1e-11: {res[0]:.2e}, {res[1]:.2e}, {physical:.2e}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
