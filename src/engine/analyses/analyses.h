/*
 * What compiling a model asks of the engine: the Jacobian pattern by
 * probing the kernels and the active part of it, the scales and derived
 * tolerances, the start check, and rc_model_compile on top (ricochet.h).
 * (engine/analyses: jacpattern.c, scales.c, start.c, prepare.c)
 */
#ifndef RC_ENGINE_ANALYSES_H
#define RC_ENGINE_ANALYSES_H

#include <stdint.h>

#include "case/case.h"
#include "model/model.h"
#include "engine/assembly/data.h"

/* ---- Jacobian pattern (jacpattern.c) ---------------------------------- */
rc_status rc_jac_build(rc_model *m, rc_error *err);
/* The slots of the pattern that can be nonzero at (t, y) in the modes of d
 * (engine/analyses/jacpattern.c): keep[nnz] 1, or 0 where every element writing
 * the slot is inactive (an open interface, the contact points of an
 * interface that is not closed, the rows of a point out of the contact
 * whose law gives them no value, a contact coupling with no face pushing);
 * returns the count kept. Uses d->sc->pt_work as scratch (not during a root or
 * Jacobian evaluation). */
int64_t rc_jac_active(const rc_model *m, const rc_data *d, double t, const double *y, unsigned char *keep);
/* What rc_jac_active's result depends on when that is each interface's
 * on/off state alone (no contact points, no contact couplings): those
 * states into key[ninter] (1 on) and 1; otherwise 0 (key untouched). Equal
 * keys give equal results. */
int rc_jac_active_key(const rc_model *m, const rc_data *d, unsigned char *key);

/* ---- scales and tolerances (scales.c) ---------------------------------- */
/* Per-interface scales (penetration, force, stiffness, speed) from the
 * laws, the masses, gravity and the initial speeds; derived regularisation
 * lengths; after the state layout, before the tolerances. */
rc_status rc_model_scales(rc_model *m, rc_error *err);
/* Absolute tolerances and weight kinds of every state. */
rc_status rc_model_tolerances(rc_model *m, rc_error *err);
/* The note of a model whose derived position tolerance rc_model_tolerances
 * raised to the coordinates' rounding for some bodies (the run cannot be
 * as accurate as rtol asks, docs/theory.md 7.1); "" when none. */
void rc_model_tol_floor_note(const rc_model *m, char *buf, size_t n);
/* The mass a unit normal impulse pair at contact point r->point drives at
 * the state y when the free bodies also turn (joints left out) [kg];
 * INFINITY when nothing moves (scales.c). */
double rc_point_mass(const rc_model *m, int i, const double *y, const rc_inter_report *r);
/* Is a body of interface i on a joint? (scales.c) */
int rc_inter_on_joint(const rc_model *m, int i);

/* ---- the fast contact path (prepare.c) ---------------------------------- */
/* The interfaces the fast path evaluates (m->inter_fast, allocated here;
 * engine/analyses/prepare.c, rule in engine/kernels/kernel_fast.inc); RC_ENOMEM when out of
 * memory. */
rc_status rc_fast_select(rc_model *m, rc_error *err);

/* ---- the start (start.c) ------------------------------------------------ */
/* The start: an overlap at t = 0 that no option accounts for (Inacti 5,
 * Icor) is an input error naming both surfaces, the interface and the
 * depth, when the elastic energy it holds exceeds RC_START_ENERGY_FACTOR
 * E_s (a resting start at the static penetration holds far less). Segment
 * surfaces whose normals point away from the other surface are named as
 * such, with the IRS/IRm value that makes them face it. (start.c) */
rc_status rc_start_check(const rc_case *c, rc_model *m, rc_error *err);
/* /INTER/TYPE7 Inacti 1, 2 (inacti.c): the secondary nodes that penetrate
 * the main surface at t = 0 (or the main segments they penetrate) found
 * on the built model *m; when any, *m is replaced by the model built
 * without them (rc_model_build_drop), carrying a notice per card (m->note).
 * RC_EINPUT for Inacti 2 on a main surface that is not a /SURF/SEG when a
 * node penetrates it. */
rc_status rc_inacti_build(const rc_case *c, rc_model **m, rc_error *err);

#endif
