/* SPDX-License-Identifier: BSD-3-Clause */
/* jpda_adaptive.c - adaptive JPDA (ALGORITHMS.md §13.7, CHOICE
 * interpretation of [S1] §3).  Rules 1, 2 and 4 also make [S1]'s other
 * gate-change variants (jpda-vg, adaptive-nnjpda, adaptive-jpda-star: the
 * association routines from MTT_ASSOCIATE_ADAPTIVE_JPDA on); rule 3 is
 * adaptive-jpda's alone.
 *
 * 1. Overlap: tracks t and s overlap when |H xbar_t - H xbar_s| <=
 *    adaptive_jpda_distance * max(sigma_x, sigma_y).
 * 2. Gate shrink: an overlapping track gates with gamma / adaptive_jpda_shrink
 *    (tf.shrink, read by gate.c for this frame: the test and the gate area;
 *    PG stays the configured one).
 * 3. Equal share: after the JPDA betas (computed with the shrunken gates),
 *    each measurement gated by N >= 2 overlapping tracks gets beta = 1/N in
 *    each of them, without renormalisation; such a track's beta_0 becomes
 *    max(0, 1 - sum beta), and a row summing over 1 is scaled to 1.
 * 4. Restore: the overlap is decided anew every frame, so tracks that no
 *    longer overlap get the full gate and the normal betas back.
 * The overlap test compares every pair of tracks: O(tracks^2), in this
 * mode only. */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES

void mtt_adaptive_gates(mtt_tracker *trk)
{
    const mtt_real sm = (trk->par.meas_sigma[0] > trk->par.meas_sigma[1]) ? trk->par.meas_sigma[0]
                                                                         : trk->par.meas_sigma[1];
    const mtt_real dmax = trk->par.adaptive_jpda_distance * sm;
    uint16_t i, j;
    for (i = 0; i < trk->n_tracks; ++i) {
        trk->tf[i].shrink = 0;
    }
    for (i = 0; i < trk->n_tracks; ++i) {
        const mtt_track_frame *a = &trk->tf[i];
        if (!a->valid) {
            continue;
        }
        for (j = (uint16_t)(i + 1u); j < trk->n_tracks; ++j) {
            const mtt_track_frame *b = &trk->tf[j];
            mtt_real dx, dy;
            if (!b->valid) {
                continue;
            }
            dx = a->xp[0] - b->xp[0];
            dy = a->xp[1] - b->xp[1];
            if (dx * dx + dy * dy <= dmax * dmax) {
                trk->tf[i].shrink = 1;
                trk->tf[j].shrink = 1;
            }
        }
    }
}

void mtt_adaptive_share(mtt_tracker *trk, uint16_t c)
{
    uint16_t q, k, x;
    for (q = trk->cl_first[c]; q < trk->cl_first[c + 1u]; ++q) {
        const uint16_t ti = trk->cl_list[q];
        mtt_track_frame *tf = &trk->tf[ti];
        mtt_real sum = MTT_R(0.0);
        int shared = 0;
        if (!tf->shrink) {
            continue;
        }
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            const uint16_t j = trk->pairs[k].meas;
            uint16_t nc = 0;
            for (x = trk->mp_first[j]; x < trk->mp_first[j + 1u]; ++x) {
                nc = (uint16_t)(nc + trk->tf[trk->pairs[trk->mp_list[x]].track].shrink);
            }
            if (nc >= 2u) {
                trk->pairs[k].beta = MTT_R(1.0) / (mtt_real)nc;
                shared = 1;
            }
            sum += trk->pairs[k].beta;
        }
        if (!shared) {
            continue;
        }
        if (sum > MTT_R(1.0)) {
            for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
                trk->pairs[k].beta /= sum;
            }
            tf->beta0 = MTT_R(0.0);
        } else {
            tf->beta0 = MTT_R(1.0) - sum;
        }
    }
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_baselines_left_out;
#endif /* MTT_WITH_BASELINES */
