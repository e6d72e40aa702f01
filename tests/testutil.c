/* Helpers shared by the test files (testutil.h). */
#include "testutil.h"
#include "harness.h"
#include "base/error.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "engine/assembly/assembly.h"

#define TU_MAX_TMP 256
static char tmp_dir[64];
static char tmp_paths[TU_MAX_TMP][160];
static int ntmp;

const char *tu_tmp_write_n(const char *name, const char *text, size_t len)
{
    if (!tmp_dir[0]) {
        snprintf(tmp_dir, sizeof tmp_dir, "/tmp/rc_test_XXXXXX");
        if (!mkdtemp(tmp_dir)) { perror("mkdtemp"); exit(1); }
    }
    char path[160];
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    int i;
    for (i = 0; i < ntmp; i++)
        if (strcmp(tmp_paths[i], path) == 0) break;
    if (i == ntmp) {
        if (ntmp == TU_MAX_TMP) { fprintf(stderr, "too many temp files\n"); exit(1); }
        snprintf(tmp_paths[ntmp++], sizeof tmp_paths[0], "%s", path);
    }
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(text, 1, len, f) != len || fclose(f) != 0) { perror(path); exit(1); }
    return tmp_paths[i];
}

const char *tu_tmp_write(const char *name, const char *text) { return tu_tmp_write_n(name, text, strlen(text)); }

void tu_tmp_cleanup(void)
{
    for (int i = 0; i < ntmp; i++) remove(tmp_paths[i]);
    ntmp = 0;
    if (tmp_dir[0]) rmdir(tmp_dir);
    tmp_dir[0] = '\0';
}

rc_status tu_load_compile(const char *path, rc_model **m, rc_error *e)
{
    rc_case *c = NULL;
    *m = NULL;
    rc_error_clear(e);
    rc_status st = rc_case_load(path, &c, e);
    if (st == RC_OK) st = rc_model_compile(c, m, e);
    rc_case_free(c);
    if (st != RC_OK) {
        rc_model_free(*m);
        *m = NULL;
    }
    return st;
}

rc_model *tu_compile_text(const char *text, const char *path, rc_error *e)
{
    FILE *f = fopen(path, "w");
    if (f) {
        fputs(text, f);
        fclose(f);
    }
    rc_model *m = NULL;
    tu_load_compile(path, &m, e);
    remove(path);
    return m;
}

rc_model *tu_compile_ok(const char *text, const char *path, const char *file, int line)
{
    rc_error e;
    rc_model *m = tu_compile_text(text, path, &e);
    if (!m) {
        fprintf(stderr, "  %s:%d: %s does not compile\n", file, line, path);
        printf("    %s\n", e.msg);
        rc_test_failed_now++;
    }
    return m;
}

rc_model *tu_load_ok(const char *path, const char *file, int line)
{
    rc_error e;
    rc_model *m = NULL;
    if (tu_load_compile(path, &m, &e) != RC_OK || !m) {
        fprintf(stderr, "  %s:%d: %s does not load and compile\n", file, line, path);
        printf("    %s\n", e.msg);
        rc_test_failed_now++;
        return NULL;
    }
    return m;
}

int tu_text_error(const char *text, const char *path, ...)
{
    rc_error e;
    rc_model *m = tu_compile_text(text, path, &e);
    int bad = m != NULL || e.code != RC_EINPUT;
    va_list ap;
    va_start(ap, path);
    bad += tu_missing_needles(m ? "" : e.msg, ap);
    va_end(ap);
    if (bad) fprintf(stderr, "  message: %s\n", m ? "(compiled)" : e.msg);
    rc_model_free(m);
    return bad;
}

int tu_missing_needles(const char *msg, va_list ap)
{
    int bad = 0;
    for (const char *s; (s = va_arg(ap, const char *));)
        if (!strstr(msg, s)) {
            fprintf(stderr, "  missing \"%s\"\n", s);
            bad++;
        }
    return bad;
}

double tu_jac_fd_error(const rc_model *m, rc_data *d, double t, double *y, int forgive_rounding, int *bad,
                       int *outside)
{
    double *f1 = calloc((size_t)m->ny, sizeof(double)), *f2 = calloc((size_t)m->ny, sizeof(double));
    double *f3 = calloc((size_t)m->ny, sizeof(double)), *f4 = calloc((size_t)m->ny, sizeof(double));
    double *val = calloc((size_t)m->nnz, sizeof(double)), maxerr = 0;
    rc_assemble_jac(m, d, t, y, val);
    const int first_own = m->ninter > 0 ? m->inter_eadr[0] : m->ny;
    for (int col = 0; col < m->ny; col++) {
        /* body states: small steps (the geometry is strongly nonlinear);
         * interface states (forces, energies) enter linearly or smoothly,
         * and their rows are large (K_t v_t): a larger step keeps the
         * difference clear of rounding */
        double h = col < first_own ? 1e-6 * fmax(fabs(y[col]), 1.0) : 1e-4 * fmax(fabs(y[col]), 1e-3);
        double keep = y[col];
        y[col] = keep + h;
        rc_assemble_rhs(m, d, t, y, f1);
        y[col] = keep - h;
        rc_assemble_rhs(m, d, t, y, f2);
        y[col] = keep;
        double scale = 1.0;
        for (int r = 0; r < m->ny; r++) scale = fmax(scale, fabs((f1[r] - f2[r]) / (2 * h)));
        int fine = 0; /* the differences at h / 4 computed */
        for (int r = 0; r < m->ny; r++) {
            double fd = (f1[r] - f2[r]) / (2 * h), an = 0;
            int64_t k;
            for (k = m->jac_colptr[col]; k < m->jac_colptr[col + 1]; k++)
                if (m->jac_rowind[k] == r) break;
            /* rounding of the central difference: eps |f| / h of the rows */
            const double noise = forgive_rounding ? 100.0 * DBL_EPSILON * fmax(fabs(f1[r]), fabs(f2[r])) / h : 0.0;
            /* off the pattern: a difference beyond its rounding */
            if (k < m->jac_colptr[col + 1]) an = val[k];
            else if (fabs(fd) > fmax(1e-9 * scale, noise)) (*outside)++;
            double er = fabs(an - fd) / scale;
            /* the truncation error of the difference: at h / 4 the central
             * difference moves towards the derivative by 16 times less; an
             * entry it converges to is right (a wrong one does not move) */
            if (er > 1e-6 && fabs(an - fd) > noise) {
                if (!fine) {
                    y[col] = keep + h / 4;
                    rc_assemble_rhs(m, d, t, y, f3);
                    y[col] = keep - h / 4;
                    rc_assemble_rhs(m, d, t, y, f4);
                    y[col] = keep;
                    fine = 1;
                }
                const double fd4 = (f3[r] - f4[r]) / (h / 2);
                if (fabs(an - fd4) <= fabs(an - fd) / 8) er = fabs(an - fd4) / scale;
            }
            maxerr = fmax(maxerr, er);
            if (er > 1e-6 && fabs(an - fd) > noise) {
                (*bad)++;
                if (getenv("RC_DEBUG_JAC"))
                    printf("      row %d col %d: J %.10g FD %.10g (scale %.3g)\n", r, col, an, fd, scale);
            }
        }
    }
    free(f1);
    free(f2);
    free(f3);
    free(f4);
    free(val);
    return maxerr;
}

double tu_dae_jac_fd_error(int n, double *Y, double *Yp, double cj, const int64_t *cp, const int64_t *ri,
                           const double *val, tu_residual_fn res, void *ctx, const tu_dae_fd_opts *o, int *outside)
{
    double *r1 = calloc((size_t)n, sizeof(double)), *r2 = calloc((size_t)n, sizeof(double)), worst = 0;
    if (!r1 || !r2) {
        free(r1);
        free(r2);
        return INFINITY;
    }
    for (int c = 0; c < n; c++) {
        const double h = 1e-6 * fmax(fabs(Y[c]), o->hfloor), keep = Y[c], keepp = Yp[c];
        Y[c] = keep + h;
        Yp[c] = keepp + cj * h;
        res(ctx, Y, Yp, r1);
        Y[c] = keep - h;
        Yp[c] = keepp - cj * h;
        res(ctx, Y, Yp, r2);
        Y[c] = keep;
        Yp[c] = keepp;
        for (int r = 0; r < n; r++) {
            const double fd = (r1[r] - r2[r]) / (2 * h);
            double an = 0;
            int64_t k;
            for (k = cp[c]; k < cp[c + 1]; k++)
                if (ri[k] == r) break;
            if (k < cp[c + 1]) an = val[k];
            else if (fabs(fd) > o->out_tol * (o->out_rel ? fmax(1.0, fabs(r1[r])) : 1.0)) (*outside)++;
            if (o->compare && !o->compare(ctx, r)) continue;
            const double rnd = o->forgive_rounding ? 100.0 * DBL_EPSILON * fmax(fabs(r1[r]), fabs(r2[r])) / h : 0.0;
            const double err = fmax(fabs(an - fd) - rnd, 0.0) / fmax(1.0, fabs(fd));
            if (err > worst) worst = err;
            if (err > o->print_tol) fprintf(stderr, "  cj %g: row %d col %d: exact %.9g, FD %.9g\n", cj, r, c, an, fd);
        }
    }
    free(r1);
    free(r2);
    return worst;
}

int tu_evlog_first(const tu_evlog *l, const char *kind, double *t, double *v)
{
    int n = 0;
    for (int k = 0; k < l->n && k < TU_MAXEV; k++)
        if (!strcmp(l->kind[k], kind) && n++ == 0) {
            *t = l->t[k];
            if (v) memcpy(v, l->v[k], 3 * sizeof *v);
        }
    return n;
}

int tu_evlog_event(void *user, double t, const char *kind, const char *element, const double values[3])
{
    tu_evlog *l = user;
    if (l->n < TU_MAXEV) {
        l->t[l->n] = t;
        memcpy(l->v[l->n], values, sizeof l->v[0]);
        snprintf(l->kind[l->n], sizeof l->kind[0], "%s", kind);
        snprintf(l->elem[l->n], sizeof l->elem[0], "%s", element);
    }
    l->n++;
    return 0;
}

rc_status tu_run_evlog(const rc_model *m, tu_evlog *ev, rc_stats *st)
{
    memset(ev, 0, sizeof *ev);
    rc_error e;
    rc_run_options o;
    memset(&o, 0, sizeof o);
    o.on_event = tu_evlog_event;
    o.user = ev;
    rc_stats s;
    const rc_status r = rc_run(m, &o, st ? st : &s, &e);
    if (r) printf("    %s\n", e.msg);
    return r;
}

/* The settling column of the benchmarks (bench.py column_deck): n spheres
 * (R 0.01 m, m 0.01 kg) 1e-4 m apart over a floor, TYPE6 k = 1e5 N/m
 * critically damped, gravity; variants by flags (testutil.h). */
char *tu_column_deck(int n, int flags)
{
    size_t cap = 4096 + (size_t)n * 700, len = 0;
    char *t = malloc(cap);
    if (!t) return NULL;
#define OUT(...) len += (size_t)snprintf(t + len, cap - len, __VA_ARGS__)
    OUT("/BEGIN\ncolumn\n      2022         0\n");
    OUT("                  kg                   m                   s\n");
    OUT("                  kg                   m                   s\n");
    OUT("/FUNCT/1\nload\n                   0                   0\n                   1              100000\n");
    OUT("/NODE\n");
    const double R = 0.01, gap = 1e-4;
    for (int i = 0; i < n; i++) {
        const double x = (flags & TU_COL_TILT) ? 0.0015 * (i % 3) : 0.0;
        OUT("%10d%20.9g%20.6g%20.9g\n", i + 1, x, 0.0, R + gap + i * (2 * R + gap));
    }
    for (int i = 0; i < n; i++)
        OUT("/RBODY/%d\nsphere\n%10d%30s%20.6g\n%20.6g%20.6g%20.6g\n%20.6g%20.6g%20.6g\n", i + 1, i + 1, "", 0.01,
            4e-7, 4e-7, 4e-7, 0.0, 0.0, 0.0);
    for (int i = 0; i < n; i++) {
        double x = (flags & TU_COL_TILT) ? 0.0015 * (i % 3) : 0.0;
        if ((flags & TU_COL_OFF) && i == 1) x += 1e-3;
        OUT("/SURF/ELLIPS/%d\nsphere\n%10d%10d%10d\n%20.9g%20.6g%20.9g\n%20.6g%20.6g%20.6g\n", i + 1, 0, 2, i + 1, x,
            0.0, R + gap + i * (2 * R + gap), R, R, R);
    }
    OUT("/SURF/PLANE/%d\nfloor\n%20d%20d%20d\n%20d%20d%20d\n", n + 1, 0, 0, 0, 0, 0, 1);
    OUT("/GRAV/1\ngravity\n         0         Z         0         0         0                             1"
        "               -9.81\n");
    OUT("/GRNOD/NODE/1\nall\n");
    for (int i = 0; i < n; i++) OUT("%10d%s", i + 1, (i % 10 == 9 || i == n - 1) ? "\n" : "");
    OUT("/GRNOD/NODE/2\nsecond\n         2\n");
    if (flags & TU_COL_LOCK) OUT("/BCS/1\nlocked\n   110 111         0         1\n");
    if (flags & TU_COL_SPIN) OUT("/INIVEL/ROT/1\nspin\n%20d%20d%20d%10d%10d\n", 0, 0, 1, 2, 0);
    if (flags & TU_COL_TILT) OUT("/INIVEL/TRA/2\npush\n%20g%20g%20g%10d%10d\n", 0.1, -0.05, 0.0, 2, 0);
    if (flags & TU_COL_SPRING)
        OUT("/COUPLING/SPRING/1\nspring\n2,0,1,0\n0,0,0\n0.05,0,%.9g\n,0.01\n20.0\n", R + gap + (2 * R + gap));
    for (int i = 0; i < n; i++) {
        const double c = i == 0 ? 2 * sqrt(1e5 * 0.01) : 2 * sqrt(1e5 * 0.005);
        OUT("/INTER/TYPE6/%d\ncontact\n%10d%10d\n%40s%20s\n%20s%10d%10d%10d%10d%10d\n%10d%10d%50s\n%10d\n%20.9g%10d%10d\n",
            i + 1, i == 0 ? 1 : i, i == 0 ? n + 1 : i + 1, (flags & TU_COL_FRIC) ? "0.3" : "", "0", "0", 0, 0, 0, 0, 0,
            1, 0, "0", 0, c, 0, 0);
    }
    OUT("/RUN\n%20g%20g\n/END\n", (flags & TU_COL_TILT) ? 0.1 : 0.05, 0.01);
#undef OUT
    return t;
}


int tu_jac_skip_compare(const rc_model *m, rc_data *d, double t, const double *y, const char *cst, double *ja,
                        double *jb, int *kept, int *nonzero)
{
    const char *keep = d->jac_skip;
    d->jac_skip = NULL;
    int st = rc_assemble_jac(m, d, t, y, ja);
    d->jac_skip = cst;
    st |= rc_assemble_jac(m, d, t, y, jb);
    d->jac_skip = keep;
    int bad = st != 0;
    *kept = *nonzero = 0;
    for (int c = 0; c < m->ny; c++)
        for (int64_t k = m->jac_colptr[c]; k < m->jac_colptr[c + 1]; k++) {
            const int r = (int)m->jac_rowind[k];
            if (!cst[r] && !cst[c]) {
                (*kept)++;
                bad += memcmp(&ja[k], &jb[k], sizeof(double)) != 0;
                *nonzero += ja[k] != 0.0;
            } else if (cst[c]) {
                bad += jb[k] != 0.0;
            }
        }
    return bad;
}
