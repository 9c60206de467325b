/* SPDX-License-Identifier: BSD-3-Clause */
/* gate.c - ellipsoidal gating of every track (ALGORITHMS.md §4).
 *
 * gamma = -2 ln(1 - PG); a measurement is gated when d^2 = nu' S^-1 nu <=
 * gamma; V_G = pi gamma sqrt(det S); p = N(nu; 0, S) / PG.
 * The measurements are stored sorted along x (measure.c's canonical
 * order); each track scans only the slice its gate can reach
 * (|nu_x| <= sqrt(gamma s11)), so the cost is O(n log n + sum of slice
 * lengths), not tracks x measurements. */
#include "mtt_internal.h"

#ifdef MTT_REAL_FIXED
/* ---- The gate's arithmetic in the fixed-point build (docs/FIXED_POINT.md
 * §4, step 5).  gamma and d^2 are Q24; S and det S are mantissas with the
 * exponents of mtt/real.h (MTT_SYM_E, MTT_DET_E); densities are held
 * relative to the declared clutter density lambda (Q MTT_FX_DENS_FRAC per
 * unit^2), so the gate area is lambda V_G, an expected count (Q
 * MTT_FX_GATE_FRAC), and the likelihood the ratio p / lambda (Q16). ---- */

/* Bit length of v > 0. */
static int bits(uint32_t v)
{
    return 32 - mtt_fx_clz(v);
}

/* a b (both > 0) rounded to 30 bits; the dropped bits go into *e. */
static int32_t mul_e(int32_t a, int32_t b, int *e)
{
    int s = bits((uint32_t)a) + bits((uint32_t)b) - 30;
    s = (s < 0) ? 0 : s;
    *e += s;
    return mtt_fx_mul(a, b, s);
}

/* sqrt(det S) as a mantissa below 2^31 times 2^*e (det > 0). */
static int32_t sqrt_det(int32_t det, const int32_t S[MTT_SYM_SLOTS], int *e)
{
    const int de = MTT_DET_E(S);
    const int f = ((de & 1) != 0) ? 31 : 30; /* de - f even */
    *e = (de - f) / 2;
    return (int32_t)mtt_fx_sqrt((uint32_t)det, f);
}

/* pi 2^29 and 2 pi 2^29 */
#define FX_PI_Q29 MTT_FX_CONST(3.14159265358979323846, 29)
#define FX_2PI_Q28 MTT_FX_CONST(6.28318530717958647693, 28)

mtt_d2 mtt_gate_gamma(mtt_prob pg)
{
    /* -2 ln(1 - PG): ln in Q25 is -gamma in Q24 (fixed.h: <= 2 units) */
    return -mtt_fx_ln((uint32_t)(MTT_P(1.0) - pg), MTT_FX_PROB_FRAC);
}

/* The per-frame factors of lambda V_G and of p / lambda's peak, each a
 * mantissa below 2^31 and its exponent: gc[0] 2^gc[1] = pi gamma lambda
 * (0 when gamma or lambda is not positive), gc[2] 2^gc[3] = 2 pi PG
 * lambda (0 when PG or lambda is not positive).  Formed once per frame,
 * they leave one product per track for each (the same three products,
 * associated the other way). */
void mtt_fx_gate_consts(mtt_d2 gamma, mtt_prob pg, int32_t dens, int32_t gc[4])
{
    int e = 0;
    gc[0] = 0;
    gc[2] = 0;
    if (gamma > 0 && dens > 0) {
        gc[0] = mul_e(mul_e(gamma, FX_PI_Q29, &e), dens, &e);
    }
    gc[1] = e - MTT_FX_D2_FRAC - 29 - MTT_FX_DENS_FRAC;
    e = 0;
    if (pg > 0 && dens > 0) {
        gc[2] = mul_e(mul_e(FX_2PI_Q28, pg, &e), dens, &e);
    }
    gc[3] = e - 28 - MTT_FX_PROB_FRAC - MTT_FX_DENS_FRAC;
}

/* lambda V_G and p / lambda's peak from one square root of det S per
 * track (the two differ only in the factors after it) and the frame's
 * factors gc.  *peak (when not NULL) is MTT_FX_MAX and the area 0 where an
 * input is not positive. */
mtt_ratio mtt_fx_gate_area_peak_c(const int32_t gc[4], int32_t det, const int32_t S[MTT_SYM_SLOTS],
                                  mtt_ratio *peak)
{
    int e = 0, e1 = 0, s;
    int32_t r = 0, m;
    mtt_ratio area = 0;
    if (peak != NULL) {
        *peak = MTT_FX_MAX;
    }
    if (!(det > 0)) {
        return 0;
    }
    r = sqrt_det(det, S, &e);
    if (gc[0] > 0) {
        m = mul_e(r, gc[0], &e1);
        /* lambda pi gamma sqrt(det S) */
        area = mtt_fx_at(m, e + e1 + gc[1], -MTT_FX_GATE_FRAC); /* saturated, 0 below */
    }
    if (peak != NULL && gc[2] > 0) {
        e1 = 0;
        m = mul_e(r, gc[2], &e1);
        e += e1 + gc[3];
        /* 1 / (2 pi sqrt(det S) PG lambda) = 2^(16 - e) / m in Q16 */
        s = MTT_FX_RATIO_FRAC - e;
        *peak = (s < 0) ? 0 : ((s > 62) ? MTT_FX_MAX : mtt_fx_div(1, m, s));
    }
    return area;
}

mtt_ratio mtt_fx_gate_area_peak(mtt_d2 gamma, int32_t det, const int32_t S[MTT_SYM_SLOTS], mtt_prob pg,
                                int32_t dens, mtt_ratio *peak)
{
    int32_t gc[4];
    mtt_fx_gate_consts(gamma, pg, dens, gc);
    return mtt_fx_gate_area_peak_c(gc, det, S, peak);
}

mtt_ratio mtt_fx_gate_area(mtt_d2 gamma, int32_t det, const int32_t S[MTT_SYM_SLOTS], int32_t dens)
{
    return mtt_fx_gate_area_peak(gamma, det, S, 0, dens, NULL);
}

mtt_ratio mtt_fx_gate_peak(int32_t det, const int32_t S[MTT_SYM_SLOTS], mtt_prob pg, int32_t dens)
{
    mtt_ratio peak;
    (void)mtt_fx_gate_area_peak(0, det, S, pg, dens, &peak);
    return peak;
}

mtt_ratio mtt_fx_gate_lik(mtt_ratio peak, mtt_d2 d2)
{
    /* exp(-d^2 / 2): d^2 / 2 in Q24 rounded (2^-25), exp in Q30 (fixed.h),
     * at most 1: the fast Q30 multiply cannot overflow */
    return mtt_fx_mulq30(peak, mtt_fx_exp_neg_q30(((uint32_t)d2 + 1u) >> 1));
}

mtt_pos mtt_fx_gate_width(mtt_d2 gamma, const int32_t S[MTT_SYM_SLOTS], int k)
{
    /* An upper bound of sqrt(gamma s_kk) in the position format.  The slice
     * only narrows the search (d^2 decides the gate), so it is rounded up
     * and 8 bits of root are enough: t = gamma s_kk 2^-a (exact, or 30
     * bits), w^2 = t 2^f in units of the position format; T = t 2^z in
     * [2^30, 2^32) with f - z even, w <= (sqrt8(T) + 1) 2^(8 + (f - z)/2)
     * (at most 1.5 2^-7 relative above: a slice at most 1.2 % wider, the
     * gated set the same), one more unit for t's rounding. */
    int a, f, z, g;
    int32_t t;
    uint32_t r;
    if (!(gamma > 0) || !(S[k] > 0)) {
        return 0;
    }
    a = bits((uint32_t)gamma) + bits((uint32_t)S[k]) - 30;
    a = (a < 0) ? 0 : a;
    t = mtt_fx_mul(gamma, S[k], a);
    if (!(t > 0)) {
        return 1;
    }
    f = MTT_SYM_E(S) - MTT_FX_D2_FRAC + 2 * MTT_FX_POS_FRAC + a;
    z = mtt_fx_clz((uint32_t)t); /* >= 1: t < 2^31 */
    z -= (f - z) & 1;
    r = (mtt_fx_sqrt8((uint32_t)t << z) + 1u) << 8; /* > sqrt(T), <= 2^16 + 2^8 */
    g = (f - z) / 2;
    if (g >= 0) {
        r = (g >= 16 || r > ((uint32_t)MTT_FX_MAX >> g)) ? (uint32_t)MTT_FX_MAX : (r << g);
    } else {
        r = (g <= -17) ? 1u : ((r + ((uint32_t)1 << -g) - 1u) >> -g); /* rounded up */
    }
    return (r >= (uint32_t)MTT_FX_MAX) ? MTT_FX_MAX : (int32_t)(r + 1u);
}
#else
/* ln x for finite x > 0 without libm's log (ALGORITHMS.md §16): x = m 2^e
 * with m in [1/sqrt 2, sqrt 2), ln m = 2 atanh s, s = (m - 1)/(m + 1),
 * |s| <= 0.172, by its series to s^9 (next term < 4e-10 relative: float
 * exact to a few ulp, for the float firmware).  Halving and doubling are
 * exact, so the only rounding is the series'. */
mtt_real mtt_gate_ln(mtt_real x)
{
    mtt_real m = x, s, s2;
    int e = 0, k;
    for (k = 0; k < 1100 && m < MTT_R(0.70710678118654752); ++k) {
        m *= MTT_R(2.0);
        --e;
    }
    for (k = 0; k < 1100 && m >= MTT_R(1.4142135623730951); ++k) {
        m *= MTT_R(0.5);
        ++e;
    }
    s = (m - MTT_R(1.0)) / (m + MTT_R(1.0));
    s2 = s * s;
    return (mtt_real)e * MTT_R(0.69314718055994531) +
           s * (MTT_R(2.0) + s2 * (MTT_R(2.0) / MTT_R(3.0) +
                                   s2 * (MTT_R(0.4) + s2 * (MTT_R(2.0) / MTT_R(7.0) + s2 * (MTT_R(2.0) / MTT_R(9.0))))));
}

mtt_real mtt_gate_gamma(mtt_real pg)
{
#if MTT_SMALL_LOG
    return MTT_R(-2.0) * mtt_gate_ln(MTT_R(1.0) - pg); /* firmware: no libm log (616 B) */
#else
    return MTT_R(-2.0) * mtt_log(MTT_R(1.0) - pg);
#endif
}

mtt_real mtt_gate_volume(mtt_real gamma, mtt_real det_s)
{
    return MTT_PI * gamma * mtt_sqrt(det_s);
}

mtt_real mtt_gate_likelihood(mtt_real d2, mtt_real det_s, mtt_real pg)
{
    return mtt_exp(MTT_R(-0.5) * d2) / (MTT_R(2.0) * MTT_PI * mtt_sqrt(det_s) * pg);
}
#endif /* MTT_REAL_FIXED */

/* A detection's own R in float and double: its likelihood is kept from
 * the gate test (mtt_gate_own); in the fixed-point build (no polar, no
 * range rate) it is formed for each gated pair as a ratio to the clutter
 * density, and own_p takes the frame's gate factors gc (mtt_fx_gate_consts). */
#if MTT_WITH_MEAS_COV && !defined(MTT_REAL_FIXED)
#define OWN_R_FLOAT 1
#else
#define OWN_R_FLOAT 0
#endif
#ifdef MTT_REAL_FIXED
#define GC_PARAM , const int32_t gc[4]
#define GC_ARG , gc
#else
#define GC_PARAM
#define GC_ARG
#endif

#if OWN_R_FLOAT
mtt_real mtt_gate_own(const mtt_tracker *trk, const mtt_real *xp, const mtt_real *Pp, const mtt_mstore *ms,
                      mtt_real *p)
{
    mtt_real d2, S[3], f;
    if (mtt_meas_gauss(Pp, Pp + MTT_MAX_STATE, ms->R, trk->par.pg, ms->x - xp[0], ms->y - xp[1], &d2, p, S) != 0) {
        *p = MTT_R(0.0);
        return MTT_REAL_MAX;
    }
    f = mtt_polar_rdot_lik(trk, xp, Pp, S, ms); /* 1 without a range rate */
    if (!(f > MTT_R(0.0))) {
        *p = MTT_R(0.0);
        return MTT_REAL_MAX;
    }
    *p *= f;
    return d2;
}
#endif

/* d^2 of a detection against the track's CV prediction: with its own R
 * when it has one (then *p gets its likelihood, mtt_gate_own), else the
 * track's S^-1 (the likelihood from d^2 and the track's peak, own_p). */
static mtt_d2 own_d2(const mtt_tracker *trk, mtt_track_frame *tf, const mtt_mstore *ms, mtt_pos dx, mtt_pos dy,
                     mtt_real *p)
{
#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
    (void)trk;
    if (ms->has_R) {
        mtt_d2 d2;
        *p = MTT_ZERO;
        return (mtt_meas_gauss_fx(tf->Pp, ms->R, NULL, dx, dy, &d2, NULL, NULL) == 0) ? d2 : MTT_FX_MAX;
    }
#elif MTT_WITH_MEAS_COV
    if (ms->has_R) {
        return mtt_gate_own(trk, tf->xp, &tf->Pp[0][0], ms, p);
    }
#else
    (void)trk;
    (void)ms;
#endif
    *p = MTT_ZERO;
    return mtt_mahal2(tf->Si, dx, dy);
}

/* Its gate-normalised likelihood N / PG (ALGORITHMS.md §4): for its own R
 * p, own_d2's (fixed point: formed here), else from d2 its own_d2. */
static mtt_ratio own_p(const mtt_tracker *trk, mtt_track_frame *tf, const mtt_mstore *ms, mtt_ratio peak, mtt_d2 d2,
                       mtt_real p GC_PARAM)
{
#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
    (void)trk;
    (void)p;
    if (ms->has_R) {
        mtt_ratio pf = 0;
        (void)mtt_meas_gauss_fx(tf->Pp, ms->R, gc, MTT_SUBS(ms->x, tf->xp[0]), MTT_SUBS(ms->y, tf->xp[1]), &d2, &pf, NULL);
        return pf;
    }
#elif MTT_WITH_MEAS_COV
    (void)trk;
    (void)tf;
    if (ms->has_R) {
        return p;
    }
#else
    (void)trk;
    (void)tf;
    (void)ms;
    (void)p;
#ifdef MTT_REAL_FIXED
    (void)gc;
#endif
#endif
    return MTT_GATE_LIK(peak, d2);
}

#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
/* The slice half-width w along k (0: x, 2: y) for the widest own R: that
 * of S with dr (variance format, the largest own r_kk less R_kk) added. */
static mtt_pos own_width(mtt_d2 gamma, const mtt_real S[MTT_SYM_SLOTS], mtt_real dr, int k, mtt_pos w)
{
    mtt_real Sk[MTT_SYM_SLOTS];
    int c;
    if (!(dr > 0)) {
        return w;
    }
    for (c = 0; c < MTT_SYM_SLOTS; ++c) {
        Sk[c] = S[c];
    }
    Sk[k] = MTT_ADDS(S[k], MTT_AT(dr, -MTT_FX_VAR_FRAC, MTT_SYM_E(S)));
    return MTT_GATE_WIDTH(gamma, Sk, k);
}
#endif

static int less_pair(const void *a, const void *b, const void *ctx)
{
    const mtt_pair *p = (const mtt_pair *)a, *q = (const mtt_pair *)b;
    (void)ctx;
    if (p->track != q->track) {
        return p->track < q->track;
    }
    return p->meas < q->meas;
}

/* First measurement (stored in x order, measure.c) whose x >= v. */
static uint16_t lower_bound_x(const mtt_mstore *meas, uint16_t n, mtt_pos v)
{
    uint16_t lo = 0, hi = n;
    while (lo < hi) {
        uint16_t mid = (uint16_t)(lo + (hi - lo) / 2u);
        if (meas[mid].x < v) {
            lo = (uint16_t)(mid + 1u);
        } else {
            hi = mid;
        }
    }
    return lo;
}

/* Beyond MTT_MAX_PAIRS: the least likely pair of the frame gives way (docs/DESIGN.md). */
static void push_pair(mtt_tracker *trk, mtt_pair *pairs, const mtt_pair *np, int *resort)
{
    uint16_t k, worst = 0;
    if (trk->n_pairs < MTT_MAX_PAIRS) {
        pairs[trk->n_pairs++] = *np;
        return;
    }
    trk->stats.last.pairs_dropped++;
    for (k = 1; k < MTT_MAX_PAIRS; ++k) {
        if (pairs[k].p < pairs[worst].p ||
            (pairs[k].p == pairs[worst].p && less_pair(&pairs[worst], &pairs[k], NULL))) {
            worst = k;
        }
    }
    if (np->p > pairs[worst].p) {
        pairs[worst] = *np;
        *resort = 1;
    }
}

#if OWN_R_FLOAT
void mtt_gate_own_widen(const mtt_tracker *trk, mtt_real gamma, mtt_real *wx, mtt_real *wy)
{
    if (trk->n_own_r > 0u) {
        /* detections with a wider R of their own: the window reaches
         * sqrt(gamma (S_xx - R_xx + r_xx)) <= w + sqrt(gamma (r_xx - R_xx)) (§3.1) */
        /* polar (§3.2): S holds the track's own R_t, not trk->R, so
         * the bound sqrt(gamma r_xx) without the subtraction */
        const int pol = trk->par.measurement == MTT_MEASUREMENT_POLAR;
        const mtt_real r0 = pol ? MTT_R(0.0) : trk->R[0], r2 = pol ? MTT_R(0.0) : trk->R[2];
        *wx += (trk->own_rmax[0] > r0) ? mtt_sqrt(gamma * (trk->own_rmax[0] - r0)) : MTT_R(0.0);
        *wy += (trk->own_rmax[1] > r2) ? mtt_sqrt(gamma * (trk->own_rmax[1] - r2)) : MTT_R(0.0);
    }
}
#endif

void mtt_gate_frame(mtt_tracker *trk)
{
    const uint16_t n = trk->n_meas;
    /* the tracker's arrays in locals: on Thumb-1 their fields lie beyond a
     * load's offset (docs/FIXED_POINT.md, "Size measures") */
    const mtt_mstore *meas = trk->meas;
    mtt_pair *pairs = trk->pairs;
    mtt_track_frame *tfs = trk->tf;
    uint16_t *mp_first = trk->mp_first;
    uint16_t cm[MTT_MAX_GATED];
    mtt_d2 cd[MTT_MAX_GATED];
#if OWN_R_FLOAT
    mtt_real cp[MTT_MAX_GATED]; /* own R: each one's likelihood, from its gate test */
#define CP_SET(k, v) (cp[k] = (v))
#define CP_GET(k) cp[k]
#else /* the likelihood from d^2 (the firmware's stack and text as they were) or formed per pair */
#define CP_SET(k, v) ((void)0)
#define CP_GET(k) MTT_ZERO
#endif
    uint16_t i, j, k;
    int resort = 0;
#ifdef MTT_REAL_FIXED
    const int32_t *gc = trk->gc; /* one gamma for every track: no adaptive JPDA in the fixed build */
#endif
#if MTT_WITH_IMM
    const int imm = trk->par.motion == MTT_MOTION_IMM;
#endif

    trk->n_pairs = 0;

    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &tfs[i];
        mtt_pos zx = tf->xp[0], zy = tf->xp[1], wx, wy;
        mtt_d2 gamma = trk->gamma;
        uint16_t nc = 0, a, b;
        mtt_ratio peak;
        if (!tf->valid) {
            continue;
        }
        if (MTT_WITH_BASELINES && tf->shrink) {
            gamma /= trk->par.adaptive_jpda_shrink; /* adaptive JPDA (ALGORITHMS.md §13.7) */
        }
        /* N(0; 0, S) / PG once per track: the pairs differ only in
         * exp(-d2/2), so the square root and divisions are not repeated per
         * pair (the fixed build shares sqrt(det S) with the area). */
#if MTT_WITH_IMM
        if (imm) {
            /* the union of the model gates (ALGORITHMS.md §14.2); the
             * models' own likelihoods (mtt_imm_gate_p) */
            peak = MTT_ZERO;
            tf->vg = tf->vgm;
            mtt_imm_gate_window(trk, i, &wx, &wy);
        } else
#endif
        {
#ifdef MTT_REAL_FIXED
            tf->vg = mtt_fx_gate_area_peak_c(gc, tf->det_s, tf->S, &peak); /* gamma: trk->gamma */
#else
            MTT_GATE_AREA_PEAK(tf->vg, peak, gamma, tf->det_s, tf->S, trk->par.pg, trk->par.clutter_density);
#endif
            wx = MTT_GATE_WIDTH(gamma, tf->S, 0);
            wy = MTT_GATE_WIDTH(gamma, tf->S, 2);
        }
#if MTT_WITH_MEAS_COV && defined(MTT_REAL_FIXED)
        if (trk->n_own_r > 0u) {
            /* detections with a wider R of their own: the window reaches
             * sqrt(gamma (S_xx - R_xx + r_xx)) (§3.1), an upper bound as
             * MTT_GATE_WIDTH's (no polar detections in this build) */
#if MTT_WITH_IMM
            if (imm) {
                /* the models' union: each model's half-width grows by at most
                 * sqrt(gamma dr) (sqrt(a + b) <= sqrt(a) + sqrt(b)) */
                const mtt_real z[MTT_SYM_SLOTS] = {0, 0, 0, -MTT_FX_VAR_FRAC};
                wx = MTT_ADDS(wx, own_width(gamma, z, trk->own_rmax[0] - trk->R[0], 0, 0));
                wy = MTT_ADDS(wy, own_width(gamma, z, trk->own_rmax[1] - trk->R[2], 2, 0));
            } else
#endif
            {
                wx = own_width(gamma, tf->S, trk->own_rmax[0] - trk->R[0], 0, wx);
                wy = own_width(gamma, tf->S, trk->own_rmax[1] - trk->R[2], 2, wy);
            }
        }
#elif MTT_WITH_MEAS_COV
        mtt_gate_own_widen(trk, gamma, &wx, &wy);
#endif
        for (j = lower_bound_x(meas, n, MTT_SUBS(zx, wx)); j < n; ++j) {
            mtt_pos dx = MTT_SUBS(meas[j].x, zx), dy = MTT_SUBS(meas[j].y, zy);
            mtt_d2 d2;
            mtt_real pj = MTT_ZERO;
            if (dx > wx) {
                break;
            }
            if (MTT_ABS(dy) > wy) {
                continue;
            }
#if MTT_WITH_IMM
            /* (its range rate outside its gate: d2 MTT_REAL_MAX, ALGORITHMS.md
             * §3.2; an IMM track's models gate it in mtt_imm_model_d2, a union) */
            d2 = imm ? mtt_imm_gate_d2(trk, i, &meas[j]) : own_d2(trk, tf, &meas[j], dx, dy, &pj);
#else
            d2 = own_d2(trk, tf, &meas[j], dx, dy, &pj);
#endif
            if (!(d2 <= gamma)) {
                continue;
            }
            if (nc < MTT_MAX_GATED) {
                cm[nc] = j;
                cd[nc] = d2;
                CP_SET(nc, pj);
                ++nc;
            } else {
                /* Gate full: the largest d^2 gives way (ALGORITHMS.md §7.2, cap). */
                uint16_t w = 0;
                for (a = 1; a < nc; ++a) {
                    if (cd[a] > cd[w] || (cd[a] == cd[w] && cm[a] > cm[w])) {
                        w = a;
                    }
                }
                trk->stats.last.gated_dropped++;
                if (d2 < cd[w] || (d2 == cd[w] && j < cm[w])) {
                    cm[w] = j;
                    cd[w] = d2;
                    CP_SET(w, pj);
                }
            }
        }
        /* Input order inside the gate (insertion sort of at most MTT_MAX_GATED). */
        for (a = 1; a < nc; ++a) {
            uint16_t mj = cm[a];
            mtt_d2 md = cd[a];
            const mtt_real mp = CP_GET(a);
            for (b = a; b > 0 && cm[b - 1u] > mj; --b) {
                cm[b] = cm[b - 1u];
                cd[b] = cd[b - 1u];
                CP_SET(b, CP_GET(b - 1u));
            }
            cm[b] = mj;
            cd[b] = md;
            CP_SET(b, mp);
            (void)mp;
        }
        for (a = 0; a < nc; ++a) {
            mtt_pair np;
            np.track = i;
            np.meas = cm[a];
#if MTT_WITH_IMM
            /* IMM: the model-mixed likelihood p* (ALGORITHMS.md §14.2) */
            np.p = imm ? mtt_imm_gate_p(trk, i, &meas[cm[a]]) : own_p(trk, tf, &meas[cm[a]], peak, cd[a], CP_GET(a) GC_ARG);
#else
            np.p = own_p(trk, tf, &meas[cm[a]], peak, cd[a], CP_GET(a) GC_ARG);
#endif
            np.w = MTT_ZERO;
            np.lam = MTT_ZERO;
            np.beta = MTT_ZERO;
            np.g = MTT_RATIO(1.0);
            push_pair(trk, pairs, &np, &resort);
        }
    }
#undef CP_SET
#undef CP_GET
    if (resort) {
        mtt_sort(pairs, trk->n_pairs, sizeof pairs[0], less_pair, NULL);
    }

    /* Per-track ranges (pairs are sorted by track). */
    for (i = 0; i < trk->n_tracks; ++i) {
        tfs[i].pair_count = 0;
        tfs[i].pair_first = 0;
        tfs[i].has_all_amp = 1;
    }
    for (k = trk->n_pairs; k > 0; --k) {
        const mtt_pair *pp = &pairs[k - 1u];
        mtt_track_frame *tf = &tfs[pp->track];
        tf->pair_first = (uint16_t)(k - 1u);
        tf->pair_count++;
        if (!meas[pp->meas].has_amp) {
            tf->has_all_amp = 0;
        }
    }
    /* Pairs of each measurement (CSR), ascending track. */
    for (i = 0; i <= n; ++i) {
        mp_first[i] = 0;
    }
    for (k = 0; k < trk->n_pairs; ++k) {
        mp_first[pairs[k].meas + 1u]++;
    }
    for (i = 0; i < n; ++i) {
        mp_first[i + 1u] = (uint16_t)(mp_first[i + 1u] + mp_first[i]);
    }
    /* Fill with mp_first[j] as the cursor of j; it then holds the end of j,
     * which is the start of j + 1: shift back by one. */
    for (k = 0; k < trk->n_pairs; ++k) {
        j = pairs[k].meas;
        trk->mp_list[mp_first[j]] = k;
        mp_first[j]++;
    }
    mtt_csr_unshift(mp_first, n);
    trk->stats.last.pairs = trk->n_pairs;
}
