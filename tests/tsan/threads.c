/*
 * ThreadSanitizer test of the library (make tsan): two threads each read,
 * compile and run their own simulation writing their own results file,
 * while a third thread steps a session opened by the main thread (its
 * worker thread writing a third file), all at the same time. Built with
 * -fsanitize=thread together with the library; any ThreadSanitizer report
 * makes the run exit non-zero (scripts/tsan.sh). The results files are
 * then read back (after every thread ended) and compared with each other.
 *   threads DECK TMPDIR
 *
 * netCDF and HDF5 are not built for ThreadSanitizer, so it cannot see their
 * memory. HDF5 keeps library-wide state that every call reads and writes
 * (it is built without thread safety); that state is made visible here:
 * the program is linked with -Wl,--wrap for every netCDF function the
 * library calls (scripts/tsan.sh checks the list against the library's
 * undefined symbols), and each wrapper writes one shared variable before
 * calling the real function. Two netCDF calls at once in two threads, i.e.
 * a call outside the library's netCDF lock, are then a data race that
 * ThreadSanitizer reports.
 */
#include <netcdf.h>
#include <netcdf_mem.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ricochet/ricochet.h"
#include "../ncrecords.h"

/* ---- HDF5's library-wide state, as ThreadSanitizer sees it ---------------- */

static unsigned long hdf5_state; /* written by every netCDF call */

#define WRAP(ret, name, params, args)                                                                    \
    ret __real_##name params;                                                                            \
    ret __wrap_##name params;                                                                            \
    ret __wrap_##name params                                                                             \
    {                                                                                                    \
        hdf5_state++;                                                                                    \
        return __real_##name args;                                                                       \
    }

/* The list that scripts/tsan.sh compares with the library's netCDF symbols
 * (one WRAP per line, the name second). */
WRAP(int, nc_close, (int a), (a))
WRAP(int, nc_create, (const char *a, int b, int *c), (a, b, c))
WRAP(int, nc_def_dim, (int a, const char *b, size_t c, int *d), (a, b, c, d))
WRAP(int, nc_def_var, (int a, const char *b, nc_type c, int d, const int *e, int *f), (a, b, c, d, e, f))
WRAP(int, nc_def_var_chunking, (int a, int b, int c, const size_t *d), (a, b, c, d))
WRAP(int, nc_def_var_fill, (int a, int b, int c, const void *d), (a, b, c, d))
WRAP(int, nc_enddef, (int a), (a))
WRAP(int, nc_free_string, (size_t a, char **b), (a, b))
WRAP(int, nc_get_att, (int a, int b, const char *c, void *d), (a, b, c, d))
WRAP(int, nc_get_att_string, (int a, int b, const char *c, char **d), (a, b, c, d))
WRAP(int, nc_get_att_text, (int a, int b, const char *c, char *d), (a, b, c, d))
WRAP(int, nc_get_var_double, (int a, int b, double *c), (a, b, c))
WRAP(int, nc_get_var_int, (int a, int b, int *c), (a, b, c))
WRAP(int, nc_get_var_string, (int a, int b, char **c), (a, b, c))
WRAP(int, nc_get_vara, (int a, int b, const size_t *c, const size_t *d, void *e), (a, b, c, d, e))
WRAP(int, nc_get_vara_double, (int a, int b, const size_t *c, const size_t *d, double *e), (a, b, c, d, e))
WRAP(int, nc_get_vara_int, (int a, int b, const size_t *c, const size_t *d, int *e), (a, b, c, d, e))
WRAP(int, nc_get_vara_string, (int a, int b, const size_t *c, const size_t *d, char **e), (a, b, c, d, e))
WRAP(int, nc_inq_att, (int a, int b, const char *c, nc_type *d, size_t *e), (a, b, c, d, e))
WRAP(int, nc_inq_attlen, (int a, int b, const char *c, size_t *d), (a, b, c, d))
WRAP(int, nc_inq_attname, (int a, int b, int c, char *d), (a, b, c, d))
WRAP(int, nc_inq_dimid, (int a, const char *b, int *c), (a, b, c))
WRAP(int, nc_inq_dimlen, (int a, int b, size_t *c), (a, b, c))
WRAP(const char *, nc_inq_libvers, (void), ())
WRAP(int, nc_inq_natts, (int a, int *b), (a, b))
WRAP(int, nc_inq_nvars, (int a, int *b), (a, b))
WRAP(int, nc_inq_type, (int a, nc_type b, char *c, size_t *d), (a, b, c, d))
WRAP(int, nc_inq_unlimdims, (int a, int *b, int *c), (a, b, c))
WRAP(int, nc_inq_var, (int a, int b, char *c, nc_type *d, int *e, int *f, int *g), (a, b, c, d, e, f, g))
WRAP(int, nc_inq_varid, (int a, const char *b, int *c), (a, b, c))
WRAP(int, nc_inq_varnatts, (int a, int b, int *c), (a, b, c))
WRAP(int, nc_open, (const char *a, int b, int *c), (a, b, c))
WRAP(int, nc_open_memio, (const char *a, int b, NC_memio *c, int *d), (a, b, c, d))
WRAP(int, nc_put_att_double, (int a, int b, const char *c, nc_type d, size_t e, const double *f), (a, b, c, d, e, f))
WRAP(int, nc_put_att_int, (int a, int b, const char *c, nc_type d, size_t e, const int *f), (a, b, c, d, e, f))
WRAP(int, nc_put_att_longlong, (int a, int b, const char *c, nc_type d, size_t e, const long long *f),
     (a, b, c, d, e, f))
WRAP(int, nc_put_att_text, (int a, int b, const char *c, size_t d, const char *e), (a, b, c, d, e))
WRAP(int, nc_put_var_double, (int a, int b, const double *c), (a, b, c))
WRAP(int, nc_put_var_int, (int a, int b, const int *c), (a, b, c))
WRAP(int, nc_put_var_string, (int a, int b, const char **c), (a, b, c))
WRAP(int, nc_put_vara, (int a, int b, const size_t *c, const size_t *d, const void *e), (a, b, c, d, e))
WRAP(int, nc_put_vara_double, (int a, int b, const size_t *c, const size_t *d, const double *e), (a, b, c, d, e))
WRAP(int, nc_put_vara_int, (int a, int b, const size_t *c, const size_t *d, const int *e), (a, b, c, d, e))
WRAP(int, nc_put_vara_string, (int a, int b, const size_t *c, const size_t *d, const char **e), (a, b, c, d, e))
WRAP(int, nc_redef, (int a), (a))
WRAP(int, nc_sync, (int a), (a))

#define T_END 0.3 /* [s] of the demo: two impacts */

typedef struct job {
    const char *deck;
    char out[512];
    rc_status st;
    rc_stats stats;
    char msg[512];
} job;

/* Read, compile and run one simulation, all in this thread. */
static void *run_one(void *arg)
{
    job *j = arg;
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    j->st = rc_case_load(j->deck, &c, &e);
    if (j->st == RC_OK) j->st = rc_model_compile(c, &m, &e);
    if (j->st == RC_OK) {
        rc_run_options opt = {.output_path = j->out, .t_end_override = T_END};
        j->st = rc_run(m, &opt, &j->stats, &e);
    }
    if (j->st) snprintf(j->msg, sizeof j->msg, "%.500s", e.msg);
    rc_model_free(m);
    rc_case_free(c);
    return NULL;
}

typedef struct stepper {
    rc_session *s;
    rc_status st;
    int pieces;
} stepper;

/* Step a session opened by another thread, in pieces of 10 ms. */
static void *step(void *arg)
{
    stepper *p = arg;
    rc_error e;
    for (int k = 1; p->st == RC_OK && !rc_session_finished(p->s); k++) {
        p->st = rc_run_until(p->s, 0.01 * k, &e);
        p->pieces++;
    }
    return NULL;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: threads DECK TMPDIR\n");
        return 2;
    }
    int fail = 0;
    job a = {.deck = argv[1]}, b = {.deck = argv[1]};
    snprintf(a.out, sizeof a.out, "%s/tsan_a.nc", argv[2]);
    snprintf(b.out, sizeof b.out, "%s/tsan_b.nc", argv[2]);
    char sess_out[512];
    snprintf(sess_out, sizeof sess_out, "%s/tsan_session.nc", argv[2]);

    /* the session: read, compiled and opened here, stepped by a thread */
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_session *s = NULL;
    rc_error e;
    rc_run_options opt = {.output_path = sess_out, .t_end_override = T_END};
    if (rc_case_load(argv[1], &c, &e) || rc_model_compile(c, &m, &e) || rc_session_open(m, &opt, &s, &e)) {
        fprintf(stderr, "FAIL tsan.setup: %s\n", e.msg);
        return 1;
    }
    stepper p = {s, RC_OK, 0};
    pthread_t ta, tb, ts;
    if (pthread_create(&ta, NULL, run_one, &a) || pthread_create(&tb, NULL, run_one, &b) ||
        pthread_create(&ts, NULL, step, &p)) {
        fprintf(stderr, "FAIL tsan.threads: cannot start the threads\n");
        return 1;
    }
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    pthread_join(ts, NULL);
    rc_stats ss;
    const rc_status sc = rc_session_close(s, &ss, &e);
    rc_model_free(m);
    rc_case_free(c);

    char ca[8], cb[8], cs[8];
    const long na = tu_nc_records(a.out, ca, sizeof ca), nb = tu_nc_records(b.out, cb, sizeof cb),
               ns = tu_nc_records(sess_out, cs, sizeof cs);
    if (a.st || b.st) {
        printf("FAIL tsan.two_runs: statuses %d, %d: %s %s\n", a.st, b.st, a.msg, b.msg);
        fail = 1;
    } else if (na < 2 || na != nb || strcmp(ca, "yes") || strcmp(cb, "yes") || a.stats.steps != b.stats.steps) {
        printf("FAIL tsan.two_runs: the two files differ: %ld and %ld records, complete %s and %s, %ld and %ld "
               "steps\n", na, nb, ca, cb, a.stats.steps, b.stats.steps);
        fail = 1;
    } else
        printf("PASS tsan.two_runs: two runs in two threads, two files of %ld records each, complete, %ld steps "
               "each\n", na, a.stats.steps);
    if (p.st || sc || ns < 2 || strcmp(cs, "yes") || ss.t_end != a.stats.t_end) {
        printf("FAIL tsan.session_other_thread: statuses %d, %d, %ld records, complete %s, end %.9g s (runs: "
               "%.9g s)\n", p.st, sc, ns, cs, ss.t_end, a.stats.t_end);
        fail = 1;
    } else
        printf("PASS tsan.session_other_thread: %d pieces stepped from another thread to %.9g s, %ld records, "
               "complete\n", p.pieces, ss.t_end, ns);
    return fail;
}
