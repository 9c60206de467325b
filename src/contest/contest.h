/* SPDX-License-Identifier: BSD-3-Clause */
/* contest.h - lm-ihpda's contest variant (ALGORITHMS.md §2.1, §7.6, §10.4),
 * built with MTT_WITH_CONTEST.  Not installed; not part of the API.  Included
 * through mtt_internal.h.  Sections "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_CONTEST_H
#define MTT_CONTEST_H

/* lm-ihpda with lm_ihpda_variant contest (ALGORITHMS.md §7.6, §10.4, §2.1):
 * the amplitude ratio in p, the amplitude rows, the contest-aware update and
 * the adaptive process noise, with motion cv and imm (an IMM track's
 * contested update is its PDA update over the models, §14.2).  Constant 0
 * with MTT_WITH_CONTEST 0, so the compiler drops that code. */
#define MTT_CONTEST_ON(trk)                                                                        \
    (MTT_WITH_CONTEST && (trk)->par.association == MTT_ASSOC_LM_IHPDA &&                           \
     (trk)->par.lm_ihpda_variant == MTT_LM_IHPDA_CONTEST)

/* ---- contest.c: the contest test of lm-ihpda contest (ALGORITHMS.md §10.4) ---- */
/* tf.contest of a track: no LM-IPDA row this frame (its IHPDA row stands),
 * an LM-IPDA row written over its pairs but not contested (the final
 * recomputation rewrites the IHPDA row), or contested (PDA update with
 * that row). */
enum { MTT_CONTEST_NONE = 0, MTT_CONTEST_ROW = 1, MTT_CONTEST_YES = 2 };
/* tf.contest tests, constant 0 with MTT_WITH_CONTEST 0 (the field stays NONE). */
#define MTT_CONTESTED(tf) (MTT_WITH_CONTEST && (tf)->contest == MTT_CONTEST_YES)
#define MTT_CONTEST_ROW_WRITTEN(tf) (MTT_WITH_CONTEST && (tf)->contest == MTT_CONTEST_ROW)
/* After MMR: the LM-IPDA row (pair.beta, tf.beta0, tf.ex_post) of every
 * track of a cluster with two or more tracks, then tf.contest. */
#if MTT_WITH_CONTEST
void mtt_contest_frame(mtt_tracker *trk);
#endif

/* ---- amplitude.c: the amplitude likelihood ratio and its row (ALGORITHMS.md §7.6) ---- */
#if MTT_WITH_CONTEST
/* Amplitude likelihood ratio of amplitude a against the background law
 * (ALGORITHMS.md §7.6): g = exp(a rho/(1+rho))/(1+rho) (exponent clamped at
 * 30), returned as g/(1 - eta + eta g); rho = 0 gives 1, eta = 0 the plain g. */
mtt_real mtt_amp_ratio(mtt_real rho, mtt_real eta, mtt_real a);
/* The §7.6 row of the m candidates c (c[i].amp holds g_i, c[i].p p_i g_i):
 * beta and L. */
void mtt_contest_amp_betas(mtt_real pdpg, mtt_real vg, const mtt_cand *c, uint16_t m,
                           mtt_real *beta, mtt_real *L);
#endif

#if MTT_WITH_CONTEST
/* The clutter stage's hook (lm_clutter.c, per gated pair of lm-ihpda
 * contest): a measurement with an amplitude multiplies the pair's p by its
 * amplitude likelihood ratio g, kept in pair.g for the row. */
static inline void mtt_contest_amp_pair(const mtt_tracker *trk, mtt_pair *pp)
{
    const mtt_mstore *ms = &trk->meas[pp->meas];
    if (ms->has_amp) {
        pp->g = mtt_amp_ratio(trk->par.snr_rho, trk->par.amplitude_eta, ms->amp);
        pp->p *= pp->g;
    }
}
#endif

/* ---- adapt_q.c: a confirmed contest track's process-noise scale (ALGORITHMS.md §2.1) ---- */
#if MTT_WITH_CONTEST
/* mtt_params_default's values of the adapt_* settings. */
void mtt_adapt_defaults(mtt_params *p);
/* At mtt_tracker_init (after trk->par and trk->gamma): the floor of the
 * first frame (1: no interval yet) and E[NIS] of a gated detection. */
void mtt_adapt_init(mtt_tracker *trk);
/* A new track: s = 1 and a NIS average of 1 (no history). */
void mtt_adapt_track_init(mtt_track *t);
/* The CV prediction with s Q (Q is read, not changed). */
void mtt_adapt_predict(mtt_real dt, mtt_cov Q, mtt_real s, const mtt_state x, mtt_cov P,
                       mtt_state xp, mtt_cov Pp);
/* The lowest scale for an interval dt: max(adapt_s_min, Lambda^2 / adapt_index), at most 1. */
mtt_real mtt_adapt_floor(const mtt_tracker *trk, mtt_real dt);
/* The prediction stage's hook (predict.c, per track with dt > 0, not IMM):
 * s raised to this interval's floor; a track off the configured level
 * (s != 1: a confirmed contest track) predicts with s Q and 1 is returned,
 * else 0 (the caller's plain prediction).  Inline: the hot path. */
static inline int mtt_adapt_predict_track(const mtt_tracker *trk, mtt_real dt, mtt_cov Q,
                                          mtt_track *t, mtt_track_frame *tf)
{
    if (t->q_scale < trk->q_floor) {
        t->q_scale = trk->q_floor; /* this interval's floor (ALGORITHMS.md §2.1) */
    }
    if (t->q_scale != MTT_R(1.0)) {
        mtt_adapt_predict(dt, Q, t->q_scale, t->x, t->P, tf->xp, tf->Pp);
        return 1;
    }
    return 0;
}
/* An IMM track's scale for this interval (imm_track.c): raised to the
 * floor, 1 without the contest variant. */
static inline mtt_real mtt_adapt_imm_scale(const mtt_tracker *trk, mtt_track *t)
{
    if (!MTT_CONTEST_ON(trk)) {
        return MTT_R(1.0);
    }
    if (t->q_scale < trk->q_floor) {
        t->q_scale = trk->q_floor;
    }
    return t->q_scale;
}
/* E[NIS] of a gated target detection: chi-square 2 truncated at gamma. */
mtt_real mtt_adapt_nis_mean(mtt_real gamma, mtt_real pg);
/* After track ti's update: its NIS average and scale s (tentative,
 * contested and s0 tracks keep s = 1 / theirs). */
void mtt_adapt_observe(mtt_tracker *trk, uint16_t ti);
#endif

#endif /* MTT_CONTEST_H */
