/*
 * Distance sensors (/SENSOR/DIST; model/sensor.c, docs/theory.md
 * "Sensors"): a sensor's two root functions (the distance of its two
 * points: rc_sens_distance, with the kernels' material points in
 * assemble_rhs.c). Pure: no allocation, no output (the root functions run inside
 * the integrator's rootfinding).
 */
#include <math.h>

#include "model/model.h"
#include "engine/assembly/assembly.h"

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
