"""Tabulated spring laws (/COUPLING/SPRING Iform 3 and 4) against the polynomial law (Iform 2).

The polynomial force F(u) = a u + b u^2 + c u^3 (u = x - x0) is given four ways
to four identical, independent mass-spring systems: the polynomial k_eff
(Iform 2), its tabulated force f_e(x) (Iform 3), its tabulated stiffness
k(x) = F'(x - x0) integrated from x0 (Iform 4), and the same stiffness table
integrated from a reference force f_r = F(x_r - x0) at x_r, with x0 set
outside the table (Iform 4 with F_r, X_r). Checks (README.md):
  - each tabulated motion equals an independent scipy integration of the same
    tabulated law (linear interpolation of f_e; exact integral of the linear
    interpolation of k), to 1e-6 of the amplitude;
  - it differs from the polynomial motion by no more than the interpolation
    and quadrature error does (the difference of the two scipy solutions),
    within 1e-6 of the amplitude, and that difference is small (< 1e-3 A).
"""
import bisect
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, A1, B2, C3, X0, AMP = 1.3, 250.0, 800.0, 4.0e4, 0.5, 0.08
H_TAB, U_TAB = 0.0005, 0.12         # table step and half-range [m]
XR = X0 + 0.05                      # reference distance of Iform 4 with F_r
X0_FAR = 0.05                       # x0 given to Iform 4 with F_r: outside the table
T_END, DT = 1.0, 0.002              # about three periods


def r12(v):
    """Values as the deck writes them (12 significant digits)."""
    return np.array([float(f"{x:.12g}") for x in np.atleast_1d(v)])


def F(u):
    return A1 * u + B2 * u**2 + C3 * u**3


def K(u):
    return A1 + 2 * B2 * u + 3 * C3 * u**2


XT = r12(X0 + np.linspace(-U_TAB, U_TAB, int(round(2 * U_TAB / H_TAB)) + 1))
FT, KT = r12(F(XT - X0)), r12(K(XT - X0))
FR = r12(F(XR - X0))[0]


XL, FL, KL = list(XT), list(FT), list(KT)
CUM = [0.0]
for j in range(len(XL) - 1):
    CUM.append(CUM[-1] + 0.5 * (KL[j] + KL[j + 1]) * (XL[j + 1] - XL[j]))


def segment(x):
    """Table segment of x (the end segments extend beyond the table)."""
    return min(max(bisect.bisect_right(XL, x) - 1, 0), len(XL) - 2)


def lin(x):
    """Linear interpolation of f_e, extended with the end slopes."""
    i = segment(x)
    return FL[i] + (FL[i + 1] - FL[i]) / (XL[i + 1] - XL[i]) * (x - XL[i])


def kint(x):
    """Exact integral of the linear interpolation of k from XT[0] to x."""
    i = segment(x)
    s = (KL[i + 1] - KL[i]) / (XL[i + 1] - XL[i])
    e = x - XL[i]
    return CUM[i] + e * (KL[i] + 0.5 * s * e)


LAWS = {
    "polynomial": lambda x: F(x - X0),
    "force_table": lin,
    "stiffness_table": lambda x: kint(x) - kint(X0),
    "stiffness_table_ref": lambda x: FR + kint(x) - kint(XR),
}


def scipy_motion(law, t):
    sol = solve_ivp(lambda _, s: [s[1], -law(s[0]) / M], (0, t[-1]), [X0 + AMP, 0.0], method="DOP853",
                    t_eval=t, rtol=1e-12, atol=1e-14)
    return sol.y[0]


def deck(rtol=1e-10):
    d = Deck("tabulated spring laws")
    d.funct(1, XT, FT, title="elastic force f_e(x) [N]")
    d.funct(2, XT, KT, title="stiffness k(x) [N/m]")
    d.nodes([(k + 1, X0 + AMP, float(k), 0.0) for k in range(4)])
    for k in range(4):
        d.rbody(k + 1, k + 1, M, [0.01, 0.01, 0.01], title=f"mass {k + 1}")
    o = [(0.0, float(k), 0.0) for k in range(4)]
    p = [(X0 + AMP, float(k), 0.0) for k in range(4)]
    d.spring(1, 0, o[0], 1, p[0], iform=2, x0=X0, a=A1, b=B2, c=C3, title="polynomial")
    d.spring(2, 0, o[1], 2, p[1], iform=3, fct=1, x0=X0, title="force table")
    d.spring(3, 0, o[2], 3, p[2], iform=4, fct=2, x0=X0, title="stiffness table from x0")
    d.spring(4, 0, o[3], 4, p[3], iform=4, fct=2, x0=X0_FAR, fr=FR, xr=XR, title="stiffness table from f_r at x_r")
    d.run(T_END, DT)
    d.solver(rtol=rtol, atol_pos=1e-2 * rtol, atol_vel=rtol, atol_energy=1e-2 * rtol)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    x = {name: r.pos[:, k, 0] for k, name in enumerate(LAWS)}
    ref = {name: scipy_motion(law, r.t) for name, law in LAWS.items()}
    err = np.max(np.abs(x["polynomial"] - ref["polynomial"])) / AMP
    rcval.check("cpl_spring_tabulated.polynomial", err < 1e-6,
                f"Iform 2 against scipy: max error {err:.2e} A (< 1e-6)")
    uu = np.linspace(-AMP, AMP, 2001)
    for name in list(LAWS)[1:]:
        e_self = np.max(np.abs(x[name] - ref[name])) / AMP
        d_ric = np.max(np.abs(x[name] - x["polynomial"])) / AMP
        d_ref = np.max(np.abs(ref[name] - ref["polynomial"])) / AMP
        df = max(abs(LAWS[name](X0 + u) - F(u)) for u in uu)
        rcval.check(f"cpl_spring_tabulated.{name}",
                    e_self < 1e-6 and abs(d_ric - d_ref) < 1e-6 and d_ref < 1e-3,
                    f"against scipy on the same table {e_self:.2e} A (< 1e-6); against the polynomial "
                    f"motion {d_ric:.3e} A, interpolation/quadrature effect {d_ref:.3e} A (differ by "
                    f"{abs(d_ric - d_ref):.1e} < 1e-6; < 1e-3); max |f_tab - F| = {df:.2e} N")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
