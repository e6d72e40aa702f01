/*
 * Joints and exact stick together: one constraint set on
 * Y = [y, the joints' extras, the stick's Lambda] with the same calls as
 * the two sets'. (engine/constraints/stick_joints.c)
 */
#ifndef RC_ENGINE_STICK_JOINTS_H
#define RC_ENGINE_STICK_JOINTS_H

#include <stdint.h>

#include "engine/constraints/joints.h"
#include "engine/constraints/stick.h"

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

/* Can interface i (exact stick, closed, in d sticking) stick at (t, y)?
 * 0: yes; 1: no, it must slide along the unit direction e (the force's on
 * a): its sliding velocity is not zero (e = -v_t / |v_t|), or the force
 * that holds it (the multipliers of all sticking exact contacts, solved
 * with the joints' where the model has joints) lies beyond the static
 * limit (e along that force). -1: out of memory or dependent rows (then it
 * slides along -v_t, or keeps F_t's direction). */
int rc_stk_decide(const rc_model *m, rc_data *d, int i, double t, const double *y, double e[3]);

#endif
