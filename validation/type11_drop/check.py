"""/INTER/TYPE11 (edge to edge) and /INTER/TYPE19 (node to surface and edge
to edge) between boxes, against rigid-body closed forms (README.md).

ricochet models both cards between two boxes (docs/theory.md 3.9): a
/SURF/BOX or a closed box mesh (a /SURF/SEG of 6 quadrilaterals on the 8
corners of a rectangular box, taken as that box) on each side, TYPE11's
through a /LINE/SURF of one surface. TYPE11 is the box pair's 144 edge
pairs alone (no corner against a face); TYPE19 the whole box pair (the
corners of each against the faces of the other, and the edges). One
contact of the linear law F = k P (Istf 1: k = Stfac) shared by the
touching points.

1. TYPE11, two /SURF/BOX: a bar (0.6 x 0.1 x 0.1 m, 6 kg) dropped across a
   fixed bar laid the other way: held by the crossing edges alone: at rest
   with F = m g, P = m g / k, the deepest point at a crossing of two edges;
2. TYPE11, the same bars as closed box meshes: the same rest;
3. TYPE11, a box dropped flat onto a fixed box, its bottom edges inside
   the other's top face: no edge meets an edge, the corners do not act:
   free fall, no force;
4. TYPE19, the same flat box: its corners against the face hold it:
   F = m g, P = m g / k;
5. TYPE19, the bars of 1: the edges hold the bar: F = m g, P = m g / k;
   with Iedge 1 (the free edges: a closed box has none) the corners alone
   act, none is over a face: the bar falls through freely;
6. TYPE11 impact, no gravity, frictionless, undamped (VISs 1e-12): a bar
   at 0.5 m/s strikes an equal free bar laid across it, edge on edge at
   four crossings symmetric about the line of the centres: a central
   elastic impact of equal masses: the momentum kept, the velocities
   exchanged (the striker stops, the struck bar leaves at 0.5 m/s); the
   peak force of the linear law v sqrt(k m*) and the contact time
   pi sqrt(m* / k), m* = m / 2.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

G = 9.81                     # gravity [m/s^2]
K = 1.0e5                    # Stfac, Istf 1 [N/m]
H0 = 0.005                   # drop height [m]
L8, W8, M8 = 0.6, 0.1, 6.0   # the bars: length, width [m], mass of the upper one [kg]
Y8 = -0.021                  # the upper bar's offset along the lower one [m]
ZETA = 0.7                   # VISs
MB = 15.0                    # the box resting flat on a box [kg], 0.2 x 0.12 x 0.08 m


def type11(d, iid, l1, l2, stfac, viss=0.0):
    """/INTER/TYPE11 in the Radioss 2022 layout: Istf 1, the rest defaults."""
    d.add(f"/INTER/TYPE11/{iid}",
          line(("i", l1), ("i", l2), ("i", 1), ("i", 0), ("i", 0), ("i", None), ("i", 0), ("i", 0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0)),
          line(("r", stfac), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", viss), ("r", 0.0), ("r", 0.0)),
          line(*[("i", None)] * 9, ("i", 0)),
          title="edge to edge")


def type19(d, iid, s1, s2, stfac, viss=0.0, iedge=0):
    """/INTER/TYPE19 in the Radioss 2022 layout: Istf 1, the rest defaults
    (Iedge 0: every edge)."""
    d.add(f"/INTER/TYPE19/{iid}",
          line(("i", s1), ("i", s2), ("i", 1), ("i", 0), ("i", 0), ("i", iedge), ("i", 0), ("i", 0), ("i", 0)),
          line(("r", 0.0), ("r", 0.0)),
          line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0)),
          line(("r", stfac), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", None), ("i", 0), ("r", viss), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", 0), ("r", 0.0), ("i", 0), ("i", 0), ("i", None), ("i", None), ("i", None), ("i", 0)),
          title="nodes to surface and edges")


def lines(d, *pairs):
    """/LINE/SURF/lid of one surface each: pairs of (lid, sid)."""
    for lid, sid in pairs:
        d.add(f"/LINE/SURF/{lid}", line(("i", sid)), title=f"edges of /SURF/{sid}")


def box_mesh(d, sid, first, x, half, title):
    """The 8 corners (node ids first..first+7) of a box centred at x with
    half-sizes half, and /SURF/SEG/sid of its 6 faces, outward."""
    c = [(first + k, x[0] + sx * half[0], x[1] + sy * half[1], x[2] + sz * half[2])
         for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                          (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    d.nodes(c)
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    d.add(f"/SURF/SEG/{sid}", *[line(("i", j + 1), *[("i", first + q) for q in fc]) for j, fc in enumerate(faces)],
          title=title)
    return [n for n, _, _, _ in c]


JB = (M8 * 2 * W8**2 / 12, M8 * (L8**2 + W8**2) / 12, M8 * (L8**2 + W8**2) / 12)


def bars(card=11, iedge=0):
    """A bar along x (/SURF/BOX 18 on body 8) dropped across a fixed bar along
    y (/SURF/BOX 1): TYPE11 through /LINE/SURF 118 and 101, or TYPE19 (of
    Iedge iedge)."""
    d = Deck(f"TYPE{card}: a bar dropped across a bar, edge on edge" + (f", Iedge {iedge}" if iedge else ""))
    d.box(1, 0, (0.0, 0.0, -W8 / 2), (W8 / 2, L8 / 2, W8 / 2), title="fixed bar along y, top face z = 0")
    x = (0.0, Y8, W8 / 2 + H0)
    d.nodes([(8, *x)])
    d.grnod(8, [8], title="bar")
    d.rbody(8, 8, M8, JB, grnod=8, title="bar 6 kg")
    d.box(18, 8, x, (L8 / 2, W8 / 2, W8 / 2), title="bar along x, across the fixed one")
    if card == 11:
        lines(d, (118, 18), (101, 1))
        type11(d, 11, 118, 101, K, viss=ZETA)
    else:
        type19(d, 19, 18, 1, K, viss=ZETA, iedge=iedge)
    d.grav(1, "Z", -G, 8)
    d.run(0.1 if iedge == 1 else 1.0, 0.01)
    return d


def mesh_bars():
    """The bars of bars() as closed box meshes, TYPE11."""
    d = Deck("TYPE11: a meshed bar dropped across a meshed bar")
    x = (0.0, Y8, W8 / 2 + H0)
    d.nodes([(8, *x)])
    corners = box_mesh(d, 18, 81, x, (L8 / 2, W8 / 2, W8 / 2), "bar along x, across the fixed one")
    d.grnod(8, corners, title="bar corners")
    d.rbody(8, 8, M8, JB, grnod=8, title="bar 6 kg")
    box_mesh(d, 1, 91, (0.0, 0.0, -W8 / 2), (W8 / 2, L8 / 2, W8 / 2), "fixed bar along y, top face z = 0")
    lines(d, (118, 18), (101, 1))
    type11(d, 11, 118, 101, K, viss=ZETA)
    d.grav(1, "Z", -G, 8)
    d.run(1.0, 0.01)
    return d


def flat(card=19):
    """A box (/SURF/BOX 15 on body 5) dropped flat onto a fixed 1 m cube
    (/SURF/BOX 1): its 4 bottom corners over the cube's top face."""
    d = Deck(f"TYPE{card}: a box dropped flat on a box")
    d.box(1, 0, (0.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="fixed 1 m cube, top face z = 0")
    x = (0.1, -0.05, 0.04 + H0)
    d.nodes([(5, *x)])
    d.grnod(5, [5], title="box")
    d.rbody(5, 5, MB, (MB * (0.12**2 + 0.08**2) / 12, MB * (0.2**2 + 0.08**2) / 12, MB * (0.2**2 + 0.12**2) / 12),
            grnod=5, title="box 15 kg")
    d.box(15, 5, x, (0.1, 0.06, 0.04), title="box on the cube")
    if card == 11:
        lines(d, (115, 15), (101, 1))
        type11(d, 11, 115, 101, K, viss=ZETA)
    else:
        type19(d, 19, 15, 1, K, viss=ZETA)
    d.grav(1, "Z", -G, 5)
    d.run(1.0 if card == 19 else 0.1, 0.01)
    return d


V6 = 0.5                     # the striking bar's speed [m/s]


def impact():
    """A bar along x (/SURF/BOX 18, body 8) at V6 downwards onto an equal
    free bar along y (/SURF/BOX 19, body 9), 1 mm below it, centred under
    it: TYPE11, no gravity, VISs 1e-12."""
    d = Deck("TYPE11: a bar striking an equal bar, edge on edge")
    x8, x9 = (0.0, 0.0, W8 / 2 + 0.001), (0.0, 0.0, -W8 / 2)
    d.nodes([(8, *x8), (9, *x9)])
    d.grnod(8, [8], title="striker")
    d.grnod(9, [9], title="struck")
    d.rbody(8, 8, M8, JB, grnod=8, title="striker 6 kg")
    d.rbody(9, 9, M8, (JB[1], JB[0], JB[2]), grnod=9, title="struck 6 kg")
    d.box(18, 8, x8, (L8 / 2, W8 / 2, W8 / 2), title="striker along x")
    d.box(19, 9, x9, (W8 / 2, L8 / 2, W8 / 2), title="struck along y")
    lines(d, (118, 18), (119, 19))
    type11(d, 11, 118, 119, K, viss=1e-12)
    d.inivel(1, (0.0, 0.0, -V6), 8)
    d.run(0.05, 0.001)
    return d


def edge_rest(name, r):
    with Dataset(r.path) as nc:
        x = nc["inter_contact_point"][-1, 0]
    fn, p = r.fn[-1, 0], r.pen[-1, 0]
    e1, e2 = rcval.rel(fn, M8 * G), rcval.rel(p, M8 * G / K)
    crossing = abs(abs(x[0]) - W8 / 2) < 1e-3 and abs(abs(x[1] - Y8) - W8 / 2) < 1e-3
    rcval.check(name, e1 < 1e-6 and e2 < 5e-5 and crossing,
                f"max rel. error {max(e1, e2):.1e}: F = {fn:.9g} N (m g = {M8 * G:.9g} N, {e1:.1e} < 1e-6), "
                f"P = {p:.9e} m (m g / k = {M8 * G / K:.9e} m, {e2:.1e} < 5e-5); deepest point ({x[0]:.5f}, "
                f"{x[1]:.5f}, {x[2]:.2e}) m at a crossing of two edges: {crossing}")


def main():
    # 1, 2. TYPE11 edge on edge: two /SURF/BOX, two closed box meshes
    edge_rest("type11.bar.rest", rcval.Result(rcval.run(bars(11), "bars11")))
    edge_rest("type11.mesh_bar.rest", rcval.Result(rcval.run(mesh_bars(), "mesh_bars11")))
    # 3. TYPE11 has no corner against a face: the flat box falls through
    r = rcval.Result(rcval.run(flat(11), "flat11"))
    z_ff = 0.04 + H0 - 0.5 * G * r.t[-1] ** 2
    ez = abs(r.pos[-1, 0, 2] - z_ff) / (0.5 * G * r.t[-1] ** 2)
    rcval.check("type11.flat.falls", ez < 1e-7 and abs(r.fn[:, 0]).max() == 0.0,
                f"error {ez:.1e} of the fall (< 1e-7): edges only, the box's bottom edges inside the cube's top face meet "
                f"no edge: z = {r.pos[-1, 0, 2]:.9f} m at t = {r.t[-1]:g} s (free fall {z_ff:.9f} m), largest "
                f"interface force {abs(r.fn[:, 0]).max():g} N")
    # 4. TYPE19: the corners against the face hold it
    r = rcval.Result(rcval.run(flat(19), "flat19"))
    fn, p = r.fn[-1, 0], r.pen[-1, 0]
    e1, e2 = rcval.rel(fn, MB * G), rcval.rel(p, MB * G / K)
    rcval.check("type19.flat.rest", e1 < 1e-6 and e2 < 5e-5,
                f"max rel. error {max(e1, e2):.1e}: a 15 kg box dropped flat on a fixed box (TYPE19, its 4 bottom "
                f"corners on the top face): F = {fn:.9g} N (m g = {MB * G:.9g} N, {e1:.1e} < 1e-6), P = {p:.9e} m "
                f"(m g / k = {MB * G / K:.9e} m, {e2:.1e} < 5e-5)")
    # 5. TYPE19: the edges hold the bar
    edge_rest("type19.bar.rest", rcval.Result(rcval.run(bars(19), "bars19")))
    # 5b. TYPE19 Iedge 1: the surfaces' free edges, none on a closed box:
    # the corners alone, and no corner of either bar is over the other's
    # faces: the bar falls through
    r = rcval.Result(rcval.run(bars(19, iedge=1), "bars19_iedge1"))
    z_ff = W8 / 2 + H0 - 0.5 * G * r.t[-1] ** 2
    ez = abs(r.pos[-1, 0, 2] - z_ff) / (0.5 * G * r.t[-1] ** 2)
    rcval.check("type19.iedge1.bar.falls", ez < 1e-7 and abs(r.fn[:, 0]).max() == 0.0,
                f"error {ez:.1e} of the fall (< 1e-7): Iedge 1 (free edges: a closed box has none), corners alone: "
                f"z = {r.pos[-1, 0, 2]:.9f} m at t = {r.t[-1]:g} s (free fall {z_ff:.9f} m), largest interface force "
                f"{abs(r.fn[:, 0]).max():g} N")
    # 6. a central elastic impact of equal masses through the edges
    r = rcval.Result(rcval.run(impact(), "impact"))
    p0, p1 = M8 * (r.vel[0, 0] + r.vel[0, 1]), M8 * (r.vel[-1, 0] + r.vel[-1, 1])
    em = abs(p1 - p0).max() / (M8 * V6)
    ev = max(abs(r.vel[-1, 0, 2]), abs(r.vel[-1, 1, 2] + V6), abs(r.vel[-1, :, :2]).max()) / V6
    opened = abs(r.fn[-1, 0]) == 0.0 and r.fn[:, 0].max() > 0
    rcval.check("type11.impact.momentum", em < 1e-9 and opened,
                f"rel. error {em:.1e} (< 1e-9): the two bars' momentum {p0[2]:.12f} -> {p1[2]:.12f} kg m/s through the "
                f"edge impact (peak force {r.fn[:, 0].max():.6g} N, open at the end: {opened})")
    rcval.check("type11.impact.exchange", ev < 1e-6,
                f"rel. error {ev:.1e} (< 1e-6): equal masses, central, elastic: the striker's v_z {r.vel[-1, 0, 2]:.3e} "
                f"m/s (0), the struck bar's {r.vel[-1, 1, 2]:.9f} m/s (-{V6}), no sideways velocity")
    with Dataset(r.path) as nc:
        fpk, dur = float(nc["impact_peak_force"][0]), float(nc["impact_duration"][0])
    ms = M8 / 2
    f_ref, t_ref = V6 * math.sqrt(K * ms), math.pi * math.sqrt(ms / K)
    e1, e2 = rcval.rel(fpk, f_ref), rcval.rel(dur, t_ref)
    rcval.check("type11.impact.law", max(e1, e2) < 1e-6,
                f"max rel. error {max(e1, e2):.1e} (< 1e-6): peak force {fpk:.9g} N (v sqrt(k m*) = {f_ref:.9g} N, "
                f"{e1:.1e}), contact time {dur:.9g} s (pi sqrt(m*/k) = {t_ref:.9g} s, {e2:.1e})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"bars.rad": bars(11), "mesh_bars.rad": mesh_bars(), "flat11.rad": flat(11),
                               "flat19.rad": flat(19), "bars19.rad": bars(19), "impact.rad": impact()})
