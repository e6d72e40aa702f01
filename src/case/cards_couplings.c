/*
 * Coupling cards (ricochet cards for docs/theory.md 8, in the Radioss block style):
 *   /COUPLING/SPRING/cpl_ID     spring-damper
 *   /COUPLING/CATENARY/cpl_ID   elastic catenary
 * Layouts as field tables (case_internal.h), documented in
 * docs/case-format.md. References (bodies, functions) are resolved by the
 * compiler (model/coupling.c).
 */
#include "case/case_coupling.h"
#include "case/case_internal.h"
#include "base/error.h"

#include <string.h>

/* New coupling of the given kind, its header checked and its title read;
 * lines 2 and 3 (the attachment points) parsed. `nmin`, `nmax`: data lines. */
static rc_status rc_new_coupling(rc_reader *rd, const rc_block *b, rc_case_cpl_kind kind,
                                 const char *usage, int nmin, int nmax, const char *desc,
                                 rc_case_coupling **out, int *nd)
{
    rc_case *c = rd->c;
    rc_status st;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "cpl_ID", usage))) return st;
    RC_GROW(rd, c->coupling, rd->capcoupling, c->ncoupling);
    rc_case_coupling *k = &c->coupling[c->ncoupling++];
    k->id = b->id;
    k->kind = kind;
    k->loc = b->hdr->loc;
    for (int i = 0; i < 6; i++) k->line_loc[i] = k->loc;
    *out = k;
    if ((st = rc_card_lines(rd, b, k->title, nmin, nmax, desc, nd))) return st;
    for (int i = 0; i < *nd; i++) k->line_loc[i] = b->lines[i + 1].loc;

    /* lines 2 and 3: the two attachment points, global at t = 0 */
    for (int e = 0; e < 2; e++) {
        static const char *const nm[2][3] = {{"X1", "Y1", "Z1"}, {"X2", "Y2", "Z2"}};
        rc_field f[] = {RC_F_REALD(nm[e][0], &k->p[e][0], 0, 0, RC_D_L), RC_F_REALD(nm[e][1], &k->p[e][1], 0, 0, RC_D_L),
                        RC_F_REALD(nm[e][2], &k->p[e][2], 0, 0, RC_D_L)};
        if ((st = rc_parse_line(rd, b, &b->lines[2 + e], f, RC_NF(f)))) return st;
    }
    /* a spring or a line between two coincident points has no direction */
    if (k->p[0][0] == k->p[1][0] && k->p[0][1] == k->p[1][1] && k->p[0][2] == k->p[1][2])
        return rc_case_fail(rd, &k->line_loc[2], b->name, "X2 Y2 Z2",
                            "expected a point 2 different from point 1 (the coupling acts along the "
                            "line between them), got both = (%.9g, %.9g, %.9g)",
                            k->p[0][0], k->p[0][1], k->p[0][2]);
    return RC_OK;
}

/* Line 1 starts with the two bodies. */
#define RC_F_BODIES(k)                                          \
    RC_F_INT("rbody_ID1", &(k)->rbody[0], 0, RC_FF_NONNEG),     \
        RC_F_INT("rbody_ID2", &(k)->rbody[1], 0, RC_FF_NONNEG)

/* The two ends must not both be fixed in space, nor on one body. */
static rc_status rc_check_ends(rc_reader *rd, const rc_block *b, const rc_case_coupling *k)
{
    if (k->rbody[0] == 0 && k->rbody[1] == 0)
        return rc_case_fail(rd, &k->line_loc[0], b->name, "rbody_ID1 rbody_ID2",
                            "expected at least one rigid body (0 = point fixed in space), got both 0");
    if (k->rbody[0] == k->rbody[1])
        return rc_case_fail(rd, &k->line_loc[0], b->name, "rbody_ID2",
                            "expected a body other than rbody_ID1 = %d (a coupling between two points "
                            "of one rigid body exerts no net force), got %d",
                            k->rbody[0], k->rbody[1]);
    return RC_OK;
}

/* /COUPLING/SPRING/cpl_ID: title;
 *   rbody_ID1 rbody_ID2 Iform fct_ID; X1 Y1 Z1; X2 Y2 Z2; X0 Kd;
 *   [A B C; [F_r X_r]] */
rc_status rc_card_coupling_spring(rc_reader *rd, const rc_block *b)
{
    rc_case_coupling *k;
    int nd;
    rc_status st;
    if ((st = rc_new_coupling(rd, b, RC_CASE_CPL_SPRING, "/COUPLING/SPRING/cpl_ID", 4, 6,
                              "rbody_ID1 rbody_ID2 Iform fct_ID, X1 Y1 Z1, X2 Y2 Z2, X0 Kd[, A B "
                              "C[, F_r X_r]]",
                              &k, &nd)))
        return st;

    rc_field l1[] = {RC_F_BODIES(k),
                     RC_F_SET("Iform", &k->iform, 1, RC_FF_ZDEF, 0x1Eu, 0, NULL),
                     RC_F_INT("fct_ID", &k->fct_id, 0, RC_FF_NONNEG)};
    rc_field l4[] = {RC_F_REALD("X0", &k->x0, 0, RC_FF_NONNEG, RC_D_L),
                     RC_F_REALD("Kd", &k->kd, 0, RC_FF_NONNEG, RC_D_C)};
    rc_field l5[] = {RC_F_REALD("A", &k->a, 0, 0, RC_D_K), RC_F_REALD("B", &k->b, 0, 0, RC_D_K2),
                     RC_F_REALD("C", &k->c, 0, 0, RC_D_K3)};
    rc_field l6[] = {RC_F_REALD("F_r", &k->fr, 0, 0, RC_D_F), RC_F_REALD("X_r", &k->xr, 0, RC_FF_NONNEG, RC_D_L)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_check_ends(rd, b, k))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
    k->x0_given = !l4[0].blank;
    if (nd >= 5 && (st = rc_parse_line(rd, b, &b->lines[5], l5, RC_NF(l5)))) return st;
    if (nd >= 6 && (st = rc_parse_line(rd, b, &b->lines[6], l6, RC_NF(l6)))) return st;
    k->ref_given = nd >= 6 && !l6[1].blank;

    /* what each form needs */
    switch (k->iform) {
    case 1:
        if (k->a < 0)
            return rc_case_fail(rd, &k->line_loc[4], b->name, "A",
                                "expected a non-negative stiffness k [N/m] for Iform = 1, got %s",
                                l5[0].got);
        break;
    case 3:
    case 4:
        if (k->fct_id == 0)
            return rc_case_fail(rd, &k->line_loc[0], b->name, "fct_ID",
                                "expected the id of a /FUNCT (the %s) for Iform = %d, got %s",
                                k->iform == 3 ? "elastic force f_e(x) [N]" : "stiffness k(x) [N/m]",
                                k->iform, l1[3].got);
        /* a table of physical values (N or N/m against m) without scale
         * factors cannot be converted from other units */
        if (rc_units_convert(rd))
            return rc_case_fail(rd, &k->line_loc[0], b->name, "fct_ID",
                                "the deck's units are not SI: a /FUNCT of forces or stiffnesses "
                                "(Iform = %d) has no scale factor to convert it; write this card "
                                "and its function in kg, m, s, got %s",
                                k->iform, l1[3].got);
        break;
    default: break;
    }
    if (k->iform != 4 && k->ref_given)
        return rc_case_fail(rd, &k->line_loc[5], b->name, "X_r",
                            "a reference point (F_r, X_r) belongs to Iform = 4, got Iform = %d; "
                            "expected a blank field",
                            k->iform);
    if (nd >= 6 && !l6[0].blank && !k->ref_given)
        return rc_case_fail(rd, &k->line_loc[5], b->name, "X_r",
                            "expected the reference distance X_r [m] where the force is F_r = %s, "
                            "got blank",
                            l6[0].got);
    return rc_note_id(rd, RC_IDK_COUPLING, k->id, &k->loc, b->hdr->text);
}

/* /COUPLING/CATENARY/cpl_ID: title;
 *   rbody_ID1 rbody_ID2; X1 Y1 Z1; X2 Y2 Z2; Lambda0 L_eq D */
rc_status rc_card_coupling_catenary(rc_reader *rd, const rc_block *b)
{
    rc_case_coupling *k;
    int nd;
    rc_status st;
    if ((st = rc_new_coupling(rd, b, RC_CASE_CPL_CATENARY, "/COUPLING/CATENARY/cpl_ID", 4, 4,
                              "rbody_ID1 rbody_ID2, X1 Y1 Z1, X2 Y2 Z2, Lambda0 L_eq D", &k, &nd)))
        return st;
    rc_field l1[] = {RC_F_BODIES(k)};
    rc_field l4[] = {RC_F_REALD("Lambda0", &k->lambda0, 0, RC_FF_POS, RC_D_LIN),
                     RC_F_REALD("L_eq", &k->leq, 0, RC_FF_POS, RC_D_L), RC_F_REALD("D", &k->d, 0, RC_FF_POS, RC_D_K)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_check_ends(rd, b, k))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
    return rc_note_id(rd, RC_IDK_COUPLING, k->id, &k->loc, b->hdr->text);
}

/* /COUPLING/CONTACT/cpl_ID (STAR-CCM+ contact coupling): title;
 *   surf_ID1 surf_ID2 Iside Iest; d0 k1 k2 mu k_t; [V_imp d_min zeta A] */
rc_status rc_card_coupling_contact(rc_reader *rd, const rc_block *b)
{
    rc_case *c = rd->c;
    rc_status st;
    int nd;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "cpl_ID", "/COUPLING/CONTACT/cpl_ID"))) return st;
    RC_GROW(rd, c->coupling, rd->capcoupling, c->ncoupling);
    rc_case_coupling *k = &c->coupling[c->ncoupling++];
    memset(k, 0, sizeof *k);
    k->id = b->id;
    k->kind = RC_CASE_CPL_CONTACT;
    k->loc = b->hdr->loc;
    for (int i = 0; i < 6; i++) k->line_loc[i] = k->loc;
    if ((st = rc_card_lines(rd, b, k->title, 2, 3, "surf_ID1 surf_ID2 Iside Iest, d0 k1 k2 mu k_t[, V_imp d_min zeta A]",
                            &nd)))
        return st;
    for (int i = 0; i < nd; i++) k->line_loc[i] = b->lines[i + 1].loc;
    rc_field l1[] = {RC_F_INT("surf_ID1", &k->surf[0], 0, RC_FF_POS), RC_F_INT("surf_ID2", &k->surf[1], 0, RC_FF_POS),
                     RC_F_SET("Iside", &k->iside, 0, 0, 0x7u, 0x7u, NULL),
                     RC_F_SET("Iest", &k->iest, 0, 0, 0x3u, 0x3u, NULL)};
    rc_field l2[] = {RC_F_REALD("d0", &k->d0, 0, RC_FF_POS, RC_D_L), RC_F_REALD("k1", &k->k1, 0, RC_FF_NONNEG, RC_D_K3),
                     RC_F_REALD("k2", &k->k2, 0, RC_FF_NONNEG, RC_DIM(1, -2, -1)),
                     RC_F_REALD("mu", &k->mu, 0, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("k_t", &k->kt, 0, RC_FF_NONNEG, RC_DIM(0, -1, 1))};
    rc_field l3[] = {RC_F_REALD("V_imp", &k->vimp, 0, RC_FF_NONNEG, RC_D_V),
                     RC_F_REALD("d_min", &k->dmin, 0, RC_FF_NONNEG, RC_D_L),
                     RC_F_REALD("zeta", &k->zeta, 0, RC_FF_NONNEG, RC_D_NONE),
                     RC_F_REALD("A", &k->area, 0, RC_FF_NONNEG, RC_D_AREA)};
    static const rc_line blank = {"", 0, {NULL, 0}};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    if ((st = rc_parse_line(rd, b, nd >= 3 ? &b->lines[3] : &blank, l3, RC_NF(l3)))) return st;
    if (k->surf[0] == k->surf[1])
        return rc_case_fail(rd, &k->line_loc[0], b->name, "surf_ID2",
                            "expected a surface other than surf_ID1 = %d (the opposing boundary), got %d", k->surf[0],
                            k->surf[1]);
    if (k->mu > 0 && !(k->kt > 0))
        return rc_case_fail(rd, &k->line_loc[1], b->name, "k_t",
                            "friction (mu > 0) needs the tanh coefficient k_t > 0 [s/m], got %s", l2[4].got);
    if (k->iest == 0) {
        if (!(k->k1 > 0))
            return rc_case_fail(rd, &k->line_loc[1], b->name, "k1",
                                "expected the elastic coefficient k1 > 0 [N/m^3] (or Iest = 1 to estimate it), got %s",
                                l2[1].got);
        if (nd >= 3 && (!l3[0].blank || !l3[1].blank || !l3[2].blank || !l3[3].blank))
            return rc_case_fail(rd, &k->line_loc[2], b->name, "V_imp",
                                "the estimator line belongs to Iest = 1; with Iest = 0 expected it blank or absent");
    } else {
        if (!l2[1].blank || !l2[2].blank)
            return rc_case_fail(rd, &k->line_loc[1], b->name, l2[1].blank ? "k2" : "k1",
                                "with Iest = 1 k1 and k2 are estimated (line 3); expected the field blank, got %s",
                                l2[1].blank ? l2[2].got : l2[1].got);
        if (nd < 3)
            return rc_case_fail(rd, &k->loc, b->name, "V_imp",
                                "Iest = 1 needs line 3 (V_imp d_min zeta A), found %d data lines", nd);
        if (!(k->vimp > 0))
            return rc_case_fail(rd, &k->line_loc[2], b->name, "V_imp",
                                "expected the normal impact speed V_imp > 0 [m/s], got %s", l3[0].got);
        if (!(k->dmin < k->d0))
            return rc_case_fail(rd, &k->line_loc[2], b->name, "d_min",
                                "expected the minimum distance d_min below the effective range d0 = %.9g [m], got %s",
                                k->d0, l3[1].got);
        if (!(k->area > 0))
            return rc_case_fail(rd, &k->line_loc[2], b->name, "A",
                                "expected the estimated contact area A > 0 [m^2], got %s", l3[3].got);
    }
    return rc_note_id(rd, RC_IDK_COUPLING, k->id, &k->loc, b->hdr->text);
}
