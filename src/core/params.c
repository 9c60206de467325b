/* SPDX-License-Identifier: BSD-3-Clause */
/* params.c - parameter defaults (docs/FORMATS.md, [S0]'s IR set-up),
 * validation against the ranges of params_table.h that names the first bad
 * field, and the status texts.  In the fixed-point build every value is in
 * its quantity's Q format (docs/FIXED_POINT.md §3).  The mode names live with the mode table
 * (associate.c). */
#include <stddef.h>
#include <string.h>

#include "mtt_internal.h"
#include "params_table.h"

/* Fixed-point build: PDEF and the rule bounds convert their constants
 * with the Q format of each REAL row's values (MTT_FX_FRAC_<member>,
 * params_table.h) (saturated: MTT_REAL_MAX is "no
 * bound"; a positive bound that rounds to 0 becomes one unit, so an open
 * or positive lower bound stays positive).  Float and double: MTT_R. */
#ifdef MTT_REAL_FIXED
#define PDEF(member, x) MTT_FX_CONST_SAT(x, MTT_FX_FRAC_##member)
#define PBOUND(member, x)                                                                          \
    (((x) > 0 && MTT_FX_CONST_SAT(x, MTT_FX_FRAC_##member) == 0) ? 1                                \
                                                                  : MTT_FX_CONST_SAT(x, MTT_FX_FRAC_##member))
#else
#define PDEF(member, x) MTT_R(x)
#define PBOUND(member, x) MTT_R(x)
#endif

#if MTT_WITH_IMM
/* docs/FORMATS.md's IMM transitions for r = imm_n_models models when
 * imm_transition is not given and the motion does not follow max_accel:
 * 0.99 on the diagonal, the rest of each row spread evenly; the slots beyond
 * r are 0.  (0.99 rather than a quicker 0.95: on straight targets in heavy
 * clutter every switch into the manoeuvre model costs;
 * docs/reports/MOTION.md "Manoeuvring targets: IMM".) */
void mtt_params_imm_pi_default(mtt_params *p)
{
    const uint8_t r = p->imm_n_models;
    uint8_t i, j;
    for (i = 0; i < MTT_MAX_MODELS; ++i) {
        for (j = 0; j < MTT_MAX_MODELS; ++j) {
            mtt_real v = MTT_ZERO;
            if (i < r && j < r) {
                v = (r == 1u) ? MTT_P(1.0) : ((i == j) ? MTT_P(0.99) : MTT_P(0.01) / (mtt_real)(r - 1u));
            }
            p->imm_transition[i][j] = v;
        }
    }
}

/* r models; imm_transition and imm_initial not given (ALGORITHMS.md §2.2:
 * resolved with the rest at set-up). */
void mtt_params_imm_reset(mtt_params *p, uint8_t r)
{
    p->imm_n_models = r;
    memset(p->imm_transition, 0, sizeof p->imm_transition);
    memset(p->imm_initial, 0, sizeof p->imm_initial);
}

/* imm_models' default: not given (every psd 0; ALGORITHMS.md §2.2), kinds
 * [cv, ca] (one cv model in a build with MTT_MAX_MODELS 1): with the motion
 * from max_accel two cv models, else cv and ca with process_psd. */
static void imm_default(mtt_params *p)
{
    uint8_t i;
    for (i = 0; i < MTT_MAX_MODELS; ++i) {
        p->imm_model[i] = (i == 1u) ? MTT_MODEL_CA : MTT_MODEL_CV;
        p->imm_psd[i] = MTT_ZERO;
    }
    mtt_params_imm_reset(p, (MTT_MAX_MODELS >= 2) ? 2u : 1u);
}

/* The cross rules of the IMM keys (ALGORITHMS.md §14): r in
 * [2, MTT_MAX_MODELS] with known model kinds; the first r rows of
 * imm_transition and the first r entries of imm_initial sum to 1 within
 * 1e-4 (the decimals of a settings file), every slot beyond them 0 (so a
 * matrix or list of another size than imm_models is caught).  The element
 * ranges are the table's rules.  Returns the bad key or NULL. */
#ifdef MTT_REAL_FIXED
#define TURN_PSD_MAX (MTT_FX_MAX - 1)
#else
#define TURN_PSD_MAX MTT_REAL_MAX
#endif
static const char *check_imm(const mtt_params *p)
{
    const mtt_prob tol = MTT_P(1e-4);
    mtt_prob s0 = MTT_ZERO;
    uint8_t i, j, r = p->imm_n_models;
    if (p->motion == MTT_MOTION_CV && r == 1u) {
        return NULL; /* a build without IMM (MTT_MAX_MODELS 1): nothing to check */
    }
    if (r < 2u || r > MTT_MAX_MODELS) {
        return "imm_models";
    }
    for (i = 0; i < MTT_MAX_MODELS; ++i) {
        mtt_prob s = MTT_ZERO;
        /* cppcheck-suppress knownConditionTrueFalse ; always true only where MTT_MAX_MODELS is 2 */
        if (i < r && !((int)p->imm_model[i] >= 0 && (int)p->imm_model[i] <= (int)MTT_MODEL_CT)) {
            return "imm_models";
        }
        if (i < r && !(p->imm_psd[i] > MTT_ZERO)) {
            return "imm_models"; /* a model's psd 0: imm_models given only in part */
        }
        /* the turn-rate noise: > 0 (and finite) for ct, 0 for the others */
        if (i < r && ((p->imm_model[i] == MTT_MODEL_CT) ? !(p->imm_turn_psd[i] > MTT_ZERO && p->imm_turn_psd[i] <= TURN_PSD_MAX)
                                                        : p->imm_turn_psd[i] != MTT_ZERO)) {
            return "imm_models";
        }
        for (j = 0; j < MTT_MAX_MODELS; ++j) {
            if ((i >= r || j >= r) && p->imm_transition[i][j] != MTT_ZERO) {
                return "imm_transition";
            }
            s = MTT_ADDS(s, p->imm_transition[i][j]);
        }
        if (i < r && !(MTT_ABS(MTT_SUB(s, MTT_P(1.0))) <= tol)) {
            return "imm_transition";
        }
        if (i >= r && p->imm_initial[i] != MTT_ZERO) {
            return "imm_initial";
        }
        s0 = MTT_ADDS(s0, p->imm_initial[i]);
    }
    if (!(MTT_ABS(MTT_SUB(s0, MTT_P(1.0))) <= tol)) {
        return "imm_initial";
    }
    return NULL;
}
#endif /* MTT_WITH_IMM */

mtt_status mtt_params_default_checked(mtt_params *p, size_t params_size, uint32_t config_id)
{
    if (p == NULL) {
        return MTT_ERR_NULL;
    }
    /* Before p is written: the caller's mtt_params may be smaller than ours. */
    if (params_size != sizeof(mtt_params) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    memset(p, 0, sizeof *p);
    p->association = MTT_ASSOC_LM_IHPDA;
    /* the contest-aware rule where it is built (ALGORITHMS.md §10.4), else [S0] */
    p->lm_ihpda_variant = MTT_WITH_CONTEST ? MTT_LM_IHPDA_CONTEST : MTT_LM_IHPDA_S0;
    p->contest_beta = PDEF(contest_beta, 0.1);
    p->process_psd = PDEF(process_psd, 0.0); /* not given: from max_accel, else 5 (ALGORITHMS.md §2.2) */
    p->max_accel = PDEF(max_accel, 0.0);
    p->meas_sigma[0] = PDEF(meas_sigma, 1.0);
    p->meas_sigma[1] = PDEF(meas_sigma, 1.0);
    p->measurement = MTT_MEASUREMENT_CARTESIAN;
    p->sensor_xy[0] = PDEF(sensor_xy, 0.0);
    p->sensor_xy[1] = PDEF(sensor_xy, 0.0);
    p->range_rate_sigma = PDEF(range_rate_sigma, 0.0);
    p->pd = PDEF(pd, 0.9);
    p->pg = PDEF(pg, 0.999);
    p->clutter_density = PDEF(clutter_density, 0.0);
    p->snr_rho = PDEF(snr_rho, 0.0);
    p->amplitude_eta = PDEF(amplitude_eta, 0.5);
#if MTT_WITH_CONTEST
    mtt_adapt_defaults(p); /* ALGORITHMS.md §2.1 */
#endif
    p->markov_p11 = PDEF(markov_p11, 0.98);
    p->markov_p21 = PDEF(markov_p21, 0.0);
    p->existence_init = PDEF(existence_init, 0.1);
    p->confirm_threshold = PDEF(confirm_threshold, 0.995);
    p->terminate_threshold = PDEF(terminate_threshold, 0.01);
    p->merge_threshold = PDEF(merge_threshold, 1.0);
    p->initiate = 1;
    p->vmax = PDEF(vmax, 60.0);
    p->init_gate = MTT_INIT_GATE_VMAX;
    /* [S2], ALGORITHMS.md §12.2 */
    p->intensity_f1[0] = PDEF(intensity_f1, -0.0007);
    p->intensity_f1[1] = PDEF(intensity_f1, 0.5072);
    p->intensity_f1[2] = PDEF(intensity_f1, 39.70);
    p->intensity_f2[0] = PDEF(intensity_f2, -0.0001);
    p->intensity_f2[1] = PDEF(intensity_f2, 0.2097);
    p->intensity_f2[2] = PDEF(intensity_f2, 57.25);
    p->intensity_blend[0] = PDEF(intensity_blend, 150.0);
    p->intensity_blend[1] = PDEF(intensity_blend, 250.0);
    p->jpda_bias = PDEF(jpda_bias, 0.0);
    p->subopt_jpda_constant_b = 0;
    p->jpda_star_threshold = PDEF(jpda_star_threshold, 0.0);
    p->nnjpda_threshold = PDEF(nnjpda_threshold, 0.0);
    p->adaptive_jpda_distance = PDEF(adaptive_jpda_distance, 9.0);
    p->adaptive_jpda_shrink = PDEF(adaptive_jpda_shrink, 3.0);
    p->motion = MTT_MOTION_AUTO;
#if MTT_WITH_IMM
    imm_default(p);
#endif
    /* ALGORITHMS.md §14.3 [CHOICE]: a split is rare (p25), a "just split"
     * without a second target falls back soon (p52), split targets seldom
     * recombine (p62) */
    p->split = 0;
    p->split_p25 = PDEF(split_p25, 0.1);
    p->split_p52 = PDEF(split_p52, 0.1);
    p->split_p62 = PDEF(split_p62, 0.1);
    p->split_dv = PDEF(split_dv, 0.0);
#if MTT_WITH_SPLIT
    p->split_confirm = PDEF(split_confirm, 0.97);
    /* [CHOICE, measured on the seeds 1000+ of split_fast.json,
     * crossing3.json and formations.json, docs/reports/MOTION.md "Split targets"] */
    p->split_decide = PDEF(split_decide, 0.9);
    p->split_provisional_exist = PDEF(split_provisional_exist, 0.6);
    p->split_provisional_scans = PDEF(split_provisional_scans, 3.0);
    p->split_across = 1;
    p->split_decouple_r = 0;
    p->split_known_speed = 0;
#endif
    p->cycle_counter = NULL;
    p->cycle_ctx = NULL;
    return MTT_OK;
}

uint8_t mtt_params_cv_model(const mtt_params *p)
{
    uint8_t j;
    for (j = 0; j < p->imm_n_models && j < MTT_MAX_MODELS; ++j) {
        if (p->imm_model[j] == MTT_MODEL_CV) {
            break;
        }
    }
    return j;
}

/* Range rules of mtt_params_check: the REAL rows of params_table.h,
 * without their texts (the library's .text is a firmware budget).  The
 * first bad field in table order is reported. */
typedef struct range_rule {
    const char *name;
    uint16_t off;          /* offsetof the first mtt_real in mtt_params */
    uint8_t count, flags;  /* elements, PF_* flags */
    mtt_real lo, hi;
} range_rule;

#define RULE(key, member, count, lo, hi, flags, cross, tier, text)                                      \
    {key, (uint16_t)offsetof(mtt_params, member), count, flags, PBOUND(member, lo), PBOUND(member, hi)},

static const range_rule rules[MTT_RULE_COUNT] = {
    MTT_PARAM_ROWS(RULE, MTT_PARAM_NO_FLAG, MTT_PARAM_NO_ENUM)};

const char *const mtt_init_gate_names[2] = {"vmax", "intensity"};
const char *const mtt_lm_ihpda_variant_names[2] = {"s0", "contest"};
const char *const mtt_motion_names[3] = {"cv", "imm", "auto"};
const char *const mtt_measurement_names[2] = {"cartesian", "polar"};
const char *const mtt_model_names[3] = {"cv", "ca", "ct"};

mtt_real *mtt_params_rule_at(mtt_params *p, size_t rule)
{
    return (mtt_real *)(void *)((char *)p + rules[rule].off);
}

int mtt_params_rule_ok(const mtt_params *p, size_t rule, int cross)
{
    const range_rule *r = &rules[rule];
    const mtt_real *v = (const mtt_real *)(const void *)((const char *)p + r->off);
    mtt_real lo = r->lo, hi = r->hi;
    uint8_t k;
    if (cross && (r->flags & PF_BELOW_CONFIRM)) {
        hi = p->confirm_threshold; /* open, as the flags say: terminate < confirm */
    }
    for (k = 0; k < r->count; ++k) {
        if (!mtt_isfinite(v[k])) {
            return 0;
        }
        if ((r->flags & PF_OPEN_LO) ? !(v[k] > lo) : !(v[k] >= lo)) {
            return 0;
        }
        if ((r->flags & PF_OPEN_HI) ? !(v[k] < hi) : !(v[k] <= hi)) {
            return 0;
        }
        if (cross && (r->flags & PF_ASCENDING) && k > 0 && !(v[k] > v[k - 1])) {
            return 0;
        }
    }
    return 1;
}

/* An enum row is bad when its value is not one of its n_names. */
#define CHECK_ENUM(key, member, type, n_names, names, tier, text)                                        \
    if (bad == NULL && !((int)p->member >= 0 && (int)p->member < (int)(n_names))) {                 \
        bad = key;                                                                                 \
    }

#ifdef MTT_REAL_FIXED
/* s^2 (s in the position format) is a variance of its format, (0, MTT_FX_MAX)
 * units of Q MTT_FX_VAR_FRAC (docs/FIXED_POINT.md §3): R = sigma^2, the
 * derived motion's a^2. */
static int var_fits(mtt_real s)
{
    const mtt_real v = MTT_VAR_OF(s);
    return v > 0 && v < MTT_FX_MAX;
}
#endif

/* mtt_params_check after its guards, with the keys as the tracker
 * resolves them in *q (written once the ranges hold; resolved when
 * MTT_OK). */
static mtt_status check_into(const mtt_params *p, const char **bad_field, mtt_params *q)
{
    const char *bad = NULL;
    mtt_status st = MTT_ERR_PARAM;
    size_t k;
    MTT_PARAM_ROWS(MTT_PARAM_NO_REAL, MTT_PARAM_NO_FLAG, CHECK_ENUM)
    if (bad == NULL && !MTT_WITH_BASELINES && mtt_modes[p->association].baseline) {
        bad = "association"; /* a baseline, built with MTT_WITH_BASELINES 0 */
        st = MTT_ERR_UNSUPPORTED;
    }
    for (k = 0; k < MTT_RULE_COUNT && bad == NULL; ++k) {
        if (!mtt_params_rule_ok(p, k, 1)) {
            bad = rules[k].name;
        }
    }
#ifdef MTT_REAL_FIXED
    if (bad == NULL && mtt_manoeuvre_derived(p) && !var_fits(p->max_accel)) {
        /* the derived level q = a^2 dT: a^2 must be a variance of its format
         * (docs/FIXED_POINT.md §3) */
        bad = "max_accel";
    }
#endif
    if (bad == NULL) {
        /* the cross rules on the keys as the tracker resolves them (ALGORITHMS.md §2.2) */
        mtt_manoeuvre lv;
        *q = *p;
        mtt_manoeuvre_resolve(q, &lv);
#if MTT_WITH_IMM
        bad = check_imm(q);
        if (bad == NULL && q->motion == MTT_MOTION_IMM && !mtt_modes[q->association].imm) {
#else
        if (q->motion == MTT_MOTION_IMM) {
#endif
            bad = "motion"; /* IMM left out of the build, or a mode without IMM (ALGORITHMS.md §14.2) */
            st = MTT_ERR_UNSUPPORTED;
        }
#if MTT_WITH_IMM && !MTT_WITH_IMM_CACT
        for (k = 0; bad == NULL && q->motion == MTT_MOTION_IMM && k < q->imm_n_models; ++k) {
            if (q->imm_model[k] != MTT_MODEL_CV) {
                bad = "imm_models"; /* ca and ct: float only (docs/FIXED_POINT.md §5) */
                st = MTT_ERR_UNSUPPORTED;
            }
        }
#endif
        if (bad == NULL && q->split &&
            (!MTT_WITH_SPLIT || q->motion != MTT_MOTION_IMM || mtt_params_cv_model(q) >= q->imm_n_models)) {
            bad = "split"; /* the split modes are IMM modes built on a cv model (ALGORITHMS.md §14.3) */
            st = MTT_ERR_UNSUPPORTED;
        }
    }
    if (bad == NULL && p->measurement == MTT_MEASUREMENT_POLAR && !MTT_WITH_POLAR) {
        /* polar detections carry their own covariance (ALGORITHMS.md
         * §3.2), which the fixed-point and firmware builds do not hold */
        bad = "measurement";
        st = MTT_ERR_UNSUPPORTED;
    }
#ifdef MTT_REAL_FIXED
    if (bad == NULL && !(p->clutter_density > 0)) {
        /* the fixed-point build holds densities relative to lambda
         * (docs/FIXED_POINT.md §2): the estimated density (0) has no
         * reference yet */
        bad = "clutter_density";
        st = MTT_ERR_UNSUPPORTED;
    }
    if (bad == NULL && (!var_fits(p->meas_sigma[0]) || !var_fits(p->meas_sigma[1]))) {
        /* R = sigma^2 must be a variance of its format: (0, 32768) unit^2 */
        bad = "meas_sigma";
        st = MTT_ERR_PARAM;
    }
    if (bad == NULL && p->init_gate == MTT_INIT_GATE_INTENSITY) {
        /* the intensity gate's f(I) coefficients (a2 = -1e-4) have no
         * precision in the amplitude format: the vmax circle only */
        bad = "init_gate";
        st = MTT_ERR_UNSUPPORTED;
    }
#endif
    if (bad == NULL && !MTT_WITH_CONTEST && p->lm_ihpda_variant == MTT_LM_IHPDA_CONTEST) {
        bad = "lm_ihpda_variant"; /* the contest variant, built with MTT_WITH_CONTEST 0 */
        st = MTT_ERR_UNSUPPORTED;
    }
    if (bad == NULL) {
        return MTT_OK;
    }
    if (bad_field != NULL) {
        *bad_field = bad;
    }
    return st;
}

mtt_status mtt_params_check_checked(const mtt_params *p, const char **bad_field, size_t params_size,
                                    uint32_t config_id)
{
    mtt_params q;
    if (p == NULL) {
        if (bad_field != NULL) {
            *bad_field = NULL;
        }
        return MTT_ERR_NULL;
    }
    /* Before p is read or bad_field written: the caller's mtt_params may
     * have another layout than ours. */
    if (params_size != sizeof(mtt_params) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    if (bad_field != NULL) {
        *bad_field = NULL;
    }
    return check_into(p, bad_field, &q);
}

mtt_status mtt_params_resolve_checked(const mtt_params *p, mtt_params *out, size_t params_size,
                                      uint32_t config_id)
{
    mtt_params q;
    mtt_status st;
    if (p == NULL || out == NULL) {
        return MTT_ERR_NULL;
    }
    if (params_size != sizeof(mtt_params) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    st = check_into(p, NULL, &q);
    if (st == MTT_OK) {
        *out = q; /* on error out is unchanged */
    }
    return st;
}

mtt_status mtt_status_text(mtt_status s, const char **text)
{
    /* Short: a firmware links them (mtt.h's list says more). */
    static const char *const texts[] = {
        "ok", "null pointer", "invalid parameter", "not initialised", "time not increasing",
        "out of range", "table full", "bad state or covariance", "not built in",
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
