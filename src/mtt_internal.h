/* mtt_internal.h - stage functions shared by the source files and the unit
 * tests.  Not installed; not part of the API.  Sections "§N" are those of
 * docs/ALGORITHMS.md. */
#ifndef MTT_INTERNAL_H
#define MTT_INTERNAL_H

#include "mtt/mtt.h"
#include "filter/motion.h"

#define MTT_MAGIC 0x4d54545fu /* "MTT_" : set by mtt_tracker_init */
#define MTT_NONE16 ((uint16_t)0xffffu)
#define MTT_PI MTT_R(3.14159265358979323846)

/* ---- sort.c: heap sort and sift for small fixed arrays (no recursion) ---- */
typedef int (*mtt_less_fn)(const void *a, const void *b, const void *ctx);
void mtt_sort(void *base, size_t n, size_t size, mtt_less_fn less, const void *ctx);
/* Restore the heap property below node i of a heap whose root is the
 * element that is NOT less than any other ("max-heap" for `less`). */
void mtt_heap_sift(void *base, size_t n, size_t size, size_t i, mtt_less_fn less, const void *ctx);

/* Sort idx[0..n) ascending by meas[idx].x, ties by index (stable merge
 * sort, bottom-up: no recursion; tmp holds n entries).  The hot-path sort:
 * typed compares, no byte swaps. */
void mtt_sort_by_x(uint16_t *idx, uint16_t *tmp, uint16_t n, const mtt_mstore *meas);

/* CSR lists filled with first[c] as the cursor of c hold in first[c] the
 * end of c, which is the start of c + 1: shift first[0..n] back by one
 * (first[0] = 0).  A forward carry, so the compiler links no memmove. */
void mtt_csr_unshift(uint16_t *first, uint16_t n);

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
void mtt_sym(mtt_cov P);
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
/* v > 0 in Q frac as m 2^e with m in [2^29, 2^30]. */
int32_t mtt_fx_unpack(int32_t v, int frac, int *e);
#endif
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

/* ---- gate.c: gating, gate area, likelihood (ALGORITHMS.md §4) ---- */
mtt_d2 mtt_gate_gamma(mtt_prob pg); /* Q24 in the fixed build */
/* ln x, finite x > 0, without libm (gamma's log under MTT_SMALL_LOG). */
mtt_real mtt_gate_ln(mtt_real x);
mtt_real mtt_gate_volume(mtt_real gamma, mtt_real det_s);
mtt_real mtt_gate_likelihood(mtt_real d2, mtt_real det_s, mtt_real pg); /* p = N / PG */
/* Frame stage: fills trk->pairs (sorted by track, then measurement), each
 * track frame's pair range, S, gate area, has_all_amp, and the CSR lists of
 * pairs per measurement.  Needs trk->tf[].xp/Pp/S/Si/det_s/valid. */
void mtt_gate_frame(mtt_tracker *trk);

/* ---- lm_clutter.c: clutter densities (ALGORITHMS.md §5.2, §8) ---- */
mtt_ratio mtt_clutter_estimate(uint16_t m, mtt_prob pd, mtt_prob pg, mtt_prob ex_pred, mtt_ratio vg);
/* Frame stage: per-track lambda (known or ALGORITHMS.md §5.2), then pair.lam = lambda
 * (lm = 0) or the LM density lambda~ (lm = 1, ALGORITHMS.md §8.2). */
void mtt_clutter_frame(mtt_tracker *trk, int lm);

/* ---- ihpda.c: intensity order statistics and IHPDA (ALGORITHMS.md §7) ---- */
/* P_r(l | m, rho), l = 1..m, into out[0..m-1], product/recurrence form (ALGORITHMS.md §7.2). */
void mtt_ihpda_prank(uint16_t m, mtt_ratio rho, mtt_prob *out);
/* Index of row m (1-based m) of the tabulated P_r triangle. */
#define MTT_PRANK_ROW(m) (((size_t)(m) * ((size_t)(m) - 1u)) / 2u)
/* beta_j and L_j (ALGORITHMS.md §7.3) of the m candidates; prank = P_r(1..m) for
 * this m, or NULL when intensity is not used (P_r = 1/m).  rank_out (may be
 * NULL) receives the 1-based rank of each candidate.  Fixed point: L gets
 * lambda_j L_j (the quotient by lambda_j where it is read: MTT_PAIR_L). */
void mtt_ihpda_betas(mtt_prob pd, mtt_prob pg, mtt_ratio vg, const mtt_prob *prank,
                     const mtt_cand *c, uint16_t m, mtt_prob *beta, mtt_ratio *L, uint8_t *rank_out);
/* A pair's IHPDA L_j as the update reads it. */
#ifdef MTT_REAL_FIXED
#define MTT_PAIR_L(pp) MTT_DIV_R((pp)->L, (pp)->lam)
#else
#define MTT_PAIR_L(pp) ((pp)->L)
#endif
/* Compute the IHPDA row of track ti over its gated pairs: with excl_used,
 * pairs whose measurement is used (assigned) are left out, except the pair
 * index `keep`.  Writes pair.beta and pair.L (beta 0 for pairs left out);
 * returns the number of candidates m; *best gets the argmax pair index (-1
 * when m = 0) under the tie rule `rule` (0: lowest measurement index,
 * ALGORITHMS.md §10.1; 1: smaller rank, then lower index, ALGORITHMS.md §7.4). */
uint16_t mtt_ihpda_row(mtt_tracker *trk, uint16_t ti, int excl_used, int16_t keep, int rule,
                       int16_t *best);
/* Amplitude likelihood ratio of amplitude a against the background law
 * (ALGORITHMS.md §7.6): g = exp(a rho/(1+rho))/(1+rho) (exponent clamped at
 * 30), returned as g/(1 - eta + eta g); rho = 0 gives 1, eta = 0 the plain g. */
mtt_real mtt_amp_ratio(mtt_real rho, mtt_real eta, mtt_real a);
/* The `ihpda` association: each valid track selects on its full gate
 * (tie rule 1); the selected measurements are marked used. */
void mtt_ihpda_select_frame(mtt_tracker *trk);
/* Final recomputation (ALGORITHMS.md §10.3) of every assigned track's row over G
 * minus the measurements assigned to other tracks, when that set changed
 * or the contest test wrote over the row; never for a contested track. */
void mtt_ihpda_final_frame(mtt_tracker *trk);

/* lm-ihpda with lm_ihpda_variant contest (ALGORITHMS.md §7.6, §10.4): the
 * amplitude ratio in p, the amplitude rows and the contest-aware update.
 * Not with motion imm: the contest update has no IMM form yet, so an IMM
 * lm-ihpda runs [S0] whatever the variant.  Constant 0 with
 * MTT_WITH_CONTEST 0, so the compiler drops that code. */
#define MTT_CONTEST_ON(trk)                                                                        \
    (MTT_WITH_CONTEST && (trk)->par.association == MTT_ASSOC_LM_IHPDA &&                           \
     (trk)->par.lm_ihpda_variant == MTT_LM_IHPDA_CONTEST && (trk)->par.motion != MTT_MOTION_IMM)

/* ---- contest.c: the contest test of lm-ihpda contest (ALGORITHMS.md §10.4) ---- */
/* tf.contest of a track: no LM-IPDA row this frame (its IHPDA row stands),
 * an LM-IPDA row written over its pairs but not contested (the final
 * recomputation rewrites the IHPDA row), or contested (PDA update with
 * that row). */
enum { MTT_CONTEST_NONE = 0, MTT_CONTEST_ROW = 1, MTT_CONTEST_YES = 2 };
/* tf.contest tests, constant 0 with MTT_WITH_CONTEST 0 (the field stays NONE). */
#define MTT_CONTESTED(tf) (MTT_WITH_CONTEST && (tf)->contest == MTT_CONTEST_YES)
#define MTT_CONTEST_ROW_WRITTEN(tf) (MTT_WITH_CONTEST && (tf)->contest == MTT_CONTEST_ROW)
/* After MMR: the LM-IPDA row (pair.beta, tf.beta0, tf.ex_post) of every
 * track of a cluster with two or more tracks, then tf.contest. */
void mtt_contest_frame(mtt_tracker *trk);

/* ---- adapt_q.c: a confirmed contest track's process-noise scale (ALGORITHMS.md §2.1) ---- */
#if MTT_WITH_CONTEST
/* The CV prediction with s Q (Q is read, not changed). */
void mtt_adapt_predict(mtt_real dt, mtt_cov Q, mtt_real s, const mtt_state x, mtt_cov P,
                       mtt_state xp, mtt_cov Pp);
/* The lowest scale for an interval dt: max(adapt_s_min, Lambda^2 / adapt_index), at most 1. */
mtt_real mtt_adapt_floor(const mtt_tracker *trk, mtt_real dt);
/* E[NIS] of a gated target detection: chi-square 2 truncated at gamma. */
mtt_real mtt_adapt_nis_mean(mtt_real gamma, mtt_real pg);
/* After track ti's update: its NIS average and scale s (tentative,
 * contested and s0 tracks keep s = 1 / theirs). */
void mtt_adapt_observe(mtt_tracker *trk, uint16_t ti);
#endif
/* ---- params.c ---- */
#if MTT_WITH_IMM
/* imm_transition and imm_initial: docs/FORMATS.md's defaults for r models. */
void mtt_params_imm_reset(mtt_params *p, uint8_t r);
/* Index of the first cv model of imm_models, imm_n_models when there is none
 * (the model the split modes build on, ALGORITHMS.md §14.3). */
uint8_t mtt_params_cv_model(const mtt_params *p);
#endif

/* ---- ipda.c: IPDA (ALGORITHMS.md §6) ---- */
/* beta_j of the m gated pairs pp[0..m) (from their p and lam) into their
 * beta; beta_0 and L. */
void mtt_ipda_betas(mtt_prob pd, mtt_prob pg, mtt_pair *pp, uint16_t m, mtt_prob *beta0, mtt_ratio *L);
/* IPDA row of track ti over its gate: pair.beta, tf.beta0 and the updated
 * existence tf.ex_post. */
void mtt_ipda_track(mtt_tracker *trk, uint16_t ti);
/* mtt_ipda_track for every valid track with a non-empty gate: the ipda /
 * lm-ipda association. */
void mtt_ipda_frame(mtt_tracker *trk);

/* ---- existence.c: Markov chain one and the existence update (ALGORITHMS.md §11, §6) ---- */
mtt_prob mtt_existence_predict(mtt_prob p, mtt_prob p11, mtt_prob p21);
mtt_prob mtt_existence_update(mtt_prob ex_pred, mtt_ratio L);

/* ---- cluster.c: clusters by union-find (ALGORITHMS.md §9) ---- */
void mtt_cluster_frame(mtt_tracker *trk);

/* ---- mmr.c: MMR assignment with recomputation (ALGORITHMS.md §10.1) ---- */
/* Assigns within cluster c; recompute = 0 runs the static greedy on the
 * pair.beta values as they are (ALGORITHMS.md §10.1 without recomputation, TV9). */
void mtt_mmr_cluster(mtt_tracker *trk, uint16_t c, int recompute);

/* ---- assign2d.c: optimal 2-D assignment (ALGORITHMS.md §10.2) ---- */
/* Fills w[0..m-1] with the weights (>= 0; 0 = not allowed) of row r. */
typedef void (*mtt_row_fn)(const void *ctx, uint16_t r, mtt_real *w);
/* Maximise sum of w over a one-to-one matching of n rows (n <=
 * MTT_MAX_ASSIGN_TRACKS) to m columns (m + n <= MTT_ASSIGN_COLS), by the
 * Hungarian method with one dummy column per row; zero-weight matches are
 * dropped.  Result: s->col_row[r] = column or -1.  Cost O(n^2 (m + n)). */
void mtt_assign2d_solve(mtt_assign_scratch *s, uint16_t n, uint16_t m, mtt_row_fn fill,
                        const void *ctx);
/* ihpda-2d, cluster c: static IHPDA rows over the full gates, optimal
 * assignment on w = beta + (n_c + 1); clusters over MTT_MAX_ASSIGN_TRACKS
 * use MMR with recomputation.  Sets tf.assigned and meas.used. */
void mtt_assign2d_cluster(mtt_tracker *trk, uint16_t c);
void mtt_assign2d_frame(mtt_tracker *trk);

/* ---- jpda.c: exact JPDA, JPDA*, JIPDA (ALGORITHMS.md §13.1, §13.2, §13.6) ---- */
enum { MTT_JPDA_EXACT = 0, MTT_JPDA_STAR = 1, MTT_JPDA_JIPDA = 2 };
/* Per frame: jp.pa (A of each pair), jp.tb (B of each track), tf.beta0 = 1
 * (ALGORITHMS.md §13). */
void mtt_jpda_weights(mtt_tracker *trk);
/* Exact enumeration over cluster c; kind = MTT_JPDA_*.  Writes pair.beta,
 * tf.beta0 (and tf.ex_post for JIPDA).  Returns 0, or -1 (nothing written)
 * when the cluster exceeds MTT_MAX_JPDA_TRACKS / _MEAS / _EVENTS. */
int mtt_jpda_exact(mtt_tracker *trk, uint16_t c, int kind);

/* ---- jpda_approx.c: Cheap and Suboptimal JPDA (ALGORITHMS.md §13.3, §13.4) ---- */
void mtt_cheap_jpda(mtt_tracker *trk, uint16_t c, int normalise);
/* per_track_b: the library's B_t of ALGORITHMS.md §13.4 (1) or the constant B (0). */
void mtt_subopt_jpda(mtt_tracker *trk, uint16_t c, int per_track_b);

/* ---- nnjpda.c: NNJPDA (ALGORITHMS.md §13.5) ---- */
/* Static MMR on the betas of cluster c with the nnjpda threshold. */
void mtt_nnjpda_cluster(mtt_tracker *trk, uint16_t c);

/* ---- jpda_adaptive.c: adaptive JPDA (ALGORITHMS.md §13.7) ---- */
/* Before gating: tf.shrink = 1 for tracks that overlap another track. */
void mtt_adaptive_gates(mtt_tracker *trk);
/* After the JPDA betas of cluster c: equal split for shared measurements. */
void mtt_adaptive_split(mtt_tracker *trk, uint16_t c);

/* ---- associate.c: the association stage and the mode table (ALGORITHMS.md §15.1) ---- */
enum { MTT_UPDATE_ONE = 0, MTT_UPDATE_PDA = 1, MTT_UPDATE_HARD = 2 };
/* The association routine of a mode (associate.c's switch). */
enum {
    MTT_ASSOCIATE_MMR = 0, MTT_ASSOCIATE_SELECT, MTT_ASSOCIATE_IPDA, MTT_ASSOCIATE_ASSIGN_2D,
    MTT_ASSOCIATE_JIPDA, MTT_ASSOCIATE_JPDA, MTT_ASSOCIATE_CHEAP_JPDA, MTT_ASSOCIATE_SUBOPT_JPDA,
    MTT_ASSOCIATE_NNJPDA, MTT_ASSOCIATE_JPDA_STAR, MTT_ASSOCIATE_ADAPTIVE_JPDA
};
/* One association mode.  update: what the update stage does with the
 * association's result -- ONE: the single assigned / selected pair with its
 * beta and L (ALGORITHMS.md §7.4); PDA: every gated pair with the beta row, beta_0 and
 * tf.ex_post (ALGORITHMS.md §6, §13.8); HARD: the assigned pair with beta 1 and
 * tf.ex_post (ALGORITHMS.md §13.5). */
typedef struct mtt_mode {
    uint8_t associate;                    /* MTT_ASSOCIATE_*: the routine, after clustering */
    uint8_t lm;                           /* LM clutter densities (ALGORITHMS.md §8) */
    uint8_t update;                       /* MTT_UPDATE_* */
    uint8_t baseline;                     /* a comparison baseline (MTT_WITH_BASELINES) */
    uint8_t imm;                          /* runs with motion = imm (ALGORITHMS.md §14.2) */
} mtt_mode;
extern const mtt_mode mtt_modes[MTT_ASSOC_COUNT];
/* Clusters, then the mode's association; PDA modes mark every gated
 * measurement used. */
void mtt_associate_frame(mtt_tracker *trk);

/* ---- update.c: state and existence update of every track (ALGORITHMS.md §6, §7.4, §10.3) ---- */
void mtt_update_frame(mtt_tracker *trk);

/* ---- initiate.c: two-point initiation (ALGORITHMS.md §12.1, §12.2) ---- */
#ifndef MTT_REAL_FIXED /* the intensity gate: not in the fixed-point build */
mtt_real mtt_init_intensity_f(const mtt_params *p, mtt_real I);
#endif
/* Velocity/intensity gate of a pair (a at k-1, b at k); 1 = accept. */
int mtt_init_pair_ok(const mtt_tracker *trk, const mtt_mstore *a, const mtt_mstore *b, mtt_real dt);
void mtt_initiate_frame(mtt_tracker *trk, mtt_real dt);

/* ---- merge.c: track merging (ALGORITHMS.md §12.3) ---- */
/* d^2 of two states; returns -1 when P_a + P_b is not positive definite. */
int mtt_merge_d2(const mtt_track *a, const mtt_track *b, mtt_d2 *d2);
void mtt_merge_frame(mtt_tracker *trk);

/* ---- measure.c: validation and selection of the frame's measurements (§15) ---- */
void mtt_measure_select(mtt_tracker *trk, const mtt_meas *meas, size_t n);

/* ---- predict.c: prediction, S, S^-1 and gain of every track (§2, §3, §11) ---- */
void mtt_predict_frame(mtt_tracker *trk, mtt_real dt);

/* ---- track_table.c: the track table (§12.4) ---- */
/* Append a track; returns its index or -1 when the table is full. */
int mtt_track_append(mtt_tracker *trk, const mtt_state x, mtt_cov P, mtt_real existence,
                     int confirmed, int born);
/* End of frame: delete, confirm, compact. */
void mtt_track_manage(mtt_tracker *trk);
/* The CV part of P as the API gives it: 4 x 4, in the fixed build in the
 * variance format (MTT_COV_VIEW); P is only read. */
void mtt_cov_view4(mtt_cov P, mtt_real out[4][4]);

/* ==== Split targets (ALGORITHMS.md §14.3): split.c ======================
 * Built with MTT_WITH_SPLIT (include/mtt/config.h).  Plain functions over
 * arrays.  A single-target model has n components (4 <= n <=
 * MTT_MAX_STATE, position first); the stacked split state is [x_1; x_2]
 * (2n components in MTT_SPLIT_STATE storage), target 1 the parent, target
 * 2 the child.  Likelihoods are ratios to the all-clutter density V^-m of
 * the m validated measurements (the scale of the IPDA likelihood ratio,
 * ALGORITHMS.md §14.2).  Functions return 0, or -1 on invalid arguments
 * or a covariance that is not positive definite (nothing written). */
#if MTT_WITH_SPLIT
/* chi-square 0.99 quantile, 2 degrees of freedom: -2 ln 0.01 ([S3] eq. 27) */
#define MTT_SPLIT_CHI2_99 MTT_R(9.2103403719761836)
/* mtt_split_state, mtt_split_cov, mtt_split_assoc, mtt_split_work: mtt/state.h
 * (tracker scratch).  mtt_split_predict, mtt_split_just, mtt_split_update
 * and mtt_split_separate take their work matrices from wk (the caller's: the split stage's
 * scratch), so that no 12 x 12 matrix is on the stack. */

/* One target's (x, P) as a stacked state: [x; x], [[P, P], [P, P]] (the
 * two targets of a split start from the one estimate, [S3] eq. 5, 11). */
int mtt_split_stack(uint8_t n, const mtt_real x[], mtt_real P[][MTT_MAX_STATE], mtt_split_state xs,
                    mtt_split_cov Ps);
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
                   const mtt_real R[3], uint16_t m, mtt_real z[][2], const mtt_real beta[],
                   mtt_real vg, mtt_split_state xs, mtt_split_cov Ps, uint8_t cluster[],
                   mtt_real beta_n[], mtt_real *lik);

/* Per-target gates (d^2 <= gamma with S_t = H P_tt H' + R) and the event
 * factors a, b.  lam = 0: non-parametric ([S3] eq. 14, V = vg; lik is the
 * ratio to V^-m); lam > 0: Poisson clutter of known density lam (the
 * detection factor is PD N / lam, no factorials; lik is the ratio to the
 * all-clutter density, the scale of the IPDA L of ALGORITHMS.md §6). */
int mtt_split_assoc_init(uint8_t n, const mtt_split_state xps, mtt_split_cov Pps, const mtt_real R[3],
                         uint16_t m, mtt_real z[][2], mtt_real pd, mtt_real pg,
                         mtt_real gamma, mtt_real vg, mtt_real lam, mtt_split_assoc *as);
/* Option (ALGORITHMS.md §14.3 as written uses the product of the
 * marginals): events in which both targets are detected weigh the joint
 * density N([z_j1; z_j2]; zhat^s, S^s) with S^s = H^s Pps H^s' + R^s (the
 * cross covariance of the coupled filter) instead of N_1 N_2.  Call after
 * mtt_split_assoc_init with the same Pps and R. */
int mtt_split_assoc_coupled(mtt_split_assoc *as, mtt_split_cov Pps, const mtt_real R[3]);
/* Unnormalised weight of the joint event (j1, j2) (measurement index of
 * target 1 and 2, -1 = undetected): (phi!/m!) prod PD V N prod (1 - PD PG);
 * 0 when infeasible. */
mtt_real mtt_split_event_weight(const mtt_split_assoc *as, int16_t j1, int16_t j2);
/* Normalise over every event: lik, beta, beta_miss, beta0. */
int mtt_split_joint(mtt_split_assoc *as);
/* Coupled update of the stacked state (ALGORITHMS.md §14.3, corrected
 * bracket of [S3] eq. 25), after mtt_split_joint. */
int mtt_split_update(mtt_split_work *wk, const mtt_split_assoc *as, const mtt_split_state xps,
                     mtt_split_cov Pps, const mtt_real R[3], mtt_real z[][2], mtt_split_state xs,
                     mtt_split_cov Ps);
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
                    const mtt_real R[3], uint16_t m, mtt_real z[][2], const uint8_t cluster[],
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

/* ==== IMM (ALGORITHMS.md §14): imm.c, motion_ca.c, motion_ct.c ==========
 * Built with MTT_WITH_IMM (include/mtt/config.h).  Plain functions over
 * arrays; model j has n[j] components, the first four [x y vx vy] (the
 * common subspace).  Matrices of r models: mtt_real P[r][MTT_MAX_STATE]
 * [MTT_MAX_STATE]; transition Pi[i][j] = P(mode j at k | mode i at k-1). */
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
int mtt_imm_mix(uint8_t r, const uint8_t n[], mtt_real mix[][MTT_MAX_MODELS],
                mtt_real x[][MTT_MAX_STATE], mtt_real P[][MTT_MAX_STATE][MTT_MAX_STATE],
                mtt_real x0[][MTT_MAX_STATE], mtt_real P0[][MTT_MAX_STATE][MTT_MAX_STATE]);
/* μ_j = Λ_j c̄_j / c (§14.1); returns c = Σ_j Λ_j c̄_j, which is the IPDA L
 * of the existence update (§14.2).  c not positive and finite: μ = c̄,
 * returns 0; r out of range: returns 0, μ untouched. */
mtt_real mtt_imm_mode_update(uint8_t r, const mtt_real cbar[], const mtt_real lam[], mtt_real mu[]);
/* Combined 4-D estimate Σ μ_j x_j,c and its covariance with the spread
 * term (§14.1), into the leading 4 entries of xc and 4 x 4 block of Pc;
 * the extras are not part of it.  Returns 0 or -1 (r). */
int mtt_imm_combine(uint8_t r, const mtt_real mu[], mtt_real x[][MTT_MAX_STATE],
                    mtt_real P[][MTT_MAX_STATE][MTT_MAX_STATE], mtt_real xc[], mtt_real Pc[][MTT_MAX_STATE]);
/* Model-mixed detection probability PD* = Σ c̄_j PD_j (into *pd_mix) and
 * model-mixed likelihood of one measurement p* = Σ c̄_j PD_j p_j / PD*
 * (p_j: its gate-normalised likelihood under model j; 0 when PD* = 0 or
 * r is out of range).
 * Every association mode runs on (PD*, p*) in place of (PD, p). */
mtt_real mtt_imm_meas_mix(uint8_t r, const mtt_real cbar[], const mtt_real pd[], const mtt_real p[],
                          mtt_real *pd_mix);
/* Split a track-level association result (β_0, β_i of m measurements,
 * conditioned on existence) into mode probabilities μ_j and per-model
 * association probabilities beta0_j[j], beta_j[j][i]:
 *   P(θ_0, M_j) = β_0 c̄_j e0[j] / Σ_k c̄_k e0[k]
 *   P(θ_i, M_j) = β_i c̄_j e[i][j] / Σ_k c̄_k e[i][k]
 *   μ_j = Σ_θ P(θ, M_j),  beta_j = P(θ, M_j) / μ_j
 * with e0[j] = 1 - PD_j PG, e[i][j] = PD_j p_i^j for the PDA modes, and
 * e0[j] = C^j, e[s][j] = A^j of the selected measurement (m = 1) for the
 * IHPDA modes.  Returns 0 or -1 (r or m out of range). */
int mtt_imm_split(uint8_t r, const mtt_real cbar[], uint16_t m, mtt_real beta0,
                  const mtt_real beta[], const mtt_real e0[], mtt_real e[][MTT_MAX_MODELS],
                  mtt_real mu[], mtt_real beta0_j[], mtt_real beta_j[][MTT_MAX_GATED]);
/* motion_ca.c: nearly constant acceleration, [x y vx vy ax ay], white-noise
 * jerk of PSD q (length^2/time^5).  Per axis [p v a] (3x3), and the full
 * 6x6 F and Q in the top-left of MTT_MAX_STATE-sized storage. */
#define MTT_CA_N 6
void mtt_ca_axis(mtt_real dt, mtt_real q, mtt_real F[3][3], mtt_real Q[3][3]);
void mtt_ca_model(mtt_real dt, mtt_real q, mtt_real F[][MTT_MAX_STATE], mtt_real Q[][MTT_MAX_STATE]);
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
/* imm_track.c: the IMM stages of track ti (motion = imm). */
/* Mixing, every model's prediction and innovation, the combined
 * prediction in tf.xp/Pp/S/Si/K; returns 1 when every S is valid. */
int mtt_imm_predict_track(mtt_tracker *trk, uint16_t ti, mtt_real dt);
/* Half-widths of the window around tf.xp that holds every model's gate. */
void mtt_imm_gate_window(const mtt_tracker *trk, uint16_t ti, mtt_real *wx, mtt_real *wy);
/* min_j d_j^2 of a measurement (the union gate tests it against gamma). */
mtt_real mtt_imm_gate_d2(const mtt_tracker *trk, uint16_t ti, mtt_real zx, mtt_real zy);
/* The model-mixed likelihood p* of a measurement (ALGORITHMS.md §14.2). */
mtt_real mtt_imm_gate_p(const mtt_tracker *trk, uint16_t ti, mtt_real zx, mtt_real zy);
/* Split the track's association result (m pairs from `first`, their beta,
 * beta0) into mode probabilities and per-model betas, update every model,
 * combine into t.x, t.P (ALGORITHMS.md §14.2). */
void mtt_imm_update_track(mtt_tracker *trk, uint16_t ti, uint16_t first, uint16_t m,
                          const mtt_real beta[], mtt_real beta0);
/* Existence L of an IHPDA-mode IMM track with selected pair a: the
 * c̄-mixture of every model's own-gate IHPDA L (ALGORITHMS.md §14.2). */
mtt_real mtt_imm_exist_L(mtt_tracker *trk, uint16_t ti, uint16_t a);
/* Model states of a new track from its 4-D x, P; dt the two-point interval. */
void mtt_imm_seed_track(mtt_tracker *trk, uint16_t ti, mtt_real dt);
#endif /* MTT_WITH_IMM */

#endif /* MTT_INTERNAL_H */
