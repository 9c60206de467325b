/* SPDX-License-Identifier: BSD-3-Clause */
/* ihpda.c - IHPDA: one selected measurement per track, using the ranks of
 * the gated intensities (ALGORITHMS.md §7).
 *
 * ALGORITHMS.md §7.2: P_r(l | m, rho) in the product/recurrence form
 *   a = 1/(1+rho), P_r(1) = prod_{j<m} j/(j+a), P_r(l+1) = P_r(l)(l-1+a)/l,
 * never the seed's alternating sum, which cancels catastrophically.
 * ALGORITHMS.md §7.3: A_j = PD PG m p_j P_r(l_j) / lambda_j,
 *           C_j = 1 - PD PG + PD PG (m / (lambda_j V_G)) (1 - P_r(l_j)),
 *           L_j = A_j + C_j, beta_j = A_j / L_j.
 * ALGORITHMS.md §7.4: the `ihpda` mode's selection on each track's full gate;
 * ALGORITHMS.md §10.3: the final recomputation after an assignment.
 * ALGORITHMS.md §7.6 (lm_ihpda_variant contest): the row with the
 * amplitude likelihood ratio in place of the ranks, contest/amplitude.c.
 * Written in the quantity macros of mtt/real.h (docs/FIXED_POINT.md §3, §4):
 * P_r and betas Q30; A, C, L Q16 ratios, with p_j and lambda_j relative to
 * the clutter density and V_G times it; m and the rank terms in the Q24
 * count format. */
#include "mtt_internal.h"

void mtt_ihpda_prank(uint16_t m, mtt_ratio rho, mtt_prob *out)
{
    mtt_prob a = MTT_DIV_PR(MTT_P(1.0), MTT_ADD(MTT_RATIO(1.0), rho));
    mtt_prob p = MTT_P(1.0);
    uint16_t j;
    if (m == 0u) {
        return;
    }
    for (j = 1; j < m; ++j) {
        p = MTT_MUL_PP(p, MTT_DIV_P(MTT_CNT(j), MTT_ADD(MTT_CNT(j), MTT_CVT_P_C(a))));
    }
    out[0] = p;
    for (j = 1; j < m; ++j) {
        out[j] = MTT_DIV_P(MTT_MUL_PC(out[j - 1u], MTT_ADD(MTT_SUB(MTT_CNT(j), MTT_CNT(1)), MTT_CVT_P_C(a))),
                           MTT_CNT(j));
    }
}

/* Rank 1 is the strongest; equal intensities: lower index ranks stronger
 * (ALGORITHMS.md §7.1). */
static uint16_t cand_rank(const mtt_cand *c, uint16_t m, uint16_t i)
{
    uint16_t rank = 1, j;
    for (j = 0; j < m; ++j) {
        if (c[j].amp > c[i].amp || (c[j].amp == c[i].amp && c[j].idx < c[i].idx)) {
            ++rank;
        }
    }
    return rank;
}

#ifdef MTT_REAL_FIXED
/* The fixed-point build: the same row with lambda_j multiplied through,
 * D = lambda_j L_j = X + (1 - PD PG) lambda_j + PD PG (1 - P_r) m / V_G
 * with X = PD PG m p_j P_r, so beta_j = X / D and L_j = D / lambda_j.  The
 * MMR reads beta alone and the update only the assigned pair's L_j, so L
 * holds D here and the quotient by lambda_j is taken where L is read
 * (MTT_PAIR_L, update.c): one quotient per candidate and m / V_G once per
 * row, instead of three quotients per candidate (docs/FIXED_POINT.md,
 * cost measures).  A ratio
 * times a probability (at most 1) cannot overflow, so those products are
 * the fast Q30 multiply (0.5007 unit instead of 0.5); 1/m once per row. */
#define MULQ_RP(a, b) mtt_fx_mulq30((a), (b))
void mtt_ihpda_betas(mtt_prob pd, mtt_prob pg, mtt_ratio vg, const mtt_prob *prank,
                     const mtt_cand *c, uint16_t m, mtt_prob *beta, mtt_ratio *L, uint8_t *rank_out)
{
    const mtt_prob pdpg = MTT_MUL_PP(pd, pg);
    const mtt_real fm = MTT_CNT(m);
    const mtt_real pdpg_m = MTT_MUL_PC(pdpg, fm);                   /* count */
    const mtt_ratio z = MULQ_RP(MTT_DIV_CG(fm, vg), pdpg);           /* PD PG m / V_G */
    const mtt_prob pr1 = (prank != NULL) ? MTT_ZERO : MTT_DIV_P(MTT_CNT(1), fm); /* P_r without ranks */
    uint16_t i;
    for (i = 0; i < m; ++i) {
        mtt_prob pr;
        mtt_ratio X, D;
        const uint16_t rank = cand_rank(c, m, i);
        if (rank_out != NULL) {
            rank_out[i] = (uint8_t)rank;
        }
        pr = (prank != NULL) ? prank[rank - 1u] : pr1;
        X = MULQ_RP(MTT_MUL_CR(pdpg_m, c[i].p), pr);
        D = MTT_ADDS(MTT_ADDS(X, MULQ_RP(c[i].lam, MTT_SUB(MTT_P(1.0), pdpg))), MULQ_RP(z, MTT_SUB(MTT_P(1.0), pr)));
        L[i] = D; /* lambda_j L_j: divided where it is read (MTT_PAIR_L) */
        beta[i] = MTT_DIV_P(X, D);
    }
}
#undef MULQ_RP
#else
void mtt_ihpda_betas(mtt_prob pd, mtt_prob pg, mtt_ratio vg, const mtt_prob *prank,
                     const mtt_cand *c, uint16_t m, mtt_prob *beta, mtt_ratio *L, uint8_t *rank_out)
{
    const mtt_prob pdpg = MTT_MUL_PP(pd, pg);
    const mtt_real fm = MTT_CNT(m);
    uint16_t i;
    for (i = 0; i < m; ++i) {
        mtt_prob pr;
        mtt_ratio A, C;
        const uint16_t rank = cand_rank(c, m, i);
        if (rank_out != NULL) {
            rank_out[i] = (uint8_t)rank;
        }
        pr = (prank != NULL) ? prank[rank - 1u] : MTT_DIV_P(MTT_CNT(1), fm);
        A = MTT_DIV_R(MTT_MUL_RP(MTT_MUL_CR(MTT_MUL_PC(pdpg, fm), c[i].p), pr), c[i].lam);
        C = MTT_ADDS(MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), pdpg)),
                     MTT_MUL_RP(MTT_MUL_RP(pdpg, MTT_DIV_CR(fm, MTT_MUL_RR(c[i].lam, vg))),
                                MTT_SUB(MTT_P(1.0), pr)));
        L[i] = MTT_ADDS(A, C);
        beta[i] = MTT_DIV_P(A, L[i]);
    }
}
#endif

uint16_t mtt_ihpda_row(mtt_tracker *trk, uint16_t ti, int excl_used, int16_t keep, int rule,
                       int16_t *best)
{
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_cand *c = trk->row.cand;
    uint16_t *pk = trk->row.pair;
    mtt_real *beta = trk->row.beta, *L = trk->row.L;
    uint8_t *rank = trk->row.rank;
    const mtt_real *prank = NULL;
    const int amp = MTT_CONTEST_ON(trk);
    mtt_pair *const pairs = trk->pairs;
    const mtt_mstore *const meas = trk->meas;
    uint16_t m = 0, k, b = 0;

    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        mtt_pair *pp = &pairs[k];
        const mtt_mstore *ms = &meas[pp->meas];
        pp->beta = MTT_ZERO;
        if (excl_used && ms->used && (int16_t)k != keep) {
            continue;
        }
        c[m].p = pp->p;
        c[m].lam = pp->lam;
        c[m].amp = amp ? pp->g : ms->amp;
        c[m].idx = pp->meas;
        pk[m] = k;
        ++m;
    }
    *best = -1;
    tf->row_m = (uint8_t)m;
    if (m == 0u) {
        return 0;
    }
#if MTT_WITH_CONTEST
    if (amp) {
        /* ranks are not computed: MMR's tie rule is the lower index */
        mtt_contest_amp_betas(trk->par.pd * trk->par.pg, tf->vg, c, m, beta, L);
    } else
#endif
    {
        /* A track with any gated measurement lacking amplitude uses rho = 0 (ALGORITHMS.md §7.1). */
        if (trk->par.snr_rho > MTT_ZERO && tf->has_all_amp) {
            prank = &trk->prank[MTT_PRANK_ROW(m)];
        }
        mtt_ihpda_betas(trk->par.pd, trk->par.pg, tf->vg, prank, c, m, beta, L, rank);
    }
    for (k = 0; k < m; ++k) {
        pairs[pk[k]].beta = beta[k];
        pairs[pk[k]].L = L[k];
        /* Candidates are in measurement order, so a strict '>' keeps the
         * lower index on ties; rule 1 lets the smaller rank win first. */
        if (k == 0u || beta[k] > beta[b] || (rule == 1 && beta[k] == beta[b] && rank[k] < rank[b])) {
            b = k;
        }
    }
    *best = (int16_t)pk[b];
    return m;
}

void mtt_ihpda_select_frame(mtt_tracker *trk)
{
    uint16_t i;
    /* Each track selects on its own full gate (the row ignores `used`), so
     * tracks may share (ALGORITHMS.md §15.1). */
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        tf->assigned = -1;
        if (tf->valid && tf->pair_count > 0u) {
            (void)mtt_ihpda_row(trk, i, 0, -1, 1, &tf->assigned);
            if (tf->assigned >= 0) {
                trk->meas[trk->pairs[tf->assigned].meas].used = 1;
            }
        }
    }
}

/* ALGORITHMS.md §10.3's set G_f = G minus the measurements assigned to other tracks
 * is a subset of the set the track's last row was computed over (MMR: the
 * free measurements when it was assigned; 2-D assignment: all of G).  So
 * equal sizes mean equal sets, equal rows, and the recomputation can be
 * skipped: the common case of a track that shares nothing. */
static int final_set_changed(const mtt_tracker *trk, uint16_t ti)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    uint16_t k, m = 0;
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        if (!trk->meas[trk->pairs[k].meas].used || (int16_t)k == tf->assigned) {
            ++m;
        }
    }
    return m != tf->row_m;
}

void mtt_ihpda_final_frame(mtt_tracker *trk)
{
    uint16_t i;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        if (tf->valid && tf->assigned >= 0 && !MTT_CONTESTED(tf) &&
            (MTT_CONTEST_ROW_WRITTEN(tf) || final_set_changed(trk, i))) {
            int16_t best;
            (void)mtt_ihpda_row(trk, i, 1, tf->assigned, 0, &best);
        }
    }
}
