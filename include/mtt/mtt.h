/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt/mtt.h - public API of mtt, a bounded multi-target tracker.
 *
 * Per frame: constant-velocity Kalman prediction, ellipsoidal gating,
 * LM-IHPDA association (or IPDA, LM-IPDA, IHPDA, IHPDA with optimal 2-D
 * assignment, JIPDA and the JPDA family), MMR assignment, Markov
 * existence, two-point initiation, merging, confirm/delete.  The algorithm
 * reference is docs/ALGORITHMS.md; "§N" below is its section N.
 *
 * Memory: all state is one caller-allocated mtt_tracker whose size is fixed
 * by mtt/config.h.  No allocation, no I/O, no clocks, no hidden statics: the
 * same inputs give the same outputs.  Not thread-safe per tracker; separate
 * trackers are independent.
 *
 * Every function returns an mtt_status: MTT_OK (0) or a negative error.  On
 * any error the tracker and the output arguments are left unchanged.
 */
#ifndef MTT_MTT_H
#define MTT_MTT_H

#include <stddef.h>
#include <stdint.h>

/* Types and macros only (config.h, real.h, fixed.h declare no function):
 * outside the linkage block, which covers every declaration below and
 * mtt/state.h's. */
#include "mtt/config.h"
#include "mtt/real.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MTT_VERSION_MAJOR 0
#define MTT_VERSION_MINOR 1
#define MTT_VERSION_PATCH 0
#define MTT_VERSION_STRING "0.1.0"

/* The configuration identity: a hash (FNV-1a steps, a constant expression)
 * of everything that fixes the layout or meaning of the tracker state --
 * the version major, every bound of mtt/config.h, the size and kind of
 * mtt_real and the feature switches.  mtt_tracker_init passes the caller's
 * value, and the library refuses one that differs from its own. */
#define MTT_CONFIG_MIX_(h, v) ((((uint32_t)(h)) ^ (uint32_t)(v)) * 16777619u)
#define MTT_CONFIG_ID                                                                              \
    MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(               \
    MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(               \
    MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(               \
    MTT_CONFIG_MIX_(MTT_CONFIG_MIX_(2166136261u,                                                                   \
        MTT_VERSION_MAJOR), MTT_MAX_TRACKS), MTT_MAX_MEAS), MTT_MAX_PAIRS), MTT_MAX_GATED),        \
        MTT_MAX_MERGE_PAIRS), MTT_MAX_ASSIGN_TRACKS), MTT_MAX_JPDA_TRACKS), MTT_MAX_JPDA_MEAS),    \
        MTT_MAX_JPDA_EVENTS), MTT_MAX_STATE), MTT_WITH_BASELINES), MTT_REAL_KIND), sizeof(mtt_real)), \
        MTT_WITH_IMM), MTT_MAX_MODELS), MTT_WITH_CONTEST), MTT_WITH_SPLIT), MTT_MAX_SPLIT_TRACKS), \
        MTT_WITH_MEAS_COV)

#if defined(__GNUC__) || defined(__clang__)
#define MTT_MUST_CHECK __attribute__((warn_unused_result))
#else
#define MTT_MUST_CHECK
#endif

/** Status of every public call. */
typedef enum mtt_status {
    MTT_OK = 0,
    MTT_ERR_NULL = -1,        /**< a required pointer argument is NULL */
    MTT_ERR_PARAM = -2,       /**< a parameter set fails mtt_params_check */
    MTT_ERR_NOT_INIT = -3,    /**< the tracker was not initialised by mtt_tracker_init */
    MTT_ERR_TIME = -4,        /**< time is not finite or does not increase */
    MTT_ERR_RANGE = -5,       /**< an index or count is out of range */
    MTT_ERR_FULL = -6,        /**< the track table is full */
    MTT_ERR_VALUE = -7,       /**< a state or covariance argument is not finite / not positive definite */
    MTT_ERR_UNSUPPORTED = -8, /**< the association mode is not built into this version */
    MTT_ERR_CONFIG = -9       /**< the caller was compiled with another configuration than the
                                   library (MTT_CONFIG_ID, sizeof(mtt_tracker) or sizeof(mtt_params)):
                                   see mtt_tracker_init, mtt_params_default */
} mtt_status;

/** Association mode (docs/FORMATS.md `association`, ALGORITHMS.md §15.1). */
typedef enum mtt_assoc {
    MTT_ASSOC_LM_IHPDA = 0, /**< LM-IHPDA with MMR (default, ALGORITHMS.md §7, §8, §10.1, §10.3) */
    MTT_ASSOC_IHPDA,        /**< single-target IHPDA per track, no assignment (ALGORITHMS.md §7.4) */
    MTT_ASSOC_LM_IPDA,      /**< IPDA with the LM clutter density (ALGORITHMS.md §6, §8) */
    MTT_ASSOC_IPDA,         /**< IPDA per track (ALGORITHMS.md §6) */
    MTT_ASSOC_IHPDA_2D,     /**< IHPDA, optimal 2-D assignment per cluster, plain lambda (ALGORITHMS.md §10.2, §10.3);
                                 clusters over MTT_MAX_ASSIGN_TRACKS use MMR (counts.assign_fallbacks) */
    MTT_ASSOC_JIPDA,        /**< JIPDA: exact enumeration, beta and existence (ALGORITHMS.md §13.2); clusters over
                                 the MTT_MAX_JPDA_* bounds use per-track IPDA (counts.jpda_fallbacks) */
    MTT_ASSOC_JPDA,         /**< exact JPDA (ALGORITHMS.md §13.1); over the bounds Cheap JPDA (counts.jpda_fallbacks) */
    MTT_ASSOC_CHEAP_JPDA,   /**< Cheap JPDA, rows normalised (ALGORITHMS.md §13.3) */
    MTT_ASSOC_SUBOPT_JPDA,  /**< Suboptimal JPDA with the per-track B_t (ALGORITHMS.md §13.4) */
    MTT_ASSOC_NNJPDA,       /**< exact JPDA beta, static MMR, hard update (ALGORITHMS.md §13.5) */
    MTT_ASSOC_JPDA_STAR,    /**< JPDA* with optional pruning (ALGORITHMS.md §13.6) */
    MTT_ASSOC_ADAPTIVE_JPDA,/**< adaptive JPDA: gate shrink and equal split for overlapping tracks (ALGORITHMS.md §13.7) */
    MTT_ASSOC_LM_IPDA_ALL,  /**< lm-ipda with the LM density over all tracks, [S4]'s LM-IPDAF (ALGORITHMS.md §8.3);
                                 a build with MTT_WITH_BASELINES=0 does not know it (MTT_ERR_PARAM, MTT_ERR_RANGE),
                                 nor the next three */
    MTT_ASSOC_JPDA_VG,      /**< exact JPDA with adaptive JPDA's gate shrink ([S1]'s "JPDA (VG change)", ALGORITHMS.md §13.7);
                                 over the bounds Cheap JPDA (counts.jpda_fallbacks) */
    MTT_ASSOC_ADAPTIVE_NNJPDA,   /**< NNJPDA with adaptive JPDA's gate shrink (ALGORITHMS.md §13.7) */
    MTT_ASSOC_ADAPTIVE_JPDA_STAR,/**< JPDA* with adaptive JPDA's gate shrink (ALGORITHMS.md §13.7) */
    MTT_ASSOC_COUNT
} mtt_assoc;

/** Motion model of every track (docs/FORMATS.md `motion`, ALGORITHMS.md §2, §14). */
typedef enum mtt_motion {
    MTT_MOTION_CV = 0,  /**< one constant-velocity filter (ALGORITHMS.md §2) */
    MTT_MOTION_IMM = 1, /**< interacting multiple models imm_model[] (ALGORITHMS.md §14); needs MTT_WITH_IMM
                             and an association other than ihpda-2d and lm-ipda-all, else MTT_ERR_UNSUPPORTED */
    MTT_MOTION_AUTO = 2 /**< the default: imm when the motion follows max_accel (process_psd 0) and the build
                             and the association mode have the IMM, else cv (ALGORITHMS.md §2.2) */
} mtt_motion;

/** A model of an IMM track (docs/FORMATS.md `imm_models`). */
typedef enum mtt_model_kind {
    MTT_MODEL_CV = 0,   /**< nearly constant velocity, white-noise acceleration, psd length²/time³ */
    MTT_MODEL_CA = 1,   /**< nearly constant acceleration, white-noise jerk, psd length²/time⁵ */
    MTT_MODEL_CT = 2    /**< coordinated turn [x y vx vy ω] (extended Kalman): psd as cv on the velocity,
                             and a turn-rate psd (imm_turn_psd) in rad²/time³ on ω */
} mtt_model_kind;

/** Form of the detections (docs/FORMATS.md `measurement`, ALGORITHMS.md §3.2). */
typedef enum mtt_measurement {
    MTT_MEASUREMENT_CARTESIAN = 0, /**< x, y (mtt_tracker_step, mtt_tracker_step_cov) */
    MTT_MEASUREMENT_POLAR = 1      /**< range, bearing from sensor_xy (mtt_tracker_step_polar); needs a
                                        float or double build with MTT_WITH_MEAS_COV, else
                                        MTT_ERR_UNSUPPORTED */
} mtt_measurement;

/** Initial (two-point) velocity gate (ALGORITHMS.md §12.1, §12.2). */
typedef enum mtt_init_gate {
    MTT_INIT_GATE_VMAX = 0,     /**< |z_k - z_{k-1}| <= vmax * dT */
    MTT_INIT_GATE_INTENSITY = 1 /**< chi-square gate with sigma_P = f(I)/sqrt(gamma) ([S2]) */
} mtt_init_gate;

/** The algorithm of the lm-ihpda mode (docs/FORMATS.md `lm_ihpda_variant`). */
typedef enum mtt_lm_ihpda_variant {
    MTT_LM_IHPDA_S0 = 0,      /**< [S0] exactly: rank statistics, MMR, ALGORITHMS.md §10.3 and §7.4 */
    MTT_LM_IHPDA_CONTEST = 1  /**< contest-aware update (ALGORITHMS.md §10.4) with the amplitude
                                   likelihood ratio in place of the ranks (ALGORITHMS.md §7.6);
                                   built with MTT_WITH_CONTEST 1 */
} mtt_lm_ihpda_variant;

/** Stages whose cost the optional cycle counter measures (docs/DESIGN.md). */
typedef enum mtt_stage {
    MTT_STAGE_VALIDATE = 0,
    MTT_STAGE_PREDICT,
    MTT_STAGE_GATE,
    MTT_STAGE_LM_CLUTTER,
    MTT_STAGE_ASSOCIATE,   /* clusters and the mode's whole association: every beta row,
                              selection / assignment, the final recomputation */
    MTT_STAGE_UPDATE,      /* state and existence update only */
    MTT_STAGE_INITIATE,
    MTT_STAGE_MERGE,
    MTT_STAGE_MANAGE,
    MTT_STAGE_COUNT
} mtt_stage;

/** A user cycle counter: returns a free-running count (wraps modulo 2^32). */
typedef uint32_t (*mtt_cycle_fn)(void *ctx);

/** Tracker parameters; mtt_params_default gives docs/FORMATS.md's defaults.
 *  Each field's settings key, range and meaning: see mtt_params_info (the
 *  key is the field's name, intensity_f1 is "intensity_gate.f1", ...). */
typedef struct mtt_params {
    mtt_assoc association;      /**< association mode */
    mtt_lm_ihpda_variant lm_ihpda_variant; /**< lm-ihpda: [S0] or the contest-aware rule */
    mtt_real contest_beta;      /**< contest threshold on the LM-IPDA beta (ALGORITHMS.md §10.4) */
    mtt_real process_psd;       /**< Sw of the CV model; 0: derived from max_accel (ALGORITHMS.md §2.2) */
    mtt_real max_accel;         /**< largest target acceleration, length/time^2; 0: not given */
    mtt_real meas_sigma[2];     /**< sx, sy (sigma^2 stays a normal float); polar: sigma_range
                                     (length), sigma_bearing (radians) */
    mtt_measurement measurement;/**< cartesian or polar detections (ALGORITHMS.md §3.2) */
    mtt_real sensor_xy[2];      /**< polar: the sensor's position */
    mtt_real range_rate_sigma;  /**< polar: sigma of a detection's range rate, length/time; 0: none given */
    mtt_real pd;                /**< detection probability; PD PG < 1 holds as pg < 1 */
    mtt_real pg;                /**< gate probability */
    mtt_real clutter_density;   /**< per unit area (polar: per unit range x bearing, length rad);
                                     0 estimates it per track (ALGORITHMS.md §5.2, §3.2) */
    mtt_real snr_rho;           /**< amplitude model rho; 0 ignores amplitude */
    mtt_real amplitude_eta;     /**< background share eta of the amplitude ratio (ALGORITHMS.md §7.6) */
#if MTT_WITH_CONTEST
    mtt_real adapt_s_min;       /**< contest: smallest process-noise scale of a confirmed track (ALGORITHMS.md §2.1) */
    mtt_real adapt_index;       /**< the scale stays >= process_psd dt^3 / (sigma^2 adapt_index) */
    mtt_real adapt_memory;      /**< its NIS average's fading factor */
    mtt_real adapt_gain;        /**< its update gain */
    mtt_real adapt_reset_nis;   /**< a NIS above this raises the scale to at least 1 at once; 0 never */
    mtt_real adapt_s_max;       /**< largest scale: the scale rises above 1 up to this */
#endif
    mtt_real markov_p11;        /**< existence Markov chain: stays */
    mtt_real markov_p21;        /**< existence Markov chain: appears */
    mtt_real existence_init;    /**< existence of a new track */
    mtt_real confirm_threshold; /**< existence that confirms */
    mtt_real terminate_threshold; /**< existence below which a track goes (and a lost one, §12.4); 0 never deletes */
    mtt_real merge_threshold;   /**< merging test threshold; 0 never merges */
    int initiate;               /**< nonzero: start tracks from unused measurements */
    mtt_real vmax;              /**< length per time */
    mtt_init_gate init_gate;    /**< two-point velocity gate */
    mtt_real intensity_f1[3];   /**< f1(I) = a2 I^2 + a1 I + a0 (default [S2]) */
    mtt_real intensity_f2[3];   /**< f2(I) (default [S2]) */
    mtt_real intensity_blend[2];/**< I_lo < I_hi of the f1/f2 blend */
    mtt_real jpda_bias;         /**< JPDA family B; 0 means lambda(1-PD*PG)/PD (ALGORITHMS.md §13) */
    int subopt_jpda_constant_b; /**< nonzero: suboptimal-jpda with [S1]'s constant B (ALGORITHMS.md §13.4) */
    mtt_real jpda_star_threshold;   /**< JPDA* pruning probability */
    mtt_real nnjpda_threshold;      /**< NNJPDA minimum beta */
    mtt_real adaptive_jpda_distance;/**< overlap distance in sigmas */
    mtt_real adaptive_jpda_shrink;  /**< gate shrink factor */
    mtt_motion motion;              /**< cv, imm (ALGORITHMS.md §14), or auto (the default, §2.2) */
    uint8_t imm_n_models;           /**< r: models of an IMM track, 2..MTT_MAX_MODELS */
    mtt_model_kind imm_model[MTT_MAX_MODELS]; /**< model j (imm_models[j].model) */
    mtt_real imm_psd[MTT_MAX_MODELS];         /**< its process noise (imm_models[j].process_psd); all 0:
                                                   imm_models not given (ALGORITHMS.md §2.2) */
#if MTT_WITH_IMM
    mtt_real imm_turn_psd[MTT_MAX_MODELS];    /**< its turn-rate noise (imm_models[j].turn_psd): > 0 for ct,
                                                   0 for the other models; only in a build with the IMM */
#endif
    mtt_real imm_transition[MTT_MAX_MODELS][MTT_MAX_MODELS]; /**< P(model j at k | model i at k-1), rows sum
                                                   to 1; all 0: not given (ALGORITHMS.md §2.2) */
    mtt_real imm_initial[MTT_MAX_MODELS];     /**< model probabilities of a new or seeded track, sum 1; all 0:
                                                   not given */
    int split;                      /**< nonzero: split-target detection (ALGORITHMS.md §14.3); needs
                                         motion = imm, a cv entry in imm_models and MTT_WITH_SPLIT; takes
                                         a covariance per detection and polar detections (and their range rates) */
    mtt_real split_p25;             /**< per scan: cv -> "just split" */
    mtt_real split_p52;             /**< "just split" -> cv (no second target); the rest -> "split" */
    mtt_real split_p62;             /**< per scan: "split" -> cv (the two targets recombine) */
    mtt_real split_dv;              /**< velocity change of a split, length/time per axis (std); 0 with
                                         max_accel: max_accel dt (ALGORITHMS.md §2.2) */
#if MTT_WITH_SPLIT
    mtt_real split_confirm;         /**< a split-off track's existence at or above: confirmed at once */
    mtt_real split_decide;          /**< μ_5 + μ_6 at or above: a decoupled split is two tracks */
    mtt_real split_provisional_exist; /**< split_known_speed: a split-off track below this existence ... */
    mtt_real split_provisional_scans; /**< ... in its first this many scans is deleted */
    int split_across;               /**< nonzero: split_dv across the course only (ALGORITHMS.md §14.3) */
    int split_known_speed;          /**< nonzero: the child leaves at split_dv across the course
                                         (model 5's child half, the late split, the provisional
                                         child; ALGORITHMS.md §14.3) */
    int split_decouple_r;           /**< nonzero: the decoupling test on S_1 + S_2 ([S3] eq. 27);
                                         0: on P_11 + P_22 (ALGORITHMS.md §14.3 [CHOICE]); only in a
                                         build with the split (the firmware's layout unchanged) */
#endif
    mtt_cycle_fn cycle_counter; /**< optional; when set, stats hold per-stage cycles */
    void *cycle_ctx;            /**< passed to cycle_counter */
} mtt_params;

/** Values per imm_models slot in mtt_params_set / get: model, process_psd, turn_psd. */
#define MTT_PARAM_MODEL_VALUES 3

/** Type of a settings key (mtt_param_info). */
typedef enum mtt_param_type {
    MTT_PARAM_REAL = 0, /**< count mtt_real values */
    MTT_PARAM_BOOL,     /**< one value, 0 or 1 (a JSON boolean) */
    MTT_PARAM_ENUM,     /**< one value, the index of one of names[] */
    MTT_PARAM_MODELS    /**< imm_models: a list of up to count {model, process_psd, turn_psd}.
                             mtt_params_set/get take 1 + MTT_PARAM_MODEL_VALUES count values: r, then
                             (model index into names[], psd, turn psd) for each of count slots (slots
                             from r on are ignored by set, zero from get); psd within lo, hi; turn psd
                             > 0 (and finite in mtt_real) for ct, 0 for the other models.  Setting it
                             resets imm_transition and imm_initial to their defaults for r models */
} mtt_param_type;

/** Tier of a settings key (docs/CONFIGURATION.md): who sets it and from what. */
typedef enum mtt_param_tier {
    MTT_PARAM_TIER_SENSOR = 0, /**< the sensor and the targets: facts the user knows (pd, meas_sigma, ...) */
    MTT_PARAM_TIER_TRACK,      /**< track management: gate, existence, initiation, confirm, delete, merge */
    MTT_PARAM_TIER_TUNING,     /**< the choice of algorithm and its variants' tuning (contest, IMM, split) */
    MTT_PARAM_TIER_BASELINE,   /**< read by the baseline modes only (MTT_WITH_BASELINES) */
    MTT_PARAM_TIER_COUNT
} mtt_param_tier;

/** One settings key of mtt_params: the table behind mtt_params_check,
 *  mtt-track's settings reader and docs/FORMATS.md's settings table. */
typedef struct mtt_param_info {
    const char *key;          /**< settings key as docs/FORMATS.md spells it; nested keys
                                   dotted ("intensity_gate.f1") */
    mtt_param_type type;
    uint8_t count;            /**< number of values (2 for meas_sigma, 3 for intensity_gate.f1) */
    double lo, hi;            /**< MTT_PARAM_REAL: every value finite and within [lo, hi];
                                   +-MTT_REAL_MAX (as double) is no bound: any value
                                   mtt_real holds.  BOOL: 0, 1.  ENUM: 0, n_names - 1 */
    uint8_t lo_open, hi_open; /**< 1 = bound excluded */
    const char *const *names; /**< MTT_PARAM_ENUM: the spellings, index = value; else NULL */
    uint8_t n_names;
    uint8_t per_model;        /**< 0; 1: one value per IMM model (count = MTT_MAX_MODELS slots, the
                                   first r used, the rest 0); 2: an r x r matrix in MTT_MAX_MODELS^2
                                   slots, row-major with row length MTT_MAX_MODELS */
    const char *cross;        /**< rule against other values that only mtt_params_check
                                   applies ("below confirm_threshold"); NULL if none */
    const char *text;         /**< one-line meaning */
    mtt_param_tier tier;      /**< sensor, track, tuning or baseline */
} mtt_param_info;


/** One detection.  Coordinates in the user's length unit. */
typedef struct mtt_meas {
    mtt_real x, y;
    mtt_real amplitude;   /**< >= 0, used when has_amplitude is nonzero */
    int has_amplitude;    /**< 0: intensity unknown for this detection */
} mtt_meas;

/** The covariance of one detection (mtt_tracker_step_cov, ALGORITHMS.md
 *  §3.1), in length^2.  All three 0: the detection has meas_sigma's.  Else
 *  it must be finite with r_xx > 0, r_yy > 0 and r_xx r_yy > r_xy^2, or the
 *  detection is skipped and counted in meas_bad. */
typedef struct mtt_meas_cov {
    mtt_real r_xx, r_xy, r_yy;
} mtt_meas_cov;

/** One polar detection (mtt_tracker_step_polar, ALGORITHMS.md §3.2): range
 *  in the user's length unit from params.sensor_xy, bearing in radians,
 *  atan2(y - y_s, x - x_s).  Range must be finite and > 0, bearing finite,
 *  or the detection is skipped and counted in meas_bad. */
typedef struct mtt_polar {
    mtt_real range, bearing;
    mtt_real amplitude;   /**< >= 0, used when has_amplitude is nonzero */
    int has_amplitude;    /**< 0: intensity unknown for this detection */
    mtt_real range_rate;  /**< length/time, finite, used when has_range_rate is nonzero: gated and
                               updated with as the radial velocity (ALGORITHMS.md §3.2) */
    int has_range_rate;   /**< 0: no range rate for this detection */
} mtt_polar;

/** mtt_track_view.parent of a track that did not split off another. */
#define MTT_NO_PARENT ((uint32_t)0xFFFFFFFFu)

/** Read-only view of one live track. */
typedef struct mtt_track_view {
    uint32_t id;          /**< unique for the tracker's life, never reused */
    int confirmed;        /**< 1 once existence reached confirm_threshold (sticky) */
    mtt_real x[4];        /**< x, y, vx, vy (fixed point: Q MTT_FX_POS_FRAC; velocity per frame) */
    mtt_real P[4][4];     /**< state covariance (fixed point: Q MTT_FX_VAR_FRAC, saturated) */
    mtt_real existence;   /**< P(target exists | Z^k) in [0, 1] (fixed point: Q30) */
    uint32_t age;         /**< frames since birth */
    int32_t meas;         /**< input index of the measurement used this frame, or -1 */
    uint8_t n_models;     /**< 1 (motion = cv), or r of motion = imm */
    mtt_real mu[MTT_MAX_MODELS]; /**< model probabilities after this frame's update, imm_models
                                      order, sum 1 (ALGORITHMS.md §14.1); mu[0] = 1 with cv */
    uint8_t split;        /**< 1 when the tracker runs split = true (p_split and parent below) */
    mtt_real p_split;     /**< split = true: P(split) = μ("just split") + μ("split") after this
                               frame's update (ALGORITHMS.md §14.3); 0 otherwise */
    uint32_t parent;      /**< id of the track this one split off from, MTT_NO_PARENT if none */
} mtt_track_view;

/** Event counters (one frame, or cumulative).  Every field is a uint32_t
 *  (mtt_tracker_step adds them as such); a new one goes at the end, and
 *  sizeof(mtt_tracker) carries the change to mtt_tracker_init's check. */
typedef struct mtt_counts {
    uint32_t frames;          /**< frames stepped */
    uint32_t meas_in;         /**< measurements passed in */
    uint32_t meas_bad;        /**< skipped: NaN/Inf coordinate, negative/NaN/Inf amplitude (malformed;
                                   out of range: meas_out_of_range) */
    uint32_t meas_dropped;    /**< valid, but beyond MTT_MAX_MEAS (weakest dropped) */
    uint32_t pairs;           /**< gated pairs kept */
    uint32_t pairs_dropped;   /**< gated, but beyond MTT_MAX_PAIRS (least likely dropped) */
    uint32_t gated_dropped;   /**< gated, but beyond MTT_MAX_GATED in one gate (largest d^2 dropped) */
    uint32_t clusters;        /**< clusters formed (ALGORITHMS.md §9) */
    uint32_t births;          /**< tentative tracks started */
    uint32_t births_dropped;  /**< pairs that passed the velocity gate with the table full */
    uint32_t merges;          /**< tracks removed by merging */
    uint32_t merge_dropped;   /**< merge candidates beyond MTT_MAX_MERGE_PAIRS */
    uint32_t deletions;       /**< tracks deleted on existence */
    uint32_t numeric_deletions; /**< tracks deleted for a non-positive-definite S (ALGORITHMS.md §3) */
    uint32_t confirmations;   /**< tracks confirmed */
    uint32_t assign_fallbacks;/**< ihpda-2d clusters over MTT_MAX_ASSIGN_TRACKS, resolved by MMR */
    uint32_t jpda_fallbacks;  /**< clusters over the exact-JPDA bounds (tracks, measurements, events):
                                   Cheap JPDA instead (per-track IPDA in jipda) */
    uint32_t splits;          /**< split = true: tracks split off a parent (decoupled, ALGORITHMS.md §14.3) */
    uint32_t split_dropped;   /**< split = true: split hypotheses dropped (split pool or track table full) */
    uint32_t meas_out_of_range; /**< skipped: a value outside the build's range, not counted in
                                     meas_bad (fixed point: a coordinate beyond +-MTT_FX_POS_LIMIT,
                                     a saturated amplitude; always 0 in float and double) */
} mtt_counts;

/** Statistics: the last frame, the tracker's life, and per-stage cycles. */
typedef struct mtt_stats {
    mtt_counts last;
    mtt_counts total;
    uint32_t stage_cycles[MTT_STAGE_COUNT]; /**< last frame; all 0 without a cycle counter */
    uint32_t max_cluster_tracks;  /**< largest cluster of the last frame (tracks) */
} mtt_stats;

/** A parameter set prepared for mtt_tracker_load (docs/FIRMWARE.md,
 *  "Parameters prepared on the host"): mtt_params_prepare checks it and
 *  computes what depends only on it, so that a firmware loads it without
 *  linking the checks, their range table or the logarithm (about 1.6 KiB of
 *  the fixed-point M0+ image).  A firmware holds it as a constant, written
 *  as C by the host (mtt_io_write_prepared, mtt-track --prepared-c) from a
 *  build of the same configuration.  Fill it only with mtt_params_prepare or
 *  that C text: mtt_tracker_load checks its mark and configuration, not the
 *  values again. */
typedef struct mtt_prepared {
    uint32_t mark;      /**< MTT_PREPARED_MARK: written by mtt_params_prepare */
    uint32_t config_id; /**< MTT_CONFIG_ID of the build that prepared it */
    mtt_params par;     /**< the checked parameters (cycle_counter and cycle_ctx NULL:
                             mtt_tracker_load takes them) */
    mtt_real gamma;     /**< the gate threshold -2 ln(1 - pg) (ALGORITHMS.md §4) */
} mtt_prepared;

/** mtt_prepared.mark of a prepared set ("MTTP"). */
#define MTT_PREPARED_MARK 0x5054544du

/* The tracker state (mtt_tracker), so that callers can allocate it.  Its
 * layout is not API: use the functions. */
#include "mtt/state.h"

/* ------------------------------------------------------------------------
 * Functions
 * ---------------------------------------------------------------------- */

/* The parameter functions that read or write an mtt_params are macros, as
 * mtt_tracker_init: mtt_params' layout follows the configuration
 * (MTT_WITH_CONTEST, MTT_WITH_IMM, MTT_WITH_SPLIT, MTT_MAX_MODELS,
 * mtt_real), so each passes the caller's sizeof(mtt_params) and
 * MTT_CONFIG_ID to its _checked function, which returns MTT_ERR_CONFIG on a
 * mismatch with nothing written (after MTT_ERR_NULL for a NULL pointer).
 * Call them through the macros. */
#define MTT_PARAMS_GUARD_ sizeof(mtt_params), (uint32_t)(MTT_CONFIG_ID)

/** Fill p with docs/FORMATS.md's defaults ([S0]'s IR set-up).
 *  @return MTT_OK; MTT_ERR_NULL if p is NULL; MTT_ERR_CONFIG. */
#define mtt_params_default(p) mtt_params_default_checked((p), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_default_checked(mtt_params *p, size_t params_size,
                                                     uint32_t config_id);

/** Validate a parameter set.
 *  @param bad_field if not NULL, receives the settings key of the first invalid
 *         field (a static string such as "pd", "intensity_gate.blend"), or NULL
 *         when valid.
 *  @return MTT_OK; MTT_ERR_NULL if p is NULL; MTT_ERR_PARAM if a field is out
 *          of its range or not finite, or breaks a rule between fields (the
 *          ranges and rules: see mtt_params_info); MTT_ERR_UNSUPPORTED if the
 *          association mode is not built into this version (bad_field =
 *          "association"), nor the IMM ("motion"), nor lm-ihpda's contest
 *          variant (MTT_WITH_CONTEST 0, "lm_ihpda_variant"); in the fixed-point
 *          build MTT_ERR_PARAM "max_accel" when the motion follows it and
 *          max_accel² does not fit the variance format (docs/FIXED_POINT.md
 *          §3); MTT_ERR_CONFIG (bad_field not written). */
#define mtt_params_check(p, bad_field) mtt_params_check_checked((p), (bad_field), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_check_checked(const mtt_params *p, const char **bad_field,
                                                   size_t params_size, uint32_t config_id);

/** The parameters as the tracker runs them (ALGORITHMS.md §2.2): out = p with
 *  the keys left out resolved: motion auto to cv or imm, process_psd 0 and
 *  imm_models, imm_transition, imm_initial not given and split_dv 0 to their
 *  values, from max_accel where the motion follows it.  Values that follow the
 *  scan interval ΔT (process_psd = max_accel² ΔT, ...) are given at ΔT = 1.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_CONFIG; the errors of
 *          mtt_params_check (out is then unchanged). */
#define mtt_params_resolve(p, out) mtt_params_resolve_checked((p), (out), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_resolve_checked(const mtt_params *p, mtt_params *out,
                                                     size_t params_size, uint32_t config_id);

/** The i-th settings key, 0 <= i < number of keys, in docs/FORMATS.md order.
 *  Host use (tools, bindings): a firmware that never calls the mtt_params_info /
 *  find / set / get functions does not link their table or double arithmetic.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE past the last key. */
MTT_MUST_CHECK mtt_status mtt_params_info(size_t i, const mtt_param_info **info);

/** Index of a settings key ("pd", "intensity_gate.blend").
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE if the key is unknown. */
MTT_MUST_CHECK mtt_status mtt_params_find(const char *key, size_t *i);

/** Set the n values of a key (REAL: the values; BOOL: v[0] 0 or 1; ENUM:
 *  v[0] the index into names).  Each value must lie in the key's range and
 *  fit mtt_real; rules between keys (terminate_threshold below
 *  confirm_threshold, blend increasing) are left to mtt_params_check.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_CONFIG; MTT_ERR_RANGE if the key is
 *          unknown or n is not its count; MTT_ERR_PARAM if a value is out of
 *          range.  On error p is unchanged. */
#define mtt_params_set(p, key, v, n) mtt_params_set_checked((p), (key), (v), (n), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_set_checked(mtt_params *p, const char *key, const double *v,
                                                 size_t n, size_t params_size, uint32_t config_id);

/** Get the n values of a key, as mtt_params_set takes them.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_CONFIG; MTT_ERR_RANGE if the key is
 *          unknown or n is not its count.  On error v is unchanged. */
#define mtt_params_get(p, key, v, n) mtt_params_get_checked((p), (key), (v), (n), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_get_checked(const mtt_params *p, const char *key, double *v,
                                                 size_t n, size_t params_size, uint32_t config_id);

/** Initialise (or reset) a tracker.  Cost: O(MTT_MAX_GATED^2) for the rank table.
 *  A macro, as zlib's deflateInit: it passes the caller's sizeof(mtt_tracker)
 *  and MTT_CONFIG_ID, so a program compiled with other bounds, another
 *  mtt_real or other feature switches than the library it links is refused
 *  instead of corrupting memory.  Compile the caller with the library's
 *  definitions (the CMake target mtt::mtt and pkg-config mtt carry them).
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_CONFIG on a configuration mismatch
 *          (nothing is written, p is not read); MTT_ERR_PARAM /
 *          MTT_ERR_UNSUPPORTED as mtt_params_check (the tracker is then left
 *          uninitialised). */
#define mtt_tracker_init(trk, p) \
    mtt_tracker_init_checked((trk), (p), sizeof(mtt_tracker), (uint32_t)(MTT_CONFIG_ID))

/** mtt_tracker_init with the caller's size of mtt_tracker and configuration
 *  identity given explicitly; call it through the macro. */
MTT_MUST_CHECK mtt_status mtt_tracker_init_checked(mtt_tracker *trk, const mtt_params *p,
                                                   size_t tracker_size, uint32_t config_id);

/** Check p (as mtt_params_check) and prepare it for mtt_tracker_load:
 *  out receives p (its cycle_counter and cycle_ctx NULL), the gate
 *  threshold, the mark and this build's MTT_CONFIG_ID.  mtt_tracker_init
 *  gives the tracker that mtt_params_prepare and mtt_tracker_load give.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_CONFIG; MTT_ERR_PARAM /
 *          MTT_ERR_UNSUPPORTED as mtt_params_check.  On error out is
 *          unchanged. */
#define mtt_params_prepare(p, out) mtt_params_prepare_checked((p), (out), MTT_PARAMS_GUARD_)
MTT_MUST_CHECK mtt_status mtt_params_prepare_checked(const mtt_params *p, mtt_prepared *out,
                                                     size_t params_size, uint32_t config_id);

/** Initialise (or reset) a tracker from a prepared parameter set, with the
 *  cycle counter fn (may be NULL) and its ctx.  Cost: O(MTT_MAX_GATED^2)
 *  for the rank table; links neither mtt_params_check nor the logarithm.
 *  A macro, as mtt_tracker_init: it passes the caller's sizeof(mtt_tracker)
 *  and MTT_CONFIG_ID.
 *  @return MTT_OK; MTT_ERR_NULL (trk or pp); MTT_ERR_CONFIG on a
 *          configuration mismatch of the caller, or a set prepared by a
 *          build of another configuration; MTT_ERR_PARAM if pp's mark is
 *          not MTT_PREPARED_MARK (not a prepared set).  On error nothing is
 *          written. */
#define mtt_tracker_load(trk, pp, fn, ctx) \
    mtt_tracker_load_checked((trk), (pp), (fn), (ctx), sizeof(mtt_tracker), (uint32_t)(MTT_CONFIG_ID))

/** mtt_tracker_load with the caller's size of mtt_tracker and configuration
 *  identity given explicitly; call it through the macro. */
MTT_MUST_CHECK mtt_status mtt_tracker_load_checked(mtt_tracker *trk, const mtt_prepared *pp,
                                                   mtt_cycle_fn fn, void *ctx,
                                                   size_t tracker_size, uint32_t config_id);

/** Run one frame at time `time` with n measurements (meas may be NULL when n = 0).
 *  Bad detections are skipped and counted; beyond MTT_MAX_MEAS the strongest
 *  amplitudes are kept (detections without amplitude rank below any amplitude,
 *  then by position).  The order of meas does not matter: the kept ones are
 *  stored by position (x, then y, then amplitude), so the tracks and their
 *  identities are the same for any order (ALGORITHMS.md §15).
 *  Cost, every mode: O(n log n + tracks + pairs) for validation, gating,
 *  the LM densities, clusters, update and initiation (an x sweep), plus
 *  merging O(sum over clusters of tracks^2).  Association per cluster of
 *  t tracks and m measurements: MMR (lm-ihpda) O(t^2 * gated), IPDA modes
 *  O(pairs), Cheap / Suboptimal JPDA O(pairs * neighbouring tracks),
 *  ihpda-2d O(t^3) up to MTT_MAX_ASSIGN_TRACKS, the exact JPDA family and
 *  JIPDA O(events) up to MTT_MAX_JPDA_EVENTS (then the counted fallback).
 *  Overflow (counted in the stats): beyond MTT_MAX_MEAS a heap keeps the
 *  strongest, O(n log MTT_MAX_MEAS); but the other caps let the worst entry
 *  give way by a linear scan, so each entry over a cap costs a scan of it:
 *  O(MTT_MAX_PAIRS) per pair beyond MTT_MAX_PAIRS, O(MTT_MAX_GATED) per
 *  measurement beyond a full gate, O(MTT_MAX_MERGE_PAIRS) per merge
 *  candidate beyond it.  A frame that overflows MTT_MAX_PAIRS by e pairs
 *  thus costs up to e * MTT_MAX_PAIRS more: size the bounds for the scene.
 *  Every loop is bounded by config.h; nothing allocates or recurses.
 *  @return MTT_OK; MTT_ERR_NULL (trk NULL, or meas NULL with n > 0);
 *          MTT_ERR_NOT_INIT; MTT_ERR_TIME if time is not finite or not greater
 *          than the previous frame's time.  On error nothing changes.
 *  Fixed point (MTT_REAL_FIXED, docs/FIXED_POINT.md): time is a Q16 count
 *  of frames modulo 2^32, greater meaning 0 < time - previous < 2^31 taken
 *  modulo 2^32; every value in its format (mtt/real.h). */
MTT_MUST_CHECK mtt_status mtt_tracker_step(mtt_tracker *trk, mtt_real time,
                                           const mtt_meas *meas, size_t n);

/** mtt_tracker_step with a covariance per detection: cov[i] is meas[i]'s
 *  (cov may be NULL: then this is mtt_tracker_step).  A detection with one
 *  is gated, weighed, updated with and initiated from its own R, in every
 *  mode, with the IMM and in the split modes (split = true, ALGORITHMS.md
 *  §14.3); one whose cov[i] is all 0 has meas_sigma's
 *  (ALGORITHMS.md §3.1).  The canonical order takes the covariance after
 *  the amplitude.
 *  @return as mtt_tracker_step; MTT_ERR_UNSUPPORTED, before anything is
 *          written, when a cov[i] is nonzero and the build has no
 *          MTT_WITH_MEAS_COV (the firmware configurations, the fixed-point
 *          build at its default scale); MTT_ERR_UNSUPPORTED
 *          (this and mtt_tracker_step) when its measurement is polar. */
MTT_MUST_CHECK mtt_status mtt_tracker_step_cov(mtt_tracker *trk, mtt_real time, const mtt_meas *meas,
                                               const mtt_meas_cov *cov, size_t n);

/** mtt_tracker_step with polar detections (ALGORITHMS.md §3.2): each is
 *  converted to Cartesian with the unbiased converted measurement of Mo et
 *  al. (1998) from meas_sigma = [sigma_range, sigma_bearing] and given its
 *  own covariance, and the clutter density at it is clutter_density / range
 *  (per unit range x bearing to per unit area).  Then as
 *  mtt_tracker_step_cov; the canonical order is that of the converted
 *  detections.  A detection with a range rate (has_range_rate) is also
 *  gated on it and updated with it, an extended Kalman update of the radial
 *  velocity with variance range_rate_sigma^2, and a birth from it takes its
 *  radial velocity from it.  With split = true the split modes take the
 *  converted detections with their own R (ALGORITHMS.md §14.3), and a
 *  range rate is refused.  det may be NULL when n = 0.  A range, bearing
 *  or range rate that is not finite, or a range <= 0: skipped, meas_bad.
 *  @return as mtt_tracker_step; MTT_ERR_UNSUPPORTED, before anything is
 *          written, when the tracker's measurement is not polar (and the
 *          build without MTT_WITH_MEAS_COV, whose params_check refuses
 *          polar), or when a detection has a range rate and the tracker
 *          runs split = true; MTT_ERR_PARAM, before anything is written,
 *          when a detection has a range rate and range_rate_sigma is 0. */
MTT_MUST_CHECK mtt_status mtt_tracker_step_polar(mtt_tracker *trk, mtt_real time, const mtt_polar *det,
                                                 size_t n);

/** The Cartesian detection and covariance that mtt_tracker_step_polar makes
 *  of det (ALGORITHMS.md §3.2): sigma = [sigma_range, sigma_bearing] (the
 *  polar meas_sigma), sensor = sensor_xy.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_VALUE if det's range is not finite
 *          and > 0, its bearing not finite, a sigma not finite and > 0, or
 *          the result not finite; MTT_ERR_UNSUPPORTED without
 *          MTT_WITH_MEAS_COV and in the fixed-point build (MTT_WITH_POLAR
 *          0).  On error m and cov are unchanged. */
MTT_MUST_CHECK mtt_status mtt_polar_to_cartesian(const mtt_real sigma[2], const mtt_real sensor[2],
                                                 const mtt_polar *det, mtt_meas *m, mtt_meas_cov *cov);

/** Add a known (seeded) track: confirmed, existence 1 (docs/FORMATS.md initial_tracks).
 *  @param x state [x, y, vx, vy]; @param P 4x4 covariance, row-major (16
 *         values; pass &P[0][0] for a mtt_real[4][4]), symmetric (to 1e-6
 *         relative) and positive definite with room for rounding: every
 *         Cholesky pivot of its correlation matrix above 1000 epsilon of
 *         mtt_real (correlations up to about 0.99994 in float).
 *  @param id if not NULL, receives the new track's identity.
 *  @return MTT_OK; MTT_ERR_NULL (trk, x or P); MTT_ERR_NOT_INIT; MTT_ERR_VALUE
 *          if x or P is not finite, P is not symmetric, or not positive
 *          definite with that margin;
 *          MTT_ERR_FULL if MTT_MAX_TRACKS tracks are live. */
MTT_MUST_CHECK mtt_status mtt_tracker_add_track(mtt_tracker *trk, const mtt_real x[4],
                                                const mtt_real P[16], uint32_t *id);

/** Number of live tracks (tentative and confirmed).
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_NOT_INIT. */
MTT_MUST_CHECK mtt_status mtt_tracker_count(const mtt_tracker *trk, size_t *count);

/** View of live track i, 0 <= i < count, in ascending identity.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_NOT_INIT; MTT_ERR_RANGE. */
MTT_MUST_CHECK mtt_status mtt_tracker_track(const mtt_tracker *trk, size_t i,
                                            mtt_track_view *view);

/** Statistics of the last frame and of the tracker's life.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_NOT_INIT. */
MTT_MUST_CHECK mtt_status mtt_tracker_stats(const mtt_tracker *trk, mtt_stats *stats);

/** The two-point initial covariance of ALGORITHMS.md §12.1 for measurement sigmas
 *  (sx, sy) and frame interval dt > 0: [[R, R/dt], [R/dt, 2R/dt^2]] (fixed
 *  point: sigmas and P as in mtt_track_view, dt in Q16 frames).
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_VALUE if an argument is not finite
 *          or not positive. */
MTT_MUST_CHECK mtt_status mtt_init_two_point_cov(mtt_real sx, mtt_real sy, mtt_real dt,
                                                 mtt_real P[4][4]);

/** Name of an association mode as docs/FORMATS.md spells it ("lm-ihpda", ...). */
MTT_MUST_CHECK mtt_status mtt_assoc_name(mtt_assoc a, const char **name);

/** Parse a docs/FORMATS.md association name.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE if the name is unknown. */
MTT_MUST_CHECK mtt_status mtt_assoc_parse(const char *name, mtt_assoc *a);

/** Human-readable text of a status ("ok", "null pointer", ...). */
MTT_MUST_CHECK mtt_status mtt_status_text(mtt_status s, const char **text);

#ifdef __cplusplus
}
#endif

#endif /* MTT_MTT_H */
