"""Invariants of one run (a..e, f) and of pairs of runs (g, h, i), checked
from the netCDF results (docs/output-format.md). Every tolerance is derived
from the scene's own scales and the run's tolerances; README.md gives each
one and why.

A violation is a dict: {"inv": key, "run": run name, "msg": text, plus
numbers}. Keys:
  a_solver_failure a_input_error a_physics_check a_crash a_incomplete a_timeout a_slow
  a_output_size
  start_not_refused
  b_energy_created
  c_damping c_hysteresis c_friction c_coupling_damping
  d_penetration d_centres d_box_overlap d_sink
  e_nonfinite
  f_linear_momentum f_angular_momentum
  g_frame g_frame_events g_frame_slow g_units g_units_events
  h_backend h_backend_events
  i_rtol
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import math

import numpy as np

import scenes as SC

C_YARD = 10.0          # variant vs base against C x (base vs tight)
REL_MOTION = 1e-5      # of L: the motion's tolerance
ENERGY_RTOL_FACTOR = 100.0   # energy tolerance = 100 max(rtol E_s, atol_energy)
ENERGY_WALK_FACTOR = 10.0    # ... + 10 sqrt(steps) atol_energy (energy_tol)
LIN_MOM_REL = 1e-8
ANG_MOM_REL = 1e-7
ANG_MOM_RTOL = 10.0     # ... or 10 rtol where larger (check_momentum)
PEN_FORCE_FACTOR = 1e3
# d_sink: a contact's deepest penetration within SINK_FACTOR x the law's
# penetration at its peak force (floor: at SINK_FLOOR x the scene's load)
SINK_FACTOR = 10.0
SINK_FLOOR = 1e-3
DIV_REL = 1e-3          # divergence threshold of the rtol study (of L)
RTOL_FLOOR_REL = 1e-7   # below this (of L) differences are not compared

CHANNELS = {"energy_damping": "c_damping", "energy_hysteresis": "c_hysteresis",
            "energy_friction": "c_friction", "energy_coupling_damping": "c_coupling_damping"}


# --------------------------------------------------------------------------
# results


def load(path):
    """The arrays the checks need from a results file (None if unreadable)."""
    import netCDF4
    try:
        d = netCDF4.Dataset(path)
    except OSError:
        return None
    try:
        r = {"attrs": {k: d.getncattr(k) for k in d.ncattrs()}}

        def arr(name):
            if name not in d.variables:
                return None
            v = d.variables[name]
            v.set_auto_mask(False)
            return np.array(v[:])
        for name in ("time", "at_event", "body_id", "body_fixed", "body_position", "body_quaternion", "body_velocity",
                     "body_angular_velocity", "inter_id", "inter_penetration", "inter_mode", "inter_force_normal",
                     "event_time", "event_penetration", "event_force_normal", "event_normal_speed", "energy_kinetic", "energy_potential", "energy_contact_work", "energy_damping",
                     "energy_friction_work", "energy_contact_stored", "energy_hysteresis", "energy_friction",
                     "energy_coupling_elastic", "energy_coupling_damping", "energy_catenary", "energy_imposed",
                     "energy_total", "impact_speed_in", "impact_peak_force", "impact_inter",
                     "impact_max_penetration", "persistent_inter", "persistent_peak_force",
                     "persistent_max_penetration"):
            r[name] = arr(name)
        for name in ("event_kind", "event_element"):
            r[name] = list(d.variables[name][:]) if name in d.variables else []
        for name in ("inter_type",):
            r[name] = list(d.variables[name][:]) if name in d.variables else []
        return r
    finally:
        d.close()


# --------------------------------------------------------------------------
# helpers


def quat_mats(q):
    """(..., 4) quaternions (w, x, y, z) -> (..., 3, 3) rotation matrices."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    R = np.empty(q.shape[:-1] + (3, 3))
    R[..., 0, 0] = 1 - 2 * (y * y + z * z)
    R[..., 0, 1] = 2 * (x * y - w * z)
    R[..., 0, 2] = 2 * (x * z + w * y)
    R[..., 1, 0] = 2 * (x * y + w * z)
    R[..., 1, 1] = 1 - 2 * (x * x + z * z)
    R[..., 1, 2] = 2 * (y * z - w * x)
    R[..., 2, 0] = 2 * (x * z - w * y)
    R[..., 2, 1] = 2 * (y * z + w * x)
    R[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return R


def rot_angle(Ra, Rb):
    """Angle of the rotation Ra^T Rb, (..., 3, 3) each."""
    M = np.einsum("...ji,...jk->...ik", Ra, Rb)
    s = 0.5 * np.sqrt((M[..., 2, 1] - M[..., 1, 2]) ** 2 + (M[..., 0, 2] - M[..., 2, 0]) ** 2 +
                      (M[..., 1, 0] - M[..., 0, 1]) ** 2)
    c = 0.5 * (M[..., 0, 0] + M[..., 1, 1] + M[..., 2, 2] - 1.0)
    return np.arctan2(s, c)


def body_radius(b):
    sh = b.get("shape", {})
    t = sh.get("type")
    if t == "sphere":
        return sh["r"]
    if t == "box":
        return float(np.linalg.norm(sh["half"]))
    if t == "cyl":
        return math.hypot(sh["r"], sh["len"] / 2 + sh["r"] * sh.get("iend", 0))
    return 0.0


def free_bodies(scene):
    return [b for b in scene["bodies"]]


def viol(inv, run, msg, **kw):
    d = {"inv": inv, "run": run, "msg": msg}
    d.update({k: (float(v) if isinstance(v, (np.floating, float)) else v) for k, v in kw.items()})
    return d


def energy_tol(scene, res):
    """100 rtol E_s, or 100 times the run's own absolute energy tolerance
    where that is larger: ricochet raises it to the work of the contact
    forces over the rounding of the penetrations (F_s times the position
    floor, when the coordinates cannot resolve rtol of the penetration
    scale), and no run can keep its ledger closer than that. Plus what
    that absolute tolerance adds up to over the run's N steps as a random
    walk, ENERGY_WALK_FACTOR sqrt(N) atol_energy: the per-step rounding of
    a ledger at its floor is not a truncation error the tolerances bound
    globally (seen: a cradle of four balls at rtol 1e-10, its ledger's
    floor 2.5e-13 J, ended 3e-11 J to 6e-11 J above its start at every
    rtol from 1e-9 to 1e-11, about sqrt(500 steps) floors). Where the
    position floor is raised, that absolute tolerance is at least the
    largest normal force of the run times the floor (not in the walk:
    that work is an error of an impact, not of every step)."""
    rtol = float(res["attrs"].get("rtol", 1e-8))
    try:
        atol_e = float(res["attrs"].get("atol_energy", 0.0))
        steps = float(res["attrs"].get("stats_steps", 0.0))
        floor = float(res["attrs"].get("atol_position_floor", 0.0))
    except (TypeError, ValueError):
        atol_e, steps, floor = 0.0, 0.0, 0.0
    if not math.isfinite(atol_e):
        atol_e = 0.0
    # where the position tolerance sits at the rounding of the coordinates,
    # the contacts' work is known to the largest normal force the run had
    # times that floor, not F_s times it: F_s is the force at the smallest
    # penetration the model is known to produce (seen: a pendulum's bob
    # striking a wall at 3.5 m/s, 8.6e7 N at 8e-8 m against F_s = 5.8 N,
    # its floor 1.6e-14 m: 1.6e-7 J above its start after each impact at
    # rtol 1e-10, 7e-7 J at rtol 1e-12, against a ledger floor of 9e-14 J)
    fn = res.get("inter_force_normal")
    work = 0.0
    if math.isfinite(floor) and floor > 0 and fn is not None and np.size(fn):
        fmax = float(np.nanmax(np.abs(fn)))
        if math.isfinite(fmax):
            work = fmax * floor
    if not (math.isfinite(steps) and steps > 0):
        steps = 0.0
    return ENERGY_RTOL_FACTOR * max(rtol * scene["scales"]["E_s"], atol_e, work) + \
        ENERGY_WALK_FACTOR * math.sqrt(steps) * atol_e


def mechanical_energy(scene, res):
    """Kinetic (from the bodies' states and the scene's masses and inertia),
    potential (from the positions and the scene's gravity), and the stored
    contact and coupling energies of the ledger."""
    pos, vel, om = res["body_position"], res["body_velocity"], res["body_angular_velocity"]
    g = np.asarray(scene.get("gravity", [0, 0, 0]), float)
    ek = np.zeros(len(res["time"]))
    ep = np.zeros(len(res["time"]))
    ids = list(res["body_id"])
    for b in scene["bodies"]:
        k = ids.index(b["id"])
        if res["body_fixed"] is not None and res["body_fixed"][k]:
            continue
        m, J = b["mass"], np.asarray(b["J"], float)
        v, w = vel[:, k, :], om[:, k, :]
        ek += 0.5 * m * np.einsum("ti,ti->t", v, v) + 0.5 * np.einsum("ti,ij,tj->t", w, J, w)
        ep += -m * pos[:, k, :] @ g
    stored = np.zeros(len(res["time"]))
    for name in ("energy_contact_stored", "energy_coupling_elastic", "energy_catenary"):
        if res.get(name) is not None:
            stored = stored + res[name]
    supply = -res["energy_imposed"] if res.get("energy_imposed") is not None else 0.0
    return ek, ep, stored, supply


# --------------------------------------------------------------------------
# single-run invariants


def check_exit(scene, run, rc, stderr, timed_out, stopped=0.0):
    """a: the exit code (stopped: the runner stopped the run, its results
    file too large: reported by the runner as a_output_size)."""
    out = []
    if stopped:
        return out
    lines = [ln for ln in (stderr or "").splitlines() if ln.strip() and "warning" not in ln.lower()]
    # the program's own message first (CVODE's warnings may precede it)
    main = [ln for ln in lines if ln.startswith("ricochet:")]
    msg = " | ".join(main or lines)[:1500]
    if scene.get("expect") == "input_error":
        # refused (exit 2), or run with ricochet's notice of the overlap: an
        # overlap whose law holds less than the scene's energy scale is
        # accepted, said on the standard error (docs/theory.md 13.3)
        if rc == 0 and "overlap at t = 0 by" in (stderr or ""):
            return out
        if rc != 2:
            out.append(viol("start_not_refused", run, f"deliberately ill-posed start (overlap "
                            f"{scene['scales'].get('overlap', 0):.3g} m) not refused: exit {rc}" +
                            (f": {msg}" if msg else ""), exit=rc))
        return out
    if timed_out:
        out.append(viol("a_timeout", run, f"run exceeded the time limit ({timed_out:g} s of CPU, or 4 x that of wall clock)"))
    elif rc == 3:
        out.append(viol("a_solver_failure", run, f"exit 3: {msg}", exit=rc))
    elif rc == 2 and ("too stiff for double precision" in msg or "below the resolution of the" in msg):
        # a deliberate refusal of numbers double precision cannot resolve (a
        # stiffness whose force moves by more than a quarter of the force
        # scale per rounding of the coordinates): the scene is beyond the
        # arithmetic, not an answer given wrong (README, "Refusals")
        pass
    elif rc == 2:
        out.append(viol("a_input_error", run, f"exit 2 on a well-posed scene: {msg}", exit=rc))
    elif rc == 5:
        # ricochet's own physics checks stopped the run: said, not silent,
        # but the scene is well posed and its answer is still wrong
        out.append(viol("a_physics_check", run, f"exit 5: {msg}", exit=rc))
    elif rc != 0:
        out.append(viol("a_crash", run, f"exit {rc}: {msg}", exit=rc))
    return out


def check_single(scene, run, res, rc):
    """Invariants a (complete), b, c, d, e, f on one run's results."""
    out = []
    if res is None or res["time"] is None or len(res["time"]) == 0:
        if rc == 0:
            out.append(viol("a_incomplete", run, "exit 0 but no readable results"))
        return out
    A = res["attrs"]
    t = res["time"]
    if rc == 0:
        if A.get("complete") != "yes" or abs(t[-1] - scene["run"]["tend"]) > 1e-9 * scene["run"]["tend"]:
            out.append(viol("a_incomplete", run, f"exit 0 but complete = {A.get('complete')}, "
                            f"last record at {t[-1]:.9g} s of {scene['run']['tend']:.9g}"))
    # e: finite values
    bad = []
    for name, v in res.items():
        if name in ("attrs", "event_kind", "event_element", "inter_type", "impact_speed_in", "impact_peak_force"):
            continue
        if isinstance(v, np.ndarray) and v.dtype.kind == "f" and name.startswith("event_") and \
                res.get("event_element") is not None and len(res["event_element"]) == len(v):
            # NaN where the event's element is not an interface (a method
            # switch's /SOLVER, a sensor): docs/output-format.md
            v = v[np.array([str(e).startswith("/INTER") for e in res["event_element"]], dtype=bool)]
        if isinstance(v, np.ndarray) and v.dtype.kind == "f" and not np.all(np.isfinite(v)):
            k = int(np.argmax(~np.all(np.isfinite(v.reshape(len(v), -1)), axis=1))) if v.ndim and len(v) else 0
            bad.append(f"{name} (first at record {k}, t = {t[min(k, len(t) - 1)]:.6g} s)")
    if bad:
        out.append(viol("e_nonfinite", run, "non-finite values: " + ", ".join(bad[:5])))
        return out
    sc = scene["scales"]
    tolE = energy_tol(scene, res)
    # b: no energy created
    ek, ep, st, supply = mechanical_energy(scene, res)
    emech = ek + ep + st
    excess = emech - emech[0] - supply
    k = int(np.argmax(excess))
    if excess[k] > tolE:
        out.append(viol("b_energy_created", run,
                        f"kinetic + potential + stored rose by {excess[k]:.4g} J above its initial {emech[0]:.4g} J "
                        f"at t = {t[k]:.6g} s (E_s = {sc['E_s']:.4g} J, tolerance {tolE:.3g} J; "
                        f"{excess[k] / sc['E_s']:.3g} E_s)",
                        value=excess[k], tol=tolE, t=t[k], E_s=sc["E_s"], E0=emech[0]))
    # c: dissipation channels non-decreasing
    for name, key in CHANNELS.items():
        c = res.get(name)
        if c is None:
            continue
        drop = np.maximum.accumulate(c) - c
        k = int(np.argmax(drop))
        if drop[k] > tolE:
            out.append(viol(key, run, f"{name} decreased by {drop[k]:.4g} J (to {c[k]:.4g} J at t = {t[k]:.6g} s; "
                            f"min {c.min():.4g} J; tolerance {tolE:.3g} J, E_s = {sc['E_s']:.4g} J)",
                            value=drop[k], tol=tolE, t=t[k], minimum=float(c.min())))
    # d: penetration bounded
    out += check_penetration(scene, run, res)
    # f: momentum
    out += check_momentum(scene, run, res)
    return out


def scene_load(scene, it, inf_impact=math.inf):
    """The scene's load on interface it [N]: the larger of its weight and
    the force of the interface's law where it has stored the kinetic
    energy of the whole scene's mass at its speed (inf_impact where that
    penetration is not finite)."""
    sc = scene["scales"]
    law = it["law_curve"]
    M = sc["m_total"]
    v = sc["v"]
    p_imp = SC.law_pen_at_energy(law, 0.5 * M * v * v)
    F_imp = float(SC.law_force(law, p_imp)) if np.isfinite(p_imp) else inf_impact
    return max(M * sc["g"], F_imp)


def pen_bound(scene, it):
    """The penetration at which the interface's elastic law reaches 1e3 x
    the larger of the scene's weight and the impact force at its speed, and
    the geometric bound (half the thinner body's thickness)."""
    law = it["law_curve"]
    F = PEN_FORCE_FACTOR * scene_load(scene, it)
    p_law = SC.law_pen_at_force(law, F)
    sh = scene["shapes"]
    h1 = sh[str(it["s1"])]["half_thickness"]
    h2 = sh[str(it["s2"])]["half_thickness"]
    if sh[str(it["s1"])]["type"] == "sphere" and sh[str(it["s2"])]["type"] == "sphere":
        p_geo = 0.5 * (h1 + h2)
    else:
        p_geo = min(h1, h2)
    return p_law, p_geo, F


def check_penetration(scene, run, res):
    out = []
    pen = res.get("inter_penetration")
    if pen is None or pen.size == 0:
        return out
    ids = list(res["inter_id"])
    t = res["time"]
    for it in scene["inters"]:
        if it["id"] not in ids:
            continue
        p = pen[:, ids.index(it["id"])]
        p_law, p_geo, F = pen_bound(scene, it)
        bound = min(p_law, p_geo)
        k = int(np.argmax(p))
        if p[k] > bound:
            out.append(viol("d_penetration", run,
                            f"{it.get('label', '')} (/INTER/{it['law'].upper()}/{it['id']}): penetration {p[k]:.4g} m at "
                            f"t = {t[k]:.6g} s beyond {bound:.4g} m ({'law at 1e3 x the load: ' + format(F, '.3g') + ' N' if p_law <= p_geo else 'half the thinner body'})",
                            value=p[k], bound=bound, t=t[k], inter=it["id"]))
    # centres of two spheres in contact never closer than (R1 + R2)/2
    surf = {f["id"]: f for f in scene["surfaces"]}
    bids = list(res["body_id"])
    pos = res["body_position"]
    for it in scene["inters"]:
        a, b = surf[it["s1"]], surf[it["s2"]]
        if a["type"] != "sphere" or b["type"] != "sphere" or not a.get("body") or not b.get("body"):
            continue
        d = np.linalg.norm(pos[:, bids.index(a["body"])] - pos[:, bids.index(b["body"])], axis=1)
        lim = 0.5 * (a["r"] + b["r"])
        k = int(np.argmin(d))
        if d[k] < lim:
            out.append(viol("d_centres", run, f"sphere centres of /INTER/{it['law'].upper()}/{it['id']} "
                            f"{d[k]:.4g} m apart at t = {t[k]:.6g} s (radii {a['r']:.4g}, {b['r']:.4g} m)",
                            value=d[k], bound=lim, t=t[k], inter=it["id"]))
    out += check_box_overlap(scene, run, res)
    out += check_sink(scene, run, res)
    return out


def check_sink(scene, run, res):
    """d_sink: each contact of the impact and persistent tables (their
    deepest penetration and peak force, both tracked at every integrator
    step) penetrates no deeper than SINK_FACTOR x the penetration at which
    the interface's elastic law reaches its peak force: a contact's force is
    its law's at its penetration (at the deepest point the rate is zero and
    the damping with it), so a body deeper than its force says has sunk
    into the other without resistance. Floor: the law's penetration at
    SINK_FLOOR x the scene's load (weight, or impact force at its speed).
    Elastic laws only: TYPE6 Iform 1 and 2 unload along their unload curve
    or Stiff line and keep a set (a penetration at zero force) by design."""
    out = []
    by_id = {it["id"]: it for it in scene["inters"]}
    floor = {}  # per interface: the law's penetration at SINK_FLOOR x the scene's load
    for tab in ("impact", "persistent"):
        inter, fpk, pmx = (res.get(f"{tab}_inter"), res.get(f"{tab}_peak_force"), res.get(f"{tab}_max_penetration"))
        if inter is None or fpk is None or pmx is None:
            continue
        for k in range(len(inter)):
            it = by_id.get(int(inter[k]))
            if it is None or not it.get("law_curve") or not np.isfinite(pmx[k]) or not np.isfinite(fpk[k]):
                continue
            if int(it.get("iform", 0) or 0) != 0:
                continue  # a hysteresis law (Iform 1, 2) keeps a set at zero force: its unload curve, its Stiff line
            law = it["law_curve"]
            if it["id"] not in floor:
                load = scene_load(scene, it, inf_impact=0.0)
                floor[it["id"]] = SC.law_pen_at_force(law, SINK_FLOOR * load) if load > 0 else 0.0
            p_fl = floor[it["id"]]
            p_pk = SC.law_pen_at_force(law, float(fpk[k])) if fpk[k] > 0 else 0.0
            bound = SINK_FACTOR * max(p_pk, p_fl)
            if bound > 0 and pmx[k] > bound:
                out.append(viol("d_sink", run,
                                f"{it.get('label', '')} (/INTER/{it['law'].upper()}/{it['id']}): the {tab} contact "
                                f"{k + 1} penetrates {pmx[k]:.4g} m, {pmx[k] / max(p_pk, p_fl):.3g} x the law's "
                                f"penetration {p_pk:.4g} m at its peak force {fpk[k]:.4g} N (beyond {SINK_FACTOR:g} x): "
                                f"sunk without the force", value=float(pmx[k]), bound=bound, inter=it["id"]))
    return out


def box_frames(scene, res, surf):
    """Centre (T, 3), axes (T, 3, 3) (rows u, v, w) and half-sizes of box
    surface `surf` over the records, from its body's motion relative to
    t = 0 (the box as the scene gives it at t = 0)."""
    c0 = np.asarray(surf["c"], float)
    u = np.asarray(surf.get("u", [1.0, 0.0, 0.0]), float)
    u = u / np.linalg.norm(u)
    v = np.asarray(surf.get("v", [0.0, 1.0, 0.0]), float)
    v = v - (v @ u) * u
    v = v / np.linalg.norm(v)
    ax0 = np.array([u, v, np.cross(u, v)])
    nt = len(res["time"])
    if not surf.get("body"):
        return np.tile(c0, (nt, 1)), np.tile(ax0, (nt, 1, 1)), np.asarray(surf["half"], float)
    k = list(res["body_id"]).index(surf["body"])
    pos = res["body_position"][:, k]
    R = quat_mats(res["body_quaternion"][:, k])
    Rrel = R @ R[0].T
    c = pos + np.einsum("tij,j->ti", Rrel, c0 - pos[0])
    axes = np.einsum("tij,kj->tki", Rrel, ax0)
    return c, axes, np.asarray(surf["half"], float)


def sat_depth(ca, A, ha, cb, B, hb):
    """Overlap depth of two boxes by the separating-axis test over the
    records: the least overlap of their projections on the 15 axes (face
    normals and edge cross products); negative when apart."""
    T = cb - ca
    axes = [A[:, k] for k in range(3)] + [B[:, k] for k in range(3)]
    for i in range(3):
        for j in range(3):
            L = np.cross(A[:, i], B[:, j])
            n = np.linalg.norm(L, axis=1)
            ok = n > 1e-6
            L = np.where(ok[:, None], L / np.where(ok, n, 1.0)[:, None], A[:, i])  # parallel: a face axis
            axes.append(L)
    depth = np.full(len(T), np.inf)
    for L in axes:
        r = -np.abs(np.einsum("ti,ti->t", T, L))
        r = r + np.einsum("k,tk->t", ha, np.abs(np.einsum("tki,ti->tk", A, L)))
        r = r + np.einsum("k,tk->t", hb, np.abs(np.einsum("tki,ti->tk", B, L)))
        depth = np.minimum(depth, r)
    return depth


def check_box_overlap(scene, run, res):
    """d_box_overlap: two boxes of an interface overlap (separating-axis
    depth, from the bodies' motion alone) no deeper than the interface's
    penetration bound: the engine's own penetration is that of its contact
    points (corners against faces) and does not see two edges that cross."""
    out = []
    if "body_quaternion" not in res or len(res.get("time", [])) == 0:
        return out
    surf = {f["id"]: f for f in scene["surfaces"]}
    t = res["time"]
    for it in scene["inters"]:
        a, b = surf.get(it["s1"]), surf.get(it["s2"])
        if not a or not b or a["type"] != "box" or b["type"] != "box":
            continue
        ca, A, ha = box_frames(scene, res, a)
        cb, B, hb = box_frames(scene, res, b)
        D = sat_depth(ca, A, ha, cb, B, hb) + float(it.get("gap", 0.0) or 0.0)
        p_law, p_geo, F = pen_bound(scene, it)
        bound = min(p_law, p_geo)
        k = int(np.argmax(D))
        if D[k] > bound:
            out.append(viol("d_box_overlap", run,
                            f"{it.get('label', '')} (/INTER/{it['law'].upper()}/{it['id']}): the boxes overlap by "
                            f"{D[k]:.4g} m (separating-axis depth) at t = {t[k]:.6g} s, beyond {bound:.4g} m",
                            value=float(D[k]), bound=bound, t=float(t[k]), inter=it["id"]))
    return out


def momentum_applies(scene):
    g = np.asarray(scene.get("gravity", [0, 0, 0]), float)
    if np.any(g != 0.0) or scene.get("joints"):
        return False
    return all(f.get("body") for f in scene["surfaces"])


def momenta(scene, res):
    ids = list(res["body_id"])
    c0 = None
    M = 0.0
    for b in scene["bodies"]:
        M += b["mass"]
    c0 = sum(b["mass"] * np.asarray(b["x"], float) for b in scene["bodies"]) / M
    P = 0.0
    L = 0.0
    for b in scene["bodies"]:
        k = ids.index(b["id"])
        x, v, w = res["body_position"][:, k], res["body_velocity"][:, k], res["body_angular_velocity"][:, k]
        R = quat_mats(res["body_quaternion"][:, k])
        P = P + b["mass"] * v
        Jw = np.einsum("ij,tj->ti", np.asarray(b["J"], float), w)
        L = L + b["mass"] * np.cross(x - c0, v) + np.einsum("tij,tj->ti", R, Jw)
    return P, L, c0


def check_momentum(scene, run, res):
    if not momentum_applies(scene):
        return []
    out = []
    sc = scene["scales"]
    P, L, c0 = momenta(scene, res)
    t = res["time"]
    Ps = sum(b["mass"] for b in scene["bodies"]) * sc["v"]
    Ls = sum(b["mass"] * sc["v"] * (np.linalg.norm(np.asarray(b["x"]) - c0) + sc["L"]) for b in scene["bodies"])
    dP = np.linalg.norm(P - P[0], axis=1)
    dL = np.linalg.norm(L - L[0], axis=1)
    k = int(np.argmax(dP))
    if dP[k] > LIN_MOM_REL * Ps:
        out.append(viol("f_linear_momentum", run, f"linear momentum changed by {dP[k]:.4g} kg m/s at t = {t[k]:.6g} s "
                        f"({dP[k] / Ps:.3g} of the scale {Ps:.4g})", value=dP[k] / Ps, t=t[k]))
    k = int(np.argmax(dL))
    # angular momentum is quadratic in the states: BDF keeps a linear
    # invariant (the linear momentum, exactly opposite forces) to the
    # Newton tolerance but not R J w, whose error is the integrator's own,
    # of order rtol (a free tumbling box at rtol 1e-6 lost 1.4e-7 of it)
    rtol = float(res["attrs"].get("rtol", 1e-8))
    if dL[k] > max(ANG_MOM_REL, ANG_MOM_RTOL * rtol) * Ls:
        out.append(viol("f_angular_momentum", run, f"angular momentum changed by {dL[k]:.4g} kg m^2/s at t = {t[k]:.6g} s "
                        f"({dL[k] / Ls:.3g} of the scale {Ls:.4g})", value=dL[k] / Ls, t=t[k]))
    return out


# --------------------------------------------------------------------------
# comparisons of two runs


def output_records(res):
    """Indices of the records at output times, keyed by their output index."""
    dt = float(res["attrs"]["dt_out"])
    t = res["time"]
    keep = np.nonzero(res["at_event"] == 0)[0]
    keys = np.rint(t[keep] / dt).astype(np.int64)
    ok = np.abs(t[keep] - keys * dt) <= 1e-6 * dt + 1e-12 * abs(t[keep])
    return dict(zip(keys[ok].tolist(), keep[ok].tolist()))


def poses(res, scene, frame=None):
    """Positions and rotation matrices of the scene's bodies, (T, B, 3) and
    (T, B, 3, 3), mapped back to the base frame when frame = (R, t)."""
    ids = list(res["body_id"])
    k = [ids.index(b["id"]) for b in scene["bodies"]]
    x = res["body_position"][:, k]
    R = quat_mats(res["body_quaternion"][:, k])
    if frame is not None:
        Rf, tf = np.asarray(frame["R"], float), np.asarray(frame["t"], float)
        x = (x - tf) @ Rf
        R = np.einsum("ji,tbjk,kl->tbil", Rf, R, Rf)
    return x, R


def distance(ra, rb, scene, frame_b=None):
    """D(t) at the output times both runs have: max over bodies of
    |dx| + radius x rotation angle. Returns (times, D)."""
    ka, kb = output_records(ra), output_records(rb)
    common = sorted(set(ka) & set(kb))
    if not common:
        return np.zeros(0), np.zeros(0)
    ia = [ka[c] for c in common]
    ib = [kb[c] for c in common]
    xa, Ra = poses(ra, scene)
    xb, Rb = poses(rb, scene, frame_b)
    xa, Ra, xb, Rb = xa[ia], Ra[ia], xb[ib], Rb[ib]
    rad = np.array([body_radius(b) for b in scene["bodies"]])
    D = np.linalg.norm(xa - xb, axis=2) + rad[None, :] * np.abs(rot_angle(Ra, Rb))
    return ra["time"][ia], D.max(axis=1)


def compare(scene, key, base, var, yard, frame=None, extra_yard=None):
    """Variant against base with the yardstick base vs tight: at every output
    time D(var, base) <= C x max_{s <= t} D(base, tight)(s) + 1e-5 L."""
    L = scene["scales"]["L"]
    tv, Dv = distance(base, var, scene, frame)
    ty, Dy = distance(base, yard, scene)
    if len(tv) == 0:
        return [viol(key, key, "no output time in common with the base")]
    Y = np.zeros_like(Dv)
    if len(ty):
        Yrun = np.maximum.accumulate(Dy)
        Y = np.interp(tv, ty, Yrun, right=Yrun[-1])
        # beyond the yardstick's last common time nothing is known: no bound
        Y[tv > ty[-1]] = np.inf
    if extra_yard is not None:
        te, De = extra_yard
        if len(te):
            Ye = np.interp(tv, te, np.maximum.accumulate(De), right=np.inf)
            Y = np.maximum(Y, Ye)
    allowed = C_YARD * Y + REL_MOTION * L
    ex = Dv / allowed
    k = int(np.argmax(ex))
    if ex[k] > 1.0:
        return [viol(key, key, f"motion differs from the base by {Dv[k]:.4g} m at t = {tv[k]:.6g} s; allowed "
                     f"{allowed[k]:.4g} m (10 x base-vs-tight {Y[k]:.3g} m + 1e-5 L, L = {L:.4g} m)",
                     value=Dv[k], allowed=allowed[k], t=tv[k], ratio=ex[k], max_diff=float(Dv.max()))]
    return []


EVENT_KINDS = ("contact_close", "contact_open", "contact_separate")


def event_counts(res, t_start=0.0):
    """Counts of the contact events (impacts, releases, separations) after
    t_start (>= 0). The modes decided at the start are left out: a touching
    start is classified by the sign of a gap that is a rounding error
    (1e-13 m) in the moved scene, with or without a contact_close event at
    t = 0 for the same motion, or a touch band later (README, invariant g)."""
    c = {}
    for t, k, e in zip(res["event_time"], res["event_kind"], res["event_element"]):
        if k not in EVENT_KINDS or not t > t_start:
            continue
        c[(k, e)] = c.get((k, e), 0) + 1
    return c


def settled_elements(res):
    """The elements with a contact_settle event."""
    return {e for k, e in zip(res["event_kind"], res["event_element"]) if k == "contact_settle"}


def compare_events(key, base, var, tight, elem_map=None, perturbed=None, t_start=0.0):
    """The same events: for every (kind, element) whose count base and tight
    agree on (and the base perturbed by the variant's rounding, when given:
    a count that the rounding alone changes is the scene's sensitivity, not
    the variant's defect), the variant must have that count too; within
    10 % (at least 2) for an element that settles after accumulating
    bounces in the base or the variant: its last bounces are microscopic
    (flights of 3e-7 s shrinking by 0.9 a bounce), and how many come before
    the settling rule holds the contact moves with the method and the
    rounding (a ball against a wall: 45 closes on CVODE, 48 on IDA, the
    motion the same). t_start: the events up to then are the start's
    (event_counts)."""
    cb, ct, cv = event_counts(base, t_start), event_counts(tight, t_start), event_counts(var, t_start)
    cp = event_counts(perturbed, t_start) if perturbed is not None else None
    settling = settled_elements(base) | settled_elements(var)
    diffs = []
    for ke in sorted(set(cb) | set(ct) | set(cv)):
        if cp is not None and cp.get(ke, 0) != cb.get(ke, 0):
            continue
        nb, nv = cb.get(ke, 0), cv.get(ke, 0)
        if ke[1] in settling and abs(nv - nb) <= max(2, 0.1 * nb):
            continue
        if nb == ct.get(ke, 0) and nv != nb:
            diffs.append(f"{ke[0]} {ke[1]}: {nv} vs {nb}")
    if diffs:
        return [viol(key, key, "event counts differ from the base (where base and tight agree): " +
                     "; ".join(diffs[:6]), n=len(diffs))]
    return []


def backend_converges(scene, var, var_tight, tight):
    """h: a backend run beyond the yardstick converges when refined: at
    rtol 1e-10 it lies nearer the base backend's rtol 1e-10 run than half
    of its rtol 1e-8 run does (the largest distances over the run). In a
    chaotic scene the two methods' errors at rtol 1e-8 differ by their
    error constants and both grow alike (a box dropped on a fixed box:
    IDA 15 x CVODE's distance from the tight run at 0.32 s, 5 x better at
    rtol 1e-10); a backend that solves another problem does not come
    nearer."""
    _, d8 = distance(var, tight, scene)
    _, d10 = distance(var_tight, tight, scene)
    return len(d8) > 0 and len(d10) > 0 and d10.max() <= 0.5 * d8.max()


def divergence_time(t, D, thr):
    k = np.nonzero(D > thr)[0]
    return t[k[0]] if len(k) else math.inf


def check_rtol(scene, base, loose, tight, perturbed=None, floored=None, finer=None, tighter=None):
    """i: refining rtol converges: D(base, tight) < D(loose, tight) when the
    scene is not chaotic; when it is, base must not diverge from tight
    earlier than loose does. perturbed: a function giving the run of the
    base scene perturbed by the rounding of its coordinates (or None),
    called only for a run that fails the test: a D(base, tight) within
    10 x D(base, perturbed) is the scene's sensitivity, not a failure to
    converge (a box landing flat: which corner lands first is decided by
    rounding, and 1e-12 m of it moved the fifth bounce by 2.4e-5 m);
    likewise a divergence of base and tight no earlier than that of the
    perturbed base (a box sliding down an incline, resting start: the base
    perturbed by 1e-17 m departed at 0.082 s, before rtol 1e-8 did).
    floored: a function giving the run of the base scene with its position
    tolerance at twice the floor the engine raised it to (the results
    file's atol_position_floor), or None, called only for a run that fails
    the tests above: where the position tolerance sits at the coordinates'
    rounding for rtol 1e-8 and 1e-10 alike, refining rtol does not refine
    the positions, and the floor sets their accuracy (a cradle of five
    balls, floor 7.4e-16 m: rtol 1e-8 was 1.9e-7 m from rtol 1e-10, rtol
    1e-6 1.4e-7 m, and the base with the floor doubled 4.6e-8 m from the
    base); a D(base, tight) within 10 x D(base, floored) is that floor's
    effect, as is a divergence no earlier than the floored run's (a given
    Atol_pos is absolute, as the derived one).
    finer: a function giving the run at rtol 1e-9 (or None), called only
    for a run whose distances are out of order (below the divergence
    threshold): when that run is nearer rtol 1e-10 than half of both
    rtol 1e-6 and 1e-8 are, the errors converge from there, and the order
    of the two coarser ones was luck (a sphere sliding on a belt, its
    normal contact ringing undamped: its stick came at the ringing's phase,
    lost by 0.8 rad after 216 periods at rtol 1e-6 to 1e-8 alike, and rtol
    1e-6 happened to land nearer; 5.5e-7, 1.4e-6, then 2.2e-7, 5e-8, 1e-8
    m at rtol 1e-9, 1e-11, 1e-12). An error that does not shrink with rtol
    (a floor of the engine's) fails it.
    tighter: a function giving the run at rtol 1e-12 (or None), called only
    for a chaotic run that departs early: when rtol 1e-10 itself departs
    from it no later than rtol 1e-8 departs from rtol 1e-10, the reference
    is no better than the base from there on, and the order of the
    departures says nothing of rtol (a box dropped tilted, its positions at
    the coordinates' rounding: every run from rtol 1e-6 to 1e-12 departed
    from every other between 0.340 and 0.345 s)."""
    L = scene["scales"]["L"]
    t6, d6 = distance(loose, tight, scene)
    t8, d8 = distance(base, tight, scene)
    if len(t6) == 0 or len(t8) == 0:
        return []
    thr = DIV_REL * L
    dt = float(base["attrs"]["dt_out"])

    def yardstick(run):
        """A function giving distance(base, run()) or None (run None or
        giving None: no such yardstick)."""
        def dist():
            ry = run() if run is not None else None
            if ry is None:
                return None
            ty, dy = distance(base, ry, scene)
            return (ty, dy) if len(dy) else None
        return dist

    rounding, floor = yardstick(perturbed), yardstick(floored)

    if d6.max() < thr:
        m6, m8 = d6.max(), d8.max()
        if m8 <= max(m6, RTOL_FLOOR_REL * L):
            return []
        for yard in (rounding, floor):
            rd = yard()
            if rd is not None and m8 <= 10.0 * rd[1].max():
                return []
        rf = finer() if finer is not None else None
        m9 = None
        if rf is not None:
            t9, d9 = distance(rf, tight, scene)
            m9 = d9.max() if len(d9) else None
            if m9 is not None and m9 <= 0.5 * min(m6, m8):
                return []
        return [viol("i_rtol", "i_rtol", f"rtol 1e-8 is farther from rtol 1e-10 ({m8:.4g} m) than rtol 1e-6 is "
                     f"({m6:.4g} m)" + (f"; rtol 1e-9 {m9:.4g} m" if m9 is not None else ""), d8=m8, d6=m6)]
    td6, td8 = divergence_time(t6, d6, thr), divergence_time(t8, d8, thr)
    if td8 >= td6 - 1.5 * dt:
        return []
    for yard in (rounding, floor):
        rd = yard()
        if rd is not None and divergence_time(rd[0], rd[1], thr) <= td8 + 1.5 * dt:
            return []
    rt = tighter() if tighter is not None else None
    td10 = None
    if rt is not None:
        t10, d10 = distance(tight, rt, scene)
        td10 = divergence_time(t10, d10, thr) if len(d10) else None
        if td10 is not None and td10 <= td8 + 1.5 * dt:
            return []
    return [viol("i_rtol", "i_rtol", f"rtol 1e-8 departs from rtol 1e-10 by 1e-3 L at t = {td8:.6g} s, earlier than "
                 f"rtol 1e-6 does (t = {td6:.6g} s)" +
                 (f"; rtol 1e-10 departs from rtol 1e-12 at t = {td10:.6g} s" if td10 is not None else ""),
                 t8=td8, t6=td6)]
