/*
 * Geometry set-up at compile time (model/geom.c): the analytic cylinder
 * and box surfaces (/SURF/CYL, /SURF/BOX) in the body frame, and the pair
 * kind of an interface from its two surfaces (with an input error for a
 * pair ricochet does not support). The kernels are in kernels.inc and
 * geom_cylinder.inc; docs/theory.md 2 has the formulas.
 */
#ifndef RC_GEOM_H
#define RC_GEOM_H

#include "case/case.h"
#include "model/model.h"

/* Cylinders whose axes differ by more than this angle are not "parallel"
 * (cylinder-cylinder contact needs parallel axes) [rad]. */
#define RC_CYL_PARALLEL_TOL 1e-6

/* Cylinder or box surface s from its card; org: the carrying body's centre
 * of mass at t = 0 (or the origin). */
void rc_geom_surface(const rc_case_surf *cs, rc_model *m, int s, const double *org);

/* Order surfaces s1, s2 of an interface into (a, b) and name the pair kind;
 * an input error (prefixed by `where`, e.g. "file:line: card X") when the
 * pair is not supported. */
rc_status rc_geom_pair(const rc_model *m, int s1, int s2, int *sa, int *sb, rc_pair_kind *kind, const char *where,
                       rc_error *err);

/* flag[s] = 1 for each box surface s of the case (index in c->surf) that
 * meets a plane or a box in an interface (TYPE6 or POWER): those pairs use
 * its corners and faces; 0 otherwise. flag: [c->nsurf]. */
void rc_geom_box_corner_flags(const rc_case *c, unsigned char *flag);

/* The corners and faces of box surface s (compiled by rc_geom_surface) as
 * segment-surface data on the same surface (docs/theory.md 2.7): 8 nodes
 * and 6 quadrilaterals with outward normals, body frame, appended after
 * surface s - 1's (fills surf_nadr[s + 1], surf_sadr[s + 1]); its kind stays
 * RC_SURF_BOX, the analytic box of its other pairs. */
rc_status rc_geom_box_corners(rc_model *m, int s, rc_error *err);

/* Pair name of interface i for listings: rc_geom_pair_name, or "box-plane
 * (...)", "box-box (...)" when a box acts through its corners. */
const char *rc_geom_inter_pair_name(const rc_model *m, int i);

#endif
