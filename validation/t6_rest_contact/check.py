"""Contacts that start or restart exactly at zero: no fall-through.

1. A sphere exactly touching a plane, at rest, under gravity (P = 0 and
   dP/dt = 0 at t = 0): the contact must close at once and the sphere settle
   at the static penetration m g / k (linear load, damping).
2. Iform 2 drop under gravity: the force is released at zero while P > 0 and
   the ball falls back onto the contact; reloading starts at zero force and
   the contact must close again (the ball settles on the contact, P bounded).
Reference: statics, P = m g / k (1) and P bounded by the first impact's
maximum penetration (2); both settle to m g / k past the permanent set of
the loading history.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e5, 9.81
C = 2 * 0.5 * math.sqrt(K * M)


def deck_rest():
    d = Deck("sphere touching a plane at rest under gravity")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    add_sphere_over_plane(d, M, R, R)
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, visc=C)
    d.run(0.3, 1e-3)
    d.solver(rtol=1e-8, atol_pos=1e-12, atol_vel=1e-9)
    return d


def deck_reload():
    d = Deck("Iform 2 drop: release and reloading")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    z0 = R + 1e-3
    add_sphere_over_plane(d, M, R, z0)
    d.grav(1, "Z", -G)
    d.type6(1, 1, 2, 1, iform=2, stiff=4 * K, visc=0.2 * C)
    d.run(1.0, 1e-3)
    d.solver(rtol=1e-8, atol_pos=1e-12, atol_vel=1e-9)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    closes = r.events("contact_close")
    ok = len(closes) > 0 and closes[0] == 0.0
    rcval.check("t6_rest_contact.closes_at_start", ok, f"first contact_close at t = {closes[0] if len(closes) else None} s (expected 0)")
    p_end, ps = r.pen[-1, 0], M * G / K
    e = abs(p_end - ps) / ps
    rcval.check("t6_rest_contact.settles", e < 1e-6, f"P(0.3 s) = {p_end:.9e} m, m g / k = {ps:.9e} m, rel. error {e:.2e} (< 1e-6)")
    r2 = rcval.Result(rcval.run(deck_reload()))
    pmax_first = float(r2.pen[:, 0].max())
    first_release = r2.events("contact_open")[0]
    after = r2.t > first_release
    ok = float(r2.pen[after, 0].max()) <= pmax_first * (1 + 1e-9)
    rcval.check("t6_rest_contact.reload_no_fallthrough", ok,
                f"max P after the first release {float(r2.pen[after, 0].max()):.6e} m <= first impact's {pmax_first:.6e} m; "
                f"{len(r2.events('contact_close'))} closings, {len(r2.events('hyst_reloading'))} reloadings")
    # settled: force balances gravity
    f_end = r2.fn[-1, 0]
    rcval.check("t6_rest_contact.reload_settles", abs(f_end - M * G) / (M * G) < 1e-4,
                f"F(1 s) = {f_end:.6f} N, m g = {M * G:.6f} N")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck_rest)
