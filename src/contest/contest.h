/* contest.h - lm-ihpda's contest variant (ALGORITHMS.md §2.1, §7.6, §10.4),
 * built with MTT_WITH_CONTEST.  Not installed; not part of the API.  Included
 * through mtt_internal.h.  Sections "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_CONTEST_H
#define MTT_CONTEST_H

/* lm-ihpda with lm_ihpda_variant contest (ALGORITHMS.md §7.6, §10.4): the
 * amplitude ratio in p, the amplitude rows and the contest-aware update.
 * Not with motion imm: the contest update has no IMM form yet, so an IMM
 * lm-ihpda runs [S0] whatever the variant.  Constant 0 with
 * MTT_WITH_CONTEST 0, so the compiler drops that code. */
#define MTT_CONTEST_ON(trk)                                                                        \
    (MTT_WITH_CONTEST && (trk)->par.association == MTT_ASSOC_LM_IHPDA &&                           \
     (trk)->par.lm_ihpda_variant == MTT_LM_IHPDA_CONTEST && (trk)->par.motion != MTT_MOTION_IMM)

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
void mtt_contest_frame(mtt_tracker *trk);

/* ---- adapt_q.c: a confirmed contest track's process-noise scale (ALGORITHMS.md §2.1) ---- */
#if MTT_WITH_CONTEST
/* The CV prediction with s Q (Q is read, not changed). */
void mtt_adapt_predict(mtt_real dt, mtt_cov Q, mtt_real s, const mtt_state x, mtt_cov P,
                       mtt_state xp, mtt_cov Pp);
/* The lowest scale for an interval dt: max(adapt_s_min, Lambda^2 / adapt_index), at most 1. */
mtt_real mtt_adapt_floor(const mtt_tracker *trk, mtt_real dt);
/* E[NIS] of a gated target detection: chi-square 2 truncated at gamma. */
mtt_real mtt_adapt_nis_mean(mtt_real gamma, mtt_real pg);
/* After track ti's update: its NIS average and scale s (tentative,
 * contested and s0 tracks keep s = 1 / theirs). */
void mtt_adapt_observe(mtt_tracker *trk, uint16_t ti);
#endif

#endif /* MTT_CONTEST_H */
