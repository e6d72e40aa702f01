/*
 * /INTER/POWER into the interface element (power.h): the geometry pair,
 * neutral TYPE6 fields, the power-law parameters and splines, the step5
 * friction; and the elastic energy the law stores.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case/case.h"
#include "case/case_power.h"
#include "base/error.h"
#include "model/geom.h"
#include "model/model.h"
#include "model/power.h"
#include "model/sensor.h"


/* Spline of /FUNCT `id` (field `field` of the card), or NULL when id = 0. */
static rc_status make_spline(const rc_case *c, const rc_case_power *p, int id, const char *card, const char *field,
                             rc_spline **out, rc_error *err)
{
    *out = NULL;
    int f;
    rc_status st = rc_case_ref_funct(c, id, 0, p->line_loc[0], card, field, &f, err);
    if (st || f < 0) return st;
    rc_spline *s = calloc(1, sizeof *s);
    if (!s) RC_RAISE(err, RC_ENOMEM, "out of memory");
    rc_error e2;
    if (rc_spline_init(s, p->ispline, id, c->funct[f].npts, c->funct[f].x, c->funct[f].y, &e2)) {
        free(s);
        RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field %s: %s", RC_LOC(p->line_loc[0]), card, field, e2.msg);
    }
    *out = s;
    return RC_OK;
}

rc_status rc_power_compile(const rc_case *c, rc_model *m, int k, int i, rc_error *err)
{
    const rc_case_power *p = &c->power[k];
    char card[64], where[600];
    snprintf(card, sizeof card, "/INTER/POWER/%d", p->id);
    snprintf(where, sizeof where, RC_LOCFMT "card %s", RC_LOC(p->line_loc[0]), card);
    m->inter_law[i] = RC_LAW_POWER;
    m->inter_name[i] = malloc(strlen(card) + 1);
    if (!m->inter_name[i]) RC_RAISE(err, RC_ENOMEM, "out of memory");
    strcpy(m->inter_name[i], card);
    /* the pair */
    int s1 = rc_case_find_surf(c, p->surf1), s2 = rc_case_find_surf(c, p->surf2);
    if (s1 < 0 || s2 < 0)
        RC_RAISE(err, RC_EINPUT, "%s, field %s: expected the id of a /SURF, got %d (no such surface)", where,
                 s1 < 0 ? "surf_ID1" : "surf_ID2", s1 < 0 ? p->surf1 : p->surf2);
    rc_status st = rc_geom_pair(m, s1, s2, &m->inter_sa[i], &m->inter_sb[i], &m->inter_pair[i], where, err);
    if (st) return st;
    m->inter_ba[i] = m->surf_body[m->inter_sa[i]];
    m->inter_bb[i] = m->surf_body[m->inter_sb[i]];
    if (m->inter_ba[i] == m->inter_bb[i])
        RC_RAISE(err, RC_EINPUT, "%s, fields surf_ID1/surf_ID2: both surfaces are on the same body; they must belong "
                 "to two different rigid bodies", where);
    /* the TYPE6 fields, neutral (no gap, no hysteresis, no curves) */
    m->inter_id[i] = p->id;
    m->inter_loc[i] = p->loc;
    m->inter_gap[i] = 0.0;
    m->inter_tstart[i] = p->tstart;
    m->inter_tstop[i] = p->tstop;
    /* a sensor turns the interface on at its time (model/sensor.c) */
    rc_status sst = rc_sensor_tstart(c, p->sensor_id, p->line_loc[0], card, &m->inter_tstart[i], &m->inter_tstop[i], &m->inter_sens[i], err);
    if (sst) return sst;
    m->inter_ascalex[i] = m->inter_fscaleld[i] = m->inter_ascalef[i] = m->inter_ascalev[i] = 1.0;
    m->inter_fscalev[i] = m->inter_fscaleul[i] = 1.0;
    m->inter_fct_ld[i] = m->inter_fct_dv[i] = m->inter_fct_df[i] = m->inter_fct_ul[i] = -1;
    /* the law */
    rc_power *pw = &m->inter_pw[i];
    pw->k = p->k;
    pw->m1 = p->m1;
    pw->m2 = p->m2;
    pw->m3 = p->m3;
    pw->c = p->c;
    pw->rdf = p->irdf == 2 ? 1.0 : p->rdf;
    pw->dreg = p->dreg;
    pw->vreg = p->vreg;
    if ((st = make_spline(c, p, p->fct_stiff, card, "fct_stiff", &pw->stiff, err))) return st;
    if ((st = make_spline(c, p, p->fct_damp, card, "fct_damp", &pw->damp, err))) return st;
    /* a restitution asked: C is derived with the scales (engine/analyses/restitution.c) */
    m->inter_etarget[i] = p->e_target;
    m->inter_vimp[i] = p->v_imp;
    if (p->e_target > 0) {
        const rc_loc l6 = rc_loc_or(p->line_loc[5], p->loc);
        if (!(p->e_target <= 1))
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field e_target: expected a restitution in (0, 1], got %g",
                     RC_LOC(l6), card, p->e_target);
        if (p->c != 0 || p->fct_damp != 0)
            RC_RAISE(err, RC_EINPUT, RC_LOCFMT "card %s, field e_target: a restitution asked replaces the damping "
                     "coefficient: expected C = 0 and fct_damp = 0 with it, got C %g, fct_damp %d",
                     RC_LOC(l6), card, p->c, p->fct_damp);
    }
    /* step5 friction (a /FRICTION card naming the parts overrides it) */
    rc_fric *fr = &m->inter_fr[i];
    fr->fct_ff = fr->fct_fv = -1;
    fr->tidx = fr->fidx = fr->widx = fr->obody = -1;
    fr->kind = p->mus > 0 || p->mud > 0 ? RC_FK_STEP5 : RC_FK_NONE;
    fr->form = RC_FF_VISCOUS;
    fr->set[0][RC_S5_MUS] = p->mus;
    fr->set[0][RC_S5_VS] = p->vs;
    fr->set[0][RC_S5_MUD] = p->mud;
    fr->set[0][RC_S5_VD] = p->vd;
    fr->set[0][RC_S5_FMAX] = p->fmax;
    fr->kt = p->kt;
    const double r = m->surf_r[m->inter_sa[i]];
    fr->area = RC_PI * r * r;
    return RC_OK;
}

void rc_power_free(rc_model *m)
{
    if (!m->inter_pw) return;
    for (int i = 0; i < m->ninter; i++) {
        rc_spline *s[2] = {m->inter_pw[i].stiff, m->inter_pw[i].damp};
        for (int k = 0; k < 2; k++) {
            rc_spline_free(s[k]);
            free(s[k]);
        }
    }
}

/* Integral of rc_powreg (power.h) from 0 to x >= 0. */
static double powreg_integral(double x, double m, double xr)
{
    if (x <= 0) return 0.0;
    if (m == 1.0) return 0.5 * x * x;
    if (m >= 1.0) return pow(x, m + 1.0) / (m + 1.0);
    const double a = (2.0 - m) * pow(xr, m - 1.0), b = (m - 1.0) * pow(xr, m - 2.0);
    const double xl = x < xr ? x : xr;
    double sum = 0.5 * a * xl * xl + b * xl * xl * xl / 3.0;
    if (x > xr) sum += (pow(x, m + 1.0) - pow(xr, m + 1.0)) / (m + 1.0);
    return sum;
}

double rc_power_stored(const rc_model *m, int i, double p)
{
    const rc_power *pw = &m->inter_pw[i];
    if (p <= 0) return 0.0;
    if (pw->stiff) return rc_spline_integral(pw->stiff, 0.0, p);
    return pw->k * powreg_integral(p, pw->m1, pw->dreg);
}

int rc_inter_undamped(const rc_model *m, int i)
{
    if (m->inter_law[i] == RC_LAW_TYPE6)
        return m->inter_visc[i] == 0.0 && !(m->inter_fct_dv[i] >= 0 && m->inter_fscalev[i] != 0.0);
    const rc_power *pw = &m->inter_pw[i];
    return pw->c == 0.0 && !pw->damp;
}

double rc_inter_k_stiff(const rc_model *m, int i)
{
    const double k = m->inter_kscale[i];
    return m->inter_law[i] == RC_LAW_TYPE6 && m->inter_iform[i] > 0 && m->inter_stiff[i] > k ? m->inter_stiff[i] : k;
}

double rc_inter_zeta_stiff(const rc_model *m, int i, double *period)
{
    *period = NAN;
    if (m->inter_law[i] != RC_LAW_TYPE6 || !(m->inter_visc[i] > 0) ||
        (m->inter_fct_dv[i] >= 0 && m->inter_fscalev[i] != 0.0))
        return NAN;
    const double k = rc_inter_k_stiff(m, i);
    const double mr = m->inter_mrest[i];
    if (!(k > 0) || !isfinite(k) || !(mr > 0) || !isfinite(mr)) return NAN;
    *period = 2.0 * RC_PI * sqrt(mr / k);
    return m->inter_visc[i] / (2.0 * sqrt(k * mr));
}

int rc_inter_elastic(const rc_model *m, int i)
{
    return rc_inter_undamped(m, i) && (m->inter_law[i] != RC_LAW_TYPE6 || m->inter_iform[i] == 0) &&
           !rc_pair_multi(m->inter_pair[i]);
}

void rc_power_print(const rc_model *m, int i, FILE *f)
{
    const rc_power *pw = &m->inter_pw[i];
    fprintf(f, "  %-18s %s, ", m->inter_name[i], rc_geom_inter_pair_name(m, i));
    if (pw->stiff) fprintf(f, "stiffness %s spline /FUNCT/%d, ", rc_spline_kind_name(pw->stiff->kind), pw->stiff->id);
    else fprintf(f, "K %.5g m1 %.5g, ", pw->k, pw->m1);
    if (pw->damp) fprintf(f, "damping %s spline /FUNCT/%d", rc_spline_kind_name(pw->damp->kind), pw->damp->id);
    else fprintf(f, "C %.5g m2 %.5g", pw->c, pw->m2);
    fprintf(f, " m3 %.5g, ", pw->m3);
    if (pw->rdf == 1.0) fprintf(f, "RDF off");
    else fprintf(f, "RDF %.5g%s", pw->rdf, rc_pw_rdf_acts(pw) ? "" : " (no damping term to scale: no effect)");
    fprintf(f, ", Tstart %.5g, Tstop %.5g%s\n", m->inter_tstart[i], m->inter_tstop[i], rc_sensor_note(m, i));
}
