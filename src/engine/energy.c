/* Energies of the state: kinetic, potential, interface work and stored
 * energy, friction, couplings, imposed velocities (docs/theory.md). Reads
 * the interface reports of assemble_rhs.c and the body views of body.c. */
#include <string.h>

#include "model/coupling.h"
#include "model/imposed.h"
#include "model/model.h"
#include "model/power.h"

/* Elastic energy stored in interface i: what the bodies would recover by
 * unloading it completely along the law (Iform 0: the load curve; Iform 1, 2:
 * the Stiff line down to the unload curve or zero, then the unload curve). */
double rc_inter_stored_energy(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    const int mode = d->inter_mode[i];
    if (mode != RC_MODE_CLOSED && mode != RC_MODE_RELEASED) return 0.0;
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    const double ax = m->inter_ascalex[i], P = r.pl, F = r.fload; /* the law's penetration */
    if (P <= 0) return 0.0;
    if (m->inter_law[i] == RC_LAW_POWER) return rc_power_stored(m, i, P); /* integral of F_k */
    if (m->inter_iform[i] == 0)
        return m->inter_fscaleld[i] * ax * rc_table_integral(&m->table[m->inter_fct_ld[i]], 0.0, P / ax);
    const double k = m->inter_stiff[i];
    if (m->inter_fct_ul[i] < 0 || F <= 0) return F > 0 ? 0.5 * F * F / k : 0.0;
    /* the Stiff line meets the unload curve at P*: bisection on
     * g(P*) = F - k (P - P*) - F_U(P*), g(P - F/k) <= 0 <= g(P) */
    const rc_table *tu = &m->table[m->inter_fct_ul[i]];
    const double fs = m->inter_fscaleul[i];
    double lo = P - F / k, hi = P, fu, dd;
    for (int it = 0; it < 80; it++) {
        double mid = 0.5 * (lo + hi);
        rc_table_eval(tu, mid / ax, &fu, &dd);
        if (F - k * (P - mid) - fs * fu > 0) hi = mid;
        else lo = mid;
    }
    rc_table_eval(tu, hi / ax, &fu, &dd);
    double tri = 0.5 * (F + fs * fu) * (P - hi);
    return tri + (hi > 0 ? fs * ax * rc_table_integral(tu, 0.0, hi / ax) : 0.0);
}

void rc_energy(const rc_model *m, const rc_data *d, double t, const double *y, double e[RC_NENERGY])
{
    memset(e, 0, RC_NENERGY * sizeof(double));
    for (int b = 0; b < m->nbody; b++) {
        if (m->body_yadr[b] < 0) continue;
        const double *s = y + m->body_yadr[b];
        const double *J = m->body_J + 9 * b;
        const double *w = s + 10;
        double g[3];
        rc_gravity(m, b, t, g);
        /* 1/2 m v.v + 1/2 w.J w ; potential -m g.x */
        double rot = 0.0;
        for (int k = 0; k < 3; k++)
            rot += w[k] * (J[3 * k] * w[0] + J[3 * k + 1] * w[1] + J[3 * k + 2] * w[2]);
        e[RC_E_KIN] += 0.5 * m->body_mass[b] * (s[7] * s[7] + s[8] * s[8] + s[9] * s[9]) + 0.5 * rot;
        e[RC_E_POT] -= m->body_mass[b] * (g[0] * s[0] + g[1] * s[1] + g[2] * s[2]);
    }
    if (m->gwork_adr >= 0) e[RC_E_POT] = y[m->gwork_adr]; /* time-varying gravity */
    for (int i = 0; i < m->ninter; i++) {
        e[RC_E_WORK] += y[m->inter_eadr[i]];
        e[RC_E_DAMP] += y[m->inter_eadr[i] + 1];
        const double en = rc_inter_stored_energy(m, d, i, t, y);
        e[RC_E_STORED] += en;
        e[RC_E_HYST] += y[m->inter_eadr[i]] - en;
        /* friction: work, and the elastic energy of the stick springs (one,
         * or one per contact point; exact stick has no spring) */
        const rc_fric *fr = &m->inter_fr[i];
        if (fr->kind == RC_FK_NONE) continue;
        const double *s = y + m->inter_eadr[i];
        double et = 0;
        if (d->inter_mode[i] == RC_MODE_CLOSED && !fr->exact) {
            rc_inter_report r;
            rc_inter_report_eval_d(m, d, i, t, y, &r);
            et = r.fstored;
        }
        e[RC_E_FWORK] += s[fr->widx];
        e[RC_E_STORED] += et;
        e[RC_E_FRIC] += s[fr->widx] - et;
    }
    /* couplings: integrated work of the spring and line forces, dissipation */
    for (int k = 0; k < m->cpl->n; k++) {
        const double *ce = y + m->cpl->eadr[k];
        if (m->cpl->kind[k] == RC_CPL_SPRING || m->cpl->kind[k] == RC_CPL_CONTACT || m->cpl->kind[k] == RC_CPL_LIMIT) {
            e[RC_E_CPL_ELASTIC] += ce[0];
            e[RC_E_CPL_DAMP] += ce[1];
        } else {
            e[RC_E_CATENARY] += ce[0];
        }
    }
    /* minus the work done by the imposed velocities (imposed.c) */
    if (m->imp) e[RC_E_IMPOSED] = y[m->imp->wadr];
    e[RC_E_TOTAL] = e[RC_E_KIN] + e[RC_E_POT] + e[RC_E_WORK] + e[RC_E_DAMP] + e[RC_E_FWORK] + e[RC_E_CPL_ELASTIC] +
                    e[RC_E_CPL_DAMP] + e[RC_E_CATENARY] + e[RC_E_IMPOSED];
}
