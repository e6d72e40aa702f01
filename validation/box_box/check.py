"""Analytic boxes against analytic boxes (/SURF/BOX - /SURF/BOX): the corners
of each box against the faces of the other, both ways (docs/theory.md 2.7).

1. Resting (case.rad): a small box (a x b x c, mass M) dropped level on a
   fixed table box (1 m cube, top face z = 0; the table first on the card),
   and a stack of two free boxes on the fixed plane z = 0: box 3 (mass M3)
   on the plane (box-plane), box 4 (mass M4, smaller) on box 3 (box-box,
   box 4 first on the card). At rest: the interface forces M g on the table,
   M4 g between 3 and 4, (M3 + M4) g on the plane; the penetrations
   M g / k, M4 g / k, (M3 + M4) g / k; the resting boxes level, so their four
   bottom corners carry F / 4 each.
2. Sliding (generated): the small box launched at v0 along x on the table,
   TYPE6 Fric = mu: it decelerates at mu g, stops at t_s = v0 / (mu g) and
   rests at v0^2 / (2 mu g) from its start less the tilt and stick-spring
   terms of validation/seg_box_slide_stop (README.md).
3. Power law (generated): /INTER/POWER between the table and a box at rest,
   P = (m g / K)^(1 / m1), four corner forces m g / 4; and a box sliding on
   it with step5 friction per corner: beyond v_d it decelerates at mu_d g.
4. Collision (generated, no gravity): two free boxes of different sizes and
   masses, one launched at the other off-centre and spinning: the total
   linear and angular momentum (about the origin) are conserved.
5. Crossing edges (generated): boxes whose corners all lie outside the
   other's faces, carried by the pairs of crossing edges alone: a bar
   (L8 x W8 x W8, mass M8) dropped across a fixed bar laid the other way,
   and a cube (edge 2 H9, mass M9) turned by 30 degrees about the vertical
   dropped on a larger fixed cube. At rest: F = m g, P = m g / k, the boxes
   level, the deepest point at a crossing of two edges. Without damping
   (the bar again, Visc 0): the contact is a linear spring k under gravity,
   closing at v = sqrt(2 g h0): it lasts (pi + 2 asin(delta / A)) / omega,
   omega = sqrt(k / m), delta = m g / k, A = sqrt(delta^2 + (v / omega)^2),
   and the bar leaves at v (no energy lost).
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxrest  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G, K, ZETA, MU = 9.81, 1.0e6, 0.7, 0.3
A, B, C, M = 0.2, 0.12, 0.08, 15.0       # small box [m], [kg]
A3, B3, C3, M3 = 0.4, 0.3, 0.1, 30.0     # lower box of the stack
A4, B4, C4, M4 = 0.2, 0.16, 0.06, 8.0    # upper box of the stack
H0 = 0.005                               # drop height of the small box and of the stack [m]
V0 = 1.0                                 # launch speed of the sliding box [m/s]


def jbox(m, a, b, c):
    return (m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12)


def add_box(d, bid, x, m, half, v0=None, w0=None, title="box"):
    """Free body bid with node bid at x, a box surface 10 + bid around it."""
    d.nodes([(bid, *x)])
    d.grnod(bid, [bid], title=title)
    d.rbody(bid, bid, m, jbox(m, *(2 * h for h in half)), grnod=bid, title=title)
    d.box(10 + bid, bid, x, half, title=title)
    if v0 is not None:
        d.inivel(bid, v0, bid)
    if w0 is not None:
        d.inivel(100 + bid, w0, bid, rot=True)


def base(title):
    d = Deck(title)
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    return d


def deck_rest():
    d = base("analytic boxes resting on a box and stacked")
    d.box(1, 0, (0.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="table: fixed 1 m cube, top face z = 0")
    d.plane(2, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    add_box(d, 5, (0.1, -0.05, C / 2 + H0), M, (A / 2, B / 2, C / 2), title="small box on the table")
    add_box(d, 3, (2.0, 0.0, C3 / 2 + H0), M3, (A3 / 2, B3 / 2, C3 / 2), title="lower box of the stack")
    add_box(d, 4, (2.0, 0.0, C3 + 2 * H0 + C4 / 2), M4, (A4 / 2, B4 / 2, C4 / 2), title="upper box of the stack")
    d.type6(1, 1, 15, 1, visc=2 * ZETA * math.sqrt(K * M), title="table and small box (table first)")
    d.type6(2, 13, 2, 1, visc=2 * ZETA * math.sqrt(K * (M3 + M4)), title="lower box on the floor")
    d.type6(3, 14, 13, 1, visc=2 * ZETA * math.sqrt(K * M4), title="upper box on the lower box")
    d.grav(1, "Z", -G)
    d.run(1.0, 0.01)
    return d


def deck_slide():
    d = base("analytic box sliding on a box, friction per corner")
    d.box(1, 0, (0.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="table: fixed 1 m cube, top face z = 0")
    p0 = M * G / K
    add_box(d, 5, (-0.3, 0.0, C / 2 - p0), M, (A / 2, B / 2, C / 2), v0=(V0, 0.0, 0.0), title="sliding box")
    d.type6(1, 15, 1, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the table, Fric 0.3")
    d.grav(1, "Z", -G)
    d.run(0.6, 0.005)
    return d


def deck_collide():
    d = base("two free boxes colliding, no gravity")
    add_box(d, 6, (0.0, 0.0, 0.0), M3, (A3 / 2, B3 / 2, C3 / 2), title="box 6 at rest")
    add_box(d, 7, (-0.35, 0.05, 0.03), M4, (A4 / 2, B4 / 2, C4 / 2), v0=(2.0, 0.1, -0.05), w0=(0.5, -1.0, 2.0),
            title="box 7 launched at box 6, spinning")
    d.type6(1, 17, 16, 1, visc=2 * 0.3 * math.sqrt(K * M3 * M4 / (M3 + M4)), title="box 7 against box 6")
    d.run(0.4, 0.005)
    return d


L8, W8, M8 = 0.6, 0.1, 6.0               # crossing bars: length, width [m], mass of the upper one [kg]
Y8 = -0.021                              # the upper bar's offset along the lower one [m]
H9, M9, TURN9 = 0.08, 4.0, 30.0          # turned cube: half-size [m], mass [kg], turn [deg]; the lower cube 0.1 m


def add_turned_box(d, bid, x, m, half, turn_deg, v0=None, title="box"):
    """add_box with the box's axes turned about the vertical by turn_deg."""
    a = math.radians(turn_deg)
    d.nodes([(bid, *x)])
    d.grnod(bid, [bid], title=title)
    d.rbody(bid, bid, m, jbox(m, *(2 * h for h in half)), grnod=bid, title=title)
    d.box(10 + bid, bid, x, half, u=(math.cos(a), math.sin(a), 0.0), v=(-math.sin(a), math.cos(a), 0.0), title=title)
    if v0 is not None:
        d.inivel(bid, v0, bid)


def deck_edges(elastic=False):
    """Crossing edges: the bar across the bar (Visc 0 when elastic, run
    alone), and the turned cube on the cube."""
    d = base("boxes carried by their crossing edges" + (", no damping" if elastic else ""))
    d.box(1, 0, (0.0, 0.0, -W8 / 2), (W8 / 2, L8 / 2, W8 / 2), title="fixed bar along y, top face z = 0")
    add_box(d, 8, (0.0, Y8, W8 / 2 + H0), M8, (L8 / 2, W8 / 2, W8 / 2), title="bar along x, across the fixed one")
    d.type6(1, 18, 1, 1, visc=0.0 if elastic else 2 * ZETA * math.sqrt(K * M8), title="bar across the bar")
    if not elastic:
        d.box(2, 0, (3.0, 0.0, -0.1), (0.1, 0.1, 0.1), title="fixed cube, top face z = 0")
        add_turned_box(d, 9, (3.0, 0.0, H9 + H0), M9, (H9, H9, H9), TURN9, title="cube turned by 30 degrees")
        d.type6(2, 19, 2, 1, visc=2 * ZETA * math.sqrt(K * M9), title="turned cube on the cube")
    d.grav(1, "Z", -G)
    d.run(0.05 if elastic else 1.0, 0.0005 if elastic else 0.01)
    return d


KP, M1, CP = 1.0e9, 1.5, 5.0e8          # power law K [N/m^1.5], m1, damping C (m2 = m3 = 1)
MUS, VS, MUD, VD = 0.5, 0.01, 0.3, 0.05  # step5 friction


def deck_power():
    """/INTER/POWER box-box: the small box resting on the table, and a second
    one sliding on it with step5 friction per corner."""
    d = base("analytic boxes on a box, power law and step5 friction")
    d.box(1, 0, (0.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="table: fixed 1 m cube, top face z = 0")
    pz = (M * G / KP) ** (1 / M1)
    add_box(d, 5, (0.2, -0.2, C / 2 + H0), M, (A / 2, B / 2, C / 2), title="box dropped on the table")
    add_box(d, 6, (-0.3, 0.2, C / 2 - pz), M, (A / 2, B / 2, C / 2), v0=(V0, 0.0, 0.0), title="box sliding on the table")
    d.power(1, 15, 1, k=KP, m1=M1, c=CP, m2=1.0, m3=1.0, irdf=2, title="dropped box on the table (box first)")
    d.power(2, 1, 16, k=KP, m1=M1, c=CP, m2=1.0, m3=1.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD,
            title="sliding box on the table (table first), step5")
    d.grav(1, "Z", -G)
    d.run(0.3, 0.005)
    return d


def main():
    # 1. resting
    r, quat, omega = boxrest.load(rcval.run_case())
    # bodies in deck order: 5, 3, 4; interfaces 1, 2, 3
    top3 = lambda: r.pos[-1, 1, 2] + C3 / 2  # noqa: E731 (top face of the lower box, level)
    cases = (("table", 0, 0, M, (A / 2, B / 2, C / 2), lambda x: -x[2]),
             ("stack_floor", 1, 1, M3 + M4, (A3 / 2, B3 / 2, C3 / 2), lambda x: -x[2]),
             ("stack_top", 2, 2, M4, (A4 / 2, B4 / 2, C4 / 2), lambda x: top3() - x[2]))
    for name, i, b, mload, half, depth in cases:
        fn, p = r.fn[-1, i], r.pen[-1, i]
        e1, e2 = rcval.rel(fn, mload * G), rcval.rel(p, mload * G / K)
        rcval.check(f"box_box.rest.{name}.force", e1 < 1e-6 and e2 < 5e-5,
                    f"interface {i + 1}: F = {fn:.9g} N, m g = {mload * G:.9g} N, rel. error {e1:.2e} (< 1e-6); "
                    f"P = {p:.9e} m, m g / k = {mload * G / K:.9e} m, rel. error {e2:.2e} (< 5e-5: P_e, at which the force is the load exactly, below the deepest corner by what the last rockings left unpaid: theory 2.7)")
        f = boxrest.corner_forces(fn, r.pos[-1, b], quat[-1, b], boxrest.box_corners(half), depth)
        boxrest.check_corners(f"box_box.rest.{name}.corners", f, mload, G, where="the surface below")
    v = float(np.max(np.linalg.norm(r.vel[-1], axis=1)) + np.max(np.linalg.norm(omega[-1], axis=1)) * A3)
    rcval.check("box_box.rest.at_rest", v < 1e-6, f"max |v| + |omega| a over the boxes = {v:.2e} m/s (< 1e-6)")
    rcval.check_ledger("box_box.rest.ledger", r, 1e-5)

    # 2. sliding to a stop on the table
    r = rcval.Result(rcval.run(deck_slide(), name="slide"))
    # references of validation/seg_box_slide_stop (README.md there): the
    # friction moment tilts the sliding box by phi (balanced by the shared
    # normal forces over the 4 bottom corners, <x^2> = a^2 / 4), the centre
    # rising by dz; after the stop the stick springs give back mu m g / K_t
    ts, D = V0 / (MU * G), V0 * V0 / (2 * MU * G)
    p0 = M * G / K
    phi = MU * C * p0 / (2 * A * A / 4 + MU * C * A / 2)
    dz = phi * A / 2
    sl = (r.t > 0.05) & (r.t < ts - 0.05)
    cf = np.polyfit(r.t[sl], r.pos[sl, 0, 0], 2)
    a = -2 * cf[0]
    e = rcval.rel(a, MU * G)
    rcval.check("box_box.slide.deceleration", e < 1e-5,
                f"quadratic fit of x over [0.05, t_s - 0.05] s: deceleration {a:.9f} m/s^2, mu g = {MU * G:.9f}, "
                f"rel. error {e:.2e} (< 1e-5)")
    stick = [t for t, kd in zip(r.ev_t, r.ev_kind) if kd == "fric_stick"]
    e = rcval.rel(stick[0], ts) if stick else float("inf")
    rcval.check("box_box.slide.stop_time", e < 1e-6,
                f"first fric_stick at {stick[0] if stick else float('nan'):.9f} s, v0 / (mu g) = {ts:.9f} s, rel. error "
                f"{e:.2e} (< 1e-6)")
    x_rest = D - MU * dz - MU * M * G / K - dz * C / A
    dx = r.pos[-1, 0, 0] - r.pos[0, 0, 0]
    e = abs(dx - x_rest) / D
    rcval.check("box_box.slide.rest_position", e < 2e-5,
                f"at rest {dx:.9f} m from the start, D - mu dz - mu m g / K_t - dz c / a = {x_rest:.9f} m "
                f"(D = v0^2 / (2 mu g) = {D:.9f} m, phi = {phi:.4e} rad), error {e:.2e} of D (< 2e-5: as the box untilts at the stop the shrinking shares scale their node springs down, shortening the creep back mu m g / K_t by a few percent: theory 2.7)")
    rcval.check("box_box.slide.rest", abs(r.vel[-1, 0, 0]) < 1e-6 and bool(r.slip[-1, 0] == 0),
                f"v at {r.t[-1]:g} s = {r.vel[-1, 0, 0]:.1e} m/s (< 1e-6), sticking: {bool(r.slip[-1, 0] == 0)}")
    rcval.check_ledger("box_box.slide.ledger", r, 1e-5)

    # 2b. the power law: at rest P = (m g / K)^(1 / m1); step5 beyond v_d: mu_d g
    r, quat, _ = boxrest.load(rcval.run(deck_power(), name="power"))
    pref = (M * G / KP) ** (1 / M1)
    e1, e2 = rcval.rel(r.fn[-1, 0], M * G), rcval.rel(r.pen[-1, 0], pref)
    f = boxrest.corner_forces(r.fn[-1, 0], r.pos[-1, 0], quat[-1, 0], boxrest.box_corners((A / 2, B / 2, C / 2)))
    e3 = float(np.max(np.abs(f - M * G / 4)) / (M * G / 4)) if len(f) == 4 else float("inf")
    rcval.check("box_box.power.rest", e1 < 1e-6 and e2 < 5e-5 and e3 < 1e-5,
                f"/INTER/POWER at rest on the table: F = {r.fn[-1, 0]:.9g} N against m g, rel. error {e1:.2e}; "
                f"P = {r.pen[-1, 0]:.9e} m, (m g / K)^(1/m1) = {pref:.9e} m, rel. error {e2:.2e} (< 5e-5: the law's "
                f"penetration's memory, theory 2.7); "
                f"{len(f)} corner forces against m g / 4, max rel. error {e3:.2e} (< 1e-5)")
    sl = (r.t >= 0.05) & (r.vel[:, 1, 0] > 2 * VD)
    cf = np.polyfit(r.t[sl], r.pos[sl, 1, 0], 2)
    a = -2 * cf[0]
    e = rcval.rel(a, MUD * G)
    ratio = np.linalg.norm(r.ffric[sl, 1], axis=1) / r.fn[sl, 1]
    er = float(np.max(np.abs(ratio - MUD)))
    rcval.check("box_box.power.step5", e < 1e-5 and er < 1e-6 and int(sl.sum()) > 20,
                f"step5 per corner beyond v_d: deceleration {a:.9f} m/s^2 over {int(sl.sum())} records, mu_d g = "
                f"{MUD * G:.9f}, rel. error {e:.2e} (< 1e-5); max ||F_t| / F_n - mu_d| = {er:.1e} (< 1e-6)")
    rcval.check_ledger("box_box.power.ledger", r, 1e-5)

    # 3. collision of two free boxes: momentum conserved
    r, quat, omega = boxrest.load(rcval.run(deck_collide(), name="collide"))
    ms = (M3, M4)
    Js = (np.diag(jbox(M3, A3, B3, C3)), np.diag(jbox(M4, A4, B4, C4)))
    p = sum(ms[b] * r.vel[:, b] for b in range(2))
    L = []
    for k in range(len(r.t)):
        tot = np.zeros(3)
        for b in range(2):
            Q = boxrest.quat_matrix(quat[k, b])
            tot += ms[b] * np.cross(r.pos[k, b], r.vel[k, b]) + Q @ (Js[b] @ omega[k, b])
        L.append(tot)
    L = np.array(L)
    ep = float(np.max(np.linalg.norm(p - p[0], axis=1)) / np.linalg.norm(p[0]))
    eL = float(np.max(np.linalg.norm(L - L[0], axis=1)) / np.linalg.norm(L[0]))
    hit = [t for t, kd in zip(r.ev_t, r.ev_kind) if kd == "contact_close"]
    dv = float(np.linalg.norm(r.vel[-1, 0]))
    rcval.check("box_box.collide.momentum", ep < 1e-8 and eL < 1e-7 and len(hit) > 0 and dv > 0.1,
                f"{len(hit)} contact_close (first at {hit[0] if hit else float('nan'):.6g} s), box 6 leaves at "
                f"{dv:.4g} m/s; max |p(t) - p(0)| / |p(0)| = {ep:.2e}, max |L(t) - L(0)| / |L(0)| = {eL:.2e} (< 1e-8, < 1e-7: the rotations integrated at rtol 1e-8)")
    rcval.check_ledger("box_box.collide.ledger", r, 1e-5)

    # 5. crossing edges: at rest, then an elastic bounce
    r, quat, omega = boxrest.load(rcval.run(deck_edges(), name="edges"))
    with Dataset(r.path) as nc:
        point = np.array(nc["inter_contact_point"][:])
    cases = (("bar", 0, M8, (0.0, Y8), lambda x: abs(abs(x[0]) - W8 / 2) < 1e-3 and abs(abs(x[1] - Y8) - W8 / 2) < 1e-3),
             ("turned_cube", 1, M9, (3.0, 0.0), None))
    for name, i, mload, xy, at_crossing in cases:
        fn, p = r.fn[-1, i], r.pen[-1, i]
        e1, e2 = rcval.rel(fn, mload * G), rcval.rel(p, mload * G / K)
        x = point[-1, i]
        if at_crossing is None:
            # the cube's bottom edges and the lower cube's top edges cross
            # where the turned square's sides meet the square's: on both
            # squares' outlines (0.1 m and H9 from the centre along their axes)
            a = math.radians(TURN9)
            rel = (x[0] - xy[0], x[1] - xy[1])
            on_lower = abs(max(abs(rel[0]), abs(rel[1])) - 0.1) < 1e-3
            uu = rel[0] * math.cos(a) + rel[1] * math.sin(a)
            vv = -rel[0] * math.sin(a) + rel[1] * math.cos(a)
            on_upper = abs(max(abs(uu), abs(vv)) - H9) < 1e-3
            crossing = on_lower and on_upper
        else:
            crossing = at_crossing(x)
        tilt = float(2 * math.asin(min(1.0, math.hypot(quat[-1, i, 1], quat[-1, i, 2]))))
        rcval.check(f"box_box.edges.{name}.rest", e1 < 1e-6 and e2 < 5e-5 and crossing and tilt < 1e-6,
                    f"interface {i + 1}: F = {fn:.9g} N, m g = {mload * G:.9g} N, rel. error {e1:.2e} (< 1e-6); "
                    f"P = {p:.9e} m, m g / k = {mload * G / K:.9e} m, rel. error {e2:.2e} (< 5e-5); deepest point "
                    f"({x[0]:.5f}, {x[1]:.5f}, {x[2]:.2e}) m at a crossing of two edges: {crossing}; tilt "
                    f"{tilt:.1e} rad (< 1e-6)")
    boxrest.check_rest("box_box.edges.at_rest", r.vel[-1], omega[-1], L8, f"at {r.t[-1]:g} s")
    rcval.check_ledger("box_box.edges.ledger", r, 1e-5)

    r = rcval.Result(rcval.run(deck_edges(elastic=True), name="edges_elastic"))
    v = math.sqrt(2 * G * H0)
    om, delta = math.sqrt(K / M8), M8 * G / K
    amp = math.hypot(delta, v / om)
    dur = (math.pi + 2 * math.asin(delta / amp)) / om
    close = [t for t, k in zip(r.ev_t, r.ev_kind) if k == "contact_close"]
    opened = [t for t, k in zip(r.ev_t, r.ev_kind) if k in ("contact_open", "contact_separate") and close and t > close[0]]
    got = opened[0] - close[0] if close and opened else float("nan")
    e = rcval.rel(got, dur) if close and opened else float("inf")
    k1 = int(np.searchsorted(r.t, opened[0])) if opened else -1
    vout = float(r.vel[min(k1, len(r.t) - 1), 0, 2]) if opened else float("nan")
    ev = rcval.rel(vout, v) if opened else float("inf")
    rcval.check("box_box.edges.bounce", e < 1e-6 and ev < 1e-5,
                f"contact from {close[0] if close else float('nan'):.9f} s to {opened[0] if opened else float('nan'):.9f} s: "
                f"{got:.9e} s, (pi + 2 asin(delta / A)) / omega = {dur:.9e} s, rel. error {e:.2e} (< 1e-6); leaves at "
                f"{vout:.9f} m/s, sqrt(2 g h0) = {v:.9f} m/s, rel. error {ev:.2e} (< 1e-5)")
    rcval.check_ledger("box_box.edges.bounce_ledger", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck_rest)
