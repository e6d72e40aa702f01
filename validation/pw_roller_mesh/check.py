"""A power-law roller driven across a meshed workpiece (cylinder against a
segment surface in /INTER/POWER).

The problem of validation/pw_roller_traction with the block's contact
surface written as a mesh: its top face (0.4 x 0.2 m at z = 0) as a
/SURF/SEG of 20 x 10 quadrilaterals on the block's rigid body instead of
the analytic /SURF/BOX. The roller (cylinder R = 20 mm, axis Y, 2 kg)
is driven about its axis and presses by its weight; the block slides along
X on a spring. The roller meets the plane of the segment under its centre
(docs/theory.md 2.7), on a flat mesh the block's top plane. References, as
there (README.md): the steady traction k_s u = mu(omega r) m g (step5 law
evaluated here), the slip speed omega r, the recorded friction force
mu(v) F_n; and the analytic-box run of the same deck: the same result.
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
from deck import Deck, line  # noqa: E402

G = 9.81
MR, R, L = 2.0, 0.02, 0.1             # roller mass [kg], radius, length [m]
MB = 10.0                              # block mass [kg]
KS, KD = 1.0e4, 200.0                  # spring [N/m], damper [N s/m]
MUS, VS, MUD, VD = 0.3, 0.01, 0.2, 0.05
KC, CC = 1.0e9, 5.0e8                  # contact: K [N/m^1.5], C [N s/m^2]
CASES = (0.004, 0.2)                   # omega r [m/s]: below v_s, beyond v_d
NX, NY = 20, 10                        # top face quadrilaterals
T_END = 3.0


def mu(v):
    return laws.step5_mu(v, MUS, VS, MUD, VD)


def deck(vr, meshed):
    d = Deck(f"roller at omega r = {vr} m/s on a {'meshed' if meshed else 'box'} block held by a spring")
    zr = R - (MR * G / KC) ** (1 / 1.5)
    d.nodes([(1, 0.0, 0.0, zr), (2, 0.0, 0.0, -0.025)])
    jr = (MR * (3 * R * R + L * L) / 12, 0.5 * MR * R * R, MR * (3 * R * R + L * L) / 12)
    d.rbody(1, 1, MR, jr, title="roller")
    d.grnod(1, [1], title="roller")
    d.cylinder(1, 1, (0.0, 0.0, zr), (0.0, 1.0, 0.0), R, L, title="roller")
    if meshed:
        ids = {}
        nodes = []
        for i in range(NX + 1):
            for j in range(NY + 1):
                ids[(i, j)] = 1000 + i * (NY + 1) + j
                nodes.append((ids[(i, j)], -0.2 + 0.4 * i / NX, -0.1 + 0.2 * j / NY, 0.0))
        d.nodes(nodes)
        d.grnod(2, [2] + [n[0] for n in nodes], title="block and its top face nodes")
        d.rbody(2, 2, MB, (0.1, 0.2, 0.3), grnod=2, title="block")
        segs = [line(*[("i", v) for v in (k + 1, ids[(i, j)], ids[(i + 1, j)], ids[(i + 1, j + 1)], ids[(i, j + 1)])])
                for k, (i, j) in enumerate((i, j) for i in range(NX) for j in range(NY))]
        d.add("/SURF/SEG/2", *segs, title="block top face, 20 x 10 quadrilaterals")
    else:
        d.grnod(2, [2], title="block")
        d.rbody(2, 2, MB, (0.1, 0.2, 0.3), title="block")
        d.box(2, 2, (0.0, 0.0, -0.025), (0.2, 0.1, 0.025), title="block")
    d.funct(1, (0.0, 100.0), (1.0, 1.0), title="constant")
    d.impvel(1, 1, "YY", 1, fscale=vr / R, title="drive")
    d.add("/BCS/1", f"{'110 000':>10s}{0:>10d}{1:>10d}", title="roller: X, Y held")
    d.add("/BCS/2", f"{'011 111':>10s}{0:>10d}{2:>10d}", title="block: slides along X")
    d.spring(1, 2, (0.0, 0.0, -0.025), 0, (1.0, 0.0, -0.025), iform=1, kd=KD, a=KS, title="block spring")
    d.grav(1, "Z", -G, grnod=1)
    d.power(1, 1, 2, k=KC, m1=1.5, c=CC, m2=1.0, m3=1.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD,
            title="roller on block")
    d.run(T_END, 0.01)
    d.solver(rtol=1e-9, atol_pos=1e-12, atol_vel=1e-9, atol_omega=1e-9, atol_energy=1e-9)
    return d


def last(out):
    with Dataset(out) as nc:
        ff = np.array(nc["inter_force_friction"][-1, 0, :])
        vs = float(nc["inter_slip_speed"][-1, 0])
        fn = float(nc["inter_force_normal"][-1, 0])
        fs = float(nc["coupling_force"][-1, 0])
        x = np.array(nc["body_position"][:, 1, 0])
    return float(np.linalg.norm(ff)), vs, fn, fs, x


def main():
    for k, vr in enumerate(CASES):
        out = rcval.run_case(f"case{k + 1}.rad") if k == 0 else rcval.run(deck(vr, True), name="mesh")
        r = rcval.Result(out)
        ft, vs, fn, fs, x = last(out)
        law, expect = mu(vs) * fn, mu(vr) * MR * G
        e1, e2, e3 = rcval.rel(ft, law), rcval.rel(vs, vr), rcval.rel(abs(fs), expect)
        rcval.check(f"pw_roller_mesh.{k + 1}", e1 < 1e-6 and e2 < 1e-6 and e3 < 1e-6,
                    f"omega r = {vr} m/s on the meshed block: traction {ft:.8f} N vs mu(v) F_n {law:.8f} N (rel. {e1:.1e}); "
                    f"slip {vs:.8f} m/s vs omega r (rel. {e2:.1e}); spring {abs(fs):.8f} N vs mu(omega r) m g "
                    f"{expect:.8f} N (rel. {e3:.1e})")
        ref = rcval.run(deck(vr, False), name="box")
        ftb, vsb, fnb, fsb, xb = last(ref)
        dx = float(np.max(np.abs(x - xb)))
        e = abs(ft - ftb) / ftb + abs(fn - fnb) / fnb
        # the two runs differ by the integrators' error (the default rtol 1e-8
        # and the contact-scaled absolute tolerances), on either backend
        rcval.check(f"pw_roller_mesh.{k + 1}.vs_box", e < 1e-7 and dx < 1e-10,
                    f"against the analytic-box run: traction {ftb:.10f} N, normal {fnb:.10f} N (sum of rel. differences "
                    f"{e:.1e} < 1e-7); block path max |x_mesh - x_box| = {dx:.1e} m (< 1e-10)")
        en = r.energy
        res = abs(en["energy_total"][-1] - en["energy_total"][0]) / abs(en["energy_imposed"][-1])
        rcval.check(f"pw_roller_mesh.ledger_{k + 1}", res < 1e-6,
                    f"|E_total(end) - E_total(0)| / drive work = {res:.1e} (< 1e-6)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case1.rad": deck(CASES[0], True)})
