/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/soak.c - mtt-soak: a long run of the tracker on an evolving random
 * scene, checking every invariant after every frame.
 *
 *   mtt-soak [--frames N] [--seed S] [--mode NAME|all] [--progress K] [--quiet]
 *
 * The scene: targets are born (singly, and in groups that converge on one
 * point and cross), move with constant velocity plus white-noise
 * acceleration, leave the area or die; each is detected with probability
 * PD with Gaussian noise and a Swerling-like amplitude (mean 1 + rho);
 * uniform Poisson clutter with amplitude mean 1, with bursts up to and
 * beyond MTT_MAX_MEAS (uniform, or packed around a target); dropped frames
 * (time advances, no step), empty frames, frames with a few NaN/Inf or
 * negative-amplitude detections, and time steps from 1e-3 to 50 times
 * the nominal one.
 *
 * After every frame tools/fuzz/mtt_check.h verifies: covariances finite,
 * symmetric and positive definite; existence in [0, 1]; counts within the
 * bounds; identities unique and never reused; stats consistent (total = sum
 * of last, births - deletions - merges - numeric deletions = count change,
 * meas_bad / meas_dropped as the scene made them).  The first violation
 * stops the run with exit status 1 and a message naming the frame: the run
 * is deterministic, so the same --seed and --frames reproduce it.
 *
 * Prints the frames run, tracks born, confirmed, deleted, merged, the
 * worst margins (smallest relative Cholesky pivot and eigenvalue of any P,
 * largest asymmetry, existence range), the time per frame, and a progress
 * line on stderr every K frames (default 100000).  `--mode all` runs every
 * association mode that mtt_params_check accepts, one after the other.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mtt/mtt.h"
#include "mtt_check.h"

#define PROG "mtt-soak"
#define MAX_TARGETS 48
#define AREA 2000.0
#define MAX_FRAME_MEAS (MTT_MAX_MEAS + 160)

typedef struct target {
    double x, y, vx, vy;
} target;

typedef struct scene {
    uint64_t rng;
    target t[MAX_TARGETS];
    int n;
    int burst_left, burst_kind;
    double rho, pd, sigma, q;
} scene;

static mtt_tracker trk;
static mtt_meas meas[MAX_FRAME_MEAS];
static mtt_check chk;

/* ---- random numbers (splitmix64: small, fast, reproducible everywhere) ---- */
static uint64_t rnd64(scene *s)
{
    uint64_t z = (s->rng += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}
static double unif(scene *s) { return (double)(rnd64(s) >> 11) * (1.0 / 9007199254740992.0); }
static double gauss(scene *s)
{
    double u = unif(s), v = unif(s);
    if (u < 1e-300)
        u = 1e-300;
    return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}
static double expo(scene *s, double mean)
{
    double u = unif(s);
    return -mean * log(u > 1e-300 ? u : 1e-300);
}
static int poisson(scene *s, double mean)
{
    /* Knuth for small means, normal approximation above */
    if (mean > 30.0) {
        double v = mean + sqrt(mean) * gauss(s);
        return v > 0.0 ? (int)(v + 0.5) : 0;
    } else {
        double l = exp(-mean), p = 1.0;
        int k = 0;
        do {
            ++k;
            p *= unif(s);
        } while (p > l);
        return k - 1;
    }
}

/* The scene's doubles into mtt_real: the cast, or in the fixed-point build
 * the host boundary's conversion into the position and amplitude formats
 * (docs/FIXED_POINT.md §3: NaN, Inf and out of range saturate, and the
 * tracker skips and counts them like NaN in float). */
#ifdef MTT_REAL_FIXED
static mtt_real to_q(double v, int f)
{
    mtt_real q;
    (void)mtt_fx_from_double(v, f, &q); /* saturated when outside */
    return q;
}
#define TO_POS(v) to_q((v), MTT_FX_POS_FRAC)
#define TO_AMP(v) to_q((v), MTT_FX_AMP_FRAC)
#define TO_TIME(v) to_q((v), MTT_FX_T_FRAC)
/* Time is Q16 frames modulo 2^32 (the tracker compares it modulo 2^32). */
#define TIME_ADD(t, d) ((mtt_real)(int32_t)((uint32_t)(t) + (uint32_t)(d)))
#define TIME_LATER(a, b) ((uint32_t)(a) != (uint32_t)(b))
#define REAL_NAME "fixed"
#else
#define TO_POS(v) ((mtt_real)(v))
#define TO_AMP(v) ((mtt_real)(v))
#define TO_TIME(v) ((mtt_real)(v))
#define TIME_ADD(t, d) ((t) + (d))
#define TIME_LATER(a, b) ((a) > (b))
#define REAL_NAME (sizeof(mtt_real) == sizeof(float) ? "float" : "double")
#endif

static void add_meas(size_t *n, double x, double y, double amp, int has)
{
    if (*n >= MAX_FRAME_MEAS)
        return;
    meas[*n].x = TO_POS(x);
    meas[*n].y = TO_POS(y);
    meas[*n].amplitude = TO_AMP(amp);
    meas[*n].has_amplitude = has;
    ++*n;
}

static void spawn(scene *s, double x, double y, double vx, double vy)
{
    if (s->n < MAX_TARGETS) {
        target *t = &s->t[s->n++];
        t->x = x;
        t->y = y;
        t->vx = vx;
        t->vy = vy;
    }
}

/* Evolve the scene over dt and write this frame's detections. */
static size_t scene_frame(scene *s, double dt, size_t *n_bad)
{
    size_t n = 0;
    int i, k, nc;
    *n_bad = 0;
    /* deaths and motion */
    for (i = 0; i < s->n;) {
        target *t = &s->t[i];
        double sq = sqrt(s->q * dt);
        t->vx += sq * gauss(s);
        t->vy += sq * gauss(s);
        t->x += t->vx * dt;
        t->y += t->vy * dt;
        if (t->x < 0.0 || t->x > AREA || t->y < 0.0 || t->y > AREA || unif(s) < 0.004) {
            s->t[i] = s->t[--s->n];
            continue;
        }
        ++i;
    }
    /* births: single targets, and groups that cross at one point */
    if (unif(s) < 0.08)
        spawn(s, 100.0 + unif(s) * (AREA - 200.0), 100.0 + unif(s) * (AREA - 200.0),
              20.0 * (unif(s) - 0.5), 20.0 * (unif(s) - 0.5));
    if (unif(s) < 0.01) {
        double cx = 400.0 + unif(s) * (AREA - 800.0), cy = 400.0 + unif(s) * (AREA - 800.0);
        double tc = 10.0 + 20.0 * unif(s), sp = 3.0 + 10.0 * unif(s);
        int g = 2 + (int)(unif(s) * 3.0);
        for (k = 0; k < g; ++k) {
            double a = 6.283185307179586 * ((double)k / g + 0.1 * unif(s));
            spawn(s, cx - sp * tc * cos(a), cy - sp * tc * sin(a), sp * cos(a), sp * sin(a));
        }
    }
    /* target detections (a shuffled order is not needed: the library sorts) */
    for (i = 0; i < s->n; ++i) {
        if (unif(s) < s->pd)
            add_meas(&n, s->t[i].x + s->sigma * gauss(s), s->t[i].y + s->sigma * gauss(s),
                     expo(s, 1.0 + s->rho), unif(s) < 0.95);
    }
    /* clutter, with bursts */
    if (s->burst_left == 0 && unif(s) < 0.004) {
        s->burst_left = 1 + (int)(unif(s) * 5.0);
        s->burst_kind = (int)(unif(s) * 3.0);
    }
    if (s->burst_left > 0) {
        --s->burst_left;
        nc = MTT_MAX_MEAS - (int)(n) + (int)(unif(s) * 150.0) - 30;
        if (nc < 0)
            nc = 0;
    } else {
        nc = poisson(s, 20.0);
    }
    for (k = 0; k < nc; ++k) {
        if (s->burst_left > 0 && s->burst_kind == 0 && s->n > 0) {
            /* packed around a target: overloads its gate and the pairs */
            const target *t = &s->t[(int)(unif(s) * s->n) % s->n];
            add_meas(&n, t->x + 8.0 * gauss(s), t->y + 8.0 * gauss(s), expo(s, 1.0),
                     unif(s) < 0.95);
        } else if (s->burst_left > 0 && s->burst_kind == 1) {
            /* exact duplicates of one point */
            add_meas(&n, 1000.0, 1000.0, 1.0, 1);
        } else {
            add_meas(&n, unif(s) * AREA, unif(s) * AREA, expo(s, 1.0), unif(s) < 0.95);
        }
    }
    /* a few bad detections now and then */
    if (unif(s) < 0.002) {
        int nb = 1 + (int)(unif(s) * 3.0);
        for (k = 0; k < nb && n < MAX_FRAME_MEAS; ++k) {
            double r = unif(s);
            if (r < 0.3)
                add_meas(&n, (double)NAN, 5.0, 1.0, 1);
            else if (r < 0.6)
                add_meas(&n, 5.0, (double)INFINITY, 1.0, 0);
            else
                add_meas(&n, 5.0, 5.0, -1.0, 1);
            ++*n_bad;
        }
    }
    return n;
}

typedef struct result {
    unsigned long frames, steps, max_live;
    mtt_stats st;
    double step_sec, wall_sec;
} result;

static double now_sec(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int run(mtt_assoc mode, unsigned long frames, uint64_t seed, unsigned long progress,
               result *r)
{
    mtt_params p;
    scene s;
    mtt_real t = TO_TIME(0.0);
    double t_user = 0.0; /* the time in the user's units, for messages */
    double t0 = now_sec(), dt_nom = 1.0;
    unsigned long f;
    const char *name = "?";
    mtt_status st;

    if (mtt_assoc_name(mode, &name) != MTT_OK)
        name = "?";
    memset(r, 0, sizeof *r);
    memset(&s, 0, sizeof s);
    s.rng = seed * 0x2545f4914f6cdd1dull + (uint64_t)mode;
    s.pd = 0.9;
    s.sigma = 1.0;
    s.rho = 3.0;
    s.q = 0.05;
    if (mtt_params_default(&p) != MTT_OK)
        return 2;
    p.association = mode;
    {
        /* in the user's units through the parameter table (each key's Q
         * format in the fixed-point build); the fixed-point build has no
         * estimated clutter density (docs/FIXED_POINT.md finding 4) */
        const double dens = ((seed & 1u) || MTT_REAL_KIND > 2) ? 5e-6 : 0.0; /* known, or estimated */
        const char *const keys[5] = {"process_psd", "pd", "snr_rho", "vmax", "clutter_density"};
        const double vals[5] = {0.5, 0.9, 3.0, 25.0, dens};
        int k;
        for (k = 0; k < 5; ++k)
            if (mtt_params_set(&p, keys[k], &vals[k], 1) != MTT_OK)
                return 2;
    }
    st = mtt_tracker_init(&trk, &p);
    if (st != MTT_OK) {
        fprintf(stderr, PROG ": mode %s: mtt_tracker_init returned %d\n", name, (int)st);
        return 2;
    }
    mtt_check_init(&chk);

    for (f = 0; f < frames; ++f) {
        double dt = dt_nom, u = unif(&s), a, b;
        size_t n, n_bad;
        mtt_real tn;
        /* time steps: mostly nominal with jitter; some tiny, some huge */
        if (u < 0.002)
            dt = 1e-3;
        else if (u < 0.004)
            dt = 50.0;
        else if (u < 0.05)
            dt = 0.5 + 1.5 * unif(&s);
        n = scene_frame(&s, dt, &n_bad);
        tn = TIME_ADD(t, TO_TIME(dt));
        if (!TIME_LATER(tn, t)) {
            /* float time has run out of resolution for this step (t ~ 1e6
             * in float has a spacing of 1/16): step by a representable one */
            tn = TIME_ADD(t, TO_TIME(dt_nom));
            dt = dt_nom;
        }
        t = tn;
        t_user += dt;
        if (unif(&s) < 0.01) {
            ++r->frames; /* a dropped frame: the scene moved, the tracker is not stepped */
            continue;
        }
        if (unif(&s) < 0.01) {
            n = 0; /* an empty frame (sensor blanked) */
            n_bad = 0;
        }
        if (!mtt_check_before(&chk, &trk)) {
            fprintf(stderr, PROG ": mode %s, seed %llu, frame %lu: %s\n", name,
                    (unsigned long long)seed, f, chk.msg);
            return 1;
        }
        a = now_sec();
        st = mtt_tracker_step(&trk, t, n > 0 ? meas : NULL, n);
        b = now_sec();
        r->step_sec += b - a;
        ++r->frames;
        ++r->steps;
        if (st != MTT_OK) {
            fprintf(stderr, PROG ": mode %s, seed %llu, frame %lu: mtt_tracker_step returned %d\n",
                    name, (unsigned long long)seed, f, (int)st);
            return 1;
        }
        if (!mtt_check_frame(&chk, &trk, n, n_bad)) {
            fprintf(stderr, PROG ": mode %s, seed %llu, frame %lu (time %.9g, %zu measurements): "
                    "invariant violated: %s\n",
                    name, (unsigned long long)seed, f, t_user, n, chk.msg);
            return 1;
        }
        if (chk.n_prev > r->max_live)
            r->max_live = chk.n_prev;
        if (progress > 0 && (f + 1) % progress == 0) {
            fprintf(stderr, PROG ": %s: %lu/%lu frames, %.1f s, %lu live tracks, %u born\n", name,
                    f + 1, frames, now_sec() - t0, (unsigned long)chk.n_prev,
                    (unsigned)chk.sum.births);
        }
    }
    r->wall_sec = now_sec() - t0;
    if (mtt_tracker_stats(&trk, &r->st) != MTT_OK)
        return 2;
    return 0;
}

static void report(mtt_assoc mode, uint64_t seed, const result *r)
{
    const char *name = "?";
    const mtt_counts *c = &r->st.total;
    if (mtt_assoc_name(mode, &name) != MTT_OK)
        name = "?";
    printf("mode %s seed %llu: %lu frames (%lu stepped), real %s\n", name,
           (unsigned long long)seed, r->frames, r->steps,
           REAL_NAME);
    printf("  tracks: born %u, confirmed %u, deleted %u, merged %u, numeric deletions %u, "
           "max live %lu, births dropped %u\n",
           (unsigned)c->births, (unsigned)c->confirmations, (unsigned)c->deletions,
           (unsigned)c->merges, (unsigned)c->numeric_deletions, r->max_live,
           (unsigned)c->births_dropped);
    printf("  measurements: in %u, bad %u, dropped %u; pairs %u, pairs dropped %u, "
           "gated dropped %u, merge candidates dropped %u\n",
           (unsigned)c->meas_in, (unsigned)c->meas_bad, (unsigned)c->meas_dropped,
           (unsigned)c->pairs, (unsigned)c->pairs_dropped, (unsigned)c->gated_dropped,
           (unsigned)c->merge_dropped);
    printf("  worst margins over %llu track checks: min P pivot/max diag %.3g, min eigenvalue "
           "%.3g, min eigenvalue ratio %.3g, max asymmetry %.3g, existence in [%.3g, %.9g]\n",
           (unsigned long long)chk.tracks_checked, chk.min_pivot_rel, chk.min_eig,
           chk.min_eig_rel, chk.max_asym, chk.ex_min, chk.ex_max);
#ifdef MTT_REAL_FIXED
    printf("  fixed point: %llu track checks with a view covariance beyond the variance format "
           "(Q%d, not the tracker's own covariance); numeric deletions %u\n",
           (unsigned long long)chk.view_saturations, MTT_FX_VAR_FRAC,
           (unsigned)c->numeric_deletions);
#endif
    printf("  time: %.2f us per step (library), %.2f us per frame with checks, %.1f s in all\n",
           r->steps ? 1e6 * r->step_sec / (double)r->steps : 0.0,
           r->frames ? 1e6 * r->wall_sec / (double)r->frames : 0.0, r->wall_sec);
    printf("  invariants: all held\n");
    fflush(stdout);
}

static int usage(FILE *fp)
{
    fprintf(fp, "Usage: " PROG " [--frames N] [--seed S] [--mode NAME|all] [--progress K]\n"
                "  --frames N    frames of the scene (default 1000000)\n"
                "  --seed S      scene seed (default 1); odd seeds use a known clutter density,\n"
                "                even seeds let the tracker estimate it\n"
                "  --mode NAME   association mode as docs/FORMATS.md spells it (default lm-ihpda);\n"
                "                'all' runs every mode the library accepts\n"
                "  --progress K  a progress line on stderr every K frames (default 100000, 0: none)\n"
                "Exit status: 0 all invariants held; 1 a violation (message on stderr); 2 usage.\n");
    return 2;
}

int main(int argc, char **argv)
{
    unsigned long frames = 1000000ul, progress = 100000ul;
    unsigned long long seed = 1;
    const char *mode_name = "lm-ihpda";
    int i, rc = 0, ran = 0;
    mtt_assoc mode;
    result r;

    for (i = 1; i < argc; i += 2) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        char *end = NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            return 0;
        }
        if (v == NULL)
            return usage(stderr);
        if (strcmp(a, "--frames") == 0)
            frames = strtoul(v, &end, 10);
        else if (strcmp(a, "--seed") == 0)
            seed = strtoull(v, &end, 10);
        else if (strcmp(a, "--progress") == 0)
            progress = strtoul(v, &end, 10);
        else if (strcmp(a, "--mode") == 0) {
            mode_name = v;
            end = (char *)v + strlen(v);
        } else
            return usage(stderr);
        if (end == NULL || *end != '\0' || end == v) {
            fprintf(stderr, PROG ": bad value '%s' for %s\n", v, a);
            return 2;
        }
    }
    if (strcmp(mode_name, "all") == 0) {
        int k;
        for (k = 0; k < (int)MTT_ASSOC_COUNT && rc == 0; ++k) {
            mtt_params p;
            if (mtt_params_default(&p) != MTT_OK)
                return 2;
            p.association = (mtt_assoc)k;
            if (MTT_REAL_KIND > 2) {
                const double dens = 5e-6; /* the fixed-point build needs it declared */
                if (mtt_params_set(&p, "clutter_density", &dens, 1) != MTT_OK)
                    return 2;
            }
            if (mtt_params_check(&p, NULL) != MTT_OK)
                continue; /* not built yet */
            rc = run((mtt_assoc)k, frames, seed, progress, &r);
            if (rc == 0)
                report((mtt_assoc)k, seed, &r);
            ++ran;
        }
    } else {
        if (mtt_assoc_parse(mode_name, &mode) != MTT_OK) {
            fprintf(stderr, PROG ": unknown mode '%s'\n", mode_name);
            return 2;
        }
        rc = run(mode, frames, seed, progress, &r);
        if (rc == 0)
            report(mode, seed, &r);
        ++ran;
    }
    if (ran == 0) {
        fprintf(stderr, PROG ": no mode ran\n");
        return 2;
    }
    return rc;
}
