/* SPDX-License-Identifier: BSD-3-Clause */
/* lm_clutter.c - clutter density seen by each gated pair.
 *
 * ALGORITHMS.md §5.1: known uniform lambda; §5.2: when lambda = 0, the per-track
 * estimate lambda^ = (m - PD PG P^) / V_G.
 * ALGORITHMS.md §8.2: the LM density lambda~_j^t = lambda + sum over the OTHER tracks
 * s gating j of p_j^s Pt_j^s / (1 - Pt_j^s), with
 * Pt_j^s = PD PG P^s (p_j^s / lambda) / sum_{l in G^s} (p_l^s / lambda).
 * Two passes over the gated pairs: O(pairs).  Only tracks that gate j
 * contribute, which is [S4]'s cluster-only computation (lm-ipda-all adds
 * the other tracks, baselines/lm_all.c, §8.3).
 * ALGORITHMS.md §7.6 (lm-ihpda, lm_ihpda_variant contest): first every
 * pair's p_j becomes p_j g_j, the amplitude likelihood ratio of its
 * measurement, so the LM densities, the rows and the existence see it.
 * Polar detections with a known density (§3.2): lambda is per unit range x
 * bearing, lambda_j = lambda / r_j at detection j (the Jacobian of x, y to
 * r, b), the track's lambda that at its predicted range, and Pt weighs
 * p_l / lambda_l.
 * Written in the quantity macros of mtt/real.h (docs/FIXED_POINT.md §3, §4):
 * in the fixed-point build p_j, w_j and lambda~ are Q16 ratios to the
 * clutter density, Pt a Q30 probability. */
#include "mtt_internal.h"

/* Measurements gated by at most this many tracks sum the other tracks'
 * terms directly; above it, W_j - w (ALGORITHMS.md §8.2: avoids float cancellation). */
#define MTT_LM_DIRECT 4u

mtt_ratio mtt_clutter_estimate(uint16_t m, mtt_prob pd, mtt_prob pg, mtt_prob ex_pred, mtt_ratio vg)
{
    return MTT_DIV_CG(MTT_SUB(MTT_CNT(m), MTT_MUL_PC(MTT_MUL_PP(pd, pg), ex_pred)), vg);
}

#if MTT_WITH_POLAR
/* Polar detections, known density lam per unit range x bearing (§3.2):
 * pair.lam = lam / r_j, tf->lambda = lam / r^ at the predicted range, and
 * with lm the w_j of pass 1 from Pt = PD PG P^ (p_j r_j) / sum (p_l r_l),
 * the p_l / lambda_l normalised as §8.1 writes it. */
static void polar_lambda(mtt_tracker *trk, mtt_track_frame *tf, mtt_real lam, int amp, int lm)
{
    const mtt_real pdpg = trk->par.pd * trk->par.pg, pt_max = MTT_R(1.0) - MTT_R(1e-6);
    const mtt_real rt = mtt_polar_range(trk, tf->xp);
    mtt_real sum = MTT_R(0.0);
    uint16_t k;
    tf->lambda = (rt > MTT_R(0.0)) ? lam / rt : MTT_REAL_MAX;
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        mtt_pair *pp = &trk->pairs[k];
        const mtt_real r = trk->meas[pp->meas].rng;
#if MTT_WITH_CONTEST
        if (amp) {
            mtt_contest_amp_pair(trk, pp); /* p_j g_j (ALGORITHMS.md §7.6) */
        }
#else
        (void)amp;
#endif
        pp->lam = lam / r;
        sum += pp->p * r;
    }
    if (!lm) {
        return;
    }
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        mtt_pair *pp = &trk->pairs[k];
        mtt_real pt = pdpg * tf->ex_pred * (pp->p * trk->meas[pp->meas].rng) / sum;
        pt = (pt > pt_max) ? pt_max : pt;
        pp->w = pp->p * pt / (MTT_R(1.0) - pt);
    }
}
#endif

void mtt_clutter_frame(mtt_tracker *trk, int lm)
{
    const mtt_prob pdpg = MTT_MUL_PP(trk->par.pd, trk->par.pg);
    const mtt_prob pt_max = MTT_SUB(MTT_P(1.0), MTT_P(1e-6)); /* ALGORITHMS.md §16 clamp */
    /* The arrays once in locals: Thumb-1 loads a large field offset from a
     * literal at every use (a firmware's .text). */
    mtt_pair *const pairs = trk->pairs;
    const uint16_t *const mp_first = trk->mp_first, *const mp_list = trk->mp_list;
    mtt_ratio *const wsum = trk->wsum;
#if MTT_WITH_CONTEST
    const int amp = MTT_CONTEST_ON(trk);
#endif
#if MTT_WITH_POLAR
    const int polar = trk->par.measurement == MTT_MEASUREMENT_POLAR;
#endif
    uint16_t i, k;

    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        mtt_ratio lam = MTT_REL_DENS(trk->par.clutter_density);
        mtt_ratio sum = MTT_ZERO;
        if (!tf->valid || tf->pair_count == 0u) {
            tf->lambda = lam;
            continue;
        }
        if (!(lam > MTT_ZERO)) {
            lam = mtt_clutter_estimate(tf->pair_count, trk->par.pd, trk->par.pg, tf->ex_pred, tf->vg);
        }
#if MTT_WITH_POLAR
        if (polar && trk->par.clutter_density > MTT_ZERO) {
#if MTT_WITH_CONTEST
            polar_lambda(trk, tf, lam, amp, lm);
#else
            polar_lambda(trk, tf, lam, 0, lm);
#endif
            continue;
        }
#endif
        tf->lambda = lam;
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            mtt_pair *pp = &pairs[k];
#if MTT_WITH_CONTEST
            if (amp) {
                mtt_contest_amp_pair(trk, pp); /* p_j g_j (ALGORITHMS.md §7.6) */
            }
#endif
            pp->lam = lam;
            sum = MTT_ADDS(sum, pp->p);
        }
        if (!lm) {
            continue;
        }
        /* Pass 1: w_j^s.  The uniform lambda cancels inside Pt (ALGORITHMS.md §8.1). */
        {
#ifdef MTT_REAL_FIXED
            /* Fixed point: PD PG P^ once per track and one reciprocal of
             * the sum, r = 2^rho / sum on 30 bits (rho = 29 + its bit
             * length), so Pt = PD PG P^ (p r 2^(30 - rho)) with p r
             * 2^(30 - rho) <= 2^30 (p <= sum): a product per pair instead
             * of a quotient. */
            const mtt_prob c = MTT_MUL_PP(pdpg, tf->ex_pred);
            const int rho = 29 + (32 - mtt_fx_clz((uint32_t)sum));
            const int32_t r = (sum > 0) ? mtt_fx_recip(sum, rho) : 0;
#define LM_PT(p) mtt_fx_mulq30(c, mtt_fx_mul((p), r, rho - 30))
#else
#define LM_PT(p) MTT_DIV_P(MTT_MUL_RP(MTT_MUL_PP(pdpg, tf->ex_pred), (p)), sum)
#endif
            for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
                mtt_pair *pp = &pairs[k];
                mtt_prob pt = LM_PT(pp->p);
                if (pt > pt_max) {
                    pt = pt_max;
                }
                pp->w = MTT_DIV_RP(MTT_MUL_RP(pp->p, pt), MTT_SUB(MTT_P(1.0), pt));
            }
#undef LM_PT
        }
    }
    if (!lm) {
        return;
    }
    for (i = 0; i < trk->n_meas; ++i) {
        mtt_ratio W = MTT_ZERO;
        for (k = mp_first[i]; k < mp_first[i + 1u]; ++k) {
            W = MTT_ADDS(W, pairs[mp_list[k]].w);
        }
        wsum[i] = W;
    }
    /* Pass 2: lambda~ = lambda + (W_j - w_j^t), clamped at 0 (ALGORITHMS.md §8.2). */
    for (k = 0; k < trk->n_pairs; ++k) {
        mtt_pair *pp = &pairs[k];
        uint16_t j = pp->meas;
        uint16_t c = (uint16_t)(mp_first[j + 1u] - mp_first[j]);
        mtt_ratio others;
        if (c <= MTT_LM_DIRECT) {
            uint16_t q;
            others = MTT_ZERO;
            for (q = mp_first[j]; q < mp_first[j + 1u]; ++q) {
                if (mp_list[q] != k) {
                    others = MTT_ADDS(others, pairs[mp_list[q]].w);
                }
            }
        } else {
            others = MTT_SUBS(wsum[j], pp->w);
            if (others < MTT_ZERO) {
                others = MTT_ZERO;
            }
        }
        pp->lam = MTT_ADDS(pp->lam, others);
    }
#if MTT_WITH_BASELINES && !defined(MTT_REAL_FIXED)
    if (lm == 2) {
        mtt_lm_all_frame(trk); /* lm-ipda-all: the tracks that do not gate j too (§8.3) */
    }
#endif
}
