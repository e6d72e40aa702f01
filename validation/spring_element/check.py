"""/SPRING elements of a /PROP/TYPE4 (SPRING) linear spring-damper against the closed form.

Two systems in one deck written in Radioss's layout, without gravity, each
started by an initial velocity along its spring (a Radioss spring is at rest
at its initial length):
  A: a body (1.7 kg) on a damped spring to a node in no body (fixed in
     space): u(t) = v0/wd exp(-zeta wn t) sin(wd t), wn = sqrt(K/m);
  B: two bodies (0.8 and 1.3 kg plus half the spring's mass 0.06 kg each)
     joined by an undamped spring: the stretch is u(t) = v0/w sin(w t),
     w = sqrt(K/mu), mu = m2 m3/(m2 + m3), period 2 pi sqrt(mu/K); the
     momentum is conserved.
Checks the histories (max error below 1e-6 of the amplitude), the
half-period zero crossing of B, the momentum, that the error shrinks as
rtol shrinks, and the static analysis of a body hanging on a spring
element (z - z0 = -m g/K) (README.md).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

MA, KA, ZETA, VA = 1.7, 250.0, 0.05, 0.37
CA = 2.0 * ZETA * math.sqrt(KA * MA)
EA = np.array([0.48, -0.6, 0.64])          # fixed node -> body A
LA = 0.9
M2, M3, MS, KB, VB = 0.8, 1.3, 0.06, 120.0, 0.23
EB = np.array([0.0, 0.6, 0.8])             # body 2 -> body 3
LB = 0.75
P2 = np.array([3.0, 0.1, -0.2])
M2E, M3E = M2 + MS / 2, M3 + MS / 2        # half the spring's mass on each node
MU = M2E * M3E / (M2E + M3E)
WA = math.sqrt(KA / MA)
WB = math.sqrt(KB / MU)
T_END = 6 * 2 * math.pi / min(WA, WB)
MS_H, K_H, G = 0.73, 3700.0, 9.81          # the static case: mass, stiffness, gravity


def ref_a(t):
    wd = WA * math.sqrt(1 - ZETA**2)
    return VA / wd * np.exp(-ZETA * WA * t) * np.sin(wd * t)


def ref_b(t):
    return VB / WB * np.sin(WB * t)


def deck(rtol=1e-9):
    d = Deck("spring elements (TYPE4) oscillators")
    pa = LA * EA
    p3 = P2 + LB * EB
    d.nodes([(1, *pa), (9, 0.0, 0.0, 0.0), (2, *P2), (3, *p3)])
    d.rbody(1, 1, MA, [0.3, 0.4, 0.5], title="body A 1.7 kg")
    d.rbody(2, 2, M2, [0.2, 0.2, 0.2], title="body 2, 0.8 kg")
    d.rbody(3, 3, M3, [0.3, 0.3, 0.3], title="body 3, 1.3 kg")
    d.grnod(1, [1], title="body A")
    d.grnod(3, [3], title="body 3")
    d.inivel(1, tuple(VA * EA), 1)
    d.inivel(2, tuple(VB * EB), 3)
    # the springs in Radioss's layout: /PART -> /PROP/TYPE4, /SPRING/part_ID
    d.add("/PART/7", "#  prop_ID    mat_ID", line(("i", 3), ("i", 0)), title="damped spring to a fixed node")
    d.add("/PART/8", "#  prop_ID    mat_ID", line(("i", 4), ("i", 0)), title="spring between two bodies")
    d.add("/PROP/TYPE4/3",
          "#               Mass                                 sens_ID    Isflag     Ileng",
          line(("r", 0.0)) + " " * 30 + i10(0) + i10(0) + i10(0),
          "#                  K                   C                   A                   B                   D",
          line(("r", KA), ("r", CA), ("r", 1.0), ("r", 0.0), ("r", 1.0)),
          "#  fct_ID1         H   fct_ID2   fct_ID3   fct_ID4                          dmin                dmax",
          line(("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0)),
          "#                  F                   E              Ascale              Hscale",
          line(("r", 1.0), ("r", 0.0), ("r", 1.0), ("r", 1.0)), title="K = 250 N/m, zeta = 0.05")
    d.add("/PROP/SPRING/4",
          "#               Mass                                 sens_ID    Isflag     Ileng",
          line(("r", MS)),
          "#                  K                   C                   A                   B                   D",
          line(("r", KB), ("r", 0.0)), title="K = 120 N/m, mass 0.06 kg")
    d.add("/SPRING/7", "#  sprg_ID  node_ID1  node_ID2", line(("i", 71), ("i", 9), ("i", 1)))
    d.add("/SPRING/8", "#  sprg_ID  node_ID1  node_ID2", line(("i", 81), ("i", 2), ("i", 3)))
    d.run(T_END, T_END / 600)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_vel=rtol, atol_energy=1e-2 * rtol)
    return d


def deck_static():
    """A body hanging from a fixed node on a /SPRING (TYPE4) under gravity,
    solved by the static analysis (/SOLVER Method 3): z = z0 - m g / K."""
    d = Deck("spring element (TYPE4) under gravity, static")
    d.nodes([(1, 0.1, 0.2, 0.3), (9, 0.1, 0.2, 1.1)])
    d.rbody(1, 1, MS_H, [0.3, 0.4, 0.5], title="hanging body")
    d.grav(1, "Z", -G)
    d.add("/PART/7", line(("i", 3), ("i", 0)), title="spring")
    d.add("/PROP/TYPE4/3", line(("r", 0.0)), line(("r", K_H), ("r", 0.0)), title="K = 3700 N/m")
    d.add("/SPRING/7", line(("i", 71), ("i", 9), ("i", 1)))
    d.run(1.0, 0.25)
    d.solver(method=3)
    return d


def errors(path):
    r = rcval.Result(path)
    xa = r.pos[:, 0, :]
    ua = xa @ EA - LA
    ea = np.max(np.abs(ua - ref_a(r.t))) / (VA / WA)
    x2, x3 = r.pos[:, 1, :], r.pos[:, 2, :]
    ub = (x3 - x2) @ EB - LB
    eb = np.max(np.abs(ub - ref_b(r.t))) / (VB / WB)
    mom = M2E * r.vel[:, 1, :] + M3E * r.vel[:, 2, :]
    em = np.max(np.linalg.norm(mom - mom[0], axis=1)) / (M3E * VB)
    return r, ea, eb, em, ub


def main():
    r, ea, eb, em, ub = errors(rcval.run_case())
    rcval.check("spring_element.fixed_node", ea < 1e-6,
                f"body on a damped spring to a node in no body: max |u - u_exact| / (v0/wn) = {ea:.2e} "
                f"over {len(r.t)} outputs (< 1e-6)")
    rcval.check("spring_element.two_bodies", eb < 1e-6,
                f"two bodies on a spring with mass: max |u - u_exact| / (v0/w) = {eb:.2e} (< 1e-6)")
    # half period from the first sign change of the stretch after t = 0
    k = np.nonzero((ub[1:-1] > 0) & (ub[2:] <= 0))[0]
    if len(k):
        i = k[0] + 1
        t0 = r.t[i] - ub[i] * (r.t[i + 1] - r.t[i]) / (ub[i + 1] - ub[i])
        half = math.pi / WB
        err_t = abs(t0 - half) / half
        rcval.check("spring_element.period", err_t < 1e-4,
                    f"first return to the rest length at {t0:.9f} s, pi sqrt(mu/K) = {half:.9f} s "
                    f"(mu with half the spring's mass on each body), rel. error {err_t:.2e} "
                    f"(< 1e-4, linear interpolation between records)")
    else:
        rcval.check("spring_element.period", False, "no return to the rest length found")
    rcval.check("spring_element.momentum", em < 1e-9,
                f"momentum of the two bodies: max change {em:.2e} of m3 v0 (< 1e-9)")
    # the static analysis (whatever the mode: its /SOLVER kept, Method 3)
    method = rcval.METHOD
    rcval.METHOD = "static" if method else ""
    rs = rcval.Result(rcval.run_case("case_static.rad", keep_solver=True))
    rcval.METHOD = method
    dz = float(np.max(np.abs(rs.pos[1:, 0, 2] - (0.3 - MS_H * G / K_H))))
    rcval.check("spring_element.static", dz < 1e-9 * MS_H * G / K_H + 1e-15,
                f"static analysis of a body hanging on a spring element: z - z0 = -m g/K to {dz:.2e} m "
                f"(of m g/K = {MS_H * G / K_H:.4e} m, < 1e-9 of it)")
    errs = [max(errors(rcval.run(deck(rtol), keep_solver=True))[1:3]) for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("spring_element.convergence", errs[2] < errs[1] < errs[0],
                "max error / amplitude at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_static.rad": deck_static()})
