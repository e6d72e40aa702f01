/*
 * Embedding ricochet (docs/embedding.md): load a deck, run it in pieces of
 * 0.1 s reading the state between them, and print every impact as the
 * event callback sees it.
 *
 *   cc embed.c $(pkg-config --cflags --libs ricochet) -o embed
 *   ./embed cases/demo_sphere_drop.rad [out.nc]
 *
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include <stdio.h>
#include <string.h>

#include <ricochet/ricochet.h>

/* Called at every event (the rows of the events table); 0: go on. */
static int on_event(void *user, double t, const char *kind, const char *element, const double v[3])
{
    int *impacts = user;
    if (!strcmp(kind, "contact_close")) /* v: penetration, approach speed, force */
        printf("impact %d at t = %.6f s on %s, approach speed %.4f m/s\n", ++*impacts, t, element, v[1]);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: embed CASE.rad [OUT.nc]\n");
        return 2;
    }
    rc_error err;
    rc_case *c = NULL;
    rc_model *m = NULL;
    if (rc_case_load(argv[1], &c, &err) || rc_model_compile(c, &m, &err)) {
        fprintf(stderr, "embed: %s\n", err.msg);
        rc_case_free(c);
        return rc_status_exit_code(err.code);
    }
    int impacts = 0;
    rc_run_options opt = {.output_path = argc > 2 ? argv[2] : NULL, .on_event = on_event, .user = &impacts};
    rc_session *s = NULL;
    rc_status st = rc_session_open(m, &opt, &s, &err);
    /* the state vector: 13 values per free body, position first (docs/theory.md) */
    for (int k = 1; !st && !rc_session_finished(s); k++) {
        st = rc_run_until(s, 0.1 * k, &err);
        if (!st) printf("t = %.2f s: body 1 at z = %.6f m\n", rc_session_time(s), rc_session_state(s)[2]);
    }
    rc_stats stats;
    rc_status st2 = rc_session_close(s, &stats, &err);
    if (!st) st = st2;
    if (st) fprintf(stderr, "embed: %s: %s\n", rc_status_str(st), err.msg);
    else printf("%d impacts, %ld events, simulated %g s (ricochet %s)\n", impacts, stats.events, stats.t_end, rc_version());
    rc_model_free(m);
    rc_case_free(c);
    return rc_status_exit_code(st);
}
