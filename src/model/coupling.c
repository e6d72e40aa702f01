/*
 * Compile the /COUPLING cards into rc_couplings (coupling.h): resolve the
 * bodies and functions, express the attachment points in the body frames,
 * default the relaxation length, integrate the form-4 stiffness tables, set
 * the gravity of the catenary lines; the /SPRING elements of a /PROP/SPRING
 * (TYPE4) as linear springs, of a /PROP/SPR_GENE (TYPE8) as general springs
 * (form 5), between the bodies carrying their nodes; the
 * energy states, their tolerances
 * and the Jacobian blocks; the run data (warm starts, solver workspace);
 * the summary of `ricochet check`.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case/case_coupling.h"
#include "case/case_joint.h"
#include "case/case_mesh.h"
#include "model/joint.h"
#include "model/table.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "base/error.h"


static const char *const kind_name[5] = {"", "SPRING", "CATENARY", "CONTACT", "JOINT_STOP"};

/* Body index of /RBODY id (0: fixed in space, -1; no such body: -2); the
 * model's bodies are the case's, in the same order. */
static int body_index(const rc_case *c, int id)
{
    if (id == 0) return -1;
    const int b = rc_case_find_rbody(c, id);
    return b >= 0 ? b : -2;
}

/* Gravity of the lines: the /GRAV cards that apply to all bodies. */
static void line_gravity(const rc_case *c, double g[3])
{
    g[0] = g[1] = g[2] = 0;
    for (int k = 0; k < c->ngrav; k++)
        if (c->grav[k].grnod_id == 0)
            for (int i = 0; i < 3; i++) g[i] += c->grav[k].fscale * c->grav[k].u[i];
}

static rc_status alloc_arrays(rc_couplings *p, int n)
{
#define CPL_ALLOC(ptr, cnt)                                   \
    if (!((ptr) = calloc((size_t)(cnt) + 1, sizeof *(ptr)))) \
        return RC_ENOMEM;
    p->n = n;
    CPL_ALLOC(p->id, n);
    CPL_ALLOC(p->kind, n);
    CPL_ALLOC(p->type, n);
    CPL_ALLOC(p->name, n);
    CPL_ALLOC(p->b1, n);
    CPL_ALLOC(p->b2, n);
    CPL_ALLOC(p->s1, 3 * n);
    CPL_ALLOC(p->s2, 3 * n);
    CPL_ALLOC(p->eadr, n);
    CPL_ALLOC(p->form, n);
    CPL_ALLOC(p->x0, n);
    CPL_ALLOC(p->kd, n);
    CPL_ALLOC(p->coef, 3 * n);
    CPL_ALLOC(p->table, n);
    CPL_ALLOC(p->fref, n);
    CPL_ALLOC(p->xref, n);
    CPL_ALLOC(p->cum, n);
    CPL_ALLOC(p->gk, 12 * n);
    CPL_ALLOC(p->gd0, 3 * n);
    CPL_ALLOC(p->gfb, n);
    CPL_ALLOC(p->gtab, 6 * n);
    CPL_ALLOC(p->gdlo, 6 * n);
    CPL_ALLOC(p->gdhi, 6 * n);
    CPL_ALLOC(p->grup, n);
    CPL_ALLOC(p->gsc, 12 * n);
    CPL_ALLOC(p->lambda0, n);
    CPL_ALLOC(p->leq, n);
    CPL_ALLOC(p->ea, n);
    CPL_ALLOC(p->jb, n);
    CPL_ALLOC(p->law_loc, n);
    CPL_ALLOC(p->ljoint, n);
    CPL_ALLOC(p->lrev, n);
    CPL_ALLOC(p->lfrm, 9 * n);
    CPL_ALLOC(p->llo, n);
    CPL_ALLOC(p->lhi, n);
#undef CPL_ALLOC
    return RC_OK;
}

/* One coupling: ends, then the law of its kind. */
static rc_status compile_one(const rc_case *c, rc_model *m, int k, rc_error *err)
{
    const rc_case_coupling *cc = &c->coupling[k];
    rc_couplings *p = m->cpl;
    char card[64];
    snprintf(card, sizeof card, "/COUPLING/%s/%d", kind_name[cc->kind], cc->id);
    p->name[k] = malloc(strlen(card) + 1);
    if (!p->name[k]) RC_RAISE(err, RC_ENOMEM, "out of memory");
    strcpy(p->name[k], card);
    p->id[k] = cc->id;
    p->kind[k] = cc->kind == RC_CASE_CPL_SPRING ? RC_CPL_SPRING : cc->kind == RC_CASE_CPL_CATENARY ? RC_CPL_CATENARY : RC_CPL_CONTACT;
    p->type[k] = kind_name[cc->kind];
    if (cc->kind == RC_CASE_CPL_CONTACT) return rc_cpl_contact_compile(c, m, k, err); /* coupling_contact.c */
    p->table[k] = -1;
    /* line 4 of both cards: X0 Kd (spring), Lambda0 L_eq D (catenary) */
    p->law_loc[k] = rc_loc_or(cc->line_loc[3], cc->loc);

    /* ends: body (or space) and the point in the body frame */
    int *bs[2] = {&p->b1[k], &p->b2[k]};
    double *ss[2] = {p->s1 + 3 * k, p->s2 + 3 * k};
    for (int e = 0; e < 2; e++) {
        int b = body_index(c, cc->rbody[e]);
        if (b == -2)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field rbody_ID%d: expected the id of a /RBODY or 0 (fixed point), got %d (no such body)",
                     RC_LOC(cc->line_loc[0]), card, e + 1, cc->rbody[e]);
        *bs[e] = b;
        /* body frame = global frame at t = 0, origin at the centre of mass */
        const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
        for (int i = 0; i < 3; i++) ss[e][i] = cc->p[e][i] - org[i];
    }
    const double dist = sqrt(pow(cc->p[1][0] - cc->p[0][0], 2) + pow(cc->p[1][1] - cc->p[0][1], 2) +
                             pow(cc->p[1][2] - cc->p[0][2], 2));

    if (cc->kind == RC_CASE_CPL_CATENARY) {
        double g[3];
        line_gravity(c, g);
        if (!(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] > 0))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: a catenary hangs in gravity: expected a /GRAV card that applies to all bodies (grnod_ID 0) with a non-zero Fscale_y, found none",
                     RC_LOC(cc->loc), card);
        memcpy(p->grav, g, sizeof g);
        p->lambda0[k] = cc->lambda0;
        p->leq[k] = cc->leq;
        p->ea[k] = cc->d * cc->leq;
        return RC_OK;
    }

    /* spring-damper */
    p->form[k] = (rc_keff_form)cc->iform;
    p->x0[k] = cc->x0_given ? cc->x0 : dist;
    p->kd[k] = cc->kd;
    p->coef[3 * k] = cc->a;
    p->coef[3 * k + 1] = cc->iform == 2 ? cc->b : 0.0;
    p->coef[3 * k + 2] = cc->iform == 2 ? cc->c : 0.0;
    if (cc->iform == RC_KEFF_FORCE || cc->iform == RC_KEFF_STIFF) {
        rc_status st = rc_case_ref_funct(c, cc->fct_id, 1, cc->line_loc[0], card, "fct_ID", &p->table[k], err);
        if (st) return st;
    }
    if (cc->iform == RC_KEFF_STIFF) {
        const rc_table *t = &m->table[p->table[k]];
        p->cum[k] = malloc((size_t)t->n * sizeof(double));
        if (!p->cum[k]) RC_RAISE(err, RC_ENOMEM, "out of memory");
        rc_error e2;
        memset(&e2, 0, sizeof e2);
        rc_status st = rc_cpl_stiff_table(t, p->cum[k], &e2);
        if (st == RC_EINPUT)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field fct_ID: %s", RC_LOC(rc_loc_or(cc->line_loc[0], cc->loc)),
                     card, e2.msg);
        if (st) {
            if (err) *err = e2;
            return st;
        }
        p->fref[k] = cc->ref_given ? cc->fr : 0.0;
        p->xref[k] = cc->ref_given ? cc->xr : p->x0[k];
    }
    return RC_OK;
}

static int has_stops(const rc_case_joint *cj) { return cj->has_lo || cj->has_hi; }

/* The law of /SPRING element se: its part's /PROP/SPRING (TYPE4),
 * /PROP/SPR_GENE (TYPE8) or /PROP/SPR_BEAM (TYPE13), checked. */
static rc_status spring_prop(const rc_case *c, const rc_case_spring *se, const rc_case_prop **out, rc_error *err)
{
    char card[64];
    snprintf(card, sizeof card, "/SPRING/%d", se->part_id);
    const int pi = rc_case_find_part(c, se->part_id);
    if (pi < 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field part_ID: expected the id of a /PART in the header, got %d (no such part; spring %d)",
                 RC_LOC(se->loc), card, se->part_id, se->id);
    const rc_case_part *pt = &c->part[pi];
    const int qi = pt->prop_id ? rc_case_find_prop(c, pt->prop_id) : -1;
    const rc_case_prop *q = qi >= 0 ? &c->mesh->prop[qi] : NULL;
    if (!q || q->kind != RC_PROP_SPRING)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /PART/%d, field prop_ID: expected the id of a /PROP/SPRING (/PROP/TYPE4), /PROP/SPR_GENE (/PROP/TYPE8) or /PROP/SPR_BEAM (/PROP/TYPE13) for the spring elements of the part (e.g. %s spring %d at %s:%d), got %d (%s)",
                 RC_LOC(rc_loc_or(pt->prop_loc, pt->loc)), pt->id, card, se->id, se->loc.file, se->loc.line, pt->prop_id,
                 !q ? "no spring property with this id; ricochet reads /PROP/TYPE4, /PROP/TYPE8 and /PROP/TYPE13 and ignores the other spring types"
                    : q->kind == RC_PROP_SHELL ? "a /PROP/SHELL" : "a /PROP/SOLID");
    if (q->sprtype == 4 && se->skew_id != 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Skew_ID: expected 0 or blank for a spring of a /PROP/TYPE4 (the skew is the "
                           "frame of a /PROP/TYPE8 or /PROP/TYPE13 spring), got %d (spring %d, /PROP/TYPE4/%d)",
                 RC_LOC(se->loc), card, se->skew_id, se->id, q->id);
    *out = q;
    return RC_OK;
}

/* Is /SPRING element se inside one rigid body (both nodes on it)? Such a
 * spring never stretches: it is left out, as the rigid body moves both its
 * nodes in Radioss. */
static int spring_inside_body(const rc_case *c, const rc_case_spring *se)
{
    const int b1 = rc_case_body_of_node(c, se->nodes[0]);
    return b1 >= 0 && b1 == rc_case_body_of_node(c, se->nodes[1]);
}

/* The skew of a general or beam spring: the element's Skew_ID when not 0,
 * else the property's; -1 when both are 0 (the global axes), else its
 * index in the case mesh (checked). */
static rc_status spring_skew(const rc_case *c, const rc_case_spring *se, const rc_case_prop *q, int *out,
                             rc_error *err)
{
    const int sk = se->skew_id ? se->skew_id : q->skew_id;
    *out = -1;
    if (!sk) return RC_OK;
    const int s = rc_case_find_skew(c, sk);
    if (s < 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s/%d, field Skew_ID: expected the id of a /SKEW/FIX, /SKEW/MOV or /SKEW/MOV2, got %d "
                           "(no such skew; spring %d)",
                 RC_LOC(se->skew_id ? se->loc : q->thick_loc), se->skew_id ? "/SPRING" : q->sprtype == 8 ? "/PROP/TYPE8" : "/PROP/TYPE13",
                 se->skew_id ? se->part_id : q->id, sk, se->id);
    *out = s;
    return RC_OK;
}

/* The end (1, 2) of spring se whose body carries the moving skew s (its
 * three nodes on that body), 0 when its nodes are in no body (the frame
 * stays where it starts); an error when they are on several bodies or on a
 * body that neither end of the spring is on. */
static rc_status skew_carrier(const rc_case *c, const rc_couplings *p, int k, const rc_case_spring *se,
                              const rc_case_prop *q, int s, int *fb, rc_error *err)
{
    const rc_case_skew *sk = &c->mesh->skew[s];
    const rc_loc at = se->skew_id ? se->loc : q->thick_loc;
    char where[48];
    snprintf(where, sizeof where, "%s/%d", se->skew_id ? "/SPRING" : q->sprtype == 8 ? "/PROP/TYPE8" : "/PROP/TYPE13",
             se->skew_id ? se->part_id : q->id);
    const int b = rc_case_body_of_node(c, sk->nodes[0]);
    for (int j = 1; j < 3; j++)
        if (rc_case_body_of_node(c, sk->nodes[j]) != b)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field Skew_ID: expected a /SKEW/MOV%s whose three nodes are on one rigid body "
                               "(or on none), got /SKEW/MOV%s/%d with nodes %d, %d, %d on different bodies: not "
                               "supported yet (a frame deformed by its nodes; spring %d)",
                     RC_LOC(at), where, sk->mov == 2 ? "2" : "", sk->mov == 2 ? "2" : "", sk->id, sk->nodes[0],
                     sk->nodes[1], sk->nodes[2], se->id);
    *fb = b < 0 ? 0 : b == p->b1[k] ? 1 : b == p->b2[k] ? 2 : -1;
    if (*fb < 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Skew_ID: expected a /SKEW/MOV%s carried by the body of node %d or of node %d "
                           "(the spring's ends) or by no body, got /SKEW/MOV%s/%d on /RBODY %d: not supported yet (a "
                           "spring's frame carried by a third body; spring %d)",
                 RC_LOC(at), where, sk->mov == 2 ? "2" : "", se->nodes[0], se->nodes[1], sk->mov == 2 ? "2" : "", sk->id,
                 c->rbody[b].id, se->id);
    return RC_OK;
}

/* A /SPRING element of a /PROP/TYPE8 (SPR_GENE) or /PROP/TYPE13 (SPR_BEAM)
 * as coupling k (form 5): six linear stiffnesses and dampings in a frame
 * E, relaxed in the initial configuration (x: the two nodes;
 * docs/theory.md 8.1).
 *   TYPE8: E = the axes of Skew_ID (the element's when not 0, else the
 *   property's; 0: the global axes); a /SKEW/FIX stays fixed in space, a
 *   /SKEW/MOV or /SKEW/MOV2 turns with the body that carries its nodes.
 *   TYPE13: X' along node 1 -> node 2, Y' the skew's Y axis (global Y when
 *   0) made normal to X' (the skew's Z axis, global Z, when Y is within
 *   1e-6 of X'), Z' = X' x Y'; the skew's axes when the nodes coincide;
 *   the frame turns with the body of node 1 (fixed when node 1 is in no
 *   body). */
static rc_status gene_elem(const rc_case *c, rc_couplings *p, const rc_case_spring *se, const rc_case_prop *q, int k,
                           const double *x[2], double dist, rc_error *err)
{
    int s;
    rc_status st = spring_skew(c, se, q, &s, err);
    if (st) return st;
    double *e = p->lfrm + 9 * k;
    memset(e, 0, 9 * sizeof *e);
    e[0] = e[4] = e[8] = 1.0;
    if (s >= 0)
        for (int j = 0; j < 3; j++)
            for (int i = 0; i < 3; i++) e[3 * j + i] = c->mesh->skew[s].axis[j][i];
    p->gfb[k] = 0;
    if (q->sprtype == 13) {
        p->gfb[k] = 1;
        if (dist > 0) {
            double X[3], Y[3], Z[3];
            for (int i = 0; i < 3; i++) X[i] = (x[1][i] - x[0][i]) / dist;
            for (int pass = 0; pass < 2; pass++) {
                const double *a = e + 3 * (1 + pass); /* the skew's Y, then Z */
                const double ax = a[0] * X[0] + a[1] * X[1] + a[2] * X[2];
                for (int i = 0; i < 3; i++) Y[i] = a[i] - ax * X[i];
                const double ny = sqrt(Y[0] * Y[0] + Y[1] * Y[1] + Y[2] * Y[2]);
                if (ny > 1e-6 || pass == 1) {
                    for (int i = 0; i < 3; i++) Y[i] /= ny;
                    break;
                }
            }
            Z[0] = X[1] * Y[2] - X[2] * Y[1];
            Z[1] = X[2] * Y[0] - X[0] * Y[2];
            Z[2] = X[0] * Y[1] - X[1] * Y[0];
            for (int i = 0; i < 3; i++) {
                e[i] = X[i];
                e[3 + i] = Y[i];
                e[6 + i] = Z[i];
            }
        }
    } else if (s >= 0 && c->mesh->skew[s].mov) {
        int fb;
        if ((st = skew_carrier(c, p, k, se, q, s, &fb, err))) return st;
        p->gfb[k] = fb;
    }
    p->form[k] = RC_KEFF_GENE;
    p->x0[k] = dist;
    p->kd[k] = 0.0;
    for (int i = 0; i < 6; i++) {
        p->gk[12 * k + i] = q->k6[i];
        p->gk[12 * k + 6 + i] = q->c6[i];
        char card[40], field[24];
        snprintf(card, sizeof card, "/PROP/TYPE%d/%d", q->sprtype, q->id);
        snprintf(field, sizeof field, "fct_ID1%d", i + 1);
        if ((st = rc_case_ref_funct(c, q->fct6[i], 0, q->fct_loc[i], card, field, &p->gtab[6 * k + i], err)))
            return st;
        p->gsc[12 * k + i] = q->a6[i];
        p->gsc[12 * k + 6 + i] = q->ascale6[i];
        p->gdlo[6 * k + i] = q->dmin6[i];
        p->gdhi[6 * k + i] = q->dmax6[i];
        if (isfinite(q->dmin6[i]) || isfinite(q->dmax6[i])) p->grup[k] = 0; /* numbered below */
    }
    for (int i = 0; i < 3; i++) p->gd0[3 * k + i] = x[1][i] - x[0][i];
    return RC_OK;
}

/* The /SPRING element e (case mesh) as coupling k: a TYPE4 spring is the
 * linear spring-damper of /COUPLING/SPRING Iform 1 between the points of
 * its two nodes, relaxed at their initial distance, k = K, k_d = C. A node
 * in no rigid body is a point fixed in space. */
static rc_status compile_spring_elem(const rc_case *c, rc_model *m, int e, int k, rc_error *err)
{
    const rc_case_spring *se = &c->mesh->spring[e];
    rc_couplings *p = m->cpl;
    char card[64];
    snprintf(card, sizeof card, "/SPRING/%d", se->part_id);
    char name[96];
    snprintf(name, sizeof name, "/SPRING/%d element %d", se->part_id, se->id);
    if (!(p->name[k] = malloc(strlen(name) + 1))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    strcpy(p->name[k], name);
    p->id[k] = se->id;
    p->kind[k] = RC_CPL_SPRING;
    p->type[k] = "SPRING_ELEMENT";
    p->table[k] = -1;
    const rc_case_prop *q = NULL;
    rc_status st = spring_prop(c, se, &q, err);
    if (st) return st;
    p->law_loc[k] = rc_loc_or(q->thick_loc, q->loc);
    /* ends: the body carrying each node, or a point fixed in space */
    int *bs[2] = {&p->b1[k], &p->b2[k]};
    double *ss[2] = {p->s1 + 3 * k, p->s2 + 3 * k};
    const double *x[2];
    for (int j = 0; j < 2; j++) {
        const int n = rc_case_find_node(c, se->nodes[j]);
        if (n < 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field node_ID%d: expected the id of a /NODE, got %d (no such node; spring %d)",
                     RC_LOC(se->loc), card, j + 1, se->nodes[j], se->id);
        x[j] = c->node[n].x;
        const int b = rc_case_body_of_node(c, se->nodes[j]);
        *bs[j] = b;
        const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
        for (int i = 0; i < 3; i++) ss[j][i] = x[j][i] - org[i];
    }
    if (p->b1[k] < 0 && p->b2[k] < 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field node_ID1: spring %d joins nodes %d and %d, which belong to no /RBODY: "
                           "expected at least one node of a rigid body (a node in no body is a point fixed in space)",
                 RC_LOC(se->loc), card, se->id, se->nodes[0], se->nodes[1]);
    const double dist = sqrt(pow(x[1][0] - x[0][0], 2) + pow(x[1][1] - x[0][1], 2) + pow(x[1][2] - x[0][2], 2));
    if (q->sprtype == 8 || q->sprtype == 13) return gene_elem(c, p, se, q, k, x, dist, err);
    if (!(dist > 0))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field node_ID2: spring %d has a zero length (nodes %d and %d coincide): a "
                           "/PROP/TYPE4 spring acts along the line between its nodes",
                 RC_LOC(se->loc), card, se->id, se->nodes[0], se->nodes[1]);
    p->form[k] = RC_KEFF_CONST;
    p->x0[k] = dist;
    p->kd[k] = q->c;
    p->coef[3 * k] = q->k;
    return RC_OK;
}

/* The stops of joint card j as coupling k (docs/theory.md, "Joint stops"):
 * the bodies and anchors as the joint's (model/joint.c, which checks them),
 * the joint frame, the law. */
static rc_status compile_stop(const rc_case *c, rc_model *m, int j, int k, rc_error *err)
{
    const rc_case_joint *cj = &c->joint[j];
    rc_couplings *p = m->cpl;
    static const char *const jname[6] = {"", "SPHERICAL", "REVOLUTE", "DISTANCE", "FIXED", "PRISMATIC"};
    char card[64];
    snprintf(card, sizeof card, "/JOINT/%s/%d", jname[cj->kind], cj->id);
    if (!(p->name[k] = malloc(strlen(card) + 1))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    strcpy(p->name[k], card);
    p->id[k] = cj->id;
    p->kind[k] = RC_CPL_LIMIT;
    p->type[k] = kind_name[RC_CPL_LIMIT];
    p->table[k] = -1;
    p->law_loc[k] = rc_loc_or(cj->line_loc[3], cj->loc);
    p->ljoint[k] = j;
    p->lrev[k] = cj->kind == RC_CASE_JNT_REVOLUTE;
    int *bs[2] = {&p->b1[k], &p->b2[k]};
    double *ss[2] = {p->s1 + 3 * k, p->s2 + 3 * k};
    for (int e = 0; e < 2; e++) {
        const int b = body_index(c, cj->rbody[e]);
        if (b == -2)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field rbody_ID%d: expected the id of a /RBODY%s, got %d (no such body)",
                     RC_LOC(cj->line_loc[0]), card, e + 1, e ? " or 0 (the ground)" : "", cj->rbody[e]);
        *bs[e] = b;
        const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
        for (int i = 0; i < 3; i++) ss[e][i] = cj->p[i] - org[i];
    }
    const double na = sqrt(cj->axis[0] * cj->axis[0] + cj->axis[1] * cj->axis[1] + cj->axis[2] * cj->axis[2]);
    const double ax[3] = {cj->axis[0] / na, cj->axis[1] / na, cj->axis[2] / na};
    rc_jnt_axis_frame(ax, p->lfrm + 9 * k);
    p->llo[k] = cj->has_lo ? cj->lim_lo : -INFINITY;
    p->lhi[k] = cj->has_hi ? cj->lim_hi : INFINITY;
    p->coef[3 * k] = cj->lim_k;
    p->kd[k] = cj->lim_c;
    if (cj->lim_fct > 0) { /* the elastic part from a curve F_e(p), through 0 */
        rc_status st = rc_case_ref_funct(c, cj->lim_fct, 1, p->law_loc[k], card, "fct_lim", &p->table[k], err);
        if (st) return st;
        double f0, df0;
        rc_table_eval(&m->table[p->table[k]], 0.0, &f0, &df0);
        double ymax = 0.0;
        for (int i = 0; i < m->table[p->table[k]].n; i++) ymax = fmax(ymax, fabs(m->table[p->table[k]].y[i]));
        if (fabs(f0) > 1e-12 * ymax)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field fct_lim: expected a curve through 0 at p = 0 (the stop's force starts "
                               "from zero at the stop), got F_e(0) = %.9g for /FUNCT %d",
                     RC_LOC(p->law_loc[k]), card, f0, cj->lim_fct);
    }
    return RC_OK;
}

rc_status rc_cpl_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    gsl_set_error_handler_off(); /* GSL reports through return codes */
    m->cpl = calloc(1, sizeof *m->cpl);
    int nlim = 0, nspr = 0;
    /* the /SPRING elements: their laws checked, those inside one body left out */
    for (int e = 0; c->mesh && e < c->mesh->nspring; e++) {
        const rc_case_prop *q;
        rc_status st = spring_prop(c, &c->mesh->spring[e], &q, err);
        if (st) return st;
        nspr += !spring_inside_body(c, &c->mesh->spring[e]);
    }
    for (int j = 0; j < c->njoint; j++) nlim += has_stops(&c->joint[j]);
    if (!m->cpl || alloc_arrays(m->cpl, c->ncoupling + nspr + nlim))
        RC_RAISE(err, RC_ENOMEM, "out of memory compiling the couplings");
    /* the cards, then the /SPRING elements (couplings too), then the stops */
    m->cpl->ncard = c->ncoupling + nspr;
    rc_status st = rc_cpl_contact_alloc(m, err);
    if (st) return st;
    for (int k = 0; k < m->cpl->n; k++) m->cpl->ljoint[k] = m->cpl->grup[k] = -1;
    for (int k = 0; k < c->ncoupling; k++) {
        m->cpl->ct->fadr[k + 1] = m->cpl->ct->fadr[k] = m->cpl->ct->nface; /* no faces unless a contact */
        st = compile_one(c, m, k, err);
        if (st) return st;
    }
    for (int e = 0, k = c->ncoupling; c->mesh && e < c->mesh->nspring; e++) {
        if (spring_inside_body(c, &c->mesh->spring[e])) continue;
        m->cpl->ct->fadr[k + 1] = m->cpl->ct->fadr[k] = m->cpl->ct->nface;
        if ((st = compile_spring_elem(c, m, e, k++, err))) return st;
    }
    for (int j = 0, k = c->ncoupling + nspr; j < c->njoint; j++) {
        if (!has_stops(&c->joint[j])) continue;
        m->cpl->ct->fadr[k + 1] = m->cpl->ct->fadr[k] = m->cpl->ct->nface;
        if ((st = compile_stop(c, m, j, k++, err))) return st;
    }
    for (int k = 0; k < m->cpl->n; k++) /* the springs' rupture roots, in order */
        if (m->cpl->grup[k] >= 0) m->cpl->grup[k] = m->cpl->nrup++;
    return RC_OK;
}

int rc_cpl_layout(rc_model *m, int ny)
{
    for (int k = 0; k < m->cpl->n; k++) {
        m->cpl->eadr[k] = ny;
        ny += RC_CE;
    }
    return ny;
}

void rc_cpl_atol(rc_model *m)
{
    for (int k = 0; k < m->cpl->n; k++)
        for (int i = 0; i < RC_CE; i++) m->atol[m->cpl->eadr[k] + i] = m->atol_energy;
}

void rc_cpl_block(const rc_model *m, int k, rc_jblock *jb)
{
    const rc_couplings *p = m->cpl;
    const int bodies[2] = {p->b1[k], p->b2[k]};
    jb->nrow = jb->ncol = 0;
    for (int s = 0; s < 2; s++) {
        const int b = bodies[s];
        if (b < 0 || m->body_yadr[b] < 0) continue;
        for (int i = 0; i < 6; i++) jb->rows[jb->nrow++] = m->body_yadr[b] + 7 + i;
        for (int i = 0; i < RC_NB; i++) jb->cols[jb->ncol++] = m->body_yadr[b] + i;
    }
    for (int i = 0; i < RC_CE; i++) jb->rows[jb->nrow++] = p->eadr[k] + i;
    if (jb->ncol == 0) jb->nrow = 0; /* both ends fixed: nothing depends on states */
}

void rc_cpl_free(rc_couplings *p)
{
    if (!p) return;
    for (int k = 0; k < p->n; k++) {
        if (p->name) free(p->name[k]);
        if (p->cum) free(p->cum[k]);
    }
    void *arrays[] = {p->id,  p->kind, (void *)p->type, p->name, p->b1,   p->b2,   p->s1,      p->s2,  p->eadr,
                      p->form, p->x0,  p->kd,   p->coef, p->table, p->fref,   p->xref, p->cum,
                      p->lambda0, p->leq, p->ea, p->jb, p->gk, p->gd0, p->gfb, p->gtab, p->gsc, p->gdlo, p->gdhi, p->grup, p->law_loc, p->ljoint, p->lrev, p->lfrm, p->llo, p->lhi};
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++) free(arrays[k]);
    rc_cpl_contact_free(p->ct);
    free(p);
}


/* ---- run data ------------------------------------------------------------ */
rc_cpl_data *rc_cpl_data_new(const rc_model *m)
{
    const rc_couplings *p = m->cpl;
    rc_cpl_data *cd = calloc(1, sizeof *cd);
    if (!cd) return NULL;
    cd->fail = -1;
    cd->warm = malloc((2 * (size_t)p->n + 1) * sizeof(double));
    int ncat = 0;
    for (int k = 0; k < p->n; k++) ncat += p->kind[k] == RC_CPL_CATENARY;
    if (ncat) cd->ws = rc_cat_ws_new();
    if (!cd->warm || (ncat && !cd->ws)) {
        rc_cpl_data_free(cd);
        return NULL;
    }
    for (int k = 0; k < 2 * p->n; k++) cd->warm[k] = NAN;
    cd->fmode = calloc((size_t)(p->ct ? p->ct->nface : 0) + 1, sizeof(int));
    cd->lmode = calloc((size_t)p->n + 1, sizeof(int));
    if (!cd->fmode || !cd->lmode) {
        rc_cpl_data_free(cd);
        return NULL;
    }
    return cd;
}

void rc_cpl_data_free(rc_cpl_data *cd)
{
    if (!cd) return;
    free(cd->warm);
    free(cd->fmode);
    free(cd->lmode);
    rc_cat_ws_free(cd->ws);
    free(cd);
}
