/*
 * cvode_ref: the settling column as a plain CVODE + KLU program.
 *
 * The same ODE as explicit_ref's column (bench/explicit_ref.c): N spheres of
 * radius R and mass m on a vertical line over a fixed floor, sphere i
 * (0 = bottom) at height z_i with velocity v_i (up > 0), gravity g(t)
 * downwards, and the clipped linear spring-dashpot contact
 *     f_j = max(0, k p_j + c_j pdot_j)   when p_j > 0,   0 otherwise,
 * contact 0 = floor (p_0 = R - z_0, c_0 = 2 zeta sqrt(k m)),
 * contact j >= 1 between spheres j-1 and j (p_j = 2R - (z_j - z_{j-1}),
 * c_j = 2 zeta sqrt(k m / 2)). Sphere i gets +f_i from below and -f_{i+1}
 * from above.
 *
 * It is what a user would write with CVODE directly for this 1-D model,
 * as a yardstick for ricochet (which integrates 15 states per sphere for
 * the same motion, through its general 3-D machinery):
 *   - 2 states per sphere, y = (z_0, v_0, z_1, v_1, ...): no energy states,
 *     no rotations;
 *   - CVODE BDF (max order 5), Newton, SUNLinSol_KLU on a CSC Jacobian with
 *     the fixed pattern of the chain (a block-tridiagonal band of width 3 in
 *     this ordering), filled analytically;
 *   - contact modes (active / open) kept fixed between events, so the
 *     right-hand side is smooth inside every step; one root function per
 *     contact, g_j = min(k p_j, k p_j + c_j pdot_j) = k p_j + min(0, c_j pdot_j)
 *     (in newtons), whose sign is the mode of the clipped law: it crosses
 *     zero at a contact onset (p = 0 while pdot > 0), at a release
 *     (f = k p + c pdot = 0) and at a re-engagement of a released contact
 *     that is still penetrating (f = 0 rising with p > 0);
 *   - at a root the modes of the roots found are flipped (direction from
 *     CVodeGetRootInfo). CVodeReInit only where the right-hand side jumps:
 *     a contact closing at p = 0 with c pdot > 0 (the force jumps from 0 to
 *     c pdot). Every other switch is continuous (the force is 0 on both
 *     sides): CVODE continues with its history, and one step with a forced
 *     linear-solver setup and a fresh Jacobian follows (the old mode's
 *     Jacobian, a stiffness that is gone, can let Newton accept a wrong
 *     correction);
 *   - CVodeSetStabLimDet on;
 *   - optional load ramp: g(t) = G (1 + min(t / T_ramp, 1)) (gravity ramped
 *     linearly from G to 2 G over T_ramp, then held); CVODE is stopped at
 *     the kink t = T_ramp (CVodeSetStopTime) and continues from there.
 *
 * Error weights (CVodeWFtolerances, a user weight function): gap-scaled,
 *     W(z_i) = 1 / (rtol * z_scale),                  z_scale = m g / k,
 *     W(v_i) = 1 / (rtol * |v_i| + rtol * v_scale),   v_scale = g sqrt(m / k).
 * z_scale is the penetration that carries one sphere's weight, the length
 * on which the contact forces depend (k z_scale = m g); v_scale is the
 * velocity of a contact oscillation of that amplitude (omega z_scale).
 * Positions get no relative part: the heights are absolute coordinates
 * (the top of a 1000-sphere column is at 20 m), and rtol |z| would let a
 * 20 m height carry a 2e-5 m error at rtol 1e-6, many times the
 * penetrations that set the forces. CVodeSVtolerances cannot express
 * this (it always adds rtol |y_i|), hence CVodeWFtolerances.
 *
 * Usage:
 *   cvode_ref column N R m k zeta gap t_end rtol [FORCES_FILE]
 *       the column of explicit_ref (spheres at rest, gap `gap` between
 *       neighbours and above the floor, constant gravity)
 *   cvode_ref ramp N R m k zeta t_ramp t_end rtol [FORCES_FILE]
 *       the settled column (static state: contact j carries (N - j) m G,
 *       p_j = (N - j) m G / k, velocities 0) under the gravity ramp G -> 2 G
 *       over t_ramp, held until t_end
 *   cvode_ref sramp ...  (same arguments)
 *       the same with the smooth ramp G (1 + (1 - cos(pi t / t_ramp)) / 2):
 *       no kink in the load at either end (its rate is continuous)
 *   cvode_ref stickslip m ks C mu_s mu_k v1 v2 V t_end rtol [EVENTS_FILE]
 *       the stick-slip drag of explicit_ref stickslip, 2 states (see
 *       run_stickslip below); EVENTS_FILE: "slip t x" / "stick t x" lines
 *   cvode_ref drag m K_t mu rate t_end dt_out rtol [FORCES_FILE]
 *       the drag to the slip of explicit_ref drag (see run_drag below);
 *       FORCES_FILE: "t F" at the multiples of dt_out before the slip
 * FORCES_FILE: the contact forces at t_end (contact 0 = floor), one a line.
 * Output: key=value lines on stdout (as explicit_ref). wall_time is
 * clock_gettime(CLOCK_MONOTONIC) around the integration loop only (CVODE
 * set-up and output excluded).
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* M_PI */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#define GRAV 9.81

typedef struct col {
    long N;
    double R, m, k, c0, c1;
    double t_ramp; /* > 0: gravity ramp G -> 2 G over t_ramp */
    int smooth;    /* the ramp's shape: 0 linear, 1 (1 - cos(pi t / t_ramp)) / 2 */
    double rtol, z_scale, v_scale;
    int *active;
} col;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of this process (user + system) [s]: less sensitive than the
 * wall time to other jobs on a shared machine */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static long peak_rss_kb(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

static double arg(char **argv, int k)
{
    char *end;
    double v = strtod(argv[k], &end);
    if (*end || end == argv[k]) {
        fprintf(stderr, "cvode_ref: bad number '%s'\n", argv[k]);
        exit(2);
    }
    return v;
}

static double gravity(const col *c, double t)
{
    if (c->t_ramp <= 0.0) return GRAV;
    double s = t <= 0.0 ? 0.0 : (t >= c->t_ramp ? 1.0 : t / c->t_ramp);
    if (c->smooth) s = 0.5 * (1.0 - cos(M_PI * s));
    return GRAV * (1.0 + s);
}

/* penetration, approach rate and damping of contact j */
static void contact(const col *c, long j, const double *y, double *p, double *pd, double *cj)
{
    if (j == 0) {
        *p = c->R - y[0];
        *pd = -y[1];
        *cj = c->c0;
    } else {
        *p = 2.0 * c->R - (y[2 * j] - y[2 * j - 2]);
        *pd = -(y[2 * j + 1] - y[2 * j - 1]);
        *cj = c->c1;
    }
}

static int rhs(sunrealtype t, N_Vector Y, N_Vector Yd, void *ud)
{
    const col *c = ud;
    const double *y = N_VGetArrayPointer(Y);
    double *yd = N_VGetArrayPointer(Yd);
    const long N = c->N;
    const double g = gravity(c, t);
    double fbelow = 0.0;
    for (long j = 0; j < N; j++) {
        double p, pd, cj;
        contact(c, j, y, &p, &pd, &cj);
        const double f = c->active[j] ? c->k * p + cj * pd : 0.0;
        if (j > 0) yd[2 * j - 1] = -g + (fbelow - f) / c->m;
        fbelow = f;
    }
    yd[2 * N - 1] = -g + fbelow / c->m;
    for (long i = 0; i < N; i++) yd[2 * i] = y[2 * i + 1];
    return 0;
}

static int roots(sunrealtype t, N_Vector Y, sunrealtype *gout, void *ud)
{
    (void)t;
    const col *c = ud;
    const double *y = N_VGetArrayPointer(Y);
    for (long j = 0; j < c->N; j++) {
        double p, pd, cj;
        contact(c, j, y, &p, &pd, &cj);
        gout[j] = c->k * p + fmin(0.0, cj * pd);
    }
    return 0;
}

/* CSC pattern: column of z_i: rows v_{i-1}, z_i (a zero), v_i, v_{i+1};
 * column of v_i: rows v_{i-1}, z_i, v_i, v_{i+1} (row indices ascending). Values: the
 * active contacts' k and c. */
static int jac(sunrealtype t, N_Vector Y, N_Vector F, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
               N_Vector t3)
{
    (void)t;
    (void)Y;
    (void)F;
    (void)t1;
    (void)t2;
    (void)t3;
    const col *c = ud;
    const long N = c->N;
    sunindextype *cp = SUNSparseMatrix_IndexPointers(J), *ri = SUNSparseMatrix_IndexValues(J);
    sunrealtype *a = SUNSparseMatrix_Data(J);
    const double im = 1.0 / c->m;
    sunindextype nz = 0;
    for (long i = 0; i < N; i++) {
        /* contact i (below sphere i) and i + 1 (above), active or not */
        const double kb = c->active[i] ? c->k : 0.0;
        const double ka = (i + 1 < N && c->active[i + 1]) ? c->k : 0.0;
        const double cb = c->active[i] ? (i == 0 ? c->c0 : c->c1) : 0.0;
        const double ca = (i + 1 < N && c->active[i + 1]) ? c->c1 : 0.0;
        for (int q = 0; q < 2; q++) { /* q = 0: column of z_i, 1: of v_i */
            const double kk = q ? cb : kb, kn = q ? ca : ka;
            cp[2 * i + q] = nz;
            if (i > 0) { /* dv_{i-1}/dt = ... - f_i / m, f_i grows with -z_i */
                ri[nz] = 2 * i - 1;
                a[nz++] = kk * im;
            }
            /* row z_i: dz_i/dt = v_i (a structural zero on the diagonal in
             * the column of z_i, so that CVODE's M = I - gamma J keeps the
             * pattern and SUNMatScaleAddI works in place) */
            ri[nz] = 2 * i;
            a[nz++] = q ? 1.0 : 0.0;
            ri[nz] = 2 * i + 1; /* dv_i/dt = (f_i - f_{i+1}) / m */
            a[nz++] = -(kk + kn) * im;
            if (i + 1 < N) { /* dv_{i+1}/dt = (f_{i+1} - ...) / m */
                ri[nz] = 2 * i + 3;
                a[nz++] = kn * im;
            }
        }
    }
    cp[2 * N] = nz;
    return 0;
}

static int ewt(N_Vector Y, N_Vector W, void *ud)
{
    const col *c = ud;
    const double *y = N_VGetArrayPointer(Y);
    double *w = N_VGetArrayPointer(W);
    for (long i = 0; i < c->N; i++) {
        w[2 * i] = 1.0 / (c->rtol * c->z_scale);
        w[2 * i + 1] = 1.0 / (c->rtol * (fabs(y[2 * i + 1]) + c->v_scale));
    }
    return 0;
}

/* CVODE's counters restart at every CVodeReInit: totals over the run */
typedef struct counts {
    long nst, nfe, nfeLS, nje, nsetups, netf, nni, nncf, nge;
} counts;

/* The integrator's counts, in the lines bench.py reads. */
static void print_counts(const counts *tot)
{
    printf("steps=%ld\nrhs_evals=%ld\njac_evals=%ld\nlin_setups=%ld\nerr_test_fails=%ld\nnewton_iters=%ld\n"
           "newton_fails=%ld\nroot_evals=%ld\n",
           tot->nst, tot->nfe + tot->nfeLS, tot->nje, tot->nsetups, tot->netf, tot->nni, tot->nncf, tot->nge);
}

static void add_counts(void *cv, counts *c)
{
    long v;
    if (CVodeGetNumSteps(cv, &v) == CV_SUCCESS) c->nst += v;
    if (CVodeGetNumRhsEvals(cv, &v) == CV_SUCCESS) c->nfe += v;
    if (CVodeGetNumLinRhsEvals(cv, &v) == CV_SUCCESS) c->nfeLS += v;
    if (CVodeGetNumJacEvals(cv, &v) == CV_SUCCESS) c->nje += v;
    if (CVodeGetNumLinSolvSetups(cv, &v) == CV_SUCCESS) c->nsetups += v;
    if (CVodeGetNumErrTestFails(cv, &v) == CV_SUCCESS) c->netf += v;
    if (CVodeGetNumNonlinSolvIters(cv, &v) == CV_SUCCESS) c->nni += v;
    if (CVodeGetNumNonlinSolvConvFails(cv, &v) == CV_SUCCESS) c->nncf += v;
    if (CVodeGetNumGEvals(cv, &v) == CV_SUCCESS) c->nge += v;
}

#define CK(call)                                                                                                   \
    do {                                                                                                           \
        int flag_ = (call);                                                                                        \
        if (flag_ < 0) {                                                                                           \
            fprintf(stderr, "cvode_ref: %s failed (%d)\n", #call, flag_);                                          \
            return 5;                                                                                              \
        }                                                                                                          \
    } while (0)

static int run(long N, double R, double m, double k, double zeta, double gap, int settled, double t_ramp,
               int smooth, double t_end, double rtol, const char *forces_path)
{
    col c;
    memset(&c, 0, sizeof c);
    c.N = N;
    c.R = R;
    c.m = m;
    c.k = k;
    c.c0 = 2.0 * zeta * sqrt(k * m);
    c.c1 = 2.0 * zeta * sqrt(k * m / 2.0);
    c.t_ramp = t_ramp;
    c.smooth = smooth;
    c.rtol = rtol;
    c.z_scale = m * GRAV / k;
    c.v_scale = GRAV * sqrt(m / k);
    c.active = calloc((size_t)N, sizeof(int));
    int *rootsfound = calloc((size_t)N, sizeof(int));
    if (!c.active || !rootsfound) return 4;

    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx)) return 5;
    N_Vector Y = N_VNew_Serial(2 * N, ctx);
    double *y = N_VGetArrayPointer(Y);
    if (settled) {
        double z = 0.0;
        for (long i = 0; i < N; i++) {
            const double p = (double)(N - i) * m * GRAV / k;
            z += (i == 0 ? R : 2.0 * R) - p;
            y[2 * i] = z;
            y[2 * i + 1] = 0.0;
        }
    } else {
        for (long i = 0; i < N; i++) {
            y[2 * i] = R + gap + (double)i * (2.0 * R + gap);
            y[2 * i + 1] = 0.0;
        }
    }
    {
        double *g0 = malloc((size_t)N * sizeof(double));
        if (!g0) return 4;
        roots(0.0, Y, g0, &c);
        for (long j = 0; j < N; j++) c.active[j] = g0[j] > 0.0;
        free(g0);
    }
    const sunindextype nnz = 8 * (sunindextype)N; /* 4 + 4 per sphere, minus the ends */
    SUNMatrix A = SUNSparseMatrix(2 * N, 2 * N, nnz, CSC_MAT, ctx);
    SUNLinearSolver LS = SUNLinSol_KLU(Y, A, ctx);
    void *cv = CVodeCreate(CV_BDF, ctx);
    if (!A || !LS || !cv) return 5;
    CK(CVodeInit(cv, rhs, 0.0, Y));
    CK(CVodeSetUserData(cv, &c));
    CK(CVodeWFtolerances(cv, ewt));
    CK(CVodeSetLinearSolver(cv, LS, A));
    CK(CVodeSetJacFn(cv, jac));
    CK(CVodeSetMaxNumSteps(cv, 100000000L));
    CK(CVodeSetStabLimDet(cv, SUNTRUE));
    CK(CVodeRootInit(cv, (int)N, roots));
    CK(CVodeSetNoInactiveRootWarn(cv));
    int ramp_pending = t_ramp > 0.0 && t_ramp < t_end;
    CK(CVodeSetStopTime(cv, ramp_pending ? t_ramp : t_end));

    long events = 0, reinits = 0, root_returns = 0, closes = 0, opens = 0;
    counts tot;
    memset(&tot, 0, sizeof tot);
    int fresh = 0;
    double t = 0.0;
    const double t0 = now(), cpu0 = cpu_now();
    while (t < t_end) {
        long nst0 = 0, nst1 = 0;
        if (fresh) {
            CK(CVodeSetLSetupFrequency(cv, 1));
            CK(CVodeSetJacEvalFrequency(cv, 1));
            CVodeGetNumSteps(cv, &nst0);
        }
        const int flag = CVode(cv, t_end, Y, &t, fresh ? CV_ONE_STEP : CV_NORMAL);
        if (fresh && CVodeGetNumSteps(cv, &nst1) == CV_SUCCESS && nst1 > nst0) {
            CK(CVodeSetLSetupFrequency(cv, 0));
            CK(CVodeSetJacEvalFrequency(cv, 0));
            fresh = 0;
        }
        if (flag < 0) {
            printf("status=failed\nflag=%s\nt_failed=%.9e\n", CVodeGetReturnFlagName(flag), t);
            return 3;
        }
        if (flag == CV_TSTOP_RETURN && ramp_pending && t >= t_ramp) {
            /* the kink of the ramp: go on to the end */
            ramp_pending = 0;
            CK(CVodeSetStopTime(cv, t_end));
            continue;
        }
        if (flag == CV_ROOT_RETURN) {
            root_returns++;
            CK(CVodeGetRootInfo(cv, rootsfound));
            int jump = 0;
            for (long j = 0; j < N; j++) {
                if (!rootsfound[j]) continue;
                const int want = rootsfound[j] > 0;
                if (want == c.active[j]) continue;
                double p, pd, cj;
                contact(&c, j, y, &p, &pd, &cj);
                if (want && cj * pd > 0.0) jump = 1; /* closes at p = 0: force jumps to c pdot */
                c.active[j] = want;
                events++;
                if (want) closes++;
                else opens++;
            }
            if (jump) {
                add_counts(cv, &tot);
                CK(CVodeReInit(cv, t, Y));
                reinits++;
                fresh = 0;
            } else {
                fresh = 1;
            }
        }
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);

    add_counts(cv, &tot);

    double *f = malloc((size_t)N * sizeof(double));
    if (!f) return 4;
    double vmax = 0.0;
    long nactive = 0;
    int finite = 1;
    for (long j = 0; j < N; j++) {
        double p, pd, cj;
        contact(&c, j, y, &p, &pd, &cj);
        f[j] = c.active[j] ? fmax(0.0, c.k * p + cj * pd) : 0.0;
        nactive += c.active[j];
        vmax = fmax(vmax, fabs(y[2 * j + 1]));
        finite &= isfinite(y[2 * j]) && isfinite(y[2 * j + 1]);
    }
    if (!finite) {
        printf("status=unstable\n");
        return 3;
    }
    printf("case=%s\nstatus=ok\nN=%ld\nrtol=%.3e\nz_scale=%.9e\nv_scale=%.9e\n", settled ? "ramp" : "column", N, rtol,
           c.z_scale, c.v_scale);
    print_counts(&tot);
    printf("events=%ld\ncloses=%ld\nopens=%ld\nroot_returns=%ld\nreinits=%ld\n", events, closes, opens, root_returns,
           reinits);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\n", wall, peak_rss_kb());
    printf("force_bottom=%.12e\nforce_top=%.12e\nactive_contacts=%ld\nmax_speed=%.12e\ntop_height=%.12e\n", f[0],
           f[N - 1], nactive, vmax, y[2 * N - 2]);
    if (forces_path) {
        FILE *fp = fopen(forces_path, "w");
        if (!fp) {
            fprintf(stderr, "cvode_ref: cannot write %s\n", forces_path);
            return 4;
        }
        for (long j = 0; j < N; j++) fprintf(fp, "%.15e\n", f[j]);
        fclose(fp);
    }
    free(f);
    CVodeFree(&cv);
    SUNLinSolFree(LS);
    SUNMatDestroy(A);
    N_VDestroy(Y);
    SUNContext_Free(&ctx);
    free(c.active);
    free(rootsfound);
    return 0;
}

/* ---- stick-slip: a block dragged across a floor through a spring ---------
 * The model of explicit_ref stickslip (bench/explicit_ref.c): x, u along the
 * floor, spring ks to an anchor at V t, normal force m G, friction
 *   stick (adhesion): F = -C u             while C |u| < mu(|u|) m G,
 *   slip (saturated): F = -mu(|u|) m G sign(u),
 * Renard's two-level mu (mu_s up to v1, cubic drop to mu_k by v2; C1, so
 * no breakpoint events are needed for BDF). Modes switch at roots of
 * C |u| - (1 +- 1e-6) mu(|u|) m G (ricochet's band against chattering:
 * slip starts above (1 + 1e-6) L, stick again below (1 - 1e-6) L), and a
 * second root, u (times its sign at the slip onset) in slip, catches a
 * reversal that a step jumps across the narrow window |u| < L/C. The force is
 * continuous across a switch up to that band, so no CVodeReInit there (only
 * at a reversal, where it jumps); the Jacobian jumps (-C/m to ~0), so one
 * step with a fresh Jacobian follows.
 * Dense 2 x 2 linear algebra (SUNLinSol_Dense). Error weights: the same as
 * ricochet's deck of the bench, CVodeSVtolerances with atol_x = 1e-3 rtol m,
 * atol_u = 1e-2 rtol m/s.
 */
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct ssm {
    double m, ks, C, mus, muk, v1, v2, V, Fn;
    int slip;
    double dir; /* sign of u when the slip started */
} ssm;

static double ss_mu(const ssm *s, double v)
{
    if (v <= s->v1) return s->mus;
    if (v < s->v2) {
        const double w = (v - s->v1) / (s->v2 - s->v1);
        return s->mus + (s->muk - s->mus) * (3.0 - 2.0 * w) * w * w;
    }
    return s->muk;
}

static int ss_rhs(sunrealtype t, N_Vector Y, N_Vector Yd, void *ud)
{
    const ssm *s = ud;
    const double *y = N_VGetArrayPointer(Y);
    double *yd = N_VGetArrayPointer(Yd);
    const double u = y[1];
    double f;
    if (s->slip) f = -ss_mu(s, fabs(u)) * s->Fn * (u > 0.0 ? 1.0 : (u < 0.0 ? -1.0 : 0.0));
    else f = -s->C * u;
    yd[0] = u;
    yd[1] = (s->ks * (s->V * t - y[0]) + f) / s->m;
    return 0;
}

static int ss_jac(sunrealtype t, N_Vector Y, N_Vector F, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
                  N_Vector t3)
{
    (void)t;
    (void)F;
    (void)t1;
    (void)t2;
    (void)t3;
    const ssm *s = ud;
    (void)Y;
    /* saturated: d mu / d|u| is left out, as in ricochet's Jacobian. In the
     * drop between v1 and v2 it is a large positive feedback (+8e5 1/s here),
     * and with it Newton fails where h gamma lambda ~ 1 */
    const double dfdu = s->slip ? 0.0 : -s->C;
    SM_ELEMENT_D(J, 0, 0) = 0.0;
    SM_ELEMENT_D(J, 0, 1) = 1.0;
    SM_ELEMENT_D(J, 1, 0) = -s->ks / s->m;
    SM_ELEMENT_D(J, 1, 1) = dfdu / s->m;
    return 0;
}

static int ss_root(sunrealtype t, N_Vector Y, sunrealtype *g, void *ud)
{
    (void)t;
    const ssm *s = ud;
    const double a = fabs(N_VGetArrayPointer(Y)[1]);
    const double L = ss_mu(s, a) * s->Fn;
    g[0] = s->C * a - (s->slip ? 1.0 - 1e-6 : 1.0 + 1e-6) * L;
    /* the sliding reverses: the window |u| < L / C where g[0] dips below
     * zero is ~5 um/s wide, a step can jump it (ricochet's reversal root) */
    g[1] = s->slip ? N_VGetArrayPointer(Y)[1] * s->dir : 1.0;
    return 0;
}

/* A CVODE BDF integrator of a 2-state model with a dense matrix: the
 * stick-slip and the drag, each a block's position and velocity, weighted
 * absolutely at 1e-3 rtol m and 1e-2 rtol m/s. */
typedef struct cv2 {
    SUNContext ctx;
    N_Vector Y, AT;
    SUNMatrix A;
    SUNLinearSolver LS;
    void *cv;
} cv2;

static int cv2_open(cv2 *c, CVRhsFn rhs, CVLsJacFn jac, void *ud, double rtol, int nroot, CVRootFn root,
                    int stablim, double t_end)
{
    memset(c, 0, sizeof *c);
    if (SUNContext_Create(NULL, &c->ctx)) return 5;
    c->Y = N_VNew_Serial(2, c->ctx);
    c->AT = N_VNew_Serial(2, c->ctx);
    double *y = N_VGetArrayPointer(c->Y);
    y[0] = 0.0;
    y[1] = 0.0;
    N_VGetArrayPointer(c->AT)[0] = 1e-3 * rtol;
    N_VGetArrayPointer(c->AT)[1] = 1e-2 * rtol;
    c->A = SUNDenseMatrix(2, 2, c->ctx);
    c->LS = SUNLinSol_Dense(c->Y, c->A, c->ctx);
    void *cv = c->cv = CVodeCreate(CV_BDF, c->ctx);
    if (!c->A || !c->LS || !cv) return 5;
    CK(CVodeInit(cv, rhs, 0.0, c->Y));
    CK(CVodeSetUserData(cv, ud));
    CK(CVodeSVtolerances(cv, rtol, c->AT));
    CK(CVodeSetLinearSolver(cv, c->LS, c->A));
    CK(CVodeSetJacFn(cv, jac));
    CK(CVodeSetMaxNumSteps(cv, 100000000L));
    if (stablim) CK(CVodeSetStabLimDet(cv, SUNTRUE));
    CK(CVodeRootInit(cv, nroot, root));
    CK(CVodeSetStopTime(cv, t_end));
    return 0;
}

static void cv2_close(cv2 *c)
{
    CVodeFree(&c->cv);
    SUNLinSolFree(c->LS);
    SUNMatDestroy(c->A);
    N_VDestroy(c->Y);
    N_VDestroy(c->AT);
    SUNContext_Free(&c->ctx);
}

static int run_stickslip(double m, double ks, double C, double mus, double muk, double v1, double v2, double V,
                         double t_end, double rtol, const char *events_path)
{
    ssm s = {m, ks, C, mus, muk, v1, v2, V, m * GRAV, 0, 1.0};
    int rf[2] = {0, 0};
    long reinits = 0;
    cv2 c;
    const int st = cv2_open(&c, ss_rhs, ss_jac, &s, rtol, 2, ss_root, 1, t_end);
    if (st) return st;
    void *cv = c.cv;
    N_Vector Y = c.Y;
    double *y = N_VGetArrayPointer(Y);
    long cap = 1024, nrec = 0, events = 0, slips = 0;
    double *rt = malloc((size_t)cap * sizeof(double)), *rx = malloc((size_t)cap * sizeof(double));
    int *rk = malloc((size_t)cap * sizeof(int));
    if (!rt || !rx || !rk) return 4;
    counts tot;
    memset(&tot, 0, sizeof tot);
    int fresh = 0;
    double t = 0.0;
    const double t0 = now(), cpu0 = cpu_now();
    while (t < t_end) {
        long nst0 = 0, nst1 = 0;
        if (fresh) {
            CK(CVodeSetLSetupFrequency(cv, 1));
            CK(CVodeSetJacEvalFrequency(cv, 1));
            CVodeGetNumSteps(cv, &nst0);
        }
        const int flag = CVode(cv, t_end, Y, &t, fresh ? CV_ONE_STEP : CV_NORMAL);
        if (fresh && CVodeGetNumSteps(cv, &nst1) == CV_SUCCESS && nst1 > nst0) {
            CK(CVodeSetLSetupFrequency(cv, 0));
            CK(CVodeSetJacEvalFrequency(cv, 0));
            fresh = 0;
        }
        if (flag < 0) {
            printf("status=failed\nflag=%s\nt_failed=%.9e\n", CVodeGetReturnFlagName(flag), t);
            return 3;
        }
        if (flag == CV_ROOT_RETURN) {
            CK(CVodeGetRootInfo(cv, rf));
            const int reversal = s.slip && rf[1] && !rf[0];
            s.slip = !s.slip;
            if (s.slip) s.dir = y[1] >= 0.0 ? 1.0 : -1.0;
            events++;
            slips += s.slip;
            if (nrec == cap) {
                cap *= 2;
                rt = realloc(rt, (size_t)cap * sizeof(double));
                rx = realloc(rx, (size_t)cap * sizeof(double));
                rk = realloc(rk, (size_t)cap * sizeof(int));
                if (!rt || !rx || !rk) return 4;
            }
            rt[nrec] = t;
            rx[nrec] = y[0];
            rk[nrec++] = s.slip;
            /* restart at every switch, as ricochet does for this law: at a
             * reversal the force jumps (limit -> ~0); at the other switches
             * the force is continuous but its Jacobian jumps by C/m = 1.4e6
             * 1/s, and a continued BDF history fails (Newton, missed stick) */
            (void)reversal;
            add_counts(cv, &tot);
            CK(CVodeReInit(cv, t, Y));
            reinits++;
            fresh = 0;
        }
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    add_counts(cv, &tot);
    printf("case=stickslip\nstatus=ok\nrtol=%.3e\n", rtol);
    print_counts(&tot);
    printf("events=%ld\nslips=%ld\nreinits=%ld\nwall_time=%.9e\npeak_rss_kb=%ld\nfinal_x=%.12e\nfinal_u=%.12e\n", events,
           slips, reinits, wall, peak_rss_kb(), y[0], y[1]);
    if (events_path) {
        FILE *fp = fopen(events_path, "w");
        if (!fp) return 4;
        for (long q = 0; q < nrec; q++) fprintf(fp, "%s %.12e %.12e\n", rk[q] ? "slip" : "stick", rt[q], rx[q]);
        fclose(fp);
    }
    free(rt);
    free(rx);
    free(rk);
    cv2_close(&c);
    return 0;
}

/* ---- drag to the slip: the model of explicit_ref drag --------------------
 * x, u along the floor, the pull rate t [N], ricochet's TYPE6 stick spring
 * K_t anchored at the start and the critical stick damper c_t = 2 sqrt(K_t
 * m): m u' = rate t - K_t x - c_t u. Normal force m G. One root, the slip
 * onset |K_t x + c_t u| - mu m G; the run ends there or at t_end. Outputs
 * (CV_NORMAL, CVODE's interpolation) at the multiples of dt_out before the
 * slip: "t F" lines, F = -K_t x - c_t u the friction force on the block.
 * Dense 2 x 2; error weights atol_x = 1e-3 rtol m, atol_u = 1e-2 rtol m/s
 * (as the stick-slip drag's).
 */
typedef struct dragm {
    double m, kt, ct, rate, lim;
} dragm;

static int drag_rhs(sunrealtype t, N_Vector Y, N_Vector Yd, void *ud)
{
    const dragm *d = ud;
    const double *y = N_VGetArrayPointer(Y);
    double *yd = N_VGetArrayPointer(Yd);
    yd[0] = y[1];
    yd[1] = (d->rate * t - d->kt * y[0] - d->ct * y[1]) / d->m;
    return 0;
}

static int drag_jac(sunrealtype t, N_Vector Y, N_Vector F, SUNMatrix J, void *ud, N_Vector t1, N_Vector t2,
                    N_Vector t3)
{
    (void)t;
    (void)Y;
    (void)F;
    (void)t1;
    (void)t2;
    (void)t3;
    const dragm *d = ud;
    SM_ELEMENT_D(J, 0, 0) = 0.0;
    SM_ELEMENT_D(J, 0, 1) = 1.0;
    SM_ELEMENT_D(J, 1, 0) = -d->kt / d->m;
    SM_ELEMENT_D(J, 1, 1) = -d->ct / d->m;
    return 0;
}

static int drag_root(sunrealtype t, N_Vector Y, sunrealtype *g, void *ud)
{
    (void)t;
    const dragm *d = ud;
    const double *y = N_VGetArrayPointer(Y);
    g[0] = fabs(d->kt * y[0] + d->ct * y[1]) - d->lim;
    return 0;
}

static int run_drag(double m, double kt, double mu, double rate, double t_end, double dt_out, double rtol,
                    const char *forces_path)
{
    dragm d = {m, kt, 2.0 * sqrt(kt * m), rate, mu * m * GRAV};
    cv2 c;
    const int st = cv2_open(&c, drag_rhs, drag_jac, &d, rtol, 1, drag_root, 0, t_end);
    if (st) return st;
    void *cv = c.cv;
    N_Vector Y = c.Y;
    double *y = N_VGetArrayPointer(Y);
    const long nout = (long)floor(t_end / dt_out + 0.5);
    double *rec_t = malloc((size_t)(nout + 1) * sizeof(double)), *rec_f = malloc((size_t)(nout + 1) * sizeof(double));
    if (!rec_t || !rec_f) return 4;
    long nrec = 0;
    rec_t[nrec] = 0.0;
    rec_f[nrec++] = 0.0;
    double t = 0.0, t_slip = -1.0;
    const double t0 = now(), cpu0 = cpu_now();
    for (long k = 1; k <= nout; k++) {
        const double tout = k == nout ? t_end : (double)k * dt_out;
        const int flag = CVode(cv, tout, Y, &t, CV_NORMAL);
        if (flag < 0) {
            printf("status=failed\nflag=%s\nt_failed=%.9e\n", CVodeGetReturnFlagName(flag), t);
            return 3;
        }
        if (flag == CV_ROOT_RETURN) {
            t_slip = t;
            break;
        }
        rec_t[nrec] = t;
        rec_f[nrec++] = -d.kt * y[0] - d.ct * y[1];
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    counts tot;
    memset(&tot, 0, sizeof tot);
    add_counts(cv, &tot);
    printf("case=drag\nstatus=ok\nrtol=%.3e\n", rtol);
    print_counts(&tot);
    printf("events=%d\nreinits=0\nrecords=%ld\nt_slip=%.12e\nwall_time=%.9e\npeak_rss_kb=%ld\n", t_slip >= 0.0, nrec,
           t_slip, wall, peak_rss_kb());
    if (forces_path) {
        FILE *fp = fopen(forces_path, "w");
        if (!fp) return 4;
        for (long q = 0; q < nrec; q++) fprintf(fp, "%.12e %.17e\n", rec_t[q], rec_f[q]);
        fclose(fp);
    }
    free(rec_t);
    free(rec_f);
    cv2_close(&c);
    return 0;
}

static void usage(FILE *fp)
{
    fprintf(fp, "usage: cvode_ref column N R m k zeta gap t_end rtol [FORCES_FILE]\n"
                "       cvode_ref ramp N R m k zeta t_ramp t_end rtol [FORCES_FILE]\n"
                "       cvode_ref sramp N R m k zeta t_ramp t_end rtol [FORCES_FILE]\n"
                "       cvode_ref stickslip m ks C mu_s mu_k v1 v2 V t_end rtol [EVENTS_FILE]\n"
                "       cvode_ref drag m K_t mu rate t_end dt_out rtol [FORCES_FILE]\n");
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "stickslip") && (argc == 12 || argc == 13))
        return run_stickslip(arg(argv, 2), arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                             arg(argv, 8), arg(argv, 9), arg(argv, 10), arg(argv, 11), argc == 13 ? argv[12] : NULL);
    if (argc >= 2 && !strcmp(argv[1], "drag") && (argc == 9 || argc == 10))
        return run_drag(arg(argv, 2), arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                        arg(argv, 8), argc == 10 ? argv[9] : NULL);
    if (argc < 2 || (argc != 10 && argc != 11)) {
        usage(stderr);
        return 2;
    }
    const int is_col = !strcmp(argv[1], "column"), is_sramp = !strcmp(argv[1], "sramp");
    const int is_ramp = !strcmp(argv[1], "ramp") || is_sramp;
    const double N = arg(argv, 2);
    if ((!is_col && !is_ramp) || N < 1 || N != floor(N)) {
        usage(stderr);
        return 2;
    }
    const char *ff = argc == 11 ? argv[10] : NULL;
    if (is_col)
        return run((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7), 0, 0.0, 0,
                   arg(argv, 8), arg(argv, 9), ff);
    return run((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), 0.0, 1, arg(argv, 7), is_sramp,
               arg(argv, 8), arg(argv, 9), ff);
}
