/* SPDX-License-Identifier: BSD-3-Clause */
/* amplitude.c - the amplitude likelihood ratio of lm-ihpda's contest
 * variant and its IHPDA row (ALGORITHMS.md §7.6).
 *
 * g_j = exp(a_j rho/(1+rho))/(1+rho), the ratio of the target's amplitude
 * law to the background's for an SNR rho, mixed with the background at
 * weight eta: g/(1 - eta + eta g).  The clutter stage multiplies every
 * pair's p_j by it (lm_clutter.c), so the LM densities, the rows and the
 * existence see it; the row then uses g_j in place of the ranks:
 * A_j = PD PG p_j g_j / lambda_j (p_j already holds g_j),
 * C_j = 1 - PD PG + PD PG (sum_{i != j} g_i) / (lambda_j V_G),
 * L_j = A_j + C_j, beta_j = A_j / L_j (the IHPDA row of ihpda.c).
 * Built with MTT_WITH_CONTEST (not in the fixed-point build, whose
 * library holds this directory as an empty file). */
#include "mtt_internal.h"

#if MTT_WITH_CONTEST

mtt_real mtt_amp_ratio(mtt_real rho, mtt_real eta, mtt_real a)
{
    mtt_real e = a * rho / (MTT_R(1.0) + rho), g;
    if (!(e < MTT_R(30.0))) {
        e = MTT_R(30.0); /* g < 1.1e13: p g / lambda stays finite */
    }
    g = mtt_exp(e) / (MTT_R(1.0) + rho);
    return g / (MTT_R(1.0) - eta + eta * g);
}

void mtt_contest_amp_betas(mtt_real pdpg, mtt_real vg, const mtt_cand *c, uint16_t m,
                           mtt_real *beta, mtt_real *L)
{
    mtt_real G = MTT_R(0.0);
    uint16_t i;
    for (i = 0; i < m; ++i) {
        G += c[i].amp;
    }
    for (i = 0; i < m; ++i) {
        mtt_real others = G - c[i].amp, A;
        if (others < MTT_R(0.0)) {
            others = MTT_R(0.0); /* rounding of G - g_i */
        }
        A = pdpg * c[i].p / c[i].lam;
        L[i] = A + MTT_R(1.0) - pdpg + pdpg * others / (c[i].lam * vg);
        beta[i] = A / L[i];
    }
}

#else
typedef int mtt_amplitude_unused; /* ISO C: no empty translation unit */
#endif /* MTT_WITH_CONTEST */
