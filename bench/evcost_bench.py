#!/usr/bin/env python3
"""Event-cost benchmark: a meshed box (validation/lib/meshbox.py; its bottom
face in nx x ny quadrilaterals, (nx + 1)(ny + 1) bottom nodes) landing flat
on a floor (land_*), landing turning about y so that its nodes touch one row
after the other (tilt_*), and sliding on the floor to rest (slide_*), with the floor an analytic plane
(/SURF/PLANE) or a fixed meshed plate (/SURF/SEG, node to segment both ways).
TYPE6, linear load curve k = 1e6 N/m, zeta = 0.7, Fric = 0.3 (friction per
contact point), g = 9.81 m/s^2, no /SOLVER card (default settings).

    python3 bench/evcost_bench.py [--sizes 12x7,40x24,125x80] [--cases land_plane,...]
                                  [--ricochet PATH ...] [--out DIR]

Several --ricochet programs are run interleaved (program A, program B, A, B,
... for each deck), so that a before/after comparison shares the machine's
load. For each run: CPU time (user + system, of the child) and wall time of
`ricochet run` (whole program), the events (the results file's events
table), restarts, steps, Jacobians, and CPU time / events (the events' own
share of it is in the profiles that bench/HISTORY.md quotes).
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from benchlib import A, B, C, G, K, M, MU, V0, ZETA, attrs, run_timed  # noqa: E402
from deck import Deck  # noqa: E402
import meshbox  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

PLATE = (1.0, 0.6, 20)             # meshed floor: length, width [m], quadrilaterals along x
GAP = 1.0e-3                       # landing: initial gap of the bottom face [m]
T_LAND, T_SLIDE = 0.1, 0.45        # simulated [s]
W_TILT = 0.5                       # tilted landing: initial angular velocity about y [rad/s]


def deck(case, nx, ny):
    land = case.startswith("land") or case.startswith("tilt")
    meshed = case.endswith("mesh")
    z0 = GAP if land else -M * G / K
    d = Deck(f"box {nx}x{ny} {'landing on' if land else 'sliding on'} a {'meshed floor' if meshed else 'plane'}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    meshbox.add_box(d, nx, ny, A, B, C, M, z0)
    if meshed:
        meshbox.add_floor(d, *PLATE, x0=-0.3)
    else:
        d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the floor")
    if not land:
        d.inivel(1, (V0, 0.0, 0.0), 7)
    if case.startswith("tilt"):  # turning about y as it falls: the nodes touch one row after the other
        d.inivel(2, (0.0, W_TILT, 0.0), 7, rot=True)
    d.grav(1, "Z", -G)
    tend = T_LAND if land else T_SLIDE
    d.run(tend, tend / 20)
    return d


def run(ricochet, path, out):
    p, wall, cpu = run_timed(ricochet, path, out)
    warn = p.stderr.count("WARNING")
    if p.returncode != 0:
        return dict(wall=wall, fail=p.stderr.strip().splitlines()[-1] if p.stderr.strip() else str(p.returncode))
    with Dataset(out) as nc:
        a = attrs(nc)
        nev = len(nc.dimensions["event"])
        kinds = {}
        if nev:
            for k in nc["event_kind"][:]:
                kinds[str(k)] = kinds.get(str(k), 0) + 1
        x = float(nc["body_position"][-1, 0, 0])
        z = float(nc["body_position"][-1, 0, 2])
    return dict(wall=wall, cpu=cpu, events=nev, kinds=kinds, reinits=a.get("stats_reinits"), steps=a.get("stats_steps"),
                jac=a.get("stats_jac_evals"), x=x, z=z, warn=warn, fail=None)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--sizes", default="12x7,40x24,125x80", help="bottom-face quadrilaterals nx x ny, comma-separated")
    ap.add_argument("--cases", default="land_plane,land_mesh,tilt_plane,tilt_mesh,slide_plane,slide_mesh")
    ap.add_argument("--ricochet", action="append", help="program(s) to compare, interleaved (default build/ricochet)")
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "evcost"))
    args = ap.parse_args()
    progs = args.ricochet or [os.path.join(ROOT, "build", "ricochet")]
    os.makedirs(args.out, exist_ok=True)
    for size in args.sizes.split(","):
        nx, ny = (int(v) for v in size.split("x"))
        nodes = (nx + 1) * (ny + 1)
        for case in args.cases.split(","):
            path = os.path.join(args.out, f"{case}_{nx}x{ny}.rad")
            deck(case, nx, ny).write(path)
            for k, prog in enumerate(progs):
                r = run(prog, path, os.path.join(args.out, f"{case}_{nx}x{ny}_{k}.nc"))
                if r["fail"]:
                    print(f"{case:12s} {nodes:6d} nodes prog {k}: FAILED after {r['wall']:.2f} s: {r['fail']}",
                          flush=True)
                    continue
                per = r["cpu"] / r["events"] if r["events"] else float("nan")
                print(f"{case:12s} {nodes:6d} nodes prog {k}: cpu {r['cpu']:8.2f} s (wall {r['wall']:7.2f}), "
                      f"events {r['events']:5d}, "
                      f"restarts {r['reinits']:5d}, steps {r['steps']:6d}, jacobians {r['jac']:5d}, "
                      f"cpu/event {per * 1e3:9.2f} ms, warnings {r['warn']}, x {r['x']:.9f} z {r['z']:.9f} "
                      f"{r['kinds']}", flush=True)


if __name__ == "__main__":
    main()
