"""Linear spring-dashpot impact of a sphere on a fixed plane (force clipped at zero).

Reference: closed form of the damped oscillator (README.md). Checks the
restitution coefficient and contact duration at the default tolerances
(relative error < 1e-4) and that the error shrinks as rtol shrinks.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, ZETA, V0, GAP0 = 1.0, 0.05, 1.0e6, 0.1, 1.0, 0.002
C = 2.0 * ZETA * math.sqrt(K * M)


def reference():
    """Contact ends when k p + c p' = 0 (the clipped force reaches zero)."""
    wn = math.sqrt(K / M)
    wd = wn * math.sqrt(1 - ZETA**2)
    tc = (math.pi - math.atan(2 * ZETA * math.sqrt(1 - ZETA**2) / (1 - 2 * ZETA**2))) / wd
    vout = V0 / wd * math.exp(-ZETA * wn * tc) * (wd * math.cos(wd * tc) - ZETA * wn * math.sin(wd * tc))
    return -vout / V0, tc


def deck(rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6):
    d = Deck("linear spring-dashpot impact")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, visc=C, title="spring-dashpot")
    d.run(0.01, 0.001)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel)
    return d


def measure(path):
    r = rcval.Result(path)
    t1 = r.events("contact_close")[0]
    t2 = r.events("contact_open")[0]
    vz = r.vel[r.state_at(t2), 0, 2]
    return vz / V0, t2 - t1


def main():
    e_ref, tc_ref = reference()
    e, tc = measure(rcval.run_case())
    rcval.check("spring_dashpot.restitution", rcval.rel(e, e_ref) < 1e-4,
                f"e = {e:.9f}, closed form {e_ref:.9f}, rel. error {rcval.rel(e, e_ref):.2e} (< 1e-4)")
    rcval.check("spring_dashpot.contact_time", rcval.rel(tc, tc_ref) < 1e-4,
                f"tc = {tc:.9e} s, closed form {tc_ref:.9e} s, rel. error {rcval.rel(tc, tc_ref):.2e} (< 1e-4)")
    # convergence: error shrinks with rtol (atol scaled alongside)
    errs = []
    for rtol in (1e-4, 1e-6, 1e-8):
        e, tc = measure(rcval.run(deck(rtol, 1e-3 * rtol, rtol), keep_solver=True))
        errs.append(max(rcval.rel(e, e_ref), rcval.rel(tc, tc_ref)))
    ok = errs[2] < errs[1] < errs[0]
    rcval.check("spring_dashpot.convergence", ok,
                "max rel. error at rtol 1e-4, 1e-6, 1e-8: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
