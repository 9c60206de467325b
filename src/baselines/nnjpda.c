/* SPDX-License-Identifier: BSD-3-Clause */
/* nnjpda.c - NNJPDA (ALGORITHMS.md §13.5; [S1] section 3).
 *
 * The exact JPDA betas of the cluster (jpda.c, Cheap JPDA beyond its
 * bounds) resolve the conflicts by static MMR (mmr.c without
 * recomputation: global maximum, remove row and column, repeat; ties to the
 * lowest track, then the lowest measurement).  Betas below nnjpda_threshold
 * are not assignable.  A beta > 0.5 is the largest of its row and of its
 * column, so it is always selected.  update.c then makes a hard Kalman
 * update with the assigned measurement; only assigned measurements are
 * used (ALGORITHMS.md §15.1), the others go to initiation. */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES

void mtt_nnjpda_cluster(mtt_tracker *trk, uint16_t c)
{
    const mtt_real thr = trk->par.nnjpda_threshold;
    uint16_t q, k;
    for (q = trk->cl_first[c]; q < trk->cl_first[c + 1u]; ++q) {
        const mtt_track_frame *tf = &trk->tf[trk->cl_list[q]];
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            if (trk->pairs[k].beta < thr) {
                trk->pairs[k].beta = MTT_R(0.0); /* never selected */
            }
        }
    }
    mtt_mmr_cluster(trk, c, 0);
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_baselines_left_out;
#endif /* MTT_WITH_BASELINES */
