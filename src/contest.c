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

/* Joint weight of "track ti takes pair k" (k < 0: ti has no measurement)
 * in the JIPDA event likelihood with clutter as the unit: PD PG P^ p / lambda
 * or 1 - PD PG P^ (ALGORITHMS.md §13.2, §10.4). */
static mtt_real joint_weight(const mtt_tracker *trk, uint16_t ti, int32_t k)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    const mtt_real w = trk->par.pd * trk->par.pg * tf->ex_pred;
    if (k < 0) {
        return MTT_R(1.0) - w;
    }
    return w * trk->pairs[k].p / tf->lambda;
}

/* lm_ihpda_variant joint: measurement j, which MMR gave to the track of
 * pair ko, is claimed by the track of pair ks too.  The pair stays on MMR's
 * hard choices unless the event "the owner missed its target and the
 * claimant took j" (the claimant's own MMR measurement, if any, clutter)
 * has a share >= contest_beta against MMR's event (ALGORITHMS.md §10.4).
 * A swap of two detections is not an alternative here: on it MMR's hard
 * choice keeps two tracks apart where a mixture would merge them. */
static int joint_ambiguous(const mtt_tracker *trk, uint16_t ko, uint16_t ks)
{
    const uint16_t to = trk->pairs[ko].track, ts = trk->pairs[ks].track;
    const mtt_real eps = trk->par.contest_beta;
    const mtt_real mmr = joint_weight(trk, to, (int32_t)ko) * joint_weight(trk, ts, trk->tf[ts].assigned);
    const mtt_real alt = joint_weight(trk, to, -1) * joint_weight(trk, ts, (int32_t)ks);
    return alt * (MTT_R(1.0) - eps) >= eps * mmr;
}

void mtt_contest_frame(mtt_tracker *trk)
{
    const mtt_real eps = trk->par.contest_beta;
    const int joint = trk->par.lm_ihpda_variant == MTT_LM_IHPDA_JOINT;
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
        int32_t owner = -1;
        for (k = trk->mp_first[j]; k < trk->mp_first[j + 1u]; ++k) {
            const uint16_t pk = trk->mp_list[k];
            if (trk->pairs[pk].beta >= eps) {
                ++claims;
            }
            if (trk->tf[trk->pairs[pk].track].assigned == (int16_t)pk) {
                owner = (int32_t)pk;
            }
        }
        if (claims < 2u) {
            continue;
        }
        for (k = trk->mp_first[j]; k < trk->mp_first[j + 1u]; ++k) {
            const uint16_t pk = trk->mp_list[k];
            const mtt_pair *pp = &trk->pairs[pk];
            if (pp->beta < eps) {
                continue;
            }
            if (!joint || owner < 0) {
                trk->tf[pp->track].contest = MTT_CONTEST_YES;
            } else if ((int32_t)pk != owner && joint_ambiguous(trk, (uint16_t)owner, pk)) {
                trk->tf[pp->track].contest = MTT_CONTEST_YES;
                trk->tf[trk->pairs[owner].track].contest = MTT_CONTEST_YES;
            }
        }
    }
}
