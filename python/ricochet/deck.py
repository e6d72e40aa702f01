"""Write ricochet case decks in the fixed-width Radioss block format.

Integer fields are 10 characters, real fields 20 (docs/case-format.md).
Part of the ricochet Python module (``ricochet.deck``); the validation
problems and the benchmarks generate their decks with it (through
validation/lib/deck.py), including the tolerance variants of the
convergence studies.

    from ricochet.deck import Deck
    d = Deck("sphere drop")
    d.nodes([(1, 0.0, 0.0, 0.1)])
    ...
    d.write("drop.rad")
"""
# SPDX-License-Identifier: GPL-3.0-or-later


def i10(v):
    return "" .rjust(10) if v is None else f"{int(v):>10d}"


def r20(v):
    return "".rjust(20) if v is None else f"{float(v):>20.12g}"


def line(*fields):
    """fields: ('i', v) or ('r', v) tuples; returns the data line."""
    out = []
    for kind, v in fields:
        out.append(i10(v) if kind == "i" else r20(v))
    return "".join(out).rstrip()


class Deck:
    def __init__(self, title="ricochet case", units=("kg", "m", "s")):
        self.cards = ["#RADIOSS STARTER", "/BEGIN", title, line(("i", 2022), ("i", 0)),
                      "".join(u.rjust(20) for u in units), "".join(u.rjust(20) for u in units)]

    def add(self, header, *lines, title=None):
        self.cards.append(header)
        if title is not None:
            self.cards.append(title)
        self.cards.extend(lines)

    def funct(self, fid, xs, ys, title="curve"):
        self.add(f"/FUNCT/{fid}", *[line(("r", x), ("r", y)) for x, y in zip(xs, ys)], title=title)

    def nodes(self, nodes):
        """nodes: list of (id, x, y, z)."""
        self.add("/NODE", *[line(("i", n), ("r", x), ("r", y), ("r", z)) for n, x, y, z in nodes])

    def grnod(self, gid, ids, title="group"):
        rows = [ids[k:k + 10] for k in range(0, len(ids), 10)]
        self.add(f"/GRNOD/NODE/{gid}", *["".join(i10(v) for v in r) for r in rows], title=title)

    def rbody(self, bid, node, mass, J, Joff=(0.0, 0.0, 0.0), grnod=None, title="body", sens=None):
        """sens: the /SENSOR that releases the body (sens_ID; held at rest until it is on)."""
        self.add(f"/RBODY/{bid}",
                 line(("i", node), ("i", sens), ("i", None), ("i", None), ("r", mass), ("i", grnod)),
                 line(("r", J[0]), ("r", J[1]), ("r", J[2])),
                 line(("r", Joff[0]), ("r", Joff[1]), ("r", Joff[2])), title=title)

    def sphere(self, sid, body, centre, radius, title="sphere"):
        self.add(f"/SURF/ELLIPS/{sid}", line(("i", 0), ("i", 2), ("i", body)),
                 line(("r", centre[0]), ("r", centre[1]), ("r", centre[2])),
                 line(("r", radius), ("r", radius), ("r", radius)), title=title)

    def plane(self, sid, m, m1, body=0, title="plane"):
        lines = [line(("r", m[0]), ("r", m[1]), ("r", m[2])), line(("r", m1[0]), ("r", m1[1]), ("r", m1[2]))]
        if body:
            lines.append(line(("i", body)))
        self.add(f"/SURF/PLANE/{sid}", *lines, title=title)

    def type6(self, iid, s1, s2, fct_ld, gap=0.0, tstart=None, tstop=None, visc=None,
              ascalex=None, fscaleld=None, iform=0, stiff=None, fct_ul=0, fscaleul=None,
              inacti=0, icor=0, fct_dv=0, fct_df=0, fscalev=None, ascalef=None, ascalev=None,
              sfric=None, fric=None, fct_ff=0, fct_fv=0, e_target=None, v_imp=None, istick=None, fric_s=None,
              isensor=None, title="contact"):
        """istick, fric_s: ricochet's exact stick (line 3 columns 1-10, line 5
        columns 11-20, a 10-column real); isensor: the /SENSOR that turns
        the interface on (line 1 columns 21-30)."""
        fs = "" if fric_s is None else f"{fric_s:>10.6g}"
        self.add(f"/INTER/TYPE6/{iid}",
                 line(("i", s1), ("i", s2), ("i", isensor)),
                 line(("r", sfric), ("r", fric), ("r", gap), ("r", tstart), ("r", tstop)),
                 line(("i", istick), ("i", 0), ("i", 0), ("i", inacti), ("i", fct_ff), ("i", fct_fv),
                      ("r", ascalef), ("r", ascalev)),
                 line(("i", fct_ld), ("i", iform), ("r", ascalex), ("r", fscaleld), ("i", icor)),
                 (i10(fct_ul) + (fs or " " * 10) + line(("r", stiff), ("r", fscaleul))).rstrip(),
                 line(("r", visc), ("i", fct_dv), ("i", fct_df), ("r", fscalev), ("r", e_target), ("r", v_imp)), title=title)

    def sensor_time(self, sid, tdelay, title="time sensor"):
        """/SENSOR/TIME: on from t = Tdelay [s]."""
        self.add(f"/SENSOR/TIME/{sid}", line(("r", tdelay)), title=title)

    def sensor_dist(self, sid, n1, n2, dmin=None, dmax=None, tdelay=None, tmin=None, title="distance sensor"):
        """/SENSOR/DIST: on Tdelay [s] after the distance of nodes n1, n2 has stayed out of [Dmin, Dmax] [m]
        for Tmin [s] (None: blank; a blank bound is no bound; Tmin: the 2022 layout's fifth field)."""
        f = [("i", n1), ("i", n2), ("r", dmin), ("r", dmax)] + ([("r", tmin)] if tmin is not None else [])
        self.add(f"/SENSOR/DIST/{sid}", line(("r", tdelay)), line(*f), title=title)

    def sensor_logic(self, kind, sid, s1, s2, tdelay=None, title="logic sensor"):
        """/SENSOR/AND or /SENSOR/OR (kind): on Tdelay [s] after both (either) of sensors s1, s2 are on."""
        self.add(f"/SENSOR/{kind}/{sid}", line(("r", tdelay)), line(("i", s1), ("i", s2)), title=title)

    def sensor_inter(self, sid, int_id, direction=None, fmin=None, fmax=None, tmin=None, fcut=None, tdelay=None,
                     title="interface sensor"):
        """/SENSOR/INTER: on Tdelay [s] after the contact of interface int_id closes (direction None:
        DIR blank), or after its normal force has stayed above Fmax [N] for Tmin [s] (direction "FN"); Radioss's
        line 2: int_ID (10) DIR (10, text) Fmin Fmax Tmin Fcut (20 each)."""
        l2 = (i10(int_id) + f"{direction or '':>10s}" + r20(fmin) + r20(fmax) + r20(tmin) + r20(fcut)).rstrip()
        self.add(f"/SENSOR/INTER/{sid}", line(("r", tdelay)), l2, title=title)

    def sensor_not(self, sid, s1, tdelay=None, title="NOT sensor"):
        """/SENSOR/NOT: on from Tdelay [s] while sensor s1 is off."""
        self.add(f"/SENSOR/NOT/{sid}", line(("r", tdelay)), line(("i", s1)), title=title)

    def inivel(self, iid, v, grnod, rot=False):
        self.add(f"/INIVEL/{'ROT' if rot else 'TRA'}/{iid}",
                 line(("r", v[0]), ("r", v[1]), ("r", v[2]), ("i", grnod), ("i", 0)), title="initial velocity")

    def grav(self, gid, direction, fscale, grnod=0, sensor=0):
        """/GRAV, constant; sensor: sensor_ID (the gravity from its time on)."""
        self.add(f"/GRAV/{gid}", f"{0:>10d}{direction:>10s}{0:>10d}{sensor:>10d}{grnod:>10d}" + " " * 10 + r20(1.0) + r20(fscale),
                 title="gravity")

    def bcs(self, bid, grnod, trarot="111 111", title="fixed", skew=0):
        """/BCS: Trarot 'TxTyTz RxRyRz' (default: the body fixed), node group;
        skew: the skew_ID whose axes the flags are along (0: global axes)."""
        self.add(f"/BCS/{bid}", f"{trarot:>10s}{skew:>10d}{grnod:>10d}", title=title)

    def grav_fct(self, gid, direction, fscale, fct, grnod=0, ascale=1.0):
        """/GRAV with a time function fct (Fscale_y f(t / Ascale_x))."""
        self.add(f"/GRAV/{gid}", f"{fct:>10d}{direction:>10s}{0:>10d}{0:>10d}{grnod:>10d}" + " " * 10 + r20(ascale) + r20(fscale),
                 title="gravity")

    def part(self, pid, body, surfs=(), title="part"):
        """/PART (ricochet's reading): rbody_ID (0: fixed in space), surface ids
        (none: the whole body)."""
        surfs = list(surfs)
        rows = [line(("i", body), *[("i", s) for s in surfs[:9]])]
        rows += ["".join(i10(v) for v in surfs[k:k + 10]) for k in range(9, len(surfs), 10)]
        self.add(f"/PART/{pid}", line(("i", 0), ("i", 0), ("i", 0), ("r", 0.0)), *rows, title=title)

    def grpart(self, gid, ids, title="part group"):
        rows = [ids[k:k + 10] for k in range(0, len(ids), 10)]
        self.add(f"/GRPART/PART/{gid}", *["".join(i10(v) for v in r) for r in rows], title=title)

    def friction(self, fid, ifric=0, ifiltr=0, xfreq=None, iform=0, dt_ref=None, area=None, c=(), fric=None,
                 visf=None, pairs=(), title="friction"):
        """/FRICTION: line A (Ifric, Ifiltr, Xfreq, Iform, Dt_ref, Area), the
        default set (C1..C6, Fric, VISF) and part-pair groups. pairs: dicts
        with grpart1, grpart2, part1, part2 (0: none), and sets: a list of one
        (isotropic) or two (Idir = 1) tuples (c, fric, visf)."""
        def setlines(cc, fr, vf):
            cc = list(cc) + [None] * (6 - len(cc))
            return [line(*[("r", v) for v in cc[:5]]), line(("r", cc[5]), ("r", fr), ("r", vf))]
        lines = [line(("i", ifric), ("i", ifiltr), ("r", xfreq), ("i", iform), ("r", dt_ref), ("r", area))]
        lines += setlines(c, fric, visf)
        for g in pairs:
            sets = g["sets"]
            lines.append(line(("i", g.get("grpart1", 0)), ("i", g.get("grpart2", 0)), ("i", g.get("part1", 0)),
                              ("i", g.get("part2", 0)), ("i", None), ("i", 1 if len(sets) == 2 else 0)))
            for s in sets:
                lines += setlines(*s)
        self.add(f"/FRICTION/{fid}", *lines, title=title)

    def fric_orient(self, oid, items, title="friction orientation"):
        """/FRIC_ORIENT: items of (grpart_ID, part_ID, V, PHI [deg])."""
        lines = []
        for grp, prt, v, phi in items:
            lines.append(line(("i", grp), ("i", prt)))
            lines.append(line(("r", v[0]), ("r", v[1]), ("r", v[2]), ("i", 0), ("r", phi)))
        self.add(f"/FRIC_ORIENT/{oid}", *lines, title=title)

    def spring(self, cid, b1, p1, b2, p2, iform=1, fct=None, x0=None, kd=None, a=None, b=None, c=None,
               fr=None, xr=None, title="spring-damper"):
        """/COUPLING/SPRING: bodies (0 = fixed point), points, Iform, /FUNCT, X0, Kd, A B C, F_r X_r."""
        lines = [line(("i", b1), ("i", b2), ("i", iform), ("i", fct)),
                 line(("r", p1[0]), ("r", p1[1]), ("r", p1[2])),
                 line(("r", p2[0]), ("r", p2[1]), ("r", p2[2])),
                 line(("r", x0), ("r", kd)),
                 line(("r", a), ("r", b), ("r", c))]
        if fr is not None or xr is not None:
            lines.append(line(("r", fr), ("r", xr)))
        self.add(f"/COUPLING/SPRING/{cid}", *lines, title=title)

    def catenary(self, cid, b1, p1, b2, p2, lambda0, leq, d, title="catenary"):
        """/COUPLING/CATENARY: bodies (0 = fixed point), points, lambda0 [kg/m], L_eq [m], D [N/m]."""
        self.add(f"/COUPLING/CATENARY/{cid}", line(("i", b1), ("i", b2)),
                 line(("r", p1[0]), ("r", p1[1]), ("r", p1[2])),
                 line(("r", p2[0]), ("r", p2[1]), ("r", p2[2])),
                 line(("r", lambda0), ("r", leq), ("r", d)), title=title)

    def joint(self, jid, kind, b1, b2, p, axis=None, p2=None, lim_min=None, lim_max=None, k_lim=None, c_lim=None,
              fct_lim=None, title="joint"):
        """/JOINT/<kind> (SPHERICAL, REVOLUTE, DISTANCE, FIXED, PRISMATIC):
        body 1, body 2 (0 = the ground), the anchor point (global, t = 0);
        REVOLUTE and PRISMATIC: the axis and optionally the stops of the joint
        coordinate (Lim_min, Lim_max [rad] or [m], None: no such stop) with
        their stiffness K_lim (or the curve fct_lim of their elastic force)
        and damping C_lim; DISTANCE: the point p2 on body 2."""
        lines = [line(("i", b1), ("i", b2)), line(("r", p[0]), ("r", p[1]), ("r", p[2]))]
        third = axis if axis is not None else p2
        if third is not None:
            lines.append(line(("r", third[0]), ("r", third[1]), ("r", third[2])))
        if lim_min is not None or lim_max is not None:
            fields = [("r", lim_min), ("r", lim_max), ("r", k_lim), ("r", c_lim)]
            if fct_lim is not None:
                fields.append(("i", fct_lim))
            lines.append(line(*fields))
        self.add(f"/JOINT/{kind.upper()}/{jid}", *lines, title=title)

    def power(self, iid, s1, s2, k=None, m1=None, c=None, m2=None, m3=None, fct_stiff=0, fct_damp=0, ispline=0,
              irdf=0, rdf=None, dreg=None, vreg=None, tstart=None, tstop=None, mus=None, vs=None, mud=None,
              vd=None, fmax=None, kt=None, e_target=None, v_imp=None, isensor=None, title="power-law contact"):
        """/INTER/POWER (docs/case-format.md): None leaves a field blank (its default)."""
        lines = [line(("i", s1), ("i", s2), ("i", fct_stiff), ("i", fct_damp), ("i", ispline), ("i", irdf),
                      ("i", isensor)),
                 line(("r", k), ("r", m1), ("r", c), ("r", m2), ("r", m3)),
                 line(("r", rdf), ("r", dreg), ("r", vreg), ("r", tstart), ("r", tstop)),
                 line(("r", mus), ("r", vs), ("r", mud), ("r", vd), ("r", fmax))]
        if kt is not None or e_target is not None or v_imp is not None:
            lines.append(line(("r", kt)))
        if e_target is not None or v_imp is not None:
            lines.append(line(("r", e_target), ("r", v_imp)))
        self.add(f"/INTER/POWER/{iid}", *lines, title=title)

    def cylinder(self, sid, body, centre, axis, radius, length, ends=0, cmode=0, title="cylinder"):
        """/SURF/CYL: body (0 = fixed), centre, axis vector, radius, length, ends 0 flat / 1 rounded,
        contact point 0 mid-length / 1 deepest."""
        self.add(f"/SURF/CYL/{sid}", line(("i", body), ("i", ends), ("i", cmode)),
                 line(("r", centre[0]), ("r", centre[1]), ("r", centre[2])),
                 line(("r", axis[0]), ("r", axis[1]), ("r", axis[2])),
                 line(("r", radius), ("r", length)), title=title)

    def box(self, sid, body, centre, half, u=None, v=None, title="box"):
        """/SURF/BOX: body (0 = fixed), centre, half-sizes, optional axes u, v."""
        lines = [line(("i", body)), line(("r", centre[0]), ("r", centre[1]), ("r", centre[2])),
                 line(("r", half[0]), ("r", half[1]), ("r", half[2]))]
        if u is not None:
            lines.append(line(("r", u[0]), ("r", u[1]), ("r", u[2])))
            lines.append(line(("r", v[0]), ("r", v[1]), ("r", v[2])))
        self.add(f"/SURF/BOX/{sid}", *lines, title=title)

    def impvel(self, iid, fct, direction, grnod, ascale=None, fscale=None, tstart=None, tstop=None,
               title="imposed velocity", sensor=0):
        """/IMPVEL: velocity component direction (X Y Z XX YY ZZ) = fscale f(t/ascale); sensor: sensor_ID
        (imposed from its time Ts on as fscale f((t - Ts)/ascale))."""
        self.add(f"/IMPVEL/{iid}", f"{fct:>10d}{direction:>10s}{0:>10d}{sensor:>10d}{grnod:>10d}{0:>10d}{0:>10d}",
                 line(("r", ascale), ("r", fscale), ("r", tstart), ("r", tstop)), title=title)

    def run(self, tend, dtout, ev_state=None, on_viol=None):
        """ev_state: /RUN Ev_state (full-state records at events: 0 auto,
        1 always, 2 never); None leaves the field out (default 0). on_viol:
        /RUN On_viol (a failed physics check: 1 stops the run, 2 records it
        and goes on); None leaves the field out (default 1)."""
        fields = [("r", tend), ("r", dtout)]
        if ev_state is not None or on_viol is not None:
            fields.append(("i", ev_state or 0))
        if on_viol is not None:
            fields.append(("i", on_viol))
        self.add("/RUN", line(*fields))

    def contact_coupling(self, cid, s1, s2, d0, k1=None, k2=None, mu=None, kt=None, iside=0, iest=0, vimp=None,
                         dmin=None, zeta=None, area=None, title="contact coupling"):
        """/COUPLING/CONTACT: the body's segment surface s1 against the opposing surface s2; effective
        range d0, k1, k2, mu, k_t; Iest = 1: V_imp, d_min, zeta, A on line 3."""
        lines = [line(("i", s1), ("i", s2), ("i", iside), ("i", iest)),
                 line(("r", d0), ("r", k1), ("r", k2), ("r", mu), ("r", kt))]
        if iest:
            lines.append(line(("r", vimp), ("r", dmin), ("r", zeta), ("r", area)))
        self.add(f"/COUPLING/CONTACT/{cid}", *lines, title=title)

    def solver(self, rtol=1e-6, atol_pos=1e-9, atol_quat=1e-9, atol_vel=1e-6, atol_omega=1e-6,
               atol_energy=1e-6, max_order=5, max_steps=100000, hmax=0.0, h0=0.0, method=1, preload=0,
               switch=0):
        """/SOLVER; method: 1 CVODE, 2 IDA, 3 static analysis (KINSOL); preload 1:
        a dynamic run starts from the static equilibrium at t = 0 (the field
        Preload is written only when set); switch 1: method switching
        (line 3's Switch, written only when set)."""
        first = [("i", method), ("i", max_order), ("i", max_steps), ("r", rtol), ("r", hmax), ("r", h0)]
        if preload:
            first.append(("i", preload))
        self.add("/SOLVER", line(*first),
                 line(("r", atol_pos), ("r", atol_quat), ("r", atol_vel), ("r", atol_omega)),
                 line(("r", atol_energy), *([("i", switch)] if switch else [])))

    def block_on_floor(self, m, r, k, g, visc, z0, v0, fric=None, stiff=None):
        """A 1-sphere "block" (rotations locked) of mass m, radius r at height z0
        on the fixed floor z = 0, launched at v0, under gravity g (its node
        group only), with a TYPE6 linear contact k and damping visc (no TYPE6
        friction unless fric, the Coulomb coefficient, is given; stiff: the
        TYPE6 Stiff field). Ids: /FUNCT 1, node 1, /RBODY 1, surfaces 1 and 2,
        /GRNOD 1, /BCS 1, /INIVEL 1, /GRAV 1, /INTER/TYPE6 1."""
        self.funct(1, [0.0, 1.0], [0.0, k], title=f"linear load curve k = {k:.0e} N/m".replace("e+0", "e"))
        self.nodes([(1, 0.0, 0.0, z0)])
        self.rbody(1, 1, m, [0.4 * m * r * r] * 3, grnod=1, title=f"block {m:g} kg")
        self.sphere(1, 1, (0.0, 0.0, z0), r, title="block sphere")
        self.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
        self.grnod(1, [1], title="block")
        self.bcs(1, 1, "000 111", title="no rotation")
        self.inivel(1, tuple(v0), 1)
        self.grav(1, "Z", -g, 1)
        if fric is None and stiff is None:
            self.type6(1, 1, 2, 1, visc=visc, title="contact (no TYPE6 friction)")
        else:
            self.type6(1, 1, 2, 1, visc=visc, fric=fric, stiff=stiff, title=f"contact, Coulomb friction mu = {fric or 0.0:g}")

    def text(self):
        return "\n".join(self.cards + ["/END", ""])

    def write(self, path):
        with open(path, "w") as f:
            f.write(self.text())
