/*
 * Restitution of one contact of a nonlinear law, as implemented (clipped
 * force, rebound damping factor, regularised powers), from the
 * single-contact problem along the normal (docs/theory.md, "Restitution
 * asked"); the damping that gives an asked restitution. Private to the
 * engine (scales.c derives, report.c prints).
 */
#ifndef RC_ENGINE_RESTITUTION_H
#define RC_ENGINE_RESTITUTION_H

#include "base/error.h"
#include "model/model.h"

/* Restitution of interface i (a power law with K or a stiffness spline and
 * C, or TYPE6 Iform 0 without fct_IDdv) for the effective mass m_eff, the
 * impact speed v0 > 0 and the damping `damp` (C of the power law, Visc of
 * TYPE6), from a GSL ODE solve of the single-contact problem; *tc the
 * contact time (until the force stops acting) [s] (NULL: not wanted). NaN when the law is not one of those
 * or the solve fails. */
double rc_restitution_solve(const rc_model *m, int i, double m_eff, double v0, double damp, double *tc);

/* Can a restitution be computed (and asked) for interface i? When not, a
 * reason in *why. */
int rc_restitution_supported(const rc_model *m, int i, const char **why);

/* The impact speed of interface i: V_imp when given, else the approach
 * speed at t = 0 increased by the fall under gravity over the initial gap
 * (docs/theory.md) [m/s]; 0 when there is none. *given is 1 for V_imp. */
double rc_restitution_speed(const rc_model *m, int i, int *given);

/* The damping (C or Visc) of interface i that gives its e_target at its
 * impact speed: GSL Brent on the damping around rc_restitution_solve.
 * Sets it in the model; an input error when it cannot. */
rc_status rc_restitution_derive(rc_model *m, int i, rc_error *err);

/* Restitution of a linear contact that cannot pull at damping ratio
 * zeta >= 0 (NaN otherwise); *tau = omega times the contact time
 * (restitution.c). */
double rc_linear_restitution(double zeta, double *tau);
/* Is the load curve of TYPE6 interface i a straight line through the
 * origin? Its slope F/P in *k [N/m] (restitution.c). */
int rc_type6_linear_slope(const rc_model *m, int i, double *k);

#endif
