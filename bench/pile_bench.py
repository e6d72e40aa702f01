#!/usr/bin/env python3
"""Active-part benchmark: N spheres dropped into a box (a floor and four
walls, fixed planes) with a TYPE6 interface between every pair of spheres
and between every sphere and every wall, most of which never touch: the
model's Jacobian pattern couples every body with every other, the Newton
matrix on the active part (docs/theory.md 7) only the touching ones.

    python3 bench/pile_bench.py [--layers L] [--side S] [--tend T] [--ricochet PATH ...] [--reps K] [--out DIR]

Each program in --ricochet (e.g. a build before the active part and one
after) runs the deck K times, interleaved; prints the best wall time, the
solver's counters and the final state's difference between the programs
(bench/README.md, "The Newton matrix on the active part").
"""
import argparse
import math
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from benchlib import attrs, run_ok  # noqa: E402
from deck import Deck  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

R, M, K, ZETA, G = 0.02, 0.05, 1.0e5, 0.5, 9.81


def pile_deck(layers, side, tend, seed=1):
    """side x side spheres per layer, layers above each other, a little apart
    and jittered so that they roll off each other into a pile."""
    rnd = random.Random(seed)
    pitch = 2.2 * R
    half = side * pitch / 2 + 0.2 * R     # the box's inner half-width
    d = Deck(f"bench: {layers * side * side} spheres into a box, all pairs in contact interfaces (pile_bench.py)")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    pos = []
    for lz in range(layers):
        for ix in range(side):
            for iy in range(side):
                x = -half + 0.2 * R + pitch * (ix + 0.5) + rnd.uniform(-0.1, 0.1) * R
                y = -half + 0.2 * R + pitch * (iy + 0.5) + rnd.uniform(-0.1, 0.1) * R
                z = R * 1.5 + lz * 2.6 * R + rnd.uniform(0.0, 0.2) * R
                pos.append((x, y, z))
    n = len(pos)
    d.nodes([(i + 1, *p) for i, p in enumerate(pos)])
    J = [0.4 * M * R * R] * 3
    for i in range(n):
        d.rbody(i + 1, i + 1, M, J, title=f"sphere {i + 1}")
        d.sphere(i + 1, i + 1, pos[i], R, title=f"sphere {i + 1}")
    walls = [((0, 0, 0), (0, 0, 1)), ((-half, 0, 0), (1, 0, 0)), ((half, 0, 0), (-1, 0, 0)),
             ((0, -half, 0), (0, 1, 0)), ((0, half, 0), (0, -1, 0))]
    for k, (p, nrm) in enumerate(walls):
        d.plane(n + 1 + k, p, tuple(p[c] + nrm[c] for c in range(3)), title=f"wall {k + 1}")  # M, M1: normal M1 - M
    c_w = 2 * ZETA * math.sqrt(K * M)
    c_s = 2 * ZETA * math.sqrt(K * M / 2)
    iid = 1
    for i in range(n):
        for k in range(len(walls)):
            d.type6(iid, i + 1, n + 1 + k, 1, visc=c_w, title=f"sphere {i + 1} - wall {k + 1}")
            iid += 1
    for i in range(n):
        for j in range(i + 1, n):
            d.type6(iid, i + 1, j + 1, 1, visc=c_s, title=f"spheres {i + 1}-{j + 1}")
            iid += 1
    d.grav(1, "Z", -G)
    d.run(tend, tend / 10)
    return d, n, iid - 1


def run(prog, path, out):
    wall = run_ok(prog, path, out)
    with Dataset(out) as nc:
        a = attrs(nc)
        pos = nc["body_position"][-1, :, :].filled()
        nev = len(nc.dimensions["event"]) if "event" in nc.dimensions else -1
    return wall, a, pos, nev


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--layers", type=int, default=3)
    ap.add_argument("--side", type=int, default=4)
    ap.add_argument("--tend", type=float, default=0.3)
    ap.add_argument("--reps", type=int, default=2)
    ap.add_argument("--ricochet", nargs="+", default=[os.path.join(ROOT, "build", "ricochet")])
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "pile"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    d, n, ni = pile_deck(args.layers, args.side, args.tend)
    path = os.path.join(args.out, f"pile{n}.rad")
    d.write(path)
    print(f"{n} spheres, {ni} interfaces, {args.tend} s simulated")
    best, res = {}, {}
    for rep in range(args.reps):
        for k, prog in enumerate(args.ricochet):
            wall, a, pos, nev = run(prog, path, os.path.join(args.out, f"pile{n}_{k}.nc"))
            best[k] = min(best.get(k, wall), wall)
            res[k] = (a, pos, nev)
            print(f"  rep {rep} prog {k}: {wall:.2f} s", flush=True)
    for k, prog in enumerate(args.ricochet):
        a, pos, nev = res[k]
        dpos = max(abs(float(v)) for v in (pos - res[0][1]).ravel())
        print(f"prog {k} ({prog}): best wall {best[k]:.2f} s; steps {a.get('stats_steps')}, jacobians "
              f"{a.get('stats_jac_evals')}, lin. setups {a.get('stats_lin_setups')}, events {a.get('stats_events')}, "
              f"restarts {a.get('stats_reinits')}, KLU analyses {a.get('stats_klu_analyses', '-')}, Newton entries "
              f"{a.get('stats_newton_nnz', '-')} of {a.get('stats_pattern_nnz', '-')}; max |x - x_prog0| {dpos:.3g} m")


if __name__ == "__main__":
    main()
