/*
 * explicit_ref: the explicit reference of the ricochet benchmarks.
 *
 * Integrates the SAME equations as ricochet for 1-D vertical models of
 * spheres (translation only, no rotation is excited in these models) with
 * the central-difference scheme of explicit crash codes:
 *
 *     a_n       = a(x_n, v_{n-1/2})          forces at the new positions,
 *                                            damping with the latest
 *                                            half-step velocity
 *     v_{n+1/2} = v_{n-1/2} + dt a_n
 *     x_{n+1}   = x_n + dt v_{n+1/2}
 *
 * started with v_{-1/2} = v_0 - dt/2 a_0 (so v_{1/2} = v_0 + dt/2 a_0).
 *
 * Contact law (ricochet's TYPE6 with a linear load curve and Visc):
 * penetration p = -(gap distance), approach rate pdot = dp/dt,
 *     f = max(0, k p + c pdot)   when p > 0,   f = 0 otherwise,
 * i.e. the total normal force is clipped at zero; the contact is "active"
 * while f > 0. Every change of that state is counted as an event.
 *
 * Stable step (undamped bound times the damped correction, exact for a
 * single damped oscillator under this scheme, see bench/README.md):
 *     dt = safety * 2 / omega_max * (sqrt(1 + zeta_max^2) - zeta_max),
 * drop:   omega_max = sqrt(k/m), zeta_max = c / (2 sqrt(k m));
 * column: omega_max = 2 sqrt(k/m) (Gershgorin bound of M^-1 K, the
 *         highest mode of the chain), 2 zeta_max omega_max = Gershgorin
 *         bound of M^-1 C (max row sum), safety = 0.9.
 * The step is then shrunk by dt_factor and rounded down so that t_end is a
 * whole number of steps.
 *
 * Usage:
 *   explicit_ref drop   m k c h t_end dt_factor
 *       one sphere (mass m) whose lowest point starts h above a fixed floor,
 *       at rest, gravity 9.81 m/s^2 downwards. Prints per bounce the impact
 *       and rebound velocities (located to second order, see below).
 *   explicit_ref ramp N R m k zeta t_ramp t_end dt_factor [FORCES_FILE]
 *   explicit_ref rampref N R m k zeta t_ramp t_end h [FORCES_FILE]
 *       quasi-static column: the column below, started at its static state
 *       under G (contact j carries (N - j) m G, at rest), gravity ramped
 *       linearly G -> 2 G over t_ramp and held until t_end; central
 *       difference (ramp) or the RK4 reference (rampref, no step across the
 *       kink at t_ramp).
 *   explicit_ref sramp | srampref ...  (same arguments)
 *       the same with the smooth ramp G (1 + (1 - cos(pi t / t_ramp)) / 2).
 *   explicit_ref stickslip m ks C mu_s mu_k v1 v2 V t_end dt_factor [EVENTS_FILE]
 *       a block dragged across a floor through a spring (see run_stickslip)
 *   explicit_ref drag m K_t mu rate t_end dt_out dt_factor [FORCES_FILE]
 *       a block on a floor held by a TYPE6 stick spring, pulled by a force
 *       ramped at rate [N/s] until it slips (see run_drag)
 *   explicit_ref column N R m k zeta gap t_end dt_factor [FORCES_FILE]
 *       N spheres of radius R, mass m stacked on a floor, gap `gap` between
 *       neighbours and above the floor, at rest, gravity. Floor contact
 *       c = 2 zeta sqrt(k m), sphere-sphere c = 2 zeta sqrt(k m/2).
 *       Writes the final contact forces (contact 0 = floor, j = between
 *       spheres j-1 and j) one per line to FORCES_FILE when given.
 *
 * Output: key=value lines on stdout. wall_time is measured with
 * clock_gettime(CLOCK_MONOTONIC) around the integration loop only (no I/O);
 * peak_rss_kb is getrusage(RUSAGE_SELF).ru_maxrss.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* M_PI */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#define GRAV 9.81
#define SAFETY 0.9
#define MAX_BOUNCE 1000

/* Quasi-static column ("ramp" and "rampref"): the column starts at its
 * static state under G (contact j carries (N - j) m G, p_j = (N - j) m G / k,
 * velocities 0) and gravity is ramped linearly from G to 2 G over t_ramp,
 * then held. */
static int settled_start = 0;
static double ramp_time = 0.0; /* > 0: the ramp */
static int ramp_smooth = 0;    /* sramp, srampref: (1 - cos(pi t / t_ramp)) / 2 */

static double gravity(double t)
{
    if (ramp_time <= 0.0) return GRAV;
    double s = t <= 0.0 ? 0.0 : (t >= ramp_time ? 1.0 : t / ramp_time);
    if (ramp_smooth) s = 0.5 * (1.0 - cos(M_PI * s));
    return GRAV * (1.0 + s);
}

/* initial heights of the column: gaps, or the static state */
static void column_start(long N, double R, double m, double k, double gap, double *z)
{
    double zz = 0.0;
    for (long i = 0; i < N; i++) {
        if (settled_start) {
            zz += (i == 0 ? R : 2.0 * R) - (double)(N - i) * m * GRAV / k;
            z[i] = zz;
        } else {
            z[i] = R + gap + (double)i * (2.0 * R + gap);
        }
    }
}

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
        fprintf(stderr, "explicit_ref: bad number '%s'\n", argv[k]);
        exit(2);
    }
    return v;
}

/* Stable step of the damped central-difference scheme. */
static double stable_step(double omega, double zeta)
{
    return 2.0 / omega * (sqrt(1.0 + zeta * zeta) - zeta);
}

/* Number of steps and step so that t_end = nsteps * dt, dt <= dtmax. */
static long step_count(double t_end, double dtmax, double *dt)
{
    long n = (long)ceil(t_end / dtmax - 1e-9);
    if (n < 1) n = 1;
    *dt = t_end / (double)n;
    return n;
}

/* ---- drop ---------------------------------------------------------------
 * State: height d of the lowest point above the floor, velocity v (up > 0).
 * Penetration p = -d, pdot = -v. Events are located after the fact:
 *  - impact: the step that first sees p > 0 while inactive; the previous
 *    step is in free flight, where the scheme is exact for constant gravity
 *    (velocity Verlet form), so the impact time and velocity follow from the
 *    ballistic solution from that step: v_in = -sqrt(v^2 + 2 g d).
 *  - rebound: the force k p + c pdot (as the scheme evaluates it) crosses
 *    zero between steps n-1 and n; the crossing time t* is interpolated
 *    linearly, and the rebound velocity is the free-flight velocity at
 *    step n carried back to t*: v_out = v_n + g (t_n - t*).
 * Velocities at whole steps: v_n = v_{n-1/2} + dt/2 a_n.
 */
static int run_drop(double m, double k, double c, double h, double t_end, double dt_factor)
{
    const double omega = sqrt(k / m), zeta = c / (2.0 * sqrt(k * m));
    const double dt_stable = SAFETY * stable_step(omega, zeta);
    double dt;
    const long nsteps = step_count(t_end, dt_factor * dt_stable, &dt);
    static double t_in[MAX_BOUNCE], v_in[MAX_BOUNCE], t_out[MAX_BOUNCE], v_out[MAX_BOUNCE];
    int nin = 0, nout = 0;
    long events = 0, force_evals = 0;

    const double t0 = now(), cpu0 = cpu_now();
    double d = h, v = 0.0;            /* d_n, v at whole step n (start) */
    double f_raw = 0.0, f = 0.0;
    int active = 0;
    /* force at step 0 (at rest above the floor: zero) */
    double a = -GRAV;
    double vh = v - 0.5 * dt * a;     /* v_{-1/2} */
    double d_prev = d, v_prev = v, fraw_prev = 0.0, t_prev = 0.0;
    for (long n = 0; n <= nsteps; n++) {
        const double t = (double)n * dt;
        /* forces at x_n with the latest half-step velocity */
        const double p = -d, pdot = -vh;
        f_raw = k * p + c * pdot;
        f = (p > 0.0 && f_raw > 0.0) ? f_raw : 0.0;
        force_evals++;
        a = -GRAV + f / m;
        const double vn = vh + 0.5 * dt * a; /* velocity at whole step n */
        const int now_active = f > 0.0;
        if (now_active != active) {
            events++;
            if (now_active && nin < MAX_BOUNCE) {
                /* impact: ballistic from step n-1 (free flight) */
                const double vi = -sqrt(v_prev * v_prev + 2.0 * GRAV * d_prev);
                t_in[nin] = t_prev + (v_prev - vi) / GRAV;
                v_in[nin++] = vi;
            } else if (!now_active && nout < MAX_BOUNCE && nout < nin) {
                /* rebound: the raw force crosses zero in (t_prev, t] */
                double s = fraw_prev / (fraw_prev - f_raw);
                if (!(s >= 0.0 && s <= 1.0)) s = 1.0;
                const double ts = t_prev + s * dt;
                t_out[nout] = ts;
                v_out[nout++] = vn + GRAV * (t - ts);
            }
            active = now_active;
        }
        d_prev = d;
        v_prev = vn;
        fraw_prev = f_raw;
        t_prev = t;
        if (n == nsteps) break;
        vh += dt * a;
        d += dt * vh;
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    if (!isfinite(d) || !isfinite(vh)) {
        printf("status=unstable\n");
        return 3;
    }
    printf("case=drop\nstatus=ok\n");
    printf("dt=%.9e\ndt_stable=%.9e\nomega_max=%.9e\nzeta_max=%.9e\n", dt, dt_stable / SAFETY, omega, zeta);
    printf("steps=%ld\nforce_evals=%ld\ncontact_evals=%ld\nevents=%ld\n", nsteps, force_evals, force_evals, events);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\n", wall, peak_rss_kb());
    printf("final_height=%.12e\nfinal_velocity=%.12e\n", d, v_prev);
    printf("bounces=%d\n", nout);
    for (int b = 0; b < nout; b++)
        printf("bounce=%d t_in=%.12e v_in=%.12e t_out=%.12e v_out=%.12e ratio=%.12e\n", b + 1, t_in[b], v_in[b],
               t_out[b], v_out[b], -v_out[b] / v_in[b]);
    return 0;
}

/* ---- column --------------------------------------------------------------
 * Sphere i (0 = bottom) centre height z_i, velocity v_i (up > 0).
 * Contact 0: floor, p_0 = R - z_0, pdot_0 = -v_0.
 * Contact j >= 1: spheres j-1, j: p_j = 2R - (z_j - z_{j-1}),
 *                 pdot_j = -(v_j - v_{j-1}).
 * Sphere i gets +f_i (contact below) and -f_{i+1} (contact above).
 */
static void column_forces(long N, double k, double c0, double c1, double R, const double *z, const double *vh,
                          double *f, int *active, long *events)
{
    for (long j = 0; j <= N - 1; j++) {
        double p, pdot, c;
        if (j == 0) {
            p = R - z[0];
            pdot = -vh[0];
            c = c0;
        } else {
            p = 2.0 * R - (z[j] - z[j - 1]);
            pdot = -(vh[j] - vh[j - 1]);
            c = c1;
        }
        const double fr = k * p + c * pdot;
        f[j] = (p > 0.0 && fr > 0.0) ? fr : 0.0;
        const int act = f[j] > 0.0;
        if (act != active[j]) {
            (*events)++;
            active[j] = act;
        }
    }
}

static int run_column(long N, double R, double m, double k, double zeta, double gap, double t_end,
                      double dt_factor, const char *forces_path)
{
    if (N < 1) return 2;
    const double c0 = 2.0 * zeta * sqrt(k * m), c1 = 2.0 * zeta * sqrt(k * m / 2.0);
    /* Gershgorin bounds: rows of M^-1 K and M^-1 C */
    const double kbound = (N == 1 ? 1.0 : 4.0) * k / m;
    const double cbound = (N == 1 ? c0 : fmax(c0 + 2.0 * c1, 4.0 * c1)) / m;
    const double omega = sqrt(kbound), zmax = cbound / (2.0 * omega);
    const double dt_stable = SAFETY * stable_step(omega, zmax);
    double dt;
    const long nsteps = step_count(t_end, dt_factor * dt_stable, &dt);
    double *z = malloc((size_t)N * sizeof(double)), *vh = malloc((size_t)N * sizeof(double));
    double *f = malloc((size_t)N * sizeof(double)), *a = malloc((size_t)N * sizeof(double));
    int *active = calloc((size_t)N, sizeof(int));
    if (!z || !vh || !f || !a || !active) {
        fprintf(stderr, "explicit_ref: out of memory\n");
        return 4;
    }
    column_start(N, R, m, k, gap, z);
    for (long i = 0; i < N; i++) vh[i] = 0.0;
    if (settled_start) /* the modes of the static state, not events */
        for (long j = 0; j < N; j++) active[j] = 1;
    long events = 0, force_evals = 0;

    const double t0 = now(), cpu0 = cpu_now();
    /* v_{-1/2} = v_0 - dt/2 a_0 */
    column_forces(N, k, c0, c1, R, z, vh, f, active, &events);
    for (long i = 0; i < N; i++) {
        a[i] = -gravity(0.0) + (f[i] - (i + 1 < N ? f[i + 1] : 0.0)) / m;
        vh[i] -= 0.5 * dt * a[i];
    }
    for (long n = 0; n < nsteps; n++) {
        column_forces(N, k, c0, c1, R, z, vh, f, active, &events);
        force_evals++;
        const double gn = gravity((double)n * dt);
        for (long i = 0; i < N; i++) {
            const double ai = -gn + (f[i] - (i + 1 < N ? f[i + 1] : 0.0)) / m;
            vh[i] += dt * ai;
            z[i] += dt * vh[i];
        }
    }
    /* forces at t_end (as the scheme evaluates them there) */
    column_forces(N, k, c0, c1, R, z, vh, f, active, &events);
    force_evals++;
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);

    double vmax = 0.0, ekin = 0.0;
    int finite = 1;
    for (long i = 0; i < N; i++) {
        /* velocity at t_end: v_{n-1/2} + dt/2 a_n */
        const double ai = -gravity(t_end) + (f[i] - (i + 1 < N ? f[i + 1] : 0.0)) / m;
        const double vi = vh[i] + 0.5 * dt * ai;
        vmax = fmax(vmax, fabs(vi));
        ekin += 0.5 * m * vi * vi;
        finite &= isfinite(z[i]) && isfinite(vi);
    }
    if (!finite) {
        printf("status=unstable\n");
        return 3;
    }
    long nactive = 0;
    for (long j = 0; j < N; j++) nactive += active[j];
    printf("case=column\nstatus=ok\nN=%ld\n", N);
    printf("dt=%.9e\ndt_stable=%.9e\nomega_max=%.9e\nzeta_max=%.9e\n", dt, dt_stable / SAFETY, omega, zmax);
    printf("steps=%ld\nforce_evals=%ld\ncontact_evals=%ld\nevents=%ld\n", nsteps, force_evals, force_evals * N,
           events);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\n", wall, peak_rss_kb());
    printf("force_bottom=%.12e\nforce_top=%.12e\nactive_contacts=%ld\n", f[0], f[N - 1], nactive);
    printf("max_speed=%.12e\nkinetic_energy=%.12e\ntop_height=%.12e\n", vmax, ekin, z[N - 1]);
    if (forces_path) {
        FILE *fp = fopen(forces_path, "w");
        if (!fp) {
            fprintf(stderr, "explicit_ref: cannot write %s\n", forces_path);
            return 4;
        }
        for (long j = 0; j < N; j++) fprintf(fp, "%.15e\n", f[j]);
        fclose(fp);
    }
    free(z);
    free(vh);
    free(f);
    free(a);
    free(active);
    return 0;
}

/* ---- reference: event-located RK4 ----------------------------------------
 * An independent, high-order integration of the same column equations, used
 * as the accuracy reference (the central-difference scheme above is only
 * first order: the lagged damping velocity and the contact onset falling
 * between steps both give O(dt) errors). Classical RK4 with a fixed step h,
 * and the contact modes switched only at located events, so that the
 * right-hand side is smooth inside every step:
 *   contact j is active iff g_j = min(p_j, k p_j + c_j pdot_j) > 0
 * (law "clip": the max(0, k p + c pdot) law above), or, with law
 * "noreclose", an open contact closes only when p_j crosses zero upwards and
 * a closed one opens when k p + c pdot crosses zero (the event rule of
 * ricochet before its RELEASED mode: it differs from the clipped law when a
 * contact that opened at zero force comes back while still penetrating, and
 * lets the bodies pass through each other; kept as a diagnostic).
 * A step that would change any mode is cut by bisection on its length down
 * to 1e-13 s; the modes are flipped at the end of the cut step.
 */
typedef struct chain {
    long N;
    double R, m, k, c0, c1;
    int law_noreclose;
    int *active;
    double *z, *v;   /* state */
    double *zt, *vt; /* stage state */
    double *k1z, *k1v, *k2z, *k2v, *k3z, *k3v, *k4z, *k4v;
    double *z1, *v1; /* candidate end of step */
    double t;        /* time of the stage being evaluated */
    long rhs_evals;
} chain;

static void chain_contact(const chain *ch, long j, const double *z, const double *v, double *p, double *fr)
{
    double pd, c;
    if (j == 0) {
        *p = ch->R - z[0];
        pd = -v[0];
        c = ch->c0;
    } else {
        *p = 2.0 * ch->R - (z[j] - z[j - 1]);
        pd = -(v[j] - v[j - 1]);
        c = ch->c1;
    }
    *fr = ch->k * *p + c * pd;
}

static void chain_rhs(chain *ch, const double *z, const double *v, double *dz, double *dv)
{
    ch->rhs_evals++;
    const long N = ch->N;
    double fbelow = 0.0;
    for (long j = 0; j < N; j++) {
        double p, fr;
        chain_contact(ch, j, z, v, &p, &fr);
        const double f = ch->active[j] ? fr : 0.0;
        if (j > 0) dv[j - 1] = -gravity(ch->t) + (fbelow - f) / ch->m;
        fbelow = f;
    }
    dv[N - 1] = -gravity(ch->t) + fbelow / ch->m;
    for (long i = 0; i < N; i++) dz[i] = v[i];
}

/* Mode that (z, v) asks for, given the current mode. */
static int chain_want(const chain *ch, long j, const double *z, const double *v, int cur, const double *zs,
                      const double *vs)
{
    double p, fr;
    chain_contact(ch, j, z, v, &p, &fr);
    if (!ch->law_noreclose) return fmin(p, fr) > 0.0;
    if (cur) return fr > 0.0;
    /* open: closes only when p crosses zero upwards over the step */
    double p0, fr0;
    chain_contact(ch, j, zs, vs, &p0, &fr0);
    return p0 <= 0.0 && p > 0.0;
}

static int chain_any_switch(const chain *ch, const double *z, const double *v)
{
    for (long j = 0; j < ch->N; j++)
        if (chain_want(ch, j, z, v, ch->active[j], ch->z, ch->v) != ch->active[j]) return 1;
    return 0;
}

/* One RK4 step of length h from (ch->z, ch->v) into (ch->z1, ch->v1). */
static void chain_rk4(chain *ch, double t, double h)
{
    const long N = ch->N;
    ch->t = t;
    chain_rhs(ch, ch->z, ch->v, ch->k1z, ch->k1v);
    for (long i = 0; i < N; i++) {
        ch->zt[i] = ch->z[i] + 0.5 * h * ch->k1z[i];
        ch->vt[i] = ch->v[i] + 0.5 * h * ch->k1v[i];
    }
    ch->t = t + 0.5 * h;
    chain_rhs(ch, ch->zt, ch->vt, ch->k2z, ch->k2v);
    for (long i = 0; i < N; i++) {
        ch->zt[i] = ch->z[i] + 0.5 * h * ch->k2z[i];
        ch->vt[i] = ch->v[i] + 0.5 * h * ch->k2v[i];
    }
    chain_rhs(ch, ch->zt, ch->vt, ch->k3z, ch->k3v);
    for (long i = 0; i < N; i++) {
        ch->zt[i] = ch->z[i] + h * ch->k3z[i];
        ch->vt[i] = ch->v[i] + h * ch->k3v[i];
    }
    ch->t = t + h;
    chain_rhs(ch, ch->zt, ch->vt, ch->k4z, ch->k4v);
    for (long i = 0; i < N; i++) {
        ch->z1[i] = ch->z[i] + h / 6.0 * (ch->k1z[i] + 2.0 * ch->k2z[i] + 2.0 * ch->k3z[i] + ch->k4z[i]);
        ch->v1[i] = ch->v[i] + h / 6.0 * (ch->k1v[i] + 2.0 * ch->k2v[i] + 2.0 * ch->k3v[i] + ch->k4v[i]);
    }
}

static int run_reference(long N, double R, double m, double k, double zeta, double c_floor, double gap,
                         double t_end, double h, const char *law, const char *forces_path)
{
    chain ch;
    memset(&ch, 0, sizeof ch);
    ch.N = N;
    ch.R = R;
    ch.m = m;
    ch.k = k;
    ch.c0 = c_floor >= 0 ? c_floor : 2.0 * zeta * sqrt(k * m);
    ch.c1 = 2.0 * zeta * sqrt(k * m / 2.0);
    ch.law_noreclose = !strcmp(law, "noreclose");
    double **arr[] = {&ch.z, &ch.v, &ch.zt, &ch.vt, &ch.k1z, &ch.k1v, &ch.k2z, &ch.k2v,
                      &ch.k3z, &ch.k3v, &ch.k4z, &ch.k4v, &ch.z1, &ch.v1};
    for (size_t q = 0; q < sizeof arr / sizeof arr[0]; q++)
        if (!(*arr[q] = calloc((size_t)N, sizeof(double)))) return 4;
    if (!(ch.active = calloc((size_t)N, sizeof(int)))) return 4;
    column_start(N, R, m, k, gap, ch.z);
    for (long j = 0; j < N; j++)
        ch.active[j] = chain_want(&ch, j, ch.z, ch.v, 0, ch.z, ch.v) && (gap <= 0.0 || settled_start);
    static double t_in[MAX_BOUNCE], v_in[MAX_BOUNCE], t_out[MAX_BOUNCE], v_out[MAX_BOUNCE];
    int nin = 0, nout = 0;
    long events = 0, steps = 0, cuts = 0;
    const double ttol = 1e-13;

    const double t0 = now(), cpu0 = cpu_now();
    double t = 0.0;
    while (t < t_end) {
        double hs = fmin(h, t_end - t);
        if (t_end - (t + hs) < 1e-12 * t_end) hs = t_end - t;
        /* no step across the kink of a ramp (keeps the 4th order) */
        if (ramp_time > 0.0 && t < ramp_time && t + hs > ramp_time) hs = ramp_time - t;
        if (ramp_time > 0.0 && t < ramp_time && ramp_time - (t + hs) < 1e-12 * ramp_time) hs = ramp_time - t;
        chain_rk4(&ch, t, hs);
        if (chain_any_switch(&ch, ch.z1, ch.v1)) {
            double lo = 0.0, hi = hs;
            while (hi - lo > ttol) {
                const double mid = 0.5 * (lo + hi);
                chain_rk4(&ch, t, mid);
                if (chain_any_switch(&ch, ch.z1, ch.v1)) hi = mid;
                else lo = mid;
            }
            hs = hi;
            chain_rk4(&ch, t, hs);
            cuts++;
            /* flip the modes that the end of the cut step asks for */
            int want0 = chain_want(&ch, 0, ch.z1, ch.v1, ch.active[0], ch.z, ch.v);
            for (long j = 0; j < N; j++) {
                const int w = j == 0 ? want0 : chain_want(&ch, j, ch.z1, ch.v1, ch.active[j], ch.z, ch.v);
                if (w != ch.active[j]) {
                    events++;
                    if (j == 0 && w && nin < MAX_BOUNCE) {
                        t_in[nin] = t + hs;
                        v_in[nin++] = ch.v1[0];
                    } else if (j == 0 && !w && nout < MAX_BOUNCE && nout < nin) {
                        t_out[nout] = t + hs;
                        v_out[nout++] = ch.v1[0];
                    }
                }
            }
            /* apply after all decisions (the noreclose law reads the step start) */
            for (long j = 0; j < N; j++) {
                const int w = chain_want(&ch, j, ch.z1, ch.v1, ch.active[j], ch.z, ch.v);
                ch.active[j] = w;
            }
        }
        memcpy(ch.z, ch.z1, (size_t)N * sizeof(double));
        memcpy(ch.v, ch.v1, (size_t)N * sizeof(double));
        t += hs;
        steps++;
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    double vmax = 0.0;
    int finite = 1;
    for (long i = 0; i < N; i++) {
        vmax = fmax(vmax, fabs(ch.v[i]));
        finite &= isfinite(ch.z[i]) && isfinite(ch.v[i]);
    }
    if (!finite) {
        printf("status=unstable\n");
        return 3;
    }
    double *f = ch.k1z;
    long nactive = 0;
    for (long j = 0; j < N; j++) {
        double p, fr;
        chain_contact(&ch, j, ch.z, ch.v, &p, &fr);
        f[j] = ch.active[j] ? fmax(fr, 0.0) : 0.0;
        nactive += ch.active[j];
    }
    printf("case=reference\nstatus=ok\nlaw=%s\nN=%ld\nh=%.9e\n", ch.law_noreclose ? "noreclose" : "clip", N, h);
    printf("steps=%ld\nevent_cuts=%ld\nrhs_evals=%ld\nevents=%ld\n", steps, cuts, ch.rhs_evals, events);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\n", wall, peak_rss_kb());
    printf("force_bottom=%.12e\nforce_top=%.12e\nactive_contacts=%ld\nmax_speed=%.12e\ntop_height=%.12e\n", f[0],
           f[N - 1], nactive, vmax, ch.z[N - 1]);
    printf("bounces=%d\n", nout);
    for (int b = 0; b < nout; b++)
        printf("bounce=%d t_in=%.12e v_in=%.12e t_out=%.12e v_out=%.12e ratio=%.12e\n", b + 1, t_in[b], v_in[b],
               t_out[b], v_out[b], -v_out[b] / v_in[b]);
    if (forces_path) {
        FILE *fp = fopen(forces_path, "w");
        if (!fp) return 4;
        for (long j = 0; j < N; j++) fprintf(fp, "%.15e\n", f[j]);
        fclose(fp);
    }
    for (size_t q = 0; q < sizeof arr / sizeof arr[0]; q++) free(*arr[q]);
    free(ch.active);
    return 0;
}

/* ---- stick-slip: a block dragged across a floor through a spring ---------
 * 1-D along the floor: block (mass m) at x, velocity u (floor fixed), a
 * linear spring ks from the block to an anchor moved at the constant speed
 * V (relaxed at t = 0: spring force ks (V t - x)). The normal force is the
 * weight m G (the normal direction stays at its static penetration).
 * Friction: ricochet's viscous (total) law, Iform 1, with Renard's
 * mu (Ifric 3) taken with mu_max = mu_s and mu_min = mu_d = mu_k:
 *     F = -sign(u) min(C |u|, mu(|u|) m G),
 *     mu(s) = mu_s for s <= v1, mu_s + (mu_k - mu_s)(3 - 2w) w^2 with
 *     w = (s - v1)/(v2 - v1) for v1 < s < v2, mu_k for s >= v2,
 * i.e. an overdamped adhesion (creep at |u| = F/C) until C |u| reaches the
 * limit (slip), back when it falls below it (stick). The central-difference
 * scheme evaluates F with the half-step velocity u_{n-1/2} (as the damping
 * of the column); stable step: the damped bound with omega = sqrt(ks/m) and
 * zeta = C / (2 m omega), which is about 2 m / C for the stiff adhesion.
 * Events: every switch of the branch of the min (slip: C|u| >= mu m G).
 * The switch time is the step time (first order); the positions at the
 * switches are written to EVENTS_FILE ("slip t x" / "stick t x").
 */
static double renard2(double s, double mus, double muk, double v1, double v2)
{
    if (s <= v1) return mus;
    if (s < v2) {
        const double w = (s - v1) / (v2 - v1);
        return mus + (muk - mus) * (3.0 - 2.0 * w) * w * w;
    }
    return muk;
}

static int run_stickslip(double m, double ks, double C, double mus, double muk, double v1, double v2, double V,
                         double t_end, double dt_factor, const char *events_path)
{
    const double omega = sqrt(ks / m), zeta = C / (2.0 * m * omega);
    const double dt_stable = SAFETY * stable_step(omega, zeta);
    double dt;
    const long nsteps = step_count(t_end, dt_factor * dt_stable, &dt);
    const double Fn = m * GRAV;
    FILE *fp = NULL;
    if (events_path && !(fp = fopen(events_path, "w"))) {
        fprintf(stderr, "explicit_ref: cannot write %s\n", events_path);
        return 4;
    }
    /* keep the switch records in memory, write after the timed loop */
    long cap = 1024, nrec = 0;
    double *rec_t = malloc((size_t)cap * sizeof(double)), *rec_x = malloc((size_t)cap * sizeof(double));
    int *rec_k = malloc((size_t)cap * sizeof(int));
    if (!rec_t || !rec_x || !rec_k) return 4;
    long events = 0, slips = 0;
    int slipping = 0;

    const double t0 = now(), cpu0 = cpu_now();
    double x = 0.0, uh = 0.0, a = 0.0;
    /* force at t = 0 (at rest, spring relaxed): 0; u_{-1/2} = u_0 - dt/2 a_0 */
    uh = 0.0;
    for (long n = 0; n <= nsteps; n++) {
        const double t = (double)n * dt;
        const double s = fabs(uh), lim = renard2(s, mus, muk, v1, v2) * Fn;
        const double visc = C * s;
        const int sl = visc >= lim;
        const double ff = (sl ? lim : visc) * (uh > 0.0 ? -1.0 : (uh < 0.0 ? 1.0 : 0.0));
        a = (ks * (V * t - x) + ff) / m;
        if (sl != slipping) {
            events++;
            slips += sl;
            slipping = sl;
            if (nrec == cap) {
                cap *= 2;
                rec_t = realloc(rec_t, (size_t)cap * sizeof(double));
                rec_x = realloc(rec_x, (size_t)cap * sizeof(double));
                rec_k = realloc(rec_k, (size_t)cap * sizeof(int));
                if (!rec_t || !rec_x || !rec_k) return 4;
            }
            rec_t[nrec] = t;
            rec_x[nrec] = x;
            rec_k[nrec++] = sl;
        }
        if (n == nsteps) break;
        uh += dt * a;
        x += dt * uh;
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    if (!isfinite(x) || !isfinite(uh)) {
        printf("status=unstable\n");
        return 3;
    }
    printf("case=stickslip\nstatus=ok\n");
    printf("dt=%.9e\ndt_stable=%.9e\nomega_max=%.9e\nzeta_max=%.9e\n", dt, dt_stable / SAFETY, omega, zeta);
    printf("steps=%ld\nforce_evals=%ld\nevents=%ld\nslips=%ld\n", nsteps, nsteps + 1, events, slips);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\nfinal_x=%.12e\nfinal_u=%.12e\n", wall, peak_rss_kb(), x, uh + 0.5 * dt * a);
    if (fp) {
        for (long q = 0; q < nrec; q++) fprintf(fp, "%s %.12e %.12e\n", rec_k[q] ? "slip" : "stick", rec_t[q], rec_x[q]);
        fclose(fp);
    }
    free(rec_t);
    free(rec_x);
    free(rec_k);
    return 0;
}

/* ---- drag to the slip: a block pulled by a ramped force until it slips ---
 * 1-D along the floor: block (mass m) at x, velocity u (floor fixed),
 * pulled by the force rate t [N] (a drag ramped at `rate` N/s), held by
 * ricochet's TYPE6 stick spring: the spring K_t anchored where the block
 * starts (force -K_t x) and the critical stick damper c_t = 2 sqrt(K_t m)
 * (docs/theory.md 3.5), friction force F = -K_t x - c_t u on the block.
 * The normal force is N = m G (the block's height imposed at its static
 * penetration). It sticks while |F| < mu N; the run ends at the first step
 * where |F| reaches mu N (the slip onset, its time interpolated linearly in
 * |F| between the two steps) or at t_end. The force F is evaluated with the
 * half-step velocity u_{n-1/2} (the damping of the scheme); stable step:
 * the damped bound with omega = sqrt(K_t/m), zeta = 1, then shrunk by
 * dt_factor and rounded down so that dt_out is a whole number of steps.
 * FORCES_FILE: "t F" at every multiple of dt_out before the slip.
 */
static int run_drag(double m, double kt, double mu, double rate, double t_end, double dt_out, double dt_factor,
                    const char *forces_path)
{
    const double omega = sqrt(kt / m), zeta = 1.0, ct = 2.0 * sqrt(kt * m);
    const double dt_stable = SAFETY * stable_step(omega, zeta);
    double dt;
    const long per = step_count(dt_out, dt_factor * dt_stable, &dt);
    const long nsteps = (long)floor(t_end / dt_out + 0.5) * per;
    const double lim = mu * m * GRAV;
    long cap = (long)floor(t_end / dt_out + 0.5) + 2, nrec = 0;
    double *rec_t = malloc((size_t)cap * sizeof(double)), *rec_f = malloc((size_t)cap * sizeof(double));
    if (!rec_t || !rec_f) return 4;
    double t_slip = -1.0, fprev = 0.0, x = 0.0, uh = 0.0, a = 0.0;
    long n = 0;
    const double t0 = now(), cpu0 = cpu_now();
    for (n = 0; n <= nsteps; n++) {
        const double t = (double)n * dt;
        const double f = -kt * x - ct * uh;
        if (fabs(f) >= lim) {
            t_slip = t - dt + dt * (lim - fabs(fprev)) / (fabs(f) - fabs(fprev));
            break;
        }
        if (n % per == 0 && nrec < cap) {
            rec_t[nrec] = t;
            rec_f[nrec++] = f;
        }
        fprev = f;
        a = (rate * t + f) / m;
        uh += dt * a;
        x += dt * uh;
    }
    const double wall = now() - t0;
    printf("cpu_time=%.9e\n", cpu_now() - cpu0);
    if (!isfinite(x) || !isfinite(uh)) {
        printf("status=unstable\n");
        return 3;
    }
    printf("case=drag\nstatus=ok\n");
    printf("dt=%.9e\ndt_stable=%.9e\nomega_max=%.9e\nzeta_max=%.9e\n", dt, dt_stable / SAFETY, omega, zeta);
    printf("steps=%ld\nforce_evals=%ld\nrecords=%ld\nt_slip=%.12e\n", n, n + 1, nrec, t_slip);
    printf("wall_time=%.9e\npeak_rss_kb=%ld\nfinal_x=%.12e\n", wall, peak_rss_kb(), x);
    if (forces_path) {
        FILE *fp = fopen(forces_path, "w");
        if (!fp) return 4;
        for (long q = 0; q < nrec; q++) fprintf(fp, "%.12e %.17e\n", rec_t[q], rec_f[q]);
        fclose(fp);
    }
    free(rec_t);
    free(rec_f);
    return 0;
}

static void usage(FILE *fp)
{
    fprintf(fp, "usage: explicit_ref drop m k c h t_end dt_factor\n"
                "       explicit_ref column N R m k zeta gap t_end dt_factor [FORCES_FILE]\n"
                "       explicit_ref reference N R m k zeta c_floor gap t_end h law [FORCES_FILE]\n"
                "           (c_floor < 0: 2 zeta sqrt(k m); law: clip | noreclose)\n"
                "       explicit_ref ramp N R m k zeta t_ramp t_end dt_factor [FORCES_FILE]\n"
                "       explicit_ref rampref N R m k zeta t_ramp t_end h [FORCES_FILE]\n"
                "           (the settled column, gravity ramped G -> 2 G over t_ramp, held to t_end;\n"
                "            central difference / event-located RK4 of the clipped law;\n"
                "            sramp, srampref: the smooth ramp G (1 + (1 - cos(pi t / t_ramp)) / 2))\n"
                "       explicit_ref stickslip m ks C mu_s mu_k v1 v2 V t_end dt_factor [EVENTS_FILE]\n"
                "       explicit_ref drag m K_t mu rate t_end dt_out dt_factor [FORCES_FILE]\n");
}

int main(int argc, char **argv)
{
    if (argc >= 2 && !strcmp(argv[1], "drop") && argc == 8) {
        return run_drop(arg(argv, 2), arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7));
    }
    if (argc >= 2 && !strcmp(argv[1], "column") && (argc == 10 || argc == 11)) {
        const double N = arg(argv, 2);
        if (N < 1 || N != floor(N)) {
            fprintf(stderr, "explicit_ref: N must be a positive integer\n");
            return 2;
        }
        return run_column((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                          arg(argv, 8), arg(argv, 9), argc == 11 ? argv[10] : NULL);
    }
    if (argc >= 2 && !strcmp(argv[1], "reference") && (argc == 12 || argc == 13)) {
        const double N = arg(argv, 2);
        if (N < 1 || N != floor(N) || (strcmp(argv[11], "clip") && strcmp(argv[11], "noreclose"))) {
            usage(stderr);
            return 2;
        }
        return run_reference((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                             arg(argv, 8), arg(argv, 9), arg(argv, 10), argv[11], argc == 13 ? argv[12] : NULL);
    }
    if (argc >= 2 && (!strcmp(argv[1], "ramp") || !strcmp(argv[1], "rampref") || !strcmp(argv[1], "sramp") ||
                      !strcmp(argv[1], "srampref")) &&
        (argc == 10 || argc == 11)) {
        const double N = arg(argv, 2);
        if (N < 1 || N != floor(N)) {
            usage(stderr);
            return 2;
        }
        settled_start = 1;
        ramp_time = arg(argv, 7);
        ramp_smooth = argv[1][0] == 's';
        const char *ff = argc == 11 ? argv[10] : NULL;
        if (!strcmp(argv[1], "ramp") || !strcmp(argv[1], "sramp"))
            return run_column((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), 0.0, arg(argv, 8),
                              arg(argv, 9), ff);
        return run_reference((long)N, arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), -1.0, 0.0,
                             arg(argv, 8), arg(argv, 9), "clip", ff);
    }
    if (argc >= 2 && !strcmp(argv[1], "stickslip") && (argc == 12 || argc == 13)) {
        return run_stickslip(arg(argv, 2), arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                             arg(argv, 8), arg(argv, 9), arg(argv, 10), arg(argv, 11), argc == 13 ? argv[12] : NULL);
    }
    if (argc >= 2 && !strcmp(argv[1], "drag") && (argc == 9 || argc == 10)) {
        return run_drag(arg(argv, 2), arg(argv, 3), arg(argv, 4), arg(argv, 5), arg(argv, 6), arg(argv, 7),
                        arg(argv, 8), argc == 10 ? argv[9] : NULL);
    }
    usage(stderr);
    return 2;
}
