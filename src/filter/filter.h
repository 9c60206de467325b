/* SPDX-License-Identifier: BSD-3-Clause */
/* filter.h - the Kalman filter layer: the filter arithmetic, the prediction
 * and the update stages (ALGORITHMS.md §2, §3, §6, §7.4).  Not installed; not
 * part of the API.  Included through mtt_internal.h.  Sections "§N" are those
 * of docs/ALGORITHMS.md. */
#ifndef MTT_FILTER_H
#define MTT_FILTER_H

/* ---- kalman.c: Kalman filter on the motion model of motion.h (ALGORITHMS.md §3, §6) ---- */
/* xp = F x, Pp = F P F' + Q through the model, symmetrised (ALGORITHMS.md §2, §3). */
void mtt_kalman_predict(mtt_real dt, mtt_real sw, const mtt_state x, mtt_cov P, mtt_state xp,
                        mtt_cov Pp);
/* The same with Q = mtt_motion_q(dt, sw) formed by the caller: the
 * prediction stage forms it once per frame for every track. */
void mtt_kalman_predict_q(mtt_real dt, mtt_cov Q, const mtt_state x, mtt_cov P, mtt_state xp,
                          mtt_cov Pp);
/* S = H Pp H' + R, its inverse, det and the gain K = Pp H' S^-1.
 * Returns 0, or -1 when det S is not positive and finite (ALGORITHMS.md §3). */
int mtt_kalman_innov(mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                     mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2]);
/* d^2 = nu' S^-1 nu (ALGORITHMS.md §4); in the fixed build Q24. */
mtt_d2 mtt_mahal2(const mtt_real Si[MTT_SYM_SLOTS], mtt_pos nx, mtt_pos ny);
/* PDA update with m measurements (ALGORITHMS.md §6), K and Si = S^-1 from
 * mtt_kalman_innov; with m = 1 and beta0 = 1 - beta this is the IHPDA
 * single-measurement update of ALGORITHMS.md §7.4, and with m = 0, beta0 = 0 it is
 * the Joseph form P_c = (I-KH) Pp (I-KH)' + K R K' (ALGORITHMS.md §3). */
#if MTT_WITH_IMM
/* The same two steps for a model of n <= MTT_MAX_STATE states (IMM, ALGORITHMS.md §14.2). */
int mtt_kalman_innov_n(int n, mtt_cov Pp, const mtt_real R[3], mtt_real S[MTT_SYM_SLOTS],
                       mtt_real Si[MTT_SYM_SLOTS], mtt_real *det, mtt_real K[][2]);
void mtt_kalman_pda_n(int n, const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
                      const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                      mtt_real beta0, mtt_state x, mtt_cov P);
#endif
void mtt_kalman_pda(const mtt_state xp, mtt_cov Pp, mtt_real K[][2], const mtt_real Si[MTT_SYM_SLOTS],
                    const mtt_real R[3], uint16_t m, mtt_real nu[][2], const mtt_real beta[],
                    mtt_real beta0, mtt_state x, mtt_cov P);
#if MTT_WITH_POLAR
/* ---- polar.c: polar detections (ALGORITHMS.md §3.2) ---- */
/* R of a detection at range r, bearing cos c, sin s, sigma = [sr, sb]. */
void mtt_polar_cov(const mtt_real sigma[2], mtt_real r, mtt_real c, mtt_real s, mtt_real R[3]);
/* The unbiased converted detection and its R; 0, or -1 when range is not
 * finite and > 0, bearing not finite or the result not finite. */
int mtt_polar_convert(const mtt_real sigma[2], const mtt_real sensor[2], mtt_real range, mtt_real bearing,
                      mtt_real *x, mtt_real *y, mtt_real R[3]);
/* The range of a predicted position xp from sensor_xy. */
mtt_real mtt_polar_range(const mtt_tracker *trk, const mtt_real *xp);
/* The R a track's S is formed with: trk->R, or under polar the converted
 * covariance at its predicted position xp (written into R). */
const mtt_real *mtt_polar_track_r(const mtt_tracker *trk, const mtt_real *xp, mtt_real R[3]);
/* A range rate rr (rr[0], variance rr[1]; NULL: none) against a
 * prediction xp (x y vx vy), Pp (its rows of stride st), S = the position's
 * innovation covariance and (nx, ny) its innovation (§3.2): 1 without
 * one, 0 when its innovation given the position's is outside gamma, else
 * N(nu; 0, s) over the clutter's 1 / (2 vmax). */
mtt_real mtt_polar_rdot_f(const mtt_real sensor[2], mtt_real gamma, mtt_real vmax, const mtt_real *xp,
                          const mtt_real *Pp, int st, const mtt_real S[3], mtt_real nx, mtt_real ny,
                          const mtt_real rr[2]);
/* mtt_polar_rdot_f of a detection against a prediction xp, Pp (a CV
 * track's, or one IMM model's, rows of MTT_MAX_STATE from &P[0][0]). */
mtt_real mtt_polar_rdot_lik(const mtt_tracker *trk, const mtt_real *xp, const mtt_real *Pp, const mtt_real S[3],
                            const mtt_mstore *ms);
/* The extended Kalman update of x (n <= 2 MTT_MAX_STATE states; P, M, T
 * rows of stride st >= n) with the range rate rr[0] of variance rr[1], the
 * target's x y vx vy at components o..o+3, linearised at x, Joseph form;
 * M receives I - K H, T is scratch.  0, or -1 (nothing done). */
int mtt_polar_rdot_step(int n, int o, int st, const mtt_real sensor[2], const mtt_real rr[2], mtt_real *x,
                        mtt_real *P, mtt_real *M, mtt_real *T);
/* mtt_polar_rdot_step of x (n <= MTT_MAX_STATE states, x y vx vy first). */
void mtt_polar_rdot_update(int n, const mtt_real sensor[2], const mtt_real rr[2], mtt_real *x, mtt_cov P);
#endif
#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
/* A detection with covariance R against the prediction Pp (a block):
 * d2 = nu' S^-1 nu (Q24), and when gc (mtt_fx_gate_consts) is not NULL
 * p = N(nu; 0, S) / (PG lambda) (Q16), when hl is not NULL ln sqrt(det S)
 * (Q24, the IMM's model weights), S = Pp_pos + R; -1 when S is not
 * positive definite. */
int mtt_meas_gauss_fx(mtt_cov Pp, const mtt_real R[3], const int32_t *gc, mtt_pos nx, mtt_pos ny, mtt_d2 *d2,
                      mtt_ratio *p, int32_t *hl);
#elif MTT_WITH_MEAS_COV
/* A detection with covariance R against a prediction whose covariance has
 * the rows p0, p1 (ALGORITHMS.md §3.1): d2 = nu' S^-1 nu and p = N(nu; 0,
 * S) / PG, S = Pp_pos + R (into S); -1 when S is not positive definite. */
int mtt_meas_gauss(const mtt_real *p0, const mtt_real *p1, const mtt_real R[3], mtt_real pg, mtt_real nx,
                   mtt_real ny, mtt_real *d2, mtt_real *p, mtt_real S[3]);
#endif
#if MTT_WITH_MEAS_COV
/* The PDA update of an n-state prediction with a covariance Rj[j] per
 * detection (§3.1); d is scratch for m corrections. */
/* rr (may be NULL): each detection's range rate and variance or NULL, an
 * EKF step after its position update (§3.2); sensor: sensor_xy. */
void mtt_kalman_pda_each(int n, const mtt_state xp, mtt_cov Pp, const mtt_real *const Rj[],
                         const mtt_real *const rr[], const mtt_real sensor[2], uint16_t m,
                         mtt_real nu[][2], const mtt_real beta[], mtt_real beta0, mtt_real d[][MTT_MAX_STATE],
                         mtt_state x, mtt_cov P);
#endif
void mtt_sym(mtt_cov P);
/* A = L D L' of the leading n x n block of A (n <= MTT_MAX_STATE; unit
 * lower L, diagonal not written): 0, or -1 when a pivot is not positive
 * and finite.  The one L D L' of the library (kalman.c). */
int mtt_ldl(int n, mtt_cov A, mtt_cov L, mtt_state d);
/* 1 when the symmetric P is positive definite with margin: every L D L'
 * pivot d_i > rel * P_ii (scale-free; rel = a few eps of mtt_real). */
int mtt_cov_ok(mtt_cov P, mtt_real rel);
/* Margins: a seeded covariance must leave room for a predict and update;
 * a track whose covariance falls below the per-frame one is numerically
 * invalid and deleted (ALGORITHMS.md §3, extended to P). */
#ifdef MTT_REAL_FIXED
/* The float build's values (1000 and 16 float epsilons) in Q30: the fixed
 * mantissas (28 bits) are finer than float's, so the same margins hold. */
#define MTT_SEED_COV_MARGIN MTT_P(1000.0 * 1.1920929e-7)
#define MTT_FRAME_COV_MARGIN MTT_P(16.0 * 1.1920929e-7)
#else
#define MTT_SEED_COV_MARGIN (MTT_R(1000.0) * MTT_REAL_EPS)
#define MTT_FRAME_COV_MARGIN (MTT_R(16.0) * MTT_REAL_EPS)
#endif
/* Solve A y = b for a symmetric positive definite A by L D L'; returns
 * d = b' A^-1 b in *d2, or -1 if A is not positive definite. */
int mtt_chol_quad(mtt_cov A, const mtt_state b, mtt_real *d2);

/* ---- manoeuvre.c: the motion that max_accel derives (ALGORITHMS.md §2.2) ---- */
enum { MTT_DERIVE_CV = 1, MTT_DERIVE_MODELS = 2, MTT_DERIVE_PI = 4, MTT_DERIVE_DV = 8 };
/* process_psd 0 and max_accel > 0: the motion follows max_accel. */
int mtt_manoeuvre_derived(const mtt_params *p);
/* Resolve in p the keys a user left out (motion auto, process_psd 0, the
 * IMM keys not given, split_dv 0) and write the derived levels to lv; p's
 * derived values are those at dT = 1 until mtt_manoeuvre_frame. */
void mtt_manoeuvre_resolve(mtt_params *p, mtt_manoeuvre *lv);
/* trk->par's derived values at this frame's dt > 0. */
void mtt_manoeuvre_frame(mtt_tracker *trk, mtt_real dt);

/* ---- predict.c: prediction, S, S^-1 and gain of every track (§2, §3, §11) ---- */
void mtt_predict_frame(mtt_tracker *trk, mtt_real dt);

/* ---- update.c: state and existence update of every track (ALGORITHMS.md §6, §7.4, §10.3) ---- */
void mtt_update_frame(mtt_tracker *trk);

#endif /* MTT_FILTER_H */
