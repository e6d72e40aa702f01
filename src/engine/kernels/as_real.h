/*
 * Instantiate the kernel templates (.inc) included next in real arithmetic
 * (kernels.inc, "Names"): T = double, RE(x) its real part, RCK(name) the
 * name_r a call reaches, RCKDEF(name_r, name_c) the name_r a definition
 * defines. Undone by as_done.h (a file that instantiates twice). No include
 * guard: one inclusion per instantiation.
 */
#define T double
#define RE(x) (x)
#define RCK(name) name##_r
#define RCKDEF(name_r, name_c) name_r
