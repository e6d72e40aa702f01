/* Rotations at rest left out of CVODE's state (model.h rc_moment_free_bodies,
 * rc_constant_states): a body whose angular velocity starts at exactly 0
 * and on which no moment about its centre of mass can act keeps omega = 0
 * and its quaternion. Checked here:
 *  - the rotation rows of the full right-hand side are exactly 0 for the
 *    bodies the rule accepts, at random states in random interface modes,
 *    on the free settling column and on every validation deck; the same
 *    check run on the column with friction (which the rule refuses) finds
 *    non-zero rows, so it would catch a friction interface let through;
 *  - decks that must keep their rotations in (friction, a sphere off the
 *    centre of mass, a coupling, an initial spin) do;
 *  - runs with and without the reduction give the same events, final
 *    states and contact forces within the error control's tolerance. */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
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

/* Variants of the free settling column (bench.py column_deck, not locked):
 * n spheres of radius 0.01 m stacked on a floor, gaps 1e-4 m, gravity -z,
 * TYPE6 linear contacts with damping. */
static rc_model *column_model(int n, int flags)
{
    char *t = tu_column_deck(n, flags);
    ENSURE(t != NULL);
    if (!t) return NULL;
    rc_error e;
    rc_model *m = tu_compile_text(t, "tf_column.rad", &e);
    free(t);
    if (!m) fprintf(stderr, "  %s\n", e.msg);
    ENSURE(m != NULL);
    return m;
}

/* xorshift64*: reproducible uniform numbers in [0, 1) */
static double rnd(uint64_t *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ull) >> 11) * 0x1.0p-53;
}

/* The rotation rows (q', omega') of the bodies marked in body[nbody] at
 * `samples` random states of m: positions moved by up to +-5 mm from the
 * initial ones (contacts penetrating and open), velocities up to 1 m/s,
 * random unit quaternions, omega 0 on the marked bodies and random on the
 * others, the interfaces' own states random, their modes (mode, branch,
 * tracking, stick/slip, the contact points' stick/slip) random. Returns
 * the largest |rate| found; *forced counts the samples in which some
 * marked body received a contact force (its acceleration differs from
 * gravity's), *nans the samples whose right-hand side was not finite. */
static double rotation_rows(const rc_model *m, const char *body, int samples, uint64_t seed, int *forced, int *nans)
{
    const int ny = m->ny;
    double *y0 = calloc((size_t)ny + 1, sizeof(double)), *y = calloc((size_t)ny + 1, sizeof(double));
    double *f = calloc((size_t)ny + 1, sizeof(double));
    rc_data *d = rc_data_new(m);
    double worst = 0.0;
    *forced = *nans = 0;
    ENSURE(y0 && y && f && d);
    if (!y0 || !y || !f || !d) goto out;
    rc_initial_state(m, y0);
    rc_modes_init(m, d, 0.0, y0);
    uint64_t s = seed | 1;
    for (int q = 0; q < samples; q++) {
        memcpy(y, y0, (size_t)ny * sizeof(double));
        for (int b = 0; b < m->nbody; b++) {
            const int a = m->body_yadr[b];
            if (a < 0) continue;
            for (int k = 0; k < 3; k++) {
                y[a + k] += 0.01 * (rnd(&s) - 0.5);
                y[a + 7 + k] = 2.0 * (rnd(&s) - 0.5);
                y[a + 10 + k] = body[b] ? 0.0 : 20.0 * (rnd(&s) - 0.5);
            }
            double qn = 0.0;
            for (int k = 3; k < 7; k++) {
                y[a + k] = rnd(&s) - 0.5;
                qn += y[a + k] * y[a + k];
            }
            for (int k = 3; k < 7; k++) y[a + k] /= sqrt(qn);
        }
        for (int i = 0; i < m->ninter; i++) {
            const int ea = m->inter_eadr[i], ns = m->inter_ns[i] + m->inter_pst[i] * m->inter_npt[i];
            for (int k = 0; k < ns; k++) y[ea + k] = rnd(&s) - 0.5;
            if (m->inter_oidx[i] >= 0) y[ea + m->inter_oidx[i]] = 1e-3 * rnd(&s);
            d->inter_mode[i] = (int)(4 * rnd(&s));
            d->inter_branch[i] = m->inter_iform[i] ? (int)(3 * rnd(&s)) : RC_BR_LOAD;
            d->inter_track[i] = m->inter_oidx[i] >= 0 && rnd(&s) < 0.3;
            d->inter_slip[i] = rnd(&s) < 0.5;
            for (int j = 0; j < m->inter_npt[i]; j++) d->pt_slip[m->inter_pbase[i] + j] = rnd(&s) < 0.5;
        }
        if (rc_assemble_rhs(m, d, 0.01, y, f) != 0) {
            (*nans)++;
            continue;
        }
        int hit = 0;
        for (int b = 0; b < m->nbody; b++) {
            const int a = m->body_yadr[b];
            if (a < 0 || !body[b]) continue;
            for (int k = 3; k < 7; k++) worst = fmax(worst, fabs(f[a + k]));
            for (int k = 10; k < 13; k++) worst = fmax(worst, fabs(f[a + k]));
            double g[3];
            rc_gravity(m, b, 0.01, g);
            for (int k = 0; k < 3; k++) hit |= f[a + 7 + k] != g[k] && !m->row_held[a + 7 + k];
        }
        *forced += hit;
    }
out:
    free(y0);
    free(y);
    free(f);
    rc_data_free(d);
    return worst;
}

/* Every body of the free column is moment-free: its 7 rotation states are
 * constant; their rates are exactly 0 at random states and modes. The
 * same column with friction: no body accepted, and the check of the rows,
 * run as if all were accepted, finds moments (it would fail). */
static void test_torquefree_column_rows(void)
{
    const int flagset[2] = {0, TU_COL_TILT};
    for (int v = 0; v < 2; v++) {
        rc_model *m = column_model(5, flagset[v]);
        if (!m) return;
        char mf[5], *cst = calloc((size_t)m->ny + 1, 1);
        double *y0 = calloc((size_t)m->ny + 1, sizeof(double));
        ENSURE(cst && y0);
        if (cst && y0) {
            rc_initial_state(m, y0);
            rc_moment_free_bodies(m, mf);
            const int n = rc_constant_states(m, y0, NULL, cst);
            ENSURE(n == 5 * 7);
            for (int b = 0; b < 5; b++) {
                const int a = m->body_yadr[b];
                ENSURE(mf[b] == 1);
                for (int k = 0; k < RC_NB; k++) ENSURE(cst[a + k] == ((k >= 3 && k < 7) || k >= 10));
            }
            int forced, nans;
            const double w = rotation_rows(m, mf, 2000, 0x9e3779b97f4a7c15ull + (uint64_t)v, &forced, &nans);
            printf("    free column%s: %d of %d states constant; rotation rows max %.1e over 2000 random states "
                   "(%d with contact forces, %d not finite)\n",
                   v ? " (staggered)" : "", n, m->ny, w, forced, nans);
            ENSURE(w == 0.0 && forced > 500 && nans == 0);
        }
        free(cst);
        free(y0);
        rc_model_free(m);
    }
    /* the negative case: friction */
    rc_model *m = column_model(5, TU_COL_FRIC);
    if (!m) return;
    char mf[5], all[5] = {1, 1, 1, 1, 1}, *cst = calloc((size_t)m->ny + 1, 1);
    double *y0 = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(cst && y0);
    if (cst && y0) {
        rc_initial_state(m, y0);
        rc_moment_free_bodies(m, mf);
        for (int b = 0; b < 5; b++) ENSURE(mf[b] == 0);
        ENSURE(rc_constant_states(m, y0, NULL, cst) == 0);
        int forced, nans;
        const double w = rotation_rows(m, all, 200, 12345, &forced, &nans);
        printf("    column with friction: no body accepted; the rows as if accepted: max %.2g rad/s^2\n", w);
        ENSURE(w > 1.0);
    }
    free(cst);
    free(y0);
    rc_model_free(m);
}

/* Decks that must keep a body's rotations: friction on its contacts (above),
 * a sphere off its centre of mass, a coupling, an initial spin: that body
 * only (sphere 2); the others of the column are still accepted. */
static void test_torquefree_refused(void)
{
    const int flags[3] = {TU_COL_OFF, TU_COL_SPRING, TU_COL_SPIN};
    const char *what[3] = {"off-centre sphere", "spring", "initial spin"};
    for (int v = 0; v < 3; v++) {
        rc_model *m = column_model(5, flags[v]);
        if (!m) continue;
        char mf[5], *cst = calloc((size_t)m->ny + 1, 1);
        double *y0 = calloc((size_t)m->ny + 1, sizeof(double));
        ENSURE(cst && y0);
        if (cst && y0) {
            rc_initial_state(m, y0);
            rc_moment_free_bodies(m, mf);
            const int n = rc_constant_states(m, y0, NULL, cst);
            /* the spin: the body is moment-free, but omega is not 0 */
            for (int b = 0; b < 5; b++) ENSURE(mf[b] == (b != 1 || flags[v] == TU_COL_SPIN));
            ENSURE(n == 4 * 7);
            const int a = m->body_yadr[1];
            for (int k = 3; k < RC_NB; k++) ENSURE(cst[a + k] == 0);
            printf("    %s: sphere 2 keeps its rotations, %d states constant\n", what[v], n);
        }
        free(cst);
        free(y0);
        rc_model_free(m);
    }
    /* a state an event may write stays in, with what depends on it */
    rc_model *m = column_model(3, 0);
    if (!m) return;
    char *cst = calloc((size_t)m->ny + 1, 1), *w = calloc((size_t)m->ny + 1, 1);
    double *y0 = calloc((size_t)m->ny + 1, sizeof(double));
    ENSURE(cst && w && y0);
    if (cst && w && y0) {
        rc_initial_state(m, y0);
        const int a = m->body_yadr[0];
        w[a + 11] = 1;
        ENSURE(rc_constant_states(m, y0, w, cst) == 2 * 7);
        for (int k = 3; k < RC_NB; k++) ENSURE(cst[a + k] == 0);
        memset(w, 0, (size_t)m->ny);
        w[a + 5] = 1;
        ENSURE(rc_constant_states(m, y0, w, cst) == 2 * 7);
        ENSURE(cst[a + 3] == 0 && cst[a + 10] == 0);
    }
    free(cst);
    free(w);
    free(y0);
    rc_model_free(m);
}

/* On every validation deck: the bodies the rule accepts have rotation rows
 * exactly 0 at random states and modes (the rule decided from the compiled
 * model, the rows from the kernels). Counts the decks and bodies covered. */
static void test_torquefree_validation_decks(void)
{
    DIR *dir = opendir("validation");
    ENSURE(dir != NULL);
    if (!dir) return;
    struct dirent *de;
    int decks = 0, with = 0, bodies = 0, pairs[16] = {0};
    while ((de = readdir(dir))) {
        if (de->d_name[0] == '.') continue;
        char sub[512];
        snprintf(sub, sizeof sub, "validation/%s", de->d_name);
        DIR *dd = opendir(sub);
        if (!dd) continue;
        struct dirent *fe;
        while ((fe = readdir(dd))) {
            const size_t l = strlen(fe->d_name);
            if (l < 5 || strcmp(fe->d_name + l - 4, ".rad") != 0) continue;
            char path[1024];
            snprintf(path, sizeof path, "%s/%s", sub, fe->d_name);
            rc_model *m = NULL;
            rc_error e;
            if (tu_load_compile(path, &m, &e) != RC_OK || !m) continue; /* decks that are meant to fail */
            decks++;
            char *mf = calloc((size_t)m->nbody + 1, 1);
            ENSURE(mf != NULL);
            if (mf) {
                rc_moment_free_bodies(m, mf);
                int nb = 0;
                for (int b = 0; b < m->nbody; b++) nb += mf[b];
                if (nb > 0) {
                    with++;
                    bodies += nb;
                    for (int i = 0; i < m->ninter; i++)
                        if ((m->inter_ba[i] >= 0 && mf[m->inter_ba[i]]) || (m->inter_bb[i] >= 0 && mf[m->inter_bb[i]]))
                            pairs[m->inter_pair[i] & 15]++;
                    int forced, nans;
                    const double w = rotation_rows(m, mf, 200, 777, &forced, &nans);
                    if (w != 0.0) printf("    %s: rotation rows %.3g\n", path, w);
                    ENSURE(w == 0.0);
                }
            }
            free(mf);
            rc_model_free(m);
        }
        closedir(dd);
    }
    closedir(dir);
    printf("    %d validation decks, %d with moment-free bodies (%d bodies); their interfaces: sphere-plane %d, "
           "sphere-sphere %d, sphere-box %d, sphere-cylinder %d\n",
           decks, with, bodies, pairs[RC_PAIR_SPHERE_PLANE], pairs[RC_PAIR_SPHERE_SPHERE], pairs[RC_PAIR_SPHERE_BOX],
           pairs[RC_PAIR_SPHERE_CYL]);
    ENSURE(decks > 50 && with > 3);
}

/* The Jacobian with the rotation states' columns skipped (rc_data.jac_skip,
 * as the CVODE backend sets it): every entry in a kept row and column bit
 * for bit the whole Jacobian's, the skipped columns 0; the whole Jacobian
 * against central differences, at a state of the staggered column with
 * every contact closed and the spheres moving. */
static void test_torquefree_jacobian(void)
{
    rc_model *m = column_model(5, TU_COL_TILT);
    if (!m) return;
    const int ny = m->ny;
    double *y = calloc((size_t)ny + 1, sizeof(double));
    double *ja = calloc((size_t)m->nnz + 1, sizeof(double)), *jb = calloc((size_t)m->nnz + 1, sizeof(double));
    char *cst = calloc((size_t)ny + 1, 1);
    rc_data *d = rc_data_new(m);
    ENSURE(y && ja && jb && cst && d);
    if (!y || !ja || !jb || !cst || !d) goto out;
    rc_initial_state(m, y);
    ENSURE(rc_constant_states(m, y, NULL, cst) == 35);
    /* every contact closed: each sphere 2e-5 m into the one below */
    for (int b = 0; b < 5; b++) {
        const int a = m->body_yadr[b];
        const double dx = 0.0015 * (b % 3), dxl = b ? 0.0015 * ((b - 1) % 3) : 0.0;
        const double hb = b ? sqrt(0.02 * 0.02 - (dx - dxl) * (dx - dxl)) - 2e-5 : 0.01 - 2e-5;
        y[a + 2] = b ? y[m->body_yadr[b - 1] + 2] + hb : hb;
        y[a + 7] = 0.01 * b;
        y[a + 9] = -0.02 * b;
    }
    rc_modes_init(m, d, 0.0, y);
    int closed = 0;
    for (int i = 0; i < m->ninter; i++) closed += d->inter_mode[i] == RC_MODE_CLOSED;
    ENSURE(closed == 5);
    int bad = 0, outside = 0;
    const double err = tu_jac_fd_error(m, d, 0.01, y, 0, &bad, &outside);
    ENSURE(bad == 0 && outside == 0);
    int kept = 0, nonzero = 0;
    const int differ = tu_jac_skip_compare(m, d, 0.01, y, cst, ja, jb, &kept, &nonzero);
    printf("    staggered column, contacts closed: Jacobian against central differences %.2g; %d kept entries "
           "(%d non-zero) identical with the rotation columns skipped\n",
           err, kept, nonzero);
    ENSURE(differ == 0 && nonzero > 50);
out:
    free(y);
    free(ja);
    free(jb);
    free(cst);
    rc_data_free(d);
    rc_model_free(m);
}

/* The column of 5 (staggered, pushed sideways: the spheres move in 3-D)
 * on CVODE with the rotations left out and with every state: the same
 * events within 5e-9 s, final positions within 1e-10 m, velocities within
 * 3e-8 m/s and normal forces within 1e-6 of m g; the rotations stay at
 * their initial values bit for bit in both. Both runs are within the error
 * control of the same solution; the reduced run's WRMS norm divides by
 * fewer components (sqrt(75 / 40) = 1.4 tighter), so its steps differ.
 * Measured: 32 events, 7.4e-10 s, 1.9e-12 m, 3.1e-11 m/s, 6.5e-13 m g.
 * A rotation state left out that should have moved, a lost event or a
 * state scattered to the wrong place fail the bounds. */
static void test_torquefree_runs(void)
{
    rc_model *m = column_model(5, TU_COL_TILT);
    if (!m) return;
    const int ny = m->ny;
    double *ya = calloc((size_t)ny + 1, sizeof(double)), *yb = calloc((size_t)ny + 1, sizeof(double));
    double *y0 = calloc((size_t)ny + 1, sizeof(double));
    tu_evlog *la = calloc(1, sizeof *la), *lb = calloc(1, sizeof *lb);
    rc_data *da = rc_data_new(m), *db = rc_data_new(m);
    ENSURE(ya && yb && y0 && la && lb && da && db);
    if (!ya || !yb || !y0 || !la || !lb || !da || !db) goto out;
    rc_initial_state(m, y0);
    rc_error e;
    rc_stats sa, sb;
    rc_run_options oa = {.y_end = ya, .on_event = tu_evlog_event, .user = la};
    rc_run_options ob = {.y_end = yb, .on_event = tu_evlog_event, .user = lb};
    rc_cvode_set_reduce(1);
    ENSURE(rc_solver_cvode.run(m, &oa, NULL, NULL, &sa, &e) == RC_OK);
    rc_cvode_set_reduce(0);
    ENSURE(rc_solver_cvode.run(m, &ob, NULL, NULL, &sb, &e) == RC_OK);
    rc_cvode_set_reduce(1);
    ENSURE(la->n == lb->n && la->n > 5 && la->n <= TU_MAXEV);
    double dt = 0.0, dx = 0.0, dv = 0.0, dfn = 0.0, fbig = 0.0;
    for (int k = 0; k < la->n && k < lb->n && k < TU_MAXEV; k++) {
        ENSURE(strcmp(la->kind[k], lb->kind[k]) == 0 && strcmp(la->elem[k], lb->elem[k]) == 0);
        dt = fmax(dt, fabs(la->t[k] - lb->t[k]));
    }
    int rot_same = 1, moved = 0;
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        for (int k = 0; k < 3; k++) {
            dx = fmax(dx, fabs(ya[a + k] - yb[a + k]));
            dv = fmax(dv, fabs(ya[a + 7 + k] - yb[a + 7 + k]));
            moved |= fabs(ya[a + k] - y0[a + k]) > 1e-3;
        }
        for (int k = 3; k < 7; k++) rot_same &= ya[a + k] == y0[a + k] && yb[a + k] == y0[a + k];
        for (int k = 10; k < 13; k++) rot_same &= ya[a + k] == 0.0 && yb[a + k] == 0.0;
    }
    /* the normal forces at the end, each run in the modes its events left */
    rc_modes_init(m, da, m->tend, ya);
    rc_modes_init(m, db, m->tend, yb);
    for (int i = 0; i < m->ninter; i++) {
        rc_inter_report ra, rb;
        rc_inter_report_eval_d(m, da, i, m->tend, ya, &ra);
        rc_inter_report_eval_d(m, db, i, m->tend, yb, &rb);
        const double fa = da->inter_mode[i] == RC_MODE_CLOSED ? ra.fn : 0.0;
        const double fb = db->inter_mode[i] == RC_MODE_CLOSED ? rb.fn : 0.0;
        dfn = fmax(dfn, fabs(fa - fb));
        fbig = fmax(fbig, fabs(fa));
    }
    const double mg = 0.01 * 9.81;
    printf("    staggered column of 5: %d events, %ld / %ld steps (reduced / all states); largest differences: "
           "event times %.2g s, x %.2g m, v %.2g m/s, normal forces %.2g m g (largest force %.3g m g)\n",
           la->n, sa.steps, sb.steps, dt, dx, dv, dfn / mg, fbig / mg);
    ENSURE(dt <= 5e-9 && dx <= 1e-10 && dv <= 3e-8 && dfn <= 1e-6 * mg);
    ENSURE(rot_same && moved && fbig > 0.5 * mg);
out:
    free(ya);
    free(yb);
    free(y0);
    free(la);
    free(lb);
    rc_data_free(da);
    rc_data_free(db);
    rc_model_free(m);
}

void suite_torquefree(void);
void suite_torquefree(void)
{
    RUN_TEST(test_torquefree_column_rows);
    RUN_TEST(test_torquefree_refused);
    RUN_TEST(test_torquefree_validation_decks);
    RUN_TEST(test_torquefree_jacobian);
    RUN_TEST(test_torquefree_runs);
}
