"""Iform 1 with a nonlinear load curve and a nonlinear unload curve.

A sphere hits a fixed plane, no gravity. Reference (README.md): the path of
the law (load curve to the turning point, Stiff line down to the unload curve,
unload curve to zero) computed independently on the piecewise-linear
interpolant of the same table points (np.interp, scipy quad and brentq).
Checks the turning point, the point where the Stiff line meets the unload
curve, the dissipated energy (area between the loading and unloading paths),
the rebound speed and the force-penetration path of the records.
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

M, R, V0, GAP0 = 1.0, 0.05, 1.0, 0.002
# curves in scaled units: P = Ascalex x, F_L = Fscaleld f_ld(x), F_U = Fscaleul f_ul(x)
ASCALEX, FSCALELD, FSCALEUL = 1e-3, 100.0, 50.0
A, B = 5.0e4, 2.0e7          # F_L = A P + B P^2                  [N]
C, PP = 3.0e7, 1.0e-3        # F_U = C (P - PP)^2 for P > PP, else 0 [N]
STIFF = 5.0e5                # [N/m], above the slopes of both curves (2.5e5, 2.3e5)
TOL = 1e-5


def tables():
    """Table points of f_ld and f_ul (abscissa x = P / Ascalex)."""
    pl = np.linspace(0.0, 5e-3, 26)
    pu = np.concatenate([[0.0], np.linspace(PP, 5e-3, 21)])
    fl = (A * pl + B * pl**2) / FSCALELD
    fu = np.where(pu > PP, C * (pu - PP) ** 2, 0.0) / FSCALEUL
    return pl / ASCALEX, fl, pu / ASCALEX, fu


XL, YL, XU, YU = tables()


def f_load(p):
    return FSCALELD * np.interp(p / ASCALEX, XL, YL)


def f_unload(p):
    return FSCALEUL * np.interp(p / ASCALEX, XU, YU)


def integral(f, xs, a, b):
    """quad of a piecewise-linear curve, breakpoints (scaled by Ascalex) passed explicitly."""
    return laws.curve_integral(f, xs, a, b, scale=ASCALEX)


def reference():
    e0 = 0.5 * M * V0**2
    # turning point: the work of the load curve equals the impact energy
    pmax = brentq(lambda p: integral(f_load, XL, 0.0, p) - e0, 1e-6, ASCALEX * XL[-1], xtol=1e-16, rtol=1e-15)
    fmax = f_load(pmax)
    # the Stiff line F = Fmax - Stiff (Pmax - P) meets the unload curve at P*
    line = lambda p: fmax - STIFF * (pmax - p)
    pstar = brentq(lambda p: line(p) - f_unload(p), pmax - fmax / STIFF, pmax, xtol=1e-16, rtol=1e-15)
    fstar = f_unload(pstar)
    # energy given back: trapezoid under the Stiff segment + area under the unload curve
    back = 0.5 * (fmax + fstar) * (pmax - pstar) + integral(f_unload, XU, 0.0, pstar)
    area = integral(f_load, XL, 0.0, pmax) - back
    # where the unload curve reaches zero (the contact releases there)
    pzero = PP
    return dict(pmax=pmax, fmax=fmax, pstar=pstar, fstar=fstar, ediss=area, vout=math.sqrt(2 * back / M),
                pzero=pzero, line=line)


def deck():
    d = Deck("Iform 1, nonlinear load and unload curves")
    d.funct(1, XL, YL, title="load curve (A P + B P^2) / Fscaleld, P = Ascalex x")
    d.funct(2, XU, YU, title="unload curve C (P - PP)^2 / Fscaleul")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, iform=1, stiff=STIFF, fct_ul=2, ascalex=ASCALEX, fscaleld=FSCALELD,
            fscaleul=FSCALEUL, title="elasto-plastic, Stiff 5e5 N/m")
    d.run(0.02, 2e-4)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    ref = reference()
    r = rcval.Result(rcval.run_case())
    ev = {k: r.events(k) for k in ("contact_close", "hyst_unloading", "hyst_unload_curve", "contact_open",
                                   "contact_separate")}
    ok = all(len(v) == 1 for v in ev.values()) and len(r.ev_t) == 5
    rcval.check("t6_unload_curve.events", ok,
                "events " + ", ".join(f"{k} {t:.9e}" for t, k in zip(r.ev_t, r.ev_kind))
                + " (expected one each of contact_close, hyst_unloading, hyst_unload_curve, contact_open, contact_separate)")
    if not ok:
        rcval.finish()

    i = r.state_at(ev["hyst_unloading"][0])
    pmax, fmax = r.pen[i, 0], r.fn[i, 0]
    e = max(rcval.rel(pmax, ref["pmax"]), rcval.rel(fmax, ref["fmax"]))
    rcval.check("t6_unload_curve.turning_point", e < TOL,
                f"hyst_unloading at P = {pmax:.10e} m, F = {fmax:.8f} N; reference {ref['pmax']:.10e} m, "
                f"{ref['fmax']:.8f} N; max rel. error {e:.2e} (< {TOL:g})")

    j = r.state_at(ev["hyst_unload_curve"][0])
    ps, fs = r.pen[j, 0], r.fn[j, 0]
    e = max(rcval.rel(ps, ref["pstar"]), rcval.rel(fs, ref["fstar"]))
    rcval.check("t6_unload_curve.stiff_meets_unload", e < TOL,
                f"hyst_unload_curve at P* = {ps:.10e} m, F* = {fs:.8f} N; reference {ref['pstar']:.10e} m, "
                f"{ref['fstar']:.8f} N; max rel. error {e:.2e} (< {TOL:g})")

    k = r.state_at(ev["contact_open"][0])
    e = rcval.rel(r.pen[k, 0], ref["pzero"])
    rcval.check("t6_unload_curve.release_point", e < TOL,
                f"contact_open (unload curve reaches zero) at P = {r.pen[k, 0]:.10e} m; unload curve zero at "
                f"{ref['pzero']:.10e} m; rel. error {e:.2e} (< {TOL:g})")

    eh = r.energy["energy_hysteresis"][-1]
    v_end = r.vel[-1, 0, 2]
    eloss = 0.5 * M * (V0**2 - v_end**2)
    e = max(rcval.rel(eh, ref["ediss"]), rcval.rel(eloss, ref["ediss"]))
    rcval.check("t6_unload_curve.dissipated_energy", e < TOL,
                f"energy_hysteresis after separation {eh:.10f} J, kinetic energy lost {eloss:.10f} J; "
                f"area between the paths (quadrature) {ref['ediss']:.10f} J; max rel. error {e:.2e} (< {TOL:g})")

    e = rcval.rel(v_end, ref["vout"])
    rcval.check("t6_unload_curve.rebound_speed", e < TOL,
                f"v_out = {v_end:.10f} m/s, sqrt(2 W_unload / m) = {ref['vout']:.10f} m/s; rel. error {e:.2e} (< {TOL:g})")

    # every record in contact on its piece of the path (reference curves, measured events)
    t_turn, t_meet, t_open = ev["hyst_unloading"][0], ev["hyst_unload_curve"][0], ev["contact_open"][0]
    t0, t_sep = ev["contact_close"][0], ev["contact_separate"][0]
    dev, n = 0.0, [0, 0, 0, 0]
    for q in range(len(r.t)):
        t, p, f = r.t[q], r.pen[q, 0], r.fn[q, 0]
        if t < t0 or t > t_sep:
            continue
        if t < t_turn or (t == t_turn and q < i):
            fr, s = f_load(p), 0
        elif t < t_meet or (t == t_meet and q < j):
            fr, s = ref["line"](p), 1
        elif t < t_open or (t == t_open and q < k):
            fr, s = f_unload(p), 2
        else:
            fr, s = 0.0, 3
        n[s] += 1
        dev = max(dev, abs(f - fr) / ref["fmax"])
    rcval.check("t6_unload_curve.force_path", dev < TOL and min(n) > 3,
                f"records on the load curve {n[0]}, the Stiff line {n[1]}, the unload curve {n[2]}, at zero force {n[3]}; "
                f"max |F - F_ref(P)| / Fmax = {dev:.2e} (< {TOL:g})")

    rcval.check_ledger("t6_unload_curve.energy_ledger", r, TOL)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
