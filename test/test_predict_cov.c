/* SPDX-License-Identifier: BSD-3-Clause */
/* test_predict_cov.c - the CV prediction x^ = F x, P^ = F P F' + Q
 * (ALGORITHMS.md §2, §3) on TV2 and on a long gap, in every build; in the
 * fixed-point one the covariance is a block of mantissas with one exponent
 * (docs/FIXED_POINT.md §2 and Status, finding 1), and the tolerance is
 * derived from its exponents (units u = 2^e):
 *
 * - the headroom rescaling of P rounds each entry to u_fit / 2 (e_fit is
 *   readable in P afterwards), and F P F' grows that by (1 + dt)^2;
 * - Q(dt) is formed at its own exponent e_Q (the quotient by 3 and the shift
 *   to e_Q: one u_Q), then F P and Q are aligned to u_c = max(u_fit, u_Q):
 *   F P's rounding (u_c / 2) is multiplied by 1 + dt in the column step;
 * - the products by dt (exact for whole frames), the symmetrisation and Q
 *   add u_c / 2 + u_c / 2 + u_c, the final renormalisation u(P^) / 2:
 *
 *   |error| <= (1 + dt)^2 u_fit / 2 + ((1 + dt) / 2 + 2) u_c + u(P^) / 2.
 *
 * The inputs are exact in their formats (P0 integers, dt and Sw in Q16). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_cov.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static const double tv2_x0[4] = {100.0, 50.0, 10.0, -5.0};
static const double tv2_P0[16] = {4, 1, 1, 0, 1, 4, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1};
static const double tv2_xpred[4] = {110, 45, 10, -5}; /* TV2 */
static const double tv2_Ppred[16] = {8.666666667, 1, 4.5, 0, 1, 8.666666667, 0, 4.5,
                                     4.5, 0, 6, 0, 0, 4.5, 0, 6}; /* TV2 */

#ifdef MTT_REAL_FIXED
#define MTT_FX_CONST_OR_R(v) ((mtt_real)llround(ldexp((v), MTT_FX_VAR_FRAC)))
#else
#define MTT_FX_CONST_OR_R(v) ((mtt_real)(v))
#endif

#ifdef MTT_REAL_FIXED
#define ASSERT_COV(want, got, tol) tv_assert_q((want), (got), (tol), "P^", __LINE__)
#else
#define ASSERT_COV(want, got, tol)                \
    do {                                          \
        (void)(tol);                              \
        TV_ASSERT_REAL_MSG((want), (got), "P^"); \
    } while (0)
#endif

#ifdef MTT_REAL_FIXED
/* 2^e of a block. */
static double unit(mtt_cov P)
{
    return ldexp(1.0, MTT_COV_E(P));
}
#endif

/* Predicts from TV2's x0 and the P given; returns the tolerance above. */
static double predict(double dt, mtt_state xp, mtt_cov P, mtt_cov Pp)
{
    mtt_state x;
    int i;
#ifdef MTT_REAL_FIXED
    mtt_cov Q;
    double uc;
    for (i = 0; i < 4; ++i) {
        x[i] = (mtt_real)llround(ldexp(tv2_x0[i], MTT_FX_POS_FRAC));
    }
    mtt_kalman_predict((mtt_real)llround(dt * 65536.0), MTT_FX_CONST(5.0, MTT_FX_VAR_FRAC), x, P, xp,
                       Pp);
    mtt_fx_cov_q((mtt_real)llround(dt * 65536.0), MTT_FX_CONST(5.0, MTT_FX_VAR_FRAC), Q);
    uc = (unit(Q) > unit(P)) ? unit(Q) : unit(P);
    return (1.0 + dt) * (1.0 + dt) * 0.5 * unit(P) + ((1.0 + dt) / 2.0 + 2.0) * uc + 0.5 * unit(Pp);
#else
    for (i = 0; i < 4; ++i) {
        x[i] = (mtt_real)tv2_x0[i];
    }
    mtt_kalman_predict((mtt_real)dt, MTT_R(5.0), x, P, xp, Pp);
    return 0.0;
#endif
}

static void test_tv2_predict(void)
{
    mtt_state xp;
    mtt_cov P, Pp;
    int i, j;
    double tol;
    tv_cov_set(P, tv2_P0, -24);
    tol = predict(1.0, xp, P, Pp);
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_Q(tv2_xpred[i], xp[i], MTT_FX_POS_FRAC, 0.0); /* dt = 1: exact */
        for (j = 0; j < 4; ++j) {
            TEST_ASSERT_TRUE(tv_cov_at(Pp, i, j) == tv_cov_at(Pp, j, i)); /* symmetric by construction */
            ASSERT_COV(tv2_Ppred[4 * i + j], tv_cov_at(Pp, i, j), tol);
        }
    }
#ifdef MTT_REAL_FIXED
    /* stored with the largest mantissa in [2^27, 2^28) */
    TEST_ASSERT_TRUE(Pp[0][0] >= (1 << 27) && Pp[0][0] < (1 << 28));
#endif
}

/* 40 frames without an update: P^ = F P F' + Q(40) from the double formula. */
static void test_long_gap(void)
{
    const double dt = 40.0, sw = 5.0;
    double F[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, want[16], FP[16];
    mtt_state xp;
    mtt_cov P, Pp;
    int i, j, k;
    double tol;
    F[2] = dt;
    F[7] = dt;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            FP[4 * i + j] = 0.0;
            for (k = 0; k < 4; ++k) {
                FP[4 * i + j] += F[4 * i + k] * tv2_P0[4 * k + j];
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            want[4 * i + j] = 0.0;
            for (k = 0; k < 4; ++k) {
                want[4 * i + j] += FP[4 * i + k] * F[4 * j + k];
            }
        }
    }
    want[0] += sw * dt * dt * dt / 3.0;
    want[5] += sw * dt * dt * dt / 3.0;
    want[2] += sw * dt * dt / 2.0;
    want[8] += sw * dt * dt / 2.0;
    want[7] += sw * dt * dt / 2.0;
    want[13] += sw * dt * dt / 2.0;
    want[10] += sw * dt;
    want[15] += sw * dt;
    tv_cov_set(P, tv2_P0, -24);
    tol = predict(dt, xp, P, Pp);
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            ASSERT_COV(want[4 * i + j], tv_cov_at(Pp, i, j), tol);
        }
    }
    TV_ASSERT_Q(100.0 + dt * 10.0, xp[0], MTT_FX_POS_FRAC, 0.0);
}

/* ---- the innovation covariance S = H P^ H' + R, S^-1 and K (ALGORITHMS.md
 * §3) on TV2.  Fixed point: R is quantised to Q16 (q = 2^-17); S's three
 * terms are re-expressed at e(S), half a unit each, two terms (three and a
 * halving for s12): dS <= dP^ + q + 2 u(S).  det = s11 s22 - s12^2:
 * (s11 + s22 + 2 |s12|) dS and its two products' roundings (u(det)); S^-1 = adj(S) / det: dSi <= (dS +
 * |Si| d det) / det + 0.76 u(Si) (S_k times one reciprocal of det S on 30 bits: the product's
 * 0.5008 unit and the reciprocal's 2^-30 relative, at most a quarter unit of S^-1 below 2^28); K = P^ S^-1 (rows): dK <= dP^ (|Si0| + |Si1|) +
 * (|P^_i0| + |P^_i1|) max dSi + 2 x 0.503 u(K) (two mtt_fx_mulq at s = 28,
 * fixed.h's bound 0.5 + 3 2^(18-s) ulp each). ---- */
static const double tv2_S[3] = {9.666666667, 1.3, 10.66666667};
static const double tv2_K[8] = {0.8986732983,  -0.01577580824, -0.005915928089, 0.8132210037,
                                0.4732742471,  -0.05768029886, -0.05768029886,  0.4289047864};

/* ---- d^2 = nu' S^-1 nu (ALGORITHMS.md §4) on TV2's nu = [1.5, -1]
 * (exact in the position format) with the S^-1 of the innovation step.
 * Fixed point: nu is normalised to 30 bits (exact here: a shift left by s),
 * w = S^-1 nu takes two mtt_fx_mulq at s = 30 per entry (0.5008 u_w each,
 * u_w = 2^(e(S^-1) - F - s + 30) in value), nu' w two more at
 * u_q = 2^(e(S^-1) - 2 (F + s) + 60), and the Q24 result half a unit:
 *
 *   |error| <= (|nx| + |ny|)^2 dSi + (|nx| + |ny|) 2 (0.5008) u_w
 *              + 2 (0.5008) u_q + 2^-25. ---- */
static const double tv2_d2 = 0.3704028309; /* TV2 d2 */

static void check_d2(const mtt_real Si[MTT_SYM_SLOTS], double dSi)
{
    const double nx = 1.5, ny = -1.0, l1 = fabs(nx) + fabs(ny);
    const mtt_pos px = MTT_POS(1.5), py = MTT_POS(-1.0);
    double tol = l1 * l1 * dSi;
#ifdef MTT_REAL_FIXED
    const int s = 30 - (32 - mtt_fx_clz((uint32_t)px | (uint32_t)-py));
    const double uw = ldexp(1.0, MTT_SYM_E(Si) - MTT_FX_POS_FRAC - s + 30);
    const double uq = ldexp(1.0, MTT_SYM_E(Si) - 2 * (MTT_FX_POS_FRAC + s) + 60);
    tol += l1 * 2.0 * 0.5008 * uw + 2.0 * 0.5008 * uq + ldexp(1.0, -25);
    TV_ASSERT_Q(tv2_d2, mtt_mahal2(Si, px, py), MTT_FX_D2_FRAC, tol);
    /* far outside every gate: saturates to the largest Q24 value, no wrap */
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_mahal2(Si, MTT_POS(1000.0), MTT_POS(-1000.0)));
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, mtt_mahal2(Si, MTT_FX_POS_LIMIT, -MTT_FX_POS_LIMIT));
    TEST_ASSERT_EQUAL_INT32(0, mtt_mahal2(Si, 0, 0));
#else
    (void)tol;
    TV_ASSERT_REAL(tv2_d2, mtt_mahal2(Si, px, py));
#endif
}

static void test_tv2_innovation(void)
{
    static const double r[3] = {1.0, 0.3, 2.0}; /* TV2 R */
    mtt_state xp;
    mtt_cov P, Pp;
    mtt_real R[3], S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det, K[MTT_MAX_STATE][2];
    double dP, dS, ddet, dSi, si[3], sv[3], kv, det_d, scale_s = 1.0, scale_si = 1.0, scale_k = 1.0;
    int i, k;
    tv_cov_set(P, tv2_P0, -24);
    dP = predict(1.0, xp, P, Pp);
    for (k = 0; k < 3; ++k) {
        R[k] = MTT_FX_CONST_OR_R(r[k]);
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, R, S, Si, &det, K));
#ifdef MTT_REAL_FIXED
    scale_s = ldexp(1.0, MTT_SYM_E(S));
    scale_si = ldexp(1.0, MTT_SYM_E(Si));
    scale_k = ldexp(1.0, MTT_COV_E(Pp) + MTT_SYM_E(Si) + 28);
#endif
    det_d = tv2_S[0] * tv2_S[2] - tv2_S[1] * tv2_S[1];
    si[0] = tv2_S[2] / det_d;
    si[1] = -tv2_S[1] / det_d;
    si[2] = tv2_S[0] / det_d;
    dS = dP + 1.0 / 131072.0 + 2.0 * scale_s;
    ddet = (tv2_S[0] + tv2_S[2] + 2.0 * fabs(tv2_S[1])) * dS + 2.0 * scale_s * scale_s * 268435456.0;
    dSi = (dS + fmax(fabs(si[0]), fabs(si[2])) * ddet) / det_d + 0.76 * scale_si;
    for (k = 0; k < 3; ++k) {
        sv[k] = (double)S[k] * scale_s;
        ASSERT_COV(tv2_S[k], sv[k], dS);                        /* TV2 S */
        ASSERT_COV(si[k], (double)Si[k] * scale_si, dSi);       /* S^-1 */
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 2; ++k) {
            const double tol = dP * (fabs(si[k]) + fabs(si[k + 1])) +
                               (fabs(tv2_Ppred[4 * i]) + fabs(tv2_Ppred[4 * i + 1])) * dSi +
                               2.0 * 0.503 * scale_k;
            kv = (double)K[i][k] * scale_k;
            ASSERT_COV(tv2_K[2 * i + k], kv, tol); /* TV2 K */
        }
    }
    check_d2(Si, dSi);
    (void)xp;
}

/* The headroom bound is reached: x and v fully correlated (a rank-one P,
 * every entry 1990, mantissas just below 2^28), so F P F' puts 4 max |P_ij|
 * plus Q on the diagonal, up to 2^30 + Q: the most that finding 1's bound
 * allows. */
static void test_headroom_correlated(void)
{
    const double c = 1990.0, q11 = 5.0 / 3.0, q13 = 2.5, q33 = 5.0;
    double v[16], want[16];
    mtt_state xp;
    mtt_cov P, Pp;
    double tol;
    int i, j;
    static const double f[16] = {4, 4, 2, 2, 4, 4, 2, 2, 2, 2, 1, 1, 2, 2, 1, 1}; /* F 1 F' */
    for (i = 0; i < 16; ++i) {
        v[i] = c;
        want[i] = c * f[i];
    }
    want[0] += q11;
    want[5] += q11;
    want[2] += q13;
    want[8] += q13;
    want[7] += q13;
    want[13] += q13;
    want[10] += q33;
    want[15] += q33;
    tv_cov_set(P, v, -17);
    tol = predict(1.0, xp, P, Pp);
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            ASSERT_COV(want[4 * i + j], tv_cov_at(Pp, i, j), tol);
        }
    }
}

/* A state pushed past the format saturates and reads as not finite, so
 * the track is invalid (ALGORITHMS.md §3), never wrapped. */
static void test_state_saturates(void)
{
#ifdef MTT_REAL_FIXED
    mtt_state x = {MTT_POS(30000.0), MTT_POS(0.0), MTT_POS(5000.0), MTT_POS(0.0)}, xp;
    mtt_cov P, Pp;
    tv_cov_set(P, tv2_P0, -24);
    TEST_ASSERT_TRUE(mtt_state_finite(x));
    mtt_kalman_predict(MTT_FX_CONST(1.0, MTT_FX_T_FRAC), MTT_FX_CONST(5.0, MTT_FX_VAR_FRAC), x, P, xp, Pp);
    TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, xp[0]);
    TEST_ASSERT_FALSE(mtt_state_finite(xp));
#else
    mtt_state x = {MTT_REAL_MAX, MTT_R(0.0), MTT_REAL_MAX, MTT_R(0.0)}, xp;
    mtt_cov P, Pp;
    tv_cov_set(P, tv2_P0, 0);
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), x, P, xp, Pp);
    TEST_ASSERT_FALSE(mtt_state_finite(xp)); /* Inf */
#endif
}

/* The prediction stage (predict.c, pipeline stage 2) on two tracks: TV2's,
 * and one whose predicted state leaves the format (fixed point) or
 * overflows (float): the first is valid with TV2's x^ and S and TV7's
 * predicted existence, the second is marked invalid (ALGORITHMS.md §3). */
static mtt_tracker trk;

static void test_predict_stage(void)
{
    static const double r[3] = {1.0, 0.3, 2.0};
    int i, k;
    memset(&trk, 0, sizeof trk);
    TV_PAR(&trk).process_psd = MTT_FX_CONST_OR_R(5.0);
    TV_PAR(&trk).markov_p11 = MTT_P(0.98);
    TV_PAR(&trk).markov_p21 = MTT_P(0.0);
    for (k = 0; k < 3; ++k) {
        TV_R(&trk)[k] = MTT_FX_CONST_OR_R(r[k]);
    }
    TV_N_TRACKS(&trk) = 2;
    for (i = 0; i < 2; ++i) {
        tv_cov_set(TV_P(&trk, i), tv2_P0, -24);
        TV_EXISTENCE(&trk, i) = MTT_P(0.9);
        for (k = 0; k < 4; ++k) {
#ifdef MTT_REAL_FIXED
            TV_X(&trk, i)[k] = (mtt_real)llround(ldexp(tv2_x0[k], MTT_FX_POS_FRAC));
#else
            TV_X(&trk, i)[k] = (mtt_real)tv2_x0[k];
#endif
        }
    }
#ifdef MTT_REAL_FIXED
    TV_X(&trk, 1)[0] = MTT_POS(30000.0);
    TV_X(&trk, 1)[2] = MTT_POS(5000.0);
    mtt_predict_frame(&trk, MTT_FX_CONST(1.0, MTT_FX_T_FRAC));
#else
    TV_X(&trk, 1)[0] = MTT_REAL_MAX;
    TV_X(&trk, 1)[2] = MTT_REAL_MAX;
    mtt_predict_frame(&trk, MTT_R(1.0));
#endif
    TEST_ASSERT_EQUAL_UINT8(1, TV_VALID(&trk, 0));
    TEST_ASSERT_EQUAL_UINT8(0, TV_VALID(&trk, 1));
    TV_ASSERT_PROB(0.882, TV_EX_PRED(&trk, 0), 2.51 / 1073741824.0); /* TV7 (test_existence.c) */
    for (k = 0; k < 4; ++k) {
        TV_ASSERT_Q(tv2_xpred[k], TV_XP(&trk, 0)[k], MTT_FX_POS_FRAC, 0.0);
    }
#ifdef MTT_REAL_FIXED
    TV_ASSERT_Q(tv2_S[0], TV_S(&trk, 0)[0], -MTT_SYM_E(TV_S(&trk, 0)), 1e-5); /* dS above */
#else
    TV_ASSERT_REAL(tv2_S[0], TV_S(&trk, 0)[0]);
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv2_predict);
    RUN_TEST(test_long_gap);
    RUN_TEST(test_tv2_innovation);
    RUN_TEST(test_headroom_correlated);
    RUN_TEST(test_state_saturates);
    RUN_TEST(test_predict_stage);
    return UNITY_END();
}
