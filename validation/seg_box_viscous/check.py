"""A meshed box sliding on a plane with viscous friction per contact point.

A box (0.2 x 0.12 x 0.08 m, m = 1 kg, /RBODY mass and inertia given, its
centre of mass on the bottom face: the friction at the base has no moment
about it, so the box does not pitch and the shares stay 1/4), its
contact surface a /SURF/SEG of its six faces (the eight nodes are the
contact points), on a fixed /SURF/PLANE floor, TYPE6 with a linear load
curve k = 1e6 N/m, normal damping ratio 0.7; /FRICTION Ifric 0 (Coulomb
mu = 0.3) in the viscous formulation (Iform 1, VISF = 1e-6), no /SOLVER
card. Launched along x at V0 = 3 m/s. Each node's force is -C_j v_t up to
its limit, C_j = w_j C, C = sqrt(2 VISF k m) (docs/theory.md 2.7): the
shares add up to one, so the box feels min(C v, mu m g) against its
motion. Reference (closed form):
  - saturated while C v > mu m g: v = V0 - mu g t, until v_s = mu m g / C
    at t_s = (V0 - v_s) / (mu g);
  - then viscous: v = v_s exp(-C (t - t_s) / m);
  x(t) the integral of v.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

A, B, C_ = 0.2, 0.12, 0.08
M, K, ZETA, MU, G, VISF, V0 = 1.0, 1.0e6, 0.7, 0.3, 9.81, 1.0e-6, 3.0
CV = math.sqrt(2.0 * VISF * K * M)  # the interface's viscous coefficient [N s/m]


def deck(tend=1.5, dtout=0.005):
    p0 = M * G / K  # F = k P, P the deepest node's penetration
    d = Deck("meshed box sliding on a plane, viscous friction per node")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    corners = [(-A / 2, -B / 2, 0), (A / 2, -B / 2, 0), (A / 2, B / 2, 0), (-A / 2, B / 2, 0),
               (-A / 2, -B / 2, C_), (A / 2, -B / 2, C_), (A / 2, B / 2, C_), (-A / 2, B / 2, C_)]
    d.nodes([(1, 0.0, 0.0, -p0)] + [(10 + j, x, y, z - p0) for j, (x, y, z) in enumerate(corners)])
    d.grnod(7, list(range(10, 18)), title="box nodes")
    J = (M * (B * B + C_ * C_) / 12, M * (A * A + C_ * C_) / 12, M * (A * A + B * B) / 12)
    d.rbody(1, 1, M, J, grnod=7, title="box")
    faces = [(10, 13, 12, 11), (14, 15, 16, 17), (10, 11, 15, 14), (11, 12, 16, 15), (12, 13, 17, 16), (13, 10, 14, 17)]
    d.add("/SURF/SEG/30", *[line(*[("i", v) for v in (k + 1,) + f]) for k, f in enumerate(faces)], title="box faces")
    d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), title="box on the floor")
    d.friction(1, ifric=0, iform=1, fric=MU, visf=VISF, title="Coulomb 0.3, viscous formulation, VISF 1e-6")
    d.inivel(1, (V0, 0.0, 0.0), 7)
    d.grav(1, "Z", -G)
    d.run(tend, dtout)
    return d


def reference(t):
    vs = MU * M * G / CV
    ts = (V0 - vs) / (MU * G)
    v = np.where(t < ts, V0 - MU * G * t, vs * np.exp(-CV * (t - ts) / M))
    xs = V0 * ts - 0.5 * MU * G * ts * ts
    x = np.where(t < ts, V0 * t - 0.5 * MU * G * t * t, xs + vs * M / CV * (1 - np.exp(-CV * (t - ts) / M)))
    return x, v, ts, vs


def main():
    r = rcval.Result(rcval.run_case())
    x = r.pos[:, 0, 0] - r.pos[0, 0, 0]
    v = r.vel[:, 0, 0]
    xr, vr, ts, vs = reference(r.t)
    ev = float(np.max(np.abs(v - vr))) / V0
    ex = float(np.max(np.abs(x - xr))) / float(np.max(np.abs(xr)))
    rcval.check("seg_box_viscous.velocity", ev < 1e-7,
                f"C = sqrt(2 VISF k m) = {CV:.6g} N s/m; saturated until v_s = mu m g / C = {vs:.6f} m/s at t_s = "
                f"{ts:.6f} s, then v_s exp(-C (t - t_s) / m): max |v - v_ref| / V0 over {len(r.t)} records = {ev:.1e} "
                f"(< 1e-7); v at {r.t[-1]:g} s = {v[-1]:.6f} m/s, reference {vr[-1]:.6f}")
    rcval.check("seg_box_viscous.position", ex < 1e-7,
                f"max |x - x_ref| / x_ref(end) = {ex:.1e} (< 1e-7); x at {r.t[-1]:g} s = {x[-1]:.6f} m, reference "
                f"{xr[-1]:.6f} m")
    # the friction force: mu F_n while saturated, C v after (the point forces add up)
    ft = np.linalg.norm(r.ffric[:, 0], axis=1)
    sat = r.t < ts - 0.02
    late = r.t > ts + 0.05
    e1 = float(np.max(np.abs(ft[sat] / r.fn[sat, 0] - MU)))
    e2 = float(np.max(np.abs(ft[late] - CV * np.abs(v[late])))) / (MU * M * G)
    rcval.check("seg_box_viscous.force", e1 < 1e-9 and e2 < 1e-9,
                f"|F_t| / F_n - mu while saturated (t < t_s - 0.02 s): max {e1:.1e} (< 1e-9); |F_t| - C |v| after "
                f"(t > t_s + 0.05 s): max {e2:.1e} of mu m g (< 1e-9)")
    rcval.check_ledger("seg_box_viscous.ledger", r, 1e-5)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
