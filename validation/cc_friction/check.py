"""Tanh friction of the contact coupling: a 2 kg plate, 0.2 m square (bottom
meshed 2 x 2), rests in gravity on a fixed plane through a contact
coupling (d0 = 10 mm, k1 = 1e7 N/m^3, k2 = 2e4 N s/m^3) at its equilibrium
distance d_eq = d0 - m g/(A k1), and slides along x at v0 = 0.5 m/s. The
centre of mass lies in the plane of the faces and every face moves alike,
so the total normal force is m g and the friction is
  m dv/dt = -mu m g tanh(k_t v)        (mu = 0.3, k_t = 20 s/m);
at high speed it decelerates at mu g, near rest exponentially at
mu g k_t. Reference: that ODE solved here by scipy solve_ivp (DOP853,
rtol 1e-12), independently of ricochet; plus the closed form of its
first phase for a check of the reference itself:
  tanh(k v) ODE: sinh(k_t v(t)) = sinh(k_t v0) exp(-mu g k_t t).
The sliding distance and the friction dissipation of the ledger follow.
"""
import math
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import rcval  # noqa: E402
from ccplate import plate  # noqa: E402
from deck import Deck  # noqa: E402

M, SIDE, G, D0, K1, K2, MU, KT, V0 = 2.0, 0.2, 9.81, 0.01, 1.0e7, 2.0e4, 0.3, 20.0, 0.5
A = SIDE * SIDE
DEQ = D0 - M * G / (A * K1)
T_END = 0.4


def deck():
    d = Deck("contact coupling: a plate slides to rest with tanh friction")
    plate(d, M, SIDE, DEQ)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    d.grav(1, "Z", -G)
    d.inivel(1, (V0, 0.0, 0.0), 2)
    d.contact_coupling(1, 5, 2, D0, K1, K2, MU, KT, title="plate - floor, tanh friction")
    d.run(T_END, 0.005)
    return d


def reference(t):
    sol = solve_ivp(lambda _t, y: [y[1], -MU * G * math.tanh(KT * y[1])], (0.0, T_END), [0.0, V0],
                    method="DOP853", rtol=1e-12, atol=1e-15, t_eval=t, dense_output=True)
    return sol.y[0], sol.y[1]


def main():
    r = rcval.Result(rcval.run(deck()))
    x, v = r.pos[:, 0, 0], r.vel[:, 0, 0]
    xr, vr = reference(r.t)
    # the reference against its closed form
    vcf = np.arcsinh(np.sinh(KT * V0) * np.exp(-MU * G * KT * r.t)) / KT
    rcval.check("cc_friction.reference", np.max(np.abs(vr - vcf)) < 1e-10,
                f"solve_ivp against sinh(k_t v) = sinh(k_t v0) exp(-mu g k_t t): {np.max(np.abs(vr - vcf)):.1e} m/s")
    ev = np.max(np.abs(v - vr)) / V0
    ex = np.max(np.abs(x - xr)) / xr[-1]
    rcval.check("cc_friction.velocity", ev < 1e-6,
                f"v(t) at {len(r.t)} records against the tanh-friction ODE: max error {ev:.2e} of v0 (< 1e-6); "
                f"v(0.2 s) = {np.interp(0.2, r.t, v):.9f} m/s (reference {np.interp(0.2, r.t, vr):.9f})")
    rcval.check("cc_friction.distance", ex < 1e-6,
                f"sliding distance {x[-1]:.9f} m (reference {xr[-1]:.9f}); max error {ex:.2e} of it (< 1e-6)")
    zdev = np.max(np.abs(r.pos[:, 0, 2] - DEQ))
    rcval.check("cc_friction.level", zdev < 1e-9,
                f"the plate stays at d_eq = {DEQ:.9f} m (max deviation {zdev:.1e} m) and level")
    ediss = r.energy["energy_coupling_damping"][-1]
    ekin = 0.5 * M * (V0**2 - v[-1] ** 2)
    rcval.check("cc_friction.dissipation", abs(ediss - ekin) < 1e-6 * 0.5 * M * V0**2,
                f"dissipated by the coupling {ediss:.9f} J = kinetic energy lost {ekin:.9f} J")
    rcval.check_ledger("cc_friction.ledger", r, 1e-6)
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
