/* SPDX-License-Identifier: BSD-3-Clause */
/* track_table.c - the track table: append a track, seed a known one with
 * its checks, delete / confirm / compact at the end of a frame
 * (ALGORITHMS.md §12.4, §3), and the read-only views of the live tracks.
 * Fixed-point build (docs/FIXED_POINT.md §3): a seed's and a view's
 * covariance are in the variance format (MTT_COV_VIEW), the table's in
 * block floating point. */
#include <string.h>

#include "mtt_internal.h"

int mtt_track_append(mtt_tracker *trk, const mtt_state x, mtt_cov P, mtt_real existence,
                     int confirmed, int born)
{
    mtt_track *t;
    if (trk->n_tracks >= MTT_MAX_TRACKS) {
        return -1;
    }
    t = &trk->tracks[trk->n_tracks];
#if MTT_MAX_STATE > MTT_STATE_N
    {
        /* The model's MTT_STATE_N leading components; the rest of the
         * storage (MTT_MAX_STATE > MTT_STATE_N with IMM) is zero, so equal
         * inputs give equal tracker states byte for byte. */
        int i;
        memset(t->x, 0, sizeof t->x);
        memset(t->P, 0, sizeof t->P);
        for (i = 0; i < MTT_STATE_N; ++i) {
            t->x[i] = x[i];
            memcpy(t->P[i], P[i], MTT_STATE_N * sizeof P[i][0]);
        }
        MTT_COV_COPY_E(t->P, P);
    }
#else
    memcpy(t->x, x, sizeof t->x);
    memcpy(t->P, P, sizeof t->P);
#endif
    t->existence = existence;
    t->id = trk->next_id++;
    t->age = 0;
    t->meas = -1;
    t->confirmed = (uint8_t)(confirmed != 0);
    t->born = (uint8_t)(born != 0);
    t->dead = 0;
#if MTT_WITH_CONTEST
    mtt_adapt_track_init(t); /* ALGORITHMS.md §2.1: a new track has no history */
#endif
#if MTT_WITH_SPLIT
    t->p_split = MTT_R(0.0);
    t->parent = MTT_NO_PARENT;
    t->split_slot = MTT_SPLIT_NONE;
#endif
    return (int)trk->n_tracks++;
}

/* Delete (numerically invalid, merged away, existence below the terminate
 * threshold, lost), then confirm, then compact in place, keeping the order. */
/* γ R_kk: the measurement's own gate along k (0: x, 2: y), a variance. */
static mtt_real noise_gate(const mtt_tracker *trk, const mtt_real R[3], int k)
{
#ifdef MTT_REAL_FIXED
    const mtt_real Sk[MTT_SYM_SLOTS] = {R[0], R[1], R[2], -MTT_FX_VAR_FRAC};
    const mtt_pos w = MTT_GATE_WIDTH(trk->gamma, Sk, k); /* sqrt(γ R_kk), rounded up */
    return MTT_VAR_OF(w);
#else
    return trk->gamma * R[k];
#endif
}

/* Lost (ALGORITHMS.md §12.4 [CHOICE]): a track's position variance along x
 * or y beyond b = (vmax ΔT)^2 + γ R, the farthest a target flies between
 * frames and the measurement's own gate, ΔT the longer of this frame's
 * interval and the last one's (interleaved sensors).  Its gate then
 * reaches beyond the two-point start's, clutter keeps it alive, and a new
 * start does better.  b is the frame's, from meas_sigma's R; under polar
 * it is formed at each track with its converted R. */
static void lost_bound(const mtt_tracker *trk, const mtt_real R[3], mtt_real r2, mtt_real b[2])
{
    b[0] = MTT_ADDS(r2, noise_gate(trk, R, 0));
    b[1] = MTT_ADDS(r2, noise_gate(trk, R, 2));
}

static int lost(const mtt_tracker *trk, const mtt_track *t, mtt_real r2, const mtt_real b0[2])
{
    const mtt_real *b = b0;
#if MTT_WITH_POLAR
    mtt_real Rb[3], bp[2];
    if (trk->par.measurement == MTT_MEASUREMENT_POLAR) {
        lost_bound(trk, mtt_polar_track_r(trk, t->x, Rb), r2, bp);
        b = bp;
    }
#else
    (void)trk;
    (void)r2;
#endif
    return MTT_COV_VIEW(t->P, 0, 0) > b[0] || MTT_COV_VIEW(t->P, 1, 1) > b[1];
}

void mtt_track_manage(mtt_tracker *trk, mtt_real dt)
{
    /* the lost test's bound, once per frame; none for a track born this
     * frame (no update yet), nor with terminate_threshold 0 (never delete) */
    const mtt_real r = MTT_MUL_T((dt > trk->dt_last) ? dt : trk->dt_last, trk->par.vmax);
    const int check = (r > MTT_ZERO) && (trk->par.terminate_threshold > MTT_ZERO);
    mtt_real r2 = MTT_ZERO, b[2] = {MTT_ZERO, MTT_ZERO};
    uint16_t i, n = 0;
    if (check) {
        r2 = MTT_VAR_OF(r);
        lost_bound(trk, trk->R, r2, b);
    }
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track *t = &trk->tracks[i];
        if (!t->born && !trk->tf[i].valid) {
            trk->stats.last.numeric_deletions++;
            continue;
        }
        if (t->dead) {
            continue; /* merged away, counted in merges */
        }
        if (t->existence < trk->par.terminate_threshold || (check && !t->born && lost(trk, t, r2, b))) {
            trk->stats.last.deletions++;
            continue;
        }
        if (!t->confirmed && t->existence >= trk->par.confirm_threshold) {
            t->confirmed = 1;
            trk->stats.last.confirmations++;
        }
        if (n != i) {
            trk->tracks[n] = *t;
        }
        ++n;
    }
    trk->n_tracks = n;
}

/* A seed is symmetric to 1e-6 relative (the decimals of a settings file);
 * in the fixed build to 2^-20 relative plus one unit of the variance
 * format (its rounding). */
#ifdef MTT_REAL_FIXED
#define SYM_OK(a, b) (MTT_ABS(mtt_fx_sub((a), (b))) <= ((MTT_ABS(a) >> 21) + (MTT_ABS(b) >> 21) + 1))
#else
#define SYM_OK(a, b)                                                                               \
    (mtt_fabs((a) - (b)) <= MTT_R(1e-6) * (mtt_fabs(a) + mtt_fabs(b)) + MTT_REAL_EPS)
#endif

mtt_status mtt_tracker_add_track(mtt_tracker *trk, const mtt_real x[4], const mtt_real P16[16],
                                 uint32_t *id)
{
    mtt_cov P;
    mtt_state xs;
    int i, j, idx;
    if (trk == NULL || x == NULL || P16 == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    /* The public seed is a CV state [x, y, vx, vy] with its 4x4 P. */
    memset(xs, 0, sizeof xs);
    memset(P, 0, sizeof P);
    for (i = 0; i < 4; ++i) {
        xs[i] = x[i];
        for (j = 0; j < 4; ++j) {
            P[i][j] = P16[4 * i + j];
        }
    }
    if (!mtt_state_finite(xs)) {
        return MTT_ERR_VALUE;
    }
    for (i = 0; i < MTT_STATE_N; ++i) {
        if (!mtt_state_finite(P[i])) {
            return MTT_ERR_VALUE;
        }
        for (j = 0; j < i; ++j) {
            if (!SYM_OK(P[i][j], P[j][i])) {
                return MTT_ERR_VALUE;
            }
        }
    }
    /* Fixed point: the variance format's values as mantissas, then the
     * block's own exponent. */
    MTT_COV_SET_E(P, -MTT_FX_VAR_FRAC);
    MTT_COV_NORM(P);
    /* Positive definite, and not nearly singular for mtt_real: every
     * scale-free pivot above 1000 eps (correlations up to about 0.99994 in
     * float); a seed past that cannot survive a predict and update. */
    if (!mtt_cov_ok(P, MTT_SEED_COV_MARGIN)) {
        return MTT_ERR_VALUE;
    }
    idx = mtt_track_append(trk, xs, P, MTT_P(1.0), 1, 0);
    if (idx < 0) {
        return MTT_ERR_FULL;
    }
    mtt_sym(trk->tracks[idx].P);
#if MTT_WITH_IMM
    if (trk->par.motion == MTT_MOTION_IMM) {
        /* [CHOICE] ALGORITHMS.md §14.2: a seeded track's CA acceleration
         * variance is q_CA times one time unit (no interval is known) */
        mtt_imm_seed_track(trk, (uint16_t)idx, MTT_TIME(1.0));
    }
#endif
    if (id != NULL) {
        *id = trk->tracks[idx].id;
    }
    return MTT_OK;
}

void mtt_cov_view4(mtt_cov P, mtt_real out[4][4])
{
    int i, j;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            out[i][j] = MTT_COV_VIEW(P, i, j);
        }
    }
}

mtt_status mtt_tracker_count(const mtt_tracker *trk, size_t *count)
{
    if (trk == NULL || count == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    *count = trk->n_tracks;
    return MTT_OK;
}

mtt_status mtt_tracker_track(const mtt_tracker *trk, size_t i, mtt_track_view *view)
{
    const mtt_track *t;
    int k;
    if (trk == NULL || view == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    if (i >= trk->n_tracks) {
        return MTT_ERR_RANGE;
    }
    t = &trk->tracks[i];
    memset(view, 0, sizeof *view); /* every byte defined, padding included: views compare with memcmp */
    view->id = t->id;
    view->confirmed = t->confirmed;
    for (k = 0; k < 4; ++k) { /* the CV part: x, y, vx, vy */
        view->x[k] = t->x[k];
    }
    mtt_cov_view4((mtt_real(*)[MTT_MAX_STATE])t->P, view->P); /* read only */
    view->existence = t->existence;
    view->age = t->age;
    view->meas = t->meas;
    view->n_models = 1u;
    view->mu[0] = MTT_P(1.0);
#if MTT_WITH_IMM
    if (trk->par.motion == MTT_MOTION_IMM) {
        view->n_models = trk->par.imm_n_models;
        memcpy(view->mu, t->mu, sizeof view->mu);
    }
#endif
#if MTT_WITH_SPLIT
    view->split = (uint8_t)(trk->par.split != 0);
    view->p_split = t->p_split;
    view->parent = t->parent;
#else
    view->parent = MTT_NO_PARENT;
#endif
    return MTT_OK;
}
