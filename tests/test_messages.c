/*
 * Messages: every entry of the state vector has a name (element, quantity,
 * unit) for the solver's failure messages, over decks that use every kind
 * of state (bodies, TYPE6 energies and hysteresis, friction with a filter,
 * couplings, imposed velocities).
 */
#include "harness.h"
#include "testutil.h"
#include "model/model.h"
#include "base/error.h"
#include "base/progress.h"

#include <time.h>

#include <stdio.h>
#include <string.h>
#include <unistd.h>
#include "engine/analyses/restitution.h"

static void check_names(const char *path)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(path, &c, &e) == RC_OK);
    if (c) ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    if (!m) {
        fprintf(stderr, "  %s: %s\n", path, e.msg);
        rc_case_free(c);
        return;
    }
    int unnamed = 0;
    for (int i = 0; i < m->ny; i++) {
        char name[200];
        rc_state_name(m, i, name, sizeof name);
        /* "<element>, <quantity> [<unit>]" */
        if (name[0] != '/' || !strstr(name, ", ") || !strchr(name, '[') || strstr(name, "own state")) {
            fprintf(stderr, "  %s: state %d named \"%s\"\n", path, i, name);
            unnamed++;
        }
    }
    ENSURE(unnamed == 0);
    char name[200];
    rc_state_name(m, m->ny, name, sizeof name); /* out of range: a plain index */
    ENSURE(strcmp(name, "state ") > 0 && strncmp(name, "state ", 6) == 0);
    rc_model_free(m);
    rc_case_free(c);
}

static void test_messages_state_names(void)
{
    check_names("cases/demo_sphere_drop.rad");
    check_names("validation/t6_unload_curve/case.rad");
    check_names("validation/frc_filter/case.rad");
    check_names("validation/cpl_catenary_swing/case.rad");
    check_names("validation/impvel_release/case.rad");
}

/* The demo deck with one substring replaced, compiled: the status and the
 * message of the first failure. */
static rc_status compile_variant(const char *from, const char *to, char *msg, size_t n)
{
    FILE *f = fopen("cases/demo_sphere_drop.rad", "rb");
    static char text[16384], out[16384];
    size_t len = f ? fread(text, 1, sizeof text - 1, f) : 0;
    if (f) fclose(f);
    text[len] = '\0';
    const char *at = strstr(text, from);
    if (!at) return RC_EINTERNAL;
    snprintf(out, sizeof out, "%.*s%s%s", (int)(at - text), text, to, at + strlen(from));
    char path[64];
    snprintf(path, sizeof path, "/tmp/rc_messages_%d.rad", (int)getpid());
    f = fopen(path, "wb");
    if (!f) return RC_EIO;
    fputs(out, f);
    fclose(f);
    rc_model *m = NULL;
    rc_error e;
    rc_status st = tu_load_compile(path, &m, &e);
    snprintf(msg, n, "%s", e.msg);
    rc_model_free(m);
    remove(path);
    return st;
}

/* A contact law beyond double precision is an input error naming the
 * interface and the fields: a penetration scale below the coordinates'
 * resolution, a time scale below the time's resolution. */
static void test_messages_unresolvable_scales(void)
{
    static char msg[8192];
    const char *curve = "                   1             1000000\n";
    /* k = 1e30 N/m: p_s = m g / k ~ 1e-29 m, far below ulp(0.2 m) */
    ENSURE(compile_variant(curve, "                   1              1e+30\n", msg, sizeof msg) == RC_EINPUT);
    ENSURE(strstr(msg, "card /INTER/TYPE6/1") && strstr(msg, "below the resolution of the coordinates") &&
           strstr(msg, "fct_ID"));
    /* a curve at the edge of the double range (1e308 N at 1 m) */
    ENSURE(compile_variant(curve, "                   1              1e+308\n", msg, sizeof msg) == RC_EINPUT);
    ENSURE(strstr(msg, "card /INTER/TYPE6/1") && strstr(msg, "below the resolution of the coordinates"));
    /* the demo itself is resolvable */
    ENSURE(compile_variant(curve, curve, msg, sizeof msg) == RC_OK);
    /* a run of 1e15 s against a contact time of 1e-3 s: time unresolvable
     * (an output interval of 1e9 s: 1e6 records, within RC_MAX_RECORDS) */
    ENSURE(compile_variant("                   1              0.0001\n", "               1e+15               1e+09\n", msg,
                           sizeof msg) == RC_EINPUT);
    ENSURE(strstr(msg, "card /INTER/TYPE6/1") && strstr(msg, "below the resolution of the time"));
}

/* Progress: silent by default and for short stages; a stage longer than
 * RC_PROGRESS_AFTER says so, with its name and time. */
static void test_messages_progress(void)
{
    FILE *f = tmpfile();
    ENSURE(f != NULL);
    if (!f) return;
    rc_progress_stage("short stage"); /* off: nothing */
    rc_progress_done();
    rc_set_progress(f);
    rc_progress_stage("short stage");
    rc_progress(1, 2);
    rc_progress_done();
    rc_progress_stage("long stage");
    struct timespec t0, t;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    long i = 0;
    do {
        rc_progress(i++, 0);
        clock_gettime(CLOCK_MONOTONIC, &t);
    } while ((double)(t.tv_sec - t0.tv_sec) + 1e-9 * (double)(t.tv_nsec - t0.tv_nsec) < 1.05 * RC_PROGRESS_AFTER);
    rc_progress_done();
    rc_set_progress(NULL);
    char text[4096] = "";
    rewind(f);
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    ENSURE(strstr(text, "short stage") == NULL);
    ENSURE(strstr(text, "ricochet: long stage: done in 1.") != NULL);
}

/* The restitution of a linear contact that cannot pull, printed by
 * `ricochet check`: no damping gives e = 1 after half a period; zeta =
 * 1/sqrt(2) leaves at maximum compression (theta = pi/2) with
 * e = exp(-pi/2); zeta = 0.1 gives the value of the Kelvin-Voigt contact
 * with a non-adhesive force (e = 0.744079, Schwager and Poschel 2007),
 * which validation/spring_dashpot also measures. */
static void test_messages_linear_restitution(void)
{
    const double pi = 3.14159265358979323846;
    double tau;
    ENSURE_NEAR(rc_linear_restitution(0.0, &tau), 1.0, 1e-15, 0);
    ENSURE_NEAR(tau, pi, 1e-15, 0);
    ENSURE_NEAR(rc_linear_restitution(1.0 / sqrt(2.0), &tau), exp(-pi / 2), 1e-12, 0);
    ENSURE_NEAR(tau, pi / sqrt(2.0), 1e-12, 0);
    ENSURE_NEAR(rc_linear_restitution(0.1, &tau), 0.744079, 1e-6, 0);
    ENSURE_NEAR(tau / 1000.0, 2.956075e-3, 1e-6, 0); /* k = 1e6 N/m, m = 1 kg */
    /* critical damping: x = tau e^-tau leaves at tau = 2 with e^-2; the
     * branches meet there */
    ENSURE_NEAR(rc_linear_restitution(1.0, &tau), exp(-2.0), 1e-15, 0);
    ENSURE_NEAR(tau, 2.0, 1e-15, 0);
    double t1, t2;
    ENSURE_NEAR(rc_linear_restitution(1.0 - 1e-7, &t1), exp(-2.0), 1e-6, 0);
    ENSURE_NEAR(rc_linear_restitution(1.0 + 1e-7, &t2), exp(-2.0), 1e-6, 0);
    ENSURE_NEAR(t1, 2.0, 1e-5, 0);
    ENSURE_NEAR(t2, 2.0, 1e-5, 0);
    /* overdamped, against a direct evaluation of x(tau) = (e^(a tau) -
     * e^(b tau))/(a - b): the force x + 2 zeta x' vanishes at tau */
    const double z = 2.0, q = sqrt(3.0), a = -z + q, b = -z - q;
    const double e = rc_linear_restitution(z, &tau);
    const double x = (exp(a * tau) - exp(b * tau)) / (a - b), xd = (a * exp(a * tau) - b * exp(b * tau)) / (a - b);
    ENSURE(fabs(x + 2 * z * xd) < 1e-15);
    ENSURE_NEAR(e, -xd, 1e-15, 0);
    ENSURE(e > 0 && e < exp(-2.0));
    ENSURE(isnan(rc_linear_restitution(-1.0, &tau)) && isnan(tau));
}

/* A restitution asked (TYPE6 e_target) replaces Visc: Visc 0 required,
 * a value in (0, 1], a linear load curve; the Visc derived gives it. */
static void test_messages_restitution_asked(void)
{
    static char msg[8192];
    const char *l6 = "       148.710194195         0         0\n";
    ENSURE(compile_variant(l6, "       148.710194195         0         0                                     0.5\n", msg,
                           sizeof msg) == RC_EINPUT);
    ENSURE(strstr(msg, "card /INTER/TYPE6/1, field e_target") && strstr(msg, "Visc = 0"));
    ENSURE(compile_variant(l6, "                   0         0         0                                     1.5\n", msg,
                           sizeof msg) == RC_EINPUT);
    ENSURE(strstr(msg, "field e_target") && strstr(msg, "(0, 1]"));
    ENSURE(compile_variant(l6, "                   0         0         0                                     0.5\n", msg,
                           sizeof msg) == RC_OK);
}

void suite_messages(void);
void suite_messages(void)
{
    RUN_TEST(test_messages_state_names);
    RUN_TEST(test_messages_unresolvable_scales);
    RUN_TEST(test_messages_progress);
    RUN_TEST(test_messages_linear_restitution);
    RUN_TEST(test_messages_restitution_asked);
}
