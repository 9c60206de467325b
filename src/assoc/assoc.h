/* SPDX-License-Identifier: BSD-3-Clause */
/* assoc.h - the association layer: gating, clutter densities, IHPDA, IPDA,
 * clusters, MMR and the association stage (ALGORITHMS.md §4 to §10).  Not
 * installed; not part of the API.  Included through mtt_internal.h.  Sections
 * "§N" are those of docs/ALGORITHMS.md. */
#ifndef MTT_ASSOC_H
#define MTT_ASSOC_H

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
#if MTT_WITH_MEAS_COV && !defined(MTT_REAL_FIXED)
/* A detection with its own R against the prediction xp, Pp (rows of
 * MTT_MAX_STATE): d^2, and p = N / PG times its range rate's ratio
 * (ALGORITHMS.md §3.1, §3.2); MTT_REAL_MAX and p = 0 when S is not
 * positive definite or the range rate is outside its gate. */
mtt_real mtt_gate_own(const mtt_tracker *trk, const mtt_real *xp, const mtt_real *Pp, const mtt_mstore *ms,
                      mtt_real *p);
/* A gate window's half-widths wx, wy (sqrt(gamma S) per axis) widened for
 * the frame's detections with a wider R of their own (ALGORITHMS.md §3.1). */
void mtt_gate_own_widen(const mtt_tracker *trk, mtt_real gamma, mtt_real *wx, mtt_real *wy);
#endif

/* ---- lm_clutter.c: clutter densities (ALGORITHMS.md §5.2, §8) ---- */
mtt_ratio mtt_clutter_estimate(uint16_t m, mtt_prob pd, mtt_prob pg, mtt_prob ex_pred, mtt_ratio vg);
/* Frame stage: per-track lambda (known or ALGORITHMS.md §5.2), then pair.lam = lambda
 * (lm = 0) or the LM density lambda~ (lm = 1, ALGORITHMS.md §8.2; lm = 2: over
 * all tracks, §8.3, baselines/lm_all.c). */
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
/* The `ihpda` association: each valid track selects on its full gate
 * (tie rule 1); the selected measurements are marked used. */
void mtt_ihpda_select_frame(mtt_tracker *trk);
/* Final recomputation (ALGORITHMS.md §10.3) of every assigned track's row over G
 * minus the measurements assigned to other tracks, when that set changed
 * or the contest test wrote over the row; never for a contested track. */
void mtt_ihpda_final_frame(mtt_tracker *trk);

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

/* ---- cluster.c: clusters by union-find (ALGORITHMS.md §9) ---- */
void mtt_cluster_frame(mtt_tracker *trk);

/* ---- mmr.c: MMR assignment with recomputation (ALGORITHMS.md §10.1) ---- */
/* Assigns within cluster c; recompute = 0 runs the static greedy on the
 * pair.beta values as they are (ALGORITHMS.md §10.1 without recomputation, TV9). */
void mtt_mmr_cluster(mtt_tracker *trk, uint16_t c, int recompute);

/* ---- associate.c: the association stage and the mode table (ALGORITHMS.md §15.1) ---- */
enum { MTT_UPDATE_ONE = 0, MTT_UPDATE_PDA = 1, MTT_UPDATE_HARD = 2 };
/* The association routine of a mode (associate.c's switch). */
enum {
    MTT_ASSOCIATE_MMR = 0, MTT_ASSOCIATE_SELECT, MTT_ASSOCIATE_IPDA, MTT_ASSOCIATE_ASSIGN_2D,
    MTT_ASSOCIATE_JIPDA, MTT_ASSOCIATE_JPDA, MTT_ASSOCIATE_CHEAP_JPDA, MTT_ASSOCIATE_SUBOPT_JPDA,
    MTT_ASSOCIATE_NNJPDA, MTT_ASSOCIATE_JPDA_STAR,
    /* from here on, the routines with adaptive JPDA's gate shrink (ALGORITHMS.md §13.7) */
    MTT_ASSOCIATE_ADAPTIVE_JPDA, MTT_ASSOCIATE_JPDA_VG, MTT_ASSOCIATE_ADAPTIVE_NNJPDA,
    MTT_ASSOCIATE_ADAPTIVE_JPDA_STAR
};
/* One association mode.  update: what the update stage does with the
 * association's result -- ONE: the single assigned / selected pair with its
 * beta and L (ALGORITHMS.md §7.4); PDA: every gated pair with the beta row, beta_0 and
 * tf.ex_post (ALGORITHMS.md §6, §13.8); HARD: the assigned pair with beta 1 and
 * tf.ex_post (ALGORITHMS.md §13.5). */
typedef struct mtt_mode {
    uint8_t associate;                    /* MTT_ASSOCIATE_*: the routine, after clustering */
    uint8_t lm;                           /* LM clutter densities: 1 §8.2, 2 over all tracks §8.3 */
    uint8_t update;                       /* MTT_UPDATE_* */
    uint8_t baseline;                     /* a comparison baseline (MTT_WITH_BASELINES) */
    uint8_t imm;                          /* runs with motion = imm (ALGORITHMS.md §14.2) */
} mtt_mode;
extern const mtt_mode mtt_modes[]; /* MTT_ASSOC_ROWS rows (core/params_table.h) */
/* Clusters, then the mode's association; PDA modes mark every gated
 * measurement used. */
void mtt_associate_frame(mtt_tracker *trk);

#endif /* MTT_ASSOC_H */
