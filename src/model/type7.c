/*
 * /INTER/TYPE7 as one-way node-to-surface contacts (docs/theory.md, "TYPE7
 * contact"; docs/case-format.md, /INTER/TYPE7).
 *
 * Radioss's TYPE7 pushes each secondary node out of the main segments with
 * a penalty spring. ricochet's bodies are rigid: the secondary nodes of one
 * body move with it, so the nodes of grnd_IDs are split by body and each
 * body's nodes become a segment surface of points (no segments) on it.
 * Each such surface meets the main surface through a TYPE6 contact built
 * here:
 *   - one way: the nodes against the main surface only (the contact's
 *     points are the nodes; TYPE6's second set, the main surface's nodes
 *     against the segments of the first, is dropped: it has none);
 *   - a linear load curve F = k P, k = Stfac (Istf 1), or (Istf 0, 1000)
 *     Stfac times the main shells' stiffness E t / 2, the mean over the
 *     main segments, within Stmin..Stmax (main_stiffness); the gap Gapmin
 *     (Igap 0), Tstart, Tstop, Inacti, sens_ID as TYPE6's;
 *   - the damping VISs of the critical damping of k and the two bodies'
 *     reduced mass, Visc = VISs 2 sqrt(k m*) (set by the compiler);
 *   - Coulomb friction Fric (TYPE6 Fric, stick stiffness k), or the
 *     /FRICTION card fric_ID.
 * Nodes on the main surface's own body are left out (a node never meets
 * the segments it is attached to, and on one rigid body they cannot move
 * against them). The contacts are named "/INTER/TYPE7/<id> (nodes of
 * /RBODY/<id>)" and carry the card's id.
 *
 * /INTER/TYPE24 and /INTER/TYPE25 make one two-way contact of their two
 * surfaces; /INTER/TYPE11 (each side a /LINE/SURF of one surface) and
 * /INTER/TYPE19 the same between two boxes (/SURF/BOX or closed box meshes
 * taken as their boxes, box_sides): TYPE11 the box pair's edge pairs alone
 * (the contact's edges_only), TYPE19 the whole box pair (docs/theory.md
 * 3.9).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_mesh.h"
#include "model/type7.h"

/* A shell element's nodes as a key: the distinct node ids ascending, 0
 * after them (a triangle), and the element's index. */
typedef struct { int n[4]; int e; } t7_key;

static void t7_key_of(const int *nodes, int nn, t7_key *k)
{
    int m = 0;
    for (int j = 0; j < 4; j++) k->n[j] = 0;
    for (int j = 0; j < nn && j < 4; j++) {
        int dup = nodes[j] == 0;
        for (int q = 0; q < m && !dup; q++) dup = k->n[q] == nodes[j];
        if (!dup) k->n[m++] = nodes[j];
    }
    for (int a = 1; a < m; a++) /* insertion sort of at most 4 */
        for (int b = a; b > 0 && k->n[b - 1] > k->n[b]; b--) {
            const int tmp = k->n[b];
            k->n[b] = k->n[b - 1];
            k->n[b - 1] = tmp;
        }
}

static int t7_key_cmp(const void *pa, const void *pb)
{
    const t7_key *a = pa, *b = pb;
    for (int j = 0; j < 4; j++)
        if (a->n[j] != b->n[j]) return (a->n[j] > b->n[j]) - (a->n[j] < b->n[j]);
    return 0;
}

/* The card whose stiffness is computed: its name, id, line 1 (the
 * messages' location), Stfac and the bounds Stmin, Stmax. */
typedef struct { const char *card; int id; rc_loc loc; double stfac, stmin, stmax; int istf; } t7_card;

/* Istf 2 to 5 (docs/theory.md 3.7): the main side's stiffness km and the
 * secondary side's ks combined: their mean, the larger, the smaller, or
 * the two springs in series. */
static double t7_combine(int istf, double km, double ks)
{
    switch (istf) {
    case 2: return 0.5 * (km + ks);
    case 3: return fmax(km, ks);
    case 4: return fmin(km, ks);
    default: return km * ks / (km + ks);
    }
}

/* k within Stmin..Stmax (0: no bound). */
static double t7_bounded(const t7_card *t, double k)
{
    if (t->stmin > 0) k = fmax(k, t->stmin);
    if (t->stmax > 0) k = fmin(k, t->stmax);
    return k;
}

/* A shell's thickness: the element's, else its part's /PROP/SHELL Thick;
 * 0 when neither is known. */
static double shell_thick(const rc_case *c, const rc_case_elem *el)
{
    if (el->thick > 0) return el->thick;
    const int p = rc_case_find_part(c, el->part_id);
    const int pi = p >= 0 ? rc_case_find_prop(c, c->part[p].prop_id) : -1;
    return pi >= 0 && c->mesh->prop[pi].kind == RC_PROP_SHELL ? c->mesh->prop[pi].thick : 0.0;
}

/* The shells of the mesh as keys, sorted (*nk of them; an owned array). */
static t7_key *shell_keys(const rc_case_mesh *ms, int *nk)
{
    const int ne = ms ? ms->nelem : 0;
    t7_key *keys = malloc(((size_t)ne + 1) * sizeof *keys);
    *nk = 0;
    if (!keys) return NULL;
    for (int e = 0; e < ne; e++) {
        const rc_case_elem *el = &ms->elem[e];
        if (el->kind != RC_ELEM_SHELL && el->kind != RC_ELEM_SH3N) continue;
        t7_key_of(el->nodes, el->nn, &keys[*nk]);
        keys[(*nk)++].e = e;
    }
    qsort(keys, (size_t)*nk, sizeof *keys, t7_key_cmp);
    return keys;
}

/* The shell (element index) on the nodes of a /SURF/SEG segment, or -1. */
static int seg_shell(const t7_key *keys, int nk, const int *seg4)
{
    t7_key q;
    t7_key_of(seg4, 4, &q);
    const t7_key *f = nk ? bsearch(&q, keys, (size_t)nk, sizeof *keys, t7_key_cmp) : NULL;
    return f ? f->e : -1;
}

/* Istf 0 (docs/theory.md 3.7): Stfac times the stiffness Radioss gives a
 * main shell segment, E t / 2 (E the Young's modulus of its part's /MAT,
 * t its thickness), the mean over the main segments, within Stmin..Stmax.
 * The main segments must be shells: the shells of a /SURF/PART, or the
 * shells with the nodes of each /SURF/SEG segment; RC_EINPUT otherwise
 * (solid faces, B A^2 / (2 V), are not supported yet). */
static rc_status shells_stiffness(const rc_case *c, const t7_card *t, int surf_id, double *sum_out, int *n_out,
                                  rc_error *err)
{
    const rc_case_surf *cs = &c->surf[rc_case_find_surf(c, surf_id)];
    const rc_case_mesh *ms = c->mesh;
    const int ne = ms ? ms->nelem : 0;
    if (cs->kind != RC_CASE_SURF_SEG && cs->kind != RC_CASE_SURF_PART)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s/%d, field Istf: Istf %d takes the stiffness from the main surface's "
                           "shell elements; /SURF/%s/%d has none: expected Istf 1 with Stfac the stiffness [N/m]",
                 RC_LOC(t->loc), t->card, t->id, t->istf, rc_case_surf_kind_name(cs->kind), surf_id);
    t7_key *keys = malloc(((size_t)ne + 1) * sizeof *keys);
    if (!keys) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_status st = RC_OK;
    int nk = 0, nsh = 0;
    double sum = 0.0;
    /* the shells, as keys (a /SURF/SEG's segments are looked up among them) */
    for (int e = 0; e < ne; e++) {
        const rc_case_elem *el = &ms->elem[e];
        if (el->kind != RC_ELEM_SHELL && el->kind != RC_ELEM_SH3N) continue;
        t7_key_of(el->nodes, el->nn, &keys[nk]);
        keys[nk++].e = e;
    }
    qsort(keys, (size_t)nk, sizeof *keys, t7_key_cmp);
    const int nseg = cs->kind == RC_CASE_SURF_SEG ? cs->nseg : ne;
    for (int j = 0; j < nseg && !st; j++) {
        int e = j;
        if (cs->kind == RC_CASE_SURF_SEG) {
            t7_key q;
            t7_key_of(cs->seg + 4 * j, 4, &q);
            const t7_key *f = nk ? bsearch(&q, keys, (size_t)nk, sizeof *keys, t7_key_cmp) : NULL;
            if (!f) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card %s/%d, field Istf: Istf %d takes the stiffness from the main "
                                      "segments' shell elements; segment %d of /SURF/SEG/%d (%s:%d) is on no /SHELL "
                                      "or /SH3N (a solid's face, B A^2 / (2 V): not supported yet): expected Istf 1 "
                                      "with Stfac the stiffness [N/m]",
                            RC_LOC(t->loc), t->card, t->id, t->istf, cs->seg_id[j], surf_id, RC_LOC(cs->seg_loc[j]));
                break;
            }
            e = f->e;
        } else {
            int in = 0;
            for (int p = 0; p < cs->npart && !in; p++) in = cs->part[p] == ms->elem[e].part_id;
            if (!in) continue;
            if (ms->elem[e].kind != RC_ELEM_SHELL && ms->elem[e].kind != RC_ELEM_SH3N) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card %s/%d, field Istf: Istf %d on the faces of the solid elements "
                                      "of /SURF/PART/%d (element %d of part %d; B A^2 / (2 V)) is not supported yet: "
                                      "expected Istf 1 with Stfac the stiffness [N/m], or a main surface of shells",
                            RC_LOC(t->loc), t->card, t->id, t->istf, surf_id, ms->elem[e].id, ms->elem[e].part_id);
                break;
            }
        }
        /* the shell's E and thickness */
        const rc_case_elem *el = &ms->elem[e];
        const int p = rc_case_find_part(c, el->part_id);
        const int mi = p >= 0 ? rc_case_find_mat(c, c->part[p].mat_id) : -1;
        const int pi = p >= 0 ? rc_case_find_prop(c, c->part[p].prop_id) : -1;
        if (mi < 0 || !ms->mat[mi].has_e) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card %s/%d, field Istf: Istf %d takes the Young's modulus of the main "
                                  "shells' material; /PART/%d has %s: expected a /MAT/LAW1 (ELAST) or /MAT/LAW2 "
                                  "(PLAS_JOHNS) with E > 0 (line 2), or Istf 1 with Stfac the stiffness [N/m]",
                        RC_LOC(t->loc), t->card, t->id, t->istf, el->part_id,
                        mi < 0 ? "no /MAT" : "a /MAT whose Young's modulus ricochet does not read");
            break;
        }
        const double th = el->thick > 0 ? el->thick : pi >= 0 && ms->prop[pi].kind == RC_PROP_SHELL ? ms->prop[pi].thick : 0.0;
        if (!(th > 0)) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card %s/%d, field Istf: Istf %d needs the main shells' thickness; element "
                                  "%d of /PART/%d has none (element Thick or /PROP/SHELL Thick): expected a thickness "
                                  "> 0, or Istf 1 with Stfac the stiffness [N/m]",
                        RC_LOC(t->loc), t->card, t->id, t->istf, el->id, el->part_id);
            break;
        }
        sum += 0.5 * t->stfac * ms->mat[mi].e * th;
        nsh++;
    }
    free(keys);
    if (st) return st;
    if (nsh == 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s/%d, field Istf: Istf %d takes the stiffness from the main surface's "
                           "shell elements; /SURF/%s/%d has none: expected Istf 1 with Stfac the stiffness [N/m]",
                 RC_LOC(t->loc), t->card, t->id, t->istf, rc_case_surf_kind_name(cs->kind), surf_id);
    *sum_out += sum;
    *n_out += nsh;
    return RC_OK;
}

/* The main side of a TYPE7 (Istf 0, 2-5): the mean of Stfac E t / 2 over
 * the main segments, unbounded (*km); Istf 0 takes it within
 * Stmin..Stmax, Istf 2-5 combine it with the secondary side's first
 * (rc_type7_contacts). */
static rc_status main_stiffness(const rc_case *c, const rc_case_type7 *t7, double *km, rc_error *err)
{
    const t7_card t = {"/INTER/TYPE7", t7->id, t7->line_loc[0], t7->stfac, t7->stmin, t7->stmax, t7->istf};
    double sum = 0.0;
    int n = 0;
    rc_status st = shells_stiffness(c, &t, t7->surf_id, &sum, &n, err);
    if (st) return st;
    *km = sum / n;
    return RC_OK;
}

/* Istf 0 of a TYPE24 (docs/theory.md 3.8): each surface is the main one of
 * the other's nodes; the one law of the pair takes the mean over the
 * segments of both surfaces, within Stmin..Stmax. Istf 2-5: the mean over
 * each surface's segments, k1 and k2, combined (t7_combine), within
 * Stmin..Stmax. */
static rc_status pair_stiffness(const rc_case *c, const rc_case_type24 *t24, double *k, rc_error *err)
{
    const char *card = t24->type == 25 ? "/INTER/TYPE25" : t24->type == 11 ? "/INTER/TYPE11"
                     : t24->type == 19 ? "/INTER/TYPE19" : "/INTER/TYPE24";
    const t7_card t = {card, t24->id, t24->line_loc[0], t24->stfac, t24->stmin, t24->stmax, t24->istf};
    double sum1 = 0.0, sum2 = 0.0;
    int n1 = 0, n2 = 0;
    rc_status st = shells_stiffness(c, &t, t24->surf1, &sum1, &n1, err);
    if (!st) st = shells_stiffness(c, &t, t24->surf2, &sum2, &n2, err);
    if (st) return st;
    *k = t24->istf == 0 ? (sum1 + sum2) / (n1 + n2) : t7_combine(t24->istf, sum1 / n1, sum2 / n2);
    *k = t7_bounded(&t, *k);
    return RC_OK;
}

/* Igap 1, 2 of a TYPE7 (docs/theory.md 3.7): the main side's part of the
 * variable gap, half the thickness of each main segment's shell (0 for a
 * segment on no shell, a solid's face, a plane or a box: Radioss's gap of
 * those), *gm; RC_EINPUT when it differs from segment to segment (a gap
 * that varies along the surface). */
static rc_status main_half_thick(const rc_case *c, const rc_case_type7 *t7, double *gm, rc_error *err)
{
    const rc_case_surf *cs = &c->surf[rc_case_find_surf(c, t7->surf_id)];
    const rc_case_mesh *ms = c->mesh;
    *gm = 0.0;
    if (!ms || (cs->kind != RC_CASE_SURF_SEG && cs->kind != RC_CASE_SURF_PART)) return RC_OK;
    int nk = 0;
    t7_key *keys = shell_keys(ms, &nk);
    if (!keys) RC_RAISE(err, RC_ENOMEM, "out of memory");
    const int nseg = cs->kind == RC_CASE_SURF_SEG ? cs->nseg : ms->nelem;
    int first = 1, seg0 = 0;
    double g0 = 0.0;
    rc_status st = RC_OK;
    for (int j = 0; j < nseg && !st; j++) {
        double g = 0.0;
        int sid = 0;
        if (cs->kind == RC_CASE_SURF_SEG) {
            const int e = seg_shell(keys, nk, cs->seg + 4 * j);
            g = e >= 0 ? 0.5 * shell_thick(c, &ms->elem[e]) : 0.0;
            sid = cs->seg_id[j];
        } else {
            int in = 0;
            for (int p = 0; p < cs->npart && !in; p++) in = cs->part[p] == ms->elem[j].part_id;
            if (!in) continue;
            const int sh = ms->elem[j].kind == RC_ELEM_SHELL || ms->elem[j].kind == RC_ELEM_SH3N;
            g = sh ? 0.5 * shell_thick(c, &ms->elem[j]) : 0.0;
            sid = ms->elem[j].id;
        }
        if (first) {
            g0 = g;
            seg0 = sid;
            first = 0;
        } else if (fabs(g - g0) > 1e-9 * fmax(g, g0)) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card /INTER/TYPE7/%d, field Igap: Igap %d takes the main side's gap from half the "
                                  "thickness of each main segment's shell; /SURF/%s/%d has %s %d of half thickness "
                                  "%.6g m and %s %d of %.6g m: a gap that varies along the main surface is not "
                                  "supported yet (one gap per contact of a rigid body); expected main shells of one "
                                  "thickness, or Igap 0 with the gap Gapmin",
                        RC_LOC(t7->line_loc[0]), t7->id, t7->igap, rc_case_surf_kind_name(cs->kind), t7->surf_id,
                        cs->kind == RC_CASE_SURF_SEG ? "segment" : "element", seg0, g0,
                        cs->kind == RC_CASE_SURF_SEG ? "segment" : "element", sid, g);
        }
    }
    free(keys);
    *gm = g0;
    return st;
}

/* The shells on each of n secondary nodes ids[] (Istf 2-5, Igap 1, 2):
 * tn[q] the largest thickness of the shells on node q, kn[q] the largest
 * Stfac E t / 2 of them (kn may be NULL: thicknesses only); both 0 for a
 * node on no shell. need_e: a shell on one of the nodes without a Young's
 * modulus or a thickness is RC_EINPUT (the message names the card t). */
static rc_status node_shells(const rc_case *c, const t7_card *t, const int *ids, int n, double *tn, double *kn,
                             rc_error *err)
{
    const rc_case_mesh *ms = c->mesh;
    for (int q = 0; q < n; q++) {
        tn[q] = 0.0;
        if (kn) kn[q] = 0.0;
    }
    for (int e = 0; ms && e < ms->nelem; e++) {
        const rc_case_elem *el = &ms->elem[e];
        if (el->kind != RC_ELEM_SHELL && el->kind != RC_ELEM_SH3N) continue;
        for (int j = 0; j < el->nn && j < 4; j++) {
            if (el->nodes[j] == 0) continue;
            for (int q = 0; q < n; q++) {
                if (ids[q] != el->nodes[j]) continue;
                const double th = shell_thick(c, el);
                if (kn) {
                    const int p = rc_case_find_part(c, el->part_id);
                    const int mi = p >= 0 ? rc_case_find_mat(c, c->part[p].mat_id) : -1;
                    if (mi < 0 || !ms->mat[mi].has_e || !(th > 0))
                        RC_RAISE(err, RC_EINPUT,
                                 RC_LOCFMT "card %s/%d, field Istf: Istf %d takes the secondary side's stiffness from "
                                           "the shells on the secondary nodes; element %d of /PART/%d on node %d has "
                                           "%s: expected a /MAT/LAW1 (ELAST) or /MAT/LAW2 (PLAS_JOHNS) with E > 0 and "
                                           "a thickness > 0 (element Thick or /PROP/SHELL Thick), or Istf 0, 1000 "
                                           "(the main side's stiffness alone) or 1 (Stfac the stiffness [N/m])",
                                 RC_LOC(t->loc), t->card, t->id, t->istf, el->id, el->part_id, ids[q],
                                 mi < 0 ? "no /MAT" : !ms->mat[mi].has_e ? "a /MAT whose Young's modulus ricochet "
                                                                           "does not read"
                                                                         : "no thickness");
                    kn[q] = fmax(kn[q], 0.5 * t->stfac * ms->mat[mi].e * th);
                }
                tn[q] = fmax(tn[q], th);
            }
        }
    }
    return RC_OK;
}

/* The stiffness and gap of the contact of TYPE7 card i whose secondary
 * nodes are ids[0..n) (one body's): Istf 0, 1 the card's k (x->k[i]); 2-5
 * the main side's x->km[i] combined with the mean of the nodes' Stfac E t
 * / 2 (node_shells; a node on no shell is RC_EINPUT), within Stmin..Stmax.
 * The gap: Gapmin (Igap 0), or the variable gap gm + gs (gs half the
 * largest thickness of a node's shells, one for all the nodes), Igap 2
 * scaled by Fscalegap and at most Gapmax, at least Gapmin. */
static rc_status contact_law(const rc_case *c, const rc_type7_case *x, int i, const int *ids, int n, double *k,
                             double *gap, rc_error *err)
{
    const rc_case_type7 *t7 = &c->type7[i];
    const t7_card t = {"/INTER/TYPE7", t7->id, t7->line_loc[0], t7->stfac, t7->stmin, t7->stmax, t7->istf};
    const rc_case_grnod *gr = &c->grnod[rc_case_find_grnod(c, t7->grnod_id)];
    *k = x->k[i];
    *gap = t7->gapmin;
    const int wk = t7->istf >= 2, wg = t7->igap == 1 || t7->igap == 2;
    if (!wk && !wg) return RC_OK;
    double *tn = malloc(2 * ((size_t)n + 1) * sizeof *tn);
    if (!tn) RC_RAISE(err, RC_ENOMEM, "out of memory");
    double *kn = tn + n + 1;
    rc_status st = node_shells(c, &t, ids, n, tn, wk ? kn : NULL, err);
    if (!st && wk) {
        double ks = 0.0;
        for (int q = 0; q < n && !st; q++) {
            if (!(kn[q] > 0))
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /INTER/TYPE7/%d, field Istf: Istf %d combines the main side's stiffness "
                                      "with the secondary nodes' (Stfac E t / 2 of the shells on each node); node %d "
                                      "of /GRNOD %d is on no /SHELL or /SH3N: expected secondary nodes on shells, or "
                                      "Istf 0, 1000 (the main side's stiffness alone) or 1 (Stfac the stiffness [N/m])",
                            RC_LOC(t7->line_loc[0]), t7->id, t7->istf, ids[q], gr->id);
            ks += kn[q] / n;
        }
        if (!st) *k = t7_bounded(&t, t7_combine(t7->istf, x->km[i], ks));
    }
    if (!st && wg) {
        for (int q = 1; q < n && !st; q++)
            if (fabs(tn[q] - tn[0]) > 1e-9 * fmax(tn[q], tn[0]))
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /INTER/TYPE7/%d, field Igap: Igap %d takes each secondary node's gap from "
                                      "half the largest thickness of its shells (0 on no shell); node %d of one body "
                                      "has %.6g m and node %d %.6g m: a gap that varies from node to node of a rigid "
                                      "body is not supported yet (one gap per contact); expected shells of one "
                                      "thickness on the body's secondary nodes, or Igap 0 with the gap Gapmin",
                            RC_LOC(t7->line_loc[0]), t7->id, t7->igap, ids[0], 0.5 * tn[0], ids[q], 0.5 * tn[q]);
        if (!st) {
            double g = x->gm[i] + 0.5 * tn[0];
            if (t7->igap == 2) {
                g *= t7->fscalegap;
                if (t7->gapmax > 0) g = fmin(g, t7->gapmax);
            }
            *gap = fmax(t7->gapmin, g);
        }
    }
    free(tn);
    return st;
}

/* A closed box mesh (TYPE25 Iedge, docs/theory.md 3.8): a /SURF/SEG of 6
 * quadrilaterals on 8 nodes of one body (or of none) that are the corners
 * of a rectangular box, one face each, as the analytic /SURF/BOX *out
 * (centre, half-sizes, axes, body); 0 when cs is not such a mesh. */
static int mesh_box(const rc_case *c, const rc_case_surf *cs, rc_case_surf *out)
{
    if (cs->kind != RC_CASE_SURF_SEG || cs->nseg != 6) return 0;
    int ids[8], n = 0;
    for (int j = 0; j < 6; j++)
        for (int q = 0; q < 4; q++) {
            const int id = cs->seg[4 * j + q];
            if (id == 0) return 0; /* a triangle */
            int dup = 0;
            for (int r = 0; r < n && !dup; r++) dup = ids[r] == id;
            if (!dup) {
                if (n == 8) return 0;
                ids[n++] = id;
            }
        }
    if (n != 8) return 0;
    double x[8][3], g[3] = {0, 0, 0};
    const int b0 = rc_case_body_of_node(c, ids[0]);
    for (int r = 0; r < 8; r++) {
        const int k = rc_case_find_node(c, ids[r]);
        if (k < 0 || rc_case_body_of_node(c, ids[r]) != b0) return 0;
        for (int d = 0; d < 3; d++) {
            x[r][d] = c->node[k].x[d];
            g[d] += x[r][d] / 8.0;
        }
    }
    /* the three nodes next to node 0 along the quadrilaterals' sides span
     * its three edges */
    int near[3], nn = 0;
    for (int j = 0; j < 6; j++)
        for (int k = 0; k < 4; k++) {
            if (cs->seg[4 * j + k] != ids[0]) continue;
            const int nb2[2] = {cs->seg[4 * j + (k + 1) % 4], cs->seg[4 * j + (k + 3) % 4]};
            for (int q = 0; q < 2; q++) {
                int r = 0, dup = 0;
                while (ids[r] != nb2[q]) r++;
                for (int z = 0; z < nn && !dup; z++) dup = near[z] == r;
                if (dup) continue;
                if (nn == 3) return 0;
                near[nn++] = r;
            }
        }
    if (nn != 3) return 0;
    double e[3][3], len[3], size = 0;
    for (int q = 0; q < 3; q++) {
        len[q] = 0;
        for (int d = 0; d < 3; d++) {
            e[q][d] = x[near[q]][d] - x[0][d];
            len[q] += e[q][d] * e[q][d];
        }
        len[q] = sqrt(len[q]);
        if (!(len[q] > 0)) return 0;
        for (int d = 0; d < 3; d++) e[q][d] /= len[q];
        size = fmax(size, len[q]);
    }
    const double tol = 1e-9;
    for (int a = 0; a < 3; a++)
        for (int bq = a + 1; bq < 3; bq++)
            if (fabs(e[a][0] * e[bq][0] + e[a][1] * e[bq][1] + e[a][2] * e[bq][2]) > tol) return 0;
    /* w = u x v: e[2] turned to it */
    const double w[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                         e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    const double sw = w[0] * e[2][0] + w[1] * e[2][1] + w[2] * e[2][2] < 0 ? -1.0 : 1.0;
    for (int d = 0; d < 3; d++) e[2][d] = sw * e[2][d];
    /* every node a corner: +- each half-size along each axis; each
     * quadrilateral on one face (its nodes on one side along one axis) */
    int sign[8][3];
    for (int r = 0; r < 8; r++)
        for (int q = 0; q < 3; q++) {
            const double t = (x[r][0] - g[0]) * e[q][0] + (x[r][1] - g[1]) * e[q][1] + (x[r][2] - g[2]) * e[q][2];
            if (fabs(fabs(t) - 0.5 * len[q]) > tol * size) return 0;
            sign[r][q] = t > 0 ? 1 : -1;
        }
    int faces = 0;
    for (int j = 0; j < 6; j++) {
        int face = -1;
        for (int q = 0; q < 3 && face < 0; q++) {
            int same = 1, s0 = 0;
            for (int k = 0; k < 4; k++) {
                int r = 0;
                while (ids[r] != cs->seg[4 * j + k]) r++;
                if (k == 0) s0 = sign[r][q];
                same &= sign[r][q] == s0;
            }
            if (same) face = 2 * q + (s0 > 0);
        }
        if (face < 0 || (faces & (1 << face))) return 0;
        faces |= 1 << face;
    }
    *out = (rc_case_surf){.id = cs->id, .kind = RC_CASE_SURF_BOX, .loc = cs->loc, .rbody_loc = cs->loc,
                          .rbody_id = b0 >= 0 ? c->rbody[b0].id : 0};
    snprintf(out->title, sizeof out->title, "the box of /SURF/SEG/%d", cs->id);
    for (int d = 0; d < 3; d++) {
        out->c[d] = g[d];
        out->abc[d] = 0.5 * len[d];
        out->axis[d] = e[0][d];
        out->axis2[d] = e[1][d];
    }
    return 1;
}

/* A /SURF/PART that is a closed box (docs/theory.md 3.9): its parts hold
 * one /BRICK on 8 distinct nodes, or six 4-node /SHELL, whose faces (the
 * brick's six, node k + 4 above node k) make a closed box mesh for
 * mesh_box; *out as mesh_box's. 0 otherwise. */
static int part_box(const rc_case *c, const rc_case_surf *cs, rc_case_surf *out)
{
    if (cs->kind != RC_CASE_SURF_PART || !c->mesh) return 0;
    static const int hex_face[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    int seg[24], nq = 0, nbrick = 0, nother = 0;
    for (int e = 0; e < c->mesh->nelem; e++) {
        const rc_case_elem *el = &c->mesh->elem[e];
        int in = 0;
        for (int k = 0; k < cs->npart && !in; k++) in = cs->part[k] == el->part_id;
        if (!in) continue;
        if (el->kind == RC_ELEM_BRICK && nbrick == 0 && nq == 0) {
            for (int f = 0; f < 6; f++)
                for (int q = 0; q < 4; q++) seg[4 * f + q] = el->nodes[hex_face[f][q]];
            nq = 6;
            nbrick = 1;
        } else if (el->kind == RC_ELEM_SHELL && !nbrick && nq < 6 && el->nodes[3] != 0 && el->nodes[3] != el->nodes[2]) {
            for (int q = 0; q < 4; q++) seg[4 * nq + q] = el->nodes[q];
            nq++;
        } else {
            nother++;
        }
    }
    if (nother || nq != 6) return 0;
    const rc_case_surf tmp = {.id = cs->id, .kind = RC_CASE_SURF_SEG, .loc = cs->loc, .nseg = 6, .seg = seg};
    if (!mesh_box(c, &tmp, out)) return 0;
    snprintf(out->title, sizeof out->title, "the box of /SURF/PART/%d", cs->id);
    return 1;
}

/* A closed box mesh of either kind: a /SURF/SEG (mesh_box) or a /SURF/PART
 * (part_box). */
static int closed_box(const rc_case *c, const rc_case_surf *cs, rc_case_surf *out)
{
    return mesh_box(c, cs, out) || part_box(c, cs, out);
}

/* The two sides of a TYPE11 (its /LINE/SURF lines, each of one surface)
 * or a TYPE19 (its surfaces): each a /SURF/BOX or a closed box mesh
 * (mesh_box: its box in bx[q]); side[q] the surface id. TYPE11's edges are
 * then the box pair's edge pairs alone, TYPE19's its corners and edges
 * (docs/theory.md 3.9); any other surface is refused. */
static rc_status box_sides(const rc_case *c, const rc_case_type24 *t, rc_case_surf *bx, int *side, rc_error *err)
{
    static const char *const lname[2] = {"line_IDs", "line_IDm"}, *const sname[2] = {"surf_IDs", "surf_IDm"};
    for (int q = 0; q < 2; q++) {
        const char *field = t->type == 11 ? lname[q] : sname[q];
        int sid = q ? t->surf2 : t->surf1;
        if (t->type == 11) {
            const int lid = q ? t->line2 : t->line1;
            const rc_case_line *l = NULL;
            for (int k = 0; k < c->nline && !l; k++)
                if (c->line[k].id == lid) l = &c->line[k];
            if (!l)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /INTER/TYPE11/%d, field %s: expected the id of a /LINE/SURF, got %d (no such line)",
                         RC_LOC(t->line_loc[0]), t->id, field, lid);
            if (l->n != 1)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /INTER/TYPE11/%d, field %s: /LINE/SURF/%d lists %d surfaces: not supported yet "
                                   "(ricochet's edges are those of one box); expected a line of one surface, a "
                                   "/SURF/BOX or a closed box mesh",
                         RC_LOC(t->line_loc[0]), t->id, field, lid, l->n);
            sid = l->surf[0];
            if (rc_case_find_surf(c, sid) < 0)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /LINE/SURF/%d, field surf_ID: expected the id of a /SURF, got %d (no such "
                                   "surface); the line is %s of /INTER/TYPE11/%d at %s:%d",
                         RC_LOC(rc_loc_at(l->surf_loc, 0, l->loc)), lid, sid, field, t->id, RC_LOC(t->line_loc[0]));
        }
        const int s = rc_case_find_surf(c, sid);
        if (s < 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /INTER/TYPE19/%d, field %s: expected the id of a /SURF, got %d (no such surface)",
                     RC_LOC(t->line_loc[0]), t->id, field, sid);
        const rc_case_surf *cs = &c->surf[s];
        side[q] = sid;
        if (cs->kind == RC_CASE_SURF_BOX) continue;
        if (closed_box(c, cs, &bx[q])) continue;
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /INTER/TYPE%d/%d, field %s: /SURF/%s/%d is not supported yet: ricochet models "
                           "TYPE%d (%s) between two boxes only; expected a /SURF/BOX or a closed box mesh (a "
                           "/SURF/SEG of 6 quadrilaterals on the 8 corners of a rectangular box, or a /SURF/PART of "
                           "one such /BRICK or six such /SHELL, taken as that box)",
                 RC_LOC(t->line_loc[0]), t->type, t->id, field, rc_case_surf_kind_name(cs->kind), sid, t->type,
                 t->type == 11 ? "the edges of each against the edges of the other"
                               : "the nodes of each against the other's faces and the edges against the edges");
    }
    return RC_OK;
}

/* 1 when v is in the n ascending ints at a. */
static int t7_listed(const int *a, int n, int v)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        const int mid = lo + (hi - lo) / 2;
        if (a[mid] == v) return 1;
        if (a[mid] < v) lo = mid + 1;
        else hi = mid - 1;
    }
    return 0;
}

/* What drop leaves out of TYPE7 card i (0: nothing). */
static int t7_ndrop(const rc_t7_drop *drop, int i) { return drop && drop->n ? drop->n[i] : 0; }

/* Inacti 2 (docs/theory.md 3.7): the copy of card i's main /SURF/SEG
 * without the segments drop leaves out, as surface *out (id sid, arrays
 * owned by x: x->mseg[i], x->mloc[i]); its nseg 0 when none is left. */
static rc_status t7_main_copy(const rc_case *c, const rc_t7_drop *drop, rc_type7_case *x, int i, int sid,
                              rc_case_surf *out, rc_error *err)
{
    const rc_case_type7 *t = &c->type7[i];
    const rc_case_surf *cs = &c->surf[rc_case_find_surf(c, t->surf_id)];
    *out = *cs;
    out->id = sid;
    out->npoint = 0;
    out->point = NULL;
    snprintf(out->title, sizeof out->title, "/SURF/SEG/%d less the segments Inacti 2 of /INTER/TYPE7/%d leaves out",
             t->surf_id, t->id);
    x->mseg[i] = malloc(5 * ((size_t)cs->nseg + 1) * sizeof *x->mseg[i]);
    x->mloc[i] = malloc(((size_t)cs->nseg + 1) * sizeof *x->mloc[i]);
    if (!x->mseg[i] || !x->mloc[i]) RC_RAISE(err, RC_ENOMEM, "out of memory");
    int *seg = x->mseg[i], *ids = seg + 4 * cs->nseg, n = 0;
    for (int k = 0; k < cs->nseg; k++) {
        if (t7_listed(drop->ids[i], drop->n[i], k)) continue;
        memcpy(seg + 4 * n, cs->seg + 4 * k, 4 * sizeof *seg);
        ids[n] = cs->seg_id[k];
        x->mloc[i][n] = cs->seg_loc[k];
        n++;
    }
    /* the ids after the kept segments' nodes */
    memmove(seg + 4 * n, ids, (size_t)n * sizeof *seg);
    out->nseg = n;
    out->seg = seg;
    out->seg_id = seg + 4 * n;
    out->seg_loc = x->mloc[i];
    return RC_OK;
}

rc_status rc_type7_begin(const rc_case *c, const rc_t7_drop *drop, rc_type7_case *x, rc_error *err)
{
    memset(x, 0, sizeof *x);
    x->c = *c;
    if (c->ntype7 == 0 && c->ntype24 == 0) return RC_OK;
    rc_status st = RC_OK;
    /* the secondary nodes of each card, by body: count the point surfaces */
    int maxn = 0;
    for (int i = 0; i < c->ntype7; i++) {
        const rc_case_type7 *t = &c->type7[i];
        const int g = rc_case_find_grnod(c, t->grnod_id);
        if (g < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /INTER/TYPE7/%d, field grnd_IDs: expected the id of a /GRNOD, got %d (no such group)",
                     RC_LOC(t->line_loc[0]), t->id, t->grnod_id);
        const int s = rc_case_find_surf(c, t->surf_id);
        if (s < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /INTER/TYPE7/%d, field surf_IDm: expected the id of a /SURF, got %d (no such surface)",
                     RC_LOC(t->line_loc[0]), t->id, t->surf_id);
        const rc_case_surf_kind k = c->surf[s].kind;
        if (k != RC_CASE_SURF_SEG && k != RC_CASE_SURF_PART && k != RC_CASE_SURF_PLANE && k != RC_CASE_SURF_BOX) {
            rc_type7_end(x);
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /INTER/TYPE7/%d, field surf_IDm: the main surface /SURF/%s/%d: not supported yet "
                               "(nodes against a sphere or a cylinder); expected a segment surface (/SURF/SEG, "
                               "/SURF/PART), a plane or a box",
                     RC_LOC(t->line_loc[0]), t->id, rc_case_surf_kind_name(k), t->surf_id);
        }
        for (int j = 0; j < c->grnod[g].n; j++)
            if (rc_case_find_node(c, c->grnod[g].nodes[j]) < 0)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /GRNOD/NODE/%d, field node_ID: expected the id of a /NODE, got %d (no such node); "
                                   "the group is grnd_IDs of /INTER/TYPE7/%d at %s:%d",
                         RC_LOC(rc_loc_at(c->grnod[g].node_loc, j, c->grnod[g].loc)), t->grnod_id, c->grnod[g].nodes[j],
                         t->id, RC_LOC(t->line_loc[0]));
        maxn = c->grnod[g].n > maxn ? c->grnod[g].n : maxn;
    }
    /* the TYPE24 cards: two segment surfaces, their stiffness, fric_ID */
    x->k24 = calloc((size_t)c->ntype24 + 1, sizeof *x->k24);
    x->name24 = calloc((size_t)c->ntype24 + 1, sizeof *x->name24);
    x->bx = calloc(2 * (size_t)c->ntype24 + 1, sizeof *x->bx);
    x->side = calloc(2 * (size_t)c->ntype24 + 1, sizeof *x->side);
    x->t24 = calloc((size_t)c->ntype24 + 1, sizeof *x->t24);
    if (!x->k24 || !x->name24 || !x->bx || !x->side || !x->t24) {
        rc_type7_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int i = 0; i < c->ntype24 && !st; i++) {
        const rc_case_type24 *t = &c->type24[i];
        if (t->type == 11 || t->type == 19) { /* two boxes or closed box meshes: box_sides */
            st = box_sides(c, t, &x->bx[2 * i], &x->side[2 * i], err);
            for (int q = 0; q < 2 && !st; q++) x->nbx += x->bx[2 * i + q].kind == RC_CASE_SURF_BOX;
        }
        const int sid[2] = {t->type == 11 ? x->side[2 * i] : t->surf1, t->type == 11 ? x->side[2 * i + 1] : t->surf2};
        static const char *const fname[2] = {"surf_ID1", "surf_ID2"};
        int nbox = 0;
        for (int q = 0; q < 2 && !st && t->type != 11 && t->type != 19; q++) {
            const int s = rc_case_find_surf(c, sid[q]);
            if (s < 0) {
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /INTER/TYPE%d/%d, field %s: expected the id of a /SURF, got %d (no such surface)",
                            RC_LOC(t->line_loc[0]), t->type, t->id, fname[q], sid[q]);
                break;
            }
            const rc_case_surf_kind k = c->surf[s].kind;
            nbox += k == RC_CASE_SURF_BOX;
            if (k != RC_CASE_SURF_SEG && k != RC_CASE_SURF_PART && !(t->type == 25 && k == RC_CASE_SURF_BOX))
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /INTER/TYPE%d/%d, field %s: /SURF/%s/%d is not supported yet (TYPE%d "
                                      "puts the nodes of each surface against the segments of the other): expected "
                                      "a segment surface (/SURF/SEG, /SURF/PART)%s",
                            RC_LOC(t->line_loc[0]), t->type, t->id, fname[q], rc_case_surf_kind_name(k), sid[q], t->type,
                            t->type == 25 ? ", or two /SURF/BOX" : "");
        }
        /* TYPE25: two boxes meet corner to face and edge to edge (the box
         * pair, docs/theory.md 2.7), with or without Iedge; meshed
         * surfaces meet node to segment only, so Iedge is refused there */
        if (!st && t->type == 25 && nbox == 1)
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card /INTER/TYPE25/%d, field surf_ID2: a /SURF/BOX against a segment surface is "
                                  "not supported yet: expected two segment surfaces or two /SURF/BOX",
                        RC_LOC(t->line_loc[0]), t->id);
        /* Iedge on two closed box meshes: their analytic boxes (mesh_box),
         * appended below; other segment surfaces have no edge pairs */
        if (!st && t->type == 25 && t->iedge != 0 && nbox == 0) {
            const rc_case_surf *s1 = &c->surf[rc_case_find_surf(c, t->surf1)], *s2 = &c->surf[rc_case_find_surf(c, t->surf2)];
            if (closed_box(c, s1, &x->bx[2 * i]) && closed_box(c, s2, &x->bx[2 * i + 1]) &&
                x->bx[2 * i].rbody_id != x->bx[2 * i + 1].rbody_id)
                x->nbx += 2;
            else
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /INTER/TYPE25/%d, field Iedge: edge-to-edge contact of segment surfaces "
                                      "is not supported yet except between two closed box meshes of two bodies "
                                      "(a /SURF/SEG of 6 quadrilaterals on the 8 corners of a rectangular box, or a "
                                      "/SURF/PART of one such /BRICK or six such /SHELL, taken as that box); /SURF/%s/%d "
                                      "and /SURF/%s/%d are not both such meshes: "
                                      "expected Iedge 0 (nodes against segments only), two such meshes, or two "
                                      "/SURF/BOX",
                            RC_LOC(t->line_loc[0]), t->id, rc_case_surf_kind_name(s1->kind), t->surf1, rc_case_surf_kind_name(s2->kind),
                            t->surf2);
        }
        if (!st && t->fric_id > 0) {
            int found = 0;
            for (int f = 0; f < c->nfriction; f++) found |= c->friction[f].id == t->fric_id;
            if (!found)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /INTER/TYPE%d/%d, field fric_ID: expected the id of a /FRICTION, got %d (no such card)",
                            RC_LOC(t->line_loc[5]), t->type, t->id, t->fric_id);
        }
        x->k24[i] = t->stfac;
        if (!st && t->istf != 1) {
            rc_case_type24 ts = *t; /* TYPE11: its lines' surfaces */
            ts.surf1 = sid[0];
            ts.surf2 = sid[1];
            st = pair_stiffness(c, &ts, &x->k24[i], err);
        }
        snprintf(x->name24[i], sizeof x->name24[i], "/INTER/TYPE%d/%d", t->type, t->id);
    }
    if (st) {
        rc_type7_end(x);
        return st;
    }
    /* the stiffness of each card: Stfac (Istf 1), the main side's (Istf
     * 0, 2-5: x->km) within Stmin..Stmax (Istf 0); the main side's half
     * thickness of Igap 1, 2 (x->gm) */
    x->k = calloc((size_t)c->ntype7 + 1, sizeof *x->k);
    x->km = calloc((size_t)c->ntype7 + 1, sizeof *x->km);
    x->gm = calloc((size_t)c->ntype7 + 1, sizeof *x->gm);
    if (!x->k || !x->km || !x->gm) {
        rc_type7_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int i = 0; i < c->ntype7; i++) {
        const rc_case_type7 *t7 = &c->type7[i];
        const t7_card tc = {"/INTER/TYPE7", t7->id, t7->line_loc[0], t7->stfac, t7->stmin, t7->stmax, t7->istf};
        x->k[i] = t7->stfac;
        if (t7->istf != 1 && (st = main_stiffness(c, t7, &x->km[i], err))) {
            rc_type7_end(x);
            return st;
        }
        if (t7->istf == 0) x->k[i] = t7_bounded(&tc, x->km[i]);
        if ((t7->igap == 1 || t7->igap == 2) && (st = main_half_thick(c, t7, &x->gm[i], err))) {
            rc_type7_end(x);
            return st;
        }
    }
    const int nb = c->nrbody + 1; /* bucket nrbody: nodes of no body */
    int *cnt = calloc((size_t)nb, sizeof *cnt);
    if (!cnt) {
        rc_type7_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    int npts = 0;
    for (int i = 0; i < c->ntype7; i++) {
        const int g = rc_case_find_grnod(c, c->type7[i].grnod_id);
        memset(cnt, 0, (size_t)nb * sizeof *cnt);
        for (int j = 0; j < c->grnod[g].n; j++) {
            const int b = rc_case_body_of_node(c, c->grnod[g].nodes[j]);
            if (cnt[b >= 0 ? b : c->nrbody]++ == 0) npts++;
        }
    }
    /* Inacti 2: a copy of the main surface of each card that leaves
     * segments out */
    int nred = 0;
    for (int i = 0; i < c->ntype7; i++) nred += c->type7[i].inacti == 2 && t7_ndrop(drop, i) > 0;
    x->nt7 = c->ntype7;
    x->dropped = calloc((size_t)c->ntype7 + 1, sizeof *x->dropped);
    for (int i = 0; x->dropped && i < c->ntype7; i++) x->dropped[i] = t7_ndrop(drop, i);
    x->mainsurf = calloc((size_t)c->ntype7 + 1, sizeof *x->mainsurf);
    x->mseg = calloc((size_t)c->ntype7 + 1, sizeof *x->mseg);
    x->mloc = calloc((size_t)c->ntype7 + 1, sizeof *x->mloc);
    if (!x->dropped || !x->mainsurf || !x->mseg || !x->mloc) {
        free(cnt);
        rc_type7_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    x->nuser = c->nsurf;
    x->surf = calloc((size_t)(c->nsurf + npts + x->nbx + nred) + 1, sizeof *x->surf);
    x->funct = calloc((size_t)c->nfunct + 1, sizeof *x->funct);
    x->name = calloc((size_t)npts + 1, sizeof *x->name);
    x->pts_t7 = calloc((size_t)npts + 1, sizeof *x->pts_t7);
    x->pts_node = calloc((size_t)npts + 1, sizeof *x->pts_node);
    if (!x->surf || !x->funct || !x->name || !x->pts_t7 || !x->pts_node) {
        free(cnt);
        rc_type7_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    if (c->nsurf) memcpy(x->surf, c->surf, (size_t)c->nsurf * sizeof *x->surf);
    if (c->nfunct) memcpy(x->funct, c->funct, (size_t)c->nfunct * sizeof *x->funct);
    /* one point surface per card and body, its nodes in the group's order */
    for (int i = 0; i < c->ntype7 && !st; i++) {
        const rc_case_type7 *t = &c->type7[i];
        const rc_case_grnod *gr = &c->grnod[rc_case_find_grnod(c, t->grnod_id)];
        for (int b = -1; b < c->nrbody && !st; b++) {
            int np = 0;
            int *ids = malloc(((size_t)gr->n + 1) * sizeof *ids);
            if (!ids) {
                st = RC_SET(err, RC_ENOMEM, "out of memory");
                break;
            }
            for (int j = 0; j < gr->n; j++) {
                int dup = 0;
                if (rc_case_body_of_node(c, gr->nodes[j]) != b) continue;
                /* Inacti 1: the node penetrated the main surface at t = 0 */
                if (t->inacti == 1 && t7_ndrop(drop, i) > 0 && t7_listed(drop->ids[i], drop->n[i], gr->nodes[j]))
                    continue;
                for (int q = 0; q < np && !dup; q++) dup = ids[q] == gr->nodes[j];
                if (!dup) ids[np++] = gr->nodes[j];
            }
            if (np == 0) {
                free(ids);
                continue;
            }
            const int k = x->npts++;
            x->pts_node[k] = ids;
            x->pts_t7[k] = i;
            if (b >= 0)
                snprintf(x->name[k], sizeof x->name[k], "/INTER/TYPE7/%d (nodes of /RBODY/%d)", t->id, c->rbody[b].id);
            else
                snprintf(x->name[k], sizeof x->name[k], "/INTER/TYPE7/%d (nodes of no body)", t->id);
            x->surf[x->nuser + k] = (rc_case_surf){.id = RC_TYPE7_SURF_ID0 - k, .kind = RC_CASE_SURF_SEG, .loc = t->line_loc[0],
                                                   .rbody_loc = t->line_loc[0], .npoint = np, .point = ids};
        }
    }
    free(cnt);
    (void)maxn;
    if (st) {
        rc_type7_end(x);
        return st;
    }
    /* the load curve y = x, scaled per contact by the scene's size */
    x->fx[1] = x->fy[1] = 1.0;
    x->funct[c->nfunct] = (rc_case_funct){.id = RC_TYPE7_FUNCT_ID, .npts = 2, .x = x->fx, .y = x->fy, .loc = c->end};
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int n = 0; n < c->nnode; n++)
        for (int k = 0; k < 3; k++) {
            lo[k] = n == 0 || c->node[n].x[k] < lo[k] ? c->node[n].x[k] : lo[k];
            hi[k] = n == 0 || c->node[n].x[k] > hi[k] ? c->node[n].x[k] : hi[k];
        }
    x->len = fmax(fmax(hi[0] - lo[0], hi[1] - lo[1]), hi[2] - lo[2]);
    if (!(x->len > 0)) x->len = 1.0;
    /* the boxes of TYPE25's closed box meshes, after the point surfaces
     * (ids below RC_TYPE7_SURF_ID0 as theirs: no surface of the body's own
     * for the walls); the copy's TYPE24/25 cards name them */
    int nbs = 0;
    if (c->ntype24) memcpy(x->t24, c->type24, (size_t)c->ntype24 * sizeof *x->t24);
    for (int i = 0; i < c->ntype24; i++) {
        if (c->type24[i].type == 11) { /* the surfaces of its lines */
            x->t24[i].surf1 = x->side[2 * i];
            x->t24[i].surf2 = x->side[2 * i + 1];
        }
        for (int q = 0; q < 2; q++) {
            if (x->bx[2 * i + q].kind != RC_CASE_SURF_BOX) continue;
            rc_case_surf *bs = &x->surf[x->nuser + x->npts + nbs];
            *bs = x->bx[2 * i + q];
            bs->id = RC_TYPE7_SURF_ID0 - (x->npts + nbs);
            if (q == 0) x->t24[i].surf1 = bs->id;
            else x->t24[i].surf2 = bs->id;
            nbs++;
        }
    }
    /* Inacti 2: the main surfaces without the segments left out, after
     * the boxes (ids below RC_TYPE7_SURF_ID0: no walls' surfaces either) */
    int nms = 0;
    for (int i = 0; i < c->ntype7 && !st; i++) {
        x->mainsurf[i] = c->type7[i].surf_id;
        if (c->type7[i].inacti != 2 || t7_ndrop(drop, i) == 0) continue;
        rc_case_surf *ms = &x->surf[x->nuser + x->npts + nbs + nms];
        st = t7_main_copy(c, drop, x, i, RC_TYPE7_SURF_ID0 - (x->npts + nbs + nms), ms, err);
        if (st) break;
        if (ms->nseg == 0) { /* every main segment left out: no contact */
            x->mainsurf[i] = 0;
            continue;
        }
        x->mainsurf[i] = ms->id;
        nms++;
    }
    if (st) {
        rc_type7_end(x);
        return st;
    }
    x->c.type24 = x->t24;
    x->c.surf = x->surf;
    x->c.nsurf = x->nuser + x->npts + nbs + nms;
    x->c.funct = x->funct;
    x->c.nfunct = c->nfunct + 1;
    /* the copy's own index (case/lookup.c) */
    x->c.index = NULL;
    st = rc_case_index_build(&x->c, err);
    if (st) rc_type7_end(x);
    return st;
}

rc_status rc_type7_contacts(rc_type7_case *x, rc_case *c, const rc_model *m, rc_error *err)
{
    if (x->npts == 0 && c->ntype24 == 0) return RC_OK;
    x->type6 = calloc((size_t)(c->ntype6 + x->npts + c->ntype24) + 1, sizeof *x->type6);
    if (!x->type6) RC_RAISE(err, RC_ENOMEM, "out of memory");
    if (c->ntype6) memcpy(x->type6, c->type6, (size_t)c->ntype6 * sizeof *x->type6);
    int n = c->ntype6;
    for (int i = 0; i < c->ntype7; i++) {
        const rc_case_type7 *t = &c->type7[i];
        /* Inacti 1, 2 that left every node or every main segment out: no
         * contact (engine/analyses/prepare.c says so) */
        const int left_out = t->inacti == 1 || t->inacti == 2 ? x->dropped[i] : 0;
        if (x->mainsurf[i] == 0) continue;
        const int sm = rc_case_find_surf(c, x->mainsurf[i]), bm = m->surf_body[sm];
        int made = 0;
        for (int k = 0; k < x->npts; k++) {
            if (x->pts_t7[k] != i) continue;
            const int s = x->nuser + k;
            if (m->surf_body[s] == bm) continue; /* the main surface's own body */
            double kc = 0.0, gap = 0.0;
            rc_status st = contact_law(c, x, i, c->surf[s].point, c->surf[s].npoint, &kc, &gap, err);
            if (st) return st;
            rc_case_type6 *t6 = &x->type6[n++];
            *t6 = (rc_case_type6){.id = t->id, .surf1 = c->surf[s].id, .surf2 = x->mainsurf[i], .fric = t->fric,
                                  .gap = gap, .tstart = t->tstart, .tstop = t->tstop,
                                  .inacti = t->inacti == 6 || t->inacti == 5 ? 5 : 0, /* 6 read as 5; 1, 2 left
                                                                           points out above (theory 3.7) */
                                  .ascalef = 1.0, .ascalev = 1.0, .fct_ld = RC_TYPE7_FUNCT_ID, .ascalex = x->len,
                                  .fscaleld = kc * x->len, .fscaleul = 1.0, .fscalev = 1.0, .loc = t->loc,
                                  .sensor_id = t->sensor_id, .name = x->name[k], .oneway = 1, .vis_crit = t->viss,
                                  .fric_id = t->fric_id};
            /* the TYPE6 lines of the messages: surfaces and sensor; Fric Gap
             * Tstart Tstop; friction; the law (Stfac) twice; the damping */
            t6->line_loc[0] = t->line_loc[0];
            t6->line_loc[1] = t6->line_loc[3] = t6->line_loc[4] = t->line_loc[3];
            t6->line_loc[2] = t->line_loc[5];
            t6->line_loc[5] = t->line_loc[4];
            made++;
        }
        if (made == 0 && !left_out)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /INTER/TYPE7/%d, field grnd_IDs: every node of /GRNOD %d belongs to the body of "
                               "the main surface %d: expected secondary nodes of another body (or of none, fixed)",
                     RC_LOC(t->line_loc[0]), t->id, t->grnod_id, t->surf_id);
    }
    /* TYPE24, TYPE25: one two-way contact of the two surfaces (the nodes of
     * each against the segments of the other; two boxes: corners against
     * faces and edges against edges), zero gap */
    for (int i = 0; i < c->ntype24; i++) {
        const rc_case_type24 *t = &c->type24[i];
        const int s1 = rc_case_find_surf(c, t->surf1), s2 = rc_case_find_surf(c, t->surf2);
        if (m->surf_body[s1] == m->surf_body[s2])
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /INTER/TYPE%d/%d, field surf_ID2: surfaces %d and %d are on one body%s: expected "
                               "surfaces of two bodies (a rigid body does not meet itself)",
                     RC_LOC(t->line_loc[0]), t->type, t->id, t->surf1, t->surf2, m->surf_body[s1] < 0 ? " (none, fixed)" : "");
        rc_case_type6 *t6 = &x->type6[n++];
        *t6 = (rc_case_type6){.id = t->id, .surf1 = t->surf1, .surf2 = t->surf2, .fric = t->fric, .gap = t->gapmin,
                              .tstart = t->tstart, .tstop = t->tstop, .inacti = t->inacti == 6 ? 5 : t->inacti,
                              .ascalef = 1.0,
                              .ascalev = 1.0, .fct_ld = RC_TYPE7_FUNCT_ID, .ascalex = x->len,
                              .fscaleld = x->k24[i] * x->len, .fscaleul = 1.0, .fscalev = 1.0, .loc = t->loc,
                              .sensor_id = t->sensor_id, .name = x->name24[i], .oneway = 0, .vis_crit = t->viss,
                              .fric_id = t->fric_id,
                              .edges_only = t->type == 11 ? 1 : t->type == 19 && t->iedge == 1 ? 2 : 0};
        t6->line_loc[0] = t->line_loc[0];
        t6->line_loc[1] = t6->line_loc[3] = t6->line_loc[4] = t->line_loc[3];
        t6->line_loc[2] = t->line_loc[5];
        t6->line_loc[5] = t->line_loc[4];
    }
    c->type6 = x->type6;
    c->ntype6 = n;
    return RC_OK;
}

void rc_type7_end(rc_type7_case *x)
{
    if (x->surf) rc_case_index_free(x->c.index); /* the copy's own (rc_type7_begin) */
    free(x->surf);
    free(x->funct);
    free(x->type6);
    free(x->name);
    for (int k = 0; x->pts_node && k < x->npts; k++) free(x->pts_node[k]);
    free(x->pts_node);
    free(x->pts_t7);
    free(x->k);
    free(x->km);
    free(x->gm);
    free(x->k24);
    free(x->name24);
    free(x->bx);
    free(x->side);
    free(x->t24);
    for (int i = 0; x->mseg && i < x->nt7; i++) {
        free(x->mseg[i]);
        free(x->mloc[i]);
    }
    free(x->mseg);
    free(x->mloc);
    free(x->mainsurf);
    free(x->dropped);
    memset(x, 0, sizeof *x);
}
