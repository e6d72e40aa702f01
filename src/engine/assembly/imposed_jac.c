/*
 * Imposed velocities in the Jacobian (model/imposed.h). Called when every
 * element has added its entries: the imposed rows then hold the
 * derivatives of the free accelerations, which give the W_imp row; then the
 * rows are replaced by the derivatives of the imposed rates (zero for
 * translations; for rotations, of R(q)^T dw_g/dt with respect to q, by
 * complex step).
 */
#include <complex.h>
#include <math.h>
#include <string.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/model.h"
#include "engine/assembly/assembly.h"
#include "engine/kernels/cstep.h"

#include "engine/kernels/as_complex.h"
#include "engine/kernels/vec.inc"

int rc_imp_jac(const rc_model *m, const rc_data *d, double t, const double *y, double *val)
{
    const rc_imposed *p = m->imp;
    const int ny = m->ny;
    double *act = d->sc->imp_scratch, *dp = d->sc->imp_scratch + ny, *cf = d->sc->imp_scratch + 2 * ny;
    /* the free accelerations at (t, y) (the rhs keeps them in imp_free) */
    const long nrhs = d->sc->n_rhs;
    if (rc_assemble_rhs(m, d, t, y, act)) return 1;
    d->sc->n_rhs = nrhs;
    memset(act, 0, (size_t)ny * sizeof(double));
    memset(dp, 0, (size_t)ny * sizeof(double));
    /* dP/dy, P the power of the reactions; cf[r]: dP/d(free rate of row r) */
    for (int k = 0; k < p->nt; k++) {
        if (!RC_IMP_T_ON(p, k, t, d->sens_rel, d->t_bp) || p->tdir[k] < 0) continue;
        const int r = p->trow[k];
        const double mass = m->body_mass[p->tbody[k]];
        const double a = rc_imp_rate(m, p->ttab[k], p->tascale[k], p->tfscale[k], t - RC_IMP_T_SHIFT(p, k, d->sens_ton));
        act[r] = 1.0;
        cf[r] = -mass * y[r];
        dp[r] += mass * (a - d->sc->imp_free[r]);
    }
    for (int j = 0; j < p->nr; j++) {
        if (!RC_IMP_R_ON(p, j, t, d->sens_rel)) continue;
        const int b = p->rbody[j], a = m->body_yadr[b];
        const double *J = m->body_J + 9 * b, *w = y + a + 10;
        double wgd[3], jw[3];
        for (int k = 0; k < 3; k++) {
            const int tab = p->rtab[3 * j + k];
            wgd[k] = tab < 0 ? 0.0 : rc_imp_rate(m, tab, p->rascale[3 * j + k], p->rfscale[3 * j + k], t);
            jw[k] = J[3 * k] * w[0] + J[3 * k + 1] * w[1] + J[3 * k + 2] * w[2];
        }
        T q[4], wg[3] = {wgd[0], wgd[1], wgd[2]}, wd[3];
        rc_cs_load(y + a + 3, 4, q);
        rotate_c(q, wg, wd, 1);
        double tau[3], dwv[3];
        for (int k = 0; k < 3; k++) dwv[k] = creal(wd[k]) - d->sc->imp_free[a + 10 + k];
        for (int k = 0; k < 3; k++) tau[k] = J[3 * k] * dwv[0] + J[3 * k + 1] * dwv[1] + J[3 * k + 2] * dwv[2];
        for (int k = 0; k < 3; k++) {
            act[a + 10 + k] = 1.0;
            cf[a + 10 + k] = -jw[k];
            dp[a + 10 + k] += tau[k];
        }
        /* q-dependence of the imposed rate, exact by complex step */
        for (int c = 0; c < 4; c++) {
            rc_cs_step(&q[c]);
            rotate_c(q, wg, wd, 1);
            rc_cs_unstep(&q[c]);
            for (int k = 0; k < 3; k++) dp[a + 3 + c] += jw[k] * cimag(wd[k]) / RC_CSTEP;
        }
    }
    /* along a skew axis u: the rows become (I - u u^T) the free rows, and
     * P = m lambda (u.v) with lambda = a - u.a_free gives dP/dy = m lambda u
     * on the velocities and -m (u.v) u.(d a_free/dy) */
    for (int k = 0; k < p->nt; k++) {
        if (!RC_IMP_T_ON(p, k, t, d->sens_rel, d->t_bp) || p->tdir[k] >= 0) continue;
        const int r = p->trow[k];
        const double mass = m->body_mass[p->tbody[k]], *u = p->tu + 3 * k;
        const double a = rc_imp_rate(m, p->ttab[k], p->tascale[k], p->tfscale[k], t - RC_IMP_T_SHIFT(p, k, d->sens_ton));
        double ua = 0.0, uv = 0.0;
        for (int i = 0; i < 3; i++) {
            ua += u[i] * d->sc->imp_free[r + i];
            uv += u[i] * y[r + i];
        }
        for (int i = 0; i < 3; i++) dp[r + i] += mass * (a - ua) * u[i];
        const int64_t *sl = p->sslot + 3 * (size_t)p->tsk[k] * (size_t)ny;
        for (int c = 0; c < ny; c++) {
            const int64_t s0 = sl[c], s1 = sl[ny + c], s2 = sl[2 * ny + c];
            if (s0 < 0 && s1 < 0 && s2 < 0) continue;
            const double v[3] = {s0 >= 0 ? val[s0] : 0.0, s1 >= 0 ? val[s1] : 0.0, s2 >= 0 ? val[s2] : 0.0};
            const double uj = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
            dp[c] -= mass * uv * uj;
            if (s0 >= 0) val[s0] = v[0] - u[0] * uj;
            if (s1 >= 0) val[s1] = v[1] - u[1] * uj;
            if (s2 >= 0) val[s2] = v[2] - u[2] * uj;
        }
    }
    /* free-rate dependence into dP, then the imposed rows cleared */
    for (int c = 0; c < ny; c++)
        for (int64_t k = m->jac_colptr[c]; k < m->jac_colptr[c + 1]; k++) {
            const int r = (int)m->jac_rowind[k];
            if (act[r] == 0.0) continue;
            dp[c] += cf[r] * val[k];
            val[k] = 0.0;
        }
    /* the rotation rows: d(R^T dw_g/dt)/dq */
    for (int j = 0; j < p->nr; j++) {
        if (!RC_IMP_R_ON(p, j, t, d->sens_rel)) continue;
        const int b = p->rbody[j], a = m->body_yadr[b];
        double wgd[3];
        for (int k = 0; k < 3; k++) {
            const int tab = p->rtab[3 * j + k];
            wgd[k] = tab < 0 ? 0.0 : rc_imp_rate(m, tab, p->rascale[3 * j + k], p->rfscale[3 * j + k], t);
        }
        T q[4], wg[3] = {wgd[0], wgd[1], wgd[2]}, wd[3];
        rc_cs_load(y + a + 3, 4, q);
        for (int c = 0; c < 4; c++) {
            rc_cs_step(&q[c]);
            rotate_c(q, wg, wd, 1);
            rc_cs_unstep(&q[c]);
            for (int k = 0; k < 3; k++)
                if (p->rqslot[12 * j + 4 * k + c] >= 0) val[p->rqslot[12 * j + 4 * k + c]] = rc_cs_deriv(wd[k]);
        }
    }
    /* the W_imp row: dW_imp/dt = -P */
    for (int c = 0; c < ny; c++)
        if (p->wslot[c] >= 0) val[p->wslot[c]] = -dp[c];
    return 0;
}
