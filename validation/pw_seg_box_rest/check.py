"""A meshed box comes to rest on a plane through /INTER/POWER (the power law
on a segment surface).

A solid box (one /BRICK, steel, mass and inertia from the mesh, contact
surface /SURF/PART: its eight nodes are the contact points) is dropped
level from h0 = 2 mm on the fixed plane z = 0; /INTER/POWER with
F = K P^m1 (K = 1e9 N/m^1.5, m1 = 1.5) at the deepest node and the damping
C v^m2 P^m3 (C = 5e8, m2 = m3 = 1) at the penetration-weighted rate, the
force shared over the nodes as p_j / sum p (docs/theory.md 2.7). Closed
forms (README.md): first contact at sqrt(2 h0 / g); at rest F = m g, so
P = (m g / K)^(1 / m1), the four bottom corners equally deep, each
carrying m g / 4.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import boxrest  # noqa: E402
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

G, KP, M1, CP = 9.81, 1.0e9, 1.5, 5.0e8
A, B, C = 0.2, 0.12, 0.08
RHO = 7800.0
M = RHO * A * B * C
H0, T_END = 0.002, 0.5
CORNERS = [(-A / 2, -B / 2, -C / 2), (A / 2, -B / 2, -C / 2), (A / 2, B / 2, -C / 2), (-A / 2, B / 2, -C / 2),
           (-A / 2, -B / 2, C / 2), (A / 2, -B / 2, C / 2), (A / 2, B / 2, C / 2), (-A / 2, B / 2, C / 2)]


def deck():
    zc = H0 + C / 2
    d = Deck("meshed box dropped on a plane, power law")
    d.nodes([(1, 0.0, 0.0, zc)] + [(10 + j, x, y, z + zc) for j, (x, y, z) in enumerate(CORNERS)])
    d.add("/MAT/LAW1/1", line(("r", RHO), ("r", 0.0)), line(("r", 2.1e11), ("r", 0.3)), title="steel")
    d.add("/PROP/SOLID/3", line(("i", 24), ("i", 4)), line(("r", 0)), line(("r", 0)), title="solid")
    d.add("/PART/1", line(("i", 3), ("i", 1), ("i", 0)), title="brick box")
    d.add("/BRICK/1", line(*[("i", v) for v in [101] + list(range(10, 18))]))
    d.add("/GRNOD/PART/101", i10(1), title="brick box nodes")
    d.add("/RBODY/1", line(("i", 1), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", 101), ("i", 0), ("i", 1), ("i", 0)),
          line(("r", 0), ("r", 0), ("r", 0)), line(("r", 0), ("r", 0), ("r", 0)), line(("i", 0), ("i", 0), ("i", 0)),
          title="brick box (mass from the mesh)")
    d.add("/SURF/PART/31", i10(1), title="brick box faces")
    d.plane(10, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    d.power(1, 31, 10, k=KP, m1=M1, c=CP, m2=1.0, m3=1.0, irdf=2, title="box on the floor, power law")
    d.grav(1, "Z", -G)
    d.run(T_END, 0.01)
    return d


def main():
    r, quat, omega = boxrest.load(rcval.run_case())
    t1 = math.sqrt(2 * H0 / G)
    boxrest.check_first_contact("pw_seg_box_rest.first_contact", r, t1)
    fn = r.fn[-1, 0]
    e = rcval.rel(fn, M * G)
    rcval.check("pw_seg_box_rest.force", e < 1e-6,
                f"total normal force at {r.t[-1]:g} s: {fn:.9g} N, m g = {M * G:.9g} N (m = {M:.6g} kg from the mesh), "
                f"rel. error {e:.2e} (< 1e-6)")
    p_ref = (M * G / KP) ** (1 / M1)
    e = rcval.rel(r.pen[-1, 0], p_ref)
    rcval.check("pw_seg_box_rest.penetration", e < 5e-5,
                f"P = {r.pen[-1, 0]:.9e} m, (m g / K)^(1/m1) = {p_ref:.9e} m, rel. error {e:.2e} (< 5e-5: P_e, at which the force is the load exactly, below the deepest corner by what the last rockings left unpaid: theory 2.7)")
    forces = boxrest.corner_forces(fn, r.pos[-1, 0], quat[-1, 0], CORNERS)
    boxrest.check_corners("pw_seg_box_rest.corners", forces, M, G)
    boxrest.check_rest("pw_seg_box_rest.rest", r.vel[-1, 0], omega[-1, 0], A, f"at {r.t[-1]:g} s")
    rcval.check_ledger("pw_seg_box_rest.ledger", r, 1e-5)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
