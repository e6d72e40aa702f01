"""Damping multiplier curves of TYPE6: fct_IDdv (force vs velocity) and
fct_IDdf (multiplier vs normal force), with Fscalev, Ascalev, Ascalef.

A sphere hits a fixed plane, no gravity, Iform 0 with a linear load curve.
Reference (README.md): an independent integration (scipy solve_ivp, DOP853,
rtol 1e-11, event at zero total force) of the 1-D equation
    m p'' = -(F_L(p) + f_df(F_L / Ascalef) (Visc p' + Fscalev f_dv(p' / Ascalev)))
with the curves evaluated by np.interp on the same table points. Compares the
rebound speed and the contact time, for Visc alone (also against the closed
form of validation/spring_dashpot, a check of the reference), Visc + f_dv,
Visc + f_df, and all together (case.rad).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, V0, GAP0 = 1.0, 0.05, 1.0e5, 1.0, 0.002
ZETA = 0.1
VISC = 2.0 * ZETA * math.sqrt(K * M)
FSCALEV, ASCALEV, ASCALEF = 100.0, 0.5, 100.0
TOL = 1e-5

# f_dv(u) = u |u| (quadratic in the velocity), u = v_n / Ascalev on [-4, 4]
XV = np.linspace(-4.0, 4.0, 41)
YV = XV * np.abs(XV)
# f_df(x) = 1 / (1 + x), x = F_L / Ascalef on [0, 6]
XF = np.linspace(0.0, 6.0, 25)
YF = 1.0 / (1.0 + XF)

VARIANTS = {  # name: (use f_dv, use f_df)
    "visc": (False, False),
    "visc_dv": (True, False),
    "visc_df": (False, True),
    "visc_dv_df": (True, True),
}


def f_load(p):
    return K * p


def reference(use_dv, use_df):
    """Contact from p = 0, p' = v0 until the total force falls to zero."""
    rng = {"u": [0.0, 0.0], "x": [0.0, 0.0]}

    def force(p, v):
        fl = f_load(p)
        fdf = np.interp(fl / ASCALEF, XF, YF) if use_df else 1.0
        fdv = FSCALEV * np.interp(v / ASCALEV, XV, YV) if use_dv else 0.0
        rng["u"] = [min(rng["u"][0], v / ASCALEV), max(rng["u"][1], v / ASCALEV)]
        rng["x"] = [min(rng["x"][0], fl / ASCALEF), max(rng["x"][1], fl / ASCALEF)]
        return fl + fdf * (VISC * v + fdv)

    def rhs(t, y):
        return [y[1], -force(y[0], y[1]) / M]

    def release(t, y):
        return force(y[0], y[1])
    release.terminal, release.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 0.1), [0.0, V0], method="DOP853", rtol=1e-11, atol=[1e-15, 1e-12],
                    events=release)
    tc = sol.t_events[0][0]
    vout = -sol.y_events[0][0][1]
    # the curves must be used inside their tables (np.interp does not extend them)
    assert XV[0] < rng["u"][0] and rng["u"][1] < XV[-1] and rng["x"][1] < XF[-1], rng
    return vout / V0, tc


def closed_form():
    """validation/spring_dashpot: restitution and contact time of Visc alone."""
    wn = math.sqrt(K / M)
    wd = wn * math.sqrt(1 - ZETA**2)
    tc = (math.pi - math.atan(2 * ZETA * math.sqrt(1 - ZETA**2) / (1 - 2 * ZETA**2))) / wd
    vout = V0 / wd * math.exp(-ZETA * wn * tc) * (wd * math.cos(wd * tc) - ZETA * wn * math.sin(wd * tc))
    return -vout / V0, tc


def deck(use_dv=True, use_df=True):
    d = Deck("damping curves: Visc" + (" + fct_IDdv" if use_dv else "") + (" + fct_IDdf" if use_df else ""))
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e5 N/m")
    d.funct(2, XV, YV, title="f_dv(u) = u |u|, u = v_n / Ascalev")
    d.funct(3, XF, YF, title="f_df(x) = 1 / (1 + x), x = F / Ascalef")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, visc=VISC, fct_dv=2 if use_dv else 0, fct_df=3 if use_df else 0,
            fscalev=FSCALEV if use_dv else None, ascalev=ASCALEV if use_dv else None,
            ascalef=ASCALEF if use_df else None, title="damped contact")
    d.run(0.02, 5e-4)
    d.solver(rtol=1e-8, atol_pos=1e-11, atol_vel=1e-8, atol_energy=1e-8)
    return d


def measure(path):
    r = rcval.Result(path)
    t1 = r.events("contact_close")[0]
    t2 = r.events("contact_open")[0]
    return r.vel[r.state_at(t2), 0, 2] / V0, t2 - t1


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    e_cf, tc_cf = closed_form()
    refs = {name: reference(*flags) for name, flags in VARIANTS.items()}
    e_v, tc_v = refs["visc"]
    err = max(rcval.rel(e_v, e_cf), rcval.rel(tc_v, tc_cf))
    rcval.check("t6_damping_curves.reference_visc", err < 1e-8,
                f"the quadrature reference with Visc alone: e = {e_v:.10f}, tc = {tc_v:.10e} s; closed form "
                f"(validation/spring_dashpot) e = {e_cf:.10f}, tc = {tc_cf:.10e} s; max rel. diff {err:.1e} (< 1e-8)")
    for name, flags in VARIANTS.items():
        path = os.path.join(here, "case.rad") if flags == (True, True) else None
        e, tc = measure(rcval.run_file(path) if path else rcval.run(deck(*flags)))
        e_r, tc_r = refs[name]
        err = max(rcval.rel(e, e_r), rcval.rel(tc, tc_r))
        # the curves must change the result by far more than the tolerance
        shift = abs(e_r - e_v) / e_v
        ok = err < TOL and (name == "visc" or shift > 100 * TOL)
        rcval.check(f"t6_damping_curves.{name}", ok,
                    f"e = {e:.9f}, tc = {tc:.9e} s; reference e = {e_r:.9f}, tc = {tc_r:.9e} s; max rel. error "
                    f"{err:.2e} (< {TOL:g})" + ("" if name == "visc" else
                                                f"; restitution changed by {100 * shift:.2f} % from Visc alone"))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
