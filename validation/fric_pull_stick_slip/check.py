"""Block under a horizontal pull on a floor: stuck below Sfric + mu m g, sliding above.

A sphere with locked rotations (a "block") on a plane, TYPE6 with Sfric and
Fric. The pull F is a horizontal /GRAV acceleration F/m on the block; both
/GRAV cards (X pull, Z weight) share one time function, a smooth ramp from 0
to 1 over T_r = 0.5 s, then 1 (README.md explains the design). Reference:
below the threshold the block stays stuck (the stick spring holds
F_t = -F after the ramp, x = F/K_t, no drift); above it slides with
a = (F - Sfric - mu m g)/m once the ramp is over.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import block_ref  # noqa: E402
import incline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck, r20  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81
SFRIC, MU = 1.0, 0.3
FTH = SFRIC + MU * M * G           # threshold Sfric + mu m g = 3.943 N
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
TR = 0.5                           # ramp duration [s]
P0 = 1e-12                         # initial penetration [m] (README.md: why not 0)


def ramp(s):
    """Quintic smoothstep on [0, 1]: f, f', f'' vanish at both ends but f(1) = 1."""
    s = np.clip(s, 0.0, 1.0)
    return s**3 * (10.0 - 15.0 * s + 6.0 * s * s)


def ramp_table(n=501):
    """Points of the time function: the ramp sampled on [0, T_r], then a far
    point at 1 so that the linear extension beyond the table stays flat."""
    t = np.linspace(0.0, TR, n)
    return list(t) + [1.0e4], list(ramp(t / TR)) + [1.0]


def deck(F, tend, dtout=0.01, rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, atol_energy=1e-6):
    z0 = R - P0
    d = Deck(f"block pulled along a floor, F = {F:g} N (TYPE6 Sfric + Fric)")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    xs, ys = ramp_table()
    d.funct(2, xs, ys, title="smooth ramp 0 -> 1 over 0.5 s (quintic smoothstep)")
    d.nodes([(1, 0.0, 0.0, z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1])
    d.add("/BCS/1", f"{'000 111':>10s}{0:>10d}{1:>10d}", title="no rotation")
    # /GRAV: fct_IDT, DIR, skew, sensor, grnod, Ascale_x, Fscale_y; one time function for both
    d.add("/GRAV/1", f"{2:>10d}{'Z':>10s}{0:>10d}{0:>10d}{1:>10d}" + " " * 10 + r20(1.0) + r20(-G), title="weight, ramped")
    d.add("/GRAV/2", f"{2:>10d}{'X':>10s}{0:>10d}{0:>10d}{1:>10d}" + " " * 10 + r20(1.0) + r20(F / M), title="pull F/m, ramped")
    d.type6(1, 1, 2, 1, visc=VISC, sfric=SFRIC, fric=MU, title="Sfric 1 N, Fric 0.3")
    d.run(tend, dtout)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_energy)
    return d


def stuck(name, r, F):
    """No slip event; over the last 10 s the position stays put, at F/K_t."""
    slips = r.events("fric_slip")
    rcval.check(f"fric_pull_stick_slip.{name}.no_slip", len(slips) == 0,
                f"F = {F:g} N = {F / FTH:.3f} (Sfric + mu m g): {len(slips)} fric_slip events (expected 0)")
    last = r.t >= r.t[-1] - 10.0 - 1e-12
    x = r.pos[last, 0, 0]
    drift = np.max(np.abs(x - x[0]))
    other = np.max(np.abs(r.pos[last, 0, 1]))
    rcval.check(f"fric_pull_stick_slip.{name}.drift", drift < 1e-9 and other < 1e-12,
                f"max |x(t) - x({r.t[last][0]:g} s)| over the last 10 s = {drift:.2e} m (< 1e-9), |y| < {other:.1e} m")
    e = rcval.rel(x[-1], F / K)
    rcval.check(f"fric_pull_stick_slip.{name}.stick_spring", e < 1e-6,
                f"x = {x[-1]:.9e} m, F/K_t = {F / K:.9e} m (K_t = load-curve slope), rel. error {e:.2e} (< 1e-6)")


def onset(F):
    """Quasi-static slip onset during the ramp: F f(t) = Sfric + mu m g f(t)."""
    fs = SFRIC / (F - MU * M * G)
    lo, hi = 0.0, 1.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ramp(mid) < fs else (lo, mid)
    return TR * 0.5 * (lo + hi)


def main():

    # below the threshold (case.rad): F = 3.5 N
    F = 3.5
    stuck("below", rcval.Result(rcval.run_case()), F)
    # just below: F = 0.99 (Sfric + mu m g)
    F = 0.99 * FTH
    stuck("just_below", rcval.Result(rcval.run(deck(F, 11.0))), F)

    # above: F = 5 N slides at (F - Sfric - mu m g)/m once the ramp is over
    F = 5.0
    r = rcval.Result(rcval.run(deck(F, 3.0)))
    a_ref = (F - FTH) / M
    slips, sticks = r.events("fric_slip"), r.events("fric_stick")
    t_qs = onset(F)
    # reference of the damped model (lib/block_ref.py): normal spring-damper
    # from P0, critically damped stick spring, the ramped table, the slip test
    # with the force band of the run's tolerances (lib/incline.py: the deck's
    # /SOLVER card, or the derived ones with F_s = m |g|max, g = (F/m, 0, -g))
    g_mag = math.hypot(G, F / M)
    tol = (incline.tolerances(M, g_mag, K) if rcval.DEFAULTS else
           incline.tolerances(M, g_mag, K, rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, coord=R))
    b = block_ref.Block(M, K, VISC, K, MU, SFRIC, tol["fband"], G, F / M, ramp_table(), p0=P0)
    t_end_ref = t_qs + 0.01
    ex = b.solve_exact(t_end_ref, nsample=16)
    ref = b.solve(t_end_ref, method="LSODA")
    t_on = ref["events"][0][0] if ref["events"] else float("nan")
    acc = abs(ex["events"][0][0] - t_on) if ex["events"] else float("inf")
    rate = b.rates(t_on, b.before[0], "fric_slip")
    dF = incline.force_resolution(b, tol, SFRIC + MU * M * G)
    win = dF / abs(rate) + 10.0 * acc
    e = abs(slips[0] - t_on) if len(slips) else float("inf")
    ok = (len(slips) == 1 and len(sticks) == 0 and e < win and [k for _, k in ref["events"]] == ["fric_slip"]
          and [k for _, k in ex["events"]] == ["fric_slip"])
    rcval.check("fric_pull_stick_slip.above.onset", ok,
                f"fric_slip at {slips[0] if len(slips) else float('nan'):.9f} s, reference (damped model, f_band "
                f"{tol['fband']:.3g} N) {t_on:.9f} s (exact flow {acc:.1e} s away), error {e:.1e} s (< {win:.1e} s: "
                f"{dF:.2e} N over dg/dt {abs(rate):.3g} N/s); quasi-static F f(t) = Sfric + mu m g f(t) at {t_qs:.9f} s "
                f"(for information: {slips[0] - t_qs if len(slips) else float('nan'):.1e} s); "
                f"{len(sticks)} fric_stick (expected 0)")
    sl = r.t >= TR + 0.5  # ramp over, normal transient damped
    a, b = np.polyfit(r.t[sl], r.vel[sl, 0, 0], 1)
    resid = np.max(np.abs(r.vel[sl, 0, 0] - (a * r.t[sl] + b)))
    e = rcval.rel(a, a_ref)
    rcval.check("fric_pull_stick_slip.above.acceleration", e < 1e-5 and resid < 1e-6,
                f"fit of v_x over [{r.t[sl][0]:g}, {r.t[-1]:g}] s: a = {a:.9f} m/s^2, (F - Sfric - mu m g)/m = {a_ref:.9f}, "
                f"rel. error {e:.2e} (< 1e-5), max fit residual {resid:.1e} m/s (< 1e-6)")
    side = np.max(np.abs(r.vel[:, 0, 1])) + np.max(np.abs(r.pos[:, 0, 1]))
    rcval.check("fric_pull_stick_slip.above.straight", side < 1e-12,
                f"max |y| + max |v_y| = {side:.1e} (< 1e-12)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(3.5, 11.0))
