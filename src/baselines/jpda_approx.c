/* SPDX-License-Identifier: BSD-3-Clause */
/* jpda_approx.c - Cheap JPDA and Suboptimal JPDA per cluster (ALGORITHMS.md §13.3,
 * §13.4; [S1] eq. 2 to 5).  Both work on the sparse gated pairs (no cluster
 * bound): A_tj = jp.pa of the pair, B_t = jp.tb of the track (jpda.c).
 *
 * Cheap JPDA (Fitzgerald; Blair's beta_t0):
 *   T_t = sum_j A_tj, M_j = sum_t A_tj,
 *   beta_tj = A_tj / (T_t + M_j - A_tj + B_t), beta_t0 = B_t / (T_t + B_t);
 *   normalise = 1 scales each row (beta_t0 and beta_tj) to sum 1 (ALGORITHMS.md §13.3
 *   CHOICE), 0 leaves the raw values (TV13).
 *
 * Suboptimal JPDA (Roecker, as written in S1 with the errata of ALGORITHMS.md §13.4):
 *   L_t = tracks other than t that share a gated measurement with t,
 *   N_sj = max_{k in A_s, k != j} A_sk (0 if none),
 *   D_tj = A_tj if L_t is empty, else A_tj sum_{s in L_t} N_sj,
 *   beta_tj = D_tj / (B'_t + sum_l D_tl), beta_t0 = B'_t / (...),
 *   with B'_t = B_t sum_{s in L_t} max_k A_sk (ALGORITHMS.md §13.4 CHOICE, per_track_b
 *   = 1; B'_t = B_t when L_t is empty) or the constant B'_t = B_t. */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES

void mtt_cheap_jpda(mtt_tracker *trk, uint16_t c, int normalise)
{
    const mtt_real *pa = trk->base.jp.pa;
    uint16_t q, k, x;
    for (q = trk->cl_first[c]; q < trk->cl_first[c + 1u]; ++q) {
        const uint16_t ti = trk->cl_list[q];
        mtt_track_frame *tf = &trk->tf[ti];
        const uint16_t k0 = tf->pair_first, k1 = (uint16_t)(tf->pair_first + tf->pair_count);
        const mtt_real B = trk->base.jp.tb[ti];
        mtt_real T = MTT_R(0.0), sum;
        if (tf->pair_count == 0u) {
            tf->beta0 = MTT_R(1.0);
            continue;
        }
        for (k = k0; k < k1; ++k) {
            T += pa[k];
        }
        tf->beta0 = B / (T + B);
        sum = tf->beta0;
        for (k = k0; k < k1; ++k) {
            const uint16_t j = trk->pairs[k].meas;
            mtt_real M = MTT_R(0.0);
            for (x = trk->mp_first[j]; x < trk->mp_first[j + 1u]; ++x) {
                M += pa[trk->mp_list[x]];
            }
            trk->pairs[k].beta = pa[k] / (T + M - pa[k] + B);
            sum += trk->pairs[k].beta;
        }
        if (normalise && sum > MTT_R(0.0)) {
            tf->beta0 /= sum;
            for (k = k0; k < k1; ++k) {
                trk->pairs[k].beta /= sum;
            }
        }
    }
}

void mtt_subopt_jpda(mtt_tracker *trk, uint16_t c, int per_track_b)
{
    mtt_jpda_scratch *s = &trk->base.jp;
    const mtt_real *pa = s->pa;
    uint16_t q, k, x, a;
    /* Per row: the largest A, its measurement and the second largest. */
    for (q = trk->cl_first[c]; q < trk->cl_first[c + 1u]; ++q) {
        const uint16_t ti = trk->cl_list[q];
        const mtt_track_frame *tf = &trk->tf[ti];
        s->max1[ti] = MTT_R(0.0);
        s->max2[ti] = MTT_R(0.0);
        s->arg1[ti] = MTT_NONE16;
        s->mark[ti] = 0;
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            if (s->arg1[ti] == MTT_NONE16 || pa[k] > s->max1[ti]) {
                s->max2[ti] = s->max1[ti];
                s->max1[ti] = pa[k];
                s->arg1[ti] = trk->pairs[k].meas;
            } else if (pa[k] > s->max2[ti]) {
                s->max2[ti] = pa[k];
            }
        }
    }
    for (q = trk->cl_first[c]; q < trk->cl_first[c + 1u]; ++q) {
        const uint16_t ti = trk->cl_list[q];
        mtt_track_frame *tf = &trk->tf[ti];
        const uint16_t k0 = tf->pair_first, k1 = (uint16_t)(tf->pair_first + tf->pair_count);
        mtt_real Bt = s->tb[ti], den;
        uint16_t nn = 0;
        if (tf->pair_count == 0u) {
            tf->beta0 = MTT_R(1.0);
            continue;
        }
        /* L_t: each neighbour once (mark = t + 1). */
        for (k = k0; k < k1; ++k) {
            const uint16_t j = trk->pairs[k].meas;
            for (x = trk->mp_first[j]; x < trk->mp_first[j + 1u]; ++x) {
                const uint16_t sj = trk->pairs[trk->mp_list[x]].track;
                if (sj != ti && s->mark[sj] != (uint16_t)(ti + 1u)) {
                    s->mark[sj] = (uint16_t)(ti + 1u);
                    s->nb[nn++] = sj;
                }
            }
        }
        if (nn > 0u && per_track_b) {
            mtt_real sm = MTT_R(0.0);
            for (a = 0; a < nn; ++a) {
                sm += s->max1[s->nb[a]];
            }
            Bt *= sm;
        }
        den = Bt;
        for (k = k0; k < k1; ++k) {
            const uint16_t j = trk->pairs[k].meas;
            mtt_real d = pa[k];
            if (nn > 0u) {
                mtt_real ns = MTT_R(0.0);
                for (a = 0; a < nn; ++a) {
                    const uint16_t sj = s->nb[a];
                    ns += (s->arg1[sj] == j) ? s->max2[sj] : s->max1[sj];
                }
                d *= ns;
            }
            trk->pairs[k].beta = d; /* D_tj until normalised below */
            den += d;
        }
        if (den > MTT_R(0.0)) {
            tf->beta0 = Bt / den;
            for (k = k0; k < k1; ++k) {
                trk->pairs[k].beta /= den;
            }
        } else {
            tf->beta0 = MTT_R(1.0);
            for (k = k0; k < k1; ++k) {
                trk->pairs[k].beta = MTT_R(0.0);
            }
        }
    }
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_baselines_left_out;
#endif /* MTT_WITH_BASELINES */
