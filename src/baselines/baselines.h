/* SPDX-License-Identifier: BSD-3-Clause */
/* baselines.h - the comparison baselines: 2-D assignment and the JPDA family
 * (ALGORITHMS.md §10.2, §13), built with MTT_WITH_BASELINES.  Not installed;
 * not part of the API.  Included through mtt_internal.h.  Sections "§N" are
 * those of docs/ALGORITHMS.md. */
#ifndef MTT_BASELINES_H
#define MTT_BASELINES_H

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

/* ---- jpda_adaptive.c: adaptive JPDA and the gate-change variants (ALGORITHMS.md §13.7) ---- */
/* Before gating: tf.shrink = 1 for tracks that overlap another track. */
void mtt_adaptive_gates(mtt_tracker *trk);
/* After the JPDA betas of cluster c: equal shares of the shared measurements. */
void mtt_adaptive_share(mtt_tracker *trk, uint16_t c);

/* ---- lm_all.c: the all-tracks LM density of lm-ipda-all (ALGORITHMS.md §8.3) ---- */
/* After §8.2's pass 2: adds to every pair's lambda~ the terms of the tracks
 * that do not gate its measurement (untruncated Gaussians); uses trk->wsum. */
void mtt_lm_all_frame(mtt_tracker *trk);

#endif /* MTT_BASELINES_H */
