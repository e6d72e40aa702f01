"""An imposed velocity that ends: /IMPVEL Tstop is a located event.

A sphere (m = 1 kg) is held at vertical velocity 0 by /IMPVEL (Dir Z,
f = 0) under gravity until Tstop = 0.2 s, then released. Reference (free
fall): z(t) = z0 - g (t - Tstop)^2 / 2 for t > Tstop; the event
`impvel_stop` at Tstop exactly; the energy ledger closes (the reaction's work
is counted in energy_imposed).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402

M, R, G, Z0, TSTOP = 1.0, 0.05, 9.81, 1.0, 0.2


def deck():
    d = Deck("imposed velocity released at Tstop")
    d.funct(1, [0.0, 1.0], [0.0, 0.0], title="zero")
    d.nodes([(1, 0.0, 0.0, Z0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3)
    d.grnod(1, [1])
    d.grav(1, "Z", -G)
    d.impvel(1, 1, "Z", 1, tstop=TSTOP)
    d.run(0.5, 0.01)
    d.solver(rtol=1e-8, atol_pos=1e-12, atol_vel=1e-10, atol_energy=1e-10)
    return d


def main():
    r = rcval.Result(rcval.run_case())
    ev = r.events("impvel_stop")
    ok = len(ev) == 1 and abs(ev[0] - TSTOP) <= 1e-14
    rcval.check("impvel_release.event", ok, f"impvel_stop at {ev} s (Tstop = {TSTOP} s)")
    held = r.t <= TSTOP
    dz_held = float(np.max(np.abs(r.pos[held, 0, 2] - Z0)))
    rcval.check("impvel_release.held", dz_held < 1e-12, f"max |z - z0| while held: {dz_held:.2e} m (< 1e-12)")
    free = r.t > TSTOP
    ref = Z0 - 0.5 * G * (r.t[free] - TSTOP) ** 2
    err = float(np.max(np.abs(r.pos[free, 0, 2] - ref)))
    rcval.check("impvel_release.free_fall", err < 1e-7, f"max |z - (z0 - g (t - Tstop)^2 / 2)| = {err:.2e} m (< 1e-7 = 10 rtol z0)")
    e = r.energy["energy_total"]
    drift = float(np.max(np.abs(e - e[0])))
    rcval.check("impvel_release.ledger", drift < 1e-6, f"max |E_total - E_total(0)| = {drift:.2e} J (< 1e-6 = 10 rtol m g z0)")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, deck)
