"""Static analysis (/SOLVER Method 3) with joints: a lever on a revolute
joint held by the joint's stop, a slider on a prismatic joint held by a
spring, and a lever on a revolute joint resting on a contact.

case.rad: a lever (mass M = 2 kg, centre of mass C = 0.4 m from its
pivot) on a /JOINT/REVOLUTE to the ground about z, horizontal at t = 0 on
its lower stop (Lim_min = 0, K_lim = KS = 50 N m/rad: a torsional spring
as soon as it turns down); beside it a slider (MS = 1.5 kg) on a
/JOINT/PRISMATIC to the ground along an axis at ALPHA = 0.5 rad in the
x-y plane, held along it by a spring (KP = 400 N/m, relaxed at t = 0);
gravity -y times f(t) = t / t_end. Closed forms at each output time, with
phi the lever's angle below the horizontal and s the slider's travel down
the axis:

    KS phi = M g f C cos(phi)                   (phi: a scalar root)
    joint force on the lever  (0, M g f, 0);  joint_stop_moment KS phi
    s = MS g f sin(ALPHA) / KP
    joint force on the slider MS g f cos(ALPHA) (-sin(ALPHA), cos(ALPHA), 0)

case_contact.rad: the lever alone (no stop), a sphere of radius R at its
tip (x = L) touching the floor y = -R at t = 0 (a linear TYPE6 contact,
k = 1e5 N/m, no friction). The contact force and the weight are both
vertical, so the moments about the pivot give at any angle

    N = M g f C / L,  P = N / k,  sin(theta) = -P / L,
    joint force on the lever (0, M g f (1 - C / L), 0).

case_preload.rad: case_contact under constant gravity on the IDA path
(Method 2) with /SOLVER Preload 1: the dynamic run starts from the static
equilibrium at rest and stays there.

The decks keep their /SOLVER card in every mode of scripts/check.sh (the
method is the point); in the 'ida' mode the static decks run with
--method static (as validation/static_column), and case_preload.rad on IDA
(its deck's Method 2) in every mode.
"""
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G = 9.81
T_END, DT_OUT = 1.0, 0.1
M, L, C = 2.0, 0.8, 0.4            # lever: mass [kg], length [m], pivot to centre of mass [m]
J_LEVER = (1e-3, M * L * L / 12.0, M * L * L / 12.0)  # [kg m^2], about its centre of mass
KS = 50.0                          # the stop's stiffness [N m/rad]
MS, ALPHA, KP = 1.5, 0.5, 400.0    # slider: mass [kg], axis angle [rad], spring [N/m]
XS = 2.0                           # slider's position [m]
R, K = 0.05, 1.0e5                 # tip sphere radius [m], contact stiffness [N/m]
TOL = 1e-9


def lever(d, body=1, node=1):
    d.rbody(body, node, M, J_LEVER, grnod=body, title="lever")


def deck():
    d = Deck("static joints: a lever on its revolute stop, a slider on a prismatic joint and a spring")
    d.funct(2, [0.0, T_END], [0.0, 1.0], title="gravity ramp f(t) = t / t_end")
    d.nodes([(1, C, 0.0, 0.0), (2, XS, 0.0, 0.0)])
    lever(d)
    d.rbody(2, 2, MS, (0.01, 0.01, 0.01), grnod=2, title="slider")
    d.grnod(1, [1], title="lever")
    d.grnod(2, [2], title="slider")
    d.grav_fct(1, "Y", -G, 2)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), lim_min=0.0, lim_max=1.0, k_lim=KS,
            title="pivot, lower stop at the horizontal")
    ax = (np.cos(ALPHA), np.sin(ALPHA), 0.0)
    d.joint(2, "PRISMATIC", 2, 0, (XS, 0.0, 0.0), axis=ax, title="slider along the inclined axis")
    d.spring(3, 2, (XS, 0.0, 0.0), 0, (XS + ax[0], ax[1], 0.0), iform=1, x0=1.0, a=KP, title="slider's spring")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def deck_contact(method=3, preload=0, ramp=True):
    d = Deck("static joints: a lever on a revolute joint resting on a contact at its tip")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    if ramp:
        d.funct(2, [0.0, T_END], [0.0, 1.0], title="gravity ramp f(t) = t / t_end")
    d.nodes([(1, C, 0.0, 0.0)])
    lever(d)
    d.grnod(1, [1], title="lever")
    d.sphere(1, 1, (L, 0.0, 0.0), R, title="tip sphere")
    d.plane(2, (0.0, -R, 0.0), (0.0, 1.0, 0.0), title="floor y = -R")
    if ramp:
        d.grav_fct(1, "Y", -G, 2)
    else:
        d.grav(1, "Y", -G)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), title="pivot")
    d.type6(1, 1, 2, 1, title="tip - floor")
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
        return (np.array(nc["joint_force"][:]), np.array(nc["joint_stop_moment"][:]),
                np.array(nc["joint_drift_position"][:]), np.array(nc["joint_drift_angle"][:]),
                [str(x) for x in nc.variables["joint_type"][:]] if "joint_type" in nc.variables else [])


def angle_z(q):
    """The rotation angle about z of unit quaternions (w, x, y, z) that turn about z."""
    return 2.0 * np.arctan2(q[..., 3], q[..., 0])


def main():
    rcval.METHOD = "static" if rcval.METHOD else ""   # the 'ida' mode: static all the same (docstring)
    # ---- the lever on its stop and the slider --------------------------------
    path = rcval.run_case(keep_solver=True)
    r = rcval.Result(path)
    jf, jsm, jdp, jda, _ = jvars(path)
    f = r.t / T_END
    rcval.check("static_joints.output_times", len(r.t) == 11 and np.allclose(r.t, np.arange(11) * DT_OUT, atol=1e-12),
                f"{len(r.t)} records at {', '.join(f'{x:g}' for x in r.t)} s (expected 0, 0.1, ..., 1)")
    phi_ref = np.array([0.0 if x == 0 else brentq(lambda p: KS * p - M * G * x * C * np.cos(p), 0.0, 1.0, xtol=1e-15,
                                                       rtol=1e-15) for x in f])
    phi = -angle_z(r.quat[:, 0, :])
    e_phi = float(np.abs(phi - phi_ref).max() / phi_ref[-1])
    rcval.check("static_joints.lever_angle", e_phi < TOL,
                f"lever's angle below the horizontal against the root of K phi = M g f C cos(phi): max error "
                f"{e_phi:.2e} of phi(t_end) = {phi_ref[-1]:.12f} rad (< {TOL:g}); at t_end {phi[-1]:.12f} rad")
    # its centre of mass on the circle about the pivot (the joint holds it)
    pc = r.pos[:, 0, :]
    e_pos = float(np.abs(pc - C * np.stack([np.cos(phi_ref), -np.sin(phi_ref), 0 * phi_ref], axis=1)).max() / C)
    rcval.check("static_joints.lever_position", e_pos < TOL,
                f"lever's centre of mass against C (cos phi, -sin phi, 0): max error {e_pos:.2e} of C (< {TOL:g})")
    W = M * G * f
    e_jf = float(np.abs(jf[:, 0, :] - np.stack([0 * W, W, 0 * W], axis=1)).max() / (M * G))
    e_st = float(np.abs(jsm[:, 0] - KS * phi_ref).max() / (M * G * C))
    rcval.check("static_joints.lever_reaction", max(e_jf, e_st) < TOL,
                f"pivot's force on the lever against (0, M g f, 0): max error {e_jf:.2e} of M g; the stop's moment "
                f"against K phi: {e_st:.2e} of M g C (< {TOL:g}); at t_end {jf[-1, 0, 1]:.12f} N, {jsm[-1, 0]:.12f} N m")
    s_ref = MS * G * f * np.sin(ALPHA) / KP
    ps = r.pos[:, 1, :]
    want = np.stack([XS - s_ref * np.cos(ALPHA), -s_ref * np.sin(ALPHA), 0 * s_ref], axis=1)
    e_s = float(np.abs(ps - want).max() / s_ref[-1])
    Fn = MS * G * f * np.cos(ALPHA)
    wantf = np.stack([-Fn * np.sin(ALPHA), Fn * np.cos(ALPHA), 0 * Fn], axis=1)
    e_sf = float(np.abs(jf[:, 1, :] - wantf).max() / (MS * G))
    rcval.check("static_joints.slider", max(e_s, e_sf) < TOL,
                f"slider's position against s = MS g f sin(alpha) / KP down the axis: max error {e_s:.2e} of s(t_end) "
                f"= {s_ref[-1]:.12e} m; the prismatic joint's force against MS g f cos(alpha) (-sin, cos, 0): "
                f"{e_sf:.2e} of MS g (< {TOL:g})")
    drift = float(max(jdp.max(), jda.max()))
    rcval.check("static_joints.drift", drift < 1e-11,
                f"largest joint drift (position [m], angle [-]) over the records {drift:.2e} (< 1e-11: the rows' "
                f"tolerance, 1e-11 of the bodies' radius of gyration)")
    ev = [(round(float(t), 9), k) for t, k in zip(r.ev_t, r.ev_kind)] if hasattr(r, "ev_t") else []
    rcval.check("static_joints.stop_event", [k for _, k in ev] == ["stop_enter"],
                f"events {ev} (expected one stop_enter at the start: the lever touches its stop)")
    # ---- the lever on a contact ----------------------------------------------
    path = rcval.run_case("case_contact.rad", keep_solver=True)
    r = rcval.Result(path)
    jf, _, jdp, jda, _ = jvars(path)
    f = r.t / T_END
    N = M * G * f * C / L
    P = N / K
    th_ref = -np.arcsin(P / L)
    th = angle_z(r.quat[:, 0, :])
    e_th = float(np.abs(th - th_ref).max() / abs(th_ref[-1]))
    e_N = float(np.abs(r.fn[:, 0] - N).max() / (M * G))
    e_P = float(np.abs(r.pen[:, 0] - P).max() / P[-1])
    rcval.check("static_joints.contact_lever", max(e_th, e_N, e_P) < TOL,
                f"lever on the floor: angle against -asin(P / L) max error {e_th:.2e} of theta(t_end) = "
                f"{th_ref[-1]:.12e} rad, contact force against M g f C / L {e_N:.2e} of M g, penetration against "
                f"N / k {e_P:.2e} of P(t_end) (< {TOL:g})")
    Wj = M * G * f * (1.0 - C / L)
    e_jf = float(np.abs(jf[:, 0, :] - np.stack([0 * Wj, Wj, 0 * Wj], axis=1)).max() / (M * G))
    rcval.check("static_joints.contact_reaction", e_jf < TOL,
                f"pivot's force on the lever against (0, M g f (1 - C/L), 0): max error {e_jf:.2e} of M g "
                f"(< {TOL:g}); at t_end {jf[-1, 0, 1]:.12f} N")
    # ---- preloaded, on IDA: at rest ----------------------------------------------
    rcval.METHOD = ""                                 # its deck's Method 2 (IDA) in every mode
    path = rcval.run_case("case_preload.rad", keep_solver=True)
    r = rcval.Result(path)
    with Dataset(path) as nc:
        pre = str(getattr(nc, "preload", ""))
        omega = np.array(nc["body_angular_velocity"][:])
    vmax = float(max(np.abs(r.vel).max(), np.abs(omega).max() * L))
    N1 = M * G * C / L
    e_N = float(np.abs(r.fn[:, 0] - N1).max() / (M * G))
    rcval.check("static_joints.preload", pre.startswith("static equilibrium") and vmax < 1e-9 and e_N < 1e-6,
                f"preloaded on IDA, {len(r.t)} records to {r.t[-1]:g} s: preload attribute {pre[:40]!r}..., max |v| (and "
                f"|omega| L) {vmax:.2e} m/s (< 1e-9), contact force against M g C / L {e_N:.2e} of M g (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_contact.rad": deck_contact(),
                               "case_preload.rad": deck_contact(method=2, preload=1, ramp=False)})
