"""Mass properties of meshed shapes against closed forms, at four
refinements, through `ricochet check` (its summary prints each body's mass,
centre of mass and inertia tensor). Used by check.py; run alone it prints
the table of README.md."""
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "lib"))
import meshes as M  # noqa: E402
import rcval  # noqa: E402

RHO = 7800.0


def body_props(cards):
    """Write a deck (/BEGIN 2022 ... /RUN), run `ricochet check`, return
    (mass, x0, J[Jxx, Jyy, Jzz, Jxy, Jyz, Jxz]) of body 1."""
    lines = ["#RADIOSS STARTER", "/BEGIN", "mass properties", M.i10(2022) + M.i10(0),
             "                  kg                   m                   s",
             "                  kg                   m                   s"]
    lines += cards + ["/RUN", M.r20(0.01) + M.r20(0.001), "/END", ""]
    d = rcval.tmpdir()
    path = os.path.join(d, "case.rad")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    p = subprocess.run([rcval.RICOCHET, "check", path], capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"ricochet check failed ({p.returncode}): {p.stderr.strip()}")
    m = re.search(r"inertia Jxx Jyy Jzz (\S+) (\S+) (\S+) Jxy Jyz Jxz (\S+) (\S+) (\S+) mass (\S+) x0 (\S+) (\S+) (\S+)",
                  p.stdout)
    v = [float(x) for x in m.groups()]
    return v[6], v[7:10], v[0:6]


def shape_deck(kind, elems, nodes, prop_cards, thick=None):
    """One body: main node 1 at the origin, the mesh as part 1."""
    cards = M.node_card([(1, 0.0, 0.0, 0.0)] + nodes.list)
    cards += M.mat_law1(1, RHO) + prop_cards + M.part(1, 2, 1, title="mesh")
    cards += M.elem_card(kind, 1, elems) + M.grnod_part(3, [1]) + M.rbody(1, 1, 3, icog=1, ispher=3)
    return cards


def sphere_shell(n, R=0.1, t=1e-4):
    nodes = M.Nodes(first=2)
    q = M.sphere_shell(nodes, n, R)
    m, x, J = body_props(shape_deck("SHELL", q, nodes, M.prop_shell(2, t)))
    Ro, Ri = R + t / 2, R - t / 2
    m_ex = RHO * 4 / 3 * math.pi * (Ro**3 - Ri**3)
    J_ex = 0.4 * m_ex * (Ro**5 - Ri**5) / (Ro**3 - Ri**3)
    return {"mass": (m, m_ex), "Jxx": (J[0], J_ex), "Jzz": (J[2], J_ex)}, x


def tube_sh3n(n, R=0.05, L=0.2, t=1e-4):
    nodes = M.Nodes(first=2)
    tri = M.tube_sh3n(nodes, 8 * n, 2, R, L)
    m, x, J = body_props(shape_deck("SH3N", tri, nodes, M.prop_shell(2, t)))
    Ro, Ri = R + t / 2, R - t / 2
    m_ex = RHO * math.pi * (Ro**2 - Ri**2) * L
    return {"mass": (m, m_ex), "Jxx": (J[0], m_ex * ((Ro**2 + Ri**2) / 4 + L**2 / 12)),
            "Jzz": (J[2], m_ex * (Ro**2 + Ri**2) / 2)}, x


def cylinder_bricks(n, R=0.05, L=0.2):
    nodes = M.Nodes(first=2)
    b = M.cylinder_bricks(nodes, 8 * n, 2 * n, R, L)
    m, x, J = body_props(shape_deck("BRICK", b, nodes, M.prop_solid(2)))
    m_ex = RHO * math.pi * R * R * L
    return {"mass": (m, m_ex), "Jxx": (J[0], m_ex * (3 * R * R + L * L) / 12), "Jzz": (J[2], m_ex * R * R / 2)}, x


def box_bricks(n, a=0.2, b=0.3, c=0.5):
    nodes = M.Nodes(first=2)
    br = M.box_bricks(nodes, n, (a, b, c), origin=(0.1, -0.2, 0.3))
    m, x, J = body_props(shape_deck("BRICK", br, nodes, M.prop_solid(2)))
    m_ex = RHO * a * b * c
    return {"mass": (m, m_ex), "Jxx": (J[0], m_ex * (b * b + c * c) / 12), "Jzz": (J[2], m_ex * (a * a + b * b) / 12),
            "Jxy": (J[3], 0.0)}, x


def box_shell(n, a=0.2, b=0.3, c=0.5, t=1e-3):
    nodes = M.Nodes(first=2)
    q = M.box_shell(nodes, n, (a, b, c), origin=(0.1, -0.2, 0.3))
    m, x, J = body_props(shape_deck("SHELL", q, nodes, M.prop_shell(2, t)))
    s = RHO * t
    Axy, Axz, Ayz = a * b, a * c, b * c
    m_ex = 2 * s * (Axy + Axz + Ayz)
    # faces as plates of thickness t on their mid-surfaces (docs/theory.md 1.2)
    Jxx = 2 * s * (Axy * (b * b / 12 + c * c / 4 + t * t / 12) + Axz * (c * c / 12 + b * b / 4 + t * t / 12)
                   + Ayz * (b * b + c * c) / 12)
    Jzz = 2 * s * (Ayz * (b * b / 12 + a * a / 4 + t * t / 12) + Axz * (a * a / 12 + b * b / 4 + t * t / 12)
                   + Axy * (a * a + b * b) / 12)
    return {"mass": (m, m_ex), "Jxx": (J[0], Jxx), "Jzz": (J[2], Jzz), "Jxy": (J[3], 0.0)}, x


SHAPES = [
    ("sphere_shell", sphere_shell, "cube-sphere /SHELL quads, R = 0.1 m, t = 0.1 mm", 2),
    ("tube_sh3n", tube_sh3n, "open tube /SH3N, R = 0.05 m, L = 0.2 m, t = 0.1 mm, 8n sectors", 2),
    ("cylinder_bricks", cylinder_bricks, "solid cylinder /BRICK, R = 0.05 m, L = 0.2 m, 8n sectors, 2n rings", 2),
    ("box_bricks", box_bricks, "box 0.2 x 0.3 x 0.5 m, n^3 /BRICK", 0),
    ("box_shell", box_shell, "closed box 0.2 x 0.3 x 0.5 m, 6 n^2 /SHELL, t = 1 mm", 0),
]
LEVELS = (4, 8, 16, 32)


def study():
    """{shape: [(n, {quantity: relative error})]}"""
    out = {}
    for name, fn, _, _ in SHAPES:
        rows = []
        for n in LEVELS:
            q, _ = fn(n)
            errs = {}
            for k, (v, ref) in q.items():
                scale = abs(ref) if ref != 0 else abs(q["Jxx"][1])
                errs[k] = abs(v - ref) / scale
            rows.append((n, errs))
        out[name] = rows
    return out


if __name__ == "__main__":
    res = study()
    for name, _, desc, _ in SHAPES:
        print(f"{name}: {desc}")
        prev = None
        for n, e in res[name]:
            s = "  ".join(f"{k} {v:.3e}" for k, v in e.items())
            if prev:
                s += "  orders " + " ".join(
                    f"{k} {math.log2(prev[k] / e[k]):.2f}" for k in e if prev[k] > 0 and e[k] > 0)
            print(f"  n = {n:2d}: {s}")
            prev = e
