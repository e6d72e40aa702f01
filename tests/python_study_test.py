"""Studies on a real Dask cluster (python/ricochet/study.py): a scheduler and
two worker processes started here (dask-scheduler, dask-worker --no-nanny,
on 127.0.0.1), a study of 20 variants of cases/t6_hysteresis_drop.rad
against serial ricochet.run bit for bit, a worker killed (SIGKILL) in the
middle of a study, an interrupted study resumed from its study_dir (the
cases done not run again), a directory of another study refused, the
command line's --study-dir, a KilledWorker recorded as status -2 (and
run again by the rerun). Every process started here is killed at the
end. Prints PASS/FAIL/SKIP lines (counted by scripts/check.sh).

    RICOCHET_LIB=build/libricochet.so PYTHONPATH=python /usr/bin/python3 tests/python_study_test.py build
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DECK = os.path.join(ROOT, "cases", "t6_hysteresis_drop.rad")
ZM = "/SURF/PLANE/2:ZM"
ZS = [round(-0.01 * i, 2) for i in range(20)]  # the floor 0 .. 0.19 m lower: drops of 0.2 .. 0.39 m
failed = 0
procs = []


def check(name, ok, detail=""):
    global failed
    print(("PASS " if ok else "FAIL ") + "pystudy." + name + (": " + detail if detail else ""), flush=True)
    failed += not ok


def guarded(name, fn, *a):
    try:
        return fn(*a)
    except Exception as e:  # noqa: BLE001
        import traceback
        traceback.print_exc()
        check(name, False, f"raised {type(e).__name__}: {e}")


def start(args, log, env=None):
    p = subprocess.Popen([sys.executable, "-m"] + args, stdout=log, stderr=subprocess.STDOUT,
                         stdin=subprocess.DEVNULL, env=env)
    procs.append(p)
    return p


def cluster(tmp, tag="", env=None):
    """A scheduler and two workers (no nanny: a SIGKILL of a worker is the
    loss of that process, nothing restarts it); returns (address, workers)."""
    # the cluster's temporary files (a killed worker leaves its case's
    # ricochet-run-*/ricochet-case-* behind) in the test's own directory
    env = dict(env or os.environ, TMPDIR=os.path.join(tmp, "tmp" + tag))
    os.makedirs(env["TMPDIR"], exist_ok=True)
    sf = os.path.join(tmp, f"scheduler{tag}.json")
    log = open(os.path.join(tmp, f"cluster{tag}.log"), "w")
    sched = start(["distributed.cli.dask_scheduler", "--host", "127.0.0.1", "--port", "0", "--dashboard-address",
                   ":0", "--scheduler-file", sf], log, env)
    t0 = time.time()
    while not os.path.exists(sf):
        if time.time() - t0 > 30 or sched.poll() is not None:
            raise RuntimeError("dask-scheduler did not start")
        time.sleep(0.1)
    time.sleep(0.2)
    with open(sf) as f:
        addr = json.load(f)["address"]
    ws = [start(["distributed.cli.dask_worker", addr, "--nworkers", "1", "--nthreads", "1", "--no-nanny",
                 "--dashboard-address", ":0", "--name", n + tag, "--local-directory", os.path.join(tmp, n + tag)],
                log, env)
          for n in ("wA", "wB")]
    return addr, ws


def serial(zs, **kw):
    import ricochet
    return [ricochet.run(DECK, set={ZM: z}, **kw) for z in zs]


def same_as_serial(st, runs):
    """Every case's final states, energies at the end and impact table equal
    the serial run's, bit for bit; returns the first difference or ''."""
    n_imp = st.sizes["impact"]
    for i, ds in enumerate(runs):
        for v in ("body_position", "body_quaternion", "body_velocity", "body_angular_velocity"):
            if not np.array_equal(st["final_" + v].values[i], ds[v].values[-1]):
                return f"case {i}: final_{v}"
        if st.final_time.values[i] != ds.time.values[-1]:
            return f"case {i}: final_time"
        for v in [k for k in st.data_vars if k.startswith("final_energy_")]:
            if st[v].values[i] != ds[v[6:]].values[-1]:
                return f"case {i}: {v}"
        if st.impact_count.values[i] != ds.sizes["impact"]:
            return f"case {i}: impact_count"
        for v in [k for k in st.data_vars if k.startswith("impact_") and k != "impact_count"]:
            a = ds[v].values[:n_imp]
            if not np.array_equal(st[v].values[i, :len(a)], a, equal_nan=True):
                return f"case {i}: {v}"
    return ""


def docs_worked_study(tmp):
    """docs/python.md's worked study, its code block run as written from the
    source tree's root: nine lines, approach speeds sqrt(2 g h) to 1e-4 m/s,
    rebounds within 2 mm below e^2 h."""
    import re
    import subprocess
    text = open(os.path.join(ROOT, "docs", "python.md")).read()
    sec = text[text.index("### A worked study"):]
    code = re.search(r"```python\n(.*?)```", sec, re.S).group(1)
    path = os.path.join(tmp, "worked.py")
    open(path, "w").write(code)
    r = subprocess.run([sys.executable, path], cwd=ROOT, capture_output=True, text=True, timeout=240)
    lines = [ln for ln in r.stdout.splitlines() if ln.startswith("h = ")]
    ok = r.returncode == 0 and len(lines) == 9
    worst_v = worst_h = 0.0
    for ln in lines:
        nums = [float(x) for x in re.findall(r"[-+]?\d+\.\d+", ln)]
        h, e, v, vr, reb, ref = nums[0], nums[1], nums[2], nums[3], nums[4], nums[5]
        worst_v = max(worst_v, abs(v - vr))
        worst_h = max(worst_h, ref - reb)
        ok = ok and abs(v - vr) <= 1e-4 and 0.0 <= ref - reb <= 2.0
    check("docs_worked_study", ok,
          f"exit {r.returncode}, {len(lines)} cases; |v_in - sqrt(2 g h)| <= {worst_v:.1e} m/s, "
          f"rebound below e^2 h by at most {worst_h:.1f} mm" + ("" if ok else ": " + (r.stderr or r.stdout)[-300:]))


def main():
    try:
        import distributed
    except ImportError:
        print("SKIP pystudy: python3-distributed not installed (scripts/install-deps.sh test installs it)")
        return 0
    import ricochet
    tmp = tempfile.mkdtemp(prefix="rc-pystudy-")
    client = None
    try:
        t_all = time.time()
        addr, ws = cluster(tmp)
        client = distributed.Client(addr, timeout=30)
        client.wait_for_workers(2, timeout=30)

        # 1. 20 cases against serial ricochet.run
        t0 = time.time()
        d1 = os.path.join(tmp, "full")
        full = ricochet.study(DECK, {ZM: ZS}, client=client, study_dir=d1)
        dt = time.time() - t0
        runs = serial(ZS)
        diff = same_as_serial(full, runs)
        check("serial_bitwise", (full.status.values == 0).all() and not diff and full.sizes["case"] == 20,
              f"20 cases on 2 workers ({dt:.1f} s) equal 20 serial ricochet.run: final states, energies, "
              f"impacts{'; differs: ' + diff if diff else ''}")
        man = json.load(open(os.path.join(d1, "study.json")))
        files = sorted(os.listdir(d1))
        check("study_dir_layout", len([f for f in files if f.endswith(".nc")]) == 20
              and len([f for f in files if f.endswith(".json")]) == 21 and man["deck"] == DECK
              and len(man["cases"]) == 20 and not [f for f in files if f.endswith(".part")],
              f"{d1}: study.json (deck sha256 {man['deck_sha256'][:12]}...), 20 case_NNNN.nc, 20 case_NNNN.json")

        # 2. interrupted, then resumed
        d2 = os.path.join(tmp, "resume")

        class Stop(Exception):
            pass
        seen = []

        def stop_after_6(i, status):
            seen.append(i)
            if len(seen) == 6:
                raise Stop()
        try:
            ricochet.study(DECK, {ZM: ZS}, client=client, study_dir=d2, on_case=stop_after_6)
            stopped = False
        except Stop:
            stopped = True
        done = sorted(int(f[5:9]) for f in os.listdir(d2) if f.startswith("case_") and f.endswith(".json"))
        mt = {f: os.stat(os.path.join(d2, f)).st_mtime_ns for f in os.listdir(d2)
              if f.startswith("case_") and int(f[5:9]) in done and not f.endswith(".part")}
        time.sleep(0.05)
        ran = []
        res = ricochet.study(DECK, {ZM: ZS}, client=client, study_dir=d2, on_case=lambda i, s: ran.append(i))
        same_files = all(os.stat(os.path.join(d2, f)).st_mtime_ns == t for f, t in mt.items())
        check("resume", stopped and len(done) >= 6 and sorted(ran) == [i for i in range(20) if i not in done]
              and same_files and len(mt) == 2 * len(done) and res.identical(full),
              f"stopped after {len(done)} cases; the rerun ran the {len(ran)} others, the {len(mt)} files of the "
              f"done ones untouched (mtimes), the Dataset identical to the full run's")
        ran.clear()
        again = ricochet.study(DECK, {ZM: ZS}, client=client, study_dir=d2, on_case=lambda i, s: ran.append(i))
        check("resume_complete", not ran and again.identical(full), "a complete study_dir: no case runs")

        # 3. another study in the same directory: refused
        errs = []
        for what, kw in (("parameters", {"parameters": {ZM: ZS[:-1] + [0.5]}}),
                         ("options", {"t_end": 1.0}), ("set", {"set": {"/INTER/TYPE6/1:Fric": 0.1}})):
            try:
                ricochet.study(DECK, kw.pop("parameters", {ZM: ZS}), client=client, study_dir=d2, **kw)
                errs.append(f"{what}: no error")
            except ricochet.StudyDirError as e:
                if "holds another study" not in str(e):
                    errs.append(f"{what}: {e}")
        other = os.path.join(tmp, "other.rad")
        with open(DECK) as f, open(other, "w") as g:
            g.write(f.read().replace("0,0,0.25", "0,0,0.26"))
        try:
            ricochet.study(other, {ZM: ZS}, client=client, study_dir=d2)
            errs.append("deck: no error")
        except ricochet.StudyDirError as e:
            if "deck differs" not in str(e):
                errs.append(f"deck: {e}")
        check("manifest_mismatch", not errs, "; ".join(errs) or
              "another deck (sha256), parameters, run options or set= in the directory: StudyDirError")

        # 4. the command line on the complete directory: nothing runs, the same file
        grid = os.path.join(tmp, "grid.json")
        with open(grid, "w") as f:
            json.dump({ZM: ZS}, f)
        out = os.path.join(tmp, "cli.nc")
        mt1 = {f: os.stat(os.path.join(d1, f)).st_mtime_ns for f in os.listdir(d1)}
        p = subprocess.run([sys.executable, "-m", "ricochet", "study", DECK, "--grid", grid, "--scheduler", addr,
                            "--study-dir", d1, "-o", out], capture_output=True, text=True, timeout=60)
        ok = p.returncode == 0 and mt1 == {f: os.stat(os.path.join(d1, f)).st_mtime_ns for f in os.listdir(d1)}
        if ok:
            import xarray as xr
            with xr.open_dataset(out) as s:
                ok = np.array_equal(s.final_body_position.values, full.final_body_position.values) and \
                    np.array_equal(s.impact_peak_force.values, full.impact_peak_force.values, equal_nan=True)
        check("cli_study_dir", ok, f"--study-dir on a complete directory: exit {p.returncode}, "
              f"{p.stdout.strip()}{p.stderr[-300:]}")

        # 5. a worker killed in the middle of a study (cases of ~0.4 s: t_end 10 s)
        zs = ZS[:12]
        killed = []

        def kill_first(i, status):
            if not killed:
                ws[0].send_signal(signal.SIGKILL)
                ws[0].wait(10)
                killed.append(i)
        t0 = time.time()
        st = ricochet.study(DECK, {ZM: zs}, client=client, t_end=10.0, on_case=kill_first)
        dt = time.time() - t0
        nw = len(client.scheduler_info()["workers"])
        diff = same_as_serial(st, serial(zs, t_end=10.0))
        check("worker_killed", killed and ws[0].returncode == -signal.SIGKILL and nw == 1
              and (st.status.values == 0).all() and not diff,
              f"worker wA killed (SIGKILL) after the first of 12 cases; {nw} worker left; every case ok "
              f"({dt:.1f} s) and equal to serial runs{'; differs: ' + diff if diff else ''}")
        client.close(timeout=5)
        client = None

        # 6. KilledWorker: a scheduler that allows no failure (allowed-failures 0) gives up the
        # cases of a killed worker: they are status -2, the study goes on; the rerun on its
        # study_dir runs just those
        env = dict(os.environ, DASK_DISTRIBUTED__SCHEDULER__ALLOWED_FAILURES="0")
        addr2, ws2 = cluster(tmp, "-kw", env)
        client = distributed.Client(addr2, timeout=30)
        client.wait_for_workers(2, timeout=30)
        zs, killed = ZS[:8], []

        def kill_a(i, status):
            if not killed:
                ws2[0].send_signal(signal.SIGKILL)
                ws2[0].wait(10)
                killed.append(i)
        d3 = os.path.join(tmp, "killed")
        st = ricochet.study(DECK, {ZM: zs}, client=client, t_end=10.0, study_dir=d3, on_case=kill_a)
        lost = [i for i in range(len(zs)) if st.status.values[i] == -2]
        msg_ok = all("KilledWorker" in str(st.message.values[i]) for i in lost)
        others_ok = all(st.status.values[i] == 0 for i in range(len(zs)) if i not in lost)
        ran = []
        st2 = ricochet.study(DECK, {ZM: zs}, client=client, t_end=10.0, study_dir=d3,
                             on_case=lambda i, s: ran.append(i))
        check("killed_worker_status", lost and msg_ok and others_ok and sorted(ran) == lost
              and (st2.status.values == 0).all() and st.attrs["failed_cases"] == len(lost),
              f"allowed-failures 0, worker killed: cases {lost} status -2 (KilledWorker), the "
              f"{len(zs) - len(lost)} others ok; the rerun on the study_dir ran just {sorted(ran)}, all ok")
        client.close(timeout=5)
        client = None

        # 7. the docs' worked study, as written (its own LocalCluster of 2)
        guarded("docs_worked_study", docs_worked_study, tmp)
        print(f"pystudy: {time.time() - t_all:.1f} s in all")
    finally:
        if client is not None:
            try:
                client.close(timeout=5)
            except Exception:  # noqa: BLE001
                pass
        for p in procs:
            if p.poll() is None:
                p.kill()
        for p in procs:
            try:
                p.wait(10)
            except subprocess.TimeoutExpired:
                check("cleanup", False, f"process {p.pid} did not end")
        shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rc = guarded("main", main)
    sys.exit(1 if failed or rc is None else rc)
