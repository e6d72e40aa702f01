/*
 * /COUPLING/CONTACT into rc_couplings (coupling_contact.h): the body's
 * segment surface cut into faces (centroid, normal, area in the body
 * frame), the opposing surface and the side of it the body is on, the
 * coefficients given or estimated (STAR-CCM+'s estimators; docs/theory.md
 * "Contact coupling").
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "case/case_coupling.h"
#include "model/coupling.h"
#include "model/coupling_contact.h"


rc_status rc_cpl_contact_alloc(rc_model *m, rc_error *err)
{
    rc_couplings *p = m->cpl;
    rc_cpl_contact *ct = calloc(1, sizeof *ct);
    if (!ct) RC_RAISE(err, RC_ENOMEM, "out of memory");
    p->ct = ct;
    const size_t n = (size_t)p->n + 1;
    int **ia[] = {&ct->fadr, &ct->sf1, &ct->sf2, &ct->est};
    for (size_t i = 0; i < sizeof ia / sizeof ia[0]; i++)
        if (!(*ia[i] = calloc(n + 1, sizeof(int)))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    double **da[] = {&ct->side, &ct->d0, &ct->k1, &ct->k2, &ct->mu, &ct->kt, &ct->vimp, &ct->dmin,
                     &ct->zeta, &ct->area, &ct->mred, &ct->tau, &ct->atot};
    for (size_t i = 0; i < sizeof da / sizeof da[0]; i++)
        if (!(*da[i] = calloc(n, sizeof(double)))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    if (!(ct->face = calloc(1, sizeof(double)))) RC_RAISE(err, RC_ENOMEM, "out of memory");
    return RC_OK;
}

void rc_cpl_contact_free(rc_cpl_contact *ct)
{
    if (!ct) return;
    void *a[] = {ct->fadr, ct->face, ct->sf1, ct->sf2, ct->side, ct->d0, ct->k1, ct->k2, ct->mu, ct->kt,
                 ct->est, ct->vimp, ct->dmin, ct->zeta, ct->area, ct->mred, ct->tau, ct->atot};
    for (size_t i = 0; i < sizeof a / sizeof a[0]; i++) free(a[i]);
    free(ct);
}

int rc_cpl_nroots(const rc_model *m)
{
    /* the faces of the contact couplings, then the joint stops, then the
     * springs' ruptures */
    return (m->cpl && m->cpl->ct ? RC_FACE_ROOTS * m->cpl->ct->nface : 0) + RC_LIM_ROOTS * rc_cpl_nlim(m) +
           (m->cpl ? m->cpl->nrup : 0);
}

int rc_root_sens_base(const rc_model *m) { return rc_root_cpl_base(m) + rc_cpl_nroots(m); }
int rc_root_count(const rc_model *m) { return rc_root_sens_base(m) + 2 * m->nsens; }

/* Global point at t = 0 of body-frame point s of body b (-1: fixed). */
static void point0(const rc_model *m, int b, const double *s, double *x)
{
    const double *org = b >= 0 ? m->body_y0 + RC_NB * b : m->ground_y0;
    for (int i = 0; i < 3; i++) x[i] = org[i] + s[i];
}

/* Is the global point x inside analytic surface s (at t = 0)? Plane: on
 * the side its normal points away from. */
static int inside0(const rc_model *m, int s, const double *x)
{
    double c[3], r[3];
    point0(m, m->surf_body[s], m->surf_p + 3 * s, c);
    for (int i = 0; i < 3; i++) r[i] = x[i] - c[i];
    const double *n = m->surf_n + 3 * s, *e = m->surf_ext + RC_SURF_NEXT * s;
    switch (m->surf_kind[s]) {
    case RC_SURF_PLANE: return r[0] * n[0] + r[1] * n[1] + r[2] * n[2] < 0;
    case RC_SURF_SPHERE: return r[0] * r[0] + r[1] * r[1] + r[2] * r[2] < m->surf_r[s] * m->surf_r[s];
    case RC_SURF_CYL: {
        const double a = r[0] * n[0] + r[1] * n[1] + r[2] * n[2];
        double q = 0.0;
        for (int i = 0; i < 3; i++) q += (r[i] - a * n[i]) * (r[i] - a * n[i]);
        return q < m->surf_r[s] * m->surf_r[s];
    }
    case RC_SURF_BOX:
        for (int k = 0; k < 3; k++) {
            const double *u = e + 3 + 3 * k;
            if (fabs(r[0] * u[0] + r[1] * u[1] + r[2] * u[2]) >= e[k]) return 0;
        }
        return 1;
    default: return 0;
    }
}

rc_status rc_cpl_contact_compile(const rc_case *c, rc_model *m, int k, rc_error *err)
{
    const rc_case_coupling *cc = &c->coupling[k];
    rc_couplings *p = m->cpl;
    rc_cpl_contact *ct = p->ct;
    const char *card = p->name[k];
    const rc_loc l1 = rc_loc_or(cc->line_loc[0], cc->loc), l2 = rc_loc_or(cc->line_loc[1], cc->loc),
                 l3 = rc_loc_or(cc->line_loc[2], cc->loc);
    p->law_loc[k] = l2;
    p->table[k] = -1;
    const int s1 = rc_case_find_surf(c, cc->surf[0]), s2 = rc_case_find_surf(c, cc->surf[1]);
    if (s1 < 0 || s2 < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: expected the id of a /SURF, got %d (no such surface)",
                 RC_LOC(l1), card, s1 < 0 ? "surf_ID1" : "surf_ID2", s1 < 0 ? cc->surf[0] : cc->surf[1]);
    if (m->surf_kind[s1] != RC_SURF_SEG || m->surf_body[s1] < 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, field surf_ID1: expected the segment surface (/SURF/SEG or /SURF/PART) of a rigid "
                 "body, whose faces carry the contact forces, got /SURF %d (%s)",
                 RC_LOC(l1), card, cc->surf[0], m->surf_kind[s1] != RC_SURF_SEG ? "an analytic surface" : "fixed in space");
    /* a cylinder acts by its lateral surface only, whatever its ends (theory) */
    const int b1 = m->surf_body[s1], b2 = m->surf_body[s2];
    if (b1 == b2)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s, fields surf_ID1/surf_ID2: both surfaces are on the same body; the opposing "
                 "surface must be fixed or on another body",
                 RC_LOC(l1), card);
    p->b1[k] = b1;
    p->b2[k] = b2;
    ct->sf1[k] = s1;
    ct->sf2[k] = s2;
    /* the faces: centroid, unit normal, area (quadrilaterals as two
     * triangles), body frame */
    const int nf = m->surf_sadr[s1 + 1] - m->surf_sadr[s1], f0 = ct->nface;
    double *fa = realloc(ct->face, ((size_t)(f0 + nf) * RC_FACE_NV + 1) * sizeof(double));
    if (!fa) RC_RAISE(err, RC_ENOMEM, "out of memory");
    ct->face = fa;
    ct->fadr[k] = f0;
    double atot = 0.0;
    for (int j = 0; j < nf; j++) {
        const int *sg = m->surf_seg + 4 * (m->surf_sadr[s1] + j);
        const double *x[4];
        for (int v = 0; v < 4; v++) x[v] = m->surf_node + 3 * (m->surf_nadr[s1] + sg[v]);
        const int ntri = sg[3] == sg[2] ? 1 : 2;
        double A = 0.0, cen[3] = {0, 0, 0}, nv[3] = {0, 0, 0};
        for (int t = 0; t < ntri; t++) {
            const double *a = x[0], *b = x[1 + t], *cc2 = x[2 + t];
            double u[3], w[3], cr[3];
            for (int i = 0; i < 3; i++) {
                u[i] = b[i] - a[i];
                w[i] = cc2[i] - a[i];
            }
            cr[0] = u[1] * w[2] - u[2] * w[1];
            cr[1] = u[2] * w[0] - u[0] * w[2];
            cr[2] = u[0] * w[1] - u[1] * w[0];
            const double at = 0.5 * sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
            for (int i = 0; i < 3; i++) {
                cen[i] += at * (a[i] + b[i] + cc2[i]) / 3.0;
                nv[i] += 0.5 * cr[i];
            }
            A += at;
        }
        double *f = ct->face + RC_FACE_NV * (f0 + j);
        const double nn = sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
        for (int i = 0; i < 3; i++) {
            f[i] = A > 0 ? cen[i] / A : x[0][i];
            f[3 + i] = nn > 0 ? nv[i] / nn : 0.0;
        }
        f[6] = A;
        atot += A;
    }
    ct->nface = f0 + nf;
    ct->fadr[k + 1] = ct->nface;
    ct->atot[k] = atot;
    /* the side: the body's centre at t = 0, unless Iside says */
    double xc[3];
    point0(m, b1, (const double[3]){0, 0, 0}, xc);
    /* a segment surface: its segments' normal side unless Iside 2 */
    const int in = cc->iside == 2 || (cc->iside == 0 && m->surf_kind[s2] != RC_SURF_SEG && inside0(m, s2, xc));
    ct->side[k] = in ? -1.0 : 1.0;
    /* the law */
    ct->d0[k] = cc->d0;
    ct->mu[k] = cc->mu;
    ct->kt[k] = cc->kt;
    ct->est[k] = cc->iest;
    ct->vimp[k] = cc->vimp;
    ct->dmin[k] = cc->dmin;
    ct->zeta[k] = cc->zeta;
    ct->area[k] = cc->area;
    double inv = 0.0;
    const int bs[2] = {b1, b2};
    for (int e = 0; e < 2; e++)
        if (bs[e] >= 0 && m->body_yadr[bs[e]] >= 0) inv += 1.0 / m->body_mass[bs[e]];
    ct->mred[k] = inv > 0 ? 1.0 / inv : INFINITY;
    if (cc->iest) {
        if (!isfinite(ct->mred[k]))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field Iest: neither body moves, so no stiffness can be estimated",
                     RC_LOC(l1), card);
        const double dd = cc->d0 - cc->dmin;
        ct->k1[k] = ct->mred[k] * cc->vimp * cc->vimp / (cc->area * dd * dd);
        ct->k2[k] = 2.0 * cc->zeta * sqrt(ct->mred[k] * ct->k1[k] / cc->area);
        if (!(isfinite(ct->k1[k]) && ct->k1[k] > 0 && isfinite(ct->k2[k])))
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s, fields V_imp d_min zeta A: the estimated coefficients k1 = %g N/m^3, k2 = %g "
                     "N s/m^3 leave the range of the doubles; expected values of ordinary magnitude",
                     RC_LOC(l3), card, ct->k1[k], ct->k2[k]);
    } else {
        ct->k1[k] = cc->k1;
        ct->k2[k] = cc->k2;
    }
    const double Aest = cc->iest ? cc->area : atot;
    ct->tau[k] = isfinite(ct->mred[k]) && Aest > 0 ? 0.5 * RC_PI * sqrt(ct->mred[k] / (Aest * ct->k1[k])) : NAN;
    if (!(atot > 0))
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field surf_ID1: the segment surface %d has no face of non-zero area",
                 RC_LOC(l1), card, cc->surf[0]);
    return RC_OK;
}
