/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/csv.c - the CSV line reader: comments, blank lines, CRLF and a UTF-8 byte
 * order mark; fields split at commas and trimmed; the header check.
 */
#define _POSIX_C_SOURCE 200809L /* getline */

#include "mtt_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

/* ====================================================================== */
/* CSV                                                                     */
/* ====================================================================== */

int mtt_io_csv_open(mtt_io_csv *c, const char *path)
{
    memset(c, 0, sizeof *c);
    c->path = path;
    c->fp = mtt_io_open(path, "r");
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
