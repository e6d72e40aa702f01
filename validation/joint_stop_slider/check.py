"""Two sliders on /JOINT/PRISMATIC joints run into the joint's stops.

Each slider (mass m) slides along the x axis on a prismatic joint to the
ground, no force along the axis (gravity -z, across the axis, is taken by the
joint). Slider 1 starts at v0 > 0 towards the upper stop Lim_max = a, with a
damped stop (damping ratio zeta); slider 2 starts at -v0 towards the lower
stop Lim_min = -a, undamped. Past the stop the joint coordinate q has the
penetration p and the stop pushes back with F = K p + C p', clipped at zero
(never pulling): m p'' = -K p - C p' from p(0) = 0, p'(0) = v0 until
K p + C p' = 0 (release), then free flight until p = 0 (leave).

References (README.md), closed forms, independent of ricochet's output:
- onset t1 = a / v0 (stop_enter);
- release after t_r = (pi - atan(2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2))) / omega_d
  (stop_release), the velocity there v_r = v0 exp(-zeta omega_n t_r) (cos
  omega_d t_r - zeta omega_n / omega_d sin omega_d t_r) (the slider's speed
  after the stop), the leave time t1 + t_r + p(t_r) / v_r (stop_leave);
- undamped: contact time pi / omega exactly, exit speed v0;
- the peak stop force v0 sqrt(K m) of the undamped stop (joint_stop_force);
- the energy ledger constant; the energy the stops took, m (v0^2 - v_r^2) / 2.

Slider 3 (at v0 into an upper stop a) has the stop's elastic part from a
stiffening curve F_e(p) (/FUNCT, piecewise linear, fct_lim) and damping C3:
its release time, exit speed and leave time against SciPy's solve_ivp
(DOP853, rtol 1e-13) of m p'' = -F_e(p) - C3 p' up to F_e(p) + C3 p' = 0,
the curve interpolated here by numpy (np.interp), then the free flight back.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, V0, A, K, ZETA, G = 2.0, 0.5, 0.05, 2.0e4, 0.1, 9.81
C = 2.0 * ZETA * math.sqrt(K * M)
T_END, DT_OUT = 0.3, 1e-3
TOL_T1 = 1e-9       # onset time, relative
TOL = 1e-6          # contact time, leave time, exit speed, relative
TOL_F = 1e-6        # peak force, relative
TOL_E = 1e-6        # energy ledger, in m v0^2 / 2
# slider 3: a stiffening stop from a curve (p [m], F_e [N]), damping C3
CX = [0.0, 0.002, 0.005, 0.01, 0.03]
CY = [0.0, 10.0, 60.0, 300.0, 3000.0]
C3 = 20.0


def deck():
    d = Deck("two sliders on prismatic joints run into the joint stops")
    d.funct(1, CX, CY, title="stiffening stop force F_e(p)")
    d.nodes([(1, 0.0, 0.0, 0.0), (2, 0.0, 1.0, 0.0), (3, 0.0, 2.0, 0.0)])
    d.rbody(1, 1, M, [0.01, 0.01, 0.01], title="slider 1 (damped upper stop)")
    d.rbody(2, 2, M, [0.01, 0.01, 0.01], title="slider 2 (undamped lower stop)")
    d.rbody(3, 3, M, [0.01, 0.01, 0.01], title="slider 3 (stop force from a curve)")
    d.grnod(1, [1])
    d.grnod(2, [2])
    d.grnod(3, [3])
    d.inivel(3, (V0, 0.0, 0.0), 3)
    d.inivel(1, (V0, 0.0, 0.0), 1)
    d.inivel(2, (-V0, 0.0, 0.0), 2)
    d.grav(1, "Z", -G)
    d.joint(1, "PRISMATIC", 1, 0, (0.0, 0.0, 0.0), axis=(1.0, 0.0, 0.0), lim_max=A, k_lim=K, c_lim=C,
            title="slider 1 along x, upper stop 0.05 m")
    d.joint(2, "PRISMATIC", 2, 0, (0.0, 1.0, 0.0), axis=(1.0, 0.0, 0.0), lim_min=-A, lim_max=1.0, k_lim=K,
            c_lim=0.0, title="slider 2 along x, lower stop -0.05 m")
    d.joint(3, "PRISMATIC", 3, 0, (0.0, 2.0, 0.0), axis=(1.0, 0.0, 0.0), lim_max=A, c_lim=C3, fct_lim=1,
            title="slider 3 along x, upper stop 0.05 m, force from a curve")
    d.run(T_END, DT_OUT)
    return d


def clipped(zeta):
    """Release time t_r, velocity there (as a fraction of v0, signed: the
    rebound is negative) and penetration there (in v0 / omega_n) of
    m p'' = -K p - C p', p(0) = 0, p'(0) = v0, closed form."""
    wn = math.sqrt(K / M)
    wd = wn * math.sqrt(1.0 - zeta * zeta)
    if zeta == 0.0:
        tr = math.pi / wd
    else:
        tr = (math.pi - math.atan(2.0 * zeta * math.sqrt(1.0 - zeta * zeta) / (1.0 - 2.0 * zeta * zeta))) / wd
    ex = math.exp(-zeta * wn * tr)
    v = ex * (math.cos(wd * tr) - zeta * wn / wd * math.sin(wd * tr))
    p = ex * math.sin(wd * tr) / wd
    return tr, v, p


def curve_stop():
    """Slider 3: release time after the onset, velocity there, leave time
    after the onset (solve_ivp of m p'' = -F_e(p) - C3 p')."""
    def fe(p):
        if p <= CX[-1]:
            return float(np.interp(p, CX, CY))
        return CY[-1] + (CY[-1] - CY[-2]) / (CX[-1] - CX[-2]) * (p - CX[-1])

    def rhs(t, s):
        return [s[1], (-fe(s[0]) - C3 * s[1]) / M]

    rel = lambda t, s: fe(s[0]) + C3 * s[1]
    rel.terminal, rel.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 1.0), [0.0, V0], method="DOP853", rtol=1e-13, atol=1e-16, events=rel)
    tr, (pr, vr) = sol.t_events[0][0], sol.y_events[0][0]
    return tr, vr, tr + pr / -vr


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    with Dataset(path) as nc:
        fstop = np.array(nc["joint_stop_force"][:])
    t1 = A / V0
    for j, zeta, name in ((0, ZETA, "slider1_damped"), (1, 0.0, "slider2_undamped")):
        elem = f"/JOINT/PRISMATIC/{j + 1}"
        ev = {k: [t for t, kk, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if kk == k and e == elem]
              for k in ("stop_enter", "stop_release", "stop_leave")}
        # undamped, the force K p vanishes with p: the stop is left at the
        # release (stop_leave, no stop_release)
        want = {"stop_enter": 1, "stop_release": 1 if zeta > 0 else 0, "stop_leave": 1}
        ok = all(len(ev[k]) == n for k, n in want.items())
        rcval.check(f"joint_stop_slider.{name}.events", ok,
                    "events " + ", ".join(f"{k} {len(v)}" for k, v in ev.items()) +
                    " (expected " + ", ".join(f"{n}" for n in want.values()) + ")")
        if not ok:
            continue
        te, tl = ev["stop_enter"][0], ev["stop_leave"][0]
        trl = ev["stop_release"][0] if zeta > 0 else tl
        tr, vr, pr = clipped(zeta)
        vout = -vr * V0
        t_leave = t1 + tr + pr * V0 / vout
        e1 = rcval.rel(te, t1)
        rcval.check(f"joint_stop_slider.{name}.onset", e1 < TOL_T1,
                    f"stop_enter at {te:.12f} s; a / v0 = {t1:.12f} s; rel. error {e1:.2e} (< {TOL_T1:g})")
        e2 = rcval.rel(trl - te, tr)
        rcval.check(f"joint_stop_slider.{name}.contact_time", e2 < TOL,
                    f"stop_release - stop_enter = {1e3 * (trl - te):.9f} ms; closed form {1e3 * tr:.9f} ms"
                    f"{' (pi/omega)' if zeta == 0 else ''}; rel. error {e2:.2e} (< {TOL:g})")
        # the speed after the stop: the free flight after the release
        i = np.where((r.t > tl + 1e-3) & (r.at_event == 0))[0][0]
        v = abs(r.vel[i, j, 0])
        e3 = rcval.rel(v, vout)
        rcval.check(f"joint_stop_slider.{name}.exit_speed", e3 < TOL,
                    f"speed after the stop {v:.10f} m/s; closed form {vout:.10f} m/s (e = {vout / V0:.10f}); "
                    f"rel. error {e3:.2e} (< {TOL:g})")
        e4 = rcval.rel(tl, t_leave)
        rcval.check(f"joint_stop_slider.{name}.leave_time", e4 < TOL,
                    f"stop_leave at {tl:.10f} s; release + p(t_r)/v_r = {t_leave:.10f} s; rel. error {e4:.2e} "
                    f"(< {TOL:g})")
        # the slider's direction after: back from the stop
        sgn = -1.0 if j == 0 else 1.0
        rcval.check(f"joint_stop_slider.{name}.rebound_direction", sgn * r.vel[i, j, 0] > 0,
                    f"velocity after the stop {r.vel[i, j, 0]:+.6f} m/s (away from the stop)")
    # slider 3: the stop force from a curve, against SciPy
    tr3, vr3, tl3 = curve_stop()
    elem = "/JOINT/PRISMATIC/3"
    ev3 = {k: [t for t, kk, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if kk == k and e == elem]
           for k in ("stop_enter", "stop_release", "stop_leave")}
    ok = all(len(v) == 1 for v in ev3.values())
    rcval.check("joint_stop_slider.slider3_curve.events", ok,
                "events " + ", ".join(f"{k} {len(v)}" for k, v in ev3.items()) + " (one each)")
    if ok:
        te = ev3["stop_enter"][0]
        e7 = rcval.rel(ev3["stop_release"][0] - te, tr3)
        rcval.check("joint_stop_slider.slider3_curve.contact_time", e7 < TOL,
                    f"stop_release - stop_enter = {1e3 * (ev3['stop_release'][0] - te):.9f} ms; solve_ivp "
                    f"{1e3 * tr3:.9f} ms; rel. error {e7:.2e} (< {TOL:g})")
        i = np.where((r.t > ev3["stop_leave"][0] + 1e-3) & (r.at_event == 0))[0][0]
        e8 = rcval.rel(r.vel[i, 2, 0], vr3)
        rcval.check("joint_stop_slider.slider3_curve.exit_speed", e8 < TOL,
                    f"velocity after the stop {r.vel[i, 2, 0]:.10f} m/s; solve_ivp {vr3:.10f} m/s; rel. error "
                    f"{e8:.2e} (< {TOL:g})")
        e9 = rcval.rel(ev3["stop_leave"][0] - te, tl3)
        rcval.check("joint_stop_slider.slider3_curve.leave_time", e9 < TOL,
                    f"stop_leave - stop_enter = {1e3 * (ev3['stop_leave'][0] - te):.9f} ms; solve_ivp + flight "
                    f"{1e3 * tl3:.9f} ms; rel. error {e9:.2e} (< {TOL:g})")
    # undamped: peak force v0 sqrt(K m) at the quarter period, a record near it
    wn = math.sqrt(K / M)
    tpk = t1 + 0.5 * math.pi / wn
    ipk = np.argmin(np.abs(r.t - tpk))
    fpk = v0_ref = V0 * math.sqrt(K * M)
    fref = fpk * math.cos(wn * (r.t[ipk] - tpk))
    e5 = rcval.rel(fstop[ipk, 1], fref)
    rcval.check("joint_stop_slider.stop_force", e5 < TOL_F and fstop[ipk, 1] > 0,
                f"joint_stop_force of slider 2 at t = {r.t[ipk]:.6f} s: {fstop[ipk, 1]:.9f} N; K p(t) = v0 sqrt(K m) "
                f"cos(omega (t - t_peak)) = {fref:.9f} N (peak {v0_ref:.6g} N); rel. error {e5:.2e} (< {TOL_F:g})")
    within = (r.t < t1 - 1e-9)
    rcval.check("joint_stop_slider.no_force_within", np.all(fstop[within] == 0.0),
                "joint_stop_force = 0 within the stops")
    e0 = 0.5 * M * V0 * V0  # per slider
    et = r.energy["energy_total"]
    drift = np.max(np.abs(et - et[0])) / e0
    rcval.check("joint_stop_slider.energy_ledger", drift < TOL_E,
                f"max |E_total(t) - E_total(0)| = {drift:.2e} m v0^2/2 (< {TOL_E:g})")
    _, vr, _ = clipped(ZETA)
    # what the stops took: the damper's dissipation and the elastic energy
    # K p_r^2 / 2 left in the damped stop at its release (lost there)
    diss = r.energy["energy_coupling_damping"][-1] + r.energy["energy_coupling_elastic"][-1]
    dref = e0 * (1.0 - vr * vr) + 0.5 * M * (V0 * V0 - vr3 * vr3)  # sliders 1 and 3
    e6 = rcval.rel(diss, dref)
    rcval.check("joint_stop_slider.energy_taken", e6 < TOL,
                f"energy_coupling_damping + energy_coupling_elastic at the end {diss:.10f} J; m (v0^2 - v_r^2)/2 of "
                f"sliders 1 and 3 = "
                f"{dref:.10f} J; rel. error {e6:.2e} (< {TOL:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
