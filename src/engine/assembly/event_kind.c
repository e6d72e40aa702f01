/* The event kinds' names (event_kind.h): the one table of the strings the
 * results file, the event callback and messages receive. */
#include <stddef.h>

#include "engine/assembly/event_kind.h"

static const char *const names[RC_EV_NKINDS] = {
    [RC_EV_NONE] = NULL,
    [RC_EV_CONTACT_CLOSE] = "contact_close",
    [RC_EV_CONTACT_OPEN] = "contact_open",
    [RC_EV_CONTACT_SEPARATE] = "contact_separate",
    [RC_EV_CONTACT_SETTLE] = "contact_settle",
    [RC_EV_FRIC_SLIP] = "fric_slip",
    [RC_EV_FRIC_STICK] = "fric_stick",
    [RC_EV_FRIC_TURN] = "fric_turn",
    [RC_EV_FRIC_LAND] = "fric_land",
    [RC_EV_FRIC_REVERSE] = "fric_reverse",
    [RC_EV_FRIC_SATURATE] = "fric_saturate",
    [RC_EV_FRIC_UNSATURATE] = "fric_unsaturate",
    [RC_EV_HYST_LOAD_CURVE] = "hyst_load_curve",
    [RC_EV_HYST_RELOADING] = "hyst_reloading",
    [RC_EV_HYST_UNLOAD_CURVE] = "hyst_unload_curve",
    [RC_EV_HYST_UNLOADING] = "hyst_unloading",
    [RC_EV_RDF_APPROACH] = "rdf_approach",
    [RC_EV_RDF_REBOUND] = "rdf_rebound",
    [RC_EV_INACTI_GAP_RECOVERED] = "inacti_gap_recovered",
    [RC_EV_INTER_START] = "inter_start",
    [RC_EV_INTER_STOP] = "inter_stop",
    [RC_EV_CPL_CONTACT_ENTER] = "cpl_contact_enter",
    [RC_EV_CPL_CONTACT_LEAVE] = "cpl_contact_leave",
    [RC_EV_CPL_CONTACT_RELEASE] = "cpl_contact_release",
    [RC_EV_CPL_CONTACT_CLOSE] = "cpl_contact_close",
    [RC_EV_STOP_ENTER] = "stop_enter",
    [RC_EV_STOP_LEAVE] = "stop_leave",
    [RC_EV_STOP_RELEASE] = "stop_release",
    [RC_EV_STOP_CLOSE] = "stop_close",
    [RC_EV_IMPVEL_STOP] = "impvel_stop",
    [RC_EV_IMPVEL_START] = "impvel_start",
    [RC_EV_SENSOR_TRIGGER] = "sensor_trigger",
    [RC_EV_METHOD_EXPLICIT] = "method_explicit",
    [RC_EV_METHOD_IMPLICIT] = "method_implicit",
    [RC_EV_SPRING_RUPTURE] = "spring_rupture",
};

const char *rc_event_kind_name(rc_event_kind k)
{
    return (int)k >= 0 && k < RC_EV_NKINDS ? names[k] : NULL;
}
