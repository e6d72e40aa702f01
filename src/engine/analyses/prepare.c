/*
 * rc_model_compile: the model stage's rc_model_build (model/compile.c:
 * bodies, surfaces, interfaces, friction, couplings, imposed velocities,
 * state layout; built again without the points that TYPE7 Inacti 1, 2
 * leave out: inacti.c), then the two analyses that evaluate the kernels: the
 * scales and tolerances (scales.c) and the Jacobian pattern by probing
 * (jacpattern.c). Here, above both, so that src/model never calls the
 * engine.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/error.h"
#include "base/progress.h"
#include "engine/assembly/bounds.h"
#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/stick.h"
#include "engine/assembly/assembly.h"
#include "engine/analyses/analyses.h"
#include "engine/constraints/joints.h"

/* Joints: the initial state satisfies them (positions and velocities) and
 * their rows are independent (engine/constraints/joints.c); else an input error at
 * the card of the joint concerned. */
static rc_status check_joints(const rc_model *m, rc_error *err)
{
    rc_jnt_work *w = rc_jnt_work_new(m);
    double *Y = w ? calloc((size_t)(m->ny + rc_jnt_nextra(w)), sizeof *Y) : NULL;
    if (!Y) {
        rc_jnt_work_free(w);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the joints");
    }
    rc_initial_state(m, Y);
    rc_status st = rc_jnt_check_initial(m, w, Y, err);
    const int j = st ? -1 : rc_jnt_dependent(m, w, Y);
    if (j >= 0)
        st = RC_SET(err, RC_EINPUT,
                    RC_LOCFMT "card %s: its constraints repeat those of the joints before it (dependent rows: "
                              "a body held twice in the same way, e.g. a closed planar loop of revolute joints "
                              "with parallel axes); remove the redundant constraint, e.g. use /JOINT/SPHERICAL "
                              "for one joint of the loop",
                    RC_LOC(m->jnt->loc[j]), m->jnt->name[j]);
    free(Y);
    rc_jnt_work_free(w);
    return st;
}

/* The interfaces the fast path evaluates (engine/kernels/kernel_fast.inc). */
rc_status rc_fast_select(rc_model *m, rc_error *err)
{
    free(m->inter_fast);
    m->inter_fast = NULL;
    if (m->ninter == 0) return RC_OK;
    m->inter_fast = malloc((size_t)m->ninter);
    if (!m->inter_fast) RC_RAISE(err, RC_ENOMEM, "out of memory for the interfaces' kernel paths");
    for (int i = 0; i < m->ninter; i++) m->inter_fast[i] = (unsigned char)rc_fast_eligible(m, i);
    return RC_OK;
}

rc_status rc_model_compile(const rc_case *c, rc_model **out, rc_error *err)
{
    rc_model *m = NULL;
    if (!out) RC_RAISE(err, RC_EINPUT, "rc_model_compile: out is NULL; expected where to store the model");
    *out = NULL;
    if (!c) RC_RAISE(err, RC_EINPUT, "rc_model_compile: the case is NULL; expected one from rc_case_load");
    rc_progress_stage("building the model");
    rc_status st = rc_model_build(c, &m, err);
    /* TYPE7 Inacti 1, 2: the points penetrating at t = 0 left out (inacti.c) */
    if (!st) st = rc_inacti_build(c, &m, err);
    rc_progress_done();
    if (st) {
        rc_model_free(m);
        return st;
    }
    if (m->method == 3) { /* the static analysis: its scope (model/static_scope.c) */
        char how[400];
        snprintf(how, sizeof how, "chosen by /SOLVER Method 3 at %s:%d", c->solver.method_loc.file ? c->solver.method_loc.file : "?",
                 c->solver.method_loc.line);
        st = rc_static_scope(m, how, err);
        if (st) {
            rc_model_free(m);
            return st;
        }
    } else if (m->preload) { /* a preload: the static analysis' scope, bodies at rest */
        char how[400];
        snprintf(how, sizeof how, "/SOLVER field Preload at %s:%d", m->preload_loc.file ? m->preload_loc.file : "?",
                 m->preload_loc.line);
        st = rc_preload_scope(m, how, err);
        if (st) {
            rc_model_free(m);
            return st;
        }
    }
    st = rc_fast_select(m, err); /* the fast path per interface (kernel_fast.inc) */
    if (st) {
        rc_model_free(m);
        return st;
    }
    rc_progress_stage("scales and tolerances (interfaces)");
    st = rc_model_scales(m, err);
    if (!st) st = rc_model_tolerances(m, err);
    rc_progress_done();
    /* bodies overlapping at t = 0 that no option accounts for (start.c) */
    if (!st) st = rc_start_check(c, m, err);
    if (!st) {
        rc_progress_stage("Jacobian pattern (bodies, interfaces, couplings)");
        st = rc_jac_build(m, err);
        rc_progress_done();
    }
    if (!st && m->jnt) st = check_joints(m, err);
    if (st) {
        rc_model_free(m);
        return st;
    }
    *out = m;
    return RC_OK;
}

rc_status rc_model_set_rtol(rc_model *m, double rtol, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_model_set_rtol: the model is NULL; expected a compiled model");
    if (!(isfinite(rtol) && rtol > 0 && rtol < 1))
        RC_RAISE(err, RC_EINPUT, "relative tolerance: expected a finite number in (0, 1), got %g", rtol);
    const double old = m->rtol;
    double *atol = m->atol;
    char *rel = m->ewt_rel;
    m->rtol = rtol;
    m->atol = NULL;
    m->ewt_rel = NULL;
    rc_status st = rc_model_tolerances(m, err);
    if (st) { /* keep the model as it was */
        free(m->atol);
        free(m->ewt_rel);
        m->rtol = old;
        m->atol = atol;
        m->ewt_rel = rel;
        return st;
    }
    free(atol);
    free(rel);
    return RC_OK;
}

rc_status rc_model_set_method(rc_model *m, int method, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_model_set_method: the model is NULL; expected a compiled model");
    if (method != 1 && method != 2 && method != 3)
        RC_RAISE(err, RC_EINPUT, "integration method: expected 1 (CVODE), 2 (IDA) or 3 (static, KINSOL), got %d",
                 method);
    if (method == 3) {
        rc_status st = rc_static_scope(m, "chosen by the method 3 (static) option", err);
        if (st) return st;
    }
    if (method == 1 && m->jnt && m->jnt->n > 0)
        RC_RAISE(err, RC_EINPUT,
                 "integration method: the model has joints (%d), which only the IDA path (method 2) runs; "
                 "expected 2, got 1",
                 m->jnt->n);
    if (method == 1 && rc_stk_count(m) > 0)
        RC_RAISE(err, RC_EINPUT,
                 "integration method: the model has exact stick (%d interfaces), a constraint that only the IDA "
                 "path (method 2) runs; expected 2, got 1",
                 rc_stk_count(m));
    if (method != 3 && m->preload) {
        rc_status st = rc_preload_scope(m, "the model's preload (/SOLVER Preload, rc_model_set_preload)", err);
        if (st) return st;
    }
    m->method = method;
    return RC_OK;
}

rc_status rc_model_set_preload(rc_model *m, int on, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_model_set_preload: the model is NULL; expected a compiled model");
    if (on != 0 && on != 1)
        RC_RAISE(err, RC_EINPUT, "preload: expected 0 (off) or 1 (start from the static equilibrium), got %d", on);
    if (on && m->method != 3) {
        rc_status st = rc_preload_scope(m, "the preload option (rc_model_set_preload, ricochet run --preload)", err);
        if (st) return st;
    }
    m->preload = on;
    return RC_OK;
}

int rc_model_preload(const rc_model *m) { return m ? m->preload : 0; }

rc_status rc_model_set_switch(rc_model *m, int on, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_model_set_switch: the model is NULL; expected a compiled model");
    if (on != 0 && on != 1)
        RC_RAISE(err, RC_EINPUT, "method switching: expected 0 (off) or 1 (BDF and an explicit method), got %d", on);
    m->method_switch = on;
    return RC_OK;
}

int rc_model_switch(const rc_model *m) { return m ? m->method_switch : 0; }

double rc_model_rtol(const rc_model *m) { return m ? m->rtol : NAN; }
double rc_model_t_end(const rc_model *m) { return m ? m->tend : NAN; }
double rc_model_dt_out(const rc_model *m) { return m ? m->dtout : NAN; }
