/*
 * Private interface of the case stage, shared by reader.c (files, lines,
 * blocks), fields.c (fields, numbers, errors, card headers), cards.c (the
 * dispatch) and cards_*.c (one function per card, one file per family).
 * Nothing outside src/case includes it.
 *
 * Reading happens in three passes:
 *  1. lex: every file (main + #include, then a Radioss engine file
 *     NAME_0001.rad next to a starter NAME_0000.rad) is read whole, split
 *     into lines, comments dropped, and appended to one flat list of lines,
 *     each with its file:line; /END or #enddata ends the file it is in.
 *  2. blocks: the flat list is cut at header lines ("/KEYWORD...") into
 *     blocks; /BEGIN and /UNIT are read first (version and units), then
 *     each other block is dispatched to its card function. An input error
 *     ends its card; reading goes on up to RC_CASE_MAX_ERRORS errors.
 *  3. checks over the whole deck: duplicate ids, the required /RUN.
 *
 * Data lines are parsed through field tables (rc_field): each card function
 * declares the layout of a line as an array of fields (name, width, type,
 * default, checks, destination) and rc_parse_line does the rest.
 */
#ifndef RC_CASE_INTERNAL_H
#define RC_CASE_INTERNAL_H

#include "case/case.h"

#include <stddef.h>
#include <sys/types.h>

/* ---- Limits (documented in docs/case-format.md) ----------------------- */
#define RC_CASE_MAX_LINE 1000            /* characters per line           */
#define RC_CASE_MAX_INCLUDE_DEPTH 32     /* nested #include levels        */
#define RC_CASE_MAX_FILE_READS 4096      /* files opened per deck         */
#define RC_CASE_MAX_BYTES (256L << 20)   /* bytes read per deck, all files */
#define RC_CASE_TITLE_MAX 100            /* title characters              */
#define RC_CASE_INERTIA_RTOL 1e-12       /* PD test: pivot > rtol * diagonal */
#define RC_CASE_MAX_ERRORS 20            /* input errors reported per run  */
#define RC_CASE_MAX_ERROR_CHARS 380      /* characters of each error after the first */

/* One line of the deck, after comment removal. `text` is NUL-terminated,
 * trailing blanks and CR removed; it points into a file buffer. */
typedef struct rc_line {
    const char *text;
    int len;
    rc_loc loc;
} rc_line;

/* A card: its header line and the lines up to the next header. */
typedef struct rc_block {
    const rc_line *hdr;
    const rc_line *lines; /* data lines (title line included) */
    int n;
    char kw[3][24];       /* keyword tokens, upper case: "INTER", "TYPE6" */
    int nkw;
    int id;               /* first numeric token, 0 if none */
    int has_id;
    int unit_id;          /* second numeric token, 0 if none */
    char name[88];        /* the header as written, for messages */
    const char *bad;      /* why the header is malformed (NULL: it is not) */
} rc_block;

/* Card kinds whose ids must be unique (one id space per kind). */
typedef enum {
    RC_IDK_FUNCT, RC_IDK_NODE, RC_IDK_GRNOD, RC_IDK_RBODY, RC_IDK_SURF,
    RC_IDK_INTER, RC_IDK_INIVEL, RC_IDK_GRAV, RC_IDK_BCS, RC_IDK_COUPLING, RC_IDK_PART,
    RC_IDK_GRPART, RC_IDK_FRICTION, RC_IDK_FRICORIENT, RC_IDK_IMPVEL,
    RC_IDK_SHELL, RC_IDK_SOLID, RC_IDK_PROP, RC_IDK_MAT, RC_IDK_SKEW, RC_IDK_ADMAS, /* cards_mesh.c */
    RC_IDK_JOINT, /* cards_joints.c */
    RC_IDK_RWALL, RC_IDK_SENSOR, /* cards_rwall.c */
    RC_IDK_SPRING, /* cards_mesh.c: /SPRING elements */
    RC_IDK_LINE,   /* cards_surfaces.c: /LINE */
    RC_IDK_COUNT
} rc_id_kind;

/* One id as declared, for the duplicate check. */
typedef struct rc_id_entry {
    int id;
    int seq;              /* declaration order */
    rc_loc loc;
    const char *card;     /* header text (valid while the reader lives) */
} rc_id_entry;

/* One --set override (override.c): "/KEYWORD/.../ID:FIELD[k]=VALUE". The
 * value replaces the deck's text of the field when the card's data line is
 * parsed (rc_parse_line), which then parses, checks and converts it as deck
 * input. */
typedef struct rc_override {
    const char *arg;      /* the argument as given (the caller's, for messages) */
    char kw[3][24];       /* the card's keywords, upper case                */
    int nkw, id, has_id;  /* and its id (as in a deck header)               */
    char field[32];       /* the field's name as given (matched ignoring case) */
    int index;            /* k of FIELD[k]: the k-th occurrence in the card
                             (1-based); 0: the field's only occurrence      */
    const char *val;      /* the value's text, blanks trimmed (in arg)      */
    int nval;
    int in_card;          /* the card being read is the one addressed       */
    int ncards;           /* cards of the deck that it addresses            */
    int seen;             /* occurrences of the field in the card           */
    int absent;           /* occurrences on lines the deck's card lacks     */
} rc_override;

/* The reader's state. The case being filled is `c`; capacities of its
 * arrays are kept here. */
typedef struct rc_reader {
    rc_case *c;
    rc_error *err;

    char **bufs; int nbufs, capbufs;          /* file contents, kept alive  */
    rc_line *lines; int nlines, caplines;     /* flat list of lines         */
    long bytes_read;                          /* all files                  */
    int file_reads;                           /* files opened               */
    int capfiles, capfileid;
    struct { dev_t dev; ino_t ino; } stack[RC_CASE_MAX_INCLUDE_DEPTH + 1];
    int depth;                                /* include stack              */
    int file_ended;                           /* /END or #enddata seen in the
                                                 file being lexed           */
    int main_last_line;                       /* for deck-level messages    */
    long main_bytes;                          /* size of the main file      */

    int capfunct, capnode, capgrnod, caprbody, capsurf, captype6, capinivel,
        capgrav, capbcs, capwarn, capcoupling, capjoint, cappart, capgrpart, capfriction, capfricorient,
        cappower, capimpvel, caprwall, capsensor, captype7, captype24, capline;
    rc_id_entry *ids[RC_IDK_COUNT];
    int nids[RC_IDK_COUNT], capids[RC_IDK_COUNT];
    int seq;
    const rc_line *begin_hdr, *run_hdr, *solver_hdr; /* single cards */
    const rc_line *engine_run_hdr;            /* Radioss engine /RUN/name/n */
    double engine_tstop;                      /* its Tstop [s]              */
    const rc_line *anim_dt_hdr;               /* engine /ANIM/DT            */
    double anim_dt;                           /* its Tfreq [s]              */
    int engine_pass;                          /* lexing the engine file     */
    /* unit systems: /BEGIN's input units (index -1) and the /UNIT cards */
    double begin_units[3];                    /* kg, m, s values; 1 if blank */
    struct rc_unitsys { int id; double f[3]; rc_loc loc; } *units;
    int nunits, capunits;
    const double *cur_units;                  /* the card being read's system */
    int converted;                            /* some system is not SI       */
    int nerrors;                              /* input errors so far        */
    char *more;                               /* errors after the first, "\n"
                                                 before each (malloc)       */
    struct { char kw[24]; int warning, count; } skipped[64]; /* cards skipped
                                                 with one warning per kind */
    int nskipped;
    /* --set overrides (override.c) */
    rc_override *ovr; int novr;
    const rc_block *ovr_block;                /* the card being read, when an
                                                 override addresses it       */
    char ovr_names[512];                      /* its numeric fields so far, for
                                                 messages: "A, B, C"         */
    const char *set_arg;                      /* the --set argument whose value
                                                 is being parsed: messages start
                                                 "--set ARG" (not file:line) */
} rc_reader;

/* ---- Field tables ----------------------------------------------------- */
typedef enum { RC_FT_INT, RC_FT_REAL, RC_FT_SKIP, RC_FT_STR } rc_ftype;

enum {
    RC_FF_ZDEF = 1u << 0,   /* 0 means "default" (Radioss convention)         */
    RC_FF_POS = 1u << 1,    /* value > 0 after defaulting                     */
    RC_FF_NONNEG = 1u << 2, /* value >= 0 after defaulting                    */
    RC_FF_ONLY0 = 1u << 3   /* anything but 0 is "not supported yet"          */
};

typedef struct rc_field {
    const char *name;  /* as in the Radioss documentation */
    int width;         /* characters in fixed format */
    rc_ftype type;
    void *out;         /* int *, double *, or char[cap] (may be NULL: read, ignored) */
    size_t cap;        /* RC_FT_STR: size of the buffer */
    double def;        /* default when blank (and 0 with RC_FF_ZDEF) */
    unsigned flags;
    unsigned valid;    /* ints: bit k set = k allowed (0: no set check) */
    unsigned supp;     /* ints: bit k set = k supported (0: all) */
    int dim;           /* reals: RC_DIM of the value (0: unknown) */
    const char *note;  /* explains a "not supported yet" */
    /* filled by rc_parse_line */
    int blank;
    char got[64];      /* "\"text\"" or "blank", for messages */
} rc_field;

#define RC_BIT(k) (1u << (k))

#define RC_F_INT(nm, p, d, fl) \
    { .name = (nm), .width = 10, .type = RC_FT_INT, .out = (p), .def = (d), .flags = (fl) }
#define RC_F_REAL(nm, p, d, fl) \
    { .name = (nm), .width = 20, .type = RC_FT_REAL, .out = (p), .def = (d), .flags = (fl) }
#define RC_F_SET(nm, p, d, fl, v, s, nt)                                               \
    { .name = (nm), .width = 10, .type = RC_FT_INT, .out = (p), .def = (d), .flags = (fl), \
      .valid = (v), .supp = (s), .note = (nt) }
#define RC_F_SKIP(w) { .name = "blank", .width = (w), .type = RC_FT_SKIP }
/* A real with its dimension (converted from the card's unit system to SI). */
#define RC_F_REALD(nm, p, d, fl, dm) \
    { .name = (nm), .width = 20, .type = RC_FT_REAL, .out = (p), .def = (d), .flags = (fl), .dim = (dm) }
/* The same with a width of the older layouts (8-character integers,
 * 16-character reals of Radioss 4.x). */
#define RC_F_INTW(nm, p, d, fl, w) \
    { .name = (nm), .width = (w), .type = RC_FT_INT, .out = (p), .def = (d), .flags = (fl) }
#define RC_F_REALW(nm, p, d, fl, w, dm)                                                 \
    { .name = (nm), .width = (w), .type = RC_FT_REAL, .out = (p), .def = (d), .flags = (fl), \
      .dim = (dm) }
#define RC_F_SETW(nm, p, d, fl, v, s, nt, w)                                          \
    { .name = (nm), .width = (w), .type = RC_FT_INT, .out = (p), .def = (d), .flags = (fl), \
      .valid = (v), .supp = (s), .note = (nt) }
#define RC_F_STR(nm, buf, w) \
    { .name = (nm), .width = (w), .type = RC_FT_STR, .out = (buf), .cap = sizeof(buf) }

/* ---- Reader services (fields.c) ---------------------------------------- */

/* Record an input error "FILE:LINE: card C, field F: msg" (card and field
 * may be NULL; "--set ARG" instead of FILE:LINE while rd->set_arg is set)
 * and return RC_EINPUT. */
rc_status rc_case_fail(rc_reader *rd, const rc_loc *loc, const char *card,
                       const char *field, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
rc_status rc_case_nomem(rc_reader *rd);

/* Parse one data line of block `b` into the fields (fixed or comma format),
 * apply defaults and the per-field checks. */
rc_status rc_parse_line(rc_reader *rd, const rc_block *b, const rc_line *ln, rc_field *f,
                        int nf);

/* Check the number of lines of a fixed-layout card: a title line when
 * `title` is not NULL (copied there), then min..max data lines described by
 * `desc`. Extra blank lines are ignored, extra non-blank lines are an
 * error. Returns the number of data lines to read in *ndata. */
rc_status rc_card_lines(rc_reader *rd, const rc_block *b, char *title, int min, int max,
                        const char *desc, int *ndata);
/* Number of lines of a variable-length block without trailing blank lines. */
int rc_block_trim(const rc_block *b);
/* Copy a title line (at most RC_CASE_TITLE_MAX characters). */
rc_status rc_read_title(rc_reader *rd, const rc_block *b, const rc_line *ln, char *title);

/* Make room for element n of array `arr` (capacity *cap, elements of `size`
 * bytes) and zero it. Returns the array, possibly moved; NULL when out of
 * memory (recorded; `arr` is then unchanged and still owned by the caller). */
void *rc_case_grow(rc_reader *rd, void *arr, int *cap, int n, size_t size);
/* rc_case_grow on an array lvalue; returns RC_ENOMEM from the calling
 * function on failure (like RC_RAISE). */
#define RC_GROW(rd, arr, cap, n)                                               \
    do {                                                                       \
        void *rc_grown_ = rc_case_grow((rd), (arr), &(cap), (n), sizeof *(arr)); \
        if (!rc_grown_) return RC_ENOMEM;                                      \
        (arr) = rc_grown_;                                                     \
    } while (0)
/* Declare an id for the duplicate check. */
rc_status rc_note_id(rc_reader *rd, rc_id_kind kind, int id, const rc_loc *loc,
                     const char *card);
/* Append a warning "FILE:LINE: msg" to c->warnings. */
rc_status rc_case_warn(rc_reader *rd, const rc_loc *loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* ---- Units (units.c) -------------------------------------------------- */

/* Dimension of a real field: exponents of mass, length, time (-8..7).
 * 0 is "unknown" (a value that is not 0 cannot be converted). */
#define RC_DIM(m, l, t) ((1 << 12) | (((m) + 8) << 8) | (((l) + 8) << 4) | ((t) + 8))
#define RC_D_NONE RC_DIM(0, 0, 0)   /* dimensionless, angles in degrees */
#define RC_D_M RC_DIM(1, 0, 0)      /* kg */
#define RC_D_L RC_DIM(0, 1, 0)      /* m */
#define RC_D_T RC_DIM(0, 0, 1)      /* s */
#define RC_D_AREA RC_DIM(0, 2, 0)   /* m^2 */
#define RC_D_V RC_DIM(0, 1, -1)     /* m/s */
#define RC_D_W RC_DIM(0, 0, -1)     /* rad/s, Hz */
#define RC_D_ACC RC_DIM(0, 1, -2)   /* m/s^2 */
#define RC_D_F RC_DIM(1, 1, -2)     /* N */
#define RC_D_K RC_DIM(1, 0, -2)     /* N/m */
#define RC_D_K2 RC_DIM(1, -1, -2)   /* N/m^2 */
#define RC_D_K3 RC_DIM(1, -2, -2)   /* N/m^3 */
#define RC_D_C RC_DIM(1, 0, -1)     /* N s/m */
#define RC_D_J RC_DIM(1, 2, 0)      /* kg m^2 */
#define RC_D_E RC_DIM(1, 2, -2)     /* J */
#define RC_D_LIN RC_DIM(1, -1, 0)   /* kg/m */

/* Value in kg (kind 0), m (1) or s (2) of a unit name of /BEGIN or /UNIT
 * (or of a positive number, the unit's value in SI). 0: unknown name. */
int rc_unit_factor(int kind, const char *name, double *si);
/* The accepted names of a kind, for messages. */
const char *rc_unit_names(int kind);
/* Factor from a unit system (kg, m, s values of its units) to SI for a
 * dimension. */
double rc_dim_scale(int dim, const double f[3]);

/* ---- Layouts by version (fields.c) ------------------------------------ */

/* The newest Radioss version whose layouts ricochet reads (used when the
 * deck has no /BEGIN version). */
#define RC_LATEST_VERSION 2026
/* The version that picks the layouts: /BEGIN Invers, else the newest. */
int rc_layout_version(const rc_reader *rd);
/* 1 when v is a Radioss version listed in docs/case-format.md. */
int rc_layout_known(int v);

/* ---- Card services (fields.c) ----------------------------------------- */

/* How a card's header carries numbers. */
typedef enum { RC_ID_NONE, RC_ID_REQUIRED, RC_ID_OPTIONAL, RC_ID_UNIT } rc_id_mode;

/* Parse the header text b->hdr->text, "/KW[/SUB]/id[/unit_id]", into b:
 * keywords (upper case), id, unit id, b->name; a malformed header sets
 * b->bad (why). */
void rc_parse_header(rc_block *b);
/* Check the header of a card with `nkw` keywords: id and unit id. */
rc_status rc_header(rc_reader *rd, const rc_block *b, int nkw, rc_id_mode mode,
                    const char *idname, const char *usage);
/* Lines of a card of variable length: title, then any number of lines
 * (trailing blank lines dropped). */
rc_status rc_var_lines(rc_reader *rd, const rc_block *b, char *title, const char *desc,
                       int *ndata);

/* Number of entries of a field table. */
#define RC_NF(arr) ((int)(sizeof(arr) / sizeof((arr)[0])))
/* An integer field with a "not supported yet" note. */
#define RC_F_INTN(nm, p, fl, nt) RC_F_SET(nm, p, 0, fl, 0, 0, nt)

/* ---- Card families (cards_*.c), called by the dispatch (cards.c) ------ */

/* Bodies and nodes (cards_bodies.c). */
rc_status rc_card_node(rc_reader *rd, const rc_block *b);
rc_status rc_card_grnod(rc_reader *rd, const rc_block *b);
rc_status rc_card_rbody(rc_reader *rd, const rc_block *b);
rc_status rc_card_part(rc_reader *rd, const rc_block *b);
rc_status rc_card_grpart(rc_reader *rd, const rc_block *b);
rc_status rc_card_line(rc_reader *rd, const rc_block *b);
rc_status rc_card_type11(rc_reader *rd, const rc_block *b);
rc_status rc_card_type19(rc_reader *rd, const rc_block *b);
/* After the last card: expand /GRPART/GRPART into part lists. */
rc_status rc_cards_grpart_finish(rc_reader *rd);

/* Joints (cards_joints.c). */
rc_status rc_card_joint(rc_reader *rd, const rc_block *b);

/* Surfaces (cards_surfaces.c). */
rc_status rc_card_plane(rc_reader *rd, const rc_block *b);
rc_status rc_card_ellips(rc_reader *rd, const rc_block *b);
rc_status rc_card_cyl(rc_reader *rd, const rc_block *b);
rc_status rc_card_box(rc_reader *rd, const rc_block *b);
rc_status rc_card_seg(rc_reader *rd, const rc_block *b);
rc_status rc_card_surfpart(rc_reader *rd, const rc_block *b);

/* Interfaces (cards_interfaces.c). */
rc_status rc_card_type6(rc_reader *rd, const rc_block *b);
rc_status rc_card_power(rc_reader *rd, const rc_block *b);
rc_status rc_card_type7(rc_reader *rd, const rc_block *b);
rc_status rc_card_type24(rc_reader *rd, const rc_block *b);
rc_status rc_card_type25(rc_reader *rd, const rc_block *b);
/* cards_rwall.c */
rc_status rc_card_rwall(rc_reader *rd, const rc_block *b);
rc_status rc_card_sensor_time(rc_reader *rd, const rc_block *b);

/* Friction (cards_friction.c). */
rc_status rc_card_friction(rc_reader *rd, const rc_block *b);
rc_status rc_inter_friction(rc_reader *rd, const rc_block *b, int nd, const rc_field *f6, int ifric, int ifiltr,
                            double xfreq, int iform, double fric, double visf, int *fric_id, int *nlaw);
rc_status rc_card_fricorient(rc_reader *rd, const rc_block *b);

/* Couplings (cards_couplings.c). */
rc_status rc_card_coupling_spring(rc_reader *rd, const rc_block *b);
rc_status rc_card_coupling_catenary(rc_reader *rd, const rc_block *b);
rc_status rc_card_coupling_contact(rc_reader *rd, const rc_block *b);

/* Curves, initial and boundary conditions, loads (cards_loads.c). */
rc_status rc_card_funct(rc_reader *rd, const rc_block *b);
rc_status rc_card_inivel(rc_reader *rd, const rc_block *b);
rc_status rc_card_grav(rc_reader *rd, const rc_block *b);
rc_status rc_card_bcs(rc_reader *rd, const rc_block *b);
rc_status rc_card_impvel(rc_reader *rd, const rc_block *b);

/* Run, solver and output (cards_run.c); deck-level defaults and checks. */
rc_status rc_card_begin(rc_reader *rd, const rc_block *b);
rc_status rc_card_run(rc_reader *rd, const rc_block *b);
rc_status rc_card_solver(rc_reader *rd, const rc_block *b);
/* Radioss engine cards read for the run settings: /RUN/name/n[/letter]
 * (Tstop) and /ANIM/DT (Tstart Tfreq). */
rc_status rc_card_engine_run(rc_reader *rd, const rc_block *b);
rc_status rc_card_anim_dt(rc_reader *rd, const rc_block *b);
/* /UNIT/unit_ID (cards_run.c): title; MUNIT LUNIT TUNIT. */
rc_status rc_card_unit(rc_reader *rd, const rc_block *b);
/* 1 when the card being read has a unit system other than SI. */
int rc_units_convert(const rc_reader *rd);
/* Deck-level checks after the last card (/RUN present, defaults). */
rc_status rc_cards_finish(rc_reader *rd);
/* Defaults of the optional cards, set before reading. */
void rc_cards_defaults(rc_case *c);

/* Mesh cards (cards_mesh.c): /SHELL /SH3N /BRICK /TETRA4 /SPRING /PROP/SHELL
 * /PROP/SOLID /PROP/SPRING /MAT /SKEW/FIX /GRNOD/PART /GRNOD/GRNOD /ADMAS. *handled = 0 for a
 * card that is not one of them (the dispatch goes on). */
rc_status rc_cards_mesh(rc_reader *rd, const rc_block *b, int *handled);
/* After the last card: expand /GRNOD/PART and /GRNOD/GRNOD into node lists. */
rc_status rc_cards_mesh_finish(rc_reader *rd);
/* /INIVEL and /GRAV skew frames into global axes (after rc_cards_mesh_finish) */
rc_status rc_cards_loads_finish(rc_reader *rd);
/* /FRIC_ORIENT skew_ID: V from the skew's X' axis (after rc_cards_mesh_finish) */
rc_status rc_cards_fricorient_finish(rc_reader *rd);
/* The index of the skew `id` named by `card` (field skew_ID, line `at`), or
 * a failure: no such skew; a moving skew when `what` (the use refused) is
 * not NULL. */
rc_status rc_case_ref_skew(rc_reader *rd, const rc_loc *at, const char *card, int id, const char *what, int *out);

/* ---- Dispatch (cards.c) ------------------------------------------------ */

/* Read one block: dispatch on its keyword. */
rc_status rc_card_dispatch(rc_reader *rd, const rc_block *b);

/* ---- --set overrides (override.c) -------------------------------------- */

/* Parse the arguments "/KEYWORD/.../ID:FIELD[k]=VALUE" into rd->ovr (the
 * strings must outlive the reading); a malformed one or a field set twice
 * is an input error naming it. */
rc_status rc_override_parse(rc_reader *rd, const char *const *set, int nset);
/* Around the reading of block b: mark the overrides that address it; then
 * check that each found its field once (`clean`: the card was read without
 * an error, so all its fields were seen). */
void rc_override_card_begin(rc_reader *rd, const rc_block *b);
rc_status rc_override_card_end(rc_reader *rd, const rc_block *b, int clean);
/* After the last card: every override addressed one card of the deck; the
 * list "ARG; ARG" into c->overrides. */
rc_status rc_override_finish(rc_reader *rd);

#endif
