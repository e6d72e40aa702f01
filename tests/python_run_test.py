"""Python runs simulations (python/ricochet: _lib, sim, study): the ctypes
structs against the C compiler's layout, run() against closed forms, set=,
errors with the CLI's messages, sessions against run(), the event callback,
threads, pip install, and a study on a LocalCluster of 2 worker processes.
Prints PASS/FAIL lines (counted by scripts/check.sh).

    RICOCHET_LIB=build/libricochet.so PYTHONPATH=python /usr/bin/python3 tests/python_run_test.py build
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import math
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import warnings

import numpy as np

if os.environ.get("RICOCHET_TEST_WATCHDOG") and __name__ == "__main__":  # a hang dumps the stacks and ends the test
    import faulthandler
    faulthandler.dump_traceback_later(float(os.environ["RICOCHET_TEST_WATCHDOG"]), exit=True)

import ricochet

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUILD = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build"))
BIN = os.path.join(BUILD, "ricochet")
G = 9.81
failed = 0


def check(name, ok, detail=""):
    global failed
    print(("PASS " if ok else "FAIL ") + "pyrun." + name + (": " + detail if detail else ""))
    failed += not ok


def guarded(name, fn):
    """Run one test; an unexpected exception is a FAIL naming it."""
    try:
        fn()
    except Exception as e:  # noqa: BLE001
        import traceback
        traceback.print_exc()
        check(name, False, f"raised {type(e).__name__}: {e}")


# A 1 kg sphere (R = 0.05 m, centre 0.15 m) 0.1 m above a plane z = ZM
# (normal +z: M1 at z = 10), linear contact k = 1e6 N/m with the damping of
# restitution 0.8 (e_target); gravity -9.81 m/s^2; 0.4 s, output every 1 ms.
DECK = """#RADIOSS STARTER
/BEGIN
drop: 1 kg sphere R = 0.05 m, 0.1 m above a plane, restitution asked 0.8
      2022         0
                  kg                   m                   s
                  kg                   m                   s
/FUNCT/1
linear load curve, k = 1e6 N/m
                   0                   0
                   1             1000000
/NODE
         1                   0                   0                0.15
/RBODY/1
sphere
         1                                                 1
               0.001               0.001               0.001
                   0                   0                   0
/SURF/ELLIPS/1
sphere
         0         2         1
                   0                   0                0.15
                0.05                0.05                0.05
/SURF/PLANE/2
floor: M on the plane, M1 above it (the normal +z)
                   0                   0                   0
                   0                   0                  10
/GRNOD/NODE/1
sphere node
         1
/GRAV/1
gravity
         0         Z         0         0         1                             1               -9.81
/INTER/TYPE6/1
sphere on floor
         1         2
                                                           0
                   0         0         0         0         0
         1         0                                                 0
         0
                   0         0         0                                     0.8
/RUN
                 0.4               0.001
/END
"""
H0 = 0.1  # drop height [m]: sphere bottom 0.1 m, floor at 0

tmp = deck = None  # set by main()


def t_first(h):
    return math.sqrt(2 * h / G)


# ---- the structs: sizes and offsets as the C compiler lays them out ------
def test_abi():
    from ricochet import _lib
    fields = {"rc_error": (_lib.RcError, "code msg src_file src_line src_func"),
              "rc_impact": (_lib.RcImpact, " ".join(f for f, _ in _lib.RcImpact._fields_)),
              "rc_contact": (_lib.RcContact, " ".join(f for f, _ in _lib.RcContact._fields_)),
              "rc_stats": (_lib.RcStats, " ".join(f for f, _ in _lib.RcStats._fields_)),
              "rc_run_options": (_lib.RcRunOptions, " ".join(f for f, _ in _lib.RcRunOptions._fields_))}
    src = ["#include <stddef.h>", "#include <stdio.h>", '#include "ricochet/ricochet.h"', "int main(void) {"]
    for t, (_cls, names) in fields.items():
        src.append(f'printf("{t} %zu\\n", sizeof({t}));')
        for n in names.split():
            src.append(f'printf("{t}.{n} %zu\\n", offsetof({t}, {n}));')
    src.append('printf("RC_STATS_IMPACTS %d\\n", RC_STATS_IMPACTS); return 0; }')
    c = os.path.join(tmp, "abi.c")
    with open(c, "w") as f:
        f.write("\n".join(src))
    exe = os.path.join(tmp, "abi")
    p = subprocess.run(["cc", "-std=c11", "-I", os.path.join(ROOT, "include"), c, "-o", exe], capture_output=True, text=True)
    if p.returncode:
        check("abi_layout", False, "cc: " + p.stderr[:300])
        return
    want = dict(line.rsplit(" ", 1) for line in subprocess.run([exe], capture_output=True, text=True).stdout.split("\n") if line)
    import ctypes
    bad = []
    for t, (cls, names) in fields.items():
        if int(want[t]) != ctypes.sizeof(cls):
            bad.append(f"sizeof {t} {ctypes.sizeof(cls)} != {want[t]}")
        for n in names.split():
            if int(want[f"{t}.{n}"]) != getattr(cls, n).offset:
                bad.append(f"{t}.{n} at {getattr(cls, n).offset} != {want[t + '.' + n]}")
    if int(want["RC_STATS_IMPACTS"]) != _lib.RC_STATS_IMPACTS:
        bad.append("RC_STATS_IMPACTS")
    check("abi_layout", not bad, "; ".join(bad) or f"rc_error {want['rc_error']} B, rc_stats {want['rc_stats']} B, "
          f"rc_run_options {want['rc_run_options']} B: every field at the compiler's offset")


# ---- run: closed forms ---------------------------------------------------
def test_run_drop():
    # the run's temporary folder goes to a folder of this test's own (the
    # system's may hold what other programs, or a run killed earlier, left)
    own, saved = tempfile.mkdtemp(prefix="tmpdir-", dir=tmp), tempfile.tempdir
    tempfile.tempdir = own
    try:
        ds = ricochet.run(deck)
    finally:
        tempfile.tempdir = saved
    t1 = float(ds.impact_close_time.values[0])
    vin = float(ds.impact_speed_in.values[0])
    check("run_first_contact", type(ds).__name__ == "Dataset" and abs(t1 - t_first(H0)) < 1e-6
          and abs(vin - math.sqrt(2 * G * H0)) < 1e-6 * math.sqrt(2 * G * H0),
          f"t = {t1:.12f} s vs sqrt(2h/g) = {t_first(H0):.12f} s (diff {abs(t1 - t_first(H0)):.2e} s); "
          f"v_in {vin:.9f} vs sqrt(2gh) {math.sqrt(2 * G * H0):.9f} m/s")
    # the rebound: the sphere leaves the floor (contact_separate, P = 0) at
    # v_out and flies 2 v_out / g until it touches again (P = 0): exact
    seps = ds.event_time.values[ds.event_kind.values == "contact_separate"]
    vout, t2 = float(ds.impact_speed_out.values[0]), float(ds.impact_close_time.values[1])
    e = float(ds.impact_restitution.values[0])
    check("run_rebound_flight", abs(t2 - (seps[0] + 2 * vout / G)) < 1e-6 and 0.79 < e < 0.81,
          f"second contact {t2:.9f} s vs separation + 2 v_out/g = {seps[0] + 2 * vout / G:.9f} s "
          f"(diff {abs(t2 - (seps[0] + 2 * vout / G)):.1e} s); restitution {e:.5f} (0.8 asked of the contact law; "
          f"gravity acts during the contact)")
    left = os.listdir(own)
    check("run_dataset_in_memory", ds.attrs["complete"] == "yes" and ds.body_position.variable._in_memory
          and "overrides" not in ds.attrs and not left,
          f"complete, in memory, its temporary file removed (left: {left}); no overrides attribute without set=")


def test_persistent():
    # the floor raised to the sphere's bottom (0.1 m): touching at rest from
    # t = 0, no impact; one persistent contact carrying the weight over the
    # run: its mean force is the floor's impulse over the run, m g + m v_z(T) / T
    # (m = 1 kg), to 1e-6
    ds = ricochet.run(deck, set={"/SURF/PLANE/2:ZM": 0.1})
    n_imp, n_per = ds.sizes.get("impact", 0), ds.sizes.get("persistent", 0)
    T = float(ds.time.values[-1])
    vz = float(ds.body_velocity.isel(time=-1).sel(body=1).values[2])
    mean = float(ds.persistent_mean_force.values[0]) if n_per else float("nan")
    want = G + vz / T
    check("persistent_table_dataset", n_imp == 0 and n_per == 1 and int(ds.persistent_inter.values[0]) == 1
          and float(ds.persistent_close_time.values[0]) == 0.0 and math.isnan(float(ds.persistent_open_time.values[0]))
          and abs(float(ds.persistent_duration.values[0]) - T) < 1e-12 and abs(mean / want - 1) < 1e-6
          and abs(mean / G - 1) < 1e-6 and ds.persistent_mean_force.attrs["units"] == "N"
          and ds.persistent_slip_distance.attrs["units"] == "m",
          f"{n_imp} impacts, {n_per} persistent; mean force {mean:.9f} N vs m g + m v_z/T = {want:.9f} N "
          f"(rel. diff {abs(mean / want - 1):.1e})")
    # the same in the statistics of a session (RunStats: contacts, contact)
    with ricochet.Session(deck, set={"/SURF/PLANE/2:ZM": 0.1}) as s:
        s.run_until(T)
        st = s.close()
    c = st["contact"][0] if st["contact"] else {}
    check("persistent_table_stats", st["contacts"] == 1 and st["impacts"] == 0 and c.get("fn_mean") == mean
          and c.get("inter_id") == 1 and math.isnan(c.get("t_open", 0.0)),
          f"contacts {st['contacts']}, first {c}")


def test_set():
    h = 0.3  # floor moved down 0.2 m
    ds = ricochet.run(deck, set={"/SURF/PLANE/2:ZM": -0.2})
    t1 = float(ds.impact_close_time.values[0])
    check("set_dict_changes_answer", abs(t1 - t_first(h)) < 1e-6 and ds.attrs.get("overrides") == "/SURF/PLANE/2:ZM=-0.2",
          f"ZM = -0.2: first contact {t1:.9f} s vs sqrt(2 * 0.3 / g) = {t_first(h):.9f} s; attrs overrides = "
          f"{ds.attrs.get('overrides')!r}")
    # a list of strings is the same; a float is written with repr(), the
    # text that reads back as the same double: the run is the one of a deck
    # with that text typed into the field, bit for bit
    z = -0.123456789012345678  # repr: -0.12345678901234568
    ds2 = ricochet.run(deck, set=["/SURF/PLANE/2:ZM=" + repr(z)], t_end=0.2)
    ds3 = ricochet.run(deck, set={"/SURF/PLANE/2:ZM": np.float64(z)}, t_end=0.2)
    typed = os.path.join(tmp, "typed.rad")
    with open(typed, "w") as f:
        f.write(DECK.replace("(the normal +z)\n                   0                   0                   0\n",
                             "(the normal +z)\n                   0                   0%20s\n" % repr(z)))
    ds4 = ricochet.run(typed, t_end=0.2)
    same = all(np.array_equal(a[v].values, ds4[v].values) for a in (ds2, ds3)
               for v in ("body_position", "body_velocity", "surface_point", "event_time"))
    check("set_list_and_repr", same and ds3.attrs["overrides"] == f"/SURF/PLANE/2:ZM={z!r}" and "overrides" not in ds4.attrs,
          f"list and dict (numpy float) = the deck with {z!r} typed in, bit for bit; overrides {ds3.attrs['overrides']!r}")
    # another card: the gravity's magnitude
    ds4 = ricochet.run(deck, set={"/GRAV/1:Fscale_y": -4.905})
    t4 = float(ds4.impact_close_time.values[0])
    check("set_other_card", abs(t4 - math.sqrt(2 * H0 / 4.905)) < 1e-6,
          f"g = 4.905 m/s^2: first contact {t4:.9f} s vs {math.sqrt(2 * H0 / 4.905):.9f} s")


def test_run_options():
    ds = ricochet.run(deck, t_end=0.05, dt_out=0.01)
    check("t_end_dt_out", abs(float(ds.time.values[-1]) - 0.05) < 1e-15 and ds.sizes["time"] == 6
          and ds.sizes.get("impact", 0) == 0, f"records {ds.time.values.tolist()}")
    out = os.path.join(tmp, "kept.nc")
    ds = ricochet.run(deck, out=out, t_end=0.05, rtol=1e-6, method="ida")
    kept = ricochet.read(out)
    check("out_kept_rtol_method", os.path.exists(out) and kept.attrs["rtol"] == 1e-6 and
          kept.attrs["solver"].startswith("IDA") and np.array_equal(kept.body_position.values, ds.body_position.values),
          f"{out} kept; rtol {kept.attrs['rtol']}, solver {kept.attrs['solver'][:20]}...")
    bad = []
    for kw, frag in ((dict(t_end=0), "t_end: expected a positive"), (dict(dt_out=-1.0), "dt_out"),
                     (dict(rtol=2.0), "relative tolerance"), (dict(method="rk4"), "method: expected"),
                     (dict(on_violation="ignore"), "on_violation"), (dict(out=deck), "drop.rad")):
        try:
            ricochet.run(deck, **kw)
            bad.append(f"{kw}: no error")
        except ricochet.InputError as e:
            if frag not in str(e) or e.exit_code != 2:
                bad.append(f"{kw}: {e}")
    check("option_errors", not bad, "; ".join(bad) or "t_end 0, dt_out < 0, rtol 2, method rk4, on_violation, "
          "out = the deck: InputError (exit code 2) naming the option")


# ---- errors: the CLI's messages -----------------------------------------
def test_input_errors():
    bad = os.path.join(tmp, "bad.rad")
    with open(bad, "w") as f:
        f.write(DECK.replace("         1                                                 1\n",
                             "         1                                                -1\n"))
    try:
        ricochet.run(bad)
        check("input_error_file_line", False, "no exception")
    except ricochet.InputError as e:
        p = subprocess.run([BIN, "run", bad, "-o", os.path.join(tmp, "bad.nc"), "-q"], capture_output=True, text=True)
        cli = p.stderr.strip()
        ok = (isinstance(e, ricochet.RicochetError) and e.status == ricochet.Status.EINPUT and e.exit_code == 2
              and p.returncode == 2 and f"{bad}:15:" in str(e) and "Mass" in str(e) and cli == f"ricochet: input error: {e}"
              and e.dataset is None)
        check("input_error_file_line", ok, f"InputError: {str(e)[:120]} (the CLI: exit {p.returncode}, same message: "
              f"{cli == 'ricochet: input error: ' + str(e)})")
    try:
        ricochet.run(deck, set={"/INTER/TYPE6/1:Fricc": 0.3})
        check("input_error_set", False, "no exception")
    except ricochet.InputError as e:
        check("input_error_set", str(e).startswith("--set /INTER/TYPE6/1:Fricc=0.3:"), str(e)[:140])
    try:
        ricochet.run(os.path.join(tmp, "nope.rad"))
        check("io_error_missing_deck", False, "no exception")
    except ricochet.RicochetError as e:
        check("io_error_missing_deck", isinstance(e, ricochet.RicochetIOError) and e.exit_code == 4 and "nope.rad" in str(e),
              f"{type(e).__name__} (exit code {e.exit_code}): {str(e)[:100]}")
    try:
        ricochet.run(deck, set={"/RUN:Tend": True})
        check("set_bool_refused", False, "no exception")
    except TypeError as e:
        check("set_bool_refused", "bool" in str(e), str(e))


# ---- the event callback --------------------------------------------------
def test_events():
    ev = []
    ds = ricochet.run(deck, on_event=lambda t, kind, el, v: ev.append((t, kind, el, v)))
    kinds = [str(k) for k in ds.event_kind.values]
    closes = [e for e in ev if e[1] == "contact_close"]
    ok = (len(ev) == len(kinds) and [e[1] for e in ev] == kinds
          and np.array_equal([e[0] for e in ev], ds.event_time.values)
          and all(e[2] == "/INTER/TYPE6/1" for e in ev) and len(closes) == ds.sizes["impact"]
          and closes[0][0] == float(ds.impact_close_time.values[0])
          and abs(closes[0][3].approach_speed - math.sqrt(2 * G * H0)) < 1e-6)
    check("on_event_receives_events", ok, f"{len(ev)} events = the events table ({', '.join(sorted(set(kinds)))}); "
          f"first contact_close at {closes[0][0]:.9f} s, approach speed {closes[0][3].approach_speed:.9f} m/s")
    # a true return stops the run: InterruptedRun with the partial results
    try:
        ricochet.run(deck, on_event=lambda t, kind, el, v: kind == "contact_separate")
        check("on_event_stop", False, "no exception")
    except ricochet.InterruptedRun as e:
        ds = e.dataset
        check("on_event_stop", e.exit_code == 130 and ds is not None and ds.attrs["complete"] == "no"
              and "stopped by the event callback" in str(e) and float(ds.time.values[-1]) < 0.2,
              f"{str(e)[:90]}; partial results to t = {float(ds.time.values[-1]):.6f} s")
    # an exception stops the run and propagates, the file marked incomplete
    out = os.path.join(tmp, "raised.nc")
    calls = []

    def boom(t, kind, el, v):
        calls.append(kind)
        if kind == "contact_open":
            raise ValueError("boom at contact_open")
    try:
        ricochet.run(deck, out=out, on_event=boom)
        check("on_event_exception", False, "no exception")
    except ValueError as e:
        r = ricochet.read(out)
        check("on_event_exception", str(e) == "boom at contact_open" and calls == ["contact_close", "contact_open"]
              and r.attrs["complete"] == "no" and len(r.event_kind) == 2,
              f"ValueError propagated after {len(calls)} calls; file complete = {r.attrs['complete']}, "
              f"{len(r.event_kind)} event rows")


# ---- sessions -------------------------------------------------------------
def test_session():
    ds = ricochet.run(deck)
    with ricochet.Session(deck) as s:
        b0 = s.body(1)
        t = 0.0
        while not s.finished:
            t = round(t + 0.05, 10)
            s.run_until(t)
        b = s.body(1)
        y = s.state
        st = s.close()
    last = ds.isel(time=-1).sel(body=1)
    same = (np.array_equal(b.position, last.body_position.values) and np.array_equal(b.velocity, last.body_velocity.values)
            and np.array_equal(b.quaternion, last.body_quaternion.values)
            and np.array_equal(b.angular_velocity, last.body_angular_velocity.values))
    check("session_pieces_equal_run", same and st["status"] == 0 and st["impacts"] == ds.sizes["impact"],
          f"8 pieces of 0.05 s: final z {b.position[2]:.15g} m, v_z {b.velocity[2]:.15g} m/s bit for bit as run()'s "
          f"last record; {st['impacts']} impacts")
    check("session_initial_and_state", np.array_equal(b0.position, [0, 0, 0.15]) and np.array_equal(b0.quaternion, [1, 0, 0, 0])
          and y.shape == (15,) and np.array_equal(y[0:3], b.position), f"state vector of {y.size} values; body 1 at its offset 0")
    # free fall to 0.1 s, then closed early: InterruptedRun's status in the stats, no exception
    out = os.path.join(tmp, "sess.nc")
    s = ricochet.Session(deck, out=out)
    s.run_until(0.1)
    b = s.body(1)
    st = s.close()
    r = ricochet.read(out)
    check("session_free_fall_close_early", abs(b.position[2] - (0.15 - 0.5 * G * 0.01)) < 1e-9
          and abs(b.velocity[2] + G * 0.1) < 1e-9 and st["status"] == ricochet.Status.EINTERRUPT
          and "stopped by the caller" in st["message"] and r.attrs["complete"] == "no" and s.close() is st,
          f"z(0.1) = {b.position[2]:.12f} m (0.15 - g t^2/2 = {0.15 - 0.5 * G * 0.01:.12f}); close: {st['message'][:60]}")
    bad = []
    try:
        s.run_until(0.2)
        bad.append("run_until after close")
    except ricochet.RicochetError as e:
        if "closed" not in str(e):
            bad.append(str(e))
    with ricochet.Session(deck) as s2:
        try:
            s2.body(7)
            bad.append("body 7")
        except ricochet.InputError as e:
            if "no /RBODY/7" not in str(e):
                bad.append(str(e))
    check("session_errors", not bad, "; ".join(bad) or "closed session refused; unknown body id: InputError naming it")


def test_session_callbacks():
    # an exception in the callback stops the session's run and is raised by run_until
    s = ricochet.Session(deck, on_event=lambda t, k, e, v: 1 / 0 if k == "contact_close" else None)
    try:
        s.run_until(1.0)
        check("session_callback_exception", False, "no exception")
    except ZeroDivisionError:
        st = s.close()
        check("session_callback_exception", s.finished and st["status"] == ricochet.Status.EINTERRUPT
              and abs(st["t_end"] - t_first(H0)) < 1e-6, f"ZeroDivisionError raised by run_until; run stopped at "
              f"{st['t_end']:.9f} s")
    # stepping the session from its own callback: refused by the library (InputError), raised by run_until
    holder = {}

    def reenter(t, k, e, v):
        holder["s"].run_until(0.3)
    s = ricochet.Session(deck, on_event=reenter)
    holder["s"] = s
    try:
        s.run_until(1.0)
        check("session_reentry_refused", False, "no exception")
    except ricochet.InputError as e:
        s.close()
        check("session_reentry_refused", "callback" in str(e), str(e)[:120])
    # a second thread while one runs: RuntimeError, not a deadlock
    inside, go = threading.Event(), threading.Event()

    def wait(t, k, e, v):
        if k == "contact_close" and not inside.is_set():
            inside.set()
            go.wait(10)
    s = ricochet.Session(deck, on_event=wait)
    th = threading.Thread(target=s.run_until, args=(0.2,))
    th.start()
    inside.wait(10)
    try:
        s.run_until(0.3)
        msg = "no error"
    except RuntimeError as e:
        msg = str(e)
    go.set()
    th.join(10)
    s.close()
    check("session_one_thread_at_a_time", "another thread" in msg and not th.is_alive(), msg)


# ---- threads ---------------------------------------------------------------
def test_threads():
    zs = [0.0, -0.05, -0.1, -0.2]
    serial = [float(ricochet.run(deck, set={"/SURF/PLANE/2:ZM": z}).impact_close_time.values[0]) for z in zs]
    par = [None] * len(zs)

    def one(i):
        par[i] = float(ricochet.run(deck, set={"/SURF/PLANE/2:ZM": zs[i]}).impact_close_time.values[0])
    ths = [threading.Thread(target=one, args=(i,)) for i in range(len(zs))]
    for th in ths:
        th.start()
    for th in ths:
        th.join()
    check("threads", par == serial and all(abs(t - t_first(H0 - z)) < 1e-6 for t, z in zip(par, zs)),
          f"4 runs in 4 threads = serial runs: {', '.join(f'{t:.6f}' for t in par)} s")


# ---- the library lookup ------------------------------------------------------
def test_lookup():
    env = dict(os.environ, RICOCHET_LIB=os.path.join(tmp, "missing.so"))
    code = ("import ricochet\nr = ricochet.read(%r)\ntry:\n    ricochet.run(%r)\nexcept ricochet.RicochetError as e:\n"
            "    print('ERR', e)\n" % (os.path.join(tmp, "kept.nc"), deck))
    p = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    check("lookup_missing_library", p.returncode == 0 and "ERR RICOCHET_LIB=" in p.stdout and "no such file" in p.stdout,
          f"import and read work; run: {p.stdout.strip()[:110]}{p.stderr[-200:]}")
    where = ricochet.library_path()
    check("lookup_env", os.environ.get("RICOCHET_LIB", "") in where, where)


# ---- pip install, offline ---------------------------------------------------
def test_pip():
    venv = os.path.join(tmp, "venv")
    src = os.path.join(tmp, "pysrc")
    shutil.copytree(os.path.join(ROOT, "python"), src, ignore=shutil.ignore_patterns("build", "*.egg-info", "__pycache__"))
    p = subprocess.run(["/usr/bin/python3", "-m", "venv", "--system-site-packages", venv], capture_output=True, text=True)
    if p.returncode:
        print(f"SKIP pyrun.pip_install: python3 -m venv failed (python3-venv missing?): {p.stderr[-200:]}")
        return
    p = subprocess.run([os.path.join(venv, "bin", "pip"), "install", "-q", "--no-build-isolation", "--no-index", src],
                       capture_output=True, text=True)
    code = "import ricochet; ds = ricochet.run(%r); print(ricochet.__file__, float(ds.impact_close_time[0]))" % deck
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}  # the venv's module, not the source tree's
    q = subprocess.run([os.path.join(venv, "bin", "python"), "-c", code], capture_output=True, text=True, cwd=tmp, env=env)
    out = q.stdout.split()
    check("pip_install_offline", p.returncode == 0 and q.returncode == 0 and out[0].startswith(venv)
          and abs(float(out[1]) - t_first(H0)) < 1e-6,
          f"pip install --no-build-isolation --no-index into a venv: {' '.join(out)[-90:]}{p.stderr[-200:]}{q.stderr[-200:]}")


# ---- a study on Dask distributed --------------------------------------------
def test_study():
    try:
        import distributed  # noqa: F401
    except ImportError:
        print("SKIP pyrun.study: python3-distributed not installed (scripts/install-deps.sh test installs it)")
        return
    zs = [0.0, -0.1, -0.25, -0.5]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st = ricochet.study(deck, {"/SURF/PLANE/2:ZM": zs}, workers=2, outputs=["body_position", "energy_total"],
                            times=np.linspace(0.0, 0.4, 41), t_end=0.4)
    t1 = st.impact_close_time.values[:, 0]
    want = [t_first(H0 - z) for z in zs]
    err = max(abs(a - b) for a, b in zip(t1, want))
    e0 = st.energy_total.values[:, 0]
    check("study_drop_heights", list(st.SURF_PLANE_2_ZM.values) == zs and (st.status.values == 0).all()
          and err < 1e-6 and st.SURF_PLANE_2_ZM.attrs["field"] == "/SURF/PLANE/2:ZM",
          f"LocalCluster, 2 worker processes: first contacts {', '.join(f'{t:.6f}' for t in t1)} s vs sqrt(2h/g), "
          f"max diff {err:.1e} s")
    z10 = st.body_position.sel(vec3="z", body=1).values[:, 10]  # t = 0.1 s: still falling in every case
    check("study_series_and_finals", np.allclose(z10, 0.15 - 0.5 * G * 0.01, atol=1e-9, rtol=0)
          and st.final_body_position.dims == ("case", "body", "vec3") and np.all(np.isfinite(e0))
          and np.all(st.final_time.values == 0.4) and st.impact_count.values[0] >= 2
          and "persistent_count" in st and st.persistent_mean_force.dims == ("case", "persistent")
          and st.persistent_mean_force.attrs["units"] == "N",
          f"z(0.1 s) = {z10[0]:.9f} m in every case; final_time 0.4 s; energy_total(0) = {e0[0]:.6f} J; "
          f"impacts {st.impact_count.values.tolist()}; persistent contacts "
          f"{st.persistent_count.values.tolist() if 'persistent_count' in st else 'none'}")
    # a failing case does not kill the study; a list of dicts; lhs
    cases = [{"/SURF/PLANE/2:ZM": -0.1}, {"/SURF/PLANE/2:ZM": 0.2}]  # 0.2: the floor through the sphere
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        st2 = ricochet.study(deck, cases, workers=2, t_end=0.3)
    check("study_failing_case", st2.status.values.tolist() == [0, 2] and st2.exit_code.values[1] == 2
          and "drop.rad" in str(st2.message.values[1]) and abs(st2.impact_close_time.values[0, 0] - t_first(0.2)) < 1e-6
          and np.isnan(st2.final_time.values[1]) and st2.attrs["failed_cases"] == 1,
          f"case 1: status 2, {str(st2.message.values[1])[:100]}")
    pts = ricochet.lhs({"/SURF/PLANE/2:ZM": (-0.5, 0.0), "/GRAV/1:Fscale_y": (-12.0, -8.0)}, 8, seed=3)
    strata = sorted(int((p["/SURF/PLANE/2:ZM"] + 0.5) / 0.5 * 8) for p in pts)
    check("lhs_strata", strata == list(range(8)) and pts == ricochet.lhs({"/SURF/PLANE/2:ZM": (-0.5, 0.0),
                                                                         "/GRAV/1:Fscale_y": (-12.0, -8.0)}, 8, seed=3),
          "8 cases, one per stratum of each range, reproducible from the seed")
    # the command line
    grid = os.path.join(tmp, "grid.json")
    with open(grid, "w") as f:
        f.write('{"/SURF/PLANE/2:ZM": [0.0, -0.3]}')
    out = os.path.join(tmp, "study.nc")
    p = subprocess.run([sys.executable, "-m", "ricochet", "study", deck, "--grid", grid, "--workers", "2", "-o", out,
                        "--t-end", "0.3"], capture_output=True, text=True)
    ok = p.returncode == 0 and os.path.exists(out)
    if ok:
        import xarray as xr
        with xr.open_dataset(out) as s:
            t = s.impact_close_time.values[:, 0]
        ok = abs(t[0] - t_first(0.1)) < 1e-6 and abs(t[1] - t_first(0.4)) < 1e-6
    check("study_cli", ok, f"python3 -m ricochet study: exit {p.returncode}, {p.stdout.strip()}{p.stderr[-300:]}")


def main():
    global tmp, deck
    tmp = tempfile.mkdtemp(prefix="rc-pyrun-test-")
    deck = os.path.join(tmp, "drop.rad")
    with open(deck, "w") as f:
        f.write(DECK)
    for name, fn in [("abi", test_abi), ("run", test_run_drop), ("persistent", test_persistent),
                     ("set", test_set), ("options", test_run_options),
                     ("errors", test_input_errors), ("events", test_events), ("session", test_session),
                     ("session_callbacks", test_session_callbacks), ("threads", test_threads), ("lookup", test_lookup),
                     ("pip", test_pip), ("study", test_study)]:
        guarded(name, fn)
    shutil.rmtree(tmp, ignore_errors=True)
    return 1 if failed else 0


# the study's worker processes import this file again (multiprocessing's
# spawn): only the main process runs the tests
if __name__ == "__main__":
    sys.exit(main())
