/* Geometry set-up (geom.h): cylinder and box surfaces, pair kinds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_power.h"
#include "model/geom.h"

static double norm3(const double *v) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void rc_geom_surface(const rc_case_surf *cs, rc_model *m, int s, const double *org)
{
    double *ext = m->surf_ext + RC_SURF_NEXT * s;
    for (int k = 0; k < 3; k++) m->surf_p[3 * s + k] = cs->c[k] - org[k];
    if (cs->kind == RC_CASE_SURF_CYL) {
        /* axis (unit), radius, half-length, ends, contact point */
        const double l = norm3(cs->axis);
        m->surf_kind[s] = RC_SURF_CYL;
        for (int k = 0; k < 3; k++) m->surf_n[3 * s + k] = cs->axis[k] / l;
        m->surf_r[s] = cs->abc[0];
        ext[0] = 0.5 * cs->length;
        ext[1] = cs->ends;
        ext[2] = cs->cmode;
        return;
    }
    /* box: half-sizes, orthonormal axes u, v (v orthogonalised), w = u x v */
    m->surf_kind[s] = RC_SURF_BOX;
    double u[3], v[3], w[3];
    const double lu = norm3(cs->axis);
    for (int k = 0; k < 3; k++) u[k] = cs->axis[k] / lu;
    const double vu = cs->axis2[0] * u[0] + cs->axis2[1] * u[1] + cs->axis2[2] * u[2];
    for (int k = 0; k < 3; k++) v[k] = cs->axis2[k] - vu * u[k];
    const double lv = norm3(v);
    for (int k = 0; k < 3; k++) v[k] /= lv;
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
    for (int k = 0; k < 3; k++) {
        ext[k] = cs->abc[k];
        ext[3 + k] = u[k];
        ext[6 + k] = v[k];
        ext[9 + k] = w[k];
    }
    m->surf_r[s] = fmin(cs->abc[0], fmin(cs->abc[1], cs->abc[2]));
}

/* Corner j = sx + 2 sy + 4 sz of a box at centre + (2 sx - 1) a u
 * + (2 sy - 1) b v + (2 sz - 1) c w; the faces -w, +w, -u, +u, -v, +v, each
 * ordered so that (x2 - x0) x (x3 - x1) points out of the box. */
static const int box_face[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}};

rc_status rc_geom_box_corners(rc_model *m, int s, rc_error *err)
{
    const int n0 = m->surf_nadr[s], s0 = m->surf_sadr[s];
    double *nx = realloc(m->surf_node, (size_t)(3 * (n0 + 8) + 1) * sizeof(double));
    if (!nx) RC_RAISE(err, RC_ENOMEM, "out of memory");
    m->surf_node = nx;
    int *sg = realloc(m->surf_seg, (size_t)(4 * (s0 + 6) + 1) * sizeof(int));
    if (!sg) RC_RAISE(err, RC_ENOMEM, "out of memory");
    m->surf_seg = sg;
    signed char *tu = realloc(m->surf_seg_turned, (size_t)(s0 + 6 + 1));
    if (!tu) RC_RAISE(err, RC_ENOMEM, "out of memory");
    m->surf_seg_turned = tu;
    int *ni = realloc(m->surf_nid, (size_t)(n0 + 8 + 1) * sizeof(int));
    if (!ni) RC_RAISE(err, RC_ENOMEM, "out of memory");
    m->surf_nid = ni;
    for (int j = 0; j < 8; j++) ni[n0 + j] = 0; /* no node of the deck */
    const double *p = m->surf_p + 3 * s, *e = m->surf_ext + RC_SURF_NEXT * s;
    for (int j = 0; j < 8; j++) {
        const double sx = (j & 1) ? 1.0 : -1.0, sy = (j & 2) ? 1.0 : -1.0, sz = (j & 4) ? 1.0 : -1.0;
        for (int k = 0; k < 3; k++)
            nx[3 * (n0 + j) + k] = p[k] + sx * e[0] * e[3 + k] + sy * e[1] * e[6 + k] + sz * e[2] * e[9 + k];
    }
    for (int f = 0; f < 6; f++) {
        for (int j = 0; j < 4; j++) sg[4 * (s0 + f) + j] = box_face[f][j];
        tu[s0 + f] = 0;
    }
    m->surf_nadr[s + 1] = n0 + 8;
    m->surf_sadr[s + 1] = s0 + 6;
    return RC_OK;
}

void rc_geom_box_corner_flags(const rc_case *c, unsigned char *flag)
{
    for (int s = 0; s < c->nsurf; s++) flag[s] = 0;
    for (int k = 0; k < c->ntype6 + c->npower; k++) {
        const int a = rc_case_find_surf(c, k < c->ntype6 ? c->type6[k].surf1 : c->power[k - c->ntype6].surf1);
        const int b = rc_case_find_surf(c, k < c->ntype6 ? c->type6[k].surf2 : c->power[k - c->ntype6].surf2);
        if (a < 0 || b < 0) continue; /* an input error later */
        const rc_case_surf_kind ka = c->surf[a].kind, kb = c->surf[b].kind;
        if (ka == RC_CASE_SURF_BOX && (kb == RC_CASE_SURF_PLANE || kb == RC_CASE_SURF_BOX)) flag[a] = 1;
        if (kb == RC_CASE_SURF_BOX && (ka == RC_CASE_SURF_PLANE || ka == RC_CASE_SURF_BOX)) flag[b] = 1;
    }
    /* an /INTER/TYPE25 of two boxes (its contact is appended after the
     * surfaces are compiled: model/type7.c) */
    for (int k = 0; k < c->ntype24; k++) {
        const int a = rc_case_find_surf(c, c->type24[k].surf1), b = rc_case_find_surf(c, c->type24[k].surf2);
        if (a < 0 || b < 0) continue;
        if (c->surf[a].kind == RC_CASE_SURF_BOX && c->surf[b].kind == RC_CASE_SURF_BOX) flag[a] = flag[b] = 1;
    }
}

const char *rc_geom_inter_pair_name(const rc_model *m, int i)
{
    const rc_pair_kind k = m->inter_pair[i];
    const int ba = m->surf_kind[m->inter_sa[i]] == RC_SURF_BOX, bb = m->surf_kind[m->inter_sb[i]] == RC_SURF_BOX;
    if (k == RC_PAIR_SEG_PLANE && ba) return "box-plane (the box's 8 corners are the contact points)";
    if (k == RC_PAIR_SEG_SEG && m->inter_oneway && m->inter_oneway[i])
        return "nodes-segments (one way: the secondary nodes against the main segments)";
    if (k == RC_PAIR_SEG_SEG && ba && bb && m->inter_edges && m->inter_edges[i] == 1)
        return "box-box, edges only (the 12 edges of each box against those of the other; no corner against a face)";
    if (k == RC_PAIR_SEG_SEG && ba && bb && m->inter_edges && m->inter_edges[i] == 2)
        return "box-box, corners only (the 8 corners of each box against the 6 faces of the other; no edge pair)";
    if (k == RC_PAIR_SEG_SEG && ba && bb)
        return "box-box (the 8 corners of each box against the 6 faces of the other, the 12 edges of each against those of the other)";
    return rc_geom_pair_name(k);
}

const char *rc_geom_pair_name(rc_pair_kind kind)
{
    switch (kind) {
    case RC_PAIR_SPHERE_PLANE: return "sphere-plane";
    case RC_PAIR_SPHERE_SPHERE: return "sphere-sphere";
    case RC_PAIR_CYL_PLANE: return "cylinder-plane";
    case RC_PAIR_CYL_BOX: return "cylinder-box";
    case RC_PAIR_CYL_CYL: return "cylinder-cylinder";
    case RC_PAIR_SPHERE_BOX: return "sphere-box";
    case RC_PAIR_SEG_PLANE: return "segments-plane";
    case RC_PAIR_SPHERE_SEG: return "sphere-segments";
    case RC_PAIR_SEG_BOX: return "segments-box";
    case RC_PAIR_SEG_SEG: return "segments-segments";
    case RC_PAIR_CYL_SEG: return "cylinder-segments";
    case RC_PAIR_SPHERE_CYL: return "sphere-cylinder";
    }
    return "?";
}

static const char *kind_name(rc_surf_kind k)
{
    switch (k) {
    case RC_SURF_PLANE: return "plane";
    case RC_SURF_SPHERE: return "sphere";
    case RC_SURF_CYL: return "cylinder";
    case RC_SURF_BOX: return "box";
    case RC_SURF_SEG: return "segment surface";
    }
    return "?";
}

/* Moving surfaces first: a sphere or cylinder is surface a. */
static int is_round(rc_surf_kind k) { return k == RC_SURF_SPHERE || k == RC_SURF_CYL; }

rc_status rc_geom_pair(const rc_model *m, int s1, int s2, int *sa, int *sb, rc_pair_kind *kind, const char *where,
                       rc_error *err)
{
    if (!is_round(m->surf_kind[s1]) && is_round(m->surf_kind[s2])) {
        int t = s1;
        s1 = s2;
        s2 = t;
    }
    /* a box against a plane or a box: the box's corners and faces (its
     * corner segment surface, rc_geom_box_corners) as a segment surface */
    const int box_seg = (m->surf_kind[s1] == RC_SURF_BOX &&
                         (m->surf_kind[s2] == RC_SURF_PLANE || m->surf_kind[s2] == RC_SURF_BOX)) ||
                        (m->surf_kind[s2] == RC_SURF_BOX && m->surf_kind[s1] == RC_SURF_PLANE);
    if (box_seg) {
        if (m->surf_kind[s1] == RC_SURF_PLANE) {
            int t = s1;
            s1 = s2;
            s2 = t;
        }
        *sa = s1;
        *sb = s2;
        *kind = m->surf_kind[s2] == RC_SURF_PLANE ? RC_PAIR_SEG_PLANE : RC_PAIR_SEG_SEG;
        return RC_OK;
    }
    /* sphere-cylinder: the sphere is surface a */
    if (m->surf_kind[s1] == RC_SURF_CYL && m->surf_kind[s2] == RC_SURF_SPHERE) {
        int t = s1;
        s1 = s2;
        s2 = t;
    }
    /* a segment surface is surface a (its nodes against b) */
    if (m->surf_kind[s2] == RC_SURF_SEG && m->surf_kind[s1] != RC_SURF_SEG && !is_round(m->surf_kind[s1])) {
        int t = s1;
        s1 = s2;
        s2 = t;
    }
    const rc_surf_kind ka = m->surf_kind[s1], kb = m->surf_kind[s2];
    *sa = s1;
    *sb = s2;
    if (ka == RC_SURF_SPHERE && kb == RC_SURF_PLANE) *kind = RC_PAIR_SPHERE_PLANE;
    else if (ka == RC_SURF_SPHERE && kb == RC_SURF_SPHERE) *kind = RC_PAIR_SPHERE_SPHERE;
    else if (ka == RC_SURF_SPHERE && kb == RC_SURF_BOX) *kind = RC_PAIR_SPHERE_BOX;
    else if (ka == RC_SURF_SPHERE && kb == RC_SURF_CYL) *kind = RC_PAIR_SPHERE_CYL;
    else if (ka == RC_SURF_CYL && kb == RC_SURF_PLANE) *kind = RC_PAIR_CYL_PLANE;
    else if (ka == RC_SURF_CYL && kb == RC_SURF_BOX) *kind = RC_PAIR_CYL_BOX;
    else if (ka == RC_SURF_CYL && kb == RC_SURF_CYL) *kind = RC_PAIR_CYL_CYL;
    else if (ka == RC_SURF_SEG && kb == RC_SURF_PLANE) *kind = RC_PAIR_SEG_PLANE;
    else if (ka == RC_SURF_SEG && kb == RC_SURF_BOX) *kind = RC_PAIR_SEG_BOX;
    else if (ka == RC_SURF_SPHERE && kb == RC_SURF_SEG) *kind = RC_PAIR_SPHERE_SEG;
    else if (ka == RC_SURF_SEG && kb == RC_SURF_SEG) *kind = RC_PAIR_SEG_SEG;
    else if (ka == RC_SURF_CYL && kb == RC_SURF_SEG) *kind = RC_PAIR_CYL_SEG;
    else if (ka == RC_SURF_SEG || kb == RC_SURF_SEG)
        RC_RAISE(err, RC_EINPUT,
                 "%s, fields surf_ID1/surf_ID2: a segment surface against %s: not supported yet (supported: a "
                 "segment surface against a plane, a box or a sphere)",
                 where, kind_name(ka == RC_SURF_SEG ? kb : ka));
    else
        RC_RAISE(err, RC_EINPUT,
                 "%s, fields surf_ID1/surf_ID2: %s against %s is not a contact pair ricochet supports (supported: "
                 "sphere-plane, sphere-sphere, sphere-box, sphere-cylinder, cylinder-plane, cylinder-box, "
                 "cylinder-cylinder with parallel axes, box-plane, box-box)",
                 where, kind_name(ka), kind_name(kb));
    /* parallel axes at t = 0 (the body frames are the global frame then) */
    if (*kind == RC_PAIR_CYL_CYL) {
        const double *a = m->surf_n + 3 * s1, *b = m->surf_n + 3 * s2;
        double x[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        if (norm3(x) > RC_CYL_PARALLEL_TOL)
            RC_RAISE(err, RC_EINPUT,
                     "%s, fields surf_ID1/surf_ID2: cylinder-cylinder contact needs parallel axes; the axes of "
                     "surfaces %d and %d make an angle of %.6g rad",
                     where, m->surf_id[s1], m->surf_id[s2], asin(fmin(1.0, norm3(x))));
    }
    return RC_OK;
}
