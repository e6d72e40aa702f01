"""Pieces shared by the benchmark scripts (seg_bench.py, evcost_bench.py,
pile_bench.py): the box-on-a-floor setting of the meshed-box benchmarks and
a timed `ricochet run`."""
import resource
import subprocess
import time

# the meshed-box benchmarks (seg_bench.py, evcost_bench.py)
A, B, C = 0.2, 0.12, 0.08          # box [m]
M = 15.0                           # [kg]
K, ZETA, MU, G = 1.0e6, 0.7, 0.3, 9.81
V0 = 1.0                           # sliding: initial speed along x [m/s] (stops at V0 / (mu g) = 0.34 s)


def run_timed(prog, path, out):
    """Run `prog run path -o out -q`: the finished process (its output
    captured), the wall time [s] of the run and its CPU time [s] (user +
    system of the child)."""
    c0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    p = subprocess.run([prog, "run", path, "-o", out, "-q"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    c1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return p, wall, (c1.ru_utime - c0.ru_utime) + (c1.ru_stime - c0.ru_stime)


def run_ok(prog, path, out):
    """run_timed, raising RuntimeError with ricochet's messages when the run
    fails; the wall time [s]."""
    p, wall, _ = run_timed(prog, path, out)
    if p.returncode != 0:
        raise RuntimeError(p.stderr)
    return wall


def attrs(nc):
    """The global attributes of an open results file (the solver's counters
    stats_*), as a dict."""
    return {k: nc.getncattr(k) for k in nc.ncattrs()}
