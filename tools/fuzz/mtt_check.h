/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/mtt_check.h - invariants of a tracker after every frame, shared by
 * the libFuzzer harness tools/fuzz/fuzz_tracker.c and the soak program
 * tools/fuzz/soak.c.  Host only (stdio); header-only so each program
 * compiles it with its own flags.
 *
 * After each successful mtt_tracker_step the caller runs mtt_check_frame,
 * which verifies through the public API:
 *   - 0 <= count <= MTT_MAX_TRACKS;
 *   - every state and covariance entry, and every existence, is finite;
 *   - every covariance is symmetric (exactly: the library symmetrises) and
 *     positive definite (Cholesky in double, every pivot > 0);
 *   - every existence in [0, 1]; confirmed tracks stay confirmed;
 *   - identities strictly ascending, unique, and never reused: an identity
 *     not live in the previous frame is larger than any identity ever seen;
 *   - meas is -1 or an input index < n;
 *   - stats: last.frames = 1, last.meas_in = n, meas_bad and meas_dropped
 *     equal what the caller counted, pairs <= MTT_MAX_PAIRS, total = the sum
 *     of every last (modulo 2^32, as the library adds), and
 *     births - deletions - merges - numeric_deletions = count change.
 * The worst margins seen are kept for the soak's report.
 */
#ifndef MTT_FUZZ_MTT_CHECK_H
#define MTT_FUZZ_MTT_CHECK_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mtt/mtt.h"
#include "real_ops.h" /* mtt_isfinite, MTT_POS_OK, mtt_fx_to_double: private (src/) */

typedef struct mtt_check {
    /* identity bookkeeping */
    uint32_t prev_ids[MTT_MAX_TRACKS];
    uint8_t prev_confirmed[MTT_MAX_TRACKS];
    size_t n_prev;
    int64_t max_id_seen;          /* -1: none yet */
    size_t count_before;          /* live count before the step (after seeding) */
    mtt_counts sum;               /* sum of every stats.last */
    /* worst margins (soak report) */
    double min_pivot_rel;         /* min over tracks of min Cholesky pivot / max diagonal */
    double min_eig;               /* smallest eigenvalue of any P */
    double min_eig_rel;           /* smallest lambda_min / lambda_max */
    double max_asym;              /* largest |Pij - Pji| / sqrt(Pii Pjj) */
    double ex_min, ex_max;        /* existence range */
    uint64_t tracks_checked;
    uint64_t frames_checked;
    /* Seeded tracks whose P the caller knows is singular in double
     * precision but mtt_tracker_add_track accepted (its float Cholesky
     * can see rounding noise as a positive pivot: ROBUSTNESS.md finding
     * F1): exempt from the positive-definite check, counted. */
    uint32_t exempt[16];
    size_t n_exempt;
    uint64_t singular_seeds;
    uint64_t view_saturations;    /* fixed point: tracks whose view P left the variance format */
    char msg[256];                /* the violation, when a check fails */
} mtt_check;

static inline void mtt_check_init(mtt_check *c)
{
    memset(c, 0, sizeof *c);
    c->max_id_seen = -1;
    c->min_pivot_rel = 1.0;
    c->min_eig = HUGE_VAL;
    c->min_eig_rel = 1.0;
    c->max_asym = 0.0;
    c->ex_min = 1.0;
    c->ex_max = 0.0;
}

/* Smallest Cholesky pivot of a symmetric 4x4 (double), relative to the
 * largest diagonal; <= 0 when not positive definite. */
static inline double mtt_check_min_pivot(const double A[4][4])
{
    double L[4][4], dmax = 0.0, pmin = HUGE_VAL;
    int i, j, k;
    for (i = 0; i < 4; ++i)
        if (A[i][i] > dmax)
            dmax = A[i][i];
    if (!(dmax > 0.0))
        return -1.0;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j <= i; ++j) {
            double s = A[i][j];
            for (k = 0; k < j; ++k)
                s -= L[i][k] * L[j][k];
            if (i == j) {
                if (s / dmax < pmin)
                    pmin = s / dmax;
                if (!(s > 0.0))
                    return s / dmax <= 0.0 ? s / dmax : -1.0;
                L[i][i] = sqrt(s);
            } else {
                L[i][j] = s / L[j][j];
            }
        }
    }
    return pmin;
}

/* Eigenvalues of a symmetric 4x4 by cyclic Jacobi (double). */
static inline void mtt_check_eig(const double A0[4][4], double *lmin, double *lmax)
{
    double A[4][4];
    int sweep, p, q, k;
    memcpy(A, A0, sizeof A);
    for (sweep = 0; sweep < 30; ++sweep) {
        double off = 0.0, on = 0.0;
        for (p = 0; p < 4; ++p)
            for (q = 0; q < 4; ++q) {
                if (p == q)
                    on += A[p][q] * A[p][q];
                else
                    off += A[p][q] * A[p][q];
            }
        if (off <= 1e-30 * on)
            break;
        for (p = 0; p < 3; ++p) {
            for (q = p + 1; q < 4; ++q) {
                double theta, t, cs, sn;
                if (A[p][q] == 0.0)
                    continue;
                theta = (A[q][q] - A[p][p]) / (2.0 * A[p][q]);
                t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                cs = 1.0 / sqrt(t * t + 1.0);
                sn = t * cs;
                for (k = 0; k < 4; ++k) {
                    double akp = A[k][p], akq = A[k][q];
                    A[k][p] = cs * akp - sn * akq;
                    A[k][q] = sn * akp + cs * akq;
                }
                for (k = 0; k < 4; ++k) {
                    double apk = A[p][k], aqk = A[q][k];
                    A[p][k] = cs * apk - sn * aqk;
                    A[q][k] = sn * apk + cs * aqk;
                }
            }
        }
    }
    *lmin = *lmax = A[0][0];
    for (k = 1; k < 4; ++k) {
        if (A[k][k] < *lmin)
            *lmin = A[k][k];
        if (A[k][k] > *lmax)
            *lmax = A[k][k];
    }
}

#define MTT_CHECK_FAIL(c, ...)                                   \
    do {                                                         \
        snprintf((c)->msg, sizeof (c)->msg, __VA_ARGS__);        \
        return 0;                                                \
    } while (0)

static inline int mtt_check_finite(double v) { return v == v && fabs(v) <= 1.7976931348623157e308; }

/* The view's values in the user's units, and "finite": in the fixed-point
 * build (docs/FIXED_POINT.md §3) positions and velocities are in the
 * position format, covariances in the variance format, existence in Q30,
 * and a saturated value (MTT_FX_MAX / MTT_FX_MIN) is the non-finite one;
 * mtt_fx_to_double is the host boundary's conversion.  A covariance
 * entry of the view saturated by the variance format (not the tracker's
 * block-floating-point covariance) is counted in view_saturations and that
 * track's positive-definiteness check is skipped. */
#ifdef MTT_REAL_FIXED
#define MTT_CHECK_POS(x) mtt_fx_to_double((x), MTT_FX_POS_FRAC)
#define MTT_CHECK_VAR(x) mtt_fx_to_double((x), MTT_FX_VAR_FRAC)
#define MTT_CHECK_PROB(x) mtt_fx_to_double((x), MTT_FX_PROB_FRAC)
#define MTT_CHECK_FIN(x) mtt_isfinite(x)
#define MTT_CHECK_EPS (1.0 / 65536.0) /* the variance format's unit */
#else
#define MTT_CHECK_POS(x) ((double)(x))
#define MTT_CHECK_VAR(x) ((double)(x))
#define MTT_CHECK_PROB(x) ((double)(x))
#define MTT_CHECK_FIN(x) mtt_check_finite((double)(x))
#define MTT_CHECK_EPS ((double)MTT_REAL_EPS)
#endif

/* Call before the step (after any mtt_tracker_add_track), so the count
 * change is measured from here. */
static inline int mtt_check_before(mtt_check *c, const mtt_tracker *trk)
{
    size_t n = 0;
    if (mtt_tracker_count(trk, &n) != MTT_OK)
        MTT_CHECK_FAIL(c, "mtt_tracker_count failed before the step");
    c->count_before = n;
    return 1;
}

static inline void mtt_check_add(mtt_counts *t, const mtt_counts *l)
{
    t->frames += l->frames;
    t->meas_in += l->meas_in;
    t->meas_bad += l->meas_bad;
    t->meas_dropped += l->meas_dropped;
    t->pairs += l->pairs;
    t->pairs_dropped += l->pairs_dropped;
    t->gated_dropped += l->gated_dropped;
    t->clusters += l->clusters;
    t->births += l->births;
    t->births_dropped += l->births_dropped;
    t->merges += l->merges;
    t->merge_dropped += l->merge_dropped;
    t->deletions += l->deletions;
    t->numeric_deletions += l->numeric_deletions;
    t->confirmations += l->confirmations;
    t->meas_out_of_range += l->meas_out_of_range;
}

/* Verify the tracker after a successful step with n inputs of which
 * n_bad were invalid (NaN/Inf coordinate, bad amplitude).  Returns 1, or 0
 * with c->msg set. */
static inline int mtt_check_frame(mtt_check *c, const mtt_tracker *trk, size_t n, size_t n_bad)
{
    mtt_stats st;
    size_t count = 0, i, j, valid = n - n_bad, pp = 0;
    uint32_t ids[MTT_MAX_TRACKS];
    uint8_t conf[MTT_MAX_TRACKS];
    int64_t max_before = c->max_id_seen;
    long change;

    if (mtt_tracker_count(trk, &count) != MTT_OK)
        MTT_CHECK_FAIL(c, "mtt_tracker_count failed");
    if (count > MTT_MAX_TRACKS)
        MTT_CHECK_FAIL(c, "count %zu > MTT_MAX_TRACKS", count);
    if (mtt_tracker_stats(trk, &st) != MTT_OK)
        MTT_CHECK_FAIL(c, "mtt_tracker_stats failed");

    for (i = 0; i < count; ++i) {
        mtt_track_view v;
        double P[4][4], piv, lmin, lmax, ex;
        int a, b, view_sat;
        if (mtt_tracker_track(trk, i, &v) != MTT_OK)
            MTT_CHECK_FAIL(c, "mtt_tracker_track(%zu) failed", i);
        ids[i] = v.id;
        conf[i] = (uint8_t)(v.confirmed != 0);
        if (i > 0 && !(v.id > ids[i - 1]))
            MTT_CHECK_FAIL(c, "identities not strictly ascending: %u after %u", (unsigned)v.id,
                           (unsigned)ids[i - 1]);
        /* new identity: larger than every identity seen before this frame */
        while (pp < c->n_prev && c->prev_ids[pp] < v.id)
            ++pp;
        if (pp < c->n_prev && c->prev_ids[pp] == v.id) {
            if (c->prev_confirmed[pp] && !v.confirmed)
                MTT_CHECK_FAIL(c, "track %u lost its confirmation", (unsigned)v.id);
        } else if ((int64_t)v.id <= max_before) {
            MTT_CHECK_FAIL(c, "identity %u reused (max seen %lld)", (unsigned)v.id,
                           (long long)max_before);
        }
        if ((int64_t)v.id > c->max_id_seen)
            c->max_id_seen = v.id;
        if (v.meas < -1 || (v.meas >= 0 && (size_t)v.meas >= n))
            MTT_CHECK_FAIL(c, "track %u: meas index %ld out of [-1, %zu)", (unsigned)v.id,
                           (long)v.meas, n);
        ex = MTT_CHECK_PROB(v.existence);
        if (!MTT_CHECK_FIN(v.existence) || !(ex >= 0.0) || !(ex <= 1.0))
            MTT_CHECK_FAIL(c, "track %u: existence %g outside [0, 1]", (unsigned)v.id, ex);
        if (ex < c->ex_min)
            c->ex_min = ex;
        if (ex > c->ex_max)
            c->ex_max = ex;
        view_sat = 0;
        for (a = 0; a < 4; ++a) {
            if (!MTT_CHECK_FIN(v.x[a]))
                MTT_CHECK_FAIL(c, "track %u: x[%d] = %g not finite", (unsigned)v.id, a,
                               MTT_CHECK_POS(v.x[a]));
            for (b = 0; b < 4; ++b) {
                P[a][b] = MTT_CHECK_VAR(v.P[a][b]);
                if (!MTT_CHECK_FIN(v.P[a][b])) {
#ifdef MTT_REAL_FIXED
                    view_sat = 1;
                    continue;
#endif
                    MTT_CHECK_FAIL(c, "track %u: P[%d][%d] = %g not finite", (unsigned)v.id, a,
                                   b, P[a][b]);
                }
            }
        }
        if (view_sat) {
            c->view_saturations++;
            c->tracks_checked++;
            continue;
        }
        for (a = 0; a < 4; ++a) {
            if (!(P[a][a] > 0.0))
                MTT_CHECK_FAIL(c, "track %u: P[%d][%d] = %g not positive", (unsigned)v.id, a, a,
                               P[a][a]);
        }
        for (a = 0; a < 4; ++a) {
            for (b = a + 1; b < 4; ++b) {
                double asym = fabs(P[a][b] - P[b][a]) / sqrt(P[a][a] * P[b][b]);
                if (asym > c->max_asym)
                    c->max_asym = asym;
                if (P[a][b] != P[b][a])
                    MTT_CHECK_FAIL(c, "track %u: P not symmetric: P[%d][%d] = %.9g, P[%d][%d] = %.9g",
                                   (unsigned)v.id, a, b, P[a][b], b, a, P[b][a]);
            }
        }
        piv = mtt_check_min_pivot((const double(*)[4])P);
        for (j = 0; j < c->n_exempt; ++j)
            if (c->exempt[j] == v.id && !(piv > 0.0))
                piv = 1.0; /* known singular seed */
        if (!(piv > 0.0))
            MTT_CHECK_FAIL(c,
                           "track %u: P not positive definite (relative pivot %g); diag %g %g %g %g, "
                           "P01 %g P02 %g P13 %g P23 %g",
                           (unsigned)v.id, piv, P[0][0], P[1][1], P[2][2], P[3][3], P[0][1],
                           P[0][2], P[1][3], P[2][3]);
        if (piv < c->min_pivot_rel)
            c->min_pivot_rel = piv;
        mtt_check_eig((const double(*)[4])P, &lmin, &lmax);
        if (lmin < c->min_eig)
            c->min_eig = lmin;
        if (lmax > 0.0 && lmin / lmax < c->min_eig_rel)
            c->min_eig_rel = lmin / lmax;
        c->tracks_checked++;
    }

    /* stats of the last frame */
    if (st.last.frames != 1u)
        MTT_CHECK_FAIL(c, "stats.last.frames = %u", (unsigned)st.last.frames);
    if (st.last.meas_in != (uint32_t)n)
        MTT_CHECK_FAIL(c, "stats.last.meas_in = %u, passed %zu", (unsigned)st.last.meas_in, n);
    /* n_bad: malformed (meas_bad) or outside the build's range (meas_out_of_range,
     * fixed point only) */
    if (st.last.meas_bad + st.last.meas_out_of_range != (uint32_t)n_bad)
        MTT_CHECK_FAIL(c, "stats.last.meas_bad + meas_out_of_range = %u + %u, expected %zu",
                       (unsigned)st.last.meas_bad, (unsigned)st.last.meas_out_of_range, n_bad);
#ifndef MTT_REAL_FIXED
    if (st.last.meas_out_of_range != 0u)
        MTT_CHECK_FAIL(c, "stats.last.meas_out_of_range = %u in float",
                       (unsigned)st.last.meas_out_of_range);
#endif
    if (st.last.meas_dropped != (uint32_t)(valid > MTT_MAX_MEAS ? valid - MTT_MAX_MEAS : 0))
        MTT_CHECK_FAIL(c, "stats.last.meas_dropped = %u with %zu valid measurements",
                       (unsigned)st.last.meas_dropped, valid);
    if (st.last.pairs > MTT_MAX_PAIRS)
        MTT_CHECK_FAIL(c, "stats.last.pairs = %u > MTT_MAX_PAIRS", (unsigned)st.last.pairs);
    if (st.last.clusters > c->count_before)
        MTT_CHECK_FAIL(c, "stats.last.clusters = %u > %zu tracks", (unsigned)st.last.clusters,
                       c->count_before);
    if (st.max_cluster_tracks > c->count_before)
        MTT_CHECK_FAIL(c, "max_cluster_tracks = %u > %zu tracks",
                       (unsigned)st.max_cluster_tracks, c->count_before);
    change = (long)st.last.births - (long)st.last.deletions - (long)st.last.merges -
             (long)st.last.numeric_deletions;
    if ((long)count - (long)c->count_before != change)
        MTT_CHECK_FAIL(c,
                       "count %zu -> %zu but births %u - deletions %u - merges %u - numeric %u = %ld",
                       c->count_before, count, (unsigned)st.last.births,
                       (unsigned)st.last.deletions, (unsigned)st.last.merges,
                       (unsigned)st.last.numeric_deletions, change);
    if (st.last.births > (uint32_t)MTT_MAX_TRACKS)
        MTT_CHECK_FAIL(c, "births %u > MTT_MAX_TRACKS", (unsigned)st.last.births);
    mtt_check_add(&c->sum, &st.last);
    {
        /* field by field: mtt_counts may grow fields this check does not know */
#define MTT_CHECK_SUM(f)                                                                     \
    if (c->sum.f != st.total.f)                                                               \
        MTT_CHECK_FAIL(c, "stats.total." #f " = %u is not the sum of stats.last." #f " = %u", \
                       (unsigned)st.total.f, (unsigned)c->sum.f);
        MTT_CHECK_SUM(frames)
        MTT_CHECK_SUM(meas_in)
        MTT_CHECK_SUM(meas_bad)
        MTT_CHECK_SUM(meas_dropped)
        MTT_CHECK_SUM(pairs)
        MTT_CHECK_SUM(pairs_dropped)
        MTT_CHECK_SUM(gated_dropped)
        MTT_CHECK_SUM(clusters)
        MTT_CHECK_SUM(births)
        MTT_CHECK_SUM(births_dropped)
        MTT_CHECK_SUM(merges)
        MTT_CHECK_SUM(merge_dropped)
        MTT_CHECK_SUM(deletions)
        MTT_CHECK_SUM(numeric_deletions)
        MTT_CHECK_SUM(confirmations)
        MTT_CHECK_SUM(meas_out_of_range)
#undef MTT_CHECK_SUM
    }

    /* remember this frame's identities */
    for (j = 0; j < count; ++j) {
        c->prev_ids[j] = ids[j];
        c->prev_confirmed[j] = conf[j];
    }
    c->n_prev = count;
    c->count_before = count;
    c->frames_checked++;
    return 1;
}

/* Seeded tracks change the live set between steps: refresh the identity
 * list (they are new identities, larger than any seen). */
static inline int mtt_check_after_seed(mtt_check *c, const mtt_tracker *trk, uint32_t id)
{
    size_t count = 0, i;
    mtt_track_view v;
    if ((int64_t)id <= c->max_id_seen)
        MTT_CHECK_FAIL(c, "seeded identity %u reused (max seen %lld)", (unsigned)id,
                       (long long)c->max_id_seen);
    c->max_id_seen = id;
    if (mtt_tracker_count(trk, &count) != MTT_OK || count > MTT_MAX_TRACKS)
        MTT_CHECK_FAIL(c, "count after seeding");
    for (i = 0; i < count; ++i) {
        if (mtt_tracker_track(trk, i, &v) != MTT_OK)
            MTT_CHECK_FAIL(c, "view after seeding");
        c->prev_ids[i] = v.id;
        c->prev_confirmed[i] = (uint8_t)(v.confirmed != 0);
    }
    c->n_prev = count;
    c->count_before = count;
    return 1;
}

/* Is a 4x4 row-major covariance positive definite, with a margin that
 * mtt_real arithmetic can keep (finding F1)? */
static inline int mtt_check_pd16(const mtt_real P16[16])
{
    double A[4][4];
    int a, b;
    for (a = 0; a < 4; ++a)
        for (b = 0; b < 4; ++b)
            A[a][b] = 0.5 * (MTT_CHECK_VAR(P16[4 * a + b]) + MTT_CHECK_VAR(P16[4 * b + a]));
    /* well conditioned for mtt_real: a relative pivot below ~1000 eps
     * cannot survive a float (or double) prediction and update */
    return mtt_check_min_pivot((const double(*)[4])A) > 1e3 * MTT_CHECK_EPS;
}

/* The caller seeded track id with a P that is singular, or too badly
 * conditioned for mtt_real, and the library accepted it (finding F1). */
static inline void mtt_check_exempt(mtt_check *c, uint32_t id)
{
    c->singular_seeds++;
    if (c->n_exempt < sizeof c->exempt / sizeof c->exempt[0])
        c->exempt[c->n_exempt++] = id;
}

/* Is this input measurement one the library must skip as bad? */
static inline int mtt_check_meas_bad(const mtt_meas *m)
{
#ifdef MTT_REAL_FIXED
    if (!MTT_POS_OK(m->x) || !MTT_POS_OK(m->y))
        return 1;
    if (m->has_amplitude && (!mtt_isfinite(m->amplitude) || m->amplitude < 0))
        return 1;
#else
    if (!mtt_check_finite((double)m->x) || !mtt_check_finite((double)m->y))
        return 1;
    if (m->has_amplitude &&
        (!mtt_check_finite((double)m->amplitude) || !(m->amplitude >= MTT_R(0.0))))
        return 1;
#endif
    return 0;
}

#endif /* MTT_FUZZ_MTT_CHECK_H */
