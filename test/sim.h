/* SPDX-License-Identifier: BSD-3-Clause */
/* sim.h - deterministic scene simulation for the end-to-end tests:
 * a fixed 64-bit generator (splitmix64), uniform and Gaussian draws.
 * Host test code: double precision is fine here. */
#ifndef MTT_TEST_SIM_H
#define MTT_TEST_SIM_H

#include <math.h>
#include <stdint.h>

#include "mtt/mtt.h"

typedef struct { uint64_t s; } sim_rng;

static inline uint64_t sim_next(sim_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in (0, 1). */
static inline double sim_unif(sim_rng *r)
{
    return ((double)(sim_next(r) >> 11) + 0.5) / 9007199254740992.0;
}

static inline double sim_gauss(sim_rng *r)
{
    double u1 = sim_unif(r), u2 = sim_unif(r);
    return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}

/* Poisson by inversion (small means only). */
static inline int sim_poisson(sim_rng *r, double mean)
{
    double L = exp(-mean), p = 1.0;
    int k = 0;
    do {
        ++k;
        p *= sim_unif(r);
    } while (p > L && k < 10000);
    return k - 1;
}


/* One detection. */
static inline mtt_meas sim_meas(mtt_real x, mtt_real y, mtt_real a, int has)
{
    mtt_meas m;
    m.x = x;
    m.y = y;
    m.amplitude = a;
    m.has_amplitude = has;
    return m;
}

#ifndef MTT_REAL_FIXED /* NaN and Inf: float and double (fixed: out of range, below) */
/* Seven detections: five bad ones (NaN x, Inf y, negative, NaN and Inf
 * amplitude) and good ones at input indices 4 and 5 (the second without
 * amplitude, its negative value ignored). */
static inline void sim_bad_mix(mtt_meas m[7])
{
    volatile mtt_real zero = MTT_R(0.0);
    m[0] = sim_meas(zero / zero, MTT_R(1.0), MTT_R(1.0), 1);
    m[1] = sim_meas(MTT_R(1.0), MTT_R(1.0) / zero, MTT_R(1.0), 1);
    m[2] = sim_meas(MTT_R(5.0), MTT_R(5.0), MTT_R(-1.0), 1);
    m[3] = sim_meas(MTT_R(5.0), MTT_R(5.0), zero / zero, 1);
    m[4] = sim_meas(MTT_R(10.0), MTT_R(20.0), MTT_R(2.0), 1);
    m[5] = sim_meas(MTT_R(5.0), MTT_R(5.0), MTT_R(-1.0), 0);
    m[6] = sim_meas(MTT_R(5.0), MTT_R(5.0), MTT_R(1.0) / zero, 1);
}
#else
/* The same seven in the fixed-point build: saturated or out-of-range
 * values in place of NaN and Inf (measure.c, docs/FIXED_POINT.md §3). */
static inline void sim_bad_mix(mtt_meas m[7])
{
    m[0] = sim_meas(MTT_FX_MAX, MTT_POS(1.0), MTT_AMP(1.0), 1);
    m[1] = sim_meas(MTT_POS(1.0), -MTT_FX_POS_LIMIT - 1, MTT_AMP(1.0), 1);
    m[2] = sim_meas(MTT_POS(5.0), MTT_POS(5.0), MTT_AMP(-1.0), 1);
    m[3] = sim_meas(MTT_POS(5.0), MTT_POS(5.0), MTT_FX_MIN, 1);
    m[4] = sim_meas(MTT_POS(10.0), MTT_POS(20.0), MTT_AMP(2.0), 1);
    m[5] = sim_meas(MTT_POS(5.0), MTT_POS(5.0), MTT_AMP(-1.0), 0);
    m[6] = sim_meas(MTT_POS(5.0), MTT_POS(5.0), MTT_FX_MAX, 1);
}
#endif

/* n detections with amplitudes i * 7 mod n, a permutation of 0..n-1 when n
 * is not a multiple of 7: the inputs with amplitude >= n - keep are the
 * strongest keep. */
static inline void sim_amplitude_permutation(mtt_meas *m, uint32_t n)
{
    uint32_t i;
    for (i = 0; i < n; ++i) {
        m[i] = sim_meas((mtt_real)(i % 97u) * MTT_POS(10.0), (mtt_real)(i / 97u) * MTT_POS(10.0),
                        (mtt_real)((i * 7u) % n) * MTT_AMP(1.0), 1);
    }
}

#endif
