/*
 * The integrator's Newton matrix as a part of the model's Jacobian pattern
 * (model.h jac_colptr / jac_rowind): the rows and columns of the states the
 * integrator carries (the others renumbered out), and of their entries only
 * those kept. The model and the engine keep writing the whole pattern's
 * values; a backend gathers the kept ones through `map`.
 */
#ifndef RC_SUBPAT_H
#define RC_SUBPAT_H

#include <stdint.h>

typedef struct rc_subpat {
    int n;           /* rows = columns of the part */
    int64_t nnz;     /* its entries */
    int64_t *colptr; /* [n + 1] CSC, rows ascending in each column */
    int64_t *rowind; /* [nnz] */
    int64_t *diag;   /* [n] slot of each diagonal entry (always kept) */
    int64_t *map;    /* [nnz of the whole] slot in the part, -1: dropped */
    int64_t cap;     /* entries allocated in rowind */
    int64_t cap_map; /* entries allocated in map */
    int cap_n;       /* columns allocated in colptr (+ 1) and diag */
} rc_subpat;

/* Allocate for parts of up to n states and nnz entries of a whole pattern
 * of nnz entries, so that later builds of such parts allocate nothing
 * (a backend's Newton matrix rebuilt in its linear-system callback).
 * Returns 0 or -1 out of memory. */
int rc_subpat_reserve(rc_subpat *s, int n, int64_t nnz);
/* Build (or rebuild in place: the arrays are grown when too small) the
 * part of the nfull x nfull pattern (colptr, rowind) with the states
 * idx[i] >= 0 renumbered to idx[i] (increasing in i; NULL: all, in order)
 * and the entries with keep[k] != 0 (NULL: all); a kept state's diagonal
 * is kept whatever keep says. Returns 0, -1 out of memory (the part is then
 * unusable: rc_subpat_free it), -2 when idx is not increasing or the whole
 * pattern lacks a kept state's diagonal. */
int rc_subpat_build(rc_subpat *s, int nfull, const int64_t *colptr, const int64_t *rowind, const int *idx,
                    const unsigned char *keep);
void rc_subpat_free(rc_subpat *s);

/* part[map[k]] = a whole[k] for the kept entries (the part's values of
 * a * whole); nnz_full: the whole pattern's entries. */
void rc_subpat_gather(const rc_subpat *s, int64_t nnz_full, double a, const double *whole, double *part);

#endif
