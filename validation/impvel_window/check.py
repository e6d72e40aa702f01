"""An imposed velocity with a start and a stop: /IMPVEL Tstart and Tstop.

A sphere (m = 1.3 kg) falls under gravity from rest and moves sideways at
vx0 (/INIVEL). /IMPVEL (Dir Z, f = 1, Fscale_y = V1 > 0: upward) acts
from Tstart = 0.15 s to Tstop = 0.4 s: before Tstart the body falls freely,
at Tstart its vertical velocity jumps to V1 (a time breakpoint, event
`impvel_start`), until Tstop it rises at V1 whatever the gravity (the
support takes m g), after Tstop it falls freely from V1 (event
`impvel_stop`). Reference (closed form, README.md):

  z(t) = z0 - g t^2 / 2                                     t <= Tstart
  z(t) = z0 - g Tstart^2 / 2 + V1 (t - Tstart)              Tstart < t <= Tstop
  z(t) = z(Tstop) + V1 (t - Tstop) - g (t - Tstop)^2 / 2    t > Tstop

and x(t) = x0 + vx0 t throughout (the card drives Z only). The energy
ledger closes: the jump's impulse and the support's work are in
energy_imposed.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, G, Z0, X0, VX0 = 1.3, 0.05, 9.81, 1.0, 0.2, 0.37
V1, TSTART, TSTOP, TEND = 0.55, 0.15, 0.4, 0.7


def z_ref(t):
    t = np.asarray(t, dtype=float)
    z1 = Z0 - 0.5 * G * TSTART**2
    z2 = z1 + V1 * (TSTOP - TSTART)
    return np.where(t <= TSTART, Z0 - 0.5 * G * t**2,
                    np.where(t <= TSTOP, z1 + V1 * (t - TSTART),
                             z2 + V1 * (t - TSTOP) - 0.5 * G * (t - TSTOP) ** 2))


def vz_ref(t):
    t = np.asarray(t, dtype=float)
    return np.where(t < TSTART, -G * t, np.where(t <= TSTOP, V1, V1 - G * (t - TSTOP)))


def deck(rtol=1e-8):
    d = Deck("imposed velocity from Tstart to Tstop")
    d.funct(1, [0.0, 1.0], [1.0, 1.0], title="one")
    d.nodes([(1, X0, 0.0, Z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3)
    d.grnod(1, [1])
    d.grav(1, "Z", -G)
    d.inivel(1, (VX0, 0.0, 0.0), 1)
    d.impvel(1, 1, "Z", 1, fscale=V1, tstart=TSTART, tstop=TSTOP)
    d.run(TEND, 0.01)
    d.solver(rtol=rtol, atol_pos=1e-4 * rtol, atol_vel=1e-2 * rtol, atol_energy=1e-2 * rtol)
    return d


def errors(r):
    ez = float(np.max(np.abs(r.pos[:, 0, 2] - z_ref(r.t))))
    ex = float(np.max(np.abs(r.pos[:, 0, 0] - (X0 + VX0 * r.t))))
    return ez, ex


def main():
    r = rcval.Result(rcval.run_case())
    ev1, ev2 = r.events("impvel_start"), r.events("impvel_stop")
    ok = len(ev1) == 1 and abs(ev1[0] - TSTART) <= 1e-14 and len(ev2) == 1 and abs(ev2[0] - TSTOP) <= 1e-14
    rcval.check("impvel_window.events", ok, f"impvel_start at {ev1} s (Tstart = {TSTART} s), "
                f"impvel_stop at {ev2} s (Tstop = {TSTOP} s)")
    ez, ex = errors(r)
    rcval.check("impvel_window.z", ez < 1e-7, f"max |z - z_exact| = {ez:.2e} m over free fall, imposed rise, free "
                f"flight (< 1e-7 = 10 rtol z0)")
    rcval.check("impvel_window.x", ex < 1e-9, f"max |x - (x0 + vx0 t)| = {ex:.2e} m (the card drives Z only, < 1e-9)")
    mid = (r.t > TSTART + 1e-9) & (r.t <= TSTOP)
    dv = float(np.max(np.abs(r.vel[mid, 0, 2] - V1)))
    rcval.check("impvel_window.imposed", dv < 1e-9, f"max |vz - V1| between Tstart and Tstop: {dv:.2e} m/s (< 1e-9)")
    e = r.energy["energy_total"]
    drift = float(np.max(np.abs(e - e[0])))
    rcval.check("impvel_window.ledger", drift < 1e-6,
                f"max |E_total - E_total(0)| = {drift:.2e} J, the jump at Tstart included (< 1e-6)")
    errs = [errors(rcval.Result(rcval.run(deck(rt), keep_solver=True)))[0] for rt in (1e-5, 1e-7, 1e-9)]
    # each refinement lowers the error, until it reaches the rounding of z
    # (4 ulps of z0: the motion is piecewise quadratic, which BDF of order
    # 2 and more follows exactly, so that tight runs end at the rounding)
    zfloor = 4.0 * np.finfo(float).eps * Z0
    conv = all(b < a or b <= zfloor for a, b in zip(errs, errs[1:])) and errs[1] < max(errs[0], zfloor)
    rcval.check("impvel_window.convergence", conv,
                "max |z - z_exact| at rtol 1e-5, 1e-7, 1e-9: " + ", ".join(f"{x:.2e}" for x in errs) +
                f" (decreasing, or within the rounding of z, {zfloor:.2e} m)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
