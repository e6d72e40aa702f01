/* Tabulated curves: GSL linear interpolation inside, linear extension outside. */
#include "model/table.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"

rc_status rc_table_init(rc_table *t, int id, int n, const double *x, const double *y,
                        rc_error *err)
{
    memset(t, 0, sizeof *t);
    t->id = id;
    t->n = n;
    t->x = malloc((size_t)n * sizeof(double));
    t->y = malloc((size_t)n * sizeof(double));
    gsl_interp *g = gsl_interp_alloc(gsl_interp_linear, (size_t)n);
    if (!t->x || !t->y || !g) {
        if (g) gsl_interp_free(g);
        rc_table_free(t);
        RC_RAISE(err, RC_ENOMEM, "out of memory for /FUNCT/%d", id);
    }
    memcpy(t->x, x, (size_t)n * sizeof(double));
    memcpy(t->y, y, (size_t)n * sizeof(double));
    if (gsl_interp_init(g, t->x, t->y, (size_t)n) != GSL_SUCCESS) {
        gsl_interp_free(g);
        rc_table_free(t);
        RC_RAISE(err, RC_EINPUT, "/FUNCT/%d: abscissae must be strictly increasing", id);
    }
    t->interp = g;
    return RC_OK;
}

void rc_table_free(rc_table *t)
{
    if (!t) return;
    if (t->interp) gsl_interp_free(t->interp);
    free(t->x);
    free(t->y);
    memset(t, 0, sizeof *t);
}

/* Below the first point and above the last: the end segment extended;
 * returns 1 with its value and slope there, 0 inside. */
static int table_outside(const rc_table *t, double x, double *f, double *dfdx)
{
    const int n = t->n;
    if (!(x <= t->x[0] || x >= t->x[n - 1])) return 0;
    const int k = x <= t->x[0] ? 0 : n - 2;
    const double s = (t->y[k + 1] - t->y[k]) / (t->x[k + 1] - t->x[k]);
    *dfdx = s;
    *f = t->y[k] + s * (x - t->x[k]);
    return 1;
}

void rc_table_eval(const rc_table *t, double x, double *f, double *dfdx)
{
    if (table_outside(t, x, f, dfdx)) return;
    /* Inside: GSL (no accelerator: the right-hand side stays pure). */
    *f = gsl_interp_eval(t->interp, t->x, t->y, x, NULL);
    *dfdx = gsl_interp_eval_deriv(t->interp, t->x, t->y, x, NULL);
}

double rc_table_max_abs(const rc_table *t)
{
    double a = 0.0;
    for (int k = 0; k < t->n; k++)
        if (fabs(t->y[k]) > a) a = fabs(t->y[k]);
    return a;
}

double rc_table_value(const rc_table *t, double x)
{
    /* rc_table_eval without the slope inside */
    double f, s;
    if (table_outside(t, x, &f, &s)) return f;
    return gsl_interp_eval(t->interp, t->x, t->y, x, NULL);
}

/* Slope of segment k and its mid-point. */
static double seg_slope(const rc_table *t, int k) { return (t->y[k + 1] - t->y[k]) / (t->x[k + 1] - t->x[k]); }

double rc_table_slope_at(const rc_table *t, double x)
{
    /* an inner point of the curve at x, within its band: both sides */
    const double band = RC_TABLE_KNOT_REL * fabs(x);
    for (int k = 1; k < t->n - 1; k++)
        if (fabs(x - t->x[k]) <= band) return fmax(seg_slope(t, k - 1), seg_slope(t, k));
    double f, df;
    rc_table_eval(t, x, &f, &df);
    return df;
}
static double seg_mid(const rc_table *t, int k) { return 0.5 * (t->x[k] + t->x[k + 1]); }

double rc_table_slope_smooth(const rc_table *t, double x, double *dslope)
{
    const int ns = t->n - 1; /* segments */
    *dslope = 0.0;
    if (ns == 1 || !(x > seg_mid(t, 0))) return seg_slope(t, 0);
    if (!(x < seg_mid(t, ns - 1))) return seg_slope(t, ns - 1);
    int lo = 0, hi = ns - 1; /* seg_mid(lo) < x < seg_mid(hi) */
    while (hi - lo > 1) {
        const int k = (lo + hi) / 2;
        if (x < seg_mid(t, k))
            hi = k;
        else
            lo = k;
    }
    const double m0 = seg_mid(t, lo), s0 = seg_slope(t, lo), s1 = seg_slope(t, hi);
    *dslope = (s1 - s0) / (seg_mid(t, hi) - m0);
    return s0 + *dslope * (x - m0);
}

/* Exact integral of the piecewise-linear curve (with its linear extension)
 * from a to b: trapezoids between the breakpoints inside [a, b]. */
double rc_table_integral(const rc_table *t, double a, double b)
{
    if (b < a) return -rc_table_integral(t, b, a);
    double sum = 0, x0 = a, f0, d;
    rc_table_eval(t, a, &f0, &d);
    for (int k = 0; k <= t->n; k++) {
        double x1 = k < t->n ? t->x[k] : b;
        if (x1 <= x0) continue;
        if (x1 > b) x1 = b;
        double f1;
        rc_table_eval(t, x1, &f1, &d);
        sum += 0.5 * (f0 + f1) * (x1 - x0);
        x0 = x1;
        f0 = f1;
        if (x0 >= b) break;
    }
    return sum;
}
