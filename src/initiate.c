/* initiate.c - two-point differencing initiation (spec 12.1) with the
 * velocity gate |z_k - z_k-1| <= vmax dT, or the intensity-based gate of
 * seed 002 (spec 12.2): sigma_P = f(I)/sqrt(gamma), accept when
 * d' (sigma_P^2 I + R)^-1 d <= gamma.
 *
 * U_k = measurements of frame k not used by any track; U_k-1 = the same of
 * the previous frame minus those that already started a track.  Every
 * accepted pair starts one tentative track (merging removes duplicates). */
#include "mtt_internal.h"

mtt_real mtt_init_intensity_f(const mtt_params *p, mtt_real I)
{
    const mtt_real *f1 = p->intensity_f1, *f2 = p->intensity_f2;
    const mtt_real lo = p->intensity_blend[0], hi = p->intensity_blend[1];
    mtt_real v1, v2, w1;
    if (!(I > MTT_R(0.0))) {
        I = MTT_R(0.0);
    }
    /* f2 is a downward parabola: clamp I at its peak so f never decreases
     * (seed 002's f2 turns negative above I = 2341; spec 12.2 guards). */
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

void mtt_two_point_cov(const mtt_real R[3], mtt_real dt, mtt_real P[4][4])
{
    const mtt_real r[2][2] = {{R[0], R[1]}, {R[1], R[2]}};
    int i, j;
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            P[i][j] = r[i][j];
            P[i][j + 2] = r[i][j] / dt;
            P[i + 2][j] = r[i][j] / dt;
            P[i + 2][j + 2] = MTT_R(2.0) * r[i][j] / (dt * dt);
        }
    }
}

int mtt_init_pair_ok(const mtt_tracker *trk, const mtt_mstore *a, const mtt_mstore *b, mtt_real dt)
{
    const mtt_real dx = b->x - a->x, dy = b->y - a->y;
    if (trk->par.init_gate == MTT_INIT_GATE_INTENSITY && a->has_amp) {
        mtt_real f = mtt_init_intensity_f(&trk->par, a->amp);
        mtt_real sp2, s11, s12, s22, det, d2;
        if (!(f > MTT_R(0.0))) {
            return 0;
        }
        sp2 = f * f / trk->gamma;
        s11 = sp2 + trk->R[0];
        s12 = trk->R[1];
        s22 = sp2 + trk->R[2];
        det = s11 * s22 - s12 * s12;
        d2 = (s22 * dx * dx - MTT_R(2.0) * s12 * dx * dy + s11 * dy * dy) / det;
        return d2 <= trk->gamma;
    }
    /* A detection without amplitude falls back to the vmax circle. */
    return dx * dx + dy * dy <= (trk->par.vmax * dt) * (trk->par.vmax * dt);
}

void mtt_initiate_frame(mtt_tracker *trk, mtt_real dt)
{
    uint16_t j, a;
    if (trk->par.initiate && dt > MTT_R(0.0)) {
        for (j = 0; j < trk->n_meas; ++j) {
            mtt_mstore *b = &trk->meas[j];
            int started = 0;
            if (b->used) {
                continue;
            }
            for (a = 0; a < trk->n_prev; ++a) {
                const mtt_mstore *pa = &trk->prev[a];
                mtt_real x[4], P[4][4];
                if (!mtt_init_pair_ok(trk, pa, b, dt)) {
                    continue;
                }
                x[0] = b->x;
                x[1] = b->y;
                x[2] = (b->x - pa->x) / dt;
                x[3] = (b->y - pa->y) / dt;
                mtt_two_point_cov(trk->R, dt, P);
                if (mtt_track_append(trk, x, P, trk->par.existence_init, 0, 1) < 0) {
                    trk->stats.last.births_dropped++;
                } else {
                    trk->stats.last.births++;
                    started = 1;
                }
            }
            if (started) {
                b->used = 1; /* it started a track: not in U_k-1 next frame */
            }
        }
    }
    trk->n_prev = 0;
    for (j = 0; j < trk->n_meas; ++j) {
        if (!trk->meas[j].used) {
            trk->prev[trk->n_prev++] = trk->meas[j];
        }
    }
}
