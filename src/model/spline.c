/* Splines of the power-law contact (power.h): GSL gsl_spline of a chosen
 * kind inside the points, linear extension with the end slopes outside. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_power.h"
#include "model/power.h"

const char *rc_spline_kind_name(int kind)
{
    switch (kind) {
    case RC_SPL_LINEAR: return "linear";
    case RC_SPL_CUBIC: return "cubic";
    case RC_SPL_AKIMA: return "akima";
    case RC_SPL_STEFFEN: return "steffen";
    }
    return "?";
}

static const gsl_interp_type *gsl_kind(int kind)
{
    switch (kind) {
    case RC_SPL_LINEAR: return gsl_interp_linear;
    case RC_SPL_CUBIC: return gsl_interp_cspline;
    case RC_SPL_AKIMA: return gsl_interp_akima;
    default: return gsl_interp_steffen;
    }
}

rc_status rc_spline_init(rc_spline *s, int kind, int id, int n, const double *x, const double *y,
                         rc_error *err)
{
    memset(s, 0, sizeof *s);
    s->id = id;
    s->kind = kind;
    s->n = n;
    const gsl_interp_type *t = gsl_kind(kind);
    if (n < (int)gsl_interp_type_min_size(t))
        RC_RAISE(err, RC_EINPUT, "/FUNCT/%d: a %s spline needs at least %u points, the function has %d", id,
                 rc_spline_kind_name(kind), gsl_interp_type_min_size(t), n);
    s->x = malloc((size_t)n * sizeof(double));
    s->y = malloc((size_t)n * sizeof(double));
    gsl_spline *g = gsl_spline_alloc(t, (size_t)n);
    if (!s->x || !s->y || !g) {
        if (g) gsl_spline_free(g);
        rc_spline_free(s);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the spline of /FUNCT/%d", id);
    }
    memcpy(s->x, x, (size_t)n * sizeof(double));
    memcpy(s->y, y, (size_t)n * sizeof(double));
    if (gsl_spline_init(g, s->x, s->y, (size_t)n) != GSL_SUCCESS) {
        gsl_spline_free(g);
        rc_spline_free(s);
        RC_RAISE(err, RC_EINPUT, "/FUNCT/%d: the %s spline cannot be built (abscissae must increase strictly)", id,
                 rc_spline_kind_name(kind));
    }
    s->spl = g;
    s->s0 = gsl_spline_eval_deriv(g, s->x[0], NULL);
    s->s1 = gsl_spline_eval_deriv(g, s->x[n - 1], NULL);
    return RC_OK;
}

void rc_spline_free(rc_spline *s)
{
    if (!s) return;
    if (s->spl) gsl_spline_free(s->spl);
    free(s->x);
    free(s->y);
    memset(s, 0, sizeof *s);
}

void rc_spline_eval(const rc_spline *s, double x, double *f, double *dfdx)
{
    const int n = s->n;
    if (x <= s->x[0]) {
        *dfdx = s->s0;
        *f = s->y[0] + s->s0 * (x - s->x[0]);
        return;
    }
    if (x >= s->x[n - 1]) {
        *dfdx = s->s1;
        *f = s->y[n - 1] + s->s1 * (x - s->x[n - 1]);
        return;
    }
    /* no accelerator: the right-hand side stays pure */
    *f = gsl_spline_eval(s->spl, x, NULL);
    *dfdx = gsl_spline_eval_deriv(s->spl, x, NULL);
}

void rc_spline_eval2(const rc_spline *s, double x, double *f, double *dfdx, double *d2f)
{
    rc_spline_eval(s, x, f, dfdx);
    *d2f = x <= s->x[0] || x >= s->x[s->n - 1] ? 0.0 : gsl_spline_eval_deriv2(s->spl, x, NULL);
}

/* Integral of the linear extension f(x) = y_e + s (x - x_e) from a to b. */
static double line_integral(double ye, double sl, double xe, double a, double b)
{
    return (b - a) * (ye + sl * (0.5 * (a + b) - xe));
}

double rc_spline_integral(const rc_spline *s, double a, double b)
{
    if (b < a) return -rc_spline_integral(s, b, a);
    const double x0 = s->x[0], xn = s->x[s->n - 1];
    double sum = 0;
    if (a < x0) sum += line_integral(s->y[0], s->s0, x0, a, b < x0 ? b : x0);
    if (b > xn) sum += line_integral(s->y[s->n - 1], s->s1, xn, a > xn ? a : xn, b);
    const double lo = a > x0 ? a : x0, hi = b < xn ? b : xn;
    if (hi > lo) sum += gsl_spline_eval_integ(s->spl, lo, hi, NULL);
    return sum;
}
