/*
 * Mass properties of the rigid bodies from their mesh (docs/theory.md,
 * "Mass properties from the mesh"): exact integrals of the elements
 * (triangles and bilinear quadrilaterals as plates of thickness t, linear
 * and quadratic tetrahedra, trilinear hexahedra and pentahedra (a
 * degenerate hexahedron)), combined with the /RBODY card's added
 * Mass and J as Radioss combines them (ICoG, Ispher, Skew_ID).
 */
#ifndef RC_MASSPROP_H
#define RC_MASSPROP_H

#include "ricochet/ricochet.h"
#include "case/case.h"

/* Sums over a body about a reference point r0 (coordinates relative to r0):
 * mass m = int dm [kg], first moment s = int r dm [kg m], second moment
 * S = int r r^T dm [kg m^2] (xx yy zz xy yz xz). */
typedef struct rc_mp {
    double m, s[3], S[6];
} rc_mp;

/* Add one element (vertices relative to r0). Plates: areal mass sigma =
 * rho t [kg/m^2], thickness t [m] (the through-thickness term
 * sigma t^2/12 n n^T per unit area is included). Solids: density rho
 * [kg/m^3]; the orientation of the node numbering does not matter.
 * Each returns the element's area [m^2] or volume [m^3]. */
double rc_mp_tri(rc_mp *a, const double p[3][3], double sigma, double t);
double rc_mp_quad(rc_mp *a, const double p[4][3], double sigma, double t);
double rc_mp_tet(rc_mp *a, const double p[4][3], double rho);
double rc_mp_hex(rc_mp *a, const double p[8][3], double rho);
/* The quadratic (10-node) tetrahedron: corners, then the mid-edge nodes of
 * 01 12 20 03 13 23 (isoparametric; exact by a 125-point rule). */
double rc_mp_tet10(rc_mp *a, const double p[10][3], double rho);

/* Centre of mass c (relative to r0) and the inertia tensor about it,
 * row-major 3x3 [kg m^2]; m must be > 0. */
void rc_mp_inertia(const rc_mp *a, double c[3], double J[9]);

/* One body's mass properties, ready for the model. */
typedef struct rc_body_mp {
    double mass;   /* [kg] */
    double x[3];   /* centre of mass, global, t = 0 [m] */
    double J[9];   /* inertia about x, global axes, row-major [kg m^2] */
    int nelem;     /* elements of the mesh in the body */
    double mesh_mass; /* [kg] */
} rc_body_mp;

/* Mass properties of every /RBODY (out[nrbody]): the elements whose nodes
 * are all in the body's node set, the card's Mass and J, ICoG, Ispher.
 * Input errors (RC_EINPUT) name file:line, card and field: unknown ids, an
 * element across bodies or partly outside one, parts with elements in no
 * body, materials without a density, a total mass or inertia that is no
 * body's. */
rc_status rc_massprop_bodies(const rc_case *c, rc_body_mp *out, rc_error *err);

#endif
