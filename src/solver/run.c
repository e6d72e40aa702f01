/*
 * rc_run: the backend-neutral entry of the integration stage. Picks the
 * backend of the model's /SOLVER Method (solver.h) and runs it; prints the
 * statistics of a run.
 */
#include <stdio.h>

#include "base/error.h"
#include "model/model.h"
#include "solver/solver.h"

/* The backends, by method. */
static const rc_solver *const rc_solvers[] = {&rc_solver_cvode, &rc_solver_ida};

rc_status rc_run_paused(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                        rc_error *err)
{
    for (size_t k = 0; k < sizeof rc_solvers / sizeof rc_solvers[0]; k++)
        if (rc_solvers[k]->method == m->method) return rc_solvers[k]->run(m, opt, pause, stats, err);
    rc_error local_err;
    return RC_SET(err ? err : &local_err, RC_EINTERNAL, "no solver backend for /SOLVER Method %d",
                  m->method);
}

rc_status rc_run(const rc_model *m, const rc_run_options *opt, rc_stats *stats, rc_error *err)
{
    return rc_run_paused(m, opt, NULL, stats, err);
}

void rc_stats_print(const rc_stats *s, FILE *f)
{
    fprintf(f, "steps %ld, rhs %ld, jacobians %ld, lin. setups %ld, newton iters %ld, newton fails %ld, "
               "error-test fails %ld, root evals %ld\n",
            s->steps, s->rhs_evals, s->jac_evals, s->lin_setups, s->nonlin_iters, s->nonlin_fails,
            s->err_test_fails, s->root_evals);
    fprintf(f, "events %ld, restarts %ld, simulated %.6g s in %.3f s wall, energy balance residual %.3g J\n",
            s->events, s->reinits, s->t_end, s->wall_time, s->energy_residual);
    if (s->settles > 0)
        fprintf(f, "settled contacts %ld (bounces accumulated: held closed), the last at t = %.9g s\n", s->settles,
                s->t_settle);
    if (s->impacts > 0) {
        fprintf(f, "impacts %ld%s:\n", s->impacts, s->impacts > RC_STATS_IMPACTS ? " (the first ones; all in the results file)" : "");
        fprintf(f, "  %-8s %12s %12s %12s %12s %10s %10s %8s %12s\n", "inter", "close [s]", "duration [s]",
                "max pen [m]", "peak F [N]", "v_in [m/s]", "v_out[m/s]", "e [-]", "E_lost [J]");
        for (long k = 0; k < s->impacts && k < RC_STATS_IMPACTS; k++) {
            const rc_impact *r = &s->impact[k];
            fprintf(f, "  %-8d %12.6g %12.6g %12.5g %12.5g %10.4g %10.4g %8.4f %12.5g\n", r->inter_id, r->t_close,
                    r->duration, r->pen_max, r->fn_max, r->v_in, r->v_out, r->restitution, r->energy_lost);
        }
    }
    if (s->sampling_note[0]) fprintf(f, "warning: %s\n", s->sampling_note);
    /* the physics checks (docs/theory.md) and what the contacts did */
    if (s->physics_note[0]) fprintf(f, "physics checks: %s\n", s->physics_note);
    if (s->contacts_note[0]) fprintf(f, "contacts: %s\n", s->contacts_note);
}
