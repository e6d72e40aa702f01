"""A sphere resting exactly on the floor, gravity ramped from 0: no fall-through.

The sphere touches the plane z = 0 with zero gap, at rest; gravity is
g f(t), f ramping linearly from 0 to 1 over T_r = 10 s, then held. At t = 0
the penetration, its rate and its acceleration are all zero (the contact is
entered at third order). Linear TYPE6 load curve k, Visc at half critical
damping. Reference (README.md): the exact response of the linear oscillator
m P'' + c P' + k P = m g f(t) from rest (the contact stays closed: its force
is positive for t > 0), its quasi-static part m g f(t) / k, and the static
penetration m g / k once the ramp is over.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e5, 9.81
ZETA = 0.5
C = 2.0 * ZETA * math.sqrt(K * M)
TR, T_END, DT_OUT = 10.0, 12.0, 1.0e-3
W = math.sqrt(K / M)
WD = W * math.sqrt(1.0 - ZETA**2)
PS = M * G / K  # static penetration


def ramp_response(t):
    """x(t) for x'' + 2 zeta w x' + w^2 x = w^2 t from rest (0 for t < 0)."""
    t = np.asarray(t, dtype=float)
    tp = np.maximum(t, 0.0)
    x = tp - 2 * ZETA / W + np.exp(-ZETA * W * tp) * (2 * ZETA / W * np.cos(WD * tp)
                                                        + (2 * ZETA**2 - 1) / WD * np.sin(WD * tp))
    return np.where(t > 0.0, x, 0.0)


def exact(t):
    """P(t) = (m g / k) (x(t) - x(t - T_r)) / T_r: the ramp, minus the ramp from T_r."""
    return PS * (ramp_response(t) - ramp_response(np.asarray(t) - TR)) / TR


def quasi_static(t):
    return PS * np.minimum(np.asarray(t) / TR, 1.0)


def deck():
    d = Deck("sphere resting on the floor, gravity ramped from zero")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    d.funct(2, [0.0, TR, 1.0e4], [0.0, 1.0, 1.0], title="gravity ramp 0 -> 1 over 10 s, then held")
    d.nodes([(1, 0.0, 0.0, R)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, title="sphere 1 kg")
    d.sphere(1, 1, (0.0, 0.0, R), R)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1])
    d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 2, 1, visc=C, title="linear contact, half critical damping")
    d.run(T_END, DT_OUT)
    d.solver(rtol=1e-10, atol_pos=1e-14, atol_vel=1e-11, atol_energy=1e-10)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    ev = list(zip(r.ev_t, r.ev_kind))
    ok = all(t == 0.0 and k == "contact_close" for t, k in ev) and len(ev) <= 1
    rcval.check("rest_ramp_gravity.events", ok,
                f"events: {[(float(t), k) for t, k in ev][:6]}{' ...' if len(ev) > 6 else ''} ({len(ev)}; expected "
                f"none but contact_close at t = 0)")
    later = r.t > 0.0
    closed = r.mode[later, 0] == 2
    ok = bool(closed.all()) and (ev[:1] == [(0.0, "contact_close")] or r.mode[0, 0] == 2)
    rcval.check("rest_ramp_gravity.closed_from_start", ok,
                f"contact closed at t = 0 ({'contact_close event' if ev[:1] == [(0.0, 'contact_close')] else 'no event'}, "
                f"mode {r.mode[0, 0]} in the first record) and in {closed.sum()} of the {later.sum()} records after it "
                f"(expected all; mode 2 = closed)")
    p = r.pen[:, 0]
    pmax = float(p.max())
    rcval.check("rest_ramp_gravity.no_fall_through", pmax < 1.5 * PS and r.pos[:, 0, 2].min() > R - 1.5 * PS,
                f"max P / (m g / k) = {pmax / PS:.3e} (< 1.5): max P = {pmax:.6e} m, lowest centre "
                f"{r.pos[:, 0, 2].min():.9f} m (floor contact at z = R = {R} m)")
    # the whole history against the exact linear response
    e = np.max(np.abs(p - exact(r.t))) / PS
    rcval.check("rest_ramp_gravity.history", e < 1e-5,
                f"max |P(t) - P_exact(t)| / (m g / k) = {e:.2e} (< 1e-5) over {len(r.t)} records")
    # quasi-static: the dynamic part is bounded by (2 zeta / w + 1 / w_d) / T_r of m g / k
    bound = (2 * ZETA / W + 1.0 / WD) / TR
    e = np.max(np.abs(p - quasi_static(r.t))) / PS
    rcval.check("rest_ramp_gravity.quasi_static", e < bound,
                f"max |P(t) - m g f(t) / k| / (m g / k) = {e:.2e} (< dynamic part bound (2 zeta/w + 1/w_d)/T_r "
                f"= {bound:.2e}; lag 2 zeta/(w T_r) = {2 * ZETA / (W * TR):.2e})")
    # held: the static penetration
    e = rcval.rel(p[-1], PS)
    rcval.check("rest_ramp_gravity.static", e < 1e-6,
                f"P({r.t[-1]:g} s) = {p[-1]:.9e} m, m g / k = {PS:.9e} m, rel. error {e:.2e} (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
