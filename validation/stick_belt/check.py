"""Stick-slip oscillator with exact stick: a block on a moving belt, held by
a spring to a fixed point, two-level Coulomb friction (TYPE6 Istick = 1,
static coefficient Fric_s = mu_s, sliding coefficient Fric = mu_k).

Reference (README.md): the exact piecewise solution of the rigid-stick
spring-block model. Stick: the block rides with the belt, x' = V, until
k x = mu_s m g; slip: m x'' = -k x + mu_k m g, harmonic about
x_k = mu_k m g / k, until x' = V again, where the spring force k (x_k - D)
lies inside the static limit, so it sticks. Closed-form switch times,
period and extremes; compared at 1e-6 relative or better.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import belt  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81     # block [kg], sphere radius [m], contact stiffness [N/m], gravity
VISC = 2.0 * 0.5 * math.sqrt(K * M)     # normal damping ratio 0.5
MU_S, MU_K = 0.4, 0.25                  # static and sliding coefficients
V = 0.05                                # belt speed [m/s]
KS = 100.0                              # spring [N/m]
L0 = 1.0                                # spring length [m]
MBELT = 1.0e12                          # belt mass [kg]
TEND = 5.0


def reference(ncycle):
    """Switch times of the rigid-stick model from x = 0, x' = V at t = 0:
    [(t, kind)], the slip duration, the period, the extremes of x."""
    w = math.sqrt(KS / M)
    xs, xk = MU_S * M * G / KS, MU_K * M * G / KS
    D = xs - xk
    A = math.hypot(D, V / w)
    t_slip = (math.pi + 2.0 * math.atan2(V / w, D)) / w   # x' = V again
    t_stick = 2.0 * D / V                                   # from x_k - D to x_s at V
    ev, t = [], xs / V
    for _ in range(ncycle):
        ev.append((t, "fric_slip"))
        t += t_slip
        ev.append((t, "fric_stick"))
        t += t_stick
    return ev, t_slip, t_slip + t_stick, (xk - A, xk + A)


def deck(dtout=1e-3):
    d = Deck("exact stick-slip: block on a belt, spring to a fixed point, TYPE6 Istick 1, Fric_s 0.4, Fric 0.25")
    z0 = belt.add_block_on_belt(d, R, M, K, G, MBELT, V)
    d.type6(1, 1, 2, 1, visc=VISC, fric=MU_K, istick=1, fric_s=MU_S,
            title="exact stick: static 0.4, sliding 0.25")
    d.spring(1, 0, (-L0, 0.0, z0), 1, (0.0, 0.0, z0), a=KS, title="spring k = 100 N/m to a fixed point, relaxed at t = 0")
    d.run(TEND, dtout)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    ev = [(t, k) for t, k in zip(r.ev_t, r.ev_kind) if k in ("fric_slip", "fric_stick")]
    ref, t_slip, period, (xmin, xmax) = reference(20)
    ref = [e for e in ref if e[0] < TEND]
    kinds_ok = [k for _, k in ev] == [k for _, k in ref]
    err = max(abs(a[0] - b[0]) / b[0] for a, b in zip(ev, ref)) if kinds_ok and ref else float("inf")
    rcval.check("stick_belt.switches", kinds_ok and err < 1e-6 and len(r.ev_t) == len(ev),
                f"{len(ev)} switches in {TEND:g} s (expected {len(ref)}, alternating fric_slip/fric_stick, no other "
                f"event: {len(r.ev_t)} in all); max |t - t_ref| / t_ref = {err:.1e} (< 1e-6); first slip at "
                f"{ev[0][0] if ev else float('nan'):.10f} s, mu_s m g / (k V) = {ref[0][0]:.10f} s")
    sl = [t for t, k in ev if k == "fric_slip"]
    st = [t for t, k in ev if k == "fric_stick"]
    per = sl[-1] - sl[-2]
    dur = st[-1] - sl[-1] if st[-1] > sl[-1] else st[-1] - sl[-2]
    e_p, e_d = rcval.rel(per, period), rcval.rel(dur, t_slip)
    rcval.check("stick_belt.period", e_p < 1e-6 and e_d < 1e-6,
                f"last cycle: period {per:.10f} s, closed form 2 D / V + (pi + 2 atan(V / (w D))) / w = {period:.10f} s, "
                f"rel. error {e_p:.1e}; slip duration {dur:.10f} s, closed form {t_slip:.10f} s, rel. error {e_d:.1e} "
                f"(both < 1e-6)")
    # while sticking the block rides with the belt (relative speed 0) and the
    # friction force is the spring's, k x; while sliding it is mu_k m g
    x = r.pos[:, 0, 0] - r.pos[0, 0, 0]
    u = r.vel[:, 0, 0] - r.vel[:, 1, 0]
    stuck = (r.slip[:, 0] == 0) & (r.at_event == 0)
    slid = (r.slip[:, 0] == 1) & (r.at_event == 0)
    u_st = np.max(np.abs(u[stuck]))
    f_st = np.max(np.abs(r.ffric[stuck, 0, 0] - KS * x[stuck])) / (MU_S * M * G)
    f_sl = np.max(np.abs(r.ffric[slid, 0, 0] - MU_K * M * G)) / (MU_K * M * G)
    rcval.check("stick_belt.forces", u_st < 1e-9 and f_st < 1e-6 and f_sl < 1e-6,
                f"sticking ({int(stuck.sum())} records): max |x' - V| = {u_st:.1e} m/s (< 1e-9), max |F - k x| / "
                f"(mu_s m g) = {f_st:.1e} (< 1e-6); sliding ({int(slid.sum())} records): max |F - mu_k m g| / (mu_k m g) "
                f"= {f_sl:.1e} (< 1e-6)")
    c = (r.t >= sl[-2]) & (r.at_event == 0)
    lo, hi = rcval.refined_extreme(x[c], -1), rcval.refined_extreme(x[c], 1)
    rcval.check("stick_belt.extremes", abs(lo - xmin) < 1e-6 * xmax and abs(hi - xmax) < 1e-6 * xmax,
                f"last cycle: x in [{lo:.10f}, {hi:.10f}] m (records every 1 ms, each extreme refined by the parabola "
                f"through its three records), closed form [x_k - A, x_k + A] = [{xmin:.10f}, {xmax:.10f}]; errors "
                f"{abs(lo - xmin):.1e}, {abs(hi - xmax):.1e} m (< 1e-6 x_max)")
    rcval.check_ledger("stick_belt.energy", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
