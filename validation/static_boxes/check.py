"""Static analysis (/SOLVER Method 3) and the preload with contacts of
several points: a box on a box on a floor (box-box: the corners of each
box against the faces of the other; box-plane: the box's 8 corners).

Two boxes, the lower (m_1 = 2 kg, half-sizes 0.2 x 0.15 x 0.05 m) on the
fixed floor z = 0 and the upper (m_2 = 1 kg, 0.1 x 0.08 x 0.03 m) on it,
0.01 m and 0.02 m off its centre, every contact exactly touching at t = 0;
both held sideways and against turning by /BCS (`110 111`: frictionless
boxes have no lateral support and nothing acts on their turning about the
vertical). TYPE6 linear load curves k = 1e6 N/m, no damping.

case.rad (Method 3): gravity g = 9.81 m/s^2 ramped by f(t) = t / t_end;
output every 0.25 s. At each output time the floor carries (m_1 + m_2) g f
and the box-box contact m_2 g f; with the law at the deepest corner (all
four bottom corners at one depth), P_floor = (m_1 + m_2) g f / k and
P_box = m_2 g f / k, and the upper box's centre sits at its start less
P_floor + P_box.
case_preload.rad (Method 1, Preload 1, constant gravity): the dynamic run
starts from the static equilibrium: the same forces and penetrations at
f = 1 from the first record to the end (1 s), the velocities at rounding.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M1, M2, G, K = 2.0, 1.0, 9.81, 1.0e6
H1 = (0.2, 0.15, 0.05)
H2 = (0.1, 0.08, 0.03)
C1 = (0.0, 0.0, H1[2])
C2 = (0.01, 0.02, 2.0 * H1[2] + H2[2])
T_END, DT_OUT = 1.0, 0.25
TOL = 1e-9


def deck(preload):
    d = Deck("static boxes: a box on a box on a floor" + (", preloaded dynamic run" if preload else ", ramped gravity"))
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.nodes([(1, *C1), (2, *C2)])
    d.rbody(1, 1, M1, [0.01, 0.02, 0.03], grnod=1, title="lower box")
    d.rbody(2, 2, M2, [0.004, 0.005, 0.006], grnod=2, title="upper box")
    d.box(1, 1, C1, H1, title="lower box")
    d.box(2, 2, C2, H2, title="upper box")
    d.plane(3, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1], title="lower")
    d.grnod(2, [2], title="upper")
    d.grnod(3, [1, 2], title="both boxes")
    d.bcs(1, 3, "110 111", title="held sideways and against turning")
    if preload:
        d.grav(1, "Z", -G)
    else:
        d.funct(2, [0.0, T_END], [0.0, 1.0], title="gravity ramp f(t) = t / t_end")
        d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 3, 1, title="lower box - floor")
    d.type6(2, 2, 1, 1, title="upper box - lower box")
    d.run(T_END, DT_OUT)
    if preload:
        d.solver(method=1, rtol=1e-8, preload=1)
    else:
        d.solver(method=3)
    return d


def errors(r, f):
    """max relative errors of the forces and penetrations of the two contacts,
    and of the upper box's height, against the closed forms at load f."""
    F = np.column_stack([(M1 + M2) * G * f, M2 * G * f])
    P = F / K
    eF = float(np.abs(r.fn - F).max()) / ((M1 + M2) * G)
    eP = float(np.abs(r.pen - P).max()) / ((M1 + M2) * G / K)
    z2 = C2[2] - P[:, 0] - P[:, 1]
    ez = float(np.abs(r.pos[:, 1, 2] - z2).max()) / ((M1 + M2) * G / K)
    return eF, eP, ez


def main():
    keep = rcval.METHOD
    rcval.METHOD = "static" if keep else ""
    r = rcval.Result(rcval.run_case("case.rad", keep_solver=True))
    eF, eP, ez = errors(r, r.t / T_END)
    rcval.check("static_boxes.ramp", len(r.t) == 5 and max(eF, eP, ez) < TOL,
                f"{len(r.t)} records: max |F - F_ref| / ((m_1 + m_2) g) {eF:.2e}, |P - P_ref| / ((m_1 + m_2) g / k) "
                f"{eP:.2e}, upper box height {ez:.2e} (< {TOL:g}); at f = 1: F {r.fn[-1, 0]:.12g} N, "
                f"{r.fn[-1, 1]:.12g} N (closed form {(M1 + M2) * G:.12g}, {M2 * G:.12g})")
    rcval.METHOD = keep
    r = rcval.Result(rcval.run_case("case_preload.rad", keep_solver=True))
    eF, eP, ez = errors(r, np.ones_like(r.t))
    vmax = float(np.abs(r.vel).max())
    vb = 1e-9 * G * (1.0 / np.sqrt(K / M1))
    rcval.check("static_boxes.preload", r.t[-1] == T_END and max(eF, eP, ez) < 1e-8 and vmax < vb,
                f"{len(r.t)} records to {r.t[-1]:g} s: max rel. errors F {eF:.2e}, P {eP:.2e}, height {ez:.2e} "
                f"(< 1e-8); max |v| {vmax:.2e} m/s (< {vb:.2e}: 1e-9 g / omega, omega = sqrt(k / m_1))")
    rcval.finish()


def cases():
    return {"case.rad": deck(False), "case_preload.rad": deck(True)}


if __name__ == "__main__":
    rcval.entry(main, cases)
