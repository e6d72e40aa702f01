/*
 * Rigid walls (/RWALL/PLANE, /RWALL/CYL, /RWALL/SPHER, /RWALL/PARAL) as penalty contacts
 * (docs/theory.md, "Rigid walls"; docs/case-format.md, /RWALL).
 *
 * Radioss's wall acts on nodes. ricochet's bodies are rigid and touch
 * through their surfaces, so a wall acts on the bodies that own its nodes
 * (grnd_ID1, the nodes within d of the wall at t = 0, minus grnd_ID2): each
 * surface of such a body gets a contact with the wall's fixed surface (a
 * plane; a sphere; a cylinder long enough to be infinite for the scene; a
 * plane bounded to a parallelogram, against spheres only),
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
#include "model/type7.h"

static const char *const rc_rwall_type[] = {"", "PLANE", "CYL", "SPHER", "PARAL"};

/* The sides e1 = M1 - M, e2 = M2 - M of a /RWALL/PARAL and its unit
 * normal n = e1 x e2 / |e1 x e2| (the reader checked e1 x e2 != 0). */
static void parallelogram(const rc_case_rwall *rw, double *e1, double *e2, double *n)
{
    for (int k = 0; k < 3; k++) {
        e1[k] = rw->m1[k] - rw->m[k];
        e2[k] = rw->m2[k] - rw->m[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    const double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) n[k] /= l;
}

/* Distance of p from segment a + u e, u in [0, 1]. */
static double seg_distance(const double *a, const double *e, const double *p)
{
    double r[3], ee = 0.0, re = 0.0;
    for (int k = 0; k < 3; k++) {
        r[k] = p[k] - a[k];
        ee += e[k] * e[k];
        re += r[k] * e[k];
    }
    const double u = fmin(1.0, fmax(0.0, re / ee));
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) d2 += (r[k] - u * e[k]) * (r[k] - u * e[k]);
    return sqrt(d2);
}

/* Distance of p from the parallelogram of a /RWALL/PARAL: from its plane
 * when p projects inside it, else from its nearest side. */
static double paral_distance(const rc_case_rwall *rw, const double *p)
{
    double e1[3], e2[3], n[3], r[3], h = 0.0, a1 = 0.0, a2 = 0.0, g11 = 0.0, g12 = 0.0, g22 = 0.0;
    parallelogram(rw, e1, e2, n);
    for (int k = 0; k < 3; k++) {
        r[k] = p[k] - rw->m[k];
        h += r[k] * n[k];
        a1 += r[k] * e1[k];
        a2 += r[k] * e2[k];
        g11 += e1[k] * e1[k];
        g12 += e1[k] * e2[k];
        g22 += e2[k] * e2[k];
    }
    const double det = g11 * g22 - g12 * g12, u = (g22 * a1 - g12 * a2) / det, v = (g11 * a2 - g12 * a1) / det;
    if (u >= 0 && u <= 1 && v >= 0 && v <= 1) return fabs(h);
    double m1[3], m2[3];
    for (int k = 0; k < 3; k++) {
        m1[k] = rw->m[k] + e1[k];
        m2[k] = rw->m[k] + e2[k];
    }
    return fmin(fmin(seg_distance(rw->m, e1, p), seg_distance(rw->m, e2, p)),
                fmin(seg_distance(m1, e2, p), seg_distance(m2, e1, p)));
}

/* The moving walls (node_ID): each becomes a body of its node, of its
 * Mass, translating only (its rotations held), starting at VX0 VY0 VZ0,
 * whose surface is the wall's with M at the node. Writes x->c's rwall,
 * rbody, grnod, bcs and inivel arrays (copies) and x->wall_body. */
static rc_status moving_walls(const rc_case *c, rc_rwall_case *x, rc_error *err)
{
    int nm = 0, gmin = 0;
    for (int w = 0; w < c->nrwall; w++) nm += c->rwall[w].node_id != 0;
    for (int g = 0; g < c->ngrnod; g++) gmin = c->grnod[g].id < gmin ? c->grnod[g].id : gmin;
    x->rwall = malloc(((size_t)c->nrwall + 1) * sizeof *x->rwall);
    x->wall_body = malloc(((size_t)c->nrwall + 1) * sizeof *x->wall_body);
    x->wall_node = calloc((size_t)c->nrwall + 1, sizeof *x->wall_node);
    x->rbody = calloc((size_t)(c->nrbody + nm) + 1, sizeof *x->rbody);
    x->grnod = calloc((size_t)(c->ngrnod + nm) + 1, sizeof *x->grnod);
    x->bcs = calloc((size_t)(c->nbcs + nm) + 1, sizeof *x->bcs);
    x->inivel = calloc((size_t)(c->ninivel + nm) + 1, sizeof *x->inivel);
    if (!x->rwall || !x->wall_body || !x->wall_node || !x->rbody || !x->grnod || !x->bcs || !x->inivel)
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    memcpy(x->rwall, c->rwall, (size_t)c->nrwall * sizeof *x->rwall);
    if (c->nrbody) memcpy(x->rbody, c->rbody, (size_t)c->nrbody * sizeof *x->rbody);
    if (c->ngrnod) memcpy(x->grnod, c->grnod, (size_t)c->ngrnod * sizeof *x->grnod);
    if (c->nbcs) memcpy(x->bcs, c->bcs, (size_t)c->nbcs * sizeof *x->bcs);
    if (c->ninivel) memcpy(x->inivel, c->inivel, (size_t)c->ninivel * sizeof *x->inivel);
    int nb = c->nrbody, ng = c->ngrnod, nc = c->nbcs, ni = c->ninivel;
    for (int w = 0; w < c->nrwall; w++) {
        rc_case_rwall *rw = &x->rwall[w];
        x->wall_body[w] = -1;
        if (rw->node_id == 0) continue;
        const rc_loc l1 = rc_loc_or(rw->line_loc[0], rw->loc), l3 = rc_loc_or(rw->line_loc[2], rw->loc);
        const int n = rc_case_find_node(c, rw->node_id);
        if (n < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /RWALL/%s/%d, field node_ID: expected the id of a /NODE, got %d (no such node)",
                     RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, rw->node_id);
        const int ob = rc_case_body_of_node(c, rw->node_id);
        if (ob >= 0)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RWALL/%s/%d, field node_ID: node %d belongs to /RBODY/%d: a moving wall on the node of "
                     "a body (which may turn) is not supported yet; expected a node of no body (the wall's own, of mass "
                     "Mass), or a surface carried by the body with an /INTER/TYPE6",
                     RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, rw->node_id, c->rbody[ob].id);
        /* M at the node; M1 must stay apart */
        memcpy(rw->m, c->node[n].x, sizeof rw->m);
        if (rw->kind != RC_RWALL_SPHER && rw->m[0] == rw->m1[0] && rw->m[1] == rw->m1[1] && rw->m[2] == rw->m1[2])
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card /RWALL/%s/%d, field XM1 YM1 ZM1: expected a point M1 different from the wall's node %d "
                     "(M of a moving wall), got M1 = (%.9g, %.9g, %.9g)",
                     RC_LOC(rc_loc_or(rw->line_loc[3], rw->loc)), rc_rwall_type[rw->kind], rw->id, rw->node_id,
                     rw->m1[0], rw->m1[1], rw->m1[2]);
        /* its body: the node, its mass, an inertia for the held rotations
         * (the mass at the wall's size: never used, the rotations are held) */
        const double a = rw->kind == RC_RWALL_SPHER ? 0.5 * rw->diameter
                                                    : sqrt((rw->m1[0] - rw->m[0]) * (rw->m1[0] - rw->m[0]) +
                                                           (rw->m1[1] - rw->m[1]) * (rw->m1[1] - rw->m[1]) +
                                                           (rw->m1[2] - rw->m[2]) * (rw->m1[2] - rw->m[2]));
        const double jw = rw->mass * a * a;
        x->wall_node[w] = rw->node_id;
        x->wall_body[w] = nb;
        x->rbody[nb++] = (rc_case_rbody){.id = -rw->id, .node_id = rw->node_id, .ispher = 3, .mass = rw->mass,
                                         .J = {jw, jw, jw, 0.0, 0.0, 0.0}, .loc = rw->loc,
                                         .line_loc = {l3, l3, l3, {NULL, 0}, {NULL, 0}}};
        snprintf(x->rbody[nb - 1].title, sizeof x->rbody[nb - 1].title, "moving wall /RWALL/%s/%d",
                 rc_rwall_type[rw->kind], rw->id);
        const int gid = gmin - 1 - w;
        x->grnod[ng++] = (rc_case_grnod){.id = gid, .n = 1, .nodes = &x->wall_node[w], .loc = l1};
        x->bcs[nc++] = (rc_case_bcs){.id = -rw->id, .fix = {0, 0, 0, 1, 1, 1}, .grnod_id = gid, .loc = rw->loc,
                                     .line_loc = l1};
        x->inivel[ni++] = (rc_case_inivel){.id = -rw->id, .v = {rw->v0[0], rw->v0[1], rw->v0[2]}, .grnod_id = gid,
                                           .loc = rw->loc, .line_loc = l3};
    }
    x->c.rwall = x->rwall;
    x->c.rbody = x->rbody;
    x->c.nrbody = nb;
    x->c.grnod = x->grnod;
    x->c.ngrnod = ng;
    x->c.bcs = x->bcs;
    x->c.nbcs = nc;
    x->c.inivel = x->inivel;
    x->c.ninivel = ni;
    return RC_OK;
}

rc_status rc_rwall_begin(const rc_case *c, rc_rwall_case *x, rc_error *err)
{
    memset(x, 0, sizeof *x);
    x->c = *c;
    if (c->nrwall == 0) return RC_OK;
    x->c.index = NULL; /* the copy gets its own below (the case's stays the case's) */
    x->surf = calloc((size_t)(c->nsurf + c->nrwall), sizeof *x->surf);
    x->funct = calloc((size_t)c->nfunct + 1, sizeof *x->funct);
    x->nodes = calloc((size_t)c->nrwall * (size_t)(c->nnode + 1), 1);
    x->nuser = c->nsurf;
    if (!x->surf || !x->funct || !x->nodes) {
        rc_rwall_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    if (c->nsurf) memcpy(x->surf, c->surf, (size_t)c->nsurf * sizeof *x->surf);
    if (c->nfunct) memcpy(x->funct, c->funct, (size_t)c->nfunct * sizeof *x->funct);
    rc_status st = moving_walls(c, x, err);
    if (st) {
        rc_rwall_end(x);
        return st;
    }
    c = &x->c; /* the walls with their points M, the moving walls' bodies */
    x->acts = calloc((size_t)c->nrwall * (size_t)(c->nrbody + 1), 1);
    if (!x->acts) {
        rc_rwall_end(x);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    /* the load curve of every wall: y = x, scaled per contact */
    x->fx[1] = x->fy[1] = 1.0;
    x->funct[c->nfunct] = (rc_case_funct){.id = -1, .npts = 2, .x = x->fx, .y = x->fy, .loc = c->end};
    /* the scene's size seen from each cylinder's M */
    for (int w = 0; w < c->nrwall; w++) {
        const rc_case_rwall *rw = &c->rwall[w];
        rc_case_surf *s = &x->surf[x->nuser + w];
        s->id = -rw->id;
        s->loc = s->rbody_loc = rw->loc;
        s->rbody_id = rw->node_id ? -rw->id : 0; /* a moving wall: on its body */
        memcpy(s->m, rw->m, sizeof s->m);
        memcpy(s->m1, rw->m1, sizeof s->m1);
        memcpy(s->c, rw->m, sizeof s->c);
        s->degree = 2;
        s->abc[0] = s->abc[1] = s->abc[2] = 0.5 * rw->diameter;
        if (rw->kind == RC_RWALL_PLANE) {
            s->kind = RC_CASE_SURF_PLANE;
        } else if (rw->kind == RC_RWALL_PARAL) {
            /* the plane through M, M1, M2, normal e1 x e2, bounded to the
             * parallelogram M, M1, M1 + M2 - M, M2 */
            double e1[3], e2[3], n[3];
            parallelogram(rw, e1, e2, n);
            s->kind = RC_CASE_SURF_PLANE;
            s->bounded = 1;
            for (int k = 0; k < 3; k++) {
                s->m1[k] = rw->m[k] + n[k];
                s->e1[k] = e1[k];
                s->e2[k] = e2[k];
            }
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
    x->c.nsurf = x->nuser + c->nrwall;
    x->c.funct = x->funct;
    x->c.nfunct = c->nfunct + 1;
    /* the copy's own index: its look-ups stay O(log N) (case/lookup.c;
     * the contacts and points appended later are few look-ups) */
    x->c.index = NULL;
    st = rc_case_index_build(&x->c, err);
    if (st) rc_rwall_end(x);
    return st;
}

/* Distance of point p from the surface of wall rw at t = 0 [m]. */
static double wall_distance(const rc_case_rwall *rw, const double *p)
{
    if (rw->kind == RC_RWALL_PARAL) return paral_distance(rw, p);
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

rc_status rc_rwall_bodies(rc_rwall_case *x, rc_model *m, rc_error *err)
{
    const rc_case *c = &x->c;
    if (c->nrwall == 0) return RC_OK;
    /* a moving wall feels the /GRAV cards whose group holds its node, not
     * those without a group (which act on the deck's bodies) */
    for (int w = 0; w < c->nrwall; w++) {
        const int b = x->wall_body[w];
        if (b < 0) continue;
        for (int k = 0; k < 3; k++) m->body_grav[3 * b + k] = 0.0;
        for (int k = 0; k < c->ngrav; k++) {
            const int g = c->grav[k].grnod_id ? rc_case_find_grnod(c, c->grav[k].grnod_id) : -1;
            int in = 0;
            for (int j = 0; g >= 0 && j < c->grnod[g].n; j++) in |= c->grnod[g].nodes[j] == c->rwall[w].node_id;
            if (in)
                for (int i = 0; i < 3; i++) m->body_grav[3 * b + i] += c->grav[k].fscale * c->grav[k].u[i];
        }
    }
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
            /* a fixed body is left out (a fixed wall never meets it); a
             * wall's own body (a moving wall) is no body a wall acts on */
            if (m->body_fixed[b]) continue;
            int wall = 0;
            for (int v = 0; v < c->nrwall; v++) wall |= x->wall_body[v] == b;
            if (wall) continue;
            x->acts[(size_t)w * (size_t)c->nrbody + (size_t)b] = 1;
            x->nodes[(size_t)w * (size_t)c->nnode + (size_t)n] = 1;
        }
    }
    free(flag);
    return st;
}


/* `p` (of `used` bytes in use) grown to `size` bytes, the new bytes zero;
 * NULL when out of memory (p unchanged). */
static void *grow_bytes(void *p, size_t size, size_t used)
{
    char *q = realloc(p, size);
    if (q) memset(q + used, 0, size - used);
    return q;
}

/* Grow the model array `arr` from n to n + add entries (the new ones zero);
 * evaluates to 1 when out of memory (arr unchanged). */
#define GROW(arr, n, add)                                                                                        \
    (tmp = grow_bytes((arr), ((size_t)((n) + (add)) + 1) * sizeof *(arr), (size_t)(n) * sizeof *(arr))) == NULL \
        ? 1                                                                                                      \
        : ((arr) = tmp, 0)

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
    for (int s = 0; s < x->nuser; s++) /* a TYPE7's points are no surface of the body's own */
        if (m->surf_body[s] >= 0 && !rc_type7_is_points(c->surf[s].id)) bare[m->surf_body[s]] = 0;
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
    void *tmp;
    if (!ns || !x->pts_wall || !x->pts_node || GROW(m->surf_id, s0, n) || GROW(m->surf_kind, s0, n) ||
        GROW(m->surf_body, s0, n) || GROW(m->surf_p, 3 * s0, 3 * n) || GROW(m->surf_n, 3 * s0, 3 * n) ||
        GROW(m->surf_r, s0, n) || GROW(m->surf_ext, RC_SURF_NEXT * s0, RC_SURF_NEXT * n) ||
        GROW(m->surf_nadr, s0 + 1, n) || GROW(m->surf_sadr, s0 + 1, n)) {
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
    const int nuser = x->nuser, p0 = nuser + c->nrwall;
    /* one contact per wall and surface of a body it acts on (the deck's
     * surfaces, or the wall's own points of a body without surfaces) */
    int n = x->npts;
    for (int w = 0; w < c->nrwall; w++)
        for (int s = 0; s < nuser; s++)
            if (m->surf_body[s] >= 0 && !rc_type7_is_points(c->surf[s].id) &&
                x->acts[(size_t)w * (size_t)c->nrbody + (size_t)m->surf_body[s]])
                n++;
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
                if (rc_type7_is_points(c->surf[s].id)) continue; /* a TYPE7's points (model/type7.c) */
                if (m->surf_body[s] != b || (s >= p0 && x->pts_wall[s - p0] != w)) continue;
                const rc_case_surf *cs = &c->surf[s];
                if ((rw->kind == RC_RWALL_CYL || rw->kind == RC_RWALL_PARAL) && cs->kind != RC_CASE_SURF_ELLIPS)
                    RC_RAISE(err, RC_EINPUT,
                             RC_LOCFMT "card /RWALL/%s/%d, field grnd_ID1: the wall acts on /RBODY/%d, whose surface "
                             "/SURF/%s/%d is not a sphere: an /RWALL/%s against anything but a sphere (/SURF/ELLIPS) "
                             "is not supported yet",
                             RC_LOC(l1), rc_rwall_type[rw->kind], rw->id, c->rbody[b].id, rc_case_surf_kind_name(cs->kind), cs->id,
                             rc_rwall_type[rw->kind]);
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
                             rw->id, rc_case_surf_kind_name(cs->kind), cs->id);
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
    if (x->surf) rc_case_index_free(x->c.index); /* the copy's own (rc_rwall_begin) */
    free(x->surf);
    free(x->type6);
    free(x->funct);
    free(x->name);
    free(x->acts);
    free(x->nodes);
    free(x->rwall);
    free(x->rbody);
    free(x->grnod);
    free(x->bcs);
    free(x->inivel);
    free(x->wall_body);
    free(x->wall_node);
    for (int k = 0; x->pts_node && k < x->npts; k++) free(x->pts_node[k]);
    free(x->pts_node);
    free(x->pts_wall);
    memset(x, 0, sizeof *x);
}
