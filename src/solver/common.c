/*
 * What the backends share (common.h): failure advice and the state that
 * failed the error test.
 */
#include <math.h>

#include "model/joint.h"
#include "solver/common.h"

const char *rc_bk_advice(rc_fail_kind kind, const rc_model *m)
{
    const int sets = m->jnt && m->jnt->n > 0;
    switch (kind) {
    case RC_FAIL_MAX_STEPS:
        return "the run took /SOLVER Max_steps steps without reaching the next output time: raise Max_steps, "
               "or, when the steps are tiny, look at the element named (a very stiff, lightly damped law, or "
               "events in quick succession) and loosen Rtol/Atol";
    case RC_FAIL_ACCURACY:
        return "the tolerances ask for more than double precision gives here: raise /SOLVER Rtol (at least "
               "1e-13) or the absolute tolerance of the quantity named";
    case RC_FAIL_ERROR_TEST:
        return "the error test kept failing as the step shrank: the quantity named changes faster than any "
               "step can follow (a jump in a /FUNCT curve, a law with a kink, or a stiffness too high for its "
               "absolute tolerance): smooth the curve, check Stiff and the scale factors of that element, or "
               "loosen its absolute tolerance in /SOLVER";
    case RC_FAIL_NEWTON:
        return sets ? "Newton's iteration did not converge even at small steps: the force of the element named "
                      "varies faster than its Jacobian says (a kink or jump in a /FUNCT curve), a body has almost "
                      "no mass or inertia for the forces on it, or the joints constrain a body twice (redundant "
                      "joints make the constraint rows dependent; so does a sticking exact-stick contact that "
                      "holds a motion a joint already holds): check the joints, that element's law and the "
                      "masses, or bound the step with /SOLVER Hmax"
                    : "Newton's iteration did not converge even at small steps: the force of the element named "
                      "varies faster than its Jacobian says (a kink or jump in a /FUNCT curve), or a body has "
                      "almost no mass or inertia for the forces on it: check that element's law and the masses, "
                      "or bound the step with /SOLVER Hmax";
    case RC_FAIL_FORCES:
        return "the forces could not be evaluated (a penetration or speed outside the range where the law "
               "is finite): extend the /FUNCT curves of that element, lower its scale factors, or bound the "
               "step with /SOLVER Hmax";
    case RC_FAIL_ROOTS:
        return "the event functions could not be evaluated: an internal error, please report the case";
    case RC_FAIL_OTHER:
    default:
        return "see the SUNDIALS documentation of the flag named";
    }
}

int rc_bk_worst_error(const double *e, const double *w, int len, int skip_lo, int skip_hi)
{
    int imax = -1;
    double vmax = 0.0;
    for (int i = 0; i < len; i++) {
        if (i >= skip_lo && i < skip_hi) continue;
        const double v = fabs(e[i] * w[i]);
        if (v > vmax || (isnan(v) && imax < 0)) {
            vmax = v;
            imax = i;
        }
    }
    return imax;
}
