/* The model's Jacobian pattern as data: the CSC position of an entry, and
 * the release of the pattern and of the element slots. The pattern is
 * built by probing the kernels (engine/jacpattern.c). */
#include <stdlib.h>

#include "model/coupling.h"
#include "model/model.h"

int64_t rc_jac_slot(const rc_model *m, int row, int col)
{
    int64_t lo = m->jac_colptr[col], hi = m->jac_colptr[col + 1] - 1;
    while (lo <= hi) {
        int64_t mid = lo + (hi - lo) / 2;
        if (m->jac_rowind[mid] == row) return mid;
        if (m->jac_rowind[mid] < row) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
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
