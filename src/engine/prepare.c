/*
 * rc_model_compile: the model stage's rc_model_build (model/compile.c:
 * bodies, surfaces, interfaces, friction, couplings, imposed velocities,
 * state layout), then the two analyses that evaluate the kernels: the
 * scales and tolerances (scales.c) and the Jacobian pattern by probing
 * (jacpattern.c). Here, above both, so that src/model never calls the
 * engine.
 */
#include "model/model.h"
#include "base/progress.h"

rc_status rc_model_compile(const rc_case *c, rc_model **out, rc_error *err)
{
    rc_model *m = NULL;
    *out = NULL;
    rc_progress_stage("building the model");
    rc_status st = rc_model_build(c, &m, err);
    rc_progress_done();
    if (st) return st;
    rc_progress_stage("scales and tolerances (interfaces)");
    st = rc_model_scales(m, err);
    if (!st) st = rc_model_tolerances(m, err);
    rc_progress_done();
    if (!st) {
        rc_progress_stage("Jacobian pattern (bodies, interfaces, couplings)");
        st = rc_jac_build(m, err);
        rc_progress_done();
    }
    if (st) {
        rc_model_free(m);
        return st;
    }
    *out = m;
    return RC_OK;
}
