/* params.c - parameter defaults (FORMATS.md, seed 000's IR set-up),
 * validation that names the first bad field, and the names of the modes. */
#include <string.h>

#include "mtt_internal.h"

static const char *const assoc_names[MTT_ASSOC_COUNT] = {
    "lm-ihpda", "ihpda", "lm-ipda", "ipda", "ihpda-2d", "jipda",
    "jpda", "cheap-jpda", "suboptimal-jpda", "nnjpda", "jpda-star", "adaptive-jpda"};

mtt_status mtt_params_default(mtt_params *p)
{
    if (p == NULL) {
        return MTT_ERR_NULL;
    }
    memset(p, 0, sizeof *p);
    p->association = MTT_ASSOC_LM_IHPDA;
    p->process_psd = MTT_R(5.0);
    p->meas_sigma[0] = MTT_R(1.0);
    p->meas_sigma[1] = MTT_R(1.0);
    p->pd = MTT_R(0.9);
    p->pg = MTT_R(0.999);
    p->clutter_density = MTT_R(0.0);
    p->snr_rho = MTT_R(0.0);
    p->markov_p11 = MTT_R(0.98);
    p->markov_p21 = MTT_R(0.0);
    p->existence_init = MTT_R(0.1);
    p->confirm_threshold = MTT_R(0.995);
    p->terminate_threshold = MTT_R(0.01);
    p->merge_threshold = MTT_R(1.0);
    p->initiate = 1;
    p->vmax = MTT_R(60.0);
    p->init_gate = MTT_INIT_GATE_VMAX;
    /* seed 002, spec 12.2 */
    p->intensity_f1[0] = MTT_R(-0.0007);
    p->intensity_f1[1] = MTT_R(0.5072);
    p->intensity_f1[2] = MTT_R(39.70);
    p->intensity_f2[0] = MTT_R(-0.0001);
    p->intensity_f2[1] = MTT_R(0.2097);
    p->intensity_f2[2] = MTT_R(57.25);
    p->intensity_blend[0] = MTT_R(150.0);
    p->intensity_blend[1] = MTT_R(250.0);
    p->jpda_bias = MTT_R(0.0);
    p->jpda_star_threshold = MTT_R(0.0);
    p->nnjpda_threshold = MTT_R(0.0);
    p->adaptive_jpda_distance = MTT_R(9.0);
    p->adaptive_jpda_shrink = MTT_R(3.0);
    p->cycle_counter = NULL;
    p->cycle_ctx = NULL;
    return MTT_OK;
}

/* lo <(=) v <(=) hi with finite v; open ends when the flags say so. */
static int in_range(mtt_real v, mtt_real lo, int lo_open, mtt_real hi, int hi_open)
{
    if (!mtt_isfinite(v)) {
        return 0;
    }
    if (lo_open ? !(v > lo) : !(v >= lo)) {
        return 0;
    }
    return hi_open ? (v < hi) : (v <= hi);
}

mtt_status mtt_params_check(const mtt_params *p, const char **bad_field)
{
    const mtt_real big = MTT_REAL_MAX;
    const char *bad = NULL;
    mtt_status st = MTT_ERR_PARAM;
    int k;
    if (bad_field != NULL) {
        *bad_field = NULL;
    }
    if (p == NULL) {
        return MTT_ERR_NULL;
    }
    if ((int)p->association < 0 || (int)p->association >= (int)MTT_ASSOC_COUNT) {
        bad = "association";
    } else if (!MTT_WITH_BASELINES && p->association > MTT_ASSOC_IPDA) {
        bad = "association"; /* built with MTT_WITH_BASELINES 0 */
        st = MTT_ERR_UNSUPPORTED;
    } else if (!in_range(p->process_psd, MTT_R(0.0), 1, big, 0)) {
        bad = "process_psd";
    } else if (!in_range(p->meas_sigma[0], MTT_R(1e-9), 0, MTT_R(1e9), 0) ||
               !in_range(p->meas_sigma[1], MTT_R(1e-9), 0, MTT_R(1e9), 0)) {
        /* sigma^2 must stay a normal number, with room for R / dT^2 */
        bad = "meas_sigma";
    } else if (!in_range(p->pd, MTT_R(0.0), 1, MTT_R(1.0), 0)) {
        bad = "pd";
    } else if (!in_range(p->pg, MTT_R(0.0), 1, MTT_R(1.0), 1)) {
        bad = "pg";
    } else if (!in_range(p->clutter_density, MTT_R(0.0), 0, big, 0)) {
        bad = "clutter_density";
    } else if (!in_range(p->snr_rho, MTT_R(0.0), 0, MTT_R(1e6), 0)) {
        bad = "snr_rho";
    } else if (!in_range(p->markov_p11, MTT_R(0.0), 0, MTT_R(1.0), 0)) {
        bad = "markov_p11";
    } else if (!in_range(p->markov_p21, MTT_R(0.0), 0, MTT_R(1.0), 0)) {
        bad = "markov_p21";
    } else if (!in_range(p->existence_init, MTT_R(0.0), 1, MTT_R(1.0), 1)) {
        bad = "existence_init";
    } else if (!in_range(p->confirm_threshold, MTT_R(0.0), 1, MTT_R(1.0), 0)) {
        bad = "confirm_threshold";
    } else if (!in_range(p->terminate_threshold, MTT_R(0.0), 0, p->confirm_threshold, 1)) {
        bad = "terminate_threshold";
    } else if (!in_range(p->merge_threshold, MTT_R(0.0), 0, big, 0)) {
        bad = "merge_threshold";
    } else if (!in_range(p->vmax, MTT_R(0.0), 1, big, 0)) {
        bad = "vmax";
    } else if (p->init_gate != MTT_INIT_GATE_VMAX && p->init_gate != MTT_INIT_GATE_INTENSITY) {
        bad = "init_gate";
    } else if (!in_range(p->jpda_bias, MTT_R(0.0), 0, big, 0)) {
        bad = "jpda_bias";
    } else if (!in_range(p->jpda_star_threshold, MTT_R(0.0), 0, MTT_R(1.0), 1)) {
        bad = "jpda_star_threshold";
    } else if (!in_range(p->nnjpda_threshold, MTT_R(0.0), 0, MTT_R(1.0), 1)) {
        bad = "nnjpda_threshold";
    } else if (!in_range(p->adaptive_jpda_distance, MTT_R(0.0), 1, big, 0)) {
        bad = "adaptive_jpda_distance";
    } else if (!in_range(p->adaptive_jpda_shrink, MTT_R(1.0), 0, big, 0)) {
        bad = "adaptive_jpda_shrink";
    } else if (!in_range(p->intensity_blend[0], -big, 0, big, 0) ||
               !in_range(p->intensity_blend[1], p->intensity_blend[0], 1, big, 0)) {
        bad = "intensity_gate.blend";
    } else {
        for (k = 0; k < 3 && bad == NULL; ++k) {
            if (!mtt_isfinite(p->intensity_f1[k])) {
                bad = "intensity_gate.f1";
            } else if (!mtt_isfinite(p->intensity_f2[k])) {
                bad = "intensity_gate.f2";
            }
        }
    }
    if (bad == NULL) {
        return MTT_OK;
    }
    if (bad_field != NULL) {
        *bad_field = bad;
    }
    return st;
}

mtt_status mtt_assoc_name(mtt_assoc a, const char **name)
{
    if (name == NULL) {
        return MTT_ERR_NULL;
    }
    if ((int)a < 0 || (int)a >= (int)MTT_ASSOC_COUNT) {
        return MTT_ERR_RANGE;
    }
    *name = assoc_names[a];
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
        if (same_text(name, assoc_names[k])) {
            *a = (mtt_assoc)k;
            return MTT_OK;
        }
    }
    return MTT_ERR_RANGE;
}

mtt_status mtt_status_text(mtt_status s, const char **text)
{
    static const char *const texts[] = {
        "ok", "null pointer", "invalid parameter", "tracker not initialised",
        "time not finite or not increasing", "index or count out of range",
        "track table full", "state or covariance not finite or not positive definite",
        "association mode not built into this version"};
    int k = -(int)s;
    if (text == NULL) {
        return MTT_ERR_NULL;
    }
    if (k < 0 || k >= (int)(sizeof texts / sizeof texts[0])) {
        return MTT_ERR_RANGE;
    }
    *text = texts[k];
    return MTT_OK;
}
