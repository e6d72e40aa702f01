"""Translations held along a skew's axes (/BCS skew_ID with one or two of
Tx Ty Tz held): a ball on a rail, and on a plane, landing on a floor.

A /SKEW/FIX whose X' axis u = (cos th cos ph, cos th sin ph, sin th) climbs at
th = 30 degrees along the azimuth ph = 40 degrees (Y' horizontal, Z' = X' x Y').
Ball 1 (m = 2 kg, R = 0.05 m) starts at z = 1 m held on the rail (/BCS 011 000:
Ty', Tz' held), ball 2 (m = 1.5 kg) at z = 0.8 m held in the rail's X'Y'
plane (/BCS 001 000: Tz' held); both thrown with v_i = (1, 2, 3) m/s
(/INIVEL) under gravity g = -9.81 m/s^2 along Z, over a floor z = 0 with a
linear elastic TYPE6 contact (k = 1e6 N/m, no damping, no friction). In
closed form (README.md), with P the projection off the held axes:

  v(0) = P v_i,  a = P g,  x(t) = x0 + v(0) t + a t^2 / 2   (free flight)
  landing: z(t) = R,  the first root of z0 + v_z(0) t + a_z t^2 / 2 = R
  contact: the penetration p = R - z of the constrained body is a linear
  oscillator, p'' + w^2 p = |g| e, e = e_z . P e_z, w^2 = k e / m; from
  p = 0 at the approach speed p0 it returns to 0 after
  t_c = (2 / w) (pi - atan(p0 / (w c))), c = |g| e / w^2 = m |g| / k,
  with the same speed out (elastic).

Checks the flights, the landing times, the contact durations and the
rebound speeds, that the velocity along the held axes stays zero, the
energy ledger, and the flight error shrinking as rtol shrinks.
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck, line  # noqa: E402

TH, PH = math.radians(30.0), math.radians(40.0)
XA = np.array([math.cos(TH) * math.cos(PH), math.cos(TH) * math.sin(PH), math.sin(TH)])  # X': the rail
YA = np.array([-math.sin(PH), math.cos(PH), 0.0])                                        # Y': horizontal
ZA = np.cross(XA, YA)                                                                    # Z'
G = np.array([0.0, 0.0, -9.81])
VI = np.array([1.0, 2.0, 3.0])
R, K = 0.05, 1.0e6
BALLS = [  # mass, start, held axes
    (2.0, np.array([0.0, 0.0, 1.0]), [YA, ZA]),
    (1.5, np.array([0.5, -0.4, 0.8]), [ZA]),
]
TEND = 1.9


def proj(held):
    return np.eye(3) - sum(np.outer(u, u) for u in held)


def flight(b):
    """Velocity at t = 0, acceleration, and the landing time of ball b."""
    m, x0, held = BALLS[b]
    P = proj(held)
    v0, a = P @ VI, P @ G
    # z0 + v0z t + az t^2 / 2 = R, the root after the apex (az < 0)
    A, B, C = 0.5 * a[2], v0[2], x0[2] - R
    tl = (-B - math.sqrt(B * B - 4 * A * C)) / (2 * A)
    return v0, a, tl


def contact(b):
    """Duration and approach speed of the first contact of ball b."""
    m, x0, held = BALLS[b]
    P = proj(held)
    v0, a, tl = flight(b)
    e = P @ np.array([0.0, 0.0, 1.0])        # the free part of e_z
    ez2 = float(e @ e)                        # |P e_z|^2 (= e_z . P e_z)
    w = math.sqrt(K * ez2 / m)
    p0 = -(v0[2] + a[2] * tl)                 # approach speed dP/dt at the landing
    c = 9.81 * ez2 / w**2
    return 2.0 / w * (math.pi - math.atan(p0 / (w * c))), p0


def reference(b, t):
    m, x0, held = BALLS[b]
    v0, a, tl = flight(b)
    t = np.asarray(t, dtype=float)[:, None]
    return x0 + v0 * t + 0.5 * a * t**2


def deck(rtol=1e-8):
    d = Deck("balls held on a rail and in a plane by /BCS along a skew's axes")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve")
    d.nodes([(b + 1, *BALLS[b][1]) for b in range(2)])
    d.add("/SKEW/FIX/7", line(("r", 0.0), ("r", 0.0), ("r", 0.0)), line(*[("r", x) for x in YA]),
          line(*[("r", x) for x in ZA]), title="X' up the rail, Y' horizontal")
    d.plane(9, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor")
    for b, (m, x0, held) in enumerate(BALLS):
        d.rbody(b + 1, b + 1, m, [0.4 * m * R * R] * 3, title=f"ball {b + 1}")
        d.sphere(b + 1, b + 1, x0, R, title=f"ball {b + 1}")
        d.grnod(b + 1, [b + 1], title=f"ball {b + 1}")
        d.type6(b + 1, b + 1, 9, 1, title=f"ball {b + 1} on the floor")
        d.bcs(b + 1, b + 1, "011 000" if len(held) == 2 else "001 000", skew=7,
              title="on the rail" if len(held) == 2 else "in the rail's plane")
        d.inivel(b + 1, tuple(VI), b + 1)
    d.grav(1, "Z", G[2])
    d.run(TEND, 0.01)
    d.solver(rtol=rtol, atol_pos=1e-4 * rtol, atol_vel=1e-2 * rtol, atol_energy=1e-2 * rtol)
    return d


def flight_error(r):
    err = 0.0
    for b in range(2):
        tl = flight(b)[2]
        keep = r.t < tl
        err = max(err, float(np.max(np.abs(r.pos[keep, b, :] - reference(b, r.t[keep])))))
    return err


def main():
    r = rcval.Result(rcval.run_case())
    err = flight_error(r)
    rcval.check("bcs_skew_rail.flight", err < 1e-7,
                f"max |x - x_exact| = {err:.2e} m over both flights before the landing (< 1e-7)")
    held = max(float(np.max(np.abs(r.vel[:, b, :] @ u))) for b in range(2) for u in BALLS[b][2])
    rcval.check("bcs_skew_rail.held", held < 1e-9, f"max |u.v| along the held axes: {held:.2e} m/s (< 1e-9)")
    for b in range(2):
        tl = flight(b)[2]
        tc, p0 = contact(b)
        name = f"ball {b + 1} on the floor"
        close = [t for t, k, e in zip(r.ev_t, r.ev_kind, r.ev_elem) if k == "contact_close" and e.endswith(f"/{b + 1}")]
        ends = [t for t, k, e in zip(r.ev_t, r.ev_kind, r.ev_elem)
                if k in ("contact_open", "contact_separate") and e.endswith(f"/{b + 1}")]
        rcval.check(f"bcs_skew_rail.landing{b + 1}", len(close) >= 1 and abs(close[0] - tl) < 1e-9,
                    f"{name}: first contact at {close[0] if close else None} s, closed form {tl:.12f} s (< 1e-9 s)")
        dur = ends[0] - close[0] if close and ends else float("nan")
        rcval.check(f"bcs_skew_rail.duration{b + 1}", abs(dur - tc) < 1e-9,
                    f"{name}: contact {dur:.12e} s, closed form {tc:.12e} s (< 1e-9 s)")
        # the rebound: the approach speed out equals the speed in (elastic)
        vn = [v for t, k, e, v in zip(r.ev_t, r.ev_kind, r.ev_elem, r.ev_vn)
              if k in ("contact_open", "contact_separate") and e.endswith(f"/{b + 1}")]
        rb = abs(-vn[0] - p0) / p0 if vn else float("nan")
        rcval.check(f"bcs_skew_rail.rebound{b + 1}", rb < 1e-6,
                    f"{name}: out {-vn[0] if vn else None} m/s, in {p0:.9f} m/s, relative {rb:.2e} (< 1e-6)")
    rcval.check_ledger("bcs_skew_rail.ledger", r, 1e-6)
    errs = [flight_error(rcval.Result(rcval.run(deck(rt), keep_solver=True))) for rt in (1e-5, 1e-7, 1e-9)]
    rcval.check("bcs_skew_rail.convergence", errs[2] < errs[1] < errs[0] or max(errs) < 1e-10,
                "max |x - x_exact| at rtol 1e-5, 1e-7, 1e-9 (decreasing, or all below 1e-10 m): " +
                ", ".join(f"{x:.2e}" for x in errs))
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
