/* SPDX-License-Identifier: BSD-3-Clause */
/* update.c - state and existence update of every valid track, by the
 * update kind of its mode's row (associate.c); the association stage has
 * written every beta.
 *
 * ONE (IHPDA modes, ALGORITHMS.md §7.4, §10.3): the assigned (or selected) pair with
 * its final beta_s and L_s; existence P = L_s P^/(1-P^+L_s P^); state
 * x = x^ + beta_s K nu_s, P = beta0 P^ + beta_s P_c + beta_s beta0 K nu nu' K'.
 * PDA (IPDA modes ALGORITHMS.md §6, JPDA family ALGORITHMS.md §13.8): the PDA update with the
 * beta row and beta_0; existence from the association stage.
 * HARD (NNJPDA, ALGORITHMS.md §13.5): the Kalman update with the assigned measurement
 * (beta 1, beta0 0); existence from the association stage (ALGORITHMS.md §13.2).
 * lm-ihpda contest (ALGORITHMS.md §10.4): a contested track takes the PDA update with
 * the LM-IPDA row of the contest test instead of ONE; after its update a
 * confirmed track's process-noise scale follows its NIS (ALGORITHMS.md §2.1).
 * A track with no measurement keeps its prediction, with L = 1 - PD PG.
 * An IMM track (motion imm, ALGORITHMS.md §14.2) takes its update in
 * imm/imm_track.c (mtt_imm_update_assoc).
 * Fixed point (docs/FIXED_POINT.md): the firmware modes only (ONE and PDA
 * with CV; IMM, the baselines and the contest variant are compiled out),
 * the covariances in block floating point through kalman.c. */
#include <string.h>

#include "mtt_internal.h"

static void keep_prediction(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    /* memcpy of distinct objects: the element loops compiled to a memmove
     * call, which alone linked newlib's memmove into the firmware */
    memcpy(t->x, tf->xp, MTT_STATE_N * sizeof t->x[0]);
#if MTT_MAX_STATE == MTT_STATE_N
    memcpy(t->P, tf->Pp, sizeof t->P); /* the whole block (fixed point: with its exponent) */
#else
    {
        int i;
        for (i = 0; i < MTT_STATE_N; ++i) {
            memcpy(t->P[i], tf->Pp[i], MTT_STATE_N * sizeof t->P[i][0]);
        }
        MTT_COV_COPY_E(t->P, tf->Pp);
    }
#endif
    t->existence = mtt_existence_update(tf->ex_pred, MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), MTT_MUL_PP(trk->par.pd, trk->par.pg))));
    t->meas = -1;
}

/* The PDA update of the track's CV prediction with the pairs
 * first..first+m-1, their innovations nu and betas: with the one R of
 * meas_sigma, or the mixture when a detection has its own (§3.1). */
static void pda(mtt_tracker *trk, mtt_track_frame *tf, uint16_t first, uint16_t m,
                mtt_real nu[][2], const mtt_real beta[], mtt_real beta0, mtt_track *t)
{
#if MTT_WITH_MEAS_COV
    if (trk->n_own_r > 0u && mtt_meas_row_r(trk, first, m) > 0u) {
        mtt_kalman_pda_each(MTT_STATE_N, tf->xp, tf->Pp, trk->row.rj, trk->row.rr, trk->par.sensor_xy, m, nu, beta,
                            beta0, trk->row.dj, t->x, t->P);
        return;
    }
#else
    (void)first;
#endif
    mtt_kalman_pda(tf->xp, tf->Pp, tf->K, tf->Si, trk->R, m, nu, beta, beta0, t->x, t->P);
}

/* Single-measurement update with pair k (ALGORITHMS.md §7.4). */
static void update_one(mtt_tracker *trk, uint16_t ti, uint16_t k)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    const mtt_pair *pp = &trk->pairs[k];
    const mtt_mstore *ms = &trk->meas[pp->meas];
    mtt_real nu[1][2];
    mtt_real beta[1];
    nu[0][0] = ms->x - tf->xp[0];
    nu[0][1] = ms->y - tf->xp[1];
    beta[0] = pp->beta;
    pda(trk, tf, k, 1, nu, beta, MTT_SUB(MTT_P(1.0), pp->beta), t);
    t->existence = mtt_existence_update(tf->ex_pred, MTT_PAIR_L(pp));
    t->meas = (int32_t)ms->src;
}

#if MTT_WITH_CONTEST
/* A contested lm-ihpda track marks its measurements with beta >=
 * contest_beta used (ALGORITHMS.md §10.4 step 5: after every final
 * recomputation, which has run by now). */
static void mark_contested_used(mtt_tracker *trk, uint16_t ti)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    uint16_t k;
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        if (trk->pairs[k].beta >= trk->par.contest_beta) {
            trk->meas[trk->pairs[k].meas].used = 1;
        }
    }
}
#endif

/* PDA update with the beta row, beta_0 and existence of the association
 * stage (ALGORITHMS.md §6, §13.8); the reported measurement is the largest beta. */
static void update_pda(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real *beta = trk->row.beta;
    mtt_real(*nu)[2] = trk->row.nu;
    const mtt_pair *const pairs = &trk->pairs[tf->pair_first];
    mtt_mstore *const meas = trk->meas;
    uint16_t m = tf->pair_count, j, b = 0;
    for (j = 0; j < m; ++j) {
        const mtt_pair *pp = &pairs[j];
        beta[j] = pp->beta;
        nu[j][0] = meas[pp->meas].x - tf->xp[0];
        nu[j][1] = meas[pp->meas].y - tf->xp[1];
        if (beta[j] > beta[b]) {
            b = j;
        }
    }
#if MTT_WITH_CONTEST
    if (MTT_CONTESTED(tf)) {
        mark_contested_used(trk, ti);
    }
#endif
    pda(trk, tf, tf->pair_first, m, nu, beta, tf->beta0, t);
    t->existence = tf->ex_post;
    t->meas = (int32_t)meas[pairs[b].meas].src;
}

#if MTT_WITH_BASELINES
/* NNJPDA: hard Kalman update with the assigned pair (ALGORITHMS.md §13.5), or the
 * prediction; existence per ALGORITHMS.md §13.2 either way. */
static void update_nn(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    if (tf->assigned < 0) {
        keep_prediction(trk, ti);
    } else {
        const mtt_mstore *ms = &trk->meas[trk->pairs[tf->assigned].meas];
        mtt_real nu[1][2];
        const mtt_real one[1] = {MTT_R(1.0)};
        nu[0][0] = ms->x - tf->xp[0];
        nu[0][1] = ms->y - tf->xp[1];
        pda(trk, tf, (uint16_t)tf->assigned, 1, nu, one, MTT_R(0.0), t);
        t->meas = (int32_t)ms->src;
    }
    t->existence = tf->ex_post;
}
#endif

void mtt_update_frame(mtt_tracker *trk)
{
    const uint8_t kind = mtt_modes[trk->par.association].update;
    uint16_t i;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        const int one = kind == MTT_UPDATE_ONE && !MTT_CONTESTED(tf); /* the ONE update */
        if (!tf->valid) {
            continue; /* deleted by the manager (ALGORITHMS.md §3) */
        }
#if MTT_WITH_IMM
        if (trk->par.motion == MTT_MOTION_IMM) {
            /* a contested track: the PDA update over its models (ALGORITHMS.md §10.4, §14.2) */
            mtt_imm_update_assoc(trk, i, MTT_CONTESTED(tf) ? (uint8_t)MTT_UPDATE_PDA : kind);
#if MTT_WITH_CONTEST
            if (MTT_CONTESTED(tf)) {
                mark_contested_used(trk, i);
            }
#endif
        } else
#endif
        if (one ? tf->assigned < 0 : tf->pair_count == 0u) {
            keep_prediction(trk, i); /* no measurement for this track */
        } else if (one) {
            update_one(trk, i, (uint16_t)tf->assigned);
#if MTT_WITH_BASELINES
        } else if (kind == MTT_UPDATE_HARD) {
            update_nn(trk, i);
#endif
        } else {
            update_pda(trk, i);
        }
#if MTT_WITH_CONTEST
        if (MTT_CONTEST_ON(trk)) {
            mtt_adapt_observe(trk, i); /* the process-noise scale (ALGORITHMS.md §2.1) */
        }
#endif
        /* ALGORITHMS.md §3 deletes a track whose S is not positive definite; the same
         * for its covariance, which float arithmetic can lose for extreme
         * priors (a velocity variance 1e30 beside a position variance of 4:
         * fuzz finding F7).  The manager counts it in numeric_deletions. */
        if (!mtt_cov_ok(trk->tracks[i].P, MTT_FRAME_COV_MARGIN)) {
            tf->valid = 0;
        }
    }
}
