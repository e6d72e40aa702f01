/*
 * Friction of one interface: TYPE6's own (Sfric + Fric f_ff f_fv) or a
 * /FRICTION law that overrides it (docs/theory.md 6). One parameter record per
 * interface, resolved at compile time (model/friction.c); the kernel is in
 * kernels.inc (friction()). docs/theory.md 3.5 and 6.
 */
#ifndef RC_FRICTION_H
#define RC_FRICTION_H

enum { RC_FK_NONE = 0, RC_FK_TYPE6 = 1, RC_FK_CARD = 2, RC_FK_STEP5 = 3 }; /* law source */
/* step5 friction of /INTER/POWER (kind RC_FK_STEP5, form viscous, no state;
 * step5.h): its parameters in set[0]; slip = 1 means capped at f_max. */
enum { RC_S5_MUS = 0, RC_S5_VS = 1, RC_S5_MUD = 2, RC_S5_VD = 3, RC_S5_FMAX = 4 };
enum { RC_FF_VISCOUS = 1, RC_FF_INCREMENTAL = 2 };               /* formulation */
enum { RC_FS_C1 = 0, RC_FS_FRIC = 6, RC_FS_VISF = 7, RC_FS_N = 8 }; /* set layout */

typedef struct rc_fric {
    int kind;             /* RC_FK_*                                           */
    int form;             /* RC_FF_*: TYPE6 is incremental                     */
    int ifric;            /* /FRICTION law: 0 Coulomb, 1 viscous, 2 Darmstad, 3 Renard */
    int ortho;            /* 1: two coefficient sets, elliptic limit          */
    double set[2][RC_FS_N]; /* C1..C6, Fric, VISF per direction              */
    double sfric;         /* TYPE6 static friction force [N]                   */
    double fric;          /* TYPE6 Coulomb coefficient [-]                     */
    int fct_ff, fct_fv;   /* TYPE6 multiplier curves, table index or -1        */
    double kt;            /* incremental (stick) stiffness [N/m]               */
    double fband;         /* force tolerance of the slip test: the absolute
                             tolerance of F_t (scales.c) [N]                   */
    double ct;            /* stick damping 2 zeta_t sqrt(kt m_red), zeta_t = 1
                             (critical), set with the scales [N s/m]           */
    double tau;           /* filter time constant [s], 0: no filter            */
    double area;          /* area for the contact pressure p = F_n / area [m^2] */
    double mred;          /* reduced mass of the two bodies [kg]               */
    double odir[3];       /* orthotropy: vector V, in the frame of obody       */
    int obody;            /* body carrying V, -1: global                        */
    int oside;            /* +1: V on the first surface's side, -1: the second's;
                             PHI turns about that surface's outward normal     */
    double ophi;          /* angle from V about the normal [rad]               */
    int card_id;          /* /FRICTION id, 0 for TYPE6's own                   */
    int tidx;             /* own-state index of F_t (incremental), -1          */
    int fidx;             /* own-state index of the filtered force, -1         */
    int widx;             /* own-state index of W_fric, -1 when no friction    */
    int exact;            /* 1: exact stick (TYPE6 Istick 1, /FRICTION Iform 3): while
                             sticking the tangential relative velocity is held at
                             zero by a constraint of the IDA path (engine/constraints/stick.h),
                             no stick spring; sliding as the incremental form     */
    double mus;           /* exact stick: static coefficient of the stick limit
                             Sfric + mus F_n [-]                                  */
} rc_fric;

#endif
