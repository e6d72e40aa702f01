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

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import cradle  # noqa: E402

if __name__ == "__main__":
    cradle.main("cradle3", n=3, v0=0.2, t_end=3.0e-4, dt_out=1.0e-7)
