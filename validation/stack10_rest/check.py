"""A stack of 10 touching spheres on a floor, at rest, gravity from t = 0.

Ten equal spheres stacked vertically, centres exactly 2R apart, the bottom
one exactly touching the floor: every contact starts at zero gap and at
rest. Gravity is applied from t = 0 (constant); linear TYPE6 contacts with
damping at the critical value of a single contact. Reference (statics,
README.md): once settled, the contact j-th from the top carries the weight of
the j spheres above it, F_j = j m g (penetration j m g / k); every contact
closes at t = 0; no sphere passes into its neighbour.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

N, M, R, K, G = 10, 1.0, 0.0625, 1.0e5, 9.81
C = 2.0 * 1.0 * math.sqrt(K * M)  # damping ratio 1 for one sphere on one contact
T_END, DT_OUT = 5.0, 1.0e-3
FLOOR = N + 1                      # surface id of the floor


def deck():
    d = Deck("stack of 10 touching spheres on a floor, gravity from t = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e5 N/m")
    z = [R + 2.0 * R * i for i in range(N)]  # exact binary numbers: the gaps are exactly zero
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(N)])
    for i in range(N):
        d.rbody(i + 1, i + 1, M, [0.4 * M * R * R] * 3, grnod=i + 1, title=f"sphere {i + 1} (from the bottom)")
    for i in range(N):
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
    d.plane(FLOOR, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    for i in range(N):
        d.grnod(i + 1, [i + 1], title=f"sphere {i + 1}")
    d.grav(1, "Z", -G)
    d.type6(1, 1, FLOOR, 1, visc=C, title="floor - sphere 1")
    for i in range(1, N):
        d.type6(i + 1, i, i + 1, 1, visc=C, title=f"sphere {i} - sphere {i + 1}")
    d.run(T_END, DT_OUT)
    d.solver(rtol=1e-10, atol_pos=1e-14, atol_vel=1e-11, atol_energy=1e-10)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    ids = list(r.inter_id)
    col = [ids.index(i + 1) for i in range(N)]  # interface i + 1: below sphere i + 1
    load = np.array([(N - i) * M * G for i in range(N)])  # interface i + 1 carries the N - i spheres above it
    # every contact closes at t = 0
    bad = []
    for i in range(N):
        name = f"/INTER/TYPE6/{i + 1}"
        first = [(t, k) for t, k, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if e == name][:1]
        if not (first == [(0.0, "contact_close")] or (not first and r.mode[0, col[i]] == 2)):
            bad.append(f"{i + 1}: {first[0][1] + ' at ' + format(first[0][0], '.3e') + ' s' if first else 'no event'}")
    rcval.check("stack10_rest.closes_at_start", not bad,
                f"contacts not closed at t = 0: {bad if bad else 'none'} ({len(r.ev_t)} events in the run)")
    # no sphere passes into its neighbour or the floor: every penetration below 3 x its static value
    pmax = r.pen[:, col].max(axis=0)
    ratio = pmax / (load / K)
    rcval.check("stack10_rest.no_pass_through", ratio.max() < 3.0,
                f"max P / (static j m g / k) = {ratio.max():.3e} (< 3); per contact, floor first: "
                f"{', '.join(f'{x:.3g}' for x in ratio)}")
    # settled: the statics
    f = r.fn[-1, col]
    e = np.abs(f - load) / load
    rcval.check("stack10_rest.static_forces", e.max() < 1e-6,
                f"F at {r.t[-1]:g} s, floor first: {', '.join(f'{x:.6f}' for x in f)} N; j m g = "
                f"{', '.join(f'{x:.2f}' for x in load)} N; max rel. error {e.max():.2e} (< 1e-6)")
    p = r.pen[-1, col]
    e = np.abs(p - load / K) / (load / K)
    rcval.check("stack10_rest.static_penetrations", e.max() < 1e-6,
                f"P at {r.t[-1]:g} s against j m g / k: max rel. error {e.max():.2e} (< 1e-6); floor {p[0]:.6e} m "
                f"(10 m g / k = {load[0] / K:.6e} m), top {p[-1]:.6e} m (m g / k = {load[-1] / K:.6e} m)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
