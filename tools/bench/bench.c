/* SPDX-License-Identifier: BSD-3-Clause */
/* bench.c - mtt-bench: per-frame cost of every association mode against
 * load, with a bare Kalman floor (docs/PERFORMANCE.md).
 *
 * Workloads (deterministic):
 *   dense N   N targets (CV, reflecting at the borders) in a square of side
 *             200 sqrt(N), PD 0.9, two uniform clutter points per target per
 *             frame; 50 warm-up frames, then --frames timed frames.
 *   replay    a docs/FORMATS.md detections file and settings (e.g. the formations
 *             scenario): the busiest frame (most tracks + gated pairs) is
 *             re-run --frames times from a snapshot of the tracker.
 * For each workload and mode: median and worst wall time per frame, the
 * per-stage breakdown from the cycle-counter callback (ns), the cost per
 * (track + gated pair), and a floor measured on the same tracks in the same
 * process: each track does only a Kalman predict and a one-measurement
 * update.  Times are wall clock (CLOCK_MONOTONIC): for repeatable figures use
 * instruction counts (tools/bench/bench.sh runs callgrind). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mtt_internal.h"
#include "mtt_io.h"
#include "sim.h"

/* Under valgrind --tool=callgrind, the counters are zeroed when the timed
 * frames start, so the inclusive instruction counts of mtt_tracker_step and
 * floor_run cover exactly the timed frames (tools/bench/bench.sh).  Outside
 * valgrind the request costs a few instructions. */
#ifdef MTT_HAVE_CALLGRIND_H
#include <valgrind/callgrind.h>
#define BENCH_ZERO_COUNTS() CALLGRIND_ZERO_STATS
#else
#define BENCH_ZERO_COUNTS() ((void)0)
#endif

static mtt_tracker trk, snap;

/* The workloads' doubles into mtt_real through tools/io/'s one conversion (the
 * fixed-point build's Q formats, docs/FIXED_POINT.md §3; float and double:
 * the cast). */
static mtt_real tor(double v, int fmt)
{
    mtt_real r;
    (void)mtt_io_to_real(v, fmt, &r); /* the workloads stay in range */
    return r;
}

/* A parameter in the user's units, through the parameter table. */
static void set_param(mtt_params *p, const char *key, double v)
{
    if (mtt_params_set(p, key, &v, 1) != MTT_OK) {
        fprintf(stderr, "mtt-bench: parameter %s = %g refused\n", key, v);
        exit(1);
    }
}

#ifdef MTT_REAL_FIXED
#define REAL_NAME "fixed"
#else
#define REAL_NAME (sizeof(mtt_real) == 4 ? "float" : "double")
#endif

/* Every library call is checked: a benchmark that silently failed would
 * time nothing. */
static void check(mtt_status st, const char *what)
{
    if (st != MTT_OK) {
        fprintf(stderr, "mtt-bench: %s failed (status %d)\n", what, (int)st);
        exit(1);
    }
}

/* 1 when mode a is built into this library (its default parameters pass
 * mtt_params_check); *name receives its docs/FORMATS.md name. */
/* --motion: cv (default), imm with the default models of docs/FORMATS.md
 * (CV + CA), or auto (with --set process_psd=0 --set max_accel=A the motion
 * of ALGORITHMS.md §2.2); modes that refuse IMM are skipped. */
static mtt_motion g_motion = MTT_MOTION_CV;
static long g_scan = -1; /* --scan: the replay frame to time (-1: the busiest) */
static int g_meas_cov;    /* --meas-cov: dense detections carry meas_sigma's R as their own */
static int g_polar;       /* --polar: dense detections as range and bearing (mtt_tracker_step_polar) */

static int mode_built(mtt_assoc a, const char **name)
{
    mtt_params p;
    check(mtt_params_default(&p), "mtt_params_default");
    p.association = a;
    p.motion = g_motion;
    if (MTT_REAL_KIND > 2) {
        set_param(&p, "clutter_density", 1e-4); /* the fixed-point build needs it declared */
    }
    if (mtt_assoc_name(a, name) != MTT_OK) {
        return 0; /* not a mode of this build's table (lm-ipda-all without the baselines) */
    }
    return mtt_params_check(&p, NULL) == MTT_OK;
}

static uint64_t now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (uint64_t)ts.tv_sec * 1000000000u + (uint64_t)ts.tv_nsec;
}

static uint32_t ns_counter(void *ctx)
{
    (void)ctx;
    return (uint32_t)now_ns();
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, size_t n)
{
    qsort(v, n, sizeof *v, cmp_double);
    return (n % 2u) ? v[n / 2u] : 0.5 * (v[n / 2u - 1u] + v[n / 2u]);
}

/* The floor: every live track of `t` does a Kalman predict and an update
 * with one measurement (its predicted position shifted by a fixed offset).
 * Works on copies: the tracker is not changed.  Not inlined, so callgrind
 * reports it as a function of its own. */
#ifndef MTT_REAL_FIXED
static mtt_state fx[MTT_MAX_TRACKS];
static mtt_cov fP[MTT_MAX_TRACKS];

#if defined(__GNUC__)
__attribute__((noinline))
#endif
static mtt_real floor_run(const mtt_tracker *t, mtt_real dt)
{
    mtt_state xp;
    mtt_cov Pp;
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], nu[1][2], beta[1] = {MTT_R(1.0)};
    mtt_real sink = MTT_R(0.0);
    uint16_t i;
    for (i = 0; i < t->n_tracks; ++i) {
        mtt_kalman_predict(dt, t->par.process_psd, fx[i], fP[i], xp, Pp);
        if (mtt_kalman_innov(Pp, t->R, S, Si, &det, K) != 0) {
            continue;
        }
        nu[0][0] = MTT_R(0.5);
        nu[0][1] = MTT_R(-0.5);
        mtt_kalman_pda(xp, Pp, K, Si, t->R, 1, nu, beta, MTT_R(0.0), fx[i], fP[i]);
        sink += fx[i][0];
    }
    return sink;
}

static double floor_ns(const mtt_tracker *t, mtt_real dt)
{
    uint64_t t0;
    uint16_t i;
    volatile mtt_real sink;
    for (i = 0; i < t->n_tracks; ++i) {
        memcpy(fx[i], t->tracks[i].x, sizeof fx[i]);
        memcpy(fP[i], t->tracks[i].P, sizeof fP[i]);
    }
    t0 = now_ns();
    sink = floor_run(t, dt);
    (void)sink;
    return (double)(now_ns() - t0);
}
#else
/* The fixed-point build: no floor (the Kalman kernels' block floating
 * point has its own entry points); the column reads 0. */
static double floor_ns(const mtt_tracker *t, mtt_real dt)
{
    (void)t;
    (void)dt;
    return 0.0;
}
#endif

typedef struct {
    double *t, *fl, *per;       /* per timed frame: step ns, floor ns, ns per (track + pair) */
    double stage[MTT_STAGE_COUNT];
    double tracks, pairs;
    size_t n;
} result;

static void result_alloc(result *r, size_t n)
{
    memset(r, 0, sizeof *r);
    r->t = calloc(n, sizeof *r->t);
    r->fl = calloc(n, sizeof *r->fl);
    r->per = calloc(n, sizeof *r->per);
    if (!r->t || !r->fl || !r->per) {
        fprintf(stderr, "mtt-bench: out of memory\n");
        exit(1);
    }
}

static void result_add(result *r, double t_ns, double fl_ns, const mtt_stats *st, uint16_t n_tracks)
{
    int s;
    double load = (double)n_tracks + (double)st->last.pairs;
    r->t[r->n] = t_ns;
    r->fl[r->n] = fl_ns;
    r->per[r->n] = t_ns / (load > 0.0 ? load : 1.0);
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        r->stage[s] += (double)st->stage_cycles[s];
    }
    r->tracks += n_tracks;
    r->pairs += st->last.pairs;
    r->n++;
}

static const char *stage_names[MTT_STAGE_COUNT] = {"valid", "predict", "gate", "lm", "assoc",
                                                   "update", "init", "merge", "manage"};

static void result_print(const char *work, const char *mode, result *r, FILE *json, int *first)
{
    double worst = 0.0, med, fmed, per, total = 0.0;
    size_t i;
    int s;
    for (i = 0; i < r->n; ++i) {
        worst = r->t[i] > worst ? r->t[i] : worst;
    }
    med = median(r->t, r->n);
    fmed = median(r->fl, r->n);
    per = median(r->per, r->n);
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        total += r->stage[s];
    }
    printf("%-12s %-16s %7.1f %7.1f %9.2f %9.2f %8.2f %7.1fx %8.1f  ", work, mode, r->tracks / (double)r->n,
           r->pairs / (double)r->n, med / 1e3, worst / 1e3, fmed / 1e3, fmed > 0 ? med / fmed : 0.0, per);
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        printf(" %s %.0f%%", stage_names[s], total > 0 ? 100.0 * r->stage[s] / total : 0.0);
    }
    printf("\n");
    if (json) {
        fprintf(json, "%s\n  {\"workload\": \"%s\", \"mode\": \"%s\", \"frames\": %zu, \"tracks\": %.2f, "
                      "\"pairs\": %.2f, \"median_us\": %.3f, \"worst_us\": %.3f, \"floor_median_us\": %.3f, "
                      "\"ratio_to_floor\": %.3f, \"ns_per_track_plus_pair\": %.2f, \"stage_ns\": {",
                *first ? "" : ",", work, mode, r->n, r->tracks / (double)r->n, r->pairs / (double)r->n,
                med / 1e3, worst / 1e3, fmed / 1e3, fmed > 0 ? med / fmed : 0.0, per);
        for (s = 0; s < MTT_STAGE_COUNT; ++s) {
            fprintf(json, "%s\"%s\": %.1f", s ? ", " : "", stage_names[s], r->stage[s] / (double)r->n);
        }
        fprintf(json, "}}");
        *first = 0;
    }
    free(r->t);
    free(r->fl);
    free(r->per);
}

/* ---- dense workload ---- */

typedef struct { double x, y, vx, vy; } tgt;

static void dense_frame(sim_rng *rng, tgt *tg, int n, double side, mtt_meas *m, size_t *nm)
{
    int i, c;
    size_t k = 0;
    for (i = 0; i < n; ++i) {
        tg[i].x += tg[i].vx;
        tg[i].y += tg[i].vy;
        if (tg[i].x < 0 || tg[i].x > side) tg[i].vx = -tg[i].vx;
        if (tg[i].y < 0 || tg[i].y > side) tg[i].vy = -tg[i].vy;
        if (sim_unif(rng) < 0.9) {
            m[k].x = tor(tg[i].x + sim_gauss(rng), MTT_IO_POS);
            m[k].y = tor(tg[i].y + sim_gauss(rng), MTT_IO_POS);
            m[k].amplitude = tor(-4.0 * log(sim_unif(rng)), MTT_IO_AMP);
            m[k].has_amplitude = 1;
            ++k;
        }
        for (c = 0; c < 2; ++c) {
            m[k].x = tor(side * sim_unif(rng), MTT_IO_POS);
            m[k].y = tor(side * sim_unif(rng), MTT_IO_POS);
            m[k].amplitude = tor(-log(sim_unif(rng)), MTT_IO_AMP);
            m[k].has_amplitude = 1;
            ++k;
        }
    }
    *nm = k;
}

/* --variant: lm_ihpda_variant for every workload, -1 = not given. */
static int variant = -1;
/* --set KEY=NUMBER: numeric settings of every workload, after --variant. */
#define MAX_SETS 8
static const char *set_key[MAX_SETS];
static double set_val[MAX_SETS];
static int n_sets;

static void apply_variant_and_sets(mtt_params *p)
{
    int k;
    if (variant >= 0) {
        p->lm_ihpda_variant = (mtt_lm_ihpda_variant)variant;
    }
    for (k = 0; k < n_sets; ++k) {
        set_param(p, set_key[k], set_val[k]);
    }
}

static void run_dense(int n, mtt_assoc mode, size_t frames, FILE *json, int *first)
{
    const double side = 200.0 * sqrt((double)n);
    tgt *tg = calloc((size_t)n, sizeof *tg);
    mtt_meas *m = calloc((size_t)n * 3u + 1u, sizeof *m);
    mtt_meas_cov *c = calloc((size_t)n * 3u + 1u, sizeof *c);
    mtt_polar *pd = calloc((size_t)n * 3u + 1u, sizeof *pd);
    /* --polar: a sensor off the scene's corner, its bearing noise meas_sigma's at the centre */
    const double sx = -side, sy = -side / 2.0, r0 = hypot(1.5 * side, side);
    sim_rng rng = {1000u + (uint64_t)n};
    mtt_params p;
    result r;
    size_t f, nm;
    int i;
    char work[32];
    const char *name = "?";
    if (!tg || !m || !c || !pd) {
        fprintf(stderr, "mtt-bench: out of memory\n");
        exit(1);
    }
    for (i = 0; i < n; ++i) {
        double a = 6.283185307179586 * sim_unif(&rng), v = 1.0 + 2.0 * sim_unif(&rng);
        tg[i].x = side * sim_unif(&rng);
        tg[i].y = side * sim_unif(&rng);
        tg[i].vx = v * cos(a);
        tg[i].vy = v * sin(a);
    }
    check(mtt_params_default(&p), "mtt_params_default");
    p.association = mode;
    p.motion = g_motion;
    set_param(&p, "clutter_density", 2.0 * n / (side * side));
    set_param(&p, "snr_rho", 3.0);
    set_param(&p, "vmax", 8.0);
    p.cycle_counter = ns_counter;
    apply_variant_and_sets(&p);
#ifdef MTT_REAL_FIXED /* polar detections are refused there (docs/FIXED_POINT.md section 5) */
    (void)sx;
    (void)sy;
    (void)r0;
#else
    if (g_polar) {
        const double sxy[2] = {sx, sy}, sig[2] = {(double)p.meas_sigma[0], (double)p.meas_sigma[1] / r0};
        p.measurement = MTT_MEASUREMENT_POLAR;
        check(mtt_params_set(&p, "sensor_xy", sxy, 2), "sensor_xy");
        check(mtt_params_set(&p, "meas_sigma", sig, 2), "meas_sigma");
        set_param(&p, "clutter_density", 2.0 * n / (side * side) * r0); /* per range x bearing */
    }
#endif
    if (mtt_tracker_init(&trk, &p) != MTT_OK) {
        fprintf(stderr, "mtt-bench: init failed%s\n", g_polar ? " (--polar: a build without MTT_WITH_MEAS_COV?)" : "");
        exit(1);
    }
    for (i = 0; i < n * 3 + 1; ++i) { /* the same R, through the per-detection paths */
        c[i].r_xx = p.meas_sigma[0] * p.meas_sigma[0];
        c[i].r_yy = p.meas_sigma[1] * p.meas_sigma[1];
    }
    result_alloc(&r, frames);
    for (f = 0; f < 50u + frames; ++f) {
        uint64_t t0;
        double fl = 0.0, dt;
        mtt_stats st;
        dense_frame(&rng, tg, n, side, m, &nm);
#ifndef MTT_REAL_FIXED
        if (g_polar) {
            size_t k;
            for (k = 0; k < nm; ++k) {
                pd[k].range = (mtt_real)hypot((double)m[k].x - sx, (double)m[k].y - sy);
                pd[k].bearing = (mtt_real)atan2((double)m[k].y - sy, (double)m[k].x - sx);
                pd[k].amplitude = m[k].amplitude;
                pd[k].has_amplitude = m[k].has_amplitude;
            }
        }
#endif
        if (f == 50u) {
            BENCH_ZERO_COUNTS();
        }
        if (f >= 50u) {
            fl = floor_ns(&trk, tor(1.0, MTT_IO_TIME));
        }
        t0 = now_ns();
        if ((g_polar ? mtt_tracker_step_polar(&trk, tor((double)f, MTT_IO_TIME), pd, nm)
                     : mtt_tracker_step_cov(&trk, tor((double)f, MTT_IO_TIME), m, g_meas_cov ? c : NULL, nm)) != MTT_OK) {
            fprintf(stderr, "mtt-bench: step failed%s\n", g_meas_cov ? " (--meas-cov: a build without MTT_WITH_MEAS_COV?)" : "");
            exit(1);
        }
        dt = (double)(now_ns() - t0);
        if (f >= 50u) {
            check(mtt_tracker_stats(&trk, &st), "mtt_tracker_stats");
            result_add(&r, dt, fl, &st, trk.n_tracks);
        }
    }
    check(mtt_assoc_name(mode, &name), "mtt_assoc_name");
    snprintf(work, sizeof work, "dense-%d", n);
    result_print(work, name, &r, json, first);
    free(tg);
    free(m);
    free(c);
    free(pd);
}

/* ---- replay workload: the busiest frame of a detections file (or --scan's) ---- */

static int run_replay(const char *det, const char *cfg, mtt_assoc mode, size_t reps, FILE *json, int *first)
{
    mtt_io_detections d;
    mtt_io_settings s;
    size_t k, busiest = 0, i;
    double best = -1.0;
    result r;
    const char *name = "?";
    mtt_real dt = tor(1.0, MTT_IO_TIME);
    if (mtt_io_read_detections(det, &d) != 0) {
        return -1;
    }
    if (mtt_io_read_settings(cfg, &s) != 0) {
        mtt_io_free_detections(&d);
        return -1;
    }
    s.params.association = mode;
    if (g_motion != MTT_MOTION_CV) {
        s.params.motion = g_motion; /* the settings file's imm_models, or the defaults */
    }
    s.params.cycle_counter = ns_counter;
    apply_variant_and_sets(&s.params);
    /* pass 1: find the busiest frame */
    for (i = 0; i < 2; ++i) {
        if (mtt_tracker_init(&trk, &s.params) != MTT_OK) {
            fprintf(stderr, "mtt-bench: bad settings in %s\n", cfg);
            return -1;
        }
        for (k = 0; k < d.n_scans; ++k) {
            const mtt_io_scan *sc = &d.scans[k];
            mtt_stats st;
            if (i == 1 && k == busiest) {
                memcpy(&snap, &trk, sizeof trk);
                dt = k > 0 ? sc->rtime - d.scans[k - 1].rtime : tor(1.0, MTT_IO_TIME);
                break;
            }
            if (mtt_tracker_step(&trk, sc->rtime, d.meas + sc->first, sc->count) != MTT_OK) {
                return -1;
            }
            check(mtt_tracker_stats(&trk, &st), "mtt_tracker_stats");
            if (i == 0 && (g_scan >= 0 ? (long)sc->scan == g_scan && best < 0.0
                                       : (double)trk.n_tracks + (double)st.last.pairs > best)) {
                best = (double)trk.n_tracks + (double)st.last.pairs;
                busiest = k;
            }
        }
        if (i == 0 && best < 0.0) {
            fprintf(stderr, "mtt-bench: %s: no scan %ld\n", det, g_scan);
            return -1;
        }
    }
    result_alloc(&r, reps);
    BENCH_ZERO_COUNTS();
    for (i = 0; i < reps; ++i) {
        const mtt_io_scan *sc = &d.scans[busiest];
        mtt_stats st;
        uint64_t t0;
        double t, fl;
        memcpy(&trk, &snap, sizeof trk);
        fl = floor_ns(&trk, dt);
        t0 = now_ns();
        check(mtt_tracker_step(&trk, sc->rtime, d.meas + sc->first, sc->count), "mtt_tracker_step");
        t = (double)(now_ns() - t0);
        check(mtt_tracker_stats(&trk, &st), "mtt_tracker_stats");
        result_add(&r, t, fl, &st, snap.n_tracks);
    }
    check(mtt_assoc_name(mode, &name), "mtt_assoc_name");
    {
        char work[32];
        snprintf(work, sizeof work, "scan-%lu", d.scans[busiest].scan);
        result_print(work, name, &r, json, first);
    }
    mtt_io_free_detections(&d);
    mtt_io_free_settings(&s);
    return 0;
}

static void usage(FILE *f)
{
    fprintf(f,
            "usage: mtt-bench [--frames N] [--dense N,N,...] [--modes m,m,...]\n"
            "                 [--det D.det.csv --config S.json] [--json OUT.json]\n"
            "                 [--motion cv|imm|auto] [--meas-cov] [--polar]\n"
            "\n"
            "Per-frame cost of each association mode against load, beside a floor of\n"
            "bare Kalman predict+update on the same tracks.\n"
            "  --frames N   timed frames per dense workload, and repetitions of the\n"
            "               busiest replay frame (default 1000)\n"
            "  --dense L    comma list of target counts (default 4,16,64,256; 0 = none)\n"
            "  --modes L    comma list of association modes (default: every mode built in)\n"
            "  --det/--config  also replay a detections file and time its busiest frame\n"
            "  --scan K     time the replay's scan K (the file's scan column) instead\n"
            "  --json F     write the results as JSON\n"
            "  --variant V  lm_ihpda_variant (s0 or contest) of every workload\n"
            "               (default: s0 for dense, the config's for the replay)\n"
            "  --set K=V    a numeric setting of every workload (repeatable, up to 8)\n"
            "  --meas-cov   the dense detections carry meas_sigma's covariance as their\n"
            "               own (mtt_tracker_step_cov): the cost of the per-detection\n"
            "               paths on the same tracks (ALGORITHMS.md section 3.1)\n"
            "  --polar      the dense detections as range and bearing from a sensor off\n"
            "               the scene (mtt_tracker_step_polar, ALGORITHMS.md section 3.2)\n"
            "  --list-modes print the modes built into this library and exit\n"
            "  --motion M   cv (default), imm (the default CV + CA models, or the\n"
            "               --config file's imm_models) or auto (with --set process_psd=0\n"
            "               --set max_accel=A: the motion from max_accel, ALGORITHMS.md\n"
            "               section 2.2); modes without IMM are skipped\n"
            "Columns: tracks, pairs = mean per timed frame; med/worst/floor in us;\n"
            "ratio = median / floor median; ns/(t+p) = median ns per (track + gated pair);\n"
            "then the share of each stage (cycle-counter callback).\n");
}

int main(int argc, char **argv)
{
    size_t frames = 1000;
    const char *dense = "4,16,64,256", *modes = NULL, *det = NULL, *cfg = NULL, *jpath = NULL;
    FILE *json = NULL;
    int i, first = 1;
    for (i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(argv[i], "--list-modes")) {
            int k;
            const char *name;
            for (k = 0; k < (int)MTT_ASSOC_COUNT; ++k) {
                if (mode_built((mtt_assoc)k, &name)) {
                    printf("%s\n", name);
                }
            }
            return 0;
        } else if (!strcmp(argv[i], "--meas-cov")) {
            g_meas_cov = 1;
        } else if (!strcmp(argv[i], "--polar")) {
#ifdef MTT_REAL_FIXED
            fprintf(stderr, "mtt-bench: --polar needs a float or double build (polar detections are refused in fixed point)\n");
            return 2;
#endif
            g_polar = 1;
        } else if (i + 1 < argc && !strcmp(argv[i], "--frames")) {
            frames = strtoul(argv[++i], NULL, 10);
        } else if (i + 1 < argc && !strcmp(argv[i], "--dense")) {
            dense = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--modes")) {
            modes = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--det")) {
            det = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--config")) {
            cfg = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--variant")) {
            ++i;
            variant = !strcmp(argv[i], "s0") ? (int)MTT_LM_IHPDA_S0
                      : !strcmp(argv[i], "contest") ? (int)MTT_LM_IHPDA_CONTEST : -2;
            if (variant == -2) {
                fprintf(stderr, "mtt-bench: --variant must be s0 or contest\n");
                return 2;
            }
        } else if (i + 1 < argc && !strcmp(argv[i], "--set")) {
            char *eq = strchr(argv[++i], '=');
            char *end = NULL;
            if (eq == NULL || n_sets == MAX_SETS) {
                fprintf(stderr, "mtt-bench: --set KEY=NUMBER, at most %d\n", MAX_SETS);
                return 2;
            }
            *eq = '\0';
            set_key[n_sets] = argv[i];
            set_val[n_sets] = strtod(eq + 1, &end);
            if (end == eq + 1 || *end != '\0') {
                fprintf(stderr, "mtt-bench: --set %s: not a number\n", argv[i]);
                return 2;
            }
            ++n_sets;
        } else if (i + 1 < argc && !strcmp(argv[i], "--scan")) {
            char *end = NULL;
            g_scan = strtol(argv[++i], &end, 10);
            if (end == argv[i] || *end != '\0' || g_scan < 0) {
                fprintf(stderr, "mtt-bench: --scan %s: not a scan number >= 0\n", argv[i]);
                return 2;
            }
        } else if (i + 1 < argc && !strcmp(argv[i], "--json")) {
            jpath = argv[++i];
        } else if (i + 1 < argc && !strcmp(argv[i], "--motion") &&
                   (!strcmp(argv[i + 1], "cv") || !strcmp(argv[i + 1], "imm") || !strcmp(argv[i + 1], "auto"))) {
            ++i;
            g_motion = !strcmp(argv[i], "imm") ? MTT_MOTION_IMM : !strcmp(argv[i], "auto") ? MTT_MOTION_AUTO : MTT_MOTION_CV;
        } else {
            fprintf(stderr, "mtt-bench: unknown or incomplete option '%s'\n", argv[i]);
            usage(stderr);
            return 2;
        }
    }
    if (frames < 1 || (det == NULL) != (cfg == NULL)) {
        usage(stderr);
        return 2;
    }
    if (jpath && !(json = fopen(jpath, "w"))) {
        fprintf(stderr, "mtt-bench: cannot write %s\n", jpath);
        return 1;
    }
    if (json) fprintf(json, "{\"max_tracks\": %d, \"real\": \"%s\", \"results\": [", MTT_MAX_TRACKS,
                      REAL_NAME);
    printf("mtt-bench: MTT_MAX_TRACKS=%d MTT_MAX_MEAS=%d MTT_MAX_PAIRS=%d mtt_real=%s\n", MTT_MAX_TRACKS,
           MTT_MAX_MEAS, MTT_MAX_PAIRS, REAL_NAME);
    printf("%-12s %-16s %7s %7s %9s %9s %8s %8s %8s   stages\n", "workload", "mode", "tracks", "pairs",
           "med_us", "worst_us", "floor_us", "ratio", "ns/(t+p)");
    for (i = 0; i < (int)MTT_ASSOC_COUNT; ++i) {
        const char *name;
        if (!mode_built((mtt_assoc)i, &name)) {
            continue;
        }
        if (modes) {
            const char *hit = strstr(modes, name);
            size_t L = strlen(name);
            /* whole comma-separated items only ("ihpda" must not match "lm-ihpda") */
            while (hit && !((hit == modes || hit[-1] == ',') && (hit[L] == ',' || hit[L] == '\0'))) {
                hit = strstr(hit + 1, name);
            }
            if (!hit) continue;
        }
        if (det && run_replay(det, cfg, (mtt_assoc)i, frames, json, &first) != 0) {
            return 1;
        }
        {
            const char *c = dense;
            while (*c) {
                int n = atoi(c);
                if (n > 0) {
                    run_dense(n, (mtt_assoc)i, frames, json, &first);
                }
                c = strchr(c, ',');
                if (!c) break;
                ++c;
            }
        }
        fflush(stdout);
    }
    if (json) {
        fprintf(json, "\n]}\n");
        fclose(json);
    }
    return 0;
}
