/* SPDX-License-Identifier: BSD-3-Clause */
/* imm.c - interacting multiple model (IMM) arithmetic of one track.
 *
 * ALGORITHMS.md §14.1: mixing (c̄_j, μ_{i|j}, x_0j, P_0j) and the combined
 * estimate; ALGORITHMS.md §14.2: the model-mixed detection probability and
 * measurement likelihood, and the apportionment of a track-level
 * association result (β_0, β_i) into mode probabilities and per-model association probabilities, which is how every
 * association mode (IPDA, LM-IPDA, IHPDA, LM-IHPDA with MMR, JIPDA) drives
 * the per-model updates.  Plain functions over arrays: r <= MTT_MAX_MODELS
 * models, model j has n[j] state components (4 <= n[j] <= MTT_MAX_STATE),
 * the first four are [x y vx vy] in every model.
 *
 * Unequal state sizes (ALGORITHMS.md §14.1 CHOICE): models mix in the
 * common 4-D subspace; the extra components e of model j (n[j] > 4) keep
 * their own mode-conditioned values.  Precisely, for the mixed start of
 * model j:
 *   common c:  x_0j,c = Σ_i μ_{i|j} x_i,c
 *              P_0j,cc = Σ_i μ_{i|j} [P_i,cc + d_i d_i'],  d_i = x_i,c - x_0j,c
 *   extras e:  x_0j,e = x_j,e,   P_0j,ee = P_j,ee       (not mixed)
 *   cross:     P_0j,ce = μ_{j|j} P_j,ce
 * This is the exact mean and covariance of the mixture in which every other
 * model i's estimate is extended by model j's own extra components,
 * uncorrelated with model i's common part (model i carries no information
 * on them).  A mixture of positive semi-definite terms, so P_0j stays
 * positive semi-definite; keeping P_j,ce unscaled would not.  The extras
 * of a model never leave it: two models with extras do not mix them.
 * The combined estimate is 4-D: only the common components, Σ_j μ_j x_j,c
 * with the spread term; the extras reach it only through their model's own
 * update of the common components.
 *
 * Weighted sums are formed as differences to one reference model
 * (x_ref + Σ_i w_i (x_i - x_ref), the same value in exact arithmetic since
 * Σ_i w_i = 1): no cancellation on large coordinates in float, and r equal
 * models reproduce their common estimate bit for bit. */
#include "mtt_internal.h"

#if MTT_WITH_IMM

#ifdef MTT_REAL_FIXED
/* 1 / v for v > 0 in Q30 as m 2^-t (m in (2^29, 2^30]): x / v of a Q30 x
 * is then mtt_fx_mul(x, m, t), one multiply per quotient instead of a
 * division (the apportionment divides rows by one value each). */
static int32_t inv_q30(int32_t v, int *t)
{
    *t = 31 - mtt_fx_clz((uint32_t)v); /* bit length - 1, in [0, 30] */
    return mtt_fx_div(MTT_P(1.0), v, *t);
}
/* x / D for a row of x by one D > 0: QUOT_SET once, QUOT per x (fixed
 * point: one reciprocal and a multiply each; float and double: the
 * division, and RECIP_* the float text's multiply by 1 / D). */
typedef struct quot {
    int32_t m;
    int t;
} quot;
#define QUOT_INIT {0, 0}
#define QUOT_SET(q, D) ((q).m = inv_q30((D), &(q).t))
#define QUOT(x, q) mtt_fx_mul((x), (q).m, (q).t)
#define RECIP_SET(q, D) QUOT_SET(q, D)
#define RECIP_MUL(x, q) QUOT(x, q)
#else
typedef mtt_real quot;
#define QUOT_INIT MTT_R(1.0)
#define QUOT_SET(q, D) ((q) = (D))
#define QUOT(x, q) ((x) / (q))
#define RECIP_SET(q, D) ((q) = MTT_R(1.0) / (D))
#define RECIP_MUL(x, q) ((x) * (q))
#endif

int mtt_imm_mix_weights(uint8_t r, mtt_real Pi[][MTT_MAX_MODELS], const mtt_real mu[],
                        mtt_real cbar[], mtt_real mix[][MTT_MAX_MODELS])
{
    quot q = QUOT_INIT;
    uint8_t i, j;
    if (r < 1u || r > MTT_MAX_MODELS) {
        return -1;
    }
    for (j = 0; j < r; ++j) {
        mtt_prob c = MTT_ZERO;
        for (i = 0; i < r; ++i) {
            c = MTT_ADDS(c, MTT_MUL_PP(Pi[i][j], mu[i]));
        }
        cbar[j] = c;
        if (c > MTT_ZERO) {
            QUOT_SET(q, c);
        }
        for (i = 0; i < r; ++i) {
            /* c̄_j = 0: no model can be in mode j; let model j start from
             * its own estimate (its weight μ_j will be 0 anyway). */
            mix[i][j] = (c > MTT_ZERO) ? QUOT(MTT_MUL_PP(Pi[i][j], mu[i]), q) : ((i == j) ? MTT_P(1.0) : MTT_ZERO);
        }
    }
    return 0;
}

#ifdef MTT_REAL_FIXED
/* The mixture below in block floating point (docs/FIXED_POINT.md §2), the
 * float text's formula: every P_i at the largest block exponent E (below
 * 2^28 there), Po = P_ref + Σ_{i≠ref} w_i (P_i - P_ref) (a convex
 * combination, below 2^28) plus the spread Σ_{i≠ref} w_i d_i D_i'
 * (= Σ_i w_i d_i d_i', PSD).  The D_i go on 27 bits together (exponent
 * EB), and s and d_i = D_i - s are formed there, not in the position
 * format: this form of the spread is first-order in the error of s (a
 * mean rounded to the position's LSB would cost 0.1 m² at 300 m apart).
 * Each product (shift 28) is below 2^27, the weighted sum too; the spread
 * meets the rest at E, the larger of e_max and the exponent that puts the
 * spread's largest entry on 28 bits (the result below 2^29: the
 * prediction renormalises a mixed start, mtt_imm_combine the estimate). */
#define MULQ(a, b) mtt_fx_mulq30((a), (b))
static void mixture4(uint8_t r, uint8_t ref, const mtt_prob w[], mtt_real x[][MTT_MAX_STATE], mtt_cov P[],
                     mtt_real xo[], mtt_real Po[][MTT_MAX_STATE])
{
    int32_t D[MTT_MAX_MODELS][MTT_IMM_COMMON], wd[MTT_MAX_MODELS][MTT_IMM_COMMON], s[MTT_IMM_COMMON] = {0};
    int32_t sp[MTT_IMM_COMMON * (MTT_IMM_COMMON + 1) / 2];
    const mtt_real *xr = x[ref];
    uint32_t u = 0u;
    int E = MTT_COV_E(P[ref]), EB = 0, sh = 0, c;
    uint8_t i, a, b;
    for (i = 0; i < r; ++i) {
        E = (MTT_COV_E(P[i]) > E) ? MTT_COV_E(P[i]) : E;
        for (a = 0; a < MTT_IMM_COMMON; ++a) {
            D[i][a] = MTT_SUBS(x[i][a], xr[a]); /* 0 for ref */
            u |= (uint32_t)MTT_ABS(D[i][a]);
        }
    }
    if (u != 0u) {
        /* |s| <= max |D_i| < 2^27, |d_i| <= 2 max |D_i| < 2^28 */
        sh = 27 - (32 - mtt_fx_clz(u));
        EB = 28 - 2 * (MTT_FX_POS_FRAC + sh); /* the products' (shift 28) */
    }
    for (a = 0; a < MTT_IMM_COMMON; ++a) {
        for (i = 0; i < r; ++i) {
            if (i != ref) { /* D_ref = 0 */
                D[i][a] = mtt_fx_shift(D[i][a], sh);
                s[a] += MULQ(w[i], D[i][a]);
            }
        }
        xo[a] = MTT_ADDS(xr[a], mtt_fx_shift(s[a], -sh));
        for (i = 0; i < r; ++i) {
            wd[i][a] = (i != ref) ? MULQ(w[i], D[i][a] - s[a]) : 0; /* w_i d_i */
        }
    }
    /* the spread's upper triangle at EB, then E from its measured size */
    for (a = 0, c = 0; a < MTT_IMM_COMMON; ++a) {
        for (b = a; b < MTT_IMM_COMMON; ++b, ++c) {
            sp[c] = 0;
            for (i = 0; i < r; ++i) {
                sp[c] += (i != ref) ? mtt_fx_mulq28(wd[i][a], D[i][b]) : 0;
            }
        }
    }
    if (u != 0u) {
        const int es = mtt_fx_top_exp(EB, mtt_fx_or_abs(sp, c), 28);
        E = (es > E) ? es : E;
    }
    for (a = 0, c = 0; a < MTT_IMM_COMMON; ++a) {
        for (b = a; b < MTT_IMM_COMMON; ++b, ++c) {
            const int32_t pr = mtt_fx_shift(P[ref][a][b], MTT_COV_E(P[ref]) - E);
            int32_t v = pr;
            for (i = 0; i < r; ++i) {
                if (i != ref) {
                    v += MULQ(w[i], mtt_fx_shift(P[i][a][b], MTT_COV_E(P[i]) - E) - pr);
                }
            }
            v += (u != 0u) ? mtt_fx_shift(sp[c], EB - E) : 0;
            Po[a][b] = v;
            Po[b][a] = v;
        }
    }
    MTT_COV_E(Po) = E; /* below 2^29: the prediction renormalises a mixed start, combine the estimate */
}
#undef MULQ
#else
/* Moment-matched mixture of the common parts of r models with weights w
 * (Σ w = 1), as differences to model ref (see the header):
 *   D_i = x_i - x_ref,  s = Σ_{i≠ref} w_i D_i,  xo = x_ref + s,
 *   Po = P_ref + Σ_{i≠ref} w_i [d_i D_i' + (P_i - P_ref)],  d_i = D_i - s.
 * The spread term is Σ_i w_i d_i d_i' (d_i = x_i - xo) in exact arithmetic:
 * Σ_i w_i d_i s' = 0 and D_ref = 0, so only the other models contribute,
 * one product each.  Only the upper triangle is formed, then mirrored:
 * symmetric by construction.  xo, Po may be rows of a larger state. */
static void mixture4(uint8_t r, uint8_t ref, const mtt_real w[], mtt_real x[][MTT_MAX_STATE], mtt_cov P[],
                     mtt_real xo[], mtt_real Po[][MTT_MAX_STATE])
{
    mtt_real D[MTT_MAX_MODELS][MTT_IMM_COMMON], s[MTT_IMM_COMMON] = {MTT_R(0.0)};
    mtt_real(*Pr)[MTT_MAX_STATE] = P[ref];
    const mtt_real *xr = x[ref];
    uint8_t i, a, b;
    for (i = 0; i < r; ++i) {
        for (a = 0; a < MTT_IMM_COMMON; ++a) {
            D[i][a] = x[i][a] - xr[a]; /* 0 for ref */
            s[a] += w[i] * D[i][a];
        }
    }
    for (a = 0; a < MTT_IMM_COMMON; ++a) {
        xo[a] = xr[a] + s[a];
    }
    /* Whole rows (fixed length 4: straight or vector code), then the upper
     * triangle mirrored onto the lower. */
    for (a = 0; a < MTT_IMM_COMMON; ++a) {
        mtt_real row[MTT_IMM_COMMON];
        for (b = 0; b < MTT_IMM_COMMON; ++b) {
            row[b] = Pr[a][b];
        }
        for (i = 0; i < r; ++i) {
            if (i != ref) {
                mtt_real(*Pi)[MTT_MAX_STATE] = P[i];
                const mtt_real wd = w[i] * (D[i][a] - s[a]);
                for (b = 0; b < MTT_IMM_COMMON; ++b) {
                    row[b] += wd * D[i][b] + w[i] * (Pi[a][b] - Pr[a][b]);
                }
            }
        }
        for (b = 0; b < MTT_IMM_COMMON; ++b) {
            Po[a][b] = row[b];
        }
    }
    for (a = 1; a < MTT_IMM_COMMON; ++a) {
        for (b = 0; b < a; ++b) {
            Po[a][b] = Po[b][a];
        }
    }
}
#endif

int mtt_imm_mix(uint8_t r, const uint8_t n[], mtt_real mix[][MTT_MAX_MODELS], mtt_real x[][MTT_MAX_STATE],
                mtt_cov P[], mtt_real x0[][MTT_MAX_STATE], mtt_cov P0[])
{
    uint8_t i, j;
#if MTT_WITH_IMM_CACT
    uint8_t a, b;
#endif
    if (r < 1u || r > MTT_MAX_MODELS) {
        return -1;
    }
    for (j = 0; j < r; ++j) {
        if (n[j] < MTT_IMM_COMMON || n[j] > MTT_MAX_STATE) {
            return -1;
        }
    }
    for (j = 0; j < r; ++j) {
        mtt_real w[MTT_MAX_MODELS];
        for (i = 0; i < r; ++i) {
            w[i] = mix[i][j];
        }
        /* Common part: the mixture with reference model j. */
        mixture4(r, j, w, x, P, x0[j], P0[j]);
#if MTT_WITH_IMM_CACT
        /* Extras of model j: own mean and block, cross terms scaled by
         * μ_{j|j} (P[j] is symmetric: every stage writes it mirrored). */
        for (a = MTT_IMM_COMMON; a < n[j]; ++a) {
            const mtt_real *pa = P[j][a];
            mtt_real *qa = P0[j][a];
            x0[j][a] = x[j][a];
            for (b = 0; b < MTT_IMM_COMMON; ++b) {
                qa[b] = mix[j][j] * pa[b];
                P0[j][b][a] = qa[b];
            }
            for (b = a; b < n[j]; ++b) {
                qa[b] = pa[b];
                P0[j][b][a] = pa[b];
            }
        }
#endif
    }
    return 0;
}

int mtt_imm_combine(uint8_t r, const mtt_real mu[], mtt_real x[][MTT_MAX_STATE], mtt_cov P[], mtt_real xc[],
                    mtt_real Pc[][MTT_MAX_STATE])
{
    if (r < 1u || r > MTT_MAX_MODELS) {
        return -1;
    }
    mixture4(r, 0, mu, x, P, xc, Pc);
    MTT_COV_NORM(Pc);
    return 0;
}

mtt_real mtt_imm_meas_mix(uint8_t r, const mtt_real cbar[], const mtt_real pd[], const mtt_real p[],
                          mtt_real *pd_mix)
{
    mtt_prob w = MTT_ZERO;
    mtt_ratio s = MTT_ZERO;
    uint8_t j;
    if (r > MTT_MAX_MODELS) {
        r = 0; /* out of range: PD* = 0, p* = 0 */
    }
    for (j = 0; j < r; ++j) {
        w = MTT_ADDS(w, MTT_MUL_PP(cbar[j], pd[j]));
        s = MTT_ADDS(s, MTT_MUL_RP(MTT_MUL_PP(cbar[j], pd[j]), p[j]));
    }
    *pd_mix = w;
    return (w > MTT_ZERO) ? MTT_DIV_RP(s, w) : MTT_ZERO;
}

int mtt_imm_apportion(uint8_t r, const mtt_real cbar[], uint16_t m, mtt_real beta0,
                  const mtt_real beta[], const mtt_real e0[], mtt_real e[][MTT_MAX_MODELS],
                  mtt_real mu[], mtt_real beta0_j[], mtt_real beta_j[][MTT_MAX_GATED])
{
    mtt_prob E0 = MTT_ZERO, sum = MTT_ZERO;
    quot q = QUOT_INIT;
    uint16_t i;
    uint8_t j;
    if (r < 1u || r > MTT_MAX_MODELS || m > MTT_MAX_GATED) {
        return -1;
    }
    for (j = 0; j < r; ++j) {
        E0 = MTT_ADDS(E0, MTT_MUL_PP(cbar[j], e0[j]));
        mu[j] = MTT_ZERO;
    }
    /* Joint P(θ_0, M_j) = β_0 c̄_j e0_j / Σ_k c̄_k e0_k, kept in beta0_j
     * until μ_j is known; the same for P(θ_i, M_j) in beta_j.  (Fixed
     * point: e0 and e are Q30, each row's largest 1: imm_track.c.) */
    if (E0 > MTT_ZERO) {
        QUOT_SET(q, E0);
    }
    for (j = 0; j < r; ++j) {
        mtt_prob v = (E0 > MTT_ZERO) ? QUOT(MTT_MUL_PP(MTT_MUL_PP(beta0, cbar[j]), e0[j]), q) : MTT_ZERO;
        beta0_j[j] = v;
        mu[j] = MTT_ADDS(mu[j], v);
    }
    for (i = 0; i < m; ++i) {
        mtt_prob Ei = MTT_ZERO;
        for (j = 0; j < r; ++j) {
            Ei = MTT_ADDS(Ei, MTT_MUL_PP(cbar[j], e[i][j]));
        }
        if (Ei > MTT_ZERO) {
            QUOT_SET(q, Ei);
        }
        for (j = 0; j < r; ++j) {
            mtt_prob v = (Ei > MTT_ZERO) ? QUOT(MTT_MUL_PP(MTT_MUL_PP(beta[i], cbar[j]), e[i][j]), q) : MTT_ZERO;
            beta_j[j][i] = v;
            mu[j] = MTT_ADDS(mu[j], v);
        }
    }
    for (j = 0; j < r; ++j) {
        sum = MTT_ADDS(sum, mu[j]);
    }
    for (j = 0; j < r; ++j) {
        if (mu[j] > MTT_ZERO) {
            RECIP_SET(q, mu[j]);
            beta0_j[j] = RECIP_MUL(beta0_j[j], q);
            for (i = 0; i < m; ++i) {
                beta_j[j][i] = RECIP_MUL(beta_j[j][i], q);
            }
        } else {
            /* A model of no weight: any valid distribution; take the track's. */
            beta0_j[j] = beta0;
            for (i = 0; i < m; ++i) {
                beta_j[j][i] = beta[i];
            }
        }
    }
    /* Σ_j μ_j = β_0 + Σ_i β_i = 1 in exact arithmetic; renormalise the
     * round-off (and a β_0 that no model can explain, e0 = 0). */
    if (sum > MTT_ZERO) {
        QUOT_SET(q, sum);
    }
    for (j = 0; j < r; ++j) {
        mu[j] = (sum > MTT_ZERO) ? QUOT(mu[j], q) : cbar[j];
    }
    return 0;
}

#endif /* MTT_WITH_IMM */
