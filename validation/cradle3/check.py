"""Newton's cradle of 3 equal steel balls, touching with zero gaps, Hertz contacts.

Ball 1 hits the row at v0 = 0.2 m/s; every contact starts exactly at zero
(P = 0; all but the first also at dP/dt = 0). Reference: scipy solve_ivp
(DOP853, rtol 1e-12, restarted at every contact event) of the same 1-D chain
with unilateral Hertz contacts (README.md). Final velocities of all balls
within 1e-4 v0, kinetic energy within 1e-5, peak overlaps within 1e-3, and
no ball passing into the next (overlap < 3 x the two-ball Hertz approach).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import cradle  # noqa: E402
import rcval  # noqa: E402

N, V0, T_END, DT_OUT = 3, 0.2, 3.0e-4, 1.0e-7


def deck():
    return cradle.deck(N, V0, T_END, DT_OUT)


def main():
    cradle.check("cradle3", N, V0, T_END, os.path.join(HERE, "case.rad"))
    rcval.finish()


if __name__ == "__main__":
    if "--write-case" in sys.argv:
        deck().write(os.path.join(HERE, "case.rad"))
    else:
        main()
