/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/mtt_io.h - libmtt_io, the host I/O library of mtt-track, mtt-bench
 * and the fuzz harnesses: the settings JSON, the detections CSV and the
 * tracks CSV of docs/FORMATS.md, one job per file:
 *
 *   error.c       the one-line messages        number.c   numbers in text
 *   file.c        opening and reading files    csv.c      the CSV line reader
 *   detections.c  *.det.csv                    settings.c settings JSON (the
 *   tracks.c      *.tracks.csv                            parameter table)
 *
 * Not part of the library: this module uses stdio, malloc and cJSON.  Every
 * reader validates the whole file and reports the first problem as one line
 * on stderr:
 *
 *     PROG: FILE:LINE: field 'NAME': message      (CSV)
 *     PROG: FILE: key 'PATH': message             (JSON)
 *
 * and returns MTT_IO_EINPUT (bad input: exit code 2) or MTT_IO_ESYS (out of
 * memory, read error: exit code 1).
 */
#ifndef MTT_IO_MTT_IO_H
#define MTT_IO_MTT_IO_H

#include <stddef.h>
#include <stdio.h>

#include "mtt/mtt.h"

#if defined(__GNUC__) || defined(__clang__)
#define MTT_IO_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define MTT_IO_PRINTF(f, a)
#endif

/** "float", "double" or "fixed": mtt_real, for messages. */
#if defined(MTT_REAL_FIXED)
#define MTT_IO_REAL_NAME "fixed"
#elif defined(MTT_REAL_DOUBLE)
#define MTT_IO_REAL_NAME "double"
#else
#define MTT_IO_REAL_NAME "float"
#endif

/** The format of each kind of number at the boundary, for mtt_io_to_real
 *  and mtt_io_from_real.  In the fixed-point build (docs/FIXED_POINT.md §3)
 *  the Q format's fraction bits: positions, velocities and measurement
 *  sigmas in the declared position format; amplitudes in the declared
 *  amplitude format; times (counted from the first scan) in Q16 of the
 *  files' time unit, which is the nominal frame interval T0; covariance
 *  entries (initial_tracks' P, the tracks' pxx, pxy, pyy) in the variance
 *  format; existence and model probabilities in Q30.  Settings keys take
 *  their row's format inside mtt_params_set/get.  Float and double: 0,
 *  unused. */
#if defined(MTT_REAL_FIXED)
#define MTT_IO_POS MTT_FX_POS_FRAC
#define MTT_IO_AMP MTT_FX_AMP_FRAC
#define MTT_IO_TIME MTT_FX_T_FRAC
#define MTT_IO_VAR MTT_FX_VAR_FRAC
#define MTT_IO_PROB MTT_FX_PROB_FRAC
#else
#define MTT_IO_POS 0
#define MTT_IO_AMP 0
#define MTT_IO_TIME 0
#define MTT_IO_VAR 0
#define MTT_IO_PROB 0
#endif

/** Result of a reader; the values are the process exit codes. */
enum {
    MTT_IO_OK = 0,
    MTT_IO_ESYS = 1,   /**< a system failure: memory, I/O */
    MTT_IO_EINPUT = 2  /**< malformed input, already reported */
};

/** Prefix of every message ("mtt-track"); set once by main. */
extern const char *mtt_io_progname;

/* ---- messages --------------------------------------------------------- */

/** "PROG: FILE:LINE: field 'FIELD': message"; line <= 0 or field NULL omit
 *  those parts. */
void mtt_io_error_at(const char *file, long line, const char *field, const char *fmt, ...)
    MTT_IO_PRINTF(4, 5);

/** "PROG: FILE: key 'KEY': message" (KEY is a JSON path such as
 *  "meas_sigma[1]"); key NULL omits it. */
void mtt_io_error_key(const char *file, const char *key, const char *fmt, ...)
    MTT_IO_PRINTF(3, 4);

/** "PROG: message". */
void mtt_io_error(const char *fmt, ...) MTT_IO_PRINTF(1, 2);

/* ---- numbers ---------------------------------------------------------- */

/** Outcome of parsing one field. */
typedef enum mtt_io_num {
    MTT_IO_NUM_OK = 0,
    MTT_IO_NUM_EMPTY,     /**< empty field */
    MTT_IO_NUM_SYNTAX,    /**< not a number, or trailing characters */
    MTT_IO_NUM_NONFINITE, /**< nan or inf (an error in files) */
    MTT_IO_NUM_RANGE      /**< overflows double, or the integer type */
} mtt_io_num;

/** Parse a whole field as a finite double with strtod (all of it consumed). */
mtt_io_num mtt_io_parse_double(const char *s, double *out);

/** Parse a whole field as a non-negative decimal integer (digits only). */
mtt_io_num mtt_io_parse_count(const char *s, unsigned long *out);

/** The one conversion of a file's number into mtt_real: float and double
 *  a cast (fmt unused), 0 if the value overflows the type (*out
 *  unchanged); the fixed-point build round(v 2^fmt) (mtt_fx_from_double),
 *  0 if it lies outside the format, with *out the saturation value of its
 *  sign: never a wrapped value (measure.c skips and counts such a
 *  detection).  Returns 1 when v fits. */
int mtt_io_to_real(double v, int fmt, mtt_real *out);

/* Write the prepared parameter set pp (mtt_params_prepare) as C: a
 * definition `static const mtt_prepared <name> = {...};` that a firmware of
 * the same configuration compiles and hands to mtt_tracker_load
 * (docs/FIRMWARE.md).  Returns 0, or -1 on a write error or if pp is not a
 * prepared set. */
int mtt_io_write_prepared(FILE *f, const mtt_prepared *pp, const char *name);

/** mtt_real of format fmt (MTT_IO_POS, ...) as a double in the user's
 *  units: exact. */
double mtt_io_from_real(mtt_real r, int fmt);

/** Write v with the fewest significant digits (at most 17) that read back
 *  as the same double.  buf needs 32 bytes. */
void mtt_io_format_double(double v, char *buf, size_t size);

/* ---- files ------------------------------------------------------------ */

/** fopen for reading; reports (and returns NULL) when it cannot, or when
 *  path is a directory. */
FILE *mtt_io_open(const char *path, const char *mode);

/** The whole file as a NUL-terminated string (*text, to free; *size bytes
 *  before the NUL).  Reports and returns MTT_IO_EINPUT / MTT_IO_ESYS. */
int mtt_io_read_text(const char *path, char **text, size_t *size);

/* ---- CSV -------------------------------------------------------------- */

/** A line reader over one file: comments ('#' first) and blank lines are
 *  skipped, "\r\n" and a UTF-8 byte order mark are accepted. */
typedef struct mtt_io_csv {
    const char *path;  /**< as given by the user: used in messages */
    FILE *fp;
    char *buf;         /**< current line (owned) */
    size_t cap;
    long line;         /**< 1-based number of the current line */
    char **fields;     /**< the current line's fields (into buf) */
    size_t n_fields, cap_fields;
    int polar_form;    /**< detections.c: the file's header is the polar form (its column names) */
} mtt_io_csv;

/** Open path for reading.  Reports and returns MTT_IO_EINPUT if it cannot. */
int mtt_io_csv_open(mtt_io_csv *c, const char *path);

/** Read the next data line and split it at commas; leading and trailing
 *  blanks of each field are removed.  *got is 1 with c->fields set, or 0 at
 *  the end of the file.  Returns MTT_IO_OK, or MTT_IO_ESYS (reported). */
int mtt_io_csv_next(mtt_io_csv *c, int *got);

/** Check the current line against the expected header (every column,
 *  in order, nothing more).  Reports and returns MTT_IO_EINPUT if not. */
int mtt_io_csv_expect_header(mtt_io_csv *c, const char *const *names, size_t n);

void mtt_io_csv_close(mtt_io_csv *c);

/* ---- detections (*.det.csv) ------------------------------------------- */

/** One scan of the detections file. */
typedef struct mtt_io_scan {
    unsigned long scan;  /**< scan number as written */
    double time;         /**< time as written (double) */
    mtt_real rtime;      /**< time as the tracker sees it: time - time0 (the
                              tracker only uses differences, and a float keeps
                              them where it could not keep an epoch time) */
    size_t first;        /**< index of its first detection in meas */
    size_t count;        /**< 0 for an empty scan */
    long line;           /**< line of its first row */
} mtt_io_scan;

/** A whole detections file, validated. */
typedef struct mtt_io_detections {
    mtt_meas *meas;      /**< all detections, file order */
    mtt_meas_cov *cov;   /**< their covariances (header with r_xx,r_xy,r_yy; all 0 where a
                              row leaves them empty), or NULL: the file has none */
    mtt_polar *polar;    /**< is_polar (header scan,time,range,bearing,amplitude): the
                              detections, file order; meas and cov are then NULL */
    int is_polar;
    int has_range_rate;  /**< is_polar: some detection has a range rate */
    long header_line;    /**< the line of the header (after comments) */
    size_t n_meas, cap_meas;
    mtt_io_scan *scans;  /**< scans, file order */
    size_t n_scans, cap_scans;
    double time0;        /**< time of the first scan */
    size_t out_of_range; /**< detections with a value outside the build's range, kept
                              saturated (MTT_IO_SKIP_OUT_OF_RANGE; the tracker skips and
                              counts them in meas_out_of_range) */
} mtt_io_detections;

/** mtt_io_read_detections_opt: a detection with a coordinate or amplitude
 *  outside the build's range (fixed point: +-2^(30-MTT_FX_POS_FRAC), the
 *  amplitude format) is read, saturated, and counted in out_of_range
 *  instead of failing the read. */
#define MTT_IO_SKIP_OUT_OF_RANGE 1u

/** Read and validate a detections file (docs/FORMATS.md).  On failure nothing
 *  needs freeing.  A detection outside the build's range fails the read with
 *  its line, value and the range (mtt_io_read_detections_opt with 0). */
int mtt_io_read_detections(const char *path, mtt_io_detections *d);
int mtt_io_read_detections_opt(const char *path, mtt_io_detections *d, unsigned flags);
void mtt_io_free_detections(mtt_io_detections *d);

/* ---- settings (*.json) ------------------------------------------------ */

/** One entry of `initial_tracks`. */
typedef struct mtt_io_seed {
    mtt_real x[4];       /**< x, y, vx, vy */
    mtt_real P[16];      /**< covariance, row-major (mtt_tracker_add_track) */
    int has_P;           /**< 0: use the two-point covariance */
} mtt_io_seed;

/** Tracker settings: the parameters and the seeded tracks. */
typedef struct mtt_io_settings {
    mtt_params params;
    mtt_io_seed *seeds;
    size_t n_seeds;
} mtt_io_settings;

/** Read a settings file: defaults from mtt_params_default, every key
 *  type-checked, then mtt_params_check (its bad field is reported as the
 *  settings key, with the allowed range).  On failure nothing needs freeing. */
int mtt_io_read_settings(const char *path, mtt_io_settings *s);
void mtt_io_free_settings(mtt_io_settings *s);

/** Print the settings keys as a Markdown table (key, type, range, default,
 *  meaning): mtt_params_info's rows, then initial_tracks.  docs/FORMATS.md
 *  shows this table. */
void mtt_io_list_settings(FILE *out);

/** The settings key of a seeded track's element, for messages
 *  ("initial_tracks[2].P"); buf needs 64 bytes. */
void mtt_io_seed_key(size_t i, const char *member, char *buf, size_t size);

/* ---- tracks (*.tracks.csv) ------------------------------------------- */

/** The header line of a tracks file. */
#define MTT_IO_TRACKS_HEADER "scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy"

/** The header line for parameters p: with motion = imm the trailing
 *  columns mu_0 .. mu_{r-1} (docs/FORMATS.md). */
void mtt_io_write_tracks_header(FILE *out, const mtt_params *p);

/** Write the rows of trk's live tracks after scan sc (confirmed ones only
 *  if confirmed_only), the time as the detections file gave it; adds the
 *  rows written to *rows.  Returns the first failing mtt_status. */
mtt_status mtt_io_write_tracks(FILE *out, const mtt_tracker *trk, const mtt_io_scan *sc,
                               int confirmed_only, unsigned long *rows);

#endif /* MTT_IO_MTT_IO_H */
