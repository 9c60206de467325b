/* SPDX-License-Identifier: BSD-3-Clause */
/* adapt_q.c - the noise-adaptive process noise of a confirmed track with
 * lm-ihpda's contest variant (ALGORITHMS.md §2.1): Q = s·Q(process_psd)
 * with s in [floor, 1], lowered while the track's normalised innovations
 * are smaller than the filter expects and raised when they grow, at once
 * past adapt_reset_nis (a manoeuvre).  The floor is adapt_s_min or, when
 * larger, the squared tracking index process_psd·dt³/σ² over adapt_index:
 * where the configured manoeuvres move a target by σ or more in one scan
 * a lower level would lose it before its innovations show the manoeuvre.
 * O(1) per track per scan: one NIS, one exp.
 *
 * process_psd stays the upper level the user configured: s = 1 is the
 * plain §2 filter, and a tentative track keeps it (it has no history).
 * Not part of [S0] (lm_ihpda_variant s0 never leaves s = 1), not with
 * motion imm, and not in a build without MTT_WITH_CONTEST (the fixed
 * point and the firmware builds), where this file is empty. */
#include <string.h>

#include "mtt_internal.h"

#if MTT_WITH_CONTEST

void mtt_adapt_defaults(mtt_params *p)
{
    /* ALGORITHMS.md §2.1 [CHOICE, measured in docs/reports/IDENTITY.md] */
    p->adapt_s_min = MTT_R(0.01);
    p->adapt_index = MTT_R(1.0);
    p->adapt_memory = MTT_R(0.8);
    p->adapt_gain = MTT_R(2.0);
    p->adapt_reset_nis = MTT_R(8.0);
    p->adapt_s_max = MTT_R(0.0); /* auto: resolved with the motion (ALGORITHMS.md §2.2) */
}

void mtt_adapt_init(mtt_tracker *trk)
{
    trk->q_floor = MTT_R(1.0); /* no interval yet: the configured level (ALGORITHMS.md §2.1) */
    trk->nis_mean = mtt_adapt_nis_mean(trk->gamma, trk->par.pg);
}

void mtt_adapt_track_init(mtt_track *t)
{
    t->q_scale = MTT_R(1.0);
    t->nis_ratio = MTT_R(1.0);
}

void mtt_adapt_predict(mtt_real dt, mtt_cov Q, mtt_real s, const mtt_state x, mtt_cov P,
                       mtt_state xp, mtt_cov Pp)
{
    /* s Q in this function's own frame, not in mtt_predict_frame's: the
     * IMM's prediction path, the deepest of a step, does not carry it */
    mtt_cov Qs;
    int i, j;
    memcpy(Qs, Q, sizeof(mtt_cov));
    for (i = 0; i < MTT_STATE_N; ++i) {
        for (j = 0; j < MTT_STATE_N; ++j) {
            Qs[i][j] = s * Q[i][j];
        }
    }
    mtt_kalman_predict_q(dt, Qs, x, P, xp, Pp);
}

mtt_real mtt_adapt_floor(const mtt_tracker *trk, mtt_real dt)
{
    const mtt_params *p = &trk->par;
    /* Lambda^2 = q dt^3 / sigma^2, sigma^2 the mean of R's diagonal */
    mtt_real f = p->process_psd * dt * dt * dt / (MTT_R(0.5) * (trk->R[0] + trk->R[2]) * p->adapt_index);
    if (f < p->adapt_s_min) {
        f = p->adapt_s_min;
    }
    return (f < MTT_R(1.0)) ? f : MTT_R(1.0);
}

mtt_real mtt_adapt_nis_mean(mtt_real gamma, mtt_real pg)
{
    /* E[chi2_2 | chi2_2 < gamma] = 2 - gamma (1 - PG) / PG, with 1 - PG =
     * exp(-gamma / 2) (ALGORITHMS.md §2.1) */
    return MTT_R(2.0) - gamma * (MTT_R(1.0) - pg) / pg;
}

void mtt_adapt_observe(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    const mtt_track_frame *tf = &trk->tf[ti];
    const mtt_params *p = &trk->par;
    const mtt_pair *pp;
    const mtt_mstore *ms;
    mtt_real dx, dy, nis, w, s;
    if (!t->confirmed || !(p->adapt_s_min < MTT_R(1.0)) || MTT_CONTESTED(tf)) {
        return; /* tentative, adaptation off, or a PDA mixture at a meeting: no observation */
    }
    if (tf->assigned < 0) {
        return; /* a miss says nothing about the level (ALGORITHMS.md §2.1) */
    }
    pp = &trk->pairs[tf->assigned];
    ms = &trk->meas[pp->meas];
#if MTT_WITH_IMM
    if (p->motion == MTT_MOTION_IMM) {
        /* the best-fitting model's NIS: the levels are too low only when
         * every model sees larger innovations than it expects */
        uint8_t j;
        nis = MTT_REAL_MAX;
        for (j = 0; j < p->imm_n_models; ++j) {
            mtt_real pj;
            const mtt_real d2 = mtt_imm_model_d2(trk, tf, j, ms, &pj);
            nis = (d2 < nis) ? d2 : nis;
        }
    } else
#endif
    {
        dx = ms->x - tf->xp[0];
        dy = ms->y - tf->xp[1];
        nis = tf->Si[0] * dx * dx + MTT_R(2.0) * tf->Si[1] * dx * dy + tf->Si[2] * dy * dy;
#if MTT_WITH_MEAS_COV
        if (ms->has_R) {
            mtt_real pj, S[3];
            nis = (mtt_meas_gauss(tf->Pp[0], tf->Pp[1], ms->R, p->pg, dx, dy, &nis, &pj, S) == 0) ? nis : MTT_REAL_MAX;
        }
#endif
    }
    /* weight beta_s: the NIS is the target's with that probability */
    w = (MTT_R(1.0) - p->adapt_memory) * pp->beta;
    t->nis_ratio += w * (nis / trk->nis_mean - t->nis_ratio);
    if (p->adapt_reset_nis > MTT_R(0.0) && nis > p->adapt_reset_nis) {
        if (t->q_scale < MTT_R(1.0)) {
            t->q_scale = MTT_R(1.0); /* a manoeuvre: back to the configured level at once */
        }
        if (!(p->adapt_s_max > MTT_R(1.0))) {
            t->nis_ratio = MTT_R(1.0); /* no rise above it: the average restarts */
            return;
        }
    }
    s = t->q_scale * mtt_exp(p->adapt_gain * (t->nis_ratio - MTT_R(1.0)));
    if (s > p->adapt_s_max) {
        s = p->adapt_s_max;
    }
    if (s < trk->q_floor) {
        s = trk->q_floor;
    }
    t->q_scale = s;
}

#else
typedef int mtt_adapt_q_unused; /* ISO C: no empty translation unit */
#endif /* MTT_WITH_CONTEST */
