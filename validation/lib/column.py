"""The column of n equal spheres standing on a floor, each on the one
below (TYPE6, linear load curve 1), held to the vertical by /BCS, and a
Hertz sphere beside it on the same floor (the power law, m1 = 1.5): the
model of static_column and preload_column. The caller gives the load
curve's funct cards and the gravity (a function of the deck), and adds
/RUN and /SOLVER."""


# The model of both problems: N spheres of mass M [kg] and radius R [m],
# contacts k = K [N/m], g = G [m/s^2]; the Hertz sphere: mass MH [kg],
# radius RH [m], K_H = KH [N/m^1.5], at x = XH [m]; the floor's surface id.
N, M, R, K, G = 5, 1.0, 0.0625, 1.0e5, 9.81
MH, RH, KH = 2.0, 0.0625, 1.0e8
XH = 1.0
FLOOR = N + 2


def column_cards(d, n, r, m, mh, rh, kh, xh, floor, gravity):
    z = [r + 2.0 * r * i for i in range(n)]  # exact binary numbers: every contact starts at zero gap
    d.nodes([(i + 1, 0.0, 0.0, z[i]) for i in range(n)] + [(n + 1, xh, 0.0, rh)])
    for i in range(n):
        d.rbody(i + 1, i + 1, m, [0.4 * m * r * r] * 3, grnod=i + 1, title=f"sphere {i + 1} (from the bottom)")
    d.rbody(n + 1, n + 1, mh, [0.4 * mh * rh * rh] * 3, grnod=n + 1, title="Hertz sphere")
    for i in range(n):
        d.sphere(i + 1, i + 1, (0.0, 0.0, z[i]), r, title=f"sphere {i + 1}")
    d.sphere(n + 1, n + 1, (xh, 0.0, rh), rh, title="Hertz sphere")
    d.plane(floor, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), title="floor z = 0")
    for i in range(n + 1):
        d.grnod(i + 1, [i + 1], title=f"sphere {i + 1}")
    d.grnod(n + 2, list(range(1, n + 2)), title="all spheres")
    # a frictionless column is laterally unsupported: held to the vertical
    d.bcs(1, n + 2, "110 000", title="held to the vertical")
    gravity(d)
    d.type6(1, 1, floor, 1, title="floor - sphere 1")
    for i in range(1, n):
        d.type6(i + 1, i, i + 1, 1, title=f"sphere {i} - sphere {i + 1}")
    d.power(n + 1, n + 1, floor, k=kh, m1=1.5, c=0.0, title="Hertz sphere - floor")
