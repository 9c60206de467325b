/* SPDX-License-Identifier: BSD-3-Clause */
/* measure.c - measurement validation and selection, pipeline stage 1
 * (ALGORITHMS.md §15, §16).
 *
 * A detection with a NaN/Inf coordinate, or a negative/NaN/Inf amplitude,
 * is skipped and counted in meas_bad; in the fixed-point build one with a
 * coordinate outside the declared range +-MTT_FX_POS_LIMIT or a saturated
 * amplitude is skipped and counted apart, in meas_out_of_range
 * (docs/FIXED_POINT.md §3: never wrapped, never silent).  Beyond MTT_MAX_MEAS the strongest stay: an
 * amplitude beats none, a larger amplitude a smaller, then the canonical
 * order below.  A heap of the kept input indices holds the weakest at its
 * root, so the cap costs O(n log MTT_MAX_MEAS).
 *
 * A detection with its own covariance (a nonzero cov[i] of
 * mtt_tracker_step_cov) keeps it when it is finite and positive definite,
 * else it is skipped and counted as bad; a build without MTT_WITH_MEAS_COV
 * never sees one (the step refuses it).
 *
 * The kept ones are stored in the canonical order (x, y, amplitude, own
 * covariance; the input index only between equal detections), so every later stage, births
 * and their identities included, is the same for any order of the input
 * (ALGORITHMS.md §15), and the gating and initiation sweeps find them
 * sorted by x. */
#include "mtt_internal.h"

/* The frame's input: the detections and their covariances (NULL: none). */
typedef struct frame_in {
    const mtt_meas *m;
#if MTT_WITH_MEAS_COV
    const mtt_meas_cov *cov;
#endif
} frame_in;

#if MTT_WITH_MEAS_COV
static int has_cov(const mtt_meas_cov *c)
{
    return c != NULL && (c->r_xx != MTT_ZERO || c->r_xy != MTT_ZERO || c->r_yy != MTT_ZERO);
}
#endif

/* The canonical order: by value, the input index only between equal
 * detections (whose outputs are the same either way). */
static int before(const frame_in *in, uint32_t i, uint32_t j)
{
    const mtt_meas *m = in->m;
    if (m[i].x != m[j].x) {
        return m[i].x < m[j].x;
    }
    if (m[i].y != m[j].y) {
        return m[i].y < m[j].y;
    }
    if (m[i].has_amplitude != m[j].has_amplitude) {
        return m[i].has_amplitude == 0;
    }
    if (m[i].has_amplitude && m[i].amplitude != m[j].amplitude) {
        return m[i].amplitude < m[j].amplitude;
    }
#if MTT_WITH_MEAS_COV
    if (in->cov != NULL) {
        const mtt_meas_cov *a = &in->cov[i], *b = &in->cov[j];
        if (a->r_xx != b->r_xx) {
            return a->r_xx < b->r_xx;
        }
        if (a->r_xy != b->r_xy) {
            return a->r_xy < b->r_xy;
        }
        if (a->r_yy != b->r_yy) {
            return a->r_yy < b->r_yy;
        }
    }
#endif
    return i < j;
}

/* Strength order for the MTT_MAX_MEAS cap. */
static int stronger(const frame_in *in, uint32_t i, uint32_t j)
{
    const mtt_meas *m = in->m;
    if (m[i].has_amplitude != m[j].has_amplitude) {
        return m[i].has_amplitude != 0;
    }
    if (m[i].has_amplitude && m[i].amplitude != m[j].amplitude) {
        return m[i].amplitude > m[j].amplitude;
    }
    return before(in, i, j);
}

/* Heap order with the weakest kept measurement at the root. */
static int sel_less(const void *a, const void *b, const void *ctx)
{
    return stronger((const frame_in *)ctx, *(const uint32_t *)a, *(const uint32_t *)b);
}

/* The kept indices into the canonical order: a bottom-up merge sort (runs
 * of 1, 2, 4, ...: log2(n) passes of n moves, the comparison inlined, no
 * recursion), several times cheaper per frame than the generic heap sort. */
static void sort_canonical(uint32_t *idx, uint32_t *tmp, uint32_t n, const frame_in *m)
{
    uint32_t *src = idx, *dst = tmp, *t, width, lo, i;
    for (width = 1u; width < n; width *= 2u) {
        for (lo = 0; lo < n; lo += 2u * width) {
            const uint32_t mid = lo + width < n ? lo + width : n;
            const uint32_t hi = lo + 2u * width < n ? lo + 2u * width : n;
            uint32_t a = lo, b = mid, k;
            for (k = lo; k < hi; ++k) {
                dst[k] = (b >= hi || (a < mid && !before(m, src[b], src[a]))) ? src[a++] : src[b++];
            }
        }
        t = src;
        src = dst;
        dst = t;
    }
    if (src != idx) {
        for (i = 0; i < n; ++i) {
            idx[i] = src[i];
        }
    }
}

/* Why a detection is skipped: 0 valid, SKIP_BAD malformed, SKIP_RANGE
 * outside the build's range.  A float NaN/Inf fails MTT_POS_OK and
 * mtt_isfinite too, and is malformed there (MTT_MEAS_RANGE). */
enum { SKIP_NONE, SKIP_BAD, SKIP_RANGE };
static int meas_skip(const mtt_meas *m, const mtt_meas_cov *c)
{
    if (!MTT_POS_OK(m->x) || !MTT_POS_OK(m->y)) {
        return SKIP_RANGE;
    }
#if MTT_WITH_MEAS_COV
    if (has_cov(c) && !(mtt_isfinite(c->r_xx) && mtt_isfinite(c->r_xy) && mtt_isfinite(c->r_yy) &&
                        c->r_xx > MTT_ZERO && c->r_yy > MTT_ZERO && c->r_xx * c->r_yy > c->r_xy * c->r_xy)) {
        return SKIP_BAD; /* not a covariance */
    }
#else
    (void)c;
#endif
    if (!m->has_amplitude) {
        return SKIP_NONE;
    }
    if (!mtt_isfinite(m->amplitude)) {
        return SKIP_RANGE;
    }
    return (m->amplitude >= MTT_ZERO) ? SKIP_NONE : SKIP_BAD;
}

static void store_meas(mtt_mstore *s, const mtt_meas *m, const mtt_meas_cov *c, uint32_t src)
{
    s->x = m->x;
    s->y = m->y;
    s->has_amp = (uint8_t)(m->has_amplitude != 0);
    s->amp = s->has_amp ? m->amplitude : MTT_ZERO;
    s->src = src;
    s->used = 0;
#if MTT_WITH_MEAS_COV
    s->has_R = (uint8_t)has_cov(c);
    s->R[0] = s->has_R ? c->r_xx : MTT_ZERO;
    s->R[1] = s->has_R ? c->r_xy : MTT_ZERO;
    s->R[2] = s->has_R ? c->r_yy : MTT_ZERO;
#else
    (void)c;
#endif
}

void mtt_measure_select(mtt_tracker *trk, const mtt_meas *meas, const mtt_meas_cov *cov, size_t n)
{
    uint32_t *const sel = trk->sel; /* in a local: a large field offset (a firmware's .text) */
#if MTT_WITH_MEAS_COV
    const frame_in in = {meas, cov};
#else
    const frame_in in = {meas};
#endif
    size_t i;
    uint32_t kept = 0, valid = 0;
    for (i = 0; i < n; ++i) {
        const int skip = meas_skip(&meas[i], (cov != NULL) ? &cov[i] : NULL);
        if (skip != SKIP_NONE) {
            ++*((skip == SKIP_RANGE) ? MTT_MEAS_RANGE(&trk->stats.last) : &trk->stats.last.meas_bad);
            continue;
        }
        ++valid;
        if (kept < MTT_MAX_MEAS) {
            sel[kept++] = (uint32_t)i;
            if (kept == MTT_MAX_MEAS) {
                uint32_t h;
                for (h = MTT_MAX_MEAS / 2u; h > 0u; --h) {
                    mtt_heap_sift(sel, MTT_MAX_MEAS, sizeof sel[0], h - 1u, sel_less, &in);
                }
            }
        } else if (stronger(&in, (uint32_t)i, sel[0])) {
            sel[0] = (uint32_t)i; /* the weakest kept one gives way */
            mtt_heap_sift(sel, MTT_MAX_MEAS, sizeof sel[0], 0u, sel_less, &in);
        }
    }
    trk->stats.last.meas_dropped = valid - kept;
    sort_canonical(sel, trk->sel_tmp, kept, &in);
#if MTT_WITH_MEAS_COV
    trk->n_own_r = 0;
    trk->own_rmax[0] = MTT_ZERO;
    trk->own_rmax[1] = MTT_ZERO;
#endif
    for (i = 0; i < kept; ++i) {
        store_meas(&trk->meas[i], &meas[sel[i]], (cov != NULL) ? &cov[sel[i]] : NULL, sel[i]);
#if MTT_WITH_MEAS_COV
        if (trk->meas[i].has_R) {
            trk->n_own_r++;
            trk->own_rmax[0] = (trk->meas[i].R[0] > trk->own_rmax[0]) ? trk->meas[i].R[0] : trk->own_rmax[0];
            trk->own_rmax[1] = (trk->meas[i].R[2] > trk->own_rmax[1]) ? trk->meas[i].R[2] : trk->own_rmax[1];
        }
#endif
    }
    trk->n_meas = (uint16_t)kept;
}

#if MTT_WITH_MEAS_COV
const mtt_real *mtt_meas_r(const mtt_tracker *trk, const mtt_mstore *ms)
{
    return ms->has_R ? ms->R : trk->R;
}

uint16_t mtt_meas_row_r(mtt_tracker *trk, uint16_t first, uint16_t m)
{
    uint16_t i, own = 0;
    for (i = 0; i < m; ++i) {
        const mtt_mstore *ms = &trk->meas[trk->pairs[first + i].meas];
        trk->row.rj[i] = mtt_meas_r(trk, ms);
        own = (uint16_t)(own + ms->has_R);
    }
    return own;
}
#endif
