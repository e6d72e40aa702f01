"""/SPRING elements of a /PROP/TYPE8 (SPR_GENE) and a /PROP/TYPE13
(SPR_BEAM) spring with rupture deformations (dmax_i, dmin_i) against the
closed form of an oscillator that breaks.

Two independent systems, without gravity, in Radioss's layout:
  A: a body (1.5 kg) on a TYPE8 spring (zero length, global frame) to a
     fixed node, K1 = 600 N/m (w = 20 rad/s), dmax1 = 0.03 m, started at
     v0 = 1 m/s along X: u = v0/w sin(w t) until u reaches dmax1 at
     t_r = asin(w dmax1/v0)/w, then free flight at v_r = sqrt(v0^2 -
     (w dmax1)^2): u = dmax1 + v_r (t - t_r);
  B: a body (J = 0.02 kg m^2 about every axis) on a TYPE13 spring of
     length 0.5 m along Y from a fixed node, K4 = 0.5 N m/rad (torsion about
     Y, w = 5 rad/s), dmin4 = -1e-4 rad, started turning at -1e-3 rad/s
     about Y: the turn reaches dmin4 at asin(w |dmin4| / |omega0|)/w, then
     turns on at the rate sqrt(omega0^2 - (w dmin4)^2) (the spring's
     measure 2 sin(phi/2) is phi to 4e-10 of it).
Checks the rupture events' times, the motion before and after, and the
energy ledger (the elastic energy stored at the rupture stays in
energy_coupling_elastic) (README.md).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

MA, KA, DA, VA = 1.5, 600.0, 0.03, 1.0
JB, KB, DB, WB0, LB = 0.02, 0.5, -1e-4, -1e-3, 0.5
PA = np.array([0.1, 0.2, 0.3])
PB = np.array([2.0, -1.0, 0.5])
WA, WB = math.sqrt(KA / MA), math.sqrt(KB / JB)
TA = math.asin(WA * DA / VA) / WA
TB = math.asin(WB * abs(DB) / abs(WB0)) / WB
VRA = math.sqrt(VA**2 - (WA * DA)**2)
WRB = -math.sqrt(WB0**2 - (WB * DB)**2)
T_END = 3.0 * max(TA, TB)


def broken(t, w, v0, d, tr, vr):
    return np.where(t < tr, v0 / w * np.sin(w * t), d + vr * (t - tr))


def prop(k, dmin, dmax, beam):
    h = "    Ileng    Ifail2" if beam else "   Ifail2    Iequil"
    lines = ["#               Mass                   I   Skew_ID   sens_ID    Isflag     Ifail" + h,
             line(("r", 0.0), ("r", 0.0), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0))]
    for i in range(6):
        lines += [line(("r", k[i]), ("r", 0.0), ("r", 1.0), ("r", 0.0), ("r", 1.0)),
                  f"# fct_ID1{i + 1}        H{i + 1}  fct_ID2{i + 1}  fct_ID3{i + 1}  fct_ID4{i + 1}"
                  f"                         dmin{i + 1}               dmax{i + 1}",
                  line(("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", None), ("r", dmin[i]), ("r", dmax[i])),
                  line(("r", 1.0), ("r", 0.0), ("r", 1.0), ("r", 1.0))]
    return lines


def deck(rtol=1e-10):
    d = Deck("general and beam springs that break (rupture deformations)")
    d.nodes([(1, *PA), (9, *PA), (2, *PB), (8, *(PB - [0.0, LB, 0.0]))])
    d.rbody(1, 1, MA, [0.3, 0.4, 0.5], title="body A 1.5 kg")
    d.rbody(2, 2, 0.8, [JB, JB, JB], title="body B, J 0.02 kg m2")
    d.grnod(1, [1], title="body A")
    d.grnod(2, [2], title="body B")
    d.inivel(1, (VA, 0.0, 0.0), 1)
    d.inivel(2, (0.0, WB0, 0.0), 2, rot=True)
    d.add("/PART/7", line(("i", 7), ("i", 0)), title="general spring")
    d.add("/PART/8", line(("i", 8), ("i", 0)), title="beam spring")
    d.add("/PROP/TYPE8/7", *prop([KA, 900.0, 900.0, 5.0, 5.0, 5.0], [0] * 6, [DA, 0, 0, 0, 0, 0], False),
          title="K1 = 600 N/m, dmax1 = 0.03 m")
    d.add("/PROP/TYPE13/8", *prop([900.0, 900.0, 900.0, KB, 3.0, 3.0], [0, 0, 0, DB, 0, 0], [0] * 6, True),
          title="K4 = 0.5 N m/rad, dmin4 = -1e-4 rad")
    d.add("/SPRING/7", line(("i", 71), ("i", 9), ("i", 1)))
    d.add("/SPRING/8", line(("i", 81), ("i", 8), ("i", 2)))
    d.run(T_END, T_END / 600)
    d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_quat=1e-4 * rtol, atol_vel=1e-3 * rtol, atol_omega=1e-4 * rtol,
             atol_energy=1e-6 * rtol)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    ev = r.events("spring_rupture")
    ok_n = len(ev) == 2
    ta = ev.min() if len(ev) else float("nan")
    tb = ev.max() if len(ev) else float("nan")
    eta, etb = abs(ta - TA) / TA, abs(tb - TB) / TB
    rcval.check("spring_rupture.events", ok_n and eta < 1e-6 and etb < 1e-6,
                f"{len(ev)} spring_rupture events (2) at {ta:.12g} s and {tb:.12g} s against asin(w d/v0)/w = "
                f"{TA:.12g} s, {TB:.12g} s (rel. {eta:.1e}, {etb:.1e}, < 1e-6)")
    ua = r.pos[:, 0, 0] - PA[0]
    ea = np.max(np.abs(ua - broken(r.t, WA, VA, DA, TA, VRA))) / DA
    rcval.check("spring_rupture.translation", ea < 1e-7,
                f"A: u against the oscillation, then the free flight at v_r = {VRA:.6g} m/s: max error / dmax1 = "
                f"{ea:.2e} (< 1e-7)")
    pb = 2.0 * np.arctan2(r.quat[:, 1, 2], r.quat[:, 1, 0])
    eb = np.max(np.abs(pb - broken(r.t, WB, WB0, DB, TB, WRB))) / abs(DB)
    rcval.check("spring_rupture.torsion", eb < 1e-6,
                f"B: the turn about Y against the oscillation, then the turn at {WRB:.6g} rad/s: max error / |dmin4| "
                f"= {eb:.2e} (< 1e-6)")
    va = r.vel[-1, 0, 0]
    rcval.check("spring_rupture.after", abs(va - VRA) / VRA < 1e-8 and np.max(np.abs(r.pos[:, 1, :] - PB)) < 1e-12,
                f"A's speed at the end {va:.12g} m/s against {VRA:.12g} (rel. {abs(va - VRA) / VRA:.1e}, < 1e-8); "
                f"B's centre kept to {np.max(np.abs(r.pos[:, 1, :] - PB)):.1e} m")
    ek0 = 0.5 * MA * VA**2 + 0.5 * JB * WB0**2
    el, ekin = r.energy["energy_coupling_elastic"], r.energy["energy_kinetic"]
    eres = np.max(np.abs(ekin + el - ek0)) / ek0
    stored = 0.5 * KA * DA**2 + 0.5 * KB * DB**2
    est = abs(el[-1] - stored) / stored
    rcval.check("spring_rupture.energy", eres < 1e-7 and est < 1e-6,
                f"kinetic + energy_coupling_elastic = initial kinetic to {eres:.1e} (< 1e-7); the elastic energy "
                f"kept after the ruptures {el[-1]:.9g} J against 1/2 K1 dmax1^2 + 1/2 K4 dmin4^2 = {stored:.9g} J "
                f"(rel. {est:.1e}, < 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
