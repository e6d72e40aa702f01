"""Seeded random scenes for the physics fuzzer (README.md, "Scene space").

`generate(seed, kinds)` returns one scene: a JSON-serialisable dict in SI
(deckwriter.py turns it into a deck). The same seed always gives the same
scene: the kind is drawn from numpy's Generator seeded with (seed, 0) among
the kinds allowed, the scene itself from (seed, 1), so `--kind K` with the
seed of a reported scene regenerates it exactly.

Besides the cards, a scene carries what the invariant checker needs
("scales", per-interface law curves and the bodies' shapes): the scene's
length, speed and energy scales derived from its own parameters.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import math

import numpy as np

G0 = 9.81

# kind -> relative weight in the default mix
KINDS = {
    "sphere_drop": 3, "sphere_incline": 2, "ramp_wall": 2, "cradle": 2, "stack": 2,
    "box_floor": 3, "box_incline": 2, "box_box": 2, "meshbox": 2, "cylinder": 2,
    "free": 3, "pendulum_wall": 1, "illposed": 1, "belt": 2,
}

LAWS = ("t6lin", "t6tab", "t6hyst1", "t6hyst1n", "t6hyst2", "power")


def loguniform(rng, lo, hi):
    return float(math.exp(rng.uniform(math.log(lo), math.log(hi))))


def unit(v):
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


def rot_axis(axis, ang):
    """Rotation matrix about a unit axis."""
    a = unit(axis)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(ang) * K + (1 - math.cos(ang)) * K @ K


def lst(v):
    return [float(x) for x in v]


class Builder:
    """Collects the cards of one scene with consecutive ids."""

    def __init__(self, kind, seed, rng):
        self.rng = rng
        self.s = {"kind": kind, "seed": int(seed), "title": f"physfuzz {kind} seed {seed}",
                  "bodies": [], "nodes": [], "surfaces": [], "funcs": [], "inters": [], "joints": [],
                  "gravity": [0.0, 0.0, 0.0], "friction": None, "expect": "ok", "notes": []}
        self.nb = self.ns = self.nf = self.ni = self.nn = 0

    # ---- bodies and surfaces
    def body(self, mass, J, x, v=(0, 0, 0), w=(0, 0, 0), label="body", shape=None):
        self.nb += 1
        J = np.asarray(J, float)
        self.s["bodies"].append({"id": self.nb, "mass": float(mass), "J": [lst(r) for r in 0.5 * (J + J.T)],
                                 "x": lst(x), "v": lst(v), "w": lst(w), "label": label, "shape": shape or {}})
        return self.nb

    def surf(self, **kw):
        self.ns += 1
        kw["id"] = self.ns
        for k in ("p", "n", "c", "u", "v", "axis", "half"):
            if k in kw:
                kw[k] = lst(kw[k])
        self.s["surfaces"].append(kw)
        return self.ns

    def node(self, x, body):
        self.nn += 1
        nid = 1000 + self.nn
        self.s["nodes"].append({"id": nid, "x": lst(x), "body": body})
        return nid

    def func(self, xs, ys, label="curve"):
        self.nf += 1
        self.s["funcs"].append({"id": self.nf, "x": lst(xs), "y": lst(ys), "label": label})
        return self.nf

    def inter(self, s1, s2, law, label="contact"):
        self.ni += 1
        it = dict(law)
        it.update({"id": self.ni, "s1": s1, "s2": s2, "label": label})
        self.s["inters"].append(it)
        return it

    def surface(self, sid):
        return self.s["surfaces"][sid - 1]

    # ---- shapes: body + surface
    def sphere(self, R, mass, c, v=(0, 0, 0), w=(0, 0, 0), label="ball"):
        b = self.body(mass, 0.4 * mass * R * R * np.eye(3), c, v, w, label,
                      shape={"type": "sphere", "r": R})
        sid = self.surf(type="sphere", body=b, c=c, r=R, label=label)
        return b, sid

    def box(self, half, mass, c, Q=np.eye(3), v=(0, 0, 0), w=(0, 0, 0), label="box"):
        a, bb, cc = half
        Jd = np.diag([bb * bb + cc * cc, a * a + cc * cc, a * a + bb * bb]) * mass / 3.0
        b = self.body(mass, Q @ Jd @ Q.T, c, v, w, label, shape={"type": "box", "half": lst(half)})
        sid = self.surf(type="box", body=b, c=c, half=half, u=Q[:, 0], v=Q[:, 1], label=label)
        return b, sid

    def cyl(self, R, L, mass, c, axis, v=(0, 0, 0), w=(0, 0, 0), iend=0, icont=0, label="cylinder"):
        e = unit(axis)
        Ja, Jp = 0.5 * mass * R * R, mass * (3 * R * R + L * L) / 12.0
        J = Jp * np.eye(3) + (Ja - Jp) * np.outer(e, e)
        b = self.body(mass, J, c, v, w, label, shape={"type": "cyl", "r": R, "len": L, "iend": iend})
        sid = self.surf(type="cyl", body=b, c=c, axis=e, r=R, len=L, iend=iend, icont=icont, label=label)
        return b, sid

    def meshbox(self, half, mass, c, Q=np.eye(3), n=(2, 2), v=(0, 0, 0), w=(0, 0, 0), label="meshed box"):
        """A box body whose surface is a /SURF/SEG on its nodes: the bottom
        face (local -w) in n[0] x n[1] quadrilaterals, the other faces one
        quadrilateral each, normals out of the box."""
        a, bb, cc = half
        Jd = np.diag([bb * bb + cc * cc, a * a + cc * cc, a * a + bb * bb]) * mass / 3.0
        b = self.body(mass, Q @ Jd @ Q.T, c, v, w, label, shape={"type": "box", "half": lst(half)})
        c = np.asarray(c, float)

        def X(lx, ly, lz):
            return c + Q @ np.array([lx, ly, lz])
        nx, ny = n
        bot = {}
        for i in range(nx + 1):
            for j in range(ny + 1):
                bot[(i, j)] = self.node(X(-a + 2 * a * i / nx, -bb + 2 * bb * j / ny, -cc), b)
        top = {}
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            top[(sx, sy)] = self.node(X(sx * a, sy * bb, cc), b)
        segs = [[bot[(i, j)], bot[(i, j + 1)], bot[(i + 1, j + 1)], bot[(i + 1, j)]]
                for i in range(nx) for j in range(ny)]
        c00, c10, c11, c01 = bot[(0, 0)], bot[(nx, 0)], bot[(nx, ny)], bot[(0, ny)]
        t00, t10, t11, t01 = top[(-1, -1)], top[(1, -1)], top[(1, 1)], top[(-1, 1)]
        segs += [[t00, t10, t11, t01], [c00, c10, t10, t00], [c10, c11, t11, t10], [c11, c01, t01, t11],
                 [c01, c00, t00, t01]]
        sid = self.surf(type="seg", body=b, segs=segs, label=label, half=half, c=c, u=Q[:, 0], v=Q[:, 1])
        return b, sid

    def meshfloor(self, size, n, z=0.0, centre=(0, 0), label="meshed floor"):
        """A fixed square plate in the plane z, n x n quadrilaterals, normals up."""
        ids = {}
        for i in range(n + 1):
            for j in range(n + 1):
                ids[(i, j)] = self.node((centre[0] - size / 2 + size * i / n, centre[1] - size / 2 + size * j / n, z), 0)
        segs = [[ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)]] for i in range(n) for j in range(n)]
        return self.surf(type="seg", body=0, segs=segs, label=label, p=(centre[0], centre[1], z), n=(0, 0, 1))

    def plane(self, p, n, label="plane", nlen=1.0):
        return self.surf(type="plane", body=0, p=p, n=unit(n), label=label, nlen=float(nlen))


# --------------------------------------------------------------------------
# parameters


def pick_size(rng, lo=1e-3, hi=1.0):
    return loguniform(rng, lo, hi)


def pick_mass(rng, volume):
    """A mass in [1e-3, 1e2] kg, for a density in [50, 5e4] kg/m^3 where the
    ranges meet (else the nearest end of the mass range)."""
    lo, hi = max(1e-3, 50.0 * volume), min(1e2, 5e4 * volume)
    if lo > hi:
        return 1e-3 if 5e4 * volume < 1e-3 else 1e2
    return loguniform(rng, lo, hi)


def pick_gravity(rng, modes=("vertical", "vertical", "tilted"), gmag=None):
    mode = modes[int(rng.integers(len(modes)))]
    g = gmag or (G0 if rng.random() < 0.7 else rng.uniform(1.0, 20.0))
    if mode == "none":
        return np.zeros(3), mode
    if mode == "vertical":
        return np.array([0.0, 0.0, -g]), mode
    tilt = math.radians(rng.uniform(2.0, 30.0))
    az = rng.uniform(0, 2 * math.pi)
    return rot_axis((math.cos(az), math.sin(az), 0.0), tilt) @ np.array([0.0, 0.0, -g]), mode


def law_force(law, p):
    """Elastic (loading) force of a law at penetration p >= 0 [N]: linear
    extension of a tabulated curve beyond its points, K p^m1 for the power
    law. The checker uses it for the penetration bound."""
    p = np.asarray(p, float)
    if law["kind"] == "power":
        return law["k"] * np.power(np.maximum(p, 0.0), law["m1"])
    x, y = np.asarray(law["x"], float), np.asarray(law["y"], float)
    s0 = (y[1] - y[0]) / (x[1] - x[0])
    s1 = (y[-1] - y[-2]) / (x[-1] - x[-2])
    return np.where(p < x[0], y[0] + s0 * (p - x[0]),
                    np.where(p > x[-1], y[-1] + s1 * (p - x[-1]), np.interp(p, x, y)))


def law_pen_at_force(law, F):
    """Smallest penetration at which the law's elastic force reaches F."""
    if law["kind"] == "power":
        return (F / law["k"]) ** (1.0 / law["m1"])
    lo, hi = 0.0, max(law["x"][-1], 1e-300)
    while law_force(law, hi) < F:
        hi *= 2.0
        if hi > 1e30:
            return math.inf
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if law_force(law, mid) < F:
            lo = mid
        else:
            hi = mid
    return hi


def law_pen_at_energy(law, E):
    """Penetration where the stored elastic energy (integral of the force)
    reaches E."""
    if E <= 0:
        return 0.0
    if law["kind"] == "power":
        m1 = law["m1"]
        return (E * (m1 + 1) / law["k"]) ** (1.0 / (m1 + 1))
    hi = max(law["x"][-1], 1e-300)

    def integ(p):
        xs = np.linspace(0.0, p, 2001)
        f = law_force(law, xs)
        return float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(xs)))
    while integ(hi) < E:
        hi *= 2.0
        if hi > 1e30:
            return math.inf
    lo = 0.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if integ(mid) < E:
            lo = mid
        else:
            hi = mid
    return hi


def make_law(B, rng, W, m_red, v_imp, size, laws=LAWS, allow_visc=True, delta_rel=None):
    """Normal law fields of an interface. W: the static load it carries [N]
    (0 without gravity), m_red: the reduced mass [kg], v_imp: the impact speed
    [m/s], size: the smaller body's size [m]. The stiffness puts the static
    penetration (or, without load, the impact penetration) at
    delta = size x 10^U(-6, -2). Returns (fields, law) where law is the
    elastic curve for the checker."""
    name = laws[int(rng.integers(len(laws)))]
    delta = size * (delta_rel if delta_rel is not None else 10.0 ** rng.uniform(-6, -2))
    if W > 0:
        k = W / delta
    else:
        v = max(v_imp, 0.1)
        k = m_red * v * v / (delta * delta)
        W = k * delta
    fields = {"law": "type6"}
    zeta = loguniform(rng, 0.02, 1.2) if (allow_visc and rng.random() < 0.6) else 0.0
    if name == "power":
        m1 = float(rng.choice([1.0, 1.5, 1.5, 2.0, rng.uniform(1.0, 2.5)]))
        K = W / delta ** m1
        fields = {"law": "power", "k": K, "m1": m1}
        law = {"kind": "power", "k": K, "m1": m1}
        if zeta > 0:
            m2 = float(rng.choice([1.0, 1.0, rng.uniform(0.6, 1.5)]))
            m3 = float(rng.choice([1.0, m1, 0.0, rng.uniform(0.0, 2.0)]))
            v = max(v_imp, math.sqrt(W / max(m_red, 1e-300) * delta), 1e-3)
            C = zeta * K * delta ** (m1 - m3) / v ** m2
            fields.update({"c": C, "m2": m2, "m3": m3})
            if rng.random() < 0.5:
                fields["irdf"] = 2
        elif rng.random() < 0.15 and v_imp > 0.05:
            # the restitution of a power law depends on the impact speed: give it
            fields["e_target"] = float(rng.uniform(0.3, 0.95))
            fields["v_imp"] = float(v_imp)
        law["name"] = name
        return fields, law
    # TYPE6: a curve written normalised (x in units of delta, y in units of
    # W, the scales Ascalex = delta, FscaleId = W) or in SI
    if name == "t6lin":
        xs, ys = [0.0, 1.0], [0.0, 1.0]
    else:
        # hardening (or first softening) piecewise-linear curve through 0
        xs = [0.0, 0.3, 1.0, 3.0, 10.0, 100.0]
        a = rng.uniform(0.0, 0.5) if rng.random() < 0.7 else -rng.uniform(0.0, 0.3)
        ys = [x * (1.0 + a * (x - 1.0)) if a >= 0 else x * (1.0 + a * min(x, 1.0)) for x in xs]
        ys = [y / ys[2] for y in ys]     # F(delta) = W
        ys[0] = 0.0
    normalised = rng.random() < 0.5
    if normalised:
        fid = B.func(xs, ys, label=f"{name} load curve, x/delta, F/W")
        fields.update({"fct_ld": fid, "ascalex": delta, "fscaleld": W})
    else:
        fid = B.func([x * delta for x in xs], [y * W for y in ys], label=f"{name} load curve [m, N]")
        fields.update({"fct_ld": fid, "ascalex": 1.0, "fscaleld": 1.0})
    law = {"kind": "curve", "x": [x * delta for x in xs], "y": [y * W for y in ys], "name": name}
    slopes = np.diff(law["y"]) / np.diff(law["x"])
    kmax = float(np.max(slopes))
    if name.startswith("t6hyst"):
        stiff = kmax * loguniform(rng, 1.5, 20.0)
        fields.update({"iform": 2 if name == "t6hyst2" else 1, "stiff": stiff})
        if name == "t6hyst1":
            # unload curve below the load curve: zero up to x0, then a scaled copy
            x0 = rng.uniform(0.0, 0.5)
            r = rng.uniform(0.2, 0.9)
            uy = [0.0 if x <= x0 else r * y * (x - x0) / x for x, y in zip(xs, ys)]
            if normalised:
                uid = B.func(xs, uy, label="unload curve, x/delta, F/W")
                fields.update({"fct_ul": uid, "fscaleul": W})
            else:
                uid = B.func([x * delta for x in xs], [y * W for y in uy], label="unload curve [m, N]")
                fields.update({"fct_ul": uid, "fscaleul": 1.0})
    if zeta > 0:
        k_d = float(slopes[1]) if len(slopes) > 1 else kmax
        fields["visc"] = 2.0 * zeta * math.sqrt(max(k_d, kmax * 0.1) * m_red)
    elif name == "t6lin" and rng.random() < 0.2 and v_imp > 0.05:
        fields["e_target"] = float(rng.uniform(0.3, 0.95))
    return fields, law


def add_friction(B, rng, it, law, mode, W, m_red, v_scale, area):
    """Friction on one interface: mode 'none', 't6' (TYPE6 Sfric/Fric, or
    step5 on a power law) or 'card' (the scene's /FRICTION card, made once)."""
    if mode == "none":
        return
    if mode == "t6":
        if it["law"] == "power":
            mus = rng.uniform(0.1, 0.9)
            vs = loguniform(rng, 1e-4, 1e-1) * max(v_scale, 0.1)
            it.update({"mus": mus, "vs": vs, "mud": mus * rng.uniform(0.5, 1.0), "vd": vs * loguniform(rng, 1.5, 10)})
            if rng.random() < 0.2:
                it["fmax"] = mus * max(W, 1e-12) * rng.uniform(0.3, 3.0)
        else:
            it["fric"] = float(rng.uniform(0.05, 1.0))
            if rng.random() < 0.2:
                it["sfric"] = float(rng.uniform(0.0, 0.2)) * max(W, 1e-12)
            if it.get("iform", 0) == 0 and rng.random() < 0.3:
                k = (law["y"][1] - law["y"][0]) / (law["x"][1] - law["x"][0])
                it["stiff"] = k * loguniform(rng, 0.1, 10.0)
        return
    # a /FRICTION card covering every interface
    if B.s["friction"] is None:
        ifric = int(rng.choice([0, 0, 1, 2, 3]))
        iform = int(rng.choice([1, 2]))
        fr = {"ifric": ifric, "iform": iform, "fric": float(rng.uniform(0.05, 0.8)), "area": area}
        p_c = max(W, 1e-12) / area
        v_c = max(v_scale, 0.01)
        if ifric == 1:
            fr["c"] = [0.1 / p_c * rng.random(), 0.05 / v_c * rng.random(), 0.0, 0.0, 0.0]
        elif ifric == 2:
            fr["c"] = [0.05 / p_c ** 2 * rng.random(), -1.0 / v_c, 0.1 / p_c * rng.random(), -2.0 / v_c,
                       0.1 * rng.random(), -0.5 / v_c]
        elif ifric == 3:
            mus, mud = rng.uniform(0.2, 0.8), rng.uniform(0.1, 0.6)
            mumax = max(mus, mud) * rng.uniform(1.0, 1.5)
            mumin = min(mus, mud) * rng.uniform(0.3, 1.0)
            v1 = loguniform(rng, 1e-4, 1e-1) * v_c
            fr["c"] = [mus, mud, mumax, mumin, v1, v1 * loguniform(rng, 2, 20)]
        if iform == 1:
            fr["visf"] = float(loguniform(rng, 0.1, 2.0))
        if rng.random() < 0.2:
            fr["ifiltr"] = 3
            fr["xfreq"] = loguniform(rng, 10.0, 1e4)
        B.s["friction"] = fr
    fr = B.s["friction"]
    if it["law"] == "power" and fr["iform"] == 2:
        # the tangential stiffness the incremental form needs on a power law:
        # the normal law's slope at the load W, times 0.1..10
        p = (max(W, 1e-12) / law["k"]) ** (1.0 / law["m1"])
        it["kt"] = law["m1"] * max(W, 1e-12) / p * loguniform(rng, 0.1, 10.0)


def pick_friction_mode(rng, p_none=0.3):
    r = rng.random()
    if r < p_none:
        return "none"
    return "t6" if rng.random() < 0.6 else "card"


def finish(B, L, E_s, v_scale, H, tend, n_out=200, extra=None):
    """Scales, run card. L: the largest body size [m]; E_s: the energy scale
    [J]; v_scale: the largest speed the scene can reach [m/s]; H: the height
    over which bodies can fall [m]."""
    s = B.s
    s["run"] = {"tend": float(tend), "dtout": float(tend / n_out)}
    g = float(np.linalg.norm(s["gravity"]))
    mtot = sum(b["mass"] for b in s["bodies"])
    s["scales"] = {"L": float(L), "E_s": float(E_s), "v": float(v_scale), "H": float(H), "g": g, "m_total": mtot}
    if extra:
        s["scales"].update(extra)
    # the /FRICTION card covers every interface: in the incremental form a
    # power-law interface that add_friction did not see (a cradle's ball
    # pairs beside its floor contacts) needs the stiffness too, which
    # ricochet otherwise refuses the card for; the normal law's slope at the
    # scene's weight (no random draw: the other scenes stay as they were)
    fr = s.get("friction")
    if fr and fr.get("iform") == 2:
        W = max(mtot * g, 1e-12)
        for it in s["inters"]:
            if it.get("law") == "power" and "kt" not in it and it.get("k"):
                p = (W / it["k"]) ** (1.0 / it["m1"])
                it["kt"] = it["m1"] * W / p
    return s


def kinetic(b):
    v, w, J = np.array(b["v"]), np.array(b["w"]), np.array(b["J"])
    return 0.5 * b["mass"] * v @ v + 0.5 * w @ J @ w


def energy_scale(s, Hfall):
    """E_s = max(initial kinetic energy, sum of m g H): the larger of the
    kinetic energy and the work gravity can do over the scene."""
    g = float(np.linalg.norm(s["gravity"]))
    ke = sum(kinetic(b) for b in s["bodies"])
    pe = sum(b["mass"] for b in s["bodies"]) * g * Hfall
    return max(ke, pe)


# --------------------------------------------------------------------------
# scene kinds


def start_mode(rng, modes=("touching", "resting", "moving", "spinning", "dropped")):
    return modes[int(rng.integers(len(modes)))]


def k_sphere_drop(B, rng):
    """A sphere on or above a fixed floor (plane, fixed box or meshed floor)."""
    R = pick_size(rng, 1e-3, 0.5)
    m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
    g, gmode = pick_gravity(rng)
    B.s["gravity"] = lst(g)
    gm = float(np.linalg.norm(g))
    start = start_mode(rng)
    floor = str(rng.choice(["plane", "plane", "box", "mesh"]))
    off = rng.uniform(-1, 1, 3) * rng.choice([0.0, 1.0]) * 0.7
    h = 0.0
    v = np.zeros(3)
    w = np.zeros(3)
    if start == "dropped":
        h = R * loguniform(rng, 0.1, 50.0)
        h = min(h, 2.0)
    if start == "moving":
        v = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0]) * loguniform(rng, 0.01, 5.0)
    if start == "spinning":
        w = rng.normal(size=3) * loguniform(rng, 0.1, 10.0) / max(R, 0.01)
    v_imp = math.sqrt(2 * gm * h) + np.linalg.norm(v)
    fields, law = make_law(B, rng, m * gm, m, v_imp, R)
    pen0 = law_pen_at_force(law, m * gm) if start == "resting" else 0.0
    c = np.array([0.0, 0.0, R + h - pen0]) + off * np.array([1, 1, 0])
    b, sb = B.sphere(R, m, c, v, w)
    if floor == "plane":
        sf = B.plane(off * np.array([1, 1, 0]), (0, 0, 1), label="floor")
    elif floor == "box":
        hb = max(R * 4, 0.05)
        sf = B.surf(type="box", body=0, c=lst(off * np.array([1, 1, 0]) + np.array([0, 0, -hb])), half=[hb * 10, hb * 10, hb],
                    u=[1.0, 0.0, 0.0], v=[0.0, 1.0, 0.0], label="fixed box (floor)")
    else:
        sf = B.meshfloor(max(R * 40, 0.1), int(rng.integers(2, 6)), centre=tuple(off[:2]))
    order = rng.random() < 0.5
    it = B.inter(sb, sf, fields) if order else B.inter(sf, sb, fields)
    it["law_curve"] = law
    fm = pick_friction_mode(rng)
    add_friction(B, rng, it, law, fm, m * gm, m, max(np.linalg.norm(v), 1.0), math.pi * R * R)
    vsc = v_imp + np.linalg.norm(w) * R + np.linalg.norm(v)
    E_s = energy_scale(B.s, h + R)
    tf = math.sqrt(2 * max(h, R) / gm)
    tend = tf * rng.uniform(3.0, 10.0)
    B.s["notes"].append(f"start {start}, floor {floor}, gravity {gmode}, law {law['name']}, friction {fm}")
    return finish(B, 2 * R, E_s, vsc, h + R, tend)


def incline_frame(theta, az):
    """Rotation taking z to the incline's normal: tilted by theta about a
    horizontal axis at azimuth az."""
    return rot_axis((math.cos(az), math.sin(az), 0.0), theta)


def k_sphere_incline(B, rng):
    """A sphere touching or resting on an incline, rolling/sliding."""
    R = pick_size(rng, 1e-3, 0.3)
    m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    th = math.radians(rng.uniform(5.0, 40.0))
    Q = incline_frame(th, rng.uniform(0, 2 * math.pi))
    n = Q @ np.array([0, 0, 1.0])
    start = start_mode(rng, ("touching", "resting", "moving", "spinning"))
    fields, law = make_law(B, rng, m * gm * math.cos(th), m, 0.0, R)
    pen0 = law_pen_at_force(law, m * gm * math.cos(th)) if start == "resting" else 0.0
    p0 = np.array([0.0, 0.0, 0.0])
    c = p0 + n * (R - pen0)
    v = np.zeros(3)
    w = np.zeros(3)
    if start == "moving":
        v = Q @ np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0]) * loguniform(rng, 0.01, 3.0)
    if start == "spinning":
        w = rng.normal(size=3) * loguniform(rng, 0.1, 10.0) / max(R, 0.01)
    b, sb = B.sphere(R, m, c, v, w)
    sf = B.plane(p0, n, label="incline")
    it = B.inter(sb, sf, fields)
    it["law_curve"] = law
    fm = pick_friction_mode(rng, 0.15)
    add_friction(B, rng, it, law, fm, m * gm * math.cos(th), m, max(np.linalg.norm(v), 0.5), math.pi * R * R)
    tend = rng.uniform(0.2, 1.0)
    # it rolls or slides at most with g sin(theta): the height lost in tend
    s_max = np.linalg.norm(v) * tend + 0.5 * gm * math.sin(th) * tend ** 2
    H = s_max * math.sin(th) + R
    vsc = np.linalg.norm(v) + gm * math.sin(th) * tend + np.linalg.norm(w) * R
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"incline {math.degrees(th):.1f} deg, start {start}, law {law['name']}, friction {fm}")
    return finish(B, 2 * R, E_s, vsc, H, tend)


def k_ramp_wall(B, rng):
    """A ball rolling down a ramp (about 20 degrees) into a wall."""
    R = pick_size(rng, 5e-3, 0.2)
    m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    th = math.radians(20.0 if rng.random() < 0.5 else rng.uniform(10.0, 35.0))
    az = rng.uniform(0, 2 * math.pi) if rng.random() < 0.5 else 0.0
    Q = incline_frame(th, az)
    n = Q @ np.array([0, 0, 1.0])
    down = np.array([0.0, 0.0, -1.0]) - (-n[2]) * n      # gravity's direction along the ramp
    down = unit(down)
    D = R * loguniform(rng, 1.0, 30.0)          # distance to the wall
    wall_p = down * (D + R)
    wall_n = -down                              # a wall normal to the ramp, facing up the slope
    if rng.random() < 0.5:                      # or a vertical wall
        wall_n = unit(-np.array([down[0], down[1], 0.0]))
    fields, law = make_law(B, rng, m * gm * math.cos(th), m, 0.0, R)
    c = n * R
    b, sb = B.sphere(R, m, c)
    sr = B.plane((0, 0, 0), n, label="ramp")
    sw = B.plane(wall_p, wall_n, label="wall")
    it1 = B.inter(sb, sr, fields, label="ball on ramp")
    it1["law_curve"] = law
    t_hit = math.sqrt(2 * D / (gm * math.sin(th) / 1.4))
    v_hit = gm * math.sin(th) * t_hit
    f2, law2 = make_law(B, rng, 0.0, m, v_hit, R)
    it2 = B.inter(sb, sw, f2, label="ball against wall")
    it2["law_curve"] = law2
    fm = pick_friction_mode(rng, 0.1)
    add_friction(B, rng, it1, law, fm, m * gm, m, v_hit, math.pi * R * R)
    add_friction(B, rng, it2, law2, fm, m * gm, m, v_hit, math.pi * R * R)
    tend = t_hit * rng.uniform(1.5, 4.0)
    H = (D + R) * math.sin(th) + R
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"ramp {math.degrees(th):.1f} deg, wall at {D:.3g} m, laws {law['name']}/{law2['name']}, friction {fm}")
    return finish(B, 2 * R, E_s, v_hit * 2, H, tend)


def k_cradle(B, rng):
    """Newton's cradle: n balls touching on a line (centres x0 + i*2R, not
    exact binary numbers), the first launched; in space or on a floor."""
    n = int(rng.integers(3, 8))
    R = pick_size(rng, 2e-3, 0.1)
    m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
    v0 = loguniform(rng, 0.01, 5.0)
    on_floor = rng.random() < 0.4
    gm = G0 if on_floor else 0.0
    B.s["gravity"] = [0.0, 0.0, -gm]
    x0 = float(rng.choice([0.0, 0.7, rng.uniform(-1, 1)]))
    touching = rng.random() < 0.85
    fields, law = make_law(B, rng, 0.0, 0.5 * m, v0, R, laws=("t6lin", "t6lin", "power", "t6tab", "t6hyst2"))
    sids = []
    z = R
    pen0 = 0.0
    flaw = None
    if on_floor:
        ff, flaw = make_law(B, rng, m * gm, m, 0.0, R, laws=("t6lin", "power"))
    gap = 0.0
    for i in range(n):
        # touching: centres x0 + i*2R exactly as written; gaps: each pair apart
        # by its own gap of 1e-4 .. 0.2 R (cumulative, so no pair overlaps)
        if not touching and i > 0:
            gap += R * loguniform(rng, 1e-4, 0.2)
        x = x0 + i * 2 * R + gap
        vb = (v0, 0.0, 0.0) if i == 0 else (0.0, 0.0, 0.0)
        b, s = B.sphere(R, m, (x, 0.0, z - pen0), vb)
        sids.append(s)
    for i in range(n - 1):
        it = B.inter(sids[i], sids[i + 1], fields, label=f"ball {i + 1} - ball {i + 2}")
        it["law_curve"] = law
    fm = "none"
    if on_floor:
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        fm = pick_friction_mode(rng, 0.5)
        for i in range(n):
            it = B.inter(sids[i], sf, ff, label=f"ball {i + 1} on floor")
            it["law_curve"] = flaw
            add_friction(B, rng, it, flaw, fm, m * gm, m, v0, math.pi * R * R)
    tend = (n * 2 * R) / v0 * rng.uniform(1.5, 4.0)
    tend = min(tend, 5.0)
    E_s = energy_scale(B.s, 2 * R)
    B.s["notes"].append(f"{n} balls, {'touching' if touching else 'gaps'}, x0 {x0:g}, v0 {v0:.3g}, "
                        f"{'floor' if on_floor else 'space'}, law {law['name']}, friction {fm}")
    return finish(B, 2 * R, E_s, 2 * v0, 2 * R, tend)


def k_stack(B, rng):
    """A column of spheres or boxes on a floor, touching or resting."""
    boxes = rng.random() < 0.35
    n = int(rng.integers(2, 4 if boxes else 6))
    R = pick_size(rng, 2e-3, 0.2)
    gm = G0
    g, gmode = pick_gravity(rng, ("vertical", "vertical", "vertical", "tilted"))
    B.s["gravity"] = lst(g)
    gm = float(np.linalg.norm(g))
    resting = rng.random() < 0.4
    vol = 4 / 3 * math.pi * R ** 3 if not boxes else 8 * R ** 3
    m = pick_mass(rng, vol)
    fields, law = make_law(B, rng, m * gm, 0.5 * m, 0.0, R, laws=("t6lin", "t6tab", "power", "t6hyst2"))
    ffl, lfl = make_law(B, rng, n * m * gm, m, 0.0, R, laws=("t6lin", "t6tab", "power"))
    sids = []
    z = 0.0
    prev = 0.0
    pens = []
    for i in range(n):
        # the contact below ball i carries (n - i) weights
        if resting:
            pens.append(law_pen_at_force(lfl if i == 0 else law, (n - i) * m * gm))
        else:
            pens.append(0.0)
    for i in range(n):
        # cubes of slightly different sizes, each turned about z, so that no
        # two edges coincide (the documented ambiguity of docs/theory.md 2.7)
        hz = R * (rng.uniform(0.6, 1.0) if boxes else 1.0)
        z += (hz if i == 0 else hz + prev) - pens[i]
        prev = hz
        if boxes:
            b, s = B.box((hz, hz, hz), m, (0.0, 0.0, z), rot_axis((0, 0, 1), rng.uniform(0.1, 1.4)))
        else:
            b, s = B.sphere(R, m, (0.0, 0.0, z))
        sids.append(s)
    sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
    fm = pick_friction_mode(rng, 0.4)
    # every body has the floor (a column that topples lands on it)
    for i in range(n):
        it = B.inter(sids[i], sf, ffl, label=f"{i + 1} on floor")
        it["law_curve"] = lfl
        add_friction(B, rng, it, lfl, fm, n * m * gm, m, 0.5, 4 * R * R)
    for i in range(n - 1):
        it = B.inter(sids[i], sids[i + 1], fields, label=f"{i + 1} - {i + 2}")
        it["law_curve"] = law
        add_friction(B, rng, it, law, fm, m * gm, 0.5 * m, 0.5, 4 * R * R)
    tend = math.sqrt(2 * R / gm) * rng.uniform(5.0, 20.0)
    H = 2 * R * n
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"{n} {'boxes' if boxes else 'balls'}, {'resting' if resting else 'touching'}, gravity {gmode}, "
                        f"laws {law['name']}/{lfl['name']}, friction {fm}")
    return finish(B, 2 * R, E_s, math.sqrt(2 * gm * H), H, tend)


def box_dims(rng, lo=2e-3, hi=0.5):
    s = pick_size(rng, lo, hi)
    half = np.array([s, s * rng.uniform(0.3, 1.0), s * rng.uniform(0.2, 1.0)])
    return half


def k_box_floor(B, rng):
    """A box on a floor plane: touching, resting, sliding, spinning, dropped
    level or tilted."""
    half = box_dims(rng)
    m = pick_mass(rng, 8 * np.prod(half))
    g, gmode = pick_gravity(rng, ("vertical", "vertical", "tilted"))
    B.s["gravity"] = lst(g)
    gm = float(np.linalg.norm(g))
    start = start_mode(rng, ("touching", "resting", "sliding", "spinning", "dropped", "dropped_tilted"))
    Q = rot_axis((0, 0, 1), rng.uniform(0, 2 * math.pi))
    h = 0.0
    v = np.zeros(3)
    w = np.zeros(3)
    if start == "sliding":
        ang = rng.uniform(0, 2 * math.pi)
        v = np.array([math.cos(ang), math.sin(ang), 0.0]) * loguniform(rng, 0.01, 5.0)
    if start == "spinning":
        w = np.array([0, 0, 1.0]) * loguniform(rng, 0.1, 30.0) * rng.choice([-1, 1])
    if start.startswith("dropped"):
        h = min(float(min(half)) * loguniform(rng, 0.1, 20.0), 1.0)
        if start == "dropped_tilted":
            Q = rot_axis(rng.normal(size=3), rng.uniform(0.05, math.pi)) @ Q
    v_imp = math.sqrt(2 * gm * h)
    fields, law = make_law(B, rng, m * gm, m, v_imp, float(min(half)))
    pen0 = law_pen_at_force(law, m * gm) if start == "resting" else 0.0
    zc = h + float(abs(Q[2, :]) @ half) - pen0
    b, sb = B.box(half, m, (0.0, 0.0, zc), Q, v, w)
    sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
    it = B.inter(sb, sf, fields) if rng.random() < 0.5 else B.inter(sf, sb, fields)
    it["law_curve"] = law
    fm = pick_friction_mode(rng, 0.2 if start == "sliding" else 0.4)
    add_friction(B, rng, it, law, fm, m * gm, m, max(np.linalg.norm(v), 0.5), 4 * half[0] * half[1])
    tend = math.sqrt(2 * max(h, half[2]) / gm) * rng.uniform(3.0, 15.0)
    if start == "sliding":
        tend = max(tend, min(2.0, np.linalg.norm(v) / (0.3 * gm) * 1.5))
    H = h + float(np.linalg.norm(half))
    vsc = v_imp + np.linalg.norm(v) + np.linalg.norm(w) * np.linalg.norm(half)
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"start {start}, gravity {gmode}, law {law['name']}, friction {fm}")
    return finish(B, 2 * float(max(half)), E_s, vsc, H, tend)


def k_box_incline(B, rng):
    """A box on an incline with friction, touching (or resting), at rest or
    launched."""
    half = box_dims(rng, 5e-3, 0.3)
    m = pick_mass(rng, 8 * np.prod(half))
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    th = math.radians(rng.uniform(5.0, 40.0))
    Qi = incline_frame(th, rng.uniform(0, 2 * math.pi))
    n = Qi @ np.array([0, 0, 1.0])
    Q = Qi @ rot_axis((0, 0, 1), rng.uniform(0, 2 * math.pi))
    start = start_mode(rng, ("touching", "touching", "resting", "moving"))
    fields, law = make_law(B, rng, m * gm * math.cos(th), m, 0.0, float(min(half)))
    pen0 = law_pen_at_force(law, m * gm * math.cos(th)) if start == "resting" else 0.0
    c = n * (half[2] - pen0)
    v = np.zeros(3)
    if start == "moving":
        v = Qi @ np.array([rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0]) * loguniform(rng, 0.01, 2.0)
    b, sb = B.box(half, m, c, Q, v)
    sf = B.plane((0, 0, 0), n, label="incline")
    it = B.inter(sb, sf, fields) if rng.random() < 0.5 else B.inter(sf, sb, fields)
    it["law_curve"] = law
    fm = pick_friction_mode(rng, 0.05)
    add_friction(B, rng, it, law, fm, m * gm * math.cos(th), m, max(np.linalg.norm(v), 0.5), 4 * half[0] * half[1])
    tend = rng.uniform(0.2, 1.0)
    s_max = np.linalg.norm(v) * tend + 0.5 * gm * math.sin(th) * tend ** 2
    H = s_max * math.sin(th) + float(np.linalg.norm(half))
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"incline {math.degrees(th):.1f} deg, start {start}, law {law['name']}, friction {fm}")
    return finish(B, 2 * float(max(half)), E_s, np.linalg.norm(v) + gm * math.sin(th) * tend, H, tend)


def k_box_box(B, rng):
    """A box on (or dropped on) a fixed box, or two free boxes stacked on a floor."""
    half = box_dims(rng, 5e-3, 0.3)
    m = pick_mass(rng, 8 * np.prod(half))
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    variant = str(rng.choice(["on_fixed", "dropped_on_fixed", "free_stack", "sliding_on_fixed"]))
    Q = rot_axis((0, 0, 1), rng.uniform(0, 2 * math.pi)) if rng.random() < 0.5 else np.eye(3)
    h = 0.0
    v = np.zeros(3)
    if variant == "dropped_on_fixed":
        h = float(min(half)) * loguniform(rng, 0.1, 10.0)
        if rng.random() < 0.5:
            Q = rot_axis(rng.normal(size=3), rng.uniform(0.02, 0.5)) @ Q
    if variant == "sliding_on_fixed":
        ang = rng.uniform(0, 2 * math.pi)
        v = np.array([math.cos(ang), math.sin(ang), 0.0]) * loguniform(rng, 0.01, 1.0)
    v_imp = math.sqrt(2 * gm * h)
    fields, law = make_law(B, rng, m * gm, m, v_imp, float(min(half)))
    fm = pick_friction_mode(rng, 0.3)
    lower = half * np.array([rng.uniform(1.5, 4.0), rng.uniform(1.5, 4.0), rng.uniform(0.5, 2.0)])
    tend = math.sqrt(2 * max(h, half[2]) / gm) * rng.uniform(3.0, 12.0)
    if variant == "sliding_on_fixed":
        tend = max(tend, min(1.5, np.linalg.norm(v) / (0.3 * gm) * 1.5))
    if variant != "free_stack":
        # the fixed box is wide enough for the whole slide: a box hanging
        # over an edge is outside what node to surface models (theory 2.7)
        lower[:2] = np.maximum(lower[:2], np.linalg.norm(v) * tend + 2 * float(np.linalg.norm(half)))
    zc = lower[2] * 2 + h + max(abs(Q[2, :]) @ half, 0.0)
    b, sb = B.box(half, m, (0.0, 0.0, zc), Q, v)
    if variant == "free_stack":
        m2 = pick_mass(rng, 8 * np.prod(lower))
        b2, s2 = B.box(lower, m2, (0.0, 0.0, lower[2]))
        ff, lf = make_law(B, rng, (m + m2) * gm, m2, 0.0, float(min(lower)))
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        it = B.inter(s2, sf, ff, label="lower box on floor")
        it["law_curve"] = lf
        add_friction(B, rng, it, lf, fm, (m + m2) * gm, m2, 0.5, 4 * lower[0] * lower[1])
    else:
        s2 = B.surf(type="box", body=0, c=[0.0, 0.0, lower[2]], half=lst(lower), u=[1.0, 0, 0], v=[0, 1.0, 0],
                    label="fixed box")
    it = B.inter(sb, s2, fields, label="upper box on lower box") if rng.random() < 0.5 else \
        B.inter(s2, sb, fields, label="lower box - upper box")
    it["law_curve"] = law
    add_friction(B, rng, it, law, fm, m * gm, m, max(np.linalg.norm(v), 0.5), 4 * half[0] * half[1])
    H = zc + float(np.linalg.norm(half))
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"{variant}, law {law['name']}, friction {fm}")
    return finish(B, 2 * float(max(lower.max(), half.max())), E_s, v_imp + np.linalg.norm(v), H, tend)


def k_meshbox(B, rng):
    """A meshed box (/SURF/SEG on the body's nodes) against a plane, a fixed
    box or a meshed floor; or a sphere on a meshed floor."""
    half = box_dims(rng, 5e-3, 0.3)
    m = pick_mass(rng, 8 * np.prod(half))
    g, gmode = pick_gravity(rng, ("vertical", "vertical", "tilted"))
    B.s["gravity"] = lst(g)
    gm = float(np.linalg.norm(g))
    target = str(rng.choice(["plane", "plane", "fixedbox", "meshfloor"]))
    start = start_mode(rng, ("touching", "sliding", "dropped", "dropped_tilted", "resting"))
    Q = rot_axis((0, 0, 1), rng.uniform(0, 2 * math.pi))
    h = 0.0
    v = np.zeros(3)
    if start.startswith("dropped"):
        h = min(float(min(half)) * loguniform(rng, 0.1, 10.0), 0.5)
        if start == "dropped_tilted":
            Q = rot_axis(rng.normal(size=3), rng.uniform(0.05, 1.0)) @ Q
    if start == "sliding":
        ang = rng.uniform(0, 2 * math.pi)
        v = np.array([math.cos(ang), math.sin(ang), 0.0]) * loguniform(rng, 0.01, 2.0)
    v_imp = math.sqrt(2 * gm * h)
    fields, law = make_law(B, rng, m * gm, m, v_imp, float(min(half)))
    pen0 = law_pen_at_force(law, m * gm) if start == "resting" else 0.0
    zc = h + max(abs(Q[2, :]) @ half, 0.0) - pen0
    nmesh = (int(rng.integers(1, 5)), int(rng.integers(1, 5)))
    b, sb = B.meshbox(half, m, (0.0, 0.0, zc), Q, nmesh, v)
    tend = math.sqrt(2 * max(h, half[2]) / gm) * rng.uniform(3.0, 12.0)
    if start == "sliding":
        tend = max(tend, min(1.5, np.linalg.norm(v) / (0.3 * gm) * 1.5))
    # how far it can slide: launched, or down the tilt of the gravity; a
    # dropped box may leave its impact sideways as fast as it fell (a tilted
    # box turns its fall into a sideways bounce: seed 247000130 left a meshed
    # floor 20 half-sizes wide after 0.6 s, a corner below the floor's plane
    # came back in under its edge 5.8 mm deep)
    travel = ((np.linalg.norm(v) + v_imp) * tend + 0.5 * math.hypot(g[0], g[1]) * tend ** 2
              + 2 * float(np.linalg.norm(half)))
    if target == "plane":
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
    elif target == "fixedbox":
        # wide enough for the slide: a box hanging over the edge of a box is
        # outside what node to surface models (docs/theory.md 2.7)
        hb = float(max(half)) * 2
        sf = B.surf(type="box", body=0, c=[0.0, 0.0, -hb], half=[max(hb * 10, travel), max(hb * 10, travel), hb],
                    u=[1.0, 0, 0], v=[0, 1.0, 0], label="fixed box (floor)")
    else:
        sf = B.meshfloor(max(float(max(half)) * 20, 2 * travel), int(rng.integers(2, 8)))
    it = B.inter(sb, sf, fields) if rng.random() < 0.5 else B.inter(sf, sb, fields)
    it["law_curve"] = law
    fm = pick_friction_mode(rng, 0.3)
    add_friction(B, rng, it, law, fm, m * gm, m, max(np.linalg.norm(v), 0.5), 4 * half[0] * half[1])
    H = h + float(np.linalg.norm(half))
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"target {target}, start {start}, mesh {nmesh}, gravity {gmode}, law {law['name']}, friction {fm}")
    return finish(B, 2 * float(max(half)), E_s, v_imp + np.linalg.norm(v), H, tend)


def k_cylinder(B, rng):
    """A cylinder rolling on a floor or down an incline, dropped tumbling, or a
    ball against a fixed cylinder."""
    R = pick_size(rng, 2e-3, 0.2)
    L = R * loguniform(rng, 0.5, 6.0)
    m = pick_mass(rng, math.pi * R * R * L)
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    variant = str(rng.choice(["roll_floor", "roll_incline", "dropped", "ball_on_cyl", "cyl_on_box"]))
    fm = pick_friction_mode(rng, 0.2)
    h = 0.0
    if variant in ("roll_floor", "roll_incline", "cyl_on_box"):
        th = math.radians(rng.uniform(5.0, 30.0)) if variant == "roll_incline" else 0.0
        Qi = incline_frame(th, rng.uniform(0, 2 * math.pi)) if th else np.eye(3)
        n = Qi @ np.array([0, 0, 1.0])
        ax = Qi @ np.array([1.0, 0, 0])
        W = m * gm * math.cos(th)
        fields, law = make_law(B, rng, W, m, 0.0, R)
        v0 = loguniform(rng, 0.01, 3.0) if (variant != "roll_incline" or rng.random() < 0.3) else 0.0
        roll = Qi @ np.array([0, 1.0, 0])
        v = roll * v0
        w = -ax * v0 / R if rng.random() < 0.5 else np.zeros(3)
        iend = int(rng.integers(0, 2))
        b, sc = B.cyl(R, L, m, n * R, ax, v, w, iend=iend, icont=0)
        if variant == "cyl_on_box":
            hb = max(R, L) * 4
            sf = B.surf(type="box", body=0, c=lst(-n * hb), half=[hb * 4, hb * 4, hb], u=[1.0, 0, 0], v=[0, 1.0, 0],
                        label="fixed box (floor)")
        else:
            sf = B.plane((0, 0, 0), n, label="floor" if th == 0 else "incline")
        it = B.inter(sc, sf, fields) if rng.random() < 0.5 else B.inter(sf, sc, fields)
        it["law_curve"] = law
        add_friction(B, rng, it, law, fm, W, m, max(v0, 0.5), 2 * R * L)
        tend = rng.uniform(0.2, 1.0)
        H = 0.5 * gm * math.sin(th) * tend ** 2 * math.sin(th) + R
        vsc = v0 + gm * math.sin(th) * tend
    elif variant == "dropped":
        h = R * loguniform(rng, 0.2, 10.0)
        Q = rot_axis(rng.normal(size=3), rng.uniform(0, math.pi))
        ax = Q[:, 0]
        iend = int(rng.integers(0, 2))
        ext = R + abs(ax[2]) * L / 2 + (R * abs(ax[2]) if iend else 0.0)
        v_imp = math.sqrt(2 * gm * h)
        fields, law = make_law(B, rng, m * gm, m, v_imp, R)
        b, sc = B.cyl(R, L, m, (0, 0, h + ext), ax, iend=iend, icont=1)
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        it = B.inter(sc, sf, fields)
        it["law_curve"] = law
        add_friction(B, rng, it, law, fm, m * gm, m, v_imp, 2 * R * L)
        tend = math.sqrt(2 * h / gm) * rng.uniform(2.0, 6.0)
        H = h + ext
        vsc = v_imp
    else:
        # a ball dropped on a fixed horizontal cylinder (off the top line)
        Rb = R * loguniform(rng, 0.2, 2.0)
        mb = pick_mass(rng, 4 / 3 * math.pi * Rb ** 3)
        h = Rb * loguniform(rng, 0.1, 10.0)
        off = rng.uniform(-0.3, 0.3) * R
        v_imp = math.sqrt(2 * gm * h)
        fields, law = make_law(B, rng, mb * gm, mb, v_imp, min(R, Rb))
        sc = B.surf(type="cyl", body=0, c=[0.0, 0.0, 0.0], axis=[1.0, 0, 0], r=R, len=L, iend=int(rng.integers(0, 2)),
                    icont=0, label="fixed cylinder")
        b, sb = B.sphere(Rb, mb, (0.0, off, R + Rb + h))
        it = B.inter(sb, sc, fields) if rng.random() < 0.5 else B.inter(sc, sb, fields)
        it["law_curve"] = law
        add_friction(B, rng, it, law, fm, mb * gm, mb, v_imp, math.pi * Rb * Rb)
        tend = math.sqrt(2 * (h + 2 * R) / gm) * rng.uniform(1.5, 4.0)
        H = h + 2 * Rb + 2 * R
        vsc = math.sqrt(2 * gm * H)
    E_s = energy_scale(B.s, H)
    B.s["notes"].append(f"{variant}, law {it['law_curve']['name']}, friction {fm}")
    Lb = max(2 * R, L + 2 * R)
    return finish(B, Lb, E_s, vsc, H, tend)


def k_free(B, rng):
    """Free bodies in space (no gravity, nothing fixed) colliding: the
    momentum invariants apply."""
    pair = str(rng.choice(["sphere-sphere", "sphere-sphere", "sphere-box", "box-box", "cyl-cyl", "sphere-cyl",
                           "mesh-sphere", "three-spheres"]))
    fm = pick_friction_mode(rng, 0.4)
    s = pick_size(rng, 2e-3, 0.3)
    v0 = loguniform(rng, 0.01, 5.0)
    bodies = []

    def mk(kind, c, v, w, scale):
        if kind == "sphere":
            R = s * scale
            m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
            b, sid = B.sphere(R, m, c, v, w)
            return b, sid, m, R
        if kind == "box":
            half = s * scale * np.array([1.0, rng.uniform(0.4, 1), rng.uniform(0.3, 1)])
            # the struck box (second) is axis-aligned and larger, so the first
            # one's corners meet its faces: no edge-edge crossing, which node
            # to surface does not see (documented, docs/theory.md 2.7)
            Q = rot_axis(rng.normal(size=3), rng.uniform(0, math.pi)) if len(bodies) == 0 else np.eye(3)
            m = pick_mass(rng, 8 * np.prod(half))
            b, sid = B.box(half, m, c, Q, v, w)
            return b, sid, m, float(max(half))
        if kind == "mesh":
            half = s * scale * np.array([1.0, rng.uniform(0.4, 1), rng.uniform(0.3, 1)])
            Q = rot_axis(rng.normal(size=3), rng.uniform(0, math.pi))
            m = pick_mass(rng, 8 * np.prod(half))
            b, sid = B.meshbox(half, m, c, Q, (int(rng.integers(1, 4)), int(rng.integers(1, 4))), v, w)
            return b, sid, m, float(max(half))
        R = s * scale
        L = R * rng.uniform(1, 4)
        m = pick_mass(rng, math.pi * R * R * L)
        b, sid = B.cyl(R, L, m, c, (0, 0, 1.0), v, w, iend=int(rng.integers(0, 2)))
        return b, sid, m, max(R, L / 2)

    if pair == "three-spheres":
        kinds = ["sphere"] * 3
    else:
        k1, k2 = pair.split("-")
        kinds = [k1, k2]
    # bodies on a line along x, approaching, with an offset across (glancing)
    x = 0.0
    prev_ext = 0.0
    spin = rng.random() < 0.4
    for i, kd in enumerate(kinds):
        scale = loguniform(rng, 0.5, 2.0) if not (kd == "box" and i > 0) else loguniform(rng, 2.0, 3.0)
        gapf = rng.uniform(0.1, 2.0) * s
        v = np.array([v0 if i == 0 else -v0 * rng.uniform(0, 1), rng.uniform(-0.2, 0.2) * v0, 0.0])
        w = rng.normal(size=3) * v0 / s if spin else np.zeros(3)
        if kd in ("cyl",):
            w = np.array([0.0, 0.0, w[2]])    # keep the axes parallel: spin about the axis only
        ext_guess = s * scale * 2.2
        if i > 0:
            x += prev_ext + ext_guess + gapf
        c = np.array([x, rng.uniform(-0.5, 0.5) * s, 0.0 if kd == "cyl" else rng.uniform(-0.3, 0.3) * s])
        b, sid, m, ext = mk(kd, c, v, w, scale)
        bodies.append((b, sid, m, ext, kd))
        prev_ext = ext_guess
    laws_allowed = LAWS
    for i in range(len(bodies)):
        for j in range(i + 1, len(bodies)):
            bi, bj = bodies[i], bodies[j]
            if bi[4] == "mesh" and bj[4] == "mesh":
                continue
            mr = bi[2] * bj[2] / (bi[2] + bj[2])
            fields, law = make_law(B, rng, 0.0, mr, 2 * v0, min(bi[3], bj[3]), laws=laws_allowed)
            it = B.inter(bi[1], bj[1], fields, label=f"{bi[4]} {bi[0]} - {bj[4]} {bj[0]}")
            it["law_curve"] = law
            add_friction(B, rng, it, law, fm, mr * v0 * v0 / s, mr, 2 * v0, s * s)
    span = x + 4 * s
    tend = span / v0 * rng.uniform(1.0, 3.0)
    tend = min(tend, 3.0)
    E_s = energy_scale(B.s, 0.0)
    B.s["notes"].append(f"{pair}, v0 {v0:.3g}, spin {spin}, friction {fm}")
    Lb = 2 * max(bb[3] for bb in bodies)
    return finish(B, Lb, E_s, 2 * v0 + (np.max([np.linalg.norm(b["w"]) for b in B.s["bodies"]]) * Lb), 0.0, tend)


def k_pendulum_wall(B, rng):
    """A distance-joint pendulum (a ball on a massless rod to a fixed point)
    swinging into a TYPE6 wall; runs on IDA (joints)."""
    R = pick_size(rng, 5e-3, 0.1)
    m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    ell = R * loguniform(rng, 3.0, 30.0)
    anchor = np.array([0.7, 0.0, 0.0]) if rng.random() < 0.5 else rng.uniform(-1, 1, 3)
    th0 = math.radians(rng.uniform(10.0, 80.0))
    c = anchor + ell * np.array([math.sin(th0), 0.0, -math.cos(th0)])
    b, sb = B.sphere(R, m, c)
    # the wall: a vertical plane just behind the lowest point, facing +x
    wall_x = anchor[0] - R - ell * math.sin(math.radians(rng.uniform(0.0, 10.0)))
    sw = B.plane((wall_x, 0.0, 0.0), (1.0, 0.0, 0.0), label="wall")
    v_hit = math.sqrt(2 * gm * ell * (1 - math.cos(th0)))
    fields, law = make_law(B, rng, 0.0, m, v_hit, R, laws=("t6lin", "t6lin", "t6tab", "t6hyst2"))
    it = B.inter(sb, sw, fields, label="bob against wall")
    it["law_curve"] = law
    B.s["joints"].append({"id": 1, "kind": "DISTANCE", "b1": b, "b2": 0, "p": lst(c), "p2": lst(anchor),
                          "label": "rod"})
    tend = 2 * math.pi * math.sqrt(ell / gm) * rng.uniform(1.0, 3.0)
    H = ell * (1 - math.cos(th0)) + 2 * R
    E_s = energy_scale(B.s, H)
    B.s["method"] = "ida"
    B.s["notes"].append(f"anchor {lst(np.round(anchor, 3))}, rod {ell:.3g} m, theta0 {math.degrees(th0):.1f} deg, "
                        f"law {law['name']}")
    return finish(B, 2 * R, E_s, v_hit, H, tend)


def k_illposed(B, rng):
    """Deliberately ill-posed starts: a body well inside another at t = 0
    with no Inacti or Gap that accounts for it. The
    expected outcome is an input error (exit code 2)."""
    variant = str(rng.choice(["sphere_in_floor", "box_in_floor", "sphere_in_sphere", "mesh_irs_reversed"]))
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    B.s["expect"] = "input_error"
    R = pick_size(rng, 5e-3, 0.2)
    depth_rel = rng.uniform(0.1, 0.6)
    fm = pick_friction_mode(rng, 0.6)
    if variant == "sphere_in_floor":
        m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
        fields, law = make_law(B, rng, m * gm, m, 0.0, R)
        b, sb = B.sphere(R, m, (0.0, 0.0, R * (1 - depth_rel)))
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        it = B.inter(sb, sf, fields)
        depth = R * depth_rel
        L = 2 * R
    elif variant == "box_in_floor":
        half = np.array([R, R * 0.8, R * 0.6])
        m = pick_mass(rng, 8 * np.prod(half))
        fields, law = make_law(B, rng, m * gm, m, 0.0, float(min(half)))
        depth = half[2] * depth_rel
        b, sb = B.box(half, m, (0.0, 0.0, half[2] - depth))
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        it = B.inter(sb, sf, fields)
        L = 2 * R
    elif variant == "sphere_in_sphere":
        m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
        fields, law = make_law(B, rng, m * gm, 0.5 * m, 0.0, R)
        f2, law2 = make_law(B, rng, 2 * m * gm, m, 0.0, R)
        b1, s1 = B.sphere(R, m, (0.0, 0.0, R))
        depth = 2 * R * depth_rel
        b2, s2 = B.sphere(R, m, (0.0, 0.0, 3 * R - depth))
        sf = B.plane((0, 0, 0), (0, 0, 1), label="floor")
        it0 = B.inter(s1, sf, f2, label="lower ball on floor")
        it0["law_curve"] = law2
        it = B.inter(s1, s2, fields, label="balls overlapping")
        L = 2 * R
    else:
        # a meshed box resting on a meshed floor whose normals the interface
        # reverses (IRS/IRm = 1): seen from the reversed floor every node of
        # the box is deep inside at t = 0
        half = np.array([R, R, R * 0.5])
        m = pick_mass(rng, 8 * np.prod(half))
        # a TYPE6 law: the power law's card has no IRS/IRm, so on it the
        # floor is not reversed and the box simply rests (found by seed
        # 61000080, a scene expected to be refused that was well posed)
        fields, law = make_law(B, rng, m * gm, m, 0.0, float(min(half)), laws=[x for x in LAWS if x != "power"])
        b, sb = B.meshbox(half, m, (0.0, 0.0, half[2]), np.eye(3), (2, 2))
        sf = B.meshfloor(R * 10, 4)
        it = B.inter(sb, sf, fields)
        it["irm"] = 1
        depth = 2 * half[2]    # through the reversed floor, the box is as deep as it is tall
        L = 2 * R
    it["law_curve"] = law
    add_friction(B, rng, it, law, fm, 1.0, 1.0, 0.5, math.pi * R * R)
    tend = math.sqrt(2 * R / gm) * rng.uniform(2.0, 5.0)
    E_s = energy_scale(B.s, L)
    B.s["notes"].append(f"{variant}, initial overlap {depth:.3g} m ({depth_rel:.2f} of the size), law {law['name']}")
    return finish(B, L, E_s, math.sqrt(2 * gm * L), L, tend, extra={"overlap": float(depth)})


def k_belt(B, rng):
    """A body on a driven belt (a box body moving at an imposed speed, /IMPVEL
    along x, its other motions held by /BCS), with friction, optionally held
    back by a fixed wall: the work of the imposed velocity is the scene's
    energy supply (energy_imposed)."""
    what = str(rng.choice(["sphere", "box", "box", "meshbox"]))
    s = pick_size(rng, 5e-3, 0.2)
    gm = G0
    B.s["gravity"] = [0.0, 0.0, -gm]
    V = loguniform(rng, 0.01, 3.0) * float(rng.choice([-1.0, 1.0]))
    tend = rng.uniform(0.2, 1.5)
    wall = rng.random() < 0.4
    span = abs(V) * tend + 10 * s
    hb = s
    belt_half = np.array([span * 2, 4 * s + span * 0.1, hb])
    Mb = pick_mass(rng, 8 * np.prod(belt_half))
    b_belt, s_belt = B.box(belt_half, Mb, (0.0, 0.0, -hb), np.eye(3), v=(V, 0.0, 0.0), label="belt")
    fid = B.func([0.0, 1e3], [1.0, 1.0], label="constant 1 (belt speed, scaled)")
    B.s["impvel"] = [{"body": b_belt, "dir": "X", "fct": fid, "scale": V}]
    B.s["bcs"] = [{"body": b_belt, "trarot": "011 111"}]
    B.s["driven"] = [b_belt]
    pen0 = 0.0
    if what == "sphere":
        R = s
        m = pick_mass(rng, 4 / 3 * math.pi * R ** 3)
        fields, law = make_law(B, rng, m * gm, m, 0.0, R)
        b, sb = B.sphere(R, m, (0.0, 0.0, R))
        area = math.pi * R * R
        half = np.array([R, R, R])
    else:
        half = np.array([s, s * rng.uniform(0.5, 1.0), s * rng.uniform(0.3, 1.0)])
        m = pick_mass(rng, 8 * np.prod(half))
        fields, law = make_law(B, rng, m * gm, m, 0.0, float(min(half)))
        Q = rot_axis((0, 0, 1), rng.uniform(0, 2 * math.pi))
        if what == "box":
            b, sb = B.box(half, m, (0.0, 0.0, half[2]), Q)
        else:
            b, sb = B.meshbox(half, m, (0.0, 0.0, half[2]), Q, (int(rng.integers(1, 4)), int(rng.integers(1, 4))))
        area = 4 * half[0] * half[1]
    it = B.inter(sb, s_belt, fields, label="object on belt") if rng.random() < 0.5 else \
        B.inter(s_belt, sb, fields, label="belt - object")
    it["law_curve"] = law
    fm = "t6" if rng.random() < 0.6 else "card"
    add_friction(B, rng, it, law, fm, m * gm, m, abs(V), area)
    if wall:
        # a fixed wall downstream, facing the object
        xw = math.copysign(float(np.linalg.norm(half)) * 1.5 + abs(V) * tend * 0.2, V)
        sw = B.plane((xw, 0.0, 0.0), (-math.copysign(1.0, V), 0.0, 0.0), label="wall")
        f2, law2 = make_law(B, rng, m * gm, m, abs(V), float(min(half)))
        it2 = B.inter(sb, sw, f2, label="object against wall")
        it2["law_curve"] = law2
        add_friction(B, rng, it2, law2, fm, m * gm, m, abs(V), area)
    # energy scale: the object's kinetic energy at the belt speed and its weight
    # over its size (the belt's own kinetic energy is constant)
    E_s = max(0.5 * m * V * V, m * gm * float(np.linalg.norm(half)))
    B.s["notes"].append(f"{what} on a belt at {V:.3g} m/s, {'wall, ' if wall else ''}law {law['name']}, friction {fm}")
    s_ = finish(B, 2 * float(max(half)), E_s, 2 * abs(V), float(np.linalg.norm(half)), tend)
    s_["scales"]["m_total"] = m
    return s_


GENERATORS = {
    "sphere_drop": k_sphere_drop, "sphere_incline": k_sphere_incline, "ramp_wall": k_ramp_wall,
    "cradle": k_cradle, "stack": k_stack, "box_floor": k_box_floor, "box_incline": k_box_incline,
    "box_box": k_box_box, "meshbox": k_meshbox, "cylinder": k_cylinder, "free": k_free,
    "pendulum_wall": k_pendulum_wall, "illposed": k_illposed, "belt": k_belt,
}


def pick_kind(seed, kinds=None):
    kinds = list(kinds or KINDS)
    w = np.array([KINDS[k] for k in kinds], float)
    rng = np.random.default_rng([int(seed), 0])
    return kinds[int(rng.choice(len(kinds), p=w / w.sum()))]


def generate(seed, kinds=None, kind=None):
    """The scene of a seed: its kind from (seed, 0) among `kinds` unless
    `kind` is given, its contents from (seed, 1)."""
    kind = kind or pick_kind(seed, kinds)
    rng = np.random.default_rng([int(seed), 1])
    B = Builder(kind, seed, rng)
    s = GENERATORS[kind](B, rng)
    s["shapes"] = shapes_of(s)
    return s


def shapes_of(s):
    """Per surface: its body, kind and half-thickness (the geometric depth
    beyond which a penetration is a pass-through, README invariant d)."""
    out = {}
    for f in s["surfaces"]:
        t = f["type"]
        if t == "sphere":
            h = f["r"]
        elif t == "box" or (t == "seg" and f.get("body")):
            h = float(min(f["half"]))
        elif t == "cyl":
            h = f["r"]
        else:
            h = math.inf
        if not f.get("body"):
            h = math.inf
        out[str(f["id"])] = {"body": f.get("body", 0), "type": t, "half_thickness": h}
    return out
