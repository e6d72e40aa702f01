"""Roller driven at a constant angular speed (/IMPVEL YY) on a block held by
a spring-damper (/COUPLING/SPRING): the traction against the step5 friction
law at the resulting slip speed, and f_max capping it (docs/theory.md
9.4).

The roller (cylinder, axis Y) presses on the block (box) by its weight; its
X and Y translations are held (/BCS 110 000), its rotation imposed. The
block slides along X only (/BCS 011 111) on a spring to a fixed point. In
the steady state the block is at rest, the slip speed is omega r and the
spring balances the friction: k_s u = mu(omega r) m g (or f_max).

Checks, at the end of the run (the transients have decayed):
the friction force against mu(v_slip) F_n (capped: the drive is ramped up
so that the traction reaches f_max during the run, a fric_saturate event) from the recorded slip speed and
normal force (step5 law evaluated here, independently), the slip speed
against omega r, the spring force against mu(omega r) m g, the four regimes
(below v_s, between v_s and v_d, beyond v_d, capped by f_max), and the
energy ledger with the drive's work.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import laws  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G = 9.81
MR, R, L = 2.0, 0.02, 0.1             # roller mass [kg], radius, length [m]
MB = 10.0                              # block mass [kg]
KS, KD = 1.0e4, 200.0                  # spring [N/m], damper [N s/m]
MUS, VS, MUD, VD = 0.3, 0.01, 0.2, 0.05
KC, CC = 1.0e9, 5.0e8                  # contact: K [N/m^1.5], C [N s/m^2] (m2 = m3 = 1): damping ratio ~0.6
# (omega r [m/s], f_max [N])
CASES = ((0.004, 0.0), (0.03, 0.0), (0.2, 0.0), (0.2, 3.0))
T_END = 3.0


def mu(v):
    """step5 friction (docs/theory.md 9.4): step5(v, -v_s, -mu_s, v_s, mu_s) below v_s, step5(v, v_s, mu_s, v_d, mu_d) beyond."""
    return laws.step5_mu(v, MUS, VS, MUD, VD)


def deck(vr, fmax):
    d = Deck(f"roller at omega r = {vr} m/s on a block held by a spring, f_max = {fmax} N")
    zr = R - (MR * G / KC) ** (1 / 1.5)  # resting on the block's top face (z = 0)
    d.nodes([(1, 0.0, 0.0, zr), (2, 0.0, 0.0, -0.025)])
    jr = (MR * (3 * R * R + L * L) / 12, 0.5 * MR * R * R, MR * (3 * R * R + L * L) / 12)
    d.rbody(1, 1, MR, jr, title="roller")
    d.rbody(2, 2, MB, (0.1, 0.2, 0.3), title="block")
    d.grnod(1, [1], title="roller")
    d.grnod(2, [2], title="block")
    d.cylinder(1, 1, (0.0, 0.0, zr), (0.0, 1.0, 0.0), R, L, title="roller")
    d.box(2, 2, (0.0, 0.0, -0.025), (0.2, 0.1, 0.025), title="block")
    if fmax > 0:  # ramped drive: the traction rises through f_max (an event)
        d.funct(1, (0.0, 1.0, 100.0), (0.0, 1.0, 1.0), title="ramp to 1 over 1 s")
    else:
        d.funct(1, (0.0, 100.0), (1.0, 1.0), title="constant")
    d.impvel(1, 1, "YY", 1, fscale=vr / R, title="drive")
    d.add("/BCS/1", f"{'110 000':>10s}{0:>10d}{1:>10d}", title="roller: X, Y held")
    d.add("/BCS/2", f"{'011 111':>10s}{0:>10d}{2:>10d}", title="block: slides along X")
    d.spring(1, 2, (0.0, 0.0, -0.025), 0, (1.0, 0.0, -0.025), iform=1, kd=KD, a=KS, title="block spring")
    d.grav(1, "Z", -G, grnod=1)
    d.power(1, 1, 2, k=KC, m1=1.5, c=CC, m2=1.0, m3=1.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD,
            fmax=fmax if fmax > 0 else None, title="roller on block")
    d.run(T_END, 0.01)
    d.solver(rtol=1e-9, atol_pos=1e-12, atol_vel=1e-9, atol_omega=1e-9, atol_energy=1e-9)
    return d


def main():
    for k, (vr, fmax) in enumerate(CASES):
        out = rcval.run_case(f"case{k + 1}.rad")
        r = rcval.Result(out)
        with Dataset(out) as nc:
            ff = np.array(nc["inter_force_friction"][-1, 0, :])
            vs = float(nc["inter_slip_speed"][-1, 0])
            fn = float(nc["inter_force_normal"][-1, 0])
            fs = float(nc["coupling_force"][-1, 0])
        ft = float(np.linalg.norm(ff))
        law = min(mu(vs) * fn, fmax) if fmax > 0 else mu(vs) * fn
        expect = min(mu(vr), fmax / (MR * G)) * MR * G if fmax > 0 else mu(vr) * MR * G
        e1, e2, e3 = rcval.rel(ft, law), rcval.rel(vs, vr), rcval.rel(abs(fs), expect)
        regime = ("capped by f_max" if fmax > 0 else "below v_s" if vr < VS else "v_s..v_d" if vr < VD else "beyond v_d")
        ncap = len(r.events("fric_saturate"))
        rcval.check(f"pw_roller_traction.{k + 1}", e1 < 1e-6 and e2 < 1e-6 and e3 < 1e-6 and (ncap == 1) == (fmax > 0),
                    f"{regime} ({ncap} cap events): traction {ft:.8f} N vs mu(v) F_n {law:.8f} N (rel. {e1:.1e}); slip {vs:.8f} m/s vs "
                    f"omega r {vr} (rel. {e2:.1e}); spring {abs(fs):.8f} N vs mu(omega r) m g "
                    f"{expect:.8f} N (rel. {e3:.1e})")
        e = r.energy
        res = abs(e["energy_total"][-1] - e["energy_total"][0]) / abs(e["energy_imposed"][-1])
        rcval.check(f"pw_roller_traction.ledger_{k + 1}", res < 1e-6,
                    f"drive work {-e['energy_imposed'][-1]:.6f} J = friction {e['energy_friction'][-1]:.6f} J + "
                    f"damping {e['energy_damping'][-1] + e['energy_coupling_damping'][-1]:.6f} J + stored; "
                    f"|E_total(end) - E_total(0)| / drive work = {res:.1e} (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {f"case{k + 1}.rad": deck(vr, fmax) for k, (vr, fmax) in enumerate(CASES)})
