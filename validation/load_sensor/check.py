"""Loads switched on by time sensors: /IMPVEL and /GRAV sensor_ID (README.md).

Two spheres (m = 1.3 kg, R = 0.05 m) start at rest at z0 = 1 m, far
apart, no contact. /GRAV (all bodies, g = 9.81 m/s^2 downwards) names
/SENSOR/AND/3 of /SENSOR/TIME/1 (0.1 s) and /SENSOR/TIME/2 (0.15 s) with
Tdelay 0.05 s: gravity from T_g = 0.2 s on. Sphere 1 carries an /IMPVEL
on X naming /SENSOR/TIME/4 (T_v = 0.25 s), Fscale_y V = 0.5 m/s, f(s) =
s / S for s < S = 0.1 s, then 1: imposed from T_v as V f(t - T_v) (the
function shifted by the sensor's time, as Radioss does).

  z(t) = z0                                  t <= T_g   (both spheres)
  z(t) = z0 - g (t - T_g)^2 / 2              t >  T_g
  x1(t) = 0                                  t <= T_v
  x1(t) = V (t - T_v)^2 / (2 S)              T_v < t <= T_v + S
  x1(t) = V S / 2 + V (t - T_v - S)          t >  T_v + S

Sphere 2 stays at x = 2 m. The energy ledger (kinetic + the work of the
time-varying gravity + energy_imposed) closes.

case_runtime.rad: a start found in the run. Ball A (R = 0.05 m, its
lowest point h = 0.1 m over a floor, TYPE6 k = 1e6 N/m) falls under
gravity; /SENSOR/INTER/5 watches the floor contact, first closed at
t_c = sqrt(2 h / g); body B (2 kg, at (1, 0, 1) m, falling freely) has an
/IMPVEL on X naming sensor 5, Fscale_y V = 0.5 m/s, f = 1: its velocity
jumps to V at t_c (event impvel_start), x_B(t) = x0 + V (t - t_c) after,
and z_B(t) = z0 - g t^2 / 2 throughout.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, G, Z0, X2 = 1.3, 0.05, 9.81, 1.0, 2.0
TG, TV, V, S, TEND = 0.2, 0.25, 0.5, 0.1, 0.6
FAST = "--fast" in sys.argv


def z_ref(t):
    t = np.asarray(t, dtype=float)
    return np.where(t <= TG, Z0, Z0 - 0.5 * G * (t - TG) ** 2)


def x1_ref(t):
    s = np.maximum(np.asarray(t, dtype=float) - TV, 0.0)
    return np.where(s <= S, V * s**2 / (2 * S), V * S / 2 + V * (s - S))


def deck(rtol=1e-10):
    d = Deck("loads switched on by time sensors")
    d.funct(1, [0.0, S, 10.0], [0.0, 1.0, 1.0], title="ramp to 1 over 0.1 s")
    d.nodes([(1, 0.0, 0.0, Z0), (2, X2, 0.0, Z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, title="sphere 1")
    d.rbody(2, 2, M, [0.4 * M * R * R] * 3, title="sphere 2")
    d.grnod(1, [1])
    d.sensor_time(1, 0.1, title="t1")
    d.sensor_time(2, 0.15, title="t2")
    d.sensor_logic("AND", 3, 1, 2, tdelay=0.05, title="both, plus 0.05 s")
    d.sensor_time(4, TV, title="the imposed velocity's start")
    d.grav(1, "Z", -G, sensor=3)
    d.impvel(1, 1, "X", 1, fscale=V, sensor=4, title="X of sphere 1 from sensor 4")
    d.run(TEND, 0.005)
    d.solver(rtol=rtol, atol_pos=1e-4 * rtol, atol_vel=1e-2 * rtol, atol_energy=1e-2 * rtol)
    return d


H, XB, ZB, MB = 0.1, 1.0, 1.0, 2.0


def deck_runtime(rtol=1e-10):
    d = Deck("an imposed velocity started by an interface sensor")
    d.funct(1, [0.0, 1.0], [0.0, 1.0e6], title="linear load curve")
    d.funct(2, [0.0, 10.0], [1.0, 1.0], title="one")
    d.nodes([(1, 0.0, 0.0, R + H), (2, XB, 0.0, ZB)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, title="ball A")
    d.rbody(2, 2, MB, [0.002] * 3, title="body B")
    d.grnod(2, [2])
    d.sphere(1, 1, (0.0, 0.0, R + H), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.type6(1, 1, 2, 1, title="ball on floor")
    d.sensor_inter(5, 1, title="first contact of A")
    d.grav(1, "Z", -G)
    d.impvel(1, 2, "X", 2, fscale=V, sensor=5, title="X of B from sensor 5")
    d.run(0.3, 0.005)
    d.solver(rtol=rtol, atol_pos=1e-4 * rtol, atol_vel=1e-2 * rtol, atol_energy=1e-2 * rtol)
    return d


def errors(r):
    ez = float(np.max(np.abs(r.pos[:, :, 2] - z_ref(r.t)[:, None])))
    ex = float(np.max(np.abs(r.pos[:, 0, 0] - x1_ref(r.t))))
    return ez, ex


def main():
    r = rcval.Result(rcval.run_case())
    ev = r.events("impvel_start")
    ok = len(ev) == 1 and abs(ev[0] - TV) <= 1e-14
    rcval.check("load_sensor.impvel_start", ok, f"impvel_start at {ev} s, the sensor's time {TV} s (to 1e-14 s)")
    held = r.t <= TG
    dz = float(np.max(np.abs(r.pos[held, :, 2] - Z0)) + np.max(np.abs(r.vel[held, :, :])))
    rcval.check("load_sensor.before", dz < 1e-12,
                f"until T_g = {TG} s ({held.sum()} records): max |z - z0| + |v| = {dz:.1e} (< 1e-12: no load yet)")
    ez, ex = errors(r)
    rcval.check("load_sensor.fall", ez < 1e-7, f"max |z - (z0 - g (t - T_g)^2/2)| = {ez:.2e} m, both spheres "
                f"(< 1e-7 m)")
    rcval.check("load_sensor.impvel", ex < 1e-7, f"max |x1 - x1_exact| = {ex:.2e} m, the shifted ramp then "
                f"constant V (< 1e-7 m)")
    on = r.t > TV
    dv = float(np.max(np.abs(r.vel[on, 0, 0] - V * np.minimum((r.t[on] - TV) / S, 1.0))))
    rcval.check("load_sensor.imposed", dv < 1e-9, f"max |vx1 - V f(t - T_v)| after T_v: {dv:.2e} m/s (< 1e-9)")
    dx2 = float(np.max(np.abs(r.pos[:, 1, 0] - X2)))
    rcval.check("load_sensor.free_x", dx2 < 1e-12, f"sphere 2: max |x - x0| = {dx2:.1e} m (no imposed velocity)")
    e = r.energy["energy_total"]
    drift = float(np.max(np.abs(e - e[0])))
    rcval.check("load_sensor.ledger", drift < 1e-6,
                f"max |E_total - E_total(0)| = {drift:.2e} J, gravity's start and the imposed velocity included "
                f"(< 1e-6 J)")
    r = rcval.Result(rcval.run_case("case_runtime.rad"))
    tc = (2 * H / G) ** 0.5
    ts, tv = r.events("sensor_trigger"), r.events("impvel_start")
    e = max(rcval.rel(ts[0], tc), rcval.rel(tv[0], tc)) if len(ts) == 1 and len(tv) == 1 else 1.0
    rcval.check("load_sensor.runtime_start", e < 1e-9, f"sensor_trigger {ts} s, impvel_start {tv} s, sqrt(2 h/g) = "
                f"{tc:.12f} s: rel. error {e:.1e} (< 1e-9)")
    xb = XB + V * np.maximum(r.t - tc, 0.0)
    ex = float(np.max(np.abs(r.pos[:, 1, 0] - xb)))
    ez = float(np.max(np.abs(r.pos[:, 1, 2] - (ZB - 0.5 * G * r.t**2))))
    rcval.check("load_sensor.runtime_x", ex < 1e-8, f"B: max |x - (x0 + V (t - t_c))| = {ex:.2e} m (< 1e-8 m); "
                f"max |z - (z0 - g t^2/2)| = {ez:.2e} m")
    rcval.check("load_sensor.runtime_z", ez < 1e-7, f"B falls freely throughout: {ez:.2e} m (< 1e-7 m)")
    en = r.energy["energy_total"]
    drift = float(np.max(np.abs(en - en[0])))
    rcval.check("load_sensor.runtime_ledger", drift < 1e-6, f"max |E_total - E_total(0)| = {drift:.2e} J, the "
                f"jump at t_c and the contact included (< 1e-6 J)")
    if not FAST:
        errs = [max(errors(rcval.Result(rcval.run(deck(rt), keep_solver=True)))) for rt in (1e-5, 1e-7, 1e-9)]
        rcval.check("load_sensor.convergence", errs[2] < errs[0],
                    "max error at rtol 1e-5, 1e-7, 1e-9: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_runtime.rad": deck_runtime()})
