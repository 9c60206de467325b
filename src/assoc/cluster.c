/* SPDX-License-Identifier: BSD-3-Clause */
/* cluster.c - clusters: connected components of the track-measurement
 * gating graph (ALGORITHMS.md §9), by union-find.
 *
 * Union by smallest index keeps every root the cluster's smallest track,
 * which gives the deterministic order of ALGORITHMS.md §9 for free: clusters by their
 * smallest track, tracks ascending inside.  Tracks with an empty gate are
 * singleton clusters; numerically invalid tracks get no cluster. */
#include "mtt_internal.h"

static uint16_t find_root(uint16_t *uf, uint16_t i)
{
    /* Path halving; each step moves closer to the root (at most n steps). */
    while (uf[i] != i) {
        uf[i] = uf[uf[i]];
        i = uf[i];
    }
    return i;
}

void mtt_cluster_frame(mtt_tracker *trk)
{
    /* The arrays once in locals: each trk-> field lies at a large offset,
     * which Thumb-1 loads from a literal at every use (a firmware's .text). */
    uint16_t *const uf = trk->uf, *const first = trk->cl_first;
    mtt_track_frame *const tfs = trk->tf;
    const mtt_pair *const pairs = trk->pairs;
    const uint16_t *const mp_first = trk->mp_first, *const mp_list = trk->mp_list;
    const uint16_t nt = trk->n_tracks;
    uint16_t i, k, nc = 0, biggest = 0;

    for (i = 0; i < nt; ++i) {
        uf[i] = i;
        first[i] = 0;
    }
    first[nt] = 0;
    for (i = 0; i < trk->n_meas; ++i) {
        const uint16_t f = mp_first[i], end = mp_first[i + 1u];
        for (k = (uint16_t)(f + 1u); k < end; ++k) {
            uint16_t ra = find_root(uf, pairs[mp_list[f]].track);
            uint16_t rb = find_root(uf, pairs[mp_list[k]].track);
            if (ra < rb) {
                uf[rb] = ra;
            } else if (rb < ra) {
                uf[ra] = rb;
            }
        }
    }
    for (i = 0; i < nt; ++i) {
        mtt_track_frame *tf = &tfs[i];
        uint16_t r;
        if (!tf->valid) {
            tf->cluster = MTT_NONE16;
            continue;
        }
        r = find_root(uf, i);
        tf->cluster = (r == i) ? nc++ : tfs[r].cluster;
        first[tf->cluster + 1u]++;
    }
    for (i = 0; i < nc; ++i) {
        const uint16_t size = first[i + 1u];
        first[i + 1u] = (uint16_t)(size + first[i]);
        if (size > biggest) {
            biggest = size;
        }
    }
    /* Fill with first[c] as the cursor of c, then shift back (as in gate.c). */
    for (i = 0; i < nt; ++i) {
        uint16_t c = tfs[i].cluster;
        if (c != MTT_NONE16) {
            trk->cl_list[first[c]] = i;
            first[c]++;
        }
    }
    mtt_csr_unshift(first, nc);
    trk->n_clusters = nc;
    trk->stats.last.clusters = nc;
    trk->stats.max_cluster_tracks = biggest;
}
