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

With friction per corner (TYPE6 Fric = mu = 0.3, stick stiffness Stiff =
K_t = 2e5 N/m), no /BCS (friction holds the box sideways and against
turning): the lower box alone (m = 2 kg) on the floor, gravity tilted by
theta from the vertical (/GRAV X and Z with one time function: the load
grows along a fixed direction):
case_incline.rad (Method 3, theta = 0.25 rad < atan(mu), f = t / t_end):
the box sticks: the floor carries F_n = m g cos(theta) f and the friction
force m g sin(theta) f against the slope (summed over the corners), and
the box has slid along x by F_t / K_t at the floor (the corners' unit
springs in parallel, each at its share; its centre moves by that plus its
tilt under the friction moment times its height).
case_incline_above.rad (theta = 0.35 rad > atan(mu)): no static
equilibrium once the load exceeds the friction limit (the engine's slip
test, with its bands): an error naming the sliding interface.
case_incline_preload.rad (Method 1, Preload 1, theta = 0.25, constant
gravity): the dynamic run starts held by the corners' static friction
forces and stays at rest.
case_slide.rad (Method 3): the box under gravity tilted 0.4 rad > atan(mu),
held by a horizontal spring (100 N/m) to a fixed point 1 m behind, the
load rising to f = 1 and falling to 0.2: its corners slide against the
spring (equilibria in slip), then stick again as the load falls: one
fric_slip and one fric_stick event.
case_stack_incline.rad (Method 3, theta = 0.25, f = t / t_end): the two
boxes stacked, friction per point on both contacts, no /BCS: the floor
contact's force on the lower box (normal and friction) carries the weight
of both, (m_1 + m_2) g f, the box-box contact's on the upper box m_2 g f,
as vectors (the lower box tilts by some 1e-6 rad under its corners'
friction moment, and the box-box contact plane with it).
"""
import math
import os
import re
import subprocess
import sys

import netCDF4
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
MU, KT = 0.3, 2.0e5
TH_BELOW, TH_ABOVE, TH_SLIDE = 0.25, 0.35, 0.4


def two_boxes(d):
    """The two boxes (bodies 1 and 2, surfaces 1 and 2, node groups 1 and 2)
    and the floor (surface 3)."""
    d.nodes([(1, *C1), (2, *C2)])
    d.rbody(1, 1, M1, [0.01, 0.02, 0.03], grnod=1, title="lower box")
    d.rbody(2, 2, M2, [0.004, 0.005, 0.006], grnod=2, title="upper box")
    d.box(1, 1, C1, H1, title="lower box")
    d.box(2, 2, C2, H2, title="upper box")
    d.plane(3, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1], title="lower")
    d.grnod(2, [2], title="upper")


def deck(preload):
    d = Deck("static boxes: a box on a box on a floor" + (", preloaded dynamic run" if preload else ", ramped gravity"))
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    two_boxes(d)
    d.grnod(3, [1, 2], title="both boxes")
    d.bcs(1, 3, "110 111", title="held sideways and against turning")
    if preload:
        d.grav(1, "Z", -G)
    else:
        d.funct(2, [0.0, T_END], [0.0, 1.0], title="gravity ramp f(t) = t / t_end")
        d.grav_fct(1, "Z", -G, 2)
    d.type6(1, 1, 3, 1, title="lower box - floor")
    d.type6(2, 2, 1, 1, title="upper box - lower box")
    return run_solver(d, preload)


def run_solver(d, preload):
    """/RUN, and /SOLVER: the static analysis, or CVODE from its preload."""
    d.run(T_END, DT_OUT)
    if preload:
        d.solver(method=1, rtol=1e-8, preload=1)
    else:
        d.solver(method=3)
    return d


def tilted(theta):
    """gravity's components per unit f, as written in the deck (12 digits)."""
    return float(f"{G * math.sin(theta):.12g}"), float(f"{-G * math.cos(theta):.12g}")


def box_on_floor(d):
    """The load curve, and box 1 (the lower box's size and place) alone on the floor z = 0."""
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.nodes([(1, *C1)])
    d.rbody(1, 1, M1, [0.01, 0.02, 0.03], grnod=1, title="box")
    d.box(1, 1, C1, H1, title="box")
    d.plane(3, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    d.grnod(1, [1], title="box")


def deck_incline(theta, preload):
    d = Deck(f"static boxes: a box with friction per corner, gravity tilted {theta:g} rad"
             + (", preloaded" if preload else ""))
    box_on_floor(d)
    gx, gz = tilted(theta)
    if preload:
        d.grav(1, "X", gx)
        d.grav(2, "Z", gz)
    else:
        d.funct(2, [0.0, T_END], [0.0, 1.0], title="load factor f(t) = t / t_end")
        d.grav_fct(1, "X", gx, 2)
        d.grav_fct(2, "Z", gz, 2)
    d.type6(1, 1, 3, 1, fric=MU, stiff=KT, title="box - floor")
    return run_solver(d, preload)


def deck_slide():
    """The box of case_incline under gravity tilted 0.4 rad > atan(mu),
    held by a horizontal spring (100 N/m) from its centre to a fixed point
    1 m behind it; the load factor rises to 1 and falls to 0.2."""
    d = Deck("static boxes: a box with friction per corner slides against a spring, sticks again")
    box_on_floor(d)
    d.funct(2, [0.0, 0.5 * T_END, T_END], [0.0, 1.0, 0.2], title="load factor f(t)")
    gx, gz = tilted(TH_SLIDE)
    d.grav_fct(1, "X", gx, 2)
    d.grav_fct(2, "Z", gz, 2)
    d.type6(1, 1, 3, 1, fric=MU, stiff=KT, title="box - floor")
    d.spring(2, 1, C1, 0, (C1[0] - 1.0, C1[1], C1[2]), iform=1, a=100.0, title="horizontal spring")
    d.run(T_END, 0.05)
    d.solver(method=3)
    return d


def deck_stack_incline(theta):
    d = Deck(f"static boxes: two boxes stacked, friction per point, gravity tilted {theta:g} rad")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear k = 1e6 N/m")
    d.funct(2, [0.0, T_END], [0.0, 1.0], title="load factor f(t) = t / t_end")
    two_boxes(d)
    gx, gz = tilted(theta)
    d.grav_fct(1, "X", gx, 2)
    d.grav_fct(2, "Z", gz, 2)
    d.type6(1, 1, 3, 1, fric=MU, stiff=KT, title="lower box - floor")
    d.type6(2, 2, 1, 1, fric=MU, stiff=KT, title="upper box - lower box")
    d.run(T_END, DT_OUT)
    d.solver(method=3)
    return d


def incline_errors(r, theta, f):
    gx, gz = tilted(theta)
    Fn, Ft = -M1 * gz * f, M1 * gx * f
    eN = float(np.abs(r.fn[:, 0] - Fn).max()) / (M1 * G)
    eT = float(max(np.abs(r.ffric[:, 0, 0] + Ft).max(), np.abs(r.ffric[:, 0, 1:]).max())) / (M1 * G)
    # the contact plane's slide: the centre's x less its tilt about y times
    # its height over the floor (the friction moment tips the box by
    # about 6e-6 rad: 0.6 % of the slide)
    q = r.quat[:, 0]
    xc = r.pos[:, 0, 0] - H1[2] * 2.0 * q[:, 2] * q[:, 0]
    ex = float(np.abs(xc - Ft / KT).max()) / (M1 * G / KT)
    return eN, eT, ex


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
    # friction per corner: sticks below atan(mu)
    rcval.METHOD = "static" if keep else ""
    r = rcval.Result(rcval.run_case("case_incline.rad", keep_solver=True))
    eN, eT, ex = incline_errors(r, TH_BELOW, r.t / T_END)
    rcval.check("static_boxes.incline_sticks", len(r.t) == 5 and max(eN, eT) < TOL and ex < 1e-8,
                f"theta = {TH_BELOW:g} rad < atan(mu): {len(r.t)} records; max |F_n - m g cos f|, |F_t - m g sin f| / "
                f"(m g) {eN:.2e}, {eT:.2e} (< {TOL:g}); slide at the floor |x - F_t / K_t| / (m g / K_t) {ex:.2e} "
                f"(< 1e-8: the tilt's correction to first order)")
    # above atan(mu): no equilibrium, the sliding interface named
    out = os.path.join(rcval.tmpdir(), "above.nc")
    p = subprocess.run([rcval.RICOCHET, "run", os.path.join(HERE, "case_incline_above.rad"), "-o", out, "-q",
                        "--method", "static"], capture_output=True, text=True)
    named = "friction can hold" in p.stderr and "/INTER/TYPE6/1 slides" in p.stderr
    mt = re.search(r"no static equilibrium at the load time t = ([0-9.eE+-]+) s", p.stderr)
    tf = float(mt.group(1)) if mt else float("nan")
    rcval.check("static_boxes.incline_slides", p.returncode == 3 and named and tf < 1e-3 * T_END,
                f"theta = {TH_ABOVE:g} rad > atan(mu): exit {p.returncode}, no equilibrium from the load time "
                f"{tf:.3g} s (f = {tf / T_END:.2g}: where the excess passes the slip test's band); message: "
                f"{p.stderr.strip()[:200]!r}")
    # two contacts of several points, each with friction per point
    r = rcval.Result(rcval.run_case("case_stack_incline.rad", keep_solver=True))
    with netCDF4.Dataset(r.path) as nc:
        normal = np.array(nc["inter_normal"][:])  # from a (the box above) to b
    gx, gz = tilted(TH_BELOW)
    f = r.t / T_END
    e, tilt = 0.0, float(np.abs(normal[:, :, 0]).max())
    for k, mass in ((0, M1 + M2), (1, M2)):
        # the contact's force on its upper body (-F_n n + F_t) carries the
        # weight above it: -mass g f, as a vector (the lower box tilts under
        # its corners' friction moment, and the box-box plane with it)
        force = -r.fn[:, k, None] * normal[:, k, :] + r.ffric[:, k, :]
        weight = mass * np.column_stack([gx * f, 0.0 * f, gz * f])
        e = max(e, float(np.abs(force + weight).max()))
    e /= (M1 + M2) * G
    rcval.check("static_boxes.stack_incline", len(r.t) == 5 and e < TOL,
                f"two stacked boxes, friction per point on both contacts, theta = {TH_BELOW:g} rad: the force of "
                f"each contact on the box above it against the weight it carries, max error / ((m_1 + m_2) g) "
                f"{e:.2e} (< {TOL:g}); the contact planes tilt by up to {tilt:.1e} rad")
    # sliding against a spring, then sticking: the events of the points
    r = rcval.Result(rcval.run_case("case_slide.rad", keep_solver=True))
    evs = [(round(float(t), 9), k) for t, k, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if k.startswith("fric_")]
    kinds = [k for _, k in evs]
    rcval.check("static_boxes.slide_events", r.t[-1] == T_END and kinds == ["fric_slip", "fric_stick"]
                and evs[0][0] < 0.5 * T_END < evs[1][0],
                f"{len(r.t)} records to {r.t[-1]:g} s; friction events {evs} (expected fric_slip while the load rises "
                f"past the friction limit, fric_stick once it falls)")
    # preloaded: held by the corners' static friction from the start
    rcval.METHOD = keep
    r = rcval.Result(rcval.run_case("case_incline_preload.rad", keep_solver=True))
    eN, eT, ex = incline_errors(r, TH_BELOW, np.ones_like(r.t))
    vmax = float(np.abs(r.vel).max())
    rcval.check("static_boxes.incline_preload", r.t[-1] == T_END and max(eN, eT, ex) < 1e-8 and vmax < 1e-9,
                f"{len(r.t)} records to {r.t[-1]:g} s: max rel. errors F_n {eN:.2e}, F_t {eT:.2e}, x {ex:.2e} "
                f"(< 1e-8); max |v| {vmax:.2e} m/s (< 1e-9)")
    rcval.finish()


def cases():
    return {"case.rad": deck(False), "case_preload.rad": deck(True),
            "case_incline.rad": deck_incline(TH_BELOW, False), "case_incline_above.rad": deck_incline(TH_ABOVE, False),
            "case_incline_preload.rad": deck_incline(TH_BELOW, True),
            "case_stack_incline.rad": deck_stack_incline(TH_BELOW), "case_slide.rad": deck_slide()}


if __name__ == "__main__":
    rcval.entry(main, cases)
