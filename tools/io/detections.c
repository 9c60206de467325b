/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/detections.c - the detections file (*.det.csv) of docs/FORMATS.md: read whole and
 * validated row by row; the first problem is reported with its line and field,
 * and a bad file gives nothing.
 */
#include "mtt_io.h"
#include "real_ops.h" /* MTT_TIME_AFTER: private (src/) */

#include <stdlib.h>
#include <string.h>

enum { COL_SCAN, COL_TIME, COL_X, COL_Y, COL_AMP, N_COLS, COL_RXX = N_COLS, COL_RXY, COL_RYY, N_COLS_COV };

#ifdef MTT_REAL_FIXED
#define MTT_IO_SATURATES 1 /* out of the format: saturated, skipped by the tracker */
#else
#define MTT_IO_SATURATES 0
#endif

#ifdef MTT_REAL_FIXED
/* The build's range of a coordinate (col COL_X, COL_Y) or amplitude: what
 * mtt_measure_select keeps (MTT_POS_OK, a finite amplitude). */
static int in_range(int col, double v, double *lo, double *hi)
{
    mtt_real r;
    if (col == COL_AMP) {
        *lo = 0.0;
        *hi = mtt_io_from_real(MTT_FX_MAX - 1, MTT_IO_AMP);
        return v < 0.0 || mtt_io_to_real(v, MTT_IO_AMP, &r); /* negative: malformed (below) */
    }
    *hi = mtt_io_from_real(MTT_FX_POS_LIMIT, MTT_IO_POS);
    *lo = -*hi;
    return mtt_io_to_real(v, MTT_IO_POS, &r) && r >= -MTT_FX_POS_LIMIT && r <= MTT_FX_POS_LIMIT;
}
#endif
static const char *const det_cols[N_COLS_COV] = {"scan", "time", "x", "y", "amplitude", "r_xx", "r_xy", "r_yy"};
/* The polar form (ALGORITHMS.md §3.2): range and bearing in the columns of x and y. */
static const char *const polar_cols[N_COLS + 1] = {"scan", "time", "range", "bearing", "amplitude", "range_rate"};

/* The column names of the file being read (one reader at a time per form). */
static const char *const *col_names(const mtt_io_csv *c)
{
    return c->polar_form ? polar_cols : det_cols;
}

/* Report a field that failed to parse; always MTT_IO_EINPUT. */
static int bad_number(const mtt_io_csv *c, int col, mtt_io_num why, const char *what)
{
    const char *s = c->fields[col];
    switch (why) {
    case MTT_IO_NUM_EMPTY:
        mtt_io_error_at(c->path, c->line, col_names(c)[col], "missing value: expected %s", what);
        break;
    case MTT_IO_NUM_NONFINITE:
        mtt_io_error_at(c->path, c->line, col_names(c)[col], "'%s' is not allowed: expected %s", s,
                        what);
        break;
    case MTT_IO_NUM_RANGE:
        mtt_io_error_at(c->path, c->line, col_names(c)[col], "'%s' is out of range: expected %s", s,
                        what);
        break;
    default:
        mtt_io_error_at(c->path, c->line, col_names(c)[col], "'%s' is not %s", s, what);
        break;
    }
    return MTT_IO_EINPUT;
}

/* Parse a finite number into mtt_real of format fmt (mtt_io_to_real).
 * In the fixed-point build a coordinate or amplitude outside the build's
 * range (in_range; out_of_range not NULL) is an error naming the line,
 * the value and the range, or with MTT_IO_SKIP_OUT_OF_RANGE counted in
 * *out_of_range and kept saturated, which the tracker skips and counts in
 * meas_out_of_range (docs/FIXED_POINT.md §3); only the time must fit.
 * Float and double: a value that overflows mtt_real is an error. */
static int field_real(const mtt_io_csv *c, int col, int fmt, double *d, mtt_real *r,
                      unsigned flags, size_t *out_of_range)
{
    mtt_io_num e = mtt_io_parse_double(c->fields[col], d);
    if (e != MTT_IO_NUM_OK)
        return bad_number(c, col, e, "a finite number");
#ifdef MTT_REAL_FIXED
    if (col == COL_TIME)
        return MTT_IO_OK; /* only time - time0 is converted (below) */
#endif
#ifdef MTT_REAL_FIXED
    {
        double lo, hi;
        char a[32], b[32];
        if (out_of_range != NULL && !in_range(col, *d, &lo, &hi)) {
            if ((flags & MTT_IO_SKIP_OUT_OF_RANGE) == 0u) {
                mtt_io_format_double(lo, a, sizeof a);
                mtt_io_format_double(hi, b, sizeof b);
                mtt_io_error_at(c->path, c->line, col_names(c)[col],
                                "'%s' is outside this build's range [%s, %s] (mtt_real="
                                MTT_IO_REAL_NAME ", Q%d; --skip-out-of-range skips and counts "
                                "such detections)",
                                c->fields[col], a, b, fmt);
                return MTT_IO_EINPUT;
            }
            ++*out_of_range; /* one per detection: the caller passes NULL after the first */
        }
    }
#else
    (void)flags;
    (void)out_of_range;
#endif
    if (!mtt_io_to_real(*d, fmt, r) && !MTT_IO_SATURATES) {
        mtt_io_error_at(c->path, c->line, col_names(c)[col],
                        "'%s' does not fit the tracker's real type (mtt_real=" MTT_IO_REAL_NAME ")",
                        c->fields[col]);
        return MTT_IO_EINPUT;
    }
    return MTT_IO_OK;
}

/* A scan's time as the tracker takes it: counted from the first scan's.
 * Fixed point: Q16 of the file's time unit modulo 2^32, as the tracker
 * compares times (docs/FIXED_POINT.md §3), so a file may be of any length
 * (each step below 32768 units, checked with the order of the scans);
 * float and double: mtt_io_to_real. */
static int time_from0(double t, mtt_real *out)
{
#ifdef MTT_REAL_FIXED
    const double s = t * (double)(1L << MTT_IO_TIME);
    unsigned long long q;
    uint32_t u;
    if (!(s >= 0.0 && s < 9007199254740992.0)) /* 2^53: exact in a double */
        return 0;
    q = (unsigned long long)(s + 0.5);
    u = (uint32_t)(q & 0xFFFFFFFFull);
    *out = (u <= (uint32_t)INT32_MAX) ? (int32_t)u : -(int32_t)(~u) - 1; /* two's complement */
    return 1;
#else
    return mtt_io_to_real(t, MTT_IO_TIME, out);
#endif
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
    free(d->cov);
    free(d->polar);
    free(d->scans);
    memset(d, 0, sizeof *d);
}

/* A row's covariance columns (ALGORITHMS.md §3.1): all three empty (the
 * settings' meas_sigma), or a finite positive definite r_xx, r_xy, r_yy.
 * Fixed point: in the variance format (MTT_IO_VAR); one that does not fit
 * it (beyond its range, or a variance that rounds to 0) is an error, or
 * with MTT_IO_SKIP_OUT_OF_RANGE counted in *out_of_range (when not NULL)
 * and kept saturated, which the tracker skips and counts in
 * meas_out_of_range (docs/FIXED_POINT.md §5). */
static int cov_fields(const mtt_io_csv *c, int empty_row, mtt_meas_cov *r, unsigned flags, size_t *out_of_range)
{
    double v[3];
    int k, rc, n_empty = 0;
    for (k = 0; k < 3; ++k)
        n_empty += c->fields[COL_RXX + k][0] == '\0';
    memset(r, 0, sizeof *r);
    if (n_empty == 3)
        return MTT_IO_OK;
    if (empty_row) {
        mtt_io_error_at(c->path, c->line, "r_xx", "must be empty on an empty-scan row (x and y empty)");
        return MTT_IO_EINPUT;
    }
    for (k = 0; k < 3; ++k) {
        mtt_real dummy;
        if (c->fields[COL_RXX + k][0] == '\0') {
            mtt_io_error_at(c->path, c->line, col_names(c)[COL_RXX + k],
                            "missing value: r_xx, r_xy and r_yy are given together or all left empty");
            return MTT_IO_EINPUT;
        }
        if ((rc = field_real(c, COL_RXX + k, MTT_IO_POS, &v[k], &dummy, 0u, NULL)) != MTT_IO_OK)
            return rc;
    }
    if (!(v[0] > 0.0) || !(v[2] > 0.0)) {
        k = v[0] > 0.0 ? COL_RYY : COL_RXX;
        mtt_io_error_at(c->path, c->line, col_names(c)[k], "'%s' must be > 0 (a variance)", c->fields[k]);
        return MTT_IO_EINPUT;
    }
    if (!(v[0] * v[2] > v[1] * v[1])) {
        mtt_io_error_at(c->path, c->line, "r_xy",
                        "'%s' makes the covariance not positive definite (r_xy^2 must be < r_xx r_yy)",
                        c->fields[COL_RXY]);
        return MTT_IO_EINPUT;
    }
#ifdef MTT_REAL_FIXED
    {
        mtt_real q[3];
        int fits = 1;
        for (k = 0; k < 3; ++k)
            fits &= mtt_io_to_real(v[k], MTT_IO_VAR, &q[k]) != 0;
        if (!fits || !(q[0] > 0) || !(q[2] > 0)) {
            char hi[32], lo[32];
            if ((flags & MTT_IO_SKIP_OUT_OF_RANGE) == 0u) {
                mtt_io_format_double(mtt_io_from_real(MTT_FX_MAX - 1, MTT_IO_VAR), hi, sizeof hi);
                mtt_io_format_double(mtt_io_from_real(1, MTT_IO_VAR), lo, sizeof lo);
                mtt_io_error_at(c->path, c->line, "r_xx",
                                "the covariance (%s, %s, %s) is outside this build's variance format "
                                "(mtt_real=" MTT_IO_REAL_NAME ", Q%d: |r| <= %s, r_xx and r_yy >= %s; "
                                "--skip-out-of-range skips and counts such detections)",
                                c->fields[COL_RXX], c->fields[COL_RXY], c->fields[COL_RYY], MTT_IO_VAR, hi, lo);
                return MTT_IO_EINPUT;
            }
            if (out_of_range != NULL)
                ++*out_of_range; /* one per detection */
            q[0] = MTT_FX_MAX; /* saturated: measure.c skips and counts it */
        }
        r->r_xx = q[0];
        r->r_xy = q[1];
        r->r_yy = q[2];
    }
#else
    (void)flags;
    (void)out_of_range;
    r->r_xx = (mtt_real)v[0];
    r->r_xy = (mtt_real)v[1];
    r->r_yy = (mtt_real)v[2];
    if (!(r->r_xx > 0) || !(r->r_yy > 0)) { /* a variance below mtt_real's smallest (fuzz: 3e-93 in float) */
        k = r->r_xx > 0 ? COL_RYY : COL_RXX;
        mtt_io_error_at(c->path, c->line, col_names(c)[k],
                        "'%s' is 0 in this build's mtt_real (" MTT_IO_REAL_NAME "): a variance must be > 0",
                        c->fields[k]);
        memset(r, 0, sizeof *r);
        return MTT_IO_EINPUT;
    }
#endif
    return MTT_IO_OK;
}

/* Validate and store one data row. */
static int det_row(mtt_io_detections *d, const mtt_io_csv *c, int *scan_has_empty_row, int ncols,
                   unsigned flags)
{
    unsigned long scan;
    double time, x = 0, y = 0, amp = 0;
    mtt_meas m;
    mtt_meas_cov r;
    mtt_real rtime, rrate = 0;
    int has_rrate = 0;
    mtt_io_num e;
    int empty, rc;
    size_t oor = 0;
    char t0[32], t1[32];
    const char *header = c->polar_form ? (ncols == N_COLS ? "scan,time,range,bearing,amplitude"
                                                          : "scan,time,range,bearing,amplitude,range_rate")
                         : ncols == N_COLS ? "scan,time,x,y,amplitude" : "scan,time,x,y,amplitude,r_xx,r_xy,r_yy";
    const char *const *names = col_names(c);
    mtt_io_scan *prev = d->n_scans != 0 ? &d->scans[d->n_scans - 1] : NULL;

    if (c->n_fields < (size_t)ncols) {
        mtt_io_error_at(c->path, c->line, col_names(c)[c->n_fields],
                        "missing: the row has %lu fields, expected %d (%s)",
                        (unsigned long)c->n_fields, ncols, header);
        return MTT_IO_EINPUT;
    }
    if (c->n_fields > (size_t)ncols) {
        mtt_io_error_at(c->path, c->line, NULL,
                        "the row has %lu fields, expected %d (%s)",
                        (unsigned long)c->n_fields, ncols, header);
        return MTT_IO_EINPUT;
    }

    e = mtt_io_parse_count(c->fields[COL_SCAN], &scan);
    if (e != MTT_IO_NUM_OK)
        return bad_number(c, COL_SCAN, e, "a non-negative integer");
    memset(&m, 0, sizeof m);
    if ((rc = field_real(c, COL_TIME, MTT_IO_TIME, &time, &rtime, flags, NULL)) != MTT_IO_OK)
        return rc;
    if (prev == NULL)
        d->time0 = time;
    if (!time_from0(time - d->time0, &rtime)) {
        mtt_io_error_at(c->path, c->line, "time", "'%s' is too far from the first scan's time",
                        c->fields[COL_TIME]);
        return MTT_IO_EINPUT;
    }
    empty = c->fields[COL_X][0] == '\0' && c->fields[COL_Y][0] == '\0';
    if (empty) {
        if (c->fields[COL_AMP][0] != '\0') {
            mtt_io_error_at(c->path, c->line, "amplitude", "must be empty on an empty-scan row (%s and %s empty)",
                            names[COL_X], names[COL_Y]);
            return MTT_IO_EINPUT;
        }
    } else {
        if ((rc = field_real(c, COL_X, MTT_IO_POS, &x, &m.x, flags, &oor)) != MTT_IO_OK ||
            (rc = field_real(c, COL_Y, MTT_IO_POS, &y, &m.y, flags, oor != 0 ? NULL : &oor)) !=
                MTT_IO_OK)
            return rc;
        if (c->polar_form && !(x > 0.0)) {
            mtt_io_error_at(c->path, c->line, "range", "'%s' must be > 0", c->fields[COL_X]);
            return MTT_IO_EINPUT;
        }
        if (c->fields[COL_AMP][0] != '\0') {
            if ((rc = field_real(c, COL_AMP, MTT_IO_AMP, &amp, &m.amplitude, flags,
                                 oor != 0 ? NULL : &oor)) != MTT_IO_OK)
                return rc;
            if (!(amp >= 0.0)) {
                mtt_io_error_at(c->path, c->line, "amplitude", "'%s' is negative: must be >= 0",
                                c->fields[COL_AMP]);
                return MTT_IO_EINPUT;
            }
            m.has_amplitude = 1;
        }
    }
    memset(&r, 0, sizeof r);
    if (!c->polar_form && ncols == N_COLS_COV && (rc = cov_fields(c, empty, &r, flags, oor != 0 ? NULL : &oor)) != MTT_IO_OK)
        return rc;
    if (c->polar_form && ncols > N_COLS && c->fields[N_COLS][0] != '\0') {
        /* a range rate (ALGORITHMS.md §3.2) */
        double v;
        if (empty) {
            mtt_io_error_at(c->path, c->line, "range_rate", "must be empty on an empty-scan row (range and bearing empty)");
            return MTT_IO_EINPUT;
        }
        if ((rc = field_real(c, N_COLS, MTT_IO_POS, &v, &rrate, 0u, NULL)) != MTT_IO_OK)
            return rc;
        has_rrate = 1;
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
            mtt_io_error_at(c->path, c->line, names[COL_X],
                            "scan %lu has both detections and an empty-scan row (%s and %s "
                            "empty): an empty scan is a single row",
                            scan, names[COL_X], names[COL_Y]);
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
#ifdef MTT_REAL_FIXED
        if (prev != NULL && !((time - prev->time) * (double)(1L << MTT_IO_TIME) < 2147483647.0)) {
            mtt_io_format_double(prev->time, t0, sizeof t0);
            mtt_io_error_at(c->path, c->line, "time",
                            "'%s' is too far after the time %s of scan %lu: a step of the "
                            "fixed-point tracker is below 32768 time units",
                            c->fields[COL_TIME], t0, prev->scan);
            return MTT_IO_EINPUT;
        }
#endif
        if (prev != NULL && !MTT_TIME_AFTER(rtime, prev->rtime)) {
            mtt_io_format_double(prev->time, t0, sizeof t0);
            mtt_io_format_double(d->time0, t1, sizeof t1);
            mtt_io_error_at(c->path, c->line, "time",
                            "'%s' cannot be told from the time %s of scan %lu in the tracker's "
                            "precision (mtt_real=" MTT_IO_REAL_NAME ", time counted from %s)",
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
    if (d->n_meas == d->cap_meas && c->polar_form) {
        mtt_polar *p = grow(d->polar, &d->cap_meas, sizeof *p);
        if (p == NULL)
            goto oom;
        d->polar = p;
    } else if (d->n_meas == d->cap_meas) {
        size_t cap = d->cap_meas;
        mtt_meas *p = grow(d->meas, &cap, sizeof *p);
        if (p == NULL)
            goto oom;
        d->meas = p;
        if (ncols == N_COLS_COV) {
            size_t cap2 = d->cap_meas;
            mtt_meas_cov *q = grow(d->cov, &cap2, sizeof *q);
            if (q == NULL)
                goto oom;
            d->cov = q;
        }
        d->cap_meas = cap;
    }
    if (c->polar_form) {
        mtt_polar *q = &d->polar[d->n_meas++];
        q->range = m.x;
        q->bearing = m.y;
        q->amplitude = m.amplitude;
        q->has_amplitude = m.has_amplitude;
        q->range_rate = rrate;
        q->has_range_rate = has_rrate;
        d->has_range_rate |= q->has_range_rate;
        d->out_of_range += oor;
        prev->count++;
        return MTT_IO_OK;
    }
    if (ncols == N_COLS_COV)
        d->cov[d->n_meas] = r;
    d->meas[d->n_meas++] = m;
    d->out_of_range += oor;
    prev->count++;
    return MTT_IO_OK;
oom:
    mtt_io_error("out of memory reading %s", c->path);
    return MTT_IO_ESYS;
}

int mtt_io_read_detections(const char *path, mtt_io_detections *d)
{
    return mtt_io_read_detections_opt(path, d, 0u);
}

int mtt_io_read_detections_opt(const char *path, mtt_io_detections *d, unsigned flags)
{
    mtt_io_csv c;
    int rc, got, scan_has_empty_row = 0, ncols = N_COLS;

    memset(d, 0, sizeof *d);
    if ((rc = mtt_io_csv_open(&c, path)) != MTT_IO_OK)
        return rc;
    if ((rc = mtt_io_csv_next(&c, &got)) != MTT_IO_OK)
        goto done;
    if (!got) {
        mtt_io_error_at(path, 0, NULL, "empty file: expected the header 'scan,time,x,y,amplitude' (or "
                                       "'scan,time,range,bearing,amplitude')");
        rc = MTT_IO_EINPUT;
        goto done;
    }
    d->header_line = c.line;
    /* the header names the form: with r_xx,r_xy,r_yy every row has them;
     * range,bearing in place of x,y: polar (ALGORITHMS.md §3.2) */
    if (c.n_fields > COL_X && strcmp(c.fields[COL_X], "range") == 0) {
        c.polar_form = 1;
        d->is_polar = 1;
        if (c.n_fields > N_COLS && strcmp(c.fields[N_COLS], "range_rate") == 0)
            ncols = N_COLS + 1; /* range,bearing,amplitude,range_rate */
    } else if (c.n_fields > N_COLS && strcmp(c.fields[N_COLS], "r_xx") == 0) {
        ncols = N_COLS_COV;
    }
    if ((rc = mtt_io_csv_expect_header(&c, col_names(&c), (size_t)ncols)) != MTT_IO_OK)
        goto done;
    for (;;) {
        if ((rc = mtt_io_csv_next(&c, &got)) != MTT_IO_OK || !got)
            break;
        if ((rc = det_row(d, &c, &scan_has_empty_row, ncols, flags)) != MTT_IO_OK)
            break;
    }
done:
    mtt_io_csv_close(&c);
    if (rc != MTT_IO_OK)
        mtt_io_free_detections(d);
    return rc;
}
