/* gate.c - ellipsoidal gating of every track (ALGORITHMS.md §4).
 *
 * gamma = -2 ln(1 - PG); a measurement is gated when d^2 = nu' S^-1 nu <=
 * gamma; V_G = pi gamma sqrt(det S); p = N(nu; 0, S) / PG.
 * Measurements are sorted once along x; each track scans only the slice
 * its gate can reach (|nu_x| <= sqrt(gamma s11)), so the cost is
 * O(n log n + sum of slice lengths), not tracks x measurements. */
#include "mtt_internal.h"

/* ln x for finite x > 0 without libm's log (ALGORITHMS.md §16): x = m 2^e
 * with m in [1/sqrt 2, sqrt 2), ln m = 2 atanh s, s = (m - 1)/(m + 1),
 * |s| <= 0.172, by its series to s^9 (next term < 4e-10 relative: float
 * exact to a few ulp, for the float firmware).  Halving and doubling are
 * exact, so the only rounding is the series'. */
mtt_real mtt_gate_ln(mtt_real x)
{
    mtt_real m = x, s, s2;
    int e = 0, k;
    for (k = 0; k < 1100 && m < MTT_R(0.70710678118654752); ++k) {
        m *= MTT_R(2.0);
        --e;
    }
    for (k = 0; k < 1100 && m >= MTT_R(1.4142135623730951); ++k) {
        m *= MTT_R(0.5);
        ++e;
    }
    s = (m - MTT_R(1.0)) / (m + MTT_R(1.0));
    s2 = s * s;
    return (mtt_real)e * MTT_R(0.69314718055994531) +
           s * (MTT_R(2.0) + s2 * (MTT_R(2.0) / MTT_R(3.0) +
                                   s2 * (MTT_R(0.4) + s2 * (MTT_R(2.0) / MTT_R(7.0) + s2 * (MTT_R(2.0) / MTT_R(9.0))))));
}

mtt_real mtt_gate_gamma(mtt_real pg)
{
#if MTT_SMALL_LOG
    return MTT_R(-2.0) * mtt_gate_ln(MTT_R(1.0) - pg); /* firmware: no libm log (616 B) */
#else
    return MTT_R(-2.0) * mtt_log(MTT_R(1.0) - pg);
#endif
}

mtt_real mtt_gate_volume(mtt_real gamma, mtt_real det_s)
{
    return MTT_PI * gamma * mtt_sqrt(det_s);
}

mtt_real mtt_gate_likelihood(mtt_real d2, mtt_real det_s, mtt_real pg)
{
    return mtt_exp(MTT_R(-0.5) * d2) / (MTT_R(2.0) * MTT_PI * mtt_sqrt(det_s) * pg);
}

static int less_pair(const void *a, const void *b, const void *ctx)
{
    const mtt_pair *p = (const mtt_pair *)a, *q = (const mtt_pair *)b;
    (void)ctx;
    if (p->track != q->track) {
        return p->track < q->track;
    }
    return p->meas < q->meas;
}

/* First position in the x-sorted order whose x >= v. */
static uint16_t lower_bound_x(const mtt_tracker *trk, mtt_real v)
{
    uint16_t lo = 0, hi = trk->n_meas;
    while (lo < hi) {
        uint16_t mid = (uint16_t)(lo + (hi - lo) / 2u);
        if (trk->meas[trk->order[mid]].x < v) {
            lo = (uint16_t)(mid + 1u);
        } else {
            hi = mid;
        }
    }
    return lo;
}

/* Beyond MTT_MAX_PAIRS: the least likely pair of the frame gives way (docs/DESIGN.md). */
static void push_pair(mtt_tracker *trk, const mtt_pair *np, int *resort)
{
    uint16_t k, worst = 0;
    if (trk->n_pairs < MTT_MAX_PAIRS) {
        trk->pairs[trk->n_pairs++] = *np;
        return;
    }
    trk->stats.last.pairs_dropped++;
    for (k = 1; k < MTT_MAX_PAIRS; ++k) {
        if (trk->pairs[k].p < trk->pairs[worst].p ||
            (trk->pairs[k].p == trk->pairs[worst].p && less_pair(&trk->pairs[worst], &trk->pairs[k], NULL))) {
            worst = k;
        }
    }
    if (np->p > trk->pairs[worst].p) {
        trk->pairs[worst] = *np;
        *resort = 1;
    }
}

void mtt_gate_frame(mtt_tracker *trk)
{
    const uint16_t n = trk->n_meas;
    uint16_t cm[MTT_MAX_GATED];
    mtt_real cd[MTT_MAX_GATED];
    uint16_t i, k;
    int resort = 0;
#if MTT_WITH_IMM
    const int imm = trk->par.motion == MTT_MOTION_IMM;
#endif

    for (i = 0; i < n; ++i) {
        trk->order[i] = i;
    }
    mtt_sort_by_x(trk->order, trk->init_cand, n, trk->meas);
    trk->n_pairs = 0;

    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        mtt_real zx = tf->xp[0], zy = tf->xp[1], wx, wy, gamma = trk->gamma;
        uint16_t nc = 0, a, b;
        mtt_real peak;
        if (!tf->valid) {
            continue;
        }
        if (MTT_WITH_BASELINES && tf->shrink) {
            gamma /= trk->par.adaptive_jpda_shrink; /* adaptive JPDA (ALGORITHMS.md §13.7) */
        }
        tf->vg = mtt_gate_volume(gamma, tf->det_s);
        wx = mtt_sqrt(gamma * tf->S[0]);
        wy = mtt_sqrt(gamma * tf->S[2]);
#if MTT_WITH_IMM
        if (imm) {
            /* the union of the model gates (ALGORITHMS.md §14.2) */
            tf->vg = tf->vgm;
            mtt_imm_gate_window(trk, i, &wx, &wy);
        }
#endif
        for (k = lower_bound_x(trk, zx - wx); k < n; ++k) {
            uint16_t j = trk->order[k];
            mtt_real dx = trk->meas[j].x - zx, dy = trk->meas[j].y - zy, d2;
            if (dx > wx) {
                break;
            }
            if (mtt_fabs(dy) > wy) {
                continue;
            }
#if MTT_WITH_IMM
            d2 = imm ? mtt_imm_gate_d2(trk, i, trk->meas[j].x, trk->meas[j].y) : mtt_mahal2(tf->Si, dx, dy);
#else
            d2 = mtt_mahal2(tf->Si, dx, dy);
#endif
            if (!(d2 <= gamma)) {
                continue;
            }
            if (nc < MTT_MAX_GATED) {
                cm[nc] = j;
                cd[nc] = d2;
                ++nc;
            } else {
                /* Gate full: the largest d^2 gives way (ALGORITHMS.md §7.2, cap). */
                uint16_t w = 0;
                for (a = 1; a < nc; ++a) {
                    if (cd[a] > cd[w] || (cd[a] == cd[w] && cm[a] > cm[w])) {
                        w = a;
                    }
                }
                trk->stats.last.gated_dropped++;
                if (d2 < cd[w] || (d2 == cd[w] && j < cm[w])) {
                    cm[w] = j;
                    cd[w] = d2;
                }
            }
        }
        /* Input order inside the gate (insertion sort of at most MTT_MAX_GATED). */
        for (a = 1; a < nc; ++a) {
            uint16_t mj = cm[a];
            mtt_real md = cd[a];
            for (b = a; b > 0 && cm[b - 1u] > mj; --b) {
                cm[b] = cm[b - 1u];
                cd[b] = cd[b - 1u];
            }
            cm[b] = mj;
            cd[b] = md;
        }
        /* N(0; 0, S) / PG once per track: the pairs differ only in exp(-d2/2),
         * so the square root and divisions are not repeated per pair. */
        peak = mtt_gate_likelihood(MTT_R(0.0), tf->det_s, trk->par.pg);
        for (a = 0; a < nc; ++a) {
            mtt_pair np;
            np.track = i;
            np.meas = cm[a];
#if MTT_WITH_IMM
            /* IMM: the model-mixed likelihood p* (ALGORITHMS.md §14.2) */
            np.p = imm ? mtt_imm_gate_p(trk, i, trk->meas[cm[a]].x, trk->meas[cm[a]].y)
                       : peak * mtt_exp(MTT_R(-0.5) * cd[a]);
#else
            np.p = peak * mtt_exp(MTT_R(-0.5) * cd[a]);
#endif
            np.w = MTT_R(0.0);
            np.lam = MTT_R(0.0);
            np.beta = MTT_R(0.0);
            np.g = MTT_R(1.0);
            push_pair(trk, &np, &resort);
        }
    }
    if (resort) {
        mtt_sort(trk->pairs, trk->n_pairs, sizeof trk->pairs[0], less_pair, NULL);
    }

    /* Per-track ranges (pairs are sorted by track). */
    for (i = 0; i < trk->n_tracks; ++i) {
        trk->tf[i].pair_count = 0;
        trk->tf[i].pair_first = 0;
        trk->tf[i].has_all_amp = 1;
    }
    for (k = trk->n_pairs; k > 0; --k) {
        const mtt_pair *pp = &trk->pairs[k - 1u];
        mtt_track_frame *tf = &trk->tf[pp->track];
        tf->pair_first = (uint16_t)(k - 1u);
        tf->pair_count++;
        if (!trk->meas[pp->meas].has_amp) {
            tf->has_all_amp = 0;
        }
    }
    /* Pairs of each measurement (CSR), ascending track. */
    for (i = 0; i <= n; ++i) {
        trk->mp_first[i] = 0;
    }
    for (k = 0; k < trk->n_pairs; ++k) {
        trk->mp_first[trk->pairs[k].meas + 1u]++;
    }
    for (i = 0; i < n; ++i) {
        trk->mp_first[i + 1u] = (uint16_t)(trk->mp_first[i + 1u] + trk->mp_first[i]);
    }
    /* Fill with mp_first[j] as the cursor of j; it then holds the end of j,
     * which is the start of j + 1: shift back by one. */
    for (k = 0; k < trk->n_pairs; ++k) {
        uint16_t j = trk->pairs[k].meas;
        trk->mp_list[trk->mp_first[j]] = k;
        trk->mp_first[j]++;
    }
    mtt_csr_unshift(trk->mp_first, n);
    trk->stats.last.pairs = trk->n_pairs;
}
