"""A conical pendulum on /JOINT/DISTANCE and a welded compound pendulum on /JOINT/FIXED.

1. A body (no rotation) hangs on a /JOINT/DISTANCE of length L from a point
   of the ground and is launched on the horizontal circle of the conical
   pendulum at angle alpha from the vertical, with the exact speed
   v = sin(alpha) sqrt(g L / cos(alpha)) (README.md): it keeps its height
   and goes round in 2 pi sqrt(L cos(alpha) / g).
2. Two bodies welded by a /JOINT/FIXED swing on a /JOINT/REVOLUTE from 90
   degrees: one rigid compound pendulum, whose period is
   4 sqrt(I_p / (M g d)) K(sin 45 deg), I_p the moment of inertia of the pair
   about the pivot, M its mass, d the distance of its centre of mass.
"""
import math
import os
import sys

import numpy as np
from scipy.special import ellipk

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

G = 9.81
# conical pendulum
L, ALPHA, MC = 0.8, math.radians(35.0), 0.7
W_CONE = math.sqrt(G / (L * math.cos(ALPHA)))
T_CONE = 2 * math.pi / W_CONE
# welded pair: body 1 at d1 along the arm, body 2 at d2, both on the arm's line
M1, I1, D1 = 1.0, 0.01, 0.4
M2, I2, D2 = 0.5, 0.02, 0.9
TH0 = math.radians(90.0)
M = M1 + M2
D = (M1 * D1 + M2 * D2) / M
IP = I1 + M1 * D1**2 + I2 + M2 * D2**2
T_WELD = 4.0 * math.sqrt(IP / (M * G * D)) * ellipk(math.sin(TH0 / 2) ** 2)


def cone_deck():
    r = L * math.sin(ALPHA)
    p = (r, -L * math.cos(ALPHA), 0.0)          # pivot at the origin, gravity -y
    v = W_CONE * r                                # tangential, along -z at (r, ., 0) for a turn about +y
    d = Deck("conical pendulum on a distance joint")
    d.nodes([(1,) + p])
    d.rbody(1, 1, MC, [1e-3, 1e-3, 1e-3], title="bob")
    d.grnod(1, [1], title="bob")
    d.inivel(1, (0.0, 0.0, -v), 1)
    d.grav(1, "Y", -G)
    d.joint(1, "DISTANCE", 1, 0, p, p2=(0.0, 0.0, 0.0), title="rod of length L")
    d.run(3 * T_CONE, T_CONE / 200)
    return d


def weld_deck():
    e = (math.sin(TH0), -math.cos(TH0), 0.0)
    d = Deck("welded compound pendulum")
    d.nodes([(1, D1 * e[0], D1 * e[1], 0.0), (2, D2 * e[0], D2 * e[1], 0.0)])
    d.rbody(1, 1, M1, [I1, I1, I1], title="arm")
    d.rbody(2, 2, M2, [I2, I2, I2], title="weight")
    d.grav(1, "Y", -G)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), title="pivot")
    d.joint(2, "FIXED", 2, 1, (0.65 * e[0], 0.65 * e[1], 0.0), title="weld")
    d.run(4 * T_WELD, T_WELD / 400)
    return d


def main():
    # 1. conical pendulum
    path = rcval.run_case()
    r = rcval.Result(path)
    x = r.pos[:, 0, :]
    h = np.max(np.abs(x[:, 1] + L * math.cos(ALPHA)))
    rcval.check("joint_distance_fixed.cone_height", h < 1e-8 * L,
                f"height of the conical pendulum constant to {h:.2e} m (< 1e-8 L) over 3 turns")
    per = np.diff(rcval.down_crossings(r.t, x[:, 0]))
    err = np.max(np.abs(per - T_CONE)) / T_CONE
    rcval.check("joint_distance_fixed.cone_period", len(per) >= 2 and err < 1e-8,
                f"turns {', '.join(f'{p:.9f}' for p in per)} s; exact 2 pi sqrt(L cos(alpha) / g) = {T_CONE:.9f} s; "
                f"max rel. error {err:.2e} (< 1e-8)")
    with Dataset(path) as nc:
        dpos = np.array(nc["joint_drift_position"][:])
        f = np.array(nc["joint_force"][:])[:, 0, :]
    tension = MC * G / math.cos(ALPHA)   # the rod's tension on the bob
    ferr = np.max(np.abs(np.linalg.norm(f, axis=1) - tension)) / tension
    rcval.check("joint_distance_fixed.cone_tension", ferr < 1e-6 and np.max(dpos) < 1e-9,
                f"rod force {np.mean(np.linalg.norm(f, axis=1)):.9f} N against m g / cos(alpha) = {tension:.9f} N: "
                f"max rel. error {ferr:.2e} (< 1e-6); max drift {np.max(dpos):.2e} m (< 1e-9)")
    # 2. welded pair
    path2 = rcval.run(weld_deck(), name="weld")
    r2 = rcval.Result(path2)
    x1, x2 = r2.pos[:, 0, :], r2.pos[:, 1, :]
    per2 = np.diff(rcval.down_crossings(r2.t, x1[:, 0]))
    err2 = np.max(np.abs(per2 - T_WELD)) / T_WELD
    rcval.check("joint_distance_fixed.weld_period", len(per2) >= 3 and err2 < 1e-8,
                f"periods {', '.join(f'{p:.9f}' for p in per2)} s; exact 4 sqrt(I_p / (M g d)) K(sin 45 deg) = "
                f"{T_WELD:.9f} s; max rel. error {err2:.2e} (< 1e-8)")
    # the weld: the pair keeps its shape and relative orientation
    with Dataset(path2) as nc:
        q = np.array(nc["body_quaternion"][:])
    q1, q2 = q[:, 0, :], q[:, 1, :]
    dq = np.max(np.abs(np.abs(np.sum(q1 * q2, axis=1)) / (np.linalg.norm(q1, axis=1) * np.linalg.norm(q2, axis=1)) - 1))
    sep = np.max(np.abs(np.linalg.norm(x2 - x1, axis=1) - (D2 - D1)))
    rcval.check("joint_distance_fixed.weld_rigid", sep < 1e-9 and dq < 1e-12,
                f"distance between the centres constant to {sep:.2e} m (< 1e-9), relative rotation "
                f"1 - |q1.q2| = {dq:.2e} (< 1e-12)")
    e = r2.energy["energy_total"]
    res = np.max(np.abs(e - e[0])) / (M * G * D)
    rcval.check("joint_distance_fixed.weld_energy", res < 1e-6, f"max |E_total - E_total(0)| / (M g d) = {res:.2e} (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cone_deck)
