/*
 * /INTER/TYPE7 compiled as one-way node-to-surface contacts (model/type7.c,
 * docs/theory.md "TYPE7 contact"). The secondary nodes (grnd_IDs) of each
 * body become a segment surface of points on that body; each such surface
 * gets a TYPE6 contact with the main surface (surf_IDm), one way (its nodes
 * against the main surface's segments only), of a linear law F = k P
 * (k = Stfac, Istf 1; Stfac E t / 2 of the main shells, Istf 0), damping VISs of the critical one and Coulomb
 * friction Fric (or the /FRICTION card fric_ID). The compiler works on a
 * copy of the case with these surfaces, contacts and their load curve
 * appended; the deck's own arrays are untouched.
 *
 * /INTER/TYPE24 (and /INTER/TYPE25, whose two /SURF/BOX surfaces meet
 * through the box pair, edges included) take the same path without point
 * surfaces: one TYPE6
 * contact of its two segment surfaces, both ways (the nodes of each
 * against the segments of the other), the same linear law (k = Stfac,
 * Istf 1; Stfac E t / 2, the mean over the shells of both surfaces, Istf 0),
 * zero gap, VISs, Fric or fric_ID.
 */
#ifndef RC_MODEL_TYPE7_H
#define RC_MODEL_TYPE7_H

#include "case/case.h"
#include "model/model.h"

/* The ids of the point surfaces made here: RC_TYPE7_SURF_ID0 - k, below
 * every id a deck or a wall can have (other stages skip them by id). */
#define RC_TYPE7_SURF_ID0 (-1000000000)
/* The id of the unit load curve y = x of the contacts. */
#define RC_TYPE7_FUNCT_ID (-2)

typedef struct rc_type7_case {
    rc_case c;               /* the case with the point surfaces, contacts and load curve */
    rc_case_surf *surf;      /* [nsurf + npts] owned */
    rc_case_funct *funct;    /* [nfunct + 1] owned */
    rc_case_type6 *type6;    /* [ntype6 + contacts] owned (rc_type7_contacts) */
    char (*name)[128];       /* [npts] the contacts' names */
    int npts;                /* point surfaces: indices nuser .. nuser + npts - 1 */
    int nuser;               /* the surfaces before them */
    int *pts_t7;             /* [npts] the TYPE7 card (index) of each */
    int **pts_node;          /* [npts] its node ids (owned) */
    double len;              /* abscissa scale of the load curve [m]: the scene's size */
    double *k;               /* [ntype7] each card's stiffness [N/m] (Istf 1: Stfac; 0: main_stiffness) */
    double *km;              /* [ntype7] Istf 0, 2-5: the main side's stiffness [N/m], unbounded */
    double *gm;              /* [ntype7] Igap 1, 2: the main side's gap, half the main shells' thickness [m] */
    double *k24;             /* [ntype24] each TYPE24 card's stiffness [N/m] */
    char (*name24)[64];      /* [ntype24] the TYPE24 contacts' names */
    rc_case_surf *bx;        /* [2 ntype24] TYPE25 Iedge, TYPE11, TYPE19: the box of each side that is a closed
                                box mesh (kind BOX), or zeros */
    int *side;               /* [2 ntype24] TYPE11, TYPE19: the surface id of each side (a /SURF/BOX or a
                                closed box mesh; TYPE11 through its /LINE/SURF), else 0 */
    int nbx;                 /* the boxes made (appended after the point surfaces) */
    rc_case_type24 *t24;     /* [ntype24] the cards of the copy, naming those boxes */
    int *mainsurf;           /* [ntype7] the main surface of each card's contacts: surf_IDm, or (Inacti 2 with
                                segments left out) the id of its copy without them; 0: none left */
    int **mseg;              /* [ntype7] those copies' segment arrays (owned): 4 ids each, then ids, */
    rc_loc **mloc;           /*           and their lines */
    int *dropped;            /* [ntype7] what Inacti 1, 2 left out of each card (rc_t7_drop.n) */
    int nt7;                 /* ntype7 (the arrays above) */
    double fx[2], fy[2];     /* the load curve: the line y = x through (0, 0), (1, 1) */
} rc_type7_case;

/* The copy of c with one point surface per TYPE7 card and body of its
 * secondary nodes (less those drop leaves out, Inacti 1; drop NULL: none),
 * a copy of the main /SURF/SEG of each card whose Inacti 2 leaves segments
 * out (without them), and the unit load curve; x->c is c itself when c has no
 * TYPE7 or TYPE24. RC_EINPUT for a group or surface that does not exist, a main
 * surface that is not a segment surface, a plane or a box, and (Istf 0)
 * main segments that are not shells with a Young's modulus and a
 * thickness. */
rc_status rc_type7_begin(const rc_case *c, const rc_t7_drop *drop, rc_type7_case *x, rc_error *err);
/* The contacts, appended to c->type6 (c: the case being compiled, the
 * copy of x->c or x->c itself) once the surfaces are compiled: one per
 * point surface whose body is not the main surface's (none for a card
 * whose Inacti 1 or 2 left no node or no main segment). */
rc_status rc_type7_contacts(rc_type7_case *x, rc_case *c, const rc_model *m, rc_error *err);
/* 1 when surface id sid is a TYPE7 point surface. */
static inline int rc_type7_is_points(int sid) { return sid <= RC_TYPE7_SURF_ID0; }
void rc_type7_end(rc_type7_case *x);

#endif
