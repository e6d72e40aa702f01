/* Helpers shared by the test files (testutil.h). */
#include "testutil.h"
#include "base/error.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

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
        for (int r = 0; r < m->ny; r++) {
            double fd = (f1[r] - f2[r]) / (2 * h), an = 0;
            int64_t k;
            for (k = m->jac_colptr[col]; k < m->jac_colptr[col + 1]; k++)
                if (m->jac_rowind[k] == r) break;
            if (k < m->jac_colptr[col + 1]) an = val[k];
            else if (fabs(fd) > 1e-9 * scale) (*outside)++;
            /* rounding of the central difference: eps |f| / h of the rows */
            const double noise = forgive_rounding ? 100.0 * DBL_EPSILON * fmax(fabs(f1[r]), fabs(f2[r])) / h : 0.0;
            double er = fabs(an - fd) / scale;
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
