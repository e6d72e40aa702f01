"""Restitution asked of a power-law contact (/INTER/POWER e_target,
ricochet's extension): ricochet derives the damping coefficient C that
gives the asked coefficient of restitution for the law as implemented
(docs/theory.md, "Restitution asked").

A sphere hits a fixed plane at V0 without gravity, once. Two laws:
  linear:  F = K delta + C d delta/dt           (m1 = 1, m2 = 1, m3 = 0, RDF off)
  Hertz:   F = K delta^1.5 + C d delta/dt delta^1.5 x RDF while delta falls
           (m1 = m3 = 1.5, m2 = 1, the default RDF 0.001)
both with the force clipped at zero (a contact cannot pull), for asked
e = 0.05 ... 0.95.

References (independent of ricochet):
  1. the asked e against the achieved e, the body's rebound speed after the
     impact over V0, measured from the simulation at the default solver
     settings (bound 1e-6);
  2. the C ricochet derived (printed by `ricochet check`) put into this
     script's own solution of the contact ODE (scipy solve_ivp, DOP853,
     rtol 1e-12, with the branch and clipping events) must give the asked
     e (bound 1e-6): ricochet's ODE and root solve checked independently;
  3. linear law: the closed form of the clipped linear oscillator (written
     here) at the damping ratio C / (2 sqrt(K m)) must give the asked e.
"""
import math
import os
import re
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

R, RHO, ESTAR = 0.01, 7850.0, 1.15e11
M = RHO * 4.0 / 3.0 * math.pi * R**3
K_HERTZ = 4.0 / 3.0 * ESTAR * math.sqrt(R)
K_LIN = 1.0e6
V0 = 1.0
RDF = 0.001
E_ASKED = (0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.8, 0.95)
TOL = 1e-6
# Dreg: delta^m3 with m3 = 0 (the indentation factor 1) is regularised below
# Dreg by the quadratic a x + b x^2, a = 2/Dreg, b = -1/Dreg^2
# (docs/theory.md 9; it rises from 0 to 1 over Dreg). The linear law gives
# Dreg = 1e-7 m (the maximum penetration is 1.8e-4 m) and this script
# includes the quadratic: it shifts e by about 1e-5, more than the bound, and
# ricochet's derivation includes it (the law as implemented).
DREG = 1e-7
LAWS = {
    "linear": dict(k=K_LIN, m1=1.0, m2=1.0, m3=0.0, irdf=2, dreg=DREG),
    "hertz": dict(k=K_HERTZ, m1=1.5, m2=1.0, m3=1.5, irdf=0, dreg=None),
    "t6_table": dict(),
}
# TYPE6 with a nonlinear load curve: the Hertz force K p^1.5 tabulated
# (linear interpolation between 81 points up to 1e-4 m), damping Visc v.
T6_X = np.linspace(0.0, 1e-4, 81)
T6_Y = K_HERTZ * T6_X**1.5


def deck(law, e):
    p = LAWS[law]
    d = Deck(f"restitution asked of a {law} power law: e = {e}")
    z0 = R + 1e-5
    add_sphere_over_plane(d, M, R, z0, V0, title="steel sphere R = 10 mm")
    if law == "t6_table":
        d.funct(1, list(T6_X), list(T6_Y), title="Hertz force tabulated")
        d.type6(1, 1, 2, 1, e_target=e, title="TYPE6 nonlinear load curve, restitution asked")
    else:
        d.power(1, 1, 2, k=p["k"], m1=p["m1"], c=None, m2=p["m2"], m3=p["m3"], irdf=p["irdf"], dreg=p["dreg"],
                e_target=e, title=f"{law}, restitution asked")
    d.run(2.0e-3 if law.startswith("linear") else 2.0e-4, 1.0e-5)
    return d


def derived_c(d):
    """C from `ricochet check` ("C derived = ...")."""
    tmp = rcval.tmpdir()
    path = os.path.join(tmp, "case.rad")
    with open(path, "w") as f:
        f.write(d.text())
    out = subprocess.run([rcval.RICOCHET, "check", path], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    m = re.search(r"(?:C|Visc) derived = ([0-9.eE+-]+)", out.stdout)
    pm = re.search(r"predicted ([0-9.eE+-]+)", out.stdout)
    return float(m.group(1)), float(pm.group(1))


def scipy_restitution(law, c):
    """The single impact solved here: m x'' = -F, F = K x^m1 + C v x^m3 [x RDF when v < 0],
    the force acting while > 0; e = -v / V0 when x returns to 0. Powers
    exact (the law's regularisation acts below 1e-4 of the penetration
    scale, far below the 1e-6 bound)."""
    p = LAWS[law]
    rdf = 1.0 if law == "t6_table" or p["irdf"] == 2 else RDF

    def force(x, v):
        xp = max(x, 0.0)
        if law == "t6_table":
            return np.interp(xp, T6_X, T6_Y) + c * v
        ind = xp ** p["m3"] if p["m3"] > 0 else (2.0 * xp / DREG - (xp / DREG) ** 2 if xp < DREG else 1.0)
        return p["k"] * xp ** p["m1"] + c * v * ind * (rdf if v < 0 else 1.0)

    state = {"closed": True}

    def rhs(t, y):
        return [y[1], -force(y[0], y[1]) / M if state["closed"] else 0.0]

    def ev_force(t, y):
        return force(y[0], y[1]) if y[0] > 0 else 1.0
    ev_force.terminal, ev_force.direction = True, -1

    def ev_sep(t, y):
        return y[0]
    ev_sep.terminal, ev_sep.direction = True, -1

    def ev_turn(t, y):
        return y[1]
    ev_turn.terminal, ev_turn.direction = True, -1

    t, y = 0.0, np.array([0.0, V0])
    tscale = 1.0
    for _ in range(10):
        evs = [ev_sep] + ([ev_force] if state["closed"] else []) + ([ev_turn] if y[1] > 0 else [])
        sol = solve_ivp(rhs, (t, t + 1.0 * tscale), y, method="DOP853", rtol=1e-12, atol=1e-16, events=evs,
                        first_step=1e-9)
        t, y = sol.t[-1], sol.y[:, -1]
        if sol.status != 1:
            raise RuntimeError("no event")
        fired = [k for k, te in enumerate(sol.t_events) if len(te)]
        ev = evs[fired[0]]
        if ev is ev_sep:
            return -y[1] / V0
        if ev is ev_force:
            state["closed"] = False
            y = np.array([y[0], y[1]])
        # ev_turn: the RDF branch starts (force() reads the sign of v)
        y = np.array([y[0], min(y[1], -1e-300)]) if ev is ev_turn else y
    raise RuntimeError("no separation")


def linear_closed_form(zeta):
    """Restitution of x'' + 2 zeta x' + x = 0, x(0) = 0, x'(0) = 1, ending
    where x + 2 zeta x' = 0 (the force reaches zero) or x = 0."""
    if zeta < 1:
        s = math.sqrt(1 - zeta * zeta)
        # the first root of x + 2 zeta x' = 0 with x = e^{-zeta t} sin(s t)/s
        theta = math.pi - math.atan2(2 * zeta * s, 1 - 2 * zeta * zeta)
        return -math.exp(-zeta * theta / s) * (math.cos(theta) - zeta / s * math.sin(theta))
    raise ValueError("overdamped: use the ODE")


def measure(path):
    r = rcval.Result(path)
    n_close = len(r.events("contact_close"))
    return r.vel[-1, 0, 2] / V0, n_close


def main():
    for law in LAWS:
        worst_sim = worst_ode = worst_cf = 0.0
        rows = []
        for e in E_ASKED:
            d = deck(law, e)
            c, pred = derived_c(d)
            got, ncl = measure(rcval.run(d))
            e_ode = scipy_restitution(law, c)
            worst_sim = max(worst_sim, abs(got - e))
            worst_ode = max(worst_ode, abs(e_ode - e))
            if law == "linear":
                zeta = c / (2.0 * math.sqrt(K_LIN * M))
                if zeta < 1:
                    worst_cf = max(worst_cf, abs(linear_closed_form(zeta) - e))
            rows.append(f"{e:g}: C {c:.6g} sim {got:.9f} scipy {e_ode:.9f}")
        rcval.check(f"pw_restitution.{law}_achieved", worst_sim < TOL,
                    f"asked vs achieved (rebound/approach speed of the simulation): {'; '.join(rows)}; "
                    f"max |error| {worst_sim:.2e} (< {TOL:g})")
        rcval.check(f"pw_restitution.{law}_scipy", worst_ode < TOL,
                    f"scipy solve_ivp of the contact ODE with the derived C gives the asked e within {worst_ode:.2e} "
                    f"(< {TOL:g})")
        if law == "linear":
            rcval.check("pw_restitution.linear_closed_form", worst_cf < 1e-4,
                        f"closed form of the clipped linear oscillator without the regularisation at zeta = "
                        f"C/(2 sqrt(K m)) (underdamped asks) gives the asked e within {worst_cf:.2e} (< 1e-4: "
                        f"the regularisation over Dreg = {DREG:g} m shifts e by about 1e-5)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck("hertz", 0.5))
