/* The preload (/SOLVER Preload, rc_model_set_preload; docs/theory.md 7.8
 * "Preload"): a dynamic run started from the static equilibrium at t = 0.
 *
 * A column of N = 5 equal spheres (m = 1 kg, R = 0.0625 m) on the floor,
 * held to the vertical, linear contacts k = 1e5 N/m, constant gravity
 * g = 9.81 m/s^2: the contact under sphere j (1 at the bottom; contact 1
 * the floor's) carries the weight of the spheres j..N, F_j = (N - j + 1) m g,
 * its penetration F_j / k. Preloaded, the dynamic run (CVODE and IDA) keeps
 * those forces at every record to 1e-8 and its bodies at rest; without the
 * preload the same deck (the spheres touching without load) falls into its
 * contacts: speeds of order g / omega (omega = sqrt(k / m)).
 *
 * A sphere on a plane under gravity tilted by theta below the friction
 * angle (tan(theta) < mu), its rotations held: preloaded, its friction
 * force is m g sin(theta) from the first record on and it does not move;
 * without the preload it moves (the contact loads from zero).
 *
 * And the refusals: a model outside the static analysis' scope, a body with
 * an initial velocity, the setter's arguments (RC_EINPUT, naming the card).
 */
#include <math.h>
#include <netcdf.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "model/model.h"
#include "testutil.h"

#define COL_N 5
#define COL_R 0.0625
#define COL_K 1e5
#define COL_M 1.0
#define G 9.81

/* Append printf-style text to the growing buffer *b (length *n, room *cap). */
static void put(char **b, size_t *n, size_t *cap, const char *fmt, ...)
{
    if (!*b) return;
    va_list ap;
    va_start(ap, fmt);
    char line[512];
    const int k = vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    if (k < 0) return;
    if (*n + (size_t)k + 1 > *cap) {
        char *nb = realloc(*b, 2 * (*cap + (size_t)k + 1));
        if (!nb) {
            free(*b);
            *b = NULL;
            return;
        }
        *b = nb;
        *cap = 2 * (*cap + (size_t)k + 1);
    }
    memcpy(*b + *n, line, (size_t)k + 1);
    *n += (size_t)k;
}

/* The column deck: N spheres touching (each on the one below, the first on
 * the floor z = 0), /SOLVER Method `method`, Preload `preload`; with
 * `inivel` sphere 3 given 0.1 m/s along z. */
static char *column_deck(int method, int preload, int inivel)
{
    size_t n = 0, cap = 8192;
    char *b = malloc(cap);
    if (b) b[0] = '\0';
    put(&b, &n, &cap, "#RADIOSS STARTER\n/BEGIN\npreload: column of %d spheres\n      2022         0\n", COL_N);
    put(&b, &n, &cap, "                  kg                   m                   s\n");
    put(&b, &n, &cap, "                  kg                   m                   s\n");
    put(&b, &n, &cap, "/FUNCT/1\nlinear k\n%20d%20d\n%20d%20.10g\n", 0, 0, 1, COL_K);
    put(&b, &n, &cap, "/NODE\n");
    for (int j = 1; j <= COL_N; j++) put(&b, &n, &cap, "%10d%20d%20d%20.10g\n", j, 0, 0, COL_R * (2 * j - 1));
    for (int j = 1; j <= COL_N; j++) {
        put(&b, &n, &cap, "/RBODY/%d\nsphere %d\n%10d%40s%10d%10d\n", j, j, j, "", 1, j);
        put(&b, &n, &cap, "%20.10g%20.10g%20.10g\n%20d%20d%20d\n", 0.4 * COL_M * COL_R * COL_R,
            0.4 * COL_M * COL_R * COL_R, 0.4 * COL_M * COL_R * COL_R, 0, 0, 0);
    }
    for (int j = 1; j <= COL_N; j++)
        put(&b, &n, &cap, "/SURF/ELLIPS/%d\nsphere %d\n%10d%10d%10d\n%20d%20d%20.10g\n%20.10g%20.10g%20.10g\n", j, j,
            0, 2, j, 0, 0, COL_R * (2 * j - 1), COL_R, COL_R, COL_R);
    put(&b, &n, &cap, "/SURF/PLANE/%d\nfloor\n%20d%20d%20d\n%20d%20d%20d\n", COL_N + 1, 0, 0, 0, 0, 0, 1);
    for (int j = 1; j <= COL_N; j++) put(&b, &n, &cap, "/GRNOD/NODE/%d\nsphere %d\n%10d\n", j, j, j);
    put(&b, &n, &cap, "/GRNOD/NODE/%d\nall\n", COL_N + 1);
    for (int j = 1; j <= COL_N; j++) put(&b, &n, &cap, "%10d", j);
    put(&b, &n, &cap, "\n/BCS/1\nheld to the vertical\n   110 000         0%10d\n", COL_N + 1);
    put(&b, &n, &cap, "/GRAV/1\ngravity\n         0         Z         0         0         0%30s%20.10g\n", "1", -G);
    if (inivel) put(&b, &n, &cap, "/INIVEL/TRA/1\nmoving\n%20d%20d%20.10g%10d%10d\n", 0, 0, 0.1, 3, 0);
    for (int j = 1; j <= COL_N; j++) {
        put(&b, &n, &cap, "/INTER/TYPE6/%d\ncontact %d\n%10d%10d\n", j, j, j == 1 ? COL_N + 1 : j - 1, j);
        put(&b, &n, &cap, "%60s\n%20s%10d%10d%10d%10d\n%10d%10d%50s\n%10d\n%30s%10d\n", "0", "0", 0, 0, 0, 0, 1, 0,
            "0", 0, "0", 0);
    }
    put(&b, &n, &cap, "/RUN\n%20.10g%20.10g\n", 0.5, 0.05);
    put(&b, &n, &cap, "/SOLVER\n%10d%10d%10d%20.10g%20d%20d%10d\n", method, 5, 100000, 1e-8, 0, 0, preload);
    put(&b, &n, &cap, "/END\n");
    return b;
}

/* A whole double variable of a results file into a new array (NULL: not
 * read), its length into *len. */
static double *nc_var(const char *path, const char *name, size_t *len)
{
    int nc, v, nd, dims[8];
    double *x = NULL;
    *len = 0;
    if (nc_open(path, NC_NOWRITE, &nc) != NC_NOERR) return NULL;
    if (nc_inq_varid(nc, name, &v) == NC_NOERR && nc_inq_varndims(nc, v, &nd) == NC_NOERR && nd <= 8 &&
        nc_inq_vardimid(nc, v, dims) == NC_NOERR) {
        size_t total = 1;
        for (int k = 0; k < nd; k++) {
            size_t l = 0;
            nc_inq_dimlen(nc, dims[k], &l);
            total *= l;
        }
        x = malloc((total + 1) * sizeof *x);
        if (x && nc_get_var_double(nc, v, x) != NC_NOERR) {
            free(x);
            x = NULL;
        }
        if (x) *len = total;
    }
    nc_close(nc);
    return x;
}

/* A global attribute's text into buf ("" when absent); its integer
 * attribute `iname` into *iv (-1 when absent). */
static void nc_attr(const char *path, const char *name, char *buf, size_t n, const char *iname, long long *iv)
{
    int nc;
    size_t l = 0;
    buf[0] = '\0';
    *iv = -1;
    if (nc_open(path, NC_NOWRITE, &nc) != NC_NOERR) return;
    if (nc_inq_attlen(nc, NC_GLOBAL, name, &l) == NC_NOERR && l < n) {
        nc_get_att_text(nc, NC_GLOBAL, name, buf);
        buf[l] = '\0';
    }
    if (nc_get_att_longlong(nc, NC_GLOBAL, iname, iv) != NC_NOERR) *iv = -1;
    nc_close(nc);
}

/* Compile `text` (optionally with the preload set by the library), run it
 * to its end into a results file; *stats. NULL path: the run failed. */
static const char *run_deck(const char *text, const char *name, int set_preload, rc_stats *st)
{
    rc_error e;
    rc_model *m = tu_compile_text(text, name, &e);
    if (!m) fprintf(stderr, "  %s: %s\n", name, e.msg);
    ENSURE(m != NULL);
    if (!m) return NULL;
    if (set_preload >= 0) ENSURE(rc_model_set_preload(m, set_preload, &e) == RC_OK);
    char out[128];
    snprintf(out, sizeof out, "%s.nc", name);
    const char *path = tu_tmp_write(out, "");
    rc_run_options o = {.output_path = path};
    const rc_status s = rc_run(m, &o, st, &e);
    if (s) fprintf(stderr, "  %s: run: %s\n", name, e.msg);
    ENSURE(s == RC_OK);
    rc_model_free(m);
    return s == RC_OK ? path : NULL;
}

/* max |v| [m/s] over every record and body of a results file */
static double max_speed(const char *path)
{
    size_t n = 0;
    double *v = nc_var(path, "body_velocity", &n), w = 0.0;
    ENSURE(v != NULL && n > 0);
    for (size_t k = 0; v && k < n; k++) w = fmax(w, fabs(v[k]));
    free(v);
    return w;
}

/* The column preloaded on `method` (1 CVODE, 2 IDA): at rest, the contact
 * forces the closed form at every record, the contacts closed from the
 * start, no event. */
static void column_preloaded(int method)
{
    char *text = column_deck(method, 1, 0);
    ENSURE(text != NULL);
    if (!text) return;
    rc_stats st;
    const char *path = run_deck(text, method == 1 ? "preload_col_cvode.rad" : "preload_col_ida.rad", -1, &st);
    free(text);
    if (!path) return;
    ENSURE(st.preloaded == 1 && st.preload_iters > 0 && st.events == 0);
    /* the velocity bound: KINSOL accepts a residual force of at most 1e-8
     * of a body's weight m g (static.c, kin_solve); N such imbalances
     * excite the column's modes, the slowest of frequency
     * omega_1 = 2 sqrt(k / m) sin(pi / (2 (2 N + 1))), to speeds of at most
     * N 1e-8 m g / (m omega_1) = 5.4e-9 m/s */
    const double w1 = 2.0 * sqrt(COL_K / COL_M) * sin(3.14159265358979323846 / (2.0 * (2 * COL_N + 1)));
    const double vbound = COL_N * 1e-8 * G / w1;
    const double vmax = max_speed(path);
    printf("    method %d: max |v| = %.3g m/s (bound %.3g), %ld preload Newton iterations, %ld steps\n", method, vmax,
           vbound, st.preload_iters, st.steps);
    ENSURE(vmax < vbound);
    size_t nf = 0, nm = 0, nt = 0;
    double *f = nc_var(path, "inter_force_normal", &nf), *mode = nc_var(path, "inter_mode", &nm);
    double *t = nc_var(path, "time", &nt);
    ENSURE(f && mode && t && nt >= 11 && nf == nt * COL_N && nm == nf);
    double worst = 0.0;
    for (size_t r = 0; f && mode && t && nf == nt * COL_N && r < nt; r++)
        for (int j = 1; j <= COL_N; j++) {
            const double ref = (COL_N - j + 1) * COL_M * G;
            worst = fmax(worst, fabs(f[r * COL_N + j - 1] - ref) / ref);
            ENSURE(mode[r * COL_N + j - 1] == 2.0); /* closed */
        }
    printf("    method %d: contact forces against (N - j + 1) m g: max relative error %.3g over %zu records\n",
           method, worst, nt);
    ENSURE(worst < 1e-8);
    ENSURE(t && fabs(t[nt - 1] - 0.5) < 1e-12);
    char pl[1024];
    long long it = -1;
    nc_attr(path, "preload", pl, sizeof pl, "preload_newton_iters", &it);
    ENSURE(strstr(pl, "static equilibrium") != NULL && it == st.preload_iters);
    free(f);
    free(mode);
    free(t);
}

static void test_preload_column(void)
{
    column_preloaded(1);
    column_preloaded(2);
    /* the same deck without the preload: the spheres fall into their
     * contacts, at speeds of the order of g / omega = 0.031 m/s (a mass on
     * a spring loaded at once by its weight reaches g / omega) */
    char *text = column_deck(1, 0, 0);
    ENSURE(text != NULL);
    if (!text) return;
    rc_stats st;
    const char *path = run_deck(text, "preload_col_none.rad", -1, &st);
    if (path) {
        const double vmax = max_speed(path), vref = G / sqrt(COL_K / COL_M);
        printf("    no preload: max |v| = %.3g m/s (g / omega = %.3g)\n", vmax, vref);
        ENSURE(st.preloaded == 0);
        ENSURE(vmax > 0.5 * vref);
        char pl[64];
        long long it;
        nc_attr(path, "preload", pl, sizeof pl, "preload_newton_iters", &it);
        ENSURE(pl[0] == '\0' && it == -1);
    }
    /* the setter turns the preload on for the same model: at rest again */
    path = run_deck(text, "preload_col_set.rad", 1, &st);
    if (path) {
        ENSURE(st.preloaded == 1);
        ENSURE(max_speed(path) < 1e-8);
    }
    free(text);
}

/* The sphere on the plane (case of validation/static_friction): m = 1 kg,
 * R = 0.05 m touching z = 0, rotations held, k = 1e5 N/m, Fric mu = 0.3,
 * Stiff K_t = 2e4 N/m; constant gravity tilted by theta from -z toward +x.
 * `fv`: a speed multiplier of friction (fct_IDfv 2), outside the static
 * scope. */
static char *incline_deck(double theta, int preload, int fv)
{
    size_t n = 0, cap = 4096;
    char *b = malloc(cap);
    if (b) b[0] = '\0';
    put(&b, &n, &cap, "#RADIOSS STARTER\n/BEGIN\npreload: sphere on an incline below the friction angle\n");
    put(&b, &n, &cap, "      2022         0\n                  kg                   m                   s\n");
    put(&b, &n, &cap, "                  kg                   m                   s\n");
    put(&b, &n, &cap, "/FUNCT/1\nlinear k\n%20d%20d\n%20d%20d\n", 0, 0, 1, 100000);
    /* a speed multiplier that is 0 at rest: no static friction */
    put(&b, &n, &cap, "/FUNCT/2\nspeed multiplier\n%20d%20d\n%20d%20d\n", 0, 0, 10, 1);
    put(&b, &n, &cap, "/NODE\n%10d%20d%20d%20.10g\n", 1, 0, 0, 0.05);
    put(&b, &n, &cap, "/RBODY/1\nsphere\n%10d%40s%10d%10d\n%20.10g%20.10g%20.10g\n%20d%20d%20d\n", 1, "", 1, 1, 0.001,
        0.001, 0.001, 0, 0, 0);
    put(&b, &n, &cap, "/SURF/ELLIPS/1\nsphere\n%10d%10d%10d\n%20d%20d%20.10g\n%20.10g%20.10g%20.10g\n", 0, 2, 1, 0, 0,
        0.05, 0.05, 0.05, 0.05);
    put(&b, &n, &cap, "/SURF/PLANE/2\nfloor\n%20d%20d%20d\n%20d%20d%20d\n", 0, 0, 0, 0, 0, 1);
    put(&b, &n, &cap, "/GRNOD/NODE/1\nsphere\n%10d\n/BCS/1\nrotations held\n   000 111         0         1\n", 1);
    put(&b, &n, &cap, "/GRAV/1\ngravity x\n         0         X         0         0         0%30s%20.13g\n", "1",
        G * sin(theta));
    put(&b, &n, &cap, "/GRAV/2\ngravity z\n         0         Z         0         0         0%30s%20.13g\n", "1",
        -G * cos(theta));
    put(&b, &n, &cap, "/INTER/TYPE6/1\nsphere - floor\n%10d%10d\n%40s%20s\n", 1, 2, "0.3", "0");
    put(&b, &n, &cap, "%20s%10d%10d%10d%10d\n%10d%10d%50s\n", "0", 0, 0, 0, 0, 1, 0, "0");
    put(&b, &n, &cap, "%10d%30s\n%30s%10d\n", 0, "20000", "0", 0);
    put(&b, &n, &cap, "/RUN\n%20.10g%20.10g\n", 0.5, 0.05);
    put(&b, &n, &cap, "/SOLVER\n%10d%10d%10d%20.10g%20d%20d%10d\n", 1, 5, 100000, 1e-8, 0, 0, preload);
    put(&b, &n, &cap, "/END\n");
    if (b && fv) { /* fct_IDfv 2: columns 51-60 of the line Istick IRS IRm Inacti fct_IDff fct_IDfv */
        char *p = strstr(b, "0.3                   0\n");
        p = p ? strchr(p, '\n') : NULL;
        if (p) memcpy(p + 1 + 50, "         2", 10);
    }
    return b;
}

static void test_preload_incline(void)
{
    const double mu = 0.3, theta = atan(mu) - 0.05, kt = 2e4;
    for (int pre = 1; pre >= 0; pre--) {
        char *text = incline_deck(theta, pre, 0);
        ENSURE(text != NULL);
        if (!text) return;
        rc_stats st;
        const char *path = run_deck(text, pre ? "preload_incline.rad" : "preload_incline_none.rad", -1, &st);
        free(text);
        if (!path) return;
        size_t nx = 0, nf = 0, nn = 0;
        double *x = nc_var(path, "body_position", &nx), *ff = nc_var(path, "inter_force_friction", &nf);
        double *fn = nc_var(path, "inter_force_normal", &nn);
        ENSURE(x && ff && fn && nx == 3 * nn && nf == 3 * nn && nn >= 11);
        if (!(x && ff && fn && nx == 3 * nn && nf == 3 * nn && nn >= 11)) {
            free(x);
            free(ff);
            free(fn);
            return;
        }
        /* the sphere's displacement from its first record [m] */
        double dmax = 0.0, ferr = 0.0;
        const double ft = COL_M * G * sin(theta), fnr = COL_M * G * cos(theta);
        for (size_t r = 0; r < nn; r++) {
            dmax = fmax(dmax, sqrt(pow(x[3 * r] - x[0], 2) + pow(x[3 * r + 1] - x[1], 2) + pow(x[3 * r + 2] - x[2], 2)));
            ferr = fmax(ferr, fmax(fabs(ff[3 * r] + ft) / ft, fabs(fn[r] - fnr) / fnr));
        }
        const double vmax = max_speed(path);
        if (pre) {
            /* bound: the residual KINSOL accepts, 1e-8 m g, displaces the
             * sphere on its stick spring by at most 2e-8 m g / K_t =
             * 9.8e-12 m (twice the static offset: a step load) */
            const double dbound = 2e-8 * COL_M * G / kt;
            printf("    preloaded: displacement %.3g m (bound %.3g), max |v| %.3g m/s, force error %.3g; x0 - "
                   "K_t offset %.3g m\n",
                   dmax, dbound, vmax, ferr, x[0] - ft / kt);
            ENSURE(st.preloaded == 1);
            ENSURE(dmax < dbound);
            ENSURE(ferr < 1e-8);
            /* the stick spring took the tangential load: x = m g sin(theta) / K_t */
            ENSURE_NEAR(x[0], ft / kt, 1e-12, 1e-8);
        } else {
            printf("    no preload: displacement %.3g m, max |v| %.3g m/s\n", dmax, vmax);
            /* the contact loads from zero: the sphere moves at least to
             * its static offset m g sin(theta) / K_t */
            ENSURE(dmax > 0.5 * ft / kt);
        }
        free(x);
        free(ff);
        free(fn);
    }
}

/* What a preload refuses: RC_EINPUT naming the card. */
static void test_preload_refusals(void)
{
    /* a body given an initial velocity */
    char *text = column_deck(1, 1, 1);
    ENSURE(text != NULL);
    if (text) TU_EXPECT_TEXT_ERROR(text, "preload_inivel.rad", "/RBODY/3", "initial velocity", "Preload");
    free(text);
    /* outside the static analysis' scope: a speed multiplier of friction
     * that is 0 at rest (no static friction) */
    text = incline_deck(0.2, 1, 1);
    ENSURE(text != NULL);
    if (text)
        TU_EXPECT_TEXT_ERROR(text, "preload_scope.rad", "/INTER/TYPE6/1", "speed multiplier", "/SOLVER field Preload",
                             "static analysis' scope", "Preload 0");
    free(text);
    /* the same through the setter: refused, the model unchanged */
    text = incline_deck(0.2, 0, 1);
    rc_error e;
    rc_model *m = text ? tu_compile_text(text, "preload_set.rad", &e) : NULL;
    ENSURE(m != NULL);
    if (m) {
        ENSURE(rc_model_set_preload(m, 1, &e) == RC_EINPUT);
        ENSURE(strstr(e.msg, "/INTER/TYPE6/1") && strstr(e.msg, "rc_model_set_preload"));
        ENSURE(rc_model_preload(m) == 0);
        ENSURE(rc_model_set_preload(m, 2, &e) == RC_EINPUT);
        ENSURE(rc_model_set_preload(m, 0, &e) == RC_OK);
        rc_model_free(m);
    }
    free(text);
    ENSURE(rc_model_set_preload(NULL, 1, &e) == RC_EINPUT);
    /* Preload takes 0 or 1 */
    text = column_deck(1, 1, 0);
    if (text) {
        char *p = strstr(text, "/SOLVER\n");
        if (p) p = strchr(p + 8, '\n');
        if (p) p[-1] = '2';
        TU_EXPECT_TEXT_ERROR(text, "preload_field.rad", "/SOLVER", "Preload");
    }
    free(text);
    /* Method 3 with Preload 1: the static analysis as it is */
    text = column_deck(3, 1, 0);
    if (text) {
        rc_stats st;
        const char *path = run_deck(text, "preload_static.rad", -1, &st);
        ENSURE(path != NULL && st.preloaded == 0);
    }
    free(text);
}

void suite_preload(void);
void suite_preload(void)
{
    RUN_TEST(test_preload_column);
    RUN_TEST(test_preload_incline);
    RUN_TEST(test_preload_refusals);
}
