/* tools/mtt_io.c - host-only readers for mtt-track (see mtt_io.h).
 *
 * Detections CSV and settings JSON of FORMATS.md.  Every check reports the
 * first problem with the file, the line (CSV) or key path (JSON), and the
 * field, then gives up: a bad file never produces partial output.
 */
#define _POSIX_C_SOURCE 200809L /* getline */

#include "mtt_io.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cJSON.h>

#ifdef MTT_REAL_DOUBLE
#define REAL_NAME "double"
#else
#define REAL_NAME "float"
#endif

const char *mtt_io_progname = "mtt-track";

/* ====================================================================== */
/* messages                                                                */
/* ====================================================================== */

void mtt_io_error_at(const char *file, long line, const char *field, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: %s:", mtt_io_progname, file);
    if (line > 0)
        fprintf(stderr, "%ld:", line);
    if (field != NULL)
        fprintf(stderr, " field '%s':", field);
    fputc(' ', stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void mtt_io_error_key(const char *file, const char *key, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: %s:", mtt_io_progname, file);
    if (key != NULL)
        fprintf(stderr, " key '%s':", key);
    fputc(' ', stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void mtt_io_error(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", mtt_io_progname);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* ====================================================================== */
/* numbers                                                                 */
/* ====================================================================== */

mtt_io_num mtt_io_parse_double(const char *s, double *out)
{
    char *end;
    double v;

    if (*s == '\0')
        return MTT_IO_NUM_EMPTY;
    errno = 0;
    v = strtod(s, &end);
    if (end == s || *end != '\0')
        return MTT_IO_NUM_SYNTAX;
    if (isnan(v) || (isinf(v) && errno != ERANGE))
        return MTT_IO_NUM_NONFINITE; /* "nan", "inf", "infinity" */
    if (errno == ERANGE && fabs(v) > 1.0)
        return MTT_IO_NUM_RANGE;     /* overflow; underflow to 0 is fine */
    *out = v;
    return MTT_IO_NUM_OK;
}

mtt_io_num mtt_io_parse_count(const char *s, unsigned long *out)
{
    unsigned long v = 0;
    const char *p;

    if (*s == '\0')
        return MTT_IO_NUM_EMPTY;
    for (p = s; *p != '\0'; ++p) {
        unsigned long d;
        if (*p < '0' || *p > '9')
            return MTT_IO_NUM_SYNTAX;
        d = (unsigned long)(*p - '0');
        if (v > (~0UL - d) / 10UL)
            return MTT_IO_NUM_RANGE;
        v = v * 10UL + d;
    }
    *out = v;
    return MTT_IO_NUM_OK;
}

int mtt_io_to_real(double v, mtt_real *out)
{
    /* Converting a double beyond the float range is undefined: test first. */
    if (!(fabs(v) <= (double)MTT_REAL_MAX))
        return 0;
    *out = (mtt_real)v;
    return 1;
}

void mtt_io_format_double(double v, char *buf, size_t size)
{
    char tmp[32];
    int prec, shortest = 17;

    for (prec = 1; prec <= 17; ++prec) {
        snprintf(tmp, sizeof tmp, "%.*g", prec, v);
        if (strtod(tmp, NULL) == v) {
            shortest = prec;
            break;
        }
    }
    /* Prefer plain notation ("10", not "1e+01") while %g allows it. */
    for (prec = shortest; prec <= 17; ++prec) {
        snprintf(buf, size, "%.*g", prec, v);
        if (strchr(buf, 'e') == NULL)
            return;
    }
    snprintf(buf, size, "%.*g", shortest, v);
}

/* ====================================================================== */
/* CSV                                                                     */
/* ====================================================================== */

/* fopen for reading; a directory is refused here rather than as a read error. */
static FILE *open_input(const char *path, const char *mode)
{
    struct stat st;
    FILE *fp = fopen(path, mode);
    if (fp == NULL) {
        mtt_io_error_at(path, 0, NULL, "cannot open: %s", strerror(errno));
        return NULL;
    }
    if (fstat(fileno(fp), &st) == 0 && S_ISDIR(st.st_mode)) {
        mtt_io_error_at(path, 0, NULL, "cannot open: is a directory");
        fclose(fp);
        return NULL;
    }
    return fp;
}

int mtt_io_csv_open(mtt_io_csv *c, const char *path)
{
    memset(c, 0, sizeof *c);
    c->path = path;
    c->fp = open_input(path, "r");
    return c->fp != NULL ? MTT_IO_OK : MTT_IO_EINPUT;
}

void mtt_io_csv_close(mtt_io_csv *c)
{
    if (c->fp != NULL)
        fclose(c->fp);
    free(c->buf);
    free(c->fields);
    memset(c, 0, sizeof *c);
}

static int is_blank(char ch) { return ch == ' ' || ch == '\t'; }

/* Split c->buf (one line, no terminator) at commas, trimming blanks. */
static int csv_split(mtt_io_csv *c, char *s)
{
    c->n_fields = 0;
    for (;;) {
        char *start, *end, *comma;

        while (is_blank(*s))
            ++s;
        start = s;
        comma = strchr(s, ',');
        end = comma != NULL ? comma : s + strlen(s);
        while (end > start && is_blank(end[-1]))
            --end;
        if (c->n_fields == c->cap_fields) {
            size_t cap = c->cap_fields != 0 ? 2 * c->cap_fields : 8;
            char **f = realloc(c->fields, cap * sizeof *f);
            if (f == NULL) {
                mtt_io_error("out of memory");
                return MTT_IO_ESYS;
            }
            c->fields = f;
            c->cap_fields = cap;
        }
        c->fields[c->n_fields++] = start;
        *end = '\0';
        if (comma == NULL)
            return MTT_IO_OK;
        s = comma + 1;
    }
}

int mtt_io_csv_next(mtt_io_csv *c, int *got)
{
    FILE *fp = c->fp;

    *got = 0;
    for (;;) {
        ssize_t len;
        char *s;

        errno = 0;
        len = getline(&c->buf, &c->cap, fp);
        if (len < 0) {
            if (ferror(fp)) {
                mtt_io_error_at(c->path, c->line + 1, NULL, "read error: %s",
                                errno != 0 ? strerror(errno) : "unknown");
                return MTT_IO_ESYS;
            }
            return MTT_IO_OK; /* end of file */
        }
        ++c->line;
        if (strlen(c->buf) != (size_t)len) {
            mtt_io_error_at(c->path, c->line, NULL, "contains a NUL byte: not a text file");
            return MTT_IO_EINPUT;
        }
        while (len > 0 && (c->buf[len - 1] == '\n' || c->buf[len - 1] == '\r'))
            c->buf[--len] = '\0';
        s = c->buf;
        if (c->line == 1 && (unsigned char)s[0] == 0xEF && (unsigned char)s[1] == 0xBB &&
            (unsigned char)s[2] == 0xBF)
            s += 3; /* UTF-8 byte order mark */
        while (is_blank(*s))
            ++s;
        if (*s == '\0' || *s == '#')
            continue; /* blank line or comment */
        if (csv_split(c, s) != MTT_IO_OK)
            return MTT_IO_ESYS;
        *got = 1;
        return MTT_IO_OK;
    }
}

int mtt_io_csv_expect_header(mtt_io_csv *c, const char *const *names, size_t n)
{
    char want[256], what[160];
    size_t i, j, len = 0;
    const char *field = NULL;

    want[0] = '\0';
    for (i = 0; i < n && len < sizeof want; ++i)
        len += (size_t)snprintf(want + len, sizeof want - len, "%s%s", i != 0 ? "," : "",
                                names[i]);
    for (i = 0; i < n && field == NULL; ++i) {
        if (i < c->n_fields && strcmp(c->fields[i], names[i]) == 0)
            continue;
        field = names[i];
        for (j = 0; j < c->n_fields; ++j)
            if (strcmp(c->fields[j], names[i]) == 0)
                break;
        if (j < c->n_fields)
            snprintf(what, sizeof what, "must be column %lu, found as column %lu",
                     (unsigned long)(i + 1), (unsigned long)(j + 1));
        else if (i < c->n_fields)
            snprintf(what, sizeof what, "missing column (column %lu is '%.60s')",
                     (unsigned long)(i + 1), c->fields[i]);
        else
            snprintf(what, sizeof what, "missing column");
    }
    if (field == NULL && c->n_fields > n) {
        field = c->fields[n];
        snprintf(what, sizeof what, "unexpected extra column");
    }
    if (field == NULL)
        return MTT_IO_OK;
    mtt_io_error_at(c->path, c->line, field, "%s: the header must be '%s'", what, want);
    return MTT_IO_EINPUT;
}

/* ====================================================================== */
/* detections                                                              */
/* ====================================================================== */

enum { COL_SCAN, COL_TIME, COL_X, COL_Y, COL_AMP, N_COLS };
static const char *const det_cols[N_COLS] = {"scan", "time", "x", "y", "amplitude"};

/* Report a field that failed to parse; always MTT_IO_EINPUT. */
static int bad_number(const mtt_io_csv *c, int col, mtt_io_num why, const char *what)
{
    const char *s = c->fields[col];
    switch (why) {
    case MTT_IO_NUM_EMPTY:
        mtt_io_error_at(c->path, c->line, det_cols[col], "missing value: expected %s", what);
        break;
    case MTT_IO_NUM_NONFINITE:
        mtt_io_error_at(c->path, c->line, det_cols[col], "'%s' is not allowed: expected %s", s,
                        what);
        break;
    case MTT_IO_NUM_RANGE:
        mtt_io_error_at(c->path, c->line, det_cols[col], "'%s' is out of range: expected %s", s,
                        what);
        break;
    default:
        mtt_io_error_at(c->path, c->line, det_cols[col], "'%s' is not %s", s, what);
        break;
    }
    return MTT_IO_EINPUT;
}

/* Parse a finite number that fits mtt_real. */
static int field_real(const mtt_io_csv *c, int col, double *d, mtt_real *r)
{
    mtt_io_num e = mtt_io_parse_double(c->fields[col], d);
    if (e != MTT_IO_NUM_OK)
        return bad_number(c, col, e, "a finite number");
    if (!mtt_io_to_real(*d, r)) {
        mtt_io_error_at(c->path, c->line, det_cols[col],
                        "'%s' does not fit the tracker's real type (mtt_real=" REAL_NAME ")",
                        c->fields[col]);
        return MTT_IO_EINPUT;
    }
    return MTT_IO_OK;
}

static void *grow(void *p, size_t *cap, size_t elem)
{
    size_t n = *cap != 0 ? 2 * *cap : 64;
    void *q;
    if (n > ((size_t)-1) / elem)
        return NULL;
    q = realloc(p, n * elem);
    if (q != NULL)
        *cap = n;
    return q;
}

void mtt_io_free_detections(mtt_io_detections *d)
{
    free(d->meas);
    free(d->scans);
    memset(d, 0, sizeof *d);
}

/* Validate and store one data row. */
static int det_row(mtt_io_detections *d, const mtt_io_csv *c, int *scan_has_empty_row)
{
    unsigned long scan;
    double time, x = 0, y = 0, amp = 0;
    mtt_meas m;
    mtt_real rtime;
    mtt_io_num e;
    int empty, rc;
    char t0[32], t1[32];
    mtt_io_scan *prev = d->n_scans != 0 ? &d->scans[d->n_scans - 1] : NULL;

    if (c->n_fields < N_COLS) {
        mtt_io_error_at(c->path, c->line, det_cols[c->n_fields],
                        "missing: the row has %lu fields, expected %d (scan,time,x,y,amplitude)",
                        (unsigned long)c->n_fields, N_COLS);
        return MTT_IO_EINPUT;
    }
    if (c->n_fields > N_COLS) {
        mtt_io_error_at(c->path, c->line, NULL,
                        "the row has %lu fields, expected %d (scan,time,x,y,amplitude)",
                        (unsigned long)c->n_fields, N_COLS);
        return MTT_IO_EINPUT;
    }

    e = mtt_io_parse_count(c->fields[COL_SCAN], &scan);
    if (e != MTT_IO_NUM_OK)
        return bad_number(c, COL_SCAN, e, "a non-negative integer");
    memset(&m, 0, sizeof m);
    if ((rc = field_real(c, COL_TIME, &time, &rtime)) != MTT_IO_OK)
        return rc;
    if (prev == NULL)
        d->time0 = time;
    if (!mtt_io_to_real(time - d->time0, &rtime)) {
        mtt_io_error_at(c->path, c->line, "time", "'%s' is too far from the first scan's time",
                        c->fields[COL_TIME]);
        return MTT_IO_EINPUT;
    }
    empty = c->fields[COL_X][0] == '\0' && c->fields[COL_Y][0] == '\0';
    if (empty) {
        if (c->fields[COL_AMP][0] != '\0') {
            mtt_io_error_at(c->path, c->line, "amplitude",
                            "must be empty on an empty-scan row (x and y empty)");
            return MTT_IO_EINPUT;
        }
    } else {
        if ((rc = field_real(c, COL_X, &x, &m.x)) != MTT_IO_OK ||
            (rc = field_real(c, COL_Y, &y, &m.y)) != MTT_IO_OK)
            return rc;
        if (c->fields[COL_AMP][0] != '\0') {
            if ((rc = field_real(c, COL_AMP, &amp, &m.amplitude)) != MTT_IO_OK)
                return rc;
            if (!(amp >= 0.0)) {
                mtt_io_error_at(c->path, c->line, "amplitude", "'%s' is negative: must be >= 0",
                                c->fields[COL_AMP]);
                return MTT_IO_EINPUT;
            }
            m.has_amplitude = 1;
        }
    }

    if (prev != NULL && scan == prev->scan) {
        if (time != prev->time) {
            mtt_io_format_double(prev->time, t0, sizeof t0);
            mtt_io_error_at(c->path, c->line, "time",
                            "'%s' differs from the time %s of scan %lu (line %ld): all rows of "
                            "a scan must have the same time",
                            c->fields[COL_TIME], t0, scan, prev->line);
            return MTT_IO_EINPUT;
        }
        if (empty || *scan_has_empty_row) {
            mtt_io_error_at(c->path, c->line, "x",
                            "scan %lu has both detections and an empty-scan row (x and y "
                            "empty): an empty scan is a single row",
                            scan);
            return MTT_IO_EINPUT;
        }
    } else {
        if (prev != NULL && scan < prev->scan) {
            mtt_io_error_at(c->path, c->line, "scan",
                            "%lu after scan %lu (line %ld): scan numbers must not decrease", scan,
                            prev->scan, prev->line);
            return MTT_IO_EINPUT;
        }
        if (prev != NULL && !(time > prev->time)) {
            mtt_io_format_double(prev->time, t0, sizeof t0);
            mtt_io_error_at(c->path, c->line, "time",
                            "'%s' is not later than the time %s of scan %lu (line %ld): time "
                            "must increase with scan",
                            c->fields[COL_TIME], t0, prev->scan, prev->line);
            return MTT_IO_EINPUT;
        }
        if (prev != NULL && !(rtime > prev->rtime)) {
            mtt_io_format_double(prev->time, t0, sizeof t0);
            mtt_io_format_double(d->time0, t1, sizeof t1);
            mtt_io_error_at(c->path, c->line, "time",
                            "'%s' cannot be told from the time %s of scan %lu in the tracker's "
                            "precision (mtt_real=" REAL_NAME ", time counted from %s)",
                            c->fields[COL_TIME], t0, prev->scan, t1);
            return MTT_IO_EINPUT;
        }
        if (d->n_scans == d->cap_scans) {
            mtt_io_scan *s = grow(d->scans, &d->cap_scans, sizeof *s);
            if (s == NULL)
                goto oom;
            d->scans = s;
        }
        prev = &d->scans[d->n_scans++];
        prev->scan = scan;
        prev->time = time;
        prev->rtime = rtime;
        prev->first = d->n_meas;
        prev->count = 0;
        prev->line = c->line;
        *scan_has_empty_row = 0;
    }

    if (empty) {
        *scan_has_empty_row = 1;
        return MTT_IO_OK;
    }
    if (d->n_meas == d->cap_meas) {
        mtt_meas *p = grow(d->meas, &d->cap_meas, sizeof *p);
        if (p == NULL)
            goto oom;
        d->meas = p;
    }
    d->meas[d->n_meas++] = m;
    prev->count++;
    return MTT_IO_OK;
oom:
    mtt_io_error("out of memory reading %s", c->path);
    return MTT_IO_ESYS;
}

int mtt_io_read_detections(const char *path, mtt_io_detections *d)
{
    mtt_io_csv c;
    int rc, got, scan_has_empty_row = 0;

    memset(d, 0, sizeof *d);
    if ((rc = mtt_io_csv_open(&c, path)) != MTT_IO_OK)
        return rc;
    if ((rc = mtt_io_csv_next(&c, &got)) != MTT_IO_OK)
        goto done;
    if (!got) {
        mtt_io_error_at(path, 0, NULL, "empty file: expected the header 'scan,time,x,y,amplitude'");
        rc = MTT_IO_EINPUT;
        goto done;
    }
    if ((rc = mtt_io_csv_expect_header(&c, det_cols, N_COLS)) != MTT_IO_OK)
        goto done;
    for (;;) {
        if ((rc = mtt_io_csv_next(&c, &got)) != MTT_IO_OK || !got)
            break;
        if ((rc = det_row(d, &c, &scan_has_empty_row)) != MTT_IO_OK)
            break;
    }
done:
    mtt_io_csv_close(&c);
    if (rc != MTT_IO_OK)
        mtt_io_free_detections(d);
    return rc;
}

/* ====================================================================== */
/* settings                                                                */
/* ====================================================================== */

/* How a settings key is read. */
typedef enum skind {
    SK_REAL,      /* one number */
    SK_REALS,     /* an array of len numbers */
    SK_BOOL,      /* true / false */
    SK_ASSOC,     /* association name (mtt_assoc_parse) */
    SK_INIT_GATE, /* "vmax" / "intensity" */
    SK_INTENSITY, /* the intensity_gate object */
    SK_TRACKS     /* the initial_tracks list */
} skind;

/* One settings key: FORMATS.md's name, where it goes in mtt_params, and the
 * range the library enforces (mtt.h), quoted when mtt_params_check fails. */
typedef struct skey {
    const char *key;
    skind kind;
    size_t off;         /* offsetof(mtt_params, member) */
    size_t len;         /* SK_REALS: element count */
    const char *field;  /* the mtt_params member, as mtt_params_check names it */
    const char *range;  /* allowed values ("[...]": of the whole array); NULL: not stated */
} skey;

#define PF(m) offsetof(mtt_params, m)

static const skey top_keys[] = {
    {"association", SK_ASSOC, PF(association), 1, "association", NULL},
    {"process_psd", SK_REAL, PF(process_psd), 1, "process_psd", "> 0"},
    {"meas_sigma", SK_REALS, PF(meas_sigma), 2, "meas_sigma", "in [1e-9, 1e9]"},
    {"pd", SK_REAL, PF(pd), 1, "pd", "in (0, 1]"},
    {"pg", SK_REAL, PF(pg), 1, "pg", "in (0, 1)"},
    {"clutter_density", SK_REAL, PF(clutter_density), 1, "clutter_density",
     ">= 0 (0 estimates it per track)"},
    {"snr_rho", SK_REAL, PF(snr_rho), 1, "snr_rho", "in [0, 1e6]"},
    {"markov_p11", SK_REAL, PF(markov_p11), 1, "markov_p11", "in [0, 1]"},
    {"markov_p21", SK_REAL, PF(markov_p21), 1, "markov_p21", "in [0, 1]"},
    {"existence_init", SK_REAL, PF(existence_init), 1, "existence_init", "in (0, 1)"},
    {"confirm_threshold", SK_REAL, PF(confirm_threshold), 1, "confirm_threshold", "in (0, 1]"},
    {"terminate_threshold", SK_REAL, PF(terminate_threshold), 1, "terminate_threshold",
     "in [0, confirm_threshold)"},
    {"merge_threshold", SK_REAL, PF(merge_threshold), 1, "merge_threshold",
     ">= 0 (0 never merges)"},
    {"initiate", SK_BOOL, PF(initiate), 1, "initiate", NULL},
    {"vmax", SK_REAL, PF(vmax), 1, "vmax", "> 0"},
    {"init_gate", SK_INIT_GATE, PF(init_gate), 1, "init_gate", NULL},
    {"intensity_gate", SK_INTENSITY, 0, 0, NULL, NULL},
    {"jpda_bias", SK_REAL, PF(jpda_bias), 1, "jpda_bias", ">= 0 (0 uses lambda(1-PD*PG)/PD)"},
    {"jpda_star_threshold", SK_REAL, PF(jpda_star_threshold), 1, "jpda_star_threshold",
     "in [0, 1)"},
    {"nnjpda_threshold", SK_REAL, PF(nnjpda_threshold), 1, "nnjpda_threshold", "in [0, 1)"},
    {"adaptive_jpda_distance", SK_REAL, PF(adaptive_jpda_distance), 1, "adaptive_jpda_distance",
     "> 0"},
    {"adaptive_jpda_shrink", SK_REAL, PF(adaptive_jpda_shrink), 1, "adaptive_jpda_shrink",
     ">= 1"},
    {"initial_tracks", SK_TRACKS, 0, 0, NULL, NULL},
};

static const skey igate_keys[] = {
    {"f1", SK_REALS, PF(intensity_f1), 3, "intensity_f1", NULL},
    {"f2", SK_REALS, PF(intensity_f2), 3, "intensity_f2", NULL},
    {"blend", SK_REALS, PF(intensity_blend), 2, "intensity_blend",
     "[I_lo, I_hi] with I_lo < I_hi"},
};
#define IGATE_PREFIX "intensity_gate."

#define N_TOP (sizeof top_keys / sizeof top_keys[0])
#define N_IGATE (sizeof igate_keys / sizeof igate_keys[0])

/* Members of one initial_tracks entry. */
static const char *const seed_keys[] = {"x", "y", "vx", "vy", "P"};
#define N_SEED_KEYS (sizeof seed_keys / sizeof seed_keys[0])

#define KEY_MAX 160 /* longest key path in a message */

typedef struct sctx {
    const char *file;
    mtt_io_settings *s;
} sctx;

static mtt_real *param_real(mtt_params *p, size_t off)
{
    return (mtt_real *)(void *)((char *)p + off);
}

static const char *json_type(const cJSON *j)
{
    if (cJSON_IsNumber(j))
        return "a number";
    if (cJSON_IsString(j))
        return "a string";
    if (cJSON_IsBool(j))
        return "a boolean";
    if (cJSON_IsNull(j))
        return "null";
    if (cJSON_IsArray(j))
        return "an array";
    if (cJSON_IsObject(j))
        return "an object";
    return "an unknown value";
}

/* Levenshtein distance, for "did you mean"; large for long names. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), i, j;
    size_t row[64], prev_diag, tmp;

    if (la >= 64 || lb >= 64)
        return (size_t)-1;
    for (j = 0; j <= lb; ++j)
        row[j] = j;
    for (i = 1; i <= la; ++i) {
        prev_diag = row[0];
        row[0] = i;
        for (j = 1; j <= lb; ++j) {
            size_t best = prev_diag + (a[i - 1] != b[j - 1]);
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            tmp = row[j];
            row[j] = best;
            prev_diag = tmp;
        }
    }
    return row[lb];
}

/* The closest of names to name, or NULL if none is close. */
static const char *suggest(const char *name, const char *const *names, size_t n,
                           size_t stride)
{
    const char *best = NULL;
    size_t i, best_d = 3; /* at most 2 edits, and fewer than half the name */
    for (i = 0; i < n; ++i) {
        const char *cand = *(const char *const *)(const void *)((const char *)names + i * stride);
        size_t d = edit_distance(name, cand);
        if (d < best_d && 2 * d < strlen(name)) {
            best_d = d;
            best = cand;
        }
    }
    return best;
}

static int unknown_key(const sctx *c, const char *key, const char *name,
                       const char *const *names, size_t n, size_t stride)
{
    const char *s = suggest(name, names, n, stride);
    if (s != NULL)
        mtt_io_error_key(c->file, key, "unknown key (did you mean '%s'?)", s);
    else
        mtt_io_error_key(c->file, key, "unknown key");
    return MTT_IO_EINPUT;
}

static int get_number(const sctx *c, const cJSON *j, const char *key, mtt_real *out)
{
    if (!cJSON_IsNumber(j)) {
        mtt_io_error_key(c->file, key, "must be a number, found %s", json_type(j));
        return MTT_IO_EINPUT;
    }
    if (!isfinite(j->valuedouble)) {
        mtt_io_error_key(c->file, key, "must be a finite number");
        return MTT_IO_EINPUT;
    }
    if (!mtt_io_to_real(j->valuedouble, out)) {
        mtt_io_error_key(c->file, key, "%g does not fit the tracker's real type (mtt_real="
                         REAL_NAME ")", j->valuedouble);
        return MTT_IO_EINPUT;
    }
    return MTT_IO_OK;
}

static int get_numbers(const sctx *c, const cJSON *j, const char *key, size_t n,
                       mtt_real *out)
{
    char sub[KEY_MAX + 32];
    const cJSON *e;
    size_t i = 0;
    int rc;

    if (!cJSON_IsArray(j)) {
        mtt_io_error_key(c->file, key, "must be an array of %lu numbers, found %s",
                         (unsigned long)n, json_type(j));
        return MTT_IO_EINPUT;
    }
    if ((size_t)cJSON_GetArraySize(j) != n) {
        mtt_io_error_key(c->file, key, "must be an array of %lu numbers, found %d elements",
                         (unsigned long)n, cJSON_GetArraySize(j));
        return MTT_IO_EINPUT;
    }
    cJSON_ArrayForEach(e, j)
    {
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)i);
        if ((rc = get_number(c, e, sub, &out[i])) != MTT_IO_OK)
            return rc;
        ++i;
    }
    return MTT_IO_OK;
}

static int get_string(const sctx *c, const cJSON *j, const char *key, const char **out)
{
    if (!cJSON_IsString(j)) {
        mtt_io_error_key(c->file, key, "must be a string, found %s", json_type(j));
        return MTT_IO_EINPUT;
    }
    *out = j->valuestring;
    return MTT_IO_OK;
}

/* "lm-ihpda, ihpda, ..." for the modes that pass (implemented only) or all. */
static void assoc_list(char *buf, size_t size, int implemented_only)
{
    int a;
    size_t len = 0;
    buf[0] = '\0';
    for (a = 0; a < (int)MTT_ASSOC_COUNT; ++a) {
        const char *name;
        mtt_params q;
        if (mtt_assoc_name((mtt_assoc)a, &name) != MTT_OK)
            continue;
        if (implemented_only) {
            if (mtt_params_default(&q) != MTT_OK)
                continue;
            q.association = (mtt_assoc)a;
            if (mtt_params_check(&q, NULL) != MTT_OK)
                continue;
        }
        if (len + strlen(name) + 3 >= size)
            break;
        len += (size_t)snprintf(buf + len, size - len, "%s%s", len != 0 ? ", " : "", name);
    }
}

static int parse_object(const sctx *c, const cJSON *obj, const char *prefix, const skey *tab,
                        size_t n);

/* P of an initial track: 16 numbers row-major, or 4 rows of 4. */
static int parse_cov(const sctx *c, const cJSON *j, const char *key, mtt_real P[16])
{
    char sub[KEY_MAX + 32];
    const cJSON *row;
    size_t r = 0;
    int rc;

    if (cJSON_IsArray(j) && cJSON_GetArraySize(j) == 16)
        return get_numbers(c, j, key, 16, P);
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != 4) {
        if (cJSON_IsArray(j))
            mtt_io_error_key(c->file, key,
                             "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), "
                             "found %d elements",
                             cJSON_GetArraySize(j));
        else
            mtt_io_error_key(c->file, key,
                             "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), "
                             "found %s",
                             json_type(j));
        return MTT_IO_EINPUT;
    }
    cJSON_ArrayForEach(row, j)
    {
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)r);
        if ((rc = get_numbers(c, row, sub, 4, &P[4 * r])) != MTT_IO_OK)
            return rc;
        ++r;
    }
    return MTT_IO_OK;
}

void mtt_io_seed_key(size_t i, const char *member, char *buf, size_t size)
{
    snprintf(buf, size, "initial_tracks[%lu]%s%s", (unsigned long)i,
             member != NULL ? "." : "", member != NULL ? member : "");
}

static int parse_tracks(const sctx *c, const cJSON *j, const char *key)
{
    char tkey[KEY_MAX], mkey[KEY_MAX];
    const cJSON *t, *m;
    size_t n, i = 0, k;
    int rc;

    if (!cJSON_IsArray(j)) {
        mtt_io_error_key(c->file, key, "must be an array of track objects, found %s",
                         json_type(j));
        return MTT_IO_EINPUT;
    }
    n = (size_t)cJSON_GetArraySize(j);
    free(c->s->seeds);
    c->s->seeds = NULL;
    c->s->n_seeds = 0;
    if (n == 0)
        return MTT_IO_OK;
    c->s->seeds = calloc(n, sizeof *c->s->seeds);
    if (c->s->seeds == NULL) {
        mtt_io_error("out of memory reading %s", c->file);
        return MTT_IO_ESYS;
    }
    c->s->n_seeds = n;
    cJSON_ArrayForEach(t, j)
    {
        mtt_io_seed *seed = &c->s->seeds[i];
        int seen[N_SEED_KEYS] = {0};

        mtt_io_seed_key(i, NULL, tkey, sizeof tkey);
        if (!cJSON_IsObject(t)) {
            mtt_io_error_key(c->file, tkey,
                             "must be an object {\"x\", \"y\", \"vx\", \"vy\"[, \"P\"]}, found %s",
                             json_type(t));
            return MTT_IO_EINPUT;
        }
        cJSON_ArrayForEach(m, t)
        {
            mtt_io_seed_key(i, m->string, mkey, sizeof mkey);
            for (k = 0; k < N_SEED_KEYS; ++k)
                if (strcmp(m->string, seed_keys[k]) == 0)
                    break;
            if (k == N_SEED_KEYS)
                return unknown_key(c, mkey, m->string, seed_keys, N_SEED_KEYS,
                                   sizeof seed_keys[0]);
            if (seen[k]++) {
                mtt_io_error_key(c->file, mkey, "given twice");
                return MTT_IO_EINPUT;
            }
            rc = k < 4 ? get_number(c, m, mkey, &seed->x[k]) : parse_cov(c, m, mkey, seed->P);
            if (rc != MTT_IO_OK)
                return rc;
        }
        for (k = 0; k < 4; ++k) {
            if (!seen[k]) {
                mtt_io_seed_key(i, seed_keys[k], mkey, sizeof mkey);
                mtt_io_error_key(c->file, mkey,
                                 "missing: every initial track needs x, y, vx and vy");
                return MTT_IO_EINPUT;
            }
        }
        seed->has_P = seen[4];
        ++i;
    }
    return MTT_IO_OK;
}

/* Read one key of a table into the parameters. */
static int parse_key(const sctx *c, const skey *k, const cJSON *j, const char *key)
{
    mtt_params *p = &c->s->params;
    const char *str;
    int rc;

    switch (k->kind) {
    case SK_REAL:
        return get_number(c, j, key, param_real(p, k->off));
    case SK_REALS:
        return get_numbers(c, j, key, k->len, param_real(p, k->off));
    case SK_BOOL:
        if (!cJSON_IsBool(j)) {
            mtt_io_error_key(c->file, key, "must be true or false, found %s", json_type(j));
            return MTT_IO_EINPUT;
        }
        p->initiate = cJSON_IsTrue(j) ? 1 : 0;
        return MTT_IO_OK;
    case SK_ASSOC:
        if ((rc = get_string(c, j, key, &str)) != MTT_IO_OK)
            return rc;
        if (mtt_assoc_parse(str, &p->association) != MTT_OK) {
            char list[512];
            assoc_list(list, sizeof list, 0);
            mtt_io_error_key(c->file, key, "unknown association '%s' (expected one of: %s)", str,
                             list);
            return MTT_IO_EINPUT;
        }
        return MTT_IO_OK;
    case SK_INIT_GATE:
        if ((rc = get_string(c, j, key, &str)) != MTT_IO_OK)
            return rc;
        if (strcmp(str, "vmax") == 0)
            p->init_gate = MTT_INIT_GATE_VMAX;
        else if (strcmp(str, "intensity") == 0)
            p->init_gate = MTT_INIT_GATE_INTENSITY;
        else {
            mtt_io_error_key(c->file, key, "unknown initial gate '%s' (expected 'vmax' or "
                             "'intensity')", str);
            return MTT_IO_EINPUT;
        }
        return MTT_IO_OK;
    case SK_INTENSITY:
        if (!cJSON_IsObject(j)) {
            mtt_io_error_key(c->file, key,
                             "must be an object {\"f1\": [a2, a1, a0], \"f2\": [a2, a1, a0], "
                             "\"blend\": [I_lo, I_hi]}, found %s",
                             json_type(j));
            return MTT_IO_EINPUT;
        }
        return parse_object(c, j, IGATE_PREFIX, igate_keys, N_IGATE);
    case SK_TRACKS:
        return parse_tracks(c, j, key);
    }
    return MTT_IO_EINPUT;
}

/* Read every member of obj; each must be a key of tab, at most once. */
static int parse_object(const sctx *c, const cJSON *obj, const char *prefix, const skey *tab,
                        size_t n)
{
    char key[KEY_MAX];
    unsigned char seen[N_TOP] = {0};
    const cJSON *j;
    size_t i;
    int rc;

    cJSON_ArrayForEach(j, obj)
    {
        snprintf(key, sizeof key, "%s%s", prefix, j->string);
        for (i = 0; i < n; ++i)
            if (strcmp(j->string, tab[i].key) == 0)
                break;
        if (i == n)
            return unknown_key(c, key, j->string, &tab[0].key, n, sizeof tab[0]);
        if (seen[i]++) {
            mtt_io_error_key(c->file, key, "given twice");
            return MTT_IO_EINPUT;
        }
        if ((rc = parse_key(c, &tab[i], j, key)) != MTT_IO_OK)
            return rc;
    }
    return MTT_IO_OK;
}

/* Does a name from mtt_params_check ("meas_sigma", "intensity_f1" or
 * "intensity_gate.f1", maybe with an index) stand for key k (under prefix)? */
static int names_key(const char *bad, const skey *k, const char *prefix)
{
    size_t len = strcspn(bad, "["), plen = strlen(prefix);
    if (k->field != NULL && strlen(k->field) == len && strncmp(k->field, bad, len) == 0)
        return 1;
    return len == plen + strlen(k->key) && strncmp(bad, prefix, plen) == 0 &&
           strncmp(bad + plen, k->key, len - plen) == 0;
}

/* The settings key that mtt_params_check's bad field names; NULL if none. */
static const skey *key_of_field(const char *bad, const char **prefix)
{
    size_t i;
    for (i = 0; i < N_TOP; ++i)
        if (names_key(bad, &top_keys[i], "")) {
            *prefix = "";
            return &top_keys[i];
        }
    for (i = 0; i < N_IGATE; ++i)
        if (names_key(bad, &igate_keys[i], IGATE_PREFIX)) {
            *prefix = IGATE_PREFIX;
            return &igate_keys[i];
        }
    return NULL;
}

/* mtt_params_check failed on bad_field: report it as a settings key. */
static int report_bad_field(const sctx *c, const char *bad_field)
{
    mtt_params *p = &c->s->params;
    const char *prefix = "";
    const skey *k = bad_field != NULL ? key_of_field(bad_field, &prefix) : NULL;
    char key[KEY_MAX], value[160];
    size_t i, len;

    if (k == NULL) {
        mtt_io_error_key(c->file, bad_field != NULL ? bad_field : "?",
                         "rejected by mtt_params_check");
        return MTT_IO_EINPUT;
    }
    snprintf(key, sizeof key, "%s%s", prefix, k->key);
    if (k->kind == SK_REALS) {
        /* The culprit element fails on its own (in the defaults), and the
         * default in its place clears this key. */
        mtt_params def;
        if (mtt_params_default(&def) != MTT_OK)
            def = *p;
        for (i = k->range != NULL && k->range[0] == '[' ? k->len : 0; i < k->len; ++i) {
            mtt_params alone = def, fixed = *p;
            const char *b1 = NULL, *b2 = NULL;
            param_real(&alone, k->off)[i] = param_real(p, k->off)[i];
            param_real(&fixed, k->off)[i] = param_real(&def, k->off)[i];
            if (mtt_params_check(&alone, &b1) != MTT_OK && b1 != NULL &&
                names_key(b1, k, prefix) &&
                (mtt_params_check(&fixed, &b2) == MTT_OK || b2 == NULL ||
                 !names_key(b2, k, prefix))) {
                snprintf(key, sizeof key, "%s%s[%lu]", prefix, k->key, (unsigned long)i);
                snprintf(value, sizeof value, "%g", (double)param_real(p, k->off)[i]);
                break;
            }
        }
        if (i == k->len) { /* a constraint between elements */
            len = (size_t)snprintf(value, sizeof value, "[");
            for (i = 0; i < k->len && len < sizeof value; ++i)
                len += (size_t)snprintf(value + len, sizeof value - len, "%s%g", i ? ", " : "",
                                        (double)param_real(p, k->off)[i]);
            if (len < sizeof value)
                snprintf(value + len, sizeof value - len, "]");
        }
    } else if (k->kind == SK_REAL) {
        snprintf(value, sizeof value, "%g", (double)*param_real(p, k->off));
    } else {
        value[0] = '\0';
    }
    if (k->range != NULL)
        mtt_io_error_key(c->file, key, "must be %s, found %s", k->range, value);
    else if (value[0] != '\0')
        mtt_io_error_key(c->file, key, "%s is out of range", value);
    else
        mtt_io_error_key(c->file, key, "rejected by mtt_params_check");
    return MTT_IO_EINPUT;
}

static int check_params(const sctx *c)
{
    const char *bad = NULL, *name = "?", *text = "?";
    char list[512];
    mtt_status st = mtt_params_check(&c->s->params, &bad);

    switch (st) {
    case MTT_OK:
        return MTT_IO_OK;
    case MTT_ERR_PARAM:
        return report_bad_field(c, bad);
    case MTT_ERR_UNSUPPORTED:
        if (mtt_assoc_name(c->s->params.association, &name) != MTT_OK)
            name = "?";
        assoc_list(list, sizeof list, 1);
        mtt_io_error_key(c->file, "association",
                         "association '%s' is not implemented in this version (available: %s)",
                         name, list);
        return MTT_IO_EINPUT;
    default:
        if (mtt_status_text(st, &text) != MTT_OK)
            text = "?";
        mtt_io_error("%s: mtt_params_check failed: %s", c->file, text);
        return MTT_IO_ESYS;
    }
}

/* The whole file as a NUL-terminated string. */
static int read_text(const char *path, char **text, size_t *size)
{
    FILE *fp = open_input(path, "rb");
    char *buf = NULL;
    size_t len = 0, cap = 0;

    if (fp == NULL)
        return MTT_IO_EINPUT;
    for (;;) {
        size_t got;
        if (cap - len < 4096 + 1) {
            size_t ncap = cap != 0 ? 2 * cap : 8192;
            char *b = ncap > cap ? realloc(buf, ncap) : NULL;
            if (b == NULL) {
                free(buf);
                fclose(fp);
                mtt_io_error("out of memory reading %s", path);
                return MTT_IO_ESYS;
            }
            buf = b;
            cap = ncap;
        }
        got = fread(buf + len, 1, cap - len - 1, fp);
        len += got;
        if (got == 0)
            break;
    }
    if (ferror(fp)) {
        mtt_io_error_at(path, 0, NULL, "read error: %s", strerror(errno));
        free(buf);
        fclose(fp);
        return MTT_IO_ESYS;
    }
    fclose(fp);
    buf[len] = '\0';
    *text = buf;
    *size = len;
    return MTT_IO_OK;
}

/* cJSON stops just past the offending token: report the line of the last
 * token before that point, and show that line. */
static void report_json_error(const char *path, const char *text, const char *at)
{
    const char *back, *ln, *q;
    long line = 1;
    int len;

    if (at == NULL || at < text || at > text + strlen(text))
        at = text;
    if (text[strspn(text, " \t\r\n")] == '\0') {
        mtt_io_error_at(path, 0, NULL, "empty file: expected a JSON object");
        return;
    }
    back = at;
    while (back > text && strchr(" \t\r\n", back[-1]) != NULL)
        --back;
    if (back > text)
        --back; /* the last character read */
    for (q = text; q < back; ++q)
        line += *q == '\n';
    for (ln = back; ln > text && ln[-1] != '\n';)
        --ln;
    ln += strspn(ln, " \t");
    len = (int)strcspn(ln, "\r\n");
    if (at[strspn(at, " \t\r\n")] == '\0')
        mtt_io_error_at(path, line, NULL, "malformed JSON: unexpected end of file after '%.*s'",
                        len < 40 ? len : 40, ln);
    else
        mtt_io_error_at(path, line, NULL, "malformed JSON near '%.*s'", len < 40 ? len : 40, ln);
}

void mtt_io_free_settings(mtt_io_settings *s)
{
    free(s->seeds);
    memset(s, 0, sizeof *s);
}

int mtt_io_read_settings(const char *path, mtt_io_settings *s)
{
    sctx c;
    char *text = NULL;
    size_t size = 0;
    const char *end = NULL, *p;
    cJSON *root;
    int rc;

    memset(s, 0, sizeof *s);
    if (mtt_params_default(&s->params) != MTT_OK) {
        mtt_io_error("mtt_params_default failed");
        return MTT_IO_ESYS;
    }
    if ((rc = read_text(path, &text, &size)) != MTT_IO_OK)
        return rc;
    if (strlen(text) != size) {
        mtt_io_error_at(path, 0, NULL, "contains a NUL byte: not a text file");
        free(text);
        return MTT_IO_EINPUT;
    }
    p = text;
    if ((unsigned char)p[0] == 0xEF && (unsigned char)p[1] == 0xBB && (unsigned char)p[2] == 0xBF)
        p += 3; /* UTF-8 byte order mark */
    root = cJSON_ParseWithOpts(p, &end, 1);
    if (root == NULL) {
        report_json_error(path, p, end != NULL ? end : cJSON_GetErrorPtr());
        free(text);
        return MTT_IO_EINPUT;
    }
    free(text);
    c.file = path;
    c.s = s;
    if (!cJSON_IsObject(root)) {
        mtt_io_error_key(path, NULL, "the settings must be a JSON object, found %s",
                         json_type(root));
        rc = MTT_IO_EINPUT;
    } else {
        rc = parse_object(&c, root, "", top_keys, N_TOP);
        if (rc == MTT_IO_OK)
            rc = check_params(&c);
    }
    cJSON_Delete(root);
    if (rc != MTT_IO_OK)
        mtt_io_free_settings(s);
    return rc;
}
