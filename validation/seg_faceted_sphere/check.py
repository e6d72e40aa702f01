"""A faceted sphere (/SURF/SEG on a sphere mesh) dropped on a plane converges
to the analytic sphere-plane drop as the mesh is refined.

Sphere of radius R, mass m, meshed by latitude rings about the x axis
(n_lon nodes a ring, n_lat = n_lon / 2 bands, quadrilaterals and polar
triangles), turned so that no node is at the bottom: the lowest nodes are
the two equator nodes at delta_n = R (1 - cos(pi / n_lon)) above the
analytic sphere's lowest point. The body (explicit mass and inertia, the
same for every mesh) falls from rest, the analytic sphere's lowest point
h0 above the plane z = 0, on a linear TYPE6 contact k without damping.

References (closed forms, README.md): the analytic sphere-plane drop
  - first contact t1 = sqrt(2 h0 / g), impact speed v = sqrt(2 g h0);
  - contact duration T_c = (2 pi - 2 atan(v w / g)) / w, w^2 = k / m;
and, for each mesh, the same closed forms with h0 + delta_n (the mesh's
lowest nodes are delta_n higher; the interface force is k P, P the largest
node penetration, whatever the number of nodes sharing it). The mesh
results must match their own closed form to 1e-6 and approach the
analytic sphere's at second order in 1/n_lon.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, R, K, G, H0 = 1.0, 0.05, 1.0e6, 9.81, 0.02
W = math.sqrt(K / M)
LEVELS = (8, 16, 32)
T_END = 0.1


def closed_form(h):
    v = math.sqrt(2 * G * h)
    t1 = math.sqrt(2 * h / G)
    tc = (2 * math.pi - 2 * math.atan(v * W / G)) / W
    return t1, t1 + tc


def sphere_mesh(n_lon):
    """Nodes (id, x, y, z) about the centre (0, 0, 0) and segments (id, n1..n4)."""
    n_lat = n_lon // 2
    nodes, segs = [(1000, -R, 0.0, 0.0), (1001, R, 0.0, 0.0)], []
    idx = {}
    for i in range(1, n_lat):
        th = math.pi * i / n_lat
        for j in range(n_lon):
            ph = (j + 0.5) * 2 * math.pi / n_lon
            nid = 1002 + (i - 1) * n_lon + j
            idx[i, j] = nid
            nodes.append((nid, -R * math.cos(th), R * math.sin(th) * math.cos(ph), R * math.sin(th) * math.sin(ph)))
    sid = 1
    for j in range(n_lon):
        j1 = (j + 1) % n_lon
        segs.append((sid, 1000, idx[1, j1], idx[1, j], idx[1, j]))
        sid += 1
        segs.append((sid, 1001, idx[n_lat - 1, j], idx[n_lat - 1, j1], idx[n_lat - 1, j1]))
        sid += 1
        for i in range(1, n_lat - 1):
            segs.append((sid, idx[i, j], idx[i, j1], idx[i + 1, j1], idx[i + 1, j]))
            sid += 1
    return nodes, segs


def deck(n_lon):
    d = Deck(f"faceted sphere (n_lon = {n_lon}) dropped on a plane")
    zc = R + H0
    nodes, segs = sphere_mesh(n_lon)
    d.nodes([(1, 0.0, 0.0, zc)] + [(i, x, y, z + zc) for i, x, y, z in nodes])
    d.grnod(1, [n[0] for n in nodes], title="sphere mesh nodes")
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="sphere 1 kg")
    d.add("/SURF/SEG/20", *[line(*[("i", v) for v in s]) for s in segs], title="faceted sphere")
    d.plane(10, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.type6(1, 20, 10, 1, title="faceted sphere on the floor")
    d.grav(1, "Z", -G)
    d.run(T_END, 1e-3)
    return d


def measure(n_lon):
    path = rcval.run(deck(n_lon), name=f"sphere{n_lon}")
    r = rcval.Result(path)
    with Dataset(path) as nc:
        omega = np.array(nc["body_angular_velocity"][:])
    t1 = r.events("contact_close")[0]
    t2 = r.contact_ends()[0]
    return t1, t2, float(np.abs(omega).max()), r


def main():
    ref = closed_form(H0)
    err1, err2 = [], []
    for n in LEVELS:
        delta = R * (1 - math.cos(math.pi / n))
        own = closed_form(H0 + delta)
        t1, t2, wmax, r = measure(n)
        e1, e2 = rcval.rel(t1, own[0]), rcval.rel(t2, own[1])
        rcval.check(f"seg_faceted_sphere.n{n}.own_closed_form", e1 < 1e-6 and e2 < 1e-6 and wmax < 1e-6,
                    f"n_lon = {n}: first contact {t1:.10f} s vs sqrt(2 (h0 + delta_n) / g) = {own[0]:.10f} s "
                    f"(rel. error {e1:.2e}), contact end {t2:.10f} s vs t1 + T_c = {own[1]:.10f} s (rel. error "
                    f"{e2:.2e}), both < 1e-6; max |omega| = {wmax:.1e} rad/s (< 1e-6: symmetric mesh, node coordinates written to 12 digits)")
        rcval.check_ledger(f"seg_faceted_sphere.n{n}.ledger", r, 1e-6)
        err1.append(abs(t1 - ref[0]) / ref[0])
        err2.append(abs((t2 - t1) - (ref[1] - ref[0])) / (ref[1] - ref[0]))
    orders = [math.log2(err1[k] / err1[k + 1]) for k in range(len(LEVELS) - 1)]
    ok = all(1.9 < o < 2.1 for o in orders) and err1[-1] < 1e-2
    rcval.check("seg_faceted_sphere.convergence_contact_time", ok,
                f"first contact vs the analytic sphere sqrt(2 h0 / g) = {ref[0]:.10f} s: rel. errors "
                f"{', '.join(f'{e:.3e}' for e in err1)} at n_lon = {', '.join(map(str, LEVELS))}, observed orders "
                f"{', '.join(f'{o:.3f}' for o in orders)} (expected 2: delta_n ~ pi^2 R / (2 n^2))")
    orders = [math.log2(err2[k] / err2[k + 1]) for k in range(len(LEVELS) - 1)]
    ok = all(1.8 < o < 2.2 for o in orders) and err2[-1] < 1e-3
    rcval.check("seg_faceted_sphere.convergence_contact_duration", ok,
                f"contact duration vs the analytic sphere's T_c = {ref[1] - ref[0]:.10f} s: rel. errors "
                f"{', '.join(f'{e:.3e}' for e in err2)}, observed orders {', '.join(f'{o:.3f}' for o in orders)} "
                f"(expected 2)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(LEVELS[-1]))
