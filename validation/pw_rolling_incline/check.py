"""A solid cylinder rolling down an incline (cylinder-plane, /INTER/POWER
with step5 friction): acceleration g sin(theta) / (1 + I/(m r^2)) without
slip, and slip beginning when tan(theta) exceeds 3 mu_s (docs/theory.md
9.4).

step5 friction is a function of the slip speed (mu(0) = 0): rolling needs a
small creep s* where mu(s*) F_n equals the friction that rolling requires,
f = m g sin(theta) I/(I + m r^2) (a third of m g sin(theta) for a solid
cylinder). Once the creep is steady, ds/dt = 0 and the centre accelerates at
exactly the rolling value. The largest friction step5 gives below v_s is
mu_s F_n (at s = v_s), so the creep exists while f <= mu_s m g cos(theta):
tan(theta) <= 3 mu_s. Beyond, the slip grows past v_d, mu = mu_d, and the
centre accelerates at g (sin(theta) - mu_d cos(theta)).

Checks (acceleration from a least-squares line through the velocity
records after the start-up, 1e-5 relative): case 1, tan(theta) = 0.95 (3
mu_s): rolling acceleration, creep below v_s; case 2, tan(theta) =
1.05 (3 mu_s): the slip passes v_d, sliding acceleration; the ledger.
"""
import math
import os
import sys

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

G = 9.81
M, R, L = 1.0, 0.05, 0.2
IAX = 0.5 * M * R * R                  # solid cylinder about its axis
MUS, VS, MUD, VD = 0.2, 1e-3, 0.15, 5e-3
KC = 1.0e9                             # Hertz-like stiffness [N/m^1.5]
T_END, T_FIT = 0.6, 0.1
CASES = (0.95, 1.05)                   # tan(theta) / (3 mu_s)


def deck(ratio):
    th = math.atan(ratio * 3.0 * MUS)
    n = np.array([math.sin(th), 0.0, math.cos(th)])      # plane normal; downhill is +X
    fn = M * G * math.cos(th)
    dq = (fn / KC) ** (1 / 1.5)                           # static penetration
    kq = 1.5 * KC * dq**0.5                               # contact stiffness there
    cc = 2 * 0.7 * math.sqrt(kq * M) / dq                 # damping ratio 0.7 (m2 = m3 = 1)
    c = (R - dq) * n
    d = Deck(f"solid cylinder on an incline, tan(theta) = {ratio} (3 mu_s)")
    d.nodes([(1, *c)])
    jt = M * (3 * R * R + L * L) / 12
    d.rbody(1, 1, M, (jt, IAX, jt), title="solid cylinder")
    d.grnod(1, [1])
    d.cylinder(1, 1, tuple(c), (0.0, 1.0, 0.0), R, L, title="cylinder, axis Y")
    d.plane(2, (0.0, 0.0, 0.0), tuple(n), title=f"incline {math.degrees(th):.4f} deg")
    d.grav(1, "Z", -G)
    d.power(1, 1, 2, k=KC, m1=1.5, c=cc, m2=1.0, m3=1.0, irdf=2, mus=MUS, vs=VS, mud=MUD, vd=VD,
            title="cylinder on incline")
    d.run(T_END, 0.002)
    d.solver(rtol=1e-10, atol_pos=1e-13, atol_vel=1e-10, atol_omega=1e-9, atol_energy=1e-10)
    return d, th


def main():
    for k, ratio in enumerate(CASES):
        _, th = deck(ratio)
        dirn = np.array([math.cos(th), 0.0, -math.sin(th)])   # downhill
        out = rcval.run_case(f"case{k + 1}.rad")
        r = rcval.Result(out)
        with Dataset(out) as nc:
            slip = np.array(nc["inter_slip_speed"][:, 0])
        sel = (r.t >= T_FIT) & (r.at_event == 0)
        v = r.vel[sel, 0, :] @ dirn
        a = np.polyfit(r.t[sel], v, 1)[0]
        res = abs(r.energy["energy_total"][-1] - r.energy["energy_total"][0]) / (0.5 * M * v[-1] ** 2)
        if ratio < 1:
            a_ref = G * math.sin(th) / (1 + IAX / (M * R * R))
            e = rcval.rel(a, a_ref)
            rcval.check("pw_rolling_incline.rolling", e < 1e-5 and slip[-1] < VS,
                        f"tan(theta) = {ratio} (3 mu_s): a = {a:.9f} m/s^2, g sin / (1 + I/(m r^2)) = {a_ref:.9f} "
                        f"(rel. {e:.1e} < 1e-5); creep {slip[-1]:.3e} m/s < v_s = {VS}")
        else:
            a_ref = G * (math.sin(th) - MUD * math.cos(th))
            late = r.t >= 0.5 * T_END
            a2 = np.polyfit(r.t[late & (r.at_event == 0)], r.vel[late & (r.at_event == 0), 0, :] @ dirn, 1)[0]
            e = rcval.rel(a2, a_ref)
            rcval.check("pw_rolling_incline.slipping", e < 1e-5 and slip[late].min() > VD,
                        f"tan(theta) = {ratio} (3 mu_s): slip grows to {slip[-1]:.3f} m/s (> v_d = {VD} from "
                        f"t = {r.t[np.argmax(slip > VD)]:.4f} s); a = {a2:.9f} m/s^2, g (sin - mu_d cos) = "
                        f"{a_ref:.9f} (rel. {e:.1e} < 1e-5)")
        rcval.check(f"pw_rolling_incline.ledger_{k + 1}", res < 1e-6,
                    f"|E_total(end) - E_total(0)| / E_kin(end) = {res:.1e} (< 1e-6); friction dissipated "
                    f"{r.energy['energy_friction'][-1]:.6e} J")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: {f"case{k + 1}.rad": deck(ratio)[0] for k, ratio in enumerate(CASES)})
