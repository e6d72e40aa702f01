"""Sliding block stopped by Coulomb friction (TYPE6 Fric only) on a floor.

A sphere with locked rotations (a "block") rests on a plane at its static
penetration under gravity and is launched horizontally at v0. Reference
(README.md): the rigid Coulomb result x_stop = v0^2 / (2 mu g),
t_stop = v0 / (mu g), which is also the exact solution of ricochet's
elastic-plastic friction law: its stick force is the spring state plus a
critically damped stick damper (c_t = 2 sqrt(K_t m)), whose force c_t v0 at
the launch exceeds the limit, so the contact slips at t = 0 and slides at
F_lim = mu m g to the stop. After the stop (fric_stick, state at -F_lim) the
critically damped stick spring relaxes the block back by F_lim/K_t without
ringing. The stopping point is the record written at the first fric_stick
event.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, MU, V0 = 1.0, 0.05, 1.0e6, 9.81, 0.3, 1.0
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5: a quiet normal direction


def coulomb():
    """Rigid Coulomb block: stopping distance and time."""
    return V0**2 / (2 * MU * G), V0 / (MU * G)


def elastic_plastic(kt, v0=V0):
    """Exact solution of ricochet's law: a sticking contact with a zero state
    whose applied force F = F_t - c_t v is the damper's alone at the launch,
    c_t v0 = 2 sqrt(K_t m) v0, far above (1 + 1e-6) F_lim: it slips at t = 0
    (lib/stick.py), then m v' = -F_lim until v = 0. Returns slip time, stop
    time, stop distance, stored tangential energy at the stop (the state is
    -F_lim along the motion from the slip on: F_lim^2/(2 K_t))."""
    flim = MU * M * G
    t1, x1, v1 = stick.launch_onset(kt, M, v0, flim)
    a = flim / M
    return t1, t1 + v1 / a, x1 + v1**2 / (2 * a), 0.5 * flim**2 / kt


def deck(rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, atol_energy=1e-6, stiff=None, angle=0.0, tend=0.4, dtout=0.01):
    """angle: direction of the launch in the floor plane (degrees from x)."""
    z0 = R - M * G / K  # static penetration m g / k
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    d = Deck("block sliding to a stop (TYPE6 Fric)")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1])
    d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    d.inivel(1, (V0 * c, V0 * s, 0.0), 1)
    d.grav(1, "Z", -G, 1)
    d.type6(1, 1, 2, 1, visc=VISC, fric=MU, stiff=stiff, title="Coulomb friction mu = 0.3")
    d.run(tend, dtout)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_energy)
    return d


def measure(r, direction=(1.0, 0.0)):
    """First fric_slip and fric_stick times; position along and across the
    launch direction, speed and energies at the fric_stick record."""
    t_slip = r.events("fric_slip")
    t_stick = r.events("fric_stick")
    i = r.state_at(t_stick[0])
    ux, uy = direction
    p = r.pos[i, 0]
    return dict(t_slip=t_slip[0], t_stop=t_stick[0], x=p[0] * ux + p[1] * uy, y=-p[0] * uy + p[1] * ux,
                z=p[2], v=np.linalg.norm(r.vel[i, 0]), efric=r.energy["energy_friction"][i],
                wfric=r.energy["energy_friction_work"][i], ekin=r.energy["energy_kinetic"][i],
                etot=r.energy["energy_total"], i=i, before=[k for t, k in zip(r.ev_t, r.ev_kind) if t <= t_stick[0]])


def main():
    x_c, t_c = coulomb()

    # 1. default solver tolerances, against the rigid Coulomb block
    r = rcval.Result(rcval.run_case())
    q = measure(r)
    rcval.check("fric_slide_stop.events", q["before"] == ["fric_slip", "fric_stick"],
                f"events up to the stop: {q['before']} (expected fric_slip at the launch, then fric_stick)")
    e = rcval.rel(q["x"], x_c)
    rcval.check("fric_slide_stop.distance", e < 1e-4,
                f"x_stop = {q['x']:.9f} m, v0^2/(2 mu g) = {x_c:.9f} m, rel. error {e:.2e} (< 1e-4)")
    e = rcval.rel(q["t_stop"], t_c)
    rcval.check("fric_slide_stop.time", e < 1e-4,
                f"t_stop = {q['t_stop']:.9f} s, v0/(mu g) = {t_c:.9f} s, rel. error {e:.2e} (< 1e-4)")
    rcval.check("fric_slide_stop.at_rest", q["v"] < 1e-6,
                f"|v| at the fric_stick record = {q['v']:.2e} m/s (< 1e-6)")

    # 2. tight tolerances, against the exact solution of the elastic-plastic law
    t1, t2, x2, est = elastic_plastic(K)
    r = rcval.Result(rcval.run(deck(1e-10, 1e-13, 1e-10, 1e-10, tend=1.0, dtout=1e-3)))  # records every 1 ms: the settling
    q = measure(r)
    e = max(rcval.rel(q["x"], x2), rcval.rel(q["t_stop"], t2))
    rcval.check("fric_slide_stop.exact_law", e < 1e-8,
                f"x_stop = {q['x']:.12f} m (exact {x2:.12f}), t_stop = {q['t_stop']:.12f} s (exact {t2:.12f}), "
                f"max rel. error {e:.2e} (< 1e-8); the exact law is the rigid Coulomb block (differs by {rcval.rel(x2, x_c):.1e})")
    e = abs(q["t_slip"] - t1)
    rcval.check("fric_slide_stop.slip_onset", e < 1e-12,
                f"fric_slip at {q['t_slip']:.6e} s, K_t = {K:g}: the stick damper's force c_t v0 = "
                f"{stick.ct(K, M) * V0:g} N exceeds (1 + 1e-6) F_lim = {(1 + stick.BAND) * MU * M * G:.6g} N at the launch, "
                f"so t_slip = {t1:g} s; error {e:.1e} s (< 1e-12)")
    ediss = 0.5 * M * V0**2 - est
    e = max(abs(q["efric"] - ediss), abs(q["wfric"] - 0.5 * M * V0**2)) / (0.5 * M * V0**2)
    rcval.check("fric_slide_stop.energy", e < 1e-8,
                f"at the stop: friction work {q['wfric']:.12f} J (1/2 m v0^2 = {0.5 * M * V0**2:.12f}), dissipated "
                f"{q['efric']:.12f} J (1/2 m v0^2 - F_lim^2/(2 K_t) = {ediss:.12f}); max rel. error {e:.2e} (< 1e-8)")
    drift = np.max(np.abs(q["etot"] - q["etot"][0])) / (0.5 * M * V0**2)
    rcval.check("fric_slide_stop.ledger", drift < 1e-7,
                f"max |energy_total - E0| / (1/2 m v0^2) = {drift:.2e} over the run, the settling included (< 1e-7)")

    # after the stop the critically damped stick spring relaxes the block back
    # by F_lim/K_t without ringing: x - x_stop = -(F_lim/K_t)(1 - (1 + w s) e^(-w s)),
    # s = t - t_stop (lib/stick.py); no further event, no further slip
    flim = MU * M * G
    after = r.t >= q["t_stop"]
    tau = r.t[after] - q["t_stop"]
    dx = r.pos[after, 0, 0] - q["x"]
    back = flim / K
    x_ex = np.array([stick.settle(K, M, flim, s)[0] for s in tau])
    e_path = np.max(np.abs(dx - x_ex)) / back
    e_end = abs(dx[-1] + back) / back
    v_end = np.linalg.norm(r.vel[-1, 0])
    n_slip = len(r.events("fric_slip"))
    n_after = sum(1 for t in r.ev_t if t > q["t_stop"])
    ok = (n_slip == 1 and n_after == 0 and dx.max() < 1e-12 and dx.min() > -back * (1 + 1e-6) and e_end < 1e-6
          and e_path < 1e-6 and v_end < 1e-10)
    rcval.check("fric_slide_stop.settle", ok,
                f"{r.t[-1] - q['t_stop']:.2f} s after the stop: x - x_stop in [{dx.min():.6e}, {dx.max():.1e}] m, "
                f"at the end {dx[-1]:.9e} m against -F_lim/K_t = {-back:.9e} m (rel. error {e_end:.1e}, < 1e-6); "
                f"max |x - x_stop - x_settle(t)| / (F_lim/K_t) = {e_path:.1e} (< 1e-6, critically damped, no ringing); "
                f"final speed {v_end:.1e} m/s (< 1e-10); events after the stop {n_after} (expected 0), "
                f"fric_slip events in the run {n_slip} (expected 1)")

    # 3. Stiff given: the stick spring is K_t = Stiff; c_t v0 = 200 N still exceeds the limit
    kt = 1.0e4
    t1, t2, x2, est = elastic_plastic(kt)
    q = measure(rcval.Result(rcval.run(deck(1e-10, 1e-13, 1e-10, 1e-10, stiff=kt))))
    e = max(rcval.rel(q["x"], x2), rcval.rel(q["t_stop"], t2), abs(q["t_slip"] - t1) / t2)
    rcval.check("fric_slide_stop.stiff", e < 1e-8,
                f"Stiff = {kt:g}: x_stop = {q['x']:.12f} m (exact {x2:.12f}), t_stop = {q['t_stop']:.12f} s "
                f"(exact {t2:.12f}), t_slip = {q['t_slip']:.9e} s (exact {t1:.9e}); max rel. error {e:.2e} (< 1e-8); "
                f"c_t v0 = {stick.ct(kt, M) * V0:g} N > F_lim = {MU * M * G:g} N")

    # 4. launched obliquely in the floor plane: same stop along the launch line, none across it
    ang = 35.0
    u = (math.cos(math.radians(ang)), math.sin(math.radians(ang)))
    t1, t2, x2, est = elastic_plastic(K)
    q = measure(rcval.Result(rcval.run(deck(1e-10, 1e-13, 1e-10, 1e-10, angle=ang))), u)
    e = max(rcval.rel(q["x"], x2), rcval.rel(q["t_stop"], t2))
    rcval.check("fric_slide_stop.oblique", e < 1e-8 and abs(q["y"]) < 1e-12,
                f"launched at {ang:g} deg: along {q['x']:.12f} m (exact {x2:.12f}), across {q['y']:.1e} m (< 1e-12), "
                f"t_stop {q['t_stop']:.12f} s (exact {t2:.12f}); max rel. error {e:.2e} (< 1e-8)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
