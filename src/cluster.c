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
    uint16_t i, k, nc = 0, biggest = 0;

    for (i = 0; i < trk->n_tracks; ++i) {
        trk->uf[i] = i;
    }
    for (i = 0; i < trk->n_meas; ++i) {
        uint16_t first = trk->mp_first[i], end = trk->mp_first[i + 1u];
        if (end - first < 2) {
            continue;
        }
        for (k = (uint16_t)(first + 1u); k < end; ++k) {
            uint16_t ra = find_root(trk->uf, trk->pairs[trk->mp_list[first]].track);
            uint16_t rb = find_root(trk->uf, trk->pairs[trk->mp_list[k]].track);
            if (ra < rb) {
                trk->uf[rb] = ra;
            } else if (rb < ra) {
                trk->uf[ra] = rb;
            }
        }
    }
    for (i = 0; i <= trk->n_tracks; ++i) {
        trk->cl_first[i] = 0;
    }
    for (i = 0; i < trk->n_tracks; ++i) {
        mtt_track_frame *tf = &trk->tf[i];
        uint16_t r;
        if (!tf->valid) {
            tf->cluster = MTT_NONE16;
            continue;
        }
        r = find_root(trk->uf, i);
        tf->cluster = (r == i) ? nc++ : trk->tf[r].cluster;
        trk->cl_first[tf->cluster + 1u]++;
    }
    for (i = 0; i < nc; ++i) {
        trk->cl_first[i + 1u] = (uint16_t)(trk->cl_first[i + 1u] + trk->cl_first[i]);
        if (trk->cl_first[i + 1u] - trk->cl_first[i] > biggest) {
            biggest = (uint16_t)(trk->cl_first[i + 1u] - trk->cl_first[i]);
        }
    }
    /* Fill with cl_first[c] as the cursor of c, then shift back (as in gate.c). */
    for (i = 0; i < trk->n_tracks; ++i) {
        uint16_t c = trk->tf[i].cluster;
        if (c != MTT_NONE16) {
            trk->cl_list[trk->cl_first[c]] = i;
            trk->cl_first[c]++;
        }
    }
    mtt_csr_unshift(trk->cl_first, nc);
    trk->n_clusters = nc;
    trk->stats.last.clusters = nc;
    trk->stats.max_cluster_tracks = biggest;
}
