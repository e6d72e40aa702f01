/*
 * --set overrides: a numeric field of a card set by name from outside the
 * deck, "/KEYWORD/.../ID:FIELD=VALUE" (docs/case-format.md, "Setting
 * fields from the command line").
 *
 * Design: the value is deck input, not a number patched into the parsed
 * case. rc_parse_line (fields.c) gives the field the override's text in
 * place of the deck's, then parses, defaults, checks and converts it to SI
 * exactly as if it had been typed into the card (the card's unit system,
 * its range checks and messages; a message then names the --set argument
 * instead of file:line). This file parses the arguments, marks the
 * overrides that address the card being read and checks after each card
 * and after the deck that each override found its card and its field once.
 *
 * Choices
 *  - The card: keywords and id as in a deck header, keywords in any case
 *    (the reader upper-cases them); a card without an id (/RUN, /SOLVER) is
 *    addressed by its keywords alone. An address that matches two cards of
 *    the deck is refused.
 *  - The field: its name in the card's field table, in any case. A field
 *    that occurs more than once in the card (table rows, /FRICTION pairs)
 *    needs FIELD[k], the k-th occurrence in reading order.
 *  - Numeric fields only: a text field, an unused column, a field read but
 *    not used, a field on a line the deck's card lacks, and a field set by
 *    two arguments are refused.
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#define RC_SET_USAGE "expected /KEYWORD[/SUBTYPE]/ID:FIELD=VALUE or FIELD[k]=VALUE (e.g. /INTER/TYPE6/1:Fric=0.3)"

/* An input error about override o: "--set ARG: [card C, [field F: ]]msg". */
static rc_status rc_set_fail(rc_reader *rd, const rc_override *o, const char *card, const char *field,
                             const char *fmt, ...) __attribute__((format(printf, 5, 6)));
static rc_status rc_set_fail(rc_reader *rd, const rc_override *o, const char *card, const char *field,
                             const char *fmt, ...)
{
    char msg[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    rd->set_arg = o->arg;
    rc_status st = rc_case_fail(rd, NULL, card, field, "%s", msg);
    rd->set_arg = NULL;
    return st;
}

/* The card an override addresses, as a header: "/INTER/TYPE6/1". */
static void rc_override_card(const rc_override *o, char *out, size_t cap)
{
    size_t w = 0;
    out[0] = '\0';
    for (int k = 0; k < o->nkw && w < cap; k++) w += (size_t)snprintf(out + w, cap - w, "/%s", o->kw[k]);
    if (o->has_id && w < cap) snprintf(out + w, cap - w, "/%d", o->id);
}

/* Does override o address block b? */
static int rc_override_matches(const rc_override *o, const rc_block *b)
{
    if (o->nkw != b->nkw || o->has_id != b->has_id || (o->has_id && o->id != b->id)) return 0;
    for (int k = 0; k < o->nkw; k++)
        if (strcmp(o->kw[k], b->kw[k]) != 0) return 0;
    return 1;
}

/* Trim blanks around s[0..*n). */
static const char *rc_override_trim(const char *s, size_t *n)
{
    while (*n > 0 && (*s == ' ' || *s == '\t')) { s++; (*n)--; }
    while (*n > 0 && (s[*n - 1] == ' ' || s[*n - 1] == '\t')) (*n)--;
    return s;
}

/* Parse one argument into o; an input error names it. */
static rc_status rc_override_one(rc_reader *rd, rc_override *o, const char *a)
{
    o->arg = a;
    for (const char *p = a; *p; p++)
        if ((unsigned char)*p < 0x20 || *p == 0x7f)
            return rc_set_fail(rd, o, NULL, NULL, "control character (byte 0x%02X): %s", (unsigned)(unsigned char)*p,
                               RC_SET_USAGE);
    const char *colon = strchr(a, ':'), *eq = colon ? strchr(colon + 1, '=') : NULL;
    if (!colon || !eq) return rc_set_fail(rd, o, NULL, NULL, "%s", RC_SET_USAGE);
    /* the card: a header "/KW[/SUB]/id" read as the deck's */
    size_t n = (size_t)(colon - a);
    const char *card = rc_override_trim(a, &n);
    char hdr[88];
    if (n == 0 || card[0] != '/') return rc_set_fail(rd, o, NULL, NULL, "the card must start with '/': %s", RC_SET_USAGE);
    if (n >= sizeof hdr) return rc_set_fail(rd, o, NULL, NULL, "card longer than %d characters", (int)sizeof hdr - 1);
    memcpy(hdr, card, n);
    hdr[n] = '\0';
    rc_line ln = {hdr, (int)n, {NULL, 0}};
    rc_block b;
    memset(&b, 0, sizeof b);
    b.hdr = &ln;
    rc_parse_header(&b);
    if (b.bad) return rc_set_fail(rd, o, NULL, NULL, "malformed card %s: %s", hdr, b.bad);
    if (b.nkw == 0) return rc_set_fail(rd, o, NULL, NULL, "no keyword in the card %s: %s", hdr, RC_SET_USAGE);
    if (b.unit_id)
        return rc_set_fail(rd, o, NULL, NULL, "the card %s has two numbers: write its keywords and id only (no unit_ID)",
                           hdr);
    memcpy(o->kw, b.kw, sizeof o->kw);
    o->nkw = b.nkw;
    o->id = b.id;
    o->has_id = b.has_id;
    /* the field, with its occurrence k of FIELD[k] */
    n = (size_t)(eq - colon - 1);
    const char *field = rc_override_trim(colon + 1, &n);
    if (n > 0 && field[n - 1] == ']') {
        const char *lb = memchr(field, '[', n);
        long k = 0;
        size_t i = lb ? (size_t)(lb - field) + 1 : n;
        for (; lb && i < n - 1 && isdigit((unsigned char)field[i]) && k <= 1000000; i++) k = 10 * k + (field[i] - '0');
        if (!lb || i != n - 1 || k < 1 || k > 1000000)
            return rc_set_fail(rd, o, NULL, NULL, "expected FIELD[k] with k a positive integer (the k-th occurrence of "
                               "the field in the card)");
        o->index = (int)k;
        n = (size_t)(lb - field);
        field = rc_override_trim(field, &n);
    }
    if (n == 0) return rc_set_fail(rd, o, NULL, NULL, "no field name: %s", RC_SET_USAGE);
    if (n >= sizeof o->field) return rc_set_fail(rd, o, NULL, NULL, "field name longer than %d characters",
                                                 (int)sizeof o->field - 1);
    if (memchr(field, '[', n) || memchr(field, ']', n))
        return rc_set_fail(rd, o, NULL, NULL, "expected FIELD[k] with k a positive integer (the k-th occurrence of the "
                           "field in the card)");
    memcpy(o->field, field, n);
    o->field[n] = '\0';
    /* the value: the field's text as typed (empty: a blank field, its
     * default) */
    n = strlen(eq + 1);
    o->val = rc_override_trim(eq + 1, &n);
    o->nval = (int)n;
    return RC_OK;
}

rc_status rc_override_parse(rc_reader *rd, const char *const *set, int nset)
{
    if (nset <= 0) return RC_OK;
    if (!(rd->ovr = calloc((size_t)nset, sizeof *rd->ovr))) return rc_case_nomem(rd);
    rd->novr = nset;
    for (int i = 0; i < nset; i++) {
        rc_override *o = &rd->ovr[i];
        if (rc_override_one(rd, o, set[i])) continue;
        /* a field set twice (the same card, field and occurrence) */
        for (int j = 0; j < i; j++) {
            const rc_override *p = &rd->ovr[j];
            int same = p->nkw == o->nkw && p->has_id == o->has_id && p->id == o->id && p->index == o->index &&
                       strcasecmp(p->field, o->field) == 0;
            for (int k = 0; same && k < o->nkw; k++) same = strcmp(p->kw[k], o->kw[k]) == 0;
            if (same) {
                char card[100];
                rc_override_card(o, card, sizeof card);
                rc_set_fail(rd, o, card, o->field, "set twice (also by --set %s)", p->arg);
                break;
            }
        }
    }
    return rd->nerrors ? RC_EINPUT : RC_OK;
}

void rc_override_card_begin(rc_reader *rd, const rc_block *b)
{
    rd->ovr_block = NULL;
    rd->ovr_names[0] = '\0';
    for (int i = 0; i < rd->novr; i++) {
        rc_override *o = &rd->ovr[i];
        o->in_card = rc_override_matches(o, b);
        if (!o->in_card) continue;
        o->ncards++;
        o->seen = o->absent = 0;
        rd->ovr_block = b;
    }
}

/* "no numeric field F" with the card's fields and a "did you mean". */
static rc_status rc_override_unknown(rc_reader *rd, const rc_block *b, const rc_override *o)
{
    const char *names = rd->ovr_names;
    if (!names[0])
        return rc_set_fail(rd, o, b->name, NULL, "no numeric field %s: ricochet reads no numeric field of this card",
                           o->field);
    /* the names upper-cased, for a comparison that ignores case */
    char up[sizeof rd->ovr_names], word[sizeof o->field];
    const char *cand[128];
    int nc = 0;
    for (size_t i = 0; i <= strlen(names); i++) up[i] = (char)toupper((unsigned char)names[i]);
    for (char *p = up; p && *p && nc < 128;) {
        cand[nc++] = p;
        if ((p = strstr(p, ", "))) {
            *p = '\0';
            p += 2;
        }
    }
    for (size_t i = 0; i <= strlen(o->field); i++) word[i] = (char)toupper((unsigned char)o->field[i]);
    const char *near = rc_closest_name(word, cand, nc);
    if (near) {
        /* the name as the table writes it */
        const char *p = names + (near - up);
        const size_t len = strlen(near);
        return rc_set_fail(rd, o, b->name, NULL, "no numeric field %s: did you mean %.*s? (the card's numeric fields: %s)",
                           o->field, (int)len, p, names);
    }
    return rc_set_fail(rd, o, b->name, NULL, "no numeric field %s (the card's numeric fields: %s)", o->field, names);
}

rc_status rc_override_card_end(rc_reader *rd, const rc_block *b, int clean)
{
    rc_status st = RC_OK, s = RC_OK;
    rd->ovr_block = NULL;
    for (int i = 0; i < rd->novr; i++) {
        rc_override *o = &rd->ovr[i];
        if (!o->in_card) continue;
        o->in_card = 0;
        /* a card with an error stopped before some of its fields */
        if (!clean) continue;
        if (o->seen == 0 && o->absent > 0)
            s = rc_set_fail(rd, o, b->name, o->field,
                            "not on a line of the deck's card (an optional line it lacks, or a field its /BEGIN "
                            "version's layout does not have): write the line in the deck to set it");
        else if (o->seen == 0) s = rc_override_unknown(rd, b, o);
        else if (o->index == 0 && o->seen > 1)
            s = rc_set_fail(rd, o, b->name, o->field,
                            "occurs %d times in the card: write %s[k], k = 1..%d, for the k-th in reading order", o->seen,
                            o->field, o->seen);
        else if (o->index > o->seen)
            s = rc_set_fail(rd, o, b->name, o->field, "occurs %d time%s in the card: no occurrence %d", o->seen,
                            o->seen == 1 ? "" : "s", o->index);
        if (s && !st) st = s;
    }
    return st;
}

rc_status rc_override_finish(rc_reader *rd)
{
    rc_status st = RC_OK, s = RC_OK;
    if (rd->novr == 0) return RC_OK;
    /* each addressed one card of the deck */
    size_t len = 1;
    for (int i = 0; i < rd->novr; i++) {
        rc_override *o = &rd->ovr[i];
        char card[100];
        rc_override_card(o, card, sizeof card);
        len += strlen(o->arg) + 2;
        if (o->ncards == 0) s = rc_set_fail(rd, o, NULL, NULL, "no card %s in the deck", card);
        else if (o->ncards > 1)
            s = rc_set_fail(rd, o, NULL, NULL, "%d cards %s in the deck: --set addresses one card (by its id)",
                            o->ncards, card);
        if (s && !st) st = s;
    }
    /* the list, for the results file: "ARG; ARG" */
    char *l = malloc(len);
    if (!l) return rc_case_nomem(rd);
    size_t w = 0;
    for (int i = 0; i < rd->novr; i++) w += (size_t)snprintf(l + w, len - w, "%s%s", i ? "; " : "", rd->ovr[i].arg);
    free(rd->c->overrides);
    rd->c->overrides = l;
    return st;
}
