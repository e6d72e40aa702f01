/* The elastic energy of an interface's normal law at a state of the law
 * (docs/theory.md 4): the load curve's integral (Iform 0, the power law)
 * or the unloading path of Iform 1, 2, and that path's first Stiff line
 * (the law's dissipation rate, 2.7). Functions of the model's curves
 * alone: the kernels (assemble_rhs.c) and the ledger (energy.c) both
 * read them. */
#include <math.h>

#include "model/model.h"
#include "model/power.h"
#include "model/table.h"
#include "engine/assembly/assembly.h"

/* The curves of interface i's law, scaled: F(x) = fscale f(x / Ascalex). */
typedef struct {
    const rc_table *t; /* NULL: none (0) */
    double fs, ax;
} scurve;

static double sc_value(const scurve *c, double x)
{
    return c->t ? c->fs * rc_table_value(c->t, x / c->ax) : 0.0;
}

/* The largest breakpoint of curve c strictly inside (lo, hi), or lo. */
static double sc_break_below(const scurve *c, double lo, double hi)
{
    double b = lo;
    if (!c->t) return b;
    for (int k = 0; k < c->t->n; k++) {
        const double x = c->t->x[k] * c->ax;
        if (x > b && x < hi) b = x;
    }
    return b;
}

/* Energy recovered by unloading interface i (Iform 1, 2) completely from
 * penetration P at elastic force F along its law: the Stiff line, held
 * below the load curve (where the load curve falls faster than the line,
 * the law follows it: branch LOAD, a hyst_load_curve event) and above the
 * unload curve or zero (once met the law follows it: branch UNLOAD) [J].
 * The curves are piecewise linear, so the path is too: exact, interval by
 * interval between their breakpoints and the path's switching points.
 * With `line`, the walk stops where the first Stiff line of the path ends
 * and line[0] is that line's length Delta in P [m] (0 where the path
 * starts on a curve): dE/dF at constant P, for the law's dissipation rate;
 * line[1], line[2] its derivatives by P and by F (the end P* moves along
 * the curve the line meets, of slope c: dP* = (dF - Stiff dP) / (c -
 * Stiff); not at P = 0). */
static double unload_path(const rc_model *m, int i, double P, double F, double *line)
{
    const double ax = m->inter_ascalex[i], k = m->inter_stiff[i];
    const scurve L = {&m->table[m->inter_fct_ld[i]], m->inter_fscaleld[i], ax};
    const scurve U = {m->inter_fct_ul[i] >= 0 ? &m->table[m->inter_fct_ul[i]] : NULL, m->inter_fscaleul[i], ax};
    enum { LINE, LOAD, UNLOAD } st = LINE;
    double x = P, E = 0.0, cend = INFINITY; /* the slope the first line ends on */
    const double fl0 = sc_value(&L, P), fu0 = fmax(sc_value(&U, P), 0.0);
    F = fmin(fmax(F, fu0), fl0);
    if (F <= fu0) st = UNLOAD;
    for (int guard = 0; x > 0 && guard < 100000; guard++) {
        if (line && st != LINE) break;
        /* the interval [a, x]: both curves linear on it */
        double a = fmax(sc_break_below(&L, 0.0, x), sc_break_below(&U, 0.0, x));
        const double fux = sc_value(&U, x);
        double fua = sc_value(&U, a);
        /* the floor max(F_U, 0) is linear on [a, x] after a split where F_U
         * crosses zero */
        if (U.t && (fux > 0) != (fua > 0) && fux != fua) {
            const double z = x - fux * (x - a) / (fux - fua);
            if (z > a && z < x) {
                a = z;
                fua = sc_value(&U, a);
            }
        }
        const double flx = sc_value(&L, x), fla = sc_value(&L, a), sL = (flx - fla) / (x - a);
        const double sU = (fux - fua) / (x - a);
        const double flo_x = fmax(fux, 0.0), sF = fux > 0 || fua > 0 ? sU : 0.0;
        if (st == UNLOAD) { /* along the floor to a */
            E += 0.5 * (flo_x + fmax(sc_value(&U, a), 0.0)) * (x - a);
            x = a;
            continue;
        }
        if (st == LOAD) {
            if (sL >= k) { /* the load curve falls at least as fast as the line: on it to a */
                E += 0.5 * (flx + fla) * (x - a);
                F = fla;
                x = a;
                continue;
            }
            st = LINE;
            F = flx;
        }
        /* on the line F - k (x - s): the first of meeting the load curve
         * (when it falls slower) and the floor (when it falls faster) */
        double s = a;
        int next = LINE;
        if (k < sL) {
            const double d = (F - flx) / (k - sL); /* F - flx <= 0 */
            if (x - d > s) {
                s = x - d;
                next = LOAD;
            }
        }
        if (k > sF) {
            const double d = (F - flo_x) / (k - sF); /* F - floor >= 0 */
            if (x - d > s) {
                s = x - d;
                next = UNLOAD;
            }
        }
        const double Fs = F - k * (x - s);
        E += 0.5 * (F + Fs) * (x - s);
        F = Fs;
        x = s;
        if (next != LINE) {
            st = next;
            cend = next == LOAD ? sL : sF;
        }
    }
    if (line) {
        line[0] = P - x;
        line[1] = line[2] = 0.0;
        if (line[0] > 0 && isfinite(cend)) {
            line[1] = cend / (cend - k);
            line[2] = 1.0 / (k - cend);
        } else if (line[0] > 0) {
            line[1] = 1.0; /* the line reaches P = 0 */
        }
    }
    return E;
}

double rc_inter_path_energy(const rc_model *m, int i, double P, double F)
{
    if (!(P > 0)) return 0.0;
    if (m->inter_law[i] == RC_LAW_POWER || m->inter_iform[i] == 0) return rc_inter_law_energy(m, i, P);
    return F > 0 ? unload_path(m, i, P, F, NULL) : 0.0;
}

double rc_inter_unload_line(const rc_model *m, int i, double P, double F, double *dP, double *dF)
{
    double line[3] = {0.0, 0.0, 0.0};
    if (P > 0 && F > 0) unload_path(m, i, P, F, line);
    *dP = line[1];
    *dF = line[2];
    return line[0];
}

double rc_inter_law_energy(const rc_model *m, int i, double P)
{
    if (!(P > 0)) return 0.0;
    if (m->inter_law[i] == RC_LAW_POWER) return rc_power_stored(m, i, P); /* integral of F_k */
    const double ax = m->inter_ascalex[i];
    return m->inter_fscaleld[i] * ax * rc_table_integral(&m->table[m->inter_fct_ld[i]], 0.0, P / ax);
}
