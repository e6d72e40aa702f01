"""/SPRING elements of a /PROP/TYPE8 (SPR_GENE) general spring with elastic
curves (fct_ID1i, scaled by Ai and Ascalei) against the closed form of the
bilinear oscillator.

One dimensionless /FUNCT, f(x) = x for |x| <= 1 and sign(x) (1 + 2 (|x| -
1)) beyond (slope 1, then 2), serves two directions of two springs with
different scales, the law F = A f(u / Ascale):
  A: translation along X. A body of 2 kg on a zero-length spring to a fixed
     node, A1 = 0.5 N, Ascale1 = 0.01 m: k1 = A1/Ascale1 = 50 N/m up to
     u1 = 0.01 m, k2 = 2 k1 beyond; started at v0 = 0.1 m/s (the linear
     amplitude would be 0.02 m);
  B: rotation about Z. A body of isotropic inertia 0.125 kg m^2,
     A6 = 2e-4 N m, Ascale6 = 1e-4 rad: k1 = 2 N m/rad up to 1e-4 rad, 4
     beyond; started at 8e-4 rad/s (the turns stay below 2e-4 rad, where
     2 sin(phi/2) is phi to 2e-9 of it).
The bilinear oscillator's motion is exact piecewise: u = v0/w1 sin(w1 t)
up to u1 at t1 = asin(u1 w1/v0)/w1, then uc + a sin(w2 (t - t1) + phi0)
about uc = u1 (1 - k1/k2) up to the peak, symmetric after; period
4 (t1 + (pi/2 - phi0)/w2). Checks the histories, the periods, the peaks,
the energy ledger (README.md).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

FX = [-10.0, -1.0, 0.0, 1.0, 10.0]
FY = [-19.0, -1.0, 0.0, 1.0, 19.0]
MA, A1, AS1, VA = 2.0, 0.5, 0.01, 0.1
JB, A6, AS6, WB0 = 0.125, 2e-4, 1e-4, 8e-4
PA = np.array([0.2, -0.1, 0.4])
PB = np.array([-1.0, 2.0, 0.5])


class Bilinear:
    """The oscillator m u'' = -F(u), F = k1 u (|u| <= u1), sign(u) (k1 u1 +
    k2 (|u| - u1)) beyond, u(0) = 0, u'(0) = v0 > 0 reaching past u1."""

    def __init__(self, m, k1, k2, u1, v0):
        self.w1, self.w2 = math.sqrt(k1 / m), math.sqrt(k2 / m)
        self.v0, self.u1 = v0, u1
        self.t1 = math.asin(u1 * self.w1 / v0) / self.w1
        v1 = math.sqrt(v0**2 - (self.w1 * u1)**2)
        s0 = k1 * u1 / k2
        self.uc = u1 - s0
        self.a = math.sqrt(s0**2 + (v1 / self.w2)**2)
        self.phi0 = math.atan2(s0 * self.w2, v1)
        self.period = 4.0 * (self.t1 + (math.pi / 2 - self.phi0) / self.w2)
        self.peak = self.uc + self.a

    def quarter(self, t):
        return np.where(t < self.t1, self.v0 / self.w1 * np.sin(self.w1 * t),
                        self.uc + self.a * np.sin(self.w2 * (t - self.t1) + self.phi0))

    def __call__(self, t):
        T = self.period
        tm = np.mod(t, T)
        half = np.where(tm < T / 2, 1.0, -1.0)
        th = np.mod(tm, T / 2)
        th = np.where(th > T / 4, T / 2 - th, th)
        return half * self.quarter(th)


OSC_A = Bilinear(MA, A1 / AS1, 2 * A1 / AS1, AS1, VA)
OSC_B = Bilinear(JB, A6 / AS6, 2 * A6 / AS6, AS6, WB0)
T_END = 10 * max(OSC_A.period, OSC_B.period)


def prop(k, a, ascale, fct):
    """/PROP/TYPE8 lines: per direction K C A B D, the curves line
    (fct_ID1i), F E Ascale Hscale."""
    lines = ["#               Mass                   I   Skew_ID   sens_ID    Isflag     Ifail    Ifail2    Iequil",
             line(("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0))]
    for i in range(6):
        lines += [f"#                 K{i + 1}                  C{i + 1}                  A{i + 1}                  B{i + 1}"
                  f"                  D{i + 1}",
                  line(("r", k[i]), ("r", 0.0), ("r", a[i]), ("r", 0.0), ("r", 1.0)),
                  f"# fct_ID1{i + 1}        H{i + 1}",
                  line(("i", fct[i]), ("i", 0), ("i", 0), ("i", 0), ("i", 0)),
                  f"#                 F{i + 1}                  E{i + 1}             Ascale{i + 1}             Hscale{i + 1}",
                  line(("r", 1.0), ("r", 0.0), ("r", ascale[i]), ("r", 1.0))]
    return lines


def deck(rtol=1e-10):
    d = Deck("general springs (TYPE8) with elastic curves: bilinear oscillators")
    d.nodes([(1, *PA), (9, *PA), (2, *PB), (8, *PB)])
    d.rbody(1, 1, MA, [0.3, 0.4, 0.5], title="body A 2 kg")
    d.rbody(2, 2, 0.8, [JB, JB, JB], title="body B, J 0.125 kg m2")
    d.grnod(1, [1], title="body A")
    d.grnod(2, [2], title="body B")
    d.inivel(1, (VA, 0.0, 0.0), 1)
    d.inivel(2, (0.0, 0.0, WB0), 2, rot=True)
    d.funct(1, FX, FY, title="bilinear, slope 1 then 2")
    for pid in (7, 8):
        d.add(f"/PART/{pid}", "#  prop_ID    mat_ID", line(("i", pid), ("i", 0)), title=f"general spring {pid}")
    d.add("/PROP/TYPE8/7", *prop([0.0, 4e4, 6e4, 10.0, 20.0, 30.0], [A1, 0, 0, 0, 0, 0], [AS1, 0, 0, 0, 0, 0],
                                 [1, 0, 0, 0, 0, 0]), title="X: A1 = 0.5 N, Ascale1 = 0.01 m")
    d.add("/PROP/TYPE8/8", *prop([1e3, 1e3, 1e3, 5.0, 6.0, 0.0], [0, 0, 0, 0, 0, A6], [0, 0, 0, 0, 0, AS6],
                                 [0, 0, 0, 0, 0, 1]), title="RZ: A6 = 2e-4 N m, Ascale6 = 1e-4 rad")
    d.add("/SPRING/7", "#  sprg_ID  node_ID1  node_ID2", line(("i", 71), ("i", 9), ("i", 1)))
    d.add("/SPRING/8", "#  sprg_ID  node_ID1  node_ID2", line(("i", 81), ("i", 8), ("i", 2)))
    d.run(T_END, T_END / 2000)
    d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_quat=1e-4 * rtol, atol_vel=1e-1 * rtol, atol_omega=1e-4 * rtol,
             atol_energy=1e-6 * rtol)
    return d


def turn_z(q):
    return 2.0 * np.arctan2(q[:, 3], q[:, 0])


def errors(path):
    r = rcval.Result(path)
    ua = r.pos[:, 0, 0] - PA[0]
    ea = np.max(np.abs(ua - OSC_A(r.t))) / OSC_A.peak
    pb = turn_z(r.quat[:, 1, :])
    eb = np.max(np.abs(pb - OSC_B(r.t))) / OSC_B.peak
    return r, ea, eb, ua, pb


def main():
    r, ea, eb, ua, pb = errors(rcval.run_case())
    # the curve's kinks are crossed without being located (a slope jump
    # inside a step): a bound of 1e-5, where the smooth laws take 1e-6
    rcval.check("spring_curve.translation", ea < 1e-5,
                f"body on a TYPE8 spring whose X law is A1 f(u/Ascale1), bilinear 50 then 100 N/m past "
                f"0.01 m: max |u - u_exact| / u_peak = {ea:.2e} over {len(r.t)} outputs (< 1e-5)")
    rcval.check("spring_curve.rotation", eb < 1e-5,
                f"body turning on a TYPE8 spring whose RZ law is A6 f(phi/Ascale6), bilinear 2 then 4 N m/rad past "
                f"1e-4 rad: max |phi - phi_exact| / phi_peak = {eb:.2e} (< 1e-5)")
    for name, x, osc in (("translation", ua, OSC_A), ("rotation", pb, OSC_B)):
        tc = rcval.down_crossings(r.t, x)
        per = float(np.mean(np.diff(tc))) if len(tc) >= 2 else float("nan")
        peak = rcval.refined_extreme(x, 1)
        ep, ek = abs(per - osc.period) / osc.period, abs(peak - osc.peak) / osc.peak
        rcval.check(f"spring_curve.{name}_period_peak", ep < 1e-6 and ek < 1e-5,
                    f"period {per:.9g} s against 4 (t1 + (pi/2 - phi0)/w2) = {osc.period:.9g} s (rel. {ep:.1e}, "
                    f"< 1e-6), peak {peak:.9g} against uc + a = {osc.peak:.9g} (rel. {ek:.1e}, < 1e-5; the "
                    f"linear law would reach {osc.v0 / osc.w1:.4g})")
    ek0 = 0.5 * MA * VA**2 + 0.5 * JB * WB0**2
    el, ekin = r.energy["energy_coupling_elastic"], r.energy["energy_kinetic"]
    eres = np.max(np.abs(ekin + el - ek0)) / ek0
    rcval.check("spring_curve.energy", eres < 1e-6,
                f"kinetic + energy_coupling_elastic (the integral of the curves) = initial kinetic to {eres:.1e} "
                f"(< 1e-6)")
    errs = [max(errors(rcval.run(deck(rtol), keep_solver=True))[1:3]) for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("spring_curve.convergence", errs[2] < errs[1] < errs[0],
                "max error / peak at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
