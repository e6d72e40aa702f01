"""A flap spinning on a /JOINT/REVOLUTE runs into the hinge's angular stop,
and a pendulum on a hinge with a stop.

Flap: a slender rod (mass m, length L) hinged at one end to the ground about
z, its centre of mass at L/2: moment of inertia I_h = m L^2 / 3 about the
hinge. Gravity along -z, the axis (no moment about it). It starts at theta =
0 spinning at omega0 towards the upper stop Lim_max = theta_s, damping ratio
zeta: past the stop, I_h p'' = -K p - C p' (p = theta - theta_s), clipped at
zero. The closed forms of joint_stop_slider, in the angle:
- onset t1 = theta_s / omega0 (stop_enter);
- release after t_r = (pi - atan(2 zeta sqrt(1 - zeta^2) / (1 - 2 zeta^2))) / omega_d,
  the angular velocity there omega0 exp(-zeta omega_n t_r) (cos omega_d t_r -
  zeta omega_n / omega_d sin omega_d t_r), kept after the stop;
- the stop moment K p + C p' at the records inside the contact, against the
  closed-form p(t);
- the energy ledger constant.

Pendulum: the same rod hinged about z with gravity -y, released from rest
at theta0 = 60 degrees from the downward vertical, swings down and past the
vertical into a damped stop 20 degrees beyond it (Lim_min = -80 degrees: the
joint coordinate is 0 at the release). Reference: SciPy's solve_ivp (DOP853,
rtol 1e-13) of the independent equation I_h theta'' = -m g l_c sin(theta) +
M_stop, M_stop = K (theta_min - theta) - C theta' past the stop until it
vanishes, written here; the stop's onset, release and leave times and the
angle of the first apex after the rebound.
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

M, L, G = 2.0, 0.6, 9.81
LC = L / 2.0
I_CM = M * L * L / 12.0
I_H = I_CM + M * LC * LC            # m L^2 / 3 = 0.24 kg m^2
OMEGA0, TH_S, ZETA = 2.0, 0.5, 0.15
K = I_H * 50.0 ** 2                 # omega_n = 50 rad/s
C = 2.0 * ZETA * math.sqrt(K * I_H)
# the pendulum
TH0 = math.radians(60.0)
TH_MIN = -math.radians(20.0)
KP, ZP = 600.0, 0.2
CP = 2.0 * ZP * math.sqrt(KP * I_H)
T_END, DT_OUT = 1.2, 1e-3
TOL_T1 = 1e-9
TOL = 1e-6
TOL_E = 1e-6


def deck():
    d = Deck("a flap spinning into the hinge's angular stop; a pendulum with a stop")
    # flap along +x, hinge at the origin; pendulum hanging from (0, 2, 5) at theta0
    px, py = LC * math.sin(TH0), 2.0 - LC * math.cos(TH0)
    d.nodes([(1, LC, 0.0, 0.0), (2, px, py, 5.0)])
    d.rbody(1, 1, M, [I_CM, I_CM, I_CM], title="flap (rod 0.6 m, 2 kg)")
    d.rbody(2, 2, M, [I_CM, I_CM, I_CM], title="pendulum (rod 0.6 m, 2 kg)")
    d.grnod(1, [1])
    d.inivel(1, (0.0, OMEGA0 * LC, 0.0), 1)
    d.inivel(2, (0.0, 0.0, OMEGA0), 1, rot=True)
    d.grav(1, "Z", -G, grnod=1)
    d.grnod(2, [2])
    d.grav(2, "Y", -G, grnod=2)
    # a revolute joint takes both stops (its angle is measured within one
    # turn around their middle): the flap's lower one and the pendulum's
    # upper one are never reached
    d.joint(1, "REVOLUTE", 1, 0, (0.0, 0.0, 0.0), axis=(0.0, 0.0, 1.0), lim_min=-2.5, lim_max=TH_S, k_lim=K, c_lim=C,
            title="flap hinge, stop at 0.5 rad")
    d.joint(2, "REVOLUTE", 2, 0, (0.0, 2.0, 5.0), axis=(0.0, 0.0, 1.0), lim_min=TH_MIN - TH0, lim_max=1.0, k_lim=KP,
            c_lim=CP, title="pendulum hinge, stop 20 degrees past the vertical")
    d.run(T_END, DT_OUT)
    return d


def clipped(zeta, wn):
    wd = wn * math.sqrt(1.0 - zeta * zeta)
    tr = (math.pi - math.atan(2.0 * zeta * math.sqrt(1.0 - zeta * zeta) / (1.0 - 2.0 * zeta * zeta))) / wd
    ex = math.exp(-zeta * wn * tr)
    return tr, ex * (math.cos(wd * tr) - zeta * wn / wd * math.sin(wd * tr))


def angle(quat):
    """Rotation about z of a body turned about z only: 2 atan2(q_z, q_w)."""
    return 2.0 * np.arctan2(quat[..., 3], quat[..., 0])


def pendulum_reference():
    """theta from the downward vertical: I_h theta'' = -m g l_c sin(theta) +
    M_stop; events: onset (theta = TH_MIN), release (the stop moment back to
    zero), leave (theta = TH_MIN again), apex (theta' = 0) after."""
    def free(t, s):
        return [s[1], -M * G * LC * math.sin(s[0]) / I_H]

    def stop(t, s):
        p, pd = TH_MIN - s[0], -s[1]
        return [s[1], (-M * G * LC * math.sin(s[0]) + (KP * p + CP * pd)) / I_H]

    opts = dict(method="DOP853", rtol=1e-13, atol=1e-15, dense_output=True)
    onset = lambda t, s: s[0] - TH_MIN
    onset.terminal, onset.direction = True, -1
    a = solve_ivp(free, (0, 5), [TH0, 0.0], events=onset, **opts)
    t1, s1 = a.t_events[0][0], a.y_events[0][0]
    rel = lambda t, s: KP * (TH_MIN - s[0]) - CP * s[1]
    rel.terminal, rel.direction = True, -1
    b = solve_ivp(stop, (t1, t1 + 5), s1, events=rel, **opts)
    t2, s2 = b.t_events[0][0], b.y_events[0][0]
    leave = lambda t, s: s[0] - TH_MIN
    leave.terminal, leave.direction = True, 1
    c = solve_ivp(free, (t2, t2 + 5), s2, events=leave, **opts)
    t3, s3 = c.t_events[0][0], c.y_events[0][0]
    apex = lambda t, s: s[1]
    apex.terminal, apex.direction = True, -1
    e = solve_ivp(free, (t3, t3 + 5), s3, events=apex, **opts)
    return t1, t2, t3, e.t_events[0][0], e.y_events[0][0][0]


def main():
    path = rcval.run_case()
    r = rcval.Result(path)
    with Dataset(path) as nc:
        mstop = np.array(nc["joint_stop_moment"][:])
        quat = np.array(nc["body_quaternion"][:])
        omega = np.array(nc["body_angular_velocity"][:])

    def ev(kind, elem):
        return [t for t, k, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == kind and e == elem]

    # ---- flap
    wn = math.sqrt(K / I_H)
    wd = wn * math.sqrt(1 - ZETA ** 2)
    t1 = TH_S / OMEGA0
    te, trl = ev("stop_enter", "/JOINT/REVOLUTE/1"), ev("stop_release", "/JOINT/REVOLUTE/1")
    tl = ev("stop_leave", "/JOINT/REVOLUTE/1")
    ok = len(te) == 1 and len(trl) == 1 and len(tl) == 1
    rcval.check("joint_stop_flap.flap.events", ok,
                f"stop_enter {len(te)}, stop_release {len(trl)}, stop_leave {len(tl)} (one each: the lower stop "
                f"at -2.5 rad is not reached)")
    if ok:
        e1 = rcval.rel(te[0], t1)
        rcval.check("joint_stop_flap.flap.onset", e1 < TOL_T1,
                    f"stop_enter at {te[0]:.12f} s; theta_s / omega0 = {t1:.12f} s; rel. error {e1:.2e} (< {TOL_T1:g})")
        tr, vr = clipped(ZETA, wn)
        e2 = rcval.rel(trl[0] - te[0], tr)
        rcval.check("joint_stop_flap.flap.contact_time", e2 < TOL,
                    f"stop_release - stop_enter = {1e3 * (trl[0] - te[0]):.9f} ms; closed form {1e3 * tr:.9f} ms; "
                    f"rel. error {e2:.2e} (< {TOL:g})")
        i = np.where((r.t > trl[0] + 0.05) & (r.at_event == 0))[0][0]
        w = omega[i, 0, 2]
        e3 = rcval.rel(w, vr * OMEGA0)
        rcval.check("joint_stop_flap.flap.exit_omega", e3 < TOL,
                    f"angular velocity after the stop {w:.10f} rad/s; closed form {vr * OMEGA0:.10f} rad/s; rel. error "
                    f"{e3:.2e} (< {TOL:g})")
        # the moment at the records inside the contact: -(K p + C p')
        sel = np.where((r.t > te[0]) & (r.t < trl[0]) & (r.at_event == 0))[0]
        tau = r.t[sel] - t1
        p = OMEGA0 / wd * np.exp(-ZETA * wn * tau) * np.sin(wd * tau)
        pd = OMEGA0 * np.exp(-ZETA * wn * tau) * (np.cos(wd * tau) - ZETA * wn / wd * np.sin(wd * tau))
        mref = -(K * p + C * pd)
        e4 = np.max(np.abs(mstop[sel, 0] - mref)) / (K * OMEGA0 / wn)
        rcval.check("joint_stop_flap.flap.stop_moment", len(sel) > 10 and e4 < TOL,
                    f"joint_stop_moment at {len(sel)} records in the contact against -(K p + C p') of the closed "
                    f"form: max error {e4:.2e} of K omega0/omega_n (< {TOL:g})")
        th = angle(quat[:, 0, :])
        e5 = np.max(np.abs(th[sel] - (TH_S + p)))
        rcval.check("joint_stop_flap.flap.angle", e5 < TOL * TH_S,
                    f"flap angle inside the contact against theta_s + p(t): max error {e5:.2e} rad "
                    f"(< {TOL * TH_S:g})")
    # ---- pendulum
    t1, t2, t3, ta, tha = pendulum_reference()
    pe, pr, pl = (ev(k, "/JOINT/REVOLUTE/2") for k in ("stop_enter", "stop_release", "stop_leave"))
    ok = len(pe) >= 1 and len(pr) >= 1 and len(pl) >= 1
    rcval.check("joint_stop_flap.pendulum.events", ok,
                f"stop_enter {len(pe)}, stop_release {len(pr)}, stop_leave {len(pl)} (at least one each)")
    if ok:
        for nm, got, ref in (("onset", pe[0], t1), ("release", pr[0], t2), ("leave", pl[0], t3)):
            err = rcval.rel(got, ref)
            rcval.check(f"joint_stop_flap.pendulum.{nm}", err < TOL,
                        f"{nm} at {got:.10f} s; solve_ivp {ref:.10f} s; rel. error {err:.2e} (< {TOL:g})")
        # the apex after the rebound: the largest angle on the records around it
        th = angle(quat[:, 1, :]) + TH0
        sel = np.where((r.t > ta - 0.02) & (r.t < ta + 0.02))[0]
        j = sel[np.argmax(th[sel])]
        cf = np.polyfit(r.t[j - 1:j + 2] - r.t[j], th[j - 1:j + 2], 2)
        th_apex = cf[2] - cf[1] ** 2 / (4 * cf[0])
        err = abs(th_apex - tha) / abs(tha - TH_MIN)
        rcval.check("joint_stop_flap.pendulum.apex", err < TOL,
                    f"apex after the rebound {math.degrees(th_apex):.8f} deg; solve_ivp {math.degrees(tha):.8f} deg; "
                    f"error {err:.2e} of the swing from the stop (< {TOL:g}; three-record parabola)")
    et = r.energy["energy_total"]
    e0 = 0.5 * I_H * OMEGA0 ** 2 + M * G * LC * (1 - math.cos(TH0))
    drift = np.max(np.abs(et - et[0])) / e0
    rcval.check("joint_stop_flap.energy_ledger", drift < TOL_E,
                f"max |E_total(t) - E_total(0)| = {drift:.2e} of the initial energy (< {TOL_E:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
