/* SPDX-License-Identifier: BSD-3-Clause */
/* fx.h - the fixed-point kernels of src/fixed/ shared by the stages (fixed
 * point only, docs/FIXED_POINT.md; the numerics of ALGORITHMS.md §16).
 * Not installed; not part of the API.  Included through mtt_internal.h.
 * Sections "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_FIXED_FX_H
#define MTT_FIXED_FX_H

#ifdef MTT_REAL_FIXED
/* ---- fx_cov.c: block floating point of the covariances (fixed point only) ---- */
/* Largest mantissa to `top` bits (exact shifts left, rounded right). */
void mtt_fx_cov_norm(mtt_cov P, int top);
/* Headroom for a prediction over dt (Q16 frames). */
void mtt_fx_cov_fit(mtt_cov P, int32_t dt);
/* Both blocks to the larger exponent. */
void mtt_fx_cov_align(mtt_cov A, mtt_cov B);
/* Q(dt) of the CV model for sw (Q16), with the headroom of mtt_fx_cov_fit. */
void mtt_fx_cov_q(int32_t dt, int32_t sw, mtt_cov Q);
/* Mantissa m at exponent `from` re-expressed at `to` (rounded, saturated). */
int32_t mtt_fx_at(int32_t m, int from, int to);
/* Exponent of S = Pp_pos + R (R in Q16) with every entry below 2^29. */
int mtt_fx_s_exp(mtt_cov Pp, const int32_t R[3]);
/* Exponent of S^-1 = adj(S) / det with every entry below 2^28 (det > 0). */
int mtt_fx_si_exp(const int32_t S[MTT_SYM_SLOTS], int32_t det);
/* S^-1 = adj(S) / det at e(S^-1) (MTT_SYM_E(Si) set): one reciprocal of det. */
void mtt_fx_si_set(int32_t Si[MTT_SYM_SLOTS], const int32_t S[MTT_SYM_SLOTS], int32_t det);
/* nu' S^-1 nu in Q24 (saturated) for nu in the position format and S^-1 as
 * mantissas with their exponent (MTT_SYM_E). */
int32_t mtt_fx_mahal2(const int32_t Si[MTT_SYM_SLOTS], int32_t nx, int32_t ny);
/* gate.c's arithmetic (docs/FIXED_POINT.md §4): lambda V_G and
 * 1 / (2 pi sqrt(det S) PG lambda) as Q16 ratios of the declared clutter
 * density dens (Q30), that times exp(-d^2 / 2), and an upper bound of
 * sqrt(gamma s_kk) in the position format. */
int32_t mtt_fx_gate_area(int32_t gamma, int32_t det, const int32_t S[MTT_SYM_SLOTS], int32_t dens);
int32_t mtt_fx_gate_area_peak(int32_t gamma, int32_t det, const int32_t S[MTT_SYM_SLOTS], int32_t pg,
                              int32_t dens, int32_t *peak);
int32_t mtt_fx_gate_peak(int32_t det, const int32_t S[MTT_SYM_SLOTS], int32_t pg, int32_t dens);
/* The gate's per-frame factors and the per-track area and peak from them. */
void mtt_fx_gate_consts(int32_t gamma, int32_t pg, int32_t dens, int32_t gc[4]);
int32_t mtt_fx_gate_area_peak_c(const int32_t gc[4], int32_t det, const int32_t S[MTT_SYM_SLOTS], int32_t *peak);
int32_t mtt_fx_gate_lik(int32_t peak, int32_t d2);
int32_t mtt_fx_gate_width(int32_t gamma, const int32_t S[MTT_SYM_SLOTS], int k);
/* v 2^s: exact for s >= 0 (the caller keeps it below 2^31), rounded to
 * nearest for s < 0 (fx_cov.c; the PDA update and L D L' of kalman.c). */
int32_t mtt_fx_shift(int32_t v, int s);
/* The exponent at which a block at exponent e whose entries' |OR| is u has
 * its largest entry on `top` bits (u = 0: e - top). */
int mtt_fx_top_exp(int e, uint32_t u, int top);
/* |OR| of n values: its bit length is that of the largest |value|. */
uint32_t mtt_fx_or_abs(const int32_t *v, int n);
/* ln sqrt(det S) in Q24 for det S > 0 a mantissa at MTT_DET_E(S)
 * (MTT_FX_MAX for det <= 0): the IMM's model weights (imm_track.c). */
int32_t mtt_fx_half_ln_det(int32_t det, const int32_t S[MTT_SYM_SLOTS]);
/* v > 0 in Q frac as m 2^e with m in [2^29, 2^30]. */
int32_t mtt_fx_unpack(int32_t v, int frac, int *e);
#endif

#endif /* MTT_FIXED_FX_H */
