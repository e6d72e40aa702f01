"""Meshes written as Radioss 2022 cards (fixed columns), for the mass
properties study and the drop deck of validation/mass_mesh.

Each generator returns (nodes, elements): nodes a list of (id, x, y, z),
elements a list of node-id tuples; the card writers below format them.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from deck import i10, r20  # noqa: E402


class Nodes:
    """Unique nodes by rounded coordinates, ids from `first`."""

    def __init__(self, first=1):
        self.next = first
        self.ids = {}
        self.list = []

    def get(self, x, y, z):
        key = (round(x, 12), round(y, 12), round(z, 12))
        if key not in self.ids:
            self.ids[key] = self.next
            self.list.append((self.next, x, y, z))
            self.next += 1
        return self.ids[key]


def sphere_shell(nodes, n, R, centre=(0.0, 0.0, 0.0)):
    """Cube-sphere: 6 n^2 quadrilaterals, nodes projected on radius R."""
    quads = []
    for f in range(6):
        ax, sg = f // 2, (1 if f % 2 == 0 else -1)
        for i in range(n):
            for j in range(n):
                q = []
                for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    x = [0.0, 0.0, 0.0]
                    x[ax] = sg
                    x[(ax + 1) % 3] = -1 + 2.0 * (i + di) / n
                    x[(ax + 2) % 3] = -1 + 2.0 * (j + dj) / n
                    r = math.sqrt(sum(v * v for v in x))
                    q.append(nodes.get(*(centre[k] + R * x[k] / r for k in range(3))))
                quads.append(tuple(q))
    return quads


def box_bricks(nodes, n, size, origin=(0.0, 0.0, 0.0)):
    """n^3 bricks filling the box origin + [0, a] x [0, b] x [0, c]."""
    a, b, c = size
    bricks = []
    for i in range(n):
        for j in range(n):
            for k in range(n):
                ids = []
                for dk in (0, 1):
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        ids.append(nodes.get(origin[0] + a * (i + di) / n, origin[1] + b * (j + dj) / n,
                                             origin[2] + c * (k + dk) / n))
                bricks.append(tuple(ids))
    return bricks


def box_shell(nodes, n, size, origin=(0.0, 0.0, 0.0)):
    """The six faces of the box, n^2 quadrilaterals each."""
    a, b, c = size
    quads = []
    for ax in range(3):
        for side in (0, 1):
            for i in range(n):
                for j in range(n):
                    q = []
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                        u = [0.0, 0.0, 0.0]
                        u[ax] = side
                        u[(ax + 1) % 3] = (i + di) / n
                        u[(ax + 2) % 3] = (j + dj) / n
                        q.append(nodes.get(origin[0] + a * u[0], origin[1] + b * u[1], origin[2] + c * u[2]))
                    quads.append(tuple(q))
    return quads


def cylinder_bricks(nodes, nt, nr, R, L):
    """Solid cylinder, axis z, centred at 0: bricks on a polar grid (the
    inner ring degenerate: wedges with two nodes on the axis)."""
    bricks = []
    for i in range(nr):
        for j in range(nt):
            ids = []
            for z in (-L / 2, L / 2):
                for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                    r, th = R * (i + di) / nr, 2 * math.pi * (j + dj) / nt
                    ids.append(nodes.get(r * math.cos(th), r * math.sin(th), z))
            bricks.append(tuple(ids))
    return bricks


def tube_sh3n(nodes, nt, nz, R, L):
    """Open tube, axis z, centred at 0: nt x nz rectangles, two triangles each."""
    tris = []
    for j in range(nt):
        for k in range(nz):
            p = [nodes.get(R * math.cos(2 * math.pi * (j + dj) / nt), R * math.sin(2 * math.pi * (j + dj) / nt),
                           -L / 2 + L * (k + dk) / nz) for dj, dk in ((0, 0), (1, 0), (1, 1), (0, 1))]
            tris.append((p[0], p[1], p[2]))
            tris.append((p[0], p[2], p[3]))
    return tris


# ---- cards (Radioss 2022 layout) ----------------------------------------------

def node_card(nodes):
    out = ["/NODE", "#  node_ID                   X                   Y                   Z"]
    out += [f"{i10(n)}{r20(x)}{r20(y)}{r20(z)}" for n, x, y, z in nodes]
    return out


def elem_card(kind, part, elems, first=1):
    head = {"SHELL": "# shell_ID  node_ID1  node_ID2  node_ID3  node_ID4",
            "SH3N": "#  sh3n_ID  node_ID1  node_ID2  node_ID3",
            "BRICK": "# brick_ID  node_ID1  node_ID2  node_ID3  node_ID4  node_ID5  node_ID6  node_ID7  node_ID8",
            "TETRA4": "# tetra_ID  node_ID1  node_ID2  node_ID3  node_ID4"}[kind]
    out = [f"/{kind}/{part}", head]
    out += [i10(first + k) + "".join(i10(v) for v in e) for k, e in enumerate(elems)]
    return out


def mat_law1(mid, rho, title="steel"):
    return [f"/MAT/LAW1/{mid}", title, "#        Init. dens.          Ref. dens.", r20(rho) + r20(0.0),
            "#                  E                  nu", r20(2.1e11) + r20(0.3)]


def prop_shell(pid, thick, title="shell"):
    return [f"/PROP/SHELL/{pid}", title,
            "#   Ishell    Ismstr     Ish3n    Idrill                            P_Thick_Fail",
            i10(24) + i10(0) + i10(0) + i10(0) + " " * 20 + r20(0.0),
            "#                 Hm                  Hf                  Hr                  Dm                  Dn",
            "".join(r20(0.0) for _ in range(5)),
            "#        N   Istrain               Thick              Ashear              Ithick     Iplas",
            i10(5) + i10(0) + r20(thick) + r20(0.0) + " " * 10 + i10(1) + i10(1)]


def prop_solid(pid, title="solid"):
    return [f"/PROP/SOLID/{pid}", title,
            "#   Isolid    Ismstr               Icpre  Itetra10     Inpts    Itetra4    Iframe                  dn",
            i10(24) + i10(4) + " " * 10 + i10(0) + i10(0) + i10(0) + i10(0) + i10(0),
            "#                q_a                 q_b                   h            LAMBDA_V                MU_V",
            "".join(r20(0.0) for _ in range(5)),
            "#             dtmin",
            r20(0.0)]


def part(pid, prop, mat, title="part"):
    return [f"/PART/{pid}", title, "#  prop_ID    mat_ID subset_ID", i10(prop) + i10(mat) + i10(0)]


def grnod_part(gid, parts, title="nodes of parts"):
    return [f"/GRNOD/PART/{gid}", title, "".join(i10(p) for p in parts)]


def rbody(bid, node, grnod, mass=0.0, J=(0.0, 0.0, 0.0), icog=1, ispher=3, title="body"):
    return [f"/RBODY/{bid}", title,
            "#  node_ID   sens_ID   Skew_ID    Ispher                Mass   grnd_ID     Ikrem      ICoG   surf_ID",
            i10(node) + i10(0) + i10(0) + i10(ispher) + r20(mass) + i10(grnod) + i10(0) + i10(icog) + i10(0),
            "#                Jxx                 Jyy                 Jzz",
            r20(J[0]) + r20(J[1]) + r20(J[2]),
            "#                Jxy                 Jyz                 Jxz",
            r20(0.0) + r20(0.0) + r20(0.0),
            "#  Ioptoff               Ifail",
            i10(0) + i10(0) + i10(0)]
