/* tracker.c - the per-frame pipeline (spec 15, DESIGN.md stages 1-10) and
 * the tracker's public functions.  This file only sequences the stages;
 * each stage computes in its own file. */
#include <string.h>

#include "mtt_internal.h"

/* ---- helpers ---- */

static uint32_t cycles_now(const mtt_tracker *trk)
{
    return (trk->par.cycle_counter != NULL) ? trk->par.cycle_counter(trk->par.cycle_ctx) : 0u;
}

/* Charge the cycles since *mark to stage s (wraps modulo 2^32 correctly). */
static void charge(mtt_tracker *trk, mtt_stage s, uint32_t *mark)
{
    uint32_t now = cycles_now(trk);
    trk->stats.stage_cycles[s] = now - *mark;
    *mark = now;
}

static int finite4(const mtt_real x[4])
{
    return mtt_isfinite(x[0]) && mtt_isfinite(x[1]) && mtt_isfinite(x[2]) && mtt_isfinite(x[3]);
}

int mtt_track_append(mtt_tracker *trk, const mtt_real x[4], mtt_real P[4][4],
                     mtt_real existence, int confirmed, int born)
{
    mtt_track *t;
    if (trk->n_tracks >= MTT_MAX_TRACKS) {
        return -1;
    }
    t = &trk->tracks[trk->n_tracks];
    memcpy(t->x, x, sizeof t->x);
    memcpy(t->P, P, sizeof t->P);
    t->existence = existence;
    t->id = trk->next_id++;
    t->age = 0;
    t->meas = -1;
    t->confirmed = (uint8_t)(confirmed != 0);
    t->born = (uint8_t)(born != 0);
    t->dead = 0;
    return (int)trk->n_tracks++;
}

/* ---- stage 1: validate and select measurements ---- */

/* Strength order for the MTT_MAX_MEAS cap: an amplitude beats none, a
 * larger amplitude beats a smaller, then the earlier input wins. */
static int stronger(const mtt_meas *m, uint32_t i, uint32_t j)
{
    if (m[i].has_amplitude != m[j].has_amplitude) {
        return m[i].has_amplitude != 0;
    }
    if (m[i].has_amplitude && m[i].amplitude != m[j].amplitude) {
        return m[i].amplitude > m[j].amplitude;
    }
    return i < j;
}

/* Heap order with the weakest kept measurement at the root. */
static int sel_less(const void *a, const void *b, const void *ctx)
{
    return stronger((const mtt_meas *)ctx, *(const uint32_t *)a, *(const uint32_t *)b);
}

static int idx_less(const void *a, const void *b, const void *ctx)
{
    (void)ctx;
    return *(const uint32_t *)a < *(const uint32_t *)b;
}

static int meas_ok(const mtt_meas *m)
{
    if (!mtt_isfinite(m->x) || !mtt_isfinite(m->y)) {
        return 0;
    }
    return !m->has_amplitude || (mtt_isfinite(m->amplitude) && m->amplitude >= MTT_R(0.0));
}

static void store_meas(mtt_tracker *trk, const mtt_meas *m, uint32_t src)
{
    mtt_mstore *s = &trk->meas[trk->n_meas++];
    s->x = m->x;
    s->y = m->y;
    s->has_amp = (uint8_t)(m->has_amplitude != 0);
    s->amp = s->has_amp ? m->amplitude : MTT_R(0.0);
    s->src = src;
    s->used = 0;
}

static void select_meas(mtt_tracker *trk, const mtt_meas *meas, size_t n)
{
    size_t i;
    uint32_t kept = 0, valid = 0;
    trk->n_meas = 0;
    for (i = 0; i < n; ++i) {
        if (!meas_ok(&meas[i])) {
            trk->stats.last.meas_bad++;
            continue;
        }
        ++valid;
        if (kept < MTT_MAX_MEAS) {
            trk->sel[kept++] = (uint32_t)i;
            if (kept == MTT_MAX_MEAS) {
                uint32_t h;
                for (h = MTT_MAX_MEAS / 2u; h > 0u; --h) {
                    mtt_heap_sift(trk->sel, MTT_MAX_MEAS, sizeof trk->sel[0], h - 1u, sel_less, meas);
                }
            }
        } else if (stronger(meas, (uint32_t)i, trk->sel[0])) {
            trk->sel[0] = (uint32_t)i; /* the weakest kept one gives way */
            mtt_heap_sift(trk->sel, MTT_MAX_MEAS, sizeof trk->sel[0], 0u, sel_less, meas);
        }
    }
    trk->stats.last.meas_dropped = valid - kept;
    if (valid > kept) {
        mtt_sort(trk->sel, kept, sizeof trk->sel[0], idx_less, NULL); /* back to input order */
    }
    for (i = 0; i < kept; ++i) {
        store_meas(trk, &meas[trk->sel[i]], trk->sel[i]);
    }
}

/* ---- stage 2: predict ---- */

static void predict_all(mtt_tracker *trk, mtt_real dt)
{
    uint16_t i;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track *t = &trk->tracks[i];
        mtt_track_frame *tf = &trk->tf[i];
        t->born = 0;
        t->dead = 0;
        t->meas = -1;
        if (dt > MTT_R(0.0)) {
            mtt_kalman_predict(dt, trk->par.process_psd, t->x, t->P, tf->xp, tf->Pp);
            tf->ex_pred = mtt_existence_predict(t->existence, trk->par.markov_p11, trk->par.markov_p21);
            t->age++;
        } else {
            /* First frame: the state is already at this time (seeded tracks). */
            memcpy(tf->xp, t->x, sizeof tf->xp);
            memcpy(tf->Pp, t->P, sizeof tf->Pp);
            tf->ex_pred = t->existence;
        }
        tf->assigned = -1;
        tf->best = -1;
        tf->shrink = 0;
        tf->pair_first = 0;
        tf->pair_count = 0;
        tf->valid = (uint8_t)(finite4(tf->xp) &&
                              mtt_kalman_innov(tf->Pp, trk->R, tf->S, tf->Si, &tf->det_s, tf->K) == 0);
    }
}

/* ---- stage 10: delete, then confirm, then compact (spec 12.4) ---- */

static void manage(mtt_tracker *trk)
{
    uint16_t i, n = 0;
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track *t = &trk->tracks[i];
        if (!t->born && !trk->tf[i].valid) {
            trk->stats.last.numeric_deletions++;
            continue;
        }
        if (t->dead) {
            continue; /* merged away, counted in merges */
        }
        if (t->existence < trk->par.terminate_threshold) {
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

static void add_counts(mtt_counts *tot, const mtt_counts *c)
{
    tot->frames += c->frames;
    tot->meas_in += c->meas_in;
    tot->meas_bad += c->meas_bad;
    tot->meas_dropped += c->meas_dropped;
    tot->pairs += c->pairs;
    tot->pairs_dropped += c->pairs_dropped;
    tot->gated_dropped += c->gated_dropped;
    tot->clusters += c->clusters;
    tot->births += c->births;
    tot->births_dropped += c->births_dropped;
    tot->merges += c->merges;
    tot->merge_dropped += c->merge_dropped;
    tot->deletions += c->deletions;
    tot->numeric_deletions += c->numeric_deletions;
    tot->confirmations += c->confirmations;
    tot->assign_fallbacks += c->assign_fallbacks;
    tot->jpda_fallbacks += c->jpda_fallbacks;
}

/* ---- public ---- */

mtt_status mtt_tracker_init(mtt_tracker *trk, const mtt_params *p)
{
    mtt_status st;
    uint16_t m;
    if (trk == NULL || p == NULL) {
        return MTT_ERR_NULL;
    }
    st = mtt_params_check(p, NULL);
    if (st != MTT_OK) {
        return st;
    }
    memset(trk, 0, sizeof *trk);
    trk->par = *p;
    trk->gamma = mtt_gate_gamma(p->pg);
    trk->R[0] = p->meas_sigma[0] * p->meas_sigma[0];
    trk->R[1] = MTT_R(0.0);
    trk->R[2] = p->meas_sigma[1] * p->meas_sigma[1];
    /* rho is a global constant: tabulate P_r(l|m) once (spec 7.2). */
    for (m = 1; m <= MTT_MAX_GATED; ++m) {
        mtt_ihpda_prank(m, p->snr_rho, &trk->prank[MTT_PRANK_ROW(m)]);
    }
    trk->magic = MTT_MAGIC;
    return MTT_OK;
}

mtt_status mtt_tracker_step(mtt_tracker *trk, mtt_real time, const mtt_meas *meas, size_t n)
{
    mtt_real dt = MTT_R(0.0);
    uint32_t mark;
    uint16_t c;
    const mtt_assoc mode = (trk != NULL) ? trk->par.association : MTT_ASSOC_LM_IHPDA;
    if (trk == NULL || (meas == NULL && n > 0u)) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    if (!mtt_isfinite(time) || (trk->have_time && !(time > trk->time))) {
        return MTT_ERR_TIME;
    }
    if (trk->have_time) {
        dt = time - trk->time;
    }
    memset(&trk->stats.last, 0, sizeof trk->stats.last);
    memset(trk->stats.stage_cycles, 0, sizeof trk->stats.stage_cycles);
    trk->stats.last.frames = 1;
    trk->stats.last.meas_in = (uint32_t)n;
    mark = cycles_now(trk);

    select_meas(trk, meas, n);
    charge(trk, MTT_STAGE_VALIDATE, &mark);
    predict_all(trk, dt);
#if MTT_WITH_BASELINES
    if (mode == MTT_ASSOC_ADAPTIVE_JPDA) {
        mtt_adaptive_gates(trk); /* per-track gate thresholds (spec 13.7) */
    }
#endif
    charge(trk, MTT_STAGE_PREDICT, &mark);
    mtt_gate_frame(trk);
    charge(trk, MTT_STAGE_GATE, &mark);
    mtt_clutter_frame(trk, mode == MTT_ASSOC_LM_IHPDA || mode == MTT_ASSOC_LM_IPDA);
    charge(trk, MTT_STAGE_LM_CLUTTER, &mark);
    mtt_cluster_frame(trk);
    if (mode == MTT_ASSOC_LM_IHPDA) {
        for (c = 0; c < trk->n_clusters; ++c) {
            mtt_mmr_cluster(trk, c, 1);
        }
    }
#if MTT_WITH_BASELINES
    else if (mode == MTT_ASSOC_IHPDA_2D) {
        mtt_assign2d_frame(trk);
    } else if (mode >= MTT_ASSOC_JIPDA) {
        mtt_jpda_frame(trk); /* JIPDA and the JPDA family (spec 13) */
    }
#endif
    charge(trk, MTT_STAGE_ASSOCIATE, &mark);
    mtt_update_frame(trk);
    charge(trk, MTT_STAGE_UPDATE, &mark);
    mtt_initiate_frame(trk, dt);
    charge(trk, MTT_STAGE_INITIATE, &mark);
    mtt_merge_frame(trk);
    charge(trk, MTT_STAGE_MERGE, &mark);
    manage(trk);
    charge(trk, MTT_STAGE_MANAGE, &mark);

    trk->time = time;
    trk->have_time = 1;
    add_counts(&trk->stats.total, &trk->stats.last);
    return MTT_OK;
}

mtt_status mtt_tracker_add_track(mtt_tracker *trk, const mtt_real x[4], const mtt_real P16[16],
                                 uint32_t *id)
{
    mtt_real P[4][4];
    int i, j, idx;
    if (trk == NULL || x == NULL || P16 == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    if (!finite4(x)) {
        return MTT_ERR_VALUE;
    }
    memcpy(P, P16, sizeof P);
    for (i = 0; i < 4; ++i) {
        if (!finite4(P[i])) {
            return MTT_ERR_VALUE;
        }
        for (j = 0; j < i; ++j) {
            mtt_real tol = MTT_R(1e-6) * (mtt_fabs(P[i][j]) + mtt_fabs(P[j][i])) + MTT_REAL_EPS;
            if (mtt_fabs(P[i][j] - P[j][i]) > tol) {
                return MTT_ERR_VALUE;
            }
        }
    }
    /* Positive definite, and not nearly singular for mtt_real: every
     * scale-free pivot above 1000 eps (correlations up to about 0.99994 in
     * float); a seed past that cannot survive a predict and update. */
    if (!mtt_cov_ok(P, MTT_SEED_COV_MARGIN)) {
        return MTT_ERR_VALUE;
    }
    idx = mtt_track_append(trk, x, P, MTT_R(1.0), 1, 0);
    if (idx < 0) {
        return MTT_ERR_FULL;
    }
    mtt_sym4(trk->tracks[idx].P);
    if (id != NULL) {
        *id = trk->tracks[idx].id;
    }
    return MTT_OK;
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
    view->id = t->id;
    view->confirmed = t->confirmed;
    memcpy(view->x, t->x, sizeof view->x);
    memcpy(view->P, t->P, sizeof view->P);
    view->existence = t->existence;
    view->age = t->age;
    view->meas = t->meas;
    return MTT_OK;
}

mtt_status mtt_tracker_stats(const mtt_tracker *trk, mtt_stats *stats)
{
    if (trk == NULL || stats == NULL) {
        return MTT_ERR_NULL;
    }
    if (trk->magic != MTT_MAGIC) {
        return MTT_ERR_NOT_INIT;
    }
    *stats = trk->stats;
    return MTT_OK;
}

mtt_status mtt_init_two_point_cov(mtt_real sx, mtt_real sy, mtt_real dt, mtt_real P[4][4])
{
    mtt_real R[3];
    if (P == NULL) {
        return MTT_ERR_NULL;
    }
    if (!(sx > MTT_R(0.0)) || !(sy > MTT_R(0.0)) || !(dt > MTT_R(0.0)) ||
        !mtt_isfinite(sx) || !mtt_isfinite(sy) || !mtt_isfinite(dt)) {
        return MTT_ERR_VALUE;
    }
    R[0] = sx * sx;
    R[1] = MTT_R(0.0);
    R[2] = sy * sy;
    mtt_two_point_cov(R, dt, P);
    return MTT_OK;
}
