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
 * Evaluated by engine/constraints/stick.c, driven by solver/ida.c and
 * engine/events/events.c.
 */
#ifndef RC_ENGINE_STICK_H
#define RC_ENGINE_STICK_H

#include <stdint.h>

#include "model/model.h"
#include "engine/assembly/data.h"

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
 * (engine/constraints/stick.c). */
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
/* The pieces of the stick/slip decision (rc_stk_decide,
 * engine/constraints/cset.h): 1 when interface i slides at (t, y)
 * with a speed beyond the tolerances (e = -v_t / |v_t|), else 0; r receives
 * its report in d's modes. */
int rc_stk_sliding(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r,
                   double e[3]);
/* The force that holds sticking exact interface i (on a, global) [N]: the
 * multipliers of all sticking exact contacts at (t, y) in a model without
 * joints. 0, or -1 (out of memory, dependent rows, f fails). */
int rc_stk_hold_force(const rc_model *m, rc_data *d, int i, double t, const double *y, double F[3]);
/* Interface i's slot in w, -1: none. */
int rc_stk_slot_of(const rc_stk_work *w, int i);
/* The force of slot q's multipliers (from Yp, the extended vector) at Y,
 * global, on a [N]. */
void rc_stk_slot_force(const rc_model *m, const rc_stk_work *w, int q, const double *Y, const double *Yp, double F[3]);

#endif
