/*
 * The git commit ricochet was built from (rc_build_commit), baked in by the
 * Makefile as RC_COMMIT ("unknown" outside a git checkout); the Makefile
 * recompiles this file whenever the commit changes. In base so that every
 * stage may name it (the results file's provenance, `ricochet --version`).
 */
#include "ricochet/ricochet.h"

#ifndef RC_COMMIT
#define RC_COMMIT "unknown"
#endif

const char *rc_build_commit(void) { return RC_COMMIT; }
