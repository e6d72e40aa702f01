/*
 * Tabulated curves y(x) (/FUNCT): piecewise linear between the points as in
 * Radioss, extended linearly beyond both ends with the end slopes. Interior
 * interpolation by GSL (gsl_interp_linear); the extension is ours, so that
 * every law has a smooth extension across its switching surface.
 */
#ifndef RC_TABLE_H
#define RC_TABLE_H

#include "ricochet/ricochet.h"

typedef struct rc_table {
    int id;          /* /FUNCT id */
    int n;           /* points, >= 2 */
    double *x, *y;   /* [n], x strictly increasing */
    void *interp;    /* gsl_interp * (opaque here) */
} rc_table;

rc_status rc_table_init(rc_table *t, int id, int n, const double *x, const double *y,
                        rc_error *err);
void rc_table_free(rc_table *t);
/* Value and slope at x (linear extension outside [x0, xn]). */
void rc_table_eval(const rc_table *t, double x, double *f, double *dfdx);
/* The value alone, the same as rc_table_eval's (half its work inside:
 * one GSL evaluation instead of two; the fast contact path). */
double rc_table_value(const rc_table *t, double x);
/* The slope smoothed across the points: the segments' slopes interpolated
 * linearly between the segments' mid-points (constant before the first
 * mid-point and after the last), continuous in x; its derivative in
 * *dslope. For a coefficient that must not jump where x crosses a point of
 * the curve (the viscous friction's stiffness, docs/theory.md 6.2). */
double rc_table_slope_smooth(const rc_table *t, double x, double *dslope);
/* The slope at x for a scale: rc_table_eval's, except at a point of the
 * curve (x within RC_TABLE_KNOT_REL |x| of it, the rounding of a value
 * found by inverting the curve) where it is the larger of the slopes of the
 * two segments that meet there, whichever side x rounded to. */
double rc_table_slope_at(const rc_table *t, double x);
#define RC_TABLE_KNOT_REL 1e-9
/* Integral of the curve from a to b (exact for the piecewise-linear curve). */
double rc_table_integral(const rc_table *t, double a, double b);
/* Largest magnitude of the table's values [-]. */
double rc_table_max_abs(const rc_table *t);

#endif
