/* SPDX-License-Identifier: BSD-3-Clause */
/* params_table.h - the settings keys of mtt_params: the one place where a
 * key's name, type, element count, range and meaning are written down.
 *
 * Expanded twice (an "X macro"): params.c makes the compact range rules of
 * mtt_params_check from it (no texts: the firmware links params.c), and
 * params_info.c makes the public mtt_param_info table of mtt_params_info /
 * find / set / get (host only: nothing in the tracker references it, so a
 * firmware image does not link it).  docs/FORMATS.md's settings table is
 * `mtt-track --list-settings`, printed from that public table, and
 * tools/ci/check_settings_doc.py keeps the two equal.
 *
 * Rows, in docs/FORMATS.md order:
 *   REAL(key, member, count, lo, hi, flags, cross, tier, text)
 *        mtt_real member (count 1) or member[count]; each element finite,
 *        lo <= v <= hi (PF_OPEN_* excludes a bound; MTT_REAL_MAX: no bound,
 *        any value mtt_real holds); cross: the rule against other values that only
 *        mtt_params_check applies (PF_BELOW_CONFIRM, PF_ASCENDING), as text
 *        in `cross` (NULL: none)
 *   FLAG(key, member, tier, text)
 *        int member, 0 or nonzero (a JSON boolean)
 *   ENUM(key, member, type, n_names, names, tier, text)
 *        enum member of `type`, value in [0, n_names); names[] spells them
 * tier (mtt_param_tier, docs/CONFIGURATION.md): SENSOR, the sensor and
 * targets (facts the user knows); TRACK, track management; TUNING, the
 * variants' tuning; BASELINE, keys that only the baseline modes read.
 *
 * imm_models is a REAL row over the psd slots with PF_MODELS: its public
 * type is MTT_PARAM_MODELS, and params_info.c sets and gets the model kinds
 * and r with it.  `split` is a key of every build (a build without
 * MTT_WITH_SPLIT refuses `true`); its transition keys only with it.
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
    PF_ASCENDING = 8,      /* cross rule: each element > the one before */
    PF_MODELS = 16,        /* imm_models: public type MTT_PARAM_MODELS over the psd slots */
    PF_PER_MODEL = 32,     /* one value per IMM model (MTT_MAX_MODELS slots) */
    PF_PER_MODEL2 = 64     /* an r x r matrix of IMM models (MTT_MAX_MODELS^2 slots) */
};

/* The modes this build knows: lm-ipda-all and [S1]'s three gate-shrink
 * variants, the last four, only with the baselines, so that a firmware's
 * mode tables and checks stay as they were
 * (a build without it refuses the value as out of range, MTT_ERR_PARAM). */
#define MTT_ASSOC_ROWS (MTT_WITH_BASELINES ? (int)MTT_ASSOC_COUNT : (int)MTT_ASSOC_LM_IPDA_ALL)

/* The spellings of the enum keys, index = value (params.c). */
extern const char *const mtt_assoc_names[MTT_ASSOC_ROWS];
extern const char *const mtt_init_gate_names[2];
extern const char *const mtt_lm_ihpda_variant_names[2];
extern const char *const mtt_motion_names[3];
extern const char *const mtt_measurement_names[2];
extern const char *const mtt_model_names[3];

/* The IMM rows (ALGORITHMS.md §14): only in a build with MTT_WITH_IMM; without
 * it only `motion` is a key (and `imm` is refused). */
#if MTT_WITH_IMM
#define MTT_PARAM_IMM_ROWS(REAL, FLAG, ENUM)                                                      \
    REAL("imm_models", imm_psd, MTT_MAX_MODELS, 0.0, MTT_REAL_MAX, PF_MODELS, NULL, TUNING,           \
         "with `imm`: the models, a list of {\"model\": M, \"process_psd\": q}; M is `cv` (white-noise acceleration, q in length²/time³), `ca` (constant acceleration, white-noise jerk, q in length²/time⁵) or `ct` (coordinated turn with unknown turn rate: q as cv on the velocity, and `turn_psd`, the turn rate's white-noise psd in rad²/time³, > 0, given for ct only); not given: with the motion from max_accel two cv models, steady and manoeuvring (§2.2), else cv and ca, both with process_psd (§14.1)") \
    REAL("imm_transition", imm_transition, MTT_MAX_MODELS * MTT_MAX_MODELS, 0.0, 1.0, PF_PER_MODEL2,       \
         "r rows of r (r models), each row summing to 1", TUNING,                                           \
         "with `imm`: the model transition matrix per scan, Π[i][j] = P(model j at k given model i at k − 1), in imm_models order (§14.1); not given: from the manoeuvre time vmax/max_accel with the motion from max_accel (§2.2), else 0.99 on the diagonal and the rest of each row spread evenly") \
    REAL("imm_initial", imm_initial, MTT_MAX_MODELS, 0.0, 1.0, PF_PER_MODEL,                         \
         "one per model, summing to 1", TUNING,                                                               \
         "with `imm`: the model probabilities of a new or seeded track (§14.2); not given: all in the first model")
#else
#define MTT_PARAM_IMM_ROWS(REAL, FLAG, ENUM)
#endif

/* The split-target rows (ALGORITHMS.md §14.3): the transitions of the
 * split modes only in a build with MTT_WITH_SPLIT. */
#if MTT_WITH_SPLIT
#define MTT_PARAM_SPLIT_P_ROWS(REAL, FLAG, ENUM)                                                  \
    REAL("split_p25", split_p25, 1, 0.0, 1.0, PF_OPEN_HI, NULL, TUNING,                                   \
         "with `split`: per-scan probability that a target in the cv model splits (cv → \"just split\"); the cv row of imm_transition is scaled by 1 − split_p25 (§14.3)") \
    REAL("split_p52", split_p52, 1, 0.0, 1.0, 0, NULL, TUNING,                                            \
         "with `split`: probability that a \"just split\" finds no second target and falls back to cv; the rest goes to \"split\" (§14.3)") \
    REAL("split_p62", split_p62, 1, 0.0, 1.0, 0, NULL, TUNING,                                            \
         "with `split`: per-scan probability that two split targets recombine (\"split\" → cv, §14.3)") \
    REAL("split_dv", split_dv, 1, 0.0, MTT_REAL_MAX, 0, NULL, TUNING,                                     \
         "with `split`: standard deviation of a split's velocity change per axis, length/time; the \"just split\" model predicts with this velocity impulse added, which widens its gate; 0: max_accel·ΔT when max_accel is given (§2.2), else the cv model's prediction (§14.3)") \
    REAL("split_confirm", split_confirm, 1, 0.0, 1.0, PF_OPEN_LO, NULL, TUNING,                           \
         "with `split`: a track that splits off is confirmed at once when its existence, P(parent) P(split), is at least this and its parent is confirmed; else it starts tentative (§14.3)") \
    REAL("split_decide", split_decide, 1, 0.0, 1.0, PF_OPEN_LO, NULL, TUNING,                      \
         "with `split`: a decoupled split ([S3] eq. 27) becomes two tracks when the split modes' probability μ_5 + μ_6 after the update is at least this (lower values split on clutter, §14.3)") \
    REAL("split_provisional_exist", split_provisional_exist, 1, 0.0, 1.0, 0, NULL, TUNING,        \
         "with `split_known_speed`: a split-off track whose existence falls below this in its first split_provisional_scans scans is deleted (a true child once detected again stays above 0.6 through a miss at PD 0.9, a clutter-driven one falls below in 1 or 2 scans; §14.3)") \
    REAL("split_provisional_scans", split_provisional_scans, 1, 0.0, 1000.0, 0, NULL, TUNING,     \
         "with `split_known_speed`: the scans of a split-off track's age (a whole number) in which split_provisional_exist applies (§14.3)") \
    FLAG("split_across", split_across, TUNING,                                                            \
         "with `split`: true: the split's velocity change (split_dv) is across the course only, the \"just split\" model's gate is widened across it; false: in every direction (§14.3)") \
    FLAG("split_known_speed", split_known_speed, TUNING,                                                  \
         "with `split`: true: a split of known speed, the child leaving at split_dv across the course: the \"just split\" model's child half from the prior moved by split_dv, also a scan late, and a split-off track deleted when its existence falls below split_provisional_exist in its first split_provisional_scans scans; false: split_dv as the impulse's standard deviation only (§14.3)") \
    FLAG("split_decouple_r", split_decouple_r, TUNING,                                                    \
         "with `split`: true: the decoupling test of [S3] eq. 27 on S_1 + S_2 (the halves' predicted measurements, R included); false: on P_11 + P_22 (the halves' position estimates), which decouples a scan or two earlier (§14.3)")
#else
#define MTT_PARAM_SPLIT_P_ROWS(REAL, FLAG, ENUM)
#endif

/* The noise-adaptive process noise of lm_ihpda_variant contest
 * (ALGORITHMS.md §2.1): only in a build with MTT_WITH_CONTEST. */
#if MTT_WITH_CONTEST
#define MTT_PARAM_ADAPT_ROWS(REAL, FLAG, ENUM)                                                    \
    REAL("adapt_s_min", adapt_s_min, 1, 0.0, 1.0, PF_OPEN_LO, NULL, TUNING,                               \
         "lm_ihpda_variant contest: smallest scale s of a confirmed track's process noise (every model's with motion imm), lowered while its innovations are smaller than the filter expects and raised when they grow; 1 with adapt_s_max 1 turns the adaptation off (§2.1)") \
    REAL("adapt_index", adapt_index, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL, TUNING,                      \
         "lm_ihpda_variant contest: s stays at or above Λ²/adapt_index, Λ² = process_psd·ΔT³/σ² the squared tracking index (σ² the mean of σx², σy²): the stronger the configured manoeuvres against the measurement noise, the less the level is lowered (§2.1)") \
    REAL("adapt_memory", adapt_memory, 1, 0.0, 1.0, PF_OPEN_HI, NULL, TUNING,                             \
         "lm_ihpda_variant contest: fading factor α of the average of the normalised innovation squared that drives s (§2.1)") \
    REAL("adapt_gain", adapt_gain, 1, 0.0, 100.0, PF_OPEN_LO, NULL, TUNING,                               \
         "lm_ihpda_variant contest: gain κ of s's update, s ← s·exp(κ(r̄ − 1)) with r̄ the average NIS over its expectation (§2.1)") \
    REAL("adapt_reset_nis", adapt_reset_nis, 1, 0.0, MTT_REAL_MAX, 0, NULL, TUNING,                       \
         "lm_ihpda_variant contest: a confirmed track whose measurement has a normalised innovation squared above this returns to s = 1 at once if s is below 1 (a manoeuvre); 0 never (§2.1)") \
    REAL("adapt_s_max", adapt_s_max, 1, 0.0, MTT_REAL_MAX, 0, NULL, TUNING,                                \
         "lm_ihpda_variant contest: largest scale s: a track whose innovations stay larger than the filter expects raises s above 1 up to this, so an under-guessed max_accel recovers; 1: never above the configured level; 0 (default): 100 with the motion from max_accel, 1 with process_psd given (§2.1, §2.2)")
#else
#define MTT_PARAM_ADAPT_ROWS(REAL, FLAG, ENUM)
#endif

#define MTT_PARAM_ROWS(REAL, FLAG, ENUM)                                                          \
    ENUM("association", association, mtt_assoc, MTT_ASSOC_ROWS, mtt_assoc_names, TUNING,                 \
         "association mode (ALGORITHMS.md §15.1); a build with MTT_WITH_BASELINES=0 accepts only the first four")                                    \
    ENUM("lm_ihpda_variant", lm_ihpda_variant, mtt_lm_ihpda_variant, 2, mtt_lm_ihpda_variant_names, TUNING, \
         "lm-ihpda's algorithm: s0 is [S0] exactly; contest is the contest-aware update with the amplitude likelihood ratio and the adaptive process noise (§10.4, §7.6, §2.1), with motion cv and imm, the default where built (MTT_WITH_CONTEST)") \
    REAL("contest_beta", contest_beta, 1, 0.0, 1.0, PF_OPEN_LO | PF_OPEN_HI, NULL, TUNING,                  \
         "lm_ihpda_variant contest: a measurement that two tracks give an LM-IPDA β >= this is contested (§10.4)") \
    REAL("process_psd", process_psd, 1, 0.0, MTT_REAL_MAX, 0, NULL, SENSOR,                                    \
         "power spectral density Sw of the constant-velocity model's white-noise acceleration, length²/time³ (§2); 0 (not given): derived from max_accel, or 5 when max_accel is not given either (§2.2)")  \
    REAL("max_accel", max_accel, 1, 0.0, MTT_REAL_MAX, 0, NULL, SENSOR,                                        \
         "largest acceleration a target pulls, length/time² (an airliner about 5 m/s², a fighter 90 m/s²); with process_psd not given it derives the motion: the noise of every model per scan, the IMM's models and transitions, split_dv; explicit keys override it; 0: not given (§2.2)")  \
    REAL("meas_sigma", meas_sigma, 2, 1e-9, 1e9, 0, NULL, SENSOR,                                    \
         "measurement noise standard deviations [σx, σy]; R = diag(σx², σy²); with measurement polar [σ_range (length), σ_bearing (radians)] (§3.2)") \
    ENUM("measurement", measurement, mtt_measurement, 2, mtt_measurement_names, SENSOR,                     \
         "form of the detections: cartesian (x, y) or polar (range, bearing from sensor_xy), converted with their own covariance (§3.2); polar needs a float or double build with MTT_WITH_MEAS_COV") \
    REAL("sensor_xy", sensor_xy, 2, -MTT_REAL_MAX, MTT_REAL_MAX, 0, NULL, SENSOR,                            \
         "with measurement polar: the sensor's position [x, y]; bearing = atan2(y − y_s, x − x_s) (§3.2)") \
    REAL("range_rate_sigma", range_rate_sigma, 1, 0.0, MTT_REAL_MAX, 0, NULL, SENSOR,                         \
         "with measurement polar: standard deviation of a detection's range rate, length/time; a detection with one is gated on it and updated with it (the radial velocity), and a birth takes its radial speed from it (§3.2); 0: no range rates (a detection with one is refused)") \
    REAL("pd", pd, 1, 0.0, 1.0, PF_OPEN_LO, NULL, SENSOR, "probability of detection PD")                   \
    REAL("pg", pg, 1, 0.0, 1.0, PF_OPEN_LO | PF_OPEN_HI, NULL, TRACK,                                   \
         "gate probability PG; the gate threshold is γ = −2 ln(1 − PG) (§4)")                       \
    REAL("clutter_density", clutter_density, 1, 0.0, MTT_REAL_MAX, 0, NULL, SENSOR,                             \
         "clutter density λ per unit area; with measurement polar per unit range × bearing (length·radian), λ/r at a detection of range r (§3.2); 0 estimates it per track (§5.2)")                          \
    REAL("snr_rho", snr_rho, 1, 0.0, 1e6, 0, NULL, SENSOR,                                             \
         "intensity parameter ρ: target amplitude mean 1 + ρ, clutter mean 1; 0 ignores amplitude (§7.1)")     \
    REAL("amplitude_eta", amplitude_eta, 1, 0.0, 1.0, PF_OPEN_HI, NULL, TUNING,                          \
         "lm_ihpda_variant contest: share η of untracked-target detections in the background amplitude law; 0 is the plain ratio (§7.6)") \
    MTT_PARAM_ADAPT_ROWS(REAL, FLAG, ENUM)                                                        \
    REAL("markov_p11", markov_p11, 1, 0.0, 1.0, 0, NULL, TRACK,                                         \
         "probability that an existing target still exists at the next scan (§11)")          \
    REAL("markov_p21", markov_p21, 1, 0.0, 1.0, 0, NULL, TRACK,                                         \
         "probability that a target that does not exist appears at the next scan (§11)")                                 \
    REAL("existence_init", existence_init, 1, 0.0, 1.0, PF_OPEN_LO | PF_OPEN_HI, NULL, TRACK,           \
         "existence probability of a new track (§12.1)")                                                  \
    REAL("confirm_threshold", confirm_threshold, 1, 0.0, 1.0, PF_OPEN_LO, NULL, TRACK,                  \
         "a track with existence >= this is confirmed (§12.4)")                                               \
    REAL("terminate_threshold", terminate_threshold, 1, 0.0, 1.0,                                \
         PF_OPEN_HI | PF_BELOW_CONFIRM, "below confirm_threshold", TRACK,                                \
         "a track with existence < this is deleted, and so is a lost one (position variance > (vmax dT)^2 + gamma R); " \
         "0 never deletes (§12.4)")                                                                    \
    REAL("merge_threshold", merge_threshold, 1, 0.0, MTT_REAL_MAX, 0, NULL, TRACK,                             \
         "chi-square threshold of the track-merging test; 0 never merges (§12.3)")                        \
    FLAG("initiate", initiate, TRACK,                                                                    \
         "true starts tracks from unused measurements; false only updates existing (seeded) tracks")               \
    REAL("vmax", vmax, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL, SENSOR,                                          \
         "largest target speed, length/time: the velocity gate of two-point initiation (§12.1)")                           \
    ENUM("init_gate", init_gate, mtt_init_gate, 2, mtt_init_gate_names, TRACK,                           \
         "initiation gate: the vmax circle, or the amplitude-based gate f(I) (§12.2)")                      \
    REAL("intensity_gate.f1", intensity_f1, 3, -MTT_REAL_MAX, MTT_REAL_MAX, 0, NULL, TRACK,                      \
         "coefficients [a2, a1, a0] of f1(I) = a2·I² + a1·I + a0, the initial gate's σ below I_lo (§12.2)")       \
    REAL("intensity_gate.f2", intensity_f2, 3, -MTT_REAL_MAX, MTT_REAL_MAX, 0, NULL, TRACK,                      \
         "coefficients [a2, a1, a0] of f2(I), the initial gate's σ above I_hi (§12.2)")                            \
    REAL("intensity_gate.blend", intensity_blend, 2, -MTT_REAL_MAX, MTT_REAL_MAX, PF_ASCENDING,           \
         "increasing (I_lo < I_hi)", TRACK, "[I_lo, I_hi]: f = f1 below I_lo, f2 above I_hi, a linear blend between (§12.2)") \
    REAL("jpda_bias", jpda_bias, 1, 0.0, MTT_REAL_MAX, 0, NULL, BASELINE,                                         \
         "B of the JPDA family except jipda; 0 uses λ(1 − PD·PG)/PD (§13)")                             \
    FLAG("subopt_jpda_constant_b", subopt_jpda_constant_b, BASELINE,                                      \
         "suboptimal-jpda: true uses [S1]'s constant B in eq. 4 and 5; false (the default) the per-track B_t (§13.4)") \
    REAL("jpda_star_threshold", jpda_star_threshold, 1, 0.0, 1.0, PF_OPEN_HI, NULL, BASELINE,              \
         "pruning probability of JPDA*; 0 is pure JPDA* (§13.6)")                                                             \
    REAL("nnjpda_threshold", nnjpda_threshold, 1, 0.0, 1.0, PF_OPEN_HI, NULL, BASELINE,                    \
         "smallest β that NNJPDA assigns (§13.5)")                                                \
    REAL("adaptive_jpda_distance", adaptive_jpda_distance, 1, 0.0, MTT_REAL_MAX, PF_OPEN_LO, NULL, BASELINE,      \
         "adaptive JPDA: tracks closer than this many measurement sigmas overlap (§13.7)")                 \
    REAL("adaptive_jpda_shrink", adaptive_jpda_shrink, 1, 1.0, MTT_REAL_MAX, 0, NULL, BASELINE,                   \
         "adaptive JPDA: gate shrink factor n of overlapping tracks (§13.7)")                       \
    ENUM("motion", motion, mtt_motion, 3, mtt_motion_names, TUNING,                                        \
         "motion model: `cv` is one constant-velocity filter per track (§2); `imm` an interacting multiple model filter per track over imm_models (§14.1, §14.2), with every association but ihpda-2d and lm-ipda-all; `auto` (the default): imm when the motion follows max_accel (process_psd not given) and the build and the mode have it, else cv (§2.2)") \
    MTT_PARAM_IMM_ROWS(REAL, FLAG, ENUM)                                                          \
    FLAG("split", split, TUNING,                                                                           \
         "true: split-target detection of [S3], the \"just split\" and \"split\" models with the coupled update and decoupling into two tracks; needs motion imm with a cv model (§14.3)") \
    MTT_PARAM_SPLIT_P_ROWS(REAL, FLAG, ENUM)

/* Fixed-point build: the Q format of each REAL row's values
 * (docs/FIXED_POINT.md §3), by member name (params.c's defaults and
 * bounds, params_info.c's conversion from and to double). */
#ifdef MTT_REAL_FIXED
#define MTT_FX_FRAC_contest_beta MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_process_psd MTT_FX_VAR_FRAC
#define MTT_FX_FRAC_max_accel MTT_FX_POS_FRAC
#define MTT_FX_FRAC_meas_sigma MTT_FX_POS_FRAC
#define MTT_FX_FRAC_sensor_xy MTT_FX_POS_FRAC
#define MTT_FX_FRAC_range_rate_sigma MTT_FX_POS_FRAC
#define MTT_FX_FRAC_pd MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_pg MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_clutter_density MTT_FX_DENS_FRAC
#define MTT_FX_FRAC_snr_rho MTT_FX_RATIO_FRAC
#define MTT_FX_FRAC_amplitude_eta MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_markov_p11 MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_markov_p21 MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_existence_init MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_confirm_threshold MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_terminate_threshold MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_merge_threshold MTT_FX_D2_FRAC
#define MTT_FX_FRAC_vmax MTT_FX_POS_FRAC
#define MTT_FX_FRAC_intensity_f1 MTT_FX_AMP_FRAC
#define MTT_FX_FRAC_intensity_f2 MTT_FX_AMP_FRAC
#define MTT_FX_FRAC_intensity_blend MTT_FX_AMP_FRAC
#define MTT_FX_FRAC_jpda_bias MTT_FX_DENS_FRAC
#define MTT_FX_FRAC_jpda_star_threshold MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_nnjpda_threshold MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_adaptive_jpda_distance MTT_FX_RATIO_FRAC
#define MTT_FX_FRAC_adaptive_jpda_shrink MTT_FX_RATIO_FRAC
#define MTT_FX_FRAC_imm_psd MTT_FX_VAR_FRAC
#define MTT_FX_FRAC_imm_transition MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_imm_initial MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_p25 MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_p52 MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_p62 MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_dv MTT_FX_POS_FRAC
#define MTT_FX_FRAC_split_confirm MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_decide MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_provisional_exist MTT_FX_PROB_FRAC
#define MTT_FX_FRAC_split_provisional_scans MTT_FX_RATIO_FRAC
#endif

/* Index of each REAL row among the REAL rows (the rules of params.c). */
#define MTT_PARAM_RULE_ID(key, member, count, lo, hi, flags, cross, tier, text) MTT_RULE_##member,
#define MTT_PARAM_NO_REAL(key, member, count, lo, hi, flags, cross, tier, text)
#define MTT_PARAM_NO_FLAG(key, member, tier, text)
#define MTT_PARAM_NO_ENUM(key, member, type, n_names, names, tier, text)
enum { MTT_PARAM_ROWS(MTT_PARAM_RULE_ID, MTT_PARAM_NO_FLAG, MTT_PARAM_NO_ENUM) MTT_RULE_COUNT };

/* Rule `rule` holds for p: every element finite and within its bounds, and
 * with `cross` nonzero the rule against the other values too (params.c). */
int mtt_params_rule_ok(const mtt_params *p, size_t rule, int cross);

/* The mtt_real elements of REAL row `rule` in p (the offsetof table access
 * of MISRA.md). */
mtt_real *mtt_params_rule_at(mtt_params *p, size_t rule);

#endif /* MTT_PARAMS_TABLE_H */
