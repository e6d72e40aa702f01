/*
 * Exact stick (docs/theory.md, "Exact stick"): TYPE6 Istick = 1 or
 * /FRICTION Iform 3. While an interface with exact stick is closed and
 * sticking, the tangential relative velocity of the material points at its
 * contact point is held at zero by two constraint rows of the IDA path, in
 * a tangent basis (t_1, t_2) of the contact plane:
 *
 *   c_k = t_k . v_rel = 0,  k = 1, 2                                  [m/s]
 *
 * whose multipliers lambda_k [N] are the friction force on body a,
 * F = lambda_1 t_1 + lambda_2 t_2 at the contact point (-F on b). As for
 * the joints (model/joint.h), each enters as the derivative of an
 * integrated impulse Lambda_k [N s]: lambda = Lambda'. The integrator's
 * vector is Y = [y, Lambda] (3 per slot, in interface order: below);
 * when an interface slides, is open or inactive its rows are Lambda' = 0.
 * A third row per slot holds a settled contact (docs/theory.md 5.2): the
 * rate of the signed distance dd/dt = 0, its multiplier lambda_n [N] the
 * normal force beyond the penalty law (-lambda_n n on a); the slots are
 * the exact interfaces and the settle-capable ones, three rows each.
 *
 * Evaluated by engine/stick.c, driven by solver/ida.c and engine/events.c.
 */
#ifndef RC_STICK_H
#define RC_STICK_H

#include <stdint.h>

#include "model/model.h"

/* Interfaces with exact stick (0: none). */
int rc_stk_count(const rc_model *m);
/* Can interface i settle into a unilateral constraint (a normal row, its
 * multiplier the normal force; docs/theory.md 5.2)? Single-point analytic
 * pairs without friction. */
int rc_stk_settle_capable(const rc_model *m, int i);
/* Slots of the constraint set: the exact interfaces and the settle-capable
 * ones, three rows each (t_1, t_2, n). */
int rc_stk_slots(const rc_model *m);

typedef struct rc_stk_work rc_stk_work;
/* Extended pattern and scratch of a run; NULL: out of memory. */
rc_stk_work *rc_stk_work_new(const rc_model *m);
/* The same with the Lambda of the interfaces from Y[base] on (a model with
 * joints: after their extras, model/joint.h); rc_stk_work_new: base = ny.
 * The pattern then spans Y[0 .. base + 2 ns). */
rc_stk_work *rc_stk_work_new_at(const rc_model *m, int base);
void rc_stk_work_free(rc_stk_work *w);
/* d->inter_fcstr: the normal multipliers of the settled contacts [N] at
 * (t, Y), from the acceleration-level equations (Yp's Lambda' if they
 * fail); 0 for the others. */
void rc_stk_fcstr(const rc_model *m, rc_data *d, rc_stk_work *w, double t, const double *Y, const double *Yp);
int rc_stk_nextra(const rc_stk_work *w); /* 3 per slot (rc_stk_slots) */
int64_t rc_stk_nnz(const rc_stk_work *w);
void rc_stk_pattern(const rc_stk_work *w, const int64_t **colptr, const int64_t **rowind);
/* Residual: adds the multipliers' terms to the bodies' rows r[0..ny)
 * (r = y' - f there) and writes the constraint rows r[ny..). Pure; the
 * modes are d's. */
void rc_stk_residual(const rc_model *m, const rc_data *d, const rc_stk_work *w, const double *Y, const double *Yp,
                     double *r);
/* dF/dY + cj dF/dY' on the extended pattern, from the model's Jacobian
 * values jf [m->nnz]. */
void rc_stk_jacobian(const rc_model *m, const rc_data *d, const rc_stk_work *w, double cj, const double *Y,
                     const double *Yp, const double *jf, double *val);
/* The slots of the extended pattern that can be nonzero in d's modes:
 * ext[rc_stk_nnz] from the model's active slots keep[m->nnz]
 * (rc_jac_active), the diagonal, and the blocks of the constraints that act
 * (engine/stick.c). */
void rc_stk_keep(const rc_model *m, const rc_data *d, const rc_stk_work *w, const unsigned char *keep,
                 unsigned char *ext);
/* Absolute tolerance of extra k [N s]; IDA's id (0 for every Lambda). */
double rc_stk_atol(const rc_stk_work *w, int k);
void rc_stk_id(const rc_model *m, const rc_stk_work *w, double *id);
/* At a (re)start (t, Y) in d's modes: the tangent bases fixed for the next
 * stretch, the velocities of the sticking contacts made exact (the change
 * of least kinetic energy), Yp[0..ny) = f with the multipliers of the
 * acceleration-level equations, Yp of the inactive rows 0. Returns 0, or -1
 * when the sticking rows are dependent (or f fails). */
int rc_stk_restart(const rc_model *m, rc_data *d, rc_stk_work *w, double t, double *Y, double *Yp);
/* rc_stk_restart in two parts, for a model with joints as well (the
 * multipliers of both sets solved together, solver/ida.c): the bases and
 * the sticking rows of the stretch, the velocities made exact (0 or -1);
 * then, with Yp[0..ny) holding the rates (f and the other constraints'
 * accelerations), the multipliers into Yp and their accelerations added to
 * Yp[0..ny) (0 or -1). */
int rc_stk_prepare(const rc_model *m, rc_data *d, rc_stk_work *w, double *Y);
int rc_stk_consistent(const rc_model *m, rc_stk_work *w, const double *Y, double *Yp);
/* Slip roots of the sticking exact interfaces, from the multipliers in Yp:
 * |lambda|^2 / L_s^2 - 1, L_s = Sfric + mu_s F_n (no band: the multiplier is
 * exact). */
void rc_stk_roots(const rc_model *m, rc_data *d, rc_stk_work *w, double t, const double *Y,
                  const double *Yp, double *g);
/* The friction state F_t of the sticking exact interfaces set to their
 * multiplier's force (global) [N], in Yout (may be Y). */
void rc_stk_sync(const rc_model *m, const rc_data *d, const rc_stk_work *w, const double *Y, const double *Yp,
                 double *Yout);
/* Can interface i (exact stick, closed, in d sticking) stick at (t, y)?
 * 0: yes; 1: no, it must slide along the unit direction e (the force's on
 * a): its sliding velocity is not zero (e = -v_t / |v_t|), or the force
 * that holds it (the multipliers of all sticking exact contacts) lies
 * beyond the static limit (e along that force). -1: out of memory or
 * dependent rows (then it slides along -v_t, or keeps F_t's direction). */
int rc_stk_decide(const rc_model *m, rc_data *d, int i, double t, const double *y, double e[3]);

/* ---- joints and exact stick together (engine/stick_joints.c) ----------
 * One constraint set on Y = [y, the joints' extras (model/joint.h), the
 * stick's Lambda]: the same calls as the two sets', over both. */
typedef struct rc_both rc_both;
rc_both *rc_both_new(const rc_model *m); /* NULL: out of memory */
void rc_both_free(rc_both *c);
struct rc_jnt_work *rc_both_jnt(const rc_both *c);
rc_stk_work *rc_both_stk(const rc_both *c);
int rc_both_nextra(const rc_both *c);
int64_t rc_both_nnz(const rc_both *c);
void rc_both_pattern(const rc_both *c, const int64_t **colptr, const int64_t **rowind);
double rc_both_atol(const rc_model *m, const rc_both *c, int k);
void rc_both_id(const rc_model *m, const rc_both *c, double *id);
void rc_both_residual(const rc_model *m, const rc_data *d, const rc_both *c, const double *Y, const double *Yp,
                      double *r);
void rc_both_jacobian(const rc_model *m, const rc_data *d, const rc_both *c, double cj, const double *Y,
                      const double *Yp, const double *jf, double *val);
/* The consistent (re)start of both sets (rc_stk_restart and the joints'
 * rc_jnt_consistent in one, the velocities of both made exact). 0, or -1
 * when the rows are dependent (a sticking contact holds a motion a joint
 * holds) or f fails. */
int rc_both_consistent(const rc_model *m, rc_data *d, rc_both *c, double t, double *Y, double *Yp);

/* Geometry of interface i for the constraint (engine/assemble_jac.c). */
void rc_stk_geom_c(const rc_model *m, int i, const double _Complex *ya, const double _Complex *yb,
                   double _Complex *point, double _Complex *n, double _Complex *vrel, double _Complex *ddot);

#endif
