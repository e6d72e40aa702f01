/*
 * Body couplings (docs/theory.md 8, STAR-CCM+ style): spring-dampers and
 * elastic catenaries between two body points, or a body point and
 * a point fixed in space. docs/theory.md section "Couplings" has the
 * equations as implemented.
 *
 * Contact couplings (RC_CPL_CONTACT): model/coupling_contact.h.
 *
 * Joint stops (RC_CPL_LIMIT): the stops of a /JOINT/REVOLUTE or
 * /JOINT/PRISMATIC (line 4 of the card), compiled as couplings after the
 * /COUPLING cards (k >= ncard): a contact law on the joint coordinate q
 * (rotation angle about the axis [rad], slide along it [m], 0 in the
 * initial configuration) that acts while q is past a stop and its force
 * does not pull (docs/theory.md, "Joint stops").
 *
 * Model side (constant): rc_couplings, one flat array per field, reached
 * from rc_model.cpl. Data side (mutable): rc_cpl_data in rc_data.cpl, the
 * catenary warm starts and the GSL workspace, allocated once per run so
 * that the right-hand side never allocates.
 *
 * States: two energy accumulators per coupling, at cpl->eadr[k]:
 *   spring:   [0] W_el   work of the elastic force (stored energy)  [J]
 *             [1] W_damp energy dissipated by the damper            [J]
 *   catenary: [0] W_cat  work done on the line by its ends = change of
 *                        its elastic + gravitational energy          [J]
 *             [1] unused (kept at zero)                              [J]
 *   limit:    [0] W_el   work of the stop's elastic part K pen       [J]
 *             [1] W_damp energy dissipated by its damper            [J]
 */
#ifndef RC_COUPLING_H
#define RC_COUPLING_H

#include <stdio.h>

#include "model/model.h"

#define RC_CE 2 /* energy states of a coupling */

/* Coupling kinds. */
typedef enum { RC_CPL_SPRING = 1, RC_CPL_CATENARY = 2, RC_CPL_CONTACT = 3, RC_CPL_LIMIT = 4 } rc_cpl_kind;

/* Joint stop modes (rc_cpl_data.lmode): q within the stops, past the lower
 * (upper) stop pushing, or past it with a force that would pull (released). */
enum { RC_LIM_FREE = 0, RC_LIM_LO_PUSH = 1, RC_LIM_LO_REL = 2, RC_LIM_HI_PUSH = 3, RC_LIM_HI_REL = 4 };
/* Root functions per joint stop coupling, after the contact couplings'
 * faces: q - q_min, q_max - q (1 without that stop), the unclipped force
 * of the stop q is past (1 within the stops). */
#define RC_LIM_ROOTS 3
/* A general or beam spring with rupture deformations (form 5, grup >= 0):
 * rc_cpl_data.lmode 0 whole, RC_SPR_BROKEN once a deformation has reached
 * its bound (for good: no force after). One root per such spring, after the
 * joint stops': the least distance of a deformation to its bound
 * (docs/theory.md 8.1). */
#define RC_SPR_BROKEN 1

/* Stiffness forms of a spring-damper (docs/theory.md 8, card field Iform). */
typedef enum {
    RC_KEFF_CONST = 1, /* k_eff = k                                        */
    RC_KEFF_POLY = 2,  /* k_eff = a + b (x - x0) + c (x - x0)^2             */
    RC_KEFF_FORCE = 3, /* tabulated elastic force f_e(x)                   */
    RC_KEFF_STIFF = 4, /* tabulated stiffness k(x), integrated              */
    RC_KEFF_GENE = 5   /* a /PROP/TYPE8 general spring or /PROP/TYPE13
                          beam spring: six linear stiffnesses and
                          dampings in a frame fixed in space or turning
                          with one end's body (docs/theory.md 8.1)        */
} rc_keff_form;

/* Horizontal spans below this fraction of L_eq are treated as vertical
 * lines (docs/theory.md, catenary limits) [-]. */
#define RC_CAT_XMIN_REL 1e-12

typedef struct rc_couplings {
    int n;
    int ncard;           /* couplings of /COUPLING cards (0..ncard-1); the
                            joint stops follow (ncard..n-1)                  */
    int *id;             /* [n] card id                                       */
    rc_cpl_kind *kind;   /* [n]                                               */
    const char **type;   /* [n] "SPRING" or "CATENARY" (static strings)       */
    char **name;         /* [n] "/COUPLING/SPRING/<id>"                       */
    int *b1, *b2;        /* [n] body index of each end, -1: fixed in space    */
    double *s1, *s2;     /* [n*3] attachment points in the body frame (offset
                            from the centre of mass), or global points for an
                            end fixed in space [m]                            */
    int *eadr;           /* [n] offset of the RC_CE energy states in y        */
    /* spring-damper */
    rc_keff_form *form;  /* [n]                                               */
    double *x0;          /* [n] relaxation length [m]                         */
    double *kd;          /* [n] damping coefficient [N s/m]                   */
    double *coef;        /* [n*3] form 1: k; form 2: a [N/m], b [N/m^2], c [N/m^3] */
    int *table;          /* [n] table index of f_e or k (forms 3, 4), else -1 */
    double *fref, *xref; /* [n] form 4: force [N] at distance [m] where the
                            integral starts (f_r at x_r, or 0 at x0)          */
    double **cum;        /* [n] form 4: [table n] integral of k from the first
                            abscissa to each abscissa [N]; else NULL         */
    /* form 5 (general spring, /PROP/TYPE8): the frame in lfrm (rows: the
     * axes X', Y', Z' in global axes), the initial separation of the ends */
    double *gk;          /* [n*12] K1..K6 [N/m, N m/rad], C1..C6 [N s/m,
                            N m s/rad]                                       */
    double *gd0;         /* [n*3] p2 - p1 at t = 0, global [m]               */
    int *gtab;           /* [n*6] per direction the table of the elastic
                            curve f_i (fct_ID1i), -1: the linear K_i       */
    double *gsc;         /* [n*12] the curves' scales A_1..A_6 [N, N m],
                            Ascale_1..Ascale_6 [m, rad]: F_i = A_i f_i(u_i /
                            Ascale_i)                                       */
    double *gdlo, *gdhi; /* [n*6] rupture bounds of u_1..u_3 [m], theta_1..
                            theta_3 [rad]: -inf, +inf none                  */
    int *grup;           /* [n] index of the spring's rupture root among
                            them, -1: no rupture                            */
    int nrup;            /* springs with rupture                            */
    int *gfb;            /* [n] the end whose body carries the frame: 0 none
                            (fixed in space), 1 or 2; the frame in lfrm is
                            then its axes at t = 0 (body frame = global)   */
    /* catenary */
    double *lambda0;     /* [n] mass per unstretched length [kg/m]            */
    double *leq;         /* [n] unstretched length [m]                        */
    double *ea;          /* [n] axial rigidity EA = D L_eq [N]                */
    double grav[3];      /* gravity acting on the lines per unit value of the
                            gravity function (the /GRAV cards with
                            grnod_ID 0) [m/s^2]                              */
    rc_jblock *jb;       /* [n] Jacobian blocks                               */
    rc_loc *law_loc;     /* [n] file:line of the card line holding the law's
                            fields (catenary: Lambda0 L_eq D), for messages  */
    struct rc_cpl_contact *ct; /* contact couplings (coupling_contact.h)      */
    /* joint stops (kind RC_CPL_LIMIT; b1, s1: the joint's body a and its
     * anchor, b2, s2: body b (or the ground); coef[3k] the stiffness K
     * [N/m] or [N m/rad], kd the damping C [N s/m] or [N m s/rad]) */
    int *ljoint;         /* [n] index of the joint (case order), -1          */
    int *lrev;           /* [n] 1: revolute (q an angle), 0: prismatic       */
    double *lfrm;        /* [9n] joint frame (axis, two normals), the body
                            frames of a and b (equal at t = 0) [-]; a
                            general spring's frame                          */
    double *llo, *lhi;   /* [n] stops q_min, q_max; -inf, +inf: none         */
} rc_couplings;

/* Solution of the catenary equations for one span (X, Y): end forces and
 * their derivatives by the implicit-function theorem. */
typedef struct rc_cat_sol {
    double X, Y;         /* horizontal span >= 0, height of end 2 over end 1 [m] */
    double w;            /* weight per unstretched length lambda0 |g| [N/m]  */
    double H;            /* horizontal tension c [N]                         */
    double V1, V2;       /* vertical tension components c sinh u1, c sinh u2 [N];
                            V2 = V1 + w L_eq                                 */
    double dH[2], dV1[2];/* d(H, V1)/d(X, Y) [N/m]                           */
    double kappa;        /* vertical line (X ~ 0): H = kappa X [N/m]         */
    int vertical;        /* 1: X below RC_CAT_XMIN_REL L_eq                  */
    int iter;            /* solver iterations used                           */
} rc_cat_sol;

/* What the output sees of one coupling. */
typedef struct rc_cpl_report {
    double length;       /* distance between the end points [m]              */
    double rate;         /* its time derivative [m/s]                        */
    double force;        /* spring: f = f_el + f_damp (> 0 pulls the ends
                            together); catenary: tension at end 1 [N]       */
    double f1[3], f2[3]; /* force applied to end 1 and to end 2, global [N]  */
    double c, u1, u2;    /* catenary parameters (docs/theory.md 8); 0 for springs      */
    double def[6];       /* general spring: u_1..u_3 [m], theta_1..theta_3
                            [rad] in its frame; 0 for the others          */
    double lowest;       /* catenary: height of its lowest point along -g,
                            from the origin [m] (an end when the line does
                            not sag below it); NaN for springs              */
} rc_cpl_report;

/* Mutable per-run data. */
typedef struct rc_cpl_data {
    double *warm;        /* [n*2] last catenary solution (H, V1), NaN: none  */
    void *ws;            /* catenary solver workspace (GSL)                  */
    int fail;            /* coupling whose forces failed in the last call, -1 */
    int *fmode;          /* [ct->nface] contact coupling face modes RC_FACE_* */
    int *lmode;          /* [n] joint stop modes RC_LIM_*; a spring with
                            rupture: 0 or RC_SPR_BROKEN (other kinds: 0)   */
} rc_cpl_data;

/* ---- compile (model/coupling.c) ---------------------------------- */
struct rc_case;
/* Resolve and check the /COUPLING cards into m->cpl (always allocated). */
rc_status rc_cpl_compile(const struct rc_case *c, rc_model *m, rc_error *err);
/* Lay out the energy states from offset ny; returns the new state count. */
int rc_cpl_layout(rc_model *m, int ny);
/* Absolute tolerances of the coupling states (m->atol allocated). */
void rc_cpl_atol(rc_model *m);
/* Jacobian block of coupling k: rows = accelerations of its free bodies and
 * its energy states, columns = all states of its free bodies. */
void rc_cpl_block(const rc_model *m, int k, rc_jblock *jb);
void rc_cpl_free(rc_couplings *cpl);

/* ---- data ------------------------------------------------------------ */
rc_cpl_data *rc_cpl_data_new(const rc_model *m);
void rc_cpl_data_free(rc_cpl_data *cd);

/* ---- spring stiffness tables (coupling_spring.c) -------------------- */
/* Form 4: cumulative integral of the stiffness table by GSL quadrature. */
rc_status rc_cpl_stiff_table(const rc_table *t, double *cum, rc_error *err);
/* Form 4: elastic force f = fref + integral from xref to x of k, and k(x). */
void rc_cpl_stiff_force(const rc_couplings *cpl, const rc_table *t, int k, double x, double *f,
                        double *dfdx);

/* ---- catenary solver (coupling_catenary.c) -------------------------- */
void *rc_cat_ws_new(void);
void rc_cat_ws_free(void *ws);
/* Solve catenary k for span X >= 0, height Y, weight per length w > 0,
 * starting from warm[2] (H, V1) when finite (updated on success). `ws` may
 * be NULL (a temporary workspace is used: not for the right-hand side).
 * Returns 0, or 1 when the solver fails (recoverable). */
int rc_cat_solve(const rc_couplings *cpl, int k, void *ws, double *warm, double X, double Y,
                 double w, rc_cat_sol *sol);

/* Joint stop couplings: their number (n - ncard). */
static inline int rc_cpl_nlim(const rc_model *m) { return m->cpl ? m->cpl->n - m->cpl->ncard : 0; }
#endif
