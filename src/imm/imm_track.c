/* SPDX-License-Identifier: BSD-3-Clause */
/* imm_track.c - the IMM stages of one track in the pipeline
 * (ALGORITHMS.md §14.1, §14.2): mixing and the per-model prediction,
 * the union gate with the model-mixed likelihood p*, the apportionment of
 * the association result over the models with the per-model PDA updates,
 * and the start of an IMM track.  The arithmetic is imm.c's; this file sequences it over
 * the track table.
 *
 * Why the association stages need no change: every association mode with
 * IMM (every mode but ihpda-2d and lm-ipda-all) sees a track as one filter
 * whose likelihood of measurement i is p*_i = Σ_j c̄_j p_i^j (one PD for
 * all models), ALGORITHMS.md §14.2.  The gate writes p* into pair.p, so
 * the LM weights, IHPDA selection, MMR and JIPDA events run unchanged; the
 * update stage then apportions their result into mode probabilities and
 * per-model betas (mtt_imm_apportion).  The existence is the mode's, except
 * in the IHPDA modes: there each model's own gate gives its §7.3 L
 * (mtt_imm_exist_L), because the selected measurement's L over the union
 * gate kept lost tracks alive on clutter.  With one PD the
 * "no measurement" factor (1 - PD PG for the PDA modes, C_s for the IHPDA
 * modes) is the same for every model and cancels in the apportionment, so
 * e0_j = 1 and e_ij = p_i^j.
 *
 * Fixed point (docs/FIXED_POINT.md §5): cv models only; the gate's ratios
 * p_i^j / lambda saturate near a converged track, so the apportionment
 * takes e_ij from the log-likelihoods instead: y_ij = d_ij^2 / 2 +
 * ln sqrt(det S_ij) and e_ij = exp(-(y_ij - min_k y_ik)) in Q30, the same
 * ratios over j with the largest 1. */
#include <string.h>

#include "mtt_internal.h"

#if MTT_WITH_IMM

#ifdef MTT_REAL_FIXED
#define D2_NONE MTT_FX_MAX
/* the IHPDA L of a candidate (ihpda.c holds lambda_j L_j in fixed point) */
#define CAND_L(L, c) MTT_DIV_R((L), (c).lam)
#else
#define D2_NONE MTT_REAL_MAX
#define CAND_L(L, c) (L)
#endif

/* State size of a model kind. */
static uint8_t model_n(mtt_model_kind k)
{
#if MTT_WITH_IMM_CACT
    return (k == MTT_MODEL_CA) ? (uint8_t)MTT_CA_N : ((k == MTT_MODEL_CT) ? (uint8_t)MTT_CT_N : (uint8_t)MTT_STATE_N);
#else
    (void)k; /* cv only (mtt_params_check) */
    return (uint8_t)MTT_STATE_N;
#endif
}

/* xp = F x, Pp = F P F' + Q of model j (ALGORITHMS.md §2 for CV, §14.1
 * for CA and CT), symmetric; in place (xp = x, Pp = P) allowed.  Fixed
 * point: the frame's Q(dT) of model j (predict.c). */
#ifdef MTT_REAL_FIXED
static void model_predict(mtt_tracker *trk, uint8_t j, mtt_real dt, mtt_real s, const mtt_state x, mtt_cov P,
                          mtt_state xp, mtt_cov Pp)
{
    (void)s;
    mtt_kalman_predict_q(dt, trk->qm[j], x, P, xp, Pp);
}
#else
static void model_predict(const mtt_params *p, uint8_t j, mtt_real dt, mtt_real s, const mtt_state x,
                          mtt_cov P, mtt_state xp, mtt_cov Pp)
{
#if MTT_WITH_CONTEST
    const mtt_real q = s * p->imm_psd[j]; /* the track's scale of the noise (ALGORITHMS.md §2.1) */
#else
    const mtt_real q = p->imm_psd[j];
    (void)s;
#endif
#if MTT_WITH_IMM_CACT
    if (p->imm_model[j] == MTT_MODEL_CV) {
        mtt_kalman_predict(dt, q, x, P, xp, Pp);
    } else if (p->imm_model[j] == MTT_MODEL_CA) {
        mtt_ca_predict(dt, q, x, P, xp, Pp);
    } else {
        mtt_ct_predict(dt, q, p->imm_turn_psd[j], x, P, xp, Pp);
    }
#else
    mtt_kalman_predict(dt, q, x, P, xp, Pp);
#endif
}
#endif

int mtt_imm_predict_track(mtt_tracker *trk, uint16_t ti, mtt_real dt)
{
    const mtt_params *p = &trk->par;
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t r = p->imm_n_models;
    mtt_real mix[MTT_MAX_MODELS][MTT_MAX_MODELS], S[MTT_SYM_SLOTS];
    uint8_t n[MTT_MAX_MODELS], j, a;
    int ok = 1;
    for (j = 0; j < r; ++j) {
        n[j] = model_n(p->imm_model[j]);
    }
    if (dt > MTT_ZERO) {
        (void)mtt_imm_mix_weights(r, (mtt_real(*)[MTT_MAX_MODELS])p->imm_transition, t->mu, tf->cbar, mix);
        /* mixed starts x_0j, P_0j, parked in xpm / Ppm, then predicted */
        (void)mtt_imm_mix(r, n, mix, t->xm, t->Pm, tf->xpm, tf->Ppm);
#if MTT_WITH_CONTEST
        const mtt_real s = mtt_adapt_imm_scale(trk, t);
#else
        const mtt_real s = MTT_RATIO(1.0);
#endif
        for (j = 0; j < r; ++j) {
#ifdef MTT_REAL_FIXED
            model_predict(trk, j, dt, s, tf->xpm[j], tf->Ppm[j], tf->xpm[j], tf->Ppm[j]);
#else
            model_predict(p, j, dt, s, tf->xpm[j], tf->Ppm[j], tf->xpm[j], tf->Ppm[j]);
#endif
        }
    } else {
        /* First frame: the state is already at this time (seeded tracks). */
        for (j = 0; j < r; ++j) {
            tf->cbar[j] = t->mu[j];
            memcpy(tf->xpm[j], t->xm[j], sizeof tf->xpm[j]);
            memcpy(tf->Ppm[j], t->Pm[j], sizeof tf->Ppm[j]);
        }
    }
    tf->vgm = MTT_ZERO;
    for (j = 0; j < r && ok; ++j) {
        mtt_real det = MTT_ZERO, Si[MTT_SYM_SLOTS], vg;
#if MTT_WITH_POLAR
        mtt_real Rt[3]; /* polar: R at the model's predicted position (ALGORITHMS.md §3.2) */
        ok = mtt_state_finite(tf->xpm[j]) &&
             mtt_kalman_innov_n(n[j], tf->Ppm[j], mtt_polar_track_r(trk, tf->xpm[j], Rt), S, Si, &det,
                                tf->Km[j]) == 0;
#else
        ok = mtt_state_finite(tf->xpm[j]) &&
             mtt_kalman_innov_n(n[j], tf->Ppm[j], trk->R, S, Si, &det, tf->Km[j]) == 0;
#endif
        if (ok) {
            memcpy(tf->Sim[j], Si, sizeof Si);
#ifdef MTT_REAL_FIXED
            vg = mtt_fx_gate_area_peak_c(trk->gc, det, S, &tf->peakm[j]); /* lambda V_G, p / lambda */
            tf->vgj[j] = vg;
            tf->hld[j] = mtt_fx_half_ln_det(det, S);
#else
            tf->peakm[j] = mtt_gate_likelihood(MTT_R(0.0), det, p->pg);
            vg = mtt_gate_volume(trk->gamma, det);
#endif
            tf->wm[j][0] = MTT_GATE_WIDTH(trk->gamma, S, 0);
            tf->wm[j][1] = MTT_GATE_WIDTH(trk->gamma, S, 2);
            tf->vgm = (vg > tf->vgm) ? vg : tf->vgm;
            if (j == 0u) {
                /* the single-filter fields, read by gate.c before its IMM branch */
                memcpy(tf->S, S, sizeof tf->S);
                memcpy(tf->Si, Si, sizeof tf->Si);
                tf->det_s = det;
            }
        }
    }
    /* The gate's centre: the c̄-weighted predicted position and velocity
     * (as differences to model 0: no cancellation on large coordinates).
     * No stage reads a combined predicted covariance of an IMM track: the
     * gate uses every model's own S (ALGORITHMS.md §14.2). */
    memset(tf->xp, 0, sizeof tf->xp);
    for (a = 0; a < MTT_IMM_COMMON; ++a) {
        mtt_pos d = MTT_ZERO;
        for (j = 1; j < r; ++j) {
            /* (fixed point: the Q30 product keeps the position's format) */
            d = MTT_ADDS(d, MTT_MUL_PP(tf->cbar[j], MTT_SUBS(tf->xpm[j][a], tf->xpm[0][a])));
        }
        tf->xp[a] = MTT_ADDS(tf->xpm[0][a], d);
    }
    return ok && mtt_state_finite(tf->xp);
}

void mtt_imm_gate_window(const mtt_tracker *trk, uint16_t ti, mtt_real *wx, mtt_real *wy)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_pos ax = MTT_ZERO, ay = MTT_ZERO;
    uint8_t j;
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        const mtt_pos hx = MTT_ADDS(MTT_ABS(MTT_SUBS(tf->xpm[j][0], tf->xp[0])), tf->wm[j][0]);
        const mtt_pos hy = MTT_ADDS(MTT_ABS(MTT_SUBS(tf->xpm[j][1], tf->xp[1])), tf->wm[j][1]);
        ax = (hx > ax) ? hx : ax;
        ay = (hy > ay) ? hy : ay;
    }
    *wx = ax;
    *wy = ay;
}

mtt_real mtt_imm_model_d2(const mtt_tracker *trk, const mtt_track_frame *tf, uint8_t j, const mtt_mstore *ms,
                          mtt_real *p)
{
    const mtt_pos nx = MTT_SUBS(ms->x, tf->xpm[j][0]), ny = MTT_SUBS(ms->y, tf->xpm[j][1]);
    mtt_d2 d2;
#if MTT_WITH_MEAS_COV && !defined(MTT_REAL_FIXED)
    if (ms->has_R) {
        /* its own R and range rate against this model's prediction (§3.1, §3.2) */
        mtt_real pk;
        return mtt_gate_own(trk, tf->xpm[j], &tf->Ppm[j][0][0], ms, (p != NULL) ? p : &pk);
    }
#elif MTT_WITH_MEAS_COV
    if (ms->has_R) {
        /* its own R against this model's prediction (§3.1) */
        if (p != NULL) {
            *p = MTT_ZERO;
        }
        return (mtt_meas_gauss_fx((mtt_real(*)[MTT_MAX_STATE])tf->Ppm[j], ms->R, (p != NULL) ? trk->gc : NULL, nx,
                                  ny, &d2, p, NULL) == 0)
                   ? d2
                   : D2_NONE;
    }
#else
    (void)trk;
#endif
    d2 = mtt_mahal2(tf->Sim[j], nx, ny);
    if (p != NULL) {
        *p = MTT_GATE_LIK(tf->peakm[j], d2);
    }
    return d2;
}

mtt_real mtt_imm_gate_d2(const mtt_tracker *trk, uint16_t ti, const mtt_mstore *ms)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_d2 best = D2_NONE;
    uint8_t j;
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        const mtt_real d2 = mtt_imm_model_d2(trk, tf, j, ms, NULL); /* d^2 alone */
        best = (d2 < best) ? d2 : best;
    }
    return best;
}

#ifdef MTT_REAL_FIXED
/* y_j = d_j^2 / 2 + ln sqrt(det S_j) of measurement z under model j (Q24,
 * saturated; with its own R, S_j is Pp_j's position block plus that R). */
static int32_t model_y(const mtt_track_frame *tf, uint8_t j, const mtt_mstore *ms)
{
    const mtt_pos nx = MTT_SUBS(ms->x, tf->xpm[j][0]), ny = MTT_SUBS(ms->y, tf->xpm[j][1]);
    int32_t hl = tf->hld[j];
    mtt_d2 d2;
#if MTT_WITH_MEAS_COV
    if (ms->has_R) {
        if (mtt_meas_gauss_fx((mtt_real(*)[MTT_MAX_STATE])tf->Ppm[j], ms->R, NULL, nx, ny, &d2, NULL, &hl) != 0) {
            return MTT_FX_MAX;
        }
    } else
#endif
    {
        d2 = mtt_mahal2(tf->Sim[j], nx, ny);
    }
    return mtt_fx_add((int32_t)(((uint32_t)d2 + 1u) >> 1), hl);
}

/* e_j = exp(-(y_j - min_k y_k)) in Q30 (see the header). */
static void model_likelihoods(const mtt_tracker *trk, const mtt_track_frame *tf, const mtt_mstore *ms,
                              mtt_real pj[])
{
    int32_t y[MTT_MAX_MODELS], ymin = MTT_FX_MAX;
    uint8_t j;
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        y[j] = model_y(tf, j, ms);
        ymin = (y[j] < ymin) ? y[j] : ymin;
    }
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        pj[j] = mtt_fx_exp_neg_q30((uint32_t)mtt_fx_sub(y[j], ymin));
    }
}
#else
/* the apportionment's e_ij are the gate's p_i^j (below) */
#define model_likelihoods model_ps
#endif

/* p_i^j = N(ν_i^j; 0, S_j)/PG of measurement z under every model. */
static void model_ps(const mtt_tracker *trk, const mtt_track_frame *tf, const mtt_mstore *ms, mtt_real pj[])
{
    uint8_t j;
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        (void)mtt_imm_model_d2(trk, tf, j, ms, &pj[j]);
    }
}

mtt_real mtt_imm_gate_p(const mtt_tracker *trk, uint16_t ti, const mtt_mstore *ms)
{
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_real pj[MTT_MAX_MODELS], pd[MTT_MAX_MODELS], pdm;
    uint8_t j;
    model_ps(trk, tf, ms, pj);
    for (j = 0; j < trk->par.imm_n_models; ++j) {
        pd[j] = trk->par.pd;
    }
    return mtt_imm_meas_mix(trk->par.imm_n_models, tf->cbar, pd, pj, &pdm);
}

/* Existence likelihood ratio of an IHPDA-mode IMM track whose selected
 * pair is `a` (ALGORITHMS.md §14.2, mode-conditioned existence):
 * L = Σ_j c̄_j L^j, L^j the §7.3 L of model j over the final row's
 * candidates inside model j's own gate (m_j, V_G^j, p_i^j, ranks among
 * them), at `a` when model j gates it, else at model j's own selection;
 * 1 - PD PG when model j gates none. */
mtt_real mtt_imm_exist_L(mtt_tracker *trk, uint16_t ti, uint16_t a)
{
    const mtt_params *p = &trk->par;
    const mtt_track_frame *tf = &trk->tf[ti];
    mtt_cand *c = trk->row.cand;
    mtt_real *beta = trk->row.beta, *L = trk->row.L;
    const mtt_ratio miss = MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), MTT_MUL_PP(p->pd, p->pg)));
    mtt_ratio sum = MTT_ZERO;
    uint16_t k;
    uint8_t j;
    for (j = 0; j < p->imm_n_models; ++j) {
#ifdef MTT_REAL_FIXED
        const mtt_ratio vg = tf->vgj[j]; /* lambda V_G^j */
#else
        /* V_G^j = π γ sqrt(det S_j) = γ / (2 PG N_j(0)) */
        const mtt_real vg = trk->gamma / (MTT_R(2.0) * p->pg * tf->peakm[j]);
#endif
        uint16_t m = 0, sel = 0, b = 0;
        int has_a = 0;
        for (k = tf->pair_first; k < tf->pair_first + tf->pair_count; ++k) {
            const mtt_pair *pp = &trk->pairs[k];
            const mtt_mstore *ms = &trk->meas[pp->meas];
            mtt_real d2;
            if (!(pp->beta > MTT_ZERO) && k != a) {
                continue; /* not in the final row */
            }
            d2 = mtt_imm_model_d2(trk, tf, j, ms, &c[m].p);
            if (!(d2 <= trk->gamma)) {
                continue;
            }
            c[m].lam = pp->lam;
            c[m].amp = ms->amp;
            c[m].idx = pp->meas;
            if (k == a) {
                has_a = 1;
                sel = m;
            }
            ++m;
        }
        if (m == 0u) {
            sum = MTT_ADDS(sum, MTT_MUL_RP(tf->cbar[j], miss));
            continue;
        }
        mtt_ihpda_betas(p->pd, p->pg, vg,
                        (p->snr_rho > MTT_ZERO && tf->has_all_amp) ? &trk->prank[MTT_PRANK_ROW(m)] : NULL, c,
                        m, beta, L, NULL);
        for (k = 1; k < m; ++k) {
            b = (beta[k] > beta[b]) ? k : b;
        }
        sum = MTT_ADDS(sum, MTT_MUL_RP(tf->cbar[j], CAND_L(L[has_a ? sel : b], c[has_a ? sel : b])));
    }
    return sum;
}

void mtt_imm_update_track(mtt_tracker *trk, uint16_t ti, uint16_t first, uint16_t m,
                          const mtt_real beta[], mtt_real beta0)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    const uint8_t r = trk->par.imm_n_models;
    mtt_real e0[MTT_MAX_MODELS], b0j[MTT_MAX_MODELS];
    /* in the tracker's row scratch, not on the stack */
    mtt_real(*e)[MTT_MAX_MODELS] = trk->row.imm_e;
    mtt_real(*bj)[MTT_MAX_GATED] = trk->row.imm_beta;
    mtt_real(*nu)[2] = trk->row.nu;
    uint16_t i;
    uint8_t j;
#if MTT_WITH_MEAS_COV
    int own;
#endif
    for (j = 0; j < MTT_MAX_MODELS; ++j) {
        e0[j] = MTT_P(1.0); /* every slot: GCC -O3 cannot see that only r are read */
    }
    for (i = 0; i < m; ++i) {
        const mtt_mstore *ms = &trk->meas[trk->pairs[first + i].meas];
        model_likelihoods(trk, tf, ms, e[i]);
    }
    (void)mtt_imm_apportion(r, tf->cbar, m, beta0, beta, e0, e, t->mu, b0j, bj);
#if MTT_WITH_MEAS_COV
    own = trk->n_own_r > 0u && mtt_meas_row_r(trk, first, m) > 0u; /* §3.1 */
#endif
    for (j = 0; j < r; ++j) {
        const uint8_t n = model_n(trk->par.imm_model[j]);
        if (m == 0u) {
            /* β_0 = 1: the PDA update is the prediction itself (as
             * update.c's keep_prediction), copied rather than recomputed */
            memcpy(t->xm[j], tf->xpm[j], n * sizeof t->xm[j][0]);
            for (i = 0; i < n; ++i) {
                memcpy(t->Pm[j][i], tf->Ppm[j][i], n * sizeof t->Pm[j][i][0]);
            }
            MTT_COV_COPY_E(t->Pm[j], tf->Ppm[j]);
            continue;
        }
        for (i = 0; i < m; ++i) {
            const mtt_mstore *ms = &trk->meas[trk->pairs[first + i].meas];
            nu[i][0] = MTT_SUBS(ms->x, tf->xpm[j][0]);
            nu[i][1] = MTT_SUBS(ms->y, tf->xpm[j][1]);
        }
#if MTT_WITH_MEAS_COV
        if (own) {
            mtt_kalman_pda_each(n, tf->xpm[j], tf->Ppm[j], trk->row.rj, trk->row.rr, trk->par.sensor_xy, m, nu,
                                bj[j], b0j[j], trk->row.dj,
                                t->xm[j], t->Pm[j]);
            continue;
        }
#endif
        mtt_kalman_pda_n(n, tf->xpm[j], tf->Ppm[j], tf->Km[j], tf->Sim[j], trk->R, m, nu, bj[j], b0j[j],
                         t->xm[j], t->Pm[j]);
    }
    (void)mtt_imm_combine(r, t->mu, t->xm, t->Pm, t->x, t->P);
}

/* [CHOICE] ALGORITHMS.md §14.2: every model starts from the two-point (or
 * seeded) x, P; CA's acceleration from 0 with variance q_CA dt per axis
 * (one interval of its own white jerk: two points carry no information on
 * it), CT's turn rate from 0 with variance q_turn dt (the same rule);
 * mode probabilities imm_initial. */
void mtt_imm_seed_track(mtt_tracker *trk, uint16_t ti, mtt_real dt)
{
    mtt_track *t = &trk->tracks[ti];
    const mtt_params *p = &trk->par;
    uint8_t j, a;
    memset(t->xm, 0, sizeof t->xm);
    memset(t->Pm, 0, sizeof t->Pm);
    memset(t->mu, 0, sizeof t->mu);
    for (j = 0; j < p->imm_n_models; ++j) {
        t->mu[j] = p->imm_initial[j];
        for (a = 0; a < MTT_STATE_N; ++a) {
            t->xm[j][a] = t->x[a];
            memcpy(t->Pm[j][a], t->P[a], MTT_STATE_N * sizeof t->P[a][0]);
        }
        MTT_COV_COPY_E(t->Pm[j], t->P);
#if MTT_WITH_IMM_CACT
        if (p->imm_model[j] == MTT_MODEL_CA) {
            t->Pm[j][4][4] = p->imm_psd[j] * dt;
            t->Pm[j][5][5] = p->imm_psd[j] * dt;
        } else if (p->imm_model[j] == MTT_MODEL_CT) {
            t->Pm[j][4][4] = p->imm_turn_psd[j] * dt;
        }
#else
        (void)dt;
#endif
    }
}

void mtt_imm_update_assoc(mtt_tracker *trk, uint16_t ti, uint8_t kind)
{
    mtt_track *t = &trk->tracks[ti];
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real *beta = trk->row.beta;
    uint16_t j, b = 0;
    if (kind == MTT_UPDATE_ONE) {
        if (tf->assigned < 0) {
            mtt_imm_update_track(trk, ti, 0, 0, beta, MTT_P(1.0));
            t->existence = mtt_existence_update(tf->ex_pred, MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), MTT_MUL_PP(trk->par.pd, trk->par.pg))));
            t->meas = -1;
        } else {
            const mtt_pair *pp = &trk->pairs[tf->assigned];
            const mtt_real L = mtt_imm_exist_L(trk, ti, (uint16_t)tf->assigned);
            beta[0] = pp->beta;
            mtt_imm_update_track(trk, ti, (uint16_t)tf->assigned, 1, beta, MTT_SUB(MTT_P(1.0), pp->beta));
            t->existence = mtt_existence_update(tf->ex_pred, L);
            t->meas = (int32_t)trk->meas[pp->meas].src;
        }
        return;
    }
    if (tf->pair_count == 0u) {
        mtt_imm_update_track(trk, ti, 0, 0, beta, MTT_P(1.0));
        t->existence = mtt_existence_update(tf->ex_pred, MTT_CVT_P_R(MTT_SUB(MTT_P(1.0), MTT_MUL_PP(trk->par.pd, trk->par.pg))));
        t->meas = -1;
        return;
    }
    if (kind == MTT_UPDATE_HARD) {
        /* NNJPDA (§13.5): every model takes the assigned measurement with
         * beta 1, or keeps its prediction; existence of §13.2 either way */
        if (tf->assigned < 0) {
            mtt_imm_update_track(trk, ti, 0, 0, beta, MTT_P(1.0));
            t->meas = -1;
        } else {
            beta[0] = MTT_P(1.0);
            mtt_imm_update_track(trk, ti, (uint16_t)tf->assigned, 1, beta, MTT_ZERO);
            t->meas = (int32_t)trk->meas[trk->pairs[tf->assigned].meas].src;
        }
        t->existence = tf->ex_post;
        return;
    }
    for (j = 0; j < tf->pair_count; ++j) {
        beta[j] = trk->pairs[tf->pair_first + j].beta;
        if (beta[j] > beta[b]) {
            b = j;
        }
    }
    mtt_imm_update_track(trk, ti, tf->pair_first, tf->pair_count, beta, tf->beta0);
    t->existence = tf->ex_post;
    t->meas = (int32_t)trk->meas[trk->pairs[tf->pair_first + b].meas].src;
}

#endif /* MTT_WITH_IMM */
