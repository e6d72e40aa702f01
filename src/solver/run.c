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
static const rc_solver *const rc_solvers[] = {&rc_solver_cvode};

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
}
