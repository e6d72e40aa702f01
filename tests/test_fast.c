/*
 * The fast path of the contact kernel (engine/kernels/kernel_fast.inc) against the
 * general kernel (kernels.inc): right-hand side, root functions (with and
 * without the reports kept for the impact samples) and reports, at random
 * states in every mode, on decks whose interfaces take it (spheres against
 * spheres and planes, TYPE6 and the power law, a plane on a moving body).
 * The two paths perform the same operations: any difference beyond
 * round-off (a term dropped, a sign, a wrong body) fails.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/power.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;
/* uniform in (-1, 1) (xorshift64*) */
static double urand(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    const uint64_t x = rng_state * 0x2545f4914f6cdd1dULL;
    return 2.0 * ((double)(x >> 11) / 9007199254740992.0) - 1.0;
}

typedef struct {
    long n, differ;  /* values compared, values not bit for bit the same */
    double max_rel;  /* largest |a - b| / max(|a|, |b|) */
} cmp_stats;

static void cmp_values(cmp_stats *s, const double *a, const double *b, int n)
{
    for (int k = 0; k < n; k++) {
        s->n++;
        if (memcmp(&a[k], &b[k], sizeof(double)) == 0) continue;
        s->differ++;
        const double den = fmax(fabs(a[k]), fabs(b[k]));
        const double rel = isnan(a[k]) != isnan(b[k]) ? INFINITY : den > 0 ? fabs(a[k] - b[k]) / den : 0.0;
        if (!(rel <= s->max_rel)) s->max_rel = rel;
    }
}

/* the smallest finite positive value of v[0..n), or fallback */
static double min_scale(const double *v, int n, double fallback)
{
    double s = INFINITY;
    for (int k = 0; k < n; k++)
        if (isfinite(v[k]) && v[k] > 0 && v[k] < s) s = v[k];
    return isfinite(s) ? s : fallback;
}

/* A random state about y0: positions moved by a few penetration scales,
 * orientations turned, velocities and rates of the order of the contact
 * speeds, the interfaces' own states anything. */
static void random_state(const rc_model *m, const double *y0, double dp, double dv, double *y)
{
    memcpy(y, y0, (size_t)m->ny * sizeof(double));
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        double *yb = y + m->body_yadr[b];
        for (int k = 0; k < 3; k++) yb[k] += 3.0 * dp * urand();
        for (int k = 3; k < 7; k++) yb[k] += 0.3 * urand();
        for (int k = 7; k < 10; k++) yb[k] = dv * urand();
        for (int k = 10; k < 13; k++) yb[k] = 10.0 * urand();
    }
    for (int i = 0; i < m->ninter; i++)
        for (int k = 0; k < m->inter_ns[i]; k++) y[m->inter_eadr[i] + k] = urand();
}

static void random_modes(const rc_model *m, rc_data *d)
{
    for (int i = 0; i < m->ninter; i++) {
        const double u = urand();
        d->inter_mode[i] = u < -0.6 ? RC_MODE_OPEN : u < 0.2 ? RC_MODE_CLOSED : u < 0.8 ? RC_MODE_RELEASED
                                                                                : RC_MODE_INACTIVE;
        const double v = urand();
        d->inter_branch[i] = v < -0.3 ? RC_BR_LOAD : v < 0.3 ? RC_BR_UNLOAD : RC_BR_ELASTIC;
        d->inter_settled[i] = urand() > 0.5;
        d->inter_band[2 * i] = 1e-3 * urand();
        d->inter_band[2 * i + 1] = 1e-3 * urand();
    }
}

typedef struct {
    int fast, ss, sp, power, moving_plane;
} fast_count;

/* Compare both paths on the deck at `path` over `trials` random states. */
static void compare_deck(const char *path, int trials, fast_count *fc, cmp_stats *s)
{
    rc_error e;
    rc_model *m = NULL;
    ENSURE(tu_load_compile(path, &m, &e) == RC_OK && m != NULL);
    if (!m) return;
    rc_data *d = rc_data_new(m);
    const int ny = m->ny, nr = rc_root_count(m);
    double *y0 = calloc((size_t)ny, sizeof(double)), *y = calloc((size_t)ny, sizeof(double));
    double *fa = calloc((size_t)ny, sizeof(double)), *fb = calloc((size_t)ny, sizeof(double));
    double *ga = calloc((size_t)nr + 1, sizeof(double)), *gb = calloc((size_t)nr + 1, sizeof(double));
    ENSURE(d && y0 && y && fa && fb && ga && gb && m->inter_fast);
    if (!d || !y0 || !y || !fa || !fb || !ga || !gb || !m->inter_fast) goto out;
    for (int i = 0; i < m->ninter; i++) {
        if (!m->inter_fast[i]) continue;
        fc->fast++;
        fc->ss += m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE;
        fc->sp += m->inter_pair[i] == RC_PAIR_SPHERE_PLANE;
        fc->power += m->inter_law[i] == RC_LAW_POWER;
        fc->moving_plane += m->inter_pair[i] == RC_PAIR_SPHERE_PLANE && m->inter_bb[i] >= 0 &&
                            m->body_yadr[m->inter_bb[i]] >= 0;
    }
    rc_initial_state(m, y0);
    rc_modes_init(m, d, 0.0, y0);
    const double dp = min_scale(m->inter_pscale, m->ninter, 1e-4);
    const double dv = fmax(min_scale(m->inter_vscale, m->ninter, 1.0), 0.1);
    unsigned char *fast = m->inter_fast;
    const int nrep = (int)(sizeof(rc_inter_report) / sizeof(double));
    for (int trial = 0; trial < trials; trial++) {
        random_state(m, y0, dp, dv, y);
        random_modes(m, d);
        const double t = 0.37 * (trial + 1) / trials;
        /* right-hand side */
        m->inter_fast = NULL;
        const int sta = rc_assemble_rhs(m, d, t, y, fa);
        m->inter_fast = fast;
        const int stb = rc_assemble_rhs(m, d, t, y, fb);
        ENSURE(sta == stb);
        cmp_values(s, fa, fb, ny);
        /* root functions, with and without the reports kept */
        for (int on = 0; on < 2; on++) {
            d->sc->repc->on = on;
            m->inter_fast = NULL;
            rc_assemble_roots(m, d, t, y, ga);
            m->inter_fast = fast;
            rc_assemble_roots(m, d, t, y, gb);
            cmp_values(s, ga, gb, nr);
        }
        d->sc->repc->on = 0;
        /* reports */
        for (int i = 0; i < m->ninter; i++) {
            rc_inter_report ra, rb;
            memset(&ra, 0, sizeof ra);
            memset(&rb, 0, sizeof rb);
            m->inter_fast = NULL;
            rc_inter_report_eval_d(m, d, i, t, y, &ra);
            m->inter_fast = fast;
            rc_inter_report_eval_d(m, d, i, t, y, &rb);
            cmp_values(s, (const double *)&ra, (const double *)&rb, nrep);
        }
    }
out:
    free(y0);
    free(y);
    free(fa);
    free(fb);
    free(ga);
    free(gb);
    rc_data_free(d);
    rc_model_free(m);
}

/* A sphere against a plane on a free, turning body of anisotropic inertia,
 * the plane's point off its body's centre: the force on the plane's body has
 * a moment (no validation deck has one: their planes' bodies are held). */
static const char *plane_deck(void)
{
    return tu_tmp_write("fast_plane_body.rad",
    "/BEGIN\n"
    "sphere against a plane on a free, turning body\n"
    "      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\n"
    "linear load curve k = 1e6 N/m\n"
    "                   0                   0\n"
    "                   1             1000000\n"
    "/NODE\n"
    "         1                   0                   0          0.04999019\n"
    "         2              -0.301               0.02                0.01\n"
    "/RBODY/1\n"
    "ball 1 kg\n"
    "         1                                                 1         1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/RBODY/2\n"
    "plate 5 kg\n"
    "         2                                                 5         2\n"
    "                 0.1                 0.2                 0.3\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\n"
    "ball sphere\n"
    "         0         2         1\n"
    "                   0                   0          0.04999019\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/3\n"
    "plate face\n"
    "              -0.051                0.01                   0\n"
    "               0.949                 0.2                 0.1\n"
    "         2\n"
    "/GRNOD/NODE/1\n"
    "ball\n"
    "         1\n"
    "/GRNOD/NODE/2\n"
    "plate\n"
    "         2\n"
    "/INTER/TYPE6/1\n"
    "ball on the plate\n"
    "         1         3\n"
    "                                                           0\n"
    "                   0         0         0         0         0\n"
    "         1         0                                                 0\n"
    "         0\n"
    "                1000         0         0\n"
    "/RUN\n"
    "                 0.4              0.0002\n"
    "/END\n");
}

static void test_fast_path_matches_general_kernel(void)
{
    static const char *decks[] = {
        "validation/stack10_rest/case.rad",      /* spheres on spheres and a floor */
        "validation/cradle5/case.rad",           /* power law, spheres */
        "validation/frc_iform_compare/case.rad", /* a plane on a moving body */
        "validation/t6_damping_curves/case.rad", /* TYPE6 damping curves f_dv, f_df */
        "validation/pw_restitution/case.rad",    /* power law on a plane */
        "validation/pw_hunt_crossley/case.rad",
        "validation/hertz/case.rad",
        "validation/spring_dashpot/case.rad",
    };
    fast_count fc = {0};
    cmp_stats s = {0};
    for (size_t k = 0; k < sizeof decks / sizeof decks[0]; k++) compare_deck(decks[k], 200, &fc, &s);
    const char *pd = plane_deck(); /* the plane's body turns: the moment */
    ENSURE(pd != NULL);
    if (pd) compare_deck(pd, 200, &fc, &s);
    printf("    %d interfaces on the fast path (%d sphere-sphere, %d sphere-plane of which %d on a moving body, %d "
           "power law); %ld values compared, %ld not bit for bit the same, max relative difference %.2e\n",
           fc.fast, fc.ss, fc.sp, fc.moving_plane, fc.power, s.n, s.differ, s.max_rel);
    ENSURE(fc.ss > 0 && fc.sp > 0 && fc.moving_plane > 0 && fc.power > 0);
    ENSURE(s.n > 100000);
    ENSURE(s.max_rel <= 1e-14);
}

/* The Newton matrix: rc_assemble_jac with the fast path's blocks
 * (assemble_jac.c, fast_inter) against the general kernel's complex-step
 * blocks (m->inter_fast NULL) at random states in every mode; entries
 * compared relative to the largest of their row (a sum that cancels to
 * near zero carries its terms' rounding); then after mode changes the
 * fast blocks refreshed alone against a whole general assembly. Returns
 * the largest difference. */
/* Largest |a - b| over the pattern, relative to the largest entry of its
 * row (keep: or of the row's scale in rmax from before); counts the entries
 * (n) and the non-zero ones (nz). */
static double jac_diff(const rc_model *m, const double *va, const double *vb, double *rmax, int keep, long *n,
                       long *nz)
{
    double worst = 0.0;
    if (!keep) memset(rmax, 0, (size_t)m->ny * sizeof(double));
    for (int64_t k = 0; k < m->nnz; k++) {
        const int r = m->jac_rowind[k];
        rmax[r] = fmax(rmax[r], fmax(fabs(va[k]), fabs(vb[k])));
    }
    for (int64_t k = 0; k < m->nnz; k++) {
        (*n)++;
        *nz += va[k] != 0.0;
        const double den = rmax[m->jac_rowind[k]];
        const double rel = isnan(va[k]) || isnan(vb[k]) ? INFINITY : den > 0 ? fabs(va[k] - vb[k]) / den : 0.0;
        if (!(rel <= worst)) worst = rel;
    }
    return worst;
}

static double compare_jac(const char *path, int trials, long *n, long *nz)
{
    rc_error e;
    rc_model *m = NULL;
    double worst = 0.0;
    ENSURE(tu_load_compile(path, &m, &e) == RC_OK && m != NULL);
    if (!m) return INFINITY;
    rc_data *d = rc_data_new(m);
    const int ny = m->ny;
    double *y0 = calloc((size_t)ny, sizeof(double)), *y = calloc((size_t)ny, sizeof(double));
    double *va = calloc((size_t)m->nnz + 1, sizeof(double)), *vb = calloc((size_t)m->nnz + 1, sizeof(double));
    double *rmax = calloc((size_t)ny, sizeof(double));
    ENSURE(d && y0 && y && va && vb && rmax && m->inter_fast);
    if (!d || !y0 || !y || !va || !vb || !rmax || !m->inter_fast) goto out;
    rc_initial_state(m, y0);
    rc_modes_init(m, d, 0.0, y0);
    const double dp = min_scale(m->inter_pscale, m->ninter, 1e-4);
    const double dv = fmax(min_scale(m->inter_vscale, m->ninter, 1.0), 0.1);
    unsigned char *fast = m->inter_fast;
    for (int trial = 0; trial < trials; trial++) {
        random_state(m, y0, dp, dv, y);
        random_modes(m, d);
        /* Inacti tracking where an interface has it (none on the fast path
         * has the offset state; the flag still zeroes vn) */
        for (int i = 0; i < m->ninter; i++) d->inter_track[i] = urand() > 0.6;
        const double t = 0.29 * (trial + 1) / trials;
        m->inter_fast = NULL;
        const int sta = rc_assemble_jac(m, d, t, y, va);
        /* the blocks cached for the refresh below: the fast assembly's own
         * (it writes only its positions once the cache holds blocks) */
        ENSURE(d->sc->jcache != NULL && d->sc->jcache_ok);
        if (d->sc->jcache)
            for (int64_t k = 0; k < d->sc->jcache_off[m->ninter]; k++) d->sc->jcache[k] = 12345.0;
        m->inter_fast = fast;
        const int stb = rc_assemble_jac(m, d, t, y, vb);
        ENSURE(sta == stb);
        worst = fmax(worst, jac_diff(m, va, vb, rmax, 0, n, nz));
        /* a mode change refreshes the fast blocks alone (rc_jac_refresh_inter,
         * through the cached blocks), against a whole general assembly */
        for (int i = 0; i < m->ninter; i++) {
            if (urand() < 0.3) continue;
            d->inter_mode[i] = d->inter_mode[i] == RC_MODE_CLOSED ? RC_MODE_RELEASED : RC_MODE_CLOSED;
            ENSURE(rc_jac_refresh_inter(m, d, i, y, vb) == 0);
        }
        m->inter_fast = NULL;
        rc_assemble_jac(m, d, t, y, va);
        m->inter_fast = fast;
        /* a refresh adds new less old: entries that become 0 keep the
         * rounding of the sum they were part of, relative to the row's scale
         * before the change */
        worst = fmax(worst, jac_diff(m, va, vb, rmax, 1, n, nz));
    }
out:
    free(y0);
    free(y);
    free(va);
    free(vb);
    free(rmax);
    rc_data_free(d);
    rc_model_free(m);
    return worst;
}

static void test_fast_jacobian_matches_general_kernel(void)
{
    static const char *decks[] = {
        "validation/stack10_rest/case.rad",      "validation/cradle5/case.rad",
        "validation/frc_iform_compare/case.rad", "validation/t6_damping_curves/case.rad",
        "validation/pw_restitution/case.rad",    "validation/pw_hunt_crossley/case.rad",
        "validation/hertz/case.rad",             "validation/spring_dashpot/case.rad",
    };
    long n = 0, nz = 0;
    double worst = 0.0;
    for (size_t k = 0; k <= sizeof decks / sizeof decks[0]; k++) {
        const char *path = k < sizeof decks / sizeof decks[0] ? decks[k] : plane_deck();
        ENSURE(path != NULL);
        if (!path) continue;
        const double w = compare_jac(path, 200, &n, &nz);
        if (w > 1e-13) printf("    %s: max difference %.2e of the row's largest entry\n", path, w);
        worst = fmax(worst, w);
    }
    printf("    %ld Jacobian entries compared (%ld non-zero), max difference %.2e of the row's largest entry\n", n,
           nz, worst);
    ENSURE(nz > 10000);
    ENSURE(worst <= 1e-13);
}

/* The fast path's Jacobian against central differences of the right-hand
 * side (which takes the fast path too; tu_jac_fd_error), every interface
 * closed, at random states about the initial one. The difference's step is
 * 1e-6 m: on a deck with one interface the bodies are first pushed to a
 * penetration of a fifth of the sphere's radius, where the laws (a Hertz
 * power of a penetration of 1e-7 m) are smooth on that scale. Returns the
 * number of fast interfaces seen. */
static int fd_deck(const char *path, int trials, double *worst, int *bad, int *outside)
{
    rc_error e;
    rc_model *m = NULL;
    int nfast = 0;
    ENSURE(tu_load_compile(path, &m, &e) == RC_OK && m != NULL);
    if (!m) return 0;
    rc_data *d = rc_data_new(m);
    double *y0 = calloc((size_t)m->ny, sizeof(double)), *y = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && y0 && y);
    if (d && y0 && y) {
        rc_initial_state(m, y0);
        rc_modes_init(m, d, 0.0, y0);
        for (int i = 0; i < m->ninter; i++) nfast += m->inter_fast[i];
        const double dp = min_scale(m->inter_pscale, m->ninter, 1e-4);
        const double dv = fmax(min_scale(m->inter_vscale, m->ninter, 1.0), 0.1);
        for (int trial = 0; trial < trials; trial++) {
            random_state(m, y0, dp, dv, y);
            /* angular velocities only on the bodies of planes (the spheres'
             * rates enter nothing of the fast path; their gyroscopic terms,
             * zero for an isotropic inertia, leave rounding noise that the
             * difference reads as entries off the pattern) */
            for (int b = 0; b < m->nbody; b++) {
                int plane = 0;
                for (int i = 0; i < m->ninter; i++)
                    plane |= m->inter_pair[i] == RC_PAIR_SPHERE_PLANE && m->inter_bb[i] == b;
                if (!plane && m->body_yadr[b] >= 0)
                    for (int k = 10; k < 13; k++) y[m->body_yadr[b] + k] = 0.0;
            }
            if (m->ninter == 1) {
                const int ba = m->inter_ba[0], bb = m->inter_bb[0];
                rc_inter_report r;
                rc_inter_report_eval(m, 0, RC_MODE_CLOSED, RC_BR_LOAD, 0, 0, 0.0, y, &r);
                const double s = 0.2 * m->surf_r[m->inter_sa[0]] - r.p; /* along n: p grows */
                if (ba >= 0 && m->body_yadr[ba] >= 0)
                    for (int k = 0; k < 3; k++) y[m->body_yadr[ba] + k] += s * r.normal[k];
                else if (bb >= 0 && m->body_yadr[bb] >= 0)
                    for (int k = 0; k < 3; k++) y[m->body_yadr[bb] + k] -= s * r.normal[k];
            }
            for (int i = 0; i < m->ninter; i++) {
                d->inter_mode[i] = RC_MODE_CLOSED;
                d->inter_branch[i] = trial % 2 ? RC_BR_UNLOAD : RC_BR_LOAD;
                d->inter_track[i] = 0;
            }
            int b = 0, o = 0;
            const double w = tu_jac_fd_error(m, d, 0.0, y, 1, &b, &o);
            if (getenv("RC_DEBUG_FASTJAC")) printf("    %s trial %d: %.2e bad %d out %d\n", path, trial, w, b, o);
            *worst = fmax(*worst, w);
            *bad += b;
            *outside += o;
        }
    }
    free(y0);
    free(y);
    rc_data_free(d);
    rc_model_free(m);
    return nfast;
}

static void test_fast_jacobian_fd(void)
{
    static const char *decks[] = {
        "validation/stack10_rest/case.rad",      /* TYPE6 spheres on spheres and a floor */
        "validation/frc_iform_compare/case.rad", /* a plane on a moving body */
        "validation/t6_damping_curves/case.rad", /* f_dv, f_df */
        "validation/bounce_settle/case.rad",     "validation/impact_table/case.rad",
        "validation/spring_dashpot/case.rad",    "validation/t6_rest_contact/case.rad",
        "validation/pw_general/case.rad", /* power laws, one interface each */
        "validation/pw_hertz/case.rad",          "validation/pw_restitution/case.rad",
        "validation/pw_hunt_crossley/case.rad",  "validation/hertz/case.rad",
    };
    double worst = 0.0;
    int bad = 0, outside = 0, nfast = 0;
    for (size_t k = 0; k < sizeof decks / sizeof decks[0]; k++) nfast += fd_deck(decks[k], 10, &worst, &bad, &outside);
    const char *pd = plane_deck();
    ENSURE(pd != NULL);
    if (pd) nfast += fd_deck(pd, 10, &worst, &bad, &outside);
    printf("    %d fast interfaces closed: max |J - FD| / scale %.2e, %d bad, %d outside the pattern\n", nfast, worst,
           bad, outside);
    ENSURE(nfast > 0);
    ENSURE(bad == 0 && outside == 0);
}

/* What takes the fast path: not an off-centre sphere, friction, hysteresis,
 * or a segment surface. */
static void test_fast_path_selection(void)
{
    static const struct {
        const char *path;
        int fast; /* 1: every interface fast, 0: none */
    } cases[] = {
        {"validation/bouncing_ball/case.rad", 1},
        {"validation/t6_restitution_offcentre/case.rad", 0}, /* the sphere off its body's centre */
        {"validation/fric_incline/case.rad", 0},              /* friction */
        {"validation/t6_unload_curve/case.rad", 0},           /* Iform 1: the hysteresis state */
        {"validation/t6_inacti_icor/case.rad", 0},            /* Inacti 5: the offset state */
        {"validation/seg_sphere_floor/case.rad", 0},          /* a segment surface */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        rc_error e;
        rc_model *m = NULL;
        ENSURE(tu_load_compile(cases[k].path, &m, &e) == RC_OK && m != NULL);
        if (!m) continue;
        int n = 0;
        for (int i = 0; i < m->ninter; i++) {
            n += m->inter_fast[i];
            ENSURE(m->inter_fast[i] == rc_fast_eligible(m, i));
        }
        if (cases[k].fast != (n == m->ninter) || (!cases[k].fast && n != 0))
            printf("    %s: %d of %d interfaces fast\n", cases[k].path, n, m->ninter);
        ENSURE(m->ninter > 0 && (cases[k].fast ? n == m->ninter : n == 0));
        rc_model_free(m);
    }
}

void suite_fast(void);
void suite_fast(void)
{
    RUN_TEST(test_fast_path_matches_general_kernel);
    RUN_TEST(test_fast_path_selection);
    RUN_TEST(test_fast_jacobian_matches_general_kernel);
    RUN_TEST(test_fast_jacobian_fd);
    tu_tmp_cleanup();
}
