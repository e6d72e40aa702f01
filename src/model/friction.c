/*
 * /FRICTION over the interfaces (docs/theory.md 6): which part each
 * surface belongs to, which card and which coefficient set govern each
 * interface, the orthotropy direction, the filter time constant, the
 * pressure area and the reduced mass. Runs after the TYPE6 interfaces are
 * compiled (their own friction is the default) and before the state layout.
 *
 * Rules (documented in docs/case-format.md):
 *  - a /PART names a body (all its surfaces) or some of its surfaces; a
 *    surface may belong to one part only;
 *  - a /FRICTION card without part-pair groups covers every interface; one
 *    with groups covers the interfaces whose two surfaces' parts both appear
 *    in its groups; among the groups matching the pair (either order) the
 *    last wins, otherwise the card's defaults apply;
 *  - among the cards covering an interface, the last in the deck wins, and it
 *    replaces the TYPE6 card's own friction (Sfric, Fric, fct_IDff, fct_IDfv).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case/case.h"
#include "base/error.h"
#include "model/geom.h"
#include "model/model.h"


/* Does group side (grpart, part) name part index p? */
static int side_names(const rc_case *c, int grpart, int part, int p)
{
    if (p < 0) return 0;
    const int pid = c->part[p].id;
    if (part && part == pid) return 1;
    int g = grpart ? rc_case_find_grpart(c, grpart) : -1;
    if (g >= 0)
        for (int k = 0; k < c->grpart[g].n; k++)
            if (c->grpart[g].parts[k] == pid) return 1;
    return 0;
}

static int group_matches(const rc_case *c, const rc_case_fricpair *g, int pa, int pb)
{
    return (side_names(c, g->grpart1, g->part1, pa) && side_names(c, g->grpart2, g->part2, pb)) ||
           (side_names(c, g->grpart1, g->part1, pb) && side_names(c, g->grpart2, g->part2, pa));
}

static int card_names(const rc_case *c, const rc_case_friction *f, int p)
{
    for (int k = 0; k < f->npair; k++) {
        const rc_case_fricpair *g = &f->pair[k];
        if (side_names(c, g->grpart1, g->part1, p) || side_names(c, g->grpart2, g->part2, p)) return 1;
    }
    return 0;
}

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* Part of every surface (index into c->part, -1: none). Each part's
 * surfaces are visited in index order, as a scan of all surfaces would, so
 * the first error reported is the same; look-ups by id are binary searches
 * (case/lookup.c), and the surfaces of a body come from a table built once,
 * so that many parts cost O(N log N), not O(parts x surfaces). */
static rc_status surface_parts(const rc_case *c, const rc_model *m, int *spart, rc_error *err)
{
    rc_status st = RC_OK;
    int maxlist = m->nsurf;
    for (int p = 0; p < c->npart; p++)
        if (c->part[p].nsurf > maxlist) maxlist = c->part[p].nsurf;
    /* surfaces of each body, ascending; bucket nbody: fixed in space */
    int *start = calloc((size_t)m->nbody + 2, sizeof(int)), *bysurf = malloc(((size_t)m->nsurf + 1) * sizeof(int));
    int *mine = malloc(((size_t)maxlist + 1) * sizeof(int));
    if (!start || !bysurf || !mine) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    for (int s = 0; s < m->nsurf; s++) {
        spart[s] = -1;
        start[(m->surf_body[s] >= 0 ? m->surf_body[s] : m->nbody) + 1]++;
    }
    for (int k = 0; k <= m->nbody; k++) start[k + 1] += start[k];
    for (int s = 0; s < m->nsurf; s++) { /* start[k] advances while filling */
        const int k = m->surf_body[s] >= 0 ? m->surf_body[s] : m->nbody;
        bysurf[start[k]++] = s;
    }
    for (int k = m->nbody; k > 0; k--) start[k] = start[k - 1]; /* back to the bucket starts */
    start[0] = 0;
    for (int p = 0; p < c->npart && !st; p++) {
        const rc_case_part *cp = &c->part[p];
        int b = -1, n = 0;
        if (!cp->rbody_id && !cp->nsurf) continue; /* a part of the mesh (no ricochet line 2) names no surface */
        if (cp->rbody_id && (b = rc_case_find_rbody(c, cp->rbody_id)) < 0) {
            st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /PART/%d, field rbody_ID: expected the id of a /RBODY, got %d (no such body)",
                        RC_LOC(rc_loc_or(cp->line_loc, cp->loc)), cp->id, cp->rbody_id);
            break;
        }
        if (cp->nsurf == 0) {
            const int k = b >= 0 ? b : m->nbody;
            for (int j = start[k]; j < start[k + 1]; j++) mine[n++] = bysurf[j];
        } else {
            for (int k = 0; k < cp->nsurf; k++) {
                const int s = rc_case_find_surf(c, cp->surf[k]);
                if (s >= 0) mine[n++] = s;
            }
            qsort(mine, (size_t)n, sizeof *mine, cmp_int);
            int u = 0;
            for (int j = 0; j < n; j++)
                if (u == 0 || mine[j] != mine[u - 1]) mine[u++] = mine[j];
            n = u;
        }
        for (int j = 0; j < n && !st; j++) {
            const int s = mine[j];
            /* the line holding this surface id (rbody_ID's: the whole body's surfaces) */
            rc_loc sl = rc_loc_or(cp->line_loc, cp->loc);
            for (int k = 0; k < cp->nsurf; k++)
                if (cp->surf[k] == m->surf_id[s]) {
                    sl = rc_loc_at(cp->surf_loc, k, cp->loc);
                    break;
                }
            if (cp->nsurf > 0 && m->surf_body[s] != b)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /PART/%d, field surf_ID: surface %d is not carried by rbody_ID %d",
                            RC_LOC(sl), cp->id, m->surf_id[s], cp->rbody_id);
            else if (spart[s] >= 0)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /PART/%d%s: surface %d already belongs to /PART/%d (a surface is in one part only)",
                            RC_LOC(sl), cp->id, cp->nsurf > 0 ? ", field surf_ID" : ", field rbody_ID", m->surf_id[s], c->part[spart[s]].id);
            else
                spart[s] = p;
        }
        for (int k = 0; k < cp->nsurf && !st; k++)
            if (rc_case_find_surf(c, cp->surf[k]) < 0)
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /PART/%d, field surf_ID: expected the id of a /SURF, got %d (no such surface)",
                            RC_LOC(rc_loc_at(cp->surf_loc, k, cp->loc)), cp->id, cp->surf[k]);
    }
done:
    free(start);
    free(bysurf);
    free(mine);
    return st;
}

/* Every part and group id named by the friction cards exists. */
static rc_status check_refs(const rc_case *c, rc_error *err)
{
    for (int g = 0; g < c->ngrpart; g++)
        for (int k = 0; k < c->grpart[g].n; k++)
            if (rc_case_find_part(c, c->grpart[g].parts[k]) < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /GRPART/PART/%d, field part_ID: expected the id of a /PART, got %d (no such part)",
                         RC_LOC(rc_loc_at(c->grpart[g].part_loc, k, c->grpart[g].loc)), c->grpart[g].id,
                         c->grpart[g].parts[k]);
    for (int f = 0; f < c->nfriction; f++)
        for (int k = 0; k < c->friction[f].npair; k++) {
            const rc_case_fricpair *g = &c->friction[f].pair[k];
            const int parts[2] = {g->part1, g->part2}, groups[2] = {g->grpart1, g->grpart2};
            for (int j = 0; j < 2; j++) {
                if (parts[j] && rc_case_find_part(c, parts[j]) < 0)
                    RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /FRICTION/%d, field part_ID%d: expected the id of a /PART, got %d (no such part)",
                             RC_LOC(g->loc), c->friction[f].id, j + 1, parts[j]);
                if (groups[j] && rc_case_find_grpart(c, groups[j]) < 0)
                    RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /FRICTION/%d, field grpart_ID%d: expected the id of a /GRPART, got %d (no such part group)",
                             RC_LOC(g->loc), c->friction[f].id, j + 1, groups[j]);
            }
        }
    for (int o = 0; o < c->nfricorient; o++)
        for (int k = 0; k < c->fricorient[o].n; k++) {
            const rc_case_fricorient_item *it = &c->fricorient[o].item[k];
            if (it->part_id && rc_case_find_part(c, it->part_id) < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /FRIC_ORIENT/%d, field part_ID: expected the id of a /PART, got %d (no such part)",
                         RC_LOC(it->loc), c->fricorient[o].id, it->part_id);
            if (it->grpart_id && rc_case_find_grpart(c, it->grpart_id) < 0)
                RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /FRIC_ORIENT/%d, field grpart_ID: expected the id of a /GRPART, got %d (no such part group)",
                         RC_LOC(it->loc), c->fricorient[o].id, it->grpart_id);
        }
    return RC_OK;
}

/* Orthotropy direction for part p (last matching /FRIC_ORIENT item). */
static const rc_case_fricorient_item *orient_of(const rc_case *c, int p)
{
    const rc_case_fricorient_item *found = NULL;
    for (int o = 0; o < c->nfricorient; o++)
        for (int k = 0; k < c->fricorient[o].n; k++) {
            const rc_case_fricorient_item *it = &c->fricorient[o].item[k];
            if (side_names(c, it->grpart_id, it->part_id, p)) found = it;
        }
    return found;
}

/* 1 when the law of card f (group g, NULL: the defaults) reads the contact
 * pressure: a non-zero coefficient of p in Ifric 1 (C1, C3, C4) or 2 (C1,
 * C3; C2, C4 are rates of its exponentials). */
static int uses_pressure(const rc_case_friction *f, const rc_case_fricpair *g)
{
    if (f->ifric != 1 && f->ifric != 2) return 0;
    for (int d = 0; d < (g && g->idir == 1 ? 2 : 1); d++) {
        const double *c = g ? g->set[d].c : f->def.c;
        if (c[0] != 0 || c[2] != 0 || (f->ifric == 1 && c[3] != 0)) return 1;
    }
    return 0;
}

/* Fill interface i's friction from card f and coefficient group g (NULL:
 * the card's defaults). */
static rc_status apply_card(const rc_case *c, rc_model *m, int i, const rc_case_friction *f, const rc_case_fricpair *g,
                            const int *spart, rc_error *err)
{
    rc_fric *fr = &m->inter_fr[i];
    const double kt = fr->kt; /* the interface's stick stiffness stays */
    char cn[96]; /* the card, for messages: a /FRICTION or the interface card of an inline law */
    if (f->owner[0])
        snprintf(cn, sizeof cn, "%s (its Ifric line)", f->owner);
    else
        snprintf(cn, sizeof cn, "/FRICTION/%d", f->id);
    memset(fr, 0, sizeof *fr);
    fr->kind = RC_FK_CARD;
    fr->card_id = f->id;
    fr->form = f->iform == 2 || f->iform == 3 ? RC_FF_INCREMENTAL : RC_FF_VISCOUS;
    /* Iform 3 (ricochet): exact stick, the static limit that of Fric */
    fr->exact = f->iform == 3;
    const rc_case_fricset *s0 = g ? &g->set[0] : &f->def;
    fr->mus = s0->fric;
    if (fr->exact && (f->ifric != 0 || f->ifiltr != 0 || (g && g->idir == 1)))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Iform: exact stick (3) is supported with the Coulomb law only, "
                           "isotropic and unfiltered (not supported yet: Ifric %d, Ifiltr %d, Idir %d); expected "
                           "Iform 2 or Ifric = Ifiltr = Idir = 0",
                 RC_LOC(f->line_loc[0]), cn, f->ifric, f->ifiltr, g ? g->idir : 0);
    fr->ifric = f->ifric;
    fr->kt = kt;
    fr->fct_ff = fr->fct_fv = -1;
    fr->tidx = fr->fidx = fr->widx = fr->obody = -1;
    const rc_case_fricset *sets[2] = {g ? &g->set[0] : &f->def, g ? &g->set[1] : &f->def};
    fr->ortho = g && g->idir == 1;
    for (int d = 0; d < 2; d++) {
        memcpy(fr->set[d], sets[d]->c, 6 * sizeof(double));
        fr->set[d][RC_FS_FRIC] = sets[d]->fric;
        fr->set[d][RC_FS_VISF] = sets[d]->visf;
    }
    /* filter: tau dF_f/dt = F - F_f (docs/theory.md 6.3) */
    if (f->ifiltr == 3) fr->tau = 1.0 / (2.0 * RC_PI * f->xfreq);
    if (f->ifiltr == 1 || f->ifiltr == 2) {
        if (!(f->dt_ref > 0))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, field Dt_ref: Ifiltr = %d gives its coefficient per explicit time step: expected the reference step Dt_ref > 0 [s], got blank",
                     RC_LOC(f->line_loc[0]), cn, f->ifiltr);
        fr->tau = f->ifiltr == 1 ? f->dt_ref / f->xfreq : f->dt_ref / (2.0 * RC_PI * f->xfreq);
    }
    /* pressure area: the card's, or the projected area of the (smaller)
     * sphere of a sphere pair; a law that reads the pressure on any other
     * pair needs the card's (a box or a mesh has no area ricochet could
     * take for its contact patch without guessing) */
    const int sphere = m->inter_pair[i] == RC_PAIR_SPHERE_PLANE || m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE ||
                       m->inter_pair[i] == RC_PAIR_SPHERE_BOX || m->inter_pair[i] == RC_PAIR_SPHERE_SEG ||
                       m->inter_pair[i] == RC_PAIR_SPHERE_CYL;
    double r = m->surf_r[m->inter_sa[i]];
    if (m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE) r = fmin(r, m->surf_r[m->inter_sb[i]]);
    fr->area = f->area > 0 ? f->area : sphere ? RC_PI * r * r : 0.0;
    if (!(fr->area > 0) && uses_pressure(f, g) && f->owner[0])
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Ifric: the law (Ifric %d) reads the contact pressure p = F_n / Area on "
                           "%s, a %s pair, whose contact area ricochet takes only for a sphere (pi R^2), and the "
                           "interface card has no Area: expected coefficients of p zero (C1, C3%s), or the law on "
                           "a /FRICTION card with its Area, named by fric_ID",
                 RC_LOC(f->line_loc[0]), f->owner, f->ifric, m->inter_name[i], rc_geom_inter_pair_name(m, i),
                 f->ifric == 1 ? ", C4" : "");
    if (!(fr->area > 0) && uses_pressure(f, g))
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field Area: the law (Ifric %d) reads the contact pressure p = F_n / Area "
                           "on %s, a %s pair, whose contact area ricochet takes only for a sphere (pi R^2): expected "
                           "Area > 0 [m^2], got blank",
                 RC_LOC(f->line_loc[0]), cn, f->ifric, m->inter_name[i], rc_geom_inter_pair_name(m, i));
    /* reduced mass of the two bodies (a body without states is infinitely heavy) */
    const int b[2] = {m->inter_ba[i], m->inter_bb[i]};
    double inv = 0;
    for (int k = 0; k < 2; k++)
        if (b[k] >= 0 && m->body_yadr[b[k]] >= 0) inv += 1.0 / m->body_mass[b[k]];
    fr->mred = inv > 0 ? 1.0 / inv : 0.0;
    if (fr->form == RC_FF_INCREMENTAL && !(fr->kt > 0))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Iform: the incremental form needs a stiffness; %s has none",
                 RC_LOC(f->line_loc[0]), cn, m->inter_name[i]);
    /* orthotropy: direction 1 from /FRIC_ORIENT of the second surface's part
     * (the main surface, as in Radioss), else of the first */
    if (fr->ortho) {
        const int pb = spart[m->inter_sb[i]], pa = spart[m->inter_sa[i]];
        const rc_case_fricorient_item *it = orient_of(c, pb);
        int side = m->inter_sb[i];
        if (!it) {
            it = orient_of(c, pa);
            side = m->inter_sa[i];
        }
        if (!it)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: orthotropic friction (Idir = 1) for %s needs a /FRIC_ORIENT naming the part of one of its surfaces",
                     RC_LOC(g->loc), cn, m->inter_name[i]);
        memcpy(fr->odir, it->v, sizeof fr->odir);
        fr->obody = m->surf_body[side];
        fr->oside = side == m->inter_sa[i] ? 1 : -1; /* n points from a to b */
        fr->ophi = it->phi * RC_PI / 180.0;
    }
    return RC_OK;
}

rc_status rc_friction_compile(const rc_case *c, rc_model *m, rc_error *err)
{
    /* an /INTER/TYPE7's fric_ID names its /FRICTION card (model/type7.c) */
    for (int i = 0; i < c->ntype6; i++) {
        if (c->type6[i].fric_id <= 0) continue;
        int found = 0;
        for (int f = 0; f < c->nfriction; f++) found |= c->friction[f].id == c->type6[i].fric_id;
        if (!found)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /INTER/TYPE7/%d, field fric_ID: expected the id of a /FRICTION, got %d (no such card)",
                     RC_LOC(c->type6[i].line_loc[2]), c->type6[i].id, c->type6[i].fric_id);
    }
    if (c->nfriction == 0) return RC_OK;
    rc_status st = check_refs(c, err);
    if (st) return st;
    int *spart = malloc(((size_t)m->nsurf + 1) * sizeof(int));
    if (!spart) RC_RAISE(err, RC_ENOMEM, "out of memory");
    if ((st = surface_parts(c, m, spart, err))) goto done;
    for (int i = 0; i < m->ninter && !st; i++) {
        const int pa = spart[m->inter_sa[i]], pb = spart[m->inter_sb[i]];
        const rc_case_friction *card = NULL;
        const rc_case_fricpair *group = NULL;
        const int fid = i < c->ntype6 ? c->type6[i].fric_id : 0;
        for (int f = 0; f < c->nfriction; f++) {
            const rc_case_friction *cf = &c->friction[f];
            /* a TYPE7's fric_ID: that card, its group of the two parts or its defaults;
             * fric_id < 0: the law written on the interface card itself */
            if (fid != 0 && cf->id != fid) continue;
            /* a card's inline law (id < 0) applies to that interface alone */
            if (fid == 0 && cf->id < 0) continue;
            if (fid <= 0 && cf->npair > 0 && !(card_names(c, cf, pa) && card_names(c, cf, pb))) continue;
            card = cf;
            group = NULL;
            for (int k = 0; k < cf->npair; k++)
                if (group_matches(c, &cf->pair[k], pa, pb)) group = &cf->pair[k];
        }
        if (card) st = apply_card(c, m, i, card, group, spart, err);
    }
done:
    free(spart);
    return st;
}

void rc_friction_print(const rc_model *m, int i, FILE *f)
{
    const rc_fric *fr = &m->inter_fr[i];
    static const char *const law[4] = {"Coulomb", "generalised viscous", "modified Darmstad", "Renard"};
    if (fr->kind == RC_FK_TYPE6 && !fr->exact)
        fprintf(f, "  %-18s friction (TYPE6) Sfric %.5g N, Fric %.5g, stick stiffness %.5g N/m\n", m->inter_name[i],
                fr->sfric, fr->fric, fr->kt);
    if (fr->kind == RC_FK_STEP5)
        fprintf(f, "  %-18s friction step5: mu_s %.5g at v_s %.5g m/s, mu_d %.5g beyond v_d %.5g m/s, f_max %.5g N%s\n",
                m->inter_name[i], fr->set[0][RC_S5_MUS], fr->set[0][RC_S5_VS], fr->set[0][RC_S5_MUD],
                fr->set[0][RC_S5_VD], fr->set[0][RC_S5_FMAX], fr->set[0][RC_S5_FMAX] > 0 ? "" : " (none)");
    if (fr->kind == RC_FK_CARD && fr->card_id < 0)
        fprintf(f, "  %-18s friction of the card's Ifric line: %s law, %s form, filter tau %.5g s, pressure area %.5g m^2\n",
                m->inter_name[i], law[fr->ifric & 3], fr->form == RC_FF_VISCOUS ? "viscous (total)" : "incremental",
                fr->tau, fr->area);
    if (fr->kind == RC_FK_CARD && fr->card_id > 0)
        fprintf(f, "  %-18s friction /FRICTION/%d: %s law, %s form%s, filter tau %.5g s, pressure area %.5g m^2%s\n",
                m->inter_name[i], fr->card_id, law[fr->ifric & 3],
                fr->form == RC_FF_VISCOUS ? "viscous (total)" : "incremental",
                fr->exact ? " with exact stick" : "", fr->tau, fr->area, fr->ortho ? ", orthotropic" : "");
    if (fr->kind == RC_FK_TYPE6 && fr->exact)
        fprintf(f, "  %-18s friction (TYPE6) with exact stick (a constraint on IDA, no stick spring): sticks within "
                   "Sfric + %.5g F_n, slides at Sfric + %.5g F_n (Sfric %.5g N; the sliding direction turns at the "
                   "rate of %.5g N/m)\n",
                m->inter_name[i], fr->mus, fr->fric, fr->sfric, fr->kt);
}
