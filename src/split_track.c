/* split_track.c - the split-target stage (ALGORITHMS.md §14.3): the "just
 * split" (model 5) and "split" (model 6) modes of every confirmed IMM
 * track, their mode probabilities from the model likelihoods over the
 * track's validated set, and the decoupling of a split track into two
 * tracks.  The arithmetic is split.c's; this file sequences it over the
 * track table, after the update stage (tracker.c), with split = true.
 *
 * The mode set is the IMM's r single-target models (imm.c, imm_track.c,
 * unchanged) followed by the two split modes.  The track's mu[] stay the
 * single-target mode probabilities conditioned on "no split"; the split
 * modes' probabilities μ_5, μ_6 (and their stacked states) live in a slot
 * of the tracker's pool (MTT_MAX_SPLIT_TRACKS), taken only while μ_5 + μ_6
 * is not negligible.  Transitions (ALGORITHMS.md §14.3 [CHOICE]: splits
 * start from cv, a "just split" lasts one scan):
 *   c̄_5 = p25 (1 - μ_5 - μ_6) c̄_cv          (c̄_cv: the predicted cv mode of imm_track.c)
 *   c̄_6 = (1 - p52) μ_5 + (1 - p62) μ_6
 *   c̄_s = 1 - c̄_5 - c̄_6                      (the single-target modes together)
 * and the mode update μ ∝ c̄ Λ with, on the scale of the IPDA likelihood
 * ratio (all-clutter density = 1, ALGORITHMS.md §14.2):
 *   Λ_s = 1 - PD PG + PD PG Σ_j p*_j / λ_j     (the track's gated pairs, p* model-mixed)
 *   Λ_5 = mtt_split_just on the cv prediction, V = 1/λ, β_j ∝ p*_j / λ_j
 *   Λ_6 = mtt_split_joint (parametric events, λ known or estimated).
 * Model 5 starts from the cv model's prediction; model 6 from the
 * moment-matched mixture of the two split modes' stacked states, predicted
 * with the cv model's F and Q per target (mtt_split_predict).  Model 6's
 * validated set is the frame's measurements in either of its two
 * per-target gates.
 *
 * Decoupling ([S3] eq. 27): when model 6's prediction passes
 * mtt_split_decouple (d² >= 9.21) and μ_5 + μ_6 >= 1/2 after the update,
 * the updated stacked state of model 6 is separated: the parent's every
 * model takes (x_1, P_11) as its common part, and a new track (fresh
 * identity, parent recorded) starts from (x_2, P_22) in every model
 * (mtt_imm_seed_track), existence P_parent (μ_5 + μ_6), confirmed when the
 * parent is: a confident split is reported at once.
 * Only confirmed tracks carry the split modes (a tentative track is not
 * yet a target that can split).  The reported estimate of a track stays
 * the single-target IMM's (the split modes enter it at decoupling). */
#include <string.h>

#include "mtt_internal.h"

#if MTT_WITH_SPLIT

#define SPLIT_KEEP MTT_R(1e-4)  /* μ_5 + μ_6 below: the split modes are dropped */
#define SPLIT_DECIDE MTT_R(0.5) /* μ_5 + μ_6 at or above: a decoupled split is two tracks */
#define N1 MTT_STATE_N          /* the split modes are built on the cv model */
#define NS (2 * MTT_STATE_N)

/* Index of the first cv model of imm_models (mtt_params_check: there is one). */
static uint8_t cv_model(const mtt_params *p)
{
    uint8_t j;
    for (j = 0; j + 1u < p->imm_n_models; ++j) {
        if (p->imm_model[j] == MTT_MODEL_CV) {
            break;
        }
    }
    return j;
}

/* Model 6's start: the moment-matched mixture of the split modes' stacked
 * states with weights w[0] (mode 5) and w[1] (mode 6), Σ w = 1. */
static void mix_stacked(const mtt_split_slot *sl, const mtt_real w[2], mtt_split_state x0,
                        mtt_split_cov P0)
{
    mtt_real d[2][NS];
    int a, b, k;
    for (a = 0; a < NS; ++a) {
        x0[a] = sl->xs[0][a] + w[1] * (sl->xs[1][a] - sl->xs[0][a]);
        d[0][a] = sl->xs[0][a] - x0[a];
        d[1][a] = sl->xs[1][a] - x0[a];
    }
    for (a = 0; a < NS; ++a) {
        for (b = 0; b < NS; ++b) {
            mtt_real s = MTT_R(0.0);
            for (k = 0; k < 2; ++k) {
                s += w[k] * (sl->Ps[k][a][b] + d[k][a] * d[k][b]);
            }
            P0[a][b] = s;
        }
    }
}

/* Model 6's validated set: the measurements inside the bounding box of
 * either target's gate (sqrt(γ S_t) per axis); mtt_split_assoc_init gates
 * them exactly.  Beyond MTT_MAX_SPLIT_MEAS the rest are left out. */
static uint16_t split_candidates(mtt_tracker *trk, const mtt_split_state xp, mtt_split_cov Pp)
{
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_real w[2][2];
    uint16_t j, m = 0;
    int t;
    for (t = 0; t < 2; ++t) {
        const int o = t * N1;
        w[t][0] = mtt_sqrt(trk->gamma * (Pp[o][o] + trk->R[0]));
        w[t][1] = mtt_sqrt(trk->gamma * (Pp[o + 1][o + 1] + trk->R[2]));
    }
    for (j = 0; j < trk->n_meas && m < MTT_MAX_SPLIT_MEAS; ++j) {
        const mtt_mstore *ms = &trk->meas[j];
        int in = 0;
        for (t = 0; t < 2; ++t) {
            const int o = t * N1;
            in |= mtt_fabs(ms->x - xp[o]) <= w[t][0] && mtt_fabs(ms->y - xp[o + 1]) <= w[t][1];
        }
        if (in) {
            sc->z[m][0] = ms->x;
            sc->z[m][1] = ms->y;
            sc->zi[m] = j;
            ++m;
        }
    }
    return m;
}

/* Model 6 of track ti from its slot: mixing, prediction, joint events and
 * the coupled update into sc->x5/P5's sibling (written to sc->x0/P0).
 * Returns Λ_6 (0 when it cannot run), *dec = 1 when the prediction passes
 * the decoupling test. */
static mtt_real model6(mtt_tracker *trk, uint16_t ti, const mtt_split_slot *sl, mtt_real dt,
                       const mtt_real w[2], int *dec)
{
    mtt_split_scratch *sc = &trk->split_scr;
    const mtt_params *p = &trk->par;
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_cov F, Q;
    mtt_real d2;
    uint16_t m;
    int a;
    *dec = 0;
    mix_stacked(sl, w, sc->x0, sc->P0);
    memset(F, 0, sizeof F);
    for (a = 0; a < N1; ++a) {
        F[a][a] = MTT_R(1.0);
    }
    F[0][2] = dt;
    F[1][3] = dt;
    mtt_motion_q(dt, p->imm_psd[cv_model(p)], Q);
    if (mtt_split_predict(N1, F, Q, sc->x0, sc->P0, sc->xp, sc->Pp) != 0) {
        return MTT_R(0.0);
    }
    *dec = mtt_split_decouple(N1, sc->xp, sc->Pp, trk->R, MTT_SPLIT_CHI2_99, &d2) == 1;
    m = split_candidates(trk, sc->xp, sc->Pp);
    if (mtt_split_assoc_init(N1, sc->xp, sc->Pp, trk->R, m, sc->z, p->pd, p->pg, trk->gamma, tf->vg,
                             tf->lambda, &sc->as) != 0 ||
        mtt_split_joint(&sc->as) != 0 ||
        mtt_split_update(&sc->as, sc->xp, sc->Pp, trk->R, sc->z, sc->x0, sc->P0) != 0) {
        *dec = 0;
        return MTT_R(0.0);
    }
    return sc->as.lik;
}

/* Λ_s of the single-target modes and model 5 (into sc->x5, sc->P5) over
 * the track's gated pairs; returns Λ_5 (0 with fewer than 2). */
static mtt_real model5(mtt_tracker *trk, uint16_t ti, mtt_real *lam_s)
{
    mtt_split_scratch *sc = &trk->split_scr;
    const mtt_params *p = &trk->par;
    mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t c = cv_model(p);
    const uint16_t m = tf->pair_count;
    mtt_real sum = MTT_R(0.0), lik = MTT_R(0.0);
    uint16_t j;
    for (j = 0; j < m; ++j) {
        const mtt_pair *pp = &trk->pairs[tf->pair_first + j];
        const mtt_real r = (pp->lam > MTT_R(0.0)) ? pp->p / pp->lam : MTT_R(0.0);
        sc->z[j][0] = trk->meas[pp->meas].x;
        sc->z[j][1] = trk->meas[pp->meas].y;
        sc->beta[j] = r;
        sum += r;
    }
    *lam_s = MTT_R(1.0) - p->pd * p->pg + p->pd * p->pg * sum;
    if (m < 2u || !(sum > MTT_R(0.0)) || !(tf->lambda > MTT_R(0.0))) {
        return MTT_R(0.0);
    }
    for (j = 0; j < m; ++j) {
        sc->beta[j] /= sum; /* only their order and ratios matter (§14.3 model 5) */
    }
    if (mtt_split_just(N1, tf->xpm[c], tf->Ppm[c], trk->R, m, sc->z, sc->beta, MTT_R(1.0) / tf->lambda,
                       sc->x5, sc->P5, sc->cluster, sc->beta_n, &lik) != 0) {
        return MTT_R(0.0);
    }
    return lik;
}

/* Free slot of the pool, or MTT_SPLIT_NONE. */
static uint8_t slot_take(mtt_tracker *trk)
{
    uint8_t k;
    for (k = 0; k < MTT_MAX_SPLIT_TRACKS; ++k) {
        if (!trk->split[k].used) {
            trk->split[k].used = 1;
            return k;
        }
    }
    return MTT_SPLIT_NONE;
}

/* Decoupling: the parent takes (x_1, P_11) of the stacked state in every
 * model (extras kept, their cross covariance with the common part zeroed),
 * the child starts from (x_2, P_22).  0, or -1 when nothing was done. */
static int decouple(mtt_tracker *trk, uint16_t ti, mtt_real ps, mtt_real dt)
{
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_track *t = &trk->tracks[ti];
    mtt_state x1, x2;
    mtt_cov P1, P2;
    uint8_t j, a, b;
    int ci;
    memset(x1, 0, sizeof x1);
    memset(x2, 0, sizeof x2);
    memset(P1, 0, sizeof P1);
    memset(P2, 0, sizeof P2);
    if (mtt_split_separate(N1, sc->x0, sc->P0, x1, P1, x2, P2) != 0) {
        return -1;
    }
    ci = mtt_track_append(trk, x2, P2, t->existence * ps, t->confirmed, 1);
    if (ci < 0) {
        trk->stats.last.split_dropped++;
        return -1;
    }
    mtt_imm_seed_track(trk, (uint16_t)ci, dt);
    trk->tracks[ci].parent = t->id;
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        for (a = 0; a < MTT_MAX_STATE; ++a) {
            if (a < N1) {
                t->xm[j][a] = x1[a];
            }
            for (b = 0; b < MTT_MAX_STATE; ++b) {
                if (a < N1 && b < N1) {
                    t->Pm[j][a][b] = P1[a][b];
                } else if (a < N1 || b < N1) {
                    t->Pm[j][a][b] = MTT_R(0.0);
                }
            }
        }
    }
    memcpy(t->x, x1, sizeof t->x);
    memcpy(t->P, P1, sizeof t->P);
    trk->stats.last.splits++;
    return 0;
}

/* The split modes of one confirmed IMM track after its update. */
static void split_track(mtt_tracker *trk, uint16_t ti, mtt_real dt)
{
    const mtt_params *p = &trk->par;
    mtt_track *t = &trk->tracks[ti];
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_split_slot *sl = (t->split_slot != MTT_SPLIT_NONE) ? &trk->split[t->split_slot] : NULL;
    const mtt_real m5 = (sl != NULL) ? sl->mu[0] : MTT_R(0.0);
    const mtt_real m6 = (sl != NULL) ? sl->mu[1] : MTT_R(0.0);
    const mtt_real c5 = p->split_p25 * (MTT_R(1.0) - m5 - m6) * trk->tf[ti].cbar[cv_model(p)];
    const mtt_real c6 = (MTT_R(1.0) - p->split_p52) * m5 + (MTT_R(1.0) - p->split_p62) * m6;
    const mtt_real cs = MTT_R(1.0) - c5 - c6;
    mtt_real lam_s, lam5, lam6 = MTT_R(0.0), c, mu5, mu6;
    int dec = 0;
    uint16_t j;
    if (c6 > MTT_R(0.0)) {
        const mtt_real w[2] = {(MTT_R(1.0) - p->split_p52) * m5 / c6, (MTT_R(1.0) - p->split_p62) * m6 / c6};
        lam6 = model6(trk, ti, sl, dt, w, &dec);
    }
    lam5 = model5(trk, ti, &lam_s);
    c = cs * lam_s + c5 * lam5 + c6 * lam6;
    if (c > MTT_R(0.0) && mtt_isfinite(c)) {
        mu5 = c5 * lam5 / c;
        mu6 = c6 * lam6 / c;
    } else {
        mu5 = MTT_R(0.0);
        mu6 = MTT_R(0.0);
    }
    t->p_split = mu5 + mu6;
    if (mu6 > MTT_R(0.0) && t->p_split >= SPLIT_DECIDE) {
        /* the child's measurements are not a new target for initiation */
        for (j = 0; j < sc->as.m; ++j) {
            if (sc->as.beta[1][j] >= MTT_R(0.5)) {
                trk->meas[sc->zi[j]].used = 1;
            }
        }
        if (dec && decouple(trk, ti, t->p_split, dt) == 0) {
            mu5 = MTT_R(0.0);
            mu6 = MTT_R(0.0);
        }
    }
    if (!(mu5 + mu6 >= SPLIT_KEEP)) {
        if (sl != NULL) {
            sl->used = 0;
            t->split_slot = MTT_SPLIT_NONE;
        }
        return;
    }
    if (sl == NULL) {
        t->split_slot = slot_take(trk);
        if (t->split_slot == MTT_SPLIT_NONE) {
            trk->stats.last.split_dropped++; /* pool full: this track cannot split now */
            return;
        }
        sl = &trk->split[t->split_slot];
    }
    sl->mu[0] = mu5;
    sl->mu[1] = mu6;
    if (mu5 > MTT_R(0.0)) {
        memcpy(sl->xs[0], sc->x5, sizeof sl->xs[0]);
        memcpy(sl->Ps[0], sc->P5, sizeof sl->Ps[0]);
    }
    if (mu6 > MTT_R(0.0)) {
        memcpy(sl->xs[1], sc->x0, sizeof sl->xs[1]);
        memcpy(sl->Ps[1], sc->P0, sizeof sl->Ps[1]);
    }
}

void mtt_split_frame(mtt_tracker *trk, mtt_real dt)
{
    const uint16_t n = trk->n_tracks; /* children appended here are not visited */
    uint16_t i;
    if (!trk->par.split) {
        return;
    }
    /* The pool: a slot is used while a live track names it (deleted and
     * merged tracks have left the table). */
    for (i = 0; i < MTT_MAX_SPLIT_TRACKS; ++i) {
        trk->split[i].used = 0;
    }
    for (i = 0; i < n; ++i) {
        if (trk->tracks[i].split_slot != MTT_SPLIT_NONE) {
            trk->split[trk->tracks[i].split_slot].used = 1;
        }
    }
    for (i = 0; i < n; ++i) {
        mtt_track *t = &trk->tracks[i];
        if (!trk->tf[i].valid || t->born || !t->confirmed || !(dt > MTT_R(0.0))) {
            t->p_split = MTT_R(0.0);
            continue;
        }
        split_track(trk, i, dt);
    }
}

#endif /* MTT_WITH_SPLIT */
