/* SPDX-License-Identifier: BSD-3-Clause */
/* jpda.c - exact JPDA, JPDA* and JIPDA by event enumeration per cluster
 * (ALGORITHMS.md §13.1, §13.2, §13.6), and the weights A and B of the whole JPDA
 * family (ALGORITHMS.md §13).
 *
 * Weights (ALGORITHMS.md §13): A_tj = N(nu; 0, S) = PG p_tj for a gated pair, B_t =
 * jpda_bias, or lambda_t (1 - PD PG) / PD when it is 0 (lambda_t the known
 * density, or the track's estimate of ALGORITHMS.md §5.2).  JIPDA (ALGORITHMS.md §13.2) uses
 * A_tj = PD PG Pbar_t p_tj / lambda_j and B_t = 1 - PD PG Pbar_t.
 *
 * Enumeration (ALGORITHMS.md §13.1): depth-first over the tracks of the cluster with
 * an explicit stack and a bit mask of used measurements; for each track
 * "none" first, then its gated measurements ascending.  Event weight
 * w = prod A (detected) * prod B (missed).  Each row (A_t., B_t) is divided
 * by its largest entry first: every event holds one factor of every row,
 * so the normalised probabilities are unchanged and the products cannot
 * underflow in float.  Over MTT_MAX_JPDA_TRACKS tracks, MTT_MAX_JPDA_MEAS
 * measurements or MTT_MAX_JPDA_EVENTS events the cluster falls back
 * (ALGORITHMS.md §13.1 CHOICE): Cheap JPDA, or per-track IPDA in jipda.
 *
 * JPDA* (ALGORITHMS.md §13.6): events grouped by (detected tracks, used
 * measurements); each group keeps its largest weight (ties: first in
 * enumeration order); kept events with normalised probability below
 * jpda_star_threshold are dropped (unless that drops all); a second
 * enumeration sums the kept ones.
 *
 * Existence (ALGORITHMS.md §13.2 CHOICE): jipda uses P_t of ALGORITHMS.md §13.2; every other
 * mode the IPDA formula of ALGORITHMS.md §6 on the track's own gate (mtt_ipda_frame,
 * run by the association stage). */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES

static int is_jipda(const mtt_tracker *trk)
{
    return trk->par.association == MTT_ASSOC_JIPDA;
}

void mtt_jpda_weights(mtt_tracker *trk)
{
    const mtt_real pd = trk->par.pd, pg = trk->par.pg, pdpg = pd * pg;
    const int jipda = is_jipda(trk);
    uint16_t i, k;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        trk->base.jp.tb[i] = MTT_R(0.0);
        tf->beta0 = MTT_R(1.0);
        if (!tf->valid) {
            continue;
        }
        if (jipda) {
            trk->base.jp.tb[i] = MTT_R(1.0) - pdpg * tf->ex_pred;
        } else if (trk->par.jpda_bias > MTT_R(0.0)) {
            trk->base.jp.tb[i] = trk->par.jpda_bias;
        } else {
            trk->base.jp.tb[i] = tf->lambda * (MTT_R(1.0) - pdpg) / pd;
        }
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            const mtt_pair *pp = &trk->pairs[k];
            trk->base.jp.pa[k] = jipda ? pdpg * tf->ex_pred * pp->p / pp->lam : pg * pp->p;
        }
    }
}

/* Dense cluster: tracks in cluster order, measurements ascending, rows
 * scaled.  Returns -1 when over the track or measurement bound. */
static int build_dense(mtt_tracker *trk, uint16_t c)
{
    mtt_jpda_scratch *s = &trk->base.jp;
    const uint16_t first = trk->cl_first[c], end = trk->cl_first[c + 1u];
    uint16_t q, k, r, j, a;
    if (end - first > MTT_MAX_JPDA_TRACKS) {
        return -1;
    }
    s->n = (uint16_t)(end - first);
    s->m = 0;
    for (q = first; q < end; ++q) {
        const mtt_track_frame *tf = &trk->tf[trk->cl_list[q]];
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            const uint16_t mj = trk->pairs[k].meas;
            for (a = 0; a < s->m && s->meas_of[a] < mj; ++a) {
            }
            if (a < s->m && s->meas_of[a] == mj) {
                continue;
            }
            if (s->m >= MTT_MAX_JPDA_MEAS) {
                return -1;
            }
            for (j = s->m; j > a; --j) {
                s->meas_of[j] = s->meas_of[j - 1u];
            }
            s->meas_of[a] = mj;
            s->m++;
        }
    }
    for (r = 0; r < s->n; ++r) {
        const uint16_t ti = trk->cl_list[first + r];
        const mtt_track_frame *tf = &trk->tf[ti];
        mtt_real big;
        s->trk_of[r] = ti;
        s->gmask[r] = 0;
        for (j = 0; j < s->m; ++j) {
            s->A[r][j] = MTT_R(0.0);
        }
        big = s->B[r] = trk->base.jp.tb[ti];
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            for (j = 0; j + 1u < s->m && s->meas_of[j] != trk->pairs[k].meas; ++j) {
            }
            s->A[r][j] = trk->base.jp.pa[k];
            s->gmask[r] |= (uint32_t)1u << j;
            big = (trk->base.jp.pa[k] > big) ? trk->base.jp.pa[k] : big;
        }
        s->scale[r] = (big > MTT_R(0.0)) ? big : MTT_R(1.0);
        s->B[r] /= s->scale[r];
        for (j = 0; j < s->m; ++j) {
            s->A[r][j] /= s->scale[r];
        }
    }
    return 0;
}

static int keep_bit(const mtt_jpda_scratch *s, uint32_t e)
{
    return (s->ev_keep[e >> 3] >> (e & 7u)) & 1;
}

/* Next option of track d at or after measurement j0: a gated, unused
 * measurement, or m when none is left. */
static int next_meas(const mtt_jpda_scratch *s, uint16_t d, int j0)
{
    int j;
    for (j = j0; j < (int)s->m; ++j) {
        const uint32_t bit = (uint32_t)1u << j;
        if ((s->gmask[d] & bit) && !(s->used[d] & bit)) {
            return j;
        }
    }
    return (int)s->m;
}

/* Enumerate every feasible event in the order of ALGORITHMS.md §13.6.  record: store
 * each event (key and weight); kept_only: sum only events with their keep
 * bit.  Returns 0, or -1 beyond MTT_MAX_JPDA_EVENTS.  Each loop pass either
 * moves one option forward or one level back, so the loop is bounded by
 * (events + 1) * n * (m + 2) passes, events <= MTT_MAX_JPDA_EVENTS. */
static int enumerate(mtt_jpda_scratch *s, int record, int kept_only)
{
    uint32_t e = 0;
    uint16_t d = 0, t, j;
    for (t = 0; t < s->n; ++t) {
        s->S0[t] = MTT_R(0.0);
        for (j = 0; j < s->m; ++j) {
            s->S[t][j] = MTT_R(0.0);
        }
    }
    s->W = MTT_R(0.0);
    s->choice[0] = -2;
    s->prod[0] = MTT_R(1.0);
    s->used[0] = 0;
    s->det[0] = 0;
    for (;;) {
        int ch = s->choice[d];
        mtt_real w;
        ch = (ch == -2) ? -1 : next_meas(s, d, ch + 1);
        if (ch >= (int)s->m) {
            if (d == 0u) {
                break;
            }
            --d;
            continue;
        }
        s->choice[d] = (int8_t)ch;
        w = s->prod[d] * ((ch < 0) ? s->B[d] : s->A[d][ch]);
        if (d + 1u < s->n) {
            s->prod[d + 1u] = w;
            s->used[d + 1u] = (ch < 0) ? s->used[d] : (s->used[d] | ((uint32_t)1u << ch));
            s->det[d + 1u] = (ch < 0) ? s->det[d] : (uint16_t)(s->det[d] | (1u << d));
            s->choice[d + 1u] = -2;
            ++d;
            continue;
        }
        /* A complete event. */
        if (e >= MTT_MAX_JPDA_EVENTS) {
            return -1;
        }
        if (record) {
            s->ev_used[e] = (ch < 0) ? s->used[d] : (s->used[d] | ((uint32_t)1u << ch));
            s->ev_det[e] = (ch < 0) ? s->det[d] : (uint16_t)(s->det[d] | (1u << d));
            s->ev_w[e] = w;
        }
        if (!kept_only || keep_bit(s, e)) {
            for (t = 0; t < s->n; ++t) {
                if (s->choice[t] < 0) {
                    s->S0[t] += w;
                } else {
                    s->S[t][s->choice[t]] += w;
                }
            }
            s->W += w;
        }
        ++e;
    }
    s->n_events = e;
    return 0;
}

/* JPDA* order: by group (detected, used), then larger weight, then
 * enumeration order (ALGORITHMS.md §13.6 tie rule). */
static int ev_less(const void *pa, const void *pb, const void *ctx)
{
    const mtt_jpda_scratch *s = (const mtt_jpda_scratch *)ctx;
    const uint16_t a = *(const uint16_t *)pa, b = *(const uint16_t *)pb;
    if (s->ev_det[a] != s->ev_det[b]) {
        return s->ev_det[a] < s->ev_det[b];
    }
    if (s->ev_used[a] != s->ev_used[b]) {
        return s->ev_used[a] < s->ev_used[b];
    }
    if (s->ev_w[a] != s->ev_w[b]) {
        return s->ev_w[a] > s->ev_w[b];
    }
    return a < b;
}

static void star_select(mtt_jpda_scratch *s, mtt_real p_prune)
{
    const uint32_t ne = s->n_events;
    uint32_t e, kept = 0;
    mtt_real wk = MTT_R(0.0);
    for (e = 0; e < ne; ++e) {
        s->ev_idx[e] = (uint16_t)e;
    }
    for (e = 0; e < (ne + 7u) / 8u; ++e) {
        s->ev_keep[e] = 0;
    }
    mtt_sort(s->ev_idx, ne, sizeof s->ev_idx[0], ev_less, s);
    for (e = 0; e < ne; ++e) {
        const uint16_t x = s->ev_idx[e];
        if (e == 0u || s->ev_det[x] != s->ev_det[s->ev_idx[e - 1u]] ||
            s->ev_used[x] != s->ev_used[s->ev_idx[e - 1u]]) {
            s->ev_keep[x >> 3] = (uint8_t)(s->ev_keep[x >> 3] | (1u << (x & 7u)));
            wk += s->ev_w[x];
            ++kept;
        }
    }
    if (p_prune > MTT_R(0.0) && wk > MTT_R(0.0)) {
        uint32_t left = 0;
        for (e = 0; e < ne; ++e) {
            if (keep_bit(s, e) && !(s->ev_w[e] < p_prune * wk)) {
                ++left;
            }
        }
        if (left > 0u) { /* never prune every event */
            for (e = 0; e < ne; ++e) {
                if (keep_bit(s, e) && s->ev_w[e] < p_prune * wk) {
                    s->ev_keep[e >> 3] = (uint8_t)(s->ev_keep[e >> 3] & ~(1u << (e & 7u)));
                }
            }
            kept = left;
        }
    }
    s->n_kept = kept;
}

int mtt_jpda_exact(mtt_tracker *trk, uint16_t c, int kind)
{
    mtt_jpda_scratch *s = &trk->base.jp;
    const mtt_real pdpg = trk->par.pd * trk->par.pg;
    uint16_t r, k, j;
    if (build_dense(trk, c) != 0) {
        return -1;
    }
    if (enumerate(s, 1, 0) != 0) {
        return -1;
    }
    s->n_kept = s->n_events;
    if (kind == MTT_JPDA_STAR) {
        star_select(s, trk->par.jpda_star_threshold);
        (void)enumerate(s, 0, 1); /* same events: cannot exceed the bound */
    }
    for (r = 0; r < s->n; ++r) {
        mtt_track_frame *tf = &trk->tf[s->trk_of[r]];
        mtt_real b0 = MTT_R(1.0), norm = MTT_R(0.0);
        if (s->W > MTT_R(0.0)) {
            if (kind == MTT_JPDA_JIPDA) {
                /* ALGORITHMS.md §13.2: P_t = D_t + q_t U_t; beta over P_t. */
                const mtt_real pb = tf->ex_pred;
                const mtt_real q = (MTT_R(1.0) - pdpg) * pb / (MTT_R(1.0) - pdpg * pb);
                mtt_real det = MTT_R(0.0), den, pt;
                for (j = 0; j < s->m; ++j) {
                    det += s->S[r][j];
                }
                /* P_t W = D_t + q_t U_t: divide by it directly.  With a
                 * vanishing existence it underflows, and 1 / (P_t W) would
                 * be infinite: the track then keeps its prediction. */
                den = det + q * s->S0[r];
                pt = den / s->W;
                tf->ex_post = (pt < MTT_R(1.0)) ? pt : MTT_R(1.0);
                norm = (den > MTT_R(0.0)) ? MTT_R(1.0) / den : MTT_R(0.0);
                if (mtt_isfinite(norm) && norm > MTT_R(0.0)) {
                    b0 = q * s->S0[r] * norm;
                } else {
                    norm = MTT_R(0.0);
                }
            } else {
                norm = MTT_R(1.0) / s->W;
                b0 = s->S0[r] * norm;
            }
        }
        tf->beta0 = b0;
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            for (j = 0; j + 1u < s->m && s->meas_of[j] != trk->pairs[k].meas; ++j) {
            }
            trk->pairs[k].beta = s->S[r][j] * norm;
        }
    }
    return 0;
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_baselines_left_out;
#endif /* MTT_WITH_BASELINES */
