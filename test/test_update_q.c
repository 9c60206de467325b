/* SPDX-License-Identifier: BSD-3-Clause */
/* test_update_q.c - the PDA update (ALGORITHMS.md §3 Joseph form, §6, §7.4),
 * the L D L' positive-definiteness test and quadratic form (§3, §16) on
 * TV2 and TV6, in every build.  Float and double: the results against the
 * test vectors by the rule of ALGORITHMS.md §16.  Fixed point
 * (docs/FIXED_POINT.md §7): the results against the double formula
 * evaluated on the very inputs the fixed code sees (P^, K, S^-1 as
 * mantissas at their exponents, R in Q16, nu in the position format, the
 * betas in Q30), within the roundings counted below; that double result is
 * in turn held to the test vector by the float rule.
 *
 * Tolerance of the updated P (fixed point).  Every intermediate block of
 * kalman.c's fixed pda_n holds its largest entry on 28 to 30 bits, so each
 * rounding (a mtt_fx_mulq at 0.5008 unit, a shift at 0.5 unit) is at most
 * 2^-28 of that block's size.  pda_n forms beta0 P^ + (1 - beta0) P_c as
 * G P^ on rows 0, 1 (G = beta0 I + (1 - beta0) R S^-1) and as P^ -
 * (1 - beta0) K_v P^_pos,v on the velocity block, plus K sp K'.  The
 * longest chain is G P^: G (R's shift, R S^-1's two products, the factor
 * 1 - beta0, the alignment of it and of beta0) enters times |P^| (2
 * entries) - 2 x 5 roundings; the two products, the alignment to P's
 * exponent and the final renormalisation: 4.  14 roundings.  That form
 * equals the Joseph form of the reference only for the gain K = P^ H'
 * S^-1; K and S^-1 carry mtt_kalman_innov's roundings (at most 4 units of
 * their blocks: S's alignment, det S's two products, the quotient; K's two
 * products), which reach P to first order through two factors: 2 x 4 more.
 * 22 roundings in units of the largest of the three terms T = max(beta0
 * |P^|, (1 - beta0) |P_c|, |K M K'|); with the blocks' sizes at most 2
 * bits below their bounds (the alignments use the measured sizes):
 * 22 x 4 x 2^-28 T.  The spread sum beta (nu - nu_c)
 * (nu - nu_c)' is held at the scale of the innovations, whose largest
 * |nu| has 28 bits (unit u <= 2^-27 max|nu|): nu's shift and nu_c's m
 * roundings move each nu - nu_c by at most (m/2 + 1) u, the two products
 * per term and the (1 - sum beta) nu_c nu_c' term add their roundings, in
 * all at most (4 m + 12) u max|nu| <= (4 m + 12) 2^-27 max|nu|^2 on an
 * entry of M, which reaches P through K M K' (one measurement: beta (1 -
 * beta) q q' with q = K nu, fewer roundings than that bound counts):
 *   tol_P(i, k) = 88 2^-28 T
 *                 + (4 m + 12) 2^-27 max|nu|^2 (|K_i0| + |K_i1|) (|K_k0| + |K_k1|).
 * Tolerance of x: the state moves by K nu_c rounded to the position format
 * (half a unit), nu_c carries one rounding per measurement plus the shift
 * of nu (units of 2^-27 max|nu|), times |K_i0| + |K_i1|, and K nu_c's two
 * products and K's shift: 3 x 2^-27 (|K_i0 nu_cx| + |K_i1 nu_cy|).  (One
 * measurement: beta (K nu), the same count: nu's shift, K nu's two
 * products and K's shift, the product by beta.) */
#include <stdio.h>
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
static const double tv2_r[3] = {1.0, 0.3, 2.0}; /* TV2 R */
static const double tv2_z[2] = {111.5, 44.0};
static const double tv2_xpred[4] = {110, 45, 10, -5};
static const double tv2_Ppred[16] = {8.666666667, 1, 4.5, 0, 1, 8.666666667, 0, 4.5,
                                     4.5, 0, 6, 0, 0, 4.5, 0, 6};
static const double tv2_xupd[4] = {111.3637858, 44.1779051, 10.76759167, -5.515425235};
static const double tv2_Pupd[16] = {
    0.8939405559, 0.238050373,  0.4559701574, 0.07099113706, 0.238050373,  1.624667229,
    0.0266216764, 0.8405054832, 0.4559701574, 0.0266216764,  3.870265888,  0.2595613449,
    0.07099113706, 0.8405054832, 0.2595613449, 4.069928461};
/* TV5's measurements and TV6's IPDA betas, x_upd and P_upd */
static const double tv5_z[3][2] = {{110.8, 44.5}, {106.5, 47.4}, {115.0, 48.0}};
static const double tv6_beta[3] = {0.61878548, 0.233249123, 0.1379880464};
static const double tv6_beta0 = 0.009977350664;
static const double tv6_x[4] = {110.320767, 45.53809847, 10.1361263, -4.736309597};
static const double tv6_P[16] = {
    6.286621717, -0.09786656496, 3.31419463, -0.4332224045, -0.09786656496, 3.219038845,
    -0.2469598763, 1.699919386, 3.31419463, -0.2469598763, 5.390980795, -0.05795771982,
    -0.4332224045, 1.699919386, -0.05795771982, 4.552799418};

/* ---- values in and out of their formats ---- */
#ifdef MTT_REAL_FIXED
#define POS(v) ((mtt_real)llround(ldexp((v), MTT_FX_POS_FRAC)))
#define VAR(v) ((mtt_real)llround(ldexp((v), MTT_FX_VAR_FRAC)))
#define PROB(v) ((mtt_real)llround(ldexp((v), MTT_FX_PROB_FRAC)))
#define POS_D(x) ldexp((double)(x), -MTT_FX_POS_FRAC)
#define VAR_D(x) ldexp((double)(x), -MTT_FX_VAR_FRAC)
#define PROB_D(x) ldexp((double)(x), -MTT_FX_PROB_FRAC)
#define SI_D(Si, k) ldexp((double)(Si)[k], MTT_SYM_E(Si))
#define K_D(f, i, c) ldexp((double)(f)->K[i][c], MTT_COV_E((f)->Pp) + MTT_SYM_E((f)->Si) + 28)
#else
#define POS(v) ((mtt_real)(v))
#define VAR(v) ((mtt_real)(v))
#define PROB(v) ((mtt_real)(v))
#define POS_D(x) ((double)(x))
#define VAR_D(x) ((double)(x))
#define PROB_D(x) ((double)(x))
#define SI_D(Si, k) ((double)(Si)[k])
#define K_D(f, i, c) ((double)(f)->K[i][c])
#endif

/* TV2's prediction and innovation step (test_predict_cov.c checks them). */
struct fix {
    mtt_state xp;
    mtt_cov Pp;
    mtt_real R[3], S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det, K[MTT_MAX_STATE][2];
};

static void tv2_fix(struct fix *f)
{
    mtt_state x;
    mtt_cov P;
    int i;
    memset(f, 0, sizeof *f);
    tv_cov_set(P, tv2_P0, -24);
    for (i = 0; i < 4; ++i) {
        x[i] = POS(tv2_x0[i]);
    }
    for (i = 0; i < 3; ++i) {
        f->R[i] = VAR(tv2_r[i]);
    }
#ifdef MTT_REAL_FIXED
    mtt_kalman_predict(MTT_FX_CONST(1.0, MTT_FX_T_FRAC), VAR(5.0), x, P, f->xp, f->Pp);
#else
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), x, P, f->xp, f->Pp);
#endif
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(f->Pp, f->R, f->S, f->Si, &f->det, f->K));
}

/* The PDA update of ALGORITHMS.md §6 in double on the inputs as given
 * (the reference of the fixed build), and the size T of its largest term. */
static double pda_ref(const struct fix *f, int m, const double nu[][2], const double *beta,
                      double beta0, double x[4], double P[16], double cxy[2])
{
    double cx = 0.0, cy = 0.0, bs = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0, A[4][2], AP[4][4];
    double Pp[4][4], K[4][2], r[3], si[3], w = 1.0 - beta0, M[3], T = 0.0;
    int i, k, j;
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            Pp[i][k] = tv_cov_at((mtt_real(*)[MTT_MAX_STATE])f->Pp, i, k);
        }
        K[i][0] = K_D(f, i, 0);
        K[i][1] = K_D(f, i, 1);
    }
    for (k = 0; k < 3; ++k) {
        r[k] = VAR_D(f->R[k]);
        si[k] = SI_D(f->Si, k);
    }
    for (j = 0; j < m; ++j) {
        cx += beta[j] * nu[j][0];
        cy += beta[j] * nu[j][1];
        bs += beta[j];
    }
    for (j = 0; j < m; ++j) {
        const double dx = nu[j][0] - cx, dy = nu[j][1] - cy;
        sxx += beta[j] * dx * dx;
        sxy += beta[j] * dx * dy;
        syy += beta[j] * dy * dy;
    }
    bs = 1.0 - bs;
    if (bs > 0.0) {
        sxx += bs * cx * cx;
        sxy += bs * cx * cy;
        syy += bs * cy * cy;
    }
    for (i = 0; i < 4; ++i) {
        x[i] = POS_D(f->xp[i]) + K[i][0] * cx + K[i][1] * cy;
    }
    M[0] = w * r[0] + sxx;
    M[1] = w * r[1] + sxy;
    M[2] = w * r[2] + syy;
    A[0][0] = r[0] * si[0] + r[1] * si[1];
    A[0][1] = r[0] * si[1] + r[1] * si[2];
    A[1][0] = r[1] * si[0] + r[2] * si[1];
    A[1][1] = r[1] * si[1] + r[2] * si[2];
    for (i = 2; i < 4; ++i) {
        A[i][0] = -K[i][0];
        A[i][1] = -K[i][1];
    }
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            AP[i][k] = A[i][0] * Pp[0][k] + A[i][1] * Pp[1][k] + ((i >= 2) ? Pp[i][k] : 0.0);
        }
    }
    for (i = 0; i < 4; ++i) {
        const double a = K[i][0] * M[0] + K[i][1] * M[1], b = K[i][0] * M[1] + K[i][1] * M[2];
        for (k = 0; k < 4; ++k) {
            const double pc = AP[i][0] * A[k][0] + AP[i][1] * A[k][1] + ((k >= 2) ? AP[i][k] : 0.0);
            const double t1 = beta0 * Pp[i][k], t2 = w * pc, t3 = a * K[k][0] + b * K[k][1];
            P[4 * i + k] = t1 + t2 + t3;
            T = fmax(T, fmax(fabs(t1), fmax(fabs(t2), fabs(t3))));
        }
    }
    cxy[0] = cx;
    cxy[1] = cy;
    return T;
}

#ifdef MTT_REAL_FIXED
static double worst = 0.0; /* largest |error| / tolerance seen */
#endif

/* mtt_kalman_pda on f with m measurements z and betas, against x_want and
 * P_want (the test vector). */
static void check_result(struct fix *f, int m, const double z[][2], const double *beta_d,
                         mtt_real beta0, const double *x_want, const double *P_want, const mtt_real *x,
                         mtt_cov P)
{
    double nud[3][2], bd[3], xr[4], Pr[16], c[2], T, numax = 0.0;
    int i, k, j;
    for (j = 0; j < m; ++j) {
        for (k = 0; k < 2; ++k) {
            nud[j][k] = POS_D(POS(z[j][k]) - f->xp[k]);
            numax = fmax(numax, fabs(nud[j][k]));
        }
        bd[j] = PROB_D(PROB(beta_d[j]));
    }
    T = pda_ref(f, m, (const double(*)[2])nud, bd, PROB_D(beta0), xr, Pr, c);
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_REAL_MSG(x_want[i], xr[i], "x of the quantised inputs");
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_TRUE(P[i][k] == P[k][i]); /* symmetric by construction */
            TV_ASSERT_REAL_MSG(P_want[4 * i + k], Pr[4 * i + k], "P of the quantised inputs");
        }
    }
#ifdef MTT_REAL_FIXED
    {
        const double tolP = 22.0 * 4.0 * ldexp(T, -28);
        for (i = 0; i < 4; ++i) {
            const double k0 = fabs(K_D(f, i, 0)), k1 = fabs(K_D(f, i, 1));
            const double tolx = ldexp(1.0, -MTT_FX_POS_FRAC - 1) + (k0 + k1) * (m + 1) * ldexp(numax, -27) +
                                3.0 * ldexp(k0 * fabs(c[0]) + k1 * fabs(c[1]), -27);
            tv_assert_q(xr[i], POS_D(x[i]), tolx, "x", __LINE__);
            worst = fmax(worst, fabs(POS_D(x[i]) - xr[i]) / tolx);
            for (k = 0; k < 4; ++k) {
                const double ks = (fabs(K_D(f, i, 0)) + fabs(K_D(f, i, 1))) *
                                  (fabs(K_D(f, k, 0)) + fabs(K_D(f, k, 1)));
                const double tol = tolP + (4.0 * m + 12.0) * ldexp(numax * numax, -27) * ks;
                tv_assert_q(Pr[4 * i + k], tv_cov_at(P, i, k), tol, "P", __LINE__);
                worst = fmax(worst, fabs(tv_cov_at(P, i, k) - Pr[4 * i + k]) / tol);
            }
        }
        /* stored renormalised: the largest mantissa on 28 bits */
        TEST_ASSERT_TRUE(P[0][0] < (1 << 28) && (P[0][0] >= (1 << 27) || P[2][2] >= (1 << 27) ||
                                                   P[3][3] >= (1 << 27) || P[1][1] >= (1 << 27)));
    }
#else
    (void)T;
    TV_ASSERT_VEC(x_want, x, 4);
    TV_ASSERT_MAT4(P_want, P);
#endif
}

static void check_pda(struct fix *f, int m, const double z[][2], const double *beta_d,
                      double beta0_d, const double *x_want, const double *P_want)
{
    mtt_real nu[3][2], beta[3];
    mtt_state x;
    mtt_cov P;
    int k, j;
    memset(nu, 0, sizeof nu);
    memset(beta, 0, sizeof beta);
    for (j = 0; j < m; ++j) {
        for (k = 0; k < 2; ++k) {
            nu[j][k] = POS(z[j][k]) - f->xp[k];
        }
        beta[j] = PROB(beta_d[j]);
    }
    mtt_kalman_pda(f->xp, f->Pp, f->K, f->Si, f->R, (uint16_t)m, nu, beta, PROB(beta0_d), x, P);
    check_result(f, m, z, beta_d, PROB(beta0_d), x_want, P_want, x, P);
}

/* One measurement, beta 1, beta0 0: the Kalman update (TV2 x_upd, P_upd). */
static void test_tv2_update(void)
{
    struct fix f;
    const double one = 1.0;
    tv2_fix(&f);
    check_pda(&f, 1, &tv2_z, &one, 0.0, tv2_xupd, tv2_Pupd);
}

/* No measurement, beta0 0: the Joseph form P_c (TV2 P_upd); x stays. */
static void test_tv2_joseph(void)
{
    struct fix f;
    tv2_fix(&f);
    check_pda(&f, 0, NULL, NULL, 0.0, tv2_xpred, tv2_Pupd);
}

/* No measurement, beta0 1: the prediction itself (TV2 x_pred, P_pred). */
static void test_tv2_keeps_prediction(void)
{
    struct fix f;
    tv2_fix(&f);
    check_pda(&f, 0, NULL, NULL, 1.0, tv2_xpred, tv2_Ppred);
}

/* Three measurements with TV6's IPDA betas (TV6 x_upd, P_upd). */
static void test_tv6_pda(void)
{
    struct fix f;
    tv2_fix(&f);
    check_pda(&f, 3, tv5_z, tv6_beta, tv6_beta0, tv6_x, tv6_P);
}

/* ---- the positive-definiteness test with its margin (d_i > rel P_ii,
 * ALGORITHMS.md §3, §16), and b' A^-1 b.  Fixed point: A is scaled D A D
 * so that every diagonal has 29 or 30 bits, then eliminated without
 * division (kalman.c, fraction-free: each step forms p B_ij - B_ik B_jk,
 * two fast products of factors below 2^30, and renormalises the block to
 * 30 bits).  Each of the 10 entries of the 4 x 4 elimination takes at
 * most 2 units of 2^-30 of its block (two products at 0.5008 units, the
 * renormalisation's half unit), and a block of a positive semi-definite
 * matrix is bounded by its diagonal, at most 2^30 times the scaled
 * matrix's largest: at most 2 2^-28 max |A| on an entry of A (D = I for
 * the test matrices, whose variances lie within a factor 4 of each other,
 * up to a factor 2); b' A^-1 b moves by |x' dA x| <= 10 2^-27 max|A|
 * (sum |x_i|)^2 with x = A^-1 b (in double).  D b bordering A is rounded
 * to 30 bits and its 10 entries of the elimination carry 2 units each: a
 * perturbation of D b within 2 (sum |x_i|) 4 2^-25 max |b|; the final
 * quotient by mu on 29 bits and the Q24 result: 6 2^-29 d2 + 2^-25.  The
 * same bound as the L D L' with reciprocals had, which it now holds with
 * more room. ---- */
static double quad_tol(const double A[16], const double b[4], double *d2)
{
    /* x = A^-1 b by Gauss-Jordan in double (the 4 x 4 test matrices are
     * well conditioned) */
    double a[4][5], amax = 0.0, bmax = 0.0, l1 = 0.0, q = 0.0;
    int i, j, k;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            a[i][j] = A[4 * i + j];
            amax = fmax(amax, fabs(A[4 * i + j]));
        }
        a[i][4] = b[i];
        bmax = fmax(bmax, fabs(b[i]));
    }
    for (k = 0; k < 4; ++k) {
        for (i = 0; i < 4; ++i) {
            if (i != k) {
                const double g = a[i][k] / a[k][k];
                for (j = k; j < 5; ++j) {
                    a[i][j] -= g * a[k][j];
                }
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        const double x = a[i][4] / a[i][i];
        l1 += fabs(x);
        q += b[i] * x;
    }
    *d2 = q;
    return 10.0 * ldexp(amax, -27) * l1 * l1 + 8.0 * l1 * ldexp(bmax, -25) + 6.0 * ldexp(fabs(q), -29) +
           ldexp(1.0, -25);
}

static void check_quad(mtt_cov A, const double b_d[4], double want)
{
    double Ad[16], bq[4], ref, tol;
    mtt_state b;
    mtt_real d2 = MTT_ZERO;
    int i, k;
    for (i = 0; i < 4; ++i) {
        b[i] = POS(b_d[i]);
        bq[i] = POS_D(b[i]);
        for (k = 0; k < 4; ++k) {
            Ad[4 * i + k] = tv_cov_at(A, i, k);
        }
    }
    tol = quad_tol(Ad, bq, &ref);
    TV_ASSERT_REAL_MSG(want, ref, "b' A^-1 b of the quantised inputs");
    TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(A, b, &d2));
    TV_ASSERT_Q(ref, d2, MTT_FX_D2_FRAC, tol);
#ifdef MTT_REAL_FIXED
    worst = fmax(worst, fabs(TV_Q(d2, MTT_FX_D2_FRAC) - ref) / tol);
#endif
}

static void test_quad_and_pd(void)
{
    struct fix f;
    double b[4];
    mtt_state x;
    mtt_cov P;
    int i;
    tv2_fix(&f);
    /* b = P^ e1: b' P^-1 b = P^_11 = 8.666666667 (TV2); b = P^ e4: 6 */
    for (i = 0; i < 4; ++i) {
        b[i] = tv2_Ppred[4 * i];
    }
    check_quad(f.Pp, b, 8.666666667);
    for (i = 0; i < 4; ++i) {
        b[i] = tv2_Ppred[4 * i + 3];
    }
    check_quad(f.Pp, b, 6.0);
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(f.Pp, MTT_FRAME_COV_MARGIN));
    /* TV2's updated P is positive definite with the margin */
    mtt_kalman_pda(f.xp, f.Pp, f.K, f.Si, f.R, 0, NULL, NULL, MTT_ZERO, x, P);
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(P, MTT_FRAME_COV_MARGIN));
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(P, MTT_SEED_COV_MARGIN));
}

static void test_pd_rejects(void)
{
    /* indefinite ([[1, 2], [2, 1]] has eigenvalue -1), singular, and a
     * pivot d_1 = 1 - c^2 on either side of the margins */
    static const double indef[16] = {1, 2, 0, 0, 2, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    static const double sing[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0};
    static const double neg[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    double near[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    mtt_cov A;
    mtt_real d2 = MTT_D2(42.0);
    const mtt_state b = {POS(1.0), POS(1.0), POS(1.0), POS(1.0)};
    tv_cov_set(A, indef, -28);
    TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
    TEST_ASSERT_TRUE(d2 == MTT_D2(42.0)); /* untouched */
    tv_cov_set(A, sing, -28);
    TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
    tv_cov_set(A, neg, -28);
    TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    /* c = 1 - 1e-7: d_1 = 2e-7, below 16 float eps (1.9e-6; the fixed
     * build's margins are the float ones, the double build's 2^-29 times
     * smaller); c = 1 - 1e-5: above it, below the seed margin 1000 eps
     * (1.2e-4) */
#ifndef MTT_REAL_DOUBLE
    near[1] = near[4] = 1.0 - 1e-7;
    tv_cov_set(A, near, -28);
    TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    near[1] = near[4] = 1.0 - 1e-5;
    tv_cov_set(A, near, -28);
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_SEED_COV_MARGIN));
#else
    near[1] = near[4] = 1.0 - 1e-5;
    tv_cov_set(A, near, -28);
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(A, MTT_SEED_COV_MARGIN));
#endif
    {
        /* variances 2^24 and 1 (a 2^24 dynamic range in one block), their
         * correlation 1 - 2^-13: d_1 / P_11 = 2.44e-4, above both margins
         * in float; exact in every format here.  The fixed test scales each
         * row and column to its own variance (D A D) and resolves it too */
        double wide[16] = {16777216.0, 4095.5, 0, 0, 4095.5, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        tv_cov_set(A, wide, -4);
        TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
        wide[1] = wide[4] = 4096.0; /* correlation 1: singular */
        tv_cov_set(A, wide, -4);
        TEST_ASSERT_EQUAL_INT(0, mtt_cov_ok(A, MTT_FRAME_COV_MARGIN));
    }
#ifdef MTT_REAL_FIXED
    /* far beyond every threshold: saturates, never wraps */
    {
        const mtt_state far = {MTT_FX_POS_LIMIT, -MTT_FX_POS_LIMIT, 0, 0};
        near[1] = near[4] = 0.0;
        near[0] = near[5] = near[10] = near[15] = 1e-6;
        tv_cov_set(A, near, -50);
        TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(A, far, &d2));
        TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, d2);
    }
#endif
}

/* ---- the two-point birth (ALGORITHMS.md §12.1, TV10) and the velocity
 * cap.  Fixed point: R and dt are exact in their formats here; R/dt is one
 * quotient q (half a unit at its exponent e2), 2R/dt^2 = 2 q / dt a second
 * one (half a unit at e3, plus q's half unit times 2/dt, at most half a
 * unit at e3 since 2^e2 / dt <= 2^(e3 - 1)); the three blocks meet at the
 * largest exponent E (half a unit) and P is renormalised (half a unit of
 * P).  Each block's largest entry has at least 26 bits, so E <= e(P) + 2:
 * |error| <= 1.5 2^E + 0.5 u(P) <= 6.5 u(P), u(P) = 2^e(P). ---- */
static const double tv10_P1[16] = {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0, 1, 0, 2};
static const double tv10_P2[16] = {4, 0, 8, 0, 0, 9, 0, 18, 8, 0, 32, 0, 0, 18, 0, 72};

#ifdef MTT_REAL_FIXED
#define DT(v) ((mtt_real)llround(ldexp((v), MTT_FX_T_FRAC)))
#define UNIT(P) ldexp(1.0, MTT_COV_E(P))
#else
#define DT(v) ((mtt_real)(v))
#define UNIT(P) 0.0
#endif

static void check_cov(mtt_cov P, const double *want, double tol)
{
    int i, k;
    for (i = 0; i < 4; ++i) {
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_TRUE(P[i][k] == P[k][i]);
#ifdef MTT_REAL_FIXED
            tv_assert_q(want[4 * i + k], tv_cov_at(P, i, k), tol, "P", __LINE__);
            worst = fmax(worst, fabs(tv_cov_at(P, i, k) - want[4 * i + k]) / tol);
#else
            (void)tol;
            TV_ASSERT_REAL_MSG(want[4 * i + k], tv_cov_at(P, i, k), "P");
#endif
        }
    }
}

static void two_point(double r11, double r12, double r22, double dt, const double *want)
{
    const mtt_real R[3] = {VAR(r11), VAR(r12), VAR(r22)};
    mtt_cov P;
    mtt_motion_two_point_cov(R, DT(dt), P);
    check_cov(P, want, 6.5 * UNIT(P));
}

static void test_tv10_two_point(void)
{
    static const double full[16] = {4, 1, 8, 2, 1, 9, 2, 18, 8, 2, 32, 8, 2, 18, 8, 72};
    two_point(1.0, 0.0, 1.0, 1.0, tv10_P1);  /* TV10 case 1 */
    two_point(4.0, 0.0, 9.0, 0.5, tv10_P2);  /* TV10 case 2 */
    two_point(4.0, 1.0, 9.0, 0.5, full);     /* an off-diagonal R term */
    {
        /* TV2's R (0.3 as its Q16 value in the fixed build), dt 3: inexact
         * quotients */
        const double r[3] = {1.0, VAR_D(VAR(0.3)), 2.0}, dt = 3.0;
        double w[16];
        int i, j;
        for (i = 0; i < 2; ++i) {
            for (j = 0; j < 2; ++j) {
                const double rr = r[i + j];
                w[4 * i + j] = rr;
                w[4 * i + j + 2] = rr / dt;
                w[4 * (i + 2) + j] = rr / dt;
                w[4 * (i + 2) + j + 2] = 2.0 * rr / (dt * dt);
            }
        }
        two_point(1.0, 0.3, 2.0, dt, w);
    }
}

static mtt_mstore mstore(double x, double y)
{
    mtt_mstore m;
    memset(&m, 0, sizeof m);
    m.x = POS(x);
    m.y = POS(y);
    return m;
}

/* TV10 case 1: a = (100, 200), b = (130, 190), dt 1, R = I, vmax 60 (no
 * cap: 2R/dt^2 = 2 < 3600).  x is exact in every build. */
static void test_tv10_birth(void)
{
    const mtt_mstore a = mstore(100.0, 200.0), b = mstore(130.0, 190.0);
    const mtt_real R[3] = {VAR(1.0), VAR(0.0), VAR(1.0)};
    static const double xw[4] = {130.0, 190.0, 30.0, -10.0};
    mtt_state x;
    mtt_cov P;
    int i;
    mtt_motion_birth(&a, &b, DT(1.0), R, POS(60.0), x, P);
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_Q(xw[i], x[i], MTT_FX_POS_FRAC, 0.0);
    }
    check_cov(P, tv10_P1, 6.5 * UNIT(P));
}

/* Detections 2^-10 frames apart with sigma 32 (as test_regress.c's F6):
 * 2R/dt^2 = 2^31 > vmax^2 = 3600, so the velocity rows and columns are
 * scaled by c = sqrt(3600 / 2^31) (P_vv = 3600).  Fixed point: c is formed
 * before the blocks meet, to 2^-27 relative (vmax^2 and the quotient on
 * 29 bits, the square root on 29 bits: three half units), and each of the
 * n = 0, 1, 2 factors c of an entry adds it and one product (0.5008 unit
 * of a block with at least 26 bits): with B_n the largest entry of the
 * block, |error| <= n (2^-27 + 2^-26) B_n + the two-point 6.5 u(P). */
static void test_velocity_cap(void)
{
    const double r = 1024.0, dt = ldexp(1.0, -10), vmax = 60.0;
    const mtt_mstore a = mstore(10.0, 20.0), b = mstore(10.0, 20.0);
    const mtt_real R[3] = {VAR(r), VAR(0.0), VAR(r)};
    const double c = sqrt(vmax * vmax / (2.0 * r / (dt * dt)));
    double P0[16], want[16];
    mtt_state x;
    mtt_cov P;
    int i, k;
    for (i = 0; i < 2; ++i) {
        for (k = 0; k < 2; ++k) {
            const double rr = (i == k) ? r : 0.0;
            P0[4 * i + k] = rr;
            P0[4 * i + k + 2] = rr / dt;
            P0[4 * (i + 2) + k] = rr / dt;
            P0[4 * (i + 2) + k + 2] = 2.0 * rr / (dt * dt);
        }
    }
    for (i = 0; i < 16; ++i) {
        want[i] = P0[i] * ((i / 4 >= 2) ? c : 1.0) * ((i % 4 >= 2) ? c : 1.0);
    }
    mtt_motion_birth(&a, &b, DT(dt), R, POS(vmax), x, P);
    TV_ASSERT_Q(0.0, x[2], MTT_FX_POS_FRAC, 0.0);
#ifdef MTT_REAL_FIXED
    {
        double B[3] = {0.0, 0.0, 0.0};
        for (i = 0; i < 16; ++i) {
            const int n = (i / 4 >= 2) + (i % 4 >= 2);
            B[n] = fmax(B[n], fabs(want[i]));
        }
        for (i = 0; i < 4; ++i) {
            for (k = 0; k < 4; ++k) {
                const int n = (i >= 2) + (k >= 2);
                const double tol = n * (ldexp(1.0, -27) + ldexp(1.0, -26)) * B[n] + 6.5 * UNIT(P);
                tv_assert_q(want[4 * i + k], tv_cov_at(P, i, k), tol, "capped P", __LINE__);
                worst = fmax(worst, fabs(tv_cov_at(P, i, k) - want[4 * i + k]) / tol);
            }
        }
    }
#else
    check_cov(P, want, 0.0);
#endif
    TEST_ASSERT_EQUAL_INT(1, mtt_cov_ok(P, MTT_SEED_COV_MARGIN));
}

/* ---- the update stage (update.c) on a hand-built frame: TV2's track
 * three times over TV5's measurements.  PDA kind (`ipda`): track 0 with
 * TV6's betas and posterior existence, track 1 with no gated measurement
 * (keeps its prediction, L = 1 - PD PG: TV5 m = 0), track 2 invalid
 * (untouched).  ONE kind (`ihpda`): track 0 assigned TV5's z2 with its
 * beta and L (TV5 x_upd, P_upd, existence), track 1 with none.  The
 * states and covariances within check_result's tolerances; the existence
 * of a track with no measurement within the roundings of L (its Q30
 * product and Q16 conversion: 2^-17 + 2^-31) and of the update (its Q16
 * numerator, 2^-17, and the Q30 quotient, 2^-31), through the condition
 * factors dE/dL = P(1-P)/den^2 and (1 + E)/den (den = 1 - P + L P). ---- */
static mtt_tracker trk;

static const double tv5_src_beta[3] = {0.3499423017, 0.7912724307, 0.1716428718}; /* TV5 */
static const double tv5_L2 = 6.870114355;                                        /* TV5 z2 */
static const double tv5_xupd[4] = {107.481207, 46.56073435, 8.579750984, -4.025743815};
static const double tv5_Pupd[16] = {4.189872991,  -0.6399013683, 2.243720278,  -0.5911472809,
                                    -0.6399013683, 3.737083804,  -0.5636540844, 2.005445908,
                                    2.243720278,  -0.5636540844, 4.846887268,  -0.1596150748,
                                    -0.5911472809, 2.005445908,  -0.1596150748, 4.723167884};

static void stage_setup(mtt_assoc mode, struct fix *f)
{
    int i, j, k;
    memset(&trk, 0, sizeof trk);
    tv2_fix(f);
    TV_PAR(&trk).association = mode;
    TV_PAR(&trk).pd = PROB(0.9);
    TV_PAR(&trk).pg = PROB(0.99);
    for (k = 0; k < 3; ++k) {
        TV_R(&trk)[k] = f->R[k];
    }
    for (j = 0; j < 3; ++j) {
        TV_MEAS_X(&trk, j) = POS(tv5_z[j][0]);
        TV_MEAS_Y(&trk, j) = POS(tv5_z[j][1]);
        TV_MEAS_SRC(&trk, j) = (uint32_t)(10 + j);
    }
    TV_N_MEAS(&trk) = 3;
    TV_N_TRACKS(&trk) = 3;
    for (i = 0; i < 3; ++i) {
        memcpy(TV_XP(&trk, i), f->xp, sizeof f->xp);
        memcpy(TV_PP(&trk, i), f->Pp, sizeof f->Pp);
        memcpy(TV_S(&trk, i), f->S, sizeof f->S);
        memcpy(TV_SI(&trk, i), f->Si, sizeof f->Si);
        memcpy(TV_GAIN(&trk, i), f->K, sizeof f->K);
        TV_DET_S(&trk, i) = f->det;
        TV_EX_PRED(&trk, i) = PROB(0.6);
        TV_VALID(&trk, i) = (uint8_t)(i < 2);
        TV_ASSIGNED(&trk, i) = -1;
        TV_X(&trk, i)[0] = POS(-1.0); /* the old state, replaced by every valid track */
        TV_EXISTENCE(&trk, i) = PROB(0.5);
    }
    /* track 0's pairs: TV5's three measurements */
    for (j = 0; j < 3; ++j) {
        TV_PAIR_TRACK(&trk, j) = 0;
        TV_PAIR_MEAS(&trk, j) = (uint16_t)j;
    }
    TV_N_PAIRS(&trk) = 3;
    TV_PAIR_FIRST(&trk, 0) = 0;
    TV_PAIR_COUNT(&trk, 0) = 3;
    TV_PAIR_FIRST(&trk, 1) = 3;
    TV_PAIR_COUNT(&trk, 1) = 0;
}

/* Track 1 (no measurement) and track 2 (invalid) after either kind. */
static void check_unupdated(struct fix *f)
{
    const double pdpg = PROB_D(MTT_MUL_PP(PROB(0.9), PROB(0.99)));
    const double L = 1.0 - pdpg, P = 0.6, den = 1.0 - P + L * P, E = L * P / den;
    int i, k;
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_TRUE(TV_X(&trk, 1)[i] == f->xp[i]);
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_TRUE(TV_P(&trk, 1)[i][k] == f->Pp[i][k]); /* copied bit for bit */
        }
    }
    TEST_ASSERT_TRUE(tv_cov_at(TV_P(&trk, 1), 0, 0) == tv_cov_at(f->Pp, 0, 0)); /* with its exponent */
    TV_ASSERT_PROB(0.1405242802, TV_EXISTENCE(&trk, 1),
                   P * (1.0 - P) / (den * den) * (ldexp(1.0, -17) + ldexp(1.0, -31)) +
                       (1.0 + E) / den * ldexp(1.0, -17) + ldexp(1.0, -31)); /* TV5 m = 0 */
    TEST_ASSERT_EQUAL_INT(-1, TV_TRACK_MEAS(&trk, 1));
    TEST_ASSERT_EQUAL_UINT8(1, TV_VALID(&trk, 1));
    TEST_ASSERT_TRUE(TV_X(&trk, 2)[0] == POS(-1.0)); /* invalid: untouched */
    TEST_ASSERT_TRUE(TV_EXISTENCE(&trk, 2) == PROB(0.5));
}

static void test_stage_pda(void)
{
    struct fix f;
    int j;
    stage_setup(MTT_ASSOC_IPDA, &f);
    for (j = 0; j < 3; ++j) {
        TV_PAIR_BETA(&trk, j) = PROB(tv6_beta[j]);
    }
    TV_BETA0(&trk, 0) = PROB(tv6_beta0);
    TV_EX_POST(&trk, 0) = PROB(0.942486148);
    mtt_update_frame(&trk);
    check_result(&f, 3, tv5_z, tv6_beta, PROB(tv6_beta0), tv6_x, tv6_P, TV_X(&trk, 0), TV_P(&trk, 0));
    TEST_ASSERT_TRUE(TV_EXISTENCE(&trk, 0) == PROB(0.942486148)); /* the association's */
    TEST_ASSERT_EQUAL_INT(10, TV_TRACK_MEAS(&trk, 0));           /* largest beta: z1 */
    TEST_ASSERT_EQUAL_UINT8(1, TV_VALID(&trk, 0));
    check_unupdated(&f);
}

static void test_stage_one(void)
{
    struct fix f;
    const double b = tv5_src_beta[1];
    stage_setup(MTT_ASSOC_IHPDA, &f);
    TV_ASSIGNED(&trk, 0) = 1; /* z2 */
    TV_PAIR_BETA(&trk, 1) = PROB(b);
    TV_PAIR_L(&trk, 1) = MTT_RATIO(6.870114355);
    TV_PAIR_LAM(&trk, 1) = MTT_RATIO(1.0); /* the fixed build reads L / lambda_j (MTT_PAIR_L): exact here */
    mtt_update_frame(&trk);
    check_result(&f, 1, &tv5_z[1], &b, PROB(1.0) - PROB(b), tv5_xupd, tv5_Pupd, TV_X(&trk, 0),
                 TV_P(&trk, 0));
    {
        /* P(exist | Z^k) = L P / (1 - P + L P): L's Q16 (2^-17) and the
         * update's roundings as above */
        const double P = 0.6, den = 1.0 - P + tv5_L2 * P, E = tv5_L2 * P / den;
        TV_ASSERT_PROB(0.9115449069, TV_EXISTENCE(&trk, 0),
                       P * (1.0 - P) / (den * den) * ldexp(1.0, -17) + (1.0 + E) / den * ldexp(1.0, -17) +
                           ldexp(1.0, -31)); /* TV5 */
    }
    TEST_ASSERT_EQUAL_INT(11, TV_TRACK_MEAS(&trk, 0));
    TEST_ASSERT_EQUAL_UINT8(1, TV_VALID(&trk, 0));
    check_unupdated(&f);
}

static void report(void)
{
#ifdef MTT_REAL_FIXED
    printf("largest |error| / derived tolerance: %.3g\n", worst);
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv2_update);
    RUN_TEST(test_tv2_joseph);
    RUN_TEST(test_tv2_keeps_prediction);
    RUN_TEST(test_tv6_pda);
    RUN_TEST(test_quad_and_pd);
    RUN_TEST(test_pd_rejects);
    RUN_TEST(test_tv10_two_point);
    RUN_TEST(test_tv10_birth);
    RUN_TEST(test_velocity_cap);
    RUN_TEST(test_stage_pda);
    RUN_TEST(test_stage_one);
    report();
    return UNITY_END();
}
