/*
 * Power-law contact, step5 friction, cylinders, boxes and /IMPVEL (issue
 * 5): step5 continuity (values, first and second derivatives at the joints),
 * the regularised powers, the splines and the stored energy, the cards
 * (a full deck parsed, compiled and run; every error on purpose), and the
 * energy ledger of an imposed rotation. The Jacobian of all of it is checked
 * in test_engine.c (test_engine_jacobian_power_cylinders_impvel_...).
 */
#include <float.h>
#include <stdlib.h>
#include <unistd.h>

#include "case/case.h"
#include "case/case_power.h"
#include "model/imposed.h"
#include "model/model.h"
#include "model/power.h"
#include "engine/kernels/step5.h"
#include "engine/events/events.h"
#include "engine/assembly/assembly.h"
#include "testutil.h"
#include "base/error.h"
#include "harness.h"

/* ---- step5 ------------------------------------------------------------ */

/* The signed friction coefficient: mu(|v|) sign(v). */
static double mu_signed(double v, double mus, double vs, double mud, double vd)
{
    double m = rc_mu_step5_d(fabs(v), mus, vs, mud, vd);
    return v < 0 ? -m : m;
}

/* One-sided first and second derivatives at x from the left (dir = -1) or
 * the right (+1), second-order differences. */
static void one_sided(double (*f)(double, const double *), const double *p, double x, int dir, double h, double *d1,
                      double *d2)
{
    const double f0 = f(x, p), f1 = f(x + dir * h, p), f2 = f(x + 2 * dir * h, p), f3 = f(x + 3 * dir * h, p);
    *d1 = dir * (-3 * f0 + 4 * f1 - f2) / (2 * h);
    *d2 = (2 * f0 - 5 * f1 + 4 * f2 - f3) / (h * h);
}

static double cubic_fn(double x, const double *p)
{
    (void)p;
    return x <= 0 ? 0.0 : x >= 1 ? 1.0 : x * x * (3.0 - 2.0 * x);
}

static double mu_fn(double v, const double *p) { return mu_signed(v, p[0], p[1], p[2], p[3]); }

static void test_power_step5_is_c2(void)
{
    /* step5 itself: ends, middle, flat first and second derivatives */
    ENSURE_NEAR(rc_step5_d(-1.0, 0.3, 2.0, 1.7, 5.0), 2.0, 0, 0);
    ENSURE_NEAR(rc_step5_d(9.0, 0.3, 2.0, 1.7, 5.0), 5.0, 0, 0);
    ENSURE_NEAR(rc_step5_d(1.0, 0.3, 2.0, 1.7, 5.0), 3.5, 1e-15, 0);
    /* mu(v) of docs/theory.md 9, with mu_d below and above mu_s */
    const double sets[2][4] = {{0.37, 0.013, 0.21, 0.11}, {0.23, 0.07, 0.41, 0.9}};
    for (int s = 0; s < 2; s++) {
        const double *p = sets[s];
        const double mus = p[0], vs = p[1], mud = p[2], vd = p[3];
        ENSURE_NEAR(mu_fn(0.0, p), 0.0, 0, 0);
        ENSURE_NEAR(mu_fn(vs, p), mus, 1e-15, 0);
        ENSURE_NEAR(mu_fn(-vs, p), -mus, 1e-15, 0);
        ENSURE_NEAR(mu_fn(vd, p), mud, 1e-15, 0);
        ENSURE_NEAR(mu_fn(5 * vd, p), mud, 0, 0);
        ENSURE_NEAR(mu_fn(0.5 * vs, p), mus * rc_step5_d(0.5 * vs, -vs, -1.0, vs, 1.0), 1e-14, 0);
        /* the joints: -v_s, 0, v_s, v_d; values, slopes and curvatures agree
         * from both sides (C2); the differences are of order h */
        const double joints[4] = {-vs, 0.0, vs, vd};
        for (int j = 0; j < 4; j++) {
            const double x = joints[j], h = 1e-5 * vs;
            double l1, l2, r1, r2;
            one_sided(mu_fn, p, x, -1, h, &l1, &l2);
            one_sided(mu_fn, p, x, 1, h, &r1, &r2);
            const double s1 = mus / vs, s2 = mus / (vs * vs); /* natural scales */
            printf("    set %d, v = %+.4g: slope %+.6e | %+.6e, curvature %+.6e | %+.6e\n", s, x, l1, r1, l2, r2);
            ENSURE_NEAR(l1, r1, 0, 1e-6 * s1);
            ENSURE_NEAR(l2, r2, 0, 1e-3 * s2);
        }
        /* away from the joints mu is monotone between 0 and v_s */
        double prev = -1;
        for (int k = 0; k <= 100; k++) {
            double v = vs * k / 100.0, m = mu_fn(v, p);
            ENSURE(m >= prev);
            prev = m;
        }
    }
    /* the classical cubic step 3 D^2 - 2 D^3 is only C1: its curvature
     * jumps at the joint, which this test detects (a check of the test) */
    double l1, l2, r1, r2;
    one_sided(cubic_fn, NULL, 1.0, -1, 1e-5, &l1, &l2);
    one_sided(cubic_fn, NULL, 1.0, 1, 1e-5, &r1, &r2);
    ENSURE(fabs(l1 - r1) < 1e-6 && fabs(l2 - r2) > 1.0);
}

/* ---- regularised powers, splines, stored energy ------------------------ */

#define RE_D(x) (x)
RC_POWREG_DEFINE(double, RE_D, _t)

static void test_power_regularised_powers(void)
{
    /* C1 at x_r, odd, finite slope at 0 for m < 1 */
    const double ms[4] = {0.0, 0.37, 0.8, 1.5};
    for (int k = 0; k < 4; k++) {
        const double m = ms[k], xr = 3.1e-4, h = 1e-9;
        double lo = rc_powreg_t(xr - h, m, xr), hi = rc_powreg_t(xr + h, m, xr), at = rc_powreg_t(xr, m, xr);
        ENSURE_NEAR(at, pow(xr, m), 1e-14, 0);
        const double s0 = pow(xr, m - 1.0); /* natural slope scale */
        ENSURE_NEAR(lo, at, 0, 1e-5 * at);
        ENSURE_NEAR(hi, at, 0, 1e-5 * at);
        double sl = (at - rc_powreg_t(xr - 1e-8, m, xr)) / 1e-8, sr = (rc_powreg_t(xr + 1e-8, m, xr) - at) / 1e-8;
        ENSURE_NEAR(sl, sr, 0, 1e-4 * s0);
        ENSURE_NEAR(rc_powreg_slope(xr * 0.999999, m, xr), rc_powreg_slope(xr * 1.000001, m, xr), 0, 1e-5 * s0);
        ENSURE_NEAR(rc_powreg_t(-2.3e-4, m, xr), -rc_powreg_t(2.3e-4, m, xr), 0, 0);
        ENSURE(isfinite(rc_powreg_slope(0.0, m, xr)));
        /* positive on (0, x_r] and increasing */
        double prev = 0;
        for (int j = 1; j <= 50; j++) {
            double v = rc_powreg_t(xr * j / 50.0, m, xr);
            ENSURE(v > prev || m == 0.0);
            prev = v;
        }
    }
}

static void test_power_splines(void)
{
    const double x[6] = {0.0, 0.0011, 0.0023, 0.0041, 0.0063, 0.009}, y[6] = {0.0, 13.0, 61.0, 230.0, 710.0, 1900.0};
    rc_error e;
    for (int kind = RC_SPL_LINEAR; kind <= RC_SPL_STEFFEN; kind++) {
        rc_spline s;
        ENSURE(rc_spline_init(&s, kind, 7, 6, x, y, &e) == RC_OK);
        /* through the points; linear beyond the ends with the end slopes */
        for (int k = 0; k < 6; k++) {
            double f, df;
            rc_spline_eval(&s, x[k], &f, &df);
            ENSURE_NEAR(f, y[k], 1e-12, 1e-12);
        }
        double f0, d0, f1, d1;
        rc_spline_eval(&s, 0.012, &f1, &d1);
        rc_spline_eval(&s, 0.009, &f0, &d0);
        ENSURE_NEAR(f1, f0 + d0 * 0.003, 1e-12, 0);
        ENSURE_NEAR(d1, d0, 1e-12, 0);
        /* integral: GSL inside, exact outside, additive */
        double a = -0.001, b = 0.011, mid = 0.003, n = 20000, q = 0;
        for (int k = 0; k < n; k++) { /* midpoint rule */
            double f, df;
            rc_spline_eval(&s, a + (b - a) * (k + 0.5) / n, &f, &df);
            q += f * (b - a) / n;
        }
        ENSURE_NEAR(rc_spline_integral(&s, a, b), q, 1e-6, 0);
        ENSURE_NEAR(rc_spline_integral(&s, a, mid) + rc_spline_integral(&s, mid, b), rc_spline_integral(&s, a, b), 1e-13, 0);
        printf("    %-8s spline: integral %.9g (midpoint %.9g)\n", rc_spline_kind_name(kind), rc_spline_integral(&s, a, b), q);
        rc_spline_free(&s);
    }
    /* too few points for Akima */
    rc_spline s;
    ENSURE(rc_spline_init(&s, RC_SPL_AKIMA, 9, 3, x, y, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "/FUNCT/9") && strstr(e.msg, "akima"));
}

/* ---- cards: a deck parsed, compiled and run --------------------------- */

static char tdir[64];

static const char *write_deck(const char *name, const char *text)
{
    static char path[256];
    if (!tdir[0]) {
        snprintf(tdir, sizeof tdir, "/tmp/rc_power_test_XXXXXX");
        if (!mkdtemp(tdir)) return NULL;
    }
    snprintf(path, sizeof path, "%s/%s", tdir, name);
    FILE *f = fopen(path, "w");
    if (!f) return NULL;
    fputs(text, f);
    fclose(f);
    return path;
}

/* A roller (cylinder) pressed on a box by gravity, driven in rotation
 * about its own axis (Y), with power-law contact and step5 friction. */
static const char roller_deck[] =
    "/NODE\n1, 0, 0, 0.02001\n2, 0, 0, -0.025\n"
    "/RBODY/1\nroller\n1,,,,2.0\n4.5e-4, 8.0e-4, 4.5e-4\n0, 0, 0\n"
    "/RBODY/2\nblock\n2,,,,10.0\n0.01, 0.01, 0.01\n0, 0, 0\n"
    "/GRNOD/NODE/1\nroller\n1\n"
    "/GRNOD/NODE/2\nblock\n2\n"
    "/SURF/CYL/1\nroller\n1, 0, 0\n0, 0, 0.02001\n0, 1, 0\n0.02, 0.1\n"
    "/SURF/BOX/2\nblock\n2\n0, 0, -0.025\n0.2, 0.1, 0.025\n"
    "/FUNCT/1\nconstant\n0, 1\n10, 1\n"
    "/IMPVEL/1\nspin\n1, YY, 0, 0, 1, 0, 0\n0, 20\n"
    "/BCS/1\nblock held\n111 111, 0, 2\n"
    "/GRAV/1\ngravity\n0, Z, 0, 0, 0, , 1, -9.81\n"
    "/INTER/POWER/1\nroller on block\n1, 2\n1e8, 1.5, 1e4, 1, 1.5\n,\n0.3, 0.001, 0.2, 0.01\n"
    "/RUN\n0.05, 0.001\n"
    "/SOLVER\n1, 5, 100000, 1e-8\n1e-12, 1e-9, 1e-8, 1e-8\n1e-9\n";

static void test_power_roller_deck_runs_and_ledger_closes(void)
{
    const char *path = write_deck("roller.rad", roller_deck);
    ENSURE(path != NULL);
    if (!path) return;
    rc_case *c = NULL;
    rc_error e;
    rc_status st = rc_case_load(path, &c, &e);
    if (st) printf("    %s\n", e.msg);
    ENSURE(st == RC_OK);
    if (!c) return;
    ENSURE(c->npower == 1 && c->nimpvel == 1 && c->nsurf == 2);
    ENSURE(c->power[0].m3 == 1.5 && c->power[0].rdf == 0.001 && c->power[0].irdf == 1);
    ENSURE(c->impvel[0].dir == 4 && c->impvel[0].fscale == 20.0);
    rc_model *m = NULL;
    st = rc_model_compile(c, &m, &e);
    if (st) printf("    %s\n", e.msg);
    ENSURE(st == RC_OK);
    rc_case_free(c);
    if (!m) return;
    ENSURE(m->inter_pair[0] == RC_PAIR_CYL_BOX && m->inter_law[0] == RC_LAW_POWER);
    ENSURE(m->inter_fr[0].kind == RC_FK_STEP5);
    ENSURE(m->imp && m->imp->nr == 1 && m->imp->nt == 0);
    ENSURE_NEAR(m->body_y0[RC_NB * 0 + 11], 20.0, 0, 0); /* initial spin from the function */
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_run_options opt = {.y_end = y};
    rc_stats s;
    st = rc_run(m, &opt, &s, &e);
    if (st) printf("    %s\n", e.msg);
    ENSURE(st == RC_OK);
    /* the roller still spins at 20 rad/s about Y; slips on the held block;
     * the drive's work is in the ledger */
    const double *w = y + m->body_yadr[0] + 10;
    printf("    roller: omega = (%.3g, %.9g, %.3g) rad/s, W_imp = %.6g J, energy residual %.3g J\n", w[0], w[1], w[2],
           y[m->imp->wadr], s.energy_residual);
    ENSURE_NEAR(w[1], 20.0, 1e-8, 0);
    ENSURE_NEAR(w[0], 0.0, 0, 1e-8);
    ENSURE(y[m->imp->wadr] < 0.0); /* minus the work the drive did against friction */
    ENSURE_NEAR(s.energy_residual, 0.0, 0, 1e-6);
    free(y);
    rc_model_free(m);
}

/* ---- cards: errors ---------------------------------------------------- */

static void expect_error(const char *name, const char *text, int compile, const char *n1, const char *n2)
{
    const char *path = write_deck(name, text);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    rc_status st = rc_case_load(path, &c, &e);
    if (compile && st == RC_OK) {
        st = rc_model_compile(c, &m, &e);
        rc_model_free(m);
        rc_case_free(c);
    }
    const int ok = st == RC_EINPUT && strstr(e.msg, n1) && (!n2 || strstr(e.msg, n2));
    if (!ok) printf("    %s: status %d, message: %s\n", name, st, e.msg);
    ENSURE(ok);
}

#define BODY_DECK                                                                                   \
    "/NODE\n1,0,0,0.05\n/RBODY/1\nr\n1,,,,1.0\n1e-3,1e-3,1e-3\n0,0,0\n/GRNOD/NODE/1\ng\n1\n"          \
    "/SURF/PLANE/2\np\n0,0,0\n0,0,1\n/FUNCT/1\nf\n0,1\n1,1\n/RUN\n0.01\n"

static void test_power_card_errors(void)
{
    expect_error("k.rad", BODY_DECK "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n/INTER/POWER/1\nt\n1,2\n,1.5\n",
                 0, "field K", "K > 0");
    expect_error("vd.rad",
                 BODY_DECK "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n/INTER/POWER/1\nt\n1,2\n1e6\n\n0.3,0.01,0.2,0.005\n",
                 0, "field v_d", "v_d > v_s");
    expect_error("vs.rad", BODY_DECK "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n/INTER/POWER/1\nt\n1,2\n1e6\n\n0.3\n",
                 0, "field v_s", NULL);
    expect_error("irdf.rad", BODY_DECK "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n/INTER/POWER/1\nt\n1,2,0,0,0,3\n1e6\n",
                 0, "Irdf", NULL);
    expect_error("axis.rad", BODY_DECK "/SURF/CYL/1\nc\n1\n0,0,0.05\n0,0,0\n0.05,0.1\n", 0, "AX AY AZ", "non-zero");
    expect_error("radius.rad", BODY_DECK "/SURF/CYL/1\nc\n1\n0,0,0.05\n1,0,0\n0,0.1\n", 0, "field R", NULL);
    expect_error("boxv.rad", BODY_DECK "/SURF/BOX/3\nb\n1\n0,0,0\n1,1,1\n1,0,0\n2,0,0\n", 0, "VX VY VZ", "not parallel");
    expect_error("dir.rad", BODY_DECK "/IMPVEL/1\ni\n1,XY,0,0,1\n", 0, "field Dir", "XX, YY or ZZ");
    /* a later start: translations only (a rotation's would jump the angular velocity) */
    expect_error("tstart.rad", BODY_DECK "/IMPVEL/1\ni\n1,XX,0,0,1\n1,1,0.5\n", 0, "Tstart", "not supported yet");
    expect_error("tstart_static.rad", BODY_DECK "/SOLVER\n3\n/IMPVEL/1\ni\n1,X,0,0,1\n1,1,0.5\n", 1, "Tstart > 0",
                 "/SOLVER Method 3");
    {
        /* a skew axis that is a global one, the other way: that component, the scale negated */
        const char *path = write_deck("skew_global.rad", BODY_DECK "/SKEW/FIX/3\ns\n0,0,0\n0,0,-1\n1,0,0\n"
                                                         "/IMPVEL/1\ni\n1,Y,3,0,1\n1,2.5\n");
        rc_case *c = NULL;
        rc_model *m = NULL;
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_case_load(path, &c, &e) == RC_OK && rc_model_compile(c, &m, &e) == RC_OK);
        if (m) ENSURE(m->imp->nt == 1 && m->imp->tdir[0] == 2 && m->imp->tfscale[0] == -2.5 && m->imp->nsk == 0);
        else printf("    skew_global.rad: %s\n", e.msg);
        rc_model_free(m);
        rc_case_free(c);
    }
    {
        /* a translation with Tstart > 0 compiles: free before, from Tstart on imposed */
        const char *path = write_deck("tstart_ok.rad", BODY_DECK "/INIVEL/TRA/1\nv\n0,0,-0.3,1\n"
                                                       "/IMPVEL/1\ni\n1,Z,0,0,1\n1,2.5,0.004,0.007\n");
        rc_case *c = NULL;
        rc_model *m = NULL;
        rc_error e;
        rc_error_clear(&e);
        ENSURE(rc_case_load(path, &c, &e) == RC_OK && rc_model_compile(c, &m, &e) == RC_OK);
        if (m) {
            ENSURE(m->imp && m->imp->nt == 1 && m->imp->ttstart[0] == 0.004 && m->imp->ttstop[0] == 0.007);
            ENSURE(m->body_y0[9] == -0.3); /* the /INIVEL stands until Tstart */
        } else
            printf("    tstart_ok.rad: %s\n", e.msg);
        rc_model_free(m);
        rc_case_free(c);
    }
    /* skew_ID: translations along a /SKEW/FIX axis only, the body's only
     * imposed or held translation */
    expect_error("skew.rad", BODY_DECK "/IMPVEL/1\ni\n1,XX,3,0,1\n", 0, "skew_ID", "not supported yet");
    expect_error("skew_missing.rad", BODY_DECK "/IMPVEL/1\ni\n1,X,3,0,1\n", 1, "skew_ID", "no such skew");
#define SKEW3 "/NODE\n7,0,0,0\n8,1,1,0\n9,0,0,1\n/SKEW/FIX/3\ns\n0,0,0\n1,1,0\n0,0,1\n"
    expect_error("skew_mov.rad", BODY_DECK "/SKEW/MOV/3\ns\n7,8,9\n/NODE\n7,0,0,0\n8,1,1,0\n9,0,0,1\n"
                                           "/IMPVEL/1\ni\n1,X,3,0,1\n", 1, "skew_ID", "moving axis");
    expect_error("skew_bcs.rad", BODY_DECK SKEW3 "/BCS/1\nb\n001 000,0,1\n/IMPVEL/1\ni\n1,X,3,0,1\n", 1,
                 "skew_ID", "held by /BCS");
    expect_error("skew_two.rad", BODY_DECK SKEW3 "/IMPVEL/1\ni\n1,X,3,0,1\n/IMPVEL/2\nj\n1,Z,0,0,1\n", 1,
                 "along a skew axis by /IMPVEL/1", NULL);
    expect_error("skew_static.rad", BODY_DECK SKEW3 "/SOLVER\n3\n/IMPVEL/1\ni\n1,X,3,0,1\n", 1, "skew axis",
                 "/SOLVER Method 3");
#undef SKEW3
    /* compile-time: pairs, references, conflicts */
    expect_error("pair.rad", BODY_DECK "/SURF/PLANE/3\nq\n0,0,1\n0,0,2\n/INTER/POWER/1\nt\n2,3\n1e6\n", 1,
                 "plane against plane", "not a contact pair");
    expect_error("parallel.rad",
                 BODY_DECK "/SURF/CYL/1\nc\n1\n0,0,0.05\n1,0,0\n0.05,0.1\n/SURF/CYL/3\nd\n0\n0,0,0\n1,0.1,0\n0.1,1\n"
                           "/INTER/POWER/1\nt\n1,3\n1e6\n",
                 1, "parallel axes", NULL);
    expect_error("spline.rad", BODY_DECK "/SURF/CYL/1\nc\n1\n0,0,0.05\n1,0,0\n0.05,0.1\n/INTER/POWER/1\nt\n1,2,1,0,3\n,1.5\n",
                 1, "fct_stiff", "akima");
    expect_error("nofun.rad", BODY_DECK "/SURF/CYL/1\nc\n1\n0,0,0.05\n1,0,0\n0.05,0.1\n/INTER/POWER/1\nt\n1,2,0,5\n1e6\n", 1,
                 "fct_damp", "no such function");
    expect_error("held.rad", BODY_DECK "/BCS/1\nb\n100 000,0,1\n/IMPVEL/1\ni\n1,X,0,0,1\n", 1, "held by /BCS", NULL);
    expect_error("twice.rad", BODY_DECK "/IMPVEL/1\ni\n1,ZZ,0,0,1\n/IMPVEL/2\nj\n1,ZZ,0,0,1\n", 1, "already imposed",
                 "/IMPVEL/1");
    expect_error("tstop.rad", BODY_DECK "/IMPVEL/1\ni\n1,ZZ,0,0,1\n,,,2\n/IMPVEL/2\nj\n1,XX,0,0,1\n", 1, "share one Tstop",
                 NULL);
    expect_error("fixed.rad", BODY_DECK "/BCS/1\nb\n111 111,0,1\n/IMPVEL/1\ni\n1,X,0,0,1\n", 1, "is fixed", NULL);
    expect_error("grp.rad", BODY_DECK "/IMPVEL/1\ni\n1,X,0,0,7\n", 1, "grnod_ID", "no such group");
    if (tdir[0]) {
        char cmd[128];
        snprintf(cmd, sizeof cmd, "rm -rf %s", tdir);
        if (system(cmd) != 0) printf("    could not remove %s\n", tdir);
    }
}

/* /IMPVEL on a translation: the velocity follows Fscale f(t / Ascale)
 * until Tstop, then the DOF is free (here: gravity along X takes over); the
 * drive's work closes the ledger. */
static const char impvel_deck[] =
    "/NODE\n1, 0.1, 0.2, 0.3\n"
    "/RBODY/1\nbody\n1,,,,3.7\n1e-3, 2e-3, 3e-3\n0, 0, 0\n"
    "/GRNOD/NODE/1\nbody\n1\n"
    "/FUNCT/1\nramp\n0, 0.5\n1, 2.5\n"
    "/IMPVEL/1\ndrive\n1, X, 0, 0, 1\n0.5, 1.3, 0, 0.3\n"
    "/GRAV/1\ng\n0, X, 0, 0, 0, , 1, -2.9\n"
    "/RUN\n0.7, 0.05\n"
    "/SOLVER\n1, 5, 100000, 1e-10\n1e-12, 1e-9, 1e-10, 1e-10\n1e-10\n";

static void test_power_impvel_follows_then_releases(void)
{
    const char *path = write_deck("impvel.rad", impvel_deck);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    ENSURE(path && rc_case_load(path, &c, &e) == RC_OK);
    if (!c) return;
    ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    rc_case_free(c);
    if (!m) return;
    /* v(t) = 1.3 f(t / 0.5), f(x) = 0.5 + 2 x: v(0) = 0.65, v(0.3) = 2.21 */
    ENSURE_NEAR(m->body_y0[7], 0.65, 1e-15, 0);
    double *y = calloc((size_t)m->ny, sizeof(double));
    rc_run_options opt = {.t_end_override = 0.25, .y_end = y};
    rc_stats st;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    printf("    t = 0.25 s: v_x = %.12f m/s (imposed %.12f), W_imp = %.9f J\n", y[7], 1.3 * (0.5 + 2 * 0.5), y[m->imp->wadr]);
    ENSURE_NEAR(y[7], 1.3 * (0.5 + 2.0 * 0.25 / 0.5), 1e-8, 0);
    opt.t_end_override = 0.7;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    /* released at 0.3 s with v = 2.21 m/s, then gravity -2.9 m/s^2 along X */
    const double v_end = 1.3 * (0.5 + 2.0 * 0.3 / 0.5) - 2.9 * 0.4;
    printf("    t = 0.7 s: v_x = %.12f m/s (free after Tstop: %.12f), energy residual %.2e J\n", y[7], v_end,
           st.energy_residual);
    ENSURE_NEAR(y[7], v_end, 1e-7, 0);
    /* W_imp = -(work of the drive) = -(kinetic energy gained - work of gravity) up to 0.3 s */
    const double v0 = 0.65, v3 = 2.21;
    const double drive = 0.5 * 3.7 * (v3 * v3 - v0 * v0) + 2.9 * 3.7 * (1.3 * (0.5 * 0.3 + 0.3 * 0.3 / 0.5));
    ENSURE_NEAR(y[m->imp->wadr], -drive, 1e-7, 0);
    ENSURE_NEAR(st.energy_residual, 0.0, 0, 1e-7);
    free(y);
    rc_model_free(m);
}

/* /FRICTION naming the parts of a power-law interface replaces step5; its
 * incremental form needs Kt. */
static void test_power_friction_card_overrides_step5(void)
{
    static const char base[] =
        "/NODE\n1, 0, 0, 0.0499\n"
        "/RBODY/1\nball\n1,,,,1.0\n1e-3, 1e-3, 1e-3\n0, 0, 0\n"
        "/GRNOD/NODE/1\nball\n1\n"
        "/SURF/ELLIPS/1\nball\n0, 2, 1\n0, 0, 0.0499\n0.05, 0.05, 0.05\n"
        "/SURF/PLANE/2\nfloor\n0, 0, 0\n0, 0, 1\n"
        "/PART/1\nball\n0, 0, 0, 0\n1\n"
        "/PART/2\nfloor\n0, 0, 0, 0\n0, 2\n"
        "/FRICTION/1\nf\n0, 0, 0, %d\n,\n, 0.4, 0.5\n0, 0, 1, 2\n,\n, 0.37, 0.5\n"
        "/INTER/POWER/1\nt\n1, 2\n1e8, 1.5\n,\n0.3, 0.01, 0.2, 0.05\n%s"
        "/RUN\n0.01,0,0,2\n"; /* On_viol 2: the ball starts 0.1 mm into the floor (accepted) */
    char text[2048];
    const int forms[3] = {1, 2, 2};
    const char *kt[3] = {"", "", "2.3e5\n"};
    for (int k = 0; k < 3; k++) {
        snprintf(text, sizeof text, base, forms[k], kt[k]);
        const char *path = write_deck("override.rad", text);
        rc_case *c = NULL;
        rc_model *m = NULL;
        rc_error e;
        ENSURE(path && rc_case_load(path, &c, &e) == RC_OK);
        if (!c) continue;
        rc_status st = rc_model_compile(c, &m, &e);
        rc_case_free(c);
        if (st && k != 1) printf("    %s\n", e.msg);
        if (k == 1) {
            ENSURE(st == RC_EINPUT && strstr(e.msg, "/FRICTION/1") && strstr(e.msg, "needs a stiffness"));
            continue;
        }
        ENSURE(st == RC_OK);
        if (!m) continue;
        ENSURE(m->inter_fr[0].kind == RC_FK_CARD && m->inter_fr[0].card_id == 1);
        ENSURE_NEAR(m->inter_fr[0].set[0][RC_FS_FRIC], 0.37, 0, 0);
        ENSURE(m->inter_fr[0].form == (k == 2 ? RC_FF_INCREMENTAL : RC_FF_VISCOUS));
        if (k == 2) ENSURE_NEAR(m->inter_fr[0].kt, 2.3e5, 0, 0);
        rc_stats s;
        rc_run_options opt = {0};
        ENSURE(rc_run(m, &opt, &s, &e) == RC_OK);
        rc_model_free(m);
    }
}

/* A released power-law contact (its damping C P^m3 v pulled the total
 * force below zero) whose force root rises through zero with P at the
 * rounding of 0 while the bodies separate: with m3 > n the elastic force
 * outlasts the damping in the last 1e-17 m, and the force's root falls
 * within rounding of the zone's. That is the separation, not a closing
 * (a box landing on a floor, 1 km from the origin, recorded a
 * contact_close at -1.46 m/s and its contact_separate at the same instant;
 * near the origin only the separation). Deeper, the same root closes the
 * contact again. */
static void test_power_released_force_root_at_zero_separates(void)
{
    rc_model *m = TU_COMPILE_OK("/BEGIN\nball leaving a floor\n      2022         0\n"
                                "                  kg                   m                   s\n"
                                "                  kg                   m                   s\n" BODY_DECK
                                "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n"
                                "/INTER/POWER/1\nt\n1,2\n1e8,1.5,1e4,1,2\n/END\n",
                                "power_released_root.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double));
    int roots[64] = {0}, restart = 0;
    ENSURE(d && y && m->ninter == 1 && rc_root_count(m) <= 64);
    if (!d || !y) goto out;
    const double deep[2] = {1e-18, 1e-6}; /* P [m]: at the rounding of 0, and inside */
    for (int k = 0; k < 2; k++) {
        rc_initial_state(m, y);
        y[m->body_yadr[0] + 2] = 0.05 - deep[k] - m->origin[2];
        y[m->body_yadr[0] + 9] = 1.46; /* leaving */
        d->inter_mode[0] = RC_MODE_RELEASED;
        memset(roots, 0, sizeof roots);
        roots[RC_ROOT_FORCE] = 1;
        rc_event ev[4];
        const int n = rc_events_apply(m, d, 0.0, y, roots, ev, 4, &restart);
        printf("    P %g m, leaving at 1.46 m/s: %d event(s), %s, mode %d\n", deep[k], n,
               n > 0 ? rc_event_kind_name(ev[0].kind) : "-", d->inter_mode[0]);
        ENSURE(n == 1);
        if (k == 0) ENSURE(n == 1 && ev[0].kind == RC_EV_CONTACT_SEPARATE && d->inter_mode[0] == RC_MODE_OPEN);
        else ENSURE(n == 1 && ev[0].kind == RC_EV_CONTACT_CLOSE && d->inter_mode[0] == RC_MODE_CLOSED);
    }
out:
    free(y);
    rc_data_free(d);
    rc_model_free(m);
}

/* The rebound damping factor scales the damping term: without one (C 0,
 * no damping curve) it changes nothing and the law has no branches, so no
 * rdf_rebound / rdf_approach event is tracked. A ball resting on a floor
 * through an undamped power law with the default RDF rang on its law for
 * 4.5 s with two branch events every period of the ringing (38 000 events
 * in a fuzzer's cradle); with a damping term the events are there. */
static void test_power_rdf_without_damping_has_no_branches(void)
{
    const char *laws[2] = {"1e8,1.5\n", "1e8,1.5,100,1,1\n"};
    int nrdf[2] = {-1, -1};
    for (int c = 0; c < 2; c++) {
        char deck[1024];
        snprintf(deck, sizeof deck,
                 "/BEGIN\nball resting on a floor\n      2022         0\n"
                 "                  kg                   m                   s\n"
                 "                  kg                   m                   s\n"
                 "/NODE\n1,0,0,0.05\n/RBODY/1\nr\n1,,,,1.0\n1e-3,1e-3,1e-3\n0,0,0\n/GRNOD/NODE/1\ng\n1\n"
                 "/SURF/PLANE/2\np\n0,0,0\n0,0,1\n"
                 "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n"
                 "/INTER/POWER/1\nt\n1,2\n%s"
                 "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n/RUN\n0.05,0.01\n/END\n",
                 laws[c]);
        rc_model *m = TU_COMPILE_OK(deck, c ? "power_rdf_damped.rad" : "power_rdf_undamped.rad");
        if (!m) continue;
        ENSURE(m->inter_pw[0].rdf == 0.001);
        ENSURE(rc_pw_rdf_acts(&m->inter_pw[0]) == c);
        tu_evlog ev;
        rc_stats st;
        ENSURE(tu_run_evlog(m, &ev, &st) == RC_OK);
        nrdf[c] = 0;
        for (int k = 0; k < ev.n && k < TU_MAXEV; k++)
            nrdf[c] += !strcmp(ev.kind[k], "rdf_rebound") || !strcmp(ev.kind[k], "rdf_approach");
        printf("    %s: %d rdf events in 0.05 s, %ld steps\n", c ? "C 100" : "C 0", nrdf[c], st.steps);
        rc_model_free(m);
    }
    ENSURE(nrdf[0] == 0);
    ENSURE(nrdf[1] >= 2);
}

/* The derived Dreg is at least what the numbers resolve: 64 times the
 * larger of the rounding of the pair's coordinates and the distance v_s
 * covers in the smallest step that moves t at the end time. A ball
 * striking a very stiff wall with a damping switched on over the first
 * Dreg (m3 = 0) at t = 0.25 s, 3.1 m/s: 1e-4 p_s (p_s at the ball's
 * weight) alone is crossed faster than t can be stepped there, and CVODE
 * stepped on the spot until Max_steps; with the floor the ball bounces
 * back. A Dreg given on the card is kept. */
static void test_power_dreg_resolvable(void)
{
    for (int given = 0; given < 2; given++) {
        char deck[1200];
        snprintf(deck, sizeof deck,
                 "/BEGIN\nball striking a stiff damped wall\n      2022         0\n"
                 "                  kg                   m                   s\n"
                 "                  kg                   m                   s\n"
                 "/NODE\n1,0,0,0.511\n/RBODY/1\nr\n1,,,,0.3\n1e-4,1e-4,1e-4\n0,0,0\n/GRNOD/NODE/1\ng\n1\n"
                 "/SURF/PLANE/2\np\n0,0,0\n0,0,1\n"
                 "/SURF/ELLIPS/1\ns\n0,2,1\n0,0,0.511\n0.03,0.03,0.03\n"
                 "/INTER/POWER/1\nt\n1,2\n4.68e16,1.5,487554,1,0\n%s"
                 "/INIVEL/TRA/1\nv0\n0,0,-0.7,1,0\n/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n/RUN\n0.5,0.01\n/END\n",
                 given ? ",1e-9\n" : "");
        rc_model *m = TU_COMPILE_OK(deck, given ? "power_dreg_given.rad" : "power_dreg_derived.rad");
        if (!m) continue;
        const double ps = m->inter_pscale[0], vs = m->inter_vscale[0], dreg = m->inter_pw[0].dreg;
        const double X = 0.511 + 0.06; /* the ball's centre plus its size; the plane's point is 0 */
        const double floor = 64.0 * fmax(64.0 * DBL_EPSILON * X, vs * 100.0 * DBL_EPSILON * 0.5);
        printf("    %s: Dreg %.3g m (1e-4 p_s %.3g m, the numbers' floor about %.3g m)\n", given ? "given" : "derived",
               dreg, 1e-4 * ps, floor);
        if (given) {
            ENSURE(dreg == 1e-9);
        } else {
            ENSURE(1e-4 * ps < floor);
            ENSURE(dreg >= 0.5 * floor && dreg <= 4.0 * floor);
            tu_evlog ev;
            rc_stats st;
            ENSURE(tu_run_evlog(m, &ev, &st) == RC_OK);
            int opened = 0;
            for (int k = 0; k < ev.n && k < TU_MAXEV; k++) opened |= !strcmp(ev.kind[k], "contact_open") || !strcmp(ev.kind[k], "contact_separate");
            printf("    the run: %ld steps, %d events, the ball leaves the wall: %s\n", st.steps, ev.n, opened ? "yes" : "no");
            ENSURE(opened);
        }
        rc_model_free(m);
    }
}

void suite_power(void);
void suite_power(void)
{
    RUN_TEST(test_power_step5_is_c2);
    RUN_TEST(test_power_regularised_powers);
    RUN_TEST(test_power_splines);
    RUN_TEST(test_power_roller_deck_runs_and_ledger_closes);
    RUN_TEST(test_power_impvel_follows_then_releases);
    RUN_TEST(test_power_friction_card_overrides_step5);
    RUN_TEST(test_power_card_errors);
    RUN_TEST(test_power_released_force_root_at_zero_separates);
    RUN_TEST(test_power_rdf_without_damping_has_no_branches);
    RUN_TEST(test_power_dreg_resolvable);
}
