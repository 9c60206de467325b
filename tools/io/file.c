/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/file.c - opening an input file (a directory is refused here rather than as a
 * read error), and reading a whole file into memory.
 */
#define _POSIX_C_SOURCE 200809L /* fileno */

#include "mtt_io.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

FILE *mtt_io_open(const char *path, const char *mode)
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


int mtt_io_read_text(const char *path, char **text, size_t *size)
{
    FILE *fp = mtt_io_open(path, "rb");
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
