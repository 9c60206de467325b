/* ipda.c - IPDA association probabilities (spec 6).
 *
 * Lambda = sum_j p_j / lambda_j, L = 1 - PD PG + PD PG Lambda,
 * beta_j = PD PG (p_j / lambda_j) / L, beta_0 = (1 - PD PG) / L.
 * With lambda_j the LM density lambda~ this is LM-IPDA (spec 8.1). */
#include "mtt_internal.h"

void mtt_ipda_betas(mtt_real pd, mtt_real pg, const mtt_real *p, const mtt_real *lam,
                    uint16_t m, mtt_real *beta, mtt_real *beta0, mtt_real *L)
{
    const mtt_real pdpg = pd * pg;
    mtt_real big = MTT_R(0.0), l;
    uint16_t j;
    for (j = 0; j < m; ++j) {
        big += p[j] / lam[j];
    }
    l = MTT_R(1.0) - pdpg + pdpg * big;
    for (j = 0; j < m; ++j) {
        beta[j] = pdpg * (p[j] / lam[j]) / l;
    }
    *beta0 = (MTT_R(1.0) - pdpg) / l;
    *L = l;
}
