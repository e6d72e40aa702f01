/*
 * Units of the deck: the unit names of /BEGIN and /UNIT, their factors to
 * SI, and the dimension of a field (exponents of mass, length and time)
 * that turns a value read in a unit system into SI. Pure functions: this
 * file calls nothing else in the stage (fields.c and cards_run.c call it).
 */
#include "case/case_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Unit names and their values in kg, m, s (the names of the Radioss
 * manual, ASCII spellings of the micro prefix included). */
static const struct {
    const char *name;
    double si;
} rc_mass_units[] = {{"kg", 1.0},  {"g", 1e-3},   {"mg", 1e-6}, {"Mg", 1e3},
                     {"t", 1e3},   {"ton", 1e3},  {"lb", 0.45359237}},
  rc_length_units[] = {{"m", 1.0},    {"dm", 1e-1},  {"cm", 1e-2},     {"mm", 1e-3},
                       {"um", 1e-6},  {"\xC2\xB5m", 1e-6}, {"\xCE\xBCm", 1e-6}, {"nm", 1e-9},
                       {"km", 1e3},   {"in", 0.0254}, {"ft", 0.3048}},
  rc_time_units[] = {{"s", 1.0},   {"ms", 1e-3},  {"us", 1e-6}, {"\xC2\xB5s", 1e-6},
                     {"\xCE\xBCs", 1e-6}, {"ns", 1e-9}, {"min", 60.0}, {"h", 3600.0}};

int rc_unit_factor(int kind, const char *name, double *si)
{
    const void *tab[3] = {rc_mass_units, rc_length_units, rc_time_units};
    const size_t n[3] = {sizeof rc_mass_units / sizeof rc_mass_units[0],
                         sizeof rc_length_units / sizeof rc_length_units[0],
                         sizeof rc_time_units / sizeof rc_time_units[0]};
    const struct { const char *name; double si; } *t = tab[kind];
    if (kind < 0 || kind > 2 || !name[0]) return 0;
    /* exact spelling first (Mg and mg differ), then any case when unambiguous */
    for (size_t i = 0; i < n[kind]; i++)
        if (strcmp(t[i].name, name) == 0) { *si = t[i].si; return 1; }
    int found = -1;
    for (size_t i = 0; i < n[kind]; i++)
        if (strcasecmp(t[i].name, name) == 0) {
            if (found >= 0 && t[found].si != t[i].si) return 0;
            found = (int)i;
        }
    if (found >= 0) { *si = t[found].si; return 1; }
    /* a number: the unit's value in kg, m or s */
    char *end;
    double v = strtod(name, &end);
    if (end != name && *end == '\0' && isfinite(v) && v > 0) { *si = v; return 1; }
    return 0;
}

const char *rc_unit_names(int kind)
{
    static const char *const s[3] = {"kg, g, mg, Mg, t, ton, lb",
                                     "m, dm, cm, mm, um (\xC2\xB5m), nm, km, in, ft",
                                     "s, ms, us (\xC2\xB5s), ns, min, h"};
    return kind >= 0 && kind < 3 ? s[kind] : "";
}

double rc_dim_scale(int dim, const double f[3])
{
    int e[3] = {((dim >> 8) & 15) - 8, ((dim >> 4) & 15) - 8, (dim & 15) - 8};
    double s = 1.0;
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < abs(e[k]); i++) s = e[k] > 0 ? s * f[k] : s / f[k];
    return s;
}
