"""Hunt-Crossley impact with /INTER/POWER (m1 = m3 = 1.5, m2 = 1, RDF off).

F = K delta^1.5 (1 + alpha d delta/dt), alpha = C / K. The coefficient of
restitution follows from the energy integral (README.md): with
G(v) = integral_0^v s / (1 + alpha s) ds, the rebound speed v_r solves
G(-v_r) = G(v0). G is computed here by quadrature (scipy.integrate.quad) and
the root by brentq, independently of ricochet. Tolerance 1e-4 on e; the
error shrinks with rtol (--all).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

R, RHO, ESTAR = 0.01, 7850.0, 1.15e11
M = RHO * 4.0 / 3.0 * math.pi * R**3
K = 4.0 / 3.0 * ESTAR * math.sqrt(R)
CASES = ((0.5, 0.4), (1.5, 0.3))  # (v0 [m/s], alpha [s/m])


def restitution(v0, alpha):
    """e from G(-e v0) = G(v0), G by quadrature."""
    def G(v):
        return quad(lambda s: s / (1.0 + alpha * s), 0.0, v, epsabs=0, epsrel=1e-13, limit=200)[0]
    g0 = G(v0)
    vr = brentq(lambda v: G(-v) - g0, 1e-9 * v0, min(v0, 0.999999 / alpha), xtol=1e-15, rtol=1e-15)
    return vr / v0


def deck(v0, alpha, rtol=1e-10):
    d = Deck(f"Hunt-Crossley impact, v0 = {v0} m/s, alpha = {alpha} s/m")
    z0 = R + 1e-6
    add_sphere_over_plane(d, M, R, z0, v0, title="steel sphere R = 10 mm")
    d.power(1, 1, 2, k=K, m1=1.5, c=alpha * K, m2=1.0, m3=1.5, irdf=2, title="Hunt-Crossley, RDF off")
    d.run(1.5e-4, 1.0e-6)
    d.solver(rtol=rtol, atol_pos=1e-15, atol_vel=1e-10, atol_energy=1e-12)
    return d


def measure(path):
    r = rcval.Result(path)
    ts = r.events("contact_separate")
    released = len(r.events("contact_open"))
    vout = r.vel[r.state_at(ts[0]), 0, 2]
    return vout, released, r


def main():
    full = "--all" in sys.argv
    for k, (v0, alpha) in enumerate(CASES):
        e_ref = restitution(v0, alpha)
        name = "case.rad" if k == 0 else f"case{k + 1}.rad"
        vout, released, r = measure(rcval.run_case(name))
        e = vout / v0
        err = abs(e - e_ref)
        rcval.check(f"pw_hunt_crossley.restitution_{k + 1}", err < 1e-4 and released == 0,
                    f"v0 {v0} m/s, alpha {alpha} s/m: e = {e:.8f}, energy integral {e_ref:.8f}, |error| {err:.2e} "
                    f"(< 1e-4); force never clipped ({released} releases)")
        res = abs(r.energy["energy_total"][-1] - r.energy["energy_total"][0]) / (0.5 * M * v0 * v0)
        rcval.check(f"pw_hunt_crossley.ledger_{k + 1}", res < 1e-6,
                    f"|E_total(end) - E_total(0)| / E_kin(0) = {res:.2e} (< 1e-6); damping dissipated "
                    f"{r.energy['energy_damping'][-1]:.6e} J, kinetic lost {0.5 * M * (v0**2 - vout**2):.6e} J")
        if full and k == 0:
            errs = []
            for rtol in (1e-6, 1e-8, 1e-10):
                v, _, _ = measure(rcval.run(deck(v0, alpha, rtol), keep_solver=True))
                errs.append(abs(v / v0 - e_ref))
            rcval.check("pw_hunt_crossley.convergence", errs[2] <= errs[0],
                        "error at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad" if k == 0 else f"case{k + 1}.rad": deck(v0, alpha)
                               for k, (v0, alpha) in enumerate(CASES)})
