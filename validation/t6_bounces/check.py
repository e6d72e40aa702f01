"""Repeated impacts: a ball bouncing under gravity on an Iform 1 interface.

Reference (README.md): the exact energy chain of the law (each impact starts
on the load curve from P = 0; turning point, Stiff segment, unload curve and
rebound from energy balances, by quadrature and root finding on the
piecewise-linear interpolant of the same table points), and the nesting of the
force-penetration loops that follows from it. Also the energy ledger.
"""
import math
import os
import sys

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import laws  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, G, H = 1.0, 0.05, 9.81, 0.1
KL, KU, PP, STIFF = 1.0e8, 1.2e8, 2.0e-4, 1.0e7   # F_L = KL P^1.5, F_U = KU (P - PP)^1.5
NB = 5                       # impacts checked (all end with a full separation)
TEND = 0.80                  # before the 6th impact
TOL = 1e-6                   # loop geometry and energy ledger
TOL_CHAIN = 1e-5             # the chain: errors accumulate over the impacts


def tables():
    pl = np.linspace(0.0, 1.5e-3, 31)
    pu = np.concatenate([[0.0], np.linspace(PP, 1.5e-3, 27)])
    return pl, KL * pl**1.5, pu, np.where(pu > PP, KU * np.maximum(pu - PP, 0.0) ** 1.5, 0.0)


XL, YL, XU, YU = tables()


def f_load(p):
    return np.interp(p, XL, YL)


def f_unload(p):
    return np.interp(p, XU, YU)


def impact(vin):
    """One impact at speed vin from P = 0, under gravity (energy balances)."""
    # loading: 1/2 m vin^2 + m g Pmax = integral_0^Pmax F_L
    pmax = brentq(lambda p: laws.curve_integral(f_load, XL, 0.0, p) - M * G * p - 0.5 * M * vin**2, 1e-9, XL[-1],
                  xtol=1e-16, rtol=1e-15)
    fmax = f_load(pmax)
    pstar = brentq(lambda p: fmax - STIFF * (pmax - p) - f_unload(p), pmax - fmax / STIFF, pmax,
                   xtol=1e-16, rtol=1e-15)
    fstar = f_unload(pstar)
    back = 0.5 * (fmax + fstar) * (pmax - pstar) + laws.curve_integral(f_unload, XU, 0.0, pstar)
    diss = laws.curve_integral(f_load, XL, 0.0, pmax) - back
    # force-free from P = PP (F_U = 0) to P = 0: 1/2 m vout^2 = back - m g pmax
    vout = math.sqrt(2.0 * (back - M * G * pmax) / M)
    return dict(vin=vin, pmax=pmax, fmax=fmax, pstar=pstar, fstar=fstar, diss=diss, vout=vout)


def reference():
    out, v = [], math.sqrt(2 * G * H)
    for _ in range(NB):
        out.append(impact(v))
        v = out[-1]["vout"]   # ballistic flight: back at P = 0 with the same speed
    return out


def deck():
    d = Deck("ball bouncing on an Iform 1 interface")
    d.funct(1, XL, YL, title="load curve 1e8 P^1.5")
    d.funct(2, XU, YU, title="unload curve 1.2e8 (P - 2e-4)^1.5")
    z0 = R + H
    add_sphere_over_plane(d, M, R, z0, title="ball 1 kg")
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, iform=1, stiff=STIFF, fct_ul=2, title="elasto-plastic floor, Stiff 1e7 N/m")
    d.run(TEND, 1e-4)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    ref = reference()
    r = rcval.Result(rcval.run_case())
    seq = ["contact_close", "hyst_unloading", "hyst_unload_curve", "contact_open", "contact_separate"]
    ok = r.ev_kind == seq * NB
    rcval.check("t6_bounces.events", ok,
                f"{len(r.ev_kind)} events; expected {NB} x ({', '.join(seq)})"
                + ("" if ok else ": got " + ", ".join(r.ev_kind)))
    if not ok:
        rcval.finish()
    ev = np.array(r.ev_t).reshape(NB, len(seq))
    rec = [[r.state_at(t) for t in row] for row in ev]
    meas = []
    for k in range(NB):
        i_c, i_t, i_m, i_o, i_s = rec[k]
        meas.append(dict(vin=-r.vel[i_c, 0, 2], pmax=r.pen[i_t, 0], fmax=r.fn[i_t, 0], pstar=r.pen[i_m, 0],
                         fstar=r.fn[i_m, 0], vout=r.vel[i_s, 0, 2],
                         diss=r.energy["energy_hysteresis"][i_s] - r.energy["energy_hysteresis"][i_c]))

    # the exact chain
    for key, what in (("pmax", "max penetration"), ("fmax", "peak force"), ("pstar", "P where Stiff meets F_U"),
                      ("fstar", "F there"), ("diss", "energy dissipated"), ("vout", "rebound speed")):
        errs = [rcval.rel(m[key], q[key]) for m, q in zip(meas, ref)]
        rcval.check(f"t6_bounces.chain_{key}", max(errs) < TOL_CHAIN,
                    f"{what} per impact " + ", ".join(f"{m[key]:.9g}" for m in meas)
                    + "; exact chain " + ", ".join(f"{q[key]:.9g}" for q in ref) + f"; max rel. error {max(errs):.2e} (< {TOL_CHAIN:g})")

    # nesting, from the measured loops alone
    dec = lambda key: all(meas[k][key] < meas[k - 1][key] for k in range(1, NB))
    c = [m["pmax"] - m["fmax"] / STIFF for m in meas]
    ok = dec("pmax") and dec("fmax") and dec("pstar") and dec("fstar") and all(c[k] < c[k - 1] for k in range(1, NB))
    rcval.check("t6_bounces.loops_shrink", ok,
                "Pmax [mm] " + ", ".join(f"{1e3 * m['pmax']:.5f}" for m in meas)
                + "; Fmax [N] " + ", ".join(f"{m['fmax']:.3f}" for m in meas)
                + "; Stiff segment end P* [mm] " + ", ".join(f"{1e3 * m['pstar']:.5f}" for m in meas)
                + "; F* [N] " + ", ".join(f"{m['fstar']:.3f}" for m in meas)
                + "; Stiff line at zero force Pmax - Fmax/Stiff [mm] " + ", ".join(f"{1e3 * x:.5f}" for x in c)
                + " (each strictly decreasing)")
    # each measured loop closes on the law: turning point on F_L, segment of slope Stiff ending on F_U
    dev = max(max(abs(m["fmax"] - f_load(m["pmax"])), abs(m["fstar"] - f_unload(m["pstar"])),
                  abs(m["fstar"] - (m["fmax"] - STIFF * (m["pmax"] - m["pstar"])))) for m in meas) / meas[0]["fmax"]
    rcval.check("t6_bounces.loop_corners", dev < TOL,
                f"turning points on F_L, Stiff segments of slope Stiff ending on F_U: max deviation / Fmax_1 = {dev:.2e} (< {TOL:g})")
    # every record of impact k lies inside loop k-1
    worst, nrec = 0.0, 0
    for k in range(1, NB):
        q = meas[k - 1]
        for j in range(rec[k][0], rec[k][4] + 1):
            p, f = r.pen[j, 0], r.fn[j, 0]
            lower = max(f_unload(p), q["fmax"] - STIFF * (q["pmax"] - p), 0.0)
            v = max(f - f_load(p), lower - f, 0.0) / meas[0]["fmax"]
            if p > q["pmax"]:
                v = max(v, 1.0)
            worst, nrec = max(worst, v), nrec + 1
    rcval.check("t6_bounces.loops_nest", worst < TOL and nrec > 50,
                f"{nrec} records of impacts 2..{NB} inside the loop of the previous impact "
                f"(max(F_U, previous Stiff line) <= F <= F_L, P <= previous Pmax): worst excursion / Fmax_1 = {worst:.2e} (< {TOL:g})")

    et = r.energy["energy_total"]
    e0 = M * G * H
    drift = np.max(np.abs(et - et[0])) / e0
    rcval.check("t6_bounces.energy_ledger", drift < TOL,
                f"max |E_total(t) - E_total(0)| = {np.max(np.abs(et - et[0])):.2e} J over {len(et)} records, "
                f"{drift:.2e} of the drop energy m g H = {e0:.4f} J (< {TOL:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
