/*
 * Optimised element-wise operations for SUNDIALS' serial vectors.
 *
 * Debian 12's libsundials_nvecserial is compiled without optimisation (its
 * loops keep every index and partial sum in memory: see docs/design.md,
 * "Vector operations"), and on the many-body models the integrator's vector
 * operations (weighted norms, linear sums, the fused Nordsieck updates) were
 * a third of the run. rc_nvector_fast installs compiled-with-optimisation
 * versions of these operations in a serial vector's operations table, the
 * extension point SUNDIALS provides for vector implementations; the clones
 * the integrators make of the vector inherit them. Each operation computes
 * the same expression in the same order as the serial vector's own, so the
 * results are identical to the last bit (checked by a unit test against
 * N_V*_Serial on random vectors, aliased arguments included).
 */
#ifndef RC_NVFAST_H
#define RC_NVFAST_H

#include <nvector/nvector_serial.h>

/* Install the operations in v's table (v: a serial vector). */
void rc_nvector_fast(N_Vector v);

#endif
