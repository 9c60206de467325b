/* SPDX-License-Identifier: BSD-3-Clause */
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
 *   Λ_5 = mtt_split_just on its own prediction and gate (below), V = 1/λ
 *   Λ_6 = mtt_split_joint (parametric events, λ known or estimated);
 * a measurement outside a model's gate is clutter under it, factor 1 on
 * this scale, so the three compare over the union of their gates.
 * A measurement that another confirmed track holds is not in the split
 * modes' sets [CHOICE, one measurement, one target]: the one it reports,
 * and every other one in its gate unless a track reports it (owners).  A
 * target already tracked, or a detection it may have produced, is not the
 * second half of this one (after a decoupling the child's detections stay
 * in the parent's gate for a while; where tracks cross, their detections
 * and the clutter between them would otherwise start splits).
 * Model 5 starts from the cv model's prediction widened by the split's
 * velocity impulse (split_dv); model 6 from the
 * moment-matched mixture of the two split modes' stacked states, predicted
 * with the cv model's F and Q per target (mtt_split_predict).  Model 6's
 * validated set is the frame's measurements in either of its two
 * per-target gates.
 *
 * Decoupling ([S3] eq. 27): when model 6's stacked estimate passes
 * mtt_split_decouple (d² >= 9.21) and μ_5 + μ_6 >= split_decide (0.9)
 * after the update [CHOICE, a setting: 0.5 decouples clutter-driven splits
 * in crossing3], the updated stacked state of model 6 is separated.  The test
 * reads the updated stacked estimate (ẑ_t = H x_t) [CHOICE]: [S3] tests
 * the prediction, which decides on the previous scan's evidence and
 * reports the child one scan later.  Its covariance is H P_tt H' (the
 * halves' position estimates are apart at 99 %) [CHOICE], or with
 * split_decouple_r [S3]'s S_t = H P_tt H' + R (the halves' measurements
 * would be apart): R adds 2 R to the sum, which at 10 m noise held the
 * decoupling until the halves were 40 to 60 m apart.  Separated: the parent's every
 * model takes (x_1, P_11) as its common part, and a new track (fresh
 * identity, parent recorded) starts from (x_2, P_22) in every model
 * (mtt_imm_seed_track), existence P_parent (μ_5 + μ_6) [CHOICE: the
 * probability that the split happened and the parent exists], confirmed at
 * once when that reaches split_confirm (and the parent is confirmed) [CHOICE:
 * a rule of its own, the split's evidence in place of the ordinary
 * confirm_threshold]:
 * a confident split is reported at once, a doubtful one starts tentative
 * and is confirmed or deleted by the ordinary rule (ALGORITHMS.md §12.4).
 * Only confirmed tracks carry the split modes (a tentative track is not
 * yet a target that can split).
 *
 * split_known_speed (ALGORITHMS.md §14.3, "A split of known speed"):
 * model 5's child half from the prior moved by split_dv across the course
 * (mtt_split_known); when model 5's own gate holds fewer than 2
 * measurements, the late look (a gate widened across the course, the
 * child at the offsets a and a + 1, late_centres); and a split-off track
 * whose existence is below split_provisional_exist (0.6) in its first
 * split_provisional_scans (3) scans is deleted (the
 * provisional child, mtt_split_frame).
 *
 * A covariance per detection (ALGORITHMS.md §3.1, polar detections §3.2):
 * the validated sets carry each measurement's R (own, or meas_sigma's),
 * which split.c takes when one of them has its own; the windows widen as
 * the gate's (mtt_gate_own_widen), and the track's R is the polar one at
 * the predicted position; their range rates go with them (split.c), and
 * a detection with one in a confirmed track's position gate is left to
 * the split modes, not to initiation, even outside the track's range-rate
 * gate (hold_rdot).  The reported estimate of a track stays
 * the single-target IMM's (the split modes enter it at decoupling). */
#include <string.h>

#include "mtt_internal.h"

#if MTT_WITH_SPLIT

#define SPLIT_KEEP MTT_R(1e-4)  /* μ_5 + μ_6 below: the split modes are dropped */
#define N1 MTT_STATE_N          /* the split modes are built on the cv model */
/* split_known_speed (ALGORITHMS.md §14.3): the late look's offsets a and
 * a + 1, a = MTT_SPLIT_KNOWN_OFFSET (a split caught one scan late; a
 * third, a + 2, scored no better and took clutter), and its gate widened
 * across the course by KNOWN_LATE_REACH x split_dv dt: the farther offset
 * (a + 1) and a beyond it.  The provisional child's scans and existence
 * are the settings split_provisional_scans and split_provisional_exist. */
#define KNOWN_LATE_OFFSETS 2u
#define KNOWN_LATE_REACH                                                                           \
    (MTT_SPLIT_KNOWN_OFFSET + (mtt_real)(KNOWN_LATE_OFFSETS - 1u) + MTT_SPLIT_KNOWN_OFFSET)
#define NS (2 * MTT_STATE_N)
#define SPLIT_HELD_BY_MANY 0xFFFFu /* owner[]: held by two or more confirmed tracks */

/* The track's R at the predicted position xp: meas_sigma's; polar: at xp
 * (ALGORITHMS.md §3.2). */
static const mtt_real *track_r(const mtt_tracker *trk, const mtt_real *xp, mtt_real R[3])
{
#if MTT_WITH_MEAS_COV
    return mtt_polar_track_r(trk, xp, R);
#else
    (void)xp;
    (void)R;
    return trk->R;
#endif
}

/* The validated set's R per measurement for split.c: NULL when none has
 * its own (every one meas_sigma's R). */
static const mtt_real *const *set_r(const mtt_tracker *trk)
{
#if MTT_WITH_MEAS_COV
    return (trk->split_scr.n_own > 0u) ? trk->split_scr.rz : NULL;
#else
    (void)trk;
    return NULL;
#endif
}

/* The validated set's range rates for split.c (ALGORITHMS.md §3.2), in
 * rd: NULL when none has one. */
static const mtt_split_rdot *set_rd(const mtt_tracker *trk, mtt_split_rdot *rd)
{
#if MTT_WITH_MEAS_COV
    if (trk->split_scr.n_rdot == 0u) {
        return NULL;
    }
    rd->rr = trk->split_scr.rr;
    rd->sensor = trk->par.sensor_xy;
    rd->gamma = trk->gamma;
    rd->vmax = trk->par.vmax;
    return rd;
#else
    (void)trk;
    (void)rd;
    return NULL;
#endif
}

/* Model 6's start: the moment-matched mixture of the split modes' stacked
 * states with weights w[0] (mode 5) and w[1] (mode 6), Σ w = 1. */
static void mix_stacked(const mtt_split_slot *sl, const mtt_real w[2], mtt_split_state x0,
                        mtt_split_cov P0)
{
    const int r = (w[1] >= w[0]) ? 1 : 0; /* the heavier mode is the reference */
    mtt_real d[2][NS];
    int a, b, k;
    for (a = 0; a < NS; ++a) {
        x0[a] = (w[1 - r] > MTT_R(0.0)) ? sl->xs[r][a] + w[1 - r] * (sl->xs[1 - r][a] - sl->xs[r][a])
                                        : sl->xs[r][a];
        d[0][a] = sl->xs[0][a] - x0[a];
        d[1][a] = sl->xs[1][a] - x0[a];
    }
    for (a = 0; a < NS; ++a) {
        for (b = 0; b < NS; ++b) {
            mtt_real s = MTT_R(0.0);
            for (k = 0; k < 2; ++k) {
                if (w[k] > MTT_R(0.0)) { /* a mode of weight 0 may hold a stale state */
                    s += w[k] * (sl->Ps[k][a][b] + d[k][a] * d[k][b]);
                }
            }
            P0[a][b] = s;
        }
    }
}

/* 1 when measurement j is free for track ti's split modes: no other
 * confirmed track holds it (owners). */
static int free_for(const mtt_tracker *trk, uint16_t ti, uint16_t j)
{
    const uint16_t o = trk->split_scr.owner[j];
    return o == 0u || o == ti + 1u;
}

/* owner[j]: 1 + the confirmed track that holds measurement j this frame,
 * SPLIT_HELD_BY_MANY for two or more, 0 for none (ALGORITHMS.md §14.3
 * [CHOICE], one measurement, one target): the first confirmed track that
 * reports it (its update took it: assigned, selected or largest β), else
 * every confirmed track in whose gate it lies.  A measurement that another
 * confirmed target may have produced is not the second half of this
 * track's split; a track keeps the one it reports. */
static void owners(mtt_tracker *trk)
{
    mtt_split_scratch *sc = &trk->split_scr;
    uint16_t i, k;
    int pass;
    memset(sc->owner, 0, trk->n_meas * sizeof sc->owner[0]);
    memset(sc->reported, 0, trk->n_meas * sizeof sc->reported[0]);
    for (pass = 0; pass < 2; ++pass) {
        for (i = 0; i < trk->n_tracks; ++i) {
            const mtt_track *t = &trk->tracks[i];
            const mtt_track_frame *tf = &trk->tf[i];
            if (!tf->valid || t->born || !t->confirmed) {
                continue;
            }
            for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
                const uint16_t j = trk->pairs[k].meas;
                if (pass == 0) {
                    if (t->meas >= 0 && (int32_t)trk->meas[j].src == t->meas && sc->owner[j] == 0u) {
                        sc->owner[j] = (uint16_t)(i + 1u);
                        sc->reported[j] = 1u;
                    }
                } else if (!sc->reported[j]) {
                    sc->owner[j] = (sc->owner[j] == 0u || sc->owner[j] == i + 1u) ? (uint16_t)(i + 1u)
                                                                                 : SPLIT_HELD_BY_MANY;
                }
            }
        }
    }
}

/* A split mode's validated set: the frame's measurements inside the
 * bounding box of one of its nt target gates (centre c[t], half-widths
 * w[t] = sqrt(γ S_t) per axis), free for track ti; split.c gates them
 * exactly.  Beyond MTT_MAX_SPLIT_MEAS the rest are left out. */
static uint16_t gather(mtt_tracker *trk, uint16_t ti, int nt, mtt_real c[2][2], mtt_real w[2][2])
{
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_real wo[2][2];
    uint16_t j, m = 0;
    int t;
#if MTT_WITH_MEAS_COV
    sc->n_own = 0;
    sc->n_rdot = 0;
#endif
    for (t = 0; t < nt; ++t) {
        wo[t][0] = w[t][0];
        wo[t][1] = w[t][1];
#if MTT_WITH_MEAS_COV
        mtt_gate_own_widen(trk, trk->gamma, &wo[t][0], &wo[t][1]);
#endif
    }
    for (j = 0; j < trk->n_meas && m < MTT_MAX_SPLIT_MEAS; ++j) {
        const mtt_mstore *ms = &trk->meas[j];
        int in = 0;
        for (t = 0; t < nt; ++t) {
            in |= mtt_fabs(ms->x - c[t][0]) <= wo[t][0] && mtt_fabs(ms->y - c[t][1]) <= wo[t][1];
        }
        if (in && free_for(trk, ti, j)) {
            sc->z[m][0] = ms->x;
            sc->z[m][1] = ms->y;
            sc->zi[m] = j;
#if MTT_WITH_MEAS_COV
            sc->rz[m] = mtt_meas_r(trk, ms);
            sc->n_own = (uint16_t)(sc->n_own + ms->has_R);
            sc->rr[m] = ms->has_rdot ? ms->rr : NULL;
            sc->n_rdot = (uint16_t)(sc->n_rdot + ms->has_rdot);
#endif
            ++m;
        }
    }
    return m;
}

/* Model 6's validated set: either target's gate of the stacked prediction. */
static uint16_t split_candidates(mtt_tracker *trk, uint16_t ti, const mtt_split_state xp,
                                 mtt_split_cov Pp)
{
    mtt_real c[2][2], w[2][2], Rb[3];
    int t;
    for (t = 0; t < 2; ++t) {
        const int o = t * N1;
        const mtt_real *R = track_r(trk, &xp[o], Rb);
        c[t][0] = xp[o];
        c[t][1] = xp[o + 1];
        w[t][0] = mtt_sqrt(trk->gamma * (Pp[o][o] + R[0]));
        w[t][1] = mtt_sqrt(trk->gamma * (Pp[o + 1][o + 1] + R[2]));
    }
    return gather(trk, ti, 2, c, w);
}

/* Model 6 of track ti from its slot: mixing, prediction, joint events and
 * the coupled update into sc->x0, sc->P0.  Returns Λ_6 (0 when it cannot
 * run), *dec = 1 when the updated estimate passes the decoupling test. */
static mtt_real model6(mtt_tracker *trk, uint16_t ti, const mtt_split_slot *sl, mtt_real dt,
                       const mtt_real w[2], int *dec)
{
    static const mtt_real no_noise[3] = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
    mtt_split_scratch *sc = &trk->split_scr;
    const mtt_params *p = &trk->par;
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_real(*F)[MTT_MAX_STATE] = sc->F6; /* scratch: not the stack */
    mtt_real(*Q)[MTT_MAX_STATE] = sc->Q6;
    mtt_real d2, Rb[3];
    const mtt_real *R;
    const mtt_split_rdot *rd;
    mtt_split_rdot rdb;
    uint16_t m;
    int a;
    *dec = 0;
    mix_stacked(sl, w, sc->x0, sc->P0);
    memset(sc->F6, 0, sizeof sc->F6);
    for (a = 0; a < N1; ++a) {
        F[a][a] = MTT_R(1.0);
    }
    F[0][2] = dt;
    F[1][3] = dt;
    mtt_motion_q(dt, p->imm_psd[mtt_params_cv_model(p)], Q);
    if (mtt_split_predict(&sc->wk, N1, F, Q, sc->x0, sc->P0, sc->xp, sc->Pp) != 0) {
        return MTT_R(0.0);
    }
    m = split_candidates(trk, ti, sc->xp, sc->Pp);
    R = track_r(trk, sc->xp, Rb); /* polar: at the parent's predicted position */
    rd = set_rd(trk, &rdb);
    if (mtt_split_assoc_init(N1, sc->xp, sc->Pp, R, set_r(trk), rd, m, sc->z, p->pd, p->pg, trk->gamma, tf->vg,
                             tf->lambda, &sc->as) != 0 ||
        mtt_split_joint(&sc->as) != 0 ||
        mtt_split_update(&sc->wk, &sc->as, sc->xp, sc->Pp, R, set_r(trk), rd, sc->z, sc->x0, sc->P0) != 0) {
        return MTT_R(0.0);
    }
    /* [CHOICE] on the updated stacked state, on P_11 + P_22 unless
     * split_decouple_r (the header) */
    *dec = mtt_split_decouple(N1, sc->x0, sc->P0, p->split_decouple_r ? R : no_noise,
                              MTT_SPLIT_CHI2_99, &d2) == 1;
    return sc->as.lik;
}

/* Λ_s of the single-target modes over the track's gated pairs. */
static mtt_real single_lik(const mtt_tracker *trk, uint16_t ti)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    const mtt_real pdpg = trk->par.pd * trk->par.pg;
    mtt_real sum = MTT_R(0.0);
    uint16_t j;
    for (j = 0; j < tf->pair_count; ++j) {
        const mtt_pair *pp = &trk->pairs[tf->pair_first + j];
        sum += (pp->lam > MTT_R(0.0)) ? pp->p / pp->lam : MTT_R(0.0);
    }
    return MTT_R(1.0) - pdpg + pdpg * sum;
}

/* With split_dv > 0 the velocity impulse is the child's alone: the parent
 * half of model 5 (target 1, the largest-β cluster) is recomputed from the
 * cv prediction without it, and the cross covariance of the halves is
 * dropped (their prediction errors are no longer the same; a block-diagonal
 * stacked covariance stays positive semi-definite).  Uses sc->xp, sc->Pp as
 * scratch (model 6 is done with them). */
static void impulse_to_child(mtt_tracker *trk, uint16_t ti, uint16_t m)
{
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t cm = mtt_params_cv_model(&trk->par);
    mtt_real lik, Rb[3];
    mtt_split_rdot rdb;
    int a, b;
    if (mtt_split_just(&sc->wk, N1, tf->xpm[cm], tf->Ppm[cm], track_r(trk, tf->xpm[cm], Rb), set_r(trk),
                       set_rd(trk, &rdb), m, sc->z, sc->beta,
                       MTT_R(1.0) / tf->lambda, sc->xp, sc->Pp, sc->cluster, sc->beta_n, &lik) != 0) {
        return; /* the impulse then stays in both halves */
    }
    for (a = 0; a < N1; ++a) {
        sc->x5[a] = sc->xp[a];
        for (b = 0; b < NS; ++b) {
            sc->P5[a][b] = (b < N1) ? sc->Pp[a][b] : MTT_R(0.0);
            sc->P5[b][a] = (b < N1) ? sc->Pp[b][a] : MTT_R(0.0);
        }
    }
}

/* The late look's clusters (split_known_speed): the parent's centre is the
 * measurement nearest the cv prediction (on its S, the prediction stage's
 * tf->Sim; beta 2, above every other), the others rank by their nearest
 * offset (a + h) split_dv dt, h < KNOWN_LATE_OFFSETS, on either side of the
 * course (unit normal nx, ny; on model 5's S^-1 Si): the child's centre is
 * the one nearest an offset. */
static void late_centres(mtt_tracker *trk, uint16_t ti, uint16_t m, const mtt_real Si[3], mtt_real dt,
                         mtt_real nx, mtt_real ny)
{
    mtt_split_scratch *sc = &trk->split_scr;
    const mtt_params *p = &trk->par;
    const mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t cm = mtt_params_cv_model(p);
    const mtt_real *xq = tf->xpm[cm];
    const mtt_real *Sci = tf->Sim[cm]; /* the cv model's S^-1 (valid: mtt_split_frame checks tf->valid) */
    mtt_real best = MTT_R(-1.0);
    uint16_t j, jb = 0;
    uint8_t h;
    int sd;
    for (j = 0; j < m; ++j) {
        const mtt_real g = mtt_exp(MTT_R(-0.5) * mtt_mahal2(Sci, sc->z[j][0] - xq[0], sc->z[j][1] - xq[1]));
        if (g > best) {
            best = g;
            jb = j;
        }
    }
    for (j = 0; j < m; ++j) {
        mtt_real g = MTT_R(0.0);
        for (h = 0u; h < KNOWN_LATE_OFFSETS; ++h) {
            for (sd = -1; sd <= 1; sd += 2) {
                const mtt_real off = (mtt_real)sd * (MTT_SPLIT_KNOWN_OFFSET + (mtt_real)h) * p->split_dv * dt;
                const mtt_real gg =
                    mtt_exp(MTT_R(-0.5) * mtt_mahal2(Si, sc->z[j][0] - xq[0] - off * nx, sc->z[j][1] - xq[1] - off * ny));
                if (gg > g) {
                    g = gg;
                }
            }
        }
        sc->beta[j] = (j == jb) ? MTT_R(2.0) : g;
    }
}

/* Model 5 of track ti into sc->x5, sc->P5; returns Λ_5 (0 with fewer than
 * 2 measurements in its gate).  Its prediction is the cv model's plus the
 * split's velocity impulse: P̄_5 = P̄_cv + Q_s, per axis split_dv² [dt²/2,
 * dt/2; dt/2, 1] [CHOICE], with split_across only across the cv model's course
 * (mtt_split_impulse_q: the gate is not widened along the course, where a
 * split does not separate the halves) [CHOICE]; its validated set is its own gate; β_j ∝ N(z_j; ẑ_5, S_5)
 * (only their order and ratios matter, §14.3 model 5); the impulse is then
 * taken out of the parent half (impulse_to_child). */
static mtt_real model5(mtt_tracker *trk, uint16_t ti, mtt_real dt)
{
    mtt_split_scratch *sc = &trk->split_scr;
    const mtt_params *p = &trk->par;
    mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t cm = mtt_params_cv_model(p);
    mtt_real(*P5)[MTT_MAX_STATE] = sc->P5p; /* Q_s, then P̄_cv + Q_s (scratch: not the stack) */
    mtt_real K[MTT_MAX_STATE][2];
    mtt_real S[3], Si[3], det, c[2][2], w[2][2], lik = MTT_R(0.0), Rb[3];
    mtt_split_rdot rdb;
    const mtt_real *R = track_r(trk, tf->xpm[cm], Rb); /* polar: at the cv prediction */
    const int known = p->split_known_speed && p->split_dv > MTT_R(0.0);
    int late = 0; /* the late look of split_known_speed */
    mtt_real nx = MTT_R(0.0), ny = MTT_R(1.0); /* the course's unit normal, for the late look */
    uint16_t j, m;
    int a, b;
    mtt_split_impulse_q(dt, p->split_dv, p->split_across, tf->xpm[cm][2], tf->xpm[cm][3], P5);
    for (a = 0; a < MTT_MAX_STATE; ++a) {
        for (b = 0; b < MTT_MAX_STATE; ++b) {
            P5[a][b] = tf->Ppm[cm][a][b] + ((a < N1 && b < N1) ? P5[a][b] : MTT_R(0.0));
        }
    }
    if (mtt_kalman_innov_n(N1, P5, R, S, Si, &det, K) != 0 || !(tf->lambda > MTT_R(0.0))) {
        return MTT_R(0.0);
    }
    c[0][0] = tf->xpm[cm][0];
    c[0][1] = tf->xpm[cm][1];
    w[0][0] = mtt_sqrt(trk->gamma * S[0]);
    w[0][1] = mtt_sqrt(trk->gamma * S[2]);
    m = gather(trk, ti, 1, c, w);
    if (known && m < 2u) {
        /* the late look: a gate widened across the course */
        (void)mtt_split_normal(tf->xpm[cm][2], tf->xpm[cm][3], &nx, &ny);
        c[1][0] = c[0][0];
        c[1][1] = c[0][1];
        w[1][0] = w[0][0] + KNOWN_LATE_REACH * p->split_dv * dt * mtt_fabs(nx);
        w[1][1] = w[0][1] + KNOWN_LATE_REACH * p->split_dv * dt * mtt_fabs(ny);
        m = gather(trk, ti, 2, c, w);
        late = 1;
    }
    if (m > MTT_MAX_GATED) {
        m = MTT_MAX_GATED; /* the first ones, in measurement order */
    }
    for (j = 0; j < m; ++j) {
#if MTT_WITH_MEAS_COV
        if (set_r(trk) != NULL) {
            /* N(z_j; ẑ_5, S_5j) with its own R (§3.1), times its range
             * rate's factor (§3.2) */
            mtt_real d2, Sj[3];
            if (mtt_meas_gauss(P5[0], P5[1], sc->rz[j], MTT_R(1.0), sc->z[j][0] - c[0][0], sc->z[j][1] - c[0][1],
                               &d2, &sc->beta[j], Sj) != 0) {
                sc->beta[j] = MTT_R(0.0);
            } else if (sc->rr[j] != NULL) {
                sc->beta[j] *= mtt_polar_rdot_lik(trk, tf->xpm[cm], P5[0], Sj, &trk->meas[sc->zi[j]]);
            }
            continue;
        }
#endif
        sc->beta[j] = mtt_exp(MTT_R(-0.5) * mtt_mahal2(Si, sc->z[j][0] - c[0][0], sc->z[j][1] - c[0][1]));
    }
    if (late && m >= 2u) {
        late_centres(trk, ti, m, Si, dt, nx, ny);
    }
    if (m < 2u || mtt_split_just(&sc->wk, N1, tf->xpm[cm], P5, R, set_r(trk), set_rd(trk, &rdb), m, sc->z, sc->beta,
                                 MTT_R(1.0) / tf->lambda, sc->x5, sc->P5, sc->cluster, sc->beta_n,
                                 &lik) != 0) {
        return MTT_R(0.0);
    }
    if (p->split_dv > MTT_R(0.0)) {
        impulse_to_child(trk, ti, m);
    }
    if (known) {
        /* the child's half at the known speed; on failure the impulse's stays */
        mtt_real lk;
        if (mtt_split_known(&sc->wk, N1, tf->xpm[cm], tf->Ppm[cm], R, set_r(trk), set_rd(trk, &rdb), m, sc->z,
                            sc->cluster,
                            sc->beta_n, p->split_dv, dt, late ? KNOWN_LATE_OFFSETS : 1u,
                            MTT_R(1.0) / tf->lambda, sc->x5, sc->P5, &lk) == 0) {
            lik = lk;
        }
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
    mtt_real *x1 = sc->xd[0], *x2 = sc->xd[1]; /* scratch: not the stack */
    mtt_real(*P1)[MTT_MAX_STATE] = sc->Pd[0];
    mtt_real(*P2)[MTT_MAX_STATE] = sc->Pd[1];
    uint8_t j, a, b;
    int ci;
    memset(sc->xd, 0, sizeof sc->xd);
    memset(sc->Pd, 0, sizeof sc->Pd);
    if (mtt_split_separate(&sc->wk, N1, sc->x0, sc->P0, x1, P1, x2, P2) != 0) {
        return -1;
    }
    ci = mtt_track_append(trk, x2, P2, t->existence * ps,
                          t->confirmed && t->existence * ps >= trk->par.split_confirm, 1);
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

#if MTT_WITH_MEAS_COV
/* [CHOICE] A detection with a range rate whose position is in confirmed
 * track ti's gate (any model's, on its own S_j) is left to ti's split
 * modes, not to initiation: without its range rate the gate would have
 * taken it (marked used), with it the range-rate gate drops the split's
 * child, which initiation would then start as a second child beside the
 * one the split modes decouple (ALGORITHMS.md §14.3). */
static void hold_rdot(mtt_tracker *trk, uint16_t ti)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    uint16_t j;
    uint8_t k;
    for (j = 0; j < trk->n_meas; ++j) {
        mtt_mstore *ms = &trk->meas[j];
        for (k = 0; k < trk->par.imm_n_models && ms->has_rdot && !ms->used; ++k) {
            mtt_real d2, p, S[3];
            if (mtt_meas_gauss(tf->Ppm[k][0], tf->Ppm[k][1], ms->R, trk->par.pg, ms->x - tf->xpm[k][0],
                               ms->y - tf->xpm[k][1], &d2, &p, S) == 0 &&
                d2 <= trk->gamma) {
                ms->used = 1;
            }
        }
    }
}
#endif

/* The split modes of one confirmed IMM track after its update. */
static void split_track(mtt_tracker *trk, uint16_t ti, mtt_real dt)
{
    const mtt_params *p = &trk->par;
    mtt_track *t = &trk->tracks[ti];
    mtt_split_scratch *sc = &trk->split_scr;
    mtt_split_slot *sl = (t->split_slot != MTT_SPLIT_NONE) ? &trk->split[t->split_slot] : NULL;
    const mtt_real m5 = (sl != NULL) ? sl->mu[0] : MTT_R(0.0);
    const mtt_real m6 = (sl != NULL) ? sl->mu[1] : MTT_R(0.0);
    const mtt_real c5 = p->split_p25 * (MTT_R(1.0) - m5 - m6) * trk->tf[ti].cbar[mtt_params_cv_model(p)];
    const mtt_real c6 = (MTT_R(1.0) - p->split_p52) * m5 + (MTT_R(1.0) - p->split_p62) * m6;
    const mtt_real cs = MTT_R(1.0) - c5 - c6;
    mtt_real lam_s, lam5, lam6 = MTT_R(0.0), c, mu5, mu6;
    int dec = 0;
    uint16_t j;
    if (sl != NULL && c6 > MTT_R(0.0)) {
        const mtt_real w[2] = {(MTT_R(1.0) - p->split_p52) * m5 / c6, (MTT_R(1.0) - p->split_p62) * m6 / c6};
        lam6 = model6(trk, ti, sl, dt, w, &dec);
    }
    lam_s = single_lik(trk, ti);
    lam5 = model5(trk, ti, dt);
    c = cs * lam_s + c5 * lam5 + c6 * lam6;
    if (c > MTT_R(0.0) && mtt_isfinite(c)) {
        mu5 = c5 * lam5 / c;
        mu6 = c6 * lam6 / c;
    } else {
        mu5 = MTT_R(0.0);
        mu6 = MTT_R(0.0);
    }
    t->p_split = mu5 + mu6;
    if (mu6 > MTT_R(0.0) && t->p_split >= trk->par.split_decide) {
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
    owners(trk);
    for (i = 0; i < n; ++i) {
        if (trk->tracks[i].split_slot != MTT_SPLIT_NONE) {
            trk->split[trk->tracks[i].split_slot].used = 1;
        }
    }
    for (i = 0; i < n; ++i) {
        mtt_track *t = &trk->tracks[i];
        if (trk->par.split_known_speed && t->parent != MTT_NO_PARENT && (mtt_real)t->age <= trk->par.split_provisional_scans &&
            t->existence < trk->par.split_provisional_exist) {
            t->existence = MTT_R(0.0); /* a provisional child that lost its evidence: deleted (§12.4) */
        }
        if (!trk->tf[i].valid || t->born || !t->confirmed || !(dt > MTT_R(0.0))) {
            t->p_split = MTT_R(0.0);
            continue;
        }
        split_track(trk, i, dt);
#if MTT_WITH_MEAS_COV
        hold_rdot(trk, i);
#endif
    }
}

#endif /* MTT_WITH_SPLIT */
