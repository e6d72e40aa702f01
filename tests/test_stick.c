/*
 * Exact stick tests (engine/constraints/stick.h, engine/constraints/stick.c): the exact Jacobian of
 * the extended residual (the constraint rows and the multipliers' terms in
 * the bodies' rows, complex step) against central finite differences of
 * the residual; the consistent multipliers (the sticking velocities stay
 * zero along the motion); joints and exact stick in one set (the summed
 * Jacobian against finite differences, the consistent multipliers of both);
 * the refusals (CVODE path, several contact points).
 */
#include "harness.h"
#include "testutil.h"
#include "base/error.h"
#include "model/model.h"
#include "model/joint.h"
#include "engine/constraints/stick.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "engine/assembly/assembly.h"
#include "engine/constraints/cset.h"

/* Two free spheres, full rotations, on a fixed plane and on each other,
 * both interfaces with exact stick (the second with a static coefficient). */
static const char *two_spheres =
    "/BEGIN\nstick\n2022,0\nkg,m,s\nkg,m,s\n"
    "/FUNCT/1\nk\n0,0\n1,1e6\n"
    "/NODE\n1,0.001,-0.002,0.0499\n2,0.013,0.021,0.1381\n"
    "/RBODY/1\nb1\n1,,,,1.3\n0.0013,0.0011,0.0017\n0,0,0\n"
    "/RBODY/2\nb2\n2,,,,0.7\n0.0005,0.0004,0.0006\n0,0,0\n"
    "/SURF/ELLIPS/1\ns1\n0,2,1\n0.001,-0.002,0.0499\n0.05,0.05,0.05\n"
    "/SURF/ELLIPS/3\ns2\n0,2,2\n0.013,0.021,0.1381\n0.04,0.04,0.04\n"
    "/SURF/PLANE/2\nfloor\n0,0,0\n0.1,0.05,1\n"
    "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n"
    "/INTER/TYPE6/1\nfloor\n1,2\n0,0.3\n1\n1\n\n300\n"
    "/INTER/TYPE6/2\npair\n3,1\n0.2,0.25\n1\n1\n0,0.45\n200\n"
    "/RUN\n1,0.01\n/END\n";

static void residual(const rc_model *m, rc_data *d, const rc_stk_work *w, const double *Y, const double *Yp,
                     double *r)
{
    rc_assemble_rhs(m, d, 0.0, Y, r);
    for (int k = 0; k < m->ny; k++) r[k] = Yp[k] - r[k];
    rc_stk_residual(m, d, w, Y, Yp, r);
}

static void perturb(const rc_model *m, double *Y, double *Yp, int n, unsigned s, double amp)
{
    for (int k = 0; k < n; k++) {
        s = s * 1103515245u + 12345u;
        const double u = (double)(s >> 8) / (double)(1u << 24) - 0.5;
        if (k < m->ny) Y[k] += amp * u;
        Yp[k] = k < m->ny ? u : 3.0 * u;
    }
}

/* The residuals and the rows compared, for tu_dae_jac_fd_error. */
typedef struct {
    const rc_model *m;
    rc_data *d;
    const rc_stk_work *w;
    const rc_cset *b;
} fd_ctx;
static void fd_residual(void *ctx, const double *Y, const double *Yp, double *r);
static int fd_compare(void *ctx, int r);

static void test_stick_jacobian_matches_finite_differences(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(two_spheres, "stick.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(rc_stk_count(m) == 2);
    ENSURE(m->method == 2); /* IDA by default with exact stick */
    rc_data *d = rc_data_new(m);
    rc_stk_work *w = rc_stk_work_new(m);
    const int n = m->ny + rc_stk_nextra(w);
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp);
    double *jf = calloc((size_t)m->nnz + 1, sizeof *jf), *val = calloc((size_t)rc_stk_nnz(w), sizeof *val);
    rc_initial_state(m, Y);
    for (int i = 0; i < m->ninter; i++) {
        d->inter_mode[i] = RC_MODE_CLOSED;
        d->inter_slip[i] = 0;
    }
    /* the bases and rows fixed at a restart, then a state off the
     * constraints: non-unit quaternions, velocities, multipliers */
    ENSURE(rc_stk_restart(m, d, w, 0.0, Y, Yp) == 0);
    perturb(m, Y, Yp, n, 4242u, 0.01);
    const int64_t *cp, *ri;
    rc_stk_pattern(w, &cp, &ri);
    double worst = 0, raw = 0;
    int outside = 0, outside_raw = 0;
    fd_ctx fc = {m, d, w, NULL};
    tu_dae_fd_opts o = {0.1, 1e-6, 1e-5, 1, 1, fd_compare};
    for (int pass = 0; pass < 2; pass++) {
        const double cj = pass ? 37.5 : 0.0;
        rc_assemble_jac(m, d, 0.0, Y, jf);
        rc_stk_jacobian(m, d, w, cj, Y, Yp, jf, val);
        /* less the rounding of the difference (contact rows of 1e3 N) */
        worst = fmax(worst, tu_dae_jac_fd_error(n, Y, Yp, cj, cp, ri, val, fd_residual, &fc, &o, &outside));
        tu_dae_fd_opts o_raw = o;
        o_raw.forgive_rounding = 0;
        o_raw.print_tol = INFINITY;
        raw = fmax(raw, tu_dae_jac_fd_error(n, Y, Yp, cj, cp, ri, val, fd_residual, &fc, &o_raw, &outside_raw));
    }
    printf("    max scaled |J - FD| = %.1e beyond the rounding of the differences (%.1e with it), %d FD entries "
           "outside the pattern\n",
           worst, raw, outside);
    ENSURE(worst < 1e-5);
    ENSURE(outside == 0);
    free(Y);
    free(Yp);
    free(jf);
    free(val);
    rc_stk_work_free(w);
    rc_data_free(d);
    rc_model_free(m);
}

/* After rc_stk_restart the constraint rows are zero and stay zero along
 * the motion (their rate along Y', by a difference along Y'), and the
 * bodies' residual rows are zero. */
static void test_stick_consistent_multipliers(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(two_spheres, "stick.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    rc_stk_work *w = rc_stk_work_new(m);
    const int n = m->ny + rc_stk_nextra(w);
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp), *r = calloc((size_t)n, sizeof *r);
    double *Y2 = calloc((size_t)n, sizeof *Y2), *r2 = calloc((size_t)n, sizeof *r2);
    rc_initial_state(m, Y);
    perturb(m, Y, Yp, m->ny, 777u, 1e-3); /* moving bodies */
    for (int i = 0; i < m->ninter; i++) {
        d->inter_mode[i] = RC_MODE_CLOSED;
        d->inter_slip[i] = 0;
    }
    ENSURE(rc_stk_restart(m, d, w, 0.0, Y, Yp) == 0);
    residual(m, d, w, Y, Yp, r);
    double rmax = 0;
    for (int k = 0; k < n; k++) rmax = fmax(rmax, fabs(r[k]));
    /* the rate of the constraint rows along Y' */
    const double h = 1e-7;
    for (int k = 0; k < n; k++) Y2[k] = Y[k] + h * Yp[k];
    residual(m, d, w, Y2, Yp, r2);
    double rate = 0, lam = 0;
    for (int k = m->ny; k < n; k++) {
        rate = fmax(rate, fabs(r2[k] - r[k]) / h);
        lam = fmax(lam, fabs(Yp[k]));
    }
    printf("    residual after the restart %.1e, rate of the rows %.1e m/s^2, |lambda| up to %.3g N\n", rmax, rate, lam);
    ENSURE(rmax < 1e-9);
    ENSURE(rate < 1e-5);
    ENSURE(lam > 0.1);
    free(Y);
    free(Yp);
    free(r);
    free(Y2);
    free(r2);
    rc_stk_work_free(w);
    rc_data_free(d);
    rc_model_free(m);
}

/* Joints and exact stick together (engine/constraints/cset.c): the two spheres
 * also tied by a rod between their centres. */
static const char *rod_tail = "/JOINT/DISTANCE/1\nrod\n1,2\n0.001,-0.002,0.0499\n0.013,0.021,0.1381\n/END\n";

static void both_residual(const rc_model *m, rc_data *d, const rc_cset *b, const double *Y, const double *Yp, double *r)
{
    rc_assemble_rhs(m, d, 0.0, Y, r);
    for (int k = 0; k < m->ny; k++) r[k] = Yp[k] - r[k];
    rc_cset_residual(m, d, b, Y, Yp, r);
}

static void fd_residual(void *ctx, const double *Y, const double *Yp, double *r)
{
    const fd_ctx *c = ctx;
    if (c->b) both_residual(c->m, c->d, c->b, Y, Yp, r);
    else residual(c->m, c->d, c->w, Y, Yp, r);
}

/* only the rows of the constraints and the bodies' rate rows (the model's
 * own block is test_engine's) */
static int fd_compare(void *ctx, int r)
{
    const fd_ctx *c = ctx;
    return r >= c->m->ny || (r < 26 && r % RC_NB >= 7);
}

static char *with_tail(const char *tail);

static void test_stick_joints_jacobian_and_multipliers(void)
{
    rc_error e;
    char *t = with_tail(rod_tail);
    rc_model *m = tu_compile_text(t, "rod.rad", &e);
    free(t);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->method == 2 && m->jnt && m->jnt->n == 1 && rc_stk_count(m) == 2);
    rc_data *d = rc_data_new(m);
    rc_cset *b = rc_cset_new(m);
    ENSURE(b != NULL);
    if (!b) return;
    const int n = m->ny + rc_cset_nextra(b);
    ENSURE(n == m->ny + 2 * m->jnt->nrows + 1 + 3 * rc_stk_slots(m));
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp);
    double *r1 = calloc((size_t)n, sizeof *r1), *r2 = calloc((size_t)n, sizeof *r2), *Y2 = calloc((size_t)n, sizeof *Y2);
    double *jf = calloc((size_t)m->nnz + 1, sizeof *jf), *val = calloc((size_t)rc_cset_nnz(b), sizeof *val);
    rc_initial_state(m, Y);
    perturb(m, Y, Yp, m->ny, 991u, 1e-3); /* moving bodies (the rod's row off zero) */
    for (int i = 0; i < m->ninter; i++) {
        d->inter_mode[i] = RC_MODE_CLOSED;
        d->inter_slip[i] = 0;
    }
    /* 1. the consistent start: every residual row zero, the rates of the
     *    velocity rows of both sets zero along Y', multipliers of both */
    ENSURE(rc_cset_consistent(m, d, b, 0.0, Y, Yp, 1) == 0);
    both_residual(m, d, b, Y, Yp, r1);
    const int nr = m->jnt->nrows, base = m->ny + 2 * nr + 1;
    double rmax = 0;
    /* all rows but the rod's position row (the perturbed positions are off
     * the rod's length: the projection multiplier nu takes that back) */
    for (int k = 0; k < n; k++)
        if (k < m->ny + nr || k >= m->ny + 2 * nr) rmax = fmax(rmax, fabs(r1[k]));
    const double h = 1e-7;
    for (int k = 0; k < n; k++) Y2[k] = Y[k] + h * Yp[k];
    both_residual(m, d, b, Y2, Yp, r2);
    double rate = 0, lam_j = fabs(Yp[m->ny]), lam_s = 0;
    for (int k = m->ny; k < m->ny + nr; k++) rate = fmax(rate, fabs(r2[k] - r1[k]) / h);
    for (int k = base; k < n; k++) {
        rate = fmax(rate, fabs(r2[k] - r1[k]) / h);
        lam_s = fmax(lam_s, fabs(Yp[k]));
    }
    printf("    both sets: residual after the start %.1e, rate of the velocity rows %.1e, |lambda| rod %.3g N, "
           "stick up to %.3g N\n", rmax, rate, lam_j, lam_s);
    ENSURE(rmax < 1e-9);
    ENSURE(rate < 1e-5);
    ENSURE(lam_j > 0.1 && lam_s > 0.1);
    /* 2. the Jacobian of the union against central differences, off the
     *    constraints */
    perturb(m, Y, Yp, n, 4243u, 0.01);
    const int64_t *cp, *ri;
    rc_cset_pattern(b, &cp, &ri);
    double worst = 0;
    int outside = 0;
    fd_ctx fc = {m, d, NULL, b};
    const tu_dae_fd_opts o = {0.1, 1e-6, 1e-5, 1, 1, fd_compare};
    for (int pass = 0; pass < 2; pass++) {
        const double cj = pass ? 41.0 : 0.0;
        rc_assemble_jac(m, d, 0.0, Y, jf);
        rc_cset_jacobian(m, d, b, cj, Y, Yp, jf, val);
        worst = fmax(worst, tu_dae_jac_fd_error(n, Y, Yp, cj, cp, ri, val, fd_residual, &fc, &o, &outside));
    }
    printf("    both sets: max scaled |J - FD| = %.1e beyond the rounding of the differences, %d FD entries outside "
           "the pattern\n", worst, outside);
    ENSURE(worst < 1e-5);
    ENSURE(outside == 0);
    free(Y);
    free(Yp);
    free(Y2);
    free(r1);
    free(r2);
    free(jf);
    free(val);
    rc_cset_free(b);
    rc_data_free(d);
    rc_model_free(m);
}

/* The deck with `tail` in place of its /END line. */
static char *with_tail(const char *tail)
{
    char *t = malloc(strlen(two_spheres) + strlen(tail) + 1);
    strcpy(t, two_spheres);
    strcpy(strstr(t, "/END"), tail);
    return t;
}

/* A ball resting on a frictionless plane (TYPE6, no friction), settled: the
 * normal row of the constraint set (its multiplier the normal force), the
 * Jacobian against central differences, the consistent multiplier m g. */
static const char *ball_on_plane =
    "/BEGIN\nsettle\n2022,0\nkg,m,s\nkg,m,s\n"
    "/FUNCT/1\nk\n0,0\n1,1e6\n"
    "/NODE\n1,0.001,-0.002,0.0499\n"
    "/RBODY/1\nb1\n1,,,,1.3\n0.0013,0.0011,0.0017\n0,0,0\n"
    "/SURF/ELLIPS/1\ns1\n0,2,1\n0.001,-0.002,0.0499\n0.05,0.05,0.05\n"
    "/SURF/PLANE/2\nfloor\n0,0,0\n0.1,0.05,1\n"
    "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n"
    "/INTER/TYPE6/1\nfloor\n1,2\n\n\n1\n\n300\n"
    "/RUN\n1,0.01\n/END\n";

static void test_stick_settled_normal_row(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(ball_on_plane, "settle.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(rc_stk_count(m) == 0 && rc_stk_slots(m) == 1 && rc_stk_settle_capable(m, 0));
    rc_data *d = rc_data_new(m);
    rc_stk_work *w = rc_stk_work_new(m);
    const int n = m->ny + rc_stk_nextra(w);
    ENSURE(n == m->ny + 3);
    double *Y = calloc((size_t)n, sizeof *Y), *Yp = calloc((size_t)n, sizeof *Yp);
    double *jf = calloc((size_t)m->nnz + 1, sizeof *jf), *val = calloc((size_t)rc_stk_nnz(w), sizeof *val);
    rc_initial_state(m, Y);
    Y[7] = 0.01; /* moving along the plane and spinning: the row holds the normal rate only */
    Y[10] = 0.3;
    Y[12] = -0.2;
    d->inter_mode[0] = RC_MODE_CLOSED;
    d->inter_settled[0] = 1;
    /* consistent start: the normal rate zeroed, the multiplier m g cos(tilt)
     * less the penalty force, the constrained acceleration zero along n */
    ENSURE(rc_stk_restart(m, d, w, 0.0, Y, Yp) == 0);
    rc_inter_report rep;
    rc_inter_report_eval_d(m, d, 0, 0.0, Y, &rep);
    const double nz = 1.0 / sqrt(0.1 * 0.1 + 0.05 * 0.05 + 1.0);
    const double lam = Yp[m->ny + 2], want = 1.3 * 9.81 * nz - rep.fn;
    printf("    settled ball: multiplier %.9g N (m g n_z - F_pen = %.9g N), gap rate %.1e m/s\n", lam, want,
           rep.vn);
    ENSURE(fabs(lam - want) < 1e-6 * fabs(want));
    ENSURE(fabs(rep.vn) < 1e-12);
    rc_stk_fcstr(m, d, w, 0.0, Y, Yp);
    ENSURE(fabs(d->inter_fcstr[0] - want) < 1e-6 * fabs(want));
    perturb(m, Y, Yp, n, 777u, 0.01);
    const int64_t *cp, *ri;
    rc_stk_pattern(w, &cp, &ri);
    double worst = 0;
    int outside = 0;
    fd_ctx fc = {m, d, w, NULL};
    const tu_dae_fd_opts o = {0.1, 1e-6, 1e-5, 1, 1, fd_compare};
    for (int pass = 0; pass < 2; pass++) {
        const double cj = pass ? 37.5 : 0.0;
        rc_assemble_jac(m, d, 0.0, Y, jf);
        rc_stk_jacobian(m, d, w, cj, Y, Yp, jf, val);
        worst = fmax(worst, tu_dae_jac_fd_error(n, Y, Yp, cj, cp, ri, val, fd_residual, &fc, &o, &outside));
    }
    printf("    settled ball: max scaled |J - FD| = %.1e, %d FD entries outside the pattern\n", worst, outside);
    ENSURE(worst < 1e-5);
    ENSURE(outside == 0);
    free(Y);
    free(Yp);
    free(jf);
    free(val);
    rc_stk_work_free(w);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_stick_refusals(void)
{
    rc_error e;
    /* /SOLVER Method 1: refused at the /SOLVER card, naming Method 2 */
    char *t = with_tail("/SOLVER\n1\n/END\n");
    rc_model *m = tu_compile_text(t, "cvode.rad", &e);
    ENSURE(m == NULL && e.code == RC_EINPUT && strstr(e.msg, "cvode.rad:59:") && strstr(e.msg, "field Method") &&
           strstr(e.msg, "Method 2") && strstr(e.msg, "Istick"));
    rc_model_free(m);
    free(t);
    /* --method cvode (rc_model_set_method) */
    m = tu_compile_text(two_spheres, "stick.rad", &e);
    ENSURE(m != NULL);
    if (m) ENSURE(rc_model_set_method(m, 1, &e) == RC_EINPUT && strstr(e.msg, "exact stick"));
    rc_model_free(m);
    /* Istick without friction; a speed-dependent coefficient */
    const char *nofric = "/BEGIN\nstick\n2022,0\nkg,m,s\nkg,m,s\n/FUNCT/1\nk\n0,0\n1,1e6\n"
                         "/NODE\n1,0,0,0.0499\n/RBODY/1\nb1\n1,,,,1.3\n0.0013,0.0011,0.0017\n0,0,0\n"
                         "/SURF/ELLIPS/1\ns1\n0,2,1\n0,0,0.0499\n0.05,0.05,0.05\n"
                         "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n/INTER/TYPE6/1\nfloor\n1,2\n0,0\n1\n1\n\n300\n"
                         "/RUN\n1,0.01\n/END\n";
    m = tu_compile_text(nofric, "nofric.rad", &e);
    ENSURE(m == NULL && e.code == RC_EINPUT && strstr(e.msg, "nofric.rad:30:") && strstr(e.msg, "field Istick"));
    rc_model_free(m);
    /* /FRICTION Iform 3 with a law other than Coulomb */
    t = with_tail("/FRICTION/1\nf\n1,0,,3\n\n,0.3\n/END\n");
    m = tu_compile_text(t, "law.rad", &e);
    ENSURE(m == NULL && e.code == RC_EINPUT && strstr(e.msg, "law.rad:60:") && strstr(e.msg, "field Iform") &&
           strstr(e.msg, "Coulomb"));
    rc_model_free(m);
    free(t);
}

void suite_stick(void);
void suite_stick(void)
{
    RUN_TEST(test_stick_jacobian_matches_finite_differences);
    RUN_TEST(test_stick_consistent_multipliers);
    RUN_TEST(test_stick_joints_jacobian_and_multipliers);
    RUN_TEST(test_stick_settled_normal_row);
    RUN_TEST(test_stick_refusals);
    tu_tmp_cleanup();
}
