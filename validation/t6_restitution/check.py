"""Restitution asked instead of a damping (TYPE6 e_target, ricochet's
extension): a sphere hits a fixed plane without gravity, the contact is a
linear load curve with the force clipped at zero, and the deck gives the
coefficient of restitution e instead of Visc. ricochet derives the damping
(docs/theory.md, "Restitution asked"); the rebound speed over the approach
speed must equal the asked e.

Reference: the asked value itself, for e = 0.05 ... 1 (ten values spanning
the under- and overdamped regimes; e < exp(-2) = 0.135 needs zeta > 1).
The measured e is the normal speed at the `contact_open` event (the force
reaches zero; `contact_separate` for e = 1, no damping) over the approach
speed at `contact_close`.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
import rcval  # noqa: E402
from deck import Deck  # noqa: E402
from sphereplane import add_sphere_over_plane  # noqa: E402

M, R, K, V0, GAP0 = 1.0, 0.05, 1.0e6, 1.0, 0.002
E_ASKED = (0.05, 0.1, 0.135, 0.2, 0.3, 0.5, 0.7, 0.8, 0.95, 1.0)
TOL = 1e-6


def deck(e):
    d = Deck(f"restitution asked: e = {e}")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    add_sphere_over_plane(d, M, R, R + GAP0, V0, title="sphere 1 kg")
    d.type6(1, 1, 2, 1, e_target=e, title="restitution asked")
    d.run(0.01, 0.001)
    return d


def measure(path):
    r = rcval.Result(path)
    i_close = r.ev_kind.index("contact_close")
    # the force reaches zero (contact_open) or, without damping, the
    # penetration does at the same moment (contact_separate)
    i_open = next(i for i, k in enumerate(r.ev_kind) if i > i_close and k in ("contact_open", "contact_separate"))
    v_in = r.ev_vn[i_close]
    v_out = r.ev_vn[i_open]
    return -v_out / v_in


def main():
    worst = 0.0
    rows = []
    for e in E_ASKED:
        got = measure(rcval.run(deck(e)))
        err = abs(got - e)
        worst = max(worst, err)
        rows.append(f"{e:g}: {got:.9f}")
    rcval.check("t6_restitution.asked_vs_achieved", worst < TOL,
                f"achieved e for asked {', '.join(rows)}; max |error| {worst:.2e} (< {TOL:g})")
    rcval.finish()


if __name__ == "__main__":
    rcval.entry(main, lambda: deck(0.3))
