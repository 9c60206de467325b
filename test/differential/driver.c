/* SPDX-License-Identifier: BSD-3-Clause */
/* driver.c - runs the library on one differential scene (stdin) and prints
 * every live track after each frame (stdout), for python/tests/test_differential.py.
 *
 * Public API only (include/mtt/mtt.h); built with mtt_real = double.  The
 * scene format is documented in python/mtt_ref/scene.py:
 *
 *   param <key> <value...>      a settings key of docs/FORMATS.md (dotted when
 *                               nested: intensity_gate.f1), set by mtt_params_set
 *   track x y vx vy p00 .. p33  mtt_tracker_add_track before the first frame
 *   frame <time> <n>            then n lines "x y amplitude|-"
 *
 * Output per frame: "frame <k> <n>", then per live track in ascending id
 *   T id confirmed x0..x3 P00..P33 existence age meas
 * every real with "%.17g" (round-trips a double).  Exit 0 on success, 2 on a
 * malformed scene or a refused call (message on stderr).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mtt/mtt.h"

#define LINE_MAX_LEN 4096
#define MAX_WORDS 32

static mtt_tracker trk;
static mtt_meas meas[4 * MTT_MAX_MEAS];

static int die(long line, const char *what)
{
    fprintf(stderr, "driver: line %ld: %s\n", line, what);
    return 2;
}

static int split(char *s, char **w)
{
    int n = 0;
    char *tok = strtok(s, " \t\r\n");
    while (tok != NULL && n < MAX_WORDS) {
        w[n++] = tok;
        tok = strtok(NULL, " \t\r\n");
    }
    return n;
}

static int num(const char *s, double *v)
{
    char *end;
    *v = strtod(s, &end);
    return end != s && *end == '\0';
}

/* "param <key> <values...>": one docs/FORMATS.md setting, through the
 * library's own parameter table (mtt_params_find / info / set); an enum
 * value is given by name.  0 on success. */
static int set_param(mtt_params *p, char **w, int n)
{
    const mtt_param_info *inf;
    double v[8];
    size_t i, k, cnt;
    if (n < 3 || mtt_params_find(w[1], &i) != MTT_OK || mtt_params_info(i, &inf) != MTT_OK) return -1;
    cnt = inf->count;
    if ((size_t)(n - 2) != cnt || cnt > sizeof v / sizeof v[0]) return -1;
    if (inf->type == MTT_PARAM_ENUM) {
        for (k = 0; k < inf->n_names && strcmp(inf->names[k], w[2]) != 0; ++k) {
        }
        if (k == inf->n_names) return -1;
        v[0] = (double)k;
    } else {
        for (k = 0; k < cnt; ++k)
            if (!num(w[2 + k], &v[k])) return -1;
    }
    return mtt_params_set(p, w[1], v, cnt) == MTT_OK ? 0 : -1;
}

static void print_tracks(long frame)
{
    size_t count, i;
    int r, c;
    if (mtt_tracker_count(&trk, &count) != MTT_OK) return;
    printf("frame %ld %zu\n", frame, count);
    for (i = 0; i < count; ++i) {
        mtt_track_view v;
        if (mtt_tracker_track(&trk, i, &v) != MTT_OK) continue;
        printf("T %lu %d", (unsigned long)v.id, v.confirmed);
        for (r = 0; r < 4; ++r) printf(" %.17g", (double)v.x[r]);
        for (r = 0; r < 4; ++r)
            for (c = 0; c < 4; ++c) printf(" %.17g", (double)v.P[r][c]);
        printf(" %.17g %lu %ld\n", (double)v.existence, (unsigned long)v.age, (long)v.meas);
    }
}

int main(void)
{
    static char buf[LINE_MAX_LEN];
    char *w[MAX_WORDS];
    mtt_params par;
    const char *bad = NULL;
    int inited = 0, n;
    long line = 0, frame = 0;

    if (mtt_params_default(&par) != MTT_OK) return 2;
    /* the reference (python/mtt_ref) is [S0]'s lm-ihpda */
    par.lm_ihpda_variant = MTT_LM_IHPDA_S0;
    while (fgets(buf, sizeof buf, stdin) != NULL) {
        ++line;
        n = split(buf, w);
        if (n == 0 || w[0][0] == '#') continue;
        if (strcmp(w[0], "param") == 0) {
            if (inited) return die(line, "param after the first track or frame");
            if (set_param(&par, w, n) != 0) return die(line, "bad param");
            continue;
        }
        if (!inited) {
            if (mtt_tracker_init(&trk, &par) != MTT_OK) {
                if (mtt_params_check(&par, &bad) != MTT_OK) bad = bad ? bad : "?";
                fprintf(stderr, "driver: invalid parameter %s\n", bad ? bad : "(init failed)");
                return 2;
            }
            inited = 1;
        }
        if (strcmp(w[0], "track") == 0) {
            mtt_real x[4], P[16];
            double v;
            int k;
            if (n != 21) return die(line, "track needs 20 numbers");
            for (k = 0; k < 20; ++k) {
                if (!num(w[1 + k], &v)) return die(line, "bad number");
                if (k < 4) x[k] = (mtt_real)v;
                else P[k - 4] = (mtt_real)v;
            }
            if (mtt_tracker_add_track(&trk, x, P, NULL) != MTT_OK) return die(line, "add_track refused");
        } else if (strcmp(w[0], "frame") == 0) {
            double t, cnt;
            size_t m, k;
            if (n != 3 || !num(w[1], &t) || !num(w[2], &cnt) || cnt < 0
                || cnt > (double)(sizeof meas / sizeof meas[0]))
                return die(line, "bad frame line");
            m = (size_t)cnt;
            for (k = 0; k < m; ++k) {
                double x, y, a = 0.0;
                if (fgets(buf, sizeof buf, stdin) == NULL) return die(line, "missing detection");
                ++line;
                if (split(buf, w) != 3 || !num(w[0], &x) || !num(w[1], &y)) return die(line, "bad detection");
                meas[k].x = (mtt_real)x;
                meas[k].y = (mtt_real)y;
                meas[k].has_amplitude = strcmp(w[2], "-") != 0;
                if (meas[k].has_amplitude && !num(w[2], &a)) return die(line, "bad amplitude");
                meas[k].amplitude = (mtt_real)a;
            }
            if (mtt_tracker_step(&trk, (mtt_real)t, m ? meas : NULL, m) != MTT_OK)
                return die(line, "mtt_tracker_step refused the frame");
            print_tracks(frame++);
        } else {
            return die(line, "unknown line");
        }
    }
    return 0;
}
