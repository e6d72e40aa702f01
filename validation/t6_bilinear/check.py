"""Bilinear hysteresis (TYPE6 Iform 2): a sphere hits a fixed plane, no gravity.

Reference: the Walton-Braun bilinear spring (README.md). Loading along the
linear load curve k1, unloading along Stiff = k2 > k1 down to zero force, then
force-free until the bodies separate. Checks the turning point, the rebound
speed, the dissipated energy (loop area), the force-penetration path and the
event times against the closed form, with tight solver tolerances.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K1, K2, V0, GAP0 = 1.0, 0.05, 1.0e5, 4.0e5, 1.0, 0.002
TOL = 1e-6


def reference():
    """Closed form of the bilinear impact (times from the first contact)."""
    w1, w2 = math.sqrt(K1 / M), math.sqrt(K2 / M)
    pmax = V0 / w1                      # 1/2 m v0^2 = 1/2 k1 pmax^2
    fmax = K1 * pmax
    vout = V0 * math.sqrt(K1 / K2)      # 1/2 m vout^2 = fmax^2 / (2 k2)
    pres = pmax - fmax / K2             # where the Stiff line reaches zero force
    t_turn = 0.5 * math.pi / w1         # quarter period on the load curve
    t_zero = t_turn + 0.5 * math.pi / w2  # quarter period on the Stiff line
    t_sep = t_zero + pres / vout        # force-free until P = 0
    ediss = 0.5 * M * V0**2 * (1 - K1 / K2)  # loop area
    return dict(pmax=pmax, fmax=fmax, vout=vout, pres=pres, t_turn=t_turn, t_zero=t_zero,
                t_sep=t_sep, ediss=ediss)


def deck():
    d = Deck("bilinear hysteresis (Iform 2)")
    d.funct(1, [0.0, 1.0], [0.0, K1], title="linear load curve k1 = 1e5 N/m")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, iform=2, stiff=K2, title="bilinear, Stiff k2 = 4e5 N/m")
    d.run(0.02, 2e-4)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    ref = reference()
    r = rcval.Result(rcval.run_case())
    t_close = r.events("contact_close")
    t_turn = r.events("hyst_unloading")
    t_zero = r.events("hyst_unload_curve")
    t_open = r.events("contact_open")
    t_sep = r.events("contact_separate")
    ok = len(t_close) == 1 and len(t_turn) == 1 and len(t_zero) == 1 and len(t_open) == 1 and len(t_sep) == 1
    rcval.check("t6_bilinear.events", ok,
                "events " + ", ".join(f"{k} {t:.9e}" for t, k in zip(r.ev_t, r.ev_kind))
                + " (expected one each of contact_close, hyst_unloading, hyst_unload_curve, contact_open, contact_separate)")
    if not ok:
        rcval.finish()
    t0 = t_close[0]

    # turning point: the record written at the reversal event
    i = r.state_at(t_turn[0])
    pmax, fmax = r.pen[i, 0], r.fn[i, 0]
    e = max(rcval.rel(pmax, ref["pmax"]), rcval.rel(fmax, ref["fmax"]))
    rcval.check("t6_bilinear.max_penetration", e < TOL,
                f"Pmax = {pmax:.12e} m, v0 sqrt(m/k1) = {ref['pmax']:.12e} m; F = {fmax:.9f} N, k1 Pmax = {ref['fmax']:.9f} N; "
                f"max rel. error {e:.2e} (< {TOL:g})")

    # rebound speed: at separation and at the end (force-free after the Stiff line reaches zero)
    v_sep = r.vel[r.state_at(t_sep[0]), 0, 2]
    v_end = r.vel[-1, 0, 2]
    e = max(rcval.rel(v_sep, ref["vout"]), rcval.rel(v_end, ref["vout"]))
    rcval.check("t6_bilinear.rebound_speed", e < TOL,
                f"v_out = {v_sep:.12f} m/s at separation, {v_end:.12f} m/s at t = {r.t[-1]:g} s; "
                f"v0 sqrt(k1/k2) = {ref['vout']:.12f} m/s; max rel. error {e:.2e} (< {TOL:g})")

    # dissipated energy: energy_hysteresis after separation = loop area
    eh = r.energy["energy_hysteresis"][-1]
    es = r.energy["energy_contact_stored"][-1]
    eloss = 0.5 * M * (V0**2 - v_end**2)
    e = max(rcval.rel(eh, ref["ediss"]), rcval.rel(eloss, ref["ediss"]))
    rcval.check("t6_bilinear.dissipated_energy", e < TOL and es == 0.0,
                f"energy_hysteresis = {eh:.12f} J, kinetic energy lost = {eloss:.12f} J, loop area "
                f"1/2 m v0^2 (1 - k1/k2) = {ref['ediss']:.12f} J; max rel. error {e:.2e} (< {TOL:g}); "
                f"stored after separation {es:g} J (= 0)")

    # the force-penetration path of every record in contact: load line, Stiff line, zero
    dev = 0.0
    n = [0, 0, 0]
    for k in range(len(r.t)):
        t, p, f = r.t[k], r.pen[k, 0], r.fn[k, 0]
        if t < t0 or t > t_sep[0]:
            continue
        if t < t_turn[0] or (t == t_turn[0] and k < i):
            fr, n[0] = K1 * p, n[0] + 1
        elif t < t_zero[0]:
            fr, n[1] = fmax - K2 * (pmax - p), n[1] + 1
        else:
            fr, n[2] = 0.0, n[2] + 1
        dev = max(dev, abs(f - fr) / ref["fmax"])
    rcval.check("t6_bilinear.force_path", dev < TOL and min(n) > 5,
                f"{n[0]} records on F = k1 P, {n[1]} on F = Fmax - k2 (Pmax - P), {n[2]} at F = 0 with P > 0; "
                f"max |F - F_path| / Fmax = {dev:.2e} (< {TOL:g})")

    # event times from the first contact: quarter periods and the free flight to P = 0
    errs = [abs((t_turn[0] - t0) - ref["t_turn"]), abs((t_zero[0] - t0) - ref["t_zero"]),
            abs((t_open[0] - t0) - ref["t_zero"]), abs((t_sep[0] - t0) - ref["t_sep"])]
    tclose_ref = GAP0 / V0
    errs.append(abs(t0 - tclose_ref))
    rcval.check("t6_bilinear.event_times", max(errs) < 1e-9,
                f"contact_close {t0:.12e} s (gap/v0 {tclose_ref:.12e}); after it: hyst_unloading {t_turn[0] - t0:.12e} s "
                f"(pi/2 sqrt(m/k1) = {ref['t_turn']:.12e}), hyst_unload_curve and contact_open {t_zero[0] - t0:.12e} s "
                f"(+ pi/2 sqrt(m/k2) = {ref['t_zero']:.12e}), contact_separate {t_sep[0] - t0:.12e} s "
                f"(+ P_res/v_out = {ref['t_sep']:.12e}); max |diff| {max(errs):.2e} s (< 1e-9)")

    # energy ledger
    rcval.check_ledger("t6_bilinear.energy_ledger", r, TOL)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
