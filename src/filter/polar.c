/* SPDX-License-Identifier: BSD-3-Clause */
/* polar.c - polar detections to Cartesian (ALGORITHMS.md §3.2): the
 * unbiased converted measurement of Mo, Song, Zhou, Sun and Bar-Shalom
 * (IEEE Trans. AES 34(3), 1998) with its covariance at the measured values,
 * written without the float cancellation of the paper's form; the same
 * covariance at a track's predicted position, which gives the track's S
 * (its gate, V_G) under polar detections; a range rate's gate test and its
 * extended Kalman update of the radial velocity; and the public conversion.
 * Only with MTT_WITH_POLAR (MTT_WITH_MEAS_COV in the float and double
 * builds; the fixed-point build has none): a converted detection is one
 * with its own covariance (§3.1). */
#include "mtt_internal.h"

#if MTT_WITH_POLAR

/* R of a detection at range r, bearing cos c, sin s (ALGORITHMS.md §3.2):
 * with u = sigma_b^2, A = 1 - e^{-2u}, B = e^u - 1 - A,
 *   R_xx = r^2 (A/2 + c^2 B) + sr^2 (1 + e^{-2u} (c^2 - s^2)) / 2
 *   R_yy = r^2 (A/2 + s^2 B) + sr^2 (1 - e^{-2u} (c^2 - s^2)) / 2
 *   R_xy = r^2 c s B + sr^2 e^{-2u} c s,
 * Mo et al.'s eq. with (e^u - 2) r^2 c^2 + r^2 (1 + e^{-2u} cos 2θ)/2
 * regrouped: in float the paper's form loses r^2 eps against r^2 sigma_b^2. */
void mtt_polar_cov(const mtt_real sigma[2], mtt_real r, mtt_real c, mtt_real s, mtt_real R[3])
{
    const mtt_real u = sigma[1] * sigma[1], sr2 = sigma[0] * sigma[0];
    const mtt_real A = -mtt_expm1(MTT_R(-2.0) * u), B = mtt_expm1(u) - A, l2 = MTT_R(1.0) - A;
    const mtt_real r2 = r * r, d = l2 * (c * c - s * s);
    R[0] = r2 * (MTT_R(0.5) * A + c * c * B) + MTT_R(0.5) * sr2 * (MTT_R(1.0) + d);
    R[1] = r2 * c * s * B + sr2 * l2 * c * s;
    R[2] = r2 * (MTT_R(0.5) * A + s * s * B) + MTT_R(0.5) * sr2 * (MTT_R(1.0) - d);
}

int mtt_polar_convert(const mtt_real sigma[2], const mtt_real sensor[2], mtt_real range, mtt_real bearing,
                      mtt_real *x, mtt_real *y, mtt_real R[3])
{
    mtt_real c, s, g;
    if (!(mtt_isfinite(range) && range > MTT_R(0.0) && mtt_isfinite(bearing))) {
        return -1;
    }
    c = mtt_cos(bearing);
    s = mtt_sin(bearing);
    g = mtt_exp(MTT_R(0.5) * sigma[1] * sigma[1]); /* 1 / E[cos w_b]: the bias compensation */
    *x = sensor[0] + g * range * c;
    *y = sensor[1] + g * range * s;
    mtt_polar_cov(sigma, range, c, s, R);
    return (mtt_isfinite(*x) && mtt_isfinite(*y) && mtt_isfinite(R[0]) && mtt_isfinite(R[1]) &&
            mtt_isfinite(R[2]))
               ? 0
               : -1;
}

mtt_real mtt_polar_range(const mtt_tracker *trk, const mtt_real *xp)
{
    const mtt_real dx = xp[0] - trk->par.sensor_xy[0], dy = xp[1] - trk->par.sensor_xy[1];
    return mtt_sqrt(dx * dx + dy * dy);
}

const mtt_real *mtt_polar_track_r(const mtt_tracker *trk, const mtt_real *xp, mtt_real R[3])
{
    mtt_real r, c = MTT_R(1.0), s = MTT_R(0.0);
    if (trk->par.measurement != MTT_MEASUREMENT_POLAR) {
        return trk->R;
    }
    r = mtt_polar_range(trk, xp);
    if (r > MTT_R(0.0)) {
        c = (xp[0] - trk->par.sensor_xy[0]) / r;
        s = (xp[1] - trk->par.sensor_xy[1]) / r;
    }
    mtt_polar_cov(trk->par.meas_sigma, r, c, s, R);
    return R;
}

/* The range rate h(x) = u . v (u the unit vector from the sensor to the
 * position of x) and its Jacobian H over x, y, vx, vy; 0, or -1 at the
 * sensor itself. */
static int rdot_h(const mtt_real sensor[2], const mtt_real *x, mtt_real *h, mtt_real H[4])
{
    const mtt_real dx = x[0] - sensor[0], dy = x[1] - sensor[1], r = mtt_sqrt(dx * dx + dy * dy);
    mtt_real ux, uy;
    if (!(r > MTT_R(0.0))) {
        return -1;
    }
    ux = dx / r;
    uy = dy / r;
    *h = ux * x[2] + uy * x[3];
    H[0] = (x[2] - ux * *h) / r;
    H[1] = (x[3] - uy * *h) / r;
    H[2] = ux;
    H[3] = uy;
    return 0;
}

/* Pp's element (i, k): rows of stride st */
#define PP(i, k) Pp[(i) * st + (k)]

mtt_real mtt_polar_rdot_f(const mtt_real sensor[2], mtt_real gamma, mtt_real vmax, const mtt_real *xp,
                          const mtt_real *Pp, int st, const mtt_real S[3], mtt_real nx, mtt_real ny,
                          const mtt_real rr[2])
{
    const mtt_real S0 = S[0], S1 = S[1], S2 = S[2], det = S0 * S2 - S1 * S1;
    mtt_real h, H[4], A[4], a0, a1, nu, s;
    int i, k;
    if (rr == NULL || rdot_h(sensor, xp, &h, H) != 0) {
        return MTT_R(1.0);
    }
    /* A = P H' over x, y, vx, vy: C = A[0..1] is the range rate's covariance
     * with the position innovation, H A + var its own variance */
    for (i = 0; i < 4; ++i) {
        A[i] = MTT_R(0.0);
        for (k = 0; k < 4; ++k) {
            A[i] += PP(i, k) * H[k];
        }
    }
    s = H[0] * A[0] + H[1] * A[1] + H[2] * A[2] + H[3] * A[3] + rr[1];
    if (!(det > MTT_R(0.0))) {
        return MTT_R(1.0);
    }
    /* the range rate's innovation given the position's: nu - C S^-1 nu_p,
     * variance s - C S^-1 C' (the sequential form of the 3-vector's d^2) */
    a0 = (S2 * A[0] - S1 * A[1]) / det;
    a1 = (S0 * A[1] - S1 * A[0]) / det;
    nu = rr[0] - h - (a0 * nx + a1 * ny);
    s -= a0 * A[0] + a1 * A[1];
    if (!(s > MTT_R(0.0))) {
        return MTT_R(1.0);
    }
    if (!(nu * nu <= gamma * s)) {
        return MTT_R(0.0);
    }
    /* [CHOICE] clutter range rates uniform on [-vmax, vmax]: the ratio of
     * N(nu; 0, s) to that density (ALGORITHMS.md §3.2) */
    return MTT_R(2.0) * vmax * mtt_exp(MTT_R(-0.5) * nu * nu / s) / mtt_sqrt(MTT_R(2.0) * MTT_PI * s);
}

mtt_real mtt_polar_rdot_lik(const mtt_tracker *trk, const mtt_real *xp, const mtt_real *Pp, const mtt_real S[3],
                            const mtt_mstore *ms)
{
    return mtt_polar_rdot_f(trk->par.sensor_xy, trk->gamma, trk->par.vmax, xp, Pp, MTT_MAX_STATE, S, ms->x - xp[0],
                            ms->y - xp[1], ms->has_rdot ? ms->rr : NULL);
}
#undef PP

/* P's, M's and T's element (i, k): rows of stride st; up to two targets'
 * states (the split modes' stacked state, §14.3) */
#define AT(X, i, k) X[(i) * st + (k)]
#define RDOT_N (2 * MTT_MAX_STATE)

int mtt_polar_rdot_step(int n, int o, int st, const mtt_real sensor[2], const mtt_real rr[2], mtt_real *x,
                        mtt_real *P, mtt_real *M, mtt_real *T)
{
    mtt_real h, H[4], A[RDOT_N], K[RDOT_N], s = rr[1], nu;
    int i, k, l;
    if (n < o + 4 || n > RDOT_N || n > st || rdot_h(sensor, x + o, &h, H) != 0) {
        return -1;
    }
    for (i = 0; i < n; ++i) {
        A[i] = MTT_R(0.0);
        for (k = 0; k < 4; ++k) {
            A[i] += AT(P, i, o + k) * H[k];
        }
    }
    for (k = 0; k < 4; ++k) {
        s += H[k] * A[o + k];
    }
    if (!(s > MTT_R(0.0)) || !mtt_isfinite(s)) {
        return -1;
    }
    nu = rr[0] - h;
    for (i = 0; i < n; ++i) {
        K[i] = A[i] / s;
        x[i] += K[i] * nu;
        for (k = 0; k < n; ++k) {
            AT(M, i, k) = ((i == k) ? MTT_R(1.0) : MTT_R(0.0)) - ((k >= o && k < o + 4) ? K[i] * H[k - o] : MTT_R(0.0));
        }
    }
    /* Joseph form (ALGORITHMS.md §3): P = M P M' + K var K' */
    for (i = 0; i < n; ++i) {
        for (k = 0; k < n; ++k) {
            AT(T, i, k) = MTT_R(0.0);
            for (l = 0; l < n; ++l) {
                AT(T, i, k) += AT(M, i, l) * AT(P, l, k);
            }
        }
    }
    for (i = 0; i < n; ++i) {
        for (k = i; k < n; ++k) {
            mtt_real v = K[i] * rr[1] * K[k];
            for (l = 0; l < n; ++l) {
                v += AT(T, i, l) * AT(M, k, l);
            }
            AT(P, i, k) = v;
            AT(P, k, i) = v;
        }
    }
    return 0;
}
#undef AT
#undef RDOT_N

void mtt_polar_rdot_update(int n, const mtt_real sensor[2], const mtt_real rr[2], mtt_real *x, mtt_cov P)
{
    mtt_real M[MTT_MAX_STATE][MTT_MAX_STATE], T[MTT_MAX_STATE][MTT_MAX_STATE];
    if (n < 4 || n > MTT_MAX_STATE) {
        return;
    }
    (void)mtt_polar_rdot_step(n, 0, MTT_MAX_STATE, sensor, rr, x, &P[0][0], &M[0][0], &T[0][0]);
}

#endif /* MTT_WITH_POLAR */

mtt_status mtt_polar_to_cartesian(const mtt_real sigma[2], const mtt_real sensor[2], const mtt_polar *det,
                                  /* cppcheck-suppress constParameter ; outputs where the build converts */
                                  mtt_meas *m, mtt_meas_cov *cov)
{
#if MTT_WITH_POLAR
    mtt_real x, y, R[3];
    if (sigma == NULL || sensor == NULL || det == NULL || m == NULL || cov == NULL) {
        return MTT_ERR_NULL;
    }
    if (!(mtt_isfinite(sigma[0]) && sigma[0] > MTT_R(0.0) && mtt_isfinite(sigma[1]) && sigma[1] > MTT_R(0.0)) ||
        !(mtt_isfinite(sensor[0]) && mtt_isfinite(sensor[1])) ||
        (det->has_amplitude && !(mtt_isfinite(det->amplitude) && det->amplitude >= MTT_R(0.0))) ||
        mtt_polar_convert(sigma, sensor, det->range, det->bearing, &x, &y, R) != 0) {
        return MTT_ERR_VALUE;
    }
    m->x = x;
    m->y = y;
    m->amplitude = det->has_amplitude ? det->amplitude : MTT_R(0.0);
    m->has_amplitude = det->has_amplitude != 0;
    cov->r_xx = R[0];
    cov->r_xy = R[1];
    cov->r_yy = R[2];
    return MTT_OK;
#else
    if (sigma == NULL || sensor == NULL || det == NULL || m == NULL || cov == NULL) {
        return MTT_ERR_NULL;
    }
    return MTT_ERR_UNSUPPORTED; /* polar needs a covariance per detection (§3.2) */
#endif
}
