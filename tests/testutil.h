/*
 * Helpers shared by the test files: a deck written from text, loaded and
 * compiled; the needles an error message must hold; the analytic Jacobian
 * against central differences.
 */
#ifndef RC_TESTUTIL_H
#define RC_TESTUTIL_H

#include <stdarg.h>

#include "model/model.h"
#include "engine/assembly/data.h"

/* Write `len` bytes as <private temporary directory>/name (created on first
 * use); returns the path (static storage, valid until tu_tmp_cleanup). */
const char *tu_tmp_write_n(const char *name, const char *text, size_t len);
const char *tu_tmp_write(const char *name, const char *text);
/* Remove the files written and the directory. */
void tu_tmp_cleanup(void);

/* Load the case at `path` and compile it; the case is freed, *m is the
 * model (NULL on failure, with the message in *e). */
rc_status tu_load_compile(const char *path, rc_model **m, rc_error *e);
/* Write `text` to `path`, load and compile it, remove the file. */
rc_model *tu_compile_text(const char *text, const char *path, rc_error *e);
/* A deck text that must compile: its model, or NULL after a failed check
 * (the failure and the error message printed at file:line). */
rc_model *tu_compile_ok(const char *text, const char *path, const char *file, int line);
#define TU_COMPILE_OK(text, path) tu_compile_ok((text), (path), __FILE__, __LINE__)
/* A case file that must load and compile: its model, or NULL after a failed
 * check (the failure and the error message printed at file:line). */
rc_model *tu_load_ok(const char *path, const char *file, int line);
#define TU_LOAD_OK(path) tu_load_ok((path), __FILE__, __LINE__)
/* How many of the NULL-terminated needles `msg` lacks (each printed). */
int tu_missing_needles(const char *msg, va_list ap);
/* Write `text` to `path` and compile it, expecting an input error whose
 * message holds every needle (NULL-terminated); returns the number of
 * faults (0: as expected), each printed with the message. */
int tu_text_error(const char *text, const char *path, ...);
#define TU_EXPECT_TEXT_ERROR(text, path, ...) ENSURE(tu_text_error((text), (path), __VA_ARGS__, (const char *)NULL) == 0)
/* Max scaled |J - FD| over the whole Jacobian at (t, y) in the current
 * modes, central differences column by column; counts entries above 1e-6
 * (*bad) and FD non-zeros outside the pattern (*outside). With
 * `forgive_rounding`, an entry is also within bounds when |J - FD| is below
 * the rounding of the difference, 100 eps |f| / h (large rows). */
double tu_jac_fd_error(const rc_model *m, rc_data *d, double t, double *y, int forgive_rounding, int *bad,
                       int *outside);

/* The iteration matrix dF/dY + cj dF/dY' of a residual F(Y, Y') of n rows
 * against central differences, column by column, Y and Y' perturbed
 * together (Y' by cj h, h = 1e-6 max(|Y_c|, hfloor)); the exact values are
 * `val` on the CSC pattern (cp, ri). An FD entry off the pattern counts in
 * *outside when |FD| > out_tol (times max(1, |F_r|) with out_rel). Rows r
 * with compare(ctx, r) == 0 are not compared (compare NULL: all rows). With
 * `forgive_rounding` the rounding of the difference, 100 eps |F| / h, is
 * subtracted. Entries above print_tol are printed. Returns the max of
 * |J - FD| / max(1, |FD|). */
typedef void (*tu_residual_fn)(void *ctx, const double *Y, const double *Yp, double *r);
typedef struct {
    double hfloor, out_tol, print_tol;
    int out_rel, forgive_rounding;
    int (*compare)(void *ctx, int r);
} tu_dae_fd_opts;
double tu_dae_jac_fd_error(int n, double *Y, double *Yp, double cj, const int64_t *cp, const int64_t *ri,
                           const double *val, tu_residual_fn res, void *ctx, const tu_dae_fd_opts *o, int *outside);

/* A run's events as the on_event callback of rc_run_options reports them
 * (the first TU_MAXEV kept; n counts all): user = a tu_evlog, zeroed. */
#define TU_MAXEV 4096
typedef struct {
    int n;
    double t[TU_MAXEV], v[TU_MAXEV][3];
    char kind[TU_MAXEV][32], elem[TU_MAXEV][32];
} tu_evlog;
int tu_evlog_event(void *user, double t, const char *kind, const char *element, const double values[3]);
/* How many events of `kind` *l holds; the first one's time into *t and
 * (v not NULL) its values into v[3]. */
int tu_evlog_first(const tu_evlog *l, const char *kind, double *t, double *v);
/* Run m to its end with its events logged into *ev (zeroed here) and the
 * statistics into *st (NULL: not wanted); the error printed when it fails. */
rc_status tu_run_evlog(const rc_model *m, tu_evlog *ev, rc_stats *st);

/* The settling column deck (text, malloc'd; NULL out of memory): n spheres
 * over a floor; flags: */
enum {
    TU_COL_FRIC = 1,   /* Fric 0.3 on every contact */
    TU_COL_OFF = 2,    /* sphere 2's surface 1e-3 m off its centre of mass (x) */
    TU_COL_SPRING = 4, /* a spring from sphere 2's centre to a point in space */
    TU_COL_SPIN = 8,   /* sphere 2 starts spinning about z (1 rad/s) */
    TU_COL_TILT = 16,  /* the spheres staggered in x (contact normals not
                          vertical) and given sideways velocities */
    TU_COL_LOCK = 32   /* x, y and the rotations held (/BCS 110 111): the 1-D column */
};
char *tu_column_deck(int n, int flags);

/* The Jacobian assembled whole (into ja) and with the columns of the
 * states in cst skipped (rc_data.jac_skip; into jb): the number of entries
 * of kept rows and columns that are not bit-identical plus the non-zero
 * entries of skipped columns (0: as it should be); kept, nonzero: counts of
 * the kept entries. d->jac_skip is restored. */
int tu_jac_skip_compare(const rc_model *m, rc_data *d, double t, const double *y, const char *cst, double *ja,
                        double *jb, int *kept, int *nonzero);

#endif
