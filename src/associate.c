/* associate.c - the association stage of every mode, driven by one mode
 * table (ALGORITHMS.md §15.1; the modes' algorithms in §6, §7, §8, §10,
 * §13).
 *
 * Per frame: clusters (§9), then the mode's association, which writes for
 * every valid track what the update stage reads: the assigned / selected
 * pair with its beta and L (update kind ONE), the beta row, beta_0 and the
 * updated existence (PDA), or the assigned pair and the existence (HARD).
 * PDA modes use every gated measurement, so those are marked used here
 * (§15.1); the other modes mark the assigned ones while assigning.  The
 * table also gives the names of docs/FORMATS.md `association`. */
#include "mtt_internal.h"

#if MTT_WITH_BASELINES
#define BASELINE(fn) fn
#else
#define BASELINE(fn) NULL /* not built: mtt_params_check reports MTT_ERR_UNSUPPORTED */
#endif

static void assoc_lm_ihpda(mtt_tracker *trk)
{
    uint16_t c;
    for (c = 0; c < trk->n_clusters; ++c) {
        mtt_mmr_cluster(trk, c, 1);
    }
    mtt_ihpda_final_frame(trk);
}

#if MTT_WITH_BASELINES

static void assoc_ihpda_2d(mtt_tracker *trk)
{
    mtt_assign2d_frame(trk);
    mtt_ihpda_final_frame(trk);
}

/* Exact betas of cluster c, or the counted fallback to Cheap JPDA (§13.1 CHOICE). */
static void exact_or_cheap(mtt_tracker *trk, uint16_t c, int kind)
{
    if (mtt_jpda_exact(trk, c, kind) != 0) {
        trk->stats.last.jpda_fallbacks++;
        mtt_cheap_jpda(trk, c, 1);
    }
}

static void jipda_cluster(mtt_tracker *trk, uint16_t c)
{
    if (mtt_jpda_exact(trk, c, MTT_JPDA_JIPDA) != 0) {
        /* Over the bounds: the per-track IPDA betas written by
         * mtt_ipda_frame stay (§13.2). */
        trk->stats.last.jpda_fallbacks++;
    }
}

static void jpda_cluster(mtt_tracker *trk, uint16_t c)
{
    exact_or_cheap(trk, c, MTT_JPDA_EXACT);
}

static void cheap_cluster(mtt_tracker *trk, uint16_t c)
{
    mtt_cheap_jpda(trk, c, 1);
}

static void subopt_cluster(mtt_tracker *trk, uint16_t c)
{
    mtt_subopt_jpda(trk, c, 1);
}

static void nnjpda_cluster(mtt_tracker *trk, uint16_t c)
{
    exact_or_cheap(trk, c, MTT_JPDA_EXACT);
    mtt_nnjpda_cluster(trk, c);
}

static void star_cluster(mtt_tracker *trk, uint16_t c)
{
    exact_or_cheap(trk, c, MTT_JPDA_STAR);
}

static void adaptive_cluster(mtt_tracker *trk, uint16_t c)
{
    exact_or_cheap(trk, c, MTT_JPDA_EXACT);
    mtt_adaptive_split(trk, c);
}

/* The JPDA family (§13): A and B of every pair and track, the IPDA row of
 * every track (its existence is §13.2's CHOICE for all but jipda, and the
 * jipda fallback's betas), then each cluster. */
static void jpda_family(mtt_tracker *trk, void (*cluster)(mtt_tracker *, uint16_t))
{
    uint16_t c;
    mtt_jpda_weights(trk);
    mtt_ipda_frame(trk);
    for (c = 0; c < trk->n_clusters; ++c) {
        const uint16_t t0 = trk->cl_list[trk->cl_first[c]];
        if (trk->cl_first[c + 1u] - trk->cl_first[c] == 1 && trk->tf[t0].pair_count == 0u) {
            trk->tf[t0].beta0 = MTT_R(1.0); /* empty gate: m = 0 update */
            continue;
        }
        cluster(trk, c);
    }
}

static void assoc_jipda(mtt_tracker *trk) { jpda_family(trk, jipda_cluster); }
static void assoc_jpda(mtt_tracker *trk) { jpda_family(trk, jpda_cluster); }
static void assoc_cheap(mtt_tracker *trk) { jpda_family(trk, cheap_cluster); }
static void assoc_subopt(mtt_tracker *trk) { jpda_family(trk, subopt_cluster); }
static void assoc_nnjpda(mtt_tracker *trk) { jpda_family(trk, nnjpda_cluster); }
static void assoc_star(mtt_tracker *trk) { jpda_family(trk, star_cluster); }
static void assoc_adaptive(mtt_tracker *trk) { jpda_family(trk, adaptive_cluster); }

#endif /* MTT_WITH_BASELINES */

#define ONE MTT_UPDATE_ONE
#define PDA MTT_UPDATE_PDA
#define HARD MTT_UPDATE_HARD

/* One row per mode, in mtt_assoc order:
 *  name (docs/FORMATS.md), associate, LM densities, update kind, baseline,
 *  per-track gates before gating (adaptive JPDA, §13.7). */
const mtt_mode mtt_modes[MTT_ASSOC_COUNT] = {
    {"lm-ihpda", assoc_lm_ihpda, 1, ONE, 0, 0},
    {"ihpda", mtt_ihpda_select_frame, 0, ONE, 0, 0},
    {"lm-ipda", mtt_ipda_frame, 1, PDA, 0, 0},
    {"ipda", mtt_ipda_frame, 0, PDA, 0, 0},
    {"ihpda-2d", BASELINE(assoc_ihpda_2d), 0, ONE, 1, 0},
    {"jipda", BASELINE(assoc_jipda), 0, PDA, 1, 0},
    {"jpda", BASELINE(assoc_jpda), 0, PDA, 1, 0},
    {"cheap-jpda", BASELINE(assoc_cheap), 0, PDA, 1, 0},
    {"suboptimal-jpda", BASELINE(assoc_subopt), 0, PDA, 1, 0},
    {"nnjpda", BASELINE(assoc_nnjpda), 0, HARD, 1, 0},
    {"jpda-star", BASELINE(assoc_star), 0, PDA, 1, 0},
    {"adaptive-jpda", BASELINE(assoc_adaptive), 0, PDA, 1, 1},
};

void mtt_associate_frame(mtt_tracker *trk)
{
    const mtt_mode *md = &mtt_modes[trk->par.association];
    uint16_t k;
    mtt_cluster_frame(trk);
    md->associate(trk);
    if (md->update == MTT_UPDATE_PDA) {
        for (k = 0; k < trk->n_pairs; ++k) {
            trk->meas[trk->pairs[k].meas].used = 1;
        }
    }
}

int mtt_mode_built(mtt_assoc a)
{
    return (int)a >= 0 && (int)a < (int)MTT_ASSOC_COUNT && mtt_modes[a].associate != NULL;
}

mtt_status mtt_assoc_name(mtt_assoc a, const char **name)
{
    if (name == NULL) {
        return MTT_ERR_NULL;
    }
    if ((int)a < 0 || (int)a >= (int)MTT_ASSOC_COUNT) {
        return MTT_ERR_RANGE;
    }
    *name = mtt_modes[a].name;
    return MTT_OK;
}

/* strcmp(a, b) == 0 without libc's strcmp (0.7 KiB on newlib); the names
 * are short, so at most 16 characters are compared. */
static int same_text(const char *a, const char *b)
{
    int i;
    for (i = 0; i < 16; ++i) {
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
    for (k = 0; k < (int)MTT_ASSOC_COUNT; ++k) {
        if (same_text(name, mtt_modes[k].name)) {
            *a = (mtt_assoc)k;
            return MTT_OK;
        }
    }
    return MTT_ERR_RANGE;
}
