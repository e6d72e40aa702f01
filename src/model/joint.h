/*
 * Joints (/JOINT/SPHERICAL, /JOINT/REVOLUTE, /JOINT/DISTANCE, /JOINT/FIXED,
 * /JOINT/PRISMATIC; docs/case-format.md): ideal constraints between two
 * rigid bodies, or a body and the ground, enforced as algebraic equations
 * on the IDA path (docs/theory.md, "Joints"). Compiled by model/joint.c
 * from the case; evaluated by engine/joints.c (rows, residual, Jacobian,
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

/* ---- evaluation (engine/joints.c) -----------------------------------
 * The integrator's vector is Y = [y, Lambda, nu, W]: the model's states,
 * the integrated multipliers (nrows each; the residual holds their
 * derivatives, the reactions lambda = Lambda' and the projection
 * multipliers mu = nu') and the work of the reactions [J]. A record vector
 * (what the output and rc_jnt_report read) is Y with lambda in place of
 * Lambda. */
typedef struct rc_jnt_work rc_jnt_work;
/* The extended sparse pattern and the scratch of a run; NULL: out of memory. */
rc_jnt_work *rc_jnt_work_new(const rc_model *m);
void rc_jnt_work_free(rc_jnt_work *w);
int rc_jnt_nextra(const rc_jnt_work *w);   /* 2 nrows + 1 */
int64_t rc_jnt_nnz(const rc_jnt_work *w);  /* entries of the extended pattern */
/* Residual: adds the joints' terms to r[0..ny) (r = y' - f(t, y) there)
 * and writes the constraint rows and the work row r[ny..). Pure. */
void rc_jnt_residual(const rc_model *m, const rc_jnt_work *w, const double *Y, const double *Yp, double *r);
/* The extended CSC pattern over Y: column pointers [N+1], row indices [nnz]. */
void rc_jnt_pattern(const rc_jnt_work *w, const int64_t **colptr, const int64_t **rowind);
/* dF/dY + cj dF/dY' on that pattern (val [nnz]), from the model's Jacobian
 * values jf [m->nnz] of f. */
void rc_jnt_jacobian(const rc_model *m, const rc_jnt_work *w, double cj, const double *Y, const double *Yp,
                     const double *jf, double *val);
/* The slots of the extended pattern that can be nonzero: ext[rc_jnt_nnz]
 * from the model's active slots keep[m->nnz] (rc_jac_active), the
 * diagonal, and every joint's block (joints always act) (engine/joints.c). */
void rc_jnt_keep(const rc_model *m, const rc_jnt_work *w, const unsigned char *keep, unsigned char *ext);
/* Absolute tolerance of extra k (0 <= k < rc_jnt_nextra) in its unit. */
double rc_jnt_atol(const rc_model *m, const rc_jnt_work *w, int k);
/* IDA's id: 0 for Lambda (out of the error test), 1 for the others. */
void rc_jnt_id(const rc_model *m, const rc_jnt_work *w, double *id);
/* Consistent Y' at (t, Y) where Yp[0..ny) holds f(t, y): mu = nu' = 0,
 * lambda = Lambda' from the acceleration-level equations (the velocity
 * constraints held along the motion), y' of the bodies with the reactions.
 * Returns 0, or -1 when the constraint rows are dependent. */
int rc_jnt_consistent(const rc_model *m, rc_jnt_work *w, double *Y, double *Yp);
/* Velocities of the bodies made to satisfy the velocity constraints G u = 0
 * exactly, by the change of smallest kinetic energy (at the start: the
 * deck's velocities satisfy them to the rounding of their digits). Returns
 * 0, or -1 when the rows are dependent. */
int rc_jnt_project_velocities(const rc_model *m, rc_jnt_work *w, double *Y);
/* The first joint (in card order) whose rows make the constraint rows
 * dependent at Y, or -1 when they are independent. */
int rc_jnt_dependent(const rc_model *m, rc_jnt_work *w, const double *Y);
/* The initial state must satisfy the constraints: RC_EINPUT naming the
 * joint's card otherwise. */
rc_status rc_jnt_check_initial(const rc_model *m, rc_jnt_work *w, const double *Y, rc_error *err);
/* Reactions of joint j at a record vector Y: force on body a [N] and moment on body a about
 * its anchor point [N m], global frame; the largest position residual of
 * its point, distance and slide rows [m] and of its angle rows [-]. */
void rc_jnt_report(const rc_model *m, int j, const double *Y, double force[3], double moment[3], double *drift_pos,
                   double *drift_ang);
/* Work of the reactions (the last component of Y) [J]. */
double rc_jnt_work_done(const rc_model *m, const double *Y);
/* The values of every joint for a record (Y a record vector): force [3n], moment [3n], drifts
 * [n] and [n], the work [1] (engine/joints.c). */
void rc_jnt_frame(const rc_model *m, const double *Y, double *force, double *moment, double *drift_pos,
                  double *drift_ang, double *work);
/* Name of extra k of Y for messages: "/JOINT/REVOLUTE/1, reaction lambda 2
 * [N]" (model/joint.c). */
void rc_jnt_extra_name(const rc_model *m, int k, char *buf, size_t n);
/* "REVOLUTE", ... (model/joint.c). */
const char *rc_jnt_type_name(const rc_model *m, int j);

#endif
