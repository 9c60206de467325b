/* params.c - parameter defaults (docs/FORMATS.md, [S0]'s IR set-up),
 * validation that names the first bad field, and the status texts.  The
 * mode names live in the mode table (associate.c). */
#include <stddef.h>
#include <string.h>

#include "mtt_internal.h"

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
    /* [S2], ALGORITHMS.md §12.2 */
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

/* Range rules of mtt_params_check, in the order the first bad field is
 * reported.  A table rather than a chain of calls: smaller code (the
 * library's .text is a firmware budget) and one place to read the ranges. */
enum {
    B_0, B_1, B_1EM9, B_1E9, B_1E6, B_MAX, B_MINUS_MAX, /* bounds, see bound() */
    OPEN_LO = 1, OPEN_HI = 2, HI_CONFIRM = 4, LO_BLEND = 8, INIT_GATE = 16
};

typedef struct range_rule {
    const char *name;
    uint16_t off;          /* offsetof the mtt_real in mtt_params */
    uint8_t lo, hi, flags; /* B_* bound indices and the flags above */
} range_rule;

#define RULE(name, member, lo, hi, flags) {name, (uint16_t)offsetof(mtt_params, member), lo, hi, flags}

static const range_rule rules[] = {
    RULE("process_psd", process_psd, B_0, B_MAX, OPEN_LO),
    /* sigma^2 must stay a normal number, with room for R / dT^2 */
    RULE("meas_sigma", meas_sigma[0], B_1EM9, B_1E9, 0),
    RULE("meas_sigma", meas_sigma[1], B_1EM9, B_1E9, 0),
    RULE("pd", pd, B_0, B_1, OPEN_LO),
    RULE("pg", pg, B_0, B_1, OPEN_LO | OPEN_HI),
    RULE("clutter_density", clutter_density, B_0, B_MAX, 0),
    RULE("snr_rho", snr_rho, B_0, B_1E6, 0),
    RULE("markov_p11", markov_p11, B_0, B_1, 0),
    RULE("markov_p21", markov_p21, B_0, B_1, 0),
    RULE("existence_init", existence_init, B_0, B_1, OPEN_LO | OPEN_HI),
    RULE("confirm_threshold", confirm_threshold, B_0, B_1, OPEN_LO),
    RULE("terminate_threshold", terminate_threshold, B_0, B_1, OPEN_HI | HI_CONFIRM),
    RULE("merge_threshold", merge_threshold, B_0, B_MAX, 0),
    RULE("vmax", vmax, B_0, B_MAX, OPEN_LO),
    RULE("init_gate", vmax, B_0, B_MAX, INIT_GATE),
    RULE("jpda_bias", jpda_bias, B_0, B_MAX, 0),
    RULE("jpda_star_threshold", jpda_star_threshold, B_0, B_1, OPEN_HI),
    RULE("nnjpda_threshold", nnjpda_threshold, B_0, B_1, OPEN_HI),
    RULE("adaptive_jpda_distance", adaptive_jpda_distance, B_0, B_MAX, OPEN_LO),
    RULE("adaptive_jpda_shrink", adaptive_jpda_shrink, B_1, B_MAX, 0),
    RULE("intensity_gate.blend", intensity_blend[0], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.blend", intensity_blend[1], B_MINUS_MAX, B_MAX, OPEN_LO | LO_BLEND),
    RULE("intensity_gate.f1", intensity_f1[0], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.f2", intensity_f2[0], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.f1", intensity_f1[1], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.f2", intensity_f2[1], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.f1", intensity_f1[2], B_MINUS_MAX, B_MAX, 0),
    RULE("intensity_gate.f2", intensity_f2[2], B_MINUS_MAX, B_MAX, 0),
};

static mtt_real bound(uint8_t b)
{
    switch (b) {
    case B_0: return MTT_R(0.0);
    case B_1: return MTT_R(1.0);
    case B_1EM9: return MTT_R(1e-9);
    case B_1E9: return MTT_R(1e9);
    case B_1E6: return MTT_R(1e6);
    case B_MINUS_MAX: return -MTT_REAL_MAX;
    default: return MTT_REAL_MAX;
    }
}

/* lo <(=) v <(=) hi with finite v; open ends as the flags say. */
static int rule_ok(const mtt_params *p, const range_rule *r)
{
    const mtt_real v = *(const mtt_real *)(const void *)((const char *)p + r->off);
    mtt_real lo = bound(r->lo), hi = bound(r->hi);
    if (r->flags & INIT_GATE) {
        return p->init_gate == MTT_INIT_GATE_VMAX || p->init_gate == MTT_INIT_GATE_INTENSITY;
    }
    if (r->flags & HI_CONFIRM) {
        hi = p->confirm_threshold;
    }
    if (r->flags & LO_BLEND) {
        lo = p->intensity_blend[0];
    }
    if (!mtt_isfinite(v)) {
        return 0;
    }
    if ((r->flags & OPEN_LO) ? !(v > lo) : !(v >= lo)) {
        return 0;
    }
    return (r->flags & OPEN_HI) ? (v < hi) : (v <= hi);
}

mtt_status mtt_params_check(const mtt_params *p, const char **bad_field)
{
    const char *bad = NULL;
    mtt_status st = MTT_ERR_PARAM;
    size_t k;
    if (bad_field != NULL) {
        *bad_field = NULL;
    }
    if (p == NULL) {
        return MTT_ERR_NULL;
    }
    if ((int)p->association < 0 || (int)p->association >= (int)MTT_ASSOC_COUNT) {
        bad = "association";
    } else if (!MTT_WITH_BASELINES && mtt_modes[p->association].baseline) {
        bad = "association"; /* a baseline, built with MTT_WITH_BASELINES 0 */
        st = MTT_ERR_UNSUPPORTED;
    } else {
        for (k = 0; k < sizeof rules / sizeof rules[0] && bad == NULL; ++k) {
            if (!rule_ok(p, &rules[k])) {
                bad = rules[k].name;
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

mtt_status mtt_status_text(mtt_status s, const char **text)
{
    static const char *const texts[] = {
        "ok", "null pointer", "invalid parameter", "tracker not initialised",
        "time not finite or not increasing", "index or count out of range",
        "track table full", "state or covariance not finite or not positive definite",
        "association mode not built into this version",
        "configuration mismatch"};
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
