/* The model's Jacobian pattern as data: the CSC position of an entry, and
 * the release of the pattern and of the element slots. The pattern is
 * built by probing the kernels (engine/analyses/jacpattern.c). */
#include <stdlib.h>

#include "model/coupling.h"
#include "model/model.h"

int64_t rc_csc_slot(const int64_t *colptr, const int64_t *rowind, int64_t row, int64_t col)
{
    int64_t lo = colptr[col], hi = colptr[col + 1] - 1;
    while (lo <= hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (rowind[mid] == row) return mid;
        if (rowind[mid] < row) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

int rc_cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

int64_t *rc_csc_from_keys(int64_t *key, int64_t nk, int64_t n, int64_t *colptr, int64_t *nnz)
{
    qsort(key, (size_t)nk, sizeof *key, rc_cmp_i64);
    int64_t u = 0;
    for (int64_t k = 0; k < nk; k++)
        if (u == 0 || key[k] != key[u - 1]) key[u++] = key[k];
    *nnz = u;
    int64_t *rowind = malloc((size_t)u * sizeof *rowind + sizeof *rowind);
    if (!rowind) return NULL;
    for (int64_t k = 0; k < u; k++) {
        rowind[k] = key[k] % n;
        colptr[key[k] / n + 1]++;
    }
    for (int64_t c = 0; c < n; c++) colptr[c + 1] += colptr[c];
    return rowind;
}

int64_t rc_jac_slot(const rc_model *m, int row, int col)
{
    return rc_csc_slot(m->jac_colptr, m->jac_rowind, row, col);
}

void rc_jac_free(rc_model *m)
{
    if (m->jb_body)
        for (int b = 0; b < m->nbody; b++) free(m->jb_body[b].slot);
    if (m->jb_inter)
        for (int i = 0; i < m->ninter; i++) free(m->jb_inter[i].slot);
    if (m->inter_ptslot)
        for (int i = 0; i < m->ninter; i++) {
            free(m->inter_ptslot[i]);
            m->inter_ptslot[i] = NULL;
        }
    if (m->cpl)
        for (int k = 0; k < m->cpl->n; k++) {
            free(m->cpl->jb[k].slot);
            m->cpl->jb[k].slot = NULL;
        }
    free(m->jb_body);
    free(m->jb_inter);
    free(m->jac_colptr);
    free(m->jac_rowind);
    free(m->jac_diag);
    m->jb_body = m->jb_inter = NULL;
    m->jac_colptr = m->jac_rowind = m->jac_diag = NULL;
}
