/*
 * The mesh of a case: elements, properties, materials, skew frames and the
 * node groups defined from parts or other groups (cards_mesh.c,
 * docs/case-format.md). Read as written; the model stage (model/massprop.c)
 * turns it into the mass properties of the rigid bodies.
 */
#ifndef RC_CASE_MESH_H
#define RC_CASE_MESH_H

#include "case/case.h"

/* Element kinds and their node counts. */
typedef enum {
    RC_ELEM_SHELL = 1,  /* /SHELL: 4 nodes (node 4 = node 3 or blank: triangle) */
    RC_ELEM_SH3N = 2,   /* /SH3N: 3 nodes */
    RC_ELEM_BRICK = 3,  /* /BRICK: 8 nodes (repeated nodes allowed: degenerate) */
    RC_ELEM_TETRA4 = 4, /* /TETRA4: 4 nodes */
    RC_ELEM_PENTA6 = 5, /* /PENTA6: 6 nodes, triangle 1-2-3 and its opposite 4-5-6 (node k+3 above node k) */
    RC_ELEM_TETRA10 = 6 /* /TETRA10: 4 corners, then the mid-edge nodes of 1-2, 2-3, 3-1, 1-4, 2-4, 3-4
                           (0: the edge's midpoint, a straight edge) */
} rc_elem_kind;

/* One element. */
typedef struct rc_case_elem {
    int id;
    int part_id;       /* from the card header /SHELL/part_ID */
    rc_elem_kind kind;
    int nn;            /* nodes used: 3, 4, 6, 8 or 10 */
    int nodes[10];     /* node ids (TETRA10: a mid-edge node may be 0) */
    double thick;      /* shells: element thickness [m] (0: the property's) */
    rc_loc loc;        /* the element's line */
} rc_case_elem;

/* /SPRING/part_ID: one spring element between two nodes (its law is the
 * part's /PROP/SPRING; the model stage makes it a coupling of the bodies
 * that carry the nodes, model/coupling.c). */
typedef struct rc_case_spring {
    int id;            /* sprg_ID */
    int part_id;       /* from the card header */
    int nodes[2];      /* node_ID1, node_ID2 */
    int skew_id;       /* Skew_ID (TYPE8, TYPE13; 0: the property's) */
    rc_loc loc;        /* the element's line */
} rc_case_spring;

/* /PROP/SHELL (/PROP/TYPE1), /PROP/SOLID (/PROP/TYPE14) and the spring
 * properties /PROP/SPRING (/PROP/TYPE4: read), /PROP/SPR_GENE (TYPE8)
 * and /PROP/SPR_BEAM (TYPE13) (read: the stiffnesses or elastic curves and
 * the dampings of six directions). */
typedef enum { RC_PROP_SHELL = 1, RC_PROP_SOLID = 2, RC_PROP_SPRING = 3 } rc_prop_kind;

typedef struct rc_case_prop {
    int id;
    char title[101];
    rc_prop_kind kind;
    double thick;      /* SHELL: Thick [m] */
    int sprtype;       /* SPRING: the Radioss type, 4, 8 or 13 */
    double mass;       /* SPRING: Mass [kg], shared by the two nodes */
    double k, c;       /* SPRING TYPE4: K [N/m], C [N s/m] */
    double inertia;    /* SPRING TYPE8, TYPE13: I [kg m^2] (read, not used) */
    int skew_id;       /* SPRING TYPE8, TYPE13: Skew_ID of the element frame
                          (TYPE13: of its Y axis; 0: global) */
    double k6[6], c6[6]; /* SPRING TYPE8, TYPE13: K1..K6, C1..C6, directions
                            X Y Z [N/m, N s/m] then RX RY RZ [N m/rad,
                            N m s/rad] */
    int fct6[6];       /* SPRING TYPE8, TYPE13: fct_ID1i, the elastic force
                          (moment) curve of direction i (0: K_i) */
    double a6[6];      /* Ai, the curve's ordinate scale (0 read as 1) [-] */
    double ascale6[6]; /* Ascalei, the curve's abscissa scale (0 read as 1)
                          [m, rad] */
    rc_loc fct_loc[6]; /* the line of fct_ID1i */
    double dmin6[6], dmax6[6]; /* SPRING TYPE8, TYPE13: rupture deformations
                          dmin_i < 0 < dmax_i [m, rad]; -inf, +inf: none
                          (0, blank or beyond 1e29 in the deck) */
    rc_loc loc;
    rc_loc thick_loc;  /* the line holding Thick; SPRING: the line of K and C */
} rc_case_prop;

/* /MAT/<law>/mat_ID: the density, when ricochet knows where the law keeps
 * it (has_rho); otherwise the reason is kept for the error raised when an
 * element uses the material. */
typedef struct rc_case_mat {
    int id;
    char title[101];
    char law[24];      /* the keyword as written, upper case: "LAW1", "PLAS_JOHNS" */
    int has_rho;
    double rho;        /* Init. dens. [kg/m^3] */
    rc_loc loc;
    rc_loc rho_loc;    /* the line holding the density */
    int has_e;         /* 1: Young's modulus read (LAW1/ELAST, LAW2/PLAS_JOHNS: line 2, columns 1-20) */
    double e;          /* Young's modulus [Pa] (the stiffness of an /INTER/TYPE7 with Istf 0) */
    rc_loc e_loc;      /* the line holding E */
} rc_case_mat;

/* /SKEW/FIX/skew_ID: origin and the axes (unit, orthonormal, right-handed):
 * Y' along (X1, Y1, Z1), X' = Y' x V2, Z' = X' x Y' (docs).
 * /SKEW/MOV/skew_ID and /SKEW/MOV2/skew_ID: a frame carried by three nodes,
 * its origin and axes those of the nodes' initial positions (filled once
 * every card is read, rc_cards_mesh_finish). */
typedef struct rc_case_skew {
    int id;
    char title[101];
    double origin[3];  /* [m] */
    double axis[3][3]; /* axis[k] = unit vector of axis k (X', Y', Z') in global axes */
    int mov;           /* 0: FIX; 1: MOV; 2: MOV2 */
    int nodes[3];      /* MOV, MOV2: node_ID1..node_ID3 */
    int dir;           /* MOV: the axis N1 -> N2, 0 X, 1 Y, 2 Z (MOV2: 2) */
    rc_loc loc;
    rc_loc line_loc;   /* MOV, MOV2: the line of the nodes */
} rc_case_skew;

/* /GRNOD/PART and /GRNOD/GRNOD before expansion: the ids they name. The
 * reader expands them into ordinary node lists (rc_case_grnod) once every
 * card is read. */
typedef struct rc_case_grnod_def {
    int grnod;         /* index of the rc_case_grnod it fills */
    int by_part;       /* 1: part ids, 0: group ids */
    int n;
    int *ids;
    rc_loc *id_loc;    /* [n] line of each id */
} rc_case_grnod_def;

/* /ADMAS/type/admas_ID, types 0 and 1: point masses on the nodes of a group. */
typedef struct rc_case_admas {
    int id;
    int type;          /* 0: Mass on each node; 1: Mass shared equally by the nodes */
    double mass;       /* [kg] */
    int grnod_id;
    rc_loc loc;
    rc_loc line_loc;   /* the line holding MASS and grnd_ID */
} rc_case_admas;

typedef struct rc_case_mesh {
    int nelem;  rc_case_elem *elem;  int capelem;
    int nspring; rc_case_spring *spring; int capspring;
    int nprop;  rc_case_prop *prop;  int capprop;
    int nmat;   rc_case_mat *mat;    int capmat;
    int nskew;  rc_case_skew *skew;  int capskew;
    int ndef;   rc_case_grnod_def *def; int capdef;
    int nadmas; rc_case_admas *admas; int capadmas;
} rc_case_mesh;

/* Index of the card with this id, or -1 (linear scans: few cards). */
int rc_case_find_prop(const rc_case *c, int id);
int rc_case_find_mat(const rc_case *c, int id);
int rc_case_find_skew(const rc_case *c, int id);

void rc_case_mesh_free(rc_case_mesh *m);

#endif
