"""Damped spring-mass (/COUPLING/SPRING, constant k_eff, damper k_d) against the closed form.

A body on a spring-damper to a point fixed in space, without gravity, released
from rest with the spring stretched by u0 along an oblique line. The motion
stays on the line (central force), u(t) = x(t) - x0 is the damped oscillator
(README.md). Checks the position history (max error below 1e-6 of u0), that
the body stays on the line, the energy ledger, and that the error shrinks as
rtol shrinks.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, K, ZETA, X0, U0 = 2.5, 400.0, 0.05, 1.2, 0.1
KD = 2.0 * ZETA * math.sqrt(K * M)
E = np.array([0.48, -0.6, 0.64])  # unit direction from the fixed point to the body
WN = math.sqrt(K / M)
T_END = 10 * 2 * math.pi / WN   # ten periods


def reference(t):
    """u(t) for u(0) = u0, u'(0) = 0."""
    wd = WN * math.sqrt(1 - ZETA**2)
    return U0 * np.exp(-ZETA * WN * t) * (np.cos(wd * t) + ZETA * WN / wd * np.sin(wd * t))


def deck(rtol=1e-9):
    p = (X0 + U0) * E
    d = Deck("damped spring-mass")
    d.nodes([(1, p[0], p[1], p[2])])
    d.rbody(1, 1, M, [0.3, 0.4, 0.5], title="mass 2.5 kg")
    d.spring(1, 0, (0.0, 0.0, 0.0), 1, tuple(p), iform=1, x0=X0, kd=KD, a=K,
             title="k = 400 N/m, zeta = 0.05")
    d.run(T_END, T_END / 400)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_vel=rtol, atol_energy=1e-2 * rtol)
    return d


def errors(path):
    r = rcval.Result(path)
    x = r.pos[:, 0, :]
    along = x @ E
    off = np.linalg.norm(x - np.outer(along, E), axis=1)
    err = np.max(np.abs(along - X0 - reference(r.t))) / U0
    return r, err, np.max(off)


def main():
    r, err, off = errors(rcval.run_case())
    rcval.check("cpl_spring_damped.history", err < 1e-6,
                f"max |u - u_exact| / u0 = {err:.2e} over {len(r.t)} outputs, 10 periods (< 1e-6)")
    rcval.check("cpl_spring_damped.on_line", off < 1e-9 * X0, f"max distance from the line {off:.2e} m (< 1e-9 x0)")
    e = r.energy
    e0 = 0.5 * K * U0**2
    stored = 0.5 * K * (r.pos[:, 0, :] @ E - X0) ** 2
    res = np.max(np.abs(e["energy_total"] - e["energy_total"][0])) / e0
    st = np.max(np.abs(e["energy_coupling_elastic"] - (stored - e0))) / e0
    rcval.check("cpl_spring_damped.energy", res < 1e-6 and st < 1e-6,
                f"ledger residual {res:.2e}, stored energy vs k u^2/2: {st:.2e} (of k u0^2/2, < 1e-6); "
                f"dissipated {e['energy_coupling_damping'][-1]:.6f} J of {e0:.6f} J")
    errs = [errors(rcval.run(deck(rtol), keep_solver=True))[1] for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("cpl_spring_damped.convergence", errs[2] < errs[1] < errs[0],
                "max error / u0 at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
