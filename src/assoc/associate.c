/* SPDX-License-Identifier: BSD-3-Clause */
/* associate.c - the association stage of every mode, driven by one mode
 * table (ALGORITHMS.md §15.1; the modes' algorithms in §6, §7, §8, §10,
 * §13).
 *
 * Per frame: clusters (§9), then the mode's association, which writes for
 * every valid track what the update stage reads: the assigned / selected
 * pair with its beta and L (update kind ONE), the beta row, beta_0 and the
 * updated existence (PDA), or the assigned pair and the existence (HARD).
 * PDA modes use every gated measurement, so those are marked used here
 * (§15.1); the other modes mark the assigned ones while assigning (the
 * update stage marks those claimed by contested lm-ihpda tracks, §10.4).  The
 * table also gives the names of docs/FORMATS.md `association`. */
#include "mtt_internal.h"

#include "core/params_table.h" /* MTT_ASSOC_ROWS, mtt_assoc_names */

/* The association routines a row names (MTT_ASSOCIATE_*): called by a
 * switch, not through pointers, so every call is direct (the firmware's
 * stack analysis sees every edge; no table of code addresses). */

#if MTT_WITH_BASELINES

/* Exact betas of cluster c, or the counted fallback to Cheap JPDA (§13.1 CHOICE). */
static void exact_or_cheap(mtt_tracker *trk, uint16_t c, int kind)
{
    if (mtt_jpda_exact(trk, c, kind) != 0) {
        trk->stats.last.jpda_fallbacks++;
        mtt_cheap_jpda(trk, c, 1);
    }
}

/* Cluster c of a JPDA-family mode (§13.1 to §13.7). */
static void jpda_cluster(mtt_tracker *trk, uint16_t c, uint8_t how)
{
    switch (how) {
    case MTT_ASSOCIATE_JIPDA:
        if (mtt_jpda_exact(trk, c, MTT_JPDA_JIPDA) != 0) {
            /* Over the bounds: the per-track IPDA betas written by
             * mtt_ipda_frame stay (§13.2). */
            trk->stats.last.jpda_fallbacks++;
        }
        break;
    case MTT_ASSOCIATE_CHEAP_JPDA:
        mtt_cheap_jpda(trk, c, 1);
        break;
    case MTT_ASSOCIATE_SUBOPT_JPDA:
        mtt_subopt_jpda(trk, c, !trk->par.subopt_jpda_constant_b); /* §13.4: B_t or [S1]'s B */
        break;
    case MTT_ASSOCIATE_JPDA_STAR:
    case MTT_ASSOCIATE_ADAPTIVE_JPDA_STAR: /* the gates were shrunk before gating (§13.7) */
        exact_or_cheap(trk, c, MTT_JPDA_STAR);
        break;
    default: /* exact JPDA (jpda, jpda-vg); NNJPDA and adaptive JPDA post-process it */
        exact_or_cheap(trk, c, MTT_JPDA_EXACT);
        if (how == MTT_ASSOCIATE_NNJPDA || how == MTT_ASSOCIATE_ADAPTIVE_NNJPDA) {
            mtt_nnjpda_cluster(trk, c);
        } else if (how == MTT_ASSOCIATE_ADAPTIVE_JPDA) {
            mtt_adaptive_share(trk, c);
        }
        break;
    }
}

/* The JPDA family (§13): A and B of every pair and track, the IPDA row of
 * every track (its existence is §13.2's CHOICE for all but jipda, and the
 * jipda fallback's betas), then each cluster. */
static void jpda_family(mtt_tracker *trk, uint8_t how)
{
    uint16_t c;
    mtt_jpda_weights(trk);
    mtt_ipda_frame(trk);
    for (c = 0; c < trk->n_clusters; ++c) {
        const uint16_t t0 = trk->cl_list[trk->cl_first[c]];
        if (trk->cl_first[c + 1u] - trk->cl_first[c] == 1 && trk->tf[t0].pair_count == 0u) {
            trk->tf[t0].beta0 = MTT_P(1.0); /* empty gate: m = 0 update */
            continue;
        }
        jpda_cluster(trk, c, how);
    }
}

#endif /* MTT_WITH_BASELINES */

#define ONE MTT_UPDATE_ONE
#define PDA MTT_UPDATE_PDA
#define HARD MTT_UPDATE_HARD

/* The names of docs/FORMATS.md `association`, in mtt_assoc order: row k of
 * mtt_modes is named mtt_assoc_names[k] (an array of its own, because the
 * parameter table of params_table.h lists it as the key's spellings). */
const char *const mtt_assoc_names[MTT_ASSOC_ROWS] = {
    "lm-ihpda", "ihpda", "lm-ipda", "ipda", "ihpda-2d", "jipda",
    "jpda", "cheap-jpda", "suboptimal-jpda", "nnjpda", "jpda-star", "adaptive-jpda",
#if MTT_WITH_BASELINES
    "lm-ipda-all", "jpda-vg", "adaptive-nnjpda", "adaptive-jpda-star",
#endif
};

/* One row per mode, in mtt_assoc order: association routine, LM
 * densities (2: over all tracks, §8.3), update kind, baseline, IMM (ALGORITHMS.md §14.2: the modes whose
 * event likelihoods are linear in each track's detection factors: all but
 * the 2-D assignment and lm-ipda-all's untruncated single-model terms). */
const mtt_mode mtt_modes[MTT_ASSOC_ROWS] = {
    {MTT_ASSOCIATE_MMR, 1, ONE, 0, 1},
    {MTT_ASSOCIATE_SELECT, 0, ONE, 0, 1},
    {MTT_ASSOCIATE_IPDA, 1, PDA, 0, 1},
    {MTT_ASSOCIATE_IPDA, 0, PDA, 0, 1},
    {MTT_ASSOCIATE_ASSIGN_2D, 0, ONE, 1, 0},
    {MTT_ASSOCIATE_JIPDA, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_JPDA, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_CHEAP_JPDA, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_SUBOPT_JPDA, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_NNJPDA, 0, HARD, 1, 1},
    {MTT_ASSOCIATE_JPDA_STAR, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_ADAPTIVE_JPDA, 0, PDA, 1, 1},
#if MTT_WITH_BASELINES
    {MTT_ASSOCIATE_IPDA, 2, PDA, 1, 0}, /* lm-ipda-all (§8.3) */
    {MTT_ASSOCIATE_JPDA_VG, 0, PDA, 1, 1},
    {MTT_ASSOCIATE_ADAPTIVE_NNJPDA, 0, HARD, 1, 1},
    {MTT_ASSOCIATE_ADAPTIVE_JPDA_STAR, 0, PDA, 1, 1},
#endif
};

void mtt_associate_frame(mtt_tracker *trk)
{
    const mtt_mode *md = &mtt_modes[trk->par.association];
    uint16_t k;
    mtt_cluster_frame(trk);
    switch (md->associate) {
    case MTT_ASSOCIATE_MMR: /* lm-ihpda: MMR with recomputation, final rows (§10.1, §10.3) */
        for (k = 0; k < trk->n_clusters; ++k) {
            mtt_mmr_cluster(trk, k, 1);
        }
#if MTT_WITH_CONTEST
        if (MTT_CONTEST_ON(trk)) {
            mtt_contest_frame(trk); /* lm_ihpda_variant contest (§10.4) */
        }
#endif
        mtt_ihpda_final_frame(trk);
        break;
    case MTT_ASSOCIATE_SELECT: /* ihpda (§7.4) */
        mtt_ihpda_select_frame(trk);
        break;
    case MTT_ASSOCIATE_IPDA: /* ipda, lm-ipda, lm-ipda-all (§6, §8) */
        mtt_ipda_frame(trk);
        break;
#if MTT_WITH_BASELINES
    case MTT_ASSOCIATE_ASSIGN_2D: /* ihpda-2d (§10.2, §10.3) */
        mtt_assign2d_frame(trk);
        mtt_ihpda_final_frame(trk);
        break;
    default: /* the JPDA family (§13) */
        jpda_family(trk, md->associate);
        break;
#else
    default: /* not built: refused by mtt_params_check */
        break;
#endif
    }
    if (md->update == MTT_UPDATE_PDA) {
        for (k = 0; k < trk->n_pairs; ++k) {
            trk->meas[trk->pairs[k].meas].used = 1;
        }
    }
}

mtt_status mtt_assoc_name(mtt_assoc a, const char **name)
{
    if (name == NULL) {
        return MTT_ERR_NULL;
    }
    if ((int)a < 0 || (int)a >= MTT_ASSOC_ROWS) {
        return MTT_ERR_RANGE;
    }
    *name = mtt_assoc_names[a];
    return MTT_OK;
}

/* strcmp(a, b) == 0 without libc's strcmp (0.7 KiB on newlib); the names
 * are short (at most 18 characters, 15 without the baselines), so at most
 * 20 (16) characters are compared. */
static int same_text(const char *a, const char *b)
{
    int i;
    for (i = 0; i < (MTT_WITH_BASELINES ? 20 : 16); ++i) {
        if (a[i] != b[i]) {
            return 0;
        }
        if (a[i] == '\0') {
            return 1;
        }
    }
    return 0;
}

mtt_status mtt_assoc_parse(const char *name, mtt_assoc *a)
{
    int k;
    if (name == NULL || a == NULL) {
        return MTT_ERR_NULL;
    }
    for (k = 0; k < MTT_ASSOC_ROWS; ++k) {
        if (same_text(name, mtt_assoc_names[k])) {
            *a = (mtt_assoc)k;
            return MTT_OK;
        }
    }
    return MTT_ERR_RANGE;
}
