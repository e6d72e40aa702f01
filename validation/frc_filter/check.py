"""Friction filter (/FRICTION Ifiltr 1, 2, 3): the filtered force after a step.

A block (sphere R = 0.05 m, rotations locked) held in x and y sits on a belt
(a plane on a 1e12 kg body) moving at V = 10 m/s along x, with Coulomb
friction mu = 0.3 in the incremental form. From the moment t0 the contact
acts, the law's force jumps to mu F_n along the belt (the stick damper's
force c_t V = 2e4 N is beyond the limit at once, so it slips at t0), and the
force that acts is the output of the continuous first-order filter
tau dF_f/dt = F - F_f, which starts at zero (docs/theory.md
6.3). Reference: F_f = L (1 - e^(-(t - t0)/tau)), 63.2 % at
t0 + tau; and the exact solution with the stick phase (the raw force
c_t V + K_t V (t - t0) up to (1 + 1e-6) L, then L: no stick phase here). tau per Ifiltr: 3: 1/(2 pi Xfreq);
1: Dt_ref/Xfreq; 2: Dt_ref/(2 pi Xfreq).
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
import stick  # noqa: E402
from deck import Deck  # noqa: E402

M, R, K, G, MU, V = 1.0, 0.05, 1.0e6, 9.81, 0.3, 10.0
VISC = 2.0 * 0.5 * math.sqrt(K * M)  # normal damping ratio 0.5
KT = K                               # stick stiffness: the load-curve slope
MBELT = 1.0e12
BAND = stick.BAND                    # slip band RC_SLIP_BAND (src/model.h)
MRED = M * MBELT / (M + MBELT)       # reduced mass of the pair (the stick damper)
P_FIXED = M * G / K                  # penetration of the fixed-block variant: F_n = m g

# name: (Ifiltr, Xfreq, Dt_ref, tau expected, t0 = Tstart, block fixed)
CASES = {
    "ifiltr3": (3, 1.0 / (2.0 * math.pi * 0.04), None, 0.04, 0.0, False),
    "ifiltr1": (1, 0.25, 5e-3, 0.02, 0.0, False),
    "ifiltr2": (2, 0.1, 2.0 * math.pi * 1e-3, 0.01, 0.0, False),
    "ifiltr3_tstart": (3, 1.0 / (2.0 * math.pi * 0.04), None, 0.04, 0.02, True),
}


def deck(ifiltr, xfreq, dt_ref, tau, t0, fixed):
    z0 = R - (P_FIXED if fixed else M * G / K)
    d = Deck(f"filtered friction on a belt: Ifiltr {ifiltr}, Xfreq {xfreq:.6g}, Dt_ref {dt_ref}, contact from {t0:g} s")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.nodes([(1, 0.0, 0.0, z0), (2, 0.0, 0.0, -1.0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title="block 1 kg")
    d.rbody(2, 2, MBELT, [MBELT] * 3, grnod=2, title="belt 1e12 kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), body=2, title="belt surface z = 0")
    d.grnod(1, [1], title="block")
    d.grnod(2, [2], title="belt")
    if fixed:
        d.bcs(1, 1, "111 111", title="block fixed in space (penetration m g / k)")
    else:
        d.bcs(1, 1, "110 111", title="block held in x and y, no rotation")
        d.grav(1, "Z", -G, 1)  # on the block only
    d.bcs(2, 2, "011 111", title="belt moves along x only")
    d.inivel(1, (V, 0.0, 0.0), 2)
    d.type6(1, 1, 2, 1, visc=VISC, tstart=t0 if t0 > 0 else None, title="contact (no TYPE6 friction)")
    d.friction(1, ifric=0, ifiltr=ifiltr, xfreq=xfreq, iform=2, dt_ref=dt_ref, fric=MU,
               title=f"Coulomb 0.3, incremental, Ifiltr {ifiltr}")
    d.run(t0 + 5.0 * tau, tau / 20.0)
    d.solver(rtol=1e-8, atol_pos=1e-12, atol_vel=1e-9, atol_energy=1e-9)
    return d


def exact(t, t0, tau, L, m_red=MRED):
    """Filter output and friction work for the raw force of the stick phase,
    b + a s (s = t - t0; the stick damper's b = c_t V, c_t = 2 sqrt(K_t m_red),
    and the spring's a = K_t V), up to (1 + band) L at s1, then L; zero before
    t0. Here b > (1 + band) L, so s1 = 0: the contact slips at t0 and the raw
    force is the step L from t0. (A fully fixed block would make m_red the
    belt's mass: a larger c_t, the same step.)"""
    a = KT * V
    b = stick.ct(KT, m_red) * V
    s1 = max((1 + BAND) * L - b, 0.0) / a

    def ramp(sr):
        e = np.exp(-sr / tau)
        f = b * (1.0 - e) + a * (sr - tau + tau * e)
        w = V * (b * (sr - tau * (1.0 - e)) + a * (0.5 * sr * sr - tau * sr + tau * tau * (1.0 - e)))
        return f, w
    s = np.maximum(np.asarray(t, dtype=float) - t0, 0.0)
    f1, w1 = ramp(s1)
    f_ramp, w_ramp = ramp(np.minimum(s, s1))
    q = np.maximum(s - s1, 0.0)
    f_after = L + (f1 - L) * np.exp(-q / tau)
    w_after = w1 + V * (L * q + (f1 - L) * tau * (1.0 - np.exp(-q / tau)))
    return np.where(s <= s1, f_ramp, f_after), np.where(s <= s1, w_ramp, w_after)


def run_case(name, path=None):
    ifiltr, xfreq, dt_ref, tau, t0, fixed = CASES[name]
    r = rcval.Result(rcval.run_file(path) if path else rcval.run(deck(*CASES[name])))
    fn = r.fn[:, 0]
    L = MU * fn[-1]
    fx = r.ffric[:, 0, 0]
    # 63.2 % at t0 + tau (a record: t0 and tau are multiples of Dt_out)
    i = int(np.argmin(np.abs(r.t - (t0 + tau))))
    ratio = fx[i] / L
    e = rcval.rel(ratio, 1.0 - math.exp(-1.0))
    rcval.check(f"frc_filter.{name}.tau", abs(r.t[i] - t0 - tau) < 1e-12 and e < 1e-4,
                f"tau = {tau:g} s (Ifiltr {ifiltr}, Xfreq {xfreq:.9g}{f', Dt_ref {dt_ref:.9g} s' if dt_ref else ''}): "
                f"F_f(t0 + tau)/(mu F_n) = {ratio:.9f}, 1 - 1/e = {1 - math.exp(-1):.9f}, rel. error {e:.1e} (< 1e-4)")
    # whole history against the exact solution (slip at t0: the step)
    fref, wref = exact(r.t, t0, tau, L)
    e = np.max(np.abs(fx - fref)) / L
    side = np.max(np.abs(r.ffric[:, 0, 1:]))
    before = np.max(np.abs(fx[r.t < t0 - 1e-12])) if t0 > 0 else 0.0
    rcval.check(f"frc_filter.{name}.history", e < 1e-6 and side < 1e-12 * L and before == 0.0,
                f"{len(r.t)} records to t0 + 5 tau: max |F_f - F_exact|/(mu F_n) = {e:.1e} (< 1e-6); "
                f"across the belt {side:.1e} N; before t0 {before:.1e} N; at t0 + 5 tau {fx[-1] / L:.9f} of the limit")
    w = r.energy["energy_friction_work"]
    e = abs(w[-1] - wref[-1]) / wref[-1]
    rcval.check(f"frc_filter.{name}.work", e < 1e-6,
                f"friction work (energy_friction_work) {w[-1]:.9f} J, V times the integral of F_f {wref[-1]:.9f} J, "
                f"rel. error {e:.1e} (< 1e-6)")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    run_case("ifiltr3", os.path.join(here, "case.rad"))
    for name in ("ifiltr1", "ifiltr2", "ifiltr3_tstart"):
        run_case(name)
    # Ifiltr 1 without Dt_ref: rejected, not guessed
    d = deck(1, 0.25, None, 0.02, 0.0, False)
    try:
        rcval.run(d)
        msg = "accepted"
    except RuntimeError as exc:
        msg = str(exc)
    rcval.check("frc_filter.ifiltr1_needs_dt_ref", "Dt_ref" in msg and msg != "accepted",
                f"Ifiltr 1 with a blank Dt_ref: {msg[:200]}")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(*CASES["ifiltr3"]))
