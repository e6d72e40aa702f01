/*
 * Segment surfaces (/SURF/SEG, /SURF/PART) into the model: their segments
 * (triangles, quadrilaterals) and nodes in the frame of the rigid body that
 * carries them (docs/case-format.md, docs/theory.md 2.7).
 *   /SURF/SEG:  the segments as written.
 *   /SURF/PART: the outer faces of the parts' elements: every shell (/SHELL,
 *               /SH3N) as it is, and the faces of the solids (/BRICK,
 *               /TETRA4) that no other solid of the listed parts shares,
 *               turned to point out of their solid.
 * All nodes of a surface belong to one /RBODY (the surface moves with it)
 * or to none (the surface is fixed in space); anything else is an input
 * error naming the card, the line and the two nodes.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case.h"
#include "case/case_mesh.h"
#include "model/model.h"
#include "model/segsurf.h"

typedef struct seg_face {
    int node[4]; /* node ids; node[3] = 0: a triangle */
    int key[4];  /* sorted ids, for finding shared faces */
    int solid;   /* 1: face of a solid (dropped when two solids share it) */
    int turned;  /* 1: turned to point out of its solid */
    rc_loc loc;  /* the element's or the segment's line */
} seg_face;

static int cmp_int(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static int cmp_face(const void *a, const void *b)
{
    const seg_face *x = a, *y = b;
    for (int k = 0; k < 4; k++)
        if (x->key[k] != y->key[k]) return (x->key[k] > y->key[k]) - (x->key[k] < y->key[k]);
    return (x->solid > y->solid) - (x->solid < y->solid);
}

static void face_key(seg_face *f)
{
    for (int k = 0; k < 4; k++) f->key[k] = f->node[k];
    qsort(f->key, 4, sizeof(int), cmp_int);
}

static const double *node_x(const rc_case *c, int id)
{
    const int k = rc_case_find_node(c, id);
    return k >= 0 ? c->node[k].x : NULL;
}

/* Face of a solid from its corner nodes (repeated nodes of a degenerate
 * element removed); turned so that its normal points away from the solid's
 * centre `ctr`. Returns 0 when fewer than 3 distinct nodes remain. */
static int solid_face(const rc_case *c, const int *v, int nv, const double *ctr, seg_face *f)
{
    int u[4], nu = 0;
    for (int k = 0; k < nv; k++) {
        int dup = 0;
        for (int j = 0; j < nu; j++) dup |= u[j] == v[k];
        if (!dup) u[nu++] = v[k];
    }
    if (nu < 3) return 0;
    const double *x[4];
    for (int k = 0; k < nu; k++)
        if (!(x[k] = node_x(c, u[k]))) return -1;
    /* normal: (x2 - x0) x (x3 - x1) for a quadrilateral, (x1 - x0) x (x2 - x0)
     * for a triangle; centre of the face */
    double a[3], b[3], n[3], fc[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++) {
        a[k] = nu == 4 ? x[2][k] - x[0][k] : x[1][k] - x[0][k];
        b[k] = nu == 4 ? x[3][k] - x[1][k] : x[2][k] - x[0][k];
        for (int j = 0; j < nu; j++) fc[k] += x[j][k] / nu;
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
    const double out = n[0] * (fc[0] - ctr[0]) + n[1] * (fc[1] - ctr[1]) + n[2] * (fc[2] - ctr[2]);
    memset(f->node, 0, sizeof f->node);
    for (int k = 0; k < nu; k++) f->node[k] = out < 0 ? u[nu - 1 - k] : u[k];
    f->solid = 1;
    f->turned = out < 0;
    face_key(f);
    return 1;
}

/* Faces of the elements of the parts of /SURF/PART card cs. */
static rc_status part_faces(const rc_case *c, const rc_case_surf *cs, seg_face **out, int *nout, rc_error *err)
{
    static const int hexf[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    static const int tetf[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    const rc_case_mesh *ms = c->mesh;
    for (int k = 0; k < cs->npart; k++)
        if (rc_case_find_part(c, cs->part[k]) < 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /SURF/PART/%d, field part_ID: expected the id of a /PART, got %d (no such part)",
                     RC_LOC(cs->part_loc[k]), cs->id, cs->part[k]);
    int *parts = malloc((size_t)cs->npart * sizeof(int));
    if (!parts) RC_RAISE(err, RC_ENOMEM, "out of memory");
    memcpy(parts, cs->part, (size_t)cs->npart * sizeof(int));
    qsort(parts, (size_t)cs->npart, sizeof(int), cmp_int);
    int n = 0, cap = 0;
    seg_face *f = NULL;
    rc_status st = RC_OK;
    for (int e = 0; ms && e < ms->nelem && !st; e++) {
        const rc_case_elem *el = &ms->elem[e];
        if (!bsearch(&el->part_id, parts, (size_t)cs->npart, sizeof(int), cmp_int)) continue;
        if (n + 6 > cap) {
            cap = 2 * cap + 64;
            seg_face *g = realloc(f, (size_t)cap * sizeof *f);
            if (!g) {
                st = RC_SET(err, RC_ENOMEM, "out of memory");
                break;
            }
            f = g;
        }
        double ctr[3] = {0, 0, 0};
        /* a quadratic tetrahedron's faces: the triangles of its corners */
        const int nc = el->kind == RC_ELEM_TETRA10 ? 4 : el->nn;
        for (int j = 0; j < nc; j++) {
            const double *x = node_x(c, el->nodes[j]);
            if (!x) {
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "element %d of part %d (for /SURF/PART/%d), field node_ID%d: expected the id of a /NODE, got %d (no such node)",
                            RC_LOC(el->loc), el->id, el->part_id, cs->id, j + 1, el->nodes[j]);
                break;
            }
            for (int k = 0; k < 3; k++) ctr[k] += x[k] / nc;
        }
        if (st) break;
        if (el->kind == RC_ELEM_SHELL || el->kind == RC_ELEM_SH3N) {
            seg_face *g = &f[n++];
            memset(g, 0, sizeof *g);
            for (int j = 0; j < el->nn && j < 4; j++) g->node[j] = el->nodes[j];
            g->solid = 0;
            g->turned = 0;
            g->loc = el->loc;
            face_key(g);
            continue;
        }
        /* a pentahedron as the degenerate brick 1 2 3 3 4 5 6 6 */
        const int hexlike = el->kind == RC_ELEM_BRICK || el->kind == RC_ELEM_PENTA6;
        static const int pmap[8] = {0, 1, 2, 2, 3, 4, 5, 5}, bmap[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        const int *hmap = el->kind == RC_ELEM_PENTA6 ? pmap : bmap;
        const int nf = hexlike ? 6 : 4, nv = hexlike ? 4 : 3;
        for (int q = 0; q < nf; q++) {
            int v[4];
            for (int j = 0; j < nv; j++) v[j] = el->nodes[nv == 4 ? hmap[hexf[q][j]] : tetf[q][j]];
            int r = solid_face(c, v, nv, ctr, &f[n]);
            if (r > 0) f[n++].loc = el->loc;
        }
    }
    free(parts);
    if (st) {
        free(f);
        return st;
    }
    /* drop the faces two solids share (inside the parts) */
    qsort(f, (size_t)n, sizeof *f, cmp_face);
    int m = 0;
    for (int a = 0; a < n;) {
        int b = a + 1;
        while (b < n && memcmp(f[b].key, f[a].key, sizeof f[a].key) == 0) b++;
        int nsolid = 0;
        for (int k = a; k < b; k++) nsolid += f[k].solid;
        for (int k = a; k < b; k++)
            if (!(f[k].solid && nsolid >= 2)) f[m++] = f[k];
        a = b;
    }
    *out = f;
    *nout = m;
    if (m == 0) {
        free(f);
        *out = NULL;
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card /SURF/PART/%d, field part_ID: the parts have no shell or solid element: the surface has no face",
                 RC_LOC(cs->part_loc[0]), cs->id);
    }
    return RC_OK;
}

rc_status rc_seg_surface(const rc_case *c, rc_model *m, int s, rc_error *err)
{
    const rc_case_surf *cs = &c->surf[s];
    const char *kind = cs->kind == RC_CASE_SURF_SEG ? "SEG" : "PART";
    seg_face *f = NULL;
    int nf = 0;
    rc_status st = RC_OK;
    if (cs->kind == RC_CASE_SURF_PART) {
        if ((st = part_faces(c, cs, &f, &nf, err))) return st;
    } else {
        f = malloc((size_t)cs->nseg * sizeof *f);
        if (!f) RC_RAISE(err, RC_ENOMEM, "out of memory");
        nf = cs->nseg;
        for (int k = 0; k < nf; k++) {
            memcpy(f[k].node, cs->seg + 4 * k, sizeof f[k].node);
            f[k].loc = cs->seg_loc[k];
            f[k].solid = 0;
            f[k].turned = 0;
        }
    }
    /* the nodes: sorted unique ids (a rigid wall's contact points: its
     * nodes of one body alone, model/rwall.c) */
    int *ids = malloc((size_t)(4 * nf + cs->npoint + 1) * sizeof(int)), nn = 0;
    if (!ids) {
        free(f);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int k = 0; k < nf; k++)
        for (int j = 0; j < 4; j++)
            if (f[k].node[j]) ids[nn++] = f[k].node[j];
    for (int k = 0; k < cs->npoint; k++) ids[nn++] = cs->point[k];
    qsort(ids, (size_t)nn, sizeof(int), cmp_int);
    int u = 0;
    for (int k = 0; k < nn; k++)
        if (u == 0 || ids[k] != ids[u - 1]) ids[u++] = ids[k];
    nn = u;
    /* each node exists; all on one body or none */
    int body = -2, first = 0;
    rc_loc floc = cs->loc;
    for (int k = 0; k < nf && !st; k++)
        for (int j = 0; j < 4 && !st; j++) {
            const int id = f[k].node[j];
            if (!id) continue;
            if (!node_x(c, id)) {
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /SURF/%s/%d, field node_ID%d: expected the id of a /NODE, got %d (no such node)",
                            RC_LOC(f[k].loc), kind, cs->id, j + 1, id);
                break;
            }
            const int b = rc_case_body_of_node(c, id);
            if (body == -2) {
                body = b;
                first = id;
                floc = f[k].loc;
            } else if (b != body) {
                char wb[64], wa[64];
                if (b >= 0) snprintf(wb, sizeof wb, "/RBODY/%d", c->rbody[b].id);
                else snprintf(wb, sizeof wb, "no /RBODY");
                if (body >= 0) snprintf(wa, sizeof wa, "/RBODY/%d", c->rbody[body].id);
                else snprintf(wa, sizeof wa, "no /RBODY");
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card /SURF/%s/%d, field node_ID%d: node %d belongs to %s, but node %d (line %d) belongs to %s: all nodes of a segment surface must belong to one rigid body (or all to none: the surface is then fixed in space)",
                            RC_LOC(f[k].loc), kind, cs->id, j + 1, id, wb, first, floc.line, wa);
            }
        }
    if (st) goto done;
    if (cs->npoint > 0 && nf == 0) body = rc_case_body_of_node(c, cs->point[0]);
    const int b = body < 0 ? -1 : body;
    const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
    const int n0 = m->surf_nadr[s], s0 = m->surf_sadr[s];
    double *nx = realloc(m->surf_node, (size_t)(3 * (n0 + nn) + 1) * sizeof(double));
    if (!nx) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    m->surf_node = nx;
    int *sg = realloc(m->surf_seg, (size_t)(4 * (s0 + nf) + 1) * sizeof(int));
    if (!sg) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    m->surf_seg = sg;
    signed char *tu = realloc(m->surf_seg_turned, (size_t)(s0 + nf + 1));
    if (!tu) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    m->surf_seg_turned = tu;
    int *ni = realloc(m->surf_nid, (size_t)(n0 + nn + 1) * sizeof(int));
    if (!ni) {
        st = RC_SET(err, RC_ENOMEM, "out of memory");
        goto done;
    }
    m->surf_nid = ni;
    for (int k = 0; k < nn; k++) ni[n0 + k] = ids[k];
    for (int k = 0; k < nf; k++) tu[s0 + k] = (signed char)f[k].turned;
    for (int k = 0; k < nn; k++) {
        const double *x = node_x(c, ids[k]);
        for (int j = 0; j < 3; j++) nx[3 * (n0 + k) + j] = x[j] - org[j];
    }
    for (int k = 0; k < nf; k++) {
        int *q = sg + 4 * (s0 + k);
        for (int j = 0; j < 4; j++) {
            const int id = f[k].node[j] ? f[k].node[j] : f[k].node[2];
            q[j] = (int)((const int *)bsearch(&id, ids, (size_t)nn, sizeof(int), cmp_int) - ids);
        }
    }
    m->surf_nadr[s + 1] = n0 + nn;
    m->surf_sadr[s + 1] = s0 + nf;
    m->surf_id[s] = cs->id;
    m->surf_kind[s] = RC_SURF_SEG;
    m->surf_body[s] = b;
    for (int j = 0; j < 3; j++) m->surf_p[3 * s + j] = m->surf_n[3 * s + j] = 0.0;
    m->surf_r[s] = 0.0;
done:
    free(ids);
    free(f);
    return st;
}

/* ---- adjacency and broad-phase grid ------------------------------------ */

/* 1 when segment q is flat (its corners within 1e-12 of its extent of the
 * plane through its centre), non-degenerate and convex; *slack (not NULL):
 * how far outside it the foot test's edge tolerance lets a point lie,
 * 1e-9 of its longest edge over sin(half its sharpest angle) [m]. */
static int seg_flat(const double *x, const int *seg, const rc_segmesh *g, int q, double *slack)
{
    const int *v = seg + 4 * q, nc = v[3] == v[2] ? 3 : 4;
    const double *c = g->scen + 3 * q, *n = g->snrm + 3 * q, *bx = g->sbox + 6 * q;
    const double ext = fmax(bx[3] - bx[0], fmax(bx[4] - bx[1], bx[5] - bx[2]));
    if (!(ext > 0) || (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)) return 0;
    double lmax = 0.0, smin = 1.0;
    for (int j = 0; j < nc; j++) {
        const double *p = x + 3 * v[j], *p0 = x + 3 * v[(j + nc - 1) % nc], *p1 = x + 3 * v[(j + 1) % nc];
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = p[k] - p0[k];
            b[k] = p1[k] - p[k];
        }
        const double turn = (a[1] * b[2] - a[2] * b[1]) * n[0] + (a[2] * b[0] - a[0] * b[2]) * n[1] +
                            (a[0] * b[1] - a[1] * b[0]) * n[2];
        if (!(turn > 0.0)) return 0;
        if (fabs((p[0] - c[0]) * n[0] + (p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2]) > 1e-12 * ext) return 0;
        const double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]), lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
        if (!(la > 0) || !(lb > 0)) return 0;
        /* interior angle alpha at p: cos alpha = -a.b / (|a||b|) */
        const double ca = -(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
        smin = fmin(smin, sqrt(fmax(0.0, 0.5 * (1.0 - ca))));
        lmax = fmax(lmax, la);
    }
    if (!(smin > 0)) return 0;
    if (slack) *slack = 1e-9 * lmax / smin;
    return 1;
}

/* Bin n items into the grid's cells (counting sort): item q covers the
 * cells of rng[6 q .. 6 q + 5] (i, j, l ranges, inclusive; empty when a
 * lower bound passes its upper one); adr [ncell + 1] zeroed on entry gets
 * the offsets, *list (allocated) the items of each cell in order. 0, or
 * -1 out of memory. */
static int grid_bin(const rc_segmesh *g, int ncell, const int *rng, int n, int *adr, int **list)
{
    for (int pass = 0; pass < 2; pass++) {
        for (int q = 0; q < n; q++) {
            const int *r = rng + 6 * q;
            for (int i = r[0]; i <= r[1]; i++)
                for (int j = r[2]; j <= r[3]; j++)
                    for (int l = r[4]; l <= r[5]; l++) {
                        const int c = (i * g->dim[1] + j) * g->dim[2] + l;
                        if (pass == 0) adr[c + 1]++;
                        else (*list)[adr[c]++] = q;
                    }
        }
        if (pass == 0) {
            for (int c = 0; c < ncell; c++) adr[c + 1] += adr[c];
            if (!(*list = malloc((size_t)adr[ncell] * sizeof(int) + sizeof(int)))) return -1;
        } else {
            for (int c = ncell; c > 0; c--) adr[c] = adr[c - 1];
            adr[0] = 0;
        }
    }
    return 0;
}

/* The node grid of surface s (segsurf.h, rc_segmesh.ncadr): the cells of
 * the broad-phase grid, each segment over its widened box. */
static rc_status node_grid(const rc_model *m, int s, rc_segmesh *g, int ncell, rc_error *err)
{
    const double *x = m->surf_node + 3 * m->surf_nadr[s];
    const int *seg = m->surf_seg + 4 * m->surf_sadr[s];
    /* rounding of coordinates far from the origin */
    double big = 0.0;
    for (int k = 0; k < 3; k++) big = fmax(big, fmax(fabs(g->lo[k]), fabs(g->lo[k] + g->dim[k] * g->h)));
    int *rng = malloc((size_t)(6 * g->ns + 1) * sizeof(int));
    g->ncadr = calloc((size_t)ncell + 1, sizeof(int));
    if (!rng || !g->ncadr) {
        free(rng);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int q = 0; q < g->ns; q++) {
        const int *v = seg + 4 * q, nc = v[3] == v[2] ? 3 : 4;
        const double *c = g->scen + 3 * q, *n = g->snrm + 3 * q, *bx = g->sbox + 6 * q;
        double warp = 0.0, ext = 0.0;
        int convex = n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
        for (int j = 0; j < nc; j++) {
            const double *p = x + 3 * v[j], *p0 = x + 3 * v[(j + nc - 1) % nc], *p1 = x + 3 * v[(j + 1) % nc];
            double a[3], b[3];
            for (int k = 0; k < 3; k++) {
                a[k] = p[k] - p0[k];
                b[k] = p1[k] - p[k];
            }
            const double turn = (a[1] * b[2] - a[2] * b[1]) * n[0] + (a[2] * b[0] - a[0] * b[2]) * n[1] +
                                (a[0] * b[1] - a[1] * b[0]) * n[2];
            convex &= turn > 0.0;
            warp = fmax(warp, fabs((p[0] - c[0]) * n[0] + (p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2]));
        }
        for (int k = 0; k < 3; k++) ext = fmax(ext, bx[3 + k] - bx[k]);
        /* the edge tolerance of the foot test and rounding, amply */
        const double tol = 1e-6 * ext + 1e-12 * big;
        for (int k = 0; k < 3; k++) {
            const double e = (convex ? (g->depth + warp) * fabs(n[k]) : g->depth) + tol;
            /* wholly outside: an empty range (not entered) */
            rc_seggrid_cells(g, k, bx[k] - e, bx[3 + k] + e, rng + 6 * q + 2 * k, rng + 6 * q + 2 * k + 1);
        }
    }
    if (grid_bin(g, ncell, rng, g->ns, g->ncadr, &g->ncseg)) {
        free(rng);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    /* isolated segments (segsurf.h) */
    g->iso = calloc((size_t)g->ns + 1, 1);
    int *stamp = malloc((size_t)(g->ns + 1) * sizeof(int));
    if (!g->iso || !stamp) {
        free(rng);
        free(stamp);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    for (int q = 0; q < g->ns; q++) stamp[q] = -1;
    for (int q = 0; q < g->ns; q++) {
        if (!seg_flat(x, seg, g, q, NULL)) continue;
        const int *r = rng + 6 * q, *v = seg + 4 * q, nc = v[3] == v[2] ? 3 : 4;
        const double *n = g->snrm + 3 * q, *c = g->scen + 3 * q;
        double emin = INFINITY;
        for (int e = 0; e < nc; e++) {
            const double *p0 = x + 3 * v[e], *p1 = x + 3 * v[(e + 1) % nc];
            emin = fmin(emin, sqrt((p1[0] - p0[0]) * (p1[0] - p0[0]) + (p1[1] - p0[1]) * (p1[1] - p0[1]) +
                                   (p1[2] - p0[2]) * (p1[2] - p0[2])));
        }
        const double ext = fmax(g->sbox[6 * q + 3] - g->sbox[6 * q],
                                fmax(g->sbox[6 * q + 4] - g->sbox[6 * q + 1], g->sbox[6 * q + 5] - g->sbox[6 * q + 2]));
        int ok = emin >= 1e-9 * big; /* rounding of the coordinates well below the margins */
        for (int i = r[0]; ok && i <= r[1]; i++)
            for (int j = r[2]; ok && j <= r[3]; j++)
                for (int l = r[4]; ok && l <= r[5]; l++) {
                    const int cell = (i * g->dim[1] + j) * g->dim[2] + l;
                    for (int a = g->ncadr[cell]; ok && a < g->ncadr[cell + 1]; a++) {
                        const int u = g->ncseg[a];
                        if (u == q || stamp[u] == q) continue;
                        stamp[u] = q;
                        const double *nu = g->snrm + 3 * u;
                        double slack;
                        /* the same plane, flat and convex */
                        ok = nu[0] == n[0] && nu[1] == n[1] && nu[2] == n[2] && seg_flat(x, seg, g, u, &slack);
                        const int *vu = seg + 4 * u, ncu = vu[3] == vu[2] ? 3 : 4;
                        for (int t = 0; ok && t < ncu; t++) {
                            const double *p = x + 3 * vu[t];
                            ok = fabs((p[0] - c[0]) * n[0] + (p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2]) <= 1e-12 * ext;
                        }
                        /* beyond an edge line of q, with room for u's edge
                         * tolerance against q's margin (geom_seg.inc) */
                        ok = ok && slack <= 1e-7 * emin;
                        int sep = 0;
                        for (int e = 0; ok && !sep && e < nc; e++) {
                            const double *p0 = x + 3 * v[e], *p1 = x + 3 * v[(e + 1) % nc];
                            const double ed[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
                            const double l2 = ed[0] * ed[0] + ed[1] * ed[1] + ed[2] * ed[2];
                            sep = 1;
                            for (int t = 0; sep && t < ncu; t++) {
                                const double *p = x + 3 * vu[t], rp[3] = {p[0] - p0[0], p[1] - p0[1], p[2] - p0[2]};
                                const double cr = (ed[1] * rp[2] - ed[2] * rp[1]) * n[0] +
                                                  (ed[2] * rp[0] - ed[0] * rp[2]) * n[1] +
                                                  (ed[0] * rp[1] - ed[1] * rp[0]) * n[2];
                                sep = cr <= 1e-12 * l2;
                            }
                        }
                        ok = ok && sep;
                    }
                }
        g->iso[q] = (unsigned char)ok;
    }
    free(stamp);
    free(rng);
    return RC_OK;
}

static rc_status seg_mesh(rc_model *m, int s, rc_segmesh *g, rc_error *err)
{
    const int n0 = m->surf_nadr[s], s0 = m->surf_sadr[s];
    g->nn = m->surf_nadr[s + 1] - n0;
    g->ns = m->surf_sadr[s + 1] - s0;
    const double *x = m->surf_node + 3 * n0;
    const int *seg = m->surf_seg + 4 * s0;
    g->vadr = calloc((size_t)g->nn + 1, sizeof(int));
    g->vseg = malloc((size_t)(4 * g->ns + 1) * sizeof(int));
    g->srange = malloc((size_t)(6 * g->ns + 1) * sizeof(int));
    g->sbox = malloc((size_t)(6 * g->ns + 1) * sizeof(double));
    if (!g->vadr || !g->vseg || !g->srange || !g->sbox) RC_RAISE(err, RC_ENOMEM, "out of memory");
    /* segments of each node (a triangle's repeated corner counted once) */
    for (int k = 0; k < g->ns; k++)
        for (int j = 0; j < 4; j++)
            if (j < 3 || seg[4 * k + 3] != seg[4 * k + 2]) g->vadr[seg[4 * k + j] + 1]++;
    for (int j = 0; j < g->nn; j++) g->vadr[j + 1] += g->vadr[j];
    int *fill = calloc((size_t)g->nn + 1, sizeof(int));
    if (!fill) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int k = 0; k < g->ns; k++)
        for (int j = 0; j < 4; j++)
            if (j < 3 || seg[4 * k + 3] != seg[4 * k + 2]) {
                const int v = seg[4 * k + j];
                g->vseg[g->vadr[v] + fill[v]++] = k;
            }
    free(fill);
    /* grid: bounding box of the nodes, cell size the mean segment extent,
     * at most about 8 cells per segment */
    double hi[3], ext = 0;
    for (int k = 0; k < 3; k++) g->lo[k] = hi[k] = x[k];
    for (int j = 1; j < g->nn; j++)
        for (int k = 0; k < 3; k++) {
            g->lo[k] = fmin(g->lo[k], x[3 * j + k]);
            hi[k] = fmax(hi[k], x[3 * j + k]);
        }
    for (int q = 0; q < g->ns; q++) {
        double a[3], b[3];
        for (int k = 0; k < 3; k++) a[k] = b[k] = x[3 * seg[4 * q] + k];
        for (int j = 1; j < 4; j++)
            for (int k = 0; k < 3; k++) {
                a[k] = fmin(a[k], x[3 * seg[4 * q + j] + k]);
                b[k] = fmax(b[k], x[3 * seg[4 * q + j] + k]);
            }
        ext += fmax(b[0] - a[0], fmax(b[1] - a[1], b[2] - a[2]));
    }
    g->h = g->ns > 0 ? ext / g->ns : 0.0; /* contact points alone (a rigid wall's): the span below */
    g->depth = 0.5 * g->h;
    /* centres and unit normals (node to segment) */
    g->scen = malloc((size_t)(3 * g->ns + 1) * sizeof(double));
    g->snrm = malloc((size_t)(3 * g->ns + 1) * sizeof(double));
    if (!g->scen || !g->snrm) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int q = 0; q < g->ns; q++) {
        const int *v = seg + 4 * q, nc = v[3] == v[2] ? 3 : 4;
        double a[3], b[3], n[3], nn = 0;
        for (int k = 0; k < 3; k++) {
            g->scen[3 * q + k] = 0;
            for (int j = 0; j < nc; j++) g->scen[3 * q + k] += x[3 * v[j] + k] / nc;
            a[k] = nc == 4 ? x[3 * v[2] + k] - x[3 * v[0] + k] : x[3 * v[1] + k] - x[3 * v[0] + k];
            b[k] = nc == 4 ? x[3 * v[3] + k] - x[3 * v[1] + k] : x[3 * v[2] + k] - x[3 * v[0] + k];
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        for (int k = 0; k < 3; k++) nn += n[k] * n[k];
        nn = sqrt(nn);
        for (int k = 0; k < 3; k++) g->snrm[3 * q + k] = nn > 0 ? n[k] / nn : 0.0;
    }
    const double span = fmax(hi[0] - g->lo[0], fmax(hi[1] - g->lo[1], hi[2] - g->lo[2]));
    if (!(g->h > 0)) g->h = span > 0 ? span : 1.0;
    for (;;) {
        double ncell = 1;
        for (int k = 0; k < 3; k++) ncell *= floor((hi[k] - g->lo[k]) / g->h) + 1;
        if (ncell <= 8.0 * g->ns + 64) break;
        g->h *= 1.5;
    }
    int ncell = 1;
    for (int k = 0; k < 3; k++) {
        g->dim[k] = (int)floor((hi[k] - g->lo[k]) / g->h) + 1;
        ncell *= g->dim[k];
    }
    g->cadr = calloc((size_t)ncell + 1, sizeof(int));
    if (!g->cadr) RC_RAISE(err, RC_ENOMEM, "out of memory");
    /* each segment's box and its cells */
    for (int q = 0; q < g->ns; q++) {
        int *r = g->srange + 6 * q;
        for (int k = 0; k < 3; k++) {
            double a = x[3 * seg[4 * q] + k], b = a;
            for (int j = 1; j < 4; j++) {
                a = fmin(a, x[3 * seg[4 * q + j] + k]);
                b = fmax(b, x[3 * seg[4 * q + j] + k]);
            }
            g->sbox[6 * q + k] = a;
            g->sbox[6 * q + 3 + k] = b;
            rc_seggrid_cells(g, k, a, b, r + 2 * k, r + 2 * k + 1); /* within the grid, which spans the nodes */
        }
    }
    if (grid_bin(g, ncell, g->srange, g->ns, g->cadr, &g->cseg)) RC_RAISE(err, RC_ENOMEM, "out of memory");
    return node_grid(m, s, g, ncell, err);
}

rc_status rc_seg_meshes(rc_model *m, rc_error *err)
{
    m->surf_mesh = calloc((size_t)m->nsurf + 1, sizeof *m->surf_mesh);
    if (!m->surf_mesh) RC_RAISE(err, RC_ENOMEM, "out of memory");
    for (int s = 0; s < m->nsurf; s++) {
        if (m->surf_nadr[s + 1] == m->surf_nadr[s]) continue; /* no nodes (a box's corners have some) */
        rc_status st = seg_mesh(m, s, &m->surf_mesh[s], err);
        if (st) return st;
    }
    return RC_OK;
}

void rc_seg_free(rc_model *m)
{
    if (!m->surf_mesh) return;
    for (int s = 0; s < m->nsurf; s++) {
        rc_segmesh *g = &m->surf_mesh[s];
        free(g->vadr);
        free(g->vseg);
        free(g->srange);
        free(g->sbox);
        free(g->scen);
        free(g->snrm);
        free(g->cadr);
        free(g->cseg);
        free(g->ncadr);
        free(g->ncseg);
        free(g->iso);
    }
    free(m->surf_mesh);
    m->surf_mesh = NULL;
}

int rc_box_is_box_pair(const rc_model *m, int i)
{
    return m->inter_pair[i] == RC_PAIR_SEG_SEG && m->surf_kind[m->inter_sa[i]] == RC_SURF_BOX &&
           m->surf_kind[m->inter_sb[i]] == RC_SURF_BOX;
}

int rc_seg_points(const rc_model *m, int i)
{
    const int sa = m->inter_sa[i], sb = m->inter_sb[i];
    int n = m->surf_nadr[sa + 1] - m->surf_nadr[sa];
    if (m->inter_pair[i] == RC_PAIR_SEG_SEG && !(m->inter_oneway && m->inter_oneway[i]))
        n += m->surf_nadr[sb + 1] - m->surf_nadr[sb]; /* one way (TYPE7): the nodes of a only */
    if (rc_box_is_box_pair(m, i)) n += RC_BOX_EDGE_PAIRS;
    return n;
}
