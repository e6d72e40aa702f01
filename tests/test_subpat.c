/* The integrator's Newton matrix as a part of the model's pattern
 * (solver/subpat.c): random patterns with a full diagonal, random states
 * renumbered out and random entries dropped, checked entry by entry
 * against the dense matrices they stand for; rebuilding in place; the
 * refusals (indices not increasing, a kept state without its diagonal). */
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "solver/subpat.h"

#define NMAX 40

/* a random CSC pattern over n states with every diagonal present */
static int64_t random_pattern(int n, double density, unsigned *seed, int64_t *cp, int64_t *ri)
{
    int64_t nz = 0;
    for (int j = 0; j < n; j++) {
        cp[j] = nz;
        for (int i = 0; i < n; i++)
            if (i == j || (double)rand_r(seed) / RAND_MAX < density) ri[nz++] = i;
    }
    cp[n] = nz;
    return nz;
}

static void check_part(int n, const int64_t *cp, const int64_t *ri, const int *idx, const unsigned char *keep,
                       const rc_subpat *s, unsigned *seed)
{
    const int64_t nz = cp[n];
    double whole[NMAX * NMAX], part[NMAX * NMAX], dense[NMAX][NMAX], got[NMAX][NMAX];
    for (int64_t k = 0; k < nz; k++) whole[k] = 1.0 + (double)rand_r(seed) / RAND_MAX;
    memset(dense, 0, sizeof dense);
    memset(got, 0, sizeof got);
    int np = 0;
    for (int j = 0; j < n; j++) np += idx[j] >= 0;
    ENSURE(s->n == np);
    /* the dense part: kept states' rows and columns, kept entries and diagonals */
    for (int j = 0; j < n; j++)
        for (int64_t k = cp[j]; k < cp[j + 1]; k++) {
            const int i = (int)ri[k];
            if (idx[i] < 0 || idx[j] < 0 || !(keep[k] || i == j)) {
                ENSURE(s->map[k] == -1);
                continue;
            }
            dense[idx[i]][idx[j]] = -2.0 * whole[k];
        }
    rc_subpat_gather(s, nz, -2.0, whole, part);
    for (int c = 0; c < s->n; c++) {
        ENSURE(s->colptr[c] <= s->colptr[c + 1]);
        for (int64_t k = s->colptr[c]; k < s->colptr[c + 1]; k++) {
            ENSURE(s->rowind[k] >= 0 && s->rowind[k] < s->n);
            if (k > s->colptr[c]) ENSURE(s->rowind[k] > s->rowind[k - 1]);
            got[s->rowind[k]][c] = part[k];
        }
        ENSURE(s->diag[c] >= s->colptr[c] && s->diag[c] < s->colptr[c + 1] && s->rowind[s->diag[c]] == c);
    }
    ENSURE(s->colptr[s->n] == s->nnz);
    for (int i = 0; i < s->n; i++)
        for (int j = 0; j < s->n; j++) ENSURE(got[i][j] == dense[i][j]);
}

static void test_subpat_random(void)
{
    unsigned seed = 12345;
    int64_t cp[NMAX + 1], ri[NMAX * NMAX];
    int idx[NMAX];
    unsigned char keep[NMAX * NMAX];
    rc_subpat s;
    memset(&s, 0, sizeof s);
    for (int trial = 0; trial < 200; trial++) {
        const int n = 1 + rand_r(&seed) % NMAX;
        const int64_t nz = random_pattern(n, 0.05 + 0.5 * (double)rand_r(&seed) / RAND_MAX, &seed, cp, ri);
        int next = 0;
        for (int j = 0; j < n; j++) idx[j] = rand_r(&seed) % 4 == 0 ? -1 : next++;
        for (int64_t k = 0; k < nz; k++) keep[k] = rand_r(&seed) % 3 != 0;
        /* rebuilt in place from the previous trial's arrays */
        ENSURE(rc_subpat_build(&s, n, cp, ri, idx, keep) == 0);
        check_part(n, cp, ri, idx, keep, &s, &seed);
    }
    /* NULL idx and keep: the whole pattern, slot for slot */
    const int64_t nz = random_pattern(10, 0.3, &seed, cp, ri);
    ENSURE(rc_subpat_build(&s, 10, cp, ri, NULL, NULL) == 0);
    ENSURE(s.n == 10 && s.nnz == nz);
    for (int64_t k = 0; k < nz; k++) ENSURE(s.map[k] == k && s.rowind[k] == ri[k]);
    rc_subpat_free(&s);
}

static void test_subpat_refusals(void)
{
    /* 3 states, column 1 without its diagonal */
    int64_t cp[] = {0, 1, 2, 3}, ri[] = {0, 0, 2};
    int idx_ok[] = {0, -1, 1}, idx_bad[] = {1, 0, -1}, idx_all[] = {0, 1, 2};
    rc_subpat s;
    memset(&s, 0, sizeof s);
    ENSURE(rc_subpat_build(&s, 3, cp, ri, idx_ok, NULL) == 0); /* state 1 renumbered out */
    ENSURE(s.n == 2 && s.nnz == 2 && s.map[1] == -1);
    ENSURE(rc_subpat_build(&s, 3, cp, ri, idx_all, NULL) == -2); /* state 1 kept, no diagonal */
    ENSURE(rc_subpat_build(&s, 3, cp, ri, idx_bad, NULL) == -2); /* not increasing */
    rc_subpat_free(&s);
}

void suite_subpat(void);
void suite_subpat(void)
{
    RUN_TEST(test_subpat_random);
    RUN_TEST(test_subpat_refusals);
}
