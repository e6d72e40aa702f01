"""Bodies swinging on elastic catenaries: the energy ledger closes.

Two independent pendulums hang from fixed anchors on heavy elastic lines
(/COUPLING/CATENARY, line weight comparable to the body's): body 1 swings in
a plane, through the vertical (the line goes slack and taut); body 2 swings
in 3-D. Checks (README.md):
  - the ledger: energy_total (kinetic + potential of the bodies + line energy
    W_cat integrated from the work of the end forces) constant to the
    tolerance level, shrinking with rtol;
  - W_cat is the elastic + gravitational energy of the lines: its change
    equals that of the closed-form line energy evaluated from the elastic
    catenary solved by scipy at the output positions
    (validation/lib/catenary_ref.py).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import catenary_ref  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, M, LEQ, LAM, D = 9.81, 5.0, 3.0, 1.5, 2.0e4
EA, W = D * LEQ, LAM * G
ANCHOR = [np.array([0.0, 0.0, 0.0]), np.array([5.0, 0.0, 0.0])]
START = [np.array([1.2, 0.0, -2.6]), np.array([6.5, 0.0, -2.5])]
V0 = [np.array([0.0, 0.0, 0.0]), np.array([0.0, 2.0, 0.0])]
T_END = 10.0


def deck(rtol=1e-9):
    d = Deck("bodies swinging on catenaries")
    d.nodes([(k + 1, *START[k]) for k in range(2)])
    for k in range(2):
        d.rbody(k + 1, k + 1, M, [0.05, 0.05, 0.05], title=f"body {k + 1}")
        d.catenary(k + 1, 0, tuple(ANCHOR[k]), k + 1, tuple(START[k]), LAM, LEQ, D, title=f"line {k + 1}")
    d.grnod(2, [2])
    d.inivel(1, tuple(V0[1]), 2)
    d.grav(1, "Z", -G)
    d.run(T_END, 0.02)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_vel=rtol, atol_energy=1e-2 * rtol)
    return d


def line_energies(r):
    """Closed-form energy of both lines at each output time (NaN when a line
    is within 1e-3 L_eq of vertical, where (c, u1, u2) are ill-conditioned)."""
    out = np.full(len(r.t), np.nan)
    guess = [None, None]
    for i in range(len(r.t)):
        tot = 0.0
        for k in range(2):
            rel = r.pos[i, k, :] - ANCHOR[k]
            X, Y = math.hypot(rel[0], rel[1]), rel[2]
            if X < 1e-3 * LEQ:
                tot = np.nan
                break
            H, V1, V2 = catenary_ref.elastic(X, Y, LEQ, W, EA, guess[k])
            guess[k] = (H, math.asinh(V1 / H), math.asinh(V2 / H))
            el, gr = catenary_ref.line_energy(H, V1, ANCHOR[k][2], LEQ, W, EA)
            tot += el + gr
        out[i] = tot
    return out


def main():
    r = rcval.Result(rcval.run_case())
    e = r.energy
    scale = M * G * LEQ
    drift = np.max(np.abs(e["energy_total"] - e["energy_total"][0])) / scale
    xmin = np.min(np.abs(r.pos[:, 0, 0]))
    rcval.check("cpl_catenary_swing.ledger", drift < 1e-6,
                f"max |E_total - E0| / (M g L) = {drift:.2e} over {T_END} s (< 1e-6, rtol 1e-9); "
                f"kinetic energy up to {np.max(e['energy_kinetic']):.2f} J; body 1 passes "
                f"{xmin:.1e} m from the vertical")
    ref = line_energies(r)
    ok = ~np.isnan(ref)
    i0 = np.argmax(ok)
    d = (e["energy_catenary"][ok] - e["energy_catenary"][i0]) - (ref[ok] - ref[i0])
    err = np.max(np.abs(d)) / scale
    rcval.check("cpl_catenary_swing.line_energy", err < 1e-6,
                f"W_cat change vs closed-form elastic + gravitational line energy at {ok.sum()} of "
                f"{len(ok)} outputs: max error {err:.2e} M g L (< 1e-6); line energy spans "
                f"{np.nanmax(ref) - np.nanmin(ref):.2f} J")
    drifts = []
    for rtol in (1e-6, 1e-8):
        rr = rcval.Result(rcval.run(deck(rtol), keep_solver=True))
        drifts.append(np.max(np.abs(rr.energy["energy_total"] - rr.energy["energy_total"][0])) / scale)
    if rcval.DEFAULTS:  # the study's rtol 1e-9 point is case.rad with its /SOLVER card
        et = rcval.Result(rcval.run_case(keep_solver=True)).energy["energy_total"]
        drift = np.max(np.abs(et - et[0])) / scale
    rcval.check("cpl_catenary_swing.convergence", drifts[1] < drifts[0] and drift < drifts[1],
                f"ledger drift at rtol 1e-6, 1e-8, 1e-9: {drifts[0]:.2e}, {drifts[1]:.2e}, {drift:.2e}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
