/*
 * The extended sparse pattern of a constraint set (cset.h): the model's
 * Jacobian pattern over y, the whole diagonal of Y[0 .. n), and the set's
 * dense blocks, in CSC with sorted row indices; the slots of the model's
 * entries, of the diagonal and of each block's entries. One builder for
 * every set (joints.c, stick.c).
 */
#ifndef RC_ENGINE_XPATTERN_H
#define RC_ENGINE_XPATTERN_H

#include <stdint.h>

#include "model/model.h"

/* Block b of a set: its rows into rows[], its columns into cols[] (at most
 * the builder's maxb each), their counts returned in *nrow, *ncol. */
typedef void (*rc_xblock_fn)(const rc_model *m, const void *ctx, int b, int *rows, int *nrow, int *cols, int *ncol);

/* The pattern over Y[0 .. n) with nblk blocks of at most maxb rows and
 * columns: colptr[n + 1] (zeroed by the caller) filled, the row indices
 * returned (malloc'd; NULL: out of memory), their count in *nnz; the
 * slots into mslot[m->nnz] (the model's entries), diag[n] and bslot
 * (block b's entry (r, c) at badr[b] + r * ncol + c). */
int64_t *rc_xpat_build(const rc_model *m, int n, int nblk, int maxb, rc_xblock_fn block, const void *ctx,
                       const int64_t *badr, int64_t *colptr, int64_t *nnz, int64_t *mslot, int64_t *diag,
                       int64_t *bslot);

#endif
