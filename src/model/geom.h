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

#endif
