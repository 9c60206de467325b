/* SPDX-License-Identifier: BSD-3-Clause */
/* existence.c - track existence probability.
 *
 * ALGORITHMS.md §11: Markov chain one prediction P_k|k-1 = p11 P + p21 (1 - P).
 * ALGORITHMS.md §6 / §7.4: update in the L form P = L P / (1 - P + L P), which stays
 * accurate when delta = 1 - L is large and negative (ALGORITHMS.md §16).  Results are
 * clamped to [0, 1] (ALGORITHMS.md §16), with anything below 1e-30 taken as 0.
 * Written in the quantity macros of mtt/real.h (docs/FIXED_POINT.md §4):
 * probabilities Q30, L a Q16 ratio in the fixed-point build. */
#include "mtt_internal.h"

static mtt_prob clamp01(mtt_prob p)
{
    /* Below 1e-30 an existence is 0 for every purpose; flushing it keeps
     * denormals (slow, or flushed by the FPU) out of the association
     * weights.  Also maps NaN to 0.  (Fixed point: below one Q30 unit.) */
    if (!(p > MTT_P_FLOOR)) {
        return MTT_ZERO;
    }
    return (p < MTT_P(1.0)) ? p : MTT_P(1.0);
}

mtt_prob mtt_existence_predict(mtt_prob p, mtt_prob p11, mtt_prob p21)
{
    return clamp01(MTT_ADD(MTT_MUL_PP(p11, p), MTT_MUL_PP(p21, MTT_SUB(MTT_P(1.0), p))));
}

/* Fixed point: num and den in the Q16 of L (P = num / den does not depend
 * on their common scale); num = L P is exactly rounded and saturates only
 * past 32768, where P is within 2^-15 of 1. */
mtt_prob mtt_existence_update(mtt_prob ex_pred, mtt_ratio L)
{
    mtt_ratio num = MTT_MUL_RP(L, ex_pred);
    mtt_ratio den = MTT_ADDS(MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), ex_pred)), num);
    if (!(den > MTT_ZERO)) {
        return MTT_ZERO;
    }
    return clamp01(MTT_DIV_P(num, den));
}
