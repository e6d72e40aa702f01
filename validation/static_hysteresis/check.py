"""Static analysis (/SOLVER Method 3) of TYPE6 hysteresis (Iform 1 and 2):
a load-unload-reload cycle traversed quasi-statically.

A sphere (m = 1 kg, R = 0.05 m) on the fixed plane z = 0, held to the
vertical by /BCS, TYPE6 with the linear load curve F_L(P) = k P (k = 1e5
N/m) and the unloading line Stiff = k_s = 1e6 N/m; gravity g = 9.81 m/s^2
times the load factor f(t): 0, 1, 0.25, 0.75, 0.1 at t = 0, 0.3, 0.5, 0.8,
1 s. At every output time the contact carries the weight, F = m g f(t),
and the penetration P follows the hysteresis law of docs/theory.md 3.2:
growing, F = min(F_L(P), F_prev + k_s dP); shrinking, F = max(F_U(P),
F_prev + k_s dP).

case.rad (Iform 2, F_U = 0): the penetration at each load is the closed
form of that law: loading along the load curve P = F / k; unloading and
reloading below it along the Stiff line, P = P_prev + (F - F_prev) / k_s,
back to the load curve where the line meets it. At the end (f = 0.1)
P = m g / k - 0.9 m g / k_s, where an elastic contact (Iform 0) would give
0.1 m g / k: the residual penetration of the plastic cycle.
case_box.rad: Iform 2 on the corners of a box lying flat (a contact of
several points, its law at the deepest corner's penetration), held against
sliding and turning: the same penetrations and dissipation as case.rad.
case_iform1.rad (Iform 1 with the unload curve F_U(P) = k_u (P - c)+,
k_u = 8e4 N/m, c = 2e-5 m, below the load curve): unloading runs down the Stiff line until it
meets F_U, then along F_U (P = c + F / k_u); reloading runs up the Stiff
line until it meets F_L: all three branches.

The reference is the law itself, applied from output time to output time
(each interval is monotone in the load: the reversals are at output
times), not ricochet's output. The energies: the ledger's sum stays at
zero along the path, and for Iform 2 the dissipation is the triangle
between the load curve and the Stiff line up to the peak force F_m = m g,
F_m^2 / 2 (1/k - 1/k_s).
"""
import os
import sys

import netCDF4
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, G = 1.0, 0.05, 9.81
K, KS = 1.0e5, 1.0e6             # load curve slope, Stiff [N/m]
KU, CU = 8.0e4, 2.0e-5            # Iform 1: unload curve slope [N/m] (below k), its zero [m]
T_END, DT_OUT = 1.0, 0.05
LOAD = ([0.0, 0.3, 0.5, 0.8, 1.0], [0.0, 1.0, 0.25, 0.75, 0.1])
TOL = 1e-8
HB = 0.05                        # the box's half-height [m]


def deck(iform):
    d = Deck(f"static hysteresis: a sphere on a floor, TYPE6 Iform {iform}, load-unload-reload")
    d.funct(1, [0.0, 1.0], [0.0, K], title="load curve F_L = k P, k = 1e5 N/m")
    if iform == 1:
        d.funct(3, [0.0, CU, 1.0], [0.0, 0.0, KU * (1.0 - CU)], title="unload curve F_U = k_u (P - c)+")
    d.funct(2, *LOAD, title="load factor f(t)")
    add_sphere_over_plane(d, M, R, R, title="sphere")
    # frictionless: nothing holds the sphere sideways; held to the vertical
    d.bcs(1, 1, "110 000", title="held to the vertical")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, iform=iform, stiff=KS, fct_ul=3 if iform == 1 else 0, title="sphere - floor")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def deck_box():
    """Iform 2 on a box's corners (a contact of several points): the box
    (m = 1 kg, half-sizes 0.1 x 0.08 x 0.05 m) lies flat on the floor, held
    by /BCS against sliding and turning (frictionless), its four bottom
    corners at one depth: the law at the deepest corner's penetration is the
    sphere's."""
    d = Deck("static hysteresis: a box on a floor, TYPE6 Iform 2 on its corners, load-unload-reload")
    d.funct(1, [0.0, 1.0], [0.0, K], title="load curve F_L = k P, k = 1e5 N/m")
    d.funct(2, *LOAD, title="load factor f(t)")
    d.nodes([(1, 0.0, 0.0, HB)])
    d.rbody(1, 1, M, [0.004, 0.005, 0.006], grnod=1, title="box")
    d.box(1, 1, (0.0, 0.0, HB), (0.1, 0.08, HB), title="box")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1], title="box")
    d.bcs(1, 1, "110 111", title="held sideways and against turning")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, iform=2, stiff=KS, title="box - floor")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def law_path(F, iform):
    """The penetrations of the hysteresis law for the forces F (one per
    output time, each interval monotone): (P, branch) per record."""
    def FL(P):
        return K * P

    def FU(P):
        return KU * max(P - CU, 0.0) if iform == 1 else 0.0

    F0, P0, out = 0.0, 0.0, []
    for F1 in F:
        Pel = P0 + (F1 - F0) / KS
        if F1 >= F0:
            P, br = (Pel, "stiff") if F1 <= FL(Pel) else (F1 / K, "load")
        else:
            P, br = (Pel, "stiff") if F1 >= FU(Pel) else (CU + F1 / KU, "unload")
        out.append((P, br))
        F0, P0 = F1, P
    return out


def main():
    rcval.METHOD = "static" if rcval.METHOD else ""
    for name, iform, tag in (("case.rad", 2, "iform2"), ("case_iform1.rad", 1, "iform1"), ("case_box.rad", 2, "box")):
        r = rcval.Result(rcval.run_case(name, keep_solver=True))
        f = np.interp(r.t, *LOAD)
        F = M * G * f
        ref = law_path(F, iform)
        P = r.pen[:, 0]
        eP = max(abs(float(P[k]) - ref[k][0]) for k in range(len(r.t))) / (M * G / K)
        eF = float(np.abs(r.fn[:, 0] - F).max()) / (M * G)
        branches = "".join(q[1][0] for q in ref)
        rcval.check(f"static_hysteresis.{tag}.penetration", len(r.t) == 21 and eP < TOL,
                    f"{len(r.t)} records; max |P - P_law| / (m g / k) {eP:.2e} (< {TOL:g}); branches along the path "
                    f"{branches} (l load curve, s Stiff line, u unload curve)")
        rcval.check(f"static_hysteresis.{tag}.force", eF < TOL,
                    f"max |F_n - m g f| / (m g) {eF:.2e} (< {TOL:g})")
        # the energies of the path: the ledger's sum stays at its start, the
        # hysteresis (the law's work less what it stores) never decreases
        with netCDF4.Dataset(r.path) as nc:
            tot = np.array(nc["energy_total"][:])
            hyst = np.array(nc["energy_hysteresis"][:])
        drop = float((np.maximum.accumulate(hyst) - hyst).max())
        etot = float(np.abs(tot).max())
        # Iform 2: everything after the peak lies on one Stiff line, so the
        # dissipation is the triangle between the load curve and that line
        # up to the peak force F_m = m g: F_m^2 / 2 (1/k - 1/k_s)
        Fm = M * G
        ref = Fm * Fm / 2.0 * (1.0 / K - 1.0 / KS)
        eh = abs(float(hyst[-1]) - ref) / ref
        # the work is summed by the trapezoidal rule over each load substep:
        # exact on the law's straight stretches (Iform 2 here), off by the
        # kink where the Stiff line meets a curve inside a substep (Iform 1
        # meets both): there the dissipation may dip by that much
        ok = etot < 1e-9 * Fm * Fm / K and float(hyst.min()) >= -1e-12 * ref
        ok = ok and (drop <= 1e-12 * ref and eh < 1e-9 if iform == 2 else drop <= 0.01 * float(hyst[-1]))
        rcval.check(f"static_hysteresis.{tag}.energies", ok,
                    f"max |energy_total| {etot:.2e} J (< 1e-9 m^2 g^2 / k); energy_hysteresis's largest drop "
                    f"{drop:.2e} J ({'none beyond rounding' if iform == 2 else '< 1 % of its end: a kink inside a substep'}),"
                    f" ends at {float(hyst[-1]):.9e} J"
                    + (f", closed form F_m^2 / 2 (1/k - 1/k_s) = {ref:.9e} J, rel. error {eh:.2e} (< 1e-9)"
                       if iform == 2 else ""))
        if tag == "iform2":
            Pend = M * G / K - 0.9 * M * G / KS
            e = abs(float(P[-1]) - Pend) / Pend
            rcval.check("static_hysteresis.iform2.residual", e < TOL and float(P[-1]) > 5.0 * 0.1 * M * G / K,
                        f"P at f = 0.1 after the cycle {float(P[-1]):.9e} m against m g / k - 0.9 m g / k_s = "
                        f"{Pend:.9e} m, rel. error {e:.2e} (< {TOL:g}); elastic would give {0.1 * M * G / K:.3e} m")
        elif tag == "iform1":
            seen = set(branches)
            rcval.check("static_hysteresis.iform1.branches", seen == {"l", "s", "u"},
                        f"the path visits the load curve, the Stiff line and the unload curve: {sorted(seen)}")
    rcval.finish()


def cases():
    return {"case.rad": deck(2), "case_iform1.rad": deck(1), "case_box.rad": deck_box()}


if __name__ == "__main__":
    rcval.entry(main, cases)
