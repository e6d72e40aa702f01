"""Hertz impact of a sphere on a rigid plane: F = K P^1.5 as a tabulated load curve.

Reference: Hertz closed form (README.md): maximum approach, peak force and
contact duration within 0.5 %.
"""
import math
import os
import sys

import numpy as np
from scipy.special import gamma

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

R, RHO, ESTAR, V0 = 0.01, 7850.0, 1.15e11, 0.5
M = RHO * 4.0 / 3.0 * math.pi * R**3
K = 4.0 / 3.0 * ESTAR * math.sqrt(R)
NPTS = 400


def reference():
    dmax = (5.0 * M * V0**2 / (4.0 * K)) ** 0.4
    fmax = K * dmax**1.5
    # tc = 2 (dmax/v0) int_0^1 (1 - x^(5/2))^(-1/2) dx, the integral in closed form
    integral = math.sqrt(math.pi) * gamma(1.4) / gamma(0.9)
    return dmax, fmax, 2.0 * dmax / V0 * integral


def deck():
    dmax = reference()[0]
    # points denser near zero, up to 1.5 dmax
    xs = 1.5 * dmax * (np.arange(NPTS) / (NPTS - 1)) ** 1.5
    d = Deck("Hertz impact, steel sphere on rigid plane")
    d.funct(1, xs, K * xs**1.5, title=f"Hertz F = K P^1.5, K = {K:.6g} N/m^1.5")
    z0 = R + 1e-5
    add_sphere_over_plane(d, M, R, z0, V0, title="steel sphere R = 10 mm")
    d.type6(1, 1, 2, 1, title="Hertz contact")
    d.run(2.0e-4, 1.0e-7)
    d.solver(rtol=1e-6, atol_pos=1e-12, atol_vel=1e-7)
    return d


def main():
    dmax, fmax, tc_ref = reference()
    r = rcval.Result(rcval.run_case())
    t1, t2 = r.events("contact_close")[0], r.contact_ends()[0]
    # peak values: the time series (dt 1e-7 s, ~1000 records in contact), refined by a parabola
    k = int(np.argmax(r.pen[:, 0]))
    pm, fm = rcval.parabola_peak(r.pen[:, 0], k), rcval.parabola_peak(r.fn[:, 0], k)
    tc = t2 - t1
    for name, got, ref, unit in (("max_approach", pm, dmax, "m"), ("peak_force", fm, fmax, "N"),
                                 ("contact_time", tc, tc_ref, "s")):
        e = rcval.rel(got, ref)
        rcval.check(f"hertz.{name}", e < 5e-3, f"{got:.6e} {unit}, Hertz {ref:.6e} {unit}, rel. error {e:.2e} (< 5e-3)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
