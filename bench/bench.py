"""ricochet benchmarks: implicit (CVODE BDF + KLU) against an explicit
central-difference integration of the same equations (bench/explicit_ref.c).

Cases (bench/README.md):
  1. sphere drop on a linear spring-dashpot floor, e = 0.8, 1 s;
     accuracy = rebound ratios v_out/v_in against the closed-form chain;
  2. settling column of N spheres (N = 10, 100, 1000), 5 s;
     accuracy = contact forces at t = 5 s against an event-located RK4
     reference of the same equations (explicit_ref reference), relative to
     the static bottom force N m g.
  3. quasi-static (the regime implicit integration is for):
     a. the settled column (N = 100, 1000) under gravity ramped G -> 2 G over
        T = 20 s and 100 s, then held 1 s; accuracy = contact forces at the
        end against an RK4 reference of the same equations (and the statics
        2 (N - j) m g for information); beside them the static analysis
        (/SOLVER Method 3, the column locked to z) of the same ramp, against
        both references (the exact statics is the right one for it);
     b. stick-slip: a block dragged across a floor through a spring, 100 s,
        Renard two-level friction in the viscous form; accuracy = period,
        slip distances and switch times against a scipy Radau reference of
        the same law;
     c. the drag to the slip in statics (--only slipstatic): a block held by
        its stick spring, pulled by a force ramped until it slips, solved by
        the static analysis (its equilibria and the load at which friction
        can no longer hold) against the explicit scheme and plain CVODE of
        the same 1-D law up to the slip, at 1e-5 m g on the friction force.

Programs (built by bench/run.sh into the build directory):
  ricochet       the CLI: accuracy (netCDF output), statistics, peak memory
  rc_time        ricochet's rc_run through the public API without an output
                 file: the integration wall time compared with explicit_ref
  explicit_ref   central difference and the RK4 reference
  cvode_ref      the column as a plain CVODE + KLU program (2 states per
                 sphere, gap-scaled error weights)
  peakrss        launcher that reports a child's own ru_maxrss (wait4)

usage: /usr/bin/python3 bench/bench.py [--build DIR] [--quick]
       [--only drop|column|quasi|ramp|stickslip|slipstatic|joint|stepcost|cascade] [--sizes 10,100,1000]
       [--qsizes 100,1000] [--ramps 20,100] [--clock wall|cpu] [--work DIR] [--json FILE]
       (ramp, stick-slip and cascade options: --help)
Prints plain tables; writes the raw numbers to DIR/bench/results.json.
"""
import argparse
import json
import math
import os
import platform
import re
import subprocess
import sys
import time

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from deck import Deck  # noqa: E402

G = 9.81
DEFAULT_RTOL = 1e-6  # ricochet's default (docs/theory.md); atol_pos 1e-9 m, atol_vel 1e-6 m/s


# ---------------------------------------------------------------- helpers
def kv(text):
    """key=value lines -> dict (numbers converted); 'bounce=' lines -> list."""
    d, bounces = {}, []
    for ln in text.splitlines():
        if ln.startswith("bounce="):
            bounces.append({k: float(v) for k, v in (tok.split("=") for tok in ln.split())})
        elif "=" in ln:
            k, v = ln.split("=", 1)
            try:
                d[k] = int(v)
            except ValueError:
                try:
                    d[k] = float(v)
                except ValueError:
                    d[k] = v
    d["bounce"] = bounces
    return d


def table(title, header, rows, note=None):
    """Print a plain-text table."""
    w = [len(str(h)) for h in header]
    for r in rows:
        for k, x in enumerate(r):
            if k < len(w):
                w[k] = max(w[k], len(str(x)))
    lines = [title, "  ".join(str(h).rjust(w[k]) for k, h in enumerate(header)),
             "  ".join("-" * x for x in w)]
    for r in rows:
        lines.append("  ".join(str(x).rjust(w[k]) if k < len(w) else str(x) for k, x in enumerate(r)))
    if note:
        lines.append(note)
    print("\n".join(lines) + "\n")
    sys.stdout.flush()


def fmt_t(x):
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "-"
    return f"{x * 1e3:.2f} ms" if x < 1 else f"{x:.2f} s"


def fmt_e(x):
    return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.2e}"


def fmt_mb(kb):
    return "-" if not kb else f"{kb / 1024:.1f} MB"


def machine():
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            for ln in f:
                if ln.startswith("model name"):
                    cpu = ln.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return {"cpu": cpu, "cores": os.cpu_count(), "kernel": platform.release()}


class Bench:
    def __init__(self, build, quick=False, work=None, clock="wall"):
        self.build = os.path.abspath(build)
        self.ricochet = os.environ.get("RICOCHET", os.path.join(self.build, "ricochet"))
        self.rc_time = os.path.join(self.build, "rc_time")
        self.explicit = os.path.join(self.build, "explicit_ref")
        self.cvode = os.path.join(self.build, "cvode_ref")
        self.peakrss = os.path.join(self.build, "peakrss")
        self.work = os.path.abspath(work) if work else os.path.join(self.build, "bench")
        os.makedirs(self.work, exist_ok=True)
        self.quick = quick
        # clock "cpu": every time in the tables is the CPU time of the timed part (cpu_time of explicit_ref,
        # cvode_ref and rc_time; peakrss's cpu for a CLI process) instead of its wall time
        self.clock = clock
        self.last_cpu = None
        self.results = {"machine": machine()}

    def measured(self, argv, timeout=None):
        """Run argv through peakrss; return (rc, stdout, stderr, elapsed, maxrss_kb)."""
        rssf = os.path.join(self.work, "peakrss.out")
        if os.path.exists(rssf):
            os.remove(rssf)
        proc = subprocess.Popen([self.peakrss, rssf] + [str(a) for a in argv], stdout=subprocess.PIPE,
                                stderr=subprocess.PIPE, text=True)
        try:
            so, se = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            proc.terminate()  # peakrss forwards SIGTERM to its child as SIGKILL
            so, se = proc.communicate()
            return -9, so, se + f"\ntimeout after {timeout} s", float(timeout), None
        rc = proc.returncode
        info = {}
        if os.path.exists(rssf):
            info = kv(open(rssf).read())
        self.last_cpu = info.get("cpu")
        return rc, so, se, info.get("elapsed"), info.get("maxrss_kb")

    def timed(self, d):
        """key=value output d of a timed program: with the CPU clock, its
        wall_time replaced by its cpu_time (the wall time kept as wall_clock)."""
        if self.clock == "cpu" and "cpu_time" in d:
            d["wall_clock"] = d["wall_time"]
            d["wall_time"] = d["cpu_time"]
        return d

    # ------------------------------------------------------------ ricochet
    def ricochet_run(self, deck, name, timeout=None, time_repeat=1):
        """CLI run (netCDF: accuracy, statistics, peak RSS, process time) and,
        when time_repeat > 0, rc_time runs for the integration wall time
        without output (best of time_repeat runs in one process)."""
        case = os.path.join(self.work, name + ".rad")
        out = os.path.join(self.work, name + ".nc")
        deck.write(case)
        if os.path.exists(out):
            os.remove(out)
        rc, so, se, elapsed, rss = self.measured([self.ricochet, "run", case, "-o", out, "-q"], timeout)
        r = {"ok": rc == 0, "rc": rc, "stderr": se.strip()[-400:], "elapsed": elapsed, "rss_kb": rss, "case": case,
             "process_cpu": self.last_cpu}
        if not os.path.exists(out):
            return r
        try:
            with Dataset(out) as nc:
                a = {k: nc.getncattr(k) for k in nc.ncattrs()}
                r["t"] = np.array(nc["time"][:])
                r["at_event"] = np.array(nc["at_event"][:])
                r["pos"] = np.array(nc["body_position"][:])
                r["vel"] = np.array(nc["body_velocity"][:])
                r["fn"] = np.array(nc["inter_force_normal"][:])
                n = len(nc.dimensions["event"])
                r["ev_t"] = np.array(nc["event_time"][:]) if n else np.zeros(0)
                r["ev_kind"] = [str(k) for k in nc["event_kind"][:]] if n else []
        except Exception as e:  # noqa: BLE001 (an incomplete file after a failure)
            r["ok"] = False
            r["stderr"] += f" (output unreadable: {e})"
            return r
        r["stats"] = {k[len("stats_"):]: (v.item() if hasattr(v, "item") else v) for k, v in a.items()
                      if k.startswith("stats_")}
        r["nc_bytes"] = os.path.getsize(out)
        if r["nc_bytes"] > 100 * 2**20:  # the N = 1000 columns write ~0.6 GB: do not keep them
            os.remove(out)
        r["cli_wall"] = float(r["stats"].get("wall_time", float("nan")))
        r["wall"] = r["cli_wall"]
        if self.clock == "cpu" and r["process_cpu"] is not None:
            r["wall"] = r["process_cpu"]  # the CLI process's CPU time: load, compile and output included
        r["wall_src"] = "cli"
        if r["ok"] and time_repeat > 0:
            rc2, so2, se2, _, rss2 = self.measured([self.rc_time, case, time_repeat], timeout)
            if rc2 == 0:
                t = self.timed(kv(so2))
                r["timing"] = t
                r["wall"] = t["wall_time"]
                r["wall_src"] = "rc_time"
                r["rss_core_kb"] = rss2
        return r

    # ------------------------------------------------------------ explicit
    def explicit_run(self, args, repeat=1, timeout=None):
        best = None
        for _ in range(repeat):
            rc, so, se, elapsed, rss = self.measured([self.explicit] + list(args), timeout)
            if rc != 0:
                return {"ok": False, "rc": rc, "stderr": (se + so).strip()}
            d = self.timed(kv(so))
            d["ok"] = d.get("status") == "ok"
            d["rss_kb"] = rss
            d["elapsed"] = elapsed
            if best is None or d["wall_time"] < best["wall_time"]:
                best = d
        return best

    # ------------------------------------------------------------ plain CVODE
    def cvode_run(self, args, repeat=1, timeout=None):
        """cvode_ref (same key=value output as explicit_ref); best of repeat."""
        best = None
        for _ in range(repeat):
            rc, so, se, elapsed, rss = self.measured([self.cvode] + list(args), timeout)
            d = self.timed(kv(so))
            if rc != 0 or d.get("status") != "ok":
                return {"ok": False, "rc": rc, "stderr": (se + so).strip()[-300:]}
            d["ok"] = True
            d["rss_kb"] = rss
            d["elapsed"] = elapsed
            if best is None or d["wall_time"] < best["wall_time"]:
                best = d
        return best


def equal_accuracy(ricochet_runs, explicit_runs):
    """For each ricochet run: the cheapest explicit run whose error is <= the
    ricochet error and stays <= it at every finer step of the scan (the
    explicit errors are O(dt) but not monotone), and the wall-time ratio
    explicit / ricochet (> 1: ricochet faster)."""
    out = []
    ex = sorted([x for x in explicit_runs if not math.isnan(x["error"])], key=lambda x: -x["dt"])
    for r in ricochet_runs:
        if not r.get("ok") or math.isnan(r.get("error", float("nan"))):
            continue
        match, prev = None, None
        for k, x in enumerate(ex):
            if all(y["error"] <= r["error"] for y in ex[k:]):
                match = x
                prev = ex[k - 1] if k > 0 else None
                break
        # log-log interpolation of the wall time between the last coarser run
        # that misses the target and the match
        interp = match["wall"] if match else None
        if match and prev and prev["error"] > r["error"] > match["error"] > 0:
            s = math.log(prev["error"] / r["error"]) / math.log(prev["error"] / match["error"])
            interp = prev["wall"] * (match["wall"] / prev["wall"]) ** s
        out.append({"rtol": r["rtol"], "ricochet_error": r["error"], "ricochet_wall": r["wall"],
                    "explicit_dt_factor": match["dt_factor"] if match else None,
                    "explicit_error": match["error"] if match else None,
                    "explicit_wall": match["wall"] if match else None,
                    "ratio": match["wall"] / r["wall"] if match and r["wall"] else None,
                    "explicit_wall_interp": interp,
                    "ratio_interp": interp / r["wall"] if match and r["wall"] else None,
                    "finest_explicit_error": ex[-1]["error"] if ex else None})
    return out


def equal_reverse(label, explicit_runs, implicit):
    """The other direction: for each explicit run, the cheapest run of each
    implicit program (implicit: {name: runs}) whose error is <= the explicit
    error, and the wall-time ratio explicit / implicit (> 1: implicit faster).
    Used by the quasi-static cases, where the explicit scheme is already very
    accurate at its stable step, so that most implicit runs are matched by
    it and the question is what an implicit run as accurate costs."""
    rows, out = [], []
    for x in sorted(explicit_runs, key=lambda x: -x["dt"]):
        if math.isnan(x.get("error", float("nan"))):
            continue
        for name, runs in implicit.items():
            ok = [r for r in runs if r.get("ok") and not math.isnan(r.get("error", float("nan")))
                  and r["error"] <= x["error"]]
            best = min(ok, key=lambda r: r["wall"]) if ok else None
            out.append({"dt_factor": x["dt_factor"], "explicit_error": x["error"], "explicit_wall": x["wall"],
                        "program": name, "rtol": best["rtol"] if best else None,
                        "error": best["error"] if best else None, "wall": best["wall"] if best else None,
                        "ratio": x["wall"] / best["wall"] if best else None})
            rows.append([f"{x['dt_factor']:g}", fmt_e(x["error"]), fmt_t(x["wall"]), name,
                         f"{best['rtol']:.0e}" if best else "none as accurate", fmt_e(best["error"]) if best else "-",
                         fmt_t(best["wall"]) if best else "-", f"{x['wall'] / best['wall']:.3g}" if best else "-"])
    table(f"{label}: the cheapest implicit run at least as accurate as each explicit run",
          ["dt_factor", "explicit err", "explicit wall", "program", "rtol", "err", "wall", "explicit/implicit"], rows,
          note="explicit/implicit > 1: the implicit run is faster")
    return out


def print_equal(label, eq, target, who="ricochet"):
    rows = []
    for q in eq:
        if q["explicit_wall"] is None:
            rows.append([f"{q['rtol']:.0e}", fmt_e(q["ricochet_error"]), fmt_t(q["ricochet_wall"]),
                         f"none <= (finest {fmt_e(q['finest_explicit_error'])})", "-", "-", "-", "-"])
        else:
            first = q["explicit_dt_factor"] == 1
            rows.append([f"{q['rtol']:.0e}", fmt_e(q["ricochet_error"]), fmt_t(q["ricochet_wall"]),
                         f"{q['explicit_dt_factor']:g}" + (" (stable step)" if first else ""),
                         fmt_e(q["explicit_error"]), fmt_t(q["explicit_wall"]), f"{q['ratio']:.3g}",
                         f"{q['ratio_interp']:.3g}"])
    table(f"{label}: equal accuracy. {target}",
          ["rtol", f"{who} err", f"{who} wall", "explicit dt_factor", "explicit err", "explicit wall",
           f"explicit/{who}", "interpolated"], rows,
          note=f"explicit/{who} = wall-time ratio (> 1: {who} faster); interpolated: explicit wall time "
               f"interpolated (log-log in error) to exactly {who}'s error. dt_factor 1 with an explicit error below "
               f"{who}'s means the explicit scheme is already more accurate at its stable step.")


CVODE_KEYS = ("steps", "rhs_evals", "jac_evals", "lin_setups", "err_test_fails", "newton_iters", "newton_fails",
              "root_evals", "events", "reinits")


# ================================================================ case 1
DROP = dict(m=1.0, R=0.05, k=1.0e6, e=0.8, h=0.1, tend=1.0)


def restitution_clipped(zeta, k, m):
    """Clipped-force restitution of the linear spring-dashpot (as in
    validation/spring_dashpot/check.py): contact ends when k p + c p' = 0."""
    wn = math.sqrt(k / m)
    wd = wn * math.sqrt(1 - zeta**2)
    tc = (math.pi - math.atan(2 * zeta * math.sqrt(1 - zeta**2) / (1 - 2 * zeta**2))) / wd
    return -math.exp(-zeta * wn * tc) * (math.cos(wd * tc) - zeta * wn / wd * math.sin(wd * tc))


def drop_params():
    p = dict(DROP)
    p["zeta"] = brentq(lambda z: restitution_clipped(z, p["k"], p["m"]) - p["e"], 1e-9, 0.7, xtol=1e-15)
    p["c"] = 2 * p["zeta"] * math.sqrt(p["k"] * p["m"])
    return p


def drop_reference(p, nmax=50):
    """Closed-form chain with gravity (validation/bouncing_ball/check.py):
    per bounce t_in, v_in, t_out, v_out, ratio = v_out/v_in, up to t_end."""
    M, K, C, Z = p["m"], p["k"], p["c"], p["zeta"]

    def contact_phase(vin):
        wn = math.sqrt(K / M)
        a, wd = Z * wn, wn * math.sqrt(1 - Z**2)
        ps = M * G / K
        A, B = -ps, (vin - a * ps) / wd

        def pp(t):
            return ps + math.exp(-a * t) * (A * math.cos(wd * t) + B * math.sin(wd * t))

        def dp(t):
            return math.exp(-a * t) * ((-a * A + wd * B) * math.cos(wd * t) + (-a * B - wd * A) * math.sin(wd * t))

        tc = brentq(lambda t: K * pp(t) + C * dp(t), 0.5 * math.pi / wd, 1.5 * math.pi / wd, xtol=1e-16, rtol=1e-15)
        return tc, -dp(tc), pp(tc)

    t = math.sqrt(2 * p["h"] / G)
    vin = math.sqrt(2 * G * p["h"])
    out = []
    for _ in range(nmax):
        tc, vout, pe = contact_phase(vin)
        if t + tc > p["tend"]:
            break
        out.append(dict(t_in=t, v_in=vin, t_out=t + tc, v_out=vout, ratio=vout / vin))
        tau = (vout + math.sqrt(vout**2 - 2 * G * pe)) / G
        t += tc + tau
        vin = math.sqrt(vout**2 - 2 * G * pe)
    return out


def drop_deck(p, rtol):
    d = Deck("bench: sphere drop, e = 0.8")
    R, m = p["R"], p["m"]
    z0 = R + p["h"]
    d.funct(1, [0.0, 1.0], [0.0, p["k"]], title="linear load curve")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, m, [0.4 * m * R * R] * 3, title="sphere")
    d.sphere(1, 1, (0.0, 0.0, z0), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, visc=p["c"], title="floor")
    d.run(p["tend"], 0.01)
    d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_vel=rtol, atol_energy=rtol)
    return d


def ratio_error(bounces, ref):
    """Max relative error of the rebound ratios over the compared bounces
    (NaN when one is missing)."""
    if len(bounces) < len(ref):
        return float("nan")
    return max(abs(b["ratio"] - r["ratio"]) / r["ratio"] for b, r in zip(bounces, ref))


def ricochet_bounces(r):
    """Impact and rebound velocities at the contact_close / contact_open
    event records."""
    out, tin, vin = [], None, None
    rec = np.where(r["at_event"] == 1)[0]
    for t, kind in zip(r["ev_t"], r["ev_kind"]):
        if len(rec) == 0:
            break
        idx = rec[np.argmin(np.abs(r["t"][rec] - t))]
        vz = float(r["vel"][idx, 0, 2])
        if kind == "contact_close":
            tin, vin = t, vz
        elif kind == "contact_open" and vin is not None:
            out.append(dict(t_in=tin, v_in=vin, t_out=t, v_out=vz, ratio=-vz / vin))
            vin = None
    return out


def bench_drop(B):
    p = drop_params()
    allref = drop_reference(p)
    # the last bounce in 1 s ends 0.5 ms before t_end: an integrator whose
    # bounce times drift by that much does not finish it; compare the bounces
    # that end at least 10 ms before t_end
    ref = [b for b in allref if b["t_out"] < p["tend"] - 0.01]
    res = {"params": {k: p[k] for k in ("m", "R", "k", "e", "h", "tend", "zeta", "c")}, "reference": allref,
           "compared_bounces": len(ref), "ricochet": [], "explicit": []}
    print(f"== Case 1: sphere drop: m = {p['m']} kg, R = {p['R']} m, k = {p['k']:.0e} N/m, Visc = {p['c']:.6f} N s/m "
          f"(zeta = {p['zeta']:.6f} for e = {p['e']}), from h = {p['h']} m, {p['tend']} s ==\n")
    table("Reference: closed-form contact phases under gravity chained with ballistic flights",
          ["bounce", "t_in [s]", "v_in [m/s]", "t_out [s]", "v_out/v_in", "(v_out/v_in - e)/e", "compared"],
          [[k + 1, f"{r['t_in']:.6f}", f"{r['v_in']:.6f}", f"{r['t_out']:.6f}", f"{r['ratio']:.9f}",
            f"{(r['ratio'] - p['e']) / p['e']:+.2e}", "yes" if k < len(ref) else "no"] for k, r in enumerate(allref)])

    rows = []
    for rtol in (1e-4, 1e-6, 1e-8):
        r = B.ricochet_run(drop_deck(p, rtol), f"drop_rtol{rtol:.0e}", time_repeat=20)
        if not r["ok"]:
            rows.append([f"{rtol:.0e}", "FAILED", r["stderr"][:70]])
            res["ricochet"].append({"rtol": rtol, "ok": False, "stderr": r["stderr"]})
            continue
        b = ricochet_bounces(r)
        err = ratio_error(b, ref)
        s = r["stats"]
        res["ricochet"].append({"rtol": rtol, "ok": True, "error": err, "wall": r["wall"], "cli_wall": r["cli_wall"],
                                "elapsed": r["elapsed"], "rss_kb": r["rss_kb"], "rss_core_kb": r.get("rss_core_kb"),
                                "energy_residual": r["timing"]["energy_residual"] if "timing" in r else None,
                                "stats": s, "bounces": b})
        rows.append([f"{rtol:.0e}", fmt_t(r["wall"]), fmt_t(r["cli_wall"]), fmt_t(r["elapsed"]), s.get("steps"),
                     s.get("rhs_evals"), s.get("jac_evals"), s.get("lin_setups"), s.get("events"), s.get("reinits"),
                     s.get("err_test_fails"), fmt_mb(r["rss_kb"]), f"{r['timing']['energy_residual']:.1e}" if "timing" in r else "-", fmt_e(err)])
    table("ricochet (atol_pos = 1e-3 rtol m, atol_vel = rtol m/s)",
          ["rtol", "wall", "wall+output", "process", "steps", "RHS", "Jac", "LU", "events", "restarts", "err fails",
           "peak RSS", "E resid [J]", "max rel err"], rows)

    factors = [1, 0.5, 0.25, 0.1, 0.05, 0.025, 0.01, 0.005, 0.0025, 0.001, 5e-4, 2.5e-4, 1e-4]
    if not B.quick:
        factors += [5e-5, 2.5e-5, 1e-5]
    rows = []
    for f in factors:
        x = B.explicit_run(["drop", p["m"], p["k"], p["c"], p["h"], p["tend"], f], repeat=5 if f >= 1e-4 else 2)
        if not x["ok"]:
            rows.append([f"{f:g}", "FAILED", x.get("stderr", "")[:60]])
            continue
        err = ratio_error(x["bounce"], ref)
        res["explicit"].append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "force_evals": x["force_evals"],
                                "wall": x["wall_time"], "rss_kb": x["rss_kb"], "error": err, "events": x["events"]})
        rows.append([f"{f:g}", f"{x['dt']:.3e}", fmt_t(x["wall_time"]), x["steps"], x["force_evals"], x["events"],
                     fmt_mb(x["rss_kb"]), fmt_e(err)])
    dt_s = res["explicit"][0]["dt"] if res["explicit"] else float("nan")
    table(f"explicit central difference (dt_factor 1 = 0.9 x stable step = {dt_s:.4e} s)",
          ["dt_factor", "dt [s]", "wall", "steps", "force evals", "events", "peak RSS", "max rel err"], rows)
    res["equal"] = equal_accuracy(res["ricochet"], res["explicit"])
    print_equal("Sphere drop", res["equal"], "Target: ricochet within 2x of explicit (explicit/ricochet >= 0.5) "
                "at ricochet's default tolerances (rtol 1e-6).")
    return res


# ================================================================ case 2
COL = dict(R=0.01, m=0.01, k=1.0e5, zeta=1.0, gap=1.0e-4, tend=5.0, dtout=0.5)


def column_deck(N, rtol, p=COL, locked=False):
    """The settling column; locked: /BCS holds the x, y translations and
    the rotations of every sphere (the 1-D model of cvode_ref)."""
    R, m, k, gap = p["R"], p["m"], p["k"], p["gap"]
    d = Deck(f"bench: settling column of {N} spheres" + (", locked to z" if locked else ""))
    d.funct(1, [0.0, 1.0], [0.0, k], title="linear load curve")
    z = [R + gap + i * (2 * R + gap) for i in range(N)]
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(N)])
    J = [0.4 * m * R * R] * 3
    for i in range(N):
        d.rbody(i + 1, i + 1, m, J, title=f"sphere {i + 1}")
    for i in range(N):
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
    floor = N + 1
    d.plane(floor, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.grav(1, "Z", -G)
    if locked:
        d.grnod(1, list(range(1, N + 1)), title="all spheres")
        d.bcs(1, 1, trarot="110 111", title="x, y and rotations held")
    c_floor = 2 * p["zeta"] * math.sqrt(k * m)       # m_red = m
    c_ss = 2 * p["zeta"] * math.sqrt(k * m / 2)      # m_red = m/2
    d.type6(1, 1, floor, 1, visc=c_floor, title="floor contact")
    for i in range(1, N):
        d.type6(i + 1, i, i + 1, 1, visc=c_ss, title=f"spheres {i}-{i + 1}")
    d.run(p["tend"], p["dtout"])
    d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_vel=rtol, atol_energy=rtol, max_steps=10**7)
    return d


def column_args(N, p=COL):
    return [N, p["R"], p["m"], p["k"], p["zeta"], p["gap"], p["tend"]]


def bench_column(B, sizes):
    p = COL
    res = {"params": dict(p), "sizes": {}}
    print(f"== Case 2: settling column: R = {p['R']} m, m = {p['m']} kg, k = {p['k']:.0e} N/m, critically damped "
          f"contacts (c = 2 sqrt(k m_red)), gaps {p['gap']} m, gravity, {p['tend']} s, dtout {p['dtout']} s ==\n")
    for N in sizes:
        scale = N * p["m"] * G
        S = {"N": N, "ricochet": [], "explicit": []}
        # ---- reference: event-located RK4 of the clipped law at h; at 2h for
        # its uncertainty
        h = 2e-5
        refs = {}
        for tag, hh in (("ref", h), ("ref2h", 2 * h)):
            ff = os.path.join(B.work, f"col{N}_{tag}.txt")
            x = B.explicit_run(["reference", N, p["R"], p["m"], p["k"], p["zeta"], -1, p["gap"], p["tend"], hh, "clip",
                                ff])
            x["F"] = np.loadtxt(ff, ndmin=1)
            refs[tag] = x
        F = refs["ref"]["F"]
        rf = refs["ref"]
        unc = float(np.max(np.abs(F - refs["ref2h"]["F"])) / scale)
        S["reference"] = {"h": h, "wall": rf["wall_time"], "rhs_evals": rf["rhs_evals"], "events": rf["events"],
                          "uncertainty": unc, "force_bottom": rf["force_bottom"], "max_speed": rf["max_speed"],
                          "top_height": rf["top_height"]}
        table(f"N = {N}: reference (event-located RK4, h = {h:g} s)",
              ["events", "bottom force [N]", "N m g [N]", "top centre z [m]", "max speed [m/s]", "uncertainty",
               "wall"],
              [[rf["events"], f"{rf['force_bottom']:.6f}", f"{scale:.6f}", f"{rf['top_height']:.6f}",
                f"{rf['max_speed']:.2e}", f"{unc:.1e}", fmt_t(rf["wall_time"])]],
              note="uncertainty = max |F(h) - F(2h)| / (N m g) over the contacts; max speed = fastest sphere at "
                   "t = 5 s (not settled when > 0)")

        # ---- ricochet
        # default tolerance first; at N = 1000 the second run only when the
        # first took less than 200 s (keeps `make bench` near 15 minutes)
        rtols = (1e-6, 1e-4) if N >= 1000 else (1e-4, 1e-6, 1e-8)
        rows, skipped = [], []
        for rtol in rtols:
            timeout = 600
            if N >= 1000 and S["ricochet"] and S["ricochet"][-1].get("spent", 1e9) > 300:
                rows.append([f"{rtol:.0e}", "skipped"])
                skipped.append(rtol)
                continue
            # wall time: rc_time (no output file) up to N = 100; at N = 1000
            # the CLI's integration time (the output is < 1 % of it there)
            # and the memory without output from a 0.1 s rc_time run
            r = B.ricochet_run(column_deck(N, rtol), f"col{N}_rtol{rtol:.0e}", timeout=timeout,
                               time_repeat=(5 if N <= 10 else 1) if N <= 100 else 0)
            if N > 100 and r.get("ok"):
                _, so2, _, _, rss2 = B.measured([B.rc_time, r["case"], 1, 0.1], 120)
                r["rss_core_kb"] = rss2
            if "stats" not in r:
                rows.append([f"{rtol:.0e}", "FAILED", fmt_t(r["elapsed"]), r["stderr"][:70]])
                S["ricochet"].append({"rtol": rtol, "ok": False, "stderr": r["stderr"], "elapsed": r["elapsed"]})
                continue
            s = r["stats"]
            complete = r["ok"] and abs(float(r["t"][-1]) - p["tend"]) < 1e-9
            fn = r["fn"][-1, :]
            err = float(np.max(np.abs(fn - F)) / scale) if complete else float("nan")
            zmin = float(np.min(r["pos"][-1, :, 2]))
            ztop = float(r["pos"][-1, N - 1, 2])
            S["ricochet"].append({"rtol": rtol, "ok": complete, "error": err, "wall": r["wall"],
                                  "spent": (r["elapsed"] or 0) + (r["wall"] if r["wall_src"] == "rc_time" else 0),
                                  "rss_core_kb": r.get("rss_core_kb"),
                                  "wall_src": r["wall_src"], "cli_wall": r["cli_wall"], "elapsed": r["elapsed"],
                                  "rss_kb": r["rss_kb"], "stats": s, "z_min_end": zmin, "z_top_end": ztop,
                                  "t_last": float(r["t"][-1]), "stderr": r["stderr"]})
            rows.append([f"{rtol:.0e}", fmt_t(r["wall"]) + ("" if r["wall_src"] == "rc_time" else " (CLI)"),
                         fmt_t(r["cli_wall"]), fmt_t(r["elapsed"]), s.get("steps"), s.get("rhs_evals"),
                         s.get("jac_evals"), s.get("lin_setups"), s.get("events"), s.get("reinits"),
                         s.get("err_test_fails"), s.get("nonlin_fails"), fmt_mb(r["rss_kb"]),
                         fmt_mb(r.get("rss_core_kb")), fmt_e(err),
                         f"{zmin:.3f}", f"{1e3 * r['wall'] / N:.2f}"])
        table(f"N = {N}: ricochet (wall: integration without output file)",
              ["rtol", "wall", "wall+output", "process", "steps", "RHS", "Jac", "LU", "events", "restarts",
               "err fails", "Newton fails", "peak RSS", "RSS no output", "max rel err", "min z end [m]",
               "wall/N [ms]"], rows,
              note="wall: rc_time, integration without output file ((CLI): the CLI's, with output); wall+output: "
                   "the CLI's stats_wall_time; process: CLI process elapsed; peak RSS: CLI; RSS no output: rc_time. "
                   + (f"rtol {', '.join(f'{x:.0e}' for x in skipped)} skipped: the rtol 1e-6 run took > 300 s. "
                      if skipped else "") +
                   "max rel err = max over contacts |F - F_ref| / (N m g) at t = 5 s; min z end = lowest sphere "
                   "centre at t = 5 s (the settled column has all centres above R = 0.01 m minus the bottom "
                   "penetration)")

        # ---- plain CVODE + KLU of the same ODE (cvode_ref: 2 states per
        # sphere, gap-scaled error weights)
        S["cvode"] = []
        rows = []
        for rtol in ((1e-4, 1e-6, 1e-8) if N <= 100 else (1e-6,)):
            ff = os.path.join(B.work, f"col{N}_cvode{rtol:.0e}.txt")
            x = B.cvode_run(["column"] + column_args(N) + [rtol, ff], repeat=3 if N <= 10 else 1, timeout=900)
            if not x["ok"]:
                rows.append([f"{rtol:.0e}", "FAILED", x.get("stderr", "")[:70]])
                continue
            err = float(np.max(np.abs(np.loadtxt(ff, ndmin=1) - F)) / scale)
            S["cvode"].append({"rtol": rtol, "ok": True, "error": err, "wall": x["wall_time"], "rss_kb": x["rss_kb"],
                               "stats": {k: x[k] for k in CVODE_KEYS if k in x}})
            rows.append([f"{rtol:.0e}", fmt_t(x["wall_time"]), x["steps"], x["rhs_evals"], x["jac_evals"],
                         x["lin_setups"], x["events"], x["reinits"], x["err_test_fails"], fmt_mb(x["rss_kb"]),
                         fmt_e(err), f"{1e3 * x['wall_time'] / max(1, x['steps']):.3f}"])
        table(f"N = {N}: plain CVODE + KLU (cvode_ref, 2 states per sphere, gap-scaled weights)",
              ["rtol", "wall", "steps", "RHS", "Jac", "LU", "events", "restarts", "err fails", "peak RSS",
               "max rel err", "wall/step [ms]"], rows,
              note="error weights 1/(rtol m g/k) on heights, 1/(rtol (|v| + g sqrt(m/k))) on velocities "
                   "(bench/cvode_ref.c)")

        # ---- explicit scan
        factors = [1, 0.5, 0.2, 0.1, 0.05, 0.02]
        if N <= 100:
            factors += [0.01, 0.005]
        rows = []
        for f in factors:
            ff = os.path.join(B.work, f"col{N}_cd{f:g}.txt")
            x = B.explicit_run(["column"] + column_args(N) + [f, ff], repeat=3 if N <= 100 else 1)
            if not x["ok"]:
                rows.append([f"{f:g}", "FAILED"])
                continue
            err = float(np.max(np.abs(np.loadtxt(ff, ndmin=1) - F)) / scale)
            S["explicit"].append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "force_evals": x["force_evals"],
                                  "wall": x["wall_time"], "rss_kb": x["rss_kb"], "error": err, "events": x["events"]})
            rows.append([f"{f:g}", f"{x['dt']:.3e}", fmt_t(x["wall_time"]), x["steps"], x["force_evals"], x["events"],
                         fmt_mb(x["rss_kb"]), fmt_e(err), f"{1e3 * x['wall_time'] / N:.3f}"])
        table(f"N = {N}: explicit central difference (dt_factor 1 = 0.9 x stable step)",
              ["dt_factor", "dt [s]", "wall", "steps", "force evals", "events", "peak RSS", "max rel err",
               "wall/N [ms]"], rows)
        S["equal"] = equal_accuracy(S["ricochet"], S["explicit"])
        print_equal(f"Column N = {N}", S["equal"], "Target at N = 1000: explicit/ricochet >= 10.")
        S["equal_cvode"] = equal_accuracy(S["cvode"], S["explicit"])
        print_equal(f"Column N = {N}, plain CVODE", S["equal_cvode"], "", who="cvode_ref")
        res["sizes"][str(N)] = S

    rows = []
    for N in sizes:
        S = res["sizes"][str(N)]
        r6 = next((r for r in S["ricochet"] if r["rtol"] == DEFAULT_RTOL and "stats" in r), None)
        e1 = next((x for x in S["explicit"] if x["dt_factor"] == 1), None)
        rows.append([N, fmt_t(r6["wall"]) if r6 else "-", f"{1e3 * r6['wall'] / N:.2f}" if r6 else "-",
                     r6["stats"]["steps"] if r6 else "-",
                     f"{1e3 * r6['wall'] / max(1, r6['stats']['steps']):.3f}" if r6 else "-",
                     fmt_t(e1["wall"]) if e1 else "-", f"{1e3 * e1['wall'] / N:.3f}" if e1 else "-",
                     f"{1e9 * e1['wall'] / e1['steps'] / N:.1f}" if e1 else "-"])
    table("Cost growth with N (ricochet at rtol 1e-6, explicit at its stable step)",
          ["N", "ricochet wall", "wall/N [ms]", "steps", "wall/step [ms]", "explicit wall", "wall/N [ms]",
           "ns per sphere-step"], rows)
    return res


# ================================================================ case 3
# Quasi-static benchmarks: the regime implicit integration is for.
QS = dict(R=0.01, m=0.01, k=1.0e5, zeta=1.0, hold=1.0)


def settled_heights(N, p=QS):
    """Static state under G: contact j (0 = floor) carries (N - j) m G, so
    its penetration is (N - j) m G / k."""
    z, zz = [], 0.0
    for i in range(N):
        zz += (p["R"] if i == 0 else 2 * p["R"]) - (N - i) * p["m"] * G / p["k"]
        z.append(zz)
    return z


# options of case 3a (command line): the ricochet decks' absolute tolerances ("scaled": atol_pos = 1e-3 rtol m,
# atol_vel = rtol m/s; "derived": only Rtol, the rest from the model's scales), their BDF Max_order, the
# ricochet rtols and the explicit dt_factors run (None: the defaults of bench_ramp)
# reuse_ref: take the RK4 references of an earlier run with the same arguments (files in the work directory)
# static_dtouts: the output intervals of the static analysis runs ("end": one equilibrium, at the end; a number:
# every that many seconds); repeat: best of how many timed runs of explicit_ref, cvode_ref, rc_time (N <= 100
# for ricochet's dynamic runs; the static runs always by rc_time)
RAMP_OPTS = {"atol": "scaled", "max_order": 5, "rtols": None, "cvode_rtols": None, "dt_factors": None,
             "reuse_ref": False, "static_dtouts": ("end", 1.0), "repeat": 1}

SMOOTH_POINTS = 20000  # samples of the smooth ramp in the deck's /FUNCT


def ramp_deck(N, T, rtol, p=QS, shape="linear", static_dtout=None):
    """The settled column, gravity ramped G -> 2 G over T (a /GRAV with a
    /FUNCT time function), held for p["hold"] s. shape "smooth": the ramp
    1 + (1 - cos(pi t/T))/2, sampled at SMOOTH_POINTS + 1 points (the linear
    interpolation departs from it by at most pi^2/(16 n^2) = 1.5e-9 of G).
    static_dtout (> 0): the static analysis (/SOLVER Method 3) with output
    (and equilibrium) times every static_dtout s up to the end, the column
    locked to z by /BCS 110 111 as the locked settling column (statics
    needs the lateral support a frictionless column lacks); rtol unused."""
    R, m, k = p["R"], p["m"], p["k"]
    tend = T + p["hold"]
    d = Deck(f"bench: static column of {N} spheres, G -> 2 G over {T:g} s ({shape}), output every {static_dtout:g} s"
             if static_dtout else f"bench: settled column of {N} spheres, gravity ramped G -> 2 G over {T:g} s ({shape})")
    d.funct(1, [0.0, 1.0], [0.0, k], title="linear load curve")
    if shape == "smooth":
        ts = [T * i / SMOOTH_POINTS for i in range(SMOOTH_POINTS + 1)]
        d.funct(2, ts + [T + 1.0e4], [1.0 + 0.5 * (1.0 - math.cos(math.pi * t / T)) for t in ts] + [2.0],
                title=f"gravity factor: 1 + (1 - cos(pi t / {T:g})) / 2, then 2")
    else:
        d.funct(2, [0.0, T, T + 1.0e4], [1.0, 2.0, 2.0], title=f"gravity factor: 1 -> 2 over {T:g} s, then 2")
    z = settled_heights(N, p)
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(N)])
    J = [0.4 * m * R * R] * 3
    for i in range(N):
        d.rbody(i + 1, i + 1, m, J, title=f"sphere {i + 1}")
    for i in range(N):
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
    floor = N + 1
    d.plane(floor, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.grav_fct(1, "Z", -G, 2)
    if static_dtout:
        d.grnod(1, list(range(1, N + 1)), title="all spheres")
        d.bcs(1, 1, trarot="110 111", title="x, y and rotations held")
    c_floor = 2 * p["zeta"] * math.sqrt(k * m)
    c_ss = 2 * p["zeta"] * math.sqrt(k * m / 2)
    d.type6(1, 1, floor, 1, visc=c_floor, title="floor contact")
    for i in range(1, N):
        d.type6(i + 1, i, i + 1, 1, visc=c_ss, title=f"spheres {i}-{i + 1}")
    if static_dtout:
        d.run(tend, static_dtout)
        d.solver(method=3)
        return d
    d.run(tend, tend / 20)
    if RAMP_OPTS["atol"] == "derived":  # blank Atol fields: derived from the model's scales (theory 7.1)
        d.solver(rtol=rtol, atol_pos=0.0, atol_quat=0.0, atol_vel=0.0, atol_omega=0.0, atol_energy=0.0,
                 max_order=RAMP_OPTS["max_order"], max_steps=10**7)
    else:
        d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_vel=rtol, atol_energy=rtol,
                 max_order=RAMP_OPTS["max_order"], max_steps=10**7)
    return d


def ramp_args(N, T, p=QS):
    return [N, p["R"], p["m"], p["k"], p["zeta"], T, T + p["hold"]]


def equal_rows(B, label, S, who_runs, who):
    eq = equal_accuracy(S[who_runs], S["explicit"])
    print_equal(label, eq, "", who=who)
    return eq


def bench_ramp(B, sizes, ramps, shape="linear"):
    p = QS
    res = {"params": dict(p), "shape": shape, "cases": {}}
    sub = {"linear": ("ramp", "rampref"), "smooth": ("sramp", "srampref")}[shape]
    print(f"== Case 3a: quasi-static column: the settled column (R = {p['R']} m, m = {p['m']} kg, k = {p['k']:.0e} "
          f"N/m, critically damped contacts), gravity ramped G -> 2 G over T ("
          + ("linear" if shape == "linear" else "smooth: 1 + (1 - cos(pi t/T))/2") + f"), held {p['hold']} s ==\n")
    for N in sizes:
        scale = N * p["m"] * G
        F_stat = np.array([2.0 * (N - j) * p["m"] * G for j in range(N)])
        for T in ramps:
            key = f"N{N}_T{T:g}" + ("" if shape == "linear" else "_smooth")
            S = {"N": N, "T": T, "ricochet": [], "cvode": [], "explicit": [], "static": []}
            rep = RAMP_OPTS["repeat"]
            # ---- reference: RK4 (no events in this problem) at h and 2h
            h = 5e-5
            refs = {}
            for tag, hh in (("ref", h), ("ref2h", 2 * h)):
                ff = os.path.join(B.work, f"ramp{key}_{tag}.txt")
                argv = [sub[1]] + ramp_args(N, T) + [hh, ff]
                saved = ff + ".json"  # the run's key=value output, for --reuse-ref
                x = None
                if RAMP_OPTS["reuse_ref"] and os.path.exists(saved) and os.path.exists(ff) \
                        and os.path.getmtime(saved) > os.path.getmtime(B.explicit):
                    with open(saved) as f:
                        x = json.load(f)
                    if x.get("argv") != [str(a) for a in argv]:
                        x = None
                if x is None:
                    x = B.explicit_run(argv)
                    if not x["ok"]:
                        sys.exit(f"bench: RK4 reference failed: {x}")
                    with open(saved, "w") as f:
                        json.dump(dict(x, argv=[str(a) for a in argv]), f)
                x["F"] = np.loadtxt(ff, ndmin=1)
                refs[tag] = x
            F = refs["ref"]["F"]
            rf = refs["ref"]
            unc = float(np.max(np.abs(F - refs["ref2h"]["F"])) / scale)
            stat_dev = float(np.max(np.abs(F - F_stat)) / scale)
            S["reference"] = {"h": h, "wall": rf["wall_time"], "events": rf["events"], "uncertainty": unc,
                              "statics_deviation": stat_dev, "force_bottom": rf["force_bottom"],
                              "max_speed": rf["max_speed"]}
            table(f"N = {N}, ramp over T = {T:g} s (+ {p['hold']:g} s hold): RK4 reference, h = {h:g} s",
                  ["events", "bottom force [N]", "2 N m g [N]", "max speed [m/s]", "uncertainty", "|ref - statics|",
                   "wall"],
                  [[rf["events"], f"{rf['force_bottom']:.6f}", f"{2 * scale:.6f}", f"{rf['max_speed']:.2e}",
                    f"{unc:.1e}", f"{stat_dev:.1e}", fmt_t(rf["wall_time"])]],
                  note="uncertainty = max |F(h) - F(2h)| / (N m g); |ref - statics| = max |F_ref - 2 (N - j) m g| / "
                       "(N m g): the dynamics left at the end of the hold (the slow modes rung by the ramp, "
                       "by its kinks when linear), physics, not integration error")

            # ---- ricochet
            rows = []
            rtols = RAMP_OPTS["rtols"]
            if rtols is None:
                rtols = (1e-4, 1e-6) if B.quick else (1e-4, 1e-6, 1e-8)
            tag = ("_derived" if RAMP_OPTS["atol"] == "derived" else "") + (
                f"_q{RAMP_OPTS['max_order']}" if RAMP_OPTS["max_order"] != 5 else "")
            for rtol in rtols:
                r = B.ricochet_run(ramp_deck(N, T, rtol, shape=shape), f"ramp{key}_rtol{rtol:.0e}{tag}", timeout=1800,
                                   time_repeat=rep if N <= 100 else 0)
                if "stats" not in r:
                    rows.append([f"{rtol:.0e}", "FAILED", fmt_t(r["elapsed"]), r["stderr"][:70]])
                    S["ricochet"].append({"rtol": rtol, "ok": False, "stderr": r["stderr"]})
                    continue
                st = r["stats"]
                complete = r["ok"] and abs(float(r["t"][-1]) - (T + p["hold"])) < 1e-9
                fn = r["fn"][-1, :]
                err = float(np.max(np.abs(fn - F)) / scale) if complete else float("nan")
                es = float(np.max(np.abs(fn - F_stat)) / scale) if complete else float("nan")
                S["ricochet"].append({"rtol": rtol, "ok": complete, "error": err, "error_statics": es,
                                      "wall": r["wall"], "wall_src": r["wall_src"], "cli_wall": r["cli_wall"],
                                      "elapsed": r["elapsed"], "rss_kb": r["rss_kb"], "stats": st})
                rows.append([f"{rtol:.0e}", fmt_t(r["wall"]) + ("" if r["wall_src"] == "rc_time" else " (CLI)"),
                             st.get("steps"), st.get("rhs_evals"), st.get("jac_evals"), st.get("lin_setups"),
                             st.get("events"), st.get("reinits"), st.get("err_test_fails"), fmt_e(err), fmt_e(es)])
            table(f"N = {N}, T = {T:g} s: ricochet ("
                  + ("absolute tolerances derived from the model" if RAMP_OPTS["atol"] == "derived"
                     else "atol_pos = 1e-3 rtol m, atol_vel = rtol m/s")
                  + f", BDF max order {RAMP_OPTS['max_order']})",
                  ["rtol", "wall", "steps", "RHS", "Jac", "LU", "events", "restarts", "err fails", "err vs RK4",
                   "err vs statics"], rows,
                  note="wall: rc_time (no output file), (CLI): the CLI's stats_wall_time (N = 1000); err = max over "
                       "contacts |F - F_ref| / (N m g) at the end of the hold")

            # ---- plain CVODE
            rows = []
            rtols = RAMP_OPTS["cvode_rtols"]
            if rtols is None:
                rtols = (1e-2, 1e-4, 1e-6) if B.quick else (1e-2, 1e-3, 1e-4, 1e-6, 1e-8)
            for rtol in rtols:
                ff = os.path.join(B.work, f"ramp{key}_cvode{rtol:.0e}.txt")
                x = B.cvode_run([sub[0]] + ramp_args(N, T) + [rtol, ff], repeat=rep, timeout=1800)
                if not x["ok"]:
                    rows.append([f"{rtol:.0e}", "FAILED", x.get("stderr", "")[:70]])
                    continue
                Fx = np.loadtxt(ff, ndmin=1)
                err = float(np.max(np.abs(Fx - F)) / scale)
                es = float(np.max(np.abs(Fx - F_stat)) / scale)
                S["cvode"].append({"rtol": rtol, "ok": True, "error": err, "error_statics": es,
                                   "wall": x["wall_time"], "rss_kb": x["rss_kb"],
                                   "stats": {k: x[k] for k in CVODE_KEYS if k in x}})
                rows.append([f"{rtol:.0e}", fmt_t(x["wall_time"]), x["steps"], x["rhs_evals"], x["jac_evals"],
                             x["lin_setups"], x["err_test_fails"], fmt_e(err), fmt_e(es)])
            table(f"N = {N}, T = {T:g} s: plain CVODE + KLU (cvode_ref, gap-scaled weights)",
                  ["rtol", "wall", "steps", "RHS", "Jac", "LU", "err fails", "err vs RK4", "err vs statics"], rows)

            # ---- explicit
            rows = []
            factors = RAMP_OPTS["dt_factors"] or ((1, 0.5) if B.quick else (1, 0.5, 0.2, 0.1))
            for f in factors:
                ff = os.path.join(B.work, f"ramp{key}_cd{f:g}.txt")
                x = B.explicit_run([sub[0]] + ramp_args(N, T) + [f, ff], repeat=rep)
                if not x["ok"]:
                    rows.append([f"{f:g}", "FAILED"])
                    continue
                Fx = np.loadtxt(ff, ndmin=1)
                err = float(np.max(np.abs(Fx - F)) / scale)
                es = float(np.max(np.abs(Fx - F_stat)) / scale)
                S["explicit"].append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "wall": x["wall_time"],
                                      "error": err, "error_statics": es, "events": x["events"]})
                rows.append([f"{f:g}", f"{x['dt']:.3e}", fmt_t(x["wall_time"]), x["steps"], x["events"], fmt_e(err),
                             fmt_e(es)])
            table(f"N = {N}, T = {T:g} s: explicit central difference", ["dt_factor", "dt [s]", "wall", "steps",
                  "events", "err vs RK4", "err vs statics"], rows)
            # ---- static analysis (Method 3, locked column): the equilibrium under 2 G at the end
            bench_ramp_static(B, S, N, T, key, shape, F, F_stat, scale)
            S["equal"] = equal_rows(B, f"Ramp N = {N}, T = {T:g} s", S, "ricochet", "ricochet")
            S["equal_cvode"] = equal_rows(B, f"Ramp N = {N}, T = {T:g} s, plain CVODE", S, "cvode", "cvode_ref")
            S["equal_reverse"] = equal_reverse(f"Ramp N = {N}, T = {T:g} s", S["explicit"],
                                               {"ricochet": S["ricochet"], "cvode_ref": S["cvode"]})
            res["cases"][key] = S
    return res


def bench_ramp_static(B, S, N, T, key, shape, F, F_stat, scale, p=QS):
    """The static analysis of the ramped column (ramp_deck with
    static_dtout): its end forces against the RK4 reference F (the dynamic
    answer, with the ringing the ramp left) and against the exact statics
    F_stat = 2 (N - j) m g (the right reference of a static question), and
    explicit/static at equal accuracy on each measure. Appends to S["static"]."""
    tend = T + p["hold"]
    rows = []
    for dto in RAMP_OPTS["static_dtouts"]:
        dt = tend if dto == "end" else float(dto)
        label = "end" if dto == "end" else f"{dt:g} s"
        name = f"ramp{key}_static_" + ("end" if dto == "end" else f"{dt:g}s")
        r = B.ricochet_run(ramp_deck(N, T, 0.0, shape=shape, static_dtout=dt), name, timeout=1800,
                           time_repeat=max(3, RAMP_OPTS["repeat"]))
        complete = r.get("ok") and "t" in r and abs(float(r["t"][-1]) - tend) < 1e-9
        if not complete:
            why = r.get("stderr", "").replace(r.get("case", ""), "DECK")
            rows.append([label, "FAILED", fmt_t(r.get("elapsed")), why[:200]])
            S["static"].append({"dtout": label, "ok": False, "stderr": r.get("stderr")})
            continue
        st = r["stats"]
        fn = r["fn"][-1, :]
        err = float(np.max(np.abs(fn - F)) / scale)
        es = float(np.max(np.abs(fn - F_stat)) / scale)
        S["static"].append({"dtout": label, "rtol": label, "ok": True, "error": err, "error_statics": es,
                            "wall": r["wall"], "wall_src": r["wall_src"], "cli_wall": r["cli_wall"],
                            "process_cpu": r["process_cpu"], "elapsed": r["elapsed"], "rss_kb": r["rss_kb"],
                            "records": int(len(r["t"])), "stats": st})
        rows.append([label, len(r["t"]), fmt_t(r["wall"]) + ("" if r["wall_src"] == "rc_time" else " (CLI)"),
                     fmt_t(r["elapsed"]), st.get("steps"), st.get("nonlin_iters"), st.get("jac_evals"),
                     st.get("events"), fmt_e(err), fmt_e(es)])
    table(f"N = {N}, T = {T:g} s: ricochet static analysis (Method 3, column locked to z)",
          ["output every", "records", "wall", "CLI process", "load steps", "Newton its", "Jac", "flips",
           "err vs RK4", "err vs statics"], rows,
          note="wall: rc_time, best of 3 (no output file); CLI process: the whole `ricochet run` (wall). err vs "
               "statics = max |F - 2 (N - j) m g| / (N m g): the right measure of a static answer; err vs RK4 "
               "includes the ringing the ramp left in the dynamic reference (its |ref - statics|)")
    ok = [r for r in S["static"] if r["ok"]]
    ex = [x for x in S["explicit"] if not math.isnan(x.get("error", float("nan")))]
    if not ok or not ex:
        return
    rows = []
    S["static_equal"] = {}
    for meas, ek in (("RK4", "error"), ("statics", "error_statics")):
        eq = equal_accuracy([dict(r, error=r[ek]) for r in ok], [dict(x, error=x[ek]) for x in ex])
        S["static_equal"][meas] = eq
        stable = max(ex, key=lambda x: x["dt"])
        for r, q in zip(ok, eq):
            m = (f"dt_factor {q['explicit_dt_factor']:g}: {fmt_t(q['explicit_wall'])} ({fmt_e(q['explicit_error'])})"
                 if q["explicit_wall"] is not None else f"none (finest {fmt_e(q['finest_explicit_error'])})")
            rows.append([meas, r["dtout"], fmt_e(r[ek]), fmt_t(r["wall"]), m,
                         f"{q['ratio']:.3g}" if q["ratio"] else "-",
                         f"{fmt_t(stable['wall'])} ({fmt_e(stable[ek])})", f"{stable['wall'] / r['wall']:.3g}"])
    table(f"Ramp N = {N}, T = {T:g} s: static analysis against explicit",
          ["measure", "static every", "static err", "static wall", "explicit as accurate", "explicit/static",
           "explicit stable step (err)", "stable/static"], rows,
          note="explicit/static > 1: the static analysis faster; 'none': no explicit run of the scan is as "
               "accurate (against the statics the explicit error is the ringing left at the end, not its step)")


# -------------------------------------------------------------- stick-slip
# options of case 3b (command line): the ricochet decks' absolute tolerances ("scaled": atol_pos = 1e-3 rtol m,
# atol_vel = 1e-2 rtol m/s; "derived": only Rtol) and the ricochet rtols run
SS_OPTS = {"atol": "scaled", "rtols": (1e-6, 1e-8, 1e-10), "dt_factors": None}
SS = dict(m=1.0, R=0.05, k=1.0e6, ks=100.0, V=0.01, mus=0.4, muk=0.25, v1=2.8e-6, v2=5.6e-6, visf=1.0e6,
          manchor=1.0e12, L0=1.0, tend=100.0)


def ss_C(p=SS):
    """Adhesion coefficient of the viscous law: C = sqrt(2 VISF K m_red), the
    floor fixed (m_red = m)."""
    return math.sqrt(2.0 * p["visf"] * p["k"] * p["m"])


def ss_mu(s, p=SS):
    """Renard's law with mu_max = mu_s, mu_min = mu_d = mu_k: a two-level law
    with a cubic drop between V_cr1 and V_cr2."""
    if s <= p["v1"]:
        return p["mus"]
    if s < p["v2"]:
        w = (s - p["v1"]) / (p["v2"] - p["v1"])
        return p["mus"] + (p["muk"] - p["mus"]) * (3.0 - 2.0 * w) * w * w
    return p["muk"]


def ss_deck(tend, rtol, p=SS):
    """A locked-rotation sphere (the block) at its static penetration on a
    fixed floor; a linear spring ks from its centre to an anchor body (1e12 kg,
    along x only, /INIVEL V) moving at V; /FRICTION Renard two-level, viscous
    form (as validation/frc_stick_slip, whose belt is here the anchor)."""
    M, R, K = p["m"], p["R"], p["k"]
    z0 = R - M * G / K
    d = Deck("bench: block dragged across a floor through a spring: stick-slip")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, 0.0, 0.0, z0), (2, -p["L0"], 0.0, z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.rbody(2, 2, p["manchor"], [p["manchor"]] * 3, grnod=2, title="anchor 1e12 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0 (fixed)")
    d.grnod(1, [1], title="block")
    d.grnod(2, [2], title="anchor")
    d.bcs(1, 1, "010 111", title="block held in y, no rotation")
    d.bcs(2, 2, "011 111", title="anchor moves along x only")
    d.inivel(1, (p["V"], 0.0, 0.0), 2)
    d.grav(1, "Z", -G, 1)  # on the block only
    d.type6(1, 1, 2, 1, visc=2.0 * 0.5 * math.sqrt(K * M), title="contact (no TYPE6 friction)")
    d.friction(1, ifric=3, iform=1, c=(p["mus"], p["muk"], p["mus"], p["muk"], p["v1"], p["v2"]), visf=p["visf"],
               title="Renard two-level: mu_s 0.4, mu_k 0.25, V_cr 2.8, 5.6 um/s; viscous VISF 1e6")
    d.spring(1, 2, (-p["L0"], 0.0, z0), 1, (0.0, 0.0, z0), a=p["ks"], title="spring 100 N/m to the anchor")
    d.run(tend, 0.5)
    if SS_OPTS["atol"] == "derived":  # blank Atol fields: derived from the model's scales (theory 7.1)
        d.solver(rtol=rtol, atol_pos=0.0, atol_quat=0.0, atol_vel=0.0, atol_omega=0.0, atol_energy=0.0,
                 max_steps=10**8)
    else:
        d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_vel=1e-2 * rtol, atol_energy=rtol, max_steps=10**8)
    return d


def ss_reference(tend, rtol=1e-11, p=SS):
    """Independent integration (scipy Radau) of m x'' = ks (V t - x) + F,
    F = -C u while C |u| < mu(|u|) m g (stick: adhesion creep), F = -mu(|u|) m g
    sign(u) once saturated (slip); terminal events at the switches and at
    |u| = V_cr1, V_cr2 (no step across a breakpoint of mu). Returns the
    switches [(kind, t, x)] and the wall time."""
    from scipy.integrate import solve_ivp
    M, KS, V, C, FN = p["m"], p["ks"], p["V"], ss_C(p), p["m"] * G

    def f_stick(t, y):
        return [y[1], (KS * (V * t - y[0]) - C * y[1]) / M]

    def f_slip(t, y):
        return [y[1], (KS * (V * t - y[0]) - ss_mu(abs(y[1]), p) * FN * np.sign(y[1])) / M]

    def ev(fun, direction):
        fun.terminal, fun.direction = True, direction
        return fun

    def sat(t, y):
        return C * abs(y[1]) - ss_mu(abs(y[1]), p) * FN

    def at(v):
        return lambda t, y: abs(y[1]) - v

    t0 = time.time()
    t, y, slip, reg, out = 0.0, np.array([0.0, 0.0]), False, 0, []
    while t < tend:
        if not slip:
            evs, f = [ev(sat, 1)], f_stick
        elif reg == 0:
            evs, f = [ev(sat, -1), ev(at(p["v1"]), 1)], f_slip
        elif reg == 1:
            evs, f = [ev(at(p["v1"]), -1), ev(at(p["v2"]), 1)], f_slip
        else:
            evs, f = [ev(at(p["v2"]), -1)], f_slip
        s = solve_ivp(f, (t, tend), y, method="Radau", rtol=rtol, atol=[1e-14, 1e-14], events=evs)
        if s.status != 1:
            break
        k = [j for j in range(len(evs)) if len(s.t_events[j])][0]
        t, y = s.t_events[k][0], s.y_events[k][0].copy()
        if not slip:
            slip, reg = True, 0
            out.append(("slip", t, y[0]))
        elif reg == 0:
            if k == 0:
                slip = False
                out.append(("stick", t, y[0]))
            else:
                reg = 1
        elif reg == 1:
            reg = 0 if k == 0 else 2
        else:
            reg = 1
    return out, time.time() - t0


def ss_classical(p=SS):
    """Classical two-level cycle (rigid stick; validation/frc_stick_slip):
    slip duration (pi + 2 atan(V/(w D)))/w, period that + 2 D/V, slip
    distance 2 D + V t_slip, with w = sqrt(ks/m), D = (mu_s - mu_k) m g/ks."""
    w = math.sqrt(p["ks"] / p["m"])
    D = (p["mus"] - p["muk"]) * p["m"] * G / p["ks"]
    ts = (math.pi + 2.0 * math.atan(p["V"] / (w * D))) / w
    return {"slip_time": ts, "period": ts + 2.0 * D / p["V"], "slip_distance": 2.0 * D + p["V"] * ts}


def ss_measures(sw, ref):
    """sw, ref: switch lists [(kind, t, x)]. Returns the mean period (first
    to last slip onset), the mean slip distance, and the errors against ref:
    period (relative), slip distance (max over cycles, relative to the mean
    reference distance), switch times (max |t - t_ref| / period_ref); NaN when
    the switch sequences differ."""
    def stats(s):
        slips = [(t, x) for k, t, x in s if k == "slip"]
        sticks = [(t, x) for k, t, x in s if k == "stick"]
        n = min(len(slips), len(sticks))
        per = (slips[-1][0] - slips[0][0]) / (len(slips) - 1) if len(slips) > 1 else float("nan")
        dist = [sticks[i][1] - slips[i][1] for i in range(n)]
        return per, dist, len(slips)
    per, dist, ns = stats(sw)
    pr, dr, nr = stats(ref)
    out = {"period": per, "slip_distance": float(np.mean(dist)) if dist else float("nan"), "slips": ns}
    if [k for k, _, _ in sw] != [k for k, _, _ in ref]:
        out.update(period_err=float("nan"), dist_err=float("nan"), time_err=float("nan"), error=float("nan"))
        return out
    dmean = float(np.mean(dr))
    out["period_err"] = abs(per - pr) / pr
    out["dist_err"] = max(abs(a - b) for a, b in zip(dist, dr)) / dmean
    out["time_err"] = max(abs(a[1] - b[1]) for a, b in zip(sw, ref)) / pr
    out["error"] = max(out["period_err"], out["dist_err"], out["time_err"])
    return out


def ricochet_switches(r):
    """fric_saturate (slip) / fric_unsaturate (stick) events with the block's
    x at the event records."""
    out = []
    rec = np.where(r["at_event"] == 1)[0]
    for t, kind in zip(r["ev_t"], r["ev_kind"]):
        if kind not in ("fric_saturate", "fric_unsaturate") or len(rec) == 0:
            continue
        idx = rec[np.argmin(np.abs(r["t"][rec] - t))]
        out.append(("slip" if kind == "fric_saturate" else "stick", float(t), float(r["pos"][idx, 0, 0])))
    return out


def bench_stickslip(B):
    p = dict(SS)
    if B.quick:
        p["tend"] = 20.0
    C = ss_C(p)
    res = {"params": p, "C": C, "ricochet": [], "explicit": []}
    cl = ss_classical(p)
    print(f"== Case 3b: stick-slip: block (m = {p['m']} kg) dragged across a floor through a spring ks = {p['ks']:g} "
          f"N/m whose anchor moves at V = {p['V']} m/s, {p['tend']:g} s; Renard two-level friction mu_s = {p['mus']}, "
          f"mu_k = {p['muk']} (drop between {p['v1']:.1e} and {p['v2']:.1e} m/s), viscous form C = {C:.4g} N s/m ==\n")
    ref, rwall = ss_reference(p["tend"], p=p)
    mref = ss_measures(ref, ref)
    res["reference"] = {"switches": ref, "wall": rwall, **{k: mref[k] for k in ("period", "slip_distance", "slips")}}
    unc = None
    if not B.quick:
        ref2, _ = ss_reference(p["tend"], rtol=1e-9, p=p)
        unc = ss_measures(ref2, ref)["error"]
    res["reference"]["uncertainty"] = unc
    table("Reference: scipy Radau (rtol 1e-11) of the same law, event-located; classical two-level cycle",
          ["slips", "period [s]", "slip distance [m]", "classical period", "classical slip distance", "uncertainty",
           "wall"],
          [[mref["slips"], f"{mref['period']:.9f}", f"{mref['slip_distance']:.9f}", f"{cl['period']:.9f}",
            f"{cl['slip_distance']:.9f}", fmt_e(unc), fmt_t(rwall)]],
          note="uncertainty: the error measure of a rtol 1e-9 run against it; the classical cycle (rigid stick, "
               "sharp drop) differs from the regularised law by ~1e-3 and from the first cycle (start at rest)")

    rows = []
    for rtol in SS_OPTS["rtols"]:
        tag = "_derived" if SS_OPTS["atol"] == "derived" else ""
        r = B.ricochet_run(ss_deck(p["tend"], rtol, p), f"stickslip_rtol{rtol:.0e}{tag}", timeout=900,
                           time_repeat=3)
        if "stats" not in r:
            rows.append([f"{rtol:.0e}", "FAILED", r["stderr"][:70]])
            res["ricochet"].append({"rtol": rtol, "ok": False, "stderr": r["stderr"]})
            continue
        st = r["stats"]
        m = ss_measures(ricochet_switches(r), ref)
        res["ricochet"].append({"rtol": rtol, "ok": r["ok"], "wall": r["wall"], "cli_wall": r["cli_wall"],
                                "stats": st, **m})
        rows.append([f"{rtol:.0e}", fmt_t(r["wall"]), st.get("steps"), st.get("rhs_evals"), st.get("jac_evals"),
                     st.get("lin_setups"), st.get("events"), st.get("reinits"), m["slips"], f"{m['period']:.7f}",
                     fmt_e(m["period_err"]), fmt_e(m["dist_err"]), fmt_e(m["time_err"])])
    table("stick-slip: ricochet (" + ("absolute tolerances derived from the model" if SS_OPTS["atol"] == "derived"
                                      else "atol_pos = 1e-3 rtol m, atol_vel = 1e-2 rtol m/s") + ")",
          ["rtol", "wall", "steps", "RHS", "Jac", "LU", "events", "restarts", "slips", "period [s]", "period err",
           "slip dist err", "switch time err"], rows,
          note="wall: rc_time (no output file); errors against the reference: period and slip distance relative, "
               "switch times max |t - t_ref| / period")

    # plain CVODE of the same 1-D law (cvode_ref stickslip: 2 states, dense
    # 2 x 2, the same tolerances as the ricochet deck, a restart at every
    # switch)
    res["cvode"] = []
    rows = []
    for rtol in (1e-6, 1e-8, 1e-10):
        ff = os.path.join(B.work, f"stickslip_cvode{rtol:.0e}.txt")
        x = B.cvode_run(["stickslip", p["m"], p["ks"], C, p["mus"], p["muk"], p["v1"], p["v2"], p["V"], p["tend"],
                         rtol, ff], repeat=3)
        if not x["ok"]:
            rows.append([f"{rtol:.0e}", "FAILED", x.get("stderr", "")[:70]])
            continue
        sw = []
        with open(ff) as fh:
            for ln in fh:
                k, t, xx = ln.split()
                sw.append((k, float(t), float(xx)))
        m = ss_measures(sw, ref)
        res["cvode"].append({"rtol": rtol, "ok": True, "wall": x["wall_time"],
                             "stats": {k: x[k] for k in CVODE_KEYS if k in x}, **m})
        rows.append([f"{rtol:.0e}", fmt_t(x["wall_time"]), x["steps"], x["rhs_evals"], x["jac_evals"],
                     x["lin_setups"], x["events"], x["reinits"], m["slips"], f"{m['period']:.7f}",
                     fmt_e(m.get("period_err")), fmt_e(m.get("dist_err")), fmt_e(m.get("time_err"))])
    table("stick-slip: plain CVODE (cvode_ref stickslip, 2 states, atol_x = 1e-3 rtol m, atol_u = 1e-2 rtol m/s)",
          ["rtol", "wall", "steps", "RHS", "Jac", "LU", "events", "restarts", "slips", "period [s]", "period err",
           "slip dist err", "switch time err"], rows)

    rows = []
    for f in SS_OPTS["dt_factors"] or ((1, 0.5) if B.quick else (1, 0.5, 0.25, 0.1, 0.05)):
        ff = os.path.join(B.work, f"stickslip_cd{f:g}.txt")
        x = B.explicit_run(["stickslip", p["m"], p["ks"], C, p["mus"], p["muk"], p["v1"], p["v2"], p["V"], p["tend"],
                            f, ff])
        if not x["ok"]:
            rows.append([f"{f:g}", "FAILED"])
            continue
        sw = []
        with open(ff) as fh:
            for ln in fh:
                k, t, xx = ln.split()
                sw.append((k, float(t), float(xx)))
        m = ss_measures(sw, ref)
        res["explicit"].append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "wall": x["wall_time"], **m})
        rows.append([f"{f:g}", f"{x['dt']:.3e}", fmt_t(x["wall_time"]), x["steps"], m["slips"], f"{m['period']:.7f}",
                     fmt_e(m["period_err"]), fmt_e(m["dist_err"]), fmt_e(m["time_err"])])
    table("stick-slip: explicit central difference (stable step ~ 2 m / C: the adhesion is a stiff damper)",
          ["dt_factor", "dt [s]", "wall", "steps", "slips", "period [s]", "period err", "slip dist err",
           "switch time err"], rows)
    res["equal"] = equal_accuracy(res["ricochet"], res["explicit"])
    print_equal("Stick-slip", res["equal"], "error = max(period, slip distance, switch time errors)")
    res["equal_cvode"] = equal_accuracy(res["cvode"], res["explicit"])
    print_equal("Stick-slip, plain CVODE", res["equal_cvode"], "", who="cvode_ref")
    res["equal_reverse"] = equal_reverse("Stick-slip", res["explicit"],
                                         {"ricochet": res["ricochet"], "cvode_ref": res["cvode"]})
    return res


# ------------------------------------------------- stick-slip onset in statics
# Case 3c: the drag to the slip, solved statically (/SOLVER Method 3). A block
# pressed on a floor (its height imposed at the static penetration m g / k:
# F_n = m g), held by the TYPE6 stick spring K_t (Coulomb mu), pulled along x
# by a force ramped at RATE N/s (a /GRAV along x on the block alone: the drag
# of the stick-slip spring, ks V = 1 N/s, on a block that does not move). A
# spring drag would hold the slide (an equilibrium in slip, which the static
# analysis follows); a force does not, so the static analysis ends where
# friction can no longer hold: rate t* = mu m g.
SLIP = dict(m=1.0, R=0.05, k=1.0e6, kt=1.0e6, mu=0.4, rates=(1.0, 0.01), target=1e-5)


def slip_deck(rate, p=SLIP):
    """The static deck: equilibria every T/10 up to T = 5 N / rate (the slip
    at t* = mu m g / rate = 0.785 T)."""
    M, R, K = p["m"], p["R"], p["k"]
    T = 5.0 / rate
    z0 = R - M * G / K
    d = Deck(f"bench: block pulled by a force ramped at {rate:g} N/s until it slips, static analysis")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.funct(2, [0.0, T], [0.0, 1.0], title="pull ramp f(t) = t / T")
    d.funct(3, [0.0, T], [0.0, 0.0], title="zero: the block's height held")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0 (fixed)")
    d.grnod(1, [1], title="block")
    d.bcs(1, 1, "010 111", title="block held in y, no rotation")
    d.impvel(1, 3, "Z", 1, title="height imposed at the static penetration")
    d.grav_fct(1, "X", rate * T / M, 2, grnod=1)  # the pull: m a f(t) = rate t [N]
    d.type6(1, 1, 2, 1, fric=p["mu"], stiff=p["kt"], visc=2.0 * 0.5 * math.sqrt(K * M),
            title="contact, Coulomb mu 0.4, stick spring K_t = 1e6 N/m")
    d.run(T, T / 10.0)
    d.solver(method=3)
    return d


def slip_forces_err(ts, F, rate, p=SLIP):
    """max |F(t) - (-rate t)| / (m g) over the records (F the friction force on the block)."""
    ts, F = np.asarray(ts), np.asarray(F)
    return float(np.abs(F + rate * ts).max() / (p["m"] * G)) if len(ts) else float("nan")


def read_tf(path):
    ts, fs = [], []
    with open(path) as fh:
        for ln in fh:
            a, b = ln.split()
            ts.append(float(a))
            fs.append(float(b))
    return ts, fs


def bench_slip_static(B):
    p = dict(SLIP)
    res = {"params": p, "rows": []}
    print(f"== Case 3c: the drag to the slip, static analysis: a block (m = {p['m']} kg) pressed on a floor (F_n = m g), "
          f"TYPE6 stick spring K_t = {p['kt']:.0e} N/m, Coulomb mu = {p['mu']}, pulled by a force ramped at RATE N/s "
          f"until it slips at t* = mu m g / RATE; accuracy target {p['target']:g} m g on the forces ==\n")
    for rate in p["rates"]:
        T = 5.0 / rate
        dto = T / 10.0
        ts_ = p["mu"] * p["m"] * G / rate
        row = {"rate": rate, "T": T, "t_slip": ts_}
        # ---- static analysis: CLI (netCDF, the error), rc_time (the solve), rc_time to the last record before t*
        name = f"slip_static_rate{rate:g}"
        case = os.path.join(B.work, name + ".rad")
        out = os.path.join(B.work, name + ".nc")
        slip_deck(rate, p).write(case)
        if os.path.exists(out):
            os.remove(out)
        rc, so, se, elapsed, _ = B.measured([B.ricochet, "run", case, "-o", out, "-q"], 300)
        st = {"rc": rc, "cli_elapsed": elapsed, "cli_cpu": B.last_cpu}
        with Dataset(out) as nc:
            t = np.array(nc["time"][:])
            ff = np.array(nc["inter_force_friction"][:])[:, 0, 0]
            fn = np.array(nc["inter_force_normal"][:])[:, 0]
            status = str(nc.getncattr("status"))
            st["newton"] = int(nc.getncattr("stats_nonlin_iters"))
            st["newton_fails"] = int(nc.getncattr("stats_nonlin_fails"))
        mt = re.search(r"no static equilibrium at the load time t = ([0-9.eE+-]+) s: the load exceeds what friction "
                       r"can hold.*the last equilibrium at t = ([0-9.eE+-]+) s", status)
        st["status"] = status[:160]
        st["limit_reported"] = bool(mt)
        if mt:
            st["t_fail"], st["t_last"] = float(mt.group(1)), float(mt.group(2))
            st["onset_err"] = max(abs(st["t_fail"] - ts_), abs(st["t_last"] - ts_)) / ts_
            st["bracket_ok"] = st["t_last"] <= ts_ * (1 + 1e-12) and st["t_fail"] >= ts_ * (1 - 1e-12)
        st["records"] = len(t)
        st["error"] = max(slip_forces_err(t, ff, rate, p), float(np.abs(fn - p["m"] * G).max() / (p["m"] * G)))
        rc2, so2, se2, _, _ = B.measured([B.rc_time, case, 3], 300)
        st["wall"] = B.timed(kv(so2))["wall_time"]
        t_eq = math.floor(ts_ / dto) * dto                  # the equilibria alone: up to the last record before t*
        rc3, so3, _, _, _ = B.measured([B.rc_time, case, 3, t_eq], 300)
        st["wall_equilibria"] = B.timed(kv(so3))["wall_time"] if rc3 == 0 else None
        row["static"] = st
        # ---- explicit central difference and plain CVODE, to the slip
        ex = []
        for f in (1.0, 0.5):
            fpath = os.path.join(B.work, f"slip_cd_rate{rate:g}_{f:g}.txt")
            x = B.explicit_run(["drag", p["m"], p["kt"], p["mu"], rate, T, dto, f, fpath], repeat=3)
            if not x.get("ok"):
                continue
            tt, FF = read_tf(fpath)
            ex.append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "wall": x["wall_time"],
                       "error": slip_forces_err(tt, FF, rate, p), "records": len(tt),
                       "slip_err": abs(x["t_slip"] - ts_) / ts_})
        cv = []
        for rtol in (1e-4, 1e-6, 1e-8):
            fpath = os.path.join(B.work, f"slip_cvode_rate{rate:g}_{rtol:.0e}.txt")
            x = B.cvode_run(["drag", p["m"], p["kt"], p["mu"], rate, T, dto, rtol, fpath], repeat=3)
            if not x.get("ok"):
                continue
            tt, FF = read_tf(fpath)
            cv.append({"rtol": rtol, "steps": x["steps"], "wall": x["wall_time"], "error": slip_forces_err(tt, FF, rate, p),
                       "records": len(tt), "slip_err": abs(x["t_slip"] - ts_) / ts_})
        row["explicit"], row["cvode"] = ex, cv
        okx = [x for x in ex if x["error"] <= p["target"]]
        okc = [x for x in cv if x["error"] <= p["target"]]
        row["explicit_best"] = min(okx, key=lambda x: x["wall"]) if okx else None
        row["cvode_best"] = min(okc, key=lambda x: x["wall"]) if okc else None
        for who in ("explicit", "cvode"):
            b = row[who + "_best"]
            row[who + "_ratio"] = b["wall"] / st["wall"] if b and st["wall"] else None
            row[who + "_ratio_equilibria"] = (b["wall"] / st["wall_equilibria"]
                                              if b and st.get("wall_equilibria") else None)
        res["rows"].append(row)
        table(f"rate {rate:g} N/s (T = {T:g} s, records every {dto:g} s, slip at t* = {ts_:.6g} s)",
              ["program", "setting", "time", "steps / Newton its", "records", "force err", "slip time err",
               "explicit/static", "cvode/static"],
              [["static", "Method 3", fmt_t(st["wall"]) + (f" (equilibria to {t_eq:g} s: {fmt_t(st['wall_equilibria'])})"
                                                          if st.get("wall_equilibria") else ""),
                f"{st['newton']} ({st['newton_fails']} failed solves)", st["records"], fmt_e(st["error"]),
                (f"{fmt_e(st['onset_err'])} (bracket [{st['t_last']:.9g}, {st['t_fail']:.9g}] s)"
                 if mt else "no limit reported: " + st["status"][:60]),
                (f"{row['explicit_ratio']:.3g} ({row['explicit_ratio_equilibria']:.3g})"
                 if row["explicit_ratio"] and row["explicit_ratio_equilibria"] else "-"),
                (f"{row['cvode_ratio']:.3g} ({row['cvode_ratio_equilibria']:.3g})"
                 if row["cvode_ratio"] and row["cvode_ratio_equilibria"] else "-")]]
              + [["explicit", f"dt_factor {x['dt_factor']:g} ({x['dt']:.3e} s)", fmt_t(x["wall"]), x["steps"],
                  x["records"], fmt_e(x["error"]), fmt_e(x["slip_err"]), "", ""] for x in ex]
              + [["cvode_ref", f"rtol {x['rtol']:.0e}", fmt_t(x["wall"]), x["steps"], x["records"], fmt_e(x["error"]),
                  fmt_e(x["slip_err"]), "", ""] for x in cv],
              note=f"force err = max over the records |F_t - (-RATE t)| / (m g) (and |F_n - m g| / (m g) for the static "
                   f"analysis); explicit/static, cvode/static: the cheapest run with force err <= {p['target']:g} over "
                   f"the static analysis to its error (> 1: the static analysis faster); in parentheses against the static "
                   f"analysis's equilibria alone (rc_time to the last record before t*, without the onset's bracketing)")
    return res


def bench_joint(B):
    """A pendulum held at 150 degrees: on a /JOINT/DISTANCE (IDA path) and on
    a stiff critically damped /COUPLING/SPRING of the same length (CVODE
    path), against the exact period 4 sqrt(L/g) K(sin 75 deg); default
    solver settings. The spring acts at the centre of mass, as the joint's
    point does: a point-mass pendulum of length L either way."""
    from scipy.special import ellipk
    m, L, g, th0, nper = 1.0, 1.0, 9.81, math.radians(150.0), 10
    T = 4.0 * math.sqrt(L / g) * ellipk(math.sin(th0 / 2) ** 2)
    x0 = (L * math.sin(th0), -L * math.cos(th0), 0.0)
    print("== pendulum at 150 degrees: exact joint (IDA) against a stiff spring (CVODE)")
    print(f"   exact period {T:.9f} s, {nper} periods, default tolerances")
    print(f"   {'model':40s} {'steps':>7s} {'wall [ms]':>10s} {'period error':>13s} {'max ||x| - L| [m]':>18s}")
    rows = []
    variants = [("joint", None)] + [("spring", k) for k in (1e4, 1e6, 1e8)]
    for kind, k in variants:
        d = Deck("pendulum " + (kind if k is None else f"spring k = {k:.0e} N/m"))
        d.nodes([(1,) + x0])
        d.rbody(1, 1, m, [1e-3, 1e-3, 1e-3], title="bob")
        d.grav(1, "Y", -g)
        if k is None:
            d.joint(1, "DISTANCE", 1, 0, x0, p2=(0.0, 0.0, 0.0), title="rod")
        else:
            d.spring(1, 0, (0.0, 0.0, 0.0), 1, x0, iform=1, x0=L, kd=2.0 * math.sqrt(k * m), a=k, title="stiff rod")
        d.run(nper * T, T / 200)
        name = "joint_pendulum" if k is None else f"spring_pendulum_{k:.0e}"
        case, out = os.path.join(B.work, name + ".rad"), os.path.join(B.work, name + ".nc")
        d.write(case)
        rc, so, se, _, _ = B.measured([B.ricochet, "run", case, "-o", out, "-q"], 600)
        if rc != 0:
            print(f"   {name}: failed ({se.strip()[-200:]})")
            rows.append({"model": name, "ok": False})
            continue
        with Dataset(out) as nc:
            t = np.array(nc["time"][:])
            x = np.array(nc["body_position"][:])[:, 0, :]
        c = []
        for i in range(1, len(t) - 2):
            if x[i, 0] > 0 >= x[i + 1, 0]:
                p = np.polyfit(t[i - 1:i + 3] - t[i], x[i - 1:i + 3, 0], 3)
                rr = [z.real for z in np.roots(p) if abs(z.imag) < 1e-12 and 0 <= z.real <= t[i + 1] - t[i]]
                c.append(t[i] + rr[0])
        per = np.diff(c)
        perr = float(np.max(np.abs(per - T)) / T)
        drift = float(np.max(np.abs(np.linalg.norm(x, axis=1) - L)))
        rc2, so2, _, _, _ = B.measured([B.rc_time, case, 3], 600)
        tm = kv(so2) if rc2 == 0 else {}
        label = "/JOINT/DISTANCE, IDA" if k is None else f"/COUPLING/SPRING k = {k:.0e} N/m, CVODE"
        print(f"   {label:40s} {int(tm.get('steps', 0)):7d} {1e3 * float(tm.get('wall_time', float('nan'))):10.2f} "
              f"{perr:13.2e} {drift:18.2e}")
        rows.append({"model": label, "ok": True, "steps": tm.get("steps"), "wall": tm.get("wall_time"),
                     "period_error": perr, "radial_drift": drift})
    print()
    return rows


def only_rtol_text(d, rtol, switch=False):
    """A deck's text with the /SOLVER card reduced to Rtol (absolute
    tolerances derived from the model, docs/theory.md 7.1); switch: with
    Switch 1 (method switching, docs/theory.md 7.9)."""
    t = d.text()
    i = t.index("/SOLVER")
    rest = t[i:].split("\n")
    return t[:i] + "\n".join([rest[0], "%10d%10d%10d%20.6g" % (1, 5, 10**7, rtol), "",
                               "%20s%10d" % ("", 1) if switch else ""] + rest[4:])


def bench_stepcost(B, old_build, repeat=3, cases=((100, 5.0), (1000, 0.02))):
    """Per-step cost against cvode_ref (target 1): the free column and the
    locked column (x, y and rotations held by /BCS: the 1-D ODE of
    cvode_ref), Rtol 1e-6 with derived absolute tolerances. rc_time of this
    build and, when old_build is given, of that build, interleaved, best of
    `repeat`; cvode_ref in the same rounds; the final-force error of each
    (CLI run, netCDF) against the event-located RK4 reference."""
    p = dict(COL)
    rtol = 1e-6
    builds = [("new", B.build)] + ([("old", os.path.abspath(old_build))] if old_build else [])
    res = {"rtol": rtol, "repeat": repeat, "builds": dict(builds), "cases": []}
    for N, tend in cases:
        q = dict(p)
        q["tend"], q["dtout"] = tend, tend / 10
        scale = N * q["m"] * G
        ff = os.path.join(B.work, f"step{N}_ref.txt")
        ref = B.explicit_run(["reference", N, q["R"], q["m"], q["k"], q["zeta"], -1, q["gap"], tend, 2e-5, "clip", ff])
        F = np.loadtxt(ff, ndmin=1)
        cases_out = {}
        decks = {}
        for var in ("free", "locked"):
            name = f"step{N}_{tend:g}_{var}"
            path = os.path.join(B.work, name + ".rad")
            with open(path, "w") as f:
                f.write(only_rtol_text(column_deck(N, rtol, q, locked=(var == "locked")), rtol))
            decks[var] = path
        walls = {(b, v): [] for b, _ in builds for v in decks}
        steps = {}
        cv = []
        for _ in range(repeat):
            for var, path in decks.items():
                for b, bdir in builds:
                    rc, so, se, _, _ = B.measured([os.path.join(bdir, "rc_time"), path, 1], 1200)
                    t = kv(so)
                    if rc == 0 and t.get("status") == "ok":
                        walls[(b, var)].append(t["wall_time"])
                        steps[(b, var)] = t["steps"]
            c = B.cvode_run(["column", N, q["R"], q["m"], q["k"], q["zeta"], q["gap"], tend, rtol,
                             os.path.join(B.work, f"step{N}_cvode.txt")])
            if c.get("ok"):
                cv.append(c)
        cbest = min(cv, key=lambda c: c["wall_time"])
        cF = np.loadtxt(os.path.join(B.work, f"step{N}_cvode.txt"), ndmin=1)
        c_err = float(np.max(np.abs(cF - F)) / scale)
        c_step = cbest["wall_time"] / cbest["steps"]
        rows = []
        for var, path in decks.items():
            for b, bdir in builds:
                ws = walls[(b, var)]
                if not ws:
                    rows.append([var, b, "FAILED"])
                    continue
                out = os.path.join(B.work, f"{os.path.basename(path)[:-4]}_{b}.nc")
                subprocess.run([os.path.join(bdir, "ricochet"), "run", path, "-o", out, "-q"], capture_output=True)
                err = float("nan")
                try:
                    with Dataset(out) as nc:
                        err = float(np.max(np.abs(np.array(nc["inter_force_normal"][-1, :]) - F)) / scale)
                    os.remove(out)
                except Exception:  # noqa: BLE001
                    pass
                best = min(ws)
                per = best / steps[(b, var)]
                cases_out[f"{var}_{b}"] = {"walls": ws, "steps": steps[(b, var)], "per_step": per,
                                           "ratio": per / c_step, "error": err}
                rows.append([var, b, ", ".join(f"{w:.3g}" for w in ws), steps[(b, var)], f"{1e3 * per:.4f}",
                             f"{per / c_step:.2f}", fmt_e(err)])
        rows.append(["cvode_ref", "", ", ".join(f"{c['wall_time']:.3g}" for c in cv), cbest["steps"],
                     f"{1e3 * c_step:.4f}", "1", fmt_e(c_err)])
        table(f"N = {N}, {tend:g} s, Rtol {rtol:g} (derived atol): per-step cost against cvode_ref (best of {repeat})",
              ["deck", "build", "wall [s]", "steps", "ms/step", "x cvode_ref", "final-force error"], rows,
              note=f"reference: event-located RK4 h = 2e-5 s ({ref.get('events')} events); error = max over contacts "
                   "|F - F_ref| / (N m g) at the end")
        res["cases"].append({"N": N, "tend": tend, "runs": cases_out, "cvode_ref": {
            "walls": [c["wall_time"] for c in cv], "steps": cbest["steps"], "per_step": c_step, "error": c_err}})
    return res


def bench_cascade(B, sizes, tend=5.0, rtol=1e-6, repeat=1, factors=(1, 0.1, 0.01), cli_from=None, switch=False,
                  variants=("locked", "free")):
    """Target 3, the impact cascade: the settling column (column_deck) over
    tend at Rtol rtol with derived absolute tolerances, locked (the 1-D ODE)
    and free, at each N of sizes. ricochet: the CLI run (netCDF: final-force
    error, statistics) and, when repeat > 0, rc_time (integration without
    output, best of repeat); the explicit scheme at each dt_factor; errors
    against the event-located RK4 (h = 2e-5 s). Sizes >= cli_from are timed
    by the CLI run alone (no rc_time run). Ends with the cost growth
    exponents between successive sizes. switch: the decks with /SOLVER
    Switch 1 (method switching); variants: the decks run."""
    q = dict(COL)
    q["tend"], q["dtout"] = tend, tend / 10
    res = {"rtol": rtol, "tend": tend, "sizes": {}}
    print(f"== Impact cascade: settling column over {tend:g} s, ricochet Rtol {rtol:g} (derived atol)"
          f"{', method switching on' if switch else ''} ==\n")
    for N in sizes:
        scale = N * q["m"] * G
        ff = os.path.join(B.work, f"casc{N}_{tend:g}_ref.txt")
        ref = B.explicit_run(["reference", N, q["R"], q["m"], q["k"], q["zeta"], -1, q["gap"], tend, 2e-5, "clip", ff])
        if not ref["ok"]:
            sys.exit(f"bench: RK4 reference failed: {ref}")
        F = np.loadtxt(ff, ndmin=1)
        S = {"N": N, "reference": {"events": ref["events"], "wall": ref["wall_time"]}, "ricochet": {}, "explicit": []}
        rows = []
        for var in variants:
            name = f"casc{N}_{tend:g}_{var}_rtol{rtol:.0e}" + ("_switch" if switch else "")
            path = os.path.join(B.work, name + ".rad")
            out = os.path.join(B.work, name + ".nc")
            with open(path, "w") as f:
                f.write(only_rtol_text(column_deck(N, rtol, q, locked=(var == "locked")), rtol, switch))
            rc, so, se, elapsed, rss = B.measured([B.ricochet, "run", path, "-o", out, "-q"], 7200)
            pcpu = B.last_cpu
            if rc != 0 or not os.path.exists(out):
                rows.append([var, "FAILED", se.strip()[-70:]])
                continue
            with Dataset(out) as nc:
                st = {k[len("stats_"):]: float(nc.getncattr(k)) for k in nc.ncattrs() if k.startswith("stats_")}
                t_last = float(nc["time"][-1])
                err = float(np.max(np.abs(np.array(nc["inter_force_normal"][-1, :]) - F)) / scale)
            os.remove(out)
            if abs(t_last - tend) > 1e-9:
                err = float("nan")
            walls = []
            for _ in range(repeat if cli_from is None or N < cli_from else 0):
                rc2, so2, _, _, _ = B.measured([B.rc_time, path, 1], 7200)
                t = B.timed(kv(so2))
                if rc2 == 0 and t.get("status") == "ok":
                    walls.append(t["wall_time"])
            wall = min(walls) if walls else (pcpu if B.clock == "cpu" and pcpu else st["wall_time"])
            S["ricochet"][var] = {"wall": wall, "walls": walls, "cli_wall": st["wall_time"], "process": elapsed,
                                  "process_cpu": pcpu, "stats": st, "error": err}
            rows.append([var, fmt_t(wall) + ("" if walls else " (CLI)"), fmt_t(st["wall_time"]),
                         fmt_t(pcpu if B.clock == "cpu" else elapsed),
                         int(st["steps"]), int(st.get("steps_explicit", 0)),
                         f"{int(st.get('switches_explicit', 0))}/{int(st.get('switches_implicit', 0))}",
                         int(st["events"]), int(st["reinits"]), f"{1e3 * wall / st['steps']:.4f}", fmt_e(err)])
        table(f"N = {N}, {tend:g} s: ricochet Rtol {rtol:g} (RK4 reference: {ref['events']} events)",
              ["deck", "time", "CLI wall", "process " + B.clock, "steps", "explicit steps", "switches", "events",
               "restarts", "ms/step", "final-force err"],
              rows, note=f"time ({B.clock}): rc_time, best of {repeat} ((CLI): the CLI process's CPU time with "
                         "--clock cpu, else its stats_wall_time); error = max over contacts |F - F_ref| / (N m g) "
                         "at the end")
        rows = []
        for f in factors:
            fx = os.path.join(B.work, f"casc{N}_{tend:g}_cd{f:g}.txt")
            x = B.explicit_run(["column", N, q["R"], q["m"], q["k"], q["zeta"], q["gap"], tend, f, fx], repeat=1)
            if not x["ok"]:
                rows.append([f"{f:g}", "FAILED"])
                continue
            err = float(np.max(np.abs(np.loadtxt(fx, ndmin=1) - F)) / scale)
            S["explicit"].append({"dt_factor": f, "dt": x["dt"], "steps": x["steps"], "wall": x["wall_time"],
                                  "error": err, "events": x["events"]})
            rows.append([f"{f:g}", f"{x['dt']:.3e}", fmt_t(x["wall_time"]), x["steps"], x["events"], fmt_e(err)])
        table(f"N = {N}, {tend:g} s: explicit central difference", ["dt_factor", "dt [s]", "wall", "steps", "events",
              "final-force err"], rows)
        res["sizes"][str(N)] = S
    rows = []
    for a, b in zip(sizes, sizes[1:]):
        Sa, Sb = res["sizes"][str(a)], res["sizes"][str(b)]
        for var in variants:
            if var in Sa["ricochet"] and var in Sb["ricochet"]:
                ra, rb = Sa["ricochet"][var], Sb["ricochet"][var]
                lr = math.log(b / a)
                rows.append([f"{a} -> {b}", var, f"{math.log(rb['wall'] / ra['wall']) / lr:.2f}",
                             f"{math.log(rb['stats']['steps'] / ra['stats']['steps']) / lr:.2f}"])
        ea = next((x for x in Sa["explicit"] if x["dt_factor"] == 1), None)
        eb = next((x for x in Sb["explicit"] if x["dt_factor"] == 1), None)
        if ea and eb:
            rows.append([f"{a} -> {b}", "explicit", f"{math.log(eb['wall'] / ea['wall']) / math.log(b / a):.2f}", "-"])
    table("Cost growth exponents d log(cost) / d log(N)", ["N", "program", "wall", "steps"], rows)
    return res


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true", help="fewer variants (smoke test)")
    ap.add_argument("--only",
                    choices=["drop", "column", "quasi", "ramp", "stickslip", "slipstatic", "joint", "stepcost",
                             "cascade"],
                    help="quasi = ramp + stickslip + slipstatic; stickslip includes slipstatic (case 3c: the drag to "
                         "the slip, solved statically); stepcost (not in the full run): the per-step cost of the free "
                         "and the locked column against cvode_ref; cascade (not in the full run): target 3, the "
                         "settling column locked and free at --sizes against the explicit scheme")
    ap.add_argument("--old-build", default=None,
                    help="stepcost: a second build directory (its rc_time and ricochet) run interleaved")
    ap.add_argument("--sizes", default="10,100,1000")
    ap.add_argument("--qsizes", default=None, help="column sizes of the ramp (default 100,1000; --quick: 100)")
    ap.add_argument("--ramps", default="20,100", help="ramp durations [s]")
    ap.add_argument("--ramp-shape", default="linear", choices=["linear", "smooth", "both"],
                    help="linear (the default) or smooth: 1 + (1 - cos(pi t/T))/2, no kink at either end")
    ap.add_argument("--ramp-atol", default="scaled", choices=["scaled", "derived"],
                    help="ramp decks: atol_pos = 1e-3 rtol m, atol_vel = rtol m/s (scaled, the default) or only Rtol "
                         "with the absolute tolerances derived from the model's scales (derived)")
    ap.add_argument("--ramp-max-order", type=int, default=5, help="ramp decks: /SOLVER Max_order (1-5)")
    ap.add_argument("--ramp-rtols", default=None,
                    help="ramp: ricochet rtols (dynamic runs), comma-separated (an empty string: none)")
    ap.add_argument("--ramp-cvode-rtols", default=None,
                    help="ramp: cvode_ref rtols, comma-separated (an empty string: none)")
    ap.add_argument("--ramp-dt-factors", default=None, help="ramp: explicit dt_factors, comma-separated")
    ap.add_argument("--ramp-static-dtouts", default="end,1",
                    help="ramp: output intervals of the static analysis runs (Method 3, locked column), "
                         "comma-separated seconds or 'end' (one equilibrium, at the end); an empty string: none")
    ap.add_argument("--ramp-repeat", type=int, default=1,
                    help="ramp: best of how many timed runs (explicit_ref, cvode_ref; rc_time at N <= 100); "
                         "the static runs: at least 3")
    ap.add_argument("--reuse-ref", action="store_true",
                    help="ramp: reuse the RK4 references of an earlier run with the same arguments (work directory)")
    ap.add_argument("--cascade-tend", type=float, default=5.0, help="cascade: end time [s]")
    ap.add_argument("--cascade-rtol", type=float, default=1e-6, help="cascade: ricochet Rtol (derived atol)")
    ap.add_argument("--cascade-dt-factors", default="1,0.1,0.01", help="cascade: explicit dt_factors")
    ap.add_argument("--cascade-cli-from", type=int, default=None,
                    help="cascade: sizes >= this are timed by their CLI run only (no rc_time run)")
    ap.add_argument("--repeat", type=int, default=1, help="cascade: rc_time runs per deck (best of; 0: CLI wall)")
    ap.add_argument("--cascade-switch", action="store_true",
                    help="cascade: the decks with /SOLVER Switch 1 (method switching, docs/theory.md 7.9)")
    ap.add_argument("--cascade-variants", default="locked,free", help="cascade: the decks run (locked, free)")
    ap.add_argument("--ss-atol", default="scaled", choices=["scaled", "derived"],
                    help="stick-slip decks: atol_pos = 1e-3 rtol m, atol_vel = 1e-2 rtol m/s (scaled, the default) "
                         "or only Rtol, the absolute tolerances derived from the model's scales (derived)")
    ap.add_argument("--ss-dt-factors", default=None, help="stick-slip: explicit dt_factors, comma-separated")
    ap.add_argument("--ss-rtols", default="1e-6,1e-8,1e-10", help="stick-slip: ricochet rtols, comma-separated")
    ap.add_argument("--clock", default="wall", choices=["wall", "cpu"],
                    help="times in the tables: wall (the default) or the CPU time of the same timed part (steadier "
                         "on a shared machine)")
    ap.add_argument("--work", default=None, help="directory of the decks and outputs (default BUILD/bench)")
    ap.add_argument("--json", default=None)
    a = ap.parse_args()

    def floats(text):
        return None if text is None else tuple(float(x) for x in text.split(",") if x)

    RAMP_OPTS.update(atol=a.ramp_atol, max_order=a.ramp_max_order, rtols=floats(a.ramp_rtols),
                     cvode_rtols=floats(a.ramp_cvode_rtols), dt_factors=floats(a.ramp_dt_factors),
                     static_dtouts=tuple(v if v == "end" else float(v)
                                         for v in (t.strip() for t in a.ramp_static_dtouts.split(",")) if v),
                     repeat=a.ramp_repeat,
                     reuse_ref=a.reuse_ref)
    SS_OPTS.update(atol=a.ss_atol, rtols=floats(a.ss_rtols), dt_factors=floats(a.ss_dt_factors))
    B = Bench(a.build, a.quick, a.work, a.clock)
    for exe in (B.ricochet, B.rc_time, B.explicit, B.peakrss, B.cvode):
        if not os.access(exe, os.X_OK):
            sys.exit(f"bench: {exe} missing (run `make bench`, or `make all` then `bash bench/run.sh build`)")
    lib = os.path.join(B.build, "libricochet.a")
    if os.path.exists(lib) and os.path.getmtime(B.rc_time) < os.path.getmtime(lib):
        sys.exit(f"bench: {B.rc_time} is older than {lib}: rebuild it (bash bench/run.sh {a.build})")
    m = B.results["machine"]
    print(f"machine: {m['cpu']}, {m['cores']} cores, Linux {m['kernel']}")
    print(f"ricochet: {B.ricochet}; times: {a.clock}\n")
    t0 = time.time()
    if a.only in (None, "drop"):
        B.results["drop"] = bench_drop(B)
    if a.only in (None, "column"):
        B.results["column"] = bench_column(B, [int(s) for s in a.sizes.split(",") if s])
    if a.only in (None, "quasi", "ramp"):
        qs = a.qsizes or ("100" if a.quick else "100,1000")
        for shape in (("linear", "smooth") if a.ramp_shape == "both" else (a.ramp_shape,)):
            B.results["ramp" if shape == "linear" else "ramp_smooth"] = bench_ramp(
                B, [int(s) for s in qs.split(",") if s], [float(s) for s in a.ramps.split(",") if s], shape)
    if a.only in (None, "quasi", "stickslip"):
        B.results["stickslip"] = bench_stickslip(B)
    if a.only in (None, "quasi", "stickslip", "slipstatic"):
        B.results["slipstatic"] = bench_slip_static(B)
    if a.only in (None, "joint"):
        B.results["joint"] = bench_joint(B)
    if a.only == "cascade":
        B.results["cascade"] = bench_cascade(B, [int(s) for s in a.sizes.split(",") if s], a.cascade_tend,
                                             a.cascade_rtol, a.repeat,
                                             tuple(float(x) for x in a.cascade_dt_factors.split(",") if x),
                                             a.cascade_cli_from, a.cascade_switch,
                                             tuple(v for v in a.cascade_variants.split(",") if v))
    if a.only == "stepcost":
        B.results["stepcost"] = bench_stepcost(B, a.old_build)
    B.results["bench_wall"] = time.time() - t0
    path = a.json or os.path.join(B.work, "results.json")
    with open(path, "w") as f:
        json.dump(B.results, f, indent=1, default=lambda o: o.item() if hasattr(o, "item") else str(o))
    print(f"total bench time {time.time() - t0:.1f} s; raw numbers in {path}")


if __name__ == "__main__":
    main()
