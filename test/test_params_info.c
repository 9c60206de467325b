/* SPDX-License-Identifier: BSD-3-Clause */
/* test_params_info.c - the public settings table (mtt_params_info, find,
 * set, get): every key round-trips, ranges are those of mtt_params_check,
 * errors change nothing. */
#include <math.h>
#include <string.h>

#include "mtt/mtt.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static size_t n_keys(void)
{
    const mtt_param_info *info;
    size_t n = 0;
    while (mtt_params_info(n, &info) == MTT_OK) {
        ++n;
    }
    return n;
}

/* Values of a key through mtt_params_set / get (imm_models: r, then a
 * model, a psd and a turn psd per slot). */
#define VALS (MTT_MAX_MODELS * MTT_MAX_MODELS + MTT_PARAM_MODEL_VALUES * MTT_MAX_MODELS + 3)
static size_t n_values(const mtt_param_info *info)
{
    return info->type == MTT_PARAM_MODELS ? 1u + MTT_PARAM_MODEL_VALUES * (size_t)info->count : info->count;
}

static void test_table_lists_the_settings_keys(void)
{
    static const char *const keys[] = {
        "association", "lm_ihpda_variant", "contest_beta", "process_psd", "max_accel", "meas_sigma", "measurement",
        "sensor_xy", "range_rate_sigma", "pd",
        "pg", "clutter_density", "snr_rho", "amplitude_eta",
#if MTT_WITH_CONTEST
        "adapt_s_min", "adapt_index", "adapt_memory", "adapt_gain", "adapt_reset_nis", "adapt_s_max",
#endif
        "markov_p11", "markov_p21", "existence_init", "confirm_threshold",
        "terminate_threshold", "merge_threshold", "initiate", "vmax", "init_gate",
        "intensity_gate.f1", "intensity_gate.f2", "intensity_gate.blend", "jpda_bias", "subopt_jpda_constant_b",
        "jpda_star_threshold", "nnjpda_threshold", "adaptive_jpda_distance",
        "adaptive_jpda_shrink", "motion"
#if MTT_WITH_IMM
        , "imm_models", "imm_transition", "imm_initial"
#endif
        , "split"
#if MTT_WITH_SPLIT
        , "split_p25", "split_p52", "split_p62", "split_dv", "split_confirm", "split_decide", "split_provisional_exist", "split_provisional_scans", "split_across", "split_known_speed", "split_decouple_r"
#endif
    };
    const mtt_param_info *info = NULL;
    size_t k, i;
    TEST_ASSERT_EQUAL_UINT(sizeof keys / sizeof keys[0], n_keys());
    for (k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(k, &info));
        TEST_ASSERT_EQUAL_STRING(keys[k], info->key);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find(keys[k], &i));
        TEST_ASSERT_EQUAL_UINT(k, i);
        TEST_ASSERT_NOT_NULL(info->text);
        TEST_ASSERT_TRUE(info->count >= 1 && info->count <= (info->per_model == 2 ? MTT_MAX_MODELS * MTT_MAX_MODELS
                                                              : info->per_model == 1 || info->type == MTT_PARAM_MODELS
                                                                  ? MTT_MAX_MODELS : 3));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(5, &info));
    TEST_ASSERT_EQUAL_UINT(2, info->count); /* meas_sigma */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("intensity_gate.f1", &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_EQUAL_UINT(3, info->count);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_info(k, &info));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_info(0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_find("initial_tracks", &i));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_find("intensity_gate", &i));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_find(NULL, &i));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_find("pd", NULL));
}

static void test_enum_names_are_the_mode_names(void)
{
    const mtt_param_info *info;
    const char *name;
    size_t i;
    int a;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("association", &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_EQUAL_INT(MTT_PARAM_ENUM, info->type);
    /* without the baselines the last mode, lm-ipda-all, is not a value at all */
    TEST_ASSERT_EQUAL_UINT(MTT_WITH_BASELINES ? MTT_ASSOC_COUNT : MTT_ASSOC_LM_IPDA_ALL, info->n_names);
    for (a = 0; a < (int)info->n_names; ++a) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_name((mtt_assoc)a, &name));
        TEST_ASSERT_EQUAL_STRING(name, info->names[a]);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("init_gate", &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_EQUAL_UINT(2, info->n_names);
    TEST_ASSERT_EQUAL_STRING("vmax", info->names[MTT_INIT_GATE_VMAX]);
    TEST_ASSERT_EQUAL_STRING("intensity", info->names[MTT_INIT_GATE_INTENSITY]);
}

/* Get every key of the defaults and set it into a zeroed set: the same
 * parameters come back. */
static void test_get_set_round_trip(void)
{
    mtt_params def, p;
    const mtt_param_info *info;
    double v[VALS];
    size_t k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&def));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pd = MTT_R(0.5);
    p.meas_sigma[1] = MTT_R(7.0);
    p.intensity_f2[2] = MTT_R(1.0);
    p.association = MTT_ASSOC_JPDA;
    p.init_gate = MTT_INIT_GATE_INTENSITY;
    p.initiate = 0;
    p.motion = MTT_MOTION_IMM;
#if MTT_WITH_IMM
    p.imm_psd[0] = MTT_R(3.0);
    p.imm_transition[0][0] = MTT_R(0.5);
#endif
    for (k = 0; mtt_params_info(k, &info) == MTT_OK; ++k) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&def, info->key, v, n_values(info)));
        TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, mtt_params_set(&p, info->key, v, n_values(info)),
                                      info->key);
    }
    TEST_ASSERT_EQUAL_MEMORY(&def, &p, sizeof p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&def, "meas_sigma", v, 2));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, v[0]);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&def, "initiate", v, 1));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, v[0]);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&def, "vmax", v, 1));
    TEST_ASSERT_EQUAL_DOUBLE(60.0, v[0]);
}

/* Try v for one element of key (the others at their defaults); expect st,
 * and p unchanged on error. */
static void try_set(const char *key, size_t elem, double value, mtt_status st)
{
    mtt_params p, before;
    double v[VALS];
    char msg[96];
    size_t i;
    const mtt_param_info *info;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find(key, &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&p, key, v, info->count));
    v[elem] = value;
    before = p;
    snprintf(msg, sizeof msg, "%s[%u] = %g", key, (unsigned)elem, value);
    TEST_ASSERT_EQUAL_INT_MESSAGE(st, mtt_params_set(&p, key, v, info->count), msg);
    if (st != MTT_OK) {
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, &p, sizeof p, msg);
    }
}

/* Every REAL key: its finite bounds are accepted or refused as the table
 * says, and so does mtt_params_check; beyond them and non-finite values
 * are refused. */
static void test_set_checks_the_table_ranges(void)
{
    const mtt_param_info *info;
    size_t k, e;
    for (k = 0; mtt_params_info(k, &info) == MTT_OK; ++k) {
        if (info->type != MTT_PARAM_REAL) {
            continue;
        }
        for (e = 0; e < info->count; ++e) {
            try_set(info->key, e, NAN, MTT_ERR_PARAM);
            try_set(info->key, e, INFINITY, MTT_ERR_PARAM);
            try_set(info->key, e, -INFINITY, MTT_ERR_PARAM);
            if (info->hi < (double)MTT_REAL_MAX) {
                try_set(info->key, e, 1e300, MTT_ERR_PARAM);
            }
#ifndef MTT_REAL_DOUBLE
            try_set(info->key, e, 1e39, MTT_ERR_PARAM); /* does not fit a float */
#endif
            if (info->lo > -(double)MTT_REAL_MAX) {
                try_set(info->key, e, info->lo, info->lo_open ? MTT_ERR_PARAM : MTT_OK);
                try_set(info->key, e, info->lo - 1e-3 - fabs(info->lo) * 1e-3, MTT_ERR_PARAM);
            }
            if (info->hi < (double)MTT_REAL_MAX) {
                /* terminate_threshold's hi is confirm_threshold's in the
                 * check: set alone takes up to 1 */
                try_set(info->key, e, info->hi, info->hi_open ? MTT_ERR_PARAM : MTT_OK);
                try_set(info->key, e, info->hi + 1e-3 + fabs(info->hi) * 1e-3, MTT_ERR_PARAM);
            }
        }
    }
}

static void test_set_refuses_bad_keys_counts_and_indices(void)
{
    mtt_params p, before;
    double v[3] = {0.5, 0.5, 0.5};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    before = p;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_set(&p, "pdd", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_set(&p, "pd", v, 2));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_set(&p, "meas_sigma", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_params_get(&p, "meas_sigma", v, 3));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_set(NULL, "pd", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_set(&p, NULL, v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_set(&p, "pd", NULL, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_get(&p, "pd", NULL, 1));
    v[0] = (double)MTT_ASSOC_COUNT;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "association", v, 1));
    v[0] = -1.0;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "association", v, 1));
    v[0] = 1.5;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "init_gate", v, 1));
    v[0] = 2.0;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "init_gate", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "initiate", v, 1));
    v[0] = NAN;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "initiate", v, 1));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    v[0] = (double)MTT_ASSOC_ADAPTIVE_JPDA;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "association", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ASSOC_ADAPTIVE_JPDA, p.association);
    v[0] = 0.0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "initiate", v, 1));
    TEST_ASSERT_EQUAL_INT(0, p.initiate);
}

/* Rules between keys are mtt_params_check's: set takes each key alone. */
static void test_cross_rules_are_left_to_check(void)
{
    mtt_params p;
    const char *bad = NULL;
    const mtt_param_info *info;
    size_t i;
    double v[2] = {0.999, 0.0};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "terminate_threshold", v, 1));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("terminate_threshold", bad);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    v[0] = 250.0;
    v[1] = 150.0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "intensity_gate.blend", v, 2));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("intensity_gate.blend", bad);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("terminate_threshold", &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_NOT_NULL(info->cross);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("pd", &i));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_info(i, &info));
    TEST_ASSERT_NULL(info->cross);
}

#if MTT_WITH_IMM
/* imm_models through set / get: (model, psd, turn psd) per slot; ct needs
 * a turn psd > 0, the other models refuse one; nothing changes on error. */
static void test_models_with_a_turn_rate(void)
{
    mtt_params p, before;
    const char *bad = NULL;
    double v[1 + MTT_PARAM_MODEL_VALUES * MTT_MAX_MODELS] = {0.0};
    const size_t n = sizeof v / sizeof v[0];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.motion = MTT_MOTION_IMM;
    v[0] = 2.0;
    v[1] = (double)MTT_MODEL_CV; v[2] = 0.5; v[3] = 0.0;
    v[4] = (double)MTT_MODEL_CT; v[5] = 30.0; v[6] = 0.005;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "imm_models", v, n));
    TEST_ASSERT_EQUAL_INT(MTT_MODEL_CT, p.imm_model[1]);
    TEST_ASSERT_TRUE(p.imm_psd[1] == MTT_R(30.0));
    TEST_ASSERT_TRUE(p.imm_turn_psd[1] == MTT_R(0.005));
    TEST_ASSERT_TRUE(p.imm_turn_psd[0] == MTT_R(0.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    memset(v, 0, sizeof v);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_get(&p, "imm_models", v, n));
    TEST_ASSERT_EQUAL_DOUBLE(2.0, v[0]);
    TEST_ASSERT_EQUAL_DOUBLE((double)MTT_MODEL_CT, v[4]);
    TEST_ASSERT_EQUAL_DOUBLE(30.0, v[5]);
    TEST_ASSERT_EQUAL_DOUBLE((double)(mtt_real)0.005, v[6]);
    before = p;
    v[6] = 0.0; /* ct without its turn-rate noise */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "imm_models", v, n));
    v[6] = 0.005;
    v[3] = 0.1; /* cv with one */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "imm_models", v, n));
    v[3] = 0.0;
    v[6] = -1.0;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_set(&p, "imm_models", v, n));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    /* the same rule in mtt_params_check, for parameters written directly */
    p.imm_turn_psd[1] = MTT_R(0.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("imm_models", bad);
    p = before;
    p.imm_turn_psd[0] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("imm_models", bad);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_table_lists_the_settings_keys);
    RUN_TEST(test_enum_names_are_the_mode_names);
    RUN_TEST(test_get_set_round_trip);
    RUN_TEST(test_set_checks_the_table_ranges);
    RUN_TEST(test_set_refuses_bad_keys_counts_and_indices);
    RUN_TEST(test_cross_rules_are_left_to_check);
#if MTT_WITH_IMM
    RUN_TEST(test_models_with_a_turn_rate);
#endif
    return UNITY_END();
}
