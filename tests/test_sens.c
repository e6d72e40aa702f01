/*
 * Forward sensitivities (rc_sens_run, src/solver/sens.c) against closed
 * forms and against central differences of whole runs (rc_case_load_set at
 * p -+ h): a free flight under gravity (dz/dg = t^2/2 exactly), a ball drop
 * through a TYPE6 impact (close and open events: d/d Visc, d/d the load
 * curve's scale, d/d gravity, whose event time moves), and a block sliding
 * to a stop on Coulomb friction (the stick event: the stopping distance
 * v0^2 / (2 mu g) and its derivatives in mu and v0), and repeated impacts
 * on a hysteresis law (events that set a history state). Each test prints the
 * worst relative difference it measured beside its tolerance.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "ricochet/ricochet.h"

#define DROP "validation/fit_drop/drop.rad"
#define SLIDE "validation/fit_drop/slide.rad"
#define BOUNCES "validation/t6_bounces/case.rad"
#define MAXP 4

/* A model of `deck` with fields `name[k]` at `val[k]` (card units). */
static rc_model *model_at(const char *deck, int np, const char *const *name, const double *val)
{
    char buf[MAXP][300];
    const char *set[MAXP];
    for (int k = 0; k < np; k++) {
        snprintf(buf[k], sizeof buf[k], "%s=%.17g", name[k], val[k]);
        set[k] = buf[k];
    }
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    if (rc_case_load_set(deck, set, np, &c, &e) || rc_model_compile(c, &m, &e)) {
        fprintf(stderr, "  %s\n", e.msg);
        m = NULL;
    }
    rc_case_free(c);
    return m;
}

/* Parameter j perturbed by f (a factor) */
static rc_model *model_pert(const char *deck, int np, const char *const *name, const double *val, int j, double f)
{
    double v[MAXP];
    memcpy(v, val, (size_t)np * sizeof(double));
    v[j] *= f;
    return model_at(deck, np, name, v);
}

/* Body 1's quantity `slot` (rc_model_body_state: 0..2 position, 7..9
 * velocity) at y, and its derivative along s. */
static double body_q(const rc_model *m, const double *y, int slot)
{
    double b[13];
    rc_model_body_state(m, y, 1, b, NULL);
    return b[slot];
}
static double body_dq(const rc_model *m, const double *y, const double *s, int slot)
{
    const int ny = rc_model_state_size(m);
    double *a = malloc((size_t)ny * sizeof(double)), *b = malloc((size_t)ny * sizeof(double));
    /* a step of 1e-7 of the state's size along s */
    double smax = 0.0, ymax = 1.0;
    for (int k = 0; k < ny; k++) {
        smax = fmax(smax, fabs(s[k]));
        ymax = fmax(ymax, fabs(y[k]));
    }
    if (!(smax > 0)) {
        free(a);
        free(b);
        return 0.0;
    }
    const double e = 1e-7 * ymax / smax;
    for (int k = 0; k < ny; k++) {
        a[k] = y[k] + e * s[k];
        b[k] = y[k] - e * s[k];
    }
    const double d = (body_q(m, a, slot) - body_q(m, b, slot)) / (2 * e);
    free(a);
    free(b);
    return d;
}

/* The events of the next sens_of (NULL: none). */
static rc_sens_events *sens_ev;

/* Sensitivities of body 1's `nslot` quantities at the times: ds[(i np + j)
 * nslot + q]; 0 or -1. */
static int sens_of(const char *deck, int np, const char *const *name, const double *val, int nt, const double *t,
                   int nslot, const int *slot, double *out, double *ds, rc_sens_info *info)
{
    rc_model *m = model_at(deck, np, name, val), *lo[MAXP] = {0}, *hi[MAXP] = {0};
    double dp[MAXP];
    const double h = 1e-4;
    int bad = !m;
    for (int j = 0; j < np && !bad; j++) {
        lo[j] = model_pert(deck, np, name, val, j, 1 - h);
        hi[j] = model_pert(deck, np, name, val, j, 1 + h);
        dp[j] = val[j] * (1 + h) - val[j] * (1 - h);
        bad = !lo[j] || !hi[j];
    }
    if (!bad) {
        const int ny = rc_model_state_size(m);
        double *y = malloc((size_t)nt * (size_t)ny * sizeof(double));
        double *s = malloc((size_t)nt * (size_t)np * (size_t)ny * sizeof(double));
        rc_error e;
        rc_status st = rc_sens_run(m, np, (const rc_model *const *)lo, (const rc_model *const *)hi, val, dp, nt, t, y, s,
                                   info, sens_ev, NULL, &e);
        if (st) {
            fprintf(stderr, "  rc_sens_run: %s\n", e.msg);
            bad = 1;
        }
        for (int i = 0; i < nt && !bad; i++)
            for (int q = 0; q < nslot; q++) {
                out[i * nslot + q] = body_q(m, y + (size_t)i * (size_t)ny, slot[q]);
                for (int j = 0; j < np; j++)
                    ds[(i * np + j) * nslot + q] = body_dq(m, y + (size_t)i * (size_t)ny,
                                                           s + ((size_t)i * (size_t)np + (size_t)j) * (size_t)ny, slot[q]);
            }
        free(y);
        free(s);
    }
    rc_model_free(m);
    for (int j = 0; j < np; j++) {
        rc_model_free(lo[j]);
        rc_model_free(hi[j]);
    }
    return bad ? -1 : 0;
}

/* Body 1's quantities at the times of a whole run of model m. */
static int run_q(rc_model *m, int nt, const double *t, int nslot, const int *slot, double *out)
{
    rc_run_options opt;
    memset(&opt, 0, sizeof opt);
    opt.t_end_override = t[nt - 1];
    rc_session *s = NULL;
    rc_error e;
    rc_status st = rc_session_open(m, &opt, &s, &e);
    for (int i = 0; i < nt && !st; i++) {
        st = rc_run_until(s, t[i], &e);
        for (int q = 0; q < nslot && !st; q++) out[i * nslot + q] = body_q(m, rc_session_state(s), slot[q]);
    }
    if (s) rc_session_close(s, NULL, NULL);
    return st ? -1 : 0;
}

/* Central differences of whole runs, relative step h: fd[(i np + j) nslot + q]. */
static int fd_of(const char *deck, int np, const char *const *name, const double *val, int nt, const double *t,
                 int nslot, const int *slot, double h, double *fd)
{
    double a[64], b[64];
    for (int j = 0; j < np; j++) {
        rc_model *lo = model_pert(deck, np, name, val, j, 1 - h), *hi = model_pert(deck, np, name, val, j, 1 + h);
        const int bad = !lo || !hi || run_q(lo, nt, t, nslot, slot, a) || run_q(hi, nt, t, nslot, slot, b);
        rc_model_free(lo);
        rc_model_free(hi);
        if (bad) return -1;
        for (int i = 0; i < nt; i++)
            for (int q = 0; q < nslot; q++)
                fd[(i * np + j) * nslot + q] = (b[i * nslot + q] - a[i * nslot + q]) / (2 * h * val[j]);
    }
    return 0;
}

/* (a) Free flight before the impact: z = z0 + g t^2 / 2, vz = g t; the
 * damping of the contact not yet touched has no effect (exactly 0). */
static void test_sens_free_flight_closed_form(void)
{
    const char *name[2] = {"/GRAV/1:Fscale_y", "/INTER/TYPE6/1:Visc"};
    const double val[2] = {-9.81, 30.0}, t[2] = {0.0371, 0.2};
    const int slot[2] = {2, 9};
    double out[4], ds[8];
    rc_sens_info info;
    ENSURE(sens_of(DROP, 2, name, val, 2, t, 2, slot, out, ds, &info) == 0);
    double worst = 0;
    for (int i = 0; i < 2; i++) {
        const double dz = ds[(i * 2 + 0) * 2 + 0], dv = ds[(i * 2 + 0) * 2 + 1];
        ENSURE_NEAR(dz, 0.5 * t[i] * t[i], 1e-6, 0);
        ENSURE_NEAR(dv, t[i], 1e-6, 0);
        ENSURE_NEAR(ds[(i * 2 + 1) * 2 + 0], 0.0, 0, 1e-15);
        ENSURE_NEAR(ds[(i * 2 + 1) * 2 + 1], 0.0, 0, 1e-15);
        worst = fmax(worst, fmax(fabs(dz / (0.5 * t[i] * t[i]) - 1), fabs(dv / t[i] - 1)));
    }
    ENSURE(info.jumps == 0);
    printf("  free flight: dz/dg, dvz/dg against t^2/2, t: worst relative difference %.2g (tolerance 1e-6)\n", worst);
}

/* (b) A ball drop through its impact on a TYPE6 linear contact with
 * damping (close and open events): the rebound's position and velocity
 * against central differences of whole runs (relative step 1e-3). */
static void test_sens_drop_impact_matches_fd(void)
{
    const char *name[3] = {"/INTER/TYPE6/1:Visc", "/INTER/TYPE6/1:FscaleId", "/GRAV/1:Fscale_y"};
    const double val[3] = {30.0, 20000.0, -9.81}, t[2] = {0.3, 0.5};
    const int slot[2] = {2, 9};
    double out[4], ds[12], fd[12];
    rc_sens_info info;
    ENSURE(sens_of(DROP, 3, name, val, 2, t, 2, slot, out, ds, &info) == 0);
    ENSURE(fd_of(DROP, 3, name, val, 2, t, 2, slot, 1e-3, fd) == 0);
    double worst = 0;
    for (int k = 0; k < 12; k++) {
        ENSURE_NEAR(ds[k], fd[k], 1e-4, 0);
        worst = fmax(worst, fabs(ds[k] - fd[k]) / fabs(fd[k]));
    }
    ENSURE(info.jumps >= 2); /* the close and the open */
    ENSURE(info.resets == 0);
    printf("  drop through a TYPE6 impact (%ld events): d(z, vz)/d(Visc, FscaleId, g) at 0.3 s and 0.5 s against "
           "whole runs: worst relative difference %.2g (tolerance 1e-4: the whole runs' own integration errors over their step)\n", info.jumps, worst);
}

/* (c) A block sliding to a stop on Coulomb friction (mu 0.3, v0 1 m/s):
 * the stopping distance v0^2 / (2 mu g), d/d mu = -v0^2 / (2 mu^2 g),
 * d/d v0 = v0 / (mu g), through the slip-to-stick event, against the
 * closed form (the stick spring's regularisation: 2e-5) and against whole
 * runs. */
static void test_sens_slide_stop_distance(void)
{
    const char *name[2] = {"/INTER/TYPE6/1:Fric", "/INIVEL/TRA/1:Vx"};
    const double val[2] = {0.3, 1.0}, t[1] = {0.5}, g = 9.81;
    const int slot[1] = {0};
    double out[1], ds[2], fd[2];
    rc_sens_info info;
    ENSURE(sens_of(SLIDE, 2, name, val, 1, t, 1, slot, out, ds, &info) == 0);
    ENSURE(fd_of(SLIDE, 2, name, val, 1, t, 1, slot, 1e-3, fd) == 0);
    const double dmu = -1.0 / (2 * 0.09 * g), dv0 = 1.0 / (0.3 * g);
    ENSURE_NEAR(ds[0], dmu, 1e-4, 0);
    ENSURE_NEAR(ds[1], dv0, 1e-4, 0);
    ENSURE_NEAR(ds[0], fd[0], 1e-5, 0);
    ENSURE_NEAR(ds[1], fd[1], 1e-5, 0);
    ENSURE(info.jumps >= 1);
    printf("  slide to a stop: d(stop)/d mu %.9g (closed form %.9g, whole runs %.9g), d(stop)/d v0 %.9g (closed form "
           "%.9g, whole runs %.9g)\n", ds[0], dmu, fd[0], ds[1], dv0, fd[1]);
}

/* (d) Repeated impacts on an Iform 1 hysteresis law (tabulated load and
 * unload curves, Stiff 1e7 N/m): the branch changes reset the hysteresis
 * state, so the jump includes the derivative of the events' state map;
 * d z/d Stiff after the first and the second impact against whole runs. */
static void test_sens_hysteresis_impacts_match_fd(void)
{
    const char *name[1] = {"/INTER/TYPE6/1:Stiff"};
    const double val[1] = {1e7}, t[3] = {0.2, 0.3, 0.5};
    const int slot[1] = {2};
    double out[3], ds[3], fd[3];
    rc_sens_info info;
    ENSURE(sens_of(BOUNCES, 1, name, val, 3, t, 1, slot, out, ds, &info) == 0);
    ENSURE(fd_of(BOUNCES, 1, name, val, 3, t, 1, slot, 1e-3, fd) == 0);
    double worst = 0;
    for (int k = 0; k < 3; k++) {
        ENSURE_NEAR(ds[k], fd[k], 5e-4, 0);
        worst = fmax(worst, fabs(ds[k] - fd[k]) / fabs(fd[k]));
    }
    ENSURE(info.resets >= 2);
    printf("  Iform 1 hysteresis, two impacts (%ld events, %ld setting the hysteresis state): d z/d Stiff at 0.2, "
           "0.3, 0.5 s against whole runs: worst relative difference %.2g (tolerance 5e-4)\n", info.jumps, info.resets,
           worst);
}

/* The first impact's close time, duration, approach and separation
 * speeds of a whole run (rc_stats.impact[0]) into q[4]; 0 or -1. */
static int impact_q(rc_model *m, double *q)
{
    rc_stats st;
    rc_error e;
    if (!m || rc_run(m, NULL, &st, &e) || st.impacts < 1) return -1;
    q[0] = st.impact[0].t_close;
    q[1] = st.impact[0].duration;
    q[2] = st.impact[0].v_in;
    q[3] = st.impact[0].v_out;
    return 0;
}

/* The damped oscillator of the drop's contact: P about m g / k from P = 0
 * at the approach speed, P(t) = ps + exp(-a t) (A cos wd t + B sin wd t);
 * P and dP/dt at t. */
typedef struct {
    double a, wd, ps, A, B;
} drop_osc;

static void drop_osc_at(const drop_osc *o, double t, double *p, double *dp)
{
    const double e = exp(-o->a * t), c = cos(o->wd * t), s = sin(o->wd * t);
    *p = o->ps + e * (o->A * c + o->B * s);
    *dp = e * (-o->a * (o->A * c + o->B * s) + o->wd * (o->B * c - o->A * s));
}

/* The drop's impact in closed form (DROP: 1 kg from a gap of h = 0.25 m at
 * rest onto the linear law F = k P + c dP/dt): the close time sqrt(2 h / g),
 * the approach speed sqrt(2 g h), the duration to the release of the force
 * (F = 0, the damped oscillator about m g / k from P = 0 at that speed) and
 * the speed at the separation (P = 0 after a flight under g from the
 * release). q: t_close [s], duration [s], v_in [m/s], v_out [m/s]. */
static void drop_closed_form(double k, double c, double g, double *q)
{
    const double m = 1.0, h = 0.25, vin = sqrt(2.0 * g * h), a = c / (2.0 * m), ps = m * g / k;
    const double wd = sqrt(k / m - a * a);
    const drop_osc o = {a, wd, ps, -ps, (vin - a * ps) / wd};
    double p = 0.0, dp = 0.0;
    /* the first release after the close: bracketed on a grid of 1e-5 s
     * (F = c v_in > 0 at the close), then halved to the last bit */
    double lo = 0.0, hi = 1e-5;
    for (;; lo = hi, hi += 1e-5) {
        drop_osc_at(&o, hi, &p, &dp);
        if (k * p + c * dp <= 0.0) break;
    }
    for (int it = 0; it < 200 && hi - lo > 0.0; it++) {
        const double mid = 0.5 * (lo + hi);
        drop_osc_at(&o, mid, &p, &dp);
        if (k * p + c * dp > 0.0) lo = mid;
        else hi = mid;
    }
    drop_osc_at(&o, hi, &p, &dp);
    q[0] = sqrt(2.0 * h / g);
    q[1] = hi;
    q[2] = vin;
    q[3] = sqrt(dp * dp - 2.0 * g * p); /* m p'' = m g in the flight, from (p, dp) to P = 0 */
}

/* (e) Impact quantities from the events' derivatives: the drop's close
 * time, contact duration (to the release of the force), approach speed and
 * rebound (separation) speed in Visc, FscaleId and g, against central
 * differences of the closed form (drop_closed_form) to 1e-5, and of the
 * whole runs' impacts tables to 1e-3 (the difference of two runs'
 * durations, 5e-7 s for g, is known to the runs' event times only: 1e-4 of
 * it). */
static void test_sens_impact_quantities_match_fd(void)
{
    const char *name[3] = {"/INTER/TYPE6/1:Visc", "/INTER/TYPE6/1:FscaleId", "/GRAV/1:Fscale_y"};
    const double val[3] = {30.0, 20000.0, -9.81}, t[1] = {0.3};
    const int slot[1] = {9};
    enum { MAXE = 16 };
    double et[MAXE], edt[MAXE * 3], evn[MAXE], edvn[MAXE * 3], out[1], ds[3];
    int eid[MAXE];
    const char *ekind[MAXE];
    rc_sens_events ev = {MAXE, 0, 0, et, eid, ekind, edt, evn, edvn, NULL, NULL};
    rc_sens_info info;
    sens_ev = &ev;
    ENSURE(sens_of(DROP, 3, name, val, 1, t, 1, slot, out, ds, &info) == 0);
    sens_ev = NULL;
    int kc = -1, ko = -1, ks = -1;
    for (int k = 0; k < ev.n; k++) {
        if (!strcmp(ev.kind[k], "contact_close") && kc < 0) kc = k;
        if (!strcmp(ev.kind[k], "contact_open") && ko < 0) ko = k;
        if (!strcmp(ev.kind[k], "contact_separate") && ks < 0) ks = k;
    }
    ENSURE(kc >= 0 && ko > kc && ks > kc);
    if (kc < 0 || ko < 0 || ks < 0) return;
    ENSURE(ev.inter_id[kc] == 1);
    double worst = 0, worst_run = 0;
    const char *qn[4] = {"t_close", "duration", "v_in", "v_out"};
    for (int j = 0; j < 3; j++) {
        double qa[4], qb[4], ca[4], cb[4], pa[3] = {val[0], val[1], -val[2]}, pb[3] = {val[0], val[1], -val[2]};
        rc_model *lo = model_pert(DROP, 3, name, val, j, 1 - 1e-3), *hi = model_pert(DROP, 3, name, val, j, 1 + 1e-3);
        const int bad = impact_q(lo, qa) || impact_q(hi, qb);
        rc_model_free(lo);
        rc_model_free(hi);
        ENSURE(!bad);
        if (bad) return;
        /* the closed form in (c, k, g = -Fscale_y) at +- 1e-6 of the value */
        pa[j] *= 1 - 1e-6;
        pb[j] *= 1 + 1e-6;
        drop_closed_form(pa[1], pa[0], pa[2], ca);
        drop_closed_form(pb[1], pb[0], pb[2], cb);
        const double sens[4] = {ev.dtdp[kc * 3 + j], ev.dtdp[ko * 3 + j] - ev.dtdp[kc * 3 + j], ev.dvndp[kc * 3 + j],
                                -ev.dvndp[ks * 3 + j]};
        for (int q = 0; q < 4; q++) {
            const double fdq = (qb[q] - qa[q]) / (2e-3 * val[j]), cfq = (cb[q] - ca[q]) / (2e-6 * val[j]);
            /* a quantity that does not depend on the parameter (the
             * impact's start in the contact's own fields): 0 in all */
            if (fabs(cfq) < 1e-12) {
                ENSURE_NEAR(sens[q], 0.0, 0, 1e-12);
                ENSURE_NEAR(fdq, 0.0, 0, 1e-12);
                continue;
            }
            ENSURE_NEAR(sens[q], cfq, 1e-5, 0);
            ENSURE_NEAR(sens[q], fdq, 1e-3, 0);
            const double rd = fabs(sens[q] - cfq) / fabs(cfq), rr = fabs(sens[q] - fdq) / fabs(fdq);
            if (rd > worst) worst = rd;
            if (rr > worst_run) worst_run = rr;
            if (rd > 1e-5) printf("    %s d%s/d%s: %.9g vs %.9g (closed form)\n", qn[q], qn[q], name[j], sens[q], cfq);
        }
    }
    printf("  drop's impact: d(t_close, duration, v_in, v_out)/d(Visc, FscaleId, g): worst relative difference %.2g "
           "against the closed form (tolerance 1e-5), %.2g against the whole runs' impacts tables (1e-3)\n",
           worst, worst_run);
}

/* (f) A body held by an imposed velocity until Tstop = 0.2 s, then
 * falling: z = z0 - g (t - Tstop)^2 / 2, so dz/dTstop = g (t - Tstop) and
 * dvz/dTstop = g, and dz/dFscale_y = (t - Tstop)^2 / 2 (Fscale_y = -9.81);
 * the run restarts at the time breakpoint (no root). */
static void test_sens_imposed_velocity_release(void)
{
    const char *name[2] = {"/GRAV/1:Fscale_y", "/IMPVEL/1:Tstop"};
    const double val[2] = {-9.81, 0.2}, t[2] = {0.1, 0.3}, g = 9.81, dt = 0.3 - 0.2;
    const int slot[2] = {2, 9};
    double out[4], ds[8];
    rc_sens_info info;
    ENSURE(sens_of("validation/impvel_release/case.rad", 2, name, val, 2, t, 2, slot, out, ds, &info) == 0);
    /* held: nothing moves */
    for (int k = 0; k < 4; k++) ENSURE_NEAR(ds[k], 0.0, 0, 1e-12);
    ENSURE_NEAR(ds[(1 * 2 + 0) * 2 + 0], 0.5 * dt * dt, 1e-6, 0);
    ENSURE_NEAR(ds[(1 * 2 + 0) * 2 + 1], dt, 1e-6, 0);
    ENSURE_NEAR(ds[(1 * 2 + 1) * 2 + 0], g * dt, 1e-6, 0);
    ENSURE_NEAR(ds[(1 * 2 + 1) * 2 + 1], g, 1e-6, 0);
    printf("  release at Tstop: dz/dTstop %.9g (g (t - Tstop) = %.9g), dvz/dTstop %.9g (g)\n",
           ds[(1 * 2 + 1) * 2 + 0], g * dt, ds[(1 * 2 + 1) * 2 + 1]);
}

/* Input errors: no parameter, times not increasing, a parameter that
 * changes the model's structure, a deck on another backend. */
static void test_sens_errors(void)
{
    const char *name[1] = {"/INTER/TYPE6/1:Visc"};
    const double val[1] = {30.0};
    rc_model *m = model_at(DROP, 1, name, val);
    ENSURE(m != NULL);
    if (!m) return;
    const int ny = rc_model_state_size(m);
    double *y = calloc(2 * (size_t)ny, sizeof(double)), *s = calloc(2 * (size_t)ny, sizeof(double));
    const rc_model *mm[1] = {m};
    const double dp[1] = {1.0}, tbad[2] = {0.2, 0.1};
    rc_error e;
    ENSURE(rc_sens_run(m, 0, mm, mm, val, dp, 1, tbad, y, s, NULL, NULL, NULL, &e) == RC_EINPUT);
    ENSURE(rc_sens_run(m, 1, mm, mm, val, dp, 2, tbad, y, s, NULL, NULL, NULL, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "increasing") != NULL);
    rc_error e2;
    ENSURE(rc_model_set_method(m, 2, &e2) == RC_OK);
    ENSURE(rc_sens_run(m, 1, mm, mm, val, dp, 1, tbad, y, s, NULL, NULL, NULL, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "Method 1") != NULL);
    free(y);
    free(s);
    rc_model_free(m);
}

void suite_sens(void);
void suite_sens(void)
{
    RUN_TEST(test_sens_free_flight_closed_form);
    RUN_TEST(test_sens_drop_impact_matches_fd);
    RUN_TEST(test_sens_slide_stop_distance);
    RUN_TEST(test_sens_hysteresis_impacts_match_fd);
    RUN_TEST(test_sens_impact_quantities_match_fd);
    RUN_TEST(test_sens_imposed_velocity_release);
    RUN_TEST(test_sens_errors);
}
