/*
 * The root functions the integrator sees (integrator.h rc_rootmap): only
 * those that can change sign in the run (model.h rc_roots_live). The
 * engine still evaluates the whole layout (into a scratch vector), and the
 * roots found and the directions are mapped between the integrator's
 * compact indices and the engine's full ones, so that the driver and the
 * events see the same indices as with every root given. SUNDIALS loops
 * over all its root functions at every step (and several times in each
 * root search); most of the ten per interface are constant for a given
 * interface (no hysteresis law, no Inacti 5, no friction, no activation
 * window).
 */
#include <stdlib.h>
#include <string.h>

#include "solver/integrator.h"
#include "engine/assembly/assembly.h"

static int compact_on = 1;

void rc_rootmap_set_compact(int on) { compact_on = on; }

int rc_rootmap_init(rc_rootmap *rm, const rc_model *m, const rc_run_options *opt)
{
    memset(rm, 0, sizeof *rm);
    const double tend = opt && opt->t_end_override > 0 ? opt->t_end_override : m->tend;
    rm->nfull = rm->n = rc_root_count(m);
    rm->ninter = m->ninter;
    if (m->ninter > 0 && !(rm->zone = malloc((size_t)m->ninter * sizeof(double)))) return -1;
    if (rm->nfull == 0 || !compact_on) return 0;
    const int n = rc_roots_live(m, tend, NULL);
    /* all live: the integrator writes the engine's vector (none live cannot
     * happen: every interface keeps ZONE and FORCE; kept whole anyway) */
    if (n == rm->nfull || n == 0) return 0;
    rm->live = malloc(((size_t)n + 1) * sizeof(int));
    rm->g = malloc((size_t)rm->nfull * sizeof(double));
    rm->iv = malloc((size_t)rm->nfull * sizeof(int));
    if (!rm->live || !rm->g || !rm->iv) return -1;
    rm->n = rc_roots_live(m, tend, rm->live);
    return 0;
}

void rc_rootmap_free(rc_rootmap *rm)
{
    free(rm->live);
    free(rm->g);
    free(rm->iv);
    free(rm->zone);
    memset(rm, 0, sizeof *rm);
}

void rc_rootmap_keep(rc_rootmap *rm, double t, const double *gfull)
{
    if (!rm->zone) return;
    for (int i = 0; i < rm->ninter; i++) rm->zone[i] = gfull[RC_ROOTS_PER_INTER * i + RC_ROOT_ZONE];
    rm->tzone = t;
    rm->zone_ok = 1;
}

const double *rc_rootmap_at(const rc_rootmap *rm, double t)
{
    return rm->zone_ok && rm->tzone == t ? rm->zone : NULL;
}

void rc_rootmap_gather(const rc_rootmap *rm, double *g)
{
    if (!rm->live) return;
    for (int j = 0; j < rm->n; j++) g[j] = rm->g[rm->live[j]];
}

const int *rc_rootmap_dirs(const rc_rootmap *rm, const int *dir)
{
    if (!rm->live) return dir;
    for (int j = 0; j < rm->n; j++) rm->iv[j] = dir[rm->live[j]];
    return rm->iv;
}

void rc_rootmap_found(const rc_rootmap *rm, int *roots)
{
    if (!rm->live) return;
    for (int k = 0; k < rm->nfull; k++) roots[k] = 0;
    for (int j = 0; j < rm->n; j++) roots[rm->live[j]] = rm->iv[j];
}
