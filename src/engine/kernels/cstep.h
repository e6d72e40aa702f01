/*
 * The complex step (docs/design.md, "Jacobian values by complex-step
 * differentiation"): its size and the few operations every complex-step
 * derivative of the engine is made of. Used by the Jacobian of the
 * assembly (engine/assembly/assemble_jac.c, imposed_jac.c) and by the
 * constraint sets' Jacobians (engine/constraints/joints.c, stick.c).
 *
 * A real state x enters a complex kernel as x + i h dx; the derivative of
 * the kernel's value f along dx is Im(f) / h, exact to rounding for any
 * tiny h because no difference of nearby values is taken.
 */
#ifndef RC_ENGINE_CSTEP_H
#define RC_ENGINE_CSTEP_H

#include <complex.h>

/* Complex step [state units]; any tiny value works, no cancellation. */
#define RC_CSTEP 1e-40

/* The number type of the complex instantiations (T of a kernel template). */
typedef double complex rc_cx;

/* n real values as complex ones, no step (a pose read, not differentiated). */
static inline void rc_cs_load(const double *x, int n, rc_cx *out)
{
    for (int k = 0; k < n; k++) out[k] = x[k];
}

/* x + i h dx: x stepped along dx (dx = 0: the real value, imaginary 0). */
static inline rc_cx rc_cs_seed(double x, double dx) { return x + I * RC_CSTEP * dx; }

/* One component stepped (+ i h), then put back to its real value. */
static inline void rc_cs_step(rc_cx *p) { *p += I * RC_CSTEP; }
static inline void rc_cs_unstep(rc_cx *p) { *p = creal(*p); }

/* A component already loaded, stepped along dx (+ i h dx). */
static inline void rc_cs_step_along(rc_cx *p, double dx) { *p += I * RC_CSTEP * dx; }

/* The derivative a value carries: Im(v) / h. */
static inline double rc_cs_deriv(rc_cx v) { return cimag(v) / RC_CSTEP; }

#endif
