"""Contact geometry of the cylinder and box pairs at rest (docs/theory.md 2).

1. A free cylinder (radius r, axis Y) in the groove between two fixed
   parallel cylinders (radius R, axes at x = -a and x = +a, z = 0), under
   gravity, cylinder-cylinder /INTER/POWER (K delta^1.5, damped). At rest:
   the centre on x = 0 at height h, each contact along the line of centres
   at the angle alpha from the vertical (sin alpha = a / (R + r - delta)),
   each normal force F = m g / (2 cos alpha) with F = K delta^1.5, the
   contact points on the line of centres between the surfaces.
2. A sphere resting on a box whose axes are permuted (u = Z, v = X, w = Y,
   half-sizes 0.03 along u): the top face is the +u face; at rest the
   sphere's centre is at the face height + r - delta, F = m g, n = -Z.

Tolerance 1e-6 relative on the forces, 1e-9 m on the positions; the
reference equations are solved by brentq.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G = 9.81
M, RF, LF = 0.8, 0.02, 0.1          # free cylinder
RB, A = 0.03, 0.035                  # fixed cylinders: radius, half distance of the axes
MS, RS = 0.3, 0.015                  # sphere
ZBOX, HU = -0.2, 0.03                # box centre height, half-size along u (vertical)
K = 2.0e9


def groove():
    """(alpha, delta, F, h) at rest."""
    def f(delta):
        d = RF + RB - delta
        ca = math.sqrt(1 - (A / d) ** 2)
        return K * delta**1.5 - M * G / (2 * ca)
    delta = brentq(f, 1e-12, 1e-3, xtol=1e-18, rtol=1e-15)
    d = RF + RB - delta
    alpha = math.asin(A / d)
    return alpha, delta, K * delta**1.5, d * math.cos(alpha)


def deck():
    alpha, delta, F, h = groove()
    dq = (MS * G / K) ** (1 / 1.5)
    zs = ZBOX + HU + RS - dq
    d = Deck("cylinder in a groove of two cylinders; sphere on a box with permuted axes")
    d.nodes([(1, 0.0, 0.0, h + 2e-7), (2, 0.5, 0.0, zs + 1e-7)])
    jt = M * (3 * RF * RF + LF * LF) / 12
    d.rbody(1, 1, M, (jt, 0.5 * M * RF * RF, jt), title="free cylinder")
    d.rbody(2, 2, MS, [0.4 * MS * RS * RS] * 3, title="sphere")
    d.grnod(1, [1, 2])
    d.cylinder(1, 1, (0.0, 0.0, h + 2e-7), (0.0, 1.0, 0.0), RF, LF, title="free")
    d.cylinder(2, 0, (-A, 0.0, 0.0), (0.0, 1.0, 0.0), RB, 0.3, title="left")
    d.cylinder(3, 0, (A, 0.0, 0.0), (0.0, -1.0, 0.0), RB, 0.3, title="right (axis reversed)")
    d.sphere(4, 2, (0.5, 0.0, zs + 1e-7), RS)
    d.box(5, 0, (0.5, 0.0, ZBOX), (HU, 0.05, 0.04), u=(0.0, 0.0, 1.0), v=(1.0, 0.0, 0.0), title="box, u = Z")
    d.grav(1, "Z", -G)
    for i, (s1, s2) in enumerate(((1, 2), (3, 1), (4, 5))):
        d.power(i + 1, s1, s2, k=K, m1=1.5, c=3e8, m2=1.0, m3=1.0, irdf=2)
    d.run(0.4, 0.01)
    d.solver(rtol=1e-10, atol_pos=1e-14, atol_vel=1e-11, atol_omega=1e-10, atol_energy=1e-12)
    return d


def main():
    alpha, delta, F, h = groove()
    out = rcval.run_case()
    with Dataset(out) as nc:
        x = np.array(nc["body_position"][-1])
        fn = np.array(nc["inter_force_normal"][-1])
        pt = np.array(nc["inter_contact_point"][-1])
        nr = np.array(nc["inter_normal"][-1])
    ef = max(rcval.rel(fn[0], F), rcval.rel(fn[1], F))
    ex = max(abs(x[0, 0]), abs(x[0, 2] - h))
    # normals: from a to b; interface 1 is free -> left (a = free), 2 is right -> free
    n_left = np.array([-math.sin(alpha), 0.0, -math.cos(alpha)])
    n_right = np.array([-math.sin(alpha), 0.0, math.cos(alpha)])
    en = max(np.abs(nr[0] - n_left).max(), np.abs(nr[1] - n_right).max())
    # contact points: on the line of centres, midway between the surfaces
    p_left = np.array([-A, 0.0, 0.0]) - n_left * (RB - 0.5 * delta)
    p_right = np.array([A, 0.0, 0.0]) + n_right * (RB - 0.5 * delta)
    ep = max(np.abs(pt[0][[0, 2]] - p_left[[0, 2]]).max(), np.abs(pt[1][[0, 2]] - p_right[[0, 2]]).max())
    rcval.check("pw_contact_geometry.groove", ef < 1e-6 and ex < 1e-9 and en < 1e-9 and ep < 1e-9,
                f"alpha {math.degrees(alpha):.4f} deg: forces {fn[0]:.9f}, {fn[1]:.9f} N vs m g / (2 cos) "
                f"{F:.9f} N (rel. {ef:.1e}); centre off by {ex:.1e} m; normals off by {en:.1e}; "
                f"contact points off by {ep:.1e} m")
    dq = (MS * G / K) ** (1 / 1.5)
    es = max(rcval.rel(fn[2], MS * G), abs(x[1, 2] - (ZBOX + HU + RS - dq)) / 1e-3)
    rcval.check("pw_contact_geometry.sphere_on_box", es < 1e-6 and np.abs(nr[2] - [0, 0, -1]).max() < 1e-12,
                f"force {fn[2]:.9f} N vs m g {MS * G:.9f} N; centre height {x[1, 2]:.12f} m vs "
                f"{ZBOX + HU + RS - dq:.12f} m; normal {nr[2]}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
