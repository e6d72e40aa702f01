/* ricochet command-line program: run, check, --help (also per command), --version. */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "ricochet/ricochet.h"
#include "cli/fit.h"
#include "cli/sens.h"

/* --set options on one command line (docs/case-format.md) */
#define RC_CLI_MAX_SET 256

static void usage(FILE *f)
{
    fprintf(f,
            "usage: ricochet run CASE [-o OUT.nc] [-q] [--t-end T] [--dt-out DT] [--rtol R] [--method M]\n"
            "                         [--preload | --no-preload] [--switch | --no-switch] [--on-violation stop|warn]\n"
            "                         [--set CARD:FIELD=VALUE]...\n"
            "                                            run a case, write results (default: CASE stem + .nc)\n"
            "       ricochet check CASE [--set CARD:FIELD=VALUE]...\n"
            "                                            read and compile a case, print the model summary\n"
            "       ricochet export-vtk RESULTS.nc [-o DIR] [--dt T | --every N] [--ascii]\n"
            "                                            ParaView files (.pvd + binary .vtp)\n"
            "       ricochet fit CASE --data FILE.csv --free CARD:FIELD=START[,LO:HI]... [--log ...] [-o REPORT]\n"
            "                                            calibrate fields to measured signals (least squares)\n"
            "       ricochet sens CASE --param CARD:FIELD=VALUE... --at T[,T...] [--out ID:Q]... [--check-fd]\n"
            "                                            derivatives of body states w.r.t. fields (sensitivities)\n"
            "       ricochet study CASE --grid FILE [--scheduler ADDRESS] [-o STUDY.nc] ...\n"
            "                                            a parameter study on Dask (the Python module)\n"
            "       ricochet COMMAND --help              the options of a command\n"
            "       ricochet --help | --version\n"
            "exit codes: 0 success, 2 input error, 3 solver failure, 4 I/O error, 5 physics check failed,\n"
            "            129 hung up (SIGHUP), 130 interrupted (SIGINT), 143 terminated (SIGTERM)\n");
}

static void usage_run(FILE *f)
{
    fprintf(f,
            "usage: ricochet run CASE [options]\n"
            "Read and compile the case (Radioss block format), integrate it from t = 0 to its end time and\n"
            "write the results (netCDF-4, docs/output-format.md).\n"
            "options (in any position, before or after CASE; --opt VALUE or --opt=VALUE; a long option\n"
            "may be shortened to a unique prefix):\n"
            "  -o OUT.nc      results file (default: the case file's name with .nc, in the current directory)\n"
            "  -q             quiet: no progress on stderr, no summary on stdout\n"
            "  --t-end T      end time [s], instead of the case's /RUN Tend\n"
            "  --dt-out DT    output interval [s], instead of the case's /RUN Dt_out\n"
            "  --rtol R       relative tolerance, instead of /SOLVER Rtol; the absolute tolerances derived\n"
            "                 from the model's scales (blank /SOLVER fields) follow it\n"
            "  --method M     integration backend, instead of /SOLVER Method: cvode (1), ida (2) or static (3:\n"
            "                 equilibrium at each output time, KINSOL); a model with joints runs on ida only\n"
            "  --preload      start the dynamic run from the static equilibrium under the loads at t = 0\n"
            "                 (instead of /SOLVER Preload): positions, orientations and the friction forces of\n"
            "                 the closed contacts solved by KINSOL, every body at rest; the model must be in the\n"
            "                 static analysis' scope with no initial velocity (exit code 2 otherwise, naming the\n"
            "                 card); nothing more with --method static\n"
            "  --no-preload   start from the deck's positions even when /SOLVER Preload is 1\n"
            "  --switch       method switching (instead of /SOLVER Switch; cvode only): BDF hands over to an\n"
            "                 explicit Runge-Kutta method (ARKODE ERKStep) while impacts hold its step near the\n"
            "                 explicit stability limit, and takes over again when the contacts rest\n"
            "  --no-switch    BDF throughout even when /SOLVER Switch is 1\n"
            "  --on-violation stop|warn\n"
            "                 what a failed physics check does (energy created, a dissipation decreasing, bodies\n"
            "                 passing through each other, non-finite values): stop ends the run there with exit\n"
            "                 code 5, warn records it (results file, summary, stderr) and goes on; default: the\n"
            "                 deck's /RUN On_viol, else stop\n"
            "  --set CARD:FIELD=VALUE\n"
            "                 set a numeric field of a card by its name, as if VALUE were typed into the deck\n"
            "                 (the card's units, its checks and defaults; repeatable), e.g.\n"
            "                 --set /INTER/TYPE6/1:Fric=0.3 --set /RBODY/2:Mass=1.5; FIELD[k] for the k-th\n"
            "                 occurrence of a field the card repeats; names in any case (docs/case-format.md,\n"
            "                 \"Setting fields from the command line\"); recorded in the results file (overrides)\n"
            "  -h, --help     this text\n"
            "T, DT and R are positive finite numbers (R below 1); T and DT in seconds (SI, as the deck is\n"
            "read: a deck naming its units is converted to SI; one naming none is used as written); T / DT\n"
            "may give at most 10000000 records. OUT.nc may not be the case file nor a file it includes.\n"
            "Progress (unless -q): one line updated on a terminal, a line every 10 s in a log, with the time\n"
            "remaining estimated from the rate of simulated time.\n"
            "SIGHUP, SIGINT, SIGTERM: the run stops at its next step, the results file is closed with what\n"
            "was computed, marked incomplete (\"interrupted at t = ...\"); a second signal kills at once.\n"
            "Every run checks its own physics (docs/theory.md, \"Physics checks of every run\"); the summary\n"
            "says whether the checks passed and which contacts never closed, stayed closed or settled.\n"
            "exit codes: 0 success, 2 input error, 3 solver failure, 4 I/O error, 5 physics check failed\n"
            "            (results kept, their status \"physics check failed: ...\"), 129 hung up (SIGHUP),\n"
            "            130 interrupted (SIGINT), 143 terminated (SIGTERM)\n");
}

static void usage_check(FILE *f)
{
    fprintf(f,
            "usage: ricochet check CASE\n"
            "Read and compile the case and print the model summary (bodies, surfaces, interfaces, couplings,\n"
            "state size, solver settings); warnings of the reading on stderr. Nothing is run.\n"
            "options (in any position; --set VALUE or --set=VALUE):\n"
            "  -q             no progress of the long stages on stderr\n"
            "  --set CARD:FIELD=VALUE\n"
            "                 set a numeric field of a card by its name, as if VALUE were typed into the deck\n"
            "                 (repeatable; as for run)\n"
            "  -h, --help     this text\n"
            "exit codes: 0 the case is valid, 2 input error (file:line, card and field), 4 I/O error\n");
}

static void version(void)
{
    printf("ricochet %s (commit %s)\n", rc_version(), rc_build_commit());
    rc_print_versions(stdout);
}

/* A positive finite number for option `opt`; 0 and a message on stderr
 * otherwise. */
static int positive(const char *opt, const char *text, double *v)
{
    char *end = NULL;
    double x = text ? strtod(text, &end) : 0.0;
    if (!text || end == text || *end != '\0' || !isfinite(x) || !(x > 0)) {
        fprintf(stderr, "ricochet: %s: expected a positive finite number, got '%s'\n", opt, text ? text : "");
        return 0;
    }
    *v = x;
    return 1;
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

/* Load (with the --set overrides) and compile; prints the error and returns
 * its exit code on failure. */
static int load(const char *path, const char *const *set, int nset, rc_case **c, rc_model **m, rc_error *e)
{
    if (rc_case_load_set(path, set, nset, c, e)) return fail(e);
    for (int i = 0; i < rc_case_warning_count(*c); i++)
        fprintf(stderr, "ricochet: warning: %s\n", rc_case_warning(*c, i));
    if (rc_model_compile(*c, m, e)) return fail(e);
    for (int i = 0; i < rc_model_note_count(*m); i++) fprintf(stderr, "ricochet: warning: %s\n", rc_model_note(*m, i));
    return 0;
}

/* Set by SIGHUP, SIGINT or SIGTERM; the run polls it (rc_run_options.stop). */
static volatile sig_atomic_t stop_requested = 0;

static void on_signal(int sig)
{
    stop_requested = sig; /* non-zero; the exit code is 128 + sig */
}

static void usage_export(FILE *f)
{
    fprintf(f,
            "usage: ricochet export-vtk RESULTS.nc [options]\n"
            "Write a ParaView time series of a results file: DIR/<stem>.pvd and, per frame, one VTK XML\n"
            "PolyData file of the bodies (surfaces tessellated, their velocities) and one of the contacts\n"
            "(points with force vectors, the events since the previous frame) (docs/output-format.md).\n"
            "Values in SI units (m, m/s, N, s), as in the results file.\n"
            "options (in any order after RESULTS.nc):\n"
            "  -o DIR         where to write (created when missing; default: the results' stem + _vtk)\n"
            "  --dt T         one frame per T seconds at most: the first record at or after each multiple\n"
            "                 of T, and the last\n"
            "  --every N      every N-th record (records 0, N, 2N, ...; N = 1: every record, the event\n"
            "                 records included); not with --dt\n"
            "                 default (neither): the records at the output times (/RUN Dt_out, not the\n"
            "                 event records), at most %d frames: when there are more, one per T s,\n"
            "                 T the smallest 1, 2 or 5 x 10^k s giving at most %d; and the last record\n"
            "  --ascii        ASCII data arrays instead of appended raw binary (larger and slower to\n"
            "                 write and read; to read the files by eye)\n"
            "  -h, --help     this text\n"
            "prints the frames written, the size in MB (10^6 bytes) and the frame interval chosen.\n"
            "exit codes: 0 success, 2 usage error, 4 I/O error (a file that cannot be read or written)\n",
            RC_VTK_DEFAULT_MAX_FRAMES, RC_VTK_DEFAULT_MAX_FRAMES);
}

/* ricochet export-vtk RESULTS.nc [-o DIR] [--dt T | --every N] [--ascii] (docs/output-format.md). */
static int export_vtk(int argc, char **argv)
{
    const char *in = NULL, *dir = NULL;
    rc_vtk_options o = {0};
    for (int k = 2; k < argc; k++) {
        const char *a = argv[k];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage_export(stdout);
            return 0;
        }
        if (!strcmp(a, "--ascii")) {
            o.ascii = 1;
            continue;
        }
        if (!strcmp(a, "-o") || !strcmp(a, "--dt") || !strcmp(a, "--every")) {
            if (k + 1 >= argc) {
                fprintf(stderr, "ricochet export-vtk: %s needs a value\n", a);
                usage_export(stderr);
                return 2;
            }
            if (!strcmp(a, "-o")) {
                dir = argv[++k];
                continue;
            }
            char *end = NULL;
            errno = 0;
            if (!strcmp(a, "--every")) {
                const long v = strtol(argv[++k], &end, 10);
                if (!end || *end || end == argv[k] || errno || v < 1 || v > 1000000000L) {
                    fprintf(stderr, "ricochet export-vtk: --every %s: expected a whole number of records >= 1\n",
                            argv[k]);
                    return 2;
                }
                o.every = (int)v;
                continue;
            }
            o.dt = strtod(argv[++k], &end);
            if (!end || *end || end == argv[k] || !(o.dt > 0) || !isfinite(o.dt)) {
                fprintf(stderr, "ricochet export-vtk: --dt %s: expected a positive number of seconds\n", argv[k]);
                return 2;
            }
            continue;
        }
        if (a[0] == '-' || in) {
            fprintf(stderr, "ricochet export-vtk: unexpected argument %s\n", a);
            usage_export(stderr);
            return 2;
        }
        in = a;
    }
    if (!in) {
        fprintf(stderr, "ricochet export-vtk: no results file given\n");
        usage_export(stderr);
        return 2;
    }
    if (o.dt > 0 && o.every > 0) {
        fprintf(stderr, "ricochet export-vtk: --dt and --every together; expected one of them\n");
        return 2;
    }
    char def[1024];
    const char *b = strrchr(in, '/'), *dot = strrchr(b ? b + 1 : in, '.');
    snprintf(def, sizeof def, "%.*s_vtk", (int)(dot && dot != (b ? b + 1 : in) ? dot - (b ? b + 1 : in) : 1000),
             b ? b + 1 : in);
    rc_error e;
    rc_vtk_result r;
    if (rc_export_vtk_opts(in, dir ? dir : def, &o, &r, &e)) return fail(&e);
    char how[96] = "";
    if (r.dt_used > 0) snprintf(how, sizeof how, ", one per %g s (default)", r.dt_used);
    else if (o.dt <= 0 && o.every <= 0) snprintf(how, sizeof how, ", the output times (default)");
    printf("ricochet %s: %s -> %s/ (%d frames, %d files, %.3g MB %s%s)\n", rc_version(), in, dir ? dir : def, r.frames,
           2 * r.frames + 1, r.bytes / 1e6, o.ascii ? "ASCII" : "binary", how);
    return 0;
}

/* `ricochet study ...`: the Python module's study runner, `python3 -m
 * ricochet study ...` (docs/python.md), which runs the cases on Dask. The
 * program in a build directory of a source tree (python/ricochet beside
 * it, one level up) puts that tree's module first on PYTHONPATH and, unless
 * RICOCHET_LIB is set, names its own shared library; an installed program
 * leaves both to python3 (the module installed with it finds the installed
 * library). The interpreter: RICOCHET_PYTHON, else Debian's /usr/bin/python3
 * (where scripts/install-deps.sh puts numpy, xarray and Dask). Returns only
 * when it cannot be started (exit code 2). */
static int study(int argc, char **argv)
{
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    char *slash = n > 0 ? (exe[n] = '\0', strrchr(exe, '/')) : NULL;
    if (slash) {
        *slash = '\0';
        char py[4200], probe[4300], lib[4200];
        snprintf(py, sizeof py, "%s/../python", exe);
        snprintf(probe, sizeof probe, "%s/ricochet/__init__.py", py);
        if (access(probe, R_OK) == 0) {
            const char *old = getenv("PYTHONPATH");
            char path[8400];
            snprintf(path, sizeof path, "%s%s%s", py, old && *old ? ":" : "", old && *old ? old : "");
            setenv("PYTHONPATH", path, 1);
            snprintf(lib, sizeof lib, "%s/libricochet.so", exe);
            if (!getenv("RICOCHET_LIB") && access(lib, R_OK) == 0) setenv("RICOCHET_LIB", lib, 1);
        }
    }
    char **av = calloc((size_t)argc + 3, sizeof *av);
    if (!av) {
        fprintf(stderr, "ricochet: study: out of memory\n");
        return 2;
    }
    const char *python = getenv("RICOCHET_PYTHON") && *getenv("RICOCHET_PYTHON") ? getenv("RICOCHET_PYTHON") : "/usr/bin/python3";
    av[0] = (char *)python;
    av[1] = "-m";
    av[2] = "ricochet";
    for (int k = 1; k < argc; k++) av[2 + k] = argv[k]; /* "study" and its arguments */
    execv(python, av);
    fprintf(stderr, "ricochet: study: cannot start %s (%s): the studies run in ricochet's Python module "
                    "(docs/python.md; RICOCHET_PYTHON names another interpreter)\n",
            python, strerror(errno));
    free(av);
    return 2;
}

/* The long options of run and check (main); `check` takes --set, -q and
 * --help only. */
enum { O_TEND = 256, O_DTOUT, O_RTOL, O_METHOD, O_ONVIOL, O_SET, O_PRELOAD, O_NOPRELOAD, O_SWITCH, O_NOSWITCH };
static const struct option run_opts[] = {
    {"t-end", required_argument, NULL, O_TEND},          {"dt-out", required_argument, NULL, O_DTOUT},
    {"rtol", required_argument, NULL, O_RTOL},            {"method", required_argument, NULL, O_METHOD},
    {"on-violation", required_argument, NULL, O_ONVIOL}, {"set", required_argument, NULL, O_SET},
    {"preload", no_argument, NULL, O_PRELOAD},            {"no-preload", no_argument, NULL, O_NOPRELOAD},
    {"switch", no_argument, NULL, O_SWITCH},              {"no-switch", no_argument, NULL, O_NOSWITCH},
    {"help", no_argument, NULL, 'h'},                     {"quiet", no_argument, NULL, 'q'},
    {"output", required_argument, NULL, 'o'},             {NULL, 0, NULL, 0}};
static const struct option check_opts[] = {{"set", required_argument, NULL, O_SET},
                                            {"help", no_argument, NULL, 'h'},
                                            {"quiet", no_argument, NULL, 'q'},
                                            {NULL, 0, NULL, 0}};

/* "unknown option" for arg, with the closest of the command's long options
 * (rc_closest_name), or, given to check, the run option it names. */
static void unknown_option(const char *cmd, const char *arg, const struct option *lo)
{
    char name[128];
    const char *p = arg;
    while (*p == '-') p++;
    snprintf(name, sizeof name, "%s", p);
    char *eq = strchr(name, '=');
    if (eq) *eq = '\0';
    const char *cand[16];
    int n = 0;
    for (; lo[n].name && n < 16; n++) cand[n] = lo[n].name;
    const char *best = rc_closest_name(name, cand, n);
    int of_run = !strcmp(name, "o");
    for (int k = 0; run_opts[k].name && lo != run_opts; k++) of_run |= !strcmp(name, run_opts[k].name);
    if (best) fprintf(stderr, "ricochet %s: unknown option '%s': did you mean --%s?\n", cmd, arg, best);
    else if (of_run) fprintf(stderr, "ricochet %s: option '%s' is an option of `ricochet run`\n", cmd, arg);
    else fprintf(stderr, "ricochet %s: unknown option '%s'\n", cmd, arg);
}

/* An option given without its value. */
static void option_needs_value(const char *cmd, const char *arg)
{
    (void)cmd;
    fprintf(stderr, "ricochet: %s: expected %s\n", arg,
            !strcmp(arg, "--set")                                            ? "CARD:FIELD=VALUE (e.g. /INTER/TYPE6/1:Fric=0.3)"
            : !strcmp(arg, "-o") || !strcmp(arg, "--output")                 ? "an output file name"
            : !strcmp(arg, "--method")                                       ? "cvode, ida or static (or 1, 2, 3)"
            : !strcmp(arg, "--on-violation")                                 ? "stop or warn"
                                                                             : "a positive finite number");
}

int main(int argc, char **argv)
{
    /* SIGHUP (the terminal closed), SIGINT, SIGTERM: end the run at the next
     * step, close the results file with what it computed (a second signal
     * kills at once). SIGHUP ignored when the program starts (nohup) stays
     * ignored; SIGINT is handled even when ignored at the start (a job in
     * the background of a script starts with it ignored) */
    struct sigaction sa, old;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sa.sa_flags = SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    if (sigaction(SIGHUP, NULL, &old) == 0 && old.sa_handler != SIG_IGN) sigaction(SIGHUP, &sa, NULL);
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    if (!strcmp(argv[1], "--version")) {
        version();
        return 0;
    }
    if (!strcmp(argv[1], "export-vtk")) return export_vtk(argc, argv);
    if (!strcmp(argv[1], "study")) return study(argc, argv);
    if (!strcmp(argv[1], "fit")) return rc_cli_fit(argc, argv);
    if (!strcmp(argv[1], "sens")) return rc_cli_sens(argc, argv);
    const char *cmd = argv[1], *case_path = NULL, *out = NULL;
    const int is_run = !strcmp(cmd, "run");
    if (!is_run && strcmp(cmd, "check")) {
        fprintf(stderr, "ricochet: unknown command '%s'\n", cmd);
        usage(stderr);
        return 2;
    }
    int quiet = 0, method = 0, on_violation = 0, preload = -1, method_switch = -1, nset = 0;
    const char *set[RC_CLI_MAX_SET]; /* the --set arguments, in order */
    double t_end = 0.0, dt_out = 0.0, rtol = 0.0;
    /* options in any position (getopt_long permutes them in front of the
     * case file), --opt VALUE or --opt=VALUE */
    const struct option *lo = is_run ? run_opts : check_opts;
    char **av = argv + 1; /* the command as argv[0] of getopt */
    const int ac = argc - 1;
    opterr = 0; /* the messages below, with a suggestion */
    optind = 1;
    int ch;
    while ((ch = getopt_long(ac, av, is_run ? ":o:qh" : ":qh", lo, NULL)) != -1) {
        switch (ch) {
        case O_TEND:
        case O_DTOUT:
        case O_RTOL: {
            const char *nm = ch == O_TEND ? "--t-end" : ch == O_DTOUT ? "--dt-out" : "--rtol";
            if (!positive(nm, optarg, ch == O_TEND ? &t_end : ch == O_DTOUT ? &dt_out : &rtol)) return 2;
            break;
        }
        case O_METHOD:
            method = !strcmp(optarg, "cvode") || !strcmp(optarg, "1")    ? 1
                     : !strcmp(optarg, "ida") || !strcmp(optarg, "2")    ? 2
                     : !strcmp(optarg, "static") || !strcmp(optarg, "3") ? 3
                                                                         : -1;
            if (method < 0) {
                fprintf(stderr, "ricochet: --method: expected cvode, ida or static (or 1, 2, 3), got %s\n", optarg);
                return 2;
            }
            break;
        case O_ONVIOL:
            on_violation = !strcmp(optarg, "stop") ? RC_ON_VIOLATION_STOP : !strcmp(optarg, "warn") ? RC_ON_VIOLATION_WARN : -1;
            if (on_violation < 0) {
                fprintf(stderr, "ricochet: --on-violation: expected stop or warn, got %s\n", optarg);
                return 2;
            }
            break;
        case O_SET:
            if (nset == RC_CLI_MAX_SET) {
                fprintf(stderr, "ricochet: --set %s: at most %d --set options\n", optarg, RC_CLI_MAX_SET);
                return 2;
            }
            set[nset++] = optarg;
            break;
        case O_PRELOAD:
        case O_NOPRELOAD: preload = ch == O_PRELOAD; break;
        case O_SWITCH:
        case O_NOSWITCH: method_switch = ch == O_SWITCH; break;
        case 'o': out = optarg; break;
        case 'q': quiet = 1; break;
        case 'h':
            if (is_run) usage_run(stdout);
            else usage_check(stdout);
            return 0;
        case ':': /* an option without its value */
            option_needs_value(cmd, av[optind - 1]);
            return 2;
        default: /* '?': unknown or ambiguous */
            unknown_option(cmd, av[optind - 1], lo);
            if (is_run) usage_run(stderr);
            else usage_check(stderr);
            return 2;
        }
    }
    for (int k = optind; k < ac; k++) {
        if (case_path) {
            fprintf(stderr, "ricochet %s: unexpected argument '%s' (one case file, %s given first)\n", cmd, av[k],
                    case_path);
            if (is_run) usage_run(stderr);
            else usage_check(stderr);
            return 2;
        }
        case_path = av[k];
    }
    if (rtol >= 1.0) {
        fprintf(stderr, "ricochet: --rtol: expected a relative tolerance below 1, got %g\n", rtol);
        return 2;
    }
    if (!case_path) {
        fprintf(stderr, "ricochet %s: no case file given\n", cmd);
        if (is_run) usage_run(stderr);
        else usage_check(stderr);
        return 2;
    }
    if (!quiet) rc_set_progress(stderr);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    memset(&e, 0, sizeof e);
    int rc = load(case_path, set, nset, &c, &m, &e);
    /* overrides, after the compile: the derived tolerances follow --rtol */
    if (rc == 0 && rtol > 0 && rc_model_set_rtol(m, rtol, &e)) rc = fail(&e);
    if (rc == 0 && preload == 0 && rc_model_set_preload(m, 0, &e)) rc = fail(&e);
    if (rc == 0 && method > 0 && rc_model_set_method(m, method, &e)) rc = fail(&e);
    if (rc == 0 && preload == 1 && rc_model_set_preload(m, 1, &e)) rc = fail(&e);
    if (rc == 0 && method_switch >= 0 && rc_model_set_switch(m, method_switch, &e)) rc = fail(&e);
    char *def = NULL;
    if (rc == 0 && is_run && !out && !(def = default_output(case_path))) {
        fprintf(stderr, "ricochet: out of memory\n");
        rc = rc_status_exit_code(RC_ENOMEM);
    }
    if (rc == 0 && !is_run) rc_model_print_summary(m, stdout);
    if (rc == 0 && is_run) {
        /* the library refuses an output that names an input, and options
         * out of range (RC_EINPUT, nothing run or written) */
        rc_run_options opt = {.output_path = out ? out : def, .progress = !quiet, .t_end_override = t_end,
                              .dt_out_override = dt_out, .stop = &stop_requested, .on_violation = on_violation};
        rc_stats s;
        rc_status st = rc_run(m, &opt, &s, &e);
        if (!quiet && st != RC_EINPUT) {
            printf("ricochet %s: %s -> %s\n", rc_version(), case_path, opt.output_path);
            rc_stats_print(&s, stdout);
        }
        /* a run spent following undamped contact vibrations: said even
         * with -q (rc_stats_print says it otherwise) */
        if (quiet && st == RC_OK && s.vibration_note[0]) fprintf(stderr, "ricochet: note: %s\n", s.vibration_note);
        if (quiet && st == RC_OK && s.tolerance_note[0]) fprintf(stderr, "ricochet: note: %s\n", s.tolerance_note);
        /* violations the run went on after (on-violation warn): never in silence */
        if (st == RC_OK && s.violations > 0)
            fprintf(stderr, "ricochet: warning: physics checks: %s (all of them in the violation table of %s)\n",
                    s.physics_note, opt.output_path);
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
