/* SPDX-License-Identifier: BSD-3-Clause */
/* core.h - the tracker core: sorting, parameters, existence (ALGORITHMS.md
 * §11), initiation and merging (§12.1 to §12.3), measurement selection
 * (§15) and the track table (§12.4); tracker.c, the pipeline's sequence
 * (§15), has no internal functions.  Not installed; not part of the API.
 * Included through mtt_internal.h.  Sections "§N" are those of
 * docs/ALGORITHMS.md. */
#ifndef MTT_CORE_H
#define MTT_CORE_H

/* ---- sort.c: heap sort and sift for small fixed arrays (no recursion) ---- */
typedef int (*mtt_less_fn)(const void *a, const void *b, const void *ctx);
void mtt_sort(void *base, size_t n, size_t size, mtt_less_fn less, const void *ctx);
/* Restore the heap property below node i of a heap whose root is the
 * element that is NOT less than any other ("max-heap" for `less`). */
void mtt_heap_sift(void *base, size_t n, size_t size, size_t i, mtt_less_fn less, const void *ctx);

/* CSR lists filled with first[c] as the cursor of c hold in first[c] the
 * end of c, which is the start of c + 1: shift first[0..n] back by one
 * (first[0] = 0).  A forward carry, so the compiler links no memmove. */
void mtt_csr_unshift(uint16_t *first, uint16_t n);

/* ---- params.c ---- */
#if MTT_WITH_IMM
/* r models, imm_transition and imm_initial not given (ALGORITHMS.md §2.2). */
void mtt_params_imm_reset(mtt_params *p, uint8_t r);
/* imm_transition: docs/FORMATS.md's default for imm_n_models models. */
void mtt_params_imm_pi_default(mtt_params *p);
/* Index of the first cv model of imm_models, imm_n_models when there is none
 * (the model the split modes build on, ALGORITHMS.md §14.3). */
uint8_t mtt_params_cv_model(const mtt_params *p);
#endif

/* ---- existence.c: Markov chain one and the existence update (ALGORITHMS.md §11, §6) ---- */
mtt_prob mtt_existence_predict(mtt_prob p, mtt_prob p11, mtt_prob p21);
mtt_prob mtt_existence_update(mtt_prob ex_pred, mtt_ratio L);

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
/* cov may be NULL; pol (polar detections, §3.2, meas and cov then NULL) NULL but
 * under polar settings. */
void mtt_measure_select(mtt_tracker *trk, const mtt_meas *meas, const mtt_meas_cov *cov, const mtt_polar *pol,
                        size_t n);
#if MTT_WITH_MEAS_COV
/* The covariance of a stored detection: its own, or meas_sigma's (§3.1). */
const mtt_real *mtt_meas_r(const mtt_tracker *trk, const mtt_mstore *ms);
/* trk->row.rj[i] of the pairs first + i, i < m; returns how many of
 * them have their own R. */
uint16_t mtt_meas_row_r(mtt_tracker *trk, uint16_t first, uint16_t m);
#endif

/* ---- track_table.c: the track table (§12.4) ---- */
/* Append a track; returns its index or -1 when the table is full. */
int mtt_track_append(mtt_tracker *trk, const mtt_state x, mtt_cov P, mtt_real existence,
                     int confirmed, int born);
/* End of frame: delete, confirm, compact. */
void mtt_track_manage(mtt_tracker *trk, mtt_real dt);
/* The CV part of P as the API gives it: 4 x 4, in the fixed build in the
 * variance format (MTT_COV_VIEW); P is only read. */
void mtt_cov_view4(mtt_cov P, mtt_real out[4][4]);

#endif /* MTT_CORE_H */
