#!/usr/bin/python3
"""Physics scene fuzzer for ricochet: seeded random scenes, run, checked
against physical invariants (README.md).

  scenefuzz.py run --scenes N --seed S [--jobs J] [--out DIR] [--kinds a,b] [--timeout T]
                   [--variant-fraction F] [--variants frame,units,ida,rtol] [--strict]
  scenefuzz.py one --seed S [--kind K] [--out DIR]        one scene, every variant, verbose
  scenefuzz.py replay DIR|FILE...                          the regression decks, same invariants
  scenefuzz.py check --scenes N --seed S [--jobs J]        the make-check sample (PASS/FAIL/XFAIL lines)
  scenefuzz.py minimise --seed S [--kind K] --inv KEY [-o FILE]   shrink a failing scene
  scenefuzz.py deck --seed S [--kind K] [--variant frame|units] -o FILE
  scenefuzz.py summary DIR [-v]                            tables of a run's report.json

Scene i of `run --seed S` has the seed S * 1000000 + i; `one --seed` that
number regenerates it. Only numpy and netCDF4 besides the standard library.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import copy
import datetime
import json
import math
import multiprocessing
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import deckwriter as DW  # noqa: E402
import invariants as INV  # noqa: E402
import scenes as SC  # noqa: E402

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DEFAULT_BIN = os.path.join(ROOT, "build", "ricochet")
VARIANTS = ("frame", "units", "ida", "rtol")
UNIT_SYSTEMS = [("g", "mm", "ms"), ("kg", "mm", "s"), ("t", "mm", "s"), ("g", "cm", "s"), ("kg", "mm", "ms"),
                ("mg", "mm", "ms")]
RTOL_BASE, RTOL_LOOSE, RTOL_TIGHT = 1e-8, 1e-6, 1e-10
EPS = 2.0 ** -52


# --------------------------------------------------------------------------
# variants


def choose_variants(seed, fraction, allowed=VARIANTS):
    """Which comparison variants a scene runs, and their parameters, from
    the generator seeded with (seed, 2): every draw is made whatever is
    selected, so a seed's choice does not depend on the options."""
    rng = np.random.default_rng([int(seed), 2])
    pick = {v: rng.random() < fraction for v in VARIANTS}
    R = DW.random_rotation(rng)
    direction = rng.normal(size=3)
    direction /= np.linalg.norm(direction)
    t = direction * rng.uniform(800.0, 1200.0)
    units = UNIT_SYSTEMS[int(rng.integers(len(UNIT_SYSTEMS)))]
    out = {}
    if pick["frame"] and "frame" in allowed:
        out["frame"] = {"R": [list(map(float, r)) for r in R], "t": [float(x) for x in t]}
    if pick["units"] and "units" in allowed:
        out["units"] = list(units)
    if pick["ida"] and "ida" in allowed:
        out["ida"] = True
    if pick["rtol"] and "rtol" in allowed:
        out["rtol"] = True
    return out


def all_variants(seed):
    return choose_variants(seed, 1.1)


def _small_rotation(angle, rng):
    """A rotation by angle [rad] about a random axis (Rodrigues)."""
    a = rng.normal(size=3)
    a /= np.linalg.norm(a)
    K = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    return np.eye(3) + math.sin(angle) * K + (1.0 - math.cos(angle)) * (K @ K)


def perturb(scene, eps, rng):
    """The scene with every body (its centre, surfaces, nodes and joint
    points) moved rigidly by a random vector of length eps and turned about
    its centre by a random angle eps / L: the size of the rounding a variant
    makes, as a yardstick for chaotic scenes. The turn matters where the
    scene is symmetric: a box spinning flat on the floor keeps w_x = w_y = 0
    exactly in the deck's own frame, while the rounding of a turned frame
    tilts it, and an unstable flat spin then rocks (a translation alone
    leaves it flat and the yardstick blind). Its velocity is rounded too, by
    a random vector of length eps |v| / L: a sliding box hopping on an
    elastic floor under a pressure-strengthening friction law trips at a
    time that a change of 1e-14 m/s in its start decides (179000179), while
    the positions' rounding alone happened to leave it within the
    yardstick."""
    s = copy.deepcopy(scene)
    L = float(scene["scales"]["L"]) or 1.0
    move = {}
    for b in s["bodies"]:
        d = rng.normal(size=3)
        d *= eps / np.linalg.norm(d)
        Rb = _small_rotation(eps / L, rng)
        c0 = np.asarray(b["x"], float)
        move[b["id"]] = (c0, c0 + d, Rb)
        b["x"] = list(c0 + d)
        v = np.asarray(b["v"], float)
        dv = rng.normal(size=3)
        b["v"] = list(v + dv * (eps * np.linalg.norm(v) / L / np.linalg.norm(dv)))
        b["w"] = list(Rb @ np.asarray(b["w"], float))
        J = Rb @ np.asarray(b["J"], float) @ Rb.T
        b["J"] = [list(r) for r in 0.5 * (J + J.T)]

    def P(bid, x):
        c0, c1, Rb = move[bid]
        return list(c1 + Rb @ (np.asarray(x, float) - c0))

    def D(bid, x):
        return list(move[bid][2] @ np.asarray(x, float))

    for n in s.get("nodes", []):
        if n.get("body"):
            n["x"] = P(n["body"], n["x"])
    for f in s["surfaces"]:
        if f.get("body"):
            for key in ("c", "p"):
                if key in f:
                    f[key] = P(f["body"], f[key])
            for key in ("n", "u", "v", "axis"):
                if key in f:
                    f[key] = D(f["body"], f[key])
    for j in s.get("joints", []):
        if j.get("b1"):
            j["p"] = P(j["b1"], j["p"])
            if "axis" in j:
                j["axis"] = D(j["b1"], j["axis"])
        if j.get("b2") and "p2" in j:
            j["p2"] = P(j["b2"], j["p2"])
    return s


def scene_extent(scene):
    xs = [np.abs(np.asarray(b["x"])).max() for b in scene["bodies"]]
    return max(xs + [scene["scales"]["L"]])


# --------------------------------------------------------------------------
# running


REGRESSION_TIMEOUT = 60.0  # [s] of CPU: the least time limit of a regression deck in `check`
MAX_OUTPUT_MB = 200.0   # a results file larger than this stops the run (a_output_size)
KEEP_NC_MB = 20.0       # results files kept with a violating scene, in all


def proc_cpu(pid):
    """CPU time [s] (user + system) a running process has used so far, from
    /proc (0 where it cannot be read)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    except (OSError, IndexError, ValueError):
        return 0.0


# A run is stopped past `timeout` seconds of its own CPU time, or past this
# many times `timeout` on the wall clock (a run that waits rather than
# computes): on a loaded machine the wall clock measures the machine.
WALL_TIMEOUT_FACTOR = 4.0


def run_deck(text, workdir, name, ricochet, args=(), timeout=60.0):
    """Write and run one deck. Returns a dict with the exit code, stderr,
    wall time, whether it timed out or outgrew MAX_OUTPUT_MB, and the loaded
    results. The results file is watched while the run goes: a scene of a
    few seconds has no business writing hundreds of megabytes (a disk filled
    by one run stops every other one)."""
    deck = os.path.join(workdir, name + ".rad")
    out = os.path.join(workdir, name + ".nc")
    with open(deck, "w") as f:
        f.write(text)
    cmd = [ricochet, "run", deck, "-o", out, "-q"] + list(args)
    t0 = time.time()
    ru0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    errf = open(os.path.join(workdir, name + ".stderr"), "w+")
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=errf, cwd=workdir)
    timed_out = 0.0
    too_large = 0.0
    while p.poll() is None:
        try:
            p.wait(timeout=0.2)
        except subprocess.TimeoutExpired:
            pass
        size = os.path.getsize(out) / 1e6 if os.path.exists(out) else 0.0
        if proc_cpu(p.pid) > timeout or time.time() - t0 > WALL_TIMEOUT_FACTOR * timeout or size > MAX_OUTPUT_MB:
            if size > MAX_OUTPUT_MB:
                too_large = size
            else:
                timed_out = timeout
            p.send_signal(signal.SIGTERM)     # ricochet closes its results file on SIGTERM
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
            break
    wall = time.time() - t0
    ru1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (ru1.ru_utime - ru0.ru_utime) + (ru1.ru_stime - ru0.ru_stime)
    errf.seek(0)
    se = errf.read()[-20000:]
    errf.close()
    res = INV.load(out) if (os.path.exists(out) and os.path.getsize(out) <= 2e6 * MAX_OUTPUT_MB) else None
    steps = int(res["attrs"].get("stats_steps", -1)) if res else -1
    return {"name": name, "rc": p.returncode, "stderr": se, "wall": wall, "cpu": cpu, "timed_out": timed_out,
            "too_large": too_large, "res": res, "steps": steps, "args": list(args), "deck": deck}


def with_atol_position(text, atol):
    """The deck text (SI units, no /SOLVER card of its own) with a /SOLVER
    card giving the position tolerance atol [m] (the other fields blank:
    their defaults and derived values)."""
    if "\n/SOLVER" in text:
        raise ValueError("the deck has a /SOLVER card already")
    k = text.index("\n/RUN")
    return text[:k] + f"\n/SOLVER\n\n{atol:20.6e}" + text[k:]


def base_args(scene):
    return ["--method", scene["method"]] if scene.get("method") else []


def process(scene, variants, ricochet, timeout=60.0, keep_dir=None, keep_all=False, base_text=None, log=None):
    """Run a scene and its variants, check every invariant. Returns the
    scene's record (JSON-serialisable)."""
    work = tempfile.mkdtemp(prefix="physfuzz-")
    rec = {"seed": scene["seed"], "kind": scene["kind"], "notes": scene.get("notes", []), "violations": [],
           "runs": {}, "variants": sorted(variants)}
    V = rec["violations"]
    runs = {}
    pcache = {}

    def do(name, text, args):
        r = run_deck(text, work, name, ricochet, args, timeout)
        runs[name] = r
        rec["runs"][name] = {"rc": r["rc"], "wall": round(r["wall"], 3), "cpu": round(r["cpu"], 3), "steps": r["steps"],
                             "args": r["args"],
                             "timed_out": r["timed_out"]}
        vn = r["res"]["attrs"].get("vibration_note") if r["res"] is not None else None
        if vn:
            rec["runs"][name]["vibration_note"] = str(vn)
        if r["too_large"]:
            V.append(INV.viol("a_output_size", name, f"the results file grew past {MAX_OUTPUT_MB:g} MB "
                              f"({r['too_large']:.0f} MB after {r['wall']:.1f} s of a {scene['run']['tend']:.3g} s "
                              f"scene, {r['steps']} steps): run stopped", size_mb=r["too_large"]))
        if log:
            log(f"  run {name:8s} exit {r['rc']}  {r['wall']:.2f} s  {r['steps']} steps  {' '.join(args)}")
        return r

    def perturbed(name, eps):
        """The base scene perturbed by eps (perturb), run once per name."""
        if name not in pcache:
            rng = np.random.default_rng([int(scene["seed"]), 3])
            pcache[name] = do(name, DW.write(perturb(scene, eps, rng)), base_args(scene))
        return pcache[name]

    def floor2():
        """The base with its position tolerance at twice the floor the
        engine raised it to (the results file's atol_position_floor), run
        once; None where the base is not floored or the run fails."""
        if "floor2" not in pcache:
            fl = float(b["res"]["attrs"].get("atol_position_floor", 0.0))
            rf = None
            if fl > 0 and "\n/SOLVER" not in text:
                rf = do("floor2", with_atol_position(text, 2.0 * fl), base_args(scene))
            pcache["floor2"] = rf["res"] if rf is not None and rf["rc"] == 0 else None
        return pcache["floor2"]

    def recheck_floored(key, viol, r, frame=None):
        """A variant beyond its yardsticks where the base's position
        tolerance sits at the coordinates' rounding: rtol no longer refines
        the positions (the tight run repeats the base step for step), and
        the floor, which the variant has at its own value, sets their
        accuracy. Accept the variant within 10 x the base's distance from
        the base with that floor doubled, as i_rtol does (a box hopping down
        an incline, 217000236: base and tight identical step for step, the
        frame's floor 2.3e-16 m against the base's 3.5e-16 m; that scene's
        frame variant, 4.6e-6 m away at 8 ms, stays beyond this yardstick
        too)."""
        if not viol:
            return viol
        rf = floor2()
        if rf is None:
            return viol
        v2 = INV.compare(scene, key, b["res"], r["res"], tight["res"], frame=frame,
                         extra_yard=INV.distance(b["res"], rf, scene))
        for v in v2:
            v["msg"] += " (and beyond 10 x the base's distance from the base with its position floor doubled)"
        return v2

    def events(key, r, name, eps):
        """compare_events, with the perturbed base as a yardstick when the
        counts differ. The start's events: up to the time the scene's speed
        scale takes to move 100 of the variant's roundings eps (a touching
        pair that the rounding leaves a gap of eps apart and approaching
        closes a touch band later, where the base closed it at t = 0: a
        cradle 1 km out, its first pair closed at 2.3e-11 s)."""
        vs = float(scene["scales"].get("v", 0.0) or 0.0)
        t0 = 100.0 * eps / vs if vs > 0 else 0.0
        v = INV.compare_events(key, b["res"], r["res"], tight["res"], t_start=t0)
        if v:
            rp = perturbed(name, eps)
            if rp["rc"] == 0 and rp["res"] is not None:
                v = INV.compare_events(key, b["res"], r["res"], tight["res"], perturbed=rp["res"], t_start=t0)
        return v

    try:
        text = base_text if base_text is not None else DW.write(scene)
        b = do("base", text, base_args(scene))
        V += INV.check_exit(scene, "base", b["rc"], b["stderr"], b["timed_out"], b["too_large"])
        if scene.get("expect") == "input_error":
            if b["rc"] == 0 and b["res"] is not None:
                # what the run made of the overlap: the largest speed reached
                vmax = float(np.linalg.norm(b["res"]["body_velocity"], axis=2).max())
                for v in V:
                    if v["inv"] == "start_not_refused":
                        v["msg"] += f"; the run reached {vmax:.4g} m/s (scene speed scale {scene['scales']['v']:.3g} m/s)"
                        v["vmax"] = vmax
            return rec
        V += INV.check_single(scene, "base", b["res"], b["rc"])
        if b["rc"] != 0 or b["res"] is None or not variants:
            return rec
        tight = do("tight", text, base_args(scene) + ["--rtol", repr(RTOL_TIGHT)])
        if tight["rc"] != 0 or tight["res"] is None:
            V += [dict(v, inv=v["inv"], run="tight") for v in INV.check_exit(scene, "tight", tight["rc"], tight["stderr"], tight["timed_out"], tight["too_large"])]
            return rec
        V += INV.check_single(scene, "tight", tight["res"], tight["rc"])
        if "frame" in variants:
            fp = variants["frame"]
            if not DW.loads_turn(scene):
                # an imposed rotation turns about a global axis (skew_ID not
                # supported for it): the frame variant of such a scene is a
                # translation; /BCS and imposed translations turn with the
                # frame (a /SKEW/FIX, deckwriter.frame_skew)
                fp = dict(fp, R=[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
            vs = DW.transform(scene, fp["R"], fp["t"])
            r = do("frame", DW.write(vs), base_args(scene))
            V += [dict(v, inv="g_frame", msg=f"frame variant: {v['msg']}") for v in
                  INV.check_exit(vs, "frame", r["rc"], r["stderr"], r["timed_out"], r["too_large"])]
            if r["res"] is not None:
                V += INV.check_single(vs, "frame", r["res"], r["rc"])
                viol = INV.compare(scene, "g_frame", b["res"], r["res"], tight["res"], frame=vs["frame"])
                eps_f = 4 * EPS * (np.linalg.norm(fp["t"]) + scene_extent(scene))
                if viol:
                    viol = recheck_perturbed(scene, "g_frame", b, r, tight, vs["frame"], perturbed("perturbed", eps_f),
                                             eps_f)
                V += recheck_floored("g_frame", viol, r, vs["frame"])
                V += events("g_frame_events", r, "perturbed", eps_f)
                if r["steps"] > 10 * max(b["steps"], 1) and r["steps"] > 1000:
                    # the yardstick of g_frame: the base perturbed by the
                    # variant's rounding. A scene at rest on an unstable
                    # equilibrium (a column of balls) stays exactly there at
                    # the origin and leaves it from the rounding 1 km away:
                    # the perturbed base moves and costs as much
                    rp = perturbed("perturbed", eps_f)
                    ref = max(b["steps"], rp["steps"] if rp["rc"] == 0 else 0, 1)
                    if r["steps"] > 10 * ref:
                        V.append(INV.viol("g_frame_slow", "frame", f"the scene 1 km away took {r['steps']} steps against "
                                          f"{b['steps']} ({r['steps'] / max(b['steps'], 1):.1f} x; the base perturbed by "
                                          f"its rounding {rp['steps']}), {r['wall']:.2f} s against {b['wall']:.2f} s",
                                          ratio=r["steps"] / ref))
        if "units" in variants:
            u = tuple(variants["units"])
            r = do("units", DW.write(scene, units=u), base_args(scene))
            V += [dict(v, inv="g_units", msg=f"units {u}: {v['msg']}") for v in
                  INV.check_exit(scene, "units", r["rc"], r["stderr"], r["timed_out"], r["too_large"])]
            if r["res"] is not None:
                V += INV.check_single(scene, "units", r["res"], r["rc"])
                viol = INV.compare(scene, "g_units", b["res"], r["res"], tight["res"])
                eps_u = 4 * EPS * scene_extent(scene)
                if viol:
                    viol = recheck_perturbed(scene, "g_units", b, r, tight, None, perturbed("perturbed_u", eps_u), eps_u)
                    viol = recheck_floored("g_units", viol, r)
                    for v in viol:
                        v["msg"] = f"units {u}: " + v["msg"]
                V += viol
                V += events("g_units_events", r, "perturbed_u", eps_u)
        if "ida" in variants and not scene.get("joints"):
            r = do("ida", text, ["--method", "ida"])
            V += [dict(v, inv="h_backend", msg=f"IDA: {v['msg']}") for v in
                  INV.check_exit(scene, "ida", r["rc"], r["stderr"], r["timed_out"], r["too_large"])]
            if r["res"] is not None:
                V += INV.check_single(scene, "ida", r["res"], r["rc"])
                # the backend's own rounding: that of the coordinates, as units'
                eps_u = 4 * EPS * scene_extent(scene)
                viol = INV.compare(scene, "h_backend", b["res"], r["res"], tight["res"])
                if viol:
                    viol = recheck_perturbed(scene, "h_backend", b, r, tight, None, perturbed("perturbed_u", eps_u),
                                             eps_u)
                    viol = recheck_floored("h_backend", viol, r)
                if viol:
                    # the backend refined: converging to the same motion
                    rt = do("ida_tight", text, ["--method", "ida", "--rtol", repr(RTOL_TIGHT)])
                    if rt["rc"] == 0 and rt["res"] is not None and \
                            INV.backend_converges(scene, r["res"], rt["res"], tight["res"]):
                        viol = []
                    else:
                        for v in viol:
                            v["msg"] += " (and IDA at rtol 1e-10 no nearer CVODE's rtol 1e-10 run)"
                V += viol
                V += events("h_backend_events", r, "perturbed_u", eps_u)
        if "rtol" in variants:
            r = do("loose", text, base_args(scene) + ["--rtol", repr(RTOL_LOOSE)])
            if r["rc"] == 0 and r["res"] is not None:
                V += INV.check_single(scene, "loose", r["res"], r["rc"])
                def rounding_run():
                    rp = perturbed("perturbed_u", 4 * EPS * scene_extent(scene))
                    return rp["res"] if rp["rc"] == 0 else None

                def floored_run():
                    return floor2()
                def finer_run():
                    rf = do("finer", text, base_args(scene) + ["--rtol", "1e-9"])
                    return rf["res"] if rf["rc"] == 0 else None
                def tighter_run():
                    rf = do("tighter", text, base_args(scene) + ["--rtol", "1e-12"])
                    return rf["res"] if rf["rc"] == 0 else None
                V += INV.check_rtol(scene, b["res"], r["res"], tight["res"], perturbed=rounding_run,
                                    floored=floored_run, finer=finer_run, tighter=tighter_run)
            else:
                V += [dict(v, inv="i_rtol", msg=f"rtol 1e-6: {v['msg']}") for v in
                      INV.check_exit(scene, "loose", r["rc"], r["stderr"], r["timed_out"], r["too_large"])]
        return rec
    finally:
        # a run stopped at /SOLVER Max_steps while following an undamped
        # contact vibration, and saying so (its failure names the contact,
        # the period and the steps an output interval needs): the cost of
        # the model at its tolerances, as a slow run's vibration_note
        # (add_slow); listed in "explained", not a violation
        expl = [v for v in V if "exit 3" in v.get("msg", "") and "vibrates undamped (period" in v["msg"]]
        # ... and a run stopped at the time limit whose results (kept up to
        # there) say where its steps went, as a slow run's do (add_slow)
        for v in V:
            vn = rec["runs"].get(v.get("run"), {}).get("vibration_note") if v["inv"] == "a_timeout" else None
            if vn:
                v["msg"] += f"; explained by the run: {vn}"
                expl.append(v)
        if expl:
            V[:] = [v for v in V if v not in expl]
            rec.setdefault("explained", []).extend(expl)
        for v in V:
            for k, val in list(v.items()):
                if isinstance(val, (np.floating, np.integer)):
                    v[k] = val.item()
        if keep_dir and (V or keep_all):
            # the decks always (they reproduce everything), the results files
            # up to KEEP_NC_MB in all, the base run's first
            dst = os.path.join(keep_dir, f"{scene['seed']}-{scene['kind']}")
            shutil.rmtree(dst, ignore_errors=True)
            os.makedirs(dst)
            budget = KEEP_NC_MB * 1e6
            names = sorted(os.listdir(work), key=lambda n: (not n.startswith("base."), n))
            for n in names:
                src_path = os.path.join(work, n)
                if n.endswith(".nc"):
                    size = os.path.getsize(src_path)
                    if size > budget:
                        continue
                    budget -= size
                shutil.copy2(src_path, os.path.join(dst, n))
            with open(os.path.join(dst, "scene.json"), "w") as f:
                json.dump(scene, f, indent=1)
            with open(os.path.join(dst, "violations.json"), "w") as f:
                json.dump(rec, f, indent=1)
            rec["kept"] = dst
        shutil.rmtree(work, ignore_errors=True)


def recheck_perturbed(scene, key, b, r, tight, frame, rp, eps):
    """A variant failed the yardstick base-vs-tight: with the run rp of the
    base scene perturbed by the variant's own rounding (eps), accept the
    variant if it stays within C x that divergence too (the scene is chaotic
    or sits on an unstable symmetry, and the variant's rounding, not a
    defect, sets its difference)."""
    if rp["rc"] != 0 or rp["res"] is None:
        return INV.compare(scene, key, b["res"], r["res"], tight["res"], frame=frame)
    extra = INV.distance(b["res"], rp["res"], scene)
    viol = INV.compare(scene, key, b["res"], r["res"], tight["res"], frame=frame, extra_yard=extra)
    for v in viol:
        v["msg"] += f" (also beyond 10 x the divergence of the base perturbed by {eps:.2g} m)"
    return viol


# --------------------------------------------------------------------------
# batch


def _task(job):
    seed, kind, opts = job
    try:
        scene = SC.generate(seed, kinds=opts.get("kinds"), kind=kind)
        variants = choose_variants(seed, opts["fraction"], opts["variants"])
        return process(scene, variants, opts["ricochet"], opts["timeout"], opts.get("keep_dir"), opts.get("keep_all"))
    except Exception as e:  # a fuzzer bug must not stop the batch
        import traceback
        return {"seed": seed, "kind": kind or "?", "violations": [{"inv": "fuzzer_error", "run": "-", "msg":
                                                                    repr(e) + " " + traceback.format_exc()[-600:]}],
                "runs": {}, "variants": []}


def _replay_task(job):
    path, opts = job
    try:
        with open(path) as f:
            text = f.read()
        scene = DW.read_scene(text)
        if scene is None:
            raise ValueError(f"{path}: no #PHYSFUZZ-SCENE lines (not a physfuzz regression deck)")
        variants = scene.get("replay_variants", {})
        rec = process(scene, variants, opts["ricochet"], opts["timeout"], opts.get("keep_dir"), base_text=text)
    except Exception as e:
        rec = {"seed": -1, "kind": "?", "runs": {}, "variants": [],
               "violations": [{"inv": "fuzzer_error", "run": "-", "msg": repr(e)}]}
    rec["file"] = path
    return rec


def add_slow(records, factor=20.0, floor=1.0):
    """a_slow: a base run over 20 x the median base CPU time of its kind
    (and over 1 s). CPU time, not the wall clock: with other jobs on the
    machine the wall clock of a run measures the load. A slow run that says
    where its steps went (its results' vibration_note: the periods of the
    undamped contact vibrations the scene's laws leave ringing and the
    events they drive on those contacts, the cost of the model at the
    tolerance, not a defect of the solver) is listed in the record's
    "explained", not a violation."""
    def cost(b):
        return b.get("cpu", b["wall"])
    by = {}
    for r in records:
        if "base" in r["runs"]:
            by.setdefault(r["kind"], []).append(cost(r["runs"]["base"]))
    med = {k: float(np.median(v)) for k, v in by.items()}
    for r in records:
        b = r["runs"].get("base")
        if b and not b["timed_out"] and cost(b) > max(factor * med[r["kind"]], floor):
            v = {"inv": "a_slow", "run": "base", "msg": f"base run took {cost(b):.2f} s of CPU, "
                 f"{cost(b) / med[r['kind']]:.0f} x the median of its kind ({med[r['kind']]:.3f} s)"}
            if b.get("vibration_note"):
                v["msg"] += f"; explained by the run: {b['vibration_note']}"
                r.setdefault("explained", []).append(v)
            else:
                r["violations"].append(v)


def tally(records):
    inv, kinds = {}, {}
    for r in records:
        keys = sorted({v["inv"] for v in r["violations"]})
        k = kinds.setdefault(r["kind"], {"scenes": 0, "violating": 0, "inv": {}})
        k["scenes"] += 1
        if keys:
            k["violating"] += 1
        for key in keys:
            inv[key] = inv.get(key, 0) + 1
            k["inv"][key] = k["inv"].get(key, 0) + 1
    return inv, kinds


def cmd_run(a):
    seeds = [a.seed * 1000000 + i for i in range(a.scenes)]
    kinds = a.kinds.split(",") if a.kinds else None
    os.makedirs(a.out, exist_ok=True)
    keep = os.path.join(a.out, "scenes")
    opts = {"kinds": kinds, "fraction": a.variant_fraction, "variants": a.variants.split(","),
            "ricochet": os.path.abspath(a.ricochet), "timeout": a.timeout, "keep_dir": keep, "keep_all": a.keep_all}
    t0 = time.time()
    records = []
    with multiprocessing.Pool(a.jobs) as pool:
        for k, rec in enumerate(pool.imap_unordered(_task, [(s, None, opts) for s in seeds])):
            records.append(rec)
            if not a.quiet and (k + 1) % max(1, a.scenes // 20) == 0:
                print(f"  {k + 1}/{a.scenes} scenes, {time.time() - t0:.0f} s", file=sys.stderr, flush=True)
    records.sort(key=lambda r: r["seed"])
    add_slow(records)
    inv, kinds = tally(records)
    wall = time.time() - t0
    nviol = sum(1 for r in records if r["violations"])
    nexp = sum(1 for r in records if r.get("explained"))
    parts = [f"physfuzz: {len(records)} scenes (seed {a.seed}, {wall:.0f} s, {a.jobs} jobs): {nviol} with violations"]
    if inv:
        parts.append(", ".join(f"{k} {v}" for k, v in sorted(inv.items())))
    parts.append(f"{nexp} scenes explained by undamped contact vibrations (slow runs with their vibration_note, runs "
                 f"stopped at the time limit whose results carry one, or runs stopped at Max_steps that name the "
                 f"vibrating contact; not violations)")
    line = "; ".join(parts)
    print(line)
    report = {"args": vars(a), "wall": wall, "ricochet": opts["ricochet"], "tally": inv, "by_kind": kinds,
              "date": datetime.datetime.now().isoformat(timespec="seconds"), "scenes": records}
    with open(os.path.join(a.out, "report.json"), "w") as f:
        json.dump(report, f, indent=1)
    print(f"report: {os.path.join(a.out, 'report.json')}; decks and results of violating scenes in {keep}/")
    return 1 if (a.strict and nviol) else 0


def print_rec(rec):
    for v in rec["violations"]:
        print(f"  VIOLATION {v['inv']} [{v['run']}]: {v['msg']}")
    for v in rec.get("explained", []):
        print(f"  explained {v['inv']} [{v['run']}]: {v['msg'][:300]}")
    if not rec["violations"]:
        print("  no violation")


def cmd_one(a):
    scene = SC.generate(a.seed, kind=a.kind)
    variants = choose_variants(a.seed, a.variant_fraction) if a.variant_fraction < 1 else all_variants(a.seed)
    if a.no_variants:
        variants = {}
    print(f"scene {a.seed}: {scene['kind']}: {'; '.join(scene['notes'])}")
    sc = scene["scales"]
    print(f"  scales: L {sc['L']:.4g} m, E_s {sc['E_s']:.4g} J, v {sc['v']:.4g} m/s, g {sc['g']:.4g}, "
          f"tend {scene['run']['tend']:.4g} s; variants {sorted(variants)}")
    out = a.out or os.path.join(tempfile.gettempdir(), f"physfuzz-one-{a.seed}")
    os.makedirs(out, exist_ok=True)
    rec = process(scene, variants, os.path.abspath(a.ricochet), a.timeout, keep_dir=out, keep_all=True, log=print)
    print_rec(rec)
    print(f"  files: {rec.get('kept')}")
    return 1 if rec["violations"] else 0


def regression_files(paths):
    out = []
    for p in paths:
        if os.path.isdir(p):
            out += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".rad"))
        elif os.path.exists(p) or not p.endswith("regressions"):
            out.append(p)
    return out


def cmd_replay(a):
    files = regression_files(a.paths)
    opts = {"ricochet": os.path.abspath(a.ricochet), "timeout": a.timeout}
    bad = 0
    with multiprocessing.Pool(a.jobs) as pool:
        for rec in pool.imap(_replay_task, [(f, opts) for f in files]):
            name = os.path.basename(rec["file"])
            if rec["violations"]:
                bad += 1
                print(f"{'FAIL' if a.strict else 'XFAIL'} physfuzz.regression.{name}: " +
                      ", ".join(sorted({v['inv'] for v in rec['violations']})))
                if a.verbose:
                    print_rec(rec)
            else:
                print(f"PASS physfuzz.regression.{name}")
    return 1 if (a.strict and bad) else 0


def cmd_check(a):
    """The make-check sample: fixed seeds and the regressions, one line each."""
    seeds = [a.seed * 1000000 + i for i in range(a.scenes)]
    opts = {"kinds": None, "fraction": a.variant_fraction, "variants": list(VARIANTS),
            "ricochet": os.path.abspath(a.ricochet), "timeout": a.timeout,
            "keep_dir": a.out and os.path.join(a.out, "scenes")}
    files = regression_files([os.path.join(HERE, "regressions")]) if not a.no_regressions else []
    # the regression decks at REGRESSION_TIMEOUT at least: known scenes,
    # some costly by nature (box_stack_power_rdf_rocking_zeno: 18.5 s of
    # CPU), that a limit sized for the random sample would turn into
    # time-outs on a slower or loaded machine
    ropts = dict(opts, timeout=max(a.timeout, REGRESSION_TIMEOUT))
    jobs = [("scene", (s, None, opts)) for s in seeds] + [("reg", (f, ropts)) for f in files]
    t0 = time.time()
    fail = xfail = npass = 0
    with multiprocessing.Pool(a.jobs) as pool:
        for rec in pool.imap(_dispatch, jobs):
            if "file" in rec:
                name = f"physfuzz.regression.{os.path.basename(rec['file'])}"
            else:
                name = f"physfuzz.{rec['seed']}.{rec['kind']}"
            keys = sorted({v["inv"] for v in rec["violations"]})
            if not keys:
                npass += 1
                print(f"PASS {name}", flush=True)
            elif a.strict or "fuzzer_error" in keys:
                fail += 1
                print(f"FAIL {name}: {', '.join(keys)}", flush=True)
            else:
                xfail += 1
                print(f"XFAIL {name}: {', '.join(keys)}", flush=True)
    print(f"physics fuzz sample: {npass} passed, {fail} failed, {xfail} expected failures (PHYSFUZZ_STRICT="
          f"{1 if a.strict else 0}), {time.time() - t0:.0f} s")
    return 1 if fail else 0


def _dispatch(job):
    kind, payload = job
    return _task(payload) if kind == "scene" else _replay_task(payload)


def variants_for(key, seed):
    v = all_variants(seed)
    if key.startswith("g_frame"):
        return {"frame": v["frame"]}
    if key.startswith("g_units"):
        return {"units": v["units"]}
    if key.startswith("h_"):
        return {"ida": True}
    if key.startswith("i_"):
        return {"rtol": True}
    return {}


def still_fails(scene, key, variants, ricochet, timeout):
    rec = process(scene, variants, ricochet, timeout)
    hits = [v for v in rec["violations"] if v["inv"] == key]
    return hits[0] if hits else None


def drop_body(scene, bid):
    s = copy.deepcopy(scene)
    s["bodies"] = [b for b in s["bodies"] if b["id"] != bid]
    gone = {f["id"] for f in s["surfaces"] if f.get("body") == bid}
    s["surfaces"] = [f for f in s["surfaces"] if f.get("body") != bid]
    s["nodes"] = [n for n in s.get("nodes", []) if n.get("body") != bid]
    s["inters"] = [i for i in s["inters"] if i["s1"] not in gone and i["s2"] not in gone]
    s["joints"] = [j for j in s.get("joints", []) if bid not in (j["b1"], j["b2"])]
    used = {i["s1"] for i in s["inters"]} | {i["s2"] for i in s["inters"]}
    s["surfaces"] = [f for f in s["surfaces"] if f["id"] in used or f.get("body")]
    keepn = {n for f in s["surfaces"] if f["type"] == "seg" for seg in f["segs"] for n in seg}
    s["nodes"] = [n for n in s["nodes"] if n.get("body") or n["id"] in keepn]
    if not s["bodies"] or not s["inters"]:
        return None
    s["shapes"] = SC.shapes_of(s)
    s["scales"]["m_total"] = sum(b["mass"] for b in s["bodies"])
    return s


def drop_inter(scene, iid):
    """The scene without interface iid (and its fixed surface, if no other
    interface uses it)."""
    s = copy.deepcopy(scene)
    if len(s["inters"]) < 2:
        return None
    s["inters"] = [i for i in s["inters"] if i["id"] != iid]
    used = {i["s1"] for i in s["inters"]} | {i["s2"] for i in s["inters"]}
    s["surfaces"] = [f for f in s["surfaces"] if f["id"] in used or f.get("body")]
    keepn = {n for f in s["surfaces"] if f["type"] == "seg" for seg in f["segs"] for n in seg}
    s["nodes"] = [n for n in s["nodes"] if n.get("body") or n["id"] in keepn]
    fids = {i.get(k) for i in s["inters"] for k in ("fct_ld", "fct_ul")} | {iv["fct"] for iv in s.get("impvel", [])}
    s["funcs"] = [f for f in s["funcs"] if f["id"] in fids]
    s["shapes"] = SC.shapes_of(s)
    return s


def no_friction(scene):
    s = copy.deepcopy(scene)
    changed = s.get("friction") is not None
    s["friction"] = None
    for it in s["inters"]:
        for k in ("fric", "sfric", "mus", "vs", "mud", "vd", "fmax", "kt"):
            if it.pop(k, None) is not None:
                changed = True
        if it.get("iform", 0) == 0 and it.pop("stiff", None) is not None:
            changed = True
    return s if changed else None


def no_damping(scene):
    s = copy.deepcopy(scene)
    changed = False
    for it in s["inters"]:
        for k in ("visc", "c", "e_target"):
            if it.pop(k, None) is not None:
                changed = True
    return s if changed else None


def severity(hit):
    """How far past its tolerance a violation is (1 when it has no numbers):
    the minimiser keeps a reduction only while the violation stays strong."""
    v, tol = hit.get("value"), hit.get("tol") or hit.get("bound") or hit.get("allowed")
    if v is None or not tol:
        return 1.0
    if hit["inv"] == "d_centres":
        return tol / max(v, 1e-300)
    return abs(v) / tol


def violation_time(hit):
    """The time of a violation: its own, or the one its message names."""
    import re
    if hit.get("t") is not None:
        return float(hit["t"])
    m = re.search(r"at t = ([0-9.eE+-]+) s", hit["msg"])
    return float(m.group(1)) if m else None


def linear_law(scene, iid):
    """The scene with the TYPE6 interface iid's law made linear (its secant
    at the law's reference penetration), no hysteresis."""
    s = copy.deepcopy(scene)
    it = next(i for i in s["inters"] if i["id"] == iid)
    law = it["law_curve"]
    if it["law"] != "type6" or law.get("name") == "t6lin":
        return None
    x, y = law["x"][2], law["y"][2]
    fid = max([f["id"] for f in s["funcs"]] + [0]) + 1
    s["funcs"].append({"id": fid, "x": [0.0, x], "y": [0.0, y], "label": "linear load curve [m, N]"})
    for k in ("iform", "stiff", "fct_ul", "fscaleul", "e_target", "v_imp"):
        it.pop(k, None)
    it.update({"fct_ld": fid, "ascalex": 1.0, "fscaleld": 1.0})
    it["law_curve"] = {"kind": "curve", "x": [0.0, x], "y": [0.0, y], "name": "t6lin"}
    used = {i.get(k) for i in s["inters"] for k in ("fct_ld", "fct_ul")}
    s["funcs"] = [f for f in s["funcs"] if f["id"] in used or f["id"] in {iv["fct"] for iv in s.get("impvel", [])}]
    return s


def cmd_minimise(a):
    if a.scene:
        with open(a.scene) as f:
            text = f.read()
        scene = DW.read_scene(text) if a.scene.endswith(".rad") else json.loads(text)
    else:
        scene = SC.generate(a.seed, kind=a.kind)
    ricochet = os.path.abspath(a.ricochet)
    variants = scene.get("replay_variants") or variants_for(a.inv, scene["seed"])
    if a.variant:
        allv = all_variants(scene["seed"])
        for v in a.variant:
            if v not in allv:
                raise SystemExit(f"--variant {v}: expected one of {', '.join(sorted(allv))}")
            variants[v] = allv[v]
    hit = still_fails(scene, a.inv, variants, ricochet, a.timeout)
    if not hit:
        print(f"seed {scene['seed']}: {a.inv} does not fail")
        return 1
    print(f"seed {scene['seed']} ({scene['kind']}): {hit['msg']}")
    hit0 = hit
    tend0 = scene["run"]["tend"]
    changed = True
    while changed:
        changed = False
        cands = []
        tv = violation_time(hit)
        tend = scene["run"]["tend"]
        if a.keep_time:
            pass
        elif tv is not None:
            te = max(tv * 1.1, tend * 0.01, tend0 * 1e-3)
            if te < 0.8 * tend:
                cands.append(("end time", dict(scene, run={"tend": te, "dtout": te / 200})))
        elif tend > 1e-3:
            cands.append(("end time / 2", dict(scene, run={"tend": tend / 2, "dtout": tend / 400})))
        for b in scene["bodies"]:
            cands.append((f"without body {b['id']}", drop_body(scene, b["id"])))
        for it in scene["inters"]:
            cands.append((f"without /INTER/{it['id']}", drop_inter(scene, it["id"])))
        cands.append(("without friction", no_friction(scene)))
        cands.append(("without damping", no_damping(scene)))
        for it in scene["inters"]:
            cands.append((f"/INTER/{it['id']} linear", linear_law(scene, it["id"])))
        for what, cand in cands:
            if cand is None:
                continue
            h = still_fails(cand, a.inv, variants, ricochet, a.timeout)
            if h and h["inv"] in ("a_solver_failure", "a_timeout", "g_frame", "g_units", "h_backend") and \
                    ("exit" in h["msg"] or "exit" in hit0["msg"]) and \
                    failure_signature(h["msg"]) != failure_signature(hit0["msg"]):
                print(f"  {what}: fails otherwise ({h['msg'][:100]})")
                continue
            if h and severity(h) < min(0.1 * severity(hit0), 1000.0):
                print(f"  {what}: still fails, but weakly ({h['msg'][:100]})")
                continue
            if h:
                print(f"  {what}: still fails ({h['msg'][:120]})")
                scene, hit, changed = cand, h, True
                break
            print(f"  {what}: passes")
    scene["replay_variants"] = variants
    out = a.o or f"{a.inv}-{scene['seed']}.rad"
    write_regression(scene, hit, out, a.note)
    print(f"written {out}")
    return 0


def write_regression(scene, hit, path, note=None):
    hdr = [f"physfuzz regression: {hit['inv']}",
           f"found {datetime.date.today().isoformat()} by fuzz/physics/scenefuzz.py, seed {scene['seed']}, "
           f"kind {scene['kind']} ({'; '.join(scene.get('notes', []))})"[:990],
           f"what it showed: {hit['msg']}"[:990],
           f"replay: /usr/bin/python3 fuzz/physics/scenefuzz.py replay {os.path.basename(path)}",
           f"variants replayed: {', '.join(sorted(scene.get('replay_variants', {}))) or 'none (the base run)'}"]
    for k in range(0, len(note or ""), 900):
        hdr.append(("mechanism: " if k == 0 else "  ") + note[k:k + 900])
    with open(path, "w") as f:
        f.write(DW.write(scene, header=hdr))


def failure_signature(msg):
    """A short class of a solver-failure message."""
    for key in ("Zeno", "CV_TOO_MUCH_WORK", "CV_ERR_FAILURE", "CV_CONV_FAILURE", "IDA_CONV_FAIL", "IDA_ERR_FAIL",
                "IDA_TOO_MUCH_WORK", "CV_REPTD", "IDA_REP_RES", "CV_ILL_INPUT", "IDA_ILL_INPUT", "too much", "time limit"):
        if key in msg:
            if key == "Zeno":
                last = msg.split("(last: ")[-1].split(")")[0] if "(last: " in msg else "?"
                return f"Zeno ({last})"
            if "at t = 0 s" in msg:
                return key + " at t = 0"
            return key
    return msg[:40]


def cmd_summary(a):
    rep = json.load(open(os.path.join(a.dir, "report.json") if os.path.isdir(a.dir) else a.dir))
    recs = rep["scenes"]
    inv, kinds = tally(recs)
    print(f"{len(recs)} scenes, {sum(1 for r in recs if r['violations'])} with violations, wall {rep['wall']:.0f} s")
    keys = sorted(inv)
    print("\nscenes violating each invariant, per kind:")
    print("| kind | scenes | violating | " + " | ".join(keys) + " |")
    print("|---|---|---|" + "---|" * len(keys))
    for k in sorted(kinds):
        d = kinds[k]
        print(f"| {k} | {d['scenes']} | {d['violating']} | " + " | ".join(str(d['inv'].get(x, '')) for x in keys) + " |")
    print(f"| all | {len(recs)} | {sum(1 for r in recs if r['violations'])} | " +
          " | ".join(str(inv[x]) for x in keys) + " |")
    sig = {}
    for r in recs:
        for v in r["violations"]:
            if v["inv"] in ("a_solver_failure", "g_frame", "h_backend", "i_rtol", "a_timeout") and "exit" in v["msg"] \
                    or v["inv"] in ("a_solver_failure", "a_timeout"):
                s = (v["inv"], v["run"], failure_signature(v["msg"]))
                sig.setdefault(s, []).append(r["seed"])
    if sig:
        print("\nrun failures by class (invariant, run, class: scenes):")
        for s, seeds in sorted(sig.items(), key=lambda x: -len(x[1])):
            print(f"  {s[0]} [{s[1]}] {s[2]}: {len(seeds)}  e.g. {seeds[:4]}")
    if a.verbose:
        for r in recs:
            if r["violations"]:
                print(f"\n{r['seed']} {r['kind']}: {'; '.join(r.get('notes', []))}")
                for v in r["violations"]:
                    print(f"    {v['inv']} [{v['run']}]: {v['msg'][:260]}")
    return 0


def cmd_deck(a):
    scene = SC.generate(a.seed, kind=a.kind)
    if a.variant == "frame":
        fp = all_variants(a.seed)["frame"]
        text = DW.write(DW.transform(scene, fp["R"], fp["t"]))
    elif a.variant == "units":
        text = DW.write(scene, units=tuple(all_variants(a.seed)["units"]))
    else:
        text = DW.write(scene)
    with open(a.o, "w") as f:
        f.write(text)
    return 0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)

    def common(q):
        q.add_argument("--ricochet", default=os.environ.get("RICOCHET", DEFAULT_BIN))
        q.add_argument("--timeout", type=float, default=60.0, help="seconds per run (default 60)")

    q = sub.add_parser("run")
    common(q)
    q.add_argument("--scenes", type=int, default=200)
    q.add_argument("--seed", type=int, default=1)
    q.add_argument("--jobs", type=int, default=2)
    q.add_argument("--out", default="physfuzz-out")
    q.add_argument("--kinds", default="")
    q.add_argument("--variant-fraction", type=float, default=0.3)
    q.add_argument("--variants", default=",".join(VARIANTS))
    q.add_argument("--strict", action="store_true", help="exit 1 when a scene violates an invariant")
    q.add_argument("--keep-all", action="store_true", help="keep the files of every scene, not only the violating ones")
    q.add_argument("--quiet", action="store_true")
    q = sub.add_parser("one")
    common(q)
    q.add_argument("--seed", type=int, required=True)
    q.add_argument("--kind", default=None)
    q.add_argument("--out", default=None)
    q.add_argument("--variant-fraction", type=float, default=1.0)
    q.add_argument("--no-variants", action="store_true")
    q = sub.add_parser("replay")
    common(q)
    q.add_argument("paths", nargs="+")
    q.add_argument("--jobs", type=int, default=2)
    q.add_argument("--strict", action="store_true")
    q.add_argument("-v", "--verbose", action="store_true")
    q = sub.add_parser("check")
    common(q)
    q.add_argument("--scenes", type=int, default=40)
    q.add_argument("--seed", type=int, default=7)
    q.add_argument("--jobs", type=int, default=2)
    q.add_argument("--variant-fraction", type=float, default=0.2)
    q.add_argument("--strict", action="store_true", default=os.environ.get("PHYSFUZZ_STRICT", "0") == "1")
    q.add_argument("--no-regressions", action="store_true")
    q.add_argument("--out", default=None)
    q = sub.add_parser("minimise")
    common(q)
    q.add_argument("--seed", type=int, default=None)
    q.add_argument("--scene", default=None, help="a scene.json of a kept scene, or a deck with its scene")
    q.add_argument("--kind", default=None)
    q.add_argument("--inv", required=True)
    q.add_argument("--note", default=None, help="a line on the mechanism for the deck's header")
    q.add_argument("--keep-time", action="store_true", help="do not shorten the run")
    q.add_argument("--variant", action="append", default=[],
                   help="a variant the violation needs (frame, units, ida, rtol; repeatable): for an "
                        "invariant whose name does not say which, e.g. a solver failure at rtol 1e-10")
    q.add_argument("-o", default=None)
    q = sub.add_parser("summary")
    q.add_argument("dir", help="a run's output folder or its report.json")
    q.add_argument("-v", "--verbose", action="store_true")
    q = sub.add_parser("deck")
    q.add_argument("--seed", type=int, required=True)
    q.add_argument("--kind", default=None)
    q.add_argument("--variant", default=None, choices=("frame", "units"))
    q.add_argument("-o", required=True)
    a = p.parse_args(argv)
    return {"run": cmd_run, "one": cmd_one, "replay": cmd_replay, "check": cmd_check, "minimise": cmd_minimise,
            "deck": cmd_deck, "summary": cmd_summary}[a.cmd](a)


if __name__ == "__main__":
    sys.exit(main())
