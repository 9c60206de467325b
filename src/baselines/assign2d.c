/* SPDX-License-Identifier: BSD-3-Clause */
/* assign2d.c - optimal 2-D assignment per cluster, the `ihpda-2d` mode
 * (ALGORITHMS.md §10.2; [S0] eq. 11 and 12; ALGORITHMS.md §15.1).
 *
 * The beta matrix is static: each track's IHPDA row (ALGORITHMS.md §7.3) over its full
 * gate, with the plain lambda (the mode skips the LM step).  The weights are
 * w = beta + (n_c + 1) for gated pairs and 0 otherwise; maximising sum w
 * first maximises the number of assigned tracks (every beta <= 1), then the
 * sum of beta.  Solver: the Hungarian method (Kuhn-Munkres with potentials,
 * O(n^2 (m + n))) on the cost -w, with one dummy zero-weight column per row
 * so that every row can be matched; zero-weight matches are dropped.
 * Clusters over MTT_MAX_ASSIGN_TRACKS fall back to MMR with recomputation
 * (ALGORITHMS.md §10.2 CHOICE, counted in the stats).  The final recomputation of
 * ALGORITHMS.md §10.3 follows in the association stage (ihpda.c). */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES

void mtt_assign2d_solve(mtt_assign_scratch *s, uint16_t n, uint16_t m, mtt_row_fn fill,
                        const void *ctx)
{
    const uint16_t cols = (uint16_t)(m + n); /* m real columns, then n dummies */
    uint16_t i, j, it, j0, j1;
    for (i = 0; i <= n; ++i) {
        s->u[i] = MTT_R(0.0);
    }
    for (j = 0; j <= cols; ++j) {
        s->v[j] = MTT_R(0.0);
        s->p[j] = 0;
        s->way[j] = 0;
    }
    /* 1-based rows and columns; column 0 is the virtual root. */
    for (i = 1; i <= n; ++i) {
        s->p[0] = i;
        j0 = 0;
        for (j = 0; j <= cols; ++j) {
            s->minv[j] = MTT_REAL_MAX;
            s->done[j] = 0;
        }
        /* Each pass marks one more column: at most cols + 1 passes. */
        for (it = 0; it <= cols; ++it) {
            const uint16_t i0 = s->p[j0];
            mtt_real delta = MTT_REAL_MAX;
            s->done[j0] = 1;
            j1 = 0;
            fill(ctx, (uint16_t)(i0 - 1u), s->row);
            for (j = 1; j <= cols; ++j) {
                if (!s->done[j]) {
                    const mtt_real w = (j <= m) ? s->row[j - 1u] : MTT_R(0.0);
                    const mtt_real cur = -w - s->u[i0] - s->v[j];
                    if (cur < s->minv[j]) {
                        s->minv[j] = cur;
                        s->way[j] = j0;
                    }
                    if (s->minv[j] < delta) {
                        delta = s->minv[j];
                        j1 = j;
                    }
                }
            }
            for (j = 0; j <= cols; ++j) {
                if (s->done[j]) {
                    s->u[s->p[j]] += delta;
                    s->v[j] -= delta;
                } else {
                    s->minv[j] -= delta;
                }
            }
            j0 = j1;
            if (s->p[j0] == 0u) {
                break;
            }
        }
        /* Augment along the alternating path (at most cols + 1 steps). */
        for (it = 0; it <= cols && j0 != 0u; ++it) {
            j1 = s->way[j0];
            s->p[j0] = s->p[j1];
            j0 = j1;
        }
    }
    for (i = 0; i < n; ++i) {
        s->col_row[i] = -1;
    }
    for (j = 1; j <= m; ++j) {
        if (s->p[j] != 0u) {
            fill(ctx, (uint16_t)(s->p[j] - 1u), s->row);
            if (s->row[j - 1u] > MTT_R(0.0)) {
                s->col_row[s->p[j] - 1u] = (int16_t)(j - 1u);
            }
        }
    }
}

typedef struct {
    const mtt_tracker *trk;
    uint16_t c;
    uint16_t m;      /* real columns */
    mtt_real offset; /* n_c + 1 */
} cluster_ctx;

/* Row r of cluster c: beta + (n_c + 1) on the track's gated columns. */
static void cluster_row(const void *vctx, uint16_t r, mtt_real *w)
{
    const cluster_ctx *cx = (const cluster_ctx *)vctx;
    const mtt_tracker *trk = cx->trk;
    const mtt_track_frame *tf = &trk->tf[trk->cl_list[trk->cl_first[cx->c] + r]];
    uint16_t j, k;
    for (j = 0; j < cx->m; ++j) {
        w[j] = MTT_R(0.0);
    }
    for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
        w[trk->base.asg.col_of[trk->pairs[k].meas]] = trk->pairs[k].beta + cx->offset;
    }
}

void mtt_assign2d_cluster(mtt_tracker *trk, uint16_t c)
{
    mtt_assign_scratch *s = &trk->base.asg;
    const uint16_t first = trk->cl_first[c], end = trk->cl_first[c + 1u];
    const uint16_t n = (uint16_t)(end - first);
    uint16_t q, k, m = 0;
    cluster_ctx cx;

    if (n > MTT_MAX_ASSIGN_TRACKS) {
        trk->stats.last.assign_fallbacks++;
        mtt_mmr_cluster(trk, c, 1);
        return;
    }
    for (q = first; q < end; ++q) {
        const uint16_t ti = trk->cl_list[q];
        mtt_track_frame *tf = &trk->tf[ti];
        int16_t best;
        tf->assigned = -1;
        (void)mtt_ihpda_row(trk, ti, 0, -1, 0, &best); /* static beta, full gate */
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            const uint16_t j = trk->pairs[k].meas;
            if (s->col_of[j] == MTT_NONE16) {
                s->col_of[j] = m;
                s->col_meas[m++] = j;
            }
        }
    }
    cx.trk = trk;
    cx.c = c;
    cx.m = m;
    cx.offset = (mtt_real)n + MTT_R(1.0);
    mtt_assign2d_solve(s, n, m, cluster_row, &cx);
    for (q = first; q < end; ++q) {
        const uint16_t ti = trk->cl_list[q];
        const int16_t col = s->col_row[q - first];
        mtt_track_frame *tf = &trk->tf[ti];
        if (col < 0) {
            continue; /* m = 0 update */
        }
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            if (trk->pairs[k].meas == s->col_meas[col]) {
                tf->assigned = (int16_t)k;
                trk->meas[s->col_meas[col]].used = 1;
            }
        }
    }
    for (k = 0; k < m; ++k) {
        s->col_of[s->col_meas[k]] = MTT_NONE16;
    }
}

void mtt_assign2d_frame(mtt_tracker *trk)
{
    uint16_t j, c;
    for (j = 0; j < trk->n_meas; ++j) {
        trk->base.asg.col_of[j] = MTT_NONE16;
    }
    for (c = 0; c < trk->n_clusters; ++c) {
        mtt_assign2d_cluster(trk, c);
    }
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_baselines_left_out;
#endif /* MTT_WITH_BASELINES */
