/*
 * The integrator's Newton matrix as a part of the model's Jacobian pattern
 * (subpat.h).
 */
#include <stdlib.h>
#include <string.h>

#include "solver/subpat.h"

void rc_subpat_free(rc_subpat *s)
{
    free(s->colptr);
    free(s->rowind);
    free(s->diag);
    free(s->map);
    memset(s, 0, sizeof *s);
}

/* *p holds at least n + 1 values (*cap counts them; grown, never shrunk). */
static int grow(int64_t **p, int64_t n, int64_t *cap)
{
    if (*p && n <= *cap) return 0;
    int64_t *q = realloc(*p, ((size_t)n + 1) * sizeof(int64_t));
    if (!q) return -1;
    *p = q;
    *cap = n;
    return 0;
}

int rc_subpat_reserve(rc_subpat *s, int n, int64_t nnz)
{
    if (grow(&s->map, nnz, &s->cap_map) || grow(&s->rowind, nnz, &s->cap)) return -1;
    if (s->colptr && s->diag && n <= s->cap_n) return 0;
    int64_t *cp = realloc(s->colptr, ((size_t)n + 1) * sizeof *cp);
    if (!cp) return -1;
    s->colptr = cp;
    int64_t *dg = realloc(s->diag, ((size_t)n + 1) * sizeof *dg);
    if (!dg) return -1;
    s->diag = dg;
    s->cap_n = n;
    return 0;
}

int rc_subpat_build(rc_subpat *s, int nfull, const int64_t *colptr, const int64_t *rowind, const int *idx,
                    const unsigned char *keep)
{
    const int64_t nz = colptr[nfull];
    int n = 0, last = -1;
    for (int i = 0; i < nfull; i++) {
        const int r = idx ? idx[i] : i;
        if (r < 0) continue;
        if (r <= last) return -2;
        last = r;
        n++;
    }
    /* the map and the column pointers are sized by the whole pattern and
     * the part's state count; the row indices by the kept entries */
    if (rc_subpat_reserve(s, n, 0) || grow(&s->map, nz, &s->cap_map)) return -1;
    int64_t cnt = 0;
    for (int j = 0; j < nfull; j++) {
        const int cj = idx ? idx[j] : j;
        for (int64_t k = colptr[j]; k < colptr[j + 1]; k++) {
            const int ri = idx ? (cj >= 0 ? idx[rowind[k]] : -1) : (int)rowind[k];
            s->map[k] = ri >= 0 && (!keep || keep[k] || rowind[k] == j) ? cnt++ : -1;
        }
    }
    if (grow(&s->rowind, cnt, &s->cap)) return -1;
    s->n = n;
    s->nnz = cnt;
    int c = 0;
    s->colptr[0] = 0;
    for (int j = 0; j < nfull; j++) {
        const int cj = idx ? idx[j] : j;
        if (cj < 0) continue;
        s->diag[c] = -1;
        int64_t end = s->colptr[c];
        for (int64_t k = colptr[j]; k < colptr[j + 1]; k++) {
            if (s->map[k] < 0) continue;
            const int ri = idx ? idx[rowind[k]] : (int)rowind[k];
            s->rowind[s->map[k]] = ri;
            if (ri == cj) s->diag[c] = s->map[k];
            end++;
        }
        if (s->diag[c] < 0) return -2;
        s->colptr[++c] = end;
    }
    return 0;
}

void rc_subpat_gather(const rc_subpat *s, int64_t nnz_full, double a, const double *whole, double *part)
{
    const int64_t *map = s->map;
    for (int64_t k = 0; k < nnz_full; k++)
        if (map[k] >= 0) part[map[k]] = a * whole[k];
}
