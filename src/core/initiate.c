/* SPDX-License-Identifier: BSD-3-Clause */
/* initiate.c - two-point differencing initiation (ALGORITHMS.md §12.1) with the
 * velocity gate |z_k - z_k-1| <= vmax dT, or the intensity-based gate of
 * [S2] (ALGORITHMS.md §12.2): sigma_P = f(I)/sqrt(gamma), accept when
 * d' (sigma_P^2 I + R)^-1 d <= gamma.
 *
 * U_k = measurements of frame k not used by any track; U_k-1 = the same of
 * the previous frame minus those that already started a track.  Every
 * accepted pair starts one tentative track (merging removes duplicates).
 * Cost: O((|U_k| + |U_k-1| + pairs within reach) log n), by an x sweep.
 * Fixed-point build (docs/FIXED_POINT.md): the vmax circle only (params.c
 * refuses the intensity gate), tested on magnitudes scaled to 15 bits;
 * positions saturate instead of overflowing; the two-point covariance of
 * mtt_init_two_point_cov is returned in the variance format. */
#include <string.h>

#include "mtt_internal.h"

#ifndef MTT_REAL_FIXED
mtt_real mtt_init_intensity_f(const mtt_params *p, mtt_real I)
{
    const mtt_real *f1 = p->intensity_f1, *f2 = p->intensity_f2;
    const mtt_real lo = p->intensity_blend[0], hi = p->intensity_blend[1];
    mtt_real v1, v2, w1;
    if (!(I > MTT_R(0.0))) {
        I = MTT_R(0.0);
    }
    /* f2 is a downward parabola: clamp I at its peak so f never decreases
     * ([S2]'s f2 turns negative above I = 2341; ALGORITHMS.md §12.2 guards). */
    if (f2[0] < MTT_R(0.0)) {
        mtt_real peak = -f2[1] / (MTT_R(2.0) * f2[0]);
        if (I > peak) {
            I = peak;
        }
    }
    v1 = (f1[0] * I + f1[1]) * I + f1[2];
    v2 = (f2[0] * I + f2[1]) * I + f2[2];
    if (I <= lo) {
        return v1;
    }
    if (I > hi) {
        return v2;
    }
    w1 = (hi - I) / (hi - lo);
    return w1 * v1 + (MTT_R(1.0) - w1) * v2;
}

#define IN_CIRCLE(dx, dy, r) ((dx) * (dx) + (dy) * (dy) <= (r) * (r))
#else
/* dx^2 + dy^2 <= r^2 (r >= 0) on magnitudes cut to 15 bits of the largest
 * (to 2^-14 of r): no product leaves 32 bits. */
static int in_circle(mtt_pos dx, mtt_pos dy, mtt_pos r)
{
    uint32_t ux = (uint32_t)MTT_ABS(dx), uy = (uint32_t)MTT_ABS(dy), ur = (uint32_t)r;
    const int s = 17 - mtt_fx_clz(ur); /* bits of r beyond 15 */
    if (r < 0 || ux > ur || uy > ur) {
        return 0;
    }
    if (s > 0) {
        ux >>= s;
        uy >>= s;
        ur >>= s;
    }
    return ux * ux + uy * uy <= ur * ur;
}
#define IN_CIRCLE(dx, dy, r) in_circle((dx), (dy), (r))
#endif

int mtt_init_pair_ok(const mtt_tracker *trk, const mtt_mstore *a, const mtt_mstore *b, mtt_real dt)
{
    const mtt_pos dx = MTT_SUBS(b->x, a->x), dy = MTT_SUBS(b->y, a->y);
#ifndef MTT_REAL_FIXED
    if (trk->par.init_gate == MTT_INIT_GATE_INTENSITY && a->has_amp) {
        mtt_real f = mtt_init_intensity_f(&trk->par, a->amp);
        mtt_real sp2, s11, s12, s22, det, d2;
#if MTT_WITH_MEAS_COV
        const mtt_real *R = mtt_meas_r(trk, a); /* the first detection's own (§3.1) */
#else
        const mtt_real *R = trk->R;
#endif
        if (!(f > MTT_R(0.0))) {
            return 0;
        }
        sp2 = f * f / trk->gamma;
        s11 = sp2 + R[0];
        s12 = R[1];
        s22 = sp2 + R[2];
        det = s11 * s22 - s12 * s12;
        d2 = (s22 * dx * dx - MTT_R(2.0) * s12 * dx * dy + s11 * dy * dy) / det;
        return d2 <= trk->gamma;
    }
#endif
    /* A detection without amplitude falls back to the vmax circle. */
    return IN_CIRCLE(dx, dy, MTT_MUL_T(dt, trk->par.vmax));
}

/* Largest |dx| any pair gate can accept this frame: vmax dT for the circle;
 * for the intensity gate the x-extent of d' S0^-1 d <= gamma, which is
 * sqrt(gamma (sigma_P^2 + R_xx)) = sqrt(f^2 + gamma R_xx). */
static mtt_real reach_x(const mtt_tracker *trk, mtt_real dt)
{
    mtt_real r = MTT_MUL_T(dt, trk->par.vmax);
#ifndef MTT_REAL_FIXED
    uint16_t a;
#endif
    if (trk->par.init_gate != MTT_INIT_GATE_INTENSITY) {
        return r;
    }
#ifndef MTT_REAL_FIXED
    for (a = 0; a < trk->n_prev; ++a) {
        if (trk->prev[a].has_amp) {
            mtt_real f = mtt_init_intensity_f(&trk->par, trk->prev[a].amp);
#if MTT_WITH_MEAS_COV
            mtt_real ra = mtt_sqrt(f * f + trk->gamma * mtt_meas_r(trk, &trk->prev[a])[0]);
#else
            mtt_real ra = mtt_sqrt(f * f + trk->gamma * trk->R[0]);
#endif
            r = (ra > r) ? ra : r;
        }
    }
#endif
    return r;
}

/* A birth needs a finite state and a positive definite covariance: with an
 * extreme frame interval R/dt^2 underflows to 0 (huge dt, tiny sigma) or
 * the velocity overflows (tiny dt), and such a track would report a
 * singular or infinite P until the next frame deletes it (ALGORITHMS.md §3).  Not
 * counted: no track was possible. */
static int birth_ok(const mtt_state x, mtt_cov P)
{
    const mtt_state zero = {MTT_ZERO};
    mtt_d2 d2;
    return mtt_state_finite(x) && mtt_chol_quad(P, zero, &d2) == 0;
}

void mtt_initiate_frame(mtt_tracker *trk, mtt_real dt)
{
    /* The arrays once in locals: Thumb-1 loads a large field offset from a
     * literal at every use (a firmware's .text). */
    mtt_mstore *const meas = trk->meas, *const prev = trk->prev;
    uint16_t j, k;
    if (trk->par.initiate && dt > MTT_ZERO && trk->n_prev > 0u) {
        /* U_k and U_k-1 are stored in the canonical order, sorted by x
         * (measure.c): each z_k scans only the slice of U_k-1 within reach,
         * O((n + pairs) log n) instead of |U_k| x |U_k-1|, and the births
         * come in that order whatever the input's (ALGORITHMS.md §12.1). */
        const mtt_real r = reach_x(trk, dt);
        for (j = 0; j < trk->n_meas; ++j) {
            mtt_mstore *b = &meas[j];
            mtt_pos x_lo, x_hi; /* the slice within reach */
            uint16_t lo = 0, hi = trk->n_prev;
            int started = 0;
            if (b->used) {
                continue;
            }
            x_lo = MTT_SUBS(b->x, r);
            x_hi = MTT_ADDS(b->x, r);
            while (lo < hi) {
                uint16_t mid = (uint16_t)(lo + (hi - lo) / 2u);
                if (prev[mid].x < x_lo) {
                    lo = (uint16_t)(mid + 1u);
                } else {
                    hi = mid;
                }
            }
            for (k = lo; k < trk->n_prev && prev[k].x <= x_hi; ++k) {
                const mtt_mstore *pa = &prev[k];
                mtt_state x;
                mtt_cov P;
                if (!mtt_init_pair_ok(trk, pa, b, dt)) {
                    continue;
                }
                mtt_motion_birth(pa, b, dt, trk->R, trk->par.vmax, x, P);
#if MTT_WITH_POLAR
                if (b->has_rdot) {
                    /* the radial velocity from b's range rate (ALGORITHMS.md §3.2) */
                    mtt_polar_rdot_update(MTT_STATE_N, trk->par.sensor_xy, b->rr, x, P);
                }
#endif
                if (!birth_ok(x, P)) {
                    continue;
                }
                int ni = mtt_track_append(trk, x, P, trk->par.existence_init, 0, 1);
                if (ni < 0) {
                    trk->stats.last.births_dropped++;
                } else {
#if MTT_WITH_IMM
                    if (trk->par.motion == MTT_MOTION_IMM) {
                        mtt_imm_seed_track(trk, (uint16_t)ni, dt);
                    }
#endif
                    trk->stats.last.births++;
                    started = 1;
                }
            }
            if (started) {
                b->used = 1; /* it started a track: not in U_k-1 next frame */
            }
        }
    }
    /* Store U_k for the next frame, in the same order. */
    trk->n_prev = 0;
    for (j = 0; j < trk->n_meas; ++j) {
        if (!meas[j].used) {
            prev[trk->n_prev++] = meas[j];
        }
    }
}

mtt_status mtt_init_two_point_cov(mtt_real sx, mtt_real sy, mtt_real dt, mtt_real P[4][4])
{
    mtt_real R[3];
    if (P == NULL) {
        return MTT_ERR_NULL;
    }
    if (!(sx > MTT_ZERO) || !(sy > MTT_ZERO) || !(dt > MTT_ZERO) ||
        !mtt_isfinite(sx) || !mtt_isfinite(sy) || !mtt_isfinite(dt)) {
        return MTT_ERR_VALUE;
    }
    R[0] = MTT_VAR_OF(sx);
    R[1] = MTT_ZERO;
    R[2] = MTT_VAR_OF(sy);
#if MTT_MAX_STATE == 4 && !defined(MTT_REAL_FIXED)
    mtt_motion_two_point_cov(R, dt, P); /* mtt_cov is mtt_real[4][4] */
#else
    {
        /* the CV part; fixed point: from the block to the variance format */
        mtt_cov Pm;
        mtt_motion_two_point_cov(R, dt, Pm);
        mtt_cov_view4(Pm, P);
    }
#endif
    return MTT_OK;
}
