/* SPDX-License-Identifier: BSD-3-Clause */
/* lm_all.c - the all-tracks LM density of lm-ipda-all, [S4]'s LM-IPDAF
 * baseline (ALGORITHMS.md §8.3).
 *
 * After lm_clutter.c's cluster-only lambda~ (§8.2), every pair (t, j) gets
 * the terms of the tracks s that do not gate j, from s's untruncated
 * Gaussian: p = N(z_j; z^s, S^s) / PG, Pt = PD PG P^s p / (sum_{l in G^s}
 * p_l + p), w = p Pt / (1 - Pt); S^s with the detection's own R when it
 * has one (§3.1).  Cost O(tracks x measurements), which is
 * the cost [S4]'s cluster restriction saves.  Float and double builds only
 * (a baseline: MTT_WITH_BASELINES, never in the fixed-point build). */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES && !defined(MTT_REAL_FIXED)
void mtt_lm_all_frame(mtt_tracker *trk)
{
    const mtt_real pdpg = trk->par.pd * trk->par.pg;
    const mtt_real pt_max = MTT_R(1.0) - MTT_R(1e-6); /* ALGORITHMS.md §16 clamp */
    const uint16_t *const mp_first = trk->mp_first;
    mtt_ratio *const out = trk->wsum; /* free after §8.2's pass 2 */
    mtt_pair *const pairs = trk->pairs;
    uint16_t i, j, k;

    for (j = 0; j < trk->n_meas; ++j) {
        out[j] = MTT_ZERO;
    }
    /* Ascending s for every j: the sum's order is normative (§8.3). */
    for (i = 0; i < trk->n_tracks; ++i) {
        const mtt_track_frame *tf = &trk->tf[i];
        const uint16_t end = (uint16_t)(tf->pair_first + tf->pair_count);
        const mtt_real c = pdpg * tf->ex_pred;
        mtt_real sum = MTT_ZERO;
        uint16_t q = tf->pair_first; /* s's pairs ascend in j: a cursor */
        if (!tf->valid) {
            continue;
        }
        for (k = tf->pair_first; k < end; ++k) {
            sum += pairs[k].p;
        }
        for (j = 0; j < trk->n_meas; ++j) {
            mtt_real dx, dy, p, pt;
            if (q < end && pairs[q].meas == j) {
                ++q; /* s gates j: its term is in lambda~ already (§8.2) */
                continue;
            }
            if (mp_first[j + 1u] == mp_first[j]) {
                continue; /* no pair reads lambda~ of j */
            }
            dx = trk->meas[j].x - tf->xp[0];
            dy = trk->meas[j].y - tf->xp[1];
#if MTT_WITH_MEAS_COV
            if (trk->meas[j].has_R) {
                mtt_real d2, S[3]; /* its own R (ALGORITHMS.md §3.1), as the gated pairs' p */
                if (mtt_meas_gauss(tf->Pp[0], tf->Pp[1], trk->meas[j].R, trk->par.pg, dx, dy, &d2, &p, S) != 0) {
                    continue; /* S_j not positive definite: no term, as no gate */
                }
            } else
#endif
            {
                p = mtt_gate_likelihood(mtt_mahal2(tf->Si, dx, dy), tf->det_s, trk->par.pg);
            }
            if (!(p > MTT_ZERO)) {
                continue; /* exp underflow: the term is 0 */
            }
            pt = c * (p / (sum + p)); /* the quotient first: <= 1 even for a subnormal p */
            if (pt > pt_max) {
                pt = pt_max;
            }
            out[j] += p * pt / (MTT_R(1.0) - pt);
        }
    }
    for (k = 0; k < trk->n_pairs; ++k) {
        pairs[k].lam += out[pairs[k].meas];
    }
}
#endif
