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
 * else it is skipped and counted as bad (in the fixed-point build one
 * with a value outside the variance format, saturated, counted in
 * meas_out_of_range); a build without MTT_WITH_MEAS_COV never sees one
 * (the step refuses it).
 *
 * The kept ones are stored in the canonical order (x, y, amplitude, own
 * covariance; the input index only between equal detections), so every later stage, births
 * and their identities included, is the same for any order of the input
 * (ALGORITHMS.md §15), and the gating and initiation sweeps find them
 * sorted by x. */
#include "mtt_internal.h"

/* The frame's input: the detections and their covariances (NULL: none),
 * or polar detections (ALGORITHMS.md §3.2), converted where read. */
typedef struct frame_in {
    const mtt_meas *m;
#if MTT_WITH_MEAS_COV
    const mtt_meas_cov *cov;
#endif
#if MTT_WITH_POLAR
    const mtt_polar *pol;
    const mtt_params *par;
    const mtt_mstore *st; /* polar, once converted: the store the sort's indices point into */
#endif
} frame_in;

#if MTT_WITH_MEAS_COV
static int has_cov(const mtt_meas_cov *c)
{
    return c != NULL && (c->r_xx != MTT_ZERO || c->r_xy != MTT_ZERO || c->r_yy != MTT_ZERO);
}
#endif

#if MTT_WITH_POLAR

/* Polar detection i as the Cartesian detection and covariance it is
 * stored as; 0, or -1 when it does not convert (malformed). */
static int polar_get(const frame_in *in, uint32_t i, mtt_meas *m, mtt_meas_cov *c)
{
    const mtt_polar *d = &in->pol[i];
    mtt_real R[3];
    if (mtt_polar_convert(in->par->meas_sigma, in->par->sensor_xy, d->range, d->bearing, &m->x, &m->y, R) != 0) {
        return -1;
    }
    m->amplitude = d->amplitude;
    m->has_amplitude = d->has_amplitude;
    c->r_xx = R[0];
    c->r_xy = R[1];
    c->r_yy = R[2];
    return 0;
}
#endif

/* The canonical order of two detections by value: -1, 0 (equal), 1. */
static int cmp_value(const mtt_meas *a, const mtt_meas_cov *ca, const mtt_meas *b, const mtt_meas_cov *cb)
{
    if (a->x != b->x) {
        return (a->x < b->x) ? -1 : 1;
    }
    if (a->y != b->y) {
        return (a->y < b->y) ? -1 : 1;
    }
    if (a->has_amplitude != b->has_amplitude) {
        return (a->has_amplitude == 0) ? -1 : 1;
    }
    if (a->has_amplitude && a->amplitude != b->amplitude) {
        return (a->amplitude < b->amplitude) ? -1 : 1;
    }
#if MTT_WITH_MEAS_COV
    if (ca != NULL) {
        if (ca->r_xx != cb->r_xx) {
            return (ca->r_xx < cb->r_xx) ? -1 : 1;
        }
        if (ca->r_xy != cb->r_xy) {
            return (ca->r_xy < cb->r_xy) ? -1 : 1;
        }
        if (ca->r_yy != cb->r_yy) {
            return (ca->r_yy < cb->r_yy) ? -1 : 1;
        }
    }
#else
    (void)ca;
    (void)cb;
#endif
    return 0;
}

#if MTT_WITH_POLAR
/* Polar detections equal once converted: by range, bearing, range rate. */
static int polar_tie(const mtt_polar *a, const mtt_polar *b)
{
    if (a->range != b->range) {
        return (a->range < b->range) ? -1 : 1;
    }
    if (a->bearing != b->bearing) {
        return (a->bearing < b->bearing) ? -1 : 1;
    }
    if (a->has_range_rate != b->has_range_rate) {
        return a->has_range_rate ? 1 : -1;
    }
    if (a->has_range_rate && a->range_rate != b->range_rate) {
        return (a->range_rate < b->range_rate) ? -1 : 1;
    }
    return 0;
}

/* A stored detection as the detection and covariance it was stored from. */
static void stored_get(const mtt_mstore *s, mtt_meas *m, mtt_meas_cov *c)
{
    m->x = s->x;
    m->y = s->y;
    m->amplitude = s->amp;
    m->has_amplitude = s->has_amp;
    c->r_xx = s->R[0];
    c->r_xy = s->R[1];
    c->r_yy = s->R[2];
}
#endif

/* The canonical order: by value (polar: the converted value, then range
 * and bearing), the input index only between equal detections (whose
 * outputs are the same either way).  With in->st, i and j are positions in
 * that store of converted polar detections (converted once, not at every
 * comparison: the conversion costs exp, sin and cos). */
static int before(const frame_in *in, uint32_t i, uint32_t j)
{
    int c;
#if MTT_WITH_POLAR
    if (in->pol != NULL) {
        mtt_meas a = {0}, b = {0};
        mtt_meas_cov ca = {0}, cb = {0}; /* written by polar_get: meas_skip converted them */
        uint32_t si = i, sj = j;         /* input indices */
        if (in->st != NULL) {
            stored_get(&in->st[i], &a, &ca);
            stored_get(&in->st[j], &b, &cb);
            si = in->st[i].src;
            sj = in->st[j].src;
        } else {
            (void)polar_get(in, i, &a, &ca);
            (void)polar_get(in, j, &b, &cb);
        }
        c = cmp_value(&a, &ca, &b, &cb);
        if (c == 0) {
            c = polar_tie(&in->pol[si], &in->pol[sj]);
        }
        return (c != 0) ? (c < 0) : (si < sj);
    }
#endif
#if MTT_WITH_MEAS_COV
    c = cmp_value(&in->m[i], (in->cov != NULL) ? &in->cov[i] : NULL, &in->m[j],
                  (in->cov != NULL) ? &in->cov[j] : NULL);
#else
    c = cmp_value(&in->m[i], NULL, &in->m[j], NULL);
#endif
    return (c != 0) ? (c < 0) : (i < j);
}

/* Strength order for the MTT_MAX_MEAS cap. */
static int stronger(const frame_in *in, uint32_t i, uint32_t j)
{
    int hi, hj;
    mtt_real ai, aj;
#if MTT_WITH_POLAR
    if (in->pol != NULL) {
        hi = in->pol[i].has_amplitude;
        hj = in->pol[j].has_amplitude;
        ai = in->pol[i].amplitude;
        aj = in->pol[j].amplitude;
    } else
#endif
    {
        hi = in->m[i].has_amplitude;
        hj = in->m[j].has_amplitude;
        ai = in->m[i].amplitude;
        aj = in->m[j].amplitude;
    }
    if (hi != hj) {
        return hi != 0;
    }
    if (hi && ai != aj) {
        return ai > aj;
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
#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
    if (has_cov(c)) {
        /* the variance format (Q MTT_FX_VAR_FRAC): a saturated value did
         * not fit it, out of range (never wrapped, docs/FIXED_POINT.md §5) */
        if (!(mtt_isfinite(c->r_xx) && mtt_isfinite(c->r_xy) && mtt_isfinite(c->r_yy))) {
            return SKIP_RANGE;
        }
        if (!(c->r_xx > MTT_ZERO && c->r_yy > MTT_ZERO &&
              (int64_t)c->r_xx * c->r_yy > (int64_t)c->r_xy * c->r_xy)) {
            return SKIP_BAD; /* not a covariance */
        }
    }
#elif MTT_WITH_MEAS_COV
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

/* Detection i of the frame: its skip reason, and (valid) the detection
 * and covariance it is stored with (polar: converted, §3.2). */
static int frame_get(const frame_in *in, size_t i, mtt_meas *m, mtt_meas_cov *c)
{
#if MTT_WITH_POLAR
    if (in->pol != NULL) {
        if (polar_get(in, (uint32_t)i, m, c) != 0 ||
            (in->pol[i].has_range_rate && !mtt_isfinite(in->pol[i].range_rate))) {
            return SKIP_BAD; /* range not > 0, a value not finite */
        }
        return meas_skip(m, c);
    }
#endif
    *m = in->m[i];
    c->r_xx = MTT_ZERO;
    c->r_xy = MTT_ZERO;
    c->r_yy = MTT_ZERO;
#if MTT_WITH_MEAS_COV
    if (in->cov != NULL) {
        *c = in->cov[i];
    }
#endif
    return meas_skip(m, c);
}

#if MTT_WITH_POLAR
/* Polar: the kept detections (input indices in trk->sel) in the store,
 * converted once (when none gave way to the cap, as the selection stored
 * them; else here), sorted by their stored values and put in the canonical
 * order, one cycle of the permutation at a time. */
static void polar_store_sorted(mtt_tracker *trk, const frame_in *in, uint32_t kept, int stored)
{
    uint32_t *const ord = trk->sel, *const done = trk->sel_tmp;
    frame_in st = *in;
    mtt_meas mi;
    mtt_meas_cov ci;
    uint32_t i, k;
    for (i = 0; i < kept; ++i) {
        if (!stored) {
            (void)frame_get(in, ord[i], &mi, &ci);
            store_meas(&trk->meas[i], &mi, &ci, ord[i]);
        }
        ord[i] = i;
    }
    st.st = trk->meas;
    sort_canonical(ord, done, kept, &st);
    for (i = 0; i < kept; ++i) {
        done[i] = 0;
    }
    for (i = 0; i < kept; ++i) { /* position j receives the stored ord[j] */
        if (!done[i]) {
            const mtt_mstore t = trk->meas[i];
            uint32_t j = i;
            for (k = 0; k < kept; ++k) {
                const uint32_t nx = ord[j];
                done[j] = 1u;
                if (nx == i) {
                    trk->meas[j] = t;
                    break;
                }
                trk->meas[j] = trk->meas[nx];
                j = nx;
            }
        }
    }
}
#endif

void mtt_measure_select(mtt_tracker *trk, const mtt_meas *meas, const mtt_meas_cov *cov, const mtt_polar *pol,
                        size_t n)
{
    uint32_t *const sel = trk->sel; /* in a local: a large field offset (a firmware's .text) */
#if MTT_WITH_POLAR
    const frame_in in = {meas, cov, pol, &trk->par, NULL};
#elif MTT_WITH_MEAS_COV
    const frame_in in = {meas, cov};
    (void)pol;
#else
    const frame_in in = {meas};
    (void)pol;
    (void)cov;
#endif
    size_t i;
    uint32_t kept = 0, valid = 0;
    mtt_meas mi;
    mtt_meas_cov ci;
    for (i = 0; i < n; ++i) {
        const int skip = frame_get(&in, i, &mi, &ci);
        if (skip != SKIP_NONE) {
            ++*((skip == SKIP_RANGE) ? MTT_MEAS_RANGE(&trk->stats.last) : &trk->stats.last.meas_bad);
            continue;
        }
        ++valid;
        if (kept < MTT_MAX_MEAS) {
#if MTT_WITH_POLAR
            if (pol != NULL) {
                store_meas(&trk->meas[kept], &mi, &ci, (uint32_t)i); /* converted once */
            }
#endif
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
#if MTT_WITH_POLAR
    if (pol != NULL) {
        polar_store_sorted(trk, &in, kept, valid == kept);
    } else
#endif
    {
        sort_canonical(sel, trk->sel_tmp, kept, &in);
    }
#if MTT_WITH_MEAS_COV
    trk->n_own_r = 0;
    trk->own_rmax[0] = MTT_ZERO;
    trk->own_rmax[1] = MTT_ZERO;
#endif
    for (i = 0; i < kept; ++i) {
#if MTT_WITH_POLAR
        const uint32_t src = (pol != NULL) ? trk->meas[i].src : sel[i];
        if (pol == NULL) {
            (void)frame_get(&in, src, &mi, &ci);
            store_meas(&trk->meas[i], &mi, &ci, src);
        }
        trk->meas[i].rng = (pol != NULL) ? pol[src].range : MTT_ZERO;
        trk->meas[i].has_rdot = (uint8_t)(pol != NULL && pol[src].has_range_rate);
        trk->meas[i].rr[0] = trk->meas[i].has_rdot ? pol[src].range_rate : MTT_ZERO;
        trk->meas[i].rr[1] = trk->meas[i].has_rdot ? trk->par.range_rate_sigma * trk->par.range_rate_sigma : MTT_ZERO;
#else
        (void)frame_get(&in, sel[i], &mi, &ci);
        store_meas(&trk->meas[i], &mi, &ci, sel[i]);
#if MTT_WITH_MEAS_COV
        trk->meas[i].rng = MTT_ZERO;
        trk->meas[i].has_rdot = 0; /* no polar detections in this build (§3.2) */
        trk->meas[i].rr[0] = MTT_ZERO;
        trk->meas[i].rr[1] = MTT_ZERO;
#endif
#endif
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
#if MTT_WITH_POLAR
        trk->row.rr[i] = ms->has_rdot ? ms->rr : NULL;
#else
        trk->row.rr[i] = NULL;
#endif
        own = (uint16_t)(own + ms->has_R);
    }
    return own;
}
#endif
