"""An analytic box (/SURF/BOX) on an inclined plane with friction: the box's
8 corners are its contact points, each with its own tangential force and
stick/slip mode (docs/theory.md 2.7).

The box a x b x c, mass M, inertia of a homogeneous box, rests on a fixed
plane tilted by theta about a horizontal axis at azimuth phi = 30 deg (the
fall line along no global axis). References (README.md), closed forms:
  - tan(theta) > mu: the box slides down the fall line at
    a = g (sin theta - mu cos theta) (the four bottom corners all slip; the
    limits mu f_j add up to mu F_n = mu M g cos theta); with TYPE6's Fric
    (box first on the card) and with a /FRICTION card (plane first);
  - tan(theta) = mu / 3 < mu: it sticks, no slip event; the friction force
    is M g sin(theta); the centre moves down the slope by the stick springs'
    elastic displacement M g sin(theta) / K_t plus the tilt the base friction
    gives (README.md).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxincline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, K, ZETA, MU = 9.81, 1.0e6, 0.7, 0.3
A, B, C, M = 0.2, 0.12, 0.08, 15.0  # box sizes [m], mass [kg]
JD = (M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12)
PHI = math.radians(30.0)            # azimuth of the fall line


def deck(tan_th, tend, dtout, card=False):
    """card: friction from a /FRICTION card (Coulomb Fric = mu, incremental
    Iform 2) instead of TYPE6's Fric, and the plane first on the TYPE6 card."""
    R = boxincline.rotation(tan_th, PHI)
    th = math.atan(tan_th)
    p0 = M * G * math.cos(th) / K  # static penetration of the four bottom corners
    d = Deck(f"analytic box on a plane tilted by atan({tan_th:g}), friction per corner")
    centre = R @ np.array([0.0, 0.0, C / 2 - p0])
    d.nodes([(1, *centre)])
    d.grnod(1, [1], title="box")
    J = R @ np.diag(JD) @ R.T
    d.rbody(1, 1, M, (J[0, 0], J[1, 1], J[2, 2]), Joff=(J[0, 1], J[1, 2], J[0, 2]), grnod=1, title="box")
    d.box(31, 1, tuple(centre), (A / 2, B / 2, C / 2), u=tuple(R[:, 0]), v=tuple(R[:, 1]), title="box surface")
    d.plane(10, (0, 0, 0), tuple(R @ np.array([0.0, 0.0, 1.0])), title="inclined plane through the origin")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    visc = 2 * ZETA * math.sqrt(K * M)
    if card:
        d.type6(1, 10, 31, 1, visc=visc, title="the incline and the box (plane first), no TYPE6 friction")
        d.friction(1, ifric=0, iform=2, fric=MU, title="Coulomb mu = 0.3, incremental (every interface)")
    else:
        d.type6(1, 31, 10, 1, visc=visc, fric=MU, title="box on the incline, Fric 0.3")
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def main():
    # 1. sticking: tan(theta) = mu / 3 (case.rad); 2. sliding: tan(theta) =
    # 0.5 > mu; 3. sliding, friction from a /FRICTION card, the plane first on the card
    boxincline.run_checks("box_plane_incline", HERE, deck, "card", f"/FRICTION Fric {MU:g}, plane first on the card",
                          PHI, M, G, K, MU, A, C)


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(MU / 3, 2.0, 0.01))
