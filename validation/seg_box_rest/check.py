"""A meshed box dropped flat on a plane settles on four equal corner forces.

Two boxes, each a rigid body whose mass and inertia come from its mesh and
whose contact surface is /SURF/PART (the outer faces of the part): a solid
box (one /BRICK, a x b x c, density rho) and a thin shell box (six /SHELL
quadrilaterals, thickness t). Each is dropped flat from the height h0 on the
fixed plane z = 0 through a TYPE6 interface with a linear load curve
k and Visc (the interface's four bottom nodes are its contact points). The first
contact is at t = sqrt(2 h0 / g) (free fall). At rest (README.md):
  - the mass from the mesh is rho a b c (brick), rho t 2 (ab + bc + ca) (shells);
  - the total normal force is m g, at the interface penetration P = m g / k
    (the load law at the largest penetration gives the interface force);
  - the box is level: the four corner penetrations are equal, and the rule
    f_j = F p_j / sum p gives four equal corner forces m g / 4.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxrest  # noqa: E402
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

G, K, ZETA = 9.81, 1.0e6, 0.7
A, B, C = 0.2, 0.12, 0.08        # box sizes [m]
RHO_S, RHO_A, T = 7800.0, 2700.0, 0.002
M_BRICK = RHO_S * A * B * C
M_SHELL = RHO_A * T * 2 * (A * B + B * C + C * A)
TILT = (0.0, 0.0)                # initial rotation about x, then y [rad] (flat)
H0 = 0.005                       # height of the lowest corner at t = 0 [m]
T_END = 0.5
CORNERS = [(-A / 2, -B / 2, -C / 2), (A / 2, -B / 2, -C / 2), (A / 2, B / 2, -C / 2), (-A / 2, B / 2, -C / 2),
           (-A / 2, -B / 2, C / 2), (A / 2, -B / 2, C / 2), (A / 2, B / 2, C / 2), (-A / 2, B / 2, C / 2)]


def rot(v):
    ax, ay = TILT
    x, y, z = v
    y, z = y * math.cos(ax) - z * math.sin(ax), y * math.sin(ax) + z * math.cos(ax)
    x, z = x * math.cos(ay) + z * math.sin(ay), -x * math.sin(ay) + z * math.cos(ay)
    return (x, y, z)


def placed(xc):
    """Corner coordinates of a box centred at (xc, 0, zc), tilted, lowest corner at H0."""
    r = [rot(v) for v in CORNERS]
    zc = H0 - min(p[2] for p in r)
    return [(p[0] + xc, p[1], p[2] + zc) for p in r], (xc, 0.0, zc)


def deck(tilt=None):
    global TILT
    if tilt is not None:
        TILT = tilt
    d = Deck("meshed boxes dropped flat on a plane" if TILT == (0.0, 0.0) else "meshed boxes dropped tilted on a plane")
    cb, ob = placed(0.0)
    cs, os_ = placed(1.0)
    ct, ot = placed(3.0)
    d.nodes([(1, *ob), (2, *os_), (3, *ot)] + [(10 + j, *p) for j, p in enumerate(cb)] +
            [(20 + j, *p) for j, p in enumerate(cs)] + [(30 + j, *p) for j, p in enumerate(ct)])
    d.add("/MAT/LAW1/1", line(("r", RHO_S), ("r", 0.0)), line(("r", 2.1e11), ("r", 0.3)), title="steel")
    d.add("/MAT/LAW1/2", line(("r", RHO_A), ("r", 0.0)), line(("r", 7e10), ("r", 0.33)), title="aluminium")
    d.add("/PROP/SOLID/3", line(("i", 24), ("i", 4)), line(("r", 0)), line(("r", 0)), title="solid")
    d.add("/PROP/SHELL/4", line(("i", 24), ("i", 0)), line(("r", 0)), line(("i", 5), ("i", 0), ("r", T)),
          title="2 mm shell")
    d.add("/PART/1", line(("i", 3), ("i", 1), ("i", 0)), title="brick box")
    d.add("/PART/2", line(("i", 4), ("i", 2), ("i", 0)), title="shell box")
    d.add("/PART/3", line(("i", 3), ("i", 1), ("i", 0)), title="brick box on the table")
    d.add("/BRICK/1", line(*[("i", v) for v in [101] + list(range(10, 18))]))
    d.add("/BRICK/3", line(*[("i", v) for v in [301] + list(range(30, 38))]))
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    d.add("/SHELL/2", *[line(*[("i", v) for v in [201 + k] + [20 + j for j in f]]) for k, f in enumerate(faces)])
    d.add("/GRNOD/PART/101", i10(1), title="brick box nodes")
    d.add("/GRNOD/PART/102", i10(2), title="shell box nodes")
    d.add("/GRNOD/PART/103", i10(3), title="brick box on the table: nodes")
    for bid, node, grp, title in ((1, 1, 101, "brick box"), (2, 2, 102, "shell box"), (3, 3, 103, "brick on the table")):
        # mass and inertia from the mesh (ICoG 1: centre of the mesh)
        d.add(f"/RBODY/{bid}", line(("i", node), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", grp), ("i", 0),
                                    ("i", 1), ("i", 0)),
              line(("r", 0), ("r", 0), ("r", 0)), line(("r", 0), ("r", 0), ("r", 0)), line(("i", 0), ("i", 0), ("i", 0)),
              title=title)
    d.add("/SURF/PART/31", i10(1), title="brick box faces")
    d.add("/SURF/PART/32", i10(2), title="shell box faces")
    d.add("/SURF/PART/33", i10(3), title="brick on the table: faces")
    d.plane(10, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    d.box(11, 0, (3.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="table: analytic box, top face z = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    for iid, s, f, m in ((1, 31, 10, M_BRICK), (2, 32, 10, M_SHELL), (3, 33, 11, M_BRICK)):
        d.type6(iid, s, f, 1, visc=2 * ZETA * math.sqrt(K * m), title=f"box {iid} on the {'table' if f == 11 else 'floor'}")
    d.grav(1, "Z", -G)
    d.run(T_END, 0.01)
    return d


def main():
    r, quat, omega = boxrest.load(rcval.run_case())
    t1 = math.sqrt(2 * H0 / G)
    for b, (name, m) in enumerate((("brick", M_BRICK), ("shell", M_SHELL), ("brick_on_box", M_BRICK))):
        boxrest.check_first_contact(f"seg_box_rest.{name}.first_contact", r, t1, b + 1)
        fn = r.fn[-1, b]
        e = rcval.rel(fn, m * G)
        rcval.check(f"seg_box_rest.{name}.force", e < 1e-6,
                    f"total normal force at t = {r.t[-1]:g} s: {fn:.9g} N, m g = {m * G:.9g} N (m = {m:.6g} kg from "
                    f"the mesh, closed form), rel. error {e:.2e} (< 1e-6)")
        p = r.pen[-1, b]
        e = rcval.rel(p, m * G / K)
        rcval.check(f"seg_box_rest.{name}.penetration", e < 5e-5,
                    f"P = {p:.9e} m, m g / k = {m * G / K:.9e} m, rel. error {e:.2e} (< 5e-5: the law's penetration P_e, at which the force is the weight exactly, lies below the deepest corner by what the last rockings left unpaid: theory 2.7)")
        # corner depths from the final pose (body frame = global at t = 0,
        # origin at the centre); the forces by the rule F p_j / sum p.
        # 1e-5: the corner depths differ at the solver's position tolerance
        # (~1e-12 m), 2e-7 of the light shell box's P = 5.3e-6 m
        forces = boxrest.corner_forces(fn, r.pos[-1, b], quat[-1, b], [np.array(rot(v)) for v in CORNERS])
        boxrest.check_corners(f"seg_box_rest.{name}.corners", forces, m, G)
        boxrest.check_rest(f"seg_box_rest.{name}.rest", r.vel[-1, b], omega[-1, b], A, f"at t = {r.t[-1]:g} s")
    rcval.check_ledger("seg_box_rest.ledger", r, 1e-5)
    # tilted (one corner first): the first contact, and the ledger with the
    # shared forces (not conservative, README) integrated as their power
    flat = TILT
    r = rcval.Result(rcval.run(deck(tilt=(0.04, -0.025)), name="tilted"))
    boxrest.check_first_contact("seg_box_rest.tilted.first_corner", r, t1, 1, before="tilted brick box: ",
                                after=" for the lowest corner")
    rcval.check_ledger("seg_box_rest.tilted.ledger", r, 1e-5)
    hy = float(r.energy["energy_hysteresis"].min())
    print(f"info: tilted brick box: lowest energy_hysteresis (work - law energy at P) {hy:.3e} J, kinetic energy "
          f"at {T_END:g} s {float(r.energy['energy_kinetic'][-1]):.3e} J (the sharing is not conservative: theory 2.7)")
    deck(tilt=flat)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
