/* update.c - state and existence update of every gated track.
 *
 * IHPDA modes (spec 7.4, 10.3): the assigned (or, in `ihpda`, selected)
 * measurement z_s with its beta recomputed over the gate minus the
 * measurements assigned to other tracks; existence P = L_s P^/(1-P^+L_s P^);
 * state x = x^ + beta_s K nu_s, P = beta0 P^ + beta_s P_c + beta_s beta0 K nu nu' K'.
 * IPDA modes (spec 6): all gated measurements, PDA update.
 * JPDA family (spec 13.8): the PDA update with the track's beta row from
 * jpda.c / jpda_approx.c / jpda_adaptive.c; NNJPDA the hard Kalman update
 * with the assigned measurement (beta 1, beta0 0); existence from the
 * association stage (spec 13.2).
 * A track with no measurement keeps its prediction, with L = 1 - PD PG. */
#include "mtt_internal.h"

static int is_ihpda_mode(mtt_assoc a)
{
    return a == MTT_ASSOC_LM_IHPDA || a == MTT_ASSOC_IHPDA || a == MTT_ASSOC_IHPDA_2D;
}

/* Constant 0 without the baselines, so their update code is not linked. */
static int is_jpda_mode(mtt_assoc a)
{
    return MTT_WITH_BASELINES && a >= MTT_ASSOC_JIPDA && a < MTT_ASSOC_COUNT;
}

static void keep_prediction(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    int i, k;
    for (i = 0; i < 4; ++i) {
        t->x[i] = tf->xp[i];
        for (k = 0; k < 4; ++k) {
            t->P[i][k] = tf->Pp[i][k];
        }
    }
    t->existence = mtt_existence_update(tf->ex_pred, MTT_R(1.0) - trk->par.pd * trk->par.pg);
    t->meas = -1;
}

/* spec 10.3's set G_f = G minus the measurements assigned to other tracks
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

/* Single-measurement update with pair k (spec 7.4). */
static void update_one(mtt_tracker *trk, uint16_t ti, uint16_t k)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    const mtt_pair *pp = &trk->pairs[k];
    const mtt_mstore *ms = &trk->meas[pp->meas];
    mtt_real nu[1][2];
    mtt_real beta[1];
    nu[0][0] = ms->x - tf->xp[0];
    nu[0][1] = ms->y - tf->xp[1];
    beta[0] = pp->beta;
    mtt_kalman_pda(tf->xp, tf->Pp, tf->K, tf->Si, trk->R, 1, nu, beta,
                   MTT_R(1.0) - pp->beta, t->x, t->P);
    t->existence = mtt_existence_update(tf->ex_pred, pp->L);
    t->meas = (int32_t)ms->src;
}

static void update_pda(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real *p = trk->row.p, *lam = trk->row.lam, *beta = trk->row.beta;
    mtt_real(*nu)[2] = trk->row.nu;
    mtt_real beta0, L;
    uint16_t m = tf->pair_count, j, b = 0;
    for (j = 0; j < m; ++j) {
        const mtt_pair *pp = &trk->pairs[tf->pair_first + j];
        p[j] = pp->p;
        lam[j] = pp->lam;
        nu[j][0] = trk->meas[pp->meas].x - tf->xp[0];
        nu[j][1] = trk->meas[pp->meas].y - tf->xp[1];
    }
    mtt_ipda_betas(trk->par.pd, trk->par.pg, p, lam, m, beta, &beta0, &L);
    for (j = 1; j < m; ++j) {
        if (beta[j] > beta[b]) {
            b = j;
        }
    }
    mtt_kalman_pda(tf->xp, tf->Pp, tf->K, tf->Si, trk->R, m, nu, beta, beta0, t->x, t->P);
    t->existence = mtt_existence_update(tf->ex_pred, L);
    t->meas = (int32_t)trk->meas[trk->pairs[tf->pair_first + b].meas].src;
}

/* JPDA family: PDA update with the beta row of the association stage
 * (spec 13.8); the reported measurement is the largest beta. */
static void update_jpda(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real *beta = trk->row.beta;
    mtt_real(*nu)[2] = trk->row.nu;
    uint16_t m = tf->pair_count, j, b = 0;
    for (j = 0; j < m; ++j) {
        const mtt_pair *pp = &trk->pairs[tf->pair_first + j];
        beta[j] = pp->beta;
        nu[j][0] = trk->meas[pp->meas].x - tf->xp[0];
        nu[j][1] = trk->meas[pp->meas].y - tf->xp[1];
        if (beta[j] > beta[b]) {
            b = j;
        }
    }
    mtt_kalman_pda(tf->xp, tf->Pp, tf->K, tf->Si, trk->R, m, nu, beta, tf->beta0, t->x, t->P);
    t->existence = tf->ex_post;
    t->meas = (int32_t)trk->meas[trk->pairs[tf->pair_first + b].meas].src;
}

/* NNJPDA: hard Kalman update with the assigned pair (spec 13.5), or the
 * prediction; existence per spec 13.2 either way. */
static void update_nn(mtt_tracker *trk, uint16_t ti)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    if (tf->assigned < 0) {
        keep_prediction(trk, ti);
    } else {
        const mtt_mstore *ms = &trk->meas[trk->pairs[tf->assigned].meas];
        mtt_real nu[1][2];
        const mtt_real one[1] = {MTT_R(1.0)};
        nu[0][0] = ms->x - tf->xp[0];
        nu[0][1] = ms->y - tf->xp[1];
        mtt_kalman_pda(tf->xp, tf->Pp, tf->K, tf->Si, trk->R, 1, nu, one, MTT_R(0.0), t->x, t->P);
        t->meas = (int32_t)ms->src;
    }
    t->existence = tf->ex_post;
}

void mtt_update_frame(mtt_tracker *trk)
{
    const mtt_assoc mode = trk->par.association;
    uint16_t i, k;

    if (mode == MTT_ASSOC_IHPDA) {
        /* Each track selects on its own full gate; tracks may share (spec 15.1). */
        for (i = 0; i < trk->n_tracks; ++i) {
            mtt_track_frame *tf = &trk->tf[i];
            tf->assigned = -1;
            if (tf->valid && tf->pair_count > 0u) {
                (void)mtt_ihpda_row(trk, i, 0, -1, 1, &tf->assigned);
            }
        }
        for (i = 0; i < trk->n_tracks; ++i) {
            if (trk->tf[i].assigned >= 0) {
                trk->meas[trk->pairs[trk->tf[i].assigned].meas].used = 1;
            }
        }
    }
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        if (!tf->valid) {
            continue; /* deleted by the manager (spec 3) */
        }
        if (is_ihpda_mode(mode)) {
            if (tf->assigned < 0) {
                keep_prediction(trk, i);
            } else {
                if (mode != MTT_ASSOC_IHPDA && final_set_changed(trk, i)) {
                    /* spec 10.3: recompute over G minus the measurements
                     * assigned to other tracks. */
                    int16_t best;
                    (void)mtt_ihpda_row(trk, i, 1, tf->assigned, 0, &best);
                }
                update_one(trk, i, (uint16_t)tf->assigned);
            }
        } else if (tf->pair_count == 0u) {
            keep_prediction(trk, i);
        } else if (is_jpda_mode(mode) && mode == MTT_ASSOC_NNJPDA) {
            update_nn(trk, i);
        } else if (is_jpda_mode(mode)) {
            update_jpda(trk, i);
        } else {
            update_pda(trk, i);
        }
        /* spec 3 deletes a track whose S is not positive definite; the same
         * for its covariance, which float arithmetic can lose for extreme
         * priors (a velocity variance 1e30 beside a position variance of 4:
         * fuzz finding F7).  The manager counts it in numeric_deletions. */
        if (!mtt_cov_ok(trk->tracks[i].P, MTT_FRAME_COV_MARGIN)) {
            tf->valid = 0;
        }
    }
    if (!is_ihpda_mode(mode) && mode != MTT_ASSOC_NNJPDA) {
        /* PDA modes: a measurement inside any gate is used; NNJPDA and the
         * IHPDA modes mark assigned / selected ones only (spec 15.1). */
        for (k = 0; k < trk->n_pairs; ++k) {
            trk->meas[trk->pairs[k].meas].used = 1;
        }
    }
}
