/*
 * `ricochet check` lines of a contact coupling (model/coupling_contact.h):
 * faces, law, the estimators (STAR-CCM+'s: k1, k2, the stopping time tau),
 * warnings when the output interval or the step budget cannot resolve tau,
 * and a rough cost estimate (docs/theory.md "Contact coupling").
 */
#include <math.h>
#include <stdio.h>

#include "model/coupling.h"
#include "model/coupling_contact.h"
#include "model/model.h"
#include "engine/reports/reports.h"

/* CVODE steps per stopping time tau, measured on the validation problems
 * at the default tolerances (a full impact, 2 tau, takes 124 to 267 steps
 * on the validation problems; 150 is used for both kinds of contact) [-]. */
#define RC_STEPS_PER_TAU 75.0
/* Output records wanted per stopping time [-]. */
#define RC_REC_PER_TAU 10.0

static const char *surf_name(int kind)
{
    switch (kind) {
    case RC_SURF_PLANE: return "plane";
    case RC_SURF_SPHERE: return "sphere";
    case RC_SURF_CYL: return "cylinder";
    case RC_SURF_BOX: return "box";
    case RC_SURF_SEG: return "segments";
    default: return "surface";
    }
}

void rc_cpl_contact_print(const rc_model *m, int k, const rc_cpl_report *r, FILE *f)
{
    const rc_couplings *c = m->cpl;
    const rc_cpl_contact *ct = c->ct;
    const int s1 = ct->sf1[k], s2 = ct->sf2[k], kind = m->surf_kind[s2];
    const char *side = kind == RC_SURF_PLANE || kind == RC_SURF_SEG ? (ct->side[k] > 0 ? "its normal side" : "against its normal")
                                             : (ct->side[k] > 0 ? "outside" : "inside");
    const int nf = ct->fadr[k + 1] - ct->fadr[k];
    fprintf(f, "%d face%s (%.5g m^2) of /SURF/%d against /SURF/%d (%s, %s, %s); d0 %.5g m, k1 %.5g N/m^3, k2 %.5g N s/m^3, "
            "mu %.5g, k_t %.5g s/m; at t = 0: nearest face at %.5g m, normal force %.5g N\n",
            nf, nf == 1 ? "" : "s", ct->atot[k], m->surf_id[s1], m->surf_id[s2], surf_name(kind),
            c->b2[k] >= 0 ? "body-body" : "fixed", side, ct->d0[k], ct->k1[k], ct->k2[k], ct->mu[k], ct->kt[k],
            r ? r->length : NAN, r ? r->force : NAN);
    const double tau = ct->tau[k];
    if (ct->est[k])
        fprintf(f, "  %-22s estimated (Iest 1) from V_imp %.5g m/s, d_min %.5g m, zeta %.5g, A %.5g m^2, m_red %.5g kg: "
                "k1 = m_red V^2/(A (d0 - d_min)^2) = %.6g N/m^3, k2 = 2 zeta sqrt(m_red k1/A) = %.6g N s/m^3\n",
                "", ct->vimp[k], ct->dmin[k], ct->zeta[k], ct->area[k], ct->mred[k], ct->k1[k], ct->k2[k]);
    if (!isfinite(tau)) {
        fprintf(f, "  %-22s no stopping time (neither body moves)\n", "");
        return;
    }
    fprintf(f, "  %-22s stopping time tau = (pi/2) sqrt(m_red/(A k1)) = %.5g s (m_red %.5g kg, A = %s %.5g m^2; weak "
            "damping)%s\n",
            "", tau, ct->mred[k], ct->est[k] ? "the estimator's" : "the total face area", ct->est[k] ? ct->area[k] : ct->atot[k],
            ct->k2[k] > 0 ? "" : ", no damping: the body rebounds at its impact speed");
    if (m->dtout > tau / RC_REC_PER_TAU)
        fprintf(f, "  %-22s WARNING: the output interval Dt_out = %.4g s cannot resolve tau (%.3g records per tau; "
                "lower /RUN Dt_out to %.3g s or less to see the stopping)\n",
                "", m->dtout, tau / m->dtout, tau / RC_REC_PER_TAU);
    const double per_out = RC_STEPS_PER_TAU * m->dtout / tau;
    if (m->max_steps > 0 && per_out > (double)m->max_steps)
        fprintf(f, "  %-22s WARNING: about %.3g steps per output interval are needed to resolve tau, more than "
                "/SOLVER Max_steps = %ld: raise Max_steps or lower Dt_out\n",
                "", per_out, m->max_steps);
    if (m->hmax > 0 && m->hmax > tau / RC_REC_PER_TAU)
        fprintf(f, "  %-22s note: Hmax = %.4g s is above tau/%g; the error control still resolves the stopping\n", "",
                m->hmax, RC_REC_PER_TAU);
    fprintf(f, "  %-22s cost: about %.0f steps per impact (2 tau) at the default tolerances; a run of %.4g s in "
            "contact throughout: at most ~%.3g steps\n",
            "", 2.0 * RC_STEPS_PER_TAU, m->tend, RC_STEPS_PER_TAU * m->tend / tau);
}
