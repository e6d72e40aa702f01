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
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from benchlib import A, B, C, G, K, M, MU, V0, ZETA, attrs, run_ok  # noqa: E402
from deck import Deck  # noqa: E402
import meshbox  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

PLATE = (1.0, 0.6)                 # plate size [m], centred at the origin, z = 0


def deck(meshed, slide, nx, ny, nplate, tend):
    p0 = M * G / K
    z0 = -p0
    d = Deck(f"box {'meshed' if meshed else 'analytic'} {'sliding' if slide else 'resting'}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k")
    # the analytic box: the same surface with its bottom face one quadrilateral
    nbox = meshbox.add_box(d, *((nx, ny) if meshed else (1, 1)), A, B, C, M, z0)
    nplate_seg = 0
    if meshed:
        nplate_seg = meshbox.add_floor(d, PLATE[0], PLATE[1], nplate, x0=-PLATE[0] / 2, title="plate (fixed)")
    else:
        d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the floor")
    if slide:
        d.inivel(1, (V0, 0.0, 0.0), 7)
    d.grav(1, "Z", -G)
    d.run(tend, tend / 20)
    return d, (nbox, nplate_seg)


def run(ricochet, path, out):
    wall = run_ok(ricochet, path, out)
    with Dataset(out) as nc:
        a = attrs(nc)
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
