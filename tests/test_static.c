/* The static analysis (solver/static.c, docs/theory.md "Static analysis"):
 * its stiffness (the force part of the engine's Jacobian, the quaternion
 * columns chained through the rotation vector about the start orientation)
 * against central finite differences of its residual, on a sphere whose
 * surface is off its centre of mass resting on a plane (forces and
 * moments) and on two such spheres stacked, the upper one on a Hertz
 * contact and held by a spring to a fixed point; at the start orientation
 * and at rotated states; with friction on the contact (the return
 * mapping's trial force, sticking and sliding), and with exact stick (the
 * friction force an unknown, its Alart-Curnier rows). And the scope: what
 * Method 3 refuses. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/model.h"
#include "solver/static.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

/* The version, SI units and the linear load curve /FUNCT/1 (1e5 N/m) of
 * both decks, after their title line. */
#define UNITS_AND_CURVE                                                                                    \
    "      2022         0\n"                                                                                 \
    "                  kg                   m                   s\n"                                         \
    "                  kg                   m                   s\n"                                         \
    "/FUNCT/1\n"                                                                                              \
    "curve\n"                                                                                                 \
    "                   0                   0\n"                                                              \
    "                   1              100000\n"

/* Gravity -9.81 m/s^2 along z and the TYPE6 contact 1 between surfaces 1
 * and 2 (load curve /FUNCT/1, no friction), as both decks write them. */
#define GRAV_AND_CONTACT                                                                                    \
    "/GRAV/1\n"                                                                                               \
    "gravity\n"                                                                                               \
    "         0         Z         0         0         0                             1               -9.81\n"     \
    "/INTER/TYPE6/1\n"                                                                                        \
    "contact\n"                                                                                               \
    "         1         2\n"                                                                                  \
    "                                                           0\n"                                          \
    "                   0         0         0         0         0\n"                                          \
    "         1         0                                                 0\n"                                \
    "         0\n"                                                                                            \
    "                             0         0\n"

static const char *deck_one =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "static jacobian: an off-centre sphere on a plane\n"
    UNITS_AND_CURVE
    "/NODE\n"
    "         1                   0                   0                 0.1\n"
    "/RBODY/1\n"
    "body\n"
    "         1                                                 1         1\n"
    "               0.002               0.003               0.004\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\n"
    "sphere\n"
    "         0         2         1\n"
    "                0.01               0.005                 0.1\n"
    "              0.1005              0.1005              0.1005\n"
    "/SURF/PLANE/2\n"
    "plane\n"
    "                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRNOD/NODE/1\n"
    "group\n"
    "         1\n"
    GRAV_AND_CONTACT
    "/RUN\n"
    "                   1                 0.1\n"
    "/SOLVER\n"
    "         3         5    100000               1e-06                   0                   0\n"
    "               1e-09               1e-09               1e-06               1e-06\n"
    "               1e-06\n"
    "/END\n";

static const char *deck_two =
    "#RADIOSS STARTER\n"
    "/BEGIN\n"
    "static jacobian: two spheres stacked\n"
    UNITS_AND_CURVE
    "/NODE\n"
    "         1                   0                   0                 0.1\n"
    "         2               0.003                   0                 0.3\n"
    "/RBODY/1\n"
    "body\n"
    "         1                                                 1         1\n"
    "               0.002               0.003               0.004\n"
    "                   0                   0                   0\n"
    "/RBODY/2\n"
    "body\n"
    "         2                                                 2         2\n"
    "               0.005               0.004               0.003\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\n"
    "sphere\n"
    "         0         2         1\n"
    "               0.004               0.002                 0.1\n"
    "              0.1002              0.1002              0.1002\n"
    "/SURF/ELLIPS/3\n"
    "sphere\n"
    "         0         2         2\n"
    "               0.003              -0.004                 0.3\n"
    "              0.1002              0.1002              0.1002\n"
    "/SURF/PLANE/2\n"
    "plane\n"
    "                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRNOD/NODE/1\n"
    "group\n"
    "         1\n"
    "/GRNOD/NODE/2\n"
    "group\n"
    "         2\n"
    GRAV_AND_CONTACT
    "/INTER/POWER/2\n"
    "power-law contact\n"
    "         3         1         0         0         0         0\n"
    "           100000000                 1.5                   0\n"
    "\n"
    "\n"
    "/COUPLING/SPRING/3\n"
    "spring-damper\n"
    "         2         0         1\n"
    "                0.02                   0                 0.3\n"
    "                 0.3                   0                 0.4\n"
    "                 0.2\n"
    "                 500\n"
    "/RUN\n"
    "                   1                 0.1\n"
    "/SOLVER\n"
    "         3         5    100000               1e-06                   0                   0\n"
    "               1e-09               1e-09               1e-06               1e-06\n"
    "               1e-06\n"
    "/END\n";

/* A static analysis of model m (owned from here on): its run data, a state
 * and the solver (members NULL when out of memory), and their release. */
typedef struct {
    rc_model *m;
    rc_data *d;
    double *y;
    rc_static *s;
} st_fix;

static st_fix fix_open(rc_model *m)
{
    st_fix f = {m, NULL, NULL, NULL};
    f.d = m ? rc_data_new(m) : NULL;
    f.y = m ? calloc((size_t)m->ny + 1, sizeof(double)) : NULL;
    f.s = f.d ? rc_static_new(m, f.d) : NULL;
    return f;
}

/* The fixture is whole (a model that did not compile has been reported
 * where it was compiled). */
static int fix_ready(const st_fix *f)
{
    ENSURE(!f->m || (f->d && f->y && f->s));
    return f->m && f->d && f->y && f->s;
}

static void fix_close(st_fix *f)
{
    rc_static_free(f->s);
    free(f->y);
    rc_data_free(f->d);
    rc_model_free(f->m);
}

/* max |K - FD| / max(|K|) per column over the stiffness at u, h scaled per
 * unknown (2e-8 m or rad: the Hertz law's third derivative at small P bounds it) */
static double stiffness_fd_error(rc_static *s, double t, const double *u0)
{
    const int n = rc_static_size(s);
    double *K = calloc((size_t)n * n, sizeof(double)), *u = calloc((size_t)n, sizeof(double));
    double *rp = calloc((size_t)n, sizeof(double)), *rm = calloc((size_t)n, sizeof(double));
    double worst = INFINITY;
    ENSURE(K && u && rp && rm);
    if (!K || !u || !rp || !rm) goto out;
    ENSURE(rc_static_stiffness(s, t, u0, K) == 0);
    double kmax = 0.0;
    for (int i = 0; i < n * n; i++) kmax = fmax(kmax, fabs(K[i]));
    worst = 0.0;
    for (int c = 0; c < n; c++) {
        const double h = 2e-8;
        memcpy(u, u0, (size_t)n * sizeof(double));
        u[c] = u0[c] + h;
        ENSURE(rc_static_residual(s, t, u, rp) == 0);
        u[c] = u0[c] - h;
        ENSURE(rc_static_residual(s, t, u, rm) == 0);
        for (int r = 0; r < n; r++) {
            const double fd = (rp[r] - rm[r]) / (2 * h), e = fabs(K[(size_t)c * n + r] - fd) / kmax;
            if (e > 1e-6) fprintf(stderr, "  K[%d][%d] = %.9g, FD %.9g\n", r, c, K[(size_t)c * n + r], fd);
            worst = fmax(worst, e);
        }
    }
out:
    free(K);
    free(u);
    free(rp);
    free(rm);
    return worst;
}

/* The model of `text`, its data with every active contact closed, the
 * stiffness checked at u = 0 and at displaced and rotated states. */
static void check_deck(const char *text, const char *name, int nfree)
{
    rc_error e;
    rc_model *m = tu_compile_text(text, name, &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        ENSURE(rc_static_size(s) == 6 * nfree);
        rc_initial_state(m, y);
        rc_modes_init(m, d, 0.0, y);
        for (int i = 0; i < m->ninter; i++) d->inter_mode[i] = RC_MODE_CLOSED;
        rc_static_set_start(s, y);
        const int n = rc_static_size(s);
        double *u = calloc((size_t)n, sizeof(double));
        ENSURE(u != NULL);
        if (u) {
            double err0 = stiffness_fd_error(s, 0.5, u);
            ENSURE(err0 < 1e-6);
            /* displaced by up to 0.2 mm and rotated by up to 0.05 rad */
            for (int i = 0; i < n; i++) u[i] = (i % 6 < 3 ? 2e-4 : 0.05) * sin(1.7 * i + 0.3);
            double err1 = stiffness_fd_error(s, 0.5, u);
            ENSURE(err1 < 1e-6);
            /* the same about a start orientation that is not the identity */
            double *y2 = calloc((size_t)m->ny + 1, sizeof(double));
            ENSURE(y2 != NULL);
            if (y2) {
                memcpy(y2, y, (size_t)m->ny * sizeof(double));
                for (int b = 0; b < m->nbody; b++) {
                    const int a = m->body_yadr[b];
                    if (a < 0) continue;
                    const double q[4] = {cos(0.2), sin(0.2) * 0.6, sin(0.2) * 0.8, 0.0};
                    memcpy(y2 + a + 3, q, sizeof q);
                }
                rc_static_set_start(s, y2);
                double err2 = stiffness_fd_error(s, 0.5, u);
                ENSURE(err2 < 1e-6);
                free(y2);
            }
            free(u);
        }
    }
    fix_close(&f);
}

static void test_static_stiffness_fd(void)
{
    check_deck(deck_one, "static_one.rad", 1);
    check_deck(deck_two, "static_two.rad", 2);
}

/* deck_one with friction on its contact: Fric 0.3, Stiff K_t = 1e4 N/m
 * (the sphere is 0.5 mm into the plane at the start: F_n = 50 N, limit
 * 15 N). NULL: out of memory. */
static char *deck_one_friction(void)
{
    static const char *const rep[][2] = {
        {"\n                                                           0\n",
         "\n                                     0.3                   0\n"},
        {"\n         0\n                             0         0\n/RUN",
         "\n         0                         10000\n                             0         0\n/RUN"}};
    char *t = malloc(strlen(deck_one) + 200);
    if (!t) return NULL;
    strcpy(t, deck_one);
    for (int k = 0; k < 2; k++) {
        char *p = strstr(t, rep[k][0]);
        ENSURE(p != NULL);
        if (!p) continue;
        const size_t lo = strlen(rep[k][0]), ln = strlen(rep[k][1]);
        memmove(p + ln, p + lo, strlen(p + lo) + 1);
        memcpy(p, rep[k][1], ln);
    }
    return t;
}

/* Friction in the static residual (docs/theory.md 7.8): the stiffness with
 * the return mapping's trial force F_t0 - K_t (p_a - p_b) against central
 * differences of the residual, sticking (the elastic tangent through the
 * engine's projection on the contact plane) and sliding (the limit along
 * the trial force: the projected tangent L/|F| (I - e e') K_t), at the
 * start orientation and displaced and rotated; and the modes it sets. */
static void stiffness_friction_deck(const char *more);
static void test_static_stiffness_friction(void)
{
    stiffness_friction_deck(NULL);
    /* a /FRICTION law of the pressure taken at rest (Ifric 1: mu(p, 0) =
     * 0.4 - 2e-5 p + 1e-10 p^2, p = F_n / 0.01 m^2; 0.3025 at F_n = 50 N,
     * the speed terms C2, C3 not acting): in slip the limit's derivative
     * through the pressure */
    stiffness_friction_deck("/FRICTION/1\nIfric 1\n1,0,,2,,0.01\n-2e-5,3,0.5,1e-10\n0,0.4\n");
    /* orthotropic (Coulomb mu_1 = 0.28 along x, mu_2 = 0.6 along y): in
     * slip the trial returned to the ellipse along its ray in the scaled
     * plane */
    stiffness_friction_deck("/PART/1\nsphere\n         0         0         0                   0\n         1\n"
                            "/PART/2\nplane\n         0         0         0                   0\n         0         2\n"
                            "/GRPART/PART/1\nplanes\n2\n"
                            "/FRICTION/1\northotropic\n0,0,,2\n\n0,0.9\n0,1,1,0,,1\n\n0,0.28\n\n0,0.6\n"
                            "/FRIC_ORIENT/1\ndirection 1\n1,0\n1,0,0,0,0\n");
}

static void stiffness_friction_deck(const char *more)
{
    char *text0 = deck_one_friction();
    ENSURE(text0 != NULL);
    if (!text0) return;
    char *text = text0;
    if (more) {
        text = malloc(strlen(text0) + strlen(more) + 1);
        ENSURE(text != NULL);
        char *r = text ? strstr(text0, "/RUN") : NULL;
        if (!r) {
            free(text0);
            free(text);
            return;
        }
        memcpy(text, text0, (size_t)(r - text0));
        strcpy(text + (r - text0), more);
        strcat(text, r);
        free(text0);
    }
    rc_error e;
    rc_model *m = tu_compile_text(text, "static_fric_jac.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        ENSURE(m->inter_fr[0].tidx >= 0 && m->inter_fr[0].kt == 1e4);
        const int n = rc_static_size(s);
        double u[6] = {0}, *r = calloc((size_t)n, sizeof(double));
        ENSURE(n == 6 && r != NULL);
        const double ft0[2][3] = {{3.0, -2.0, 0.0}, {13.5, 6.0, 0.0}}; /* sticks; slides once displaced */
        for (int c = 0; c < 2 && r; c++) {
            rc_initial_state(m, y);
            rc_modes_init(m, d, 0.0, y);
            d->inter_mode[0] = RC_MODE_CLOSED;
            memcpy(y + m->inter_eadr[0] + m->inter_fr[0].tidx, ft0[c], sizeof ft0[c]);
            rc_static_set_start(s, y);
            rc_static_set_substep_start(s, 0.5, y);
            /* displaced by up to 0.2 mm (2 N of the spring) and rotated by up to 0.01 rad */
            for (int i = 0; i < n; i++) u[i] = (i % 6 < 3 ? 2e-4 : 0.01) * sin(1.7 * i + 0.3);
            if (c == 1) u[0] = -4e-4; /* the trial force past the limit */
            ENSURE(rc_static_residual(s, 0.5, u, r) == 0);
            ENSURE(d->inter_slip[0] == c);
            const double err0 = stiffness_fd_error(s, 0.5, u);
            if (!(err0 < 1e-6)) fprintf(stderr, "  friction (%s): stiffness error %.3g\n", c ? "slip" : "stick", err0);
            ENSURE(err0 < 1e-6);
            /* at the substep's start (u = 0) the spring keeps F_t0 (within
             * the limit in both cases): the tangential force residual */
            double u0[6] = {0};
            ENSURE(rc_static_residual(s, 0.5, u0, r) == 0);
            ENSURE(d->inter_slip[0] == 0);
            ENSURE_NEAR(r[0], ft0[c][0], 1e-12, 1e-12);
            ENSURE_NEAR(r[1], ft0[c][1], 1e-12, 1e-12);
        }
        free(r);
    }
    fix_close(&f);
    free(text);
}

/* Exact stick in the static residual (docs/theory.md 7.8, "Exact stick"):
 * deck_one's contact with friction (Fric 0.3: the limit 15 N at F_n = 50
 * N) and Istick 1. Its force lambda is three unknowns after the sphere's,
 * its rows lambda - Phi(P_n (lambda - K_t D)); the stiffness (the engine's
 * columns of the friction state in the body rows, the rows by complex step
 * along the normal's, the limit's and D's derivatives) against central
 * differences of the residual, sticking and sliding, at the start and
 * displaced and rotated; at u = 0 with lambda in the contact plane the rows
 * vanish (nothing has moved: stuck exactly) and the sphere's force rows
 * carry lambda. */
static void test_static_stiffness_exact_stick(void)
{
    char *text = deck_one_friction();
    ENSURE(text != NULL);
    if (!text) return;
    char *p = strstr(text, "0.3                   0\n");
    p = p ? strchr(p, '\n') : NULL; /* the line Istick, ... */
    ENSURE(p != NULL);
    if (!p) {
        free(text);
        return;
    }
    memcpy(p + 1, "         1", 10);
    rc_error e;
    rc_model *m = tu_compile_text(text, "static_exact_jac.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        ENSURE(m->inter_fr[0].exact && m->inter_fr[0].tidx >= 0);
        const int n = rc_static_size(s);
        ENSURE(n == 9);
        double u[9] = {0}, r[9] = {0};
        /* lambda within the limit (sticks); past it with the sphere moved
         * against it (slides) */
        const double lam[2][3] = {{3.0, -2.0, 0.0}, {13.5, 6.0, 0.0}};
        for (int c = 0; c < 2 && n == 9; c++) {
            rc_initial_state(m, y);
            rc_modes_init(m, d, 0.0, y);
            d->inter_mode[0] = RC_MODE_CLOSED;
            d->inter_slip[0] = 0;
            rc_static_set_start(s, y);
            rc_static_set_substep_start(s, 0.5, y);
            for (int i = 0; i < 6; i++) u[i] = (i % 6 < 3 ? 2e-4 : 0.01) * sin(1.7 * i + 0.3);
            if (c == 1) u[0] = -4e-4;
            for (int k = 0; k < 3; k++) u[6 + k] = lam[c][k] + (k == 2 ? 0.1 : 0.0);
            ENSURE(rc_static_residual(s, 0.5, u, r) == 0);
            ENSURE(d->inter_slip[0] == c);
            const double err0 = stiffness_fd_error(s, 0.5, u);
            fprintf(stderr, "    exact stick (%s): stiffness error %.3g of the largest entry\n", c ? "slip" : "stick", err0);
            ENSURE(err0 < 1e-6);
            /* about a start orientation that is not the identity */
            double *y2 = calloc((size_t)m->ny + 1, sizeof(double));
            ENSURE(y2 != NULL);
            if (y2) {
                memcpy(y2, y, (size_t)m->ny * sizeof(double));
                const int a = m->body_yadr[m->inter_ba[0]];
                const double q[4] = {cos(0.02), sin(0.02) * 0.6, sin(0.02) * 0.8, 0.0};
                memcpy(y2 + a + 3, q, sizeof q);
                rc_static_set_start(s, y2);
                rc_static_set_substep_start(s, 0.5, y2);
                const double err1 = stiffness_fd_error(s, 0.5, u);
                fprintf(stderr, "    exact stick (%s, turned): stiffness error %.3g of the largest entry\n", c ? "slip" : "stick", err1);
                ENSURE(err1 < 1e-6);
                free(y2);
            }
            rc_static_set_start(s, y);
            rc_static_set_substep_start(s, 0.5, y);
            /* at the substep's start: stuck exactly, the rows zero, the
             * sphere's tangential force rows lambda */
            double u0[9] = {0};
            for (int k = 0; k < 3; k++) u0[6 + k] = c ? 0.5 * lam[c][k] : lam[c][k];
            ENSURE(rc_static_residual(s, 0.5, u0, r) == 0);
            ENSURE(d->inter_slip[0] == 0);
            for (int k = 0; k < 3; k++) ENSURE_NEAR(r[6 + k], 0.0, 1e-13, 0.0);
            ENSURE_NEAR(r[0], u0[6], 1e-12, 1e-12);
            ENSURE_NEAR(r[1], u0[7], 1e-12, 1e-12);
        }
    }
    fix_close(&f);
    free(text);
}

/* Hysteresis in the static residual (docs/theory.md 7.8): TYPE6 Iform 1
 * (validation/static_hysteresis/case_iform1.rad: F_L = 1e5 P, Stiff 1e6,
 * F_U = 8e4 (P - 2e-5)+) from F_h0 = 3.5 N at P_0 = 6e-5 m: the trial
 * F_h0 + Stiff (P - P_0) on the Stiff line (ELASTIC, the state F_h), past
 * the load curve (LOAD) and below the unload curve (UNLOAD), each with its
 * branch and force, and the stiffness against central differences of the
 * residual (on the Stiff line: the column of F_h times Stiff dP/du). */
static void test_static_stiffness_hysteresis(void)
{
    rc_model *m = TU_LOAD_OK("validation/static_hysteresis/case_iform1.rad");
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        ENSURE(m->inter_iform[0] == 1 && m->inter_hidx[0] >= 0 && m->inter_stiff[0] == 1e6);
        const int n = rc_static_size(s), a = m->body_yadr[m->inter_ba[0]];
        double *r = calloc((size_t)n, sizeof(double)), *u = calloc((size_t)n, sizeof(double));
        ENSURE(n == 6 && r && u);
        /* dz of the sphere (P grows as z falls), the branch, the force */
        const double dz[3] = {-1e-6, -5e-6, 1e-6};
        const int want[3] = {RC_BR_ELASTIC, RC_BR_LOAD, RC_BR_UNLOAD};
        const double fw[3] = {3.5 + 1e6 * 1e-6, 1e5 * 6.5e-5, 8e4 * (5.9e-5 - 2e-5)};
        for (int c = 0; c < 3 && r && u; c++) {
            rc_initial_state(m, y);
            rc_modes_init(m, d, 0.5, y);
            d->inter_mode[0] = RC_MODE_CLOSED;
            d->inter_branch[0] = RC_BR_ELASTIC;
            y[a + 2] -= 6e-5; /* P_0 = 6e-5 m */
            y[m->inter_eadr[0] + m->inter_hidx[0]] = 3.5;
            rc_static_set_start(s, y);
            rc_static_set_substep_start(s, 0.5, y);
            memset(u, 0, (size_t)n * sizeof(double));
            u[2] = dz[c];
            ENSURE(rc_static_residual(s, 0.5, u, r) == 0);
            ENSURE(d->inter_branch[0] == want[c]);
            /* the vertical residual: the contact's force on the sphere less
             * its weight m g f(0.5), m = 1 kg, f(0.5) = 0.25 */
            ENSURE_NEAR(r[2], fw[c] - 9.81 * 0.25, 1e-9, 1e-9);
            const double err0 = stiffness_fd_error(s, 0.5, u);
            if (!(err0 < 1e-6)) fprintf(stderr, "  hysteresis branch %d: stiffness error %.3g\n", want[c], err0);
            ENSURE(err0 < 1e-6);
        }
        free(r);
        free(u);
    }
    fix_close(&f);
}

/* The whole of a text file, malloc'd (NULL: not read). */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *t = NULL;
    long n = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    if (n >= 0 && fseek(f, 0, SEEK_SET) == 0 && (t = malloc((size_t)n + 1)) != NULL) {
        if (fread(t, 1, (size_t)n, f) != (size_t)n) {
            free(t);
            t = NULL;
        } else {
            t[n] = '\0';
        }
    }
    fclose(f);
    return t;
}

/* Exact stick with hysteresis (docs/theory.md 7.8, "Exact stick"): the
 * sphere of validation/static_hysteresis/case_iform1.rad (held to the
 * vertical by /BCS 110 000, its rotations free) with Fric 0.3 and Istick 1,
 * on the Stiff line (F_h0 = 3.5 N at P_0 = 6e-5 m, 1 um deeper): the
 * limit's derivative through the hysteresis state (Stiff dP/du) in the
 * exact rows' columns, sticking and sliding, against central differences;
 * and with the sphere's rotations held as well (/BCS 110 111): x and y are
 * then held by the support alone, lambda_x = lambda_y = 0 their rows. */
static void test_static_stiffness_exact_stick_hysteresis(void)
{
    for (int held = 0; held < 2; held++) {
        char *text = read_text("validation/static_hysteresis/case_iform1.rad");
        ENSURE(text != NULL);
        if (!text) return;
        char *p = strstr(text, "/INTER/TYPE6/1\n");
        for (int k = 0; k < 3 && p; k++) p = strchr(p + 1, '\n'); /* the line Sfric Fric ... */
        if (p) memcpy(p + 1 + 20, "                 0.3", 20);
        p = p ? strchr(p + 1, '\n') : NULL; /* Istick, ... */
        if (p) memcpy(p + 1, "         1", 10);
        char *b = held ? strstr(text, "   110 000") : NULL;
        if (b) memcpy(b, "   110 111", 10);
        ENSURE(p != NULL && (!held || b));
        rc_error e;
        rc_model *m = tu_compile_text(text, "static_exact_hyst.rad", &e);
        if (!m) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(m != NULL);
        st_fix f = fix_open(m);
        rc_data *d = f.d;
        double *y = f.y;
        rc_static *s = f.s;
        if (fix_ready(&f)) {
            ENSURE(m->inter_fr[0].exact && m->inter_iform[0] == 1);
            const int n = rc_static_size(s), a = m->body_yadr[m->inter_ba[0]];
            ENSURE(n == 9);
            double u[9] = {0}, r[9] = {0};
            /* F_n = 4.5 N, the limit 1.35 N: lambda within it, and well beyond (the
             * central differences of the slip rows, r = K_t = Stiff = 1e6 N/m, need
             * |v| well above r h) */
            const double lam[2][3] = {{0.3, -0.2, 0.0}, {13.0, 6.0, 0.0}};
            for (int c = 0; c < 2 && n == 9; c++) {
                rc_initial_state(m, y);
                rc_modes_init(m, d, 0.5, y);
                d->inter_mode[0] = RC_MODE_CLOSED;
                d->inter_branch[0] = RC_BR_ELASTIC;
                d->inter_slip[0] = 0;
                y[a + 2] -= 6e-5;
                y[m->inter_eadr[0] + m->inter_hidx[0]] = 3.5;
                rc_static_set_start(s, y);
                rc_static_set_substep_start(s, 0.5, y);
                memset(u, 0, sizeof u);
                u[2] = -1e-6;
                if (!held) {
                    u[3] = 2e-7;
                    u[4] = -3e-7;
                }
                for (int k = 0; k < 3; k++) u[6 + k] = lam[c][k];
                ENSURE(rc_static_residual(s, 0.5, u, r) == 0);
                ENSURE(d->inter_branch[0] == RC_BR_ELASTIC);
                ENSURE(d->inter_slip[0] == c);
                if (held) {
                    ENSURE(r[6] == u[6] && r[7] == u[7]); /* the support carries x and y */
                }
                const double err = stiffness_fd_error(s, 0.5, u);
                fprintf(stderr, "    exact stick on the Stiff line%s (%s): stiffness error %.3g of the largest entry\n",
                        held ? ", x, y held" : "", c ? "slip" : "stick", err);
                ENSURE(err < 1e-6);
            }
        }
        fix_close(&f);
        free(text);
    }
}

/* Validation deck `path` without its /BCS card (its bodies free), compiled
 * (NULL on failure, with the message printed). */
static rc_model *compile_without_bcs(const char *path, const char *name)
{
    char *text = read_text(path);
    ENSURE(text != NULL);
    if (!text) return NULL;
    char *b = strstr(text, "/BCS/1"), *e = b ? strstr(b + 1, "\n/") : NULL;
    ENSURE(b && e);
    if (b && e) memmove(b, e + 1, strlen(e + 1) + 1);
    rc_error err;
    rc_model *m = tu_compile_text(text, name, &err);
    if (!m) fprintf(stderr, "  %s\n", err.msg);
    ENSURE(m != NULL);
    free(text);
    return m;
}

/* Hysteresis on a contact of several points: validation/static_hysteresis'
 * case_box.rad (Iform 2 on a box's corners, P_e := P the deepest corner's)
 * without its /BCS, pressed in from F_h0 = 3.5 N at P_0 = 6e-5 m and tilted,
 * on the Stiff line: the stiffness (F_h's and P_e's columns) against
 * central differences. */
static void test_static_stiffness_hysteresis_box(void)
{
    rc_model *m = compile_without_bcs("validation/static_hysteresis/case_box.rad", "static_hyst_box.rad");
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        const int n = rc_static_size(s), a = m->body_yadr[m->inter_ba[0]];
        ENSURE(n == 6 && m->inter_peidx[0] >= 0 && m->inter_hidx[0] >= 0);
        rc_initial_state(m, y);
        rc_modes_init(m, d, 0.5, y);
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->inter_branch[0] = RC_BR_ELASTIC;
        y[a + 2] -= 6e-5;
        y[m->inter_eadr[0] + m->inter_hidx[0]] = 3.5;
        y[m->inter_eadr[0] + m->inter_peidx[0]] = 6e-5;
        rc_static_set_start(s, y);
        rc_static_set_substep_start(s, 0.5, y);
        /* 1 um in, tilts of 1e-5 rad (corners 1 um apart): on the Stiff line */
        const double u[6] = {0.0, 0.0, -1e-6, 1e-5, -0.7e-5, 0.0};
        double r[6];
        ENSURE(n != 6 || rc_static_residual(s, 0.5, u, r) == 0);
        ENSURE(d->inter_branch[0] == RC_BR_ELASTIC);
        const double err0 = n == 6 ? stiffness_fd_error(s, 0.5, u) : INFINITY;
        if (!(err0 < 1e-6)) fprintf(stderr, "  hysteresis on a box: stiffness error %.3g\n", err0);
        ENSURE(err0 < 1e-6);
    }
    fix_close(&f);
}

/* Several contact points (docs/theory.md 7.8): validation/static_boxes'
 * box on a box on a floor without its /BCS, both boxes pressed in and
 * tilted (a single deepest corner in each contact), the law at the deepest
 * point's penetration (P_e := P) shared over the corners: the stiffness
 * (the engine's P_e columns times dP/du added) against central differences
 * of the residual. */
static void test_static_stiffness_boxes(void)
{
    rc_model *m = compile_without_bcs("validation/static_boxes/case.rad", "static_boxes_jac.rad");
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        const int n = rc_static_size(s);
        ENSURE(n == 12 && m->inter_peidx[0] >= 0 && m->inter_peidx[1] >= 0);
        double u[12] = {0}, r[12];
        rc_initial_state(m, y);
        rc_modes_init(m, d, 0.5, y);
        d->inter_mode[0] = d->inter_mode[1] = RC_MODE_CLOSED;
        rc_static_set_start(s, y);
        rc_static_set_substep_start(s, 0.5, y);
        /* lower box 30 um down, upper 50 um; tilts of 1e-4 rad */
        const double du[12] = {1e-6, -2e-6, -3e-5, 1e-4, -0.7e-4, 0.3e-4, 2e-6, 1e-6, -5e-5, -0.8e-4, 1.2e-4, -0.5e-4};
        memcpy(u, du, sizeof u);
        ENSURE(n != 12 || rc_static_residual(s, 0.5, u, r) == 0);
        const double err0 = n == 12 ? stiffness_fd_error(s, 0.5, u) : INFINITY;
        if (!(err0 < 1e-6)) fprintf(stderr, "  boxes: stiffness error %.3g\n", err0);
        ENSURE(err0 < 1e-6);
    }
    fix_close(&f);
}

/* Friction per contact point (docs/theory.md 7.8): validation/static_boxes'
 * case_incline.rad (a box on a floor, TYPE6 Fric 0.3 with Stiff 2e5 on its
 * 8 corners; gravity tilted), pressed in and tilted, each corner's unit
 * force from a start value: all four bottom corners sticking, then pushed
 * past the limit (sliding): the stiffness (the engine's columns of each
 * corner's state times -K_t d(p_a - p_b)/du) against central differences
 * of the residual, and the corners' modes. */
static void test_static_stiffness_point_friction(void)
{
    rc_model *m = TU_LOAD_OK("validation/static_boxes/case_incline.rad");
    st_fix f = fix_open(m);
    rc_data *d = f.d;
    double *y = f.y;
    rc_static *s = f.s;
    if (fix_ready(&f)) {
        const int n = rc_static_size(s), npt = m->inter_npt[0];
        ENSURE(n == 6 && npt == 8 && m->inter_pst[0] == 3);
        double u[6], r[6];
        for (int c = 0; c < 2 && n == 6; c++) {
            rc_initial_state(m, y);
            rc_modes_init(m, d, 0.5, y);
            d->inter_mode[0] = RC_MODE_CLOSED;
            /* every corner's unit force 1 N along x at the start */
            for (int j = 0; j < npt; j++) y[m->inter_eadr[0] + m->inter_ns[0] + 3 * j] = 1.0;
            rc_static_set_start(s, y);
            rc_static_set_substep_start(s, 0.5, y);
            /* 20 um in, tilts of 1e-4 rad; c = 1: 1 mm along x (200 N of
             * the unit spring, past the limit) */
            const double du[6] = {c ? -1e-3 : 2e-6, -1e-6, -2e-5, 1e-4, -0.6e-4, 0.3e-4};
            memcpy(u, du, sizeof u);
            ENSURE(rc_static_residual(s, 0.5, u, r) == 0);
            int nslip = 0;
            for (int j = 0; j < npt; j++) nslip += d->pt_slip[m->inter_pbase[0] + j];
            printf("    case %d: %d corners sliding of %d\n", c, nslip, npt);
            ENSURE(c ? nslip >= 1 : nslip == 0);
            const double err0 = stiffness_fd_error(s, 0.5, u);
            if (!(err0 < 1e-6)) fprintf(stderr, "  point friction (%s): stiffness error %.3g\n", c ? "slip" : "stick", err0);
            ENSURE(err0 < 1e-6);
        }
    }
    fix_close(&f);
}

/* Method 3 refuses what this version does not solve, naming the card. */
static void test_static_scope(void)
{
    char *t = malloc(strlen(deck_one) + 400);
    ENSURE(t != NULL);
    if (!t) return;
    /* friction with a speed multiplier (TYPE6 fct_IDfv): the static
     * analysis has no sliding speed */
    strcpy(t, deck_one);
    char *p = strstr(t, "/INTER/TYPE6/1");
    ENSURE(p != NULL);
    if (p) {
        p = strchr(p, '\n'); /* title line */
        p = p ? strchr(p + 1, '\n') : NULL; /* surfaces */
        p = p ? strchr(p + 1, '\n') : NULL; /* Sfric Fric Gap ... */
        if (p) memcpy(p + 1 + 20, "                 0.3", 20);
        p = p ? strchr(p + 1, '\n') : NULL; /* Istick, Inacti, fct_IDff, fct_IDfv */
        if (p) memcpy(p + 1 + 50, "         1", 10);
        TU_EXPECT_TEXT_ERROR(t, "static_fric.rad", "/INTER/TYPE6/1", "static analysis", "speed multiplier");
    }
    /* exact stick (Istick 1): in the scope (the friction force an unknown
     * of the equilibrium), through the setter and under a preload */
    {
        char *x = deck_one_friction();
        char *q = x ? strstr(x, "0.3                   0\n") : NULL;
        q = q ? strchr(q, '\n') : NULL;
        ENSURE(q != NULL);
        if (q) {
            memcpy(q + 1, "         1", 10);
            rc_error e1;
            rc_model *mx = tu_compile_text(x, "static_exact_scope.rad", &e1);
            if (!mx) fprintf(stderr, "  %s\n", e1.msg);
            ENSURE(mx != NULL && mx->method == 3);
            if (mx) {
                ENSURE(rc_static_scope(mx, NULL, &e1) == RC_OK);
                ENSURE(rc_preload_scope(mx, NULL, &e1) == RC_OK);
                ENSURE(rc_model_set_method(mx, 1, &e1) == RC_EINPUT && strstr(e1.msg, "exact stick"));
                ENSURE(rc_model_set_method(mx, 3, &e1) == RC_OK);
                rc_model_free(mx);
            }
        }
        free(x);
    }
    /* a joint-free model accepts the method through the setter, and 4 is refused */
    rc_error e;
    rc_model *m = tu_compile_text(deck_two, "static_set.rad", &e);
    ENSURE(m != NULL);
    if (m) {
        ENSURE(rc_model_set_method(m, 1, &e) == RC_OK);
        ENSURE(rc_model_set_method(m, 3, &e) == RC_OK);
        ENSURE(rc_model_set_method(m, 4, &e) == RC_EINPUT);
        rc_model_free(m);
    }
    free(t);
}

/* A limit point: a sphere (1 kg, x and y and its rotations held) on a
 * floor whose TYPE6 load curve rises to 10 N at 1 mm and falls after it
 * (a softening contact), gravity ramped from 0 to 2 g over 1 s: the static
 * analysis follows the curve up to the peak, at m g f(t) = 10 N, t* =
 * 10 / (9.81 * 2) s, and past it reports a snap-through with its load time
 * and the contact's peak, not a Newton failure. */
static void test_static_snap_through(void)
{
    static const char *deck =
        "/NODE\n1,0,0,0\n"
        "/RBODY/1\nsphere\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
        "/SURF/ELLIPS/1\nsphere\n0,2,1\n0,0,0\n0.05,0.05,0.05\n"
        "/GRNOD/NODE/1\ngroup\n1\n"
        "/BCS/1\nheld\n110 111,0,1\n"
        "/SURF/PLANE/2\nfloor\n0,0,-0.05\n0,0,1\n"
        "/FUNCT/2\nload factor\n0,0\n1,2\n"
        "/GRAV/1\ngravity\n2,Z,0,0,0,,1,-9.81\n"
        "/INTER/TYPE6/1\nsphere - floor\n1,2\n\n\n"
        "         3         0                                                 0\n"
        "         0                             1\n"
        "                             0         0\n"
        "/FUNCT/3\nsoftening load curve\n0,0\n0.001,10\n0.002,5\n0.01,20\n"
        "/RUN\n1.0,0.05\n/SOLVER\n3\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "static_snap.rad", &e);
    ENSURE(m != NULL);
    if (!m) {
        fprintf(stderr, "  %s\n", e.msg);
        return;
    }
    rc_stats st;
    const rc_status r = rc_run(m, NULL, &st, &e);
    const double ts = 10.0 / (9.81 * 2.0);
    printf("    %s\n", e.msg);
    ENSURE(r == RC_ESOLVER);
    ENSURE(strstr(e.msg, "a limit point (snap-through)") != NULL);
    ENSURE(strstr(e.msg, "card /INTER/TYPE6/1 stops rising at P = 0.001 m, F = 10 N") != NULL);
    const char *q = strstr(e.msg, "(snap-through) at the load time t = ");
    const double tl = q ? strtod(q + strlen("(snap-through) at the load time t = "), NULL) : -1.0;
    ENSURE(tl <= ts && ts - tl < 1e-6);
    rc_model_free(m);
}


/* Joints (docs/theory.md 7.8, "Joints"): a chain of every kind, a body on
 * a revolute joint to the ground, a spherical, a distance, a fixed and a
 * prismatic joint from each body to the next, under gravity with a spring
 * on the last; the stiffness with the joints' rows and multipliers (the
 * augmented system [K G^T; G 0] of the unknowns and the reactions) against
 * central differences of the residual at the start and off the joints
 * (displaced, rotated, with reactions of some newtons). */
static const char *deck_joints =
    "/NODE\n1,0.3,0,0\n2,0.6,0.1,0\n3,0.9,0,0.1\n4,1.2,0,0\n5,1.5,0,0\n"
    "/RBODY/1\nb1\n1,,,,1.3\n0.011,0.013,0.017\n0,0,0\n"
    "/RBODY/2\nb2\n2,,,,0.7\n0.005,0.007,0.006\n0,0,0\n"
    "/RBODY/3\nb3\n3,,,,0.9\n0.008,0.004,0.009\n0,0,0\n"
    "/RBODY/4\nb4\n4,,,,1.1\n0.012,0.010,0.007\n0,0,0\n"
    "/RBODY/5\nb5\n5,,,,0.5\n0.003,0.004,0.005\n0,0,0\n"
    "/GRAV/1\ngravity\n0,Y,0,0,0,,1,-9.81\n"
    "/JOINT/REVOLUTE/1\npivot\n1,0\n0,0,0\n0.1,0.2,1\n"
    "/JOINT/SPHERICAL/2\nball\n2,1\n0.45,0.05,0\n"
    "/JOINT/DISTANCE/3\nrod\n3,2\n0.9,0,0.1\n0.6,0.1,0\n"
    "/JOINT/FIXED/4\nweld\n4,3\n1.05,0,0.05\n"
    "/JOINT/PRISMATIC/5\nslide\n5,4\n1.35,0,0\n1,0.3,0\n"
    "/COUPLING/SPRING/6\nspring\n5,0,1\n1.5,0,0\n1.6,0.2,0.1\n0.1\n300\n"
    "/RUN\n1.0,0.5\n/SOLVER\n3\n";

static void test_static_stiffness_joints(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(deck_joints, "static_joints.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    st_fix f = fix_open(m);
    if (fix_ready(&f)) {
        /* 30 unknowns of the bodies, 5 + 3 + 1 + 6 + 5 joint rows */
        const int n = rc_static_size(f.s);
        ENSURE(n == 30 + 20);
        rc_initial_state(m, f.y);
        rc_modes_init(m, f.d, 0.0, f.y);
        rc_static_set_start(f.s, f.y);
        double *u = calloc((size_t)n, sizeof(double)), *r = calloc((size_t)n, sizeof(double));
        ENSURE(u && r);
        if (u && r) {
            /* at the start the rows vanish (the joints hold there) */
            ENSURE(rc_static_residual(f.s, 0.5, u, r) == 0);
            double gmax = 0.0;
            for (int i = 30; i < n; i++) gmax = fmax(gmax, fabs(r[i]));
            printf("    joint rows at the start: max |g| %.2e\n", gmax);
            ENSURE(gmax < 1e-15);
            for (int i = 30; i < n; i++) u[i] = 3.7 * sin(0.9 * i + 0.2);
            const double e0 = stiffness_fd_error(f.s, 0.5, u);
            for (int i = 0; i < 30; i++) u[i] = (i % 6 < 3 ? 2e-3 : 0.05) * sin(1.7 * i + 0.3);
            const double e1 = stiffness_fd_error(f.s, 0.5, u);
            printf("    max scaled |K - FD|: %.2e at the start, %.2e off the joints\n", e0, e1);
            ENSURE(e0 < 1e-6);
            ENSURE(e1 < 1e-6);
            /* a unit reaction of the pivot's first row (a force along x
             * on body 1 at the pivot): the residual's force on body 1 */
            memset(u, 0, (size_t)n * sizeof(double));
            ENSURE(rc_static_residual(f.s, 0.5, u, r) == 0);
            const double fy0 = r[1];
            u[30] = 1.0;
            ENSURE(rc_static_residual(f.s, 0.5, u, r) == 0);
            ENSURE_NEAR(r[0], 1.0, 0, 1e-14);
            ENSURE_NEAR(r[1], fy0, 0, 1e-14);
            ENSURE_NEAR(fy0, -1.3 * 9.81, 1e-14, 0);
        }
        free(u);
        free(r);
    }
    fix_close(&f);
}

/* Imposed rotations and a release at Tstop (docs/theory.md 7.8, "Imposed
 * velocities"): body 1 (translations held) turned about z by /IMPVEL ZZ
 * at 0.2 rad/s until Tstop = 0.5 s against two pretensioned springs at
 * its arms, then released; body 2 pushed down by /IMPVEL Z at 0.1 m/s
 * until Tstop = 0.5 s against gravity on a spring above it, then
 * released. At t_end = 0.4 s (held): body 1 turned by 0.08 rad about z,
 * body 2 at z = -0.04 m; at 1 s (released): body 1 back at its start
 * (the springs' equilibrium), body 2 at z = -m g / k. */
static const char *deck_impvel =
    "/NODE\n1,0,0,0\n2,5,0,0\n"
    "/RBODY/1\nlever\n1,,,,1.0\n0.01,0.01,0.01\n0,0,0\n"
    "/RBODY/2\nblock\n2,,,,2.0\n0.01,0.01,0.01\n0,0,0\n"
    "/GRNOD/NODE/1\ng1\n1\n/GRNOD/NODE/2\ng2\n2\n"
    "/BCS/1\nheld\n111 000,0,1\n"
    "/GRAV/1\ngravity\n0,Z,0,0,2,,1,-9.81\n"
    "/COUPLING/SPRING/1\narm x\n1,0,1\n0.5,0,0\n1.5,0,0\n0.8\n300\n"
    "/COUPLING/SPRING/2\narm y\n1,0,1\n0,0.5,0\n0,1.5,0\n0.8\n300\n"
    "/COUPLING/SPRING/3\nhanger\n2,0,1\n5,0,0\n5,0,1\n1.0\n1000\n"
    "/FUNCT/1\nconstant\n0,1\n10,1\n"
    "/IMPVEL/1\nturn\n1,ZZ,0,0,1\n1,0.2,0,0.5\n"
    "/IMPVEL/2\npush\n1,Z,0,0,2\n1,-0.1,0,0.5\n"
    "/RUN\n1.0,0.1\n/SOLVER\n3\n";

static void test_static_impvel(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(deck_impvel, "static_impvel.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    double *y = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(y != NULL);
    const double tends[2] = {0.4, 1.0};
    for (int c = 0; y && c < 2; c++) {
        rc_run_options o = {.y_end = y, .t_end_override = tends[c]};
        rc_stats st;
        const rc_status r = rc_run(m, &o, &st, &e);
        if (r) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(r == RC_OK);
        const double *y1 = y + m->body_yadr[0], *y2 = y + m->body_yadr[1];
        const double ang = c == 0 ? 0.08 : 0.0, z2 = c == 0 ? -0.04 : -2.0 * 9.81 / 1000.0;
        printf("    t = %.1f s: q1 = (%.15f, %.3g, %.3g, %.15f), z2 = %.15f m\n", tends[c], y1[3], y1[4], y1[5], y1[6],
               y2[2]);
        ENSURE_NEAR(y1[3], cos(0.5 * ang), 0, 1e-12);
        ENSURE_NEAR(y1[6], sin(0.5 * ang), 0, 1e-12);
        ENSURE_NEAR(y1[4], 0.0, 0, 1e-12);
        ENSURE_NEAR(y1[5], 0.0, 0, 1e-12);
        ENSURE_NEAR(y2[2], z2, 0, 1e-12);
        ENSURE_NEAR(y2[0], 5.0, 0, 1e-12);
    }
    free(y);
    rc_model_free(m);
    /* rotations about axes that turn (two components on one body), the
     * orientation e (x) q0 with e integrated from de/dt = 1/2 w_g (x) e:
     * (a) w_g = (0.1, 0, 0.2) rad/s constant (a fixed axis): e = exp(w_g t);
     * (b) w_x = 0.5 rad/s up to 0.2 s, then w_z = 1 rad/s (from 0.2 + 1e-12 s):
     * e = exp(1.0 (t - 0.2) z) (x) exp(0.1 x), which differs from the
     * rotation by the integral of w_g (the order matters) */
    static const char *extra[2] = {"/IMPVEL/3\nturn x\n1,XX,0,0,1\n1,0.1,0,0.5\n",
                                   "/FUNCT/7\nx first\n0,1\n0.2,1\n0.200000000001,0\n10,0\n"
                                   "/FUNCT/8\nz after\n0,0\n0.2,0\n0.200000000001,1\n10,1\n"
                                   "/IMPVEL/3\nturn x\n7,XX,0,0,1\n1,0.5,0,0.5\n"};
    for (int c = 0; c < 2; c++) {
        char *t = malloc(strlen(deck_impvel) + 300);
        ENSURE(t != NULL);
        if (!t) continue;
        strcpy(t, deck_impvel);
        if (c == 1) { /* the z rotation on function 8 at 1 rad/s */
            char *q = strstr(t, "/IMPVEL/1\nturn\n1,ZZ,0,0,1\n1,0.2,0,0.5\n");
            memcpy(q, "/IMPVEL/1\nturn\n8,ZZ,0,0,1\n1,1.0,0,0.5\n", strlen("/IMPVEL/1\nturn\n8,ZZ,0,0,1\n1,1.0,0,0.5\n"));
        }
        char *p = strstr(t, "/RUN");
        memmove(p + strlen(extra[c]), p, strlen(p) + 1);
        memcpy(p, extra[c], strlen(extra[c]));
        rc_model *m2 = tu_compile_text(t, "static_impvel2.rad", &e);
        if (!m2) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(m2 != NULL);
        double *y2 = m2 ? calloc((size_t)m2->ny + 1, sizeof(double)) : NULL;
        if (y2) {
            rc_run_options o = {.y_end = y2, .t_end_override = 0.4};
            rc_stats st;
            const rc_status r = rc_run(m2, &o, &st, &e);
            if (r) fprintf(stderr, "  %s\n", e.msg);
            ENSURE(r == RC_OK);
            const double *q1 = y2 + m2->body_yadr[0];
            double want[4];
            if (c == 0) {
                const double w[3] = {0.1, 0.0, 0.2}, a = 0.4 * sqrt(0.05);
                want[0] = cos(0.5 * a);
                for (int k = 0; k < 3; k++) want[k + 1] = sin(0.5 * a) * 0.4 * w[k] / a;
            } else { /* exp(0.2 z) (x) exp(0.1 x) */
                const double cz = cos(0.1), sz = sin(0.1), cx = cos(0.05), sx = sin(0.05);
                want[0] = cz * cx;
                want[1] = cz * sx;
                want[2] = sz * sx;
                want[3] = sz * cx;
            }
            printf("    two axes (%s): q1 = (%.15f, %.15f, %.15f, %.15f), closed form (%.15f, %.15f, %.15f, %.15f)\n",
                   c == 0 ? "fixed axis" : "x then z", q1[3], q1[4], q1[5], q1[6], want[0], want[1], want[2], want[3]);
            for (int k = 0; k < 4; k++) ENSURE_NEAR(q1[3 + k], want[k], 0, 1e-11);
        }
        free(y2);
        rc_model_free(m2);
        free(t);
    }
}

/* Inacti 5 in statics (docs/theory.md 3.1, 7.8): a sphere (1 kg) 1 mm
 * into a floor (k = 1e5 N/m) at the start, the gap reduced by it (force
 * free), x and y held, a spring of 100 N/m above it relaxed at the start;
 * gravity's function 1 at t = 0, -1 at t = 1 s, 1 again at t = 2 s. It
 * sinks by m g / (k + k_s) (the offset unchanged), lifts off by m g / k_s
 * at t = 1 s (the offset taken up to 0: the full gap back), and comes back
 * at t = 2 s onto the full gap: a sink of (m g - k P0) / (k + k_s). */
static void test_static_inacti5(void)
{
    static const char *deck =
        "/NODE\n1,0,0,0.049\n"
        "/RBODY/1\nsphere\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
        "/SURF/ELLIPS/1\nsphere\n0,2,1\n0,0,0.049\n0.05,0.05,0.05\n"
        "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
        "/GRNOD/NODE/1\ngroup\n1\n"
        "/BCS/1\nheld\n110 000,0,1\n"
        "/FUNCT/1\nload curve\n0,0\n1,100000\n"
        "/FUNCT/2\ngravity factor\n0,1\n1,-1\n2,1\n"
        "/GRAV/1\ngravity\n2,Z,0,0,0,,1,-9.81\n"
        "/COUPLING/SPRING/1\nspring\n1,0,1\n0,0,0.049\n0,0,1.049\n1.0\n100\n"
        "/INTER/TYPE6/1\nsphere - floor\n1,2\n\n"
        "                   0         0         5         0         0\n"
        "         1         0                                                 0\n"
        "         0\n"
        "                             0         0\n"
        "/RUN\n2.0,0.25\n/SOLVER\n3\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "static_inacti5.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    double *y = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(y != NULL);
    const double g = 9.81, k = 1e5, ks = 100.0, P0 = 1e-3;
    const double tends[3] = {0.25, 1.0, 2.0};
    const double sink[3] = {0.5 * g / (k + ks), -g / ks, (g - k * P0) / (k + ks)};
    for (int c = 0; y && c < 3; c++) {
        rc_run_options o = {.y_end = y, .t_end_override = tends[c]};
        rc_stats st;
        const rc_status r = rc_run(m, &o, &st, &e);
        if (r) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(r == RC_OK);
        const double z = y[m->body_yadr[0] + 2];
        printf("    t = %.2f s: sink %.15g m, expected %.15g m\n", tends[c], 0.049 - z, sink[c]);
        ENSURE_NEAR(0.049 - z, sink[c], 1e-9, 1e-15);
    }
    free(y);
    /* a preload refuses it: the dynamic start would take the equilibrium's
     * penetration as its offset */
    ENSURE(rc_model_set_method(m, 1, &e) == RC_OK);
    ENSURE(rc_model_set_preload(m, 1, &e) == RC_EINPUT);
    ENSURE(strstr(e.msg, "Inacti 5") != NULL && strstr(e.msg, "/INTER/TYPE6/1") != NULL);
    rc_model_free(m);
}

/* A pendulum (1.5 kg at 1 m on a revolute joint about z, gravity -y)
 * started 30 degrees from the bottom finds the bottom, its pivot carrying
 * the weight; started 30 degrees from the top, Newton finds the top, which
 * the stability check refuses (docs/theory.md 7.8, "Joints"). */
static void test_static_pendulum(void)
{
    static const char *fmt =
        "/NODE\n1,0.5,%s,0\n"
        "/RBODY/1\nbob\n1,,,,1.5\n0.02,0.02,0.02\n0,0,0\n"
        "/GRAV/1\ngravity\n0,Y,0,0,0,,1,-9.81\n"
        "/JOINT/REVOLUTE/1\npivot\n1,0\n0,0,0\n0,0,1\n"
        "/RUN\n1.0,0.5\n/SOLVER\n3\n";
    for (int top = 0; top < 2; top++) {
        char deck[1024];
        snprintf(deck, sizeof deck, fmt, top ? "0.866025403784439" : "-0.866025403784439");
        rc_error e;
        rc_model *m = tu_compile_text(deck, top ? "static_pend_top.rad" : "static_pend_bottom.rad", &e);
        if (!m) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(m != NULL);
        if (!m) continue;
        double *y = calloc((size_t)m->ny + 1, sizeof(double));
        ENSURE(y != NULL);
        rc_run_options o = {.y_end = y};
        rc_stats st;
        const rc_status r = y ? rc_run(m, &o, &st, &e) : RC_ENOMEM;
        if (top) {
            printf("    from the top: %s\n", e.msg);
            ENSURE(r == RC_ESOLVER);
            ENSURE(strstr(e.msg, "is unstable") != NULL);
        } else {
            ENSURE(r == RC_OK);
            if (y) {
                ENSURE_NEAR(y[m->body_yadr[0]], 0.0, 0, 1e-12);
                ENSURE_NEAR(y[m->body_yadr[0] + 1], -1.0, 0, 1e-12);
            }
        }
        free(y);
        rc_model_free(m);
    }
}

/* A slider on a prismatic joint along x with nothing along its axis (the
 * joint holds the rest): the stiffness is singular in that one direction,
 * an error naming the body and translation x; with gravity along the axis
 * and a spring it rests where the spring carries it (the joint alone holds
 * the other five directions). */
static void test_static_prismatic_free(void)
{
    static const char *fmt =
        "/NODE\n1,0,0,0\n"
        "/RBODY/1\nslider\n1,,,,2.0\n0.01,0.01,0.01\n0,0,0\n"
        "/GRAV/1\ngravity\n0,%s,0,0,0,,1,-9.81\n"
        "/JOINT/PRISMATIC/1\nslide\n1,0\n0,0,0\n1,0,0\n"
        "%s"
        "/RUN\n1.0,0.5\n/SOLVER\n3\n";
    for (int held = 0; held < 2; held++) {
        char deck[1024];
        snprintf(deck, sizeof deck, fmt, held ? "X" : "Y",
                 held ? "/COUPLING/SPRING/2\nspring\n1,0,1\n0,0,0\n1,0,0\n1.0\n500\n" : "");
        rc_error e;
        rc_model *m = tu_compile_text(deck, held ? "static_slide_held.rad" : "static_slide_free.rad", &e);
        if (!m) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(m != NULL);
        if (!m) continue;
        double *y = calloc((size_t)m->ny + 1, sizeof(double));
        rc_run_options o = {.y_end = y};
        rc_stats st;
        const rc_status r = y ? rc_run(m, &o, &st, &e) : RC_ENOMEM;
        if (!held) {
            printf("    free along the axis: %s\n", e.msg);
            ENSURE(r == RC_ESOLVER);
            ENSURE(strstr(e.msg, "/RBODY/1 has no support in translation x") != NULL);
        } else {
            ENSURE(r == RC_OK);
            /* the spring (500 N/m, relaxed) stretched by m g / k towards -x */
            if (y) ENSURE_NEAR(y[m->body_yadr[0]], -2.0 * 9.81 / 500.0, 1e-10, 0);
        }
        free(y);
        rc_model_free(m);
    }
}

/* Friction laws taken at rest (docs/theory.md 7.8, "Friction at rest"): a
 * sphere (1 kg, R = 0.05 m, rotations held) touching a floor (linear k =
 * 1e5 N/m, stick stiffness 2e4 N/m), gravity g = 9.81 m/s^2 tilted by
 * theta from the vertical and ramped by f(t) = t over 1 s (output every
 * 0.05 s). While it sticks F_n = m g cos(theta) f [N], F_t = m g sin(theta)
 * f [N]; it slides, with no static equilibrium, where F_t reaches Sfric +
 * mu(p, v = 0) F_n, p = F_n / Area [Pa]. The deck with gravity tilted by
 * theta, the TYPE6 line 2 (Sfric, Fric), line 3 (fct_IDff, fct_IDfv) and
 * the extra cards `more` (a /FRICTION card, curves). */
static char *deck_at_rest(double theta, const char *line2, const char *line3, const char *more)
{
    const double g = 9.81;
    char *t = malloc(4096);
    if (!t) return NULL;
    snprintf(t, 4096,
             "/NODE\n1,0,0,0.05\n"
             "/RBODY/1\nsphere\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
             "/SURF/ELLIPS/1\nsphere\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n"
             "/GRNOD/NODE/1\ngroup\n1\n"
             "/BCS/1\nrotations held\n000 111,0,1\n"
             "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear k = 1e5 N/m\n0,0\n1,100000\n"
             "/FUNCT/2\nload factor\n0,0\n1,1\n"
             "/GRAV/1\ngravity x\n2,X,0,0,0,,1,%.17g\n"
             "/GRAV/2\ngravity z\n2,Z,0,0,0,,1,%.17g\n"
             "/INTER/TYPE6/1\nsphere - floor\n1,2\n%s\n%s\n"
             "1,0\n"
             "0,0,20000\n"
             "\n"
             "%s"
             "/RUN\n1.0,0.05\n/SOLVER\n3\n",
             g * sin(theta), -g * cos(theta), line2, line3, more);
    return t;
}

/* Runs deck `text`: 0 when it sticks through the ramp (*x the sphere's x
 * at the end [m]),
 * else the load times that bracket the onset of sliding from the error
 * (*t0 the last equilibrium's, *t1 the first without one). */
static int run_at_rest_stats(const char *text, const char *name, double *x, double *t0, double *t1, rc_stats *sto)
{
    rc_error e;
    rc_model *m = tu_compile_text(text, name, &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return -1;
    double *y = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(y != NULL);
    rc_run_options o = {.y_end = y};
    rc_stats st;
    const rc_status r = y ? rc_run(m, &o, &st, &e) : RC_ENOMEM;
    int out = 0;
    if (r == RC_OK) *x = y[m->body_yadr[0]];
    free(y);
    if (r != RC_OK) {
        const char *a = "no static equilibrium at the load time t = ", *b = "the last equilibrium at t = ";
        const char *pa = strstr(e.msg, a), *pb = strstr(e.msg, b);
        ENSURE(r == RC_ESOLVER && pa && pb && strstr(e.msg, "friction can hold") != NULL);
        if (!(r == RC_ESOLVER && pa && pb)) fprintf(stderr, "  %s\n", e.msg);
        *t1 = pa ? strtod(pa + strlen(a), NULL) : -1.0;
        *t0 = pb ? strtod(pb + strlen(b), NULL) : -1.0;
        out = 1;
    }
    if (sto) *sto = st;
    rc_model_free(m);
    return out;
}

static int run_at_rest(const char *text, const char *name, double *x, double *t0, double *t1)
{
    return run_at_rest_stats(text, name, x, t0, t1, NULL);
}

/* The onset of sliding of deck_at_rest's sphere against the closed form
 * ts (the load factor at which m g sin(theta) f = Sfric + mu(p, 0) m g
 * cos(theta) f): bracketed by the last equilibrium and the first load time
 * without one, within twice the smallest substep (1e-6 of Dt_out). */
static void check_onset(const char *text, const char *name, double ts)
{
    double x = 0, t0 = -1, t1 = -1;
    const int r = run_at_rest(text, name, &x, &t0, &t1);
    printf("    %s: onset t* = %.9f s, bracket [%.9f, %.9f] s (closed form - last equilibrium %.2e s)\n", name, ts,
           t0, t1, ts - t0);
    ENSURE(r == 1);
    ENSURE(t0 <= ts && ts <= t1 && t1 - t0 < 2e-6 * 0.05);
}

static void test_static_friction_at_rest(void)
{
    const double g = 9.81, A = 0.01; /* m = 1 kg; Area [m^2] */
    /* the pressure at which mu(p, 0) = tan(theta), from the root of
     * a + b p + c p^2 = tan(theta) (c < 0, b < 0: mu falls with the
     * pressure) */
#define ROOT_P(a, b, c, th) ((-(b) - sqrt((b) * (b) - 4.0 * (c) * ((a) - tan(th)))) / (2.0 * (c)))
    const double th = 0.33;
    /* Ifric 1, generalised viscous: mu(p, 0) = Fric + C1 p + C4 p^2, the
     * speed terms C2, C3, C5 not acting at rest */
    {
        const double fric = 0.5, c1 = -2e-4, c4 = -1e-8;
        const double ps = ROOT_P(fric, c1, c4, th), ts = ps * A / (g * cos(th));
        char card[600];
        snprintf(card, sizeof card,
                 "/FRICTION/1\nIfric 1 at rest\n1,0,,2,,%g\n%g,5,0.01,%g,3\n0,%g\n", A, c1, c4, fric);
        char *t = deck_at_rest(th, "", "", card);
        ENSURE(t != NULL);
        if (t) check_onset(t, "static_ifric1.rad", ts);
        free(t);
        /* the same with a filter (Ifiltr 3, 4 Hz): at rest the filtered
         * limit is the limit */
        snprintf(card, sizeof card,
                 "/FRICTION/1\nIfric 1 at rest, filtered\n1,3,4,2,,%g\n%g,5,0.01,%g,3\n0,%g\n", A, c1, c4, fric);
        t = deck_at_rest(th, "", "", card);
        ENSURE(t != NULL);
        if (t) check_onset(t, "static_ifric1_filter.rad", ts);
        free(t);
    }
    /* Ifric 2, modified Darmstad: mu(p, 0) = Fric + C5 + C3 p + C1 p^2 (the
     * exponentials of the speed 1 at rest) */
    {
        const double fric = 0.1, c5 = 0.45, c3 = -2.5e-4, c1 = -2e-8;
        const double ps = ROOT_P(fric + c5, c3, c1, th), ts = ps * A / (g * cos(th));
        char card[600];
        snprintf(card, sizeof card, "/FRICTION/1\nIfric 2 at rest\n2,0,,2,,%g\n%g,-1,%g,-2,%g\n-3,%g\n", A, c1,
                 c3, c5, fric);
        char *t = deck_at_rest(th, "", "", card);
        ENSURE(t != NULL);
        if (t) check_onset(t, "static_ifric2.rad", ts);
        free(t);
    }
#undef ROOT_P
    /* Ifric 3, Renard: mu(0) = mu_s = C1 = 0.3 (mu_max 0.4 reached at
     * V_cr1 does not act): tilted 0.01 rad below atan(mu_s) it sticks
     * through the ramp, its friction force m g sin(theta) at the end;
     * 0.01 rad above it slides at the first load */
    {
        const char *card = "/FRICTION/1\nIfric 3 at rest\n3,0,,2\n0.3,0.2,0.4,0.1,0.01\n0.1\n";
        const double tb = atan(0.3) - 0.01;
        char *t = deck_at_rest(tb, "", "", card);
        double y[1] = {0}, t0 = -1, t1 = -1;
        ENSURE(t != NULL);
        if (t) {
            ENSURE(run_at_rest(t, "static_renard_below.rad", y, &t0, &t1) == 0);
            /* the stick spring's displacement F_t / K_t along x */
            const double x = g * sin(tb) / 2e4;
            printf("    Renard below: x = %.12g m, closed form %.12g m\n", y[0], x);
            ENSURE_NEAR(y[0], x, 1e-12, 1e-9);
        }
        free(t);
        t = deck_at_rest(atan(0.3) + 0.01, "", "", card);
        ENSURE(t != NULL);
        if (t) {
            ENSURE(run_at_rest(t, "static_renard_above.rad", y, &t0, &t1) == 1);
            ENSURE(t0 == 0.0 && t1 < 1e-6);
        }
        free(t);
    }
    /* TYPE6 fct_IDfv: mu = Fric f_fv(0) = 0.6 * 0.5 = 0.3, Sfric = 1 N,
     * tilted by 0.4 rad: slides at f* = Sfric / (m g (sin(theta) - mu
     * cos(theta))) */
    {
        const double mu = 0.3, sf = 1.0, tt = 0.4, ts = sf / (g * (sin(tt) - mu * cos(tt)));
        char *t = deck_at_rest(tt, "1,0.6", ",,,,,3", "/FUNCT/3\nspeed multiplier\n0,0.5\n1,0.1\n");
        ENSURE(t != NULL);
        if (t) check_onset(t, "static_fct_fv.rad", ts);
        free(t);
        /* a multiplier that is 0 at rest, no Sfric: no static friction */
        t = deck_at_rest(tt, "0,0.6", ",,,,,3", "/FUNCT/3\nspeed multiplier\n0,0\n1,1\n");
        ENSURE(t != NULL);
        if (t)
            TU_EXPECT_TEXT_ERROR(t, "static_fct_fv0.rad", "/INTER/TYPE6/1", "static analysis",
                                 "no static friction at rest");
        free(t);
    }
    /* Renard with mu_s = 0, and Ifric 1 with no coefficient at rest: no
     * static friction at rest; viscous friction (Iform 1): zero at rest */
    {
        char *t = deck_at_rest(0.3, "", "", "/FRICTION/1\nRenard mu_s 0\n3,0,,2\n0,0.2,0.4,0,0.01\n0.1\n");
        ENSURE(t != NULL);
        if (t) TU_EXPECT_TEXT_ERROR(t, "static_renard0.rad", "/INTER/TYPE6/1", "no static friction at rest");
        free(t);
        t = deck_at_rest(0.3, "", "", "/FRICTION/1\nspeed only\n1,0,,2\n0,0.5\n0,0\n");
        ENSURE(t != NULL);
        if (t) TU_EXPECT_TEXT_ERROR(t, "static_ifric1_0.rad", "/INTER/TYPE6/1", "no static friction at rest");
        free(t);
        t = deck_at_rest(0.3, "", "", "/FRICTION/1\nviscous\n0,0,,1\n\n0,0.3\n");
        ENSURE(t != NULL);
        if (t) TU_EXPECT_TEXT_ERROR(t, "static_viscous.rad", "/INTER/TYPE6/1", "viscous friction", "zero at rest");
        free(t);
    }
}

/* The slip load located by its estimate (docs/theory.md 7.8, "A load
 * beyond friction"): deck_at_rest's sphere with Coulomb friction mu = 0.3
 * and Sfric = 1 N, tilted by 0.4 rad, slides at f* = Sfric / (m g
 * (sin(theta) - mu cos(theta))) = 0.901 s of the 1 s ramp; its friction
 * utilisation m g sin(theta) f / (Sfric + mu m g cos(theta) f) is not
 * linear in the load, so the secant estimate is refined. The bracket holds
 * f* within the cut-back's precision (2e-6 Dt_out), found with a few
 * failed solves (the halving of the load substep alone took 27). */
static void test_static_slip_estimate(void)
{
    const double g = 9.81, mu = 0.3, sf = 1.0, tt = 0.4, ts = sf / (g * (sin(tt) - mu * cos(tt)));
    char *t = deck_at_rest(tt, "1,0.3", "", "");
    ENSURE(t != NULL);
    if (!t) return;
    double x = 0, t0 = -1, t1 = -1;
    rc_stats st;
    memset(&st, 0, sizeof st);
    const int r = run_at_rest_stats(t, "static_slip_estimate.rad", &x, &t0, &t1, &st);
    printf("    onset t* = %.9f s, bracket [%.9f, %.9f] s; %ld failed solves, %ld Newton iterations\n", ts, t0, t1,
           (long)st.nonlin_fails, (long)st.nonlin_iters);
    ENSURE(r == 1);
    ENSURE(t0 <= ts && ts <= t1 && t1 - t0 < 2e-6 * 0.05);
    ENSURE(st.nonlin_fails >= 1 && st.nonlin_fails <= 5);
    free(t);
}

/* A solve beyond friction ended at its stall (docs/theory.md 7.8, "A load
 * beyond friction"): the drag of bench/README.md, a 1 kg block pressed on a
 * floor (its height imposed at the static penetration m g / k, F_n = m g),
 * Coulomb mu = 0.4 with the stick spring K_t = 1e6 N/m, pulled along x by
 * a force ramped at 1 N/s (output every 0.5 s): it slides at t* = mu m g /
 * 1 N/s = 3.924 s. Only x is free, and in slip nothing changes the force
 * along it, so Newton could not leave the slide (it ran about 30
 * iterations in each failed solve). The onset is bracketed as before, with
 * the failed solves ended after a few iterations: each converged solve
 * takes one iteration (the stick spring is linear), each failed one at
 * most 4. */
static void test_static_slip_stall(void)
{
    const double g = 9.81, mu = 0.4, z0 = 0.05 - g / 1e6, ts = mu * g;
    char deck[2048];
    snprintf(deck, sizeof deck,
             "/NODE\n1,0,0,%.17g\n"
             "/RBODY/1\nblock\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
             "/SURF/ELLIPS/1\nblock\n0,2,1\n0,0,%.17g\n0.05,0.05,0.05\n"
             "/GRNOD/NODE/1\nblock\n1\n"
             "/BCS/1\ny and rotations held\n010 111,0,1\n"
             "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear k = 1e6 N/m\n0,0\n1,1000000\n"
             "/FUNCT/2\npull ramp\n0,0\n5,1\n"
             "/FUNCT/3\nzero\n0,0\n5,0\n"
             "/IMPVEL/1\nheight held\n3,Z,0,0,1\n\n"
             "/GRAV/1\npull\n2,X,0,0,1,,1,5\n"
             "/INTER/TYPE6/1\nblock - floor\n1,2\n0,%.17g\n\n1,0\n0,0,1000000\n\n"
             "/RUN\n5.0,0.5\n/SOLVER\n3\n",
             z0, z0, mu);
    double x = 0, t0 = -1, t1 = -1;
    rc_stats st;
    memset(&st, 0, sizeof st);
    const int r = run_at_rest_stats(deck, "static_slip_stall.rad", &x, &t0, &t1, &st);
    printf("    onset t* = %.9f s, bracket [%.9f, %.9f] s; %ld equilibria, %ld failed solves, %ld Newton "
           "iterations\n", ts, t0, t1, (long)st.steps, (long)st.nonlin_fails, (long)st.nonlin_iters);
    ENSURE(r == 1);
    ENSURE(t0 <= ts && ts <= t1 && t1 - t0 < 2e-6 * 0.5);
    ENSURE(st.nonlin_fails == 2);
    ENSURE(st.nonlin_iters <= st.steps + 4 * st.nonlin_fails);
}

/* Orthotropic friction at rest (docs/theory.md 7.8, "Orthotropic friction"):
 * deck_at_rest's sphere with a /FRICTION card of two coefficient sets,
 * direction 1 along V = (cos(alpha), sin(alpha), 0) on the floor
 * (/FRIC_ORIENT), the load along x at alpha to it. Each set falls with the
 * pressure, mu_k(p, 0) = c_k (1 - beta p) (Ifric 1: Fric c_k, C1 = -beta
 * c_k, Area 0.01 m^2), so that the sphere sticks while the load's
 * components lie within the ellipse, (F_t cos(alpha) / (mu_1 F_n))^2 +
 * (F_t sin(alpha) / (mu_2 F_n))^2 <= 1, and slides where it leaves it:
 * 1 - beta p* = tan(theta) sqrt(cos^2(alpha) / c_1^2 + sin^2(alpha) /
 * c_2^2), p* = m g cos(theta) f* / Area. */
static void test_static_friction_orthotropic(void)
{
    const double g = 9.81, A = 0.01, c1 = 0.3, c2 = 0.6, beta = 5e-4, th = atan(0.25);
    const double alphas[3] = {0.0, 0.6, 1.0};
    for (int k = 0; k < 3; k++) {
        const double al = alphas[k];
        const double S = sqrt(cos(al) * cos(al) / (c1 * c1) + sin(al) * sin(al) / (c2 * c2));
        const double ps = (1.0 - tan(th) * S) / beta, ts = ps * A / (g * cos(th));
        char card[1200], name[64];
        snprintf(card, sizeof card,
                 "/PART/1\nsphere\n         0         0         0                   0\n         1\n"
                 "/PART/2\nfloor\n         0         0         0                   0\n         0         2\n"
                 "/GRPART/PART/1\nfloors\n2\n"
                 "/FRICTION/1\northotropic, falling with the pressure\n1,0,,2,,%g\n\n0,0.9\n"
                 "0,1,1,0,,1\n%.17g\n0,%g\n%.17g\n0,%g\n"
                 "/FRIC_ORIENT/1\ndirection 1\n1,0\n%.17g,%.17g,0,0,0\n",
                 A, -beta * c1, c1, -beta * c2, c2, cos(al), sin(al));
        snprintf(name, sizeof name, "static_ortho_%d.rad", k);
        char *t = deck_at_rest(th, "", "", card);
        ENSURE(t != NULL);
        if (t) check_onset(t, name, ts);
        free(t);
    }
}

/* A preload with a friction filter (Ifiltr 3, 4 Hz): the sphere on a floor
 * under gravity tilted by atan(0.25) < atan(mu = 0.3), run dynamically
 * (CVODE) for 0.2 s from the static equilibrium: the filter states start
 * at the limit (the filter at rest), so it stays at rest; without them the
 * filtered limit would rise from zero and the sphere slide. */
static void test_static_preload_filter(void)
{
    const double g = 9.81, th = atan(0.25);
    char t[2048];
    snprintf(t, sizeof t,
             "/NODE\n1,0,0,0.05\n"
             "/RBODY/1\nsphere\n1,,,,1.0\n0.001,0.001,0.001\n0,0,0\n"
             "/SURF/ELLIPS/1\nsphere\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n"
             "/GRNOD/NODE/1\ngroup\n1\n"
             "/BCS/1\nrotations held\n000 111,0,1\n"
             "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
             "/FUNCT/1\nlinear k = 1e5 N/m\n0,0\n1,100000\n"
             "/GRAV/1\ngravity x\n0,X,0,0,0,,1,%.17g\n"
             "/GRAV/2\ngravity z\n0,Z,0,0,0,,1,%.17g\n"
             "/INTER/TYPE6/1\nsphere - floor\n1,2\n\n\n1,0\n0,0,20000\n\n"
             "/FRICTION/1\nCoulomb, filtered\n0,3,4,2\n\n0,0.3\n"
             "/RUN\n0.2,0.05\n/SOLVER\n1,5,100000,1e-8,0,0,1\n",
             g * sin(th), -g * cos(th));
    rc_error e;
    rc_model *m = tu_compile_text(t, "static_preload_filter.rad", &e);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return;
    double *y = calloc((size_t)m->ny + 1, sizeof(double)), *y0 = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(y && y0);
    if (y && y0) {
        rc_initial_state(m, y0);
        rc_run_options o = {.y_end = y};
        rc_stats st;
        const rc_status r = rc_run(m, &o, &st, &e);
        if (r) fprintf(stderr, "  %s\n", e.msg);
        ENSURE(r == RC_OK && st.preloaded == 1);
        const int a = m->body_yadr[0];
        const double v = sqrt(y[a + 7] * y[a + 7] + y[a + 8] * y[a + 8] + y[a + 9] * y[a + 9]);
        /* the stick spring's slide m g sin(theta) / K_t, taken in the preload */
        const double dx = y[a] - y0[a], x_el = g * sin(th) / 2e4;
        printf("    preloaded with a filter: |v| %.3g m/s at 0.2 s, x %.12g m (m g sin(theta) / K_t %.12g m)\n", v,
               dx, x_el);
        ENSURE(v < 1e-9);
        ENSURE_NEAR(dx, x_el, 1e-12, 1e-8);
    }
    free(y);
    free(y0);
    rc_model_free(m);
}

void suite_static(void);
void suite_static(void)
{
    RUN_TEST(test_static_stiffness_fd);
    RUN_TEST(test_static_stiffness_friction);
    RUN_TEST(test_static_stiffness_exact_stick);
    RUN_TEST(test_static_stiffness_exact_stick_hysteresis);
    RUN_TEST(test_static_stiffness_hysteresis);
    RUN_TEST(test_static_stiffness_boxes);
    RUN_TEST(test_static_stiffness_hysteresis_box);
    RUN_TEST(test_static_stiffness_point_friction);
    RUN_TEST(test_static_stiffness_joints);
    RUN_TEST(test_static_impvel);
    RUN_TEST(test_static_inacti5);
    RUN_TEST(test_static_pendulum);
    RUN_TEST(test_static_prismatic_free);
    RUN_TEST(test_static_scope);
    RUN_TEST(test_static_snap_through);
    RUN_TEST(test_static_friction_at_rest);
    RUN_TEST(test_static_friction_orthotropic);
    RUN_TEST(test_static_slip_estimate);
    RUN_TEST(test_static_slip_stall);
    RUN_TEST(test_static_preload_filter);
}
