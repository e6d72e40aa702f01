/*
 * The run data (data.h): allocated per run for a compiled model, every
 * array sized by the model, freed in one call.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/assembly/data.h"
#include "model/coupling.h"
#include "model/segsurf.h"

rc_data *rc_data_new(const rc_model *m)
{
    rc_data *d = calloc(1, sizeof *d);
    if (!d) return NULL;
    if (!(d->sc = calloc(1, sizeof *d->sc))) {
        free(d);
        return NULL;
    }
    size_t n = (size_t)m->ninter + 1;
    d->inter_mode = calloc(n, sizeof(int));
    d->inter_branch = calloc(n, sizeof(int));
    d->inter_track = calloc(n, sizeof(int));
    d->inter_slip = calloc(n, sizeof(int));
    d->inter_dref = calloc(3 * n, sizeof(double));
    d->inter_band = calloc(2 * n, sizeof(double));
    d->inter_rband = calloc(n + 1, sizeof(double));
    d->inter_settled = calloc(n, sizeof(int));
    d->inter_lowq = calloc(n, sizeof(int));
    d->inter_deck = calloc(n, sizeof(int));
    d->inter_hacc = calloc(2 * n, sizeof(double));
    d->mode_was = calloc(n, sizeof(int));
    d->sens_ton = calloc((size_t)m->nsens + 1, sizeof(double));
    d->sens_new = calloc((size_t)m->nsens + 1, sizeof(int));
    d->sens_arm = calloc(2 * (size_t)m->nsens + 1, sizeof(double));
    d->sens_rel = calloc((size_t)m->nsens + 1, sizeof(int));
    d->t_bp = -INFINITY;
    d->inter_fcstr = calloc(n, sizeof(double));
    d->cpl = rc_cpl_data_new(m);
    /* friction per contact point: modes, and the scratch of the roots
     * (RC_PT_OUT per point) and of the Jacobian (complex own and point states and rates) */
    int maxpt = 0;
    for (int i = 0; i < m->ninter; i++) maxpt = m->inter_npt[i] > maxpt ? m->inter_npt[i] : maxpt;
    int maxnode = 0;
    for (int i = 0; i < m->ninter; i++)
        if (rc_pair_nodes(m->inter_pair[i]) && rc_seg_points(m, i) > maxnode) maxnode = rc_seg_points(m, i);
    {
        /* the hints, then the node cache (its offset a multiple of 16
         * bytes), then the points a Jacobian column computes into it */
        const size_t nh = (size_t)rc_seg_hint_len(m), ncd = 2 * RC_NODE_CACHE * (size_t)maxnode + 2;
        d->sc->seg_hint = calloc(nh * sizeof(int) + ncd * sizeof(double) + (size_t)maxnode + 1, 1);
        if (d->sc->seg_hint) {
            for (size_t k = 0; k < nh; k++) d->sc->seg_hint[k] = -1;
            d->sc->node_cache = d->sc->seg_hint + nh;
            d->sc->node_only = (unsigned char *)((double *)d->sc->node_cache + ncd);
        }
    }
    d->pt_slip = calloc((size_t)m->npt + 1, sizeof(int));
    d->sc->pt_share = malloc(((size_t)m->npt + 1) * sizeof(double));
    d->pt_lband = calloc((size_t)m->npt + 1, sizeof(double));
    d->sc->inter_flim = calloc(2 * (size_t)m->ninter + 1, sizeof(double));
    d->sc->inter_fnr = calloc((size_t)m->ninter + 1, sizeof(double));
    if (d->sc->pt_share)
        for (int j = 0; j <= m->npt; j++) d->sc->pt_share[j] = 1.0;
    d->sc->pt_work = calloc(RC_PT_OUT * (size_t)maxpt + 4 * ((size_t)RC_NS_MAX + 6 * (size_t)maxpt) + 16, sizeof(double));
    /* the point flips' scratch (points_flip): 4 doubles, an int and a flag per point */
    d->pt_flip = malloc((size_t)maxpt * (4 * sizeof(double) + sizeof(int) + 1) + 1);
    /* the reports of the last root evaluation (rc_report_cache_state) */
    int rc_ok = 0;
    d->sc->repc = calloc(1, sizeof *d->sc->repc);
    if (d->sc->repc) {
        d->sc->repc->y = calloc((size_t)m->ny + 1, sizeof(double));
        d->sc->repc->rep = calloc(n, sizeof *d->sc->repc->rep);
        d->sc->repc->key = malloc(4 * n * sizeof(int));
        d->sc->repc->pslip = calloc((size_t)m->npt + 1, sizeof(int));
        rc_ok = d->sc->repc->y && d->sc->repc->rep && d->sc->repc->key && d->sc->repc->pslip;
        if (rc_ok)
            for (size_t k = 0; k < 4 * n; k++) d->sc->repc->key[k] = -1;
    }
    int imp_ok = 1;
    if (m->imp) { /* imposed velocities: scratch of rhs and Jacobian (imposed.c) */
        d->sc->imp_free = calloc((size_t)m->ny, sizeof(double));
        d->sc->imp_scratch = calloc(3 * (size_t)m->ny, sizeof(double));
        imp_ok = d->sc->imp_free && d->sc->imp_scratch;
    }
    int jc_ok = 1;
    if (m->jb_inter) { /* the interfaces' Jacobian blocks (rc_jac_refresh_inter) */
        d->sc->jcache_off = malloc(n * sizeof *d->sc->jcache_off);
        jc_ok = d->sc->jcache_off != NULL;
        int64_t off = 0;
        for (int i = 0; jc_ok && i < m->ninter; i++) {
            d->sc->jcache_off[i] = off;
            off += (int64_t)m->jb_inter[i].nrow * m->jb_inter[i].ncol;
        }
        if (jc_ok) {
            d->sc->jcache_off[m->ninter] = off;
            d->sc->jcache = calloc((size_t)off + 1, sizeof(double));
            jc_ok = d->sc->jcache != NULL;
        }
    }
    if (!d->inter_mode || !d->inter_branch || !d->inter_track || !d->inter_slip || !d->inter_dref || !d->inter_band || !d->inter_rband || !d->inter_settled || !d->inter_lowq || !d->inter_deck || !d->inter_hacc || !d->mode_was || !d->sens_ton || !d->sens_new || !d->sens_arm || !d->sens_rel || !d->inter_fcstr || !d->cpl || !imp_ok || !jc_ok || !rc_ok ||
        !d->pt_slip || !d->sc->pt_share || !d->sc->inter_flim || !d->sc->inter_fnr || !d->pt_lband || !d->sc->pt_work || !d->pt_flip || !d->sc->node_cache) {
        rc_data_free(d);
        return NULL;
    }
    d->sc->fail_inter = -1;
    return d;
}

void rc_data_free(rc_data *d)
{
    if (!d) return;
    free(d->inter_mode);
    free(d->inter_branch);
    free(d->inter_track);
    free(d->inter_slip);
    free(d->inter_dref);
    free(d->inter_band);
    free(d->inter_deck);
    free(d->inter_rband);
    free(d->inter_settled);
    free(d->inter_lowq);
    free(d->inter_hacc);
    free(d->mode_was);
    free(d->sens_ton);
    free(d->sens_rel);
    free(d->sens_new);
    free(d->sens_arm);
    free(d->inter_fcstr);
    free(d->pt_slip);
    free(d->sc->pt_share);
    free(d->sc->inter_flim);
    free(d->sc->inter_fnr);
    free(d->pt_lband);
    free(d->sc->pt_work);
    free(d->pt_flip);
    free(d->sc->seg_hint); /* and the node cache */
    rc_cpl_data_free(d->cpl);
    free(d->sc->imp_free);
    free(d->sc->imp_scratch);
    free(d->sc->jcache);
    free(d->sc->jcache_off);
    if (d->sc->repc) {
        free(d->sc->repc->y);
        free(d->sc->repc->rep);
        free(d->sc->repc->key);
        free(d->sc->repc->pslip);
        free(d->sc->repc);
    }
    free(d->sc);
    free(d);
}

const char *rc_cpl_failed(const rc_model *m, const rc_data *d)
{
    return d->cpl->fail >= 0 ? m->cpl->name[d->cpl->fail] : NULL;
}
