/* Method switching (/SOLVER Switch, rc_model_set_switch; docs/theory.md
 * 7.9): the CVODE path hands over to an explicit Runge-Kutta method while
 * impacts pin BDF's step near the explicit stability limit, and back when
 * the contacts rest.
 *
 * An impact cascade: a column of SW_N spheres (m = 0.01 kg, R = 0.01 m)
 * held to the vertical, each 1e-4 m above the one below (the first above
 * the floor), falling under gravity into linear critically damped contacts
 * (k = 1e5 N/m): dozens of impacts within 0.1 s, then the column rests.
 * With switching on, the run switches to the explicit method and back at
 * least once, the events table's method_explicit and method_implicit rows
 * (here the event callback's) match the statistics, the final state agrees
 * with the run without switching (both at Rtol 1e-6: positions to 1e-9 m,
 * velocities to 1e-6 m/s, against a fall speed sqrt(2 g gap) = 0.044 m/s),
 * and no energy is created: the ledger's residual E_total(t_end) -
 * E_total(0) is at most 1e-6 of the potential energy the column gives up,
 * the mechanical energy at the end at most the initial one, the physics
 * checks pass.
 *
 * And the option's surface: Switch 2 is an input error naming the field,
 * the setter takes 0 or 1 only, and a run without switching has no switch.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "engine/assembly/assembly.h"
#include "engine/reports/reports.h"
#include "model/model.h"
#include "testutil.h"

#define SW_N 12
#define SW_R 0.01
#define SW_M 0.01
#define SW_K 1e5
#define SW_GAP 1e-4
#define SW_G 9.81
#define SW_TEND 0.4

static void put(char **b, size_t *n, size_t *cap, const char *fmt, ...)
{
    if (!*b) return;
    va_list ap;
    va_start(ap, fmt);
    char line[512];
    const int k = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (k < 0) return;
    if (*n + (size_t)k + 1 > *cap) {
        char *nb = realloc(*b, 2 * (*cap + (size_t)k + 1));
        if (!nb) {
            free(*b);
            *b = NULL;
            return;
        }
        *b = nb;
        *cap = 2 * (*cap + (size_t)k + 1);
    }
    memcpy(*b + *n, line, (size_t)k + 1);
    *n += (size_t)k;
}

/* The cascade deck; `sw` is written into /SOLVER Switch (line 3, columns
 * 21-30). */
static char *cascade_deck(int sw)
{
    size_t n = 0, cap = 16384;
    char *b = malloc(cap);
    if (b) b[0] = '\0';
    put(&b, &n, &cap, "#RADIOSS STARTER\n/BEGIN\nswitch: cascade of %d spheres\n      2022         0\n", SW_N);
    put(&b, &n, &cap, "                  kg                   m                   s\n");
    put(&b, &n, &cap, "                  kg                   m                   s\n");
    put(&b, &n, &cap, "/FUNCT/1\nlinear k\n%20d%20d\n%20d%20.10g\n", 0, 0, 1, SW_K);
    put(&b, &n, &cap, "/NODE\n");
    double z[SW_N];
    for (int j = 0; j < SW_N; j++) z[j] = SW_R + SW_GAP + j * (2 * SW_R + SW_GAP);
    for (int j = 0; j < SW_N; j++) put(&b, &n, &cap, "%10d%20d%20d%20.10g\n", j + 1, 0, 0, z[j]);
    const double J = 0.4 * SW_M * SW_R * SW_R;
    for (int j = 1; j <= SW_N; j++) {
        put(&b, &n, &cap, "/RBODY/%d\nsphere %d\n%10d%40s%10.6g\n", j, j, j, "", SW_M);
        put(&b, &n, &cap, "%20.10g%20.10g%20.10g\n%20d%20d%20d\n", J, J, J, 0, 0, 0);
    }
    for (int j = 1; j <= SW_N; j++)
        put(&b, &n, &cap, "/SURF/ELLIPS/%d\nsphere %d\n%10d%10d%10d\n%20d%20d%20.10g\n%20.10g%20.10g%20.10g\n", j, j, 0,
            2, j, 0, 0, z[j - 1], SW_R, SW_R, SW_R);
    put(&b, &n, &cap, "/SURF/PLANE/%d\nfloor\n%20d%20d%20d\n%20d%20d%20d\n", SW_N + 1, 0, 0, 0, 0, 0, 1);
    put(&b, &n, &cap, "/GRAV/1\ngravity\n         0         Z         0         0         0%30s%20.10g\n", "1", -SW_G);
    put(&b, &n, &cap, "/GRNOD/NODE/1\nall spheres\n");
    for (int j = 1; j <= SW_N; j++) put(&b, &n, &cap, "%10d%s", j, j % 8 == 0 || j == SW_N ? "\n" : "");
    put(&b, &n, &cap, "/BCS/1\nheld to the vertical\n   110 111         0         1\n");
    for (int j = 1; j <= SW_N; j++) {
        const double c = j == 1 ? 2.0 * sqrt(SW_K * SW_M) : 2.0 * sqrt(SW_K * SW_M / 2.0); /* critical */
        put(&b, &n, &cap, "/INTER/TYPE6/%d\ncontact %d\n%10d%10d\n", j, j, j == 1 ? SW_N + 1 : j - 1, j);
        put(&b, &n, &cap, "%60s\n%20s%10d%10d%10d%10d\n%10d%10d%50s\n%10d\n%20.10g%10d%10d\n", "0", "0", 0, 0, 0, 0,
            1, 0, "0", 0, c, 0, 0);
    }
    put(&b, &n, &cap, "/RUN\n%20.10g%20.10g\n", SW_TEND, SW_TEND / 10);
    put(&b, &n, &cap, "/SOLVER\n%10d%10d%10d%20.10g\n\n%20s%10d\n/END\n", 1, 5, 10000000, 1e-6, "", sw);
    return b;
}

typedef struct { long expl, impl, other; } sw_count;
static int count_event(void *user, double t, const char *kind, const char *element, const double v[3])
{
    sw_count *c = user;
    (void)t;
    (void)v;
    if (!strcmp(kind, "method_explicit")) c->expl += !strcmp(element, "/SOLVER");
    else if (!strcmp(kind, "method_implicit")) c->impl += !strcmp(element, "/SOLVER");
    else c->other++;
    return 0;
}

/* Kinetic and gravitational potential energy of the state y [J]. */
static double mech_energy(const rc_model *m, const double *y)
{
    double e = 0.0;
    for (int j = 1; j <= SW_N; j++) {
        const int a = rc_model_body_index(m, j);
        if (a < 0) continue;
        const double *s = y + a;
        e += 0.5 * SW_M * (s[7] * s[7] + s[8] * s[8] + s[9] * s[9]) + SW_M * SW_G * s[2];
    }
    return e;
}

/* Run the cascade deck with Switch `sw` (set_sw >= 0: then by the setter):
 * the final state into y (rc_model_state_size values), the statistics and
 * the switch events counted. Returns the model (freed by the caller), NULL
 * after a failure. */
static rc_model *run_cascade(int sw, int set_sw, double **y, rc_stats *st, sw_count *cnt)
{
    char *text = cascade_deck(sw);
    ENSURE(text != NULL);
    if (!text) return NULL;
    rc_error e;
    rc_model *m = tu_compile_text(text, "switch_cascade.rad", &e);
    free(text);
    if (!m) fprintf(stderr, "  switch_cascade.rad: %s\n", e.msg);
    ENSURE(m != NULL);
    if (!m) return NULL;
    if (set_sw >= 0) ENSURE(rc_model_set_switch(m, set_sw, &e) == RC_OK);
    *y = calloc((size_t)rc_model_state_size(m) + 1, sizeof(double));
    memset(cnt, 0, sizeof *cnt);
    rc_run_options o = {.y_end = *y, .on_event = count_event, .user = cnt};
    const rc_status s = rc_run(m, &o, st, &e);
    if (s) fprintf(stderr, "  run (switch %d): %s\n", sw, e.msg);
    ENSURE(s == RC_OK);
    if (s) {
        rc_model_free(m);
        return NULL;
    }
    return m;
}

static void test_switch_cascade(void)
{
    double *y0 = NULL, *y1 = NULL;
    rc_stats s0, s1;
    sw_count c0, c1;
    rc_model *m0 = run_cascade(0, -1, &y0, &s0, &c0);
    rc_model *m1 = run_cascade(1, -1, &y1, &s1, &c1);
    if (m0 && m1) {
        printf("    off: %ld steps, %ld events, %ld restarts; on: %ld steps (%ld explicit), %ld events, "
               "switches %ld to explicit, %ld back\n",
               s0.steps, s0.events, s0.reinits, s1.steps, s1.steps_explicit, s1.events, s1.switches_explicit,
               s1.switches_implicit);
        ENSURE(rc_model_switch(m1) == 1 && rc_model_switch(m0) == 0);
        /* (a) switches both ways, as events and in the statistics */
        ENSURE(s0.switches_explicit == 0 && s0.switches_implicit == 0 && s0.steps_explicit == 0);
        ENSURE(c0.expl == 0 && c0.impl == 0);
        ENSURE(s1.switches_explicit >= 1 && s1.switches_implicit >= 1);
        ENSURE(c1.expl == s1.switches_explicit && c1.impl == s1.switches_implicit);
        ENSURE(s1.steps_explicit > 0 && s1.steps_explicit < s1.steps);
        /* the same impacts: the events other than the switches */
        ENSURE(s0.events > 20 && labs(s1.events - s0.events) <= s0.events / 20);
        /* (b) the final state agrees */
        double dz = 0.0, dv = 0.0;
        for (int j = 1; j <= SW_N; j++) {
            const int a = rc_model_body_index(m0, j);
            ENSURE(a >= 0 && a == rc_model_body_index(m1, j));
            if (a < 0) continue;
            dz = fmax(dz, fabs(y1[a + 2] - y0[a + 2]));
            dv = fmax(dv, fabs(y1[a + 9] - y0[a + 9]));
        }
        printf("    final state: |dz| <= %.3g m, |dv| <= %.3g m/s\n", dz, dv);
        ENSURE(dz <= 1e-9 && dv <= 1e-6);
        /* (c) no energy created */
        double z0[SW_N];
        for (int j = 0; j < SW_N; j++) z0[j] = SW_R + SW_GAP + j * (2 * SW_R + SW_GAP);
        double e0 = 0.0;
        for (int j = 0; j < SW_N; j++) e0 += SW_M * SW_G * z0[j];
        const double e1 = mech_energy(m1, y1), drop = e0 - e1;
        printf("    energy: mechanical %.9g J -> %.9g J; ledger residual %.3g J (off: %.3g J)\n", e0, e1,
               s1.energy_residual, s0.energy_residual);
        ENSURE(drop > 0);
        ENSURE(s1.energy_residual <= 1e-6 * drop);
        ENSURE(s1.violations == 0);
    }
    free(y0);
    free(y1);
    rc_model_free(m0);
    rc_model_free(m1);
    /* the setter turns it on as the field does */
    double *y2 = NULL;
    rc_stats s2;
    sw_count c2;
    rc_model *m2 = run_cascade(0, 1, &y2, &s2, &c2);
    if (m2) ENSURE(s2.switches_explicit >= 1 && c2.expl == s2.switches_explicit);
    free(y2);
    rc_model_free(m2);
}

static void test_switch_option(void)
{
    /* Switch takes 0 or 1 */
    char *text = cascade_deck(2);
    ENSURE(text != NULL);
    if (text) TU_EXPECT_TEXT_ERROR(text, "switch_field.rad", "/SOLVER", "Switch");
    free(text);
    text = cascade_deck(0);
    rc_error e;
    rc_model *m = text ? tu_compile_text(text, "switch_set.rad", &e) : NULL;
    ENSURE(m != NULL);
    if (m) {
        ENSURE(rc_model_switch(m) == 0);
        ENSURE(rc_model_set_switch(m, 2, &e) == RC_EINPUT && strstr(e.msg, "got 2"));
        ENSURE(rc_model_switch(m) == 0);
        ENSURE(rc_model_set_switch(m, 1, &e) == RC_OK && rc_model_switch(m) == 1);
        rc_model_free(m);
    }
    free(text);
    ENSURE(rc_model_set_switch(NULL, 1, &e) == RC_EINPUT);
    ENSURE(rc_model_switch(NULL) == 0);
}

/* The critical explicit step counts the relaxation of a law's penetration
 * P_e (docs/theory.md 2.7, 7.9): a box on a floor (its corners, P_e at
 * kappa = 10 omega_s) closed, h_crit = min(2 / kappa, 2 / omega_max) with
 * omega_max^2 = k_s / m (undamped, against a fixed floor): here kappa wins
 * (an explicit step of 2 / omega_max is 10 times past the relaxation's
 * stability bound); open, no bound. */
static void test_switch_critical_step_counts_pe_relaxation(void)
{
    static const char *deck =
        "/BEGIN\nbox on a floor\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/FUNCT/1\nlinear\n0,0\n1,1000000\n"
        "/NODE\n1,0,0,0.05\n"
        "/RBODY/1\nbox\n1,,,,1,1\n0.0016666666666667,0.0016666666666667,0.0016666666666667\n0,0,0\n"
        "/SURF/BOX/1\nbox\n1\n0,0,0.05\n0.05,0.05,0.05\n1,0,0\n0,1,0\n"
        "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
        "/GRNOD/NODE/1\nbox\n1\n"
        "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
        "/INTER/TYPE6/1\nbox on floor\n1,2\n\n\n1,0\n\n\n"
        "/RUN\n0.1,0.01\n/END\n";
    rc_model *m = TU_COMPILE_OK(deck, "box_floor_hcrit.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *work = malloc((2 * (size_t)m->nbody + 1) * sizeof(double));
    ENSURE(d != NULL && work != NULL && m->ninter == 1 && m->inter_peidx[0] >= 0);
    if (d && work && m->ninter == 1) {
        d->inter_mode[0] = RC_MODE_OPEN;
        ENSURE(isinf(rc_explicit_step(m, d, 0.0, NULL, work)));
        d->inter_mode[0] = RC_MODE_CLOSED;
        const double h = rc_explicit_step(m, d, 0.0, NULL, work), kappa = m->inter_perelax[0];
        const double om = sqrt(m->inter_kscale[0] / m->body_mass[0]), want = fmin(2.0 / kappa, 2.0 / om);
        printf("    box on a floor, closed: h_crit %.6g s (2 / kappa %.6g s, 2 / omega_max %.6g s)\n", h, 2.0 / kappa,
               2.0 / om);
        ENSURE(kappa > 0 && isfinite(kappa));
        ENSURE(fabs(h - want) <= 1e-12 * want);
        ENSURE(2.0 / kappa < 2.0 / om); /* the relaxation is the stiffer rate here */
    }
    free(work);
    rc_data_free(d);
    rc_model_free(m);
}

/* The critical explicit step counts the friction's stick spring and slip
 * law (docs/theory.md 7.9): a ball (1 kg, radius 0.05 m, J = 0.001 kg
 * m^2 = 2/5 m r^2) sliding at 1 m/s on a floor, TYPE6 Fric 0.5 with a
 * stick spring K_t = Stiff = 1e7 N/m, closed and slipping. The spring acts
 * at the contact point, r below the centre: through the ball's rotation
 * its tangential rate is K_t (1/m + r^2/J) = 3.5 K_t / m (the rolling
 * sphere's 1 + 5/2), added to the normal contact's k_s / m; the slip law
 * turns F_t at K_t |v_t| / L_r, L_r = max(limit, F_s). Before, the step
 * saw the normal contact alone: an explicit method switched in at the
 * closing of a sliding ball and turned its friction every step (200
 * fric_turn within 1.4e-10 s, Zeno, the fuzzer's 157000027). */
static void test_switch_critical_step_counts_friction(void)
{
    static const char *deck =
        "/BEGIN\nball sliding on a floor\n      2022         0\n"
        "                  kg                   m                   s\n"
        "                  kg                   m                   s\n"
        "/FUNCT/1\nlinear\n0,0\n1,1000000\n"
        "/NODE\n1,0,0,0.05\n"
        "/RBODY/1\nball\n1,,,,1,1\n0.001,0.001,0.001\n0,0,0\n"
        "/SURF/ELLIPS/1\nball\n0,2,1\n0,0,0.05\n0.05,0.05,0.05\n"
        "/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
        "/GRNOD/NODE/1\nball\n1\n"
        "/GRAV/1\ng\n0,Z,0,0,1,,1,-9.81\n"
        "/INTER/TYPE6/1\nball on floor\n1,2\n0,0.5\n\n1,0\n0,0,10000000\n\n"
        "/RUN\n0.1,0.01\n/END\n";
    rc_model *m = TU_COMPILE_OK(deck, "ball_slide_hcrit.rad");
    if (!m) return;
    rc_data *d = rc_data_new(m);
    double *work = malloc((2 * (size_t)m->nbody + 1) * sizeof(double));
    double *y = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && work && y && m->ninter == 1 && m->inter_fr[0].kt == 1e7);
    if (d && work && y && m->ninter == 1) {
        rc_initial_state(m, y);
        double *yb = y + m->body_yadr[0];
        yb[2] = 0.05 - 9.81e-6; /* pressed by its weight: k = 1e6 N/m */
        yb[7] = 1.0;            /* sliding along x */
        d->inter_mode[0] = RC_MODE_CLOSED;
        d->inter_slip[0] = 1;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, 0, 0.0, y, &r);
        const double h0 = rc_explicit_step(m, d, 0.0, NULL, work), h = rc_explicit_step(m, d, 0.0, y, work);
        /* by hand: the row of the ball, normal k_s plus 3.5 K_t; the stick
         * damper 2 sqrt(K_t m_red) likewise through 3.5; the slip rate */
        const rc_fric *fr = &m->inter_fr[0];
        const double w2 = (m->inter_kscale[0] + 3.5 * fr->kt) / 1.0, om = sqrt(w2);
        const double zeta = 3.5 * fr->ct / (2.0 * om);
        const double hosc = 2.0 / om * (sqrt(1.0 + zeta * zeta) - zeta);
        const double rate = fr->kt * 1.0 / fmax(r.flim, m->inter_fscale[0]);
        const double want = fmin(hosc, 2.0 / rate);
        printf("    ball sliding at %.3g m/s: h_crit %.6g s (normal contact alone %.6g s; stick spring through the "
               "rotation %.6g s, slip law 2 / (K_t |v_t| / L_r) %.6g s)\n", r.vslip, h, h0, hosc, 2.0 / rate);
        ENSURE(fabs(r.vslip - 1.0) < 1e-9);
        ENSURE(fabs(h - want) <= 1e-9 * want);
        ENSURE(h < h0);
        /* sticking at rest: the spring through the rotation alone */
        yb[7] = 0.0;
        d->inter_slip[0] = 0;
        const double hs = rc_explicit_step(m, d, 0.0, y, work);
        printf("    ball sticking: h_crit %.6g s (by hand %.6g s)\n", hs, hosc);
        ENSURE(fabs(hs - hosc) <= 1e-9 * hosc);
    }
    free(y);
    free(work);
    rc_data_free(d);
    rc_model_free(m);
}

void suite_switch(void);
void suite_switch(void)
{
    RUN_TEST(test_switch_cascade);
    RUN_TEST(test_switch_option);
    RUN_TEST(test_switch_critical_step_counts_pe_relaxation);
    RUN_TEST(test_switch_critical_step_counts_friction);
}
