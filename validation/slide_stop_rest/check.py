"""A block slides to a stop under Coulomb friction, then stays stopped.

A sphere with locked rotations (deck.block_on_floor) at its static
penetration on a floor is launched horizontally at v0 and stopped by TYPE6
friction (Fric = mu, default stick stiffness). Reference (README.md): the
rigid Coulomb block, x_stop = v0^2 / (2 mu g), t_stop = v0 / (mu g), within
the tolerance that the stick-spring onset allows; after the stop nothing
pushes the block along the floor, so it stays at rest: no further event,
|v| and the displacement from the stopping point stay below small bounds
for the remaining 0.5 s of the run.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, MU, V0 = 1.0, 0.05, 1.0e6, 9.81, 0.3, 0.5
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
X_STOP, T_STOP = V0**2 / (2 * MU * G), V0 / (MU * G)
T_AFTER = 0.5                        # run on after the stop [s]
T_END, DT_OUT = 0.7, 1.0e-3
V_TOL, X_TOL = 1e-6, 1e-7            # at rest: |v| [m/s], |x - x_stop| [m]


def deck():
    d = Deck("block sliding to a stop, then at rest (TYPE6 Fric)")
    d.block_on_floor(M, R, K, G, VISC, R - M * G / K, (V0, 0.0, 0.0), fric=MU)
    d.run(T_END, DT_OUT)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    r = rcval.Result(rcval.run_file(os.path.join(HERE, "case.rad")))
    sticks = r.events("fric_stick")
    if len(sticks) == 0:
        rcval.check("slide_stop_rest.stops", False, f"no fric_stick event up to {r.t[-1]:g} s; events {r.ev_kind[:10]}")
        rcval.finish()
    ts = sticks[0]
    i = r.state_at(ts)
    xs = r.pos[i, 0].copy()
    before = [k for t, k in zip(r.ev_t, r.ev_kind) if t <= ts]
    rcval.check("slide_stop_rest.events_to_stop", before == ["fric_slip", "fric_stick"],
                f"events up to the stop: {before} (expected fric_slip at the stick onset, then fric_stick)")
    e = rcval.rel(xs[0], X_STOP)
    rcval.check("slide_stop_rest.distance", e < 1e-4,
                f"x_stop = {xs[0]:.9f} m, v0^2/(2 mu g) = {X_STOP:.9f} m, rel. error {e:.2e} (< 1e-4; stick onset "
                f"F_lim/(2 K_t) = {MU * M * G / (2 * K) / X_STOP:.1e})")
    e = rcval.rel(ts, T_STOP)
    rcval.check("slide_stop_rest.time", e < 1e-4,
                f"t_stop = {ts:.9f} s, v0/(mu g) = {T_STOP:.9f} s, rel. error {e:.2e} (< 1e-4)")
    # after the stop: nothing happens
    after = [(float(t), k) for t, k in zip(r.ev_t, r.ev_kind) if t > ts]
    rcval.check("slide_stop_rest.no_events_after_stop", not after,
                f"{len(after)} events in the {r.t[-1] - ts:.3f} s after the stop (expected 0)"
                + (f"; first: {after[:4]}, kinds {sorted(set(k for _, k in after))}" if after else ""))
    sel = r.t >= ts
    ok_len = r.t[-1] - ts >= T_AFTER - 1e-9
    v = np.linalg.norm(r.vel[sel, 0], axis=1)
    rcval.check("slide_stop_rest.at_rest", ok_len and v.max() < V_TOL,
                f"max |v| = {v.max():.2e} m/s (< {V_TOL:g}) over {sel.sum()} records from the stop to {r.t[-1]:g} s "
                f"({r.t[-1] - ts:.3f} s, >= {T_AFTER} s)")
    dx = np.linalg.norm(r.pos[sel, 0, :2] - xs[:2], axis=1)
    rcval.check("slide_stop_rest.stays_put", ok_len and dx.max() < X_TOL,
                f"max horizontal |x - x_stop| = {dx.max():.2e} m (< {X_TOL:g}) after the stop; final x "
                f"{r.pos[-1, 0, 0]:.9f} m")
    rcval.finish()


if __name__ == "__main__":
    if "--write-case" in sys.argv:
        deck().write(os.path.join(HERE, "case.rad"))
    else:
        main()
