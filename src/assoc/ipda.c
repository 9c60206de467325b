/* SPDX-License-Identifier: BSD-3-Clause */
/* ipda.c - IPDA association probabilities and the IPDA row of a track
 * (ALGORITHMS.md §6); the association of the ipda and lm-ipda modes.
 *
 * Lambda = sum_j p_j / lambda_j, L = 1 - PD PG + PD PG Lambda,
 * beta_j = PD PG (p_j / lambda_j) / L, beta_0 = (1 - PD PG) / L.
 * With lambda_j the LM density lambda~ this is LM-IPDA (ALGORITHMS.md §8.1).
 * Fixed point (docs/FIXED_POINT.md §2, §3): p_j and lambda_j are held
 * relative to the clutter density, so p_j / lambda_j is a quotient of two
 * Q16 ratios; Lambda and L are Q16 ratios, the betas Q30.  When Lambda
 * saturates (many gated measurements with large p_j / lambda_j: a burst of
 * duplicates at a confident track), the betas are formed on the row scaled
 * by 2^-k with m < 2^k, which fits: beta_j only needs the ratios, and with
 * the saturated sum they would add up to more than 1 (and the PDA spread
 * term turn P indefinite). */
#include "mtt_internal.h"

#ifdef MTT_REAL_FIXED
#define ROW(x) ((x) >> k)
#else
#define ROW(x) (x)
#endif

void mtt_ipda_betas(mtt_prob pd, mtt_prob pg, mtt_pair *pp, uint16_t m, mtt_prob *beta0, mtt_ratio *L)
{
    const mtt_prob pdpg = MTT_MUL_PP(pd, pg);
    mtt_ratio big = MTT_ZERO, l, lb;
    uint16_t j;
#ifdef MTT_REAL_FIXED
    int k = 0;
#endif
    /* beta_j holds p_j / lambda_j until the betas are formed: one
     * quotient per pair instead of two (three when Lambda saturates). */
    for (j = 0; j < m; ++j) {
        pp[j].beta = MTT_DIV_R(pp[j].p, pp[j].lam);
        big = MTT_ADDS(big, pp[j].beta);
    }
    l = MTT_ADDS(MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), pdpg)), MTT_MUL_RP(pdpg, big));
    lb = l;
#ifdef MTT_REAL_FIXED
    if (!(big < MTT_FX_MAX)) {
        k = 32 - mtt_fx_clz(m); /* m < 2^k: the scaled sum stays below 2^31 */
        big = 0;
        for (j = 0; j < m; ++j) {
            big += ROW(pp[j].beta);
        }
        lb = MTT_ADDS(ROW(MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), pdpg))), MTT_MUL_RP(pdpg, big));
    }
#endif
    for (j = 0; j < m; ++j) {
        pp[j].beta = MTT_DIV_P(MTT_MUL_RP(pdpg, ROW(pp[j].beta)), lb);
    }
    *beta0 = MTT_DIV_PR(MTT_SUB(MTT_P(1.0), pdpg), l);
    *L = l;
}

void mtt_ipda_track(mtt_tracker *trk, uint16_t ti)
{
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real L;
    mtt_ipda_betas(trk->par.pd, trk->par.pg, &trk->pairs[tf->pair_first], tf->pair_count, &tf->beta0, &L);
    tf->ex_post = mtt_existence_update(tf->ex_pred, L);
}

void mtt_ipda_frame(mtt_tracker *trk)
{
    uint16_t i;
    /* An empty gate needs no row: the update keeps the prediction with
     * L = 1 - PD PG (ALGORITHMS.md §6, m = 0). */
    for (i = 0; i < trk->n_tracks; ++i) {
        if (trk->tf[i].valid && trk->tf[i].pair_count > 0u) {
            mtt_ipda_track(trk, i);
        }
    }
}
