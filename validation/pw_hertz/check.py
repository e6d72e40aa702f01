"""Hertz impact with /INTER/POWER: K delta^1.5, C = 0 (docs/theory.md 9.1).

Reference: Hertz closed form (README.md): maximum approach, peak force and
contact duration, within 1e-4; and the same impact with /INTER/TYPE6 and the
tabulated Hertz curve (validation/hertz), within 0.5 %.
"""
import math
import os
import sys

import numpy as np
from scipy.special import gamma

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

R, RHO, ESTAR, V0 = 0.01, 7850.0, 1.15e11, 0.5
M = RHO * 4.0 / 3.0 * math.pi * R**3
K = 4.0 / 3.0 * ESTAR * math.sqrt(R)


def reference():
    dmax = (5.0 * M * V0**2 / (4.0 * K)) ** 0.4
    fmax = K * dmax**1.5
    integral = math.sqrt(math.pi) * gamma(1.4) / gamma(0.9)
    return dmax, fmax, 2.0 * dmax / V0 * integral


def deck(rtol=1e-8):
    d = Deck("Hertz impact with the power-law contact")
    z0 = R + 1e-5
    add_sphere_over_plane(d, M, R, z0, V0, title="steel sphere R = 10 mm")
    d.power(1, 1, 2, k=K, m1=1.5, c=0.0, title="Hertz: K delta^1.5, no damping")
    d.run(2.0e-4, 1.0e-7)
    d.solver(rtol=rtol, atol_pos=1e-13, atol_vel=1e-8)
    return d


def measure(r):
    t1, t2 = r.events("contact_close")[0], r.contact_ends()[0]
    k = int(np.argmax(r.pen[:, 0]))
    return rcval.parabola_peak(r.pen[:, 0], k), rcval.parabola_peak(r.fn[:, 0], k), t2 - t1


def main():
    ref = reference()
    got = measure(rcval.Result(rcval.run_case()))
    t6 = measure(rcval.Result(rcval.run_file(os.path.join(HERE, "..", "hertz", "case.rad"))))
    names = (("max_approach", "m"), ("peak_force", "N"), ("contact_time", "s"))
    for (name, unit), g, rf, b in zip(names, got, ref, t6):
        e = rcval.rel(g, rf)
        rcval.check(f"pw_hertz.{name}", e < 1e-4, f"{g:.8e} {unit}, Hertz {rf:.8e} {unit}, rel. error {e:.2e} (< 1e-4)")
        e6 = rcval.rel(g, b)
        rcval.check(f"pw_hertz.{name}_vs_type6", e6 < 5e-3,
                    f"TYPE6 tabulated {b:.8e} {unit}, rel. difference {e6:.2e} (< 5e-3)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
