"""/SPRING elements of a /PROP/TYPE8 (SPR_GENE) general spring against the closed forms.

Two systems in one deck written in Radioss's layout, without gravity, each a
rigid body on a general spring to a node in no body (fixed in space), the
two nodes coincident (a zero-length spring, as TYPE8 allows), the spring's
frame a /SKEW/FIX turned away from the global axes:
  A: translation. A body (1.7 kg) started at v0 along the skew's X' axis on
     K1 = 250 N/m, C1 = 2 zeta sqrt(K1 m), zeta = 0.05:
     u(t) = v0/wd exp(-zeta wn t) sin(wd t), wn = sqrt(K1/m);
  B: rotation. A body with the isotropic inertia J = 0.2 kg m^2 started at
     omega0 along the skew's Z' axis on K6 = 3.2 N m/rad, C6 = 2 zeta_r
     sqrt(K6 J), zeta_r = 0.03: the turn phi about Z' obeys
     J phi'' + C6 phi' + K6 sin(phi) = 0 (the moment of the potential
     K6/2 (2 sin(phi/2))^2), within (phi0^2/16) of the linear
     phi(t) = omega0/wd exp(-zeta_r wr t) sin(wd t), wr = sqrt(K6/J), for
     the amplitude phi0 = omega0/wr = 1e-4 rad;
  C: undamped rotation (C = 0), its period 2 pi sqrt(J/K) and the energy
     kept in energy_coupling_elastic.
Checks the histories (max error below 1e-6 of the amplitude), the period of
C, that the other directions stay at rest, the energy ledger, and the static
analysis of a body hanging on a general spring (z - z0 = -m g/K3)
(README.md).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, i10, line  # noqa: E402

# the skew: Y' along V1, X' = Y' x V2, Z' = X' x Y'
V1 = np.array([0.48, -0.6, 0.64])
V2 = np.array([0.0, 0.0, 1.0])
EY = V1 / np.linalg.norm(V1)
EX = np.cross(EY, V2)
EX /= np.linalg.norm(EX)
EZ = np.cross(EX, EY)
MA, KA, ZETA, VA = 1.7, 250.0, 0.05, 0.37
CA = 2.0 * ZETA * math.sqrt(KA * MA)
JB, KB, ZB, WB0 = 0.2, 3.2, 0.03, 4e-4
CB = 2.0 * ZB * math.sqrt(KB * JB)
JC, KC, WC0 = 0.5, 8.0, 2e-4
WA = math.sqrt(KA / MA)
WB = math.sqrt(KB / JB)
WC = math.sqrt(KC / JC)
PA = np.array([0.432, -0.54, 0.576])
PB = np.array([3.0, 0.1, -0.2])
PC = np.array([-2.0, 1.0, 0.5])
T_END = 6 * 2 * math.pi / min(WA, WB, WC)


def damped(v0, w, z, t):
    wd = w * math.sqrt(1 - z**2)
    return v0 / wd * np.exp(-z * w * t) * np.sin(wd * t)


def prop(pid, k, c, title, skew=5):
    """/PROP/TYPE8 lines: Mass I Skew_ID ...; per direction K C A B D, the
    curves line (blank), F E Ascale Hscale."""
    lines = ["#               Mass                   I   Skew_ID   sens_ID    Isflag     Ifail    Ifail2    Iequil",
             line(("r", 0.0), ("r", 0.0), ("i", skew), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0))]
    for i in range(6):
        lines += [f"#                 K{i + 1}                  C{i + 1}                  A{i + 1}                  B{i + 1}"
                  f"                  D{i + 1}",
                  line(("r", k[i]), ("r", c[i]), ("r", 1.0), ("r", 0.0), ("r", 1.0)),
                  line(("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0)),
                  line(("r", 1.0), ("r", 0.0), ("r", 1.0), ("r", 1.0))]
    return lines


def deck(rtol=1e-9):
    d = Deck("general spring elements (TYPE8) oscillators")
    d.nodes([(1, *PA), (9, *PA), (2, *PB), (8, *PB), (3, *PC), (7, *PC)])
    d.rbody(1, 1, MA, [0.3, 0.4, 0.5], title="body A 1.7 kg")
    d.rbody(2, 2, 0.8, [JB, JB, JB], title="body B, J 0.2 kg m2")
    d.rbody(3, 3, 1.1, [JC, JC, JC], title="body C, J 0.5 kg m2")
    d.grnod(1, [1], title="body A")
    d.grnod(2, [2], title="body B")
    d.grnod(3, [3], title="body C")
    d.inivel(1, tuple(VA * EX), 1)
    d.inivel(2, tuple(WB0 * EZ), 2, rot=True)
    d.inivel(3, tuple(WC0 * EY), 3, rot=True)
    d.add("/SKEW/FIX/5", line(("r", 0.0), ("r", 0.0), ("r", 0.0)), line(*[("r", x) for x in V1]),
          line(*[("r", x) for x in V2]), title="spring frame")
    for pid in (7, 8, 9):
        d.add(f"/PART/{pid}", "#  prop_ID    mat_ID", line(("i", pid), ("i", 0)), title=f"general spring {pid}")
    d.add("/PROP/TYPE8/7", *prop(7, [KA, 400.0, 600.0, 10.0, 20.0, 30.0], [CA, 0, 0, 0, 0, 0], "A"),
          title="translation, K1 = 250 N/m, zeta 0.05")
    d.add("/PROP/SPR_GENE/8", *prop(8, [100.0, 100.0, 100.0, 5.0, 6.0, KB], [0, 0, 0, 0, 0, CB], "B"),
          title="rotation, K6 = 3.2 N m/rad, zeta 0.03")
    d.add("/PROP/TYPE8/9", *prop(9, [100.0, 100.0, 100.0, 5.0, KC, 6.0], [0] * 6, "C"),
          title="rotation, K5 = 8 N m/rad, undamped")
    d.add("/SPRING/7", "#  sprg_ID  node_ID1  node_ID2", line(("i", 71), ("i", 9), ("i", 1)))
    d.add("/SPRING/8", "#  sprg_ID  node_ID1  node_ID2", line(("i", 81), ("i", 8), ("i", 2)))
    d.add("/SPRING/9", "#  sprg_ID  node_ID1  node_ID2", line(("i", 91), ("i", 7), ("i", 3)))
    d.run(T_END, T_END / 600)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_quat=1e-2 * rtol, atol_vel=rtol, atol_omega=1e-2 * rtol,
             atol_energy=1e-4 * rtol)
    return d


MS_H, K_H, G = 0.73, 3700.0, 9.81          # the static case: mass, K3, gravity


def deck_static():
    """A body hanging on a zero-length TYPE8 spring (global frame) to a fixed
    node under gravity, solved by the static analysis (/SOLVER Method 3):
    z = z0 - m g / K3, no turn."""
    d = Deck("general spring element (TYPE8) under gravity, static")
    d.nodes([(1, 0.1, 0.2, 0.3), (9, 0.1, 0.2, 0.3)])
    d.rbody(1, 1, MS_H, [0.3, 0.4, 0.5], title="hanging body")
    d.grav(1, "Z", -G)
    d.add("/PART/7", line(("i", 3), ("i", 0)), title="spring")
    d.add("/PROP/TYPE8/3", *prop(3, [900.0, 1300.0, K_H, 5.0, 6.0, 7.0], [0] * 6, "static", skew=0), title="K3 = 3700 N/m")
    d.add("/SPRING/7", line(("i", 71), ("i", 9), ("i", 1)))
    d.run(1.0, 0.25)
    d.solver(method=3)
    return d


def turn(q, axis):
    """Turn about `axis` [rad] from the quaternions (w, x, y, z)."""
    return 2.0 * np.arctan2(q[:, 1:] @ axis, q[:, 0])


def errors(path):
    r = rcval.Result(path)
    ua = (r.pos[:, 0, :] - PA) @ EX
    ea = np.max(np.abs(ua - damped(VA, WA, ZETA, r.t))) / (VA / WA)
    off_a = np.max(np.abs((r.pos[:, 0, :] - PA) @ np.stack([EY, EZ], 1))) / (VA / WA)
    pb = turn(r.quat[:, 1, :], EZ)
    eb = np.max(np.abs(pb - damped(WB0, WB, ZB, r.t))) / (WB0 / WB)
    pc = turn(r.quat[:, 2, :], EY)
    ec = np.max(np.abs(pc - damped(WC0, WC, 0.0, r.t))) / (WC0 / WC)
    off_b = max(np.max(np.abs(r.pos[:, 1, :] - PB)), np.max(np.abs(r.quat[:, 1, 1:] @ np.stack([EX, EY], 1))))
    return r, ea, eb, ec, pc, off_a, off_b


def main():
    r, ea, eb, ec, pc, off_a, off_b = errors(rcval.run_case())
    rcval.check("spring_gene.translation", ea < 1e-6,
                f"body on a damped TYPE8 spring along the skew's X': max |u - u_exact| / (v0/wn) = {ea:.2e} "
                f"over {len(r.t)} outputs (< 1e-6)")
    rcval.check("spring_gene.rotation_damped", eb < 1e-6,
                f"body turning on a damped TYPE8 spring about the skew's Z': max |phi - phi_lin| / phi0 = {eb:.2e} "
                f"(< 1e-6; the sine's cubic term is phi0^2/16 = {1e-8 / 16:.1e} of it)")
    rcval.check("spring_gene.rotation", ec < 1e-6,
                f"undamped turn about the skew's Y': max |phi - phi_lin| / phi0 = {ec:.2e} (< 1e-6)")
    rcval.check("spring_gene.other_directions", off_a < 1e-9 and off_b < 1e-12,
                f"the unexcited directions stay at rest: body A off X' {off_a:.1e} of the amplitude, body B's "
                f"position and turn off Z' {off_b:.1e} (< 1e-9, 1e-12)")
    k = np.nonzero((pc[1:-1] > 0) & (pc[2:] <= 0))[0]
    if len(k):
        i = k[0] + 1
        t0 = r.t[i] - pc[i] * (r.t[i + 1] - r.t[i]) / (pc[i + 1] - pc[i])
        half = math.pi / WC
        err_t = abs(t0 - half) / half
        rcval.check("spring_gene.period", err_t < 1e-4,
                    f"first return of C to phi = 0 at {t0:.9f} s, pi sqrt(J/K5) = {half:.9f} s, rel. error "
                    f"{err_t:.2e} (< 1e-4, linear interpolation between records)")
    else:
        rcval.check("spring_gene.period", False, "no return to phi = 0 found")
    # the ledger: kinetic + elastic + damping = the initial kinetic energy
    ek0 = 0.5 * MA * VA**2 + 0.5 * JB * WB0**2 + 0.5 * JC * WC0**2
    el, dp = r.energy["energy_coupling_elastic"], r.energy["energy_coupling_damping"]
    ekin = r.energy["energy_kinetic"]
    eres = np.max(np.abs(ekin + el + dp - ek0)) / ek0
    # the damping drew (nearly) all of A's and B's energy by the end; C keeps its own
    rcval.check("spring_gene.energy", eres < 1e-6 and dp[-1] > 0.5 * 0.5 * MA * VA**2,
                f"kinetic + energy_coupling_elastic + energy_coupling_damping = initial kinetic to {eres:.1e} "
                f"(< 1e-6, the integration at rtol 1e-9); dissipated {dp[-1]:.6g} J of {ek0:.6g} J")
    # the static analysis (whatever the mode: its /SOLVER kept, Method 3)
    method = rcval.METHOD
    rcval.METHOD = "static" if method else ""
    rs = rcval.Result(rcval.run_case("case_static.rad", keep_solver=True))
    rcval.METHOD = method
    dz = float(np.max(np.abs(rs.pos[1:, 0, 2] - (0.3 - MS_H * G / K_H))))
    dxy = float(np.max(np.abs(rs.pos[1:, 0, :2] - [0.1, 0.2])))
    rcval.check("spring_gene.static", dz < 1e-9 * MS_H * G / K_H + 1e-15 and dxy < 1e-15,
                f"static analysis of a body hanging on a general spring: z - z0 = -m g/K3 to {dz:.2e} m "
                f"(of m g/K3 = {MS_H * G / K_H:.4e} m, < 1e-9 of it), x, y kept to {dxy:.1e} m")
    errs = [max(errors(rcval.run(deck(rtol), keep_solver=True))[1:4]) for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("spring_gene.convergence", errs[2] < errs[1] < errs[0],
                "max error / amplitude at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_static.rad": deck_static()})
