/* SPDX-License-Identifier: BSD-3-Clause */
/* merge.c - track merging (ALGORITHMS.md §12.3, [S0] eq. 17).
 *
 * d^2 = (x_a - x_b)' (P_a + P_b)^-1 (x_a - x_b) < t_merge merges.  Only
 * tracks of one cluster are candidates (they share gated measurements
 * transitively); tracks born this frame have no gate and are not.  Pairs
 * are processed by ascending d^2 (ties by track index); the survivor is the
 * smaller position-covariance trace (then higher existence, then lower
 * identity), keeps its state, takes the larger existence and the OR of the
 * confirmed flags.  With lm-ihpda contest, two tracks both contested this
 * frame are no candidates (ALGORITHMS.md §10.4).
 * Fixed-point build (docs/FIXED_POINT.md §3): P_a + P_b at the larger of
 * the two block exponents, d^2 in Q24 through the integer L D L', the
 * traces compared at one exponent. */
#include "mtt_internal.h"

int mtt_merge_d2(const mtt_track *a, const mtt_track *b, mtt_d2 *d2)
{
    mtt_cov A;
    mtt_state d;
    int i, j;
    /* fixed point: both blocks at the larger exponent (identity otherwise) */
    MTT_COV_SET_E(A, MTT_COV_EMAX(a->P, b->P));
    for (i = 0; i < MTT_STATE_N; ++i) {
        d[i] = MTT_SUBS(a->x[i], b->x[i]);
        for (j = 0; j < MTT_STATE_N; ++j) {
            A[i][j] = MTT_ADD(MTT_AT(a->P[i][j], MTT_COV_E(a->P), MTT_COV_E(A)),
                              MTT_AT(b->P[i][j], MTT_COV_E(b->P), MTT_COV_E(A)));
        }
    }
    return mtt_chol_quad(A, d, d2);
}

static int less_cand(const void *pa, const void *pb, const void *ctx)
{
    const mtt_merge_cand *a = (const mtt_merge_cand *)pa, *b = (const mtt_merge_cand *)pb;
    (void)ctx;
    if (a->d2 != b->d2) {
        return a->d2 < b->d2;
    }
    if (a->a != b->a) {
        return a->a < b->a;
    }
    return a->b < b->b;
}

static void add_cand(mtt_tracker *trk, mtt_d2 d2, uint16_t a, uint16_t b)
{
    mtt_merge_cand c;
    uint16_t k, worst = 0;
    c.d2 = d2;
    c.a = a;
    c.b = b;
    if (trk->n_merge < MTT_MAX_MERGE_PAIRS) {
        trk->merge[trk->n_merge++] = c;
        return;
    }
    /* Full: the largest d^2 gives way. */
    trk->stats.last.merge_dropped++;
    for (k = 1; k < MTT_MAX_MERGE_PAIRS; ++k) {
        if (less_cand(&trk->merge[worst], &trk->merge[k], NULL)) {
            worst = k;
        }
    }
    if (less_cand(&c, &trk->merge[worst], NULL)) {
        trk->merge[worst] = c;
    }
}

void mtt_merge_frame(mtt_tracker *trk)
{
    const mtt_d2 thr = trk->par.merge_threshold;
    /* The arrays once in locals: Thumb-1 loads a large field offset from a
     * literal at every use (a firmware's .text). */
    const uint16_t *const first = trk->cl_first, *const list = trk->cl_list;
    const mtt_track_frame *const tf = trk->tf;
    mtt_track *const tracks = trk->tracks;
    const mtt_merge_cand *const mc = trk->merge;
    uint16_t c, q1, q2, k;
    trk->n_merge = 0;
    if (!(thr > MTT_ZERO)) {
        return;
    }
    for (c = 0; c < trk->n_clusters; ++c) {
        for (q1 = first[c]; q1 < first[c + 1u]; ++q1) {
            for (q2 = (uint16_t)(q1 + 1u); q2 < first[c + 1u]; ++q2) {
                uint16_t a = list[q1], b = list[q2];
                mtt_d2 d2;
                /* A track the update found numerically invalid is deleted
                 * as such, not merged (it would be counted twice). */
                if (!tf[a].valid || !tf[b].valid) {
                    continue;
                }
                /* lm-ihpda contest (ALGORITHMS.md §10.4): two tracks that both
                 * took the mixture this frame are two targets meeting, not
                 * one target tracked twice; merging them lost one. */
                if (MTT_CONTESTED(&tf[a]) && MTT_CONTESTED(&tf[b])) {
                    continue;
                }
                if (mtt_merge_d2(&tracks[a], &tracks[b], &d2) == 0 && d2 < thr) {
                    add_cand(trk, d2, a, b);
                }
            }
        }
    }
    mtt_sort(trk->merge, trk->n_merge, sizeof trk->merge[0], less_cand, NULL);
    for (k = 0; k < trk->n_merge; ++k) {
        mtt_track *ta = &tracks[mc[k].a], *tb = &tracks[mc[k].b];
        mtt_track *keep, *drop;
        mtt_real tra, trb;
        if (ta->dead || tb->dead) {
            continue;
        }
        /* fixed point: both at the larger exponent */
        tra = MTT_AT(MTT_ADD(ta->P[0][0], ta->P[1][1]), MTT_COV_E(ta->P), MTT_COV_EMAX(ta->P, tb->P));
        trb = MTT_AT(MTT_ADD(tb->P[0][0], tb->P[1][1]), MTT_COV_E(tb->P), MTT_COV_EMAX(ta->P, tb->P));
        /* a has the lower index, hence the lower identity: it wins full ties. */
        if (tra < trb || (tra == trb && ta->existence >= tb->existence)) {
            keep = ta;
            drop = tb;
        } else {
            keep = tb;
            drop = ta;
        }
        if (drop->existence > keep->existence) {
            keep->existence = drop->existence;
        }
        keep->confirmed = (uint8_t)(keep->confirmed | drop->confirmed);
        drop->dead = 1;
        trk->stats.last.merges++;
    }
}
