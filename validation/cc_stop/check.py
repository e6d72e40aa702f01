"""Contact coupling (/COUPLING/CONTACT) stopping a body: a 2 kg plate,
0.2 m square, its bottom meshed as 2 x 2 quadrilaterals, falls flat at
V = 1 m/s (no gravity) towards a fixed plane. The effective range is
d0 = 10 mm; k1 and k2 come from the card's estimator (Iest 1) for the
minimum distance d_min = 2 mm, the contact area A = 0.04 m^2 (the plate's)
and the damping factor zeta.

Every face is at the same distance d, so the plate obeys
  m d'' = -A k1 (d - d0) - A k2 d'    while d < d0 and the force is positive.
References (closed forms, README.md), w = sqrt(A k1 / m):
  zeta = 0: d(t) = d0 - (d0 - d_min) sin(w (t - t_e)), t_e = (z0 - d0)/V;
    the plate stops exactly at d_min at t_e + tau, tau = (pi/2)/w (the
    estimator's stopping time), and leaves d0 at t_e + 2 tau with speed V;
  zeta = 0.2: x = d0 - d = (V/w_d) e^(-zeta w s) sin(w_d s), w_d = w sqrt(1 - zeta^2),
    s = t - t_e; it stops before d_min, at x_max = x(s*), tan(w_d s*) = w_d/(zeta w);
the energy ledger stays constant.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from ccplate import plate  # noqa: E402
from deck import Deck, line  # noqa: E402

M, SIDE, V, D0, DMIN, Z0 = 2.0, 0.2, 1.0, 0.01, 0.002, 0.02
A = SIDE * SIDE
K1 = M * V * V / (A * (D0 - DMIN) ** 2)
W = math.sqrt(A * K1 / M)
TAU = 0.5 * math.pi / W
TE = (Z0 - D0) / V
DT = TAU / 200


M2 = 6.0   # body-body: a free slab carrying the plane
MRED = M * M2 / (M + M2)


def deck(zeta, body_body=False, meshed=False):
    d = Deck(f"contact coupling stops a plate: zeta = {zeta}" + (", on a free slab" if body_body else "")
             + (" (meshed top)" if meshed else ""))
    plate(d, M, SIDE, Z0)
    if body_body and meshed:
        # the slab's top z = 0 as a segment surface: 3 x 3 squares of 0.2 m,
        # each split into two triangles, on the slab's nodes
        xs = [-0.3, -0.1, 0.1, 0.3]
        top = [(100 + 4 * i + j, xs[i], xs[j], 0.0) for i in range(4) for j in range(4)]
        d.nodes([(2, 0.0, 0.0, -0.05)] + top)
        d.grnod(4, [p[0] for p in top], title="slab top nodes")
        d.grnod(3, [2], title="slab node")
        d.rbody(2, 2, M2, [0.1, 0.1, 0.1], grnod=4, title="slab")
        segs = []
        for i in range(3):
            for j in range(3):
                a, b, c, e = 100 + 4 * i + j, 100 + 4 * (i + 1) + j, 100 + 4 * (i + 1) + j + 1, 100 + 4 * i + j + 1
                segs.append(line(("i", len(segs) + 1), ("i", a), ("i", b), ("i", c)))
                segs.append(line(("i", len(segs) + 1), ("i", a), ("i", c), ("i", e)))
        d.add("/SURF/SEG/2", *segs, title="slab top: 18 triangles")
        d.inivel(1, (0.0, 0.0, -V * M2 / (M + M2)), 2)
        d.inivel(2, (0.0, 0.0, V * M / (M + M2)), 3)
    elif body_body:
        # the slab: a body of mass M2 whose top is the plane z = 0, moving
        # up at V M/(M + M2) while the plate falls at V M2/(M + M2) (no net
        # momentum): the approach speed is V
        d.nodes([(2, 0.0, 0.0, -0.05)])
        d.grnod(3, [2], title="slab node")
        d.rbody(2, 2, M2, [0.1, 0.1, 0.1], title="slab")
        d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), body=2, title="slab top")
        d.inivel(1, (0.0, 0.0, -V * M2 / (M + M2)), 2)
        d.inivel(2, (0.0, 0.0, V * M / (M + M2)), 3)
    else:
        d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
        d.inivel(1, (0.0, 0.0, -V), 2)
    d.contact_coupling(1, 5, 2, D0, iest=1, vimp=V, dmin=DMIN, zeta=zeta, area=A, title="plate - floor, estimated")
    d.run(TE + 3 * TAU, DT)
    return d


K1S = 1.0e5   # the static plate's k1 [N/m^3]


def deck_static():
    """The plate resting on the contact coupling under gravity, only its z
    free (/BCS 110 111), 1 mm inside the range at t = 0, for the static
    analysis: A k1 (d0 - d) = m g."""
    d = Deck("contact coupling carries a plate at rest: static analysis")
    plate(d, M, SIDE, D0 - 1e-3)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.bcs(1, 2, "110 111", title="plate: z free only")
    d.grav(1, "Z", -9.81)
    d.contact_coupling(1, 5, 2, D0, k1=K1S, k2=0.0, title="plate - floor")
    d.run(1.0, 0.5)
    return d


def closed(zeta, s):
    """x = d0 - d during the contact (s = t - t_e)."""
    wd = W * math.sqrt(1 - zeta * zeta)
    return V / wd * np.exp(-zeta * W * s) * np.sin(wd * s)


def main():
    # undamped: the trajectory, the stop at d_min at tau, the exit
    r = rcval.Result(rcval.run(deck(0.0)))
    te = r.events("cpl_contact_enter")
    tl = r.events("cpl_contact_leave")
    ok = len(te) == 1 and len(tl) == 1
    rcval.check("cc_stop.events", ok and abs(te[0] - TE) < 1e-9 and abs(tl[0] - (TE + 2 * TAU)) < 1e-6 * TAU,
                f"enters d0 at {te[0] if len(te) else float('nan'):.12f} s (closed form {TE:.12f}), leaves at "
                f"{tl[0] if len(tl) else float('nan'):.12f} s (t_e + 2 tau = {TE + 2 * TAU:.12f})")
    z, vz = r.pos[:, 0, 2], r.vel[:, 0, 2]
    inside = (r.t > TE) & (r.t < TE + 2 * TAU)
    err = np.max(np.abs((D0 - z[inside]) - closed(0.0, r.t[inside] - TE))) / (D0 - DMIN)
    rcval.check("cc_stop.trajectory", err < 1e-6,
                f"d(t) inside the range against d0 - (d0 - d_min) sin(w (t - t_e)) at {inside.sum()} records: "
                f"max error {err:.2e} of d0 - d_min (< 1e-6)")
    # the stop: where v_z changes sign, the cubic Hermite interpolant between the records
    k = np.where((vz[:-1] < 0) & (vz[1:] >= 0))[0][0]
    h = r.t[k + 1] - r.t[k]
    # root of the Hermite velocity (derivative of the position interpolant), by bisection
    def herm(tt):
        s = (tt - r.t[k]) / h
        h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
        return h00 * z[k] + h10 * h * vz[k] + h01 * z[k + 1] + h11 * h * vz[k + 1]
    ts = np.linspace(r.t[k], r.t[k + 1], 20001)
    zs = herm(ts)
    zmin, tmin = zs.min(), ts[np.argmin(zs)]
    rcval.check("cc_stop.d_min", abs(zmin - DMIN) < 1e-6 * DMIN,
                f"minimum distance {zmin:.12f} m (estimator's d_min {DMIN} m), relative error {abs(zmin - DMIN) / DMIN:.2e} (< 1e-6)")
    rcval.check("cc_stop.tau", abs((tmin - TE) - TAU) < 1e-4 * TAU,
                f"stopping time {tmin - TE:.9f} s against tau = (pi/2) sqrt(m/(A k1)) = {TAU:.9f} s "
                f"(relative {abs((tmin - TE) - TAU) / TAU:.2e} < 1e-4, the interpolation's resolution); from the "
                f"events (t_leave - t_enter)/2 = {(tl[0] - te[0]) / 2:.12f} s")
    rcval.check("cc_stop.rebound", abs(vz[-1] - V) < 1e-6 * V, f"exit speed {vz[-1]:.12f} m/s (V = {V})")
    rcval.check_ledger("cc_stop.ledger", r, 1e-6)
    # damped: stops before d_min, at the closed form's maximum
    zeta = 0.2
    r = rcval.Result(rcval.run(deck(zeta)))
    z = r.pos[:, 0, 2]
    te = r.events("cpl_contact_enter")[0]
    wd = W * math.sqrt(1 - zeta * zeta)
    sstar = math.atan(wd / (zeta * W)) / wd
    xmax = closed(zeta, sstar)
    inside = (r.t > te) & (r.t < te + TAU)
    err = np.max(np.abs((D0 - z[inside]) - closed(zeta, r.t[inside] - te))) / xmax
    rcval.check("cc_stop.damped_trajectory", err < 1e-6 and D0 - xmax > DMIN,
                f"zeta = {zeta}: stops at d = {D0 - xmax:.9f} m > d_min = {DMIN} m (closed form); records against "
                f"the damped closed form: max error {err:.2e} of the stopping depth (< 1e-6)")
    rel = r.events("cpl_contact_release")
    rcval.check("cc_stop.damped_release", len(rel) == 1,
                f"the force reaches zero while the plate rebounds (clipped: released at t = "
                f"{rel[0] if len(rel) else float('nan'):.9f} s), then it leaves d0")
    rcval.check_ledger("cc_stop.damped_ledger", r, 1e-6)
    # body-body: the plate against a plane on a free slab, approach speed V;
    # the body-body estimator (m_red = m1 m2/(m1 + m2)) stops the relative
    # motion at d_min after tau = (pi/2) sqrt(m_red/(A k1))
    for meshed in (False, True):
        name = "body_body_meshed" if meshed else "body_body"
        r = rcval.Result(rcval.run(deck(0.0, body_body=True, meshed=meshed)))
        gap = r.pos[:, 0, 2] - r.pos[:, 1, 2] - 0.05
        k1bb = MRED * V * V / (A * (D0 - DMIN) ** 2)
        wbb = math.sqrt(A * k1bb / MRED)
        taubb = 0.5 * math.pi / wbb
        te, tl = r.events("cpl_contact_enter"), r.events("cpl_contact_leave")
        inside = (r.t > te[0]) & (r.t < tl[0])
        err = np.max(np.abs((D0 - gap[inside]) - (D0 - DMIN) * np.sin(wbb * (r.t[inside] - te[0])))) / (D0 - DMIN)
        rcval.check(f"cc_stop.{name}", err < 1e-6 and abs((tl[0] - te[0]) / 2 - taubb) < 1e-6 * taubb,
                    f"plate on a free 6 kg slab ({'its top a segment surface of 18 triangles' if meshed else 'a plane'}): "
                    f"gap against d0 - (d0 - d_min) sin(w t), w = sqrt(A k1/m_red), m_red = {MRED} kg: max error "
                    f"{err:.2e} of d0 - d_min (< 1e-6); (t_leave - t_enter)/2 = {(tl[0] - te[0]) / 2:.12f} s, "
                    f"tau = {taubb:.12f} s")
        rcval.check_ledger(f"cc_stop.{name}_ledger", r, 1e-6)
    # the static analysis (--method static, in every mode): the plate rests
    # where the faces' force A k1 (d0 - d) carries its weight
    saved = rcval.METHOD
    rcval.METHOD = "static"
    r = rcval.Result(rcval.run(deck_static(), name="static"))
    rcval.METHOD = saved
    dref = D0 - M * 9.81 / (A * K1S)
    err = float(np.abs(r.pos[:, 0, 2] - dref).max()) / (D0 - dref)
    rcval.check("cc_stop.static", err < 1e-9,
                f"static analysis: the plate at d = {r.pos[-1, 0, 2]:.12f} m against d0 - m g / (A k1) = {dref:.12f} m "
                f"at {len(r.t)} records: max error {err:.2e} of the sink (< 1e-9)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.0))
