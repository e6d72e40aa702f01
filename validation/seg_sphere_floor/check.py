"""Analytic spheres dropped on a meshed floor bounce as on the analytic plane.

The floor is /SURF/SEG: a grid of 0.1 m squares, each split into two
triangles (alternating diagonals), on nodes in no rigid body (fixed in
space); a second fixed /SURF/SEG is a 90-degree ridge of two
quadrilaterals. Six spheres (R = 0.05 m, m = 1 kg, each its own body and
its own TYPE6 interface, linear k = 1e6 N/m, no damping, no friction) fall
from rest or gliding, their lowest point h0 above the floor (the ridge):
  A on a face, B on a grid line, C on a node, D on a diagonal, E gliding at
  (0.7, 0.45) m/s across a diagonal and a grid line during the contact,
  F on the ridge's edge (a convex edge: the kept point is on the edge).
References (closed forms, README.md): the contact point is the closest
point of the floor, straight below the centre, so every sphere bounces as
on the analytic plane: first contact t1 = sqrt(2 h0 / g), contact end
t1 + T_c with T_c = (2 pi - 2 atan(v w / g)) / w, v = sqrt(2 g h0),
w^2 = k / m; the horizontal velocity is unchanged and the sphere does not
turn.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, R, K, G, H0 = 1.0, 0.05, 1.0e6, 9.81, 0.02
W = math.sqrt(K / M)
V = math.sqrt(2 * G * H0)
T1 = math.sqrt(2 * H0 / G)
TC = (2 * math.pi - 2 * math.atan(V * W / G)) / W
T_END = 0.1
RIDGE = (2.0, 0.0, 0.3)
VE = (0.7, 0.45)
# name, landing point (x, y), floor height, horizontal velocity
SPHERES = [("face", (0.033, 0.021), 0.0, (0.0, 0.0)),
           ("grid_line", (0.05, 0.0), 0.0, (0.0, 0.0)),
           ("node", (0.1, 0.1), 0.0, (0.0, 0.0)),
           ("diagonal", (0.03, 0.03), 0.0, (0.0, 0.0)),
           ("gliding", (0.199, 0.0123), 0.0, VE),
           ("ridge_edge", (RIDGE[0], RIDGE[1]), RIDGE[2], (0.0, 0.0))]


def floor():
    n, nodes, segs = 11, [], []
    for i in range(n):
        for j in range(n):
            nodes.append((5000 + i * n + j, -0.5 + 0.1 * i, -0.5 + 0.1 * j, 0.0))
    sid = 1
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = (5000 + i * n + j, 5000 + (i + 1) * n + j, 5000 + (i + 1) * n + j + 1, 5000 + i * n + j + 1)
            if (i + j) % 2 == 0:  # diagonal a-c
                segs += [(sid, a, b, c, c), (sid + 1, a, c, d, d)]
            else:                 # diagonal b-d
                segs += [(sid, a, b, d, d), (sid + 1, b, c, d, d)]
            sid += 2
    return nodes, segs


def deck():
    d = Deck("analytic spheres on a meshed floor")
    fn, fs = floor()
    x0, y0, z0 = RIDGE
    ridge = [(6001, x0 - 0.2, y0 - 0.1, z0 - 0.1), (6002, x0 + 0.2, y0 - 0.1, z0 - 0.1), (6003, x0 + 0.2, y0, z0),
             (6004, x0 - 0.2, y0, z0), (6005, x0 + 0.2, y0 + 0.1, z0 - 0.1), (6006, x0 - 0.2, y0 + 0.1, z0 - 0.1)]
    centres = []
    for k, (name, (x, y), zf, (vx, vy)) in enumerate(SPHERES):
        # the centre lands on (x, y) at t1
        centres.append((k + 1, x - vx * T1, y - vy * T1, zf + R + H0))
    d.nodes(centres + fn + ridge)
    d.add("/SURF/SEG/90", *[line(*[("i", v) for v in s]) for s in fs], title="floor: 200 triangles")
    d.add("/SURF/SEG/91", line(("i", 1), ("i", 6001), ("i", 6002), ("i", 6003), ("i", 6004)),
          line(("i", 2), ("i", 6004), ("i", 6003), ("i", 6005), ("i", 6006)), title="ridge: two quadrilaterals")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    for k, (name, _, zf, (vx, vy)) in enumerate(SPHERES):
        b = k + 1
        d.grnod(b, [b], title=f"sphere {name}")
        d.rbody(b, b, M, [0.4 * M * R * R] * 3, title=f"sphere {name}")
        d.sphere(10 + b, b, centres[k][1:], R, title=f"sphere {name}")
        d.type6(b, 10 + b, 91 if name == "ridge_edge" else 90, 1, title=f"sphere {name} on the floor")
        if vx or vy:
            d.inivel(b, (vx, vy, 0.0), b)
    d.grav(1, "Z", -G)
    d.run(T_END, 1e-3)
    return d


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    with Dataset(path) as nc:
        omega = np.array(nc["body_angular_velocity"][:])
    for k, (name, _, _, (vx, vy)) in enumerate(SPHERES):
        el = f"/INTER/TYPE6/{k + 1}"
        close = [t for t, kd, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if kd == "contact_close" and e == el]
        ends = [t for t, kd, e in zip(r.ev_t, r.ev_kind, r.ev_elem)
                if kd in ("contact_open", "contact_separate") and e == el]
        ok = len(close) >= 1 and len(ends) >= 1
        e1 = rcval.rel(close[0], T1) if ok else float("inf")
        e2 = rcval.rel(ends[0], T1 + TC) if ok else float("inf")
        rcval.check(f"seg_sphere_floor.{name}.bounce", ok and e1 < 1e-6 and e2 < 1e-6,
                    f"first contact {close[0] if close else float('nan'):.10f} s vs sqrt(2 h0 / g) = {T1:.10f} s "
                    f"(rel. error {e1:.2e}), contact end {ends[0] if ends else float('nan'):.10f} s vs t1 + T_c = "
                    f"{T1 + TC:.10f} s (rel. error {e2:.2e}), both < 1e-6")
        dv = float(np.max(np.abs(r.vel[:, k, :2] - np.array([vx, vy]))))
        wmax = float(np.max(np.abs(omega[:, k])))
        rcval.check(f"seg_sphere_floor.{name}.no_side_force", dv < 1e-9 and wmax < 1e-9,
                    f"max |v_xy - v_xy(0)| = {dv:.1e} m/s, max |omega| = {wmax:.1e} rad/s (both < 1e-9: the contact "
                    f"force is vertical, through the centre)")
        vz = float(r.vel[-1, k, 2])
        vz_ref = V - G * (T_END - T1 - TC)
        e = rcval.rel(vz, vz_ref)
        rcval.check(f"seg_sphere_floor.{name}.rebound", e < 1e-6,
                    f"v_z({T_END:g} s) = {vz:.9f} m/s vs v - g (t - t1 - T_c) = {vz_ref:.9f} m/s (elastic rebound), "
                    f"rel. error {e:.2e} (< 1e-6)")
    rcval.check_ledger("seg_sphere_floor.ledger", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
