/*
 * Distance and interface sensors (/SENSOR/DIST, /SENSOR/INTER;
 * model/sensor.c, docs/theory.md "Sensors"): which of a sensor's root
 * functions are live (the trigger roots, and the release root of a sensor
 * that releases a held body), whether an interface sensor's contact is
 * closed, and an interface's start under a sensor (the distance and the root functions
 * are in assemble_rhs.c, with the kernels' material points). Pure: no allocation, no output (the root functions run inside
 * the integrator's rootfinding).
 */
#include <math.h>

#include "model/model.h"
#include "engine/assembly/assembly.h"

int rc_sens_root_live(const rc_model *m, int j)
{
    const int k = j / 2, bounds = m->sens_kind[k] == 1 || m->sens_kind[k] == 5;
    /* the first slot of a sensor releasing a held body: its release root;
     * a distance sensor's bounds (Dmax first); an interface sensor with a
     * force bound: its force root, first slot; with Tmin (only with a
     * bound) both slots: the criterion's end and Tmin reached
     * (rc_sens_roots) */
    return (bounds && (m->sens_d[2 * k + (j % 2 ? 0 : 1)] > 0 || m->sens_tmin[k] > 0)) ||
           (j % 2 == 0 && m->sens_hold[k]);
}

int rc_sens_inter_closed(const rc_model *m, const rc_data *d, int k)
{
    for (int i = 0; i < m->ninter; i++)
        if (m->inter_id[i] == m->sens_inter[k] && d->inter_mode[i] == RC_MODE_CLOSED) return 1;
    return 0;
}

double rc_sens_inter_ton(const rc_model *m, const rc_data *d, int i)
{
    const int s = m->inter_sens[i];
    return s < 0 ? m->inter_tstart[i] : fmax(m->inter_tstart[i], d->sens_ton[s]);
}
