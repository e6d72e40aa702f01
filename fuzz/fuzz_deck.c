/*
 * Fuzz target of the case reader and the model compiler: the input bytes are
 * a deck; it is read (rc_case_load), compiled (rc_model_compile: the model,
 * its scales, tolerances and Jacobian pattern), its summary printed to
 * /dev/null (as `ricochet check` prints it) and everything is freed. No
 * run. Built with libFuzzer (make fuzz) and, without it, by the replay
 * driver fuzz/replay.c that make check runs on fuzz/regressions/.
 *
 * Files: the reader reads paths, so the input is written to a private
 * directory made once per process (mkdtemp under $TMPDIR or /tmp):
 *   deck.rad  the input up to a line starting with "#FILE" (a comment), or
 *             all of it;
 *   inc.rad   the lines after that "#FILE" line, when there is one.
 * `#include inc.rad` (or `deck.rad`: a cycle) thus reaches real files. An
 * input whose #include line holds a '/' is skipped before anything is read,
 * so the reader never opens a path outside that directory.
 *
 * Beyond "no crash, no leak, no hang" (the sanitizers and libFuzzer), every
 * outcome must be clean: success, or an input error whose message starts
 * with "DIR/deck.rad:LINE: " or "DIR/inc.rad:LINE: " (a place). Anything else
 * (internal error, out of memory, a message without a place) aborts, so that
 * the fuzzer keeps the input.
 */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "ricochet/ricochet.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static char dir[256];
static FILE *sink; /* /dev/null, for the summary */
static char main_path[300], inc_path[300];

static void remove_dir(void)
{
    if (!dir[0]) return;
    unlink(main_path);
    unlink(inc_path);
    rmdir(dir);
}

static int make_dir(void)
{
    if (dir[0]) return 0;
    const char *tmp = getenv("TMPDIR");
    if (!tmp || !*tmp || strlen(tmp) > 200) tmp = "/tmp";
    snprintf(dir, sizeof dir, "%s/ricochet-fuzz-XXXXXX", tmp);
    if (!mkdtemp(dir)) {
        perror("fuzz_deck: mkdtemp");
        dir[0] = '\0';
        return -1;
    }
    snprintf(main_path, sizeof main_path, "%s/deck.rad", dir);
    snprintf(inc_path, sizeof inc_path, "%s/inc.rad", dir);
    atexit(remove_dir);
    return 0;
}

/* Does any line that the reader takes for #include hold a '/'? The test is
 * wider than the reader's (any line starting with "#include", in any case,
 * after an optional byte order mark). */
static int include_leaves_dir(const uint8_t *d, size_t n)
{
    size_t i = 0;
    if (n >= 3 && d[0] == 0xEF && d[1] == 0xBB && d[2] == 0xBF) i = 3;
    while (i < n) {
        size_t e = i;
        while (e < n && d[e] != '\n') e++;
        if (e - i >= 8 && strncasecmp((const char *)d + i, "#include", 8) == 0 &&
            memchr(d + i, '/', e - i))
            return 1;
        /* a BOM may also start the included part */
        i = e + 1;
        if (i + 3 <= n && d[i] == 0xEF && d[i + 1] == 0xBB && d[i + 2] == 0xBF) i += 3;
    }
    return 0;
}

static int write_file(const char *path, const uint8_t *d, size_t n)
{
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    size_t w = n ? fwrite(d, 1, n, f) : 0;
    return (fclose(f) != 0 || w != n) ? -1 : 0;
}

/* "PATH:DIGITS: " at the start of msg for one of our two files. */
static int has_place(const char *msg)
{
    const char *paths[2] = {main_path, inc_path};
    for (int k = 0; k < 2; k++) {
        size_t n = strlen(paths[k]);
        if (strncmp(msg, paths[k], n) != 0 || msg[n] != ':') continue;
        const char *p = msg + n + 1;
        if (*p < '1' || *p > '9') return 0;
        while (*p >= '0' && *p <= '9') p++;
        return p[0] == ':' && p[1] == ' ';
    }
    return 0;
}

static void bad_outcome(const char *what, const rc_error *e)
{
    fprintf(stderr, "fuzz_deck: %s: status %d (%s): %s\n", what, (int)e->code,
            rc_status_str(e->code), e->msg);
    abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (make_dir() != 0) abort();
    if (include_leaves_dir(data, size)) return 0;

    /* split at the first line starting with "#FILE" */
    size_t cut = size, rest = size;
    for (size_t i = 0; i < size; i++) {
        if ((i == 0 || data[i - 1] == '\n') && size - i >= 5 && memcmp(data + i, "#FILE", 5) == 0) {
            cut = i;
            const uint8_t *nl = memchr(data + i, '\n', size - i);
            rest = nl ? (size_t)(nl - data) + 1 : size;
            break;
        }
    }
    unlink(inc_path);
    if (write_file(main_path, data, cut) != 0 ||
        (cut < size && write_file(inc_path, data + rest, size - rest) != 0)) {
        perror("fuzz_deck: writing the input");
        abort();
    }

    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    memset(&e, 0, sizeof e);
    rc_status st = rc_case_load(main_path, &c, &e);
    if (st == RC_OK) {
        if (!c) bad_outcome("rc_case_load returned no case", &e);
        st = rc_model_compile(c, &m, &e);
        if (st == RC_OK && !m) bad_outcome("rc_model_compile returned no model", &e);
        if (st == RC_OK && !sink) sink = fopen("/dev/null", "w");
        if (st == RC_OK && sink) rc_model_print_summary(m, sink);
    }
    rc_model_free(m);
    rc_case_free(c);
    if (st == RC_OK) return 0;
    if (st != RC_EINPUT) bad_outcome("not an input error", &e);
    if (!has_place(e.msg)) bad_outcome("input error without file:line", &e);
    return 0;
}
