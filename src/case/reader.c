/*
 * Case reader: files, lines, blocks, fields, numbers and error messages.
 * The cards themselves are read in case_cards.c.
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
#include "base/error.h"

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
#include <sys/stat.h>

#define RC_MAX_FIELDS 16    /* fields on one data line (layouts have <= 10) */
#define RC_MAX_REAL_CHARS 255 /* longest real accepted in comma format      */
#define RC_MAX_PATH 4096

/* ======================================================================
 * Errors and warnings
 * ====================================================================== */

rc_status rc_case_fail(rc_reader *rd, const rc_loc *loc, const char *card, const char *field,
                       const char *fmt, ...)
{
    char msg[1536];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);

    /* "FILE:LINE: card C, field F: msg", parts present when given */
    const char *file = loc && loc->file ? loc->file : "?";
    int line = loc ? loc->line : 0;
    if (card && field)
        return RC_SET(rd->err, RC_EINPUT, "%s:%d: card %s, field %s: %s", file, line, card,
                      field, msg);
    if (card) return RC_SET(rd->err, RC_EINPUT, "%s:%d: card %s: %s", file, line, card, msg);
    return RC_SET(rd->err, RC_EINPUT, "%s:%d: %s", file, line, msg);
}

rc_status rc_case_nomem(rc_reader *rd)
{
    return RC_SET(rd->err, RC_ENOMEM, "out of memory while reading the case file");
}

rc_status rc_case_warn(rc_reader *rd, const rc_loc *loc, const char *fmt, ...)
{
    char msg[1024], *s;
    rc_case *c = rd->c;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);

    /* "FILE:LINE: msg" appended to c->warnings */
    size_t need = strlen(loc->file) + strlen(msg) + 32;
    if (!(s = malloc(need))) return rc_case_nomem(rd);
    snprintf(s, need, "%s:%d: %s", loc->file, loc->line, msg);
    char **w = rc_case_grow(rd, c->warnings, &rd->capwarn, c->nwarnings, sizeof *w);
    if (!w) {
        free(s);
        return RC_ENOMEM;
    }
    c->warnings = w;
    c->warnings[c->nwarnings++] = s;
    return RC_OK;
}

/* ======================================================================
 * Growable arrays
 * ====================================================================== */

void *rc_case_grow(rc_reader *rd, void *arr, int *cap, int n, size_t size)
{
    /* double the capacity when full */
    if (n >= *cap) {
        int ncap = *cap ? *cap : 8;
        while (ncap <= n) {
            if (ncap > INT_MAX / 2) { rc_case_nomem(rd); return NULL; }
            ncap *= 2;
        }
        if ((size_t)ncap > SIZE_MAX / size) { rc_case_nomem(rd); return NULL; }
        void *p = realloc(arr, (size_t)ncap * size);
        if (!p) { rc_case_nomem(rd); return NULL; }
        arr = p;
        *cap = ncap;
    }
    /* the new element starts zeroed */
    memset((char *)arr + (size_t)n * size, 0, size);
    return arr;
}

/* ======================================================================
 * Files and lines (pass 1)
 * ====================================================================== */

static rc_status rc_lex_file(rc_reader *rd, const char *path, const rc_loc *inc);

/* Register a file name in c->files (once) and return the stored copy. */
static const char *rc_file_name(rc_reader *rd, const char *path)
{
    rc_case *c = rd->c;
    for (int i = 0; i < c->nfiles; i++)
        if (strcmp(c->files[i], path) == 0) return c->files[i];
    char *s = strdup(path);
    char **f = s ? rc_case_grow(rd, c->files, &rd->capfiles, c->nfiles, sizeof *f) : NULL;
    if (!f) {
        free(s);
        rc_case_nomem(rd);
        return NULL;
    }
    c->files = f;
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
    /* comments; #include is the one comment with a meaning */
    if (p[0] == '#' || p[0] == '$') {
        if (strncasecmp(p, "#include", 8) == 0 && (p[8] == ' ' || p[8] == '\t' || !p[8]))
            return rc_include(rd, p, loc);
        return RC_OK;
    }
    /* fixed format cannot contain tabs; comma format may */
    const char *tab = memchr(p, '\t', (size_t)len);
    if (tab && !memchr(p, ',', (size_t)len))
        return rc_case_fail(rd, loc, NULL, NULL,
                            "column %d: tab character: fixed-format lines cannot contain "
                            "tabs (use spaces, or commas for free format)",
                            (int)(tab - p) + 1);
    /* /END ends the deck */
    if (p[0] == '/' && rc_is_end(p)) {
        rd->ended = 1;
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
    while (p < end && !rd->ended) {
        char *eol = memchr(p, '\n', (size_t)(end - p));
        if (!eol) eol = end;
        *eol = '\0';
        loc.line++;
        rc_status st = rc_lex_line(rd, p, (int)(eol - p), &loc);
        if (st) return st;
        p = eol + 1;
    }
    if (fname == rd->c->files[0]) rd->main_last_line = loc.line > 0 ? loc.line : 1;
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

    /* open; a regular file only (no directory, device or pipe) */
    FILE *fp = fopen(path, "rb");
    if (!fp) return rc_file_error(rd, path, inc, strerror(errno));
    if (fstat(fileno(fp), &sb) != 0 || !S_ISREG(sb.st_mode)) {
        fclose(fp);
        return rc_file_error(rd, path, inc, "not a regular file");
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
    if (!inc) {
        rd->c->checksum = rc_fnv1a64(buf, size);
        rd->main_bytes = size;
    }
    const char *fname = rc_file_name(rd, path);
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

/* Parse "/KW[/SUB]/id[/unit_id]" into b: keywords (upper case), id, unit
 * id. A malformed header is an error unless the card is ignored, so the
 * problem is recorded in b->bad for the dispatcher. */
static void rc_parse_header(rc_block *b)
{
    const char *p = b->hdr->text + 1;
    const char **bad = &b->bad;
    int nnum = 0;
    *bad = NULL;
    snprintf(b->name, sizeof b->name, "%s", b->hdr->text);
    for (;;) {
        /* one token between slashes, blanks around it ignored */
        const char *e = strchr(p, '/');
        if (!e) e = p + strlen(p);
        const char *s = p, *t = e;
        while (s < t && *s == ' ') s++;
        while (t > s && t[-1] == ' ') t--;
        size_t n = (size_t)(t - s), nd = strspn(s, "0123456789");
        if (n == 0) { *bad = "empty keyword between two '/'"; return; }
        if (nd >= n) {
            /* numeric: id, then unit id */
            long long v = 0;
            for (size_t i = 0; i < n && v <= INT_MAX; i++) v = 10 * v + (s[i] - '0');
            if (v > INT_MAX) { *bad = "id larger than 2147483647"; return; }
            if (nnum == 0) { b->id = (int)v; b->has_id = 1; }
            else if (nnum == 1) b->unit_id = (int)v;
            else { *bad = "more than two numbers (id and unit_ID)"; return; }
            nnum++;
        } else {
            /* keyword: before any number */
            if (nnum) { *bad = "keyword after the id"; return; }
            if (b->nkw == 3) { *bad = "more than three keywords"; return; }
            if (n >= sizeof b->kw[0]) { *bad = "keyword too long"; return; }
            for (size_t i = 0; i < n; i++)
                b->kw[b->nkw][i] = (char)toupper((unsigned char)s[i]);
            b->nkw++;
        }
        if (!*e) break;
        p = e + 1;
    }
}

/* Cut the lines into blocks and read each card. */
static rc_status rc_read_blocks(rc_reader *rd)
{
    int i = 0, ncards = 0;
    while (i < rd->nlines) {
        const rc_line *ln = &rd->lines[i];
        /* before the first card only blank lines may appear */
        if (ln->text[0] != '/') {
            if (ln->len == 0) { i++; continue; }
            return rc_case_fail(rd, &ln->loc, NULL, NULL,
                                "data line outside any card (a card starts with '/' in "
                                "column 1): \"%.40s\"",
                                ln->text);
        }
        /* the block runs to the next header */
        int j = i + 1;
        while (j < rd->nlines && rd->lines[j].text[0] != '/') j++;
        rc_block b;
        memset(&b, 0, sizeof b);
        b.hdr = ln;
        b.lines = ln + 1;
        b.n = j - i - 1;
        rc_parse_header(&b);
        if (b.bad && b.nkw == 0)
            return rc_case_fail(rd, &ln->loc, b.name, NULL, "malformed card header: %s", b.bad);
        rc_status st = rc_card_dispatch(rd, &b);
        if (st) return st;
        ncards++;
        i = j;
    }
    if (ncards == 0) {
        rc_loc loc = {rd->c->files[0], rd->main_last_line > 0 ? rd->main_last_line : 1};
        if (rd->main_bytes == 0)
            return rc_case_fail(rd, &loc, NULL, NULL, "empty file: no cards");
        return rc_case_fail(rd, &loc, NULL, NULL,
                            "no cards found (a card starts with '/' in column 1)");
    }
    return RC_OK;
}

/* ======================================================================
 * Blocks: helpers for the card functions
 * ====================================================================== */

int rc_block_trim(const rc_block *b)
{
    int n = b->n;
    while (n > 0 && b->lines[n - 1].len == 0) n--;
    return n;
}

rc_status rc_read_title(rc_reader *rd, const rc_block *b, const rc_line *ln, char *title)
{
    if (ln->len > RC_CASE_TITLE_MAX)
        return rc_case_fail(rd, &ln->loc, b->name, "title",
                            "expected at most %d characters, got %d", RC_CASE_TITLE_MAX,
                            ln->len);
    memcpy(title, ln->text, (size_t)ln->len + 1);
    return RC_OK;
}

rc_status rc_card_lines(rc_reader *rd, const rc_block *b, char *title, int min, int max,
                        const char *desc, int *ndata)
{
    int first = title ? 1 : 0;
    const char *s = min == 1 ? "" : "s";
    /* missing lines: blame the header */
    if (title && b->n == 0 && min == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "expected a title line then data lines (%s), found no line", desc);
    if (title && b->n == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "expected a title line then %d data line%s (%s), found no line", min,
                            s, desc);
    if (b->n - first < min)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "expected %d data line%s (%s), found %d", min, s, desc,
                            b->n - first);
    /* lines beyond the layout: blank ones are harmless */
    for (int i = first + max; i < b->n; i++)
        if (b->lines[i].len)
            return rc_case_fail(rd, &b->lines[i].loc, b->name, NULL,
                                "unexpected data line: the card has at most %d data line%s "
                                "(%s); a new card starts with '/' in column 1",
                                max, max == 1 ? "" : "s", desc);
    if (title) {
        rc_status st = rc_read_title(rd, b, &b->lines[0], title);
        if (st) return st;
    }
    *ndata = b->n - first < max ? b->n - first : max;
    return RC_OK;
}

/* ======================================================================
 * Numbers
 * ====================================================================== */

/* Plain integer with optional sign. 0: ok, 1: not an integer, 2: out of
 * range of int. */
static int rc_parse_int(const char *s, int n, int *v)
{
    int i = 0, neg = 0;
    long long acc = 0;
    if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
    if (i == n) return 1;
    for (; i < n; i++) {
        if (s[i] < '0' || s[i] > '9') return 1;
        if (acc <= (long long)INT_MAX + 1) acc = 10 * acc + (s[i] - '0');
    }
    if (acc > (long long)INT_MAX + (neg ? 1 : 0)) return 2;
    *v = (int)(neg ? -acc : acc);
    return 0;
}

/* Skip decimal digits from s[i], return the new index. */
static int rc_digits(const char *s, int i, int n)
{
    while (i < n && s[i] >= '0' && s[i] <= '9') i++;
    return i;
}

/* Fortran real: [sign] (d+[.d*] | .d+) [(e|E|d|D)[sign]d+]. Rejects the
 * letterless exponent form "1.5-3", nan, inf, hex. 0: ok, 1: bad, 2: not
 * finite. */
static int rc_parse_real(const char *s, int n, double *v)
{
    char buf[RC_MAX_REAL_CHARS + 1];
    int i = 0, j;
    if (n > RC_MAX_REAL_CHARS) return 1;
    /* mantissa */
    if (i < n && (s[i] == '+' || s[i] == '-')) i++;
    j = rc_digits(s, i, n);
    int nd = j - i;
    i = j;
    if (i < n && s[i] == '.') {
        j = rc_digits(s, i + 1, n);
        nd += j - i - 1;
        i = j;
    }
    if (nd == 0) return 1;
    /* exponent */
    if (i < n && strchr("eEdD", s[i])) {
        i++;
        if (i < n && (s[i] == '+' || s[i] == '-')) i++;
        j = rc_digits(s, i, n);
        if (j == i) return 1;
        i = j;
    }
    if (i != n) return 1;
    /* convert with D -> e */
    for (i = 0; i < n; i++) buf[i] = (s[i] == 'd' || s[i] == 'D') ? 'e' : s[i];
    buf[n] = '\0';
    char *end;
    double x = strtod(buf, &end);
    if (end != buf + n) return 1;
    if (!isfinite(x)) return 2;
    *v = x;
    return 0;
}

/* "{0, 1, 2}" from a bit mask. */
static void rc_set_str(unsigned mask, char *out, size_t cap)
{
    size_t k = 0;
    k += (size_t)snprintf(out, cap, "{");
    for (int i = 0, first = 1; i < 32 && k < cap; i++)
        if (mask & RC_BIT(i)) {
            k += (size_t)snprintf(out + k, cap - k, "%s%d", first ? "" : ", ", i);
            first = 0;
        }
    if (k < cap) snprintf(out + k, cap - k, "}");
}

/* ======================================================================
 * Fields
 * ====================================================================== */

/* Failure on field f of line ln. */
#define RC_FIELD_FAIL(rd, b, ln, f, ...) rc_case_fail((rd), &(ln)->loc, (b)->name, (f)->name, __VA_ARGS__)

/* Checks of an integer after defaulting: set, sign, supported values. */
static rc_status rc_check_int(rc_reader *rd, const rc_block *b, const rc_line *ln,
                              const rc_field *f, int v)
{
    char set[160];
    int in_valid = v >= 0 && v < 32 && (f->valid & RC_BIT(v));
    int in_supp = v >= 0 && v < 32 && (f->supp & RC_BIT(v));
    const char *sp = f->note ? " " : "", *note = f->note ? f->note : "";
    if (f->valid && !in_valid) {
        rc_set_str(f->valid, set, sizeof set);
        return RC_FIELD_FAIL(rd, b, ln, f, "expected an integer in %s, got %s", set, f->got);
    }
    if ((f->flags & RC_FF_POS) && v <= 0)
        return RC_FIELD_FAIL(rd, b, ln, f, "expected a positive integer, got %s", f->got);
    if ((f->flags & RC_FF_NONNEG) && v < 0)
        return RC_FIELD_FAIL(rd, b, ln, f, "expected a non-negative integer, got %s", f->got);
    if ((f->flags & RC_FF_ONLY0) && v != 0)
        return RC_FIELD_FAIL(rd, b, ln, f, "expected 0, got %s: not supported yet%s%s", f->got,
                             sp, note);
    if (f->supp && !in_supp) {
        rc_set_str(f->supp, set, sizeof set);
        return RC_FIELD_FAIL(rd, b, ln, f, "expected an integer in %s, got %s: not supported yet%s%s",
                             set, f->got, sp, note);
    }
    return RC_OK;
}

/* Checks of a real after defaulting. */
static rc_status rc_check_real(rc_reader *rd, const rc_block *b, const rc_line *ln,
                               const rc_field *f, double v)
{
    const char *sp = f->note ? " " : "", *note = f->note ? f->note : "";
    if ((f->flags & RC_FF_POS) && !(v > 0))
        return RC_FIELD_FAIL(rd, b, ln, f, "expected a positive real number, got %s", f->got);
    if ((f->flags & RC_FF_NONNEG) && v < 0)
        return RC_FIELD_FAIL(rd, b, ln, f, "expected a non-negative real number, got %s",
                             f->got);
    if ((f->flags & RC_FF_ONLY0) && v != 0)
        return RC_FIELD_FAIL(rd, b, ln, f, "expected 0, got %s: not supported yet%s%s", f->got,
                             sp, note);
    return RC_OK;
}

/* Parse the text s[0..n) (trimmed) of one field, default it, check it and
 * store it. */
static rc_status rc_parse_field(rc_reader *rd, const rc_block *b, const rc_line *ln, rc_field *f,
                                const char *s, int n)
{
    int iv = 0, r;
    double dv = 0;
    /* the text as found, for messages */
    f->blank = n == 0;
    if (f->blank) snprintf(f->got, sizeof f->got, "blank");
    else snprintf(f->got, sizeof f->got, "\"%.*s%s\"", n > 40 ? 40 : n, s, n > 40 ? "..." : "");

    switch (f->type) {
    case RC_FT_SKIP:
        if (!f->blank)
            return RC_FIELD_FAIL(rd, b, ln, f, "expected an unused (blank) field, got %s", f->got);
        return RC_OK;
    case RC_FT_STR:
        if ((size_t)n >= f->cap)
            return RC_FIELD_FAIL(rd, b, ln, f, "expected at most %d characters, got %s",
                                 (int)f->cap - 1, f->got);
        if (f->out) {
            memcpy(f->out, s, (size_t)n);
            ((char *)f->out)[n] = '\0';
        }
        return RC_OK;
    case RC_FT_INT:
        if (!f->blank && (r = rc_parse_int(s, n, &iv)) != 0)
            return RC_FIELD_FAIL(rd, b, ln, f, r == 1 ? "expected an integer, got %s"
                                 : "expected an integer in [-2147483648, 2147483647], got %s",
                                 f->got);
        if (f->blank || (iv == 0 && (f->flags & RC_FF_ZDEF))) iv = (int)f->def;
        if ((r = rc_check_int(rd, b, ln, f, iv))) return (rc_status)r;
        if (f->out) *(int *)f->out = iv;
        return RC_OK;
    case RC_FT_REAL:
        if (!f->blank && (r = rc_parse_real(s, n, &dv)) != 0)
            return RC_FIELD_FAIL(rd, b, ln, f, "expected a finite real number, got %s", f->got);
        if (f->blank || (dv == 0 && (f->flags & RC_FF_ZDEF))) dv = f->def;
        if ((r = rc_check_real(rd, b, ln, f, dv))) return (rc_status)r;
        if (f->out) *(double *)f->out = dv;
        return RC_OK;
    }
    return RC_SET(rd->err, RC_EINTERNAL, "bad field type");
}

/* Trim blanks (and tabs, possible in comma format) around s[0..*n). */
static const char *rc_trim(const char *s, int *n)
{
    while (*n > 0 && (*s == ' ' || *s == '\t')) { s++; (*n)--; }
    while (*n > 0 && (s[*n - 1] == ' ' || s[*n - 1] == '\t')) (*n)--;
    return s;
}

/* Fixed format: cut the line at the field widths; text beyond the layout
 * is an error. */
static rc_status rc_split_fixed(rc_reader *rd, const rc_block *b, const rc_line *ln,
                                const rc_field *f, int nf, const char **st, int *sn)
{
    int off = 0;
    for (int k = 0; k < nf; k++) {
        int s0 = off < ln->len ? off : ln->len;
        int s1 = off + f[k].width < ln->len ? off + f[k].width : ln->len;
        sn[k] = s1 - s0;
        st[k] = rc_trim(ln->text + s0, &sn[k]);
        off += f[k].width;
    }
    for (int i = off; i < ln->len; i++)
        if (ln->text[i] != ' ')
            return rc_case_fail(rd, &ln->loc, b->name, NULL,
                                "unexpected text after column %d (the last field ends "
                                "there): \"%.20s\"",
                                off, ln->text + i);
    return RC_OK;
}

/* Comma format: one field per comma-separated token, in layout order;
 * missing trailing fields and empty tokens take the default. */
static rc_status rc_split_comma(rc_reader *rd, const rc_block *b, const rc_line *ln,
                                int nf, const char **st, int *sn)
{
    const char *p = ln->text;
    int k = 0;
    for (int i = 0; i < nf; i++) { st[i] = ""; sn[i] = 0; }
    for (;;) {
        const char *e = strchr(p, ',');
        int n = e ? (int)(e - p) : (int)strlen(p);
        const char *t = rc_trim(p, &n);
        if (k < nf) { st[k] = t; sn[k] = n; }
        else if (n > 0)
            return rc_case_fail(rd, &ln->loc, b->name, NULL,
                                "expected at most %d comma-separated fields, got \"%.20s\" as "
                                "field %d",
                                nf, t, k + 1);
        k++;
        if (!e) break;
        p = e + 1;
    }
    return RC_OK;
}

rc_status rc_parse_line(rc_reader *rd, const rc_block *b, const rc_line *ln, rc_field *f, int nf)
{
    const char *st[RC_MAX_FIELDS];
    int sn[RC_MAX_FIELDS];
    rc_status s;
    if (nf > RC_MAX_FIELDS) return RC_SET(rd->err, RC_EINTERNAL, "too many fields in a layout");
    /* a comma anywhere selects the free format */
    if (memchr(ln->text, ',', (size_t)ln->len)) s = rc_split_comma(rd, b, ln, nf, st, sn);
    else s = rc_split_fixed(rd, b, ln, f, nf, st, sn);
    if (s) return s;
    for (int k = 0; k < nf; k++)
        if ((s = rc_parse_field(rd, b, ln, &f[k], st[k], sn[k]))) return s;
    return RC_OK;
}

/* ======================================================================
 * Duplicate ids (pass 3)
 * ====================================================================== */

rc_status rc_note_id(rc_reader *rd, rc_id_kind kind, int id, const rc_loc *loc, const char *card)
{
    RC_GROW(rd, rd->ids[kind], rd->capids[kind], rd->nids[kind]);
    rc_id_entry *e = &rd->ids[kind][rd->nids[kind]++];
    e->id = id;
    e->seq = rd->seq++;
    e->loc = *loc;
    e->card = card;
    return RC_OK;
}

static int rc_cmp_id(const void *pa, const void *pb)
{
    const rc_id_entry *a = pa, *b = pb;
    if (a->id != b->id) return a->id < b->id ? -1 : 1;
    return (a->seq > b->seq) - (a->seq < b->seq);
}

/* After sorting by (id, order), report the earliest redefinition. */
static rc_status rc_check_dups(rc_reader *rd)
{
    static const char *const names[RC_IDK_COUNT] = {
        "fct_ID", "node_ID", "grnod_ID", "rbody_ID", "surf_ID",
        "inter_ID", "inivel_ID", "grav_ID", "bcs_ID", "cpl_ID", "part_ID", "grpart_ID",
        "fric_ID", "fric_orient_ID", "impvel_ID"};
    const rc_id_entry *worst = NULL, *first = NULL;
    int wkind = 0;
    for (int k = 0; k < RC_IDK_COUNT; k++) {
        rc_id_entry *e = rd->ids[k];
        int g = 0;
        if (rd->nids[k] > 1) qsort(e, (size_t)rd->nids[k], sizeof *e, rc_cmp_id);
        for (int i = 1; i < rd->nids[k]; i++) {
            if (e[i].id != e[g].id) { g = i; continue; }
            if (!worst || e[i].seq < worst->seq) { worst = &e[i]; first = &e[g]; wkind = k; }
        }
    }
    if (!worst) return RC_OK;
    return rc_case_fail(rd, &worst->loc, worst->card, names[wkind],
                        "duplicate id %d, first defined at %s:%d", worst->id, first->loc.file,
                        first->loc.line);
}

/* ======================================================================
 * Entry points
 * ====================================================================== */

/* Free the reader's own memory (not the case). */
static void rc_reader_release(rc_reader *rd)
{
    for (int i = 0; i < rd->nbufs; i++) free(rd->bufs[i]);
    free(rd->bufs);
    free(rd->lines);
    for (int k = 0; k < RC_IDK_COUNT; k++) free(rd->ids[k]);
}

rc_status rc_case_load(const char *path, rc_case **out, rc_error *err)
{
    rc_reader rd;
    rc_status st;
    memset(&rd, 0, sizeof rd);
    if (out) *out = NULL;
    if (!path || !out) RC_RAISE(err, RC_EINTERNAL, "rc_case_load: NULL argument");
    rd.err = err;
    /* the case, with the defaults of optional cards */
    if (!(rd.c = calloc(1, sizeof *rd.c))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_cards_defaults(rd.c);
    if (!(rd.c->path = strdup(path))) { st = rc_case_nomem(&rd); goto fail; }

    /* pass 1: lines of every file; pass 2: cards; pass 3: deck checks */
    if ((st = rc_lex_file(&rd, path, NULL))) goto fail;
    if ((st = rc_read_blocks(&rd))) goto fail;
    if ((st = rc_check_dups(&rd))) goto fail;
    if ((st = rc_cards_finish(&rd))) goto fail;
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
    for (int i = 0; i < c->nfiles; i++) free(c->files[i]);
    free(c->files);
    for (int i = 0; i < c->nfunct; i++) { free(c->funct[i].x); free(c->funct[i].y); }
    free(c->funct);
    free(c->node);
    for (int i = 0; i < c->ngrnod; i++) free(c->grnod[i].nodes);
    free(c->grnod);
    free(c->rbody);
    free(c->surf);
    free(c->type6);
    free(c->power);
    free(c->impvel);
    free(c->inivel);
    free(c->grav);
    free(c->bcs);
    free(c->coupling);
    for (int i = 0; i < c->npart; i++) free(c->part[i].surf);
    free(c->part);
    for (int i = 0; i < c->ngrpart; i++) free(c->grpart[i].parts);
    free(c->grpart);
    for (int i = 0; i < c->nfriction; i++) free(c->friction[i].pair);
    free(c->friction);
    for (int i = 0; i < c->nfricorient; i++) free(c->fricorient[i].item);
    free(c->fricorient);
    for (int i = 0; i < c->nwarnings; i++) free(c->warnings[i]);
    free(c->warnings);
    rc_case_index_free(c->index);
    free(c);
}
