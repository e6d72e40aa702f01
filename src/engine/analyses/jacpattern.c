/*
 * Fixed Jacobian pattern. Every element declares the dense block of
 * (row, column) state indices it may write. The entries that are
 * structurally zero (a centred sphere's rotation does not move its surface;
 * positions do not depend on angular velocities; ...) are pruned by probing:
 * the element's exact block is evaluated at two generic states (every body
 * moved, turned and set moving by deterministic pseudo-random amounts, the
 * contact law closed) and an entry zero in both is dropped. The union of the
 * kept entries and the full diagonal is sorted once into CSC, and each
 * element receives the CSC position of every entry of its block (its slots,
 * -1 when pruned). KLU analyses this pattern once per run.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/friction.h"
#include "base/error.h"
#include "model/imposed.h"
#include "model/model.h"
#include "base/progress.h"
#include "model/power.h"
#include "engine/assembly/assembly.h"
#include "engine/analyses/analyses.h"

/* Body block: its 13 rows by its 13 columns. */
static void block_body(const rc_model *m, int b, rc_jblock *jb)
{
    jb->nrow = jb->ncol = 0;
    if (m->body_yadr[b] < 0) return;
    for (int k = 0; k < RC_NB; k++) {
        jb->rows[jb->nrow++] = m->body_yadr[b] + k;
        jb->cols[jb->ncol++] = m->body_yadr[b] + k;
    }
}

/* Interface block: rows = accelerations of its free bodies and its own
 * states; columns = all states of its free bodies and its own states. */
static void block_inter(const rc_model *m, int i, rc_jblock *jb)
{
    jb->nrow = jb->ncol = 0;
    const int bodies[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int s = 0; s < 2; s++) {
        const int b = bodies[s];
        if (b < 0 || m->body_yadr[b] < 0) continue;
        for (int k = 0; k < 6; k++) jb->rows[jb->nrow++] = m->body_yadr[b] + 7 + k;
        for (int k = 0; k < RC_NB; k++) jb->cols[jb->ncol++] = m->body_yadr[b] + k;
    }
    for (int k = 0; k < m->inter_ns[i]; k++) {
        jb->rows[jb->nrow++] = m->inter_eadr[i] + k;
        jb->cols[jb->ncol++] = m->inter_eadr[i] + k;
    }
}

/* Deterministic generator in [-1, 1) (64-bit LCG). */
static double probe_rand(uint64_t *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 4503599627370496.0 - 1.0;
}

/* Generic state: initial state, bodies shifted by up to 1e-4 (length units),
 * turned to a random orientation, random velocities and angular velocities. */
static void probe_state(const rc_model *m, uint64_t seed, double *y)
{
    rc_initial_state(m, y);
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        double *s = y + m->body_yadr[b], nq = 0;
        for (int k = 0; k < 3; k++) s[k] += 1e-4 * probe_rand(&seed);
        for (int k = 3; k < 7; k++) {
            s[k] = probe_rand(&seed);
            nq += s[k] * s[k];
        }
        for (int k = 3; k < 7; k++) s[k] /= sqrt(nq);
        for (int k = 7; k < 13; k++) s[k] = probe_rand(&seed);
    }
    for (int i = 0; i < m->ninter; i++)
        for (int k = 0; k < m->inter_ns[i]; k++) y[m->inter_eadr[i] + k] = probe_rand(&seed);
}


/* ---- Probing once per kind of interface --------------------------------
 * The kept entries of an interface block are structural: with the probe
 * states generic, they depend on what the interface kernel reads apart from
 * the states of its free bodies and its own states. An interface whose data
 * are bit for bit those of one already probed (its own parameters, friction
 * and power-law records, and for each side the surface, the body's mass and
 * inertia, whether it is free, and the pose of a fixed one) gets that
 * interface's pattern without being probed: a column of 10^5 identical
 * contacts is probed once. Any difference, even of a byte (-0.0, a table
 * index, a pointer), means a probe of its own. */
#define RC_KEY_MAX 2048

typedef struct key_buf {
    unsigned char b[RC_KEY_MAX];
    size_t n;
} key_buf;

static void key_put(key_buf *k, const void *p, size_t n)
{
    if (k->n + n > RC_KEY_MAX) { /* cannot happen with the fields below; no sharing then */
        k->n = RC_KEY_MAX + 1;
        return;
    }
    memcpy(k->b + k->n, p, n);
    k->n += n;
}

/* The data interface i's kernel reads, apart from states; 0 when too long. */
static int inter_key(const rc_model *m, int i, key_buf *k)
{
    k->n = 0;
    const int ints[] = {m->inter_law[i], m->inter_iform[i], m->inter_hidx[i], m->inter_oidx[i], m->inter_ns[i],
                        m->inter_fct_ld[i], m->inter_fct_ul[i], m->inter_fct_dv[i], m->inter_fct_df[i],
                        (int)m->inter_pair[i], m->jb_inter[i].nrow, m->jb_inter[i].ncol};
    const double dbl[] = {m->inter_gap[i], m->inter_visc[i], m->inter_stiff[i], m->inter_fscalev[i],
                          m->inter_ascalex[i], m->inter_fscaleld[i], m->inter_ascalef[i], m->inter_ascalev[i],
                          m->inter_fscaleul[i]};
    key_put(k, ints, sizeof ints);
    key_put(k, dbl, sizeof dbl);
    key_put(k, &m->inter_fr[i], sizeof m->inter_fr[i]);
    key_put(k, &m->inter_pw[i], sizeof m->inter_pw[i]);
    const int surf[2] = {m->inter_sa[i], m->inter_sb[i]}, body[2] = {m->inter_ba[i], m->inter_bb[i]};
    for (int e = 0; e < 2; e++) {
        const int sf = surf[e], b = body[e];
        const int sk = (int)m->surf_kind[sf], free_b = b >= 0 && m->body_yadr[b] >= 0;
        key_put(k, &sk, sizeof sk);
        key_put(k, m->surf_p + 3 * sf, 3 * sizeof(double));
        key_put(k, m->surf_n + 3 * sf, 3 * sizeof(double));
        key_put(k, m->surf_r + sf, sizeof(double));
        key_put(k, m->surf_ext + RC_SURF_NEXT * sf, RC_SURF_NEXT * sizeof(double));
        key_put(k, &free_b, sizeof free_b);
        if (b >= 0) {
            key_put(k, m->body_mass + b, sizeof(double));
            key_put(k, m->body_J + 9 * b, 9 * sizeof(double));
            key_put(k, m->body_Jinv + 9 * b, 9 * sizeof(double));
        }
        if (!free_b) key_put(k, rc_body_state(m, b, NULL), RC_NB * sizeof(double)); /* fixed pose */
    }
    return k->n <= RC_KEY_MAX;
}

static uint64_t key_hash(const key_buf *k)
{
    uint64_t h = 1469598103934665603ULL; /* FNV-1a 64 */
    for (size_t j = 0; j < k->n; j++) h = (h ^ k->b[j]) * 1099511628211ULL;
    return h;
}

/* Probed interfaces by key: open addressing on the hash, the key bytes kept
 * for the exact comparison. */
typedef struct key_table {
    size_t cap, n;
    uint64_t *hash;
    int *inter;             /* representative interface, -1: empty */
    unsigned char **bytes;  /* its key */
    size_t *len;
} key_table;

static int key_table_init(key_table *t, int ninter)
{
    memset(t, 0, sizeof *t);
    t->cap = 64;
    while (t->cap < 2 * (size_t)ninter) t->cap *= 2;
    t->hash = calloc(t->cap, sizeof *t->hash);
    t->inter = malloc(t->cap * sizeof *t->inter);
    t->bytes = calloc(t->cap, sizeof *t->bytes);
    t->len = calloc(t->cap, sizeof *t->len);
    if (!t->hash || !t->inter || !t->bytes || !t->len) return 0;
    for (size_t j = 0; j < t->cap; j++) t->inter[j] = -1;
    return 1;
}

static void key_table_free(key_table *t)
{
    if (t->bytes)
        for (size_t j = 0; j < t->cap; j++) free(t->bytes[j]);
    free(t->hash);
    free(t->inter);
    free(t->bytes);
    free(t->len);
}

/* The slot of key k: its representative's, or the empty one to fill. */
static size_t key_find(const key_table *t, const key_buf *k, uint64_t h)
{
    size_t j = (size_t)h & (t->cap - 1);
    while (t->inter[j] >= 0 &&
           !(t->hash[j] == h && t->len[j] == k->n && memcmp(t->bytes[j], k->b, k->n) == 0))
        j = (j + 1) & (t->cap - 1);
    return j;
}

/* Mark the kept entries of each block in its slot array: 0 kept, -1 pruned. */
static rc_status probe_blocks(rc_model *m, rc_error *err)
{
    double *y[2], dense[RC_JB_MAX];
    key_table kt;
    key_buf *key = NULL;
    memset(&kt, 0, sizeof kt);
    y[0] = malloc((size_t)m->ny * sizeof(double));
    y[1] = malloc((size_t)m->ny * sizeof(double));
    rc_status st = RC_OK;
    if (!y[0] || !y[1]) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
        goto done;
    }
    probe_state(m, 0x5eed1ULL, y[0]);
    probe_state(m, 0x5eed2ULL, y[1]);
    if (!key_table_init(&kt, m->ninter) || !(key = malloc(sizeof *key))) {
        st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
        goto done;
    }
    for (int e = 0; e < m->nbody + m->ninter && !st; e++) {
        const int is_inter = e >= m->nbody, idx = is_inter ? e - m->nbody : e;
        rc_jblock *jb = is_inter ? &m->jb_inter[idx] : &m->jb_body[idx];
        const int n = jb->nrow * jb->ncol;
        if (n == 0) continue;
        jb->slot = malloc((size_t)n * sizeof(int64_t));
        if (!jb->slot) {
            st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
            break;
        }
        /* a segment surface: which of its points act depends on the state,
         * so the probe states cannot tell the structural zeros: the whole
         * block is kept (docs/theory.md 2.7); the same for sphere-cylinder,
         * whose region (lateral, end, rim) depends on the state, and for
         * sphere-box (a face, an edge or a corner: at an edge or a corner
         * the normal turns with the sphere's centre, at a face it does not),
         * for cylinder-box (the same regions, seen from the cylinder's
         * centre), and for a sphere against a plane bounded to a parallelogram
         * (/RWALL/PARAL: beyond a side, as at a box's edge) */
        if (is_inter && (rc_pair_multi(m->inter_pair[idx]) || m->inter_pair[idx] == RC_PAIR_CYL_SEG ||
                         m->inter_pair[idx] == RC_PAIR_SPHERE_CYL || m->inter_pair[idx] == RC_PAIR_SPHERE_BOX ||
                         m->inter_pair[idx] == RC_PAIR_CYL_BOX ||
                         (m->inter_pair[idx] == RC_PAIR_SPHERE_PLANE &&
                          m->surf_ext[RC_SURF_NEXT * m->inter_sb[idx]] != 0.0))) {
            for (int k = 0; k < n; k++) jb->slot[k] = 0;
            continue;
        }
        /* an interface like one already probed: its pattern */
        size_t ks = 0;
        uint64_t kh = 0;
        const int keyed = is_inter && inter_key(m, idx, key);
        if (keyed) {
            kh = key_hash(key);
            ks = key_find(&kt, key, kh);
            if (kt.inter[ks] >= 0) {
                memcpy(jb->slot, m->jb_inter[kt.inter[ks]].slot, (size_t)n * sizeof(int64_t));
                continue;
            }
        }
        for (int k = 0; k < n; k++) jb->slot[k] = -1;
        /* every mode in which the element writes and that it can reach
         * (events.c): contact closed (forces) and released; each hysteresis
         * branch, unless the branch stays LOAD (TYPE6, Iform 0, no F_h
         * state); Inacti tracking on/off when it has the offset state; stick
         * and slip when it has friction. A plain contact needs 4 of the 48
         * combinations (the probing is most of the set-up of a large model) */
        const int nbr = is_inter && !(m->inter_law[idx] == RC_LAW_TYPE6 && m->inter_iform[idx] == 0 &&
                                      m->inter_hidx[idx] < 0) ? 3 : 1;
        const int ntrk = is_inter && m->inter_oidx[idx] >= 0 ? 2 : 1;
        const int nsl = is_inter && m->inter_fr[idx].kind != RC_FK_NONE ? 2 : 1;
        for (int p = 0; p < 2; p++)
            for (int md = 0; md < (is_inter ? 2 : 1); md++)
                for (int br = 0; br < nbr; br++)
                    for (int trk = 0; trk < ntrk; trk++)
                        for (int sl = 0; sl < nsl; sl++) {
                            const int mode = md ? RC_MODE_RELEASED : RC_MODE_CLOSED;
                            rc_jac_dense_block(m, is_inter, idx, mode, br, trk, sl, 0.0, y[p], dense);
                            for (int k = 0; k < n; k++)
                                if (dense[k] != 0.0) jb->slot[k] = 0; /* NaN counts as kept */
                        }
        if (keyed) { /* the first of its kind */
            if (!(kt.bytes[ks] = malloc(key->n ? key->n : 1))) {
                st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
                break;
            }
            memcpy(kt.bytes[ks], key->b, key->n);
            kt.len[ks] = key->n;
            kt.hash[ks] = kh;
            kt.inter[ks] = idx;
        }
    }
    /* couplings (coupling.h): no modes */
    for (int k = 0; k < m->cpl->n && !st; k++) {
        rc_jblock *jb = &m->cpl->jb[k];
        const int n = jb->nrow * jb->ncol;
        if (n == 0) continue;
        if (!(jb->slot = malloc((size_t)n * sizeof(int64_t)))) {
            st = RC_SET(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
            break;
        }
        for (int i = 0; i < n; i++) jb->slot[i] = -1;
        for (int p = 0; p < 2 && !st; p++) {
            if (rc_cpl_dense_block(m, NULL, k, 0.0, y[p], dense))
                st = RC_SET(err, RC_EINPUT, RC_LOCFMT "card %s, fields Lambda0 L_eq D: the catenary equations have "
                            "no solution near the initial position (probing the Jacobian pattern)",
                            RC_LOC(m->cpl->law_loc[k]), m->cpl->name[k]);
            for (int i = 0; i < n; i++)
                if (dense[i] != 0.0) jb->slot[i] = 0;
        }
    }
done:
    key_table_free(&kt);
    free(key);
    free(y[0]);
    free(y[1]);
    return st;
}

/* CSC position of (row, col), -1 when the entry is not in the pattern. */

static rc_status fill_slots(const rc_model *m, rc_jblock *jb, rc_error *err)
{
    for (int r = 0; r < jb->nrow; r++)
        for (int c = 0; c < jb->ncol; c++) {
            if (jb->slot[r * jb->ncol + c] < 0) continue; /* pruned */
            int64_t s = rc_jac_slot(m, jb->rows[r], jb->cols[c]);
            if (s < 0) RC_RAISE(err, RC_EINTERNAL, "Jacobian slot (%d, %d) missing", jb->rows[r], jb->cols[c]);
            jb->slot[r * jb->ncol + c] = s;
        }
    return RC_OK;
}

rc_status rc_jac_build(rc_model *m, rc_error *err)
{
    const int64_t ny = m->ny;
    m->jb_body = calloc((size_t)m->nbody + 1, sizeof(rc_jblock));
    m->jb_inter = calloc((size_t)m->ninter + 1, sizeof(rc_jblock));
    if (!m->jb_body || !m->jb_inter) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    /* count and collect the keys col * ny + row */
    int64_t nkey = ny;
    for (int b = 0; b < m->nbody; b++) {
        block_body(m, b, &m->jb_body[b]);
        nkey += (int64_t)m->jb_body[b].nrow * m->jb_body[b].ncol;
    }
    for (int i = 0; i < m->ninter; i++) {
        block_inter(m, i, &m->jb_inter[i]);
        nkey += (int64_t)m->jb_inter[i].nrow * m->jb_inter[i].ncol;
    }
    for (int k = 0; k < m->cpl->n; k++) {
        rc_cpl_block(m, k, &m->cpl->jb[k]);
        nkey += (int64_t)m->cpl->jb[k].nrow * m->cpl->jb[k].ncol;
    }
    m->probing = 1;
    rc_status pst = probe_blocks(m, err);
    m->probing = 0;
    if (pst) return pst;
    if (m->gwork_adr >= 0) nkey += 3 * (int64_t)m->nbody;
    /* friction per contact point: all kept (which points act depends on
     * the state), per point of s states (inter_pst) P = s ncol + s nrow +
     * s^2 entries: its rows
     * against the block's columns, the block's rows against its columns, its
     * rows against its columns (layout of inter_ptslot) */
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_npt[i] > 0) {
            const rc_jblock *jb = &m->jb_inter[i];
            const int64_t s = m->inter_pst[i], P = s * jb->ncol + s * jb->nrow + s * s;
            nkey += P * m->inter_npt[i];
            m->inter_ptslot[i] = malloc((size_t)(P * m->inter_npt[i]) * sizeof(int64_t));
            if (!m->inter_ptslot[i]) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
        }
    int64_t *key = malloc((size_t)nkey * sizeof(int64_t));
    if (!key) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    int64_t n = 0;
    for (int64_t k = 0; k < ny; k++) key[n++] = k * ny + k;
    for (int e = 0; e < m->nbody + m->ninter + m->cpl->n; e++) {
        rc_progress(e, m->nbody + m->ninter + m->cpl->n);
        const int nbi = m->nbody + m->ninter;
        const rc_jblock *jb = e < m->nbody ? &m->jb_body[e] : e < nbi ? &m->jb_inter[e - m->nbody] : &m->cpl->jb[e - nbi];
        for (int r = 0; r < jb->nrow; r++)
            for (int c = 0; c < jb->ncol; c++)
                if (jb->slot[r * jb->ncol + c] >= 0) key[n++] = (int64_t)jb->cols[c] * ny + jb->rows[r];
    }
    for (int i = 0; i < m->ninter; i++)
        for (int j = 0; j < m->inter_npt[i]; j++) {
            const rc_jblock *jb = &m->jb_inter[i];
            const int s = m->inter_pst[i], p0 = m->inter_eadr[i] + m->inter_ns[i] + s * j;
            for (int e = 0; e < s; e++)
                for (int c = 0; c < jb->ncol; c++) key[n++] = (int64_t)jb->cols[c] * ny + p0 + e;
            for (int r = 0; r < jb->nrow; r++)
                for (int e = 0; e < s; e++) key[n++] = (int64_t)(p0 + e) * ny + jb->rows[r];
            for (int r = 0; r < s; r++)
                for (int e = 0; e < s; e++) key[n++] = (int64_t)(p0 + e) * ny + p0 + r;
        }
    /* potential of a time-varying gravity: its row against all velocities */
    if (m->gwork_adr >= 0)
        for (int b = 0; b < m->nbody; b++)
            for (int k = 0; k < 3 && m->body_yadr[b] >= 0; k++)
                key[n++] = (int64_t)(m->body_yadr[b] + 7 + k) * ny + m->gwork_adr;
    /* imposed velocities: their work row, the q-dependence of rotations */
    if (m->imp) {
        rc_status ist = rc_imp_pattern_keys(m, &key, &n, err);
        if (ist) {
            free(key);
            return ist;
        }
    }
    /* sort, unique, split into CSC */
    qsort(key, (size_t)n, sizeof(int64_t), rc_cmp_i64);
    int64_t u = 0;
    for (int64_t k = 0; k < n; k++)
        if (u == 0 || key[k] != key[u - 1]) key[u++] = key[k];
    m->nnz = u;
    m->jac_colptr = calloc((size_t)ny + 1, sizeof(int64_t));
    m->jac_rowind = malloc((size_t)u * sizeof(int64_t));
    m->jac_diag = malloc((size_t)ny * sizeof(int64_t));
    if (!m->jac_colptr || !m->jac_rowind || !m->jac_diag) {
        free(key);
        RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
    }
    for (int64_t k = 0; k < u; k++) {
        m->jac_rowind[k] = key[k] % ny;
        m->jac_colptr[key[k] / ny + 1]++;
    }
    free(key);
    for (int64_t c = 0; c < ny; c++) m->jac_colptr[c + 1] += m->jac_colptr[c];
    /* slots */
    for (int64_t k = 0; k < ny; k++) m->jac_diag[k] = rc_jac_slot(m, (int)k, (int)k);
    if (m->gwork_adr >= 0) {
        m->gwork_slot = calloc(3 * (size_t)m->nbody + 1, sizeof(int64_t));
        if (!m->gwork_slot) RC_RAISE(err, RC_ENOMEM, "out of memory for the Jacobian pattern");
        for (int b = 0; b < m->nbody; b++)
            for (int k = 0; k < 3 && m->body_yadr[b] >= 0; k++)
                m->gwork_slot[3 * b + k] = rc_jac_slot(m, m->gwork_adr, m->body_yadr[b] + 7 + k);
    }
    if (m->imp) {
        rc_status ist = rc_imp_slots(m, err);
        if (ist) return ist;
    }
    for (int b = 0; b < m->nbody; b++) {
        rc_status st = fill_slots(m, &m->jb_body[b], err);
        if (st) return st;
    }
    for (int i = 0; i < m->ninter; i++) {
        rc_status st = fill_slots(m, &m->jb_inter[i], err);
        if (st) return st;
    }
    for (int k = 0; k < m->cpl->n; k++) {
        rc_status st = m->cpl->jb[k].slot ? fill_slots(m, &m->cpl->jb[k], err) : RC_OK;
        if (st) return st;
    }
    for (int i = 0; i < m->ninter; i++)
        for (int j = 0; j < m->inter_npt[i]; j++) {
            const rc_jblock *jb = &m->jb_inter[i];
            const int s = m->inter_pst[i];
            const int64_t P = (int64_t)s * jb->ncol + (int64_t)s * jb->nrow + s * s;
            int64_t *sl = m->inter_ptslot[i] + j * P;
            const int p0 = m->inter_eadr[i] + m->inter_ns[i] + s * j;
            for (int e = 0; e < s; e++)
                for (int c = 0; c < jb->ncol; c++) *sl++ = rc_jac_slot(m, p0 + e, jb->cols[c]);
            for (int r = 0; r < jb->nrow; r++)
                for (int e = 0; e < s; e++) *sl++ = rc_jac_slot(m, jb->rows[r], p0 + e);
            for (int r = 0; r < s; r++)
                for (int e = 0; e < s; e++) *sl++ = rc_jac_slot(m, p0 + r, p0 + e);
        }
    return RC_OK;
}

/* ---- The slots that can be nonzero in the present modes ----------------
 * (model.h rc_jac_active; docs/theory.md 7, "The Newton matrix follows the
 * contacts"). A slot is dropped when every element that writes it is
 * inactive: an interface neither closed nor released (no force, its own
 * rates zero) unless its Inacti 5 offset tracks the separation; the
 * contact points of an interface that is not closed; the rows of a contact
 * point out of the contact (share w_j = 0) against the interface's columns
 * when the point's law gives them no value (it slips, its law has no
 * tangential spring state, or that state is zero); a contact coupling with
 * no face pushing. Bodies, joints' stops, springs, catenaries, gravity's
 * and imposed velocities' rows, and the diagonal are always kept. */
enum { AP_NONE = 0, AP_KEEP = 1, AP_DROP = 2 };

static void ap_mark(unsigned char *mk, const int64_t *slot, int64_t n, unsigned char v)
{
    for (int64_t k = 0; k < n; k++)
        if (slot[k] >= 0 && (v == AP_KEEP || mk[slot[k]] == AP_NONE)) mk[slot[k]] = v;
}

/* Is interface i's block (forces and own rates) nonzero in its modes? */
static int ap_inter_on(const rc_data *d, int i)
{
    const int mode = d->inter_mode[i];
    return mode == RC_MODE_CLOSED || mode == RC_MODE_RELEASED || (mode == RC_MODE_OPEN && d->inter_track[i]);
}

static void ap_points(const rc_model *m, const rc_data *d, int i, double t, const double *y, unsigned char *mk,
                      int pass)
{
    const rc_jblock *jb = &m->jb_inter[i];
    const int npt = m->inter_npt[i], s = m->inter_pst[i];
    const int64_t P = (int64_t)s * jb->ncol + (int64_t)s * jb->nrow + (int64_t)s * s, rows = (int64_t)s * jb->ncol;
    const int64_t *sl = m->inter_ptslot[i];
    if (d->inter_mode[i] != RC_MODE_CLOSED) { /* no point writes (assemble_jac.c) */
        if (pass == AP_DROP) ap_mark(mk, sl, P * npt, AP_DROP);
        return;
    }
    if (pass == AP_DROP) return;
    double *w = d->sc->pt_work; /* RC_PT_OUT per point (rc_data_new), free outside the root and Jacobian evaluations */
    rc_points_eval(m, d, i, NULL, t, y, w);
    for (int j = 0; j < npt; j++) {
        const int64_t *pj = sl + j * P;
        /* a point out of the contact applies no force and its states relax
         * on their own (segfric_point): its rows against the interface's
         * columns have no value; the columns of its states (its force on
         * the bodies, its own rates) are kept */
        const int quiet = !(w[RC_PT_OUT * j + 4] > 0);
        ap_mark(mk, pj, rows, quiet ? AP_DROP : AP_KEEP);
        ap_mark(mk, pj + rows, P - rows, AP_KEEP);
    }
}

int rc_jac_active_key(const rc_model *m, const rc_data *d, unsigned char *key)
{
    if (m->npt > 0) return 0; /* the points' rows follow their laws and modes */
    const rc_couplings *c = m->cpl;
    for (int k = 0; c && k < c->n; k++)
        if (c->jb[k].slot && c->kind[k] == RC_CPL_CONTACT) return 0; /* their faces' modes */
    for (int i = 0; i < m->ninter; i++) key[i] = (unsigned char)ap_inter_on(d, i);
    return 1;
}

int64_t rc_jac_active(const rc_model *m, const rc_data *d, double t, const double *y, unsigned char *keep)
{
    memset(keep, AP_NONE, (size_t)m->nnz);
    /* drops first, then every slot an active element writes is kept */
    for (int pass = AP_DROP; pass >= AP_KEEP; pass--) {
        for (int i = 0; i < m->ninter; i++) {
            const rc_jblock *jb = &m->jb_inter[i];
            const int on = ap_inter_on(d, i);
            if (jb->slot && (on ? AP_KEEP : AP_DROP) == pass) ap_mark(keep, jb->slot, (int64_t)jb->nrow * jb->ncol, (unsigned char)pass);
            if (m->inter_npt[i] > 0) ap_points(m, d, i, t, y, keep, pass);
        }
        const rc_couplings *c = m->cpl;
        for (int k = 0; c && k < c->n; k++) {
            const rc_jblock *jb = &c->jb[k];
            if (!jb->slot) continue;
            int on = 1;
            if (c->kind[k] == RC_CPL_CONTACT && d->cpl) {
                on = 0;
                for (int f = c->ct->fadr[k]; f < c->ct->fadr[k + 1]; f++) on |= d->cpl->fmode[f] == RC_FACE_PUSH;
            }
            if ((on ? AP_KEEP : AP_DROP) == pass) ap_mark(keep, jb->slot, (int64_t)jb->nrow * jb->ncol, (unsigned char)pass);
        }
    }
    /* bodies, the imposed velocities' slots, the diagonal: kept */
    for (int b = 0; b < m->nbody; b++)
        if (m->jb_body[b].slot) ap_mark(keep, m->jb_body[b].slot, (int64_t)m->jb_body[b].nrow * m->jb_body[b].ncol, AP_KEEP);
    if (m->imp) {
        ap_mark(keep, m->imp->rqslot, 12 * (int64_t)m->imp->nr, AP_KEEP);
        ap_mark(keep, m->imp->wslot, m->ny, AP_KEEP);
    }
    ap_mark(keep, m->jac_diag, m->ny, AP_KEEP);
    int64_t n = 0;
    for (int64_t k = 0; k < m->nnz; k++) {
        keep[k] = keep[k] != AP_DROP;
        n += keep[k];
    }
    return n;
}
