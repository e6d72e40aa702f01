/*
 * Reports of a model that evaluate the kernels: the summary of `ricochet
 * check` (rc_model_print_summary, with the couplings at t = 0) and the
 * coupling values of an output frame (rc_cpl_frame).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/geom.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/sensor.h"
#include "model/power.h"
#include "engine/analyses/restitution.h"
#include "engine/assembly/assembly.h"
#include "engine/analyses/analyses.h"
#include "engine/reports/reports.h"

/* CVODE steps per impact at the default tolerances, measured on the
 * restitution validation problems (t6_restitution: 124 steps, pw_restitution:
 * 217, cc_stop: 267 for an impact and free flight) [-]. */
#define RC_STEPS_PER_IMPACT 150.0

/* Guidance per interface: the gap at t = 0, the effective mass, the natural
 * frequency at the force scale, the damping ratio of Visc, the predicted
 * restitution and contact time (linear contacts), the stable step of an
 * explicit scheme, and how many output records a contact gets. */
static void print_guidance(const rc_model *m, FILE *f)
{
    double *y = malloc(((size_t)m->ny + 1) * sizeof(double));
    if (!y) return;
    rc_initial_state(m, y);
    fprintf(f, "contacts    guidance per interface (at the force scale F_s; docs/theory.md, \"Guidance\")\n");
    for (int i = 0; i < m->ninter && i < 20; i++) {
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        if (r.p_raw > 0)
            fprintf(f, "  %-18s WARNING: overlap at t = 0 of %.4g m (the surfaces start %s)\n", m->inter_name[i], r.p_raw,
                    m->inter_inacti[i] == 5 ? "inside each other; Inacti 5 takes it as the gap" : "inside each other: a force at once");
        else
            fprintf(f, "  %-18s gap at t = 0: %.4g m\n", m->inter_name[i], -r.p_raw);
        const double mr = m->inter_mrest[i], ks = m->inter_kscale[i];
        if (!(isfinite(mr) && mr > 0 && isfinite(ks) && ks > 0)) {
            fprintf(f, "  %-18s no effective mass along the normal or no scale: no estimate\n", "");
            continue;
        }
        double k = ks;
        const int lin = rc_type6_linear_slope(m, i, &k);
        const double w = sqrt(k / mr), c = m->inter_law[i] == RC_LAW_TYPE6 ? m->inter_visc[i] : 0.0;
        const double zeta = c / (2.0 * sqrt(k * mr));
        fprintf(f, "  %-18s m_eff %.4g kg, k %.4g N/m%s, natural frequency %.4g Hz, damping ratio of Visc %.4g\n", "", mr, k,
                lin ? "" : " (at p_s, nonlinear law)", w / (2.0 * RC_PI), zeta);
        /* m_eff is the pair's mass along the normal: a contact off the line
         * of the centres of mass, or on a jointed body, drives another mass
         * (the rotation), and the predictions below (and a derived damping)
         * do not hold for it */
        if (rc_inter_on_joint(m, i))
            fprintf(f, "  %-18s WARNING: a body of this contact is on a joint: m_eff leaves the joint out, the mass the "
                    "contact drives differs (a hinged body hit at r from the hinge: I_h / r^2), and so do the restitution "
                    "and contact time below%s\n", "", m->inter_etarget[i] > 0 ? " and the damping derived from e_target" : "");
        else if (fabs(m->inter_mrest[i] - m->inter_mred[i]) > 1e-3 * m->inter_mred[i])
            fprintf(f, "  %-18s m_eff includes the rotations: the contact point at t = 0 is off the line of the centres "
                    "of mass (the translations alone: %.4g kg)\n", "", m->inter_mred[i]);
        const int curves = m->inter_law[i] == RC_LAW_TYPE6 &&
                           (m->inter_fct_dv[i] >= 0 || m->inter_fct_df[i] >= 0 || m->inter_iform[i] != 0);
        double tau = NAN, e = NAN, tcn = NAN;
        if (lin && !curves) e = rc_linear_restitution(zeta, &tau);
        /* other laws: the single-contact ODE at the impact speed */
        int given = 0;
        const double vimp = rc_restitution_speed(m, i, &given);
        const char *why = NULL;
        const int ode = !isfinite(e) && rc_restitution_supported(m, i, &why) && vimp > 0;
        const double damp = m->inter_law[i] == RC_LAW_POWER ? m->inter_pw[i].c : m->inter_visc[i];
        if (ode) e = rc_restitution_solve(m, i, mr, vimp, damp, &tcn);
        if (m->inter_etarget[i] > 0)
            fprintf(f, "  %-18s restitution asked %.9g%s: %s derived = %.9g %s, predicted %.9g\n", "", m->inter_etarget[i],
                    ode ? (given ? " at V_imp" : " at the derived impact speed") : " (any impact speed, linear law)",
                    m->inter_law[i] == RC_LAW_POWER ? "C" : "Visc", damp,
                    m->inter_law[i] == RC_LAW_POWER ? "N (s/m)^m2/m^m3" : "N s/m", e);
        const double tc = isfinite(tau) ? tau / w : isfinite(tcn) ? tcn : RC_PI / w;
        if (isfinite(e) && !ode)
            fprintf(f, "  %-18s predicted restitution %.6g, contact time %.4g s (linear law, force >= 0, no other load)\n", "", e, tc);
        else if (isfinite(e))
            fprintf(f, "  %-18s predicted restitution %.6g, contact time %.4g s at impact speed %.6g m/s (%s; "
                    "single-contact ODE, force >= 0, no other load)\n", "", e, tc, vimp, given ? "V_imp" : "derived from t = 0");
        else
            fprintf(f, "  %-18s contact time ~%.4g s (pi/omega; restitution not predicted: %s)\n", "", tc,
                    why ? why : vimp > 0 ? "the ODE failed" : "no impact speed (give V_imp)");
        const double dt_exp = 2.0 / w; /* central differences, undamped */
        const double nrec = tc / m->dtout;
        fprintf(f, "  %-18s explicit stable step %.4g s; output every %.4g s gives %.3g records per contact%s\n", "", dt_exp,
                m->dtout, nrec, nrec < 10 ? " (WARNING: peaks between records are missed; lower /RUN Dt_out)" : "");
        /* a rough cost: CVODE steps per impact, measured on the validation
         * problems at the default tolerances (a contact held through the
         * run, resting, needs far fewer once the BDF order has risen) */
        fprintf(f, "  %-18s cost: about %.0f steps per impact (measured at the default tolerances); %.3g impacts of "
                "this contact fit in the run's %.4g s\n", "", RC_STEPS_PER_IMPACT, m->tend / tc, m->tend);
    }
    if (m->ninter > 20) fprintf(f, "  ... %d more\n", m->ninter - 20);
    free(y);
}

/* The shortest of %.15g, %.16g, %.17g that reads back as v (0.15, not
 * 0.14999999999999999; every digit that matters, for the scripts that
 * parse the line). */
static void exact(char *buf, size_t n, double v)
{
    for (int p = 15; p <= 17; p++) {
        snprintf(buf, n, "%.*g", p, v);
        if (strtod(buf, NULL) == v) return;
    }
}

/* "lo..hi" at 3 digits, or one value when they print the same. */
static void range3(char *buf, size_t n, double lo, double hi)
{
    char a[32], b[32];
    snprintf(a, sizeof a, "%.3g", lo);
    snprintf(b, sizeof b, "%.3g", hi);
    if (strcmp(a, b) == 0) snprintf(buf, n, "%s", a);
    else snprintf(buf, n, "%s..%s", a, b);
}

/* The gravity the free bodies feel (in SI; the time function's factor
 * aside), and a warning when it is far from the Earth's: a deck in mm with
 * gravity left at 9.81 (9.81 mm/s^2, a thousandth), or one in m with mm
 * values (9810 m/s^2). */
static void print_gravity(const rc_model *m, FILE *f)
{
    int nfree = 0, nsame = 0, first = -1;
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        nfree++;
        if (first < 0) first = b;
        const double *g = m->body_grav + 3 * b, *g0 = m->body_grav + 3 * first;
        nsame += g[0] == g0[0] && g[1] == g0[1] && g[2] == g0[2];
    }
    if (first < 0) return;
    const double *g = m->body_grav + 3 * first, gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    char fn[128] = "";
    if (m->grav_table >= 0 && m->grav_tstart > 0)
        snprintf(fn, sizeof fn, " times /FUNCT/%d of t - %.6g s, from %.6g s", m->table[m->grav_table].id,
                 m->grav_tstart, m->grav_tstart);
    else if (m->grav_table >= 0) snprintf(fn, sizeof fn, " times /FUNCT/%d of t", m->table[m->grav_table].id);
    else if (m->grav_tstart > 0) snprintf(fn, sizeof fn, " from %.6g s (its sensor)", m->grav_tstart);
    if (m->grav_sens >= 0 && m->sens_id)
        snprintf(fn, sizeof fn, "%s from the time sensor %d turns on (found in the run)",
                 m->grav_table >= 0 ? " times a /FUNCT of t - t_on," : "", m->sens_id[m->grav_sens]);
    if (gn == 0.0 && nsame == nfree) {
        fprintf(f, "gravity     none\n");
        return;
    }
    fprintf(f, "gravity     (%.6g, %.6g, %.6g) m/s^2%s, |g| %.6g m/s^2, on %s%s\n", g[0], g[1], g[2], fn, gn,
            nsame == nfree ? "every free body" : "the first free body",
            nsame == nfree ? "" : " (others differ: /GRAV on node groups)");
    /* the same in the deck's own units (/BEGIN's input units), as typed */
    const double lf = m->deck_factor[1], tf = m->deck_factor[2];
    char du[64] = "";
    if (lf > 0 && tf > 0) {
        const double s = tf * tf / lf; /* m/s^2 -> deck length / deck time^2 */
        snprintf(du, sizeof du, "%s/%s^2", m->deck_unit[1], m->deck_unit[2]);
        fprintf(f, "            in the deck's units: (%.6g, %.6g, %.6g) %s, |g| %.6g %s\n", g[0] * s + 0.0, g[1] * s + 0.0,
                g[2] * s + 0.0, du, gn * s, du);
    } else {
        fprintf(f, "            the deck names no units: the values are taken as written, in one consistent system "
                   "(shown as SI)\n");
    }
    const double r = gn / 9.80665;
    if (gn > 0 && (r < 0.05 || r > 20)) {
        char hint[400] = "a deck in mm takes -9810 mm/s^2, not -9.81";
        if (du[0])
            snprintf(hint, sizeof hint, "the deck's length unit is %s: the Earth's gravity is %.6g %s, the deck gives "
                     "%.6g %s%s", m->deck_unit[1], 9.80665 * tf * tf / lf, du, gn * tf * tf / lf, du,
                     r > 20 && lf >= 0.5 ? ", the value in mm/s^2?" : "");
        fprintf(f, "warning     |g| = %.6g m/s^2 is %.3g times the Earth's 9.81 m/s^2: gravity is given in the deck's "
                   "units (%s); is it meant?\n",
                gn, r, hint);
    }
}

void rc_model_print_summary(const rc_model *m, FILE *f)
{
    if (!m || !f) return;
    fprintf(f, "case        %s (checksum %016lx)\n", m->case_path, m->checksum);
    if (m->title[0]) fprintf(f, "title       %s\n", m->title);
    if (m->unit_mass[0])
        fprintf(f, "units       declared (/BEGIN or /UNIT): the values are converted to mass %s, length %s, time %s "
                   "(the warnings of the reading give the deck's units and the factors)\n",
                m->unit_mass, m->unit_length, m->unit_time);
    else
        fprintf(f, "units       undeclared (one consistent system assumed; this summary names SI units)\n");
    fprintf(f, "bodies      %d (%d free, %d fixed)\n", m->nbody, m->nfree, m->nbody - m->nfree);
    for (int b = 0; b < m->nbody && b < 20; b++) {
        const double *y0 = m->body_y0 + RC_NB * b;
        const double x0[3] = {y0[0] + m->origin[0], y0[1] + m->origin[1], y0[2] + m->origin[2]}; /* the deck's */
        fprintf(f, "  /RBODY/%-6d mass %-11.5g x0 (%.5g, %.5g, %.5g) v0 (%.5g, %.5g, %.5g)%s\n", m->body_id[b],
                m->body_mass[b], x0[0], x0[1], x0[2], y0[7], y0[8], y0[9], m->body_fixed[b] ? " fixed" : "");
        const double *J = m->body_J + 9 * b;
        const double v[10] = {J[0], J[4], J[8], J[1], J[5], J[2], m->body_mass[b], x0[0], x0[1], x0[2]};
        char ex[10][32];
        for (int k = 0; k < 10; k++) exact(ex[k], sizeof ex[k], v[k]);
        fprintf(f, "               inertia Jxx Jyy Jzz %s %s %s Jxy Jyz Jxz %s %s %s mass %s x0 %s %s %s\n", ex[0], ex[1],
                ex[2], ex[3], ex[4], ex[5], ex[6], ex[7], ex[8], ex[9]);
    }
    if (m->nbody > 20) fprintf(f, "  ... and %d more bodies (the first 20 in deck order are listed)\n", m->nbody - 20);
    print_gravity(m, f);
    rc_report_plausibility(m, f); /* estimate.c */
    fprintf(f, "surfaces    %d\n", m->nsurf);
    if (m->start_note) fprintf(f, "warning     accepted by /RUN On_viol 2: %s\n", m->start_note); /* engine/analyses/start.c */
    fprintf(f, "interfaces  %d\n", m->ninter);
    for (int i = 0; i < m->ninter && i < 20; i++) {
        if (m->inter_law[i] == RC_LAW_POWER) {
            rc_power_print(m, i, f); /* model/power.c */
            continue;
        }
        fprintf(f, "  %-18s %s, Iform %d, Gap %.5g, Visc %.5g, Stiff %.5g, Inacti %d, Tstart %.5g, Tstop %.5g%s\n",
                m->inter_name[i], rc_geom_inter_pair_name(m, i), m->inter_iform[i], m->inter_gap[i],
                m->inter_visc[i], m->inter_stiff[i], m->inter_inacti[i], m->inter_tstart[i], m->inter_tstop[i],
                rc_sensor_note(m, i));
    }
    for (int i = 0; i < m->ninter && i < 20; i++) rc_friction_print(m, i, f);
    if (m->ninter > 20)
        fprintf(f, "  ... and %d more interfaces (the first 20 in deck order are listed)\n", m->ninter - 20);
    rc_cpl_print_summary(m, f);
    if (m->jnt) {
        fprintf(f, "joints      %d, %d constraint rows (IDA path)\n", m->jnt->n, m->jnt->nrows);
        rc_jnt_print(m, f);
    }
    rc_imp_print(m, f);
    fprintf(f, "states      %d, Jacobian nonzeros %lld\n", m->ny, (long long)m->nnz);
    fprintf(f, "run         end time %.6g s, output every %.6g s\n", m->tend, m->dtout);
    if (m->ev_state == 0)
        fprintf(f, "            full-state records at events: %s (Ev_state 0: while bodies <= %d)\n",
                rc_event_records(m) ? "yes" : "no, events table only", RC_EVREC_MAX_BODIES);
    else
        fprintf(f, "            full-state records at events: %s (Ev_state %d)\n",
                m->ev_state == 1 ? "yes" : "no, events table only", m->ev_state);
    fprintf(f, "solver      %s BDF (max order %d), Newton, KLU; rtol %.3g\n",
            m->method == 2 ? "IDA (residual form, Method 2)" : "CVODE (Method 1)", m->max_order, m->rtol);
    if (m->preload && m->method != 3)
        fprintf(f, "            preload: the run starts at rest from the static equilibrium at t = 0 (KINSOL; "
                   "/SOLVER Preload 1)\n");
    if (m->method_switch && m->method != 2 && m->method != 3)
        fprintf(f, "            method switching: to an explicit Runge-Kutta method (ARKODE ERKStep) while impacts "
                   "pin BDF near the explicit stability limit, and back (/SOLVER Switch 1)\n");
    /* the tolerances in force: given on /SOLVER, or derived from the scales */
    const int au = m->tol_auto;
    if (au == 0) {
        fprintf(f, "            atol: position %.3g m, quaternion %.3g, velocity %.3g m/s, angular %.3g rad/s, energy %.3g J\n",
                m->atol_pos, m->atol_quat, m->atol_vel, m->atol_omega, m->atol_energy);
    } else {
        double lo[4] = {INFINITY, INFINITY, INFINITY, INFINITY}, hi[4] = {0, 0, 0, 0};
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            const int off[4] = {0, 3, 7, 10};
            for (int k = 0; k < 4; k++) {
                const double a = m->atol[m->body_yadr[b] + off[k]];
                lo[k] = fmin(lo[k], a);
                hi[k] = fmax(hi[k], a);
            }
        }
        char rg[4][80];
        for (int k = 0; k < 4; k++) range3(rg[k], sizeof rg[k], lo[k], hi[k]);
        fprintf(f, "            atol (%s): position %s m%s, quaternion %s, velocity %s m/s,\n"
                   "            angular %s rad/s, energy %.3g J\n",
                au == (RC_TOL_AUTO_POS | RC_TOL_AUTO_QUAT | RC_TOL_AUTO_VEL | RC_TOL_AUTO_OMEGA | RC_TOL_AUTO_ENERGY)
                    ? "derived from the contact scales"
                    : "blank fields derived from the contact scales",
                rg[0], m->ewt_rel ? " (absolute)" : "", rg[1], rg[2], rg[3], m->atol_energy);
        char fl[480];
        rc_model_tol_floor_note(m, fl, sizeof fl);
        if (fl[0]) fprintf(f, "            note: %s\n", fl);
    }
    int nsc = 0;
    for (int i = 0; i < m->ninter; i++) nsc += isfinite(m->inter_pscale[i]) != 0;
    fprintf(f, "scales      %d of %d interfaces scaled (penetration p_s, force F_s, speed v_s)\n", nsc, m->ninter);
    for (int i = 0; i < m->ninter && i < 20; i++) {
        if (isfinite(m->inter_pscale[i]))
            fprintf(f, "  %-18s p_s %.4g m, F_s %.4g N, k_s %.4g N/m, v_s %.4g m/s\n", m->inter_name[i],
                    m->inter_pscale[i], m->inter_fscale[i], m->inter_kscale[i], m->inter_vscale[i]);
        else
            fprintf(f, "  %-18s no scale (no gravity or speed reaches it): fixed fallback tolerances\n", m->inter_name[i]);
    }
    if (m->ninter > 20) fprintf(f, "  ... %d more\n", m->ninter - 20);
    if (m->ninter > 0) print_guidance(m, f);
    if (m->method != 3) rc_report_estimate(m, f); /* estimate.c; not for a static solve (/SOLVER Method 3) */
}

void rc_cpl_print_summary(const rc_model *m, FILE *f)
{
    static const char *const form_name[6] = {"", "constant k", "polynomial k_eff", "force table f_e(x)",
                                             "stiffness table k(x)", "general spring (six K, C in a frame)"};
    const rc_couplings *p = m->cpl;
    fprintf(f, "couplings   %d\n", p->ncard); /* the joint stops: with their joints */
    double *y = malloc(((size_t)m->ny + 1) * sizeof(double));
    if (y) rc_initial_state(m, y);
    for (int k = 0; k < p->ncard && k < 20; k++) {
        const int ids[2] = {p->b1[k] >= 0 ? m->body_id[p->b1[k]] : 0, p->b2[k] >= 0 ? m->body_id[p->b2[k]] : 0};
        rc_cpl_report r;
        const int ok = y && rc_cpl_report_eval(m, NULL, k, 0.0, y, &r) == 0;
        fprintf(f, "  %-22s bodies %d-%d, ", p->name[k], ids[0], ids[1]);
        if (p->kind[k] == RC_CPL_CONTACT)
            rc_cpl_contact_print(m, k, ok ? &r : NULL, f);
        else if (p->kind[k] == RC_CPL_SPRING && p->form[k] == RC_KEFF_GENE) {
            const double *g = p->gk + 12 * k;
            const int fb = p->gfb[k], fbody = fb == 1 ? p->b1[k] : fb == 2 ? p->b2[k] : -1;
            char curves[64] = "";
            for (int i = 0, n = 0; i < 6; i++)
                if (p->gtab[6 * k + i] >= 0)
                    n += snprintf(curves + n, sizeof curves - (size_t)n, "%s%s", n ? " " : ", curves in ",
                                  (const char *const[]){"X'", "Y'", "Z'", "RX'", "RY'", "RZ'"}[i]);
            char frame[48];
            if (fbody >= 0) snprintf(frame, sizeof frame, "frame turning with body %d", m->body_id[fbody]);
            else snprintf(frame, sizeof frame, "frame fixed in space");
            fprintf(f, "%s, %s, K %.5g %.5g %.5g N/m, %.5g %.5g %.5g N m/rad, C %.5g %.5g %.5g N s/m, %.5g %.5g %.5g "
                       "N m s/rad%s; at t = 0: displacement %.5g m, force %.5g N\n",
                    form_name[p->form[k]], frame, g[0], g[1], g[2], g[3], g[4], g[5], g[6], g[7], g[8], g[9], g[10],
                    g[11], curves, ok ? r.length : NAN, ok ? r.force : NAN);
        } else if (p->kind[k] == RC_CPL_SPRING)
            fprintf(f, "%s, x0 %.5g m, k_d %.5g N s/m; at t = 0: length %.5g m, force %.5g N\n",
                    form_name[p->form[k]], p->x0[k], p->kd[k], ok ? r.length : NAN, ok ? r.force : NAN);
        else
            fprintf(f, "lambda0 %.5g kg/m, L_eq %.5g m, EA %.5g N; at t = 0: distance %.5g m, tension at end 1 %.5g N, "
                    "lowest point %.5g m along -g%s\n",
                    p->lambda0[k], p->leq[k], p->ea[k], ok ? r.length : NAN, ok ? r.force : NAN,
                    ok ? r.lowest : NAN, ok ? "" : " (catenary equations not solved)");
    }
    if (p->ncard > 20)
        fprintf(f, "  ... and %d more couplings (the first 20 in deck order are listed)\n", p->ncard - 20);
    free(y);
}

void rc_cpl_frame(const rc_model *m, const rc_data *d, double t, const double *y, double *buf)
{
    const int n = m->cpl->ncard; /* the joint stops: with their joints */
    for (int k = 0; k < n; k++) {
        rc_cpl_report r;
        rc_cpl_report_eval(m, d, k, t, y, &r);
        buf[k] = r.force;
        buf[n + k] = r.length;
        for (int i = 0; i < 3; i++) {
            buf[2 * n + 3 * k + i] = r.f1[i];
            buf[5 * n + 3 * k + i] = r.f2[i];
        }
        buf[8 * n + k] = r.lowest;
    }
}
