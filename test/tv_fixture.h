/* SPDX-License-Identifier: BSD-3-Clause */
/* tv_fixture.h - hand-built tracker states for the stage tests.
 *
 * The stage functions work on an mtt_tracker; these helpers fill just what
 * a stage reads: a track frame from a predicted measurement and an
 * innovation covariance (as TV8 gives its tracks), measurements, gated
 * pairs and their CSR lists.  Include after tv_assert.h. */
#ifndef TV_FIXTURE_H
#define TV_FIXTURE_H

#include <string.h>

#include "mtt_internal.h"
#include "unity.h"

/* ---- the test-only accessor layer ----
 * Stage tests name the state they set up and check through these (lvalues:
 * read and write), not through the layout of mtt/state.h; when the layout
 * changes, this block changes, not the tests. */
/* counts of this frame */
#define TV_N_TRACKS(t) ((t)->n_tracks)
#define TV_N_MEAS(t) ((t)->n_meas)
#define TV_N_PAIRS(t) ((t)->n_pairs)
#define TV_N_CLUSTERS(t) ((t)->n_clusters)
/* the tracker's working parameters, R = [r11, r12, r22], gate gamma, next
 * track id, and the init mark */
#define TV_PAR(t) ((t)->par)
#define TV_R(t) ((t)->R)
#define TV_GAMMA(t) ((t)->gamma)
#define TV_NEXT_ID(t) ((t)->next_id)
#define TV_MAGIC(t) ((t)->magic)
/* gated pair k: track, measurement, p = N/PG, clutter density, LM weight,
 * beta and L of the row last computed */
#define TV_PAIR_TRACK(t, k) ((t)->pairs[k].track)
#define TV_PAIR_MEAS(t, k) ((t)->pairs[k].meas)
#define TV_PAIR_P(t, k) ((t)->pairs[k].p)
#define TV_PAIR_LAM(t, k) ((t)->pairs[k].lam)
#define TV_PAIR_W(t, k) ((t)->pairs[k].w)
#define TV_PAIR_BETA(t, k) ((t)->pairs[k].beta)
#define TV_PAIR_L(t, k) ((t)->pairs[k].L)
/* gated pair k as a whole (to clear it), and its amplitude ratio g */
#define TV_PAIR(t, k) ((t)->pairs[k])
#define TV_PAIR_G(t, k) ((t)->pairs[k].g)
/* track i this frame: valid (S positive definite), its pairs, gate area,
 * clutter density, cluster, assigned pair, beta_0, updated existence */
#define TV_VALID(t, i) ((t)->tf[i].valid)
#define TV_PAIR_FIRST(t, i) ((t)->tf[i].pair_first)
#define TV_PAIR_COUNT(t, i) ((t)->tf[i].pair_count)
#define TV_ALL_AMP(t, i) ((t)->tf[i].has_all_amp)
#define TV_GATE_AREA(t, i) ((t)->tf[i].vg)
#define TV_LAMBDA(t, i) ((t)->tf[i].lambda)
#define TV_CLUSTER_OF(t, i) ((t)->tf[i].cluster)
#define TV_ASSIGNED(t, i) ((t)->tf[i].assigned)
#define TV_BETA0(t, i) ((t)->tf[i].beta0)
#define TV_EX_POST(t, i) ((t)->tf[i].ex_post)
/* track i this frame as a whole (to clear it), its prediction xp, Pp, the
 * innovation S, S^-1, det S, gain K, predicted existence, best pair, and
 * contest class */
#define TV_FRAME(t, i) ((t)->tf[i])
#define TV_XP(t, i) ((t)->tf[i].xp)
#define TV_PP(t, i) ((t)->tf[i].Pp)
#define TV_S(t, i) ((t)->tf[i].S)
#define TV_SI(t, i) ((t)->tf[i].Si)
#define TV_DET_S(t, i) ((t)->tf[i].det_s)
#define TV_GAIN(t, i) ((t)->tf[i].K)
#define TV_EX_PRED(t, i) ((t)->tf[i].ex_pred)
#define TV_BEST(t, i) ((t)->tf[i].best)
#define TV_CONTEST(t, i) ((t)->tf[i].contest)
#if MTT_WITH_CONTEST
/* track i's process-noise scale s and NIS average (ALGORITHMS.md §2.1),
 * and the frame's floor of s */
#define TV_Q_SCALE(t, i) ((t)->tracks[i].q_scale)
#define TV_NIS_RATIO(t, i) ((t)->tracks[i].nis_ratio)
#define TV_Q_FLOOR(t) ((t)->q_floor)
#endif
/* track i of the table */
#define TV_TRACK(t, i) (&(t)->tracks[i])
#define TV_X(t, i) ((t)->tracks[i].x)
#define TV_P(t, i) ((t)->tracks[i].P)
#define TV_EXISTENCE(t, i) ((t)->tracks[i].existence)
#define TV_CONFIRMED(t, i) ((t)->tracks[i].confirmed)
#define TV_DEAD(t, i) ((t)->tracks[i].dead)
#define TV_TRACK_MEAS(t, i) ((t)->tracks[i].meas)
#define TV_TRACK_ID(t, i) ((t)->tracks[i].id)
#define TV_BORN(t, i) ((t)->tracks[i].born)
/* measurement j: used (assigned, selected or gated) this frame */
#define TV_USED(t, j) ((t)->meas[j].used)
/* measurement j as a whole (to clear it), its position, amplitude, whether
 * it has one, and its input index */
#define TV_MEAS(t, j) ((t)->meas[j])
#define TV_MEAS_X(t, j) ((t)->meas[j].x)
#define TV_MEAS_Y(t, j) ((t)->meas[j].y)
#define TV_MEAS_AMP(t, j) ((t)->meas[j].amp)
#define TV_HAS_AMP(t, j) ((t)->meas[j].has_amp)
#define TV_MEAS_SRC(t, j) ((t)->meas[j].src)
/* W_j, the LM weight sum of measurement j */
#define TV_WSUM(t, j) ((t)->wsum[j])
/* last frame's unused measurements U_{k-1} (initiation): count, entry i */
#define TV_N_PREV(t) ((t)->n_prev)
#define TV_PREV(t, i) ((t)->prev[i])
#define TV_PREV_X(t, i) ((t)->prev[i].x)
/* merge candidates: count, and pair i (tracks a < b, distance d2) */
#define TV_N_MERGE(t) ((t)->n_merge)
#define TV_MERGE_A(t, i) ((t)->merge[i].a)
#define TV_MERGE_B(t, i) ((t)->merge[i].b)
#define TV_MERGE_D2(t, i) ((t)->merge[i].d2)
#if MTT_WITH_SPLIT
/* split = true (ALGORITHMS.md §14.3): track i's slot of the pool, and slot k
 * (its mode probabilities mu[0] "just split", mu[1] "split", stacked
 * states xs[0], xs[1] and covariances Ps[0], Ps[1], used) */
#define TV_SPLIT_SLOT(t, i) ((t)->tracks[i].split_slot)
#define TV_SPLIT(t, k) ((t)->split[k])
#endif
/* IHPDA rank weights: row MTT_PRANK_ROW(m) holds m entries */
#define TV_PRANK(t, r) ((t)->prank[r])
/* the frame's counters */
#define TV_STATS(t) ((t)->stats)
/* JPDA family scratch: A of pair k, B of track i, Suboptimal JPDA's two
 * largest A of row i and the measurement of the largest, row scale,
 * enumerated and kept events, weight of event e, kept bit byte q */
#define TV_JP_PA(t, k) ((t)->base.jp.pa[k])
#define TV_JP_TB(t, i) ((t)->base.jp.tb[i])
#define TV_JP_MAX1(t, i) ((t)->base.jp.max1[i])
#define TV_JP_MAX2(t, i) ((t)->base.jp.max2[i])
#define TV_JP_ARG1(t, i) ((t)->base.jp.arg1[i])
#define TV_JP_SCALE(t, i) ((t)->base.jp.scale[i])
#define TV_JP_N_EVENTS(t) ((t)->base.jp.n_events)
#define TV_JP_N_KEPT(t) ((t)->base.jp.n_kept)
#define TV_JP_EV_W(t, e) ((t)->base.jp.ev_w[e])
#define TV_JP_EV_KEEP(t, q) ((t)->base.jp.ev_keep[q])
/* clusters (CSR): tracks cl_list[cl_first[c] .. cl_first[c + 1]) */
#define TV_CL_FIRST(t, c) ((t)->cl_first[c])
#define TV_CL_LIST(t, q) ((t)->cl_list[q])
/* pairs of measurement j (CSR): mp_list[mp_first[j] .. mp_first[j + 1]) */
#define TV_MP_FIRST(t, j) ((t)->mp_first[j])
#define TV_MP_LIST(t, x) ((t)->mp_list[x])
/* records handed to a stage on their own: a measurement r (position,
 * amplitude, whether it has one), an IHPDA candidate c (p, lambda,
 * amplitude, measurement index), and the 2-D assignment's row of column c */
#define TV_REC_X(r) ((r)->x)
#define TV_REC_Y(r) ((r)->y)
#define TV_REC_AMP(r) ((r)->amp)
#define TV_REC_HAS_AMP(r) ((r)->has_amp)
#define TV_CAND_P(c) ((c)->p)
#define TV_CAND_LAM(c) ((c)->lam)
#define TV_CAND_AMP(c) ((c)->amp)
#define TV_CAND_IDX(c) ((c)->idx)
#define TV_COL_ROW(ws, c) ((ws)->col_row[c])


/* d^2 of gated pair k, as the gate computed it (the pair keeps only p). */
static inline mtt_real tv_pair_d2(const mtt_tracker *trk, uint16_t k)
{
    const mtt_pair *pp = &trk->pairs[k];
    const mtt_track_frame *tf = &trk->tf[pp->track];
    return mtt_mahal2(tf->Si, trk->meas[pp->meas].x - tf->xp[0], trk->meas[pp->meas].y - tf->xp[1]);
}

/* Input index of kept measurement i of this frame, and how many are kept. */
static inline uint32_t tv_meas_src(const mtt_tracker *trk, uint16_t i)
{
    return trk->meas[i].src;
}
static inline uint16_t tv_meas_count(const mtt_tracker *trk)
{
    return trk->n_meas;
}

/* IPDA betas of m candidates given as arrays (p, lambda), through the
 * library's pair-based mtt_ipda_betas. */
static inline void tv_ipda_betas(mtt_real pd, mtt_real pg, const mtt_real *p, const mtt_real *lam,
                                 uint16_t m, mtt_real *beta, mtt_real *beta0, mtt_real *L)
{
    mtt_pair pp[MTT_MAX_GATED];
    uint16_t j;
    memset(pp, 0, sizeof pp);
    for (j = 0; j < m; ++j) {
        pp[j].p = p[j];
        pp[j].lam = lam[j];
    }
    mtt_ipda_betas(pd, pg, pp, m, beta0, L);
    for (j = 0; j < m; ++j) {
        beta[j] = pp[j].beta;
    }
}

/* ---- writers ---- */

/* Initialise trk with p (must succeed); no tracks, no measurements. */
static inline void tv_init(mtt_tracker *trk, const mtt_params *p)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(trk, p));
}

/* Add track i with prediction xp and covariance Pp (innovation from trk->R).
 * Also copies the prediction into the track itself. */
static inline uint16_t tv_add_track_xp(mtt_tracker *trk, const mtt_state xp,
                                       mtt_cov Pp, mtt_real ex_pred)
{
    uint16_t i = trk->n_tracks++;
    mtt_track_frame *tf = &trk->tf[i];
    mtt_track *t = &trk->tracks[i];
    memset(tf, 0, sizeof *tf);
    memset(t, 0, sizeof *t);
    memcpy(tf->xp, xp, sizeof tf->xp);
    memcpy(tf->Pp, Pp, sizeof tf->Pp);
    memcpy(t->x, xp, sizeof t->x);
    memcpy(t->P, Pp, sizeof t->P);
    t->id = trk->next_id++;
    t->existence = ex_pred;
    t->meas = -1;
    tf->ex_pred = ex_pred;
    tf->assigned = -1;
    tf->best = -1;
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(tf->Pp, trk->R, tf->S, tf->Si, &tf->det_s, tf->K));
    tf->vg = MTT_GATE_AREA(trk->gamma, tf->det_s, tf->S, trk->par.clutter_density);
    tf->valid = 1;
    return i;
}

#ifndef MTT_REAL_FIXED /* covariances have no fixed-point format yet (docs/FIXED_POINT.md) */
/* Track given by its predicted measurement z_hat and innovation covariance
 * S = [s11, s12; s12, s22]: position block of Pp = S - R, velocity block I. */
static inline uint16_t tv_add_track_s(mtt_tracker *trk, mtt_real zx, mtt_real zy, mtt_real s11,
                                      mtt_real s12, mtt_real s22, mtt_real ex_pred)
{
    mtt_state xp;
    mtt_cov Pp;
    memset(Pp, 0, sizeof Pp);
    xp[0] = zx;
    xp[1] = zy;
    xp[2] = MTT_R(0.0);
    xp[3] = MTT_R(0.0);
    Pp[0][0] = s11 - trk->R[0];
    Pp[0][1] = s12 - trk->R[1];
    Pp[1][0] = s12 - trk->R[1];
    Pp[1][1] = s22 - trk->R[2];
    Pp[2][2] = MTT_R(1.0);
    Pp[3][3] = MTT_R(1.0);
    return tv_add_track_xp(trk, xp, Pp, ex_pred);
}
#endif

static inline uint16_t tv_add_meas(mtt_tracker *trk, mtt_real x, mtt_real y, mtt_real amp,
                                   int has_amp)
{
    uint16_t j = trk->n_meas++;
    mtt_mstore *m = &trk->meas[j];
    m->x = x;
    m->y = y;
    m->amp = has_amp ? amp : MTT_ZERO;
    m->has_amp = (uint8_t)(has_amp != 0);
    m->src = j;
    m->used = 0;
    return j;
}

/* Append a pair (must come in track, then measurement order) with a beta. */
static inline void tv_add_pair(mtt_tracker *trk, uint16_t t, uint16_t j, mtt_real beta)
{
    mtt_pair *pp = &trk->pairs[trk->n_pairs++];
    memset(pp, 0, sizeof *pp);
    pp->track = t;
    pp->meas = j;
    pp->beta = beta;
}

/* Per-track pair ranges and the per-measurement CSR lists from trk->pairs. */
static inline void tv_index_pairs(mtt_tracker *trk)
{
    uint16_t i, k, c = 0;
    for (i = 0; i < trk->n_tracks; ++i) {
        trk->tf[i].pair_first = 0;
        trk->tf[i].pair_count = 0;
        trk->tf[i].has_all_amp = 1;
    }
    for (k = 0; k < trk->n_pairs; ++k) {
        mtt_track_frame *tf = &trk->tf[trk->pairs[k].track];
        if (tf->pair_count == 0u) {
            tf->pair_first = k;
        }
        tf->pair_count++;
        if (!trk->meas[trk->pairs[k].meas].has_amp) {
            tf->has_all_amp = 0;
        }
    }
    for (i = 0; i < trk->n_meas; ++i) {
        trk->mp_first[i] = c;
        for (k = 0; k < trk->n_pairs; ++k) {
            if (trk->pairs[k].meas == i) {
                trk->mp_list[c++] = k;
            }
        }
    }
    trk->mp_first[trk->n_meas] = c;
}

/* Index of the pair (t, j), or -1. */
static inline int tv_find_pair(const mtt_tracker *trk, uint16_t t, uint16_t j)
{
    uint16_t k;
    for (k = 0; k < trk->n_pairs; ++k) {
        if (trk->pairs[k].track == t && trk->pairs[k].meas == j) {
            return (int)k;
        }
    }
    return -1;
}

#endif /* TV_FIXTURE_H */
