/*
 * Contacts at zero and friction at its switches: after the modes are decided
 * from the state (at the start and after every event), every root function
 * must wait strictly on its own side, so that the integrator can see the
 * crossing that changes the mode (docs/theory.md 5.1, 3.5). A root that
 * starts past its crossing is never reported: a contact that never closes
 * again (bodies passing through each other), friction that never sticks and
 * pushes the sliding.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/events.h"
#include "harness.h"
#include "model/friction.h"
#include "model/model.h"
#include "testutil.h"

/* A row of five touching balls at x = i 2R (not exactly representable: the
 * pairs overlap or part by rounding), the first one moving; Hertz contacts. */
static const char *cradle_deck(void)
{
    static char buf[8192];
    int n = snprintf(buf, sizeof buf, "/BEGIN\ncradle\n      2022         0\n"
                                      "                  kg                   m                   s\n"
                                      "                  kg                   m                   s\n/NODE\n");
    for (int i = 0; i < 5; i++) n += snprintf(buf + n, sizeof buf - (size_t)n, "%10d%20.17g%20d%20d\n", i + 1, 0.02 * i, 0, 0);
    for (int i = 0; i < 5; i++)
        n += snprintf(buf + n, sizeof buf - (size_t)n,
                      "/RBODY/%d\nball\n%10d%10s%10s%10s%20s%10d\n%20s%20s%20s\n%20d%20d%20d\n/SURF/ELLIPS/%d\nball\n"
                      "%10d%10d%10d\n%20.17g%20d%20d\n%20s%20s%20s\n/GRNOD/NODE/%d\nball\n%10d\n",
                      i + 1, i + 1, "", "", "", "0.0327", i + 1, "1.308e-6", "1.308e-6", "1.308e-6", 0, 0, 0, i + 1, 0,
                      2, i + 1, 0.02 * i, 0, 0, "0.01", "0.01", "0.01", i + 1, i + 1);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "/INIVEL/TRA/1\nv\n%20s%20s%20s%10d%10d\n", "1.0", "0", "0", 1, 0);
    for (int i = 0; i < 4; i++)
        n += snprintf(buf + n, sizeof buf - (size_t)n,
                      "/INTER/POWER/%d\nHertz\n%10d%10d%10d%10d%10d%10d\n%20s%20s%20s\n\n\n", i + 1, i + 1, i + 2, 0, 0, 0,
                      0, "1e10", "1.5", "0");
    snprintf(buf + n, sizeof buf - (size_t)n, "/RUN\n%20s%20s\n/END\n", "0.002", "1e-5");
    return buf;
}

/* A sphere resting on an incline (touching, at rest) with TYPE6 friction and
 * damping, a wall below it; a box on a floor, touching, sliding with
 * friction. */
static const char *incline_deck =
    "/BEGIN\nball on a ramp\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
    "/NODE\n         1-0.26480677906948907                   0 0.14959067403699605\n"
    "/RBODY/1\nball\n         1                                                 1         1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\nball\n         0         2         1\n"
    "-0.26480677906948907                   0 0.14959067403699605\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\nincline\n                   0                   0                   0\n"
    " 0.34202014332566871                   0 0.93969262078590843\n"
    "/SURF/PLANE/3\nwall\n                 0.2                   0                   0\n"
    "                  -1                   0                   0\n"
    "/GRNOD/NODE/1\nball\n         1\n"
    "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
    "/INTER/TYPE6/1\nball on ramp\n         1         2\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/INTER/TYPE6/2\nball on wall\n         1         3\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/RUN\n                   2               0.001\n/END\n";

static const char *box_deck =
    "/BEGIN\nbox on a floor\n      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
    "/NODE\n         1                   0                   0                0.05\n"
    "/RBODY/1\nbox\n         1                                                 1         1\n"
    "  0.0016666666666667  0.0016666666666667  0.0016666666666667\n"
    "                   0                   0                   0\n"
    "/SURF/BOX/1\nbox\n         1\n                   0                   0                0.05\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\nfloor\n                   0                   0                   0\n"
    "                   0                   0                   1\n"
    "/GRNOD/NODE/1\nbox\n         1\n"
    "/GRAV/1\ng\n         0         Z         0         0         1                             1               -9.81\n"
    "/INIVEL/TRA/1\nv\n                   1                 0.3                   0         1         0\n"
    "/INTER/TYPE6/1\nbox on floor\n         1         2\n"
    "                                   0.3\n\n         1         0\n\n         600\n"
    "/RUN\n                 0.5               0.001\n/END\n";

static uint64_t rng = 0x9e3779b97f4a7c15ULL;
static double urand(void) /* [0, 1) */
{
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rng >> 11) / 9007199254740992.0;
}

/* Every root of every active interface on its waiting side, in the modes
 * rc_modes_touch left (returns the number of roots that are not; each
 * printed). */
static int roots_waiting(const rc_model *m, const rc_data *d, double t, const double *y, double *g, const char *what)
{
    rc_assemble_roots(m, d, t, y, g);
    int bad = 0;
    for (int i = 0; i < m->ninter; i++) {
        const int md = d->inter_mode[i];
        if (md == RC_MODE_INACTIVE) continue;
        const double *gi = g + RC_ROOTS_PER_INTER * i;
        const char *why = NULL;
        if (!d->inter_track[i] && md == RC_MODE_OPEN && !(gi[RC_ROOT_ZONE] < 0)) why = "open, zone root not < 0";
        if (md != RC_MODE_OPEN && !(gi[RC_ROOT_ZONE] > 0)) why = "in the zone, zone root not > 0";
        if (md == RC_MODE_CLOSED && !d->inter_settled[i] && !(gi[RC_ROOT_FORCE] > 0)) why = "closed, force root not > 0";
        if (md == RC_MODE_RELEASED && !(gi[RC_ROOT_FORCE] < 0)) why = "released, force root not < 0";
        const rc_fric *fr = &m->inter_fr[i];
        if (md == RC_MODE_CLOSED && fr->kind != RC_FK_NONE && fr->form == RC_FF_INCREMENTAL && !fr->exact &&
            m->inter_npt[i] == 0 && !(gi[RC_ROOT_SLIP] <= 0))
            why = d->inter_slip[i] ? "slipping along its force (v_t . e > 0)" : "sticking beyond its limit";
        if (why) {
            if (bad < 10) printf("    %s: %s %s (zone %.3g, force %.3g, slip %.3g)\n", what, m->inter_name[i], why,
                                 gi[RC_ROOT_ZONE], gi[RC_ROOT_FORCE], gi[RC_ROOT_SLIP]);
            bad++;
        }
    }
    return bad;
}

/* Random states near the deck's start (positions moved by a few ulps to a
 * few 1e-9 of their size, velocities of any size and sign), random modes;
 * after rc_modes_touch every root waits on its side. */
static void roots_wait_on_their_side(const char *deck, const char *name, int trials)
{
    rc_error e;
    rc_model *m = tu_compile_text(deck, name, &e);
    ENSURE(m != NULL);
    if (!m) {
        printf("    %s\n", e.msg);
        return;
    }
    rc_data *d = rc_data_new(m);
    double *y0 = calloc((size_t)m->ny, sizeof(double)), *y = calloc((size_t)m->ny, sizeof(double));
    double *f = calloc((size_t)m->ny, sizeof(double)), *g = calloc((size_t)rc_root_count(m) + 1, sizeof(double));
    rc_initial_state(m, y0);
    int bad = 0, events = 0;
    for (int k = 0; k < trials; k++) {
        memcpy(y, y0, (size_t)m->ny * sizeof(double));
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double *s = y + m->body_yadr[b];
            const double scale = pow(10.0, -16.0 + 8.0 * urand()); /* relative position change */
            for (int q = 0; q < 3; q++) s[q] += (urand() - 0.5) * scale * (fabs(s[q]) + 0.01);
            const double vs = urand() < 0.3 ? 0.0 : pow(10.0, -12.0 + 12.0 * urand());
            for (int q = 7; q < 13; q++) s[q] += (urand() - 0.5) * vs;
        }
        for (int i = 0; i < m->ninter; i++) {
            const int r = (int)(4 * urand());
            d->inter_mode[i] = r == 0 ? RC_MODE_OPEN : r == 3 ? RC_MODE_RELEASED : RC_MODE_CLOSED;
            d->inter_branch[i] = RC_BR_LOAD;
            d->inter_track[i] = 0;
            d->inter_slip[i] = urand() < 0.5;
            d->inter_settled[i] = 0;
            d->inter_band[2 * i] = d->inter_band[2 * i + 1] = 0.0;
            /* a tangential state of any direction, up to a few times the weight */
            const rc_fric *fr = &m->inter_fr[i];
            if (fr->tidx >= 0)
                for (int q = 0; q < 3; q++) y[m->inter_eadr[i] + fr->tidx + q] = (urand() - 0.5) * 20.0;
        }
        rc_event ev[64];
        int restart = 0;
        for (int round = 0; round < 2; round++) { /* as the driver: twice */
            rc_assemble_rhs(m, d, 0.0, y, f);
            events += rc_modes_touch(m, d, 0.0, y, f, ev, 64, &restart);
        }
        bad += roots_waiting(m, d, 0.0, y, g, name);
    }
    printf("    %s: %d random states near the start, %d transitions decided, %d roots past their crossing\n", name,
           trials, events, bad);
    ENSURE(bad == 0);
    free(y0);
    free(y);
    free(f);
    free(g);
    rc_data_free(d);
    rc_model_free(m);
}

static void test_touching_roots_wait_on_their_side(void)
{
    roots_wait_on_their_side(cradle_deck(), "cradle.rad", 400);
    roots_wait_on_their_side(incline_deck, "incline.rad", 400);
    roots_wait_on_their_side(box_deck, "box.rad", 200);
}

/* End-to-end: the cradle passes its momentum down the row (no ball passes
 * through another); the box sliding from a touching start stays on the
 * floor; the ball on the ramp gains no energy from friction. */
static double run_end(const char *deck, const char *name, double *yend)
{
    rc_error e;
    rc_model *m = tu_compile_text(deck, name, &e);
    ENSURE(m != NULL);
    if (!m) return NAN;
    rc_run_options o;
    memset(&o, 0, sizeof o);
    o.y_end = yend;
    rc_stats st;
    const rc_status s = rc_run(m, &o, &st, &e);
    ENSURE(s == RC_OK);
    if (s) printf("    %s\n", e.msg);
    const int ny = m->ny;
    rc_model_free(m);
    return ny;
}

static void test_cradle_off_grid_passes_momentum(void)
{
    double y[256];
    memset(y, 0, sizeof y);
    if (!(run_end(cradle_deck(), "cradle.rad", y) > 0)) return;
    /* ball i's state at 13 i: x at 0, v_x at 7 */
    double vmax = 0, dmin = INFINITY;
    for (int i = 0; i < 5; i++) vmax = fmax(vmax, y[13 * i + 7]);
    for (int i = 0; i + 1 < 5; i++) dmin = fmin(dmin, y[13 * (i + 1)] - y[13 * i]);
    printf("    cradle at x = i 2R: ball 5 leaves at %.4f m/s (1 m/s struck), closest centres %.5f m apart (2R = 0.02)\n",
           y[13 * 4 + 7], dmin);
    ENSURE(y[13 * 4 + 7] > 0.9 && y[13 * 4 + 7] <= 1.0 + 1e-9);
    ENSURE(dmin > 0.019);
}

static void test_box_sliding_from_touch_stays_on_the_floor(void)
{
    double y[64];
    memset(y, 0, sizeof y);
    if (!(run_end(box_deck, "box.rad", y) > 0)) return;
    printf("    box sliding from a touching start: centre at z = %.9f m after 0.5 s (half size 0.05 m), speed %.2e m/s\n",
           y[2], hypot(y[7], y[8]));
    ENSURE(y[2] > 0.05 - 1e-4 && y[2] < 0.05 + 1e-6);
    ENSURE(hypot(y[7], y[8]) < 1e-6); /* stopped by friction (mu g t = 1.47 m/s > 1.04) */
}

static void test_ball_on_ramp_friction_never_pushes(void)
{
    double y[64];
    memset(y, 0, sizeof y);
    if (!(run_end(incline_deck, "incline.rad", y) > 0)) return;
    /* kinetic energy at the end (the ball settles against the wall within
     * 2 s) and the spin: rolling down 0.3 m of a 20 degree ramp (1.47 J),
     * then stopped by the wall; before, friction spun it up to 113 rad/s */
    const double ke = 0.5 * (y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
    printf("    ball on the ramp into the wall: final speed %.2e m/s, spin %.2e rad/s, kinetic energy %.2e J\n",
           sqrt(2 * ke), hypot(hypot(y[10], y[11]), y[12]), ke);
    ENSURE(ke < 1e-6);
    ENSURE(hypot(hypot(y[10], y[11]), y[12]) < 1.0);
}

void suite_passive(void);
void suite_passive(void)
{
    RUN_TEST(test_touching_roots_wait_on_their_side);
    RUN_TEST(test_cradle_off_grid_passes_momentum);
    RUN_TEST(test_box_sliding_from_touch_stays_on_the_floor);
    RUN_TEST(test_ball_on_ramp_friction_never_pushes);
}
