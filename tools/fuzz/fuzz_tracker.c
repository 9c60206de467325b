/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/fuzz_tracker.c - libFuzzer harness: mtt_tracker_step on arbitrary
 * frames with arbitrary (valid) parameters, in every association mode that
 * mtt_params_check accepts.
 *
 * The input bytes decode into
 *   1. a parameter set: each field is its default, a special value (0, 1,
 *      denormal, FLT_MAX, NaN, Inf, ...), a scaled default or raw bits; sets
 *      that fail mtt_params_check are skipped (the input is uninteresting);
 *   2. up to MAX_FRAMES frames: a time step (1, tiny, huge, raw, NaN, <= 0),
 *      a count (0, a few, up to 255, exactly MTT_MAX_MEAS, far beyond it),
 *      optionally a seeded track and a NULL-pointer misuse; measurements
 *      placed near the previous frame's (to start and feed tracks), near a
 *      live track, duplicated, special (NaN, Inf, huge, denormal) or raw,
 *      with amplitudes absent, 0, negative, NaN, Inf, huge or raw.  When the
 *      bytes run out the rest comes from a PRNG seeded by the input.
 * The same frames run in every mode (MTT_ASSOC_COUNT of them; modes not yet
 * built return MTT_ERR_UNSUPPORTED and are skipped, so new modes are fuzzed
 * as soon as they are built).  After each step tools/fuzz/mtt_check.h's
 * invariants must hold, errors must be the documented ones and leave the
 * tracker unchanged; any violation aborts with a message.
 *
 * Also built without libFuzzer as a replay program (tools/fuzz/replay_main.c).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mtt/mtt.h"
#include "mtt_check.h"

#define MAX_FRAMES 24
#define MAX_INPUT_MEAS (MTT_MAX_MEAS + 4 * 255 + 1)

static mtt_tracker trk, saved;
static int one_mode; /* MTT_FUZZ_ONE_MODE=1 */
static int verbose; /* MTT_FUZZ_VERBOSE=1: print what each frame feeds in */
/* MTT_FUZZ_SKIP_MODES="name,name": modes left out (open findings, so that a
 * smoke run can look for new ones; docs/ROBUSTNESS.md lists them). */
static int skip_mode[MTT_ASSOC_COUNT];
static mtt_check chk;

typedef struct src {
    const uint8_t *p;
    size_t n;
    uint64_t rng;
} src;

static uint64_t rng_next(src *s)
{
    /* xorshift64* */
    s->rng ^= s->rng >> 12;
    s->rng ^= s->rng << 25;
    s->rng ^= s->rng >> 27;
    return s->rng * 2685821657736338717ull;
}

static uint8_t u8(src *s)
{
    if (s->n == 0)
        return (uint8_t)(rng_next(s) >> 56);
    s->n--;
    return *s->p++;
}

static mtt_real raw_real(src *s)
{
    mtt_real r;
    uint8_t b[sizeof(mtt_real)];
    size_t i;
    for (i = 0; i < sizeof b; ++i)
        b[i] = u8(s);
    memcpy(&r, b, sizeof r);
    return r;
}

static mtt_real special(uint8_t k)
{
    static const double tab[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 1e-45, 1e-40, 1e-38, 1e-30, 1e-10, 1e-6,
        1e-3, 10.0, 100.0, 1e3, 1e6, 1e10, 1e20, 1e30, 3.4028235e38, -3.4028235e38,
        1.1920929e-7, 0.99999994, 0.999, 255.0, -1e30, 4096.0, 65536.0, 1e15,
        0.0 /* NaN */, 0.0 /* Inf */};
    k = (uint8_t)(k % 32u);
    if (k == 30)
        return (mtt_real)NAN;
    if (k == 31)
        return (mtt_real)INFINITY;
    return (mtt_real)tab[k];
}

/* One parameter field: mostly its default, else a special, scaled,
 * raw or uniform value. */
static mtt_real field(src *s, mtt_real def)
{
    uint8_t b = u8(s);
    switch (b >> 5) {
    case 0:
    case 1:
    case 2:
        return def;
    case 3:
        return special(b);
    case 4:
        return def * (mtt_real)ldexp(1.0, (int)(b & 31u) - 16);
    case 5:
        return raw_real(s);
    case 6:
        return (mtt_real)(b & 31u) / MTT_R(31.0);
    default:
        return def * (MTT_R(1.0) + (mtt_real)((int)(b & 31u) - 16) / MTT_R(64.0));
    }
}

static uint32_t fake_cycles(void *ctx)
{
    uint32_t *c = (uint32_t *)ctx;
    *c += 0x9e3779b9u; /* wraps: the library must subtract modulo 2^32 */
    return *c;
}
static uint32_t cycle_state;

static void decode_params(src *s, mtt_params *p)
{
    uint8_t flags;
    int k;
    if (mtt_params_default(p) != MTT_OK)
        abort();
    p->process_psd = field(s, p->process_psd);
    p->meas_sigma[0] = field(s, p->meas_sigma[0]);
    p->meas_sigma[1] = field(s, p->meas_sigma[1]);
    p->pd = field(s, p->pd);
    p->pg = field(s, p->pg);
    p->clutter_density = field(s, p->clutter_density);
    p->snr_rho = field(s, p->snr_rho);
    p->markov_p11 = field(s, p->markov_p11);
    p->markov_p21 = field(s, p->markov_p21);
    p->existence_init = field(s, p->existence_init);
    p->confirm_threshold = field(s, p->confirm_threshold);
    p->terminate_threshold = field(s, p->terminate_threshold);
    p->merge_threshold = field(s, p->merge_threshold);
    p->vmax = field(s, p->vmax);
    flags = u8(s);
    p->initiate = (flags & 1u) ? 0 : 1;
    p->init_gate = (flags & 2u) ? MTT_INIT_GATE_INTENSITY : MTT_INIT_GATE_VMAX;
    if (flags & 4u) {
        p->cycle_counter = fake_cycles;
        p->cycle_ctx = &cycle_state;
    }
    if (flags & 8u) {
        for (k = 0; k < 3; ++k) {
            p->intensity_f1[k] = field(s, p->intensity_f1[k]);
            p->intensity_f2[k] = field(s, p->intensity_f2[k]);
        }
        p->intensity_blend[0] = field(s, p->intensity_blend[0]);
        p->intensity_blend[1] = field(s, p->intensity_blend[1]);
    }
    if (flags & 16u) {
        p->jpda_bias = field(s, p->jpda_bias);
        p->jpda_star_threshold = field(s, p->jpda_star_threshold);
        p->nnjpda_threshold = field(s, p->nnjpda_threshold);
        p->adaptive_jpda_distance = field(s, p->adaptive_jpda_distance);
        p->adaptive_jpda_shrink = field(s, p->adaptive_jpda_shrink);
    }
}

/* ---- frames ---- */

typedef struct frame {
    mtt_real dt;
    size_t first, n;       /* into the measurement pool */
    uint8_t null_misuse;   /* also call with meas = NULL, n > 0 */
    uint8_t seed;          /* add a seeded track before the step */
    mtt_real seed_x[4];
    mtt_real seed_P[16];
} frame;

static frame frames[MAX_FRAMES];
static size_t n_frames;
static mtt_meas pool[MAX_FRAMES * 64 + 4 * MAX_INPUT_MEAS];
static size_t pool_n;

static mtt_real amplitude(src *s, int *has)
{
    uint8_t b = u8(s);
    *has = 1;
    switch (b >> 5) {
    case 0:
    case 1:
        *has = 0;
        return MTT_R(0.0);
    case 2:
        return (mtt_real)(b & 31u) + MTT_R(0.25); /* ordinary 0.25 .. 31.25 */
    case 3:
        return special(b);
    case 4:
        return raw_real(s);
    default:
        return MTT_R(1.0) + (mtt_real)(b & 31u) / MTT_R(8.0);
    }
}

/* Measurement j of a frame whose previous frame had measurements prev[0..np). */
static mtt_meas decode_meas(src *s, const mtt_meas *prev, size_t np, const mtt_meas *cur,
                            size_t j)
{
    mtt_meas m;
    uint8_t b = u8(s);
    int has;
    switch (b & 7u) {
    case 0:
    case 1:
    case 2:
        if (np > 0) { /* near one of the previous frame's measurements */
            const mtt_meas *q = &prev[u8(s) % np];
            m.x = q->x + (mtt_real)(int8_t)u8(s) / MTT_R(8.0);
            m.y = q->y + (mtt_real)(int8_t)u8(s) / MTT_R(8.0);
            break;
        }
        /* fall through */
    case 3: /* on a coarse grid */
        m.x = (mtt_real)u8(s) * MTT_R(4.0);
        m.y = (mtt_real)u8(s) * MTT_R(4.0);
        break;
    case 4:
        if (j > 0) { /* duplicate of an earlier measurement of this frame */
            m = cur[u8(s) % j];
            return m;
        }
        m.x = MTT_R(0.0);
        m.y = MTT_R(0.0);
        break;
    case 5: /* special coordinates */
        m.x = special(u8(s));
        m.y = special(u8(s));
        break;
    case 6: /* raw bits */
        m.x = raw_real(s);
        m.y = raw_real(s);
        break;
    default: /* near a previous measurement, tiny offset (denormal-scale) */
        if (np > 0) {
            const mtt_meas *q = &prev[u8(s) % np];
            m.x = q->x + special(u8(s)) * MTT_R(1e-3);
            m.y = q->y;
        } else {
            m.x = special(u8(s));
            m.y = MTT_R(1.0);
        }
        break;
    }
    m.amplitude = amplitude(s, &has);
    m.has_amplitude = has;
    return m;
}

static mtt_real decode_dt(src *s, uint8_t op)
{
    switch (op & 7u) {
    case 4:
        return special((uint8_t)(6u + u8(s) % 6u)); /* 1e-45 .. 1e-6 */
    case 5:
        return special((uint8_t)(15u + u8(s) % 6u)); /* 1e3 .. 3.4e38 */
    case 6:
        return raw_real(s);
    case 7:
        return special(u8(s)); /* anything: 0, negative, NaN, Inf too */
    default:
        return MTT_R(1.0) + (mtt_real)(op & 3u) * MTT_R(0.25);
    }
}

static void decode_frames(src *s)
{
    size_t np = 0, f;
    const mtt_meas *prev = NULL;
    n_frames = 0;
    pool_n = 0;
    for (f = 0; f < MAX_FRAMES && s->n > 0; ++f) {
        frame *fr = &frames[n_frames++];
        uint8_t op = u8(s);
        size_t n, j;
        fr->dt = decode_dt(s, op);
        switch ((op >> 3) & 7u) {
        case 0:
            n = 0;
            break;
        case 1:
        case 2:
        case 3:
        case 4:
            n = u8(s) & 15u;
            break;
        case 5:
            n = u8(s);
            break;
        case 6:
            n = MTT_MAX_MEAS + 4u * (size_t)u8(s) + 1u;
            break;
        default:
            n = MTT_MAX_MEAS;
            break;
        }
        if (pool_n + n > sizeof pool / sizeof pool[0])
            n = sizeof pool / sizeof pool[0] - pool_n;
        fr->first = pool_n;
        fr->n = n;
        fr->seed = (uint8_t)((op >> 6) & 1u);
        fr->null_misuse = (uint8_t)((op >> 7) & 1u);
        if (fr->seed) {
            int a;
            for (a = 0; a < 4; ++a)
                fr->seed_x[a] = field(s, a < 2 ? MTT_R(100.0) : MTT_R(1.0));
            for (a = 0; a < 16; ++a)
                fr->seed_P[a] = MTT_R(0.0);
            for (a = 0; a < 4; ++a)
                fr->seed_P[a * 5] = field(s, MTT_R(4.0));
            fr->seed_P[2] = fr->seed_P[8] = field(s, MTT_R(0.5)); /* P[0][2] */
            fr->seed_P[7] = fr->seed_P[13] = field(s, MTT_R(0.5)); /* P[1][3] */
        }
        /* Once the input bytes run out, measurements come from the PRNG:
         * long frames cost no input. */
        for (j = 0; j < n; ++j)
            pool[pool_n + j] = decode_meas(s, prev, np, &pool[pool_n], j);
        prev = &pool[pool_n];
        np = n;
        pool_n += n;
    }
}

#define FAIL(...)                                   \
    do {                                            \
        fprintf(stderr, "fuzz_tracker: " __VA_ARGS__); \
        fputc('\n', stderr);                        \
        abort();                                    \
    } while (0)

static void run_mode(const mtt_params *p)
{
    mtt_real t = MTT_R(0.0), last = MTT_R(0.0);
    int have = 0;
    size_t f;
    mtt_status st;

    if (verbose) {
        const char *name = "?";
        if (mtt_assoc_name(p->association, &name) != MTT_OK)
            name = "?";
        fprintf(stderr, "mode %s: psd %.9g sigma %.9g %.9g pd %.9g pg %.9g lambda %.9g rho %.9g "
                "p11 %.9g p21 %.9g ex0 %.9g conf %.9g term %.9g merge %.9g vmax %.9g initiate %d "
                "init_gate %d\n", name, (double)p->process_psd, (double)p->meas_sigma[0],
                (double)p->meas_sigma[1], (double)p->pd, (double)p->pg, (double)p->clutter_density,
                (double)p->snr_rho, (double)p->markov_p11, (double)p->markov_p21,
                (double)p->existence_init, (double)p->confirm_threshold,
                (double)p->terminate_threshold, (double)p->merge_threshold, (double)p->vmax,
                p->initiate, (int)p->init_gate);
    }
    st = mtt_tracker_init(&trk, p);
    if (st != MTT_OK)
        FAIL("mtt_tracker_init failed (%d) on a set that mtt_params_check accepted", (int)st);
    mtt_check_init(&chk);
    for (f = 0; f < n_frames; ++f) {
        const frame *fr = &frames[f];
        const mtt_meas *m = &pool[fr->first];
        size_t j, n_bad = 0;

        int expect_time_err;

        if (verbose) {
            fprintf(stderr, "frame %zu: dt %.9g n %zu seed %d null %d\n", f, (double)fr->dt, fr->n,
                    fr->seed, fr->null_misuse);
            if (fr->seed) {
                int a;
                fprintf(stderr, "  seed x %.9g %.9g %.9g %.9g P", (double)fr->seed_x[0],
                        (double)fr->seed_x[1], (double)fr->seed_x[2], (double)fr->seed_x[3]);
                for (a = 0; a < 16; ++a)
                    fprintf(stderr, " %.9g", (double)fr->seed_P[a]);
                fputc('\n', stderr);
            }
            for (j = 0; j < fr->n && j < 40; ++j)
                fprintf(stderr, "  meas %zu: %.9g %.9g amp %.9g has %d\n", j, (double)m[j].x,
                        (double)m[j].y, (double)m[j].amplitude, m[j].has_amplitude);
        }
        if (fr->seed) {
            uint32_t id = 0;
            st = mtt_tracker_add_track(&trk, fr->seed_x, fr->seed_P, &id);
            if (st == MTT_OK) {
                if (!mtt_check_pd16(fr->seed_P)) {
                    if (chk.n_exempt >= sizeof chk.exempt / sizeof chk.exempt[0])
                        return; /* cannot track more exemptions: stop here */
                    mtt_check_exempt(&chk, id);
                }
                if (!mtt_check_after_seed(&chk, &trk, id))
                    FAIL("frame %zu (seed): %s", f, chk.msg);
            } else if (st != MTT_ERR_VALUE && st != MTT_ERR_FULL) {
                FAIL("frame %zu: mtt_tracker_add_track returned %d", f, (int)st);
            }
        }
        t = have ? last + fr->dt : fr->dt;
        expect_time_err = !mtt_isfinite(t) || (have && !(t > last));
        if (fr->null_misuse || expect_time_err) {
            memcpy(&saved, &trk, sizeof saved);
            if (fr->null_misuse && fr->n > 0) {
                st = mtt_tracker_step(&trk, t, NULL, fr->n);
                if (st != MTT_ERR_NULL)
                    FAIL("frame %zu: step(meas = NULL, n = %zu) returned %d", f, fr->n, (int)st);
                if (memcmp(&saved, &trk, sizeof saved) != 0)
                    FAIL("frame %zu: a NULL-pointer error changed the tracker", f);
            }
            if (expect_time_err) {
                st = mtt_tracker_step(&trk, t, m, fr->n);
                if (st != MTT_ERR_TIME)
                    FAIL("frame %zu: time %g after %g returned %d, not MTT_ERR_TIME", f,
                         (double)t, (double)last, (int)st);
                if (memcmp(&saved, &trk, sizeof saved) != 0)
                    FAIL("frame %zu: a time error changed the tracker", f);
                continue;
            }
        }
        for (j = 0; j < fr->n; ++j)
            n_bad += (size_t)mtt_check_meas_bad(&m[j]);
        if (!mtt_check_before(&chk, &trk))
            FAIL("frame %zu: %s", f, chk.msg);
        st = mtt_tracker_step(&trk, t, fr->n > 0 ? m : NULL, fr->n);
        if (st != MTT_OK)
            FAIL("frame %zu: mtt_tracker_step(time %g after %g, n %zu) returned %d", f, (double)t,
                 (double)last, fr->n, (int)st);
        if (!mtt_check_frame(&chk, &trk, fr->n, n_bad)) {
            const char *name = "?";
            if (mtt_assoc_name(p->association, &name) != MTT_OK)
                name = "?";
            FAIL("frame %zu (mode %s, time %g, dt %g, n %zu): %s", f, name, (double)t,
                 (double)fr->dt, fr->n, chk.msg);
        }
        last = t;
        have = 1;
    }
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    const char *v = getenv("MTT_FUZZ_VERBOSE");
    (void)argc;
    (void)argv;
    const char *skip = getenv("MTT_FUZZ_SKIP_MODES");
    const char *one = getenv("MTT_FUZZ_ONE_MODE");
    int k;
    verbose = v != NULL && strcmp(v, "1") == 0;
    one_mode = one != NULL && strcmp(one, "1") == 0;
    if (one_mode)
        fprintf(stderr, "fuzz_tracker: one mode per input (MTT_FUZZ_ONE_MODE=1)\n");
    for (k = 0; skip != NULL && k < (int)MTT_ASSOC_COUNT; ++k) {
        const char *name = NULL, *q = skip;
        size_t len;
        if (mtt_assoc_name((mtt_assoc)k, &name) != MTT_OK)
            continue;
        len = strlen(name);
        while ((q = strstr(q, name)) != NULL) {
            if ((q == skip || q[-1] == ',') && (q[len] == '\0' || q[len] == ',')) {
                skip_mode[k] = 1;
                fprintf(stderr, "fuzz_tracker: skipping mode %s (MTT_FUZZ_SKIP_MODES)\n", name);
            }
            q += len;
        }
    }
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    src s;
    mtt_params p;
    int k;
    uint64_t h = 1469598103934665603ull;
    size_t i;

    for (i = 0; i < size; ++i)
        h = (h ^ data[i]) * 1099511628211ull;
    s.p = data;
    s.n = size;
    s.rng = h | 1u;
    decode_params(&s, &p);
    p.association = MTT_ASSOC_LM_IHPDA;
    /* lm-ihpda's algorithm from a bit of the hash (no input byte, so the
     * other fields of a corpus entry decode as before) */
    p.lm_ihpda_variant = (h & 2u) ? MTT_LM_IHPDA_CONTEST : MTT_LM_IHPDA_S0;
    if (mtt_params_check(&p, NULL) != MTT_OK)
        return 0; /* not a valid set: nothing to test */
    decode_frames(&s);
    for (k = 0; k < (int)MTT_ASSOC_COUNT; ++k) {
        mtt_status st;
        /* MTT_FUZZ_ONE_MODE=1: only the mode the input's hash picks, about
         * twelve times more inputs per second for long runs. */
        if (one_mode && (uint64_t)k != (h >> 33) % (uint64_t)MTT_ASSOC_COUNT)
            continue;
        p.association = (mtt_assoc)k;
        st = mtt_params_check(&p, NULL);
        if (st == MTT_ERR_UNSUPPORTED)
            continue; /* not built yet */
        if (st != MTT_OK || skip_mode[k])
            continue; /* a mode-specific field out of range, or skipped on request */
        run_mode(&p);
    }
    return 0;
}
