"""Time sensors (/SENSOR/TIME) switching a body and interfaces on
(README.md).

1. A ball of /RBODY sens_ID = 1 (Tdelay T_s = 0.25 s) is held at rest in
   its initial pose until T_s, then falls freely: z(t) = z0 for t <= T_s,
   z0 - g (t - T_s)^2 / 2 after, first impact on the floor at
   T_s + sqrt(2 h / g); the floor's TYPE6 names sensor 2 (Isensor,
   T_i = 0.1 s): its inter_start event at T_i exactly.
2. Two spheres, no gravity: A at speed v0 towards the fixed B, an
   /INTER/POWER between them named by a sensor. Turned on at 0.5 s (before
   they meet): contact at (d0 - R_A - R_B) / v0. Turned on at 3 s (after A
   has passed through B): no contact, A's velocity unchanged, the
   inter_start event at 3 s.
3. A floor on while a time sensor is off (/SENSOR/NOT of a time sensor at
   T_n = 0.3 s): the ball rests on it from the start (centre at
   R - m g / k), the floor stops at T_n exactly (inter_stop) and the ball
   falls freely from rest: z0 - g (t - T_n)^2 / 2.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, R, G, K = 1.0, 0.05, 9.81, 1.0e6
J = 0.4 * M * R * R
TS, TI, H = 0.25, 0.1, 0.1       # body sensor, interface sensor, fall height [s] [s] [m]
V0, D0, RB = 1.0, 1.0, 0.05      # the pass: A's speed, initial distance of the centres, B's radius


def held_ball():
    d = Deck("ball held until its sensor's time")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    d.nodes([(1, 0.0, 0.0, R + H)])
    d.add("/RBODY/1", line(("i", 1), ("i", 1), ("i", None), ("i", None), ("r", M)),
          line(("r", J), ("r", J), ("r", J)), line(("r", 0.0), ("r", 0.0), ("r", 0.0)), title="ball, sens_ID 1")
    d.sensor_time(1, TS, title="release of the ball")
    d.sensor_time(2, TI, title="the floor's contact on")
    d.sphere(1, 1, (0.0, 0.0, R + H), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.type6(1, 1, 2, 1, e_target=0.5, isensor=2, title="ball on floor, Isensor 2")
    d.grav(1, "Z", -G)
    d.run(0.6, 0.001)
    return d


def pass_by(t_on):
    d = Deck("sphere passing a fixed sphere, contact on at %g s" % t_on)
    d.nodes([(1, -D0, 0.0, 0.0), (2, 0.0, 0.0, 0.0)])
    d.rbody(1, 1, M, [J] * 3, grnod=1, title="A")
    d.rbody(2, 2, M, [J] * 3, grnod=2, title="B")
    d.grnod(1, [1])
    d.grnod(2, [2])
    d.add("/BCS/1", f"{'111 111':>10s}{0:>10d}{2:>10d}", title="B fixed")
    d.sphere(1, 1, (-D0, 0.0, 0.0), R)
    d.sphere(2, 2, (0.0, 0.0, 0.0), RB)
    d.sensor_time(3, t_on, title="contact on")
    d.inivel(1, (V0, 0.0, 0.0), 1)
    d.power(1, 1, 2, k=1e7, m1=1.5, isensor=3, title="A on B, Isensor 3")
    d.run(4.0, 0.01)
    return d


TN = 0.3                         # the NOT sensor's input time [s]


def floor_not():
    z0 = R - M * G / K
    d = Deck("ball resting on a floor that a /SENSOR/NOT turns off")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, M, [J] * 3, title="ball")
    d.sensor_time(1, TN, title="time sensor")
    d.sensor_not(2, 1, title="on until sensor 1 is on")
    d.sphere(1, 1, (0.0, 0.0, z0), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.type6(1, 1, 2, 1, e_target=0.5, isensor=2, title="ball on floor, Isensor 2 (NOT)")
    d.grav(1, "Z", -G)
    d.run(0.5, 0.001)
    return d


def main():
    # 1. the held ball
    r = rcval.Result(rcval.run(held_ball(), "held"))
    t_rel = r.events("impvel_stop")
    t_on = r.events("inter_start")
    rcval.check("sensor_time.body_release", len(t_rel) == 1 and abs(t_rel[0] - TS) <= 1e-15,
                f"hold ends (impvel_stop) at {t_rel} s, Tdelay {TS} s: error {abs(t_rel[0] - TS) if len(t_rel) else 1:.1e} s (<= 1e-15)")
    rcval.check("sensor_time.interface_on", len(t_on) == 1 and abs(t_on[0] - TI) <= 1e-15,
                f"inter_start at {t_on} s, Tdelay {TI} s: error {abs(t_on[0] - TI) if len(t_on) else 1:.1e} s (<= 1e-15)")
    z0 = R + H
    before = r.t <= TS
    drift = max(np.abs(r.pos[before, 0] - [0.0, 0.0, z0]).max(), np.abs(r.vel[before, 0]).max())
    rcval.check("sensor_time.held", drift < 1e-12,
                f"until {TS} s ({before.sum()} records): max |x - x0|, |v| = {drift:.1e} (< 1e-12: the velocities "
                f"are imposed at zero, rounding only)")
    t1 = r.events("contact_close")[0]
    fall = (r.t > TS) & (r.t < t1)
    e = np.abs(r.pos[fall, 0, 2] - (z0 - 0.5 * G * (r.t[fall] - TS) ** 2)).max()
    rcval.check("sensor_time.free_fall", e < 1e-9,
                f"after the release, {fall.sum()} records: max |z - (z0 - g (t - T_s)^2/2)| = {e:.1e} m (< 1e-9)")
    t1_ref = TS + math.sqrt(2 * H / G)
    e = rcval.rel(t1, t1_ref)
    rcval.check("sensor_time.impact", e < 1e-9,
                f"first contact at {t1:.12f} s, T_s + sqrt(2 h/g) = {t1_ref:.12f} s, rel. error {e:.2e} (< 1e-9)")

    # 2. an interface on before the spheres meet, and after A has passed B
    r = rcval.Result(rcval.run(pass_by(0.5), "pass_early"))
    tc_ref = (D0 - R - RB) / V0
    tc = r.events("contact_close")
    e = rcval.rel(tc[0], tc_ref) if len(tc) else 1.0
    rcval.check("sensor_time.on_before", len(tc) >= 1 and e < 1e-9 and abs(r.events("inter_start")[0] - 0.5) <= 1e-15
                and r.vel[-1, 0, 0] < 0,
                f"Isensor at 0.5 s: inter_start {r.events('inter_start')} s, contact at {tc[0] if len(tc) else None} s "
                f"((d0 - R_A - R_B)/v0 = {tc_ref:.12f}), rel. error {e:.2e} (< 1e-9); A rebounds: v_x = {r.vel[-1, 0, 0]:.6f} m/s")
    r = rcval.Result(rcval.run(pass_by(3.0), "pass_late"))
    t_on = r.events("inter_start")
    dv = np.abs(r.vel[:, 0] - [V0, 0.0, 0.0]).max()
    rcval.check("sensor_time.off_before", len(r.events("contact_close")) == 0 and dv < 1e-12 and len(t_on) == 1
                and abs(t_on[0] - 3.0) <= 1e-15,
                f"Isensor at 3 s: A passes through B (no contact, its velocity within {dv:.1e} m/s of v0, < 1e-12); "
                f"inter_start at {t_on} s; at 3 s the centres are {r.pos[r.state_at(t_on[0]), 0, 0]:.6f} m apart")

    # 3. a floor turned off by a NOT sensor
    r = rcval.Result(rcval.run(floor_not(), "floor_not"))
    z0 = R - M * G / K
    t_off = r.events("inter_stop")
    before, after = r.t <= TN, r.t > TN
    drift = np.abs(r.pos[before, 0, 2] - z0).max()
    e = np.abs(r.pos[after, 0, 2] - (z0 - 0.5 * G * (r.t[after] - TN) ** 2)).max()
    rcval.check("sensor_time.not_floor", len(t_off) == 1 and abs(t_off[0] - TN) <= 1e-15 and drift < 1e-9 and e < 1e-9,
                f"/SENSOR/NOT of a time sensor at {TN} s: the floor stops (inter_stop) at {t_off} s (error <= 1e-15); "
                f"at rest before it within {drift:.1e} m of R - m g/k, free fall from rest after it to {e:.1e} m "
                f"(< 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, held_ball)
