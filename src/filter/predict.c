/* SPDX-License-Identifier: BSD-3-Clause */
/* predict.c - prediction of every track, pipeline stage 2 (ALGORITHMS.md
 * §2, §3, §11): the motion model's x^ = F x, P^ = F P F' + Q, the Markov
 * existence prediction, and the innovation covariance S = H P^ H' + R
 * with its inverse and the gain, from which gating and every update work
 * (under polar detections R is the converted covariance at the track's
 * predicted position, §3.2).
 * A confirmed track of lm-ihpda contest predicts with its own scale of the
 * process noise (§2.1, adapt_q.c).
 * A track whose S is not positive definite is marked invalid (§3): it is
 * not gated and the manager deletes it. */
#include <string.h>

#include "mtt_internal.h"

void mtt_predict_frame(mtt_tracker *trk, mtt_real dt)
{
    mtt_cov Q; /* Q(dt): one dt and one Sw for every track of the frame */
    uint16_t i;
    if (dt > MTT_ZERO) {
        mtt_manoeuvre_frame(trk, dt); /* the derived motion at this dt (ALGORITHMS.md §2.2) */
        mtt_motion_q(dt, trk->par.process_psd, Q);
#if MTT_WITH_IMM && defined(MTT_REAL_FIXED)
        for (i = 0; i < trk->par.imm_n_models && trk->par.motion == MTT_MOTION_IMM; ++i) {
            mtt_motion_q(dt, trk->par.imm_psd[i], trk->qm[i]); /* every IMM track's, once */
        }
#endif
#if MTT_WITH_CONTEST
        trk->q_floor = mtt_adapt_floor(trk, dt);
#endif
    }
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track *t = &trk->tracks[i];
        mtt_track_frame *tf = &trk->tf[i];
        t->born = 0;
        t->dead = 0;
        t->meas = -1;
        if (dt > MTT_ZERO) {
#if MTT_WITH_IMM
            if (trk->par.motion != MTT_MOTION_IMM)
#endif
            {
#if MTT_WITH_CONTEST
                if (!mtt_adapt_predict_track(trk, dt, Q, t, tf)) /* its own level (§2.1) */
#endif
                {
                    mtt_kalman_predict_q(dt, Q, t->x, t->P, tf->xp, tf->Pp);
                }
            }
            tf->ex_pred = mtt_existence_predict(t->existence, trk->par.markov_p11, trk->par.markov_p21);
            t->age++;
        } else {
            /* First frame: the state is already at this time (seeded tracks). */
            memcpy(tf->xp, t->x, sizeof tf->xp);
            memcpy(tf->Pp, t->P, sizeof tf->Pp);
            tf->ex_pred = t->existence;
        }
        tf->assigned = -1;
        tf->best = -1;
        tf->shrink = 0;
        tf->pair_first = 0;
        tf->pair_count = 0;
#if MTT_WITH_IMM
        if (trk->par.motion == MTT_MOTION_IMM) {
            /* IMM (ALGORITHMS.md §14.1): replaces the single-model prediction above */
            tf->valid = (uint8_t)mtt_imm_predict_track(trk, i, dt);
            continue;
        }
#endif
#if MTT_WITH_POLAR
        {
            mtt_real Rt[3]; /* polar: R at the predicted position (ALGORITHMS.md §3.2) */
            tf->valid = (uint8_t)(mtt_state_finite(tf->xp) &&
                                  mtt_kalman_innov(tf->Pp, mtt_polar_track_r(trk, tf->xp, Rt), tf->S, tf->Si,
                                                   &tf->det_s, tf->K) == 0);
        }
#else
        tf->valid = (uint8_t)(mtt_state_finite(tf->xp) &&
                              mtt_kalman_innov(tf->Pp, trk->R, tf->S, tf->Si, &tf->det_s, tf->K) == 0);
#endif
    }
}
