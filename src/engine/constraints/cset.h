/*
 * The constraint sets of the DAE path (docs/theory.md, "IDA backend"): a
 * set adds extra unknowns after the model's states in the integrator's
 * vector Y = [y, extras of set 1, extras of set 2, ...] and their rows to
 * the residual. Each set is one file of this room and one table of
 * operations (rc_cset_ops: joints.c, stick.c); the sets a model needs are
 * composed here (cset.c), so that the backend sees one set whatever the
 * model holds: one extended pattern, one residual, one Jacobian, one
 * consistent restart.
 */
#ifndef RC_ENGINE_CSET_H
#define RC_ENGINE_CSET_H

#include <stdint.h>

#include "model/model.h"
#include "engine/assembly/data.h"

/* What a constraint set gives. `w` is the set's work (its pattern and
 * scratch), made by `open` with its extras from Y[base] on. */
typedef struct rc_cset_ops {
    const char *what;    /* for the integrator's line: "joints: stabilised index-2 constraints (GGL)" */
    const char *start_failed; /* the message when its rows are dependent at t = 0 */
    int (*needed)(const rc_model *m);
    /* the work, its extras from Y[base] on; NULL: out of memory (or a base
     * the set does not support) */
    void *(*open)(const rc_model *m, int base);
    void (*close)(void *w);
    int (*nextra)(const void *w);
    /* the extended pattern over Y[0 .. base + nextra) (CSC), its entries */
    int64_t (*nnz)(const void *w);
    void (*pattern)(const void *w, const int64_t **colptr, const int64_t **rowind);
    double (*atol)(const rc_model *m, const void *w, int k); /* of extra k */
    void (*id)(const rc_model *m, const void *w, double *id); /* IDA's id: 1 on y, its extras' */
    /* the rows: adds the set's terms to the bodies' rows r[0..ny) (r = y' - f
     * there) and writes its own rows; pure */
    void (*residual)(const rc_model *m, const rc_data *d, const void *w, const double *Y, const double *Yp,
                     double *r);
    /* dF/dY + cj dF/dY' on its extended pattern, the model's block cj I - J_f
     * included, from the model's Jacobian values jf */
    void (*jacobian)(const rc_model *m, const rc_data *d, const void *w, double cj, const double *Y,
                     const double *Yp, const double *jf, double *val);
    /* the slots of its extended pattern that can be nonzero in d's modes from
     * the model's active slots (NULL: the set gives none; the Newton matrix
     * is then the whole pattern) */
    void (*keep)(const rc_model *m, const rc_data *d, const void *w, const unsigned char *keep, unsigned char *ext);
    /* the velocities in Y made to satisfy the set's rows (the change of
     * least kinetic energy), and what the stretch from here fixes; 0, or -1
     * (dependent rows) */
    int (*project)(const rc_model *m, rc_data *d, void *w, double *Y);
    int project_at_restart; /* 1: at every restart; 0: at the start only */
    /* with Yp[0..ny) holding the rates (f and the other sets'
     * accelerations): its multipliers into Yp and its accelerations added
     * to Yp[0..ny); 0, or -1 (dependent rows) */
    int (*multipliers)(const rc_model *m, void *w, double *Y, double *Yp);
    /* its root functions into the engine's layout g (NULL: none) */
    void (*roots)(const rc_model *m, rc_data *d, void *w, double t, const double *Y, const double *Yp, double *g);
    /* a record vector: its extras of Yrec (a copy of Y) as the output reads
     * them, and what d keeps of them (NULL: Y's) */
    void (*record)(const rc_model *m, rc_data *d, void *w, double t, const double *Y, const double *Yp,
                   double *Yrec);
    /* before the events of a root return, on the integrator's state (NULL: nothing) */
    void (*before_events)(const rc_model *m, const rc_data *d, void *w, double *Y, const double *Yp);
} rc_cset_ops;

/* The sets, in the order of their extras in Y (the joints first: their
 * extras start at ny). */
extern const rc_cset_ops rc_jnt_set_ops, rc_stk_set_ops;

typedef struct rc_cset rc_cset;
/* Does the model need a constraint set (the IDA path's extended vector)? */
int rc_cset_needed(const rc_model *m);
/* The sets the model needs, composed; NULL when it needs none or out of
 * memory (rc_cset_needed tells them apart). */
rc_cset *rc_cset_new(const rc_model *m);
void rc_cset_free(rc_cset *c);
/* The work of one set of the composition (NULL: not in it). */
void *rc_cset_part(const rc_cset *c, const rc_cset_ops *ops);
/* "joints: ...; exact stick: ..." for the integrator's line. */
const char *rc_cset_what(const rc_cset *c);
/* The message when the rows are dependent at t = 0. */
const char *rc_cset_start_failed(const rc_cset *c);
int rc_cset_nextra(const rc_cset *c);
int64_t rc_cset_nnz(const rc_cset *c);
void rc_cset_pattern(const rc_cset *c, const int64_t **colptr, const int64_t **rowind);
double rc_cset_atol(const rc_model *m, const rc_cset *c, int k);
void rc_cset_id(const rc_model *m, const rc_cset *c, double *id);
void rc_cset_residual(const rc_model *m, const rc_data *d, const rc_cset *c, const double *Y, const double *Yp,
                      double *r);
void rc_cset_jacobian(const rc_model *m, const rc_data *d, const rc_cset *c, double cj, const double *Y,
                      const double *Yp, const double *jf, double *val);
/* Can the Newton matrix be the active part of the extended pattern (one
 * set that gives its active slots)? */
int rc_cset_keeps(const rc_cset *c);
void rc_cset_keep(const rc_model *m, const rc_data *d, const rc_cset *c, const unsigned char *keep,
                  unsigned char *ext);
/* The consistent (re)start at (t, Y): the velocities made to satisfy every
 * set's rows, Yp[0..ny) = f plus the sets' accelerations and the
 * multipliers of all sets solved together. `start`: the start of the run
 * (every set projects its velocities; at a restart those with
 * project_at_restart). 0; -1 when the rows are dependent; -2 when f cannot
 * be evaluated. */
int rc_cset_consistent(const rc_model *m, rc_data *d, rc_cset *c, double t, double *Y, double *Yp, int start);
void rc_cset_roots(const rc_model *m, rc_data *d, const rc_cset *c, double t, const double *Y, const double *Yp,
                   double *g);
/* The record vector of (Y, Y') into Yrec [ny + nextra]. */
void rc_cset_record(const rc_model *m, rc_data *d, const rc_cset *c, double t, const double *Y, const double *Yp,
                    double *Yrec);
void rc_cset_before_events(const rc_model *m, const rc_data *d, const rc_cset *c, double *Y, const double *Yp);

/* Can interface i (exact stick, closed, in d sticking) stick at (t, y)?
 * 0: yes; 1: no, it must slide along the unit direction e (the force's on
 * a): its sliding velocity is not zero (e = -v_t / |v_t|), or the force
 * that holds it (the multipliers of all sticking exact contacts, solved
 * with every other set of the model) lies beyond the static limit (e along
 * that force). -1: out of memory or dependent rows (then it slides along
 * -v_t, or keeps F_t's direction). */
int rc_stk_decide(const rc_model *m, rc_data *d, int i, double t, const double *y, double e[3]);

#endif
