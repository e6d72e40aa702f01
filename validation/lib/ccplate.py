"""A square plate as a rigid body whose contact surface is its bottom face,
meshed as n x n quadrilaterals (/SURF/SEG), for the contact-coupling
validation problems. The centre of mass lies in the plane of the faces, so
that forces in that plane exert no pitching moment."""
from deck import line


def plate(d, m, side, z, n=2, J=(0.01, 0.01, 0.02), body=1, surf=5, first_node=10):
    """Add the plate body (main node 1 at (0, 0, z)), its node groups and
    /SURF/SEG `surf`; node group 2 holds the main node (for /INIVEL)."""
    nodes = [(1, 0.0, 0.0, z)]
    ids = {}
    nid = first_node
    for i in range(n + 1):
        for j in range(n + 1):
            nodes.append((nid, -side / 2 + side * i / n, -side / 2 + side * j / n, z))
            ids[(i, j)] = nid
            nid += 1
    d.nodes(nodes)
    d.grnod(1, [p[0] for p in nodes[1:]], title="plate nodes")
    d.rbody(body, 1, m, list(J), grnod=1, title="plate")
    segs = []
    for i in range(n):
        for j in range(n):
            segs.append(line(("i", len(segs) + 1), ("i", ids[(i, j)]), ("i", ids[(i + 1, j)]),
                             ("i", ids[(i + 1, j + 1)]), ("i", ids[(i, j + 1)])))
    d.add(f"/SURF/SEG/{surf}", *segs, title=f"plate bottom, {n} x {n} quadrilaterals")
    d.grnod(2, [1], title="plate main node")
