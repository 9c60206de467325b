/* params_table.h - the settings keys of mtt_params: the one place where a
 * key's name, type, element count, range and meaning are written down.
 *
 * Expanded twice (an "X macro"): params.c makes the compact range rules of
 * mtt_params_check from it (no texts: the firmware links params.c), and
 * params_info.c makes the public mtt_param_info table of mtt_params_info /
 * find / set / get (host only: nothing in the tracker references it, so a
 * firmware image does not link it).  docs/FORMATS.md's settings table is
 * `mtt-track --list-settings`, printed from that public table, and
 * scripts/check_settings_doc.py keeps the two equal.
 *
 * Rows, in docs/FORMATS.md order:
 *   REAL(key, member, count, lo, hi, flags, cross, text)
 *        mtt_real member (count 1) or member[count]; each element finite,
 *        lo <= v <= hi (PF_OPEN_* excludes a bound; MTT_REAL_MAX: no bound,
 *        any value mtt_real holds); cross: the rule against other values that only
 *        mtt_params_check applies (PF_BELOW_CONFIRM, PF_ASCENDING), as text
 *        in `cross` (NULL: none)
 *   FLAG(key, member, text)
 *        int member, 0 or nonzero (a JSON boolean)
 *   ENUM(key, member, type, n_names, names, text)
 *        enum member of `type`, value in [0, n_names); names[] spells them
 *
 * Not yet here, and their place is after adaptive_jpda_shrink: the motion
 * model keys (motion, imm_models, imm_transition, imm_initial) and split.
 * initial_tracks is not a parameter (it seeds the tracker): mtt-track reads
 * it itself. */
#ifndef MTT_PARAMS_TABLE_H
#define MTT_PARAMS_TABLE_H

#include "mtt/mtt.h"

/* Flags of the REAL rows. */
enum {
    PF_OPEN_LO = 1,        /* lo excluded */
    PF_OPEN_HI = 2,        /* hi excluded */
    PF_BELOW_CONFIRM = 4,  /* cross rule: v < confirm_threshold */
    PF_ASCENDING = 8       /* cross rule: each element > the one before */
};

/* The spellings of the enum keys, index = value (params.c). */
extern const char *const mtt_assoc_names[MTT_ASSOC_COUNT];
extern const char *const mtt_init_gate_names[2];

#define MTT_PARAM_ROWS(REAL, FLAG, ENUM)                                                          \
    ENUM("association", association, mtt_assoc, MTT_ASSOC_COUNT, mtt_assoc_names,                \
         "association mode (docs/ALGORITHMS.md describes each)")                                    \
    REAL("process_psd", process_psd, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL,                            \
         "power spectral density Sw of the constant-velocity model's white-noise acceleration")  \
    REAL("meas_sigma", meas_sigma, 2, 1e-9, 1e9, 0, NULL,                                    \
         "[sx, sy]: measurement noise standard deviations")                                       \
    REAL("pd", pd, 1, 0.0, 1.0, PF_OPEN_LO, NULL, "probability of detection")                   \
    REAL("pg", pg, 1, 0.0, 1.0, PF_OPEN_LO | PF_OPEN_HI, NULL,                                   \
         "gate probability; the chi-square gate threshold follows from it")                       \
    REAL("clutter_density", clutter_density, 1, 0.0, MTT_REAL_MAX, 0, NULL,                             \
         "clutter measurements per unit area; 0 estimates it per track")                          \
    REAL("snr_rho", snr_rho, 1, 0.0, 1e6, 0, NULL,                                             \
         "amplitude model rho (target amplitude mean 1+rho, clutter 1); 0 ignores amplitude")     \
    REAL("markov_p11", markov_p11, 1, 0.0, 1.0, 0, NULL,                                         \
         "probability that an existing target keeps existing from one scan to the next")          \
    REAL("markov_p21", markov_p21, 1, 0.0, 1.0, 0, NULL,                                         \
         "probability that a target that does not exist appears")                                 \
    REAL("existence_init", existence_init, 1, 0.0, 1.0, PF_OPEN_LO | PF_OPEN_HI, NULL,           \
         "existence probability of a new track")                                                  \
    REAL("confirm_threshold", confirm_threshold, 1, 0.0, 1.0, PF_OPEN_LO, NULL,                  \
         "existence at which a track is confirmed")                                               \
    REAL("terminate_threshold", terminate_threshold, 1, 0.0, 1.0,                                \
         PF_OPEN_HI | PF_BELOW_CONFIRM, "below confirm_threshold",                                \
         "existence below which a track is deleted; 0 never deletes")                             \
    REAL("merge_threshold", merge_threshold, 1, 0.0, MTT_REAL_MAX, 0, NULL,                             \
         "chi-square threshold of the track merging test; 0 never merges")                        \
    FLAG("initiate", initiate,                                                                    \
         "start tracks from unused measurements; false only updates seeded tracks")               \
    REAL("vmax", vmax, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL,                                          \
         "maximum target speed of the two-point initial velocity gate")                           \
    ENUM("init_gate", init_gate, mtt_init_gate, 2, mtt_init_gate_names,                           \
         "initial gate: vmax, or intensity (the amplitude-based gate f(I))")                      \
    REAL("intensity_gate.f1", intensity_f1, 3, -MTT_REAL_MAX, MTT_REAL_MAX, 0, NULL,                      \
         "[a2, a1, a0] of f1(I) = a2 I^2 + a1 I + a0, the initial gate's sigma below I_lo")       \
    REAL("intensity_gate.f2", intensity_f2, 3, -MTT_REAL_MAX, MTT_REAL_MAX, 0, NULL,                      \
         "[a2, a1, a0] of f2(I), the initial gate's sigma above I_hi")                            \
    REAL("intensity_gate.blend", intensity_blend, 2, -MTT_REAL_MAX, MTT_REAL_MAX, PF_ASCENDING,           \
         "increasing (I_lo < I_hi)", "[I_lo, I_hi]: intensities between which f1 blends into f2") \
    REAL("jpda_bias", jpda_bias, 1, 0.0, MTT_REAL_MAX, 0, NULL,                                         \
         "bias B of the JPDA family; 0 uses lambda (1 - PD PG) / PD")                             \
    REAL("jpda_star_threshold", jpda_star_threshold, 1, 0.0, 1.0, PF_OPEN_HI, NULL,              \
         "JPDA* pruning probability")                                                             \
    REAL("nnjpda_threshold", nnjpda_threshold, 1, 0.0, 1.0, PF_OPEN_HI, NULL,                    \
         "NNJPDA minimum association probability")                                                \
    REAL("adaptive_jpda_distance", adaptive_jpda_distance, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL,      \
         "adaptive JPDA: distance in measurement sigmas at which tracks overlap")                 \
    REAL("adaptive_jpda_shrink", adaptive_jpda_shrink, 1, 1.0, MTT_REAL_MAX, 0, NULL,                   \
         "adaptive JPDA: gate shrink factor of overlapping tracks")

/* Index of each REAL row among the REAL rows (the rules of params.c). */
#define MTT_PARAM_RULE_ID(key, member, count, lo, hi, flags, cross, text) MTT_RULE_##member,
#define MTT_PARAM_NO_REAL(key, member, count, lo, hi, flags, cross, text)
#define MTT_PARAM_NO_FLAG(key, member, text)
#define MTT_PARAM_NO_ENUM(key, member, type, n_names, names, text)
enum { MTT_PARAM_ROWS(MTT_PARAM_RULE_ID, MTT_PARAM_NO_FLAG, MTT_PARAM_NO_ENUM) MTT_RULE_COUNT };

/* Rule `rule` holds for p: every element finite and within its bounds, and
 * with `cross` nonzero the rule against the other values too (params.c). */
int mtt_params_rule_ok(const mtt_params *p, size_t rule, int cross);

/* The mtt_real elements of REAL row `rule` in p (the offsetof table access
 * of MISRA.md). */
mtt_real *mtt_params_rule_at(mtt_params *p, size_t rule);

#endif /* MTT_PARAMS_TABLE_H */
