/*
 * What every integration backend computes the same way (internal to
 * solver/): the error weight of a model state, the failure kinds with
 * their advice, and the state whose local error failed a step. Written
 * once here; cvode.c and ida.c (and any later backend) map their own flags
 * onto the kinds.
 */
#ifndef RC_SOLVER_COMMON_H
#define RC_SOLVER_COMMON_H

#include <float.h>
#include <math.h>
#include <stddef.h>

#include "model/model.h"
#include "engine/assembly/data.h"

/* The error tolerance of model state k at the value yk (its weight is the
 * inverse): atol_k plus rtol |y_k| where the model weighs it relatively
 * (model.h ewt_rel); positions (derived or given) and rotations under
 * derived tolerances are weighed against the contact scales, not against
 * centre coordinates, with a floor of 64 ulps of the value (a far-away coordinate stays testable); a
 * contact point's state at its share (RC_EWT_SHARE_MIN). Inline: the
 * integrators call it for every state at every step. */
static inline double rc_bk_state_tol(const rc_model *m, const rc_data *d, int k, double yk)
{
    const double ay = fabs(yk);
    const int rel = !m->ewt_rel || m->ewt_rel[k];
    double s = m->atol[k] + (rel ? m->rtol * ay : 0.0);
    if (!rel) {
        const double fl = 64.0 * DBL_EPSILON * ay; /* fmax(s, fl) without the libm call */
        if (fl > s) s = fl;
    }
    if (m->state_pt[k] >= 0) {
        const double sh = d->sc->pt_share[m->state_pt[k]];
        s /= sqrt(sh > RC_EWT_SHARE_MIN ? sh : RC_EWT_SHARE_MIN);
    }
    return s;
}

/* Why an integrator gave up, whatever its own flag. */
typedef enum {
    RC_FAIL_MAX_STEPS,  /* Max_steps steps before the next output time */
    RC_FAIL_ACCURACY,   /* the tolerances ask for more than double precision */
    RC_FAIL_ERROR_TEST, /* the error test failed as the step shrank */
    RC_FAIL_NEWTON,     /* Newton's iteration or the linear solver failed */
    RC_FAIL_FORCES,     /* the forces (residual) could not be evaluated */
    RC_FAIL_ROOTS,      /* the event functions could not be evaluated */
    RC_FAIL_OTHER
} rc_fail_kind;

/* The likely cause and what to change in the case, for a model m (the
 * constraint sets' causes where it has joints or exact stick). */
const char *rc_bk_advice(rc_fail_kind kind, const rc_model *m);

/* The component with the largest |e_i w_i| (the error test's measure; a NaN
 * counts when nothing else is found) among i in [0, len) outside
 * [skip_lo, skip_hi); -1: none. */
int rc_bk_worst_error(const double *e, const double *w, int len, int skip_lo, int skip_hi);

#endif
