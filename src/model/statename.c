/*
 * Names of the entries of the state vector, for messages: the element that
 * owns a state and the quantity, with its unit (layout in model.h).
 */
#include "model/model.h"
#include "model/coupling.h"
#include "model/imposed.h"

#include <stdio.h>

int rc_state_inter(const rc_model *m, int i)
{
    for (int k = 0; k < m->ninter; k++) {
        const int j = i - m->inter_eadr[k];
        if (j >= 0 && j < m->inter_ns[k] + m->inter_pst[k] * m->inter_npt[k]) return k;
    }
    return -1;
}

void rc_state_name(const rc_model *m, int i, char *buf, size_t n)
{
    static const char *const body_q[RC_NB] = {
        "position x [m]", "position y [m]", "position z [m]", "quaternion w [-]", "quaternion x [-]",
        "quaternion y [-]", "quaternion z [-]", "velocity x [m/s]", "velocity y [m/s]", "velocity z [m/s]",
        "angular velocity x (body frame) [rad/s]", "angular velocity y (body frame) [rad/s]",
        "angular velocity z (body frame) [rad/s]"};
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        if (a >= 0 && i >= a && i < a + RC_NB) {
            snprintf(buf, n, "/RBODY/%d, %s", m->body_id[b], body_q[i - a]);
            return;
        }
    }
    const int it = rc_state_inter(m, i);
    if (it >= 0) {
        const int j = i - m->inter_eadr[it];
        const int ps = m->inter_pst[it];
        if (j >= m->inter_ns[it]) {
            const int p = (j - m->inter_ns[it]) / ps, e = (j - m->inter_ns[it]) % ps;
            const rc_fric *fp = &m->inter_fr[it];
            /* 3 states: F_t (incremental) or the filtered force (viscous with
             * a filter); 6: F_t, then the filtered force F_f */
            const int filt = e >= 3 || (fp->form != RC_FF_INCREMENTAL && fp->tau > 0);
            snprintf(buf, n, "%s, %s of contact point %d (node %d of the surface) %c [N]", m->inter_name[it],
                     filt ? "filtered friction force F_f" : "tangential (friction) force F_t", p + 1, p + 1,
                     "xyz"[e % 3]);
            return;
        }
        const rc_fric *fr = &m->inter_fr[it];
        const char *q = j == 0 ? "work of the normal force W_load [J]"
                        : j == 1 ? "energy of the normal damping W_damp [J]"
                        : j == m->inter_hidx[it] ? "hysteresis force F_h [N]"
                        : j == m->inter_oidx[it] ? "Inacti 5 gap offset [m]"
                        : j == m->inter_peidx[it] ? "effective penetration P_e of the law [m]"
                        : j == m->inter_dhidx[it] ? "dissipation D_h of the law (the relaxation of P_e; Iform 1, 2: the load curve) [J]"
                        : fr->kind != RC_FK_NONE && fr->form == RC_FF_INCREMENTAL && j >= fr->tidx && j < fr->tidx + 3
                            ? "tangential (friction) force F_t [N]"
                        : fr->kind != RC_FK_NONE && fr->tau > 0 && j >= fr->fidx && j < fr->fidx + 3
                            ? "filtered friction force [N]"
                        : fr->kind != RC_FK_NONE && j == fr->widx ? "work of the friction force W_fric [J]"
                                                                   : "own state";
        snprintf(buf, n, "%s, %s", m->inter_name[it], q);
        return;
    }
    if (m->cpl)
        for (int k = 0; k < m->cpl->n; k++)
            if (i >= m->cpl->eadr[k] && i < m->cpl->eadr[k] + RC_CE) {
                snprintf(buf, n, "%s, energy accumulator [J]", m->cpl->name[k]);
                return;
            }
    if (i == m->gwork_adr) {
        snprintf(buf, n, "/GRAV, work of the time-varying gravity [J]");
        return;
    }
    if (m->imp && i == m->imp->wadr) {
        snprintf(buf, n, "/IMPVEL, work of the imposed velocities [J]");
        return;
    }
    snprintf(buf, n, "state %d", i);
}
