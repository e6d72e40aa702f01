"""/INTER/TYPE7 Inacti 1: a block's nodes that lie within the gap of the
floor at t = 0 are left out of the contact for the whole run; the block
falls onto its other nodes and rests on them (README.md).

A cube (m = 2 kg, half side a = 0.1 m, J = 0.0133 kg m^2) is a /RBODY of
13 nodes, all of them the secondary nodes (grnd_IDs) of an /INTER/TYPE7 in
the Radioss 2022 layout against a fixed meshed floor (/SURF/SEG, 2 x 2
quadrilaterals, z = 0, normal +z): its 4 top corners, and its bottom a
3 x 3 grid whose 4 corners are h0 = 3 mm above the floor and whose 5 other
nodes (the centre and the middles of the edges: bumps of the rigid body)
b = 2.5 mm lower, 0.5 mm above the floor. Istf 1, Stfac k = 1e5 N/m,
Gapmin g = 1 mm: the 5 bumps lie within the gap at t = 0.

1. Inacti 1: the 5 bumps are left out (the notice of `ricochet check`
   names them); the block falls freely until its 4 bottom corners reach the
   gap, at t = sqrt(2 (h0 - g) / g_0), and rests on them: the interface
   force m g_0 and its corners g - m g_0 / k above the floor (ricochet's one
   force over the nodes, docs/theory.md 3.7).
2. Inacti 0 (the same deck): the bumps act from the start; the block is
   lifted onto them and rests b higher: its bumps at g - m g_0 / k.
"""
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, J, A, G0 = 2.0, 0.0133, 0.1, 9.81
K = 1.0e5          # Stfac, Istf 1 [N/m]
GAP = 0.001        # Gapmin [m]
H0 = 0.003         # the bottom corners' height at t = 0 [m]
BUMP = 0.0025      # the bumps below the corners [m]
BUMPS = [32, 34, 35, 36, 38]  # the bottom grid's centre and edge middles
TEND = 4.0


def type7(d, iid, grnod, surf, stfac, gapmin, inacti):
    """/INTER/TYPE7 in the Radioss 2022 layout: Istf 1, Gapmin, Inacti, the
    rest defaults (VISs 0.05, VISF 1)."""
    d.add(f"/INTER/TYPE7/{iid}",
          line(("i", grnod), ("i", surf), ("i", 1), ("i", 0), ("i", 0), ("i", None), ("i", 0), ("i", 0), ("i", 0),
               ("i", 0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0)),
          line(("r", stfac), ("r", 0.0), ("r", gapmin), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", inacti), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", 0), ("r", 0.0), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", 0)),
          title="block nodes on the floor")


def deck(inacti):
    d = Deck(f"TYPE7 Inacti {inacti}: a block with bumps within the gap on a meshed floor")
    top = [(15 + k, sx * A, sy * A, H0 + 2 * A) for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1)])]
    bottom = []
    for j in range(3):
        for i in range(3):
            nid = 31 + i + 3 * j
            bottom.append((nid, -A + A * i, -A + A * j, H0 - (BUMP if nid in BUMPS else 0.0)))
    floor = [(101 + 3 * j + i, -1.0 + i, -1.0 + j, 0.0) for j in range(3) for i in range(3)]
    nodes = top + bottom
    d.nodes([(1, 0.0, 0.0, H0 + A)] + nodes + floor)
    d.rbody(1, 1, M, [J] * 3, grnod=2, title="block 2 kg")
    d.grnod(2, [n for n, _, _, _ in nodes], title="block nodes")
    segs = []
    for j in range(2):
        for i in range(2):
            n0 = 101 + 3 * j + i
            segs.append(line(("i", len(segs) + 1), ("i", n0), ("i", n0 + 1), ("i", n0 + 4), ("i", n0 + 3)))
    d.add("/SURF/SEG/30", *segs, title="floor")
    d.grav(1, "Z", -G0, 2)
    type7(d, 7, 2, 30, K, GAP, inacti)
    d.solver(rtol=1e-8, atol_pos=1e-11, atol_vel=1e-9, atol_energy=1e-8)
    d.run(TEND, 0.005)
    return d


def notice(dk):
    """The warnings of `ricochet check` on the deck (stderr)."""
    path = os.path.join(rcval.tmpdir(), "check.rad")
    with open(path, "w") as f:
        f.write(dk.text())
    p = subprocess.run([rcval.RICOCHET, "check", path], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"ricochet check failed ({p.returncode}): {p.stderr.strip()}")
    return [ln for ln in p.stderr.splitlines() if "field Inacti" in ln]


def main():
    p_rest = M * G0 / K
    # the notice: the 5 bumps, by id
    notes = notice(deck(1))
    want = "Inacti 1 leaves 5 of the 13 secondary nodes"
    ids = "nodes " + ", ".join(str(n) for n in BUMPS)
    ok = len(notes) == 1 and want in notes[0] and ids in notes[0]
    rcval.check("type7_inacti.notice", ok,
                f"ricochet check warns once: {notes[0] if notes else '(no notice)'!r} (expected '{want}' and "
                f"'{ids}')")
    # 1. Inacti 1: free fall to the gap, rest on the corners
    r = rcval.Result(rcval.run(deck(1), "inacti1"))
    t_close = r.events("contact_close")
    t_ref = math.sqrt(2.0 * (H0 - GAP) / G0)
    et = rcval.rel(t_close[0], t_ref) if len(t_close) else 1.0
    h = r.pos[-1, 0, 2] - A  # the bottom corners' height
    eh = rcval.rel(h, GAP - p_rest)
    ef = rcval.rel(r.fn[-1, 0], M * G0)
    rcval.check("type7_inacti.fall", et < 1e-6,
                f"the first contact at {t_close[0] if len(t_close) else float('nan'):.9f} s: the corners reach the "
                f"gap after a free fall of h0 - g = {H0 - GAP} m, sqrt(2 (h0 - g) / g) = {t_ref:.9f} s, rel. error "
                f"{et:.1e} (< 1e-6; the bumps, within the gap at t = 0, are out of the contact)")
    rcval.check("type7_inacti.rest", max(eh, ef) < 1e-5,
                f"at rest at t = {r.t[-1]:g} s on the 4 corners: {h:.9e} m above the floor (g - m g / k = "
                f"{GAP - p_rest:.9e} m, {eh:.1e}), force {r.fn[-1, 0]:.12f} N (m g = {M * G0:.12f} N, {ef:.1e}); "
                f"max rel. error < 1e-5")
    # 2. Inacti 0: the bumps act; at rest b higher
    r0 = rcval.Result(rcval.run(deck(0), "inacti0"))
    h0 = r0.pos[-1, 0, 2] - A
    e0 = rcval.rel(h0, GAP - p_rest + BUMP)
    ef0 = rcval.rel(r0.fn[-1, 0], M * G0)
    rcval.check("type7_inacti.inacti0", max(e0, ef0) < 1e-5 and abs((h0 - h) - BUMP) < 1e-8,
                f"Inacti 0: at rest on the bumps, corners {h0:.9e} m above the floor (g - m g / k + b = "
                f"{GAP - p_rest + BUMP:.9e} m, {e0:.1e}), force {r0.fn[-1, 0]:.12f} N ({ef0:.1e}); "
                f"{h0 - h:.9e} m above the Inacti 1 rest (b = {BUMP} m, to 1e-8 m)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(1), "inacti0.rad": deck(0)})
