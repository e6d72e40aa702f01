"""Reference solutions of the catenary for the validation checks, independent
of ricochet's solver (which eliminates one equation and solves for the end
tensions, src/coupling_catenary.c).

elastic(): the three equations of the elastic catenary (docs/theory.md 8.2) in
its own unknowns (c, u1, u2), solved by
scipy.optimize.root (MINPACK hybrd, finite-difference Jacobian):
    a (u2 - u1) + b (sinh u2 - sinh u1) = X
    a (cosh u2 - cosh u1) + b/2 (sinh^2 u2 - sinh^2 u1) = Y
    c (sinh u2 - sinh u1) = w L
with a = c / w, b = c a / EA, w = lambda0 g, EA = D L (axial rigidity).

inextensible(): the classical inextensible catenary through two points
(Irvine, Cable Structures, MIT Press 1981, ch. 1): with a = H/w and
xi = X/(2a), sinh(xi)/xi = sqrt(L^2 - Y^2)/X (one scalar root, brentq);
the vertex abscissa is x_m = X/2 - a artanh(Y/L).

line_energy(): elastic energy int T^2/(2 EA) ds0 and gravitational energy
int w y ds0 over the unstretched arc length s0, with the tension components
V(s0) = V1 + w s0, H constant, T = sqrt(H^2 + V^2), and the height
y(s0) = y1 + (T - T1)/w + (V^2 - V1^2)/(2 w EA).
"""
import math

import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq, minimize_scalar, root


def inextensible(X, Y, L, w):
    """Inextensible catenary: (H, V1, V2), V_i the upward tension components at
    the ends (the force on end 1 is (H, V1), on end 2 (-H, -V2))."""
    r = math.sqrt(L * L - Y * Y) / X
    xi = brentq(lambda s: math.sinh(s) / s - r, 1e-12, 700.0, xtol=1e-15, rtol=1e-15, maxiter=500)
    a = X / (2.0 * xi)
    xm = 0.5 * X - a * math.atanh(Y / L)
    H = w * a
    return H, H * math.sinh(-xm / a), H * math.sinh((X - xm) / a)


def _guess(X, Y, L, w, EA):
    """(c, u1, u2) from the inextensible catenary, or a straight line when
    the chord exceeds L."""
    chord = math.hypot(X, Y)
    if chord < L * (1 - 1e-9):
        H, V1, V2 = inextensible(X, Y, L, w)
    else:
        T = max(EA * (chord / L - 1.0), w * L)
        H, V1 = T * X / chord, T * Y / chord - 0.5 * w * L
        V2 = V1 + w * L
    return np.array([H, math.asinh(V1 / H), math.asinh(V2 / H)])


def elastic(X, Y, L, w, EA, guess=None):
    """Elastic catenary: (H, V1, V2) from its three equations in (c, u1, u2)."""
    def eqs(z):
        c, u1, u2 = z
        a = c / w
        b = c * a / EA
        return [(a * (u2 - u1) + b * (math.sinh(u2) - math.sinh(u1)) - X) / L,
                (a * (math.cosh(u2) - math.cosh(u1)) + 0.5 * b * (math.sinh(u2) ** 2 - math.sinh(u1) ** 2) - Y) / L,
                (c * (math.sinh(u2) - math.sinh(u1)) - w * L) / (w * L)]

    starts = [] if guess is None else [np.asarray(guess, float)]
    for z0 in starts + [_guess(X, Y, L, w, EA)]:
        sol = root(eqs, z0, method="hybr", options={"xtol": 1e-15, "maxfev": 20000})
        if max(abs(v) for v in eqs(sol.x)) <= 1e-12:
            break
    else:
        raise RuntimeError(f"catenary reference did not converge: X={X}, Y={Y}: {sol.message}")
    c, u1, u2 = sol.x
    return c, c * math.sinh(u1), c * math.sinh(u2)


def height(s, H, V1, y1, w, EA):
    """Height of the point at unstretched arc length s from end 1."""
    V = V1 + w * s
    return y1 + (math.hypot(H, V) - math.hypot(H, V1)) / w + (V * V - V1 * V1) / (2.0 * w * EA)


def lowest(H, V1, y1, L, w, EA):
    """Height of the lowest point of the line: a bounded scalar minimisation of
    height(s) over [0, L], and the two ends."""
    f = lambda s: height(s, H, V1, y1, w, EA)
    r = minimize_scalar(f, bounds=(0.0, L), method="bounded", options={"xatol": 1e-12 * L})
    return min(f(0.0), f(L), r.fun)


def line_energy(H, V1, y1, L, w, EA):
    """(elastic, gravitational) energy of the line [J]; y1 the height of end 1."""
    def hgt(s):
        return height(s, H, V1, y1, w, EA)

    elastic = quad(lambda s: (H * H + (V1 + w * s) ** 2) / (2.0 * EA), 0.0, L, epsabs=0, epsrel=1e-13)[0]
    grav = w * quad(hgt, 0.0, L, epsabs=0, epsrel=1e-13)[0]
    return elastic, grav
