"""A solid sphere over the fixed plane z = 0, the scaffold of the impact and
bounce problems (hertz, the pw_* power-law impacts, the t6_* TYPE6 impacts,
the bouncing balls): node 1 at the sphere's centre, rigid body 1 on it with
the inertia of a homogeneous ball, sphere surface 1, plane surface 2 through
the origin with normal +z, node group 1 holding node 1. The load curves, the
interface, gravity and the run are the caller's."""


def add_sphere_over_plane(d, m, r, z0, v0=None, title=None):
    """Add the cards: a sphere of mass m [kg] and radius r [m] (inertia
    0.4 m r^2 [kg m^2] about each axis) centred at (0, 0, z0) [m], and the
    plane. With v0 [m/s] given, the sphere starts moving straight down at v0
    (/INIVEL (0, 0, -v0) on node group 1). title: the /RBODY title (the
    deck writer's default when None)."""
    d.nodes([(1, 0.0, 0.0, z0)])
    if title is None:
        d.rbody(1, 1, m, [0.4 * m * r * r] * 3)
    else:
        d.rbody(1, 1, m, [0.4 * m * r * r] * 3, title=title)
    d.sphere(1, 1, (0.0, 0.0, z0), r)
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
    d.grnod(1, [1])
    if v0 is not None:
        d.inivel(1, (0.0, 0.0, -v0), 1)
