#!/usr/bin/env python3
"""A meshed box slides on a floor and comes to rest (friction per contact point).

A box (a x b x c = 0.2 x 0.12 x 0.08 m, 15 kg, /RBODY mass and inertia given)
whose contact surface is a /SURF/SEG (the bottom face meshed into nx x ny
quadrilaterals, the other five faces one quadrilateral each) sits level at
its static penetration on a fixed floor and starts sliding along x at v0.
TYPE6, linear load curve k = 1e6 N/m, Visc = 2 zeta sqrt(k m) (zeta = 0.7),
Fric = mu = 0.3 (stick stiffness K_t = k). Each node has its own tangential
state and stick/slip mode (docs/theory.md 2.7). No /SOLVER card.

References (README.md), closed forms:
  - the rigid Coulomb block stops at t_s = v0 / (mu g) after D = v0^2 / (2 mu g);
  - while it slides the friction moment tilts it by phi (sharing rule), which
    lifts the centre by dz = phi a / 2 and (momentum balance m a_x = -mu F_n,
    F_n = m (g + a_z)) shortens the slide of the centre by mu dz;
  - at rest the stick springs and the tilt relax: the centre ends at
    x_rest = D - mu dz - mu m g / K_t - dz c / a, level, F_n = m g, every
    bottom node at m g / N_bottom (the shares of equal penetrations).
Variants: the 8-node box on /SURF/PLANE (case.rad), the bottom face meshed
into 25 x 16 = 400 quadrilaterals on /SURF/PLANE, and that box on a fixed
meshed /SURF/SEG floor (node to segment both ways).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
import meshbox  # noqa: E402

A, B, C = 0.2, 0.12, 0.08        # box [m]
M = 15.0                         # [kg]
K, ZETA, MU, G = 1.0e6, 0.7, 0.3, 9.81
V0 = 1.0                         # initial speed along x [m/s]
TEND, DTOUT = 0.8, 0.01          # [s]
HOLD = 0.25                      # the hold window starts this long after the stop [s]
FLOOR = (1.0, 0.6, 8)            # meshed floor: length, width [m], quadrilaterals along x
S5_MUS, S5_VS, S5_VD = 0.5, 0.01, 0.05  # step5: mu_s at v_s [m/s], mu_d = MU beyond v_d [m/s]
GX = 0.15                        # held variant: gravity's component along -x [g] (< mu)
S5_FMAX = 20.0                   # step5 cap of the capped variant [N]
S5_TEND, S5_FIT = 0.3, 0.1       # step5 run [s] (the box still above v_d), fit from [s]


def deck(nx, ny, floor, step5=False, fmax=None, gx=0.0):
    """The box with its bottom face in nx x ny quadrilaterals on a plane
    (floor = None) or on a fixed meshed floor (floor = (L, W, n)); step5:
    the power-law contact with step5 friction instead of TYPE6."""
    p0 = M * G / K
    z0 = -p0
    d = Deck(f"box {nx}x{ny} sliding to rest on a {'plane' if floor is None else 'meshed floor'}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    meshbox.add_box(d, nx, ny, A, B, C, M, z0)
    if floor is None:
        d.plane(40, (0, 0, 0), (0, 0, 1), title="floor")
    else:
        meshbox.add_floor(d, *floor, x0=-0.3)
    if step5:
        d.power(1, 30, 40, k=K, m1=1.0, c=2 * ZETA * math.sqrt(K * M), m2=1.0, m3=0.0, irdf=2, mus=S5_MUS, vs=S5_VS,
                mud=MU, vd=S5_VD, fmax=fmax, title="box on the floor, step5 friction")
    else:
        d.type6(1, 30, 40, 1, visc=2 * ZETA * math.sqrt(K * M), fric=MU, title="box on the floor")
    d.inivel(1, (V0, 0.0, 0.0), 7)
    d.grav(1, "Z", -G)
    if gx:
        d.grav(2, "X", -gx * G)
    d.run(S5_TEND if step5 else TEND, DTOUT)
    return d


def quat_rotate(q, v):
    w, x, y, z = q
    u = np.array([x, y, z])
    v = np.asarray(v, dtype=float)
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def variant(name, nx, ny, floor, r):
    D = V0 * V0 / (2 * MU * G)
    ts_ref = V0 / (MU * G)
    p0 = M * G / K
    x2 = A * A * (nx + 2) / (12.0 * nx)   # mean of x_j^2 over the bottom nodes
    phi = MU * C * p0 / (2 * x2 + MU * C * A / 2)
    dz = phi * A / 2
    flim = MU * M * G
    x_stop_ref = D - MU * dz
    x_rest_ref = D - MU * dz - flim / K - dz * C / A
    n_ev = len(r.ev_t)
    rcval.check(f"seg_box_slide_stop.{name}.run", r.attrs.get("status") == "complete" and n_ev < 100,
                f"status '{r.attrs.get('status')}', {n_ev} events (< 100: no accumulation), kinds "
                f"{sorted(set(r.ev_kind))}, {r.attrs.get('stats_steps')} steps")
    sticks = r.events("fric_stick")
    if len(sticks) == 0:
        rcval.check(f"seg_box_slide_stop.{name}.stop_time", False, "no fric_stick event")
        return
    ts = float(sticks[0])
    e = rcval.rel(ts, ts_ref)
    rcval.check(f"seg_box_slide_stop.{name}.stop_time", e < 1e-6,
                f"first fric_stick at {ts:.10f} s, v0 / (mu g) = {ts_ref:.10f} s, rel. error {e:.2e} (< 1e-6)")
    k = r.state_at(ts)
    xs = float(r.pos[k, 0, 0])
    e_raw = rcval.rel(xs, D)
    e = abs(xs - x_stop_ref) / D
    rcval.check(f"seg_box_slide_stop.{name}.stop_distance", e < 1e-6 and e_raw < 2e-4,
                f"centre at the stop {xs:.9f} m; v0^2 / (2 mu g) = {D:.9f} m (rel. {e_raw:.2e} < 2e-4), less mu dz "
                f"(tilt phi = {phi:.4e} rad, dz = {dz:.4e} m): {x_stop_ref:.9f} m, error {e:.2e} of D (< 1e-6)")
    xe = float(r.pos[-1, 0, 0])
    e = abs(xe - x_rest_ref) / D
    rcval.check(f"seg_box_slide_stop.{name}.rest_position", e < 2e-5,
                f"centre at rest ({r.t[-1]:g} s) {xe:.9f} m, D - mu dz - mu m g / K_t - dz c / a = {x_rest_ref:.9f} m, "
                f"error {e:.2e} of D (< 2e-5: as the box untilts at the stop the shrinking shares scale their node springs down, shortening the creep back mu m g / K_t by a few percent: theory 2.7)")
    hold = r.t >= ts + HOLD
    vmax = float(np.max(np.linalg.norm(r.vel[hold, 0], axis=1)))
    drift = float(np.max(np.linalg.norm(r.pos[hold, 0] - r.pos[-1, 0], axis=1)))
    rcval.check(f"seg_box_slide_stop.{name}.hold", vmax < 1e-6 and drift < 1e-8,
                f"over [{ts + HOLD:.3f}, {TEND:g}] s: max |v| = {vmax:.1e} m/s (< 1e-6), max |x - x_end| = {drift:.1e} m "
                f"(< 1e-8): no drift")
    fn = float(r.fn[-1, 0])
    ft = float(np.linalg.norm(r.ffric[-1, 0]))
    e = rcval.rel(fn, M * G)
    rcval.check(f"seg_box_slide_stop.{name}.normal_force", e < 1e-6 and ft < 1e-6 * M * G,
                f"F_n at rest {fn:.9f} N, m g = {M * G:.9f} N, rel. error {e:.2e} (< 1e-6); |F_t| = {ft:.1e} N "
                f"(< 1e-6 m g)")
    if floor is None:
        # bottom nodes' depths from the final pose; forces F p_j / sum p
        q = np.array(r.quat[-1, 0])
        depths = []
        for i in range(nx + 1):
            for j in range(ny + 1):
                b = np.array([-A / 2 + A * i / nx, -B / 2 + B * j / ny, -C / 2])
                depths.append(-(r.pos[-1, 0] + quat_rotate(q, b))[2])
        depths = np.array(depths)
        pen = depths[depths > 0]
        nb = (nx + 1) * (ny + 1)
        forces = fn * pen / pen.sum()
        e = float(np.max(np.abs(forces - M * G / nb)) / (M * G / nb)) if len(pen) == nb else float("inf")
        rcval.check(f"seg_box_slide_stop.{name}.node_forces", len(pen) == nb and e < 1e-5,
                    f"{len(pen)} of {nb} bottom nodes past the floor, forces in [{forces.min():.9g}, {forces.max():.9g}] N, "
                    f"m g / {nb} = {M * G / nb:.9g} N, max rel. error {e:.2e} (< 1e-5)")
    rcval.check_ledger(f"seg_box_slide_stop.{name}.ledger", r, 1e-6)


def result(path):
    r = rcval.Result(path)
    from netCDF4 import Dataset
    with Dataset(path) as nc:
        r.quat = np.array(nc["body_quaternion"][:])
    return r


def step5_variant(r):
    """Beyond v_d every node's law is mu_d w_j F_n against its sliding: the
    box decelerates at mu_d g (closed form), |F_t| = mu_d F_n."""
    name = "step5"
    n_ev = len(r.ev_t)
    rcval.check(f"seg_box_slide_stop.{name}.run", r.attrs.get("status") == "complete" and n_ev < 100,
                f"status '{r.attrs.get('status')}', {n_ev} events, {r.attrs.get('stats_steps')} steps")
    sl = r.t >= S5_FIT
    cf = np.polyfit(r.t[sl], r.pos[sl, 0, 0], 2)
    a = -2 * cf[0]
    resid = float(np.max(np.abs(r.pos[sl, 0, 0] - np.polyval(cf, r.t[sl]))))
    e = rcval.rel(a, MU * G)
    vmin = float(np.min(r.vel[sl, 0, 0]))
    rcval.check(f"seg_box_slide_stop.{name}.deceleration", e < 1e-6 and resid < 1e-8 and vmin > S5_VD,
                f"442 bottom nodes, step5 per node: quadratic fit of x over [{S5_FIT:g}, {S5_TEND:g}] s: deceleration "
                f"{a:.9f} m/s^2, mu_d g = {MU * G:.9f}, rel. error {e:.2e} (< 1e-6), max residual {resid:.1e} m "
                f"(< 1e-8); v >= {vmin:.3f} m/s > v_d")
    ratio = np.linalg.norm(r.ffric[sl, 0], axis=1) / r.fn[sl, 0]
    e = float(np.max(np.abs(ratio - MU)))
    rcval.check(f"seg_box_slide_stop.{name}.friction", e < 1e-6,
                f"|F_t| / F_n over [{S5_FIT:g}, {S5_TEND:g}] s in [{ratio.min():.9f}, {ratio.max():.9f}], mu_d = {MU:g} "
                f"(the node laws mu_d w_j F_n add up to mu_d F_n), max error {e:.1e} (< 1e-6)")
    rcval.check_ledger(f"seg_box_slide_stop.{name}.ledger", r, 1e-6)


def step5_cap_variant(r):
    """Every node capped at w_j f_max: the caps add up to f_max, the box
    decelerates at f_max / m (closed form)."""
    name = "step5_cap"
    rcval.check(f"seg_box_slide_stop.{name}.run", r.attrs.get("status") == "complete" and len(r.ev_t) < 100,
                f"status '{r.attrs.get('status')}', {len(r.ev_t)} events {sorted(set(r.ev_kind))}")
    sl = r.t >= S5_FIT
    cf = np.polyfit(r.t[sl], r.pos[sl, 0, 0], 2)
    a = -2 * cf[0]
    resid = float(np.max(np.abs(r.pos[sl, 0, 0] - np.polyval(cf, r.t[sl]))))
    e = rcval.rel(a, S5_FMAX / M)
    ft = np.linalg.norm(r.ffric[sl, 0], axis=1)
    ef = float(np.max(np.abs(ft - S5_FMAX))) / S5_FMAX
    rcval.check(f"seg_box_slide_stop.{name}.deceleration", e < 1e-6 and resid < 1e-8 and ef < 1e-9,
                f"f_max = {S5_FMAX:g} N < mu_d m g: deceleration {a:.9f} m/s^2, f_max / m = {S5_FMAX / M:.9f}, rel. error "
                f"{e:.2e} (< 1e-6), max residual {resid:.1e} m (< 1e-8); |F_t| = f_max to {ef:.1e} (< 1e-9)")


def held_variant(r):
    """Gravity with a component s g along -x (an incline in its own frame):
    the box decelerates at (s + mu) g, stops at v0 / ((s + mu) g) and, s < mu,
    stays: the stick springs hold m g s."""
    name = "held"
    rcval.check(f"seg_box_slide_stop.{name}.run", r.attrs.get("status") == "complete" and len(r.ev_t) < 100,
                f"status '{r.attrs.get('status')}', {len(r.ev_t)} events {sorted(set(r.ev_kind))}")
    sticks = r.events("fric_stick")
    ts_ref = V0 / ((GX + MU) * G)
    ts = float(sticks[0]) if len(sticks) else float("nan")
    e = rcval.rel(ts, ts_ref)
    rcval.check(f"seg_box_slide_stop.{name}.stop_time", e < 1e-6,
                f"442 bottom nodes: first fric_stick at {ts:.10f} s, v0 / ((s + mu) g) = {ts_ref:.10f} s, rel. error "
                f"{e:.2e} (< 1e-6)")
    hold = r.t >= ts + HOLD
    vmax = float(np.max(np.linalg.norm(r.vel[hold, 0], axis=1)))
    drift = float(np.max(np.linalg.norm(r.pos[hold, 0] - r.pos[-1, 0], axis=1)))
    ft = r.ffric[-1, 0]
    e = float(np.linalg.norm(ft - np.array([GX * M * G, 0.0, 0.0]))) / (GX * M * G)
    rcval.check(f"seg_box_slide_stop.{name}.hold", vmax < 1e-6 and drift < 1e-8 and e < 1e-6,
                f"over [{ts + HOLD:.3f}, {TEND:g}] s: max |v| = {vmax:.1e} m/s (< 1e-6), max |x - x_end| = {drift:.1e} m "
                f"(< 1e-8); friction at rest ({ft[0]:.9f}, {ft[1]:.1e}, {ft[2]:.1e}) N, m g s = {GX * M * G:.9f} N along "
                f"+x, rel. error {e:.2e} (< 1e-6)")


def main():
    runs = [("corners", 1, 1, None, None), ("meshed", 25, 16, None, "meshed"),
            ("meshed_floor", 25, 16, FLOOR, "meshed_floor")]
    for name, nx, ny, floor, tag in runs:
        try:
            path = rcval.run_case() if tag is None else \
                rcval.run(deck(nx, ny, floor), name=tag)
        except RuntimeError as err:
            rcval.check(f"seg_box_slide_stop.{name}.run", False, str(err))
            continue
        variant(name, nx, ny, floor, result(path))
    try:
        held_variant(result(rcval.run(deck(25, 16, None, gx=GX), name="held")))
    except RuntimeError as err:
        rcval.check("seg_box_slide_stop.held.run", False, str(err))
    try:
        step5_variant(result(rcval.run(deck(25, 16, None, step5=True), name="step5")))
    except RuntimeError as err:
        rcval.check("seg_box_slide_stop.step5.run", False, str(err))
    try:
        step5_cap_variant(result(rcval.run(deck(25, 16, None, step5=True, fmax=S5_FMAX), name="step5_cap")))
    except RuntimeError as err:
        rcval.check("seg_box_slide_stop.step5_cap.run", False, str(err))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(1, 1, None))
