"""Distance sensors (/SENSOR/DIST) switching an interface on at a time found
in the run (README.md).

Ball A (m = 1 kg, R = 0.05 m) falls from rest under gravity, its centre
z0 = 1 m above the centre of the fixed ball B (R = 0.05 m); an
/INTER/POWER between A and B names a distance sensor (Isensor).

1. Dmax: sensor between A's node and a fixed node at A's start, Dmax =
   0.2 m, no delay: it triggers at t* = sqrt(2 Dmax / g), the interface
   starts then, and A meets B at sqrt(2 (z0 - R_A - R_B) / g) and rebounds.
2. Dmin and a delay: sensor between A's and B's nodes, Dmin = 0.5 m,
   Tdelay = 0.1 s: it triggers at sqrt(2 (z0 - Dmin) / g), the interface
   starts Tdelay later (before the meeting), same meeting.
3. Too late: as 1 with Tdelay = 0.3 s: on after A has passed through B's
   centre (no overlap then): no contact, free fall to the end.
4. AND: the sensor of 1 and a time sensor at 0.3 s, Tdelay 0.045 s: the
   interface on at 0.345 s (the later of the two, plus the delay).
5. OR: the sensor of 2 without delay and a time sensor at 0.4 s: on at
   the trigger, 0.319 s (the earlier).
6. Tmin: as 1 with Tmin = 0.05 s: the distance stays above Dmax, the
   trigger at t* + Tmin.
7. Tmin broken: the contact on by the sensor of 1; between A's and B's
   nodes, Dmin = 0.3 m, sensor 5 with Tmin = 0.05 s triggers at
   sqrt(2 (z0 - Dmin) / g) + Tmin (before the meeting), sensor 8 with
   Tmin = 0.2 s never does: A rebounds above Dmin after some 0.102 s.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, G = 1.0, 0.05, 9.81
J = 0.4 * M * R * R
Z0 = 1.0                          # A's start above B's centre [m]
DMAX, DMIN = 0.2, 0.5             # the sensors' bounds [m]
TMIN = 0.05                       # tmin.rad, tmin_break.rad (sensor 5) [s]
DMIN_B, TMIN_LONG = 0.3, 0.2      # tmin_break.rad: below Dmin for ~0.102 s [s]
TEND = 0.6


def two_balls(title):
    """Ball A above the fixed ball B, node 3 fixed at A's start; no sensor, contact or load yet."""
    d = Deck(title)
    d.nodes([(1, 0.0, 0.0, Z0), (2, 0.0, 0.0, 0.0), (3, 0.0, 0.0, Z0)])
    d.rbody(1, 1, M, [J] * 3, grnod=1, title="A")
    d.rbody(2, 2, M, [J] * 3, grnod=2, title="B")
    d.grnod(1, [1])
    d.grnod(2, [2])
    d.bcs(1, 2, title="B fixed")
    d.sphere(1, 1, (0.0, 0.0, Z0), R)
    d.sphere(2, 2, (0.0, 0.0, 0.0), R)
    return d


def falling(name, n2, dmin, dmax, tdelay, logic=None, tmin=None):
    d = two_balls(f"ball falling onto a fixed ball, contact on by a distance sensor ({name})")
    d.sensor_dist(5, 1, n2, dmin=dmin, dmax=dmax, tdelay=tdelay, tmin=tmin, title="distance sensor")
    isensor = 5
    if logic:  # (kind, time sensor's Tdelay, own Tdelay): sensor 7 = kind(5, 6)
        d.sensor_time(6, logic[1], title="time sensor")
        d.sensor_logic(logic[0], 7, 5, 6, tdelay=logic[2], title=f"{logic[0]} of 5 and 6")
        isensor = 7
    d.power(1, 1, 2, k=1e7, m1=1.5, isensor=isensor, title=f"A on B, Isensor {isensor}")
    d.grav(1, "Z", -G, grnod=1)
    d.run(TEND, 0.01)
    return d


def broken():
    """tmin_break.rad: the contact on by sensor 6 (Dmax, as dmax.rad); sensors 5 and 8 below Dmin_b
    between A and B, Tmin 0.05 s and 0.2 s."""
    d = two_balls("ball falling onto a fixed ball, distance sensors with a minimum duration (Tmin)")
    d.sensor_dist(6, 1, 3, dmax=DMAX, title="the contact's sensor")
    d.sensor_dist(5, 1, 2, dmin=DMIN_B, tmin=TMIN, title="below Dmin for Tmin")
    d.sensor_dist(8, 1, 2, dmin=DMIN_B, tmin=TMIN_LONG, title="below Dmin for longer than it is")
    d.power(1, 1, 2, k=1e7, m1=1.5, isensor=6, title="A on B, Isensor 6")
    d.grav(1, "Z", -G, grnod=1)
    d.run(TEND, 0.01)
    return d


def cases():
    return {"dmax.rad": falling("Dmax", 3, None, DMAX, None),
            "dmin_delay.rad": falling("Dmin, Tdelay", 2, DMIN, None, 0.1),
            "late.rad": falling("too late", 3, None, DMAX, 0.3),
            "and.rad": falling("AND of Dmax and a time", 3, None, DMAX, None, logic=("AND", 0.3, 0.045)),
            "or.rad": falling("OR of Dmin and a time", 2, DMIN, None, None, logic=("OR", 0.4, 0.0)),
            "tmin.rad": falling("Dmax held for Tmin", 3, None, DMAX, None, tmin=TMIN),
            "tmin_break.rad": broken()}


def main():
    tc_ref = math.sqrt(2 * (Z0 - 2 * R) / G)
    for name, t_trig, td in (("dmax", math.sqrt(2 * DMAX / G), 0.0), ("dmin_delay", math.sqrt(2 * (Z0 - DMIN) / G), 0.1),
                             ("late", math.sqrt(2 * DMAX / G), 0.3),
                             # AND: on 0.045 s after the later of the trigger and 0.3 s
                             ("and", math.sqrt(2 * DMAX / G), 0.3 + 0.045 - math.sqrt(2 * DMAX / G)),
                             # OR: on at the earlier of the trigger and 0.4 s
                             ("or", math.sqrt(2 * (Z0 - DMIN) / G), 0.0),
                             ("tmin", math.sqrt(2 * DMAX / G) + TMIN, 0.0)):
        r = rcval.Result(rcval.run(cases()[name + ".rad"], name))
        ts = r.events("sensor_trigger")
        e = rcval.rel(ts[0], t_trig) if len(ts) == 1 else 1.0
        rcval.check(f"sensor_dist.{name}.trigger", e < 1e-9,
                    f"sensor_trigger at {ts} s, closed form {t_trig:.12f} s: rel. error {e:.2e} (< 1e-9)")
        t_on = r.events("inter_start")
        e = rcval.rel(t_on[0], t_trig + td) if len(t_on) == 1 else 1.0
        rcval.check(f"sensor_dist.{name}.inter_start", e < 1e-9,
                    f"inter_start at {t_on} s, trigger + Tdelay {t_trig + td:.12f} s: rel. error {e:.2e} (< 1e-9)")
        tc = r.events("contact_close")
        if name != "late":
            e = rcval.rel(tc[0], tc_ref) if len(tc) else 1.0
            fall = r.t < (tc[0] if len(tc) else 0.0)
            ez = np.abs(r.pos[fall, 0, 2] - (Z0 - 0.5 * G * r.t[fall] ** 2)).max()
            rcval.check(f"sensor_dist.{name}.contact", e < 1e-9 and ez < 1e-9 and r.vel[-1, 0, 2] > 0,
                        f"contact at {tc[0] if len(tc) else None} s, sqrt(2 (z0 - R_A - R_B)/g) = {tc_ref:.12f} s, "
                        f"rel. error {e:.2e} (< 1e-9); free fall before it to {ez:.1e} m (< 1e-9); "
                        f"A rebounds: v_z = {r.vel[-1, 0, 2]:.6f} m/s")
        else:
            ez = np.abs(r.pos[:, 0, 2] - (Z0 - 0.5 * G * r.t ** 2)).max()
            rcval.check(f"sensor_dist.{name}.no_contact", len(tc) == 0 and ez < 1e-9,
                        f"on at {t_trig + td:.6f} s, after A passed B's centre (at {math.sqrt(2 * Z0 / G):.6f} s): "
                        f"no contact, free fall to the end within {ez:.1e} m (< 1e-9)")
    # Tmin broken: sensor 5 triggers Tmin after the fall below Dmin_b, sensor 8 never (A back above
    # Dmin_b before its Tmin: the distance at the end)
    r = rcval.Result(rcval.run(cases()["tmin_break.rad"], "tmin_break"))
    trig = {el: t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "sensor_trigger"}
    ntrig = len(r.events("sensor_trigger"))
    t1 = math.sqrt(2 * (Z0 - DMIN_B) / G)
    e6 = rcval.rel(trig.get("/SENSOR/DIST/6", 0.0), math.sqrt(2 * DMAX / G))
    e5 = rcval.rel(trig.get("/SENSOR/DIST/5", 0.0), t1 + TMIN)
    back = r.pos[-1, 0, 2] > DMIN_B and r.vel[-1, 0, 2] > 0
    rcval.check("sensor_dist.tmin_break.triggers", ntrig == 2 and e6 < 1e-9 and e5 < 1e-9 and back,
                f"sensor_trigger {trig} ({ntrig}, 2 expected): /SENSOR/DIST/6 at sqrt(2 Dmax/g), rel. error {e6:.2e}; "
                f"/SENSOR/DIST/5 at sqrt(2 (z0 - Dmin)/g) + Tmin = {t1 + TMIN:.12f} s, rel. error {e5:.2e} (< 1e-9 "
                f"each); /SENSOR/DIST/8 (Tmin {TMIN_LONG} s) none: A back above Dmin = {DMIN_B} m at the end "
                f"(z = {r.pos[-1, 0, 2]:.4f} m, rising)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cases)
