/*
 * Spring-damper stiffness form 4: the elastic force from a
 * tabulated stiffness k(x),
 *
 *     f_e(x) = f_r + integral from x_r to x of k        (x_r, f_r given)
 *     f_e(x) = integral from x0 to x of k               (otherwise)
 *
 * so that k_eff(x) = f_e(x) / (x - x0) as docs/theory.md 8 writes it, without the
 * division. The integral is built once, at compile time: the cumulative
 * integral K(x_i) from the first abscissa to each abscissa, each segment by
 * GSL adaptive quadrature (gsl_integration_qag) of the interpolated curve.
 * In the right-hand side the integral to any x is K(x_i) plus the exact
 * integral of the linear segment [x_i, x]: no quadrature, no allocation, and
 * f_e' = k exactly (what the complex-step Jacobian needs).
 */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_interp.h>

#include "model/coupling.h"
#include "base/error.h"

/* Quadrature tolerances and workspace size (the integrand is linear on each
 * segment, so one Gauss-Kronrod rule converges at once). */
#define RC_QUAD_EPSREL 1e-13
#define RC_QUAD_LIMIT 16

static double stiffness_at(double x, void *p)
{
    double f, df;
    rc_table_eval(p, x, &f, &df);
    return f;
}

rc_status rc_cpl_stiff_table(const rc_table *t, double *cum, rc_error *err)
{
    gsl_integration_workspace *w = gsl_integration_workspace_alloc(RC_QUAD_LIMIT);
    if (!w) RC_RAISE(err, RC_ENOMEM, "out of memory for the quadrature of /FUNCT/%d", t->id);
    gsl_function fn = {stiffness_at, (void *)t};
    rc_status st = RC_OK;
    cum[0] = 0.0;
    for (int i = 0; i + 1 < t->n; i++) {
        double r, e;
        int gs = gsl_integration_qag(&fn, t->x[i], t->x[i + 1], 0.0, RC_QUAD_EPSREL, RC_QUAD_LIMIT,
                                     GSL_INTEG_GAUSS15, w, &r, &e);
        /* a table whose integral leaves the doubles is a fault of the input */
        if (gs != GSL_SUCCESS || !isfinite(r) || !isfinite(cum[i] + r)) {
            st = RC_SET(err, RC_EINPUT,
                        "the integral of the stiffness /FUNCT/%d on [%g, %g] cannot be computed (%s); expected "
                        "values whose integral stays finite",
                        t->id, t->x[i], t->x[i + 1], gs != GSL_SUCCESS ? gsl_strerror(gs) : "not finite");
            break;
        }
        cum[i + 1] = cum[i] + r;
    }
    gsl_integration_workspace_free(w);
    return st;
}

/* Integral of k from the first abscissa to x (linear extension outside). */
static double antiderivative(const rc_table *t, const double *cum, double x)
{
    const int n = t->n;
    size_t i = x <= t->x[0] ? 0 : x >= t->x[n - 1] ? (size_t)n - 2 : gsl_interp_bsearch(t->x, x, 0, (size_t)n - 1);
    const double s = (t->y[i + 1] - t->y[i]) / (t->x[i + 1] - t->x[i]), e = x - t->x[i];
    return cum[i] + e * (t->y[i] + 0.5 * s * e);
}

void rc_cpl_stiff_force(const rc_couplings *cpl, const rc_table *t, int k, double x, double *f,
                        double *dfdx)
{
    const double *cum = cpl->cum[k];
    *f = cpl->fref[k] + antiderivative(t, cum, x) - antiderivative(t, cum, cpl->xref[k]);
    double kk;
    rc_table_eval(t, x, &kk, dfdx);
    *dfdx = kk;
}
