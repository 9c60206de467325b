/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/fuzz_io_common.h - shared by the reader harnesses: the input bytes
 * become a file that the reader opens by path (the readers of libmtt_io, tools/io/
 * take a path), and the readers' one-line messages are silenced.
 *
 * The file is a memfd (no disk traffic, nothing left behind), opened by the
 * reader as /proc/self/fd/N.  stderr (the FILE) is pointed at /dev/null so
 * millions of "bad input" messages do not flood the log; libFuzzer's own
 * output and the sanitizers' reports write to file descriptor 2 directly
 * and still appear.  Set MTT_FUZZ_VERBOSE=1 to keep the messages. */
#ifndef MTT_FUZZ_IO_COMMON_H
#define MTT_FUZZ_IO_COMMON_H

#define _GNU_SOURCE 1
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

static int fuzz_fd = -1;
static char fuzz_path[64];

static void fuzz_io_setup(void)
{
    const char *v = getenv("MTT_FUZZ_VERBOSE");
    if (fuzz_fd >= 0)
        return;
    fuzz_fd = memfd_create("mtt-fuzz-input", 0);
    if (fuzz_fd < 0) {
        perror("memfd_create");
        abort();
    }
    snprintf(fuzz_path, sizeof fuzz_path, "/proc/self/fd/%d", fuzz_fd);
    if (v == NULL || strcmp(v, "1") != 0) {
        FILE *null = fopen("/dev/null", "w");
        if (null != NULL)
            stderr = null;
    }
}

/* Make the input the whole content of the file; returns its path. */
static const char *fuzz_io_file(const unsigned char *data, size_t size)
{
    size_t done = 0;
    fuzz_io_setup();
    if (ftruncate(fuzz_fd, 0) != 0) {
        perror("ftruncate");
        abort();
    }
    while (done < size) {
        ssize_t w = pwrite(fuzz_fd, data + done, size - done, (off_t)done);
        if (w <= 0) {
            perror("pwrite");
            abort();
        }
        done += (size_t)w;
    }
    return fuzz_path;
}

#define FUZZ_FAIL(name, ...)                                          \
    do {                                                              \
        fprintf(stdout, name ": invariant violated: " __VA_ARGS__);   \
        fputc('\n', stdout);                                          \
        fflush(stdout);                                               \
        abort();                                                      \
    } while (0)

#endif
