/*
 * Imposed velocities in the right-hand side (model/imposed.h), in real
 * arithmetic. Overwrites the rates of the imposed rows, after every force
 * has been added to them (their values are then the free accelerations),
 * and integrates minus the power of the reactions into W_imp.
 */
#include <math.h>
#include <tgmath.h>

#include "model/imposed.h"
#include "model/model.h"
#include "model/table.h"
#include "engine/assembly/assembly.h"

#include "engine/kernels/as_real.h"
#include "engine/kernels/vec.inc"

double rc_imp_rate(const rc_model *m, int tab, double ascale, double fscale, double t)
{
    if (tab < 0) return 0.0; /* held at zero (/BCS along a skew axis) */
    double f, df;
    rc_table_eval(&m->table[tab], t / ascale, &f, &df);
    return fscale * df / ascale;
}

void rc_imp_rhs(const rc_model *m, const rc_data *d, double t, const double *y, double *ydot)
{
    const rc_imposed *p = m->imp;
    double power = 0.0; /* of the reactions [W] */
    /* translations: reaction m (a_imposed - a_free) along the component */
    for (int k = 0; k < p->nt; k++) {
        const int r = p->trow[k];
        /* a body's skewed entries (orthogonal axes) apply one after the
         * other, u.a_free unchanged by the projections before; the free
         * rates, which the Jacobian measures each lambda by, are those its
         * first skewed entry finds, kept whether that entry acts or not (an
         * /IMPVEL past its Tstop beside /BCS holds) */
        if (p->tfirst[k])
            for (int i = 0; i < 3; i++) d->sc->imp_free[r + i] = ydot[r + i];
        if (!RC_IMP_T_ON(p, k, t, d->sens_rel, d->t_bp)) continue;
        const double a = rc_imp_rate(m, p->ttab[k], p->tascale[k], p->tfscale[k], t - RC_IMP_T_SHIFT(p, k, d->sens_ton));
        if (p->tdir[k] < 0) {
            /* along u: the support's force m lambda u, lambda = a - u.a_free */
            const double *u = p->tu + 3 * k;
            double ua = 0.0, uv = 0.0;
            for (int i = 0; i < 3; i++) {
                ua += u[i] * ydot[r + i];
                uv += u[i] * y[r + i];
            }
            const double lam = a - ua;
            for (int i = 0; i < 3; i++) ydot[r + i] += lam * u[i];
            power += m->body_mass[p->tbody[k]] * lam * uv;
            continue;
        }
        d->sc->imp_free[r] = ydot[r];
        power += m->body_mass[p->tbody[k]] * (a - ydot[r]) * y[r];
        ydot[r] = a;
    }
    /* rotations: omega = R^T w_g(t), rate R^T dw_g/dt; reaction torque
     * J (omegadot_imposed - omegadot_free), body frame */
    for (int j = 0; j < p->nr; j++) {
        if (!RC_IMP_R_ON(p, j, t, d->sens_rel)) continue;
        const int b = p->rbody[j], a = m->body_yadr[b];
        const double *J = m->body_J + 9 * b, *w = y + a + 10;
        double wgd[3], wd[3], dw[3];
        for (int k = 0; k < 3; k++) {
            const int tab = p->rtab[3 * j + k];
            wgd[k] = tab < 0 ? 0.0 : rc_imp_rate(m, tab, p->rascale[3 * j + k], p->rfscale[3 * j + k], t);
        }
        rotate_r(y + a + 3, wgd, wd, 1);
        for (int k = 0; k < 3; k++) {
            d->sc->imp_free[a + 10 + k] = ydot[a + 10 + k];
            dw[k] = wd[k] - ydot[a + 10 + k];
            ydot[a + 10 + k] = wd[k];
        }
        for (int k = 0; k < 3; k++) power += w[k] * (J[3 * k] * dw[0] + J[3 * k + 1] * dw[1] + J[3 * k + 2] * dw[2]);
    }
    ydot[p->wadr] = -power;
}

/* Translation k of the imposed velocities starts: the velocity (along u:
 * its component along u) jumps to the imposed value at the function's
 * argument x; the support's impulse does the work m (|v1|^2 - |v0|^2) / 2,
 * which W_imp takes back. */
static void start_translation(const rc_model *m, const rc_imposed *p, int k, double x, double *y)
{
    double f, df;
    rc_table_eval(&m->table[p->ttab[k]], x, &f, &df);
    const int r = p->trow[k], nr = p->tdir[k] < 0 ? 3 : 1;
    const double *u = p->tu + 3 * k;
    double uv = 0.0, e0 = 0.0, e1 = 0.0;
    for (int i = 0; i < nr; i++) uv += (nr == 3 ? u[i] : 1.0) * y[r + i];
    const double dv = p->tfscale[k] * f - uv;
    for (int i = 0; i < nr; i++) {
        e0 += y[r + i] * y[r + i];
        y[r + i] += dv * (nr == 3 ? u[i] : 1.0);
        e1 += y[r + i] * y[r + i];
    }
    y[p->wadr] -= 0.5 * m->body_mass[p->tbody[k]] * (e1 - e0);
}

int rc_imp_start(const rc_model *m, double t0, double t1, double *y)
{
    const rc_imposed *p = m->imp;
    int n = 0;
    for (int k = 0; p && k < p->nt; k++) {
        const double ts = p->ttstart[k];
        if (!(ts > t0 && ts <= t1) || ts > p->ttstop[k]) continue;
        start_translation(m, p, k, (ts - p->ttshift[k]) / p->tascale[k], y);
        n++;
    }
    return n;
}

int rc_imp_start_sens(const rc_model *m, const rc_data *d, int s, double t, double *y)
{
    const rc_imposed *p = m->imp;
    int n = 0;
    for (int k = 0; p && k < p->nt; k++) {
        if (p->tson[k] != s || t > p->ttstop[k]) continue;
        start_translation(m, p, k, (t - d->sens_ton[s]) / p->tascale[k], y); /* as rc_imp_start */
        n++;
    }
    return n;
}
