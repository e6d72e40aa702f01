"""/INTER/TYPE7: a box's nodes on a meshed floor, against rigid-body closed
forms (README.md).

A cube (m = 2 kg, half side a = 0.1 m, J = 0.0133 kg m^2) is a /RBODY of its
8 corner nodes, all of them the secondary nodes (grnd_IDs) of an
/INTER/TYPE7 whose main surface is a fixed meshed floor (/SURF/SEG, 2 x 2
quadrilaterals on nodes of no body, 2 m square). Istf 1: Stfac is the
interface's stiffness k [N/m]; ricochet's TYPE7 is a TYPE6 contact of the
linear law F = k P over the nodes, one way (docs/theory.md, "TYPE7
contact"):

1. dropped from 5 mm, damped by VISs (default 0.05 of the critical
   damping): at rest with the interface force m g and the penetration
   P = m g / k, the four bottom nodes carrying m g / 4 each (a flat face);
2. launched at v0 along x on its four bottom nodes (rotations held), Coulomb
   Fric mu on the TYPE7 card: stops after v0^2 / (2 mu g) at v0 / (mu g);
1b. the same with a meshed bottom face (5 x 5 secondary nodes) on a 7 x 7
   floor: the same rest;
1c. Istf 0: the floor a fixed body of shells (/MAT/LAW1 E, /PROP/SHELL
   Thick), k = Stfac E t / 2: the same rest;
1d. no gravity: the cube at -1 m/s along z, 3 cm off the centre, onto a
   free slab (7 kg) whose top face is the main surface: the linear
   momentum of the two bodies is conserved;
3. the same with Fric 0 on the card and fric_ID naming a /FRICTION card of
   the Coulomb law (Ifric 0, Iform 2) with Fric mu: the same stop.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, J, A, G = 2.0, 0.0133, 0.1, 9.81
K = 1.0e5                      # Stfac, Istf 1 [N/m]
P_REST = M * G / K             # resting penetration [m]
MU, V0 = 0.3, 1.0
H0 = 0.005                     # drop height of the bottom face [m]


def type7(d, iid, grnod, surf, stfac, fric=0.0, gapmin=0.0, fric_id=0, istf=1, stmin=0.0, stmax=0.0, igap=0,
          fscalegap=0.0, gapmax=0.0):
    """/INTER/TYPE7 in the Radioss 2022 layout: Istf 1 (by default), the rest
    defaults."""
    d.add(f"/INTER/TYPE7/{iid}",
          line(("i", grnod), ("i", surf), ("i", istf), ("i", 0), ("i", igap), ("i", None), ("i", 0), ("i", 0), ("i", 0),
               ("i", 0)),
          line(("r", fscalegap), ("r", gapmax), ("r", 0.0), ("i", 0)),
          line(("r", stmin), ("r", stmax), ("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0)),
          line(("r", stfac), ("r", fric), ("r", gapmin), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", 0), ("r", 0.0), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", fric_id)),
          title="box nodes on the floor")


# Istf 0: the floor a fixed body of shells (/MAT/LAW1 E, /PROP/SHELL Thick):
# k = Stfac E t / 2 = K
E_FLOOR, T_FLOOR, STFAC0 = 4.0e7, 0.01, 0.5
# Istf 2-5, Igap 1, 2: the cube's six faces shells too (density 1e-6 kg/m^3:
# 5e-9 kg), their Stfac E t / 2 = 6e5 N/m, half thickness 0.01 m
E_CUBE, T_CUBE = 1.2e8, 0.02
KM, KS = 0.5 * STFAC0 * E_FLOOR * T_FLOOR, 0.5 * STFAC0 * E_CUBE * T_CUBE
K_COMB = {2: 0.5 * (KM + KS), 3: max(KM, KS), 4: min(KM, KS), 5: KM * KS / (KM + KS)}
GAP_VAR = 0.5 * T_FLOOR + 0.5 * T_CUBE  # Igap 1: gm + gs
FSCALEGAP, GAPMAX = 0.5, 0.006          # Igap 2: min(Fscalegap (gm + gs), Gapmax)
H_GAP = 0.02                            # the drop height of the Igap runs [m]


def deck(title, z0, v=None, fric=0.0, fric_card=False, nb=2, nf=2, istf=1, igap=0):
    """nb: bottom nodes per side of the cube (its 4 corners for 2); nf: floor
    segments per side."""
    d = Deck(title)
    corners = [(11 + k, sx * A, sy * A, z0 + A + sz * A)
               for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                                (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    if nb > 2:  # a meshed bottom face: nb x nb nodes (the corners among them)
        corners = corners[4:] + [(31 + nb * j + i, -A + 2 * A * i / (nb - 1), -A + 2 * A * j / (nb - 1), z0)
                                 for j in range(nb) for i in range(nb)]
    # the floor: (nf + 1)^2 nodes of no body, nf x nf quadrilaterals, normal +z
    n1 = nf + 1
    floor = [(101 + n1 * j + i, -1.0 + 2.0 * i / nf, -1.0 + 2.0 * j / nf, 0.0) for j in range(n1) for i in range(n1)]
    d.nodes([(1, 0.0, 0.0, z0 + A)] + corners + floor)
    d.rbody(1, 1, M, [J] * 3, grnod=2, title="cube 2 kg")
    d.grnod(2, [n for n, _, _, _ in corners], title="corners")
    segs = []
    for j in range(nf):
        for i in range(nf):
            n0 = 101 + n1 * j + i
            segs.append(line(("i", len(segs) + 1), ("i", n0), ("i", n0 + 1), ("i", n0 + n1 + 1), ("i", n0 + n1)))
    d.add("/SURF/SEG/30", *segs, title="floor")
    if istf != 1:  # the floor: a fixed body of shells, their E and thickness
        d.nodes([(100, 0.0, 0.0, 0.0)])
        d.rbody(2, 100, 0.0, [0.0] * 3, grnod=3, title="floor")
        d.grnod(3, [n for n, _, _, _ in floor], title="floor nodes")
        d.bcs(2, 3, title="floor fixed")
        d.add("/SHELL/5", *[s_[:10] + s_[10:] for s_ in segs])
        d.add("/PART/5", line(("i", 5), ("i", 5)), title="floor shells")
        d.add("/PROP/SHELL/5", "", "", line(("i", 0), ("i", 0), ("r", T_FLOOR)), title="floor thickness")
        d.add("/MAT/LAW1/5", line(("r", 7800.0)), line(("r", E_FLOOR), ("r", 0.3)), title="floor material")
    if istf >= 2 or igap:  # the cube's faces: shells on the secondary nodes
        faces = [(11, 14, 13, 12), (15, 16, 17, 18), (11, 12, 16, 15), (12, 13, 17, 16), (13, 14, 18, 17), (14, 11, 15, 18)]
        d.add("/SHELL/6", *[line(("i", 201 + j), *[("i", n) for n in f]) for j, f in enumerate(faces)])
        d.add("/PART/6", line(("i", 6), ("i", 6)), title="cube shells")
        d.add("/PROP/SHELL/6", "", "", line(("i", 0), ("i", 0), ("r", T_CUBE)), title="cube thickness")
        d.add("/MAT/LAW1/6", line(("r", 1e-6)), line(("r", E_CUBE), ("r", 0.3)), title="cube material")
    if v is not None:
        d.bcs(1, 2, trarot="000 111", title="no rotation")
        d.inivel(1, v, 2)
    d.grav(1, "Z", -G, 2)
    type7(d, 7, 2, 30, K if istf == 1 else STFAC0, fric=0.0 if fric_card else fric, fric_id=9 if fric_card else 0,
          istf=istf, igap=igap, fscalegap=FSCALEGAP if igap == 2 else 0.0, gapmax=GAPMAX if igap == 2 else 0.0)
    if fric_card:
        d.friction(9, iform=2, fric=MU, title="Coulomb")
    d.run(4.0 if v is None else 0.5, 0.005)
    return d


def drop():
    return deck("TYPE7: a cube of nodes dropped on a meshed floor", H0)


def drop_meshed():
    return deck("TYPE7: a cube with a meshed bottom (5 x 5 nodes) dropped on a 7 x 7 floor", H0, nb=5, nf=7)


def drop_istf0():
    return deck("TYPE7 Istf 0: a cube of nodes dropped on a floor of shells", H0, istf=0)


def drop_istf(istf):
    return deck(f"TYPE7 Istf {istf}: a cube of shells' nodes dropped on a floor of shells", H0, istf=istf)


def drop_igap(igap):
    return deck(f"TYPE7 Igap {igap}: a cube of shells' nodes dropped on a floor of shells", H_GAP, istf=0, igap=igap)


MS = 7.0  # the free slab's mass [kg]


def free_free():
    """No gravity: the cube of nodes (off the slab's centre by 0.03 m along x)
    at -1 m/s along z onto a free slab (7 kg, 0.6 x 0.6 x 0.1 m) whose top
    face is the main surface (one segment on its body)."""
    d = Deck("TYPE7: a cube of nodes hitting a free slab")
    x0 = 0.03
    corners = [(11 + k, x0 + sx * A, sy * A, 0.01 + A + sz * A)
               for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                                (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    slab = [(21 + k, sx * 0.3, sy * 0.3, -0.05 + sz * 0.05)
            for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                             (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    d.nodes([(1, x0, 0.0, 0.01 + A), (2, 0.0, 0.0, -0.05)] + corners + slab)
    d.rbody(1, 1, M, [J] * 3, grnod=2, title="cube 2 kg")
    d.grnod(2, [n for n, _, _, _ in corners], title="corners")
    js = MS * (0.6**2 + 0.1**2) / 12
    d.rbody(2, 2, MS, [js, js, MS * 0.72 / 12], grnod=3, title="slab 7 kg")
    d.grnod(3, [n for n, _, _, _ in slab], title="slab nodes")
    d.add("/SURF/SEG/30", line(("i", 1), ("i", 25), ("i", 26), ("i", 27), ("i", 28)), title="slab top")
    d.inivel(1, (0.0, 0.0, -1.0), 2)
    type7(d, 7, 2, 30, K)
    d.run(0.1, 0.001)
    return d


def slide(card=False):
    return deck("TYPE7: a cube of nodes sliding to rest", -P_REST, v=(V0, 0.0, 0.0), fric=MU, fric_card=card)


def main():
    # 1. at rest: F = m g, P = m g / k
    r = rcval.Result(rcval.run(drop(), "drop"))
    pen = A - r.pos[-1, 0, 2]
    ep, ef = rcval.rel(pen, P_REST), rcval.rel(r.fn[-1, 0], M * G)
    rcval.check("type7.rest.force", ef < 1e-6,
                f"dropped {H0} m: at rest at t = {r.t[-1]:g} s with the interface force {r.fn[-1, 0]:.12f} N "
                f"(m g = {M * G:.12f} N), rel. error {ef:.1e} (< 1e-6; VISs 0.05 damps the bounces)")
    rcval.check("type7.rest.penetration", ep < 1e-5,
                f"resting {pen:.9e} m deep (m g / k = {P_REST:.9e} m, k = Stfac = {K:g} N/m), rel. error {ep:.1e} "
                f"(< 1e-5: the force is the law at the state P_e, docs/theory.md 2.7, which the geometric P follows to 2e-6)")
    # 1b. a meshed bottom face (25 nodes) on a finer floor: the same rest
    r = rcval.Result(rcval.run(drop_meshed(), "meshed"))
    pen = A - r.pos[-1, 0, 2]
    ep, ef = rcval.rel(pen, P_REST), rcval.rel(r.fn[-1, 0], M * G)
    rcval.check("type7.rest.meshed", ef < 1e-6 and ep < 1e-5,
                f"max rel. error {max(ef, ep):.1e}: a bottom face of 5 x 5 secondary nodes on a 7 x 7 floor (several nodes per floor segment): "
                f"force {r.fn[-1, 0]:.12f} N (m g, {ef:.1e} < 1e-6), {pen:.9e} m deep (m g / k, {ep:.1e} < 1e-5)")
    # 1c. Istf 0: k = Stfac E t / 2 from the floor's shells
    r = rcval.Result(rcval.run(drop_istf0(), "istf0"))
    k0 = 0.5 * STFAC0 * E_FLOOR * T_FLOOR
    pen = A - r.pos[-1, 0, 2]
    ep, ef = rcval.rel(pen, M * G / k0), rcval.rel(r.fn[-1, 0], M * G)
    rcval.check("type7.rest.istf0", ef < 1e-6 and ep < 1e-5,
                f"max rel. error {max(ef, ep):.1e}: Istf 0, Stfac {STFAC0} on a floor of shells (E {E_FLOOR:g} Pa, t {T_FLOOR} m): k = Stfac E t / 2 = "
                f"{k0:g} N/m; force {r.fn[-1, 0]:.12f} N (m g, {ef:.1e} < 1e-6), {pen:.9e} m deep (m g / k = "
                f"{M * G / k0:.9e} m, {ep:.1e} < 1e-5)")
    # 1e. Istf 2-5: the floor's and the cube's shell stiffnesses combined
    for istf in (2, 3, 4, 5):
        r = rcval.Result(rcval.run(drop_istf(istf), f"istf{istf}"))
        kc = K_COMB[istf]
        pen = A - r.pos[-1, 0, 2]
        ep, ef = rcval.rel(pen, M * G / kc), rcval.rel(r.fn[-1, 0], M * G)
        how = {2: "their mean", 3: "the larger", 4: "the smaller", 5: "in series"}[istf]
        rcval.check(f"type7.rest.istf{istf}", ef < 1e-6 and ep < 1e-5,
                    f"max rel. error {max(ef, ep):.1e}: Istf {istf}, the floor's shells k_m = {KM:g} N/m and the "
                    f"cube's k_s = {KS:g} N/m (Stfac E t / 2), {how}: k = {kc:.9g} N/m; force {r.fn[-1, 0]:.12f} N "
                    f"(m g, {ef:.1e} < 1e-6), {pen:.9e} m deep (m g / k = {M * G / kc:.9e} m, {ep:.1e} < 1e-5)")
    # 1f. Igap 1, 2: the contact starts at the variable gap and the cube
    # rests the gap less m g / k above the floor
    for igap, gap in ((1, GAP_VAR), (2, min(FSCALEGAP * GAP_VAR, GAPMAX))):
        r = rcval.Result(rcval.run(drop_igap(igap), f"igap{igap}"))
        k0 = KM
        h = r.pos[-1, 0, 2] - A
        eh, ef = rcval.rel(h, gap - M * G / k0), rcval.rel(r.fn[-1, 0], M * G)
        t_close = r.events("contact_close")
        t_ref = math.sqrt(2.0 * (H_GAP - gap) / G)
        et = rcval.rel(t_close[0], t_ref) if len(t_close) else 1.0
        what = "gm + gs" if igap == 1 else f"min(Fscalegap {FSCALEGAP} (gm + gs), Gapmax {GAPMAX})"
        rcval.check(f"type7.rest.igap{igap}", max(ef, eh, et) < 1e-5,
                    f"max rel. error {max(ef, eh, et):.1e}: Igap {igap}, gap {what} = {gap:g} m (half the floor's "
                    f"{T_FLOOR} m and the cube's {T_CUBE} m shells): dropped from {H_GAP} m, contact at "
                    f"{t_close[0] if len(t_close) else float('nan'):.9f} s (free fall to the gap sqrt(2 (h0 - gap) / g) "
                    f"= {t_ref:.9f} s, {et:.1e}); at rest {h:.9e} m above the floor (gap - m g / k = "
                    f"{gap - M * G / k0:.9e} m, {eh:.1e}), force {r.fn[-1, 0]:.12f} N ({ef:.1e}); max rel. error < 1e-5")
    # 1d. free-free: the contact's forces are equal and opposite at the nodes
    r = rcval.Result(rcval.run(free_free(), "free"))
    p = M * r.vel[:, 0] + MS * r.vel[:, 1]
    ep = np.abs(p - p[0]).max() / (M * 1.0)
    t_sep = r.contact_ends()
    rcval.check("type7.free.momentum", ep < 1e-12 and len(t_sep) > 0 and r.vel[-1, 1, 2] < 0,
                f"error / (m v0) {ep:.1e} (< 1e-12): the cube at 1 m/s onto a free slab, off its centre: linear "
                f"momentum over the run; the contact opened at {t_sep[0] if len(t_sep) else float('nan'):.6f} s, "
                f"the slab leaves at {r.vel[-1, 1, 2]:.6f} m/s")
    # 2. Coulomb stop with the card's Fric, 3. with /FRICTION via fric_ID
    for name, card in (("fric", False), ("friction_card", True)):
        r = rcval.Result(rcval.run(slide(card), name))
        d_ref = V0**2 / (2 * MU * G)
        t_stop = r.events("fric_stick")
        et = rcval.rel(t_stop[0], V0 / (MU * G)) if len(t_stop) else 1.0
        x_stop = r.pos[r.state_at(t_stop[0]), 0, 0] if len(t_stop) else 0.0
        e = rcval.rel(x_stop, d_ref)
        # after the stop the stick springs (stiffness k per node, the shares
        # of mu m g) unload: the box moves back by mu m g / k
        x_rest = d_ref - MU * M * G / K
        er = rcval.rel(r.pos[-1, 0, 0], x_rest)
        rcval.check(f"type7.slide.{name}", max(e, et, er) < 1e-6,
                    f"max rel. error {max(e, et, er):.1e}: launched at {V0} m/s on its 4 bottom nodes, mu {MU} ({'fric_ID -> /FRICTION' if card else 'Fric'}): "
                    f"stops at {t_stop[0] if len(t_stop) else float('nan'):.9f} s (v0/(mu g) = {V0 / (MU * G):.9f} s, "
                    f"{et:.1e}) at x = {x_stop:.9f} m (v0^2/(2 mu g) = {d_ref:.9f} m, {e:.1e}); at rest at "
                    f"x = {r.pos[-1, 0, 0]:.9f} m (v0^2/(2 mu g) - mu m g/k = {x_rest:.9f} m, {er:.1e}); max rel. "
                    f"error < 1e-6")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": drop(), "meshed.rad": drop_meshed(), "istf0.rad": drop_istf0(), "istf5.rad": drop_istf(5), "igap1.rad": drop_igap(1), "free.rad": free_free(), "slide.rad": slide()})
