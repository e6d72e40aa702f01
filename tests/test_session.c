/* The event callback, stepping (rc_session, rc_run_until), rc_model_set_rtol
 * and the end time of a run, on the demo case and a case with a time
 * breakpoint. */
#include "harness.h"

#include <netcdf.h>
#include <stdlib.h>
#include <unistd.h>

#include "model/model.h"
#include "ricochet/ricochet.h"

#define DEMO "cases/demo_sphere_drop.rad"
#define IMPVEL "validation/impvel_release/case.rad"
#define JOINTS "validation/joint_double_pendulum/case.rad"

static rc_model *compile(const char *path)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    if (rc_case_load(path, &c, &e) == RC_OK) rc_model_compile(c, &m, &e);
    rc_case_free(c);
    return m;
}

static void tmp_path(char *buf, size_t n, const char *tag)
{
    snprintf(buf, n, "/tmp/rc_test_session_%ld_%s.nc", (long)getpid(), tag);
}

static size_t nc_events(const char *path, char *complete, size_t ncomplete, char *status, size_t nstatus)
{
    int ncid, dim;
    size_t n = (size_t)-1;
    complete[0] = status[0] = '\0';
    if (nc_open(path, NC_NOWRITE, &ncid) != NC_NOERR) return n;
    if (nc_inq_dimid(ncid, "event", &dim) == NC_NOERR) nc_inq_dimlen(ncid, dim, &n);
    size_t len = 0;
    if (nc_inq_attlen(ncid, NC_GLOBAL, "complete", &len) == NC_NOERR && len < ncomplete) {
        nc_get_att_text(ncid, NC_GLOBAL, "complete", complete);
        complete[len] = '\0';
    }
    if (nc_inq_attlen(ncid, NC_GLOBAL, "status", &len) == NC_NOERR && len < nstatus) {
        nc_get_att_text(ncid, NC_GLOBAL, "status", status);
        status[len] = '\0';
    }
    nc_close(ncid);
    return n;
}

typedef struct counter {
    long n, stop_at, impvel;
    double last_t;
    int ordered, finite;
} counter;

static int count_events(void *user, double t, const char *kind, const char *element, const double v[3])
{
    counter *c = user;
    c->n++;
    if (t < c->last_t) c->ordered = 0;
    c->last_t = t;
    if (!strcmp(kind, "impvel_stop")) c->impvel++;
    else if (!(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) || strncmp(element, "/INTER/", 7)) c->finite = 0;
    return c->stop_at > 0 && c->n >= c->stop_at;
}

/* One callback per row of the events table, in time order. */
static void test_session_callback_counts_equal_events_table(void)
{
    const char *cases[] = {DEMO, IMPVEL};
    for (int k = 0; k < 2; k++) {
        rc_model *m = compile(cases[k]);
        ENSURE(m != NULL);
        if (!m) continue;
        char path[256], complete[16], status[512];
        tmp_path(path, sizeof path, "count");
        counter c = {0, 0, 0, -1.0, 1, 1};
        rc_run_options opt = {.output_path = path, .on_event = count_events, .user = &c};
        rc_stats st;
        rc_error e;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
        const size_t rows = nc_events(path, complete, sizeof complete, status, sizeof status);
        printf("    %s: %ld callbacks, %zu rows in the events table, %ld events\n", cases[k], c.n, rows, st.events);
        ENSURE(c.n > 0 && (size_t)c.n == rows && c.n == st.events);
        ENSURE(c.ordered && c.finite);
        ENSURE(k == 0 || c.impvel == 1);
        ENSURE(!strcmp(complete, "yes"));
        /* without an output file the callback still sees every event */
        counter c2 = {0, 0, 0, -1.0, 1, 1};
        rc_run_options opt2 = {.on_event = count_events, .user = &c2};
        ENSURE(rc_run(m, &opt2, NULL, &e) == RC_OK && c2.n == c.n);
        unlink(path);
        rc_model_free(m);
    }
}

/* A non-zero return stops the run after that event: the file keeps what was
 * computed, marked incomplete with the reason; RC_EINTERRUPT. */
static void test_session_callback_stops_run(void)
{
    rc_model *m = compile(DEMO);
    ENSURE(m != NULL);
    if (!m) return;
    char path[256], complete[16], status[512];
    tmp_path(path, sizeof path, "stop");
    counter c = {0, 3, 0, -1.0, 1, 1};
    rc_run_options opt = {.output_path = path, .on_event = count_events, .user = &c};
    rc_stats st;
    rc_error e;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_EINTERRUPT);
    ENSURE(strstr(e.msg, "stopped by the event callback at t = ") != NULL);
    const size_t rows = nc_events(path, complete, sizeof complete, status, sizeof status);
    printf("    stopped: %s; %zu events in the file, t_end %.6g s; status \"%s\"\n", e.msg, rows, st.t_end, status);
    ENSURE(c.n == 3 && rows == 3);
    ENSURE(st.t_end > 0 && st.t_end < rc_model_t_end(m));
    ENSURE(!strcmp(complete, "no") && strstr(status, "stopped by the event callback") != NULL);
    unlink(path);
    rc_model_free(m);
}

/* rc_run_until in pieces ending on output times gives the run of one
 * rc_run: same final state, bit for bit, same statistics and records. */
static void test_session_run_until_pieces_equal_one_run(void)
{
    /* on both backends (method 1 CVODE, 2 IDA), and a model with joints */
    const char *cases[] = {DEMO, IMPVEL, DEMO, IMPVEL, JOINTS};
    const int method[] = {1, 1, 2, 2, 2};
    for (int k = 0; k < 5; k++) {
        rc_model *m = compile(cases[k]);
        ENSURE(m != NULL);
        if (!m) continue;
        rc_error em;
        ENSURE(rc_model_set_method(m, method[k], &em) == RC_OK);
        const int ny = rc_model_state_size(m);
        double *y1 = calloc((size_t)ny, sizeof(double)), *y2 = calloc((size_t)ny, sizeof(double));
        char p1[256], p2[256], complete[16], status[512];
        tmp_path(p1, sizeof p1, "one");
        tmp_path(p2, sizeof p2, "pieces");
        rc_run_options o1 = {.output_path = p1, .y_end = y1};
        rc_stats s1, s2;
        rc_error e;
        ENSURE(rc_run(m, &o1, &s1, &e) == RC_OK);
        rc_run_options o2 = {.output_path = p2, .y_end = y2};
        rc_session *s = NULL;
        ENSURE(rc_session_open(m, &o2, &s, &e) == RC_OK && s != NULL);
        if (!s) continue;
        ENSURE(rc_session_time(s) == 0.0 && !rc_session_finished(s));
        const double tend = rc_model_t_end(m), dt = rc_model_dt_out(m);
        int pieces = 0, monotone = 1;
        double tprev = 0.0;
        /* 7 pieces on output times, then past the end */
        for (int j = 1; j <= 7; j++) {
            const double target = (double)(long)((j * tend / 8.0) / dt) * dt;
            ENSURE(rc_run_until(s, target, &e) == RC_OK);
            ENSURE_NEAR(rc_session_time(s), target, 0, 1e-15);
            monotone &= rc_session_time(s) >= tprev;
            tprev = rc_session_time(s);
            pieces++;
        }
        /* a time not on an output: the state is there */
        const double tmid = tprev + 0.37 * dt;
        ENSURE(rc_run_until(s, tmid, &e) == RC_OK && rc_session_time(s) == tmid);
        ENSURE(rc_run_until(s, tmid - dt, &e) == RC_OK && rc_session_time(s) == tmid); /* backwards: nothing */
        ENSURE(rc_run_until(s, 2.0 * tend, &e) == RC_OK);
        ENSURE(rc_session_finished(s) && rc_session_time(s) == tend);
        ENSURE(monotone);
        ENSURE(rc_session_close(s, &s2, &e) == RC_OK);
        ENSURE(memcmp(y1, y2, (size_t)ny * sizeof(double)) == 0);
        ENSURE(s1.steps == s2.steps && s1.events == s2.events && s1.rhs_evals == s2.rhs_evals &&
               s1.reinits == s2.reinits && s1.t_end == s2.t_end);
        const size_t r1 = nc_events(p1, complete, sizeof complete, status, sizeof status);
        const size_t r2 = nc_events(p2, complete, sizeof complete, status, sizeof status);
        ENSURE(r1 == r2 && !strcmp(complete, "yes"));
        printf("    %s (method %d): %d pieces + 1 off the output times: %ld steps, %ld events (one run: %ld, %ld), "
               "final state %s\n",
               cases[k], method[k], pieces, s2.steps, s2.events, s1.steps, s1.events,
               memcmp(y1, y2, (size_t)ny * sizeof(double)) ? "differs" : "identical");
        unlink(p1);
        unlink(p2);
        free(y1);
        free(y2);
        rc_model_free(m);
    }
}

/* Closing a session before the end time stops the run there: the file is
 * marked incomplete with the reason. */
static void test_session_close_early(void)
{
    rc_model *m = compile(DEMO);
    ENSURE(m != NULL);
    if (!m) return;
    char path[256], complete[16], status[512];
    tmp_path(path, sizeof path, "early");
    rc_run_options opt = {.output_path = path};
    rc_session *s = NULL;
    rc_error e;
    rc_stats st;
    ENSURE(rc_session_open(m, &opt, &s, &e) == RC_OK);
    ENSURE(rc_run_until(s, 0.3, &e) == RC_OK);
    const double *y = rc_session_state(s);
    ENSURE(y != NULL && isfinite(y[2]));
    ENSURE(rc_session_close(s, &st, &e) == RC_EINTERRUPT);
    ENSURE(strstr(e.msg, "stopped by the caller at t = ") != NULL);
    nc_events(path, complete, sizeof complete, status, sizeof status);
    ENSURE(!strcmp(complete, "no") && strstr(status, "stopped by the caller") != NULL);
    ENSURE(st.t_end >= 0.3 && st.t_end < rc_model_t_end(m));
    ENSURE(rc_session_close(NULL, NULL, NULL) == RC_OK);
    /* a run that cannot start: the open fails with its status, no session */
    rc_run_options bad = {.output_path = "/nonexistent_dir_rc_test/x.nc"};
    rc_session *s2 = (rc_session *)&bad;
    ENSURE(rc_session_open(m, &bad, &s2, &e) == RC_EIO && s2 == NULL && strstr(e.msg, "nonexistent_dir_rc_test"));
    unlink(path);
    rc_model_free(m);
}

/* A run ends exactly at its end time (a stop time for the integrator), with
 * an overridden end time and output interval too. */
static void test_session_end_time_exact(void)
{
    const char *cases[] = {DEMO, IMPVEL};
    for (int k = 0; k < 2; k++) {
        rc_model *m = compile(cases[k]);
        ENSURE(m != NULL);
        if (!m) continue;
        rc_stats st;
        rc_error e;
        rc_run_options o = {0};
        ENSURE(rc_run(m, &o, &st, &e) == RC_OK);
        ENSURE(st.t_end == rc_model_t_end(m));
        const double te = 0.7 * rc_model_t_end(m) + 1.234e-5;
        rc_run_options o2 = {.t_end_override = te, .dt_out_override = 0.013};
        ENSURE(rc_run(m, &o2, &st, &e) == RC_OK);
        ENSURE(st.t_end == te);
        printf("    %s: end time %.17g s reached exactly; override %.17g s too\n", cases[k], rc_model_t_end(m), te);
        rc_model_free(m);
    }
}

/* rc_model_set_rtol: the derived absolute tolerances scale with rtol, the
 * ones given on /SOLVER stay; bad values refused, the model unchanged. */
static void test_session_set_rtol(void)
{
    rc_model *m = compile(DEMO); /* /SOLVER with Atol given */
    /* the demo without its /SOLVER card: every tolerance derived */
    char nosolver[256];
    snprintf(nosolver, sizeof nosolver, "/tmp/rc_test_session_%ld_nosolver.rad", (long)getpid());
    FILE *in = fopen(DEMO, "r"), *outf = fopen(nosolver, "w");
    char line[512];
    int skip = 0;
    while (in && outf && fgets(line, sizeof line, in)) {
        if (line[0] == '/') skip = !strncmp(line, "/SOLVER", 7);
        if (!skip) fputs(line, outf);
    }
    if (in) fclose(in);
    if (outf) fclose(outf);
    rc_model *d = compile(nosolver);
    unlink(nosolver);
    ENSURE(m != NULL && d != NULL);
    if (!m || !d) {
        rc_model_free(m);
        rc_model_free(d);
        return;
    }
    rc_error e;
    const double r0 = rc_model_rtol(m);
    double *a0 = malloc((size_t)m->ny * sizeof(double));
    memcpy(a0, m->atol, (size_t)m->ny * sizeof(double));
    ENSURE(rc_model_set_rtol(m, 1e-4, &e) == RC_OK && rc_model_rtol(m) == 1e-4);
    int same = 1;
    for (int k = 0; k < m->ny; k++) same &= m->atol[k] == a0[k] || !(m->tol_auto);
    ENSURE(same || m->tol_auto);
    const double bad[] = {0.0, -1e-6, 1.0, NAN, INFINITY};
    for (int k = 0; k < 5; k++) ENSURE(rc_model_set_rtol(m, bad[k], &e) == RC_EINPUT && rc_model_rtol(m) == 1e-4);
    (void)r0;
    free(a0);
    /* derived tolerances: each scales with rtol */
    const double rd = rc_model_rtol(d);
    double *b0 = malloc((size_t)d->ny * sizeof(double));
    memcpy(b0, d->atol, (size_t)d->ny * sizeof(double));
    ENSURE(rc_model_set_rtol(d, rd * 100.0, &e) == RC_OK);
    int scaled = 0, fixed = 0;
    for (int k = 0; k < d->ny; k++) {
        const double ratio = d->atol[k] / b0[k];
        if (fabs(ratio - 100.0) < 1e-9 * 100.0) scaled++;
        else if (ratio == 1.0) fixed++;
    }
    printf("    demo without /SOLVER: rtol %.3g -> %.3g: %d of %d absolute tolerances scaled by 100, %d kept\n", rd, rd * 100.0, scaled,
           d->ny, fixed);
    ENSURE(d->tol_auto != 0 && scaled > 0 && scaled + fixed == d->ny);
    rc_stats st;
    rc_run_options o = {0};
    ENSURE(rc_run(d, &o, &st, &e) == RC_OK);
    free(b0);
    rc_model_free(m);
    rc_model_free(d);
}

void suite_session(void);
void suite_session(void)
{
    RUN_TEST(test_session_callback_counts_equal_events_table);
    RUN_TEST(test_session_callback_stops_run);
    RUN_TEST(test_session_run_until_pieces_equal_one_run);
    RUN_TEST(test_session_close_early);
    RUN_TEST(test_session_end_time_exact);
    RUN_TEST(test_session_set_rtol);
}
