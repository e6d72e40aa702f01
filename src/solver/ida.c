/*
 * IDA backend: the model as the implicit system F(t, Y, Y') = 0 integrated
 * by IDA (variable-order BDF, Newton, KLU on a fixed sparse pattern), run
 * by the same loop as the CVODE backend (rc_drive, drive.c, through the
 * rc_backend table of integrator.h): the same rootfinding, events, records,
 * impacts table and statistics. The backend of /SOLVER Method 2
 * (rc_solver_ida, solver.h), and the one that runs models with joints
 * (docs/theory.md, "Joints"). Every mode change restarts IDA.
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
 * (engine/constraints/joints.c; IDACalcIC cannot: no algebraic unknown in the rows).
 *
 * Exact stick (engine/constraints/stick.h): Y = [y, Lambda], two rows per exact interface, F_Lambda = t_k . v_rel
 * while it sticks (lambda = Lambda' its friction force), Lambda' = 0
 * otherwise; the multipliers and the velocities of the sticking contacts
 * are made consistent at every (re)start (engine/constraints/stick.c), the slip roots
 * of the sticking contacts compare |lambda| (from Y') with the limit.
 * Joints and exact stick together: Y = [y, the joints' extras, the
 * stick's Lambda], whose multipliers are made consistent together at every
 * (re)start. The callbacks see one constraint set whatever the model holds
 * (engine/constraints/cset.h).
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

#include "base/error.h"
#include "engine/events/events.h"
#include "model/coupling.h"
#include "model/joint.h"
#include "model/model.h"
#include "engine/constraints/stick.h"
#include "solver/activepart.h"
#include "solver/impacts.h"
#include "solver/nvfast.h"
#include "solver/common.h"
#include "solver/integrator.h"
#include "solver/solver.h"
#include "engine/assembly/assembly.h"
#include "engine/constraints/cset.h"
#include "engine/constraints/joints.h"

typedef struct ida_ctx {
    const rc_model *m;
    rc_data *d;
    int n;          /* size of Y */
    double *jsave;  /* [nnz] Jacobian values of f on the model's pattern */
    rc_cset *cs;     /* the model's constraint sets (joints, exact stick) composed into one:
                        the extended vector, pattern, residual, Jacobian (NULL: none) */
    double *yrec;    /* with constraint sets: the record vector (joints: Y with lambda =
                        Lambda'; exact stick: the sticking contacts' F_t = their multipliers) */
    volatile sig_atomic_t *stop;
    char msg[512];  /* IDA's last error message */
    int nwarn;      /* IDA's warnings in this run (rc_bk_keep_error) */
    char integrator[320]; /* the integrator's line */
    /* the integrator and its vectors (ida_open, ida_start) */
    SUNContext ctx;
    void *ida;
    SUNMatrix A;
    SUNLinearSolver LS;
    N_Vector yy, yp, ytn, ypt, ysamp, idv, ewt; /* ewt: the error weights of a restart's first step */
    rc_rootmap rm; /* the root functions IDA is given (integrator.h) */
    rc_actpart ap; /* the Newton matrix on the active part of the pattern (activepart.h; with
                      exact stick or joints on the extended pattern; both: whole) */
} ida_ctx;

/* ---- IDA callbacks -------------------------------------------------- */
static void cb_err(int code, const char *module, const char *function, char *msg, void *ud)
{
    ida_ctx *c = ud;
    rc_bk_keep_error(c ? c->stop : NULL, c ? c->msg : NULL, sizeof c->msg, c ? &c->nwarn : NULL, code, module,
                     function, msg);
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
    if (c->cs) rc_cset_residual(c->m, c->d, c->cs, y, p, r);
    return 0;
}

/* dF/dY + cj dF/dY' on the fixed pattern: cj I - J_f on the model's
 * block (J_f from the engine's Jacobian), the constraint sets' exact
 * blocks; on the active part of the pattern where it is on (activepart.h). */
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
    if (!c->cs) {
        /* IDA zeroed A (pattern included): cj I - J_f on the active part */
        if (rc_actpart_follow(&c->ap, m, c->d, t, N_VGetArrayPointer(yy), c->jsave)) return -1;
        return rc_actpart_load(&c->ap, m, A, c->LS, -1.0, c->jsave, cj, 1) ? -1 : 0;
    }
    if (c->ap.on) { /* the extended matrix on its active part */
        rc_cset_jacobian(m, c->d, c->cs, cj, N_VGetArrayPointer(yy), N_VGetArrayPointer(yp), c->jsave, c->ap.xval);
        if (rc_actpart_follow(&c->ap, m, c->d, t, N_VGetArrayPointer(yy), c->jsave)) return -1;
        return rc_actpart_load(&c->ap, m, A, c->LS, 1.0, c->ap.xval, 0.0, 1) ? -1 : 0;
    }
    sunindextype *cp = SUNSparseMatrix_IndexPointers(A), *ri = SUNSparseMatrix_IndexValues(A);
    const int64_t *pc, *pr;
    rc_cset_pattern(c->cs, &pc, &pr);
    for (int k = 0; k <= c->n; k++) cp[k] = (sunindextype)pc[k];
    for (int64_t k = 0; k < pc[c->n]; k++) ri[k] = (sunindextype)pr[k];
    rc_cset_jacobian(m, c->d, c->cs, cj, N_VGetArrayPointer(yy), N_VGetArrayPointer(yp), c->jsave,
                     SUNSparseMatrix_Data(A));
    return 0;
}

static int cb_root(realtype t, N_Vector yy, N_Vector yp, realtype *g, void *ud)
{
    ida_ctx *c = ud;
    c->d->sc->n_root++;
    double *gf = rc_rootmap_full(&c->rm, g);
    rc_assemble_roots(c->m, c->d, t, N_VGetArrayPointer(yy), gf);
    if (c->cs) rc_cset_roots(c->m, c->d, c->cs, t, N_VGetArrayPointer(yy), N_VGetArrayPointer(yp), gf);
    rc_rootmap_keep(&c->rm, t, gf); /* for the physics checks */
    rc_rootmap_gather(&c->rm, g);
    return 0;
}

/* Error weights: the model's states by the rule every backend shares
 * (common.h rc_bk_state_tol), the constraint sets' extras by their own
 * absolute tolerances (rc_cset_atol). */
static int cb_ewt(N_Vector yv, N_Vector wv, void *ud)
{
    const ida_ctx *c = ud;
    const rc_model *m = c->m;
    const double *y = N_VGetArrayPointer(yv);
    double *w = N_VGetArrayPointer(wv);
    for (int k = 0; k < c->n; k++) {
        const double s = k < m->ny ? rc_bk_state_tol(m, c->d, k, y[k])
                                   : rc_cset_atol(m, c->cs, k - m->ny) + m->rtol * fabs(y[k]);
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

/* The first step after a restart at t (docs/theory.md 7.7): IDA's own
 * estimate (0 here), unless its bound 0.5 / ||Y'|| (the error norm of its
 * differential components) falls below the rounding of t, where a step
 * does not move t and IDA, stepping on the spot, never gets past it (the
 * damping work of a damped wall at the instant it closes: 3e5 W against an
 * energy tolerance of 1e-14 J): then 100 eps |t|, the CVODE backend's
 * lower bound. */
static double first_step(ida_ctx *c, double t, N_Vector yy, N_Vector yp)
{
    const double hmin = 100.0 * DBL_EPSILON * fabs(t);
    if (!(hmin > 0) || cb_ewt(yy, c->ewt, c)) return 0.0;
    /* IDA's norm: over the differential components when it has an id */
    const double norm = c->cs ? N_VWrmsNormMask(yp, c->ewt, c->idv) : N_VWrmsNorm(yp, c->ewt);
    return 0.5 < hmin * norm ? hmin : 0.0;
}

/* Consistent Y' (and multipliers) at (t, Y), then IDA restarted there.
 * Without constraint sets Y' = f(t, y) exactly; with them the velocities
 * and multipliers of every set are made consistent (rc_cset_consistent:
 * IDACalcIC cannot, the constraint rows hold no algebraic unknown). */
static int restart(ida_ctx *c, void *ida, double t, N_Vector yy, N_Vector yp)
{
    const rc_model *m = c->m;
    double *y = N_VGetArrayPointer(yy), *p = N_VGetArrayPointer(yp);
    if (c->cs) {
        const int st = rc_cset_consistent(m, c->d, c->cs, t, y, p, 0);
        if (st) return st == -2 ? IDA_FIRST_RES_FAIL : IDA_CONV_FAIL;
    } else if (rc_assemble_rhs(m, c->d, t, y, p))
        return IDA_FIRST_RES_FAIL;
    if (m->h0 <= 0) {
        const int flag = IDASetInitStep(ida, first_step(c, t, yy, yp));
        if (flag < 0) return flag;
    }
    return IDAReInit(ida, t, yy, yp);
}

/* The message of a failed IDASolve: where, and the likely cause. */
static void failure_advice(const rc_model *m, const rc_data *d, void *ida, int flag, double t, double tout,
                           const char *msg, N_Vector tmp1, N_Vector tmp2, char *buf, size_t n)
{
    double h = 0.0;
    IDAGetCurrentStep(ida, &h);
    char elem[200] = "";
    int istate = -1;
    if (IDAGetEstLocalErrors(ida, tmp1) == IDA_SUCCESS && IDAGetErrWeights(ida, tmp2) == IDA_SUCCESS) {
        /* the components in the error test: not the multipliers lambda */
        const int len = (int)N_VGetLength(tmp1), nr = m->jnt ? m->jnt->nrows : len - m->ny;
        const int imax = rc_bk_worst_error(N_VGetArrayPointer(tmp1), N_VGetArrayPointer(tmp2), len, m->ny, m->ny + nr);
        if (imax >= 0 && imax < m->ny) rc_state_name(m, istate = imax, elem, sizeof elem);
        else if (imax >= 0 && m->jnt && imax - m->ny < 2 * m->jnt->nrows + 1) rc_jnt_extra_name(m, imax - m->ny, elem, sizeof elem);
    }
    char *fname = IDAGetReturnFlagName(flag);
    rc_fail_kind kind = RC_FAIL_OTHER;
    switch (flag) {
    case IDA_TOO_MUCH_WORK: kind = RC_FAIL_MAX_STEPS; break;
    case IDA_TOO_MUCH_ACC: kind = RC_FAIL_ACCURACY; break;
    case IDA_ERR_FAIL: kind = RC_FAIL_ERROR_TEST; break;
    case IDA_CONV_FAIL:
    case IDA_LSETUP_FAIL:
    case IDA_LSOLVE_FAIL:
    case IDA_NO_RECOVERY:
    case IDA_LINESEARCH_FAIL: kind = RC_FAIL_NEWTON; break;
    case IDA_RES_FAIL:
    case IDA_REP_RES_ERR:
    case IDA_FIRST_RES_FAIL: kind = RC_FAIL_FORCES; break;
    case IDA_RTFUNC_FAIL: kind = RC_FAIL_ROOTS; break;
    default: break;
    }
    const char *advice = rc_bk_advice(kind, m);
    rc_bk_failure_message(m, d, "IDA", t, h, tout, fname, msg, elem, istate, advice, buf, n);
    free(fname);
}

/* ---- the backend's operations (integrator.h rc_backend) ---------------- */
#define IDACHECK(call, what)                                                                                  \
    do {                                                                                                      \
        int flag_ = (call);                                                                                   \
        if (flag_ < 0) {                                                                                      \
            char *name_ = IDAGetReturnFlagName(flag_);                                                        \
            rc_status st_ = RC_SET(err, RC_ESOLVER, "IDA call %s failed at t = %.9g s: %s (%s)", what, 0.0,   \
                                   name_ ? name_ : "?", c->msg);                                              \
            free(name_);                                                                                      \
            return st_;                                                                                       \
        }                                                                                                     \
    } while (0)

static rc_status ida_open(void *self, const rc_model *m, rc_data *d, const rc_run_options *opt, double **y,
                          double **yp, int *n, const char **integrator, rc_error *err)
{
    ida_ctx *c = self;
    c->m = m;
    c->d = d;
    c->n = m->ny;
    c->stop = opt ? opt->stop : NULL;
    if (rc_rootmap_init(&c->rm, m, opt)) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    if (rc_cset_needed(m)) { /* Y = [y, the extras of each set] */
        if (!(c->cs = rc_cset_new(m)) || !(c->yrec = calloc((size_t)m->ny + rc_cset_nextra(c->cs), sizeof(double))))
            return RC_SET(err, RC_ENOMEM, "out of memory for the constraint sets (joints, exact stick)");
        c->n = m->ny + rc_cset_nextra(c->cs);
    }
    if (SUNContext_Create(NULL, &c->ctx)) return RC_SET(err, RC_ESOLVER, "SUNContext_Create failed");
    c->yy = N_VNew_Serial(c->n, c->ctx);
    c->yp = N_VNew_Serial(c->n, c->ctx);
    c->ytn = N_VNew_Serial(c->n, c->ctx);
    c->ypt = N_VNew_Serial(c->n, c->ctx);
    c->ysamp = N_VNew_Serial(c->n, c->ctx);
    c->idv = N_VNew_Serial(c->n, c->ctx);
    c->ewt = N_VNew_Serial(c->n, c->ctx);
    /* optimised vector operations, inherited by IDA's clones (nvfast.h) */
    N_Vector vecs[] = {c->yy, c->yp, c->ytn, c->ypt, c->ysamp, c->idv, c->ewt};
    for (size_t k = 0; k < sizeof vecs / sizeof vecs[0]; k++) rc_nvector_fast(vecs[k]);
    c->jsave = calloc((size_t)m->nnz + 1, sizeof(double));
    const int64_t nnz = c->cs ? rc_cset_nnz(c->cs) : m->nnz;
    c->A = SUNSparseMatrix(c->n, c->n, nnz, CSC_MAT, c->ctx);
    if (!c->yy || !c->yp || !c->ytn || !c->ypt || !c->ysamp || !c->idv || !c->ewt || !c->jsave || !c->A)
        return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    if (!(c->LS = SUNLinSol_KLU(c->yy, c->A, c->ctx))) return RC_SET(err, RC_ESOLVER, "SUNLinSol_KLU failed");
    /* a set that gives no active slots (a composition): the whole pattern */
    if (rc_actpart_open(&c->ap, m, c->LS, !c->cs || rc_cset_keeps(c->cs), c->cs))
        return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    N_VConst(0.0, c->yy);
    *y = N_VGetArrayPointer(c->yy);
    *yp = N_VGetArrayPointer(c->yp);
    *n = c->n;
    snprintf(c->integrator, sizeof c->integrator, "IDA BDF, Newton, KLU sparse direct, rootfinding%s%s",
             c->cs ? "; " : "", c->cs ? rc_cset_what(c->cs) : "");
    *integrator = c->integrator;
    return RC_OK;
}

static rc_status ida_start(void *self, rc_error *err)
{
    ida_ctx *c = self;
    const rc_model *m = c->m;
    rc_data *d = c->d;
    const double t = 0.0;
    void *ida = c->ida = IDACreate(c->ctx);
    if (!ida) return RC_SET(err, RC_ESOLVER, "IDACreate failed");
    IDACHECK(IDASetUserData(ida, c), "IDASetUserData");
    IDACHECK(IDASetErrHandlerFn(ida, cb_err, c), "IDASetErrHandlerFn");
    double *yd = N_VGetArrayPointer(c->yy), *p = N_VGetArrayPointer(c->yp);
    if (rc_assemble_rhs(m, d, t, yd, p)) return RC_SET(err, RC_ESOLVER, "the forces at t = 0 could not be evaluated");
    if (c->cs && rc_cset_consistent(m, d, c->cs, t, yd, p, 1))
        return RC_SET(err, RC_ESOLVER, "%s", rc_cset_start_failed(c->cs));
    IDACHECK(IDAInit(ida, cb_res, t, c->yy, c->yp), "IDAInit");
    IDACHECK(IDAWFtolerances(ida, cb_ewt), "IDAWFtolerances");
    IDACHECK(IDASetLinearSolver(ida, c->LS, c->A), "IDASetLinearSolver");
    IDACHECK(IDASetJacFn(ida, cb_jac), "IDASetJacFn");
    IDACHECK(IDASetMaxOrd(ida, m->max_order), "IDASetMaxOrd");
    IDACHECK(IDASetMaxNumSteps(ida, m->max_steps), "IDASetMaxNumSteps");
    IDACHECK(IDASetMaxErrTestFails(ida, RC_MAX_ERR_TEST_FAILS), "IDASetMaxErrTestFails");
    IDACHECK(IDASetMaxConvFails(ida, RC_MAX_CONV_FAILS), "IDASetMaxConvFails");
    /* Newton's convergence test as CVODE's (0.1 of the error test; IDA's
     * default is 0.33): the same accuracy of the corrections on both paths */
    IDACHECK(IDASetNonlinConvCoef(ida, 0.1), "IDASetNonlinConvCoef");
    if (m->hmax > 0) IDACHECK(IDASetMaxStep(ida, m->hmax), "IDASetMaxStep");
    if (m->h0 > 0) IDACHECK(IDASetInitStep(ida, m->h0), "IDASetInitStep");
    if (c->cs) {
        /* the multipliers are algebraic, out of the error test */
        rc_cset_id(m, c->cs, N_VGetArrayPointer(c->idv));
        IDACHECK(IDASetId(ida, c->idv), "IDASetId");
        IDACHECK(IDASetSuppressAlg(ida, SUNTRUE), "IDASetSuppressAlg");
    }
    if (c->rm.n > 0) IDACHECK(IDARootInit(ida, c->rm.n, cb_root), "IDARootInit");
    IDACHECK(IDASetNoInactiveRootWarn(ida), "IDASetNoInactiveRootWarn");
    return RC_OK;
}

static int ida_solve(void *self, double tout, double *t, int *one_step)
{
    ida_ctx *c = self;
    return IDASolve(c->ida, tout, t, c->yy, c->yp, *one_step ? IDA_ONE_STEP : IDA_NORMAL);
}

static int ida_dky(void *self, double t, int k, int slot, const double **out)
{
    ida_ctx *c = self;
    N_Vector v = slot == RC_BK_SAMPLE ? c->ysamp : k == 1 ? c->ypt : c->ytn;
    int flag = IDAGetDky(c->ida, t, k, v);
    *out = N_VGetArrayPointer(v);
    return flag;
}

static int ida_last_step(void *self, double *tn, double *hu)
{
    ida_ctx *c = self;
    int flag = IDAGetCurrentTime(c->ida, tn);
    return flag < 0 ? flag : IDAGetLastStep(c->ida, hu);
}

/* roots and directions in the engine's full layout (integrator.h rc_rootmap) */
static int ida_root_info(void *self, int *roots)
{
    ida_ctx *c = self;
    int flag = IDAGetRootInfo(c->ida, rc_rootmap_info(&c->rm, roots));
    if (flag == IDA_SUCCESS) rc_rootmap_found(&c->rm, roots);
    return flag;
}
static int ida_set_root_dirs(void *self, int *dir)
{
    ida_ctx *c = self;
    return IDASetRootDirection(c->ida, (int *)rc_rootmap_dirs(&c->rm, dir));
}
static int ida_set_stop_time(void *self, double tstop) { return IDASetStopTime(((ida_ctx *)self)->ida, tstop); }

/* Every restart (an event, a breakpoint) from the state with a consistent
 * Y' (docs/theory.md, "IDA backend"). */
static int ida_restart(void *self, double t, int at_breakpoint)
{
    ida_ctx *c = self;
    (void)at_breakpoint;
    /* the first step: IDA's own estimate bounded below by the rounding of
     * t (first_step; docs/theory.md 7.7: the CVODE backend's restart_step
     * cost IDA steps, its step growing at most twofold per step), or
     * /SOLVER H0 */
    return restart(c, c->ida, t, c->yy, c->yp);
}

static void ida_add_stats(void *self, rc_stats *s)
{
    ida_ctx *c = self;
    if (c->ida) add_stats(c->ida, s);
    if (c->d && c->ap.on) { /* counted on the active part only */
        c->d->n_klu_sym = rc_actpart_analyses(&c->ap);
        c->d->newton_nnz = (long)c->ap.nnz_max;
    }
}

static long ida_steps(void *self)
{
    long nst = 0;
    IDAGetNumSteps(((ida_ctx *)self)->ida, &nst);
    return nst;
}

static void ida_failure(void *self, int flag, double t, double tout, char *buf, size_t n)
{
    ida_ctx *c = self;
    failure_advice(c->m, c->d, c->ida, flag, t, tout, c->msg, c->ytn, c->ysamp, buf, n);
}

static const char *ida_last_msg(void *self) { return ((ida_ctx *)self)->msg; }

/* A record of (Y, Y'): with constraint sets, the record vector (the
 * joints' reactions lambda = Lambda' in the slots of Lambda, the sticking
 * contacts' F_t their multipliers' force). */
static const double *ida_record_vector(void *self, double t, const double *Y, const double *Yp)
{
    ida_ctx *c = self;
    if (!c->cs) return Y;
    rc_cset_record(c->m, c->d, c->cs, t, Y, Yp, c->yrec);
    return c->yrec;
}

/* The sets' state before the events of a root return (exact stick: the
 * sticking contacts' F_t take their multipliers' force, for the slip
 * direction and the event records). */
static void ida_before_events(void *self)
{
    ida_ctx *c = self;
    if (c->cs) rc_cset_before_events(c->m, c->d, c->cs, N_VGetArrayPointer(c->yy), N_VGetArrayPointer(c->yp));
}

/* Every mode change restarts IDA from the event state. */
static int ida_after_events(void *self, double t, const double *y, int cpl_ev, int restart_anyway)
{
    (void)self;
    (void)t;
    (void)y;
    (void)cpl_ev;
    (void)restart_anyway;
    return 1;
}

static void ida_close(void *self)
{
    ida_ctx *c = self;
    IDAFree(&c->ida);
    SUNLinSolFree(c->LS);
    SUNMatDestroy(c->A);
    N_VDestroy(c->yy);
    N_VDestroy(c->yp);
    N_VDestroy(c->ytn);
    N_VDestroy(c->ypt);
    N_VDestroy(c->ysamp);
    N_VDestroy(c->idv);
    N_VDestroy(c->ewt);
    free(c->jsave);
    rc_cset_free(c->cs);
    free(c->yrec);
    rc_actpart_close(&c->ap);
    rc_rootmap_free(&c->rm);
    SUNContext_Free(&c->ctx);
}

static const double *ida_roots_at(void *self, double t) { return rc_rootmap_at(&((ida_ctx *)self)->rm, t); }

static const rc_backend ida_backend = {
    .name = "IDA", .prefix = "IDA", .root_return = IDA_ROOT_RETURN, .tstop_return = IDA_TSTOP_RETURN,
    .too_much_work = IDA_TOO_MUCH_WORK, .open = ida_open, .start = ida_start, .solve = ida_solve, .dky = ida_dky,
    .last_step = ida_last_step, .root_info = ida_root_info, .set_root_dirs = ida_set_root_dirs,
    .set_stop_time = ida_set_stop_time, .restart = ida_restart, .add_stats = ida_add_stats, .steps = ida_steps,
    .failure = ida_failure, .flag_name = IDAGetReturnFlagName, .last_msg = ida_last_msg,
    .record_vector = ida_record_vector, .before_events = ida_before_events, .after_events = ida_after_events,
    .continued = NULL, .close = ida_close, .roots_at = ida_roots_at};

static rc_status ida_run(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                         rc_stats *stats, rc_error *err)
{
    ida_ctx c;
    memset(&c, 0, sizeof c);
    return rc_drive(m, opt, pause, pre, stats, err, &ida_backend, &c);
}

/* The backend of /SOLVER Method 2 (solver.h). */
const rc_solver rc_solver_ida = {"ida", RC_METHOD_IDA, ida_run};
