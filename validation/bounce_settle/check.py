"""A ball bouncing on a penalty contact with restitution e < 1 settles into
persistent contact near the Zeno time of the rigid limit.

A sphere (m = 1 kg, R = 0.05 m) falls from rest with its lowest point h = 1 m
above a fixed plane, under gravity g = 9.81 m/s^2, onto a /INTER/TYPE6
contact with the linear load curve F = k P and the restitution e = 0.7
asked (e_target: ricochet derives the damping). The rigid limit (zero
contact time, restitution e at every impact) bounces infinitely often in
finite time:
    t_1 = sqrt(2 h / g),  v_1 = sqrt(2 g h),
    t_(j+1) = t_j + 2 v_1 e^j / g   (the flight after impact j takes off at e^j v_1),
    t_inf = t_1 + sum_(j>=1) 2 v_1 e^j / g = t_1 + 2 v_1 e / (g (1 - e)).
With a penalty contact the bounces end after finitely many: ricochet holds
the contact closed ("settled", event contact_settle, docs/theory.md 5.2)
once a flight is shorter than the contact phase before it, and reports that
time. As k grows the contact time pi / omega_d shrinks as k^(-1/2), and the
settling time must converge to t_inf with it.

Checks (default solver settings; the case.rad is the k = 1e10 N/m deck, the
other stiffnesses are run from the same deck with k changed):
- the run ends normally, resting on the floor: normal force m g, speed 0;
- one contact_settle, after which the contact stays closed; the statistics
  (stats_settles, stats_t_settle) agree with the event;
- the impact times (contact_close) against the rigid chain t_j;
- the settling time against t_inf, and its convergence as k grows: the error
  falls as k^(-1/2) (fitted order between 0.4 and 0.6 over 1e8..1e11 N/m);
- the energy ledger constant.
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

M, R, G, H, E = 1.0, 0.05, 9.81, 1.0, 0.7
K_MAIN = 1e10
K_STUDY = [1e6, 1e7, 1e8, 1e9, 1e10, 1e11]
T_END, DT_OUT = 3.0, 1e-2
NB = 8                 # impact times checked


def deck(k=K_MAIN):
    d = Deck(f"ball settling on a penalty contact, restitution {E} asked, k = {k:g} N/m")
    d.funct(1, [0.0, 1.0], [0.0, k], title=f"linear load curve k = {k:g} N/m")
    z0 = R + H
    add_sphere_over_plane(d, M, R, z0, title="ball")
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, e_target=E, title="floor, restitution asked")
    d.run(T_END, DT_OUT)
    return d


def rigid():
    t1, v1 = math.sqrt(2 * H / G), math.sqrt(2 * G * H)
    t = [t1]
    for j in range(1, NB):
        t.append(t[-1] + 2 * v1 * E ** j / G)
    return np.array(t), t1 + 2 * v1 * E / (G * (1 - E))


def contact_time(k):
    """pi / omega_d of the linear contact at the damping ratio that gives e
    (unclipped oscillator; only its scaling with k matters here)."""
    return math.pi / math.sqrt(k / M)


def settle_time(path):
    r = rcval.Result(path)
    ts = [t for t, kk in zip(r.ev_t, r.ev_kind) if kk == "contact_settle"]
    return r, ts


def main():
    tj, tinf = rigid()
    path = rcval.run_case()
    r, ts = settle_time(path)
    with Dataset(path) as nc:
        st_n, st_t = int(nc.getncattr("stats_settles")), float(nc.getncattr("stats_t_settle"))
        status = nc.getncattr("status")
    rcval.check("bounce_settle.run_complete", status == "complete" and abs(r.t[-1] - T_END) < 1e-12,
                f"status '{status}', last record at {r.t[-1]:.6g} s (t_end {T_END} s)")
    ok = len(ts) == 1
    rcval.check("bounce_settle.one_settling", ok and st_n == 1 and st_t == ts[0],
                f"{len(ts)} contact_settle event(s); stats_settles {st_n}, stats_t_settle {st_t:.9f} s")
    if not ok:
        rcval.finish()
    after = [kk for t, kk in zip(r.ev_t, r.ev_kind) if t > ts[0]]
    rcval.check("bounce_settle.stays_closed", len(after) == 0,
                f"events after the settling: {after if after else 'none'}")
    fn, vz = r.fn[-1, 0], r.vel[-1, 0, 2]
    rcval.check("bounce_settle.resting_force", rcval.rel(fn, M * G) < 1e-6 and abs(vz) < 1e-9,
                f"at t_end: normal force {fn:.9f} N (m g = {M * G:.9f} N, rel. error {rcval.rel(fn, M * G):.1e} "
                f"< 1e-6), speed {abs(vz):.1e} m/s (< 1e-9)")
    closes = r.events("contact_close")
    tc = contact_time(K_MAIN)
    ok = len(closes) >= NB
    dev = np.abs(closes[:NB] - tj) if ok else np.full(NB, np.inf)
    # the first impact ends a free fall (exact); impact j follows j - 1
    # contact phases, each shifting it by less than one contact time
    bound = np.array([1e-9] + [j * tc for j in range(1, NB)])
    rcval.check("bounce_settle.impact_times", ok and np.all(dev < bound),
                "first impacts " + ", ".join(f"{x:.6f}" for x in closes[:NB]) +
                " s; rigid chain t_(j+1) = t_j + 2 v1 e^j / g: |diff| " + ", ".join(f"{x:.1e}" for x in dev) +
                f" s (< 1e-9 s for the first, < (j - 1) pi/omega_n after, pi/omega_n = {tc:.2e} s)")
    err = ts[0] - tinf
    rcval.check("bounce_settle.settling_time", abs(err) < 3 * tc,
                f"settled at {ts[0]:.9f} s; rigid Zeno time t_1 + 2 v1 e / (g (1 - e)) = {tinf:.9f} s; diff "
                f"{err:+.2e} s ({abs(err) / tinf:.1e} rel.; < 3 pi/omega_n = {3 * tc:.2e} s)")
    # convergence with k
    errs, lines = [], []
    for k in K_STUDY:
        rk, tsk = settle_time(rcval.run(deck(k), name=f"k{k:g}"))
        nb = len(rk.events("contact_close"))
        e_k = (tsk[0] - tinf) if len(tsk) == 1 else float("nan")
        errs.append(e_k)
        lines.append(f"k {k:g}: {nb} impacts, settled {tsk[0] if tsk else float('nan'):.9f} s, diff {e_k:+.3e} s")
    ks = np.array(K_STUDY)
    sel = ks >= 1e8
    p = -np.polyfit(np.log10(ks[sel]), np.log10(np.abs(np.array(errs)[sel])), 1)[0]
    rcval.check("bounce_settle.convergence", np.all(np.isfinite(errs)) and 0.4 < p < 0.6,
                "; ".join(lines) + f"; |diff| ~ k^-p over 1e8..1e11 N/m: p = {p:.3f} (0.4 < p < 0.6; contact time ~ "
                f"k^-0.5)")
    e0 = M * G * H
    et = r.energy["energy_total"]
    drift = np.max(np.abs(et - et[0])) / e0
    rcval.check("bounce_settle.energy_ledger", drift < 1e-6,
                f"max |E_total(t) - E_total(0)| = {drift:.2e} m g h (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
