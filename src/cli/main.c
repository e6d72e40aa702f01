/* ricochet command-line program: run, check, --help, --version. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "ricochet/ricochet.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: ricochet run CASE [-o OUT.nc] [-q]   run a case, write results (default: CASE stem + .nc)\n"
            "       ricochet check CASE                  read and compile a case, print the model summary\n"
            "       ricochet --help | --version\n"
            "exit codes: 0 success, 2 input error, 3 solver failure, 4 I/O error\n");
}

/* Default output: the case file name with its extension replaced by .nc, in
 * the current directory. */
static char *default_output(const char *case_path)
{
    const char *base = strrchr(case_path, '/');
    base = base ? base + 1 : case_path;
    size_t n = strlen(base);
    const char *dot = strrchr(base, '.');
    if (dot && dot != base) n = (size_t)(dot - base);
    char *o = malloc(n + 4);
    if (!o) return NULL;
    memcpy(o, base, n);
    strcpy(o + n, ".nc");
    return o;
}

static int fail(const rc_error *e)
{
    fprintf(stderr, "ricochet: %s: %s\n", rc_status_str(e->code), e->msg);
    return rc_status_exit_code(e->code);
}

/* Load and compile; prints the error and returns its exit code on failure. */
static int load(const char *path, rc_case **c, rc_model **m, rc_error *e)
{
    if (rc_case_load(path, c, e)) return fail(e);
    for (int i = 0; i < rc_case_warning_count(*c); i++)
        fprintf(stderr, "ricochet: warning: %s\n", rc_case_warning(*c, i));
    if (rc_model_compile(*c, m, e)) return fail(e);
    return 0;
}

/* Set by SIGINT or SIGTERM; the run polls it (rc_run_options.stop). */
static volatile sig_atomic_t stop_requested = 0;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

int main(int argc, char **argv)
{
    /* SIGINT, SIGTERM: end the run at the next step, keep what it computed
     * (a second signal kills at once) */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("ricochet %s\n", rc_version());
        return 0;
    }
    const char *cmd = argv[1], *case_path = NULL, *out = NULL;
    int quiet = 0;
    for (int k = 2; k < argc; k++) {
        if (!strcmp(argv[k], "-o") && k + 1 < argc) out = argv[++k];
        else if (!strcmp(argv[k], "-q")) quiet = 1;
        else if (argv[k][0] == '-' || case_path) {
            fprintf(stderr, "ricochet: unexpected argument '%s'\n", argv[k]);
            usage(stderr);
            return 2;
        } else case_path = argv[k];
    }
    if (!case_path || (strcmp(cmd, "run") && strcmp(cmd, "check"))) {
        usage(stderr);
        return 2;
    }
    /* never write the results over the case file itself */
    struct stat sin, sout;
    if (out && !strcmp(cmd, "run") && stat(case_path, &sin) == 0 && stat(out, &sout) == 0 &&
        sin.st_dev == sout.st_dev && sin.st_ino == sout.st_ino) {
        fprintf(stderr, "ricochet: the output file '%s' is the case file '%s': refusing to overwrite the input "
                        "(give another -o path)\n",
                out, case_path);
        return 2;
    }
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    memset(&e, 0, sizeof e);
    int rc = load(case_path, &c, &m, &e);
    if (rc == 0 && !strcmp(cmd, "check")) rc_model_print_summary(m, stdout);
    if (rc == 0 && !strcmp(cmd, "run")) {
        char *def = out ? NULL : default_output(case_path);
        rc_run_options opt = {out ? out : def, !quiet, 0.0, NULL, &stop_requested};
        rc_stats s;
        rc_status st = rc_run(m, &opt, &s, &e);
        if (!quiet) {
            printf("ricochet %s: %s -> %s\n", rc_version(), case_path, opt.output_path);
            rc_stats_print(&s, stdout);
        }
        if (st) rc = fail(&e);
        free(def);
    }
    rc_model_free(m);
    rc_case_free(c);
    return rc;
}
