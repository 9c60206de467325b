/* SPDX-License-Identifier: BSD-3-Clause */
/* mmr.c - maximum marginal return assignment with recomputation
 * (ALGORITHMS.md §10.1; [S0] eq. 13; Kolitz 1988).
 *
 * Repeatedly take the global maximum beta of the cluster (ties: lowest track
 * index, then lowest measurement index), assign it, and recompute the rows
 * of the remaining tracks that gated the taken measurement: only those
 * rows change.  Each iteration removes one track, so the loop runs at most
 * (tracks in the cluster) times. */
#include "mtt_internal.h"

/* Best available entry of a row, static values (no recomputation). */
static void static_best(mtt_tracker *trk, uint16_t ti)
{
    mtt_track_frame *tf = &trk->tf[ti];
    uint16_t k;
    tf->best = -1;
    tf->best_beta = MTT_ZERO;
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        const mtt_pair *pp = &trk->pairs[k];
        if (!trk->meas[pp->meas].used && pp->beta > MTT_ZERO &&
            (tf->best < 0 || pp->beta > tf->best_beta)) {
            tf->best = (int16_t)k;
            tf->best_beta = pp->beta;
        }
    }
}

static void row_best(mtt_tracker *trk, uint16_t ti, int recompute)
{
    mtt_track_frame *tf = &trk->tf[ti];
    if (!recompute) {
        static_best(trk, ti);
        return;
    }
    (void)mtt_ihpda_row(trk, ti, 1, -1, 0, &tf->best);
    tf->best_beta = (tf->best >= 0) ? trk->pairs[tf->best].beta : MTT_ZERO;
}

void mtt_mmr_cluster(mtt_tracker *trk, uint16_t c, int recompute)
{
    const uint16_t first = trk->cl_first[c], end = trk->cl_first[c + 1u];
    uint16_t q, it;

    for (q = first; q < end; ++q) {
        uint16_t ti = trk->cl_list[q];
        trk->tf[ti].assigned = -1;
        row_best(trk, ti, recompute);
    }
    for (it = first; it < end; ++it) {
        int32_t win = -1;
        uint16_t j, k;
        mtt_track_frame *tw;
        for (q = first; q < end; ++q) {
            const mtt_track_frame *tf = &trk->tf[trk->cl_list[q]];
            if (tf->assigned < 0 && tf->best >= 0 &&
                (win < 0 || tf->best_beta > trk->tf[win].best_beta)) {
                win = trk->cl_list[q];
            }
        }
        if (win < 0) {
            break; /* every remaining track has an empty row: m = 0 update */
        }
        tw = &trk->tf[win];
        tw->assigned = tw->best;
        j = trk->pairs[tw->best].meas;
        trk->meas[j].used = 1;
        for (k = trk->mp_first[j]; k < trk->mp_first[j + 1u]; ++k) {
            uint16_t t2 = trk->pairs[trk->mp_list[k]].track;
            if (trk->tf[t2].assigned < 0 && t2 != (uint16_t)win) {
                row_best(trk, t2, recompute);
            }
        }
    }
}
