/*
 * Case cards: one function per card, each filling its part of rc_case from
 * a block (header + lines). Layouts are field tables (case_internal.h): the
 * table states each field's name (as in the Radioss documentation), width,
 * default and checks, so a card function is its layout plus the checks that
 * involve several fields. docs/case-format.md documents every table here.
 *
 * Values are range-checked one by one (negative mass, non-positive-definite
 * inertia, ...); references between cards are not resolved here (the
 * compiler does that). Values ricochet cannot honour yet are rejected with
 * "not supported yet", never ignored.
 */
#include "case/case_internal.h"
#include "base/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Defaults of /SOLVER (docs/case-format.md). */
#define RC_DEF_METHOD 1
#define RC_DEF_MAX_ORDER 5
#define RC_DEF_MAX_STEPS 100000
#define RC_DEF_RTOL 1e-8
/* absolute tolerances: 0 (blank) = derived from the model's scales */
#define RC_DEF_ATOL_POS 0.0
#define RC_DEF_ATOL_QUAT 0.0
#define RC_DEF_ATOL_VEL 0.0
#define RC_DEF_ATOL_OMEGA 0.0
#define RC_DEF_ATOL_ENERGY 0.0
/* Default output interval as a fraction of Tend. */
#define RC_DEF_DTOUT_FRACTION 0.01
/* Default Tstop of /INTER (Radioss). */
#define RC_DEF_TSTOP 1e30

/* An integer field with a "not supported yet" note. */
#define RC_F_INTN(nm, p, fl, nt) RC_F_SET(nm, p, 0, fl, 0, 0, nt)
#define RC_NF(arr) ((int)(sizeof(arr) / sizeof((arr)[0])))

static const char rc_note_skew[] = "(skew frames)";
static const char rc_note_sensor[] = "(sensors)";

/* ======================================================================
 * Header and common checks
 * ====================================================================== */

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
    /* a unit system other than the deck's */
    int unit = mode == RC_ID_UNIT ? b->id : b->unit_id;
    if (unit != 0)
        return rc_case_fail(rd, loc, b->name, "unit_ID",
                            "expected 0 or nothing, got %d: unit systems (/UNIT) not supported yet",
                            unit);
    return RC_OK;
}

/* A card allowed once per deck. */
static rc_status rc_single(rc_reader *rd, const rc_block *b, const rc_line **slot)
{
    if (*slot)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "only one such card is allowed, first at %s:%d", (*slot)->loc.file,
                            (*slot)->loc.line);
    *slot = b->hdr;
    return RC_OK;
}

/* Lines of a card of variable length: title, then any number of lines
 * (trailing blank lines dropped). */
static rc_status rc_var_lines(rc_reader *rd, const rc_block *b, char *title, const char *desc,
                              int *ndata)
{
    int n = rc_block_trim(b);
    rc_status st = rc_card_lines(rd, b, title, 0, b->n > 0 ? b->n - 1 : 0, desc, ndata);
    if (st) return st;
    *ndata = n > 1 ? n - 1 : 0;
    return RC_OK;
}

/* ======================================================================
 * /BEGIN and /NODE
 * ====================================================================== */

/* /BEGIN: run name; Invers Irun; input units; work units (= input). */
static rc_status rc_card_begin(rc_reader *rd, const rc_block *b)
{
    static const char *const in_nm[3] = {"Input_mass_unit", "Input_length_unit",
                                         "Input_time_unit"};
    static const char *const wk_nm[3] = {"Work_mass_unit", "Work_length_unit",
                                         "Work_time_unit"};
    rc_case *c = rd->c;
    char in[3][21] = {"", "", ""}, wk[3][21] = {"", "", ""};
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_NONE, NULL, "/BEGIN"))) return st;
    if ((st = rc_single(rd, b, &rd->begin_hdr))) return st;
    if ((st = rc_card_lines(rd, b, c->title, 3, 3, "Invers Irun, input units, work units", &nd)))
        return st;

    /* three lines: version flags (ignored), input units, work units */
    rc_field l1[] = {RC_F_INT("Invers", NULL, 0, 0), RC_F_INT("Irun", NULL, 0, 0)};
    rc_field l2[] = {RC_F_STR(in_nm[0], in[0], 20), RC_F_STR(in_nm[1], in[1], 20),
                     RC_F_STR(in_nm[2], in[2], 20)};
    rc_field l3[] = {RC_F_STR(wk_nm[0], wk[0], 20), RC_F_STR(wk_nm[1], wk[1], 20),
                     RC_F_STR(wk_nm[2], wk[2], 20)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;

    /* work units must be blank or the input units: no conversion yet */
    for (int k = 0; k < 3; k++)
        if (wk[k][0] && strcmp(wk[k], in[k]) != 0)
            return rc_case_fail(rd, &b->lines[3].loc, b->name, wk_nm[k],
                                "expected blank or \"%s\" (the input unit), got \"%s\": unit "
                                "conversion not supported yet",
                                in[k], wk[k]);
    memcpy(c->unit_mass, in[0], sizeof in[0]);
    memcpy(c->unit_length, in[1], sizeof in[1]);
    memcpy(c->unit_time, in[2], sizeof in[2]);
    return RC_OK;
}

/* /NODE: lines node_ID X Y Z. */
static rc_status rc_card_node(rc_reader *rd, const rc_block *b)
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
static rc_status rc_card_grnod(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0;
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
static rc_status rc_card_rbody(rc_reader *rd, const rc_block *b)
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
 * /SURF/PLANE and /SURF/ELLIPS
 * ====================================================================== */

/* New surface of the given kind (also used by case_cards_power.c). */
rc_case_surf *rc_new_surf(rc_reader *rd, const rc_block *b, rc_case_surf_kind kind)
{
    rc_case *c = rd->c;
    rc_case_surf *arr = rc_case_grow(rd, c->surf, &rd->capsurf, c->nsurf, sizeof *arr);
    if (!arr) return NULL;
    c->surf = arr;
    rc_case_surf *s = &c->surf[c->nsurf++];
    s->id = b->id;
    s->kind = kind;
    s->loc = b->hdr->loc;
    return s;
}

/* /SURF/PLANE/surf_ID: title; point M; point M1; ricochet: rbody_ID. */
static rc_status rc_card_plane(rc_reader *rd, const rc_block *b)
{
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "surf_ID", "/SURF/PLANE/surf_ID"))) return st;
    rc_case_surf *s = rc_new_surf(rd, b, RC_CASE_SURF_PLANE);
    if (!s) return RC_ENOMEM;
    if ((st = rc_card_lines(rd, b, s->title, 2, 3, "XM YM ZM, XM1 YM1 ZM1", &nd))) return st;

    /* M, M1 and the optional carrying body */
    rc_field l1[] = {RC_F_REAL("XM", &s->m[0], 0, 0), RC_F_REAL("YM", &s->m[1], 0, 0),
                     RC_F_REAL("ZM", &s->m[2], 0, 0)};
    rc_field l2[] = {RC_F_REAL("XM1", &s->m1[0], 0, 0), RC_F_REAL("YM1", &s->m1[1], 0, 0),
                     RC_F_REAL("ZM1", &s->m1[2], 0, 0)};
    rc_field l3[] = {RC_F_INT("rbody_ID", &s->rbody_id, 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if (nd == 3 && (st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;

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
static rc_status rc_card_ellips(rc_reader *rd, const rc_block *b)
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
    rc_field l2[] = {RC_F_REAL("Xc", &s->c[0], 0, 0), RC_F_REAL("Yc", &s->c[1], 0, 0),
                     RC_F_REAL("Zc", &s->c[2], 0, 0)};
    rc_field l3[] = {RC_F_REAL("a", &s->abc[0], 0, RC_FF_POS), RC_F_REAL("b", &s->abc[1], 0, RC_FF_POS),
                     RC_F_REAL("c", &s->abc[2], 0, RC_FF_POS)};
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
 * /INTER/TYPE6
 * ====================================================================== */

/* /INTER/TYPE6/inter_ID: title and the six Radioss lines. */
static rc_status rc_card_type6(rc_reader *rd, const rc_block *b)
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
    if ((st = rc_card_lines(rd, b, t->title, 6, 6,
                            "surf_ID1 surf_ID2, Sfric Fric Gap Tstart Tstop, IRS..., "
                            "fct_IDld..., fct_IDul..., Visc...",
                            &nd)))
        return st;

    rc_field l1[] = {RC_F_INT("surf_ID1", &t->surf1, 0, RC_FF_POS),
                     RC_F_INT("surf_ID2", &t->surf2, 0, RC_FF_POS)};
    rc_field l2[] = {
        RC_F_REAL("Sfric", &t->sfric, 0, RC_FF_NONNEG),
        RC_F_REAL("Fric", &t->fric, 0, RC_FF_NONNEG),
        RC_F_REAL("Gap", &t->gap, 0, RC_FF_NONNEG),
        RC_F_REAL("Tstart", &t->tstart, 0, 0),
        RC_F_REAL("Tstop", &t->tstop, RC_DEF_TSTOP, RC_FF_ZDEF)};
    rc_field l3[] = {
        RC_F_SKIP(10),
        RC_F_SET("IRS", &t->irs, 0, 0, 0x7u, RC_BIT(0),
                 "(only analytic surfaces exist now; their normals are fixed)"),
        RC_F_SET("IRm", &t->irm, 0, 0, 0x7u, RC_BIT(0),
                 "(only analytic surfaces exist now; their normals are fixed)"),
        RC_F_SET("Inacti", &t->inacti, 0, 0, RC_BIT(0) | RC_BIT(5), RC_BIT(0) | RC_BIT(5), NULL),
        RC_F_INT("fct_IDff", &t->fct_ff, 0, RC_FF_NONNEG),
        RC_F_INT("fct_IDfv", &t->fct_fv, 0, RC_FF_NONNEG),
        RC_F_REAL("Ascalef", &t->ascalef, 1, RC_FF_ZDEF | RC_FF_POS),
        RC_F_REAL("Ascalev", &t->ascalev, 1, RC_FF_ZDEF | RC_FF_POS)};
    rc_field l4[] = {
        RC_F_INT("fct_IDld", &t->fct_ld, 0, RC_FF_POS),
        RC_F_SET("Iform", &t->iform, 0, 0, 0x7u, 0x7u, NULL),
        RC_F_REAL("Ascalex", &t->ascalex, 1, RC_FF_ZDEF | RC_FF_POS),
        RC_F_REAL("FscaleId", &t->fscaleld, 1, RC_FF_ZDEF),
        RC_F_SET("Icor", &t->icor, 0, 0, 0x3u, 0x3u, NULL)};
    rc_field l5[] = {
        RC_F_INT("fct_IDul", &t->fct_ul, 0, RC_FF_NONNEG),
        RC_F_SKIP(10),
        RC_F_REAL("Stiff", &t->stiff, 0, RC_FF_NONNEG),
        RC_F_REAL("Fscaleul", &t->fscaleul, 1, RC_FF_ZDEF)};
    rc_field l6[] = {
        RC_F_REAL("Visc", &t->visc, 0, RC_FF_NONNEG),
        RC_F_INT("fct_IDdv", &t->fct_dv, 0, RC_FF_NONNEG),
        RC_F_INT("fct_IDdf", &t->fct_df, 0, RC_FF_NONNEG),
        RC_F_REAL("Fscalev", &t->fscalev, 1, RC_FF_ZDEF)};
    rc_field *lines[6] = {l1, l2, l3, l4, l5, l6};
    const int nf[6] = {RC_NF(l1), RC_NF(l2), RC_NF(l3), RC_NF(l4), RC_NF(l5), RC_NF(l6)};

    /* the six lines, each with its location */
    for (int k = 0; k < 6; k++) {
        t->line_loc[k] = b->lines[k + 1].loc;
        if ((st = rc_parse_line(rd, b, &b->lines[k + 1], lines[k], nf[k]))) return st;
    }
    if (t->tstop < t->tstart)
        return rc_case_fail(rd, &t->line_loc[1], b->name, "Tstop",
                            "expected Tstop >= Tstart = %.15g, got %s", t->tstart, l2[4].got);
    /* the elasto-plastic laws move between the curves with slope Stiff */
    if (t->iform != 0 && !(t->stiff > 0))
        return rc_case_fail(rd, &t->line_loc[4], b->name, "Stiff",
                            "expected a positive stiffness [N/m]: Stiff is required for Iform = %d, got %s",
                            t->iform, l5[2].got);
    return rc_note_id(rd, RC_IDK_INTER, t->id, &t->loc, b->hdr->text);
}

/* ======================================================================
 * /FUNCT
 * ====================================================================== */

/* /FUNCT/fct_ID: title, then X Y pairs; X strictly increasing. */
static rc_status rc_card_funct(rc_reader *rd, const rc_block *b)
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
        rc_field f[] = {RC_F_REAL("X", &fn->x[i], 0, 0), RC_F_REAL("Y", &fn->y[i], 0, 0)};
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
static rc_status rc_card_inivel(rc_reader *rd, const rc_block *b)
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
    if ((st = rc_card_lines(rd, b, title, 1, 1, "Vx Vy Vz grnod_ID skew_ID", &nd))) return st;

    rc_field f[] = {RC_F_REAL("Vx", &v->v[0], 0, 0), RC_F_REAL("Vy", &v->v[1], 0, 0),
                    RC_F_REAL("Vz", &v->v[2], 0, 0),
                    RC_F_INT("grnod_ID", &v->grnod_id, 0, RC_FF_NONNEG),
                    RC_F_INTN("skew_ID", &v->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;
    return rc_note_id(rd, RC_IDK_INIVEL, v->id, &v->loc, b->hdr->text);
}

/* /GRAV/grav_ID: title; fct_IDT DIR skew_ID sensor_ID grnod_ID Ascale_x
 * Fscale_y. */
static rc_status rc_card_grav(rc_reader *rd, const rc_block *b)
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

    rc_field f[] = {RC_F_INT("fct_IDT", &g->fct_id, 0, RC_FF_NONNEG),
                    RC_F_STR("DIR", dir, 10),
                    RC_F_INTN("skew_ID", &g->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
                    RC_F_INTN("sensor_ID", &g->sensor_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_sensor),
                    RC_F_INT("grnod_ID", &g->grnod_id, 0, RC_FF_NONNEG),
                    RC_F_REAL("Ascale_x", &g->ascale, 1, RC_FF_ZDEF | RC_FF_POS),
                    RC_F_REAL("Fscale_y", &g->fscale, 1, RC_FF_ZDEF)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;

    /* DIR: one letter, either case, anywhere in its columns */
    const char *p = strchr("XYZxyz", dir[0]);
    if (!dir[0] || dir[1] || !p)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "DIR", "expected X, Y or Z, got %s",
                            f[1].got);
    g->dir = (int)(p - "XYZxyz") % 3;
    return rc_note_id(rd, RC_IDK_GRAV, g->id, &g->loc, b->hdr->text);
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
static rc_status rc_card_bcs(rc_reader *rd, const rc_block *b)
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

    rc_field f[] = {RC_F_STR("Trarot", tr, 10),
                    RC_F_INTN("skew_ID", &x->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
                    RC_F_INT("grnod_ID", &x->grnod_id, 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], f, RC_NF(f)))) return st;
    if (!rc_trarot(tr, x->fix))
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "Trarot",
                            "expected up to six 0/1 flags TxTyTz RxRyRz (e.g. \"111 000\"), got %s",
                            f[0].got);
    return rc_note_id(rd, RC_IDK_BCS, x->id, &x->loc, b->hdr->text);
}

/* ======================================================================
 * /PART, /GRPART/PART
 * ====================================================================== */

/* Lines first..last of block b: up to ten ids a line (10 columns each),
 * every field named `name`, >= 0; blank and 0 fields are skipped. The ids
 * are appended to *ids (count *n, capacity *cap). */
static rc_status rc_id_lines(rc_reader *rd, const rc_block *b, int first, int last,
                             const char *name, int **ids, int *n, int *cap)
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
            (*ids)[(*n)++] = v[k];
        }
    }
    return RC_OK;
}

/* /PART/part_ID (ricochet's reading: a rigid body, or a named subset of its
 * surfaces): title; the Radioss line prop_ID mat_ID subset_ID Thick (read,
 * ignored); rbody_ID and up to nine surface ids; then up to ten surface ids
 * a line. */
static rc_status rc_card_part(rc_reader *rd, const rc_block *b)
{
    static const char desc[] = "prop_ID mat_ID subset_ID Thick, rbody_ID surf_ID1 ... surf_ID9"
                               "[, surf_ID1 ... surf_ID10 ...]";
    rc_case *c = rd->c;
    int nd, cap = 0, v[10];
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
        p->surf[p->nsurf++] = v[k];
    }
    if ((st = rc_id_lines(rd, b, 3, nd, "surf_ID", &p->surf, &p->nsurf, &cap))) return st;

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
static rc_status rc_card_grpart(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    int nd, cap = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "grpart_ID", "/GRPART/PART/grpart_ID")))
        return st;
    RC_GROW(rd, c->grpart, rd->capgrpart, c->ngrpart);
    rc_case_grpart *g = &c->grpart[c->ngrpart++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, g->title, "part_ID1 ... part_ID10", &nd))) return st;
    if ((st = rc_id_lines(rd, b, 1, nd, "part_ID", &g->parts, &g->n, &cap))) return st;
    return rc_note_id(rd, RC_IDK_GRPART, g->id, &g->loc, b->hdr->text);
}

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
    rc_field f1[] = {RC_F_REAL("C1", &s->c[0], 0, 0), RC_F_REAL("C2", &s->c[1], 0, 0),
                     RC_F_REAL("C3", &s->c[2], 0, 0), RC_F_REAL("C4", &s->c[3], 0, 0),
                     RC_F_REAL("C5", &s->c[4], 0, 0)};
    rc_field f2[] = {RC_F_REAL("C6", &s->c[5], 0, 0),
                     RC_F_REAL("Fric", &s->fric, 0, RC_FF_NONNEG),
                     RC_F_REAL("VISF", &s->visf, 1, RC_FF_ZDEF | RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, l1, f1, RC_NF(f1)))) return st;
    if ((st = rc_parse_line(rd, b, l2, f2, RC_NF(f2)))) return st;
    return ifric == 3 ? rc_renard(rd, b, l1, f1, s) : RC_OK;
}

/* /FRICTION/fric_ID: title; Ifric Ifiltr Xfreq Iform, then ricochet's
 * Dt_ref Area; the default set (C1..C5; C6 Fric VISF); then part-pair
 * groups of 3 lines, 5 when Idir = 1:
 * grpart_ID1 grpart_ID2 part_ID1 part_ID2 (unused) Idir; direction 1 set;
 * [direction 2 set]. */
static rc_status rc_card_friction(rc_reader *rd, const rc_block *b)
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
                     RC_F_REAL("Xfreq", &fr->xfreq, 1, 0),
                     RC_F_SET("Iform", &fr->iform, 1, RC_FF_ZDEF, 0x7u, 0, NULL),
                     RC_F_REAL("Dt_ref", &fr->dt_ref, 0, RC_FF_NONNEG),
                     RC_F_REAL("Area", &fr->area, 0, RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], la, RC_NF(la)))) return st;
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
        if ((st = rc_parse_line(rd, b, ln, l1, RC_NF(l1)))) return st;

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

/* /FRIC_ORIENT/fric_orient_ID: title; per part or part group two lines:
 * grpart_ID part_ID; VX VY VZ skew_ID PHI Iorth. */
static rc_status rc_card_fricorient(rc_reader *rd, const rc_block *b)
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
            RC_F_REAL("VX", &it->v[0], 0, 0), RC_F_REAL("VY", &it->v[1], 0, 0),
            RC_F_REAL("VZ", &it->v[2], 0, 0),
            RC_F_INTN("skew_ID", &it->skew_id, RC_FF_NONNEG | RC_FF_ONLY0, rc_note_skew),
            RC_F_REAL("PHI", &it->phi, 0, 0),
            RC_F_SET("Iorth", &it->iorth, 0, 0, 0x3u, 0, NULL)};
        if ((st = rc_parse_line(rd, b, &b->lines[i + 1], l2, RC_NF(l2)))) return st;
        if (it->v[0] == 0 && it->v[1] == 0 && it->v[2] == 0)
            return rc_case_fail(rd, &b->lines[i + 1].loc, b->name, "VX VY VZ",
                                "expected a non-zero vector V (direction 1 of orthotropy), got "
                                "(0, 0, 0)");
    }
    return rc_note_id(rd, RC_IDK_FRICORIENT, o->id, &o->loc, b->hdr->text);
}

/* ======================================================================
 * /RUN and /SOLVER (ricochet cards)
 * ====================================================================== */

/* /RUN: Tend Dt_out Ev_state. */
static rc_status rc_card_run(rc_reader *rd, const rc_block *b)
{
    rc_case_run *r = &rd->c->run;
    int nd;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/RUN or /RUN/1"))) return st;
    if ((st = rc_single(rd, b, &rd->run_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 1, "Tend Dt_out Ev_state", &nd))) return st;
    rc_field f[] = {RC_F_REAL("Tend", &r->tend, 0, RC_FF_POS),
                    RC_F_REAL("Dt_out", &r->dtout, 0, RC_FF_NONNEG),
                    RC_F_SET("Ev_state", &r->ev_state, 0, 0, RC_BIT(0) | RC_BIT(1) | RC_BIT(2), 0, NULL)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], f, RC_NF(f)))) return st;
    /* output interval: blank or 0 means Tend/100 */
    if (r->dtout == 0) r->dtout = RC_DEF_DTOUT_FRACTION * r->tend;
    r->present = 1;
    r->loc = b->hdr->loc;
    return RC_OK;
}

/* /SOLVER: Method Max_order Max_steps Rtol Hmax H0; the four absolute
 * tolerances; Atol_energy. */
static rc_status rc_card_solver(rc_reader *rd, const rc_block *b)
{
    rc_case_solver *s = &rd->c->solver;
    int nd, steps = 0;
    rc_status st;
    if ((st = rc_header(rd, b, 1, RC_ID_OPTIONAL, NULL, "/SOLVER or /SOLVER/1"))) return st;
    if ((st = rc_single(rd, b, &rd->solver_hdr))) return st;
    if ((st = rc_card_lines(rd, b, NULL, 1, 3,
                            "Method Max_order Max_steps Rtol Hmax H0[, Atol_pos Atol_quat "
                            "Atol_vel Atol_omega[, Atol_energy]]",
                            &nd)))
        return st;

    const unsigned zp = RC_FF_ZDEF | RC_FF_POS;
    rc_field l1[] = {
        RC_F_SET("Method", &s->method, RC_DEF_METHOD, RC_FF_ZDEF, RC_BIT(1) | RC_BIT(2), RC_BIT(1),
                 "(2 = IDA is planned)"),
        RC_F_SET("Max_order", &s->max_order, RC_DEF_MAX_ORDER, RC_FF_ZDEF, 0x3Eu, 0, NULL),
        RC_F_INT("Max_steps", &steps, RC_DEF_MAX_STEPS, zp),
        RC_F_REAL("Rtol", &s->rtol, RC_DEF_RTOL, zp),
        RC_F_REAL("Hmax", &s->hmax, 0, RC_FF_NONNEG),
        RC_F_REAL("H0", &s->h0, 0, RC_FF_NONNEG)};
    rc_field l2[] = {RC_F_REAL("Atol_pos", &s->atol_pos, RC_DEF_ATOL_POS, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_quat", &s->atol_quat, RC_DEF_ATOL_QUAT, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_vel", &s->atol_vel, RC_DEF_ATOL_VEL, RC_FF_ZDEF | RC_FF_NONNEG),
                     RC_F_REAL("Atol_omega", &s->atol_omega, RC_DEF_ATOL_OMEGA, RC_FF_ZDEF | RC_FF_NONNEG)};
    rc_field l3[] = {RC_F_REAL("Atol_energy", &s->atol_energy, RC_DEF_ATOL_ENERGY, RC_FF_ZDEF | RC_FF_NONNEG)};
    if ((st = rc_parse_line(rd, b, &b->lines[0], l1, RC_NF(l1)))) return st;
    if (nd >= 2 && (st = rc_parse_line(rd, b, &b->lines[1], l2, RC_NF(l2)))) return st;
    if (nd >= 3 && (st = rc_parse_line(rd, b, &b->lines[2], l3, RC_NF(l3)))) return st;
    s->max_steps = steps;
    s->present = 1;
    s->loc = b->hdr->loc;
    return RC_OK;
}

/* ======================================================================
 * Dispatch
 * ====================================================================== */

typedef enum {
    RC_CARD_BEGIN, RC_CARD_NODE, RC_CARD_GRNOD, RC_CARD_RBODY, RC_CARD_PLANE, RC_CARD_ELLIPS,
    RC_CARD_TYPE6, RC_CARD_FUNCT, RC_CARD_INIVEL, RC_CARD_GRAV, RC_CARD_BCS, RC_CARD_RUN,
    RC_CARD_SOLVER, RC_CARD_CPL_SPRING, RC_CARD_CPL_CATENARY, RC_CARD_PART, RC_CARD_GRPART,
    RC_CARD_FRICTION, RC_CARD_FRIC_ORIENT, RC_CARD_POWER, RC_CARD_CYL, RC_CARD_BOX, RC_CARD_IMPVEL
} rc_card_kind;

/* Supported cards; a family (kw with a sub) lists each subtype. */
static const struct {
    const char *kw, *sub;
    rc_card_kind kind;
} rc_card_table[] = {
    {"BEGIN", NULL, RC_CARD_BEGIN},    {"NODE", NULL, RC_CARD_NODE},
    {"GRNOD", "NODE", RC_CARD_GRNOD},  {"RBODY", NULL, RC_CARD_RBODY},
    {"SURF", "PLANE", RC_CARD_PLANE},  {"SURF", "ELLIPS", RC_CARD_ELLIPS},
    {"INTER", "TYPE6", RC_CARD_TYPE6}, {"FUNCT", NULL, RC_CARD_FUNCT},
    {"INIVEL", "TRA", RC_CARD_INIVEL}, {"INIVEL", "ROT", RC_CARD_INIVEL},
    {"GRAV", NULL, RC_CARD_GRAV},      {"BCS", NULL, RC_CARD_BCS},
    {"RUN", NULL, RC_CARD_RUN},        {"SOLVER", NULL, RC_CARD_SOLVER},
    {"COUPLING", "SPRING", RC_CARD_CPL_SPRING}, {"COUPLING", "CATENARY", RC_CARD_CPL_CATENARY},
    {"PART", NULL, RC_CARD_PART},      {"GRPART", "PART", RC_CARD_GRPART},
    {"FRICTION", NULL, RC_CARD_FRICTION}, {"FRIC_ORIENT", NULL, RC_CARD_FRIC_ORIENT},
    {"INTER", "POWER", RC_CARD_POWER}, {"SURF", "CYL", RC_CARD_CYL},
    {"SURF", "BOX", RC_CARD_BOX},      {"IMPVEL", NULL, RC_CARD_IMPVEL},
};

/* Radioss cards without meaning for rigid bodies: skipped with a warning. */
static const char *const rc_ignored[] = {"TITLE", "ANALY",  "DEF_SOLID", "DEF_SHELL", "IOFLAG",
                                         "SPMD",  "RANDOM", "PROP",      "MAT"};
/* Radioss cards ricochet plans to support: an error until then. */
static const char *const rc_planned[] = {"UNIT", "SKEW", "SENSOR"};

static int rc_in_list(const char *kw, const char *const *list, int n)
{
    for (int i = 0; i < n; i++)
        if (strcmp(kw, list[i]) == 0) return 1;
    return 0;
}

/* Call the card function of a kind. */
static rc_status rc_card_call(rc_reader *rd, const rc_block *b, rc_card_kind kind)
{
    switch (kind) {
    case RC_CARD_BEGIN: return rc_card_begin(rd, b);
    case RC_CARD_NODE: return rc_card_node(rd, b);
    case RC_CARD_GRNOD: return rc_card_grnod(rd, b);
    case RC_CARD_RBODY: return rc_card_rbody(rd, b);
    case RC_CARD_PLANE: return rc_card_plane(rd, b);
    case RC_CARD_ELLIPS: return rc_card_ellips(rd, b);
    case RC_CARD_TYPE6: return rc_card_type6(rd, b);
    case RC_CARD_FUNCT: return rc_card_funct(rd, b);
    case RC_CARD_INIVEL: return rc_card_inivel(rd, b);
    case RC_CARD_GRAV: return rc_card_grav(rd, b);
    case RC_CARD_BCS: return rc_card_bcs(rd, b);
    case RC_CARD_RUN: return rc_card_run(rd, b);
    case RC_CARD_SOLVER: return rc_card_solver(rd, b);
    case RC_CARD_CPL_SPRING: return rc_card_coupling_spring(rd, b);
    case RC_CARD_CPL_CATENARY: return rc_card_coupling_catenary(rd, b);
    case RC_CARD_PART: return rc_card_part(rd, b);
    case RC_CARD_GRPART: return rc_card_grpart(rd, b);
    case RC_CARD_FRICTION: return rc_card_friction(rd, b);
    case RC_CARD_FRIC_ORIENT: return rc_card_fricorient(rd, b);
    case RC_CARD_POWER: return rc_card_power(rd, b);
    case RC_CARD_CYL: return rc_card_cyl(rd, b);
    case RC_CARD_BOX: return rc_card_box(rd, b);
    case RC_CARD_IMPVEL: return rc_card_impvel(rd, b);
    }
    return RC_SET(rd->err, RC_EINTERNAL, "unknown card kind %d", (int)kind);
}

/* A family whose subtype is missing or not supported. */
static rc_status rc_bad_subtype(rc_reader *rd, const rc_block *b)
{
    char list[256] = "";
    size_t k = 0;
    for (size_t i = 0; i < sizeof rc_card_table / sizeof rc_card_table[0]; i++)
        if (rc_card_table[i].sub && strcmp(rc_card_table[i].kw, b->kw[0]) == 0 && k < sizeof list)
            k += (size_t)snprintf(list + k, sizeof list - k, "%s/%s/%s", k ? ", " : "",
                                  rc_card_table[i].kw, rc_card_table[i].sub);
    if (b->nkw < 2)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "missing subtype (expected %s)",
                            list);
    return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                        "/%s/%s: not supported yet (supported: %s)", b->kw[0], b->kw[1], list);
}

rc_status rc_card_dispatch(rc_reader *rd, const rc_block *b)
{
    const char *kw = b->kw[0];
    int family = 0;
    /* ignored Radioss cards: a warning, whatever their header */
    if (rc_in_list(kw, rc_ignored, RC_NF(rc_ignored)))
        return rc_case_warn(rd, &b->hdr->loc, "card %s ignored: no meaning for rigid bodies",
                            b->name);
    if (b->bad)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "malformed card header: %s", b->bad);
    /* supported cards */
    for (size_t i = 0; i < sizeof rc_card_table / sizeof rc_card_table[0]; i++) {
        if (strcmp(rc_card_table[i].kw, kw) != 0) continue;
        if (!rc_card_table[i].sub) return rc_card_call(rd, b, rc_card_table[i].kind);
        family = 1;
        if (b->nkw >= 2 && strcmp(rc_card_table[i].sub, b->kw[1]) == 0)
            return rc_card_call(rd, b, rc_card_table[i].kind);
    }
    if (family) return rc_bad_subtype(rd, b);
    /* planned, then unknown */
    if (rc_in_list(kw, rc_planned, RC_NF(rc_planned)))
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "not supported yet");
    return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                        "unknown card (docs/case-format.md lists the cards read and those "
                        "ignored)");
}

/* ======================================================================
 * Deck level
 * ====================================================================== */

void rc_cards_defaults(rc_case *c)
{
    rc_case_solver *s = &c->solver;
    s->present = 0;
    s->method = RC_DEF_METHOD;
    s->max_order = RC_DEF_MAX_ORDER;
    s->max_steps = RC_DEF_MAX_STEPS;
    s->rtol = RC_DEF_RTOL;
    s->atol_pos = RC_DEF_ATOL_POS;
    s->atol_quat = RC_DEF_ATOL_QUAT;
    s->atol_vel = RC_DEF_ATOL_VEL;
    s->atol_omega = RC_DEF_ATOL_OMEGA;
    s->atol_energy = RC_DEF_ATOL_ENERGY;
    s->hmax = 0;
    s->h0 = 0;
}

rc_status rc_cards_finish(rc_reader *rd)
{
    rc_case *c = rd->c;
    /* the end time is required */
    if (!c->run.present) {
        rc_loc loc = {c->files[0], rd->main_last_line > 0 ? rd->main_last_line : 1};
        return rc_case_fail(rd, &loc, NULL, NULL, "no /RUN card: the end time is required");
    }
    /* without /SOLVER, the defaults apply at the main file */
    if (!c->solver.present) c->solver.loc = (rc_loc){c->files[0], 0};
    return RC_OK;
}
