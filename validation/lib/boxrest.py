"""Boxes dropped on and resting on a surface, shared by the resting-box
problems (box_plane_rest, seg_box_rest, pw_seg_box_rest, box_box): the
bodies' orientations from the results file, the first contact at the
free-fall time, and the corner forces at rest checked against m g / 4.

The forces of the bottom corners follow the rule F p_j / sum p (the total
normal force F shared by the corners' depths p_j, docs/theory.md 2.7); at
rest on a level surface each of the four carries m g / 4.
"""
from netCDF4 import Dataset
import numpy as np

import rcval


def load(path):
    """The results file's Result, body quaternions (w, x, y, z) and angular
    velocities [rad/s], per record and body."""
    r = rcval.Result(path)
    with Dataset(path) as nc:
        quat = np.array(nc["body_quaternion"][:])
        omega = np.array(nc["body_angular_velocity"][:])
    return r, quat, omega


def check_first_contact(name, r, t1, iface=None, before="", after=""):
    """The first contact_close event (of interface iface, or of any) at the
    free-fall time t1 = sqrt(2 h0 / g) [s], rel. 1e-8; before, after: words
    around the message's times."""
    close = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem)
             if k == "contact_close" and (iface is None or el.endswith(f"/{iface}"))]
    e = rcval.rel(close[0], t1) if close else float("inf")
    rcval.check(name, e < 1e-8,
                f"{before}first contact_close at {close[0] if close else float('nan'):.12g} s, sqrt(2 h0 / g) = "
                f"{t1:.12g} s{after}, rel. error {e:.2e} (< 1e-8)")


def quat_matrix(q):
    """The rotation matrix of the quaternion q = (w, x, y, z), normalised."""
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def corner_forces(fn, pos, quat, corners, depth_of=lambda x: -x[2]):
    """Forces [N] of the corners past the surface by the rule F p_j / sum p:
    corners in the body frame relative to the centre pos [m], the pose from
    the quaternion quat, depth_of(x) the depth of a point x (> 0: past the
    surface; default the floor z = 0)."""
    Q = quat_matrix(quat)
    dep = np.array([depth_of(pos + Q @ np.asarray(v)) for v in corners])
    pen = dep[dep > 0]
    return fn * pen / pen.sum() if len(pen) else pen


def box_corners(half):
    """The eight corners of a box of half sizes half, centre at the origin."""
    return [np.array([sx * half[0], sy * half[1], sz * half[2]]) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]


def check_corners(name, forces, m, g, where="the floor", mg="m g"):
    """Four corners past the surface, each carrying m g / 4 (rel. 1e-5: the
    corner depths differ at the solver's position tolerance)."""
    e = float(np.max(np.abs(forces - m * g / 4)) / (m * g / 4)) if len(forces) == 4 else float("inf")
    rcval.check(name, len(forces) == 4 and e < 1e-5,
                f"{len(forces)} corners past {where} (expected 4), forces {', '.join(f'{f:.9g}' for f in forces)} N, "
                f"{mg} / 4 = {m * g / 4:.9g} N, max rel. error {e:.2e} (< 1e-5)")


def check_rest(name, vel, omega, a, when):
    """At rest: |v| + |omega| a < 1e-6 m/s (a: a length of the box [m])."""
    v = float(np.linalg.norm(vel)) + float(np.linalg.norm(omega)) * a
    rcval.check(name, v < 1e-6, f"|v| + |omega| a = {v:.2e} m/s {when} (< 1e-6: at rest)")
