/*
 * IDA backend: the model as the implicit system F(t, Y, Y') = 0 integrated
 * by IDA (variable-order BDF, Newton, KLU on a fixed sparse pattern) with
 * the same rootfinding, events, records, impacts table and statistics as
 * the CVODE backend: the backend of /SOLVER Method 2 (rc_solver_ida,
 * solver.h), and the one that runs models with joints (docs/theory.md,
 * "Joints").
 *
 * Y = [y, Lambda, nu, W]: the model's states y (model.h), then, when the
 * model has joints (model/joint.h), the integrated multipliers of their
 * stabilised index-2 rows (Gear, Gupta and Leimkuhler): the impulses
 * Lambda of the reactions lambda = Lambda' and the projections nu of the
 * position constraints, mu = nu'; and the work W of the reactions [J].
 *
 *   F_y      = y' - f(t, y) + (joint terms of the bodies' rows: G^T lambda, G^T mu)
 *   F_Lambda = G(q) u               (velocity constraints)
 *   F_nu     = g(q)                 (position constraints)
 *   F_W      = W' - lambda . G(q) u (the reactions' power: 0 on the manifold)
 *
 * Without joints F = y' - f(t, y): an ODE, whose consistent derivative is
 * y' = f(t, y) exactly; it is set so at the start and after every restart.
 * With joints the velocities are made to satisfy G u = 0 at the start, and
 * lambda follows from the acceleration-level equations at every (re)start
 * (engine/joints.c; IDACalcIC cannot: no algebraic unknown in the rows).
 */
#include <float.h>
#include <ida/ida.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <unistd.h>

#include "base/error.h"
#include "engine/events.h"
#include "model/coupling.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "output/output.h"
#include "solver/impacts.h"
#include "solver/nvfast.h"
#include "solver/integrator.h"
#include "solver/solver.h"

typedef struct ida_ctx {
    const rc_model *m;
    rc_data *d;
    int n;          /* size of Y */
    double *jsave;  /* [nnz] Jacobian values of f on the model's pattern */
    rc_jnt_work *jw; /* joints: pattern of the extended matrix, scratch (NULL: none) */
    double *yrec;    /* joints: the record vector, Y with lambda = Lambda' (model/joint.h) */
    volatile sig_atomic_t *stop;
    char msg[512];  /* IDA's last error message */
} ida_ctx;

/* ---- IDA callbacks -------------------------------------------------- */
static void cb_err(int code, const char *module, const char *function, char *msg, void *ud)
{
    ida_ctx *c = ud;
    if (c && c->stop && *c->stop) return;
    if (code < 0 && c) snprintf(c->msg, sizeof c->msg, "%s", msg);
    else fprintf(stderr, "[%s %s]  %s\n  %s\n\n", module, code < 0 ? "ERROR" : "WARNING", function, msg);
}

/* F(t, Y, Y'): pure, as the right-hand side. */
static int cb_res(realtype t, N_Vector yy, N_Vector yp, N_Vector rr, void *ud)
{
    ida_ctx *c = ud;
    if (c->stop && *c->stop) return -1;
    const double *y = N_VGetArrayPointer(yy), *p = N_VGetArrayPointer(yp);
    double *r = N_VGetArrayPointer(rr);
    int st = rc_assemble_rhs(c->m, c->d, t, y, r);
    if (st) return st;
    for (int k = 0; k < c->m->ny; k++) r[k] = p[k] - r[k];
    if (c->jw) rc_jnt_residual(c->m, c->jw, y, p, r);
    return 0;
}

/* dF/dY + cj dF/dY' on the fixed pattern: cj I - J_f on the model's
 * block (J_f from the engine's Jacobian), the joints' exact blocks. */
static int cb_jac(realtype t, realtype cj, N_Vector yy, N_Vector yp, N_Vector rr, SUNMatrix A, void *ud,
                  N_Vector t1, N_Vector t2, N_Vector t3)
{
    ida_ctx *c = ud;
    const rc_model *m = c->m;
    (void)rr;
    (void)t1;
    (void)t2;
    (void)t3;
    int st = rc_assemble_jac(m, c->d, t, N_VGetArrayPointer(yy), c->jsave);
    if (st) return st;
    sunindextype *cp = SUNSparseMatrix_IndexPointers(A), *ri = SUNSparseMatrix_IndexValues(A);
    double *a = SUNSparseMatrix_Data(A);
    if (!c->jw) {
        for (int k = 0; k <= m->ny; k++) cp[k] = (sunindextype)m->jac_colptr[k];
        for (int64_t k = 0; k < m->nnz; k++) ri[k] = (sunindextype)m->jac_rowind[k];
        for (int64_t k = 0; k < m->nnz; k++) a[k] = -c->jsave[k];
        for (int r = 0; r < m->ny; r++) a[m->jac_diag[r]] += cj;
        return 0;
    }
    const int64_t *pc, *pr;
    rc_jnt_pattern(c->jw, &pc, &pr);
    for (int k = 0; k <= c->n; k++) cp[k] = (sunindextype)pc[k];
    for (int64_t k = 0; k < pc[c->n]; k++) ri[k] = (sunindextype)pr[k];
    rc_jnt_jacobian(m, c->jw, cj, N_VGetArrayPointer(yy), N_VGetArrayPointer(yp), c->jsave, a);
    return 0;
}

static int cb_root(realtype t, N_Vector yy, N_Vector yp, realtype *g, void *ud)
{
    ida_ctx *c = ud;
    (void)yp;
    c->d->n_root++;
    rc_assemble_roots(c->m, c->d, t, N_VGetArrayPointer(yy), g);
    return 0;
}

/* Error weights as in the CVODE backend (model.h ewt_rel); the multipliers
 * and the joint work by their own absolute tolerances (rc_jnt_atol). */
static int cb_ewt(N_Vector yv, N_Vector wv, void *ud)
{
    const ida_ctx *c = ud;
    const rc_model *m = c->m;
    const double *y = N_VGetArrayPointer(yv);
    double *w = N_VGetArrayPointer(wv);
    for (int k = 0; k < c->n; k++) {
        const double ay = fabs(y[k]);
        double s;
        if (k < m->ny) {
            s = m->atol[k] + (!m->ewt_rel || m->ewt_rel[k] ? m->rtol * ay : 0.0);
            if (m->ewt_rel && !m->ewt_rel[k]) s = fmax(s, 64.0 * DBL_EPSILON * ay);
        } else {
            s = rc_jnt_atol(m, c->jw, k - m->ny) + m->rtol * ay;
        }
        if (!(s > 0)) return -1;
        w[k] = 1.0 / s;
    }
    return 0;
}

/* ---- helpers -------------------------------------------------------- */
static void add_stats(void *ida, rc_stats *s)
{
    long v;
    if (IDAGetNumSteps(ida, &v) == IDA_SUCCESS) s->steps += v;
    if (IDAGetNumResEvals(ida, &v) == IDA_SUCCESS) s->rhs_evals += v;
    if (IDAGetNumJacEvals(ida, &v) == IDA_SUCCESS) s->jac_evals += v;
    if (IDAGetNumLinSolvSetups(ida, &v) == IDA_SUCCESS) s->lin_setups += v;
    if (IDAGetNumNonlinSolvIters(ida, &v) == IDA_SUCCESS) s->nonlin_iters += v;
    if (IDAGetNumNonlinSolvConvFails(ida, &v) == IDA_SUCCESS) s->nonlin_fails += v;
    if (IDAGetNumErrTestFails(ida, &v) == IDA_SUCCESS) s->err_test_fails += v;
    if (IDAGetNumGEvals(ida, &v) == IDA_SUCCESS) s->root_evals += v;
}

/* Consistent Y' (and multipliers) at (t, Y), then IDA restarted there.
 * Without joints Y' = f(t, y) exactly; with joints the multipliers follow
 * from the acceleration-level equations (rc_jnt_consistent). */
static int restart(ida_ctx *c, void *ida, double t, N_Vector yy, N_Vector yp)
{
    const rc_model *m = c->m;
    double *y = N_VGetArrayPointer(yy), *p = N_VGetArrayPointer(yp);
    if (rc_assemble_rhs(m, c->d, t, y, p)) return IDA_FIRST_RES_FAIL;
    /* joints: the multipliers and y' from the acceleration-level equations
     * (IDACalcIC cannot: the constraint rows hold no algebraic unknown) */
    if (c->jw && rc_jnt_consistent(m, c->jw, y, p)) return IDA_CONV_FAIL;
    return IDAReInit(ida, t, yy, yp);
}

/* The interpolant of IDA's last step for the impact table (rc_interp_fn). */
typedef struct interp_ctx {
    void *ida;
    N_Vector ys;
} interp_ctx;

static int interp_last_step(void *ctx, double t, const double **y)
{
    interp_ctx *c = ctx;
    if (IDAGetDky(c->ida, t, 0, c->ys) != IDA_SUCCESS) return -1;
    *y = N_VGetArrayPointer(c->ys);
    return 0;
}

/* The impacts in progress at the end of a step over (t_prev, t] with the
 * state y (rc_impacts_step, as the CVODE backend). */
static void sample_step(void *ida, rc_impacts *im, const rc_model *m, const rc_data *d, double t_prev, double t,
                        N_Vector y, N_Vector ys)
{
    double tn = t, hu = 0.0;
    if (!rc_impacts_active(im) || IDAGetCurrentTime(ida, &tn) != IDA_SUCCESS ||
        IDAGetLastStep(ida, &hu) != IDA_SUCCESS)
        return;
    const double lo = fmax(t_prev, tn - hu);
    if (!(t > lo)) return;
    interp_ctx c = {ida, ys};
    rc_impacts_step(im, m, d, lo, t, N_VGetArrayPointer(y), interp_last_step, &c);
}

/* Roots that are exactly zero at t after a flat approach: bisect on the
 * interpolant for where they reached zero (as the CVODE backend). */
static int refine_flat_roots(const rc_model *m, rc_data *d, void *ida, double t, const int *roots, double *g,
                             N_Vector yref, double *refined_time)
{
    const int nr = rc_root_count(m);
    double tn, hu;
    if (nr == 0 || IDAGetCurrentTime(ida, &tn) != IDA_SUCCESS || IDAGetLastStep(ida, &hu) != IDA_SUCCESS) return 0;
    double *y = N_VGetArrayPointer(yref);
    if (IDAGetDky(ida, t, 0, yref) != IDA_SUCCESS) return 0;
    rc_assemble_roots(m, d, t, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] != 0.0) return 0;
    double lo = fmax(tn - hu, 0.0), hi = t;
    if (IDAGetDky(ida, lo, 0, yref) != IDA_SUCCESS) return 0;
    rc_assemble_roots(m, d, lo, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] == 0.0) return 0;
    int it = 0;
    for (; it < 200 && hi - lo > 4.0 * DBL_EPSILON * fmax(fabs(hi), 1.0); it++) {
        const double mid = 0.5 * (lo + hi);
        if (IDAGetDky(ida, mid, 0, yref) != IDA_SUCCESS) return 0;
        rc_assemble_roots(m, d, mid, y, g);
        int all = 1;
        for (int k = 0; k < nr; k++)
            if (roots[k] != 0 && g[k] != 0.0) all = 0;
        if (all) hi = mid;
        else lo = mid;
    }
    if (hi >= t || IDAGetDky(ida, hi, 0, yref) != IDA_SUCCESS) return 0;
    *refined_time = hi;
    return it > 0 ? it : 1;
}

/* One record at (t, Y, Y'): with joints, of the record vector (the
 * reactions lambda = Lambda' in the slots of Lambda). */
static rc_status record(const ida_ctx *c, rc_output *o, frame_buf *fb, double t, const double *Y, const double *Yp,
                        int at_event, rc_error *err)
{
    if (!c->jw) return write_frame(c->m, c->d, o, fb, t, Y, at_event, err);
    const int ny = c->m->ny, nr = c->m->jnt->nrows;
    memcpy(c->yrec, Y, (size_t)c->n * sizeof(double));
    memcpy(c->yrec + ny, Yp + ny, (size_t)nr * sizeof(double));
    return write_frame(c->m, c->d, o, fb, t, c->yrec, at_event, err);
}

/* Records of the output times a step passed before an event at t. */
static rc_status outputs_before(void *ida, const ida_ctx *c, rc_output *o, frame_buf *fb, double t, double tend,
                                double dtout, double *tout, long *nout, N_Vector ytmp, N_Vector yptmp, rc_error *err)
{
    while (*tout < t && t - *tout > 1e-12 * fmax(fabs(t), dtout)) {
        if (IDAGetDky(ida, *tout, 0, ytmp) != IDA_SUCCESS || IDAGetDky(ida, *tout, 1, yptmp) != IDA_SUCCESS)
            RC_RAISE(err, RC_ESOLVER, "IDA interpolation at the output time %.9g s failed", *tout);
        rc_status st = record(c, o, fb, *tout, N_VGetArrayPointer(ytmp), N_VGetArrayPointer(yptmp), 0, err);
        if (st) return st;
        (*nout)++;
        const double next = fmin(*nout * dtout, tend);
        if (next <= *tout) break;
        *tout = next;
        if (tend - *tout < 1e-12 * tend) *tout = tend;
    }
    return RC_OK;
}

/* The message of a failed IDASolve: where, and the likely cause. */
static void failure_advice(const rc_model *m, const rc_data *d, void *ida, int flag, double t, double tout,
                           const char *msg, N_Vector tmp1, N_Vector tmp2, char *buf, size_t n)
{
    double h = 0.0;
    IDAGetCurrentStep(ida, &h);
    char elem[200] = "";
    if (IDAGetEstLocalErrors(ida, tmp1) == IDA_SUCCESS && IDAGetErrWeights(ida, tmp2) == IDA_SUCCESS) {
        const double *e = N_VGetArrayPointer(tmp1), *w = N_VGetArrayPointer(tmp2);
        int imax = -1;
        double vmax = 0.0;
        /* the components in the error test: not the multipliers lambda */
        const int len = (int)N_VGetLength(tmp1), nr = m->jnt ? m->jnt->nrows : 0;
        for (int i = 0; i < len; i++) {
            if (i >= m->ny && i < m->ny + nr) continue;
            const double v = fabs(e[i] * w[i]);
            if (v > vmax || (isnan(v) && imax < 0)) {
                vmax = v;
                imax = i;
            }
        }
        if (imax >= 0 && imax < m->ny) rc_state_name(m, imax, elem, sizeof elem);
        else if (imax >= 0) rc_jnt_extra_name(m, imax - m->ny, elem, sizeof elem);
    }
    const char *cf = rc_cpl_failed(m, d);
    char where[512];
    if (d->fail_inter >= 0) snprintf(where, sizeof where, "non-finite force in %s", m->inter_name[d->fail_inter]);
    else if (cf) snprintf(where, sizeof where, "no force from %s", cf);
    else if (elem[0]) snprintf(where, sizeof where, "largest local error in %s", elem);
    else snprintf(where, sizeof where, "element not identified");
    char *fname = IDAGetReturnFlagName(flag);
    const char *advice;
    switch (flag) {
    case IDA_TOO_MUCH_WORK:
        advice = "the run took /SOLVER Max_steps steps without reaching the next output time: raise Max_steps, "
                 "or look at the element named and loosen Rtol/Atol";
        break;
    case IDA_TOO_MUCH_ACC:
        advice = "the tolerances ask for more than double precision gives here: raise /SOLVER Rtol";
        break;
    case IDA_ERR_FAIL:
        advice = "the error test kept failing as the step shrank: the quantity named changes faster than any "
                 "step can follow (a jump in a /FUNCT curve, a law with a kink, a stiffness too high for its "
                 "absolute tolerance)";
        break;
    case IDA_CONV_FAIL:
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL:
    case IDA_NO_RECOVERY:
    case IDA_LINESEARCH_FAIL:
        advice = "Newton's iteration did not converge: a force varies faster than its Jacobian says, a body "
                 "has almost no mass or inertia, or the joints constrain a body twice (redundant joints make "
                 "the constraint rows dependent): check the joints and the masses, or bound the step with "
                 "/SOLVER Hmax";
        break;
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL:
        advice = "the forces could not be evaluated (a penetration or speed outside the range where the law "
                 "is finite): extend the /FUNCT curves of that element or bound the step with /SOLVER Hmax";
        break;
    default:
        advice = "see the SUNDIALS IDA documentation of this flag";
        break;
    }
    snprintf(buf, n, "IDA failed at t = %.9g s (step h = %.3g s, next output at %.9g s): %s%s%s%s; %s. Likely "
             "cause: %s",
             t, h, tout, fname ? fname : "?", msg[0] ? " (\"" : "", msg, msg[0] ? "\")" : "", where, advice);
    free(fname);
}

#define IDACHECK(call, what)                                                                                      \
    do {                                                                                                          \
        int flag_ = (call);                                                                                       \
        if (flag_ < 0) {                                                                                          \
            char *name_ = IDAGetReturnFlagName(flag_);                                                            \
            st = RC_SET(err, RC_ESOLVER, "IDA call %s failed at t = %.9g s: %s (%s)", what, t, name_ ? name_ : "?", \
                        c.msg);                                                                                   \
            free(name_);                                                                                          \
            goto done;                                                                                            \
        }                                                                                                         \
    } while (0)

static rc_status ida_run(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                         rc_error *err)
{
    rc_status st = RC_OK;
    double t = 0.0;
    rc_error local_err;
    if (!err) err = &local_err;
    rc_error_clear(err);
    rc_stats s;
    memset(&s, 0, sizeof s);
    SUNContext ctx = NULL;
    N_Vector yy = NULL, yp = NULL, ytn = NULL, ypt = NULL, ysamp = NULL, idv = NULL;
    rc_impacts im;
    memset(&im, 0, sizeof im);
    char note[sizeof s.sampling_note];
    rc_impacts_sampling_note(m, note, sizeof note);
    int *rootdir = NULL, *roots = NULL, *zeno_n = NULL;
    double *gbuf = NULL, *flook = NULL, *bp = NULL, *zeno_t = NULL;
    int nbp = 0, ibp = 0;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    void *ida = NULL;
    rc_output *out = NULL;
    frame_buf fb;
    memset(&fb, 0, sizeof fb);
    const char *fail_reason = NULL;
    char reason[2048] = "";
    rc_data *d = rc_data_new(m);
    const double tend = opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    const double dtout = opt && opt->dt_out_override > 0 ? opt->dt_out_override : m->dtout;
    const int show = opt && opt->progress, tty = show && isatty(2);
    ev_sink sink = {NULL, opt ? opt->on_event : NULL, opt ? opt->user : NULL, 0, ""};
    const int evrec = rc_event_records(m);
    double wall0 = wall_now(), last_progress = wall0;
    const int nr = rc_root_count(m);
    ida_ctx c = {m, d, m->ny, NULL, NULL, NULL, opt ? opt->stop : NULL, ""};

    if (!d || !frame_alloc(m, &fb)) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    if (m->jnt && m->jnt->n > 0) {
        if (!(c.jw = rc_jnt_work_new(m))) {
            st = RC_SET(err, RC_ENOMEM, "out of memory for the joints");
            goto done;
        }
        c.n = m->ny + rc_jnt_nextra(c.jw);
        if (!(c.yrec = calloc((size_t)c.n, sizeof(double)))) {
            st = RC_SET(err, RC_ENOMEM, "out of memory for the joints");
            goto done;
        }
    }
    if (SUNContext_Create(NULL, &ctx)) {
        st = RC_SET(err, RC_ESOLVER, "SUNContext_Create failed");
        goto done;
    }
    yy = N_VNew_Serial(c.n, ctx);
    yp = N_VNew_Serial(c.n, ctx);
    ytn = N_VNew_Serial(c.n, ctx);
    ypt = N_VNew_Serial(c.n, ctx);
    ysamp = N_VNew_Serial(c.n, ctx);
    idv = N_VNew_Serial(c.n, ctx);
    /* optimised vector operations, inherited by IDA's clones (nvfast.h) */
    N_Vector vecs[] = {yy, yp, ytn, ypt, ysamp, idv};
    for (size_t k = 0; k < sizeof vecs / sizeof vecs[0]; k++) rc_nvector_fast(vecs[k]);
    rootdir = calloc((size_t)nr + 1, sizeof(int));
    roots = calloc((size_t)nr + 1, sizeof(int));
    gbuf = calloc((size_t)nr + 1, sizeof(double));
    zeno_t = calloc((size_t)m->ninter + 1, sizeof(double));
    zeno_n = calloc((size_t)m->ninter + 1, sizeof(int));
    flook = calloc((size_t)c.n, sizeof(double));
    c.jsave = calloc((size_t)m->nnz + 1, sizeof(double));
    const int64_t nnz = c.jw ? rc_jnt_nnz(c.jw) : m->nnz;
    A = SUNSparseMatrix(c.n, c.n, nnz, CSC_MAT, ctx);
    if (rc_impacts_init(&im, m) || !yy || !yp || !ytn || !ypt || !ysamp || !idv || !rootdir || !roots ||
        !gbuf || !zeno_t || !zeno_n || !flook || !c.jsave || !A) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the solver");
        goto done;
    }
    if (!(LS = SUNLinSol_KLU(yy, A, ctx))) {
        st = RC_SET(err, RC_ESOLVER, "SUNLinSol_KLU failed");
        goto done;
    }
    double *yd = N_VGetArrayPointer(yy), *ypd = N_VGetArrayPointer(yp);
    N_VConst(0.0, yy);
    rc_initial_state(m, yd);
    rc_modes_init(m, d, t, yd);
    if ((st = open_output(m, opt ? opt->output_path : NULL, note, &out, err,
                          c.jw ? "IDA BDF, Newton, KLU sparse direct, rootfinding; joints: stabilised index-2 "
                                 "constraints (GGL)"
                               : "IDA BDF, Newton, KLU sparse direct, rootfinding")))
        goto done;
    sink.out = out;
    {
        int jmp = 0;
        resolve_touching(m, d, t, yd, flook, &sink, &im, &s.events, &jmp, &st, err);
        if (st) goto done;
    }

    ida = IDACreate(ctx);
    if (!ida) {
        st = RC_SET(err, RC_ESOLVER, "IDACreate failed");
        goto done;
    }
    IDACHECK(IDASetUserData(ida, &c), "IDASetUserData");
    IDACHECK(IDASetErrHandlerFn(ida, cb_err, &c), "IDASetErrHandlerFn");
    {
        double *p = N_VGetArrayPointer(yp);
        if (rc_assemble_rhs(m, d, t, yd, p)) {
            st = RC_SET(err, RC_ESOLVER, "the forces at t = 0 could not be evaluated");
            goto done;
        }
        if (c.jw && (rc_jnt_project_velocities(m, c.jw, yd) || rc_assemble_rhs(m, d, t, yd, p) ||
                     rc_jnt_consistent(m, c.jw, yd, p))) {
            st = RC_SET(err, RC_ESOLVER, "the joints' constraint rows are dependent at t = 0 (the model's "
                                         "compile checks them: an internal error)");
            goto done;
        }
    }
    IDACHECK(IDAInit(ida, cb_res, t, yy, yp), "IDAInit");
    IDACHECK(IDAWFtolerances(ida, cb_ewt), "IDAWFtolerances");
    IDACHECK(IDASetLinearSolver(ida, LS, A), "IDASetLinearSolver");
    IDACHECK(IDASetJacFn(ida, cb_jac), "IDASetJacFn");
    IDACHECK(IDASetMaxOrd(ida, m->max_order), "IDASetMaxOrd");
    IDACHECK(IDASetMaxNumSteps(ida, m->max_steps), "IDASetMaxNumSteps");
    /* Newton's convergence test as CVODE's (0.1 of the error test; IDA's
     * default is 0.33): the same accuracy of the corrections on both paths */
    IDACHECK(IDASetNonlinConvCoef(ida, 0.1), "IDASetNonlinConvCoef");
    if (m->hmax > 0) IDACHECK(IDASetMaxStep(ida, m->hmax), "IDASetMaxStep");
    if (m->h0 > 0) IDACHECK(IDASetInitStep(ida, m->h0), "IDASetInitStep");
    if (c.jw) {
        /* the multipliers are algebraic, out of the error test */
        rc_jnt_id(m, c.jw, N_VGetArrayPointer(idv));
        IDACHECK(IDASetId(ida, idv), "IDASetId");
        IDACHECK(IDASetSuppressAlg(ida, SUNTRUE), "IDASetSuppressAlg");
    }
    if (nr > 0) IDACHECK(IDARootInit(ida, nr, cb_root), "IDARootInit");
    IDACHECK(IDASetNoInactiveRootWarn(ida), "IDASetNoInactiveRootWarn");
    if (nr > 0) {
        root_directions(m, d, rootdir);
        IDACHECK(IDASetRootDirection(ida, rootdir), "IDASetRootDirection");
    }
    if ((nbp = time_breakpoints(m, tend, &bp)) < 0) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    IDACHECK(IDASetStopTime(ida, nbp > 0 ? bp[0] : tend), "IDASetStopTime");

    double e0[RC_NENERGY];
    rc_energy(m, d, t, yd, e0);
    if ((st = record(&c, out, &fb, t, yd, ypd, 0, err))) goto done;

    long nout = 1;
    double tout = fmin(dtout, tend);
    double t_prev = t;
    const double dt_contact =
        evrec && m->nbody <= RC_CONTACT_REC_MAX_BODIES ? rc_contact_record_interval(m, dtout) : 0.0;
    double t_contact_rec = -INFINITY;
    long single = 0;
    while (t < tend) {
        if (sink.stop) {
            snprintf(reason, sizeof reason, "%s: the results up to there are kept", sink.why);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            break;
        }
        int paused_stop = 0;
        while (pause && t >= pause->until && !paused_stop) {
            const double tu = pause->until;
            const double *yu = yd;
            if (t > tu) {
                IDACHECK(IDAGetDky(ida, tu, 0, ytn), "IDAGetDky");
                yu = N_VGetArrayPointer(ytn);
            }
            paused_stop = pause->reached(pause, tu, yu);
        }
        if (paused_stop) {
            snprintf(reason, sizeof reason, "stopped by the caller at t = %.9g s: the results up to there are kept", t);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            break;
        }
        /* single steps while an impact is in progress (its maxima are
         * sampled at every step), as the CVODE backend */
        const int one_step = rc_impacts_active(&im);
        const double tcall = pause && pause->until < tout ? pause->until : tout;
        int flag = IDASolve(ida, tcall, &t, yy, yp, one_step ? IDA_ONE_STEP : IDA_NORMAL);
        if (opt && opt->stop && *opt->stop) {
            snprintf(reason, sizeof reason, "interrupted at t = %.9g s (signal): the results up to there are kept", t);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            break;
        }
        if (one_step && flag >= 0 && ++single > m->max_steps) flag = IDA_TOO_MUCH_WORK;
        if (flag >= 0) sample_step(ida, &im, m, d, t_prev, t, yy, ysamp);
        t_prev = t;
        if (flag < 0) {
            failure_advice(m, d, ida, flag, t, tout, c.msg, ytn, ysamp, reason, sizeof reason);
            fail_reason = reason;
            st = RC_SET(err, RC_ESOLVER, "%s", reason);
            break;
        }
        const int at_bp = flag == IDA_TSTOP_RETURN && ibp < nbp && t >= bp[ibp];
        if (at_bp || flag == IDA_ROOT_RETURN)
            if ((st = outputs_before(ida, &c, out, &fb, t, tend, dtout, &tout, &nout, ytn, ypt, err))) goto done;
        if (at_bp) {
            s.events++;
            if ((st = sink_event(&sink, t, "impvel_stop", "/IMPVEL", NULL, err))) goto done;
            add_stats(ida, &s);
            IDACHECK(restart(&c, ida, t, yy, yp), "IDAReInit");
            s.reinits++;
            while (ibp < nbp && bp[ibp] <= t) ibp++;
            IDACHECK(IDASetStopTime(ida, ibp < nbp ? bp[ibp] : tend), "IDASetStopTime");
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if ((evrec || on_out) && (st = record(&c, out, &fb, t, yd, ypd, evrec, err))) goto done;
            if (on_out) {
                nout++;
                tout = fmin(nout * dtout, tend);
            }
            continue;
        }
        if (flag == IDA_ROOT_RETURN) {
            t_contact_rec = t;
            IDACHECK(IDAGetRootInfo(ida, roots), "IDAGetRootInfo");
            double t_ref = t;
            const int refined = refine_flat_roots(m, d, ida, t, roots, gbuf, ytn, &t_ref);
            if (refined > 0) {
                t = t_ref;
                memcpy(yd, N_VGetArrayPointer(ytn), (size_t)c.n * sizeof(double));
            }
            rc_event ev[RC_MAX_EV];
            int jumped = 0;
            int nev = rc_events_apply(m, d, t, yd, roots, ev, RC_MAX_EV, &jumped);
            s.events += nev;
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) rc_impacts_event(&im, m, d, ev[k].inter, ev[k].kind, t, yd);
            for (int k = 0; k < nev && k < RC_MAX_EV; k++)
                if ((st = write_event(m, d, &sink, t, yd, &ev[k], err))) goto done;
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) {
                const int i = ev[k].inter;
                if (i < 0) continue; /* a contact coupling: its faces change modes with the state moving */
                zeno_n[i] = t - zeno_t[i] <= RC_ZENO_REL * fmax(fabs(t), dtout) ? zeno_n[i] + 1 : 0;
                zeno_t[i] = t;
                if (zeno_n[i] > RC_ZENO_MAX) {
                    snprintf(reason, sizeof reason,
                             "event accumulation (Zeno) at t = %.9g s in %s: more than %d events within %.2g s of "
                             "each other (last: %s); the modes of this element switch without the state moving: "
                             "tighter tolerances or a smoother law may help",
                             t, m->inter_name[i], RC_ZENO_MAX, RC_ZENO_REL * fmax(fabs(t), dtout), ev[k].kind);
                    fail_reason = reason;
                    st = RC_SET(err, RC_ESOLVER, "%s", reason);
                    goto done;
                }
            }
            nev += resolve_touching(m, d, t, yd, flook, &sink, &im, &s.events, &jumped, &st, err);
            if (st) goto done;
            if (nev > 0 && nr > 0) {
                root_directions(m, d, rootdir);
                IDACHECK(IDASetRootDirection(ida, rootdir), "IDASetRootDirection");
            }
            /* every mode change restarts IDA from the event state with a
             * consistent Y' (docs/theory.md, "IDA backend") */
            if (refined > 0 || jumped || nev > 0 || root_on_zero(m, d, t, yd, gbuf)) {
                add_stats(ida, &s);
                IDACHECK(restart(&c, ida, t, yy, yp), "IDAReInit");
                s.reinits++;
            }
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if (nev > 0 && (evrec || on_out) && (st = record(&c, out, &fb, t, yd, ypd, evrec, err))) goto done;
            if (on_out) {
                nout++;
                tout = fmin(nout * dtout, tend);
            }
        } else if (one_step && t < tout) {
            if (dt_contact > 0 && rc_impacts_active(&im) && t - t_contact_rec >= dt_contact) {
                if ((st = record(&c, out, &fb, t, yd, ypd, RC_REC_CONTACT, err))) goto done;
                t_contact_rec = t;
            }
        } else {
            while (tout <= t) {
                const double *yo = yd, *ypo = ypd;
                if (tout < t) {
                    IDACHECK(IDAGetDky(ida, tout, 0, ytn), "IDAGetDky");
                    IDACHECK(IDAGetDky(ida, tout, 1, ypt), "IDAGetDky");
                    yo = N_VGetArrayPointer(ytn);
                    ypo = N_VGetArrayPointer(ypt);
                }
                if ((st = record(&c, out, &fb, tout, yo, ypo, 0, err))) goto done;
                single = 0;
                nout++;
                const double next = fmin(nout * dtout, tend);
                if (next <= tout) break;
                tout = next;
                if (tend - tout < 1e-12 * tend) tout = tend;
            }
        }
        if (show && wall_now() - last_progress > (tty ? 0.5 : RC_LOG_EVERY)) {
            long nst = 0;
            IDAGetNumSteps(ida, &nst);
            progress_line(tend, &s, t, s.steps + nst, wall0, tty);
            last_progress = wall_now();
        }
    }
    double e1[RC_NENERGY];
    rc_energy(m, d, t, yd, e1);
    s.energy_residual = e1[RC_E_TOTAL] - e0[RC_E_TOTAL];
    s.t_end = t;
    if (opt && opt->y_end) memcpy(opt->y_end, yd, (size_t)m->ny * sizeof(double));

done:
    if (ida) add_stats(ida, &s);
    rc_impacts_finish(&im);
    s.impacts = im.n;
    for (int k = 0; k < im.n && k < RC_STATS_IMPACTS; k++) s.impact[k] = im.row[k];
    snprintf(s.sampling_note, sizeof s.sampling_note, "%s", note);
    if (out && st == RC_OK) st = rc_output_impacts(out, im.n, im.row, err);
    else if (out) {
        rc_error e3;
        rc_output_impacts(out, im.n, im.row, &e3);
    }
    if (st != RC_OK) s.t_end = t;
    s.wall_time = wall_now() - wall0;
    if (tty) fprintf(stderr, "\n");
    if (out) {
        rc_error e2;
        rc_status st2 = rc_output_close(out, &s, st == RC_OK, fail_reason ? fail_reason : err->msg, &e2);
        if (st == RC_OK && st2) {
            st = st2;
            *err = e2;
        }
    }
    if (stats) *stats = s;
    IDAFree(&ida);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(yy);
    N_VDestroy(yp);
    N_VDestroy(ytn);
    N_VDestroy(ypt);
    N_VDestroy(ysamp);
    N_VDestroy(idv);
    rc_impacts_free(&im);
    free(rootdir);
    free(roots);
    free(gbuf);
    free(zeno_t);
    free(zeno_n);
    free(flook);
    free(bp);
    free(c.jsave);
    rc_jnt_work_free(c.jw);
    free(c.yrec);
    SUNContext_Free(&ctx);
    frame_free(&fb);
    rc_data_free(d);
    return st;
}

/* The backend of /SOLVER Method 2 (solver.h). */
const rc_solver rc_solver_ida = {"ida", RC_METHOD_IDA, ida_run};
