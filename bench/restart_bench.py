#!/usr/bin/env python3
"""The step after a restart, before and after: steps, right-hand sides,
error-test failures, integrator warnings and CPU time of the benchmark
decks (bench.py's sphere drop and settling column N = 100 over 5 s, at each
rtol given; seg_bench.py's analytic and meshed boxes; evcost_bench.py's
landing and sliding meshed boxes) run by several ricochet programs,
interleaved (A, B, A, B, ... per deck, --reps times), so that the programs
share the machine's load.

    /usr/bin/python3 bench/restart_bench.py --ricochet OLD --ricochet NEW [--reps 3] [--rtols 1e-6,1e-8]
        [--decks drop,column,seg,evcost] [--out DIR] [--method cvode|ida]

Prints one line per deck and program: the median CPU time (user + system)
over the repetitions and the counters of the results file (the same at every
repetition).
"""
import argparse
import os
import resource
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
import bench  # noqa: E402
import evcost_bench  # noqa: E402
import seg_bench  # noqa: E402
from netCDF4 import Dataset  # noqa: E402


def decks(which, rtols, out):
    paths = []
    for r in rtols:
        if "drop" in which:
            p = os.path.join(out, f"drop_rtol{r:g}.rad")
            bench.drop_deck(bench.drop_params(), r).write(p)
            paths.append(p)
        if "column" in which:
            p = os.path.join(out, f"col100_rtol{r:g}.rad")
            bench.column_deck(100, r).write(p)
            paths.append(p)
    if "seg" in which:
        for meshed, nx, ny in ((False, 1, 1), (True, 40, 24)):
            p = os.path.join(out, f"seg_{'meshed' if meshed else 'analytic'}_slide.rad")
            seg_bench.deck(meshed, True, nx, ny, 20, 0.1)[0].write(p)
            paths.append(p)
    if "evcost" in which:
        for case in ("land_plane", "slide_plane"):
            p = os.path.join(out, f"{case}_40x24.rad")
            evcost_bench.deck(case, 40, 24).write(p)
            paths.append(p)
    return paths


def run(prog, path, out, method):
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cmd = [prog, "run", path, "-o", out, "-q"] + (["--method", method] if method else [])
    p = subprocess.run(cmd, capture_output=True, text=True)
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    wall = (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)  # CPU time of the child [s]
    if p.returncode != 0:
        return wall, None, p.stderr.strip().splitlines()[-1:]
    with Dataset(out) as nc:
        a = {k: nc.getncattr(k) for k in nc.ncattrs()}
    return wall, a, p.stderr.count("t + h = t")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ricochet", action="append", required=True)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--rtols", default="1e-6,1e-8")
    ap.add_argument("--decks", default="drop,column,seg,evcost")
    ap.add_argument("--method", default="")
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "bench", "restart"))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    for path in decks(args.decks.split(","), [float(r) for r in args.rtols.split(",")], args.out):
        walls = {k: [] for k in range(len(args.ricochet))}
        info = {}
        for _ in range(args.reps):
            for k, prog in enumerate(args.ricochet):
                wall, a, warn = run(prog, path, os.path.join(args.out, f"out{k}.nc"), args.method)
                walls[k].append(wall)
                info[k] = (a, warn)
        name = os.path.basename(path)[:-4]
        for k in range(len(args.ricochet)):
            a, warn = info[k]
            if a is None:
                print(f"{name:28s} prog {k}: FAILED {warn}", flush=True)
                continue
            print(f"{name:28s} prog {k}: cpu {statistics.median(walls[k]):8.3f} s, steps {a['stats_steps']:7d}, "
                  f"rhs {a['stats_rhs_evals']:7d}, jac {a['stats_jac_evals']:5d}, err-test fails "
                  f"{a['stats_err_test_fails']:5d}, events {a['stats_events']:5d}, restarts {a['stats_reinits']:5d}, "
                  f"'t + h = t' warnings {warn}", flush=True)


if __name__ == "__main__":
    main()
