/*
 * Id lookups in a parsed case, shared by the compilers (index or -1).
 *
 * rc_case_load ends with rc_case_index_build: for each card kind, the
 * (id, index) pairs sorted by id (ties by index, so the first card of an id
 * wins, as a linear search would), and the body carrying each node; look-ups
 * are then binary searches, O(log N), and compiling N bodies costs
 * O(N log N) instead of O(N^2). A case built by hand (tests) or changed
 * since (another count) has no valid index: the look-ups then scan the arrays
 * as before, with the same answers.
 */
#include <limits.h>
#include <stdlib.h>

#include "case/case.h"
#include "base/error.h"

enum { LK_FUNCT, LK_NODE, LK_GRNOD, LK_RBODY, LK_SURF, LK_PART, LK_GRPART, LK_COUNT };

/* One sorted key -> value table. */
typedef struct rc_lk_pair {
    int key, val;
} rc_lk_pair;

typedef struct rc_lk_table {
    int n;          /* number of cards of the kind when built */
    int npair;
    rc_lk_pair *p;  /* [npair] sorted by (key, val) */
} rc_lk_table;

struct rc_case_index {
    rc_lk_table t[LK_COUNT];
    rc_lk_table node_body; /* node id -> body index (first body carrying it) */
    int nrbody, ngrnod;    /* counts when node_body was built */
};

static int cmp_pair(const void *a, const void *b)
{
    const rc_lk_pair *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return (x->val > y->val) - (x->val < y->val);
}

/* Value of the first pair with this key (smallest value), or -1. */
static int lk_search(const rc_lk_table *t, int key)
{
    int lo = 0, hi = t->npair; /* first pair with p.key >= key */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (t->p[mid].key < key) lo = mid + 1;
        else hi = mid;
    }
    return lo < t->npair && t->p[lo].key == key ? t->p[lo].val : -1;
}

/* Sort the pairs of a table (filled by the caller). */
static void lk_sort(rc_lk_table *t)
{
    if (t->npair > 1) qsort(t->p, (size_t)t->npair, sizeof *t->p, cmp_pair);
}

/* The id of card k of kind `kind`. */
static int card_id(const rc_case *c, int kind, int k)
{
    switch (kind) {
    case LK_FUNCT: return c->funct[k].id;
    case LK_NODE: return c->node[k].id;
    case LK_GRNOD: return c->grnod[k].id;
    case LK_RBODY: return c->rbody[k].id;
    case LK_SURF: return c->surf[k].id;
    case LK_PART: return c->part[k].id;
    default: return c->grpart[k].id;
    }
}

static int card_count(const rc_case *c, int kind)
{
    const int n[LK_COUNT] = {c->nfunct, c->nnode, c->ngrnod, c->nrbody, c->nsurf, c->npart, c->ngrpart};
    return n[kind];
}

/* Linear search (no valid index). */
static int scan(const rc_case *c, int kind, int id)
{
    const int n = card_count(c, kind);
    for (int k = 0; k < n; k++)
        if (card_id(c, kind, k) == id) return k;
    return -1;
}

static int find(const rc_case *c, int kind, int id)
{
    const rc_case_index *x = c->index;
    if (!x || x->t[kind].n != card_count(c, kind)) return scan(c, kind, id);
    return lk_search(&x->t[kind], id);
}

int rc_case_find_funct(const rc_case *c, int id) { return find(c, LK_FUNCT, id); }
int rc_case_find_node(const rc_case *c, int id) { return find(c, LK_NODE, id); }
int rc_case_find_grnod(const rc_case *c, int id) { return find(c, LK_GRNOD, id); }
int rc_case_find_rbody(const rc_case *c, int id) { return find(c, LK_RBODY, id); }
int rc_case_find_surf(const rc_case *c, int id) { return find(c, LK_SURF, id); }

const char *rc_case_surf_kind_name(int kind)
{
    static const char *const name[] = {"?", "PLANE", "ELLIPS", "CYL", "BOX", "SEG", "PART"};
    return kind >= RC_CASE_SURF_PLANE && kind <= RC_CASE_SURF_PART ? name[kind] : "?";
}
int rc_case_find_part(const rc_case *c, int id) { return find(c, LK_PART, id); }
int rc_case_find_grpart(const rc_case *c, int id) { return find(c, LK_GRPART, id); }

int rc_case_body_of_node(const rc_case *c, int node_id)
{
    const rc_case_index *x = c->index;
    if (x && x->nrbody == c->nrbody && x->ngrnod == c->ngrnod) return lk_search(&x->node_body, node_id);
    for (int b = 0; b < c->nrbody; b++) {
        if (c->rbody[b].node_id == node_id) return b;
        int g = c->rbody[b].grnod_id ? rc_case_find_grnod(c, c->rbody[b].grnod_id) : -1;
        if (g >= 0)
            for (int k = 0; k < c->grnod[g].n; k++)
                if (c->grnod[g].nodes[k] == node_id) return b;
    }
    return -1;
}

void rc_case_index_free(rc_case_index *x)
{
    if (!x) return;
    for (int k = 0; k < LK_COUNT; k++) free(x->t[k].p);
    free(x->node_body.p);
    free(x);
}

rc_status rc_case_index_build(rc_case *c, rc_error *err)
{
    rc_case_index_free(c->index);
    c->index = NULL;
    rc_case_index *x = calloc(1, sizeof *x);
    if (!x) RC_RAISE(err, RC_ENOMEM, "out of memory for the id index");
    for (int kind = 0; kind < LK_COUNT; kind++) {
        rc_lk_table *t = &x->t[kind];
        t->n = card_count(c, kind);
        if (!(t->p = malloc(((size_t)t->n + 1) * sizeof *t->p))) goto nomem;
        for (int k = 0; k < t->n; k++) t->p[t->npair++] = (rc_lk_pair){card_id(c, kind, k), k};
        lk_sort(t);
    }
    /* the body of each node: its main node, then the nodes of its group;
     * sorted by (node, body), the first body wins as in the scan above */
    size_t np = (size_t)c->nrbody;
    for (int b = 0; b < c->nrbody; b++) {
        const int g = c->rbody[b].grnod_id ? lk_search(&x->t[LK_GRNOD], c->rbody[b].grnod_id) : -1;
        if (g >= 0) np += (size_t)c->grnod[g].n;
    }
    if (np > (size_t)INT_MAX || !(x->node_body.p = malloc((np + 1) * sizeof *x->node_body.p))) goto nomem;
    rc_lk_table *nb = &x->node_body;
    for (int b = 0; b < c->nrbody; b++) {
        nb->p[nb->npair++] = (rc_lk_pair){c->rbody[b].node_id, b};
        const int g = c->rbody[b].grnod_id ? lk_search(&x->t[LK_GRNOD], c->rbody[b].grnod_id) : -1;
        if (g >= 0)
            for (int k = 0; k < c->grnod[g].n; k++) nb->p[nb->npair++] = (rc_lk_pair){c->grnod[g].nodes[k], b};
    }
    lk_sort(nb);
    x->nrbody = c->nrbody;
    x->ngrnod = c->ngrnod;
    c->index = x;
    return RC_OK;
nomem:
    rc_case_index_free(x);
    RC_RAISE(err, RC_ENOMEM, "out of memory for the id index");
}

rc_status rc_case_ref_funct(const rc_case *c, int id, int required, rc_loc loc, const char *card,
                            const char *field, int *index, rc_error *err)
{
    *index = -1;
    if (id == 0 && !required) return RC_OK;
    *index = rc_case_find_funct(c, id);
    if (*index < 0)
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: expected the id of a /FUNCT, got %d (no such function)",
                 RC_LOC(loc), card, field, id);
    return RC_OK;
}

int rc_case_warning_count(const rc_case *c) { return c ? c->nwarnings : 0; }

const char *rc_case_warning(const rc_case *c, int i)
{
    return c && i >= 0 && i < c->nwarnings ? c->warnings[i] : NULL;
}

int rc_case_find_rwall(const rc_case *c, int id)
{
    for (int k = 0; c && k < c->nrwall; k++)
        if (c->rwall[k].id == id) return k;
    return -1;
}

int rc_case_find_sensor(const rc_case *c, int id)
{
    for (int k = 0; c && k < c->nsensor; k++)
        if (c->sensor[k].id == id) return k;
    return -1;
}
