/*
 * Rigid walls (/RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER) as penalty contacts
 * (docs/theory.md, "Rigid walls"; docs/case-format.md, /RWALL).
 *
 * Radioss's wall acts on nodes. ricochet's bodies are rigid and touch
 * through their surfaces, so a wall acts on the bodies that own its nodes
 * (grnd_ID1, the nodes within d of the wall at t = 0, minus grnd_ID2): each
 * surface of such a body gets a contact with the wall's fixed surface (a
 * plane; a sphere; a cylinder long enough to be infinite for the scene),
 * with a TYPE6 law built here:
 *   - a linear load curve F = k P, k = m g_ref / (RC_RWALL_PEN_FRAC L),
 *     m the body's mass, L its radius of gyration sqrt(tr J / (2 m)),
 *     g_ref = max(|g| of the body, RC_RWALL_G_REF): under its weight the
 *     body sinks RC_RWALL_PEN_FRAC L into the wall;
 *   - the damping of a restitution RC_RWALL_RESTITUTION (TYPE6 e_target:
 *     Visc derived with the scales), for Radioss's plastic impact;
 *   - Slide 2: Coulomb friction fric (TYPE6 Fric, its stick stiffness k).
 * The contacts are appended to a copy of the case, compiled as TYPE6 cards
 * are; they are named "/RWALL/<type>/<id> with /SURF/<kind>/<id>" and carry
 * the id -rwall_ID (the wall's surface too), so that they cannot be taken
 * for a deck's /INTER or /SURF.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "model/rwall.h"
#include "model/segsurf.h"

static const char *const rc_rwall_type[] = {"", "PLANE", "CYL", "SPHER", "PARAL"};

rc_status rc_rwall_begin(const rc_case *c, rc_rwall_case *x, rc_error *err)
{
    memset(x, 0, sizeof *x);
    x->c = *c;
    if (c->nrwall == 0) return RC_OK;
    x->surf = calloc((size_t)(c->nsurf + c->nrwall), sizeof *x->surf);
    x->funct = calloc((size_t)c->nfunct + 1, sizeof *x->funct);
    x->acts = calloc((size_t)c->nrwall * (size_t)(c->nrbody + 1), 1);
    x->nodes = calloc((size_t)c->nrwall * (size_t)(c->nnode + 1), 1);
    x->nuser = c->nsurf;
    if (!x->surf || !x->funct || !x->acts || !x->nodes) {
        rc_rwall_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    if (c->nsurf) memcpy(x->surf, c->surf, (size_t)c->nsurf * sizeof *x->surf);
    if (c->nfunct) memcpy(x->funct, c->funct, (size_t)c->nfunct * sizeof *x->funct);
    /* the load curve of every wall: y = x, scaled per contact */
    x->fx[1] = x->fy[1] = 1.0;
    x->funct[c->nfunct] = (rc_case_funct){.id = -1, .npts = 2, .x = x->fx, .y = x->fy, .loc = c->end};
    /* the scene's size seen from each cylinder's M */
    for (int w = 0; w < c->nrwall; w++) {
        const rc_case_rwall *rw = &c->rwall[w];
        rc_case_surf *s = &x->surf[c->nsurf + w];
        s->id = -rw->id;
        s->loc = s->rbody_loc = rw->loc;
        memcpy(s->m, rw->m, sizeof s->m);
        memcpy(s->m1, rw->m1, sizeof s->m1);
        memcpy(s->c, rw->m, sizeof s->c);
        s->degree = 2;
        s->abc[0] = s->abc[1] = s->abc[2] = 0.5 * rw->diameter;
        if (rw->kind == RC_RWALL_PLANE) {
            s->kind = RC_CASE_SURF_PLANE;
        } else if (rw->kind == RC_RWALL_SPHER) {
            s->kind = RC_CASE_SURF_ELLIPS;
        } else {
            s->kind = RC_CASE_SURF_CYL;
            double reach = 0.0;
            for (int n = 0; n < c->nnode; n++)
                reach = fmax(reach, hypot(hypot(c->node[n].x[0] - rw->m[0], c->node[n].x[1] - rw->m[1]),
                                          c->node[n].x[2] - rw->m[2]));
            for (int k = 0; k < 3; k++) s->axis[k] = rw->m1[k] - rw->m[k];
            s->length = 2.0 * RC_RWALL_CYL_REACH * (reach + rw->diameter);
        }
    }
    x->c.surf = x->surf;
    x->c.nsurf = c->nsurf + c->nrwall;
    x->c.funct = x->funct;
    x->c.nfunct = c->nfunct + 1;
    return RC_OK;
}

/* Distance of point p from the surface of wall rw at t = 0 [m]. */
static double wall_distance(const rc_case_rwall *rw, const double *p)
{
    double d[3], a[3], dd = 0.0, aa = 0.0, da = 0.0;
    for (int k = 0; k < 3; k++) {
        d[k] = p[k] - rw->m[k];
        a[k] = rw->m1[k] - rw->m[k];
        dd += d[k] * d[k];
        aa += a[k] * a[k];
        da += d[k] * a[k];
    }
    if (rw->kind == RC_RWALL_PLANE) return fabs(da) / sqrt(aa);
    if (rw->kind == RC_RWALL_SPHER) return fabs(sqrt(dd) - 0.5 * rw->diameter);
    return fabs(sqrt(fmax(0.0, dd - da * da / aa)) - 0.5 * rw->diameter);
}

/* Set flag[node index] to `on` for the nodes of group gid, field `field`
 * of line 1 of wall rw; RC_EINPUT when the group does not exist. */
static rc_status mark_group(const rc_case *c, const rc_case_rwall *rw, int gid, const char *field, unsigned char *flag,
                            unsigned char on, rc_error *err)
{
    if (gid == 0) return RC_OK;
    const rc_loc l1 = rc_loc_or(rw->line_loc[0], rw->loc);
    const int g = rc_case_find_grnod(c, gid);
    if (g < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RWALL/%s/%d, field %s: expected the id of a /GRNOD, got %d (no such group)",
                 RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, field, gid);
    for (int k = 0; k < c->grnod[g].n; k++) {
        const int n = rc_case_find_node(c, c->grnod[g].nodes[k]);
        if (n < 0) {
            const rc_loc nl = rc_loc_at(c->grnod[g].node_loc, k, c->grnod[g].loc);
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /GRNOD/NODE/%d, field node_ID: expected the id of a /NODE, got %d (no such node); "
                     "the group is %s of /RWALL/%s/%d at %s:%d",
                     RC_LOC(nl), gid, c->grnod[g].nodes[k], field, rc_rwall_type[rw->kind], rw->id, RC_LOC(l1));
        }
        flag[n] = on;
    }
    return RC_OK;
}

rc_status rc_rwall_bodies(rc_rwall_case *x, const rc_model *m, rc_error *err)
{
    const rc_case *c = &x->c;
    if (c->nrwall == 0) return RC_OK;
    unsigned char *flag = malloc((size_t)c->nnode + 1);
    if (!flag) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_status st = RC_OK;
    for (int w = 0; w < c->nrwall && !st; w++) {
        const rc_case_rwall *rw = &c->rwall[w];
        const rc_loc l1 = rc_loc_or(rw->line_loc[0], rw->loc);
        if (rw->grnd1 == 0 && !(rw->dsearch > 0)) {
            st = RC_SET(err, RC_EINPUT,
                        RC_LOCFMT "card /RWALL/%s/%d, field grnd_ID1: expected the node group the wall acts on (or a "
                        "search distance d > 0 on line 2), got 0: the wall would act on no node",
                        RC_LOC(l1), rc_rwall_type[rw->kind], rw->id);
            break;
        }
        /* the nodes: grnd_ID1, those within d at t = 0, minus grnd_ID2 */
        memset(flag, 0, (size_t)c->nnode + 1);
        if ((st = mark_group(c, rw, rw->grnd1, "grnd_ID1", flag, 1, err))) break;
        if (rw->dsearch > 0)
            for (int n = 0; n < c->nnode; n++)
                if (wall_distance(rw, c->node[n].x) <= rw->dsearch && rc_case_body_of_node(c, c->node[n].id) >= 0)
                    flag[n] = 1;
        if ((st = mark_group(c, rw, rw->grnd2, "grnd_ID2", flag, 0, err))) break;
        /* their bodies: every node of grnd_ID1 must have one */
        for (int n = 0; n < c->nnode; n++) {
            if (!flag[n]) continue;
            const int b = rc_case_body_of_node(c, c->node[n].id);
            if (b < 0) {
                st = RC_SET(err, RC_EINPUT,
                            RC_LOCFMT "card /RWALL/%s/%d, field grnd_ID1: node %d (%s:%d) belongs to no /RBODY "
                            "(ricochet bodies are rigid: the wall acts on the bodies that own its nodes)",
                            RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, c->node[n].id, RC_LOC(c->node[n].loc));
                break;
            }
            /* a fixed body never meets a fixed wall */
            if (m->body_fixed[b]) continue;
            x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b] = 1;
            x->nodes[(size_t)w * (size_t)c->nnode + (size_t)n] = 1;
        }
    }
    free(flag);
    return st;
}

/* Grow a model array of the surfaces from n to n + add entries of `size`
 * bytes, the new ones zero. */
static int grow(void *pp, int n, int add, size_t size)
{
    void **p = pp;
    char *q = realloc(*p, ((size_t)(n + add) + 1) * size);
    if (!q) return -1;
    memset(q + (size_t)n * size, 0, ((size_t)add + 1) * size);
    *p = q;
    return 0;
}

rc_status rc_rwall_points(rc_rwall_case *x, rc_model *m, rc_error *err)
{
    rc_case *c = &x->c;
    if (c->nrwall == 0) return RC_OK;
    /* the (plane wall, body without surface) pairs */
    int n = 0, idmax = 0;
    for (int w = 0; w < c->nrwall; w++) idmax = w == 0 || c->rwall[w].id > idmax ? c->rwall[w].id : idmax;
    unsigned char *bare = calloc((size_t)c->nrbody + 1, 1);
    if (!bare) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int b = 0; b < c->nrbody; b++) bare[b] = 1;
    for (int s = 0; s < x->nuser; s++)
        if (m->surf_body[s] >= 0) bare[m->surf_body[s]] = 0;
    for (int w = 0; w < c->nrwall; w++)
        for (int b = 0; b < c->nrbody; b++)
            n += c->rwall[w].kind == RC_RWALL_PLANE && bare[b] && x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b];
    if (n == 0) {
        free(bare);
        return RC_OK;
    }
    const int s0 = c->nsurf;
    rc_case_surf *ns = realloc(x->surf, ((size_t)(s0 + n) + 1) * sizeof *ns);
    if (ns) x->surf = c->surf = ns;
    x->pts_wall = calloc((size_t)n + 1, sizeof *x->pts_wall);
    x->pts_node = calloc((size_t)n + 1, sizeof *x->pts_node);
    if (!ns || !x->pts_wall || !x->pts_node || grow(&m->surf_id, s0, n, sizeof *m->surf_id) ||
        grow(&m->surf_kind, s0, n, sizeof *m->surf_kind) || grow(&m->surf_body, s0, n, sizeof *m->surf_body) ||
        grow(&m->surf_p, 3 * s0, 3 * n, sizeof *m->surf_p) || grow(&m->surf_n, 3 * s0, 3 * n, sizeof *m->surf_n) ||
        grow(&m->surf_r, s0, n, sizeof *m->surf_r) ||
        grow(&m->surf_ext, RC_SURF_NEXT * s0, RC_SURF_NEXT * n, sizeof *m->surf_ext) ||
        grow(&m->surf_nadr, s0 + 1, n, sizeof *m->surf_nadr) || grow(&m->surf_sadr, s0 + 1, n, sizeof *m->surf_sadr)) {
        free(bare);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    /* one surface of points per pair: the wall's nodes of the body, in the
     * order of /NODE; ids below every wall's -rwall_ID */
    rc_status st = RC_OK;
    for (int w = 0; w < c->nrwall && !st; w++)
        for (int b = 0; b < c->nrbody && !st; b++) {
            if (c->rwall[w].kind != RC_RWALL_PLANE || !bare[b] || !x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b])
                continue;
            const int k = x->npts, s = s0 + k;
            int *ids = malloc(((size_t)c->nnode + 1) * sizeof *ids), np = 0;
            if (!ids) {
                st = RC_SET(err, RC_ENOMEM, "out of memory");
                break;
            }
            for (int j = 0; j < c->nnode; j++)
                if (x->nodes[(size_t)w * (size_t)c->nnode + (size_t)j] && rc_case_body_of_node(c, c->node[j].id) == b)
                    ids[np++] = c->node[j].id;
            x->pts_node[k] = ids;
            x->pts_wall[k] = w;
            x->npts++;
            c->surf[s] = (rc_case_surf){.id = -(idmax + 1 + k), .kind = RC_CASE_SURF_SEG, .loc = c->rwall[w].loc,
                                        .rbody_loc = c->rwall[w].loc, .npoint = np, .point = ids};
            c->nsurf = m->nsurf = s + 1;
            m->surf_nadr[s + 1] = m->surf_nadr[s];
            m->surf_sadr[s + 1] = m->surf_sadr[s];
            st = rc_seg_surface(c, m, s, err); /* model/segsurf.c */
        }
    free(bare);
    return st;
}

void rc_rwall_box_flags(const rc_rwall_case *x, unsigned char *corners)
{
    const rc_case *c = &x->c;
    for (int w = 0; w < c->nrwall; w++) {
        if (c->rwall[w].kind != RC_RWALL_PLANE) continue;
        for (int s = 0; s < c->nsurf; s++) {
            if (c->surf[s].kind != RC_CASE_SURF_BOX || c->surf[s].rbody_id == 0) continue;
            const int b = rc_case_find_rbody(c, c->surf[s].rbody_id);
            if (b >= 0 && x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b]) corners[s] = 1;
        }
    }
}

rc_status rc_rwall_contacts(rc_rwall_case *x, const rc_model *m, rc_error *err)
{
    rc_case *c = &x->c;
    if (c->nrwall == 0) return RC_OK;
    static const char *const kinds[] = {"", "PLANE", "ELLIPS", "CYL", "BOX", "SEG", "PART"};
    const int nuser = x->nuser, p0 = nuser + c->nrwall;
    /* one contact per wall and surface of a body it acts on (the deck's
     * surfaces, or the wall's own points of a body without surfaces) */
    int n = x->npts;
    for (int w = 0; w < c->nrwall; w++)
        for (int s = 0; s < nuser; s++)
            if (m->surf_body[s] >= 0 && x->acts[(size_t)w * (size_t)c->nrbody + (size_t)m->surf_body[s]]) n++;
    x->type6 = calloc((size_t)(c->ntype6 + n) + 1, sizeof *x->type6);
    x->name = calloc((size_t)n + 1, sizeof *x->name);
    if (!x->type6 || !x->name) RC_RAISE(err, RC_ENOMEM, "out of memory");
    if (c->ntype6) memcpy(x->type6, c->type6, (size_t)c->ntype6 * sizeof *x->type6);
    int k = c->ntype6, j = 0;
    for (int w = 0; w < c->nrwall; w++) {
        const rc_case_rwall *rw = &c->rwall[w];
        const rc_loc l1 = rc_loc_or(rw->line_loc[0], rw->loc);
        for (int b = 0; b < c->nrbody; b++) {
            if (!x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b]) continue;
            int ns = 0;
            for (int s = 0; s < c->nsurf; s++) {
                if (s >= nuser && s < p0) continue; /* the walls */
                if (m->surf_body[s] != b || (s >= p0 && x->pts_wall[s - p0] != w)) continue;
                const rc_case_surf *cs = &c->surf[s];
                if (rw->kind == RC_RWALL_CYL && cs->kind != RC_CASE_SURF_ELLIPS)
                    RC_RAISE(err, RC_EINPUT,
                             RC_LOCFMT "card /RWALL/CYL/%d, field grnd_ID1: the wall acts on /RBODY/%d, whose surface "
                             "/SURF/%s/%d is not a sphere: an /RWALL/CYL against anything but a sphere (/SURF/ELLIPS) "
                             "is not supported yet",
                             RC_LOC(l1), rw->id, c->rbody[b].id, kinds[cs->kind], cs->id);
                /* the body's scales: mass, radius of gyration, gravity */
                const double mass = m->body_mass[b], *J = m->body_J + 9 * b, *g = m->body_grav + 3 * b;
                const double len = sqrt((J[0] + J[4] + J[8]) / (2.0 * mass));
                const double gref = fmax(hypot(hypot(g[0], g[1]), g[2]), RC_RWALL_G_REF);
                const double kw = mass * gref / (RC_RWALL_PEN_FRAC * len);
                rc_case_type6 *t = &x->type6[k++];
                if (s >= p0)
                    snprintf(x->name[j], sizeof x->name[j], "/RWALL/%s/%d with the nodes of /RBODY/%d",
                             rc_rwall_type[rw->kind], rw->id, c->rbody[b].id);
                else
                    snprintf(x->name[j], sizeof x->name[j], "/RWALL/%s/%d with /SURF/%s/%d", rc_rwall_type[rw->kind],
                             rw->id, kinds[cs->kind], cs->id);
                *t = (rc_case_type6){.id = -rw->id, .surf1 = cs->id, .surf2 = -rw->id, .fric = rw->slide == 2 ? rw->fric : 0.0,
                                     .tstop = 1e30, .ascalef = 1.0, .ascalev = 1.0, .fct_ld = -1, .ascalex = len,
                                     .fscaleld = kw * len, .fscaleul = 1.0, .fscalev = 1.0,
                                     .e_target = RC_RWALL_RESTITUTION, .loc = rw->loc, .name = x->name[j++]};
                for (int l = 0; l < 6; l++) t->line_loc[l] = l1;
                ns++;
            }
            if (ns == 0)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /RWALL/%s/%d, field grnd_ID1: the wall acts on /RBODY/%d, which carries no "
                         "surface; an /RWALL/%s acting on the nodes of a body alone is not supported yet (an /RWALL/PLANE "
                         "is): give the body a surface (/SURF/ELLIPS, /SURF/CYL or /SURF/BOX with its rbody_ID, "
                         "/SURF/SEG or /SURF/PART on its nodes)",
                         RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, c->rbody[b].id, rc_rwall_type[rw->kind]);
        }
    }
    c->type6 = x->type6;
    c->ntype6 = k;
    return RC_OK;
}

void rc_rwall_end(rc_rwall_case *x)
{
    free(x->surf);
    free(x->type6);
    free(x->funct);
    free(x->name);
    free(x->acts);
    free(x->nodes);
    for (int k = 0; x->pts_node && k < x->npts; k++) free(x->pts_node[k]);
    free(x->pts_node);
    free(x->pts_wall);
    memset(x, 0, sizeof *x);
}
