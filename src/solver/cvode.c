/*
 * CVODE backend: BDF + Newton + KLU on the fixed sparse pattern, with
 * rootfinding for the events: the backend of /SOLVER Method 1 behind the
 * interface of solver.h (rc_solver_cvode). The only file that includes
 * SUNDIALS.
 *
 * Loop: integrate to the next output time; at a root, flip the modes
 * (events.c), write a record, and restart the integrator only when the
 * right-hand side jumps by more than the error control tolerates over the
 * current step (a contact that opens at zero force, or closes without
 * damping, is continuous: no restart). Quaternion norms are kept by CVODE's
 * projection (CVodeSetProjFn).
 */
#include <cvode/cvode.h>
#include <cvode/cvode_proj.h>
#include <float.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <klu.h>
#include <sundials/sundials_config.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <time.h>
#include <unistd.h>

#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/joint.h"
#include "base/error.h"
#include "engine/events.h"
#include "model/model.h"
#include "model/imposed.h"
#include "output/output.h"
#include "model/power.h"
#include "solver/impacts.h"
#include "solver/nvfast.h"
#include "solver/solver.h"
#include "solver/integrator.h"

/* A jump in ydot whose effect over one step, relative to the error weight,
 * exceeds this fraction triggers a restart after an event [-]. */
#define RC_REINIT_JUMP 0.1

typedef struct run_ctx {
    const rc_model *m;
    rc_data *d;
    double *jsave; /* [nnz] the Jacobian values of the last evaluation */
    int jac_patched; /* jsave's blocks of the interfaces whose modes an event
                        changed were refreshed at the event state */
    volatile sig_atomic_t *stop; /* the caller's stop flag (rc_run_options), NULL */
    char cvmsg[512]; /* CVODE's last error message, quoted in the failure message */
} run_ctx;

/* ---- CVODE callbacks ----------------------------------------------- */
/* CVODE's warnings go to stderr as CVODE prints them; its last error is
 * kept for the failure message (nothing is said of the failure that an
 * interruption provokes on purpose). */
static void cb_err(int code, const char *module, const char *function, char *msg, void *ud)
{
    run_ctx *c = ud;
    if (c && c->stop && *c->stop) return;
    if (code < 0 && c) snprintf(c->cvmsg, sizeof c->cvmsg, "%s", msg);
    else fprintf(stderr, "[%s %s]  %s\n  %s\n\n", module, code < 0 ? "ERROR" : "WARNING", function, msg);
}

static int cb_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    run_ctx *c = ud;
    /* the caller asked to stop (a signal): an unrecoverable failure ends
     * CVode at the last accepted step; no mode or state is touched */
    if (c->stop && *c->stop) return -1;
    return rc_assemble_rhs(c->m, c->d, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
}

/* The Newton matrix I - gamma J formed in place (CVodeSetLinSysFn): J is
 * evaluated into jsave only when CVODE asks for a new one (jok false), and
 * A is written in one pass over the fixed pattern, instead of CVODE's copy,
 * zero and scale-add of the whole sparse matrix at every setup. */
static int cb_linsys(realtype t, N_Vector y, N_Vector fy, SUNMatrix A, booleantype jok, booleantype *jcur,
                     realtype gamma, void *ud, N_Vector t1, N_Vector t2, N_Vector t3)
{
    run_ctx *c = ud;
    const rc_model *m = c->m;
    (void)fy;
    (void)t1;
    (void)t2;
    (void)t3;
    /* the first setup after an event that changed only interface modes
     * uses jsave with those interfaces' blocks refreshed at the event
     * (rc_jac_refresh_inter): the modes are right, the other blocks as
     * stale as CVODE's own Jacobian reuse allows. A convergence failure
     * then asks again (jok false) and gets a whole new Jacobian. */
    const int patched = c->jac_patched;
    c->jac_patched = 0;
    if (!jok && patched) {
        *jcur = SUNTRUE;
    } else if (!jok) {
        int st = rc_assemble_jac(m, c->d, t, N_VGetArrayPointer(y), c->jsave);
        if (st) return st;
        *jcur = SUNTRUE;
    } else {
        *jcur = SUNFALSE;
    }
    sunindextype *cp = SUNSparseMatrix_IndexPointers(A), *ri = SUNSparseMatrix_IndexValues(A);
    for (int k = 0; k <= m->ny; k++) cp[k] = (sunindextype)m->jac_colptr[k];
    for (int64_t k = 0; k < m->nnz; k++) ri[k] = (sunindextype)m->jac_rowind[k];
    double *a = SUNSparseMatrix_Data(A);
    for (int64_t k = 0; k < m->nnz; k++) a[k] = -gamma * c->jsave[k];
    for (int r = 0; r < m->ny; r++) a[m->jac_diag[r]] += 1.0;
    return 0;
}

static int cb_root(realtype t, N_Vector y, realtype *g, void *ud)
{
    run_ctx *c = ud;
    c->d->n_root++;
    rc_assemble_roots(c->m, c->d, t, N_VGetArrayPointer(y), g);
    return 0;
}

/* Error weights with an absolute part only where the model asks for it
 * (model.h ewt_rel): positions and rotations under derived tolerances are
 * weighed against the contact scales, not against centre coordinates; a
 * floor of 64 ulps of the value keeps a far-away coordinate testable. */
static int cb_ewt(N_Vector yv, N_Vector wv, void *ud)
{
    const rc_model *m = ((run_ctx *)ud)->m;
    const double *y = N_VGetArrayPointer(yv);
    double *w = N_VGetArrayPointer(wv);
    for (int k = 0; k < m->ny; k++) {
        const double ay = fabs(y[k]);
        double s = m->atol[k] + (m->ewt_rel[k] ? m->rtol * ay : 0.0);
        if (!m->ewt_rel[k]) s = fmax(s, 64.0 * DBL_EPSILON * ay);
        if (!(s > 0)) return -1;
        w[k] = 1.0 / s;
    }
    return 0;
}

/* Projection onto unit quaternions; the error estimate loses its radial part. */
static int cb_proj(realtype t, N_Vector ycur, N_Vector corr, realtype eps, N_Vector err, void *ud)
{
    run_ctx *c = ud;
    const rc_model *m = c->m;
    double *y = N_VGetArrayPointer(ycur), *cr = N_VGetArrayPointer(corr);
    double *e = err ? N_VGetArrayPointer(err) : NULL;
    N_VConst(0.0, corr);
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double *q = y + m->body_yadr[b] + 3;
        double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int k = 0; k < 4; k++) cr[m->body_yadr[b] + 3 + k] = q[k] / nq - q[k];
        if (e) {
            double *eq = e + m->body_yadr[b] + 3, dot = 0;
            for (int k = 0; k < 4; k++) dot += eq[k] * q[k] / nq;
            for (int k = 0; k < 4; k++) eq[k] -= dot * q[k] / nq;
        }
    }
    return 0;
}

/* ---- helpers ----------------------------------------------------------- */
static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Time breakpoints: instants where the right-hand side jumps by time alone
 * (the end of an imposed velocity, /IMPVEL Tstop), inside (0, tend), sorted,
 * distinct. CVODE is stopped exactly there (CVodeSetStopTime) and restarted.
 * Returns the count; *bp is allocated (free it). */
int time_breakpoints(const rc_model *m, double tend, double **bp)
{
    const rc_imposed *p = m->imp;
    int n = 0, cap = p ? p->nt + p->nr : 0;
    *bp = malloc(((size_t)cap + 1) * sizeof(double));
    if (!*bp) return -1;
    for (int k = 0; p && k < p->nt + p->nr; k++) {
        double ts = k < p->nt ? p->ttstop[k] : p->rtstop[k - p->nt];
        if (ts > 0 && ts < tend) (*bp)[n++] = ts;
    }
    qsort(*bp, (size_t)n, sizeof(double), cmp_double);
    int u = 0;
    for (int k = 0; k < n; k++)
        if (u == 0 || (*bp)[k] > (*bp)[u - 1]) (*bp)[u++] = (*bp)[k];
    return u;
}

/* Only the crossing that changes a mode is a root (docs/theory.md 5). */
void root_directions(const rc_model *m, const rc_data *d, int *dir)
{
    for (int i = 0; i < m->ninter; i++) {
        int *r = dir + RC_ROOTS_PER_INTER * i;
        const int mode = d->inter_mode[i], br = d->inter_branch[i];
        r[RC_ROOT_TSTART] = 1;
        r[RC_ROOT_TSTOP] = 1;
        r[RC_ROOT_ZONE] = mode == RC_MODE_OPEN ? 1 : -1;         /* enter / leave */
        r[RC_ROOT_FORCE] = mode == RC_MODE_RELEASED ? 1 : -1;    /* re-close / release */
        r[RC_ROOT_HYST_A] = br == RC_BR_UNLOAD ? 1 : -1;          /* reversal, or F_h meets F_L */
        r[RC_ROOT_HYST_B] = -1;                                   /* F_h meets F_U */
        r[RC_ROOT_TRK_A] = 1;                                     /* bodies approach again */
        r[RC_ROOT_TRK_B] = -1;                                    /* offset used up */
        r[RC_ROOT_SLIP] = 1;                                      /* limit reached / sliding stops */
        r[RC_ROOT_REV] = -1;                                      /* saturated sliding reverses */
    }
    for (int j = 0; j < m->npt; j++) dir[rc_root_point_base(m) + j] = 1; /* points: as RC_ROOT_SLIP */
    if (rc_cpl_nroots(m) > 0) rc_cpl_root_dirs(m, d, dir + rc_root_cpl_base(m));
}

static int set_root_directions(const rc_model *m, const rc_data *d, void *cv, int *dir)
{
    if (rc_root_count(m) == 0) return CV_SUCCESS;
    root_directions(m, d, dir);
    return CVodeSetRootDirection(cv, dir);
}

/* One event to the sink; RC_OK or the output's error. */
rc_status sink_event(ev_sink *k, double t, const char *kind, const char *element, const double v[3],
                            rc_error *err)
{
    rc_status st = RC_OK;
    if (k->out) st = v ? rc_output_event_values(k->out, t, kind, element, v, err) : rc_output_event(k->out, t, kind, element, err);
    if (!st && k->fn && !k->stop) {
        const double none[3] = {NAN, NAN, NAN}; /* not an interface, as in the file */
        if (k->fn(k->user, t, kind, element, v ? v : none)) {
            k->stop = 1;
            snprintf(k->why, sizeof k->why, "stopped by the event callback at t = %.9g s (%s %s)", t, kind, element);
        }
    }
    return st;
}

/* Append event `ev` at (t, y) to the events table with its interface's
 * penetration P [m], approach speed dP/dt [m/s] and normal force [N], in the
 * mode after the event. */
rc_status write_event(const rc_model *m, const rc_data *d, ev_sink *o, double t, const double *y,
                             const rc_event *ev, rc_error *err)
{
    const int i = ev->inter;
    if (i < 0) return sink_event(o, t, ev->kind, m->cpl->name[-1 - i], NULL, err); /* a coupling */
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    const double v[3] = {r.p, r.vn, d->inter_mode[i] == RC_MODE_CLOSED && r.fn > 0 ? r.fn : 0.0};
    return sink_event(o, t, ev->kind, m->inter_name[i], v, err);
}

/* Contacts at zero penetration or zero force, decided by the state after
 * the start and after every event (events.c, rc_modes_touch): the rate of
 * the state in the current modes is computed first, for the force rates.
 * Writes the events; returns their number (*jumped is set when history
 * states were reset). */
int resolve_touching(const rc_model *m, rc_data *d, double t, double *y, double *f, ev_sink *out,
                            rc_impacts *im, long *nevents, int *jumped, rc_status *st, rc_error *err)
{
    int total = 0;
    *st = RC_OK;
    if (m->ninter == 0) return 0;
    /* a touching contact closed at zero force changes no rate, so one more
     * round settles what the first one enabled */
    for (int round = 0; round < 2; round++) {
        if (rc_assemble_rhs(m, d, t, y, f)) break;
        rc_event ev[RC_MAX_EV];
        int jmp = 0, nev = rc_modes_touch(m, d, t, y, f, ev, RC_MAX_EV, &jmp);
        *jumped |= jmp;
        total += nev;
        *nevents += nev;
        for (int k = 0; k < nev && k < RC_MAX_EV; k++) rc_impacts_event(im, m, d, ev[k].inter, ev[k].kind, t, y);
        for (int k = 0; k < nev && k < RC_MAX_EV; k++)
            if ((*st = write_event(m, d, out, t, y, &ev[k], err))) return total;
        if (nev == 0) break;
    }
    return total;
}

/* The roots reported at t are all exactly zero there and were positive (or
 * negative) at the start of the step: a function that reached zero and stayed
 * flat (CVODE reports such a root at the step's end, not where it got there).
 * Bisect on CVODE's interpolant over [t_n - h_u, t] for the first time all of
 * them are zero; on success the state there is in yref, the time in
 * *refined_time, and the number of bisections is returned (0: nothing to do). */
static int refine_flat_roots(const rc_model *m, rc_data *d, void *cv, double t, const int *roots, double *g,
                             N_Vector yref, double *refined_time)
{
    const int nr = rc_root_count(m);
    double tn, hu;
    if (nr == 0 || CVodeGetCurrentTime(cv, &tn) != CV_SUCCESS || CVodeGetLastStep(cv, &hu) != CV_SUCCESS) return 0;
    double *y = N_VGetArrayPointer(yref);
    if (CVodeGetDky(cv, t, 0, yref) != CV_SUCCESS) return 0;
    rc_assemble_roots(m, d, t, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] != 0.0) return 0; /* a true crossing: located by CVODE */
    double lo = fmax(tn - hu, 0.0), hi = t;
    if (CVodeGetDky(cv, lo, 0, yref) != CV_SUCCESS) return 0;
    rc_assemble_roots(m, d, lo, y, g);
    for (int k = 0; k < nr; k++)
        if (roots[k] != 0 && g[k] == 0.0) return 0; /* already zero at the start */
    int it = 0;
    for (; it < 200 && hi - lo > 4.0 * DBL_EPSILON * fmax(fabs(hi), 1.0); it++) {
        const double mid = 0.5 * (lo + hi);
        if (CVodeGetDky(cv, mid, 0, yref) != CV_SUCCESS) return 0;
        rc_assemble_roots(m, d, mid, y, g);
        int all = 1;
        for (int k = 0; k < nr; k++)
            if (roots[k] != 0 && g[k] != 0.0) all = 0;
        if (all) hi = mid;
        else lo = mid;
    }
    if (hi >= t || CVodeGetDky(cv, hi, 0, yref) != CV_SUCCESS) return 0;
    *refined_time = hi;
    return it > 0 ? it : 1;
}

/* A root function exactly zero at the event state (flat to rounding, e.g. a
 * penetration of two slowly separating bodies) makes CVODE stop with "close
 * roots" on the next call; after a restart CVODE instead deactivates it until
 * it moves away from zero. */
int root_on_zero(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    rc_assemble_roots(m, d, t, y, g);
    for (int k = 0; k < rc_root_count(m); k++)
        if (g[k] == 0.0) return 1;
    return 0;
}

double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Add CVODE's counters to the totals (they restart at every ReInit). */
static void add_stats(void *cv, rc_stats *s)
{
    long v;
    if (CVodeGetNumSteps(cv, &v) == CV_SUCCESS) s->steps += v;
    if (CVodeGetNumRhsEvals(cv, &v) == CV_SUCCESS) s->rhs_evals += v;
    if (CVodeGetNumLinSolvSetups(cv, &v) == CV_SUCCESS) s->lin_setups += v;
    if (CVodeGetNumNonlinSolvIters(cv, &v) == CV_SUCCESS) s->nonlin_iters += v;
    if (CVodeGetNumNonlinSolvConvFails(cv, &v) == CV_SUCCESS) s->nonlin_fails += v;
    if (CVodeGetNumErrTestFails(cv, &v) == CV_SUCCESS) s->err_test_fails += v;
    if (CVodeGetNumGEvals(cv, &v) == CV_SUCCESS) s->root_evals += v;
}

void frame_free(frame_buf *f)
{
    void *p[] = {f->pos, f->quat, f->vel, f->omega, f->pen, f->fload, f->fdamp, f->fn, f->point, f->normal, f->mode,
                 f->cpl, f->ffric, f->vslip, f->slip, f->jnt};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
}

int frame_alloc(const rc_model *m, frame_buf *f)
{
    memset(f, 0, sizeof *f);
    size_t nb = (size_t)m->nbody + 1, ni = (size_t)m->ninter + 1;
    f->pos = malloc(3 * nb * sizeof(double));
    f->quat = malloc(4 * nb * sizeof(double));
    f->vel = malloc(3 * nb * sizeof(double));
    f->omega = malloc(3 * nb * sizeof(double));
    f->pen = malloc(ni * sizeof(double));
    f->fload = malloc(ni * sizeof(double));
    f->fdamp = malloc(ni * sizeof(double));
    f->fn = malloc(ni * sizeof(double));
    f->point = malloc(3 * ni * sizeof(double));
    f->normal = malloc(3 * ni * sizeof(double));
    f->mode = malloc(ni * sizeof(int));
    f->ffric = malloc(3 * ni * sizeof(double));
    f->vslip = malloc(ni * sizeof(double));
    f->slip = malloc(ni * sizeof(int));
    f->cpl = malloc((9 * (size_t)m->cpl->n + 1) * sizeof(double));
    f->jnt = malloc((8 * (size_t)(m->jnt ? m->jnt->n : 0) + 1) * sizeof(double));
    return f->jnt && f->pos && f->quat && f->vel && f->omega && f->pen && f->fload && f->fdamp && f->fn && f->point &&
           f->normal && f->mode && f->cpl && f->ffric && f->vslip && f->slip;
}

/* Fill and write one record at (t, y). */
rc_status write_frame(const rc_model *m, const rc_data *d, rc_output *o, frame_buf *f, double t,
                             const double *y, int at_event, rc_error *err)
{
    for (int b = 0; b < m->nbody; b++) {
        const double *s = rc_body_state(m, b, y);
        memcpy(f->pos + 3 * b, s, 3 * sizeof(double));
        memcpy(f->quat + 4 * b, s + 3, 4 * sizeof(double));
        memcpy(f->vel + 3 * b, s + 7, 3 * sizeof(double));
        memcpy(f->omega + 3 * b, s + 10, 3 * sizeof(double));
    }
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report r;
        int mode = d->inter_mode[i];
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        const int acts = mode == RC_MODE_CLOSED;
        f->pen[i] = r.p;
        f->fload[i] = acts ? r.fload : 0.0;
        f->fdamp[i] = acts ? r.fdamp : 0.0;
        f->fn[i] = acts && r.fn > 0 ? r.fn : 0.0;
        memcpy(f->point + 3 * i, r.point, 3 * sizeof(double));
        memcpy(f->normal + 3 * i, r.normal, 3 * sizeof(double));
        for (int k = 0; k < 3; k++) f->ffric[3 * i + k] = acts ? r.ft[k] : 0.0;
        f->vslip[i] = acts ? r.vslip : 0.0;
        int sl = d->inter_slip[i]; /* friction per point: any point slipping */
        for (int j = 0; j < m->inter_npt[i]; j++) sl |= d->pt_slip[m->inter_pbase[i] + j];
        f->slip[i] = acts && sl;
        f->mode[i] = mode == RC_MODE_CLOSED     ? RC_OUT_MODE_CLOSED
                     : mode == RC_MODE_OPEN     ? RC_OUT_MODE_OPEN
                     : mode == RC_MODE_RELEASED ? RC_OUT_MODE_RELEASED
                                                : RC_OUT_MODE_INACTIVE;
    }
    rc_energy(m, d, t, y, f->energy);
    if (!o) return RC_OK;
    const int nc = m->cpl->n;
    rc_cpl_frame(m, d, t, y, f->cpl);
    rc_frame fr = {.t = t, .at_event = at_event, .body_pos = f->pos, .body_quat = f->quat, .body_vel = f->vel,
                   .body_omega = f->omega, .inter_pen = f->pen, .inter_fload = f->fload, .inter_fdamp = f->fdamp,
                   .inter_fnormal = f->fn, .inter_point = f->point, .inter_normal = f->normal,
                   .inter_mode = f->mode, .inter_ffric = f->ffric, .inter_vslip = f->vslip, .inter_slip = f->slip,
                   .energy = f->energy, .cpl_force = f->cpl, .cpl_length = f->cpl + nc, .cpl_f1 = f->cpl + 2 * nc,
                   .cpl_f2 = f->cpl + 5 * nc, .cpl_lowest = f->cpl + 8 * nc};
    if (m->jnt) { /* joints: y is the IDA backend's whole vector (model/joint.h) */
        const int nj = m->jnt->n;
        rc_jnt_frame(m, y, f->jnt, f->jnt + 3 * nj, f->jnt + 6 * nj, f->jnt + 7 * nj, f->jnt + 8 * nj);
        fr.joint_force = f->jnt;
        fr.joint_moment = f->jnt + 3 * nj;
        fr.joint_drift_pos = f->jnt + 6 * nj;
        fr.joint_drift_ang = f->jnt + 7 * nj;
        fr.joint_work = f->jnt + 8 * nj;
    }
    return rc_output_frame(o, &fr, err);
}

static const char *const energy_name[RC_NENERGY] = {
    "energy_kinetic",        "energy_potential",  "energy_contact_work", "energy_damping", "energy_friction_work",
    "energy_contact_stored", "energy_hysteresis", "energy_friction",     "energy_coupling_elastic",
    "energy_coupling_damping", "energy_catenary", "energy_imposed", "energy_total"};
static const char *const energy_long[RC_NENERGY] = {
    "kinetic energy of the free bodies",
    "gravitational potential energy",
    "work done on the contacts by the elastic(-plastic) normal forces",
    "energy dissipated by the contact damping",
    "work done on the contacts by the friction forces",
    "elastic energy stored in the contacts, normal and tangential (recoverable by unloading)",
    "energy dissipated by contact hysteresis (normal work - normal stored)",
    "energy dissipated by friction (friction work - tangential stored)",
    "elastic energy stored in the spring-damper couplings",
    "energy dissipated by the coupling dampers",
    "elastic and gravitational energy of the catenary lines (work done by their ends)",
    "minus the work done on the bodies by the imposed velocities (/IMPVEL reactions)",
    ("kinetic + potential + contact work + damping + friction work + couplings + imposed (constant in exact "
     "arithmetic)")};

/* The interpolant of CVODE's last step for the impact table (rc_interp_fn). */
typedef struct interp_ctx {
    void *cv;
    N_Vector ys;
} interp_ctx;

static int interp_last_step(void *ctx, double t, const double **y)
{
    interp_ctx *c = ctx;
    if (CVodeGetDky(c->cv, t, 0, c->ys) != CV_SUCCESS) return -1;
    *y = N_VGetArrayPointer(c->ys);
    return 0;
}

/* The impacts in progress at the end of a step over (t_prev, t] with the
 * state y (rc_impacts_step); the part of the interval before the last step
 * (right after a root return) is not covered by the interpolant. */
static void sample_step(void *cv, rc_impacts *im, const rc_model *m, const rc_data *d, double t_prev, double t,
                        N_Vector y, N_Vector ys)
{
    double tn = t, hu = 0.0;
    if (!rc_impacts_active(im) || CVodeGetCurrentTime(cv, &tn) != CV_SUCCESS ||
        CVodeGetLastStep(cv, &hu) != CV_SUCCESS)
        return;
    const double lo = fmax(t_prev, tn - hu);
    if (!(t > lo)) return;
    interp_ctx c = {cv, ys};
    rc_impacts_step(im, m, d, lo, t, N_VGetArrayPointer(y), interp_last_step, &c);
}

/* Output times strictly before t (not within rounding of it) that a single
 * step passed before stopping at an event or a breakpoint at t: their
 * records, from the interpolant of that step, in the modes before the
 * event. Advances *tout and *nout. */
static rc_status outputs_before(void *cv, const rc_model *m, const rc_data *d, rc_output *o, frame_buf *fb, double t,
                                double tend, double *tout, long *nout, N_Vector ytmp, rc_error *err)
{
    while (*tout < t && t - *tout > 1e-12 * fmax(fabs(t), m->dtout)) {
        if (CVodeGetDky(cv, *tout, 0, ytmp) != CV_SUCCESS)
            RC_RAISE(err, RC_ESOLVER, "CVODE interpolation at the output time %.9g s failed", *tout);
        rc_status st = write_frame(m, d, o, fb, *tout, N_VGetArrayPointer(ytmp), 0, err);
        if (st) return st;
        (*nout)++;
        const double next = fmin(*nout * m->dtout, tend);
        if (next <= *tout) break;
        *tout = next;
        if (tend - *tout < 1e-12 * tend) *tout = tend;
    }
    return RC_OK;
}

_Static_assert(RC_SURF_NEXT == RC_OUT_SURF_NPARAM, "surface parameters: model and file disagree");
static const char *const surf_kind_name[] = {"", "PLANE", "SPHERE", "CYLINDER", "BOX", "SEGMENTS"};

rc_status open_output(const rc_model *m, const char *path, const char *note, rc_output **o, rc_error *err,
                      const char *integrator)
{
    *o = NULL;
    if (!path) return RC_OK;
    const char **types = malloc(((size_t)m->ninter + 1) * sizeof(char *));
    if (!types) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int i = 0; i < m->ninter; i++) types[i] = m->inter_law[i] == RC_LAW_POWER ? "POWER" : "TYPE6";
    rc_output_meta meta = {m->title, m->case_path, m->checksum, m->unit_mass, m->unit_length, m->unit_time,
                           integrator, m->rtol, m->atol_pos,
                           m->atol_quat, m->atol_vel, m->atol_omega, m->atol_energy, m->nbody, m->body_id,
                           m->body_fixed, m->ninter, m->inter_id, types, RC_NENERGY, energy_name, energy_long,
                           m->cpl->n, m->cpl->id, m->cpl->type, NULL, .nfile = 0};
    /* provenance, every solver setting, the surfaces */
    meta.nfile = m->nfile;
    meta.file = (const char *const *)m->file;
    meta.max_order = m->max_order;
    meta.max_steps = m->max_steps;
    meta.hmax = m->hmax;
    meta.h0 = m->h0;
    meta.t_end = m->tend;
    meta.dt_out = m->dtout;
    char derived[128] = "";
    static const char *const tol_name[5] = {"atol_position", "atol_quaternion", "atol_velocity",
                                            "atol_angular_velocity", "atol_energy"};
    for (int k = 0; k < 5; k++)
        if (m->tol_auto & (1 << k))
            snprintf(derived + strlen(derived), sizeof derived - strlen(derived), "%s%s", derived[0] ? " " : "",
                     tol_name[k]);
    meta.tol_derived = derived[0] ? derived : "none (all given in /SOLVER)";
    meta.sampling_note = note;
    const char **kinds = malloc(((size_t)m->nsurf + 1) * sizeof *kinds);
    int *isurf = malloc((2 * (size_t)m->ninter + 1) * sizeof *isurf);
    if (!kinds || !isurf) {
        free(kinds);
        free(isurf);
        free(types);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int k = 0; k < m->nsurf; k++)
        kinds[k] = m->surf_kind[k] >= RC_SURF_PLANE && m->surf_kind[k] <= RC_SURF_SEG ? surf_kind_name[m->surf_kind[k]]
                                                                                    : "UNKNOWN";
    for (int i = 0; i < m->ninter; i++) {
        isurf[2 * i] = m->inter_sa[i];
        isurf[2 * i + 1] = m->inter_sb[i];
    }
    meta.nsurf = m->nsurf;
    meta.surf_id = m->surf_id;
    meta.surf_kind = kinds;
    meta.surf_body = m->surf_body;
    meta.surf_point = m->surf_p;
    meta.surf_normal = m->surf_n;
    meta.surf_radius = m->surf_r;
    meta.surf_param = m->surf_ext;
    meta.inter_surf = isurf;
    /* segment surfaces: their nodes and segments */
    if (m->surf_nadr && m->surf_sadr && m->surf_sadr[m->nsurf] > 0) {
        meta.nseg_node = m->surf_nadr[m->nsurf];
        meta.nseg = m->surf_sadr[m->nsurf];
        meta.surf_first_node = m->surf_nadr;
        meta.surf_first_seg = m->surf_sadr;
        meta.seg_node = m->surf_node;
        meta.seg_corner = m->surf_seg;
    }
    const int njt = m->jnt ? m->jnt->n : 0;
    const char **jtype = malloc(((size_t)njt + 1) * sizeof *jtype);
    if (!jtype) {
        free(types);
        free(kinds);
        free(isurf);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int j = 0; j < njt; j++) jtype[j] = rc_jnt_type_name(m, j);
    meta.njoint = njt;
    meta.joint_id = m->jnt ? m->jnt->id : NULL;
    meta.joint_type = jtype;
    char evrec[160];
    const int full = rc_event_records(m);
    if (m->ev_state == 0)
        snprintf(evrec, sizeof evrec, "%s (/RUN Ev_state 0: %d bodies, %s %d)",
                 full ? "full-state record at every event" : "events table only", m->nbody,
                 full ? "at most" : "more than", RC_EVREC_MAX_BODIES);
    else
        snprintf(evrec, sizeof evrec, "%s (/RUN Ev_state %d)",
                 full ? "full-state record at every event" : "events table only", m->ev_state);
    meta.event_records = evrec;
    rc_status st = rc_output_open(o, path, &meta, err);
    free(jtype);
    free(types);
    free(kinds);
    free(isurf);
    return st;
}

/* Must the integrator restart after a mode change at troot? CVODE has
 * already stepped to tn >= troot with the old modes; continuing is right only
 * if the old and new right-hand sides agree, within the error weights, over
 * [troot, tn] and over the next step h: compare them at troot and at tn.
 * old_mode is the mode array before the flip; d->inter_mode after it. */
static int needs_restart(const rc_model *m, rc_data *d, void *cv, int *old_mode, int *old_branch,
                         int *old_track, int *old_slip, double troot, const double *yroot, N_Vector ytn, N_Vector f0,
                         N_Vector f1)
{
    double h = 0, tn = troot;
    CVodeGetCurrentStep(cv, &h);
    CVodeGetCurrentTime(cv, &tn);
    if (CVodeGetDky(cv, tn, 0, ytn) != CV_SUCCESS) return 1;
    const double *y_at[2] = {yroot, N_VGetArrayPointer(ytn)};
    const double t_at[2] = {troot, tn}, span[2] = {h, (tn - troot) + h};
    double *a = N_VGetArrayPointer(f0), *b = N_VGetArrayPointer(f1);
    for (int s = 0; s < 2; s++) {
        /* old modes, then new modes, at the same state */
        int *new_mode = d->inter_mode, *new_branch = d->inter_branch, *new_track = d->inter_track;
        int *new_slip = d->inter_slip;
        d->inter_mode = old_mode;
        d->inter_branch = old_branch;
        d->inter_track = old_track;
        d->inter_slip = old_slip;
        int bad = rc_assemble_rhs(m, d, t_at[s], y_at[s], a);
        d->inter_mode = new_mode;
        d->inter_branch = new_branch;
        d->inter_track = new_track;
        d->inter_slip = new_slip;
        bad |= rc_assemble_rhs(m, d, t_at[s], y_at[s], b);
        if (bad) return 1;
        for (int k = 0; k < m->ny; k++) {
            double w = m->rtol * fabs(y_at[s][k]) + m->atol[k];
            if (fabs(b[k] - a[k]) * span[s] > RC_REINIT_JUMP * w) return 1;
        }
    }
    return 0;
}

/* Progress of the integration on stderr: one line rewritten on a terminal,
 * whole lines in a log. The time remaining is estimated from the rate of
 * simulated time over the wall time so far. */
void progress_line(double tend, const rc_stats *s, double t, long steps, double t0, int tty)
{
    const double wall = wall_now() - t0;
    char left[64] = "";
    if (t > 0 && t < tend) {
        const double rem = (tend - t) * wall / t;
        if (rem < 10) snprintf(left, sizeof left, ", about %.1f s left", rem);
        else if (rem < 120) snprintf(left, sizeof left, ", about %.0f s left", rem);
        else if (rem < 7200) snprintf(left, sizeof left, ", about %.0f min left", rem / 60);
        else snprintf(left, sizeof left, ", about %.1f h left", rem / 3600);
    }
    fprintf(stderr, "%sricochet: t = %.6g of %.6g s (%.1f%%), steps %ld, events %ld, wall %.1f s%s%s", tty ? "\r" : "",
            t, tend, 100.0 * t / tend, steps, s->events, wall, left, tty ? "   " : "\n");
    fflush(stderr);
}

#define CVCHECK(call, what)                                                            \
    do {                                                                               \
        int flag_ = (call);                                                            \
        if (flag_ < 0) {                                                               \
            char *name_ = CVodeGetReturnFlagName(flag_); /* malloc'ed by CVODE */      \
            st = RC_SET(err, RC_ESOLVER, "CVODE call %s failed at t = %.9g s: %s (%s)", \
                        what, t, name_ ? name_ : "?", rc.cvmsg);                       \
            free(name_);                                                               \
            goto done;                                                                 \
        }                                                                              \
    } while (0)

/* The message of a failed CVode call: where (t, the step, the element whose
 * state carries the largest weighted local error) and, by the kind of
 * failure, the likely cause and what to change in the case. */
static void failure_advice(const rc_model *m, const rc_data *d, void *cv, int flag, double t, double tout,
                           const char *cvmsg, N_Vector tmp1, N_Vector tmp2, char *buf, size_t n)
{
    double h = 0.0;
    CVodeGetCurrentStep(cv, &h);
    /* the element: largest |local error| x weight (the error test's measure) */
    char elem[200] = "";
    if (CVodeGetEstLocalErrors(cv, tmp1) == CV_SUCCESS && CVodeGetErrWeights(cv, tmp2) == CV_SUCCESS) {
        const double *e = N_VGetArrayPointer(tmp1), *w = N_VGetArrayPointer(tmp2);
        int imax = -1;
        double vmax = 0.0;
        for (int i = 0; i < m->ny; i++) {
            const double v = fabs(e[i] * w[i]);
            if (v > vmax || (isnan(v) && imax < 0)) {
                vmax = v;
                imax = i;
            }
        }
        if (imax >= 0) rc_state_name(m, imax, elem, sizeof elem);
    }
    const char *cf = rc_cpl_failed(m, d);
    char where[512];
    if (d->fail_inter >= 0)
        snprintf(where, sizeof where, "non-finite force in %s", m->inter_name[d->fail_inter]);
    else if (cf)
        snprintf(where, sizeof where, "no force from %s", cf);
    else if (elem[0])
        snprintf(where, sizeof where, "largest local error in %s", elem);
    else
        snprintf(where, sizeof where, "element not identified");
    char *fname = CVodeGetReturnFlagName(flag); /* malloc'ed by CVODE */
    const char *advice;
    switch (flag) {
    case CV_TOO_MUCH_WORK:
        advice = "the run took /SOLVER Max_steps steps without reaching the next output time: raise Max_steps, "
                 "or, when the steps are tiny, look at the element named (a very stiff, lightly damped law, or "
                 "events in quick succession) and loosen Rtol/Atol";
        break;
    case CV_TOO_MUCH_ACC:
        advice = "the tolerances ask for more than double precision gives here: raise /SOLVER Rtol (at least "
                 "1e-13) or the absolute tolerance of the quantity named";
        break;
    case CV_ERR_FAILURE:
        advice = "the error test kept failing as the step shrank: the quantity named changes faster than any "
                 "step can follow (a jump in a /FUNCT curve, a law with a kink, or a stiffness too high for its "
                 "absolute tolerance): smooth the curve, check Stiff and the scale factors of that element, or "
                 "loosen its absolute tolerance in /SOLVER";
        break;
    case CV_CONV_FAILURE:
    case CV_LSETUP_FAIL:
    case CV_LSOLVE_FAIL:
        advice = "Newton's iteration did not converge even at small steps: the force of the element named "
                 "varies faster than its Jacobian says (a kink or jump in a /FUNCT curve), or a body has "
                 "almost no mass or inertia for the forces on it: check that element's law and the masses, "
                 "or bound the step with /SOLVER Hmax";
        break;
    case CV_RHSFUNC_FAIL:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR:
    case CV_FIRST_RHSFUNC_ERR:
        advice = "the forces could not be evaluated (a penetration or speed outside the range where the law "
                 "is finite): extend the /FUNCT curves of that element, lower its scale factors, or bound the "
                 "step with /SOLVER Hmax";
        break;
    case CV_RTFUNC_FAIL:
        advice = "the event functions could not be evaluated: an internal error, please report the case";
        break;
    default:
        advice = "see the SUNDIALS CVODE documentation of this flag";
        break;
    }
    snprintf(buf, n, "CVODE failed at t = %.9g s (step h = %.3g s, next output at %.9g s): %s%s%s%s; %s. Likely "
             "cause: %s",
             t, h, tout, fname ? fname : "?", cvmsg[0] ? " (\"" : "", cvmsg, cvmsg[0] ? "\")" : "", where, advice);
    free(fname);
}

static rc_status cvode_run(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                           rc_error *err)
{
    rc_status st = RC_OK;
    double t = 0.0; /* time reached [s] */
    rc_error local_err;
    if (!err) err = &local_err;
    rc_error_clear(err);
    rc_stats s;
    memset(&s, 0, sizeof s);
    SUNContext ctx = NULL;
    N_Vector y = NULL, av = NULL, f0 = NULL, f1 = NULL, ytn = NULL, ysamp = NULL;
    rc_impacts im;
    memset(&im, 0, sizeof im);
    char note[sizeof s.sampling_note];
    rc_impacts_sampling_note(m, note, sizeof note);
    int *old_mode = NULL, *old_branch = NULL, *old_track = NULL, *old_slip = NULL, *rootdir = NULL;
    double *gbuf = NULL, *g2buf = NULL, *ylook = NULL, *flook = NULL, *bp = NULL, *zeno_t = NULL;
    int *zeno_n = NULL;
    double *jsave = NULL; /* Jacobian values (run_ctx.jsave) */
    int nbp = 0, ibp = 0;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    void *cv = NULL;
    rc_output *out = NULL;
    frame_buf fb;
    memset(&fb, 0, sizeof fb);
    int *roots = NULL;
    const char *fail_reason = NULL;
    char reason[2048] = "";
    rc_data *d = rc_data_new(m);
    const double tend = opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    const double dtout = opt && opt->dt_out_override > 0 ? opt->dt_out_override : m->dtout;
    const int show = opt && opt->progress, tty = show && isatty(2);
    ev_sink sink = {NULL, opt ? opt->on_event : NULL, opt ? opt->user : NULL, 0, ""};
    const int evrec = rc_event_records(m); /* full-state records at events */
    double wall0 = wall_now(), last_progress = wall0;

    if (!d || !frame_alloc(m, &fb)) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    run_ctx rc = {.m = m, .d = d, .jsave = NULL, .jac_patched = 0, .stop = opt ? opt->stop : NULL, .cvmsg = ""};
    if (SUNContext_Create(NULL, &ctx)) {
        st = RC_SET(err, RC_ESOLVER, "SUNContext_Create failed");
        goto done;
    }
    y = N_VNew_Serial(m->ny, ctx);
    av = N_VNew_Serial(m->ny, ctx);
    f0 = N_VNew_Serial(m->ny, ctx);
    f1 = N_VNew_Serial(m->ny, ctx);
    ytn = N_VNew_Serial(m->ny, ctx);
    ysamp = N_VNew_Serial(m->ny, ctx);
    /* optimised vector operations, inherited by CVODE's clones of y (nvfast.h) */
    N_Vector vecs[] = {y, av, f0, f1, ytn, ysamp};
    for (size_t k = 0; k < sizeof vecs / sizeof vecs[0]; k++) rc_nvector_fast(vecs[k]);
    old_mode = calloc((size_t)m->ninter + 1, sizeof(int));
    old_branch = calloc((size_t)m->ninter + 1, sizeof(int));
    old_track = calloc((size_t)m->ninter + 1, sizeof(int));
    old_slip = calloc((size_t)m->ninter + 1, sizeof(int));
    rootdir = calloc((size_t)rc_root_count(m) + 1, sizeof(int));
    gbuf = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    zeno_t = calloc((size_t)m->ninter + 1, sizeof(double));
    zeno_n = calloc((size_t)m->ninter + 1, sizeof(int));
    g2buf = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    ylook = calloc((size_t)m->ny, sizeof(double));
    flook = calloc((size_t)m->ny, sizeof(double));
    A = SUNSparseMatrix(m->ny, m->ny, m->nnz, CSC_MAT, ctx);
    roots = calloc((size_t)rc_root_count(m) + 1, sizeof(int));
    if (rc_impacts_init(&im, m) || !ysamp || !y || !av || !f0 || !f1 || !ytn || !old_mode || !old_branch || !old_track || !old_slip || !rootdir || !gbuf || !A ||
        !roots || !g2buf || !ylook || !flook || !zeno_t || !zeno_n) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the solver");
        goto done;
    }
    LS = SUNLinSol_KLU(y, A, ctx);
    if (!LS) {
        st = RC_SET(err, RC_ESOLVER, "SUNLinSol_KLU failed");
        goto done;
    }
    /* initial state and modes */
    double *yd = N_VGetArrayPointer(y);
    rc_initial_state(m, yd);
    memcpy(N_VGetArrayPointer(av), m->atol, (size_t)m->ny * sizeof(double));
    rc_modes_init(m, d, t, yd);
    if ((st = open_output(m, opt ? opt->output_path : NULL, note, &out, err,
                          "CVODE BDF, Newton, KLU sparse direct, rootfinding"))) goto done;
    sink.out = out;
    {
        int jmp = 0;
        resolve_touching(m, d, t, yd, flook, &sink, &im, &s.events, &jmp, &st, err);
        if (st) goto done;
    }

    cv = CVodeCreate(CV_BDF, ctx);
    if (!cv) {
        st = RC_SET(err, RC_ESOLVER, "CVodeCreate failed");
        goto done;
    }
    CVCHECK(CVodeInit(cv, cb_rhs, t, y), "CVodeInit");
    CVCHECK(CVodeSetUserData(cv, &rc), "CVodeSetUserData");
    CVCHECK(CVodeSetErrHandlerFn(cv, cb_err, &rc), "CVodeSetErrHandlerFn");
    if (m->ewt_rel) CVCHECK(CVodeWFtolerances(cv, cb_ewt), "CVodeWFtolerances");
    else CVCHECK(CVodeSVtolerances(cv, m->rtol, av), "CVodeSVtolerances");
    CVCHECK(CVodeSetLinearSolver(cv, LS, A), "CVodeSetLinearSolver");
    if (!(rc.jsave = jsave = calloc((size_t)m->nnz + 1, sizeof(double)))) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian");
        goto done;
    }
    CVCHECK(CVodeSetLinSysFn(cv, cb_linsys), "CVodeSetLinSysFn");
    CVCHECK(CVodeSetMaxOrd(cv, m->max_order), "CVodeSetMaxOrd");
    CVCHECK(CVodeSetMaxNumSteps(cv, m->max_steps), "CVodeSetMaxNumSteps");
    CVCHECK(CVodeSetStabLimDet(cv, SUNTRUE), "CVodeSetStabLimDet");
    if (m->hmax > 0) CVCHECK(CVodeSetMaxStep(cv, m->hmax), "CVodeSetMaxStep");
    if (m->h0 > 0) CVCHECK(CVodeSetInitStep(cv, m->h0), "CVodeSetInitStep");
    if (m->nfree > 0) CVCHECK(CVodeSetProjFn(cv, cb_proj), "CVodeSetProjFn");
    if (rc_root_count(m) > 0) CVCHECK(CVodeRootInit(cv, rc_root_count(m), cb_root), "CVodeRootInit");
    CVCHECK(CVodeSetNoInactiveRootWarn(cv), "CVodeSetNoInactiveRootWarn");
    CVCHECK(set_root_directions(m, d, cv, rootdir), "CVodeSetRootDirection");

    /* time breakpoints: stop exactly there */
    if ((nbp = time_breakpoints(m, tend, &bp)) < 0) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    /* and never step past the end time (a single step may overshoot tout) */
    CVCHECK(CVodeSetStopTime(cv, nbp > 0 ? bp[0] : tend), "CVodeSetStopTime");

    double e0[RC_NENERGY];
    rc_energy(m, d, t, yd, e0);
    if ((st = write_frame(m, d, out, &fb, t, yd, 0, err))) goto done;

    /* ---- main loop: output times and events ---- */
    long nout = 1;
    double tout = fmin(dtout, tend);
    int fresh = 0; /* modes changed without a restart: the Jacobian is stale */
    double t_prev = t; /* where the last CVode call ended [s] */
    /* records inside contacts, at their own time scale, when the output
     * interval cannot resolve them (with full-state event records only) */
    const double dt_contact =
        evrec && m->nbody <= RC_CONTACT_REC_MAX_BODIES ? rc_contact_record_interval(m, dtout) : 0.0;
    double t_contact_rec = -INFINITY; /* time of the last such record [s] */
    long single = 0;   /* single steps since the last output time */
    while (t < tend) {
        /* the event callback asked to stop: end here as an interrupted run */
        if (sink.stop) {
            snprintf(reason, sizeof reason, "%s: the results up to there are kept", sink.why);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            break;
        }
        /* stepping (rc_run_until): hand over the state at each time asked
         * for; the caller may stop the run there */
        int paused_stop = 0;
        while (pause && t >= pause->until && !paused_stop) {
            const double tu = pause->until;
            const double *yu = yd;
            if (t > tu) {
                CVCHECK(CVodeGetDky(cv, tu, 0, ytn), "CVodeGetDky");
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
        /* after such a change, one internal step with a forced linear solver
         * setup and a new Jacobian: a stale Jacobian of the old mode (a
         * contact stiffness that is gone, a viscous friction term that
         * saturated) can make Newton's first small correction pass the
         * convergence test with a wrong solution */
        /* single steps also while an impact is in progress: its peak force
         * and maximum penetration are tracked at every step (sample_step);
         * /SOLVER Max_steps then bounds the single steps between two output
         * times, as CVODE bounds the steps of one call */
        const int one_step = fresh || rc_impacts_active(&im);
        long nst_before = 0, nst_after = 0;
        if (fresh) {
            CVCHECK(CVodeSetLSetupFrequency(cv, 1), "CVodeSetLSetupFrequency");
            CVCHECK(CVodeSetJacEvalFrequency(cv, 1), "CVodeSetJacEvalFrequency");
            CVodeGetNumSteps(cv, &nst_before);
        }
        /* a time asked for by the caller before the next output time: return
         * there (CV_NORMAL interpolates; the steps are the same) */
        const double tcall = pause && pause->until < tout ? pause->until : tout;
        int flag = CVode(cv, tcall, y, &t, one_step ? CV_ONE_STEP : CV_NORMAL);
        /* right after a root return, a single-step call may only hand back
         * the rest of the step already taken: keep the forced setup until a
         * new step has been taken */
        if (fresh && CVodeGetNumSteps(cv, &nst_after) == CV_SUCCESS && nst_after > nst_before) {
            CVCHECK(CVodeSetLSetupFrequency(cv, 0), "CVodeSetLSetupFrequency");
            CVCHECK(CVodeSetJacEvalFrequency(cv, 0), "CVodeSetJacEvalFrequency");
            fresh = 0;
        }
        /* interrupted (a signal): inside CVode the right-hand side made it
         * fail; between two calls the next call returns at its first one */
        if (opt && opt->stop && *opt->stop) {
            snprintf(reason, sizeof reason, "interrupted at t = %.9g s (signal): the results up to there are kept", t);
            fail_reason = reason;
            st = RC_SET(err, RC_EINTERRUPT, "%s", reason);
            break;
        }
        if (one_step && flag >= 0 && ++single > m->max_steps) flag = CV_TOO_MUCH_WORK;
        if (flag >= 0) sample_step(cv, &im, m, d, t_prev, t, y, ysamp);
        t_prev = t;
        if (flag < 0) {
            failure_advice(m, d, cv, flag, t, tout, rc.cvmsg, ytn, f0, reason, sizeof reason);
            fail_reason = reason;
            st = RC_SET(err, RC_ESOLVER, "%s", reason);
            break;
        }
        if ((flag == CV_TSTOP_RETURN && ibp < nbp && t >= bp[ibp]) || flag == CV_ROOT_RETURN) {
            if ((st = outputs_before(cv, m, d, out, &fb, t, tend, &tout, &nout, ytn, err))) goto done;
        }
        if (flag == CV_TSTOP_RETURN && ibp < nbp && t >= bp[ibp]) {
            /* a time breakpoint: an imposed velocity ends; restart there */
            s.events++;
            if ((st = sink_event(&sink, t, "impvel_stop", "/IMPVEL", NULL, err))) goto done;
            rc.jac_patched = 0; /* the imposed rows change: a whole new Jacobian */
            add_stats(cv, &s);
            CVCHECK(CVodeReInit(cv, t, y), "CVodeReInit");
            s.reinits++;
            while (ibp < nbp && bp[ibp] <= t) ibp++;
            /* the next breakpoint, or the end time */
            CVCHECK(CVodeSetStopTime(cv, ibp < nbp ? bp[ibp] : tend), "CVodeSetStopTime");
            /* a full-state record at the event (rc_event_records), or the
             * output record when the event falls on an output time */
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if ((evrec || on_out) && (st = write_frame(m, d, out, &fb, t, yd, evrec, err))) goto done;
            if (on_out) {
                nout++;
                tout = fmin(nout * dtout, tend);
            }
            continue;
        }
        if (flag == CV_ROOT_RETURN) {
            t_contact_rec = t; /* the event's own record stands for a contact record */
            /* flip modes; restart only when the right-hand side jumps */
            CVCHECK(CVodeGetRootInfo(cv, roots), "CVodeGetRootInfo");
            /* roots that land exactly on zero at the step's end (a law flat at
             * zero: an unload curve reaching zero before P does) were not
             * located: bisect on the interpolant for where they reached it */
            double t_ref = t;
            const int refined = refine_flat_roots(m, d, cv, t, roots, gbuf, ytn, &t_ref);
            if (refined > 0) {
                t = t_ref;
                memcpy(yd, N_VGetArrayPointer(ytn), (size_t)m->ny * sizeof(double));
            }
            rc_event ev[RC_MAX_EV];
            memcpy(old_mode, d->inter_mode, (size_t)m->ninter * sizeof(int));
            memcpy(old_branch, d->inter_branch, (size_t)m->ninter * sizeof(int));
            memcpy(old_track, d->inter_track, (size_t)m->ninter * sizeof(int));
            memcpy(old_slip, d->inter_slip, (size_t)m->ninter * sizeof(int));
            int jumped = 0;
            int nev = rc_events_apply(m, d, t, yd, roots, ev, RC_MAX_EV, &jumped);
            int cpl_ev = 0; /* a contact coupling's faces changed modes */
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) cpl_ev |= ev[k].inter < 0;
            s.events += nev;
            for (int k = 0; k < nev && k < RC_MAX_EV; k++) rc_impacts_event(&im, m, d, ev[k].inter, ev[k].kind, t, yd);
            for (int k = 0; k < nev && k < RC_MAX_EV; k++)
                if ((st = write_event(m, d, &sink, t, yd, &ev[k], err))) goto done;
            /* event accumulation: report it rather than stall */
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
            /* contacts left at zero penetration or zero force: by the state */
            nev += resolve_touching(m, d, t, yd, flook, &sink, &im, &s.events, &jumped, &st, err);
            if (st) goto done;
            if (nev > 0) CVCHECK(set_root_directions(m, d, cv, rootdir), "CVodeSetRootDirection");
            /* the Jacobian blocks of the interfaces whose modes changed, at
             * the event state (cb_linsys) */
            if (nev > 0) {
                int ok = 1, changed = 0;
                for (int i = 0; ok && i < m->ninter; i++)
                    if (d->inter_mode[i] != old_mode[i] || d->inter_branch[i] != old_branch[i] ||
                        d->inter_track[i] != old_track[i] || d->inter_slip[i] != old_slip[i]) {
                        changed = 1;
                        ok = rc_jac_refresh_inter(m, d, i, yd, jsave) == 0;
                    }
                /* coupling blocks are not refreshed in place: a whole new
                 * Jacobian when a contact coupling changed modes */
                rc.jac_patched = ok && changed && !cpl_ev;
            }
            if (refined > 0 || jumped || (nev > 0 && needs_restart(m, d, cv, old_mode, old_branch, old_track, old_slip, t, yd, ytn, f0, f1)) ||
                root_on_zero(m, d, t, yd, gbuf)) {
                add_stats(cv, &s);
                CVCHECK(CVodeReInit(cv, t, y), "CVodeReInit");
                s.reinits++;
            } else if (nev > 0) {
                fresh = 1;
            }
            /* an event on an output time stands for that output: a
             * full-state record at the event (rc_event_records), or else the
             * output record */
            const int on_out = tout - t <= 1e-12 * fmax(fabs(t), dtout);
            if (nev > 0 && (evrec || on_out) && (st = write_frame(m, d, out, &fb, t, yd, evrec, err))) goto done;
            if (on_out) {
                nout++;
                tout = fmin(nout * dtout, tend);
            }
        } else if (one_step && t < tout) {
            /* the single step ended before the output time: carry on, with
             * a record inside a contact when its time scale calls for one */
            if (dt_contact > 0 && rc_impacts_active(&im) && t - t_contact_rec >= dt_contact) {
                if ((st = write_frame(m, d, out, &fb, t, yd, RC_REC_CONTACT, err))) goto done;
                t_contact_rec = t;
            }
        } else {
            /* output times reached (a single step may pass several) */
            while (tout <= t) {
                const double *yo = yd;
                if (tout < t) {
                    CVCHECK(CVodeGetDky(cv, tout, 0, ytn), "CVodeGetDky");
                    yo = N_VGetArrayPointer(ytn);
                }
                if ((st = write_frame(m, d, out, &fb, tout, yo, 0, err))) goto done;
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
            CVodeGetNumSteps(cv, &nst);
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
    if (cv) add_stats(cv, &s);
    /* whole Jacobian evaluations (CVODE also counts the setups that used
     * jsave with the blocks refreshed after an event, cb_linsys) */
    if (d) s.jac_evals = d->n_jac;
    /* the impacts: in the file and, the first ones, in the statistics */
    rc_impacts_finish(&im);
    s.impacts = im.n;
    for (int k = 0; k < im.n && k < RC_STATS_IMPACTS; k++) s.impact[k] = im.row[k];
    snprintf(s.sampling_note, sizeof s.sampling_note, "%s", note);
    if (out && st == RC_OK) st = rc_output_impacts(out, im.n, im.row, err);
    else if (out) {
        rc_error e3;
        rc_output_impacts(out, im.n, im.row, &e3);
    }
    if (st != RC_OK) s.t_end = t; /* how far a failed run got */
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
    CVodeFree(&cv);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(y);
    N_VDestroy(av);
    N_VDestroy(f0);
    N_VDestroy(f1);
    N_VDestroy(ytn);
    N_VDestroy(ysamp);
    rc_impacts_free(&im);
    free(old_mode);
    free(old_branch);
    free(old_track);
    free(old_slip);
    free(rootdir);
    free(gbuf);
    free(zeno_t);
    free(zeno_n);
    free(bp);
    free(g2buf);
    free(ylook);
    free(flook);
    SUNContext_Free(&ctx);
    free(roots);
    frame_free(&fb);
    rc_data_free(d);
    free(jsave);
    return st;
}

/* The backend of /SOLVER Method 1 (solver.h). */
const rc_solver rc_solver_cvode = {"cvode", RC_METHOD_CVODE, cvode_run};

void rc_cvode_versions(FILE *f)
{
    fprintf(f, "SUNDIALS %s\nKLU %d.%d.%d (%s)\n", SUNDIALS_VERSION, KLU_MAIN_VERSION, KLU_SUB_VERSION,
            KLU_SUBSUB_VERSION, KLU_DATE);
}
