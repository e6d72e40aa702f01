"""/INTER/TYPE25: a meshed cube on a meshed floor and two boxes meeting edge
on edge, against rigid-body closed forms (README.md).

ricochet's TYPE25 is TYPE24's contact (docs/theory.md 3.8): one contact of
its two surfaces, both ways, of the linear law F = k P (Istf 1: k = Stfac),
zero gap. Between two /SURF/BOX surfaces the pair is the box pair of
docs/theory.md 2.7: the corners of each against the faces of the other and
the 12 edges of each against those of the other (Iedge); between segment
surfaces Iedge is refused (nodes against segments only).

1. the cube of validation/type24_drop (bottom face surf_ID1, one segment)
   dropped onto the fixed 2 x 2 floor through TYPE25: at rest with the
   interface force m g and P = m g / k;
2. the plate on the pedestal (both ways): F = m g, P = m g / k;
3. edge on edge, Iedge 2: a bar (0.6 x 0.1 x 0.1 m, 6 kg, /SURF/BOX)
   dropped across a fixed bar laid the other way: no corner of either is
   over the other's faces, only the crossing edges hold it: at rest with
   F = m g, P = m g / k, the deepest point at a crossing of two edges;
3c. the same bars as closed box meshes (/SURF/SEG of 6 faces on 8
   corners), Iedge 2: taken as their boxes, the same rest; with Iedge 0
   (nodes against segments only) the upper bar falls through;
3b. corners against faces: a box (15 kg) dropped flat onto a fixed box
   through TYPE25 (two /SURF/BOX, Iedge 0): F = m g, P = m g / k;
4. Coulomb stop of the cube with Fric: v0^2 / (2 mu g) at v0 / (mu g).
"""
import importlib.util
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

# the decks of validation/type24_drop, their interface card made a TYPE25
_spec = importlib.util.spec_from_file_location("type24_check", os.path.join(HERE, "..", "type24_drop", "check.py"))
t24 = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(t24)
M, G, K, A, MU, V0, H0, X0 = t24.M, t24.G, t24.K, t24.A, t24.MU, t24.V0, t24.H0, t24.X0
P_REST = M * G / K


def type25(d, iid, s1, s2, stfac, fric=0.0, fric_id=0, istf=1, iedge=0, viss=0.0, law=None):
    """/INTER/TYPE25 in the Radioss 2022 layout: Istf 1 (by default), the
    rest defaults; law: (Ifric, Ifiltr, Xfreq, C1..C6) on the card, as
    type24_drop's."""
    ifric, ifiltr, xfreq, c = law if law else (0, 0, 0.0, ())
    c = list(c) + [0.0] * (6 - len(c))
    extra = ([line(*[("r", v) for v in c[:5]])] if ifric > 0 else []) + ([line(("r", c[5]))] if ifric > 1 else [])
    d.add(f"/INTER/TYPE25/{iid}",
          line(("i", s1), ("i", s2), ("i", istf), ("i", 0), ("i", 0), ("i", 0), ("i", None), ("i", 0), ("i", iedge)),
          line(("i", 0), ("i", None), ("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0)),
          line(("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0), ("r", 0.0)),
          line(("r", stfac), ("r", fric), ("r", None), ("r", 0.0), ("r", 0.0)),
          line(("i", 0), ("i", None), ("i", 0), ("i", 0), ("r", viss)),
          line(("i", ifric), ("i", ifiltr), ("r", xfreq), ("i", None), ("i", 0), ("i", None), ("r", None),
               ("i", fric_id)),
          *extra, title="surface to surface")


t24.type24 = type25  # the type24_drop decks now write TYPE25 cards


def as25(make):
    """The type24_drop deck of `make`, its run title naming TYPE25."""
    def f():
        d = make()
        d.cards[2] = d.cards[2].replace("TYPE24", "TYPE25")
        return d
    return f


drop, plate, slide = as25(t24.drop), as25(t24.plate), as25(t24.slide)


L8, W8, M8 = 0.6, 0.1, 6.0   # the bars: length, width [m], mass of the upper one [kg]
Y8 = -0.021                  # the upper bar's offset along the lower one [m]
ZETA = 0.7                   # VISs of the bars' contact


def bars():
    """A bar along x (/SURF/BOX 18 on body 8) dropped across a fixed bar along
    y (/SURF/BOX 1), TYPE25 Iedge 2."""
    d = Deck("TYPE25 Iedge 2: a bar dropped across a bar, edge on edge")
    d.box(1, 0, (0.0, 0.0, -W8 / 2), (W8 / 2, L8 / 2, W8 / 2), title="fixed bar along y, top face z = 0")
    x = (0.0, Y8, W8 / 2 + H0)
    d.nodes([(8, *x)])
    d.grnod(8, [8], title="bar")
    j = (M8 * 2 * W8**2 / 12, M8 * (L8**2 + W8**2) / 12, M8 * (L8**2 + W8**2) / 12)
    d.rbody(8, 8, M8, j, grnod=8, title="bar 6 kg")
    d.box(18, 8, x, (L8 / 2, W8 / 2, W8 / 2), title="bar along x, across the fixed one")
    type25(d, 25, 18, 1, K, iedge=2, viss=ZETA)
    d.grav(1, "Z", -G, 8)
    d.run(1.0, 0.01)
    return d


def box_mesh(d, sid, first, x, half, title):
    """The 8 corners (node ids first..first+7) of a box centred at x with
    half-sizes half, and /SURF/SEG/sid of its 6 faces, outward."""
    c = [(first + k, x[0] + sx * half[0], x[1] + sy * half[1], x[2] + sz * half[2])
         for k, (sx, sy, sz) in enumerate([(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1),
                                          (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)])]
    d.nodes(c)
    f = first
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    d.add(f"/SURF/SEG/{sid}", *[line(("i", j + 1), *[("i", f + q) for q in fc]) for j, fc in enumerate(faces)],
          title=title)
    return [n for n, _, _, _ in c]


def mesh_bars(iedge=2):
    """The bars of bars() as closed box meshes (/SURF/SEG of 6 faces on 8
    corners): the upper one on body 8, the lower one on nodes of no body."""
    d = Deck(f"TYPE25 Iedge {iedge}: a meshed bar dropped across a meshed bar")
    x = (0.0, Y8, W8 / 2 + H0)
    d.nodes([(8, *x)])
    corners = box_mesh(d, 18, 81, x, (L8 / 2, W8 / 2, W8 / 2), "bar along x, across the fixed one")
    d.grnod(8, corners, title="bar corners")
    j = (M8 * 2 * W8**2 / 12, M8 * (L8**2 + W8**2) / 12, M8 * (L8**2 + W8**2) / 12)
    d.rbody(8, 8, M8, j, grnod=8, title="bar 6 kg")
    box_mesh(d, 1, 91, (0.0, 0.0, -W8 / 2), (W8 / 2, L8 / 2, W8 / 2), "fixed bar along y, top face z = 0")
    type25(d, 25, 18, 1, K, iedge=iedge, viss=ZETA)
    d.grav(1, "Z", -G, 8)
    d.run(1.0 if iedge else 0.3, 0.01)
    return d


MB = 15.0                    # the box resting flat on a box [kg], 0.2 x 0.12 x 0.08 m


def flat():
    """A box (/SURF/BOX 15 on body 5) dropped flat onto a fixed 1 m cube
    (/SURF/BOX 1): its 4 bottom corners on the cube's top face, TYPE25
    Iedge 0."""
    d = Deck("TYPE25: a box dropped flat on a box (corners against faces)")
    d.box(1, 0, (0.0, 0.0, -0.5), (0.5, 0.5, 0.5), title="fixed 1 m cube, top face z = 0")
    x = (0.1, -0.05, 0.04 + H0)
    d.nodes([(5, *x)])
    d.grnod(5, [5], title="box")
    d.rbody(5, 5, MB, (MB * (0.12**2 + 0.08**2) / 12, MB * (0.2**2 + 0.08**2) / 12, MB * (0.2**2 + 0.12**2) / 12),
            grnod=5, title="box 15 kg")
    d.box(15, 5, x, (0.1, 0.06, 0.04), title="box on the cube")
    type25(d, 25, 15, 1, K, viss=ZETA)
    d.grav(1, "Z", -G, 5)
    d.run(1.0, 0.01)
    return d


def main():
    # 1, 2. at rest: F = m g, P = m g / k
    for name, deck, z_of in (("cube", drop, lambda r: A - r.pos[-1, 0, 2]),
                             ("plate", plate, lambda r: -r.pos[-1, 0, 2])):
        r = rcval.Result(rcval.run(deck(), name))
        pen = z_of(r)
        ep, ef = rcval.rel(pen, P_REST), rcval.rel(r.fn[-1, 0], M * G)
        rcval.check(f"type25.rest.{name}", ef < 1e-6 and ep < 1e-5,
                    f"max rel. error {max(ef, ep):.1e}: at rest at t = {r.t[-1]:g} s with the interface force "
                    f"{r.fn[-1, 0]:.12f} N (m g, {ef:.1e} < 1e-6), {pen:.9e} m deep (m g / k = {P_REST:.9e} m, "
                    f"{ep:.1e} < 1e-5)")
    # 3. edge on edge
    r = rcval.Result(rcval.run(bars(), "bars"))
    with Dataset(r.path) as nc:
        x = nc["inter_contact_point"][-1, 0]
    fn, p = r.fn[-1, 0], r.pen[-1, 0]
    e1, e2 = rcval.rel(fn, M8 * G), rcval.rel(p, M8 * G / K)
    crossing = abs(abs(x[0]) - W8 / 2) < 1e-3 and abs(abs(x[1] - Y8) - W8 / 2) < 1e-3
    rcval.check("type25.edges.bar.rest", e1 < 1e-6 and e2 < 5e-5 and crossing,
                f"max rel. error {max(e1, e2):.1e}: the bar across the bar (Iedge 2, two /SURF/BOX): F = {fn:.9g} N "
                f"(m g = {M8 * G:.9g} N, {e1:.1e} < 1e-6), P = {p:.9e} m (m g / k = {M8 * G / K:.9e} m, {e2:.1e} < 5e-5); "
                f"deepest point ({x[0]:.5f}, {x[1]:.5f}, {x[2]:.2e}) m at a crossing of two edges: {crossing}")
    # 3c. the same bars as closed box meshes: Iedge 2 takes them as their
    # boxes (the same rest); Iedge 0, nodes against segments, they pass
    # through each other
    r = rcval.Result(rcval.run(mesh_bars(), "mesh_bars"))
    with Dataset(r.path) as nc:
        x = nc["inter_contact_point"][-1, 0]
    fn, p = r.fn[-1, 0], r.pen[-1, 0]
    e1, e2 = rcval.rel(fn, M8 * G), rcval.rel(p, M8 * G / K)
    crossing = abs(abs(x[0]) - W8 / 2) < 1e-3 and abs(abs(x[1] - Y8) - W8 / 2) < 1e-3
    rcval.check("type25.edges.mesh_bar.rest", e1 < 1e-6 and e2 < 5e-5 and crossing,
                f"max rel. error {max(e1, e2):.1e}: two meshed bars (/SURF/SEG, 6 faces on 8 corners each), Iedge 2: "
                f"F = {fn:.9g} N ({e1:.1e} < 1e-6), P = {p:.9e} m ({e2:.1e} < 5e-5); deepest point ({x[0]:.5f}, "
                f"{x[1]:.5f}) m at a crossing of two edges: {crossing}")
    r = rcval.Result(rcval.run(mesh_bars(iedge=0), "mesh_bars_iedge0"))
    z_ff = W8 / 2 + H0 - 0.5 * G * r.t[-1] ** 2
    ez = rcval.rel(r.pos[-1, 0, 2], z_ff)
    rcval.check("type25.edges.mesh_bar_iedge0_falls", ez < 1e-9 and abs(r.fn[:, 0]).max() == 0.0,
                f"rel. error {ez:.1e} (< 1e-9): Iedge 0 (nodes against segments only): no corner of either bar over "
                f"the other's faces, the bar falls through: z = {r.pos[-1, 0, 2]:.9f} m at t = {r.t[-1]:g} s (free fall "
                f"{z_ff:.9f} m), largest interface force {abs(r.fn[:, 0]).max():g} N")
    # 3b. corners against faces: a box resting flat on a box
    r = rcval.Result(rcval.run(flat(), "flat"))
    fn, p = r.fn[-1, 0], r.pen[-1, 0]
    e1, e2 = rcval.rel(fn, MB * G), rcval.rel(p, MB * G / K)
    rcval.check("type25.boxes.flat.rest", e1 < 1e-6 and e2 < 5e-5,
                f"max rel. error {max(e1, e2):.1e}: a 15 kg box dropped flat on a fixed box (Iedge 0, two /SURF/BOX, "
                f"its 4 bottom corners on the top face): F = {fn:.9g} N (m g = {MB * G:.9g} N, {e1:.1e} < 1e-6), "
                f"P = {p:.9e} m (m g / k = {MB * G / K:.9e} m, {e2:.1e} < 5e-5)")
    # 4. Coulomb stop
    r = rcval.Result(rcval.run(slide(), "fric"))
    d_ref = V0**2 / (2 * MU * G)
    t_stop = r.events("fric_stick")
    et = rcval.rel(t_stop[0], V0 / (MU * G)) if len(t_stop) else 1.0
    x_stop = r.pos[r.state_at(t_stop[0]), 0, 0] - X0 if len(t_stop) else 0.0
    e = rcval.rel(x_stop, d_ref)
    rcval.check("type25.slide.fric", max(e, et) < 1e-6,
                f"max rel. error {max(e, et):.1e}: launched at {V0} m/s, Fric {MU}: stops at "
                f"{t_stop[0] if len(t_stop) else float('nan'):.9f} s (v0/(mu g), {et:.1e}) after {x_stop:.9f} m "
                f"(v0^2/(2 mu g) = {d_ref:.9f} m, {e:.1e}); max rel. error < 1e-6")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": drop(), "bars.rad": bars(), "mesh_bars.rad": mesh_bars(), "flat.rad": flat(),
                               "slide.rad": slide()})
