"""The impact table against the closed form of the damped linear contact.

A sphere (m = 1 kg) hits a fixed plane at v0 = 1 m/s without gravity
through a TYPE6 contact with a linear load curve k = 1e6 N/m and Visc
c = 2 zeta sqrt(k m), zeta = 0.05, 0.2, 0.45, 0.7, 1.5. The output interval
(1 ms) is a third of the contact time, so the records cannot give the peaks:
the impact table must (it samples the integrator's steps).

Reference (README.md): while the contact is closed the penetration obeys
x'' + 2 zeta w x' + w^2 x = 0, x(0) = 0, x'(0) = v0, w = sqrt(k/m), in closed
form (under-, critically and overdamped); the force is F = k x + c x',
clipped at zero. Maximum penetration: the root of x' = 0; peak force: the
root of F' = k x' + c x'' = 0 where F' changes sign from + to -, or
F(0) = c v0 when F' < 0 from the start (c^2 > k m, zeta > 1/2). The roots
are found with brentq on the closed-form derivatives.
"""
import math
import os
import sys

from netCDF4 import Dataset
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, V0, GAP0 = 1.0, 0.05, 1.0e6, 1.0, 0.002
ZETAS = (0.05, 0.2, 0.45, 0.7, 1.5)
TOL = 1e-6


def deck(zeta):
    c = 2.0 * zeta * math.sqrt(K * M)
    d = Deck(f"impact table: linear contact, zeta = {zeta}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, visc=c, title=f"zeta = {zeta}")
    d.run(0.01, 0.001)
    return d


def solution(zeta):
    """x(t), x'(t), x''(t) of the closed contact (t from the closing)."""
    w = math.sqrt(K / M)
    if zeta < 1.0:
        wd = w * math.sqrt(1.0 - zeta * zeta)
        a = -zeta * w

        def x(t):
            return V0 / wd * math.exp(a * t) * math.sin(wd * t)

        def xd(t):
            return V0 / wd * math.exp(a * t) * (a * math.sin(wd * t) + wd * math.cos(wd * t))
    else:
        s = math.sqrt(zeta * zeta - 1.0)
        r1, r2 = w * (-zeta + s), w * (-zeta - s)

        def x(t):
            return V0 / (r1 - r2) * (math.exp(r1 * t) - math.exp(r2 * t))

        def xd(t):
            return V0 / (r1 - r2) * (r1 * math.exp(r1 * t) - r2 * math.exp(r2 * t))

    def xdd(t):
        return -2.0 * zeta * w * xd(t) - w * w * x(t)
    return x, xd, xdd


def reference(zeta):
    w = math.sqrt(K / M)
    c = 2.0 * zeta * math.sqrt(K * M)
    x, xd, xdd = solution(zeta)
    # x' > 0 at 0 and turns negative before the (undamped) half period for
    # zeta < 1; overdamped: within a few time constants
    hi = math.pi / w
    while xd(hi) > 0:
        hi *= 2.0
    tp = brentq(xd, 0.0, hi, xtol=1e-16, rtol=1e-15)
    pmax = x(tp)

    def fd(t):
        return K * xd(t) + c * xdd(t)
    if fd(0.0) <= 0.0:
        tf, fmax = 0.0, c * V0
    else:
        tf = brentq(fd, 0.0, tp, xtol=1e-16, rtol=1e-15)
        fmax = K * x(tf) + c * xd(tf)
    return pmax, tp, fmax, tf


def main():
    rows, worst = [], 0.0
    for zeta in ZETAS:
        out = rcval.run(deck(zeta))
        with Dataset(out) as nc:
            n = len(nc.dimensions["impact"])
            tc = float(nc["impact_close_time"][0])
            pm = float(nc["impact_max_penetration"][0])
            tpm = float(nc["impact_max_penetration_time"][0]) - tc
            fm = float(nc["impact_peak_force"][0])
            r = rcval.Result(out)
        pref, tpref, fref, tfref = reference(zeta)
        ep, ef = rcval.rel(pm, pref), rcval.rel(fm, fref)
        # the records never come close: the peaks are the table's own
        rec_f = float(max(r.fn[:, 0]))
        worst = max(worst, ep, ef)
        rows.append(f"zeta {zeta}: P_max {pm:.9e} m (exact {pref:.9e}, at {tpm:.3e} s vs {tpref:.3e} s), "
                    f"F_max {fm:.9e} N (exact {fref:.9e}; largest record {rec_f:.4e}); errors {ep:.1e}, {ef:.1e}"
                    + ("" if n == 1 else f"; {n} impacts (expected 1)"))
        if n != 1:
            worst = math.inf
    rcval.check("impact_table.peaks", worst < TOL,
                "; ".join(rows) + f"; max rel. error {worst:.2e} (< {TOL:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.2))
