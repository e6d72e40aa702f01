/*
 * Power-law contact with splines, RecurDyn style (docs/theory.md 9). A second normal law of the interface element: an
 * interface has inter_law RC_LAW_TYPE6 or RC_LAW_POWER, and a power-law
 * interface keeps the modes, events, energy states, output and /FRICTION of
 * the element (kernels.inc, type6()).
 *
 *   F_n = F_k(delta) + F_c(d delta) delta^m3 [x RDF while delta decreases]
 *   F_k = K delta^m1       or the stiffness spline f_k(delta)
 *   F_c = C sgn(v)|v|^m2   or the damping spline f_c(v),   v = d delta/dt
 *
 * Powers of exponent m < 1 have an infinite slope at 0; they are replaced
 * below a regularisation length x_r by the C1 quadratic that matches value
 * and slope at x_r (RC_POWREG_DEFINE): Newton always sees a finite slope.
 * Every power is extended oddly to negative arguments (sgn(x) |x|^m), a
 * smooth extension across the switching surfaces delta = 0 and v = 0.
 *
 * Splines: GSL (gsl_spline) of the kind named on the card, built once at
 * compile time, evaluated without an accelerator (the right-hand side stays
 * pure), extended linearly beyond their end points with the end slopes.
 */
#ifndef RC_POWER_H
#define RC_POWER_H

#include <math.h>

#include "ricochet/ricochet.h"

/* Normal law of an interface. */
enum { RC_LAW_TYPE6 = 0, RC_LAW_POWER = 1 };


/* A /FUNCT as a GSL spline. */
typedef struct rc_spline {
    int id;          /* /FUNCT id */
    int kind;        /* RC_SPL_* (case/case_power.h) */
    int n;           /* points */
    double *x, *y;   /* [n] */
    void *spl;       /* gsl_spline * (opaque here) */
    double s0, s1;   /* slopes at the first and last point (linear extension) */
} rc_spline;

rc_status rc_spline_init(rc_spline *s, int kind, int id, int n, const double *x, const double *y,
                         rc_error *err);
void rc_spline_free(rc_spline *s);
/* Value and slope at x (linear extension outside [x0, xn]). */
void rc_spline_eval(const rc_spline *s, double x, double *f, double *dfdx);
/* The same with the second derivative (0 on the linear extension). */
void rc_spline_eval2(const rc_spline *s, double x, double *f, double *dfdx, double *d2f);
/* Integral of the spline (with its extension) from a to b. */
double rc_spline_integral(const rc_spline *s, double a, double b);
/* Name of a spline kind ("steffen", ...). */
const char *rc_spline_kind_name(int kind);

/* Parameters of one power-law interface. */
typedef struct rc_power {
    double k;          /* stiffness coefficient K [N/m^m1]                   */
    double m1, m2, m3; /* stiffness, damping and indentation exponents [-]   */
    double c;          /* damping coefficient C [N (s/m)^m2 / m^m3]          */
    rc_spline *stiff;  /* stiffness spline F_k(delta), NULL: K delta^m1      */
    rc_spline *damp;   /* damping spline F_c(v), NULL: C sgn(v)|v|^m2        */
    double rdf;        /* rebound damping factor; 1 when RDF is off [-]      */
    double dreg;       /* regularisation length of delta^m, m < 1 [m]        */
    double vreg;       /* regularisation speed of |v|^m2, m2 < 1 [m/s]       */
} rc_power;

/* Does the rebound damping factor act (RDF on and a damping term for it to
 * scale)? Without one the law has no branches: the approach and the
 * rebound give the same force, and no rdf_rebound / rdf_approach event
 * is tracked (a ball resting on an undamped power law with the default
 * RDF switched branch every half period of its ringing). */
static inline int rc_pw_rdf_acts(const rc_power *pw) { return pw->rdf != 1.0 && (pw->c != 0.0 || pw->damp != NULL); }

/* x^m for x >= 0, regularised below xr when m < 1, extended oddly:
 *   m >= 1:  sgn(x) |x|^m
 *   m < 1:   |x| >= xr: sgn(x) |x|^m;   |x| < xr: a x + b sgn(x) x^2,
 *            a = (2 - m) xr^(m-1), b = (m - 1) xr^(m-2)
 * (value and slope continuous at xr; slope a > 0 at 0). RC_POWREG_DEFINE(T,
 * RE, suffix) defines T rc_powreg##suffix(T x, double m, double xr) for a
 * value type T (kernels: double and double complex). */
#define RC_POWREG_DEFINE(T, RE, suffix)                                                            \
    static inline T rc_powreg##suffix(T x, double m, double xr)                                    \
    {                                                                                              \
        const int neg = RE(x) < 0;                                                                 \
        T ax = neg ? -x : x;                                                                       \
        T v;                                                                                       \
        if (m == 1.0) v = ax;                                                                      \
        else if (m < 1.0 && RE(ax) < xr)                                                           \
            v = ax * ((2.0 - m) * pow(xr, m - 1.0) + (m - 1.0) * pow(xr, m - 2.0) * ax);           \
        else if (RE(ax) == 0)                                                                      \
            v = 0.0 * ax;                                                                          \
        else                                                                                       \
            v = pow(ax, m);                                                                        \
        return neg ? -v : v;                                                                       \
    }

/* Slope of rc_powreg at x (real) [1/m^(1-m)]. */
static inline double rc_powreg_slope(double x, double m, double xr)
{
    const double ax = x < 0 ? -x : x;
    if (m == 1.0) return 1.0;
    if (m < 1.0 && ax < xr) return (2.0 - m) * pow(xr, m - 1.0) + 2.0 * (m - 1.0) * pow(xr, m - 2.0) * ax;
    return ax == 0 ? 0.0 : m * pow(ax, m - 1.0);
}

/* Curvature of rc_powreg at x (real): the slope's derivative, odd in x. */
static inline double rc_powreg_curv(double x, double m, double xr)
{
    const double ax = x < 0 ? -x : x, sg = x < 0 ? -1.0 : 1.0;
    if (m == 1.0 || ax == 0) return 0.0;
    if (m < 1.0 && ax < xr) return sg * 2.0 * (m - 1.0) * pow(xr, m - 2.0);
    return sg * m * (m - 1.0) * pow(ax, m - 2.0);
}

/* Elastic energy stored in a power-law interface at penetration p [J]:
 * the integral of F_k from 0 to p (model/power.c). */
struct rc_model;
struct rc_case;
double rc_power_stored(const struct rc_model *m, int i, double p);
/* Compile /INTER/POWER card k of the case into interface i. */
rc_status rc_power_compile(const struct rc_case *c, struct rc_model *m, int k, int i, rc_error *err);
/* Free the splines of the power-law interfaces (not the inter_pw array). */
void rc_power_free(struct rc_model *m);
/* One line of `ricochet check` for power-law interface i. */
void rc_power_print(const struct rc_model *m, int i, FILE *f);

#endif
