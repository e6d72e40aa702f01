"""Scene -> ricochet deck (Radioss block format), in any consistent unit
system and with full double precision in every real field.

A scene (scenes.py) is a JSON-serialisable dict in SI: bodies, extra nodes,
surfaces, curves, interfaces, a /FRICTION card, joints, gravity, run. This
module writes it as a deck; `transform` returns the same scene moved by a
rotation R and a translation t (the frame-invariance variant); `write` with
`units=(mass, length, time)` writes every dimensioned field divided by its
unit (the unit-invariance variant). Fields without a fixed dimension
(/INTER/POWER K and C and its splines, /FRICTION C1..C6 of Ifric 1, 2) are
written in cards whose header names /UNIT/9 (kg, m, s), as
docs/case-format.md section 1 requires.

Reals are written in 20 columns with the shortest representation that
reads back to the same double (repr), falling back to fewer digits only when
that does not fit (at least 14 significant digits with an exponent), so the
deck is the scene to the last bit in almost every field (the deck writer of
python/ricochet/deck.py keeps 12 digits, which is not enough for a
millimetre scene 1 km from the origin).
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import copy
import json

import numpy as np

UNIT = {"kg": 1.0, "g": 1e-3, "mg": 1e-6, "t": 1e3,
        "m": 1.0, "cm": 1e-2, "mm": 1e-3, "km": 1e3,
        "s": 1.0, "ms": 1e-3}

# dimensions (mass, length, time)
NONE, MASS, LEN, TIME = (0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)
VEL, ACC, ANGVEL = (0, 1, -1), (0, 1, -2), (0, 0, -1)
FORCE, STIFF, VISC = (1, 1, -2), (1, 0, -2), (1, 0, -1)
INERTIA, AREA, FREQ = (1, 2, 0), (0, 2, 0), (0, 0, -1)

SI_UNIT_ID = 9          # the /UNIT card in kg, m, s of every deck


def freal(v):
    """A real in at most 20 characters, reading back to the same double when
    it can (repr; 17 significant digits can take all 20 columns, so two
    fields may touch: the format is column-based)."""
    v = float(v)
    if not np.isfinite(v):
        raise ValueError(f"non-finite value {v} in a scene")
    if v == 0.0:
        return "0.0"
    s = repr(v)
    if len(s) <= 20:
        return s
    for p in range(16, 5, -1):
        s = f"{v:.{p}g}"
        if len(s) <= 20:
            return s
    raise ValueError(f"cannot write {v} in 20 columns")


class Writer:
    def __init__(self, units=("kg", "m", "s")):
        self.units = tuple(units)
        self.f = tuple(UNIT[u] for u in units)
        self.lines = []

    def c(self, v, dim):
        """v [SI] in the deck's units."""
        a, b, t = dim
        return float(v) / (self.f[0] ** a * self.f[1] ** b * self.f[2] ** t)

    def line(self, *fields):
        """fields: ('i', v) 10 columns, ('r', v, dim) 20 columns, ('s', text,
        width); None leaves a field blank."""
        out = []
        for fld in fields:
            kind, v = fld[0], fld[1]
            if kind == "i":
                out.append(" " * 10 if v is None else f"{int(v):>10d}")
            elif kind == "r":
                dim = fld[2] if len(fld) > 2 else NONE
                out.append(" " * 20 if v is None else f"{freal(self.c(v, dim)):>20s}")
            elif kind == "rsi":  # a real written as is (an SI card)
                out.append(" " * 20 if v is None else f"{freal(v):>20s}")
            else:
                out.append(f"{v:>{fld[2]}s}")
        return "".join(out).rstrip()

    def add(self, *lines):
        self.lines.extend(lines)


def vec(w, v, dim=LEN):
    return w.line(("r", v[0], dim), ("r", v[1], dim), ("r", v[2], dim))


FRAME_SKEW_ID = 9000    # the /SKEW/FIX of a turned scene's /BCS and /IMPVEL


def loads_turn(scene):
    """Whether the scene's /BCS and /IMPVEL can be turned with a frame (along
    the axes of a /SKEW/FIX): its imposed velocities are all translations
    (ricochet imposes a rotation about a global axis only)."""
    return all(len(iv["dir"]) == 1 for iv in scene.get("impvel", []))


def frame_skew(scene):
    """Whether the scene, turned by the frame variant (transform), writes its
    /BCS and /IMPVEL along the turned axes (a /SKEW/FIX)."""
    return "frame" in scene and bool(scene.get("bcs") or scene.get("impvel")) and loads_turn(scene)


def write(scene, units=("kg", "m", "s"), header=()):
    """The deck text of a scene. header: comment lines (without '#') put at
    the top; the scene itself is embedded as '#PHYSFUZZ-SCENE' comment lines
    so that the deck alone reproduces the scene (scenefuzz.py replay)."""
    w = Writer(units)
    si = units == ("kg", "m", "s")
    w.add("#RADIOSS STARTER")
    for h in header:
        w.add("# " + h if h else "#")
    blob = json.dumps(scene, separators=(",", ":"), sort_keys=True)
    for k in range(0, len(blob), 900):
        w.add("#PHYSFUZZ-SCENE " + blob[k:k + 900])
    w.add("/BEGIN", scene.get("title", "physfuzz scene")[:100], w.line(("i", 2022), ("i", 0)),
          "".join(u.rjust(20) for u in units), "".join(u.rjust(20) for u in units))
    w.add(f"/UNIT/{SI_UNIT_ID}", "SI for the cards without a fixed dimension",
          "".join(u.rjust(20) for u in ("kg", "m", "s")))

    bodies = scene["bodies"]
    nodes = [(b["id"], b["x"]) for b in bodies] + [(n["id"], n["x"]) for n in scene.get("nodes", [])]
    w.add("/NODE", *[w.line(("i", nid), ("s", "", 0)) + "".join(f"{freal(w.c(x, LEN)):>20s}" for x in xx)
                     for nid, xx in nodes])
    for b in bodies:
        w.add(f"/GRNOD/NODE/{100000 + b['id']}", f"main node of body {b['id']}", w.line(("i", b["id"])))
        sec = [n["id"] for n in scene.get("nodes", []) if n.get("body") == b["id"]]
        grnd = None
        if sec:
            grnd = 200000 + b["id"]
            rows = [sec[k:k + 10] for k in range(0, len(sec), 10)]
            w.add(f"/GRNOD/NODE/{grnd}", f"mesh nodes of body {b['id']}",
                  *["".join(f"{v:>10d}" for v in r) for r in rows])
        J = b["J"]
        w.add(f"/RBODY/{b['id']}", b.get("label", "body")[:100],
              w.line(("i", b["id"]), ("i", 0), ("i", 0), ("i", 3), ("r", b["mass"], MASS), ("i", grnd)),
              w.line(("r", J[0][0], INERTIA), ("r", J[1][1], INERTIA), ("r", J[2][2], INERTIA)),
              w.line(("r", J[0][1], INERTIA), ("r", J[1][2], INERTIA), ("r", J[0][2], INERTIA)))
        if any(v != 0.0 for v in b["v"]):
            w.add(f"/INIVEL/TRA/{b['id']}", "initial velocity",
                  w.line(("r", b["v"][0], VEL), ("r", b["v"][1], VEL), ("r", b["v"][2], VEL),
                         ("i", 100000 + b["id"]), ("i", 0)))
        if any(v != 0.0 for v in b["w"]):
            w.add(f"/INIVEL/ROT/{500000 + b['id']}", "initial angular velocity",
                  w.line(("r", b["w"][0], ANGVEL), ("r", b["w"][1], ANGVEL), ("r", b["w"][2], ANGVEL),
                         ("i", 100000 + b["id"]), ("i", 0)))

    for s in scene["surfaces"]:
        t, sid, body = s["type"], s["id"], s.get("body", 0)
        if t == "plane":
            p, n = np.array(s["p"]), np.array(s["n"])
            w.add(f"/SURF/PLANE/{sid}", s.get("label", "plane"), vec(w, p), vec(w, p + s.get("nlen", 1.0) * n))
            if body:
                w.add(w.line(("i", body)))
        elif t == "sphere":
            r = s["r"]
            w.add(f"/SURF/ELLIPS/{sid}", s.get("label", "sphere"), w.line(("i", 0), ("i", 2), ("i", body)),
                  vec(w, s["c"]), w.line(("r", r, LEN), ("r", r, LEN), ("r", r, LEN)))
        elif t == "box":
            w.add(f"/SURF/BOX/{sid}", s.get("label", "box"), w.line(("i", body)), vec(w, s["c"]),
                  vec(w, s["half"]), vec(w, s["u"], NONE), vec(w, s["v"], NONE))
        elif t == "cyl":
            w.add(f"/SURF/CYL/{sid}", s.get("label", "cylinder"),
                  w.line(("i", body), ("i", s.get("iend", 0)), ("i", s.get("icont", 0))),
                  vec(w, s["c"]), vec(w, s["axis"], NONE), w.line(("r", s["r"], LEN), ("r", s["len"], LEN)))
        elif t == "seg":
            w.add(f"/SURF/SEG/{sid}", s.get("label", "segments"),
                  *[w.line(("i", k + 1), *[("i", v) for v in seg]) for k, seg in enumerate(s["segs"])])
        else:
            raise ValueError(f"unknown surface type {t}")

    for f in scene.get("funcs", []):
        # curves are dimensionless tables (their scales are on the cards);
        # the splines of /INTER/POWER are physical values in SI, in an SI card
        w.add(f"/FUNCT/{f['id']}", f.get("label", "curve"),
              *[f"{freal(x):>20s}{freal(y):>20s}" for x, y in zip(f["x"], f["y"])])

    for it in scene["inters"]:
        if it["law"] == "type6":
            g = it.get
            fs = g("fric_s")
            w.add(f"/INTER/TYPE6/{it['id']}", it.get("label", "contact"),
                  w.line(("i", it["s1"]), ("i", it["s2"])),
                  w.line(("r", g("sfric"), FORCE), ("r", g("fric")), ("r", g("gap"), LEN), ("r", g("tstart"), TIME),
                         ("r", g("tstop"), TIME)),
                  w.line(("i", g("istick")), ("i", g("irs")), ("i", g("irm")), ("i", g("inacti")), ("i", 0), ("i", 0),
                         ("r", None), ("r", None)),
                  w.line(("i", it["fct_ld"]), ("i", g("iform", 0)), ("r", g("ascalex", 1.0), LEN),
                         ("r", g("fscaleld", 1.0), FORCE), ("i", g("icor"))),
                  w.line(("i", g("fct_ul")), ("s", "" if fs is None else freal(fs), 10), ("r", g("stiff"), STIFF),
                         ("r", g("fscaleul", 1.0), FORCE)),
                  w.line(("r", g("visc"), VISC), ("i", 0), ("i", 0), ("r", None), ("r", g("e_target")),
                         ("r", g("v_imp"), VEL)))
        elif it["law"] == "power":
            g = it.get
            if g("irs") or g("irm"):  # the card has no such fields: the scene would not be what it says
                raise ValueError("an /INTER/POWER interface cannot reverse its surfaces' normals (irs, irm)")
            lines = [w.line(("i", it["s1"]), ("i", it["s2"]), ("i", g("fct_stiff")), ("i", g("fct_damp")),
                            ("i", g("ispline")), ("i", g("irdf"))),
                     w.line(("rsi", g("k")), ("rsi", g("m1")), ("rsi", g("c")), ("rsi", g("m2")), ("rsi", g("m3"))),
                     w.line(("rsi", g("rdf")), ("rsi", g("dreg")), ("rsi", g("vreg")), ("rsi", g("tstart")),
                            ("rsi", g("tstop"))),
                     w.line(("rsi", g("mus")), ("rsi", g("vs")), ("rsi", g("mud")), ("rsi", g("vd")),
                            ("rsi", g("fmax")))]
            if g("kt") is not None or g("e_target") is not None:
                lines.append(w.line(("rsi", g("kt"))))
            if g("e_target") is not None:
                lines.append(w.line(("rsi", g("e_target")), ("rsi", g("v_imp"))))
            w.add(f"/INTER/POWER/{it['id']}/{SI_UNIT_ID}", it.get("label", "power-law contact"), *lines)
        else:
            raise ValueError(f"unknown law {it['law']}")

    fr = scene.get("friction")
    if fr:
        ifric = fr.get("ifric", 0)
        cc = list(fr.get("c", [])) + [None] * 6
        if ifric in (1, 2):   # coefficients without a fixed dimension: an SI card
            hdr, cf = f"/FRICTION/1/{SI_UNIT_ID}", [("rsi", v) for v in cc[:6]]
            xf = ("rsi", fr.get("xfreq"))
            dtr, area = ("rsi", fr.get("dt_ref")), ("rsi", fr.get("area"))
            fric, visf = ("rsi", fr.get("fric")), ("rsi", fr.get("visf"))
        else:
            hdr = "/FRICTION/1"
            dims = [NONE, NONE, NONE, NONE, VEL, VEL] if ifric == 3 else [NONE] * 6
            cf = [("r", v, d) for v, d in zip(cc[:6], dims)]
            xf = ("r", fr.get("xfreq"), FREQ if fr.get("ifiltr") == 3 else NONE)
            dtr, area = ("r", fr.get("dt_ref"), TIME), ("r", fr.get("area"), AREA)
            fric, visf = ("r", fr.get("fric")), ("r", fr.get("visf"))
        w.add(hdr, "friction of every interface",
              w.line(("i", ifric), ("i", fr.get("ifiltr", 0)), xf, ("i", fr.get("iform", 1)), dtr, area),
              w.line(*cf[:5]), w.line(cf[5], fric, visf))

    for j in scene.get("joints", []):
        w.add(f"/JOINT/{j['kind'].upper()}/{j['id']}", j.get("label", "joint"),
              w.line(("i", j["b1"]), ("i", j["b2"])), vec(w, j["p"]))
        if j["kind"].upper() in ("DISTANCE",):
            w.add(vec(w, j["p2"]))
        elif j["kind"].upper() in ("REVOLUTE", "PRISMATIC"):
            w.add(vec(w, j["axis"], NONE))

    # a scene turned by the frame variant: its /BCS and /IMPVEL flags along
    # the turned axes, those of a /SKEW/FIX (Y' and Z' the turned y and z,
    # X' = Y' x Z')
    skew = FRAME_SKEW_ID if frame_skew(scene) else 0
    if skew:
        R = np.asarray(scene["frame"]["R"], float)
        w.add(f"/SKEW/FIX/{skew}", "the frame variant's axes", vec(w, [0.0, 0.0, 0.0]), vec(w, R[:, 1], NONE),
              vec(w, R[:, 2], NONE))
    for k, bc in enumerate(scene.get("bcs", [])):
        w.add(f"/BCS/{k + 1}", "held degrees of freedom",
              w.line(("s", bc["trarot"], 10), ("i", skew), ("i", 100000 + bc["body"])))
    for k, iv in enumerate(scene.get("impvel", [])):
        w.add(f"/IMPVEL/{k + 1}", "imposed velocity",
              w.line(("i", iv["fct"]), ("s", iv["dir"], 10), ("i", skew), ("i", 0), ("i", 100000 + iv["body"]),
                     ("i", 0), ("i", 0)),
              w.line(("r", 1.0, TIME), ("r", iv["scale"], ANGVEL if len(iv["dir"]) == 2 else VEL)))

    gvec = scene.get("gravity", [0.0, 0.0, 0.0])
    for k, (dname, gk) in enumerate(zip("XYZ", gvec)):
        if gk != 0.0:
            w.add(f"/GRAV/{k + 1}", f"gravity {dname}",
                  w.line(("i", 0), ("s", dname, 10), ("i", 0), ("i", 0), ("i", 0), ("s", "", 10),
                         ("r", 1.0, TIME), ("r", gk, ACC)))
    run = scene["run"]
    w.add("/RUN", w.line(("r", run["tend"], TIME), ("r", run["dtout"], TIME)))
    w.add("/END", "")
    return "\n".join(w.lines)


def read_scene(deck_text):
    """The scene embedded in a deck written by `write` (None if absent)."""
    parts = [ln[len("#PHYSFUZZ-SCENE "):] for ln in deck_text.splitlines() if ln.startswith("#PHYSFUZZ-SCENE ")]
    return json.loads("".join(parts)) if parts else None


# --------------------------------------------------------------------------
# frame transform


def random_rotation(rng):
    """A uniformly random rotation matrix (from a random unit quaternion)."""
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    return quat_to_mat(q)


def quat_to_mat(q):
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def transform(scene, R, t):
    """The scene rotated by R and translated by t: every point, direction,
    velocity, angular velocity, inertia tensor and the gravity vector."""
    s = copy.deepcopy(scene)
    R = np.asarray(R, float)
    t = np.asarray(t, float)

    def P(x):
        return list(R @ np.asarray(x, float) + t)

    def D(x):
        return list(R @ np.asarray(x, float))

    for b in s["bodies"]:
        b["x"], b["v"], b["w"] = P(b["x"]), D(b["v"]), D(b["w"])
        J = R @ np.asarray(b["J"], float) @ R.T
        J = 0.5 * (J + J.T)
        b["J"] = [list(r) for r in J]
    for n in s.get("nodes", []):
        n["x"] = P(n["x"])
    for f in s["surfaces"]:
        for key in ("p", "c"):
            if key in f:
                f[key] = P(f[key])
        for key in ("n", "u", "v", "axis"):
            if key in f:
                f[key] = D(f[key])
    for j in s.get("joints", []):
        for key in ("p", "p2"):
            if key in j:
                j[key] = P(j[key])
        if "axis" in j:
            j["axis"] = D(j["axis"])
    s["gravity"] = D(s.get("gravity", [0.0, 0.0, 0.0]))
    s["frame"] = {"R": [list(r) for r in R], "t": list(t)}
    return s
