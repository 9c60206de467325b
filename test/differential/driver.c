/* driver.c - runs the library on one differential scene (stdin) and prints
 * every live track after each frame (stdout), for python/tests/test_differential.py.
 *
 * Public API only (include/mtt/mtt.h); built with mtt_real = double.  The
 * scene format is documented in python/mtt_ref/scene.py:
 *
 *   param <name> <value...>     an mtt_params field, named as in docs/FORMATS.md
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

/* One docs/FORMATS.md setting onto mtt_params; 0 on success. */
static int set_param(mtt_params *p, char **w, int n)
{
    static const struct { const char *name; size_t off; int count; } reals[] = {
        {"process_psd", offsetof(mtt_params, process_psd), 1},
        {"meas_sigma", offsetof(mtt_params, meas_sigma), 2},
        {"pd", offsetof(mtt_params, pd), 1},
        {"pg", offsetof(mtt_params, pg), 1},
        {"clutter_density", offsetof(mtt_params, clutter_density), 1},
        {"snr_rho", offsetof(mtt_params, snr_rho), 1},
        {"markov_p11", offsetof(mtt_params, markov_p11), 1},
        {"markov_p21", offsetof(mtt_params, markov_p21), 1},
        {"existence_init", offsetof(mtt_params, existence_init), 1},
        {"confirm_threshold", offsetof(mtt_params, confirm_threshold), 1},
        {"terminate_threshold", offsetof(mtt_params, terminate_threshold), 1},
        {"merge_threshold", offsetof(mtt_params, merge_threshold), 1},
        {"vmax", offsetof(mtt_params, vmax), 1},
        {"intensity_f1", offsetof(mtt_params, intensity_f1), 3},
        {"intensity_f2", offsetof(mtt_params, intensity_f2), 3},
        {"intensity_blend", offsetof(mtt_params, intensity_blend), 2},
    };
    size_t i;
    int k;
    double v;
    if (n < 3) return -1;
    if (strcmp(w[1], "association") == 0)
        return mtt_assoc_parse(w[2], &p->association) == MTT_OK ? 0 : -1;
    if (strcmp(w[1], "init_gate") == 0) {
        if (strcmp(w[2], "vmax") == 0) p->init_gate = MTT_INIT_GATE_VMAX;
        else if (strcmp(w[2], "intensity") == 0) p->init_gate = MTT_INIT_GATE_INTENSITY;
        else return -1;
        return 0;
    }
    if (strcmp(w[1], "initiate") == 0) {
        if (!num(w[2], &v)) return -1;
        p->initiate = v != 0.0;
        return 0;
    }
    for (i = 0; i < sizeof reals / sizeof reals[0]; ++i) {
        if (strcmp(w[1], reals[i].name) != 0) continue;
        if (n != 2 + reals[i].count) return -1;
        for (k = 0; k < reals[i].count; ++k) {
            if (!num(w[2 + k], &v)) return -1;
            ((mtt_real *)(void *)((char *)p + reals[i].off))[k] = (mtt_real)v;
        }
        return 0;
    }
    return -1;
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
