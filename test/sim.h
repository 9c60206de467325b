/* sim.h - deterministic scene simulation for the end-to-end tests:
 * a fixed 64-bit generator (splitmix64), uniform and Gaussian draws.
 * Host test code: double precision is fine here. */
#ifndef MTT_TEST_SIM_H
#define MTT_TEST_SIM_H

#include <math.h>
#include <stdint.h>

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


#endif
