"""Interface sensors (/SENSOR/INTER) releasing a held body and turning an
interface on at a time found in the run (README.md).

Ball A (m = 1 kg, R = 0.05 m) falls from rest under gravity onto a fixed
floor, its centre z0 = 0.25 m above it; /INTER/TYPE6/1 (linear load curve
k = 1e5 N/m, no damping, no friction) is its contact. Sensor 5 is a
/SENSOR/INTER on interface 1. Body B (m = 2 kg, no surface, at (1, 0, 1))
names a sensor in its /RBODY sens_ID: held at rest until that sensor is
on, then free: z_B(t) = z_B0 - g (t - t_rel)^2 / 2.

The contact closes at t_c = sqrt(2 (z0 - R) / g). While closed, the
penetration p(tau) (tau = t - t_c) of the undamped linear contact is
p = A (1 - cos w tau) + B sin w tau, A = g / w^2, B = g t_c / w,
w = sqrt(k / m): the normal force k p reaches F at
tau_F = (asin((F / k - A) / R_p) + phi) / w, R_p = sqrt(A^2 + B^2),
phi = atan2(A, B).

1. first: DIR blank, no delay: trigger at t_c, B released at t_c; ball C
   (m = 1 kg, R = 0.05 m, at (2, 0, 0.6)) has its floor contact
   /INTER/TYPE6/2 turned on by sensor 5 (Isensor): inter_start at t_c, its
   contact at sqrt(2 (0.6 - R) / g).
2. delay: DIR blank, Tdelay 0.1 s: trigger at t_c, B released at t_c + 0.1.
3. fmax: DIR FN, Fmax = 400 N, no delay: trigger and release at t_c + tau_F.
4. and: B names /SENSOR/AND 7 of sensor 5 (DIR blank) and a /SENSOR/TIME
   at 0.1 s, Tdelay 0.02 s: released at max(t_c, 0.1) + 0.02.
5. tmin: as 3 with Tmin half the time T_w the force stays above Fmax:
   trigger and release at t_c + tau_F + T_w / 2.
6. tmin_long: as 3 with Tmin = 1.5 T_w: never triggers, B held to the end.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

MA, MB, R, G, K = 1.0, 2.0, 0.05, 9.81, 1e5
Z0, ZB0, ZC0, TEND = 0.25, 1.0, 0.6, 0.5
FMAX = 400.0
TC = math.sqrt(2 * (Z0 - R) / G)          # A's contact closes [s]
TCC = math.sqrt(2 * (ZC0 - R) / G)        # C's contact closes [s]
W = math.sqrt(K / MA)
AP, BP = G / W ** 2, G * TC / W
TF = TC + (math.asin((FMAX / K - AP) / math.hypot(AP, BP)) + math.atan2(AP, BP)) / W  # k p = Fmax [s]
TWIN = (math.pi - 2 * math.asin((FMAX / K - AP) / math.hypot(AP, BP))) / W  # k p above Fmax that long [s]
TMIN = 0.5 * TWIN                        # tmin.rad: within the window
TMIN_LONG = 1.5 * TWIN                   # tmin_long.rad: longer than the window, never triggers


def falling(name, direction=None, fmax=None, tdelay=None, logic=None, ball_c=False, tmin=None):
    d = Deck(f"ball on a floor, its contact releasing a held body ({name})")
    nodes = [(1, 0.0, 0.0, Z0), (2, 1.0, 0.0, ZB0)]
    if ball_c:
        nodes.append((3, 2.0, 0.0, ZC0))
    d.nodes(nodes)
    sens = 7 if logic else 5
    d.rbody(1, 1, MA, [0.4 * MA * R * R] * 3, grnod=1, title="A")
    d.rbody(2, 2, MB, [0.4 * MB * R * R] * 3, grnod=2, title=f"B, released by sensor {sens}", sens=sens)
    d.grnod(1, [1])
    d.grnod(2, [2])
    d.sphere(1, 1, (0.0, 0.0, Z0), R, title="A")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e5 N/m")
    d.type6(1, 1, 2, 1, title="A on the floor")
    if ball_c:
        d.rbody(3, 3, MA, [0.4 * MA * R * R] * 3, grnod=3, title="C")
        d.grnod(3, [3])
        d.sphere(3, 3, (2.0, 0.0, ZC0), R, title="C")
        d.type6(2, 3, 2, 1, isensor=5, title="C on the floor, on by sensor 5")
    d.sensor_inter(5, 1, direction=direction, fmax=fmax, tdelay=tdelay, tmin=tmin, title="A's contact")
    if logic:  # (kind, time sensor's Tdelay, own Tdelay): sensor 7 = kind(5, 6)
        d.sensor_time(6, logic[1], title="time sensor")
        d.sensor_logic(logic[0], 7, 5, 6, tdelay=logic[2], title=f"{logic[0]} of 5 and 6")
    d.grav(1, "Z", -G)
    # tight: rtol 1e-10, the absolute tolerances derived from the model's scales (blank)
    d.solver(rtol=1e-10, atol_pos=None, atol_quat=None, atol_vel=None, atol_omega=None, atol_energy=None)
    d.run(TEND, 0.01)
    return d


def cases():
    return {"first.rad": falling("first contact", ball_c=True),
            "delay.rad": falling("first contact, Tdelay 0.1 s", tdelay=0.1),
            "fmax.rad": falling("normal force above Fmax", direction="FN", fmax=FMAX),
            "and.rad": falling("AND of the first contact and a time", logic=("AND", 0.1, 0.02)),
            "tmin.rad": falling("normal force above Fmax for Tmin", direction="FN", fmax=FMAX, tmin=TMIN),
            "tmin_long.rad": falling("normal force above Fmax for longer than it is", direction="FN", fmax=FMAX,
                                     tmin=TMIN_LONG)}


def main():
    for name, t_trig, t_rel in (("first", TC, TC), ("delay", TC, TC + 0.1), ("fmax", TF, TF),
                                ("and", TC, max(TC, 0.1) + 0.02), ("tmin", TF + TMIN, TF + TMIN)):
        r = rcval.Result(rcval.run_case(name + ".rad"))
        tol = 1e-9
        ts = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "sensor_trigger" and el == "/SENSOR/INTER/5"]
        e = rcval.rel(ts[0], t_trig) if len(ts) == 1 and len(r.events("sensor_trigger")) == 1 else 1.0
        rcval.check(f"sensor_inter.{name}.trigger", e < tol,
                    f"sensor_trigger /SENSOR/INTER/5 at {ts} s, closed form {t_trig:.12f} s: rel. error {e:.2e} "
                    f"(< {tol:.0e})")
        tcl = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "contact_close" and el == "/INTER/TYPE6/1"]
        if name not in ("fmax", "tmin"):
            # the trigger is the contact's own closing event: the same time
            same = len(tcl) >= 1 and len(ts) == 1 and ts[0] == tcl[0]
            rcval.check(f"sensor_inter.{name}.onset", same,
                        f"first contact_close of /INTER/TYPE6/1 at {tcl[:1]} s, the trigger at {ts} s (equal)")
        rel = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "impvel_stop" and el == "/RBODY/2"]
        e = rcval.rel(rel[0], t_rel) if len(rel) == 1 else 1.0
        rcval.check(f"sensor_inter.{name}.release", e < tol,
                    f"B's hold ends (impvel_stop /RBODY/2) at {rel} s, closed form {t_rel:.12f} s: rel. error "
                    f"{e:.2e} (< {tol:.0e})")
        tr = rel[0] if rel else t_rel
        held = r.t <= tr
        drift = max(np.abs(r.pos[held, 1] - [1.0, 0.0, ZB0]).max(), np.abs(r.vel[held, 1]).max())
        rcval.check(f"sensor_inter.{name}.held", drift < 1e-12,
                    f"until the release ({held.sum()} records): B's max |x - x0|, |v| = {drift:.1e} (< 1e-12)")
        free = r.t > tr
        ez = np.abs(r.pos[free, 1, 2] - (ZB0 - 0.5 * G * (r.t[free] - t_rel) ** 2)).max()
        ev = np.abs(r.vel[free, 1, 2] + G * (r.t[free] - t_rel)).max()
        before = r.t <= TC
        za = np.abs(r.pos[before, 0, 2] - (Z0 - 0.5 * G * r.t[before] ** 2)).max()
        rcval.check(f"sensor_inter.{name}.fall", ez < tol and ev < 1e-8 and za < 1e-9,
                    f"after the release ({free.sum()} records) max |z_B - (z0 - g (t - t_rel)^2/2)| = {ez:.1e} m "
                    f"(< {tol:.0e}), |v_B + g (t - t_rel)| = {ev:.1e} m/s (< 1e-8); A's free fall to the "
                    f"contact {za:.1e} m (< 1e-9)")
        if name == "first":
            st = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "inter_start" and el == "/INTER/TYPE6/2"]
            e1 = rcval.rel(st[0], TC) if len(st) == 1 else 1.0
            cc = [t for t, k, el in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "contact_close" and el == "/INTER/TYPE6/2"]
            e2 = rcval.rel(cc[0], TCC) if cc else 1.0
            rcval.check(f"sensor_inter.{name}.activate", e1 < 1e-9 and e2 < 1e-9,
                        f"/INTER/TYPE6/2 (Isensor 5) starts at {st} s, t_c = {TC:.12f} s: rel. error {e1:.2e}; "
                        f"C's contact closes at {cc[:1]} s, sqrt(2 (z_C0 - R)/g) = {TCC:.12f} s: rel. error "
                        f"{e2:.2e} (both < 1e-9)")
    # the force above Fmax for less than Tmin: no trigger, B held to the end
    r = rcval.Result(rcval.run_case("tmin_long.rad"))
    fpk = float(r.fn[:, 0].max())
    n_trig, n_rel = len(r.events("sensor_trigger")), len(r.events("impvel_stop"))
    drift = max(np.abs(r.pos[:, 1] - [1.0, 0.0, ZB0]).max(), np.abs(r.vel[:, 1]).max())
    rcval.check("sensor_inter.tmin_long.never", n_trig == 0 and n_rel == 0 and drift < 1e-12 and fpk > FMAX,
                f"the force above Fmax = {FMAX:g} N (peak of the records {fpk:.4g} N) for {TWIN:.6e} s, Tmin "
                f"{TMIN_LONG:.6e} s: {n_trig} sensor_trigger, {n_rel} impvel_stop (0 each), B at rest to the end "
                f"(max |x - x0|, |v| = {drift:.1e}, < 1e-12)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, cases)
