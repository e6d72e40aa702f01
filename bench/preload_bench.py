#!/usr/bin/env python3
"""The preload against dynamic settling: a column of N spheres (default 100)
stacked touching on a floor with its contacts unloaded (the deck's
positions; R = 2^-7 m so that the centres 2R apart are exact binary numbers
and every gap is exactly zero: a static solve needs every body supported at
its start, and a gap of rounding would leave a sphere floating), locked to z
(/BCS 110 111), critically damped linear contacts, gravity. How long does it
take to get it settled?

- preload: /SOLVER Preload 1 (the static equilibrium at t = 0, KINSOL),
  then a dynamic run of one output interval (DT_OUT) from it;
- dynamic: the same deck without the preload, run until every velocity
  stays below V_THR = 1e-2 g / omega (omega = sqrt(k / m), g / omega the
  speed a sphere reaches when its contact takes its weight at once; the
  tolerances of bench.py's column: atol_pos = 1e-3 rtol m, atol_vel = rtol
  m/s, so that the speeds are resolved well below V_THR): the
  settling time t_s is the first output time after which every record's
  max |v| is below V_THR (a scan to T_SCAN), then a run to t_s timed alone.

Prints the wall and CPU times of the ricochet processes (CLI: reading,
set-up, solve, output) and the solve's own time (the preload's from the
summary line, the dynamic run's from stats_wall_time), and the contact
forces' error against the exact statics F_j = (N - j + 1) m g at the end,
max over contacts / (N m g).

    /usr/bin/python3 bench/preload_bench.py [--prog build/ricochet] [--n 100] [--repeat 3]
"""
import argparse
import math
import os
import re
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "validation", "lib"))
from deck import Deck  # noqa: E402

R, M, K, ZETA, G = 0.0078125, 0.01, 1.0e5, math.sqrt(2.0), 9.81   # bench.py's Case 2, R = 2^-7 m
DT_OUT, T_SCAN = 0.01, 60.0
RTOL = 1e-6
V_THR = 1e-2 * G / math.sqrt(K / M)


def deck(N, preload, tend):
    d = Deck(f"bench: column of {N} spheres touching, unloaded" + (", preloaded" if preload else ""))
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    z = [R + 2.0 * R * i for i in range(N)]
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(N)])
    for i in range(N):
        d.rbody(i + 1, i + 1, M, [0.4 * M * R * R] * 3, title=f"sphere {i + 1}")
    for i in range(N):
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
    d.plane(N + 1, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.grav(1, "Z", -G)
    d.grnod(1, list(range(1, N + 1)), title="all spheres")
    d.bcs(1, 1, trarot="110 111", title="x, y and rotations held")
    d.type6(1, 1, N + 1, 1, visc=2 * ZETA * math.sqrt(K * M), title="floor contact")
    for i in range(1, N):
        d.type6(i + 1, i, i + 1, 1, visc=2 * ZETA * math.sqrt(K * M / 2), title=f"spheres {i}-{i + 1}")
    d.run(tend, DT_OUT)
    d.solver(rtol=RTOL, atol_pos=1e-3 * RTOL, atol_vel=RTOL, atol_energy=RTOL, max_steps=10**7,
             preload=1 if preload else 0)
    return d


def run(prog, path, out, extra=()):
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run([prog, "run", path, "-o", out] + list(extra), capture_output=True, text=True)
    wall = time.perf_counter() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    return p.stdout, wall, (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)


def force_error(out, N):
    with Dataset(out) as nc:
        f = np.array(nc["inter_force_normal"][-1, :])
        ids = list(np.array(nc["inter_id"][:]))
    ref = np.array([(N - j) * M * G for j in range(N)])
    got = np.array([f[ids.index(j + 1)] for j in range(N)])
    return float(np.abs(got - ref).max() / (N * M * G))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--prog", default=os.path.join(HERE, "..", "build", "ricochet"))
    ap.add_argument("--n", type=int, default=100)
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    N, w = a.n, tempfile.mkdtemp(prefix="preload_bench_")
    # the dynamic settling time: one scan
    scan = os.path.join(w, "scan.rad")
    deck(N, False, T_SCAN).write(scan)
    run(a.prog, scan, os.path.join(w, "scan.nc"), ["-q"])
    with Dataset(os.path.join(w, "scan.nc")) as nc:
        t = np.array(nc["time"][:])
        v = np.abs(np.array(nc["body_velocity"][:])).max(axis=(1, 2))
    above = np.nonzero(v >= V_THR)[0]
    if len(above) == 0 or above[-1] + 1 >= len(t):
        sys.exit(f"not settled below {V_THR:.3g} m/s within {T_SCAN} s (max |v| at the end {v[-1]:.3g})")
    ts = float(t[above[-1] + 1])
    dyn = os.path.join(w, "dyn.rad")
    deck(N, False, ts).write(dyn)
    pre = os.path.join(w, "pre.rad")
    deck(N, True, DT_OUT).write(pre)
    best = {"dyn": [math.inf] * 3, "pre": [math.inf] * 3}
    for _ in range(a.repeat):  # interleaved
        for key, path in (("dyn", dyn), ("pre", pre)):
            out = os.path.join(w, key + ".nc")
            so, wall, cpu = run(a.prog, path, out)
            if key == "pre":
                solve = float(re.search(r"preload: .*?(\d+) Newton iterations in ([0-9.eE+-]+) s wall", so).group(2))
                iters = int(re.search(r"preload: .*?(\d+) Newton iterations", so).group(1))
            else:
                with Dataset(out) as nc:
                    solve = float(nc.getncattr("stats_wall_time"))
                    steps = int(nc.getncattr("stats_steps"))
            b = best[key]
            best[key] = [min(b[0], wall), min(b[1], cpu), min(b[2], solve)]
    e_dyn, e_pre = force_error(os.path.join(w, "dyn.nc"), N), force_error(os.path.join(w, "pre.nc"), N)
    with Dataset(os.path.join(w, "pre.nc")) as nc:
        vpre = float(np.abs(np.array(nc["body_velocity"][:])).max())
    print(f"column of {N} spheres (R = {R} m, m = {M} kg, k = {K:.0e} N/m, zeta = {ZETA:.3g}), rtol {RTOL:g}, "
          f"best of {a.repeat}")
    print(f"dynamic settling: max |v| < {V_THR:.3g} m/s from t_s = {ts:g} s; run to t_s: CLI wall {best['dyn'][0]*1e3:.1f} ms, "
          f"CPU {best['dyn'][1]*1e3:.1f} ms, integration {best['dyn'][2]*1e3:.1f} ms, {steps} steps, force error {e_dyn:.2e}")
    print(f"preload: {iters} Newton iterations, solve {best['pre'][2]*1e3:.2f} ms; with a dynamic run of {DT_OUT:g} s: "
          f"CLI wall {best['pre'][0]*1e3:.1f} ms, CPU {best['pre'][1]*1e3:.1f} ms; max |v| {vpre:.2g} m/s, force error {e_pre:.2e}")
    print(f"ratio dynamic / preload: CLI wall {best['dyn'][0]/best['pre'][0]:.1f}x, CPU {best['dyn'][1]/best['pre'][1]:.1f}x, "
          f"solve (integration to t_s / preload solve) {best['dyn'][2]/best['pre'][2]:.0f}x")


if __name__ == "__main__":
    main()
