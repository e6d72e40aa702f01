"""General power-law impact (K, m1, C, m2, m3) with the default RDF, against
an independent integration of the 1-D equation of motion by SciPy.

    m d2delta/dt2 = -max(0, K p(delta, m1) + C p(v, m2) p(delta, m3) r(v)),
    v = d delta/dt,  r(v) = RDF when v < 0 else 1,
    p(x, m) = x^m regularised below Dreg (m < 1) as docs/theory.md 9.2.

Reference: scipy.integrate.solve_ivp (DOP853, rtol 1e-13) in phases split at
v = 0 and at the release (force reaching zero); rebound speed and contact
duration within 1e-6 relative. Two cases: exponents above and below 1 (the
regularised indentation factor), and RDF on (0.001, default) and off.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

R, M = 0.01, 7850.0 * 4.0 / 3.0 * math.pi * 0.01**3
DREG = 1e-6  # regularisation length set on the card [m] (the reference integrates the same law)
# (v0 [m/s], K, m1, C, m2, m3, RDF (None: off))
CASES = ((0.8, 1.9e8, 1.3, 3.6e5, 1.2, 0.8, 0.001),
         (0.6, 4.1e9, 1.7, 2.3e6, 0.9, 1.1, None))


def powreg(x, m, xr):
    """x^m, regularised below xr for m < 1 (C1 quadratic), odd extension."""
    s, ax = (-1.0 if x < 0 else 1.0), abs(x)
    if m == 1.0:
        v = ax
    elif m < 1.0 and ax < xr:
        v = ax * ((2.0 - m) * xr ** (m - 1.0) + (m - 1.0) * xr ** (m - 2.0) * ax)
    else:
        v = ax ** m if ax > 0 else 0.0
    return s * v


def reference(v0, K, m1, C, m2, m3, rdf):
    """Rebound speed and contact duration of the 1-D impact."""
    vreg = 1e-6

    def force(d, v):
        f = K * powreg(d, m1, DREG) + C * powreg(v, m2, vreg) * powreg(d, m3, DREG) * (rdf if (rdf and v < 0) else 1.0)
        return f

    def rhs(t, y):
        return [y[1], -max(0.0, force(y[0], y[1])) / M]

    def ev_v(t, y):
        return y[1]
    ev_v.terminal, ev_v.direction = True, -1

    def ev_f(t, y):
        return force(y[0], y[1])
    ev_f.terminal, ev_f.direction = True, -1

    def ev_d(t, y):
        return y[0]
    ev_d.terminal, ev_d.direction = True, -1

    opts = dict(method="DOP853", rtol=1e-13, atol=[1e-18, 1e-14])
    # compression: until v = 0
    s = solve_ivp(rhs, (0, 1), [0.0, v0], events=[ev_v], **opts)
    t, y = s.t[-1], s.y[:, -1]
    # restitution: until the force is released or delta = 0
    s = solve_ivp(rhs, (t, t + 1), y, events=[ev_f, ev_d], **opts)
    t, y = s.t[-1], s.y[:, -1]
    if s.t_events[0].size:  # released: free flight to delta = 0
        t += y[0] / -y[1]
    return -y[1], t


def deck(v0, K, m1, C, m2, m3, rdf, rtol=1e-10):
    d = Deck(f"power-law impact K {K:g} m1 {m1} C {C:g} m2 {m2} m3 {m3} RDF {rdf}")
    z0 = R + 1e-7
    add_sphere_over_plane(d, M, R, z0, v0, title="steel sphere R = 10 mm")
    d.power(1, 1, 2, k=K, m1=m1, c=C, m2=m2, m3=m3, irdf=0 if rdf else 2, rdf=rdf, dreg=DREG, vreg=1e-6)
    d.run(4e-4, 1.0e-6)
    d.solver(rtol=rtol, atol_pos=1e-15, atol_vel=1e-10, atol_energy=1e-12)
    return d


def measure(path):
    r = rcval.Result(path)
    t1 = r.events("contact_close")[0]
    t2 = r.events("contact_separate")[0]
    return r.vel[r.state_at(t2), 0, 2], t2 - t1, len(r.events("contact_open")), r


def main():
    full = "--all" in sys.argv
    for k, cs in enumerate(CASES):
        v0 = cs[0]
        vr_ref, tc_ref = reference(*cs)
        name = "case.rad" if k == 0 else f"case{k + 1}.rad"
        vout, tc, nrel, r = measure(rcval.run_case(name))
        ev, et = rcval.rel(vout, vr_ref), rcval.rel(tc, tc_ref)
        rcval.check(f"pw_general.rebound_{k + 1}", ev < 1e-6 and et < 1e-6,
                    f"K {cs[1]:g} m1 {cs[2]} C {cs[3]:g} m2 {cs[4]} m3 {cs[5]} RDF {cs[6]}: rebound {vout:.9f} m/s, "
                    f"solve_ivp {vr_ref:.9f} m/s (rel. {ev:.1e}); contact {tc:.9e} s vs {tc_ref:.9e} s "
                    f"(rel. {et:.1e}); {nrel} release(s)")
        res = abs(r.energy["energy_total"][-1] - r.energy["energy_total"][0]) / (0.5 * M * v0 * v0)
        rcval.check(f"pw_general.ledger_{k + 1}", res < 1e-6, f"|E_total(end) - E_total(0)| / E_kin(0) = {res:.2e} (< 1e-6)")
        if full and k == 0:
            errs = []
            for rtol in (1e-6, 1e-8, 1e-10):
                v, _, _, _ = measure(rcval.run(deck(*cs, rtol=rtol), keep_solver=True))
                errs.append(rcval.rel(v, vr_ref))
            rcval.check("pw_general.convergence", errs[2] <= errs[0],
                        "error at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad" if k == 0 else f"case{k + 1}.rad": deck(*cs) for k, cs in enumerate(CASES)})
