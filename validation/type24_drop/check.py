"""/INTER/TYPE24: meshed bodies on meshed floors, both ways, against
rigid-body closed forms (README.md).

ricochet's TYPE24 is one TYPE6 contact of its two segment surfaces, both
ways (the nodes of each against the segments of the other), of the linear
law F = k P (Istf 1: k = Stfac), zero gap (docs/theory.md, "TYPE24
contact"):

1. a cube (m = 2 kg, half side a = 0.1 m) whose bottom face is surf_ID1 (one
   segment on its 4 bottom corners) dropped from 5 mm onto a fixed meshed
   floor (surf_ID2, 2 x 2 segments; the floor's centre node lies under the
   cube's face): at rest with the interface force m g and P = m g / k;
2. both ways: a large plate (2 x 2 m, one segment on its 4 corners, 2 kg)
   dropped onto a small fixed pedestal (0.2 x 0.2 m, one segment): no node
   of the plate is over the pedestal, so only the pedestal's 4 nodes
   against the plate's face hold it (a one-way TYPE7 of the plate's nodes
   lets it fall through, checked too): at rest with F = m g, P = m g / k;
3. the cube launched at v0 along x (rotations held), Coulomb Fric mu on the
   card: stops after v0^2 / (2 mu g) at v0 / (mu g);
4. the same with fric_ID naming a /FRICTION card of the Coulomb law;
5. the generalised viscous law written on the card (Ifric 1, mu = Fric + C2
   v): the rigid block's distance v0/(g C2) - (mu0/C2) t_s, t_s = ln(1 + C2
   v0/mu0)/(g C2); that law and Renard filtered (Ifric 3, Ifiltr 3) on the
   card run exactly as the same laws on a /FRICTION card named by fric_ID;
1b. Istf 0: shells under both surfaces (the floor a fixed body of shells,
   the cube's bottom face a shell of negligible mass), k = Stfac E t / 2:
   the same rest.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

M, J, A, G = 2.0, 0.0133, 0.1, 9.81
K = 1.0e5                      # Stfac, Istf 1 [N/m]
P_REST = M * G / K             # resting penetration [m]
MU, V0 = 0.3, 1.0
H0 = 0.005                     # drop height [m]
X0 = -0.5                      # the sliding cube's start: no floor node under it on its way


def type24(d, iid, s1, s2, stfac, fric=0.0, fric_id=0, istf=1, law=None):
    """/INTER/TYPE24 in the Radioss 2022 layout: Istf 1 (by default), the
    rest defaults. law: (Ifric, Ifiltr, Xfreq, C1..C6) written on the card
    (line 6 and Radioss's law lines after it: C1..C5 when Ifric > 0, C6
    when Ifric > 1)."""
    ifric, ifiltr, xfreq, c = law if law else (0, 0, 0.0, ())
    c = list(c) + [0.0] * (6 - len(c))
    extra = ([line(*[("r", v) for v in c[:5]])] if ifric > 0 else []) + ([line(("r", c[5]))] if ifric > 1 else [])
    d.add(f"/INTER/TYPE24/{iid}",
          line(("i", s1), ("i", s2), ("i", istf), ("i", None), ("i", None), ("i", 0), ("i", None), ("i", 0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0), ("r", 0.0)),
          line(("r", stfac), ("r", fric), ("r", None), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", 0.0), ("r", None), ("r", 0.0)),
          line(("i", ifric), ("i", ifiltr), ("r", xfreq), ("i", None), ("i", 0), ("i", None), ("r", None),
               ("i", fric_id)),
          *extra, title="surface to surface")


# Istf 0: the floor and the cube's bottom face shells (/MAT/LAW1 E,
# /PROP/SHELL Thick): k = Stfac E t / 2 = K on both sides
E_SH, T_SH, STFAC0 = 4.0e7, 0.01, 0.5


# Istf 2-5: the cube's bottom shell E_CUBE, T_CUBE (Stfac E t / 2 = 6e5 N/m)
# against the floor's (1e5 N/m), combined
E_CUBE, T_CUBE = 1.2e8, 0.02
K1, K2 = 0.5 * STFAC0 * E_SH * T_SH, 0.5 * STFAC0 * E_CUBE * T_CUBE
K_COMB = {2: 0.5 * (K1 + K2), 3: max(K1, K2), 4: min(K1, K2), 5: K1 * K2 / (K1 + K2)}


def shells(d, pid, segs, rho, title, e=E_SH, t=T_SH):
    """/SHELL/pid on the segments' nodes, /PART, /PROP/SHELL (t) and
    /MAT/LAW1 (e, density rho) of id pid."""
    d.add(f"/SHELL/{pid}", *segs)
    d.add(f"/PART/{pid}", line(("i", pid), ("i", pid)), title=title)
    d.add(f"/PROP/SHELL/{pid}", "", "", line(("i", 0), ("i", 0), ("r", t)), title=title)
    d.add(f"/MAT/LAW1/{pid}", line(("r", rho)), line(("r", e), ("r", 0.3)), title=title)


def floor_seg(d, sid, x, y, nf, h, first):
    """A fixed floor at z = 0: (nf + 1)^2 nodes of no body from node id
    first, centred at (x, y), side 2 h, nf x nf segments, normal +z."""
    n1 = nf + 1
    nodes = [(first + n1 * j + i, x - h + 2.0 * h * i / nf, y - h + 2.0 * h * j / nf, 0.0)
             for j in range(n1) for i in range(n1)]
    d.nodes(nodes)
    segs = []
    for j in range(nf):
        for i in range(nf):
            n0 = first + n1 * j + i
            segs.append(line(("i", len(segs) + 1), ("i", n0), ("i", n0 + 1), ("i", n0 + n1 + 1), ("i", n0 + n1)))
    d.add(f"/SURF/SEG/{sid}", *segs, title="floor")
    return nodes, segs


def cube(title, z0, x0=0.0, v=None, fric=0.0, fric_card=False, istf=1, law=None):
    d = Deck(title)
    corners = [(11 + k, x0 + sx * A, sy * A, z0 + A + sz * A)
               for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                                (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    d.nodes([(1, x0, 0.0, z0 + A)] + corners)
    d.rbody(1, 1, M, [J] * 3, grnod=2, title="cube 2 kg")
    d.grnod(2, [n for n, _, _, _ in corners], title="corners")
    # the bottom face, normal -z (towards the floor)
    bottom = line(("i", 1), ("i", 11), ("i", 14), ("i", 13), ("i", 12))
    d.add("/SURF/SEG/20", bottom, title="cube bottom")
    fnodes, fsegs = floor_seg(d, 30, 0.0, 0.0, 2, 1.0, 101)
    if istf != 1:  # shells under both surfaces; the floor a fixed body
        d.nodes([(100, 0.0, 0.0, 0.0)])
        d.rbody(2, 100, 0.0, [0.0] * 3, grnod=3, title="floor")
        d.grnod(3, [n for n, _, _, _ in fnodes], title="floor nodes")
        d.bcs(2, 3, title="floor fixed")
        shells(d, 5, fsegs, 7800.0, "floor shells")
        shells(d, 6, [line(("i", 9), ("i", 11), ("i", 14), ("i", 13), ("i", 12))], 1e-6,
               "cube bottom shell (1e-6 kg/m^3: 4e-10 kg)", *((E_SH, T_SH) if istf == 0 else (E_CUBE, T_CUBE)))
    if v is not None:
        d.bcs(1, 2, trarot="000 111", title="no rotation")
        d.inivel(1, v, 2)
    d.grav(1, "Z", -G, 2)
    type24(d, 24, 20, 30, K if istf == 1 else STFAC0, fric=0.0 if fric_card else fric, fric_id=9 if fric_card else 0,
           istf=istf, law=None if fric_card else law)
    if fric_card and law:  # the same law on a /FRICTION card (Iform 2: TYPE24's incremental form)
        d.friction(9, ifric=law[0], ifiltr=law[1], xfreq=law[2], iform=2, c=law[3], fric=fric, title="the law")
    elif fric_card:
        d.friction(9, iform=2, fric=MU, title="Coulomb")
    d.run(4.0 if v is None else 0.5, 0.005)
    return d


def drop():
    return cube("TYPE24: a cube's bottom face dropped on a meshed floor", H0)


def type7(d, iid, grnod, surf, stfac):
    """/INTER/TYPE7 (Radioss 2022 layout), Istf 1, the rest defaults."""
    d.add(f"/INTER/TYPE7/{iid}",
          line(("i", grnod), ("i", surf), ("i", 1), ("i", 0), ("i", 0), ("i", None), ("i", 0), ("i", 0), ("i", 0),
               ("i", 0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0)),
          line(("r", stfac), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", 0), ("r", 0.0), ("i", 0), ("i", 0), ("i", 0), ("r", 0.0), ("i", 0)),
          title="plate nodes on the pedestal")


def drop_istf0():
    return cube("TYPE24 Istf 0: a cube's bottom shell dropped on a floor of shells", H0, istf=0)


def drop_istf(istf):
    return cube(f"TYPE24 Istf {istf}: a cube's bottom shell dropped on a floor of shells", H0, istf=istf)


def plate(one_way=False):
    """A 2 x 2 m plate (one segment, 2 kg) over a 0.2 x 0.2 m pedestal;
    one_way: through a TYPE7 of the plate's corners instead."""
    d = Deck("TYPE7: a large plate's corners against a small pedestal" if one_way else
             "TYPE24: a large plate on a small pedestal (the pedestal's nodes hold it)")
    h = 1.0
    corners = [(11 + k, sx * h, sy * h, H0) for k, (sx, sy) in enumerate([(-1, -1), (1, -1), (1, 1), (-1, 1)])]
    d.nodes([(1, 0.0, 0.0, H0)] + corners)
    jp = M * (2 * h) ** 2 / 12
    d.rbody(1, 1, M, [jp, jp, 2 * jp], grnod=2, title="plate 2 kg")
    d.grnod(2, [n for n, _, _, _ in corners], title="plate corners")
    d.add("/SURF/SEG/20", line(("i", 1), ("i", 11), ("i", 14), ("i", 13), ("i", 12)), title="plate underside")
    floor_seg(d, 30, 0.0, 0.0, 1, A, 101)
    d.grav(1, "Z", -G, 2)
    if one_way:
        type7(d, 7, 2, 30, K)
        d.run(0.5, 0.005)
    else:
        type24(d, 24, 20, 30, K)
        d.run(4.0, 0.005)
    return d


def slide(card=False, law=None):
    return cube("TYPE24: a cube sliding to rest", -P_REST, x0=X0, v=(V0, 0.0, 0.0), fric=MU, fric_card=card, law=law)


# 5. the generalised viscous law on the card (Ifric 1): mu = Fric + C2 v
C2_VISC = 0.1                  # [s/m]
LAW_VISC = (1, 0, 0.0, (0.0, C2_VISC))
# 6. Renard (Ifric 3: mu_s, mu_d, mu_max, mu_min, V_cr1, V_cr2) filtered
# (Ifiltr 3, cut-off 200 Hz) on the card
LAW_RENARD = (3, 3, 200.0, (0.3, 0.25, 0.4, 0.2, 0.05, 0.5))


def main():
    # 1. at rest: F = m g, P = m g / k
    for name, deck, z_of in (("cube", drop, lambda r: A - r.pos[-1, 0, 2]), ("plate", plate, lambda r: -r.pos[-1, 0, 2]),
                             ("istf0", drop_istf0, lambda r: A - r.pos[-1, 0, 2])):
        r = rcval.Result(rcval.run(deck(), name))
        pen = z_of(r)
        ep, ef = rcval.rel(pen, P_REST), rcval.rel(r.fn[-1, 0], M * G)
        what = {"cube": "the cube's 4 bottom nodes and the floor's centre node",
                "plate": "the pedestal's 4 nodes alone against the plate's face (both ways)",
                "istf0": f"Istf 0, Stfac {STFAC0} on shells (E {E_SH:g} Pa, t {T_SH} m) under both surfaces: "
                         f"k = Stfac E t / 2 = {0.5 * STFAC0 * E_SH * T_SH:g} N/m"}[name]
        rcval.check(f"type24.rest.{name}", ef < 1e-6 and ep < 1e-5,
                    f"max rel. error {max(ef, ep):.1e}: dropped {H0} m, {what}: at rest at t = {r.t[-1]:g} s with the "
                    f"interface force {r.fn[-1, 0]:.12f} N (m g = {M * G:.12f} N, {ef:.1e} < 1e-6), {pen:.9e} m deep "
                    f"(m g / k = {P_REST:.9e} m, {ep:.1e} < 1e-5)")
    # 1b. Istf 2-5: the two surfaces' shell stiffnesses combined
    for istf in (2, 3, 4, 5):
        r = rcval.Result(rcval.run(drop_istf(istf), f"istf{istf}"))
        kc = K_COMB[istf]
        pen = A - r.pos[-1, 0, 2]
        ep, ef = rcval.rel(pen, M * G / kc), rcval.rel(r.fn[-1, 0], M * G)
        how = {2: "their mean", 3: "the larger", 4: "the smaller", 5: "in series"}[istf]
        rcval.check(f"type24.rest.istf{istf}", ef < 1e-6 and ep < 1e-5,
                    f"max rel. error {max(ef, ep):.1e}: Istf {istf}, the floor's shells k1 = {K1:g} N/m and the "
                    f"cube's bottom shell k2 = {K2:g} N/m (Stfac E t / 2), {how}: k = {kc:.9g} N/m; force "
                    f"{r.fn[-1, 0]:.12f} N (m g, {ef:.1e} < 1e-6), {pen:.9e} m deep (m g / k = {M * G / kc:.9e} m, "
                    f"{ep:.1e} < 1e-5)")
    # 2b. the same plate through a one-way TYPE7 of its corners falls past
    # the pedestal: free fall z = H0 - g t^2 / 2
    r = rcval.Result(rcval.run(plate(one_way=True), "plate_type7"))
    z_ff = H0 - 0.5 * G * r.t[-1] ** 2
    ez = rcval.rel(r.pos[-1, 0, 2], z_ff)
    rcval.check("type24.rest.plate_type7_falls", ez < 1e-9 and abs(r.fn[:, 0]).max() == 0.0,
                f"rel. error {ez:.1e} (< 1e-9): the plate through an /INTER/TYPE7 of its corners (one way) meets "
                f"nothing: at t = {r.t[-1]:g} s at z = {r.pos[-1, 0, 2]:.9f} m (free fall H0 - g t^2/2 = {z_ff:.9f} m), "
                f"largest interface force {abs(r.fn[:, 0]).max():g} N")
    # 3. Coulomb stop with the card's Fric, 4. with /FRICTION via fric_ID
    for name, card in (("fric", False), ("friction_card", True)):
        r = rcval.Result(rcval.run(slide(card), name))
        d_ref = V0**2 / (2 * MU * G)
        t_stop = r.events("fric_stick")
        et = rcval.rel(t_stop[0], V0 / (MU * G)) if len(t_stop) else 1.0
        x_stop = r.pos[r.state_at(t_stop[0]), 0, 0] - X0 if len(t_stop) else 0.0
        e = rcval.rel(x_stop, d_ref)
        rcval.check(f"type24.slide.{name}", max(e, et) < 1e-6,
                    f"max rel. error {max(e, et):.1e}: launched at {V0} m/s, mu {MU} "
                    f"({'fric_ID -> /FRICTION' if card else 'Fric'}): stops at "
                    f"{t_stop[0] if len(t_stop) else float('nan'):.9f} s (v0/(mu g) = {V0 / (MU * G):.9f} s, {et:.1e}) "
                    f"after {x_stop:.9f} m (v0^2/(2 mu g) = {d_ref:.9f} m, {e:.1e}); max rel. error < 1e-6")
    # 5. the generalised viscous law written on the card: m dv/dt = -m g
    # (mu0 + C2 v) stops at t_s = ln(1 + C2 v0 / mu0) / (g C2) after
    # v0 / (g C2) - (mu0 / C2) t_s; and the same as the /FRICTION card of it
    ts_ref = math.log(1.0 + C2_VISC * V0 / MU) / (G * C2_VISC)
    d_ref = V0 / (G * C2_VISC) - MU / C2_VISC * ts_ref
    runs = {}
    for name, law in (("visc", LAW_VISC), ("renard", LAW_RENARD)):
        for card in (False, True):
            r = rcval.Result(rcval.run(slide(card, law), f"{name}_{'card' if card else 'inline'}"))
            t_stop = r.events("fric_stick")
            ts = t_stop[0] if len(t_stop) else float("nan")
            runs[name, card] = (ts, r.pos[r.state_at(ts), 0, 0] - X0 if len(t_stop) else float("nan"), r)
    ts, xs, _ = runs["visc", False]
    e = max(rcval.rel(ts, ts_ref), rcval.rel(xs, d_ref))
    rcval.check("type24.slide.ifric1_inline", e < 1e-6,
                f"max rel. error {e:.1e} (< 1e-6): Ifric 1 on the card (Fric {MU}, C2 {C2_VISC} s/m: mu = Fric + C2 v), "
                f"launched at {V0} m/s: stops at {ts:.9f} s (ln(1 + C2 v0/mu0)/(g C2) = {ts_ref:.9f} s) after "
                f"{xs:.9f} m (v0/(g C2) - (mu0/C2) t_s = {d_ref:.9f} m)")
    for name, what in (("visc", "Ifric 1"), ("renard", "Ifric 3 (Renard), Ifiltr 3 (Xfreq 200 Hz)")):
        (t1, x1, r1), (t2, x2, r2) = runs[name, False], runs[name, True]
        n = min(len(r1.t), len(r2.t))
        dx = float(abs(r1.pos[:n, 0, 0] - r2.pos[:n, 0, 0]).max())
        e = max(rcval.rel(t1, t2), rcval.rel(x1, x2))
        rcval.check(f"type24.slide.{name}_inline_eq_card", e < 1e-9 and dx < 1e-9 and len(r1.t) == len(r2.t),
                    f"{what} on the card against the same law on a /FRICTION card (fric_ID): stops at {t1:.12f} s "
                    f"and {t2:.12f} s after {x1:.12f} m and {x2:.12f} m (max rel. difference {e:.1e} < 1e-9); the "
                    f"largest difference of x over the {n} output states {dx:.1e} m (< 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": drop(), "plate.rad": plate(), "istf0.rad": drop_istf0(), "istf5.rad": drop_istf(5), "slide.rad": slide()})
