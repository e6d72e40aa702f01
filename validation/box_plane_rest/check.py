"""Analytic boxes (/SURF/BOX) dropped on a plane: the box's 8 corners are the
contact points (docs/theory.md 2.7, "Boxes against a plane or a box").

Four rigid boxes a x b x c, mass M, inertia of a homogeneous box, on the
fixed plane z = 0 (/SURF/PLANE), each through its own interface:
  1. TYPE6, box first on the card (surf_ID1 = box), dropped level;
  2. TYPE6, plane first on the card (the same box, the pair reordered);
  3. TYPE6, the box tilted (0.04 rad about x, then -0.025 rad about y;
     its axes on the card), its lowest corner first;
  4. /INTER/POWER F = K P^m1, box first, dropped level.
Each starts at rest, its lowest corner h0 above the plane; g = 9.81 m/s^2.

References (closed forms, README.md):
  - first contact at t1 = sqrt(2 h0 / g) (free fall of the lowest corner,
    whose height the check computes from the tilt);
  - at rest the interface force is M g, at the interface penetration
    P = M g / k (TYPE6, linear load curve), P = (M g / K)^(1 / m1) (POWER);
  - the box rests level: its four bottom corners at equal depths, and the
    sharing rule f_j = F p_j / sum p gives four equal forces M g / 4 (the
    corner depths from the output pose);
  - the energy ledger (total energy) stays constant.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import quad

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxrest  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, K, ZETA = 9.81, 1.0e6, 0.7
A, B, C, M = 0.2, 0.12, 0.08, 15.0       # box sizes [m], mass [kg]
KP, M1, CP = 1.0e9, 1.5, 5.0e8           # power law K [N/m^1.5], m1, damping C [N s/m^2] (m2 = m3 = 1)
H0 = 0.005                               # lowest corner above the plane at t = 0 [m]
TILT = (0.04, -0.025)                    # box 3: about x, then about y [rad]
T_END = 0.5
JD = (M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12)
CORNERS = [(sx * A / 2, sy * B / 2, sz * C / 2) for sz in (-1, 1) for sy in (-1, 1) for sx in (-1, 1)]


def rotation(tilt):
    ax, ay = tilt
    rx = np.array([[1, 0, 0], [0, math.cos(ax), -math.sin(ax)], [0, math.sin(ax), math.cos(ax)]])
    ry = np.array([[math.cos(ay), 0, math.sin(ay)], [0, 1, 0], [-math.sin(ay), 0, math.cos(ay)]])
    return ry @ rx


def centre_height(R):
    """Height of the centre that puts the lowest corner at H0."""
    return H0 - min((R @ np.array(v))[2] for v in CORNERS)


def deck():
    d = Deck("analytic boxes dropped on a plane (corners as contact points)")
    R3 = rotation(TILT)
    xs = (0.0, 1.0, 2.0, 3.0)
    Rs = (np.eye(3), np.eye(3), R3, np.eye(3))
    d.nodes([(b + 1, xs[b], 0.0, centre_height(Rs[b])) for b in range(4)])
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.plane(10, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    for b in range(4):
        J = Rs[b] @ np.diag(JD) @ Rs[b].T
        d.grnod(b + 1, [b + 1], title=f"box {b + 1}")
        d.rbody(b + 1, b + 1, M, (J[0, 0], J[1, 1], J[2, 2]), Joff=(J[0, 1], J[1, 2], J[0, 2]), grnod=b + 1,
                title=f"box {b + 1}")
        c = (xs[b], 0.0, centre_height(Rs[b]))
        if b == 2:
            d.box(11 + b, b + 1, c, (A / 2, B / 2, C / 2), u=tuple(Rs[b][:, 0]), v=tuple(Rs[b][:, 1]),
                  title="box 3, tilted")
        else:
            d.box(11 + b, b + 1, c, (A / 2, B / 2, C / 2), title=f"box {b + 1}")
    visc = 2 * ZETA * math.sqrt(K * M)
    d.type6(1, 11, 10, 1, visc=visc, title="box 1 on the floor (box first)")
    d.type6(2, 10, 12, 1, visc=visc, title="box 2 on the floor (plane first)")
    d.type6(3, 13, 10, 1, visc=visc, title="box 3, tilted, on the floor")
    d.power(4, 14, 10, k=KP, m1=M1, c=CP, m2=1.0, m3=1.0, irdf=2, title="box 4 on the floor, power law")
    d.grav(1, "Z", -G)
    d.run(T_END, 0.01)
    return d


KP2, TH0 = 1.0e8, 0.3                    # pivot: contact stiffness [N/m], initial tilt [rad]


def deck_pivot():
    """A box standing on its +x bottom edge, tilted by TH0 about y, released
    at rest on a frictionless plane (stiff contact): it falls back flat."""
    d = Deck("analytic box falling back from its edge, frictionless plane")
    R = np.array([[math.cos(TH0), 0, math.sin(TH0)], [0, 1, 0], [-math.sin(TH0), 0, math.cos(TH0)]])
    # the edge's penetration at t = 0: the normal force of the released box,
    # m (g + z''(0)), z'' = z' th'' with th'' = -m g z' / (m z'^2 + J_yy)
    dz0 = A / 2 * math.cos(TH0) - C / 2 * math.sin(TH0)
    p0 = M * (G - dz0 * M * G * dz0 / (M * dz0 * dz0 + JD[1])) / KP2
    zc = A / 2 * math.sin(TH0) + C / 2 * math.cos(TH0) - p0
    J = R @ np.diag(JD) @ R.T
    d.nodes([(1, 0.0, 0.0, zc)])
    d.grnod(1, [1], title="box")
    d.rbody(1, 1, M, (J[0, 0], J[1, 1], J[2, 2]), Joff=(J[0, 1], J[1, 2], J[0, 2]), grnod=1, title="box")
    d.box(11, 1, (0.0, 0.0, zc), (A / 2, B / 2, C / 2), u=tuple(R[:, 0]), v=tuple(R[:, 1]), title="box on its edge")
    d.plane(10, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    d.funct(1, [0.0, 1.0], [0.0, KP2], title="linear k = 1e8 N/m")
    d.type6(1, 11, 10, 1, visc=2 * ZETA * math.sqrt(KP2 * M), title="box on the floor, frictionless")
    d.grav(1, "Z", -G)
    d.run(0.3, 0.001)
    return d


def pivot_reference(th):
    """Rigid box on its edge, frictionless plane: the centre moves only
    vertically, z(th) = a/2 sin th + c/2 cos th, and the energy
    m g (z(TH0) - z(th)) = (m z'(th)^2 + J_yy) th'^2 / 2 gives |th'|."""
    z = lambda t: A / 2 * math.sin(t) + C / 2 * math.cos(t)  # noqa: E731
    dz = A / 2 * math.cos(th) - C / 2 * math.sin(th)
    return math.sqrt(2 * M * G * (z(TH0) - z(th)) / (M * dz * dz + JD[1]))


def check_pivot():
    r, quat, omega = boxrest.load(rcval.run(deck_pivot(), name="pivot"))
    th = TH0 + 2 * np.arctan2(quat[:, 0, 2], quat[:, 0, 0])  # rotation about y from the start
    land = np.where(th <= 0)[0]
    k1 = int(land[0]) if len(land) else len(th)
    # the tilt rate against the closed form while the box turns on its edge
    win = [k for k in range(k1) if 0.02 <= th[k] <= TH0 - 0.02]
    err = max(abs(-omega[k, 0, 1] - pivot_reference(th[k])) / pivot_reference(th[k]) for k in win) if win else float("inf")
    rcval.check("box_plane_rest.pivot.rate", len(win) > 20 and err < 1e-4,
                f"box falling back from its edge (tilt {TH0:g} rad, frictionless, k = {KP2:.0e} N/m): over {len(win)} "
                f"records with the tilt in [0.02, {TH0 - 0.02:g}] rad, max rel. error of |d tilt/dt| against the "
                f"rigid-body energy closed form {err:.2e} (< 1e-4: the penetration m g / k = {M * G / KP2:.1e} m "
                f"against the drop {A / 2 * math.sin(TH0) + C / 2 * math.cos(TH0) - C / 2:.4f} m)")
    # the fall: the tilt reaches TH1 (just before the flat landing, whose
    # impact stops the turn) at T = int_TH1^TH0 dth / |th'(th)|
    TH1 = 0.01
    T = quad(lambda t: 1.0 / pivot_reference(t), TH1, TH0, limit=200)[0]
    below = np.where(th <= TH1)[0]
    k2 = int(below[0]) if len(below) else 0
    tl = r.t[k2 - 1] + (r.t[k2] - r.t[k2 - 1]) * (th[k2 - 1] - TH1) / (th[k2 - 1] - th[k2]) if k2 > 0 else float("nan")
    e = abs(tl - T) / T
    rcval.check("box_plane_rest.pivot.fall_time", e < 1e-4,
                f"tilt {TH1:g} rad at {tl:.7f} s (records every 1 ms, linear interpolation), closed form "
                f"int dth / |th'| from {TH0:g} to {TH1:g} rad = {T:.7f} s (scipy quad), rel. error {e:.2e} (< 1e-4)")
    dx = float(np.max(np.abs(r.pos[:k1, 0, 0] - r.pos[0, 0, 0])))
    rcval.check("box_plane_rest.pivot.no_drift", dx < 1e-9,
                f"frictionless: no horizontal force, the centre's x stays put until the landing: max |dx| = {dx:.1e} m "
                f"(< 1e-9)")


def main():
    r, quat, omega = boxrest.load(rcval.run_case())
    t1 = math.sqrt(2 * H0 / G)
    Rs = (np.eye(3), np.eye(3), rotation(TILT), np.eye(3))
    names = ("box_first", "plane_first", "tilted", "power")
    for b, name in enumerate(names):
        boxrest.check_first_contact(f"box_plane_rest.{name}.first_contact", r, t1, b + 1, after=" (lowest corner)")
        fn = r.fn[-1, b]
        e = rcval.rel(fn, M * G)
        rcval.check(f"box_plane_rest.{name}.force", e < 1e-6,
                    f"normal force at t = {r.t[-1]:g} s: {fn:.9g} N, M g = {M * G:.9g} N, rel. error {e:.2e} (< 1e-6)")
        pref = (M * G / KP) ** (1 / M1) if b == 3 else M * G / K
        p = r.pen[-1, b]
        e = rcval.rel(p, pref)
        rcval.check(f"box_plane_rest.{name}.penetration", e < 5e-5,
                    f"P = {p:.9e} m, {'(M g / K)^(1/m1)' if b == 3 else 'M g / k'} = {pref:.9e} m, rel. error {e:.2e} "
                    f"(< 5e-5: the law's penetration P_e, at which the force is the weight exactly, lies below the deepest corner by what the last rockings left unpaid: theory 2.7)")
        # corner depths from the final pose (body frame = global at t = 0)
        forces = boxrest.corner_forces(fn, r.pos[-1, b], quat[-1, b], [Rs[b] @ np.array(v) for v in CORNERS])
        boxrest.check_corners(f"box_plane_rest.{name}.corners", forces, M, G, mg="M g")
        boxrest.check_rest(f"box_plane_rest.{name}.rest", r.vel[-1, b], omega[-1, b], A, f"at t = {r.t[-1]:g} s")
    rcval.check_ledger("box_plane_rest.ledger", r, 1e-5)
    check_pivot()
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
