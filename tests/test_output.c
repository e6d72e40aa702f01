/* Output module: write netCDF files through src/output/output.h, read them back with
 * the netCDF C API and compare every value and attribute. */
#include "harness.h"
#include "base/error.h"
#include "output/output.h"
#include "base/sha256.h"
#include "ricochet/ricochet.h"
#include "model/model.h"
#include "solver/impacts.h"
#include "engine/assembly/event_kind.h"

#include <math.h>
#include <netcdf.h>
#include <stdlib.h>
#include <unistd.h>

enum { NB = 2, NI = 1, NE = 3, NF = 5 };

/* Fields of a frame, for the value formula. */
enum { F_POS, F_QUAT, F_VEL, F_OMEGA, F_PEN, F_FLOAD, F_FDAMP, F_FNORMAL, F_POINT, F_NORMAL,
       F_ENERGY, F_TIME };

/* High-entropy value of component i of field `field` in frame k. */
static double val(int k, int field, int i)
{
    return 0.0371 * (k + 1) + 0.1731 * field * field - 0.0113 * i + 1e-7 * (k * 37 + i * 11);
}

/* A temporary file name unique to this process. */
static void tmp_path(char *buf, size_t n, const char *tag)
{
    snprintf(buf, n, "/tmp/rc_test_output_%ld_%s.nc", (long)getpid(), tag);
}

/* The described model: 2 bodies, `ninter` interfaces, 3 energy entries. */
static const int body_id[NB] = {17, 4};
static const int body_fixed[NB] = {0, 1};
static const int inter_id[NI] = {3};
static const char *const inter_type[NI] = {"TYPE6"};
static const char *const energy_name[NE] = {"energy_kinetic", "energy_potential",
                                            "energy_dissipated_damping"};
static const char *const energy_long[NE] = {"kinetic energy", "gravitational potential energy",
                                            "energy dissipated by damping"};

static rc_output_meta make_meta(int ninter)
{
    rc_output_meta m = {0};
    m.title = "output test";
    m.case_path = "cases/test.rad";
    m.checksum = 0x0123456789abcdefUL;
    m.unit_mass = "kg";
    m.unit_length = "m";
    m.unit_time = "s";
    m.solver = "CVODE BDF, Newton, KLU sparse";
    m.rtol = 1.37e-6;
    m.atol_pos = 2.1e-9;
    m.atol_quat = 3.3e-8;
    m.atol_vel = 4.7e-7;
    m.atol_omega = 5.9e-6;
    m.atol_energy = 6.1e-5;
    m.nbody = NB;
    m.body_id = body_id;
    m.body_fixed = body_fixed;
    m.ninter = ninter;
    m.inter_id = ninter ? inter_id : NULL;
    m.inter_type = ninter ? inter_type : NULL;
    m.nenergy = NE;
    m.energy_name = energy_name;
    m.energy_long = energy_long;
    return m;
}

/* Storage of one frame, filled from val(). */
typedef struct frame_buf {
    double pos[NB * 3], quat[NB * 4], vel[NB * 3], omega[NB * 3];
    double pen[NI], fload[NI], fdamp[NI], fnormal[NI], point[NI * 3], normal[NI * 3];
    int mode[NI];
    double ffric[NI * 3], vslip[NI];
    int slip[NI];
    double energy[NE];
    rc_frame f;
} frame_buf;

static void fill(double *a, int n, int k, int field)
{
    for (int i = 0; i < n; i++) a[i] = val(k, field, i);
}

static void make_frame(frame_buf *b, int k, int with_inter)
{
    fill(b->pos, NB * 3, k, F_POS);
    fill(b->quat, NB * 4, k, F_QUAT);
    fill(b->vel, NB * 3, k, F_VEL);
    fill(b->omega, NB * 3, k, F_OMEGA);
    fill(b->pen, NI, k, F_PEN);
    fill(b->fload, NI, k, F_FLOAD);
    fill(b->fdamp, NI, k, F_FDAMP);
    fill(b->fnormal, NI, k, F_FNORMAL);
    fill(b->point, NI * 3, k, F_POINT);
    fill(b->normal, NI * 3, k, F_NORMAL);
    fill(b->energy, NE, k, F_ENERGY);
    b->mode[0] = k % 3;
    for (int i = 0; i < NI; i++) {
        for (int j = 0; j < 3; j++) b->ffric[3 * i + j] = 0.0371 * (k + 1) * (j - 1.3);
        b->vslip[i] = 0.0113 * k;
        b->slip[i] = k % 2;
    }
    rc_frame f = {.t = val(k, F_TIME, 0), .at_event = k == 2, .body_pos = b->pos, .body_quat = b->quat,
                  .body_vel = b->vel, .body_omega = b->omega, .inter_pen = b->pen, .inter_fload = b->fload,
                  .inter_fdamp = b->fdamp, .inter_fnormal = b->fnormal, .inter_point = b->point,
                  .inter_normal = b->normal, .inter_mode = b->mode, .inter_ffric = b->ffric,
                  .inter_vslip = b->vslip, .inter_slip = b->slip, .energy = b->energy /* no couplings */};
    if (!with_inter) /* without interfaces the engine has nothing to hand over */
        f.inter_pen = f.inter_fload = f.inter_fdamp = f.inter_fnormal = f.inter_point =
            f.inter_normal = f.inter_ffric = f.inter_vslip = NULL,
        f.inter_mode = f.inter_slip = NULL;
    b->f = f;
}

/* Write `nframes` frames; returns the number of failed calls. */
static int write_frames(rc_output *o, int nframes, int with_inter)
{
    int bad = 0;
    frame_buf b;
    rc_error e;
    for (int k = 0; k < nframes; k++) {
        make_frame(&b, k, with_inter);
        bad += rc_output_frame(o, &b.f, &e) != RC_OK;
    }
    return bad;
}

/* ---- Reading back ------------------------------------------------------ */

/* Text attribute into buf; 1 if present. */
static int att_text(int ncid, int varid, const char *name, char *buf, size_t n)
{
    size_t len;
    nc_type t;
    buf[0] = '\0';
    if (nc_inq_att(ncid, varid, name, &t, &len) != NC_NOERR || t != NC_CHAR || len >= n) return 0;
    if (nc_get_att_text(ncid, varid, name, buf) != NC_NOERR) return 0;
    buf[len] = '\0';
    return 1;
}

static size_t dim_len(int ncid, const char *name)
{
    int id;
    size_t len = (size_t)-1;
    if (nc_inq_dimid(ncid, name, &id) == NC_NOERR) nc_inq_dimlen(ncid, id, &len);
    return len;
}

static int var_id(int ncid, const char *name)
{
    int id = -1;
    if (nc_inq_varid(ncid, name, &id) != NC_NOERR) return -1;
    return id;
}

/* Compare a whole time series with val(): nframes records of n values. */
static void check_series(int ncid, const char *name, int field, int nframes, int n)
{
    double got[NF * NB * 4];
    int id = var_id(ncid, name), ndims = 0, dimids[NC_MAX_VAR_DIMS];
    ENSURE(id >= 0);
    if (id < 0) return;
    /* the stored size must be exactly what was written (and fit `got`) */
    size_t total = 1, len;
    ENSURE(nc_inq_var(ncid, id, NULL, NULL, &ndims, dimids, NULL) == NC_NOERR);
    for (int d = 0; d < ndims; d++) total *= nc_inq_dimlen(ncid, dimids[d], &len) ? 0 : len;
    ENSURE(total == (size_t)(nframes * n));
    if (total != (size_t)(nframes * n)) return;
    ENSURE(nc_get_var_double(ncid, id, got) == NC_NOERR);
    for (int k = 0; k < nframes; k++)
        for (int i = 0; i < n; i++) ENSURE(got[k * n + i] == val(k, field, i));
}

/* Every variable carries units and long_name. */
static void check_units_everywhere(int ncid)
{
    int nvars = 0;
    ENSURE(nc_inq_nvars(ncid, &nvars) == NC_NOERR);
    ENSURE(nvars > 0);
    for (int v = 0; v < nvars; v++) {
        char name[NC_MAX_NAME + 1], buf[256];
        nc_inq_varname(ncid, v, name);
        int has_units = att_text(ncid, v, "units", buf, sizeof buf) && buf[0];
        int has_long = att_text(ncid, v, "long_name", buf, sizeof buf) && buf[0];
        if (!has_units || !has_long) fprintf(stderr, "  variable %s lacks units/long_name\n", name);
        ENSURE(has_units && has_long);
    }
}

/* String element i of an NC_STRING variable equals `want`. */
static int string_is(int ncid, const char *var, size_t i, const char *want)
{
    char *s = NULL;
    int id = var_id(ncid, var);
    if (id < 0 || nc_get_var1_string(ncid, id, &i, &s) != NC_NOERR) return 0;
    int same = s && strcmp(s, want) == 0;
    nc_free_string(1, &s);
    return same;
}

/* ---- Tests ------------------------------------------------------------- */

static void test_output_roundtrip(void)
{
    char path[256], buf[256];
    tmp_path(path, sizeof path, "full");
    rc_output_meta meta = make_meta(NI);
    rc_output *o = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    ENSURE(o != NULL);
    if (!o) return;
    ENSURE(write_frames(o, NF, 1) == 0);
    ENSURE(rc_output_event(o, 0.0371, "contact_close", "/INTER/TYPE6/3", &e) == RC_OK);
    ENSURE(rc_output_event(o, 0.1113, "contact_open", "/INTER/TYPE6/3", &e) == RC_OK);
    rc_stats st = {12345, 23456, 345, 456, 5678, 67, 78, 8901, 2, 1, 0.1855, 0.0421, 3.7e-9, .impacts = 0};
    ENSURE(rc_output_close(o, &st, 1, NULL, &e) == RC_OK);

    int ncid;
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    /* dimensions */
    ENSURE(dim_len(ncid, "time") == NF);
    ENSURE(dim_len(ncid, "body") == NB);
    ENSURE(dim_len(ncid, "inter") == NI);
    ENSURE(dim_len(ncid, "vec3") == 3);
    ENSURE(dim_len(ncid, "quat") == 4);
    ENSURE(dim_len(ncid, "event") == 2);
    /* every time series, value by value */
    check_series(ncid, "time", F_TIME, NF, 1);
    check_series(ncid, "body_position", F_POS, NF, NB * 3);
    check_series(ncid, "body_quaternion", F_QUAT, NF, NB * 4);
    check_series(ncid, "body_velocity", F_VEL, NF, NB * 3);
    check_series(ncid, "body_angular_velocity", F_OMEGA, NF, NB * 3);
    check_series(ncid, "inter_penetration", F_PEN, NF, NI);
    check_series(ncid, "inter_force_load", F_FLOAD, NF, NI);
    check_series(ncid, "inter_force_damping", F_FDAMP, NF, NI);
    check_series(ncid, "inter_force_normal", F_FNORMAL, NF, NI);
    check_series(ncid, "inter_contact_point", F_POINT, NF, NI * 3);
    check_series(ncid, "inter_normal", F_NORMAL, NF, NI * 3);
    /* one slice by index: frame 3, body 1, quaternion */
    double q[4];
    size_t start[3] = {3, 1, 0}, count[3] = {1, 1, 4};
    ENSURE(nc_get_vara_double(ncid, var_id(ncid, "body_quaternion"), start, count, q) == NC_NOERR);
    for (int i = 0; i < 4; i++) ENSURE(q[i] == val(3, F_QUAT, 4 + i));
    /* friction: frame 3, interface 0, the force vector; speed and mode */
    double ff[3], vs;
    int sl;
    size_t s3[3] = {3, 0, 0}, c3[3] = {1, 1, 3}, s2[2] = {3, 0};
    ENSURE(nc_get_vara_double(ncid, var_id(ncid, "inter_force_friction"), s3, c3, ff) == NC_NOERR);
    for (int j = 0; j < 3; j++) ENSURE(ff[j] == 0.0371 * 4 * (j - 1.3));
    ENSURE(nc_get_var1_double(ncid, var_id(ncid, "inter_slip_speed"), s2, &vs) == NC_NOERR && vs == 0.0113 * 3);
    ENSURE(nc_get_var1_int(ncid, var_id(ncid, "inter_slip"), s2, &sl) == NC_NOERR && sl == 1);
    /* energies: one variable each, frame k entry j */
    for (int j = 0; j < NE; j++) {
        double en[NF];
        int id = var_id(ncid, energy_name[j]);
        ENSURE(id >= 0 && nc_get_var_double(ncid, id, en) == NC_NOERR);
        for (int k = 0; k < NF; k++) ENSURE(en[k] == val(k, F_ENERGY, j));
        ENSURE(att_text(ncid, id, "units", buf, sizeof buf) && strcmp(buf, "J") == 0);
        ENSURE(att_text(ncid, id, "long_name", buf, sizeof buf) && strcmp(buf, energy_long[j]) == 0);
    }
    /* integer series and fixed variables */
    int ev[NF], mode[NF], ids[NB], fixed[NB], iid, flags[4];
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "at_event"), ev) == NC_NOERR);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "inter_mode"), mode) == NC_NOERR);
    for (int k = 0; k < NF; k++) ENSURE(ev[k] == (k == 2) && mode[k] == k % 3);
    ENSURE(nc_get_att_int(ncid, var_id(ncid, "inter_mode"), "flag_values", flags) == NC_NOERR);
    ENSURE(flags[0] == 0 && flags[1] == 1 && flags[2] == 2);
    ENSURE(att_text(ncid, var_id(ncid, "inter_mode"), "flag_meanings", buf, sizeof buf) &&
           strcmp(buf, "inactive open closed released") == 0);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "body_id"), ids) == NC_NOERR);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "body_fixed"), fixed) == NC_NOERR);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "inter_id"), &iid) == NC_NOERR);
    ENSURE(ids[0] == 17 && ids[1] == 4 && fixed[0] == 0 && fixed[1] == 1 && iid == 3);
    ENSURE(string_is(ncid, "inter_type", 0, "TYPE6"));
    /* units: the expected ones on a few, present on all */
    ENSURE(att_text(ncid, var_id(ncid, "time"), "units", buf, sizeof buf) &&
           !strcmp(buf, "seconds since 1970-01-01 00:00:00"));
    ENSURE(att_text(ncid, var_id(ncid, "event_time"), "units", buf, sizeof buf) && !strcmp(buf, "s"));
    ENSURE(att_text(ncid, var_id(ncid, "time"), "standard_name", buf, sizeof buf) &&
           !strcmp(buf, "time"));
    ENSURE(att_text(ncid, var_id(ncid, "body_velocity"), "units", buf, sizeof buf) &&
           !strcmp(buf, "m s-1"));
    ENSURE(att_text(ncid, var_id(ncid, "inter_force_normal"), "units", buf, sizeof buf) &&
           !strcmp(buf, "N"));
    ENSURE(att_text(ncid, var_id(ncid, "body_quaternion"), "comment", buf, sizeof buf) &&
           !strcmp(buf, "w,x,y,z, body to global"));
    check_units_everywhere(ncid);
    /* events table */
    double et[2];
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "event_time"), et) == NC_NOERR);
    ENSURE(et[0] == 0.0371 && et[1] == 0.1113);
    ENSURE(string_is(ncid, "event_kind", 0, "contact_close"));
    ENSURE(string_is(ncid, "event_kind", 1, "contact_open"));
    ENSURE(string_is(ncid, "event_element", 1, "/INTER/TYPE6/3"));
    /* global attributes */
    long long steps = 0;
    double rtol = 0, resid = 0;
    ENSURE(att_text(ncid, NC_GLOBAL, "complete", buf, sizeof buf) && !strcmp(buf, "yes"));
    ENSURE(att_text(ncid, NC_GLOBAL, "status", buf, sizeof buf) && !strcmp(buf, "complete"));
    ENSURE(att_text(ncid, NC_GLOBAL, "case_checksum", buf, sizeof buf) &&
           !strcmp(buf, "0123456789abcdef"));
    ENSURE(att_text(ncid, NC_GLOBAL, "Conventions", buf, sizeof buf) && !strcmp(buf, "CF-1.8"));
    ENSURE(att_text(ncid, NC_GLOBAL, "source", buf, sizeof buf) &&
           !strcmp(buf, "ricochet " RICOCHET_VERSION));
    ENSURE(att_text(ncid, NC_GLOBAL, "unit_system", buf, sizeof buf) &&
           !strcmp(buf, "mass=kg length=m time=s"));
    ENSURE(att_text(ncid, NC_GLOBAL, "history", buf, sizeof buf) && !strncmp(buf, "created 2", 9));
    ENSURE(nc_get_att_longlong(ncid, NC_GLOBAL, "stats_steps", &steps) == NC_NOERR);
    ENSURE(steps == 12345);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "rtol", &rtol) == NC_NOERR && rtol == 1.37e-6);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "energy_balance_residual", &resid) == NC_NOERR &&
           resid == 3.7e-9);
    ENSURE(nc_close(ncid) == NC_NOERR);
    ENSURE(remove(path) == 0);
}

/* Records are buffered and written in blocks: a run longer than a block
 * (and than the event buffer) keeps every record and row, in order, and the
 * event rows carry their interface values (NaN when none is given). */
static void test_output_blocks_and_event_values(void)
{
    enum { NREC = 20000, NEV = 600 };
    char path[256];
    tmp_path(path, sizeof path, "blocks");
    rc_output_meta meta = make_meta(NI);
    rc_output *o = NULL;
    rc_error e;
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    if (!o) return;
    ENSURE(write_frames(o, NREC, 1) == 0);
    for (int k = 0; k < NEV; k++) {
        const double v[3] = {1e-3 * k, -0.5 * k, 10.0 * k};
        ENSURE(rc_output_event_values(o, 0.001 * k, "contact_close", "/INTER/TYPE6/3", k % 7 ? v : NULL, &e) ==
               RC_OK);
    }
    ENSURE(rc_output_close(o, NULL, 0, "stopped", &e) == RC_OK);

    int ncid;
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(dim_len(ncid, "time") == NREC);
    ENSURE(dim_len(ncid, "event") == NEV);
    double *t = malloc(NREC * sizeof *t), *pos = malloc((size_t)NREC * NB * 3 * sizeof *pos);
    int *mode = malloc(NREC * sizeof *mode);
    if (t && pos && mode) {
        ENSURE(nc_get_var_double(ncid, var_id(ncid, "time"), t) == NC_NOERR);
        ENSURE(nc_get_var_double(ncid, var_id(ncid, "body_position"), pos) == NC_NOERR);
        ENSURE(nc_get_var_int(ncid, var_id(ncid, "inter_mode"), mode) == NC_NOERR);
        int bad = 0;
        for (int k = 0; k < NREC; k++) {
            bad += t[k] != val(k, F_TIME, 0) || mode[k] != k % 3;
            for (int i = 0; i < NB * 3; i++) bad += pos[(size_t)k * NB * 3 + i] != val(k, F_POS, i);
        }
        ENSURE(bad == 0);
    }
    free(t);
    free(pos);
    free(mode);
    double et[NEV], ep[NEV], evn[NEV], efn[NEV];
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "event_time"), et) == NC_NOERR);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "event_penetration"), ep) == NC_NOERR);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "event_normal_speed"), evn) == NC_NOERR);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "event_force_normal"), efn) == NC_NOERR);
    int bad = 0;
    for (int k = 0; k < NEV; k++) {
        bad += et[k] != 0.001 * k;
        if (k % 7)
            bad += ep[k] != 1e-3 * k || evn[k] != -0.5 * k || efn[k] != 10.0 * k;
        else
            bad += !isnan(ep[k]) || !isnan(evn[k]) || !isnan(efn[k]);
    }
    ENSURE(bad == 0);
    ENSURE(string_is(ncid, "event_element", NEV - 1, "/INTER/TYPE6/3"));
    char buf[64];
    ENSURE(att_text(ncid, var_id(ncid, "event_normal_speed"), "units", buf, sizeof buf) && !strcmp(buf, "m s-1"));
    ENSURE(att_text(ncid, var_id(ncid, "event_force_normal"), "units", buf, sizeof buf) && !strcmp(buf, "N"));
    ENSURE(att_text(ncid, var_id(ncid, "event_penetration"), "units", buf, sizeof buf) && !strcmp(buf, "m"));
    ENSURE(att_text(ncid, NC_GLOBAL, "complete", buf, sizeof buf) && !strcmp(buf, "no"));
    ENSURE(nc_close(ncid) == NC_NOERR);
    ENSURE(remove(path) == 0);
}

/* A failed run: the frames written so far are kept, the file says why. */
static void test_output_incomplete_keeps_frames(void)
{
    char path[256], buf[256];
    tmp_path(path, sizeof path, "incomplete");
    rc_output_meta meta = make_meta(NI);
    rc_output *o = NULL;
    rc_error e;
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    if (!o) return;
    ENSURE(write_frames(o, 2, 1) == 0);
    ENSURE(rc_output_close(o, NULL, 0, "CVODE failed at t=0.5", &e) == RC_OK);

    int ncid, id;
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(dim_len(ncid, "time") == 2);
    ENSURE(dim_len(ncid, "event") == 0);
    check_series(ncid, "body_position", F_POS, 2, NB * 3);
    ENSURE(att_text(ncid, NC_GLOBAL, "complete", buf, sizeof buf) && !strcmp(buf, "no"));
    ENSURE(att_text(ncid, NC_GLOBAL, "status", buf, sizeof buf) &&
           strstr(buf, "incomplete") && strstr(buf, "CVODE failed at t=0.5"));
    ENSURE(nc_inq_attid(ncid, NC_GLOBAL, "stats_steps", &id) == NC_ENOTATT); /* no stats given */
    ENSURE(nc_close(ncid) == NC_NOERR);
    ENSURE(remove(path) == 0);
}

/* No interfaces: no inter dimension or variables; bodies and energies work. */
static void test_output_no_interfaces(void)
{
    char path[256], buf[256];
    tmp_path(path, sizeof path, "nointer");
    rc_output_meta meta = make_meta(0);
    meta.unit_mass = meta.unit_length = meta.unit_time = "";
    rc_output *o = NULL;
    rc_error e;
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    if (!o) return;
    ENSURE(write_frames(o, 3, 0) == 0);
    ENSURE(rc_output_close(o, NULL, 1, NULL, &e) == RC_OK);

    int ncid, id;
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(nc_inq_dimid(ncid, "inter", &id) == NC_EBADDIM);
    ENSURE(var_id(ncid, "inter_force_normal") < 0 && var_id(ncid, "inter_type") < 0);
    ENSURE(dim_len(ncid, "time") == 3);
    check_series(ncid, "body_velocity", F_VEL, 3, NB * 3);
    check_units_everywhere(ncid);
    ENSURE(att_text(ncid, NC_GLOBAL, "unit_system", buf, sizeof buf) &&
           !strcmp(buf, "undeclared (consistent units assumed)"));
    ENSURE(nc_close(ncid) == NC_NOERR);
    ENSURE(remove(path) == 0);
}

/* A case in g, mm, ms: the units of every quantity follow it. */
static void test_output_units_follow_case(void)
{
    char path[256], buf[256];
    tmp_path(path, sizeof path, "units");
    rc_output_meta meta = make_meta(NI);
    meta.unit_mass = "g";
    meta.unit_length = "mm";
    meta.unit_time = "ms";
    rc_output *o = NULL;
    rc_error e;
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    if (!o) return;
    ENSURE(rc_output_close(o, NULL, 1, NULL, &e) == RC_OK);

    int ncid;
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    static const char *const want[][2] = {
        {"time", "ms since 1970-01-01 00:00:00"}, {"event_time", "ms"}, {"body_position", "mm"}, {"body_velocity", "mm ms-1"},
        {"body_angular_velocity", "rad ms-1"}, {"inter_force_normal", "g mm ms-2"},
        {"energy_kinetic", "g mm2 ms-2"}, {"body_quaternion", "1"}};
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++)
        ENSURE(att_text(ncid, var_id(ncid, want[i][0]), "units", buf, sizeof buf) &&
               !strcmp(buf, want[i][1]));
    ENSURE(att_text(ncid, NC_GLOBAL, "unit_system", buf, sizeof buf) &&
           !strcmp(buf, "mass=g length=mm time=ms"));
    ENSURE(dim_len(ncid, "time") == 0);
    ENSURE(nc_close(ncid) == NC_NOERR);
    ENSURE(remove(path) == 0);
}

/* A path in a directory that does not exist: RC_EIO naming the path. */
static void test_output_open_bad_directory(void)
{
    const char *path = "/nonexistent_dir_rc_test/sub/out.nc";
    rc_output_meta meta = make_meta(NI);
    rc_output *o = (rc_output *)&meta; /* must be reset to NULL */
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_EIO);
    ENSURE(o == NULL);
    ENSURE(e.code == RC_EIO);
    ENSURE(strstr(e.msg, path) != NULL);
    ENSURE(rc_output_close(NULL, NULL, 1, NULL, &e) == RC_OK); /* NULL is a no-op */
}

/* A name netCDF refuses: RC_EIO naming the variable, no file left behind. */
static void test_output_open_bad_name_removes_file(void)
{
    char path[256];
    tmp_path(path, sizeof path, "badname");
    static const char *const names[NE] = {"energy_kinetic", "energy/bad", "energy_other"};
    rc_output_meta meta = make_meta(NI);
    meta.energy_name = names;
    rc_output *o = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_EIO);
    ENSURE(o == NULL);
    ENSURE(strstr(e.msg, path) && strstr(e.msg, "energy/bad"));
    ENSURE(access(path, F_OK) != 0);
}

/* SHA-256 against the FIPS 180-4 examples, and of a file. */
static void test_output_sha256_vectors(void)
{
    static const char *const want[4] = {
        "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855",
        "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad",
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1",
        "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"};
    char hex[65];
    rc_sha256_hex("", 0, hex);
    ENSURE(!strcmp(hex, want[0]));
    rc_sha256_hex("abc", 3, hex);
    ENSURE(!strcmp(hex, want[1]));
    rc_sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq", 56, hex);
    ENSURE(!strcmp(hex, want[2]));
    char path[256];
    tmp_path(path, sizeof path, "million_a");
    FILE *f = fopen(path, "wb");
    ENSURE(f != NULL);
    if (!f) return;
    for (int k = 0; k < 1000000; k++) fputc('a', f);
    fclose(f);
    ENSURE(rc_sha256_file(path, hex) == 0 && !strcmp(hex, want[3]));
    ENSURE(rc_sha256_file("/nonexistent_rc_test_file", hex) == -1);
    remove(path);
}

/* Coordinate variables (ids), the CF time axis, provenance attributes,
 * solver settings, the surfaces and the impacts table. */
static void test_output_coordinates_provenance(void)
{
    char path[256], deck[256], inc[256], buf[1024];
    tmp_path(path, sizeof path, "coords");
    tmp_path(deck, sizeof deck, "deck_abc");
    tmp_path(inc, sizeof inc, "include_empty");
    FILE *f = fopen(deck, "wb");
    if (f) {
        fputs("abc", f);
        fclose(f);
    }
    f = fopen(inc, "wb");
    if (f) fclose(f);
    const char *files[2] = {deck, inc};
    static const int surf_id[3] = {11, 12, 13}, surf_body[3] = {0, -1, 1}, inter_surf[2] = {0, 1};
    static const char *const surf_kind[3] = {"SPHERE", "PLANE", "BOX"};
    static const double spoint[9] = {0, 0, 0, 0, 0, -1, 0.1, 0.2, 0.3}, snormal[9] = {0, 0, 0, 0, 0, 1, 0, 0, 0};
    static const double srad[3] = {0.05, 0, 0};
    double sparam[3 * RC_OUT_SURF_NPARAM] = {0};
    sparam[2 * RC_OUT_SURF_NPARAM + 0] = 0.5;
    rc_output_meta meta = make_meta(NI);
    meta.case_path = deck;
    meta.nfile = 2;
    meta.file = files;
    meta.max_order = 4;
    meta.max_steps = 12345;
    meta.hmax = 0.25;
    meta.h0 = 1e-7;
    meta.t_end = 2.5;
    meta.dt_out = 1e-3;
    meta.tol_derived = "atol_position atol_velocity";
    meta.sampling_note = "output interval 0.001 s samples a contact of ~0.0055 s with ~5 records";
    meta.nsurf = 3;
    meta.surf_id = surf_id;
    meta.surf_kind = surf_kind;
    meta.surf_body = surf_body;
    meta.surf_point = spoint;
    meta.surf_normal = snormal;
    meta.surf_radius = srad;
    meta.surf_param = sparam;
    meta.inter_surf = inter_surf;
    rc_output *o = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_output_open(&o, path, &meta, &e) == RC_OK);
    if (!o) return;
    ENSURE(write_frames(o, NF, 1) == 0);
    const rc_impact imp[2] = {{3, 0.1, 0.103, 0.003, 1.2e-3, 0.1015, 1275.0, 0.1014, 1.4, 1.12, 0.8, 0.356},
                              {3, 0.3, NAN, NAN, 1e-5, 0.31, 10.0, 0.31, 0.01, NAN, NAN, NAN}};
    ENSURE(rc_output_impacts(o, 2, imp, 0, NULL, &e) == RC_OK);
    ENSURE(rc_output_close(o, NULL, 1, NULL, &e) == RC_OK);

    int ncid, ids[NB], iid, sid[3], sbody[3], isurf[2];
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    /* coordinate variables: named as their dimension, holding the ids */
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "body"), ids) == NC_NOERR && ids[0] == 17 && ids[1] == 4);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "inter"), &iid) == NC_NOERR && iid == 3);
    int dimid = -1, vdim = -2;
    ENSURE(nc_inq_dimid(ncid, "body", &dimid) == NC_NOERR && nc_inq_vardimid(ncid, var_id(ncid, "body"), &vdim) == NC_NOERR &&
           vdim == dimid);
    /* the CF time axis */
    ENSURE(att_text(ncid, var_id(ncid, "time"), "units", buf, sizeof buf) &&
           !strcmp(buf, "seconds since 1970-01-01 00:00:00"));
    ENSURE(att_text(ncid, var_id(ncid, "time"), "calendar", buf, sizeof buf) && !strcmp(buf, "proleptic_gregorian"));
    ENSURE(att_text(ncid, var_id(ncid, "time"), "axis", buf, sizeof buf) && !strcmp(buf, "T"));
    /* provenance */
    ENSURE(att_text(ncid, NC_GLOBAL, "command_line", buf, sizeof buf) && strstr(buf, "run_tests"));
    ENSURE(att_text(ncid, NC_GLOBAL, "ricochet_version", buf, sizeof buf) && !strcmp(buf, rc_version()));
    ENSURE(att_text(ncid, NC_GLOBAL, "ricochet_commit", buf, sizeof buf) && strlen(buf) > 0);
    ENSURE(att_text(ncid, NC_GLOBAL, "case_sha256", buf, sizeof buf) &&
           !strcmp(buf, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
    char want[1024];
    snprintf(want, sizeof want, "%s  %s\n%s  %s", "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad",
             deck, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855", inc);
    ENSURE(att_text(ncid, NC_GLOBAL, "input_files_sha256", buf, sizeof buf) && !strcmp(buf, want));
    /* solver settings */
    long long ll = 0;
    double dv = 0;
    ENSURE(nc_get_att_longlong(ncid, NC_GLOBAL, "max_order", &ll) == NC_NOERR && ll == 4);
    ENSURE(nc_get_att_longlong(ncid, NC_GLOBAL, "max_steps", &ll) == NC_NOERR && ll == 12345);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "hmax", &dv) == NC_NOERR && dv == 0.25);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "h0", &dv) == NC_NOERR && dv == 1e-7);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "dt_out", &dv) == NC_NOERR && dv == 1e-3);
    ENSURE(nc_get_att_double(ncid, NC_GLOBAL, "t_end", &dv) == NC_NOERR && dv == 2.5);
    ENSURE(att_text(ncid, NC_GLOBAL, "tolerances_derived", buf, sizeof buf) &&
           !strcmp(buf, "atol_position atol_velocity"));
    ENSURE(att_text(ncid, NC_GLOBAL, "sampling_note", buf, sizeof buf) && strstr(buf, "~5 records"));
    /* surfaces: ids, kinds, carrying body ids (-1 fixed in space), geometry */
    ENSURE(dim_len(ncid, "surface") == 3 && dim_len(ncid, "surface_parameter") == RC_OUT_SURF_NPARAM);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "surface"), sid) == NC_NOERR && sid[2] == 13);
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "surface_body"), sbody) == NC_NOERR && sbody[0] == 17 &&
           sbody[1] == -1 && sbody[2] == 4);
    ENSURE(string_is(ncid, "surface_kind", 2, "BOX"));
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "inter_surface"), isurf) == NC_NOERR && isurf[0] == 11 && isurf[1] == 12);
    double r[3], pt[9], prm[3 * RC_OUT_SURF_NPARAM];
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "surface_radius"), r) == NC_NOERR && r[0] == 0.05);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "surface_point"), pt) == NC_NOERR && pt[8] == 0.3);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "surface_parameters"), prm) == NC_NOERR &&
           prm[2 * RC_OUT_SURF_NPARAM] == 0.5);
    ENSURE(att_text(ncid, var_id(ncid, "surface_point"), "units", buf, sizeof buf) && !strcmp(buf, "m"));
    /* impacts table, with units */
    ENSURE(dim_len(ncid, "impact") == 2);
    double col[2];
    int ii[2];
    ENSURE(nc_get_var_int(ncid, var_id(ncid, "impact_inter"), ii) == NC_NOERR && ii[0] == 3 && ii[1] == 3);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "impact_peak_force"), col) == NC_NOERR && col[0] == 1275.0);
    ENSURE(nc_get_var_double(ncid, var_id(ncid, "impact_restitution"), col) == NC_NOERR && col[0] == 0.8 &&
           isnan(col[1]));
    ENSURE(att_text(ncid, var_id(ncid, "impact_peak_force"), "units", buf, sizeof buf) && !strcmp(buf, "N"));
    ENSURE(att_text(ncid, var_id(ncid, "impact_energy_lost"), "units", buf, sizeof buf) && !strcmp(buf, "J"));
    ENSURE(att_text(ncid, var_id(ncid, "impact_duration"), "units", buf, sizeof buf) && !strcmp(buf, "s"));
    ENSURE(nc_close(ncid) == NC_NOERR);
    remove(path);
    remove(deck);
    remove(inc);
}

/* Closed form of the demo's bounce: a 1 kg sphere reaching the plane at
 * v0 = sqrt(2 g 0.1 m) on a linear spring-dashpot (k = 1e6 N/m, c =
 * 148.710194195 N s/m) under gravity g, force clipped at zero:
 *   P(t) = g/w^2 + e^(-s t) (A cos(wd t) + B sin(wd t)),  A = -g/w^2,
 *   B = (v0 + s A)/wd, s = zeta w, wd = w sqrt(1 - zeta^2);
 * the force k P + c P' stops at its zero t_r (the contact releases), then the
 * sphere flies freely until P = 0. */
typedef struct bounce { double w, s, wd, A, B, g, k, c; } bounce;
static double bx(const bounce *b, double t) { return b->g / (b->w * b->w) + exp(-b->s * t) * (b->A * cos(b->wd * t) + b->B * sin(b->wd * t)); }
static double bv(const bounce *b, double t)
{
    return exp(-b->s * t) * ((-b->s * b->A + b->wd * b->B) * cos(b->wd * t) + (-b->s * b->B - b->wd * b->A) * sin(b->wd * t));
}
static double bf(const bounce *b, double t) { return b->k * bx(b, t) + b->c * bv(b, t); }
/* d F / d t = k P' + c P'' with P'' = g - F/m (m = 1) */
static double bdf(const bounce *b, double t) { return b->k * bv(b, t) + b->c * (b->g - bf(b, t)); }
/* Root of fn on [lo, hi] by bisection (a sign change there). */
static double bisect(const bounce *b, double (*fn)(const bounce *, double), double lo, double hi)
{
    const double flo = fn(b, lo);
    for (int k = 0; k < 200; k++) {
        const double mid = 0.5 * (lo + hi), fm = fn(b, mid);
        if ((fm > 0) == (flo > 0)) lo = mid;
        else hi = mid;
    }
    return 0.5 * (lo + hi);
}

static void test_output_impacts_demo_closed_form(void)
{
    char path[256];
    tmp_path(path, sizeof path, "demo_impacts");
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load("cases/demo_sphere_drop.rad", &c, &e) == RC_OK);
    ENSURE(c && rc_model_compile(c, &m, &e) == RC_OK);
    if (!m) {
        rc_case_free(c);
        return;
    }
    rc_run_options opt = {.output_path = path, .t_end_override = 0.3};
    rc_stats st;
    ENSURE(rc_run(m, &opt, &st, &e) == RC_OK);
    ENSURE(st.impacts >= 1);
    /* closed form of the first impact */
    const double g = 9.81, k = 1e6, cd = 148.710194195, v0 = sqrt(2 * g * 0.1);
    bounce b = {sqrt(k), 0, 0, 0, 0, g, k, cd};
    const double zeta = cd / (2 * sqrt(k));
    b.s = zeta * b.w;
    b.wd = b.w * sqrt(1 - zeta * zeta);
    b.A = -g / k;
    b.B = (v0 + b.s * b.A) / b.wd;
    const double T = 3.14159265358979323846 / b.wd;
    const double t_rel = bisect(&b, bf, 0.5 * T, 1.2 * T), t_pen = bisect(&b, bv, 0.2 * T, 0.8 * T);
    const double t_fmax = bisect(&b, bdf, 1e-9, t_pen);
    const double xr = bx(&b, t_rel), vr = bv(&b, t_rel);
    const double tfly = (-vr - sqrt(vr * vr - 2 * g * xr)) / g, v_out = -(vr + g * tfly);
    const rc_impact *r = &st.impact[0];
    const double want[5] = {t_rel, bx(&b, t_pen), bf(&b, t_fmax), v_out, v_out / v0};
    const double got[5] = {r->duration, r->pen_max, r->fn_max, r->v_out, r->restitution};
    static const char *const name[5] = {"duration [s]", "max penetration [m]", "peak force [N]", "speed out [m/s]",
                                        "restitution [-]"};
    for (int q = 0; q < 5; q++) {
        printf("    demo impact 1: %-20s ricochet %.7g, closed form %.7g, rel. diff %.1e\n", name[q], got[q], want[q],
               fabs(got[q] / want[q] - 1));
        ENSURE(fabs(got[q] / want[q] - 1) < 1e-4);
    }
    ENSURE(fabs(r->v_in / v0 - 1) < 1e-5); /* the free fall, integrated within the tolerances */
    /* energy lost: the damping work; equals the kinetic energy lost less the
     * gravity work over the penetration, within the tolerances */
    ENSURE(fabs(r->energy_lost - 0.5 * (v0 * v0 - v_out * v_out)) < 1e-3 * 0.5 * v0 * v0);
    /* the file has the same table */
    int ncid;
    double dur = 0;
    size_t start[1] = {0};
    ENSURE(nc_open(path, NC_NOWRITE, &ncid) == NC_NOERR);
    ENSURE(dim_len(ncid, "impact") == (size_t)st.impacts);
    ENSURE(nc_get_var1_double(ncid, var_id(ncid, "impact_duration"), start, &dur) == NC_NOERR && dur == r->duration);
    ENSURE(nc_close(ncid) == NC_NOERR);
    remove(path);
    /* the sampling note: none at the demo's Dt_out = 0.1 ms (~31 records
     * per contact), given at 1 ms (~3 records) */
    char note[320];
    rc_impacts_sampling_note(m, note, sizeof note);
    ENSURE(note[0] == '\0');
    const double dt = m->dtout;
    m->dtout = 1e-3;
    rc_impacts_sampling_note(m, note, sizeof note);
    printf("    Dt_out 1 ms: %s\n", note);
    ENSURE(strstr(note, "output interval 0.001 s samples a contact of ~0.0031 s") && strstr(note, "~3 records"));
    m->dtout = dt;
    rc_model_free(m);
    rc_case_free(c);
}

/* Every event kind has one name, distinct from the others, listed in the
 * events table's kinds of docs/output-format.md. */
static void test_output_event_kind_names_documented(void)
{
    FILE *f = fopen("docs/output-format.md", "rb");
    ENSURE(f != NULL);
    if (!f) return;
    static char doc[1 << 17];
    size_t n = fread(doc, 1, sizeof doc - 1, f);
    fclose(f);
    doc[n] = '\0';
    const char *kinds = strstr(doc, "Kinds (element");
    ENSURE(kinds != NULL);
    ENSURE(rc_event_kind_name(RC_EV_NONE) == NULL && rc_event_kind_name(RC_EV_NKINDS) == NULL);
    for (int k = RC_EV_NONE + 1; k < RC_EV_NKINDS; k++) {
        const char *name = rc_event_kind_name((rc_event_kind)k);
        ENSURE(name != NULL && name[0] != '\0');
        if (!name) continue;
        for (int j = RC_EV_NONE + 1; j < k; j++) ENSURE(strcmp(name, rc_event_kind_name((rc_event_kind)j)) != 0);
        char quoted[64];
        snprintf(quoted, sizeof quoted, "`%s`", name);
        if (kinds && !strstr(kinds, quoted)) printf("    %s not in docs/output-format.md\n", name);
        ENSURE(kinds && strstr(kinds, quoted));
    }
}

void suite_output(void);
void suite_output(void)
{
    RUN_TEST(test_output_roundtrip);
    RUN_TEST(test_output_incomplete_keeps_frames);
    RUN_TEST(test_output_blocks_and_event_values);
    RUN_TEST(test_output_no_interfaces);
    RUN_TEST(test_output_units_follow_case);
    RUN_TEST(test_output_open_bad_directory);
    RUN_TEST(test_output_open_bad_name_removes_file);
    RUN_TEST(test_output_sha256_vectors);
    RUN_TEST(test_output_coordinates_provenance);
    RUN_TEST(test_output_impacts_demo_closed_form);
    RUN_TEST(test_output_event_kind_names_documented);
}
