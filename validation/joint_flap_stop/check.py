"""A hinged flap falls onto a stop: revolute joint, TYPE6 contact with a restitution asked.

A rigid flap (a slender rod of mass m and length L, hinged at one end) turns
on a /JOINT/REVOLUTE (axis z) to the ground at the origin, under gravity -g
along y. Released from rest at theta0 from the downward vertical, it swings
down until a small sphere on it, at the distance r from the hinge, meets a
fixed plane (the stop) at the angle theta_s: a /INTER/TYPE6 contact with a
linear load curve k and the restitution e asked (e_target: ricochet derives
the damping). It rebounds, swings up and falls onto the stop again.

References (README.md), all independent of ricochet's output:
- first impact time: the pendulum time from theta0 to theta_s about the
  hinge, sqrt(L_eq/g) (K(k) - F(phi_s, k)), checked against SciPy's quad of
  dtheta / theta';
- impact angular velocity: energy conservation;
- derived damping: the restitution of the clipped linear contact (solve_ivp
  of the scaled oscillator up to the zero of its force) inverted for e by
  Brent, on the hinge's effective mass at the contact I_h / r^2, against the
  Visc that `ricochet check` prints;
- contact phase: SciPy's solve_ivp of the one-degree-of-freedom hinge
  equation with gravity and the clipped linear contact force, giving the
  contact time, the rebound angular velocity and the restitution achieved;
- second impact: the pendulum times up to the apex and back down
  (incomplete elliptic integrals) from the state at the end of contact;
- energy ledger and the work of the joint reaction (zero).
"""
import math
import os
import re
import subprocess
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.integrate import quad, solve_ivp
from scipy.optimize import brentq
from scipy.special import ellipkinc

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, LEN, G = 2.0, 0.6, 9.81               # rod mass [kg], length [m], gravity [m/s^2]
LC = LEN / 2.0                           # hinge to centre of mass [m]
I_CM = M * LEN * LEN / 12.0              # about the centre of mass [kg m^2]
I_H = I_CM + M * LC * LC                 # about the hinge [kg m^2]
R_ARM = math.sqrt(I_H / M)               # sphere at the radius of gyration about the hinge [m]
R_S = 0.02                               # sphere radius [m]
K_C = 1.0e6                              # linear load curve [N/m]
E_ASKED = 0.5
TH0 = math.radians(80.0)                 # release angle from the downward vertical
TH_S = math.radians(15.0)                # angle at which the sphere touches the stop
T_END, DT_OUT = 1.0, 0.001
L_EQ = I_H / (M * LC)                    # equivalent simple-pendulum length [m]

# tolerances (README.md: measured values)
TOL_T1 = 1e-7        # first impact time, relative
TOL_W1 = 1e-7        # impact angular velocity, relative
TOL_VISC = 1e-8      # derived damping, relative
TOL_TC = 1e-6        # contact time, relative
TOL_W2 = 1e-6        # rebound angular velocity, relative
TOL_E = 1e-6         # achieved restitution, absolute
TOL_T2 = 1e-6        # second impact time, relative
TOL_LEDGER = 1e-6    # energy ledger, relative to the initial potential energy scale
TOL_WORK = 1e-6      # joint work, in m g l_c
TOL_F0 = 1e-9        # hinge reaction at release, in m g


def unit(th):
    """The flap's direction at angle th from the downward vertical."""
    return (math.sin(th), -math.cos(th), 0.0)


def stop_normal():
    """The plane's normal, along the sphere's motion at theta_s (pointing
    towards the approaching sphere)."""
    return (math.cos(TH_S), math.sin(TH_S), 0.0)


def deck():
    d = Deck("hinged flap falls onto a stop: revolute joint, TYPE6 with e asked")
    u = unit(TH0)
    d.funct(1, [0.0, 1.0], [0.0, K_C], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, LC * u[0], LC * u[1], 0.0)])
    d.rbody(1, 1, M, [I_CM, I_CM, I_CM], title="flap (rod 0.6 m, 2 kg)")
    d.sphere(1, 1, (R_ARM * u[0], R_ARM * u[1], 0.0), R_S, title="striker on the flap")
    n = stop_normal()
    # the plane touches the sphere exactly at theta_s: it passes through the
    # contact point r u(theta_s) - R_s n
    us = unit(TH_S)
    pm = (R_ARM * us[0] - R_S * n[0], R_ARM * us[1] - R_S * n[1], 0.0)
    d.plane(2, pm, (pm[0] + n[0], pm[1] + n[1], 0.0), title="stop (normal from M to M1)")
    d.grav(1, "Y", -G)
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), title="hinge at the origin")
    d.type6(1, 1, 2, 1, e_target=E_ASKED, title="flap against the stop, e asked 0.5")
    d.run(T_END, DT_OUT)
    return d


# ---------------------------------------------------------------- references
def pendulum_time(th_hi, th_lo, th_top):
    """Time to swing between th_hi and th_lo (th_top >= th_hi > th_lo >= 0),
    the apex being th_top: sqrt(L/g) (F(phi_hi) - F(phi_lo)), sin(th/2) =
    k sin(phi), k = sin(th_top/2) (Landau-Lifshitz, Mechanics 11)."""
    k = math.sin(th_top / 2.0)

    def phi(th):
        return math.asin(min(1.0, math.sin(th / 2.0) / k))
    return math.sqrt(L_EQ / G) * (ellipkinc(phi(th_hi), k * k) - ellipkinc(phi(th_lo), k * k))


def omega_at(th, th_top):
    """|theta'| at th for a swing with the apex th_top (energy conservation)."""
    return math.sqrt(2.0 * M * G * LC * (math.cos(th) - math.cos(th_top)) / I_H)


def e_clipped(zeta):
    """Restitution of the linear contact that cannot pull, damping ratio zeta:
    x'' + 2 zeta x' + x = 0, x(0) = 0, x'(0) = 1, until the force x + 2 zeta x'
    vanishes (integrated here by solve_ivp, independently of the closed
    form quoted in docs/theory.md)."""
    def rhs(_, y):
        return [y[1], -2.0 * zeta * y[1] - y[0]]

    def force(_, y):
        return y[0] + 2.0 * zeta * y[1]
    force.terminal, force.direction = True, -1
    s = solve_ivp(rhs, (0.0, 50.0), [0.0, 1.0], method="DOP853", rtol=1e-13, atol=1e-15,
                  events=force, first_step=1e-6)
    return -s.y_events[0][0][1]


def contact_phase(c):
    """One degree of freedom from the touch at theta_s: I_h theta'' = -m g l_c
    sin(theta) + F r cos(theta - theta_s), F = max(0, k p + c p'), p = -r
    sin(theta - theta_s). Returns (contact time, theta, theta' at the end of
    contact (F = 0), penetration rate p' there)."""
    def pen(y):
        return -R_ARM * math.sin(y[0] - TH_S), -R_ARM * math.cos(y[0] - TH_S) * y[1]

    def rhs(_, y):
        p, pd = pen(y)
        f = max(0.0, K_C * p + c * pd)
        return [y[1], (-M * G * LC * math.sin(y[0]) + f * R_ARM * math.cos(y[0] - TH_S)) / I_H]

    def released(_, y):
        p, pd = pen(y)
        return K_C * p + c * pd
    released.terminal, released.direction = True, -1
    w1 = omega_at(TH_S, TH0)
    s = solve_ivp(rhs, (0.0, 0.1), [TH_S, -w1], method="DOP853", rtol=1e-13, atol=[1e-16, 1e-13],
                  events=released, first_step=1e-9)
    th, w = s.y_events[0][0]
    return s.t_events[0][0], th, w, pen((th, w))[1]


def ricochet_visc(case):
    """The Visc that `ricochet check` derives from e_target."""
    p = subprocess.run([rcval.RICOCHET, "check", case], capture_output=True, text=True)
    mt = re.search(r"restitution asked [0-9.eE+-]+.*?: Visc derived = ([0-9.eE+-]+)", p.stdout + p.stderr)
    return float(mt.group(1)) if mt else float("nan")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    case = os.path.join(here, "case.rad")
    # the references
    t1 = pendulum_time(TH0, TH_S, TH0)
    # quad of dtheta / |theta'| with theta = theta0 - u^2 (removes the
    # inverse square root at the release point)
    t1q, _ = quad(lambda u: 2.0 * u / omega_at(TH0 - u * u, TH0) if u > 0 else
                  2.0 / math.sqrt(M * G * LC * math.sin(TH0) / I_H * 2.0),
                  0.0, math.sqrt(TH0 - TH_S), limit=200, epsabs=0, epsrel=1e-13)
    w1 = omega_at(TH_S, TH0)
    m_eff = I_H / R_ARM ** 2                 # effective mass of the hinged flap at the sphere
    zeta = brentq(lambda z: e_clipped(z) - E_ASKED, 1e-3, 0.99, xtol=1e-14)
    c_ref = 2.0 * zeta * math.sqrt(K_C * m_eff)
    tc, th_out, w_out, pd_out = contact_phase(c_ref)
    e_ref = -pd_out / (R_ARM * w1)
    # after the contact: up to the apex and back to theta_s
    top = math.acos(math.cos(th_out) - I_H * w_out ** 2 / (2.0 * M * G * LC))
    t2 = t1 + tc + pendulum_time(top, th_out, top) + pendulum_time(top, TH_S, top)

    path = rcval.run_file(case)
    r = rcval.Result(path)
    with Dataset(path) as nc:
        omega = np.array(nc["body_angular_velocity"][:])[:, 0, 2]
        work = np.array(nc["joint_work"][:])
        force0 = np.array(nc["joint_force"][0, 0, :])
    closes = r.events("contact_close")
    i_c = r.ev_kind.index("contact_close")
    i_o = next(i for i, k in enumerate(r.ev_kind) if i > i_c and k in ("contact_open", "contact_separate"))
    t1_m, t_o = r.ev_t[i_c], r.ev_t[i_o]

    err = rcval.rel(t1_m, t1)
    rcval.check("joint_flap_stop.impact_time", err < TOL_T1 and rcval.rel(t1q, t1) < 1e-10,
                f"first contact_close at {t1_m:.10f} s; pendulum time sqrt(L/g)(K - F(phi_s)) = {t1:.10f} s "
                f"(quad {t1q:.10f} s); rel. error {err:.2e} (< {TOL_T1:g})")
    w1_m = r.ev_vn[i_c] / R_ARM
    ia = r.state_at(t1_m)
    err_w = max(rcval.rel(w1_m, w1), rcval.rel(-omega[ia], w1))
    rcval.check("joint_flap_stop.impact_speed", err_w < TOL_W1,
                f"angular velocity at impact {-omega[ia]:.10f} rad/s (normal speed / r: {w1_m:.10f}); energy "
                f"conservation {w1:.10f} rad/s; rel. error {err_w:.2e} (< {TOL_W1:g})")
    visc = ricochet_visc(case)
    err_c = rcval.rel(visc, c_ref)
    rcval.check("joint_flap_stop.derived_damping", err_c < TOL_VISC,
                f"`ricochet check` Visc derived = {visc:.9g} N s/m; clipped linear contact on I_h/r^2 = "
                f"{m_eff:.6g} kg, zeta {zeta:.9f}: {c_ref:.9g} N s/m; rel. error {err_c:.2e} (< {TOL_VISC:g})")
    tc_m = t_o - t1_m
    err_tc = rcval.rel(tc_m, tc)
    rcval.check("joint_flap_stop.contact_time", err_tc < TOL_TC,
                f"contact time {tc_m * 1e3:.7f} ms; solve_ivp of the hinge with the clipped contact "
                f"{tc * 1e3:.7f} ms; rel. error {err_tc:.2e} (< {TOL_TC:g})")
    io = r.state_at(t_o)
    err_w2 = rcval.rel(omega[io], w_out)
    rcval.check("joint_flap_stop.rebound_omega", err_w2 < TOL_W2,
                f"angular velocity at the end of contact {omega[io]:.9f} rad/s; solve_ivp {w_out:.9f} rad/s; "
                f"rel. error {err_w2:.2e} (< {TOL_W2:g})")
    e_m = -r.ev_vn[i_o] / r.ev_vn[i_c]
    err_e = abs(e_m - e_ref)
    rcval.check("joint_flap_stop.restitution", err_e < TOL_E,
                f"achieved e = {e_m:.9f} (normal speeds at contact_open / contact_close); solve_ivp with "
                f"gravity {e_ref:.9f} (asked {E_ASKED}: the weight shifts it by {e_ref - E_ASKED:+.2e}); "
                f"|error| {err_e:.2e} (< {TOL_E:g})")
    t2_m = closes[1] if len(closes) > 1 else float("nan")
    err_t2 = rcval.rel(t2_m, t2)
    rcval.check("joint_flap_stop.second_impact", err_t2 < TOL_T2,
                f"second contact_close at {t2_m:.9f} s; apex {math.degrees(top):.6f} deg, t1 + t_c + swing up "
                f"and back = {t2:.9f} s; rel. error {err_t2:.2e} (< {TOL_T2:g})")
    # the hinge reaction at release (from rest): F = m a - m g, a = l_c
    # theta'' along the tangent (cos theta0, sin theta0), theta'' = -m g l_c
    # sin(theta0) / I_h
    alpha0 = -M * G * LC * math.sin(TH0) / I_H
    f0 = np.array([M * LC * alpha0 * math.cos(TH0), M * LC * alpha0 * math.sin(TH0) + M * G, 0.0])
    err_f = np.max(np.abs(force0 - f0)) / (M * G)
    rcval.check("joint_flap_stop.reaction_at_release", err_f < TOL_F0,
                f"joint_force at t = 0 ({force0[0]:.9f}, {force0[1]:.9f}, {force0[2]:.2e}) N; m a - m g = "
                f"({f0[0]:.9f}, {f0[1]:.9f}, 0) N; max error {err_f:.2e} m g (< {TOL_F0:g})")
    et = r.energy["energy_total"]
    scale = M * G * LC
    drift = np.max(np.abs(et - et[0])) / scale
    rcval.check("joint_flap_stop.ledger", drift < TOL_LEDGER,
                f"max |E_total(t) - E_total(0)| / (m g l_c) = {drift:.2e} (< {TOL_LEDGER:g})")
    wmax = np.max(np.abs(work)) / scale
    rcval.check("joint_flap_stop.no_work", wmax < TOL_WORK,
                f"work of the hinge reaction: max |W| / (m g l_c) = {wmax:.2e} (< {TOL_WORK:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
