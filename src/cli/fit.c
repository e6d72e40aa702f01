/*
 * ricochet fit: numeric fields of a deck (addressed as by --set) calibrated
 * so that simulated signals match measured ones, by nonlinear least squares
 * (docs/calibration.md).
 *
 * Design
 *  - The model is a black box behind the public API: each evaluation loads
 *    the deck with the trial values as --set overrides (rc_case_load_set),
 *    compiles it, opens a session without a results file and stops it at
 *    every data time (rc_run_until); the body states there are the
 *    simulated signals. Nothing is interpolated between records.
 *  - Residuals: (simulated - measured) / scale for every measured value,
 *    scale the signal's measured range (max - min; 1 unit when flat), so
 *    that signals of different units weigh alike, or its stated
 *    uncertainty ("+- SIGMA" in the header). Blank cells are not measured
 *    and give no residual. Measured quantities of impacts and persistent
 *    contacts (--impacts, each with its uncertainty) come from the run's
 *    statistics at the session's close and add their residuals.
 *  - Solver: GSL gsl_multifit_nlinear, trust region, double dogleg by
 *    default (--trs): its steps stay inside the trust radius, whereas GSL's
 *    Levenberg-Marquardt (no geodesic acceleration; --trs lm) bounds them
 *    by its damping parameter only and, from a start 5x off, stepped the
 *    damping of a drop to 1e5 times its value, where the ball sticks and
 *    the signal no longer depends on the parameters.
 *  - The fitted variables u are dimensionless: p = start + |start| u
 *    (free), p = start exp(u) (--log), and with bounds p = lo + (hi - lo)
 *    (1 + tanh u) / 2 (in log p for --log), so that every trial lies inside
 *    the bounds.
 *  - Jacobian: finite differences in u (central by default), the columns
 *    evaluated in parallel by a pool of threads, each simulation loading and
 *    compiling its own model (the library is thread-safe for separate
 *    cases, models and sessions; no results file is written).
 *  - --jacobian sens: the Jacobian from one run with forward sensitivities
 *    (rc_sens_run) at the data times: the deck compiled at p and, per
 *    parameter, at p -+ RC_FIT_SENS_STEP |p|; d sim/dp from the state's
 *    sensitivities (the body state's central difference along them), times
 *    dp/du; of the impacts' t_close, duration, v_in and v_out, from the
 *    events' derivatives (rc_sens_events; other quantities need the finite
 *    differences).
 *  - Statistics at the solution: s^2 = sum r^2 / (n - rank J), the covariance
 *    s^2 (J^T J)^-1 (gsl_multifit_nlinear_covar, whose pivoted QR drops
 *    dependent columns) mapped to the parameters by dp/du. A parameter the
 *    residuals do not depend on (its column of J below RC_FIT_COLUMN_TOL of
 *    the largest), dropped by the rank test, at its bound, or with a
 *    relative standard error above --max-rse is UNIDENTIFIABLE: reported
 *    as such, no number.
 */
#include "cli/fit.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include "ricochet/ricochet.h"

/* at most this many free parameters, signals, --set options */
#define RC_FIT_MAX_PAR 32
#define RC_FIT_MAX_SIG 64
#define RC_FIT_MAX_SET 256
/* a column of J below this fraction of the largest column's norm: the data
 * do not see the parameter */
#define RC_FIT_COLUMN_TOL 1e-9
/* a bounded parameter whose tanh map has flattened below this slope
 * (1 - tanh^2 u = 4 s (1 - s), s its relative place between the bounds:
 * within 0.1 % of the range from a bound) sits at its bound */
#define RC_FIT_AT_BOUND 4e-3
/* rank test of the covariance (gsl_multifit_nlinear_covar epsrel) */
#define RC_FIT_RANK_TOL 1e-9
/* --jacobian sens: the relative step of the parameters inside the
 * sensitivity run's right-hand side (rc_sens_run's two models) [-] */
#define RC_FIT_SENS_STEP 1e-4
/* residual of a trial whose simulation failed (the step is then rejected:
 * measured residuals are of order 1 by their scaling) */
#define RC_FIT_FAILED_RESIDUAL 1e3

/* the quantities a signal can name: position and velocity of a body's
 * centre of mass (rc_model_body_state: out[0..2], out[7..9]) */
static const char *const quantity_name[6] = {"x", "y", "z", "vx", "vy", "vz"};
static const int quantity_slot[6] = {0, 1, 2, 7, 8, 9};

typedef struct {
    char name[256];   /* CARD:FIELD, as --set addresses it           */
    double start;     /* start value, card units                     */
    double lo, hi;    /* bounds (bounded only), card units           */
    int bounded;      /* 1: lo < p < hi                              */
    int logscale;     /* 1: fitted in log p (p > 0)                  */
} fit_par;

typedef struct {
    int body;            /* /RBODY id                                  */
    int q;               /* index into quantity_name                   */
    char label[96];      /* "body 1 z [m]", as in the header            */
    char unit[16];       /* the data's unit                            */
    double to_si;        /* data unit -> SI                            */
    double scale;        /* residual scale, SI                         */
    double sigma;        /* stated uncertainty, SI; 0: none             */
} fit_sig;

/* the quantities of an impact (rc_impact) or of a persistent contact
 * (rc_contact, names contact_*) a target can name */
typedef struct {
    const char *name;
    const char *unit_si, *unit_alt; /* accepted units; alt = 1e-3 SI (ms, mm), or kN for N */
    double alt_to_si;
} impact_quantity;
static const impact_quantity impact_q[] = {
    {"t_close", "s", "ms", 1e-3},       {"duration", "s", "ms", 1e-3}, {"pen_max", "m", "mm", 1e-3},
    {"fn_max", "N", "kN", 1e3},         {"v_in", "m/s", "mm/s", 1e-3}, {"v_out", "m/s", "mm/s", 1e-3},
    {"restitution", "-", NULL, 0.0},    {"energy_lost", "J", NULL, 0.0},
    /* persistent contacts, from RC_FIT_FIRST_CONTACT_Q on */
    {"contact_t_close", "s", "ms", 1e-3}, {"contact_duration", "s", "ms", 1e-3},
    {"contact_pen_max", "m", "mm", 1e-3}, {"contact_fn_max", "N", "kN", 1e3},
    {"contact_fn_mean", "N", "kN", 1e3},  {"contact_slip", "m", "mm", 1e-3}};
#define RC_FIT_FIRST_CONTACT_Q 8
#define RC_FIT_NIMPQ ((int)(sizeof impact_q / sizeof impact_q[0]))

/* A measured quantity of one impact (--impacts). */
typedef struct {
    int inter;          /* /INTER id                                    */
    int k;              /* the k-th impact of that interface (1 = first) */
    int q;              /* index into impact_q                          */
    double value;       /* measured, SI                                 */
    double sigma;       /* its standard uncertainty, SI                 */
    double to_si;       /* the row's unit -> SI                         */
    char unit[16];
    char label[96];     /* "inter 1 impact 1 v_out [m/s]"               */
} fit_imp;

typedef struct {
    const char *deck;
    const char *data;
    const char *impacts;  /* --impacts FILE.csv, or NULL                */
    int nimp;
    fit_imp imp[RC_FIT_MAX_SIG];
    int weighted;         /* 1: every residual divided by its stated
                             uncertainty; 0: by the signal's range      */
    int nres_ts;          /* residuals of the time series               */
    int np;
    fit_par par[RC_FIT_MAX_PAR];
    int nset; /* fixed overrides (--set) */
    const char *set[RC_FIT_MAX_SET];
    int nt, ns;           /* data times, signals                        */
    double *t;            /* [nt] data times [s]                        */
    double *meas;         /* [nt * ns] measured values, SI; NaN: none   */
    char time_unit[8];
    double t_to_si;
    fit_sig sig[RC_FIT_MAX_SIG];
    int nres;             /* measured values (residuals)                */
    double rtol;          /* > 0: replaces /SOLVER Rtol                 */
    int method;           /* > 0: replaces /SOLVER Method (1, 2)        */
    double h;             /* finite-difference step in u                */
    int central;          /* 1: central differences                     */
    int sens;             /* 1: the Jacobian from forward sensitivities
                             (--jacobian sens, rc_sens_run), one run per
                             Jacobian; 0: finite differences            */
    int jobs;             /* threads of the Jacobian                    */
    int quiet;
    int trs;              /* 0 double dogleg, 1 LM, 2 dogleg, 3 2-D subspace */
    FILE *progress;       /* the program's stderr while the library's is muted */
    /* counters and the first failure, shared by the threads */
    pthread_mutex_t lock;
    long nsim, nsim_failed;
    double sim_wall;
    char first_failure[1024];
} fit_problem;

/* ---- parameters ------------------------------------------------------ */

/* p(u) and dp/du of parameter j */
static double par_value(const fit_par *q, double u, double *dpdu)
{
    if (q->bounded) {
        const double th = tanh(u), dth = 1.0 - th * th;
        if (q->logscale) {
            const double a = log(q->lo), b = log(q->hi);
            const double p = exp(a + (b - a) * 0.5 * (1.0 + th));
            if (dpdu) *dpdu = p * (b - a) * 0.5 * dth;
            return p;
        }
        if (dpdu) *dpdu = (q->hi - q->lo) * 0.5 * dth;
        return q->lo + (q->hi - q->lo) * 0.5 * (1.0 + th);
    }
    if (q->logscale) {
        const double p = q->start * exp(u);
        if (dpdu) *dpdu = p;
        return p;
    }
    const double s = q->start != 0.0 ? fabs(q->start) : 1.0;
    if (dpdu) *dpdu = s;
    return q->start + s * u;
}

/* u of the start value */
static double par_u0(const fit_par *q)
{
    if (q->bounded) {
        const double a = q->logscale ? log(q->lo) : q->lo, b = q->logscale ? log(q->hi) : q->hi;
        const double x = q->logscale ? log(q->start) : q->start;
        return atanh(2.0 * (x - a) / (b - a) - 1.0);
    }
    return 0.0;
}

/* A number with nothing after it. */
static int parse_number(const char *s, size_t n, double *v)
{
    char buf[128];
    while (n > 0 && (*s == ' ' || *s == '\t')) { s++; n--; }
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r')) n--;
    if (n == 0 || n >= sizeof buf) return 0;
    memcpy(buf, s, n);
    buf[n] = '\0';
    char *end = NULL;
    errno = 0;
    const double x = strtod(buf, &end);
    if (end == buf || *end || !isfinite(x)) return 0;
    *v = x;
    return 1;
}

/* --free / --log CARD:FIELD=START[,LO:HI] into q; 0 and a message on
 * stderr when malformed. */
static int parse_free(const char *opt, const char *arg, int logscale, fit_par *q)
{
    memset(q, 0, sizeof *q);
    q->logscale = logscale;
    const char *colon = strchr(arg, ':'), *eq = strchr(arg, '=');
    if (!colon || !eq || eq < colon || eq == colon + 1 || arg[0] != '/' || (size_t)(eq - arg) >= sizeof q->name) {
        fprintf(stderr, "ricochet fit: %s %s: expected CARD:FIELD=START or CARD:FIELD=START,LO:HI "
                        "(e.g. /INTER/TYPE6/1:Visc=20,1:500)\n", opt, arg);
        return 0;
    }
    memcpy(q->name, arg, (size_t)(eq - arg));
    q->name[eq - arg] = '\0';
    const char *v = eq + 1, *comma = strchr(v, ',');
    if (!parse_number(v, comma ? (size_t)(comma - v) : strlen(v), &q->start)) {
        fprintf(stderr, "ricochet fit: %s %s: START: expected a finite number (the field's start value, in the "
                        "card's units), got '%.*s'\n", opt, arg, comma ? (int)(comma - v) : (int)strlen(v), v);
        return 0;
    }
    if (comma) {
        const char *b = comma + 1, *c2 = strchr(b, ':');
        if (!c2 || !parse_number(b, (size_t)(c2 - b), &q->lo) || !parse_number(c2 + 1, strlen(c2 + 1), &q->hi)) {
            fprintf(stderr, "ricochet fit: %s %s: bounds: expected LO:HI, two finite numbers, got '%s'\n", opt, arg, b);
            return 0;
        }
        if (!(q->lo < q->hi)) {
            fprintf(stderr, "ricochet fit: %s %s: bounds: expected LO < HI, got %g:%g\n", opt, arg, q->lo, q->hi);
            return 0;
        }
        if (!(q->start > q->lo && q->start < q->hi)) {
            fprintf(stderr, "ricochet fit: %s %s: expected START strictly inside (LO, HI) = (%g, %g), got %g\n", opt,
                    arg, q->lo, q->hi, q->start);
            return 0;
        }
        q->bounded = 1;
    }
    if (logscale && (!(q->start > 0) || (q->bounded && !(q->lo > 0)))) {
        fprintf(stderr, "ricochet fit: %s %s: a log-scaled parameter needs START > 0%s\n", opt, arg,
                q->bounded ? " and LO > 0" : "");
        return 0;
    }
    return 1;
}

/* ---- data ------------------------------------------------------------- */

/* Split a CSV line at commas in place: cells[] point into line; returns the
 * count (at most cap; cap + 1 when there are more). */
static int split_cells(char *line, char **cells, int cap)
{
    int n = 0;
    char *p = line;
    for (;;) {
        if (n == cap) return cap + 1;
        cells[n++] = p;
        char *c = strchr(p, ',');
        if (!c) break;
        *c = '\0';
        p = c + 1;
    }
    return n;
}

/* Trim blanks (and a line end) in place. */
static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r' || s[n - 1] == '\n')) s[--n] = '\0';
    return s;
}

/* "NAME [UNIT]" -> name, unit; 0 without a bracketed unit at the end. */
static int name_unit(char *cell, char **name, char **unit)
{
    char *c = trim(cell);
    size_t n = strlen(c);
    char *open = strrchr(c, '[');
    if (n < 3 || c[n - 1] != ']' || !open) return 0;
    c[n - 1] = '\0';
    *open = '\0';
    *unit = trim(open + 1);
    *name = trim(c);
    return **unit != '\0';
}

/* Read the data CSV (docs/calibration.md, "The data file"). Input errors:
 * "FILE:LINE: ..." on stderr, return 2; I/O error 4; 0 on success. */
static int read_data(fit_problem *fp)
{
    FILE *f = fopen(fp->data, "r");
    if (!f) {
        fprintf(stderr, "ricochet fit: %s: cannot open the data file (%s)\n", fp->data, strerror(errno));
        return 4;
    }
    char line[65536];
    int lineno = 0, header = 0, cap = 0, rc = 0;
    char *cells[RC_FIT_MAX_SIG + 2];
    while (fgets(line, sizeof line, f)) {
        lineno++;
        if (!strchr(line, '\n') && !feof(f)) {
            fprintf(stderr, "ricochet fit: %s:%d: line longer than %zu characters\n", fp->data, lineno, sizeof line - 1);
            rc = 2;
            break;
        }
        char *s = trim(line);
        if (*s == '\0' || *s == '#') continue; /* blank lines and comments */
        int n = split_cells(s, cells, RC_FIT_MAX_SIG + 1);
        if (!header) {
            /* the header: the time column, then one column per signal */
            header = 1;
            if (n > RC_FIT_MAX_SIG + 1) {
                fprintf(stderr, "ricochet fit: %s:%d: expected at most %d signal columns after the time column\n",
                        fp->data, lineno, RC_FIT_MAX_SIG);
                rc = 2;
                break;
            }
            if (n < 2) {
                fprintf(stderr, "ricochet fit: %s:%d: expected a header naming the time column and at least one "
                                "signal, e.g. 't [s], body 1 z [m]'\n", fp->data, lineno);
                rc = 2;
                break;
            }
            char *nm, *un;
            if (!name_unit(cells[0], &nm, &un) || (strcasecmp(nm, "t") && strcasecmp(nm, "time"))) {
                fprintf(stderr, "ricochet fit: %s:%d: column 1: expected the time column 't [s]' (or 'time', unit s "
                                "or ms), got '%s'\n", fp->data, lineno, trim(cells[0]));
                rc = 2;
                break;
            }
            if (!strcmp(un, "s")) fp->t_to_si = 1.0;
            else if (!strcmp(un, "ms")) fp->t_to_si = 1e-3;
            else {
                fprintf(stderr, "ricochet fit: %s:%d: column 1: expected the unit s or ms, got [%s]\n", fp->data,
                        lineno, un);
                rc = 2;
                break;
            }
            snprintf(fp->time_unit, sizeof fp->time_unit, "%s", un);
            fp->ns = n - 1;
            for (int k = 1; k < n && rc == 0; k++) {
                fit_sig *g = &fp->sig[k - 1];
                char raw[96];
                snprintf(raw, sizeof raw, "%s", trim(cells[k]));
                char body[16] = "", qty[16] = "";
                int id = 0, used = 0;
                /* an optional stated uncertainty after the unit: "+- SIGMA" */
                char *pm = strstr(cells[k], "+-");
                double sig = 0.0;
                if (pm) {
                    if (!parse_number(pm + 2, strlen(pm + 2), &sig) || !(sig > 0)) {
                        fprintf(stderr, "ricochet fit: %s:%d: column %d: expected '+- SIGMA' after the unit, SIGMA a "
                                        "positive number in the column's unit, got '%s'\n", fp->data, lineno, k + 1, raw);
                        rc = 2;
                        break;
                    }
                    *pm = '\0';
                }
                if (!name_unit(cells[k], &nm, &un) || sscanf(nm, "%15s %d %15s %n", body, &id, qty, &used) != 3 ||
                    nm[used] != '\0' || strcasecmp(body, "body") || id <= 0) {
                    fprintf(stderr, "ricochet fit: %s:%d: column %d: expected 'body ID Q [UNIT]' (Q one of x, y, z, "
                                    "vx, vy, vz; e.g. 'body 1 z [m]'), got '%s'\n", fp->data, lineno, k + 1, raw);
                    rc = 2;
                    break;
                }
                g->body = id;
                g->q = -1;
                for (int j = 0; j < 6; j++)
                    if (!strcasecmp(qty, quantity_name[j])) g->q = j;
                if (g->q < 0) {
                    fprintf(stderr, "ricochet fit: %s:%d: column %d: quantity '%s': expected one of x, y, z (position "
                                    "of the centre of mass), vx, vy, vz (its velocity)\n", fp->data, lineno, k + 1, qty);
                    rc = 2;
                    break;
                }
                const int vel = g->q >= 3;
                if (!strcmp(un, vel ? "m/s" : "m")) g->to_si = 1.0;
                else if (!strcmp(un, vel ? "mm/s" : "mm")) g->to_si = 1e-3;
                else {
                    fprintf(stderr, "ricochet fit: %s:%d: column %d: expected the unit %s, got [%s]\n", fp->data,
                            lineno, k + 1, vel ? "m/s or mm/s" : "m or mm", un);
                    rc = 2;
                    break;
                }
                snprintf(g->unit, sizeof g->unit, "%s", un);
                g->sigma = sig * g->to_si;
                if (k > 1 && (g->sigma > 0) != (fp->sig[0].sigma > 0)) {
                    fprintf(stderr, "ricochet fit: %s:%d: column %d: %s uncertainty '+- SIGMA' while column 2 %s: "
                                    "expected one for every signal or for none\n", fp->data, lineno, k + 1,
                            g->sigma > 0 ? "has an" : "has no", g->sigma > 0 ? "has none" : "has one");
                    rc = 2;
                    break;
                }
                snprintf(g->label, sizeof g->label, "body %d %s [%s]", id, quantity_name[g->q], un);
                for (int j = 0; j < k - 1; j++)
                    if (fp->sig[j].body == id && fp->sig[j].q == g->q) {
                        fprintf(stderr, "ricochet fit: %s:%d: column %d: body %d %s measured twice (also column %d)\n",
                                fp->data, lineno, k + 1, id, quantity_name[g->q], j + 2);
                        rc = 2;
                    }
            }
            if (rc) break;
            continue;
        }
        /* a row: the time, then one value per signal (blank: not measured) */
        if (n != fp->ns + 1) {
            fprintf(stderr, "ricochet fit: %s:%d: expected %d values (the time and %d signal%s, as the header), got %d\n",
                    fp->data, lineno, fp->ns + 1, fp->ns, fp->ns > 1 ? "s" : "", n > RC_FIT_MAX_SIG + 1 ? n - 1 : n);
            rc = 2;
            break;
        }
        if (fp->nt == cap) {
            cap = cap ? 2 * cap : 256;
            double *t = realloc(fp->t, (size_t)cap * sizeof *t);
            if (t) fp->t = t;
            double *mv = t ? realloc(fp->meas, (size_t)cap * (size_t)fp->ns * sizeof *mv) : NULL;
            if (mv) fp->meas = mv;
            if (!t || !mv) {
                fprintf(stderr, "ricochet fit: out of memory\n");
                rc = 5;
                break;
            }
        }
        double tv;
        if (!parse_number(cells[0], strlen(cells[0]), &tv) || tv < 0) {
            fprintf(stderr, "ricochet fit: %s:%d: column 1 (time): expected a number >= 0 [%s], got '%s'\n", fp->data,
                    lineno, fp->time_unit, trim(cells[0]));
            rc = 2;
            break;
        }
        tv *= fp->t_to_si;
        if (fp->nt > 0 && !(tv > fp->t[fp->nt - 1])) {
            fprintf(stderr, "ricochet fit: %s:%d: column 1 (time): expected times increasing, got %s after %g s\n",
                    fp->data, lineno, trim(cells[0]), fp->t[fp->nt - 1] / fp->t_to_si);
            rc = 2;
            break;
        }
        fp->t[fp->nt] = tv;
        for (int k = 1; k < n; k++) {
            double *mv = &fp->meas[(size_t)fp->nt * (size_t)fp->ns + (size_t)(k - 1)];
            char *c = trim(cells[k]);
            if (*c == '\0') {
                *mv = NAN; /* not measured at this time */
                continue;
            }
            if (!parse_number(c, strlen(c), mv)) {
                fprintf(stderr, "ricochet fit: %s:%d: column %d (%s): expected a number [%s] or a blank cell, got '%s'\n",
                        fp->data, lineno, k + 1, fp->sig[k - 1].label, fp->sig[k - 1].unit, c);
                rc = 2;
                break;
            }
            *mv *= fp->sig[k - 1].to_si;
            fp->nres++;
        }
        if (rc) break;
        fp->nt++;
    }
    if (rc == 0 && ferror(f)) {
        fprintf(stderr, "ricochet fit: %s: read error (%s)\n", fp->data, strerror(errno));
        rc = 4;
    }
    fclose(f);
    if (rc) return rc;
    if (!header || fp->nt == 0) {
        fprintf(stderr, "ricochet fit: %s:%d: expected a header and at least one row of values, got %s\n", fp->data,
                lineno, header ? "no row" : "no header");
        return 2;
    }
    /* each signal's residual scale: its measured range */
    for (int k = 0; k < fp->ns; k++) {
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < fp->nt; i++) {
            const double v = fp->meas[(size_t)i * (size_t)fp->ns + (size_t)k];
            if (isnan(v)) continue;
            lo = fmin(lo, v);
            hi = fmax(hi, v);
        }
        if (!(hi >= lo)) {
            fprintf(stderr, "ricochet fit: %s: column %d (%s): no value measured\n", fp->data, k + 2, fp->sig[k].label);
            return 2;
        }
        fp->sig[k].scale = hi > lo ? hi - lo : fp->sig[k].to_si;
    }
    return 0;
}

/* The simulated values of one evaluation: the signals at the data times,
 * then the impacts' quantities. */
static size_t sim_len(const fit_problem *fp)
{
    return (size_t)fp->nt * (size_t)fp->ns + (size_t)fp->nimp;
}

/* Read the impacts file (docs/calibration.md, "Impacts"): a header
 * "inter, impact, quantity, value, sigma", then one row per measured
 * quantity. Input errors: "FILE:LINE: ...", return 2; I/O error 4. */
static int read_impacts(fit_problem *fp)
{
    FILE *f = fopen(fp->impacts, "r");
    if (!f) {
        fprintf(stderr, "ricochet fit: %s: cannot open the impacts file (%s)\n", fp->impacts, strerror(errno));
        return 4;
    }
    static const char *const head[5] = {"inter", "impact", "quantity", "value", "sigma"};
    char line[4096], *cells[7];
    int lineno = 0, header = 0, rc = 0;
    while (rc == 0 && fgets(line, sizeof line, f)) {
        lineno++;
        char *t = trim(line);
        if (*t == '\0' || *t == '#') continue;
        const int n = split_cells(t, cells, 6);
        if (!header) {
            header = 1;
            int ok = n == 5;
            for (int k = 0; ok && k < 5; k++) {
                const char *c = trim(cells[k]);
                ok = !strcasecmp(c, head[k]) || (k == 1 && !strcasecmp(c, "number"));
            }
            if (!ok) {
                fprintf(stderr, "ricochet fit: %s:%d: expected the header 'inter, impact, quantity, value, sigma' ('number' "
                                "for 'impact' also)\n",
                        fp->impacts, lineno);
                rc = 2;
            }
            continue;
        }
        if (n != 5) {
            fprintf(stderr, "ricochet fit: %s:%d: expected 5 values (inter, impact, quantity, value, sigma), got %d\n",
                    fp->impacts, lineno, n > 5 ? 6 : n);
            rc = 2;
            break;
        }
        if (fp->nimp == RC_FIT_MAX_SIG) {
            fprintf(stderr, "ricochet fit: %s:%d: at most %d impact quantities\n", fp->impacts, lineno, RC_FIT_MAX_SIG);
            rc = 2;
            break;
        }
        fit_imp *g = &fp->imp[fp->nimp];
        memset(g, 0, sizeof *g);
        double a, b;
        if (!parse_number(cells[0], strlen(cells[0]), &a) || a != floor(a) || a < 1 || a > 1e9 ||
            !parse_number(cells[1], strlen(cells[1]), &b) || b != floor(b) || b < 1 || b > RC_STATS_IMPACTS) {
            fprintf(stderr, "ricochet fit: %s:%d: expected an /INTER id (a whole number >= 1) and the impact's number "
                            "on that interface (1 = its first; at most %d), got '%s', '%s'\n", fp->impacts, lineno,
                    RC_STATS_IMPACTS, trim(cells[0]), trim(cells[1]));
            rc = 2;
            break;
        }
        g->inter = (int)a;
        g->k = (int)b;
        char raw[64], *nm, *un;
        snprintf(raw, sizeof raw, "%s", trim(cells[2]));
        g->q = -1;
        if (name_unit(cells[2], &nm, &un))
            for (int q = 0; q < RC_FIT_NIMPQ; q++)
                if (!strcasecmp(nm, impact_q[q].name)) g->q = q;
        if (g->q < 0) {
            fprintf(stderr, "ricochet fit: %s:%d: quantity: expected 'NAME [UNIT]', NAME one of t_close, duration, "
                            "pen_max, fn_max, v_in, v_out, restitution, energy_lost (an impact), contact_t_close, "
                            "contact_duration, contact_pen_max, contact_fn_max, contact_fn_mean, contact_slip (a "
                            "persistent contact), got '%s'\n", fp->impacts, lineno, raw);
            rc = 2;
            break;
        }
        const impact_quantity *iq = &impact_q[g->q];
        if (!strcmp(un, iq->unit_si)) g->to_si = 1.0;
        else if (iq->unit_alt && !strcmp(un, iq->unit_alt)) g->to_si = iq->alt_to_si;
        else {
            fprintf(stderr, "ricochet fit: %s:%d: quantity %s: expected the unit %s%s%s, got [%s]\n", fp->impacts,
                    lineno, iq->name, iq->unit_si, iq->unit_alt ? " or " : "", iq->unit_alt ? iq->unit_alt : "", un);
            rc = 2;
            break;
        }
        if (!parse_number(cells[3], strlen(cells[3]), &g->value) || !parse_number(cells[4], strlen(cells[4]), &g->sigma) ||
            !(g->sigma > 0)) {
            fprintf(stderr, "ricochet fit: %s:%d: expected the measured value and its standard uncertainty sigma > 0 [%s], "
                            "got '%s', '%s'\n", fp->impacts, lineno, un, trim(cells[3]), trim(cells[4]));
            rc = 2;
            break;
        }
        g->value *= g->to_si;
        g->sigma *= g->to_si;
        snprintf(g->unit, sizeof g->unit, "%s", un);
        snprintf(g->label, sizeof g->label, "inter %d %s %d %s [%s]", g->inter,
                 g->q >= RC_FIT_FIRST_CONTACT_Q ? "contact" : "impact", g->k, iq->name, un);
        for (int j = 0; j < fp->nimp; j++)
            if (fp->imp[j].inter == g->inter && fp->imp[j].k == g->k && fp->imp[j].q == g->q) {
                fprintf(stderr, "ricochet fit: %s:%d: inter %d %s %d %s measured twice\n", fp->impacts, lineno,
                        g->inter, g->q >= RC_FIT_FIRST_CONTACT_Q ? "contact" : "impact", g->k, iq->name);
                rc = 2;
            }
        if (rc == 0) fp->nimp++;
    }
    fclose(f);
    if (rc == 0 && fp->nimp == 0) {
        fprintf(stderr, "ricochet fit: %s:%d: expected the header and at least one row\n", fp->impacts, lineno);
        rc = 2;
    }
    return rc;
}

/* ---- simulation ------------------------------------------------------- */

/* Milliseconds of wall time since an arbitrary origin. */
static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The --set strings of the fixed overrides and of the parameters at p;
 * buf holds the text. Returns the count. */
static int build_set(const fit_problem *fp, const double *p, const char **set, char (*buf)[320])
{
    int n = 0;
    for (int k = 0; k < fp->nset; k++) set[n++] = fp->set[k];
    for (int j = 0; j < fp->np; j++) {
        /* the shortest decimal that reads back as p[j] */
        int prec = 6;
        while (prec < 17) {
            char t[64];
            snprintf(t, sizeof t, "%.*g", prec, p[j]);
            if (strtod(t, NULL) == p[j]) break;
            prec++;
        }
        snprintf(buf[j], sizeof buf[j], "%s=%.*g", fp->par[j].name, prec, p[j]);
        set[n++] = buf[j];
    }
    return n;
}

/* Simulate at parameter values p (card units): sim[nt * ns] receives the
 * signals (SI) at the data times. RC_OK, or the status with *e filled. */
static rc_status simulate(fit_problem *fp, const double *p, double *sim, rc_error *e)
{
    const char *set[RC_FIT_MAX_SET + RC_FIT_MAX_PAR];
    char buf[RC_FIT_MAX_PAR][320];
    const int nset = build_set(fp, p, set, buf);
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_session *s = NULL;
    const double t0 = wall_now();
    rc_status st = rc_case_load_set(fp->deck, set, nset, &c, e);
    if (!st) st = rc_model_compile(c, &m, e);
    if (!st && fp->rtol > 0) st = rc_model_set_rtol(m, fp->rtol, e);
    if (!st && fp->method > 0) st = rc_model_set_method(m, fp->method, e);
    /* the run ends at the last data time; a failed physics check is noted,
     * not a stop (a trial may be unphysical) */
    rc_run_options opt = {0};
    opt.t_end_override = fp->t[fp->nt - 1] > 0 ? fp->t[fp->nt - 1] : 0.0;
    opt.on_violation = RC_ON_VIOLATION_WARN;
    if (!st) st = rc_session_open(m, &opt, &s, e);
    for (int i = 0; i < fp->nt && !st; i++) {
        st = rc_run_until(s, fp->t[i], e);
        const double *y = st ? NULL : rc_session_state(s);
        if (!st && fabs(rc_session_time(s) - fp->t[i]) > 1e-12 * fmax(1.0, fp->t[i])) {
            if (e) {
                e->code = RC_ESOLVER;
                snprintf(e->msg, sizeof e->msg, "the run stopped at t = %.17g s before the data time %.17g s",
                         rc_session_time(s), fp->t[i]);
            }
            st = RC_ESOLVER;
        }
        for (int k = 0; k < fp->ns && !st; k++) {
            double b[13];
            st = rc_model_body_state(m, y, fp->sig[k].body, b, e);
            if (!st) sim[(size_t)i * (size_t)fp->ns + (size_t)k] = b[quantity_slot[fp->sig[k].q]];
        }
    }
    if (s) {
        rc_error e2;
        rc_stats stats;
        memset(&stats, 0, sizeof stats);
        rc_status st2 = rc_session_close(s, &stats, &e2);
        if (!st && st2 && st2 != RC_EINTERRUPT) {
            st = st2;
            if (e) *e = e2;
        }
        /* the impacts' quantities: the k-th impact of the interface among
         * the first RC_STATS_IMPACTS of the run (the k-th persistent
         * contact among the first RC_STATS_CONTACTS for contact_*) */
        double *si = sim + (size_t)fp->nt * (size_t)fp->ns;
        for (int j = 0; j < fp->nimp && !st; j++) {
            const fit_imp *g = &fp->imp[j];
            const int persistent = g->q >= RC_FIT_FIRST_CONTACT_Q;
            int hit = 0;
            double v = NAN;
            if (!persistent) {
                const int n = stats.impacts < RC_STATS_IMPACTS ? (int)stats.impacts : RC_STATS_IMPACTS;
                for (int i = 0, seen = 0; i < n && !hit; i++)
                    if (stats.impact[i].inter_id == g->inter && ++seen == g->k) {
                        const rc_impact *h = &stats.impact[i];
                        const double vals[] = {h->t_close, h->duration, h->pen_max,     h->fn_max,
                                               h->v_in,    h->v_out,    h->restitution, h->energy_lost};
                        v = vals[g->q];
                        hit = 1;
                    }
            } else {
                const int n = stats.contacts < RC_STATS_CONTACTS ? (int)stats.contacts : RC_STATS_CONTACTS;
                for (int i = 0, seen = 0; i < n && !hit; i++)
                    if (stats.contact[i].inter_id == g->inter && ++seen == g->k) {
                        const rc_contact *h = &stats.contact[i];
                        const double vals[] = {h->t_close, h->duration, h->pen_max, h->fn_max, h->fn_mean, h->slip};
                        v = vals[g->q - RC_FIT_FIRST_CONTACT_Q];
                        hit = 1;
                    }
            }
            if (!isfinite(v)) {
                if (e) {
                    e->code = RC_ESOLVER;
                    snprintf(e->msg, sizeof e->msg, "%s: %s (the run has %ld %s; the first %d are seen)", g->label,
                             hit ? "not defined (the bodies did not separate before the end)"
                                 : persistent ? "no such persistent contact in the run"
                                              : "no such impact among the first impacts of the run",
                             persistent ? stats.contacts : stats.impacts,
                             persistent ? "persistent contacts" : "impacts",
                             persistent ? RC_STATS_CONTACTS : RC_STATS_IMPACTS);
                }
                st = RC_ESOLVER;
            }
            si[j] = v;
        }
    }
    rc_model_free(m);
    rc_case_free(c);
    pthread_mutex_lock(&fp->lock);
    fp->nsim++;
    fp->sim_wall += wall_now() - t0;
    if (st) {
        fp->nsim_failed++;
        if (!fp->first_failure[0] && e) snprintf(fp->first_failure, sizeof fp->first_failure, "%.1000s", e->msg);
    }
    pthread_mutex_unlock(&fp->lock);
    return st;
}

/* Residuals at u: r = (sim - measured) / scale over the measured values.
 * A failed simulation gives RC_FIT_FAILED_RESIDUAL everywhere (the trial
 * step is rejected). Returns the simulation's status. */
static rc_status residuals(fit_problem *fp, const double *u, double *r, double *sim)
{
    double p[RC_FIT_MAX_PAR];
    for (int j = 0; j < fp->np; j++) p[j] = par_value(&fp->par[j], u[j], NULL);
    rc_error e;
    memset(&e, 0, sizeof e);
    rc_status st = simulate(fp, p, sim, &e);
    int k = 0;
    for (int i = 0; i < fp->nt; i++)
        for (int s = 0; s < fp->ns; s++) {
            const double mv = fp->meas[(size_t)i * (size_t)fp->ns + (size_t)s];
            if (isnan(mv)) continue;
            r[k++] = st ? RC_FIT_FAILED_RESIDUAL
                        : (sim[(size_t)i * (size_t)fp->ns + (size_t)s] - mv) /
                              (fp->weighted ? fp->sig[s].sigma : fp->sig[s].scale);
        }
    /* the impacts' quantities, after the signals (simulate puts them there) */
    const double *si = sim + (size_t)fp->nt * (size_t)fp->ns;
    for (int j = 0; j < fp->nimp; j++)
        r[k++] = st ? RC_FIT_FAILED_RESIDUAL : (si[j] - fp->imp[j].value) / fp->imp[j].sigma;
    return st;
}

/* ---- GSL callbacks ---------------------------------------------------- */

static int fit_f(const gsl_vector *x, void *params, gsl_vector *f)
{
    fit_problem *fp = params;
    double u[RC_FIT_MAX_PAR];
    for (int j = 0; j < fp->np; j++) u[j] = gsl_vector_get(x, (size_t)j);
    double *r = malloc((size_t)fp->nres * sizeof *r), *sim = malloc(sim_len(fp) * sizeof *sim);
    if (!r || !sim) {
        free(r);
        free(sim);
        return GSL_ENOMEM;
    }
    residuals(fp, u, r, sim);
    for (int k = 0; k < fp->nres; k++) gsl_vector_set(f, (size_t)k, r[k]);
    free(r);
    free(sim);
    return GSL_SUCCESS;
}

/* One finite-difference evaluation: u0 + sign h e_j into r. */
typedef struct {
    int j;
    double sign;
    double *r;
    rc_status st;
} fd_task;

typedef struct {
    fit_problem *fp;
    const double *u0;
    fd_task *task;
    int ntask, next;
    pthread_mutex_t lock;
} fd_pool;

static void *fd_worker(void *arg)
{
    fd_pool *pool = arg;
    fit_problem *fp = pool->fp;
    double *sim = malloc(sim_len(fp) * sizeof *sim);
    for (;;) {
        pthread_mutex_lock(&pool->lock);
        const int k = pool->next < pool->ntask ? pool->next++ : -1;
        pthread_mutex_unlock(&pool->lock);
        if (k < 0) break;
        fd_task *t = &pool->task[k];
        if (!sim) {
            t->st = RC_ENOMEM;
            continue;
        }
        double u[RC_FIT_MAX_PAR];
        memcpy(u, pool->u0, (size_t)fp->np * sizeof *u);
        u[t->j] += t->sign * fp->h;
        t->st = residuals(fp, u, t->r, sim);
    }
    free(sim);
    return NULL;
}

/* The Jacobian by finite differences in u, the evaluations in parallel. */
static int fit_df(const gsl_vector *x, void *params, gsl_matrix *J)
{
    fit_problem *fp = params;
    double u0[RC_FIT_MAX_PAR];
    for (int j = 0; j < fp->np; j++) u0[j] = gsl_vector_get(x, (size_t)j);
    const int per = fp->central ? 2 : 1, ntask = per * fp->np + (fp->central ? 0 : 1);
    fd_task task[2 * RC_FIT_MAX_PAR + 1];
    double *store = malloc((size_t)ntask * (size_t)fp->nres * sizeof *store);
    if (!store) return GSL_ENOMEM;
    for (int k = 0; k < ntask; k++) {
        task[k].r = store + (size_t)k * (size_t)fp->nres;
        task[k].st = RC_OK;
        if (fp->central) {
            task[k].j = k / 2;
            task[k].sign = k % 2 ? -1.0 : 1.0;
        } else {
            /* the last task is the base point (f is not passed here) */
            task[k].j = k < fp->np ? k : 0;
            task[k].sign = k < fp->np ? 1.0 : 0.0;
        }
    }
    fd_pool pool = {.fp = fp, .u0 = u0, .task = task, .ntask = ntask, .next = 0};
    pthread_mutex_init(&pool.lock, NULL);
    int nth = fp->jobs < ntask ? fp->jobs : ntask;
    pthread_t th[2 * RC_FIT_MAX_PAR + 1];
    int started = 0;
    for (int k = 1; k < nth; k++) {
        if (pthread_create(&th[started], NULL, fd_worker, &pool) == 0) started++;
    }
    fd_worker(&pool); /* this thread works too */
    for (int k = 0; k < started; k++) pthread_join(th[k], NULL);
    pthread_mutex_destroy(&pool.lock);
    int status = GSL_SUCCESS;
    for (int k = 0; k < ntask; k++)
        if (task[k].st) status = GSL_EBADFUNC;
    if (status == GSL_SUCCESS) {
        for (int j = 0; j < fp->np; j++) {
            const double *rp = fp->central ? task[2 * j].r : task[j].r;
            const double *rm = fp->central ? task[2 * j + 1].r : task[fp->np].r;
            const double d = fp->central ? 2.0 * fp->h : fp->h;
            for (int k = 0; k < fp->nres; k++) gsl_matrix_set(J, (size_t)k, (size_t)j, (rp[k] - rm[k]) / d);
        }
    }
    free(store);
    return status;
}

/* A model of the deck at the parameter values p (card units), with the
 * fit's overrides of the tolerance and the method; *used receives p[j]
 * as read back (j >= 0). */
static rc_status compile_p(fit_problem *fp, const double *p, rc_model **m, rc_error *e)
{
    const char *set[RC_FIT_MAX_SET + RC_FIT_MAX_PAR];
    char buf[RC_FIT_MAX_PAR][320];
    const int nset = build_set(fp, p, set, buf);
    rc_case *c = NULL;
    rc_status st = rc_case_load_set(fp->deck, set, nset, &c, e);
    if (!st) st = rc_model_compile(c, m, e);
    if (!st && fp->rtol > 0) st = rc_model_set_rtol(*m, fp->rtol, e);
    if (!st && fp->method > 0) st = rc_model_set_method(*m, fp->method, e);
    rc_case_free(c);
    return st;
}

/* The Jacobian from forward sensitivities (--jacobian sens): one run of
 * the deck at p with the sensitivities to every parameter at the data
 * times. */
static int fit_df_sens(const gsl_vector *x, void *params, gsl_matrix *J)
{
    fit_problem *fp = params;
    const int np = fp->np;
    double p[RC_FIT_MAX_PAR], dpdu[RC_FIT_MAX_PAR], pl[RC_FIT_MAX_PAR], dp[RC_FIT_MAX_PAR];
    for (int j = 0; j < np; j++) p[j] = par_value(&fp->par[j], gsl_vector_get(x, (size_t)j), &dpdu[j]);
    rc_model *m = NULL, *mlo[RC_FIT_MAX_PAR] = {0}, *mhi[RC_FIT_MAX_PAR] = {0};
    rc_error e;
    memset(&e, 0, sizeof e);
    const double t0 = wall_now();
    rc_status st = compile_p(fp, p, &m, &e);
    for (int j = 0; j < np && !st; j++) {
        /* p -+ h, h taken from the values as they read back (build_set's
         * shortest decimals are exact) */
        const double h = p[j] != 0.0 ? RC_FIT_SENS_STEP * fabs(p[j]) : RC_FIT_SENS_STEP;
        memcpy(pl, p, (size_t)np * sizeof(double));
        pl[j] = p[j] - h;
        st = compile_p(fp, pl, &mlo[j], &e);
        const double lo = pl[j];
        pl[j] = p[j] + h;
        if (!st) st = compile_p(fp, pl, &mhi[j], &e);
        dp[j] = pl[j] - lo;
    }
    const int ny = m ? rc_model_state_size(m) : 0;
    double *y = NULL, *s = NULL, *ya = NULL, *yb = NULL;
    if (!st) {
        y = malloc((size_t)fp->nt * (size_t)ny * sizeof(double));
        s = malloc((size_t)fp->nt * (size_t)np * (size_t)ny * sizeof(double));
        ya = malloc((size_t)ny * sizeof(double));
        yb = malloc((size_t)ny * sizeof(double));
        if (!y || !s || !ya || !yb) st = RC_ENOMEM;
    }
    /* the events, for the impacts' quantities */
    enum { MAXEV = 256 };
    double *evd = !st ? malloc((2 + 2 * (size_t)np) * MAXEV * sizeof(double)) : NULL;
    int ev_id[MAXEV];
    const char *ev_kind[MAXEV];
    rc_sens_events ev = {MAXEV, 0, 0, evd, ev_id, ev_kind, evd + MAXEV, evd + MAXEV * (1 + (size_t)np),
                         evd + MAXEV * (2 + (size_t)np), NULL, NULL};
    rc_stats stats;
    memset(&stats, 0, sizeof stats);
    if (!st && !evd) st = RC_ENOMEM;
    if (!st)
        st = rc_sens_run(m, np, (const rc_model *const *)mlo, (const rc_model *const *)mhi, p, dp, fp->nt, fp->t, y, s,
                         NULL, &ev, &stats, &e);
    /* dr/du = d sim/dp dp/du / scale over the measured values */
    int k = 0;
    for (int i = 0; i < fp->nt && !st; i++) {
        const double *yi = y + (size_t)i * (size_t)ny;
        for (int q = 0; q < fp->ns && !st; q++) {
            if (isnan(fp->meas[(size_t)i * (size_t)fp->ns + (size_t)q])) continue;
            const double w = fp->weighted ? fp->sig[q].sigma : fp->sig[q].scale;
            for (int j = 0; j < np && !st; j++) {
                /* the body state's central difference along s */
                const double *sj = s + ((size_t)i * (size_t)np + (size_t)j) * (size_t)ny;
                double smax = 0.0, ymax = 1.0, der = 0.0;
                for (int r = 0; r < ny; r++) {
                    smax = fmax(smax, fabs(sj[r]));
                    ymax = fmax(ymax, fabs(yi[r]));
                }
                if (smax > 0) {
                    const double eps = 1e-7 * ymax / smax;
                    double ba[13], bb[13];
                    for (int r = 0; r < ny; r++) {
                        ya[r] = yi[r] + eps * sj[r];
                        yb[r] = yi[r] - eps * sj[r];
                    }
                    st = rc_model_body_state(m, ya, fp->sig[q].body, ba, &e);
                    if (!st) st = rc_model_body_state(m, yb, fp->sig[q].body, bb, &e);
                    der = (ba[quantity_slot[fp->sig[q].q]] - bb[quantity_slot[fp->sig[q].q]]) / (2.0 * eps);
                }
                gsl_matrix_set(J, (size_t)k, (size_t)j, der * dpdu[j] / w);
            }
            k++;
        }
    }
    /* the impacts' quantities: the k-th impact of the interface (as
     * simulate finds it), its events by their times: t_close and v_in at
     * the contact_close, duration to the event at t_open, v_out = -dP/dt at
     * the contact_separate that follows */
    for (int g = 0; g < fp->nimp && !st; g++) {
        const fit_imp *im = &fp->imp[g];
        const rc_impact *h = NULL;
        const int n = stats.impacts < RC_STATS_IMPACTS ? (int)stats.impacts : RC_STATS_IMPACTS;
        for (int i = 0, seen = 0; i < n && !h; i++)
            if (stats.impact[i].inter_id == im->inter && ++seen == im->k) h = &stats.impact[i];
        int a = -1, b = -1, c = -1;
        for (int i = 0; h && i < ev.n; i++) {
            if (ev.inter_id[i] != im->inter) continue;
            const double tol = 1e-12 * fmax(1.0, fabs(ev.t[i]));
            if (a < 0 && !strcmp(ev.kind[i], "contact_close") && fabs(ev.t[i] - h->t_close) <= tol) a = i;
            if (b < 0 && isfinite(h->t_open) && fabs(ev.t[i] - h->t_open) <= tol) b = i;
            if (c < 0 && b >= 0 && !strcmp(ev.kind[i], "contact_separate")) c = i;
        }
        const int need = im->q == 1 ? b : im->q == 5 ? c : a;
        if (!h || a < 0 || need < 0) {
            st = RC_ESOLVER;
            snprintf(e.msg, sizeof e.msg, "--jacobian sens: %s: its event%s not found among the run's events", im->label,
                     h ? "" : " (the impact itself)");
            break;
        }
        for (int j = 0; j < np; j++) {
            const double *dt = ev.dtdp, *dv = ev.dvndp;
            const double d = im->q == 0   ? dt[(size_t)a * (size_t)np + (size_t)j]
                             : im->q == 1 ? dt[(size_t)b * (size_t)np + (size_t)j] - dt[(size_t)a * (size_t)np + (size_t)j]
                             : im->q == 4 ? dv[(size_t)a * (size_t)np + (size_t)j]
                                          : -dv[(size_t)c * (size_t)np + (size_t)j];
            gsl_matrix_set(J, (size_t)k, (size_t)j, d * dpdu[j] / im->sigma);
        }
        k++;
    }
    free(evd);
    free(y);
    free(s);
    free(ya);
    free(yb);
    rc_model_free(m);
    for (int j = 0; j < np; j++) {
        rc_model_free(mlo[j]);
        rc_model_free(mhi[j]);
    }
    pthread_mutex_lock(&fp->lock);
    fp->nsim++;
    fp->sim_wall += wall_now() - t0;
    if (st) {
        fp->nsim_failed++;
        if (!fp->first_failure[0]) snprintf(fp->first_failure, sizeof fp->first_failure, "%.1000s", e.msg);
    }
    pthread_mutex_unlock(&fp->lock);
    return st ? GSL_EBADFUNC : GSL_SUCCESS;
}

/* Progress: one line per iteration on stderr. */
static void fit_callback(const size_t iter, void *params, const gsl_multifit_nlinear_workspace *w)
{
    fit_problem *fp = params;
    if (fp->quiet) return;
    gsl_vector *f = gsl_multifit_nlinear_residual(w);
    gsl_vector *x = gsl_multifit_nlinear_position(w);
    double chi = gsl_blas_dnrm2(f);
    FILE *o = fp->progress ? fp->progress : stderr;
    fprintf(o, "ricochet fit: iteration %zu: residual RMS %.6g,", iter, chi / sqrt((double)fp->nres));
    for (int j = 0; j < fp->np; j++)
        fprintf(o, " %s=%.6g", fp->par[j].name, par_value(&fp->par[j], gsl_vector_get(x, (size_t)j), NULL));
    fprintf(o, "\n");
    fflush(o);
}

/* ---- the report -------------------------------------------------------- */

typedef struct {
    double p[RC_FIT_MAX_PAR], se[RC_FIT_MAX_PAR], lo95[RC_FIT_MAX_PAR], hi95[RC_FIT_MAX_PAR];
    int unident[RC_FIT_MAX_PAR]; /* 0 identified; 1 zero column; 2 rank; 3 rse; 4 at a bound */
    double rse[RC_FIT_MAX_PAR];
    double corr[RC_FIT_MAX_PAR][RC_FIT_MAX_PAR];
    double rms_all, tq;
    int dof;
} fit_stats;

static void print_report(FILE *o, const fit_problem *fp, const fit_stats *S, const double *sim, size_t iters,
                         size_t nfev, size_t njev, double wall, const char *status, double max_rse, int nth)
{
    fprintf(o, "ricochet %s fit: %s against %s\n", rc_version(), fp->deck, fp->data);
    char imps[160] = "";
    if (fp->nimp > 0)
        snprintf(imps, sizeof imps, " and %d quantit%s of impacts or contacts from %s", fp->nimp,
                 fp->nimp > 1 ? "ies" : "y", fp->impacts);
    fprintf(o, "data: %d times from %g to %g s, %d signal%s%s, %d measured values; %d free parameter%s, %d degrees of "
               "freedom\n", fp->nt, fp->t[0], fp->t[fp->nt - 1], fp->ns, fp->ns > 1 ? "s" : "", imps, fp->nres, fp->np,
            fp->np > 1 ? "s" : "", S->dof);
    fprintf(o, "status: %s\n", status);
    fprintf(o, "parameters (card units, as --set; 95%% interval = value +- t(0.975, %d) x standard error, t = %.4g):\n",
            S->dof, S->tq);
    for (int j = 0; j < fp->np; j++) {
        const fit_par *q = &fp->par[j];
        char range[96] = "";
        if (q->bounded) snprintf(range, sizeof range, " bounds [%g, %g]", q->lo, q->hi);
        fprintf(o, "  %s%s%s (start %g)\n", q->name, q->logscale ? " (log)" : "", range, q->start);
        if (S->unident[j]) {
            const char *why = S->unident[j] == 1   ? "the signals do not depend on it (its column of the Jacobian is zero)"
                              : S->unident[j] == 2 ? "the Jacobian is rank-deficient: a combination of the others"
                                                   : "relative standard error above the limit";
            if (S->unident[j] == 4) {
                const int hi = S->p[j] > 0.5 * (q->lo + q->hi);
                fprintf(o, "    UNIDENTIFIABLE: at its bound %s = %g (the data push it beyond; widen the bounds or "
                           "fix it); left at %.10g\n", hi ? "HI" : "LO", hi ? q->hi : q->lo, S->p[j]);
            } else if (S->unident[j] == 3) {
                /* the parameter it is most correlated with: the data may fix
                 * a combination of the two */
                int jb = -1;
                for (int b = 0; b < fp->np; b++)
                    if (b != j && isfinite(S->corr[j][b]) && (jb < 0 || fabs(S->corr[j][b]) > fabs(S->corr[j][jb])))
                        jb = b;
                char with[400] = "";
                if (jb >= 0 && fabs(S->corr[j][jb]) > 0.99)
                    snprintf(with, sizeof with, "; correlation %.6f with %s: the data fix a combination of the two",
                             S->corr[j][jb], fp->par[jb].name);
                fprintf(o, "    UNIDENTIFIABLE: relative standard error %.3g > %g (--max-rse)%s; left at %.10g\n",
                        S->rse[j], max_rse, with, S->p[j]);
            }
            else fprintf(o, "    UNIDENTIFIABLE: %s; left at %.10g\n", why, S->p[j]);
        } else {
            fprintf(o, "    fitted %.10g  standard error %.4g (%.3g %%)  95%% interval [%.10g, %.10g]\n", S->p[j],
                    S->se[j], 100.0 * S->rse[j], S->lo95[j], S->hi95[j]);
        }
    }
    if (fp->np > 1) {
        fprintf(o, "correlation matrix (in the order above; '-': a parameter without covariance):\n");
        for (int a = 0; a < fp->np; a++) {
            fprintf(o, "  ");
            for (int b = 0; b < fp->np; b++) {
                if (!isfinite(S->corr[a][b])) fprintf(o, " %8s", "-");
                else fprintf(o, " %8.4f", S->corr[a][b]);
            }
            fprintf(o, "\n");
        }
    }
    if (fp->weighted)
        fprintf(o, "residuals: each divided by its stated uncertainty: RMS %.4g, chi-square / dof = %.4g (near 1 when "
                   "the uncertainties are right and the model explains the data)\n",
                S->rms_all, S->rms_all * S->rms_all * fp->nres / (S->dof > 0 ? S->dof : 1));
    else
        fprintf(o, "residuals: RMS %.4g of the scaled residuals (each signal divided by its measured range)\n",
                S->rms_all);
    for (int s = 0; s < fp->ns; s++) {
        double ss = 0;
        int n = 0;
        for (int i = 0; i < fp->nt; i++) {
            const double mv = fp->meas[(size_t)i * (size_t)fp->ns + (size_t)s];
            if (isnan(mv)) continue;
            const double d = sim[(size_t)i * (size_t)fp->ns + (size_t)s] - mv;
            ss += d * d;
            n++;
        }
        fprintf(o, "  %s: RMS %.4g %s over %d values (range %.4g %s)\n", fp->sig[s].label,
                sqrt(ss / (n > 0 ? n : 1)) / fp->sig[s].to_si, fp->sig[s].unit, n, fp->sig[s].scale / fp->sig[s].to_si,
                fp->sig[s].unit);
    }
    const double *si = sim + (size_t)fp->nt * (size_t)fp->ns;
    for (int j = 0; j < fp->nimp; j++) {
        const fit_imp *g = &fp->imp[j];
        fprintf(o, "  %s: measured %.6g +- %.3g, fitted %.6g (%+.2f sigma)\n", g->label, g->value / g->to_si,
                g->sigma / g->to_si, si[j] / g->to_si, (si[j] - g->value) / g->sigma);
    }
    if (fp->sens)
        fprintf(o, "cost: %zu iterations, %zu residual and %zu Jacobian evaluations (forward sensitivities, one run "
                   "each), %ld simulations (%ld failed), %.3f s wall (%.3f s of simulation)\n",
                iters, nfev, njev, fp->nsim, fp->nsim_failed, wall, fp->sim_wall);
    else
        fprintf(o, "cost: %zu iterations, %zu residual and %zu Jacobian evaluations (%s differences, step %g), %ld "
                   "simulations (%ld failed), %.3f s wall (%.3f s of simulation over %d thread%s)\n",
                iters, nfev, njev, fp->central ? "central" : "forward", fp->h, fp->nsim, fp->nsim_failed, wall,
                fp->sim_wall, nth, nth > 1 ? "s" : "");
    if (fp->nsim_failed > 0) fprintf(o, "first failed simulation: %s\n", fp->first_failure);
    fprintf(o, "the deck with the fitted values: ricochet run %s", fp->deck);
    for (int k = 0; k < fp->nset; k++) fprintf(o, " --set %s", fp->set[k]);
    for (int j = 0; j < fp->np; j++)
        if (!S->unident[j]) fprintf(o, " --set %s=%.10g", fp->par[j].name, S->p[j]);
    fprintf(o, "\n");
}

/* A JSON string (the names and messages here hold no control characters
 * but may hold quotes and backslashes). */
static void json_str(FILE *o, const char *t)
{
    fputc('"', o);
    for (; *t; t++) {
        if (*t == '"' || *t == '\\') fputc('\\', o);
        if ((unsigned char)*t >= 0x20) fputc(*t, o);
    }
    fputc('"', o);
}

/* A JSON number; null for NaN and infinities. */
static void json_num(FILE *o, double v)
{
    if (isfinite(v)) fprintf(o, "%.17g", v);
    else fprintf(o, "null");
}

/* The report as JSON (--json; docs/calibration.md, "The JSON report"). */
static int write_json(const char *path, const fit_problem *fp, const fit_stats *S, const double *sim, size_t iters,
                      size_t nfev, size_t njev, double wall, const char *status, int converged)
{
    static const char *const reason[] = {NULL, "zero column", "rank", "relative standard error", "at bound"};
    FILE *o = fopen(path, "w");
    if (!o) {
        fprintf(stderr, "ricochet fit: %s: cannot write the JSON report (%s)\n", path, strerror(errno));
        return 4;
    }
    fprintf(o, "{\n  \"version\": ");
    json_str(o, rc_version());
    fprintf(o, ",\n  \"deck\": ");
    json_str(o, fp->deck);
    fprintf(o, ",\n  \"data\": ");
    json_str(o, fp->data);
    fprintf(o, ",\n  \"status\": ");
    json_str(o, status);
    fprintf(o, ",\n  \"converged\": %s,\n  \"iterations\": %zu,\n  \"residual_evaluations\": %zu,\n"
               "  \"jacobian_evaluations\": %zu,\n  \"jacobian\": \"%s\",\n  \"simulations\": %ld,\n"
               "  \"failed_simulations\": %ld,\n  \"wall_time\": ",
            converged ? "true" : "false", iters, nfev, njev, fp->sens ? "sens" : "fd", fp->nsim, fp->nsim_failed);
    json_num(o, wall);
    fprintf(o, ",\n  \"measured_values\": %d,\n  \"dof\": %d,\n  \"t_quantile\": ", fp->nres, S->dof);
    json_num(o, S->tq);
    fprintf(o, ",\n  \"residual_rms\": ");
    json_num(o, S->rms_all);
    fprintf(o, ",\n  \"parameters\": [");
    for (int j = 0; j < fp->np; j++) {
        const fit_par *q = &fp->par[j];
        const int id = !S->unident[j];
        fprintf(o, "%s\n    {\"name\": ", j ? "," : "");
        json_str(o, q->name);
        fprintf(o, ", \"log\": %s, \"start\": ", q->logscale ? "true" : "false");
        json_num(o, q->start);
        fprintf(o, ", \"lo\": ");
        json_num(o, q->bounded ? q->lo : NAN);
        fprintf(o, ", \"hi\": ");
        json_num(o, q->bounded ? q->hi : NAN);
        fprintf(o, ", \"identifiable\": %s, \"reason\": ", id ? "true" : "false");
        if (id) fprintf(o, "null");
        else json_str(o, reason[S->unident[j]]);
        fprintf(o, ", \"value\": ");
        json_num(o, S->p[j]);
        fprintf(o, ", \"standard_error\": ");
        json_num(o, id ? S->se[j] : NAN);
        fprintf(o, ", \"lo95\": ");
        json_num(o, id ? S->lo95[j] : NAN);
        fprintf(o, ", \"hi95\": ");
        json_num(o, id ? S->hi95[j] : NAN);
        fprintf(o, "}");
    }
    fprintf(o, "\n  ],\n  \"correlation\": [");
    for (int a = 0; a < fp->np; a++) {
        fprintf(o, "%s\n    [", a ? "," : "");
        for (int b = 0; b < fp->np; b++) {
            if (b) fprintf(o, ", ");
            json_num(o, S->corr[a][b]);
        }
        fprintf(o, "]");
    }
    fprintf(o, "\n  ],\n  \"signals\": [");
    for (int k = 0; k < fp->ns; k++) {
        double ss = 0;
        int n = 0;
        for (int i = 0; i < fp->nt; i++) {
            const double mv = fp->meas[(size_t)i * (size_t)fp->ns + (size_t)k];
            if (isnan(mv)) continue;
            const double d = sim[(size_t)i * (size_t)fp->ns + (size_t)k] - mv;
            ss += d * d;
            n++;
        }
        fprintf(o, "%s\n    {\"label\": ", k ? "," : "");
        json_str(o, fp->sig[k].label);
        fprintf(o, ", \"body\": %d, \"quantity\": \"%s\", \"unit\": ", fp->sig[k].body, quantity_name[fp->sig[k].q]);
        json_str(o, fp->sig[k].unit);
        fprintf(o, ", \"values\": %d, \"rms\": ", n);
        json_num(o, sqrt(ss / (n > 0 ? n : 1)) / fp->sig[k].to_si);
        fprintf(o, "}");
    }
    fprintf(o, "\n  ],\n  \"weighted\": %s,\n  \"impacts\": [", fp->weighted ? "true" : "false");
    const double *si = sim + (size_t)fp->nt * (size_t)fp->ns;
    for (int j = 0; j < fp->nimp; j++) {
        const fit_imp *g = &fp->imp[j];
        fprintf(o, "%s\n    {\"label\": ", j ? "," : "");
        json_str(o, g->label);
        fprintf(o, ", \"inter\": %d, \"impact\": %d, \"quantity\": \"%s\", \"unit\": ", g->inter, g->k,
                impact_q[g->q].name);
        json_str(o, g->unit);
        fprintf(o, ", \"measured\": ");
        json_num(o, g->value / g->to_si);
        fprintf(o, ", \"sigma\": ");
        json_num(o, g->sigma / g->to_si);
        fprintf(o, ", \"fitted\": ");
        json_num(o, si[j] / g->to_si);
        fprintf(o, "}");
    }
    fprintf(o, "\n  ],\n  \"set\": [");
    int first = 1;
    for (int j = 0; j < fp->np; j++) {
        if (S->unident[j]) continue;
        char buf[400];
        snprintf(buf, sizeof buf, "%s=%.10g", fp->par[j].name, S->p[j]);
        fprintf(o, "%s", first ? "" : ", ");
        json_str(o, buf);
        first = 0;
    }
    fprintf(o, "]\n}\n");
    if (fclose(o) != 0) {
        fprintf(stderr, "ricochet fit: %s: write error\n", path);
        return 4;
    }
    return 0;
}

/* Measured against fitted signals, in the data's units. */
static int write_fitted(const char *path, const fit_problem *fp, const double *sim)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "ricochet fit: %s: cannot write the fitted signals (%s)\n", path, strerror(errno));
        return 4;
    }
    fprintf(f, "t [%s]", fp->time_unit);
    for (int s = 0; s < fp->ns; s++) {
        const fit_sig *g = &fp->sig[s];
        fprintf(f, ", measured body %d %s [%s], fitted body %d %s [%s]", g->body, quantity_name[g->q], g->unit, g->body,
                quantity_name[g->q], g->unit);
    }
    fprintf(f, "\n");
    for (int i = 0; i < fp->nt; i++) {
        fprintf(f, "%.15g", fp->t[i] / fp->t_to_si);
        for (int s = 0; s < fp->ns; s++) {
            const double mv = fp->meas[(size_t)i * (size_t)fp->ns + (size_t)s];
            if (isnan(mv)) fprintf(f, ",");
            else fprintf(f, ",%.15g", mv / fp->sig[s].to_si);
            fprintf(f, ",%.15g", sim[(size_t)i * (size_t)fp->ns + (size_t)s] / fp->sig[s].to_si);
        }
        fprintf(f, "\n");
    }
    if (fclose(f) != 0) {
        fprintf(stderr, "ricochet fit: %s: write error\n", path);
        return 4;
    }
    return 0;
}

/* ---- the command ------------------------------------------------------- */

static void usage_fit(FILE *f)
{
    fprintf(f,
            "usage: ricochet fit CASE --data FILE.csv --free CARD:FIELD=START[,LO:HI] [--free ...] [options]\n"
            "Fit numeric fields of the case (addressed as by --set) so that the simulated signals match the\n"
            "measured ones: nonlinear least squares (GSL, trust region: double dogleg), the Jacobian by\n"
            "finite differences evaluated in parallel (docs/calibration.md).\n"
            "  --data FILE.csv       measured signals: a header 't [s], body 1 z [m], body 1 vx [m/s], ...'\n"
            "                        (time in s or ms; x, y, z in m or mm; vx, vy, vz in m/s or mm/s; after the\n"
            "                        unit, '+- SIGMA' states a signal's uncertainty: each residual is then divided\n"
            "                        by it), then one row per time, increasing; a blank cell is not measured; '#'\n"
            "                        lines are comments\n"
            "  --free CARD:FIELD=START[,LO:HI]\n"
            "                        a field to fit, from START, kept inside (LO, HI) when given; values in the\n"
            "                        card's units, as --set (repeatable, at most %d)\n"
            "  --log CARD:FIELD=START[,LO:HI]\n"
            "                        the same, fitted in log(value) (START > 0, LO > 0): for scales and stiffnesses\n"
            "  --set CARD:FIELD=VALUE a field set to a fixed value (repeatable)\n"
            "  -o REPORT             write the report to REPORT as well as to stdout\n"
            "  --fitted FILE.csv     measured against fitted signals (default: the data file's stem + _fit.csv,\n"
            "                        in the current directory)\n"
            "  --impacts FILE.csv    measured quantities of impacts as well: a header 'inter, impact, quantity,\n"
            "                        value, sigma', then rows such as '1, 1, v_out [m/s], 1.59, 0.01' (t_close,\n"
            "                        duration, pen_max, fn_max, v_in, v_out, restitution, energy_lost; of a\n"
            "                        persistent contact: contact_slip, contact_fn_mean, ...); needs the\n"
            "                        data file's signals to state their uncertainties: 'body 1 z [m] +- 0.0005'\n"
            "  --json FILE.json      the report as JSON as well (docs/calibration.md)\n"
            "  --rtol R              relative tolerance of the simulations, instead of /SOLVER Rtol\n"
            "  --trs METHOD          trust-region method of GSL: ddogleg (default: double dogleg), dogleg,\n"
            "                        subspace2D, or lm (Levenberg-Marquardt, whose steps the trust radius does not\n"
            "                        bound: from a poor start it may leave for a flat region)\n"
            "  --method M            integration backend of the simulations: cvode (1) or ida (2), instead of\n"
            "                        /SOLVER Method\n"
            "  --max-iter N          at most N iterations (default 100)\n"
            "  --fd-step H           finite-difference step in the fitted variables (default 1e-4)\n"
            "  --forward             forward differences (p + 1 simulations per Jacobian, default central: 2p)\n"
            "  --jacobian fd|sens    the Jacobian by finite differences (default) or from forward sensitivities in\n"
            "                        one run per Jacobian (ricochet sens; with --impacts: t_close, duration, v_in,\n"
            "                        v_out only; /SOLVER Method 1)\n"
            "  --jobs N              threads of the Jacobian (default: the processors online)\n"
            "  --max-rse X           a relative standard error above X reports the parameter UNIDENTIFIABLE\n"
            "                        (default 1, i.e. 100 %%)\n"
            "  -q                    no progress on stderr\n"
            "  -h, --help            this text\n"
            "exit codes: 0 converged, 1 not converged within the iterations (report written), 2 input error (the\n"
            "            data file's file:line, an option; nothing run), 3 the simulation at the start failed,\n"
            "            4 a file could not be read or written\n",
            RC_FIT_MAX_PAR);
}

/* The value of option a (argv[k + 1] or after '='); NULL and a message when
 * missing. */
static const char *opt_value(int argc, char **argv, int *k, const char *a, const char *name)
{
    const size_t n = strlen(name);
    if (!strncmp(a, name, n) && a[n] == '=') return a + n + 1;
    if (*k + 1 >= argc) {
        fprintf(stderr, "ricochet fit: %s needs a value\n", name);
        return NULL;
    }
    return argv[++*k];
}

/* Do paths a and b name the same existing file (device and inode)? */
static int same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return a && b && stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

static int is_opt(const char *a, const char *name)
{
    const size_t n = strlen(name);
    return !strncmp(a, name, n) && (a[n] == '\0' || a[n] == '=');
}

int rc_cli_fit(int argc, char **argv)
{
    gsl_set_error_handler_off();
    /* a fit writes nothing before its end: SIGINT, SIGTERM and SIGHUP end
     * it at once (the program's handlers, meant for a run that closes its
     * results file, would wait for a second signal) */
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    struct sigaction old_hup;
    if (sigaction(SIGHUP, NULL, &old_hup) == 0 && old_hup.sa_handler != SIG_IGN) signal(SIGHUP, SIG_DFL);
    static fit_problem P; /* large; one per process */
    fit_problem *fp = &P;
    memset(fp, 0, sizeof *fp);
    fp->h = 1e-4;
    fp->central = 1;
    long nproc = sysconf(_SC_NPROCESSORS_ONLN);
    fp->jobs = nproc > 0 ? (int)nproc : 1;
    int max_iter = 100;
    double max_rse = 1.0;
    const char *report = NULL, *fitted = NULL, *json = NULL;
    for (int k = 2; k < argc; k++) {
        const char *a = argv[k], *v;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage_fit(stdout);
            return 0;
        }
        if (!strcmp(a, "-q")) {
            fp->quiet = 1;
        } else if (!strcmp(a, "--forward")) {
            fp->central = 0;
        } else if (is_opt(a, "--jacobian")) {
            if (!(v = opt_value(argc, argv, &k, a, "--jacobian"))) return 2;
            if (strcmp(v, "fd") && strcmp(v, "sens")) {
                fprintf(stderr, "ricochet fit: --jacobian: expected fd or sens, got '%s'\n", v);
                return 2;
            }
            fp->sens = !strcmp(v, "sens");
        } else if (is_opt(a, "--free") || is_opt(a, "--log")) {
            const char *nm = is_opt(a, "--free") ? "--free" : "--log";
            if (!(v = opt_value(argc, argv, &k, a, nm))) return 2;
            if (fp->np == RC_FIT_MAX_PAR) {
                fprintf(stderr, "ricochet fit: %s %s: at most %d free parameters\n", nm, v, RC_FIT_MAX_PAR);
                return 2;
            }
            if (!parse_free(nm, v, !strcmp(nm, "--log"), &fp->par[fp->np])) return 2;
            for (int j = 0; j < fp->np; j++)
                if (!strcasecmp(fp->par[j].name, fp->par[fp->np].name)) {
                    fprintf(stderr, "ricochet fit: %s %s: %s is already free\n", nm, v, fp->par[j].name);
                    return 2;
                }
            fp->np++;
        } else if (is_opt(a, "--set")) {
            if (!(v = opt_value(argc, argv, &k, a, "--set"))) return 2;
            if (fp->nset == RC_FIT_MAX_SET) {
                fprintf(stderr, "ricochet fit: --set %s: at most %d --set options\n", v, RC_FIT_MAX_SET);
                return 2;
            }
            fp->set[fp->nset++] = v;
        } else if (is_opt(a, "--method")) {
            if (!(v = opt_value(argc, argv, &k, a, "--method"))) return 2;
            fp->method = !strcmp(v, "cvode") || !strcmp(v, "1") ? 1 : !strcmp(v, "ida") || !strcmp(v, "2") ? 2 : -1;
            if (fp->method < 0) {
                fprintf(stderr, "ricochet fit: --method: expected cvode or ida (or 1, 2), got %s\n", v);
                return 2;
            }
        } else if (is_opt(a, "--trs")) {
            if (!(v = opt_value(argc, argv, &k, a, "--trs"))) return 2;
            fp->trs = !strcmp(v, "ddogleg") ? 0 : !strcmp(v, "lm") ? 1 : !strcmp(v, "dogleg") ? 2 : !strcmp(v, "subspace2D") ? 3 : -1;
            if (fp->trs < 0) {
                fprintf(stderr, "ricochet fit: --trs: expected ddogleg, dogleg, subspace2D or lm, got %s\n", v);
                return 2;
            }
        } else if (is_opt(a, "--data")) {
            if (!(fp->data = opt_value(argc, argv, &k, a, "--data"))) return 2;
        } else if (!strcmp(a, "-o") || is_opt(a, "--output")) {
            if (!(report = opt_value(argc, argv, &k, a, a[1] == 'o' ? "-o" : "--output"))) return 2;
        } else if (is_opt(a, "--impacts")) {
            if (!(fp->impacts = opt_value(argc, argv, &k, a, "--impacts"))) return 2;
        } else if (is_opt(a, "--json")) {
            if (!(json = opt_value(argc, argv, &k, a, "--json"))) return 2;
        } else if (is_opt(a, "--fitted")) {
            if (!(fitted = opt_value(argc, argv, &k, a, "--fitted"))) return 2;
        } else if (is_opt(a, "--rtol") || is_opt(a, "--fd-step") || is_opt(a, "--max-rse") ||
                   is_opt(a, "--max-iter") || is_opt(a, "--jobs")) {
            const char *nm = is_opt(a, "--rtol")      ? "--rtol"
                             : is_opt(a, "--fd-step") ? "--fd-step"
                             : is_opt(a, "--max-rse") ? "--max-rse"
                             : is_opt(a, "--max-iter") ? "--max-iter"
                                                       : "--jobs";
            if (!(v = opt_value(argc, argv, &k, a, nm))) return 2;
            double x;
            const int whole = !strcmp(nm, "--max-iter") || !strcmp(nm, "--jobs");
            if (!parse_number(v, strlen(v), &x) || !(x > 0) || (whole && (x != floor(x) || x > 1e6)) ||
                (!strcmp(nm, "--rtol") && !(x < 1))) {
                fprintf(stderr, "ricochet fit: %s: expected %s, got '%s'\n", nm,
                        whole ? "a whole number >= 1" : !strcmp(nm, "--rtol") ? "a number in (0, 1)" : "a positive number",
                        v);
                return 2;
            }
            if (!strcmp(nm, "--rtol")) fp->rtol = x;
            else if (!strcmp(nm, "--fd-step")) fp->h = x;
            else if (!strcmp(nm, "--max-rse")) max_rse = x;
            else if (!strcmp(nm, "--max-iter")) max_iter = (int)x;
            else fp->jobs = (int)x;
        } else if (a[0] == '-') {
            fprintf(stderr, "ricochet fit: unknown option '%s'\n", a);
            usage_fit(stderr);
            return 2;
        } else if (fp->deck) {
            fprintf(stderr, "ricochet fit: unexpected argument '%s' (one case file, %s given first)\n", a, fp->deck);
            return 2;
        } else {
            fp->deck = a;
        }
    }
    if (!fp->deck || !fp->data || fp->np == 0) {
        fprintf(stderr, "ricochet fit: expected a case file, --data FILE.csv and at least one --free; missing %s\n",
                !fp->deck ? "the case file" : !fp->data ? "--data" : "--free");
        usage_fit(stderr);
        return 2;
    }
    /* the outputs may not replace an input */
    char def[1024];
    if (!fitted) {
        const char *b = strrchr(fp->data, '/');
        b = b ? b + 1 : fp->data;
        const char *dot = strrchr(b, '.');
        snprintf(def, sizeof def, "%.*s_fit.csv", dot && dot != b ? (int)(dot - b) : (int)strlen(b), b);
        fitted = def;
    }
    const char *outs[3] = {report, fitted, json}, *ins[3] = {fp->deck, fp->data, fp->impacts};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            if (same_file(outs[a], ins[b])) {
                fprintf(stderr, "ricochet fit: %s %s: expected an output file, got the %s\n",
                        a == 0 ? "-o" : a == 1 ? "--fitted" : "--json", outs[a],
                        b == 0 ? "case file" : b == 1 ? "data file" : "impacts file");
                return 2;
            }
    int rc = read_data(fp);
    if (rc) goto done;
    fp->nres_ts = fp->nres;
    fp->weighted = fp->sig[0].sigma > 0;
    if (fp->impacts) {
        if ((rc = read_impacts(fp)) != 0) goto done;
        /* --jacobian sens: the impacts' quantities that the events' derivatives give */
        for (int j = 0; j < fp->nimp && fp->sens; j++) {
            const int q = fp->imp[j].q;
            if (q != 0 && q != 1 && q != 4 && q != 5) {
                fprintf(stderr, "ricochet fit: %s: --jacobian sens: covers the impacts' t_close, duration, v_in and "
                                "v_out, not %s (use --jacobian fd)\n", fp->impacts, impact_q[q].name);
                rc = 2;
                goto done;
            }
        }
        if (!fp->weighted) {
            fprintf(stderr, "ricochet fit: %s: --impacts: expected the signals' uncertainties in the header (e.g. "
                            "'body 1 z [m] +- 0.0005'), to weigh them against the impacts'\n", fp->data);
            rc = 2;
            goto done;
        }
        fp->nres += fp->nimp;
    }
    if (fp->nres <= fp->np) {
        fprintf(stderr, "ricochet fit: %s: %d measured values for %d free parameters: expected more values than "
                        "parameters\n", fp->data, fp->nres, fp->np);
        rc = 2;
        goto done;
    }
    pthread_mutex_init(&fp->lock, NULL);
    /* the deck at the start values, read and compiled once: its input
     * errors (a --free or --set that names no field, a body id the model
     * lacks) before anything runs */
    {
        const char *set[RC_FIT_MAX_SET + RC_FIT_MAX_PAR];
        char buf[RC_FIT_MAX_PAR][320];
        double p0[RC_FIT_MAX_PAR];
        for (int j = 0; j < fp->np; j++) p0[j] = fp->par[j].start;
        const int nset = build_set(fp, p0, set, buf);
        rc_case *c = NULL;
        rc_model *m = NULL;
        rc_error e;
        memset(&e, 0, sizeof e);
        rc_status st = rc_case_load_set(fp->deck, set, nset, &c, &e);
        if (!st) st = rc_model_compile(c, &m, &e);
        if (!st && fp->rtol > 0) st = rc_model_set_rtol(m, fp->rtol, &e);
        if (!st && fp->method > 0) st = rc_model_set_method(m, fp->method, &e);
        if (st) {
            fprintf(stderr, "ricochet fit: %s: %s\n%s", rc_status_str(e.code), e.msg,
                    !strncmp(e.msg, "--set ", 6) ? "ricochet fit: (the start values of --free and --log are read "
                                                   "as --set overrides)\n" : "");
            rc = rc_status_exit_code(st);
        }
        for (int k = 0; k < fp->ns && !rc; k++) {
            if (rc_model_body_index(m, fp->sig[k].body) == -2) {
                fprintf(stderr, "ricochet fit: %s: column %d (%s): the deck has no /RBODY/%d\n", fp->data, k + 2,
                        fp->sig[k].label, fp->sig[k].body);
                rc = 2;
            }
        }
        rc_model_free(m);
        rc_case_free(c);
        if (rc) goto done;
    }

    {
        const double t0 = wall_now();
        const size_t n = (size_t)fp->nres, p = (size_t)fp->np;
        gsl_multifit_nlinear_fdf fdf;
        gsl_multifit_nlinear_parameters fpar = gsl_multifit_nlinear_default_parameters();
        fpar.trs = fp->trs == 1   ? gsl_multifit_nlinear_trs_lm
                   : fp->trs == 2 ? gsl_multifit_nlinear_trs_dogleg
                   : fp->trs == 3 ? gsl_multifit_nlinear_trs_subspace2D
                                  : gsl_multifit_nlinear_trs_ddogleg;
        fdf.f = fit_f;
        fdf.df = fp->sens ? fit_df_sens : fit_df;
        fdf.fvv = NULL;
        fdf.n = n;
        fdf.p = p;
        fdf.params = fp;
        gsl_multifit_nlinear_workspace *w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fpar, n, p);
        gsl_vector *x0 = gsl_vector_alloc(p);
        gsl_matrix *covar = gsl_matrix_alloc(p, p);
        double *sim = malloc(sim_len(fp) * sizeof *sim);
        double *r = malloc(n * sizeof *r);
        if (!w || !x0 || !covar || !sim || !r) {
            fprintf(stderr, "ricochet fit: out of memory\n");
            rc = 5;
            goto free_fit;
        }
        /* the simulation at the start must run */
        double u0[RC_FIT_MAX_PAR];
        for (int j = 0; j < fp->np; j++) u0[j] = par_u0(&fp->par[j]);
        if (residuals(fp, u0, r, sim)) {
            fprintf(stderr, "ricochet fit: the simulation at the start values failed: %s\n", fp->first_failure);
            rc = 3;
            goto free_fit;
        }
        for (int j = 0; j < fp->np; j++) gsl_vector_set(x0, (size_t)j, u0[j]);
        gsl_multifit_nlinear_init(x0, &fdf, w);
        /* the integrator's warnings of the trial simulations (a trial far
         * from the answer may be hard to integrate) are not shown: the
         * library's stderr goes to /dev/null during the iterations, the
         * progress lines to the program's own */
        fflush(stderr);
        const int saved = dup(2), devnull = open("/dev/null", O_WRONLY);
        if (saved >= 0 && devnull >= 0 && (fp->progress = fdopen(saved, "w")) != NULL) dup2(devnull, 2);
        if (devnull >= 0) close(devnull);
        int info = 0;
        int gst = gsl_multifit_nlinear_driver((size_t)max_iter, 1e-8, 1e-8, 1e-12, fit_callback, fp, &info, w);
        char status[512];
        if (gst == GSL_SUCCESS)
            snprintf(status, sizeof status, "converged (%s)",
                     info == 1 ? "small step" : info == 2 ? "small gradient" : "small change of the cost");
        else if (gst == GSL_EMAXITER)
            snprintf(status, sizeof status, "NOT CONVERGED within %d iterations (--max-iter)", max_iter);
        else if (gst == GSL_ENOPROG)
            snprintf(status, sizeof status, "converged (no further decrease of the cost found)");
        else
            snprintf(status, sizeof status, "stopped: %.100s%s%.300s", gsl_strerror(gst), fp->first_failure[0] ? "; " : "",
                     fp->first_failure);
        const int ok = gst == GSL_SUCCESS || gst == GSL_ENOPROG;
        /* statistics at the solution */
        gsl_matrix *J = gsl_multifit_nlinear_jac(w);
        gsl_vector *xs = gsl_multifit_nlinear_position(w);
        gsl_vector *fs = gsl_multifit_nlinear_residual(w);
        fit_stats S;
        memset(&S, 0, sizeof S);
        double chi2;
        gsl_blas_ddot(fs, fs, &chi2);
        gsl_multifit_nlinear_covar(J, RC_FIT_RANK_TOL, covar);
        double colmax = 0, col[RC_FIT_MAX_PAR], dpdu[RC_FIT_MAX_PAR];
        for (size_t j = 0; j < p; j++) {
            gsl_vector_view cj = gsl_matrix_column(J, j);
            col[j] = gsl_blas_dnrm2(&cj.vector);
            colmax = fmax(colmax, col[j]);
        }
        /* degrees of freedom: the measured values less the rank of J (the
         * parameters the data do not see take none) */
        int rank = 0;
        for (size_t j = 0; j < p; j++) rank += gsl_matrix_get(covar, j, j) > 0 && col[j] > RC_FIT_COLUMN_TOL * colmax;
        S.dof = (int)n - rank;
        S.rms_all = sqrt(chi2 / (double)n);
        S.tq = gsl_cdf_tdist_Pinv(0.975, (double)S.dof);
        const double s2 = chi2 / (double)S.dof;
        for (size_t j = 0; j < p; j++) {
            S.p[j] = par_value(&fp->par[j], gsl_vector_get(xs, j), &dpdu[j]);
            const double cu = gsl_matrix_get(covar, j, j);
            S.se[j] = fabs(dpdu[j]) * sqrt(fmax(cu, 0.0) * s2);
            S.rse[j] = S.p[j] != 0 ? S.se[j] / fabs(S.p[j]) : INFINITY;
            const double th = tanh(gsl_vector_get(xs, j));
            if (fp->par[j].bounded && 1.0 - th * th < RC_FIT_AT_BOUND) S.unident[j] = 4;
            else if (!(col[j] > RC_FIT_COLUMN_TOL * colmax)) S.unident[j] = 1;
            else if (!(cu > 0)) S.unident[j] = 2;
            else if (!(S.rse[j] <= max_rse)) S.unident[j] = 3;
            S.lo95[j] = S.p[j] - S.tq * S.se[j];
            S.hi95[j] = S.p[j] + S.tq * S.se[j];
        }
        for (size_t a = 0; a < p; a++)
            for (size_t b = 0; b < p; b++) {
                const double caa = gsl_matrix_get(covar, a, a), cbb = gsl_matrix_get(covar, b, b);
                S.corr[a][b] = caa > 0 && cbb > 0 ? gsl_matrix_get(covar, a, b) / sqrt(caa * cbb) : NAN;
            }
        /* the signals at the solution, for the report and the CSV */
        double ufin[RC_FIT_MAX_PAR];
        for (size_t j = 0; j < p; j++) ufin[j] = gsl_vector_get(xs, j);
        const rc_status fin = residuals(fp, ufin, r, sim);
        /* the program's stderr back */
        if (fp->progress) {
            fflush(fp->progress);
            dup2(fileno(fp->progress), 2);
            fclose(fp->progress);
            fp->progress = NULL;
        } else if (saved >= 0) {
            close(saved);
        }
        if (fin) {
            fprintf(stderr, "ricochet fit: the simulation at the fitted values failed: %s\n", fp->first_failure);
            rc = 3;
            goto free_fit;
        }
        const double wall = wall_now() - t0;
        const int nth = fp->jobs < (fp->central ? 2 * fp->np : fp->np + 1) ? fp->jobs
                                                                         : (fp->central ? 2 * fp->np : fp->np + 1);
        print_report(stdout, fp, &S, sim, gsl_multifit_nlinear_niter(w), fdf.nevalf, fdf.nevaldf, wall, status,
                     max_rse, nth);
        if (report) {
            FILE *o = fopen(report, "w");
            if (!o) {
                fprintf(stderr, "ricochet fit: %s: cannot write the report (%s)\n", report, strerror(errno));
                rc = 4;
                goto free_fit;
            }
            print_report(o, fp, &S, sim, gsl_multifit_nlinear_niter(w), fdf.nevalf, fdf.nevaldf, wall, status,
                         max_rse, nth);
            if (fclose(o) != 0) {
                fprintf(stderr, "ricochet fit: %s: write error\n", report);
                rc = 4;
                goto free_fit;
            }
        }
        if (json && (rc = write_json(json, fp, &S, sim, gsl_multifit_nlinear_niter(w), fdf.nevalf, fdf.nevaldf, wall,
                                     status, ok)) != 0)
            goto free_fit;
        rc = write_fitted(fitted, fp, sim);
        if (rc == 0) {
            printf("measured against fitted signals: %s\n", fitted);
            rc = ok ? 0 : 1;
        }
    free_fit:
        free(r);
        free(sim);
        gsl_matrix_free(covar);
        gsl_vector_free(x0);
        if (w) gsl_multifit_nlinear_free(w);
    }
    pthread_mutex_destroy(&fp->lock);
done:
    free(fp->t);
    free(fp->meas);
    return rc;
}
