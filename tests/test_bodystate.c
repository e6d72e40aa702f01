/* The bodies of a compiled model for the library's users
 * (model/body_state.c): ids, offsets in the state vector, a body's state
 * in the deck's coordinates, also for a scene far from the deck's origin
 * (the model computes about a nearer origin) and for a fixed body. */
#include "harness.h"

#include <netcdf.h>
#include <pthread.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

#include "model/model.h"
#include "ricochet/ricochet.h"

/* A 1 kg sphere (R = 0.05 m, centre at z = 0.15 m) above a plane z = 0
 * carried by body 2, which /BCS holds fixed (its node off the axes). */
static const char *const FIXED_DECK =
    "#RADIOSS STARTER\n/BEGIN\nbody state: a sphere above a plane carried by a fixed body\n"
    "      2022         0\n"
    "                  kg                   m                   s\n"
    "                  kg                   m                   s\n"
    "/FUNCT/1\ncurve\n                   0                   0\n                   1             1000000\n"
    "/NODE\n         1                   0                   0                0.15\n"
    "         2              0.0371             -0.0123               -0.25\n"
    "/RBODY/1\nbody\n         1                                                 1\n"
    "               0.001               0.001               0.001\n"
    "                   0                   0                   0\n"
    "/RBODY/2\nbody\n         2                                                 5\n"
    "                 0.1                 0.1                 0.1\n"
    "                   0                   0                   0\n"
    "/SURF/ELLIPS/1\nsphere\n         0         2         1\n"
    "                   0                   0                0.15\n"
    "                0.05                0.05                0.05\n"
    "/SURF/PLANE/2\nplane\n                   0                   0                   0\n"
    "                   0                   0                   1\n         2\n"
    "/GRNOD/NODE/1\ngroup\n         1\n/GRNOD/NODE/2\ngroup\n         2\n"
    "/GRAV/1\ngravity\n         0         Z         0         0         1                             1               -9.81\n"
    "/BCS/1\nfixed\n   111 111         0         2\n"
    "/INTER/TYPE6/1\ncontact\n         1         2\n"
    "                                                           0\n"
    "                   0         0         0         0         0\n"
    "         1         0                                                 0\n"
    "         0\n              148.71         0         0\n"
    "/RUN\n                 0.3                0.01\n/END\n";

static void deck_path(char *buf, size_t n, const char *ext)
{
    snprintf(buf, n, "/tmp/rc_test_bodystate_%ld.%s", (long)getpid(), ext);
}

/* The deck compiled with the overrides `set` (NULL when the file cannot be
 * written or the deck is refused). */
static rc_model *compile_fixed(const char *const *set, int nset)
{
    char path[128];
    deck_path(path, sizeof path, "rad");
    FILE *f = fopen(path, "w");
    if (!f) return NULL;
    fputs(FIXED_DECK, f);
    fclose(f);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    if (rc_case_load_set(path, set, nset, &c, &e) == RC_OK) rc_model_compile(c, &m, &e);
    else fprintf(stderr, "  %s\n", e.msg);
    rc_case_free(c);
    remove(path);
    return m;
}

static void test_bodystate_ids_and_offsets(void)
{
    rc_model *m = compile_fixed(NULL, 0);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(rc_model_body_count(m) == 2 && rc_model_body_id(m, 0) == 1 && rc_model_body_id(m, 1) == 2);
    ENSURE(rc_model_body_id(m, 2) == -1 && rc_model_body_id(m, -1) == -1);
    ENSURE(rc_model_body_count(NULL) == 0 && rc_model_body_id(NULL, 0) == -1);
    /* the free body's 13 states first; the fixed one has none */
    ENSURE(rc_model_body_index(m, 1) == 0 && rc_model_body_index(m, 2) == -1);
    ENSURE(rc_model_body_index(m, 3) == -2 && rc_model_body_index(NULL, 1) == -2);
    rc_model_free(m);
}

static void test_bodystate_values_and_errors(void)
{
    rc_model *m = compile_fixed(NULL, 0);
    ENSURE(m != NULL);
    if (!m) return;
    rc_error e;
    rc_session *s = NULL;
    ENSURE(rc_session_open(m, NULL, &s, &e) == RC_OK);
    if (!s) {
        rc_model_free(m);
        return;
    }
    double b[13], g[13];
    /* t = 0: the deck's pose, at rest */
    ENSURE(rc_model_body_state(m, rc_session_state(s), 1, b, &e) == RC_OK);
    const double b0[13] = {0, 0, 0.15, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 13; k++) ENSURE_NEAR(b[k], b0[k], 0.0, 1e-16);
    /* the fixed body: its pose, at rest, without a state vector */
    ENSURE(rc_model_body_state(m, NULL, 2, g, &e) == RC_OK);
    const double g0[13] = {0.0371, -0.0123, -0.25, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 13; k++) ENSURE_NEAR(g[k], g0[k], 1e-15, 0.0);
    /* free fall to t = 0.1 s: z = 0.15 - g t^2 / 2, v_z = -g t */
    ENSURE(rc_run_until(s, 0.1, &e) == RC_OK);
    ENSURE(rc_model_body_state(m, rc_session_state(s), 1, b, &e) == RC_OK);
    ENSURE_NEAR(b[2], 0.15 - 0.5 * 9.81 * 0.01, 1e-9, 0.0);
    ENSURE_NEAR(b[9], -0.981, 1e-9, 0.0);
    ENSURE_NEAR(b[3], 1.0, 0.0, 1e-15);
    /* the same values as the state vector at the offset (origin at 0 here) */
    const double *y = rc_session_state(s);
    for (int k = 0; k < 13; k++) ENSURE(b[k] == y[rc_model_body_index(m, 1) + k]);
    /* refused: an unknown id (the message lists the ids), NULL y for a
     * free body, NULL out, NULL model */
    ENSURE(rc_model_body_state(m, y, 99, b, &e) == RC_EINPUT && strstr(e.msg, "no /RBODY/99") &&
           strstr(e.msg, "1, 2"));
    ENSURE(rc_model_body_state(m, NULL, 1, b, &e) == RC_EINPUT && strstr(e.msg, "y is NULL"));
    ENSURE(rc_model_body_state(m, y, 1, NULL, &e) == RC_EINPUT && strstr(e.msg, "out is NULL"));
    ENSURE(rc_model_body_state(NULL, y, 1, b, &e) == RC_EINPUT && strstr(e.msg, "model is NULL"));
    ENSURE(rc_model_body_state(NULL, y, 1, b, NULL) == RC_EINPUT);
    rc_session_close(s, NULL, NULL);
    rc_model_free(m);
}

/* The scene moved 1 km up (by --set overrides): the model computes about
 * an origin near the scene; y_end and rc_model_body_state give the deck's
 * coordinates, the values of the results file's body_position bit for bit,
 * the fixed body's included. */
static void test_bodystate_far_scene_in_deck_coordinates(void)
{
    const char *set[] = {"/NODE:Z[1]=1000.15", "/NODE:Z[2]=999.75", "/SURF/ELLIPS/1:Zc=1000.15",
                         "/SURF/PLANE/2:ZM=1000", "/SURF/PLANE/2:ZM1=1001", "/RUN:Tend=0.1"};
    rc_model *m = compile_fixed(set, 6);
    ENSURE(m != NULL);
    if (!m) return;
    ENSURE(m->origin[2] > 999.0); /* the model's own origin */
    const int ny = rc_model_state_size(m);
    double *y = calloc((size_t)ny, sizeof(double));
    char out[128];
    deck_path(out, sizeof out, "nc");
    rc_run_options o = {.output_path = out, .y_end = y};
    rc_error e;
    ENSURE(rc_run(m, &o, NULL, &e) == RC_OK);
    double b[13], g[13];
    ENSURE(rc_model_body_state(m, y, 1, b, &e) == RC_OK);
    ENSURE(y[rc_model_body_index(m, 1) + 2] == b[2]); /* y_end is in the deck's coordinates */
    ENSURE_NEAR(b[2], 1000.15 - 0.5 * 9.81 * 0.01, 1e-12, 0.0);
    ENSURE(rc_model_body_state(m, y, 2, g, &e) == RC_OK);
    ENSURE_NEAR(g[2], 999.75, 1e-15, 0.0);
    /* the last record of the results file */
    int nc, var, dim;
    size_t nt = 0;
    double pos[6] = {0}, vel[6] = {0};
    ENSURE(nc_open(out, NC_NOWRITE, &nc) == NC_NOERR);
    ENSURE(nc_inq_dimid(nc, "time", &dim) == NC_NOERR && nc_inq_dimlen(nc, dim, &nt) == NC_NOERR && nt > 0);
    size_t start[3] = {nt - 1, 0, 0}, count[3] = {1, 2, 3};
    ENSURE(nc_inq_varid(nc, "body_position", &var) == NC_NOERR && nc_get_vara_double(nc, var, start, count, pos) == NC_NOERR);
    ENSURE(nc_inq_varid(nc, "body_velocity", &var) == NC_NOERR && nc_get_vara_double(nc, var, start, count, vel) == NC_NOERR);
    nc_close(nc);
    for (int k = 0; k < 3; k++) {
        ENSURE(pos[k] == b[k] && vel[k] == b[7 + k]);
        ENSURE(pos[3 + k] == g[k] && vel[3 + k] == 0.0);
    }
    printf("    scene 1 km up: model origin z = %.6g m; body 1 z %.12g m (file %.12g m), fixed body 2 z %.12g m\n",
           m->origin[2], b[2], pos[2], g[2]);
    remove(out);
    free(y);
    rc_model_free(m);
}

typedef struct lock_run {
    rc_model *m;
    char out[128];
    rc_status st;
    volatile int done;
} lock_run;

static void *run_thread(void *arg)
{
    lock_run *r = arg;
    rc_run_options o = {.output_path = r->out};
    r->st = rc_run(r->m, &o, NULL, NULL);
    r->done = 1;
    return NULL;
}

/* rc_netcdf_lock is the lock of the library's netCDF calls: a run of
 * another thread cannot create its results file while it is held, and
 * completes once it is released. */
static void test_bodystate_netcdf_lock_holds_runs(void)
{
    const char *set[] = {"/RUN:Tend=0.05"};
    lock_run r = {.m = compile_fixed(set, 1), .st = RC_EINTERNAL};
    ENSURE(r.m != NULL);
    if (!r.m) return;
    deck_path(r.out, sizeof r.out, "lock.nc");
    rc_netcdf_lock();
    pthread_t th;
    ENSURE(pthread_create(&th, NULL, run_thread, &r) == 0);
    const struct timespec wait = {0, 300000000}; /* 0.3 s: the run alone takes ~10 ms */
    nanosleep(&wait, NULL);
    const int done_while_held = r.done;
    rc_netcdf_unlock();
    pthread_join(th, NULL);
    ENSURE(done_while_held == 0 && r.done == 1 && r.st == RC_OK);
    remove(r.out);
    rc_model_free(r.m);
}

void suite_bodystate(void);
void suite_bodystate(void)
{
    RUN_TEST(test_bodystate_ids_and_offsets);
    RUN_TEST(test_bodystate_values_and_errors);
    RUN_TEST(test_bodystate_far_scene_in_deck_coordinates);
    RUN_TEST(test_bodystate_netcdf_lock_holds_runs);
}
