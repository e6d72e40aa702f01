/*
 * Rigid walls (/RWALL) compiled as contacts (model/rwall.c,
 * docs/theory.md "Rigid walls"). A wall becomes a fixed analytic surface
 * (plane, sphere, long cylinder) and one penalty contact, a TYPE6 law made
 * by the compiler, between it and each surface of each body that owns a
 * node the wall acts on. The compiler works on a copy of the case with
 * these surfaces, contacts and their load curve appended; the deck's own
 * arrays are untouched.
 */
#ifndef RC_MODEL_RWALL_H
#define RC_MODEL_RWALL_H

#include "case/case.h"
#include "model/model.h"

/* The wall's penetration under the body's weight, as a fraction of the
 * body's radius of gyration sqrt((Jxx + Jyy + Jzz) / (2 m)) [-]. */
#define RC_RWALL_PEN_FRAC 1e-4
/* The smallest acceleration the stiffness is sized for: standard gravity
 * [m/s^2] (a body without gravity gets the stiffness it would have under it). */
#define RC_RWALL_G_REF 9.80665
/* The restitution of a wall's contact [-]: Radioss's kinematic wall stops
 * the normal velocity (a plastic impact); the damping that gives this is
 * derived as for a TYPE6 e_target. */
#define RC_RWALL_RESTITUTION 0.01
/* An /RWALL/CYL is infinite: its cylinder reaches this many times the
 * scene's size (the largest distance of a node from M at t = 0, plus the
 * diameter) beyond M on either side [-]. */
#define RC_RWALL_CYL_REACH 1e3

typedef struct rc_rwall_case {
    rc_case c;               /* the case with the walls' surfaces, contacts and load curve */
    rc_case_surf *surf;      /* [nsurf + nrwall] owned */
    rc_case_type6 *type6;    /* [ntype6 + contacts] owned */
    rc_case_funct *funct;    /* [nfunct + 1] owned */
    char (*name)[96];        /* [contacts] the contacts' names */
    rc_case_rwall *rwall;    /* [nrwall] owned: a moving wall's M set to its node */
    rc_case_rbody *rbody;    /* [nrbody + moving walls] owned: a moving wall's body */
    rc_case_grnod *grnod;    /* [ngrnod + moving walls] owned: its node's group */
    rc_case_bcs *bcs;        /* [nbcs + moving walls] owned: its rotations held */
    rc_case_inivel *inivel;  /* [ninivel + moving walls] owned: its VX0 VY0 VZ0 */
    int *wall_body;          /* [nrwall] body index of a moving wall, -1: fixed */
    int *wall_node;          /* [nrwall] its node id (the groups' storage) */
    unsigned char *acts;     /* [nrwall * nrbody] 1: wall w acts on body b */
    unsigned char *nodes;    /* [nrwall * nnode] 1: wall w acts on node n (by index) */
    int nuser;               /* the deck's surfaces: 0 .. nuser-1; the walls' next;
                                then the points of bodies without surfaces */
    int npts;                /* point surfaces: nuser + nrwall + k, k < npts */
    int *pts_wall;           /* [npts] the wall of each */
    int **pts_node;          /* [npts] its node ids (owned) */
    double fx[2], fy[2];     /* the load curve: the line y = x through (0, 0), (1, 1) */
} rc_rwall_case;

/* The copy of c with the walls' surfaces (ids -rwall_ID) and the unit load
 * curve (id -1) appended, and for each moving wall (node_ID) a body of its
 * node (/RBODY -rwall_ID: its Mass, rotations held, VX0 VY0 VZ0) carrying
 * its surface; x->c is c itself when c has no wall. RC_EINPUT for a
 * moving wall's node that does not exist, belongs to a /RBODY (not
 * supported yet) or lies on M1. */
rc_status rc_rwall_begin(const rc_case *c, rc_rwall_case *x, rc_error *err);
/* The bodies each wall acts on (grnd_ID1, the nodes within d, minus
 * grnd_ID2; fixed bodies and the walls' own bodies left out), once the
 * bodies are compiled; a moving wall's gravity: the /GRAV cards whose
 * group holds its node. */
rc_status rc_rwall_bodies(rc_rwall_case *x, rc_model *m, rc_error *err);
/* The contact points of the bodies without a surface that a plane wall
 * acts on: its nodes of each such body, as a segment surface of points
 * (appended to the model's surfaces once the deck's are compiled). */
rc_status rc_rwall_points(rc_rwall_case *x, rc_model *m, rc_error *err);
/* Flag the boxes a plane wall meets: their corners are the contact points. */
void rc_rwall_box_flags(const rc_rwall_case *x, unsigned char *corners);
/* The contacts, appended to x->c.type6 once the surfaces are compiled. */
rc_status rc_rwall_contacts(rc_rwall_case *x, const rc_model *m, rc_error *err);
void rc_rwall_end(rc_rwall_case *x);

#endif
