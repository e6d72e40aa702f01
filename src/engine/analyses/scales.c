/*
 * The model's own scales, and the tolerances and regularisations derived
 * from them (docs/theory.md 7.1).
 *
 * Each interface gets a penetration scale p_s: the smallest penetration the
 * model is known to produce in it, from
 *   p_F  where the load law reaches the weight of the lighter free body,
 *        F(p_F) = m_min |g|max,
 *   p_E  where the law's stored energy reaches the kinetic energy of the
 *        pair at the speed scale, integral_0^p_E F = m_red v^2 / 2, with v
 *        the largest initial or imposed speed of any body (momentum travels
 *        through chains of contacts) or the fall speed over the
 *        interface's initial gap sqrt(2 |g|max gap0),
 *   p_s = min(p_F, p_E) over those that exist, but not below
 *   RC_PSCALE_SPAN p_F (a tiny speed must not set absurd tolerances).
 * With it: the force scale F_s = F(p_s), the stiffness k_s = dF/dp at p_s,
 * the contact frequency omega_s = sqrt(k_s / m_red) and the speed scale
 * v_s = p_s omega_s. The laws are inverted with GSL's Brent solver.
 *
 * Tolerances left blank on /SOLVER are derived per body from the smallest
 * scales of its contacts, so that the error control weighs what sets the
 * forces: positions absolutely at rtol p_s (not relative to centre
 * coordinates), rotations at rtol p_s / L (L the body's size), velocities
 * absolutely at rtol min(v_s, F_s / c) (c the largest velocity sensitivity
 * of the contact's forces), energies at 0.1 rtol times the model's energy
 * scale. A body without a scaled contact gets tolerances from its size and
 * the model's speed scale (RC_TOL_FALLBACK_*).
 */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/coupling.h"
#include "base/error.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "engine/assembly/bounds.h"
#include "model/model.h"
#include "base/progress.h"
#include "model/power.h"
#include "engine/analyses/restitution.h"
#include "engine/assembly/assembly.h"
#include "engine/analyses/analyses.h"

/* A body without a scaled contact: positions at rtol RC_TOL_FALLBACK_LFRAC
 * L (L its size), velocities at rtol RC_TOL_FALLBACK_LFRAC v_model, both
 * absolute only [-]; without any speed scale RC_TOL_FALLBACK_SPEED stands
 * for v_model. Energies without a scale: RC_TOL_FALLBACK_ENERGY. */
#define RC_TOL_FALLBACK_LFRAC 1e-4
#define RC_TOL_FALLBACK_SPEED 1.0   /* [m/s] */
#define RC_TOL_FALLBACK_ENERGY 1e-6 /* [J] */
/* Energy accumulators: RC_TOL_EFRAC rtol E_s [-]. */
#define RC_TOL_EFRAC 0.1
/* Derived regularisation of the power law: Dreg = RC_DREG_FRAC p_s,
 * Vreg = RC_DREG_FRAC v_s [-]. */
#define RC_DREG_FRAC 1e-4
/* ... and Dreg at least this many roundings of the pair's coordinates and
 * of the time's steps (docs/theory.md 9.2) [-]. */
#define RC_DREG_RES 64.0
/* p_s is at least this fraction of p_F [-]. */
#define RC_PSCALE_SPAN 1e-2
/* the end band of a cylinder's deepest point, in penetration scales */
#define RC_CYL_END_BAND 0.25
/* Damping ratio of the stick spring of incremental friction [-]. */
#define RC_STICK_ZETA 1.0

/* ---- the normal laws on p >= 0 ------------------------------------- */
/* Load force of interface i at penetration p [N] (no hysteresis, no damping). */
static double law_force(const rc_model *m, int i, double p)
{
    if (m->inter_law[i] == RC_LAW_POWER) {
        const rc_power *pw = &m->inter_pw[i];
        if (pw->stiff) {
            double f, df;
            rc_spline_eval(pw->stiff, p, &f, &df);
            return f;
        }
        return pw->k * pow(p, pw->m1);
    }
    double f, df;
    rc_table_eval(&m->table[m->inter_fct_ld[i]], p / m->inter_ascalex[i], &f, &df);
    return m->inter_fscaleld[i] * f;
}

/* Its slope [N/m]. */
static double law_slope(const rc_model *m, int i, double p)
{
    if (m->inter_law[i] == RC_LAW_POWER) {
        const rc_power *pw = &m->inter_pw[i];
        if (pw->stiff) {
            double f, df;
            rc_spline_eval(pw->stiff, p, &f, &df);
            return df;
        }
        return pw->k * pw->m1 * pow(p, pw->m1 - 1.0);
    }
    /* at a point of the load curve (a scale found by inverting the curve
     * lands on one within rounding: a curve with a point at the body's
     * weight), the steeper of its two sides, the same whichever side the
     * rounding put p on (the scene rotated and moved 1 km away took the
     * other side, k_s 1.1e4 against 2.3e4 N/m, and ran with other
     * tolerances) */
    return m->inter_fscaleld[i] / m->inter_ascalex[i] *
           rc_table_slope_at(&m->table[m->inter_fct_ld[i]], p / m->inter_ascalex[i]);
}

/* Energy stored at penetration p: integral_0^p of the load force [J]. */
static double law_energy(const rc_model *m, int i, double p)
{
    if (m->inter_law[i] == RC_LAW_POWER) {
        const rc_power *pw = &m->inter_pw[i];
        if (pw->stiff) return rc_spline_integral(pw->stiff, 0.0, p);
        return pw->k * pow(p, pw->m1 + 1.0) / (pw->m1 + 1.0);
    }
    const double ax = m->inter_ascalex[i];
    return m->inter_fscaleld[i] * ax * rc_table_integral(&m->table[m->inter_fct_ld[i]], 0.0, p / ax);
}

typedef struct {
    const rc_model *m;
    int i;
    int energy; /* 1: invert the energy, 0: the force */
    double target;
} inv_ctx;

static double inv_fn(double p, void *v)
{
    const inv_ctx *c = v;
    return (c->energy ? law_energy(c->m, c->i, p) : law_force(c->m, c->i, p)) - c->target;
}

/* Smallest p > 0 where the law (force or energy) reaches target > 0, or NAN
 * when it never does (a flat or falling law). */
static double invert(const rc_model *m, int i, int energy, double target)
{
    if (!(target > 0) || !isfinite(target)) return NAN;
    inv_ctx c = {m, i, energy, target};
    /* bracket: decades up from 1e-15 of the length unit */
    double lo = 0.0, hi = 1e-15;
    while (inv_fn(hi, &c) < 0) {
        lo = hi;
        hi *= 10.0;
        if (hi > 1e9) return NAN;
    }
    gsl_function f = {inv_fn, &c};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return NAN;
    double r = NAN;
    if (gsl_root_fsolver_set(s, &f, lo, hi) == GSL_SUCCESS) {
        for (int it = 0; it < 200; it++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
            double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
            r = gsl_root_fsolver_root(s);
            if (gsl_root_test_interval(a, b, 0.0, 1e-10) == GSL_SUCCESS) break;
        }
    }
    gsl_root_fsolver_free(s);
    return r > 0 ? r : NAN;
}

/* ---- body properties ------------------------------------------------- */
/* Sizes of all bodies (rc_body_size): the largest distance
 * from a body's centre to the far side of one of its surfaces [m] (0 when
 * it carries none). */
static void body_sizes(const rc_model *m, double *size) { rc_body_sizes(m, size); }

/* Largest speed of body b at t = 0: |v| + |omega| L [m/s]. */
static double body_speed(const rc_model *m, int b, double L)
{
    if (b < 0 || m->body_yadr[b] < 0) return 0.0;
    const double *y = m->body_y0 + RC_NB * b;
    double v = sqrt(y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
    double w = sqrt(y[10] * y[10] + y[11] * y[11] + y[12] * y[12]);
    return v + w * L;
}

/* Largest imposed speed of body b [m/s] (translations; rotations times L). */
static double imposed_speed(const rc_model *m, int b, double L)
{
    const rc_imposed *p = m->imp;
    double v = 0.0;
    if (!p) return 0.0;
    for (int k = 0; k < p->nt; k++)
        if (p->tbody[k] == b) v += rc_imp_tspeed(m, k);
    for (int k = 0; k < p->nr; k++)
        if (p->rbody[k] == b)
            for (int j = 0; j < 3; j++) v += rc_imp_rrate(m, k, j) * L;
    return v;
}

/* Does imposed translation j hold body b's translation along its
 * direction to the end of the run (imposed: any; else a /BCS hold alone)?
 * One that ends before, e.g. the hold of a body until its sensor's time,
 * leaves it free. */
static int held_along(const rc_model *m, int b, int j, int imposed)
{
    const rc_imposed *p = m->imp;
    return p->tbody[j] == b && p->ttstop[j] >= m->tend && p->tsens[j] < 0 && (imposed || p->tbcs[j] != 0);
}

/* The part of the unit normal n along which body b translates freely
 * [-]: the sum of n_k^2 over the global axes k along which it is neither
 * held (/BCS) nor, with imposed, imposed to the end of the run (/IMPVEL),
 * less (n . u)^2 for each skew axis u it is held or driven along, so that
 * a hold along a skew's axes counts as the same hold along the global ones
 * does. (A body with a skewed entry has no hold along a global axis, and
 * its skew axes are orthonormal: model/imposed.h. A belt held and driven
 * along a skew's axes counted as free: the contact on it got another
 * reduced mass, stick damper and speed scale than in the scene's own
 * axes.) */
static double free_part(const rc_model *m, int b, const double *n, int imposed)
{
    const rc_imposed *p = m->imp;
    const int nt = p ? p->nt : 0;
    double w = 0.0;
    for (int k = 0; k < 3; k++) {
        int held = m->body_dofmask[6 * b + k];
        for (int j = 0; j < nt; j++) held |= p->tdir[j] == k && held_along(m, b, j, imposed);
        if (!held) w += n[k] * n[k];
    }
    for (int j = 0; j < nt; j++)
        if (p->tdir[j] < 0 && held_along(m, b, j, imposed)) {
            const double *u = p->tu + 3 * j, d = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
            w -= d * d;
        }
    return w > 0.0 ? w : 0.0;
}

/* Mass of body b as seen along the unit normal n: m over the part of n
 * along which it translates freely (free_part), INFINITY for a fixed body
 * or one held along n (by /BCS, or by an /IMPVEL to the end of the run). */
static double normal_mass(const rc_model *m, int b, const double *n)
{
    if (b < 0 || m->body_yadr[b] < 0) return INFINITY;
    const double w = free_part(m, b, n, 1);
    return w > 1e-12 ? m->body_mass[b] / w : INFINITY;
}

/* Reduced mass of interface i's pair, every free body taking part whatever
 * its held directions [kg]; INFINITY when neither body is free. */
static double pair_mass(const rc_model *m, int i)
{
    double inv = 0.0;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int k = 0; k < 2; k++)
        if (bs[k] >= 0 && m->body_yadr[bs[k]] >= 0) inv += 1.0 / m->body_mass[bs[k]];
    return inv > 0 ? 1.0 / inv : INFINITY;
}

/* A contact's scales must be finite and resolvable in double precision: its
 * penetration scale above the resolution of the coordinates, its time scale
 * sqrt(m/k) above the resolution of the time over the run. Otherwise the
 * law's numbers (Stiff, the scale factors, the load curve) are beyond what
 * the integrator can follow: an input error naming the interface. */
static rc_status check_resolvable(const rc_model *m, int i, double mv, const double *y, const double *size,
                                  rc_error *err)
{
    const double p = m->inter_pscale[i], f = m->inter_fscale[i], k = m->inter_kscale[i], v = m->inter_vscale[i];
    const char *fields = m->inter_law[i] == RC_LAW_POWER ? "the stiffness and exponent fields"
                                                         : "Stiff, Fscale_ld and the load curve (fct_ID)";
    if (!isfinite(f) || !isfinite(k) || !isfinite(v)) {
        return RC_SET(err, RC_EINPUT,
                 RC_LOCFMT "card %s: the contact law overflows at its penetration scale p_s = %.3g m (force %.3g N, "
                 "stiffness %.3g N/m): %s give values beyond the double range; expected a law whose force "
                 "and stiffness stay finite",
                 RC_LOC(m->inter_loc[i]), m->inter_name[i], p, f, k, fields);
    }
    /* the largest coordinate of a body of the pair, and the time reached */
    double L = 0.0;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int j = 0; j < 2; j++) {
        const int b = bs[j];
        if (b < 0) continue;
        const double *x = m->body_yadr[b] >= 0 ? y + m->body_yadr[b] : m->body_y0 + RC_NB * b;
        for (int c = 0; c < 3; c++) L = fmax(L, fabs(x[c]) + size[b]);
    }
    const double ulp_x = L * DBL_EPSILON, tc = sqrt(mv / k), ulp_t = fmax(m->tend, 0.0) * DBL_EPSILON;
    if (p < 4.0 * ulp_x) {
        return RC_SET(err, RC_EINPUT,
                 RC_LOCFMT "card %s: the contact's penetration scale p_s = %.3g m (its penetration under the lighter "
                 "body's weight or at the impact energy) is below the resolution of the coordinates (%.3g m at "
                 "%.3g m from the origin): %s make the contact too stiff for double precision; expected a "
                 "stiffness that gives p_s of at least %.3g m (or coordinates nearer the origin)",
                 RC_LOC(m->inter_loc[i]), m->inter_name[i], p, ulp_x, L, fields, 4.0 * ulp_x);
    }
    if (tc < 4.0 * ulp_t) {
        return RC_SET(err, RC_EINPUT,
                 RC_LOCFMT "card %s: the contact's time scale sqrt(m/k) = %.3g s (reduced mass %.3g kg, stiffness "
                 "%.3g N/m at p_s) is below the resolution of the time at the end of the run (%.3g s at "
                 "T_end = %.3g s): %s make the contact too stiff to integrate; expected a stiffness below "
                 "%.3g N/m or a shorter run",
                 RC_LOC(m->inter_loc[i]), m->inter_name[i], tc, mv, k, ulp_t, m->tend, fields,
                 mv / (16.0 * ulp_t * ulp_t));
    }
    /* the stiffnesses of the law's states: the Stiff line of Iform 1 and 2
     * (F_h) and the stick spring of incremental friction (F_t) move their
     * forces by K times a displacement; at the position tolerance the
     * coordinates allow (64 roundings, the floor of 7.1) that is more than
     * the force scale when F_s / K is below 64 roundings: the integrator
     * cannot control such a state (the error it accepts is its whole force) */
    const rc_fric *fr = &m->inter_fr[i];
    const double kst = m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0 ? m->inter_stiff[i] : 0.0;
    const double kt = fr->kind != RC_FK_NONE && fr->form == RC_FF_INCREMENTAL && !fr->exact ? fr->kt : 0.0;
    for (int c = 0; c < 2; c++) {
        const double K = c ? kt : kst;
        if (!(K > 0) || !(f / K < 64.0 * ulp_x)) continue;
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s: %s K = %.3g N/m moves its force by %.3g N over the position tolerance the "
                      "coordinates allow (64 roundings, %.3g m at %.3g m from the origin), more than the contact's "
                      "force scale F_s = %.3g N: too stiff for double precision (its state would be rounding "
                      "noise); expected %s below %.3g N/m (F_s over 64 roundings), or coordinates nearer the origin",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i],
                      c ? "the stick spring of its friction (the incremental form's K_t: Stiff, or the load curve's "
                          "steepest slope)"
                        : "the Stiff line of its hysteresis (Iform 1 or 2),",
                      K, K * 64.0 * ulp_x, 64.0 * ulp_x, L, f, c ? "K_t (Stiff)" : "Stiff", f / (64.0 * ulp_x));
    }
    (void)v;
    return RC_OK;
}

/* Restitution of the linear contact minus the target, in the damping ratio. */
static double restitution_gap(double zeta, void *target)
{
    return rc_linear_restitution(zeta, NULL) - *(const double *)target;
}

/* The Visc of TYPE6 interface i that gives its asked restitution e_target:
 * for a linear load curve k P and the pair's effective mass m_eff along the
 * normal, the damping ratio zeta solving e(zeta) = e_target (e decreasing
 * from 1 at zeta = 0 to 0; closed form in report.c) by GSL's Brent
 * iteration, then Visc = 2 zeta sqrt(k m_eff). */
static rc_status derive_visc(rc_model *m, int i, rc_error *err)
{
    double target = m->inter_etarget[i], k = 0.0;
    const double mr = m->inter_mrest[i];
    if (!rc_type6_linear_slope(m, i, &k))
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field e_target: a restitution can be asked of a linear load curve only (a straight line "
                      "through the origin); for other curves give Visc (not supported yet)",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i]);
    if (!(isfinite(mr) && mr > 0))
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field e_target: the bodies of the pair cannot move along the contact normal (no effective mass), "
                      "so no restitution can be asked",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i]);
    double zeta = 0.0;
    if (target < 1) {
        double lo = 0.0, hi = 1.0;
        while (restitution_gap(hi, &target) > 0 && hi < 1e12) hi *= 10.0;
        gsl_function fn = {restitution_gap, &target};
        gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
        if (!s) return RC_SET(err, RC_ENOMEM, "out of memory");
        zeta = NAN;
        if (gsl_root_fsolver_set(s, &fn, lo, hi) == GSL_SUCCESS)
            for (int it = 0; it < 300; it++) {
                if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
                zeta = gsl_root_fsolver_root(s);
                if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-15) ==
                    GSL_SUCCESS)
                    break;
            }
        gsl_root_fsolver_free(s);
        if (!isfinite(zeta))
            return RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field e_target: no damping gives the restitution %g",
                          RC_LOC(m->inter_loc[i]), m->inter_name[i], target);
    }
    m->inter_visc[i] = 2.0 * zeta * sqrt(k * mr);
    return RC_OK;
}

/* The mass a unit impulse pair along the normal at the contact point drives
 * at t = 0 when the bodies also turn (free bodies: 1/m on the free
 * translations, J^-1 about the free axes; the body frame is the global one
 * at t = 0) [kg]; INFINITY when nothing moves. Joints are not included. */
double rc_point_mass(const rc_model *m, int i, const double *y, const rc_inter_report *r)
{
    double inv = 0.0;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int s = 0; s < 2; s++) {
        const int b = bs[s];
        if (b < 0 || m->body_yadr[b] < 0) continue;
        const double *x = y + m->body_yadr[b], *n = r->normal;
        const double rv[3] = {r->point[0] - x[0], r->point[1] - x[1], r->point[2] - x[2]};
        const double c[3] = {rv[1] * n[2] - rv[2] * n[1], rv[2] * n[0] - rv[0] * n[2], rv[0] * n[1] - rv[1] * n[0]};
        inv += free_part(m, b, n, 1) / m->body_mass[b]; /* held or driven: global or skew axes */
        /* rotation about the free axes: c_F . (J_FF)^-1 c_F (Gauss on <= 3 x
         * 3); an imposed rotation (all three components) to the end of the
         * run leaves none */
        int driven = 0;
        for (int j = 0; m->imp && j < m->imp->nr; j++)
            driven |= m->imp->rbody[j] == b && m->imp->rtstop[j] >= m->tend && m->imp->rsens[j] < 0;
        int ax[3], nf = 0;
        for (int k = 0; k < 3 && !driven; k++)
            if (!m->body_dofmask[6 * b + 3 + k]) ax[nf++] = k;
        double a[3][4];
        for (int p = 0; p < nf; p++) {
            for (int q = 0; q < nf; q++) a[p][q] = m->body_J[9 * b + 3 * ax[p] + ax[q]];
            a[p][nf] = c[ax[p]];
        }
        int ok = 1;
        for (int p = 0; p < nf && ok; p++) {
            ok = fabs(a[p][p]) > 0.0;
            for (int q = p + 1; q < nf && ok; q++) {
                const double f = a[q][p] / a[p][p];
                for (int k = p; k <= nf; k++) a[q][k] -= f * a[p][k];
            }
        }
        double u[3] = {0.0, 0.0, 0.0};
        for (int p = nf - 1; p >= 0 && ok; p--) {
            double v = a[p][nf];
            for (int q = p + 1; q < nf; q++) v -= a[p][q] * u[q];
            u[p] = v / a[p][p];
        }
        for (int p = 0; p < nf && ok; p++) inv += c[ax[p]] * u[p];
    }
    return inv > 0.0 ? 1.0 / inv : INFINITY;
}

/* Is body b on a joint? */
static int on_joint(const rc_model *m, int b)
{
    for (int j = 0; b >= 0 && m->jnt && j < m->jnt->n; j++)
        if (m->jnt->ba[j] == b || m->jnt->bb[j] == b) return 1;
    return 0;
}

int rc_inter_on_joint(const rc_model *m, int i) { return on_joint(m, m->inter_ba[i]) || on_joint(m, m->inter_bb[i]); }

/* The position floor of coordinates of magnitude X in the model [m]. */
static double coordinate_floor(double X)
{
    return RC_TOL_ULPS * DBL_EPSILON * X;
}

/* The largest coordinate of interface i's pair at t = 0 [m]: its bodies'
 * centres plus their sizes (size: rc_body_size), its fixed surfaces'
 * points. */
static double inter_extent(const rc_model *m, int i, const double *size)
{
    double X = 0.0;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int k = 0; k < 2; k++) {
        const int b = bs[k];
        if (b < 0) continue;
        const double *x = m->body_y0 + RC_NB * b;
        for (int c = 0; c < 3; c++) X = fmax(X, fabs(x[c]) + size[b]);
    }
    const int ss[2] = {m->inter_sa[i], m->inter_sb[i]};
    for (int k = 0; k < 2; k++) {
        if (ss[k] < 0 || m->surf_body[ss[k]] >= 0) continue;
        const double *p = m->surf_p + 3 * ss[k];
        for (int c = 0; c < 3; c++) X = fmax(X, fabs(p[c]));
    }
    return X;
}

rc_status rc_model_scales(rc_model *m, rc_error *err)
{
    const int n = m->ninter;
    double **arr[] = {&m->inter_pscale, &m->inter_fscale, &m->inter_kscale, &m->inter_vscale, &m->inter_mred,
                      &m->inter_mrest, &m->inter_pweight, &m->inter_pimpact, &m->inter_sband, &m->inter_perelax, &m->inter_hband};
    for (size_t k = 0; k < sizeof arr / sizeof arr[0]; k++) {
        *arr[k] = malloc(((size_t)n + 1) * sizeof(double));
        if (!*arr[k]) RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    double *y = malloc((size_t)m->ny * sizeof(double));
    double *size = malloc(((size_t)m->nbody + 1) * sizeof(double));
    if (!y || !size) {
        free(y);
        free(size);
        RC_RAISE(err, RC_ENOMEM, "out of memory");
    }
    rc_initial_state(m, y);
    body_sizes(m, size);
    /* the largest gravity over the run [m/s^2] */
    double gmax = 0.0;
    const double gf = m->grav_table >= 0 ? rc_table_max_abs(&m->table[m->grav_table]) : 1.0;
    for (int b = 0; b < m->nbody; b++) {
        const double *g = m->body_grav + 3 * b;
        double a = gf * sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (m->body_yadr[b] >= 0 && a > gmax) gmax = a;
    }
    /* the model's speed scale: the largest initial or imposed speed of a
     * body; without gravity and speeds, the speed the initial elastic energy
     * (contacts penetrating at t = 0, stretched couplings) gives the
     * lightest free body */
    double vmodel = 0.0, mlight = INFINITY;
    for (int b = 0; b < m->nbody; b++) {
        vmodel = fmax(vmodel, body_speed(m, b, size[b]) + imposed_speed(m, b, size[b]));
        if (m->body_yadr[b] >= 0) mlight = fmin(mlight, m->body_mass[b]);
    }
    double e0 = 0.0;
    for (int i = 0; i < n; i++) {
        rc_inter_report r0;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r0);
        if (r0.p_raw > 0) e0 += law_energy(m, i, r0.p_raw);
    }
    rc_data *d0 = rc_data_new(m);
    if (d0) {
        double e[RC_NENERGY];
        rc_energy(m, d0, 0.0, y, e);
        e0 += fabs(e[RC_E_CPL_ELASTIC]) + fabs(e[RC_E_CATENARY]);
        rc_data_free(d0);
    }
    /* the initial elastic energy speaks only when nothing else does (no
     * gravity, no speed): a rounding-level initial penetration must not */
    if (vmodel == 0 && gmax == 0 && e0 > 0 && isfinite(mlight)) vmodel = sqrt(2.0 * e0 / mlight);
    m->vscale = vmodel;
    double escale = 0.0;
    for (int i = 0; i < n; i++) {
        rc_progress(i, n);
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        rc_inter_report r;
        rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
        /* mobility along the contact normal: a body whose translations along
         * it are held (/BCS) or imposed does not take part */
        const double ma = normal_mass(m, ba, r.normal), mb = normal_mass(m, bb, r.normal);
        const double mred = isfinite(ma) && isfinite(mb) ? ma * mb / (ma + mb) : isfinite(ma) ? ma : mb;
        const double mmin = fmin(ma, mb);
        m->inter_mred[i] = mred;
        /* the mass for a derived restitution and the guidance: with the
         * rotations at a single contact point of free bodies (a segment
         * surface's several points balance their moments; joints change it
         * in ways this leaves out, docs/theory.md 12) */
        const double mp = rc_point_mass(m, i, y, &r);
        m->inter_mrest[i] = m->surf_kind[m->inter_sa[i]] != RC_SURF_SEG && m->surf_kind[m->inter_sb[i]] != RC_SURF_SEG &&
                                    !rc_pair_nodes(m->inter_pair[i]) &&
                                    !rc_inter_on_joint(m, i) && isfinite(mp) && isfinite(mred)
                                ? mp
                                : mred;
        m->inter_pscale[i] = m->inter_fscale[i] = m->inter_kscale[i] = m->inter_vscale[i] = NAN;
        m->inter_pweight[i] = m->inter_pimpact[i] = NAN;
        if (!isfinite(mred) && !(r.p_raw > 0)) continue; /* nothing moves along the normal */
        /* speed scale: initial and imposed speeds, fall over the gap; a
         * gap within the touch band (the rounding of the coordinates, the
         * model's and the deck's) is a touching start, no fall: a touching
         * start moved 1 km away begins 1e-13 m apart, and its fall over
         * that gap set p_s at 1e-2 p_F where the same scene at the origin,
         * exactly touching, had p_F (tolerances 100 times tighter) */
        double v = vmodel; /* momentum travels through chains of contacts */
        const double band = rc_touch_band(m, i, y, &r, RC_TOUCH_ULPS, 0.0, 1);
        if (r.p_raw < -band) v = fmax(v, sqrt(2.0 * gmax * -r.p_raw));
        const double pF = invert(m, i, 0, mmin * gmax);
        const double pE = invert(m, i, 1, 0.5 * mred * v * v);
        m->inter_pweight[i] = pF;
        m->inter_pimpact[i] = pE;
        double p = isfinite(pF) ? pF : NAN;
        if (isfinite(pE) && !(pE >= p)) p = pE;
        /* within RC_PSCALE_SPAN of the larger: a tiny initial penetration or
         * speed must not set absurd tolerances */
        if (isfinite(pE) && isfinite(pF)) p = fmax(p, RC_PSCALE_SPAN * pF);
        /* nothing moves along the normal or loads it, but the contact starts
         * penetrating (bodies held there): its initial penetration */
        if (!isfinite(p) && r.p_raw > 0) p = r.p_raw;
        if (!isfinite(p)) continue;
        double k = law_slope(m, i, p), f = law_force(m, i, p);
        if (!(k > 0)) k = f / p; /* a curve flat at p_s: its secant */
        if (!(k > 0) || !(f > 0)) continue;
        m->inter_pscale[i] = p;
        m->inter_fscale[i] = f;
        m->inter_kscale[i] = k;
        const double mv = isfinite(mred) ? mred : pair_mass(m, i); /* held along the normal */
        if (!isfinite(mv)) {
            m->inter_pscale[i] = m->inter_fscale[i] = m->inter_kscale[i] = NAN;
            continue;
        }
        m->inter_vscale[i] = p * sqrt(k / mv);
        escale = fmax(escale, law_energy(m, i, p));
        rc_status st = check_resolvable(m, i, mv, y, size, err);
        if (st) {
            free(y);
            free(size);
            return st;
        }
    }
    /* energy scale: the contacts' energies at their scales; without any,
     * the initial kinetic energy and the work of gravity over one body size
     * (a 1e12 kg belt's kinetic energy is not what the ledger exchanges) */
    double ebody = e0;
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double *yb = m->body_y0 + RC_NB * b, *J = m->body_J + 9 * b;
        double ek = 0.5 * m->body_mass[b] * (yb[7] * yb[7] + yb[8] * yb[8] + yb[9] * yb[9]);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) ek += 0.5 * yb[10 + r] * J[3 * r + c] * yb[10 + c];
        ebody = fmax(ebody, ek);
        ebody = fmax(ebody, m->body_mass[b] * gmax * size[b]);
    }
    m->escale = escale > 0 ? escale : ebody;
    /* pairs with several contact points (docs/theory.md 2.7): the share
     * band, RC_SHARE_BAND of the penetration scale (or of the bodies' sizes
     * without one), and the relaxation rate of P_e down to P,
     * RC_PE_RELAX times the contact's frequency omega_s = v_s / p_s */
    for (int i = 0; i < n; i++) {
        m->inter_sband[i] = m->inter_perelax[i] = m->inter_hband[i] = 0.0;
        if (!rc_pair_multi(m->inter_pair[i])) continue;
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        const double L = fmax(ba >= 0 ? size[ba] : 0.0, bb >= 0 ? size[bb] : 0.0);
        const double ps = m->inter_pscale[i], vs = m->inter_vscale[i];
        m->inter_sband[i] = isfinite(ps) && ps > 0 ? RC_SHARE_BAND * ps : RC_SHARE_BAND * 1e-3 * (L > 0 ? L : 1.0);
        if (isfinite(ps) && isfinite(vs) && ps > 0 && vs > 0) m->inter_perelax[i] = RC_PE_RELAX * vs / ps;
    }
    /* the end band of cylinders (docs/theory.md 2, cylinder - plane):
     * RC_CYL_END_BAND of the penetration scale of their interfaces with a
     * plane, a box or a segment surface (the smallest), within which the
     * contact point passes from one end (or the middle) to the other; 0
     * (the nearer end alone, or the middle) without a scale */
    for (int s = 0; s < m->nsurf; s++)
        if (m->surf_kind[s] == RC_SURF_CYL) m->surf_ext[RC_SURF_NEXT * s + 3] = 0.0;
    for (int i = 0; i < n; i++) {
        const rc_pair_kind pk = m->inter_pair[i];
        if (pk != RC_PAIR_CYL_PLANE && pk != RC_PAIR_CYL_BOX && pk != RC_PAIR_CYL_SEG) continue;
        double *ext = m->surf_ext + RC_SURF_NEXT * m->inter_sa[i];
        const double ps = m->inter_pscale[i];
        if (!(isfinite(ps) && ps > 0)) continue;
        const double eb = RC_CYL_END_BAND * ps;
        ext[3] = ext[3] > 0 ? fmin(ext[3], eb) : eb;
    }
    /* stick damping of the incremental friction: the stick spring critically
     * damped on the pair's reduced mass, so that a body stopped on a
     * sticking contact comes to rest instead of ringing */
    for (int i = 0; i < n; i++) {
        rc_fric *fr = &m->inter_fr[i];
        const double mr = pair_mass(m, i); /* a held body still carries the damper */
        fr->ct = fr->kind != RC_FK_NONE && fr->form == RC_FF_INCREMENTAL && fr->kt > 0 && isfinite(mr)
                     ? RC_STICK_ZETA * 2.0 * sqrt(fr->kt * mr)
                     : 0.0;
    }
    /* derived regularisation of the power law (blank Dreg, Vreg), Dreg at
     * least RC_DREG_RES roundings of the pair's coordinates and the
     * distance v_s covers in RC_DREG_RES of the smallest steps that move t
     * at the end time (100 eps t_end): a damping switched on over the
     * first Dreg (m3 = 0) must be crossed in steps the time can resolve
     * (a ball striking a wall of 4.7e16 N/m^1.5 with C = 4.9e5 N s/m: Dreg
     * 1.6e-15 m, crossed in 2e-15 s at t = 0.25 s, where one rounding of t
     * is 5.6e-17 s: CVODE stepped on the spot) */
    for (int i = 0; i < n; i++) {
        if (m->inter_law[i] != RC_LAW_POWER) continue;
        rc_power *pw = &m->inter_pw[i];
        const int ok = isfinite(m->inter_pscale[i]);
        if (pw->dreg == 0) {
            const double vs = isfinite(m->inter_vscale[i]) ? m->inter_vscale[i] : 0.0;
            const double res = RC_DREG_RES * fmax(coordinate_floor(inter_extent(m, i, size)),
                                                  vs * 100.0 * DBL_EPSILON * m->tend);
            pw->dreg = ok ? fmax(RC_DREG_FRAC * m->inter_pscale[i], res) : 1e-6;
        }
        if (pw->vreg == 0) pw->vreg = ok ? RC_DREG_FRAC * m->inter_vscale[i] : 1e-6;
    }
    /* a restitution asked (e_target): the damping that gives it, in closed
     * form for a linear TYPE6 load curve, else by the single-contact ODE
     * (restitution.c; after the regularisation, which it includes) */
    for (int i = 0; i < n; i++) {
        if (!(m->inter_etarget[i] > 0)) continue;
        double k;
        const int closed_form = m->inter_law[i] == RC_LAW_TYPE6 && m->inter_fct_df[i] < 0 && rc_type6_linear_slope(m, i, &k);
        rc_status st = closed_form ? derive_visc(m, i, err) : rc_restitution_derive(m, i, err);
        if (st) {
            free(y);
            free(size);
            return st;
        }
    }
    free(y);
    free(size);
    return RC_OK;
}

/* The largest velocity sensitivity of interface i's forces at its scales
 * [N s/m]: normal damping Visc, the viscous friction form's C = sqrt(2 VISF
 * k_s m_red), the stick damper; a velocity error dv moves a force by c dv,
 * so the velocity tolerance is at most rtol F_s / c. */
static double inter_damping(const rc_model *m, int i)
{
    double c = m->inter_law[i] == RC_LAW_TYPE6 ? m->inter_visc[i] : 0.0;
    const rc_fric *fr = &m->inter_fr[i];
    if (fr->kind == RC_FK_CARD && fr->form == RC_FF_VISCOUS)
        for (int k = 0; k < 1 + fr->ortho; k++)
            c = fmax(c, sqrt(2.0 * fr->set[k][RC_FS_VISF] * m->inter_kscale[i] * fr->mred));
    c = fmax(c, fr->ct);
    return c > 0 ? c : 1e-300;
}

rc_status rc_model_tolerances(rc_model *m, rc_error *err)
{
    const int ny = m->ny;
    m->atol = malloc((size_t)ny * sizeof(double));
    m->ewt_rel = malloc((size_t)ny + 1);
    if (!m->atol || !m->ewt_rel) RC_RAISE(err, RC_ENOMEM, "out of memory");
    memset(m->ewt_rel, 1, (size_t)ny);
    const int au = m->tol_auto;
    const double rt = m->rtol;
    /* bodies: the smallest scales of their contacts (one pass over the
     * interfaces) */
    const size_t nb = (size_t)m->nbody + 1;
    /* scratch: per body its size, smallest scales and floors (below), per
     * interface its position floor; one block */
    double *scratch = malloc((5 * nb + (size_t)m->ninter + 1) * sizeof(double));
    if (!scratch) RC_RAISE(err, RC_ENOMEM, "out of memory");
    double *size = scratch, *bps = size + nb, *bvs = bps + nb, *pflb = bvs + nb, *vflb = pflb + nb,
           *pfl = vflb + nb;
    body_sizes(m, size);
    /* the resolution of the coordinates: a penetration is the difference of
     * coordinates, rounded at DBL_EPSILON times their magnitude in the
     * model, so that no tolerance below RC_TOL_ULPS of it can be met. The
     * deck's own rounding (its positions 1 km from its origin are given to
     * 1e-13 m) is an error of the initial state, not a bound on the
     * integration's: the model computes about its own origin (compile.c),
     * and a floor from the deck's coordinates would control the error of
     * every body far from the deck's origin more loosely than the same
     * scene's at the origin (its motion then departs from it by far more
     * than the rounding of its start explains); the deck's rounding enters
     * the touch bands only (bounds.c rc_touch_band). For each
     * contact, the largest coordinate of its pair at t = 0 (bodies'
     * centres plus sizes, fixed surfaces' points) gives the floor pf_i of its position
     * tolerances; the body's floor is the largest of its contacts', and its
     * velocity floor is pf times the contact's frequency v_s / p_s. */
    m->tol_floored = 0;
    m->tol_floor_pos = 0.0;
    for (int b = 0; b < m->nbody; b++) bps[b] = bvs[b] = INFINITY;
    for (int b = 0; b < m->nbody; b++) pflb[b] = vflb[b] = 0.0;
    for (int i = 0; i < m->ninter; i++) {
        pfl[i] = 0.0;
        if (!isfinite(m->inter_pscale[i])) continue;
        const double vi = fmin(m->inter_vscale[i], m->inter_fscale[i] / inter_damping(m, i));
        const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
        pfl[i] = coordinate_floor(inter_extent(m, i, size));
        const double om = m->inter_vscale[i] / m->inter_pscale[i];
        for (int k = 0; k < 2; k++) {
            if (bs[k] < 0) continue;
            bps[bs[k]] = fmin(bps[bs[k]], m->inter_pscale[i]);
            bvs[bs[k]] = fmin(bvs[bs[k]], vi);
            pflb[bs[k]] = fmax(pflb[bs[k]], pfl[i]);
            if (isfinite(om)) vflb[bs[k]] = fmax(vflb[bs[k]], om * pfl[i]);
        }
    }
    /* every body: at least the rounding of its own coordinates (a body on
     * joints or couplings only) */
    for (int b = 0; b < m->nbody; b++) {
        const double *x = m->body_y0 + RC_NB * b;
        double X = 0.0;
        for (int c = 0; c < 3; c++) X = fmax(X, fabs(x[c]) + size[b]);
        pflb[b] = fmax(pflb[b], coordinate_floor(X));
    }
    /* joints: a constraint row is a difference of the two anchor points
     * (p = x + R s, or the ground's anchor), rounded at the larger of their
     * model coordinates; the projection displacement nu of the row takes
     * its tolerance from its bodies' positions (joints.c), and a tolerance
     * below that rounding leaves Newton's corrections of nu as noise of
     * the tolerance's own size, which IDA's convergence test reads as
     * divergence (a pendulum whose body's contact gives it a tolerance of
     * 2.8e-15 m, its pivot 0.53 m from the model's origin: every Newton
     * iteration failed from t = 9e-9 s and the step fell to 1e-25 s). */
    for (int j = 0; m->jnt && j < m->jnt->n; j++) {
        const rc_joints *J = m->jnt;
        const int bs[2] = {J->ba[j], J->bb[j]};
        double X = 0.0;
        for (int e = 0; e < 2; e++) {
            const double *s = (e ? J->sb : J->sa) + 3 * j;
            const double arm = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
            if (bs[e] < 0) {
                for (int c = 0; c < 3; c++) X = fmax(X, fabs(s[c]));
                continue;
            }
            const double *x = m->body_y0 + RC_NB * bs[e];
            for (int c = 0; c < 3; c++) X = fmax(X, fabs(x[c]) + arm);
        }
        for (int e = 0; e < 2; e++)
            if (bs[e] >= 0) pflb[bs[e]] = fmax(pflb[bs[e]], coordinate_floor(X));
    }
    /* energies: 0.1 rtol of the model's energy scale, at least the work of
     * the contact forces over the rounding of the penetrations (the
     * accounting states integrate F v, whose rounding is F_s pf) */
    if (au & RC_TOL_AUTO_ENERGY) {
        m->atol_energy = m->escale > 0 ? RC_TOL_EFRAC * rt * m->escale : RC_TOL_FALLBACK_ENERGY;
        double ef = 0.0;
        for (int i = 0; i < m->ninter; i++)
            if (isfinite(m->inter_fscale[i])) ef += m->inter_fscale[i] * pfl[i];
        m->atol_energy = fmax(m->atol_energy, ef);
    }
    for (int k = 0; k < ny; k++) m->atol[k] = m->atol_energy; /* accounting states unless set below */
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double ps = bps[b], vs = bvs[b];
        const int scaled = isfinite(ps);
        const double L = size[b] > 0 ? size[b] : 1.0;
        /* no contact scale: the body's size and the model's speed scale,
         * with the relative part (couplings, free flight) */
        const double vb = m->vscale > 0 ? m->vscale : RC_TOL_FALLBACK_SPEED;
        double *a = m->atol + m->body_yadr[b];
        char *rel = m->ewt_rel + m->body_yadr[b];
        for (int k = 0; k < 3; k++) {
            if (au & RC_TOL_AUTO_POS) {
                const double d = scaled ? rt * ps : rt * RC_TOL_FALLBACK_LFRAC * L;
                if (k == 0 && pflb[b] > d) {
                    m->tol_floored++;
                    m->tol_floor_pos = fmax(m->tol_floor_pos, pflb[b]);
                }
                a[k] = fmax(d, pflb[b]);
                rel[k] = 0;
            } else {
                /* given (/SOLVER Atol_pos): absolute as well. rtol |x|
                 * weighs a position by its distance from the origin, which
                 * no contact force depends on: 4e-9 m at rtol 1e-8 for a
                 * pendulum's ball 0.4 m out, against a wall whose
                 * penetration scale is 3e-13 m; it took 368 310 steps,
                 * every one failing the error test, where the same value
                 * derived took 3 622 (absolute: 3 316) */
                a[k] = m->atol_pos;
                rel[k] = 0;
            }
        }
        for (int k = 3; k < 7; k++) {
            if (au & RC_TOL_AUTO_QUAT) {
                a[k] = fmax(scaled ? rt * ps / L : rt * RC_TOL_FALLBACK_LFRAC, pflb[b] / L);
                rel[k] = 0;
            } else {
                a[k] = m->atol_quat;
            }
        }
        for (int k = 7; k < 10; k++) {
            a[k] = (au & RC_TOL_AUTO_VEL)
                       ? fmax(scaled ? rt * vs : rt * RC_TOL_FALLBACK_LFRAC * vb, vflb[b])
                       : m->atol_vel;
            /* velocities absolutely as well: what sets the forces is the
             * relative velocity at the contacts (a block sticking on a belt
             * at 0.05 m/s creeps at um/s), not |v| */
            if (au & RC_TOL_AUTO_VEL) rel[k] = 0;
        }
        for (int k = 10; k < 13; k++)
            a[k] = (au & RC_TOL_AUTO_OMEGA)
                       ? fmax(scaled ? rt * vs / L : rt * RC_TOL_FALLBACK_LFRAC * vb / L, vflb[b] / L)
                       : m->atol_omega;
    }
    /* interface states: forces at rtol of the force scale (or the
     * stiffness times the position tolerance when given), lengths at the
     * position tolerance */
    for (int i = 0; i < m->ninter; i++) {
        const int scaled = isfinite(m->inter_pscale[i]) && (au & RC_TOL_AUTO_POS);
        /* an interface without a scale: rtol RC_TOL_FALLBACK_LFRAC of its
         * bodies' sizes */
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        double Li = (ba >= 0 ? size[ba] : 0.0) + (bb >= 0 ? size[bb] : 0.0);
        if (!(Li > 0)) Li = 1.0;
        const double apos = scaled                      ? fmax(rt * m->inter_pscale[i], pfl[i])
                            : (au & RC_TOL_AUTO_POS) ? rt * RC_TOL_FALLBACK_LFRAC * Li
                                                     : m->atol_pos;
        /* forces: rtol F_s, at least the force of the coordinates' rounding;
         * F_h at that of the steeper of the law's stiffness scale and its
         * Stiff line, which it follows on unloading and reloading: on the
         * line F_h moves by Stiff per metre of P, which the coordinates
         * give only to pf (a ball pressed against a wall with a Stiff line
         * of 3.9e14 N/m, its curve's k_s 6.5e11, F_h held to 1.2e-3 N where
         * the rounding of P moves it by 0.75 N: steps of 2e-8 s at every
         * reversal of its load, CV_TOO_MUCH_WORK) */
        const double ffl = scaled ? m->inter_kscale[i] * pfl[i] : 0.0;
        const double ffh = scaled ? fmax(m->inter_kscale[i], m->inter_stiff[i]) * pfl[i] : 0.0;
        double *a = m->atol + m->inter_eadr[i];
        if (m->inter_hidx[i] >= 0) a[m->inter_hidx[i]] = scaled ? fmax(rt * m->inter_fscale[i], ffh) : m->inter_stiff[i] * apos;
        if (m->inter_oidx[i] >= 0) a[m->inter_oidx[i]] = apos;
        if (m->inter_peidx[i] >= 0) a[m->inter_peidx[i]] = apos;
        const rc_fric *fr = &m->inter_fr[i];
        /* the friction states likewise at the rounding force of the stick
         * spring K_t they follow while sticking (TYPE6: K_t = Stiff) */
        const double fft = scaled && isfinite(fr->kt) ? fmax(ffl, fr->kt * pfl[i]) : ffl;
        double af = scaled ? fmax(rt * m->inter_fscale[i], fft) : fr->kt * apos;
        /* a given position tolerance and no stick stiffness to carry it to
         * a force (the power law's K_t, 0 at P = 0): rtol of the force
         * scale, as where it is derived (a box on a power-law incline with
         * /SOLVER Atol_pos given was refused: its friction states' tolerance
         * was 0) */
        if (!(af > 0) || !isfinite(af)) af = isfinite(m->inter_fscale[i]) ? rt * m->inter_fscale[i] : af;
        for (int k = 0; k < 3; k++) {
            if (fr->tidx >= 0) a[fr->tidx + k] = af;
            if (fr->fidx >= 0) a[fr->fidx + k] = af;
        }
        /* friction per contact point: each point's F_t as the interface's */
        const int npt = m->inter_npt[i];
        for (int k = 0; k < m->inter_pst[i] * npt; k++) a[m->inter_ns[i] + k] = af;
        /* slip-test band: the force tolerance of F_t, and at least RC_SLIP_BAND
         * of the contact's force scale (the relative band of the limit,
         * carried down to small loads: a load ramped from zero, carried by the
         * dampers at first, must not slip on differences of 1e-8 F_s) */
        const int tt = fr->tidx >= 0 ? fr->tidx : npt > 0 ? m->inter_ns[i] : -1; /* an F_t state */
        double fb = tt >= 0 ? a[tt] : 0.0;
        if (tt >= 0 && isfinite(m->inter_fscale[i])) fb = fmax(fb, RC_SLIP_BAND * m->inter_fscale[i]);
        m->inter_fr[i].fband = fb;
        /* the Stiff line's roots (F_L - F_h, F_h - F_U): F_h is integrated
         * to its tolerance, the curves follow P to the stiffness times the
         * position tolerance; a line that has just left a curve stays
         * within that of it without crossing it */
        if (m->inter_hidx[i] >= 0) {
            double ap = 0.0;
            for (int k = 0; k < 2; k++) {
                const int b = k ? bb : ba;
                if (b >= 0 && m->body_yadr[b] >= 0) ap = fmax(ap, m->atol[m->body_yadr[b]]);
            }
            m->inter_hband[i] = a[m->inter_hidx[i]] + m->inter_stiff[i] * ap;
        }
    }
    free(scratch);
    rc_cpl_atol(m);
    /* a tolerance derived from scales that under- or overflow (values near
     * the limits of the doubles, e.g. a denormal load curve slope or gap):
     * an input error at the card owning the state */
    for (int k = 0; k < ny; k++) {
        if (m->atol[k] > 0) continue;
        for (int b = 0; b < m->nbody; b++)
            if (m->body_yadr[b] >= 0 && k >= m->body_yadr[b] && k < m->body_yadr[b] + RC_NB)
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card /RBODY/%d: the absolute tolerance derived for its state %d is %g: the scales of its "
                         "contacts (docs/theory.md 7.1) leave the range of the doubles; expected values of ordinary "
                         "magnitude",
                         RC_LOC(m->body_loc[b]), m->body_id[b], k - m->body_yadr[b], m->atol[k]);
        for (int i = 0; i < m->ninter; i++) /* its own states, then its contact points' */
            if (k >= m->inter_eadr[i] && k < m->inter_eadr[i] + m->inter_ns[i] + m->inter_pst[i] * m->inter_npt[i])
                RC_RAISE(err, RC_EINPUT,
                         RC_LOCFMT "card %s: the absolute tolerance derived for its state %d is %g: its scales "
                         "(docs/theory.md 7.1) leave the range of the doubles; expected values of ordinary magnitude",
                         RC_LOC(m->inter_loc[i]), m->inter_name[i], k - m->inter_eadr[i], m->atol[k]);
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "the absolute tolerance derived for state %d (energy accounting) is %g: the energy scale of "
                 "the model (docs/theory.md 7.1) leaves the range of the doubles; expected values of ordinary "
                 "magnitude, or /SOLVER Atol_energy given",
                 RC_LOC(m->end_loc), k, m->atol[k]);
    }
    /* all relative: plain per-component tolerances */
    int any = 0;
    for (int k = 0; k < ny; k++) any |= !m->ewt_rel[k];
    if (!any) {
        free(m->ewt_rel);
        m->ewt_rel = NULL;
    }
    return RC_OK;
}

void rc_model_tol_floor_note(const rc_model *m, char *buf, size_t n)
{
    if (n == 0) return;
    buf[0] = '\0';
    if (m->tol_floored <= 0) return;
    snprintf(buf, n,
             "rtol %.3g times the penetration scale is below what the coordinates resolve for %d bod%s: their "
             "position tolerance is raised to %.3g m (%d roundings of the contacts' coordinates about the model's "
             "origin; docs/theory.md 7.1): the results cannot be as accurate as rtol asks (a smaller rtol no longer "
             "tightens that tolerance); a scene spread less widely about its centre, or smaller bodies, resolve "
             "more",
             m->rtol, m->tol_floored, m->tol_floored == 1 ? "y" : "ies", m->tol_floor_pos, (int)RC_TOL_ULPS);
}
