/*
 * The closest of a list of names to a misspelt one, for the "did you mean"
 * of the reader (cards, --set fields) and of the command line (options).
 */
#include "ricochet/ricochet.h"

#include <string.h>

/* Edit distance of two names (insertions, deletions, substitutions;
 * letters compared as written), capped at 9. */
static int rc_name_distance(const char *a, const char *b)
{
    const size_t na = strlen(a), nb = strlen(b);
    if (na > 31 || nb > 31) return 9;
    int row[32];
    for (size_t j = 0; j <= nb; j++) row[j] = (int)j;
    for (size_t i = 1; i <= na; i++) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= nb; j++) {
            const int up = row[j];
            int v = diag + (a[i - 1] != b[j - 1]); /* substitution */
            if (up + 1 < v) v = up + 1;               /* deletion */
            if (row[j - 1] + 1 < v) v = row[j - 1] + 1; /* insertion */
            row[j] = v;
            diag = up;
        }
    }
    return row[nb] > 9 ? 9 : row[nb];
}

const char *rc_closest_name(const char *word, const char *const *cand, int n)
{
    const int lim = strlen(word) <= 4 ? 1 : 2;
    const char *best = NULL;
    int dbest = lim + 1, ties = 0;
    for (int i = 0; i < n; i++) {
        if (!cand[i]) continue;
        const int d = rc_name_distance(word, cand[i]);
        if (d < dbest) {
            dbest = d;
            best = cand[i];
            ties = 0;
        } else if (d == dbest && best && strcmp(best, cand[i]) != 0) {
            ties = 1;
        }
    }
    return dbest <= lim && !ties ? best : NULL;
}
