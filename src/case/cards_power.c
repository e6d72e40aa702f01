/*
 * Cards of the power-law contact and the roller (SPEC 7, 3, 4):
 *   /INTER/POWER/inter_ID   power-law contact with splines (ricochet card)
 *   /SURF/CYL/surf_ID       finite cylinder, flat or rounded ends (ricochet)
 *   /SURF/BOX/surf_ID       box (ricochet)
 *   /IMPVEL/impvel_ID       imposed velocity (Radioss layout)
 * Layouts as field tables (case_internal.h), documented in
 * docs/case-format.md. References are resolved by the compiler.
 */
#include <math.h>
#include <string.h>

#include "case/case_internal.h"
#include "case/case_power.h"
#include "base/error.h"
#include "model/power.h"

#define RC_NF(arr) ((int)(sizeof(arr) / sizeof((arr)[0])))
#define RC_F_INTN(nm, p, fl, nt) RC_F_SET(nm, p, 0, fl, 0, 0, nt)

/* Defaults of /INTER/POWER (docs/case-format.md). */
#define RC_PW_DEF_M1 2.0      /* stiffness exponent [-]                     */
#define RC_PW_DEF_M2 1.0      /* damping exponent [-]                       */
#define RC_PW_DEF_M3 2.0      /* indentation exponent [-]                   */
#define RC_PW_DEF_RDF 0.001   /* rebound damping factor [-]                 */
#define RC_PW_DEF_DREG 0.0    /* regularisation length of delta^m, m < 1 [m]; 0: 1e-4 p_s (scales.c) */
#define RC_PW_DEF_VREG 0.0    /* regularisation speed of |v|^m2, m2 < 1 [m/s]; 0: 1e-4 v_s */
#define RC_PW_DEF_TSTOP 1e30  /* [s], as /INTER/TYPE6                       */

static const char rc_note_skew[] = "(skew frames)";
static const char rc_note_sensor[] = "(sensors)";

/* ======================================================================
 * /INTER/POWER
 * ====================================================================== */

/* /INTER/POWER/inter_ID: title;
 *   surf_ID1 surf_ID2 fct_stiff fct_damp Ispline Irdf;
 *   K m1 C m2 m3;
 *   [RDF Dreg Vreg Tstart Tstop;
 *   [mu_s v_s mu_d v_d f_max;
 *   [Kt]]] */
rc_status rc_card_power(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "inter_ID", "/INTER/POWER/inter_ID"))) return st;
    RC_GROW(rd, c->power, rd->cappower, c->npower);
    rc_case_power *p = &c->power[c->npower++];
    p->id = b->id;
    p->loc = b->hdr->loc;
    for (int k = 0; k < 5; k++) p->line_loc[k] = p->loc;
    if ((st = rc_card_lines(rd, b, p->title, 2, 5,
                            "surf_ID1 surf_ID2 fct_stiff fct_damp Ispline Irdf, K m1 C m2 m3[, RDF Dreg "
                            "Vreg Tstart Tstop[, mu_s v_s mu_d v_d f_max[, Kt]]]",
                            &nd)))
        return st;

    const unsigned zp = RC_FF_ZDEF | RC_FF_POS;
    rc_field l1[] = {RC_F_INT("surf_ID1", &p->surf1, 0, RC_FF_POS),
                     RC_F_INT("surf_ID2", &p->surf2, 0, RC_FF_POS),
                     RC_F_INT("fct_stiff", &p->fct_stiff, 0, RC_FF_NONNEG),
                     RC_F_INT("fct_damp", &p->fct_damp, 0, RC_FF_NONNEG),
                     RC_F_SET("Ispline", &p->ispline, RC_SPL_DEFAULT, RC_FF_ZDEF, 0x1Fu, 0, NULL),
                     RC_F_SET("Irdf", &p->irdf, 1, RC_FF_ZDEF, 0x7u, 0, NULL)};
    /* exponents: blank is the default, an explicit 0 is 0 */
    rc_field l2[] = {RC_F_REAL("K", &p->k, 0, RC_FF_NONNEG), RC_F_REAL("m1", &p->m1, RC_PW_DEF_M1, RC_FF_NONNEG),
                     RC_F_REAL("C", &p->c, 0, RC_FF_NONNEG), RC_F_REAL("m2", &p->m2, RC_PW_DEF_M2, RC_FF_NONNEG),
                     RC_F_REAL("m3", &p->m3, RC_PW_DEF_M3, RC_FF_NONNEG)};
    rc_field l3[] = {RC_F_REAL("RDF", &p->rdf, RC_PW_DEF_RDF, zp), RC_F_REAL("Dreg", &p->dreg, RC_PW_DEF_DREG, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Vreg", &p->vreg, RC_PW_DEF_VREG, RC_FF_ZDEF | RC_FF_NONNEG), RC_F_REAL("Tstart", &p->tstart, 0, 0),
                     RC_F_REAL("Tstop", &p->tstop, RC_PW_DEF_TSTOP, RC_FF_ZDEF)};
    rc_field l4[] = {RC_F_REAL("mu_s", &p->mus, 0, RC_FF_NONNEG), RC_F_REAL("v_s", &p->vs, 0, RC_FF_NONNEG),
                     RC_F_REAL("mu_d", &p->mud, 0, RC_FF_NONNEG), RC_F_REAL("v_d", &p->vd, 0, RC_FF_NONNEG),
                     RC_F_REAL("f_max", &p->fmax, 0, RC_FF_NONNEG)};
    rc_field l5[] = {RC_F_REAL("Kt", &p->kt, 0, RC_FF_NONNEG)};
    rc_field *lines[5] = {l1, l2, l3, l4, l5};
    const int nf[5] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5)};
    /* absent optional lines take their defaults, like blank ones */
    static const rc_line blank = {"", 0, {NULL, 0}};
    for (int k = 0; k < 5; k++) {
        const rc_line *ln = k < nd ? &b->lines[k + 1] : &blank;
        if (k < nd) p->line_loc[k] = ln->loc;
        if ((st = rc_parse_line(rd, b, ln, lines[k], nf[k]))) return st;
    }

    /* the stiffness term must exist; the splines replace K and C */
    if (p->fct_stiff == 0 && !(p->k > 0))
        return rc_case_fail(rd, &p->line_loc[1], b->name, "K",
                            "expected a stiffness coefficient K > 0 [N/m^m1] (or a stiffness spline "
                            "fct_stiff), got %s",
                            l2[0].got);
    if (p->ispline < RC_SPL_LINEAR || p->ispline > RC_SPL_STEFFEN)
        return rc_case_fail(rd, &p->line_loc[0], b->name, "Ispline",
                            "expected 1 linear, 2 cubic, 3 akima or 4 steffen (0: default 4), got %s",
                            l1[4].got);
    if (p->irdf != 1 && p->irdf != 2)
        return rc_case_fail(rd, &p->line_loc[0], b->name, "Irdf",
                            "expected 1 (rebound damping factor on, the default) or 2 (off), got %s", l1[5].got);
    if (p->tstop < p->tstart)
        return rc_case_fail(rd, &p->line_loc[2], b->name, "Tstop", "expected Tstop >= Tstart = %.15g, got %s",
                            p->tstart, l3[4].got);
    /* step5 friction: 0 < v_s < v_d */
    if (p->mus > 0 || p->mud > 0) {
        if (!(p->vs > 0))
            return rc_case_fail(rd, &p->line_loc[3], b->name, "v_s",
                                "friction (mu_s or mu_d > 0) needs the static threshold velocity v_s > 0 "
                                "[m/s], got %s",
                                l4[1].got);
        if (!(p->vd > p->vs))
            return rc_case_fail(rd, &p->line_loc[3], b->name, "v_d",
                                "expected the dynamic threshold velocity v_d > v_s = %.15g [m/s], got %s", p->vs,
                                l4[3].got);
    }
    return rc_note_id(rd, RC_IDK_INTER, p->id, &p->loc, b->hdr->text);
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
    rc_field l2[] = {RC_F_REAL("Xc", &s->c[0], 0, 0), RC_F_REAL("Yc", &s->c[1], 0, 0),
                     RC_F_REAL("Zc", &s->c[2], 0, 0)};
    rc_field l3[] = {RC_F_REAL("AX", &s->axis[0], 0, 0), RC_F_REAL("AY", &s->axis[1], 0, 0),
                     RC_F_REAL("AZ", &s->axis[2], 0, 0)};
    rc_field l4[] = {RC_F_REAL("R", &s->abc[0], 0, RC_FF_POS), RC_F_REAL("L", &s->length, 0, RC_FF_POS)};
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
    rc_field l2[] = {RC_F_REAL("Xc", &s->c[0], 0, 0), RC_F_REAL("Yc", &s->c[1], 0, 0),
                     RC_F_REAL("Zc", &s->c[2], 0, 0)};
    rc_field l3[] = {RC_F_REAL("a", &s->abc[0], 0, RC_FF_POS), RC_F_REAL("b", &s->abc[1], 0, RC_FF_POS),
                     RC_F_REAL("c", &s->abc[2], 0, RC_FF_POS)};
    rc_field l4[] = {RC_F_REAL("UX", &s->axis[0], 0, 0), RC_F_REAL("UY", &s->axis[1], 0, 0),
                     RC_F_REAL("UZ", &s->axis[2], 0, 0)};
    rc_field l5[] = {RC_F_REAL("VX", &s->axis2[0], 0, 0), RC_F_REAL("VY", &s->axis2[1], 0, 0),
                     RC_F_REAL("VZ", &s->axis2[2], 0, 0)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
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
                     RC_F_INTN("skew_ID", &v->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
                     RC_F_INTN("sensor_ID", &v->sensor_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_sensor),
                     RC_F_INT("grnod_ID", &v->grnod_id, 0, RC_FF_POS),
                     RC_F_INTN("frame_ID", &v->frame_id, RC_FF_NONNEG | RC_FF_ONLY0, "(moving frames)"),
                     RC_F_INTN("Icoor", &v->icoor, RC_FF_NONNEG | RC_FF_ONLY0, "(cylindrical coordinates)")};
    rc_field l2[] = {RC_F_REAL("Ascale_x", &v->ascale, 1, RC_FF_ZDEF | RC_FF_POS),
                     RC_F_REAL("Fscale_y", &v->fscale, 1, RC_FF_ZDEF), RC_F_REAL("Tstart", &v->tstart, 0, 0),
                     RC_F_REAL("Tstop", &v->tstop, RC_PW_DEF_TSTOP, RC_FF_ZDEF)};
    static const rc_line blank = {"", 0, {NULL, 0}};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, nd >= 2 ? &b->lines[2] : &blank, l2, RC_NF(l2)))) return st;

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
    if (v->tstart > 0)
        return rc_case_fail(rd, &v->line_loc[1], b->name, "Tstart",
                            "expected Tstart <= 0, got %s: a later start (a jump of the velocity) is not "
                            "supported yet; shape the time function instead",
                            l2[2].got);
    return rc_note_id(rd, RC_IDK_IMPVEL, v->id, &v->loc, b->hdr->text);
}
