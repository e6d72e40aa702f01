/* Id lookups in a parsed case, shared by the compilers (index or -1). */
#include "case.h"
#include "error.h"

#define RC_FIND(name, arr, count)                               \
    int rc_case_find_##name(const rc_case *c, int id)           \
    {                                                           \
        for (int k = 0; k < c->count; k++)                      \
            if (c->arr[k].id == id) return k;                   \
        return -1;                                              \
    }

RC_FIND(funct, funct, nfunct)
RC_FIND(node, node, nnode)
RC_FIND(grnod, grnod, ngrnod)
RC_FIND(rbody, rbody, nrbody)
RC_FIND(surf, surf, nsurf)
RC_FIND(part, part, npart)
RC_FIND(grpart, grpart, ngrpart)

int rc_case_body_of_node(const rc_case *c, int node_id)
{
    for (int b = 0; b < c->nrbody; b++) {
        if (c->rbody[b].node_id == node_id) return b;
        int g = c->rbody[b].grnod_id ? rc_case_find_grnod(c, c->rbody[b].grnod_id) : -1;
        if (g >= 0)
            for (int k = 0; k < c->grnod[g].n; k++)
                if (c->grnod[g].nodes[k] == node_id) return b;
    }
    return -1;
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
