/*
 * Cards of bodies and nodes: /NODE, /GRNOD/NODE, /RBODY, /PART,
 * /GRPART/PART.
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

static const char rc_note_skew[] = "(skew frames)";
static const char rc_note_sensor[] = "(sensors)";

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

/* Cholesky test of the inertia tensor [[Jxx,Jxy,Jxz],[Jxy,Jyy,Jyz],
 * [Jxz,Jyz,Jzz]]: 0 when positive definite, else the failing pivot (1..3).
 * A pivot must exceed RC_CASE_INERTIA_RTOL times its diagonal term. */
static int rc_inertia_pivot(const double J[6])
{
    double l11, l21, l31, l22, l32, d;
    if (!(J[0] > 0)) return 1;
    l11 = sqrt(J[0]);
    l21 = J[3] / l11;
    l31 = J[5] / l11;
    d = J[1] - l21 * l21;
    if (!(d > RC_CASE_INERTIA_RTOL * J[1])) return 2;
    l22 = sqrt(d);
    l32 = (J[4] - l21 * l31) / l22;
    d = J[2] - l31 * l31 - l32 * l32;
    if (!(d > RC_CASE_INERTIA_RTOL * J[2])) return 3;
    return 0;
}

/* /RBODY/rbody_ID: title; main node, flags, mass; Jxx Jyy Jzz; Jxy Jyz
 * Jxz; optional Ioptoff Ifail. */
rc_status rc_card_rbody(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, unused = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "rbody_ID", "/RBODY/rbody_ID"))) return st;
    RC_GROW(rd, c->rbody, rd->caprbody, c->nrbody);
    rc_case_rbody *r = &c->rbody[c->nrbody++];
    r->id = b->id;
    r->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, r->title, 3, 4, "node_ID..., Jxx Jyy Jzz, Jxy Jyz Jxz", &nd)))
        return st;
    for (int k = 0; k < 3; k++) r->line_loc[k] = b->lines[k + 1].loc;

    /* line 1: main node, unsupported options must be 0, mass > 0 */
    rc_field l1[] = {
        RC_F_INT("node_ID", &r->node_id, 0, RC_FF_POS),
        RC_F_INTN("sens_ID", &unused, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_sensor),
        RC_F_INTN("Skew_ID", &r->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
        RC_F_SET("Ispher", &r->ispher, 0, 0, 0xFu, 0, NULL),
        RC_F_REAL("Mass", &r->mass, 0, RC_FF_POS),
        RC_F_INT("grnd_ID", &r->grnod_id, 0, RC_FF_NONNEG),
        RC_F_INT("Ikrem", NULL, 0, 0),
        RC_F_SET("ICoG", &r->icog, 0, 0, 0x1Fu, RC_BIT(0) | RC_BIT(1) | RC_BIT(3),
                 "(ICoG 2 and 4 need the secondary nodes' masses)"),
        RC_F_INTN("surf_ID", &unused, RC_FF_NONNEG | RC_FF_ONLY0, "(envelope surfaces)"),
    };
    /* lines 2 and 3: the inertia tensor in global axes */
    rc_field l2[] = {RC_F_REAL("Jxx", &r->J[0], 0, RC_FF_POS), RC_F_REAL("Jyy", &r->J[1], 0, RC_FF_POS),
                     RC_F_REAL("Jzz", &r->J[2], 0, RC_FF_POS)};
    rc_field l3[] = {RC_F_REAL("Jxy", &r->J[3], 0, 0), RC_F_REAL("Jyz", &r->J[4], 0, 0),
                     RC_F_REAL("Jxz", &r->J[5], 0, 0)};
    /* line 4: HMPP decomposition flag (no meaning here), failure */
    rc_field l4[] = {RC_F_INT("Ioptoff", NULL, 0, 0),
                     RC_F_INTN("Ifail", &unused, RC_FF_ONLY0, "(rigid body failure)")};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
    if (nd == 4 && (st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;

    /* the tensor as a whole must be positive definite */
    int piv = rc_inertia_pivot(r->J);
    if (piv)
        return rc_case_fail(rd, &b->lines[3].loc, b->name, "Jxy Jyz Jxz",
                            "expected a positive-definite inertia tensor, got Jxx Jyy Jzz = "
                            "%.9g %.9g %.9g and Jxy Jyz Jxz = %.9g %.9g %.9g (leading minor "
                            "%d is not positive)",
                            r->J[0], r->J[1], r->J[2], r->J[3], r->J[4], r->J[5], piv);
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

/* /PART/part_ID (ricochet's reading: a rigid body, or a named subset of its
 * surfaces): title; the Radioss line prop_ID mat_ID subset_ID Thick (read,
 * ignored); rbody_ID and up to nine surface ids; then up to ten surface ids
 * a line. */
rc_status rc_card_part(rc_reader *rd, const rc_block *b)
{
    static const char desc[] = "prop_ID mat_ID subset_ID Thick, rbody_ID surf_ID1 ... surf_ID9"
                               "[, surf_ID1 ... surf_ID10 ...]";
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0, v[10];
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "part_ID", "/PART/part_ID"))) return st;
    RC_GROW(rd, c->part, rd->cappart, c->npart);
    rc_case_part *p = &c->part[c->npart++];
    p->id = b->id;
    p->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, p->title, desc, &nd))) return st;

    /* the ricochet line is required: a Radioss /PART alone names no body */
    if (b->n < 3)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "rbody_ID",
                            "expected 2 data lines at least (%s), found %d: line 2 (rbody_ID "
                            "surf_ID1 ... surf_ID9) is a ricochet extension, required: a part "
                            "is a rigid body or a named subset of its surfaces",
                            desc, b->n - 1);
    if (nd < 2) nd = 2; /* a blank line 2 is a line of defaults */

    /* line 1 (Radioss): property, material, subset, thickness */
    rc_field l1[] = {RC_F_INT("prop_ID", NULL, 0, 0), RC_F_INT("mat_ID", NULL, 0, 0),
                     RC_F_INT("subset_ID", NULL, 0, 0), RC_F_REAL("Thick", NULL, 0, 0)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;

    /* line 2: the body, then surface ids; further lines: surface ids */
    rc_field l2[10];
    for (int k = 0; k < 10; k++) {
        rc_field fk = RC_F_INT(k ? "surf_ID" : "rbody_ID", &v[k], 0, RC_FF_NONNEG);
        l2[k] = fk;
    }
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

/* /GRPART/PART/grpart_ID: title, then up to 10 part ids per line. */
rc_status rc_card_grpart(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0, lcap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "grpart_ID", "/GRPART/PART/grpart_ID")))
        return st;
    RC_GROW(rd, c->grpart, rd->capgrpart, c->ngrpart);
    rc_case_grpart *g = &c->grpart[c->ngrpart++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, g->title, "part_ID1 ... part_ID10", &nd))) return st;
    if ((st = rc_id_lines(rd, b, 1, nd, "part_ID", &g->parts, &g->part_loc, &g->n, &cap, &lcap)))
        return st;
    return rc_note_id(rd, RC_IDK_GRPART, g->id, &g->loc, b->hdr->text);
}
