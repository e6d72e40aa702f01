/*
 * Cards of curves, initial and boundary conditions and loads: /FUNCT,
 * /INIVEL, /GRAV, /BCS, /IMPVEL (imposed velocity).
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
#include "case/case_mesh.h"
#include "case/case_power.h"

static const char rc_note_sensor[] = "(sensors)";

/* Default Tstop of /IMPVEL [s], as /INTER/TYPE6. */
#define RC_PW_DEF_TSTOP 1e30

/* ======================================================================
 * /FUNCT
 * ====================================================================== */

/* /FUNCT/fct_ID: title, then X Y pairs; X strictly increasing. */
rc_status rc_card_funct(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "fct_ID", "/FUNCT/fct_ID"))) return st;
    RC_GROW(rd, c->funct, rd->capfunct, c->nfunct);
    rc_case_funct *fn = &c->funct[c->nfunct++];
    fn->id = b->id;
    fn->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, fn->title, "X Y", &nd))) return st;

    /* a function needs two points at least */
    if (nd < 2)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "X",
                            "not a function: expected at least 2 points (one X Y pair a line), "
                            "found %d",
                            nd);
    fn->x = malloc((size_t)nd * sizeof *fn->x);
    fn->y = malloc((size_t)nd * sizeof *fn->y);
    if (!fn->x || !fn->y) return rc_case_nomem(rd);

    /* the points, abscissae strictly increasing */
    for (int i = 0; i < nd; i++) {
        const rc_line *ln = &b->lines[i + 1];
        /* 20-character columns; 16 in Radioss 4.x */
        const int w = rc_layout_version(rd) >= 51 ? 20 : 16;
        rc_field f[] = {RC_F_REALW("X", &fn->x[i], 0, 0, w, RC_D_NONE),
                        RC_F_REALW("Y", &fn->y[i], 0, 0, w, RC_D_NONE)};
        if ((st = rc_parse_line(rd, b, ln, f, RC_NF(f)))) return st;
        if (i > 0 && !(fn->x[i] > fn->x[i - 1]))
            return rc_case_fail(rd, &ln->loc, b->name, "X",
                                "not a function: abscissae must increase strictly, got %s "
                                "after %.15g (line %d)",
                                f[0].got, fn->x[i - 1], b->lines[i].loc.line);
        fn->npts = i + 1;
    }
    return rc_note_id(rd, RC_IDK_FUNCT, fn->id, &fn->loc, b->hdr->text);
}

/* ======================================================================
 * /INIVEL, /GRAV, /BCS
 * ====================================================================== */

/* /INIVEL/TRA/id and /INIVEL/ROT/id: title; Vx Vy Vz grnod_ID skew_ID. */
rc_status rc_card_inivel(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    char title[RC_CASE_TITLE_MAX + 1];
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "inivel_ID", "/INIVEL/TRA/inivel_ID"))) return st;
    RC_GROW(rd, c->inivel, rd->capinivel, c->ninivel);
    rc_case_inivel *v = &c->inivel[c->ninivel++];
    v->id = b->id;
    v->rot = strcmp(b->kw[1], "ROT") == 0;
    v->loc = b->hdr->loc;
    /* Radioss 2025 adds an optional line: Tstart sens_ID */
    const int ver = rc_layout_version(rd);
    if ((st = rc_card_lines(rd, b, title, 1, ver >= 2025 ? 2 : 1,
                            ver >= 2025 ? "Vx Vy Vz grnod_ID skew_ID[, Tstart sens_ID]"
                                        : "Vx Vy Vz grnod_ID skew_ID",
                            &nd)))
        return st;
    v->line_loc = b->lines[1].loc;

    /* 20- and 10-character fields; 16 and 8 in Radioss 4.x */
    const int wr = ver >= 51 ? 20 : 16, wi = ver >= 51 ? 10 : 8;
    const int dv = v->rot ? RC_D_W : RC_D_V;
    rc_field f[] = {RC_F_REALW("Vx", &v->v[0], 0, 0, wr, dv), RC_F_REALW("Vy", &v->v[1], 0, 0, wr, dv),
                    RC_F_REALW("Vz", &v->v[2], 0, 0, wr, dv),
                    RC_F_INTW("grnod_ID", &v->grnod_id, 0, RC_FF_NONNEG, wi),
                    RC_F_INTW("skew_ID", &v->skew_id, 0, RC_FF_NONNEG, wi)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;
    memcpy(v->v_skew, v->v, sizeof v->v); /* rotated once the skews are known */
    if (nd >= 2) {
        double tstart = 0;
        int sens = 0;
        rc_field f2[] = {RC_F_REALD("Tstart", &tstart, 0, RC_FF_ONLY0, RC_D_T),
                         RC_F_INTN("sens_ID", &sens, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_sensor)};
        f2[0].note = "(a later start of the initial velocity)";
        if ((st = rc_parse_line(rd, b, &b->lines[2], f2, RC_NF(f2)))) return st;
    }
    return rc_note_id(rd, RC_IDK_INIVEL, v->id, &v->loc, b->hdr->text);
}

/* /GRAV/grav_ID: title; fct_IDT DIR skew_ID sensor_ID grnod_ID (unused)
 * Ascale_x Fscale_y (Radioss 5.1 and later: Ascale_x in columns 61-80). */
rc_status rc_card_grav(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    char title[RC_CASE_TITLE_MAX + 1], dir[11] = "";
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "grav_ID", "/GRAV/grav_ID"))) return st;
    RC_GROW(rd, c->grav, rd->capgrav, c->ngrav);
    rc_case_grav *g = &c->grav[c->ngrav++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, title, 1, 1, "fct_IDT DIR skew_ID sensor_ID grnod_ID "
                            "Ascale_x Fscale_y", &nd)))
        return st;
    g->line_loc = b->lines[1].loc;

    rc_field f[] = {RC_F_INT("fct_IDT", &g->fct_id, 0, RC_FF_NONNEG),
                    RC_F_STR("DIR", dir, 10),
                    RC_F_INT("skew_ID", &g->skew_id, 0, RC_FF_NONNEG),
                    RC_F_INT("sensor_ID", &g->sensor_id, 0, RC_FF_NONNEG),
                    RC_F_INT("grnod_ID", &g->grnod_id, 0, RC_FF_NONNEG),
                    RC_F_SKIP(10),
                    RC_F_REALD("Ascale_x", &g->ascale, 1, RC_FF_ZDEF | RC_FF_POS, RC_D_T),
                    RC_F_REALD("Fscale_y", &g->fscale, 1, RC_FF_ZDEF, RC_D_ACC)};
    /* Radioss 4.x: fct_IDT DIR skew_ID sensor_ID (8 characters) Scale (16)
     * grnod_ID (8); no abscissa scale */
    rc_field f44[] = {RC_F_INTW("fct_IDT", &g->fct_id, 0, RC_FF_NONNEG, 8),
                      RC_F_STR("DIR", dir, 8), f[2], f[3],
                      RC_F_REALW("Scale", &g->fscale, 1, RC_FF_ZDEF, 16, RC_D_ACC),
                      RC_F_INTW("grnod_ID", &g->grnod_id, 0, RC_FF_NONNEG, 8)};
    f44[2].width = f44[3].width = 8;
    const int old = rc_layout_version(rd) < 51;
    g->ascale = 1;
    if ((st = rc_parse_line(rd, b, &b->lines[1], old ? f44 : f, old ? RC_NF(f44) : RC_NF(f))))
        return st;

    /* DIR: one letter, either case, anywhere in its columns */
    const char *p = strchr("XYZxyz", dir[0]);
    if (!dir[0] || dir[1] || !p)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "DIR", "expected X, Y or Z, got %s",
                            f[1].got);
    g->dir = (int)(p - "XYZxyz") % 3;
    g->u[g->dir] = 1; /* the skew's axis once the skews are known */
    return rc_note_id(rd, RC_IDK_GRAV, g->id, &g->loc, b->hdr->text);
}

/* A skew named by a card's skew_ID: its index, or a failure (no such skew;
 * a moving skew where only a fixed one will do: `what` names the use). */
rc_status rc_case_ref_skew(rc_reader *rd, const rc_loc *at, const char *card, int id, const char *what, int *out)
{
    const int fixed_only = what != NULL;
    const int s = rc_case_find_skew(rd->c, id);
    if (s < 0)
        return rc_case_fail(rd, at, card, "skew_ID",
                            fixed_only ? "expected the id of a /SKEW/FIX, got %d (no such skew)"
                                       : "expected the id of a /SKEW/FIX, /SKEW/MOV or /SKEW/MOV2, got %d (no such skew)",
                            id);
    const rc_case_skew *sk = &rd->c->mesh->skew[s];
    if (fixed_only && sk->mov)
        return rc_case_fail(rd, at, card, "skew_ID",
                            "/SKEW/%s/%d moves with its nodes: %s is not supported yet (expected a /SKEW/FIX)",
                            sk->mov == 2 ? "MOV2" : "MOV", id, what);
    *out = s;
    return RC_OK;
}

/* Once the skews' axes are known (rc_cards_mesh_finish): a /BCS's skew
 * exists; an /INIVEL's
 * components given in a skew's axes (Radioss: V = Vx X' + Vy Y' + Vz Z', a
 * moving skew taken at its nodes' initial positions) and a /GRAV's
 * direction along a /SKEW/FIX axis, into global axes. */
rc_status rc_cards_loads_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    rc_status st;
    char card[48];
    for (int k = 0; k < c->ninivel; k++) {
        rc_case_inivel *v = &c->inivel[k];
        if (!v->skew_id) continue;
        snprintf(card, sizeof card, "/INIVEL/%s/%d", v->rot ? "ROT" : "TRA", v->id);
        int s = -1;
        if ((st = rc_case_ref_skew(rd, &v->line_loc, card, v->skew_id, NULL, &s))) return st;
        const rc_case_skew *sk = &c->mesh->skew[s];
        for (int i = 0; i < 3; i++)
            v->v[i] = v->v_skew[0] * sk->axis[0][i] + v->v_skew[1] * sk->axis[1][i] + v->v_skew[2] * sk->axis[2][i];
    }
    /* /BCS: the skew must exist (its flags, all or none, hold the same in
     * any frame) */
    for (int k = 0; k < c->nbcs; k++) {
        const rc_case_bcs *x = &c->bcs[k];
        if (!x->skew_id) continue;
        snprintf(card, sizeof card, "/BCS/%d", x->id);
        int s = -1;
        if ((st = rc_case_ref_skew(rd, &x->line_loc, card, x->skew_id, NULL, &s))) return st;
    }
    for (int k = 0; k < c->ngrav; k++) {
        rc_case_grav *g = &c->grav[k];
        if (!g->skew_id) continue;
        snprintf(card, sizeof card, "/GRAV/%d", g->id);
        int s = -1;
        if ((st = rc_case_ref_skew(rd, &g->line_loc, card, g->skew_id, "a gravity along a moving axis", &s)))
            return st;
        memcpy(g->u, c->mesh->skew[s].axis[g->dir], sizeof g->u);
    }
    return RC_OK;
}

/* Trarot "111 111": the first three 0/1 digits are Tx Ty Tz, the next three
 * Rx Ry Rz; blanks are ignored, missing digits are 0. */
static int rc_trarot(const char *s, int fix[6])
{
    int k = 0;
    for (; *s; s++) {
        if (*s == ' ') continue;
        if ((*s != '0' && *s != '1') || k == 6) return 0;
        fix[k++] = *s - '0';
    }
    return 1;
}

/* /BCS/bcs_ID: title; Trarot skew_ID grnod_ID. */
rc_status rc_card_bcs(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    char title[RC_CASE_TITLE_MAX + 1], tr[11] = "";
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "bcs_ID", "/BCS/bcs_ID"))) return st;
    RC_GROW(rd, c->bcs, rd->capbcs, c->nbcs);
    rc_case_bcs *x = &c->bcs[c->nbcs++];
    x->id = b->id;
    x->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, title, 1, 1, "Trarot skew_ID grnod_ID", &nd))) return st;
    x->line_loc = b->lines[1].loc;

    /* 10-character fields; 8 in Radioss 4.x */
    const int w = rc_layout_version(rd) >= 51 ? 10 : 8;
    rc_field f[] = {RC_F_STR("Trarot", tr, 10),
                    RC_F_INT("skew_ID", &x->skew_id, 0, RC_FF_NONNEG),
                    RC_F_INTW("grnod_ID", &x->grnod_id, 0, RC_FF_NONNEG, w)};
    f[0].width = f[1].width = w;
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;
    if (!rc_trarot(tr, x->fix))
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "Trarot",
                            "expected up to six 0/1 flags TxTyTz RxRyRz (e.g. \"111 000\"), got %s",
                            f[0].got);
    /* with a skew: the flags held along its axes; one or two translations
     * are held along the skew's axes (model/imposed.h); ricochet holds
     * body-frame rotations, so only all or none of the three (the same set
     * in any frame) */
    if (x->skew_id && (x->fix[3] + x->fix[4] + x->fix[5]) % 3 != 0)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "skew_ID",
                            "Trarot %s holds some rotations about the axes of skew %d: not supported yet "
                            "(with a skew, Rx Ry Rz all held or all free; ricochet holds rotations about the "
                            "global axes)",
                            f[0].got, x->skew_id);
    return rc_note_id(rd, RC_IDK_BCS, x->id, &x->loc, b->hdr->text);
}

/* ======================================================================
 * /IMPVEL
 * ====================================================================== */

/* /IMPVEL/impvel_ID: title; fct_IDT Dir skew_ID sensor_ID grnod_ID frame_ID
 * Icoor; Ascale_x Fscale_y Tstart Tstop. */
rc_status rc_card_impvel(rc_reader *rd, const rc_block *b)
{
    static const char *const dirs[6] = {"X", "Y", "Z", "XX", "YY", "ZZ"};
    rc_case *c = rd->c;
    char dir[11] = "";
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "impvel_ID", "/IMPVEL/impvel_ID"))) return st;
    RC_GROW(rd, c->impvel, rd->capimpvel, c->nimpvel);
    rc_case_impvel *v = &c->impvel[c->nimpvel++];
    v->id = b->id;
    v->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, v->title, 1, 2,
                            "fct_IDT Dir skew_ID sensor_ID grnod_ID frame_ID Icoor[, Ascale_x Fscale_y Tstart "
                            "Tstop]",
                            &nd)))
        return st;
    v->line_loc[0] = b->lines[1].loc;
    v->line_loc[1] = nd >= 2 ? b->lines[2].loc : b->lines[1].loc;

    rc_field l1[] = {RC_F_INT("fct_IDT", &v->fct_id, 0, RC_FF_POS),
                     RC_F_STR("Dir", dir, 10),
                     RC_F_INT("skew_ID", &v->skew_id, 0, RC_FF_NONNEG),
                     RC_F_INT("sensor_ID", &v->sensor_id, 0, RC_FF_NONNEG),
                     RC_F_INT("grnod_ID", &v->grnod_id, 0, RC_FF_POS),
                     RC_F_INTN("frame_ID", &v->frame_id, RC_FF_NONNEG | RC_FF_ONLY0, "(moving frames)"),
                     RC_F_INTN("Icoor", &v->icoor, RC_FF_NONNEG | RC_FF_ONLY0, "(cylindrical coordinates)")};
    /* the velocity scale: m/s (X, Y, Z) or rad/s (XX, YY, ZZ, known once
     * line 1 is read) */
    rc_field l2[] = {RC_F_REALD("Ascale_x", &v->ascale, 1, RC_FF_ZDEF | RC_FF_POS, RC_D_T),
                     RC_F_REALD("Fscale_y", &v->fscale, 1, RC_FF_ZDEF, RC_D_V),
                     RC_F_REALD("Tstart", &v->tstart, 0, 0, RC_D_T),
                     RC_F_REALD("Tstop", &v->tstop, RC_PW_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    static const rc_line blank = {"", 0, {NULL, 0}};
    if (rc_layout_version(rd) < 51) {
        /* Radioss 4.x: 8-character fields; Scale Tstart Tstop (16) */
        for (int k = 0; k < RC_NF(l1); k++) l1[k].width = 8;
        rc_field o2[] = {RC_F_REALW("Scale", &v->fscale, 1, RC_FF_ZDEF, 16, RC_D_V),
                         RC_F_REALW("Tstart", &v->tstart, 0, 0, 16, RC_D_T),
                         RC_F_REALW("Tstop", &v->tstop, RC_PW_DEF_TSTOP, RC_FF_ZDEF, 16, RC_D_T)};
        if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1) - 1))) return st;
        o2[0].dim = strlen(dir) == 2 ? RC_D_W : RC_D_V;
        if ((st = rc_parse_line(rd, b, nd >= 2 ? &b->lines[2] : &blank, o2, RC_NF(o2)))) return st;
        rc_field d[] = {l1[6], l2[0]};
        if ((st = rc_parse_line(rd, b, &blank, d, RC_NF(d)))) return st;
        l2[2] = o2[1];
        l2[3] = o2[2];
    } else {
        /* Icoor (61-70) exists from Radioss 12.0 on */
        const int nl1 = rc_layout_version(rd) >= 120 ? RC_NF(l1) : RC_NF(l1) - 1;
        if ((st = rc_parse_line(rd, b, &b->lines[1], l1, nl1))) return st;
        if (nl1 < RC_NF(l1) && (st = rc_parse_line(rd, b, &blank, &l1[nl1], 1))) return st;
        l2[1].dim = strlen(dir) == 2 ? RC_D_W : RC_D_V;
        if ((st = rc_parse_line(rd, b, nd >= 2 ? &b->lines[2] : &blank, l2, RC_NF(l2)))) return st;
    }

    /* Dir: X Y Z XX YY ZZ, either case, anywhere in its columns */
    v->dir = -1;
    for (int k = 0; k < 6; k++) {
        size_t n = strlen(dirs[k]);
        if (strlen(dir) == n && (dir[0] & ~0x20) == dirs[k][0] && (n == 1 || (dir[1] & ~0x20) == dirs[k][1]))
            v->dir = k;
    }
    if (v->dir < 0)
        return rc_case_fail(rd, &v->line_loc[0], b->name, "Dir", "expected X, Y, Z, XX, YY or ZZ, got %s",
                            l1[1].got);
    if (v->tstop < v->tstart)
        return rc_case_fail(rd, &v->line_loc[1], b->name, "Tstop", "expected Tstop >= Tstart = %.15g, got %s",
                            v->tstart, l2[3].got);
    if (v->skew_id && v->dir >= 3)
        return rc_case_fail(rd, &v->line_loc[0], b->name, "skew_ID",
                            "expected 0 for a rotation (Dir %s), got %s: an imposed rotation about a skew axis is "
                            "not supported yet (a translation along a skew axis is: Dir X, Y or Z)",
                            dirs[v->dir], l1[2].got);
    if (v->tstart > 0 && v->dir >= 3)
        return rc_case_fail(rd, &v->line_loc[1], b->name, "Tstart",
                            "expected Tstart <= 0 for a rotation (Dir %s), got %s: a later start of an imposed "
                            "rotation (a jump of the angular velocity) is not supported yet; shape the time "
                            "function instead",
                            dirs[v->dir], l2[2].got);
    return rc_note_id(rd, RC_IDK_IMPVEL, v->id, &v->loc, b->hdr->text);
}
