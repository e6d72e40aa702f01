/*
 * CVODE backend: BDF + Newton + KLU on the fixed sparse pattern, with
 * rootfinding for the events: the backend of /SOLVER Method 1 behind the
 * interface of solver.h (rc_solver_cvode), run by the shared loop rc_drive
 * (drive.c) through its rc_backend table (integrator.h).
 *
 * What is CVODE's own: after a root return the integrator is restarted
 * only when the right-hand side jumps by more than the error control
 * tolerates over the current step (a contact that opens at zero force, or
 * closes without damping, is continuous: no restart, needs_restart); the
 * Jacobian blocks of the interfaces whose modes changed are refreshed at
 * the event (jac_patched, cb_linsys), and without a restart the next step
 * is taken alone with a forced linear solver setup (fresh, cv_solve).
 * Quaternion norms are kept by CVODE's projection (CVodeSetProjFn).
 *
 * What CVODE carries: the states that can change (docs/theory.md 7.2).
 * The driver and the engine keep the model's whole state vector (yfull,
 * m->ny values); the states that keep their initial values whatever
 * happens (rc_constant_states: held velocity components, positions along
 * held translations at rest, the quaternions of bodies whose rotations are
 * all held at rest, the rotation states of bodies without spin on which no
 * moment can act) are left out of CVODE's vector. Every callback scatters
 * CVODE's vector into a whole-state scratch (the constant states in place)
 * and gathers what it returns; the Newton matrix is the part of the
 * model's Jacobian pattern on the kept states, and of it the active part
 * (activepart.h).
 *
 * Method switching (/SOLVER Switch 1, docs/theory.md 7.9): at a restart
 * after events, when BDF's largest step since its last restart is at most
 * RC_SW_PIN critical explicit steps of the closed contacts
 * (rc_explicit_step), the run goes on with ARKODE's ERKStep (an explicit
 * Runge-Kutta method with its own error control) from the same (t, y), on
 * the same right-hand side, root functions, directions, error weights and
 * stop time; after RC_SW_QUIET explicit steps without an event while its
 * step stays within RC_SW_NEAR critical steps (stability, not accuracy,
 * limits it), BDF takes over again at the time the last call returned.
 * Every switch is reported to the driver (cv_switched) as an event.
 */
#include <arkode/arkode_erkstep.h>
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

#include "model/coupling.h"
#include "model/joint.h"
#include "base/error.h"
#include "engine/events/events.h"
#include "model/model.h"
#include "solver/activepart.h"
#include "solver/impacts.h"
#include "solver/nvfast.h"
#include "solver/solver.h"
#include "solver/common.h"
#include "solver/integrator.h"
#include "solver/sens.h"
#include "engine/assembly/assembly.h"
#include "engine/reports/reports.h"

/* Method switching (docs/theory.md 7.9): BDF hands over to the explicit
 * method when its largest step since the last restart is at most RC_SW_PIN
 * critical steps h_crit [-]; the explicit method hands back after
 * RC_SW_QUIET steps without an event [-] with its last step at most
 * RC_SW_NEAR h_crit [-]. A step the explicit method's error test keeps
 * failing on hands back at once; after RC_SW_MAX_FAILS of them [-] BDF
 * carries the rest of the run. */
#define RC_SW_PIN 3.0
#define RC_SW_QUIET 200
#define RC_SW_NEAR 4.0
#define RC_SW_MAX_FAILS 3
/* the BDF order at most after a restart that follows a fric_turn (cv_restart) */
#define RC_TURN_MAX_ORDER 2
/* ... and after a restart where a damped contact of several points closed (below) */
#define RC_MULTI_MAX_ORDER 3
/* the order while a lightly damped contact whose events crowded is closed */
#define RC_LOWQ_MAX_ORDER 2
/* BDF order 2 at most until the next restart once CVODE's stability limit
 * detection has lowered the order at least RC_STALD_REDS times [-] since
 * the last restart, in at least RC_STALD_FRAC of its steps [-] (cv_solve) */
#define RC_STALD_REDS 1000
#define RC_STALD_FRAC 0.01
/* The Newton iteration's convergence coefficient (CVODE's default 0.1 of
 * the error test's tolerance) [-]: the stick springs of friction turn and
 * relax at K_t |v_t| / L (1e10 /s for K_t = 2.5e14 N/m, a slip of 5e-5 m/s
 * under a limit of 1 N), h lambda of several hundred at the steps the bodies
 * allow; a corrector stopped at 0.1 of the weight left F_t a few of its
 * tolerances off its attractor each step and the BDF history extrapolated
 * that into a spring of 1.4e4 N under a limit of 0.57 N within 30 steps (a
 * ball sliding along a wall; docs/theory.md 7.2) */
#define RC_NEWTON_CONV_COEF 0.01
/* The explicit method: Cash-Karp 6(4)5 [ARKODE table] */
#define RC_ERK_TABLE ARKODE_CASH_KARP_6_4_5

/* A jump in ydot whose effect over one step, relative to the error weight,
 * exceeds this fraction triggers a restart after an event [-]. */
#define RC_REINIT_JUMP 0.1

/* Tests only (integrator.h rc_cvode_set_reduce): 0 gives CVODE every state. */
static int reduce_on = 1;
void rc_cvode_set_reduce(int on) { reduce_on = on; }

typedef struct run_ctx {
    const rc_model *m;
    rc_data *d;
    double *jsave; /* [nnz] the Jacobian values of the last evaluation */
    int jac_patched; /* jsave's blocks of the interfaces whose modes an event
                        changed were refreshed at the event state */
    volatile sig_atomic_t *stop; /* the caller's stop flag (rc_run_options), NULL */
    char cvmsg[512]; /* CVODE's last error message, quoted in the failure message */
    int nwarn;       /* CVODE's warnings in this run (rc_bk_keep_error) */
    /* the integrator and its vectors (cv_open, cv_start) */
    SUNContext ctx;
    void *cv;
    SUNMatrix A;
    SUNLinearSolver LS;
    /* CVODE's vectors, over the kept states (nr of them) */
    N_Vector y, av, f0, f1, ytn, ysamp;
    /* the kept states: nr of m->ny; kidx[nr] their indices in the whole
     * state, ridx[ny] the reverse (-1: constant, not in CVODE's vector) */
    int nr, red; /* red: some state left out (nr < ny) */
    int *kidx, *ridx;
    char *cst; /* [ny] 1: constant, left out (the engine skips their Jacobian columns) */
    int nq, *qoff; /* kept quaternions: their offsets in CVODE's vector */
    /* whole-state vectors [ny]: the driver's state, and scratch for the
     * callbacks (rhs state and rate, interpolants of order 0 and higher,
     * impact samples, restart test); the constant states hold their values
     * (0 in dyf, the derivatives) */
    double *yfull, *ysc, *fsc, *ytf, *dyf, *ysf, *fa, *fb;
    int *old_mode, *old_branch, *old_track, *old_slip; /* the modes before a root return's events */
    int *old_pslip;                                    /* [npt] the contact points' modes before them */
    double *jshare; /* [npt] the contact points' shares when the Jacobian was last evaluated */
    double *jflim;  /* [2 ninter] the slipping interfaces' friction limits and sliding speeds then
                       (rc_scratch.inter_flim) */
    double *jfnr;   /* [ninter] the closed interfaces' normal forces then (rc_scratch.inter_fnr) */
    unsigned char *jland; /* [ninter] closed from open by the last events, until it opens (loads_moved) */
    int fresh; /* modes changed without a restart: the Jacobian is stale */
    double h_restart; /* the first step of the last restart [s] (restart_step) */
    int own_h0;       /* the integrator runs from a restart with h_restart, no step taken yet */
    int stald_low;    /* the order held at 2 until the next restart (cv_solve, RC_STALD_REDS) */
    int stald_due;    /* that hold asked for, applied at the next call (stald_apply) */
    int sens;         /* sensitivities on (rc_cvode_parts): no restart of cv_solve's own */
    rc_stats lost;    /* the counters of a first attempt redone (cv_solve) */
    rc_rootmap rm; /* the root functions CVODE is given (integrator.h) */
    rc_actpart ap; /* the Newton matrix on the active part of the pattern (activepart.h) */
    /* method switching (docs/theory.md 7.9) */
    int sw;          /* switching on (m->method_switch; off under sensitivities) */
    int expl;        /* the explicit integrator (erk) carries the run */
    void *erk;       /* ARKODE ERKStep, created at the first switch */
    double *hwork;   /* [2 nbody] scratch of rc_explicit_step */
    double hmax_bdf; /* BDF's largest step seen since its last restart [s] */
    double h_erk;    /* the explicit method's last step [s] */
    double t_last;   /* where the last solve returned, or the last restart [s] */
    long erk_base;   /* the explicit steps counted at its last restart */
    long erk_seen[4]; /* its counters already added: steps, rhs, error-test fails, root evals */
    N_Vector ysw;     /* the state where the explicit method's call began (erk_solve) */
    int sw_fails;     /* the explicit method's failures so far (RC_SW_MAX_FAILS) */
    rc_event_kind sw_kind; /* a switch not yet reported (cv_switched), RC_EV_NONE */
    double sw_t;           /* its time [s] */
    double tstop;    /* the stop time given (applied to both integrators) [s] */
    int tstop_set;
    int *dirs;       /* [rm.n] the root directions given (the integrator's layout) */
    int dirs_set;
} run_ctx;

/* ---- CVODE callbacks ----------------------------------------------- */
/* CVODE's warnings go to stderr as CVODE prints them; its last error is
 * kept for the failure message (nothing is said of the failure that an
 * interruption provokes on purpose). */
static void cb_err(int code, const char *module, const char *function, char *msg, void *ud)
{
    run_ctx *c = ud;
    /* the library is CVODES (sens.h); the integrator is named as the backend */
    if (module && !strcmp(module, "CVODES")) module = "CVODE";
    rc_bk_keep_error(c ? c->stop : NULL, c ? c->cvmsg : NULL, sizeof c->cvmsg, c ? &c->nwarn : NULL, code, module,
                     function, msg);
}

static int cb_rhs(realtype t, N_Vector y, N_Vector ydot, void *ud)
{
    run_ctx *c = ud;
    /* the caller asked to stop (a signal): an unrecoverable failure ends
     * CVode at the last accepted step; no mode or state is touched */
    if (c->stop && *c->stop) return -1;
    if (!c->red) return rc_assemble_rhs(c->m, c->d, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    const double *yr = N_VGetArrayPointer(y);
    double *fr = N_VGetArrayPointer(ydot);
    for (int j = 0; j < c->nr; j++) c->ysc[c->kidx[j]] = yr[j];
    const int st = rc_assemble_rhs(c->m, c->d, t, c->ysc, c->fsc);
    for (int j = 0; j < c->nr; j++) fr[j] = c->fsc[c->kidx[j]];
    return st;
}

/* CVODE's vector into the whole state (the constant states stay). */
static const double *whole(const run_ctx *c, N_Vector v, double *full)
{
    const double *r = N_VGetArrayPointer(v);
    if (!c->red) return r;
    for (int j = 0; j < c->nr; j++) full[c->kidx[j]] = r[j];
    return full;
}

/* Has a contact point's share moved since the Jacobian was evaluated
 * (jshare)? Its friction's rows and columns scale with the share: a point
 * that lands (w_j from 0) reaches shares 1e4 to 1e10 times those of the
 * Jacobian within microseconds, and a Newton iteration on such a matrix can
 * pass its convergence test in one iteration, away from the solution (a
 * friction state driven past its limit against its own rate, then steps of
 * 1e-12 s). The state's own rows move with the share's relative rate
 * too: -(dw/dt / w) s_j, of order 1/(t - t_landing), is 1e9 /s at the
 * landing and gone a few microseconds later; a Jacobian that keeps it
 * damps every Newton correction of that state, which then follows the
 * predictor (seen: a landed point's state driven to 1000 times its limit
 * against its own rate, energy_friction falling). A share that doubled or
 * halved (above RC_JSHARE_FLOOR), or moved by more than RC_JSHARE_MOVE,
 * asks for a new Jacobian. */
#define RC_JSHARE_MOVE 0.05
#define RC_JSHARE_FLOOR 1e-12
static int shares_moved(const run_ctx *c)
{
    const double *w = c->d->sc->pt_share, *wj = c->jshare;
    for (int j = 0; j < c->m->npt; j++) {
        const double a = w[j], b = wj[j];
        if (fabs(a - b) > RC_JSHARE_MOVE || a > 2.0 * b + RC_JSHARE_FLOOR || b > 2.0 * a + RC_JSHARE_FLOOR) return 1;
    }
    return 0;
}

/* Has the friction limit or the sliding speed of a slipping interface
 * doubled or halved (beyond its force band, its slip speed band) since the
 * Jacobian was evaluated (jflim)? The slip law's rows turn and load the
 * state at K_t |v_t| / L_r (kernels.inc, L_r about the limit), a stiff
 * rate: a Newton matrix whose rate is off by more than a factor 2 makes the
 * iteration diverge in the directions the rate acts on, or, too stiff, damps
 * every correction there. A ball striking a stiff wall while sliding raises
 * the limit from 1e2 to 1e8 N within 1e-8 s; with a matrix kept from the
 * first steps of it the corrections followed the predictor and the state grew
 * at K_t |v_t| to 300 times its limit (20 J stored in the stick spring,
 * energy_friction falling by as much). A block sliding down an incline
 * speeds up from rest a hundredfold; with a matrix kept from its first
 * millimetres the iteration amplified the rounding across the fall line to
 * a lateral velocity of 6e-6 m/s within one step. */
static int limits_moved(const run_ctx *c)
{
    const double *l = c->d->sc->inter_flim, *lj = c->jflim;
    for (int i = 0; i < c->m->ninter; i++) {
        const double fb = c->m->inter_fr[i].fband, vs = c->m->inter_vscale[i];
        const double vb = isfinite(vs) && vs > 0 ? RC_SLIP_BAND * vs : c->m->atol_vel;
        const double a = l[2 * i], b = lj[2 * i], va = l[2 * i + 1], vj = lj[2 * i + 1];
        if (a > 2.0 * b + fb || b > 2.0 * a + fb || va > 2.0 * vj + vb || vj > 2.0 * va + vb) return 1;
    }
    return 0;
}

/* Has the normal force of an interface that closed from open (jland) grown
 * by a factor RC_JLOAD_FACTOR, beyond RC_JLOAD_BAND of its force scale,
 * since the Jacobian was evaluated (jfnr)? A restart at the closing
 * evaluates the Jacobian at P = 0, where the law's stiffness is about zero
 * (a power law's dF/dP grows as P^(n-1)) and the rows of the states that
 * follow the force (the accounting states, the effective penetration, the
 * friction) are those of no contact, or singular (entries of 1e17 against
 * P_e at 1e-17 m). The accounting states feed nothing back: Newton's
 * iteration converges on the motion whatever their rows, and with that
 * matrix kept their corrections follow the stale rows every step, a bias
 * the error test cannot see (it moves the history too). Seen: a spinning
 * box landing on a corner kept the matrix of the closing for 40 steps
 * while its force grew a thousandfold, and its friction work fell 1e-3 J
 * while its rate was at most +0.9 W. Only after a closing: a contact that
 * vibrates between zero and twice its load asked for a matrix every half
 * period (a meshed box on a belt, 1.9 times longer). */
#define RC_JLOAD_FACTOR 10.0
#define RC_JLOAD_BAND 1e-3
static int loads_moved(const run_ctx *c)
{
    const double *f = c->d->sc->inter_fnr, *fj = c->jfnr;
    for (int i = 0; i < c->m->ninter; i++) {
        if (!c->jland[i]) continue;
        const double fs = c->m->inter_fscale[i];
        const double fb = isfinite(fs) && fs > 0 ? RC_JLOAD_BAND * fs : 0.0;
        if (f[i] > RC_JLOAD_FACTOR * fj[i] + fb) return 1;
    }
    return 0;
}

/* The Newton matrix I - gamma J formed in place (CVodeSetLinSysFn): J is
 * evaluated into jsave only when CVODE asks for a new one (jok false, or
 * a contact point's share moved: shares_moved), and
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
    if (jok && !patched && ((m->npt > 0 && shares_moved(c)) || limits_moved(c) || loads_moved(c))) jok = SUNFALSE;
    if (!jok) {
        const double *yf = whole(c, y, c->ysc); /* the whole state (the part's slots depend on it) */
        if (!patched) {
            int st = rc_assemble_jac(m, c->d, t, yf, c->jsave);
            if (st) return st;
            /* the shares of a whole Jacobian (a patched one keeps the other
             * points' blocks, and their shares, from the last whole one) */
            if (m->npt > 0) memcpy(c->jshare, c->d->sc->pt_share, (size_t)m->npt * sizeof(double));
            memcpy(c->jflim, c->d->sc->inter_flim, 2 * (size_t)m->ninter * sizeof(double));
            memcpy(c->jfnr, c->d->sc->inter_fnr, (size_t)m->ninter * sizeof(double));
        }
        *jcur = SUNTRUE;
        /* new values, perhaps new active slots: the part follows */
        if (rc_actpart_follow(&c->ap, m, c->d, t, yf, patched ? NULL : c->jsave)) return -1;
    } else {
        *jcur = SUNFALSE;
    }
    /* nothing else writes A: its pattern is written when the part changes */
    return rc_actpart_load(&c->ap, m, A, c->LS, -gamma, c->jsave, 1.0, 0) ? -1 : 0;
}

static int cb_root(realtype t, N_Vector y, realtype *g, void *ud)
{
    run_ctx *c = ud;
    c->d->sc->n_root++;
    rc_assemble_roots(c->m, c->d, t, whole(c, y, c->ysc), rc_rootmap_full(&c->rm, g));
    rc_rootmap_keep(&c->rm, t, rc_rootmap_full(&c->rm, g)); /* for the physics checks */
    rc_rootmap_gather(&c->rm, g);
    return 0;
}

/* Error weights: the rule every backend shares (common.h rc_bk_state_tol),
 * on the states the integrator carries. */
static int cb_ewt(N_Vector yv, N_Vector wv, void *ud)
{
    const run_ctx *c = ud;
    const double *y = N_VGetArrayPointer(yv);
    double *w = N_VGetArrayPointer(wv);
    for (int j = 0; j < c->nr; j++) {
        const double s = rc_bk_state_tol(c->m, c->d, c->kidx[j], y[j]);
        if (!(s > 0)) return -1;
        w[j] = 1.0 / s;
    }
    return 0;
}

/* Projection onto unit quaternions. The error estimate is not projected
 * (CVodeSetProjErrEst off, cv_start): CVODE's error test would then read
 * the projected estimate, but its order selection (the estimates at orders
 * q - 1 and q + 1) reads the unprojected correction, whose radial part,
 * fed back by the projection into the history, exceeds the quaternions'
 * absolute tolerances many times over. BDF then never left order 1: three
 * spinning balls in free flight took 3e-6 s steps, 281 660 steps for
 * 0.78 s (3 040 with the estimate unprojected). */
static int cb_proj(realtype t, N_Vector ycur, N_Vector corr, realtype eps, N_Vector err, void *ud)
{
    run_ctx *c = ud;
    double *y = N_VGetArrayPointer(ycur), *cr = N_VGetArrayPointer(corr);
    N_VConst(0.0, corr);
    for (int b = 0; b < c->nq; b++) {
        const int o = c->qoff[b]; /* the kept quaternions (a constant one is exactly unit) */
        const double *q = y + o;
        double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int k = 0; k < 4; k++) cr[o + k] = q[k] / nq - q[k];
    }
    return 0;
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

/* Must the integrator restart after a mode change at troot? CVODE has
 * already stepped to tn >= troot with the old modes; continuing is right only
 * if the old and new right-hand sides agree, within the error weights, over
 * [troot, tn] and over the next step h: compare them at troot and at tn.
 * old_mode is the mode array before the flip; d->inter_mode after it. */
static int needs_restart(run_ctx *c, double troot, const double *yroot)
{
    const rc_model *m = c->m;
    rc_data *d = c->d;
    void *cv = c->cv;
    int *old_mode = c->old_mode, *old_branch = c->old_branch, *old_track = c->old_track, *old_slip = c->old_slip;
    double h = 0, tn = troot;
    CVodeGetCurrentStep(cv, &h);
    CVodeGetCurrentTime(cv, &tn);
    if (CVodeGetDky(cv, tn, 0, c->ytn) != CV_SUCCESS) return 1;
    const double *y_at[2] = {yroot, whole(c, c->ytn, c->ytf)};
    const double t_at[2] = {troot, tn}, span[2] = {h, (tn - troot) + h};
    double *a = c->fa, *b = c->fb;
    for (int s = 0; s < 2; s++) {
        /* old modes, then new modes, at the same state */
        int *new_mode = d->inter_mode, *new_branch = d->inter_branch, *new_track = d->inter_track;
        int *new_slip = d->inter_slip, *new_pslip = d->pt_slip;
        d->inter_mode = old_mode;
        d->inter_branch = old_branch;
        d->inter_track = old_track;
        d->inter_slip = old_slip;
        if (m->npt > 0) d->pt_slip = c->old_pslip; /* the contact points' modes too */
        int bad = rc_assemble_rhs(m, d, t_at[s], y_at[s], a);
        d->inter_mode = new_mode;
        d->inter_branch = new_branch;
        d->inter_track = new_track;
        d->inter_slip = new_slip;
        d->pt_slip = new_pslip;
        bad |= rc_assemble_rhs(m, d, t_at[s], y_at[s], b);
        if (bad) return 1;
        for (int k = 0; k < m->ny; k++) {
            double w = m->rtol * fabs(y_at[s][k]) + m->atol[k];
            if (fabs(b[k] - a[k]) * span[s] > RC_REINIT_JUMP * w) return 1;
        }
    }
    return 0;
}

/* The message of a failed CVode call: where (t, the step, the element whose
 * state carries the largest weighted local error) and, by the kind of
 * failure, the likely cause and what to change in the case. */
static void failure_advice(const rc_model *m, const rc_data *d, void *cv, int flag, double t, double tout,
                           const char *cvmsg, N_Vector tmp1, N_Vector tmp2, const int *kidx, char *buf, size_t n)
{
    double h = 0.0;
    CVodeGetCurrentStep(cv, &h);
    /* the element: largest |local error| x weight (the error test's measure) */
    char elem[200] = "";
    int istate = -1;
    if (CVodeGetEstLocalErrors(cv, tmp1) == CV_SUCCESS && CVodeGetErrWeights(cv, tmp2) == CV_SUCCESS) {
        const int imax = rc_bk_worst_error(N_VGetArrayPointer(tmp1), N_VGetArrayPointer(tmp2),
                                           (int)N_VGetLength(tmp1), 0, 0);
        if (imax >= 0) rc_state_name(m, istate = kidx[imax], elem, sizeof elem);
    }
    char *fname = CVodeGetReturnFlagName(flag); /* malloc'ed by CVODE */
    rc_fail_kind kind = RC_FAIL_OTHER;
    switch (flag) {
    case CV_TOO_MUCH_WORK: kind = RC_FAIL_MAX_STEPS; break;
    case CV_TOO_MUCH_ACC: kind = RC_FAIL_ACCURACY; break;
    case CV_ERR_FAILURE: kind = RC_FAIL_ERROR_TEST; break;
    case CV_CONV_FAILURE:
    case CV_LSETUP_FAIL:
    case CV_LSOLVE_FAIL: kind = RC_FAIL_NEWTON; break;
    case CV_RHSFUNC_FAIL:
    case CV_REPTD_RHSFUNC_ERR:
    case CV_UNREC_RHSFUNC_ERR:
    case CV_FIRST_RHSFUNC_ERR: kind = RC_FAIL_FORCES; break;
    case CV_RTFUNC_FAIL: kind = RC_FAIL_ROOTS; break;
    default: break;
    }
    const char *advice = rc_bk_advice(kind, m);
    rc_bk_failure_message(m, d, "CVODE", t, h, tout, fname, cvmsg, elem, istate, advice, buf, n);
    free(fname);
}

/* The message of a failed call of the explicit integrator (method
 * switching): as failure_advice, with ERKStep's flag and estimates. */
static void erk_failure(run_ctx *c, int flag, double t, double tout, char *buf, size_t n)
{
    double h = 0.0;
    ERKStepGetCurrentStep(c->erk, &h);
    char elem[200] = "";
    int istate = -1;
    if (ERKStepGetEstLocalErrors(c->erk, c->ytn) == ARK_SUCCESS && ERKStepGetErrWeights(c->erk, c->f0) == ARK_SUCCESS) {
        const int imax = rc_bk_worst_error(N_VGetArrayPointer(c->ytn), N_VGetArrayPointer(c->f0),
                                           (int)N_VGetLength(c->ytn), 0, 0);
        if (imax >= 0) rc_state_name(c->m, istate = c->kidx[imax], elem, sizeof elem);
    }
    char *fname = ERKStepGetReturnFlagName(flag); /* malloc'ed by ARKODE */
    rc_fail_kind kind = RC_FAIL_OTHER;
    switch (flag) {
    case ARK_TOO_MUCH_WORK: kind = RC_FAIL_MAX_STEPS; break;
    case ARK_TOO_MUCH_ACC: kind = RC_FAIL_ACCURACY; break;
    case ARK_ERR_FAILURE: kind = RC_FAIL_ERROR_TEST; break;
    case ARK_RHSFUNC_FAIL:
    case ARK_REPTD_RHSFUNC_ERR:
    case ARK_UNREC_RHSFUNC_ERR:
    case ARK_FIRST_RHSFUNC_ERR: kind = RC_FAIL_FORCES; break;
    case ARK_RTFUNC_FAIL: kind = RC_FAIL_ROOTS; break;
    default: break;
    }
    rc_bk_failure_message(c->m, c->d, "ARKODE ERKStep (method switching)", t, h, tout, fname, c->cvmsg, elem,
                          istate, rc_bk_advice(kind, c->m), buf, n);
    free(fname);
}

/* ---- the backend's operations (integrator.h rc_backend) ---------------- */
#define CVCHECK(call, what)                                                                            \
    do {                                                                                               \
        int flag_ = (call);                                                                            \
        if (flag_ < 0) {                                                                               \
            char *name_ = CVodeGetReturnFlagName(flag_); /* malloc'ed by CVODE */                      \
            return RC_SET(err, RC_ESOLVER, "CVODE call %s failed at t = %.9g s: %s (%s)", what, 0.0,   \
                          name_ ? name_ : "?", c->cvmsg);                                              \
        }                                                                                              \
    } while (0)

static rc_status cv_open(void *self, const rc_model *m, rc_data *d, const rc_run_options *opt, double **y,
                         double **yp, int *n, const char **integrator, rc_error *err)
{
    run_ctx *c = self;
    c->m = m;
    c->d = d;
    c->stop = opt ? opt->stop : NULL;
    if (rc_rootmap_init(&c->rm, m, opt)) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    if (SUNContext_Create(NULL, &c->ctx)) return RC_SET(err, RC_ESOLVER, "SUNContext_Create failed");
    const size_t ny = (size_t)m->ny + 1;
    double **full[] = {&c->yfull, &c->ysc, &c->fsc, &c->ytf, &c->dyf, &c->ysf, &c->fa, &c->fb};
    for (size_t k = 0; k < sizeof full / sizeof full[0]; k++)
        if (!(*full[k] = calloc(ny, sizeof(double)))) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    c->old_mode = calloc((size_t)m->ninter + 1, sizeof(int));
    c->old_branch = calloc((size_t)m->ninter + 1, sizeof(int));
    c->old_track = calloc((size_t)m->ninter + 1, sizeof(int));
    c->old_slip = calloc((size_t)m->ninter + 1, sizeof(int));
    c->old_pslip = calloc((size_t)m->npt + 1, sizeof(int));
    c->jsave = calloc((size_t)m->nnz + 1, sizeof(double));
    c->jshare = calloc((size_t)m->npt + 1, sizeof(double));
    c->jflim = calloc(2 * (size_t)m->ninter + 1, sizeof(double));
    c->jfnr = calloc((size_t)m->ninter + 1, sizeof(double));
    c->jland = calloc((size_t)m->ninter + 1, 1);
    c->kidx = malloc(ny * sizeof(int));
    c->ridx = malloc(ny * sizeof(int));
    c->qoff = malloc(((size_t)m->nbody + 1) * sizeof(int));
    c->sw = m->method_switch;
    c->hwork = malloc((2 * (size_t)m->nbody + 1) * sizeof(double));
    c->dirs = calloc((size_t)c->rm.n + 1, sizeof(int));
    if (!c->hwork || !c->dirs) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    if (!c->old_mode || !c->old_branch || !c->old_track || !c->old_slip || !c->old_pslip || !c->jsave || !c->jshare || !c->jflim || !c->jfnr || !c->jland || !c->kidx ||
        !c->ridx || !c->qoff)
        return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    /* the driver fills the whole state; CVODE's vectors follow in cv_start,
     * once the initial state says which states are constant */
    *y = c->yfull;
    *yp = NULL;
    *n = m->ny;
    *integrator = m->method_switch ? "CVODE BDF, Newton, KLU sparse direct, rootfinding; method switching to "
                                     "ARKODE ERKStep (Cash-Karp 6(4)5) and back"
                                   : "CVODE BDF, Newton, KLU sparse direct, rootfinding";
    return RC_OK;
}

/* The states CVODE carries (rc_constant_states at the initial state y0):
 * kidx, ridx, the kept quaternions and the Newton matrix's pattern. */
static rc_status plan_states(run_ctx *c, const double *y0, rc_error *err)
{
    const rc_model *m = c->m;
    char *cst = c->cst = calloc((size_t)m->ny + 1, 1);
    if (!cst) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    /* (every state constant: a body held in all six directions by two
     * cards and nothing else; CVODE is given them all) */
    if (reduce_on && rc_constant_states(m, y0, NULL, cst) == m->ny) memset(cst, 0, (size_t)m->ny);
    c->nr = 0;
    for (int k = 0; k < m->ny; k++) {
        c->ridx[k] = cst[k] ? -1 : c->nr;
        if (!cst[k]) c->kidx[c->nr++] = k;
    }
    c->red = c->nr < m->ny;
    /* the Jacobian's columns of the constant states are not needed: the
     * engine leaves them out (their rows and columns are not in the part) */
    c->d->jac_skip = c->red ? cst : NULL;
    c->nq = 0;
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0 && c->ridx[m->body_yadr[b] + 3] >= 0) c->qoff[c->nq++] = c->ridx[m->body_yadr[b] + 3];
    return RC_OK;
}

static rc_status cv_start(void *self, rc_error *err)
{
    run_ctx *c = self;
    const rc_model *m = c->m;
    rc_status st = plan_states(c, c->yfull, err);
    if (st) return st;
    const sunindextype nr = c->nr;
    /* nothing left out: CVODE's vector is the driver's state itself (no copy
     * after each call) */
    c->y = c->red ? N_VNew_Serial(nr, c->ctx) : N_VMake_Serial(nr, c->yfull, c->ctx);
    c->av = N_VNew_Serial(nr, c->ctx);
    c->f0 = N_VNew_Serial(nr, c->ctx);
    c->f1 = N_VNew_Serial(nr, c->ctx);
    c->ytn = N_VNew_Serial(nr, c->ctx);
    c->ysamp = N_VNew_Serial(nr, c->ctx);
    /* A has the whole pattern's capacity: every part of it fits */
    c->A = SUNSparseMatrix(nr, nr, m->nnz, CSC_MAT, c->ctx);
    if (!c->y || !c->av || !c->f0 || !c->f1 || !c->ytn || !c->ysamp || !c->A)
        return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    /* optimised vector operations, inherited by CVODE's clones of y (nvfast.h) */
    N_Vector vecs[] = {c->y, c->av, c->f0, c->f1, c->ytn, c->ysamp};
    for (size_t k = 0; k < sizeof vecs / sizeof vecs[0]; k++) rc_nvector_fast(vecs[k]);
    /* every state kept: the model's pattern, once (it stays when the active
     * part is off); cb_linsys writes the values */
    if (!c->red) {
        sunindextype *cp = SUNSparseMatrix_IndexPointers(c->A), *ri = SUNSparseMatrix_IndexValues(c->A);
        for (int k = 0; k <= m->ny; k++) cp[k] = (sunindextype)m->jac_colptr[k];
        for (int64_t k = 0; k < m->nnz; k++) ri[k] = (sunindextype)m->jac_rowind[k];
    }
    if (!(c->LS = SUNLinSol_KLU(c->y, c->A, c->ctx))) return RC_SET(err, RC_ESOLVER, "SUNLinSol_KLU failed");
    /* the Newton matrix: the kept states' rows and columns, of them the
     * active part (activepart.h) */
    const int ap = rc_actpart_open(&c->ap, m, c->LS, 1, NULL);
    const int as = ap ? -1 : rc_actpart_set_states(&c->ap, c->red ? c->ridx : NULL);
    if (as == -1) return RC_SET(err, RC_ENOMEM, "out of memory for the solver");
    if (as) return RC_SET(err, RC_EINTERNAL, "the Newton matrix's pattern lacks a diagonal entry");
    /* the constant states of the scratch vectors, once */
    for (int k = 0; k < m->ny; k++)
        if (c->ridx[k] < 0) c->ysc[k] = c->ytf[k] = c->ysf[k] = c->yfull[k];
    double *yr = N_VGetArrayPointer(c->y), *av = N_VGetArrayPointer(c->av);
    for (int j = 0; j < c->nr; j++) {
        yr[j] = c->yfull[c->kidx[j]];
        av[j] = m->atol[c->kidx[j]];
    }
    void *cv = c->cv = CVodeCreate(CV_BDF, c->ctx);
    if (!cv) return RC_SET(err, RC_ESOLVER, "CVodeCreate failed");
    CVCHECK(CVodeInit(cv, cb_rhs, 0.0, c->y), "CVodeInit");
    CVCHECK(CVodeSetUserData(cv, c), "CVodeSetUserData");
    CVCHECK(CVodeSetErrHandlerFn(cv, cb_err, c), "CVodeSetErrHandlerFn");
    if (m->ewt_rel || m->npt > 0) CVCHECK(CVodeWFtolerances(cv, cb_ewt), "CVodeWFtolerances");
    else CVCHECK(CVodeSVtolerances(cv, m->rtol, c->av), "CVodeSVtolerances");
    CVCHECK(CVodeSetLinearSolver(cv, c->LS, c->A), "CVodeSetLinearSolver");
    CVCHECK(CVodeSetLinSysFn(cv, cb_linsys), "CVodeSetLinSysFn");
    CVCHECK(CVodeSetMaxOrd(cv, m->max_order), "CVodeSetMaxOrd");
    CVCHECK(CVodeSetNonlinConvCoef(cv, RC_NEWTON_CONV_COEF), "CVodeSetNonlinConvCoef");
    CVCHECK(CVodeSetMaxNumSteps(cv, m->max_steps), "CVodeSetMaxNumSteps");
    CVCHECK(CVodeSetStabLimDet(cv, SUNTRUE), "CVodeSetStabLimDet");
    CVCHECK(CVodeSetMaxErrTestFails(cv, RC_MAX_ERR_TEST_FAILS), "CVodeSetMaxErrTestFails");
    CVCHECK(CVodeSetMaxConvFails(cv, RC_MAX_CONV_FAILS), "CVodeSetMaxConvFails");
    if (m->hmax > 0) CVCHECK(CVodeSetMaxStep(cv, m->hmax), "CVodeSetMaxStep");
    if (m->h0 > 0) CVCHECK(CVodeSetInitStep(cv, m->h0), "CVodeSetInitStep");
    if (c->nq > 0) {
        CVCHECK(CVodeSetProjFn(cv, cb_proj), "CVodeSetProjFn");
        CVCHECK(CVodeSetProjErrEst(cv, SUNFALSE), "CVodeSetProjErrEst");
    }
    if (c->rm.n > 0) CVCHECK(CVodeRootInit(cv, c->rm.n, cb_root), "CVodeRootInit");
    CVCHECK(CVodeSetNoInactiveRootWarn(cv), "CVodeSetNoInactiveRootWarn");
    return RC_OK;
}

/* The driver's whole state into CVODE's vector (at a restart), and back
 * (after a solve). */
static void gather_state(run_ctx *c)
{
    if (!c->red) return; /* the same array */
    double *yr = N_VGetArrayPointer(c->y);
    for (int j = 0; j < c->nr; j++) yr[j] = c->yfull[c->kidx[j]];
}
static void scatter_state(run_ctx *c)
{
    if (!c->red) return;
    const double *yr = N_VGetArrayPointer(c->y);
    for (int j = 0; j < c->nr; j++) c->yfull[c->kidx[j]] = yr[j];
}


/* ---- method switching (docs/theory.md 7.9) ----------------------------- */
/* The explicit integrator's counters since they were last added, into s
 * (its steps also into steps_explicit); a ReInit that zeroed them is seen
 * as counters below the ones added. */
static void erk_stats(run_ctx *c, rc_stats *s)
{
    long v[4] = {0, 0, 0, 0}, dv[4];
    ERKStepGetNumSteps(c->erk, &v[0]);
    ERKStepGetNumRhsEvals(c->erk, &v[1]);
    ERKStepGetNumErrTestFails(c->erk, &v[2]);
    ERKStepGetNumGEvals(c->erk, &v[3]);
    for (int k = 0; k < 4; k++) {
        dv[k] = v[k] >= c->erk_seen[k] ? v[k] - c->erk_seen[k] : v[k];
        c->erk_seen[k] = v[k];
    }
    s->steps += dv[0];
    s->steps_explicit += dv[0];
    s->rhs_evals += dv[1];
    s->err_test_fails += dv[2];
    s->root_evals += dv[3];
}

/* The stop time and the root directions given, to the integrator that now
 * carries the run. */
static int apply_settings(run_ctx *c)
{
    int flag = 0;
    if (c->expl) {
        if (c->tstop_set && (flag = ERKStepSetStopTime(c->erk, c->tstop)) < 0) return flag;
        if (c->dirs_set && c->rm.n > 0 && (flag = ERKStepSetRootDirection(c->erk, c->dirs)) < 0) return flag;
    } else {
        if (c->tstop_set && (flag = CVodeSetStopTime(c->cv, c->tstop)) < 0) return flag;
        if (c->dirs_set && c->rm.n > 0 && (flag = CVodeSetRootDirection(c->cv, c->dirs)) < 0) return flag;
    }
    return 0;
}

/* The kept quaternions of CVODE's vector normalised (the explicit method has
 * no projection: at each of its restarts), and the driver's state after it. */
static void normalise_quats(run_ctx *c)
{
    double *y = N_VGetArrayPointer(c->y);
    for (int b = 0; b < c->nq; b++) {
        double *q = y + c->qoff[b];
        const double nq = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (nq > 0)
            for (int k = 0; k < 4; k++) q[k] /= nq;
    }
    if (c->nq > 0) scatter_state(c);
}

/* (Re)start the explicit integrator at (t, CVODE's vector), first step h
 * (0: its estimate). */
static int erk_start(run_ctx *c, double t, double h)
{
    const rc_model *m = c->m;
    int flag;
    if (!c->erk) {
        if (!(c->ysw = N_VClone(c->y))) return ARK_MEM_FAIL;
        if (!(c->erk = ERKStepCreate(cb_rhs, t, c->y, c->ctx))) return ARK_MEM_FAIL;
        if ((flag = ERKStepSetUserData(c->erk, c)) < 0 || (flag = ERKStepSetErrHandlerFn(c->erk, cb_err, c)) < 0)
            return flag;
        if (m->ewt_rel || m->npt > 0) flag = ERKStepWFtolerances(c->erk, cb_ewt);
        else flag = ERKStepSVtolerances(c->erk, m->rtol, c->av);
        if (flag < 0 || (flag = ERKStepSetMaxNumSteps(c->erk, m->max_steps)) < 0) return flag;
        if ((flag = ERKStepSetMaxErrTestFails(c->erk, RC_MAX_ERR_TEST_FAILS)) < 0) return flag;
        if (m->hmax > 0 && (flag = ERKStepSetMaxStep(c->erk, m->hmax)) < 0) return flag;
        if (c->rm.n > 0 && (flag = ERKStepRootInit(c->erk, c->rm.n, cb_root)) < 0) return flag;
        if ((flag = ERKStepSetNoInactiveRootWarn(c->erk)) < 0) return flag;
        /* fifth order, six stages: at the tolerances of impacts it took a
         * third of the steps of the default fourth order (Zonneveld) on
         * the settling column, and fewer than the sixth and eighth orders,
         * whose error tests failed at the stability limit */
        if ((flag = ERKStepSetTableNum(c->erk, RC_ERK_TABLE)) < 0) return flag;
        if ((flag = ERKStepSetInitStep(c->erk, h)) < 0) return flag;
    } else {
        if ((flag = ERKStepSetInitStep(c->erk, h)) < 0 || (flag = ERKStepReInit(c->erk, cb_rhs, t, c->y)) < 0)
            return flag;
    }
    c->expl = 1;
    /* the counters now: what follows is added (erk_stats) */
    ERKStepGetNumSteps(c->erk, &c->erk_seen[0]);
    ERKStepGetNumRhsEvals(c->erk, &c->erk_seen[1]);
    ERKStepGetNumErrTestFails(c->erk, &c->erk_seen[2]);
    ERKStepGetNumGEvals(c->erk, &c->erk_seen[3]);
    c->erk_base = c->erk_seen[0];
    c->t_last = t;
    return apply_settings(c);
}

/* Back to BDF at (t, the driver's state): the explicit method's counters
 * kept (lost), CVODE restarted with a new Jacobian. */
static int to_implicit(run_ctx *c, double t)
{
    erk_stats(c, &c->lost);
    gather_state(c);
    normalise_quats(c);
    c->expl = 0;
    c->stald_low = 0;
    c->stald_due = 0;
    c->jac_patched = 0;
    c->fresh = 0;
    c->hmax_bdf = 0.0;
    if (c->m->h0 <= 0) {
        c->h_restart = rc_bk_restart_step(c->m, t, c->h_erk);
        int flag = CVodeSetInitStep(c->cv, c->h_restart);
        if (flag < 0) return flag;
        c->own_h0 = c->h_restart > 0;
    }
    int flag = CVodeSetMaxOrd(c->cv, c->m->max_order); /* the deck's order (cv_restart) */
    if (flag < 0) return flag;
    flag = CVodeReInit(c->cv, t, c->y);
    if (flag < 0) return flag;
    c->sw_kind = RC_EV_METHOD_IMPLICIT;
    c->sw_t = t;
    c->t_last = t;
    return apply_settings(c);
}

/* Is the explicit method held at the stability limit while nothing
 * happens (RC_SW_QUIET steps without an event, its step within RC_SW_NEAR
 * h_crit)? */
static int explicit_resting(run_ctx *c)
{
    long nst = 0;
    if (ERKStepGetNumSteps(c->erk, &nst) < 0 || nst - c->erk_base < RC_SW_QUIET) return 0;
    const double hc = rc_explicit_step(c->m, c->d, c->t_last, c->yfull, c->hwork);
    return isfinite(hc) && c->h_erk > 0 && c->h_erk <= RC_SW_NEAR * hc;
}

/* One call of the explicit integrator (cv_solve), or the switch back to
 * BDF first when it rests (then *back is set and CVODE solves). */
static int erk_solve(run_ctx *c, double tout, double *t, int one_step, int *back)
{
    *back = 0;
    if (explicit_resting(c)) {
        *back = 1;
        return to_implicit(c, c->t_last);
    }
    const double t0 = c->t_last;
    N_VScale(1.0, c->y, c->ysw);
    int flag = ERKStepEvolve(c->erk, tout, c->y, t, one_step ? ARK_ONE_STEP : ARK_NORMAL);
    if (flag == ARK_ERR_FAILURE) {
        /* a step its error test kept failing on (a kink it cannot step
         * over, a rate stiffer than h_crit counts: a box's corners
         * changing roles at the explicit step): BDF takes over from where
         * this call began, and after RC_SW_MAX_FAILS such failures carries
         * the rest of the run */
        N_VScale(1.0, c->ysw, c->y);
        if (++c->sw_fails >= RC_SW_MAX_FAILS) c->sw = 0;
        *back = 1;
        return to_implicit(c, t0);
    }
    scatter_state(c);
    double hu = 0.0;
    if (ERKStepGetLastStep(c->erk, &hu) == ARK_SUCCESS && hu > 0) c->h_erk = hu;
    c->t_last = *t;
    return flag;
}

/* A stiff mode near the imaginary axis that its damping holds only
 * weakly (a box resting on its corners on a lightly damped contact, whose
 * shared mode has a damping ratio of 0.0026) is amplified by BDF orders 3
 * to 5 at steps of h omega within their unstable bands (order 3: from
 * (4 zeta)^(1/3) to 1.9); with the steps accuracy allows at a vibration at
 * the level of the tolerances there, the error test then holds a ringing
 * of 1e3 position tolerances for good. CVODE's stability limit detection
 * sees it and lowers the order, which CVODE raises again a few steps
 * later: 26 097 such reductions in 666 064 steps for 0.47 s of a box
 * resting on a box, ringing at 4e-7 m/s (1.5e-12 m) to the end. Once they
 * number RC_STALD_REDS and RC_STALD_FRAC of the steps since the last
 * restart, and a damped contact is closed, the integrator restarts at
 * (t, y) with the order at most 2 (A-stable) until the next restart
 * (docs/theory.md 7.7); the box then rings down with its damper and rests
 * (37 491 steps). Without a damped contact the vibration is the model's
 * own, and order 2 only follows it at more steps (a resting column of
 * undamped balls 1 km from the origin: 14 430 steps against 6 131).
 * stald_check decides after a step; stald_apply restarts at the next call. */
static void stald_check(run_ctx *c)
{
    long nor = 0, nst = 0;
    if (c->stald_low || c->stald_due || c->sens || c->m->max_order <= 2 ||
        CVodeGetNumStabLimOrderReds(c->cv, &nor) != CV_SUCCESS || CVodeGetNumSteps(c->cv, &nst) != CV_SUCCESS ||
        nor < RC_STALD_REDS || (double)nor < RC_STALD_FRAC * (double)nst)
        return;
    int damped = 0;
    for (int i = 0; i < c->m->ninter && !damped; i++)
        damped = c->d->inter_mode[i] == RC_MODE_CLOSED && !rc_inter_undamped(c->m, i);
    c->stald_due = damped;
}

/* The restart stald_check asked for, at the start of the next call, from
 * where the last one returned (t_last, y): the driver has used the
 * interpolant of the last step in between (output times and impact samples
 * inside that step; a restart right after the step lost it, and an output
 * time inside the step then failed with CV_BAD_T). A restart of the
 * driver's own in between cancels it (cv_restart). */
static int stald_apply(run_ctx *c)
{
    c->stald_due = 0;
    double hu = 0.0; /* the last step (no step taken since stald_check) */
    if (CVodeGetLastStep(c->cv, &hu) != CV_SUCCESS) hu = 0.0;
    add_stats(c->cv, &c->lost);
    c->stald_low = 1;
    int flag = CVodeSetMaxOrd(c->cv, 2);
    if (flag >= 0 && c->m->h0 <= 0) { /* from the last step (/SOLVER H0 stands where given) */
        flag = CVodeSetInitStep(c->cv, hu);
        c->own_h0 = hu > 0;
    }
    return flag < 0 ? flag : CVodeReInit(c->cv, c->t_last, c->y);
}

/* After modes changed without a restart (cv_continued), one internal step
 * with a forced linear solver setup and a new Jacobian: a stale Jacobian of
 * the old mode (a contact stiffness that is gone, a viscous friction term
 * that saturated) can make Newton's first small correction pass the
 * convergence test with a wrong solution. */
static int cv_solve(void *self, double tout, double *t, int *one_step)
{
    run_ctx *c = self;
    long nst_before = 0, nst_after = 0;
    int flag;
    if (c->expl) {
        int back = 0;
        flag = erk_solve(c, tout, t, *one_step, &back);
        if (!back || flag < 0) return flag;
    }
    if (c->stald_due && (flag = stald_apply(c)) < 0) return flag;
    *one_step = *one_step || c->fresh;
    if (c->fresh) {
        if ((flag = CVodeSetLSetupFrequency(c->cv, 1)) < 0 || (flag = CVodeSetJacEvalFrequency(c->cv, 1)) < 0)
            return flag;
        CVodeGetNumSteps(c->cv, &nst_before);
    }
    flag = CVode(c->cv, tout, c->y, t, *one_step ? CV_ONE_STEP : CV_NORMAL);
    /* the first step after a restart failed from h_restart (a state whose
     * error weights ask for a far smaller step than the contact scales,
     * restart_step): once more from the same state with CVODE's estimate */
    long nst = 0;
    if ((flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE) && c->own_h0 &&
        CVodeGetNumSteps(c->cv, &nst) == CV_SUCCESS && nst == 0) {
        double t0 = 0.0;
        add_stats(c->cv, &c->lost);
        c->own_h0 = 0;
        if ((flag = CVodeGetCurrentTime(c->cv, &t0)) < 0 || (flag = CVodeSetInitStep(c->cv, 0.0)) < 0 ||
            (flag = CVodeReInit(c->cv, t0, c->y)) < 0)
            return flag;
        flag = CVode(c->cv, tout, c->y, t, *one_step ? CV_ONE_STEP : CV_NORMAL);
    }
    if (c->own_h0 && CVodeGetNumSteps(c->cv, &nst) == CV_SUCCESS && nst > 0) c->own_h0 = 0;
    scatter_state(c);
    c->t_last = *t;
    if (c->sw && flag >= 0) {
        double hu = 0.0;
        if (CVodeGetLastStep(c->cv, &hu) == CV_SUCCESS && hu > c->hmax_bdf) c->hmax_bdf = hu;
    }
    /* right after a root return, a single-step call may only hand back the
     * rest of the step already taken: keep the forced setup until a new
     * step has been taken */
    if (c->fresh && CVodeGetNumSteps(c->cv, &nst_after) == CV_SUCCESS && nst_after > nst_before) {
        int f2;
        if ((f2 = CVodeSetLSetupFrequency(c->cv, 0)) < 0 || (f2 = CVodeSetJacEvalFrequency(c->cv, 0)) < 0)
            return f2;
        c->fresh = 0;
    }
    if ((flag == CV_SUCCESS || flag == CV_TSTOP_RETURN) && !c->fresh) stald_check(c);
    return flag;
}

static int cv_dky(void *self, double t, int k, int slot, const double **out)
{
    run_ctx *c = self;
    N_Vector v = slot == RC_BK_SAMPLE ? c->ysamp : c->ytn;
    int flag = c->expl ? ERKStepGetDky(c->erk, t, k, v) : CVodeGetDky(c->cv, t, k, v);
    /* the whole state: the constant states at their values, their
     * derivatives 0 */
    *out = whole(c, v, k > 0 ? c->dyf : slot == RC_BK_SAMPLE ? c->ysf : c->ytf);
    return flag;
}

static int cv_last_step(void *self, double *tn, double *hu)
{
    run_ctx *c = self;
    if (c->expl) {
        int flag = ERKStepGetCurrentTime(c->erk, tn);
        return flag < 0 ? flag : ERKStepGetLastStep(c->erk, hu);
    }
    int flag = CVodeGetCurrentTime(c->cv, tn);
    return flag < 0 ? flag : CVodeGetLastStep(c->cv, hu);
}

/* roots and directions in the engine's full layout (integrator.h rc_rootmap) */
static int cv_root_info(void *self, int *roots)
{
    run_ctx *c = self;
    int *r = rc_rootmap_info(&c->rm, roots);
    int flag = c->expl ? ERKStepGetRootInfo(c->erk, r) : CVodeGetRootInfo(c->cv, r);
    if (flag == CV_SUCCESS) rc_rootmap_found(&c->rm, roots);
    return flag;
}
static int cv_set_root_dirs(void *self, int *dir)
{
    run_ctx *c = self;
    const int *dv = rc_rootmap_dirs(&c->rm, dir);
    memcpy(c->dirs, dv, (size_t)c->rm.n * sizeof(int)); /* kept for a switch */
    c->dirs_set = 1;
    return c->expl ? ERKStepSetRootDirection(c->erk, c->dirs) : CVodeSetRootDirection(c->cv, c->dirs);
}
static int cv_set_stop_time(void *self, double tstop)
{
    run_ctx *c = self;
    c->tstop = tstop;
    c->tstop_set = 1;
    return c->expl ? ERKStepSetStopTime(c->erk, tstop) : CVodeSetStopTime(c->cv, tstop);
}

static int cv_restart(void *self, double t, int at_breakpoint)
{
    run_ctx *c = self;
    if (at_breakpoint) c->jac_patched = 0; /* the imposed rows change: a whole new Jacobian */
    c->stald_low = 0; /* the deck's order again (below) */
    c->stald_due = 0;
    const int turned = c->d->fric_turned; /* a fric_turn among the events: below */
    const int multi = c->d->multi_closed; /* a damped contact of several points closed: below */
    c->d->fric_turned = 0;
    c->d->multi_closed = 0;
    gather_state(c);
    c->t_last = t;
    if (c->expl) {
        /* the explicit method goes on from the event, at its last step or
         * half the critical step of the modes the event set, when less (a
         * contact that closed, a friction that began to slip: the step
         * the explicit method had reached for the old modes is unstable
         * on the new ones) */
        normalise_quats(c);
        const double hc = rc_explicit_step(c->m, c->d, t, c->yfull, c->hwork);
        if (isfinite(hc) && 0.5 * hc < c->h_erk) c->h_erk = 0.5 * hc;
        return erk_start(c, t, c->h_erk);
    }
    if (c->sw) {
        /* BDF pinned near the explicit stability limit: the explicit method
         * goes on from here */
        double hu = 0.0;
        if (CVodeGetLastStep(c->cv, &hu) != CV_SUCCESS) hu = 0.0;
        const double hb = fmax(hu, c->hmax_bdf), hc = rc_explicit_step(c->m, c->d, t, c->yfull, c->hwork);
        c->hmax_bdf = 0.0;
        if (isfinite(hc) && hb > 0 && hb <= RC_SW_PIN * hc) {
            normalise_quats(c);
            c->h_erk = 0.5 * hc;
            const int flag = erk_start(c, t, c->h_erk);
            if (flag >= 0) {
                c->sw_kind = RC_EV_METHOD_EXPLICIT;
                c->sw_t = t;
            }
            return flag;
        }
    }
    /* the first step: /SOLVER H0 when given (set once, cv_start), else from
     * the last accepted step and the contact scales (restart_step) */
    if (c->m->h0 <= 0) {
        double hu = 0.0;
        if (CVodeGetLastStep(c->cv, &hu) != CV_SUCCESS || !(hu > 0)) hu = c->h_restart;
        c->h_restart = rc_bk_restart_step(c->m, t, hu);
        const int flag = CVodeSetInitStep(c->cv, c->h_restart);
        if (flag < 0) return flag;
        c->own_h0 = c->h_restart > 0;
    }
    /* after a fric_turn the turned state reloads towards its limit at
     * K_t |v_t| / L_r (1e13 1/s with a stiff wall line), a rate the steps
     * soon exceed several times over; BDF orders above 2 are not A-stable,
     * and with the steps growing out of the restart an order-3 step carried
     * such a state through zero along the sliding, within its tolerance
     * (the force of the coordinates' rounding, a third of a small limit):
     * the slip root crossed again, turn after turn (200 within 3e-10 s,
     * Zeno). Until the next restart the order stays at most 2 (A-stable);
     * the deck's Max_order again at the next restart without a turn
     * (docs/theory.md 3.5) */
    int qmax = c->m->max_order;
    if (multi && qmax > RC_MULTI_MAX_ORDER) qmax = RC_MULTI_MAX_ORDER;
    /* a lightly damped contact whose events crowded (inter_lowq): order 3
     * and above amplify its vibration at the steps its tolerance allows
     * once the vibration is small, and the amplified vibration changed its
     * modes every period or two for good (opened and reclosed it, or its
     * friction stuck and slipped); order 2 (A-stable) while it stays
     * closed (docs/theory.md 7.7) */
    for (int i = 0; i < c->m->ninter && qmax > RC_LOWQ_MAX_ORDER; i++)
        if (c->d->inter_lowq[i] && c->d->inter_mode[i] == RC_MODE_CLOSED) qmax = RC_LOWQ_MAX_ORDER;
    if (turned && qmax > RC_TURN_MAX_ORDER) qmax = RC_TURN_MAX_ORDER;
    const int fq = CVodeSetMaxOrd(c->cv, qmax);
    if (fq < 0) return fq;
    return CVodeReInit(c->cv, t, c->y);
}

/* CVODE's counters (they restart at every ReInit) into the totals; the
 * Jacobian evaluations are the whole ones (CVODE also counts the setups
 * that used jsave with the blocks refreshed after an event, cb_linsys). */
static void cv_add_stats(void *self, rc_stats *s)
{
    run_ctx *c = self;
    if (c->expl) erk_stats(c, s);
    else if (c->cv) add_stats(c->cv, s);
    s->steps += c->lost.steps;
    s->steps_explicit += c->lost.steps_explicit;
    s->rhs_evals += c->lost.rhs_evals;
    s->lin_setups += c->lost.lin_setups;
    s->nonlin_iters += c->lost.nonlin_iters;
    s->nonlin_fails += c->lost.nonlin_fails;
    s->err_test_fails += c->lost.err_test_fails;
    s->root_evals += c->lost.root_evals;
    memset(&c->lost, 0, sizeof c->lost);
    if (c->d) {
        s->jac_evals = c->d->sc->n_jac;
        c->d->n_klu_sym = rc_actpart_analyses(&c->ap);
        c->d->newton_nnz = (long)c->ap.nnz_max;
    }
}

static long cv_steps(void *self)
{
    run_ctx *c = self;
    long nst = 0;
    if (c->expl) {
        ERKStepGetNumSteps(c->erk, &nst);
        return nst - c->erk_seen[0];
    }
    CVodeGetNumSteps(c->cv, &nst);
    return nst;
}

static void cv_failure(void *self, int flag, double t, double tout, char *buf, size_t n)
{
    run_ctx *c = self;
    if (c->expl) {
        erk_failure(c, flag, t, tout, buf, n);
        return;
    }
    failure_advice(c->m, c->d, c->cv, flag, t, tout, c->cvmsg, c->ytn, c->f0, c->kidx, buf, n);
}

static const char *cv_last_msg(void *self) { return ((run_ctx *)self)->cvmsg; }

static void cv_before_events(void *self)
{
    run_ctx *c = self;
    const size_t ni = (size_t)c->m->ninter * sizeof(int);
    memcpy(c->old_mode, c->d->inter_mode, ni);
    memcpy(c->old_branch, c->d->inter_branch, ni);
    memcpy(c->old_track, c->d->inter_track, ni);
    memcpy(c->old_slip, c->d->inter_slip, ni);
    if (c->m->npt > 0) memcpy(c->old_pslip, c->d->pt_slip, (size_t)c->m->npt * sizeof(int));
}

/* The Jacobian blocks of the interfaces whose modes changed, refreshed at
 * the event state (cb_linsys); a restart only when the right-hand side
 * jumps (needs_restart). */
static int cv_after_events(void *self, double t, const double *y, int cpl_ev, int restart)
{
    run_ctx *c = self;
    const rc_model *m = c->m;
    rc_data *d = c->d;
    int ok = 1, changed = 0;
    /* the interfaces closed from open (by the implicit method), until they
     * open (loads_moved): modes change only at events */
    for (int i = 0; i < m->ninter; i++)
        c->jland[i] = d->inter_mode[i] == RC_MODE_CLOSED &&
                      (c->jland[i] || (!c->expl && c->old_mode[i] == RC_MODE_OPEN));
    if (c->expl) { /* no Jacobian; a one-step method restarts from the event */
        c->jac_patched = 0;
        return 1;
    }
    for (int i = 0; ok && i < m->ninter; i++) {
        const int npt = m->inter_npt[i], *op = c->old_pslip + m->inter_pbase[i];
        const int same = d->inter_mode[i] == c->old_mode[i] && d->inter_branch[i] == c->old_branch[i] &&
                         d->inter_track[i] == c->old_track[i];
        int pflip = 0;
        for (int j = 0; j < npt && !pflip; j++) pflip = d->pt_slip[m->inter_pbase[i] + j] != op[j];
        if (npt > 0 && same && !m->inter_fr[i].exact) {
            /* contact points: their interface-level slip flag is only a
             * report (the points carry their own modes); the points that
             * flipped are refreshed (rc_jac_refresh_points) */
            if (pflip) {
                changed = 1;
                ok = rc_jac_refresh_points(m, d, i, op, y, c->jsave) == 0;
            }
        } else if (!same || d->inter_slip[i] != c->old_slip[i] || pflip) {
            changed = 1;
            ok = rc_jac_refresh_inter(m, d, i, y, c->jsave) == 0;
        }
    }
    /* coupling blocks are not refreshed in place: a whole new Jacobian when
     * a contact coupling changed modes */
    c->jac_patched = ok && changed && !cpl_ev;
    return restart || needs_restart(c, t, y);
}

static void cv_continued(void *self) { ((run_ctx *)self)->fresh = 1; }

static void cv_close(void *self)
{
    run_ctx *c = self;
    CVodeFree(&c->cv);
    ERKStepFree(&c->erk);
    free(c->hwork);
    free(c->dirs);
    SUNLinSolFree(c->LS);
    SUNMatDestroy(c->A);
    N_VDestroy(c->y);
    N_VDestroy(c->av);
    N_VDestroy(c->f0);
    N_VDestroy(c->f1);
    N_VDestroy(c->ytn);
    N_VDestroy(c->ysamp);
    if (c->ysw) N_VDestroy(c->ysw);
    free(c->old_mode);
    free(c->old_branch);
    free(c->old_track);
    free(c->old_slip);
    free(c->old_pslip);
    free(c->jsave);
    free(c->jshare);
    free(c->jflim);
    free(c->jfnr);
    free(c->jland);
    if (c->d) c->d->jac_skip = NULL;
    free(c->cst);
    free(c->kidx);
    free(c->ridx);
    free(c->qoff);
    double *full[] = {c->yfull, c->ysc, c->fsc, c->ytf, c->dyf, c->ysf, c->fa, c->fb};
    for (size_t k = 0; k < sizeof full / sizeof full[0]; k++) free(full[k]);
    rc_actpart_close(&c->ap);
    rc_rootmap_free(&c->rm);
    SUNContext_Free(&c->ctx);
}

static const double *cv_roots_at(void *self, double t) { return rc_rootmap_at(&((run_ctx *)self)->rm, t); }

/* A method switch not yet reported: its kind (and *t), once. */
static rc_event_kind cv_switched(void *self, double *t)
{
    run_ctx *c = self;
    const rc_event_kind k = c->sw_kind;
    *t = c->sw_t;
    c->sw_kind = RC_EV_NONE;
    return k;
}

static const rc_backend cvode_backend = {
    .name = "CVODE", .prefix = "CVode", .root_return = CV_ROOT_RETURN, .tstop_return = CV_TSTOP_RETURN,
    .too_much_work = CV_TOO_MUCH_WORK, .open = cv_open, .start = cv_start, .solve = cv_solve, .dky = cv_dky,
    .last_step = cv_last_step, .root_info = cv_root_info, .set_root_dirs = cv_set_root_dirs,
    .set_stop_time = cv_set_stop_time, .restart = cv_restart, .add_stats = cv_add_stats, .steps = cv_steps,
    .failure = cv_failure, .flag_name = CVodeGetReturnFlagName, .last_msg = cv_last_msg,
    .record_vector = NULL, .before_events = cv_before_events, .after_events = cv_after_events,
    .continued = cv_continued, .close = cv_close, .roots_at = cv_roots_at, .switched = cv_switched};

static rc_status cvode_run(const rc_model *m, const rc_run_options *opt, rc_pause *pause, const rc_preload *pre,
                           rc_stats *stats, rc_error *err)
{
    run_ctx c;
    memset(&c, 0, sizeof c);
    return rc_drive(m, opt, pause, pre, stats, err, &cvode_backend, &c);
}

/* The backend of /SOLVER Method 1 (solver.h). */
const rc_solver rc_solver_cvode = {"cvode", RC_METHOD_CVODE, cvode_run};

void rc_cvode_versions(FILE *f)
{
    fprintf(f, "SUNDIALS %s\nKLU %d.%d.%d (%s)\n", SUNDIALS_VERSION, KLU_MAIN_VERSION, KLU_SUB_VERSION,
            KLU_SUBSUB_VERSION, KLU_DATE);
}

/* ---- for the sensitivity backend (sens.h) ------------------------------ */
const rc_backend *rc_cvode_backend(void) { return &cvode_backend; }
size_t rc_cvode_self_size(void) { return sizeof(run_ctx); }
void *rc_cvode_parts(void *self, int *nr, const int **kidx, double **yfull, void **sunctx)
{
    run_ctx *c = self;
    c->sw = 0; /* the sensitivities follow CVODE alone: no method switching, */
    c->sens = 1; /* no order held by a restart of cv_solve's own (stald_check) */
    *sunctx = c->ctx;
    *nr = c->nr;
    *kidx = c->kidx;
    *yfull = c->yfull;
    return c->cv;
}
