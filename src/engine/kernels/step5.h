/*
 * step5 and the step5 friction coefficient of the power-law contact
 * (docs/theory.md 9.4).
 *
 * step5(x, x0, h0, x1, h1) is the quintic step of MSC ADAMS and RecurDyn:
 *   h0                                      x <= x0
 *   h0 + (h1 - h0) D^3 (10 - 15 D + 6 D^2)  x0 < x < x1, D = (x - x0)/(x1 - x0)
 *   h1                                      x >= x1
 * Its first and second derivatives vanish at x0 and x1 (the cubic step
 * 3 D^2 - 2 D^3 is only C1): step5 is C2 (docs/theory.md 9.4).
 *
 * Friction coefficient against the sliding speed s = |v| >= 0:
 *   s <  v_s: mu = step5(s, -v_s, -mu_s, v_s, mu_s)
 *             = mu_s (s / v_s) (15 - 10 u^2 + 3 u^4) / 8,  u = s / v_s
 *   s >= v_s: mu = step5(s, v_s, mu_s, v_d, mu_d)
 * so mu(0) = 0, mu(v_s) = mu_s, mu = mu_d beyond v_d; as a function of the
 * signed velocity, mu(v) sign(v) is odd and C2 everywhere (at v = 0 through
 * the odd inner step, at +-v_s and +-v_d by step5's flat ends).
 *
 * The functions are written once as macros over the value type, so that the
 * kernels (kernels.inc, real and complex-step) and the tests use the same
 * formula: RC_STEP5_DEFINE(T, RE, suffix) defines
 *   T rc_step5##suffix(T x, double x0, double h0, double x1, double h1)
 *   T rc_step5_inner##suffix(T u2)   the factor (15 - 10 u^2 + 3 u^4) / 8
 *   T rc_mu_step5##suffix(T s, double mus, double vs, double mud, double vd)
 * The real instance (suffix _d) is defined here.
 */
#ifndef RC_STEP5_H
#define RC_STEP5_H

#define RC_STEP5_DEFINE(T, RE, suffix)                                                             \
    static inline T rc_step5##suffix(T x, double x0, double h0, double x1, double h1)             \
    {                                                                                              \
        if (RE(x) <= x0) return (T)h0;                                                             \
        if (RE(x) >= x1) return (T)h1;                                                             \
        T D = (x - x0) / (x1 - x0);                                                                \
        return h0 + (h1 - h0) * D * D * D * (10.0 + D * (-15.0 + 6.0 * D));                       \
    }                                                                                              \
    static inline T rc_step5_inner##suffix(T u2) { return (15.0 + u2 * (-10.0 + 3.0 * u2)) / 8.0; } \
    static inline T rc_mu_step5##suffix(T s, double mus, double vs, double mud, double vd)         \
    {                                                                                              \
        if (RE(s) < vs) return mus * (s / vs) * rc_step5_inner##suffix(s * s / (vs * vs));         \
        return rc_step5##suffix(s, vs, mus, vd, mud);                                              \
    }

#define RC_STEP5_RE_D(x) (x)
RC_STEP5_DEFINE(double, RC_STEP5_RE_D, _d)

#endif
