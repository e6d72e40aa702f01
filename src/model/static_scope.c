/*
 * The scope of the static analysis (/SOLVER Method 3, solver/static.c):
 * what its first version solves, and a clear input error naming the card
 * of the first element it does not (docs/case-format.md, /SOLVER). Called
 * where Method 3 is chosen: by the compiler for the deck's /SOLVER, by
 * rc_model_set_method, and by the static backend itself.
 */
#include <stdio.h>

#include "base/error.h"
#include "model/coupling.h"
#include "model/imposed.h"
#include "model/joint.h"
#include "model/model.h"
#include "model/power.h"

#define RC_STATIC_NOT "static analysis (/SOLVER Method 3) does not support %s in this version"

rc_status rc_static_scope(const rc_model *m, const char *how, rc_error *err)
{
    if (!how) how = "/SOLVER Method 3";
    if (m->jnt && m->jnt->n > 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card %s: " RC_STATIC_NOT " (%s); expected a model without joints, or Method 1 or 2",
                 RC_LOC(m->jnt->loc[0]), m->jnt->name[0], "joints", how);
    if (m->imp && m->imp->nt + m->imp->nr > 0)
        RC_RAISE(err, RC_EINPUT,
                 RC_LOCFMT "card /IMPVEL: " RC_STATIC_NOT " (%s); expected no /IMPVEL card, or Method 1 or 2",
                 RC_LOC(m->end_loc), "imposed velocities", how);
    for (int i = 0; i < m->ninter; i++) {
        const rc_fric *fr = &m->inter_fr[i];
        const char *what = NULL;
        char fbuf[96];
        if (fr->exact) what = "exact stick (TYPE6 Istick 1, /FRICTION Iform 3)";
        else if (!rc_inter_frictionless(m, i)) {
            if (fr->card_id > 0) snprintf(fbuf, sizeof fbuf, "friction (/FRICTION/%d on it)", fr->card_id);
            else snprintf(fbuf, sizeof fbuf, "friction (its own friction fields)");
            what = fbuf;
        } else if (m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] != 0)
            what = m->inter_iform[i] == 1 ? "TYPE6 Iform 1 (elasto-plastic hysteresis)"
                                          : "TYPE6 Iform 2 (decoupled hardening hysteresis)";
        else if (m->inter_oidx[i] >= 0)
            what = "Inacti 5 (the gap offset state)";
        else if (m->inter_peidx[i] >= 0 || rc_pair_multi(m->inter_pair[i]))
            what = "pairs with several contact points (segment surfaces)";
        if (what)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: " RC_STATIC_NOT " (%s); expected a frictionless elastic contact (TYPE6 "
                               "Iform 0, or the power law) between spheres, planes, boxes or "
                               "cylinders, or Method 1 or 2",
                     RC_LOC(m->inter_loc[i]), m->inter_name[i], what, how);
    }
    for (int k = 0; m->cpl && k < m->cpl->n; k++)
        if (m->cpl->kind[k] != RC_CPL_SPRING)
            RC_RAISE(err, RC_EINPUT,
                     RC_LOCFMT "card %s: " RC_STATIC_NOT " (%s); expected spring couplings (/COUPLING/SPRING) only, "
                               "or Method 1 or 2",
                     RC_LOC(m->cpl->law_loc[k]), m->cpl->name[k],
                     m->cpl->kind[k] == RC_CPL_CATENARY ? "catenary couplings"
                     : m->cpl->kind[k] == RC_CPL_CONTACT ? "contact couplings"
                                                         : "joint stops",
                     how);
    return RC_OK;
}
