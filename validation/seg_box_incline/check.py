"""A meshed box on an inclined plane with friction per contact point.

A solid box (one /BRICK, mass and inertia from the mesh, contact surface
/SURF/PART: its eight nodes are the contact points) rests on a fixed plane
tilted by theta about a horizontal axis at azimuth phi = 30 deg (so the fall
line is along no global axis), TYPE6 with a linear load curve and Fric = mu.
Each node carries its own tangential force and stick/slip mode
(docs/theory.md 2.7). References (README.md), closed forms:
  - tan(theta) > mu: the box slides down the fall line at
    a = g (sin theta - mu cos theta) (the four bottom nodes all slip; the
    limits mu f_j add up to mu F_n = mu m g cos theta);
  - tan(theta) < mu / 3 (a step load that the critically damped stick spring
    takes without reaching the limit): it sticks, no slip event; its drift
    along the fall line stays within the elastic displacement of the stick
    spring, x_s <= m g sin(theta) / K_t (the point springs w_j K_t add up to
    K_t), and ends there.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxincline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

G, K, ZETA, MU = 9.81, 1.0e6, 0.7, 0.3
A, B, C = 0.2, 0.12, 0.08        # box sizes [m]
RHO = 7800.0                     # steel [kg/m^3]
M = RHO * A * B * C              # mass from the mesh [kg]
PHI = math.radians(30.0)         # azimuth of the fall line
NPLATE, PW = 10, 0.4             # the meshed incline: segments along the fall line, width [m]
CORNERS = [(-A / 2, -B / 2, -C / 2), (A / 2, -B / 2, -C / 2), (A / 2, B / 2, -C / 2), (-A / 2, B / 2, -C / 2),
           (-A / 2, -B / 2, C / 2), (A / 2, -B / 2, C / 2), (A / 2, B / 2, C / 2), (-A / 2, B / 2, C / 2)]


def deck(tan_th, tend, dtout, plate=False):
    """plate: the incline a fixed /SURF/SEG plate (a strip of quadrilaterals
    along the fall line, its nodes on the strip's long edges, off the box's
    path) instead of /SURF/PLANE."""
    R = boxincline.rotation(tan_th, PHI)
    th = math.atan(tan_th)
    p0 = M * G * math.cos(th) / K  # static penetration of the four bottom nodes
    d = Deck(f"meshed box on a plane tilted by atan({tan_th:g}), friction per node")
    centre = R @ np.array([0.0, 0.0, C / 2 - p0])
    nodes = [(1, *centre)] + [(10 + j, *(R @ (np.array(v) + np.array([0.0, 0.0, C / 2 - p0])))) for j, v in
                              enumerate(CORNERS)]
    d.nodes(nodes)
    d.add("/MAT/LAW1/1", line(("r", RHO), ("r", 0.0)), line(("r", 2.1e11), ("r", 0.3)), title="steel")
    d.add("/PROP/SOLID/3", line(("i", 24), ("i", 4)), line(("r", 0)), line(("r", 0)), title="solid")
    d.add("/PART/1", line(("i", 3), ("i", 1), ("i", 0)), title="brick box")
    d.add("/BRICK/1", line(*[("i", v) for v in [101] + list(range(10, 18))]))
    d.add("/GRNOD/PART/101", i10(1), title="brick box nodes")
    d.add("/RBODY/1", line(("i", 1), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", 101), ("i", 0), ("i", 1), ("i", 0)),
          line(("r", 0), ("r", 0), ("r", 0)), line(("r", 0), ("r", 0), ("r", 0)), line(("i", 0), ("i", 0), ("i", 0)),
          title="brick box (mass from the mesh)")
    d.add("/SURF/PART/31", i10(1), title="brick box faces")
    if plate:
        xs = np.linspace(-0.3, 1.5, NPLATE + 1)
        pn = [(1000 + 2 * k + e, *(R @ np.array([x, -PW / 2 if e == 0 else PW / 2, 0.0]))) for k, x in enumerate(xs)
              for e in (0, 1)]
        d.nodes(pn)
        # quadrilaterals (x_k, -w/2), (x_k+1, -w/2), (x_k+1, w/2), (x_k, w/2): normal up the plate
        segs = [line(*[("i", v) for v in (k + 1, 1000 + 2 * k, 1002 + 2 * k, 1003 + 2 * k, 1001 + 2 * k)])
                for k in range(NPLATE)]
        d.add("/SURF/SEG/10", *segs, title="inclined plate: fixed segments")
    else:
        d.plane(10, (0, 0, 0), tuple(R @ np.array([0.0, 0.0, 1.0])), title="inclined plane through the origin")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.type6(1, 31, 10, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the incline, Fric 0.3")
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def main():
    # 1. sticking: tan(theta) = mu / 3 (case.rad); 2. sliding: tan(theta) =
    # 0.5 > mu; 3. sliding on a meshed incline: the box's surface against a
    # fixed segment surface (node to segment both ways), the same references
    boxincline.run_checks("seg_box_incline", HERE, deck, "plate", f"on a fixed /SURF/SEG plate of {NPLATE} quadrilaterals",
                          PHI, M, G, K, MU, A, C)


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(MU / 3, 2.0, 0.01))
