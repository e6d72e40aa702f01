"""Viscous (Iform 1) against incremental (Iform 2) friction on the same sliding case.

A sphere with locked rotations (a "block", m = 1 kg, R = 0.05 m) rests at its
static penetration on the fixed floor z = 0, under gravity, with Coulomb
friction mu = 0.3 from a /FRICTION card (part-pair group block/floor), and
slides to a stop, run with each formulation:
  Iform 2: stick spring K_t with its critical damper c_t = 2 sqrt(K_t m),
           then F = mu F_n; stops (fric_stick) at rest;
  Iform 1: F = -C v up to the limit (C = sqrt(2 VISF K m) = 1414 N s/m); it
           never sticks: below v* = mu m g / C it creeps to a stop
           exponentially, time constant m / C.
Two launches (README.md): at 1 m/s from t = 0 (exact closed forms), and by a
pusher (a plane on a 1e12 kg body at 0.5 m/s, undamped contact 1e6 N/m, no
friction, active until 0.02 s) that closes a 1 mm gap and leaves the block at
about 1 m/s (references: independent solve_ivp of the 1-D push and slide for
each formulation and for rigid Coulomb friction). The stopping points agree
with their own references (1e-8 m) and with each other within the
regularisation.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, MU = 1.0, 0.05, 1.0e6, 9.81, 0.3
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # floor: normal damping ratio 0.5
KP, VP, GAP = 1.0e6, 0.5, 1.0e-3      # pusher contact stiffness [N/m], speed [m/s], initial gap [m]
TSTOP = 0.02                         # pusher interface active until [s]
KT = K                               # Iform 2 stick stiffness (the floor load-curve slope)
VISF = 1.0
C = math.sqrt(2.0 * VISF * K * M)    # Iform 1 adhesion coefficient (the floor is fixed: m_red = m)
L = MU * M * G                       # friction limit
VSTAR = L / C                        # Iform 1 unsaturates below this speed
BAND = stick.BAND                    # slip band RC_SLIP_BAND (src/model.h)
TEND = 0.4


def reference(form, kt=KT, c=C, rtol=1e-12):
    """1-D block: x'' = (F_push + F_fric)/m, F_push = KP p for p = VP t - GAP - x > 0.
    form 'rigid': stuck (x = 0) until KP p = L, then F_fric = -L while v > 0;
    form 2: critically damped stick spring (F_fric = -(f + c_t v), f' = KT v, c_t = 2 sqrt(KT m), the
            floor fixed) until |f + c_t v| = (1 + band) L, then -L, stop at v = 0;
    form 1: F_fric = -C v until C v = L, -L while C v > L, then -C v (creep).
    Returns a dict of the key times and states and a dense evaluator of (x, v)."""
    segs = []

    def run(rhs, t0, y0, events, t1=10.0):
        for e in events:
            e.terminal = True
        s = solve_ivp(rhs, (t0, t1), y0, method="DOP853", rtol=rtol, atol=1e-15, dense_output=True, events=events)
        segs.append((t0, s.t[-1], s.sol))
        k = [j for j in range(len(events)) if len(s.t_events[j])]
        return (s.t_events[k[0]][0], s.y_events[k[0]][0], k[0]) if k else (s.t[-1], s.y[:, -1], -1)

    def push(t, x):
        p = VP * t - GAP - x
        return KP * p if p > 0 else 0.0

    def free(t, y):
        return [y[1], -L / M]

    def p_open(t, y):
        return VP * t - GAP - y[0]
    p_open.direction = -1
    out = {}
    tc = GAP / VP  # contact closes; block at rest
    if form == "rigid":
        t1 = tc + L / (KP * VP)  # KP p = L with x = 0
        def rhs(t, y):
            return [y[1], (push(t, y[0]) - L) / M]
        t, y, k = run(rhs, t1, [0.0, 0.0], [p_open])
        out["open"] = (t, y)
        ev = (lambda tt, yy: yy[1])
        ev.direction = -1
        t, y, k = run(free, t, y, [ev])
        out["stop"] = (t, y[0])
    elif form == 2:
        ct = stick.ct(kt, M)

        def rhs_stick(t, y):
            return [y[1], (push(t, y[0]) - y[2] - ct * y[1]) / M, kt * y[1]]
        ev = (lambda tt, yy: abs(yy[2] + ct * yy[1]) - (1 + BAND) * L)
        ev.direction = 1
        t, y, k = run(rhs_stick, tc, [0.0, 0.0, 0.0], [ev])
        out["slip"] = (t, y)

        def rhs(t, y):
            return [y[1], (push(t, y[0]) - L) / M]
        t, y, k = run(rhs, t, y[:2], [p_open])
        out["open"] = (t, y)
        ev = (lambda tt, yy: yy[1])
        ev.direction = -1
        t, y, k = run(free, t, y, [ev])
        out["stop"] = (t, y[0])
    else:
        def rhs_visc(t, y):
            return [y[1], (push(t, y[0]) - c * y[1]) / M]
        ev = (lambda tt, yy: c * yy[1] - L)
        ev.direction = 1
        t, y, k = run(rhs_visc, tc, [0.0, 0.0], [ev])
        out["saturate"] = t

        def rhs(t, y):
            return [y[1], (push(t, y[0]) - L) / M]
        t, y, k = run(rhs, t, y, [p_open])
        out["open"] = (t, y)
        ev = (lambda tt, yy: c * yy[1] - L)
        ev.direction = -1
        t, y, k = run(free, t, y, [ev])
        out["unsaturate"] = (t, y)
        # creep: m v' = -C v, closed form
        out["stop"] = (math.inf, y[0] + M * y[1] / c)
    out["segs"] = segs
    return out


def deck(iform, stiff=None, visf=VISF, rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, tend=TEND, dtout=2e-4,
         launched=False):
    """launched: no pusher, the block starts at V0 = 2 VP (sliding from t = 0)."""
    z0 = R - M * G / K  # static penetration m g / k
    d = Deck(f"block {'launched' if launched else 'launched by a pusher'}, slides to a stop: /FRICTION Coulomb, "
             f"Iform {iform}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, 0.0, 0.0, z0), (2, -R - GAP - 1.0, 0.0, z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.rbody(2, 2, 1.0e12, [1.0e12] * 3, grnod=2, title="pusher 1e12 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.plane(3, (-R - GAP, 0.0, 0.0), (-R - GAP + 1.0, 0.0, 0.0), body=2, title="pusher face, 1 mm behind the block")
    d.grnod(1, [1], title="block")
    d.grnod(2, [2], title="pusher")
    d.bcs(1, 1, "000 111", title="block: no rotation")
    d.bcs(2, 2, "011 111", title="pusher moves along x only")
    if launched:
        d.inivel(1, (2 * VP, 0.0, 0.0), 1)
    else:
        d.inivel(1, (VP, 0.0, 0.0), 2)
    d.grav(1, "Z", -G, 1)  # on the block only
    d.type6(1, 1, 2, 1, visc=VISC, stiff=stiff, title="block on the floor" + (f", Stiff {stiff:g}" if stiff else ""))
    if not launched:
        d.type6(2, 1, 3, 1, tstop=TSTOP, title="pusher on the block (undamped, no friction, until 0.02 s)")
    d.part(1, 1, title="block")
    d.part(2, 0, [2], title="floor")
    d.friction(1, ifric=0, iform=iform, fric=0.9, pairs=[dict(part1=1, part2=2, sets=[((), MU, visf)])],
               title=f"Coulomb 0.3 on block/floor only (defaults 0.9 unused), Iform {iform}")
    d.run(tend, dtout)
    d.solver(rtol=rtol, atol_pos=atol_pos, atol_vel=atol_vel, atol_energy=atol_vel)
    return d


def compare(name, here, stiff, visf, tol_same):
    """Both formulations with stick stiffness K_t (Stiff, or the load-curve
    slope) and VISF, against their references and against each other."""
    kt = stiff if stiff else KT
    c = math.sqrt(2.0 * visf * K * M)
    vstar = L / c
    ref = {"rigid": reference("rigid"), 1: reference(1, c=c), 2: reference(2, kt=kt)}
    xr = ref["rigid"]["stop"][1]
    print(f"{name}: K_t = {kt:g} N/m, VISF = {visf:g} (C = {c:.6g} N s/m); launch speed (pusher gone) rigid "
          f"{ref['rigid']['open'][1][1]:.9f}, Iform 1 {ref[1]['open'][1][1]:.9f}, Iform 2 {ref[2]['open'][1][1]:.9f} m/s; "
          f"stops rigid {xr:.9f}, Iform 1 {ref[1]['stop'][1]:.9f}, Iform 2 {ref[2]['stop'][1]:.9f} m")

    # Iform 2: stops at rest (fric_stick) where its reference does
    r2 = rcval.Result(rcval.run_case() if stiff is None and here
                      else rcval.run(deck(2, stiff=stiff, visf=visf)))
    ts = r2.events("fric_stick")
    t2, x2 = ts[0], r2.pos[r2.state_at(ts[0]), 0, 0]
    tr, xr2 = ref[2]["stop"]
    e = max(abs(t2 - tr), abs(x2 - xr2))
    slip = r2.events("fric_slip")[0]
    rcval.check(f"frc_iform_compare.{name}.iform2_stop", e < 1e-8 and abs(slip - ref[2]["slip"][0]) < 1e-9,
                f"fric_slip at {slip:.9f} s (reference {ref[2]['slip'][0]:.9f}); first fric_stick at {t2:.9f} s, "
                f"x = {x2:.9f} m; reference {tr:.9f} s, {xr2:.9f} m; max error {e:.1e} (< 1e-8 s, m)")
    # Iform 1: saturates, unsaturates at v*, creeps; never sticks
    r1 = rcval.Result(rcval.run(deck(1, stiff=stiff, visf=visf)))
    kinds = [k for k, el in zip(r1.ev_kind, r1.ev_elem) if el == "/INTER/TYPE6/1"]
    tsat, tuns = r1.events("fric_saturate"), r1.events("fric_unsaturate")
    ok = kinds == ["fric_saturate", "fric_unsaturate"] and abs(tsat[0] - ref[1]["saturate"]) < 1e-9 \
        and abs(tuns[0] - ref[1]["unsaturate"][0]) < 1e-8
    rcval.check(f"frc_iform_compare.{name}.iform1_events", ok,
                f"floor events {kinds} (expected saturate, unsaturate; no stick); saturate at {tsat[0]:.9f} s "
                f"(reference {ref[1]['saturate']:.9f}), unsaturate at {tuns[0]:.9f} s (reference "
                f"{ref[1]['unsaturate'][0]:.9f}), where v = {r1.vel[r1.state_at(tuns[0]), 0, 0]:.6e} m/s, "
                f"v* = mu m g / C = {vstar:.6e}")
    # creep from the recorded unsaturation (t*, x*, v*): v = v* e^(-C (t - t*)/m)
    iu = r1.state_at(tuns[0])
    tu, xu, vu = tuns[0], r1.pos[iu, 0, 0], r1.vel[iu, 0, 0]
    cr = (r1.t > tu) & (r1.t < tu + 10 * M / c)
    v_ex = vu * np.exp(-c * (r1.t[cr] - tu) / M)
    x_ex = xu + M * (vu - v_ex) / c
    ev = np.max(np.abs(r1.vel[cr, 0, 0] - v_ex))
    ex = np.max(np.abs(r1.pos[cr, 0, 0] - x_ex))
    x1 = r1.pos[-1, 0, 0]
    e = abs(x1 - ref[1]["stop"][1])
    rcval.check(f"frc_iform_compare.{name}.iform1_creep", ev < 1e-8 and ex < 1e-8 and e < 1e-8,
                f"{cr.sum()} records within 10 m/C = {10 * M / c:.2g} s of the unsaturation: v = v* exp(-C (t - t*)/m) "
                f"to {ev:.1e} m/s, x = x* + m (v* - v)/C to {ex:.1e} m (< 1e-8); final x = {x1:.9f} m against the "
                f"reference x* + m v*/C = {ref[1]['stop'][1]:.9f} m, error {e:.1e} m (< 1e-8); final speed "
                f"{r1.vel[-1, 0, 0]:.1e} m/s")
    # the two forms against each other and against rigid Coulomb
    d12, d1r, d2r = abs(x1 - x2) / xr, abs(x1 - xr) / xr, abs(x2 - xr) / xr
    rcval.check(f"frc_iform_compare.{name}.same_stop", max(d12, d1r, d2r) < tol_same,
                f"stopping points: Iform 1 {x1:.9f} m, Iform 2 {x2:.9f} m, rigid Coulomb {xr:.9f} m; "
                f"relative differences 1-2 {d12:.1e}, 1-rigid {d1r:.1e}, 2-rigid {d2r:.1e} (< {tol_same:g}, the "
                f"regularisation; the references predict {abs(ref[1]['stop'][1] - ref[2]['stop'][1]) / xr:.1e}, "
                f"{abs(ref[1]['stop'][1] - xr) / xr:.1e}, {abs(ref[2]['stop'][1] - xr) / xr:.1e})")
    # from its own launch state each slide is the Coulomb slide; Iform 1 adds its creep
    i1 = r1.state_at(r1.contact_ends()[0])
    i2 = r2.state_at(r2.contact_ends()[0])
    s1 = x1 - r1.pos[i1, 0, 0] - r1.vel[i1, 0, 0] ** 2 / (2 * MU * G)
    s2 = x2 - r2.pos[i2, 0, 0] - r2.vel[i2, 0, 0] ** 2 / (2 * MU * G)
    creep = L / (4 * visf * K)
    rcval.check(f"frc_iform_compare.{name}.slide", abs(s1 - creep) < 1e-9 and abs(s2) < 1e-9,
                f"from the pusher's release (x_o, v_o): x_stop - x_o - v_o^2/(2 mu g) = {s1:.4e} m for Iform 1 "
                f"(the creep term mu m g/(4 VISF K) = {creep:.4e} m), {s2:.1e} m for Iform 2 (0); < 1e-9 m")


def launched():
    """Both forms launched at V0 = 1 m/s (sliding from t = 0): the viscous form
    starts at its limit (saturated), the incremental one sticking with a zero
    state, whose stick damper's force c_t V0 = 2000 N exceeds the limit: it
    slips at t = 0 (fric_slide_stop, lib/stick.py). Exact: Iform 2 stops at
    x1 + v1^2/(2 mu g) = V0^2/(2 mu g) (t1 = x1 = 0, v1 = V0), the rigid
    Coulomb point; Iform 1 saturated from t = 0 creeps to
    V0^2/(2 mu g) + L/(4 VISF K)."""
    v0, a = 2 * VP, MU * G
    t1, x1, v1 = stick.launch_onset(KT, M, v0, L)
    x2_ref = x1 + v1**2 / (2 * a)
    x1_ref = v0**2 / (2 * a) + L / (4 * VISF * K)
    r2 = rcval.Result(rcval.run(deck(2, launched=True)))
    ts = r2.events("fric_stick")[0]
    x2 = r2.pos[r2.state_at(ts), 0, 0]
    r1 = rcval.Result(rcval.run(deck(1, launched=True)))
    x1 = r1.pos[-1, 0, 0]
    kinds = list(r1.ev_kind)
    e1, e2 = abs(x1 - x1_ref), abs(x2 - x2_ref)
    rcval.check("frc_iform_compare.launched.exact", e1 < 1e-8 and e2 < 1e-8 and kinds == ["fric_unsaturate"],
                f"launched at {v0:g} m/s: Iform 2 stops (fric_stick) at {x2:.10f} m, exact {x2_ref:.10f} (error {e2:.1e}); "
                f"Iform 1 (events {kinds}: saturated from t = 0) ends at {x1:.10f} m, exact {x1_ref:.10f} "
                f"(error {e1:.1e}); < 1e-8 m")
    xr = v0**2 / (2 * a)
    # each regularisation bounds its distance to the rigid stop: L/(4 VISF K) for
    # Iform 1, L/(2 K_t) for the undamped stick onset of Iform 2 before aa7c6b5 (0 now)
    bound = L / (2 * KT) + L / (4 * VISF * K)
    rcval.check("frc_iform_compare.launched.same_stop", abs(x1 - x2) <= bound,
                f"|x_1 - x_2| = {abs(x1 - x2):.3e} m <= L/(2 K_t) + L/(4 VISF K) = {bound:.3e} m (relative "
                f"{abs(x1 - x2) / xr:.1e}); rigid Coulomb {xr:.10f} m: Iform 1 {x1 - xr:+.3e}, Iform 2 {x2 - xr:+.3e} m")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    launched()
    compare("default", here, None, VISF, 2e-3)
    compare("stiffer", None, 1e8, 100.0, 5e-4)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(2))
