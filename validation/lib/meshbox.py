"""A rigid box with a meshed surface and a meshed floor, shared by the
meshed-box problems (seg_box_slide_stop, seg_box_filter_slide) and the
benchmarks (bench/seg_bench.py, bench/evcost_bench.py).

The box A x B x C [m], mass M [kg], centre at (0, 0, z0 + C/2): its bottom
face at z = z0 in nx x ny quadrilaterals (nodes 100000 + i (ny + 1) + j),
its top corners nodes 90001..90004, every other face one quadrilateral;
node 1 is the centre of mass, node group 7 holds the surface nodes, body 1
the box, /SURF/SEG/30 its faces with outward normals (add_box). The floor
(add_floor) is a fixed plate in z = 0, /SURF/SEG/40.
"""
from deck import line


def add_box(d, nx, ny, A, B, C, M, z0):
    nodes, bottom = [], {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            nid = 100000 + i * (ny + 1) + j
            bottom[(i, j)] = nid
            nodes.append((nid, -A / 2 + A * i / nx, -B / 2 + B * j / ny, z0))
    top = {}
    for k, (sx, sy) in enumerate(((-1, -1), (1, -1), (1, 1), (-1, 1))):
        top[(sx, sy)] = 90001 + k
        nodes.append((90001 + k, sx * A / 2, sy * B / 2, z0 + C))
    d.nodes([(1, 0.0, 0.0, z0 + C / 2)] + nodes)
    d.grnod(7, [n[0] for n in nodes], title="box nodes")
    d.rbody(1, 1, M, (M * (B * B + C * C) / 12, M * (A * A + C * C) / 12, M * (A * A + B * B) / 12), grnod=7,
            title="box")
    quads = [(bottom[(i, j)], bottom[(i, j + 1)], bottom[(i + 1, j + 1)], bottom[(i + 1, j)])
             for i in range(nx) for j in range(ny)]  # bottom: normals down, out of the box
    c00, c10, c11, c01 = bottom[(0, 0)], bottom[(nx, 0)], bottom[(nx, ny)], bottom[(0, ny)]
    t00, t10, t11, t01 = top[(-1, -1)], top[(1, -1)], top[(1, 1)], top[(-1, 1)]
    quads += [(t00, t10, t11, t01), (c00, c10, t10, t00), (c10, c11, t11, t10), (c11, c01, t01, t11),
              (c01, c00, t00, t01)]
    d.add("/SURF/SEG/30", *[line(*[("i", v) for v in (k + 1,) + q]) for k, q in enumerate(quads)], title="box faces")
    return len(quads)


def add_floor(d, L, W, n, x0, title="meshed floor (fixed)"):
    """A fixed plate in z = 0, L x W [m] from x = x0 along x and centred on
    y = 0, in n quadrilaterals along x and as many along y as keep them
    about square (nodes 200000 + i (py + 1) + j), normals up: /SURF/SEG/40.
    Returns the number of quadrilaterals."""
    py = max(1, round(n * W / L))
    pid, pn = {}, []
    for i in range(n + 1):
        for j in range(py + 1):
            nid = 200000 + i * (py + 1) + j
            pid[(i, j)] = nid
            pn.append((nid, x0 + L * i / n, -W / 2 + W * j / py, 0.0))
    d.nodes(pn)
    ps = [line(*[("i", v) for v in (k + 1, pid[(i, j)], pid[(i + 1, j)], pid[(i + 1, j + 1)], pid[(i, j + 1)])])
          for k, (i, j) in enumerate((i, j) for i in range(n) for j in range(py))]
    d.add("/SURF/SEG/40", *ps, title=title)
    return len(ps)
