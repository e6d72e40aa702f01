/*
 * The physics checks of every run (guards.h; docs/theory.md, "Physics
 * checks of every run"). Everything is allocated in rc_guards_new; the
 * checks read values the run has already computed (the state, the zone
 * root values the integrator evaluated, the energies and forces of the
 * records) and add only the stored energy of the interfaces in contact at
 * each record (the per-interface hysteresis).
 */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/assembly/bounds.h"
#include "model/coupling.h"
#include "solver/guards.h"
#include "engine/assembly/assembly.h"

/* The dissipation channels, in the order of their per-element arrays. */
enum { CH_DAMP, CH_HYST, CH_FRIC, CH_CPL, CH_N };
static const char *const ch_name[CH_N] = {"energy_damping", "energy_hysteresis", "energy_friction",
                                          "energy_coupling_damping"};
static const int ch_energy[CH_N] = {RC_E_DAMP, RC_E_HYST, RC_E_FRIC, RC_E_CPL_DAMP};

/* Contact history of an interface (the results file's inter_contact_history). */
enum { HIST_NEVER = 0, HIST_REOPENED = 1, HIST_PERSISTENT = 2, HIST_STAYED = 3, HIST_SETTLED = 4 };

/* A quantity that must not decrease: its largest value so far and when
 * (time [s], integrator steps), and its value at the previous record. */
typedef struct mono {
    double max, t;
    long n;
    double prev, tp;
    long np;
} mono;
static mono mono_start(double v, double t, long n) { return (mono){v, t, n, v, t, n}; }

struct rc_guards {
    const rc_model *m;
    int warn, show;
    rc_scene scene;
    double *pbound, *fbound;  /* [ninter] penetration bound [m] (INFINITY: none), its force [N] */
    double *size;             /* [nbody] body sizes [m] */
    double *gscratch;         /* [root count] zone values when the integrator's are not at hand */
    /* energies */
    int started;
    long steps;               /* integrator steps so far (rc_guards_step) */
    double t_prev;            /* the previous record [s] */
    double mech0, imp0, pot0; /* at the first record [J] */
    double eref;              /* the largest energy in play so far [J] */
    double mech_done;         /* excess already reported (warn) [J] */
    mono gmax[CH_N];          /* channels in total */
    mono *emax;               /* [3 ninter + ncpl]: per interface damping, hysteresis, friction; per coupling */
    double *hyst;             /* [ninter] scratch: each interface's hysteresis at the record */
    double *pmax;             /* [ninter] largest penetration checked [m] */
    double *pemax;            /* [ninter] largest law's penetration P_e since the contact closed [m] */
    mono balance;             /* minus energy_total: the balance never rises */
    /* excursions in progress (reported once each): penetration, centres, open */
    unsigned char *on;        /* [6 ninter] */
    unsigned char *fric_over; /* [ninter] a friction force beyond its limit reported */
    unsigned char nonfinite;  /* reported once */
    /* results */
    long total;
    int nrow, caprow;
    rc_violation *row;        /* [caprow] the first RC_GUARD_ROWS violations (grown as they come) */
    char stop_msg[sizeof(((rc_violation *)0)->message)];
    double ratio[3];          /* energy excess, channel decrease, penetration: largest over its tolerance */
    double epre[RC_NENERGY];  /* the energies before the events of a root return */
    /* once per integrator step: the states in between are the integrator's
     * interpolant of the same step */
    long step_checked;        /* steps at the last state check (-1: none) */
    /* contact history */
    unsigned char *closed0, *ever, *settled;
    int *prev_mode, *hist;
    long *ncl, *nleave;
    double *t_settle;
};

static void *zalloc(size_t n, size_t size) { return calloc(n ? n : 1, size); }
/* max without the libm call (the operands are never NaN here) */
static inline double dmax(double a, double b) { return a > b ? a : b; }

/* Whether every value of v[n] is finite: an exponent of all ones (inf,
 * NaN) carries into the sign bit when one is added to it; an OR of
 * integers, which the compiler vectorises. */
static int all_finite(const double *v, int n)
{
    const uint64_t expo = 0x7FF0000000000000u, one = 0x0010000000000000u;
    uint64_t acc = 0;
    for (int k = 0; k < n; k++) {
        uint64_t b;
        memcpy(&b, v + k, sizeof b);
        acc |= (b & expo) + one;
    }
    return !(acc >> 63);
}

rc_guards *rc_guards_new(const rc_model *m, int warn, int show)
{
    rc_guards *g = calloc(1, sizeof *g);
    if (!g) return NULL;
    const size_t ni = (size_t)m->ninter, nc = (size_t)(m->cpl ? m->cpl->n : 0);
    g->m = m;
    g->warn = warn;
    g->show = show;
    g->pbound = zalloc(ni, sizeof(double));
    g->fbound = zalloc(ni, sizeof(double));
    g->size = zalloc((size_t)m->nbody, sizeof(double));
    g->gscratch = zalloc((size_t)rc_root_count(m), sizeof(double));
    g->emax = zalloc(3 * ni + nc, sizeof(mono));
    g->hyst = zalloc(ni, sizeof(double));
    g->pmax = zalloc(ni, sizeof(double));
    g->pemax = zalloc(ni, sizeof(double));
    g->on = zalloc(6 * ni, 1);
    g->fric_over = zalloc(ni, 1);
    g->closed0 = zalloc(ni, 1);
    g->ever = zalloc(ni, 1);
    g->settled = zalloc(ni, 1);
    g->prev_mode = zalloc(ni, sizeof(int));
    g->hist = zalloc(ni, sizeof(int));
    g->ncl = zalloc(ni, sizeof(long));
    g->nleave = zalloc(ni, sizeof(long));
    g->t_settle = zalloc(ni, sizeof(double));
    if (!g->pbound || !g->fbound || !g->size || !g->gscratch || !g->emax || !g->hyst || !g->pmax || !g->pemax || !g->on ||
        !g->fric_over || !g->closed0 || !g->ever || !g->settled || !g->prev_mode || !g->hist || !g->ncl ||
        !g->nleave || !g->t_settle) {
        rc_guards_free(g);
        return NULL;
    }
    g->step_checked = -1;
    rc_scene_scales(m, &g->scene);
    rc_body_sizes(m, g->size);
    for (int i = 0; i < m->ninter; i++) g->pbound[i] = rc_pen_bound(m, i, &g->scene, g->size, &g->fbound[i]);
    return g;
}

void rc_guards_free(rc_guards *g)
{
    if (!g) return;
    void *p[] = {g->pbound, g->fbound, g->size, g->gscratch, g->emax, g->hyst, g->pmax, g->pemax, g->on, g->fric_over,
                 g->row, g->closed0, g->ever, g->settled, g->prev_mode, g->hist, g->ncl, g->nleave, g->t_settle};
    for (size_t k = 0; k < sizeof p / sizeof p[0]; k++) free(p[k]);
    free(g);
}

const char *rc_guards_message(const rc_guards *g) { return g ? g->stop_msg : ""; }

int rc_guards_rows(const rc_guards *g, const rc_violation **rows)
{
    *rows = g ? g->row : NULL;
    return g ? g->nrow : 0;
}

/* Record a violation; 1 when it stops the run. */
static int violate(rc_guards *g, double t, double t_from, const char *check, const char *element, double value,
                   double limit, const char *fmt, ...) __attribute__((format(printf, 8, 9)));
static int violate(rc_guards *g, double t, double t_from, const char *check, const char *element, double value,
                   double limit, const char *fmt, ...)
{
    rc_violation v;
    memset(&v, 0, sizeof v);
    v.t = t;
    v.t_from = t_from;
    snprintf(v.check, sizeof v.check, "%s", check);
    snprintf(v.element, sizeof v.element, "%s", element ? element : "");
    v.value = value;
    v.limit = limit;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(v.message, sizeof v.message, fmt, ap);
    va_end(ap);
    if (g->nrow == g->caprow && g->caprow < RC_GUARD_ROWS) { /* only when a check fails */
        const int cap = g->caprow ? 2 * g->caprow : 16;
        rc_violation *r = realloc(g->row, (size_t)(cap < RC_GUARD_ROWS ? cap : RC_GUARD_ROWS) * sizeof *r);
        if (r) {
            g->row = r;
            g->caprow = cap < RC_GUARD_ROWS ? cap : RC_GUARD_ROWS;
        }
    }
    if (g->nrow < g->caprow) g->row[g->nrow++] = v;
    g->total++;
    if (!g->warn) {
        snprintf(g->stop_msg, sizeof g->stop_msg, "%s", v.message);
        return 1;
    }
    if (g->show && g->total <= RC_GUARD_PRINT)
        fprintf(stderr, "ricochet: physics check failed (the run goes on: on-violation warn): %s\n", v.message);
    return 0;
}

/* ---- every accepted state ------------------------------------------ */
/* Rotate v by the unit quaternion q (w, x, y, z). */
static void qrot(const double *q, const double *v, double *out)
{
    const double w = q[0], x = q[1], y = q[2], z = q[3];
    const double t[3] = {2.0 * (y * v[2] - z * v[1]), 2.0 * (z * v[0] - x * v[2]), 2.0 * (x * v[1] - y * v[0])};
    out[0] = v[0] + w * t[0] + (y * t[2] - z * t[1]);
    out[1] = v[1] + w * t[1] + (z * t[0] - x * t[2]);
    out[2] = v[2] + w * t[2] + (x * t[1] - y * t[0]);
}

/* Centre of sphere surface s at the state y, global frame [m]. */
static void sphere_centre(const rc_model *m, int s, const double *y, double *c)
{
    const double *x = rc_body_state(m, m->surf_body[s], y), *p = m->surf_p + 3 * s;
    double r[3];
    qrot(x + 3, p, r);
    for (int k = 0; k < 3; k++) c[k] = x[k] + r[k];
}

/* Box surface s at the state y: centre c, unit axes a[3][3] (rows) and
 * half-sizes h, global frame. */
static void box_pose(const rc_model *m, int s, const double *y, double c[3], double a[3][3], double h[3])
{
    const double *x = rc_body_state(m, m->surf_body[s], y), *e = m->surf_ext + RC_SURF_NEXT * s;
    qrot(x + 3, m->surf_p + 3 * s, c);
    for (int k = 0; k < 3; k++) {
        c[k] += x[k];
        h[k] = e[k];
        qrot(x + 3, e + 3 + 3 * k, a[k]);
    }
}

/* Depth of the overlap of the two boxes of a box-box interface i at y [m]
 * by the separating-axis test: the least overlap of their projections on
 * the 15 candidate axes (the 6 face normals, the 9 cross products of
 * their edges); negative when the boxes are apart. For two convex
 * polyhedra this is the distance one must move to separate them along
 * the best axis, whatever touches: face, edge or corner. The engine's
 * contact points are the corners against the faces and the edges against
 * the edges (docs/theory.md 2.7), each within a search depth; this depth
 * is the solids' own, an independent check of what they carry. */
static double box_box_depth(const rc_model *m, int i, const double *y)
{
    double ca[3], cb[3], A[3][3], B[3][3], ha[3], hb[3];
    box_pose(m, m->inter_sa[i], y, ca, A, ha);
    box_pose(m, m->inter_sb[i], y, cb, B, hb);
    const double T[3] = {cb[0] - ca[0], cb[1] - ca[1], cb[2] - ca[2]};
    double depth = INFINITY;
    for (int k = 0; k < 15; k++) {
        double L[3];
        if (k < 3) {
            for (int c = 0; c < 3; c++) L[c] = A[k][c];
        } else if (k < 6) {
            for (int c = 0; c < 3; c++) L[c] = B[k - 3][c];
        } else {
            const double *u = A[(k - 6) / 3], *v = B[(k - 6) % 3];
            L[0] = u[1] * v[2] - u[2] * v[1];
            L[1] = u[2] * v[0] - u[0] * v[2];
            L[2] = u[0] * v[1] - u[1] * v[0];
            const double n = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
            if (n < 1e-6) continue; /* parallel edges: the face axes decide */
            for (int c = 0; c < 3; c++) L[c] /= n;
        }
        double r = -fabs(T[0] * L[0] + T[1] * L[1] + T[2] * L[2]);
        for (int j = 0; j < 3; j++) {
            r += ha[j] * fabs(A[j][0] * L[0] + A[j][1] * L[1] + A[j][2] * L[2]);
            r += hb[j] * fabs(B[j][0] * L[0] + B[j][1] * L[1] + B[j][2] * L[2]);
        }
        depth = fmin(depth, r);
    }
    return depth;
}

/* How far the point x lies outside the solid box of surface s [m] (0
 * inside): the distance from x to its nearest point of the box. A
 * cylinder against a box acts through the plane of the face facing its
 * centre, or of the edge it lies along (docs/theory.md 2, cylinder - box),
 * which goes on beyond the box: a cylinder lying across an edge, or
 * standing on its end over it, may be held where the box is not. */
static double outside_box(const rc_model *m, int s, const double *y, const double x[3])
{
    double c[3], a[3][3], h[3];
    box_pose(m, s, y, c, a, h);
    double b2 = 0.0;
    for (int k = 0; k < 3; k++) {
        const double xl = (x[0] - c[0]) * a[k][0] + (x[1] - c[1]) * a[k][1] + (x[2] - c[2]) * a[k][2];
        if (fabs(xl) > h[k]) b2 += (fabs(xl) - h[k]) * (fabs(xl) - h[k]);
    }
    return sqrt(b2);
}

/* The band within which an open interface i may penetrate at y: the
 * rounding of P (a thousand ulps of the coordinates and sizes involved)
 * and the position tolerance rtol p_s [m]. */
static double open_band(const rc_guards *g, int i, const double *y)
{
    const rc_model *m = g->m;
    const int ba = m->inter_ba[i], bb = m->inter_bb[i];
    const double *xa = rc_body_state(m, ba, y), *xb = rc_body_state(m, bb, y);
    double L = (ba >= 0 ? g->size[ba] : 0.0) + (bb >= 0 ? g->size[bb] : 0.0);
    for (int k = 0; k < 3; k++) L += fabs(xa[k]) + fabs(xb[k]);
    double band = 1e3 * DBL_EPSILON * L;
    if (isfinite(m->inter_pscale[i])) band = fmax(band, fmax(1e-9, m->rtol) * m->inter_pscale[i]);
    return band;
}

/* A finite state y[n] (at the records: the integrator's error test rejects
 * a step to a non-finite state, and the states it leaves out are
 * constant); 1: a violation stops the run. */
static int state_finite(rc_guards *g, double t, const double *y, int n)
{
    const rc_model *m = g->m;
    if (g->nonfinite || all_finite(y, n)) return 0;
    for (int k = 0; k < n; k++) {
        if (isfinite(y[k])) continue;
        char name[160], el[64] = "";
        rc_state_name(m, k, name, sizeof name);
        for (int b = 0; b < m->nbody; b++)
            if (m->body_yadr[b] >= 0 && k >= m->body_yadr[b] && k < m->body_yadr[b] + RC_NB)
                snprintf(el, sizeof el, "/RBODY/%d", m->body_id[b]);
        g->nonfinite = 1;
        return violate(g, t, t, "non_finite", el, y[k], 0.0, "non-finite state at t = %.9g s: %s = %g", t, name, y[k]);
    }
    return 0;
}

int rc_guards_due(rc_guards *g, long steps, int at_root)
{
    if (!g) return 0;
    g->steps = steps;
    /* an output time inside the last step: its interpolant, checked at the
     * step (a located root is checked: its events follow) */
    return at_root || steps != g->step_checked;
}

int rc_guards_step(rc_guards *g, const rc_data *d, double t, const double *y, const double *zone, int at_root,
                   long steps)
{
    if (!rc_guards_due(g, steps, at_root)) return 0;
    const rc_model *m = g->m;
    g->step_checked = steps;
    if (m->ninter == 0) return 0;
    const int per = zone ? 1 : RC_ROOTS_PER_INTER, off = zone ? 0 : RC_ROOT_ZONE;
    if (!zone) { /* the integrator's values are not at hand: evaluate them */
        rc_assemble_roots(m, d, t, y, g->gscratch);
        zone = g->gscratch;
    }
    for (int i = 0; i < m->ninter; i++) {
        const int mode = d->inter_mode[i];
        if (mode == RC_MODE_INACTIVE || d->inter_track[i]) continue; /* not acting, or P = 0 by construction */
        const double P = zone[per * i + off] - (mode != RC_MODE_OPEN ? d->inter_band[2 * i] : 0.0);
        unsigned char *on = g->on + 6 * i;
        /* beyond the contact's scales */
        const double pb = g->pbound[i];
        if (P > g->pmax[i]) g->pmax[i] = P; /* over its bound at the end (rc_guards_finish) */
        if (!(P <= pb) && !on[0]) {
            on[0] = 1;
            char why[200];
            if (isfinite(g->fbound[i]) && rc_law_force(m, i, pb) >= (1.0 - 1e-9) * g->fbound[i])
                snprintf(why, sizeof why, "where the law's force reaches %.3g N, %g x the larger of the scene's weight %.3g N and "
                         "its impact force", g->fbound[i], RC_PEN_FORCE_FACTOR, g->scene.weight);
            else
                snprintf(why, sizeof why, "the size of the smaller body, or half the thinner surface's thickness (a quarter of a box's)");
            if (violate(g, t, t, "penetration", m->inter_name[i], P, pb,
                        "penetration of %s is %.6g m at t = %.9g s, beyond its bound %.6g m (%s): the bodies pass "
                        "through each other", m->inter_name[i], P, t, pb, why))
                return 1;
        } else if (P <= pb) {
            on[0] = 0;
        }
        /* several contact points sharing the law: its penetration P_e (an
         * own state) behind the points' P by more than RC_DEFICIT_FACTOR
         * max(P_e^max, p_s), P_e^max the largest since the contact closed,
         * kept while it is released (an impact's: within an impact on a
         * corner the law's penetration falls as the other corners recede
         * while the deepest is still in): the force is the law's at P_e,
         * the bodies sink into each other by the difference (docs/theory.md
         * 2.7) */
        if (mode != RC_MODE_CLOSED && mode != RC_MODE_RELEASED) g->pemax[i] = 0.0; /* open */
        if (mode == RC_MODE_CLOSED && rc_pair_multi(m->inter_pair[i]) && m->inter_peidx[i] >= 0) {
            const double pe = y[m->inter_eadr[i] + m->inter_peidx[i]], ps = m->inter_pscale[i];
            g->pemax[i] = dmax(g->pemax[i], pe);
            const double lim = RC_DEFICIT_FACTOR * dmax(g->pemax[i], isfinite(ps) ? ps : 0.0);
            if (lim > 0 && P - pe > lim && !on[5]) {
                on[5] = 1;
                if (violate(g, t, t, "law_deficit", m->inter_name[i], P - pe, lim,
                            "the contact points of %s penetrate by %.6g m at t = %.9g s, %.3g m deeper than its "
                            "law's penetration P_e = %.3g m (the force it carries), beyond %g max(P_e^max, p_s) = "
                            "%.3g m (P_e^max its largest since closing, p_s %.3g m): the shared force follows the "
                            "work done on it, rocking left it behind, the contact's dissipation did not pay its "
                            "recovery (docs/theory.md 2.7): the bodies sink into each other", m->inter_name[i], P, t,
                            P - pe, pe, RC_DEFICIT_FACTOR, lim, ps))
                    return 1;
            } else if (!(P - pe > lim)) {
                on[5] = 0;
            }
        }
        /* two spheres' centres: from P = Gap - (|c_b - c_a| - R_a - R_b)
         * (an Inacti offset moves P: from the state then) */
        if (m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE) {
            const double rs = m->surf_r[m->inter_sa[i]] + m->surf_r[m->inter_sb[i]];
            double dc = rs + m->inter_gap[i] - P;
            if (m->inter_oidx[i] >= 0) {
                double ca[3], cb[3];
                sphere_centre(m, m->inter_sa[i], y, ca);
                sphere_centre(m, m->inter_sb[i], y, cb);
                dc = sqrt((ca[0] - cb[0]) * (ca[0] - cb[0]) + (ca[1] - cb[1]) * (ca[1] - cb[1]) +
                          (ca[2] - cb[2]) * (ca[2] - cb[2]));
            }
            const double lim = RC_SPHERE_CENTRE_FRAC * rs;
            if (dc < lim && !on[1]) {
                on[1] = 1;
                if (violate(g, t, t, "sphere_centres", m->inter_name[i], dc, lim,
                            "the sphere centres of %s are %.6g m apart at t = %.9g s, closer than (R1 + R2)/2 = "
                            "%.6g m: the spheres pass through each other", m->inter_name[i], dc, t, lim))
                    return 1;
            } else if (dc >= lim) {
                on[1] = 0;
            }
        }
        /* two boxes: their overlap, whatever touches (box_box_depth); not
         * for TYPE11's edges alone, whose corners pass through faces, nor
         * TYPE19's corners alone (Iedge 1), whose edges pass each other */
        if (m->inter_pair[i] == RC_PAIR_SEG_SEG && m->surf_kind[m->inter_sa[i]] == RC_SURF_BOX &&
            m->surf_kind[m->inter_sb[i]] == RC_SURF_BOX && !(m->inter_edges && m->inter_edges[i])) {
            /* the overlap of the two solids, whatever carries it, within the
             * bound of the penetration (a corner on a face or two crossing
             * edges give the separating-axis depth itself: then P is
             * checked above) */
            const double D = box_box_depth(m, i, y) + m->inter_gap[i];
            if (!(D <= pb) && !on[3]) {
                on[3] = 1;
                if (violate(g, t, t, "box_overlap", m->inter_name[i], D, pb,
                            "the boxes of %s overlap by %.6g m at t = %.9g s (separating-axis depth), beyond its "
                            "bound %.6g m, while its contact points (corners against faces, edges against "
                            "edges) see a penetration of %.6g m: the boxes have passed into each other beyond "
                            "what the contact points see (docs/theory.md 2.7): the bodies pass through each other",
                            m->inter_name[i], D, t, pb, P))
                    return 1;
            } else if (D <= pb) {
                on[3] = 0;
            }
        }
        /* a cylinder held where the box is not: a closed, pressing
         * contact whose point lies outside the solid box by more than 1 %
         * of the radius */
        if (m->inter_pair[i] == RC_PAIR_CYL_BOX && mode == RC_MODE_CLOSED) {
            rc_inter_report r; /* the roots' evaluation of this state when kept */
            if (!(rc_report_cache_state(m, d, y) && rc_report_cache_get(m, d, i, &r))) rc_inter_report_eval_d(m, d, i, t, y, &r);
            const double lim = 0.01 * m->surf_r[m->inter_sa[i]];
            const double B = r.fn > 0 ? outside_box(m, m->inter_sb[i], y, r.point) : 0.0;
            if (B > lim && !on[4]) {
                on[4] = 1;
                if (violate(g, t, t, "support_beyond_edge", m->inter_name[i], B, lim,
                            "the contact point of %s lies %.6g m outside the box at t = %.9g s (more than 1 %% "
                            "of the cylinder's radius) while it presses with %.6g N: a cylinder against a box "
                            "acts through the plane of the face facing its centre (or of the edge it lies "
                            "along), which goes on beyond the box, so a cylinder lying across an edge (or "
                            "standing on its end over it) is held up where the box is not: the contact of a "
                            "cylinder with an edge it crosses is not modelled in this version "
                            "(docs/theory.md 2, cylinder - box)",
                            m->inter_name[i], B, t, r.fn))
                    return 1;
            } else if (B <= lim) {
                on[4] = 0;
            }
        }
        /* open while penetrating: a contact the engine did not close (at a
         * located root the event is still to be applied) */
        if (mode == RC_MODE_OPEN && !at_root && (P > 0 || on[2])) {
            const double band = open_band(g, i, y);
            if (P > band && !on[2]) {
                on[2] = 1;
                if (violate(g, t, t, "open_penetrating", m->inter_name[i], P, band,
                            "%s is open (no force) while penetrating by %.6g m at t = %.9g s, beyond its touch band "
                            "%.3g m: the contact was never closed", m->inter_name[i], P, t, band))
                    return 1;
            } else if (P <= band) {
                on[2] = 0;
            }
        }
        /* open at the located root of its closing yet far in: its
         * penetration jumped across zero instead of crossing it (a root
         * locates a crossing to within a rounding of t, where a continuous
         * P is nearly zero; the touch band (open_band) holds the rounding
         * of the coordinates, against a p_s of 1e-15 m: a wall contact of
         * 7.8e4 N at 7e-9 m closed 2.7 p_s in). Several contact points: a
         * point that came in under a face across the face's free edge,
         * already deep (a box hanging over the edge of a finite meshed
         * floor, whose corner below the floor's plane moves back over it):
         * node to surface does not see the edge, the force would start at
         * the law's value at that depth (the event closes it; the next step
         * finds the bodies deeper than the force the shared law carries) */
        const double deep = mode == RC_MODE_OPEN && at_root && isfinite(m->inter_pscale[i])
                                ? RC_DEFICIT_FACTOR * fmax(m->inter_pscale[i], open_band(g, i, y))
                                : INFINITY;
        if (P > deep) {
            rc_inter_report r;
            if (!(rc_report_cache_state(m, d, y) && rc_report_cache_get(m, d, i, &r)))
                rc_inter_report_eval_d(m, d, i, t, y, &r);
            if (violate(g, t, t, "entered_deep", m->inter_name[i], P, deep,
                        "%s closes at t = %.9g s already %.6g m deep, beyond %.3g m (%g times its penetration "
                        "scale p_s %.3g m, or its touch band where that is larger), deepest at (%.6g, %.6g, "
                        "%.6g) m: its penetration jumped from apart to deep "
                        "instead of crossing zero, a contact point that came in under a face across an edge of "
                        "that face: node to surface contact does not see a surface's free edge cutting into the "
                        "other body (a body hanging over the edge of a finite surface, or a mesh coarser than the "
                        "body it carries) (docs/theory.md 2.7): the bodies pass into each other",
                        m->inter_name[i], t, P, deep, RC_DEFICIT_FACTOR, m->inter_pscale[i], r.point[0], r.point[1],
                        r.point[2]))
                return 1;
        }
    }
    return 0;
}

/* ---- every record ------------------------------------------------------ */
/* Each interface's hysteresis at the record y into g->hyst: its W_load
 * minus its stored energy (energy.c), the stored energy evaluated for the
 * interfaces in contact but the last, whose value follows from the total
 * e_hyst (one evaluation fewer: none in a model of one contact). */
static void hysteresis_values(rc_guards *g, const rc_data *d, double t, const double *y, double e_hyst)
{
    const rc_model *m = g->m;
    int last = -1;
    for (int i = 0; i < m->ninter; i++)
        if (d->inter_mode[i] == RC_MODE_CLOSED || d->inter_mode[i] == RC_MODE_RELEASED) last = i;
    double others = 0.0;
    for (int i = 0; i < m->ninter; i++) {
        if (i == last) continue;
        g->hyst[i] = rc_inter_hysteresis(m, d, i, t, y);
        others += g->hyst[i];
    }
    if (last >= 0) g->hyst[last] = e_hyst - others;
}

/* Per-element channel values at the record y: per interface damping,
 * hysteresis and friction (as energy.c sums them), per coupling damping. */
static double element_channel(const rc_guards *g, const rc_data *d, double t, const double *y, int k)
{
    const rc_model *m = g->m;
    const int ni = m->ninter;
    if (k >= 3 * ni) { /* a coupling's damper */
        const int c = k - 3 * ni;
        const rc_cpl_kind kind = m->cpl->kind[c];
        return kind == RC_CPL_CATENARY ? 0.0 : y[m->cpl->eadr[c] + 1];
    }
    const int i = k / 3, ch = k % 3;
    const double *s = y + m->inter_eadr[i];
    if (ch == CH_DAMP) return s[1];
    if (ch == CH_HYST) return g->hyst[i]; /* hysteresis_values */
    const rc_fric *fr = &m->inter_fr[i];
    if (fr->kind == RC_FK_NONE) return 0.0;
    /* as energy.c: the stick springs of the interface or of its points */
    return s[fr->widx] - rc_inter_friction_stored(m, d, i, t, y);
}

/* The error weight of an energy accumulator at the energies in play,
 * rtol max(E_ref, |v|) + atol_E [J] (a sum of nacc accumulators: nacc
 * atol_E), and the tolerance of a drift over `steps` integrator steps:
 * `factor` (1 + steps) weights. */
static double drift_tol(const rc_guards *g, double v, long steps, double factor, int nacc)
{
    const rc_model *m = g->m;
    return factor * (double)(1 + (steps > 0 ? steps : 0)) *
           (m->rtol * dmax(g->eref, fabs(v)) + (nacc > 1 ? nacc : 1) * m->atol_energy);
}

/* Check a quantity v that must not decrease (a dissipation channel, or
 * minus energy_total for the balance) against its previous record (a jump
 * at an event) and its largest value so far (a slow drift), each within
 * the drift the error control allows over the steps since (drift_tol).
 * balance: the quantity is -energy_total. 1: stop. */
static int nondecreasing(rc_guards *g, double t, double v, mono *k, int balance, int nacc, const char *name,
                         const char *element, int *fired)
{
    const double from[2] = {k->prev, k->max}, tf[2] = {k->tp, k->t};
    const long steps[2] = {g->steps - k->np, g->steps - k->n};
    int worst = -1;
    double worst_ratio = 0.0, tol[2];
    for (int j = 0; j < 2; j++) {
        const double drop = from[j] - v;
        tol[j] = drift_tol(g, balance ? 0.0 : from[j], steps[j], balance ? RC_GUARD_ENERGY : RC_GUARD_CHANNEL, nacc);
        if (!(drop > 0) || !(tol[j] > 0)) continue;
        const double r = drop / tol[j];
        g->ratio[balance ? 0 : 1] = dmax(g->ratio[balance ? 0 : 1], r);
        if (r > 1.0 && r > worst_ratio) {
            worst = j;
            worst_ratio = r;
        }
    }
    k->prev = v;
    k->tp = t;
    k->np = g->steps;
    if (worst < 0) {
        if (v > k->max) {
            k->max = v;
            k->t = t;
            k->n = g->steps;
        }
        return 0;
    }
    *k = mono_start(v, t, g->steps); /* warn: a further decrease is reported anew */
    *fired = 1;
    const double drop = from[worst] - v;
    char when[120];
    if (tf[worst] < t) snprintf(when, sizeof when, "between t = %.9g and %.9g s", tf[worst], t);
    else snprintf(when, sizeof when, "at the events at t = %.9g s", t);
    if (balance)
        return violate(g, t, tf[worst], name, "", drop, tol[worst],
                       "energy_total (the energies plus everything dissipated and supplied: constant in exact "
                       "arithmetic) rose by %.6g J (from %.9g to %.9g J) %s, beyond the tolerance %.3g J (%g (1 + "
                       "k) energy error weights, k = %ld steps): energy created",
                       drop, -from[worst], -v, when, tol[worst], RC_GUARD_ENERGY, steps[worst]);
    char el[80] = "";
    if (element) snprintf(el, sizeof el, " of %s", element);
    return violate(g, t, tf[worst], name, element, drop, tol[worst],
                   "%s%s decreased by %.6g J (from %.9g to %.9g J) %s, beyond the tolerance %.3g J (%g (1 + k) "
                   "energy error weights, k = %ld steps): a dissipation never decreases",
                   name, el, drop, from[worst], v, when, tol[worst], RC_GUARD_CHANNEL, steps[worst]);
}

/* Finite energies; 0 when all are (else a violation is recorded, once;
 * *stop set when it stops the run). */
static int energies_finite(rc_guards *g, double t, const double *e, int *stop)
{
    static const char *const ename[RC_NENERGY] = {
        "energy_kinetic", "energy_potential", "energy_contact_work", "energy_damping", "energy_friction_work",
        "energy_contact_stored", "energy_hysteresis", "energy_friction", "energy_coupling_elastic",
        "energy_coupling_damping", "energy_catenary", "energy_imposed", "energy_total"};
    for (int k = 0; k < RC_NENERGY; k++)
        if (!isfinite(e[k])) {
            if (!g->nonfinite) {
                g->nonfinite = 1;
                *stop = violate(g, t, t, "non_finite", "", e[k], 0.0,
                                "non-finite %s = %g at t = %.9g s (masses, speeds or gravity beyond the range of the "
                                "doubles?)", ename[k], e[k], t);
            }
            return 1;
        }
    return 0;
}

/* The ledger at (t, y) with its energies e: the dissipation channels, the
 * mechanical energy and the balance. 1: stop. */
static int ledger(rc_guards *g, const rc_data *d, double t, const double *y, const double *e)
{
    const rc_model *m = g->m;
    const int ni = m->ninter, nc = m->cpl ? m->cpl->n : 0;
    const double mech = e[RC_E_KIN] + e[RC_E_POT] + e[RC_E_STORED] + e[RC_E_CPL_ELASTIC] + e[RC_E_CATENARY];
    hysteresis_values(g, d, t, y, e[RC_E_HYST]);
    if (!g->started) { /* the first record: the baseline */
        g->started = 1;
        g->mech0 = mech;
        g->imp0 = e[RC_E_IMPOSED];
        g->pot0 = e[RC_E_POT];
        g->eref = g->scene.escale;
        for (int c = 0; c < CH_N; c++) g->gmax[c] = mono_start(e[ch_energy[c]], t, g->steps);
        for (int k = 0; k < 3 * ni + nc; k++) g->emax[k] = mono_start(element_channel(g, d, t, y, k), t, g->steps);
        g->balance = mono_start(-e[RC_E_TOTAL], t, g->steps);
        g->t_prev = t;
        return 0;
    }
    /* the largest energy in play so far */
    const double supply = -(e[RC_E_IMPOSED] - g->imp0);
    const double inplay[] = {e[RC_E_KIN], e[RC_E_POT] - g->pot0, e[RC_E_STORED], e[RC_E_CPL_ELASTIC], e[RC_E_CATENARY],
                             supply};
    for (size_t k = 0; k < sizeof inplay / sizeof inplay[0]; k++) g->eref = fmax(g->eref, fabs(inplay[k]));
    /* the dissipation channels: per element, then in total (a sum of
     * ninter or ncoupling accumulators) */
    int fired[CH_N] = {0, 0, 0, 0};
    for (int k = 0; k < 3 * ni + nc; k++) {
        const int c = k >= 3 * ni ? CH_CPL : k % 3;
        if (c == CH_FRIC && m->inter_fr[k / 3].kind == RC_FK_NONE) continue;
        const char *el = k >= 3 * ni ? m->cpl->name[k - 3 * ni] : m->inter_name[k / 3];
        if (nondecreasing(g, t, element_channel(g, d, t, y, k), &g->emax[k], 0, 1, ch_name[c], el, &fired[c]))
            return 1;
    }
    int nel[CH_N] = {ni, ni, 0, nc}; /* elements of each channel */
    for (int i = 0; i < ni; i++) nel[CH_FRIC] += m->inter_fr[i].kind != RC_FK_NONE;
    for (int c = 0; c < CH_N; c++) {
        int dummy = 0;
        if (nel[c] <= 1) continue; /* the total is its one element, checked */
        if (fired[c]) { /* already named per element: the total starts afresh */
            g->gmax[c] = mono_start(e[ch_energy[c]], t, g->steps);
            continue;
        }
        if (nondecreasing(g, t, e[ch_energy[c]], &g->gmax[c], 0, c == CH_CPL ? nc : ni, ch_name[c], NULL, &dummy))
            return 1;
    }
    /* no energy from nothing: mechanical energy <= initial + supply, within
     * the drift the error control allows over the run's steps */
    const double tol = drift_tol(g, 0.0, g->steps, RC_GUARD_ENERGY, nc + 1);
    const double excess = mech - g->mech0 - supply;
    if (tol > 0) g->ratio[0] = dmax(g->ratio[0], excess / tol);
    if (excess > tol + g->mech_done) {
        g->mech_done = excess; /* warn: reported again when it grows by another tolerance */
        if (violate(g, t, g->t_prev, "mechanical_energy", "", excess, tol,
                    "the mechanical energy (kinetic + potential + stored in contacts and couplings) is %.9g J at "
                    "t = %.9g s, %.6g J above its initial %.9g J plus the supply %.6g J (the work of imposed "
                    "velocities), beyond the tolerance %.3g J (%g (1 + k) energy error weights, k = %ld steps): "
                    "energy created %s %.9g s",
                    mech, t, excess, g->mech0, supply, tol, RC_GUARD_ENERGY, g->steps,
                    g->t_prev < t ? "since the record before, at t =" : "at the events at t =", g->t_prev < t ? g->t_prev : t))
            return 1;
    }
    /* the balance: energy_total (constant in exact arithmetic, a sum of
     * all the accumulators) never rises */
    int dummy = 0;
    if (nondecreasing(g, t, -e[RC_E_TOTAL], &g->balance, 1, 3 * ni + 2 * nc + 2, "energy_balance", NULL, &dummy))
        return 1;
    g->t_prev = t;
    return 0;
}

/* The tolerance to which interface i's normal force is integrated [N]:
 * the Stiff line's band where the law has one (F_h and the curves at P,
 * inter_hband), at least the stiffness scale times the interface's
 * position tolerance. */
static double normal_force_tol(const rc_model *m, int i)
{
    const double ks = m->inter_kscale[i];
    return dmax(m->inter_hband[i], isfinite(ks) ? ks * rc_inter_apos(m, i) : 0.0);
}

/* Coulomb's bound at the record: the friction force of a closed contact is
 * within its limit (Sfric + mu F_n, the filtered limit where a filter acts;
 * the sum of the points' limits with friction per point), up to the bands
 * its stick -> slip and saturation roots leave, (1 + RC_SLIP_BAND) L plus
 * the force band (the viscous form's: at least RC_SLIP_BAND of the force
 * scale), and 1e-6 of L for the roots' location. The modes' roots keep
 * every state short of that: a force beyond it is a mode that was never
 * decided (a viscous friction left unsaturated at a start at P = 0 braked
 * a sliding sphere with 0.96 N at no normal force). The limit itself is
 * known only as well as F_n: mu times the normal force's tolerance
 * (normal_force_tol) is added (a ball held against a wall at 2e-5 N on an
 * undamped Stiff line of 2e11 N/m, its F_n known to 1.5e-4 N: at an
 * output time inside a step F_n read 0 and the viscous friction 1.2e-5 N).
 * The orthotropic laws (an ellipse, their report's limit one of its axes)
 * are not checked. 1: stop. */
static int friction_within_limits(rc_guards *g, const rc_data *d, double t, const frame_buf *fb)
{
    const rc_model *m = g->m;
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        if (fr->kind == RC_FK_NONE || fr->ortho || d->inter_mode[i] != RC_MODE_CLOSED || g->fric_over[i]) continue;
        const double *ft = fb->ffric + 3 * i, f = sqrt(ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2]);
        const double lim = fmax(fb->flim[i], 0.0),
                     bound = lim * (1.0 + RC_SLIP_BAND + 1e-6) + rc_fric_band(m, i) + fb->fmu[i] * normal_force_tol(m, i);
        if (!(f > bound)) continue;
        g->fric_over[i] = 1;
        if (violate(g, t, t, "friction_limit", m->inter_name[i], f, bound,
                    "the friction force of %s is %.6g N at t = %.9g s, beyond its limit %.6g N (Sfric + mu F_n, "
                    "F_n = %.6g N; with its bands and mu times the tolerance of F_n %.6g N): friction without the normal "
                    "force to carry it",
                    m->inter_name[i], f, t, lim, fb->fn[i], bound))
            return 1;
    }
    return 0;
}

int rc_guards_record(rc_guards *g, const rc_data *d, double t, const double *y, const frame_buf *fb)
{
    if (!g) return 0;
    const rc_model *m = g->m;

    if (state_finite(g, t, y, m->ny)) return 1;
    int stop = 0;
    if (energies_finite(g, t, fb->energy, &stop)) return stop; /* the ledger of this record cannot be compared */
    for (int i = 0; i < m->ninter; i++) {
        const double v[6] = {fb->fn[i], fb->fload[i], fb->fdamp[i], fb->ffric[3 * i], fb->ffric[3 * i + 1],
                             fb->ffric[3 * i + 2]};
        for (int k = 0; k < 6; k++) {
            if (isfinite(v[k])) continue;
            if (g->nonfinite) return 0;
            g->nonfinite = 1;
            static const char *const what[6] = {"normal", "load", "damping", "friction", "friction", "friction"};
            return violate(g, t, t, "non_finite", m->inter_name[i], v[k], 0.0,
                           "non-finite %s force of %s at t = %.9g s: %g", what[k], m->inter_name[i], t, v[k]);
        }
    }
    if (friction_within_limits(g, d, t, fb)) return 1;
    return ledger(g, d, t, y, fb->energy);
}

int rc_guards_before_events(rc_guards *g, const rc_data *d, double t, const double *y)
{
    if (!g || !g->started) return 0;
    rc_energy(g->m, d, t, y, g->epre);
    int stop = 0;
    if (energies_finite(g, t, g->epre, &stop)) return stop;
    return ledger(g, d, t, y, g->epre);
}

/* ---- contacts' history ------------------------------------------------- */
int rc_guards_started(rc_guards *g, const rc_data *d)
{
    if (!g) return 0;
    const rc_model *m = g->m;
    for (int i = 0; i < m->ninter; i++) {
        g->closed0[i] = g->ever[i] = d->inter_mode[i] == RC_MODE_CLOSED;
        g->prev_mode[i] = d->inter_mode[i];
    }
    /* an overlap at t = 0 the deck accepted (/RUN On_viol 2, engine/analyses/start.c) */
    if (m->start_note)
        return violate(g, 0.0, 0.0, "start_overlap", m->inter_name[m->start_inter], m->start_energy, m->start_escale,
                       "%s (accepted by /RUN On_viol 2)", m->start_note);
    return 0;
}

void rc_guards_event(rc_guards *g, const rc_data *d, int i, rc_event_kind kind, double t)
{
    if (!g || i < 0 || i >= g->m->ninter || t <= 0.0) return; /* t = 0: the start (rc_guards_started) */
    const int mode = d->inter_mode[i], was = g->prev_mode[i];
    if (mode == RC_MODE_CLOSED && was != RC_MODE_CLOSED) {
        g->ever[i] = 1;
        g->ncl[i]++;
    }
    if (mode != RC_MODE_CLOSED && was == RC_MODE_CLOSED) g->nleave[i]++;
    g->prev_mode[i] = mode;
    if (kind == RC_EV_CONTACT_SETTLE) {
        g->settled[i] = 1;
        g->t_settle[i] = t;
    }
}

/* Append "name" to a list of at most `most` names in buf. */
static void list_add(char *buf, size_t n, int *count, const char *name, int most)
{
    (*count)++;
    const size_t l = strlen(buf);
    if (*count <= most) snprintf(buf + l, n - l, "%s%s", *count > 1 ? ", " : "", name);
    else if (*count == most + 1) snprintf(buf + l, n - l, ", ...");
}

void rc_guards_finish(rc_guards *g, const rc_data *d, rc_stats *s, rc_output *o, int stopped)
{
    if (!g) return;
    const rc_model *m = g->m;
    for (int i = 0; i < m->ninter; i++)
        if (g->pbound[i] > 0 && isfinite(g->pbound[i])) g->ratio[2] = dmax(g->ratio[2], g->pmax[i] / g->pbound[i]);
    /* the contacts' history */
    char never[300] = "", pers[300] = "", stayed[300] = "", sett[300] = "";
    int nn = 0, np = 0, ns = 0, nt = 0, nr = 0;
    for (int i = 0; i < m->ninter; i++) {
        int h = HIST_REOPENED;
        if (g->settled[i]) h = HIST_SETTLED;
        else if (!g->ever[i]) h = HIST_NEVER;
        else if (g->closed0[i] && g->nleave[i] == 0) h = HIST_PERSISTENT;
        else if (g->nleave[i] == 0) h = HIST_STAYED;
        g->hist[i] = h;
        switch (h) {
        case HIST_NEVER: list_add(never, sizeof never, &nn, m->inter_name[i], 4); break;
        case HIST_PERSISTENT: list_add(pers, sizeof pers, &np, m->inter_name[i], 4); break;
        case HIST_STAYED: list_add(stayed, sizeof stayed, &nt, m->inter_name[i], 4); break;
        case HIST_SETTLED: list_add(sett, sizeof sett, &ns, m->inter_name[i], 4); break;
        default: nr++;
        }
    }
    char contacts[sizeof s->contacts_note] = "";
    size_t l = 0;
#define ADD(...) (l = strlen(contacts), snprintf(contacts + l, sizeof contacts - l, __VA_ARGS__))
    if (nn) ADD("%s%d never closed (%s)", l ? "; " : "", nn, never);
    if (np) ADD("%s%d closed from the start and never reopened (%s)", strlen(contacts) ? "; " : "", np, pers);
    if (nt) ADD("%s%d closed during the run and never reopened (%s)", strlen(contacts) ? "; " : "", nt, stayed);
    if (ns) ADD("%s%d settled into persistent contact after accumulating bounces (%s)", strlen(contacts) ? "; " : "", ns,
                sett);
    if (nr && strlen(contacts)) ADD("; %d closed and reopened", nr);
    /* nothing ever touched: say so plainly (a deck in mm with gravity in
     * m/s^2, a gap, a run that ends before the first contact) */
    if (nn > 0 && nn == m->ninter)
        ADD(" - no contact closed in the whole run: the bodies never touched; check the gravity and the units, "
            "the gaps, the initial positions and the end time");
#undef ADD
    (void)d;
    /* the checks */
    char summary[sizeof s->physics_note];
    if (g->total == 0)
        snprintf(summary, sizeof summary,
                 "passed (finite values, penetrations, friction limits, dissipation channels, energy balance)");
    else if (stopped)
        snprintf(summary, sizeof summary, "failed: %s", g->stop_msg);
    else
        snprintf(summary, sizeof summary, "%ld violation%s (the run went on: on-violation warn); the first: %.500s",
                 g->total, g->total > 1 ? "s" : "", g->row[0].message);
    if (s) {
        s->violations = g->total;
        snprintf(s->physics_note, sizeof s->physics_note, "%s", summary);
        snprintf(s->contacts_note, sizeof s->contacts_note, "%s", contacts);
    }
    if (o) {
        rc_out_physics p = {summary, contacts, stopped, g->total, g->nrow, g->row, m->ninter ? g->hist : NULL,
                            {g->ratio[0], g->ratio[1], g->ratio[2]}};
        rc_error e;
        rc_output_physics(o, &p, &e);
    }
}
