/* Progress of the long stages (progress.h). */
#include "base/progress.h"
#include "ricochet/ricochet.h"

#include <time.h>
#include <unistd.h>

static FILE *stream;     /* NULL: off (set once, before threads start) */
static int tty;          /* the stream is a terminal: one line, overwritten */
/* the stage under way, per thread: threads reading or compiling their own
 * cases at once each time their own stage */
static _Thread_local const char *stage;
static _Thread_local double t_stage, t_last;
static _Thread_local int printed;
static _Thread_local unsigned long calls;

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void rc_set_progress(FILE *f)
{
    stream = f;
    tty = f && isatty(fileno(f));
}

void rc_progress_stage(const char *what)
{
    if (!stream) return;
    stage = what;
    t_stage = t_last = now();
    printed = 0;
    calls = 0;
}

void rc_progress(long done, long total)
{
    if (!stream || !stage || (calls++ & 4095u)) return;
    const double t = now();
    if (t - t_stage < RC_PROGRESS_AFTER || t - t_last < (tty ? 1.0 : RC_PROGRESS_EVERY)) return;
    fprintf(stream, "%sricochet: %s: %ld of %ld (%.0f%%), %.1f s%s", tty ? "\r" : "", stage, done, total,
            total > 0 ? 100.0 * (double)done / (double)total : 0.0, t - t_stage, tty ? "" : "\n");
    fflush(stream);
    t_last = t;
    printed = 1;
}

void rc_progress_done(void)
{
    if (!stream || !stage) return;
    const double dt = now() - t_stage;
    if (printed || dt >= RC_PROGRESS_AFTER)
        fprintf(stream, "%sricochet: %s: done in %.1f s\n", tty && printed ? "\r" : "", stage, dt);
    stage = NULL;
}
