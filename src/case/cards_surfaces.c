/*
 * Cards of surfaces: /SURF/PLANE, /SURF/ELLIPS, and ricochet's /SURF/CYL
 * (finite cylinder, flat or rounded ends) and /SURF/BOX.
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

/* ======================================================================
 * /SURF/PLANE and /SURF/ELLIPS
 * ====================================================================== */

/* New surface of the given kind. */
static rc_case_surf *rc_new_surf(rc_reader *rd, const rc_block *b, rc_case_surf_kind kind)
{
    rc_case *c = rd->c;
    rc_case_surf *arr = rc_case_grow(rd, c->surf, &rd->capsurf, c->nsurf, sizeof *arr);
    if (!arr) return NULL;
    c->surf = arr;
    rc_case_surf *s = &c->surf[c->nsurf++];
    s->id = b->id;
    s->kind = kind;
    s->loc = b->hdr->loc;
    s->rbody_loc = b->hdr->loc;
    return s;
}

/* /SURF/PLANE/surf_ID: title; point M; point M1; ricochet: rbody_ID. */
rc_status rc_card_plane(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/PLANE/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_PLANE);
    if (!s) return RC_ENOMEM;
    if ((st = rc_card_lines(rd, b, s->title, 2, 3, "XM YM ZM, XM1 YM1 ZM1", &nd))) return st;

    /* M, M1 and the optional carrying body */
    rc_field l1[] = {RC_F_REALD("XM", &s->m[0], 0, 0, RC_D_L), RC_F_REALD("YM", &s->m[1], 0, 0, RC_D_L),
                     RC_F_REALD("ZM", &s->m[2], 0, 0, RC_D_L)};
    rc_field l2[] = {RC_F_REALD("XM1", &s->m1[0], 0, 0, RC_D_L), RC_F_REALD("YM1", &s->m1[1], 0, 0, RC_D_L),
                     RC_F_REALD("ZM1", &s->m1[2], 0, 0, RC_D_L)};
    rc_field l3[] = {RC_F_INT("rbody_ID", &s->rbody_id, 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if (nd == 3 && (st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
    if (nd == 3) s->rbody_loc = b->lines[3].loc;

    /* the normal M -> M1 must exist */
    if (s->m[0] == s->m1[0] && s->m[1] == s->m1[1] && s->m[2] == s->m1[2])
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "XM1 YM1 ZM1",
                            "expected a point M1 different from M (the normal points from M "
                            "towards M1), got M1 = M = (%.9g, %.9g, %.9g)",
                            s->m[0], s->m[1], s->m[2]);
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}

/* /SURF/ELLIPS/surf_ID: title; skew_ID n rbody_ID; centre; semi-axes.
 * Only spheres for now. */
rc_status rc_card_ellips(rc_reader *rd, const rc_block *b)
{
    static const char note[] = "(only spheres: n = 2, a = b = c)";
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/ELLIPS/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_ELLIPS);
    if (!s) return RC_ENOMEM;
    if ((st = rc_card_lines(rd, b, s->title, 3, 3, "skew_ID n rbody_ID, Xc Yc Zc, a b c", &nd)))
        return st;

    rc_field l1[] = {RC_F_INTN("skew_ID", &s->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
                     RC_F_INT("n", &s->degree, 2, RC_FF_ZDEF | RC_FF_POS),
                     RC_F_INT("rbody_ID", &s->rbody_id, 0, RC_FF_NONNEG)};
    rc_field l2[] = {RC_F_REALD("Xc", &s->c[0], 0, 0, RC_D_L), RC_F_REALD("Yc", &s->c[1], 0, 0, RC_D_L),
                     RC_F_REALD("Zc", &s->c[2], 0, 0, RC_D_L)};
    rc_field l3[] = {RC_F_REALD("a", &s->abc[0], 0, RC_FF_POS, RC_D_L), RC_F_REALD("b", &s->abc[1], 0, RC_FF_POS, RC_D_L),
                     RC_F_REALD("c", &s->abc[2], 0, RC_FF_POS, RC_D_L)};
    s->rbody_loc = b->lines[1].loc;
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;

    /* spheres only */
    if (s->degree != 2)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "n",
                            "expected 2, got %s: not supported yet %s", l1[1].got, note);
    for (int k = 1; k < 3; k++)
        if (s->abc[k] != s->abc[0])
            return rc_case_fail(rd, &b->lines[3].loc, b->name, l3[k].name,
                                "expected %.15g (= a), got %s: not supported yet %s",
                                s->abc[0], l3[k].got, note);
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}

/* ======================================================================
 * /SURF/CYL and /SURF/BOX
 * ====================================================================== */

static double norm3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* /SURF/CYL/surf_ID: title; rbody_ID Iend Icont; Xc Yc Zc; AX AY AZ; R L. */
rc_status rc_card_cyl(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/CYL/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_CYL);
    if (!s) return RC_ENOMEM;
    if ((st = rc_card_lines(rd, b, s->title, 4, 4, "rbody_ID Iend Icont, Xc Yc Zc, AX AY AZ, R L", &nd))) return st;

    rc_field l1[] = {RC_F_INT("rbody_ID", &s->rbody_id, 0, RC_FF_NONNEG),
                     RC_F_SET("Iend", &s->ends, 0, 0, 0x3u, 0, NULL),
                     RC_F_SET("Icont", &s->cmode, 0, 0, 0x3u, 0, NULL)};
    rc_field l2[] = {RC_F_REALD("Xc", &s->c[0], 0, 0, RC_D_L), RC_F_REALD("Yc", &s->c[1], 0, 0, RC_D_L),
                     RC_F_REALD("Zc", &s->c[2], 0, 0, RC_D_L)};
    rc_field l3[] = {RC_F_REALD("AX", &s->axis[0], 0, 0, RC_D_NONE), RC_F_REALD("AY", &s->axis[1], 0, 0, RC_D_NONE),
                     RC_F_REALD("AZ", &s->axis[2], 0, 0, RC_D_NONE)};
    rc_field l4[] = {RC_F_REALD("R", &s->abc[0], 0, RC_FF_POS, RC_D_L), RC_F_REALD("L", &s->length, 0, RC_FF_POS, RC_D_L)};
    s->rbody_loc = b->lines[1].loc;
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
    if (!(norm3(s->axis) > 0))
        return rc_case_fail(rd, &b->lines[3].loc, b->name, "AX AY AZ",
                            "expected a non-zero axis vector, got (0, 0, 0)");
    s->abc[1] = s->abc[2] = s->abc[0];
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}

/* /SURF/BOX/surf_ID: title; rbody_ID; Xc Yc Zc; a b c; [UX UY UZ; VX VY VZ]. */
rc_status rc_card_box(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/BOX/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_BOX);
    if (!s) return RC_ENOMEM;
    if ((st = rc_card_lines(rd, b, s->title, 3, 5, "rbody_ID, Xc Yc Zc, a b c[, UX UY UZ, VX VY VZ]", &nd)))
        return st;

    rc_field l1[] = {RC_F_INT("rbody_ID", &s->rbody_id, 0, RC_FF_NONNEG)};
    rc_field l2[] = {RC_F_REALD("Xc", &s->c[0], 0, 0, RC_D_L), RC_F_REALD("Yc", &s->c[1], 0, 0, RC_D_L),
                     RC_F_REALD("Zc", &s->c[2], 0, 0, RC_D_L)};
    rc_field l3[] = {RC_F_REALD("a", &s->abc[0], 0, RC_FF_POS, RC_D_L), RC_F_REALD("b", &s->abc[1], 0, RC_FF_POS, RC_D_L),
                     RC_F_REALD("c", &s->abc[2], 0, RC_FF_POS, RC_D_L)};
    rc_field l4[] = {RC_F_REALD("UX", &s->axis[0], 0, 0, RC_D_NONE), RC_F_REALD("UY", &s->axis[1], 0, 0, RC_D_NONE),
                     RC_F_REALD("UZ", &s->axis[2], 0, 0, RC_D_NONE)};
    rc_field l5[] = {RC_F_REALD("VX", &s->axis2[0], 0, 0, RC_D_NONE), RC_F_REALD("VY", &s->axis2[1], 0, 0, RC_D_NONE),
                     RC_F_REALD("VZ", &s->axis2[2], 0, 0, RC_D_NONE)};
    s->rbody_loc = b->lines[1].loc;
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
    /* the corners (centre +- the half-sizes along any axes) and the box's
     * extent must be numbers: a half-size near the largest double made the
     * compiler's grid of the box's faces infinite */
    const double reach = fabs(s->c[0]) + fabs(s->c[1]) + fabs(s->c[2]) + 2.0 * (s->abc[0] + s->abc[1] + s->abc[2]);
    if (!isfinite(reach) || reach > 1e300)
        return rc_case_fail(rd, &b->lines[3].loc, b->name, "a b c",
                            "the box's corners (the centre +- the half-sizes) go beyond 1e300 m: expected a centre and "
                            "half-sizes whose sum stays below 1e300 m, got a = %s, b = %s, c = %s",
                            l3[0].got, l3[1].got, l3[2].got);
    /* orientation: global axes when lines 4 and 5 are absent */
    s->axis[0] = 1.0;
    s->axis2[1] = 1.0;
    if (nd >= 4) {
        s->axis[0] = 0.0;
        if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
        if (!(norm3(s->axis) > 0))
            return rc_case_fail(rd, &b->lines[4].loc, b->name, "UX UY UZ",
                                "expected a non-zero axis vector u, got (0, 0, 0)");
    }
    if (nd >= 5) {
        s->axis2[1] = 0.0;
        if ((st = rc_parse_line(rd, b, &b->lines[5], l5, RC_NF(l5)))) return st;
    }
    /* v must not be parallel to u */
    const double *u = s->axis, *v = s->axis2;
    double w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (!(norm3(w) > 1e-9 * norm3(u) * norm3(v)))
        return rc_case_fail(rd, nd >= 5 ? &b->lines[5].loc : &b->hdr->loc, b->name, "VX VY VZ",
                            "expected an axis v not parallel to u = (%.9g, %.9g, %.9g), got (%.9g, %.9g, %.9g)",
                            u[0], u[1], u[2], v[0], v[1], v[2]);
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}

/* ======================================================================
 * /SURF/SEG and /SURF/PART (segment surfaces; model/segsurf.c builds them)
 * ====================================================================== */

/* /SURF/SEG/surf_ID: title; one segment a line: seg_ID node_ID1..node_ID4
 * (node_ID4 blank or equal to node_ID3: a triangle). */
rc_status rc_card_seg(rc_reader *rd, const rc_block *b)
{
    static const char *const nname[] = {"node_ID1", "node_ID2", "node_ID3", "node_ID4"};
    int nd, cap = 0, capi = 0, capl = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/SEG/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_SEG);
    if (!s) return RC_ENOMEM;
    if ((st = rc_var_lines(rd, b, s->title, "seg_ID node_ID1 node_ID2 node_ID3 node_ID4", &nd))) return st;
    for (int i = 1; i <= nd; i++) {
        int id = 0, nodes[4] = {0, 0, 0, 0};
        rc_field f[5] = {RC_F_INT("seg_ID", &id, 0, RC_FF_NONNEG), RC_F_INT("node_ID1", &nodes[0], 0, RC_FF_POS),
                         RC_F_INT("node_ID2", &nodes[1], 0, RC_FF_POS), RC_F_INT("node_ID3", &nodes[2], 0, RC_FF_POS),
                         RC_F_INT("node_ID4", &nodes[3], 0, RC_FF_NONNEG)};
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, 5))) return st;
        if (nodes[3] == nodes[2]) nodes[3] = 0; /* a triangle */
        for (int j = 1; j < 4; j++)
            for (int k = 0; k < j; k++)
                if (nodes[j] != 0 && nodes[j] == nodes[k])
                    return rc_case_fail(rd, &b->lines[i].loc, b->name, nname[j],
                                        "expected a node different from %s of the segment, got %d again (a "
                                        "segment has 3 or 4 distinct nodes; node_ID4 blank or equal to node_ID3 "
                                        "makes a triangle)",
                                        nname[k], nodes[j]);
        RC_GROW(rd, s->seg, cap, 4 * s->nseg + 3);
        RC_GROW(rd, s->seg_id, capi, s->nseg);
        RC_GROW(rd, s->seg_loc, capl, s->nseg);
        memcpy(s->seg + 4 * s->nseg, nodes, sizeof nodes);
        s->seg_id[s->nseg] = id;
        s->seg_loc[s->nseg++] = b->lines[i].loc;
    }
    if (s->nseg == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "seg_ID",
                            "expected at least one segment line (seg_ID node_ID1 node_ID2 node_ID3 node_ID4), got "
                            "none");
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}

/* /SURF/PART/surf_ID: title; part ids, ten a line (the outer faces of the
 * parts' shells and solids). */
rc_status rc_card_surfpart(rc_reader *rd, const rc_block *b)
{
    int nd, cap = 0, capl = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/PART/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_PART);
    if (!s) return RC_ENOMEM;
    if ((st = rc_var_lines(rd, b, s->title, "part_ID1 ... part_ID10", &nd))) return st;
    for (int i = 1; i <= nd; i++) {
        int v[10];
        rc_field f[10];
        for (int k = 0; k < 10; k++) {
            rc_field fk = RC_F_INT("part_ID", &v[k], 0, RC_FF_NONNEG);
            f[k] = fk;
        }
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, 10))) return st;
        for (int k = 0; k < 10; k++) {
            if (v[k] == 0) continue;
            RC_GROW(rd, s->part, cap, s->npart);
            RC_GROW(rd, s->part_loc, capl, s->npart);
            s->part[s->npart] = v[k];
            s->part_loc[s->npart++] = b->lines[i].loc;
        }
    }
    if (s->npart == 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "part_ID",
                            "expected at least one part id (ten a line, 10 characters each), got none");
    return rc_note_id(rd, RC_IDK_SURF, s->id, &s->loc, b->hdr->text);
}
