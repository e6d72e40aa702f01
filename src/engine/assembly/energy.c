/* Energies of the state: kinetic, potential, interface work and stored
 * energy, friction, couplings, imposed velocities (docs/theory.md). Reads
 * the interface reports of assemble_rhs.c and the body views of body.c. */
#include <math.h>
#include <string.h>

#include "model/coupling.h"
#include "model/imposed.h"
#include "model/model.h"
#include "model/power.h"
#include "model/table.h"
#include "engine/assembly/assembly.h"

/* Elastic energy stored in interface i: what the bodies would recover by
 * unloading it completely along the law (Iform 0: the load curve; Iform 1, 2:
 * the Stiff line between the load curve and the unload curve or zero, then
 * the unload curve: law_energy.c). */
double rc_inter_stored_energy(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    const int mode = d->inter_mode[i];
    if (mode != RC_MODE_CLOSED && mode != RC_MODE_RELEASED) return 0.0;
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    return rc_inter_path_energy(m, i, r.pl, r.fload); /* at the law's penetration */
}

int rc_inter_release_ledger(const rc_model *m, int i)
{
    return m->inter_peidx[i] < 0 && m->inter_inacti[i] == 0 &&
           (m->inter_law[i] == RC_LAW_POWER || m->inter_iform[i] == 0);
}

/* An elastic law loads and unloads along one curve: its hysteresis is 0.
 * Not so with several contact points (they dissipate through P_e, 2.7 of
 * the theory), with the Inacti offset (it moves the law's penetration by
 * itself), or where the contact can release at P > 0 and lose its stored
 * energy: a damper (Visc or TYPE6's damping curve, the power law's C or
 * spline: rc_inter_undamped), or a load curve
 * that goes negative at some P > 0 (its points, or its linear extensions
 * at 0 and beyond the last point). */
static int inter_elastic(const rc_model *m, int i)
{
    if (m->inter_peidx[i] >= 0 || m->inter_inacti[i] != 0 || !rc_inter_undamped(m, i)) return 0;
    if (m->inter_law[i] == RC_LAW_POWER) return 1;
    if (m->inter_iform[i] != 0) return 0;
    const rc_table *tb = &m->table[m->inter_fct_ld[i]];
    const int n = tb->n;
    if (rc_table_value(tb, 0.0) < 0.0 || tb->y[n - 1] < tb->y[n - 2]) return 0;
    for (int k = 0; k < n; k++)
        if (tb->y[k] < 0.0) return 0;
    return 1;
}

/* Interface i's hysteresis dissipation [J], its stored energy en given. */
static double hysteresis_of(const rc_model *m, const rc_data *d, int i, const double *y, double en)
{
    if (inter_elastic(m, i)) return 0.0;
    if (rc_inter_release_ledger(m, i))
        return d->inter_hacc[2 * i] + (d->inter_mode[i] == RC_MODE_RELEASED ? d->inter_hacc[2 * i + 1] - en : 0.0);
    if (m->inter_dhidx[i] >= 0) return y[m->inter_eadr[i] + m->inter_dhidx[i]]; /* D_h */
    return y[m->inter_eadr[i]] - en;
}

double rc_inter_hysteresis(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    return hysteresis_of(m, d, i, y, rc_inter_stored_energy(m, d, i, t, y));
}

double rc_inter_friction_stored(const rc_model *m, const rc_data *d, int i, double t, const double *y)
{
    const rc_fric *fr = &m->inter_fr[i];
    if (fr->kind == RC_FK_NONE || fr->exact || d->inter_mode[i] != RC_MODE_CLOSED) return 0.0;
    rc_inter_report r;
    rc_inter_report_eval_d(m, d, i, t, y, &r);
    return r.fstored;
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
        const double *o = m->origin; /* the positions in the deck's coordinates */
        e[RC_E_POT] -= m->body_mass[b] * (g[0] * (s[0] + o[0]) + g[1] * (s[1] + o[1]) + g[2] * (s[2] + o[2]));
    }
    if (m->gwork_adr >= 0) e[RC_E_POT] = y[m->gwork_adr]; /* time-varying gravity */
    for (int i = 0; i < m->ninter; i++) {
        e[RC_E_WORK] += y[m->inter_eadr[i]];
        e[RC_E_DAMP] += y[m->inter_eadr[i] + 1];
        const double en = rc_inter_stored_energy(m, d, i, t, y);
        e[RC_E_STORED] += en;
        e[RC_E_HYST] += hysteresis_of(m, d, i, y, en);
        /* friction: work, and the elastic energy of the stick springs (one,
         * or one per contact point; exact stick has no spring) */
        const rc_fric *fr = &m->inter_fr[i];
        if (fr->kind == RC_FK_NONE) continue;
        const double *s = y + m->inter_eadr[i];
        const double et = rc_inter_friction_stored(m, d, i, t, y);
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
