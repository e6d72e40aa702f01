/*
 * Case reader: files, lines and blocks, the duplicate-id check, and the
 * entry points rc_case_load and rc_case_free. Fields, numbers and error
 * messages are in fields.c; the cards themselves are read by cards.c (the
 * dispatch) and the card families cards_*.c.
 *
 * Design notes
 *  - Every file is read whole into memory and split in place; lines point
 *    into the buffers, which live until the end of rc_case_load. This keeps
 *    the reader free of fixed-size line buffers and makes any byte sequence
 *    safe to read: NUL bytes and control characters are detected per line.
 *  - #include is expanded while lexing, so a card may even span files; each
 *    line keeps its own file:line for messages.
 *  - Input limits (line length, include depth, files, bytes) are constants
 *    of case_internal.h, documented in docs/case-format.md; they make the
 *    reader terminate quickly on any input, including include bombs.
 */
#include "case/case_internal.h"
#include "case/case_mesh.h"
#include "base/error.h"
#include "base/progress.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#define RC_MAX_PATH 4096

/* ======================================================================
 * Files and lines (pass 1)
 * ====================================================================== */

static rc_status rc_lex_file(rc_reader *rd, const char *path, const rc_loc *inc);

/* Register a file name in c->files (once), with the device, inode, size and
 * modification time it was read with, and return the stored copy. */
static const char *rc_file_name(rc_reader *rd, const char *path, const struct stat *sb)
{
    rc_case *c = rd->c;
    for (int i = 0; i < c->nfiles; i++)
        if (strcmp(c->files[i], path) == 0) return c->files[i];
    char *s = strdup(path);
    char **f = s ? rc_case_grow(rd, c->files, &rd->capfiles, c->nfiles, sizeof *f) : NULL;
    if (f) c->files = f;
    /* four entries per file, grown as one element */
    unsigned long long(*id)[4] =
        f ? rc_case_grow(rd, c->file_id, &rd->capfileid, c->nfiles, sizeof *id) : NULL;
    if (!f || !id) {
        free(s);
        rc_case_nomem(rd);
        return NULL;
    }
    c->file_id = &id[0][0];
    id[c->nfiles][0] = (unsigned long long)sb->st_dev;
    id[c->nfiles][1] = (unsigned long long)sb->st_ino;
    id[c->nfiles][2] = (unsigned long long)sb->st_size;
    id[c->nfiles][3] = (unsigned long long)sb->st_mtim.tv_sec * 1000000000ull + (unsigned long long)sb->st_mtim.tv_nsec;
    c->files[c->nfiles++] = s;
    return s;
}

/* An error about opening or reading a file: RC_EIO for the main file,
 * RC_EINPUT at the #include line otherwise. */
static rc_status rc_file_error(rc_reader *rd, const char *path, const rc_loc *inc,
                               const char *what)
{
    if (!inc) return RC_SET(rd->err, RC_EIO, "%s: cannot read the case file: %s", path, what);
    return rc_case_fail(rd, inc, NULL, NULL, "#include \"%s\": cannot read it: %s", path, what);
}

/* Read a whole open file into a NUL-terminated buffer kept in rd->bufs. */
static rc_status rc_slurp(rc_reader *rd, FILE *fp, const char *path, const rc_loc *inc,
                          char **out, long *size)
{
    char *buf = NULL;
    long n = 0, cap = 0, limit = RC_CASE_MAX_BYTES - rd->bytes_read;
    for (;;) {
        /* grow by doubling; read at most one byte past the deck's limit */
        if (n + 1 >= cap) {
            long ncap = cap ? 2 * cap : 65536;
            char *p = realloc(buf, (size_t)ncap);
            if (!p) { free(buf); return rc_case_nomem(rd); }
            buf = p;
            cap = ncap;
        }
        long want = cap - n - 1;
        if (want > limit + 1 - n) want = limit + 1 - n;
        size_t got = fread(buf + n, 1, (size_t)want, fp);
        n += (long)got;
        if (n > limit) {
            free(buf);
            if (!inc) return RC_SET(rd->err, RC_EINPUT, "%s: larger than %ld bytes: not a case file",
                                    path, (long)RC_CASE_MAX_BYTES);
            return rc_case_fail(rd, inc, NULL, NULL,
                                "#include \"%s\": the deck exceeds %ld bytes in all", path,
                                (long)RC_CASE_MAX_BYTES);
        }
        if (got == 0) break;
    }
    if (ferror(fp)) {
        free(buf);
        return rc_file_error(rd, path, inc, strerror(errno));
    }
    buf[n] = '\0';
    /* keep the buffer: lines point into it */
    char **bufs = rc_case_grow(rd, rd->bufs, &rd->capbufs, rd->nbufs, sizeof *bufs);
    if (!bufs) {
        free(buf);
        return RC_ENOMEM;
    }
    rd->bufs = bufs;
    rd->bufs[rd->nbufs++] = buf;
    rd->bytes_read += n;
    *out = buf;
    *size = n;
    return RC_OK;
}

/* FNV-1a 64-bit hash of the main file's bytes. */
static unsigned long rc_fnv1a64(const char *s, long n)
{
    uint64_t h = 14695981039346656037ull;
    for (long i = 0; i < n; i++) {
        h ^= (unsigned char)s[i];
        h *= 1099511628211ull;
    }
    return (unsigned long)h;
}

/* #include FILE: resolve FILE relative to the including file and lex it. */
static rc_status rc_include(rc_reader *rd, const char *text, const rc_loc *loc)
{
    const char *s = text + 8, *e;
    while (*s == ' ' || *s == '\t') s++;
    e = s + strlen(s);
    /* optional quotes around the name */
    if (e - s >= 2 && (*s == '"' || *s == '\'') && e[-1] == *s) { s++; e--; }
    if (e == s) return rc_case_fail(rd, loc, NULL, NULL, "#include: missing file name");

    /* directory of the including file, unless the name is absolute */
    const char *slash = strrchr(loc->file, '/');
    size_t dlen = (*s == '/' || !slash) ? 0 : (size_t)(slash - loc->file + 1);
    size_t nlen = (size_t)(e - s);
    if (dlen + nlen >= RC_MAX_PATH)
        return rc_case_fail(rd, loc, NULL, NULL, "#include: path longer than %d characters",
                            RC_MAX_PATH - 1);
    char *path = malloc(dlen + nlen + 1);
    if (!path) return rc_case_nomem(rd);
    memcpy(path, loc->file, dlen);
    memcpy(path + dlen, s, nlen);
    path[dlen + nlen] = '\0';

    rc_status st = rc_lex_file(rd, path, loc);
    free(path);
    return st;
}

/* Strip trailing blanks/CR and check one raw line: text only, no tabs in
 * fixed format, not too long. */
static rc_status rc_line_check(rc_reader *rd, char *p, int *len, const rc_loc *loc)
{
    int n = *len;
    while (n > 0 && (p[n - 1] == ' ' || p[n - 1] == '\t' || p[n - 1] == '\r')) n--;
    p[n] = '\0';
    *len = n;
    /* control characters (NUL bytes included) mean binary content */
    for (int i = 0; i < n; i++) {
        unsigned char ch = (unsigned char)p[i];
        if ((ch < 0x20 && ch != '\t') || ch == 0x7f)
            return rc_case_fail(rd, loc, NULL, NULL,
                                "column %d: byte 0x%02X: not a text file (binary content "
                                "or control character)",
                                i + 1, ch);
    }
    if (n > RC_CASE_MAX_LINE)
        return rc_case_fail(rd, loc, NULL, NULL, "line of %d characters: at most %d allowed", n,
                            RC_CASE_MAX_LINE);
    return RC_OK;
}

/* Is this header line /END? */
static int rc_is_end(const char *p)
{
    p++;
    while (*p == ' ') p++;
    if (strncasecmp(p, "END", 3) != 0) return 0;
    p += 3;
    while (*p == ' ') p++;
    return *p == '\0' || *p == '/';
}

/* Process one line: comments, #include, tabs, /END, else keep it. */
static rc_status rc_lex_line(rc_reader *rd, char *p, int len, const rc_loc *loc)
{
    rc_status st = rc_line_check(rd, p, &len, loc);
    if (st) return st;
    /* comments; #include and #enddata are the comments with a meaning */
    if (p[0] == '#' || p[0] == '$') {
        if (strncasecmp(p, "#include", 8) == 0 && (p[8] == ' ' || p[8] == '\t' || !p[8]))
            return rc_include(rd, p, loc);
        if (strncasecmp(p, "#enddata", 8) == 0 && (p[8] == ' ' || p[8] == '\t' || !p[8]))
            rd->file_ended = 1; /* ends the file it is in */
        return RC_OK;
    }
    /* fixed format cannot contain tabs; comma format may */
    const char *tab = memchr(p, '\t', (size_t)len);
    if (tab && !memchr(p, ',', (size_t)len))
        return rc_case_fail(rd, loc, NULL, NULL,
                            "column %d: tab character: fixed-format lines cannot contain "
                            "tabs (use spaces, or commas for free format)",
                            (int)(tab - p) + 1);
    /* leading blanks before a header's '/' are dropped (Radioss reads the
     * line as a header) */
    if (p[0] == ' ') {
        int k = 0;
        while (p[k] == ' ') k++;
        if (p[k] == '/') { p += k; len -= k; }
    }
    /* /END ends the file it is in: the deck in the main file, the included
     * file otherwise (models are assembled from files each ending in /END) */
    if (p[0] == '/' && rc_is_end(p)) {
        rd->file_ended = 1;
        return RC_OK;
    }
    RC_GROW(rd, rd->lines, rd->caplines, rd->nlines);
    rc_line *ln = &rd->lines[rd->nlines++];
    ln->text = p;
    ln->len = len;
    ln->loc = *loc;
    return RC_OK;
}

/* Split a file buffer into lines and process them. */
static rc_status rc_lex_buffer(rc_reader *rd, char *buf, long size, const char *fname)
{
    char *p = buf, *end = buf + size;
    rc_loc loc = {fname, 0};
    /* a UTF-8 byte order mark is not part of the text */
    if (size >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3;
    while (p < end && !rd->file_ended) {
        rc_progress((long)(p - buf), (long)size); /* bytes */
        char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        *eol = '\0';
        loc.line++;
        rc_status st = rc_lex_line(rd, p, (int)(eol - p), &loc);
        if (st) return st;
        p = eol + 1;
    }
    if (fname == rd->c->files[0] && !rd->engine_pass)
        rd->main_last_line = loc.line > 0 ? loc.line : 1;
    rd->file_ended = 0; /* the including file reads on */
    return RC_OK;
}

/* Open a file, check it is a regular file not already open, read and lex
 * it. `inc` is the #include line (NULL for the main file). */
static rc_status rc_lex_file(rc_reader *rd, const char *path, const rc_loc *inc)
{
    struct stat sb;
    char *buf = NULL;
    long size = 0;
    rc_status st;

    /* limits: include depth and number of files read */
    if (rd->depth > RC_CASE_MAX_INCLUDE_DEPTH)
        return rc_case_fail(rd, inc, NULL, NULL, "#include \"%s\": includes nested deeper than %d levels",
                            path, RC_CASE_MAX_INCLUDE_DEPTH);
    if (++rd->file_reads > RC_CASE_MAX_FILE_READS)
        return rc_case_fail(rd, inc, NULL, NULL, "#include \"%s\": more than %d files read",
                            path, RC_CASE_MAX_FILE_READS);

    /* open; a regular file only (no directory, device or pipe). Opened
     * without blocking: opening a FIFO with no writer, or some devices,
     * would wait for ever; checked with fstat before anything is read */
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) return rc_file_error(rd, path, inc, strerror(errno));
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        const char *kind = S_ISDIR(sb.st_mode) ? "a directory" : S_ISFIFO(sb.st_mode) ? "a named pipe"
                         : S_ISCHR(sb.st_mode) || S_ISBLK(sb.st_mode) ? "a device" : S_ISSOCK(sb.st_mode) ? "a socket"
                                                                                                           : "not a file";
        close(fd);
        if (!inc)
            return RC_SET(rd->err, RC_EINPUT, "%s: cannot read the case file: not a regular file (%s); expected a "
                          "case file", path, kind);
        return rc_case_fail(rd, inc, NULL, NULL, "#include \"%s\": cannot read it: not a regular file (%s)", path,
                            kind);
    }
    /* a regular file: reads never block; back to ordinary reads */
    const int fl = fcntl(fd, F_GETFL);
    FILE *fp = fl >= 0 && fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) == 0 ? fdopen(fd, "rb") : NULL;
    if (!fp) {
        const int e = errno;
        close(fd);
        return rc_file_error(rd, path, inc, strerror(e));
    }

    /* a file already on the include stack is a cycle */
    for (int i = 0; i < rd->depth; i++)
        if (rd->stack[i].dev == sb.st_dev && rd->stack[i].ino == sb.st_ino) {
            fclose(fp);
            return rc_case_fail(rd, inc, NULL, NULL,
                                "#include \"%s\": include cycle (the file is already being read)",
                                path);
        }

    st = rc_slurp(rd, fp, path, inc, &buf, &size);
    fclose(fp);
    if (st) return st;
    if (!inc && !rd->engine_pass) {
        rd->c->checksum = rc_fnv1a64(buf, size);
        rd->main_bytes = size;
    }
    const char *fname = rc_file_name(rd, path, &sb);
    if (!fname) return RC_ENOMEM;

    /* lex with the file on the include stack */
    rd->stack[rd->depth].dev = sb.st_dev;
    rd->stack[rd->depth].ino = sb.st_ino;
    rd->depth++;
    st = rc_lex_buffer(rd, buf, size, fname);
    rd->depth--;
    return st;
}

/* ======================================================================
 * Blocks (pass 2)
 * ====================================================================== */

/* A Radioss starter file NAME_0000.rad: read its engine file
 * NAME_0001.rad next to it, when it exists, after it (a warning says so). */
static rc_status rc_lex_engine(rc_reader *rd, const char *path)
{
    size_t n = strlen(path);
    struct stat sb;
    if (n < 9 || strncmp(path + n - 9, "_0000.", 6) != 0 || strcasecmp(path + n - 3, "rad") != 0)
        return RC_OK;
    char *eng = strdup(path);
    if (!eng) return rc_case_nomem(rd);
    eng[n - 5] = '1';
    rc_status st = RC_OK;
    if (stat(eng, &sb) == 0 && S_ISREG(sb.st_mode)) {
        rd->engine_pass = 1;
        st = rc_lex_file(rd, eng, NULL);
        rd->engine_pass = 0;
        const char *fname = st ? NULL : rc_file_name(rd, eng, &sb);
        if (fname) {
            rc_loc loc = {fname, 1};
            st = rc_case_warn(rd, &loc,
                              "Radioss engine file read after its starter file %s (the pair "
                              "NAME_0000.rad, NAME_0001.rad)",
                              rd->c->files[0]);
        } else if (!st) st = RC_ENOMEM;
    }
    free(eng);
    return st;
}

/* Is block b the card /KW (first keyword)? */
static int rc_block_is(const rc_block *b, const char *kw)
{
    return b->nkw > 0 && strcmp(b->kw[0], kw) == 0;
}

/* Read one card; an input error is counted (rc_case_fail) and the reading
 * goes on with the next card until RC_CASE_MAX_ERRORS. */
static rc_status rc_read_one(rc_reader *rd, const rc_block *b)
{
    rc_status st;
    const int nerrors = rd->nerrors;
    rd->cur_units = rd->begin_units; /* until the card's header says otherwise */
    rc_override_card_begin(rd, b);   /* the --set overrides that address it */
    if (b->bad && b->nkw == 0)
        st = rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "malformed card header: %s", b->bad);
    else st = rc_card_dispatch(rd, b);
    /* each override of the card found its field (when the card was read
     * whole) */
    const rc_status so = rc_override_card_end(rd, b, st == RC_OK && rd->nerrors == nerrors);
    if (st == RC_OK) st = so;
    if (st != RC_EINPUT) return st;
    return rd->nerrors > RC_CASE_MAX_ERRORS ? RC_EINPUT : RC_OK;
}

/* Cut the lines into blocks and read each card: /BEGIN first (the version,
 * hence the layouts, and the deck's units), then the /UNIT cards, then the
 * other cards in order. */
static rc_status rc_read_blocks(rc_reader *rd)
{
    int ncards = 0, cap = 0;
    rc_block *blocks = NULL;
    rc_status st = RC_OK;
    rc_progress_stage("reading the cards (lines)");
    for (int i = 0; i < rd->nlines;) {
        rc_progress(i, rd->nlines);
        const rc_line *ln = &rd->lines[i];
        /* before the first card only blank lines may appear */
        if (ln->text[0] != '/') {
            if (ln->len == 0) { i++; continue; }
            st = rc_case_fail(rd, &ln->loc, NULL, NULL,
                              "data line outside any card (a card starts with '/' in "
                              "column 1): \"%.40s\"",
                              ln->text);
            if (rd->nerrors > RC_CASE_MAX_ERRORS) goto done;
            while (i < rd->nlines && rd->lines[i].text[0] != '/') i++;
            continue;
        }
        /* the block runs to the next header */
        int j = i + 1;
        while (j < rd->nlines && rd->lines[j].text[0] != '/') j++;
        rc_block *nb = rc_case_grow(rd, blocks, &cap, ncards, sizeof *blocks);
        if (!nb) { st = RC_ENOMEM; goto done; }
        blocks = nb;
        rc_block *b = &blocks[ncards++];
        b->hdr = ln;
        b->lines = ln + 1;
        b->n = j - i - 1;
        rc_parse_header(b);
        i = j;
    }
    st = RC_OK;
    for (int pass = 0; pass < 3; pass++)
        for (int k = 0; k < ncards; k++) {
            int when = rc_block_is(&blocks[k], "BEGIN") ? 0 : rc_block_is(&blocks[k], "UNIT") ? 1 : 2;
            if (when != pass) continue;
            if ((st = rc_read_one(rd, &blocks[k]))) goto done;
        }
    if (ncards == 0 && rd->nerrors == 0) {
        rc_loc loc = {rd->c->files[0], rd->main_last_line > 0 ? rd->main_last_line : 1};
        if (rd->main_bytes == 0)
            st = rc_case_fail(rd, &loc, NULL, NULL, "empty file: no cards");
        else
            st = rc_case_fail(rd, &loc, NULL, NULL,
                              "no cards found (a card starts with '/' in column 1)");
    }
done:
    free(blocks);
    if (st == RC_EINPUT && rd->nerrors <= RC_CASE_MAX_ERRORS) st = RC_OK;
    return st;
}

static int rc_cmp_id(const void *pa, const void *pb)
{
    const rc_id_entry *a = pa, *b = pb;
    if (a->id != b->id) return a->id < b->id ? -1 : 1;
    return (a->seq > b->seq) - (a->seq < b->seq);
}

/* A redefinition: the entry, the first definition, the id kind. */
typedef struct { const rc_id_entry *dup, *first; int kind; } rc_dup;

static int rc_cmp_dup(const void *pa, const void *pb)
{
    const rc_dup *a = pa, *b = pb;
    return (a->dup->seq > b->dup->seq) - (a->dup->seq < b->dup->seq);
}

/* After sorting by (id, order), report every redefinition in the order of
 * the deck (each an input error, up to RC_CASE_MAX_ERRORS in all). */
static rc_status rc_check_dups(rc_reader *rd)
{
    static const char *const names[RC_IDK_COUNT] = {
        "fct_ID", "node_ID", "grnod_ID", "rbody_ID", "surf_ID",
        "inter_ID", "inivel_ID", "grav_ID", "bcs_ID", "cpl_ID", "part_ID", "grpart_ID",
        "fric_ID", "fric_orient_ID", "impvel_ID",
        "shell_ID", "brick_ID", "prop_ID", "mat_ID", "skew_ID", "admas_ID", "joint_ID", "rwall_ID", "sens_ID",
        "sprg_ID", "line_ID"};
    rc_dup *d = NULL;
    int nd = 0, cap = 0;
    rc_status st = RC_OK;
    for (int k = 0; k < RC_IDK_COUNT; k++) {
        rc_id_entry *e = rd->ids[k];
        int g = 0;
        if (rd->nids[k] > 1) qsort(e, (size_t)rd->nids[k], sizeof *e, rc_cmp_id);
        for (int i = 1; i < rd->nids[k]; i++) {
            if (e[i].id != e[g].id) { g = i; continue; }
            rc_dup *nw = rc_case_grow(rd, d, &cap, nd, sizeof *d);
            if (!nw) { free(d); return RC_ENOMEM; }
            d = nw;
            d[nd++] = (rc_dup){&e[i], &e[g], k};
        }
    }
    if (nd > 1) qsort(d, (size_t)nd, sizeof *d, rc_cmp_dup);
    for (int i = 0; i < nd && rd->nerrors <= RC_CASE_MAX_ERRORS; i++)
        st = rc_case_fail(rd, &d[i].dup->loc, d[i].dup->card, names[d[i].kind],
                          "duplicate id %d, first defined at %s:%d", d[i].dup->id,
                          d[i].first->loc.file, d[i].first->loc.line);
    free(d);
    return st;
}

/* ======================================================================
 * Entry points
 * ====================================================================== */

/* The report of several input errors: the first one, then the others,
 * one a line, then the count. */
static void rc_case_report(rc_reader *rd)
{
    if (!rd->err || rd->nerrors < 2) return;
    size_t n = strlen(rd->err->msg), cap = sizeof rd->err->msg;
    char tail[128];
    if (rd->nerrors > RC_CASE_MAX_ERRORS)
        snprintf(tail, sizeof tail, "\ntoo many errors: the reading stopped after %d",
                 RC_CASE_MAX_ERRORS);
    else snprintf(tail, sizeof tail, "\n%d input errors", rd->nerrors);
    size_t room = cap - n - 1 > strlen(tail) ? cap - n - 1 - strlen(tail) : 0;
    if (rd->more && room > 0) {
        size_t m = strlen(rd->more);
        if (m > room) {
            /* cut at the last whole line */
            m = room;
            while (m > 0 && rd->more[m] != '\n') m--;
        }
        memcpy(rd->err->msg + n, rd->more, m);
        n += m;
        rd->err->msg[n] = '\0';
    }
    if (n + strlen(tail) < cap) strcat(rd->err->msg, tail);
}

/* Free the reader's own memory (not the case). */
static void rc_reader_release(rc_reader *rd)
{
    free(rd->more);
    for (int i = 0; i < rd->nbufs; i++) free(rd->bufs[i]);
    free(rd->bufs);
    free(rd->lines);
    for (int k = 0; k < RC_IDK_COUNT; k++) free(rd->ids[k]);
    free(rd->units);
    free(rd->ovr);
}

rc_status rc_case_load(const char *path, rc_case **out, rc_error *err)
{
    return rc_case_load_set(path, NULL, 0, out, err);
}

rc_status rc_case_load_set(const char *path, const char *const *set, int nset, rc_case **out, rc_error *err)
{
    rc_reader rd;
    rc_status st;
    memset(&rd, 0, sizeof rd);
    if (out) *out = NULL;
    if (!out) RC_RAISE(err, RC_EINPUT, "rc_case_load: out is NULL; expected where to store the case");
    if (!path) RC_RAISE(err, RC_EINPUT, "rc_case_load: the path is NULL; expected a case file name");
    if (nset < 0 || (nset > 0 && !set))
        RC_RAISE(err, RC_EINPUT, "rc_case_load_set: %s; expected nset >= 0 strings in set",
                 nset < 0 ? "nset is negative" : "set is NULL");
    for (int i = 0; i < nset; i++)
        if (!set[i]) RC_RAISE(err, RC_EINPUT, "rc_case_load_set: set[%d] is NULL; expected \"CARD:FIELD=VALUE\"", i);
    rd.err = err;
    rd.begin_units[0] = rd.begin_units[1] = rd.begin_units[2] = 1.0;
    rd.cur_units = rd.begin_units;
    /* the case, with the defaults of optional cards */
    if (!(rd.c = calloc(1, sizeof *rd.c))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_cards_defaults(rd.c);
    if (!(rd.c->path = strdup(path))) { st = rc_case_nomem(&rd); goto fail; }
    /* the --set overrides, checked before any file is read */
    if ((st = rc_override_parse(&rd, set, nset))) {
        if (st == RC_EINPUT) rc_case_report(&rd);
        goto fail;
    }

    /* pass 1: lines of every file; pass 2: cards; pass 3: deck checks.
     * Input errors of cards are counted and the reading goes on, so that up
     * to RC_CASE_MAX_ERRORS are reported at once. */
    rc_progress_stage("reading the files");
    st = rc_lex_file(&rd, path, NULL);
    if (!st) st = rc_lex_engine(&rd, path);
    rc_progress_done();
    if (st) goto fail;
    st = rc_read_blocks(&rd); /* its own progress stage */
    rc_progress_done();
    if (st) goto report;
    /* every override found its card (when every card was read) */
    if (rd.nerrors <= RC_CASE_MAX_ERRORS && (st = rc_override_finish(&rd)) && st != RC_EINPUT) goto fail;
    rc_progress_stage("checking ids, groups and the mesh");
    if ((st = rc_check_dups(&rd)) && st != RC_EINPUT) goto fail;
    if (rd.nerrors <= RC_CASE_MAX_ERRORS && (st = rc_cards_finish(&rd)) && st != RC_EINPUT) goto fail;
    if (rd.nerrors == 0 && (st = rc_cards_mesh_finish(&rd)) && st != RC_EINPUT) goto fail;
    if (rd.nerrors == 0 && (st = rc_cards_loads_finish(&rd)) && st != RC_EINPUT) goto fail;
    if (rd.nerrors == 0 && (st = rc_cards_fricorient_finish(&rd)) && st != RC_EINPUT) goto fail;
    if (rd.nerrors == 0 && (st = rc_cards_grpart_finish(&rd)) && st != RC_EINPUT) goto fail;
report:
    rc_progress_done();
    if (st != RC_OK && st != RC_EINPUT) goto fail;
    if (rd.nerrors > 0) {
        st = RC_EINPUT;
        rc_case_report(&rd);
        goto fail;
    }
    if ((st = rc_case_index_build(rd.c, err))) goto fail;

    rc_reader_release(&rd);
    *out = rd.c;
    return RC_OK;
fail:
    rc_reader_release(&rd);
    rc_case_free(rd.c);
    return st;
}

void rc_case_free(rc_case *c)
{
    if (!c) return;
    free(c->path);
    free(c->overrides);
    for (int i = 0; i < c->nfiles; i++) free(c->files[i]);
    free(c->files);
    free(c->file_id);
    for (int i = 0; i < c->nfunct; i++) { free(c->funct[i].x); free(c->funct[i].y); }
    free(c->funct);
    free(c->node);
    for (int i = 0; i < c->ngrnod; i++) { free(c->grnod[i].nodes); free(c->grnod[i].node_loc); }
    free(c->grnod);
    free(c->rbody);
    rc_case_mesh_free(c->mesh);
    for (int i = 0; i < c->nsurf; i++) {
        free(c->surf[i].seg);
        free(c->surf[i].seg_id);
        free(c->surf[i].seg_loc);
        free(c->surf[i].part);
        free(c->surf[i].part_loc);
    }
    free(c->surf);
    free(c->type6);
    free(c->type7);
    free(c->type24);
    free(c->power);
    free(c->rwall);
    free(c->sensor);
    free(c->impvel);
    free(c->inivel);
    free(c->grav);
    free(c->bcs);
    free(c->coupling);
    free(c->joint);
    for (int i = 0; i < c->npart; i++) { free(c->part[i].surf); free(c->part[i].surf_loc); }
    free(c->part);
    for (int i = 0; i < c->ngrpart; i++) { free(c->grpart[i].parts); free(c->grpart[i].part_loc); }
    free(c->grpart);
    for (int i = 0; i < c->nline; i++) { free(c->line[i].surf); free(c->line[i].surf_loc); }
    free(c->line);
    for (int i = 0; i < c->nfriction; i++) free(c->friction[i].pair);
    free(c->friction);
    for (int i = 0; i < c->nfricorient; i++) free(c->fricorient[i].item);
    free(c->fricorient);
    for (int i = 0; i < c->nwarnings; i++) free(c->warnings[i]);
    free(c->warnings);
    rc_case_index_free(c->index);
    free(c);
}

int rc_case_file_count(const rc_case *c) { return c ? c->nfiles : 0; }

const char *rc_case_file(const rc_case *c, int i)
{
    return c && i >= 0 && i < c->nfiles ? c->files[i] : NULL;
}
