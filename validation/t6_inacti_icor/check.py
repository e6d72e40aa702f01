"""Initial penetration: Inacti 5 (force-free start), Inacti 0, and Icor with Iform 1.

Reference (README.md): closed forms of the damped oscillator under gravity for
Inacti 5 and Inacti 0 (sphere at rest with an initial penetration P0), and the
law of Iform 1 for Icor 1 (start on the unload curve) and Icor 0 (start on the
load curve), with the exit speeds by quadrature of the same table points.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import laws  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, G = 1.0, 0.05, 9.81
K, ZETA, P0 = 1.0e5, 0.2, 1.0e-3             # Inacti: linear spring-dashpot
C = 2.0 * ZETA * math.sqrt(K * M)
WN = math.sqrt(K / M)
WD = WN * math.sqrt(1 - ZETA**2)
PS = M * G / K                                # static deflection
TEND_SETTLE = 0.4                             # 25 decay times 1/(zeta wn)
T1 = 1e-6                                     # first record of the short runs
# Icor: the curves of validation/t6_unload_curve (F_L = A P + B P^2, F_U = C2 (P - PP)^2)
A, B, C2, PP, STIFF, P0I = 5.0e4, 2.0e7, 3.0e7, 1.0e-3, 5.0e5, 2.0e-3
XL = np.linspace(0.0, 5e-3, 26)
YL = A * XL + B * XL**2
XU = np.concatenate([[0.0], np.linspace(PP, 5e-3, 21)])
YU = np.where(XU > PP, C2 * (XU - PP) ** 2, 0.0)
TOL = 1e-6


def osc(t, p0, v0):
    """m p'' + c p' + k p = m g (p: penetration, positive down), p(0) = p0, p'(0) = v0."""
    a, b = p0 - PS, (v0 + ZETA * WN * (p0 - PS)) / WD
    e = math.exp(-ZETA * WN * t)
    p = PS + e * (a * math.cos(WD * t) + b * math.sin(WD * t))
    v = e * ((-ZETA * WN * a + WD * b) * math.cos(WD * t) + (-ZETA * WN * b - WD * a) * math.sin(WD * t))
    return p, v


def deck_inacti(inacti, tend, dtout):
    d = Deck(f"sphere at rest with an initial penetration, Inacti {inacti}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e5 N/m")
    z0 = R - P0
    add_sphere_over_plane(d, M, R, z0, title="sphere 1 kg")
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, visc=C, inacti=inacti, title="spring-dashpot, zeta 0.2")
    d.run(tend, dtout)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def deck_icor(icor, tend=0.02, dtout=5e-4):
    d = Deck(f"sphere at rest with an initial penetration, Iform 1, Icor {icor}")
    d.funct(1, XL, YL, title="load curve A P + B P^2")
    d.funct(2, XU, YU, title="unload curve C (P - PP)^2")
    z0 = R - P0I
    add_sphere_over_plane(d, M, R, z0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, iform=1, stiff=STIFF, fct_ul=2, icor=icor, title="elasto-plastic")
    # Icor 1 declares the initial penetration (a plastic overlap); Icor 0
    # starts the same overlap on the load curve, an overlap no option
    # accounts for: accepted here (/RUN On_viol 2), and reported by the
    # physics checks (docs/theory.md 13.3)
    d.run(tend, dtout, on_viol=None if icor else 2)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def f_load(p):
    return np.interp(p, XL, YL)


def f_unload(p):
    return np.interp(p, XU, YU)


def icor_reference():
    """Exit speeds: Icor 1 rides F_U from P0 down; Icor 0 leaves F_L(P0) along Stiff to F_U."""
    v1 = math.sqrt(2.0 * laws.curve_integral(f_unload, XU, 0.0, P0I) / M)
    f0 = f_load(P0I)
    ps = brentq(lambda p: f0 - STIFF * (P0I - p) - f_unload(p), P0I - f0 / STIFF, P0I, xtol=1e-16, rtol=1e-15)
    back = 0.5 * (f0 + f_unload(ps)) * (P0I - ps) + laws.curve_integral(f_unload, XU, 0.0, ps)
    return v1, math.sqrt(2.0 * back / M), ps


def main():

    # ---- Inacti 5: force-free start, settles at P0 + m g / k (case.rad)
    r = rcval.Result(rcval.run_case())
    rs = rcval.Result(rcval.run(deck_inacti(5, 10 * T1, T1)))
    a0 = rs.vel[1, 0, 2] / rs.t[1]
    p1, v1 = osc(rs.t[1], 0.0, 0.0)
    ok = r.fn[0, 0] == 0.0 and rs.fn[0, 0] == 0.0 and rcval.rel(a0, -G) < 1e-3
    rcval.check("t6_inacti_icor.inacti5_force_free_start", ok,
                f"F(0) = {r.fn[0, 0]:g} N (0); v({rs.t[1]:g} s) = {rs.vel[1, 0, 2]:.9e} m/s (closed form {-v1:.9e}); "
                f"initial acceleration v/t = {a0:.7f} m/s^2, -g = {-G} (rel. error {rcval.rel(a0, -G):.1e} < 1e-3: "
                f"the spring-dashpot takes over as t grows, c t / 2m = {C * rs.t[1] / (2 * M):.1e})")
    dev = 0.0
    for j in range(len(r.t)):
        p, v = osc(r.t[j], 0.0, 0.0)
        dev = max(dev, abs((R - P0 - p) - r.pos[j, 0, 2]) / PS, abs(-v - r.vel[j, 0, 2]) / (G / WN))
    rcval.check("t6_inacti_icor.inacti5_trajectory", dev < TOL,
                f"{len(r.t)} records against m p'' + c p' + k p = m g from p = p' = 0 (p = P_raw - P0): "
                f"max |dz| / (m g/k), |dv| / (g/wn) = {dev:.2e} (< {TOL:g})")
    praw_end = R - r.pos[-1, 0, 2]
    e = abs(praw_end - (P0 + PS)) / PS
    rcval.check("t6_inacti_icor.inacti5_settles", e < TOL and abs(r.fn[-1, 0] - M * G) < TOL * M * G,
                f"penetration at t = {r.t[-1]:g} s {praw_end:.12e} m, P0 + m g/k = {P0 + PS:.12e} m "
                f"(error / (m g/k) {e:.2e} < {TOL:g}); force {r.fn[-1, 0]:.9f} N, m g = {M * G} N")

    # ---- Inacti 0: the initial force k P0 pushes the sphere out
    r0 = rcval.Result(rcval.run(deck_inacti(0, 10 * T1, T1)))
    a0 = r0.vel[1, 0, 2] / r0.t[1]
    p1, v1 = osc(r0.t[1], P0, 0.0)
    a_ref = K * P0 / M - G
    ok = rcval.rel(r0.fn[0, 0], K * P0) < 1e-12 and rcval.rel(-r0.vel[1, 0, 2], v1) < 1e-4 and rcval.rel(a0, a_ref) < 1e-3
    rcval.check("t6_inacti_icor.inacti0_initial_force", ok,
                f"F(0) = {r0.fn[0, 0]:.9f} N, k P0 = {K * P0:.9f} N; v({r0.t[1]:g} s) = {r0.vel[1, 0, 2]:.9e} m/s, "
                f"closed form {-v1:.9e}; v/t = {a0:.5f} m/s^2, k P0/m - g = {a_ref:.5f} "
                f"(rel. error {rcval.rel(a0, a_ref):.1e} < 1e-3; the damping force grows as c a0 t)")

    # ---- Icor 1 / Icor 0 with Iform 1, no gravity
    v_u, v_l, pstar = icor_reference()
    for icor, f_ref, v_ref, what in ((1, f_unload(P0I), v_u, "F_U(P0) (unload curve)"),
                                     (0, f_load(P0I), v_l, "F_L(P0) (load curve)")):
        rr = rcval.Result(rcval.run(deck_icor(icor)))
        ok_f = rcval.rel(rr.fn[0, 0], f_ref) < 1e-12
        v_end = rr.vel[-1, 0, 2]
        e = rcval.rel(v_end, v_ref)
        rcval.check(f"t6_inacti_icor.icor{icor}_initial_force", ok_f,
                    f"F(0) = {rr.fn[0, 0]:.9f} N, {what} = {f_ref:.9f} N (F_L(P0) = {f_load(P0I):g}, F_U(P0) = {f_unload(P0I):g})")
        path = "down the unload curve from P0" if icor == 1 else \
            f"Stiff line from F_L(P0) to the unload curve (P* = {1e3 * pstar:.6f} mm), then the unload curve"
        rcval.check(f"t6_inacti_icor.icor{icor}_exit_speed", e < 1e-5,
                    f"exit speed {v_end:.10f} m/s; {path}: {v_ref:.10f} m/s; rel. error {e:.2e} (< 1e-5); "
                    "events " + ", ".join(rr.ev_kind))
        # the physics checks: Icor 1 accounts for the overlap; Icor 0's
        # overlap is reported at t = 0 (start_overlap) and nothing else
        with Dataset(rr.path) as nc:
            v = [(str(c), float(t)) for c, t in zip(nc["violation_check"][:], nc["violation_time"][:])] \
                if len(nc.dimensions["violation"]) else []
        want = [] if icor else [("start_overlap", 0.0)]
        rcval.check(f"t6_inacti_icor.icor{icor}_start_reported", v == want,
                    f"violations {v} (expected {want}: " +
                    ("Icor 1 declares the overlap)" if icor else "the overlap no option accounts for, reported)"))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck_inacti(5, TEND_SETTLE, 1e-3))
