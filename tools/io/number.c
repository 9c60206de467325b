/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/number.c - numbers in text files: whole-field parsing (strtod, decimal counts),
 * the one conversion into mtt_real (a Q format in the fixed-point build) and
 * back, and the shortest text that reads back as the same double.
 */
#include "mtt_io.h"
#include "real_ops.h" /* mtt_fx_from_double, mtt_fx_to_double: private (src/) */

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

#ifdef MTT_REAL_FIXED
int mtt_io_to_real(double v, int fmt, mtt_real *out)
{
    return mtt_fx_from_double(v, fmt, out) == MTT_OK;
}

double mtt_io_from_real(mtt_real r, int fmt)
{
    return mtt_fx_to_double(r, fmt);
}
#else
int mtt_io_to_real(double v, int fmt, mtt_real *out)
{
    (void)fmt;
    /* Converting a double beyond the float range is undefined: test first. */
    if (!(fabs(v) <= (double)MTT_REAL_MAX))
        return 0;
    *out = (mtt_real)v;
    return 1;
}

double mtt_io_from_real(mtt_real r, int fmt)
{
    (void)fmt;
    return (double)r;
}
#endif

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
