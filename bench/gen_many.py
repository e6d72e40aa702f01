#!/usr/bin/env python3
"""Write a deck of N spheres for the set-up and output measurements
(bench/README.md, "Output and set-up").

    gen_many.py N OUT.rad [--tend T] [--dtout DT] [--ev-state S]

A vertical column of N spheres (R = 0.01 m, m = 0.01 kg) above a floor, each
with its /NODE, /RBODY, /SURF/ELLIPS, and a TYPE6 linear contact
(k = 1e5 N/m, critically damped) with its lower neighbour (the first one with
the floor): the same model as the bench's settling column (bench.py, COL),
with ids in a shuffled order so that the reader cannot rely on sorted ids.
--no-contacts keeps only the floor contact (the set-up cost without the
per-contact Jacobian probing).
Uses validation/lib/deck.py.
"""
import argparse
import math
import os
import random
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
from deck import Deck  # noqa: E402

G = 9.81


def many_deck(N, tend, dtout, ev_state=None, contacts=True, R=0.01, m=0.01, k=1.0e5, zeta=1.0, gap=1.0e-4, seed=1):
    d = Deck(f"bench: column of {N} spheres (gen_many.py)")
    d.funct(1, [0.0, 1.0], [0.0, k], title="linear load curve")
    z = [R + gap + i * (2 * R + gap) for i in range(N)]
    order = list(range(N))
    random.Random(seed).shuffle(order)       # cards in a shuffled id order
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in order])
    J = [0.4 * m * R * R] * 3
    for i in order:
        d.rbody(i + 1, i + 1, m, J, title=f"sphere {i + 1}")
    for i in order:
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), R, title=f"sphere {i + 1}")
    floor = N + 1
    d.plane(floor, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.grav(1, "Z", -G)
    c_floor = 2 * zeta * math.sqrt(k * m)
    c_ss = 2 * zeta * math.sqrt(k * m / 2)
    d.type6(1, 1, floor, 1, visc=c_floor, title="floor contact")
    for i in order if contacts else []:
        if i > 0:
            d.type6(i + 1, i, i + 1, 1, visc=c_ss, title=f"spheres {i}-{i + 1}")
    d.run(tend, dtout, ev_state)
    d.solver(rtol=1e-6, atol_pos=1e-9, atol_vel=1e-6, atol_energy=1e-6, max_steps=10**7)
    return d


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("N", type=int)
    ap.add_argument("out")
    ap.add_argument("--tend", type=float, default=0.2)
    ap.add_argument("--dtout", type=float, default=0.0, help="output interval [s] (0: Tend/100)")
    ap.add_argument("--ev-state", type=int, default=None, help="/RUN Ev_state (default: field left out)")
    ap.add_argument("--no-contacts", action="store_true", help="only the floor contact of sphere 1")
    a = ap.parse_args()
    many_deck(a.N, a.tend, a.dtout, a.ev_state, not a.no_contacts).write(a.out)


if __name__ == "__main__":
    main()
