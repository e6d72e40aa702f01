/* Event kinds: what happened at an event, as an enum. Producers (the
 * contact couplings' and joint stops' face modes here in the assembly, the
 * interfaces' transitions in engine/events, the driver's own events) set
 * it; consumers compare it. The names, one table (event_kind.c), are what
 * the events table of the results file, the event callback and messages
 * receive (docs/output-format.md, "Kinds"). */
#ifndef RC_EVENT_KIND_H
#define RC_EVENT_KIND_H

typedef enum rc_event_kind {
    RC_EV_NONE = 0, /* no event (no name) */
    /* interfaces: the contact */
    RC_EV_CONTACT_CLOSE,
    RC_EV_CONTACT_OPEN,
    RC_EV_CONTACT_SEPARATE,
    RC_EV_CONTACT_SETTLE,
    /* interfaces: friction */
    RC_EV_FRIC_SLIP,
    RC_EV_FRIC_STICK,
    RC_EV_FRIC_TURN,
    RC_EV_FRIC_LAND,
    RC_EV_FRIC_REVERSE,
    RC_EV_FRIC_SATURATE,
    RC_EV_FRIC_UNSATURATE,
    /* interfaces: TYPE6 hysteresis branches, the power law's rebound damping */
    RC_EV_HYST_LOAD_CURVE,
    RC_EV_HYST_RELOADING,
    RC_EV_HYST_UNLOAD_CURVE,
    RC_EV_HYST_UNLOADING,
    RC_EV_RDF_APPROACH,
    RC_EV_RDF_REBOUND,
    /* interfaces: Inacti 5 tracking, activation window */
    RC_EV_INACTI_GAP_RECOVERED,
    RC_EV_INTER_START,
    RC_EV_INTER_STOP,
    /* contact couplings' faces (in the order of their transitions) */
    RC_EV_CPL_CONTACT_ENTER,
    RC_EV_CPL_CONTACT_LEAVE,
    RC_EV_CPL_CONTACT_RELEASE,
    RC_EV_CPL_CONTACT_CLOSE,
    /* joint stops (likewise) */
    RC_EV_STOP_ENTER,
    RC_EV_STOP_LEAVE,
    RC_EV_STOP_RELEASE,
    RC_EV_STOP_CLOSE,
    /* the driver's own: an imposed velocity ends (a time breakpoint) */
    RC_EV_IMPVEL_STOP,
    /* the driver's own: an imposed velocity starts (/IMPVEL Tstart > 0) */
    RC_EV_IMPVEL_START,
    /* the driver's own: a distance sensor triggers (/SENSOR/DIST) */
    RC_EV_SENSOR_TRIGGER,
    /* the driver's own: the CVODE path switches to the explicit method, and
     * back to BDF (/SOLVER Switch 1) */
    RC_EV_METHOD_EXPLICIT,
    RC_EV_METHOD_IMPLICIT,
    /* a general or beam spring breaks (a deformation reached its bound) */
    RC_EV_SPRING_RUPTURE,
    RC_EV_NKINDS
} rc_event_kind;

/* The kind's name as in the events table ("contact_close", ...); NULL for
 * RC_EV_NONE and out-of-range values. */
const char *rc_event_kind_name(rc_event_kind k);

#endif
