/* io/error.c - the one-line messages of the host I/O library (mtt_io.h):
 *   PROG: FILE:LINE: field 'NAME': message   and   PROG: FILE: key 'PATH': message.
 */
#include "mtt_io.h"

#include <stdarg.h>
#include <stdio.h>

const char *mtt_io_progname = "mtt-track";

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
