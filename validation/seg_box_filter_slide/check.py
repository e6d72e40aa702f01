#!/usr/bin/env python3
"""A meshed box slides to a stop with incremental friction and a filter.

The box of seg_box_slide_stop (a x b x c = 0.2 x 0.12 x 0.08 m, 15 kg, a
/SURF/SEG of its six faces: 8 contact points, its corners) sits level at its
static penetration on a fixed plane and starts sliding along x at v0 = 1 m/s.
TYPE6, linear load curve k = 1e6 N/m, Visc = 2 zeta sqrt(k m) (zeta = 0.7);
/FRICTION Coulomb mu = 0.3, incremental formulation (Iform 2, K_t = k) with
a filter Ifiltr 3, Xfreq = 1 / (2 pi tau), tau = 0.05 s. Each node has its
tangential force and its filtered force (docs/theory.md 2.7). No /SOLVER card.

References (README.md), written independently of ricochet:
  - every node slips from the start on its share of the limit, the raw
    forces add up to mu m g against the sliding, and the filtered force that
    acts is F_f = mu m g (1 - exp(-t / tau)) (closed form);
  - the box m dv/dt = -F_f with the filter tau dF_f/dt = mu m g - F_f,
    solved with SciPy (solve_ivp, event v = 0): the stop time and the
    distance to the stop (less mu dz, the lift of the centre by the tilt the
    friction moment gives, as in seg_box_slide_stop);
  - the energy ledger stays constant (the friction work counts the power of
    the filtered force).
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
import meshbox  # noqa: E402

A, B, C = 0.2, 0.12, 0.08        # box [m]
M = 15.0                         # [kg]
K, ZETA, MU, G = 1.0e6, 0.7, 0.3, 9.81
V0 = 1.0                         # initial speed along x [m/s]
TAU = 0.05                       # filter time constant [s]
TEND, DTOUT = 0.5, 0.005         # [s]


def deck(nx=1, ny=1):
    """The box with its bottom face in nx x ny quadrilaterals, the other
    faces one quadrilateral each, on the plane z = 0."""
    p0 = M * G / K
    z0 = -p0
    d = Deck(f"box {nx}x{ny} sliding to a stop, incremental friction with a filter")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    meshbox.add_box(d, nx, ny, A, B, C, M, z0)
    d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), title="box on the floor")
    d.friction(1, ifric=0, ifiltr=3, xfreq=1.0 / (2 * math.pi * TAU), iform=2, fric=MU,
               title="Coulomb 0.3, incremental, filter tau 0.05 s")
    d.inivel(1, (V0, 0.0, 0.0), 7)
    d.grav(1, "Z", -G)
    d.run(TEND, DTOUT)
    return d


def reference():
    """The box equation with the filter ODE, to the stop (v = 0)."""
    def rhs(t, s):
        x, v, ff = s
        return [v, -ff / M, (MU * M * G - ff) / TAU]

    def stop(t, s):
        return s[1]
    stop.terminal = True
    sol = solve_ivp(rhs, (0.0, 10.0), [0.0, V0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14, events=stop)
    ts = float(sol.t_events[0][0])
    xs = float(sol.y_events[0][0][0])
    return ts, xs


def variant(name, nx, ny, r):
    ts_ref, xs_ref = reference()
    sticks = r.events("fric_stick")
    ts = float(sticks[0]) if len(sticks) else float("nan")
    # events while sliding (the slip of every node at the start); after the
    # stop the filter's lag against the stiff stick springs rocks the box
    # (README), not checked here
    n_ev = len(r.ev_t)
    n_sl = int(np.sum(np.asarray(r.ev_t) < ts)) if len(sticks) else n_ev
    rcval.check(f"seg_box_filter_slide.{name}.run", r.attrs.get("status") == "complete" and n_sl <= 2,
                f"status '{r.attrs.get('status')}', {n_sl} events before the stop (<= 2), {n_ev} in all, kinds "
                f"{sorted(set(r.ev_kind))}, {r.attrs.get('stats_steps')} steps")
    # the filtered force while sliding: mu m g (1 - exp(-t / tau)); the raw
    # force is mu F_n, and F_n = m (g + a_z) departs from m g while the
    # friction moment tilts the box (up to 7e-3 m g on the meshed box),
    # which the filter passes on: 2e-3 of mu m g
    sl = (r.t > 0) & (r.t < ts - 2 * DTOUT) if len(sticks) else r.t > 0
    ff = np.linalg.norm(r.ffric[sl, 0], axis=1)
    fref = MU * M * G * (1.0 - np.exp(-r.t[sl] / TAU))
    e = float(np.max(np.abs(ff - fref))) / (MU * M * G)
    dfn = float(np.max(np.abs(r.fn[sl, 0] - M * G))) / (M * G)
    k63 = int(np.argmin(np.abs(r.t - TAU)))
    rcval.check(f"seg_box_filter_slide.{name}.filtered_force", e < 2e-3,
                f"|F_f| over (0, t_s): max |F_f - mu m g (1 - exp(-t/tau))| = {e:.2e} mu m g (< 2e-3; F_n departs "
                f"from m g by up to {dfn:.2e} m g while the box tilts); at t = {r.t[k63]:g} s "
                f"{np.linalg.norm(r.ffric[k63, 0]) / (MU * M * G):.6f} mu m g, 1 - 1/e = "
                f"{1 - math.exp(-r.t[k63] / TAU):.6f}")
    e = rcval.rel(ts, ts_ref)
    rcval.check(f"seg_box_filter_slide.{name}.stop_time", e < 1e-5,
                f"first fric_stick at {ts:.9f} s, SciPy box + filter ODE {ts_ref:.9f} s (v0 / (mu g) + ~tau: "
                f"{V0 / (MU * G) + TAU:.6f} s), rel. error {e:.2e} (< 1e-5)")
    # the tilt phi by the friction moment lifts the centre by dz = phi a / 2
    # (seg_box_slide_stop): the slide of the centre is shorter by mu dz
    p0 = M * G / K
    x2 = A * A * (nx + 2) / (12.0 * nx)  # mean of x_j^2 over the bottom nodes
    phi = MU * C * p0 / (2 * x2 + MU * C * A / 2)
    dz = phi * A / 2
    if len(sticks):
        k = r.state_at(ts)
        xs = float(r.pos[k, 0, 0])
        e_raw = rcval.rel(xs, xs_ref)
        e = abs(xs - (xs_ref - MU * dz)) / xs_ref
        rcval.check(f"seg_box_filter_slide.{name}.stop_distance", e < 1e-5 and e_raw < 2e-4,
                    f"centre at the stop {xs:.9f} m; SciPy {xs_ref:.9f} m (rel. {e_raw:.2e} < 2e-4), less mu dz "
                    f"(dz = {dz:.3e} m): {xs_ref - MU * dz:.9f} m, error {e:.2e} of it (< 1e-5)")
    else:
        rcval.check(f"seg_box_filter_slide.{name}.stop_distance", False, "no fric_stick event")
    rcval.check_ledger(f"seg_box_filter_slide.{name}.ledger", r, 1e-6)


def main():
    for name, nx, ny, tag in (("corners", 1, 1, None), ("meshed", 10, 6, "meshed")):
        try:
            path = rcval.run_case() if tag is None else \
                rcval.run(deck(nx, ny), name=tag)
        except RuntimeError as err:
            rcval.check(f"seg_box_filter_slide.{name}.run", False, str(err))
            continue
        variant(name, nx, ny, rcval.Result(path))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
