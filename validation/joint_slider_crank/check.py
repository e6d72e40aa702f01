"""Slider-crank (revolute, two spherical joints, prismatic) against its closed-form kinematics.

A crank turns on a /JOINT/REVOLUTE about z at the origin; a connecting rod
joins the crank pin and the slider pin by /JOINT/SPHERICAL at both ends; the
slider moves along x on a /JOINT/PRISMATIC. Released from rest under gravity
-g along y, the crank swings. Whatever the motion, the slider position and
speed are fixed by the crank angle (README.md):
x = r cos(phi) + sqrt(l^2 - r^2 sin^2(phi)), and its derivative.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

G, R, L = 9.81, 0.2, 0.6         # gravity, crank radius, rod length
MC, MR, MS = 1.0, 0.5, 0.8       # masses of crank, rod, slider
PHI0 = math.radians(60.0)
T_END = 4.0


def slider_x(phi):
    return R * np.cos(phi) + np.sqrt(L**2 - (R * np.sin(phi)) ** 2)


def deck():
    p = (R * math.cos(PHI0), R * math.sin(PHI0))
    s = (float(slider_x(PHI0)), 0.0)
    d = Deck("slider-crank")
    d.nodes([(1, p[0] / 2, p[1] / 2, 0.0), (2, (p[0] + s[0]) / 2, (p[1] + s[1]) / 2, 0.0), (3, s[0], s[1], 0.0)])
    d.rbody(1, 1, MC, [2e-3, 2e-3, 4e-3], title="crank")
    d.rbody(2, 2, MR, [1.5e-2, 1.5e-2, 1.5e-2], title="connecting rod")
    d.rbody(3, 3, MS, [1e-3, 1e-3, 1e-3], title="slider")
    d.grav(1, "Y", -G)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), title="crank bearing")
    d.joint(2, "SPHERICAL", 2, 1, (p[0], p[1], 0.0), title="crank pin")
    d.joint(3, "SPHERICAL", 2, 3, (s[0], s[1], 0.0), title="wrist pin")
    d.joint(4, "PRISMATIC", 3, 0, (s[0], s[1], 0.0), axis=(1.0, 0.0, 0.0), title="slide along x")
    d.run(T_END, 0.005)
    return d


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    crank, slider = r.pos[:, 0, :], r.pos[:, 2, :]
    phi = np.arctan2(crank[:, 1], crank[:, 0])
    with Dataset(path) as nc:
        w = np.array(nc["body_angular_velocity"][:])[:, 0, 2]   # crank, body z = global z (planar)
        dpos = np.array(nc["joint_drift_position"][:])
        dang = np.array(nc["joint_drift_angle"][:])
        work = np.array(nc["joint_work"][:])
    swing = np.ptp(np.unwrap(phi))
    xerr = np.max(np.abs(slider[:, 0] - slider_x(phi)))
    rcval.check("joint_slider_crank.position", xerr < 1e-9 and swing > 1.0,
                f"slider x against r cos(phi) + sqrt(l^2 - r^2 sin^2 phi) over a crank swing of "
                f"{math.degrees(swing):.1f} deg: max error {xerr:.2e} m (< 1e-9)")
    root = np.sqrt(L**2 - (R * np.sin(phi)) ** 2)
    vref = -R * np.sin(phi) * w - R**2 * np.sin(phi) * np.cos(phi) * w / root
    verr = np.max(np.abs(r.vel[:, 2, 0] - vref)) / max(np.max(np.abs(vref)), 1e-12)
    rcval.check("joint_slider_crank.speed", verr < 1e-7,
                f"slider speed against the derivative of the closed form: max error {verr:.2e} of the peak "
                f"{np.max(np.abs(vref)):.4f} m/s (< 1e-7)")
    off = max(np.max(np.abs(slider[:, 1])), np.max(np.abs(slider[:, 2])), np.max(np.abs(r.pos[:, :, 2])))
    rcval.check("joint_slider_crank.guide", off < 1e-9, f"slider off its line, bodies off the plane: {off:.2e} m (< 1e-9)")
    e = r.energy["energy_total"]
    scale = (MC + MR + MS) * G * R
    res = np.max(np.abs(e - e[0])) / scale
    rcval.check("joint_slider_crank.energy", res < 1e-6 and np.max(np.abs(work)) < 1e-6 * scale,
                f"max |E_total - E_total(0)| = {res:.2e} of (m_c + m_r + m_s) g r (< 1e-6); work of the reactions "
                f"{np.max(np.abs(work)):.2e} J")
    rcval.check("joint_slider_crank.drift", np.max(dpos) < 1e-9 and np.max(dang) < 1e-9,
                f"max position residual {np.max(dpos):.2e} m, angle residual {np.max(dang):.2e} (< 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
