"""Double pendulum of two rigid bodies on two revolute joints: energy over many periods, trajectory against SciPy.

Body 1 hangs on a /JOINT/REVOLUTE (axis z) to the ground at the origin; body
2 hangs on a /JOINT/REVOLUTE to body 1 at the end of its link; gravity -g
along y; released from rest at theta1 = 60, theta2 = -30 degrees from the
downward vertical. The reference is Lagrange's equations of the two angles
(README.md), written here and solved with SciPy (DOP853, rtol 1e-12):
trajectory over the first seconds, then conservation of the total energy,
the constraint residuals and the work of the reactions over 30 s (about 15
periods of the slow mode).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

G = 9.81
M1, I1, C1, L1 = 2.0, 0.1, 0.5, 1.0     # body 1: mass, inertia about its centre (z), centre and link length
M2, I2, C2 = 1.0, 0.05, 0.4             # body 2: mass, inertia, centre from the second joint
TH1, TH2 = math.radians(60.0), math.radians(-30.0)
T_END, T_CMP = 30.0, 3.0


def positions(th1, th2):
    c1 = np.array([C1 * math.sin(th1), -C1 * math.cos(th1)])
    j2 = np.array([L1 * math.sin(th1), -L1 * math.cos(th1)])
    c2 = j2 + np.array([C2 * math.sin(th2), -C2 * math.cos(th2)])
    return c1, j2, c2


def deck():
    c1, j2, c2 = positions(TH1, TH2)
    d = Deck("double pendulum, two revolute joints")
    d.nodes([(1, c1[0], c1[1], 0.0), (2, c2[0], c2[1], 0.0)])
    d.rbody(1, 1, M1, [I1, I1, I1], title="upper body")
    d.rbody(2, 2, M2, [I2, I2, I2], title="lower body")
    d.grav(1, "Y", -G)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), title="pivot")
    d.joint(2, "REVOLUTE", 2, 1, (j2[0], j2[1], 0.0), axis=(0.0, 0.0, 1.0), title="elbow")
    d.run(T_END, 0.01)
    return d


def reference(t):
    """theta1, theta2 at times t from Lagrange's equations."""
    A, B, C = M1 * C1**2 + I1 + M2 * L1**2, M2 * L1 * C2, M2 * C2**2 + I2
    P1, P2 = (M1 * C1 + M2 * L1) * G, M2 * C2 * G

    def f(_, s):
        a, b, wa, wb = s
        dl = a - b
        mat = np.array([[A, B * math.cos(dl)], [B * math.cos(dl), C]])
        rhs = np.array([-B * math.sin(dl) * wb**2 - P1 * math.sin(a), B * math.sin(dl) * wa**2 - P2 * math.sin(b)])
        acc = np.linalg.solve(mat, rhs)
        return [wa, wb, acc[0], acc[1]]

    sol = solve_ivp(f, (0.0, t[-1]), [TH1, TH2, 0.0, 0.0], method="DOP853", t_eval=t, rtol=1e-12, atol=1e-14)
    return sol.y[0], sol.y[1]


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    x1, x2 = r.pos[:, 0, :], r.pos[:, 1, :]
    th1 = np.arctan2(x1[:, 0], -x1[:, 1])
    j2 = x1[:, :2] * (L1 / C1)
    th2 = np.arctan2(x2[:, 0] - j2[:, 0], -(x2[:, 1] - j2[:, 1]))
    sel = r.t <= T_CMP
    a, b = reference(r.t[sel])
    wrap = lambda d: np.abs((d + np.pi) % (2 * np.pi) - np.pi)  # noqa: E731
    err = max(np.max(wrap(th1[sel] - a)), np.max(wrap(th2[sel] - b)))
    rcval.check("joint_double_pendulum.trajectory", err < 1e-6,
                f"theta1, theta2 against Lagrange's equations (SciPy DOP853) over {T_CMP:g} s: max error {err:.2e} rad "
                f"(< 1e-6)")
    e = r.energy["energy_total"]
    scale = (M1 * C1 + M2 * (L1 + C2)) * G
    res = np.max(np.abs(e - e[0])) / scale
    rcval.check("joint_double_pendulum.energy", res < 1e-6,
                f"max |E_total - E_total(0)| over {T_END:g} s = {res:.2e} of the energy scale "
                f"(m1 c1 + m2 (l1 + c2)) g = {scale:.3f} J (< 1e-6)")
    with Dataset(path) as nc:
        dpos = np.array(nc["joint_drift_position"][:])
        dang = np.array(nc["joint_drift_angle"][:])
        work = np.array(nc["joint_work"][:])
    rcval.check("joint_double_pendulum.drift", np.max(dpos) < 1e-9 and np.max(dang) < 1e-9,
                f"max position residual {np.max(dpos):.2e} m, axis residual {np.max(dang):.2e} (< 1e-9)")
    rcval.check("joint_double_pendulum.no_work", np.max(np.abs(work)) < 1e-6 * scale,
                f"work of the reactions: max |W| = {np.max(np.abs(work)):.2e} J (< 1e-6 of the energy scale)")
    plane = max(np.max(np.abs(x1[:, 2])), np.max(np.abs(x2[:, 2])))
    rcval.check("joint_double_pendulum.plane", plane < 1e-12, f"max |z| {plane:.2e} m (< 1e-12)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
