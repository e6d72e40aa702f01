/*
 * `ricochet check`: an order-of-magnitude estimate of a whole run's
 * integrator steps and wall time, and the plausibility warnings on the
 * deck's scales (docs/case-format.md, "ricochet check").
 *
 * The estimate treats every interface on its own along its normal, from
 * the state at t = 0: a contact closed at t = 0 without approaching is a
 * persistent contact for the whole run; one that closes (at the approach
 * speed and the gravity along the normal, over its gap) bounces at its
 * predicted restitution (the geometric series of flights 2 v e^k / a_n)
 * until the end time, or until a flight is shorter than the contact time
 * scale: then it rests (a persistent contact for the rest of the run).
 * Steps: RC_EST_STEPS_IMPACT per impact, RC_EST_STEPS_SETTLE per persistent
 * contact (its settling) and RC_EST_STEPS_PER_TC per contact time scale of
 * the busiest persistent contact (they share the steps), plus
 * RC_EST_STEPS_PER_PERIOD per period of each coupling and joint stop; wall
 * time: a fixed cost plus a cost per step that grows with the bodies and
 * contact points. The constants were measured on the cases/ decks; the
 * estimate is within a factor of 10 of the runs there, not better.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "model/coupling.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/power.h"
#include "engine/analyses/restitution.h"
#include "engine/assembly/assembly.h"
#include "engine/assembly/bounds.h"
#include "engine/reports/reports.h"

/* Steps per impact at the default tolerances (report.c measures 124..267 on
 * the restitution validation problems; a whole bounce with its flight takes
 * about 75 on the demo) [-]. */
#define RC_EST_STEPS_IMPACT 100.0
/* Steps of a persistent contact settling, and per contact time scale while
 * it is held [-]. */
#define RC_EST_STEPS_SETTLE 150.0
#define RC_EST_STEPS_PER_TC 5.0
/* ... for a hysteresis law (Iform 1, 2: a held contact keeps moving along
 * its branches; measured on cases/t6_hysteresis_drop.rad) [-] */
#define RC_EST_STEPS_PER_TC_HYST 60.0
/* A held contact costs steps for at most this many contact time scales,
 * and a coupling for at most this many periods: once the motion has
 * settled the integrator's steps grow (measured: a ball at rest for 1 s,
 * 34000 contact times, took 2000 steps) [-]. */
#define RC_EST_HELD_TC_MAX 400.0
#define RC_EST_PERIODS_MAX 200.0
/* A body at rest whose acceleration at t = 0 is below this fraction of its
 * gravity (or of 1 m/s^2 without gravity) starts in equilibrium [-]. */
#define RC_EST_EQUILIBRIUM 1e-3
/* The fewest steps of a run [-]. */
#define RC_EST_STEPS_MIN 10.0
/* Steps per period of a coupling's natural frequency (measured on
 * cases/catenary_swing.rad: 413) [-]. */
#define RC_EST_STEPS_PER_PERIOD 300.0
/* Steps per swing of a jointed body (the IDA path; measured on the
 * pendulums of cases/ and validation/) and per impact on a joint's stop [-]. */
#define RC_EST_STEPS_JOINT 1000.0
#define RC_EST_STEPS_STOP 300.0
/* Wall time: fixed cost of a run (opening and closing the results file,
 * the compile already done) [s], and per step and per (body + contact
 * point + interface) [s]. */
#define RC_EST_WALL_FIXED 0.01
#define RC_EST_WALL_STEP 4e-6
#define RC_EST_WALL_RECORD 1e-6
/* Restitution assumed where none is predicted [-]. */
#define RC_EST_RESTITUTION 0.5
/* Impacts counted per interface at most [-]. */
#define RC_EST_MAX_IMPACTS 1e7

/* Plausibility bounds: a free body larger (largest distance from its
 * centre to the far side of its surfaces) [m] or heavier [kg]. */
#define RC_PLAUS_SIZE 50.0
#define RC_PLAUS_MASS 1e6

/* The predicted restitution of interface i at the impact speed v [-]. */
static double restitution(const rc_model *m, int i, double v)
{
    const double mr = m->inter_mrest[i];
    double k = m->inter_kscale[i];
    double e = NAN;
    const int curves = m->inter_law[i] == RC_LAW_TYPE6 &&
                       (m->inter_fct_dv[i] >= 0 || m->inter_fct_df[i] >= 0 || m->inter_iform[i] != 0);
    if (isfinite(mr) && mr > 0 && rc_type6_linear_slope(m, i, &k) && !curves && k > 0) {
        const double zeta = m->inter_visc[i] / (2.0 * sqrt(k * mr));
        double tau;
        e = rc_linear_restitution(zeta, &tau);
    } else if (isfinite(mr) && mr > 0 && v > 0 && rc_restitution_supported(m, i, NULL)) {
        const double damp = m->inter_law[i] == RC_LAW_POWER ? m->inter_pw[i].c : m->inter_visc[i];
        e = rc_restitution_solve(m, i, mr, v, damp, NULL);
    }
    if (!(e >= 0.0 && e < 1.0)) e = RC_EST_RESTITUTION;
    return e;
}

/* Which free bodies start at rest in equilibrium (rest[b] = 1): no speed
 * and, with the contacts penetrating at t = 0 closed, an acceleration below
 * RC_EST_EQUILIBRIUM of their gravity. Such a body costs no steps until
 * something reaches it. */
static void at_rest(const rc_model *m, const double *y, int *rest)
{
    for (int b = 0; b < m->nbody; b++) rest[b] = 0;
    rc_data *d = rc_data_new(m);
    double *f = malloc(((size_t)m->ny + 1) * sizeof(double));
    if (d && f) {
        for (int i = 0; i < m->ninter; i++) {
            rc_inter_report r;
            rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
            if (r.p_raw > 0) d->inter_mode[i] = RC_MODE_CLOSED;
        }
        if (rc_assemble_rhs(m, d, 0.0, y, f) == 0) {
            for (int b = 0; b < m->nbody; b++) {
                const int a = m->body_yadr[b];
                if (a < 0) continue;
                const double *v = y + a + 7, *g = m->body_grav + 3 * b, *dv = f + a + 7, *dw = f + a + 10;
                double speed = 0.0, acc = 0.0, gn = 0.0;
                for (int c = 0; c < 6; c++) speed = fmax(speed, fabs(v[c]));
                for (int c = 0; c < 3; c++) {
                    acc = fmax(acc, fmax(fabs(dv[c]), fabs(dw[c]) * 0.0));
                    gn += g[c] * g[c];
                }
                gn = sqrt(gn);
                rest[b] = speed == 0.0 && acc <= RC_EST_EQUILIBRIUM * (gn > 0 ? gn : 1.0);
            }
        }
    }
    free(f);
    rc_data_free(d);
}

/* Does interface i or coupling end b start at rest (a fixed end or no end
 * counts as at rest)? */
static int pair_rest(const int *rest, int ba, int bb)
{
    return (ba < 0 || rest[ba]) && (bb < 0 || rest[bb]);
}

void rc_report_estimate(const rc_model *m, FILE *f)
{
    const double T = m->tend;
    double *y = malloc(((size_t)m->ny + 1) * sizeof(double));
    double *y2 = malloc(((size_t)m->ny + 1) * sizeof(double));
    int *rest = malloc(((size_t)m->nbody + 1) * sizeof(int));
    if (!y || !y2 || !rest) {
        free(y);
        free(y2);
        free(rest);
        return;
    }
    rc_initial_state(m, y);
    at_rest(m, y, rest);
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] < 0) rest[b] = 1;
    /* the same state with every free body's velocity raised by its gravity
     * over 1 s: the approach rate's change is the gravity along the normal */
    for (int k = 0; k < m->ny; k++) y2[k] = y[k];
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0)
            for (int c = 0; c < 3; c++) y2[m->body_yadr[b] + 7 + c] += m->body_grav[3 * b + c];
    double nimp = 0.0, npers = 0.0, busy = 0.0, steps = 0.0;
    int unscaled = 0;
    for (int i = 0; i < m->ninter; i++) {
        const double tc = RC_PI * m->inter_pscale[i] / m->inter_vscale[i];
        if (!(isfinite(tc) && tc > 0)) {
            unscaled++;
            continue;
        }
        rc_inter_report r, r2;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y2, &r2);
        const double gap = -r.p_raw, vn = r.vn, a = r2.vn - r.vn;
        const double t0 = fmax(m->inter_tstart[i], 0.0);
        double held = 0.0; /* time held as a persistent contact [s] */
        if (gap <= 0.0 && !(vn > 0.0)) {
            held = T - t0; /* closed (or touching) at rest: persistent from the start */
        } else {
            /* the first closing: gap = vn t + a t^2 / 2 */
            double t1 = INFINITY;
            if (gap <= 0.0) t1 = 0.0;
            else if (a > 0.0) t1 = (-vn + sqrt(vn * vn + 2.0 * a * gap)) / a;
            else if (vn > 0.0 && a == 0.0) t1 = gap / vn;
            else if (vn > 0.0 && vn * vn + 2.0 * a * gap >= 0.0) t1 = (-vn + sqrt(vn * vn + 2.0 * a * gap)) / a;
            double t = t0 + t1, v = vn + a * t1;
            const double e = restitution(m, i, v);
            double n = 0.0;
            while (t < T && n < RC_EST_MAX_IMPACTS) {
                n += 1.0;
                t += tc;
                if (!(a > 0.0)) break; /* nothing brings it back: one impact */
                v *= e;
                const double flight = 2.0 * v / a;
                if (flight < tc) {
                    held = T - t; /* the bounces accumulated: at rest */
                    break;
                }
                t += flight;
            }
            nimp += n;
        }
        if (held > 0.0) {
            npers += 1.0;
            /* from a static preload the contacts start settled: the
             * integrator's steps grow while nothing moves */
            const int from_start =
                held >= T - t0 && (m->preload || pair_rest(rest, m->inter_ba[i], m->inter_bb[i]));
            const double rate = m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0 ? RC_EST_STEPS_PER_TC_HYST
                                                                                         : RC_EST_STEPS_PER_TC;
            if (!m->preload) steps += RC_EST_STEPS_SETTLE;
            if (!from_start) busy = fmax(busy, rate * fmin(held / tc, RC_EST_HELD_TC_MAX));
        }
    }
    steps += RC_EST_STEPS_IMPACT * nimp + busy;
    /* couplings: their natural periods over the run (springs of constant
     * stiffness, catenaries by EA / L_eq, on the mass of their free end);
     * contact couplings: one impact, then held (their stopping time tau
     * for the contact time); joint stops (the IDA path): the pendulum's
     * swings under gravity and two stop impacts per swing */
    const rc_couplings *p = m->cpl;
    double osc = 0.0; /* the busiest coupling or joint: they share the steps */
    for (int k = 0; p && k < p->n; k++) {
        const int b = p->b1[k] >= 0 ? p->b1[k] : p->b2[k];
        if (b < 0 || m->body_yadr[b] < 0) continue;
        const double mass = m->body_mass[b];
        double stiff = NAN;
        if (p->kind[k] == RC_CPL_CATENARY && p->leq[k] > 0) stiff = p->ea[k] / p->leq[k];
        if (p->kind[k] == RC_CPL_SPRING && p->form[k] == RC_KEFF_CONST) stiff = p->coef[3 * k];
        const int still = pair_rest(rest, p->b1[k], p->b2[k]);
        if (p->kind[k] == RC_CPL_SPRING && p->form[k] == RC_KEFF_POLY && p->coef[3 * k] > 0) stiff = p->coef[3 * k];
        if (p->kind[k] == RC_CPL_SPRING && p->form[k] == RC_KEFF_GENE) /* the stiffest translation */
            stiff = fmax(fmax(p->gk[12 * k], p->gk[12 * k + 1]), p->gk[12 * k + 2]);
        if (!still && (p->kind[k] == RC_CPL_SPRING || p->kind[k] == RC_CPL_CATENARY)) {
            /* a stiffness not known here (tables): the most periods */
            const double per = isfinite(stiff) && stiff > 0 && mass > 0
                                   ? fmin(T / (2.0 * RC_PI * sqrt(mass / stiff)), RC_EST_PERIODS_MAX)
                                   : RC_EST_PERIODS_MAX;
            osc = fmax(osc, RC_EST_STEPS_PER_PERIOD * per);
        }
        if (p->kind[k] == RC_CPL_CONTACT && k < p->ncard) {
            const double tau = p->ct->tau[k];
            if (isfinite(tau) && tau > 0) {
                nimp += 1.0;
                steps += RC_EST_STEPS_IMPACT + RC_EST_STEPS_PER_TC * T / tau;
            }
        }
        if (p->kind[k] == RC_CPL_LIMIT) {
            const double *s = p->s1 + 3 * k, r = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
            const double *g = m->body_grav + 3 * b, gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
            const double *J = m->body_J + 9 * b, I = fmax(J[0], fmax(J[4], J[8])) + mass * r * r;
            const double swings = gn > 0 && r > 0 ? T / (2.0 * RC_PI * sqrt(I / (mass * gn * r))) : 1.0;
            nimp += 2.0 * swings; /* the stops: two impacts per swing */
            steps += RC_EST_STEPS_STOP * 2.0 * swings;
        }
    }
    /* joints (the IDA path): the swings of each jointed body under gravity
     * about its anchor */
    const rc_joints *jn = m->jnt;
    for (int k = 0; jn && k < jn->n; k++) {
        const int b = jn->ba[k] >= 0 && m->body_yadr[jn->ba[k]] >= 0 ? jn->ba[k] : jn->bb[k];
        if (b < 0 || m->body_yadr[b] < 0 || rest[b]) continue;
        const double *s = b == jn->ba[k] ? jn->sa + 3 * k : jn->sb + 3 * k;
        const double r = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), mass = m->body_mass[b];
        const double *g = m->body_grav + 3 * b, gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        const double *J = m->body_J + 9 * b, I = fmax(J[0], fmax(J[4], J[8])) + mass * r * r;
        const double swings = gn > 0 && r > 0 && mass > 0 ? T / (2.0 * RC_PI * sqrt(I / (mass * gn * r))) : 1.0;
        osc = fmax(osc, RC_EST_STEPS_JOINT * fmin(swings, RC_EST_PERIODS_MAX));
    }
    steps += osc;
    steps = fmax(steps, RC_EST_STEPS_MIN);
    const double work = 1.0 + m->nbody + m->ninter + 0.1 * m->npt;
    const double nrec = T / m->dtout + 2.0 * nimp;
    const double wall = RC_EST_WALL_FIXED + RC_EST_WALL_STEP * steps * work + RC_EST_WALL_RECORD * nrec * work;
    fprintf(f, "estimate    an order of magnitude, within ~10x (from the contact time scales pi p_s / v_s, the "
               "predicted restitutions, the gaps and the end time %.4g s):\n",
            T);
    fprintf(f, "            ~%.2g impacts, ~%.2g persistent contacts (resting, rolling, sliding); ~%.2g integrator "
               "steps; ~%.2g s wall time on a 2-core machine\n",
            nimp, npers, steps, wall);
    if (unscaled > 0)
        fprintf(f, "            (%d interface%s without scales left out)\n", unscaled, unscaled == 1 ? "" : "s");
    free(y);
    free(y2);
    free(rest);
}

void rc_report_plausibility(const rc_model *m, FILE *f)
{
    double *size = malloc(((size_t)m->nbody + 1) * sizeof(double));
    if (!size) return;
    rc_body_sizes(m, size);
    const char *lu = m->deck_unit[1][0] ? m->deck_unit[1] : "m";
    const double lf = m->deck_factor[1] > 0 ? m->deck_factor[1] : 1.0, mf = m->deck_factor[0] > 0 ? m->deck_factor[0] : 1.0;
    const char *mu = m->deck_unit[0][0] ? m->deck_unit[0] : "kg";
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue; /* fixed: the ground may be large */
        char in[64] = "";
        if (size[b] > RC_PLAUS_SIZE) {
            if (lf != 1.0) snprintf(in, sizeof in, " (%.4g %s)", size[b] / lf, lu);
            fprintf(f, "warning     /RBODY/%d is %.4g m%s from its centre to the far side of its surfaces, above "
                       "%g m: are the lengths in the deck's units (%s)?\n",
                    m->body_id[b], size[b], in, RC_PLAUS_SIZE, lu);
        }
        /* a heavy body that gravity does not act on is a driver of
         * quasi-infinite mass (a belt, a press): meant */
        const double *g = m->body_grav + 3 * b;
        if (m->body_mass[b] > RC_PLAUS_MASS && (g[0] != 0.0 || g[1] != 0.0 || g[2] != 0.0))
        {
            in[0] = '\0';
            if (mf != 1.0) snprintf(in, sizeof in, " (%.4g %s)", m->body_mass[b] / mf, mu);
            fprintf(f, "warning     /RBODY/%d has a mass of %.4g kg%s, above %g kg: is the mass in the deck's units "
                       "(%s)?\n",
                    m->body_id[b], m->body_mass[b], in, RC_PLAUS_MASS, mu);
        }
    }
    /* a contact so soft that the weight, or the impact, pushes one body
     * into the other deeper than the body's own size */
    for (int i = 0; i < m->ninter; i++) {
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        double L = INFINITY;
        if (ba >= 0 && size[ba] > 0) L = fmin(L, size[ba]);
        if (bb >= 0 && size[bb] > 0) L = fmin(L, size[bb]);
        if (!isfinite(L)) continue;
        const double pw = m->inter_pweight[i], pi = m->inter_pimpact[i];
        if (isfinite(pw) && pw > L)
            fprintf(f, "warning     %s: the static penetration under the weight, %.4g m, is larger than the body's "
                       "size %.4g m: the contact stiffness is too low (in the deck's units?)\n",
                    m->inter_name[i], pw, L);
        else if (isfinite(pi) && pi > L)
            fprintf(f, "warning     %s: the penetration of an impact (at the model's speed scale, or the fall over "
                       "the gap), %.4g m, is larger than the body's size %.4g m: the contact stiffness is too low (in "
                       "the deck's units?)\n",
                    m->inter_name[i], pi, L);
    }
    free(size);
}

/* The largest eigenvalue of body b's inverse inertia, bounded by the
 * largest absolute row sum (Gershgorin) [1/(kg m^2)]. */
static double jinv_bound(const rc_model *m, int b)
{
    const double *Ji = m->body_Jinv + 9 * b;
    double g = 0.0;
    for (int k = 0; k < 3; k++) g = fmax(g, fabs(Ji[3 * k]) + fabs(Ji[3 * k + 1]) + fabs(Ji[3 * k + 2]));
    return g;
}

/* The friction of closed interface i at (t, y), where it is a stick spring
 * (the incremental form, K_t): its stiffness K_t and the stick damper's
 * rate act along the tangent at the contact point, through the bodies'
 * rotations too (1 / m + rho^2 / J for a body whose centre is rho from the
 * point), into kb, cb (weight w, as the normal contact's); the slip law
 * turns and loads F_t at K_t |v_t| / L_r (L_r at least the limit and the
 * force scale F_s, docs/theory.md 3.5), a decay rate returned [1/s]. */
static double friction_rates(const rc_model *m, const rc_data *d, int i, double t, const double *y, double w,
                             double *kb, double *cb)
{
    const rc_fric *fr = &m->inter_fr[i];
    if (fr->kind == RC_FK_NONE || fr->form != RC_FF_INCREMENTAL || fr->exact || !(fr->kt > 0) || !isfinite(fr->kt))
        return 0.0;
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]}, per_point = m->inter_npt[i] > 0;
    /* the sliding speed: the report's, and with friction per contact
     * point (the report's a mean weighted by the shares) the points' spread
     * about it, at most |omega| times each body's size */
    double vs = r.vslip;
    for (int k = 0; k < 2; k++) {
        const int b = bs[k];
        if (b < 0 || m->body_yadr[b] < 0) continue;
        const double *x = y + m->body_yadr[b], *om = x + 10;
        const double size = per_point ? rc_body_size(m, b) : 0.0;
        const double rho2 = per_point ? size * size
                                      : (r.point[0] - x[0]) * (r.point[0] - x[0]) +
                                            (r.point[1] - x[1]) * (r.point[1] - x[1]) +
                                            (r.point[2] - x[2]) * (r.point[2] - x[2]);
        const double rot = 1.0 + m->body_mass[b] * rho2 * jinv_bound(m, b);
        kb[b] += w * fr->kt * rot;
        if (isfinite(fr->ct) && fr->ct > 0) cb[b] += w * fr->ct * rot;
        vs += sqrt(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]) * size;
    }
    const double fs = m->inter_fscale[i];
    const double L = fmax(r.flim, isfinite(fs) ? RC_SLIP_LFLOOR * fs : 0.0);
    return L > 0 ? fr->kt * vs / L : 0.0;
}

/* The critical step of an explicit method on the closed contacts
 * (reports.h; docs/theory.md 7.9): omega_max^2 and the damping rate
 * bounded by Gershgorin's rows of M^-1 K and M^-1 C over the free bodies'
 * translations, each closed contact with its stiffness scale k_s and its
 * linear damping, its friction's stick spring with the rotations it
 * turns (friction_rates), h_crit = 2 / omega_max (sqrt(1 + zeta^2) -
 * zeta), and at most 2 / kappa for the fastest decay kappa of a law's
 * state (P_e's relaxation, the slip law's turning). */
double rc_explicit_step(const rc_model *m, const rc_data *d, double t, const double *y, double *work)
{
    double *kb = work, *cb = work + m->nbody;
    for (int b = 0; b < m->nbody; b++) kb[b] = cb[b] = 0.0;
    int any = 0;
    double kappa = 0.0; /* the fastest decay of a law's state (P_e, the slip law) [1/s] */
    for (int i = 0; i < m->ninter; i++) {
        if (d->inter_mode[i] != RC_MODE_CLOSED) continue;
        if (m->inter_peidx[i] >= 0 && isfinite(m->inter_perelax[i])) kappa = fmax(kappa, m->inter_perelax[i]);
        const double k = m->inter_kscale[i];
        if (!(k > 0) || !isfinite(k)) continue;
        double c = 0.0;
        if (m->inter_law[i] == RC_LAW_TYPE6) c = m->inter_visc[i];
        else if (m->inter_law[i] == RC_LAW_POWER && m->inter_pw[i].m2 == 1.0 && m->inter_pw[i].m3 == 0.0 &&
                 !m->inter_pw[i].damp)
            c = m->inter_pw[i].c;
        if (!(c >= 0) || !isfinite(c)) c = 0.0;
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
        const double w = fa && fb ? 2.0 : 1.0; /* the diagonal and the off-diagonal entry of the row */
        if (fa) {
            kb[ba] += w * k;
            cb[ba] += w * c;
        }
        if (fb) {
            kb[bb] += w * k;
            cb[bb] += w * c;
        }
        any |= fa || fb;
        if (y) kappa = fmax(kappa, friction_rates(m, d, i, t, y, w, kb, cb));
    }
    /* P_e relaxes at kappa (theory 2.7), the slip law turns F_t at its
     * rate: decays the explicit method is stable on for h kappa <= 2 */
    const double hk = kappa > 0 ? 2.0 / kappa : INFINITY;
    if (!any) return hk;
    double w2 = 0.0, cr = 0.0;
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0 || !(m->body_mass[b] > 0)) continue;
        w2 = fmax(w2, kb[b] / m->body_mass[b]);
        cr = fmax(cr, cb[b] / m->body_mass[b]);
    }
    if (!(w2 > 0)) return hk;
    const double om = sqrt(w2), zeta = cr / (2.0 * om);
    return fmin(hk, 2.0 / om * (sqrt(1.0 + zeta * zeta) - zeta));
}
