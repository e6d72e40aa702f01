/*
 * Instantiate the kernel templates (.inc) included next in complex
 * arithmetic, for complex-step derivatives (cstep.h; kernels.inc, "Names"):
 * T = rc_cx (double complex), RE(x) its real part, RCK(name) the name_c a
 * call reaches, RCKDEF(name_r, name_c) the name_c a definition defines.
 * Undone by as_done.h (a file that instantiates twice). No include guard:
 * one inclusion per instantiation.
 */
#include "engine/kernels/cstep.h"

#define T rc_cx
#define RE(x) creal(x)
#define RCK(name) name##_c
#define RCKDEF(name_r, name_c) name_c
