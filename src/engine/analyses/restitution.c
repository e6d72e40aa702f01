/*
 * Restitution of a nonlinear contact law as implemented, and the damping
 * that gives an asked one (docs/theory.md, "Restitution asked").
 *
 * The single-contact problem along the normal: the penetration p of two
 * bodies of effective mass m_eff meeting at speed v0, no other load,
 *   m_eff p'' = -F(p, p'),  p(0) = 0, p'(0) = v0,
 * with F the interface's normal law exactly as the kernels evaluate it
 * (power_law.inc, kernels.inc type6_law): the regularised powers of the
 * power law, the rebound damping factor while p decreases (the engine's
 * rdf_rebound event), the force acting only while positive (contact_open
 * when it reaches zero, contact_close when it is positive again). The
 * restitution is e = -p'/v0 when p returns to zero.
 *
 * Integrated with GSL's gsl_odeiv2 (Runge-Kutta Prince-Dormand 8(9),
 * tolerances 1e-13 in units of the undamped maximum penetration P and of
 * v0); each mode change is located by GSL's Brent iteration on the time
 * within the step, the state there integrated again from the step's start.
 * The damping asked is then a Brent root of e(damping) = e_target.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/analyses/restitution.h"
#include "model/power.h"
#include "engine/assembly/assembly.h"

#define RC_RE_ID(x) (x)
RC_POWREG_DEFINE(double, RC_RE_ID, _r)

/* ODE tolerances (scaled units) and limits; pi. */
#define RC_REST_TOL 1e-13
#define RC_REST_MAXSTEPS 2000000
#define RC_REST_MAXEVENTS 1000

typedef struct {
    const rc_model *m;
    int i;
    double damp;   /* C or Visc */
    double meff;   /* [kg] */
    double P, V;   /* length and speed units [m] [m/s] */
    int closed;    /* the force acts */
    int unload;    /* p decreasing: RDF */
} rest_ctx;

/* Normal force of interface i at penetration p, rate v, damping d [N]
 * (unclipped), as the kernels compute it in the contact zone. */
static double law_force(const rc_model *m, int i, double d, double p, double v, int unload)
{
    if (m->inter_law[i] == RC_LAW_POWER) {
        const rc_power *pw = &m->inter_pw[i];
        double fk, s;
        if (pw->stiff) rc_spline_eval(pw->stiff, p, &fk, &s);
        else fk = pw->k * rc_powreg_r(p, pw->m1, pw->dreg);
        const double fc = d * rc_powreg_r(v, pw->m2, pw->vreg), ind = rc_powreg_r(p, pw->m3, pw->dreg);
        return fk + fc * ind * (unload ? pw->rdf : 1.0);
    }
    double f, s;
    rc_table_eval(&m->table[m->inter_fct_ld[i]], p / m->inter_ascalex[i], &f, &s);
    const double fel = m->inter_fscaleld[i] * f;
    double fdf = 1.0;
    if (m->inter_fct_df[i] >= 0) rc_table_eval(&m->table[m->inter_fct_df[i]], fel / m->inter_ascalef[i], &fdf, &s);
    return fel + fdf * d * v;
}

/* Elastic energy stored at penetration p: integral_0^p of the load force [J]. */
static double law_energy(const rc_model *m, int i, double p)
{
    if (m->inter_law[i] == RC_LAW_POWER) return rc_power_stored(m, i, p);
    const double ax = m->inter_ascalex[i];
    return m->inter_fscaleld[i] * ax * rc_table_integral(&m->table[m->inter_fct_ld[i]], 0.0, p / ax);
}

int rc_restitution_supported(const rc_model *m, int i, const char **why)
{
    const char *w = NULL;
    if (m->inter_law[i] == RC_LAW_POWER) {
        if (m->inter_pw[i].damp) w = "a damping spline (fct_damp)";
    } else if (m->inter_iform[i] != 0) {
        w = "hysteresis (Iform != 0)";
    } else if (m->inter_fct_dv[i] >= 0) {
        w = "a damping curve (fct_IDdv)";
    } else if (m->inter_fct_ld[i] < 0) {
        w = "no load curve";
    }
    if (why) *why = w;
    return w == NULL;
}

static int ode_rhs(double s, const double *y, double *dy, void *par)
{
    (void)s;
    const rest_ctx *c = par;
    dy[0] = y[1];
    dy[1] = c->closed ? -c->P / (c->meff * c->V * c->V) *
                            law_force(c->m, c->i, c->damp, c->P * y[0], c->V * y[1], c->unload)
                      : 0.0;
    return isfinite(dy[1]) ? GSL_SUCCESS : GSL_EBADFUNC;
}

/* Event functions of the current mode; an event happens when one goes from
 * > 0 to <= 0: 0 the rate reverses (branch), 1 the force changes sign
 * (clipping), 2 the penetration returns to zero (the end). */
#define RC_REST_NEV 3
static void events(const rest_ctx *c, const double *y, double *g)
{
    const double f = law_force(c->m, c->i, c->damp, c->P * y[0], c->V * y[1], c->unload) / (c->meff * c->V * c->V / c->P);
    g[0] = c->unload ? -y[1] : y[1];
    g[1] = c->closed ? f : -f;
    g[2] = y[0];
}

/* Integrate from (s0, y0) to s1 into y (fresh driver, tight tolerances). */
static int integrate_to(rest_ctx *c, double s0, const double *y0, double s1, double *y)
{
    gsl_odeiv2_system sys = {ode_rhs, NULL, 2, c};
    memcpy(y, y0, 2 * sizeof *y);
    if (s1 <= s0) return 0;
    gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 0.25 * (s1 - s0), RC_REST_TOL,
                                                         RC_REST_TOL);
    if (!d) return -1;
    double s = s0;
    const int st = gsl_odeiv2_driver_apply(d, &s, s1, y);
    gsl_odeiv2_driver_free(d);
    return st == GSL_SUCCESS ? 0 : -1;
}

typedef struct {
    rest_ctx *c;
    double s0;
    const double *y0;
    int k;
} loc_ctx;

static double loc_fn(double s, void *p)
{
    loc_ctx *l = p;
    double y[2], g[RC_REST_NEV];
    if (integrate_to(l->c, l->s0, l->y0, s, y)) return NAN;
    events(l->c, y, g);
    return g[l->k];
}

/* The time of event k in (s0, s1], where g_k > 0 at s0 and <= 0 at s1: the
 * upper end of the Brent bracket (the event has happened there). */
static double locate(rest_ctx *c, double s0, const double *y0, double s1, int k)
{
    loc_ctx l = {c, s0, y0, k};
    gsl_function fn = {loc_fn, &l};
    gsl_root_fsolver *rs = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!rs) return NAN;
    double hi = s1;
    if (gsl_root_fsolver_set(rs, &fn, s0, s1) == GSL_SUCCESS) {
        for (int it = 0; it < 200; it++) {
            if (gsl_root_fsolver_iterate(rs) != GSL_SUCCESS) break;
            const double a = gsl_root_fsolver_x_lower(rs), b = gsl_root_fsolver_x_upper(rs);
            /* keep the end where the event has happened */
            hi = loc_fn(b, &l) <= 0 ? b : hi;
            if (gsl_root_test_interval(a, b, 1e-300, 4e-16) == GSL_SUCCESS) break;
        }
    }
    gsl_root_fsolver_free(rs);
    return hi;
}

double rc_restitution_solve(const rc_model *m, int i, double meff, double v0, double damp, double *tc)
{
    if (tc) *tc = NAN;
    if (!rc_restitution_supported(m, i, NULL) || !(meff > 0) || !isfinite(meff) || !(v0 > 0) || !(damp >= 0))
        return NAN;
    /* the length unit: the undamped maximum penetration, E(P) = m v0^2 / 2 */
    const double ekin = 0.5 * meff * v0 * v0;
    double lo = 0.0, hi = 1e-12;
    while (law_energy(m, i, hi) < ekin) {
        lo = hi;
        hi *= 2.0;
        if (hi > 1e6) return NAN;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
        const double mid = 0.5 * (lo + hi);
        if (law_energy(m, i, mid) < ekin) lo = mid;
        else hi = mid;
    }
    rest_ctx c = {m, i, damp, meff, hi, v0, 1, 0};
    gsl_odeiv2_system sys = {ode_rhs, NULL, 2, &c};
    gsl_odeiv2_step *stp = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    gsl_odeiv2_control *ctl = gsl_odeiv2_control_y_new(RC_REST_TOL, RC_REST_TOL);
    gsl_odeiv2_evolve *ev = gsl_odeiv2_evolve_alloc(2);
    double e = NAN;
    if (!stp || !ctl || !ev) goto done;
    double s = 0.0, h = 1e-3, y[2] = {0.0, 1.0};
    int nev = 0;
    double s_open = 0.0; /* when the force last stopped acting */
    for (long n = 0; n < RC_REST_MAXSTEPS; n++) {
        const double s0 = s, y0[2] = {y[0], y[1]};
        double g0[RC_REST_NEV], g1[RC_REST_NEV];
        events(&c, y0, g0);
        if (gsl_odeiv2_evolve_apply(ev, ctl, stp, &sys, &s, s + 1e6, &h, y) != GSL_SUCCESS)
            goto done;
        events(&c, y, g1);
        /* the first event of the step */
        int kfirst = -1;
        double sfirst = s;
        for (int k = 0; k < RC_REST_NEV; k++) {
            if (!(g0[k] > 0 && g1[k] <= 0)) continue;
            if (k == 0 && !(m->inter_law[i] == RC_LAW_POWER && c.closed)) continue; /* no branch to change */
            const double sk = locate(&c, s0, y0, s, k);
            if (!isfinite(sk)) goto done;
            if (kfirst < 0 || sk < sfirst) {
                kfirst = k;
                sfirst = sk;
            }
        }
        if (kfirst < 0) continue;
        if (integrate_to(&c, s0, y0, sfirst, y)) goto done;
        s = sfirst;
        gsl_odeiv2_evolve_reset(ev);
        if (kfirst == 2 || y[0] <= 0) { /* back at p = 0 (with the force, when undamped) */
            e = -y[1];
            if (tc) *tc = (c.closed ? s : s_open) * c.P / c.V;
            break;
        }
        if (kfirst == 0) c.unload = !c.unload;
        if (kfirst == 1) c.closed = !c.closed;
        if (kfirst == 1 && !c.closed) s_open = s;
        if (++nev > RC_REST_MAXEVENTS) goto done;
    }
done:
    if (ev) gsl_odeiv2_evolve_free(ev);
    if (ctl) gsl_odeiv2_control_free(ctl);
    if (stp) gsl_odeiv2_step_free(stp);
    return e;
}

double rc_restitution_speed(const rc_model *m, int i, int *given)
{
    if (given) *given = m->inter_vimp[i] > 0;
    if (m->inter_vimp[i] > 0) return m->inter_vimp[i];
    double *y = malloc(((size_t)m->ny + 1) * sizeof(double));
    if (!y) return 0.0;
    rc_initial_state(m, y);
    rc_inter_report r;
    rc_inter_report_eval(m, i, RC_MODE_OPEN, RC_BR_LOAD, 0, 0, 0.0, y, &r);
    free(y);
    /* relative gravity along the approach: p'' = -(g_b - g_a) . n */
    double a = 0.0;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int k = 0; k < 2; k++) {
        if (bs[k] < 0 || m->body_yadr[bs[k]] < 0) continue;
        double g[3];
        rc_gravity(m, bs[k], 0.0, g);
        const double gn = g[0] * r.normal[0] + g[1] * r.normal[1] + g[2] * r.normal[2];
        a += k == 0 ? gn : -gn;
    }
    const double gap = r.p_raw < 0 ? -r.p_raw : 0.0;
    if (a > 0) return sqrt(r.vn_raw * r.vn_raw + 2.0 * a * gap);
    return r.vn_raw > 0 ? r.vn_raw : 0.0;
}

typedef struct {
    const rc_model *m;
    int i;
    double meff, v0, target;
} der_ctx;

static double der_fn(double d, void *p)
{
    const der_ctx *c = p;
    return rc_restitution_solve(c->m, c->i, c->meff, c->v0, d, NULL) - c->target;
}

rc_status rc_restitution_derive(rc_model *m, int i, rc_error *err)
{
    const int pw = m->inter_law[i] == RC_LAW_POWER;
    const char *field = pw ? "e_target (line 6)" : "e_target", *dname = pw ? "C" : "Visc", *why = NULL;
    const double target = m->inter_etarget[i], meff = m->inter_mrest[i];
    if (!rc_restitution_supported(m, i, &why))
        return RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: a restitution cannot be asked of a law with %s",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i], field, why);
    if (!(isfinite(meff) && meff > 0))
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field %s: the bodies of the pair cannot move along the contact normal (no "
                      "effective mass), so no restitution can be asked",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i], field);
    int given = 0;
    const double v0 = rc_restitution_speed(m, i, &given);
    if (!(v0 > 0))
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field V_imp: the restitution of this law depends on the impact speed and none "
                      "can be derived (the surfaces do not approach at t = 0 and no gravity closes the gap); expected "
                      "the impact speed V_imp > 0 [m/s]",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i]);
    der_ctx c = {m, i, meff, v0, target};
    const double e0 = der_fn(0.0, &c) + target;
    if (!isfinite(e0))
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field %s: the single-contact problem at %.6g m/s cannot be solved for this "
                      "law (the law does not store the impact energy, or the integration failed)",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i], field, v0);
    double d = 0.0;
    if (target < e0 && !(target == 1.0)) {
        /* bracket: up from the damping whose force at (P, v0) is 1 % of the
         * elastic force there */
        double p = 0.0, fk0 = 0.0;
        {
            /* P: the scaled problem's length unit, from the undamped law */
            double lo = 0.0, hi = 1e-12;
            const double ek = 0.5 * meff * v0 * v0;
            while (law_energy(m, i, hi) < ek && hi < 1e6) { lo = hi; hi *= 2.0; }
            (void)lo;
            p = hi;
            fk0 = law_force(m, i, 0.0, p, 0.0, 0);
        }
        const double unit = law_force(m, i, 1.0, p, v0, 0) - fk0; /* damping force of damping 1 at (P, v0) */
        double lo = 0.0, hi = unit > 0 ? 1e-2 * fk0 / unit : 1.0;
        int it = 0;
        double fhi;
        while ((fhi = der_fn(hi, &c)) > 0 && it++ < 200) {
            lo = hi;
            hi *= 4.0;
        }
        if (!(fhi <= 0))
            return RC_SET(err, RC_EINPUT,
                          RC_LOCFMT "card %s, field %s: no damping %s up to %.6g gives the restitution %g at %.6g m/s "
                          "(the law gives %.9g there)",
                          RC_LOC(m->inter_loc[i]), m->inter_name[i], field, dname, hi, target, v0, fhi + target);
        gsl_function fn = {der_fn, &c};
        gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
        if (!s) return RC_SET(err, RC_ENOMEM, "out of memory");
        d = NAN;
        if (gsl_root_fsolver_set(s, &fn, lo, hi) == GSL_SUCCESS)
            for (it = 0; it < 300; it++) {
                if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
                d = gsl_root_fsolver_root(s);
                if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-13) ==
                    GSL_SUCCESS)
                    break;
            }
        gsl_root_fsolver_free(s);
        if (!isfinite(d))
            return RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: no damping %s gives the restitution %g at %.6g m/s",
                          RC_LOC(m->inter_loc[i]), m->inter_name[i], field, dname, target, v0);
    } else if (target > e0 + 1e-9) {
        return RC_SET(err, RC_EINPUT,
                      RC_LOCFMT "card %s, field %s: expected a restitution of at most %.9g, the law's without damping "
                      "at %.6g m/s, got %g",
                      RC_LOC(m->inter_loc[i]), m->inter_name[i], field, e0, v0, target);
    }
    if (pw) m->inter_pw[i].c = d;
    else m->inter_visc[i] = d;
    return RC_OK;
}

/* Restitution of a linear spring-dashpot contact that cannot pull (the
 * force k x + c x' clipped at zero) at damping ratio zeta >= 0, and the
 * contact time in units of 1/omega (*tau = omega t_c). In units of v0/omega
 * and 1/omega the free response x(tau) of x'' + 2 zeta x' + x = 0, x(0) = 0,
 * x'(0) = 1 leaves the contact when x + 2 zeta x' = 0; e = -x'(tau) there:
 *   zeta < 1: x = e^(-zeta tau) sin(s tau)/s, s = sqrt(1 - zeta^2), and
 *             s tau = pi - atan2(2 zeta s, 1 - 2 zeta^2);
 *   zeta = 1: x = tau e^(-tau), tau = 2, e = e^(-2);
 *   zeta > 1: x = (e^(a tau) - e^(b tau))/(a - b), a, b = -zeta +- q,
 *             q = sqrt(zeta^2 - 1), and e^((a - b) tau) = (1 + 2 zeta b)/(1 + 2 zeta a).
 * NaN for zeta < 0 or not finite. */
double rc_linear_restitution(double zeta, double *tau_out)
{
    double tau = NAN, e = NAN;
    if (zeta >= 0 && zeta < 1) {
        const double s = sqrt(1.0 - zeta * zeta);
        const double theta = RC_PI - atan2(2.0 * zeta * s, 1.0 - 2.0 * zeta * zeta);
        tau = theta / s;
        e = -exp(-zeta * theta / s) * (cos(theta) - zeta / s * sin(theta));
    } else if (zeta == 1) {
        tau = 2.0;
        e = exp(-2.0);
    } else if (zeta > 1 && isfinite(zeta)) {
        const double q = sqrt((zeta - 1.0) * (zeta + 1.0)), a = -zeta + q, b = -zeta - q;
        /* (1 + 2 zeta a)(1 + 2 zeta b) = 1, so the ratio is (1 + 2 zeta b)^2
         * and tau = ln(2 zeta^2 + 2 zeta q - 1) / q (no cancellation) */
        tau = log(2.0 * zeta * zeta + 2.0 * zeta * q - 1.0) / q;
        e = -(a * exp(a * tau) - b * exp(b * tau)) / (a - b);
    }
    if (tau_out) *tau_out = tau;
    return e;
}

/* Is the load curve of TYPE6 interface i a straight line through the
 * origin (F = k P)? Its slope in *k [N/m]. */
int rc_type6_linear_slope(const rc_model *m, int i, double *k)
{
    if (m->inter_law[i] != RC_LAW_TYPE6 || m->inter_fct_ld[i] < 0) return 0;
    const rc_table *t = &m->table[m->inter_fct_ld[i]];
    const double sl = t->y[t->n - 1] / t->x[t->n - 1];
    for (int j = 0; j < t->n; j++)
        if (fabs(t->y[j] - sl * t->x[j]) > 1e-12 * (fabs(t->y[j]) + fabs(sl * t->x[j])) + 1e-300) return 0;
    *k = sl * m->inter_fscaleld[i] / m->inter_ascalex[i];
    return *k > 0;
}
