/* SPDX-License-Identifier: BSD-3-Clause */
/* app.c - the firmware example's scenario program, identical on host and
 * target: run the tracker over the built-in scene, print per frame
 *
 *   F <frame> meas <n> live <tracks> conf <confirmed tracks>
 *   C <frame> ticks <t> [stage ticks...]        (target only, with a tick counter)
 *
 * then every final track
 *
 *   T <id> conf <0|1> x <x> y <y> vx <vx> vy <vy> ex <existence> hex <8 hex digits x 5>
 *
 * (the hex words are the IEEE-754 bits of x, y, vx, vy, existence, for an
 * exact comparison), and "END ok" or "END fail <reason>".
 *
 * Compiled with FW_IMM 1 (the image mtt-fw-imm, in a build with
 * MTT_WITH_IMM) it runs the same scene with motion = imm (ALGORITHMS.md §14:
 * the default imm_models cv and ca, each with the process_psd below as
 * docs/FORMATS.md's default says; lm-ihpda) and prefixes its lines with I:
 * IF, IC, and IT lines that add the model probabilities,
 *
 *   IT <id> conf <0|1> x .. ex <existence> mu <mu_0> .. <mu_r-1> hex <8 hex digits x (5 + r)>
 *
 * With FW_IMM 0 the program is the CV example, unchanged.  With
 * FW_PREPARED 1 it loads parameters prepared on the host (below).  In the
 * fixed-point build (MTT_REAL_FIXED) the T lines end "qhex <position
 * frac> <probability frac>" and the five 32-bit words instead. */
#include "fw.h"

#ifndef FW_IMM
#define FW_IMM 0
#endif
/* FW_PREPARED 1 (the fixed-point target image): the tracker loads the
 * parameters that the build prepared on the host (fw_prepared.h, written by
 * mtt-fw-prepare from fw_params.c) instead of checking them itself; the
 * host reference initialises from the same fw_params.c, so the comparison
 * of the two runs also compares the two paths. */
#ifndef FW_PREPARED
#define FW_PREPARED 0
#endif
#if FW_PREPARED
#include "fw_prepared.h"
#endif
#if FW_IMM
#if !MTT_WITH_IMM
#error "FW_IMM 1 needs a library built with MTT_WITH_IMM 1"
#endif
#define FW_PASS "I" /* line prefix of the IMM run */
#define FW_TITLE "mtt firmware scenario (motion imm, default imm_models): frames "
#else
#define FW_PASS ""
#define FW_TITLE "mtt firmware scenario: frames "
#endif

/* Frame k's time: k frames (T0 = 1; Q16 frames in the fixed-point build). */
#ifdef MTT_REAL_FIXED
#define FW_TIME(k) ((int32_t)(k) * ((int32_t)1 << MTT_FX_T_FRAC))
#else
#define FW_TIME(k) ((float)(k))
#endif

/* The tracker's whole RAM cost; static, as firmware allocates it. */
static mtt_tracker trk;
static mtt_meas meas[SCN_MAX_MEAS];
static char line[FW_IMM ? 256 : 192]; /* an IT line holds up to 8 more numbers */

static int fail(const char *what)
{
    char *p = fmt_str(line, "END fail ");
    p = fmt_str(p, what);
    (void)fmt_str(p, "\n");
    fw_puts(line);
    return 1;
}

static void print_frame(int k, size_t n, size_t live, size_t conf)
{
    char *p = fmt_str(line, FW_PASS "F ");
    p = fmt_i32(p, (int32_t)k);
    p = fmt_str(p, " meas ");
    p = fmt_u32(p, (uint32_t)n);
    p = fmt_str(p, " live ");
    p = fmt_u32(p, (uint32_t)live);
    p = fmt_str(p, " conf ");
    p = fmt_u32(p, (uint32_t)conf);
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

static void print_ticks(int k, const mtt_stats *st)
{
    uint32_t total = 0;
    int s;
    char *p;
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        total += st->stage_cycles[s];
    }
    p = fmt_str(line, FW_PASS "C ");
    p = fmt_i32(p, (int32_t)k);
    p = fmt_str(p, " ticks ");
    p = fmt_u32(p, total);
    p = fmt_str(p, " stages");
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        p = fmt_str(p, " ");
        p = fmt_u32(p, st->stage_cycles[s]);
    }
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

#if FW_IMM
/* The model probabilities of v: " mu <decimal>..." or, hex 1, " <hex>...". */
static char *print_mu(char *p, const mtt_track_view *v, int hex)
{
    int j;
    if (!hex) {
        p = fmt_str(p, " mu");
    }
    for (j = 0; j < (int)v->n_models && j < MTT_MAX_MODELS; ++j) {
        p = fmt_str(p, " ");
        p = hex ? fmt_hex(p, v->mu[j]) : fmt_fixed(p, v->mu[j], 5);
    }
    return p;
}
#endif

/* The value i of a T line (x, y, vx, vy: 3 decimals; existence: 5) and
 * its word for the exact comparison.  The fixed-point build prints the Q
 * values in the user's units (positions and velocities in the position
 * format, existence in Q30) and, after "qhex <position frac> <probability
 * frac>", their 32-bit words (fwcheck.py compare); float the IEEE-754 bits
 * after "hex". */
#ifdef MTT_REAL_FIXED
#define FMT_VAL(p, v, i) fmt_q((p), (v), (i) < 4 ? MTT_FX_POS_FRAC : MTT_FX_PROB_FRAC, (i) < 4 ? 3 : 5)
#define FMT_WORD(p, v) fmt_hex32((p), (uint32_t)(v))
static char *fmt_word_tag(char *p)
{
    p = fmt_str(p, " qhex ");
    p = fmt_u32(p, MTT_FX_POS_FRAC);
    p = fmt_str(p, " ");
    return fmt_u32(p, MTT_FX_PROB_FRAC);
}
#else
#define FMT_VAL(p, v, i) fmt_fixed((p), (v), (i) < 4 ? 3 : 5)
#define FMT_WORD(p, v) fmt_hex((p), (v))
#define fmt_word_tag(p) fmt_str((p), " hex")
#endif

static void print_track(const mtt_track_view *v)
{
    const mtt_real val[5] = {v->x[0], v->x[1], v->x[2], v->x[3], v->existence};
    static const char *const name[5] = {" x ", " y ", " vx ", " vy ", " ex "};
    int i;
    char *p = fmt_str(line, FW_PASS "T ");
    p = fmt_u32(p, v->id);
    p = fmt_str(p, " conf ");
    p = fmt_u32(p, (uint32_t)(v->confirmed != 0));
    for (i = 0; i < 5; ++i) {
        p = fmt_str(p, name[i]);
        p = FMT_VAL(p, val[i], i);
    }
#if FW_IMM
    p = print_mu(p, v, 0);
#endif
    p = fmt_word_tag(p);
    for (i = 0; i < 5; ++i) {
        p = fmt_str(p, " ");
        p = FMT_WORD(p, val[i]);
    }
#if FW_IMM
    p = print_mu(p, v, 1);
#endif
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

int fw_app_run(void)
{
#if !FW_PREPARED
    mtt_params par;
#endif
    mtt_stats st;
    mtt_track_view v;
    scn_state scn;
    size_t n, live, conf, i;
    int k;
    char *p;

#if FW_PREPARED
    /* the parameters prepared on the host (fw_prepared.h): no
     * mtt_params_check and no logarithm in the image */
    if (mtt_tracker_load(&trk, &mtt_fw_prepared, fw_cycle_counter, NULL) != MTT_OK) {
        return fail("load");
    }
#else
    if (fw_params(&par) != 0) {
        return fail("params");
    }
    par.cycle_counter = fw_cycle_counter; /* NULL on the host */
#if FW_IMM
    par.motion = MTT_MOTION_IMM;
    /* docs/FORMATS.md: imm_models' default follows process_psd */
    for (i = 0; i < par.imm_n_models && i < MTT_MAX_MODELS; ++i) {
        par.imm_psd[i] = par.process_psd;
    }
#endif
    if (mtt_tracker_init(&trk, &par) != MTT_OK) {
        return fail("init");
    }
#endif
    scn_init(&scn, 20240601u);

    p = fmt_str(line, FW_TITLE);
    p = fmt_u32(p, SCN_FRAMES);
    p = fmt_str(p, " targets ");
    p = fmt_u32(p, SCN_TARGETS);
    p = fmt_str(p, " sizeof(mtt_tracker) ");
    p = fmt_u32(p, (uint32_t)sizeof(mtt_tracker));
    (void)fmt_str(p, "\n");
    fw_puts(line);

    for (k = 0; k < SCN_FRAMES; ++k) {
        n = scn_frame(&scn, k, meas);
        if (mtt_tracker_step(&trk, FW_TIME(k), meas, n) != MTT_OK) {
            return fail("step");
        }
        if (mtt_tracker_count(&trk, &live) != MTT_OK) {
            return fail("count");
        }
        conf = 0;
        for (i = 0; i < live; ++i) {
            if (mtt_tracker_track(&trk, i, &v) != MTT_OK) {
                return fail("track");
            }
            conf += (v.confirmed != 0) ? 1u : 0u;
        }
        print_frame(k, n, live, conf);
        if (fw_cycle_counter != NULL) {
            if (mtt_tracker_stats(&trk, &st) != MTT_OK) {
                return fail("stats");
            }
            print_ticks(k, &st);
        }
    }
    if (mtt_tracker_count(&trk, &live) != MTT_OK) {
        return fail("count");
    }
    for (i = 0; i < live; ++i) {
        if (mtt_tracker_track(&trk, i, &v) != MTT_OK) {
            return fail("track");
        }
        print_track(&v);
    }
    fw_puts("END ok\n");
    return 0;
}
