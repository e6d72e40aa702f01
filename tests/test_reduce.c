/* The states CVODE carries (solver/cvode.c, model.h rc_constant_states):
 * which states are constant, that their rates are exactly 0 wherever the
 * engine evaluates them, that a state an event may write stays in, and
 * runs with the constant states left out of CVODE's vector against runs
 * with every state: the same events and final states within the
 * tolerance that the different error norm explains (below). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/model.h"
#include "solver/integrator.h"
#include "solver/solver.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"
#include "engine/events/events.h"

/* Three bodies on a floor plane (z = 0), gravity -z:
 *  1 a sphere whose translations are held (/BCS 111 000), spinning freely
 *    at omega0 = (3, -2, 5) rad/s with an isotropic inertia: no torque, so
 *    omega stays omega0 and q(t) = (cos(|w| t/2), sin(|w| t/2) w/|w|);
 *  2 a sphere with x and the rotations held, given v = (1, 0.5, -0.3) m/s
 *    (the held x component is set to 0 by the compiler), bouncing on the
 *    floor (damped TYPE6): impacts;
 *  3 a sphere with y held (/BCS 010 000), rotations free, sliding along x
 *    on the floor with Coulomb friction (Fric 0.3): it rolls up, its
 *    quaternion and omega change, its y and v_y are constant. */
static const char *DECK =
    "/BEGIN\nreduce\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nload\n                   0                   0\n                   1              100000\n"
    "/NODE\n"
    "         1                   0                   0                0.05\n"
    "         2                 0.3                   0                 0.2\n"
    "         3                -0.3                   0                0.05\n"
    "/RBODY/1\nspinner\n         1                                                 1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/RBODY/2\nbouncer\n         2                                               0.5\n"
    "              0.0005              0.0008              0.0011\n"
    "                   0                   0                   0\n"
    "/RBODY/3\nslider\n         3                                                 1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/GRNOD/NODE/1\ng1\n         1\n/GRNOD/NODE/2\ng2\n         2\n/GRNOD/NODE/3\ng3\n         3\n"
    "/INIVEL/ROT/1\nspin\n                   3                  -2                   5         1         0\n"
    "/INIVEL/TRA/2\nthrow\n                   1                 0.5                -0.3         2         0\n"
    "/INIVEL/TRA/3\nslide\n                   1                   0                   0         3         0\n"
    "/SURF/ELLIPS/1\ns1\n         0         2         1\n"
    "                   0                   0                0.05\n"
    "                0.05                0.05                0.05\n"
    "/SURF/ELLIPS/2\ns2\n         0         2         2\n"
    "                 0.3                   0                 0.2\n"
    "                0.04                0.04                0.04\n"
    "/SURF/ELLIPS/3\ns3\n         0         2         3\n"
    "                -0.3                   0                0.05\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/4\nfloor\n                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRAV/1\ngravity\n         0         Z         0         0         0                             1"
    "               -9.81\n"
    "/BCS/1\ntranslations held\n   111 000         0         1\n"
    "/BCS/2\nx and rotations held\n   100 111         0         2\n"
    "/BCS/3\ny held\n   010 000         0         3\n"
    "/INTER/TYPE6/1\nbounce\n         2         4\n"
    "                                                           0\n"
    "                   0         0         0         0         0\n"
    "         1         0                                                 0\n"
    "         0\n"
    "                  50         0         0\n"
    "/INTER/TYPE6/2\nslide\n         3         4\n"
    "                                     0.3                   0\n"
    "                   0         0         0         0         0\n"
    "         1         0                                                 0\n"
    "         0\n"
    "                  90         0         0\n"
    "/RUN\n                 0.5                0.05\n"
    "/END\n";

/* Every constant state: its rate exactly 0 at the initial state and at a
 * perturbed one (the rhs sets the held rows after every force; a position
 * or quaternion moves only through a velocity that is constant at 0). */
static void rates_zero(const rc_model *m, const char *what)
{
    const int ny = m->ny;
    double *y = calloc((size_t)ny + 1, sizeof(double)), *f = calloc((size_t)ny + 1, sizeof(double));
    char *cst = calloc((size_t)ny + 1, 1);
    rc_data *d = rc_data_new(m);
    ENSURE(y && f && cst && d);
    if (!y || !f || !cst || !d) goto out;
    rc_initial_state(m, y);
    rc_modes_init(m, d, 0.0, y);
    const int n = rc_constant_states(m, y, NULL, cst);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) /* move the kept states: the rates of the constant ones stay 0 */
            for (int k = 0; k < ny; k++)
                if (!cst[k]) y[k] += 1e-4 * (1 + k % 7);
        ENSURE(rc_assemble_rhs(m, d, 0.01, y, f) == 0);
        int bad = 0;
        for (int k = 0; k < ny; k++) bad += cst[k] && f[k] != 0.0;
        ENSURE(bad == 0);
    }
    printf("    %s: %d of %d states constant\n", what, n, ny);
out:
    free(y);
    free(f);
    free(cst);
    rc_data_free(d);
}

static void test_reduce_constant_states(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(DECK, "reduce.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    const int ny = m->ny;
    double *y = calloc((size_t)ny + 1, sizeof(double));
    char *cst = calloc((size_t)ny + 1, 1), *w = calloc((size_t)ny + 1, 1);
    ENSURE(y && cst && w);
    if (!y || !cst || !w) goto out;
    rc_initial_state(m, y);
    const int a1 = m->body_yadr[0], a2 = m->body_yadr[1], a3 = m->body_yadr[2];
    /* the held x velocity of body 2 was set to 0 by the compiler */
    ENSURE(y[a2 + 7] == 0.0 && y[a2 + 8] == 0.5);
    const int n = rc_constant_states(m, y, NULL, cst);
    /* body 1: x (3) and v (3); body 2: x, v_x, q (4), omega (3); body 3: y, v_y */
    ENSURE(n == 6 + 9 + 2);
    for (int k = 0; k < 13; k++) {
        ENSURE(cst[a1 + k] == (k < 3 || (k >= 7 && k < 10)));
        ENSURE(cst[a2 + k] == (k == 0 || k == 7 || (k >= 3 && k < 7) || k >= 10));
        ENSURE(cst[a3 + k] == (k == 1 || k == 8));
    }
    for (int k = 3 * 13; k < ny; k++) ENSURE(cst[k] == 0); /* interface states */
    /* a held velocity that starts non-zero: the velocity is constant, its
     * position is not */
    y[a2 + 7] = 0.25;
    ENSURE(rc_constant_states(m, y, NULL, cst) == n - 1);
    ENSURE(cst[a2 + 7] && !cst[a2 + 0]);
    /* held rotations with a non-zero omega: omega constant, q not */
    y[a2 + 7] = 0.0;
    y[a2 + 11] = 1.0;
    ENSURE(rc_constant_states(m, y, NULL, cst) == n - 4);
    ENSURE(cst[a2 + 10] && cst[a2 + 11] && cst[a2 + 12] && !cst[a2 + 3] && !cst[a2 + 6]);
    y[a2 + 11] = 0.0;
    /* a state an event may write stays in, and so does what depends on it:
     * v_x of body 2 (then x too), one omega of body 2 (then all of omega
     * and q), the x position of body 1 alone */
    w[a2 + 7] = 1;
    ENSURE(rc_constant_states(m, y, w, cst) == n - 2);
    ENSURE(!cst[a2 + 7] && !cst[a2 + 0] && cst[a2 + 3]);
    memset(w, 0, (size_t)ny);
    w[a2 + 11] = 1;
    ENSURE(rc_constant_states(m, y, w, cst) == n - 7);
    for (int k = 3; k < 13; k++) ENSURE(!cst[a2 + k] || k == 7);
    memset(w, 0, (size_t)ny);
    w[a1 + 0] = 1;
    ENSURE(rc_constant_states(m, y, w, cst) == n - 1);
    ENSURE(!cst[a1 + 0] && cst[a1 + 7]);
    rates_zero(m, "three bodies");
out:
    free(y);
    free(cst);
    free(w);
    rc_model_free(m);
}

/* The rates of the constant states are exactly 0 on the validation decks
 * with held degrees of freedom. */
static void test_reduce_rates_zero_decks(void)
{
    const char *decks[] = {"validation/frc_incline/case.rad", "validation/stick_belt/case.rad",
                           "validation/pw_roller_traction/case1.rad", "validation/seg_sphere_incline/case.rad",
                           "validation/fric_slide_stop/case.rad", "validation/frc_iform_compare/case.rad"};
    for (size_t q = 0; q < sizeof decks / sizeof decks[0]; q++) {
        rc_model *m = NULL;
        rc_error e;
        ENSURE(tu_load_compile(decks[q], &m, &e) == RC_OK);
        if (!m) continue;
        rates_zero(m, decks[q]);
        rc_model_free(m);
    }
}

/* The Jacobian with the constant states' columns skipped (rc_data
 * jac_skip, set by the CVODE backend): every entry in a kept row and a
 * kept column bit for bit the whole Jacobian's (complex-step columns are
 * independent), the skipped columns 0; the same after an interface's
 * block is refreshed at an event (rc_jac_refresh_inter). */
static void test_reduce_jacobian_skip(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(DECK, "reduce.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    const int ny = m->ny;
    double *y = calloc((size_t)ny + 1, sizeof(double));
    double *ja = calloc((size_t)m->nnz + 1, sizeof(double)), *jb = calloc((size_t)m->nnz + 1, sizeof(double));
    char *cst = calloc((size_t)ny + 1, 1);
    rc_data *d = rc_data_new(m);
    ENSURE(y && ja && jb && cst && d);
    if (!y || !ja || !jb || !cst || !d) goto out;
    rc_initial_state(m, y);
    const int n = rc_constant_states(m, y, NULL, cst);
    ENSURE(n == 17);
    /* both contacts closed, bodies moving and turning */
    const int a2 = m->body_yadr[1], a3 = m->body_yadr[2];
    y[a2 + 2] = 0.0395;
    y[a2 + 9] = -0.4;
    y[a3 + 2] = 0.0497;
    y[a3 + 4] = 0.1;
    y[a3 + 11] = 2.0;
    rc_modes_init(m, d, 0.0, y);
    ENSURE(d->inter_mode[0] == RC_MODE_CLOSED && d->inter_mode[1] == RC_MODE_CLOSED);
    /* the whole Jacobian against central differences (held rotations at
     * rest take a short cut in the body kernel: q' = 0, no gyroscopic term) */
    {
        int bad = 0, outside = 0;
        const double err = tu_jac_fd_error(m, d, 0.01, y, 0, &bad, &outside);
        printf("    Jacobian against central differences: max scaled difference %.2g\n", err);
        ENSURE(bad == 0 && outside == 0);
    }
    for (int pass = 0; pass < 2; pass++) {
        int kept = 0, nonzero = 0;
        int differ = tu_jac_skip_compare(m, d, 0.01, y, cst, ja, jb, &kept, &nonzero);
        ENSURE(differ == 0 && nonzero > 20);
        printf("    pass %d: %d kept entries (%d non-zero) identical, skipped columns 0\n", pass, kept, nonzero);
        /* refresh the slider's interface in another mode (released) after
         * a whole assembly, each way (the block cache is the last assembly's) */
        for (int v = 0; v < 2; v++) {
            d->jac_skip = v ? cst : NULL;
            ENSURE(rc_assemble_jac(m, d, 0.01, y, v ? jb : ja) == 0);
            d->inter_mode[1] = RC_MODE_RELEASED;
            ENSURE(rc_jac_refresh_inter(m, d, 1, y, v ? jb : ja) == 0);
            d->inter_mode[1] = RC_MODE_CLOSED;
        }
        differ = 0;
        for (int c = 0; c < ny; c++)
            for (int64_t k = m->jac_colptr[c]; k < m->jac_colptr[c + 1]; k++)
                if (!cst[m->jac_rowind[k]] && !cst[c]) differ += memcmp(&ja[k], &jb[k], sizeof(double)) != 0;
        ENSURE(differ == 0);
        /* the second pass at another state of the slider */
        y[a3 + 11] += 1.0;
    }
    d->jac_skip = NULL;
out:
    free(y);
    free(ja);
    free(jb);
    free(cst);
    rc_data_free(d);
    rc_model_free(m);
}

/* Largest |a - b| over the states of a kind, against scale. */
static double maxdiff(const double *a, const double *b, const int *idx, int n)
{
    double d = 0;
    for (int k = 0; k < n; k++) d = fmax(d, fabs(a[idx[k]] - b[idx[k]]));
    return d;
}

/* Run m on CVODE with the constant states left out and with every state:
 * the same events (kind, element; times within dt_ev) and final states
 * within the tolerances (positions tol_x [m], velocities tol_v [m/s],
 * quaternions and omega tol_r [-, rad/s]); the constant states equal to
 * their initial values in both. Returns the reduced run's final state
 * (malloc'd) for the caller's checks. */
static double *same_runs(const rc_model *m, const char *what, double dt_ev, double tol_x, double tol_v, double tol_r)
{
    const int ny = m->ny;
    double *ya = calloc((size_t)ny + 1, sizeof(double)), *yb = calloc((size_t)ny + 1, sizeof(double));
    double *y0 = calloc((size_t)ny + 1, sizeof(double));
    char *cst = calloc((size_t)ny + 1, 1);
    tu_evlog *la = calloc(1, sizeof *la), *lb = calloc(1, sizeof *lb);
    int *ix = malloc(((size_t)ny + 1) * sizeof(int)), *iv = malloc(((size_t)ny + 1) * sizeof(int));
    int *ir = malloc(((size_t)ny + 1) * sizeof(int));
    ENSURE(ya && yb && y0 && cst && la && lb && ix && iv && ir);
    if (!ya || !yb || !y0 || !cst || !la || !lb || !ix || !iv || !ir) goto out;
    rc_initial_state(m, y0);
    const int nc = rc_constant_states(m, y0, NULL, cst);
    rc_error e;
    rc_stats sa, sb;
    rc_run_options oa = {.y_end = ya, .on_event = tu_evlog_event, .user = la};
    rc_run_options ob = {.y_end = yb, .on_event = tu_evlog_event, .user = lb};
    rc_cvode_set_reduce(1);
    ENSURE(rc_solver_cvode.run(m, &oa, NULL, NULL, &sa, &e) == RC_OK);
    rc_cvode_set_reduce(0);
    ENSURE(rc_solver_cvode.run(m, &ob, NULL, NULL, &sb, &e) == RC_OK);
    rc_cvode_set_reduce(1);
    ENSURE(nc > 0);
    ENSURE(la->n == lb->n && la->n <= TU_MAXEV);
    double dt = 0;
    for (int k = 0; k < la->n && k < lb->n && k < TU_MAXEV; k++) {
        ENSURE(strcmp(la->kind[k], lb->kind[k]) == 0 && strcmp(la->elem[k], lb->elem[k]) == 0);
        dt = fmax(dt, fabs(la->t[k] - lb->t[k]));
    }
    ENSURE(dt <= dt_ev);
    int nx = 0, nv = 0, nr = 0;
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        if (a < 0) continue;
        for (int k = 0; k < 3; k++) ix[nx++] = a + k, iv[nv++] = a + 7 + k, ir[nr++] = a + 10 + k;
        for (int k = 3; k < 7; k++) ir[nr++] = a + k;
    }
    const double dx = maxdiff(ya, yb, ix, nx), dv = maxdiff(ya, yb, iv, nv), dr = maxdiff(ya, yb, ir, nr);
    ENSURE(dx <= tol_x && dv <= tol_v && dr <= tol_r);
    int moved = 0;
    for (int k = 0; k < ny; k++) moved += cst[k] && (ya[k] != y0[k] || yb[k] != y0[k]);
    ENSURE(moved == 0);
    printf("    %s: %d of %d states constant; %d events, %ld / %ld steps (reduced / all states); "
           "largest differences: event times %.2g s, x %.2g m, v %.2g m/s, q and omega %.2g\n",
           what, nc, ny, la->n, sa.steps, sb.steps, dt, dx, dv, dr);
out:
    free(yb);
    free(y0);
    free(cst);
    free(la);
    free(lb);
    free(ix);
    free(iv);
    free(ir);
    return ya;
}

/* The tolerances of the comparisons. Both runs are within CVODE's error
 * control of the same solution, with the same error weights per state;
 * the reduced run's WRMS norm divides by fewer components (sqrt(ny / nr)
 * tighter: 1.7 on the three bodies, 1.9 on the locked column), so its
 * steps differ and the two runs differ by about what the local error
 * tests admit (Rtol 1e-6, positions weighed against the contact
 * penetration scales, 5e-5 m on the bodies' floor contacts, 1e-6 m in
 * the column). Measured: three bodies 2.5e-10 s, 3e-10 m, 7.4e-9 m/s,
 * 1.4e-9; column 4.9e-11 s, 2e-13 m, 6.5e-11 m/s. The bounds are about
 * 30x those and 1e-4 of the penetration scales: a constant state that
 * moved, a lost event or a state scattered to the wrong place fail them. */
static void test_reduce_runs(void)
{
    rc_error e;
    rc_model *m = tu_compile_text(DECK, "reduce.rad", &e);
    ENSURE(m != NULL);
    if (m) {
        double *y = same_runs(m, "three bodies", 1e-8, 1e-8, 3e-7, 3e-8);
        if (y) {
            /* the spinner against the closed form of torque-free rotation
             * with an isotropic inertia */
            const double *s = y + m->body_yadr[0], w0[3] = {3, -2, 5}, T = m->tend;
            const double wn = sqrt(38.0), c = cos(0.5 * wn * T), sn = sin(0.5 * wn * T);
            ENSURE_NEAR(s[3], c, 0, 1e-5);
            for (int k = 0; k < 3; k++) ENSURE_NEAR(s[4 + k], sn * w0[k] / wn, 0, 1e-5);
            for (int k = 0; k < 3; k++) ENSURE_NEAR(s[10 + k], w0[k], 0, 1e-9);
            ENSURE(s[0] == 0.0 && s[1] == 0.0 && s[2] == 0.05);
            /* the bouncer kept its x and stays unrotated; the slider its y */
            const double *b2 = y + m->body_yadr[1], *b3 = y + m->body_yadr[2];
            ENSURE(b2[0] == 0.3 && b2[7] == 0.0 && b2[3] == 1.0 && b2[10] == 0.0);
            ENSURE(b3[1] == 0.0 && b3[8] == 0.0);
            ENSURE(fabs(b2[1] - 0.25) < 1e-9); /* y = 0.5 m/s x 0.5 s: no friction on the bouncer */
            ENSURE(b3[0] > -0.3 + 0.1 && fabs(b3[11]) > 1.0); /* the slider moved and rolls */
        }
        free(y);
        rc_model_free(m);
    }
    char *t = tu_column_deck(5, TU_COL_LOCK);
    ENSURE(t != NULL);
    if (!t) return;
    m = tu_compile_text(t, "column.rad", &e);
    free(t);
    ENSURE(m != NULL);
    if (!m) return;
    free(same_runs(m, "locked column of 5", 2e-9, 1e-11, 3e-9, 0.0));
    rc_model_free(m);
}

/* A body held in all six directions by two cards (not fixed: it keeps
 * its states) and nothing else: every state constant; CVODE is then given
 * them all (a vector of none cannot be integrated) and the run ends with
 * the state unchanged. */
static void test_reduce_all_constant(void)
{
    const char *deck = "/BEGIN\nheld\n      2022         0\n"
                       "                  kg                   m                   s\n"
                       "                  kg                   m                   s\n"
                       "/NODE\n         1                   0                   0                   1\n"
                       "/RBODY/1\nbody\n         1                                                 1\n"
                       "                 0.1                 0.1                 0.1\n"
                       "                   0                   0                   0\n"
                       "/GRNOD/NODE/1\ng\n         1\n"
                       "/GRAV/1\ngravity\n         0         Z         0         0         0"
                       "                             1               -9.81\n"
                       "/BCS/1\ntranslations\n   111 000         0         1\n"
                       "/BCS/2\nrotations\n   000 111         0         1\n"
                       "/RUN\n                 0.1                0.05\n/END\n";
    rc_error e;
    rc_model *m = tu_compile_text(deck, "held.rad", &e);
    ENSURE(m != NULL);
    if (!m) return;
    double y0[RC_NB], y[RC_NB];
    char cst[RC_NB];
    ENSURE(m->ny == RC_NB);
    rc_initial_state(m, y0);
    ENSURE(rc_constant_states(m, y0, NULL, cst) == RC_NB);
    rc_run_options o = {.y_end = y};
    rc_stats st;
    ENSURE(rc_solver_cvode.run(m, &o, NULL, NULL, &st, &e) == RC_OK);
    rc_state_to_deck(m, y0); /* y_end is in the deck's coordinates */
    ENSURE(memcmp(y, y0, sizeof y) == 0);
    rc_model_free(m);
}

void suite_reduce(void);
void suite_reduce(void)
{
    RUN_TEST(test_reduce_constant_states);
    RUN_TEST(test_reduce_rates_zero_decks);
    RUN_TEST(test_reduce_jacobian_skip);
    RUN_TEST(test_reduce_runs);
    RUN_TEST(test_reduce_all_constant);
}
