"""Study throughput (python/ricochet/study.py) against bare runs of the same
cases: N variants of a deck (the floor height /SURF/PLANE/2:ZM), run

  - bare:    `ricochet run CASE --set ... -o X.nc -q`, one process after another
  - run():   ricochet.run in this process, one after another
  - study:   ricochet.study on a LocalCluster of 1 and of 2 worker processes
             (the cluster started once, outside the timed study; its start
             is timed apart), without and with a study_dir

and prints a table: wall time, cases/s, and the per-case overhead of the
study over a bare run (wall x workers / N - the bare run's time per case).

    RICOCHET_LIB=build/libricochet.so PYTHONPATH=python \\
        /usr/bin/python3 bench/study.py [--prog build/ricochet] [--n 40] [--t-end T] [--repeat 2]
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
import warnings

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ZM = "/SURF/PLANE/2:ZM"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--prog", default=os.path.join(ROOT, "build", "ricochet"))
    ap.add_argument("--deck", default=os.path.join(ROOT, "cases", "t6_hysteresis_drop.rad"))
    ap.add_argument("--n", type=int, default=40, help="cases (default 40)")
    ap.add_argument("--t-end", type=float, help="end time of every case [s] (default: the deck's)")
    ap.add_argument("--repeat", type=int, default=2, help="best of REPEAT (default 2)")
    a = ap.parse_args()
    import ricochet
    from distributed import Client, LocalCluster
    zs = [-0.19 * i / max(a.n - 1, 1) for i in range(a.n)]
    kw = {} if a.t_end is None else {"t_end": a.t_end}
    tmp = tempfile.mkdtemp(prefix="rc-bench-study-")
    rows = []

    def best(fn):
        ts = []
        for _ in range(a.repeat):
            t0 = time.perf_counter()
            fn()
            ts.append(time.perf_counter() - t0)
        return min(ts)

    def bare():
        for i, z in enumerate(zs):
            cmd = [a.prog, "run", a.deck, "-q", "--set", f"{ZM}={z!r}", "-o", os.path.join(tmp, f"b{i}.nc")]
            if a.t_end is not None:
                cmd += ["--t-end", repr(a.t_end)]
            subprocess.run(cmd, check=True)
    t_bare = best(bare)
    per = t_bare / a.n
    rows.append(("bare `ricochet run`, one after another", 1, t_bare, ""))

    def inproc():
        for z in zs:
            ricochet.run(a.deck, set={ZM: z}, **kw)
    t_run = best(inproc)
    rows.append(("`ricochet.run` in one process", 1, t_run, ""))

    for w in (1, 2):
        t0 = time.perf_counter()
        cluster = LocalCluster(n_workers=w, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        t_start = time.perf_counter() - t0
        ricochet.study(a.deck, {ZM: zs[:w]}, client=client, **kw)  # the workers import ricochet once
        t_st = best(lambda: ricochet.study(a.deck, {ZM: zs}, client=client, **kw))
        rows.append((f"study, LocalCluster of {w} (its start: {t_start:.2f} s)", w, t_st, ""))

        def with_dir():
            d = os.path.join(tmp, f"dir{w}")
            shutil.rmtree(d, ignore_errors=True)
            ricochet.study(a.deck, {ZM: zs}, client=client, study_dir=d, **kw)
        t_dir = best(with_dir)
        rows.append((f"study with study_dir, {w} worker{'s' if w > 1 else ''}", w, t_dir, ""))
        d = os.path.join(tmp, f"dir{w}")
        t_resume = best(lambda: ricochet.study(a.deck, {ZM: zs}, client=client, study_dir=d, **kw))
        rows.append((f"the same rerun, every case done (read back), {w} worker{'s' if w > 1 else ''}", 0,
                     t_resume, ""))
        client.close()
        cluster.close()
    shutil.rmtree(tmp, ignore_errors=True)

    te = f"t_end {a.t_end} s" if a.t_end is not None else "the deck's t_end"
    print(f"{a.n} cases of {os.path.basename(a.deck)} ({te}), best of {a.repeat}; bare run {per * 1e3:.1f} ms/case\n")
    print("| how | wall [s] | cases/s | per case [ms] | overhead per case over a bare run [ms] |")
    print("|---|---|---|---|---|")
    for name, w, t, _ in rows:
        pc = t / a.n * max(w, 1)
        ov = f"{(pc - per) * 1e3:+.1f}" if w >= 1 and name.startswith("study") else ""
        print(f"| {name} | {t:.2f} | {a.n / t:.1f} | {pc * 1e3:.1f} | {ov} |")


if __name__ == "__main__":
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sys.exit(main())
