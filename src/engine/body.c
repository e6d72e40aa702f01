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
