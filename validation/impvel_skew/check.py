"""An imposed velocity along a skew axis: /IMPVEL with skew_ID (a /SKEW/FIX).

A sphere (m = 0.9 kg) under gravity g = 9.81 m/s^2 (along -Z) starts with
the velocity v_i = (0.3, -0.2, 0.1) m/s (/INIVEL). An /IMPVEL on Dir Y with
skew_ID 5 holds its velocity component along the skew's Y' axis
u = (0.48, -0.36, 0.8) at V = 0.45 m/s (f = 1) until Tstop = 0.3 s; the
other two components are free. The translational mass being isotropic, the
support's force is along u and the motion is, in closed form (README.md):

  v(0) = v_i + u (V - u.v_i),  a = g - u (u.g)     for t <= Tstop
  x(t) = x0 + v(0) t + a t^2 / 2
  x(t) = x(Tstop) + v(Tstop) (t - Tstop) + g (t - Tstop)^2 / 2    after

Checks the trajectory, the velocity along u while imposed, the event at
Tstop, the energy ledger (the support's work in energy_imposed), and the
error shrinking as rtol shrinks.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

M, R = 0.9, 0.04
G = np.array([0.0, 0.0, -9.81])
X0 = np.array([0.2, 0.1, 1.0])
VI = np.array([0.3, -0.2, 0.1])
U = np.array([0.48, -0.36, 0.8])   # the skew's Y' axis
V2 = np.array([0.6, 0.8, 0.0])     # in the plane Y'Z' with Y': gives X' = Y' x V2 normalised
V, TSTOP, TEND = 0.45, 0.3, 0.6


def reference(t):
    t = np.asarray(t, dtype=float)[:, None]
    v0 = VI + U * (V - U @ VI)
    a = G - U * (U @ G)
    x1 = X0 + v0 * TSTOP + 0.5 * a * TSTOP**2
    v1 = v0 + a * TSTOP
    s = t - TSTOP
    return np.where(t <= TSTOP, X0 + v0 * t + 0.5 * a * t**2, x1 + v1 * s + 0.5 * G * s**2)


def deck(rtol=1e-8):
    d = Deck("imposed velocity along a skew axis")
    d.funct(1, [0.0, 1.0], [1.0, 1.0], title="one")
    d.nodes([(1, *X0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3)
    d.grnod(1, [1])
    d.grav(1, "Z", G[2])
    d.inivel(1, tuple(VI), 1)
    d.add("/SKEW/FIX/5", line(("r", 0.0), ("r", 0.0), ("r", 0.0)), line(*[("r", x) for x in U]),
          line(*[("r", x) for x in V2]), title="Y' along u")
    d.add("/IMPVEL/1", "#  fct_IDT       Dir   skew_ID sensor_ID  grnod_ID  frame_ID     Icoor",
          i10(1) + "Y".rjust(10) + i10(5) + i10(0) + i10(1) + i10(0) + i10(0),
          "#           Ascale_x            Fscale_y              Tstart               Tstop",
          line(("r", 1.0), ("r", V), ("r", 0.0), ("r", TSTOP)), title="along Y' of skew 5")
    d.run(TEND, 0.01)
    d.solver(rtol=rtol, atol_pos=1e-4 * rtol, atol_vel=1e-2 * rtol, atol_energy=1e-2 * rtol)
    return d


def error(r):
    return float(np.max(np.abs(r.pos[:, 0, :] - reference(r.t))))


def main():
    r = rcval.Result(rcval.run_case())
    err = error(r)
    rcval.check("impvel_skew.trajectory", err < 1e-7,
                f"max |x - x_exact| = {err:.2e} m over the imposed phase and the free flight (< 1e-7)")
    held = r.t <= TSTOP
    du = float(np.max(np.abs(r.vel[held, 0, :] @ U - V)))
    rcval.check("impvel_skew.along_u", du < 1e-9, f"max |u.v - V| while imposed: {du:.2e} m/s (< 1e-9)")
    ev = r.events("impvel_stop")
    rcval.check("impvel_skew.event", len(ev) == 1 and abs(ev[0] - TSTOP) <= 1e-14, f"impvel_stop at {ev} s (Tstop = {TSTOP} s)")
    e = r.energy["energy_total"]
    drift = float(np.max(np.abs(e - e[0])))
    rcval.check("impvel_skew.ledger", drift < 1e-6, f"max |E_total - E_total(0)| = {drift:.2e} J (< 1e-6)")
    errs = [error(rcval.Result(rcval.run(deck(rt), keep_solver=True))) for rt in (1e-5, 1e-7, 1e-9)]
    rcval.check("impvel_skew.convergence", errs[2] < errs[1] < errs[0] or errs[0] < 1e-12,
                "max |x - x_exact| at rtol 1e-5, 1e-7, 1e-9: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
