"""/SPRING elements of a /PROP/TYPE13 (SPR_BEAM) beam spring, and of a
/PROP/TYPE8 (SPR_GENE) general spring in a /SKEW/MOV frame, against the
closed forms.

case.rad, without gravity, in Radioss's layout:
  A: translation. A body (1.7 kg) on a TYPE13 spring of length 0.4 m from a
     node fixed in space, started at v0 along the spring's X' axis (node 1
     -> node 2), K1 = 250 N/m, C1 = 2 zeta sqrt(K1 m), zeta = 0.05:
     u(t) = v0/wd exp(-zeta wn t) sin(wd t), wn = sqrt(K1/m);
  B: torsion of two free bodies (isotropic inertias J1 = 0.2, J2 = 0.3
     kg m^2) joined by a TYPE13 spring of length 0.5 m along X', spun
     about X' in opposite senses (no angular momentum), K4 = 2 N m/rad: the
     twist psi obeys psi'' = -K4 (1/J1 + 1/J2) sin(psi) (the potential
     K4/2 (2 sin(psi/2))^2), within psi0^2/16 of the linear
     psi(t) = W0/wr sin(wr t), wr = sqrt(K4 (J1 + J2)/(J1 J2)), for the
     amplitude psi0 = 1e-4 rad; the frame turns with body 1.
  C: shear and bending. A body (mass 0.6 kg, J = 0.05 kg m^2 about Z) at
     node 1 of a TYPE13 spring of length L = 0.3 m along X to a node fixed
     in space, K2 = 80 N/m, K6 = 1.5 N m/rad; the frame turns with the
     body, so its lateral offset y and turn theta about Z deform the spring
     by u2 = -(y + L theta) (to first order) and theta: the two-degree-of-
     freedom system m y'' = -K2 (y + L theta), J theta'' = -K2 L (y + L
     theta) - K6 theta (the cantilever coupling, docs/theory.md 8.1),
     started at v0 = 1e-4 m/s along Y, solved by its modes.
case_mov.rad: a turntable spun at Omega = 2 rad/s about Z (/IMPVEL, its
  centre held by /BCS) carries a /SKEW/MOV (its three nodes on the
  turntable); a rider (1 kg) rides on a zero-length TYPE8 spring in that
  frame from a node of the turntable at radius R = 0.5 m, with K1 = 100
  N/m radially, K2 = 400 N/m tangentially, 2 % damping, started moving with
  its node. In the turning frame its offset (x, y) obeys the linear system
    x'' = -k1 x - c1 x' + 2 Omega y' + Omega^2 (R + x),
    y'' = -k2 y - c2 y' - 2 Omega x' + Omega^2 y        (k = K/m, c = C/m)
  solved exactly (matrix exponential); a frame fixed in space would give
  the rider the stiffness K1 radially only at t = 0.
Checks the histories, the period of B, the unexcited directions, the energy
ledger of case.rad, and convergence in rtol (README.md).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

# A: the spring's axis, Y' the global Y made normal to it, Z' = X' x Y'
NA = np.array([0.6, 0.0, 0.8])
YA = np.array([0.0, 1.0, 0.0])
ZA = np.cross(NA, YA)
MA, KA, ZETA, VA, LA = 1.7, 250.0, 0.05, 0.37, 0.4
CA = 2.0 * ZETA * math.sqrt(KA * MA)
WA = math.sqrt(KA / MA)
PA = np.array([0.3, -0.2, 0.5])
# B: two bodies along NB
NB = np.array([0.0, 0.6, 0.8])
J1, J2, KB, LB = 0.2, 0.3, 2.0, 0.5
WB = math.sqrt(KB * (J1 + J2) / (J1 * J2))
W0 = 1e-4 * WB                                   # the twist rate at t = 0: amplitude 1e-4 rad
PB1 = np.array([2.0, 1.0, -0.5])
PB2 = PB1 + LB * NB
# C: shear and bending
MC, JC, KC2, KC6, LC, VC = 0.6, 0.05, 80.0, 1.5, 0.3, 1e-4
PC = np.array([-1.0, 0.5, 1.5])
T_END = 8 * 2 * math.pi / min(WA, WB)
# D: the turntable and the rider
OM, RD, MD = 2.0, 0.5, 1.0
K1D, K2D, K3D, ZD = 100.0, 400.0, 300.0, 0.02
C1D, C2D = 2 * ZD * math.sqrt(K1D * MD), 2 * ZD * math.sqrt(K2D * MD)
OT = np.array([0.0, 0.0, -3.0])
T_MOV = 3 * 2 * math.pi / OM


def damped(v0, w, z, t):
    wd = w * math.sqrt(1 - z**2)
    return v0 / wd * np.exp(-z * w * t) * np.sin(wd * t)


def prop(k, c, skew=0, beam=True):
    """The property's lines: line 1 (TYPE13: Mass I Skew_ID sens_ID Isflag
    Ifail Ileng Ifail2; TYPE8: ... Ifail2 Iequil), per direction K C A B D,
    the curves line (none), F E Ascale Hscale; TYPE13: V0 W0 Fcut Fsmooth
    and the six failure lines (no failure)."""
    h = "    Ileng    Ifail2" if beam else "   Ifail2    Iequil"
    lines = ["#               Mass                   I   Skew_ID   sens_ID    Isflag     Ifail" + h,
             line(("r", 0.0), ("r", 0.0), ("i", skew), ("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0))]
    for i in range(6):
        lines += [f"#                 K{i + 1}                  C{i + 1}                  A{i + 1}                  B{i + 1}"
                  f"                  D{i + 1}",
                  line(("r", k[i]), ("r", c[i]), ("r", 1.0), ("r", 0.0), ("r", 1.0)),
                  line(("i", 0), ("i", 0), ("i", 0), ("i", 0), ("i", 0)),
                  line(("r", 1.0), ("r", 0.0), ("r", 1.0), ("r", 1.0))]
    if beam:
        lines += ["#                 V0                  W0                Fcut   Fsmooth",
                  line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("i", 0))]
        lines += [line(("r", 0.0), ("r", 0.0), ("r", 0.0), ("r", 0.0)) for _ in range(6)]
    return lines


def solver(d, rtol):
    d.solver(rtol=rtol, atol_pos=1e-3 * rtol, atol_quat=1e-3 * rtol, atol_vel=1e-3 * rtol, atol_omega=1e-3 * rtol,
             atol_energy=1e-4 * rtol)


def deck(rtol=1e-10):
    d = Deck("beam spring elements (TYPE13) oscillators")
    d.nodes([(1, *PA), (91, *(PA - LA * NA)), (2, *PB1), (3, *PB2), (4, *PC), (94, *(PC + [LC, 0, 0]))])
    d.rbody(1, 1, MA, [0.3, 0.4, 0.5], title="body A 1.7 kg")
    d.rbody(2, 2, 0.9, [J1, J1, J1], title="body B1, J 0.2 kg m2")
    d.rbody(3, 3, 1.2, [J2, J2, J2], title="body B2, J 0.3 kg m2")
    d.rbody(4, 4, MC, [0.04, 0.045, JC], title="body C, J 0.05 kg m2 about Z")
    for g in (1, 2, 3, 4):
        d.grnod(g, [g], title=f"node {g}")
    d.inivel(1, tuple(VA * NA), 1)
    d.inivel(2, tuple(-W0 * J2 / (J1 + J2) * NB), 2, rot=True)
    d.inivel(3, tuple(W0 * J1 / (J1 + J2) * NB), 3, rot=True)
    d.inivel(4, (0.0, VC, 0.0), 4)
    d.add("/PART/7", "#  prop_ID    mat_ID", line(("i", 7), ("i", 0)), title="beam spring A")
    d.add("/PART/8", "#  prop_ID    mat_ID", line(("i", 8), ("i", 0)), title="beam spring B")
    d.add("/PROP/TYPE13/7", *prop([KA, 400.0, 600.0, 10.0, 20.0, 30.0], [CA, 0, 0, 0, 0, 0]),
          title="translation, K1 = 250 N/m, zeta 0.05")
    d.add("/PROP/SPR_BEAM/8", *prop([1000.0, 1000.0, 1000.0, KB, 50.0, 50.0], [0] * 6),
          title="torsion, K4 = 2 N m/rad")
    d.add("/PART/9", "#  prop_ID    mat_ID", line(("i", 9), ("i", 0)), title="beam spring C")
    d.add("/PROP/TYPE13/9", *prop([500.0, KC2, 500.0, 3.0, 4.0, KC6], [0] * 6),
          title="shear K2 = 80 N/m, bending K6 = 1.5 N m/rad")
    d.add("/SPRING/7", "#  sprg_ID  node_ID1  node_ID2", line(("i", 71), ("i", 91), ("i", 1)))
    d.add("/SPRING/9", "#  sprg_ID  node_ID1  node_ID2", line(("i", 91 + 1), ("i", 4), ("i", 94)))
    d.add("/SPRING/8", "#  sprg_ID  node_ID1  node_ID2", line(("i", 81), ("i", 2), ("i", 3)))
    d.run(T_END, T_END / 800)
    solver(d, rtol)
    return d


def deck_mov(rtol=1e-10, fixed=False):
    """fixed: the frame a /SKEW/FIX with the same axes at t = 0 (the
    contrast: a frame that does not turn with the turntable)."""
    d = Deck("general spring (TYPE8) in a /SKEW/MOV frame on a turntable")
    d.nodes([(4, *OT), (41, *(OT + [RD, 0, 0])), (42, *(OT + [0, RD, 0])), (5, *(OT + [RD, 0, 0]))])
    d.grnod(4, [4], title="turntable")
    d.grnod(40, [41, 42], title="turntable's frame nodes")
    d.grnod(5, [5], title="rider")
    d.rbody(4, 4, 10.0, [1.0, 1.0, 2.0], grnod=40, title="turntable")
    d.rbody(5, 5, MD, [0.01, 0.01, 0.01], title="rider 1 kg")
    d.bcs(1, 4, "111 000", title="turntable's centre held")
    d.funct(1, [0.0, 100.0], [1.0, 1.0], title="constant")
    d.impvel(1, 1, "ZZ", 4, fscale=OM, title="turntable spin 2 rad/s")
    d.inivel(5, (0.0, OM * RD, 0.0), 5)
    d.inivel(6, (0.0, 0.0, OM), 5, rot=True)
    if fixed:
        d.add("/SKEW/FIX/6", line(("r", 0.0), ("r", 0.0), ("r", 0.0)), line(("r", 0.0), ("r", 1.0), ("r", 0.0)),
              line(("r", 0.0), ("r", 0.0), ("r", 1.0)), title="fixed frame")
    else:
        d.add("/SKEW/MOV/6", "#  node_ID1  node_ID2  node_ID3       Dir",
              line(("i", 4), ("i", 41), ("i", 42), ("i", None)), title="turntable frame")
    d.add("/PART/9", "#  prop_ID    mat_ID", line(("i", 9), ("i", 0)), title="rider's spring")
    d.add("/PROP/TYPE8/9", *prop([K1D, K2D, K3D, 5.0, 5.0, 5.0], [C1D, C2D, 0, 0, 0, 0], skew=6, beam=False),
          title="K1 100 N/m radial, K2 400 N/m tangential")
    d.add("/SPRING/9", "#  sprg_ID  node_ID1  node_ID2", line(("i", 91), ("i", 41), ("i", 5)))
    d.run(T_MOV, T_MOV / 600)
    solver(d, rtol)
    return d


def twist(q1, q2, axis):
    """The turn of body 2 relative to body 1 about `axis` [rad]: q2 q1^*."""
    w1, v1 = q1[:, 0], q1[:, 1:]
    w2, v2 = q2[:, 0], q2[:, 1:]
    w = w2 * w1 + np.sum(v2 * v1, 1)
    v = w1[:, None] * v2 - w2[:, None] * v1 - np.cross(v2, v1)
    return 2.0 * np.arctan2(v @ axis, w)


def modes(M, K, x0, v0, t):
    """The undamped linear system M q'' = -K q from q(0) = x0, q'(0) = v0."""
    n = len(x0)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n] = -np.linalg.solve(M, K)
    lam, V = np.linalg.eig(A)
    c0 = np.linalg.solve(V, np.concatenate([x0, v0]))
    return (V[None, :, :] * (c0[None, :] * np.exp(np.outer(t, lam)))[:, None, :]).sum(2).real[:, :n], \
        np.sort(np.abs(lam.imag))[::2]


def shear_bending(t):
    M = np.diag([MC, JC])
    K = np.array([[KC2, KC2 * LC], [KC2 * LC, KC2 * LC**2 + KC6]])
    return modes(M, K, np.zeros(2), np.array([VC, 0.0]), t)


def rider_exact(t):
    """The rider's offset (x, y) in the turning frame: s' = A s + b, s(0) = 0."""
    k1, k2, c1, c2 = K1D / MD, K2D / MD, C1D / MD, C2D / MD
    A = np.array([[0, 0, 1, 0], [0, 0, 0, 1], [OM**2 - k1, 0, -c1, 2 * OM], [0, OM**2 - k2, -2 * OM, -c2]])
    b = np.array([0, 0, OM**2 * RD, 0])
    sp = -np.linalg.solve(A, b)
    lam, V = np.linalg.eig(A)
    c0 = np.linalg.solve(V, -sp)
    s = (V[None, :, :] * (c0[None, :] * np.exp(np.outer(t, lam)))[:, None, :]).sum(2).real + sp
    return s[:, 0], s[:, 1], sp[0]


def errors(path):
    r = rcval.Result(path)
    ua = (r.pos[:, 0, :] - PA) @ NA
    ea = np.max(np.abs(ua - damped(VA, WA, ZETA, r.t))) / (VA / WA)
    off_a = np.max(np.abs((r.pos[:, 0, :] - PA) @ np.stack([YA, ZA], 1))) / (VA / WA)
    psi = twist(r.quat[:, 1, :], r.quat[:, 2, :], NB)
    eb = np.max(np.abs(psi - damped(W0, WB, 0.0, r.t))) / (W0 / WB)
    off_b = max(np.max(np.abs(r.pos[:, 1, :] - PB1)), np.max(np.abs(r.pos[:, 2, :] - PB2)))
    q, _ = shear_bending(r.t)
    yc = r.pos[:, 3, 1] - PC[1]
    thc = 2.0 * np.arctan2(r.quat[:, 3, 3], r.quat[:, 3, 0])
    scale = np.max(np.abs(q[:, 0]))
    ec = max(np.max(np.abs(yc - q[:, 0])) / scale, np.max(np.abs(thc - q[:, 1])) / np.max(np.abs(q[:, 1])))
    return r, ea, eb, psi, off_a, off_b, ec


def errors_mov(path):
    r = rcval.Result(path)
    c, s = np.cos(OM * r.t), np.sin(OM * r.t)
    p = r.pos[:, 1, :] - OT
    x = c * p[:, 0] + s * p[:, 1] - RD
    y = -s * p[:, 0] + c * p[:, 1]
    xe, ye, xss = rider_exact(r.t)
    err = max(np.max(np.abs(x - xe)), np.max(np.abs(y - ye))) / xss
    return r, err, xss, x, p[:, 2]


def main():
    r, ea, eb, psi, off_a, off_b, ec = errors(rcval.run_case())
    rcval.check("spring_beam.translation", ea < 1e-6,
                f"body on a damped TYPE13 spring along its axis X': max |u - u_exact| / (v0/wn) = {ea:.2e} "
                f"over {len(r.t)} outputs (< 1e-6)")
    rcval.check("spring_beam.torsion", eb < 1e-6,
                f"two bodies twisting on a TYPE13 spring about X': max |psi - psi_lin| / psi0 = {eb:.2e} "
                f"(< 1e-6; the sine's cubic term is psi0^2/16 = {1e-8 / 16:.1e} of it)")
    rcval.check("spring_beam.other_directions", off_a < 1e-9 and off_b < 1e-12,
                f"the unexcited directions stay at rest: body A off X' {off_a:.1e} of the amplitude, the centres "
                f"of B1 and B2 {off_b:.1e} m (< 1e-9, 1e-12)")
    _, w = shear_bending(np.zeros(1))
    rcval.check("spring_beam.shear_bending", ec < 1e-5,
                f"a body on a TYPE13 spring to a fixed node, shear K2 and bending K6 coupled through the frame "
                f"turning with it (modes {w[0]:.6g}, {w[1]:.6g} rad/s): max error of y and theta over the largest "
                f"of each {ec:.2e} (< 1e-5; second-order terms {VC / w[0] / LC:.0e} of it)")
    tc = rcval.down_crossings(r.t, psi)
    if len(tc) >= 2:
        per = float(np.mean(np.diff(tc)))
        err_t = abs(per - 2 * math.pi / WB) / (2 * math.pi / WB)
        rcval.check("spring_beam.period", err_t < 1e-6,
                    f"the twist's period {per:.9f} s over {len(tc) - 1} periods, 2 pi / sqrt(K4 (1/J1 + 1/J2)) = "
                    f"{2 * math.pi / WB:.9f} s, rel. error {err_t:.2e} (< 1e-6)")
    else:
        rcval.check("spring_beam.period", False, "fewer than two downward crossings of the twist")
    ek0 = 0.5 * MA * VA**2 + 0.5 * J1 * (W0 * J2 / (J1 + J2))**2 + 0.5 * J2 * (W0 * J1 / (J1 + J2))**2 + \
        0.5 * MC * VC**2
    el, dp = r.energy["energy_coupling_elastic"], r.energy["energy_coupling_damping"]
    ekin = r.energy["energy_kinetic"]
    eres = np.max(np.abs(ekin + el + dp - ek0)) / ek0
    rcval.check("spring_beam.energy", eres < 1e-6 and dp[-1] > 0.5 * 0.5 * MA * VA**2 and np.all(np.diff(dp) >= 0),
                f"kinetic + energy_coupling_elastic + energy_coupling_damping = initial kinetic to {eres:.1e} "
                f"(< 1e-6); dissipated {dp[-1]:.6g} J of {ek0:.6g} J, never decreasing")
    rm, em, xss, x, z = errors_mov(rcval.run_case("case_mov.rad"))
    rcval.check("spring_beam.moving_skew", em < 1e-6,
                f"rider on a TYPE8 spring in a /SKEW/MOV frame on a turntable at 2 rad/s: max |(x, y) - exact| / "
                f"x_ss = {em:.2e} over 3 turns (< 1e-6; x_ss = Omega^2 R/(K1/m - Omega^2) = {xss:.6g} m, x at the "
                f"end {x[-1]:.6g} m)")
    rcval.check("spring_beam.moving_skew_plane", np.max(np.abs(z)) < 1e-12,
                f"the rider stays in the turntable's plane: max |z| = {np.max(np.abs(z)):.1e} m (< 1e-12)")
    ef = errors_mov(rcval.run(deck_mov(fixed=True), keep_solver=True))[1]
    rcval.check("spring_beam.moving_skew_contrast", ef > 0.1,
                f"the same rider in a /SKEW/FIX frame with the turntable's axes at t = 0 departs from the turning-"
                f"frame solution by {ef:.2f} x_ss (> 0.1: the check tells a turning frame from a fixed one)")
    errs = [max(errors(rcval.run(deck(rtol), keep_solver=True))[1:3]) for rtol in (1e-6, 1e-8, 1e-10)]
    rcval.check("spring_beam.convergence", errs[2] < errs[1] < errs[0],
                "max error / amplitude at rtol 1e-6, 1e-8, 1e-10: " + ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {"case.rad": deck(), "case_mov.rad": deck_mov()})
