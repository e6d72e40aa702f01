"""A sphere against a cylinder of finite length (docs/theory.md 2).

Steel ball (R_s = 20 mm, m = 0.2630 kg) and a cylinder (R_c = 0.1 m,
L = 0.4 m). References (README.md), independent of ricochet:
  1. impact on the lateral surface at mid-length of a FREE cylinder
     (m_c = 2 kg), no gravity, /INTER/POWER linear (K, m1 = 1, C = 0) and
     /INTER/TYPE6 with the same linear load curve: a linear spring between
     the two masses, closed form with the reduced mass m_red:
     contact time pi sqrt(m_red / K), maximum approach v0 sqrt(m_red / K),
     velocities after the impact v_s' = v0 (m_s - m_c) / (m_s + m_c),
     v_c' = 2 m_s v0 / (m_s + m_c);
  2. impact on the flat end disc of a fixed cylinder, off the axis, along
     the axis, Hertz law K delta^1.5: Hertz closed form (as pw_hertz) with
     the ball's mass; the same on the cap of a rounded cylinder, head-on;
  3. the ball released at the top of a fixed horizontal cylinder with a
     small speed across the axis, gravity, frictionless, Hertz and linear
     laws: it slides round and leaves the cylinder; the leaving time and angle
     against a SciPy solve (DOP853) of the centre's equations in the plane
     across the axis, written here (the same penalty law), and the angle
     against the rigid closed form cos(theta) = 2/3 cos(theta0) +
     v0^2 / (3 g (R_c + R_s)) (the small-ball limit with the ball's radius
     in the radius of the centre's path);
  4. along the top of a tilted cylinder with friction: rolling (TYPE6, also
     with exact stick) at g sin / (1 + J / (m r^2)), sliding (power law, step5) at
     g (sin - mu_d cos);
  5. bouncing to rest on a flat end disc: F_n = m g.
Default solver settings (no /SOLVER card).
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset
from scipy.integrate import solve_ivp
from scipy.special import gamma

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

RS, RHO = 0.02, 7850.0
MS = RHO * 4.0 / 3.0 * math.pi * RS**3
RC, LC, MC = 0.1, 0.4, 2.0
G = 9.81
KLIN = 2.0e7       # linear law [N/m]
KH = 1.0e9         # Hertz law [N/m^1.5]


def omega(path):
    """body_angular_velocity [rad/s] of an output file: (time, body, 3)."""
    with Dataset(path) as nc:
        return np.array(nc["body_angular_velocity"][:])


def js(m, r):
    return [0.4 * m * r * r] * 3


def impact_deck(law, v0=0.5):
    """1: the ball (x = -(RC + RS + gap)) moving +x onto the free cylinder
    (axis y, centre at the origin), no gravity."""
    d = Deck(f"ball onto the lateral surface of a free cylinder, {law}")
    x0 = -(RC + RS + 1e-4)
    d.nodes([(1, x0, 0.0, 0.0), (2, 0.0, 0.0, 0.0)])
    d.rbody(1, 1, MS, js(MS, RS), title="ball")
    d.rbody(2, 2, MC, [MC * (3 * RC**2 + LC**2) / 12.0, 0.5 * MC * RC**2, MC * (3 * RC**2 + LC**2) / 12.0],
            title="free cylinder")
    d.grnod(1, [1], title="ball")
    d.sphere(1, 1, (x0, 0.0, 0.0), RS, title="ball")
    d.cylinder(2, 2, (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), RC, LC, title="cylinder, flat ends")
    d.inivel(1, (v0, 0.0, 0.0), 1)
    if law == "power":
        d.power(1, 2, 1, k=KLIN, m1=1.0, c=0.0, title="linear power law, cylinder first on the card")
    else:
        d.funct(1, [0.0, 1.0], [0.0, KLIN], title="linear load curve")
        d.type6(1, 1, 2, 1, title="TYPE6 linear")
    d.run(1.0e-3, 1.0e-6)
    return d


def end_deck(ends, v0=0.5, rho=0.05):
    """2: the ball moving -z onto the top end of a fixed upright cylinder
    (axis z), off the axis by rho (flat) or on it (rounded), Hertz law."""
    top = 0.5 * LC + (RC if ends else 0.0)
    z0 = top + RS + 1e-5
    x0 = 0.0 if ends else rho
    d = Deck(f"ball onto the {'rounded cap' if ends else 'flat end disc'} of a fixed cylinder, Hertz")
    d.nodes([(1, x0, 0.0, z0)])
    d.rbody(1, 1, MS, js(MS, RS), title="ball")
    d.grnod(1, [1], title="ball")
    d.sphere(1, 1, (x0, 0.0, z0), RS, title="ball")
    d.cylinder(2, 0, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), RC, LC, ends=ends, title="fixed cylinder")
    d.inivel(1, (0.0, 0.0, -v0), 1)
    d.power(1, 1, 2, k=KH, m1=1.5, c=0.0, title="Hertz: K delta^1.5")
    d.run(1.2e-3, 2.0e-7)
    return d


TH0, V0S = 0.0, 0.05  # leaving problem: start at the top, speed across the axis
LAWS = {"hertz": (KH, 1.5), "linear": (KLIN, 1.0)}


def p_top(law):
    """Static penetration at the top with the centripetal demand of V0S."""
    k, m1 = LAWS[law]
    f = MS * G * math.cos(TH0) - MS * V0S**2 / (RC + RS)
    return (f / k) ** (1.0 / m1)


def leave_deck(law, tend=1.0):
    """3: the ball on top of a fixed horizontal cylinder (axis y), speed V0S
    along +x, gravity -z, frictionless."""
    k, m1 = LAWS[law]
    rr = RC + RS - p_top(law)
    c = (rr * math.sin(TH0), 0.0, rr * math.cos(TH0))
    d = Deck(f"ball sliding off a fixed horizontal cylinder, frictionless, {law} law")
    d.nodes([(1, *c)])
    d.rbody(1, 1, MS, js(MS, RS), title="ball")
    d.grnod(1, [1], title="ball")
    d.sphere(1, 1, c, RS, title="ball")
    d.cylinder(2, 0, (0.0, 0.0, 0.0), (0.0, 1.0, 0.0), RC, LC, title="fixed cylinder, axis y")
    d.inivel(1, (V0S * math.cos(TH0), 0.0, -V0S * math.sin(TH0)), 1)
    d.power(1, 1, 2, k=k, m1=m1, c=0.0, title=f"{law}, frictionless")
    d.grav(1, "Z", -G)
    d.run(tend, 1.0e-3)
    return d


def leave_reference(law):
    """SciPy: the centre (x, z) in the plane across the axis, force
    K p^m1 along the radius while p = R_c + R_s - r > 0, gravity -z;
    until p = 0 from above. Returns (t, theta) at the leaving and theta(t)."""
    k, m1 = LAWS[law]
    rr = RC + RS

    def f(t, y):
        x, z, vx, vz = y
        r = math.hypot(x, z)
        p = rr - r
        fn = k * p**m1 if p > 0 else 0.0
        return [vx, vz, fn / MS * x / r, fn / MS * z / r - G]

    def sep(t, y):
        return rr - math.hypot(y[0], y[1])
    sep.terminal, sep.direction = True, -1
    r0 = rr - p_top(law)
    y0 = [r0 * math.sin(TH0), r0 * math.cos(TH0), V0S * math.cos(TH0), -V0S * math.sin(TH0)]
    s = solve_ivp(f, (0.0, 5.0), y0, method="DOP853", rtol=1e-12, atol=1e-14, events=sep, max_step=2e-4,
                  dense_output=True)
    t = s.t_events[0][0]
    x, z = s.y_events[0][0][:2]

    def theta(tt):
        yy = s.sol(tt)
        return math.atan2(yy[0], yy[1])
    return t, math.atan2(x, z), theta


TAN_A, MU, MUS, MUD, VS, VD = 0.5, 0.3, 0.35, 0.25, 0.01, 0.05  # along the top of a tilted cylinder


def along_deck(kind, tend=0.3):
    """4: the ball on the top generator of a fixed cylinder whose axis is
    tilted by alpha (tan alpha = 0.5) in the x-z plane, gravity -z: TYPE6
    with Fric (rotations free: it rolls) or the power law with step5
    friction (rotations locked, v0 = 0.5 m/s down the axis > v_d: it slides
    at mu_d)."""
    al = math.atan(TAN_A)
    e = (math.cos(al), 0.0, -math.sin(al))
    n = (math.sin(al), 0.0, math.cos(al))
    p0 = MS * G * math.cos(al) / KLIN
    c = tuple(-0.15 * e[k] + (RC + RS - p0) * n[k] for k in range(3))
    d = Deck(f"ball along the top of a tilted fixed cylinder, {kind}")
    d.nodes([(1, *c)])
    d.rbody(1, 1, MS, js(MS, RS), title="ball")
    d.grnod(1, [1], title="ball")
    d.sphere(1, 1, c, RS, title="ball")
    d.cylinder(2, 0, (0.0, 0.0, 0.0), e, RC, LC, title="fixed cylinder, tilted axis")
    visc = 2.0 * 0.5 * math.sqrt(KLIN * MS)
    if kind in ("roll", "roll_exact_stick"):
        d.funct(1, [0.0, 1.0], [0.0, KLIN], title="linear load curve")
        d.type6(1, 2, 1, 1, visc=visc, fric=MU, istick=1 if kind == "roll_exact_stick" else None,
                title="TYPE6, Fric 0.3, cylinder first")
    else:
        d.bcs(1, 1, "000 111", title="no rotation")
        d.inivel(1, tuple(0.5 * e[k] for k in range(3)), 1)
        d.power(1, 1, 2, k=KLIN, m1=1.0, c=visc, m2=1.0, m3=0.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD,
                title="power law, step5 friction")
    d.grav(1, "Z", -G)
    d.run(tend, 1.0e-3)
    return d, np.array(e), p0


def rest_deck():
    """5: the ball dropped 0.05 m onto the flat end disc of a fixed upright
    cylinder, 0.03 m off the axis, TYPE6 linear with damping ratio 0.1,
    gravity: it bounces and comes to rest on the disc."""
    z0 = 0.5 * LC + RS + 0.05
    d = Deck("ball bouncing to rest on the end disc of a fixed cylinder")
    d.nodes([(1, 0.03, 0.0, z0)])
    d.rbody(1, 1, MS, js(MS, RS), title="ball")
    d.grnod(1, [1], title="ball")
    d.sphere(1, 1, (0.03, 0.0, z0), RS, title="ball")
    d.cylinder(2, 0, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), RC, LC, title="fixed upright cylinder")
    d.funct(1, [0.0, 1.0], [0.0, 2.0e6], title="linear load curve")
    d.type6(1, 2, 1, 1, visc=2.0 * 0.1 * math.sqrt(2.0e6 * MS), title="TYPE6, damping ratio 0.1")
    d.grav(1, "Z", -G)
    d.run(3.0, 0.01)
    return d


def hertz(m, v0):
    dmax = (5.0 * m * v0**2 / (4.0 * KH)) ** 0.4
    return dmax, 2.0 * dmax / v0 * math.sqrt(math.pi) * gamma(1.4) / gamma(0.9)


def main():
    # 1. free-free impact on the lateral surface, power and TYPE6
    v0 = 0.5
    mred = MS * MC / (MS + MC)
    tc_ref, dmax_ref = math.pi * math.sqrt(mred / KLIN), v0 * math.sqrt(mred / KLIN)
    vs_ref, vc_ref = v0 * (MS - MC) / (MS + MC), 2 * MS * v0 / (MS + MC)
    for law in ("power", "type6"):
        path = (rcval.run_case() if law == "power"
                else rcval.run(impact_deck(law), name=law))
        r, w = rcval.Result(path), omega(path)
        t1, t2 = r.events("contact_close")[0], r.contact_ends()[0]
        k = int(np.argmax(r.pen[:, 0]))
        dm = rcval.parabola_peak(r.pen[:, 0], k)
        e1, e2 = rcval.rel(t2 - t1, tc_ref), rcval.rel(dm, dmax_ref)
        rcval.check(f"pw_sphere_cylinder.lateral_{law}.contact_time", e1 < 1e-5,
                    f"{t2 - t1:.9e} s, pi sqrt(m_red / K) = {tc_ref:.9e} s, rel. error {e1:.2e} (< 1e-5)")
        rcval.check(f"pw_sphere_cylinder.lateral_{law}.max_approach", e2 < 1e-5,
                    f"{dm:.9e} m, v0 sqrt(m_red / K) = {dmax_ref:.9e} m, rel. error {e2:.2e} (< 1e-5)")
        vs, vc = r.vel[-1, 0, :], r.vel[-1, 1, :]
        ev = max(abs(vs[0] - vs_ref), abs(vc[0] - vc_ref), *np.abs(vs[1:]), *np.abs(vc[1:]),
                 *(RC * np.abs(w[-1].ravel()))) / v0
        rcval.check(f"pw_sphere_cylinder.lateral_{law}.velocities", ev < 1e-5,
                    f"after: ball {vs[0]:.9f} m/s (ref {vs_ref:.9f}), cylinder {vc[0]:.9f} m/s (ref {vc_ref:.9f}), "
                    f"other components and spins (times R_c) zero; max error / v0 = {ev:.2e} (< 1e-5)")
        if law == "power":
            rcval.check_ledger("pw_sphere_cylinder.lateral_power.ledger", r, 1e-5)

    # 2. end disc (flat, off the axis) and rounded cap (head-on), Hertz
    dmax_ref, tc_ref = hertz(MS, v0)
    for ends, name in ((0, "end_disc"), (1, "rounded_cap")):
        r = rcval.Result(rcval.run(end_deck(ends, v0), name=name))
        t1, t2 = r.events("contact_close")[0], r.contact_ends()[0]
        k = int(np.argmax(r.pen[:, 0]))
        dm = rcval.parabola_peak(r.pen[:, 0], k)
        e1, e2 = rcval.rel(t2 - t1, tc_ref), rcval.rel(dm, dmax_ref)
        vz = r.vel[-1, 0, 2]
        e3 = abs(vz - v0) / v0 + float(np.max(np.abs(r.vel[-1, 0, :2]))) / v0
        rcval.check(f"pw_sphere_cylinder.{name}.hertz", e1 < 1e-5 and e2 < 1e-5 and e3 < 1e-6,
                    f"contact time {t2 - t1:.9e} s vs Hertz {tc_ref:.9e} s ({e1:.2e}), max approach {dm:.9e} m vs "
                    f"{dmax_ref:.9e} m ({e2:.2e}) (< 1e-5); rebound {vz:.9f} m/s along the axis (error / v0 "
                    f"{e3:.1e} < 1e-6)")

    # 3. leaving the cylinder, frictionless: Hertz and linear laws
    for law in ("hertz", "linear"):
        t_ref, th_ref, theta = leave_reference(law)
        path = rcval.run(leave_deck(law), name="leave_" + law)
        r, w = rcval.Result(path), omega(path)
        ends = r.contact_ends()
        t_l = ends[0] if len(ends) else float("nan")
        k = r.state_at(t_l) if len(ends) else -1
        x, z = r.pos[k, 0, 0], r.pos[k, 0, 2]
        th = math.atan2(x, z)
        e1 = abs(t_l - t_ref) / t_ref
        e2 = abs(th - theta(t_l))
        # the leaving time: p crosses zero at the slow rate dF/dt / K (linear:
        # 2e-6 m/s), so a position error of 1e-11 m moves it by 5e-6 s
        ttol = 1e-5 if law == "hertz" else 1e-4
        rcval.check(f"pw_sphere_cylinder.leave_{law}.scipy", e1 < ttol and e2 < 1e-5,
                    f"leaves at t = {t_l:.9f} s, theta = {math.degrees(th):.7f} deg; SciPy {t_ref:.9f} s, "
                    f"{math.degrees(th_ref):.7f} deg; rel. time error {e1:.2e} (< {ttol:g}), angle error against "
                    f"SciPy's theta at the same time {e2:.2e} rad (< 1e-5)")
        if law == "linear":
            c_rigid = 2.0 / 3.0 * math.cos(TH0) + V0S**2 / (3.0 * G * (RC + RS))
            e3 = abs(math.cos(th) - c_rigid)
            rcval.check("pw_sphere_cylinder.leave_linear.rigid_limit", e3 < 1e-3,
                        f"cos(theta) = {math.cos(th):.7f}, rigid 2/3 cos(theta0) + v0^2 / (3 g (R_c + R_s)) = "
                        f"{c_rigid:.7f} (2/3 = 0.6666667), difference {e3:.1e} (< 1e-3: the compliance)")
        spin = float(np.max(np.abs(w[:k + 1, 0, :])))
        rcval.check(f"pw_sphere_cylinder.leave_{law}.no_spin", spin < 1e-9 and abs(r.pos[k, 0, 1]) < 1e-9,
                    f"frictionless: max |omega| = {spin:.1e} rad/s, |y| = {abs(r.pos[k, 0, 1]):.1e} m (< 1e-9)")
        rcval.check_ledger(f"pw_sphere_cylinder.leave_{law}.ledger", r, 1e-6)

    # 4. along the top of a tilted cylinder with friction: rolling (TYPE6)
    # and sliding at mu_d (power law, step5)
    al = math.atan(TAN_A)
    for kind in ("roll", "roll_exact_stick", "slide"):
        dk, e, p0 = along_deck(kind)
        path = rcval.run(dk, name=kind)
        r = rcval.Result(path)
        xs = (r.pos[:, 0, :] - r.pos[0, 0, :]) @ e
        sl = r.t >= 0.05
        cf = np.polyfit(r.t[sl], xs[sl], 2)
        a, resid = 2 * cf[0], float(np.max(np.abs(xs[sl] - np.polyval(cf, r.t[sl]))))
        if kind != "slide":
            # rolling (TYPE6's stick spring, or exact stick on the IDA path) on the radius R_s - p0/2 of the contact point (midway
            # between the surfaces)
            rr = RS - 0.5 * p0
            a_ref = G * math.sin(al) / (1.0 + 0.4 * MS * RS * RS / (MS * rr * rr))
            what = "g sin(alpha) / (1 + J / (m (R_s - p0/2)^2))"
        else:
            a_ref = G * (math.sin(al) - MUD * math.cos(al))
            what = "g (sin(alpha) - mu_d cos(alpha))"
        e1 = rcval.rel(a, a_ref)
        slips = [t for t, kk in zip(r.ev_t, r.ev_kind) if kk == "fric_slip"]
        rcval.check(f"pw_sphere_cylinder.{kind}.acceleration", e1 < 1e-5 and resid < 1e-6 and
                    (kind == "slide" or not slips),
                    f"quadratic fit of the travel along the axis over [0.05, {r.t[-1]:g}] s: a = {a:.9f} m/s^2, "
                    f"{what} = {a_ref:.9f}, rel. error {e1:.2e} (< 1e-5), max residual {resid:.1e} m (< 1e-6), "
                    f"{xs[-1]:.3f} m travelled, {len(slips)} fric_slip events")
        rcval.check_ledger(f"pw_sphere_cylinder.{kind}.ledger", r, 1e-5)

    # 5. bouncing to rest on the end disc: the resting force m g
    r = rcval.Result(rcval.run(rest_deck(), name="rest"))
    ef = abs(r.fn[-1, 0] / (MS * G) - 1.0)
    v = float(np.max(np.abs(r.vel[-1, 0])))
    rcval.check("pw_sphere_cylinder.rest_on_disc", ef < 1e-9 and v < 1e-9 and r.mode[-1, 0] == 2,
                f"at {r.t[-1]:g} s: F_n = {r.fn[-1, 0]:.12f} N, m g = {MS * G:.12f} N, rel. error {ef:.1e} (< 1e-9), "
                f"|v| = {v:.1e} m/s (< 1e-9), contact closed")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: impact_deck("power"))
