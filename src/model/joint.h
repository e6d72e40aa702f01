/*
 * Joints (/JOINT/SPHERICAL, /JOINT/REVOLUTE, /JOINT/DISTANCE, /JOINT/FIXED,
 * /JOINT/PRISMATIC; docs/case-format.md): ideal constraints between two
 * rigid bodies, or a body and the ground, enforced as algebraic equations
 * on the IDA path (docs/theory.md, "Joints"). Compiled by model/joint.c
 * from the case; evaluated by engine/constraints/joints.c (rows, residual, Jacobian,
 * consistent multipliers, reactions), driven by solver/ida.c.
 *
 * Each joint contributes constraint rows r (nrow of them) of three kinds:
 *   point k      g = (p_a - p_b) . e_k, p = x + R s the anchor points [m]
 *   angle (i, j) g = (R_a u_a,i) . (R_b u_b,j), two frame axes          [-]
 *   distance     g = (|p_a - p_b|^2 - L^2) / (2 L)                      [m]
 *   slide i      g = (R_b u_b,i) . (p_a - p_b)                           [m]
 * Their multipliers: lambda_r (the reaction: [N] for point, distance and
 * slide rows, [N m] for angle rows) and mu_r (the position projection,
 * zero on the exact solution: [m/s] or [rad/s]).
 */
#ifndef RC_JOINT_H
#define RC_JOINT_H

#include <stdio.h>

#include "case/case.h"
#include "model/model.h"

typedef enum {
    RC_JNT_SPHERICAL = 1, /* anchor points coincide: 3 point rows              */
    RC_JNT_REVOLUTE = 2,  /* + axes stay parallel: 3 point + 2 angle rows       */
    RC_JNT_DISTANCE = 3,  /* the anchor points keep their distance: 1 row       */
    RC_JNT_FIXED = 4,     /* 3 point + 3 angle rows                             */
    RC_JNT_PRISMATIC = 5  /* 3 angle rows + 2 slide rows (motion along the axis) */
} rc_jnt_kind;

/* Row kinds. */
enum { RC_JROW_POINT = 1, RC_JROW_ANGLE = 2, RC_JROW_DIST = 3, RC_JROW_SLIDE = 4 };

#define RC_JNT_MAXROW 6

typedef struct rc_joints {
    int n;
    int *id;            /* [n] joint id (the card's)                        */
    rc_jnt_kind *kind;  /* [n]                                               */
    char **name;        /* [n] "/JOINT/REVOLUTE/3"                           */
    rc_loc *loc;        /* [n] the card's header                             */
    int *ba, *bb;       /* [n] body indices, -1: the ground                  */
    double *sa, *sb;    /* [3n] anchor points, body frames of a and b [m]    */
    double *ua, *ub;    /* [9n] joint frame (axis, then two normals) in the body
                           frames of a and b (rows of 3) [-]                  */
    double *len;        /* [n] distance L of /JOINT/DISTANCE [m]            */
    int *nrow;          /* [n] constraint rows                               */
    int *radr;          /* [n] first row                                     */
    int *rkind;         /* [nrows] RC_JROW_*                                 */
    int *rarg;          /* [2 nrows] row arguments (k; i, j)                 */
    int nrows;
} rc_joints;

/* Compile the /JOINT cards into m->jnt (NULL when there are none);
 * model/joint.c. */
rc_status rc_jnt_compile(const rc_case *c, rc_model *m, rc_error *err);
void rc_jnt_free(rc_joints *j);
/* A right-handed orthonormal frame e[9] (rows) with e[0..2] along the unit
 * axis a: the joint frame of REVOLUTE and PRISMATIC (model/joint.c). */
void rc_jnt_axis_frame(const double a[3], double e[9]);
/* Lines of `ricochet check`. */
void rc_jnt_print(const rc_model *m, FILE *f);

/* Name of extra k of Y for messages: "/JOINT/REVOLUTE/1, reaction lambda 2
 * [N]" (model/joint.c). */
void rc_jnt_extra_name(const rc_model *m, int k, char *buf, size_t n);
/* "REVOLUTE", ... (model/joint.c). */
const char *rc_jnt_type_name(const rc_model *m, int j);

#endif
