/* SPDX-License-Identifier: BSD-3-Clause */
/* imm.h - interacting multiple models (ALGORITHMS.md §14), built with
 * MTT_WITH_IMM.  Not installed; not part of the API.  Included through
 * mtt_internal.h.  Sections "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_IMM_H
#define MTT_IMM_H

/* ==== IMM (ALGORITHMS.md §14): imm.c, motion_ca.c, motion_ct.c ==========
 * Built with MTT_WITH_IMM (include/mtt/config.h).  Plain functions over
 * arrays; model j has n[j] components, the first four [x y vx vy] (the
 * common subspace).  Matrices of r models: mtt_cov P[r] (fixed point:
 * each with its block exponent); transition Pi[i][j] = P(mode j at k |
 * mode i at k-1).  The fixed-point build has cv models only (n = 4). */
#define MTT_IMM_COMMON 4
#if MTT_WITH_IMM
/* c̄_j = Σ_i Pi[i][j] μ_i and mix[i][j] = μ_{i|j} (§14.1); a mode with
 * c̄_j = 0 gets mix[.][j] = e_j.  Returns 0, or -1 when r is out of range. */
int mtt_imm_mix_weights(uint8_t r, mtt_real Pi[][MTT_MAX_MODELS], const mtt_real mu[],
                        mtt_real cbar[], mtt_real mix[][MTT_MAX_MODELS]);
/* Mixed starts x0[j], P0[j] (§14.1, common subspace; the extras of model j
 * keep their own mean and block, their cross-covariance with the common
 * part is scaled by μ_{j|j}: see imm.c).  Returns 0, or -1 on r or n[] out
 * of range (nothing written). */
int mtt_imm_mix(uint8_t r, const uint8_t n[], mtt_real mix[][MTT_MAX_MODELS], mtt_real x[][MTT_MAX_STATE],
                mtt_cov P[], mtt_real x0[][MTT_MAX_STATE], mtt_cov P0[]);
/* Combined 4-D estimate Σ μ_j x_j,c and its covariance with the spread
 * term (§14.1), into the leading 4 entries of xc and 4 x 4 block of Pc;
 * the extras are not part of it.  Returns 0 or -1 (r). */
int mtt_imm_combine(uint8_t r, const mtt_real mu[], mtt_real x[][MTT_MAX_STATE], mtt_cov P[], mtt_real xc[],
                    mtt_real Pc[][MTT_MAX_STATE]);
/* Model-mixed detection probability PD* = Σ c̄_j PD_j (into *pd_mix) and
 * model-mixed likelihood of one measurement p* = Σ c̄_j PD_j p_j / PD*
 * (p_j: its gate-normalised likelihood under model j; 0 when PD* = 0 or
 * r is out of range).
 * Every association mode runs on (PD*, p*) in place of (PD, p). */
mtt_real mtt_imm_meas_mix(uint8_t r, const mtt_real cbar[], const mtt_real pd[], const mtt_real p[],
                          mtt_real *pd_mix);
/* Apportion a track-level association result (β_0, β_i of m measurements,
 * conditioned on existence) into mode probabilities μ_j and per-model
 * association probabilities beta0_j[j], beta_j[j][i]:
 *   P(θ_0, M_j) = β_0 c̄_j e0[j] / Σ_k c̄_k e0[k]
 *   P(θ_i, M_j) = β_i c̄_j e[i][j] / Σ_k c̄_k e[i][k]
 *   μ_j = Σ_θ P(θ, M_j),  beta_j = P(θ, M_j) / μ_j
 * with e0[j] = 1 - PD_j PG, e[i][j] = PD_j p_i^j for the PDA modes, and
 * e0[j] = C^j, e[s][j] = A^j of the selected measurement (m = 1) for the
 * IHPDA modes.  Returns 0 or -1 (r or m out of range). */
int mtt_imm_apportion(uint8_t r, const mtt_real cbar[], uint16_t m, mtt_real beta0,
                  const mtt_real beta[], const mtt_real e0[], mtt_real e[][MTT_MAX_MODELS],
                  mtt_real mu[], mtt_real beta0_j[], mtt_real beta_j[][MTT_MAX_GATED]);
#if MTT_WITH_IMM_CACT
/* motion_ca.c: nearly constant acceleration, [x y vx vy ax ay], white-noise
 * jerk of PSD q (length^2/time^5).  Per axis [p v a] (3x3), and the full
 * 6x6 F and Q in the top-left of MTT_MAX_STATE-sized storage. */
#define MTT_CA_N 6
void mtt_ca_axis(mtt_real dt, mtt_real q, mtt_real F[3][3], mtt_real Q[3][3]);
/* xp = F x, Pp = F P F' + Q of the CA model (Pp symmetric by construction);
 * in place (xp = x, Pp = P) allowed. */
void mtt_ca_predict(mtt_real dt, mtt_real q, const mtt_real x[], mtt_real P[][MTT_MAX_STATE],
                    mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE]);
/* motion_ct.c: coordinated turn, [x y vx vy w].  xp = f(x) and the
 * Jacobian F = df/dx at x (extended Kalman prediction); Q: CV white-noise
 * acceleration (PSD sw) on [x y vx vy], sw_turn T on w. */
#define MTT_CT_N 5
void mtt_ct_f(mtt_real dt, const mtt_real x[MTT_CT_N], mtt_real xp[MTT_CT_N], mtt_real F[][MTT_MAX_STATE]);
void mtt_ct_q(mtt_real dt, mtt_real sw, mtt_real sw_turn, mtt_real Q[][MTT_MAX_STATE]);
/* Extended Kalman prediction: xp = f(x), Pp = F P F' + Q (symmetric by
 * construction); in place (xp = x, Pp = P) allowed. */
void mtt_ct_predict(mtt_real dt, mtt_real sw, mtt_real sw_turn, const mtt_real x[], mtt_real P[][MTT_MAX_STATE],
                    mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE]);
#endif
/* imm_track.c: the IMM stages of track ti (motion = imm). */
/* Mixing, every model's prediction and innovation, the combined
 * prediction in tf.xp/Pp/S/Si/K; returns 1 when every S is valid. */
int mtt_imm_predict_track(mtt_tracker *trk, uint16_t ti, mtt_real dt);
/* Half-widths of the window around tf.xp that holds every model's gate. */
void mtt_imm_gate_window(const mtt_tracker *trk, uint16_t ti, mtt_real *wx, mtt_real *wy);
/* min_j d_j^2 of a measurement (the union gate tests it against gamma). */
mtt_real mtt_imm_gate_d2(const mtt_tracker *trk, uint16_t ti, const mtt_mstore *ms);
/* The model-mixed likelihood p* of a measurement (ALGORITHMS.md §14.2). */
mtt_real mtt_imm_gate_p(const mtt_tracker *trk, uint16_t ti, const mtt_mstore *ms);
/* d^2 of detection ms under model j (and, p not NULL, *p = N(nu; 0, S_j) /
 * PG), with its own R when it has one (ALGORITHMS.md §3.1). */
mtt_real mtt_imm_model_d2(const mtt_tracker *trk, const mtt_track_frame *tf, uint8_t j, const mtt_mstore *ms,
                          mtt_real *p);
/* Apportion the track's association result (m pairs from `first`, their beta,
 * beta0) into mode probabilities and per-model betas, update every model,
 * combine into t.x, t.P (ALGORITHMS.md §14.2). */
void mtt_imm_update_track(mtt_tracker *trk, uint16_t ti, uint16_t first, uint16_t m,
                          const mtt_real beta[], mtt_real beta0);
/* The update stage of IMM track ti (update.c, ALGORITHMS.md §14.2): the
 * mode's result -- the assigned pair with beta_s and L_s (kind ONE), or
 * the beta row, beta_0 and tf.ex_post (PDA) -- apportioned over the
 * models; existence as the mode gives it, with the IHPDA modes' L mixed
 * over the models' own gates (mtt_imm_exist_L). */
void mtt_imm_update_assoc(mtt_tracker *trk, uint16_t ti, uint8_t kind);
/* Existence L of an IHPDA-mode IMM track with selected pair a: the
 * c̄-mixture of every model's own-gate IHPDA L (ALGORITHMS.md §14.2). */
mtt_real mtt_imm_exist_L(mtt_tracker *trk, uint16_t ti, uint16_t a);
/* Model states of a new track from its 4-D x, P; dt the two-point interval. */
void mtt_imm_seed_track(mtt_tracker *trk, uint16_t ti, mtt_real dt);
#endif /* MTT_WITH_IMM */

#endif /* MTT_IMM_H */
