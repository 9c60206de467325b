/* SPDX-License-Identifier: BSD-3-Clause */
/* motion.h - the motion-model seam (ALGORITHMS.md §2, §3, §12.1).
 *
 * Everything prediction, gating, update, initiation and merging need of a
 * motion model, in one small interface: the state size, the transition F
 * with the process noise Q (applied by mtt_motion_predict), the
 * measurement matrix H, and a first state and covariance from two points.
 *
 * H is the same for every model: the first MTT_MEAS_DIM states are the
 * measured position, H = [I 0].  So the Kalman stages (kalman.c) need no H
 * matrix, and any model that keeps position first fits: constant velocity
 * (x, y, vx, vy), constant acceleration (x, y, vx, vy, ax, ay: its first
 * four states are CV's), coordinated turn.
 *
 * The track table stores states as mtt_state / mtt_cov, sized by the
 * compile-time MTT_MAX_STATE (mtt/config.h); a model uses the leading
 * MTT_STATE_N entries.  The model is chosen at compile time (one model,
 * CV, today): the calls go straight to its functions, with no function
 * pointer on the hot path.  Adding a model is one file (motion_<name>.c)
 * implementing these functions; several models at once (IMM) add a model
 * index to the calls and a switch over the built-in models. */
#ifndef MTT_MOTION_H
#define MTT_MOTION_H

#include "mtt/mtt.h"

/* H = [I 0]: the measured position is the first two states. */
#define MTT_MEAS_DIM 2

/* State size of the built-in model (CV). */
#define MTT_STATE_N 4
#if MTT_STATE_N > MTT_MAX_STATE
#error "the motion model needs MTT_MAX_STATE >= MTT_STATE_N"
#endif

typedef mtt_real mtt_state[MTT_MAX_STATE];
/* Fixed point: one more row holds the block exponent (mtt/real.h). */
typedef mtt_real mtt_cov[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];

/* 1 when the MTT_STATE_N entries of a state are finite. */
int mtt_state_finite(const mtt_real *x);

/* Q(dt) for the process noise power spectral density sw (§2). */
void mtt_motion_q(mtt_real dt, mtt_real sw, mtt_cov Q);
/* xp = F(dt) x, Pp = F P F' + Q (§2, §3) with Q = mtt_motion_q(dt, sw),
 * which the caller forms once for every track of one dt and sw (Q is read,
 * not changed); Pp is symmetrised by the caller. */
void mtt_motion_predict(mtt_real dt, mtt_cov Q, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp);
/* The two-point covariance of a full measurement covariance R (sym: r11,
 * r12, r22) and interval dt > 0 (§12.1). */
void mtt_motion_two_point_cov(const mtt_real R[3], mtt_real dt, mtt_cov P);
/* First state and covariance of a track from measurement a (time k-1) and
 * b (time k), dt apart (§12.1), with the velocity variance capped at vmax^2. */
struct mtt_mstore;
void mtt_motion_birth(const struct mtt_mstore *a, const struct mtt_mstore *b, mtt_real dt,
                      const mtt_real R[3], mtt_real vmax, mtt_state x, mtt_cov P);

#endif /* MTT_MOTION_H */
