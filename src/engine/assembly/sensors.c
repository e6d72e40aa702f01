/*
 * Distance sensors (/SENSOR/DIST; model/sensor.c, docs/theory.md
 * "Sensors"): the distance of a sensor's two points and its two root
 * functions. Pure: no allocation, no output (the root functions run inside
 * the integrator's rootfinding).
 */
#include <math.h>

#include "model/model.h"
#include "engine/assembly/assembly.h"

/* Point p (body frame) of body state s (x, q = (w, x, y, z), ...) in global coordinates. */
static void to_global(const double *s, const double *p, double *x)
{
    const double w = s[3], u[3] = {s[4], s[5], s[6]};
    const double c[3] = {u[1] * p[2] - u[2] * p[1], u[2] * p[0] - u[0] * p[2], u[0] * p[1] - u[1] * p[0]};
    const double cc[3] = {u[1] * c[2] - u[2] * c[1], u[2] * c[0] - u[0] * c[2], u[0] * c[1] - u[1] * c[0]};
    for (int k = 0; k < 3; k++) x[k] = s[k] + p[k] + 2.0 * (w * c[k] + cc[k]);
}

double rc_sens_distance(const rc_model *m, int k, const double *y)
{
    double a[3], b[3];
    to_global(rc_body_state(m, m->sens_body[2 * k], y), m->sens_p + 6 * k, a);
    to_global(rc_body_state(m, m->sens_body[2 * k + 1], y), m->sens_p + 6 * k + 3, b);
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

void rc_sens_roots(const rc_model *m, const rc_data *d, const double *y, double *g)
{
    for (int k = 0; k < m->nsens; k++) {
        g[2 * k] = g[2 * k + 1] = -1.0; /* a time sensor, or one that has triggered */
        if (m->sens_kind[k] != 1 || isfinite(d->sens_ton[k])) continue;
        const double dist = rc_sens_distance(m, k, y), *b = m->sens_d + 2 * k;
        if (b[1] > 0) g[2 * k] = dist - b[1];
        if (b[0] > 0) g[2 * k + 1] = b[0] - dist;
    }
}

int rc_sens_root_live(const rc_model *m, int j)
{
    const int k = j / 2;
    return m->sens_kind[k] == 1 && m->sens_d[2 * k + (j % 2 ? 0 : 1)] > 0;
}

double rc_sens_inter_ton(const rc_model *m, const rc_data *d, int i)
{
    const int s = m->inter_sens[i];
    return s < 0 ? m->inter_tstart[i] : fmax(m->inter_tstart[i], d->sens_ton[s]);
}
