/*
 * The static analysis (/SOLVER Method 3, static.c; docs/theory.md "Static
 * analysis"): the equilibrium of the free bodies' forces and moments at
 * each output time, solved by KINSOL (Newton with line search) and KLU on
 * the stiffness. The unknowns are, per free body (in the order of the
 * model's bodies), its displacement u = x - x0 (global, [m]) and the
 * rotation vector theta of its orientation about the orientation q0 at the
 * start of the solve (body frame, q = q0 (x) exp(theta), [rad]); the
 * residual is the force (global, [N]) and the moment about the centre of
 * mass (body frame, [N m]) on it at zero velocities, in the modes of the
 * run data. A held unknown (a translation held by /BCS, the rotation of a
 * body whose rotations are held or on which no moment can act) has the
 * residual k_s (u - u_imp) instead (k_s: its stiffness scale; u_imp the
 * imposed displacement of an imposed translation, else 0). With joints the
 * unknowns end with their rows' multipliers lambda (the reactions, [N] or
 * [N m]; model/joint.h, in the order of the rows), and the residual with
 * the rows g ([m] or [-]); the bodies' residual includes the reactions.
 *
 * Exposed here for the tests (tests/test_static.c): the residual and the
 * stiffness of a model in given modes, about a start state.
 */
#ifndef RC_SOLVER_STATIC_H
#define RC_SOLVER_STATIC_H

#include "engine/assembly/data.h"
#include "model/model.h"

typedef struct rc_static rc_static;

/* The static problem of m with the run data d (its modes are used as
 * they are); NULL: out of memory. */
rc_static *rc_static_new(const rc_model *m, rc_data *d);
void rc_static_free(rc_static *s);
/* Unknowns: 6 per free body, then one per joint row. */
int rc_static_size(const rc_static *s);
/* Set the start state of the solve (the state y0 [ny]; its velocities are
 * ignored, taken as zero). */
void rc_static_set_start(rc_static *s, const double *y0);
/* Set the start of the load substep (docs/theory.md 7.8: the return
 * mappings of friction, per contact and per point, and of hysteresis; the
 * energies of the path): the state y0 of the last equilibrium at the load
 * time t, in the modes of the run data (its closed contacts' friction
 * states F_t0 and contact points fixed in the bodies, their hysteresis
 * forces and penetrations, the bodies' positions). Until it is called the
 * return mappings are off: the states are those of the start state. */
void rc_static_set_substep_start(rc_static *s, double t, const double *y0);
/* The residual r[n] at the unknowns u[n] at the load time t: 0, or 1 when
 * the forces could not be evaluated. */
int rc_static_residual(rc_static *s, double t, const double *u, double *r);
/* The stiffness dr/du at u, dense column-major into K[n n]: 0, or 1. */
int rc_static_stiffness(rc_static *s, double t, const double *u, double *K);

#endif
