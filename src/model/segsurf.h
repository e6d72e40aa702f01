/*
 * Segment surfaces (/SURF/SEG, /SURF/PART) into the model (model/segsurf.c):
 * nodes and segments in the carrying body's frame (model.h, surf_nadr ...).
 */
#ifndef RC_SEGSURF_H
#define RC_SEGSURF_H

#include "case/case.h"
#include "model/model.h"

/* Surface s of the case (a /SURF/SEG or /SURF/PART card) into the model:
 * kind RC_SURF_SEG, its body (that of its nodes, -1: fixed in space), its
 * nodes and segments appended after those of surface s - 1 (surf_nadr[s]
 * and surf_sadr[s] set; fills [s + 1]). Bodies are compiled. */
rc_status rc_seg_surface(const rc_case *c, rc_model *m, int s, rc_error *err);

#endif
