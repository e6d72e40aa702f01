"""Write case.rad: two meshed rigid bodies on the plane z = 0, in the Radioss
2022 layout (run once; case.rad is kept in the repository).

Body 1: a steel spherical shell (cube-sphere of 6 x 8^2 /SHELL quads, mid
radius 0.1 m, /PROP/SHELL thickness 2 mm) dropped from a 50 mm gap.
Body 2: an aluminium box 0.2 x 0.2 x 0.1 m of 2 x 2 x 2 /BRICK elements on
four spherical feet (radius 10 mm) touching the plane at t = 0.
No card mass or inertia: both bodies take their mass from the mesh.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import meshes as M  # noqa: E402
from deck import Deck, line  # noqa: E402

R, T, GAP, N = 0.1, 0.002, 0.05, 8
RHO_S, RHO_A = 7800.0, 2700.0
BOX, BOX_O, RF = (0.2, 0.2, 0.1), (0.4, -0.1, 0.01), 0.01
K, G = 1.0e6, 9.81
ZC = R + T / 2 + GAP                      # sphere centre: outer surface GAP above the plane
M_SPHERE = RHO_S * 4 * math.pi * R * R * T   # for the damping only
M_BOX = RHO_A * BOX[0] * BOX[1] * BOX[2]


def build():
    d = Deck(title="meshed shell sphere and brick box on a plane (Radioss 2022 layout)")
    nodes = M.Nodes(first=11)
    quads = M.sphere_shell(nodes, N, R, centre=(0.0, 0.0, ZC))
    n_sphere = len(nodes.list)
    bricks = M.box_bricks(nodes, 2, BOX, origin=BOX_O)
    d.cards += M.node_card([(1, 0.0, 0.0, ZC), (2, 0.5, 0.0, 0.5)] + nodes.list)
    d.cards += M.mat_law1(1, RHO_S, title="steel")
    d.cards += ["/MAT/PLAS_JOHNS/2", "aluminium", "#        Init. dens.          Ref. dens.",
                M.r20(RHO_A) + M.r20(0.0),
                "#                  E                  nu     Iflag",
                M.r20(7.0e10) + M.r20(0.33) + M.i10(0),
                "#                  a                   b                   n             EPS_max            SIG_max0",
                "".join(M.r20(v) for v in (2.0e8, 1.0e8, 0.3, 0.0, 0.0)),
                "#                  c           EPS_DOT_0       ICC   Fsmooth               F_cut               Chard",
                M.r20(0.0) + M.r20(0.0) + M.i10(0) + M.i10(0) + M.r20(0.0) + M.r20(0.0),
                "#                  m              T_melt              rhoC_p                 T_r",
                "".join(M.r20(v) for v in (0.0, 0.0, 0.0, 0.0))]
    d.cards += M.prop_shell(3, T, title="2 mm shell") + M.prop_solid(4, title="solid")
    d.cards += M.part(1, 3, 1, title="sphere skin") + M.part(2, 4, 2, title="box")
    d.cards += M.elem_card("SHELL", 1, quads) + M.elem_card("BRICK", 2, bricks, first=1001)
    d.cards += M.grnod_part(101, [1], title="sphere nodes") + M.grnod_part(102, [2], title="box nodes")
    d.cards += M.rbody(1, 1, 101, icog=1, ispher=0, title="shell sphere")
    d.cards += M.rbody(2, 2, 102, icog=1, ispher=0, title="brick box")
    # contact surfaces carried by the bodies, the fixed plane
    d.sphere(11, 1, (0.0, 0.0, ZC), R + T / 2, title="outer surface of the shell")
    feet = [(BOX_O[0] + i * BOX[0], BOX_O[1] + j * BOX[1], RF) for i in (0, 1) for j in (0, 1)]
    for k, c in enumerate(feet):
        d.sphere(21 + k, 2, c, RF, title=f"foot {k + 1}")
    d.plane(10, (0, 0, 0), (0, 0, 1), title="floor z = 0")
    d.funct(1, [0.0, 1.0], [0.0, K], title="linear load curve k = 1e6 N/m")
    d.type6(1, 11, 10, 1, visc=2 * 0.5 * math.sqrt(K * M_SPHERE), title="sphere on floor")
    for k in range(4):
        d.type6(2 + k, 21 + k, 10, 1, visc=2 * 0.5 * math.sqrt(K * M_BOX / 4), title=f"foot {k + 1} on floor")
    d.grav(1, "Z", -G)
    d.run(0.6, 0.001)
    return d


if __name__ == "__main__":
    build().write(os.path.join(HERE, "case.rad"))
