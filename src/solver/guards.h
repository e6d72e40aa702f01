/*
 * The physics checks of every run (docs/theory.md, "Physics checks of
 * every run"), run by the driver (drive.c) between integrator calls, on
 * values the run computes anyway:
 *
 *   at every step the integrator takes (rc_guards_step, at its first
 *   return after the step, and at every located root): each interface's
 *   penetration P (the zone root values the
 *   integrator evaluated at that state) stays below its bound
 *   (engine/assembly/bounds.c); two spheres' centres stay (R1 + R2)/2 apart; an
 *   open interface does not penetrate beyond its touch band;
 *
 *   at every record (rc_guards_record), and at the state of a root just
 *   before its events (rc_guards_before_events): the state, the energies
 *   and the forces written are finite; every dissipation channel (damping, hysteresis,
 *   friction, coupling damping; in total and per interface and coupling)
 *   does not decrease; the mechanical energy (kinetic + potential + stored
 *   contact and coupling energy) does not exceed its initial value plus
 *   the supply (the work of the imposed velocities); energy_total does not
 *   rise;
 *
 *   at every event (rc_guards_event): the contacts' history, for the
 *   summary (never closed, persistent, settled).
 *
 * A violation stops the run (RC_EPHYSICS, exit code 5) or, when the run
 * was asked to go on (on_violation warn), is kept and the run continues;
 * either way every violation is in the results file and in the run's
 * statistics. Nothing here allocates after rc_guards_new, but the table of
 * violations when a check fails.
 */
#ifndef RC_GUARDS_H
#define RC_GUARDS_H

#include "model/model.h"
#include "output/output.h"
#include "solver/integrator.h"
#include "engine/assembly/data.h"

/* Tolerances (docs/theory.md 13.1): with E_ref the largest energy in play
 * so far (the scene's E_s, the kinetic energy, the change of the potential
 * energy, the stored energies, the supply) and atol_E the absolute
 * tolerance of the energy accumulators, the error weight of an energy is
 * w = rtol max(E_ref, |E|) + atol_E (a sum of n accumulators: n atol_E);
 * over k integrator steps a quantity may drift by C (1 + k) w: a
 * dissipation channel from its previous record and from its largest value
 * so far (C = RC_GUARD_CHANNEL), the mechanical energy from its initial
 * value plus the supply and energy_total from its previous record and its
 * lowest value so far (C = RC_GUARD_ENERGY) [-]. */
#define RC_GUARD_CHANNEL 30.0
#define RC_GUARD_ENERGY 30.0
/* Violations kept for the results file (more are counted) [-]. */
#define RC_GUARD_ROWS 10000
/* Violations printed on stderr in warn mode with the progress [-]. */
#define RC_GUARD_PRINT 20

typedef struct rc_guards rc_guards;

/* The checks of a run of m: warn 1 keeps going after a violation; show 1
 * prints violations on stderr (warn mode). NULL when out of memory. */
rc_guards *rc_guards_new(const rc_model *m, int warn, int show);
void rc_guards_free(rc_guards *g); /* NULL: no-op */
/* The modes the run starts in (after the contacts at zero were decided),
 * and an overlap at t = 0 the deck accepted (model.h start_note): a
 * violation. 1: stop. */
int rc_guards_started(rc_guards *g, const rc_data *d);
/* An accepted state (t, y) returned by the integrator. zone: the zone
 * root values of the interfaces (rc_rootmap_at) at (t, y) in the present
 * modes, NULL: evaluated here; at_root: the state of a located root,
 * whose events are not applied yet; steps: the integrator's steps so far
 * (the energy tolerances grow with them). 1: a violation stops the run. */
int rc_guards_step(rc_guards *g, const rc_data *d, double t, const double *y, const double *zone, int at_root,
                   long steps);
/* Whether rc_guards_step has anything to check at this return: a step was
 * taken since its last check, or a root was located (else the state is the
 * interpolant of a step already checked, and the run's step count is
 * noted). */
int rc_guards_due(rc_guards *g, long steps, int at_root);
/* A record at (t, y) whose values are in fb (rc_bk_write_frame); the driver
 * asks at the first record after each step or events (frame_buf
 * guards_due). 1: stop. */
int rc_guards_record(rc_guards *g, const rc_data *d, double t, const double *y, const frame_buf *fb);
/* The state (t, y) of a root return before its events are applied: the
 * ledger checked there as at a record, so that a jump at the events is
 * measured against it (no record is written). 1: stop. */
int rc_guards_before_events(rc_guards *g, const rc_data *d, double t, const double *y);
/* An event of interface i (>= 0) at t, after its modes changed. */
void rc_guards_event(rc_guards *g, const rc_data *d, int i, rc_event_kind kind, double t);
/* The violation that stopped the run ("" none). */
const char *rc_guards_message(const rc_guards *g);
/* The violations kept so far (the first RC_GUARD_ROWS): *rows, their count. */
int rc_guards_rows(const rc_guards *g, const rc_violation **rows);
/* At the end: the statistics' physics and contact notes, and the results
 * file's physics part (o NULL: none); stopped 1 when a violation ended
 * the run. */
void rc_guards_finish(rc_guards *g, const rc_data *d, rc_stats *s, rc_output *o, int stopped);

#endif
