/* Rigid bodies: state views, gravity (of the bodies and of the coupling
 * lines), initial state. Energies are in energy.c. */
#include <string.h>

#include "model/coupling.h"
#include "model/imposed.h"
#include "model/model.h"
#include "model/power.h"

const double *rc_body_state(const rc_model *m, int b, const double *y)
{
    if (b < 0) return m->ground_y0;
    return m->body_yadr[b] >= 0 ? y + m->body_yadr[b] : m->body_y0 + RC_NB * b;
}

double rc_gravity_factor(const rc_model *m, double t)
{
    /* f(t / Ascale), 1 when no function is given */
    double f = 1.0, df;
    if (m->grav_table >= 0) rc_table_eval(&m->table[m->grav_table], t / m->grav_ascale, &f, &df);
    return f;
}

void rc_gravity(const rc_model *m, int b, double t, double g[3])
{
    /* g(t) = vector * f(t / Ascale) */
    const double f = rc_gravity_factor(m, t);
    for (int k = 0; k < 3; k++) g[k] = m->body_grav[3 * b + k] * f;
}

void rc_cpl_gravity(const rc_model *m, double t, double g[3])
{
    const double f = rc_gravity_factor(m, t);
    for (int k = 0; k < 3; k++) g[k] = m->cpl->grav[k] * f;
}

void rc_initial_state(const rc_model *m, double *y)
{
    memset(y, 0, (size_t)m->ny * sizeof(double));
    for (int b = 0; b < m->nbody; b++)
        if (m->body_yadr[b] >= 0) memcpy(y + m->body_yadr[b], m->body_y0 + RC_NB * b, RC_NB * sizeof(double));
    /* time-varying gravity: its potential starts at -sum m g(0).x0 */
    if (m->gwork_adr >= 0)
        for (int b = 0; b < m->nbody; b++) {
            if (m->body_yadr[b] < 0) continue;
            double g[3];
            const double *x = y + m->body_yadr[b];
            rc_gravity(m, b, 0.0, g);
            y[m->gwork_adr] -= m->body_mass[b] * (g[0] * x[0] + g[1] * x[1] + g[2] * x[2]);
        }
}

int rc_constant_states(const rc_model *m, const double *y0, const char *written, char *cst)
{
    memset(cst, 0, (size_t)m->ny);
    int n = 0;
#define RC_W(k) (written && written[k])
    /* an imposed velocity's row has its own rate (a held component cannot
     * be imposed: the compiler refuses it; checked again here) */
    const rc_imposed *p = m->imp;
    for (int b = 0; b < m->nbody; b++) {
        const int a = m->body_yadr[b];
        if (a < 0) continue;
        int held[6];
        for (int j = 0; j < 6; j++) held[j] = m->body_dofmask[6 * b + j];
        for (int k = 0; p && k < p->nt; k++)
            if (p->trow[k] >= a + 7 && p->trow[k] < a + 10) held[p->trow[k] - a - 7] = 0;
        for (int k = 0; p && k < p->nr; k++)
            if (p->rbody[k] == b) held[3] = held[4] = held[5] = 0;
        /* translations: v_j held; x_j also when v_j starts at exactly 0 */
        for (int j = 0; j < 3; j++) {
            if (!held[j] || !m->row_held[a + 7 + j] || RC_W(a + 7 + j)) continue;
            cst[a + 7 + j] = 1;
            n++;
            if (y0[a + 7 + j] == 0.0 && !RC_W(a + j)) {
                cst[a + j] = 1;
                n++;
            }
        }
        /* rotations: all held (a partial lock is refused), omega held; q
         * also when omega starts at exactly 0 (q' = q (0, omega) / 2 = 0) */
        int rot = 1, still = 1;
        for (int j = 3; j < 6; j++) {
            rot &= held[j] && m->row_held[a + 7 + j] && !RC_W(a + 7 + j);
            still &= y0[a + 7 + j] == 0.0;
        }
        if (!rot) continue;
        for (int j = 3; j < 6; j++) cst[a + 7 + j] = 1;
        n += 3;
        for (int k = 3; k < 7; k++) still &= !RC_W(a + k);
        if (!still) continue;
        for (int k = 3; k < 7; k++) cst[a + k] = 1;
        n += 4;
    }
#undef RC_W
    return n;
}
