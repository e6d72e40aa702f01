"""Block decelerating along Renard's friction curve (/FRICTION Ifric 3, Iform 2).

A sphere with locked rotations (a "block", m = 1 kg, R = 0.05 m) at its
static penetration on the fixed floor z = 0, under gravity, launched
horizontally at v0 = 1.2 m/s; its friction is Renard's law. Reference
(README.md): the stick onset solved exactly (the critically damped stick
spring, with mu = mu_s while sticking: its damper's force c_t v0 exceeds the
limit, so the contact slips at t = 0), then an independent scipy solve_ivp of
m dv/dt = -mu(v) m g (rtol 1e-11) to the stop. The velocity history, the
stopping time and the stopping distance are compared.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, V0 = 1.0, 0.05, 1.0e6, 9.81, 1.2
VISC = 2.0 * 0.5 * math.sqrt(K * M)   # normal damping ratio 0.5
KT = K                                # stick stiffness: the load-curve slope (no Stiff)
# Renard: mu_s, mu_d, mu_max, mu_min, V_cr1, V_cr2
MUS, MUD, MUMAX, MUMIN, VCR1, VCR2 = 0.3, 0.25, 0.45, 0.1, 0.15, 0.5


def mu(v):
    """Renard's law (docs/theory.md 6.1), written from its definition."""
    if v <= VCR1:
        x = v / VCR1
        return MUS + (MUMAX - MUS) * x * (2.0 - x)
    if v < VCR2:
        w = (v - VCR1) / (VCR2 - VCR1)
        return MUMAX + (MUMIN - MUMAX) * (3.0 - 2.0 * w) * w * w
    return MUD - (MUD - MUMIN) / (1.0 + (MUD - MUMIN) * (v - VCR2) ** 2)


def reference():
    """Stick onset (exact), then solve_ivp of x' = v, v' = -mu(v) g to v = 0.
    Returns (t1, x1, v1) at the slip, the dense solution and the stop.
    Onset: sticking with a zero state, the force that acts is the damper's,
    c_t v0 = 2 sqrt(K_t m) v0, against the sticking limit mu_s m g (sliding
    speed 0): beyond it, so the contact slips at t = 0 (lib/stick.py)."""
    t1, x1, v1 = stick.launch_onset(KT, M, V0, MUS * M * G)

    def rhs(t, y):
        return [y[1], -mu(max(y[1], 0.0)) * G]

    def stop(t, y):
        return y[1]
    stop.terminal, stop.direction = True, -1

    # integrate piecewise between the breakpoints of mu (v = V_cr2, V_cr1)
    # so that the integrator never steps across a jump of d2mu/dv2
    segs, t, y = [], t1, [x1, v1]
    for vb in (VCR2, VCR1, 0.0):
        ev = (lambda tt, yy, vb=vb: yy[1] - vb)
        ev.terminal, ev.direction = True, -1
        s = solve_ivp(rhs, (t, t + 10.0), y, method="DOP853", rtol=1e-11, atol=1e-14, dense_output=True,
                      events=ev)
        segs.append((t, s.t_events[0][0], s.sol))
        t, y = s.t_events[0][0], s.y_events[0][0]
        y[1] = vb
    return (t1, x1, v1), segs, t, y[0]


def ref_at(segs, t):
    for a, b, sol in segs:
        if a <= t <= b:
            return sol(t)
    return None


def deck(rtol=1e-8, tend=0.9):
    z0 = R - M * G / K  # static penetration m g / k
    d = Deck("block launched on a floor, /FRICTION Renard, incremental")
    d.block_on_floor(M, R, K, G, VISC, z0, (V0, 0.0, 0.0))
    d.friction(1, ifric=3, iform=2, c=(MUS, MUD, MUMAX, MUMIN, VCR1, VCR2),
               title="Renard: mu_s 0.3, mu_d 0.25, mu_max 0.45, mu_min 0.1, V_cr1 0.15, V_cr2 0.5")
    d.run(tend, 0.005)
    d.solver(rtol=rtol, atol_pos=1e-9 * rtol / 1e-6, atol_vel=1e-6 * rtol / 1e-6)
    return d


def compare(name, r, ref, tol_v, tol_stop):
    (t1, x1, v1), segs, t_stop, x_stop = ref
    sticks = r.events("fric_stick")
    if len(sticks) == 0:
        rcval.check(f"{name}.stop", False, "no fric_stick event")
        return
    ts = sticks[0]
    # velocity history: every record from the launch to the stop
    sel = (r.t >= t1) & (r.t < ts)
    err, worst_t = 0.0, 0.0
    for t, v, x in zip(r.t[sel], r.vel[sel, 0, 0], r.pos[sel, 0, 0]):
        yr = ref_at(segs, t)
        if yr is not None and abs(v - yr[1]) > err:
            err, worst_t = abs(v - yr[1]), t
    rcval.check(f"{name}.velocity", err < tol_v and sel.sum() > 100,
                f"{sel.sum()} records from the slip to the stop: max |v(t) - v_ref(t)| = {err:.1e} m/s at t = {worst_t:.3f} s "
                f"(< {tol_v:g}; v0 = {V0} m/s)")
    i = r.state_at(ts)
    et, ex = abs(ts - t_stop), abs(r.pos[i, 0, 0] - x_stop)
    before = [k for t, k in zip(r.ev_t, r.ev_kind) if t <= ts]
    rcval.check(f"{name}.stop", et < tol_stop and ex < tol_stop and before == ["fric_slip", "fric_stick"],
                f"stop (first fric_stick) at t = {ts:.9f} s, x = {r.pos[i, 0, 0]:.9f} m; reference {t_stop:.9f} s, "
                f"{x_stop:.9f} m; errors {et:.1e} s, {ex:.1e} m (< {tol_stop:g}); events before: {before}")


def main():
    ref = reference()
    (t1, x1, v1), segs, t_stop, x_stop = ref
    print(f"reference: slip at {t1:.3e} s, v1 = {v1:.9f} m/s; stop at {t_stop:.9f} s, {x_stop:.9f} m "
          f"(crossing V_cr2 at {segs[0][1]:.6f} s, V_cr1 at {segs[1][1]:.6f} s)")
    r = rcval.Result(rcval.run_case())
    rcval.check("frc_renard_decel.slip", len(r.events("fric_slip")) > 0 and abs(r.events("fric_slip")[0] - t1) < 1e-9,
                f"first fric_slip at {r.events('fric_slip')[0]:.6e} s, exact stick onset {t1:.6e} s (the stick damper's "
                f"c_t v0 = {stick.ct(KT, M) * V0:g} N against mu_s m g = {MUS * M * G:.6g} N)")
    compare("frc_renard_decel.rtol1e-8", r, ref, 1e-5, 1e-6)
    # along the curve: the measured |F_t|/F_n against mu(sliding speed) while sliding
    sl = (r.slip[:, 0] == 1) & (r.vslip[:, 0] > 0)
    e = max(abs(np.linalg.norm(f) / fn - mu(v)) for f, fn, v in zip(r.ffric[sl, 0], r.fn[sl, 0], r.vslip[sl, 0]))
    rcval.check("frc_renard_decel.on_curve", e < 1e-9,
                f"{sl.sum()} sliding records: max | |F_t|/F_n - mu(v_slip) | = {e:.1e} (< 1e-9)")
    r = rcval.Result(rcval.run(deck(rtol=1e-10), keep_solver=True))  # a named point of the rtol study
    compare("frc_renard_decel.rtol1e-10", r, ref, 1e-7, 1e-8)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
