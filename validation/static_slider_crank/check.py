"""Static analysis (/SOLVER Method 3) of a slider-crank: the crank held by
its revolute joint's stop (a torsional spring) against a load on the slider,
the equilibrium crank angle and every joint reaction against the closed-form
torque balance (virtual work).

case.rad: the geometry of validation/joint_slider_crank (crank radius
R = 0.2 m, connecting rod L = 0.6 m, slider MS = 0.8 kg, the crank at
PHI0 = 60 deg from the slide line at t = 0). The crank (MC = 1 kg) turns
on a /JOINT/REVOLUTE about z at the origin, on the upper stop of its joint
coordinate (Lim_max = 0, K_lim = KS: a torsional spring as soon as the crank
turns forward); the connecting rod is a massless rigid link, a
/JOINT/DISTANCE of length L between the crank pin and the slider's centre
(a pin at each end: a two-force member); the slider slides along x on a
/JOINT/PRISMATIC to the ground. An acceleration field along -x on the
slider alone (/GRAV on its node group, A = 100 m/s^2 times f(t) = t / t_end)
pushes it towards the crank with the force W = MS A f.

With phi the crank angle and x(phi) = R cos(phi) + sqrt(L^2 - R^2 sin^2(phi))
the slider's position, virtual work gives the balance of the moments on the
crank (the stop's moment KS (phi - PHI0) against the load's W (-dx/dphi)):

    KS (phi - PHI0) = W R sin(phi) (1 + R cos(phi) / sqrt(L^2 - R^2 sin^2(phi)))

(a scalar root), and the reactions follow from the slider's balance: the
rod's force T along e = (P - S) / L (P the crank pin, S the slider) with
T e_x = W, the prismatic joint's force on the slider -T e_y along y, the
revolute joint's force on the crank T e, the rod's force on the crank -T e.

case_preload.rad: the same under a constant field (f = 1) on the IDA path
(Method 2) with /SOLVER Preload 1: the dynamic run starts from the static
equilibrium at rest and stays there.

Modes of scripts/check.sh: at the deck's settings the static deck runs as
written (Method 3); at the defaults its /SOLVER card is removed and it runs
with --method static (the static analysis at ricochet's default settings);
in the 'ida' mode it runs with --method static at the deck's settings and
case_preload.rad on IDA (its deck's Method 2, every mode).
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

R, L = 0.2, 0.6                    # crank radius, rod length [m]
MC, MS = 1.0, 0.8                  # crank, slider masses [kg]
J_CRANK = (2e-3, 2e-3, 4e-3)       # [kg m^2] about its centre of mass
J_SLIDER = (1e-3, 1e-3, 1e-3)
PHI0 = math.radians(60.0)          # crank angle at t = 0 [rad]
A = 100.0                          # the field on the slider [m/s^2] (along -x)
KS = 50.0                          # the crank stop's stiffness [N m/rad]
T_END, DT_OUT = 1.0, 0.1
TOL = 1e-9


def slider_x(phi):
    return R * np.cos(phi) + np.sqrt(L**2 - (R * np.sin(phi)) ** 2)


def load_moment(phi, w):
    """The load's moment on the crank about z [N m]: W (-dx/dphi)."""
    return w * R * np.sin(phi) * (1.0 + R * np.cos(phi) / np.sqrt(L**2 - (R * np.sin(phi)) ** 2))


def deck(method=3, preload=0):
    p = (R * math.cos(PHI0), R * math.sin(PHI0))
    s = float(slider_x(PHI0))
    d = Deck("static slider-crank: the crank's stop against a load on the slider")
    if not preload:
        d.funct(2, [0.0, T_END], [0.0, 1.0], title="load ramp f(t) = t / t_end")
    d.nodes([(1, p[0] / 2, p[1] / 2, 0.0), (3, s, 0.0, 0.0)])
    d.rbody(1, 1, MC, J_CRANK, grnod=1, title="crank")
    d.rbody(3, 3, MS, J_SLIDER, grnod=3, title="slider")
    d.grnod(1, [1], title="crank")
    d.grnod(3, [3], title="slider")
    if preload:
        d.grav(1, "X", -A, grnod=3)
    else:
        d.grav_fct(1, "X", -A, 2, grnod=3)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), lim_min=-1.0, lim_max=0.0, k_lim=KS,
            title="crank bearing, its upper stop at phi0")
    d.joint(2, "DISTANCE", 1, 3, (p[0], p[1], 0.0), p2=(s, 0.0, 0.0), title="connecting rod (massless link)")
    d.joint(4, "PRISMATIC", 3, 0, (s, 0.0, 0.0), axis=(1.0, 0.0, 0.0), title="slide along x")
    if preload:
        d.run(0.2, 0.01)
        d.solver(method=method, preload=1, rtol=1e-8, atol_pos=1e-12, atol_quat=1e-12, atol_vel=1e-10,
                 atol_omega=1e-10)
    else:
        d.run(T_END, DT_OUT)
        d.solver(method=method)
    return d


def jvars(path):
    with Dataset(path) as nc:
        return (np.array(nc["joint_force"][:]), np.array(nc["joint_moment"][:]),
                np.array(nc["joint_stop_moment"][:]), np.array(nc["joint_drift_position"][:]),
                np.array(nc["joint_drift_angle"][:]))


def reference(f):
    """phi, the slider's x, the rod's force T and its direction e at the load levels f."""
    w = MS * A * f
    phi = np.array([PHI0 if x == 0 else brentq(lambda q: KS * (q - PHI0) - load_moment(q, MS * A * x), PHI0,
                                                PHI0 + 1.5, xtol=1e-15, rtol=1e-15) for x in f])
    xs = slider_x(phi)
    e = np.stack([R * np.cos(phi) - xs, R * np.sin(phi), 0 * phi], axis=1) / L
    T = w / e[:, 0]
    return phi, xs, T, e, w


def main():
    mode = "defaults" if rcval.DEFAULTS else ("ida" if rcval.METHOD else "deck")
    # the deck's Method 3 as written; the defaults: no /SOLVER, --method static; 'ida': --method static
    rcval.METHOD = "static" if mode != "deck" else ""
    path = rcval.run_case(keep_solver=(mode != "defaults"))
    r = rcval.Result(path)
    jf, jm, jsm, jdp, jda = jvars(path)
    f = r.t / T_END
    rcval.check("static_slider_crank.output_times",
                len(r.t) == 11 and np.allclose(r.t, np.arange(11) * DT_OUT, atol=1e-12),
                f"{len(r.t)} records at {', '.join(f'{x:g}' for x in r.t)} s (expected 0, 0.1, ..., 1)")
    phi_ref, x_ref, T, e, w = reference(f)
    crank = r.pos[:, 0, :]
    phi_q = 2.0 * np.arctan2(r.quat[:, 0, 3], r.quat[:, 0, 0]) + PHI0    # the crank's turn about z
    dphi = phi_ref[-1] - PHI0
    e_phi = float(np.abs(phi_q - phi_ref).max() / dphi)
    e_c = float(np.abs(crank - 0.5 * R * np.stack([np.cos(phi_ref), np.sin(phi_ref), 0 * f], axis=1)).max() / R)
    rcval.check("static_slider_crank.crank_angle", max(e_phi, e_c) < TOL,
                f"crank angle against the root of KS (phi - phi0) = W R sin(phi) (1 + R cos(phi) / sqrt(L^2 - "
                f"R^2 sin^2 phi)): max error {e_phi:.2e} of its turn phi(t_end) - phi0 = {dphi:.12f} rad (< {TOL:g}); "
                f"crank's centre against (R/2)(cos, sin, 0): {e_c:.2e} of R; phi(t_end) = {phi_q[-1]:.12f} rad")
    slider = r.pos[:, 1, :]
    e_x = float(np.abs(slider - np.stack([x_ref, 0 * f, 0 * f], axis=1)).max() / R)
    rcval.check("static_slider_crank.slider_position", e_x < TOL,
                f"slider against (x(phi), 0, 0): max error {e_x:.2e} of R (< {TOL:g}); x(t_end) = {slider[-1, 0]:.12f} m")
    m_load = load_moment(phi_ref, w)
    scale_m = MS * A * R
    # joint_stop_moment: the stop's moment on the crank about +z, back from the upper stop: negative
    e_st = float(np.abs(-jsm[:, 0] - KS * (phi_ref - PHI0)).max() / scale_m)
    e_vw = float(np.abs(-jsm[:, 0] - m_load).max() / scale_m)
    rcval.check("static_slider_crank.stop_moment", max(e_st, e_vw) < TOL,
                f"crank stop's moment (-joint_stop_moment) against KS (phi - phi0): max error {e_st:.2e}, against the load's W (-dx/dphi) "
                f"(virtual work): {e_vw:.2e} of MS A R = {scale_m:g} N m (< {TOL:g}); at t_end {jsm[-1, 0]:.12f} N m")
    scale_f = MS * A
    rod = T[:, None] * e
    # joint 1 (revolute, on the crank): T e; joint 2 (the rod, on the crank, its first body): -T e;
    # joint 4 (prismatic, on the slider): (0, -T e_y, 0), no moment about z (the rod acts at the slider's centre)
    want_prism = np.stack([0 * f, -rod[:, 1], 0 * f], axis=1)
    errs = {"revolute": float(np.abs(jf[:, 0, :] - rod).max() / scale_f),
            "rod": float(np.abs(jf[:, 1, :] + rod).max() / scale_f),
            "prismatic": float(np.abs(jf[:, 2, :] - want_prism).max() / scale_f),
            "prismatic moment": float(np.abs(jm[:, 2, :]).max() / scale_m),
            "revolute moment": float(np.abs(jm[:, 0, :]).max() / scale_m)}
    rcval.check("static_slider_crank.reactions", max(errs.values()) < TOL,
                f"reactions against the slider's balance T e_x = W: max error {max(errs.values()):.2e} of MS A = "
                f"{scale_f:g} N (forces) or MS A R (moments) (< {TOL:g}); " +
                ", ".join(f"{k} {v:.2e}" for k, v in errs.items()) +
                f"; rod force T(t_end) = {T[-1]:.9f} N (compression), measured {float(np.dot(-jf[-1, 1, :], e[-1])):.9f} N")
    drift = float(max(jdp.max(), jda.max()))
    rcval.check("static_slider_crank.drift", drift < 1e-11,
                f"largest joint drift (position [m], angle [-]) over the records {drift:.2e} (< 1e-11)")
    ev = [(round(float(t), 9), k) for t, k in zip(r.ev_t, r.ev_kind)]
    rcval.check("static_slider_crank.stop_event", [k for _, k in ev] == ["stop_enter"],
                f"events {ev} (expected one stop_enter at the start: the crank touches its stop)")
    # ---- preloaded, on IDA: at rest ------------------------------------------
    rcval.METHOD = ""                                 # its deck's Method 2 (IDA) in every mode
    path = rcval.run_case("case_preload.rad", keep_solver=True)
    r = rcval.Result(path)
    jf, jm, jsm, _, _ = jvars(path)
    with Dataset(path) as nc:
        pre = str(getattr(nc, "preload", ""))
        omega = np.array(nc["body_angular_velocity"][:])
    vmax = float(max(np.abs(r.vel).max(), np.abs(omega).max() * R))
    phi1, x1, T1, e1, _ = reference(np.array([1.0]))
    e_st = float(np.abs(-jsm[:, 0] - KS * (phi1[0] - PHI0)).max() / scale_m)
    rcval.check("static_slider_crank.preload", pre.startswith("static equilibrium") and vmax < 1e-9 and e_st < 1e-6,
                f"preloaded on IDA, {len(r.t)} records to {r.t[-1]:g} s: preload attribute {pre[:40]!r}..., max |v| "
                f"(and |omega| R) {vmax:.2e} m/s (< 1e-9), stop moment against KS (phi - phi0) {e_st:.2e} of MS A R "
                f"(< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_preload.rad": deck(method=2, preload=1)})
