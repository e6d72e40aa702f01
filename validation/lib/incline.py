"""Geometry shared by the inclined-plane problems (fric_incline, frc_incline).

The plane is tilted by theta about a horizontal axis at azimuth phi, so the
fall line is along no global axis; gravity is -z.
"""
import math

import numpy as np


def frame(tan_th, phi):
    """theta, plane normal n, fall-line direction s (down the slope), in-plane u = n x s."""
    th = math.atan(tan_th)
    n = np.array([math.sin(th) * math.cos(phi), math.sin(th) * math.sin(phi), math.cos(th)])
    s = np.array([math.cos(th) * math.cos(phi), math.cos(th) * math.sin(phi), -math.sin(th)])
    return th, n, s, np.cross(n, s)


def ramp_table(tr, n=501):
    """Quintic smoothstep 0 -> 1 on [0, tr] (f', f'' zero at both ends), then
    a far point at 1 so that the linear extension beyond the table stays flat."""
    t = np.linspace(0.0, tr, n)
    x = t / tr
    return list(t) + [1.0e4], list(x**3 * (10.0 - 15.0 * x + 6.0 * x * x)) + [1.0]


def along(r, tan_th, phi):
    """Positions along s and u relative to the start, velocities along s, u, n."""
    th, n, s, u = frame(tan_th, phi)
    dp = r.pos[:, 0, :] - r.pos[0, 0, :]
    return dp @ s, dp @ u, r.vel[:, 0, :] @ s, r.vel[:, 0, :] @ u, r.vel[:, 0, :] @ n
