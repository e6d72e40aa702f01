/* ricochet command-line program: run, check, --help, --version. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "ricochet/ricochet.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: ricochet run CASE [-o OUT.nc] [-q]   run a case, write results (default: CASE stem + .nc)\n"
            "       ricochet check CASE                  read and compile a case, print the model summary\n"
            "       ricochet export-vtk RESULTS.nc [-o DIR]  ParaView files (.pvd + .vtp; default DIR: stem_vtk)\n"
            "       ricochet --help | --version\n"
            "exit codes: 0 success, 2 input error, 3 solver failure, 4 I/O error,\n"
            "            130 interrupted (SIGINT), 143 terminated (SIGTERM)\n");
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

/* The results must never overwrite an input: the output path may not be the
 * case file nor any file it includes (same device and inode). Exit code 2. */
static int check_output_path(const rc_case *c, const char *out)
{
    struct stat so;
    if (!out || stat(out, &so) != 0) return 0; /* a new file overwrites nothing */
    for (int i = 0; i < rc_case_file_count(c); i++) {
        struct stat si;
        if (stat(rc_case_file(c, i), &si) == 0 && si.st_dev == so.st_dev && si.st_ino == so.st_ino) {
            fprintf(stderr,
                    "ricochet: the output file '%s' is the input file '%s'%s: refusing to overwrite an input "
                    "(give another -o path)\n",
                    out, rc_case_file(c, i), i == 0 ? " (the case file)" : " (included by the case)");
            return 2;
        }
    }
    return 0;
}

/* Set by SIGINT or SIGTERM; the run polls it (rc_run_options.stop). */
static volatile sig_atomic_t stop_requested = 0;

static void on_signal(int sig)
{
    stop_requested = sig; /* non-zero; the exit code is 128 + sig */
}

/* ricochet export-vtk RESULTS.nc [-o DIR] (docs/output-format.md). */
static int export_vtk(int argc, char **argv)
{
    const char *in = argc > 2 ? argv[2] : NULL, *dir = argc == 5 && !strcmp(argv[3], "-o") ? argv[4] : NULL;
    if (!in || in[0] == '-' || (argc != 3 && !dir)) {
        usage(stderr);
        return 2;
    }
    char def[1024];
    const char *b = strrchr(in, '/'), *dot = strrchr(b ? b + 1 : in, '.');
    snprintf(def, sizeof def, "%.*s_vtk", (int)(dot && dot != (b ? b + 1 : in) ? dot - (b ? b + 1 : in) : 1000),
             b ? b + 1 : in);
    rc_error e;
    int n = 0;
    if (rc_export_vtk(in, dir ? dir : def, &n, &e)) return fail(&e);
    printf("ricochet %s: %s -> %s/ (%d records)\n", rc_version(), in, dir ? dir : def, n);
    return 0;
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
    if (!strcmp(argv[1], "export-vtk")) return export_vtk(argc, argv);
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
    if (!quiet) rc_set_progress(stderr);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    memset(&e, 0, sizeof e);
    int rc = load(case_path, &c, &m, &e);
    char *def = NULL;
    if (rc == 0 && !strcmp(cmd, "run")) {
        def = out ? NULL : default_output(case_path);
        rc = check_output_path(c, out ? out : def);
    }
    if (rc == 0 && !strcmp(cmd, "check")) rc_model_print_summary(m, stdout);
    if (rc == 0 && !strcmp(cmd, "run")) {
        rc_run_options opt = {out ? out : def, !quiet, 0.0, NULL, &stop_requested};
        rc_stats s;
        rc_status st = rc_run(m, &opt, &s, &e);
        if (!quiet) {
            printf("ricochet %s: %s -> %s\n", rc_version(), case_path, opt.output_path);
            rc_stats_print(&s, stdout);
        }
        if (st == RC_EINTERRUPT && stop_requested > 0) {
            fprintf(stderr, "ricochet: %s: %s\n", rc_status_str(e.code), e.msg);
            rc = 128 + (int)stop_requested;
        } else if (st) {
            rc = fail(&e);
        }
    }
    free(def);
    rc_model_free(m);
    rc_case_free(c);
    if (rc_output_abandoned()) {
        /* after a failed write HDF5's exit-time clean-up would crash */
        fflush(NULL);
        _exit(rc);
    }
    return rc;
}
