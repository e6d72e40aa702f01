/*
 * rc_run: the backend-neutral entry of the integration stage. Checks the
 * arguments and options of a run as the reader checks a deck (nothing runs
 * and nothing is written when they are wrong), picks the backend of the
 * model's /SOLVER Method (solver.h) and runs it; prints the statistics of a
 * run.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/error.h"
#include "model/model.h"
#include "solver/solver.h"

/* The backends, by method. */
static const rc_solver *const rc_solvers[] = {&rc_solver_cvode, &rc_solver_ida, &rc_solver_static};

/* The kind of a file that is not a regular one, for messages. */
static const char *file_kind(mode_t mode)
{
    return S_ISDIR(mode) ? "a directory" : S_ISFIFO(mode) ? "a named pipe" : S_ISCHR(mode) || S_ISBLK(mode) ? "a device"
         : S_ISSOCK(mode) ? "a socket" : "not a file";
}

/* The output path must not name an input of the model: the case file or a
 * file it includes, compared by device and inode (as read, with the size and
 * modification time then, and as the paths
 * resolve now), so that another spelling, a link or a symbolic link of an
 * input is recognised; nor anything but a regular file. RC_EINPUT. */
static rc_status check_output_path(const rc_model *m, const char *out, rc_error *err)
{
    struct stat so;
    if (stat(out, &so) != 0) return RC_OK; /* a new file overwrites nothing; a bad path fails at its creation */
    if (!S_ISREG(so.st_mode))
        RC_RAISE(err, RC_EINPUT,
                 "%s: the output path is %s, not a regular file: expected a new file or a results file to replace; "
                 "nothing was written",
                 out, file_kind(so.st_mode));
    for (int i = 0; i < m->nfile; i++) {
        struct stat si;
        /* as read: the same device and inode, and the same size and
         * modification time, so that a file that got the inode of an
         * input deleted since (a new results file) is not taken for it */
        const unsigned long long *id = m->file_id ? m->file_id + 4 * i : NULL;
        const int as_read = id && id[0] == (unsigned long long)so.st_dev && id[1] == (unsigned long long)so.st_ino &&
                            id[2] == (unsigned long long)so.st_size &&
                            id[3] == (unsigned long long)so.st_mtim.tv_sec * 1000000000ull +
                                         (unsigned long long)so.st_mtim.tv_nsec;
        const int as_now = stat(m->file[i], &si) == 0 && si.st_dev == so.st_dev && si.st_ino == so.st_ino;
        if (as_read || as_now)
            RC_RAISE(err, RC_EINPUT,
                     "%s: the output file is the input file '%s'%s: refusing to overwrite an input; nothing was "
                     "written (give another output path)",
                     out, m->file[i], i == 0 ? " (the case file)" : " (included by the case)");
    }
    return RC_OK;
}

/* A run's arguments and options, checked before anything runs or is
 * written: RC_EINPUT naming the option. */
static rc_status check_run(const rc_model *m, const rc_run_options *opt, rc_error *err)
{
    if (!m) RC_RAISE(err, RC_EINPUT, "rc_run: the model is NULL; expected a compiled model (rc_model_compile)");
    const double te = opt ? opt->t_end_override : 0.0, dt = opt ? opt->dt_out_override : 0.0;
    if (te != 0.0 && !(isfinite(te) && te > 0))
        RC_RAISE(err, RC_EINPUT,
                 "run option t_end_override: expected 0 (the case's end time) or a positive finite end time [s], got %g",
                 te);
    if (dt != 0.0 && !(isfinite(dt) && dt > 0))
        RC_RAISE(err, RC_EINPUT,
                 "run option dt_out_override: expected 0 (the case's output interval) or a positive finite interval "
                 "[s], got %g",
                 dt);
    const double tend = te > 0 ? te : m->tend, dtout = dt > 0 ? dt : m->dtout;
    /* records at the output times 0, dt, ..., tend (events add their own) */
    const double nrec = floor(tend / dtout) + 2.0;
    if (!(nrec <= (double)RC_MAX_RECORDS))
        RC_RAISE(err, RC_EINPUT,
                 "run options: the output interval %g s (%s) over the end time %g s (%s) gives %.4g records, more "
                 "than the limit of %d (RC_MAX_RECORDS); expected an output interval of at least %g s or a shorter "
                 "end time",
                 dtout, dt > 0 ? "dt_out_override, --dt-out" : "the case's /RUN Dt_out", tend,
                 te > 0 ? "t_end_override, --t-end" : "the case's /RUN Tend", nrec, RC_MAX_RECORDS,
                 tend / (RC_MAX_RECORDS - 2.0));
    if (opt && opt->output_path) return check_output_path(m, opt->output_path, err);
    return RC_OK;
}

rc_status rc_run_paused(const rc_model *m, const rc_run_options *opt, rc_pause *pause, rc_stats *stats,
                        rc_error *err)
{
    rc_error local_err;
    if (!err) err = &local_err;
    if (stats) {
        memset(stats, 0, sizeof *stats);
        stats->t_settle = NAN;
    }
    rc_status st = check_run(m, opt, err);
    if (st != RC_OK) return st;
    const rc_solver *sv = NULL;
    for (size_t k = 0; k < sizeof rc_solvers / sizeof rc_solvers[0]; k++)
        if (rc_solvers[k]->method == m->method) sv = rc_solvers[k];
    if (!sv) return RC_SET(err, RC_EINTERNAL, "no solver backend for /SOLVER Method %d", m->method);
    if (!m->preload || m->method == RC_METHOD_STATIC) return sv->run(m, opt, pause, NULL, stats, err);
    /* a preload: the dynamic run starts from the static equilibrium at
     * t = 0 (static.c); nothing is run or written when it fails */
    rc_preload pre;
    memset(&pre, 0, sizeof pre);
    pre.y = calloc((size_t)m->ny + 1, sizeof(double));
    pre.closed = calloc((size_t)m->ninter + 1, sizeof(int));
    if (!pre.y || !pre.closed) st = RC_SET(err, RC_ENOMEM, "out of memory for the preload");
    else st = rc_static_preload(m, &pre, err);
    if (st == RC_OK) {
        st = sv->run(m, opt, pause, &pre, stats, err);
        if (stats) {
            stats->preloaded = 1;
            stats->preload_iters = pre.iters;
            stats->preload_wall_time = pre.wall;
        }
    }
    free(pre.y);
    free(pre.closed);
    return st;
}

rc_status rc_run(const rc_model *m, const rc_run_options *opt, rc_stats *stats, rc_error *err)
{
    return rc_run_paused(m, opt, NULL, stats, err);
}

/* A number in the format fmt, or "-" right-aligned to the width w when it
 * is not finite; a negative zero printed as 0. */
static void num_or_dash(char *buf, size_t n, int w, const char *fmt, double v)
{
    if (!isfinite(v)) snprintf(buf, n, "%*s", w, "-");
    else snprintf(buf, n, fmt, v == 0.0 ? 0.0 : v);
}

void rc_stats_print(const rc_stats *s, FILE *f)
{
    if (!s || !f) return;
    fprintf(f, "steps %ld, rhs %ld, jacobians %ld, lin. setups %ld, newton iters %ld, newton fails %ld, "
               "error-test fails %ld, root evals %ld\n",
            s->steps, s->rhs_evals, s->jac_evals, s->lin_setups, s->nonlin_iters, s->nonlin_fails,
            s->err_test_fails, s->root_evals);
    fprintf(f, "events %ld, restarts %ld, simulated %.6g s in %.3f s wall, energy balance residual %.3g J\n",
            s->events, s->reinits, s->t_end, s->wall_time, s->energy_residual);
    if (s->switches_explicit > 0 || s->switches_implicit > 0)
        fprintf(f, "method switches %ld to explicit, %ld to implicit; explicit steps %ld of %ld\n",
                s->switches_explicit, s->switches_implicit, s->steps_explicit, s->steps);
    if (s->preloaded)
        fprintf(f, "preload: static equilibrium at t = 0 (KINSOL), %ld Newton iterations in %.3g s wall; the run "
                   "started from it at rest\n",
                s->preload_iters, s->preload_wall_time);
    if (s->settles > 0)
        fprintf(f, "settled contacts %ld (bounces accumulated: held closed), the last at t = %.9g s\n", s->settles,
                s->t_settle);
    if (s->impacts > 0) {
        fprintf(f, "impacts %ld%s:\n", s->impacts, s->impacts > RC_STATS_IMPACTS ? " (the first ones; all in the results file)" : "");
        fprintf(f, "  %-8s %12s %12s %12s %12s %10s %10s %8s %12s\n", "inter", "close [s]", "duration [s]",
                "max pen [m]", "peak F [N]", "v_in [m/s]", "v_out[m/s]", "e [-]", "E_lost [J]");
        for (long k = 0; k < s->impacts && k < RC_STATS_IMPACTS; k++) {
            const rc_impact *r = &s->impact[k];
            /* no NaN and no -0 on the screen: "-" where a value does not
             * exist (no separation yet) */
            char cl[16], dur[16], pen[16], fmx[16], vin[16], vout[16], e[16], el[16];
            num_or_dash(cl, sizeof cl, 12, "%12.6g", r->t_close);
            num_or_dash(dur, sizeof dur, 12, "%12.6g", r->duration);
            num_or_dash(pen, sizeof pen, 12, "%12.5g", r->pen_max);
            num_or_dash(fmx, sizeof fmx, 12, "%12.5g", r->fn_max);
            num_or_dash(vin, sizeof vin, 10, "%10.4g", r->v_in);
            num_or_dash(vout, sizeof vout, 10, "%10.4g", r->v_out);
            num_or_dash(e, sizeof e, 8, "%8.4f", r->restitution);
            num_or_dash(el, sizeof el, 12, "%12.5g", r->energy_lost);
            fprintf(f, "  %-8d %s %s %s %s %s %s %s %s\n", r->inter_id, cl, dur, pen, fmx, vin, vout, e, el);
        }
    }
    if (s->contacts > 0) {
        fprintf(f, "persistent contacts %ld (closed from the start or without approaching, or longer than %d "
                   "contact times)%s:\n",
                s->contacts, RC_IMPACT_SPAN, s->contacts > RC_STATS_CONTACTS ? " (the first ones; all in the results file)" : "");
        fprintf(f, "  %-8s %12s %12s %12s %12s %12s %12s %12s\n", "inter", "close [s]", "open [s]", "duration [s]",
                "peak F [N]", "mean F [N]", "max pen [m]", "slip [m]");
        for (long k = 0; k < s->contacts && k < RC_STATS_CONTACTS; k++) {
            const rc_contact *r = &s->contact[k];
            char cl[16], op[16], dur[16], fmx[16], fme[16], pen[16], sl[16];
            num_or_dash(cl, sizeof cl, 12, "%12.6g", r->t_close);
            num_or_dash(op, sizeof op, 12, "%12.6g", r->t_open);
            num_or_dash(dur, sizeof dur, 12, "%12.6g", r->duration);
            num_or_dash(fmx, sizeof fmx, 12, "%12.5g", r->fn_max);
            num_or_dash(fme, sizeof fme, 12, "%12.5g", r->fn_mean);
            num_or_dash(pen, sizeof pen, 12, "%12.5g", r->pen_max);
            num_or_dash(sl, sizeof sl, 12, "%12.5g", r->slip);
            fprintf(f, "  %-8d %s %s %s %s %s %s %s\n", r->inter_id, cl, op, dur, fmx, fme, pen, sl);
        }
    }
    if (s->sampling_note[0]) fprintf(f, "warning: %s\n", s->sampling_note);
    if (s->records_thinned > 0)
        fprintf(f,
                "warning: %ld records at events and inside contacts left out of the results file: more than %d "
                "in an output interval (stats_records_thinned; the events table has every event, the impact "
                "table every peak; a smaller /RUN Dt_out writes more)\n",
                s->records_thinned, RC_EXTRA_RECORDS);
    if (s->vibration_note[0]) fprintf(f, "note: %s\n", s->vibration_note);
    if (s->tolerance_note[0]) fprintf(f, "note: %s\n", s->tolerance_note);
    /* the physics checks (docs/theory.md) and what the contacts did */
    if (s->physics_note[0]) fprintf(f, "physics checks: %s\n", s->physics_note);
    if (s->contacts_note[0]) fprintf(f, "contacts: %s\n", s->contacts_note);
}
