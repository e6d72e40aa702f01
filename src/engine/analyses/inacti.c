/*
 * /INTER/TYPE7 Inacti 1 and 2 (docs/theory.md 3.7, "Inacti 1 and 2"):
 * the secondary nodes that penetrate the main surface at t = 0, or the
 * main segments they penetrate, left out of the card's contacts for the
 * whole run.
 *
 * A rigid body's initial pose is the deck's (its nodes' coordinates), so
 * the penetrating points are known before anything runs: a first build of
 * the model evaluates every contact point of those cards at the initial
 * state through the contact's own geometry (rc_point_distance: the node
 * against the plane, the nearest face of a box, or the main segment it
 * projects onto within the search depth), a node being penetrating when
 * its signed distance is below the contact's gap (less a touch band of
 * roundings). When any is found, the model is built again with them left
 * out (rc_model_build_drop, model/type7.c), and a notice names the card,
 * the count and the ids.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/model.h"
#include "model/segsurf.h"
#include "engine/assembly/assembly.h"
#include "engine/assembly/bounds.h"
#include "engine/analyses/analyses.h"

/* A node within RC_INACTI_TOUCH_REL of the largest body size of the gap
 * is touching, not penetrating (the roundings of the coordinates) [-]. */
#define RC_INACTI_TOUCH_REL 1e-9
/* Ids listed in a notice; more are counted [-]. */
#define RC_INACTI_LIST 20

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Sort the n ints at a and drop repeats; returns the count left. */
static int sort_unique(int *a, int n)
{
    if (n == 0) return 0;
    qsort(a, (size_t)n, sizeof *a, cmp_int);
    int u = 1;
    for (int k = 1; k < n; k++)
        if (a[k] != a[u - 1]) a[u++] = a[k];
    return u;
}

/* The penetrating points of TYPE7 card i (index in c->type7) in model m at
 * its initial state y: Inacti 1 the node ids, Inacti 2 the indices of the
 * main segments in its /SURF/SEG list, into out (ascending, unique; *nout);
 * *ntot the nodes of its contacts (Inacti 1) or its main segments
 * (Inacti 2). RC_EINPUT for Inacti 2 on a main surface without a list of
 * segments that a node penetrates. */
static rc_status card_points(const rc_case *c, const rc_model *m, int i, const double *y, int *hints, double tol,
                             int *out, int *nout, int *ntot, double *gap, rc_error *err)
{
    const rc_case_type7 *t = &c->type7[i];
    const int cs = rc_case_find_surf(c, t->surf_id);
    *nout = *ntot = 0;
    *gap = t->gapmin;
    for (int k = 0; k < m->ninter; k++) {
        if (m->inter_id[k] != t->id || strncmp(m->inter_name[k], "/INTER/TYPE7/", 13)) continue;
        const int sa = m->inter_sa[k], na = m->surf_nadr[sa + 1] - m->surf_nadr[sa];
        *gap = m->inter_gap[k];
        if (t->inacti == 1) *ntot += na;
        for (int j = 0; j < na; j++) {
            const int slot = m->surf_nadr[sa] + j;
            hints[slot] = -1;
            const double d = rc_point_distance(m, k, j, y, hints);
            if (!(d < m->inter_gap[k] - tol)) continue;
            if (t->inacti == 1) {
                out[(*nout)++] = m->surf_nid[slot];
                continue;
            }
            /* Inacti 2: the main segment the node projects onto */
            const int sk = c->surf[cs].kind;
            if (sk != RC_CASE_SURF_SEG)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /INTER/TYPE7/%d, field Inacti: Inacti 2 leaves the main segments that "
                                   "secondary nodes penetrate at t = 0 out of the contact; node %d penetrates the "
                                   "main surface /SURF/%s/%d (at %.6g m, within the gap of %.6g m), which %s: not supported "
                                   "yet; expected a main /SURF/SEG (its segments listed), Inacti 1 (the penetrating "
                                   "nodes left out instead), or the bodies apart at t = 0",
                         RC_LOC(t->line_loc[4]), t->id, m->surf_nid[slot], rc_case_surf_kind_name(sk), t->surf_id,
                         d, m->inter_gap[k],
                         sk == RC_CASE_SURF_PART ? "has its segments from the parts' elements, not a list of "
                                                   "segments that a copy without some of them could keep"
                                                 : "is one analytic surface without segments (leaving it out would "
                                                   "leave the whole surface out)");
            const int seg = hints[slot];
            if (seg < 0) continue; /* no segment (cannot be below the gap: beyond the search) */
            out[(*nout)++] = seg;
        }
    }
    if (t->inacti == 2) *ntot = c->surf[cs].kind == RC_CASE_SURF_SEG ? c->surf[cs].nseg : 0;
    *nout = sort_unique(out, *nout);
    return RC_OK;
}

/* The notice of card i: what it left out. */
static char *card_note(const rc_case *c, int i, const int *ids, int n, int ntot, double gap)
{
    const rc_case_type7 *t = &c->type7[i];
    const rc_case_surf *cs = &c->surf[rc_case_find_surf(c, t->surf_id)];
    char list[512] = "";
    size_t len = 0;
    for (int k = 0; k < n && k < RC_INACTI_LIST && len < sizeof list - 16; k++) {
        const int v = t->inacti == 1 ? ids[k] : cs->seg_id[ids[k]];
        len += (size_t)snprintf(list + len, sizeof list - len, "%s%d", k ? ", " : "", v);
    }
    if (n > RC_INACTI_LIST && len < sizeof list - 16) snprintf(list + len, sizeof list - len, ", ... (%d more)", n - RC_INACTI_LIST);
    char *s = malloc(1024 + sizeof list);
    if (!s) return NULL;
    const int all = n >= ntot;
    snprintf(s, 1024 + sizeof list,
             RC_LOCFMT "card /INTER/TYPE7/%d, field Inacti: Inacti %d leaves %d of the %d %s out of the contact for "
                       "the whole run (%s within the gap of %.6g m of the main surface /SURF/%s/%d at t = 0): %s %s%s",
             RC_LOC(t->line_loc[4]), t->id, t->inacti, n, ntot,
             t->inacti == 1 ? "secondary nodes of its contacts" : "main segments",
             t->inacti == 1 ? "the nodes" : "the segments that secondary nodes lie", gap,
             rc_case_surf_kind_name(cs->kind), t->surf_id,
             t->inacti == 1 ? "nodes" : "segments", list,
             all ? t->inacti == 1 ? "; no secondary node is left: the card has no contact at all"
                                  : "; no main segment is left: the card has no contact at all"
                 : "");
    return s;
}

rc_status rc_inacti_build(const rc_case *c, rc_model **pm, rc_error *err)
{
    int any = 0;
    for (int i = 0; i < c->ntype7; i++) any |= c->type7[i].inacti == 1 || c->type7[i].inacti == 2;
    if (!any) return RC_OK;
    rc_model *m = *pm;
    const int nhint = rc_seg_hint_len(m) + 1;
    double *y = malloc(((size_t)m->ny + 1) * sizeof *y);
    int *hints = malloc((size_t)nhint * sizeof *hints);
    rc_t7_drop drop = {calloc((size_t)c->ntype7 + 1, sizeof *drop.ids), calloc((size_t)c->ntype7 + 1, sizeof *drop.n)};
    int *ntot = calloc((size_t)c->ntype7 + 1, sizeof *ntot);
    double *gap = calloc((size_t)c->ntype7 + 1, sizeof *gap);
    rc_status st = RC_OK;
    if (!y || !hints || !drop.ids || !drop.n || !ntot || !gap) st = RC_SET(err, RC_ENOMEM, "out of memory for Inacti");
    if (!st) {
        rc_initial_state(m, y);
        for (int k = 0; k < nhint; k++) hints[k] = -1;
    }
    rc_scene sc;
    if (!st) rc_scene_scales(m, &sc);
    int left = 0;
    for (int i = 0; i < c->ntype7 && !st; i++) {
        const rc_case_type7 *t = &c->type7[i];
        if (t->inacti != 1 && t->inacti != 2) continue;
        /* at most every surface node of the model, or every main segment */
        const int cap = m->surf_nadr[m->nsurf] + m->surf_sadr[m->nsurf] + 1;
        drop.ids[i] = malloc((size_t)cap * sizeof *drop.ids[i]);
        if (!drop.ids[i]) {
            st = RC_SET(err, RC_ENOMEM, "out of memory for Inacti");
            break;
        }
        const double tol = RC_INACTI_TOUCH_REL * fmax(sc.lmax, t->gapmin);
        st = card_points(c, m, i, y, hints, tol, drop.ids[i], &drop.n[i], &ntot[i], &gap[i], err);
        left += drop.n[i];
    }
    if (!st && left > 0) { /* again, without them; the notices on the new model */
        rc_model *m2 = NULL;
        st = rc_model_build_drop(c, &drop, &m2, err);
        if (!st) {
            rc_model_free(m);
            *pm = m = m2;
            for (int i = 0; i < c->ntype7 && !st; i++)
                if (drop.n[i] > 0) st = rc_model_add_note(m, card_note(c, i, drop.ids[i], drop.n[i], ntot[i], gap[i]), err);
        }
    }
    for (int i = 0; drop.ids && i < c->ntype7; i++) free(drop.ids[i]);
    free(drop.ids);
    free(drop.n);
    free(ntot);
    free(gap);
    free(hints);
    free(y);
    return st;
}
