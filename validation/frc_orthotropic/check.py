"""Orthotropic friction (/FRICTION Idir = 1, /FRIC_ORIENT): a block launched
across the directions of friction follows the elliptic, maximum-dissipation law.

A sphere with locked rotations (a "block", m = 1 kg, R = 0.05 m) at its static
penetration on the fixed floor z = 0, under gravity, launched at v0 = 1 m/s
along x. The floor's /PART carries a /FRIC_ORIENT: V = (1, sqrt 3, 0.7), whose
projection on the floor is at 60 deg from x: direction 1; mu_1 = 0.2
along it, mu_2 = 0.5 across it (Coulomb, incremental form). Reference
(README.md): independent solve_ivp of
    m dv/dt = -F_n (mu_1^2 v_1, mu_2^2 v_2) / sqrt(mu_1^2 v_1^2 + mu_2^2 v_2^2)
in the (d1, d2) frame to the stop (the path curves towards direction 1).
"""
import math
import os
import sys
import warnings

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck, line  # noqa: E402

M, R, K, G, V0 = 1.0, 0.05, 1.0e6, 9.81, 1.0
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
KT = K                               # stick stiffness: the load-curve slope
BAND = 1e-6
MU1, MU2 = 0.2, 0.5
# /FRIC_ORIENT vector V (out of the floor plane: its projection is at 60 deg
# from x) and angle PHI [deg] (0: README.md, "PHI")
VDIR, PHI = (1.0, math.sqrt(3.0), 0.7), 0.0
ANG1 = math.radians(60.0)            # direction 1 in the floor plane
D1 = np.array([math.cos(ANG1), math.sin(ANG1), 0.0])
D2 = np.cross([0.0, 0.0, 1.0], D1)   # n x d1


def reference(v0=(V0, 0.0), rtol=1e-12):
    """Rigid block, elliptic limit with maximum dissipation, from the launch.
    Returns the dense solution [x, y, v_x, v_y] (global), the stop time and point."""
    L1, L2 = MU1 * M * G, MU2 * M * G

    def rhs(t, y):
        v = y[2:4]
        v1, v2 = v @ D1[:2], v @ D2[:2]
        s = math.sqrt((L1 * v1) ** 2 + (L2 * v2) ** 2)
        f1, f2 = -L1 * L1 * v1 / s, -L2 * L2 * v2 / s
        a = (f1 * D1[:2] + f2 * D2[:2]) / M
        return [y[2], y[3], a[0], a[1]]

    def slow(t, y):  # speed 1e-9 m/s: the rest of the way is below 1e-15 m
        return math.hypot(y[2], y[3]) - 1e-9
    slow.terminal, slow.direction = True, -1
    s = solve_ivp(rhs, (0.0, 10.0), [0.0, 0.0, v0[0], v0[1]], method="DOP853", rtol=rtol, atol=1e-15,
                  dense_output=True, events=slow)
    return s.sol, s.t_events[0][0], s.y_events[0][0][:2]


def deck(iform=2, tend=0.45, rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, skew=False):
    z0 = R - M * G / K
    d = Deck("block launched on an orthotropic floor (/FRICTION Idir 1, /FRIC_ORIENT)")
    d.block_on_floor(M, R, K, G, VISC, z0, (V0, 0.0, 0.0))
    d.part(1, 1, title="block")
    d.part(2, 0, [2], title="floor (fixed surface 2)")
    d.grpart(1, [2], title="floors")
    d.friction(1, ifric=0, iform=iform, fric=0.9,
               pairs=[dict(part1=1, grpart2=1, sets=[((), MU1, None), ((), MU2, None)])],
               title="defaults 0.9 (unused); block/floor: mu_1 0.2, mu_2 0.5")
    if skew:
        # the same direction 1 from a /SKEW/FIX's X' axis: Y' = z, X' = Y' x
        # (sqrt 3, -1, 0) normalised = (1, sqrt 3, 0)/2; VX VY VZ unused
        d.add("/SKEW/FIX/5", line(("r", 0.0), ("r", 0.0), ("r", 0.0)), line(("r", 0.0), ("r", 0.0), ("r", 1.0)),
              line(("r", math.sqrt(3.0)), ("r", -1.0), ("r", 0.0)), title="X' at 60 deg from x in the floor")
        d.add("/FRIC_ORIENT/1", line(("i", 1), ("i", 0)),
              line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 5), ("r", PHI)),
              title="direction 1: the X' axis of skew 5")
    else:
        d.fric_orient(1, [(1, 0, VDIR, PHI)], title="direction 1: (1, sqrt 3, 0.7) projected on the floor")
    d.run(tend, 0.005)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_vel)
    return d


def incremental(v0=(V0, 0.0), rtol=1e-12, fband=BAND * M * G):
    """Independent integration of ricochet's incremental orthotropic law
    (docs/theory.md 3.5, 6.4, with the critically damped stick spring of
    commit aa7c6b5, lib/stick.py): from the launch the contact sticks with a
    zero state, and the force that acts is the spring plus the stick damper,
    F = F_t - c_t v, c_t = 2 sqrt(K_t m) (the floor is fixed): at the launch
    F = -c_t v0. It slips when the scaled force u_k = F.d_k/L_k reaches
    |u| = 1 + band (the critically damped stick force -m w v0 (2 - w t) e^(-w t)
    only falls from there, so the contact slips at t = 0 or never), the state
    taking the direction of F with the magnitude the state had (zero), at
    least the slip band fband [N] (docs/theory.md 3.5: a friction reset
    stores no energy that no work put there); then sliding on the ellipse,
    F = L_1 e_1 d1 + L_2 e_2 d2 with e = u/|u| turning towards -w
    (w_k = L_k v_k) and the state loading along e towards the ellipse |u| = 1,
    du/dt = -K_t/(L_1 L_2) (w - (w.e) e + (w.e) (1 - |u|)/max(1, |u|) e),
    until w.e rises through 0.
    Returns the slip time, the dense solution [x, y, v_x, v_y, u_1, u_2], the stop time and state."""
    L1, L2 = MU1 * M * G, MU2 * M * G
    d1, d2 = D1[:2], D2[:2]
    v0 = np.array(v0)
    f0 = -stick.ct(KT, M) * v0               # applied force at the launch: the damper's
    u0 = np.array([f0 @ d1 / L1, f0 @ d2 / L2])
    if math.hypot(*u0) <= 1 + BAND:
        raise ValueError("the stick damper does not reach the ellipse: the block sticks")
    t1, x1, v1 = 0.0, np.zeros(2), v0
    ft0 = fband * f0 / np.linalg.norm(f0)    # the damper's direction, the band's magnitude
    u1 = np.array([ft0 @ d1 / L1, ft0 @ d2 / L2])

    def rhs(t, y):
        v, u = y[2:4], y[4:6]
        nu = math.hypot(*u)
        e = u / nu
        wv = np.array([L1 * (v @ d1), L2 * (v @ d2)])
        du = -KT / (L1 * L2) * (wv - (wv @ e) * e + (wv @ e) * (1.0 - nu) / max(1.0, nu) * e)
        f = L1 * e[0] * d1 + L2 * e[1] * d2
        return np.concatenate([v, f / M, du])

    def sticks(t, y):
        u, v = y[4:6], y[2:4]
        e = u / math.hypot(*u)
        return L1 * (v @ d1) * e[0] + L2 * (v @ d2) * e[1]
    sticks.terminal, sticks.direction = True, 1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # Radau's finite-difference Jacobian probing
        s = solve_ivp(rhs, (t1, 10.0), np.concatenate([x1, v1, u1]), method="Radau",
                      rtol=rtol, atol=1e-15, dense_output=True, events=sticks)
    return t1, s.sol, s.t_events[0][0], s.y_events[0][0]


def compare(name, r, ref, tol_path, tol_vel, tol_stop, what):
    t0, sol, t_stop, x_stop = ref
    sticks = r.events("fric_stick")
    ts = sticks[0] if len(sticks) else r.t[-1]
    sel = (r.t > t0) & (r.t < min(ts, t_stop))
    y = sol(r.t[sel])
    ep = np.max(np.hypot(r.pos[sel, 0, 0] - y[0], r.pos[sel, 0, 1] - y[1]))
    ev = np.max(np.hypot(r.vel[sel, 0, 0] - y[2], r.vel[sel, 0, 1] - y[3]))
    rcval.check(f"{name}.path", ep < tol_path and ev < tol_vel,
                f"against {what}, {sel.sum()} records to the stop: max distance to the reference path {ep:.1e} m "
                f"(< {tol_path:g}), max velocity difference {ev:.1e} m/s (< {tol_vel:g})")
    i = r.state_at(ts) if len(sticks) else -1
    xs = r.pos[i, 0, :2]
    es, et = np.hypot(*(xs - x_stop[:2])), abs(ts - t_stop)
    rcval.check(f"{name}.stop", len(sticks) > 0 and es < tol_stop and et < tol_stop,
                f"stop (first fric_stick) at t = {ts:.9f} s, ({xs[0]:.9f}, {xs[1]:.9f}) m; reference {t_stop:.9f} s, "
                f"({x_stop[0]:.9f}, {x_stop[1]:.9f}) m; errors {et:.1e} s, {es:.1e} m (< {tol_stop:g})")


def max_dissipation(name, r, tol, why):
    """Every sliding record after 1 ms above 0.1 m/s: the force on the
    ellipse, and within tol of the maximum-dissipation force."""
    L = np.array([MU1, MU2]) * M * G
    speed = np.linalg.norm(r.vel[:, 0, :2], axis=1)
    sl = (r.slip[:, 0] == 1) & (r.t > 1e-3) & (r.t < r.events("fric_stick")[0]) & (speed > 0.1)
    eo, ed = 0.0, 0.0
    for f, v in zip(r.ffric[sl, 0], r.vel[sl, 0]):
        fk, vk = np.array([f @ D1, f @ D2]), np.array([v @ D1, v @ D2])
        eo = max(eo, abs(math.hypot(*(fk / L)) - 1.0))
        fmd = -L * L * vk / math.hypot(*(L * vk))
        ed = max(ed, np.linalg.norm(fk - fmd) / np.linalg.norm(fmd))
    rcval.check(f"{name}.max_dissipation", sl.sum() > 20 and eo < 1e-9 and ed < tol,
                f"{sl.sum()} sliding records after 1 ms, above 0.1 m/s: max | |F/L| - 1 | = {eo:.1e} (on the ellipse, "
                f"< 1e-9); max |F - F_md|/|F_md| = {ed:.1e} (< {tol:.2g}: {why}), "
                f"F_md = -(L_k^2 v_k)/sqrt(sum L_j^2 v_j^2)")


def main():
    rigid = reference()
    rigid = (0.0, rigid[0], rigid[1], rigid[2])
    inc = incremental()
    # the slip band of the state's magnitude at the onset: its effect on the path
    inc2 = incremental(fband=BAND * M * G / 100.0)
    tt = np.linspace(1e-3, min(inc[2], inc2[2]), 200)
    print(f"incremental reference: the state starting at the slip band or 100 times below it: paths within "
          f"{np.max(np.hypot(*(inc[1](tt)[:2] - inc2[1](tt)[:2]))):.1e} m")
    print(f"rigid maximum-dissipation stop {rigid[2]:.9f} s at ({rigid[3][0]:.9f}, {rigid[3][1]:.9f}) m, "
          f"{math.degrees(math.atan2(rigid[3][1], rigid[3][0])):.3f} deg from the launch line "
          f"(isotropic mu_1: {V0**2 / (2 * MU1 * G):.6f} m along x, mu_2: {V0**2 / (2 * MU2 * G):.6f} m)")
    # default tolerances (case.rad): the rigid law, within the incremental form's regularisation
    r = rcval.Result(rcval.run_case())
    compare("frc_orthotropic.default", r, rigid, 1e-5, 1e-4, 1e-5, "the rigid elliptic law (solve_ivp)")
    # sliding: on the ellipse, along the maximum-dissipation direction; at
    # the deck's tolerances within the integration error of the direction
    # state (absolute tolerance of F_t, K_t atol_pos = 1e-3 N, against the
    # smaller limit L_1 = 1.96 N: 10 times that, 5.1e-3)
    max_dissipation("frc_orthotropic.default", r, 10.0 * KT * 1e-9 / (MU1 * M * G),
                    "the integration error of the direction at atol(F_t) = 1e-3 N")
    # direction 1 from a /SKEW/FIX (skew_ID, its X' axis) instead of V: the same run
    rs = rcval.Result(rcval.run(deck(skew=True), name="skew"))
    # the records at the output times (events may fall a rounding apart)
    ka, kb = rs.at_event == 0, r.at_event == 0
    same = np.array_equal(rs.t[ka], r.t[kb])
    dx = float(np.max(np.abs(rs.pos[ka] - r.pos[kb]))) if same else np.inf
    rcval.check("frc_orthotropic.skew.same_path", dx < 1e-9,
                f"direction 1 from skew_ID (X' = (1, sqrt 3, 0)/2) against V = (1, sqrt 3, 0.7): max |dx| = {dx:.2e} m "
                f"(< 1e-9, same records: {same})")
    compare("frc_orthotropic.skew", rs, rigid, 1e-5, 1e-4, 1e-5, "the rigid elliptic law (solve_ivp)")
    # tight tolerances: the incremental law exactly; the rigid law within its regularisation
    r = rcval.Result(rcval.run(deck(rtol=1e-11, atol_pos=1e-14, atol_vel=1e-11)))
    compare("frc_orthotropic.tight", r, inc, 1e-8, 1e-8, 1e-8, "the incremental law (solve_ivp)")
    max_dissipation("frc_orthotropic.tight", r, 1e-3, "the lag of the incremental direction, README.md")
    slip = r.events("fric_slip")
    e = abs(slip[0] - inc[0]) if len(slip) else 1.0
    rcval.check("frc_orthotropic.tight.slip_onset", e < 1e-12,
                f"fric_slip at {slip[0] if len(slip) else float('nan'):.9e} s; the stick damper's force "
                f"c_t v0 = {stick.ct(KT, M) * V0:g} N is beyond the ellipse at the launch: slip at {inc[0]:g} s "
                f"(error {e:.1e} s, < 1e-12)")
    compare("frc_orthotropic.tight_vs_rigid", r, rigid, 5e-6, 5e-5, 1e-5, "the rigid elliptic law (solve_ivp)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
