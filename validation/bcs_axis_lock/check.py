"""A partial rotation lock (/BCS Trarot "111 110"): a body turning about the global Z axis only.

A body (main node at the origin, principal inertia Jx, Jy, Jz along the
global axes) has its translations and its rotations about X and Y held;
a spring element (/SPRING, /PROP/TYPE4) joins its node P = (R, 0, h) to a
ground node F = (R, L, h) (in no body, held by /BCS 111 111), the spring
at rest at its initial length L. It starts spinning with the angular
velocity (0.3, -0.2, 2.0) rad/s (/INIVEL/ROT): the held components start at
rest, so it turns about Z at 2 rad/s, a nonlinear torsional pendulum:

  Jz theta'' = tau_z(theta),  tau_z = (P(theta) x f)_z,
  P(theta) = (R cos theta, R sin theta, h),
  f = K (|F - P| - L) (F - P)/|F - P|

against a SciPy solve (rtol 1e-12). The spring's force has moments about X
and Y too (h != 0): the lock takes them, the body stays a rotation about Z
(quaternion x, y components zero) with zero angular velocity about X and
Y. Checks the angle history, the axis, and the error shrinking with rtol
(README.md).
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

M, JX, JY, JZ = 1.9, 0.4, 0.7, 0.25
R, H, L, K = 0.5, 0.3, 0.4, 50.0
W0 = (0.3, -0.2, 2.0)
T_END = 3.0


def tau_z(th):
    p = np.array([R * math.cos(th), R * math.sin(th), H])
    d = np.array([R, L, H]) - p
    dist = np.linalg.norm(d)
    f = K * (dist - L) * d / dist
    return p[0] * f[1] - p[1] * f[0]


def reference(t):
    sol = solve_ivp(lambda s, y: [y[1], tau_z(y[0]) / JZ], (0.0, T_END), [0.0, W0[2]], t_eval=t,
                    rtol=1e-12, atol=1e-14, method="DOP853")
    return sol.y[0]


def deck(rtol=1e-9):
    d = Deck("a body turning about Z only (/BCS 111 110) on a spring element")
    d.nodes([(1, 0.0, 0.0, 0.0), (2, R, 0.0, H), (9, R, L, H)])
    d.grnod(1, [1], title="body")
    d.grnod(2, [2], title="spring end on the body")
    d.grnod(9, [9], title="ground node")
    d.rbody(1, 1, M, [JX, JY, JZ], grnod=2, title="body")
    d.bcs(1, 1, trarot="111 110", title="turns about Z only")
    d.bcs(2, 9, trarot="111 111", title="ground")
    d.inivel(1, W0, 1, rot=True)
    d.add("/PART/7", line(("i", 3), ("i", 0)), title="spring")
    d.add("/PROP/TYPE4/3", "#               Mass                                 sens_ID    Isflag     Ileng",
          line(("r", 0.0)) + " " * 30 + i10(0) + i10(0) + i10(0),
          "#                  K                   C", line(("r", K), ("r", 0.0)), title="K = 50 N/m")
    d.add("/SPRING/7", line(("i", 71), ("i", 9), ("i", 2)))
    d.run(T_END, T_END / 300)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_quat=1e-2 * rtol, atol_vel=rtol, atol_omega=rtol,
             atol_energy=1e-2 * rtol)
    return d


def errors(path):
    r = rcval.Result(path)
    q = r.quat[:, 0, :]
    th = np.unwrap(2.0 * np.arctan2(q[:, 3], q[:, 0]))
    err = float(np.max(np.abs(th - reference(r.t))))
    axis = float(np.max(np.abs(q[:, 1:3])))
    return r, err, axis


def main():
    r, err, axis = errors(rcval.run_case())
    rcval.check("bcs_axis_lock.angle", err < 1e-6,
                f"max |theta - theta_SciPy| = {err:.2e} rad over {len(r.t)} outputs, {T_END} s (< 1e-6)")
    with Dataset(r.path) as nc:
        w = np.array(nc["body_angular_velocity"][:])[:, 0, :]  # body frame = global about Z
    wxy = float(np.max(np.abs(w[:, :2])))
    wz0 = float(w[0, 2])
    rcval.check("bcs_axis_lock.axis", axis < 1e-12 and wxy == 0.0 and wz0 == W0[2],
                f"a rotation about Z only: max |q_x|, |q_y| = {axis:.1e} (< 1e-12), "
                f"max |omega_x|, |omega_y| = {wxy:.1e} rad/s (0: held), omega_z(0) = {wz0} rad/s (the /INIVEL's)")
    errs = [errors(rcval.run(deck(rtol), keep_solver=True))[1] for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("bcs_axis_lock.convergence", errs[2] < errs[1] < errs[0],
                "max angle error at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
