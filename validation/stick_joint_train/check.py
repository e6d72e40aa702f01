"""Exact stick in a model with joints: two balls on an incline tied by a rod.

Two solid spheres (m = 1 kg, R = 0.05 m, J = 2/5 m R^2, rotations free) on
a plane tilted by theta about a horizontal axis at azimuth phi = 30 deg,
gravity -z; ball A (body 1) has exact-stick friction (TYPE6 Istick 1), ball
B (body 2), 0.2 m further down the fall line, none; a /JOINT/DISTANCE ties
their centres. Reference (README.md): rigid-body mechanics of the pair
(Newton's law along the fall line for each ball, Euler's about A's centre):
A rolls without slipping while the friction it needs is within mu m g
cos(theta), else A slides from t = 0.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import incline  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81
J = 0.4 * M * R * R
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
PHI = math.radians(30.0)
GAP = 0.2  # distance of the centres along the fall line [m]


def deck(tan_th, mu, tend, dtout):
    th, n, s, u = incline.frame(tan_th, PHI)
    p = M * G * math.cos(th) / K  # the static normal penetration of each ball
    ca = (R - p) * n
    cb = ca + GAP * s
    d = Deck(f"exact stick with a joint: two balls on a plane tilted by atan({tan_th:g}), a rod, Fric {mu:g} on A")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, *ca), (2, *cb)])
    d.rbody(1, 1, M, [J] * 3, grnod=1, title="ball A 1 kg")
    d.rbody(2, 2, M, [J] * 3, grnod=2, title="ball B 1 kg")
    d.sphere(1, 1, tuple(ca), R, title="ball A")
    d.sphere(3, 2, tuple(cb), R, title="ball B")
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title="inclined plane through the origin")
    d.grnod(1, [1], title="A")
    d.grnod(2, [2], title="B")
    d.grav(1, "Z", -G, 0)
    d.type6(1, 1, 2, 1, visc=VISC, fric=mu, istick=1, title="ball A: exact stick")
    d.type6(2, 3, 2, 1, visc=VISC, title="ball B: no friction")
    d.joint(1, "DISTANCE", 1, 2, tuple(ca), p2=tuple(cb), title="rod between the centres")
    d.run(tend, dtout)
    return d


def load(path):
    r = rcval.Result(path)
    with Dataset(path) as nc:
        r.jforce = np.array(nc["joint_force"][:])[:, 0, :]
        r.omega = np.array(nc["body_angular_velocity"][:]) if "body_angular_velocity" in nc.variables else None
    return r


def main():
    # 1. rolling (case.rad): tan(theta) = 0.5, mu = 0.3. Rolling of A, both
    #    balls at the same speed: (2 m + J/R^2) a = 2 m g sin(theta); the
    #    friction on A, J a / R^2 = (1/3) m g sin(theta) up the slope, is
    #    within mu m g cos(theta) (tan(theta) = 0.5 < 3 mu); the rod pulls A
    #    down the slope with m g sin(theta) - m a = m g sin(theta) / 6.
    tan_th, mu = 0.5, 0.3
    th, n, s, u = incline.frame(tan_th, PHI)
    r = load(rcval.run_case())
    a_ref = 2.0 * M * G * math.sin(th) / (2.0 * M + J / R**2)
    xa = (r.pos[:, 0, :] - r.pos[0, 0, :]) @ s
    xb = (r.pos[:, 1, :] - r.pos[0, 1, :]) @ s
    va = r.vel[:, 0, :] @ s
    x_ref = 0.5 * a_ref * r.t**2
    ex = np.max(np.abs(xa - x_ref)) / x_ref[-1]
    exb = np.max(np.abs(xb - x_ref)) / x_ref[-1]
    ev = np.max(np.abs(va - a_ref * r.t)) / (a_ref * r.t[-1])
    rcval.check("stick_joint_train.rolling.motion", ex < 1e-6 and exb < 1e-6 and ev < 1e-6,
                f"x_A(t), x_B(t) against a t^2/2, a = 2 m g sin(theta) / (2 m + J/R^2) = {a_ref:.10f} m/s^2: "
                f"max error {ex:.1e}, {exb:.1e} of x(end) = {x_ref[-1]:.6f} m (< 1e-6); v_A(t) against a t: "
                f"{ev:.1e} (< 1e-6); x_A(end) = {xa[-1]:.10f} m")
    f_ref = -J * a_ref / R**2 * s  # on A, up the slope
    ef = np.max(np.linalg.norm(r.ffric[:, 0, :] - f_ref, axis=1)) / (M * G * math.sin(th))
    rcval.check("stick_joint_train.rolling.friction", ef < 1e-6 and len(r.ev_t) == 0 and np.all(r.slip[:, 0] == 0),
                f"friction on A = J a / R^2 = m g sin(theta) / 3 = {J * a_ref / R**2:.10f} N up the slope: max "
                f"|F - F_ref| / (m g sin theta) = {ef:.1e} (< 1e-6); |F| at the end "
                f"{np.linalg.norm(r.ffric[-1, 0]):.10f} N; {len(r.ev_t)} events (expected 0), sticking throughout")
    t_ref = (M * G * math.sin(th) - M * a_ref) * s  # the rod's force on A
    et = np.max(np.linalg.norm(r.jforce - t_ref, axis=1)) / (M * G * math.sin(th))
    rcval.check("stick_joint_train.rolling.rod", et < 1e-6,
                f"rod force on A = m g sin(theta) / 6 = {M * G * math.sin(th) - M * a_ref:.10f} N down the slope: "
                f"max |F - F_ref| / (m g sin theta) = {et:.1e} (< 1e-6); at the end {r.jforce[-1] @ s:.10f} N")

    # 2. sliding: tan(theta) = 0.5, mu = 0.1 < (1/3) tan(theta): A slides
    #    from t = 0 (one fric_slip event at t = 0); then both balls at
    #    a = g sin(theta) - mu g cos(theta) / 2, the rod's force on A
    #    mu m g cos(theta) / 2 down the slope, A spins up at
    #    mu m g cos(theta) R / J.
    mu = 0.1
    r = load(rcval.run(deck(tan_th, mu, 0.5, 0.01)))
    a_ref = G * math.sin(th) - 0.5 * mu * G * math.cos(th)
    xa = (r.pos[:, 0, :] - r.pos[0, 0, :]) @ s
    x_ref = 0.5 * a_ref * r.t**2
    ex = np.max(np.abs(xa - x_ref)) / x_ref[-1]
    ok_ev = r.ev_kind == ["fric_slip"] and r.ev_t[0] == 0.0
    rcval.check("stick_joint_train.sliding.motion", ex < 1e-6 and ok_ev,
                f"events {list(zip(r.ev_t, r.ev_kind))} (expected one fric_slip at t = 0: the force that would "
                f"hold A, m g sin(theta) / 3 with the rod, is beyond mu m g cos(theta)); x_A(t) against a t^2/2, "
                f"a = g sin(theta) - mu g cos(theta) / 2 = {a_ref:.10f} m/s^2: max error {ex:.1e} of "
                f"x(end) (< 1e-6)")
    t_ref = 0.5 * mu * M * G * math.cos(th) * s
    sl = r.t >= 0.05
    et = np.max(np.linalg.norm(r.jforce[sl] - t_ref, axis=1)) / (M * G * math.sin(th))
    fm = np.linalg.norm(r.ffric[sl, 0, :], axis=1)
    ef = np.max(np.abs(fm - mu * M * G * math.cos(th))) / (mu * M * G * math.cos(th))
    rcval.check("stick_joint_train.sliding.forces", et < 1e-6 and ef < 1e-6,
                f"over [0.05, 0.5] s: rod force on A = mu m g cos(theta) / 2 = {t_ref @ s:.10f} N down the slope: "
                f"max error {et:.1e} m g sin(theta) (< 1e-6); |friction| = mu m g cos(theta) = "
                f"{mu * M * G * math.cos(th):.10f} N: max rel. error {ef:.1e} (< 1e-6)")
    rcval.check_ledger("stick_joint_train.sliding.energy", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.5, 0.3, 1.0, 0.01))
