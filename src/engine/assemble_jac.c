/*
 * Analytic Jacobian by complex-step differentiation of the element kernels
 * (kernels.inc compiled with T = double complex): column j of an element's
 * block is Im(f(y + i h e_j)) / h, exact to rounding for any h because no
 * difference is taken (docs/design.md). Values go into the fixed CSC pattern
 * through each element's slot table.
 */
#include <complex.h>
#include <math.h>
#include <string.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/model.h"

#define T double complex
#define RE(x) creal(x)
#define RCK(name) name##_c
#include "kernels.inc"
#include "kernels_coupling.inc"

/* Complex step [state units]; any tiny value works, no cancellation. */
#define RC_CSTEP 1e-40

/* Complex copy of a body's 13 states (ground/fixed pose when b has none). */
static void load_body(const rc_model *m, int b, const double *y, T *yc)
{
    const double *s = rc_body_state(m, b, y);
    for (int k = 0; k < RC_NB; k++) yc[k] = s[k];
}

/* Dense 13 x 13 block of body b: d(ydot_b)/d(y_b). */
static void dense_body(const rc_model *m, int b, double t, const double *y, double *out)
{
    T yc[RC_NB], yd[RC_NB];
    load_body(m, b, y, yc);
    for (int c = 0; c < RC_NB; c++) {
        yc[c] += I * RC_CSTEP;
        body_rhs_c(m, b, t, yc, yd);
        for (int r = 0; r < RC_NB; r++) out[r * RC_NB + c] = cimag(yd[r]) / RC_CSTEP;
        yc[c] = creal(yc[c]);
    }
}

/* Dense block of interface i in the given modes: rows = accelerations of a
 * (if free), of b (if free), own states; columns = states of a, of b, own. */
static void dense_inter(const rc_model *m, int i, int mode, int branch, int track, int slip, const double *y,
                        double *out)
{
    const rc_jblock *jb = &m->jb_inter[i];
    const int ba = m->inter_ba[i], bb = m->inter_bb[i], ns = m->inter_ns[i];
    const int fa = ba >= 0 && m->body_yadr[ba] >= 0, fb = bb >= 0 && m->body_yadr[bb] >= 0;
    const int na = fa ? RC_NB : 0, nb = fb ? RC_NB : 0;
    T ya[RC_NB], yb[RC_NB], ys[RC_NS_MAX];
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    for (int k = 0; k < ns; k++) ys[k] = y[m->inter_eadr[i] + k];
    for (int c = 0; c < jb->ncol; c++) {
        T *yp = c < na ? ya + c : c < na + nb ? yb + (c - na) : ys + (c - na - nb);
        *yp += I * RC_CSTEP;
        T acc[12] = {0}, sdot[RC_NS_MAX];
        type6_c(m, i, mode, branch, track, slip, ya, yb, ys, fa ? acc : NULL, fb ? acc + 6 : NULL, sdot, NULL);
        *yp = creal(*yp);
        int r = 0;
        if (fa)
            for (int k = 0; k < 6; k++, r++) out[r * jb->ncol + c] = cimag(acc[k]) / RC_CSTEP;
        if (fb)
            for (int k = 0; k < 6; k++, r++) out[r * jb->ncol + c] = cimag(acc[6 + k]) / RC_CSTEP;
        for (int k = 0; k < ns; k++, r++) out[r * jb->ncol + c] = cimag(sdot[k]) / RC_CSTEP;
    }
}

void rc_jac_dense_block(const rc_model *m, int is_inter, int e, int mode, int branch, int track, int slip,
                        double t, const double *y, double *out)
{
    if (is_inter) dense_inter(m, e, mode, branch, track, slip, y, out);
    else dense_body(m, e, t, y, out);
}

/* Add a dense block into the CSC values through its slots (-1: pruned). */
static void scatter(const rc_jblock *jb, const double *dense, double *val)
{
    for (int k = 0; k < jb->nrow * jb->ncol; k++)
        if (jb->slot[k] >= 0) val[jb->slot[k]] += dense[k];
}

int rc_assemble_jac(const rc_model *m, rc_data *d, double t, const double *y, double *val)
{
    double dense[RC_JB_MAX];
    d->n_jac++;
    memset(val, 0, (size_t)m->nnz * sizeof(double));
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) {
            dense_body(m, b, t, y, dense);
            scatter(&m->jb_body[b], dense, val);
        }
    for (int i = 0; i < m->ninter; i++) {
        const rc_jblock *jb = &m->jb_inter[i];
        const int nd = jb->nrow * jb->ncol;
        if (d->inter_mode[i] != RC_MODE_INACTIVE && jb->ncol > 0) {
            dense_inter(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i], y, dense);
            scatter(jb, dense, val);
        } else {
            memset(dense, 0, (size_t)nd * sizeof(double));
        }
        if (d->jcache) memcpy(d->jcache + d->jcache_off[i], dense, (size_t)nd * sizeof(double));
    }
    d->jcache_ok = d->jcache != NULL;
    /* couplings (coupling_jac.inc) */
    if (rc_cpl_jac(m, d, t, y, val)) return 1;
    /* potential of a time-varying gravity: d/dv of -m g(t).v */
    if (m->gwork_adr >= 0)
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double g[3];
            rc_gravity(m, b, t, g);
            for (int k = 0; k < 3; k++) val[m->gwork_slot[3 * b + k]] -= m->body_mass[b] * g[k];
        }
    /* imposed velocities (imposed_jac.inc): the work row, their rows */
    if (m->imp && rc_imp_jac(m, d, t, y, val)) return 1;
    /* held DOFs: their rows are zero */
    if (m->nheld > 0)
        for (int64_t k = 0; k < m->nnz; k++)
            if (m->row_held[m->jac_rowind[k]]) val[k] = 0.0;
    return 0;
}

int rc_jac_refresh_inter(const rc_model *m, rc_data *d, int i, const double *y, double *val)
{
    if (!d->jcache || !d->jcache_ok || i < 0 || i >= m->ninter) return -1;
    const rc_jblock *jb = &m->jb_inter[i];
    const int nd = jb->nrow * jb->ncol;
    if (nd == 0) return 0;
    double dense[RC_JB_MAX];
    if (d->inter_mode[i] != RC_MODE_INACTIVE)
        dense_inter(m, i, d->inter_mode[i], d->inter_branch[i], d->inter_track[i], d->inter_slip[i], y, dense);
    else
        memset(dense, 0, (size_t)nd * sizeof(double));
    double *old = d->jcache + d->jcache_off[i];
    for (int k = 0; k < nd; k++) {
        const int64_t sl = jb->slot[k];
        /* held rows stay zero (rc_assemble_jac) */
        if (sl >= 0 && !(m->nheld > 0 && m->row_held[m->jac_rowind[sl]])) val[sl] += dense[k] - old[k];
        old[k] = dense[k];
    }
    d->n_jac_refresh++;
    return 0;
}

#include "coupling_jac.inc"
#include "imposed_jac.inc"

void rc_inter_report_rate(const rc_model *m, int i, int mode, int branch, int track, int slip, const double *y,
                          const double *ydot, rc_inter_report *dr)
{
    /* d/dt q = Im(q(y + i h ydot)) / h for every reported quantity q */
    const int ba = m->inter_ba[i], bb = m->inter_bb[i], ns = m->inter_ns[i];
    T ya[RC_NB], yb[RC_NB], ys[RC_NS_MAX];
    load_body(m, ba, y, ya);
    load_body(m, bb, y, yb);
    if (ba >= 0 && m->body_yadr[ba] >= 0)
        for (int k = 0; k < RC_NB; k++) ya[k] += I * RC_CSTEP * ydot[m->body_yadr[ba] + k];
    if (bb >= 0 && m->body_yadr[bb] >= 0)
        for (int k = 0; k < RC_NB; k++) yb[k] += I * RC_CSTEP * ydot[m->body_yadr[bb] + k];
    for (int k = 0; k < ns; k++) ys[k] = y[m->inter_eadr[i] + k] + I * RC_CSTEP * ydot[m->inter_eadr[i] + k];
    t6out_c o;
    type6_c(m, i, mode, branch, track, slip, ya, yb, ys, NULL, NULL, NULL, &o);
    memset(dr, 0, sizeof *dr);
    dr->p = cimag(o.p) / RC_CSTEP;
    dr->vn = cimag(o.vn) / RC_CSTEP;
    dr->p_raw = cimag(o.p_raw) / RC_CSTEP;
    dr->vn_raw = cimag(o.vn_raw) / RC_CSTEP;
    dr->fload = cimag(o.fel) / RC_CSTEP;
    dr->fdamp = cimag(o.fd) / RC_CSTEP;
    dr->fn = dr->fload + dr->fdamp;
    dr->fl = cimag(o.fl) / RC_CSTEP;
    dr->fu = cimag(o.fu) / RC_CSTEP;
    dr->fh = cimag(o.fh) / RC_CSTEP;
    dr->offset = cimag(o.off) / RC_CSTEP;
}
