"""Tstart / Tstop: a sphere passes through a plane while the interface is
inactive and is pushed back when it becomes active; a variant switches the
interface off during the contact.

Reference (README.md): free flight before Tstart; from Tstart the linear
spring-dashpot with an initial penetration P0 (closed form of the damped
oscillator, force clipped at zero), then force-free until P = 0; after Tstop
constant velocity.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, ZETA, V0, GAP0 = 1.0, 0.05, 1.0e5, 0.1, 1.0, 0.002
C = 2.0 * ZETA * math.sqrt(K * M)
TSTART = 0.005                    # the sphere is then P0 = V0 TSTART - GAP0 = 3 mm deep
P0 = V0 * TSTART - GAP0
WN = math.sqrt(K / M)
WD = WN * math.sqrt(1 - ZETA**2)
TOL = 1e-6


def p_ref(tau):
    """Penetration tau after Tstart: m p'' + c p' + k p = 0, p(0) = P0, p'(0) = V0."""
    a, b = P0, (V0 + ZETA * WN * P0) / WD
    return math.exp(-ZETA * WN * tau) * (a * math.cos(WD * tau) + b * math.sin(WD * tau))


def v_ref(tau):
    """dp/dt (approach rate; the body's z-velocity is its opposite)."""
    a, b = P0, (V0 + ZETA * WN * P0) / WD
    e = math.exp(-ZETA * WN * tau)
    return e * ((-ZETA * WN * a + WD * b) * math.cos(WD * tau) + (-ZETA * WN * b - WD * a) * math.sin(WD * tau))


def reference():
    """Release (k p + c p' = 0), exit speed and separation (p = 0), times after Tstart."""
    f = lambda tau: K * p_ref(tau) + C * v_ref(tau)
    # first zero of the total force after the peak: bracket by scanning
    taus = np.linspace(0.0, 2 * math.pi / WD, 2001)
    vals = [f(t) for t in taus]
    k = next(i for i in range(1, len(taus)) if vals[i] < 0 <= vals[i - 1])
    tr = brentq(f, taus[k - 1], taus[k], xtol=1e-16, rtol=1e-15)
    vout, pr = -v_ref(tr), p_ref(tr)
    return dict(t_release=tr, vout=vout, p_release=pr, t_sep=tr + pr / vout)


TSTOP = TSTART + 0.5 * reference()["t_release"]


def deck(tstop=None):
    d = Deck("Tstart / Tstop" if tstop else "Tstart: pass through, then pushed back")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e5 N/m")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, visc=C, tstart=TSTART, tstop=tstop, title="spring-dashpot, active from Tstart")
    # activated 3 mm deep, the contact releases its elastic energy k P0^2 / 2
    # (0.45 J): energy created by the deck's design, which the physics
    # checks report (docs/theory.md 13); the run goes on (On_viol 2)
    d.run(0.02, 2e-4, on_viol=2)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    ref = reference()
    r = rcval.Result(rcval.run_case())

    # the physics checks report the energy the activation creates: the
    # mechanical energy jumps by k P0^2 / 2 at Tstart
    v = []
    with Dataset(r.path) as nc:
        if len(nc.dimensions["violation"]):
            v = list(zip(nc["violation_check"][:], nc["violation_time"][:], nc["violation_value"][:]))
    e_created = 0.5 * K * P0 ** 2
    ok = len(v) >= 1 and v[0][0] == "mechanical_energy" and abs(v[0][1] - TSTART) < 1e-9 and \
        abs(v[0][2] - e_created) < 1e-3 * e_created
    rcval.check("t6_tstart_tstop.energy_created_reported", ok,
                f"violations {[(c, float(t), float(x)) for c, t, x in v]}: the first mechanical_energy at Tstart = "
                f"{TSTART:g} s, {e_created:.6g} J created (k P0^2 / 2)")

    # before Tstart: free flight through the plane
    pre = np.where(r.t < TSTART)[0]
    dv = np.max(np.abs(r.vel[pre, 0, 2] + V0))
    dz = np.max(np.abs(r.pos[pre, 0, 2] - (R + GAP0 - V0 * r.t[pre])))
    deepest = np.max(r.pen[pre, 0])
    ok = dv < 1e-12 and dz < 1e-12 and np.all(r.fn[pre, 0] == 0.0) and deepest > 0.5 * P0 \
        and len(r.events("contact_close")) == 0 and r.ev_kind[0] == "inter_start"
    rcval.check("t6_tstart_tstop.inactive_pass_through", ok,
                f"{len(pre)} records before Tstart: velocity -v0 within {dv:.1e} m/s, position within {dz:.1e} m, "
                f"force 0, penetration up to {1e3 * deepest:.4f} mm past the plane; first event {r.ev_kind[0]} "
                f"(no contact_close while inactive)")

    t_start = r.events("inter_start")
    ok = len(t_start) == 1 and abs(t_start[0] - TSTART) < 1e-9
    rcval.check("t6_tstart_tstop.start_time", ok,
                f"inter_start at {t_start[0]:.15f} s, Tstart {TSTART:.15f} s, |diff| {abs(t_start[0] - TSTART):.1e} s (< 1e-9)")
    i = r.state_at(t_start[0])
    e = max(rcval.rel(r.pen[i, 0], P0), rcval.rel(r.fn[i, 0], K * P0 + C * V0))
    rcval.check("t6_tstart_tstop.start_state", e < TOL,
                f"at inter_start P = {r.pen[i, 0]:.12e} m (P0 = {P0:.12e}), F = {r.fn[i, 0]:.9f} N "
                f"(k P0 + c v0 = {K * P0 + C * V0:.9f}); max rel. error {e:.2e} (< {TOL:g})")

    # pushed back: damped oscillator from (P0, v0), release at zero force, flight to P = 0
    t_rel, t_sep = r.events("contact_open"), r.events("contact_separate")
    ok = len(t_rel) == 1 and len(t_sep) == 1
    if ok:
        v_out = r.vel[r.state_at(t_sep[0]), 0, 2]
        errs = [abs(t_rel[0] - TSTART - ref["t_release"]) / ref["t_release"],
                abs(t_sep[0] - TSTART - ref["t_sep"]) / ref["t_sep"], rcval.rel(v_out, ref["vout"]),
                rcval.rel(r.vel[-1, 0, 2], ref["vout"])]
        ok = max(errs) < TOL
    rcval.check("t6_tstart_tstop.pushed_back", ok,
                (f"release (contact_open) {1e3 * (t_rel[0] - TSTART):.9f} ms after Tstart, closed form "
                 f"{1e3 * ref['t_release']:.9f} ms; separation {1e3 * (t_sep[0] - TSTART):.9f} ms, closed form "
                 f"{1e3 * ref['t_sep']:.9f} ms; exit speed {v_out:.10f} m/s, closed form {ref['vout']:.10f} m/s; "
                 f"max rel. error {max(errs):.2e} (< {TOL:g})") if len(t_rel) == 1 and len(t_sep) == 1 else
                "events: " + ", ".join(r.ev_kind))
    sel = np.where((r.t >= TSTART) & (r.t <= t_rel[0]))[0]
    dev = max(max(abs(r.pen[j, 0] - p_ref(r.t[j] - TSTART)) for j in sel) / P0,
              max(abs(-r.vel[j, 0, 2] - v_ref(r.t[j] - TSTART)) for j in sel) / V0)
    rcval.check("t6_tstart_tstop.trajectory", dev < TOL,
                f"{len(sel)} records from Tstart to the release against the closed form: max |dP| / P0, |dv| / v0 = {dev:.2e} (< {TOL:g})")

    # variant: switched off at Tstop during the contact
    rs = rcval.Result(rcval.run(deck(TSTOP)))
    t_stop = rs.events("inter_stop")
    ok = len(t_stop) == 1 and abs(t_stop[0] - TSTOP) < 1e-9 and rs.ev_kind[-1] == "inter_stop"
    rcval.check("t6_tstart_tstop.stop_time", ok,
                f"inter_stop at {t_stop[0]:.15f} s, Tstop {TSTOP:.15f} s, |diff| {abs(t_stop[0] - TSTOP):.1e} s (< 1e-9); "
                "events " + ", ".join(rs.ev_kind))
    j = rs.state_at(t_stop[0])
    vstop = -v_ref(TSTOP - TSTART)
    post = np.where(rs.t > TSTOP)[0]
    dv = np.max(np.abs(rs.vel[post, 0, 2] - rs.vel[j, 0, 2]))
    e = rcval.rel(rs.vel[j, 0, 2], vstop)
    ok = e < TOL and dv < 1e-12 and np.all(rs.fn[post, 0] == 0.0) and np.all(rs.fn[j, 0] == 0.0) and len(post) > 10
    rcval.check("t6_tstart_tstop.stopped", ok,
                f"velocity at Tstop {rs.vel[j, 0, 2]:.10f} m/s, closed form {vstop:.10f} m/s (rel. error {e:.2e} < {TOL:g}); "
                f"force 0 from the inter_stop record on; velocity constant afterwards within {dv:.1e} m/s over {len(post)} records "
                f"(then moving away at P = {1e3 * rs.pen[-1, 0]:.4f} mm at the end)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
