/*
 * rc_time: time ricochet's integration alone, through the public API.
 *
 *   rc_time CASE [REPEAT [T_END]]
 *
 * Loads and compiles CASE once, then runs it REPEAT times (default 1) with
 * no output file (rc_run_options.output_path = NULL), so that the wall time
 * is the integration only, comparable with bench/explicit_ref, which also
 * times its loop without I/O. Prints key=value lines: the statistics of the
 * fastest run, the load and compile times, and the peak RSS of this process
 * (meaningful when started through bench/peakrss, see bench/README.md).
 * T_END > 0 replaces the case's end time (used to measure the memory of a
 * long run from a short one: the solver allocates everything at the start).
 * A run that ends in an error (status=failed, the error's exit code; e.g. a
 * static analysis whose load passes what friction can hold, the end the
 * static stick-slip benchmark asks for) is timed as well, at every repeat.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "ricochet/ricochet.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of this process (user + system) [s]: less sensitive than the
 * wall time to other jobs on a shared machine */
static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 4) {
        fprintf(stderr, "usage: rc_time CASE [REPEAT [T_END]]\n");
        return 2;
    }
    const int repeat = argc >= 3 ? atoi(argv[2]) : 1;
    const double t_end = argc == 4 ? atof(argv[3]) : 0.0;
    rc_error e;
    memset(&e, 0, sizeof e);
    rc_case *c = NULL;
    rc_model *m = NULL;
    double t0 = now();
    if (rc_case_load(argv[1], &c, &e)) {
        fprintf(stderr, "rc_time: %s\n", e.msg);
        return rc_status_exit_code(e.code);
    }
    double t1 = now();
    if (rc_model_compile(c, &m, &e)) {
        fprintf(stderr, "rc_time: %s\n", e.msg);
        return rc_status_exit_code(e.code);
    }
    double t2 = now();
    rc_stats best;
    memset(&best, 0, sizeof best);
    int status = 0;
    double best_cpu = 0.0; /* the least CPU time of the runs (rc_run whole, set-up included) */
    for (int k = 0; k < (repeat > 0 ? repeat : 1); k++) {
        rc_run_options opt;
        memset(&opt, 0, sizeof opt);
        opt.t_end_override = t_end;
        rc_stats s;
        const double c0 = cpu_now();
        rc_status st = rc_run(m, &opt, &s, &e);
        const double cpu = cpu_now() - c0;
        if (st) {
            /* a run that ends in an error (e.g. a static analysis whose load passes what friction can hold,
             * the end a benchmark asks for) is timed as well: the same error at every repeat */
            if (k == 0) fprintf(stderr, "rc_time: %s\n", e.msg);
            status = rc_status_exit_code(st);
        }
        if (k == 0 || s.wall_time < best.wall_time) best = s;
        if (k == 0 || cpu < best_cpu) best_cpu = cpu;
    }
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    printf("status=%s\n", status ? "failed" : "ok");
    printf("load_time=%.9e\ncompile_time=%.9e\n", t1 - t0, t2 - t1);
    printf("steps=%ld\nrhs_evals=%ld\njac_evals=%ld\nlin_setups=%ld\nnonlin_iters=%ld\n", best.steps, best.rhs_evals,
           best.jac_evals, best.lin_setups, best.nonlin_iters);
    printf("nonlin_fails=%ld\nerr_test_fails=%ld\nroot_evals=%ld\nevents=%ld\nreinits=%ld\n", best.nonlin_fails,
           best.err_test_fails, best.root_evals, best.events, best.reinits);
    printf("t_end=%.12e\nwall_time=%.9e\nenergy_residual=%.9e\npeak_rss_kb=%ld\n", best.t_end, best.wall_time,
           best.energy_residual, ru.ru_maxrss);
    printf("cpu_time=%.9e\n", best_cpu);
    rc_model_free(m);
    rc_case_free(c);
    return status;
}
