/*
 * Cards of friction: /FRICTION (Coulomb, Renard, ricochet's filters) and
 * /FRIC_ORIENT (orthotropic directions).
 * Layouts are field tables (case_internal.h), documented in
 * docs/case-format.md; references between cards are resolved by the
 * compiler (src/model). Values ricochet cannot honour yet are rejected with
 * "not supported yet", never ignored.
 */
#include "case/case_internal.h"
#include "base/error.h"
#include "case/case_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>


/* ======================================================================
 * /FRICTION, /FRIC_ORIENT
 * ====================================================================== */

/* Renard law (Ifric 3) on one coefficient set: 0 < C5 < C6, C1 <= C3,
 * C2 <= C3, C4 <= C1, C4 <= C2. `f` are the fields C1..C5 of line `ln`. */
static rc_status rc_renard(rc_reader *rd, const rc_block *b, const rc_line *ln,
                           const rc_field *f, const rc_case_fricset *s)
{
    const double *k = s->c;
    if (!(k[4] > 0 && k[4] < k[5]))
        return rc_case_fail(rd, &ln->loc, b->name, "C5",
                            "expected 0 < C5 < C6 = %.15g (Renard: 0 < V_cr1 < V_cr2), got %s",
                            k[5], f[4].got);
    if (!(k[0] <= k[2]))
        return rc_case_fail(rd, &ln->loc, b->name, "C1",
                            "expected C1 <= C3 = %.15g (Renard: mu_s <= mu_max), got %s", k[2],
                            f[0].got);
    if (!(k[1] <= k[2]))
        return rc_case_fail(rd, &ln->loc, b->name, "C2",
                            "expected C2 <= C3 = %.15g (Renard: mu_d <= mu_max), got %s", k[2],
                            f[1].got);
    if (!(k[3] <= k[0]))
        return rc_case_fail(rd, &ln->loc, b->name, "C4",
                            "expected C4 <= C1 = %.15g (Renard: mu_min <= mu_s), got %s", k[0],
                            f[3].got);
    if (!(k[3] <= k[1]))
        return rc_case_fail(rd, &ln->loc, b->name, "C4",
                            "expected C4 <= C2 = %.15g (Renard: mu_min <= mu_d), got %s", k[1],
                            f[3].got);
    return RC_OK;
}

/* One coefficient set of /FRICTION: C1..C5 on line l1, C6 Fric VISF on
 * line l2; the Renard checks when Ifric = 3. */
static rc_status rc_fricset(rc_reader *rd, const rc_block *b, const rc_line *l1,
                            const rc_line *l2, int ifric, rc_case_fricset *s)
{
    rc_status st;
    rc_field f1[] = {RC_F_REALD("C1", &s->c[0], 0, 0, 0), RC_F_REALD("C2", &s->c[1], 0, 0, 0),
                     RC_F_REALD("C3", &s->c[2], 0, 0, 0), RC_F_REALD("C4", &s->c[3], 0, 0, 0),
                     RC_F_REALD("C5", &s->c[4], 0, 0, 0)};
    rc_field f2[] = {RC_F_REALD("C6", &s->c[5], 0, 0, 0),
                     RC_F_REALD("Fric", &s->fric, 0, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("VISF", &s->visf, 1, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE)};
    /* units of C1..C6: none for Coulomb, velocities V_cr1, V_cr2 for Renard;
     * the laws 1 and 2 mix pressures and velocities: not converted */
    for (int k = 0; k < 5; k++) f1[k].dim = ifric == 0 || ifric == 3 ? RC_D_NONE : 0;
    f2[0].dim = ifric == 0 ? RC_D_NONE : ifric == 3 ? RC_D_V : 0;
    if (ifric == 3) f1[4].dim = RC_D_V;
    if ((st = rc_parse_line(rd, b, l1, f1, RC_NF(f1)))) return st;
    if ((st = rc_parse_line(rd, b, l2, f2, RC_NF(f2)))) return st;
    return ifric == 3 ? rc_renard(rd, b, l1, f1, s) : RC_OK;
}

/* /FRICTION/fric_ID: title; Ifric Ifiltr Xfreq Iform, then ricochet's
 * Dt_ref Area; the default set (C1..C5; C6 Fric VISF); then part-pair
 * groups of 3 lines, 5 when Idir = 1:
 * grpart_ID1 grpart_ID2 part_ID1 part_ID2 (unused) Idir; direction 1 set;
 * [direction 2 set]. */
rc_status rc_card_friction(rc_reader *rd, const rc_block *b)
{
    /* the lines of a group: first field (for messages) and description */
    static const char *const gfield[5] = {"grpart_ID1", "C1 C2 C3 C4 C5", "C6 Fric VISF",
                                          "C1 C2 C3 C4 C5", "C6 Fric VISF"};
    static const char *const gdesc[5] = {
        "grpart_ID1 grpart_ID2 part_ID1 part_ID2 Idir", "C1 C2 C3 C4 C5", "C6 Fric VISF",
        "direction 2: C1 C2 C3 C4 C5", "direction 2: C6 Fric VISF"};
    static const char *const side[2][2] = {{"grpart_ID1", "part_ID1"},
                                           {"grpart_ID2", "part_ID2"}};
    rc_case *c = rd->c;
    int nd, cap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "fric_ID", "/FRICTION/fric_ID"))) return st;
    RC_GROW(rd, c->friction, rd->capfriction, c->nfriction);
    rc_case_friction *fr = &c->friction[c->nfriction++];
    fr->id = b->id;
    fr->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, fr->title, 3, b->n > 0 ? b->n - 1 : 0,
                            "Ifric Ifiltr Xfreq Iform Dt_ref Area, C1 C2 C3 C4 C5, C6 Fric "
                            "VISF[, part-pair groups]",
                            &nd)))
        return st;
    for (int k = 0; k < 3; k++) fr->line_loc[k] = b->lines[k + 1].loc;

    /* line A: law, filter, penalty formulation (0 means 1); ricochet
     * extensions: reference step of Ifiltr 1, 2 and pressure area */
    rc_field la[] = {RC_F_SET("Ifric", &fr->ifric, 0, 0, 0xFu, 0, NULL),
                     RC_F_SET("Ifiltr", &fr->ifiltr, 0, 0, 0xFu, 0, NULL),
                     RC_F_REALD("Xfreq", &fr->xfreq, 1, 0, RC_D_NONE),
                     RC_F_SET("Iform", &fr->iform, 1, RC_FF_ZDEF, 0xFu, 0, NULL),
                     RC_F_REALD("Dt_ref", &fr->dt_ref, 0, RC_FF_NONNEG, RC_D_T),
                     RC_F_REALD("Area", &fr->area, 0, RC_FF_NONNEG, RC_D_AREA)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], la, RC_NF(la)))) return st;
    /* Ifiltr 3: Xfreq is a frequency [1/s] in the card's time unit */
    if (fr->ifiltr == 3 && rc_units_convert(rd)) fr->xfreq /= rd->cur_units[2];
    if ((fr->ifiltr == 1 || fr->ifiltr == 2) && !(fr->xfreq >= 0 && fr->xfreq <= 1))
        return rc_case_fail(rd, &fr->line_loc[0], b->name, "Xfreq",
                            "expected a filtering coefficient in [0, 1] for Ifiltr = %d, got %s",
                            fr->ifiltr, la[2].got);
    if (fr->ifiltr == 3 && !(fr->xfreq > 0))
        return rc_case_fail(rd, &fr->line_loc[0], b->name, "Xfreq",
                            "expected a cut-off frequency > 0 [Hz] for Ifiltr = 3, got %s",
                            la[2].got);
    /* Radioss: Xfreq = 0 switches the filter off */
    if (fr->xfreq == 0) fr->ifiltr = 0;
    /* Ifiltr 1, 2 give a coefficient per explicit step: which step? */
    if ((fr->ifiltr == 1 || fr->ifiltr == 2) && !(fr->dt_ref > 0))
        return rc_case_fail(rd, &fr->line_loc[0], b->name, "Dt_ref",
                            "Ifiltr = %d gives its coefficient per explicit time step: expected "
                            "the reference step Dt_ref > 0 [s] (ricochet extension, columns "
                            "51-70), got %s",
                            fr->ifiltr, la[4].got);

    /* lines B and C: the default set */
    if ((st = rc_fricset(rd, b, &b->lines[2], &b->lines[3], fr->ifric, &fr->def))) return st;

    /* the groups, as many as the lines hold; blank lines after the last
     * group are ignored, blank lines inside a group are lines of defaults */
    int last = rc_block_trim(b);
    for (int i = 4, g = 1; i < last; g++) {
        const rc_line *ln = &b->lines[i];
        RC_GROW(rd, fr->pair, cap, fr->npair);
        rc_case_fricpair *pr = &fr->pair[fr->npair++];
        pr->loc = ln->loc;
        rc_field l1[] = {RC_F_INT("grpart_ID1", &pr->grpart1, 0, RC_FF_NONNEG),
                         RC_F_INT("grpart_ID2", &pr->grpart2, 0, RC_FF_NONNEG),
                         RC_F_INT("part_ID1", &pr->part1, 0, RC_FF_NONNEG),
                         RC_F_INT("part_ID2", &pr->part2, 0, RC_FF_NONNEG), RC_F_SKIP(10),
                         RC_F_SET("Idir", &pr->idir, 0, 0, 0x3u, 0, NULL)};
        /* Radioss 2018 and 2019: no Idir (isotropic only) */
        if ((st = rc_parse_line(rd, b, ln, l1, rc_layout_version(rd) >= 2020 ? RC_NF(l1) : 4)))
            return st;

        /* each side names a part group or a part (the group wins, Radioss) */
        const int grp[2] = {pr->grpart1, pr->grpart2}, prt[2] = {pr->part1, pr->part2};
        for (int e = 0; e < 2; e++) {
            char fld[32];
            snprintf(fld, sizeof fld, "%s %s", side[e][0], side[e][1]);
            if (grp[e] == 0 && prt[e] == 0)
                return rc_case_fail(rd, &ln->loc, b->name, fld,
                                    "expected a part group or a part for side %d of part-pair "
                                    "group %d (%s or %s > 0), got both blank or 0",
                                    e + 1, g, side[e][0], side[e][1]);
            if (grp[e] != 0 && prt[e] != 0 &&
                (st = rc_case_warn(rd, &ln->loc,
                                   "card %s: %s = %d ignored: %s = %d is given (Radioss rule)",
                                   b->name, side[e][1], prt[e], side[e][0], grp[e])))
                return st;
        }

        /* 3 lines, 5 with a second direction */
        int need = pr->idir ? 5 : 3, have = b->n - i;
        if (have < need)
            return rc_case_fail(rd, &ln->loc, b->name, gfield[have],
                                "part-pair group %d (Idir = %d, starting on this line) is "
                                "truncated: expected %d lines, found %d; missing line %d of "
                                "the group (%s)",
                                g, pr->idir, need, have, have + 1, gdesc[have]);
        for (int d = 0; d <= pr->idir; d++)
            if ((st = rc_fricset(rd, b, &b->lines[i + 1 + 2 * d], &b->lines[i + 2 + 2 * d],
                                 fr->ifric, &pr->set[d])))
                return st;
        i += need;
    }
    return rc_note_id(rd, RC_IDK_FRICTION, fr->id, &fr->loc, b->hdr->text);
}

/* The friction law written on a penalty interface card (/INTER/TYPE7,
 * TYPE19, TYPE24, TYPE25): line 6's Ifric Ifiltr Xfreq (fields f6[0..2],
 * read from b->lines[6]), then Radioss's law lines after line 6: C1..C5
 * when Ifric > 0, C6 when Ifric > 1 (five and one fields of 20). A law or
 * a filter becomes a /FRICTION card of the same values (Iform, Fric and
 * VISF the interface's: Iform 0, 1, 1000 the viscous form, 2 the
 * incremental one; TYPE24 and TYPE25, which have no Iform, pass 2, the
 * form of their own Coulomb Fric; no part pairs, no Dt_ref or Area) with
 * id < 0,
 * named by the interface's fric_id; the compiler applies it to that
 * interface alone (model/friction.c). A fric_ID on the card wins, as in
 * Radioss. *nlaw: the law lines read (0, 1 or 2); nd: the card's data
 * lines. */
rc_status rc_inter_friction(rc_reader *rd, const rc_block *b, int nd, const rc_field *f6, int ifric, int ifiltr,
                            double xfreq, int iform, double fric, double visf, int *fric_id, int *nlaw)
{
    rc_case *c = rd->c;
    rc_status st;
    const rc_loc *l6 = &b->lines[6].loc;
    *nlaw = 0;
    if (ifric < 0 || ifric > 3)
        return rc_case_fail(rd, l6, b->name, "Ifric",
                            "expected 0 (Coulomb: Fric), 1 (generalised viscous), 2 (modified Darmstad) or 3 "
                            "(Renard), got %s",
                            f6[0].got);
    if (ifiltr < 0 || ifiltr > 3)
        return rc_case_fail(rd, l6, b->name, "Ifiltr",
                            "expected 0 (no filter), 1 (simple numerical), 2 (-3 dB filter with a period) or 3 "
                            "(-3 dB filter with a cut-off frequency), got %s",
                            f6[1].got);
    *nlaw = ifric > 1 ? 2 : ifric;
    if (nd < 6 + *nlaw)
        return rc_case_fail(rd, &b->lines[nd].loc, b->name, *nlaw == 2 && nd == 7 ? "C6" : "C1 C2 C3 C4 C5",
                            "Ifric %d reads %d friction law line%s after line 6 (C1 C2 C3 C4 C5%s): expected %d data "
                            "lines, got %d",
                            ifric, *nlaw, *nlaw > 1 ? "s" : "", *nlaw > 1 ? "; C6" : "", 6 + *nlaw, nd);
    /* the filter, as /FRICTION reads it: Ifiltr 3 a frequency [1/s] in the
     * card's time unit; Xfreq 0 switches a filter of 1 or 2 off */
    if (ifiltr == 3 && rc_units_convert(rd)) xfreq /= rd->cur_units[2];
    if ((ifiltr == 1 || ifiltr == 2) && !(xfreq >= 0 && xfreq <= 1))
        return rc_case_fail(rd, l6, b->name, "Xfreq",
                            "expected a filtering coefficient in [0, 1] for Ifiltr = %d, got %s", ifiltr, f6[2].got);
    if (ifiltr == 3 && !(xfreq > 0))
        return rc_case_fail(rd, l6, b->name, "Xfreq", "expected a cut-off frequency > 0 [Hz] for Ifiltr = 3, got %s",
                            f6[2].got);
    if (xfreq == 0) ifiltr = 0;
    if (ifiltr == 1 || ifiltr == 2)
        return rc_case_fail(rd, l6, b->name, "Ifiltr",
                            "got %s: not supported yet on the interface card: Ifiltr %d gives its coefficient Xfreq "
                            "per explicit time step, and ricochet's variable-step integrator has none; the card has "
                            "no column for the reference step; expected 0, 3 (a cut-off frequency), Xfreq 0 (no "
                            "filter), or the filter on a /FRICTION card with its Dt_ref, named by fric_ID",
                            f6[1].got, ifiltr);
    rc_case_fricset s = {.fric = fric, .visf = visf};
    rc_field f1[] = {RC_F_REALD("C1", &s.c[0], 0, 0, 0), RC_F_REALD("C2", &s.c[1], 0, 0, 0),
                     RC_F_REALD("C3", &s.c[2], 0, 0, 0), RC_F_REALD("C4", &s.c[3], 0, 0, 0),
                     RC_F_REALD("C5", &s.c[4], 0, 0, 0)};
    rc_field f2[] = {RC_F_REALD("C6", &s.c[5], 0, 0, 0)};
    /* the units of /FRICTION's C1..C6 (rc_fricset) */
    for (int k = 0; k < 5; k++) f1[k].dim = ifric == 3 ? RC_D_NONE : 0;
    if (ifric == 3) f1[4].dim = f2[0].dim = RC_D_V;
    if (*nlaw >= 1 && (st = rc_parse_line(rd, b, &b->lines[7], f1, RC_NF(f1)))) return st;
    if (*nlaw >= 2 && (st = rc_parse_line(rd, b, &b->lines[8], f2, RC_NF(f2)))) return st;
    if (ifric == 3 && (st = rc_renard(rd, b, &b->lines[7], f1, &s))) return st;
    if (ifric == 0 && ifiltr == 0) return RC_OK; /* the interface's own Coulomb Fric */
    if (*fric_id > 0)
        return rc_case_warn(rd, l6, "card %s: the friction of Ifric %d, Ifiltr %d is not used: fric_ID names "
                                    "/FRICTION/%d, which applies (Radioss rule)",
                            b->name, ifric, ifiltr, *fric_id);
    RC_GROW(rd, c->friction, rd->capfriction, c->nfriction);
    rc_case_friction *fr = &c->friction[c->nfriction++];
    memset(fr, 0, sizeof *fr);
    fr->id = -c->nfriction;
    snprintf(fr->owner, sizeof fr->owner, "/%s/%s/%d", b->kw[0], b->kw[1], b->id);
    fr->loc = b->hdr->loc;
    fr->line_loc[0] = *l6;
    fr->line_loc[1] = *nlaw >= 1 ? b->lines[7].loc : *l6;
    fr->line_loc[2] = *nlaw >= 2 ? b->lines[8].loc : fr->line_loc[1];
    fr->ifric = ifric;
    fr->ifiltr = ifiltr;
    fr->xfreq = xfreq;
    fr->iform = iform == 2 ? 2 : 1;
    fr->def = s;
    *fric_id = fr->id;
    return RC_OK;
}

/* /FRIC_ORIENT/fric_orient_ID: title; per part or part group two lines:
 * grpart_ID part_ID; VX VY VZ skew_ID PHI Iorth. */
rc_status rc_card_fricorient(rc_reader *rd, const rc_block *b)
{
    static const char desc[] = "grpart_ID part_ID, VX VY VZ skew_ID PHI Iorth";
    rc_case *c = rd->c;
    int nd, cap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "fric_orient_ID",
                        "/FRIC_ORIENT/fric_orient_ID")))
        return st;
    RC_GROW(rd, c->fricorient, rd->capfricorient, c->nfricorient);
    rc_case_fricorient *o = &c->fricorient[c->nfricorient++];
    o->id = b->id;
    o->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, o->title, desc, &nd))) return st;
    if (nd == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "grpart_ID part_ID",
                            "expected at least one orientation (two lines: %s), found none",
                            desc);

    /* the items, two lines each */
    for (int i = 1, n = 1; i <= nd; i += 2, n++) {
        const rc_line *ln = &b->lines[i];
        RC_GROW(rd, o->item, cap, o->n);
        rc_case_fricorient_item *it = &o->item[o->n++];
        it->loc = ln->loc;
        rc_field l1[] = {RC_F_INT("grpart_ID", &it->grpart_id, 0, RC_FF_NONNEG),
                         RC_F_INT("part_ID", &it->part_id, 0, RC_FF_NONNEG)};
        if ((st = rc_parse_line(rd, b, ln, l1, RC_NF(l1)))) return st;
        if (it->grpart_id == 0 && it->part_id == 0)
            return rc_case_fail(rd, &ln->loc, b->name, "grpart_ID part_ID",
                                "expected a part group or a part for orientation %d "
                                "(grpart_ID or part_ID > 0), got both blank or 0",
                                n);
        if (i + 1 >= b->n)
            return rc_case_fail(rd, &ln->loc, b->name, "VX VY VZ",
                                "orientation %d (starting on this line) is truncated: missing "
                                "its line 2 (VX VY VZ skew_ID PHI Iorth)",
                                n);
        rc_field l2[] = {
            RC_F_REALD("VX", &it->v[0], 0, 0, RC_D_NONE), RC_F_REALD("VY", &it->v[1], 0, 0, RC_D_NONE),
            RC_F_REALD("VZ", &it->v[2], 0, 0, RC_D_NONE),
            RC_F_INT("skew_ID", &it->skew_id, 0, RC_FF_NONNEG),
            RC_F_REALD("PHI", &it->phi, 0, 0, RC_D_NONE),
            RC_F_SET("Iorth", &it->iorth, 0, 0, 0x3u, 0, NULL)};
        if ((st = rc_parse_line(rd, b, &b->lines[i + 1], l2, RC_NF(l2)))) return st;
        it->line_loc = b->lines[i + 1].loc;
        /* Radioss: a zero vector V means the global X axis (with a skew, V
         * is the skew's X' axis: rc_cards_fricorient_finish) */
        if (!it->skew_id && it->v[0] == 0 && it->v[1] == 0 && it->v[2] == 0) {
            it->v[0] = 1;
            if ((st = rc_case_warn(rd, &b->lines[i + 1].loc,
                                   "card %s: orientation %d: V = (0, 0, 0) read as (1, 0, 0), "
                                   "as Radioss does",
                                   b->name, n)))
                return st;
        }
    }
    return rc_note_id(rd, RC_IDK_FRICORIENT, o->id, &o->loc, b->hdr->text);
}

/* Once the skews' axes are known (rc_cards_mesh_finish): an orientation
 * with a skew_ID takes V from the skew's X' axis, VX VY VZ unused (as
 * Radioss); a /SKEW/FIX only (a moving skew turns with its nodes, not
 * necessarily with the body carrying V). */
rc_status rc_cards_fricorient_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    rc_status st;
    char card[48];
    for (int o = 0; o < c->nfricorient; o++)
        for (int k = 0; k < c->fricorient[o].n; k++) {
            rc_case_fricorient_item *it = &c->fricorient[o].item[k];
            if (!it->skew_id) continue;
            snprintf(card, sizeof card, "/FRIC_ORIENT/%d", c->fricorient[o].id);
            int s = -1;
            if ((st = rc_case_ref_skew(rd, &it->line_loc, card, it->skew_id,
                                       "a friction direction from a moving skew", &s)))
                return st;
            memcpy(it->v, c->mesh->skew[s].axis[0], sizeof it->v);
        }
    return RC_OK;
}
