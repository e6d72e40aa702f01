/*
 * Analytic Jacobian by complex-step differentiation of the element kernels
 * (kernels.inc compiled with T = double complex): column j of an element's
 * block is Im(f(y + i h e_j)) / h, exact to rounding for any h because no
 * difference is taken (docs/design.md). Values go into the fixed CSC pattern
 * through each element's slot table.
 */
#include <complex.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/model.h"
#include "engine/assembly/assembly.h"
#include "engine/kernels/cstep.h"

#include "engine/kernels/as_complex.h"
#include "engine/kernels/kernels.inc"
#include "engine/kernels/kernels_coupling.inc"

/* Complex copy of a body's 13 states (ground/fixed pose when b has none). */
static void load_body(const rc_model *m, int b, const double *y, T *yc)
{
    rc_cs_load(rc_body_state(m, b, y), RC_NB, yc);
}

/* Dense 13 x 13 block of body b: d(ydot_b)/d(y_b); the columns of the
 * states in skip (NULL: none) are left 0. */
static void dense_body(const rc_model *m, int b, double t, const double *y, double *out, const char *skip)
{
    T yc[RC_NB], yd[RC_NB];
    load_body(m, b, y, yc);
    const double gf = rc_gravity_factor(m, t); /* gravity does not vary with y: either limit */
    for (int c = 0; c < RC_NB; c++) {
        if (skip && skip[m->body_yadr[b] + c]) {
            for (int r = 0; r < RC_NB; r++) out[r * RC_NB + c] = 0.0;
            continue;
        }
        rc_cs_step(&yc[c]);
        body_rhs_c(m, b, gf, yc, yd);
        for (int r = 0; r < RC_NB; r++) out[r * RC_NB + c] = rc_cs_deriv(yd[r]);
        rc_cs_unstep(&yc[c]);
    }
}

/* The contact points of node pair i that a complex-step column computes
 * (seg_fill's `only`): every kernel decides on real parts, which the step
 * leaves as they are, so a point out of the contact at the unperturbed
 * state (q_j = Gap - d_j - offset - c <= 0, c the shares' offset: no share,
 * no force, no power, its states relaxing on their own) stays out in every
 * column and contributes nothing there; only the real parts of its cache
 * entry, filled here, are read (for the deepest point's choice). The
 * deepest point (P and c move with it) and the points tied with it are
 * computed in every column, and so is every point within a margin of the
 * contact (rounding of the real parts under the step, 1e-80 relative, is
 * far inside it). Fills the cache nc at (ya, yb) and only[]; returns only,
 * or NULL where the interface has no node points. Most of a box pair's 240
 * points (corners against faces, edge pairs) and of a meshed surface's
 * nodes are out of the contact at any time: a Jacobian of a stack of
 * boxes took 26 evaluations of every one of them. */
static const unsigned char *point_mask(const rc_model *m, int i, const T *ya, const T *yb, const T *ys, T *nc,
                                       unsigned char *only)
{
    if (!nc || !rc_pair_nodes(m->inter_pair[i])) return NULL;
    seg_fill_c(m, i, ya, yb, nc, NULL);
    const int nn = rc_seg_points(m, i), oi = m->inter_oidx[i];
    const double gap = m->inter_gap[i], off = oi >= 0 ? creal(ys[oi]) : 0.0;
    double dmin = 0.0;
    for (int j = 0; j < nn; j++) {
        const double d = creal(nc[RC_NC * j]);
        if (j == 0 || d < dmin) dmin = d;
    }
    const double c = creal(share_c_c(m, i, gap - dmin - off));
    for (int j = 0; j < nn; j++) {
        const double d = creal(nc[RC_NC * j]);
        const double marg = 1e-9 * (fabs(gap) + fabs(d) + fabs(off) + fabs(c) + fabs(dmin)) + 1e-30;
        /* NaN: computed (whatever the kernels make of it) */
        only[j] = (unsigned char)!(gap - d - off - c < -marg && d > dmin + marg);
    }
    return only;
}

/* Dense block of interface i in the given modes: rows = accelerations of a
 * (if free), of b (if free), own states; columns = states of a, of b, own.
 * Contact points with friction (inter_npt): their states are read from y,
 * modes pslip (NULL: all `slip`); work: complex scratch of 2 (RC_NS_MAX +
 * inter_pst npt) values; ptslot (NULL: not wanted): the point-state rows of the
 * same columns are added into val through it (inter_ptslot); ncache, nonly:
 * the node cache and point_mask's scratch (NULL: every point computed where
 * needed, in every column); the columns of the states in skip (NULL: none)
 * are left 0. */
static void dense_inter(const rc_model *m, int i, int mode, int branch, int track, int slip, const int *pslip,
                        const double *y, double *out, T *work, const int64_t *ptslot, double *val, T *ncache,
                        unsigned char *nonly, const char *skip)
{
    const rc_jblock *jb = &m->jb_inter[i];
    const int ba = m->inter_ba[i], bb = m->inter_bb[i], ns = m->inter_ns[i], ps = m->inter_pst[i];
    const int np3 = ps * m->inter_npt[i];
    const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
    const int na = fa ? RC_NB : 0, nb = fb ? RC_NB : 0;
    const int64_t P = (int64_t)ps * jb->ncol + (int64_t)ps * jb->nrow + ps * ps;
    T ya[RC_NB], yb[RC_NB], ysl[RC_NS_MAX], sdl[RC_NS_MAX];
    T *ys = np3 > 0 ? work : ysl, *sdot = np3 > 0 ? work + RC_NS_MAX + np3 : sdl;
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    rc_cs_load(y + m->inter_eadr[i], ns + np3, ys);
    const unsigned char *only = point_mask(m, i, ya, yb, ys, ncache, nonly);
    for (int c = 0; c < jb->ncol; c++) {
        if (skip && skip[jb->cols[c]]) {
            for (int r = 0; r < jb->nrow; r++) out[r * jb->ncol + c] = 0.0;
            continue;
        }
        T *yp = c < na ? ya + c : c < na + nb ? yb + (c - na) : ys + (c - na - nb);
        rc_cs_step(yp);
        T acc[12] = {0};
        type6_c(m, i, mode, branch, track, slip, pslip, ya, yb, ys, fa ? acc : NULL, fb ? acc + 6 : NULL, sdot, NULL,
                NULL, ncache, only);
        rc_cs_unstep(yp);
        int r = 0;
        if (fa)
            for (int k = 0; k < 6; k++, r++) out[r * jb->ncol + c] = rc_cs_deriv(acc[k]);
        if (fb)
            for (int k = 0; k < 6; k++, r++) out[r * jb->ncol + c] = rc_cs_deriv(acc[6 + k]);
        for (int k = 0; k < ns; k++, r++) out[r * jb->ncol + c] = rc_cs_deriv(sdot[k]);
        if (ptslot)
            for (int k = 0; k < np3; k++) {
                const int64_t sl = ptslot[(k / ps) * P + (k % ps) * jb->ncol + c];
                if (sl >= 0) val[sl] += rc_cs_deriv(sdot[ns + k]);
            }
    }
}

/* The geometry of a fast interface: sphere a (radius ra) against sphere
 * b (rb; ss) or the plane of surface sb, the centres the bodies' own
 * states (kernel_fast.inc's t6fast, in complex arithmetic). */
static inline void fast_geom(const rc_model *m, int ss, int sb, const T *ya, const T *yb, double ra, double rb,
                             geom_c *g)
{
    if (ss)
        geom_sph_sph_c(ya, ya + 7, ra, yb, yb + 7, rb, 0, 0, g);
    else
        geom_sph_plane_c(m, sb, ya, ya + 7, ra, yb, g);
}

/* Dense block of interface i on the fast contact path (rc_fast_eligible in
 * kernel_fast.inc: a centred sphere against a centred sphere or a plane,
 * TYPE6 Iform 0 or the power law, no friction, no offset, no contact
 * points), the same values as dense_inter to rounding at a fraction of the
 * cost (docs/design.md, "The fast contact path"). Only a closed contact
 * acts: its force is fn(p, vn) n through the sphere centres, with p = gap -
 * d and vn = -dd/dt (0 when tracking), and its own rates are fel vn and fd
 * vn. The law's partial derivatives (of fel and fd, by p and by vn) are
 * taken once, by one complex step of the law alone for each variable; each
 * column then takes one complex step of the geometry only (d, dd/dt, n) and
 * the chain rule. Columns nothing reads are
 * left 0: a centred sphere's orientation and angular velocity (its centre
 * and the centre's velocity are its body's own states) and the own states
 * (the work integrals; the law has no state). Writes only the positions
 * (row * ncol + column) it lists in pos (their number returned), 0 where
 * nothing acts; the rest of `out` is left as it is (the caller keeps it 0).
 * tests/test_fast.c compares the blocks with dense_inter's at random
 * states in every mode. */
static int fast_inter(const rc_model *m, int i, int mode, int branch, int track, const double *y, double *out,
                      const char *skip, int *pos)
{
    const rc_jblock *jb = &m->jb_inter[i];
    const int ncol = jb->ncol;
    const int ba = m->inter_ba[i], bb = m->inter_bb[i], ns = m->inter_ns[i];
    const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
    const int na = fa ? RC_NB : 0, nb = fb ? RC_NB : 0;
    const int ss = m->inter_pair[i] == RC_PAIR_SPHERE_SPHERE, sb = m->inter_sb[i];
    const int rs = (fa ? 6 : 0) + (fb ? 6 : 0); /* first own-state row */
    /* the positions written: rows a's force (3), b's force (3) or force
     * and moment (6, the plane's body), the own rates (ns <= 2 read); the
     * columns below */
    int rows[14], nr = 0, np = 0;
    if (fa)
        for (int e = 0; e < 3; e++) rows[nr++] = e;
    if (fb)
        for (int e = 0; e < (ss ? 3 : 6); e++) rows[nr++] = (fa ? 6 : 0) + e;
    for (int e = 0; e < ns && e < 2; e++) rows[nr++] = rs + e;
    int cols[2 * RC_NB], nc = 0;
    for (int c = 0; c < na + nb; c++) {
        const int onb = c >= na, k = onb ? c - na : c;
        /* a sphere's centre and its velocity; the plane's body: all */
        if ((onb && !ss) || k < 3 || (k >= 7 && k < 10)) cols[nc++] = c;
    }
    for (int a = 0; a < nr; a++)
        for (int c = 0; c < nc; c++) {
            pos[np] = rows[a] * ncol + cols[c];
            out[pos[np++]] = 0.0;
        }
    if (mode != RC_MODE_CLOSED) return np; /* no force, no work rates */
    const double ra = m->surf_r[m->inter_sa[i]], rb = ss ? m->surf_r[sb] : 0.0;
    T ya[RC_NB], yb[RC_NB];
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    geom_c g;
    fast_geom(m, ss, sb, ya, yb, ra, rb, &g);
    const double p0 = m->inter_gap[i] - creal(g.d), vn0 = track ? 0.0 : -creal(g.ddot);
    /* the law at (p0, vn0): fel, fd and their derivatives by p (k = 0) and
     * by vn (k = 1) */
    double fel0 = 0.0, fd0 = 0.0, dfel[2], dfd[2];
    for (int k = 0; k < 2; k++) {
        t6out_c r;
        memset(&r, 0, sizeof r);
        r.p = r.pl = rc_cs_seed(p0, k == 0); /* one point: the law at P */
        r.vn = r.vl = rc_cs_seed(vn0, k == 1);
        if (m->inter_law[i] == RC_LAW_POWER) {
            T kn;
            power_law_c(m, i, 1, branch, &r, &kn);
        } else {
            T kn, dfh, ys0[RC_NS_MAX] = {0};
            type6_law_c(m, i, mode, branch, ys0, &r, &kn, &dfh);
        }
        fel0 = creal(r.fel);
        fd0 = creal(r.fd);
        dfel[k] = rc_cs_deriv(r.fel);
        dfd[k] = rc_cs_deriv(r.fd);
    }
    const double ima = fa ? 1.0 / m->body_mass[ba] : 0.0, imb = fb ? 1.0 / m->body_mass[bb] : 0.0;
    for (int q = 0; q < nc; q++) {
        const int c = cols[q], onb = c >= na, k = onb ? c - na : c;
        if (skip && skip[jb->cols[c]]) continue;
        T *yp = onb ? yb + k : ya + k;
        rc_cs_step(yp);
        fast_geom(m, ss, sb, ya, yb, ra, rb, &g);
        const double dp = -rc_cs_deriv(g.d), dv = track ? 0.0 : -rc_cs_deriv(g.ddot);
        const double del = dfel[0] * dp + dfel[1] * dv, ddf = dfd[0] * dp + dfd[1] * dv;
        const T fn = rc_cs_seed(fel0 + fd0, del + ddf);
        T f[3];
        for (int e = 0; e < 3; e++) f[e] = fn * g.n[e];
        int r = 0;
        if (fa) {
            /* through a's centre: no moment (rows 3..5 stay 0) */
            for (int e = 0; e < 3; e++) out[(r + e) * ncol + c] = -rc_cs_deriv(f[e]) * ima;
            r += 6;
        }
        if (fb) {
            if (ss) {
                for (int e = 0; e < 3; e++) out[(r + e) * ncol + c] = rc_cs_deriv(f[e]) * imb;
            } else {
                /* the plane's body: the force at the sphere's centre */
                T acc[6] = {0};
                apply_force_c(m, bb, yb, f, g.act_b, acc);
                for (int e = 0; e < 6; e++) out[(r + e) * ncol + c] = rc_cs_deriv(acc[e]);
            }
        }
        rc_cs_unstep(yp);
        /* the work rates fel vn and fd vn */
        out[rs * ncol + c] = del * vn0 + fel0 * dv;
        if (ns > 1) out[(rs + 1) * ncol + c] = ddf * vn0 + fd0 * dv;
    }
    return np;
}

/* dense_inter, or fast_inter for an interface on the fast path. */
static void inter_block(const rc_model *m, const rc_data *d, int i, const double *y, double *out, const int64_t *ptslot,
                        double *val)
{
    if (m->inter_fast && m->inter_fast[i]) {
        int pos[RC_JB_MAX];
        memset(out, 0, (size_t)m->jb_inter[i].nrow * (size_t)m->jb_inter[i].ncol * sizeof(double));
        fast_inter(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], y, out, d->jac_skip, pos);
        return;
    }
    dense_inter(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i],
                d->pt_slip + m->inter_pbase[i], y, out, d->sc->pt_work, ptslot, val, d->sc->node_cache,
                d->sc->node_only, d->jac_skip);
}

/* A slot of `val` written by a refresh: not in a held row (those stay 0). */
static int live_slot(const rc_model *m, int64_t sl)
{
    return sl >= 0 && !(m->nheld > 0 && m->row_held[m->jac_rowind[sl]]);
}

/* Contact point j of interface i (closed, in mode `slip`, its state fj at
 * the evaluation), the columns of its own state: one complex step per
 * component, added into the values of its rows on the bodies (sb: the
 * point's accelerations of a then b, then W_fric at racc + widx) and of its
 * own rates (sc). only_live: not into held rows (a refresh: no assembly
 * clears them afterwards). */
static void point_columns(const rc_model *m, int i, const segctx_c *c, int j, int slip, const T *ya, const T *yb,
                          const T *po, const double *fj, const int64_t *sb, const int64_t *sc, int only_live,
                          double *val)
{
    const int ps = m->inter_pst[i], ba = m->inter_ba[i], bb = m->inter_bb[i];
    const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
    const int racc = (fa ? 6 : 0) + (fb ? 6 : 0), widx = m->inter_fr[i].widx;
#define PUT(sl, v) do { const int64_t s_ = (sl); if (only_live ? live_slot(m, s_) : s_ >= 0) val[s_] += (v); } while (0)
    T Fj[6];
    rc_cs_load(fj, ps, Fj);
    for (int k = 0; k < ps; k++) {
        rc_cs_step(&Fj[k]);
        segpt_c q;
        segfric_point_c(m, i, c, j, slip, ya, yb, Fj, po, &q);
        rc_cs_unstep(&Fj[k]);
        T acc[12] = {0}, fbv[3] = {-q.ft[0], -q.ft[1], -q.ft[2]};
        const int in = creal(q.w) > 0; /* out of the contact: no force, exactly (segfric_point) */
        if (fa && in) apply_force_c(m, ba, ya, q.ft, q.x, acc);
        if (fb && in) apply_force_c(m, bb, yb, fbv, q.x, acc + 6);
        int r = 0;
        for (int a = 0; a < 12; a++) {
            if ((a < 6 && !fa) || (a >= 6 && !fb)) continue;
            PUT(sb[r * ps + k], rc_cs_deriv(acc[a]));
            r++;
        }
        PUT(sb[(racc + widx) * ps + k], -rc_cs_deriv(dot_c(q.ft, q.vrel)));
        for (int e = 0; e < ps; e++) PUT(sc[e * ps + k], rc_cs_deriv(q.dF[e]));
    }
#undef PUT
}

/* Contact points with friction of interface i, closed: every row a point's
 * state moves (the accelerations, W_fric, its own rates) against that state,
 * into the values through inter_ptslot (jacpattern.c). A point's state moves
 * only its own force, so its columns take one evaluation of that point. */
static void points_jac(const rc_model *m, const rc_data *d, int i, const double *y, double *val)
{
    const rc_jblock *jb = &m->jb_inter[i];
    const int npt = m->inter_npt[i], ns = m->inter_ns[i], ncol = jb->ncol, nrow = jb->nrow, ps = m->inter_pst[i];
    const int64_t P = (int64_t)ps * ncol + (int64_t)ps * nrow + ps * ps, *slot = m->inter_ptslot[i];
    const int *pslip = d->pt_slip + m->inter_pbase[i];
    const int ba = m->inter_ba[i], bb = m->inter_bb[i];
    const rc_fric *fr = &m->inter_fr[i];
    T ya[RC_NB], yb[RC_NB], po[RC_NB];
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    load_body(m, fr->obody, y, po);
    /* the shared part at the state (real values) */
    const double *yr = y + m->inter_eadr[i];
    T *ys = d->sc->pt_work;
    rc_cs_load(yr, ns + ps * npt, ys);
    t6out_c o;
    type6_c(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i], pslip, ya, yb, ys, NULL,
            NULL, NULL, &o, NULL, d->sc->node_cache, NULL);
    segctx_c c;
    rc_cx fnf, kfr, fnd;
    fric_normal_c(m, i, o.fel + o.fd, o.kn, &o, &fnf, &kfr, &fnd);
    segfric_ctx_c(m, i, fnf, kfr, fnd, o.off, ya, yb, d->sc->node_cache, &c);
    for (int j = 0; j < npt; j++) {
        const int64_t *sb = slot + j * P + ps * ncol, *sc = sb + ps * nrow;
        point_columns(m, i, &c, j, pslip[j], ya, yb, po, yr + ns + ps * j, sb, sc, 0, val);
    }
}

void rc_jac_dense_block(const rc_model *m, int is_inter, int e, int mode, int branch, int track, int slip,
                        double t, const double *y, double *out)
{
    if (!is_inter) {
        dense_body(m, e, t, y, out, NULL);
        return;
    }
    /* contact points: their states in a scratch of their own, all in mode slip */
    const int np3 = m->inter_pst[e] * m->inter_npt[e];
    T *work = np3 > 0 ? malloc(2 * ((size_t)RC_NS_MAX + (size_t)np3) * sizeof(T)) : NULL;
    if (np3 > 0 && !work) {
        for (int k = 0; k < m->jb_inter[e].nrow * m->jb_inter[e].ncol; k++) out[k] = NAN;
        return;
    }
    dense_inter(m, e, mode, branch, track, slip, NULL, y, out, work, NULL, NULL, NULL, NULL, NULL);
    free(work);
}

/* Add a dense block into the CSC values through its slots (-1: pruned). */
static void scatter(const rc_jblock *jb, const double *dense, double *val)
{
    for (int k = 0; k < jb->nrow * jb->ncol; k++)
        if (jb->slot[k] >= 0) val[jb->slot[k]] += dense[k];
}

int rc_assemble_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val)
{
    double dense[RC_JB_MAX];
    d->sc->n_jac++;
    memset(val, 0, (size_t)m->nnz * sizeof(double));
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) {
            dense_body(m, b, t, y, dense, d->jac_skip);
            scatter(&m->jb_body[b], dense, val);
        }
    /* fast interfaces: a block kept 0 but where fast_inter writes, those
     * positions alone scattered and cached (the cache's other entries of
     * the block stay 0 from the first assembly on) */
    double fdense[RC_JB_MAX];
    int pos[RC_JB_MAX];
    memset(fdense, 0, sizeof fdense);
    for (int i = 0; i < m->ninter; i++) {
        const rc_jblock *jb = &m->jb_inter[i];
        const int nd = jb->nrow * jb->ncol;
        if (m->inter_fast && m->inter_fast[i] && jb->ncol > 0) {
            const int np = fast_inter(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], y, fdense,
                                      d->jac_skip, pos);
            double *jc = d->sc->jcache ? d->sc->jcache + d->sc->jcache_off[i] : NULL;
            if (jc && !d->sc->jcache_ok) memcpy(jc, fdense, (size_t)nd * sizeof(double));
            for (int q = 0; q < np; q++) {
                const int k = pos[q];
                if (jb->slot[k] >= 0) val[jb->slot[k]] += fdense[k];
                if (jc) jc[k] = fdense[k];
                fdense[k] = 0.0;
            }
            continue;
        }
        if (d->inter_mode[i] != RC_MODE_INACTIVE && jb->ncol > 0) {
            const int np = m->inter_npt[i];
            inter_block(m, d, i, y, dense, np > 0 ? m->inter_ptslot[i] : NULL, val);
            scatter(jb, dense, val);
            if (np > 0 && d->inter_mode[i] == RC_MODE_CLOSED) points_jac(m, d, i, y, val);
        } else {
            memset(dense, 0, (size_t)nd * sizeof(double));
        }
        if (d->sc->jcache) memcpy(d->sc->jcache + d->sc->jcache_off[i], dense, (size_t)nd * sizeof(double));
    }
    d->sc->jcache_ok = d->sc->jcache != NULL;
    /* couplings (rc_cpl_jac) */
    if (rc_cpl_jac(m, d, t, y, val)) return 1;
    /* potential of a time-varying gravity: d/dv of -m g(t).v */
    if (m->gwork_adr >= 0)
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            const double gf = rc_gravity_factor_run(m, d, t);
            for (int k = 0; k < 3; k++) val[m->gwork_slot[3 * b + k]] -= m->body_mass[b] * m->body_grav[3 * b + k] * gf;
        }
    /* imposed velocities (imposed_jac.c): the work row, their rows */
    if (m->imp && rc_imp_jac(m, d, t, y, val)) return 1;
    /* held DOFs: their rows are zero */
    if (m->nheld > 0)
        for (int64_t k = 0; k < m->nnz; k++)
            if (m->row_held[m->jac_rowind[k]]) val[k] = 0.0;
    return 0;
}

int rc_jac_refresh_inter(const rc_model *m, const rc_data *d, int i, const double *y, double *val)
{
    /* interfaces with contact points write their point rows and columns
     * outside the dense block (points_jac): assemble whole */
    if (!d->sc->jcache || !d->sc->jcache_ok || i < 0 || i >= m->ninter || m->inter_npt[i] > 0) return -1;
    /* imposed velocities replace their rows and derive the W_imp row from
     * every free acceleration after the elements (rc_imp_jac): a block
     * added here would put the contact's entries back in those rows */
    if (m->imp) return -1;
    const rc_jblock *jb = &m->jb_inter[i];
    const int nd = jb->nrow * jb->ncol;
    if (nd == 0) return 0;
    double dense[RC_JB_MAX];
    if (d->inter_mode[i] != RC_MODE_INACTIVE)
        inter_block(m, d, i, y, dense, NULL, val);
    else
        memset(dense, 0, (size_t)nd * sizeof(double));
    double *old = d->sc->jcache + d->sc->jcache_off[i];
    for (int k = 0; k < nd; k++) {
        const int64_t sl = jb->slot[k];
        /* held rows stay zero (rc_assemble_jac) */
        if (sl >= 0 && !(m->nheld > 0 && m->row_held[m->jac_rowind[sl]])) val[sl] += dense[k] - old[k];
        old[k] = dense[k];
    }
    d->sc->n_jac_refresh++;
    return 0;
}

/* The pose carrying the orthotropy vector of interface i's friction, as
 * type6 takes it: a's or b's (complex) states, else the ground's. */
static const T *fric_pose(const rc_model *m, int i, const T *ya, const T *yb, T *yo)
{
    const int ob = m->inter_fr[i].obody;
    if (ob >= 0 && ob == m->inter_ba[i]) return ya;
    if (ob >= 0 && ob == m->inter_bb[i]) return yb;
    rc_cs_load(m->ground_y0, RC_NB, yo);
    return yo;
}

int rc_jac_refresh_points(const rc_model *m, const rc_data *d, int i, const int *old_slip, const double *y, double *val)
{
    if (!d->sc->jcache || !d->sc->jcache_ok || i < 0 || i >= m->ninter || m->inter_npt[i] == 0 || !old_slip) return -1;
    if (m->imp) return -1; /* as rc_jac_refresh_inter */
    /* the point modes act only while the interface is closed */
    if (d->inter_mode[i] != RC_MODE_CLOSED || m->inter_fr[i].kind == RC_FK_NONE) return 0;
    const int npt = m->inter_npt[i], ns = m->inter_ns[i], ps = m->inter_pst[i];
    const int *pslip = d->pt_slip + m->inter_pbase[i];
    int nflip = 0;
    for (int j = 0; j < npt; j++) nflip += pslip[j] != old_slip[j];
    if (nflip == 0) return 0;
    /* each column below evaluates the shared part and two laws per flipped
     * point; the whole assembly evaluates every point: no gain past half */
    if (2 * nflip >= npt) return -1;
    const rc_jblock *jb = &m->jb_inter[i];
    const int ncol = jb->ncol, nrow = jb->nrow, nd = nrow * ncol;
    const int64_t P = (int64_t)ps * ncol + (int64_t)ps * nrow + ps * ps, *slot = m->inter_ptslot[i];
    const int ba = m->inter_ba[i], bb = m->inter_bb[i];
    const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
    const int na = fa ? RC_NB : 0, nb = fb ? RC_NB : 0, racc = (fa ? 6 : 0) + (fb ? 6 : 0);
    const int widx = m->inter_fr[i].widx;
    T *nc = rc_pair_nodes(m->inter_pair[i]) ? d->sc->node_cache : NULL;
    const double *yr = y + m->inter_eadr[i];
    double delta[RC_JB_MAX];
    memset(delta, 0, (size_t)nd * sizeof(double));
    T ya[RC_NB], yb[RC_NB], ys[RC_NS_MAX], yo[RC_NB];
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    rc_cs_load(yr, ns, ys);
    const unsigned char *only = point_mask(m, i, ya, yb, ys, nc, d->sc->node_only);
    /* 1. the block's columns: the flipped points' forces on a and b and
     * their friction power, new law less old law; their own rows anew */
    for (int c = 0; c <= ncol; c++) {
        const int real = c == ncol; /* last: unperturbed, for step 2 */
        if (!real && d->jac_skip && d->jac_skip[jb->cols[c]]) continue;
        T *yp = real ? NULL : c < na ? ya + c : c < na + nb ? yb + (c - na) : ys + (c - na - nb);
        if (yp) rc_cs_step(yp);
        if (nc) seg_fill_c(m, i, ya, yb, nc, only);
        t6out_c r;
        memset(&r, 0, sizeof r);
        T kn, dfh;
        const T fn = type6_normal_c(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], ya, yb, ys, nc, &r,
                                    &kn, &dfh);
        segctx_c cx;
        rc_cx fnf, kfr, fnd;
        fric_normal_c(m, i, fn, kn, &r, &fnf, &kfr, &fnd);
        segfric_ctx_c(m, i, fnf, kfr, fnd, r.off, ya, yb, nc, &cx);
        const T *po = fric_pose(m, i, ya, yb, yo);
        if (real) {
            /* 2. the flipped points' columns anew (points_jac) */
            for (int j = 0; j < npt; j++) {
                if (pslip[j] == old_slip[j]) continue;
                const int64_t *sb = slot + j * P + ps * ncol, *sc = sb + ps * nrow;
                for (int k = 0; k < ps * nrow; k++)
                    if (live_slot(m, sb[k])) val[sb[k]] = 0.0;
                for (int k = 0; k < ps * ps; k++)
                    if (live_slot(m, sc[k])) val[sc[k]] = 0.0;
                point_columns(m, i, &cx, j, pslip[j], ya, yb, po, yr + ns + ps * j, sb, sc, 1, val);
            }
            break;
        }
        T acc[12] = {0}, dw = 0.0;
        for (int j = 0; j < npt; j++) {
            if (pslip[j] == old_slip[j]) continue;
            T Fj[6];
            rc_cs_load(yr + ns + ps * j, ps, Fj);
            segpt_c qn, qo;
            segfric_point_c(m, i, &cx, j, pslip[j], ya, yb, Fj, po, &qn);
            segfric_point_c(m, i, &cx, j, old_slip[j], ya, yb, Fj, po, &qo);
            T df[3], mdf[3];
            for (int k = 0; k < 3; k++) {
                df[k] = qn.ft[k] - qo.ft[k];
                mdf[k] = -df[k];
            }
            /* the old and new points sit at the same place (the geometry) */
            if (fa) apply_force_c(m, ba, ya, df, qn.x, acc);
            if (fb) apply_force_c(m, bb, yb, mdf, qn.x, acc + 6);
            dw += -(dot_c(qn.ft, qn.vrel) - dot_c(qo.ft, qo.vrel));
            /* the point's rows against this column, anew */
            for (int k = 0; k < ps; k++) {
                const int64_t sl = slot[j * P + k * ncol + c];
                if (live_slot(m, sl)) val[sl] = rc_cs_deriv(qn.dF[k]);
            }
        }
        rc_cs_unstep(yp);
        int rr = 0;
        if (fa)
            for (int k = 0; k < 6; k++, rr++) delta[rr * ncol + c] = rc_cs_deriv(acc[k]);
        if (fb)
            for (int k = 0; k < 6; k++, rr++) delta[rr * ncol + c] = rc_cs_deriv(acc[6 + k]);
        delta[(racc + widx) * ncol + c] = rc_cs_deriv(dw);
    }
    double *old = d->sc->jcache + d->sc->jcache_off[i];
    for (int k = 0; k < nd; k++) {
        if (live_slot(m, jb->slot[k])) val[jb->slot[k]] += delta[k];
        old[k] += delta[k];
    }
    d->sc->n_jac_refresh++;
    return 0;
}

/* Coupling Jacobian blocks. A catenary is solved once in real arithmetic
 * at the current state; every column then reuses that solution, lifted by
 * its implicit-function derivatives. */
int rc_cpl_dense_block(const rc_model *m, const rc_data *d, int k, double t, const double *y,
                       double *out)
{
    const rc_couplings *c = m->cpl;
    const rc_jblock *jb = &c->jb[k];
    const int b1 = c->b1[k], b2 = c->b2[k];
    const int n1 = b1 >= 0 && m->body_yadr[b1] >= 0 ? RC_NB : 0;
    const int f2 = b2 >= 0 && m->body_yadr[b2] >= 0;
    T ya[RC_NB], yb[RC_NB];
    load_body(m, b1, y, ya);
    load_body(m, b2, y, yb);
    double eup[3];
    rc_cat_sol s;
    if (c->kind[k] == RC_CPL_CATENARY && cat_solve_at_c(m, d, k, t, y, eup, &s)) return 1;
    for (int col = 0; col < jb->ncol; col++) {
        T *yp = col < n1 ? ya + col : yb + (col - n1);
        rc_cs_step(yp);
        T acc[12] = {0}, edot[RC_CE] = {0};
        if (c->kind[k] == RC_CPL_SPRING && d && c->grup[k] >= 0 && d->cpl->lmode[k] == RC_SPR_BROKEN) {
            /* a broken spring: no force, no energy rate */
        } else if (c->kind[k] == RC_CPL_SPRING)
            spring_c(m, k, ya, yb, n1 ? acc : NULL, f2 ? acc + 6 : NULL, edot, NULL);
        else if (c->kind[k] == RC_CPL_LIMIT) /* no data (the pattern's probe): pushing past a stop */
            jlimit_c(m, k, d ? d->cpl->lmode[k] : isfinite(c->llo[k]) ? RC_LIM_LO_PUSH : RC_LIM_HI_PUSH, ya, yb, n1 ? acc : NULL, f2 ? acc + 6 : NULL, edot,
                     NULL, NULL, NULL, NULL, NULL);
        else if (c->kind[k] == RC_CPL_CONTACT)
            contact_cpl_c(m, k, d ? d->cpl->fmode : NULL, 0, ya, yb, n1 ? acc : NULL, f2 ? acc + 6 : NULL, edot, NULL);
        else
            catenary_c(m, k, eup, &s, ya, yb, n1 ? acc : NULL, f2 ? acc + 6 : NULL, edot, NULL, NULL);
        rc_cs_unstep(yp);
        int r = 0;
        if (n1)
            for (int i = 0; i < 6; i++, r++) out[r * jb->ncol + col] = rc_cs_deriv(acc[i]);
        if (f2)
            for (int i = 0; i < 6; i++, r++) out[r * jb->ncol + col] = rc_cs_deriv(acc[6 + i]);
        for (int i = 0; i < RC_CE; i++, r++) out[r * jb->ncol + col] = rc_cs_deriv(edot[i]);
    }
    return 0;
}

int rc_cpl_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val)
{
    double dense[RC_JB_MAX];
    for (int k = 0; k < m->cpl->n; k++) {
        if (m->cpl->jb[k].ncol == 0) continue;
        if (rc_cpl_dense_block(m, d, k, t, y, dense)) {
            d->cpl->fail = k;
            d->sc->fail_t = t;
            return 1;
        }
        scatter(&m->cpl->jb[k], dense, val);
    }
    return 0;
}

void rc_inter_report_rate(const rc_model *m, int i, int mode, int branch, int track, int slip, const double *y,
                          const double *ydot, rc_inter_report *dr)
{
    /* d/dt q = Im(q(y + i h ydot)) / h for every reported quantity q */
    const int ba = m->inter_ba[i], bb = m->inter_bb[i], ns = m->inter_ns[i];
    const int np3 = m->inter_pst[i] * m->inter_npt[i];
    T ya[RC_NB], yb[RC_NB], ysl[RC_NS_MAX];
    /* contact points: their states (read, not differentiated) */
    T *ys = np3 > 0 ? malloc(((size_t)ns + (size_t)np3) * sizeof(T)) : ysl;
    memset(dr, 0, sizeof *dr);
    if (!ys) return;
    rc_cs_load(y + m->inter_eadr[i] + ns, np3, ys + ns);
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    if (ba >= 0 && m->body_yadr[ba] >= 0)
        for (int k = 0; k < RC_NB; k++) rc_cs_step_along(&ya[k], ydot[m->body_yadr[ba] + k]);
    if (bb >= 0 && m->body_yadr[bb] >= 0)
        for (int k = 0; k < RC_NB; k++) rc_cs_step_along(&yb[k], ydot[m->body_yadr[bb] + k]);
    for (int k = 0; k < ns; k++) ys[k] = rc_cs_seed(y[m->inter_eadr[i] + k], ydot[m->inter_eadr[i] + k]);
    t6out_c o;
    type6_c(m, i, mode, branch, track, slip, NULL, ya, yb, ys, NULL, NULL, NULL, &o, NULL, NULL, NULL);
    if (ys != ysl) free(ys);
    dr->p = rc_cs_deriv(o.p);
    dr->vn = rc_cs_deriv(o.vn);
    dr->p_raw = rc_cs_deriv(o.p_raw);
    dr->vn_raw = rc_cs_deriv(o.vn_raw);
    dr->pl = rc_cs_deriv(o.pl);
    dr->vl = rc_cs_deriv(o.vl);
    dr->vd = rc_cs_deriv(o.vd);
    dr->fload = rc_cs_deriv(o.fel);
    dr->fdamp = rc_cs_deriv(o.fd);
    dr->fn = dr->fload + dr->fdamp;
    dr->fl = rc_cs_deriv(o.fl);
    dr->fu = rc_cs_deriv(o.fu);
    dr->fh = rc_cs_deriv(o.fh);
    dr->offset = rc_cs_deriv(o.off);
    dr->flim = rc_cs_deriv(o.flim);
    for (int k = 0; k < 3; k++) dr->normal[k] = rc_cs_deriv(o.g.n[k]);
}

/* Contact point, unit normal (from a to b) and relative velocity of the
 * material points there, for the exact-stick constraint (engine/constraints/stick.h;
 * single-point pairs). Complex, for its complex-step derivatives. */
void rc_stk_geom_c(const rc_model *m, int i, const double complex *ya, const double complex *yb,
                   double complex *point, double complex *n, double complex *vrel, double complex *ddot)
{
    geom_c g;
    geometry_c(m, i, ya, yb, &g, NULL);
    *ddot = g.ddot; /* the exact rate of the signed distance [m/s] */
    for (int k = 0; k < 3; k++) {
        point[k] = g.point[k];
        n[k] = g.n[k];
        vrel[k] = g.vrel[k];
    }
}
