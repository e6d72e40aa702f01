/*
 * Cards of bodies and nodes: /NODE, /GRNOD/NODE, /RBODY, /PART,
 * /GRPART/PART, and the lists of surfaces /LINE/SURF.
 * Layouts are field tables (case_internal.h), documented in
 * docs/case-format.md; references between cards are resolved by the
 * compiler (src/model). Values ricochet cannot honour yet are rejected with
 * "not supported yet", never ignored.
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>


/* ======================================================================
 * /NODE and /GRNOD
 * ====================================================================== */

/* /NODE: lines node_ID X Y Z. */
rc_status rc_card_node(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int n = rc_block_trim(b);
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_UNIT, NULL, "/NODE"))) return st;
    for (int i = 0; i < n; i++) {
        /* one node per line */
        RC_GROW(rd, c->node, rd->capnode, c->nnode);
        rc_case_node *nd = &c->node[c->nnode++];
        rc_field f[] = {RC_F_INT("node_ID", &nd->id, 0, RC_FF_POS), RC_F_REAL("X", &nd->x[0], 0, 0),
                        RC_F_REAL("Y", &nd->x[1], 0, 0), RC_F_REAL("Z", &nd->x[2], 0, 0)};
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, RC_NF(f)))) return st;
        nd->loc = b->lines[i].loc;
        if ((st = rc_note_id(rd, RC_IDK_NODE, nd->id, &nd->loc, b->hdr->text))) return st;
    }
    return RC_OK;
}

/* /GRNOD/NODE/grnod_ID: title, then up to 10 node ids per line. */
rc_status rc_card_grnod(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "grnod_ID", "/GRNOD/NODE/grnod_ID")))
        return st;
    RC_GROW(rd, c->grnod, rd->capgrnod, c->ngrnod);
    rc_case_grnod *g = &c->grnod[c->ngrnod++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, g->title, "node_ID1 ... node_ID10", &nd))) return st;
    for (int i = 1; i <= nd; i++) {
        /* ten 10-column fields; blank or 0 fields are skipped */
        int v[10];
        rc_field f[10];
        for (int k = 0; k < 10; k++) {
            rc_field fk = RC_F_INT("node_ID", &v[k], 0, RC_FF_NONNEG);
            f[k] = fk;
        }
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, 10))) return st;
        for (int k = 0; k < 10; k++) {
            if (v[k] == 0) continue;
            RC_GROW(rd, g->nodes, cap, g->n);
            RC_GROW(rd, g->node_loc, lcap, g->n);
            g->node_loc[g->n] = b->lines[i].loc;
            g->nodes[g->n++] = v[k];
        }
    }
    return rc_note_id(rd, RC_IDK_GRNOD, g->id, &g->loc, b->hdr->text);
}

/* ======================================================================
 * /RBODY
 * ====================================================================== */

/* /RBODY/rbody_ID (Radioss 2017..2026): title; main node, sensor, skew,
 * Ispher, Mass, secondary nodes, Ikrem, ICoG, surface; Jxx Jyy Jzz; Jxy Jyz
 * Jxz; optional line 4 Ioptoff, Iexpams (internal), Ifail (2021+); line 5
 * FN FT expN expT when Ifail = 1. The mass and inertia are added to those
 * of the mesh by the model stage (model/massprop.c). */
rc_status rc_card_rbody(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "rbody_ID", "/RBODY/rbody_ID"))) return st;
    RC_GROW(rd, c->rbody, rd->caprbody, c->nrbody);
    rc_case_rbody *r = &c->rbody[c->nrbody++];
    r->id = b->id;
    r->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, r->title, 3, 5,
                            "node_ID..., Jxx Jyy Jzz, Jxy Jyz Jxz[, Ioptoff Iexpams Ifail[, FN FT "
                            "expN expT]]",
                            &nd)))
        return st;
    for (int k = 0; k < 3; k++) r->line_loc[k] = b->lines[k + 1].loc;

    rc_field l1[] = {
        RC_F_INT("node_ID", &r->node_id, 0, RC_FF_POS),
        RC_F_INT("sens_ID", &r->sens_id, 0, RC_FF_NONNEG),
        RC_F_INT("Skew_ID", &r->skew_id, 0, RC_FF_NONNEG),
        RC_F_SET("Ispher", &r->ispher, 0, 0, 0xFu, 0, NULL),
        RC_F_REAL("Mass", &r->mass, 0, RC_FF_NONNEG),
        RC_F_INT("grnd_ID", &r->grnod_id, 0, RC_FF_NONNEG),
        RC_F_SET("Ikrem", &r->ikrem, 0, 0, 0x3u, 0, NULL),
        RC_F_SET("ICoG", &r->icog, 0, 0, 0x1Fu, 0, NULL),
        RC_F_INT("surf_ID", &r->surf_id, 0, RC_FF_NONNEG),
    };
    /* lines 2 and 3: the added inertia, skew axes (global without skew) */
    rc_field l2[] = {RC_F_REAL("Jxx", &r->J[0], 0, RC_FF_NONNEG),
                     RC_F_REAL("Jyy", &r->J[1], 0, RC_FF_NONNEG),
                     RC_F_REAL("Jzz", &r->J[2], 0, RC_FF_NONNEG)};
    rc_field l3[] = {RC_F_REAL("Jxy", &r->J[3], 0, 0), RC_F_REAL("Jyz", &r->J[4], 0, 0),
                     RC_F_REAL("Jxz", &r->J[5], 0, 0)};
    /* line 4: HMPP decomposition flag, an internal AMS flag, failure */
    rc_field l4[] = {RC_F_INT("Ioptoff", &r->ioptoff, 0, 0), RC_F_INT("Iexpams", &r->iexpams, 0, 0),
                     RC_F_SET("Ifail", &r->ifail, 0, 0, 0x3u, 0, NULL)};
    rc_field l5[] = {RC_F_REAL("FN", &r->fail[0], 0, 0), RC_F_REAL("FT", &r->fail[1], 0, 0),
                     RC_F_REAL("expN", &r->fail[2], 0, 0), RC_F_REAL("expT", &r->fail[3], 0, 0)};
    rc_field *lf[5] = {l1, l2, l3, l4, l5};
    const int nf[5] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5)};
    for (int i = 0; i < nd; i++) {
        if (i == 4 && r->ifail != 1 && b->lines[5].len == 0) break; /* blank: harmless */
        if (i == 4 && r->ifail != 1)
            return rc_case_fail(rd, &b->lines[5].loc, b->name, NULL,
                                "unexpected data line: line 5 (FN FT expN expT) follows Ifail = 1 "
                                "only, got Ifail = %d",
                                r->ifail);
        if ((st = rc_parse_line(rd, b, &b->lines[i + 1], lf[i], nf[i]))) return st;
        r->line_loc[i] = b->lines[i + 1].loc;
    }
    /* fields with a Radioss meaning ricochet does not model: warned */
    if (r->surf_id &&
        (st = rc_case_warn(rd, &r->line_loc[0], "card %s, field surf_ID: envelope surface %d ignored "
                     "(ricochet's contacts use the analytic surfaces of the body)",
                     b->name, r->surf_id)))
        return st;
    if (r->ifail &&
        (st = rc_case_warn(rd, &r->line_loc[3], "card %s, field Ifail: rigid body failure ignored: the "
                     "body never fails", b->name)))
        return st;
    return rc_note_id(rd, RC_IDK_RBODY, r->id, &r->loc, b->hdr->text);
}

/* ======================================================================
 * /PART, /GRPART/PART
 * ====================================================================== */

/* Lines first..last of block b: up to ten ids a line (10 columns each),
 * every field named `name`, >= 0; blank and 0 fields are skipped. The ids
 * are appended to *ids (count *n, capacity *cap). */
static rc_status rc_id_lines(rc_reader *rd, const rc_block *b, int first, int last,
                             const char *name, int **ids, rc_loc **locs, int *n, int *cap,
                             int *lcap)
{
    rc_status st;
    for (int i = first; i <= last; i++) {
        int v[10];
        rc_field f[10];
        for (int k = 0; k < 10; k++) {
            rc_field fk = RC_F_INT(name, &v[k], 0, RC_FF_NONNEG);
            f[k] = fk;
        }
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, 10))) return st;
        for (int k = 0; k < 10; k++) {
            if (v[k] == 0) continue;
            RC_GROW(rd, *ids, *cap, *n);
            RC_GROW(rd, *locs, *lcap, *n);
            (*locs)[*n] = b->lines[i].loc;
            (*ids)[(*n)++] = v[k];
        }
    }
    return RC_OK;
}

/* /PART/part_ID: title; the Radioss line prop_ID mat_ID subset_ID Thick;
 * optionally ricochet's line 2, rbody_ID and up to nine surface ids, then up
 * to ten surface ids a line (a part as a subset of a body's surfaces, for
 * /FRICTION). Without line 2 the part is a part of the mesh: its elements
 * (/SHELL/part_ID, ...) give their body its mass. */
rc_status rc_card_part(rc_reader *rd, const rc_block *b)
{
    static const char desc[] = "prop_ID mat_ID subset_ID Thick[, rbody_ID surf_ID1 ... surf_ID9"
                               "[, surf_ID1 ... surf_ID10 ...]]";
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0, v[10];
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "part_ID", "/PART/part_ID"))) return st;
    RC_GROW(rd, c->part, rd->cappart, c->npart);
    rc_case_part *p = &c->part[c->npart++];
    p->id = b->id;
    p->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, p->title, desc, &nd))) return st;
    if (nd < 1)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "prop_ID",
                            "expected a title line and the line prop_ID mat_ID subset_ID Thick, "
                            "found %d data line%s",
                            nd, nd == 1 ? "" : "s");

    /* line 1 (Radioss): property, material, subset, (contact) thickness */
    rc_field l1[] = {RC_F_INT("prop_ID", &p->prop_id, 0, RC_FF_NONNEG),
                     RC_F_INT("mat_ID", &p->mat_id, 0, RC_FF_NONNEG),
                     RC_F_INT("subset_ID", NULL, 0, 0), RC_F_REAL("Thick", NULL, 0, 0)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    p->prop_loc = b->lines[1].loc;
    if (nd < 2) return rc_note_id(rd, RC_IDK_PART, p->id, &p->loc, b->hdr->text);

    /* line 2 (ricochet): the body, then surface ids; further lines: surface ids */
    rc_field l2[10];
    for (int k = 0; k < 10; k++) {
        rc_field fk = RC_F_INT(k ? "surf_ID" : "rbody_ID", &v[k], 0, RC_FF_NONNEG);
        l2[k] = fk;
    }
    p->ext = 1;
    p->line_loc = b->lines[2].loc;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, 10))) return st;
    p->rbody_id = v[0];
    for (int k = 1; k < 10; k++) {
        if (v[k] == 0) continue;
        RC_GROW(rd, p->surf, cap, p->nsurf);
        RC_GROW(rd, p->surf_loc, lcap, p->nsurf);
        p->surf_loc[p->nsurf] = p->line_loc;
        p->surf[p->nsurf++] = v[k];
    }
    if ((st = rc_id_lines(rd, b, 3, nd, "surf_ID", &p->surf, &p->surf_loc, &p->nsurf, &cap, &lcap)))
        return st;

    /* a part fixed in space is a set of surfaces */
    if (p->rbody_id == 0 && p->nsurf == 0)
        return rc_case_fail(rd, &p->line_loc, b->name, "rbody_ID",
                            "expected a rigid body id > 0, or at least one surface id "
                            "(rbody_ID = 0: the part's surfaces are fixed in space), got %s "
                            "and no surface id",
                            l2[0].got);
    return rc_note_id(rd, RC_IDK_PART, p->id, &p->loc, b->hdr->text);
}

/* /GRPART/PART/grpart_ID: title, then up to 10 part ids per line.
 * /GRPART/GRPART/grpart_ID: the same with part group ids (expanded by
 * rc_cards_grpart_finish). */
rc_status rc_card_grpart(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0;
    rc_status st;
    const int by_group = strcmp(b->kw[1], "GRPART") == 0;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "grpart_ID",
                        by_group ? "/GRPART/GRPART/grpart_ID" : "/GRPART/PART/grpart_ID")))
        return st;
    RC_GROW(rd, c->grpart, rd->capgrpart, c->ngrpart);
    rc_case_grpart *g = &c->grpart[c->ngrpart++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    g->by_group = by_group;
    if ((st = rc_var_lines(rd, b, g->title, by_group ? "grpart_ID1 ... grpart_ID10" : "part_ID1 ... part_ID10",
                           &nd)))
        return st;
    if ((st = rc_id_lines(rd, b, 1, nd, by_group ? "grpart_ID" : "part_ID", &g->parts, &g->part_loc, &g->n, &cap,
                          &lcap)))
        return st;
    return rc_note_id(rd, RC_IDK_GRPART, g->id, &g->loc, b->hdr->text);
}

/* /LINE/SURF/line_ID: title, then up to 10 surface ids per line (the
 * edges of those surfaces: the sides of /INTER/TYPE11, resolved by
 * model/type7.c). */
rc_status rc_card_line(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "line_ID", "/LINE/SURF/line_ID"))) return st;
    RC_GROW(rd, c->line, rd->capline, c->nline);
    rc_case_line *l = &c->line[c->nline++];
    l->id = b->id;
    l->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, l->title, "surf_ID1 ... surf_ID10", &nd))) return st;
    if ((st = rc_id_lines(rd, b, 1, nd, "surf_ID", &l->surf, &l->surf_loc, &l->n, &cap, &lcap))) return st;
    if (l->n == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "surf_ID",
                            "expected at least one surface id (up to ten a line, 10 columns each), got none");
    return rc_note_id(rd, RC_IDK_LINE, l->id, &l->loc, b->hdr->text);
}

/* Expand /GRPART/GRPART group gi into its parts (its nested groups first);
 * `state`: 0 not yet, 1 being expanded (a cycle when met again), 2 done. */
static rc_status rc_grpart_expand(rc_reader *rd, int gi, char *state)
{
    rc_case *c = rd->c;
    rc_case_grpart *g = &c->grpart[gi];
    char card[48];
    snprintf(card, sizeof card, "/GRPART/GRPART/%d", g->id);
    if (state[gi] == 2 || !g->by_group) return RC_OK;
    state[gi] = 1;
    int *parts = NULL, n = 0, cap = 0, lcap = 0;
    rc_loc *locs = NULL;
    rc_status st = RC_OK;
    for (int k = 0; k < g->n && !st; k++) {
        int gj = -1;
        for (int q = 0; q < c->ngrpart && gj < 0; q++)
            if (c->grpart[q].id == g->parts[k]) gj = q;
        const rc_loc at = rc_loc_at(g->part_loc, k, g->loc);
        if (gj < 0) {
            st = rc_case_fail(rd, &at, card, "grpart_ID", "expected the id of a /GRPART, got %d (no such group)",
                              g->parts[k]);
            break;
        }
        if (state[gj] == 1) {
            st = rc_case_fail(rd, &at, card, "grpart_ID",
                              gj == gi ? "group %d names itself" : "the groups of /GRPART/%d form a cycle (through /GRPART/%d)",
                              g->parts[k], g->id);
            break;
        }
        if ((st = rc_grpart_expand(rd, gj, state))) break;
        const rc_case_grpart *h = &c->grpart[gj];
        for (int j = 0; j < h->n; j++) {
            int seen = 0;
            for (int u = 0; u < n && !seen; u++) seen = parts[u] == h->parts[j];
            if (seen) continue;
            void *np = rc_case_grow(rd, parts, &cap, n, sizeof *parts), *nl = NULL;
            if (np) parts = np;
            if (np) nl = rc_case_grow(rd, locs, &lcap, n, sizeof *locs);
            if (!np || !nl) { st = RC_ENOMEM; break; }
            locs = nl;
            parts[n] = h->parts[j];
            locs[n++] = at; /* a part of a nested group: the line naming that group */
        }
    }
    if (st) {
        free(parts);
        free(locs);
        return st;
    }
    free(g->parts);
    free(g->part_loc);
    g->parts = parts;
    g->part_loc = locs;
    g->n = n;
    state[gi] = 2;
    return RC_OK;
}

rc_status rc_cards_grpart_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    char *state = calloc((size_t)c->ngrpart + 1, 1);
    if (!state) return rc_case_nomem(rd);
    rc_status st = RC_OK;
    for (int k = 0; k < c->ngrpart && !st; k++) st = rc_grpart_expand(rd, k, state);
    free(state);
    return st;
}
