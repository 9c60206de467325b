/* SPDX-License-Identifier: BSD-3-Clause */
/* split.c - split-target mathematics of one track (ALGORITHMS.md §14.3,
 * [S3]): model 5 "just split" (two clusters, per-half PDA update, cross
 * covariance, likelihood with the exponent -(m_i - 1)), model 6 "split"
 * (stacked two-target state, non-parametric joint events of [S3] eq. 14,
 * coupled update with the corrected bracket of eq. 25, model likelihood),
 * the decoupling test of eq. 27 and the conversion of a decoupled split
 * state into two independent track states; model 5's child half for a
 * split of known speed (ALGORITHMS.md §14.3, split_known_speed).
 *
 * Plain functions over arrays: a single-target model has n state
 * components (4 <= n <= MTT_MAX_STATE), position first (H = [I 0],
 * motion.h); the stacked state is [x_1; x_2] with 2n components, target 1
 * the parent (the largest-beta cluster of model 5), target 2 the child.
 *
 * Likelihoods are returned as ratios to the all-clutter density V^-m of
 * the m validated measurements (V: the validation volume), the scale of
 * the IPDA likelihood ratio of ALGORITHMS.md §14.2, so that the IMM mode
 * update can weigh models 5 and 6 against the single-target models; the
 * literal densities of [S3] are the ratio times V^-m, which under- or
 * overflows float for a handful of measurements.
 *
 * Covariances are written as beta0 Pp + (1 - beta0) A Pp A' + W M W',
 * A = I - W H, M = (1 - beta0) R + spread: the Joseph form of the updated
 * covariance plus the spread of the innovations, a sum of positive
 * semi-definite terms (as kalman.c does for one target).  A's measured
 * block is R S^-1 (exact: H Pp H' = S - R), which avoids the cancellation
 * of I - W H when the prior is far wider than R.
 *
 * A covariance per detection (Rj, ALGORITHMS.md §3.1; NULL: R for every
 * measurement, the forms above): each measurement's S_j = H P H' + R_j in
 * its gate and likelihood, and an update that is the mixture of the
 * single-detection (model 6: single-event) updates, each the Joseph form
 * with its own R and gain, plus their spread (the forms above when the R_j
 * are equal).  Only with MTT_WITH_MEAS_COV.  Their range rates (rd, polar
 * detections, ALGORITHMS.md §3.2): mtt_polar_rdot_f's factor in the gate
 * and likelihood of the detection's target, and the EKF step of that
 * target's block (mtt_polar_rdot_step) at the end of each single-detection
 * (single-event) update. */
#include "mtt_internal.h"

#if MTT_WITH_SPLIT

#define NS MTT_SPLIT_STATE
#define QMAX 4 /* measurement size of the stacked model: 2 targets x 2 */

/* Inverse of the symmetric positive definite q x q matrix S (q <= QMAX);
 * L: the caller's room for its LDL' factor. */
static int inv_spd(int q, mtt_cov S, mtt_cov L, mtt_real Si[][QMAX])
{
    mtt_state d;
    mtt_real y[QMAX];
    int i, k, c;
    if (mtt_ldl(q, S, L, d) != 0) {
        return -1;
    }
    for (c = 0; c < q; ++c) {
        /* column c: L y = e_c, then D L' x = y */
        for (i = 0; i < q; ++i) {
            mtt_real s = (i == c) ? MTT_R(1.0) : MTT_R(0.0);
            for (k = 0; k < i; ++k) {
                s -= L[i][k] * y[k];
            }
            y[i] = s;
        }
        for (i = q - 1; i >= 0; --i) {
            mtt_real s = y[i] / d[i];
            for (k = i + 1; k < q; ++k) {
                s -= L[k][i] * Si[k][c];
            }
            Si[i][c] = s;
        }
    }
    for (i = 0; i < q; ++i) {
        for (k = i + 1; k < q; ++k) {
            const mtt_real s = MTT_R(0.5) * (Si[i][k] + Si[k][i]);
            Si[i][k] = s;
            Si[k][i] = s;
        }
    }
    return 0;
}

/* Inverse Si and determinant of the symmetric 2x2 S (s11, s12, s22).
 * Returns -1 (nothing written) when det S is not positive and finite. */
static int inv2(const mtt_real S[3], mtt_real Si[3], mtt_real *det)
{
    const mtt_real d = S[0] * S[2] - S[1] * S[1];
    if (!(d > MTT_R(0.0)) || !mtt_isfinite(d)) {
        return -1;
    }
    *det = d;
    Si[0] = S[2] / d;
    Si[1] = -S[1] / d;
    Si[2] = S[0] / d;
    return 0;
}

/* 2x2 innovation covariance of the target whose position is at offset o
 * of the state: S = Pp_pos + R (sym: s11, s12, s22), S^-1 and det S.
 * Returns -1 when det S is not positive and finite. */
static int innov2(mtt_real Pp[][NS], int o, const mtt_real R[3], mtt_real S[3], mtt_real Si[3],
                  mtt_real *det)
{
    S[0] = Pp[o][o] + R[0];
    S[1] = MTT_R(0.5) * (Pp[o][o + 1] + Pp[o + 1][o]) + R[1];
    S[2] = Pp[o + 1][o + 1] + R[2];
    return inv2(S, Si, det);
}

static mtt_real quad2(const mtt_real Si[3], mtt_real a, mtt_real b)
{
    return Si[0] * a * a + MTT_R(2.0) * Si[1] * a * b + Si[2] * b * b;
}

/* N(nu; 0, S) of a 2-D innovation with d2 = nu' S^-1 nu (untruncated). */
static mtt_real gauss2(mtt_real d2, mtt_real det)
{
    return mtt_exp(MTT_R(-0.5) * d2) / (MTT_R(2.0) * MTT_PI * mtt_sqrt(det));
}

/* The mixed update of an N-state (N <= NS) with a q-dimensional measurement
 * of the components sel[0..q) (H selects them), measurement noise Rq:
 *   S = H Pp H' + Rq, W = Pp H' S^-1, A = I - W H,
 *   x = xp + W nub,
 *   P = beta0 Pp + (1 - beta0) A Pp A' + W [(1 - beta0) Rq + spread] W'
 * (ALGORITHMS.md §6 and §14.3 in one form; beta0 = 0 and spread = 0 is the
 * Joseph-form Kalman update of ALGORITHMS.md §3).  APA (may be NULL)
 * receives A Pp A'.  W, A and A Pp live in wk (not the stack).  Returns
 * -1 when S is not positive definite (nothing written). */
static int mixed_update(mtt_split_work *wk, int N, int q, const int sel[], const mtt_real xp[],
                        mtt_real Pp[][NS], mtt_real Rq[][QMAX], mtt_real beta0,
                        const mtt_real nub[], mtt_real spread[][QMAX], mtt_real x[],
                        mtt_real P[][NS], mtt_real APA[][NS])
{
    mtt_real(*S)[MTT_MAX_STATE] = wk->S; /* q x q used, q <= QMAX <= MTT_MAX_STATE */
    mtt_real Si[QMAX][QMAX], M[QMAX][QMAX];
    mtt_real(*W)[QMAX] = wk->W;
    mtt_real(*A)[NS] = wk->A;
    mtt_real(*AP)[NS] = wk->AP;
    const mtt_real w = MTT_R(1.0) - beta0;
    int i, k, a, b;
    for (a = 0; a < q; ++a) {
        for (b = 0; b < q; ++b) {
            S[a][b] = MTT_R(0.5) * (Pp[sel[a]][sel[b]] + Pp[sel[b]][sel[a]]) + Rq[a][b];
        }
    }
    if (inv_spd(q, S, wk->L, Si) != 0) {
        return -1;
    }
    for (i = 0; i < N; ++i) {
        for (a = 0; a < q; ++a) {
            mtt_real s = MTT_R(0.0);
            for (b = 0; b < q; ++b) {
                s += Pp[i][sel[b]] * Si[b][a];
            }
            W[i][a] = s;
        }
    }
    /* A = I - W H; its measured block (rows and columns sel) is Rq S^-1. */
    for (i = 0; i < N; ++i) {
        for (k = 0; k < N; ++k) {
            A[i][k] = (i == k) ? MTT_R(1.0) : MTT_R(0.0);
        }
        for (a = 0; a < q; ++a) {
            A[i][sel[a]] -= W[i][a];
        }
    }
    for (a = 0; a < q; ++a) {
        for (b = 0; b < q; ++b) {
            mtt_real s = MTT_R(0.0);
            for (k = 0; k < q; ++k) {
                s += Rq[a][k] * Si[k][b];
            }
            A[sel[a]][sel[b]] = s;
        }
    }
    for (i = 0; i < N; ++i) {
        for (k = 0; k < N; ++k) {
            mtt_real s = MTT_R(0.0);
            int l;
            for (l = 0; l < N; ++l) {
                s += A[i][l] * Pp[l][k];
            }
            AP[i][k] = s;
        }
    }
    for (a = 0; a < q; ++a) {
        for (b = 0; b < q; ++b) {
            M[a][b] = w * Rq[a][b] + spread[a][b];
        }
    }
    for (i = 0; i < N; ++i) {
        for (k = i; k < N; ++k) {
            mtt_real apa = MTT_R(0.0), wmw = MTT_R(0.0);
            int l;
            for (l = 0; l < N; ++l) {
                apa += AP[i][l] * A[k][l];
            }
            for (a = 0; a < q; ++a) {
                mtt_real s = MTT_R(0.0);
                for (b = 0; b < q; ++b) {
                    s += M[a][b] * W[k][b];
                }
                wmw += W[i][a] * s;
            }
            if (APA != NULL) {
                APA[i][k] = apa;
                APA[k][i] = apa;
            }
            P[i][k] = beta0 * MTT_R(0.5) * (Pp[i][k] + Pp[k][i]) + w * apa + wmw;
            P[k][i] = P[i][k];
        }
    }
    for (i = 0; i < N; ++i) {
        mtt_real s = xp[i];
        for (a = 0; a < q; ++a) {
            s += W[i][a] * nub[a];
        }
        x[i] = s;
    }
    return 0;
}

static int n_ok(uint8_t n)
{
    return n >= 4u && n <= MTT_MAX_STATE;
}

/* R (r11, r12, r22) as the 2 x 2 block of Rq at (o, o). */
static void rq_block(const mtt_real R[3], mtt_real Rq[][QMAX], int o)
{
    Rq[o][o] = R[0];
    Rq[o][o + 1] = R[1];
    Rq[o + 1][o] = R[1];
    Rq[o + 1][o + 1] = R[2];
}

#if MTT_WITH_MEAS_COV
/* ---- the mixture of single-detection updates (ALGORITHMS.md §3.1) ---- */

/* Clears the mixture's sums of N states (and Am, may be NULL). */
static void mix_clear(mtt_split_work *wk, int N, mtt_real Am[][NS])
{
    int i, k;
    for (i = 0; i < N; ++i) {
        wk->da[i] = MTT_R(0.0);
        for (k = 0; k < N; ++k) {
            wk->Pa[i][k] = MTT_R(0.0);
            if (Am != NULL) {
                Am[i][k] = MTT_R(0.0);
            }
        }
    }
}

/* The range-rate factor of measurement j (1 without rd or its range rate)
 * against a target's prediction xo, Po (rows of stride st), S its S_j and
 * (nx, ny) its position innovation. */
static mtt_real rdot_f(const mtt_split_rdot *rd, uint16_t j, const mtt_real *xo, const mtt_real *Po, int st,
                       const mtt_real S[3], mtt_real nx, mtt_real ny)
{
    return (rd == NULL) ? MTT_R(1.0)
                        : mtt_polar_rdot_f(rd->sensor, rd->gamma, rd->vmax, xo, Po, st, S, nx, ny, rd->rr[j]);
}

/* The EKF steps of a term's range rates on (wk->xe, wk->Pe): target t's
 * detection jt[t] (-1: none; its block at t N / 2, rd NULL: none); with am
 * each step's I - K H also left-multiplies wk->A (the term's map of the
 * prior error, for model 5's cross covariance). */
static void rdot_steps(mtt_split_work *wk, int N, const mtt_split_rdot *rd, const int16_t jt[2], int am)
{
    int t, i, k, l;
    for (t = 0; t < 2 && rd != NULL; ++t) {
        const mtt_real *rr = (jt[t] >= 0) ? rd->rr[jt[t]] : NULL;
        if (rr == NULL || mtt_polar_rdot_step(N, t * (N / 2), NS, rd->sensor, rr, wk->xe, &wk->Pe[0][0],
                                              &wk->Mr[0][0], &wk->AP[0][0]) != 0 || !am) {
            continue;
        }
        for (i = 0; i < N; ++i) {
            for (k = 0; k < N; ++k) {
                mtt_real v = MTT_R(0.0);
                for (l = 0; l < N; ++l) {
                    v += wk->Mr[i][l] * wk->A[l][k];
                }
                wk->AP[i][k] = v;
            }
        }
        for (i = 0; i < N; ++i) {
            for (k = 0; k < N; ++k) {
                wk->A[i][k] = wk->AP[i][k];
            }
        }
    }
}

/* One term of weight w: the Kalman update of (xp, Pp) with the q-vector
 * innovation nu of noise Rq, then its range rates' steps (rdot_steps; x_e,
 * P_e, d = x_e - xp).  Pass 0 adds w d to wk->da and (Am not NULL) w (the
 * map of the prior error: I - W H, times the steps' I - K H) to Am; pass
 * 1, with da complete, w (P_e + (d - da)(d - da)') to wk->Pa.  -1 when S
 * is not positive definite. */
static int mix_term(mtt_split_work *wk, int N, int q, const int sel[], const mtt_real xp[], mtt_real Pp[][NS],
                    mtt_real Rq[][QMAX], const mtt_real nu[], const mtt_split_rdot *rd, const int16_t jt[2],
                    mtt_real w, int pass, mtt_real Am[][NS])
{
    mtt_real none[QMAX][QMAX] = {{MTT_R(0.0)}};
    int i, k;
    if (mixed_update(wk, N, q, sel, xp, Pp, Rq, MTT_R(0.0), nu, none, wk->xe, wk->Pe, NULL) != 0) {
        return -1;
    }
    rdot_steps(wk, N, rd, jt, pass == 0 && Am != NULL);
    for (i = 0; i < N; ++i) {
        const mtt_real di = wk->xe[i] - xp[i];
        for (k = 0; k < N; ++k) {
            if (pass == 0) {
                if (Am != NULL) {
                    Am[i][k] += w * wk->A[i][k];
                }
            } else {
                wk->Pa[i][k] += w * (wk->Pe[i][k] + (di - wk->da[i]) * (wk->xe[k] - xp[k] - wk->da[k]));
            }
        }
        if (pass == 0) {
            wk->da[i] += w * di;
        }
    }
    return 0;
}

/* The mixture: x = xp + da, P = b0 (Pp + da da') + Pa, symmetrised (b0:
 * the weight of no detection, whose d is 0). */
static void mix_finish(const mtt_split_work *wk, int N, const mtt_real xp[], mtt_real Pp[][NS], mtt_real b0,
                       mtt_real x[], mtt_real P[][NS])
{
    int i, k;
    for (i = 0; i < N; ++i) {
        x[i] = xp[i] + wk->da[i];
    }
    for (i = 0; i < N; ++i) {
        for (k = i; k < N; ++k) {
            const mtt_real v = b0 * (MTT_R(0.5) * (Pp[i][k] + Pp[k][i]) + wk->da[i] * wk->da[k]) +
                               MTT_R(0.5) * (wk->Pa[i][k] + wk->Pa[k][i]);
            P[i][k] = v;
            P[k][i] = v;
        }
    }
}

/* A half of model 5 (and mtt_split_known's child) with the detections'
 * own R and range rates: the measurements j of cluster h, weights w[j],
 * innovations nu[j]; Am (may be NULL) the weighted mean of the maps I -
 * W_j H (times the range rate's I - K_j H). */
static int mix_half(mtt_split_work *wk, int n, const mtt_real xp[], mtt_real Pp[][NS], const mtt_real *const Rj[],
                    const mtt_split_rdot *rd, uint16_t m, const uint8_t cl[], uint8_t h, const mtt_real w[],
                    mtt_real nu[][2], mtt_real x[], mtt_real P[][NS], mtt_real Am[][NS])
{
    static const int sel[2] = {0, 1};
    mtt_real Rq[QMAX][QMAX] = {{MTT_R(0.0)}};
    uint16_t j;
    int pass;
    mix_clear(wk, n, Am);
    for (pass = 0; pass < 2; ++pass) {
        for (j = 0u; j < m; ++j) {
            if (cl[j] == h) {
                const int16_t jt[2] = {(int16_t)j, -1};
                rq_block(Rj[j], Rq, 0);
                if (mix_term(wk, n, 2, sel, xp, Pp, Rq, nu[j], rd, jt, w[j], pass, Am) != 0) {
                    return -1;
                }
            }
        }
    }
    mix_finish(wk, n, xp, Pp, MTT_R(0.0), x, P);
    return 0;
}

/* Model 5's cross covariance with the detections' own R: Am[0] Pp Am[1]'
 * (A Pp A' of [S3] eq. 12 when the R_j are equal). */
static void mix_cross(mtt_split_work *wk, int n, mtt_real Pp[][NS], mtt_real P12[][NS])
{
    int i, k, l;
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            mtt_real s = MTT_R(0.0);
            for (l = 0; l < n; ++l) {
                s += wk->Am[0][i][l] * Pp[l][k];
            }
            wk->AP[i][k] = s;
        }
    }
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            mtt_real s = MTT_R(0.0);
            for (l = 0; l < n; ++l) {
                s += wk->AP[i][l] * wk->Am[1][k][l];
            }
            P12[i][k] = s;
        }
    }
}
#endif

/* ---- stacked prediction ---- */

int mtt_split_predict(mtt_split_work *wk, uint8_t n, mtt_real F[][MTT_MAX_STATE],
                      mtt_real Q[][MTT_MAX_STATE], const mtt_split_state xs, mtt_split_cov Ps,
                      mtt_split_state xps, mtt_split_cov Pps)
{
    mtt_real(*FP)[NS] = wk->AP;
    int i, k, l, ti, tk;
    if (!n_ok(n)) {
        return -1;
    }
    /* F^s = blockdiag(F, F): each target moves alone; Q^s = blockdiag(Q,
     * Q): their process noises are independent, so the cross covariance
     * only propagates (F P_12 F') and the targets decorrelate. */
    for (ti = 0; ti < 2; ++ti) {
        const int o = ti * (int)n;
        for (i = 0; i < n; ++i) {
            mtt_real s = MTT_R(0.0);
            for (l = 0; l < n; ++l) {
                s += F[i][l] * xs[o + l];
            }
            xps[o + i] = s;
            for (k = 0; k < 2 * n; ++k) {
                s = MTT_R(0.0);
                for (l = 0; l < n; ++l) {
                    s += F[i][l] * Ps[o + l][k];
                }
                FP[o + i][k] = s;
            }
        }
    }
    for (ti = 0; ti < 2; ++ti) {
        for (tk = ti; tk < 2; ++tk) {
            const int oi = ti * (int)n, ok = tk * (int)n;
            for (i = 0; i < n; ++i) {
                for (k = 0; k < n; ++k) {
                    mtt_real s = (ti == tk) ? MTT_R(0.5) * (Q[i][k] + Q[k][i]) : MTT_R(0.0);
                    for (l = 0; l < n; ++l) {
                        s += FP[oi + i][ok + l] * F[k][l];
                    }
                    Pps[oi + i][ok + k] = s;
                }
            }
        }
    }
    /* P_21 = P_12', then the diagonal blocks symmetrised */
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            Pps[n + k][i] = Pps[i][n + k];
        }
    }
    for (i = 0; i < 2 * n; ++i) {
        for (k = i + 1; k < 2 * n; ++k) {
            const mtt_real v = MTT_R(0.5) * (Pps[i][k] + Pps[k][i]);
            Pps[i][k] = v;
            Pps[k][i] = v;
        }
    }
    return 0;
}

/* ---- model 5: just split ---- */

int mtt_split_just(mtt_split_work *wk, uint8_t n, const mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE],
                   const mtt_real R[3], const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m,
                   mtt_real z[][2], const mtt_real beta[], mtt_real vg, mtt_split_state xs, mtt_split_cov Ps,
                   uint8_t cluster[],
                   mtt_real beta_n[], mtt_real *lik)
{
    mtt_real(*Pq)[NS] = wk->Pq;
    mtt_real(*xh)[NS] = wk->xh;
    mtt_real(*Ph)[NS][NS] = wk->Ph;
    mtt_real(*P12)[NS] = wk->P12;
    mtt_real(*nu)[2] = wk->nu;
    mtt_real *bn = wk->bn;
    uint8_t *cl = wk->cl;
    mtt_real S[3], Si[3], det, bs[2], gs[2];
    mtt_real Rq[QMAX][QMAX] = {{MTT_R(0.0)}};
    uint16_t mi[2] = {0u, 0u};
    uint16_t j, c[2] = {0u, 0u};
    static const int sel[2] = {0, 1};
    int i, k, h;
    if (!n_ok(n) || m < 2u || m > MTT_MAX_SPLIT_MEAS || !(vg > MTT_R(0.0))) {
        return -1;
    }
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            Pq[i][k] = Pp[i][k];
        }
    }
    if (innov2(Pq, 0, R, S, Si, &det) != 0) {
        return -1;
    }
    /* Steps 1 and 2: centres = the two largest beta (ties: lower index). */
    for (j = 1u; j < m; ++j) {
        if (beta[j] > beta[c[0]]) {
            c[0] = j;
        }
    }
    c[1] = (c[0] == 0u) ? 1u : 0u;
    for (j = 0u; j < m; ++j) {
        if (j != c[0] && beta[j] > beta[c[1]]) {
            c[1] = j;
        }
    }
    /* Step 3: every other measurement to the nearer centre, Mahalanobis
     * distance with S; ties to cluster 1 (the parent). */
    for (j = 0u; j < m; ++j) {
        nu[j][0] = z[j][0] - xp[0];
        nu[j][1] = z[j][1] - xp[1];
        if (j == c[0] || j == c[1]) {
            cl[j] = (uint8_t)((j == c[0]) ? 0u : 1u);
        } else {
            const mtt_real d0 = quad2(Si, z[j][0] - z[c[0]][0], z[j][1] - z[c[0]][1]);
            const mtt_real d1 = quad2(Si, z[j][0] - z[c[1]][0], z[j][1] - z[c[1]][1]);
            cl[j] = (uint8_t)((d1 < d0) ? 1u : 0u);
        }
        ++mi[cl[j]];
    }
    /* Step 4: beta renormalised per cluster (both targets detected, no
     * beta_0); a cluster whose betas are all 0 shares equally. */
    bs[0] = MTT_R(0.0);
    bs[1] = MTT_R(0.0);
    gs[0] = MTT_R(0.0);
    gs[1] = MTT_R(0.0);
    for (j = 0u; j < m; ++j) {
        bs[cl[j]] += beta[j];
#if MTT_WITH_MEAS_COV
        if (Rj != NULL) {
            /* its own S_j (§3.1) and range rate (§3.2); the clusters stay
             * on the track's S */
            mtt_real Sj[3], Sij[3], detj;
            if (innov2(Pq, 0, Rj[j], Sj, Sij, &detj) != 0) {
                return -1;
            }
            gs[cl[j]] += gauss2(quad2(Sij, nu[j][0], nu[j][1]), detj) *
                         rdot_f(rd, j, xp, &Pq[0][0], NS, Sj, nu[j][0], nu[j][1]);
            continue;
        }
#endif
        gs[cl[j]] += gauss2(quad2(Si, nu[j][0], nu[j][1]), det);
    }
#if !MTT_WITH_MEAS_COV
    (void)Rj;
    (void)rd;
#endif
    for (h = 0; h < 2; ++h) {
        mtt_real nub[QMAX] = {MTT_R(0.0)}, sp[QMAX][QMAX] = {{MTT_R(0.0)}};
        for (j = 0u; j < m; ++j) {
            if (cl[j] == (uint8_t)h) {
                bn[j] = (bs[h] > MTT_R(0.0)) ? beta[j] / bs[h] : MTT_R(1.0) / (mtt_real)mi[h];
                nub[0] += bn[j] * nu[j][0];
                nub[1] += bn[j] * nu[j][1];
            }
        }
#if MTT_WITH_MEAS_COV
        if (Rj != NULL) {
            if (mix_half(wk, n, xp, Pq, Rj, rd, m, cl, (uint8_t)h, bn, nu, xh[h], Ph[h], wk->Am[h]) != 0) {
                return -1;
            }
            continue;
        }
#endif
        for (j = 0u; j < m; ++j) {
            if (cl[j] == (uint8_t)h) {
                const mtt_real dx = nu[j][0] - nub[0], dy = nu[j][1] - nub[1];
                sp[0][0] += bn[j] * dx * dx;
                sp[0][1] += bn[j] * dx * dy;
                sp[1][1] += bn[j] * dy * dy;
            }
        }
        sp[1][0] = sp[0][1];
        rq_block(R, Rq, 0);
        /* Step 5: the PDA update of the half (beta_0 = 0): x_h and P_hh;
         * A Pp A' is the cross covariance P_12 of [S3] eq. 12. */
        if (mixed_update(wk, n, 2, sel, xp, Pq, Rq, MTT_R(0.0), nub, sp, xh[h], Ph[h], P12) != 0) {
            return -1;
        }
    }
#if MTT_WITH_MEAS_COV
    if (Rj != NULL) {
        mix_cross(wk, n, Pq, P12);
    }
#endif
    for (i = 0; i < n; ++i) {
        xs[i] = xh[0][i];
        xs[n + i] = xh[1][i];
        for (k = 0; k < n; ++k) {
            Ps[i][k] = Ph[0][i][k];
            Ps[n + i][n + k] = Ph[1][i][k];
            Ps[i][n + k] = P12[i][k];
            Ps[n + i][k] = P12[k][i];
        }
    }
    for (j = 0u; j < m; ++j) {
        cluster[j] = cl[j];
        beta_n[j] = bn[j];
    }
    /* Likelihood [S3] eq. 13 with the exponent -(m_i - 1) (ALGORITHMS.md
     * §14.3 RECON): prod_i (1/m_i) sum_{j in I_i} N_j V^-(m_i - 1), returned
     * as its ratio to V^-m: prod_i (V/m_i) sum_{j in I_i} N_j. */
    *lik = (vg / (mtt_real)mi[0]) * gs[0] * (vg / (mtt_real)mi[1]) * gs[1];
    return 0;
}

/* ---- model 6: split ---- */

int mtt_split_assoc_init(uint8_t n, const mtt_split_state xps, mtt_split_cov Pps, const mtt_real R[3],
                         const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m, mtt_real z[][2],
                         mtt_real pd, mtt_real pg, mtt_real gamma, mtt_real vg, mtt_real lam, mtt_split_assoc *as)
{
    mtt_real S[3], Si[2][3], det[2];
    uint16_t j;
    int t;
    if (!n_ok(n) || m > MTT_MAX_SPLIT_MEAS || !(pd >= MTT_R(0.0) && pd <= MTT_R(1.0)) ||
        !(pg > MTT_R(0.0) && pg <= MTT_R(1.0)) || !(gamma > MTT_R(0.0)) || !(lam >= MTT_R(0.0)) ||
        !mtt_isfinite(lam) || (lam == MTT_R(0.0) && !(vg > MTT_R(0.0)))) {
        return -1;
    }
    /* every innovation covariance first: on error nothing is written */
#if MTT_WITH_MEAS_COV
    for (t = 0; t < 2 && Rj != NULL; ++t) {
        for (j = 0u; j < m; ++j) {
            if (innov2(Pps, t * (int)n, Rj[j], S, Si[t], &det[t]) != 0) {
                return -1;
            }
        }
    }
#else
    (void)Rj;
    (void)rd;
#endif
    for (t = 0; t < 2; ++t) {
        if (innov2(Pps, t * (int)n, R, S, Si[t], &det[t]) != 0) {
            return -1;
        }
    }
    for (t = 0; t < 2; ++t) {
        const int o = t * (int)n;
        for (j = 0u; j < m; ++j) {
            const mtt_real *sit = Si[t];
            mtt_real dt = det[t], d2, g, f = MTT_R(1.0);
#if MTT_WITH_MEAS_COV
            mtt_real sij[3];
            if (Rj != NULL) {
                (void)innov2(Pps, o, Rj[j], S, sij, &dt); /* its own S_tj (§3.1): checked above */
                sit = sij;
                /* its range rate at target t's prediction (§3.2) */
                f = rdot_f(rd, j, &xps[o], &Pps[o][o], NS, S, z[j][0] - xps[o], z[j][1] - xps[o + 1]);
            }
#endif
            d2 = quad2(sit, z[j][0] - xps[o], z[j][1] - xps[o + 1]);
            /* PD V N: the detection factor of [S3] eq. 14 times V (the
             * ratio to V^-m), or PD N / lambda with a known clutter
             * density (times a range rate's factor); 0 outside the
             * target's gate (not feasible, a range rate's included). */
            g = ((lam > MTT_R(0.0)) ? gauss2(d2, dt) / lam : vg * gauss2(d2, dt)) * f;
            as->a[t][j] = (d2 <= gamma) ? pd * g : MTT_R(0.0);
            as->nu[t][j][0] = z[j][0] - xps[o];
            as->nu[t][j][1] = z[j][1] - xps[o + 1];
        }
        /* Undetected: 1 - PD PG, the library's convention for N truncated
         * to the gate (ALGORITHMS.md §4); PG = 1 gives [S3]'s 1 - PD. */
        as->b[t] = MTT_R(1.0) - pd * pg;
    }
    as->m = m;
    as->n = n;
    as->parametric = (uint8_t)((lam > MTT_R(0.0)) ? 1u : 0u);
    as->pd = pd;
    as->scale = (lam > MTT_R(0.0)) ? MTT_R(1.0) / lam : vg;
    return 0;
}

mtt_real mtt_split_event_weight(const mtt_split_assoc *as, int16_t j1, int16_t j2)
{
    /* Non-parametric: phi!/m! of [S3] eq. 14 (phi = m - number detected)
     * with the V^m of the ratio folded into the detection factors.
     * Parametric (Poisson clutter of density lambda): the factorials
     * cancel, the ratio to lambda^m is the product of the factors. */
    const int16_t m = (int16_t)as->m;
    const mtt_real m1 = as->parametric ? MTT_R(1.0) : (mtt_real)m;
    const mtt_real m2 = as->parametric ? MTT_R(1.0) : (mtt_real)m * (mtt_real)(m - 1);
    mtt_real w;
    if (j1 < -1 || j2 < -1 || j1 >= m || j2 >= m || (j1 >= 0 && j1 == j2)) {
        return MTT_R(0.0); /* not an event: one measurement, two targets */
    }
    if (j1 >= 0 && j2 >= 0) {
        w = as->a[0][j1] * as->a[1][j2] / m2;
    } else if (j1 >= 0) {
        w = as->a[0][j1] * as->b[1] / m1;
    } else if (j2 >= 0) {
        w = as->b[0] * as->a[1][j2] / m1;
    } else {
        w = as->b[0] * as->b[1];
    }
    return w;
}

int mtt_split_joint(mtt_split_assoc *as)
{
    const int16_t m = (int16_t)as->m;
    mtt_real c = MTT_R(0.0);
    int16_t j1, j2;
    int t;
    /* Brute force over the (m + 1)^2 pairs (j1, j2), -1 = undetected;
     * infeasible ones weigh 0.  First the normalising constant c. */
    for (j1 = -1; j1 < m; ++j1) {
        for (j2 = -1; j2 < m; ++j2) {
            c += mtt_split_event_weight(as, j1, j2);
        }
    }
    if (!(c > MTT_R(0.0)) || !mtt_isfinite(c)) {
        return -1;
    }
    as->lik = c;
    for (t = 0; t < 2; ++t) {
        as->beta_miss[t] = MTT_R(0.0);
        for (j1 = 0; j1 < m; ++j1) {
            as->beta[t][j1] = MTT_R(0.0);
        }
    }
    for (j1 = -1; j1 < m; ++j1) {
        for (j2 = -1; j2 < m; ++j2) {
            const mtt_real p = mtt_split_event_weight(as, j1, j2) / c;
            if (j1 >= 0) {
                as->beta[0][j1] += p;
            } else {
                as->beta_miss[0] += p;
            }
            if (j2 >= 0) {
                as->beta[1][j2] += p;
            } else {
                as->beta_miss[1] += p;
            }
        }
    }
    as->beta0 = mtt_split_event_weight(as, -1, -1) / c;
    return 0;
}

#if MTT_WITH_MEAS_COV
/* Model 6's update with the detections' own R: the mixture over the
 * events theta != theta_0 of the stacked Kalman updates with R^s(theta) =
 * blockdiag(R_j1, R_j2) (an undetected target's block R, its innovation 0,
 * as in the form with one R), each followed by the EKF steps of its
 * detections' range rates on their targets' blocks, and theta_0's
 * prediction (beta0). */
static int mix_events(mtt_split_work *wk, const mtt_split_assoc *as, const mtt_split_state xps, mtt_split_cov Pps,
                      const mtt_real R[3], const mtt_real *const Rj[], const mtt_split_rdot *rd, mtt_real z[][2],
                      mtt_split_state xs, mtt_split_cov Ps)
{
    const int16_t m = (int16_t)as->m;
    const int n = (int)as->n;
    const int sel[QMAX] = {0, 1, n, n + 1};
    mtt_real Rq[QMAX][QMAX] = {{MTT_R(0.0)}};
    int16_t j1, j2;
    int pass;
    mix_clear(wk, 2 * n, NULL);
    for (pass = 0; pass < 2; ++pass) {
        for (j1 = -1; j1 < m; ++j1) {
            for (j2 = -1; j2 < m; ++j2) {
                const mtt_real p = mtt_split_event_weight(as, j1, j2) / as->lik;
                const int16_t jt[2] = {j1, j2};
                mtt_real nu[QMAX];
                if (!(p > MTT_R(0.0)) || (j1 < 0 && j2 < 0)) {
                    continue;
                }
                rq_block((j1 >= 0) ? Rj[j1] : R, Rq, 0);
                rq_block((j2 >= 0) ? Rj[j2] : R, Rq, 2);
                nu[0] = (j1 >= 0) ? z[j1][0] - xps[0] : MTT_R(0.0);
                nu[1] = (j1 >= 0) ? z[j1][1] - xps[1] : MTT_R(0.0);
                nu[2] = (j2 >= 0) ? z[j2][0] - xps[n] : MTT_R(0.0);
                nu[3] = (j2 >= 0) ? z[j2][1] - xps[n + 1] : MTT_R(0.0);
                if (mix_term(wk, 2 * n, QMAX, sel, xps, Pps, Rq, nu, rd, jt, p, pass, NULL) != 0) {
                    return -1;
                }
            }
        }
    }
    mix_finish(wk, 2 * n, xps, Pps, as->beta0, xs, Ps);
    return 0;
}
#endif

int mtt_split_update(mtt_split_work *wk, const mtt_split_assoc *as, const mtt_split_state xps,
                     mtt_split_cov Pps, const mtt_real R[3], const mtt_real *const Rj[],
                     const mtt_split_rdot *rd, mtt_real z[][2], mtt_split_state xs, mtt_split_cov Ps)
{
    const int16_t m = (int16_t)as->m;
    const int n = (int)as->n;
    const int sel[QMAX] = {0, 1, n, n + 1};
    mtt_real Rq[QMAX][QMAX] = {{MTT_R(0.0)}}, sp[QMAX][QMAX] = {{MTT_R(0.0)}};
    mtt_real nub[QMAX] = {MTT_R(0.0)}, zh[QMAX];
    int16_t j1, j2;
    int a, b;
    if (!(as->lik > MTT_R(0.0))) {
        return -1;
    }
#if MTT_WITH_MEAS_COV
    if (Rj != NULL) {
        return mix_events(wk, as, xps, Pps, R, Rj, rd, z, xs, Ps);
    }
#else
    (void)Rj;
    (void)rd;
#endif
    for (a = 0; a < QMAX; ++a) {
        zh[a] = xps[sel[a]];
    }
    /* nu^s = sum_theta P(theta) nu^s(theta), an undetected target's part 0
     * (ALGORITHMS.md §14.3 CHOICE): from the marginals. */
    for (j1 = 0; j1 < m; ++j1) {
        nub[0] += as->beta[0][j1] * (z[j1][0] - zh[0]);
        nub[1] += as->beta[0][j1] * (z[j1][1] - zh[1]);
        nub[2] += as->beta[1][j1] * (z[j1][0] - zh[2]);
        nub[3] += as->beta[1][j1] * (z[j1][1] - zh[3]);
    }
    /* The corrected bracket of [S3] eq. 25: sum_theta P(theta) nu(theta)
     * nu(theta)' - nu^s nu^s', as sum_theta P(theta) (nu(theta) - nu^s)
     * (nu(theta) - nu^s)' over every event (theta_0 included): equal, and
     * positive semi-definite term by term. */
    for (j1 = -1; j1 < m; ++j1) {
        for (j2 = -1; j2 < m; ++j2) {
            const mtt_real p = mtt_split_event_weight(as, j1, j2) / as->lik;
            mtt_real d[QMAX];
            if (!(p > MTT_R(0.0))) {
                continue;
            }
            d[0] = ((j1 >= 0) ? z[j1][0] - zh[0] : MTT_R(0.0)) - nub[0];
            d[1] = ((j1 >= 0) ? z[j1][1] - zh[1] : MTT_R(0.0)) - nub[1];
            d[2] = ((j2 >= 0) ? z[j2][0] - zh[2] : MTT_R(0.0)) - nub[2];
            d[3] = ((j2 >= 0) ? z[j2][1] - zh[3] : MTT_R(0.0)) - nub[3];
            for (a = 0; a < QMAX; ++a) {
                for (b = a; b < QMAX; ++b) {
                    sp[a][b] += p * d[a] * d[b];
                }
            }
        }
    }
    for (a = 0; a < QMAX; ++a) {
        for (b = 0; b < a; ++b) {
            sp[a][b] = sp[b][a];
        }
    }
    /* R^s = blockdiag(R, R), H^s = blockdiag(H, H) ([S3] eq. 22, 23). */
    rq_block(R, Rq, 0);
    rq_block(R, Rq, 2);
    return mixed_update(wk, 2 * n, QMAX, sel, xps, Pps, Rq, as->beta0, nub, sp, xs, Ps, NULL);
}

int mtt_split_normal(mtt_real vx, mtt_real vy, mtt_real *nx, mtt_real *ny)
{
    const mtt_real v = mtt_sqrt(vx * vx + vy * vy);
    *nx = MTT_R(0.0);
    *ny = MTT_R(1.0);
    if (!(v > MTT_R(0.0))) {
        return 0;
    }
    *nx = -vy / v;
    *ny = vx / v;
    return 1;
}

/* ---- model 5's velocity impulse ---- */

void mtt_split_impulse_q(mtt_real dt, mtt_real dv, int across, mtt_real vx, mtt_real vy, mtt_cov Q)
{
    const mtt_real q = dv * dv;
    mtt_real qb[2][2], D[2][2], nx, ny;
    int a, b;
    /* per axis: position q dt^2 / 2, cross q dt / 2, velocity q */
    qb[0][0] = MTT_R(0.5) * q * dt * dt;
    qb[0][1] = MTT_R(0.5) * q * dt;
    qb[1][0] = qb[0][1];
    qb[1][1] = q;
    /* the directions: every axis (D = I), or across the course (D = n n') */
    D[0][0] = MTT_R(1.0);
    D[0][1] = MTT_R(0.0);
    D[1][0] = MTT_R(0.0);
    D[1][1] = MTT_R(1.0);
    if (across && mtt_split_normal(vx, vy, &nx, &ny)) {
        D[0][0] = nx * nx;
        D[0][1] = nx * ny;
        D[1][0] = nx * ny;
        D[1][1] = ny * ny;
    }
    for (a = 0; a < MTT_MAX_STATE; ++a) {
        for (b = 0; b < MTT_MAX_STATE; ++b) {
            Q[a][b] = (a < 4 && b < 4) ? qb[a / 2][b / 2] * D[a % 2][b % 2] : MTT_R(0.0);
        }
    }
}

/* ---- model 5's child half for a split of known speed ---- */

int mtt_split_known(mtt_split_work *wk, uint8_t n, const mtt_real xp[], mtt_real Pp[][MTT_MAX_STATE],
                    const mtt_real R[3], const mtt_real *const Rj[], const mtt_split_rdot *rd, uint16_t m,
                    mtt_real z[][2], const uint8_t cluster[], const mtt_real beta_n[], mtt_real dv, mtt_real dt,
                    uint8_t n_off, mtt_real vg,
                    mtt_split_state xs, mtt_split_cov Ps, mtt_real *lik)
{
    mtt_real(*Pk)[NS] = wk->Pq; /* the child's prior */
    mtt_real *xk = wk->xh[1];
    const mtt_real vv = (MTT_SPLIT_KNOWN_SD * dv) * (MTT_SPLIT_KNOWN_SD * dv);
    mtt_real nx, ny, zx = MTT_R(0.0), zy = MTT_R(0.0), bs = MTT_R(0.0);
    mtt_real side, off, best = MTT_R(0.0), qb[2][2], D[2][2], Sa[3], Sai[3], Sb[3], Sbi[3], deta, detb;
    mtt_real nub[QMAX] = {MTT_R(0.0)}, sp[QMAX][QMAX] = {{MTT_R(0.0)}}, g[2] = {MTT_R(0.0), MTT_R(0.0)};
    mtt_real Rq[QMAX][QMAX] = {{MTT_R(0.0)}};
    static const int sel[2] = {0, 1};
    uint16_t j, mi[2] = {0u, 0u};
    uint8_t h;
    int a, b;
    if (!n_ok(n) || m < 2u || m > MTT_MAX_SPLIT_MEAS || !(vg > MTT_R(0.0)) || !(dv > MTT_R(0.0)) ||
        !(dt > MTT_R(0.0)) || n_off < 1u || n_off > MTT_SPLIT_KNOWN_MAX_OFFSETS) {
        return -1;
    }
    (void)mtt_split_normal(xp[2], xp[3], &nx, &ny); /* per axis y at speed 0 */
    for (j = 0u; j < m; ++j) {
        if (cluster[j] > 1u) {
            return -1;
        }
        ++mi[cluster[j]];
        if (cluster[j] == 1u) {
            zx += beta_n[j] * z[j][0];
            zy += beta_n[j] * z[j][1];
            bs += beta_n[j];
        }
    }
    if (mi[0] == 0u || mi[1] == 0u || !(bs > MTT_R(0.0))) {
        return -1;
    }
    zx /= bs;
    zy /= bs;
    /* the side of the course the child's cluster is on; the offset
     * (a + h) dv dt, h < n_off, nearest to the cluster's mean */
    side = ((zx - xp[0]) * nx + (zy - xp[1]) * ny >= MTT_R(0.0)) ? MTT_R(1.0) : MTT_R(-1.0);
    off = MTT_SPLIT_KNOWN_OFFSET;
    for (h = 0u; h < n_off; ++h) {
        const mtt_real o = (MTT_SPLIT_KNOWN_OFFSET + (mtt_real)h) * dv * dt;
        const mtt_real ex = zx - xp[0] - side * o * nx, ey = zy - xp[1] - side * o * ny;
        const mtt_real d = ex * ex + ey * ey;
        if (h == 0u || d < best) {
            best = d;
            off = MTT_SPLIT_KNOWN_OFFSET + (mtt_real)h;
        }
    }
    /* the prior: moved by side dv n in velocity and side off dv dt n in
     * position; across the course the velocity variance vv, the position
     * variance (dv dt)^2 / 12 + vv dt^2 / 4, their covariance vv dt / 2 */
    qb[0][0] = dv * dv * dt * dt / MTT_R(12.0) + MTT_R(0.25) * vv * dt * dt;
    qb[0][1] = MTT_R(0.5) * vv * dt;
    qb[1][0] = qb[0][1];
    qb[1][1] = vv;
    D[0][0] = nx * nx;
    D[0][1] = nx * ny;
    D[1][0] = nx * ny;
    D[1][1] = ny * ny;
    for (a = 0; a < (int)n; ++a) {
        xk[a] = xp[a];
        for (b = 0; b < (int)n; ++b) {
            Pk[a][b] = Pp[a][b] + ((a < 4 && b < 4) ? qb[a / 2][b / 2] * D[a % 2][b % 2] : MTT_R(0.0));
        }
    }
    xk[0] += side * off * dv * dt * nx;
    xk[1] += side * off * dv * dt * ny;
    xk[2] += side * dv * nx;
    xk[3] += side * dv * ny;
    /* the parent's cluster on the cv prediction's S, the child's on the prior's */
    Sa[0] = Pp[0][0] + R[0];
    Sa[1] = MTT_R(0.5) * (Pp[0][1] + Pp[1][0]) + R[1];
    Sa[2] = Pp[1][1] + R[2];
    deta = Sa[0] * Sa[2] - Sa[1] * Sa[1];
    if (!(deta > MTT_R(0.0)) || !mtt_isfinite(deta) || innov2(Pk, 0, R, Sb, Sbi, &detb) != 0) {
        return -1;
    }
    Sai[0] = Sa[2] / deta;
    Sai[1] = -Sa[1] / deta;
    Sai[2] = Sa[0] / deta;
#if MTT_WITH_MEAS_COV
    if (Rj != NULL) {
        /* the detections' own R (§3.1) and range rates (§3.2): each its
         * own S_j on both priors, the child half the mixture of its
         * single-detection updates */
        for (j = 0u; j < m; ++j) {
            mtt_real d2, pj, S[3];
            wk->nu[j][0] = z[j][0] - xk[0];
            wk->nu[j][1] = z[j][1] - xk[1];
            wk->bn[j] = beta_n[j] / bs;
            if (cluster[j] == 0u) {
                if (mtt_meas_gauss(Pp[0], Pp[1], Rj[j], MTT_R(1.0), z[j][0] - xp[0], z[j][1] - xp[1], &d2,
                                   &pj, S) != 0) {
                    return -1;
                }
                g[0] += pj * rdot_f(rd, j, xp, &Pp[0][0], MTT_MAX_STATE, S, z[j][0] - xp[0], z[j][1] - xp[1]);
            } else {
                if (innov2(Pk, 0, Rj[j], Sb, Sbi, &detb) != 0) {
                    return -1;
                }
                g[1] += gauss2(quad2(Sbi, wk->nu[j][0], wk->nu[j][1]), detb) *
                        rdot_f(rd, j, xk, &Pk[0][0], NS, Sb, wk->nu[j][0], wk->nu[j][1]);
            }
        }
        if (mix_half(wk, n, xk, Pk, Rj, rd, m, cluster, 1u, wk->bn, wk->nu, wk->xh[0], wk->Ph[0], NULL) != 0) {
            return -1;
        }
    } else
#else
    (void)Rj;
    (void)rd;
#endif
    {
        for (j = 0u; j < m; ++j) {
            if (cluster[j] == 0u) {
                g[0] += gauss2(quad2(Sai, z[j][0] - xp[0], z[j][1] - xp[1]), deta);
            } else {
                const mtt_real w = beta_n[j] / bs;
                g[1] += gauss2(quad2(Sbi, z[j][0] - xk[0], z[j][1] - xk[1]), detb);
                nub[0] += w * (z[j][0] - xk[0]);
                nub[1] += w * (z[j][1] - xk[1]);
            }
        }
        for (j = 0u; j < m; ++j) {
            if (cluster[j] == 1u) {
                const mtt_real w = beta_n[j] / bs;
                const mtt_real dx = z[j][0] - xk[0] - nub[0], dy = z[j][1] - xk[1] - nub[1];
                sp[0][0] += w * dx * dx;
                sp[0][1] += w * dx * dy;
                sp[1][1] += w * dy * dy;
            }
        }
        sp[1][0] = sp[0][1];
        rq_block(R, Rq, 0);
        /* the child half's PDA update (beta0 = 0) from the prior */
        if (mixed_update(wk, n, 2, sel, xk, Pk, Rq, MTT_R(0.0), nub, sp, wk->xh[0], wk->Ph[0], NULL) != 0) {
            return -1;
        }
    }
    for (a = 0; a < (int)n; ++a) {
        xs[n + a] = wk->xh[0][a];
        for (b = 0; b < (int)n; ++b) {
            Ps[n + a][n + b] = wk->Ph[0][a][b];
            Ps[a][n + b] = MTT_R(0.0);
            Ps[n + a][b] = MTT_R(0.0);
        }
    }
    /* (V/m_1) sum N_1 (V/m_2) sum N_2, over the 2 sides and the n_off offsets */
    *lik = (vg / (mtt_real)mi[0]) * g[0] * (vg / (mtt_real)mi[1]) * g[1] /
           (MTT_R(2.0) * (mtt_real)n_off);
    return 0;
}

/* ---- decoupling and conversion ---- */

int mtt_split_decouple(uint8_t n, const mtt_split_state xps, mtt_split_cov Pps, const mtt_real R[3],
                       mtt_real c, mtt_real *d2)
{
    mtt_real S1[3], S2[3], Si[3], det, sum[3]; /* sum: s11, s12, s22 */
    if (!n_ok(n)) {
        return -1;
    }
    if (innov2(Pps, 0, R, S1, Si, &det) != 0 || innov2(Pps, (int)n, R, S2, Si, &det) != 0) {
        return -1;
    }
    /* (z1 - z2)' (S1 + S2)^-1 (z1 - z2), [S3] eq. 27 */
    sum[0] = S1[0] + S2[0];
    sum[1] = S1[1] + S2[1];
    sum[2] = S1[2] + S2[2];
    if (inv2(sum, Si, &det) != 0) {
        return -1;
    }
    *d2 = quad2(Si, xps[0] - xps[n], xps[1] - xps[n + 1]);
    return (*d2 >= c) ? 1 : 0;
}

int mtt_split_separate(mtt_split_work *wk, uint8_t n, const mtt_split_state xs, mtt_split_cov Ps,
                       mtt_real x1[], mtt_real P1[][MTT_MAX_STATE], mtt_real x2[],
                       mtt_real P2[][MTT_MAX_STATE])
{
    mtt_state d;
    int i, k, h;
    if (!n_ok(n)) {
        return -1;
    }
    /* The halves, symmetrised; the cross covariance P_12 is dropped: from
     * now on the two targets are filtered independently.  Both are checked
     * (in wk) before anything is written. */
    for (h = 0; h < 2; ++h) {
        const int o = h * (int)n;
        for (i = 0; i < n; ++i) {
            for (k = 0; k < n; ++k) {
                wk->S[i][k] = MTT_R(0.5) * (Ps[o + i][o + k] + Ps[o + k][o + i]);
            }
        }
        if (mtt_ldl((int)n, wk->S, wk->L, d) != 0) {
            return -1;
        }
    }
    for (i = 0; i < n; ++i) {
        x1[i] = xs[i];
        x2[i] = xs[n + i];
        for (k = 0; k < n; ++k) {
            P1[i][k] = MTT_R(0.5) * (Ps[i][k] + Ps[k][i]);
            P2[i][k] = MTT_R(0.5) * (Ps[n + i][n + k] + Ps[n + k][n + i]);
        }
    }
    return 0;
}

#else
/* ISO C wants a non-empty translation unit. */
typedef int mtt_split_left_out;
#endif /* MTT_WITH_SPLIT */
