"""Rigid walls (/RWALL/PLANE, /RWALL/SPHER, /RWALL/CYL, /RWALL/PARAL) against rigid-body
closed forms (README.md).

A sphere (m = 1 kg, R = 0.05 m, J = 0.4 m R^2: radius of gyration
L = sqrt(0.6) R) meets fixed walls. ricochet models a wall as a penalty
contact of linear stiffness k = m g_ref / (1e-4 L) (g_ref = max(|g|,
9.80665 m/s^2)), so that the body rests 1e-4 L deep in it, with the damping
of a restitution 0.01 (docs/theory.md, "Rigid walls"):

1. dropped from 0.1 m onto /RWALL/PLANE (Slide 0) and onto the top of an
   /RWALL/SPHER: first contact at sqrt(2 h / g); no rebound above e^2 h
   (e = 0.01); at rest with its centre at R - 1e-4 L above the wall;
2. a block (rotations held) launched at v0 on /RWALL/PLANE, Slide 2,
   fric mu: stops after v0^2 / (2 mu g) at v0 / (mu g); Slide 0: keeps v0;
2b. a cube of 8 nodes without any surface (the usual Radioss rigid body):
   the wall's nodes are its contact points; it rests 1e-4 L deep with the
   normal force m g, and slides to rest at v0^2 / (2 mu g) with Slide 2;
2c. a moving /RWALL/PLANE (its node, Mass m_w, VX0 v0) hitting a ball at
   rest: the two-body impact of restitution e, ball m_w v0 (1 + e)/(m_w + m),
   wall (m_w - e m) v0/(m_w + m), momentum conserved, the wall not turning;
3. a ball sliding (Slide 0) over the top of a horizontal /RWALL/CYL of
   radius Rc from the top at v0: it leaves the cylinder where
   cos(theta) = 2/3 + v0^2 / (3 g (Rc + R)) (a particle on a circle).
4. a ball sliding (Slide 0) at v0 on a horizontal /RWALL/PARAL (corners
   (-1, -0.5, 0), M1 (0, -0.5, 0), M2 (-1, 0.5, 0): normal +z, the edge
   x = 0) from x0 = -0.5: flat until its centre reaches the edge at
   -x0 / v0, then it turns about the edge (radius R) and leaves it where
   cos(theta) = 2/3 + v0^2 / (3 g R), at -x0 / v0 + the integral of
   R dtheta / sqrt(v0^2 + 2 g R (1 - cos theta)); then a free flight. Fast
   (v0^2 > g R): it leaves at the edge.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, R, G = 1.0, 0.05, 9.81
J = 0.4 * M * R * R
L = math.sqrt(3 * J / (2 * M))            # radius of gyration sqrt(tr J / (2 m))
PEN = 1e-4 * L * max(G, 9.80665) / G      # rest penetration m g / k [m]
E_WALL = 0.01                             # the wall's restitution
H = 0.1                                   # drop height of the lowest point [m]
MU, V0 = 0.3, 1.0                         # the sliding block
RC, VC = 0.5, 0.5                         # the cylinder's radius, the ball's speed on its top


def rwall(d, kind, wid, grnod, m, m1=None, slide=0, fric=0.0, diameter=0.0, m2=None):
    """/RWALL/<kind>/wid in the Radioss 2022 layout (fixed wall); m2: the third corner of PARAL."""
    lines = [line(("i", 0), ("i", slide), ("i", grnod), ("i", 0)),
             line(("r", 0.0), ("r", fric), ("r", diameter), ("r", 0.0), ("i", 0)),
             line(("r", m[0]), ("r", m[1]), ("r", m[2]))]
    if m1 is not None:
        lines.append(line(("r", m1[0]), ("r", m1[1]), ("r", m1[2])))
    if m2 is not None:
        lines.append(line(("r", m2[0]), ("r", m2[1]), ("r", m2[2])))
    d.add(f"/RWALL/{kind}/{wid}", *lines, title=f"{kind.lower()} wall")


def ball(title, z0, x0=0.0, locked=False, v=None):
    d = Deck(title)
    d.nodes([(1, x0, 0.0, z0)])
    d.rbody(1, 1, M, [J] * 3, grnod=1, title="ball 1 kg")
    d.sphere(1, 1, (x0, 0.0, z0), R)
    d.grnod(1, [1])
    if locked:
        d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    if v is not None:
        d.inivel(1, v, 1)
    d.grav(1, "Z", -G, 1)
    return d


def drop_plane():
    d = ball("ball dropped onto /RWALL/PLANE", R + H)
    rwall(d, "PLANE", 3, 1, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    d.run(1.0, 0.001)
    return d


def drop_sphere():
    d = ball("ball dropped onto the top of /RWALL/SPHER", R + H)
    rwall(d, "SPHER", 4, 1, (0.0, 0.0, -0.5), diameter=1.0)
    d.run(1.0, 0.001)
    return d


def slide(slide_flag):
    d = ball("block sliding on /RWALL/PLANE", R - PEN, locked=True, v=(V0, 0.0, 0.0))
    rwall(d, "PLANE", 5, 1, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), slide=slide_flag, fric=MU if slide_flag == 2 else 0.0)
    d.run(0.5, 0.005)
    return d


def over_cylinder():
    d = ball("ball sliding over /RWALL/CYL", RC + R, v=(VC, 0.0, 0.0))
    rwall(d, "CYL", 6, 1, (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), diameter=2 * RC)
    d.run(0.8, 0.002)
    return d


VP, XP = 0.3, -0.5             # the ball on the parallelogram: speed, start
VPF = 1.0                      # the fast ball: v0^2 > g R


def off_paral(v0):
    d = ball(f"ball sliding off the edge of /RWALL/PARAL at {v0} m/s", R - PEN, x0=XP, v=(v0, 0.0, 0.0))
    rwall(d, "PARAL", 7, 1, (-1.0, -0.5, 0.0), (0.0, -0.5, 0.0), m2=(-1.0, 0.5, 0.0))
    d.run(2.0, 0.002)
    return d


MC, JC, HC = 2.0, 0.0133, 0.1  # the cube of nodes: mass, inertia, half side
LC = math.sqrt(3 * JC / (2 * MC))
PENC = 1e-4 * LC * max(G, 9.80665) / G


def cube(slide_flag, v=None, z0=None):
    """A body of 8 corner nodes and no surface (Radioss's usual rigid body)
    on /RWALL/PLANE z = 0: the wall's nodes are its contact points."""
    z0 = HC + HC if z0 is None else z0
    d = Deck("cube of nodes on /RWALL/PLANE")
    corners = [(11 + k, sx * HC, sy * HC, z0 + sz * HC)
               for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                                (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    d.nodes([(1, 0.0, 0.0, z0)] + corners)
    d.rbody(1, 1, MC, [JC] * 3, grnod=2, title="cube 2 kg")
    d.grnod(2, [n for n, _, _, _ in corners], title="corners")
    if v is not None:
        d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{2:>10d}", title="no rotation")
        d.inivel(1, v, 2)
    d.grav(1, "Z", -G, 2)
    rwall(d, "PLANE", 3, 2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), slide=slide_flag, fric=MU if slide_flag == 2 else 0.0)
    d.run(1.0 if v is None else 0.5, 0.005)
    return d


MW, VW = 3.0, 2.0  # the moving wall's mass and speed


def moving_wall():
    """A moving /RWALL/PLANE (node 9, Mass 3 kg, VX0 2 m/s, normal +x)
    hitting a ball at rest, no gravity."""
    d = Deck("moving wall hitting a ball")
    d.nodes([(1, 0.0, 0.0, 0.0), (9, -0.5, 0.0, 0.0)])
    d.rbody(1, 1, M, [J] * 3, grnod=1, title="ball 1 kg")
    d.sphere(1, 1, (0.0, 0.0, 0.0), R)
    d.grnod(1, [1])
    d.add("/RWALL/PLANE/3", line(("i", 9), ("i", 0), ("i", 1), ("i", 0)), "",
          line(("r", MW), ("r", VW), ("r", 0.0), ("r", 0.0)), line(("r", 1.0), ("r", 0.0), ("r", 0.0)),
          title="moving wall")
    d.run(0.5, 0.005)
    return d


def check_drop(name, r, z_wall):
    t1_ref = math.sqrt(2 * H / G)
    t1 = r.events("contact_close")[0]
    e = rcval.rel(t1, t1_ref)
    rcval.check(f"rwall.{name}.first_contact", e < 1e-6,
                f"first contact_close at {t1:.9f} s, sqrt(2 h/g) = {t1_ref:.9f} s, rel. error {e:.2e} (< 1e-6)")
    z = r.pos[:, 0, 2] - z_wall - R
    after = r.t > t1
    apex = z[after].max()
    rcval.check(f"rwall.{name}.no_rebound", apex <= 1.5 * E_WALL**2 * H,
                f"the ball's lowest point after the impact reaches {apex:.3e} m (< {1.5 * E_WALL**2 * H:.1e}, 1.5 e^2 h: "
                f"the rebound of the wall's restitution e = {E_WALL:g}; a kinematic wall: 0); "
                f"{len(r.events('contact_separate'))} separations")
    pen = -z[-1]
    e = rcval.rel(pen, PEN)
    rcval.check(f"rwall.{name}.rest", e < 1e-3 and np.linalg.norm(r.vel[-1, 0]) < 1e-6,
                f"at rest at t = {r.t[-1]:g} s {pen:.6e} m deep, 1e-4 L m g / (m g_ref) = {PEN:.6e} m "
                f"(1e-4 of the radius of gyration), rel. error {e:.2e} (< 1e-3); |v| {np.linalg.norm(r.vel[-1, 0]):.1e} m/s")


def main():
    # 1. drops: plane, top of a sphere of diameter 1 m centred 0.5 m below
    check_drop("plane", rcval.Result(rcval.run(drop_plane(), "plane")), 0.0)
    check_drop("spher", rcval.Result(rcval.run(drop_sphere(), "spher")), 0.0)

    # 2. sliding block: Slide 2 stops at v0^2/(2 mu g); Slide 0 keeps v0
    r = rcval.Result(rcval.run(slide(2), "slide2"))
    t_stop = r.events("fric_stick")[0]
    x = r.pos[r.state_at(t_stop), 0, 0]
    ex, et = rcval.rel(x, V0**2 / (2 * MU * G)), rcval.rel(t_stop, V0 / (MU * G))
    rcval.check("rwall.slide.friction_stop", max(ex, et) < 1e-4,
                f"Slide 2, fric {MU}: stops at x = {x:.9f} m (v0^2/(2 mu g) = {V0**2 / (2 * MU * G):.9f}), "
                f"t = {t_stop:.9f} s (v0/(mu g) = {V0 / (MU * G):.9f}); rel. errors {ex:.1e}, {et:.1e} (< 1e-4)")
    r = rcval.Result(rcval.run(slide(0), "slide0"))
    e = abs(r.vel[-1, 0, 0] - V0) / V0
    rcval.check("rwall.slide.frictionless", e < 1e-9 and len(r.events("fric_slip", "fric_stick")) == 0,
                f"Slide 0: speed after {r.t[-1]:g} s {r.vel[-1, 0, 0]:.12f} m/s (v0 = {V0}), rel. error {e:.1e} "
                f"(< 1e-9), no friction event")

    # 2b. a body of nodes without surface: its nodes touch the wall
    r = rcval.Result(rcval.run(cube(0), "cube"))
    pen = HC - r.pos[-1, 0, 2]
    e, ef = rcval.rel(pen, PENC), rcval.rel(r.fn[-1, 0], MC * G)
    rcval.check("rwall.nodes.rest", e < 1e-3 and ef < 1e-6,
                f"a cube of 8 nodes (no surface) dropped 0.1 m: rests {pen:.6e} m deep (1e-4 L = {PENC:.6e} m, "
                f"rel. error {e:.2e} (< 1e-3)); normal force {r.fn[-1, 0]:.9f} N (m g = {MC * G:.9f} N, "
                f"{ef:.1e}, < 1e-6)")
    r = rcval.Result(rcval.run(cube(2, v=(V0, 0.0, 0.0), z0=HC - PENC), "cube_slide"))
    x_end = r.pos[-1, 0, 0]
    e = abs(x_end - V0**2 / (2 * MU * G)) / (V0**2 / (2 * MU * G))
    rcval.check("rwall.nodes.friction_stop", e < 1e-4,
                f"the cube launched at {V0} m/s on its 4 bottom nodes, Slide 2, fric {MU}: at rest at x = {x_end:.9f} m "
                f"(v0^2/(2 mu g) = {V0**2 / (2 * MU * G):.9f}, per-node friction, F_lim/K_t creep), "
                f"rel. error {e:.2e} (< 1e-4)")

    # 2c. a moving wall: an impact of restitution e between the wall and the
    # ball (the two-body closed form), momentum conserved, the wall turning
    # not at all
    r = rcval.Result(rcval.run(moving_wall(), "moving"))
    vb_ref = MW * VW * (1 + E_WALL) / (MW + M)
    vw_ref = (MW * VW - M * E_WALL * VW) / (MW + M)
    t1 = r.events("contact_close")[0]
    t1_ref = (0.5 - R) / VW
    e = max(rcval.rel(r.vel[-1, 0, 0], vb_ref), rcval.rel(r.vel[-1, 1, 0], vw_ref), rcval.rel(t1, t1_ref))
    p = M * r.vel[-1, 0] + MW * r.vel[-1, 1]
    ep = np.linalg.norm(p - [MW * VW, 0.0, 0.0]) / (MW * VW)
    rot = np.abs(r.quat[:, 1, 1:]).max()
    rcval.check("rwall.moving.impact", e < 1e-6 and ep < 1e-12 and rot == 0.0,
                f"wall {MW} kg at {VW} m/s onto a {M} kg ball: contact at {t1:.9f} s ((0.45 m)/v0 = {t1_ref:.9f}); "
                f"after: ball {r.vel[-1, 0, 0]:.9f} m/s (m_w v0 (1 + e)/(m_w + m) = {vb_ref:.9f}), wall "
                f"{r.vel[-1, 1, 0]:.9f} m/s ({vw_ref:.9f}); max rel. error {e:.2e} (< 1e-6); momentum to {ep:.1e} "
                f"(< 1e-12); the wall does not turn (quaternion vector part {rot:.1e})")

    # 3. over the top of a cylinder: leaves at cos = 2/3 + v0^2/(3 g rho)
    r = rcval.Result(rcval.run(over_cylinder(), "cyl"))
    t_off = r.contact_ends()[0]
    p = r.pos[r.state_at(t_off), 0]
    cos_sim = p[2] / math.hypot(p[0], p[2])
    rho = RC + R
    cos_ref = 2.0 / 3.0 + VC**2 / (3 * G * rho)
    e = abs(cos_sim - cos_ref)
    rcval.check("rwall.cyl.leave_angle", e < 1e-3,
                f"leaves the cylinder at cos(theta) = {cos_sim:.7f} (t = {t_off:.6f} s), rigid particle on a circle "
                f"of radius Rc + R: 2/3 + v0^2/(3 g (Rc + R)) = {cos_ref:.7f}; error {e:.1e} (< 1e-3)")
    w = np.abs(r.energy["energy_total"] - r.energy["energy_total"][0]).max() / (M * G * rho)
    rcval.check("rwall.cyl.ledger", w < 1e-6,
                f"max |E_total(t) - E_total(0)| / (m g (Rc + R)) = {w:.1e} (< 1e-6)")

    # 4. off the edge of a parallelogram: flat to the edge, then about the
    # edge as a particle on a circle of radius R, leaving at cos = 2/3 +
    # v0^2/(3 g R); a fast ball leaves at the edge
    r = rcval.Result(rcval.run(off_paral(VP), "paral"))
    t_edge = -XP / VP
    t_off = r.contact_ends()[0]
    p = r.pos[r.state_at(t_off), 0]
    cos_sim = p[2] / math.hypot(p[0], p[2])
    cos_ref = 2.0 / 3.0 + VP**2 / (3 * G * R)
    th = np.linspace(0.0, math.acos(cos_ref), 200001)
    f = R / np.sqrt(VP**2 + 2 * G * R * (1 - np.cos(th)))
    t_ref = t_edge + float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(th)))
    flat = r.t < t_edge
    ez = np.abs(r.pos[flat, 0, 2] - (R - PEN)).max()
    ex = np.abs(r.pos[flat, 0, 0] - (XP + VP * r.t[flat])).max()
    e = abs(cos_sim - cos_ref)
    et = rcval.rel(t_off, t_ref)
    rcval.check("rwall.paral.leave", e < 1e-3 and et < 1e-3 and ez < 1e-9 and ex < 1e-9,
                f"over the parallelogram ({flat.sum()} records): x = x0 + v0 t to {ex:.1e} m, z = R - 1e-4 L to "
                f"{ez:.1e} m (< 1e-9); leaves the edge at cos(theta) = {cos_sim:.7f}, t = {t_off:.6f} s; a particle "
                f"on a circle of radius R about the edge: 2/3 + v0^2/(3 g R) = {cos_ref:.7f} (error {e:.1e} < 1e-3), "
                f"t = -x0/v0 + int R dtheta/v = {t_ref:.6f} s (rel. error {et:.1e} < 1e-3)")
    w = np.abs(r.energy["energy_total"] - r.energy["energy_total"][0]).max() / (M * G * R)
    rcval.check("rwall.paral.ledger", w < 1e-6, f"max |E_total(t) - E_total(0)| / (m g R) = {w:.1e} (< 1e-6)")
    r = rcval.Result(rcval.run(off_paral(VPF), "paral_fast"))
    t_edge = -XP / VPF
    t_off = r.contact_ends()[0]
    # it leaves once its free flight has risen PEN above the circle about
    # the edge: x^2 (1/R - g/v0^2)/2 = PEN
    dt_ref = math.sqrt(2 * PEN / (1 / R - G / VPF**2)) / VPF
    rcval.check("rwall.paral.fast", 0.0 < t_off - t_edge < 2 * dt_ref,
                f"v0 = {VPF} m/s (v0^2 > g R): leaves {t_off - t_edge:.2e} s after its centre passes the edge at "
                f"{t_edge} s (0 < .. < 2 sqrt(2 p0/(1/R - g/v0^2))/v0 = {2 * dt_ref:.2e} s, the time its free flight "
                f"takes to clear the rest penetration p0)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, drop_plane)
