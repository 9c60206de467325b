/* SPDX-License-Identifier: BSD-3-Clause */
/* split.h - split targets (ALGORITHMS.md §14.3), built with MTT_WITH_SPLIT.
 * Not installed; not part of the API.  Included through mtt_internal.h;
 * sections "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_SPLIT_H
#define MTT_SPLIT_H

/* ==== Split targets (ALGORITHMS.md §14.3): split.c ======================
 * Built with MTT_WITH_SPLIT (include/mtt/config.h).  Plain functions over
 * arrays.  A single-target model has n components (4 <= n <=
 * MTT_MAX_STATE, position first); the stacked split state is [x_1; x_2]
 * (2n components in MTT_SPLIT_STATE storage), target 1 the parent, target
 * 2 the child.  Likelihoods are ratios to the all-clutter density V^-m of
 * the m validated measurements (the scale of the IPDA likelihood ratio,
 * ALGORITHMS.md §14.2).  Functions return 0, or -1 on invalid arguments
 * or a covariance that is not positive definite (nothing written).
 * R is the track's measurement covariance (meas_sigma's; polar: at its
 * predicted position); Rj (NULL: R for every measurement) each
 * measurement's own (ALGORITHMS.md §3.1, MTT_WITH_MEAS_COV): its S_j in
 * the gates and likelihoods, the mixture of single-detection updates (the
 * clusters of model 5 stay on the track's S); rd (NULL: none) their range
 * rates, taken with Rj. */
#if MTT_WITH_SPLIT
/* The validated set's range rates (polar, ALGORITHMS.md §3.2): rr[j]
 * measurement j's range rate and its variance, or NULL.  A range rate
 * multiplies its detection's gate and likelihood by mtt_polar_rdot_f at
 * its target's prediction (model 6: that target's block), and each
 * single-detection (single-event) update ends with its EKF step on that
 * target's block (mtt_polar_rdot_step). */
typedef struct mtt_split_rdot {
    const mtt_real *const *rr;
    const mtt_real *sensor; /* sensor_xy */
    mtt_real gamma;         /* the range rate's gate threshold */
    mtt_real vmax;          /* clutter range rates uniform on [-vmax, vmax] */
} mtt_split_rdot;
/* chi-square 0.99 quantile, 2 degrees of freedom: -2 ln 0.01 ([S3] eq. 27) */
#define MTT_SPLIT_CHI2_99 MTT_R(9.2103403719761836)
/* mtt_split_state, mtt_split_cov, mtt_split_assoc, mtt_split_work: mtt/state.h
 * (tracker scratch).  mtt_split_predict, mtt_split_just, mtt_split_update
 * and mtt_split_separate take their work matrices from wk (the caller's: the split stage's
 * scratch), so that no 12 x 12 matrix is on the stack. */

/* Stacked prediction with the model's F and Q (n x n): xps = blockdiag(F,
 * F) xs, Pps = F^s Ps F^s' + blockdiag(Q, Q), symmetrised. */
int mtt_split_predict(mtt_split_work *wk, uint8_t n, mtt_real F[][MTT_MAX_STATE],
                      mtt_real Q[][MTT_MAX_STATE], const mtt_split_state xs, mtt_split_cov Ps,
                      mtt_split_state xps, mtt_split_cov Pps);
/* Model 5 "just split" from one prediction (xp, Pp) and the m >= 2
 * validated measurements z with their PDA betas: clusters around the two
 * largest betas (Mahalanobis with S; cluster[j] = 0 parent, 1 child), betas
 * renormalised per cluster (beta_n), per-half PDA update and the cross
 * covariance (I - WH) Pp (I - WH)' into the stacked (xs, Ps), and *lik =
 * prod_i (V/m_i) sum_{j in I_i} N_j (eq. 13 with V^-(m_i - 1), over V^-m);
 * vg = V, the validation volume (1/lambda for a known clutter density
 * lambda: the m_i - 1 others are clutter of density lambda). */
int mtt_split_just(mtt_split_work *wk, uint8_t n, const mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE],
                   const mtt_real R[3], const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m,
                   mtt_real z[][2], const mtt_real beta[],
                   mtt_real vg, mtt_split_state xs, mtt_split_cov Ps, uint8_t cluster[],
                   mtt_real beta_n[], mtt_real *lik);

/* Per-target gates (d^2 <= gamma with S_t = H P_tt H' + R) and the event
 * factors a, b.  lam = 0: non-parametric ([S3] eq. 14, V = vg; lik is the
 * ratio to V^-m); lam > 0: Poisson clutter of known density lam (the
 * detection factor is PD N / lam, no factorials; lik is the ratio to the
 * all-clutter density, the scale of the IPDA L of ALGORITHMS.md §6). */
int mtt_split_assoc_init(uint8_t n, const mtt_split_state xps, mtt_split_cov Pps, const mtt_real R[3],
                         const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m, mtt_real z[][2], mtt_real pd, mtt_real pg,
                         mtt_real gamma, mtt_real vg, mtt_real lam, mtt_split_assoc *as);
/* Unnormalised weight of the joint event (j1, j2) (measurement index of
 * target 1 and 2, -1 = undetected): (phi!/m!) prod PD V N prod (1 - PD PG);
 * 0 when infeasible. */
mtt_real mtt_split_event_weight(const mtt_split_assoc *as, int16_t j1, int16_t j2);
/* Normalise over every event: lik, beta, beta_miss, beta0. */
int mtt_split_joint(mtt_split_assoc *as);
/* Coupled update of the stacked state (ALGORITHMS.md §14.3, corrected
 * bracket of [S3] eq. 25), after mtt_split_joint. */
int mtt_split_update(mtt_split_work *wk, const mtt_split_assoc *as, const mtt_split_state xps,
                     mtt_split_cov Pps, const mtt_real R[3], const mtt_real *const Rj[],
                     const mtt_split_rdot *rd, mtt_real z[][2], mtt_split_state xs, mtt_split_cov Ps);
/* Model 5's velocity impulse over dt (ALGORITHMS.md §14.3 [CHOICE]): a
 * velocity change of standard deviation dv, per axis the blocks position
 * dv^2 dt^2 / 2, cross dv^2 dt / 2, velocity dv^2; with across only across
 * the course (vx, vy): the blocks times n n', n the unit normal of the
 * course (per axis when the speed is 0).  Q's 4 x 4 cv part (position
 * first, then velocity), 0 beyond. */
void mtt_split_impulse_q(mtt_real dt, mtt_real dv, int across, mtt_real vx, mtt_real vy, mtt_cov Q);
/* The unit normal (-vy, vx)/|v| of a course; (0, 1) and 0 returned at speed 0, else 1. */
int mtt_split_normal(mtt_real vx, mtt_real vy, mtt_real *nx, mtt_real *ny);
/* Model 5's child half for a split of known speed (ALGORITHMS.md §14.3,
 * split_known_speed): after mtt_split_just (its cluster and beta_n), the
 * child's half is updated again from the cv prediction (xp, Pp) moved
 * across the course, to the side of the child's cluster, by dv in velocity
 * and by (MTT_SPLIT_KNOWN_OFFSET + h) dv dt in position, h < n_off the
 * offset nearest the cluster's mean (h >= 1: a split caught h scans late),
 * with across the course the velocity variance (MTT_SPLIT_KNOWN_SD dv)^2,
 * the position variance (dv dt)^2 / 12 + that times dt^2 / 4 and their
 * covariance that times dt / 2.  Writes the child's half of (xs, Ps)
 * (cross covariance 0; the parent's half untouched) and *lik = (V/m_1)
 * sum_{I_1} N(z; H xp, S_cv) (V/m_2) sum_{I_2} N(z; H x_k, S_k) / (2 n_off)
 * (the side and the offset each one of 2 and n_off equally likely). */
#define MTT_SPLIT_KNOWN_OFFSET MTT_R(1.25)
#define MTT_SPLIT_KNOWN_SD MTT_R(0.15)
#define MTT_SPLIT_KNOWN_MAX_OFFSETS 4u
int mtt_split_known(mtt_split_work *wk, uint8_t n, const mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE],
                    const mtt_real R[3], const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m,
                    mtt_real z[][2], const uint8_t cluster[],
                    const mtt_real beta_n[], mtt_real dv, mtt_real dt, uint8_t n_off, mtt_real vg,
                    mtt_split_state xs, mtt_split_cov Ps, mtt_real *lik);
/* Decoupling test [S3] eq. 27 on a stacked prediction: *d2 = (z1 - z2)'
 * (S1 + S2)^-1 (z1 - z2); returns 1 when d2 >= c (decoupled), 0 when not,
 * -1 on invalid input. */
int mtt_split_decouple(uint8_t n, const mtt_split_state xps, mtt_split_cov Pps, const mtt_real R[3],
                       mtt_real c, mtt_real *d2);
/* A decoupled split state as two independent track states: (x1, P1) the
 * parent's, (x2, P2) the child's first state; the cross covariance is
 * dropped.  -1 when a half is not positive definite. */
int mtt_split_separate(mtt_split_work *wk, uint8_t n, const mtt_split_state xs, mtt_split_cov Ps,
                       mtt_real x1[], mtt_real P1[][MTT_MAX_STATE], mtt_real x2[],
                       mtt_real P2[][MTT_MAX_STATE]);
/* The split stage of every confirmed IMM track after the update (split =
 * true; split_track.c): mode probabilities of the split modes, decoupling
 * into a child track. */
void mtt_split_frame(mtt_tracker *trk, mtt_real dt);
#endif /* MTT_WITH_SPLIT */

#endif /* MTT_SPLIT_H */
