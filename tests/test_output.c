/* Output module: write netCDF files through src/output/output.h, read them back with
 * the netCDF C API and compare every value and attribute. */
#include "harness.h"
#include "base/error.h"
#include "output/output.h"

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
    rc_stats st = {12345, 23456, 345, 456, 5678, 67, 78, 8901, 2, 1, 0.1855, 0.0421, 3.7e-9};
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
    ENSURE(att_text(ncid, var_id(ncid, "time"), "units", buf, sizeof buf) && !strcmp(buf, "s"));
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
        {"time", "ms"}, {"body_position", "mm"}, {"body_velocity", "mm ms-1"},
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
}
