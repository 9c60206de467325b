/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/error.c - the one-line messages of the host I/O library (mtt_io.h):
 *   PROG: FILE:LINE: field 'NAME': message   and   PROG: FILE: key 'PATH': message.
 */
#include "mtt_io.h"

#include <stdarg.h>
#include <stdio.h>

const char *mtt_io_progname = "mtt-track";

/* "PROG: FILE:[LINE:] [LABEL 'NAME':] message\n": the one layout of both. */
static void report(const char *file, long line, const char *label, const char *name,
                   const char *fmt, va_list ap)
{
    fprintf(stderr, "%s: %s:", mtt_io_progname, file);
    if (line > 0)
        fprintf(stderr, "%ld:", line);
    if (name != NULL)
        fprintf(stderr, " %s '%s':", label, name);
    fputc(' ', stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void mtt_io_error_at(const char *file, long line, const char *field, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    report(file, line, "field", field, fmt, ap);
    va_end(ap);
}

void mtt_io_error_key(const char *file, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    report(file, 0, "key", key, fmt, ap);
    va_end(ap);
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
