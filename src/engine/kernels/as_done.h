/*
 * The end of an instantiation (as_real.h, as_complex.h): T, RE, RCK and
 * RCKDEF undefined, for the next instantiation or for the code that follows.
 * No include guard.
 */
#undef T
#undef RE
#undef RCK
#undef RCKDEF
