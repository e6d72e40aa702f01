/*
 * The engine's evaluation of a model at (t, y) in the modes of the run
 * data: initial state, right-hand side, Jacobian values, root functions,
 * the interfaces' reports, energies; couplings and imposed velocities.
 * (engine/assembly: body.c, assemble_rhs.c, assemble_jac.c, imposed_rhs.c,
 * imposed_jac.c, energy.c)
 */
#ifndef RC_ENGINE_ASSEMBLY_H
#define RC_ENGINE_ASSEMBLY_H

#include <stdint.h>

#include "model/model.h"
#include "model/coupling.h"
#include "model/imposed.h"
#include "engine/assembly/data.h"
#include "engine/assembly/event_kind.h"

/* ---- states, right-hand side, Jacobian, roots, reports (body.c,
 *      assemble_rhs.c, assemble_jac.c) ---------------------------------- */
/* Initial state vector [ny]. */
void rc_initial_state(const rc_model *m, double *y);
/* The gravity work state of y (time-varying gravity: -sum m g(0).x at the
 * bodies' positions in y) set for a run that starts at y; none without one. */
void rc_gravity_work_init(const rc_model *m, double *y);
/* A state vector y (ny values) from the model's coordinates into the deck's:
 * the bodies' positions plus the model's origin (what the caller sees:
 * rc_run_options.y_end, rc_session_state, the results). */
void rc_state_to_deck(const rc_model *m, double *y);
/* The states that keep their initial values y0 through any run of m on
 * the ODE path (docs/theory.md 7.2, "What the integrator carries"): a held
 * velocity component (/BCS; its rate is set to 0 after every force, and
 * an imposed velocity cannot name it), the position along a held
 * translation whose velocity is exactly 0 in y0, the quaternion of a
 * body whose rotations are all held with omega exactly 0 in y0, and the
 * quaternion and omega of a body on which no moment can act
 * (rc_moment_free_bodies) with omega exactly 0 in y0. `written`
 * [ny] marks the states an event may write (NULL: the events of events.c,
 * which write interface and contact-point states only, never a body's);
 * such a state is never constant, nor the position or quaternion that
 * depends on it. cst[ny] receives 1 for the constant states; returns
 * their number (body.c). */
int rc_constant_states(const rc_model *m, const double *y0, const char *written, char *cst);
/* mf[nbody] receives 1 for the free bodies on which no moment about the
 * centre of mass can act in any state and mode (docs/theory.md 7.2): every
 * interface side on the body a sphere centred exactly on its centre of
 * mass in a sphere-plane, sphere-sphere, sphere-box or sphere-cylinder
 * pair without friction of any kind; no coupling, joint or imposed
 * velocity on it. Gravity acts at the centre of mass. (body.c) */
void rc_moment_free_bodies(const rc_model *m, char *mf);
/* The same, with the forces through a body's centre of mass taken as no
 * moment there when `centred` is 1: the spring and catenary couplings
 * attached exactly at it, and the reaction of an imposed translation (a
 * force along the component at the centre of mass); the static analysis'
 * bodies whose rotation nothing can turn (body.c). */
void rc_moment_free_bodies_centred(const rc_model *m, int centred, char *mf);
/* ydot = f(t, y; modes). Returns 0, or 1 (recoverable) on a non-finite force. */
int rc_assemble_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot);
/* Jacobian values into `val` [nnz] on the fixed pattern. */
int rc_assemble_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val);
/* After a mode change of interface i: replace its block in `val` (values
 * last assembled by rc_assemble_jac, with later refreshes) by its block at y
 * in d's present modes; the rest of `val` stays as it was. 0, or -1 when d
 * holds no blocks of `val`, or when the model has imposed velocities (their
 * rows are rewritten after every element): assemble it whole then. */
int rc_jac_refresh_inter(const rc_model *m, const rc_data *d, int i, const double *y, double *val);
/* After stick/slip flips of some contact points of interface i (their modes
 * before in old_slip[inter_npt], now in d->pt_slip), its modes otherwise
 * unchanged: the flipped points' part of `val` at y in their new modes (their
 * rows and columns anew, their forces' share of the interface block replaced
 * by the change new law less old law); the rest stays. 0 (also when nothing
 * acts), or -1: assemble whole (as rc_jac_refresh_inter, or when half the
 * points or more flipped). */
int rc_jac_refresh_points(const rc_model *m, const rc_data *d, int i, const int *old_slip, const double *y, double *val);

/* Root functions [rc_root_count(m)]. */
void rc_assemble_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
/* Whether interface i qualifies for the fast path (the rule of rc_fast_select). */
int rc_fast_eligible(const rc_model *m, int i);
/* The root functions that can change sign in a run from t = 0 to tend,
 * from the interfaces' static configuration (no hysteresis law, no
 * Inacti 5, no friction, an activation window wider than the run: those
 * roots keep one sign); their indices ascending into live (NULL: only
 * counted); returns their number (assemble_rhs.c). */
int rc_roots_live(const rc_model *m, double tend, int *live);
/* Distance sensors (sensors.c): the distance of sensor k's points at y
 * [m]; its two roots (d - Dmax, Dmin - d; -1 for a bound not given, a time
 * sensor, a sensor triggered; a sensor releasing a held body: t - t_on in
 * g[2k] once t_on is known, until the release; an interface sensor with a
 * force bound: F_n - Fmax from the forces the interfaces' roots evaluated
 * just before at the same state, rc_data scratch inter_fnr) into g[2k],
 * g[2k+1] (assemble_rhs.c, called by rc_assemble_roots only); whether root j of the
 * sensors' block can change sign; the time interface i turns on (its
 * Tstart, or later its run-time sensor's time on: INFINITY until known;
 * the times on are set in engine/events). */
double rc_sens_distance(const rc_model *m, int k, const double *y);
void rc_sens_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
int rc_sens_root_live(const rc_model *m, int j);
double rc_sens_inter_ton(const rc_model *m, const rc_data *d, int i);
/* Interface sensor k's force at (t, y) in the modes of d: the sum of the
 * normal forces of the closed interfaces of its /INTER card [N]
 * (assemble_rhs.c; pure, as the root functions). */
double rc_sens_inter_force(const rc_model *m, const rc_data *d, int k, double t, const double *y);
/* 1 when an interface of interface sensor k's /INTER card is closed in d
 * (sensors.c). */
int rc_sens_inter_closed(const rc_model *m, const rc_data *d, int k);

/* Evaluate one interface at (t, y) in the given modes, for reports, roots
 * and events; contact points with friction all take the mode `slip`. */
void rc_inter_report_eval(const rc_model *m, int i, int mode, int branch, int track, int slip, double t,
                          const double *y, rc_inter_report *r);
/* The same in the modes of d, contact points each in its own. */
void rc_inter_report_eval_d(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r);
/* The contact points of interface i (friction per point) at (t, y), closed
 * in the modes of d, each point j in mode slip[j] (NULL: its mode in d):
 * per point RC_PT_OUT values into out: its slip root, the law's tangential
 * force on a before any projection (3) [N], its share w_j = f_j / F_n [-],
 * its depth q_j below the level of the shares [m] (> 0: it has a share),
 * the magnitude of its state F_t in its tangent plane at unit share [N]. */
void rc_points_eval(const rc_model *m, const rc_data *d, int i, const int *slip, double t, const double *y, double *out);
/* Contact point j of node-pair interface i (rc_seg_points) at the state y:
 * where its force acts, global [m] (a node, or the middle of the closest
 * points of a pair of box edges). */
void rc_point_position(const rc_model *m, int i, int j, const double *y, double x[3]);
/* The same point's signed distance to the surface it meets at the state y,
 * along that surface's outward normal [m], as the contact computes it (a
 * node of a segments-segments pair that projects onto no segment within
 * the search depth: Gap + depth). hints: NULL, or rc_seg_hint_len(m) ints,
 * where the segment a node of surface s projects onto is written at
 * [surf_nadr[s] + its index] (left as it was when none; the entry, when a
 * segment of that surface, is tried first: set it to -1 before). */
double rc_point_distance(const rc_model *m, int i, int j, const double *y, int *hints);
/* The same point's fade at the state y (docs/theory.md 2.7): fade[0] the
 * factor [-] of its depth in its share (1 for a node; for a pair of box
 * edges, down to 1e-6 as it nears the end of its validity), fade[1] its
 * rate [1/s] along the bodies' motion. Returns the point's distance as
 * rc_point_distance's. */
double rc_point_fade(const rc_model *m, int i, int j, const double *y, double fade[2]);
/* The reports kept by the last rc_assemble_roots: 1 when y is, bit for bit,
 * the state of that evaluation (then rc_report_cache_get may be asked). */
int rc_report_cache_state(const rc_model *m, const rc_data *d, const double *y);
/* Interface i's report of that evaluation into r, when it was evaluated
 * there in the modes d holds now (1), else 0 (r untouched). Only after
 * rc_report_cache_state returned 1 for the same y. */
int rc_report_cache_get(const rc_model *m, const rc_data *d, int i, rc_inter_report *r);
/* Gravity acceleration vector of body b at time t [m/s^2]. */
void rc_gravity(const rc_model *m, int b, double t, double g[3]);
/* Value of the gravity time function at t [-] (1 when none is given). */
double rc_gravity_factor(const rc_model *m, double t);
/* rc_gravity_factor in a run: at a /GRAV sensor's time once the run
 * restarted there (rc_data.t_bp), the right limit (the gravity on). */
double rc_gravity_factor_run(const rc_model *m, const rc_data *d, double t);

/* Friction coefficient of interface i, direction dir, at pressure p [Pa],
 * sliding speed v [m/s], normal force fn [N] (the kernel's law, for tests). */
double rc_friction_mu(const rc_model *m, int i, int dir, double p, double v, double fn);

/* Time derivatives of the reported quantities of interface i (in the given
 * modes) along the state rate ydot: p, vn (the normal acceleration), p_raw,
 * vn_raw, fload, fdamp, fn, fl, fu, fh, offset, flim (the friction limit)
 * and normal (the unit normal's); other fields 0. Exact, by complex step
 * (assemble_jac.c). */
void rc_inter_report_rate(const rc_model *m, int i, int mode, int branch, int track, int slip, const double *y,
                          const double *ydot, rc_inter_report *dr);

/* Energies [J]: kinetic, gravitational potential, work of the normal
 * elastic(-plastic) forces, damping dissipation, work of the friction forces,
 * elastic energy stored in the contacts (normal and tangential), hysteresis
 * dissipation (= normal work - normal stored), friction dissipation (=
 * friction work - tangential stored), coupling energies (spring elastic,
 * damper dissipation, catenary lines: coupling.h), minus the work done by
 * the imposed velocities (/IMPVEL, imposed.h), total (kinetic + potential +
 * work + damping + friction work + couplings + imposed; constant in exact
 * arithmetic). */
enum {
    RC_E_KIN, RC_E_POT, RC_E_WORK, RC_E_DAMP, RC_E_FWORK, RC_E_STORED, RC_E_HYST, RC_E_FRIC,
    RC_E_CPL_ELASTIC, RC_E_CPL_DAMP, RC_E_CATENARY, RC_E_IMPOSED, RC_E_TOTAL, RC_NENERGY
};
/* (engine/assembly/energy.c) */
void rc_energy(const rc_model *m, const rc_data *d, double t, const double *y, double e[RC_NENERGY]);
/* Normal elastic energy stored in interface i (recoverable by unloading) [J]. */
double rc_inter_stored_energy(const rc_model *m, const rc_data *d, int i, double t, const double *y);
/* The hysteresis of interface i at (t, y) [J]: D_h where the interface
 * integrates it (rc_model.inter_dhidx); else its normal work less its
 * stored energy; exactly 0 for an elastic law (Iform 0 or the power law,
 * one contact point, no Inacti offset) that cannot release at P > 0 (no
 * damper, a load curve that never pulls), whose work differs from its
 * stored energy only by the integration error of the work accumulator;
 * for an elastic law that can (rc_inter_release_ledger), the energy it
 * stored at each release at P > 0 less what it held again when it closed
 * (rc_data.inter_hacc, kept at the mode changes), without that error. */
double rc_inter_hysteresis(const rc_model *m, const rc_data *d, int i, double t, const double *y);
/* The elastic energy of interface i's law (Iform 0 or the power law) at
 * penetration P: its load curve's integral from 0 [J] (0 for P <= 0). */
double rc_inter_law_energy(const rc_model *m, int i, double P);
/* The elastic energy interface i's law holds at penetration P [m] and
 * elastic force F [N] (Iform 1, 2: what unloading along the Stiff line and
 * the curves gives back; else rc_inter_law_energy's, F unused) [J]. */
double rc_inter_path_energy(const rc_model *m, int i, double P, double F);
/* Iform 1, 2: the length in P of the first Stiff line of the unloading
 * path from (P, F) [m], dE/dF at constant P (0 where the path starts on a
 * curve, and for P <= 0 or F <= 0); *dP [-] and *dF [m/N] its derivatives
 * (for the Jacobian). */
double rc_inter_unload_line(const rc_model *m, int i, double P, double F, double *dP, double *dF);
/* 1 when interface i's law is elastic (Iform 0 or the power law) with one
 * contact point and no Inacti offset: its hysteresis is the stored energy
 * lost at its releases at P > 0, kept by the events (rc_data.inter_hacc)
 * rather than integrated. */
int rc_inter_release_ledger(const rc_model *m, int i);
/* The energy held in the stick springs of interface i's friction at (t, y)
 * (one, or one per contact point; 0 unless closed, none for exact stick)
 * [J]: its friction work less this is its energy_friction. */
double rc_inter_friction_stored(const rc_model *m, const rc_data *d, int i, double t, const double *y);

/* Dense block of an element (body e, or interface e in the given modes) at
 * (t, y), row-major over its rc_jblock rows and columns (assemble_jac.c). */
void rc_jac_dense_block(const rc_model *m, int is_inter, int e, int mode, int branch, int track, int slip,
                        double t, const double *y, double *out);

/* Geometry of interface i for the constraint (engine/assembly/assemble_jac.c). */
void rc_stk_geom_c(const rc_model *m, int i, const double _Complex *ya, const double _Complex *yb,
                   double _Complex *point, double _Complex *n, double _Complex *vrel, double _Complex *ddot);


/* ---- couplings (assemble_rhs.c, assemble_jac.c;
 *      gravity of the lines in body.c) -------------------------------- */
/* Gravity acting on the lines at time t [m/s^2] (engine/assembly/body.c). */
void rc_cpl_gravity(const rc_model *m, double t, double g[3]);
/* Add the coupling forces to the accelerations and write the energy
 * rates. Returns 0, or 1 (recoverable) when a coupling fails. */
int rc_cpl_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot);
/* Report of coupling k at (t, y); returns 0 or 1 (catenary not solved). */
int rc_cpl_report_eval(const rc_model *m, const rc_data *d, int k, double t, const double *y,
                       rc_cpl_report *r);
/* Dense block of coupling k (rows/cols of cpl->jb[k]); d may be NULL. */
int rc_cpl_dense_block(const rc_model *m, const rc_data *d, int k, double t, const double *y,
                       double *out);
/* Add the coupling Jacobian blocks into the CSC values. */
int rc_cpl_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val);
/* Root functions of the contact couplings (rc_cpl_nroots of them), their
 * directions, the face modes at the start and at events (assemble_rhs.c).
 * rc_cpl_events returns the events written into
 * kinds[]/cpls[] (at most max_ev; the kinds RC_EV_CPL_CONTACT_*, RC_EV_STOP_*,
 * event_kind.h) and sets *restart when a mode changed. */
void rc_cpl_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g);
void rc_cpl_root_dirs(const rc_model *m, const rc_data *d, int *dir);
void rc_cpl_modes_init(const rc_model *m, rc_data *d, double t, const double *y);
int rc_cpl_events(const rc_model *m, rc_data *d, double t, const double *y, const int *roots, rc_event_kind *kinds,
                  int *cpls, int max_ev, int *restart);

/* The stop force or moment of joint j at (t, y) in the modes of d: the
 * generalised force on the joint coordinate q (along +q on body a) [N] or
 * [N m]; 0 without stops (engine/assembly/assemble_rhs.c). *q receives q [m] or
 * [rad] (NaN without stops). */
double rc_cpl_joint_stop(const rc_model *m, const rc_data *d, int j, const double *y, double *q);


/* ---- imposed velocities (imposed_rhs.c, imposed_jac.c) ------------ */
/* Rate of an imposed component at t: Fscale f'(t / Ascale) / Ascale, f the
 * table tab (imposed_rhs.c). */
double rc_imp_rate(const rc_model *m, int tab, double ascale, double fscale, double t);
/* Right-hand side (imposed_rhs.c): overwrite the imposed rows, W_imp'. */
void rc_imp_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot);
/* At a time breakpoint t1 (the previous one t0): the translations whose
 * Tstart lies in (t0, t1] start, their velocity set to Fscale f(Tstart /
 * Ascale) in y and the impulse's work taken into W_imp; returns how many
 * (imposed_rhs.c). */
int rc_imp_start(const rc_model *m, double t0, double t1, double *y);
/* At the event where sensor s (found in the run) turns on, at t: the
 * imposed translations it starts (tson) jump to Fscale f((t - t_on) /
 * Ascale) (W_imp takes the work); returns how many (imposed_rhs.c). */
int rc_imp_start_sens(const rc_model *m, const rc_data *d, int s, double t, double *y);
/* Jacobian (imposed_jac.c): the W_imp row, then the imposed rows replaced. */
int rc_imp_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val);

#endif
