/* mtt/mtt.h - public API of mtt, a bounded multi-target tracker.
 *
 * Per frame: constant-velocity Kalman prediction, ellipsoidal gating,
 * LM-IHPDA association (or IPDA, LM-IPDA, IHPDA, IHPDA with optimal 2-D
 * assignment, JIPDA and the JPDA family), MMR assignment, Markov
 * existence, two-point initiation, merging, confirm/delete.  The algorithm
 * reference is ALGORITHMS.md ("spec"); section numbers below point into it.
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

#include "mtt/config.h"
#include "mtt/real.h"

#ifdef __cplusplus
extern "C" {
#endif

#define MTT_VERSION_MAJOR 0
#define MTT_VERSION_MINOR 1
#define MTT_VERSION_PATCH 0
#define MTT_VERSION_STRING "0.1.0"

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
    MTT_ERR_UNSUPPORTED = -8  /**< the association mode is not built into this version */
} mtt_status;

/** Association mode (FORMATS.md `association`, spec 15.1). */
typedef enum mtt_assoc {
    MTT_ASSOC_LM_IHPDA = 0, /**< LM-IHPDA with MMR (default, spec 7, 8, 10.1, 10.3) */
    MTT_ASSOC_IHPDA,        /**< single-target IHPDA per track, no assignment (spec 7.4) */
    MTT_ASSOC_LM_IPDA,      /**< IPDA with the LM clutter density (spec 6, 8) */
    MTT_ASSOC_IPDA,         /**< IPDA per track (spec 6) */
    MTT_ASSOC_IHPDA_2D,     /**< IHPDA, optimal 2-D assignment per cluster, plain lambda (spec 10.2, 10.3);
                                 clusters over MTT_MAX_ASSIGN_TRACKS use MMR (counts.assign_fallbacks) */
    MTT_ASSOC_JIPDA,        /**< JIPDA: exact enumeration, beta and existence (spec 13.2); clusters over
                                 the MTT_MAX_JPDA_* bounds use per-track IPDA (counts.jpda_fallbacks) */
    MTT_ASSOC_JPDA,         /**< exact JPDA (spec 13.1); over the bounds Cheap JPDA (counts.jpda_fallbacks) */
    MTT_ASSOC_CHEAP_JPDA,   /**< Cheap JPDA, rows normalised (spec 13.3) */
    MTT_ASSOC_SUBOPT_JPDA,  /**< Suboptimal JPDA with the per-track B_t (spec 13.4) */
    MTT_ASSOC_NNJPDA,       /**< exact JPDA beta, static MMR, hard update (spec 13.5) */
    MTT_ASSOC_JPDA_STAR,    /**< JPDA* with optional pruning (spec 13.6) */
    MTT_ASSOC_ADAPTIVE_JPDA,/**< adaptive JPDA: gate shrink and equal split for overlapping tracks (spec 13.7) */
    MTT_ASSOC_COUNT
} mtt_assoc;

/** Initial (two-point) velocity gate (spec 12.1, 12.2). */
typedef enum mtt_init_gate {
    MTT_INIT_GATE_VMAX = 0,     /**< |z_k - z_{k-1}| <= vmax * dT */
    MTT_INIT_GATE_INTENSITY = 1 /**< chi-square gate with sigma_P = f(I)/sqrt(gamma) (seed 002) */
} mtt_init_gate;

/** Stages whose cost the optional cycle counter measures (DESIGN.md). */
typedef enum mtt_stage {
    MTT_STAGE_VALIDATE = 0,
    MTT_STAGE_PREDICT,
    MTT_STAGE_GATE,
    MTT_STAGE_LM_CLUTTER,
    MTT_STAGE_ASSOCIATE,   /* clusters, beta rows and assignment */
    MTT_STAGE_UPDATE,
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
    mtt_real process_psd;       /**< Sw of the CV model */
    mtt_real meas_sigma[2];     /**< sx, sy (sigma^2 stays a normal float) */
    mtt_real pd;                /**< detection probability; PD PG < 1 holds as pg < 1 */
    mtt_real pg;                /**< gate probability */
    mtt_real clutter_density;   /**< per unit area; 0 estimates it per track (ALGORITHMS.md §5.2) */
    mtt_real snr_rho;           /**< amplitude model rho; 0 ignores amplitude */
    mtt_real markov_p11;        /**< existence Markov chain: stays */
    mtt_real markov_p21;        /**< existence Markov chain: appears */
    mtt_real existence_init;    /**< existence of a new track */
    mtt_real confirm_threshold; /**< existence that confirms */
    mtt_real terminate_threshold; /**< existence below which a track goes; 0 never deletes */
    mtt_real merge_threshold;   /**< merging test threshold; 0 never merges */
    int initiate;               /**< nonzero: start tracks from unused measurements */
    mtt_real vmax;              /**< length per time */
    mtt_init_gate init_gate;    /**< two-point velocity gate */
    mtt_real intensity_f1[3];   /**< f1(I) = a2 I^2 + a1 I + a0 (default [S2]) */
    mtt_real intensity_f2[3];   /**< f2(I) (default [S2]) */
    mtt_real intensity_blend[2];/**< I_lo < I_hi of the f1/f2 blend */
    mtt_real jpda_bias;         /**< JPDA family B; 0 means lambda(1-PD*PG)/PD (ALGORITHMS.md §13) */
    mtt_real jpda_star_threshold;   /**< JPDA* pruning probability */
    mtt_real nnjpda_threshold;      /**< NNJPDA minimum beta */
    mtt_real adaptive_jpda_distance;/**< overlap distance in sigmas */
    mtt_real adaptive_jpda_shrink;  /**< gate shrink factor */
    mtt_cycle_fn cycle_counter; /**< optional; when set, stats hold per-stage cycles */
    void *cycle_ctx;            /**< passed to cycle_counter */
} mtt_params;

/** Type of a settings key (mtt_param_info). */
typedef enum mtt_param_type {
    MTT_PARAM_REAL = 0, /**< count mtt_real values */
    MTT_PARAM_BOOL,     /**< one value, 0 or 1 (a JSON boolean) */
    MTT_PARAM_ENUM      /**< one value, the index of one of names[] */
} mtt_param_type;

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
    const char *cross;        /**< rule against other values that only mtt_params_check
                                   applies ("below confirm_threshold"); NULL if none */
    const char *text;         /**< one-line meaning */
} mtt_param_info;


/** One detection.  Coordinates in the user's length unit. */
typedef struct mtt_meas {
    mtt_real x, y;
    mtt_real amplitude;   /**< >= 0, used when has_amplitude is nonzero */
    int has_amplitude;    /**< 0: intensity unknown for this detection */
} mtt_meas;

/** Read-only view of one live track. */
typedef struct mtt_track_view {
    uint32_t id;          /**< unique for the tracker's life, never reused */
    int confirmed;        /**< 1 once existence reached confirm_threshold (sticky) */
    mtt_real x[4];        /**< x, y, vx, vy */
    mtt_real P[4][4];     /**< state covariance */
    mtt_real existence;   /**< P(target exists | Z^k) in [0, 1] */
    uint32_t age;         /**< frames since birth */
    int32_t meas;         /**< input index of the measurement used this frame, or -1 */
} mtt_track_view;

/** Event counters (one frame, or cumulative). */
typedef struct mtt_counts {
    uint32_t frames;          /**< frames stepped */
    uint32_t meas_in;         /**< measurements passed in */
    uint32_t meas_bad;        /**< skipped: NaN/Inf coordinate, negative/NaN/Inf amplitude */
    uint32_t meas_dropped;    /**< valid, but beyond MTT_MAX_MEAS (weakest dropped) */
    uint32_t pairs;           /**< gated pairs kept */
    uint32_t pairs_dropped;   /**< gated, but beyond MTT_MAX_PAIRS (least likely dropped) */
    uint32_t gated_dropped;   /**< gated, but beyond MTT_MAX_GATED in one gate (largest d^2 dropped) */
    uint32_t clusters;        /**< clusters formed (spec 9) */
    uint32_t births;          /**< tentative tracks started */
    uint32_t births_dropped;  /**< pairs that passed the velocity gate with the table full */
    uint32_t merges;          /**< tracks removed by merging */
    uint32_t merge_dropped;   /**< merge candidates beyond MTT_MAX_MERGE_PAIRS */
    uint32_t deletions;       /**< tracks deleted on existence */
    uint32_t numeric_deletions; /**< tracks deleted for a non-positive-definite S (spec 3) */
    uint32_t confirmations;   /**< tracks confirmed */
    uint32_t assign_fallbacks;/**< ihpda-2d clusters over MTT_MAX_ASSIGN_TRACKS, resolved by MMR */
    uint32_t jpda_fallbacks;  /**< clusters over the exact-JPDA bounds (tracks, measurements, events):
                                   Cheap JPDA instead (per-track IPDA in jipda) */
} mtt_counts;

/** Statistics: the last frame, the tracker's life, and per-stage cycles. */
typedef struct mtt_stats {
    mtt_counts last;
    mtt_counts total;
    uint32_t stage_cycles[MTT_STAGE_COUNT]; /**< last frame; all 0 without a cycle counter */
    uint32_t max_cluster_tracks;  /**< largest cluster of the last frame (tracks) */
} mtt_stats;

/* ------------------------------------------------------------------------
 * Tracker state.  Its members are not part of the API (use the functions);
 * they are here so the caller can allocate it, statically in firmware.
 * ---------------------------------------------------------------------- */

/** A live track. */
typedef struct mtt_track {
    mtt_real x[4];
    mtt_real P[4][4];
    mtt_real existence;
    uint32_t id;
    uint32_t age;
    int32_t meas;        /* input index used this frame, -1 */
    uint8_t confirmed;
    uint8_t born;        /* born in the current frame: no gate yet */
    uint8_t dead;        /* marked for removal in this frame (merged / numeric) */
} mtt_track;

/** Per-frame, per-track scratch (prediction, innovation, gate). */
typedef struct mtt_track_frame {
    mtt_real xp[4];
    mtt_real Pp[4][4];
    mtt_real ex_pred;    /* predicted existence (spec 11) */
    mtt_real S[3];       /* innovation covariance s11, s12, s22 */
    mtt_real Si[3];      /* its inverse */
    mtt_real det_s;
    mtt_real vg;         /* gate area (spec 4) */
    mtt_real K[4][2];    /* Kalman gain */
    mtt_real lambda;     /* clutter density of this track: known, or estimate (spec 5.2) */
    uint16_t pair_first, pair_count;
    int16_t assigned;    /* pair index chosen, -1 */
    uint16_t cluster;
    int16_t best;        /* MMR: pair index of the row's best beta, -1 */
    uint8_t row_m;       /* candidates of the last IHPDA row computed (its m) */
    mtt_real best_beta;  /* MMR: that beta */
    mtt_real beta0;      /* JPDA family: beta of "no measurement" (spec 13) */
    mtt_real ex_post;    /* JPDA family: updated existence (spec 13.2) */
    uint8_t has_all_amp; /* every gated measurement has an amplitude */
    uint8_t valid;       /* S positive definite */
    uint8_t shrink;      /* adaptive-jpda: gate threshold gamma/n this frame (spec 13.7) */
} mtt_track_frame;

/** A gated (track, measurement) pair. */
typedef struct mtt_pair {
    uint16_t track;      /* index into the track table */
    uint16_t meas;       /* index into the frame's measurement store */
    mtt_real d2;         /* squared Mahalanobis distance */
    mtt_real p;          /* gate-normalised likelihood N/PG (spec 4) */
    mtt_real w;          /* LM weight p * Pt / (1 - Pt) (spec 8.2) */
    mtt_real lam;        /* clutter density this track sees for this measurement */
    mtt_real beta;       /* association probability of the current row */
    mtt_real L;          /* IHPDA likelihood ratio L_j of the current row (spec 7.3) */
} mtt_pair;

/** A measurement kept for this frame (or the previous one, for initiation). */
typedef struct mtt_mstore {
    mtt_real x, y, amp;
    uint32_t src;        /* input index */
    uint8_t has_amp;
    uint8_t used;        /* assigned / selected / gated: not available for initiation */
} mtt_mstore;

/** One IHPDA candidate: p_j, lambda_j, amplitude, measurement index. */
typedef struct mtt_cand {
    mtt_real p, lam, amp;
    uint16_t idx;         /* measurement index (for the tie rules) */
    uint8_t has_amp;
} mtt_cand;

/** Per-row scratch of the association stages: a member of the tracker,
 *  not the stack, so mtt_tracker_step's stack stays small and bounded. */
typedef struct mtt_row_scratch {
    mtt_cand cand[MTT_MAX_GATED];
    uint16_t pair[MTT_MAX_GATED];
    mtt_real beta[MTT_MAX_GATED];
    mtt_real L[MTT_MAX_GATED];
    mtt_real p[MTT_MAX_GATED];
    mtt_real lam[MTT_MAX_GATED];
    mtt_real nu[MTT_MAX_GATED][2];
    uint8_t rank[MTT_MAX_GATED];
} mtt_row_scratch;

/** Columns of the optimal 2-D assignment: the measurements one cluster can
 *  gate, plus one dummy ("unassigned") column per track. */
#define MTT_ASSIGN_COLS                                                             \
    (((MTT_MAX_ASSIGN_TRACKS * MTT_MAX_GATED) < MTT_MAX_MEAS ? (MTT_MAX_ASSIGN_TRACKS * MTT_MAX_GATED) \
                                                             : MTT_MAX_MEAS) + MTT_MAX_ASSIGN_TRACKS)

/** Scratch of the optimal 2-D assignment (spec 10.2), one cluster at a time. */
typedef struct mtt_assign_scratch {
    mtt_real u[MTT_MAX_ASSIGN_TRACKS + 1];  /* row potentials */
    mtt_real v[MTT_ASSIGN_COLS + 1];        /* column potentials */
    mtt_real minv[MTT_ASSIGN_COLS + 1];
    mtt_real row[MTT_ASSIGN_COLS];          /* weights of one row */
    uint16_t p[MTT_ASSIGN_COLS + 1];        /* row matched to each column (1-based), 0 none */
    uint16_t way[MTT_ASSIGN_COLS + 1];
    uint8_t done[MTT_ASSIGN_COLS + 1];
    uint16_t col_meas[MTT_ASSIGN_COLS];     /* measurement of each column */
    uint16_t col_of[MTT_MAX_MEAS];          /* column of each measurement, or none */
    int16_t col_row[MTT_MAX_ASSIGN_TRACKS]; /* result: column of each row, -1 */
} mtt_assign_scratch;

/** Scratch of the JPDA family (spec 13): per-frame weights, one dense
 *  cluster, the explicit depth-first stack and the events of the last
 *  enumeration (JPDA* grouping). */
typedef struct mtt_jpda_scratch {
    mtt_real pa[MTT_MAX_PAIRS];      /* A of each gated pair */
    mtt_real tb[MTT_MAX_TRACKS];     /* B of each track */
    mtt_real max1[MTT_MAX_TRACKS];   /* Suboptimal JPDA: largest A of each row ... */
    mtt_real max2[MTT_MAX_TRACKS];   /* ... and the second largest (0 if none) */
    uint16_t arg1[MTT_MAX_TRACKS];   /* measurement of max1 */
    uint16_t mark[MTT_MAX_TRACKS];   /* neighbour set L_t: mark = t + 1 */
    uint16_t nb[MTT_MAX_TRACKS];     /* neighbour list of one track */
    uint16_t n, m;                   /* dense cluster: tracks, measurements */
    uint16_t trk_of[MTT_MAX_JPDA_TRACKS];
    uint16_t meas_of[MTT_MAX_JPDA_MEAS];
    mtt_real A[MTT_MAX_JPDA_TRACKS][MTT_MAX_JPDA_MEAS]; /* rows scaled by 1/scale */
    mtt_real B[MTT_MAX_JPDA_TRACKS];
    mtt_real scale[MTT_MAX_JPDA_TRACKS];
    uint32_t gmask[MTT_MAX_JPDA_TRACKS];
    mtt_real S[MTT_MAX_JPDA_TRACKS][MTT_MAX_JPDA_MEAS]; /* sum of w over events with t -> j */
    mtt_real S0[MTT_MAX_JPDA_TRACKS];                   /* sum of w over events with t missed */
    mtt_real W;                                         /* sum of w */
    int8_t choice[MTT_MAX_JPDA_TRACKS];                 /* depth-first stack */
    mtt_real prod[MTT_MAX_JPDA_TRACKS + 1];
    uint32_t used[MTT_MAX_JPDA_TRACKS + 1];
    uint16_t det[MTT_MAX_JPDA_TRACKS + 1];
    uint32_t n_events, n_kept;
    uint32_t ev_used[MTT_MAX_JPDA_EVENTS];   /* measurements used by each event */
    uint16_t ev_det[MTT_MAX_JPDA_EVENTS];    /* tracks detected in each event */
    mtt_real ev_w[MTT_MAX_JPDA_EVENTS];      /* scaled weight */
    uint16_t ev_idx[MTT_MAX_JPDA_EVENTS];    /* sort order */
    uint8_t ev_keep[(MTT_MAX_JPDA_EVENTS + 7) / 8];
} mtt_jpda_scratch;

/** A track pair that passed the merge test (spec 12.3). */
typedef struct mtt_merge_cand {
    mtt_real d2;
    uint16_t a, b;       /* track indices, a < b */
} mtt_merge_cand;

/** The tracker: all state.  Allocate it, then call mtt_tracker_init. */
typedef struct mtt_tracker {
    uint32_t magic;                 /* init marker */
    mtt_params par;
    mtt_real gamma;                 /* gate threshold from pg */
    mtt_real R[3];                  /* measurement covariance (sym) */
    mtt_real prank[(MTT_MAX_GATED * (MTT_MAX_GATED + 1)) / 2]; /* P_r(l|m), spec 7.2 */
    mtt_real time;
    uint8_t have_time;
    uint32_t next_id;
    uint16_t n_tracks;
    mtt_track tracks[MTT_MAX_TRACKS];
    mtt_track_frame tf[MTT_MAX_TRACKS];
    /* frame scratch */
    uint16_t n_meas;
    mtt_mstore meas[MTT_MAX_MEAS];
    uint16_t order[MTT_MAX_MEAS];   /* measurements sorted by x (gating sweep) */
    uint32_t sel[MTT_MAX_MEAS];     /* overflow: heap of the strongest input indices */
    uint16_t n_pairs;
    mtt_pair pairs[MTT_MAX_PAIRS];
    uint16_t mp_first[MTT_MAX_MEAS + 1]; /* pairs of each measurement (CSR) */
    uint16_t mp_list[MTT_MAX_PAIRS];
    mtt_real wsum[MTT_MAX_MEAS];    /* LM sum W_j */
    uint16_t uf[MTT_MAX_TRACKS];    /* union-find parents, then cluster ids */
    uint16_t cl_first[MTT_MAX_TRACKS + 1]; /* tracks of each cluster (CSR) */
    uint16_t cl_list[MTT_MAX_TRACKS];
    uint16_t n_clusters;
    uint16_t n_merge;
    mtt_merge_cand merge[MTT_MAX_MERGE_PAIRS];
    mtt_row_scratch row;
#if MTT_WITH_BASELINES
    /* One mode runs per tracker, so the baselines share their scratch. */
    union {
        mtt_assign_scratch asg;     /* ihpda-2d */
        mtt_jpda_scratch jp;        /* JIPDA and the JPDA family */
    } base;
#endif
    /* previous frame's unused measurements (U_{k-1}, spec 12.1) */
    uint16_t n_prev;
    mtt_mstore prev[MTT_MAX_MEAS];
    uint16_t prev_order[MTT_MAX_MEAS]; /* U_{k-1} sorted by x (initiation sweep) */
    uint16_t init_cand[MTT_MAX_MEAS];  /* U_{k-1} within reach of one z_k */
    mtt_stats stats;
} mtt_tracker;

/* ------------------------------------------------------------------------
 * Functions
 * ---------------------------------------------------------------------- */

/** Fill p with FORMATS.md's defaults (seed 000's IR set-up).
 *  @return MTT_OK; MTT_ERR_NULL if p is NULL. */
MTT_MUST_CHECK mtt_status mtt_params_default(mtt_params *p);

/** Validate a parameter set.
 *  @param bad_field if not NULL, receives the settings key of the first invalid
 *         field (a static string such as "pd", "intensity_gate.blend"), or NULL
 *         when valid.
 *  @return MTT_OK; MTT_ERR_NULL if p is NULL; MTT_ERR_PARAM if a field is out
 *          of its range or not finite, or breaks a rule between fields (the
 *          ranges and rules: see mtt_params_info); MTT_ERR_UNSUPPORTED if the
 *          association mode is not built into this version (bad_field =
 *          "association"). */
MTT_MUST_CHECK mtt_status mtt_params_check(const mtt_params *p, const char **bad_field);

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
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE if the key is unknown or n is
 *          not its count; MTT_ERR_PARAM if a value is out of range.  On
 *          error p is unchanged. */
MTT_MUST_CHECK mtt_status mtt_params_set(mtt_params *p, const char *key, const double *v,
                                         size_t n);

/** Get the n values of a key, as mtt_params_set takes them.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE if the key is unknown or n is
 *          not its count. */
MTT_MUST_CHECK mtt_status mtt_params_get(const mtt_params *p, const char *key, double *v,
                                         size_t n);

/** Initialise (or reset) a tracker.  Cost: O(MTT_MAX_GATED^2) for the rank table.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_PARAM / MTT_ERR_UNSUPPORTED as
 *          mtt_params_check (the tracker is then left uninitialised). */
MTT_MUST_CHECK mtt_status mtt_tracker_init(mtt_tracker *trk, const mtt_params *p);

/** Run one frame at time `time` with n measurements (meas may be NULL when n = 0).
 *  Bad detections are skipped and counted; beyond MTT_MAX_MEAS the strongest
 *  amplitudes are kept (detections without amplitude rank below any amplitude,
 *  then by input order).
 *  Cost, every mode: O(n log n + tracks + pairs) for validation, gating,
 *  the LM densities, clusters, update and initiation (an x sweep), plus
 *  merging O(sum over clusters of tracks^2).  Association per cluster of
 *  t tracks and m measurements: MMR (lm-ihpda) O(t^2 * gated), IPDA modes
 *  O(pairs), Cheap / Suboptimal JPDA O(pairs * neighbouring tracks),
 *  ihpda-2d O(t^3) up to MTT_MAX_ASSIGN_TRACKS, the exact JPDA family and
 *  JIPDA O(events) up to MTT_MAX_JPDA_EVENTS (then the counted fallback).
 *  Every loop is bounded by config.h; nothing allocates or recurses.
 *  @return MTT_OK; MTT_ERR_NULL (trk NULL, or meas NULL with n > 0);
 *          MTT_ERR_NOT_INIT; MTT_ERR_TIME if time is not finite or not greater
 *          than the previous frame's time.  On error nothing changes. */
MTT_MUST_CHECK mtt_status mtt_tracker_step(mtt_tracker *trk, mtt_real time,
                                           const mtt_meas *meas, size_t n);

/** Add a known (seeded) track: confirmed, existence 1 (FORMATS.md initial_tracks).
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

/** The two-point initial covariance of spec 12.1 for measurement sigmas
 *  (sx, sy) and frame interval dt > 0: [[R, R/dt], [R/dt, 2R/dt^2]].
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_VALUE if an argument is not finite
 *          or not positive. */
MTT_MUST_CHECK mtt_status mtt_init_two_point_cov(mtt_real sx, mtt_real sy, mtt_real dt,
                                                 mtt_real P[4][4]);

/** Name of an association mode as FORMATS.md spells it ("lm-ihpda", ...). */
MTT_MUST_CHECK mtt_status mtt_assoc_name(mtt_assoc a, const char **name);

/** Parse a FORMATS.md association name.
 *  @return MTT_OK; MTT_ERR_NULL; MTT_ERR_RANGE if the name is unknown. */
MTT_MUST_CHECK mtt_status mtt_assoc_parse(const char *name, mtt_assoc *a);

/** Human-readable text of a status ("ok", "null pointer", ...). */
MTT_MUST_CHECK mtt_status mtt_status_text(mtt_status s, const char **text);

#ifdef __cplusplus
}
#endif

#endif /* MTT_MTT_H */
