"""A body hanging from two elastic catenaries settles at the static equilibrium.

Two catenaries (/COUPLING/CATENARY) from fixed points (-S, 0, 0) and (S, 0, 0)
to the centre of mass of a body of mass M, in gravity; a pure damper (a
/COUPLING/SPRING with k = 0) to a point far below takes the energy out. By
symmetry the body settles on the axis at the height z where the two lines'
vertical end forces carry its weight, 2 V(z) = M g, V(z) from the elastic
catenary equations solved by scipy (validation/lib/catenary_ref.py), z by
brentq. Checks the settled height, that the body stays on the axis, and the
ledger: the energy lost equals what the damper dissipated; and the same deck
solved by the static analysis (--method static): the equilibrium height at
every output time.
"""
import math
import os
import sys

import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import catenary_ref  # noqa: E402
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, G, S, LEQ, LAM, D, KD = 50.0, 9.81, 5.0, 7.0, 2.0, 1.0e5, 400.0
Z0 = -3.0
EA, W = D * LEQ, LAM * G


def equilibrium():
    """Height z of the body: the left line runs from (-S, 0) to (0, z); its
    end force on the body is (-H, -V2) and the right line mirrors it."""
    def excess(z):
        H, V1, V2 = catenary_ref.elastic(S, z, LEQ, W, EA)
        return -2.0 * V2 - M * G
    return brentq(excess, -6.9, -3.0, xtol=1e-14, rtol=1e-15)


def deck():
    d = Deck("body hanging from two catenaries")
    d.nodes([(1, 0.0, 0.0, Z0)])
    d.rbody(1, 1, M, [2.0, 2.0, 2.0], title="body 50 kg")
    d.catenary(1, 0, (-S, 0.0, 0.0), 1, (0.0, 0.0, Z0), LAM, LEQ, D, title="left line")
    d.catenary(2, 1, (0.0, 0.0, Z0), 0, (S, 0.0, 0.0), LAM, LEQ, D, title="right line")
    d.spring(3, 0, (0.0, 0.0, -100.0), 1, (0.0, 0.0, Z0), iform=1, kd=KD, a=0.0, title="vertical damper")
    d.grav(1, "Z", -G)
    d.run(30.0, 0.1)
    d.solver(rtol=1e-9, atol_pos=1e-11, atol_vel=1e-9, atol_energy=1e-8)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    z_ref = equilibrium()
    z = r.pos[-1, 0, 2]
    rcval.check("cpl_catenary_hanging.equilibrium", abs(z - z_ref) < 1e-7,
                f"settled at z = {z:.10f} m, catenary equations {z_ref:.10f} m, error {abs(z - z_ref):.1e} m "
                f"(< 1e-7 m); sag below the anchors {-z_ref:.4f} m, line length {LEQ} m")
    off = np.max(np.abs(r.pos[:, 0, :2]))
    v = np.max(np.abs(r.vel[-1, 0, :]))
    rcval.check("cpl_catenary_hanging.at_rest", off < 1e-6 and v < 1e-8,
                f"max horizontal offset {off:.1e} m (< 1e-6), final speed {v:.1e} m/s (< 1e-8)")
    e = r.energy
    drop = e["energy_total"][0] - e["energy_total"][-1]
    scale = M * G * abs(z_ref - Z0)
    lost = e["energy_kinetic"][0] + e["energy_potential"][0] - (e["energy_kinetic"][-1] + e["energy_potential"][-1]) \
        - (e["energy_catenary"][-1] - e["energy_catenary"][0])
    rcval.check("cpl_catenary_hanging.ledger", abs(drop) < 1e-7 * scale and rcval.rel(e["energy_coupling_damping"][-1], lost) < 1e-6,
                f"energy_total drift {abs(drop):.1e} J (< 1e-7 of M g dz = {scale:.1f} J); damper dissipated "
                f"{e['energy_coupling_damping'][-1]:.6f} J = bodies and lines lost {lost:.6f} J")
    # the same deck solved by the static analysis (--method static, in every
    # mode): the equilibrium at each output time, without the settling
    saved = rcval.METHOD
    rcval.METHOD = "static"
    rs = rcval.Result(rcval.run_case(keep_solver=True))
    rcval.METHOD = saved
    es = float(np.abs(rs.pos[:, 0, 2] - z_ref).max())
    offs = float(np.abs(rs.pos[:, 0, :2]).max())
    rcval.check("cpl_catenary_hanging.static", es < 1e-9 and offs < 1e-12,
                f"static analysis: {len(rs.t)} records at z = {rs.pos[-1, 0, 2]:.12f} m, max |z - z_ref| {es:.1e} m "
                f"(< 1e-9 m), horizontal offset {offs:.1e} m (< 1e-12)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
