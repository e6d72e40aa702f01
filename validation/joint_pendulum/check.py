"""Rigid pendulum on a joint at 150 degrees amplitude against the elliptic-integral period.

A rigid body (mass m, moment of inertia I about its centre of mass) hangs on
a /JOINT/REVOLUTE (axis z) to the ground at distance d from its centre of
mass, under gravity -g along y, released from rest at theta0 = 150 degrees
from the downward vertical. Its angle obeys the pendulum equation with the
equivalent length L = (I + m d^2) / (m d), whose exact period is
T = 4 sqrt(L / g) K(sin(theta0 / 2)) (README.md). Checks the period (every
swing), the constraint residual (drift), the plane of motion, the energy
ledger, the work of the reaction (zero), and the reaction force against the
closed form m a - m g along the exact trajectory; then the same body on a
/JOINT/SPHERICAL (the motion stays in its plane).
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

M, I_CM, D, G = 1.5, 0.02, 1.0, 9.81
TH0 = math.radians(150.0)
IP = I_CM + M * D * D                   # moment of inertia about the pivot
L_EQ = IP / (M * D)                     # equivalent simple-pendulum length
K = math.sin(TH0 / 2.0)
T_EXACT = 4.0 * math.sqrt(L_EQ / G) * ellipk(K * K)   # scipy: parameter m = k^2
T_END = 6.0 * T_EXACT


def deck(kind="REVOLUTE"):
    d = Deck(f"pendulum on a {kind.lower()} joint, 150 degrees")
    d.nodes([(1, D * math.sin(TH0), -D * math.cos(TH0), 0.0)])
    d.rbody(1, 1, M, [I_CM, I_CM, I_CM], title="bob")
    d.grav(1, "Y", -G)
    d.joint(1, kind, 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0) if kind == "REVOLUTE" else None,
            title="pivot at the origin")
    d.run(T_END, T_EXACT / 500)
    return d


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    x = r.pos[:, 0, :]
    periods = np.diff(rcval.down_crossings(r.t, x[:, 0]))
    err = np.max(np.abs(periods - T_EXACT)) / T_EXACT
    rcval.check("joint_pendulum.period", len(periods) >= 5 and err < 1e-8,
                f"{len(periods)} periods {', '.join(f'{p:.9f}' for p in periods)} s; exact "
                f"4 sqrt(L/g) K(sin 75 deg) = {T_EXACT:.9f} s; max rel. error {err:.2e} (< 1e-8)")
    with Dataset(path) as nc:
        dpos = np.array(nc["joint_drift_position"][:])
        dang = np.array(nc["joint_drift_angle"][:])
        force = np.array(nc["joint_force"][:])[:, 0, :]
        work = np.array(nc["joint_work"][:])
        funit = nc["joint_force"].units
    rcval.check("joint_pendulum.drift", np.max(dpos) < 1e-9 and np.max(dang) < 1e-9,
                f"max position residual {np.max(dpos):.2e} m, axis residual {np.max(dang):.2e} (< 1e-9)")
    radius = np.linalg.norm(x, axis=1)
    rcval.check("joint_pendulum.plane", np.max(np.abs(x[:, 2])) < 1e-12 and np.max(np.abs(radius - D)) < 1e-9,
                f"max |z| {np.max(np.abs(x[:, 2])):.2e} m (< 1e-12), max ||x| - d| {np.max(np.abs(radius - D)):.2e} m "
                f"(< 1e-9)")
    e = r.energy["energy_total"]
    scale = M * G * D
    res = np.max(np.abs(e - e[0])) / scale
    rcval.check("joint_pendulum.energy", res < 1e-6,
                f"max |E_total - E_total(0)| / (m g d) = {res:.2e} (< 1e-6)")
    rcval.check("joint_pendulum.no_work", np.max(np.abs(work)) < 1e-6 * scale,
                f"work of the reaction: max |W| = {np.max(np.abs(work)):.2e} J (< 1e-6 m g d: an ideal joint does "
                f"no work)")
    # reaction on the bob: m a - m g, a from the exact theta, theta', theta''
    th = np.arctan2(x[:, 0], -x[:, 1])
    w2 = 2.0 * M * G * D * (np.cos(th) - math.cos(TH0)) / IP
    al = -M * G * D * np.sin(th) / IP
    a = D * al[:, None] * np.stack([np.cos(th), np.sin(th)], 1) + D * w2[:, None] * np.stack([-np.sin(th), np.cos(th)], 1)
    fref = np.zeros_like(force)
    fref[:, :2] = M * a
    fref[:, 1] += M * G
    ferr = np.max(np.abs(force - fref)) / (M * G)
    rcval.check("joint_pendulum.reaction", ferr < 1e-6 and funit == "N",
                f"joint_force [{funit}] against m a - m g on the exact trajectory: max error {ferr:.2e} m g (< 1e-6); "
                f"peak {np.max(np.linalg.norm(force, axis=1)):.4f} N")
    # the same body on a spherical joint
    r2 = rcval.Result(rcval.run(deck("SPHERICAL"), name="spherical"))
    x2 = r2.pos[:, 0, :]
    p2 = np.diff(rcval.down_crossings(r2.t, x2[:, 0]))
    err2 = np.max(np.abs(p2 - T_EXACT)) / T_EXACT
    rcval.check("joint_pendulum.spherical", len(p2) >= 5 and err2 < 1e-6 and np.max(np.abs(x2[:, 2])) < 1e-9,
                f"spherical joint: max rel. period error {err2:.2e} (< 1e-6), max |z| {np.max(np.abs(x2[:, 2])):.2e} m "
                f"(< 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
