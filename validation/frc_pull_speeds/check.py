"""Friction law mu(p, v) of /FRICTION measured on a block dragged by a belt.

A sphere with locked rotations (a "block", m = 1 kg, R = 0.05 m) rests at
its static penetration on a plane carried by a 1e12 kg body (the "belt")
moving at constant speed V along x. The block is held in x and y (/BCS
"110 111"), free along z, so it slides at exactly V over the belt and its
normal force is its weight. The measured coefficient |F_t| / F_n
(inter_force_friction, inter_force_normal) is compared with the law of
docs/theory.md 6.1, evaluated here at p = F_n / Area and v = V, for Ifric 1, 2,
3 at several (p, v) points (README.md), in both formulations: while sliding the
incremental form (Iform 2) and the saturated viscous form (Iform 1) apply
exactly the limit mu F_n.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G = 1.0, 0.05, 1.0e6, 9.81
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
MBELT = 1.0e12                       # belt mass [kg]
TEND = 0.05                          # run length [s]: the stick onset lasts F_lim/(K_t V) < 1e-4 s

# coefficient sets: (C1..C6, Fric)
LAWS = {
    1: ((5e-7, 0.04, 2e-7, -3e-13, 0.01, 0.0), 0.15),   # Fric + C1 p + C2 v + C3 p v + C4 p^2 + C5 v^2
    2: ((2e-12, -0.5, 5e-7, -1.0, 0.2, -2.0), 0.1),     # Fric + C1 e^(C2 v) p^2 + C3 e^(C4 v) p + C5 e^(C6 v)
    3: ((0.3, 0.25, 0.45, 0.1, 0.2, 0.6), 0.0),         # Renard: mu_s, mu_d, mu_max, mu_min, V_cr1, V_cr2
}
# (Area [m^2] or None for the default pi R^2, V [m/s], block mass [kg]) per law
POINTS = {
    1: [(1e-4, 0.01, 1.0), (1e-4, 0.5, 1.0), (4e-4, 0.1, 1.0), (4e-4, 3.0, 1.0), (2e-5, 1.0, 1.0),
        (2e-5, 3.0, 1.0), (None, 0.3, 1.0), (1e-4, 0.2, 4.0)],
    2: [(1e-4, 0.01, 1.0), (1e-4, 0.5, 1.0), (4e-4, 0.1, 1.0), (4e-4, 2.0, 1.0), (2e-5, 1.0, 1.0),
        (2e-5, 3.0, 1.0), (None, 0.3, 1.0), (1e-4, 0.2, 4.0)],
    3: [(1e-4, 0.05, 1.0), (1e-4, 0.15, 1.0), (1e-4, 0.2, 1.0), (4e-4, 0.3, 1.0), (4e-4, 0.5, 1.0),
        (1e-4, 0.6, 1.0), (2e-5, 1.0, 1.0), (None, 3.0, 1.0), (1e-4, 0.4, 4.0)],
}


def mu_law(ifric, c, fric, p, v):
    """The laws of docs/theory.md 6.1, written from their definition, floored at zero."""
    c1, c2, c3, c4, c5, c6 = c
    if ifric == 0:
        mu = fric
    elif ifric == 1:
        mu = fric + c1 * p + c2 * v + c3 * p * v + c4 * p * p + c5 * v * v
    elif ifric == 2:
        mu = fric + c1 * math.exp(c2 * v) * p * p + c3 * math.exp(c4 * v) * p + c5 * math.exp(c6 * v)
    else:  # Renard
        mus, mud, mumax, mumin, vcr1, vcr2 = c
        if v <= vcr1:
            x = v / vcr1
            mu = mus + (mumax - mus) * x * (2.0 - x)
        elif v < vcr2:
            w = (v - vcr1) / (vcr2 - vcr1)
            mu = mumax + (mumin - mumax) * (3.0 - 2.0 * w) * w * w
        else:
            mu = mud - (mud - mumin) / (1.0 + (mud - mumin) * (v - vcr2) ** 2)
    return max(mu, 0.0)


def deck(ifric, area, v, c=None, fric=None, m=M, iform=2):
    if c is None:
        c, fric = LAWS[ifric]
    z0 = R - m * G / K  # static penetration: F_n = m g from the start
    d = Deck(f"block on a belt at {v:g} m/s, /FRICTION Ifric {ifric}, Area {area}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, 0.0, 0.0, z0), (2, 0.0, 0.0, -1.0)])
    d.rbody(1, 1, m, [0.4 * m * R * R] * 3, grnod=1, title=f"block {m:g} kg")
    d.rbody(2, 2, MBELT, [MBELT] * 3, grnod=2, title="belt 1e12 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), body=2, title="belt surface z = 0")
    d.grnod(1, [1], title="block")
    d.grnod(2, [2], title="belt")
    d.bcs(1, 1, "110 111", title="block held in x and y, no rotation")
    d.bcs(2, 2, "011 111", title="belt moves along x only")
    d.inivel(1, (v, 0.0, 0.0), 2)
    d.grav(1, "Z", -G, 1)  # on the block only
    d.type6(1, 1, 2, 1, visc=VISC, title="contact (no TYPE6 friction)")
    d.friction(1, ifric=ifric, iform=iform, area=area, c=c, fric=fric, title=f"Ifric {ifric}, Iform {iform}")
    d.run(TEND, TEND / 10)
    return d


def measure(r):
    """mu = |F_t| / F_n, F_n, sliding speed and mode at the last record."""
    ft = r.ffric[-1, 0]
    return np.linalg.norm(ft) / r.fn[-1, 0], r.fn[-1, 0], r.vslip[-1, 0], r.slip[-1, 0], ft


def point(name, ifric, area, v, m=M, c=None, fric=None, iform=2):
    if c is None:
        c, fric = LAWS[ifric]
    r = rcval.Result(rcval.run(deck(ifric, area, v, c, fric, m, iform)))
    mu, fn, vs, slip, ft = measure(r)
    a = area if area else math.pi * R * R
    p = fn / a
    ref = mu_law(ifric, c, fric, p, v)
    e = abs(mu - ref) / max(ref, 1e-300) if ref > 0 else abs(mu)
    ok = (e < 1e-6 and slip == 1 and abs(vs - v) < 1e-9 * v and rcval.rel(fn, m * G) < 1e-9
          and abs(ft[1]) + abs(ft[2]) < 1e-12 * max(1.0, abs(ft[0])) and (ref == 0 or ft[0] > 0))
    rcval.check(name, ok,
                f"Iform {iform}, m = {m:g} kg, p = {p:.6g} Pa (Area {'pi R^2' if not area else f'{area:g} m^2'}), v = {v:g} m/s: "
                f"measured mu = {mu:.12g}, law {ref:.12g}, rel. error {e:.1e} (< 1e-6); "
                f"F_n = {fn:.9g} N, sliding speed {vs:.9g} m/s, mode {'slip/saturated' if slip else 'stick/viscous'}")
    return e


def main():
    names = {1: "gen_viscous", 2: "darmstad", 3: "renard"}
    worst = 0.0
    for iform, form in ((2, "iform2"), (1, "iform1")):
        for ifric in (1, 2, 3):
            for k, (area, v, m) in enumerate(POINTS[ifric]):
                worst = max(worst, point(f"frc_pull_speeds.{form}.{names[ifric]}.{k + 1}", ifric, area, v, m,
                                         iform=iform))
        # mu floored at zero: Fric + C2 v < 0 at v = 1 m/s (while sticking, v = 0: mu = Fric)
        point(f"frc_pull_speeds.{form}.floor_zero", 1, 1e-4, 1.0, c=(0.0, -0.2, 0.0, 0.0, 0.0, 0.0), fric=0.1,
              iform=iform)
    # case.rad: the first Darmstad point, as written by --write-case
    r = rcval.Result(rcval.run_case())
    mu, fn, vs, slip, ft = measure(r)
    area, v, m = POINTS[2][0]
    ref = mu_law(2, *LAWS[2], fn / area, v)
    e = rcval.rel(mu, ref)
    rcval.check("frc_pull_speeds.case_rad", e < 1e-6,
                f"case.rad (Darmstad, p = {fn / area:.6g} Pa, v = {v:g} m/s): mu = {mu:.12g}, law {ref:.12g}, rel. error {e:.1e}")
    print(f"largest relative error over the law points: {worst:.1e}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(2, POINTS[2][0][0], POINTS[2][0][1], m=POINTS[2][0][2]))
