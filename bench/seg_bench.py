#!/usr/bin/env python3
"""Segment-surface benchmark: a box whose bottom face is meshed into about
10^4 quadrilaterals, resting and sliding on a fixed plate meshed into about
10^4 quadrilaterals (segments against segments, node to segment both ways,
friction per contact point), against the same contact written with an
analytic plane (the box's eight corners against /SURF/PLANE). One run of
each; wall time of `ricochet run` (whole program: reading, set-up,
integration, netCDF output), the solver's counters from the results file.

    python3 bench/seg_bench.py [--n NX,NY] [--plate N] [--ricochet PATH] [--out DIR]

Writes the decks and results into DIR (default build/bench/seg) and prints
a table (bench/README.md, "Segment surfaces").
"""
import argparse
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from deck import Deck, i10, line  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

A, B, C = 0.2, 0.12, 0.08          # box [m]
M = 15.0                           # [kg]
K, ZETA, MU, G = 1.0e6, 0.7, 0.3, 9.81
PLATE = (1.0, 0.6)                 # plate size [m], centred at the origin, z = 0
V0 = 1.0                           # sliding: initial speed along x [m/s]


def box_nodes(nx, ny, z0):
    """Bottom grid nodes (ids 100000 + i (ny + 1) + j), top corners 90001..90004."""
    nodes, bottom = [], {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            nid = 100000 + i * (ny + 1) + j
            bottom[(i, j)] = nid
            nodes.append((nid, -A / 2 + A * i / nx, -B / 2 + B * j / ny, z0))
    top = {}
    for k, (sx, sy) in enumerate(((-1, -1), (1, -1), (1, 1), (-1, 1))):
        top[(sx, sy)] = 90001 + k
        nodes.append((90001 + k, sx * A / 2, sy * B / 2, z0 + C))
    return nodes, bottom, top


def deck(meshed, slide, nx, ny, nplate, tend):
    p0 = M * G / K
    z0 = -p0
    d = Deck(f"box {'meshed' if meshed else 'analytic'} {'sliding' if slide else 'resting'}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k")
    n = (nx, ny) if meshed else (1, 1)
    nodes, bottom, top = box_nodes(*n, z0)
    d.nodes([(1, 0.0, 0.0, z0 + C / 2)] + nodes)
    ids = [nd[0] for nd in nodes]
    d.grnod(7, ids, title="box nodes")
    Jx, Jy, Jz = M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12
    d.rbody(1, 1, M, (Jx, Jy, Jz), grnod=7, title="box")
    bx, by = n
    segs, sid = [], 1
    # bottom: normals down (out of the box)
    for i in range(bx):
        for j in range(by):
            q = (bottom[(i, j)], bottom[(i, j + 1)], bottom[(i + 1, j + 1)], bottom[(i + 1, j)])
            segs.append(line(*[("i", v) for v in (sid,) + q]))
            sid += 1
    c00, c10, c11, c01 = bottom[(0, 0)], bottom[(bx, 0)], bottom[(bx, by)], bottom[(0, by)]
    t00, t10, t11, t01 = top[(-1, -1)], top[(1, -1)], top[(1, 1)], top[(-1, 1)]
    for q in ((t00, t10, t11, t01), (c00, c10, t10, t00), (c10, c11, t11, t10), (c11, c01, t01, t11),
              (c01, c00, t00, t01)):
        segs.append(line(*[("i", v) for v in (sid,) + q]))
        sid += 1
    d.add("/SURF/SEG/30", *segs, title="box faces")
    if meshed:
        px, py = nplate, max(1, round(nplate * PLATE[1] / PLATE[0]))
        pn, pid = [], {}
        for i in range(px + 1):
            for j in range(py + 1):
                nid = 200000 + i * (py + 1) + j
                pid[(i, j)] = nid
                pn.append((nid, -PLATE[0] / 2 + PLATE[0] * i / px, -PLATE[1] / 2 + PLATE[1] * j / py, 0.0))
        d.nodes(pn)
        ps = [line(*[("i", v) for v in (k + 1, pid[(i, j)], pid[(i + 1, j)], pid[(i + 1, j + 1)], pid[(i, j + 1)])])
              for k, (i, j) in enumerate((i, j) for i in range(px) for j in range(py))]
        d.add("/SURF/SEG/40", *ps, title="plate (fixed)")
    else:
        d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the floor")
    if slide:
        d.inivel(1, (V0, 0.0, 0.0), 7)
    d.grav(1, "Z", -G)
    d.run(tend, tend / 20)
    return d, (sid - 1, len(ps) if meshed else 0)


def run(ricochet, path, out):
    t0 = time.perf_counter()
    p = subprocess.run([ricochet, "run", path, "-o", out, "-q"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    with Dataset(out) as nc:
        a = {k: nc.getncattr(k) for k in nc.ncattrs()}
        x = float(nc["body_position"][-1, 0, 0])
        v = float(nc["body_velocity"][-1, 0, 0])
    return wall, a, x, v


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", default="125,80", help="bottom face quadrilaterals along x, y")
    ap.add_argument("--plate", type=int, default=20, help="plate quadrilaterals along x (y in proportion)")
    ap.add_argument("--ricochet", default=os.path.join(ROOT, "build", "ricochet"))
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "seg"))
    ap.add_argument("--only", default="", help="analytic or meshed")
    ap.add_argument("--tslide", type=float, default=0.1, help="simulated time of the sliding runs [s] (the box stops "
                    "at V0 / (mu g) = 0.34 s)")
    ap.add_argument("--trest", type=float, default=0.2, help="simulated time of the resting runs [s]")
    args = ap.parse_args()
    nx, ny = (int(v) for v in args.n.split(","))
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for meshed in (False, True):
        if args.only and args.only != ("meshed" if meshed else "analytic"):
            continue
        for slide, tend in ((False, args.trest), (True, args.tslide)):
            d, (nbox, nplate) = deck(meshed, slide, nx, ny, args.plate, tend)
            name = f"{'meshed' if meshed else 'analytic'}_{'slide' if slide else 'rest'}"
            path = os.path.join(args.out, name + ".rad")
            d.write(path)
            wall, a, x, v = run(args.ricochet, path, os.path.join(args.out, name + ".nc"))
            rows.append((name, nbox, nplate, tend, wall, wall / tend, a.get("stats_steps"), a.get("stats_rhs_evals"),
                         a.get("stats_jac_evals"), x, v))
            print(f"{name:16s} box segments {nbox:6d}, plate segments {nplate:6d}: {tend:g} s simulated in {wall:.2f} s "
                  f"wall ({wall / tend:.2f} s per simulated s), steps {a.get('stats_steps')}, rhs "
                  f"{a.get('stats_rhs_evals')}, jacobians {a.get('stats_jac_evals')}; final x {x:.6f} m, v {v:.3e} m/s",
                  flush=True)
    # the sliding distance of the closed form: V0^2 / (2 mu g)
    print(f"closed form, sliding: stops after {V0 / (MU * G):.4f} s at x = {V0 * V0 / (2 * MU * G):.6f} m")


if __name__ == "__main__":
    main()
