/*
 * Joints on the IDA backend's vector (docs/theory.md, "Joints"): the
 * constraint set of the joints of model/joint.h. (engine/constraints/joints.c)
 */
#ifndef RC_ENGINE_JOINTS_H
#define RC_ENGINE_JOINTS_H

#include <complex.h>
#include <stdint.h>

#include "model/joint.h"
#include "engine/assembly/data.h"

/* ---- evaluation (engine/constraints/joints.c) -----------------------------------
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
 * diagonal, and every joint's block (joints always act) (engine/constraints/joints.c). */
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
/* The rows of joint j at the poses of its bodies, ya and yb (x [m], then
 * the quaternion; 7 values each, the ground's or a fixed body's pose for
 * a body that is not free: rc_body_state): their values g[nrow] ([m] for
 * point, distance and slide rows, [-] for angle rows) and unit wrenches
 * w[nrow] = (F_a, tau_a, F_b, tau_b), global (the rows of G and the
 * generalised forces of unit multipliers, docs/theory.md 7.4). Real, and
 * complex for derivatives by complex step (the static analysis'
 * constraint rows, solver/static.c). Pure. */
void rc_jnt_rows(const rc_model *m, int j, const double *ya, const double *yb, double *g, double (*w)[12]);
void rc_jnt_rows_cx(const rc_model *m, int j, const double complex *ya, const double complex *yb, double complex *g,
                    double complex (*w)[12]);
/* Work of the reactions (the last component of Y) [J]. */
double rc_jnt_work_done(const rc_model *m, const double *Y);
/* The values of every joint for a record (Y a record vector): force [3n], moment [3n], drifts
 * [n] and [n], the work [1] (engine/constraints/joints.c). */
void rc_jnt_frame(const rc_model *m, const double *Y, double *force, double *moment, double *drift_pos,
                  double *drift_ang, double *work);

#endif
