/* SPDX-License-Identifier: BSD-3-Clause */
/* tracker.c - the per-frame pipeline (ALGORITHMS.md §15; docs/DESIGN.md
 * its nine stages, the mtt_stage values): mtt_tracker_init, mtt_tracker_step and the statistics.
 * This file only sequences the stages; each stage computes in its own
 * file, and the association mode is a row of the mode table (associate.c).
 * In the fixed-point build (docs/FIXED_POINT.md) time is a Q16 count of
 * frames modulo 2^32 and R is formed in the variance format; the modes,
 * IMM, split and the estimated clutter density that the build does not
 * hold are refused by mtt_params_check with MTT_ERR_UNSUPPORTED.
 * mtt_tracker_init does what mtt_params_prepare (the checks, the gate
 * threshold) and mtt_tracker_load (the state) do together, through one
 * setup, so a firmware can load a set prepared on the host
 * (docs/FIRMWARE.md). */
#include <string.h>

#include "mtt_internal.h"

/* ---- helpers ---- */

static uint32_t cycles_now(const mtt_tracker *trk)
{
    return (trk->par.cycle_counter != NULL) ? trk->par.cycle_counter(trk->par.cycle_ctx) : 0u;
}

/* Charge the cycles since *mark to stage s (wraps modulo 2^32 correctly). */
static void charge(mtt_tracker *trk, mtt_stage s, uint32_t *mark)
{
    uint32_t now = cycles_now(trk);
    trk->stats.stage_cycles[s] = now - *mark;
    *mark = now;
}

/* tot += c, counter by counter: mtt_counts holds uint32_t counters only
 * (mtt.h), so one loop over its words instead of a line per member (a
 * firmware's .text; docs/FIRMWARE.md).  The byte offset k of a word is
 * that of a uint32_t member, so the cast pointer points at that member and
 * reads and writes it with its own type (no memcpy call per word). */
typedef char mtt_counts_words[(sizeof(mtt_counts) % sizeof(uint32_t) == 0u) ? 1 : -1];
static void add_counts(mtt_counts *tot, const mtt_counts *c)
{
    unsigned char *t = (unsigned char *)tot;
    const unsigned char *s = (const unsigned char *)c;
    size_t k;
    for (k = 0; k < sizeof *tot; k += sizeof(uint32_t)) {
        *(uint32_t *)(void *)(t + k) += *(const uint32_t *)(const void *)(s + k);
    }
}

/* ---- public ---- */

/* The tracker state from checked parameters p, their gate threshold and
 * the cycle counter: the one setup of mtt_tracker_init and
 * mtt_tracker_load. */
static void setup(mtt_tracker *trk, const mtt_params *p, mtt_real gamma, mtt_cycle_fn fn, void *ctx)
{
    uint16_t m;
    memset(trk, 0, sizeof *trk);
    trk->par = *p;
    mtt_manoeuvre_resolve(&trk->par, &trk->lv); /* the keys left out (ALGORITHMS.md §2.2) */
    trk->par.cycle_counter = fn;
    trk->par.cycle_ctx = ctx;
    trk->gamma = gamma;
#ifdef MTT_REAL_FIXED
    mtt_fx_gate_consts(gamma, p->pg, p->clutter_density, trk->gc); /* one gamma and lambda per run */
#endif
    trk->R[0] = MTT_VAR_OF(p->meas_sigma[0]);
    trk->R[1] = MTT_ZERO;
    /* polar (ALGORITHMS.md §3.2): every detection has its own R and every
     * track its R at its predicted position; this one, sigma_range in
     * both axes, is only the length scale of the contest's tracking index
     * and adaptive JPDA's overlap distance */
    trk->R[2] = MTT_VAR_OF(p->meas_sigma[(p->measurement == MTT_MEASUREMENT_POLAR) ? 0 : 1]);
#if MTT_WITH_CONTEST
    mtt_adapt_init(trk); /* the process-noise scale's set-up (ALGORITHMS.md §2.1) */
#endif
    /* rho is a global constant: tabulate P_r(l|m) once (ALGORITHMS.md §7.2). */
    for (m = 1; m <= MTT_MAX_GATED; ++m) {
        mtt_ihpda_prank(m, p->snr_rho, &trk->prank[MTT_PRANK_ROW(m)]);
    }
    trk->magic = MTT_MAGIC;
}

mtt_status mtt_tracker_init_checked(mtt_tracker *trk, const mtt_params *p, size_t tracker_size,
                                    uint32_t config_id)
{
    mtt_status st;
    if (trk == NULL || p == NULL) {
        return MTT_ERR_NULL;
    }
    /* Before anything is read or written: the caller's mtt_tracker and
     * mtt_params may have another layout than ours. */
    if (tracker_size != sizeof(mtt_tracker) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    st = mtt_params_check(p, NULL);
    if (st != MTT_OK) {
        return st;
    }
    setup(trk, p, mtt_gate_gamma(p->pg), p->cycle_counter, p->cycle_ctx);
    return MTT_OK;
}

/* The parameter-time work of mtt_tracker_init, for a host to do once
 * (docs/FIRMWARE.md, "Parameters prepared on the host"): the checks and
 * the gate threshold, whose logarithm a firmware that loads the result
 * does not link. */
mtt_status mtt_params_prepare_checked(const mtt_params *p, mtt_prepared *out, size_t params_size,
                                      uint32_t config_id)
{
    mtt_status st;
    if (p == NULL || out == NULL) {
        return MTT_ERR_NULL;
    }
    /* Before p is read or out written (its mtt_params member included). */
    if (params_size != sizeof(mtt_params) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    st = mtt_params_check(p, NULL);
    if (st != MTT_OK) {
        return st;
    }
    memset(out, 0, sizeof *out);
    out->mark = MTT_PREPARED_MARK;
    out->config_id = (uint32_t)(MTT_CONFIG_ID);
    out->par = *p;
    out->par.cycle_counter = NULL;
    out->par.cycle_ctx = NULL;
    out->gamma = mtt_gate_gamma(p->pg);
    return MTT_OK;
}

mtt_status mtt_tracker_load_checked(mtt_tracker *trk, const mtt_prepared *pp, mtt_cycle_fn fn, void *ctx,
                                    size_t tracker_size, uint32_t config_id)
{
    if (trk == NULL || pp == NULL) {
        return MTT_ERR_NULL;
    }
    /* Before anything is read or written: the caller's mtt_tracker and
     * mtt_prepared may have another layout than ours. */
    if (tracker_size != sizeof(mtt_tracker) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    if (pp->config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG; /* prepared by a build of another configuration */
    }
    if (pp->mark != MTT_PREPARED_MARK) {
        return MTT_ERR_PARAM; /* not written by mtt_params_prepare */
    }
    setup(trk, &pp->par, pp->gamma, fn, ctx);
    return MTT_OK;
}

mtt_status mtt_tracker_step(mtt_tracker *trk, mtt_real time, const mtt_meas *meas, size_t n)
{
    return mtt_tracker_step_cov(trk, time, meas, NULL, n);
}

/* The checks of every step: 0 or the status (nothing written). */
static mtt_status step_check(const mtt_tracker *trk, mtt_real time, const void *det, size_t n)
{
    if (trk == NULL || (det == NULL && n > 0u)) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    /* Fixed point: time counts Q16 frames modulo 2^32 (mtt/real.h). */
    if (!MTT_TIME_OK(time) || (trk->have_time && !MTT_TIME_AFTER(time, trk->time))) {
        return MTT_ERR_TIME;
    }
    return MTT_OK;
}

static void step_frame(mtt_tracker *trk, mtt_real time, const mtt_meas *meas, const mtt_meas_cov *cov,
                       const mtt_polar *pol, size_t n);

mtt_status mtt_tracker_step_polar(mtt_tracker *trk, mtt_real time, const mtt_polar *det, size_t n)
{
    const mtt_status st = step_check(trk, time, det, n);
    if (st != MTT_OK) {
        return st;
    }
#if MTT_WITH_POLAR
    if (trk->par.measurement != MTT_MEASUREMENT_POLAR) {
        return MTT_ERR_UNSUPPORTED; /* polar detections need polar settings (§3.2) */
    }
    if (!(trk->par.range_rate_sigma > MTT_ZERO)) {
        size_t i;
        for (i = 0; i < n; ++i) {
            if (det[i].has_range_rate) {
                return MTT_ERR_PARAM; /* a range rate without its sigma (§3.2) */
            }
        }
    }
    step_frame(trk, time, NULL, NULL, det, n);
    return MTT_OK;
#else
    return MTT_ERR_UNSUPPORTED; /* mtt_params_check refuses polar settings in this build (§3.2) */
#endif
}

mtt_status mtt_tracker_step_cov(mtt_tracker *trk, mtt_real time, const mtt_meas *meas, const mtt_meas_cov *cov,
                                size_t n)
{
    const mtt_status st = step_check(trk, time, meas, n);
    if (st != MTT_OK) {
        return st;
    }
#if MTT_WITH_MEAS_COV
    if (trk->par.measurement == MTT_MEASUREMENT_POLAR) {
        return MTT_ERR_UNSUPPORTED; /* polar settings take mtt_tracker_step_polar (§3.2) */
    }
#endif
    if (cov != NULL && !MTT_WITH_MEAS_COV) {
        /* a covariance per detection where the build has none
         * (ALGORITHMS.md §3.1): refused before anything is written */
        size_t i;
        for (i = 0; i < n; ++i) {
            if (cov[i].r_xx != MTT_ZERO || cov[i].r_xy != MTT_ZERO || cov[i].r_yy != MTT_ZERO) {
                return MTT_ERR_UNSUPPORTED;
            }
        }
    }
    step_frame(trk, time, meas, cov, NULL, n);
    return MTT_OK;
}

/* One frame of checked input: the nine stages. */
static void step_frame(mtt_tracker *trk, mtt_real time, const mtt_meas *meas, const mtt_meas_cov *cov,
                       const mtt_polar *pol, size_t n)
{
    mtt_real dt = MTT_ZERO;
    const mtt_mode *md;
    uint32_t mark;
    if (trk->have_time) {
        dt = MTT_TIME_SUB(time, trk->time);
    }
    md = &mtt_modes[trk->par.association];
    memset(&trk->stats.last, 0, sizeof trk->stats.last);
    memset(trk->stats.stage_cycles, 0, sizeof trk->stats.stage_cycles);
    trk->stats.last.frames = 1;
    trk->stats.last.meas_in = (uint32_t)n;
    mark = cycles_now(trk);

    mtt_measure_select(trk, meas, cov, pol, n);
    charge(trk, MTT_STAGE_VALIDATE, &mark);
    mtt_predict_frame(trk, dt);
#if MTT_WITH_BASELINES
    if (md->associate >= MTT_ASSOCIATE_ADAPTIVE_JPDA) {
        mtt_adaptive_gates(trk); /* per-track gate thresholds before gating (ALGORITHMS.md §13.7) */
    }
#endif
    charge(trk, MTT_STAGE_PREDICT, &mark);
    mtt_gate_frame(trk);
    charge(trk, MTT_STAGE_GATE, &mark);
    mtt_clutter_frame(trk, md->lm);
    charge(trk, MTT_STAGE_LM_CLUTTER, &mark);
    mtt_associate_frame(trk);
    charge(trk, MTT_STAGE_ASSOCIATE, &mark);
    mtt_update_frame(trk);
#if MTT_WITH_SPLIT
    mtt_split_frame(trk, dt); /* split = true: the split modes, decoupling (ALGORITHMS.md §14.3) */
#endif
    charge(trk, MTT_STAGE_UPDATE, &mark);
    mtt_initiate_frame(trk, dt);
    charge(trk, MTT_STAGE_INITIATE, &mark);
    mtt_merge_frame(trk);
    charge(trk, MTT_STAGE_MERGE, &mark);
    mtt_track_manage(trk, dt);
    charge(trk, MTT_STAGE_MANAGE, &mark);

    trk->time = time;
    trk->dt_last = dt;
    trk->have_time = 1;
    add_counts(&trk->stats.total, &trk->stats.last);
}

mtt_status mtt_tracker_stats(const mtt_tracker *trk, mtt_stats *stats)
{
    if (trk == NULL || stats == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    *stats = trk->stats;
    return MTT_OK;
}
