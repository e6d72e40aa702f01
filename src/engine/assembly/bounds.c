/*
 * The scene's scales for the physics checks, and the penetration bound of
 * each contact (docs/theory.md, "Physics checks of every run").
 *
 *   M      total mass of the free bodies, g = the largest gravity over the
 *          run, L = the largest body size, H = the scene's extent along
 *          gravity (body centres, surface points, mesh nodes) + 2 L;
 *   E_s    = max(kinetic energy at t = 0, M g L): the energy scale;
 *   E_a    = E_kin(0) + M g H + M v_imp^2 / 2: what the scene can put into
 *            one contact without the work of imposed motions beyond their
 *            speed (every body falling over the whole scene, at its
 *            initial and imposed speeds);
 *   W      = M g: the scene's weight, all of which one contact may carry.
 *
 * A contact's penetration bound is where its load law's force reaches
 * RC_PEN_FORCE_FACTOR max(W, F(p_a)), p_a the penetration where the law's
 * energy reaches E_a (the impact force at the scene's energy), and at most
 * the size of the smaller body of the pair.
 */
#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "engine/assembly/bounds.h"
#include "model/imposed.h"
#include "model/power.h"
#include "engine/assembly/data.h"

/* The far side of surface s from the centre of its body [m] (a plane:
 * the distance of its point). */
static double surf_extent(const rc_model *m, int s)
{
    const double *p = m->surf_p + 3 * s, *e = m->surf_ext + RC_SURF_NEXT * s;
    double c = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), ext = 0.0;
    switch (m->surf_kind[s]) {
    case RC_SURF_SPHERE: ext = m->surf_r[s]; break;
    case RC_SURF_CYL: ext = m->surf_r[s] + e[0] + (e[1] > 0 ? m->surf_r[s] : 0.0); break;
    case RC_SURF_BOX: ext = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]); break;
    case RC_SURF_SEG:
        c = 0.0; /* nodes are in the body frame, from its centre */
        for (int j = m->surf_nadr[s]; j < m->surf_nadr[s + 1]; j++) {
            const double *x = m->surf_node + 3 * j;
            ext = fmax(ext, sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
        }
        break;
    default: break; /* a plane: the distance of its point from the centre */
    }
    return c + ext;
}

double rc_body_size(const rc_model *m, int b)
{
    double size = 0.0;
    for (int s = 0; s < m->nsurf; s++)
        if (m->surf_body[s] == b) size = fmax(size, surf_extent(m, s));
    return size;
}

void rc_body_sizes(const rc_model *m, double *size)
{
    for (int b = 0; b < m->nbody; b++) size[b] = 0.0;
    for (int s = 0; s < m->nsurf; s++) {
        const int b = m->surf_body[s];
        if (b >= 0 && b < m->nbody) size[b] = fmax(size[b], surf_extent(m, s));
    }
}

double rc_touch_band(const rc_model *m, int i, const double *y, const rc_inter_report *r, double ulps, double rel,
                     int deck)
{
    const double *xa = rc_body_state(m, m->inter_ba[i], y), *xb = rc_body_state(m, m->inter_bb[i], y);
    /* the model's coordinates, and the deck's (where the positions were
     * rounded when read: a touching start moved 1 km away begins with a
     * gap of 2e-14 m, a fifth of a rounding there, that 1000 roundings of
     * the model's coordinates about its origin do not cover) */
    const double *o = m->origin;
    double L = 0.0, Ld = 0.0;
    for (int k = 0; k < 3; k++) {
        L += fabs(xa[k]) + fabs(xb[k]) + fabs(r->point[k]);
        Ld += fabs(xa[k] + o[k]) + fabs(xb[k] + o[k]) + fabs(r->point[k] + o[k]);
    }
    double band = fmax(ulps * L, deck ? RC_TOL_DECK_ULPS * Ld : 0.0) * DBL_EPSILON;
    if (isfinite(m->inter_pscale[i])) band = fmax(band, rel * m->inter_pscale[i]);
    return band;
}

double rc_law_force(const rc_model *m, int i, double p)
{
    double f, df;
    if (m->inter_law[i] == RC_LAW_POWER) {
        const rc_power *pw = &m->inter_pw[i];
        if (!pw->stiff) return pw->k * pow(p, pw->m1);
        rc_spline_eval(pw->stiff, p, &f, &df);
        return f;
    }
    rc_table_eval(&m->table[m->inter_fct_ld[i]], p / m->inter_ascalex[i], &f, &df);
    return m->inter_fscaleld[i] * f;
}

double rc_law_energy(const rc_model *m, int i, double p)
{
    if (!(p > 0)) return 0.0;
    if (m->inter_law[i] == RC_LAW_POWER) return rc_power_stored(m, i, p);
    const double ax = m->inter_ascalex[i];
    return m->inter_fscaleld[i] * ax * rc_table_integral(&m->table[m->inter_fct_ld[i]], 0.0, p / ax);
}

double rc_law_reach(const rc_model *m, int i, int energy, double target)
{
    if (!(target > 0) || !isfinite(target)) return NAN;
    /* bracket by decades from 1e-15 of the length unit, then bisect (the
     * laws are monotone on p >= 0 where they matter; the first crossing) */
    double lo = 0.0, hi = 1e-15;
    for (;;) {
        const double v = energy ? rc_law_energy(m, i, hi) : rc_law_force(m, i, hi);
        if (v >= target) break;
        if (!isfinite(v) || hi > 1e9) return NAN;
        lo = hi;
        hi *= 10.0;
    }
    for (int it = 0; it < 200 && hi - lo > 1e-12 * hi; it++) {
        const double mid = 0.5 * (lo + hi);
        const double v = energy ? rc_law_energy(m, i, mid) : rc_law_force(m, i, mid);
        if (v >= target) hi = mid;
        else lo = mid;
    }
    return hi;
}

void rc_scene_scales(const rc_model *m, rc_scene *s)
{
    const double gf = m->grav_table >= 0 ? rc_table_max_abs(&m->table[m->grav_table]) : 1.0;
    double gdir[3] = {0.0, 0.0, 0.0};
    s->mass = s->gmax = s->lmax = s->ekin0 = s->vimp = 0.0;
    /* the largest body: the largest extent of a surface on a body (one
     * pass over the surfaces) */
    for (int k = 0; k < m->nsurf; k++)
        if (m->surf_body[k] >= 0) s->lmax = fmax(s->lmax, surf_extent(m, k));
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double *g = m->body_grav + 3 * b, *y = m->body_y0 + RC_NB * b, *J = m->body_J + 9 * b;
        const double a = gf * sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (a > s->gmax) {
            s->gmax = a;
            for (int k = 0; k < 3; k++) gdir[k] = gf * g[k] / a;
        }
        s->mass += m->body_mass[b];
        double ek = 0.5 * m->body_mass[b] * (y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) ek += 0.5 * y[10 + r] * J[3 * r + c] * y[10 + c];
        s->ekin0 += ek;
    }
    /* imposed speeds: translations, and rotations at the body's size */
    const rc_imposed *p = m->imp;
    for (int k = 0; p && k < p->nt; k++)
        s->vimp = fmax(s->vimp, rc_imp_tspeed(m, k));
    for (int k = 0; p && k < p->nr; k++)
        for (int j = 0; j < 3; j++) s->vimp = fmax(s->vimp, rc_imp_rrate(m, k, j) * rc_body_size(m, p->rbody[k]));
    /* the extent along gravity: body centres, surface points, mesh nodes
     * (the body frame is the global one at t = 0) */
    double hmin = INFINITY, hmax = -INFINITY;
    for (int b = 0; b < m->nbody; b++) {
        const double *x = m->body_y0 + RC_NB * b;
        const double h = gdir[0] * x[0] + gdir[1] * x[1] + gdir[2] * x[2];
        hmin = fmin(hmin, h);
        hmax = fmax(hmax, h);
    }
    for (int k = 0; k < m->nsurf; k++) {
        const int b = m->surf_body[k];
        const double *x = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0, *q = m->surf_p + 3 * k;
        double h = 0.0;
        for (int c = 0; c < 3; c++) h += gdir[c] * (x[c] + q[c]);
        hmin = fmin(hmin, h);
        hmax = fmax(hmax, h);
        if (m->surf_kind[k] != RC_SURF_SEG) continue;
        for (int j = m->surf_nadr[k]; j < m->surf_nadr[k + 1]; j++) {
            const double *n = m->surf_node + 3 * j;
            h = 0.0;
            for (int c = 0; c < 3; c++) h += gdir[c] * (x[c] + n[c]);
            hmin = fmin(hmin, h);
            hmax = fmax(hmax, h);
        }
    }
    s->height = (hmax > hmin ? hmax - hmin : 0.0) + 2.0 * s->lmax;
    s->weight = s->mass * s->gmax;
    s->escale = fmax(s->ekin0, s->weight * s->lmax);
    s->eavail = s->ekin0 + s->weight * s->height + 0.5 * s->mass * s->vimp * s->vimp;
}

/* The depth into surface s beyond which its contact means nothing [m]:
 * half its thickness, a sphere's radius, a cylinder's radius or half-length
 * (with rounded ends, its half-length and radius); for a box half its
 * smallest half-size, since a point inside a box meets its nearest face,
 * which changes at the mid-plane: the depth a box reports never exceeds
 * its smallest half-size (a meshed box sank 2.25 m through a belt 0.059 m
 * thick while its reported depth stopped at the belt's half-thickness,
 * 0.0294 m, the bound itself); infinite for a plane and a segment surface
 * (whose thickness its nodes do not tell). */
static double surface_depth_limit(const rc_model *m, int s)
{
    if (s < 0) return INFINITY;
    const double *e = m->surf_ext + RC_SURF_NEXT * s;
    switch (m->surf_kind[s]) {
    case RC_SURF_SPHERE: return m->surf_r[s];
    case RC_SURF_BOX: return 0.5 * fmin(e[0], fmin(e[1], e[2]));
    case RC_SURF_CYL: return fmin(m->surf_r[s], e[0] + (e[1] > 0 ? m->surf_r[s] : 0.0));
    default: return INFINITY;
    }
}

double rc_pen_bound(const rc_model *m, int i, const rc_scene *s, const double *size, double *fbound)
{
    /* the impact force at the scene's energy, the weight */
    const double pa = rc_law_reach(m, i, 1, s->eavail);
    const double fa = isfinite(pa) ? rc_law_force(m, i, pa) : 0.0;
    const double f = RC_PEN_FORCE_FACTOR * fmax(s->weight, fa);
    double p = f > 0 ? rc_law_reach(m, i, 0, f) : NAN;
    *fbound = isfinite(p) ? f : NAN;
    if (!isfinite(p)) p = INFINITY;
    /* the size of the smaller body: beyond it, it has passed through; and
     * the half-thickness of the thinner surface in contact (a sphere's
     * radius, a box's smallest half-size, a cylinder's radius or half-
     * length): deeper, a rigid body's contact no longer means anything (a
     * box 0.25 m thick sank 0.18 m into a belt, its law at zero force,
     * under a bound of its half-diagonal, 0.26 m) */
    double lb = INFINITY;
    const int bs[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int k = 0; k < 2; k++) {
        const double l = bs[k] < 0 ? 0.0 : size ? size[bs[k]] : rc_body_size(m, bs[k]);
        if (l > 0) lb = fmin(lb, l);
    }
    const int ss[2] = {m->inter_sa[i], m->inter_sb[i]};
    for (int k = 0; k < 2; k++) lb = fmin(lb, surface_depth_limit(m, ss[k]));
    return fmin(p, lb);
}
