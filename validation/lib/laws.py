"""Small pieces of the contact laws' references shared by several problems:
the step5 smooth step and its friction coefficient (docs/theory.md 9.4:
pw_roller_mesh, pw_roller_traction), and the quadrature of a tabulated
(piecewise-linear) load curve (t6_bounces, t6_inacti_icor, t6_unload_curve).
"""
from scipy.integrate import quad


def step5(x, x0, h0, x1, h1):
    """The quintic smooth step: h0 up to x0, h1 from x1 on, between them
    h0 + (h1 - h0) d^3 (10 - 15 d + 6 d^2), d = (x - x0)/(x1 - x0); in the
    units of h0, h1."""
    if x <= x0:
        return h0
    if x >= x1:
        return h1
    d = (x - x0) / (x1 - x0)
    return h0 + (h1 - h0) * d**3 * (10 - 15 * d + 6 * d * d)


def step5_mu(v, mus, vs, mud, vd):
    """The step5 friction coefficient at the slip speed v [m/s]:
    step5(v, -v_s, -mu_s, v_s, mu_s) below v_s [m/s], step5(v, v_s, mu_s, v_d,
    mu_d) beyond (dimensionless)."""
    return step5(v, -vs, -mus, vs, mus) if v < vs else step5(v, vs, mus, vd, mud)


def curve_integral(f, xs, a, b, scale=1.0):
    """Integral of the piecewise-linear curve f from a to b [m] (scipy quad,
    rtol 1e-13), its breakpoints scale * xs [m] inside (a, b) passed
    explicitly; in [f] m (J for a force curve)."""
    pts = [scale * x for x in xs if a < scale * x < b]
    return quad(f, a, b, points=pts or None, limit=200, epsabs=0.0, epsrel=1e-13)[0]
