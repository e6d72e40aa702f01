/*
 * Forward sensitivities (rc_sens_run, include/ricochet/ricochet.h): the
 * derivatives of the state with respect to numeric deck fields, by CVODES
 * forward sensitivity analysis between the events and the jump of the
 * sensitivities at each event (docs/theory.md "Sensitivities").
 *
 * Design
 *  - The run is rc_drive on the CVODE backend (cvode.c) wrapped by this
 *    file's backend: every operation is cvode.c's, and this file adds the
 *    sensitivities to its integrator memory (CVodeSensInit after start,
 *    CVodeSensReInit after every restart). Everything the plain run does
 *    (events, touching contacts, restarts, the physics checks) is the same.
 *  - The parameters are deck fields: the model is compiled, not a function
 *    of p. A parameter enters through two more models compiled at p -+ h
 *    (m_lo, m_hi: the caller's --set overrides), each with its own run data
 *    whose modes are copied from the run's at every mode change. The
 *    sensitivity right-hand side (CVSensRhsFn) is
 *        s' = J s + df/dp,
 *    J s the central difference of f along s (the engine's right-hand side
 *    at y -+ e s), df/dp the central difference of the two models' f at the
 *    same (t, y) and modes. No kernel knows about the parameters, and any
 *    numeric field (a stiffness, a load curve's point, a friction
 *    coefficient, gravity, an initial velocity) is a parameter. The step h
 *    is the caller's (ricochet sens: 1e-4 relative); most forces are
 *    linear in their parameters, so the difference is exact to rounding.
 *  - Initial sensitivities: the central difference of the two models'
 *    initial states (an initial velocity or position is a parameter too).
 *  - Events: at a root of g (the first root found; the old modes' root
 *    function) at time tau, with f- (old modes) and f+ (new modes, after
 *    the events' state changes), and the events' state map y+ = R(y-, p)
 *    (the identity unless an event sets a history state):
 *        dtau/dp = -(g_y s- + g_p) / (g_t + g_y f-),
 *        s+ = R_y s- + R_p + (R_y f- - f+) dtau/dp,
 *    g_y s- and g_t + g_y f- by central differences of the root function
 *    along s- and along the flow, g_p from the two models; R_y v by central
 *    differences of the engine's event map (rc_events_apply from the old
 *    modes on scratch run data) along v, R_p from the two models.
 *    Every event restarts the integrator here (the plain run may continue
 *    across a continuous one): the sensitivities jump even where f does
 *    not.
 *  - Error control: CVODES's on the sensitivities too (CVodeSetSensErrCon),
 *    with the state's relative tolerance and absolute tolerances atol / |p|
 *    (a sensitivity of the size of the state over the parameter). Where
 *    that run fails (seen: a segment sphere rolling down an incline, its
 *    steps shrinking to 1e-9 s where the plain run's do not), the run is
 *    redone with the state's error test alone (rc_sens_info.errcon 0); on
 *    the drop, the slide and the hysteresis impacts both agree with whole
 *    runs, while a long chain of hysteresis impacts failed without the
 *    sensitivities' error test and passes with it.
 *  - The quaternions' projection (cvode.c) acts on the state only; their
 *    sensitivities are not projected (a drift of the order of the local
 *    error).
 */
#include <cvodes/cvodes.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdalign.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "engine/assembly/assembly.h"
#include "engine/assembly/data.h"
#include "engine/events/events.h"
#include "model/model.h"
#include "model/imposed.h"
#include "model/sensor.h"
#include "solver/integrator.h"
#include "solver/sens.h"
#include "solver/solver.h"

/* Central differences along a direction v: the step e is chosen so that
 * the largest relative change of a state, |e v_k| / (|y_k| + atol_k /
 * rtol), is RC_SENS_DIR_STEP [-]. */
#define RC_SENS_DIR_STEP 1e-6

typedef struct sens_ctx {
    const rc_backend *ib; /* cvode.c's operations (on the block's start) */
    const rc_model *m;
    rc_data *d; /* the run's data (rc_drive's) */
    int np, ny, nroot;
    const rc_model *const *mlo, *const *mhi;
    const double *dp;
    const double *pval; /* [np] the parameters' values (their tolerances' scale), NULL: 1 */
    rc_data **dlo, **dhi; /* [np] run data of the perturbed models (modes copied) */
    rc_data *dold;        /* the modes before a root return's events */
    rc_data *dscr;        /* scratch run data of the event's state map (reset_map) */
    void *cv;
    int nr;
    const int *kidx;
    double *yfull;   /* the driver's whole state (cvode.c) */
    N_Vector *yS;    /* [np] CVODES's sensitivities (the kept states) */
    N_Vector *abstolS;
    double *s0;      /* [np ny] the initial sensitivities (the constant states keep theirs) */
    double *ya, *yb, *fa, *fb, *fm, *fp, *sv, *yc; /* [ny] scratch */
    double *yminus;                                /* [ny] the state before a root return's events */
    double *ga;                                    /* [nroot] scratch */
    int *roots;                                        /* [nroot] the roots of the last root return */
    int pending;     /* yS holds the sensitivities after an event, for the restart */
    int on;          /* CVodeSensInit done */
    /* the outputs */
    int nt, it;
    const double *times;
    double *yout, *sout;
    rc_sens_info info;
    rc_sens_events *ev; /* the caller's events, NULL */
    int fail; /* a sensitivity evaluation failed (reported after the run) */
    int errcon; /* 1: the sensitivities in CVODES's error test */
} sens_ctx;

/* The block rc_drive runs on: cvode.c's context first (CVODE's user data
 * is its address, so that cvode.c's callbacks find it), this file's after. */
static size_t sens_offset(void)
{
    const size_t a = alignof(max_align_t), n = rc_cvode_self_size();
    return (n + a - 1) / a * a;
}
static sens_ctx *ctx_of(void *self) { return (sens_ctx *)((char *)self + sens_offset()); }

/* The modes and bands of the run data (what events change) from src to dst. */
static void copy_modes(const rc_model *m, const rc_data *src, rc_data *dst)
{
    const size_t ni = (size_t)m->ninter, np = (size_t)m->npt;
    memcpy(dst->inter_mode, src->inter_mode, ni * sizeof(int));
    memcpy(dst->inter_branch, src->inter_branch, ni * sizeof(int));
    memcpy(dst->inter_track, src->inter_track, ni * sizeof(int));
    memcpy(dst->inter_slip, src->inter_slip, ni * sizeof(int));
    memcpy(dst->inter_settled, src->inter_settled, ni * sizeof(int));
    memcpy(dst->inter_lowq, src->inter_lowq, ni * sizeof(int));
    memcpy(dst->inter_deck, src->inter_deck, ni * sizeof(int));
    memcpy(dst->inter_rband, src->inter_rband, ni * sizeof(double));
    memcpy(dst->inter_fcstr, src->inter_fcstr, ni * sizeof(double));
    memcpy(dst->inter_dref, src->inter_dref, 3 * ni * sizeof(double));
    memcpy(dst->inter_hacc, src->inter_hacc, 2 * ni * sizeof(double));
    memcpy(dst->inter_band, src->inter_band, 2 * ni * sizeof(double));
    if (m->nsens > 0) {
        memcpy(dst->sens_ton, src->sens_ton, (size_t)m->nsens * sizeof(double));
        memcpy(dst->sens_new, src->sens_new, (size_t)m->nsens * sizeof(int));
        memcpy(dst->sens_arm, src->sens_arm, 2 * (size_t)m->nsens * sizeof(double));
        memcpy(dst->sens_rel, src->sens_rel, (size_t)m->nsens * sizeof(int));
    }
    dst->t_bp = src->t_bp;
    if (np > 0) {
        memcpy(dst->pt_slip, src->pt_slip, np * sizeof(int));
        memcpy(dst->pt_lband, src->pt_lband, np * sizeof(double));
    }
}
static void copy_modes_all(sens_ctx *x, const rc_data *src)
{
    for (int j = 0; j < x->np; j++) {
        copy_modes(x->m, src, x->dlo[j]);
        copy_modes(x->m, src, x->dhi[j]);
    }
}

/* The step of a central difference along v at y (RC_SENS_DIR_STEP); 0
 * when v is zero. */
static double dir_step(const rc_model *m, const double *y, const double *v)
{
    double r = 0.0;
    for (int k = 0; k < m->ny; k++) {
        const double sc = fabs(y[k]) + m->atol[k] / m->rtol;
        const double q = fabs(v[k]) / sc;
        if (q > r) r = q;
    }
    return r > 0 && isfinite(r) ? RC_SENS_DIR_STEP / r : 0.0;
}

/* A reduced (CVODE) vector into a whole one: the constant states' entries
 * from cst (the initial sensitivities, or the state). */
static void to_full(const sens_ctx *x, N_Vector v, const double *cst, double *full)
{
    const double *r = N_VGetArrayPointer(v);
    memcpy(full, cst, (size_t)x->ny * sizeof(double));
    for (int j = 0; j < x->nr; j++) full[x->kidx[j]] = r[j];
}
static void to_reduced(const sens_ctx *x, const double *full, N_Vector v)
{
    double *r = N_VGetArrayPointer(v);
    for (int j = 0; j < x->nr; j++) r[j] = full[x->kidx[j]];
}

/* J v + df/dp_j at (t, y) with the run's modes into out (whole vectors);
 * the engine's status (> 0: recoverable). */
static int sens_rate(sens_ctx *x, int j, double t, const double *y, const double *v, double *out)
{
    const rc_model *m = x->m;
    const int ny = x->ny;
    int st = 0;
    const double e = dir_step(m, y, v);
    if (e > 0) {
        for (int k = 0; k < ny; k++) {
            x->ya[k] = y[k] + e * v[k];
            x->yb[k] = y[k] - e * v[k];
        }
        st = rc_assemble_rhs(m, x->d, t, x->ya, x->fa);
        if (!st) st = rc_assemble_rhs(m, x->d, t, x->yb, x->fb);
        if (st) return st;
        for (int k = 0; k < ny; k++) out[k] = (x->fa[k] - x->fb[k]) / (2.0 * e);
    } else {
        memset(out, 0, (size_t)ny * sizeof(double));
    }
    st = rc_assemble_rhs(x->mhi[j], x->dhi[j], t, y, x->fa);
    if (!st) st = rc_assemble_rhs(x->mlo[j], x->dlo[j], t, y, x->fb);
    if (st) return st;
    for (int k = 0; k < ny; k++) out[k] += (x->fa[k] - x->fb[k]) / x->dp[j];
    return 0;
}

/* CVODES's sensitivity right-hand side (CVSensRhsFn); the user data is
 * cvode.c's context, at the start of the block. */
static int cb_sens(int ns, realtype t, N_Vector y, N_Vector ydot, N_Vector *yS, N_Vector *ySdot, void *ud,
                   N_Vector t1, N_Vector t2)
{
    (void)ydot;
    (void)t1;
    (void)t2;
    sens_ctx *x = ctx_of(ud);
    double *yf = x->yc; /* the whole state at y */
    to_full(x, y, x->yfull, yf);
    for (int j = 0; j < ns; j++) {
        to_full(x, yS[j], x->s0 + (size_t)j * (size_t)x->ny, x->sv);
        const int st = sens_rate(x, j, t, yf, x->sv, x->fm);
        if (st) return st;
        to_reduced(x, x->fm, ySdot[j]);
    }
    return 0;
}

/* ---- the wrapped backend's operations ---------------------------------- */
static rc_status sb_open(void *self, const rc_model *m, rc_data *d, const rc_run_options *opt, double **y,
                         double **yp, int *n, const char **integrator, rc_error *err)
{
    sens_ctx *x = ctx_of(self);
    rc_status st = x->ib->open(self, m, d, opt, y, yp, n, integrator, err);
    if (st) return st;
    x->m = m;
    x->d = d;
    x->ny = m->ny;
    x->nroot = rc_root_count(m);
    const size_t ny = (size_t)m->ny + 1, nrt = (size_t)x->nroot + 1;
    double **v[] = {&x->ya, &x->yb, &x->fa, &x->fb, &x->fm, &x->fp, &x->sv, &x->yc, &x->yminus};
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
        if (!(*v[k] = calloc(ny, sizeof(double)))) return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    x->s0 = calloc(ny * (size_t)x->np, sizeof(double));
    x->ga = calloc(nrt, sizeof(double));
    x->roots = calloc(nrt, sizeof(int));
    x->dlo = calloc((size_t)x->np, sizeof(rc_data *));
    x->dhi = calloc((size_t)x->np, sizeof(rc_data *));
    x->dold = rc_data_new(m);
    x->dscr = rc_data_new(m);
    if (!x->s0 || !x->ga || !x->roots || !x->dlo || !x->dhi || !x->dold || !x->dscr)
        return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    for (int j = 0; j < x->np; j++)
        if (!(x->dlo[j] = rc_data_new(x->mlo[j])) || !(x->dhi[j] = rc_data_new(x->mhi[j])))
            return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    *integrator = "CVODES BDF, Newton, KLU sparse direct, rootfinding, forward sensitivities (staggered)";
    return RC_OK;
}

#define SCHECK(call, what)                                                                                   \
    do {                                                                                                     \
        const int flag_ = (call);                                                                            \
        if (flag_ < 0) return RC_SET(err, RC_ESOLVER, "CVODES call %s failed (flag %d)", what, flag_);       \
    } while (0)

static rc_status sb_start(void *self, rc_error *err)
{
    sens_ctx *x = ctx_of(self);
    const rc_model *m = x->m;
    rc_status st = x->ib->start(self, err);
    if (st) return st;
    void *sunctx = NULL;
    x->cv = rc_cvode_parts(self, &x->nr, &x->kidx, &x->yfull, &sunctx);
    /* the initial sensitivities: the perturbed models' initial states */
    for (int j = 0; j < x->np; j++) {
        rc_initial_state(x->mhi[j], x->ya);
        rc_initial_state(x->mlo[j], x->yb);
        double *s = x->s0 + (size_t)j * (size_t)x->ny;
        for (int k = 0; k < x->ny; k++) s[k] = (x->ya[k] - x->yb[k]) / x->dp[j];
    }
    /* CVODES's vectors, over the states CVODE carries */
    N_Vector tmpl = N_VNew_Serial(x->nr, (SUNContext)sunctx);
    if (tmpl) {
        x->yS = N_VCloneVectorArray(x->np, tmpl);
        x->abstolS = N_VCloneVectorArray(x->np, tmpl);
        N_VDestroy(tmpl);
    }
    if (!x->yS || !x->abstolS) return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    double *pbar = malloc((size_t)x->np * sizeof(double) + 1);
    if (!pbar) return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    for (int j = 0; j < x->np; j++) {
        to_reduced(x, x->s0 + (size_t)j * (size_t)x->ny, x->yS[j]);
        /* a sensitivity of the size of the state over the parameter */
        pbar[j] = x->pval ? fabs(x->pval[j]) : 0.0;
        if (!(pbar[j] > 0)) pbar[j] = 1.0;
        double *a = N_VGetArrayPointer(x->abstolS[j]);
        for (int r = 0; r < x->nr; r++) a[r] = m->atol[x->kidx[r]] / pbar[j];
    }
    copy_modes_all(x, x->d);
    int flag = CVodeSensInit(x->cv, x->np, CV_STAGGERED, cb_sens, x->yS);
    if (flag >= 0) flag = CVodeSensSVtolerances(x->cv, m->rtol, x->abstolS);
    if (flag >= 0) flag = CVodeSetSensErrCon(x->cv, x->errcon ? SUNTRUE : SUNFALSE);
    if (flag >= 0) flag = CVodeSetSensParams(x->cv, NULL, pbar, NULL);
    free(pbar);
    SCHECK(flag, "CVodeSensInit");
    x->on = 1;
    return RC_OK;
}

/* The sensitivities at t into the whole vectors s[j ny] (the constant
 * states' from s0). */
static int sens_at(sens_ctx *x, double t, double *s)
{
    for (int j = 0; j < x->np; j++) {
        const int flag = CVodeGetSensDky1(x->cv, t, 0, j, x->yS[j]);
        if (flag < 0) return flag;
        to_full(x, x->yS[j], x->s0 + (size_t)j * (size_t)x->ny, s + (size_t)j * (size_t)x->ny);
    }
    return 0;
}

static int sb_root_info(void *self, int *roots)
{
    sens_ctx *x = ctx_of(self);
    const int flag = x->ib->root_info(self, roots);
    if (flag >= 0) memcpy(x->roots, roots, (size_t)x->nroot * sizeof(int));
    return flag;
}

/* The modes and the state just before the events. */
static void sb_before_events(void *self)
{
    sens_ctx *x = ctx_of(self);
    if (x->ib->before_events) x->ib->before_events(self);
    copy_modes(x->m, x->d, x->dold);
    memcpy(x->yminus, x->yfull, (size_t)x->ny * sizeof(double));
}

/* Root function r of model mm with data dd at (t, y). */
static double root_value(sens_ctx *x, const rc_model *mm, rc_data *dd, double t, const double *y, int r)
{
    rc_assemble_roots(mm, dd, t, y, x->ga);
    return x->ga[r];
}

/* The event's state map R (rc_events_apply from the old modes, at the
 * roots found) of model mm with data dd applied to y_in, into y_out. */
static void reset_map(sens_ctx *x, const rc_model *mm, rc_data *dd, double t, const double *y_in, double *y_out)
{
    rc_event ev[RC_MAX_EV];
    int jumped = 0;
    copy_modes(x->m, x->dold, dd);
    memcpy(y_out, y_in, (size_t)x->ny * sizeof(double));
    (void)rc_events_apply(mm, dd, t, y_out, x->roots, ev, RC_MAX_EV, &jumped);
}

/* The derivative of the state map along v at ym, by central differences,
 * into out (whole vectors); v zero: 0. */
static void reset_dir(sens_ctx *x, double t, const double *ym, const double *v, double *out)
{
    const double e = dir_step(x->m, ym, v);
    if (!(e > 0)) {
        memset(out, 0, (size_t)x->ny * sizeof(double));
        return;
    }
    for (int k = 0; k < x->ny; k++) x->sv[k] = ym[k] + e * v[k];
    reset_map(x, x->m, x->dscr, t, x->sv, x->ya);
    for (int k = 0; k < x->ny; k++) x->sv[k] = ym[k] - e * v[k];
    reset_map(x, x->m, x->dscr, t, x->sv, x->yb);
    for (int k = 0; k < x->ny; k++) out[k] = (x->ya[k] - x->yb[k]) / (2.0 * e);
}

/* The jump of the sensitivities at the events of a root return at t (y:
 * the state after them): into yS, for the restart that follows. With the
 * event's state map y+ = R(y-, p) (the identity when the events only flip
 * modes):
 *     s+ = R_y s- + R_p + (R_y f- - f+) dtau/dp. */
static int sens_jump(sens_ctx *x, double t, const double *yplus)
{
    const rc_model *m = x->m;
    const int ny = x->ny;
    int r = -1, nfound = 0;
    for (int k = 0; k < x->nroot; k++)
        if (x->roots[k]) {
            if (r < 0) r = k;
            nfound++;
        }
    /* the state before the events (x->yminus holds it; a copy: the
     * scratch is reused), f-, f+, R_y f-, R_y s- */
    double *ym = malloc(5 * (size_t)ny * sizeof(double) + 1);
    double *s = malloc((size_t)x->np * (size_t)ny * sizeof(double) + 1);
    if (!ym || !s) {
        free(ym);
        free(s);
        return -1;
    }
    double *fminus = ym + ny, *fplus = ym + 2 * (size_t)ny, *rf = ym + 3 * (size_t)ny, *rs = ym + 4 * (size_t)ny;
    memcpy(ym, x->yminus, (size_t)ny * sizeof(double));
    int flag = sens_at(x, t, s);
    if (flag < 0) goto out;
    x->info.jumps++;
    if (nfound > 1) x->info.simultaneous++;
    int reset = 0;
    for (int k = 0; k < ny && !reset; k++) reset = ym[k] != yplus[k];
    x->info.resets += reset;
    /* f- (old modes, before) and f+ (new modes, after) */
    flag = rc_assemble_rhs(m, x->dold, t, ym, fminus);
    if (!flag) flag = rc_assemble_rhs(m, x->d, t, yplus, fplus);
    if (flag) goto out;
    if (reset) reset_dir(x, t, ym, fminus, rf);
    else memcpy(rf, fminus, (size_t)ny * sizeof(double));
    /* dg/dt along the flow: g_t + g_y f- */
    double gdot = 0.0;
    if (r >= 0) {
        const double et = dir_step(m, ym, fminus);
        if (et > 0) {
            for (int k = 0; k < ny; k++) {
                x->ya[k] = ym[k] + et * fminus[k];
                x->yb[k] = ym[k] - et * fminus[k];
            }
            const double g1 = root_value(x, m, x->dold, t + et, x->ya, r);
            const double g0 = root_value(x, m, x->dold, t - et, x->yb, r);
            gdot = (g1 - g0) / (2.0 * et);
        }
    }
    /* the caller's record of the event */
    rc_sens_events *ev = x->ev;
    int iev = -1;
    if (ev && r >= 0) {
        if (ev->n < ev->max) {
            iev = ev->n++;
            ev->t[iev] = t;
            const int i = r < rc_root_point_base(m) ? r / RC_ROOTS_PER_INTER : -1;
            ev->inter_id[iev] = i >= 0 ? m->inter_id[i] : 0;
            rc_event evs[RC_MAX_EV];
            int jumped = 0;
            copy_modes(m, x->dold, x->dscr);
            memcpy(x->sv, ym, (size_t)ny * sizeof(double));
            const int n = rc_events_apply(m, x->dscr, t, x->sv, x->roots, evs, RC_MAX_EV, &jumped);
            ev->kind[iev] = n > 0 ? rc_event_kind_name(evs[0].kind) : "";
            if (ev->y) memcpy(ev->y + (size_t)iev * (size_t)ny, ym, (size_t)ny * sizeof(double));
            ev->vn[iev] = 0.0;
            if (i >= 0) {
                rc_inter_report rep;
                rc_inter_report_eval_d(m, x->dold, i, t, ym, &rep);
                ev->vn[iev] = rep.vn;
            }
        } else {
            ev->more++;
        }
    }
    for (int j = 0; j < x->np; j++) {
        double *sj = s + (size_t)j * (size_t)ny;
        /* dtau/dp = -(g_y s- + g_p) / (g_t + g_y f-) */
        double dtau = 0.0;
        if (r >= 0 && gdot != 0.0 && isfinite(gdot)) {
            const double e = dir_step(m, ym, sj);
            double gys = 0.0;
            if (e > 0) {
                for (int k = 0; k < ny; k++) {
                    x->ya[k] = ym[k] + e * sj[k];
                    x->yb[k] = ym[k] - e * sj[k];
                }
                gys = (root_value(x, m, x->dold, t, x->ya, r) - root_value(x, m, x->dold, t, x->yb, r)) / (2.0 * e);
            }
            copy_modes(m, x->dold, x->dlo[j]);
            copy_modes(m, x->dold, x->dhi[j]);
            const double gp = (root_value(x, x->mhi[j], x->dhi[j], t, ym, r) -
                               root_value(x, x->mlo[j], x->dlo[j], t, ym, r)) /
                              x->dp[j];
            dtau = -(gys + gp) / gdot;
        }
        if (iev >= 0) {
            const size_t ij = (size_t)iev * (size_t)x->np + (size_t)j;
            ev->dtdp[ij] = dtau;
            /* the total derivative of the state before the event, and of
             * the interface's approach rate there: along (dtau, dy), and
             * the rate's own dependence on p */
            for (int k = 0; k < ny; k++) x->fp[k] = sj[k] + fminus[k] * dtau;
            if (ev->dydp) memcpy(ev->dydp + ij * (size_t)ny, x->fp, (size_t)ny * sizeof(double));
            ev->dvndp[ij] = 0.0;
            const int i = r < rc_root_point_base(m) ? r / RC_ROOTS_PER_INTER : -1;
            if (i >= 0) {
                rc_inter_report ra, rb;
                const double e = dir_step(m, ym, x->fp);
                double dv = 0.0;
                if (e > 0) {
                    for (int k = 0; k < ny; k++) {
                        x->ya[k] = ym[k] + e * x->fp[k];
                        x->yb[k] = ym[k] - e * x->fp[k];
                    }
                    rc_inter_report_eval_d(m, x->dold, i, t + e * dtau, x->ya, &ra);
                    rc_inter_report_eval_d(m, x->dold, i, t - e * dtau, x->yb, &rb);
                    dv = (ra.vn - rb.vn) / (2.0 * e);
                }
                copy_modes(m, x->dold, x->dlo[j]);
                copy_modes(m, x->dold, x->dhi[j]);
                rc_inter_report_eval_d(x->mhi[j], x->dhi[j], i, t, ym, &ra);
                rc_inter_report_eval_d(x->mlo[j], x->dlo[j], i, t, ym, &rb);
                ev->dvndp[ij] = dv + (ra.vn - rb.vn) / x->dp[j];
            }
        }
        if (reset) {
            /* R_y s- and R_p */
            reset_dir(x, t, ym, sj, rs);
            reset_map(x, x->mhi[j], x->dhi[j], t, ym, x->fa);
            reset_map(x, x->mlo[j], x->dlo[j], t, ym, x->fb);
            for (int k = 0; k < ny; k++) sj[k] = rs[k] + (x->fa[k] - x->fb[k]) / x->dp[j] + (rf[k] - fplus[k]) * dtau;
        } else {
            for (int k = 0; k < ny; k++) sj[k] += (rf[k] - fplus[k]) * dtau;
        }
    }
    for (int j = 0; j < x->np; j++) to_reduced(x, s + (size_t)j * (size_t)ny, x->yS[j]);
    x->pending = 1;
out:
    copy_modes_all(x, x->d);
    free(ym);
    free(s);
    return flag;
}

/* After the events: cvode.c's bookkeeping, then the jump; always a restart
 * (the sensitivities jump even where the state's rate does not). */
static int sb_after_events(void *self, double t, const double *y, int cpl_ev, int restart)
{
    sens_ctx *x = ctx_of(self);
    (void)x->ib->after_events(self, t, y, cpl_ev, restart);
    if (sens_jump(x, t, y)) x->fail = 1;
    return 1;
}

static int sb_restart(void *self, double t, int at_breakpoint)
{
    sens_ctx *x = ctx_of(self);
    /* continuous sensitivities (a breakpoint, a root left at zero): as they are */
    if (!x->pending) {
        for (int j = 0; j < x->np; j++) {
            const int f = CVodeGetSensDky1(x->cv, t, 0, j, x->yS[j]);
            if (f < 0) return f;
        }
    }
    x->pending = 0;
    copy_modes_all(x, x->d);
    int flag = x->ib->restart(self, t, at_breakpoint);
    if (flag >= 0) flag = CVodeSensReInit(x->cv, CV_STAGGERED, x->yS);
    if (flag >= 0) x->info.restarts++;
    return flag;
}

static void sb_close(void *self)
{
    sens_ctx *x = ctx_of(self);
    /* the run ended at the last output time (rc_drive's loop ends there
     * before its pause would hand it over) */
    double tn = 0.0;
    if (x->on && x->it == x->nt - 1 && CVodeGetCurrentTime(x->cv, &tn) == CV_SUCCESS &&
        fabs(tn - x->times[x->it]) <= 1e-12 * fmax(1.0, tn)) {
        const size_t ny = (size_t)x->ny, np = (size_t)x->np, it = (size_t)x->it;
        memcpy(x->yout + it * ny, x->yfull, ny * sizeof(double));
        if (sens_at(x, tn, x->sout + it * np * ny) < 0) x->fail = 1;
        x->it++;
    }
    if (x->yS) N_VDestroyVectorArray(x->yS, x->np);
    if (x->abstolS) N_VDestroyVectorArray(x->abstolS, x->np);
    x->yS = x->abstolS = NULL;
    x->ib->close(self);
    double *v[] = {x->ya, x->yb, x->fa, x->fb, x->fm, x->fp, x->sv, x->yc, x->yminus, x->s0, x->ga};
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++) free(v[k]);
    free(x->roots);
    for (int j = 0; x->dlo && j < x->np; j++) rc_data_free(x->dlo[j]);
    for (int j = 0; x->dhi && j < x->np; j++) rc_data_free(x->dhi[j]);
    free(x->dlo);
    free(x->dhi);
    rc_data_free(x->dold);
    rc_data_free(x->dscr);
}

/* Pass-through operations (the block's start is cvode.c's context). */
#define IB (ctx_of(self)->ib)
static int sb_solve(void *self, double tout, double *t, int *one_step) { return IB->solve(self, tout, t, one_step); }
static int sb_dky(void *self, double t, int k, int slot, const double **out) { return IB->dky(self, t, k, slot, out); }
static int sb_last_step(void *self, double *tn, double *hu) { return IB->last_step(self, tn, hu); }
static int sb_set_root_dirs(void *self, int *dir) { return IB->set_root_dirs(self, dir); }
static int sb_set_stop_time(void *self, double tstop) { return IB->set_stop_time(self, tstop); }
static void sb_add_stats(void *self, rc_stats *s) { IB->add_stats(self, s); }
static long sb_steps(void *self) { return IB->steps(self); }
static void sb_failure(void *self, int flag, double t, double tout, char *buf, size_t n) { IB->failure(self, flag, t, tout, buf, n); }
static const char *sb_last_msg(void *self) { return IB->last_msg(self); }
static void sb_continued(void *self) { if (IB->continued) IB->continued(self); }
static const double *sb_roots_at(void *self, double t) { return IB->roots_at ? IB->roots_at(self, t) : NULL; }

/* The outputs: the state and the sensitivities at each time asked for
 * (rc_drive's pauses). */
typedef struct sens_pause {
    rc_pause p;
    sens_ctx *x;
} sens_pause;
static int sp_reached(rc_pause *p, double t, const double *y)
{
    sens_pause *q = (sens_pause *)p;
    sens_ctx *x = q->x;
    if (x->it < x->nt && x->on) {
        const size_t ny = (size_t)x->ny, np = (size_t)x->np, it = (size_t)x->it;
        memcpy(x->yout + it * ny, y, ny * sizeof(double));
        if (sens_at(x, t, x->sout + it * np * ny) < 0) x->fail = 1;
        x->it++;
    }
    p->until = x->it < x->nt ? x->times[x->it] : INFINITY;
    return 0;
}

/* One sensitivity run, the sensitivities in the error test or not. */
static rc_status sens_attempt(const rc_model *m, int np, const rc_model *const *m_lo, const rc_model *const *m_hi,
                              const double *p, const double *dp, int nt, const double *times, double *y, double *s,
                              rc_sens_info *info, rc_sens_events *ev, rc_stats *stats, rc_error *err, int errcon)
{
    const size_t off = sens_offset();
    void *block = calloc(1, off + sizeof(sens_ctx));
    if (!block) return RC_SET(err, RC_ENOMEM, "out of memory for the sensitivities");
    sens_ctx *x = ctx_of(block);
    x->ib = rc_cvode_backend();
    x->np = np;
    x->mlo = m_lo;
    x->mhi = m_hi;
    x->dp = dp;
    x->pval = p;
    x->ev = ev;
    x->errcon = errcon;
    x->info.errcon = errcon;
    if (ev) {
        ev->n = 0;
        ev->more = 0;
    }
    x->nt = nt;
    x->times = times;
    x->yout = y;
    x->sout = s;
    rc_backend bk = *x->ib;
    bk.name = "CVODES";
    bk.open = sb_open;
    bk.start = sb_start;
    bk.solve = sb_solve;
    bk.dky = sb_dky;
    bk.last_step = sb_last_step;
    bk.root_info = sb_root_info;
    bk.set_root_dirs = sb_set_root_dirs;
    bk.set_stop_time = sb_set_stop_time;
    bk.restart = sb_restart;
    bk.add_stats = sb_add_stats;
    bk.steps = sb_steps;
    bk.failure = sb_failure;
    bk.last_msg = sb_last_msg;
    bk.before_events = sb_before_events;
    bk.after_events = sb_after_events;
    bk.continued = sb_continued;
    bk.roots_at = sb_roots_at;
    bk.close = sb_close;
    sens_pause sp = {{times[0], sp_reached}, x};
    rc_run_options opt;
    memset(&opt, 0, sizeof opt);
    opt.t_end_override = times[nt - 1];
    rc_status st = rc_drive(m, &opt, &sp.p, NULL, stats, err, &bk, block);
    if (!st && x->it < nt)
        st = RC_SET(err, RC_ESOLVER, "sensitivities: the run ended before the output time %.17g s", times[x->it]);
    if (!st && x->fail)
        st = RC_SET(err, RC_ESOLVER, "sensitivities: an evaluation of the sensitivities failed (a force not finite "
                                     "at a perturbed state or parameter)");
    if (info) *info = x->info;
    free(block);
    return st;
}

rc_status rc_sens_run(const rc_model *m, int np, const rc_model *const *m_lo, const rc_model *const *m_hi,
                      const double *p, const double *dp, int nt, const double *times, double *y, double *s, rc_sens_info *info,
                      rc_sens_events *ev, rc_stats *stats, rc_error *err)
{
    rc_error local;
    if (!err) err = &local;
    rc_error_clear(err);
    if (info) memset(info, 0, sizeof *info);
    if (stats) memset(stats, 0, sizeof *stats);
    if (ev && (ev->max < 0 || (ev->max > 0 && (!ev->t || !ev->inter_id || !ev->kind || !ev->dtdp || !ev->vn || !ev->dvndp))))
        return RC_SET(err, RC_EINPUT, "rc_sens_run: the events' arrays t, inter_id, kind, dtdp, vn and dvndp are needed "
                                      "when max > 0");
    if (!m || np < 1 || !m_lo || !m_hi || !dp || nt < 1 || !times || !y || !s)
        return RC_SET(err, RC_EINPUT, "rc_sens_run: expected a model, np >= 1 parameters with their models and "
                                      "steps, nt >= 1 times and the output arrays");
    if (m->method != RC_METHOD_CVODE)
        return RC_SET(err, RC_EINPUT, "sensitivities: only /SOLVER Method 1 (CVODE) is covered, the deck has Method %d",
                      m->method);
    if (m->preload) return RC_SET(err, RC_EINPUT, "sensitivities: a run from a preload (/SOLVER Preload 1) is not covered");
    /* an imposed translation that starts later sets its velocity at a
     * breakpoint (a jump of the state the sensitivities do not follow) */
    /* a distance or interface sensor's time on is a number of the run
     * data, set at its trigger: its dependence on the parameters is not
     * followed */
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_sens[i] >= 0) {
            const int kk = m->sens_kind[m->inter_sens[i]];
            return RC_SET(err, RC_EINPUT,
                          "sensitivities: %s is turned on by /SENSOR/%s/%d, a sensor found in the run (a distance or "
                          "interface sensor): not covered (the derivative of its trigger time is not followed in "
                          "this version)",
                          m->inter_name[i], rc_sensor_kind_name(kk), m->sens_id[m->inter_sens[i]]);
        }
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tsens[k] >= 0)
            return RC_SET(err, RC_EINPUT,
                          "sensitivities: /RBODY/%d is released by sensor %d at a time found in the run: not covered "
                          "(the derivative of its release time is not followed in this version)",
                          m->body_id[m->imp->tbody[k]], m->sens_id[m->imp->tsens[k]]);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->tson[k] >= 0)
            return RC_SET(err, RC_EINPUT,
                          "sensitivities: an /IMPVEL on /RBODY/%d started by sensor %d at a time found in the run is "
                          "not covered (the derivative of its start time is not followed in this version)",
                          m->body_id[m->imp->tbody[k]], m->sens_id[m->imp->tson[k]]);
    if (m->grav_sens >= 0)
        return RC_SET(err, RC_EINPUT,
                      "sensitivities: a /GRAV switched on by sensor %d at a time found in the run is not covered (the "
                      "derivative of its start time is not followed in this version)",
                      m->sens_id[m->grav_sens]);
    if (m->grav_tstart > 0)
        return RC_SET(err, RC_EINPUT,
                      "sensitivities: a /GRAV switched on by its sensor at %g s is not covered (the gravity jumps "
                      "there, at a time that may itself be a parameter, the sensor's Tdelay: a jump the "
                      "sensitivities do not follow in this version)",
                      m->grav_tstart);
    for (int k = 0; m->imp && k < m->imp->nt; k++)
        if (m->imp->ttstart[k] > 0)
            return RC_SET(err, RC_EINPUT,
                          "sensitivities: an /IMPVEL that starts after t = 0 (Tstart %g s on /RBODY/%d) is not covered "
                          "(its velocity jumps at Tstart, a reset the sensitivities do not follow in this version)",
                          m->imp->ttstart[k], m->body_id[m->imp->tbody[k]]);
    for (int i = 0; i < nt; i++)
        if (!(times[i] >= 0) || !isfinite(times[i]) || (i > 0 && !(times[i] > times[i - 1])) || !(times[nt - 1] > 0))
            return RC_SET(err, RC_EINPUT, "sensitivities: expected output times >= 0, finite and increasing, the last > 0, got "
                                          "%.17g at position %d", times[i], i + 1);
    for (int j = 0; j < np; j++) {
        const rc_model *a = m_lo[j], *b = m_hi[j];
        if (!a || !b || !(dp[j] != 0.0) || !isfinite(dp[j]))
            return RC_SET(err, RC_EINPUT, "sensitivities: parameter %d: expected its two models and a finite step "
                                          "dp != 0", j + 1);
        if (a->ny != m->ny || b->ny != m->ny || a->ninter != m->ninter || b->ninter != m->ninter ||
            a->npt != m->npt || b->npt != m->npt || a->nbody != m->nbody || b->nbody != m->nbody ||
            rc_root_count(a) != rc_root_count(m) || rc_root_count(b) != rc_root_count(m))
            return RC_SET(err, RC_EINPUT, "sensitivities: parameter %d changes the model's structure (its states, "
                                          "interfaces, contact points or root functions): not a continuous parameter",
                          j + 1);
    }
    /* the sensitivities in the error test first; when that run fails (its
     * steps shrink where the plain run's do not), once more without (the
     * steps then follow the state's error alone) */
    rc_status st = sens_attempt(m, np, m_lo, m_hi, p, dp, nt, times, y, s, info, ev, stats, err, 1);
    if (st == RC_ESOLVER) {
        rc_error first = *err;
        st = sens_attempt(m, np, m_lo, m_hi, p, dp, nt, times, y, s, info, ev, stats, err, 0);
        if (st == RC_ESOLVER) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%.1500s", err->msg);
            RC_SET(err, RC_ESOLVER, "%s (with the sensitivities in the error test as well: %.800s)", msg, first.msg);
        }
    }
    return st;
}
