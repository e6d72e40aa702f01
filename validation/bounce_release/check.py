"""A settled contact is released when the load that holds it turns.

A sphere (m = 1 kg, R = 0.05 m) falls from rest with its lowest point h =
0.02 m above a fixed plane onto a /INTER/TYPE6 contact (linear load curve F
= k P, k = 1e10 N/m, restitution e = 0.7 asked) and settles (event
contact_settle, docs/theory.md 5.2). Gravity follows a time function: g f(t)
with f = 1 up to T1 = 1 s, falling linearly to f = -1 at T2 = 1.5 s (then
constant). The ball rests until the load turns; the normal force it needs
is m g f(t), which reaches zero at

    t_r = (T1 + T2) / 2 = 1.25 s   (f(t_r) = 0),

after which gravity pulls it off the plane.

Checks (default solver settings; the deck has no /SOLVER card):
- IDA path (--method ida): the settled contact is a unilateral constraint,
  its multiplier the normal force: m g f(t) at the records between the
  settling and t_r (1e-6 m g), the penetration frozen at its settling value
  (drift < 1e-12 m), and the release (contact_open) at t_r within 1e-6 s;
- CVODE (the deck's method and the defaults mode): the penalty law is held
  closed (no release at zero force); the contact ends when P returns to 0
  (contact_separate) within 3 pi/omega_n of t_r, and while it rests the
  normal force is m g f(t) to 1e-6 m g (the penalty spring follows the slow
  load);
- both: settled (IDA once; CVODE up to three times within 1 ms, the held
  penalty law opening at P = 0 while the last bounces die out), the run complete, the energy ledger constant
  (1e-6 m g h).
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, G, H, E, K = 1.0, 0.05, 9.81, 0.02, 0.7, 1e10
T1, T2, T_END, DT_OUT = 1.0, 1.5, 1.4, 1e-2
T_R = 0.5 * (T1 + T2)


def f(t):
    return np.interp(t, [0.0, T1, T2, 10.0], [1.0, 1.0, -1.0, -1.0])


def deck():
    d = Deck(f"ball settled on a penalty contact, released when gravity turns at t_r = {T_R} s")
    d.funct(1, [0.0, 1.0], [0.0, K], title=f"linear load curve k = {K:g} N/m")
    d.funct(2, [0.0, T1, T2, 10.0], [1.0, 1.0, -1.0, -1.0], title="gravity factor: 1, turning to -1")
    z0 = R + H
    add_sphere_over_plane(d, M, R, z0, title="ball")
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, e_target=E, title="floor, restitution asked")
    d.run(T_END, DT_OUT)
    return d


def main():
    ida = rcval.METHOD == "ida"
    path = rcval.run_case()
    r = rcval.Result(path)
    with Dataset(path) as nc:
        status = nc.getncattr("status")
    rcval.check("bounce_release.run_complete", status == "complete" and abs(r.t[-1] - T_END) < 1e-12,
                f"status '{status}', last record at {r.t[-1]:.6g} s (t_end {T_END} s)")
    ts = r.events("contact_settle")
    # IDA: one settling (the contact held until released); CVODE: the held
    # penalty law may still open at P = 0 while the last bounces die out,
    # and settle again
    nmax = 1 if ida else 3
    ok = 1 <= len(ts) <= nmax and ts[-1] < T1 and all(ts - ts[0] < 1e-3)
    rcval.check("bounce_release.settling", ok,
                f"contact_settle at {', '.join(f'{x:.9f}' for x in ts) or 'none'} s (1 to {nmax}, within 1 ms, "
                f"before T1 = {T1} s)")
    if not ok:
        rcval.finish()
    ts = ts[-1:]
    # the hold: records after the settling (not at events) up to t_r
    sel = (r.t > ts[0]) & (r.t < T_R) & (r.at_event == 0)
    fn, need = r.fn[sel, 0], M * G * f(r.t[sel])
    ferr = np.max(np.abs(fn - need)) / (M * G)
    # the multiplier to 1e-6; the held penalty law F = k P no better than k
    # times the position tolerance's floor (64 roundings of the body's
    # coordinates, |z| + R = 0.1 m: 1.4e-15 m, 1.45e-6 m g here): two of those
    pfloor = 64 * np.finfo(float).eps * (R + R)
    tol = 1e-6 if ida else max(1e-6, 2 * K * pfloor / (M * G))
    rcval.check("bounce_release.hold_force", sel.sum() > 10 and ferr < tol,
                f"{sel.sum()} records in the hold: max |F_n - m g f(t)| = {ferr:.2e} m g (< {tol:.3g}"
                f"{'; the multiplier' if ida else '; the held penalty law, 2 k x the position floor'})")
    pen = r.pen[sel, 0]
    wn = math.sqrt(K / M)
    if ida:
        drift = np.max(np.abs(pen - pen[0]))
        rcval.check("bounce_release.frozen_penetration", drift < 1e-12,
                    f"penetration {pen[0]:.3e} m at the first record of the hold, drift {drift:.1e} m (< 1e-12 m)")
        ends = r.events("contact_open")
        after = ends[ends > ts[0]]
        dt = after[0] - T_R if len(after) else float("inf")
        rcval.check("bounce_release.release_time", abs(dt) < 1e-6,
                    f"release (contact_open) at {after[0] if len(after) else float('nan'):.9f} s; "
                    f"t_r = (T1 + T2) / 2 = {T_R:.9f} s; diff {dt:+.1e} s (< 1e-6 s)")
    else:
        ends = r.events("contact_separate", "contact_open")
        after = ends[ends > ts[0]]
        dt = after[0] - T_R if len(after) else float("inf")
        tc = math.pi / wn
        rcval.check("bounce_release.release_time", abs(dt) < 3 * tc,
                    f"held penalty law: the contact ends at {after[0] if len(after) else float('nan'):.9f} s "
                    f"({', '.join(k for t, k in zip(r.ev_t, r.ev_kind) if len(after) and t == after[0])}); "
                    f"t_r = {T_R:.9f} s; diff {dt:+.2e} s (< 3 pi/omega_n = {3 * tc:.1e} s)")
    et = r.energy["energy_total"]
    drift = np.max(np.abs(et - et[0])) / (M * G * H)
    rcval.check("bounce_release.energy_ledger", drift < 1e-6,
                f"max |E_total(t) - E_total(0)| = {drift:.2e} m g h (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
