/*
 * Right-hand side, root functions and reports, in real arithmetic.
 * Pure: reads (t, y, modes), writes ydot; no allocation, no printing, no
 * mode change.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/model.h"
#include "model/coupling_contact.h"
#include "engine/assembly/assembly.h"

#include "engine/kernels/as_real.h"
#include "engine/kernels/kernels.inc"
#include "engine/kernels/kernels_coupling.inc"
#include "engine/kernels/kernel_fast.inc"

/* Interface i goes the fast path (kernel_fast.inc). */
static inline int is_fast(const rc_model *m, int i) { return m->inter_fast && m->inter_fast[i]; }

/* Acceleration slot (vdot, wdot) of body b in ydot, NULL when b has no states. */
static double *acc_slot(const rc_model *m, int b, double *ydot)
{
    return (b >= 0 && m->body_yadr[b] >= 0) ? ydot + m->body_yadr[b] + 7 : NULL;
}

int rc_assemble_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot)
{
    d->sc->n_rhs++;
    /* bodies: free motion (the gravity time function once) */
    const double gf = rc_gravity_factor_run(m, d, t);
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) body_rhs_r(m, b, gf, y + m->body_yadr[b], ydot + m->body_yadr[b]);
    /* interfaces: forces into the accelerations, own-state rates */
    for (int i = 0; i < m->ninter; i++) {
        double *sdot = ydot + m->inter_eadr[i];
        const int ba = m->inter_ba[i], bb = m->inter_bb[i];
        const int nst = m->inter_ns[i] + m->inter_pst[i] * m->inter_npt[i]; /* own and point states */
        if (d->inter_mode[i] == RC_MODE_INACTIVE) {
            memset(sdot, 0, (size_t)nst * sizeof(double));
            continue;
        }
        if (is_fast(m, i)) {
            t6out_r o;
            t6fast(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], rc_body_state(m, ba, y),
                   rc_body_state(m, bb, y), y + m->inter_eadr[i], acc_slot(m, ba, ydot), acc_slot(m, bb, ydot), sdot,
                   &o, 0);
        } else {
            type6_r(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i],
                    d->pt_slip + m->inter_pbase[i], rc_body_state(m, ba, y), rc_body_state(m, bb, y),
                    y + m->inter_eadr[i], acc_slot(m, ba, ydot), acc_slot(m, bb, ydot), sdot, NULL, NULL,
                    d->sc->node_cache, NULL);
        }
        for (int k = 0; k < nst; k++)
            if (!isfinite(sdot[k])) {
                d->sc->fail_inter = i;
                d->sc->fail_t = t;
                return 1; /* recoverable: CVODE retries with a smaller step */
            }
    }
    /* couplings (below) */
    if (rc_cpl_rhs(m, d, t, y, ydot)) return 1;
    /* potential of a time-varying gravity: E' = -sum m g(t).v */
    if (m->gwork_adr >= 0) {
        double w = 0;
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double g[3]; /* rc_gravity at t */
            const double *v = y + m->body_yadr[b] + 7;
            for (int k = 0; k < 3; k++) g[k] = m->body_grav[3 * b + k] * gf;
            w -= m->body_mass[b] * (g[0] * v[0] + g[1] * v[1] + g[2] * v[2]);
        }
        ydot[m->gwork_adr] = w;
    }
    /* held DOFs (/BCS): the support takes whatever force acts */
    for (int k = 0; k < m->nheld; k++) ydot[m->held[k]] = 0.0;
    /* imposed velocities (imposed_rhs.c): their rates, the reactions' work */
    if (m->imp) rc_imp_rhs(m, d, t, y, ydot);
    return 0;
}

double rc_friction_mu(const rc_model *m, int i, int dir, double p, double v, double fn)
{
    return fric_mu_r(m, &m->inter_fr[i], dir, p, v, fn, i);
}

/* The normal part of an interface's report from its kernel's quantities
 * (all that the root functions read of a fast interface). */
static inline void report_normal_of(const t6out_r *po, rc_inter_report *r)
{
    r->p = po->p;
    r->vn = po->vn;
    r->p_raw = po->p_raw;
    r->vn_raw = po->vn_raw;
    r->pl = po->pl;
    r->vl = po->vl;
    r->vd = po->vd;
    r->fload = po->fel;
    r->fdamp = po->fd;
    r->fn = po->fel + po->fd;
    r->fl = po->fl;
    r->fu = po->fu;
    r->fh = po->fh;
    r->offset = po->off;
}

/* The report of an interface from its kernel's quantities. */
static void report_of(const t6out_r *po, rc_inter_report *r)
{
    /* read in place (a copy of the struct cost as much as the rest) */
    report_normal_of(po, r);
    r->flim = po->flim;
    r->mu = po->mu;
    r->fstored = po->estore;
    r->ftan = po->ftan;
    r->vslip = po->vslip;
    r->slip_root = po->slip_root;
    for (int k = 0; k < 3; k++) {
        r->ft[k] = po->ft[k];
        r->fraw[k] = po->fraw[k];
        r->vt[k] = po->vt[k];
    }
    for (int k = 0; k < 3; k++) {
        r->point[k] = po->g.point[k];
        r->normal[k] = po->g.n[k];
    }
}

/* ncache: the node geometry cache of a node pair (rc_data.node_cache), NULL:
 * none (each pass over the points computes their geometry again) */
static void report_eval(const rc_model *m, int i, int mode, int branch, int track, int slip, const int *pslip,
                        const double *y, rc_inter_report *r, void *ncache)
{
    t6out_r o;
    if (is_fast(m, i))
        t6fast(m, i, mode, branch, track, rc_body_state(m, m->inter_ba[i], y), rc_body_state(m, m->inter_bb[i], y),
               y + m->inter_eadr[i], NULL, NULL, NULL, &o, T6F_LAW | T6F_FULL);
    else
        type6_r(m, i, mode, branch, track, slip, pslip, rc_body_state(m, m->inter_ba[i], y),
                rc_body_state(m, m->inter_bb[i], y), y + m->inter_eadr[i], NULL, NULL, NULL, &o, NULL, ncache, NULL);
    report_of(&o, r);
}

void rc_inter_report_eval(const rc_model *m, int i, int mode, int branch, int track, int slip, double t,
                          const double *y, rc_inter_report *r)
{
    (void)t;
    report_eval(m, i, mode, branch, track, slip, NULL, y, r, NULL);
}

void rc_inter_report_eval_d(const rc_model *m, const rc_data *d, int i, double t, const double *y, rc_inter_report *r)
{
    (void)t;
    report_eval(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i],
                d->pt_slip + m->inter_pbase[i], y, r, d->sc->node_cache);
}

void rc_points_eval(const rc_model *m, const rc_data *d, int i, const int *slip, double t, const double *y, double *out)
{
    (void)t;
    const int npt = m->inter_npt[i];
    for (int j = 0; j < npt; j++) {
        out[RC_PT_OUT * j] = -1.0;
        for (int k = 1; k < 5; k++) out[RC_PT_OUT * j + k] = 0.0;
        out[RC_PT_OUT * j + 5] = -1.0;
    }
    if (d->inter_mode[i] != RC_MODE_CLOSED || npt == 0) return;
    t6out_r o;
    type6_r(m, i, RC_MODE_CLOSED, d->inter_branch[i], d->inter_track[i], d->inter_slip[i],
            slip ? slip : d->pt_slip + m->inter_pbase[i], rc_body_state(m, m->inter_ba[i], y),
            rc_body_state(m, m->inter_bb[i], y), y + m->inter_eadr[i], NULL, NULL, NULL, &o, out, d->sc->node_cache, NULL);
}

/* The distance of distance sensor k's two points (body-frame points of
 * its bodies, or fixed) at y [m]: the kernels' material points. */
double rc_sens_distance(const rc_model *m, int k, const double *y)
{
    double a[3], b[3], v[3];
    body_point_r(rc_body_state(m, m->sens_body[2 * k], y), m->sens_p + 6 * k, a, v);
    body_point_r(rc_body_state(m, m->sens_body[2 * k + 1], y), m->sens_p + 6 * k + 3, b, v);
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double rc_sens_inter_force(const rc_model *m, const rc_data *d, int k, double t, const double *y)
{
    double f = 0.0;
    for (int i = 0; i < m->ninter; i++) {
        if (m->inter_id[i] != m->sens_inter[k] || d->inter_mode[i] != RC_MODE_CLOSED) continue;
        rc_inter_report r;
        rc_inter_report_eval_d(m, d, i, t, y, &r);
        if (r.fn > 0) f += r.fn;
    }
    return f;
}

/* Distance sensors' root functions: d - Dmax and Dmin - d until triggered;
 * an interface sensor's with a force bound: F_n - Fmax in its first slot
 * until triggered (F_n the total normal force of its interfaces, in their
 * current modes); a sensor that releases a held body (sens_hold), once its
 * time on is known and until the release: t - t_on in its first slot. */
void rc_sens_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    for (int k = 0; k < m->nsens; k++) {
        g[2 * k] = g[2 * k + 1] = -1.0; /* a time sensor, or one that has triggered */
        if (m->sens_hold[k] && isfinite(d->sens_ton[k])) {
            g[2 * k] = d->sens_rel[k] ? 1.0 : t - d->sens_ton[k];
            continue;
        }
        if (isfinite(d->sens_ton[k])) continue;
        if (m->sens_kind[k] == 5 && m->sens_d[2 * k + 1] > 0) {
            /* the forces the interfaces' roots just evaluated (inter_fnr):
             * rc_sens_roots runs after them, at the same state */
            double f = 0.0;
            for (int i = 0; i < m->ninter; i++)
                if (m->inter_id[i] == m->sens_inter[k]) f += d->sc->inter_fnr[i];
            g[2 * k] = f - m->sens_d[2 * k + 1];
        } else if (m->sens_kind[k] == 1) {
            const double dist = rc_sens_distance(m, k, y), *b = m->sens_d + 2 * k;
            if (b[1] > 0) g[2 * k] = dist - b[1];
            if (b[0] > 0) g[2 * k + 1] = b[0] - dist;
        }
        /* a criterion that holds, waiting for Tmin: its end (the root of
         * the bound it crossed, negated: the value back within it) and the
         * time Tmin after it began, both rising through 0 */
        const double arm = d->sens_arm[2 * k];
        if (isfinite(arm)) {
            g[2 * k] = -(d->sens_arm[2 * k + 1] > 0 ? g[2 * k] : g[2 * k + 1]);
            g[2 * k + 1] = t - (arm + m->sens_tmin[k]);
        }
    }
}

void rc_point_position(const rc_model *m, int i, int j, const double *y, double x[3])
{
    const double *ya = rc_body_state(m, m->inter_ba[i], y), *yb = rc_body_state(m, m->inter_bb[i], y);
    double pl[12], d, dd, nb[3];
    if (m->inter_pair[i] == RC_PAIR_SEG_PLANE) plane_of_r(m, m->inter_sb[i], yb, pl, pl + 3, pl + 6, pl + 9);
    seg_node_r(m, i, j, ya, yb, pl, &d, &dd, x, nb, NULL, NULL, NULL, NULL);
}

double rc_point_distance(const rc_model *m, int i, int j, const double *y, int *hints)
{
    const double *ya = rc_body_state(m, m->inter_ba[i], y), *yb = rc_body_state(m, m->inter_bb[i], y);
    double pl[12], d, dd, x[3], nb[3];
    if (m->inter_pair[i] == RC_PAIR_SEG_PLANE) plane_of_r(m, m->inter_sb[i], yb, pl, pl + 3, pl + 6, pl + 9);
    seg_node_r(m, i, j, ya, yb, pl, &d, &dd, x, nb, NULL, NULL, hints, NULL);
    return d;
}

double rc_point_fade(const rc_model *m, int i, int j, const double *y, double fade[2])
{
    const double *ya = rc_body_state(m, m->inter_ba[i], y), *yb = rc_body_state(m, m->inter_bb[i], y);
    double pl[12], d, dd, x[3], nb[3];
    if (m->inter_pair[i] == RC_PAIR_SEG_PLANE) plane_of_r(m, m->inter_sb[i], yb, pl, pl + 3, pl + 6, pl + 9);
    seg_node_r(m, i, j, ya, yb, pl, &d, &dd, x, nb, NULL, fade, NULL, NULL);
    return d;
}

/* The state of the reports kept (rc_data.repc): the caller compares once
 * and reads per interface. */
int rc_report_cache_state(const rc_model *m, const rc_data *d, const double *y)
{
    const rc_repcache *c = d->sc->repc;
    return c && c->ok && memcmp(c->y, y, (size_t)m->ny * sizeof(double)) == 0;
}

int rc_report_cache_get(const rc_model *m, const rc_data *d, int i, rc_inter_report *r)
{
    const rc_repcache *c = d->sc->repc;
    const int *k = c->key + 4 * i;
    if (k[0] < 0 || k[0] != d->inter_mode[i] || k[1] != d->inter_branch[i] || k[2] != d->inter_track[i] ||
        k[3] != d->inter_slip[i])
        return 0;
    const int pb = m->inter_pbase[i], npt = m->inter_npt[i];
    if (npt > 0 && memcmp(c->pslip + pb, d->pt_slip + pb, (size_t)npt * sizeof(int)) != 0) return 0;
    *r = c->rep[i];
    return 1;
}

/* Keep interface i's report r, evaluated in its present modes. */
static void keep(rc_repcache *rc, const rc_data *d, int i, const rc_inter_report *r)
{
    int *k = rc->key + 4 * i;
    k[0] = d->inter_mode[i];
    k[1] = d->inter_branch[i];
    k[2] = d->inter_track[i];
    k[3] = d->inter_slip[i];
    rc->rep[i] = *r;
}

void rc_assemble_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    /* the reports are kept for samples at the same state (rc_report_cache_get):
     * the interfaces of the general kernel, whose report depends on the
     * state, the four modes and, with contact points, the points' modes */
    rc_repcache *rc = d->sc->repc && d->sc->repc->on ? d->sc->repc : NULL;
    int kept = 0; /* reports kept */
    for (int i = 0; i < m->ninter; i++) {
        if (rc) rc->key[4 * i] = -1;
        double *gi = g + RC_ROOTS_PER_INTER * i;
        for (int k = 0; k < RC_ROOTS_PER_INTER; k++) gi[k] = 1.0; /* inactive roots */
        d->sc->inter_flim[2 * i] = d->sc->inter_flim[2 * i + 1] = 0.0;
        d->sc->inter_fnr[i] = 0.0;
        /* the start: Tstart, or a distance sensor's time on (-1 until it triggers) */
        const double ton = m->inter_sens[i] < 0 ? m->inter_tstart[i] : rc_sens_inter_ton(m, d, i);
        gi[RC_ROOT_TSTART] = isfinite(ton) ? t - ton : -1.0;
        gi[RC_ROOT_TSTOP] = t - m->inter_tstop[i];
        const int mode = d->inter_mode[i], br = d->inter_branch[i], trk = d->inter_track[i];
        if (mode == RC_MODE_INACTIVE) continue;
        rc_inter_report r;
        const int npt = m->inter_npt[i];
        double *gp = g + rc_root_point_base(m) + m->inter_pbase[i];
        double *gl = g + rc_root_land_base(m) + m->inter_pbase[i];
        for (int j = 0; j < npt; j++) {
            gp[j] = 1.0;  /* inactive point roots */
            gl[j] = -1.0; /* no landing while the contact is not closed */
            d->sc->pt_share[m->inter_pbase[i] + j] = 0.0;
        }
        if (npt > 0 && mode == RC_MODE_CLOSED) {
            /* friction per contact point: each point's slip root, and its
             * depth below the level of the shares (rising through 0: the
             * point lands, events.c) */
            double *pout = d->sc->pt_work; /* RC_PT_OUT npt values (rc_data_new) */
            t6out_r o;
            type6_r(m, i, mode, br, trk, d->inter_slip[i], d->pt_slip + m->inter_pbase[i],
                    rc_body_state(m, m->inter_ba[i], y), rc_body_state(m, m->inter_bb[i], y), y + m->inter_eadr[i],
                    NULL, NULL, NULL, &o, pout, d->sc->node_cache, NULL);
            for (int j = 0; j < npt; j++) {
                gp[j] = pout[RC_PT_OUT * j];
                if (m->inter_fr[i].form == RC_FF_INCREMENTAL)
                    gl[j] = pout[RC_PT_OUT * j + 5] + d->pt_lband[m->inter_pbase[i] + j];
                d->sc->pt_share[m->inter_pbase[i] + j] = pout[RC_PT_OUT * j + 4];
            }
            report_of(&o, &r); /* the same evaluation as rc_inter_report_eval_d */
            if (rc) {
                keep(rc, d, i, &r);
                memcpy(rc->pslip + m->inter_pbase[i], d->pt_slip + m->inter_pbase[i], (size_t)npt * sizeof(int));
                kept = 1;
            }
        } else if (is_fast(m, i)) {
            /* only what the roots below read of such an interface: P, the
             * approach rate, and the force when not open. Its report is not
             * kept: the sampler evaluates afresh the few interfaces whose
             * impact is in progress, which costs less than a full report of
             * every interface at every root evaluation */
            t6out_r o;
            t6fast(m, i, mode, br, trk, rc_body_state(m, m->inter_ba[i], y), rc_body_state(m, m->inter_bb[i], y),
                   y + m->inter_eadr[i], NULL, NULL, NULL, &o, mode != RC_MODE_OPEN ? T6F_LAW : 0);
            report_normal_of(&o, &r);
            r.slip_root = 1.0;
            for (int k = 0; k < 3; k++) r.vt[k] = 0.0;
        } else {
            rc_inter_report_eval_d(m, d, i, t, y, &r);
            if (rc && npt == 0) {
                keep(rc, d, i, &r);
                kept = 1;
            }
        }
        /* friction: stick -> slip at the limit, slip -> stick when sliding stops */
        if (mode == RC_MODE_CLOSED && m->inter_fr[i].kind != RC_FK_NONE) gi[RC_ROOT_SLIP] = r.slip_root;
        if (mode == RC_MODE_CLOSED && d->inter_slip[i] && npt == 0 && m->inter_fr[i].kind != RC_FK_NONE &&
            m->inter_fr[i].form == RC_FF_INCREMENTAL && m->inter_fr[i].tidx >= 0 && isfinite(r.flim) &&
            isfinite(r.vslip)) {
            d->sc->inter_flim[2 * i] = r.flim;
            d->sc->inter_flim[2 * i + 1] = r.vslip;
        }
        /* saturated stateless law: its force -L v_t/|v_t| flips when the sliding
         * reverses; the saturation root dips below zero only in a velocity window
         * of width ~L/C that a step may jump, so watch v_t . d_ref as well;
         * not on a zero limit, where the saturated force is zero whatever
         * the direction (two balls touching at zero force, sliding at the
         * velocities' rounding: 200 reversals within 1e-10 s), and the root
         * crosses when the limit rises from zero, the mode then set anew */
        if (mode == RC_MODE_CLOSED && d->inter_slip[i] && m->inter_fr[i].form == RC_FF_VISCOUS &&
            m->inter_fr[i].kind != RC_FK_NONE) {
            const double *dr = d->inter_dref + 3 * i;
            gi[RC_ROOT_REV] = r.flim > 0 ? r.vt[0] * dr[0] + r.vt[1] * dr[1] + r.vt[2] * dr[2] : 1.0;
        }
        /* zone: P (not while the Inacti offset tracks it, P = 0 there) */
        /* the touch bands (events.c, signed: a contact left at zero waits
         * a band away on the side of its next crossing) */
        if (!trk) gi[RC_ROOT_ZONE] = r.p + d->inter_band[2 * i];
        if (mode == RC_MODE_CLOSED && r.fn > 0) d->sc->inter_fnr[i] = r.fn; /* the interface sensors' */
        /* total normal force, unclipped: release and re-close */
        if (mode != RC_MODE_OPEN) gi[RC_ROOT_FORCE] = r.fn + d->inter_band[2 * i + 1];
        /* a settled contact is not released at zero force: it opens with P */
        if (mode == RC_MODE_CLOSED && d->inter_settled[i]) gi[RC_ROOT_FORCE] = 1.0;
        /* hysteresis: reversal on the curves, bounds on the Stiff line */
        /* power law with RDF: the rate of P (approach / rebound) */
        if (mode != RC_MODE_OPEN && m->inter_law[i] == RC_LAW_POWER && rc_pw_rdf_acts(&m->inter_pw[i]))
            gi[RC_ROOT_HYST_A] = r.vd + d->inter_rband[i]; /* the damping's own rate */
        if (mode != RC_MODE_OPEN && m->inter_iform[i] != 0) {
            if (br == RC_BR_ELASTIC) {
                /* F_h starts on the curve it left (F_L at a reversal, F_U
                 * at a re-loading): the roots wait past it by the accuracy
                 * of F_h and of the curves at P (inter_hband) and a
                 * thousand roundings of the forces, so that the error of a
                 * line leaving the curve is not a crossing (a reversal put
                 * back on the load curve unloaded along it, 1.4e-5 J drawn
                 * from the hysteresis ledger) */
                const double hb = m->inter_hband[i] + RC_TOUCH_ULPS * DBL_EPSILON * (fabs(r.fl) + fabs(r.fh) + fabs(r.fu));
                gi[RC_ROOT_HYST_A] = r.fl - r.fh + hb;
                gi[RC_ROOT_HYST_B] = r.fh - r.fu + hb;
            } else {
                gi[RC_ROOT_HYST_A] = r.vl + d->inter_rband[i]; /* the law's rate (its band: events.c) */
            }
        }
        /* Inacti 5: tracking stops when P_raw turns, or the offset is used up */
        if (trk) {
            gi[RC_ROOT_TRK_A] = r.vn_raw;
            gi[RC_ROOT_TRK_B] = r.offset;
        }
    }
    /* the state of the reports kept (none kept: none to compare) */
    if (d->sc->repc) {
        d->sc->repc->ok = kept;
        if (kept) memcpy(d->sc->repc->y, y, (size_t)m->ny * sizeof(double));
    }
    /* contact couplings: after the interfaces' roots (below) */
    if (rc_cpl_nroots(m) > 0) rc_cpl_roots(m, d, t, y, g + rc_root_cpl_base(m));
    /* distance sensors: last */
    if (m->nsens > 0) rc_sens_roots(m, d, t, y, g + rc_root_sens_base(m));
}

/* Which of an interface's root functions can change sign in a run from
 * t = 0 to tend, from its static configuration alone (what
 * rc_assemble_roots above writes in each case); the others stay at a
 * constant value or keep one sign, and the integrator is not given them
 * (solver/rootmap.c). In doubt a root is live. */
static int inter_root_live(const rc_model *m, int i, int k, double tend)
{
    const rc_fric *fr = &m->inter_fr[i];
    switch (k) {
    case RC_ROOT_TSTART: /* t - Tstart >= 0 from t = 0 on; < 0 up to tend; a distance sensor's: live */
        return m->inter_sens[i] >= 0 || (m->inter_tstart[i] > 0.0 && m->inter_tstart[i] <= tend);
    case RC_ROOT_TSTOP: /* t - Tstop < 0 up to tend (the stop time of the run) */
        return m->inter_tstop[i] <= tend;
    case RC_ROOT_HYST_A: /* the curves' bounds, or the rate of P: power law with RDF */
        return m->inter_iform[i] != 0 || (m->inter_law[i] == RC_LAW_POWER && rc_pw_rdf_acts(&m->inter_pw[i]));
    case RC_ROOT_HYST_B: /* the Stiff line's upper bound */
        return m->inter_iform[i] != 0;
    case RC_ROOT_TRK_A:
    case RC_ROOT_TRK_B: /* Inacti 5 tracking needs the offset state */
        return m->inter_oidx[i] >= 0;
    case RC_ROOT_SLIP: /* friction; exact stick writes it too (engine/constraints/stick.c) */
        return fr->kind != RC_FK_NONE || fr->exact;
    case RC_ROOT_REV: /* a saturated stateless (viscous) friction law */
        return fr->kind != RC_FK_NONE && fr->form == RC_FF_VISCOUS;
    default: /* zone, normal force */
        return 1;
    }
}

int rc_roots_live(const rc_model *m, double tend, int *live)
{
    const int nr = rc_root_count(m), base = rc_root_point_base(m), sbase = rc_root_sens_base(m);
    int n = 0;
    for (int k = 0; k < nr; k++) {
        const int on = k >= sbase ? rc_sens_root_live(m, k - sbase)
                       : k >= base ? 1
                                   : inter_root_live(m, k / RC_ROOTS_PER_INTER, k % RC_ROOTS_PER_INTER, tend);
        if (on && live) live[n] = k;
        n += on;
    }
    return n;
}

/* ---- couplings ------------------------------------------------------ */
/*
 * Coupling drivers in real arithmetic: right-hand side and reports.
 * (After kernels_coupling.inc and acc_slot.) Pure like the rest of the right-hand side, except for the
 * catenary warm starts in d->cpl, which change only the starting point of
 * the solver, not its converged result.
 */

int rc_cpl_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot)
{
    const rc_couplings *c = m->cpl;
    d->cpl->fail = -1;
    for (int k = 0; k < c->n; k++) {
        double *edot = ydot + c->eadr[k];
        const int b1 = c->b1[k], b2 = c->b2[k];
        const double *y1 = rc_body_state(m, b1, y), *y2 = rc_body_state(m, b2, y);
        double *a1 = acc_slot(m, b1, ydot), *a2 = acc_slot(m, b2, ydot);
        int bad = 0;
        if (c->kind[k] == RC_CPL_SPRING && c->grup[k] >= 0 && d->cpl->lmode[k] == RC_SPR_BROKEN) {
            edot[0] = edot[1] = 0.0; /* a broken spring: no force */
        } else if (c->kind[k] == RC_CPL_SPRING) {
            spring_r(m, k, y1, y2, a1, a2, edot, NULL);
        } else if (c->kind[k] == RC_CPL_CONTACT) {
            contact_cpl_r(m, k, d->cpl->fmode, 0, y1, y2, a1, a2, edot, NULL);
        } else if (c->kind[k] == RC_CPL_LIMIT) {
            jlimit_r(m, k, d->cpl->lmode[k], y1, y2, a1, a2, edot, NULL, NULL, NULL, NULL, NULL);
        } else {
            double eup[3];
            rc_cat_sol s;
            bad = cat_solve_at_r(m, d, k, t, y, eup, &s);
            if (!bad) catenary_r(m, k, eup, &s, y1, y2, a1, a2, edot, NULL, NULL);
        }
        if (bad || !isfinite(edot[0]) || !isfinite(edot[1])) {
            d->cpl->fail = k;
            d->sc->fail_t = t;
            return 1; /* recoverable: CVODE retries with a smaller step */
        }
    }
    return 0;
}

static int contact_report(const rc_model *m, const rc_data *d, int k, const double *y, rc_cpl_report *r);

int rc_cpl_report_eval(const rc_model *m, const rc_data *d, int k, double t, const double *y,
                       rc_cpl_report *r)
{
    const rc_couplings *c = m->cpl;
    const double *y1 = rc_body_state(m, c->b1[k], y), *y2 = rc_body_state(m, c->b2[k], y);
    if (c->kind[k] == RC_CPL_SPRING) {
        spring_r(m, k, y1, y2, NULL, NULL, NULL, r);
        r->lowest = NAN;
        if (d && c->grup[k] >= 0 && d->cpl->lmode[k] == RC_SPR_BROKEN) { /* broken: no force */
            r->force = 0.0;
            for (int i = 0; i < 3; i++) r->f1[i] = r->f2[i] = 0.0;
        }
        return !isfinite(r->force);
    }
    if (c->kind[k] == RC_CPL_CONTACT) return contact_report(m, d, k, y, r);
    if (c->kind[k] == RC_CPL_LIMIT) {
        /* the joint coordinate as the length, the generalised force */
        double fa[6];
        memset(r, 0, sizeof *r);
        jlimit_r(m, k, d ? d->cpl->lmode[k] : RC_LIM_FREE, y1, y2, NULL, NULL, NULL, &r->force, &r->length, &r->rate,
                 NULL, fa);
        for (int i = 0; i < 3; i++) {
            r->f1[i] = fa[i];
            r->f2[i] = fa[3 + i];
        }
        r->lowest = NAN;
        return !isfinite(r->force);
    }
    /* catenary: solve, end forces, parameters, lowest point */
    double eup[3], X, Y, h[3], p1[3], v1[3], p2[3], v2[3];
    rc_cat_sol s;
    memset(r, 0, sizeof *r);
    if (cat_solve_at_r(m, d, k, t, y, eup, &s)) {
        r->force = r->length = r->c = r->u1 = r->u2 = r->lowest = NAN;
        for (int i = 0; i < 3; i++) r->f1[i] = r->f2[i] = NAN;
        return 1;
    }
    catenary_r(m, k, eup, &s, y1, y2, NULL, NULL, NULL, r->f1, r->f2);
    cat_span_r(m, k, eup, y1, y2, &X, &Y, h, p1, v1, p2, v2);
    double del[3] = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
    double vdel[3] = {v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2]};
    r->length = sqrt(dot_r(del, del));
    r->rate = dot_r(del, vdel) / r->length;
    r->force = sqrt(dot_r(r->f1, r->f1));
    r->c = s.H;
    r->u1 = asinh(s.V1 / s.H);
    r->u2 = asinh(s.V2 / s.H);
    /* lowest point: end 1 when the line rises from it, end 2 when it falls
     * to it, else the vertex, (T1 - H)/w + V1^2/(2 w EA) below end 1 */
    const double z1 = dot_r(p1, eup) + dot_r(m->origin, eup), T1 = hypot(s.H, s.V1); /* the deck's heights */
    if (s.V1 >= 0) r->lowest = z1;
    else if (s.V2 <= 0) r->lowest = z1 + Y;
    else r->lowest = z1 - s.V1 * s.V1 * (1.0 / (T1 + s.H) + 0.5 / c->ea[k]) / s.w;
    return 0;
}

double rc_cpl_joint_stop(const rc_model *m, const rc_data *d, int j, const double *y, double *q)
{
    const rc_couplings *c = m->cpl;
    *q = NAN;
    for (int k = c->ncard; k < c->n; k++) {
        if (c->ljoint[k] != j) continue;
        double Q;
        jlimit_r(m, k, d->cpl->lmode[k], rc_body_state(m, c->b1[k], y), rc_body_state(m, c->b2[k], y), NULL, NULL,
                 NULL, &Q, q, NULL, NULL, NULL);
        return Q;
    }
    return 0.0;
}

/* ---- contact couplings: face modes, roots and events; joint stops ---- */
/*
 * Contact coupling face modes, roots and events (model/coupling_contact.h),
 * in real arithmetic.
 *
 * Face f has two root functions: g[2f] = d - d0 (entering the effective
 * range, falling; leaving it, rising) and g[2f + 1] = the unclipped normal
 * force a_f (k1 (d0 - d) - k2 dd/dt) while in range (released when it
 * falls through zero, pushing again when it rises), 1 out of range.
 */

/* Unclipped normal force of face f at the real state [N], its distance. */
static double cface_force(const rc_model *m, int k, int f, const double *y1, const double *y2, double *dist)
{
    const rc_cpl_contact *ct = m->cpl->ct;
    double x[3], d, dd, n[3], vt[3];
    cface_r(m, k, f, y1, y2, x, &d, &dd, n, vt);
    *dist = d;
    return ct->face[RC_FACE_NV * f + 6] * (ct->k1[k] * (ct->d0[k] - d) - ct->k2[k] * dd);
}

/* The mode a face takes from the state: out of range, pushing, or in range
 * with a force that would pull (released). */
static int cface_mode(const rc_model *m, int k, int f, const double *y1, const double *y2)
{
    const rc_cpl_contact *ct = m->cpl->ct;
    double x[3], d, dd, n[3], vt[3];
    cface_r(m, k, f, y1, y2, x, &d, &dd, n, vt);
    const double d0 = ct->d0[k], fn = ct->face[RC_FACE_NV * f + 6] * (ct->k1[k] * (d0 - d) - ct->k2[k] * dd);
    /* a face exactly at d0 (to rounding) that approaches is entering: its
     * root is zero here and would not be seen to cross */
    const int at_d0 = fabs(d - d0) <= 1.5e-14 * (fabs(d0) + fabs(x[0]) + fabs(x[1]) + fabs(x[2])); /* 64 ulps */
    if (!(d < d0) && !(at_d0 && dd < 0)) return RC_FACE_OUT;
    return fn > 0 || dd < 0 ? RC_FACE_PUSH : RC_FACE_RELEASED;
}

static void cface_modes(const rc_model *m, int k, const double *y, int *modes)
{
    const rc_couplings *c = m->cpl;
    const double *y1 = rc_body_state(m, c->b1[k], y), *y2 = rc_body_state(m, c->b2[k], y);
    for (int f = c->ct->fadr[k]; f < c->ct->fadr[k + 1]; f++) modes[f] = cface_mode(m, k, f, y1, y2);
}

static int contact_report(const rc_model *m, const rc_data *d, int k, const double *y, rc_cpl_report *r)
{
    const rc_couplings *c = m->cpl;
    const double *y1 = rc_body_state(m, c->b1[k], y), *y2 = rc_body_state(m, c->b2[k], y);
    contact_cpl_r(m, k, d ? d->cpl->fmode : NULL, !d, y1, y2, NULL, NULL, NULL, r);
    return !isfinite(r->force);
}

/* ---- joint stops (after the faces' roots: RC_LIM_ROOTS per stop coupling) */
static int lim_root0(const rc_model *m, int k)
{
    return RC_FACE_ROOTS * m->cpl->ct->nface + RC_LIM_ROOTS * (k - m->cpl->ncard);
}

/* q, dq/dt and the unclipped force F of stop coupling k past the stop of
 * `mode` at the real state. */
static void lim_eval(const rc_model *m, int k, int mode, const double *y, double *q, double *qd, double *F)
{
    const rc_couplings *c = m->cpl;
    double Q;
    jlimit_r(m, k, mode, rc_body_state(m, c->b1[k], y), rc_body_state(m, c->b2[k], y), NULL, NULL, NULL, &Q, q, qd,
             F, NULL);
}

/* The mode a stop takes from the state: past a stop (or on it and moving
 * past it), pushing when its force is positive or the coordinate moves on
 * past it, released otherwise. */
static int lim_mode(const rc_model *m, int k, const double *y)
{
    const rc_couplings *c = m->cpl;
    double q, qd, F;
    lim_eval(m, k, RC_LIM_FREE, y, &q, &qd, &F);
    const double tiny = 1.5e-14 * (1.0 + fabs(q)); /* on the stop to rounding */
    if (q < c->llo[k] || (q - c->llo[k] <= tiny && qd < 0)) {
        lim_eval(m, k, RC_LIM_LO_PUSH, y, &q, &qd, &F);
        return F > 0 || qd < 0 ? RC_LIM_LO_PUSH : RC_LIM_LO_REL;
    }
    if (q > c->lhi[k] || (c->lhi[k] - q <= tiny && qd > 0)) {
        lim_eval(m, k, RC_LIM_HI_PUSH, y, &q, &qd, &F);
        return F > 0 || qd > 0 ? RC_LIM_HI_PUSH : RC_LIM_HI_REL;
    }
    return RC_LIM_FREE;
}

static void lim_roots(const rc_model *m, const rc_data *d, const double *y, double *g)
{
    const rc_couplings *c = m->cpl;
    for (int k = c->ncard; k < c->n; k++) {
        double *gk = g + lim_root0(m, k), q, qd, F;
        const int mode = d->cpl->lmode[k];
        lim_eval(m, k, mode, y, &q, &qd, &F);
        gk[0] = isfinite(c->llo[k]) ? q - c->llo[k] : 1.0;
        gk[1] = isfinite(c->lhi[k]) ? c->lhi[k] - q : 1.0;
        gk[2] = mode == RC_LIM_FREE ? 1.0 : F;
    }
}

static void lim_root_dirs(const rc_model *m, const rc_data *d, int *dir)
{
    const rc_couplings *c = m->cpl;
    for (int k = c->ncard; k < c->n; k++) {
        int *r = dir + lim_root0(m, k);
        const int mode = d->cpl->lmode[k];
        const int lo = mode == RC_LIM_LO_PUSH || mode == RC_LIM_LO_REL;
        const int hi = mode == RC_LIM_HI_PUSH || mode == RC_LIM_HI_REL;
        r[0] = lo ? 1 : -1; /* leave / reach the lower stop */
        r[1] = hi ? 1 : -1; /* leave / reach the upper stop */
        r[2] = mode == RC_LIM_LO_PUSH || mode == RC_LIM_HI_PUSH ? -1 : 1; /* release / push again */
    }
}

static int lim_events(const rc_model *m, rc_data *d, const double *y, const int *roots, rc_event_kind *kinds,
                      int *cpls, int max_ev, int *restart, int n)
{
    static const rc_event_kind names[4] = {RC_EV_STOP_ENTER, RC_EV_STOP_LEAVE, RC_EV_STOP_RELEASE, RC_EV_STOP_CLOSE};
    const rc_couplings *c = m->cpl;
    for (int k = c->ncard; k < c->n; k++) {
        const int *r = roots + lim_root0(m, k);
        int *mode = d->cpl->lmode + k, kind = -1;
        const int lo = *mode == RC_LIM_LO_PUSH || *mode == RC_LIM_LO_REL;
        const int hi = *mode == RC_LIM_HI_PUSH || *mode == RC_LIM_HI_REL;
        if (*mode == RC_LIM_FREE && (r[0] != 0 || r[1] != 0)) {
            /* reaching a stop: pushing when the force is positive or the
             * coordinate moves on past it (the elastic part grows from 0) */
            double q, qd, F;
            const int lower = r[0] != 0;
            lim_eval(m, k, lower ? RC_LIM_LO_PUSH : RC_LIM_HI_PUSH, y, &q, &qd, &F);
            const int on = lower ? qd < 0 : qd > 0;
            *mode = lower ? (F > 0 || on ? RC_LIM_LO_PUSH : RC_LIM_LO_REL) : (F > 0 || on ? RC_LIM_HI_PUSH : RC_LIM_HI_REL);
            kind = 0;
        } else if ((lo && r[0] != 0) || (hi && r[1] != 0)) {
            *mode = RC_LIM_FREE;
            kind = 1;
        } else if ((*mode == RC_LIM_LO_PUSH || *mode == RC_LIM_HI_PUSH) && r[2] != 0) {
            *mode = *mode == RC_LIM_LO_PUSH ? RC_LIM_LO_REL : RC_LIM_HI_REL;
            kind = 2;
        } else if ((*mode == RC_LIM_LO_REL || *mode == RC_LIM_HI_REL) && r[2] != 0) {
            *mode = *mode == RC_LIM_LO_REL ? RC_LIM_LO_PUSH : RC_LIM_HI_PUSH;
            kind = 3;
        }
        if (kind < 0) continue;
        *restart = 1;
        if (n < max_ev) {
            kinds[n] = names[kind];
            cpls[n] = k;
        }
        n++;
    }
    return n;
}

/* ---- spring ruptures (after the joint stops' roots: one per spring with
 * rupture deformations, docs/theory.md 8.1) ---- */
static int rup_root0(const rc_model *m)
{
    return RC_FACE_ROOTS * m->cpl->ct->nface + RC_LIM_ROOTS * rc_cpl_nlim(m);
}

/* The least distance of spring k's deformations to their rupture bounds
 * (relative to each bound): > 0 whole, reaching 0 at the rupture. */
static double rup_margin(const rc_model *m, int k, const double *y)
{
    const rc_couplings *c = m->cpl;
    rc_cpl_report r;
    spring_r(m, k, rc_body_state(m, c->b1[k], y), rc_body_state(m, c->b2[k], y), NULL, NULL, NULL, &r);
    double g = 1.0;
    for (int i = 0; i < 6; i++) {
        const double lo = c->gdlo[6 * k + i], hi = c->gdhi[6 * k + i];
        if (isfinite(lo)) g = fmin(g, 1.0 - r.def[i] / lo);
        if (isfinite(hi)) g = fmin(g, 1.0 - r.def[i] / hi);
    }
    return g;
}

static void rup_roots(const rc_model *m, const rc_data *d, const double *y, double *g)
{
    const rc_couplings *c = m->cpl;
    if (!c->nrup) return;
    double *g0 = g + rup_root0(m);
    for (int k = 0; k < c->n; k++)
        if (c->grup[k] >= 0) g0[c->grup[k]] = d->cpl->lmode[k] == RC_SPR_BROKEN ? 1.0 : rup_margin(m, k, y);
}

static int rup_events(const rc_model *m, rc_data *d, const int *roots, rc_event_kind *kinds, int *cpls, int max_ev,
                      int *restart, int n)
{
    const rc_couplings *c = m->cpl;
    for (int k = 0; c->nrup && k < c->n; k++) {
        if (c->grup[k] < 0 || d->cpl->lmode[k] == RC_SPR_BROKEN || roots[rup_root0(m) + c->grup[k]] == 0) continue;
        d->cpl->lmode[k] = RC_SPR_BROKEN;
        *restart = 1;
        if (n < max_ev) {
            kinds[n] = RC_EV_SPRING_RUPTURE;
            cpls[n] = k;
        }
        n++;
    }
    return n;
}

void rc_cpl_roots(const rc_model *m, const rc_data *d, double t, const double *y, double *g)
{
    (void)t;
    const rc_couplings *c = m->cpl;
    for (int k = 0; k < c->n; k++) {
        if (c->kind[k] != RC_CPL_CONTACT) continue;
        const double *y1 = rc_body_state(m, c->b1[k], y), *y2 = rc_body_state(m, c->b2[k], y);
        for (int f = c->ct->fadr[k]; f < c->ct->fadr[k + 1]; f++) {
            double dist;
            const double fn = cface_force(m, k, f, y1, y2, &dist);
            g[RC_FACE_ROOTS * f] = dist - c->ct->d0[k];
            g[RC_FACE_ROOTS * f + 1] = d->cpl->fmode[f] == RC_FACE_OUT ? 1.0 : fn;
        }
    }
    lim_roots(m, d, y, g);
    rup_roots(m, d, y, g);
}

void rc_cpl_root_dirs(const rc_model *m, const rc_data *d, int *dir)
{
    const rc_cpl_contact *ct = m->cpl->ct;
    for (int f = 0; f < ct->nface; f++) {
        const int mode = d->cpl->fmode[f];
        dir[RC_FACE_ROOTS * f] = mode == RC_FACE_OUT ? -1 : 1;
        dir[RC_FACE_ROOTS * f + 1] = mode == RC_FACE_PUSH ? -1 : 1;
    }
    lim_root_dirs(m, d, dir);
    const rc_couplings *c = m->cpl;
    for (int k = 0; c->nrup && k < c->n; k++) /* a rupture: the margin falling through 0, once */
        if (c->grup[k] >= 0) dir[rup_root0(m) + c->grup[k]] = d->cpl->lmode[k] == RC_SPR_BROKEN ? 0 : -1;
}

void rc_cpl_modes_init(const rc_model *m, rc_data *d, double t, const double *y)
{
    (void)t;
    const rc_couplings *c = m->cpl;
    for (int k = 0; k < c->n; k++)
        if (c->kind[k] == RC_CPL_CONTACT) cface_modes(m, k, y, d->cpl->fmode);
        else if (c->kind[k] == RC_CPL_LIMIT) d->cpl->lmode[k] = lim_mode(m, k, y);
        else if (c->grup[k] >= 0) /* whole, unless a preload left it past a bound */
            d->cpl->lmode[k] = rup_margin(m, k, y) <= 0 ? RC_SPR_BROKEN : 0;
}

int rc_cpl_events(const rc_model *m, rc_data *d, double t, const double *y, const int *roots, rc_event_kind *kinds,
                  int *cpls, int max_ev, int *restart)
{
    (void)t;
    static const rc_event_kind names[4] = {RC_EV_CPL_CONTACT_ENTER, RC_EV_CPL_CONTACT_LEAVE,
                                           RC_EV_CPL_CONTACT_RELEASE, RC_EV_CPL_CONTACT_CLOSE};
    const rc_couplings *c = m->cpl;
    int n = 0;
    for (int k = 0; k < c->n; k++) {
        if (c->kind[k] != RC_CPL_CONTACT) continue;
        const double *y1 = rc_body_state(m, c->b1[k], y), *y2 = rc_body_state(m, c->b2[k], y);
        int seen[4] = {0, 0, 0, 0};
        for (int f = c->ct->fadr[k]; f < c->ct->fadr[k + 1]; f++) {
            const int *r = roots + RC_FACE_ROOTS * f;
            int *mode = d->cpl->fmode + f, kind = -1;
            if (*mode == RC_FACE_OUT && r[0] != 0) {
                /* entering at d = d0: pushing when the force is positive or
                 * the face approaches (the elastic part grows from zero) */
                double x[3], dist, dd, nn[3], vt[3];
                cface_r(m, k, f, y1, y2, x, &dist, &dd, nn, vt);
                const double fn = c->ct->face[RC_FACE_NV * f + 6] * (c->ct->k1[k] * (c->ct->d0[k] - dist) - c->ct->k2[k] * dd);
                *mode = fn > 0 || dd < 0 ? RC_FACE_PUSH : RC_FACE_RELEASED;
                kind = 0;
            } else if (*mode != RC_FACE_OUT && r[0] != 0) {
                *mode = RC_FACE_OUT;
                kind = 1;
            } else if (*mode == RC_FACE_PUSH && r[1] != 0) {
                *mode = RC_FACE_RELEASED;
                kind = 2;
            } else if (*mode == RC_FACE_RELEASED && r[1] != 0) {
                *mode = RC_FACE_PUSH;
                kind = 3;
            }
            if (kind < 0) continue;
            *restart = 1;
            if (seen[kind]++) continue;
            if (n < max_ev) {
                kinds[n] = names[kind];
                cpls[n] = k;
            }
            n++;
        }
    }
    n = lim_events(m, d, y, roots, kinds, cpls, max_ev, restart, n);
    return rup_events(m, d, roots, kinds, cpls, max_ev, restart, n);
}
