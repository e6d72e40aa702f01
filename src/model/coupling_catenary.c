/*
 * Elastic catenary: solution of the catenary equations of docs/theory.md 8
 * for the end tensions by GSL multiroot solvers with the analytic Jacobian:
 * Newton with line search (gnewton, quadratic) from the last solution (warm
 * start), else Powell's hybrid method (hybridsj, robust) from a cold guess;
 * and the
 * derivatives of the tensions with respect to the span by the
 * implicit-function theorem. docs/theory.md, "Couplings", derives every
 * formula used here.
 *
 * docs/theory.md 8 parametrises the line by (c, u1, u2). With H = c and the vertical
 * tension components V_i = c sinh u_i, its third equation,
 * c (sinh u2 - sinh u1) = lambda0 g L_eq, is linear: V2 = V1 + w L_eq
 * (w = lambda0 g). It is eliminated exactly, and the two span equations
 *
 *   X = H L/EA + (H/w) (asinh(V2/H) - asinh(V1/H))
 *   Y = L (V1 + V2) (1/(T1 + T2) + 1/(2 EA)),   T_i = sqrt(H^2 + V_i^2)
 *
 * (EA = D L_eq) are solved for (H, V1); u_i = asinh(V_i/H). The unknowns
 * are scaled by the line weight W = w L and the lengths by L. Unlike
 * (c, u1, u2), (H, V1) stay finite as the line becomes vertical (u -> inf)
 * or taut (u2 - u1 -> 0), and the forms below are free of cancellation in
 * both limits.
 *
 * The only file that includes the GSL root solvers.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <math.h>
#include <stdlib.h>

#include "model/coupling.h"

/* Solver controls (dimensionless residuals: lengths over L_eq). */
#define RC_CAT_FTOL 1e-12      /* residual accepted from GSL, then polished */
#define RC_CAT_FTOL_STALL 1e-9 /* residual accepted when GSL stops progressing */
#define RC_CAT_MAXITER 200     /* hybridsj iterations from a cold start */
#define RC_CAT_MAXITER_WARM 20 /* gnewton iterations from a warm start */
#define RC_CAT_XI_ITER 60      /* Newton iterations of the cold-start guess */
#define RC_CAT_CANON_BITS 30   /* bits kept of the root before the final polish */

typedef struct cat_ws {
    gsl_multiroot_fdfsolver *newton, *hybrid;
    gsl_vector *z;
} cat_ws;

/* Target span and rigidity, dimensionless. */
typedef struct cat_par {
    double x, y; /* X/L, Y/L */
    double ea;   /* EA/(w L) */
} cat_par;

void *rc_cat_ws_new(void)
{
    cat_ws *ws = calloc(1, sizeof *ws);
    if (!ws) return NULL;
    gsl_set_error_handler_off(); /* GSL reports through return codes */
    ws->newton = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_gnewton, 2);
    ws->hybrid = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, 2);
    ws->z = gsl_vector_alloc(2);
    if (!ws->newton || !ws->hybrid || !ws->z) {
        rc_cat_ws_free(ws);
        return NULL;
    }
    return ws;
}

void rc_cat_ws_free(void *p)
{
    cat_ws *ws = p;
    if (!ws) return;
    if (ws->newton) gsl_multiroot_fdfsolver_free(ws->newton);
    if (ws->hybrid) gsl_multiroot_fdfsolver_free(ws->hybrid);
    if (ws->z) gsl_vector_free(ws->z);
    free(ws);
}

/* a/b, 0 when b = 0 (limits at the singular point h = v = 0). */
static double ratio(double a, double b) { return b != 0 ? a / b : 0.0; }

/* Span (xs, ys) of the line with scaled tensions h = H/W, v1 = V1/W
 * (v2 = v1 + 1), and its Jacobian J = d(xs, ys)/d(h, v1), row-major.
 * h < 0 is the odd extension (xs < 0), so the root h > 0 of xs = x > 0 is
 * approached from either side. Returns GSL_EDOM at h = 0 with the lowest
 * point inside the span, where xs'(h) is infinite. */
static int span(double h, double v1, double ea, double *xs, double *ys, double *J)
{
    const double ah = fabs(h), v2 = v1 + 1.0, s = v1 + v2;
    const double t1 = hypot(ah, v1), t2 = hypot(ah, v2), tt = t1 + t2;
    double A, hA; /* asinh(v2/h) - asinh(v1/h), and |h| dA/d|h| */
    if (v1 >= 0 || v2 <= 0) {
        /* both tensions point the same way: difference of logarithms
         * written as one log1p (stable when v2 ~ v1 relatively, taut) */
        A = v1 >= 0 ? log1p((1.0 + s / tt) / (v1 + t1)) : log1p((1.0 - s / tt) / (t2 - v2));
        hA = -ah * ah * s / (t1 * t2 * (v1 * t2 + v2 * t1));
    } else {
        /* lowest point inside the span: no cancellation */
        if (ah == 0) return GSL_EDOM;
        A = log(v2 + t2) + log(t1 - v1) - 2.0 * log(ah);
        hA = (v1 * t2 - v2 * t1) / (t1 * t2);
    }
    const double P = 1.0 / tt + 0.5 / ea, dA1 = -s / (t1 * t2 * tt);
    *xs = h * (1.0 / ea + A);
    *ys = s * P;
    if (J) {
        J[0] = 1.0 / ea + A + hA;
        J[1] = h * dA1;
        J[2] = -s * (ratio(h, t1) + ratio(h, t2)) / (tt * tt);
        J[3] = 2.0 * P - s * (ratio(v1, t1) + ratio(v2, t2)) / (tt * tt);
    }
    if (!isfinite(*xs) || !isfinite(*ys)) return GSL_EDOM;
    return GSL_SUCCESS;
}

/* ---- GSL callbacks: residual (xs - x, ys - y) and its Jacobian ---------- */
static int cb_fdf(const gsl_vector *z, void *p, gsl_vector *f, gsl_matrix *J)
{
    const cat_par *c = p;
    double xs, ys, Jv[4];
    int st = span(gsl_vector_get(z, 0), gsl_vector_get(z, 1), c->ea, &xs, &ys, Jv);
    if (st) return st;
    if (f) {
        gsl_vector_set(f, 0, xs - c->x);
        gsl_vector_set(f, 1, ys - c->y);
    }
    if (J)
        for (int k = 0; k < 4; k++) gsl_matrix_set(J, (size_t)(k / 2), (size_t)(k % 2), Jv[k]);
    return GSL_SUCCESS;
}
static int cb_f(const gsl_vector *z, void *p, gsl_vector *f) { return cb_fdf(z, p, f, NULL); }
static int cb_df(const gsl_vector *z, void *p, gsl_matrix *J) { return cb_fdf(z, p, NULL, J); }

/* ln(sinh(xi)/xi) for xi > 0, without overflow. */
static double lnsinhc(double xi)
{
    if (xi < 1e-4) return xi * xi / 6.0;
    return xi + log1p(-exp(-2.0 * xi)) - log(2.0 * xi);
}

/* Cold start: the straight elastic line when the chord is at least the
 * unstretched length, else the inextensible catenary through the ends
 * (sinh(xi)/xi = sqrt(1 - y^2)/x, h = x/(2 xi), lowest point from the
 * height difference). */
static void cold_guess(const cat_par *c, double *h, double *v1)
{
    const double l = hypot(c->x, c->y);
    const double r = l < 1.0 ? sqrt(1.0 - c->y * c->y) / c->x : 1.0;
    if (l >= 1.0 || r < 1.0 + 1e-12) {
        const double T = fmax(c->ea * (l - 1.0), 1.0);
        *h = T * c->x / l;
        *v1 = T * c->y / l - 0.5;
        return;
    }
    double xi = r < 2.0 ? sqrt(6.0 * (r - 1.0)) : log(2.0 * r) + log(log(2.0 * r));
    for (int it = 0; it < RC_CAT_XI_ITER; it++) {
        const double g = lnsinhc(xi) - log(r), dg = 1.0 / tanh(xi) - 1.0 / xi;
        const double nx = xi - g / dg;
        xi = nx > 0 ? nx : 0.5 * xi;
        if (fabs(g) < 1e-15) break;
    }
    *h = c->x / (2.0 * xi);
    const double xm = 0.5 * c->x - *h * asinh(c->y / (2.0 * *h * sinh(xi)));
    *v1 = -*h * sinh(xm / *h);
}

/* Vertical line (h = 0): closed forms on the three branches of the
 * tensions' signs (docs/theory.md), and the transverse stiffness
 * kappa = dh/dx at x = 0. */
static void vertical(const cat_par *c, double *v1, double *dv1dy, double *kappa)
{
    const double knee = 1.0 + 0.5 / c->ea, y = c->y;
    double s, dsdy, A0;
    if (y >= knee) { /* hangs straight up from end 1 to end 2, taut */
        s = 2.0 * c->ea * (y - 1.0);
        dsdy = 2.0 * c->ea;
        A0 = log1p(2.0 / (s - 1.0));
    } else if (y <= -knee) { /* from end 2 up to end 1 */
        s = 2.0 * c->ea * (y + 1.0);
        dsdy = 2.0 * c->ea;
        A0 = log1p(2.0 / (-s - 1.0));
    } else { /* folded: both halves hang from their ends */
        s = y / knee;
        dsdy = 1.0 / knee;
        A0 = INFINITY;
    }
    *v1 = 0.5 * (s - 1.0);
    *dv1dy = 0.5 * dsdy;
    *kappa = 1.0 / (1.0 / c->ea + A0);
}

/* Run solver s from (h, v1) for at most maxit iterations; 0 and the root
 * in ws->z on success. */
static int run_solver(cat_ws *ws, gsl_multiroot_fdfsolver *s, gsl_multiroot_function_fdf *fdf, double h,
                      double v1, int maxit, int *iter)
{
    gsl_vector_set(ws->z, 0, h);
    gsl_vector_set(ws->z, 1, v1);
    if (gsl_multiroot_fdfsolver_set(s, fdf, ws->z) != GSL_SUCCESS) return 1;
    for (int it = 0;; it++) {
        if (gsl_multiroot_test_residual(s->f, RC_CAT_FTOL) == GSL_SUCCESS) break;
        if (it == maxit) return 1;
        (*iter)++;
        if (gsl_multiroot_fdfsolver_iterate(s) != GSL_SUCCESS) {
            if (gsl_multiroot_test_residual(s->f, RC_CAT_FTOL_STALL) == GSL_SUCCESS) break;
            return 1;
        }
    }
    gsl_vector_memcpy(ws->z, s->x);
    return 0;
}

/* `n` Newton steps on the scaled equations from z; the Jacobian at the
 * final point in J and its determinant in *det. Returns 0, or 1 when the
 * equations cannot be evaluated or J is singular. */
static int newton(const cat_par *par, double *z, int n, double *J, double *det)
{
    for (int it = 0;; it++) {
        double xs, ys;
        if (span(z[0], z[1], par->ea, &xs, &ys, J)) return 1;
        *det = J[0] * J[3] - J[1] * J[2];
        if (!(fabs(*det) > 0) || !isfinite(*det)) return 1;
        if (it == n) return 0;
        const double rx = xs - par->x, ry = ys - par->y;
        z[0] -= (J[3] * rx - J[1] * ry) / *det;
        z[1] -= (J[0] * ry - J[2] * rx) / *det;
    }
}

int rc_cat_solve(const rc_couplings *cpl, int k, void *wsp, double *warm, double X, double Y,
                 double w, rc_cat_sol *sol)
{
    const double L = cpl->leq[k], W = w * L, sc = W / L;
    cat_par par = {X / L, Y / L, cpl->ea[k] / W};
    sol->X = X;
    sol->Y = Y;
    sol->w = w;
    sol->iter = 0;
    sol->kappa = 0;
    if (!(W > 0) || !isfinite(X) || !isfinite(Y)) return 1;

    /* vertical line: closed form */
    if (par.x < RC_CAT_XMIN_REL) {
        double v1, dv1, kap;
        vertical(&par, &v1, &dv1, &kap);
        sol->vertical = 1;
        sol->H = 0;
        sol->V1 = W * v1;
        sol->V2 = sol->V1 + W;
        sol->dH[0] = sol->dH[1] = sol->dV1[0] = 0;
        sol->dV1[1] = sc * dv1;
        sol->kappa = sc * kap;
        if (warm) warm[0] = warm[1] = NAN; /* not a start for the general case */
        return 0;
    }
    sol->vertical = 0;

    /* Newton from the warm start, else the hybrid method from the cold guess */
    cat_ws *ws = wsp ? wsp : rc_cat_ws_new();
    if (!ws) return 1;
    gsl_multiroot_function_fdf fdf = {cb_f, cb_df, cb_fdf, 2, &par};
    int fail = 1;
    if (warm && isfinite(warm[0]) && isfinite(warm[1]) && warm[0] > 0)
        fail = run_solver(ws, ws->newton, &fdf, warm[0] / W, warm[1] / W, RC_CAT_MAXITER_WARM, &sol->iter);
    if (fail) {
        double h, v1;
        cold_guess(&par, &h, &v1);
        fail = run_solver(ws, ws->hybrid, &fdf, h, v1, RC_CAT_MAXITER, &sol->iter);
    }
    double z[2] = {gsl_vector_get(ws->z, 0), gsl_vector_get(ws->z, 1)};
    if (!wsp) rc_cat_ws_free(ws);
    if (fail) return 1;

    /* The root is known to the solver tolerance and its last bits depend on
     * the start. Polished to the rounding level by Newton, then rounded to
     * RC_CAT_CANON_BITS bits, it is the same point whatever the start (but
     * in ties, about one in 1e7), and two Newton steps from there reach the
     * rounding level again: the result is a function of (X, Y) alone, so the
     * right-hand side stays pure. Then the Jacobian there. */
    double J[4], det;
    if (newton(&par, z, 2, J, &det)) return 1;
    for (int i = 0; i < 2; i++) {
        int e;
        const double f = frexp(z[i], &e);
        z[i] = ldexp(nearbyint(ldexp(f, RC_CAT_CANON_BITS)), e - RC_CAT_CANON_BITS);
    }
    if (newton(&par, z, 2, J, &det) || !(z[0] > 0)) return 1;
    /* implicit-function theorem: d(h, v1)/d(x, y) = J^-1 */
    sol->dH[0] = sc * J[3] / det;
    sol->dH[1] = -sc * J[1] / det;
    sol->dV1[0] = -sc * J[2] / det;
    sol->dV1[1] = sc * J[0] / det;
    sol->H = W * z[0];
    sol->V1 = W * z[1];
    sol->V2 = sol->V1 + W;
    if (warm) {
        warm[0] = sol->H;
        warm[1] = sol->V1;
    }
    return 0;
}
