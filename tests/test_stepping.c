/* Stepping a session to times that the integrator passes over: single
 * steps while an impact or a stop is in progress, a root found after the
 * time asked for, the last step landing on the end time. Each rc_run_until
 * must stop at the time asked for, with the state interpolated there (what
 * `ricochet fit` relies on, docs/calibration.md). */
#include "harness.h"

#include <math.h>

#include "ricochet/ricochet.h"

/* a block launched at 1 m/s, stopped by Coulomb friction mu = 0.3 at
 * t = v0 / (mu g) = 0.34 s; the data times of the calibration example */
#define SLIDE "validation/fit_drop/slide.rad"
#define DROP "validation/fit_drop/drop.rad"

static rc_model *compile_rtol(const char *path, double rtol)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    if (rc_case_load(path, &c, &e) == RC_OK && rc_model_compile(c, &m, &e) == RC_OK) rc_model_set_rtol(m, rtol, &e);
    rc_case_free(c);
    return m;
}

/* every 5 ms to the end time (0.5 s): the stop at 0.34 s, the end */
static void test_stepping_friction_stop_every_time_served(void)
{
    rc_model *m = compile_rtol(SLIDE, 1e-9);
    ENSURE(m != NULL);
    if (!m) return;
    rc_session *s = NULL;
    rc_error e;
    rc_run_options opt = {0};
    ENSURE(rc_session_open(m, &opt, &s, &e) == RC_OK);
    const double g = 9.81, mu = 0.3, v0 = 1.0, tstop = v0 / (mu * g);
    int served = 0, exact = 0;
    double worst = 0.0;
    for (int i = 1; i <= 100; i++) {
        const double t = 0.005 * i;
        if (rc_run_until(s, t, &e) != RC_OK) break;
        served++;
        if (fabs(rc_session_time(s) - t) <= 1e-15) exact++;
        double b[13];
        rc_model_body_state(m, rc_session_state(s), 1, b, &e);
        /* rigid Coulomb before the stop (the stick spring relaxes the
         * block by F/K_t = 3e-6 m after it) */
        const double tc = fmin(t, tstop), x = v0 * tc - 0.5 * mu * g * tc * tc;
        worst = fmax(worst, fabs(b[0] - x));
    }
    ENSURE(served == 100);
    ENSURE(exact == 100);
    ENSURE(worst < 1e-5);
    ENSURE(rc_session_close(s, NULL, &e) == RC_OK);
    rc_model_free(m);
}

/* the drop: an impact of 21 ms (single steps) between two data times 2 ms
 * apart, and data times that a root follows within one step */
static void test_stepping_impact_every_time_served(void)
{
    rc_model *m = compile_rtol(DROP, 1e-9);
    ENSURE(m != NULL);
    if (!m) return;
    rc_session *s = NULL;
    rc_error e;
    rc_run_options opt = {0};
    ENSURE(rc_session_open(m, &opt, &s, &e) == RC_OK);
    int served = 0;
    double zmin = 1.0;
    for (int i = 1; i <= 500; i++) {
        const double t = 0.001 * i;
        if (rc_run_until(s, t, &e) != RC_OK || fabs(rc_session_time(s) - t) > 1e-15) break;
        double b[13];
        rc_model_body_state(m, rc_session_state(s), 1, b, &e);
        zmin = fmin(zmin, b[2]);
        served++;
    }
    ENSURE(served == 500);
    /* the deepest sample: near the peak penetration 0.0138 m below R = 0.05 m */
    ENSURE_NEAR(zmin, 0.05 - 0.013804, 0, 1e-4); /* sampled every 1 ms */
    ENSURE(rc_session_close(s, NULL, &e) == RC_OK);
    rc_model_free(m);
}

void suite_stepping(void);
void suite_stepping(void)
{
    RUN_TEST(test_stepping_friction_stop_every_time_served);
    RUN_TEST(test_stepping_impact_every_time_served);
}
