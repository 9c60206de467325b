/* ipda.c - IPDA association probabilities and the IPDA row of a track
 * (ALGORITHMS.md §6); the association of the ipda and lm-ipda modes.
 *
 * Lambda = sum_j p_j / lambda_j, L = 1 - PD PG + PD PG Lambda,
 * beta_j = PD PG (p_j / lambda_j) / L, beta_0 = (1 - PD PG) / L.
 * With lambda_j the LM density lambda~ this is LM-IPDA (ALGORITHMS.md §8.1). */
#include "mtt_internal.h"

void mtt_ipda_betas(mtt_real pd, mtt_real pg, mtt_pair *pp, uint16_t m, mtt_real *beta0, mtt_real *L)
{
    const mtt_real pdpg = pd * pg;
    mtt_real big = MTT_R(0.0), l;
    uint16_t j;
    for (j = 0; j < m; ++j) {
        big += pp[j].p / pp[j].lam;
    }
    l = MTT_R(1.0) - pdpg + pdpg * big;
    for (j = 0; j < m; ++j) {
        pp[j].beta = pdpg * (pp[j].p / pp[j].lam) / l;
    }
    *beta0 = (MTT_R(1.0) - pdpg) / l;
    *L = l;
}

void mtt_ipda_track(mtt_tracker *trk, uint16_t ti)
{
    mtt_track_frame *tf = &trk->tf[ti];
    mtt_real L;
    mtt_ipda_betas(trk->par.pd, trk->par.pg, &trk->pairs[tf->pair_first], tf->pair_count, &tf->beta0, &L);
    tf->ex_post = mtt_existence_update(tf->ex_pred, L);
}

void mtt_ipda_frame(mtt_tracker *trk)
{
    uint16_t i;
    /* An empty gate needs no row: the update keeps the prediction with
     * L = 1 - PD PG (ALGORITHMS.md §6, m = 0). */
    for (i = 0; i < trk->n_tracks; ++i) {
        if (trk->tf[i].valid && trk->tf[i].pair_count > 0u) {
            mtt_ipda_track(trk, i);
        }
    }
}
