/*
 * Reports of a compiled model: the `ricochet check` summary
 * (rc_model_print_summary, ricochet.h), the couplings' lines of it, and the
 * couplings' values of an output record. (engine/reports)
 */
#ifndef RC_ENGINE_REPORTS_H
#define RC_ENGINE_REPORTS_H

#include <stdio.h>

#include "model/model.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "engine/assembly/data.h"

void rc_cpl_print_summary(const rc_model *m, FILE *f); /* engine/reports/report.c */
/* `ricochet check`: an order-of-magnitude estimate of the run's impacts,
 * persistent contacts, steps and wall time (engine/reports/estimate.c). */
void rc_report_estimate(const rc_model *m, FILE *f);
/* `ricochet check`: warnings on implausible scales: a free body larger than
 * 50 m or heavier than 1e6 kg, a contact whose penetration under the weight
 * or in an impact exceeds its body's size (engine/reports/estimate.c). */
void rc_report_plausibility(const rc_model *m, FILE *f);
/* The critical step [s] of an explicit method on the contacts closed in
 * d's modes at (t, y) (docs/theory.md 7.9, "Method switching"): 2 /
 * omega_max (sqrt(1 + zeta^2) - zeta), omega_max^2 and the damping rate 2
 * zeta omega_max bounded by Gershgorin's rows of M^-1 K and M^-1 C over
 * the free bodies' translations, each closed contact with its stiffness
 * scale and its linear damping, and its friction's stick spring (with the
 * rotations it turns); at most 2 / kappa for the fastest decay of a law's
 * state (P_e's relaxation, the slip law's turning, K_t |v_t| / L_r);
 * INFINITY when no contact is closed. y NULL: the friction is left out.
 * work: scratch [2 nbody] (engine/reports/estimate.c). */
double rc_explicit_step(const rc_model *m, const rc_data *d, double t, const double *y, double *work);

/* ---- output ------------------------------------------------------------ */
/* Values per coupling at (t, y) for one output record, into buf [9 n]:
 * force [n], length [n], force on end 1 [3 n], force on end 2 [3 n],
 * lowest point of a catenary [n] (NaN for springs) (rc_cpl_report; NaN for
 * a catenary that cannot be solved). */
void rc_cpl_frame(const rc_model *m, const rc_data *d, double t, const double *y, double *buf); /* engine/reports/report.c */

/* `ricochet check` lines of contact coupling k (engine/reports/contact_report.c);
 * r: its report at t = 0 (NULL: none). */
struct rc_cpl_report;
void rc_cpl_contact_print(const rc_model *m, int k, const struct rc_cpl_report *r, FILE *f);

#endif
