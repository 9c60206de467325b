/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/replay_main.c - a main() for the harnesses without libFuzzer: runs
 * LLVMFuzzerTestOneInput once on every file named (directories: every file
 * in them, sorted).  Used by ctest to replay the seed corpus and the
 * regression inputs of tools/fuzz/regress/ with any compiler; exits 0 when every
 * input ran (a violated invariant aborts). */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    unsigned char *buf = NULL;
    size_t len = 0, cap = 0, got;
    if (fp == NULL) {
        fprintf(stdout, "replay: cannot open %s\n", path);
        return 1;
    }
    do {
        if (cap - len < 4096) {
            unsigned char *b;
            cap = cap ? 2 * cap : 65536;
            b = realloc(buf, cap);
            if (b == NULL) {
                fclose(fp);
                free(buf);
                return 1;
            }
            buf = b;
        }
        got = fread(buf + len, 1, cap - len, fp);
        len += got;
    } while (got > 0);
    fclose(fp);
    fprintf(stdout, "replay: %s (%zu bytes)\n", path, len);
    fflush(stdout);
    (void)LLVMFuzzerTestOneInput(buf, len);
    free(buf);
    return 0;
}

static int cmp(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(int argc, char **argv)
{
    int i, bad = 0, runs = 0;
    (void)LLVMFuzzerInitialize(&argc, &argv);
    for (i = 1; i < argc; ++i) {
        struct stat st;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode)) {
            DIR *d = opendir(argv[i]);
            struct dirent *e;
            char **names = NULL;
            size_t n = 0, k;
            if (d == NULL)
                continue;
            while ((e = readdir(d)) != NULL) {
                char *full;
                char **nn;
                if (e->d_name[0] == '.')
                    continue;
                full = malloc(strlen(argv[i]) + strlen(e->d_name) + 2);
                nn = realloc(names, (n + 1) * sizeof *names);
                if (full == NULL || nn == NULL)
                    return 1;
                names = nn;
                sprintf(full, "%s/%s", argv[i], e->d_name);
                names[n++] = full;
            }
            closedir(d);
            qsort(names, n, sizeof *names, cmp);
            for (k = 0; k < n; ++k) {
                bad |= run_file(names[k]);
                ++runs;
                free(names[k]);
            }
            free(names);
        } else {
            bad |= run_file(argv[i]);
            ++runs;
        }
    }
    fprintf(stdout, "replay: %d inputs, %s\n", runs, bad ? "some unreadable" : "all passed");
    return bad;
}
