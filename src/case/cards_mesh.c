/*
 * Mesh cards: the elements whose mass makes a rigid body's (/SHELL, /SH3N,
 * /BRICK, /TETRA4, /PENTA6, /TETRA10), the spring elements between nodes (/SPRING, couplings
 * of the bodies in the model stage), their properties (/PROP/SHELL,
 * /PROP/SOLID, /PROP/SPRING) and
 * materials (/MAT/<law>: the density), skew frames (/SKEW/FIX, /SKEW/MOV,
 * /SKEW/MOV2: their axes from the nodes after the last card) and the node
 * groups built from parts or groups (/GRNOD/PART, /GRNOD/GRNOD, expanded into
 * node lists once every card is read). Layouts: docs/case-format.md; the
 * mass properties are computed by the model stage (model/massprop.c).
 */
#include "case/case_internal.h"
#include "case/case_mesh.h"
#include "base/error.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The mesh part of the case, created on first use. */
static rc_case_mesh *rc_mesh(rc_reader *rd)
{
    if (!rd->c->mesh) rd->c->mesh = calloc(1, sizeof *rd->c->mesh);
    if (!rd->c->mesh) rc_case_nomem(rd);
    return rd->c->mesh;
}

/* ======================================================================
 * Elements
 * ====================================================================== */

/* /SHELL/part_ID, /SH3N/part_ID, /BRICK/part_ID, /TETRA4/part_ID: no title,
 * one element a line: id, nodes; shells then phi and Thick. */
static rc_status rc_card_elements(rc_reader *rd, const rc_block *b, rc_elem_kind kind)
{
    static const char *const usage[] = {"", "/SHELL/part_ID", "/SH3N/part_ID", "/BRICK/part_ID",
                                        "/TETRA4/part_ID", "/PENTA6/part_ID", "/TETRA10/part_ID"};
    static const char *const idname[] = {"", "shell_ID", "sh3n_ID", "brick_ID", "tetra_ID", "penta_ID", "tetra_ID"};
    static const int nnode[] = {0, 4, 3, 8, 4, 6, 10};
    static const char *const nname[] = {"node_ID1", "node_ID2", "node_ID3", "node_ID4", "node_ID5",
                                        "node_ID6", "node_ID7", "node_ID8", "node_ID9", "node_ID10"};
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "part_ID", usage[kind]))) return st;
    const int n = rc_block_trim(b), nn = nnode[kind];
    const int shell = kind == RC_ELEM_SHELL || kind == RC_ELEM_SH3N;
    /* /TETRA10: two lines an element, the id then the ten nodes */
    const int t10 = kind == RC_ELEM_TETRA10;
    if (t10 && n % 2)
        return rc_case_fail(rd, &b->lines[n - 1].loc, b->name, "node_ID1",
                            "expected the line of the ten nodes of element %s after its id line, found the end of "
                            "the card (a /TETRA10 element is two lines: tetra_ID; node_ID1 ... node_ID10)",
                            b->lines[n - 1].text + strspn(b->lines[n - 1].text, " \t,"));
    for (int i = 0; i < n; i += 1 + t10) {
        RC_GROW(rd, ms->elem, ms->capelem, ms->nelem);
        rc_case_elem *e = &ms->elem[ms->nelem++];
        rc_field f[14];
        int k = 0;
        rc_field fid = RC_F_INT(idname[kind], &e->id, 0, RC_FF_POS);
        f[k++] = fid;
        if (t10) {
            if ((st = rc_parse_line(rd, b, &b->lines[i], f, 1))) return st;
            k = 0;
        }
        for (int j = 0; j < nn; j++) {
            /* SHELL node 4 may be blank (a triangle), so may a TETRA10 mid-edge node */
            rc_field fj = RC_F_INT(nname[j], &e->nodes[j], 0,
                                   (kind == RC_ELEM_SHELL && j == 3) || (t10 && j >= 4) ? RC_FF_NONNEG : RC_FF_POS);
            f[k++] = fj;
        }
        if (shell) {
            rc_field pad = RC_F_SKIP(10), phi = RC_F_REAL("phi", NULL, 0, 0),
                     th = RC_F_REAL("Thick", &e->thick, 0, RC_FF_NONNEG);
            if (kind == RC_ELEM_SH3N) f[k++] = pad;
            f[k++] = pad;
            f[k++] = phi;
            f[k++] = th;
        }
        if ((st = rc_parse_line(rd, b, &b->lines[i + t10], f, k))) return st;
        e->kind = kind;
        e->nn = nn;
        e->part_id = b->id;
        e->loc = b->lines[i + t10].loc;
        if (kind == RC_ELEM_SHELL && (e->nodes[3] == 0 || e->nodes[3] == e->nodes[2])) {
            e->nodes[3] = 0;
            e->nn = 3; /* a degenerate quadrilateral is a triangle */
        }
        if ((st = rc_note_id(rd, shell ? RC_IDK_SHELL : RC_IDK_SOLID, e->id, &e->loc,
                             b->hdr->text)))
            return st;
    }
    return RC_OK;
}

/* /SPRING/part_ID: no title, one spring a line: sprg_ID node_ID1 node_ID2,
 * then node_ID3..node_ID6, which only the Radioss spring types that
 * ricochet does not read use (blank or 0 here), and Skew_ID (the frame of a
 * /PROP/TYPE8 spring; the compiler refuses it on the other types). */
static rc_status rc_card_springs(rc_reader *rd, const rc_block *b)
{
    static const char *const more =
        "(nodes 3 to 6 belong to the pulley and multi-node spring types; ricochet reads /PROP/TYPE4 "
        "springs between two nodes)";
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 1, RC_ID_REQUIRED, "part_ID", "/SPRING/part_ID"))) return st;
    const int n = rc_block_trim(b);
    for (int i = 0; i < n; i++) {
        RC_GROW(rd, ms->spring, ms->capspring, ms->nspring);
        rc_case_spring *e = &ms->spring[ms->nspring++];
        rc_field f[] = {RC_F_INT("sprg_ID", &e->id, 0, RC_FF_POS),
                        RC_F_INT("node_ID1", &e->nodes[0], 0, RC_FF_POS),
                        RC_F_INT("node_ID2", &e->nodes[1], 0, RC_FF_POS),
                        RC_F_INTN("node_ID3", NULL, RC_FF_ONLY0, more),
                        RC_F_INTN("node_ID4", NULL, RC_FF_ONLY0, more),
                        RC_F_INTN("node_ID5", NULL, RC_FF_ONLY0, more),
                        RC_F_INTN("node_ID6", NULL, RC_FF_ONLY0, more),
                        RC_F_INT("Skew_ID", &e->skew_id, 0, RC_FF_NONNEG)};
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, RC_NF(f)))) return st;
        e->part_id = b->id;
        e->loc = b->lines[i].loc;
        if (e->nodes[0] == e->nodes[1])
            return rc_case_fail(rd, &e->loc, b->name, "node_ID2",
                                "expected a node other than node_ID1 = %d (a spring acts along the line "
                                "between its two nodes), got %d",
                                e->nodes[0], e->nodes[1]);
        if ((st = rc_note_id(rd, RC_IDK_SPRING, e->id, &e->loc, b->hdr->text))) return st;
    }
    return RC_OK;
}

/* ======================================================================
 * /PROP/SHELL, /PROP/SOLID
 * ====================================================================== */

/* /PROP/SHELL/prop_ID (TYPE1): title, three lines; Thick on line 3 (21-40).
 * /PROP/SOLID/prop_ID (TYPE14): title and lines, not read (no thickness). */
static rc_status rc_card_prop(rc_reader *rd, const rc_block *b, rc_prop_kind kind)
{
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "prop_ID",
                        kind == RC_PROP_SHELL ? "/PROP/SHELL/prop_ID" : "/PROP/SOLID/prop_ID")))
        return st;
    RC_GROW(rd, ms->prop, ms->capprop, ms->nprop);
    rc_case_prop *p = &ms->prop[ms->nprop++];
    p->id = b->id;
    p->kind = kind;
    p->loc = b->hdr->loc;
    if ((st = rc_var_lines(rd, b, p->title, "the property's lines", &nd))) return st;
    if (kind == RC_PROP_SHELL) {
        if (nd < 3)
            return rc_case_fail(rd, &b->hdr->loc, b->name, "Thick",
                                "expected 3 data lines at least (Ishell..., Hm..., N Istrain "
                                "Thick ...), found %d",
                                nd);
        /* line 3: N, Istrain (blank in the 2024+ formats), Thick, Ashear,
         * blank, Ithick, Iplas, Ipos */
        rc_field l3[] = {RC_F_INT("N", NULL, 0, 0),           RC_F_INT("Istrain", NULL, 0, 0),
                         RC_F_REAL("Thick", &p->thick, 0, RC_FF_NONNEG),
                         RC_F_REAL("Ashear", NULL, 0, 0),     RC_F_SKIP(10),
                         RC_F_INT("Ithick", NULL, 0, 0),      RC_F_INT("Iplas", NULL, 0, 0),
                         RC_F_INT("Ipos", NULL, 0, 0)};
        if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
        p->thick_loc = b->lines[3].loc;
    }
    return rc_note_id(rd, RC_IDK_PROP, p->id, &p->loc, b->hdr->text);
}

/* /PROP/SPR_GENE/prop_ID (/PROP/TYPE8): title; Mass (1-20), I (21-40),
 * Skew_ID (41-50), sens_ID (51-60), Isflag, Ifail, Ifail2, Iequil (10
 * each); then per direction X, Y, Z, RX, RY, RZ three lines: Ki Ci Ai Bi Di
 * (20 each); fct_ID1i Hi fct_ID2i fct_ID3i fct_ID4i (10 each), blank,
 * dmin_i dmax_i (20 each); Fi Ei Ascalei Hscalei (20 each).
 * /PROP/SPR_BEAM/prop_ID (/PROP/TYPE13): the same but line 1 Mass, I,
 * Skew_ID, sens_ID, Isflag, Ifail, Ileng, Ifail2; after the 18 direction
 * lines, V0 W0 (20 each) Fcut (20) Fsmooth (10), then the six failure
 * lines c_i n_i alpha_i beta_i (20 each), optional.
 * The linear stiffnesses and dampings are read, the elastic curves
 * fct_ID1i with their scales Ai, Ascalei (B_i 0), and the rupture
 * deformations dmin_i, dmax_i (Ifail 0, Ifail2 0); the rate and unloading
 * curves, hardening, the sensor and per-length input are not supported
 * yet; the
 * rate-filter and failure-criterion fields, which act only with them, are
 * read and not used. */
static rc_status rc_card_prop_gene(rc_reader *rd, const rc_block *b, rc_case_prop *p)
{
    static const char *const fct = "(a rate-dependent or unloading curve of a general spring: ricochet reads "
                                   "the elastic law F_i = -K_i u_i, or -A_i f_i(u_i/Ascale_i) with fct_ID1i, and "
                                   "the damping -C_i du_i/dt per direction)";
    static const char *const nm[6][14] = {
#define RC_GENE_NAMES(i)                                                                                   \
    {"K" #i, "C" #i, "A" #i, "B" #i, "D" #i, "fct_ID1" #i, "H" #i, "fct_ID2" #i, "fct_ID3" #i, "fct_ID4" #i, \
     "dmin" #i, "dmax" #i, "F" #i, "E" #i}
        RC_GENE_NAMES(1), RC_GENE_NAMES(2), RC_GENE_NAMES(3), RC_GENE_NAMES(4), RC_GENE_NAMES(5), RC_GENE_NAMES(6)
#undef RC_GENE_NAMES
    };
    static const char *const asc[6] = {"Ascale1", "Ascale2", "Ascale3", "Ascale4", "Ascale5", "Ascale6"};
    static const char *const hsc[6] = {"Hscale1", "Hscale2", "Hscale3", "Hscale4", "Hscale5", "Hscale6"};
    rc_status st;
    int nd;
    const int beam = p->sprtype == 13;
    int ifail = 0, ifail2 = 0, rupture = 0;
    if ((st = rc_card_lines(rd, b, p->title, 19, beam ? 26 : 19,
                            beam ? "Mass I Skew_ID sens_ID Isflag Ifail Ileng Ifail2, then for each of X, Y, Z, RX, RY, "
                                   "RZ the three lines Ki Ci Ai Bi Di; fct_ID1i Hi fct_ID2i fct_ID3i fct_ID4i dmini "
                                   "dmaxi; Fi Ei Ascalei Hscalei; then V0 W0 Fcut Fsmooth and six lines ci ni alphai "
                                   "betai (optional)"
                                 : "Mass I Skew_ID sens_ID Isflag Ifail Ifail2 Iequil, then for each of X, Y, Z, RX, RY, "
                                   "RZ the three lines Ki Ci Ai Bi Di; fct_ID1i Hi fct_ID2i fct_ID3i fct_ID4i dmini "
                                   "dmaxi; Fi Ei Ascalei Hscalei",
                            &nd)))
        return st;
    rc_field l13[] = {RC_F_REALD("Mass", &p->mass, 0, RC_FF_NONNEG, RC_D_M),
                      RC_F_REALD("I", &p->inertia, 0, RC_FF_NONNEG, RC_D_J),
                      RC_F_INT("Skew_ID", &p->skew_id, 0, RC_FF_NONNEG),
                      RC_F_INTN("sens_ID", NULL, RC_FF_ONLY0, "(a spring switched on or off by a sensor)"),
                      RC_F_INT("Isflag", NULL, 0, 0),
                      RC_F_INT("Ifail", &ifail, 0, 0),
                      RC_F_SET("Ileng", NULL, 0, 0, 0x3u, 0x1u, "(input per unit length)"),
                      RC_F_INT("Ifail2", &ifail2, 0, 0)};
    rc_field l1[] = {RC_F_REALD("Mass", &p->mass, 0, RC_FF_NONNEG, RC_D_M),
                     RC_F_REALD("I", &p->inertia, 0, RC_FF_NONNEG, RC_D_J),
                     RC_F_INT("Skew_ID", &p->skew_id, 0, RC_FF_NONNEG),
                     RC_F_INTN("sens_ID", NULL, RC_FF_ONLY0, "(a spring switched on or off by a sensor)"),
                     RC_F_INT("Isflag", NULL, 0, 0),
                     RC_F_INT("Ifail", &ifail, 0, 0),
                     RC_F_INT("Ifail2", &ifail2, 0, 0),
                     RC_F_SET("Iequil", NULL, 0, 0, 0x3u, 0x1u,
                              "(the moment equilibrium of a spring of non-zero length)")};
    if ((st = beam ? rc_parse_line(rd, b, &b->lines[1], l13, RC_NF(l13))
                   : rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1))))
        return st;
    p->thick_loc = b->lines[1].loc;
    for (int i = 0; i < 6; i++) {
        const int rot = i >= 3;
        const int dk = rot ? RC_DIM(1, 2, -2) : RC_D_K, dc = rot ? RC_DIM(1, 2, -1) : RC_D_C;
        double dmin = 0, dmax = 0, bcoef = 0;
        const rc_line *la = &b->lines[2 + 3 * i], *lb = &b->lines[3 + 3 * i], *lc = &b->lines[4 + 3 * i];
        rc_field fa[] = {RC_F_REALD(nm[i][0], &p->k6[i], 0, RC_FF_NONNEG, dk),
                         RC_F_REALD(nm[i][1], &p->c6[i], 0, RC_FF_NONNEG, dc),
                         RC_F_REALD(nm[i][2], &p->a6[i], 1, RC_FF_ZDEF, rot ? RC_D_E : RC_D_F),
                         RC_F_REALD(nm[i][3], &bcoef, 0, 0, RC_D_NONE),
                         RC_F_REALD(nm[i][4], NULL, 0, 0, RC_D_NONE)};
        rc_field fb[] = {RC_F_INT(nm[i][5], &p->fct6[i], 0, RC_FF_NONNEG),
                         RC_F_SET(nm[i][6], NULL, 0, 0, 0x1FFu, 0x1u, "(hardening and unloading of a nonlinear spring)"),
                         RC_F_INTN(nm[i][7], NULL, RC_FF_ONLY0, fct),
                         RC_F_INTN(nm[i][8], NULL, RC_FF_ONLY0, fct),
                         RC_F_INTN(nm[i][9], NULL, RC_FF_ONLY0, fct),
                         RC_F_SKIP(10),
                         RC_F_REALD(nm[i][10], &dmin, 0, 0, rot ? RC_D_NONE : RC_D_L),
                         RC_F_REALD(nm[i][11], &dmax, 0, 0, rot ? RC_D_NONE : RC_D_L)};
        rc_field fc[] = {RC_F_REALD(nm[i][12], NULL, 0, 0, RC_D_NONE), RC_F_REALD(nm[i][13], NULL, 0, 0, RC_D_NONE),
                         RC_F_REALD(asc[i], &p->ascale6[i], 1, RC_FF_ZDEF | RC_FF_POS, rot ? RC_D_NONE : RC_D_L),
                         RC_F_REALD(hsc[i], NULL, 0, 0, RC_D_NONE)};
        if ((st = rc_parse_line(rd, b, la, fa, RC_NF(fa)))) return st;
        if ((st = rc_parse_line(rd, b, lb, fb, RC_NF(fb)))) return st;
        p->fct_loc[i] = lb->loc;
        if (p->fct6[i] && bcoef != 0)
            return rc_case_fail(rd, &la->loc, b->name, nm[i][3],
                                "expected 0 or blank with a force curve, got %s: not supported yet (the logarithmic "
                                "rate effect of a nonlinear spring)",
                                fa[3].got);
        /* rupture deformations: 0, blank or beyond 1e29 none */
        p->dmin6[i] = dmin == 0 || dmin <= -1e29 ? -INFINITY : dmin;
        p->dmax6[i] = dmax == 0 || dmax >= 1e29 ? INFINITY : dmax;
        if (p->dmin6[i] >= 0)
            return rc_case_fail(rd, &lb->loc, b->name, fb[6].name,
                                "expected a negative deformation (the rupture in compression), 0 or blank (none), "
                                "got %s",
                                fb[6].got);
        if (p->dmax6[i] <= 0)
            return rc_case_fail(rd, &lb->loc, b->name, fb[7].name,
                                "expected a positive deformation (the rupture in tension), 0 or blank (none), got %s",
                                fb[7].got);
        rupture |= isfinite(p->dmin6[i]) || isfinite(p->dmax6[i]);
        if ((st = rc_parse_line(rd, b, lc, fc, RC_NF(fc)))) return st;
    }
    /* the uni-directional criterion (Ifail 0) and the plain rupture
     * (Ifail2 0) only, with rupture deformations */
    if (rupture && ifail != 0)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "Ifail",
                            "expected 0 with rupture deformations (the spring breaks when one deformation reaches its "
                            "bound), got %d: not supported yet (a multi-directional failure criterion)",
                            ifail);
    if (rupture && ifail2 != 0)
        return rc_case_fail(rd, &b->lines[1].loc, b->name, "Ifail2",
                            "expected 0 with rupture deformations, got %d: not supported yet (a failure model "
                            "other than the deformation bounds)",
                            ifail2);
    if (beam && nd >= 20) { /* the rate filter: acts on the curves only */
        rc_field fr[] = {RC_F_REALD("V0", NULL, 0, 0, RC_D_NONE), RC_F_REALD("W0", NULL, 0, 0, RC_D_NONE),
                         RC_F_REALD("Fcut", NULL, 0, 0, RC_D_NONE), RC_F_INT("Fsmooth", NULL, 0, 0)};
        if ((st = rc_parse_line(rd, b, &b->lines[20], fr, RC_NF(fr)))) return st;
    }
    for (int i = 0; beam && i < 6 && 21 + i <= nd; i++) { /* failure criteria: with rupture only */
        static const char *const fn[6][4] = {{"c1", "n1", "alpha1", "beta1"}, {"c2", "n2", "alpha2", "beta2"},
                                             {"c3", "n3", "alpha3", "beta3"}, {"c4", "n4", "alpha4", "beta4"},
                                             {"c5", "n5", "alpha5", "beta5"}, {"c6", "n6", "alpha6", "beta6"}};
        rc_field ff[] = {RC_F_REALD(fn[i][0], NULL, 0, 0, RC_D_NONE), RC_F_REALD(fn[i][1], NULL, 0, 0, RC_D_NONE),
                         RC_F_REALD(fn[i][2], NULL, 0, 0, RC_D_NONE), RC_F_REALD(fn[i][3], NULL, 0, 0, RC_D_NONE)};
        if ((st = rc_parse_line(rd, b, &b->lines[21 + i], ff, RC_NF(ff)))) return st;
    }
    return rc_note_id(rd, RC_IDK_PROP, p->id, &p->loc, b->hdr->text);
}

/* /PROP/SPRING/prop_ID (/PROP/TYPE4): title; Mass (1-20), sens_ID (51-60),
 * Isflag, Ileng; K C A B D; fct_ID1 H fct_ID2 fct_ID3 fct_ID4 (blank)
 * dmin dmax; F E Ascale Hscale (the last two lines optional). The linear
 * spring-damper F = K dl + C dl/dt is read; the curves, rate effects,
 * rupture, sensor and per-length input are not supported yet.
 * /PROP/SPR_GENE (TYPE8) and /PROP/SPR_BEAM (TYPE13): rc_card_prop_gene. */
static rc_status rc_card_prop_spring(rc_reader *rd, const rc_block *b, int type)
{
    static const char *const fct = "(a nonlinear or rate-dependent spring: ricochet reads the linear "
                                   "spring F = K dl + C dl/dt; use /COUPLING/SPRING Iform 3 or 4 for a "
                                   "tabulated force)";
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "prop_ID", "/PROP/SPRING/prop_ID"))) return st;
    RC_GROW(rd, ms->prop, ms->capprop, ms->nprop);
    rc_case_prop *p = &ms->prop[ms->nprop++];
    p->id = b->id;
    p->kind = RC_PROP_SPRING;
    p->sprtype = type;
    p->loc = b->hdr->loc;
    if (type == 8 || type == 13) return rc_card_prop_gene(rd, b, p);
    if ((st = rc_card_lines(rd, b, p->title, 2, 4,
                            "Mass sens_ID Isflag Ileng, K C A B D[, fct_ID1 H fct_ID2 fct_ID3 fct_ID4 dmin "
                            "dmax[, F E Ascale Hscale]]",
                            &nd)))
        return st;
    double dmin = 0, dmax = 0;
    rc_field l1[] = {RC_F_REALD("Mass", &p->mass, 0, RC_FF_NONNEG, RC_D_M), RC_F_SKIP(30),
                     RC_F_INTN("sens_ID", NULL, RC_FF_ONLY0, "(a spring switched on or off by a sensor)"),
                     RC_F_INT("Isflag", NULL, 0, 0),
                     RC_F_SET("Ileng", NULL, 0, 0, 0x3u, 0x1u, "(input per unit length)")};
    rc_field l2[] = {RC_F_REALD("K", &p->k, 0, RC_FF_NONNEG, RC_D_K),
                     RC_F_REALD("C", &p->c, 0, RC_FF_NONNEG, RC_D_C),
                     RC_F_REALD("A", NULL, 0, 0, RC_D_NONE), RC_F_REALD("B", NULL, 0, 0, RC_D_NONE),
                     RC_F_REALD("D", NULL, 0, 0, RC_D_NONE)};
    rc_field l3[] = {RC_F_INTN("fct_ID1", NULL, RC_FF_ONLY0, fct),
                     RC_F_SET("H", NULL, 0, 0, 0x1FFu, 0x1u, "(hardening and unloading of a nonlinear spring)"),
                     RC_F_INTN("fct_ID2", NULL, RC_FF_ONLY0, fct),
                     RC_F_INTN("fct_ID3", NULL, RC_FF_ONLY0, fct),
                     RC_F_INTN("fct_ID4", NULL, RC_FF_ONLY0, fct),
                     RC_F_SKIP(10),
                     RC_F_REALD("dmin", &dmin, 0, 0, RC_D_L),
                     RC_F_REALD("dmax", &dmax, 0, 0, RC_D_L)};
    rc_field l4[] = {RC_F_REALD("F", NULL, 0, 0, RC_D_NONE), RC_F_REALD("E", NULL, 0, 0, RC_D_NONE),
                     RC_F_REALD("Ascale", NULL, 0, 0, RC_D_NONE), RC_F_REALD("Hscale", NULL, 0, 0, RC_D_NONE)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, RC_NF(l2)))) return st;
    p->thick_loc = b->lines[2].loc;
    if (nd >= 3) {
        if ((st = rc_parse_line(rd, b, &b->lines[3], l3, RC_NF(l3)))) return st;
        /* a rupture length (0: none, as Radioss's defaults of -1e30, 1e30) */
        if (dmin != 0 && dmin > -1e29)
            return rc_case_fail(rd, &b->lines[3].loc, b->name, "dmin",
                                "expected 0 or blank (no rupture), got %s: not supported yet (a spring "
                                "that fails at a negative elongation)",
                                l3[6].got);
        if (dmax != 0 && dmax < 1e29)
            return rc_case_fail(rd, &b->lines[3].loc, b->name, "dmax",
                                "expected 0 or blank (no rupture), got %s: not supported yet (a spring "
                                "that fails at a positive elongation)",
                                l3[7].got);
    }
    if (nd >= 4 && (st = rc_parse_line(rd, b, &b->lines[4], l4, RC_NF(l4)))) return st;
    return rc_note_id(rd, RC_IDK_PROP, p->id, &p->loc, b->hdr->text);
}

/* ======================================================================
 * /MAT
 * ====================================================================== */

/* Laws whose first data line holds Init. dens. in columns 1-20 (checked
 * against the Radioss 2017..2026 formats; docs/case-format.md). */
static const char *const rc_rho_laws[] = {
    "LAW1",  "ELAST",     "LAW2",     "PLAS_JOHNS", "PLAS_ZERIL", "LAW3",     "HYDPLA",
    "LAW4",  "HYD_JCOOK", "LAW13",    "RIGID",      "LAW19",      "FABRI",    "LAW27",
    "PLAS_BRIT", "LAW32", "HILL",     "LAW36",      "PLAS_TAB",   "LAW42",    "OGDEN",
    "LAW43", "HILL_TAB",  "LAW44",    "COWPER",     "LAW65",      "ELASTOMER", "LAW66",
    "LAW70", "FOAM_TAB",  "LAW87",    "BARLAT2000"};

/* /MAT/<law>/mat_ID: title, then the law's lines; the density is the real
 * in columns 1-20 of the first data line (up to the first comma in comma
 * format), for the laws above. */
static rc_status rc_card_mat(rc_reader *rd, const rc_block *b)
{
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "mat_ID", "/MAT/<law>/mat_ID"))) return st;
    RC_GROW(rd, ms->mat, ms->capmat, ms->nmat);
    rc_case_mat *m = &ms->mat[ms->nmat++];
    m->id = b->id;
    m->loc = b->hdr->loc;
    snprintf(m->law, sizeof m->law, "%s", b->kw[1]);
    if ((st = rc_var_lines(rd, b, m->title, "the law's lines", &nd))) return st;
    for (int i = 0; i < RC_NF(rc_rho_laws); i++)
        if (strcmp(m->law, rc_rho_laws[i]) == 0) m->has_rho = 1;
    if (m->has_rho) {
        if (nd < 1)
            return rc_case_fail(rd, &b->hdr->loc, b->name, "Init. dens.",
                                "expected a data line with the density (Init. dens., columns "
                                "1-20), found none");
        /* the first field only: columns 1-20, or up to the first comma */
        const rc_line *ln = &b->lines[1];
        char buf[RC_CASE_MAX_LINE + 1];
        const char *comma = strchr(ln->text, ',');
        int len = comma ? (int)(comma - ln->text) : ln->len < 20 ? ln->len : 20;
        memcpy(buf, ln->text, (size_t)len);
        buf[len] = '\0';
        rc_line one = {buf, len, ln->loc};
        rc_field f[] = {RC_F_REAL("Init. dens.", &m->rho, 0, RC_FF_NONNEG)};
        if ((st = rc_parse_line(rd, b, &one, f, 1))) return st;
        m->rho_loc = ln->loc;
        /* Young's modulus of the elastic and Johnson-Cook laws (line 2,
         * columns 1-20): the stiffness of an /INTER/TYPE7 with Istf 0 */
        static const char *const e_laws[] = {"LAW1", "ELAST", "LAW2", "PLAS_JOHNS"};
        int with_e = 0;
        for (int i = 0; i < RC_NF(e_laws); i++) with_e |= strcmp(m->law, e_laws[i]) == 0;
        if (with_e && nd >= 2) {
            const rc_line *l2 = &b->lines[2];
            const char *c2 = strchr(l2->text, ',');
            int n2 = c2 ? (int)(c2 - l2->text) : l2->len < 20 ? l2->len : 20;
            memcpy(buf, l2->text, (size_t)n2);
            buf[n2] = '\0';
            rc_line two = {buf, n2, l2->loc};
            rc_field fe[] = {RC_F_REALD("E", &m->e, 0, RC_FF_NONNEG, RC_D_K2)};
            if ((st = rc_parse_line(rd, b, &two, fe, 1))) return st;
            m->has_e = m->e > 0;
            m->e_loc = l2->loc;
        }
    } else if ((st = rc_case_warn(rd, &b->hdr->loc,
                                  "card %s ignored: ricochet reads the density of the laws listed "
                                  "in docs/case-format.md only; an element using this material "
                                  "is an error",
                                  b->name)))
        return st;
    return rc_note_id(rd, RC_IDK_MAT, m->id, &m->loc, b->hdr->text);
}

/* ======================================================================
 * /SKEW/FIX
 * ====================================================================== */

static double rc_norm3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

static void rc_cross3(const double *a, const double *b, double *o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* /SKEW/MOV/skew_ID: title; node_ID1 node_ID2 node_ID3 Dir.
 * /SKEW/MOV2/skew_ID: title; node_ID1 node_ID2 node_ID3 (Dir Z).
 * The axes come from the nodes once every card is read. */
static rc_status rc_card_skew_mov(rc_reader *rd, const rc_block *b, int mov2)
{
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    char dir[11] = "";
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "skew_ID", mov2 ? "/SKEW/MOV2/skew_ID" : "/SKEW/MOV/skew_ID")))
        return st;
    RC_GROW(rd, ms->skew, ms->capskew, ms->nskew);
    rc_case_skew *s = &ms->skew[ms->nskew++];
    s->id = b->id;
    s->loc = b->hdr->loc;
    s->mov = 1 + mov2;
    if ((st = rc_card_lines(rd, b, s->title, 1, 1, mov2 ? "node_ID1 node_ID2 node_ID3" : "node_ID1 node_ID2 node_ID3 Dir",
                            &nd)))
        return st;
    rc_field l1[] = {RC_F_INT("node_ID1", &s->nodes[0], 0, RC_FF_POS), RC_F_INT("node_ID2", &s->nodes[1], 0, RC_FF_POS),
                     RC_F_INT("node_ID3", &s->nodes[2], 0, RC_FF_POS), RC_F_STR("Dir", dir, 10)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, mov2 ? 3 : 4))) return st;
    s->line_loc = b->lines[1].loc;
    s->dir = 2;
    if (!mov2) {
        const char d = (char)(dir[0] & ~0x20);
        if (!dir[0]) s->dir = 0; /* X by default */
        else if (!dir[1] && (d == 'X' || d == 'Y' || d == 'Z')) s->dir = d - 'X';
        else
            return rc_case_fail(rd, &s->line_loc, b->name, "Dir", "expected X, Y or Z (the axis from node_ID1 to "
                                "node_ID2), got %s", l1[3].got);
    }
    if (s->nodes[0] == s->nodes[1] || s->nodes[0] == s->nodes[2] || s->nodes[1] == s->nodes[2])
        return rc_case_fail(rd, &s->line_loc, b->name, "node_ID1 node_ID2 node_ID3",
                            "expected three different nodes, got %d, %d, %d", s->nodes[0], s->nodes[1], s->nodes[2]);
    return rc_note_id(rd, RC_IDK_SKEW, s->id, &s->loc, b->hdr->text);
}

/* The axes of a /SKEW/MOV or /SKEW/MOV2 from its nodes' positions: the
 * axis Dir (k) along N1 -> N2, the next one (k+1, cyclically) in the plane
 * of N1 N2 N3 on the side of N3: a'' = N3 - N1, axis k+2 = axis k x a''
 * (normalised), axis k+1 = axis k+2 x axis k; origin N1. */
static rc_status rc_skew_mov_axes(rc_reader *rd, rc_case_skew *s)
{
    rc_case *c = rd->c;
    const double *x[3];
    char card[40];
    snprintf(card, sizeof card, "/SKEW/%s/%d", s->mov == 2 ? "MOV2" : "MOV", s->id);
    for (int j = 0; j < 3; j++) {
        int n = -1;
        for (int q = 0; q < c->nnode && n < 0; q++)
            if (c->node[q].id == s->nodes[j]) n = q;
        if (n < 0) {
            char f[24];
            snprintf(f, sizeof f, "node_ID%d", j + 1);
            return rc_case_fail(rd, &s->line_loc, card, f, "expected the id of a /NODE, got %d (no such node)",
                                s->nodes[j]);
        }
        x[j] = c->node[n].x;
    }
    const int k = s->dir, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    double a[3], b[3], z[3];
    for (int d = 0; d < 3; d++) {
        a[d] = x[1][d] - x[0][d];
        b[d] = x[2][d] - x[0][d];
        s->origin[d] = x[0][d];
    }
    const double na = rc_norm3(a);
    rc_cross3(a, b, z);
    const double nz = rc_norm3(z);
    if (!(na > 0) || !(nz > 1e-10 * na * rc_norm3(b)))
        return rc_case_fail(rd, &s->line_loc, card, "node_ID1 node_ID2 node_ID3",
                            "expected three nodes not on one line (they define a plane), got nodes %d, %d, %d at "
                            "(%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g), (%.9g, %.9g, %.9g)",
                            s->nodes[0], s->nodes[1], s->nodes[2], x[0][0], x[0][1], x[0][2], x[1][0], x[1][1], x[1][2],
                            x[2][0], x[2][1], x[2][2]);
    for (int d = 0; d < 3; d++) {
        s->axis[k][d] = a[d] / na;
        s->axis[k2][d] = z[d] / nz;
    }
    rc_cross3(s->axis[k2], s->axis[k], s->axis[k1]);
    return RC_OK;
}

/* /SKEW/FIX/skew_ID: title; origin; vector Y'; vector Z'. */
static rc_status rc_card_skew(rc_reader *rd, const rc_block *b)
{
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    double v1[3], v2[3], x[3];
    if (!ms) return RC_ENOMEM;
    if (b->nkw >= 2 && (strcmp(b->kw[1], "MOV") == 0 || strcmp(b->kw[1], "MOV2") == 0))
        return rc_card_skew_mov(rd, b, strcmp(b->kw[1], "MOV2") == 0);
    if (b->nkw < 2 || strcmp(b->kw[1], "FIX") != 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL,
                            "%s: not supported yet (supported: /SKEW/FIX, /SKEW/MOV, /SKEW/MOV2)", b->name);
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "skew_ID", "/SKEW/FIX/skew_ID"))) return st;
    RC_GROW(rd, ms->skew, ms->capskew, ms->nskew);
    rc_case_skew *s = &ms->skew[ms->nskew++];
    s->id = b->id;
    s->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, s->title, 3, 3, "Ox Oy Oz, X1 Y1 Z1, X2 Y2 Z2", &nd))) return st;
    rc_field l1[] = {RC_F_REAL("Ox", &s->origin[0], 0, 0), RC_F_REAL("Oy", &s->origin[1], 0, 0),
                     RC_F_REAL("Oz", &s->origin[2], 0, 0)};
    rc_field l2[] = {RC_F_REAL("X1", &v1[0], 0, 0), RC_F_REAL("Y1", &v1[1], 0, 0),
                     RC_F_REAL("Z1", &v1[2], 0, 0)};
    rc_field l3[] = {RC_F_REAL("X2", &v2[0], 0, 0), RC_F_REAL("Y2", &v2[1], 0, 0),
                     RC_F_REAL("Z2", &v2[2], 0, 0)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, 3))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[2], l2, 3))) return st;
    if ((st = rc_parse_line(rd, b, &b->lines[3], l3, 3))) return st;
    const double n1 = rc_norm3(v1), n2 = rc_norm3(v2);
    if (!(n1 > 0))
        return rc_case_fail(rd, &b->lines[2].loc, b->name, "X1 Y1 Z1",
                            "expected a non-zero vector (axis Y'), got 0");
    rc_cross3(v1, v2, x);
    const double nx = rc_norm3(x);
    if (!(n2 > 0) || !(nx > 1e-10 * n1 * n2))
        return rc_case_fail(rd, &b->lines[3].loc, b->name, "X2 Y2 Z2",
                            "expected a vector not parallel to Y' = (%.9g, %.9g, %.9g) (axis Z'), "
                            "got (%.9g, %.9g, %.9g)",
                            v1[0], v1[1], v1[2], v2[0], v2[1], v2[2]);
    for (int k = 0; k < 3; k++) {
        s->axis[1][k] = v1[k] / n1;
        s->axis[0][k] = x[k] / nx;
    }
    rc_cross3(s->axis[0], s->axis[1], s->axis[2]);
    return rc_note_id(rd, RC_IDK_SKEW, s->id, &s->loc, b->hdr->text);
}

/* ======================================================================
 * /GRNOD/PART, /GRNOD/GRNOD
 * ====================================================================== */

/* Title, then up to ten part (group) ids a line; expanded at the end. */
static rc_status rc_card_grnod_def(rc_reader *rd, const rc_block *b, int by_part)
{
    rc_case *c = rd->c;
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd, cap = 0, capl = 0;
    const char *usage = by_part ? "/GRNOD/PART/grnod_ID" : "/GRNOD/GRNOD/grnod_ID";
    const char *name = by_part ? "part_ID" : "grnod_ID";
    if (!ms) return RC_ENOMEM;
    if ((st = rc_header(rd, b, 2, RC_ID_REQUIRED, "grnod_ID", usage))) return st;
    RC_GROW(rd, c->grnod, rd->capgrnod, c->ngrnod);
    rc_case_grnod *g = &c->grnod[c->ngrnod++];
    g->id = b->id;
    g->loc = b->hdr->loc;
    RC_GROW(rd, ms->def, ms->capdef, ms->ndef);
    rc_case_grnod_def *d = &ms->def[ms->ndef++];
    d->grnod = c->ngrnod - 1;
    d->by_part = by_part;
    if ((st = rc_var_lines(rd, b, g->title, by_part ? "part_ID1 ... part_ID10"
                                                    : "grnod_ID1 ... grnod_ID10", &nd)))
        return st;
    for (int i = 1; i <= nd; i++) {
        int v[10];
        rc_field f[10];
        for (int k = 0; k < 10; k++) {
            rc_field fk = RC_F_INT(name, &v[k], 0, RC_FF_NONNEG);
            f[k] = fk;
        }
        if ((st = rc_parse_line(rd, b, &b->lines[i], f, 10))) return st;
        for (int k = 0; k < 10; k++) {
            if (v[k] == 0) continue;
            RC_GROW(rd, d->ids, cap, d->n);
            RC_GROW(rd, d->id_loc, capl, d->n);
            d->ids[d->n] = v[k];
            d->id_loc[d->n++] = b->lines[i].loc;
        }
    }
    return rc_note_id(rd, RC_IDK_GRNOD, g->id, &g->loc, b->hdr->text);
}

static int rc_cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Append the nodes of group index gi (expanded first when it is a
 * definition) to *out; depth guards against cycles. */
static rc_status rc_grnod_expand(rc_reader *rd, int gi, int depth, int **out, int *n, int *cap);

static int rc_def_of(const rc_case_mesh *ms, int gi)
{
    for (int k = 0; ms && k < ms->ndef; k++)
        if (ms->def[k].grnod == gi) return k;
    return -1;
}

static rc_status rc_grnod_fill(rc_reader *rd, int di, int depth)
{
    rc_case *c = rd->c;
    rc_case_mesh *ms = c->mesh;
    rc_case_grnod_def *d = &ms->def[di];
    rc_case_grnod *g = &c->grnod[d->grnod];
    int *nodes = NULL, n = 0, cap = 0;
    char card[48];
    snprintf(card, sizeof card, "/GRNOD/%s/%d", d->by_part ? "PART" : "GRNOD", g->id);
    rc_status st = RC_OK;
    if (g->n || g->nodes) return RC_OK; /* done */
    if (depth > c->ngrnod)
        return rc_case_fail(rd, &g->loc, card, "grnod_ID",
                            "the groups of /GRNOD/%d form a cycle", g->id);
    if (d->by_part) {
        /* every id a part; then one pass over the elements */
        int *want = malloc(((size_t)d->n + 1) * sizeof *want);
        if (!want) return rc_case_nomem(rd);
        for (int k = 0; k < d->n; k++) {
            int found = 0;
            for (int p = 0; p < c->npart && !found; p++) found = c->part[p].id == d->ids[k];
            if (!found) {
                free(want);
                return rc_case_fail(rd, &d->id_loc[k], card, "part_ID",
                                    "expected the id of a /PART, got %d (no such part)", d->ids[k]);
            }
            want[k] = d->ids[k];
        }
        qsort(want, (size_t)d->n, sizeof *want, rc_cmp_int);
        for (int e = 0; ms && e < ms->nelem; e++) {
            const rc_case_elem *el = &ms->elem[e];
            if (!bsearch(&el->part_id, want, (size_t)d->n, sizeof *want, rc_cmp_int)) continue;
            for (int j = 0; j < el->nn; j++) {
                if (el->nodes[j] == 0) continue; /* a TETRA10 straight edge */
                if (n == cap) {
                    int nc = cap ? 2 * cap : 64;
                    int *p = realloc(nodes, (size_t)nc * sizeof *p);
                    if (!p) { free(nodes); free(want); return rc_case_nomem(rd); }
                    nodes = p;
                    cap = nc;
                }
                nodes[n++] = el->nodes[j];
            }
        }
        free(want);
    }
    for (int k = 0; k < d->n && !st && !d->by_part; k++) {
        int gj = -1;
        for (int q = 0; q < c->ngrnod; q++)
            if (c->grnod[q].id == d->ids[k]) { gj = q; break; }
        if (gj < 0) {
            st = rc_case_fail(rd, &d->id_loc[k], card, "grnod_ID",
                              "expected the id of a /GRNOD, got %d (no such group)", d->ids[k]);
            break;
        }
        if (gj == d->grnod) {
            st = rc_case_fail(rd, &d->id_loc[k], card, "grnod_ID",
                              "group %d names itself", d->ids[k]);
            break;
        }
        st = rc_grnod_expand(rd, gj, depth + 1, &nodes, &n, &cap);
    }
    if (st) { free(nodes); return st; }
    /* sorted, each node once */
    if (n > 1) qsort(nodes, (size_t)n, sizeof *nodes, rc_cmp_int);
    int u = 0;
    for (int j = 0; j < n; j++)
        if (u == 0 || nodes[j] != nodes[u - 1]) nodes[u++] = nodes[j];
    if (!nodes) nodes = malloc(sizeof *nodes); /* marks "done" for an empty group */
    if (!nodes) return rc_case_nomem(rd);
    g->nodes = nodes;
    g->n = u;
    return RC_OK;
}

static rc_status rc_grnod_expand(rc_reader *rd, int gi, int depth, int **out, int *n, int *cap)
{
    rc_case *c = rd->c;
    int di = rc_def_of(c->mesh, gi);
    rc_status st;
    if (di >= 0 && (st = rc_grnod_fill(rd, di, depth))) return st;
    const rc_case_grnod *g = &c->grnod[gi];
    for (int k = 0; k < g->n; k++) {
        if (*n == *cap) {
            int nc = *cap ? 2 * *cap : 64;
            int *p = realloc(*out, (size_t)nc * sizeof *p);
            if (!p) return rc_case_nomem(rd);
            *out = p;
            *cap = nc;
        }
        (*out)[(*n)++] = g->nodes[k];
    }
    return RC_OK;
}

rc_status rc_cards_mesh_finish(rc_reader *rd)
{
    rc_case_mesh *ms = rd->c->mesh;
    rc_status st;
    for (int k = 0; ms && k < ms->ndef; k++)
        if ((st = rc_grnod_fill(rd, k, 0))) return st;
    for (int k = 0; ms && k < ms->nskew; k++)
        if (ms->skew[k].mov && (st = rc_skew_mov_axes(rd, &ms->skew[k]))) return st;
    return RC_OK;
}

/* ======================================================================
 * /ADMAS
 * ====================================================================== */

/* /ADMAS/type/admas_ID (the header's two numbers), types 0 and 1: title;
 * MASS grnd_ID. */
static rc_status rc_card_admas(rc_reader *rd, const rc_block *b)
{
    rc_case_mesh *ms = rc_mesh(rd);
    rc_status st;
    int nd;
    if (!ms) return RC_ENOMEM;
    if (b->nkw != 1 || !b->has_id || b->unit_id <= 0)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "admas_ID",
                            "expected the header /ADMAS/type/admas_ID with admas_ID > 0");
    if (b->id > 1)
        return rc_case_fail(rd, &b->hdr->loc, b->name, "type",
                            "type %d: not supported yet (supported: 0 mass on each node, 1 mass "
                            "shared by the nodes of a group)",
                            b->id);
    RC_GROW(rd, ms->admas, ms->capadmas, ms->nadmas);
    rc_case_admas *a = &ms->admas[ms->nadmas++];
    char title[RC_CASE_TITLE_MAX + 1];
    a->id = b->unit_id;
    a->type = b->id;
    a->loc = b->hdr->loc;
    if ((st = rc_card_lines(rd, b, title, 1, 1, "MASS grnd_ID", &nd))) return st;
    rc_field l1[] = {RC_F_REAL("MASS", &a->mass, 0, RC_FF_NONNEG),
                     RC_F_INT("grnd_ID", &a->grnod_id, 0, RC_FF_POS)};
    if ((st = rc_parse_line(rd, b, &b->lines[1], l1, RC_NF(l1)))) return st;
    a->line_loc = b->lines[1].loc;
    return rc_note_id(rd, RC_IDK_ADMAS, a->id, &a->loc, b->hdr->text);
}

/* ======================================================================
 * Dispatch and look-ups
 * ====================================================================== */

rc_status rc_cards_mesh(rc_reader *rd, const rc_block *b, int *handled)
{
    const char *kw = b->kw[0], *sub = b->nkw >= 2 ? b->kw[1] : "";
    rc_elem_kind ek = 0;
    rc_prop_kind pk = 0;
    int grnod = -1, sprtype = 0, springs = 0;
    *handled = 0;
    if (strcmp(kw, "SHELL") == 0) ek = RC_ELEM_SHELL;
    else if (strcmp(kw, "SH3N") == 0) ek = RC_ELEM_SH3N;
    else if (strcmp(kw, "BRICK") == 0) ek = RC_ELEM_BRICK;
    else if (strcmp(kw, "TETRA4") == 0) ek = RC_ELEM_TETRA4;
    else if (strcmp(kw, "PENTA6") == 0) ek = RC_ELEM_PENTA6;
    else if (strcmp(kw, "TETRA10") == 0) ek = RC_ELEM_TETRA10;
    else if (strcmp(kw, "SPRING") == 0) springs = 1;
    else if (strcmp(kw, "PROP") == 0 && (!strcmp(sub, "SPRING") || !strcmp(sub, "TYPE4"))) sprtype = 4;
    else if (strcmp(kw, "PROP") == 0 && (!strcmp(sub, "SPR_GENE") || !strcmp(sub, "TYPE8"))) sprtype = 8;
    else if (strcmp(kw, "PROP") == 0 && (!strcmp(sub, "SPR_BEAM") || !strcmp(sub, "TYPE13"))) sprtype = 13;
    else if (strcmp(kw, "PROP") == 0 && (!strcmp(sub, "SHELL") || !strcmp(sub, "TYPE1"))) pk = RC_PROP_SHELL;
    else if (strcmp(kw, "PROP") == 0 && (!strcmp(sub, "SOLID") || !strcmp(sub, "TYPE14"))) pk = RC_PROP_SOLID;
    else if (strcmp(kw, "GRNOD") == 0 && strcmp(sub, "PART") == 0) grnod = 1;
    else if (strcmp(kw, "GRNOD") == 0 && strcmp(sub, "GRNOD") == 0) grnod = 0;
    else if (strcmp(kw, "ADMAS") == 0) {
        *handled = 1;
        if (b->bad)
            return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "malformed card header: %s", b->bad);
        return rc_card_admas(rd, b);
    } else if (strcmp(kw, "MAT") == 0 && b->nkw != 2) return RC_OK; /* e.g. /MAT/GAS/MOLE: ignored */
    else if (strcmp(kw, "MAT") != 0 && strcmp(kw, "SKEW") != 0) return RC_OK;
    *handled = 1;
    if (b->bad)
        return rc_case_fail(rd, &b->hdr->loc, b->name, NULL, "malformed card header: %s", b->bad);
    if (ek) return rc_card_elements(rd, b, ek);
    if (springs) return rc_card_springs(rd, b);
    if (pk) return rc_card_prop(rd, b, pk);
    if (sprtype) return rc_card_prop_spring(rd, b, sprtype);
    if (grnod >= 0) return rc_card_grnod_def(rd, b, grnod);
    if (strcmp(kw, "MAT") == 0) return rc_card_mat(rd, b);
    return rc_card_skew(rd, b);
}

int rc_case_find_prop(const rc_case *c, int id)
{
    for (int k = 0; c->mesh && k < c->mesh->nprop; k++)
        if (c->mesh->prop[k].id == id) return k;
    return -1;
}

int rc_case_find_mat(const rc_case *c, int id)
{
    for (int k = 0; c->mesh && k < c->mesh->nmat; k++)
        if (c->mesh->mat[k].id == id) return k;
    return -1;
}

int rc_case_find_skew(const rc_case *c, int id)
{
    for (int k = 0; c->mesh && k < c->mesh->nskew; k++)
        if (c->mesh->skew[k].id == id) return k;
    return -1;
}

void rc_case_mesh_free(rc_case_mesh *m)
{
    if (!m) return;
    free(m->elem);
    free(m->spring);
    free(m->prop);
    free(m->mat);
    free(m->skew);
    for (int k = 0; k < m->ndef; k++) {
        free(m->def[k].ids);
        free(m->def[k].id_loc);
    }
    free(m->def);
    free(m->admas);
    free(m);
}
