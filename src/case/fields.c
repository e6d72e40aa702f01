/*
 * Services of the case stage shared by the reader and the card functions:
 * error and warning messages with file:line, growable arrays, block and
 * title helpers, number and field parsing (the field tables of
 * case_internal.h), card headers and their unit systems, layouts by
 * version, the conversion of values to SI, duplicate-id notes, and the
 * place where a --set override's text replaces the deck's (rc_parse_line;
 * the overrides themselves are parsed and checked in override.c). It calls
 * only units.c in the stage (reader.c reads the files and blocks, cards.c
 * dispatches them to the card families cards_*.c).
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define RC_MAX_FIELDS 16    /* fields on one data line (layouts have <= 10) */
#define RC_MAX_REAL_CHARS 255 /* longest real accepted in comma format      */

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

    /* "FILE:LINE: card C, field F: msg", parts present when given; a value
     * of a --set argument is blamed on the argument, not on the deck */
    char full[2048];
    const int w = rd->set_arg ? snprintf(full, sizeof full, "--set %.400s", rd->set_arg)
                              : snprintf(full, sizeof full, "%s:%d", loc && loc->file ? loc->file : "?", loc ? loc->line : 0);
    const size_t k = w < 0 ? 0 : (size_t)w < sizeof full ? (size_t)w : sizeof full - 1;
    if (card && field) snprintf(full + k, sizeof full - k, ": card %s, field %s: %s", card, field, msg);
    else if (card) snprintf(full + k, sizeof full - k, ": card %s: %s", card, msg);
    else snprintf(full + k, sizeof full - k, ": %s", msg);
    /* the first error is the report; the next ones (up to RC_CASE_MAX_ERRORS)
     * are kept for the end of the reading */
    if (rd->nerrors++ == 0) return RC_SET(rd->err, RC_EINPUT, "%s", full);
    if (rd->nerrors <= RC_CASE_MAX_ERRORS) {
        size_t n = strlen(full), have = rd->more ? strlen(rd->more) : 0;
        if (n > RC_CASE_MAX_ERROR_CHARS) n = RC_CASE_MAX_ERROR_CHARS;
        char *m = realloc(rd->more, have + n + 2);
        if (m) {
            m[have] = '\n';
            memcpy(m + have + 1, full, n);
            m[have + 1 + n] = '\0';
            rd->more = m;
        }
    }
    return RC_EINPUT;
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

/* Dimensions of the fields of the cards whose tables do not give one
 * (their fields use RC_F_REAL). */
static int rc_known_dim(const rc_block *b, const char *name)
{
    static const struct { const char *kw, *name; int dim; } t[] = {
        {"NODE", "X", RC_D_L},     {"NODE", "Y", RC_D_L},     {"NODE", "Z", RC_D_L},
        {"RBODY", "Mass", RC_D_M}, {"RBODY", "Jxx", RC_D_J},  {"RBODY", "Jyy", RC_D_J},
        {"RBODY", "Jzz", RC_D_J},  {"RBODY", "Jxy", RC_D_J},  {"RBODY", "Jyz", RC_D_J},
        {"RBODY", "Jxz", RC_D_J},  {"PART", "Thick", RC_D_L}};
    for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
        if (strcmp(b->kw[0], t[i].kw) == 0 && strcmp(name, t[i].name) == 0) return t[i].dim;
    return 0;
}

int rc_units_convert(const rc_reader *rd)
{
    const double *u = rd->cur_units;
    return u && (u[0] != 1 || u[1] != 1 || u[2] != 1);
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
    if (f->blank) memcpy(f->got, "blank", 6);
    else { /* "text" quoted, cut after 40 characters with "..." (written
            * directly: a printf per field was a fifth of reading a deck) */
        const int k = n > 40 ? 40 : n;
        char *g = f->got;
        *g++ = '"';
        memcpy(g, s, (size_t)k);
        g += k;
        if (n > 40) {
            memcpy(g, "...", 3);
            g += 3;
        }
        *g++ = '"';
        *g = '\0';
    }

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
        /* a subnormal value is no physical quantity: its inverse overflows */
        if (dv != 0 && fabs(dv) < DBL_MIN)
            return RC_FIELD_FAIL(rd, b, ln, f, "expected 0 or a number of magnitude at least %g (a normal double), got %s",
                                 DBL_MIN, f->got);
        if (f->blank || (dv == 0 && (f->flags & RC_FF_ZDEF))) dv = f->def;
        if ((r = rc_check_real(rd, b, ln, f, dv))) return (rc_status)r;
        /* into SI from the card's unit system (default values too: they are
         * in the deck's units, as in Radioss) */
        if (rc_units_convert(rd) && dv != 0) {
            int dim = f->dim ? f->dim : rc_known_dim(b, f->name);
            if (!dim)
                return RC_FIELD_FAIL(rd, b, ln, f,
                                     "the deck's units are not SI and this field has no fixed "
                                     "dimension (it depends on other fields): write it in kg, m, s "
                                     "(a /UNIT card of kg m s for this card), got %s",
                                     f->got);
            dv *= rc_dim_scale(dim, rd->cur_units);
            if (!isfinite(dv))
                return RC_FIELD_FAIL(rd, b, ln, f, "the value overflows when converted to SI, got %s",
                                     f->got);
        }
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
    /* Radioss reads the layout's columns only: the rest is ignored */
    for (int i = off; i < ln->len; i++)
        if (ln->text[i] != ' ')
            return rc_case_warn(rd, &ln->loc,
                                "card %s: text after column %d ignored (the last field of "
                                "the layout ends there): \"%.20s\"",
                                b->name, off, ln->text + i);
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

/* Add a field's name to rd->ovr_names (once; silently full). */
static void rc_name_note(rc_reader *rd, const char *name)
{
    char *l = rd->ovr_names;
    const size_t n = strlen(name), have = strlen(l);
    for (const char *p = l; (p = strstr(p, name)); p += n)
        if ((p == l || p[-1] == ' ') && (p[n] == ',' || p[n] == '\0')) return;
    if (have + n + 3 < sizeof rd->ovr_names) snprintf(l + have, sizeof rd->ovr_names - have, "%s%s", have ? ", " : "", name);
}

/* --set overrides of one line of the card rd->ovr_block (override.c): each
 * field that an override names (FIELD: its only occurrence in the card,
 * FIELD[k]: the k-th) takes the override's text; from[k] is the override's
 * index, -1 for the deck's text. The defaults of lines the deck's card
 * lacks (an optional line, an older version's layout) are no text to
 * replace: counted apart, for the message. */
static rc_status rc_override_fields(rc_reader *rd, const rc_block *b, const rc_line *ln, const rc_field *f,
                                    int nf, const char **st, int *sn, int *from)
{
    const int real = ln->loc.file != NULL;
    for (int k = 0; k < nf; k++) {
        if (f[k].type == RC_FT_SKIP) continue;
        if (real && f[k].type != RC_FT_STR && f[k].out) rc_name_note(rd, f[k].name);
        for (int i = 0; i < rd->novr; i++) {
            rc_override *o = &rd->ovr[i];
            if (!o->in_card || strcasecmp(o->field, f[k].name) != 0) continue;
            if (!real) {
                o->absent++;
                continue;
            }
            if (++o->seen != (o->index ? o->index : 1)) continue;
            /* a number that the card uses, set once */
            rc_status s = RC_OK;
            rd->set_arg = o->arg;
            if (f[k].type == RC_FT_STR)
                s = RC_FIELD_FAIL(rd, b, ln, &f[k], "a text field: --set sets numeric fields only (integers and reals)");
            else if (!f[k].out)
                s = RC_FIELD_FAIL(rd, b, ln, &f[k], "read but not used by ricochet: setting it would change nothing");
            else if (from[k] >= 0)
                s = RC_FIELD_FAIL(rd, b, ln, &f[k], "set twice (also by --set %s)", rd->ovr[from[k]].arg);
            rd->set_arg = NULL;
            if (s) return s;
            from[k] = i;
            st[k] = o->val;
            sn[k] = o->nval;
        }
    }
    return RC_OK;
}

rc_status rc_parse_line(rc_reader *rd, const rc_block *b, const rc_line *ln, rc_field *f, int nf)
{
    const char *st[RC_MAX_FIELDS];
    int sn[RC_MAX_FIELDS], from[RC_MAX_FIELDS];
    rc_status s;
    if (nf > RC_MAX_FIELDS) return RC_SET(rd->err, RC_EINTERNAL, "too many fields in a layout");
    /* a comma anywhere selects the free format */
    if (memchr(ln->text, ',', (size_t)ln->len)) s = rc_split_comma(rd, b, ln, nf, st, sn);
    else s = rc_split_fixed(rd, b, ln, f, nf, st, sn);
    if (s) return s;
    /* the texts of --set overrides replace the deck's */
    for (int k = 0; k < nf; k++) from[k] = -1;
    if (rd->ovr_block == b && (s = rc_override_fields(rd, b, ln, f, nf, st, sn, from))) return s;
    /* each field parsed, defaulted, checked and converted alike: a message
     * about an override's value names its argument */
    for (int k = 0; k < nf; k++) {
        rd->set_arg = from[k] >= 0 ? rd->ovr[from[k]].arg : NULL;
        s = rc_parse_field(rd, b, ln, &f[k], st[k], sn[k]);
        rd->set_arg = NULL;
        if (s) return s;
    }
    return RC_OK;
}

/* ======================================================================
 * Layouts by Radioss version
 * ====================================================================== */

/* The Radioss versions whose layouts ricochet knows (/BEGIN Invers). */
static const int rc_versions[] = {41, 42, 43, 44, 51, 90, 100, 110, 120, 130, 140,
                                  2017, 2018, 2019, 2020, 2021, 2022, 2023, 2024, 2025, 2026};

int rc_layout_known(int v)
{
    for (size_t i = 0; i < sizeof rc_versions / sizeof rc_versions[0]; i++)
        if (rc_versions[i] == v) return 1;
    return 0;
}

int rc_layout_version(const rc_reader *rd)
{
    int v = rd->c->invers;
    return v > 0 ? v : RC_LATEST_VERSION;
}

/* ======================================================================
 * Duplicate ids: the notes (the check, pass 3, is in reader.c)
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

/* ======================================================================
 * Card headers and variable-length cards
 * ====================================================================== */

/* Parse "/KW[/SUB]/id[/unit_id]" into b: keywords (upper case), id, unit
 * id. A malformed header is an error unless the card is ignored, so the
 * problem is recorded in b->bad for the dispatcher. */
void rc_parse_header(rc_block *b)
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
        if (n == 0 && !*e && p > b->hdr->text + 1) break; /* a trailing '/' */
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

/* Check the header of a card with `nkw` keywords: id and unit id. */
rc_status rc_header(rc_reader *rd, const rc_block *b, int nkw, rc_id_mode mode,
                    const char *idname, const char *usage)
{
    const rc_loc *loc = &b->hdr->loc;
    if (b->nkw > nkw)
        return rc_case_fail(rd, loc, b->name, NULL, "unexpected keyword /%s (expected %s)",
                            b->kw[nkw], usage);
    /* the id, per card */
    if (mode == RC_ID_REQUIRED && (!b->has_id || b->id <= 0))
        return rc_case_fail(rd, loc, b->name, idname,
                            "expected a positive integer id in the header (%s)", usage);
    if (mode == RC_ID_NONE && b->has_id)
        return rc_case_fail(rd, loc, b->name, NULL, "this card takes no id (expected %s)",
                            usage);
    if (mode == RC_ID_OPTIONAL && b->has_id && b->id <= 0)
        return rc_case_fail(rd, loc, b->name, NULL, "expected a positive id or none (%s)",
                            usage);
    /* the card's unit system: /BEGIN's, or a /UNIT card's */
    int unit = mode == RC_ID_UNIT ? b->id : b->unit_id;
    rd->cur_units = rd->begin_units;
    if (unit == 0) return RC_OK;
    for (int i = 0; i < rd->nunits; i++)
        if (rd->units[i].id == unit) {
            rd->cur_units = rd->units[i].f;
            return RC_OK;
        }
    return rc_case_fail(rd, loc, b->name, "unit_ID",
                        "expected 0, nothing or the id of a /UNIT card, got %d: no /UNIT/%d in "
                        "the deck",
                        unit, unit);
}

/* Lines of a card of variable length: title, then any number of lines
 * (trailing blank lines dropped). */
rc_status rc_var_lines(rc_reader *rd, const rc_block *b, char *title, const char *desc,
                     int *ndata)
{
    int n = rc_block_trim(b);
    rc_status st = rc_card_lines(rd, b, title, 0, b->n > 0 ? b->n - 1 : 0, desc, ndata);
    if (st) return st;
    *ndata = n > 1 ? n - 1 : 0;
    return RC_OK;
}
