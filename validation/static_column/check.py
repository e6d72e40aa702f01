"""Static analysis (/SOLVER Method 3): a column of spheres and a Hertz contact under ramped gravity.

A column of N = 5 equal spheres on a floor, linear TYPE6 contacts of
stiffness k, and beside it one sphere on the floor with a Hertz contact
(/INTER/POWER, F = K P^1.5); gravity ramped by a /FUNCT from 0 to g over
t_end. The static analysis solves the equilibrium at each output time.
Closed form (README.md): the contact between sphere j and j + 1 (j = 0 the
floor) carries (N - j) m g f(t), its penetration (N - j) m g f(t) / k; the
Hertz contact carries m g f(t), its penetration (m g f(t) / K)^(1/1.5).

A second deck (case_active.rad): one sphere hung from a spring above the
floor with a gap, under a gravity that rises to g at t_end / 2 and falls
back to 0: it meets the floor and leaves it again (the unilateral active
set). It sinks by d = W / k_s while d <= gap, else d = (W + k gap) /
(k_s + k), its contact carrying k (d - gap).

The deck forces Method 3 and keeps it in every mode of scripts/check.sh:
the checks are of the static analysis itself (closed forms to 1e-9, which
no dynamic run of this deck reaches: the gravity ramp excites the column's
oscillations). In the 'default' mode the /SOLVER card is kept (it holds the
method); in the 'ida' mode the run is given --method static instead of
--method ida. The check names carry the mode's prefix as usual.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from column import FLOOR, G, K, KH, M, MH, N, R, RH, XH, column_cards  # noqa: E402,F401
from deck import Deck  # noqa: E402

T_END, DT_OUT = 1.0, 0.1
TOL = 1e-9
MS, RS, GAP, KS = 1.0, 0.05, 1.0e-3, 1.0e3   # the hung sphere: mass, radius, gap, spring [N/m]


def deck():
    d = Deck("static column of 5 spheres and a Hertz sphere under ramped gravity")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    d.funct(2, [0.0, T_END], [0.0, 1.0], title="gravity ramp f(t) = t / t_end")
    column_cards(d, N, R, M, MH, RH, KH, XH, FLOOR, lambda d: d.grav_fct(1, "Z", -G, 2))
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def deck_active():
    d = Deck("static active set: a sphere hung from a spring meets the floor and leaves it")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    d.funct(2, [0.0, 0.5 * T_END, T_END], [0.0, 1.0, 0.0], title="gravity up and down")
    d.nodes([(1, 0.0, 0.0, RS + GAP)])
    d.rbody(1, 1, MS, [0.4 * MS * RS * RS] * 3, grnod=1, title="hung sphere")
    d.sphere(1, 1, (0.0, 0.0, RS + GAP), RS, title="hung sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1], title="hung sphere")
    # the spring, attached at the centre, holds no rotation nor sideways: held
    d.bcs(1, 1, "110 111", title="vertical translation only")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, title="hung sphere - floor")
    d.spring(2, 1, (0.0, 0.0, RS + GAP), 0, (0.0, 0.0, RS + GAP + 0.5), iform=1, a=KS, title="hanger")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


NP, VP = 3, 1.0e-3                      # case_press: spheres in the pressed column, the press's speed [m/s]


def deck_press():
    """A press: NP spheres in a column on the floor, no gravity, the top
    one's z imposed at -VP (/IMPVEL Z, a constant velocity: the held
    displacement -VP t)."""
    d = Deck("static press: the top sphere of a column driven down by an imposed velocity")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    d.funct(2, [0.0, T_END], [-1.0, -1.0], title="constant velocity, down")
    z = [R + 2.0 * R * i for i in range(NP)]  # exact binary numbers: every contact starts at zero gap
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(NP)])
    for i in range(NP):
        d.rbody(i + 1, i + 1, M, [0.4 * M * R * R] * 3, grnod=i + 1, title=f"sphere {i + 1} (from the bottom)")
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
        d.grnod(i + 1, [i + 1], title=f"sphere {i + 1}")
    d.plane(FLOOR, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(NP + 1, list(range(1, NP + 1)), title="all spheres")
    d.bcs(1, NP + 1, "110 111", title="held to the vertical, not turning")
    d.impvel(1, 2, "Z", NP, ascale=1.0, fscale=VP, title="the press: the top sphere driven down")
    d.type6(1, 1, FLOOR, 1, title="floor - sphere 1")
    for i in range(1, NP):
        d.type6(i + 1, i, i + 1, 1, title=f"sphere {i} - sphere {i + 1}")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def main():
    rcval.METHOD = "static" if rcval.METHOD else ""   # the 'ida' mode: static all the same (docstring)
    r = rcval.Result(rcval.run_case(keep_solver=True))
    f = r.t / T_END
    ids = list(r.inter_id)
    rcval.check("static_column.output_times", len(r.t) == 11 and np.allclose(r.t, np.arange(11) * DT_OUT, atol=1e-12),
                f"{len(r.t)} records at {', '.join(f'{x:g}' for x in r.t)} s (expected 0, 0.1, ..., 1)")
    rcval.check("static_column.solver", "static" in str(r.attrs.get("solver", "")) and "KINSOL" in str(r.attrs.get("solver", "")),
                f"solver attribute: {r.attrs.get('solver', '?')!r}")
    vmax = float(np.abs(r.vel).max())
    rcval.check("static_column.velocities_zero", vmax == 0.0, f"max |v| over the records {vmax:g} m/s")
    ef, ep = 0.0, 0.0
    worst = ""
    for j in range(N):
        c = ids.index(j + 1)          # /INTER/TYPE6/j+1: below sphere j + 1
        F = (N - j) * M * G * f
        P = F / K
        fn, pen = r.fn[:, c], r.pen[:, c]
        for k in range(len(r.t)):
            if F[k] == 0.0:
                e1 = abs(fn[k]) / (M * G)
                e2 = abs(pen[k]) / (M * G / K)
            else:
                e1 = abs(fn[k] - F[k]) / F[k]
                e2 = abs(pen[k] - P[k]) / P[k]
            if max(e1, e2) > max(ef, ep):
                worst = f"contact {j + 1} at t = {r.t[k]:g} s"
            ef, ep = max(ef, e1), max(ep, e2)
    rcval.check("static_column.column_forces", ef < TOL,
                f"max rel. error of the contact forces against (N - j) m g f(t): {ef:.2e} (< {TOL:g}; worst {worst}); "
                f"floor at t_end {r.fn[-1, ids.index(1)]:.12g} N (5 m g = {N * M * G:.12g} N)")
    rcval.check("static_column.column_penetrations", ep < TOL,
                f"max rel. error of the penetrations against (N - j) m g f(t) / k: {ep:.2e} (< {TOL:g}); floor at "
                f"t_end {r.pen[-1, ids.index(1)]:.12e} m (5 m g / k = {N * M * G / K:.12e} m)")
    c = ids.index(N + 1)
    F = MH * G * f
    P = (F / KH) ** (1.0 / 1.5)
    pos = F > 0
    eF = np.abs(r.fn[pos, c] - F[pos]) / F[pos]
    eP = np.abs(r.pen[pos, c] - P[pos]) / P[pos]
    e0 = max(abs(r.fn[~pos, c]).max() / (MH * G), abs(r.pen[~pos, c]).max() / P[-1]) if (~pos).any() else 0.0
    rcval.check("static_column.hertz", max(eF.max(), eP.max(), e0) < TOL,
                f"Hertz sphere: max rel. error of F against m g f(t) {eF.max():.2e}, of P against (F/K)^(1/1.5) "
                f"{eP.max():.2e}, at f = 0 {e0:.2e} (< {TOL:g}); P at t_end {r.pen[-1, c]:.12e} m "
                f"(closed form {P[-1]:.12e} m)")
    # the hung sphere: the active set (closes on the way up, opens on the way down)
    r = rcval.Result(rcval.run_case("case_active.rad", keep_solver=True))
    fs = np.where(r.t <= 0.5 * T_END, r.t / (0.5 * T_END), (T_END - r.t) / (0.5 * T_END))
    W = MS * G * fs
    dfree = W / KS
    dd = np.where(dfree <= GAP, dfree, (W + K * GAP) / (KS + K))
    Fc = np.where(dfree <= GAP, 0.0, K * (dd - GAP))
    eF = float(np.abs(r.fn[:, 0] - Fc).max() / (MS * G))
    ez = float(np.abs((RS + GAP - r.pos[:, 0, 2]) - dd).max() / GAP)
    modes = [int(x) for x in r.mode[:, 0]]
    want = [2 if x > 0 else 1 for x in Fc]
    evs = [(round(float(t), 12), k) for t, k in zip(r.ev_t, r.ev_kind)]
    rcval.check("static_column.active_set", modes == want and [k for _, k in evs] == ["contact_close", "contact_open"],
                f"hung sphere's contact modes {modes} (expected {want}; 1 open, 2 closed); events {evs}")
    rcval.check("static_column.active_set_forces", max(eF, ez) < TOL,
                f"hung sphere: max |F - F_ref| / (m g) {eF:.2e}, max |d - d_ref| / gap {ez:.2e} (< {TOL:g})")
    # the press: an imposed translation held at the integral of its velocity
    r = rcval.Result(rcval.run_case("case_press.rad", keep_solver=True))
    ids = list(r.inter_id)
    Fp = K * VP * r.t / NP                      # the springs in series share the press's travel
    eF = max(float(np.abs(r.fn[:, ids.index(j + 1)] - Fp).max()) for j in range(NP)) / (K * VP / NP)
    ez = float(np.abs(r.pos[:, NP - 1, 2] - (R + 2.0 * R * (NP - 1) - VP * r.t)).max()) / VP
    ew = 0.5 * K * (VP * r.t) ** 2 / NP        # the work the press puts in = the energy the contacts store
    eI = float(np.abs(-r.energy["energy_imposed"] - ew).max()) / ew[-1]
    eS = float(np.abs(r.energy["energy_contact_stored"] - ew).max()) / ew[-1]
    rcval.check("static_column.press", max(eF, ez) < TOL and max(eI, eS) < 1e-6,
                f"{len(r.t)} records: each contact's force against k v t / {NP} max error {eF:.1e} of k v / {NP}, the "
                f"top sphere's height against z_0 - v t {ez:.1e} of v (< {TOL:g}); the work supplied "
                f"(-energy_imposed) and the energy stored against k (v t)^2 / (2 {NP}) {eI:.1e}, {eS:.1e} of its "
                f"end value (< 1e-6: the trapezoid over each load step, exact for a linear contact)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_active.rad": deck_active(), "case_press.rad": deck_press()})
