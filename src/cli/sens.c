/*
 * ricochet sens: the derivatives of body positions and velocities at given
 * times with respect to numeric deck fields addressed as by --set, by
 * forward sensitivity analysis (rc_sens_run; docs/calibration.md
 * "Sensitivities").
 *
 * Design
 *  - A parameter CARD:FIELD=VALUE is evaluated at VALUE (card units): the
 *    deck is compiled three times per parameter, at VALUE and at VALUE -+ h
 *    (h = --rel-step x |VALUE|, or --rel-step itself when VALUE is 0), the
 *    values written as the shortest decimals that read back, and the step
 *    dp taken from the numbers read back, so that the derivative is per
 *    card unit of the field exactly.
 *  - The outputs (x, y, z, vx, vy, vz of a body's centre of mass,
 *    rc_model_body_state) and their derivatives are taken from the state
 *    and its sensitivities: d out/dp = central difference of the body's
 *    state along the sensitivity (exact for these linear read-outs).
 *  - --check-fd also runs the deck at VALUE -+ H (H = --fd-step x |VALUE|)
 *    to the output times and prints the central difference of the outputs
 *    of the whole runs beside each sensitivity.
 */
#include "cli/sens.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ricochet/ricochet.h"

#define RC_SENS_MAX_PAR 16
#define RC_SENS_MAX_T 64
#define RC_SENS_MAX_OUT 64
#define RC_SENS_MAX_SET 256
/* default relative steps of the parameters: inside the right-hand side
 * (rc_sens_run's df/dp) and of the whole runs of --check-fd [-] */
#define RC_SENS_REL_STEP 1e-4
#define RC_SENS_FD_STEP 1e-3

static const char *const qname[6] = {"x", "y", "z", "vx", "vy", "vz"};
static const char *const qunit[6] = {"m", "m", "m", "m/s", "m/s", "m/s"};
static const int qslot[6] = {0, 1, 2, 7, 8, 9};

typedef struct {
    char name[256]; /* CARD:FIELD */
    double value;   /* card units */
} sens_par;
typedef struct {
    int body, q;
} sens_out;

static void usage_sens(FILE *f)
{
    fprintf(f,
            "usage: ricochet sens CASE --param CARD:FIELD=VALUE [--param ...] --at T[,T...] [options]\n"
            "The derivatives of body positions and velocities at the times T with respect to numeric fields\n"
            "of the deck (addressed as by --set), by forward sensitivity analysis (CVODES) between the events\n"
            "and the jump of the sensitivities at each event (docs/calibration.md, \"Sensitivities\").\n"
            "The derivatives are per card unit of each field, at VALUE (in the card's units).\n"
            "options:\n"
            "  --param CARD:FIELD=VALUE  a parameter and the value it is evaluated at (at most %d)\n"
            "  --at T[,T...]   output times [s], increasing, > 0 (at most %d); the run ends at the last\n"
            "  --out ID:Q      an output: Q one of x, y, z, vx, vy, vz of the centre of mass of /RBODY ID\n"
            "                  (repeatable; default: the six of every body)\n"
            "  --set CARD:FIELD=VALUE  a fixed override, as for ricochet run\n"
            "  --rel-step H    relative step of the parameters' central difference in the right-hand side\n"
            "                  (default %g; absolute when VALUE is 0)\n"
            "  --check-fd      also the central differences of whole runs at VALUE -+ --fd-step, beside each\n"
            "                  derivative, with their relative difference\n"
            "  --fd-step H     relative step of --check-fd (default %g)\n"
            "exit codes: 0 done, 2 input error, 3 solver failure\n",
            RC_SENS_MAX_PAR, RC_SENS_MAX_T, RC_SENS_REL_STEP, RC_SENS_FD_STEP);
}

/* The shortest decimal of v that reads back as v. */
static void shortest(double v, char *buf, size_t n)
{
    for (int prec = 6; prec <= 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        if (strtod(buf, NULL) == v) return;
    }
}

/* Load and compile the deck with the fixed overrides and parameter j at v
 * (j < 0: every parameter at its value); *used receives v as read back. */
static rc_status compile_at(const char *deck, const char *const *set, int nset, const sens_par *par, int np, int j,
                            double v, double *used, rc_model **m, rc_error *e)
{
    const char *all[RC_SENS_MAX_SET + RC_SENS_MAX_PAR];
    char buf[RC_SENS_MAX_PAR][320];
    int n = 0;
    for (int k = 0; k < nset; k++) all[n++] = set[k];
    for (int k = 0; k < np; k++) {
        char num[64];
        shortest(k == j ? v : par[k].value, num, sizeof num);
        if (k == j && used) *used = strtod(num, NULL);
        snprintf(buf[k], sizeof buf[k], "%s=%s", par[k].name, num);
        all[n++] = buf[k];
    }
    rc_case *c = NULL;
    rc_status st = rc_case_load_set(deck, all, n, &c, e);
    if (!st) st = rc_model_compile(c, m, e);
    rc_case_free(c);
    return st;
}

/* The outputs at the times of a plain run of model m (--check-fd). */
static rc_status run_outputs(const rc_model *m, const double *times, int nt, const sens_out *out, int no,
                             double *val, rc_error *e)
{
    rc_run_options opt;
    memset(&opt, 0, sizeof opt);
    opt.t_end_override = times[nt - 1];
    rc_session *s = NULL;
    rc_status st = rc_session_open(m, &opt, &s, e);
    for (int i = 0; i < nt && !st; i++) {
        st = rc_run_until(s, times[i], e);
        for (int k = 0; k < no && !st; k++) {
            double b[13];
            st = rc_model_body_state(m, rc_session_state(s), out[k].body, b, e);
            val[i * no + k] = b[qslot[out[k].q]];
        }
    }
    if (s) {
        rc_error e2;
        rc_status st2 = rc_session_close(s, NULL, &e2);
        if (!st && st2) {
            st = st2;
            *e = e2;
        }
    }
    return st;
}

static int parse_par(const char *arg, sens_par *p)
{
    const char *colon = strchr(arg, ':'), *eq = strchr(arg, '=');
    char *end = NULL;
    if (arg[0] != '/' || !colon || !eq || eq < colon || eq == colon + 1 || (size_t)(eq - arg) >= sizeof p->name) {
        fprintf(stderr, "ricochet sens: --param %s: expected CARD:FIELD=VALUE (e.g. /INTER/TYPE6/1:Visc=30)\n", arg);
        return 0;
    }
    memcpy(p->name, arg, (size_t)(eq - arg));
    p->name[eq - arg] = '\0';
    errno = 0;
    p->value = strtod(eq + 1, &end);
    if (end == eq + 1 || *end || !isfinite(p->value)) {
        fprintf(stderr, "ricochet sens: --param %s: VALUE: expected a finite number (card units), got '%s'\n", arg,
                eq + 1);
        return 0;
    }
    return 1;
}

static int parse_times(const char *arg, double *t, int *nt)
{
    const char *s = arg;
    while (*s) {
        char *end = NULL;
        const double v = strtod(s, &end);
        if (end == s || !(v > 0) || !isfinite(v) || (*end && *end != ',') || *nt >= RC_SENS_MAX_T ||
            (*nt > 0 && !(v > t[*nt - 1]))) {
            fprintf(stderr, "ricochet sens: --at %s: expected times [s] > 0, increasing, separated by commas "
                            "(at most %d)\n", arg, RC_SENS_MAX_T);
            return 0;
        }
        t[(*nt)++] = v;
        s = *end ? end + 1 : end;
    }
    return *nt > 0;
}

static int parse_out(const char *arg, sens_out *o)
{
    char *end = NULL;
    const long id = strtol(arg, &end, 10);
    if (end != arg && *end == ':') {
        for (int q = 0; q < 6; q++)
            if (!strcmp(end + 1, qname[q])) {
                o->body = (int)id;
                o->q = q;
                return 1;
            }
    }
    fprintf(stderr, "ricochet sens: --out %s: expected ID:Q, Q one of x, y, z, vx, vy, vz (e.g. 1:z)\n", arg);
    return 0;
}

static const char *opt_arg(int argc, char **argv, int *k, const char *name)
{
    const size_t n = strlen(name);
    if (!strncmp(argv[*k], name, n) && argv[*k][n] == '=') return argv[*k] + n + 1;
    if (strcmp(argv[*k], name)) return NULL;
    if (*k + 1 >= argc) {
        fprintf(stderr, "ricochet sens: %s needs a value\n", name);
        return "";
    }
    return argv[++*k];
}

int rc_cli_sens(int argc, char **argv)
{
    sens_par par[RC_SENS_MAX_PAR];
    sens_out out[RC_SENS_MAX_OUT];
    const char *set[RC_SENS_MAX_SET];
    double times[RC_SENS_MAX_T];
    int np = 0, no = 0, nset = 0, nt = 0, check_fd = 0;
    double rel = RC_SENS_REL_STEP, fd = RC_SENS_FD_STEP;
    const char *deck = NULL;
    for (int k = 2; k < argc; k++) {
        const char *a = argv[k], *v;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage_sens(stdout);
            return 0;
        } else if ((v = opt_arg(argc, argv, &k, "--param"))) {
            if (!*v || np >= RC_SENS_MAX_PAR || !parse_par(v, &par[np++])) return 2;
        } else if ((v = opt_arg(argc, argv, &k, "--at"))) {
            if (!*v || !parse_times(v, times, &nt)) return 2;
        } else if ((v = opt_arg(argc, argv, &k, "--out"))) {
            if (!*v || no >= RC_SENS_MAX_OUT || !parse_out(v, &out[no++])) return 2;
        } else if ((v = opt_arg(argc, argv, &k, "--set"))) {
            if (!*v || nset >= RC_SENS_MAX_SET) return 2;
            set[nset++] = v;
        } else if ((v = opt_arg(argc, argv, &k, "--rel-step")) || (v = opt_arg(argc, argv, &k, "--fd-step"))) {
            char *end = NULL;
            const double h = strtod(v, &end);
            if (!*v || *end || !(h > 0) || !(h < 0.5)) {
                fprintf(stderr, "ricochet sens: %s: expected a step in (0, 0.5), got '%s'\n", argv[k - 1], v);
                return 2;
            }
            if (!strcmp(argv[k - 1], "--rel-step") || !strncmp(a, "--rel-step=", 11)) rel = h;
            else fd = h;
        } else if (!strcmp(a, "--check-fd")) {
            check_fd = 1;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "ricochet sens: unknown option '%s'\n", a);
            usage_sens(stderr);
            return 2;
        } else if (!deck) {
            deck = a;
        } else {
            fprintf(stderr, "ricochet sens: one case file expected, got '%s' and '%s'\n", deck, a);
            return 2;
        }
    }
    if (!deck || np == 0 || nt == 0) {
        fprintf(stderr, "ricochet sens: expected CASE, at least one --param and --at\n");
        usage_sens(stderr);
        return 2;
    }
    rc_error e;
    rc_model *m = NULL, *mlo[RC_SENS_MAX_PAR] = {0}, *mhi[RC_SENS_MAX_PAR] = {0};
    double pv[RC_SENS_MAX_PAR], dp[RC_SENS_MAX_PAR];
    double *y = NULL, *s = NULL, *fdv = NULL;
    int rc = 0;
    rc_status st = compile_at(deck, set, nset, par, np, -1, 0.0, NULL, &m, &e);
    for (int j = 0; j < np && !st; j++) {
        const double h = par[j].value != 0.0 ? rel * fabs(par[j].value) : rel;
        double lo = 0, hi = 0;
        pv[j] = par[j].value;
        st = compile_at(deck, set, nset, par, np, j, par[j].value - h, &lo, &mlo[j], &e);
        if (!st) st = compile_at(deck, set, nset, par, np, j, par[j].value + h, &hi, &mhi[j], &e);
        dp[j] = hi - lo;
    }
    if (st) {
        fprintf(stderr, "ricochet sens: %s\n", e.msg);
        rc = rc_status_exit_code(st);
        goto done;
    }
    /* the default outputs: the six of every body */
    if (no == 0)
        for (int b = 0; b < rc_model_body_count(m) && no + 6 <= RC_SENS_MAX_OUT; b++)
            for (int q = 0; q < 6; q++) out[no++] = (sens_out){rc_model_body_id(m, b), q};
    for (int k = 0; k < no; k++) {
        double b[13];
        if (rc_model_body_index(m, out[k].body) < 0) {
            st = rc_model_body_state(m, NULL, out[k].body, b, &e); /* the message lists the ids */
            fprintf(stderr, "ricochet sens: --out %d:%s: %s\n", out[k].body, qname[out[k].q], e.msg);
            rc = 2;
            goto done;
        }
    }
    const int ny = rc_model_state_size(m);
    y = malloc((size_t)nt * (size_t)ny * sizeof(double));
    s = malloc((size_t)nt * (size_t)np * (size_t)ny * sizeof(double));
    if (!y || !s) {
        fprintf(stderr, "ricochet sens: out of memory\n");
        rc = 3;
        goto done;
    }
    rc_sens_info info;
    rc_stats stats;
    /* the events and their times' derivatives */
    enum { MAXEV = 64 };
    double ev_t[MAXEV], ev_dt[MAXEV * RC_SENS_MAX_PAR], ev_vn[MAXEV], ev_dvn[MAXEV * RC_SENS_MAX_PAR];
    int ev_id[MAXEV];
    const char *ev_kind[MAXEV];
    rc_sens_events ev = {MAXEV, 0, 0, ev_t, ev_id, ev_kind, ev_dt, ev_vn, ev_dvn, NULL, NULL};
    st = rc_sens_run(m, np, (const rc_model *const *)mlo, (const rc_model *const *)mhi, pv, dp, nt, times, y, s,
                     &info, &ev, &stats, &e);
    if (st) {
        fprintf(stderr, "ricochet sens: %s\n", e.msg);
        rc = rc_status_exit_code(st);
        goto done;
    }
    /* --check-fd: the outputs of whole runs at VALUE -+ H */
    if (check_fd) {
        fdv = calloc((size_t)np * (size_t)nt * (size_t)no + 1, sizeof(double));
        double *a = malloc((size_t)nt * (size_t)no * sizeof(double) + 1), *b = malloc((size_t)nt * (size_t)no * sizeof(double) + 1);
        for (int j = 0; j < np && !st && fdv && a && b; j++) {
            const double h = par[j].value != 0.0 ? fd * fabs(par[j].value) : fd;
            double lo = 0, hi = 0;
            rc_model *ml = NULL, *mh = NULL;
            st = compile_at(deck, set, nset, par, np, j, par[j].value - h, &lo, &ml, &e);
            if (!st) st = compile_at(deck, set, nset, par, np, j, par[j].value + h, &hi, &mh, &e);
            if (!st) st = run_outputs(ml, times, nt, out, no, a, &e);
            if (!st) st = run_outputs(mh, times, nt, out, no, b, &e);
            for (int k = 0; k < nt * no && !st; k++) fdv[(size_t)j * (size_t)nt * (size_t)no + (size_t)k] = (b[k] - a[k]) / (hi - lo);
            rc_model_free(ml);
            rc_model_free(mh);
        }
        free(a);
        free(b);
        if (st || !fdv) {
            fprintf(stderr, "ricochet sens: --check-fd: %s\n", st ? e.msg : "out of memory");
            rc = st ? rc_status_exit_code(st) : 3;
            goto done;
        }
    }
    printf("ricochet sens: %s: %d parameter%s, %d time%s; %ld events with a jump of the sensitivities (%ld with a "
           "state reset, %ld with simultaneous roots), %ld restarts, %ld steps\n",
           deck, np, np > 1 ? "s" : "", nt, nt > 1 ? "s" : "", info.jumps, info.resets, info.simultaneous,
           info.restarts, stats.steps);
    if (!info.errcon)
        printf("(the run with the sensitivities in the error test failed; these are from a run with the state's error "
               "test alone)\n");
    double *ya = malloc((size_t)ny * sizeof(double)), *yb = malloc((size_t)ny * sizeof(double));
    for (int i = 0; i < nt && ya && yb; i++) {
        const double *yi = y + (size_t)i * (size_t)ny;
        for (int k = 0; k < no; k++) {
            double bs[13];
            rc_model_body_state(m, yi, out[k].body, bs, NULL);
            printf("t = %.9g s  body %d %s = %.12g %s\n", times[i], out[k].body, qname[out[k].q], bs[qslot[out[k].q]],
                   qunit[out[k].q]);
            for (int j = 0; j < np; j++) {
                /* the output's derivative: its central difference along s */
                const double *sj = s + ((size_t)i * (size_t)np + (size_t)j) * (size_t)ny;
                double smax = 0.0, ymax = 1.0;
                for (int r = 0; r < ny; r++) {
                    smax = fmax(smax, fabs(sj[r]));
                    ymax = fmax(ymax, fabs(yi[r]));
                }
                double der = 0.0;
                if (smax > 0) {
                    const double eps = 1e-7 * ymax / smax;
                    double ba[13], bb[13];
                    for (int r = 0; r < ny; r++) {
                        ya[r] = yi[r] + eps * sj[r];
                        yb[r] = yi[r] - eps * sj[r];
                    }
                    rc_model_body_state(m, ya, out[k].body, ba, NULL);
                    rc_model_body_state(m, yb, out[k].body, bb, NULL);
                    der = (ba[qslot[out[k].q]] - bb[qslot[out[k].q]]) / (2.0 * eps);
                }
                printf("    d/d %s = %.9g %s per card unit", par[j].name, der, qunit[out[k].q]);
                if (check_fd) {
                    const double f = fdv[((size_t)j * (size_t)nt + (size_t)i) * (size_t)no + (size_t)k];
                    printf("   (finite difference %.9g, relative difference %.2g)", f,
                           fabs(der - f) / fmax(fabs(f), 1e-300));
                }
                printf("\n");
            }
        }
    }
    free(ya);
    free(yb);
    /* the events: their times and the interfaces' approach rates there */
    if (ev.n > 0)
        printf("events (t [s], the interface's approach rate dP/dt just before [m/s], and their derivatives per card "
               "unit):\n");
    for (int k = 0; k < ev.n; k++) {
        printf("t = %.9g s  %s /INTER %d  dP/dt = %.9g m/s\n", ev.t[k], ev.kind[k], ev.inter_id[k], ev.vn[k]);
        for (int j = 0; j < np; j++)
            printf("    d/d %s: dt = %.9g s, d(dP/dt) = %.9g m/s per card unit\n", par[j].name, ev.dtdp[k * np + j],
                   ev.dvndp[k * np + j]);
    }
    if (ev.more > 0) printf("(%ld more events not listed)\n", ev.more);
done:
    free(y);
    free(s);
    free(fdv);
    rc_model_free(m);
    for (int j = 0; j < np; j++) {
        rc_model_free(mlo[j]);
        rc_model_free(mhi[j]);
    }
    return rc;
}
