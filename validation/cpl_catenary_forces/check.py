"""Catenary end forces (/COUPLING/CATENARY) against the catenary equations.

Lines from points fixed in space to bodies, in gravity along -y (so the
vertical planes of the lines are not coordinate planes), each in its own
vertical plane turned about y. The end forces at t = 0 (coupling_force_end1,
coupling_force_end2) are compared with (README.md):
  - stiff lines (EA = 1e12 w L): the inextensible catenary through the two
    ends (closed form with one scalar root), within 1e-6 relative;
  - soft and taut lines: an independent scipy solution of the elastic
    catenary equations in (c, u1, u2) (validation/lib/catenary_ref.py),
    within 1e-12 relative.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import catenary_ref  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, LAM = 9.81, 2.0
UP = np.array([0.0, 1.0, 0.0])
# span X, height Y of end 2 over end 1, L_eq, EA / (w L_eq); "stiff" rows use the inextensible reference
LINES = [
    ("stiff", 3.0, 0.4, 5.0, 1e12), ("stiff", 3.0, -1.7, 5.0, 1e12), ("stiff", 1.0, 4.6, 5.0, 1e12),
    ("stiff", 4.9, 0.5, 5.0, 1e12), ("stiff", 2.0, -4.5, 5.0, 1e12), ("stiff", 0.4, 0.1, 5.0, 1e12),
    ("soft", 3.0, 0.4, 5.0, 0.8), ("soft", 6.0, -2.0, 5.0, 3.0), ("soft", 0.3, -0.2, 5.0, 50.0),
    ("soft", 2.5, 1.5, 4.0, 20.0), ("taut", 5.2, 0.3, 5.0, 2e3), ("taut", 3.0, 4.2, 5.0, 2e3),
]


def r12(v):
    """Values as the deck writes them (12 significant digits)."""
    return np.array([float(f"{x:.12g}") for x in np.atleast_1d(v)])


def geometry(k):
    """End points of line k as written in the deck (end 1 fixed, end 2 on body
    k + 1, vertical plane turned about the up axis), and the span (X, Y) and
    horizontal direction they give."""
    _, X, Y, L, _ = LINES[k]
    phi = 0.37 + 0.61 * k
    p1 = r12([10.0 * k, 0.5 * k, -3.0])
    p2 = r12(p1 + X * np.array([math.cos(phi), 0.0, math.sin(phi)]) + Y * UP)
    d = p2 - p1
    h = d - np.dot(d, UP) * UP
    return p1, p2, np.linalg.norm(h), np.dot(d, UP), h / np.linalg.norm(h)


def stiffness(k):
    """D [N/m] as written: EA = ea w L_eq = D L_eq."""
    return r12(LINES[k][4] * LAM * G)[0]


def deck():
    d = Deck("catenary end forces")
    d.nodes([(k + 1, *geometry(k)[1]) for k in range(len(LINES))])
    for k, (_, X, Y, L, ea) in enumerate(LINES):
        p1, p2 = geometry(k)[:2]
        d.rbody(k + 1, k + 1, 1.0, [0.1, 0.1, 0.1], title=f"end body {k + 1}")
        d.catenary(k + 1, 0, tuple(p1), k + 1, tuple(p2), LAM, L, stiffness(k), title=f"line {k + 1}")
    d.grav(1, "Y", -G)
    d.run(1e-4, 1e-4)
    return d


def main():
    from netCDF4 import Dataset
    with Dataset(rcval.run_case()) as nc:
        f1 = np.array(nc["coupling_force_end1"][0])
        f2 = np.array(nc["coupling_force_end2"][0])
        low = np.array(nc["coupling_lowest"][0])
    w = LAM * G
    worst = {"stiff": 0.0, "soft": 0.0, "taut": 0.0}
    low_err = 0.0
    for k, (kind, _, _, L, _) in enumerate(LINES):
        _, _, X, Y, ex = geometry(k)
        if kind == "stiff":
            H, V1, V2 = catenary_ref.inextensible(X, Y, L, w)
        else:
            H, V1, V2 = catenary_ref.elastic(X, Y, L, w, stiffness(k) * L)
        ref1, ref2 = H * ex + V1 * UP, -H * ex - V2 * UP
        p1 = geometry(k)[0]
        ea_k = stiffness(k) * L
        low_err = max(low_err, abs(low[k] - catenary_ref.lowest(H, V1, np.dot(p1, UP), L, w, ea_k)) / L)
        scale = max(np.linalg.norm(ref1), np.linalg.norm(ref2))
        err = max(np.linalg.norm(f1[k] - ref1), np.linalg.norm(f2[k] - ref2)) / scale
        worst[kind] = max(worst[kind], err)
    rcval.check("cpl_catenary_forces.stiff", worst["stiff"] < 1e-6,
                f"6 stiff lines (EA = 1e12 w L) against the inextensible catenary: max rel. error "
                f"{worst['stiff']:.2e} (< 1e-6)")
    rcval.check("cpl_catenary_forces.soft", worst["soft"] < 1e-12,
                f"4 soft lines (EA = 0.8 .. 50 w L) against scipy's elastic catenary: max rel. error "
                f"{worst['soft']:.2e} (< 1e-12)")
    rcval.check("cpl_catenary_forces.taut", worst["taut"] < 1e-12,
                f"2 taut lines (chord > L_eq) against scipy's elastic catenary: max rel. error "
                f"{worst['taut']:.2e} (< 1e-12)")
    rcval.check("cpl_catenary_forces.lowest", low_err < 1e-9,
                f"height of the lowest point of each line (coupling_lowest) against a numerical "
                f"minimisation along the line: max error {low_err:.1e} L_eq (< 1e-9)")
    bal = max(abs(np.dot(f1[k] + f2[k], UP) + w * LINES[k][3]) / (w * LINES[k][3]) for k in range(len(LINES)))
    hor = max(np.linalg.norm(f1[k] + f2[k] - np.dot(f1[k] + f2[k], UP) * UP) for k in range(len(LINES)))
    rcval.check("cpl_catenary_forces.balance", bal < 1e-12 and hor < 1e-9,
                f"end forces carry the line weight: max |f1 + f2 + w L e_up| / (w L) = {bal:.1e}, "
                f"horizontal resultant {hor:.1e} N")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
