"""A body released by a sensor found in the run (README.md).

Ball A (m = 1 kg) falls from rest under gravity from z0 = 1 m. A distance
sensor between A's node and a fixed node at A's start (Dmax = 0.2 m)
triggers at t* = sqrt(2 Dmax / g). Ball B (m = 2 kg, 1 m aside, also at
z0) names a sensor in its /RBODY sens_ID: it is held at rest in its
initial pose until that sensor is on, then falls freely from rest:
z_B(t) = z0 - g (t - t_rel)^2 / 2.

1. dist: B's sensor is the distance sensor, Tdelay 0.1 s: t_rel = t* + 0.1.
2. dist0: the distance sensor without delay: t_rel = t* (the release in the
   trigger's own event).
3. and: AND of the distance sensor (no delay) and a time sensor at 0.3 s,
   Tdelay 0.05 s: t_rel = max(t*, 0.3) + 0.05 = 0.35 s.
4. or: OR of the distance sensor (no delay) and a time sensor at 0.4 s:
   t_rel = min(t*, 0.4) = t*.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

MA, MB, R, G = 1.0, 2.0, 0.05, 9.81
Z0, DMAX, TEND = 1.0, 0.2, 0.6
TSTAR = math.sqrt(2 * DMAX / G)   # the distance sensor's trigger [s]


def released(name, tdelay, logic=None):
    d = Deck(f"ball B released by a sensor found in the run ({name})")
    d.nodes([(1, 0.0, 0.0, Z0), (2, 1.0, 0.0, Z0), (3, 0.0, 0.0, Z0)])
    sens = 5
    if logic:  # (kind, time sensor's Tdelay, own Tdelay): sensor 7 = kind(5, 6)
        sens = 7
    d.rbody(1, 1, MA, [0.4 * MA * R * R] * 3, grnod=1, title="A")
    d.rbody(2, 2, MB, [0.4 * MB * R * R] * 3, grnod=2, title=f"B, released by sensor {sens}", sens=sens)
    d.grnod(1, [1])
    d.grnod(2, [2])
    d.sensor_dist(5, 1, 3, dmax=DMAX, tdelay=tdelay, title="A's fall of Dmax")
    if logic:
        d.sensor_time(6, logic[1], title="time sensor")
        d.sensor_logic(logic[0], 7, 5, 6, tdelay=logic[2], title=f"{logic[0]} of 5 and 6")
    d.grav(1, "Z", -G)
    d.run(TEND, 0.01)
    return d


def cases():
    return {"dist.rad": released("DIST, Tdelay 0.1 s", 0.1),
            "dist0.rad": released("DIST, no delay", None),
            "and.rad": released("AND of DIST and a time", None, logic=("AND", 0.3, 0.05)),
            "or.rad": released("OR of DIST and a time", None, logic=("OR", 0.4, 0.0))}


def main():
    for name, t_rel in (("dist", TSTAR + 0.1), ("dist0", TSTAR), ("and", max(TSTAR, 0.3) + 0.05),
                        ("or", min(TSTAR, 0.4))):
        r = rcval.Result(rcval.run(cases()[name + ".rad"], name))
        ts = r.events("sensor_trigger")
        e = rcval.rel(ts[0], TSTAR) if len(ts) == 1 else 1.0
        rcval.check(f"sensor_release.{name}.trigger", e < 1e-9,
                    f"sensor_trigger at {ts} s, sqrt(2 Dmax/g) = {TSTAR:.12f} s: rel. error {e:.2e} (< 1e-9)")
        rel = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "impvel_stop" and el == "/RBODY/2"]
        e = rcval.rel(rel[0], t_rel) if len(rel) == 1 else 1.0
        rcval.check(f"sensor_release.{name}.release", e < 1e-9,
                    f"B's hold ends (impvel_stop /RBODY/2) at {rel} s, closed form {t_rel:.12f} s: rel. error "
                    f"{e:.2e} (< 1e-9)")
        tr = rel[0] if rel else t_rel
        held = r.t <= tr
        drift = max(np.abs(r.pos[held, 1] - [1.0, 0.0, Z0]).max(), np.abs(r.vel[held, 1]).max())
        rcval.check(f"sensor_release.{name}.held", drift < 1e-12,
                    f"until the release ({held.sum()} records): B's max |x - x0|, |v| = {drift:.1e} (< 1e-12)")
        free = r.t > tr
        ez = np.abs(r.pos[free, 1, 2] - (Z0 - 0.5 * G * (r.t[free] - t_rel) ** 2)).max()
        za = np.abs(r.pos[:, 0, 2] - (Z0 - 0.5 * G * r.t ** 2)).max()
        zend = Z0 - 0.5 * G * (TEND - t_rel) ** 2
        ee = abs(r.pos[-1, 1, 2] - zend)
        rcval.check(f"sensor_release.{name}.fall", ez < 1e-9 and ee < 1e-9 and za < 1e-9,
                    f"after the release ({free.sum()} records) max |z_B - (z0 - g (t - t_rel)^2/2)| = {ez:.1e} m; "
                    f"at {TEND} s z_B = {r.pos[-1, 1, 2]:.12f} m, closed form {zend:.12f} m, error {ee:.1e} m; "
                    f"A's free fall to {za:.1e} m (all < 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cases)
