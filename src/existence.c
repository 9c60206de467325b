/* existence.c - track existence probability.
 *
 * ALGORITHMS.md §11: Markov chain one prediction P_k|k-1 = p11 P + p21 (1 - P).
 * ALGORITHMS.md §6 / §7.4: update in the L form P = L P / (1 - P + L P), which stays
 * accurate when delta = 1 - L is large and negative (ALGORITHMS.md §16).  Results are
 * clamped to [0, 1] (ALGORITHMS.md §16), with anything below 1e-30 taken as 0. */
#include "mtt_internal.h"

static mtt_real clamp01(mtt_real p)
{
    /* Below 1e-30 an existence is 0 for every purpose; flushing it keeps
     * denormals (slow, or flushed by the FPU) out of the association
     * weights.  Also maps NaN to 0. */
    if (!(p > MTT_R(1e-30))) {
        return MTT_R(0.0);
    }
    return (p < MTT_R(1.0)) ? p : MTT_R(1.0);
}

mtt_real mtt_existence_predict(mtt_real p, mtt_real p11, mtt_real p21)
{
    return clamp01(p11 * p + p21 * (MTT_R(1.0) - p));
}

mtt_real mtt_existence_update(mtt_real ex_pred, mtt_real L)
{
    mtt_real num = L * ex_pred;
    mtt_real den = MTT_R(1.0) - ex_pred + num;
    if (!(den > MTT_R(0.0))) {
        return MTT_R(0.0);
    }
    return clamp01(num / den);
}
