"""Preload (/SOLVER Preload 1): a dynamic run started from the static equilibrium at t = 0.

case.rad: the column of validation/static_column (N = 5 equal spheres on a
floor, linear TYPE6 contacts of stiffness k, held to the vertical) and the
sphere beside it on a Hertz contact (/INTER/POWER, F = K P^1.5), under a
constant gravity g, run dynamically (CVODE; the IDA mode of
scripts/check.sh runs it with --method ida) from the equilibrium at t = 0.
Closed form (README.md): the contact under sphere j + 1 (j = 0 the floor)
carries (N - j) m g, its penetration (N - j) m g / k; the Hertz contact
carries m_h g, its penetration (m_h g / K)^(1/1.5); at rest: every record
of the dynamic run, the first (t = 0) and the later ones (t = 0.1 ... 1 s),
has these forces and no velocity.

case_incline.rad: a sphere (rotations held) on the floor under a gravity
tilted by theta = atan(mu) - 0.05 (below the friction angle), TYPE6 friction
mu = 0.3 with the stick spring K_t: the friction force is m g sin(theta)
from the first record on, the normal force m g cos(theta), the sphere sits
at its stick spring's offset x = m g sin(theta) / K_t and does not move.

The decks keep their /SOLVER card in every mode of scripts/check.sh (it
holds the preload): in the 'default' mode the runs are at the decks'
settings all the same; the check names carry the mode's prefix as usual.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from column import FLOOR, G, K, KH, M, MH, N, R, RH, XH, column_cards  # noqa: E402,F401
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

T_END, DT_OUT = 1.0, 0.1
TOL = 1e-8
MU, KT, RS = 0.3, 2.0e4, 0.05     # incline: friction coefficient, stick stiffness [N/m], radius [m]
THETA = math.atan(MU) - 0.05
# the velocity bound: KINSOL accepts a residual force of at most 1e-8 of a
# body's weight (src/solver/static.c); N such imbalances excite the column's
# modes, the slowest of frequency omega_1 = 2 sqrt(k / m) sin(pi / (2 (2 N + 1))),
# to speeds of at most N 1e-8 m g / (m omega_1)
W1 = 2.0 * math.sqrt(K / M) * math.sin(math.pi / (2.0 * (2 * N + 1)))
VBOUND = N * 1e-8 * G / W1
# the incline's displacement bound: 1e-8 m g on the stick spring, as a step load
DBOUND = 2e-8 * M * G / KT


def deck():
    d = Deck("preload: column of 5 spheres and a Hertz sphere at rest from t = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    column_cards(d, N, R, M, MH, RH, KH, XH, FLOOR, lambda d: d.grav(1, "Z", -G))
    d.run(T_END, DT_OUT)
    d.solver(method=1, rtol=1e-8, preload=1)
    return d


def deck_incline():
    d = Deck("preload: a sphere held by friction below its slipping angle")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    add_sphere_over_plane(d, M, RS, RS, title="sphere")
    d.bcs(1, 1, "000 111", title="rotations held")
    d.grav(1, "X", G * math.sin(THETA))
    d.grav(2, "Z", -G * math.cos(THETA))
    d.type6(1, 1, 2, 1, fric=MU, stiff=KT, title="sphere - floor")
    d.run(T_END, DT_OUT)
    d.solver(method=1, rtol=1e-8, preload=1)
    return d


def main():
    r = rcval.Result(rcval.run_case(keep_solver=True))
    ids = list(r.inter_id)
    pre = str(r.attrs.get("preload", ""))
    rcval.check("preload_column.attribute", "static equilibrium" in pre and int(r.attrs.get("preload_newton_iters", -1)) > 0,
                f"preload attribute: {pre[:60]!r}..., preload_newton_iters {r.attrs.get('preload_newton_iters', '?')}")
    rcval.check("preload_column.records", len(r.t) >= 11 and abs(r.t[-1] - T_END) < 1e-12,
                f"{len(r.t)} records to t = {r.t[-1]:g} s")
    vmax = float(np.abs(r.vel).max())
    rcval.check("preload_column.at_rest", vmax < VBOUND,
                f"max |v| over the records {vmax:.3g} m/s (< {VBOUND:.3g} m/s: N 1e-8 m g / (m omega_1))")
    ef, ep, worst = 0.0, 0.0, ""
    for j in range(N):
        c = ids.index(j + 1)
        F = (N - j) * M * G
        P = F / K
        e1 = float(np.abs(r.fn[:, c] - F).max() / F)
        e2 = float(np.abs(r.pen[:, c] - P).max() / P)
        if max(e1, e2) > max(ef, ep):
            worst = f"contact {j + 1}"
        ef, ep = max(ef, e1), max(ep, e2)
    rcval.check("preload_column.column_forces", ef < TOL,
                f"max rel. error of the contact forces against (N - j) m g over every record: {ef:.2e} (< {TOL:g}; "
                f"worst {worst}); floor at t = 0 {r.fn[0, ids.index(1)]:.12g} N, at t_end {r.fn[-1, ids.index(1)]:.12g} N "
                f"(5 m g = {N * M * G:.12g} N)")
    rcval.check("preload_column.column_penetrations", ep < TOL,
                f"max rel. error of the penetrations against (N - j) m g / k: {ep:.2e} (< {TOL:g})")
    closed = bool((r.mode[0, :] == 2).all())
    rcval.check("preload_column.closed_from_start", closed and len(r.ev_t) == 0,
                f"modes at t = 0 {[int(x) for x in r.mode[0, :]]} (2: closed), {len(r.ev_t)} events")
    c = ids.index(N + 1)
    F = MH * G
    P = (F / KH) ** (1.0 / 1.5)
    eF = float(np.abs(r.fn[:, c] - F).max() / F)
    eP = float(np.abs(r.pen[:, c] - P).max() / P)
    rcval.check("preload_column.hertz", max(eF, eP) < TOL,
                f"Hertz sphere: max rel. error of F against m g {eF:.2e}, of P against (m g / K)^(1/1.5) {eP:.2e} "
                f"(< {TOL:g}); P at t = 0 {r.pen[0, c]:.12e} m (closed form {P:.12e} m)")

    r = rcval.Result(rcval.run_case("case_incline.rad", keep_solver=True))
    ft, fnr, x0 = M * G * math.sin(THETA), M * G * math.cos(THETA), M * G * math.sin(THETA) / KT
    eft = float(np.abs(r.ffric[:, 0, 0] + ft).max() / ft)
    efn = float(np.abs(r.fn[:, 0] - fnr).max() / fnr)
    rcval.check("preload_column.incline_forces", max(eft, efn) < TOL,
                f"friction force against -m g sin(theta) {eft:.2e}, normal force against m g cos(theta) {efn:.2e} "
                f"(< {TOL:g}) over every record; at t = 0 {r.ffric[0, 0, 0]:.12g} N ({-ft:.12g} N)")
    d = float(np.sqrt(((r.pos[:, 0, :] - r.pos[0, 0, :]) ** 2).sum(axis=1)).max())
    ex = abs(r.pos[0, 0, 0] - x0)
    rcval.check("preload_column.incline_held", d < DBOUND and ex < 1e-8 * x0 and int((r.slip[:, 0] != 0).sum()) == 0,
                f"displacement over the run {d:.3g} m (< {DBOUND:.3g} m), x at t = 0 {r.pos[0, 0, 0]:.12e} m against "
                f"m g sin(theta) / K_t = {x0:.12e} m, slipping records {int((r.slip[:, 0] != 0).sum())}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_incline.rad": deck_incline()})
