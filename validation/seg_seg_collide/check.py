"""Two meshed boxes collide in free space (segment surface against segment
surface, node to segment both ways).

Two solid boxes (one /BRICK each, steel, mass and inertia from the mesh,
contact surfaces /SURF/PART), no gravity, one /INTER/TYPE6 between their
surfaces with a linear load curve k. References (README.md), closed forms:
  1. (case.rad) a small box A falls flat and centred on the top face of a
     large box B at rest, velocity (0, 0, v0 = -1) m/s, elastic (Visc 0), no
     friction: A's four bottom nodes meet B's top face, one linear contact
     along z: after it v_A = (0, 0, v0 (mA - mB)/(mA + mB)),
     v_B = (0, 0, 2 mA v0/(mA + mB)), no rotation (the impulse along the
     face normal, z). Run again sliding at (0.3, 0.2) m/s, it shows (info,
     not a check) the rocking the sharing rule lets grow (README.md);
  2. (generated) a large box A, offset and tilted, spinning, falls on a
     small box B at rest, damped (the nodes of B's top face against A's
     bottom face: the other direction): total linear and angular momentum
     are those of the start.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

K, RHO = 1.0e6, 7800.0
SMALL, LARGE = (0.1, 0.08, 0.06), (0.2, 0.12, 0.08)
H0 = 0.002                 # initial gap [m]
SIGNS = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]


def mass(s):
    return RHO * s[0] * s[1] * s[2]


def rot_x(a):
    return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])


def inertia(s, R):
    m = mass(s)
    a, b, c = s
    J = m / 12 * np.diag([b * b + c * c, a * a + c * c, a * a + b * b])
    return R @ J @ R.T


def corners(s, centre, R):
    return [centre + R @ (0.5 * np.array(sg) * np.array(s)) for sg in SIGNS]


def deck(case, zeta=None, vt=(0.0, 0.0)):
    """case 1: small A on large B (A's nodes on B's face); case 2: large A,
    offset, tilted and spinning, on small B (B's nodes on A's face)."""
    if case == 1:
        sa, sb, ra, off, va, wa = SMALL, LARGE, np.eye(3), (0.0, 0.0), (vt[0], vt[1], -1.0), (0, 0, 0)
        mr = mass(sa) * mass(sb) / (mass(sa) + mass(sb))
        visc = 2 * (zeta or 0.0) * math.sqrt(K * mr)
    else:
        sa, sb, ra, off, va, wa = LARGE, SMALL, rot_x(0.02), (0.03, 0.01), (0.1, -0.05, -0.8), (0.5, -0.3, 0.2)
        mr = mass(sa) * mass(sb) / (mass(sa) + mass(sb))
        visc = 2 * 0.3 * math.sqrt(K * mr)
    cb = np.array([0.0, 0.0, -sb[2] / 2])  # B's top face at z = 0
    # A's lowest bottom corner H0 above z = 0
    low = min((ra @ (0.5 * np.array(sg) * np.array(sa)))[2] for sg in SIGNS)
    ca = np.array([off[0], off[1], H0 - low])
    d = Deck(f"two meshed boxes collide ({'small on large' if case == 1 else 'large, tilted, on small'})")
    na, nb = corners(sa, ca, ra), corners(sb, cb, np.eye(3))
    d.nodes([(1, *ca), (2, *cb)] + [(10 + j, *p) for j, p in enumerate(na)] + [(20 + j, *p) for j, p in enumerate(nb)])
    d.add("/MAT/LAW1/1", line(("r", RHO), ("r", 0.0)), line(("r", 2.1e11), ("r", 0.3)), title="steel")
    d.add("/PROP/SOLID/3", line(("i", 24), ("i", 4)), line(("r", 0)), line(("r", 0)), title="solid")
    for pid, title in ((1, "box A"), (2, "box B")):
        d.add(f"/PART/{pid}", line(("i", 3), ("i", 1), ("i", 0)), title=title)
    d.add("/BRICK/1", line(*[("i", v) for v in [101] + list(range(10, 18))]))
    d.add("/BRICK/2", line(*[("i", v) for v in [201] + list(range(20, 28))]))
    for pid in (1, 2):
        d.add(f"/GRNOD/PART/{100 + pid}", i10(pid), title=f"box {'AB'[pid - 1]} nodes")
        d.add(f"/RBODY/{pid}", line(("i", pid), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", 100 + pid), ("i", 0),
                                     ("i", 1), ("i", 0)),
              line(("r", 0), ("r", 0), ("r", 0)), line(("r", 0), ("r", 0), ("r", 0)), line(("i", 0), ("i", 0), ("i", 0)),
              title=f"box {'AB'[pid - 1]} (mass from the mesh)")
        d.add(f"/SURF/PART/{30 + pid}", i10(pid), title=f"box {'AB'[pid - 1]} faces")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.type6(1, 31, 32, 1, visc=visc, title="box A against box B")
    d.inivel(1, va, 101)
    if case == 2:
        d.inivel(2, wa, 101, rot=True)
    d.run(0.02, 0.0005)
    return d, (sa, sb, ra, ca, cb, np.array(va), np.array(wa, dtype=float))


def quat_matrix(q):
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def momenta(path, sa, sb, ra):
    """Total linear momentum and angular momentum about the origin at every record."""
    with Dataset(path) as nc:
        x = np.array(nc["body_position"][:])
        v = np.array(nc["body_velocity"][:])
        q = np.array(nc["body_quaternion"][:])
        w = np.array(nc["body_angular_velocity"][:])  # body frame
    J = [inertia(sa, ra), inertia(sb, np.eye(3))]  # body frame = global at t = 0
    m = [mass(sa), mass(sb)]
    P = sum(m[b] * v[:, b] for b in range(2))
    L = np.zeros_like(P)
    for k in range(len(P)):
        for b in range(2):
            R = quat_matrix(q[k, b])
            L[k] += m[b] * np.cross(x[k, b], v[k, b]) + R @ (J[b] @ w[k, b])
    return P, L, w


def main():
    # 1. small on large, central, elastic
    d, (sa, sb, ra, ca, cb, va, wa) = deck(1)
    path = rcval.run_case()
    r = rcval.Result(path)
    ma, mb = mass(sa), mass(sb)
    v0 = va[2]
    vA = np.array([va[0], va[1], v0 * (ma - mb) / (ma + mb)])
    vB = np.array([0.0, 0.0, 2 * ma * v0 / (ma + mb)])
    ea = float(np.max(np.abs(r.vel[-1, 0] - vA))) / abs(v0)
    eb = float(np.max(np.abs(r.vel[-1, 1] - vB))) / abs(v0)
    kinds = sorted(set(r.ev_kind))
    rcval.check("seg_seg_collide.central.velocities", ea < 1e-6 and eb < 1e-6 and r.mode[-1, 0] == 1,
                f"after the contact (t = {r.t[-1]:g} s, contact open): v_A = {np.round(r.vel[-1, 0], 9)}, closed form "
                f"{np.round(vA, 9)}; v_B = {np.round(r.vel[-1, 1], 9)}, closed form {np.round(vB, 9)} m/s; max error / "
                f"|v0| {max(ea, eb):.1e} (< 1e-6); events {kinds}")
    P, L, w = momenta(path, sa, sb, ra)
    rot = float(np.max(np.abs(w)))
    rcval.check("seg_seg_collide.central.no_rotation", rot < 1e-5,
                f"max |omega| = {rot:.1e} rad/s (< 1e-5): the impulse along the face normal through both centres")
    eP = float(np.max(np.linalg.norm(P - P[0], axis=1)) / np.linalg.norm(P[0]))
    rcval.check("seg_seg_collide.central.momentum", eP < 1e-8,
                f"max |P(t) - P(0)| / |P(0)| = {eP:.1e} (< 1e-8)")
    rcval.check_ledger("seg_seg_collide.central.ledger", r, 1e-5)
    # 1b. the same sliding: the sharing rule's rocking (README.md), info only
    d, _ = deck(1, vt=(0.3, 0.2))
    p2 = rcval.run(d, name="sliding")
    r2 = rcval.Result(p2)
    P2, L2, w2 = momenta(p2, sa, sb, ra)
    print(f"info: sliding at (0.3, 0.2) m/s: max |omega| = {float(np.max(np.abs(w2))):.3g} rad/s, v_A after = "
          f"{np.round(r2.vel[-1, 0], 6)}, v_B after = {np.round(r2.vel[-1, 1], 6)} m/s (closed form without rocking: "
          f"(0.3, 0.2, {vA[2]:.6g}) and (0, 0, {vB[2]:.6g})); momentum drift "
          f"{float(np.max(np.linalg.norm(P2 - P2[0], axis=1)) / np.linalg.norm(P2[0])):.1e}")
    # 2. large, tilted and spinning, on small: the other direction, damped
    d, (sa, sb, ra, ca, cb, va, wa) = deck(2)
    path = rcval.run(d, name="tilted")
    r = rcval.Result(path)
    P, L, w = momenta(path, sa, sb, ra)
    ma, mb = mass(sa), mass(sb)
    P0 = ma * va
    L0 = ma * np.cross(ca, va) + inertia(sa, ra) @ wa
    e0 = float(np.linalg.norm(P[0] - P0) / np.linalg.norm(P0)) + float(np.linalg.norm(L[0] - L0) / np.linalg.norm(L0))
    eP = float(np.max(np.linalg.norm(P - P0, axis=1)) / np.linalg.norm(P0))
    eL = float(np.max(np.linalg.norm(L - L0, axis=1)) / np.linalg.norm(L0))
    closes = [t for t, k in zip(r.ev_t, r.ev_kind) if k == "contact_close"]
    touched = len(closes) > 0 and float(np.max(r.fn[:, 0])) > 0
    dv = float(np.linalg.norm(r.vel[-1, 1]))
    rcval.check("seg_seg_collide.tilted.contact", touched and dv > 0.1,
                f"contact closed at {closes[0] if closes else float('nan'):.6g} s, peak normal force "
                f"{float(np.max(r.fn[:, 0])):.4g} N, box B leaves at |v_B| = {dv:.4f} m/s")
    rcval.check("seg_seg_collide.tilted.momentum", eP < 1e-8 and e0 < 1e-12,
                f"linear momentum: max |P(t) - m_A v_A0| / |P0| = {eP:.1e} (< 1e-8); P0 = {np.round(P0, 6)} kg m/s")
    rcval.check("seg_seg_collide.tilted.angular_momentum", eL < 1e-8,
                f"angular momentum about the origin: max |L(t) - L0| / |L0| = {eL:.1e} (< 1e-8); L0 = "
                f"{np.round(L0, 6)} kg m^2/s (m_A x_A x v_A + J_A omega_A, the mesh's inertia)")
    rcval.check_ledger("seg_seg_collide.tilted.ledger", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(1)[0])
