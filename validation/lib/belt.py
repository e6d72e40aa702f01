"""The block-on-a-belt scaffold shared by the stick-slip problems
(frc_stick_slip, stick_belt): a sphere (radius R [m], mass M [kg], body 1)
resting with the static penetration M g / K on the plane z = 0 of a belt of
mass MBELT [kg] (body 2) moving at V [m/s] along x; the block held in y and
in rotation, the belt moving along x only; gravity -G on the block only.
Interface and spring are the caller's."""


def _num(x):
    return f"{x:g}".replace("e+0", "e").replace("e+", "e")


def add_block_on_belt(d, R, M, K, G, MBELT, V):
    """Add the cards; returns z0, the block centre's height [m]."""
    z0 = R - M * G / K  # static penetration: F_n = m g
    d.funct(1, [0.0, 1.0], [0.0, K], title=f"linear load curve k = {_num(K)} N/m")
    d.nodes([(1, 0.0, 0.0, z0), (2, 0.0, 0.0, -1.0)])
    d.rbody(1, 1, M, [0.4 * M * R * R] * 3, grnod=1, title=f"block {_num(M)} kg")
    d.rbody(2, 2, MBELT, [MBELT] * 3, grnod=2, title=f"belt {_num(MBELT)} kg")
    d.sphere(1, 1, (0.0, 0.0, z0), R, title="block sphere")
    d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), body=2, title="belt surface z = 0")
    d.grnod(1, [1], title="block")
    d.grnod(2, [2], title="belt")
    d.bcs(1, 1, "010 111", title="block held in y, no rotation")
    d.bcs(2, 2, "011 111", title="belt moves along x only")
    d.inivel(1, (V, 0.0, 0.0), 2)
    d.inivel(2, (V, 0.0, 0.0), 1)
    d.grav(1, "Z", -G, 1)  # on the block only
    return z0
