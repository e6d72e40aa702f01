/*
 * Messages: every entry of the state vector has a name (element, quantity,
 * unit) for the solver's failure messages, over decks that use every kind
 * of state (bodies, TYPE6 energies and hysteresis, friction with a filter,
 * couplings, imposed velocities).
 */
#include "harness.h"
#include "model/model.h"
#include "base/error.h"

#include <string.h>

static void check_names(const char *path)
{
    rc_case *c = NULL;
    rc_model *m = NULL;
    rc_error e;
    rc_error_clear(&e);
    ENSURE(rc_case_load(path, &c, &e) == RC_OK);
    if (c) ENSURE(rc_model_compile(c, &m, &e) == RC_OK);
    if (!m) {
        fprintf(stderr, "  %s: %s\n", path, e.msg);
        rc_case_free(c);
        return;
    }
    int unnamed = 0;
    for (int i = 0; i < m->ny; i++) {
        char name[200];
        rc_state_name(m, i, name, sizeof name);
        /* "<element>, <quantity> [<unit>]" */
        if (name[0] != '/' || !strstr(name, ", ") || !strchr(name, '[') || strstr(name, "own state")) {
            fprintf(stderr, "  %s: state %d named \"%s\"\n", path, i, name);
            unnamed++;
        }
    }
    ENSURE(unnamed == 0);
    char name[200];
    rc_state_name(m, m->ny, name, sizeof name); /* out of range: a plain index */
    ENSURE(strcmp(name, "state ") > 0 && strncmp(name, "state ", 6) == 0);
    rc_model_free(m);
    rc_case_free(c);
}

static void test_messages_state_names(void)
{
    check_names("cases/demo_sphere_drop.rad");
    check_names("validation/t6_unload_curve/case.rad");
    check_names("validation/frc_filter/case.rad");
    check_names("validation/cpl_catenary_swing/case.rad");
    check_names("validation/impvel_release/case.rad");
}

void suite_messages(void);
void suite_messages(void)
{
    RUN_TEST(test_messages_state_names);
}
