/*
 * Restitution of a nonlinear law by the single-contact ODE
 * (engine/analyses/restitution.c): against the closed form of the clipped linear
 * contact, the undamped laws (e = 1), the damping derived for an asked e,
 * the impact speed derived from the initial state, and the errors.
 */
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "base/error.h"
#include "engine/events/events.h"
#include "engine/events/settle.h"
#include "engine/analyses/restitution.h"
#include "model/model.h"
#include "model/power.h"
#include "harness.h"
#include "testutil.h"
#include "engine/assembly/assembly.h"

/* A 1 kg sphere 2 mm above a fixed plane at -1 m/s (z), then the interface
 * card text `inter` and its functions. */
static const char *deck(char *buf, size_t n, const char *inter, const char *vz)
{
    snprintf(buf, n,
             "#RADIOSS STARTER\n/BEGIN\nrestitution test\n      2022         0\n"
             "                  kg                   m                   s\n"
             "                  kg                   m                   s\n"
             "/FUNCT/1\nlinear\n                   0                   0\n                   1             1000000\n"
             "/FUNCT/2\nstiffening\n                   0                   0\n              0.0001                 100\n"
             "               0.001                5000\n                0.01              200000\n"
             "/NODE\n         1                   0                   0               0.052\n"
             "/RBODY/1\nsphere 1 kg\n         1                                                 1\n"
             "               0.001               0.001               0.001\n                   0                   0                   0\n"
             "/SURF/ELLIPS/1\nsphere\n         0         2         1\n                   0                   0               0.052\n"
             "                0.05                0.05                0.05\n"
             "/SURF/PLANE/2\nplane\n                   0                   0                   0\n"
             "                   0                   0                   1\n"
             "/GRNOD/NODE/1\ngroup\n         1\n"
             "/INIVEL/TRA/1\ninitial velocity\n                   0                   0%20s         1         0\n"
             "%s/RUN\n                0.01               0.001\n/END\n",
             vz, inter);
    return buf;
}

static rc_model *compile(const char *inter, const char *vz, rc_error *e)
{
    static char buf[8192];
    return tu_compile_text(deck(buf, sizeof buf, inter, vz), "restitution.rad", e);
}

/* TYPE6 with a linear load curve: the ODE gives the closed form of the
 * clipped linear contact at every damping ratio (under-, critically and
 * overdamped). */
static void test_restitution_ode_matches_linear_closed_form(void)
{
    rc_error e;
    rc_model *m = compile("/INTER/TYPE6/1\ncontact\n         1         2\n\n\n         1         0\n         0\n\n", "-1", &e);
    ENSURE(m);
    if (!m) return;
    const double k = 1e6, mr = m->inter_mred[0];
    ENSURE_NEAR(mr, 1.0, 1e-12, 0);
    const double zetas[] = {0.0, 0.05, 0.3, 0.7, 1.0, 1.5, 3.0};
    for (size_t j = 0; j < sizeof zetas / sizeof zetas[0]; j++) {
        double tc = 0, tau = 0;
        const double c = 2.0 * zetas[j] * sqrt(k * mr);
        const double eo = rc_restitution_solve(m, 0, mr, 1.0, c, &tc);
        const double ecf = rc_linear_restitution(zetas[j], &tau);
        ENSURE_NEAR(eo, ecf, 1e-9, 1e-11);
        ENSURE_NEAR(tc, tau / sqrt(k / mr), 1e-8, 0);
        /* a linear law: the same at any impact speed */
        ENSURE_NEAR(rc_restitution_solve(m, 0, mr, 7.0, c, NULL), ecf, 1e-9, 1e-11);
    }
    int given = 1;
    ENSURE_NEAR(rc_restitution_speed(m, 0, &given), 1.0, 1e-15, 0);
    ENSURE(!given);
    rc_model_free(m);
}

/* A nonlinear TYPE6 load curve asked e = 0.4 without V_imp: Visc derived at
 * the initial approach speed (2 m/s) gives 0.4 there and another value at
 * another speed; V_imp overrides the speed. */
static void test_restitution_type6_nonlinear_asked(void)
{
    rc_error e;
    const char *t6 = "/INTER/TYPE6/1\ncontact\n         1         2\n\n\n         2         0\n         0\n"
                     "                             0         0                                     0.4\n";
    rc_model *m = compile(t6, "-2", &e);
    ENSURE(m);
    if (!m) return;
    const double c = m->inter_visc[0];
    ENSURE(c > 0);
    ENSURE_NEAR(rc_restitution_solve(m, 0, m->inter_mred[0], 2.0, c, NULL), 0.4, 1e-9, 0);
    ENSURE(fabs(rc_restitution_solve(m, 0, m->inter_mred[0], 0.5, c, NULL) - 0.4) > 1e-3);
    rc_model_free(m);
    const char *t6v = "/INTER/TYPE6/1\ncontact\n         1         2\n\n\n         2         0\n         0\n"
                      "                             0         0                                     0.4                 0.5\n";
    m = compile(t6v, "-2", &e);
    ENSURE(m);
    if (!m) return;
    int given = 0;
    ENSURE_NEAR(rc_restitution_speed(m, 0, &given), 0.5, 0, 0);
    ENSURE(given);
    ENSURE_NEAR(rc_restitution_solve(m, 0, m->inter_mred[0], 0.5, m->inter_visc[0], NULL), 0.4, 1e-9, 0);
    rc_model_free(m);
}

/* Power law: undamped Hertz gives e = 1; C derived for e = 0.3 with the
 * default RDF gives 0.3; the gravity fall over the gap sets the speed. */
static void test_restitution_power_asked(void)
{
    rc_error e;
    const char *pw = "/INTER/POWER/1\nhertz\n         1         2         0         0         0         0\n"
                     "         10000000000                 1.5                   0                   1                 1.5\n"
                     "\n\n\n                 0.3\n";
    rc_model *m = compile(pw, "-1", &e);
    ENSURE(m);
    if (!m) return;
    const double c = m->inter_pw[0].c, mr = m->inter_mred[0];
    ENSURE(c > 0);
    ENSURE_NEAR(rc_restitution_solve(m, 0, mr, 1.0, c, NULL), 0.3, 1e-9, 0);
    ENSURE_NEAR(rc_restitution_solve(m, 0, mr, 1.0, 0.0, NULL), 1.0, 1e-9, 0);
    /* Hertz-type damping: a faster impact loses more */
    ENSURE(rc_restitution_solve(m, 0, mr, 2.0, c, NULL) < 0.3);
    /* `ricochet check`: asked, derived and predicted */
    FILE *f = tmpfile();
    ENSURE(f);
    if (f) {
        rc_model_print_summary(m, f);
        static char out[16384];
        rewind(f);
        size_t n = fread(out, 1, sizeof out - 1, f);
        out[n] = 0;
        fclose(f);
        ENSURE(strstr(out, "restitution asked 0.3 at the derived impact speed: C derived = "));
        ENSURE(strstr(out, "predicted 0.3"));
        ENSURE(strstr(out, "predicted restitution 0.3, contact time") && strstr(out, "at impact speed 1 m/s"));
    }
    rc_model_free(m);
}

/* Errors: a damping spline, nothing approaching without V_imp, C given. */
static void test_restitution_errors(void)
{
    rc_error e;
    const char *spl = "/INTER/POWER/1\nhertz\n         1         2         0         2         0         0\n"
                      "         10000000000                 1.5                   0                   1                 1.5\n"
                      "\n\n\n                 0.3\n";
    ENSURE(!compile(spl, "-1", &e));
    ENSURE(strstr(e.msg, "field e_target") && strstr(e.msg, "C = 0 and fct_damp = 0"));
    const char *pw = "/INTER/POWER/1\nhertz\n         1         2         0         0         0         0\n"
                     "         10000000000                 1.5                   0                   1                 1.5\n"
                     "\n\n\n                 0.3\n";
    ENSURE(!compile(pw, "0", &e));
    ENSURE(strstr(e.msg, "card /INTER/POWER/1, field V_imp") && strstr(e.msg, "impact speed"));
    const char *t6h = "/INTER/TYPE6/1\ncontact\n         1         2\n\n\n         2         1\n"
                      "         0                             1\n                             0         0                                     0.4\n";
    ENSURE(!compile(t6h, "-1", &e));
    ENSURE(strstr(e.msg, "field e_target"));
}

/* A ball 1 m above a floor (TYPE6, linear 1e8 N/m, restitution 0.7),
 * under gravity or not, compiled; NULL (message printed) on an error. */
static rc_model *settle_ball(int gravity, const char *name, rc_error *e)
{
    char text[1024];
    snprintf(text, sizeof text,
             "/BEGIN\nsettle\n2022,0\nkg,m,s\nkg,m,s\n/FUNCT/1\nlinear\n0,0\n1,1e8\n"
             "/NODE\n1,0,0,1.05\n/RBODY/1\nball\n1,,,,1\n0.001,0.001,0.001\n0,0,0\n"
             "/SURF/ELLIPS/1\nball\n0,2,1\n0,0,1.05\n0.05,0.05,0.05\n/SURF/PLANE/2\nfloor\n0,0,0\n0,0,1\n"
             "%s/INTER/TYPE6/1\nfloor\n         1         2\n"
             "                                                           0\n"
             "                   0         0         0         0         0\n"
             "         1         0                                                 0\n         0\n"
             "                             0         0                                     0.7\n"
             "/RUN\n3,0.01\n/END\n",
             gravity ? "/GRAV/1\ng\n0,Z,0,0,0,,1,-9.81\n" : "");
    rc_model *m = tu_compile_text(text, name, e);
    ENSURE(m != NULL);
    if (!m) fprintf(stderr, "  %s\n", e->msg);
    return m;
}

/* Settling (docs/theory.md 5.2): a ball bouncing with e = 0.7 under
 * gravity ends held in persistent contact, once, near the rigid Zeno time;
 * a settled contact's release root is off, and the mark goes with the
 * closed mode. */
static void test_restitution_settling(void)
{
    rc_error e;
    rc_model *m = settle_ball(1, "settle.rad", &e);
    if (!m) return;
    rc_run_options o = {0};
    rc_stats st;
    ENSURE(rc_run(m, &o, &st, &e) == RC_OK);
    /* t_inf = sqrt(2h/g) + 2 v1 e / (g (1 - e)), h = 1 m: 2.558634 s */
    const double h = 1.0, g = 9.81, v1 = sqrt(2 * g * h), tinf = sqrt(2 * h / g) + 2 * v1 * 0.7 / (g * 0.3);
    printf("    settled %ld time(s), at %.9f s (rigid Zeno time %.9f s)\n", st.settles, st.t_settle, tinf);
    ENSURE(st.settles == 1 && fabs(st.t_settle - tinf) < 1e-3 && st.t_end == 3.0);
    /* the release root of a settled closed contact is off */
    rc_data *d = rc_data_new(m);
    double *y = calloc((size_t)m->ny, sizeof(double)), *gr = calloc((size_t)rc_root_count(m), sizeof(double));
    rc_initial_state(m, y);
    y[m->body_yadr[0] + 2] = 0.049999 - m->origin[2]; /* 1 um deep (the model's coordinates) */
    y[m->body_yadr[0] + 9] = 0.5;    /* leaving fast: the force pulls */
    d->inter_mode[0] = RC_MODE_CLOSED;
    rc_assemble_roots(m, d, 0.0, y, gr);
    ENSURE(gr[RC_ROOT_FORCE] < 0);
    d->inter_settled[0] = 1;
    rc_assemble_roots(m, d, 0.0, y, gr);
    ENSURE(gr[RC_ROOT_FORCE] == 1.0 && gr[RC_ROOT_ZONE] > 0);
    /* separation at P = 0 (the zone root falling) opens it and clears the mark */
    int roots[64] = {0}, restart = 0;
    roots[RC_ROOT_ZONE] = -1;
    rc_event ev[4];
    ENSURE(rc_events_apply(m, d, 0.0, y, roots, ev, 4, &restart) == 1 && d->inter_mode[0] == RC_MODE_OPEN &&
           d->inter_settled[0] == 0);
    free(y);
    free(gr);
    rc_data_free(d);
    rc_model_free(m);
}

/* Bounces of settle_ball's contact in the history h at the state y (f
 * scratch): closes at tc[0..3], separations 3e-4 s after the first three
 * (contact phases of half the contact's period 2 pi sqrt(m / k) = 6.3e-4
 * s); the third of those openings of kind
 * `third` (a separation, or a release the fourth close reloads). Whether
 * the fourth close settled (the first three must not). */
static int settles_after_bounces(const rc_model *m, rc_data *d, rc_settle *h, const double *y, double *f,
                                 rc_event_kind third, const double tc[4])
{
    rc_event sev[4];
    char why[512] = "";
    int ns = 0, restart = 0, settled = 0;
    for (int k = 0; k < 4; k++) {
        d->inter_mode[0] = RC_MODE_CLOSED;
        const rc_event close = {0, RC_EV_CONTACT_CLOSE};
        restart = 0;
        ENSURE(rc_settle_after_events(h, m, d, tc[k], y, f, 0.01, &close, 1, sev, 4, &ns, &restart, why, sizeof why) ==
               RC_SETTLE_GO_ON);
        ENSURE(ns == restart && ns == d->inter_settled[0] && (ns == 0 || k == 3));
        if (ns) ENSURE(sev[0].inter == 0 && sev[0].kind == RC_EV_CONTACT_SETTLE);
        if (k == 3) {
            settled = ns;
            break;
        }
        d->inter_mode[0] = RC_MODE_OPEN;
        const rc_event sep = {0, k == 2 ? third : RC_EV_CONTACT_SEPARATE};
        ENSURE(rc_settle_after_events(h, m, d, tc[k] + 3e-4, y, f, 0.01, &sep, 1, sev, 4, &ns, &restart, why,
                                      sizeof why) == RC_SETTLE_GO_ON &&
               ns == 0);
    }
    return settled;
}

/* The engine's verdict after events (engine/events/settle.c): flights
 * shrinking twice in a row, the last shorter than the contact phase before
 * it, that phase one bounce and the flight ended by a load (gravity), settle
 * the closed contact; flights shrinking by a few percent do not; a reload of a contact released but never separated
 * is no landing; the same bounces without gravity (the ball's closing
 * speed, 1e-3 m/s, not turned by any load) do not; more than RC_ZENO_MAX
 * crowded events settle a closed contact when they are its contact events,
 * and end the run otherwise, with the message naming the element and the
 * last kind. */
static void test_restitution_settle_verdicts(void)
{
    rc_error e;
    rc_model *m = settle_ball(1, "settle_verdicts.rad", &e), *m0 = settle_ball(0, "settle_verdicts0.rad", &e);
    if (!m || !m0) {
        rc_model_free(m);
        rc_model_free(m0);
        return;
    }
    rc_data *d = rc_data_new(m), *d0 = rc_data_new(m0);
    rc_settle *h = rc_settle_new(m), *h0 = rc_settle_new(m0);
    double *y = calloc((size_t)m->ny, sizeof(double)), *f = calloc((size_t)m->ny, sizeof(double));
    ENSURE(d && h && d0 && h0 && y && f && m0->ny == m->ny);
    if (!d || !h || !d0 || !h0 || !y || !f) goto out;
    /* the ball approaching the floor at 1e-3 m/s: gravity over the last
     * flight (2e-4 s) gives 1.96e-3 m/s, beyond RC_SETTLE_LOAD times it */
    rc_initial_state(m, y);
    y[m->body_yadr[0] + 9] = -1e-3;
    /* flights 4e-3, 2e-3, 2e-4 s, the last shorter than the phase before it */
    const double tc[4] = {1.0, 1.0043, 1.0066, 1.0071};
    ENSURE(settles_after_bounces(m, d, h, y, f, RC_EV_CONTACT_SEPARATE, tc) == 1);
    ENSURE(settles_after_bounces(m0, d0, h0, y, f, RC_EV_CONTACT_SEPARATE, tc) == 0);
    /* flights 2.2e-4, 2.1e-4, 2.0e-4 s: shrinking by a few percent, a
     * steady motion rather than an accumulation (RC_SETTLE_RATIO) */
    rc_settle_free(h0);
    h0 = rc_settle_new(m);
    d->inter_settled[0] = 0;
    const double tw[4] = {1.0, 1.00052, 1.00103, 1.00153};
    ENSURE(h0 && settles_after_bounces(m, d, h0, y, f, RC_EV_CONTACT_SEPARATE, tw) == 0);
    /* the last "flight" a release that never separated: no landing */
    rc_settle_free(h0);
    h0 = rc_settle_new(m);
    d->inter_settled[0] = 0;
    ENSURE(h0 && settles_after_bounces(m, d, h0, y, f, RC_EV_CONTACT_OPEN, tc) == 0);
    rc_settle_free(h0);
    h0 = NULL;
    rc_event sev[4];
    char why[512] = "";
    int ns = 0, restart = 0;
    ENSURE(strstr(rc_settle_hold(m, 0), "penalty law"));
    /* crowded contact events of a closed contact: it settles */
    rc_settle_free(h);
    h = rc_settle_new(m);
    d->inter_settled[0] = 0;
    d->inter_mode[0] = RC_MODE_CLOSED;
    const rc_event open = {0, RC_EV_CONTACT_OPEN}, slip = {0, RC_EV_FRIC_SLIP};
    int go = 1;
    for (int k = 0; k <= RC_ZENO_MAX + 1; k++) {
        restart = 0;
        go &= rc_settle_after_events(h, m, d, 2.0, y, f, 0.01, &open, 1, sev, 4, &ns, &restart, why, sizeof why) ==
              RC_SETTLE_GO_ON;
        if (k < RC_ZENO_MAX + 1) go &= ns == 0 && !restart;
    }
    ENSURE(go && ns == 1 && restart && d->inter_settled[0] == 1 && sev[0].kind == RC_EV_CONTACT_SETTLE);
    /* crowded events of another kind: Zeno */
    rc_settle_free(h);
    h = rc_settle_new(m);
    go = 1;
    for (int k = 0; k < RC_ZENO_MAX + 1; k++)
        go &= rc_settle_after_events(h, m, d, 2.0, y, f, 0.01, &slip, 1, sev, 4, &ns, &restart, why, sizeof why) ==
              RC_SETTLE_GO_ON;
    ENSURE(go);
    ENSURE(rc_settle_after_events(h, m, d, 2.0, y, f, 0.01, &slip, 1, sev, 4, &ns, &restart, why, sizeof why) ==
           RC_SETTLE_ZENO);
    printf("    %s\n", why);
    ENSURE(strstr(why, "event accumulation (Zeno) at t = 2 s in ") && strstr(why, m->inter_name[0]) &&
           strstr(why, "more than 200 events within 2e-07 s of each other (last: fric_slip)"));
out:
    free(y);
    free(f);
    rc_settle_free(h);
    rc_settle_free(h0);
    rc_data_free(d);
    rc_data_free(d0);
    rc_model_free(m);
    rc_model_free(m0);
}

void suite_restitution(void);
void suite_restitution(void)
{
    RUN_TEST(test_restitution_settling);
    RUN_TEST(test_restitution_settle_verdicts);
    RUN_TEST(test_restitution_ode_matches_linear_closed_form);
    RUN_TEST(test_restitution_type6_nonlinear_asked);
    RUN_TEST(test_restitution_power_asked);
    RUN_TEST(test_restitution_errors);
}
