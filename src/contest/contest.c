/* SPDX-License-Identifier: BSD-3-Clause */
/* contest.c - the contest test of lm-ihpda with lm_ihpda_variant contest
 * (ALGORITHMS.md §10.4), between MMR (§10.1) and the final recomputation
 * (§10.3).
 *
 * MMR hands a measurement to one track with a hard beta ~ 1 update even
 * when a neighbour claims it about as strongly; the track of a missed
 * target then takes its neighbour's detection.  The test finds those
 * cases on the LM-IPDA row (§6 with the §8 densities) of every track of a
 * cluster with two or more tracks: a measurement is contested when two or
 * more tracks give it beta >= contest_beta, a track when one of its
 * measurements with beta >= contest_beta is contested.  A contested track
 * takes the LM-IPDA (PDA) update with that row, as JPDA's marginal betas
 * would, and marks its measurements with beta >= contest_beta used
 * (update.c); the others keep §10.3 and §7.4.  O(gated pairs), no
 * enumeration. */
#include "mtt_internal.h"

#if MTT_WITH_CONTEST
void mtt_contest_frame(mtt_tracker *trk)
{
    const mtt_real eps = trk->par.contest_beta;
    uint16_t i, j, k;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        tf->contest = MTT_CONTEST_NONE;
        /* a lone track shares no measurement: its IHPDA row stands */
        if (tf->valid && tf->pair_count > 0u &&
            trk->cl_first[tf->cluster + 1u] >= trk->cl_first[tf->cluster] + 2u) {
            mtt_ipda_track(trk, i); /* pair.beta, tf.beta0, tf.ex_post */
            tf->contest = MTT_CONTEST_ROW;
        }
    }
    /* A measurement gated by two or more tracks lies in one cluster of two
     * or more tracks, so every beta read here is an LM-IPDA beta. */
    for (j = 0; j < trk->n_meas; ++j) {
        uint16_t claims = 0;
        for (k = trk->mp_first[j]; k < trk->mp_first[j + 1u]; ++k) {
            if (trk->pairs[trk->mp_list[k]].beta >= eps) {
                ++claims;
            }
        }
        if (claims < 2u) {
            continue;
        }
        for (k = trk->mp_first[j]; k < trk->mp_first[j + 1u]; ++k) {
            const mtt_pair *pp = &trk->pairs[trk->mp_list[k]];
            if (pp->beta >= eps) {
                trk->tf[pp->track].contest = MTT_CONTEST_YES;
            }
        }
    }
}
#endif /* MTT_WITH_CONTEST */
