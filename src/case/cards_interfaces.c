/*
 * Cards of contact interfaces: /INTER/TYPE6, /INTER/TYPE7, /INTER/TYPE24, /INTER/TYPE25, /INTER/TYPE11,
 * /INTER/TYPE19 and ricochet's /INTER/POWER
 * (power-law contact with splines).
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
#include "case/case_power.h"

/* Default Tstop of /INTER (Radioss). */
#define RC_DEF_TSTOP 1e30

/* Defaults of /INTER/POWER (docs/case-format.md). */
#define RC_PW_DEF_M1 2.0      /* stiffness exponent [-]                     */
#define RC_PW_DEF_M2 1.0      /* damping exponent [-]                       */
#define RC_PW_DEF_M3 2.0      /* indentation exponent [-]                   */
#define RC_PW_DEF_RDF 0.001   /* rebound damping factor [-]                 */
#define RC_PW_DEF_DREG 0.0    /* regularisation length of delta^m, m < 1 [m]; 0: 1e-4 p_s (scales.c) */
#define RC_PW_DEF_VREG 0.0    /* regularisation speed of |v|^m2, m2 < 1 [m/s]; 0: 1e-4 v_s */
#define RC_PW_DEF_TSTOP 1e30  /* [s], as /INTER/TYPE6                       */

/* ======================================================================
 * /INTER/TYPE6
 * ====================================================================== */

/* /INTER/TYPE6/inter_ID: title and the six Radioss lines. */
rc_status rc_card_type6(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "inter_ID", "/INTER/TYPE6/inter_ID")))
        return st;
    RC_GROW(rd, c->type6, rd->captype6, c->ntype6);
    rc_case_type6 *t = &c->type6[c->ntype6++];
    t->id = b->id;
    t->loc = b->hdr->loc;
    /* the layout of the /BEGIN version: 6 lines from 14.0 (140), 5 lines
     * from 10.0 (100), 4 lines in 5.1 and 9.0, 3 lines of 8- and
     * 16-character fields in 4.x */
    const int ver = rc_layout_version(rd);
    const int nl = ver >= 140 ? 6 : ver >= 100 ? 5 : ver >= 51 ? 4 : 3;
    static const char *const desc[4] = {
        "surf_ID1 surf_ID2, Scale Fric Gap Tstart Tstop, fct_ID IRS IRM (Radioss 4.x layout)",
        "surf_ID1 surf_ID2, Fric Gap Tstart Tstop, IRS IRM, fct_ID Ascalex FscaleY (Radioss "
        "5.1/9.0 layout)",
        "surf_ID1 surf_ID2, Fric Gap Tstart Tstop, IRS IRM, fct_IDld Iform Ascalex Fscaleld, "
        "fct_IDul Stiff Fscaleul (Radioss 10.0-13.0 layout)",
        "surf_ID1 surf_ID2, Sfric Fric Gap Tstart Tstop, IRS..., fct_IDld..., fct_IDul..., "
        "Visc..."};
    if ((st = rc_card_lines(rd, b, t->title, nl, nl, desc[nl - 3], &nd))) return st;

    rc_field l1[] = {RC_F_INT("surf_ID1", &t->surf1, 0, RC_FF_POS),
                     RC_F_INT("surf_ID2", &t->surf2, 0, RC_FF_POS),
                     /* ricochet's extension in Radioss's blank columns: the sensor */
                     RC_F_INT("Isensor", &t->sensor_id, 0, RC_FF_NONNEG)};
    rc_field l2[] = {
        RC_F_REALD("Sfric", &t->sfric, 0, RC_FF_NONNEG, RC_D_F),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gap", &t->gap, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l3[] = {
        /* ricochet's extension in Radioss's blank columns: exact stick */
        RC_F_SET("Istick", &t->istick, 0, 0, 0x3u, 0x3u, NULL),
        RC_F_SET("IRS", &t->irs, 0, 0, 0x7u, 0x7u, NULL),
        RC_F_SET("IRm", &t->irm, 0, 0, 0x7u, 0x7u, NULL),
        RC_F_SET("Inacti", &t->inacti, 0, 0, RC_BIT(0) | RC_BIT(5), RC_BIT(0) | RC_BIT(5), NULL),
        RC_F_INT("fct_IDff", &t->fct_ff, 0, RC_FF_NONNEG),
        RC_F_INT("fct_IDfv", &t->fct_fv, 0, RC_FF_NONNEG),
        RC_F_REALD("Ascalef", &t->ascalef, 1, RC_FF_ZDEF | RC_FF_POS, RC_D_F),
        RC_F_REALD("Ascalev", &t->ascalev, 1, RC_FF_ZDEF | RC_FF_POS, RC_D_V)};
    rc_field l4[] = {
        RC_F_INT("fct_IDld", &t->fct_ld, 0, RC_FF_POS),
        RC_F_SET("Iform", &t->iform, 0, 0, 0x7u, 0x7u, NULL),
        RC_F_REALD("Ascalex", &t->ascalex, 1, RC_FF_ZDEF | RC_FF_POS, RC_D_L),
        RC_F_REALD("FscaleId", &t->fscaleld, 1, RC_FF_ZDEF, RC_D_F),
        RC_F_SET("Icor", &t->icor, 0, 0, 0x3u, 0x3u, NULL)};
    rc_field l5[] = {
        RC_F_INT("fct_IDul", &t->fct_ul, 0, RC_FF_NONNEG),
        /* ricochet's extension in Radioss's blank columns: static coefficient of exact stick */
        RC_F_REALW("Fric_s", &t->fric_s, 0, RC_FF_NONNEG, 10, RC_D_NONE),
        RC_F_REALD("Stiff", &t->stiff, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fscaleul", &t->fscaleul, 1, RC_FF_ZDEF, RC_D_F)};
    rc_field l6[] = {
        RC_F_REALD("Visc", &t->visc, 0, RC_FF_NONNEG, RC_D_C),
        RC_F_INT("fct_IDdv", &t->fct_dv, 0, RC_FF_NONNEG),
        RC_F_INT("fct_IDdf", &t->fct_df, 0, RC_FF_NONNEG),
        RC_F_REALD("Fscalev", &t->fscalev, 1, RC_FF_ZDEF, RC_D_F),
        /* ricochet's extension: a restitution asked instead of Visc */
        RC_F_REALD("e_target", &t->e_target, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("V_imp", &t->v_imp, 0, RC_FF_NONNEG, RC_D_V)};
    /* older layouts: the lines as their versions wrote them (the fields they
     * lack keep their defaults) */
    rc_field o2[] = {
        RC_F_SKIP(20),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gap", &t->gap, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field o3[] = {RC_F_SKIP(10), l3[1], l3[2]};
    rc_field o4_100[] = {l4[0], l4[1], l4[2], l4[3]};
    rc_field o4_51[] = {l4[0], RC_F_SKIP(10), l4[2], l4[3]};
    rc_field o1_44[] = {RC_F_INTW("surf_ID1", &t->surf1, 0, RC_FF_POS, 8),
                        RC_F_INTW("surf_ID2", &t->surf2, 0, RC_FF_POS, 8)};
    rc_field o2_44[] = {
        RC_F_REALW("Scale", &t->sfric, 0, RC_FF_NONNEG, 16, RC_D_F),
        RC_F_REALW("Fric", &t->fric, 0, RC_FF_NONNEG, 16, RC_D_NONE),
        RC_F_REALW("Gap", &t->gap, 0, RC_FF_NONNEG, 16, RC_D_L),
        RC_F_REALW("Tstart", &t->tstart, 0, 0, 16, RC_D_T),
        RC_F_REALW("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, 16, RC_D_T)};
    rc_field o3_44[] = {RC_F_INTW("fct_ID", &t->fct_ld, 0, RC_FF_POS, 8), l3[1], l3[2]};
    o3_44[1].width = o3_44[2].width = 8;
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    if (nl < 6) { nf[0] = 2; lines[1] = o2; nf[1] = RC_NF(o2); lines[2] = o3; nf[2] = RC_NF(o3); } /* no Isensor */
    if (nl == 5) { lines[3] = o4_100; nf[3] = RC_NF(o4_100); }
    if (nl == 4) { lines[3] = o4_51; nf[3] = RC_NF(o4_51); }
    if (nl == 3) {
        lines[0] = o1_44; nf[0] = RC_NF(o1_44);
        lines[1] = o2_44; nf[1] = RC_NF(o2_44);
        lines[2] = o3_44; nf[2] = RC_NF(o3_44);
    }
    /* the lines, each with its location; the lines a layout lacks take the
     * defaults (an older layout's missing fields) at its last line */
    static const rc_line blank = {"", 0, {NULL, 0}};
    for (int k = 0; k < 6; k++) {
        if (k >= nl) {
            /* the fields of lines 4-6 the older layout lacks: defaults */
            t->line_loc[k] = t->line_loc[nl - 1];
            if (k == 3 && nl == 3) {
                rc_field d4[] = {l4[1], l4[2], l4[3], l4[4]};
                if ((st = rc_parse_line(rd, b, &blank, d4, RC_NF(d4)))) return st;
                continue;
            }
            if ((st = rc_parse_line(rd, b, &blank, lines[k], nf[k]))) return st;
            continue;
        }
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    /* the fields of lines 2-4 that older layouts lack: defaults */
    if (nl < 6) {
        rc_field d3[] = {l3[3], l3[4], l3[5], l3[6], l3[7]};
        if ((st = rc_parse_line(rd, b, &blank, d3, RC_NF(d3)))) return st;
        t->sfric = nl == 3 ? t->sfric : 0;
        rc_field d4[] = {l4[4]};
        if ((st = rc_parse_line(rd, b, &blank, d4, RC_NF(d4)))) return st;
        if (nl == 4) t->iform = 0;
    }
    if (nl < 6) t->istick = 0;
    if (nl < 5) t->fric_s = 0;
    if (t->fric_s > 0 && t->istick != 1)
        return rc_case_fail(rd, &t->line_loc[4], b->name, "Fric_s",
                            "the static coefficient is that of exact stick: expected blank or 0 without Istick = 1 "
                            "(line 3, columns 1-10), got %s",
                            l5[1].got);
    if (t->tstop < t->tstart)
        return rc_case_fail(rd, &t->line_loc[1], b->name, "Tstop",
                            "expected Tstop >= Tstart = %.15g, got %s", t->tstart, lines[1][nf[1] - 1].got);
    /* the elasto-plastic laws move between the curves with slope Stiff;
     * without it Radioss uses the nonlinear elastic law (Iform 0) */
    if (t->iform != 0 && !(t->stiff > 0)) {
        if ((st = rc_case_warn(rd, &t->line_loc[4],
                               "card %s: Iform = %d with Stiff = 0 (%s) read as Iform = 0 "
                               "(nonlinear elastic), as Radioss does",
                               b->name, t->iform, l5[2].blank ? "blank" : "0")))
            return st;
        t->iform = 0;
    }
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* ======================================================================
 * /INTER/POWER
 * ====================================================================== */

/* /INTER/POWER/inter_ID: title;
 *   surf_ID1 surf_ID2 fct_stiff fct_damp Ispline Irdf;
 *   K m1 C m2 m3;
 *   [RDF Dreg Vreg Tstart Tstop;
 *   [mu_s v_s mu_d v_d f_max;
 *   [Kt;
 *   [e_target V_imp]]]] */
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
    for (int k = 0; k < 6; k++) p->line_loc[k] = p->loc;
    if ((st = rc_card_lines(rd, b, p->title, 2, 6,
                            "surf_ID1 surf_ID2 fct_stiff fct_damp Ispline Irdf, K m1 C m2 m3[, RDF Dreg "
                            "Vreg Tstart Tstop[, mu_s v_s mu_d v_d f_max[, Kt[, e_target V_imp]]]]",
                            &nd)))
        return st;

    const unsigned zp = RC_FF_ZDEF | RC_FF_POS;
    rc_field l1[] = {RC_F_INT("surf_ID1", &p->surf1, 0, RC_FF_POS),
                     RC_F_INT("surf_ID2", &p->surf2, 0, RC_FF_POS),
                     RC_F_INT("fct_stiff", &p->fct_stiff, 0, RC_FF_NONNEG),
                     RC_F_INT("fct_damp", &p->fct_damp, 0, RC_FF_NONNEG),
                     RC_F_SET("Ispline", &p->ispline, RC_SPL_DEFAULT, RC_FF_ZDEF, 0x1Fu, 0, NULL),
                     RC_F_SET("Irdf", &p->irdf, 1, RC_FF_ZDEF, 0x7u, 0, NULL),
                     RC_F_INT("Isensor", &p->sensor_id, 0, RC_FF_NONNEG)};
    /* exponents: blank is the default, an explicit 0 is 0 */
    rc_field l2[] = {RC_F_REAL("K", &p->k, 0, RC_FF_NONNEG), RC_F_REALD("m1", &p->m1, RC_PW_DEF_M1, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REAL("C", &p->c, 0, RC_FF_NONNEG), RC_F_REALD("m2", &p->m2, RC_PW_DEF_M2, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("m3", &p->m3, RC_PW_DEF_M3, RC_FF_NONNEG, RC_D_NONE)};
    rc_field l3[] = {RC_F_REALD("RDF", &p->rdf, RC_PW_DEF_RDF, zp, RC_D_NONE), RC_F_REALD("Dreg", &p->dreg, RC_PW_DEF_DREG, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_L),
                     RC_F_REALD("Vreg", &p->vreg, RC_PW_DEF_VREG, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_V), RC_F_REALD("Tstart", &p->tstart, 0, 0, RC_D_T),
                     RC_F_REALD("Tstop", &p->tstop, RC_PW_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l4[] = {RC_F_REALD("mu_s", &p->mus, 0, RC_FF_NONNEG, RC_D_NONE), RC_F_REALD("v_s", &p->vs, 0, RC_FF_NONNEG, RC_D_V),
                     RC_F_REALD("mu_d", &p->mud, 0, RC_FF_NONNEG, RC_D_NONE), RC_F_REALD("v_d", &p->vd, 0, RC_FF_NONNEG, RC_D_V),
                     RC_F_REALD("f_max", &p->fmax, 0, RC_FF_NONNEG, RC_D_F)};
    rc_field l5[] = {RC_F_REALD("Kt", &p->kt, 0, RC_FF_NONNEG, RC_D_K)};
    rc_field l6[] = {RC_F_REALD("e_target", &p->e_target, 0, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("V_imp", &p->v_imp, 0, RC_FF_NONNEG, RC_D_V)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    /* absent optional lines take their defaults, like blank ones */
    static const rc_line blank = {"", 0, {NULL, 0}};
    for (int k = 0; k < 6; k++) {
        const rc_line *ln = k < nd ? &b->lines[k + 1] : &blank;
        if (k < nd) p->line_loc[k] = ln->loc;
        if ((st = rc_parse_line(rd, b, ln, lines[k], nf[k]))) return st;
    }

    /* spline tables of physical values have no scale factors: they cannot
     * be converted from other units */
    if (rc_units_convert(rd) && (p->fct_stiff || p->fct_damp))
        return rc_case_fail(rd, &p->line_loc[0], b->name, p->fct_stiff ? "fct_stiff" : "fct_damp",
                            "the deck's units are not SI: a spline /FUNCT of forces has no scale "
                            "factor to convert it; write this card and its functions in kg, m, s, "
                            "got %s",
                            p->fct_stiff ? l1[2].got : l1[3].got);
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
 * /INTER/TYPE7
 * ====================================================================== */

/* Radioss's defaults of /INTER/TYPE7 that ricochet reads. */
#define RC_T7_DEF_VISS 0.05   /* critical damping fraction of the normal stiffness [-] */
#define RC_T7_DEF_VISF 1.0    /* critical damping fraction of the friction [-] */
#define RC_T7_DEFAULT 1000    /* Radioss's "default" value of the flags (Igap, Inacti, ...) */

/* A flag field read as an integer whose only supported values are 0 (or
 * blank) and Radioss's 1000 (both: the default); anything else is "not
 * supported yet" with the note. */
static rc_status t7_only_default(rc_reader *rd, const rc_block *b, const rc_loc *loc, const rc_field *f, int v,
                                 const char *note)
{
    if (v == 0 || v == RC_T7_DEFAULT) return RC_OK;
    return rc_case_fail(rd, loc, b->name, f->name, "expected 0, blank or 1000 (the default), got %s: not supported yet (%s)",
                        f->got, note);
}

/* The friction law lines of an interface card (rc_inter_friction) and no
 * data line after them; what: the lines the card leaves out, for the
 * message ("" or "...; "). */
static rc_status inter_friction_lines(rc_reader *rd, const rc_block *b, int nd, const rc_field *l6, int ifric,
                                      int ifiltr, double xfreq, int iform, double fric, double visf, int *fric_id,
                                      const char *what)
{
    int nlaw = 0;
    rc_status st = rc_inter_friction(rd, b, nd, l6, ifric, ifiltr, xfreq, iform, fric, visf, fric_id, &nlaw);
    if (st) return st;
    if (nd > 6 + nlaw)
        return rc_case_fail(rd, &b->lines[7 + nlaw].loc, b->name, NULL,
                            "expected %d data lines (%sIfric %d: %d friction law lines), got %d", 6 + nlaw, what,
                            ifric, nlaw, nd);
    return RC_OK;
}

/* Inacti of the node-to-surface and edge cards (TYPE7, TYPE11, TYPE19):
 * 0 and 1000 no action; 5 the gap reduced by the initial penetration; 6
 * the same with Radioss's 5 % depenetration, read as 5 (docs/theory.md
 * 3.7: the start is force-free either way); TYPE7's 1, 2 (the initially
 * penetrating secondary nodes or the main segments they penetrate left
 * out, found when the model is compiled: engine/analyses/prepare.c);
 * TYPE11's and TYPE19's 1, 2 and every card's 3 (the nodes moved out)
 * refused with their reason. */
static rc_status t7_inacti(rc_reader *rd, const rc_block *b, const rc_loc *loc, int *inacti, const rc_field *f, int type)
{
    if (*inacti == RC_T7_DEFAULT) *inacti = 0;
    if (*inacti == 0 || *inacti == 5 || *inacti == 6) return RC_OK;
    if ((*inacti == 1 || *inacti == 2) && type == 7) return RC_OK;
    if (*inacti == 1 || *inacti == 2)
        return rc_case_fail(rd, loc, b->name, "Inacti",
                            "got %s: not supported yet: Inacti %d leaves the initially penetrating %s out of the "
                            "contact, but ricochet's TYPE%d is the contact of two boxes (their edges%s, taken from "
                            "the box each side is), which has no secondary node or main segment of the deck to leave "
                            "out; expected 0, blank, 1000 (no action), 5 or 6 (the gap reduced by the initial "
                            "penetration), or the boxes apart at t = 0",
                            f->got, *inacti, *inacti == 1 ? "secondary nodes" : "main segments", type,
                            type == 19 ? " and corners" : "");
    if (*inacti == 3)
        return rc_case_fail(rd, loc, b->name, "Inacti",
                            "got %s: not supported: Inacti 3 moves the penetrating nodes onto the surface, which "
                            "for a rigid body would change its shape and mass at t = 0; expected 0, blank, 1000, "
                            "%s5 or 6 (the initial penetration taken as a reduction of the gap), or the bodies apart "
                            "at t = 0",
                            f->got, type == 7 ? "1, 2 (the penetrating nodes or segments left out), " : "");
    return rc_case_fail(rd, loc, b->name, "Inacti",
                        "expected 0, blank, 1000 (no action), %s5 or 6 (the gap reduced by the initial penetration), "
                        "got %s",
                        type == 7 ? "1 (the initially penetrating secondary nodes left out), 2 (the main segments "
                                    "they penetrate left out), "
                                  : "",
                        f->got);
}

/* /INTER/TYPE7/inter_ID: title and Radioss's six lines (layout of 11.0 and
 * later; the curvature line of Icurv, the friction law lines of Ifric and
 * the thermal lines of Ithe are refused with their flags). */
rc_status rc_card_type7(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "inter_ID", "/INTER/TYPE7/inter_ID"))) return st;
    RC_GROW(rd, c->type7, rd->captype7, c->ntype7);
    rc_case_type7 *t = &c->type7[c->ntype7++];
    t->id = b->id;
    t->loc = b->hdr->loc;
    for (int k = 0; k < 6; k++) t->line_loc[k] = t->loc;
    if (rc_layout_version(rd) < 110)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "the /INTER/TYPE7 layout of Radioss versions before 11.0 (/BEGIN Invers %d) is not "
                            "supported yet: expected Invers 110 or later (or 0)",
                            rc_layout_version(rd));
    if ((st = rc_card_lines(rd, b, t->title, 6, 12,
                            "grnd_IDs surf_IDm Istf Ithe Igap (blank) Ibag Idel Icurv Iadm, Fscalegap Gapmax "
                            "Fpenmax ITIED, Stmin Stmax %mesh_size dtmin Irem_gap Irem_i2, Stfac Fric Gapmin "
                            "Tstart Tstop, IBC (blank) Inacti VISs VISF Bumult, Ifric Ifiltr Xfreq Iform sens_ID "
                            "fct_IDF AscaleF fric_ID",
                            &nd)))
        return st;
    int ithe = 0, ibag = 0, idel = 0, icurv = 0, iadm = 0, itied = 0, irem_gap = 0, irem_i2 = 0, ibc = 0;
    int ifric = 0, ifiltr = 0, fct_f = 0;
    double fpenmax = 0, mesh_size = 0, dtmin = 0, bumult = 0, xfreq = 0, ascalef = 0;
    static const char heat[] = "heat transfer: ricochet has no temperatures";
    rc_field l1[] = {
        RC_F_INT("grnd_IDs", &t->grnod_id, 0, RC_FF_POS),
        RC_F_INT("surf_IDm", &t->surf_id, 0, RC_FF_POS),
        RC_F_INT("Istf", &t->istf, 0, RC_FF_NONNEG),
        {.name = "Ithe", .width = 10, .type = RC_FT_INT, .out = &ithe, .flags = RC_FF_ONLY0, .note = heat},
        RC_F_INT("Igap", &t->igap, 0, RC_FF_NONNEG),
        RC_F_SKIP(10),
        RC_F_INT("Ibag", &ibag, 0, RC_FF_NONNEG),
        RC_F_INT("Idel", &idel, 0, 0),
        {.name = "Icurv", .width = 10, .type = RC_FT_INT, .out = &icurv, .flags = RC_FF_ONLY0,
         .note = "a gap envelope with curvature"},
        {.name = "Iadm", .width = 10, .type = RC_FT_INT, .out = &iadm, .flags = RC_FF_ONLY0,
         .note = "curvature of an adaptive mesh"}};
    rc_field l2[] = {
        RC_F_REALD("Fscalegap", &t->fscalegap, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gapmax", &t->gapmax, 0, RC_FF_NONNEG, RC_D_L),
        {.name = "Fpenmax", .width = 20, .type = RC_FT_REAL, .out = &fpenmax, .flags = RC_FF_ONLY0, .dim = RC_D_NONE,
         .note = "the largest initial penetration as a fraction of the gap"},
        {.name = "ITIED", .width = 10, .type = RC_FT_INT, .out = &itied, .flags = RC_FF_ONLY0,
         .note = "tied contact"}};
    rc_field l3[] = {
        RC_F_REALD("Stmin", &t->stmin, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Stmax", &t->stmax, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("%mesh_size", &mesh_size, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("dtmin", &dtmin, 0, RC_FF_NONNEG, RC_D_T),
        RC_F_INT("Irem_gap", &irem_gap, 0, RC_FF_NONNEG),
        RC_F_INT("Irem_i2", &irem_i2, 0, RC_FF_NONNEG)};
    rc_field l4[] = {
        /* a stiffness [N/m] with Istf 1, a factor with Istf 0: converted as a
         * stiffness and back for Istf 0 below */
        RC_F_REALD("Stfac", &t->stfac, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gapmin", &t->gapmin, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l5[] = {
        {.name = "IBC", .width = 10, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(20),
        RC_F_INT("Inacti", &t->inacti, 0, 0),
        RC_F_REALD("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("VISF", &t->visf, RC_T7_DEF_VISF, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Bumult", &bumult, 0, RC_FF_NONNEG, RC_D_NONE)};
    rc_field l6[] = {
        RC_F_INT("Ifric", &ifric, 0, 0),
        RC_F_INT("Ifiltr", &ifiltr, 0, 0),
        RC_F_REALD("Xfreq", &xfreq, 1, 0, RC_D_NONE),
        RC_F_INT("Iform", &t->iform, 0, RC_FF_NONNEG),
        RC_F_INT("sens_ID", &t->sensor_id, 0, RC_FF_NONNEG),
        {.name = "fct_IDF", .width = 10, .type = RC_FT_INT, .out = &fct_f, .flags = RC_FF_ONLY0,
         .note = "a friction coefficient that varies with temperature"},
        RC_F_REALD("AscaleF", &ascalef, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_INT("fric_ID", &t->fric_id, 0, RC_FF_NONNEG)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    for (int k = 0; k < 6; k++) {
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    if ((st = inter_friction_lines(rd, b, nd, l6, ifric, ifiltr, xfreq, t->iform, t->fric, t->visf, &t->fric_id,
                                   "Icurv and Ithe 0: no curvature or thermal lines; ")))
        return st;
    /* the stiffness: Stfac a stiffness value (Istf 1), or a factor on the
     * main elements' stiffness (0, 1000: model/type7.c) */
    if (t->istf == RC_T7_DEFAULT) t->istf = 0;
    if (t->istf > 5)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Istf",
                            "expected 0, 1000 (the main elements' stiffness times Stfac), 1 (Stfac is the "
                            "stiffness [N/m]), 2, 3, 4 or 5 (the main and secondary elements' stiffnesses times "
                            "Stfac: their mean, larger, smaller, or in series), got %s",
                            l1[2].got);
    if (t->istf == 1 && !(t->stfac > 0))
        return rc_case_fail(rd, &t->line_loc[3], b->name, "Stfac",
                            "with Istf 1, Stfac is the interface stiffness: expected a value > 0 [N/m], got %s",
                            l4[0].got);
    /* Istf 0, 2-5: Stfac is a factor, converted as a stiffness above: back */
    if (t->istf != 1 && rc_units_convert(rd)) t->stfac /= rc_dim_scale(RC_D_K, rd->cur_units);
    if (t->istf != 1 && t->stfac == 0) t->stfac = 1.0; /* the scale factor's default */
    if (t->stmax > 0 && t->stmax < t->stmin)
        return rc_case_fail(rd, &t->line_loc[2], b->name, "Stmax", "expected Stmax >= Stmin = %.15g (or 0: none), got %s",
                            t->stmin, l3[1].got);
    /* Igap: 0 (1000) the constant gap Gapmin; 1, 2 the shells' half
     * thicknesses (model/type7.c); 3 also bounds it by the mesh size */
    if (t->igap == RC_T7_DEFAULT) t->igap = 0;
    if (t->igap == 3)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Igap",
                            "got %s: not supported yet (Igap 3 also bounds the variable gap by %%mesh_size times "
                            "the elements' size); expected 0, blank or 1000 (the constant gap Gapmin), 1 (the "
                            "variable gap of the shells' thicknesses) or 2 (the same, scaled by Fscalegap, at most "
                            "Gapmax)",
                            l1[4].got);
    if (t->igap > 2)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Igap",
                            "expected 0, blank or 1000 (the constant gap Gapmin), 1 (the variable gap of the shells' "
                            "thicknesses) or 2 (the same, scaled by Fscalegap, at most Gapmax), got %s",
                            l1[4].got);
    if (t->fscalegap == 0) t->fscalegap = 1.0; /* Igap 2's scale: Radioss's default */
    if ((st = t7_inacti(rd, b, &t->line_loc[4], &t->inacti, &l5[2], 7))) return st;
    if (t->visf != RC_T7_DEF_VISF)
        return rc_case_fail(rd, &t->line_loc[4], b->name, "VISF",
                            "expected 1, 0 or blank (the default), got %s: not supported yet (ricochet's friction "
                            "per contact point has no tangential damping)",
                            l5[4].got);
    if (t->iform > 2 && t->iform != RC_T7_DEFAULT)
        return rc_case_fail(rd, &t->line_loc[5], b->name, "Iform",
                            "expected 0, 1, 2 or 1000 (friction penalty formulation), got %s", l6[3].got);
    if (t->tstop < t->tstart)
        return rc_case_fail(rd, &t->line_loc[3], b->name, "Tstop", "expected Tstop >= Tstart = %.15g, got %s",
                            t->tstart, l4[4].got);
    (void)ibag;
    (void)idel;
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* ======================================================================
 * /INTER/TYPE24
 * ====================================================================== */

/* The start TYPE24, TYPE25, TYPE11 and TYPE19 share: the header, a new
 * record of c->type24 of the given type, and the refusal of the layouts
 * before version minver (110: 11.0). */
static rc_status t24_begin(rc_reader *rd, const rc_block *b, int type, rc_case_type24 **out, int minver)
{
    rc_case *c = rd->c;
    rc_status st;
    char usage[40];
    snprintf(usage, sizeof usage, "/INTER/TYPE%d/inter_ID", type);
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "inter_ID", usage))) return st;
    RC_GROW(rd, c->type24, rd->captype24, c->ntype24);
    rc_case_type24 *t = &c->type24[c->ntype24++];
    t->id = b->id;
    t->type = type;
    t->loc = b->hdr->loc;
    for (int k = 0; k < 6; k++) t->line_loc[k] = t->loc;
    *out = t;
    if (rc_layout_version(rd) < minver)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "the /INTER/TYPE%d layout of Radioss versions before %d.0 (/BEGIN Invers %d) is not "
                            "supported yet: expected Invers %d or later (or 0)",
                            type, minver / 10, rc_layout_version(rd), minver);
    return RC_OK;
}

/* The fields whose checks TYPE24 and TYPE25 share (their columns differ:
 * the fields as each card read them, for the text it got). */
typedef struct {
    const rc_field *surf2, *istf, *stfac, *stmax, *igap0, *inacti, *tstop;
    const char *surf1_name; /* the first side's field */
} t24_fields;

/* Those checks, on the values read into t (and Igap0): two surfaces, no
 * self-contact; Istf 0/1000 or 1 with its Stfac (a factor converted back
 * from a stiffness for Istf 0, 1 by default); Stmax >= Stmin; Igap0 0, 1 or
 * 1000 (the gap is zero: model/type7.c); Inacti 0 or 5; Tstop >= Tstart. */
static rc_status t24_checks(rc_reader *rd, const rc_block *b, rc_case_type24 *t, int igap0, const t24_fields *f)
{
    /* the two sides: surfaces, or TYPE11's lines */
    const int one = t->type == 11 ? t->line1 : t->surf1, two = t->type == 11 ? t->line2 : t->surf2;
    const char *n1 = f->surf1_name, *n2 = f->surf2->name, *what = t->type == 11 ? "line" : "surface";
    if (two == 0)
        return rc_case_fail(rd, &t->line_loc[0], b->name, n2,
                            "blank or 0 (self-contact of %s) is not supported yet: a rigid body does not "
                            "meet itself; expected the id of the second %s",
                            n1, what);
    if (two == one)
        return rc_case_fail(rd, &t->line_loc[0], b->name, n2,
                            "expected a %s other than %s = %d (self-contact is not supported yet), got %s", what, n1,
                            one, f->surf2->got);
    /* the stiffness: Stfac a stiffness value (Istf 1), or a factor on the
     * shells' stiffness (0, 1000: model/type7.c) */
    if (t->istf == RC_T7_DEFAULT) t->istf = 0;
    /* TYPE24's Istf 6 (Radioss: the smaller of the two, adjusted for the
     * convergence of its implicit solver) is read as 4 (docs/theory.md 3.8) */
    if (t->istf == 6 && t->type == 24) t->istf = 4;
    if (t->istf > 5)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Istf",
                            "expected 0, 1000 (the shells' stiffness times Stfac, the mean over both surfaces), 1 "
                            "(Stfac is the stiffness [N/m]), 2, 3, 4 or 5 (the two surfaces' stiffnesses times "
                            "Stfac: their mean, larger, smaller, or in series)%s, got %s",
                            t->type == 24 ? " or 6 (read as 4)" : "", f->istf->got);
    if (t->istf == 1 && !(t->stfac > 0))
        return rc_case_fail(rd, &t->line_loc[3], b->name, "Stfac",
                            "with Istf 1, Stfac is the interface stiffness: expected a value > 0 [N/m], got %s",
                            f->stfac->got);
    if (t->istf != 1 && rc_units_convert(rd)) t->stfac /= rc_dim_scale(RC_D_K, rd->cur_units);
    if (t->istf != 1 && t->stfac == 0) t->stfac = 1.0; /* the scale factor's default */
    if (t->stmax > 0 && t->stmax < t->stmin)
        return rc_case_fail(rd, &t->line_loc[2], b->name, "Stmax", "expected Stmax >= Stmin = %.15g (or 0: none), got %s",
                            t->stmin, f->stmax->got);
    if (igap0 != 0 && igap0 != 1 && igap0 != RC_T7_DEFAULT)
        return rc_case_fail(rd, &t->line_loc[2], b->name, "Igap0", "expected 0, 1 or 1000, got %s", f->igap0->got);
    /* TYPE11, TYPE19: TYPE7's values; TYPE24, TYPE25: -1 every initial
     * penetration acts (ricochet's 0), 5 the main segment shifted by it */
    if (t->type == 11 || t->type == 19) {
        rc_status st = t7_inacti(rd, b, &t->line_loc[4], &t->inacti, f->inacti, t->type);
        if (st) return st;
    } else {
        if (t->inacti == RC_T7_DEFAULT || t->inacti == -1) t->inacti = 0;
        if (t->inacti != 0 && t->inacti != 5)
            return rc_case_fail(rd, &t->line_loc[4], b->name, "Inacti",
                                "expected -1 (every initial penetration acts), 0, blank, 1000 (no action) or 5 (the "
                                "gap reduced by the initial penetration), Radioss's values of TYPE%d, got %s",
                                t->type,
                                f->inacti->got);
    }
    if (t->tstop < t->tstart)
        return rc_case_fail(rd, &t->line_loc[3], b->name, "Tstop", "expected Tstop >= Tstart = %.15g, got %s",
                            t->tstart, f->tstop->got);
    return RC_OK;
}

/* /INTER/TYPE24/inter_ID: title and Radioss's six lines (layout of 11.0 and
 * later; the friction law lines of Ifric are refused with their flag). */
rc_status rc_card_type24(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    rc_case_type24 *t = NULL;
    if ((st = t24_begin(rd, b, 24, &t, 110))) return st;
    if ((st = rc_card_lines(rd, b, t->title, 6, 8,
                            "surf_ID1 surf_ID2 Istf (blank) (blank) Irem_i2 (blank) Idel, grnd_IDs (blank) Iedge "
                            "Edge_angle Gap_max_s Gap_max_m, Stmin Stmax Igap0 Ipen0 Ipen_max, Stfac Fric "
                            "(blank) Tstart Tstop, IBC (blank) Inacti VISs (blank) Tpressfit, Ifric Ifiltr Xfreq "
                            "(blank) sens_ID (blank) fric_ID",
                            &nd)))
        return st;
    int irem_i2 = 0, idel = 0, grnod = 0, iedge = 0, igap0 = 0, ipen0 = 0, ibc = 0, ifric = 0, ifiltr = 0;
    double edge_angle = 0, gap_max_s = 0, gap_max_m = 0, ipen_max = 0, tpressfit = 0, xfreq = 0;
    rc_field l1[] = {
        RC_F_INT("surf_ID1", &t->surf1, 0, RC_FF_POS),
        {.name = "surf_ID2", .width = 10, .type = RC_FT_INT, .out = &t->surf2, .flags = RC_FF_NONNEG},
        RC_F_INT("Istf", &t->istf, 0, RC_FF_NONNEG),
        RC_F_SKIP(20),
        RC_F_INT("Irem_i2", &irem_i2, 0, 0),
        RC_F_SKIP(10),
        RC_F_INT("Idel", &idel, 0, 0)};
    rc_field l2[] = {
        {.name = "grnd_IDs", .width = 10, .type = RC_FT_INT, .out = &grnod, .flags = RC_FF_ONLY0,
         .note = "additional secondary nodes; expected the nodes as segments of surf_ID1 or an /INTER/TYPE7"},
        RC_F_SKIP(20),
        {.name = "Iedge", .width = 10, .type = RC_FT_INT, .out = &iedge, .flags = RC_FF_ONLY0,
         .note = "edge-to-edge contact of TYPE24"},
        RC_F_REALD("Edge_angle", &edge_angle, 0, 0, RC_D_NONE),
        RC_F_REALD("Gap_max_s", &gap_max_s, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Gap_max_m", &gap_max_m, 0, RC_FF_NONNEG, RC_D_L)};
    rc_field l3[] = {
        RC_F_REALD("Stmin", &t->stmin, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Stmax", &t->stmax, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_INT("Igap0", &igap0, 0, RC_FF_NONNEG),
        RC_F_INT("Ipen0", &ipen0, 0, RC_FF_NONNEG),
        {.name = "Ipen_max", .width = 20, .type = RC_FT_REAL, .out = &ipen_max, .flags = RC_FF_ONLY0, .dim = RC_D_L,
         .note = "the largest initial penetration taken into account"}};
    rc_field l4[] = {
        /* a stiffness [N/m] with Istf 1, a factor with Istf 0: converted as a
         * stiffness and back for Istf 0 below */
        RC_F_REALD("Stfac", &t->stfac, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_SKIP(20),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l5[] = {
        {.name = "IBC", .width = 10, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(20),
        RC_F_INT("Inacti", &t->inacti, 0, 0),
        RC_F_REALD("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_SKIP(20),
        {.name = "Tpressfit", .width = 20, .type = RC_FT_REAL, .out = &tpressfit, .flags = RC_FF_ONLY0, .dim = RC_D_T,
         .note = "press-fit of initially penetrating surfaces"}};
    rc_field l6[] = {
        RC_F_INT("Ifric", &ifric, 0, 0),
        RC_F_INT("Ifiltr", &ifiltr, 0, 0),
        RC_F_REALD("Xfreq", &xfreq, 1, 0, RC_D_NONE),
        RC_F_SKIP(10),
        RC_F_INT("sens_ID", &t->sensor_id, 0, RC_FF_NONNEG),
        RC_F_SKIP(30),
        RC_F_INT("fric_ID", &t->fric_id, 0, RC_FF_NONNEG)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    for (int k = 0; k < 6; k++) {
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    if ((st = inter_friction_lines(rd, b, nd, l6, ifric, ifiltr, xfreq, 2, t->fric, 1.0, &t->fric_id,
                                   "")))
        return st;
    const t24_fields f = {&l1[1], &l1[2], &l4[0], &l3[1], &l3[2], &l5[2], &l4[4], "surf_ID1"};
    if ((st = t24_checks(rd, b, t, igap0, &f))) return st;
    if ((st = t7_only_default(rd, b, &t->line_loc[2], &l3[3], ipen0,
                              "initial penetrations within each part; ricochet's bodies are rigid")))
        return st;
    (void)irem_i2;
    (void)idel;
    (void)edge_angle;
    (void)gap_max_s;
    (void)gap_max_m;
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* ======================================================================
 * /INTER/TYPE25
 * ====================================================================== */

/* /INTER/TYPE25/inter_ID: title and Radioss's six lines (layout of 11.0 and
 * later; the friction law lines of Ifric, the adhesion line of IVIS2 -1
 * and the thermal lines of Ithe are refused with their flags). Read into
 * c->type24 (type 25). */
rc_status rc_card_type25(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    rc_case_type24 *t = NULL;
    if ((st = t24_begin(rd, b, 25, &t, 110))) return st;
    if ((st = rc_card_lines(rd, b, t->title, 6, 12,
                            "surf_ID1 surf_ID2 Istf Ithe Igap Irem_i2 (blank) Idel Iedge IPSTIF, grnd_IDs (blank) "
                            "Gap_scale %mesh_size Gap_max_s Gap_max_m, Stmin Stmax Igap0 Ishape Edge_angle "
                            "STFAC_MDT, Stfac Fric Tpressfit Tstart Tstop, IBC (blank) IVIS2 Inacti VISs Ithick "
                            "(blank) Pmax, Ifric Ifiltr Xfreq (blank) sens_ID DTSTIF (blank) fric_ID",
                            &nd)))
        return st;
    int ithe = 0, igap = 0, irem_i2 = 0, idel = 0, grnod = 0, igap0 = 0, ishape = 0, ibc = 0, ivis2 = 0;
    int ifric = 0, ifiltr = 0, ipstif = 0, ithick = 0;
    double stfac_mdt = 0, tpressfit = 0, pmax = 0, dtstif = 0;
    double gap_scale = 0, mesh_size = 0, gap_max_s = 0, gap_max_m = 0, edge_angle = 0, xfreq = 0;
    rc_field l1[] = {
        RC_F_INT("surf_ID1", &t->surf1, 0, RC_FF_POS),
        {.name = "surf_ID2", .width = 10, .type = RC_FT_INT, .out = &t->surf2, .flags = RC_FF_NONNEG},
        RC_F_INT("Istf", &t->istf, 0, RC_FF_NONNEG),
        {.name = "Ithe", .width = 10, .type = RC_FT_INT, .out = &ithe, .flags = RC_FF_ONLY0,
         .note = "heat transfer: ricochet has no temperatures"},
        RC_F_INT("Igap", &igap, 0, RC_FF_NONNEG),
        RC_F_INT("Irem_i2", &irem_i2, 0, 0),
        RC_F_SKIP(10),
        RC_F_INT("Idel", &idel, 0, 0),
        RC_F_INT("Iedge", &t->iedge, 0, RC_FF_NONNEG),
        {.name = "IPSTIF", .width = 10, .type = RC_FT_INT, .out = &ipstif, .flags = RC_FF_ONLY0,
         .note = "the other penalty stiffness formulations of TYPE25"}};
    rc_field l2[] = {
        {.name = "grnd_IDs", .width = 10, .type = RC_FT_INT, .out = &grnod, .flags = RC_FF_ONLY0,
         .note = "additional secondary nodes; expected the nodes as segments of surf_ID1 or an /INTER/TYPE7"},
        RC_F_SKIP(10),
        RC_F_REALD("Gap_scale", &gap_scale, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("%mesh_size", &mesh_size, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gap_max_s", &gap_max_s, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Gap_max_m", &gap_max_m, 0, RC_FF_NONNEG, RC_D_L)};
    rc_field l3[] = {
        RC_F_REALD("Stmin", &t->stmin, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Stmax", &t->stmax, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_INT("Igap0", &igap0, 0, RC_FF_NONNEG),
        RC_F_INT("Ishape", &ishape, 0, RC_FF_NONNEG),
        RC_F_REALD("Edge_angle", &edge_angle, 0, 0, RC_D_NONE),
        {.name = "STFAC_MDT", .width = 20, .type = RC_FT_REAL, .out = &stfac_mdt, .flags = RC_FF_ONLY0,
         .dim = RC_D_NONE, .note = "a stiffness from the explicit time step"}};
    rc_field l4[] = {
        RC_F_REALD("Stfac", &t->stfac, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        {.name = "Tpressfit", .width = 20, .type = RC_FT_REAL, .out = &tpressfit, .flags = RC_FF_ONLY0, .dim = RC_D_T,
         .note = "press-fit of initially penetrating surfaces"},
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l5[] = {
        {.name = "IBC", .width = 10, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(10),
        {.name = "IVIS2", .width = 10, .type = RC_FT_INT, .out = &ivis2, .flags = RC_FF_ONLY0,
         .note = "the other damping formulations and adhesion of TYPE25"},
        RC_F_INT("Inacti", &t->inacti, 0, 0),
        RC_F_REALD("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        {.name = "Ithick", .width = 10, .type = RC_FT_INT, .out = &ithick, .flags = RC_FF_ONLY0,
         .note = "a gap from the shells' thickness"},
        RC_F_SKIP(10),
        {.name = "Pmax", .width = 20, .type = RC_FT_REAL, .out = &pmax, .flags = RC_FF_ONLY0, .dim = RC_D_K2,
         .note = "a largest contact pressure"}};
    rc_field l6[] = {
        RC_F_INT("Ifric", &ifric, 0, 0),
        RC_F_INT("Ifiltr", &ifiltr, 0, 0),
        RC_F_REALD("Xfreq", &xfreq, 1, 0, RC_D_NONE),
        RC_F_SKIP(10),
        RC_F_INT("sens_ID", &t->sensor_id, 0, RC_FF_NONNEG),
        {.name = "DTSTIF", .width = 20, .type = RC_FT_REAL, .out = &dtstif, .flags = RC_FF_ONLY0, .dim = RC_D_NONE,
         .note = "a stiffness from the explicit time step"},
        RC_F_SKIP(10),
        RC_F_INT("fric_ID", &t->fric_id, 0, RC_FF_NONNEG)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    for (int k = 0; k < 6; k++) {
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    if ((st = inter_friction_lines(rd, b, nd, l6, ifric, ifiltr, xfreq, 2, t->fric, 1.0, &t->fric_id,
                                   "IVIS2 0 and Ithe 0: no adhesion or thermal lines; ")))
        return st;
    const t24_fields f = {&l1[1], &l1[2], &l4[0], &l3[1], &l3[2], &l5[3], &l4[4], "surf_ID1"};
    if ((st = t24_checks(rd, b, t, igap0, &f))) return st;
    if ((st = t7_only_default(rd, b, &t->line_loc[0], &l1[4], igap,
                              "a variable gap from the elements' thicknesses and sizes; ricochet's TYPE25 gap is zero")))
        return st;
    /* Iedge: 0 and 1000 none; 1 (free edges), 2 (all edges), 3 (both)
     * checked against the surfaces by the compiler (model/type7.c) */
    if (t->iedge == RC_T7_DEFAULT) t->iedge = 0;
    if (t->iedge > 3)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Iedge", "expected 0, 1, 2, 3 or 1000, got %s", l1[8].got);
    (void)irem_i2;
    (void)idel;
    (void)gap_scale;
    (void)mesh_size;
    (void)gap_max_s;
    (void)gap_max_m;
    (void)ishape;
    (void)edge_angle;
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* ======================================================================
 * /INTER/TYPE11 and /INTER/TYPE19
 * ====================================================================== */

/* /INTER/TYPE11/inter_ID: title and Radioss's four lines (layouts of 11.0
 * to 2017), or five (2018 and later: the fric_ID line); the thermal lines
 * of Ithe are refused with their flag. One table reads every layout from
 * 11.0 on: the columns a version lacks (Ithe before 14.0, Irem_gap before
 * 2020, dtmin Iform sens_ID in 11.0) are blank there, and 11.0's Multimp
 * (columns 51-60, blank from 12.0 on) is read, unused. The layouts of 5.1
 * to 10.0 lack the Stmin line (three lines); those of 4.x write the same
 * three lines in 8- and 16-character fields. Read into c->type24 (type 11)
 * with the two /LINE ids; the line roles of t->line_loc are TYPE24's
 * (line 1, line 1, Stmin, Stfac, Inacti, fric_ID). */
rc_status rc_card_type11(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    rc_case_type24 *t = NULL;
    if ((st = t24_begin(rd, b, 11, &t, 41))) return st;
    const int ver = rc_layout_version(rd), nmax = ver >= 2018 ? 5 : ver >= 110 ? 4 : 3;
    if (ver < 110 && (st = rc_card_lines(rd, b, t->title, 3, 3,
                                         ver >= 51 ? "line_IDs line_IDm Istf (blank) Igap Multimp (blank) Idel, Stfac Fric "
                                                     "Gapmin Tstart Tstop, IBC Inacti VISs VISF Bumult (Radioss 5.1-10.0 "
                                                     "layout)"
                                                   : "line_IDs line_IDm Istf (blank) Igap Multimp, Stfac Fric Gapmin Tstart "
                                                     "Tstop, IBC Inacti VISs VISF Bumult (Radioss 4.x layout, 8- and "
                                                     "16-character fields)",
                                         &nd)))
        return st;
    if (ver >= 110 && (st = rc_card_lines(rd, b, t->title, 4, nmax,
                            nmax == 5 ? "line_IDs line_IDm Istf Ithe Igap Multimp Irem_gap Idel, Stmin Stmax "
                                        "%mesh_size dtmin Iform sens_ID, Stfac Fric Gapmin Tstart Tstop, IBC "
                                        "Inacti VISs VISF Bumult[, fric_ID]"
                                      : "line_IDs line_IDm Istf Ithe Igap Multimp Irem_gap Idel, Stmin Stmax "
                                        "%mesh_size dtmin Iform sens_ID, Stfac Fric Gapmin Tstart Tstop, IBC "
                                        "Inacti VISs VISF Bumult",
                            &nd)))
        return st;
    int ithe = 0, igap = 0, multimp = 0, irem_gap = 0, idel = 0, iform = 0, ibc = 0;
    double mesh_size = 0, dtmin = 0, visf = RC_T7_DEF_VISF, bumult = 0;
    static const char heat[] = "heat transfer: ricochet has no temperatures";
    rc_field l1[] = {
        RC_F_INT("line_IDs", &t->line1, 0, RC_FF_POS),
        {.name = "line_IDm", .width = 10, .type = RC_FT_INT, .out = &t->line2, .flags = RC_FF_NONNEG},
        RC_F_INT("Istf", &t->istf, 0, RC_FF_NONNEG),
        {.name = "Ithe", .width = 10, .type = RC_FT_INT, .out = &ithe, .flags = RC_FF_ONLY0, .note = heat},
        RC_F_INT("Igap", &igap, 0, RC_FF_NONNEG),
        RC_F_INT("Multimp", &multimp, 0, RC_FF_NONNEG),
        RC_F_INT("Irem_gap", &irem_gap, 0, RC_FF_NONNEG),
        RC_F_INT("Idel", &idel, 0, 0)};
    rc_field l2[] = {
        RC_F_REALD("Stmin", &t->stmin, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Stmax", &t->stmax, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("%mesh_size", &mesh_size, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("dtmin", &dtmin, 0, RC_FF_NONNEG, RC_D_T),
        RC_F_INT("Iform", &iform, 0, RC_FF_NONNEG),
        RC_F_INT("sens_ID", &t->sensor_id, 0, RC_FF_NONNEG)};
    rc_field l3[] = {
        RC_F_REALD("Stfac", &t->stfac, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gapmin", &t->gapmin, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l4[] = {
        {.name = "IBC", .width = 10, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(20),
        RC_F_INT("Inacti", &t->inacti, 0, 0),
        RC_F_REALD("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("VISF", &visf, RC_T7_DEF_VISF, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Bumult", &bumult, 0, RC_FF_NONNEG, RC_D_NONE)};
    rc_field l5[] = {RC_F_SKIP(90), RC_F_INT("fric_ID", &t->fric_id, 0, RC_FF_NONNEG)};
    /* 4.x: 8- and 16-character fields, no Stmin line */
    rc_field o1[] = {RC_F_INTW("line_IDs", &t->line1, 0, RC_FF_POS, 8),
                     {.name = "line_IDm", .width = 8, .type = RC_FT_INT, .out = &t->line2, .flags = RC_FF_NONNEG},
                     RC_F_INTW("Istf", &t->istf, 0, RC_FF_NONNEG, 8), RC_F_SKIP(8),
                     RC_F_INTW("Igap", &igap, 0, RC_FF_NONNEG, 8), RC_F_INTW("Multimp", &multimp, 0, RC_FF_NONNEG, 8)};
    rc_field o3[] = {RC_F_REALW("Stfac", &t->stfac, 0, RC_FF_NONNEG, 16, RC_D_K),
                     RC_F_REALW("Fric", &t->fric, 0, RC_FF_NONNEG, 16, RC_D_NONE),
                     RC_F_REALW("Gapmin", &t->gapmin, 0, RC_FF_NONNEG, 16, RC_D_L),
                     RC_F_REALW("Tstart", &t->tstart, 0, 0, 16, RC_D_T),
                     RC_F_REALW("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, 16, RC_D_T)};
    rc_field o4[] = {
        {.name = "IBC", .width = 8, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(16),
        RC_F_INTW("Inacti", &t->inacti, 0, 0, 8),
        RC_F_REALW("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, 16, RC_D_NONE),
        RC_F_REALW("VISF", &visf, RC_T7_DEF_VISF, RC_FF_ZDEF | RC_FF_NONNEG, 16, RC_D_NONE),
        RC_F_REALW("Bumult", &bumult, 0, RC_FF_NONNEG, 16, RC_D_NONE)};
    rc_field *lines[5] = {l1, l2, l3, l4, l5};
    int nf[5] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5)};
    int role[5] = {0, 2, 3, 4, 5}; /* TYPE24's line of each */
    if (ver < 110) { /* no Stmin line: Stmin, Stmax 0 */
        lines[1] = ver >= 51 ? l3 : o3;
        lines[2] = ver >= 51 ? l4 : o4;
        nf[1] = ver >= 51 ? RC_NF(l3) : RC_NF(o3);
        nf[2] = ver >= 51 ? RC_NF(l4) : RC_NF(o4);
        role[1] = 3;
        role[2] = 4;
        if (ver < 51) {
            lines[0] = o1;
            nf[0] = RC_NF(o1);
        }
        t->line_loc[2] = b->lines[1].loc;
    }
    t->line_loc[1] = t->line_loc[5] = b->lines[1].loc;
    for (int k = 0; k < nd; k++) {
        t->line_loc[role[k]] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    const rc_field igap0 = RC_F_INT("Igap0", NULL, 0, 0);
    const rc_field *const fl1 = lines[0], *const fl3 = lines[ver < 110 ? 1 : 2], *const fl4 = lines[ver < 110 ? 2 : 3];
    const t24_fields f = {&fl1[1], &fl1[2], &fl3[0], &l2[1], &igap0, &fl4[2], &fl3[4], "line_IDs"};
    if ((st = t24_checks(rd, b, t, 0, &f))) return st;
    if ((st = t7_only_default(rd, b, &t->line_loc[0], &fl1[4], igap,
                              "a variable gap from the elements' thicknesses and sizes; 0 is the constant gap Gapmin")))
        return st;
    if (visf != RC_T7_DEF_VISF)
        return rc_case_fail(rd, &t->line_loc[4], b->name, "VISF",
                            "expected 1, 0 or blank (the default), got %s: not supported yet (ricochet's friction "
                            "per contact point has no tangential damping)",
                            fl4[4].got);
    if (iform > 2 && iform != RC_T7_DEFAULT)
        return rc_case_fail(rd, &t->line_loc[2], b->name, "Iform",
                            "expected 0, 1, 2 or 1000 (friction penalty formulation), got %s", l2[4].got);
    (void)multimp;
    (void)irem_gap;
    (void)idel;
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* /INTER/TYPE19/inter_ID: title and Radioss's six lines; the curvature line
 * of Icurv 1, 2, the friction law lines of Ifric and the thermal lines of
 * Ithe are refused with their flags. One table reads every layout from
 * 11.0 on (the columns a version lacks are blank there: Ithe before 2021,
 * Iedge in 14.0, %mesh_size Irem_gap Irem_i2 before 2020, dtmin and
 * sens_ID in 11.0, fric_ID before 2018). Read into c->type24 (type 19). */
rc_status rc_card_type19(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    rc_case_type24 *t = NULL;
    if ((st = t24_begin(rd, b, 19, &t, 100))) return st;
    if ((st = rc_card_lines(rd, b, t->title, 6, 12,
                            "surf_IDs surf_IDm Istf Ithe Igap Iedge Ibag Idel Icurv, Fscalegap Gapmax, Stmin "
                            "Stmax %mesh_size dtmin Irem_gap Irem_i2, Stfac Fric Gapmin Tstart Tstop, IBC (blank) "
                            "Inacti VISs VISF Bumult, Ifric Ifiltr Xfreq Iform sens_ID (blank) fric_ID",
                            &nd)))
        return st;
    int ithe = 0, igap = 0, iedge = 0, ibag = 0, idel = 0, icurv = 0, irem_gap = 0, irem_i2 = 0, ibc = 0;
    int ifric = 0, ifiltr = 0, iform = 0;
    double fscalegap = 0, gapmax = 0, mesh_size = 0, dtmin = 0, visf = RC_T7_DEF_VISF, bumult = 0, xfreq = 0;
    static const char heat[] = "heat transfer: ricochet has no temperatures";
    rc_field l1[] = {
        RC_F_INT("surf_IDs", &t->surf1, 0, RC_FF_POS),
        {.name = "surf_IDm", .width = 10, .type = RC_FT_INT, .out = &t->surf2, .flags = RC_FF_NONNEG},
        RC_F_INT("Istf", &t->istf, 0, RC_FF_NONNEG),
        {.name = "Ithe", .width = 10, .type = RC_FT_INT, .out = &ithe, .flags = RC_FF_ONLY0, .note = heat},
        RC_F_INT("Igap", &igap, 0, RC_FF_NONNEG),
        RC_F_INT("Iedge", &iedge, 0, RC_FF_NONNEG),
        RC_F_INT("Ibag", &ibag, 0, RC_FF_NONNEG),
        RC_F_INT("Idel", &idel, 0, 0),
        {.name = "Icurv", .width = 10, .type = RC_FT_INT, .out = &icurv, .flags = RC_FF_ONLY0,
         .note = "a gap envelope with curvature"}};
    rc_field l2[] = {
        RC_F_REALD("Fscalegap", &fscalegap, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gapmax", &gapmax, 0, RC_FF_NONNEG, RC_D_L)};
    rc_field l3[] = {
        RC_F_REALD("Stmin", &t->stmin, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Stmax", &t->stmax, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("%mesh_size", &mesh_size, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("dtmin", &dtmin, 0, RC_FF_NONNEG, RC_D_T),
        RC_F_INT("Irem_gap", &irem_gap, 0, RC_FF_NONNEG),
        RC_F_INT("Irem_i2", &irem_i2, 0, RC_FF_NONNEG)};
    rc_field l4[] = {
        RC_F_REALD("Stfac", &t->stfac, 0, RC_FF_NONNEG, RC_D_K),
        RC_F_REALD("Fric", &t->fric, 0, RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Gapmin", &t->gapmin, 0, RC_FF_NONNEG, RC_D_L),
        RC_F_REALD("Tstart", &t->tstart, 0, 0, RC_D_T),
        RC_F_REALD("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF, RC_D_T)};
    rc_field l5[] = {
        {.name = "IBC", .width = 10, .type = RC_FT_INT, .out = &ibc, .flags = RC_FF_ONLY0,
         .note = "boundary conditions of the secondary nodes at deactivation"},
        RC_F_SKIP(20),
        RC_F_INT("Inacti", &t->inacti, 0, 0),
        RC_F_REALD("VISs", &t->viss, RC_T7_DEF_VISS, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("VISF", &visf, RC_T7_DEF_VISF, RC_FF_ZDEF | RC_FF_NONNEG, RC_D_NONE),
        RC_F_REALD("Bumult", &bumult, 0, RC_FF_NONNEG, RC_D_NONE)};
    rc_field l6[] = {
        RC_F_INT("Ifric", &ifric, 0, 0),
        RC_F_INT("Ifiltr", &ifiltr, 0, 0),
        RC_F_REALD("Xfreq", &xfreq, 1, 0, RC_D_NONE),
        RC_F_INT("Iform", &iform, 0, RC_FF_NONNEG),
        RC_F_INT("sens_ID", &t->sensor_id, 0, RC_FF_NONNEG),
        RC_F_SKIP(30),
        RC_F_INT("fric_ID", &t->fric_id, 0, RC_FF_NONNEG)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};
    for (int k = 0; k < 6; k++) {
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    if ((st = inter_friction_lines(rd, b, nd, l6, ifric, ifiltr, xfreq, iform, t->fric, visf, &t->fric_id,
                                   "Icurv and Ithe 0: no curvature or thermal lines; ")))
        return st;
    const rc_field igap0 = RC_F_INT("Igap0", NULL, 0, 0);
    const t24_fields f = {&l1[1], &l1[2], &l4[0], &l3[1], &igap0, &l5[2], &l4[4], "surf_IDs"};
    if ((st = t24_checks(rd, b, t, 0, &f))) return st;
    if ((st = t7_only_default(rd, b, &t->line_loc[0], &l1[4], igap,
                              "a variable gap from the elements' thicknesses and sizes; 0 is the constant gap Gapmin")))
        return st;
    if (visf != RC_T7_DEF_VISF)
        return rc_case_fail(rd, &t->line_loc[4], b->name, "VISF",
                            "expected 1, 0 or blank (the default), got %s: not supported yet (ricochet's friction "
                            "per contact point has no tangential damping)",
                            l5[4].got);
    if (iform > 2 && iform != RC_T7_DEFAULT)
        return rc_case_fail(rd, &t->line_loc[5], b->name, "Iform",
                            "expected 0, 1, 2 or 1000 (friction penalty formulation), got %s", l6[3].got);
    /* Iedge: which edges TYPE19 makes of the surfaces: 0, 1000 (the
     * default) and 2 every segment edge, the boxes' 12; 1 the free edges
     * of the surfaces, which a closed box has none of (model/type7.c: the
     * corners alone) */
    t->iedge = iedge == RC_T7_DEFAULT ? 0 : iedge;
    if (t->iedge > 2)
        return rc_case_fail(rd, &t->line_loc[0], b->name, "Iedge",
                            "expected 0, 1 (the free edges), 2 (every segment edge) or 1000, got %s", l1[5].got);
    (void)ibag;
    (void)idel;
    (void)fscalegap;
    (void)gapmax;
    (void)mesh_size;
    (void)dtmin;
    (void)irem_gap;
    (void)irem_i2;
    (void)bumult;
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}
