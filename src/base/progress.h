/*
 * Progress of the long stages (reading a deck, compiling the model) on a
 * stream the program chooses (the command line: stderr, unless -q). Off by
 * default, so the library says nothing unless asked. A stage prints only
 * once it has run for RC_PROGRESS_AFTER seconds, then at most once per
 * second on a terminal (overwriting its line) or every RC_PROGRESS_EVERY
 * seconds in a log; small decks print nothing.
 */
#ifndef RC_PROGRESS_H
#define RC_PROGRESS_H

#include <stdio.h>

#define RC_PROGRESS_AFTER 1.0  /* [s] */
#define RC_PROGRESS_EVERY 5.0  /* [s], when the stream is not a terminal */

/* Start a stage ("reading cards"). */
void rc_progress_stage(const char *what);
/* `done` of `total` items of the stage; cheap when nothing is printed (a
 * clock read every 4096 calls). */
void rc_progress(long done, long total);
/* End of the stage: its time, if anything was printed. */
void rc_progress_done(void);

#endif
