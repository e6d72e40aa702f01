/* The library's contract at its boundary (include/ricochet/ricochet.h): the
 * results never overwrite an input, NULL arguments are refused, a callback
 * cannot wait for itself, run options are checked as deck values are, a
 * named pipe is never opened for reading, a failed write is reported as
 * what the file keeps, values whose products overflow are refused. */
#include "harness.h"
#include "testutil.h"
#include "ncrecords.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <netcdf.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "ricochet/ricochet.h"

#define DEMO "cases/demo_sphere_drop.rad"
/* a deadlock or a blocking open would hang the run: end it instead [s] */
#define HANG_LIMIT 120

/* ---- helpers ------------------------------------------------------------- */

/* The whole file (NUL-terminated, malloc'd) and its length; NULL: unreadable. */
static char *slurp(const char *path, size_t *n)
{
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    char *b = malloc(1 << 20);
    size_t k = b ? fread(b, 1, (1 << 20) - 1, f) : 0;
    fclose(f);
    if (b) b[k] = '\0';
    if (n) *n = k;
    return b;
}

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    fputs(text, f);
    return fclose(f);
}

/* The demo deck with `from` replaced by `to` (the first occurrence), written
 * to `path`; 0 on success. */
static int demo_variant(const char *path, const char *from, const char *to)
{
    char *t = slurp(DEMO, NULL);
    char *at = t ? strstr(t, from) : NULL;
    if (!at) {
        free(t);
        return -1;
    }
    FILE *f = fopen(path, "wb");
    if (!f) {
        free(t);
        return -1;
    }
    fprintf(f, "%.*s%s%s", (int)(at - t), t, to, at + strlen(from));
    free(t);
    return fclose(f);
}

/* The line (1-based) of the first line of `path` that starts with `prefix`. */
static int line_of(const char *path, const char *prefix)
{
    char *t = slurp(path, NULL);
    int line = 0, found = 0;
    for (char *p = t; p && *p && !found;) {
        line++;
        found = !strncmp(p, prefix, strlen(prefix));
        char *nl = strchr(p, '\n');
        p = nl ? nl + 1 : NULL;
    }
    free(t);
    return found ? line : -1;
}

static int same_file_bytes(const char *a, const char *b)
{
    size_t na = 0, nb = 0;
    char *x = slurp(a, &na), *y = slurp(b, &nb);
    const int same = x && y && na == nb && !memcmp(x, y, na);
    free(x);
    free(y);
    return same;
}

static rc_model *compile(const char *path, rc_error *e)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    if (rc_case_load(path, &c, e) == RC_OK) rc_model_compile(c, &m, e);
    rc_case_free(c);
    return m;
}

static void make_dir(char *dir)
{
    snprintf(dir, 64, "/tmp/rc_contract_XXXXXX");
    if (!mkdtemp(dir)) dir[0] = '\0';
}

static void remove_dir(const char *dir)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (dir[0] && system(cmd) != 0) fprintf(stderr, "  cannot remove %s\n", dir);
}

/* ---- the results never overwrite an input -------------------------------- */

/* The output path names the case file (as given, another spelling, a
 * symbolic link, a hard link, after the working directory changed) or a
 * file it includes: RC_EINPUT, nothing run, the input unchanged. */
static void test_contract_output_never_an_input(void)
{
    char dir[64], deck[128], orig[128], out[192], inc_main[128], inc_run[128], inc_orig[128];
    make_dir(dir);
    ENSURE(dir[0] != '\0');
    if (!dir[0]) return;
    snprintf(deck, sizeof deck, "%s/deck.rad", dir);
    snprintf(orig, sizeof orig, "%s/deck.orig", dir);
    ENSURE(demo_variant(deck, "/RUN", "/RUN") == 0 && demo_variant(orig, "/RUN", "/RUN") == 0);
    rc_error e;
    rc_model *m = compile(deck, &e);
    ENSURE(m != NULL);
    if (!m) return;
    char slink[128], hard[128];
    snprintf(slink, sizeof slink, "%s/link.nc", dir);
    snprintf(hard, sizeof hard, "%s/hard.nc", dir);
    ENSURE(symlink("deck.rad", slink) == 0 && link(deck, hard) == 0);
    const char *spell[4] = {deck, NULL, slink, hard};
    char dotted[160];
    snprintf(dotted, sizeof dotted, "%s/./deck.rad", dir);
    spell[1] = dotted;
    for (int k = 0; k < 4; k++) {
        rc_run_options opt = {.output_path = spell[k]};
        rc_stats st;
        st.steps = -1;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_EINPUT);
        ENSURE(strstr(e.msg, "refusing to overwrite an input") && strstr(e.msg, "(the case file)") &&
               strstr(e.msg, spell[k]));
        ENSURE(st.steps == 0);
        ENSURE(same_file_bytes(deck, orig));
        rc_session *s = (rc_session *)&e;
        ENSURE(rc_session_open(m, &opt, &s, &e) == RC_EINPUT && s == NULL);
        ENSURE(strstr(e.msg, "refusing to overwrite an input") != NULL);
        ENSURE(same_file_bytes(deck, orig));
    }
    printf("    %s\n", e.msg);
    rc_model_free(m);

    /* read from a relative path, run after the working directory changed:
     * the file as read is recognised (its device and inode) */
    char cwd[PATH_MAX];
    ENSURE(getcwd(cwd, sizeof cwd) != NULL);
    ENSURE(chdir(dir) == 0);
    m = compile("deck.rad", &e);
    ENSURE(chdir(cwd) == 0);
    ENSURE(m != NULL);
    if (m) {
        rc_run_options opt = {.output_path = deck};
        ENSURE(rc_run(m, &opt, NULL, &e) == RC_EINPUT && strstr(e.msg, "refusing to overwrite an input"));
        ENSURE(same_file_bytes(deck, orig));
        /* a directory is no output file; a new file is */
        opt.output_path = dir;
        ENSURE(rc_run(m, &opt, NULL, &e) == RC_EINPUT && strstr(e.msg, "not a regular file"));
        snprintf(out, sizeof out, "%s/results.nc", dir);
        opt.output_path = out;
        opt.t_end_override = 0.02;
        ENSURE(rc_run(m, &opt, NULL, &e) == RC_OK);
        rc_model_free(m);
    }

    /* a file the case includes, named through another directory */
    snprintf(inc_main, sizeof inc_main, "%s/main.rad", dir);
    snprintf(inc_run, sizeof inc_run, "%s/run.inc", dir);
    snprintf(inc_orig, sizeof inc_orig, "%s/run.orig", dir);
    ENSURE(demo_variant(inc_main, "/RUN\n                   1              0.0001\n", "#include run.inc\n") == 0);
    ENSURE(write_text(inc_run, "/RUN\n                   1              0.0001\n") == 0 &&
           write_text(inc_orig, "/RUN\n                   1              0.0001\n") == 0);
    m = compile(inc_main, &e);
    ENSURE(m != NULL);
    if (m) {
        char sub[128];
        snprintf(sub, sizeof sub, "%s/sub", dir);
        ENSURE(mkdir(sub, 0700) == 0);
        snprintf(out, sizeof out, "%s/sub/../run.inc", dir);
        rc_run_options opt = {.output_path = out};
        ENSURE(rc_run(m, &opt, NULL, &e) == RC_EINPUT && strstr(e.msg, "(included by the case)"));
        ENSURE(same_file_bytes(inc_run, inc_orig));
        printf("    %s\n", e.msg);
        rc_model_free(m);
    }
    remove_dir(dir);
}

/* ---- NULL arguments ------------------------------------------------------ */

/* Every public function with NULL for each pointer it takes: an error
 * status, or the value the header states; never a crash. */
static void test_contract_null_arguments(void)
{
    rc_error e;
    rc_case *c = (rc_case *)&e;
    ENSURE(rc_case_load(NULL, &c, &e) == RC_EINPUT && c == NULL && strstr(e.msg, "path is NULL"));
    ENSURE(rc_case_load(DEMO, NULL, &e) == RC_EINPUT && strstr(e.msg, "out is NULL"));
    ENSURE(rc_case_load(NULL, NULL, NULL) == RC_EINPUT);
    ENSURE(rc_case_file_count(NULL) == 0 && rc_case_file(NULL, 0) == NULL);
    ENSURE(rc_case_warning_count(NULL) == 0 && rc_case_warning(NULL, 0) == NULL);
    rc_case_free(NULL);
    rc_model *m = (rc_model *)&e;
    ENSURE(rc_model_compile(NULL, &m, &e) == RC_EINPUT && m == NULL && strstr(e.msg, "case is NULL"));
    ENSURE(rc_model_compile(NULL, NULL, NULL) == RC_EINPUT);
    ENSURE(rc_case_load(DEMO, &c, &e) == RC_OK);
    ENSURE(rc_model_compile(c, NULL, &e) == RC_EINPUT && strstr(e.msg, "out is NULL"));
    ENSURE(rc_model_compile(c, &m, NULL) == RC_OK && m != NULL);
    rc_case_free(c);
    if (!m) return;
    rc_model_free(NULL);
    rc_model_print_summary(NULL, stdout);
    rc_model_print_summary(m, NULL);
    ENSURE(rc_model_set_rtol(NULL, 1e-6, &e) == RC_EINPUT && strstr(e.msg, "model is NULL"));
    ENSURE(rc_model_set_method(NULL, 1, NULL) == RC_EINPUT);
    ENSURE(isnan(rc_model_rtol(NULL)) && isnan(rc_model_t_end(NULL)) && isnan(rc_model_dt_out(NULL)));
    ENSURE(rc_model_state_size(NULL) == 0);
    rc_stats st;
    st.steps = -1;
    ENSURE(rc_run(NULL, NULL, &st, &e) == RC_EINPUT && strstr(e.msg, "model is NULL") && st.steps == 0);
    ENSURE(rc_run(NULL, NULL, NULL, NULL) == RC_EINPUT);
    rc_session *s = (rc_session *)&e;
    ENSURE(rc_session_open(NULL, NULL, &s, &e) == RC_EINPUT && s == NULL && strstr(e.msg, "model is NULL"));
    ENSURE(rc_session_open(m, NULL, NULL, &e) == RC_EINPUT && strstr(e.msg, "out is NULL"));
    ENSURE(rc_run_until(NULL, 1.0, &e) == RC_EINPUT && strstr(e.msg, "session is NULL"));
    ENSURE(isnan(rc_session_time(NULL)) && rc_session_state(NULL) == NULL && rc_session_finished(NULL) == 1);
    ENSURE(rc_session_close(NULL, NULL, NULL) == RC_OK);
    /* a session with NULL options and NULL errors */
    ENSURE(rc_session_open(m, NULL, &s, NULL) == RC_OK && s != NULL);
    ENSURE(rc_run_until(s, 0.01, NULL) == RC_OK && rc_session_time(s) == 0.01);
    ENSURE(rc_session_close(s, NULL, NULL) == RC_EINTERRUPT); /* before the end time */
    rc_stats_print(NULL, stdout);
    rc_stats_print(&st, NULL);
    rc_print_versions(NULL);
    ENSURE(rc_export_vtk(NULL, "/tmp", NULL, &e) == RC_EINPUT && strstr(e.msg, "results path is NULL"));
    ENSURE(rc_export_vtk("x.nc", NULL, NULL, NULL) == RC_EINPUT);
    ENSURE(!strcmp(rc_status_str((rc_status)99), "unknown status"));
    rc_model_free(m);
}

/* ---- a callback cannot wait for itself ---------------------------------- */

typedef struct reentry {
    rc_session *refused; /* stepped and closed from the callback: refused  */
    rc_session *stepped; /* stepped from the callback: allowed            */
    int done;
    rc_status until, close, step;
    double t_seen;
    int have_state;
    char msg[256];
} reentry;

static int reenter(void *user, double t, const char *kind, const char *element, const double v[3])
{
    reentry *r = user;
    if (t <= 0 || r->done) return 0;
    r->done = 1;
    rc_error e;
    if (r->refused) {
        r->until = rc_run_until(r->refused, t + 0.01, &e);
        snprintf(r->msg, sizeof r->msg, "%.255s", e.msg);
        r->close = rc_session_close(r->refused, NULL, &e);
        r->t_seen = rc_session_time(r->refused);
        r->have_state = rc_session_state(r->refused) != NULL;
    }
    if (r->stepped) r->step = rc_run_until(r->stepped, 0.3, &e);
    return 0;
}

/* From its event callback a session can be neither stepped nor closed (the
 * callback runs on its integration thread, which would wait for itself):
 * RC_EINPUT, the run goes on; the same through a chain of two sessions,
 * the first one's callback stepping the second, whose callback steps the
 * first. Reading the session's time and state is allowed. */
static void test_contract_callback_cannot_wait_for_itself(void)
{
    rc_error e;
    rc_model *m = compile(DEMO, &e);
    ENSURE(m != NULL);
    if (!m) return;
    alarm(HANG_LIMIT); /* a deadlock ends the test run (SIGALRM) */
    reentry r = {0};
    rc_run_options opt = {.on_event = reenter, .user = &r, .t_end_override = 0.5};
    rc_session *s = NULL;
    ENSURE(rc_session_open(m, &opt, &s, &e) == RC_OK && s != NULL);
    if (s) {
        r.refused = s;
        ENSURE(rc_run_until(s, 0.4, &e) == RC_OK && rc_session_time(s) == 0.4);
        ENSURE(r.done && r.until == RC_EINPUT && r.close == RC_EINPUT);
        ENSURE(strstr(r.msg, "event callback") && strstr(r.msg, "wait for itself"));
        ENSURE(r.t_seen == 0.0 && r.have_state); /* where the caller last stopped it */
        ENSURE(rc_run_until(s, 1.0, &e) == RC_OK && rc_session_finished(s));
        ENSURE(rc_session_close(s, NULL, &e) == RC_OK);
        printf("    from its own callback: %s\n", r.msg);
    }
    /* a chain: A's callback steps B, whose callback steps A */
    reentry ra = {0}, rb = {0};
    rc_run_options oa = {.on_event = reenter, .user = &ra, .t_end_override = 0.5};
    rc_run_options ob = {.on_event = reenter, .user = &rb, .t_end_override = 0.5};
    rc_session *a = NULL, *b = NULL;
    ENSURE(rc_session_open(m, &oa, &a, &e) == RC_OK && rc_session_open(m, &ob, &b, &e) == RC_OK);
    if (a && b) {
        ra.stepped = b;
        rb.refused = a;
        ENSURE(rc_run_until(a, 0.5, &e) == RC_OK);
        ENSURE(ra.done && ra.step == RC_OK && rc_session_time(b) == 0.3);
        ENSURE(rb.done && rb.until == RC_EINPUT && rb.close == RC_EINPUT);
        printf("    through another session's callback: %s\n", rb.msg);
    }
    ENSURE(rc_session_close(a, NULL, &e) == RC_OK);
    ENSURE(rc_session_close(b, NULL, &e) == RC_EINTERRUPT); /* stopped at 0.3 s */
    alarm(0);
    rc_model_free(m);
}

/* ---- run options checked as deck values are ----------------------------- */

/* An end time or output interval that is not finite, not positive, or
 * gives more than RC_MAX_RECORDS records: RC_EINPUT naming it (with the
 * count), nothing run, no file created; the same at the opening of a
 * session, and in the deck's /RUN. */
static void test_contract_run_options_checked(void)
{
    rc_error e;
    rc_model *m = compile(DEMO, &e);
    ENSURE(m != NULL);
    if (!m) return;
    char dir[64], out[128];
    make_dir(dir);
    snprintf(out, sizeof out, "%s/out.nc", dir);
    const struct {
        double te, dt;
        const char *needle;
    } bad[] = {{INFINITY, 0, "t_end_override"}, {NAN, 0, "t_end_override"},          {-1, 0, "t_end_override"},
               {0, 1e-300, "gives 1e+300 records"}, {0, NAN, "dt_out_override"}, {0, -1e-3, "dt_out_override"},
               {0, INFINITY, "dt_out_override"},    {1e300, 0, "gives 1e+304 records"},
               {1e4, 1e-4, "gives 1e+08 records, more than the limit of 10000000"}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        rc_run_options opt = {.output_path = out, .t_end_override = bad[k].te, .dt_out_override = bad[k].dt};
        rc_stats st;
        st.steps = -1;
        ENSURE(rc_run(m, &opt, &st, &e) == RC_EINPUT && strstr(e.msg, bad[k].needle));
        ENSURE(st.steps == 0 && access(out, F_OK) != 0);
        rc_session *s = (rc_session *)&e;
        ENSURE(rc_session_open(m, &opt, &s, &e) == RC_EINPUT && s == NULL && access(out, F_OK) != 0);
        if (k == 3) printf("    %s\n", e.msg);
    }
    /* within the limits: runs */
    rc_run_options opt = {.output_path = out, .t_end_override = 0.05, .dt_out_override = 0.01};
    ENSURE(rc_run(m, &opt, NULL, &e) == RC_OK && access(out, F_OK) == 0);
    /* rc_run_until: NaN refused, +infinity runs to the end */
    rc_session *s = NULL;
    ENSURE(rc_session_open(m, &opt, &s, &e) == RC_OK);
    ENSURE(rc_run_until(s, NAN, &e) == RC_EINPUT && strstr(e.msg, "NaN") && rc_session_time(s) == 0.0);
    ENSURE(rc_run_until(s, INFINITY, &e) == RC_OK && rc_session_finished(s) && rc_session_time(s) == 0.05);
    ENSURE(rc_session_close(s, NULL, &e) == RC_OK);
    rc_model_free(m);
    /* the deck's own /RUN Dt_out */
    char deck[128];
    snprintf(deck, sizeof deck, "%s/dt.rad", dir);
    ENSURE(demo_variant(deck, "                   1              0.0001\n", "                   1              1e-300\n") ==
           0);
    rc_case *c = NULL;
    ENSURE(rc_case_load(deck, &c, &e) == RC_EINPUT && c == NULL);
    char place[256];
    snprintf(place, sizeof place, "%s:%d: card /RUN, field Dt_out", deck, line_of(deck, "/RUN") + 1);
    ENSURE(strstr(e.msg, place) && strstr(e.msg, "1e+300 records"));
    printf("    %s\n", e.msg);
    remove_dir(dir);
}

/* ---- named pipes --------------------------------------------------------- */

/* A named pipe as the case file or as an included file is refused at once
 * (RC_EINPUT naming it, and the file:line of the #include), not opened for
 * reading (which waits for a writer). */
static void test_contract_named_pipe_refused(void)
{
    char dir[64], pipe_deck[128], main_deck[128], pipe_inc[128];
    make_dir(dir);
    snprintf(pipe_deck, sizeof pipe_deck, "%s/pipe.rad", dir);
    snprintf(main_deck, sizeof main_deck, "%s/main.rad", dir);
    snprintf(pipe_inc, sizeof pipe_inc, "%s/run.inc", dir);
    ENSURE(mkfifo(pipe_deck, 0600) == 0 && mkfifo(pipe_inc, 0600) == 0);
    ENSURE(demo_variant(main_deck, "/RUN\n                   1              0.0001\n", "#include run.inc\n") == 0);
    alarm(HANG_LIMIT); /* a blocking open ends the test run (SIGALRM) */
    rc_case *c = (rc_case *)dir;
    rc_error e;
    ENSURE(rc_case_load(pipe_deck, &c, &e) == RC_EINPUT && c == NULL);
    ENSURE(strstr(e.msg, pipe_deck) && strstr(e.msg, "not a regular file (a named pipe)"));
    printf("    %s\n", e.msg);
    ENSURE(rc_case_load(main_deck, &c, &e) == RC_EINPUT && c == NULL);
    char place[512];
    snprintf(place, sizeof place, "%s:%d: #include \"%s/run.inc\"", main_deck, line_of(main_deck, "#include"), dir);
    ENSURE(strstr(e.msg, place) && strstr(e.msg, "not a regular file (a named pipe)"));
    printf("    %s\n", e.msg);
    alarm(0);
    remove_dir(dir);
}

/* ---- a failed write says what the file keeps ----------------------------- */

/* Run the demo for 3 s (about 30000 records, 10 MB) in a child process
 * whose files may not grow beyond `limit` bytes (RLIMIT_FSIZE, SIGXFSZ
 * ignored: the writes fail with EFBIG, as on a file system that another
 * program filled after ricochet checked the room). The child sends back
 * its status and message. */
static rc_status run_limited(const char *out, long limit, char *msg, size_t n)
{
    int fd[2];
    msg[0] = '\0';
    if (pipe(fd) != 0) return RC_EINTERNAL;
    fflush(NULL);
    const pid_t pid = fork();
    if (pid < 0) return RC_EINTERNAL;
    if (pid == 0) {
        close(fd[0]);
        signal(SIGXFSZ, SIG_IGN);
        const struct rlimit rl = {(rlim_t)limit, (rlim_t)limit};
        rc_error e;
        rc_status st = setrlimit(RLIMIT_FSIZE, &rl) == 0 ? RC_OK : RC_EINTERNAL;
        rc_model *m = st ? NULL : compile(DEMO, &e);
        if (m) {
            rc_run_options opt = {.output_path = out, .t_end_override = 3.0};
            st = rc_run(m, &opt, NULL, &e);
        } else
            st = RC_EINTERNAL;
        char buf[4096];
        const int len = snprintf(buf, sizeof buf, "%d %.4000s", (int)st, e.msg);
        if (write(fd[1], buf, (size_t)len) != len) st = RC_EINTERNAL;
        _exit(0); /* HDF5's exit-time clean-up is skipped (rc_output_abandoned) */
    }
    close(fd[1]);
    char buf[4096];
    size_t got = 0;
    ssize_t r;
    while (got < sizeof buf - 1 && (r = read(fd[0], buf + got, sizeof buf - 1 - got)) > 0) got += (size_t)r;
    buf[got] = '\0';
    close(fd[0]);
    int wst;
    waitpid(pid, &wst, 0);
    int code = -1;
    char *sp = strchr(buf, ' ');
    if (sscanf(buf, "%d", &code) != 1 || !sp) return RC_EINTERNAL;
    snprintf(msg, n, "%s", sp + 1);
    return (rc_status)code;
}

/* A write that fails during the run (the file size limit reached before the
 * first block, or after one): RC_EIO whose message says exactly what the
 * file keeps, checked by reading the file from another process: the
 * records it names, or no file at all when it says it was removed. */
static void test_contract_write_failure_says_what_is_kept(void)
{
    char dir[64], out[128], msg[4096], complete[16];
    make_dir(dir);
    snprintf(out, sizeof out, "%s/limited.nc", dir);
    const long limits[2] = {1200000, 5000000};
    for (int k = 0; k < 2; k++) {
        remove(out);
        const rc_status st = run_limited(out, limits[k], msg, sizeof msg);
        printf("    file size limit %ld bytes: status %d: %s\n", limits[k], (int)st, msg);
        ENSURE(st == RC_EIO && strstr(msg, out) && strstr(msg, "record"));
        const long nrec = tu_nc_records(out, complete, sizeof complete);
        const char *keeps = strstr(msg, "it keeps records 0 to ");
        if (strstr(msg, "it was removed")) {
            ENSURE(strstr(msg, "no results were kept") && access(out, F_OK) != 0 && !keeps);
        } else if (keeps) {
            long last = -1;
            ENSURE(sscanf(keeps, "it keeps records 0 to %ld", &last) == 1);
            ENSURE(nrec >= last + 1 && last >= 0 && !strcmp(complete, "no"));
        } else {
            ENSURE(strstr(msg, "could not be read back") != NULL);
        }
        /* never a claim that results were kept for a file that does not read */
        ENSURE(!(nrec < 0 && (keeps || strstr(msg, "are kept"))));
    }
    remove_dir(dir);
}

/* ---- values whose products overflow ------------------------------------- */

/* A body of 1e308 kg (weight inf N), an initial velocity of 1e200 m/s or
 * angular velocity of 1e160 rad/s (infinite kinetic energy), a body far
 * out with a large mass (infinite potential energy): input errors naming
 * the field at its file:line. */
static void test_contract_overflowing_values_refused(void)
{
    char dir[64], deck[128];
    make_dir(dir);
    snprintf(deck, sizeof deck, "%s/big.rad", dir);
    const char *rbody = "         1                                                 1\n";
    const char *inivel_at = "/INTER/TYPE6/1\n";
    const struct {
        const char *from, *to, *card, *field, *what, *line_of;
    } v[] = {
        {rbody, "         1                                             1e308\n", "card /RBODY/1", "field Mass",
         "weight m |g|", "sphere, 1 kg"},
        {inivel_at,
         "/INIVEL/TRA/1\nfast\n               1e200                   0                   0         1         0\n"
         "/INTER/TYPE6/1\n",
         "card /INIVEL/TRA/1", "field Vx, Vy, Vz", "kinetic energy", "fast"},
        {inivel_at,
         "/INIVEL/ROT/1\nspin\n               1e160                   0                   0         1         0\n"
         "/INTER/TYPE6/1\n",
         "card /INIVEL/ROT/1", "field Vx, Vy, Vz", "rotational energy", "spin"},
    };
    for (size_t k = 0; k < sizeof v / sizeof v[0]; k++) {
        ENSURE(demo_variant(deck, v[k].from, v[k].to) == 0);
        rc_error e;
        rc_case *c = NULL;
        rc_model *m = NULL;
        ENSURE(rc_case_load(deck, &c, &e) == RC_OK);
        ENSURE(rc_model_compile(c, &m, &e) == RC_EINPUT && m == NULL);
        char place[160];
        snprintf(place, sizeof place, "%s:%d: %s, %s", deck, line_of(deck, v[k].line_of) + 1, v[k].card, v[k].field);
        ENSURE(strstr(e.msg, place) && strstr(e.msg, v[k].what) && strstr(e.msg, "beyond 1e+300"));
        printf("    %s\n", e.msg);
        rc_model_free(m);
        rc_case_free(c);
    }
    remove_dir(dir);
}

void suite_contract(void);
void suite_contract(void)
{
    RUN_TEST(test_contract_output_never_an_input);
    RUN_TEST(test_contract_null_arguments);
    RUN_TEST(test_contract_callback_cannot_wait_for_itself);
    RUN_TEST(test_contract_run_options_checked);
    RUN_TEST(test_contract_named_pipe_refused);
    RUN_TEST(test_contract_write_failure_says_what_is_kept);
    RUN_TEST(test_contract_overflowing_values_refused);
}
