"""A block slides to a stop under Coulomb friction, then stays stopped.

A sphere with locked rotations (deck.block_on_floor) at its static
penetration on a floor is launched horizontally at v0 and stopped by TYPE6
friction (Fric = mu, default stick stiffness). Reference (README.md): the
rigid Coulomb block, x_stop = v0^2 / (2 mu g), t_stop = v0 / (mu g); after
the stop the stick spring, loaded to F_lim, relaxes through its critical
stick damper: the block moves back by F_lim/K_t along the closed form
x_stop - (F_lim/K_t)(1 - (1 + w t) exp(-w t)), w = sqrt(K_t/m), and stays at
rest: no further event, |v| below a small bound once relaxed.
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
KT = K                               # default stick stiffness: the load curve's slope [N/m]
W_T = math.sqrt(KT / M)              # stick frequency [rad/s]; damper critical
T_RELAX = 30.0 / W_T                 # relaxed after 30 / w [s]
T_END, DT_OUT = 0.7, 1.0e-3
V_TOL, X_TOL = 1e-6, 1e-7            # at rest: |v| [m/s], |x - x_stop| [m]


def deck():
    d = Deck("block sliding to a stop, then at rest (TYPE6 Fric)")
    d.block_on_floor(M, R, K, G, VISC, R - M * G / K, (V0, 0.0, 0.0), fric=MU)
    d.run(T_END, DT_OUT)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    r = rcval.Result(rcval.run_case())
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
    relaxed = r.t >= ts + T_RELAX
    v = np.linalg.norm(r.vel[relaxed, 0], axis=1)
    rcval.check("slide_stop_rest.at_rest", ok_len and v.max() < V_TOL,
                f"max |v| = {v.max():.2e} m/s (< {V_TOL:g}) over {relaxed.sum()} records from 30/w_t = {T_RELAX:.3f} s "
                f"after the stop to {r.t[-1]:g} s ({r.t[-1] - ts:.3f} s after the stop, >= {T_AFTER} s)")
    back = MU * M * G / KT
    tt = r.t[sel] - ts
    x_ref = xs[0] - back * (1.0 - (1.0 + W_T * tt) * np.exp(-W_T * tt))
    dx = np.abs(r.pos[sel, 0, 0] - x_ref)
    dy = np.abs(r.pos[sel, 0, 1] - xs[1])
    rcval.check("slide_stop_rest.stays_put", ok_len and dx.max() < X_TOL and dy.max() < X_TOL,
                f"after the stop x follows x_stop - (F_lim/K_t)(1 - (1 + w t) e^(-w t)) to {dx.max():.2e} m, y constant "
                f"to {dy.max():.1e} m (< {X_TOL:g}); final x {r.pos[-1, 0, 0]:.9f} m = x_stop - {xs[0] - r.pos[-1, 0, 0]:.6e} m "
                f"(F_lim/K_t = {back:.6e} m)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
