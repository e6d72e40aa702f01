/*
 * The extended pattern of a constraint set (xpattern.h).
 */
#include <stdlib.h>

#include "engine/constraints/xpattern.h"

int64_t *rc_xpat_build(const rc_model *m, int n, int nblk, int maxb, rc_xblock_fn block, const void *ctx,
                       const int64_t *badr, int64_t *colptr, int64_t *nnz, int64_t *mslot, int64_t *diag,
                       int64_t *bslot)
{
    int *rows = malloc(2 * ((size_t)maxb + 1) * sizeof *rows), *cols = rows ? rows + maxb + 1 : NULL;
    int64_t *key = malloc(((size_t)m->nnz + (size_t)n + (size_t)nblk * (size_t)maxb * (size_t)maxb + 1) * sizeof *key);
    if (!rows || !key) {
        free(rows);
        free(key);
        return NULL;
    }
    /* entries: the model's, the diagonal, the blocks */
    int64_t nk = 0;
    for (int c = 0; c < m->ny; c++)
        for (int64_t k = m->jac_colptr[c]; k < m->jac_colptr[c + 1]; k++) key[nk++] = (int64_t)c * n + m->jac_rowind[k];
    for (int c = 0; c < n; c++) key[nk++] = (int64_t)c * n + c;
    for (int b = 0; b < nblk; b++) {
        int nr, nc;
        block(m, ctx, b, rows, &nr, cols, &nc);
        for (int r = 0; r < nr; r++)
            for (int c = 0; c < nc; c++) key[nk++] = (int64_t)cols[c] * n + rows[r];
    }
    int64_t *rowind = rc_csc_from_keys(key, nk, n, colptr, nnz);
    free(key);
    if (rowind) {
        for (int c = 0; c < m->ny; c++)
            for (int64_t k = m->jac_colptr[c]; k < m->jac_colptr[c + 1]; k++)
                mslot[k] = rc_csc_slot(colptr, rowind, m->jac_rowind[k], c);
        for (int c = 0; c < n; c++) diag[c] = rc_csc_slot(colptr, rowind, c, c);
        for (int b = 0; b < nblk; b++) {
            int nr, nc;
            block(m, ctx, b, rows, &nr, cols, &nc);
            for (int r = 0; r < nr; r++)
                for (int c = 0; c < nc; c++) bslot[badr[b] + r * nc + c] = rc_csc_slot(colptr, rowind, rows[r], cols[c]);
        }
    }
    free(rows);
    return rowind;
}
