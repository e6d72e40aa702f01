/*
 * Segment surfaces (/SURF/SEG, /SURF/PART) into the model (model/segsurf.c):
 * nodes and segments in the carrying body's frame (model.h, surf_nadr ...).
 */
#ifndef RC_SEGSURF_H
#define RC_SEGSURF_H

#include <math.h>

#include "case/case.h"
#include "model/model.h"

/* Surface s of the case (a /SURF/SEG or /SURF/PART card) into the model:
 * kind RC_SURF_SEG, its body (that of its nodes, -1: fixed in space), its
 * nodes and segments appended after those of surface s - 1 (surf_nadr[s]
 * and surf_sadr[s] set; fills [s + 1]). Bodies are compiled. */
rc_status rc_seg_surface(const rc_case *c, rc_model *m, int s, rc_error *err);

/* Adjacency and broad-phase grid of a segment surface (m->surf_mesh[s]),
 * body frame, built at compile time: the segments of each node, and a
 * uniform grid of cells of size h over the segments' bounding boxes. */
typedef struct rc_segmesh {
    int nn, ns;          /* nodes, segments (local indices) */
    int *vadr, *vseg;    /* [nn + 1], [4 ns]: segments of node j at vseg[vadr[j] .. vadr[j+1]) */
    double lo[3], h;     /* grid origin [m] and cell size [m] */
    int dim[3];          /* cells along each axis */
    int *cadr, *cseg;    /* [ncell + 1]: segments of cell c at cseg[cadr[c] .. cadr[c+1]) */
    int *srange;         /* [6 ns]: first and last cell of segment k along x, y, z */
    double *sbox;        /* [6 ns]: bounding box of segment k, lower then upper corner [m] */
    /* node to segment (segments-segments pairs, docs/theory.md 2.7) */
    double *scen, *snrm; /* [3 ns]: centre of segment k [m] and its unit normal [-]
                            ((x2 - x0) x (x3 - x1), a triangle (x1 - x0) x (x2 - x0)) */
    double depth;        /* search depth: half the mean segment extent [m] */
    /* node grid (node to segment at the search depth): the same cells,
     * each segment entered over its box widened by what a point within
     * depth of its plane, whose foot is inside it, can lie outside the box:
     * (depth + warp) |n_j| along axis j, warp the largest distance of a
     * corner from the plane through the centre (the whole box widened by
     * depth along every axis when its outline, projected on that plane, is
     * not convex); so the cell of the point alone holds every candidate */
    int *ncadr, *ncseg;  /* [ncell + 1]: segments of cell c at ncseg[ncadr[c] .. ncadr[c+1]) */
    /* [ns] 1: segment k is isolated: flat, convex, and every segment whose
     * widened box meets its own is flat, convex, in its plane (the same
     * normal) and beyond one of its edges; a point whose foot lies inside
     * k away from its edges then has k as its only candidate (geom_seg.inc,
     * node_seg: the segment a node met last is tried first) */
    unsigned char *iso;
} rc_segmesh;

/* The cells [*lo, *hi] of g's grid along axis k that the interval [a, b] [m]
 * (body frame) covers, clamped to the grid: computed in double and clamped
 * before the conversion to int, so that an interval far outside the grid, or
 * not finite, cannot overflow an int. 0: the interval misses the grid (or is
 * not finite); *lo and *hi are then an empty range. */
static inline int rc_seggrid_cells(const rc_segmesh *g, int k, double a, double b, int *lo, int *hi)
{
    const double fl = floor((a - g->lo[k]) / g->h), fh = floor((b - g->lo[k]) / g->h);
    if (!(fh >= 0.0) || !(fl <= g->dim[k] - 1) || !(fl <= fh)) {
        *lo = 1;
        *hi = 0;
        return 0;
    }
    *lo = fl < 0.0 ? 0 : (int)fl;
    *hi = fh > g->dim[k] - 1 ? g->dim[k] - 1 : (int)fh;
    return 1;
}

/* Ints before rc_data.node_cache: the segment each surface node met last
 * (geom_seg.inc), node j of surface s at [surf_nadr[s] + j]; a multiple of 4
 * (the node cache after it stays aligned). */
static inline int rc_seg_hint_len(const rc_model *m) { return (m->surf_nadr[m->nsurf] + 3) / 4 * 4; }

/* Contact points of interface i whose points are nodes (rc_pair_nodes): the
 * nodes of surface a, then, segments-segments, those of surface b (not for
 * a one-way pair, m->inter_oneway: an /INTER/TYPE7), then,
 * box against box, the RC_BOX_EDGE_PAIRS pairs of their edges (edge e / 12
 * of a against edge e % 12 of b: rc_box_is_box_pair). */
int rc_seg_points(const rc_model *m, int i);
/* Edges of a box (12), pairs of edges of two boxes (144). */
#define RC_BOX_EDGES 12
#define RC_BOX_EDGE_PAIRS (RC_BOX_EDGES * RC_BOX_EDGES)
/* Is interface i a box against a box (corners against faces both ways,
 * and edge against edge)? */
int rc_box_is_box_pair(const rc_model *m, int i);

/* Build the adjacency and grid of every segment surface (after all
 * surfaces are compiled). */
rc_status rc_seg_meshes(rc_model *m, rc_error *err);
/* Release m->surf_mesh. */
void rc_seg_free(rc_model *m);

#endif
