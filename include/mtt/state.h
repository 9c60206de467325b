/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt/state.h - the layout of the tracker state, mtt_tracker.
 *
 * NOT API.  It is public only so that a caller can allocate the tracker
 * (statically in firmware): its size follows from mtt/config.h alone.
 * Members change between versions without notice; read a tracker through
 * the functions of mtt/mtt.h (mtt_tracker_track, mtt_tracker_stats, ...).
 * Included by mtt/mtt.h; include that instead. */
#ifndef MTT_STATE_H
#define MTT_STATE_H

#include "mtt/mtt.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A live track. */
typedef struct mtt_track {
    mtt_real x[MTT_MAX_STATE];    /* the motion model's state (x, y, vx, vy for CV) */
    mtt_real P[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE]; /* mtt_cov */
    mtt_real existence;
    uint32_t id;
    uint32_t age;
    int32_t meas;        /* input index used this frame, -1 */
    uint8_t confirmed;
    uint8_t born;        /* born in the current frame: no gate yet */
    uint8_t dead;        /* marked for removal in this frame (merged / numeric) */
#if MTT_WITH_CONTEST
    /* lm-ihpda contest: the noise-adaptive process noise of a confirmed
     * track (ALGORITHMS.md §2.1, src/contest/adapt_q.c) */
    mtt_real q_scale;    /* s: the track's Q is s times process_psd's, in [adapt_s_min, 1] */
    mtt_real nis_ratio;  /* fading average of NIS / its expectation, 1 at birth */
#endif
#if MTT_WITH_IMM
    /* motion = imm (ALGORITHMS.md §14): x, P above hold the combined 4-D
     * estimate; these the model-conditioned ones and the mode probabilities. */
    mtt_real mu[MTT_MAX_MODELS];
    mtt_real xm[MTT_MAX_MODELS][MTT_MAX_STATE];
    mtt_real Pm[MTT_MAX_MODELS][MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE]; /* mtt_cov each */
#endif
#if MTT_WITH_SPLIT
    /* split = true (ALGORITHMS.md §14.3, src/split/split_track.c) */
    mtt_real p_split;    /* μ("just split") + μ("split") after this frame */
    uint32_t parent;     /* id of the track this one split off from, MTT_NO_PARENT */
    uint8_t split_slot;  /* its stacked states in mtt_tracker.split, MTT_SPLIT_NONE */
#endif
} mtt_track;

/** Per-frame, per-track scratch (prediction, innovation, gate). */
typedef struct mtt_track_frame {
    mtt_real xp[MTT_MAX_STATE];
    mtt_real Pp[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE]; /* mtt_cov */
    mtt_real ex_pred;    /* predicted existence (ALGORITHMS.md §11) */
    mtt_real S[MTT_SYM_SLOTS];  /* innovation covariance s11, s12, s22 (fixed point: + exponent) */
    mtt_real Si[MTT_SYM_SLOTS]; /* its inverse */
    mtt_real det_s;
    mtt_real vg;         /* gate area (ALGORITHMS.md §4; fixed point: lambda V_G, Q MTT_FX_GATE_FRAC) */
    mtt_real K[MTT_MAX_STATE][2]; /* Kalman gain */
    mtt_real lambda;     /* clutter density of this track: known, or estimate (ALGORITHMS.md §5.2) */
    uint16_t pair_first, pair_count;
    int16_t assigned;    /* pair index chosen, -1 */
    uint16_t cluster;
    int16_t best;        /* MMR: pair index of the row's best beta, -1 */
    uint8_t row_m;       /* candidates of the last IHPDA row computed (its m) */
    mtt_real best_beta;  /* MMR: that beta */
    mtt_real beta0;      /* JPDA family: beta of "no measurement" (ALGORITHMS.md §13) */
    mtt_real ex_post;    /* JPDA family: updated existence (ALGORITHMS.md §13.2) */
    uint8_t has_all_amp; /* every gated measurement has an amplitude */
    uint8_t valid;       /* S positive definite */
    uint8_t shrink;      /* adaptive-jpda: gate threshold gamma/n this frame (ALGORITHMS.md §13.7) */
    uint8_t contest;     /* lm-ihpda contest: MTT_CONTEST_* (ALGORITHMS.md §10.4) */
#if MTT_WITH_IMM
    /* motion = imm: xp, Pp, S, Si, det_s, K above are the combined
     * prediction (the gate's centre); per model j the predicted mode
     * probability c̄_j and the model's own prediction and innovation. */
    mtt_real cbar[MTT_MAX_MODELS];
    mtt_real xpm[MTT_MAX_MODELS][MTT_MAX_STATE];
    mtt_real Ppm[MTT_MAX_MODELS][MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE]; /* mtt_cov each */
    mtt_real Km[MTT_MAX_MODELS][MTT_MAX_STATE][2];
    mtt_real Sim[MTT_MAX_MODELS][MTT_SYM_SLOTS];
    mtt_real peakm[MTT_MAX_MODELS]; /* N(0; 0, S_j) / PG (fixed point: its ratio to lambda, Q16) */
    mtt_real vgm;                   /* largest model gate area: the union's (ALGORITHMS.md §14.2) */
    mtt_real wm[MTT_MAX_MODELS][2]; /* gate half-widths sqrt(gamma S_j) */
#ifdef MTT_REAL_FIXED
    mtt_real vgj[MTT_MAX_MODELS];   /* lambda V_G of each model's gate (Q MTT_FX_GATE_FRAC) */
    int32_t hld[MTT_MAX_MODELS];    /* ln sqrt(det S_j), Q24: the model weights (src/imm/imm_track.c) */
#endif
#endif
} mtt_track_frame;

#if MTT_WITH_SPLIT
/* Split-target storage (ALGORITHMS.md §14.3): the stacked two-target
 * state [x_1; x_2] (2n components in MTT_SPLIT_STATE storage). */
typedef mtt_real mtt_split_state[MTT_SPLIT_STATE];
typedef mtt_real mtt_split_cov[MTT_SPLIT_STATE][MTT_SPLIT_STATE];
#define MTT_SPLIT_NONE 0xFFu

/* Model 6 "split": the joint association of the two targets of a stacked
 * prediction with m validated measurements ([S3] eq. 14, non-parametric). */
typedef struct mtt_split_assoc {
    mtt_real a[2][MTT_MAX_SPLIT_MEAS];    /* PD V N(z_j; zhat_t, S_t), 0 outside t's gate */
    mtt_real b[2];                        /* 1 - PD PG: target t undetected */
    mtt_real beta[2][MTT_MAX_SPLIT_MEAS]; /* P(z_j is target t's) */
    mtt_real beta_miss[2];                /* P(target t undetected) */
    mtt_real beta0;                       /* P(theta_0): neither detected */
    mtt_real lik;                         /* Lambda_6 = c of eq. 14 over V^-m */
    mtt_real nu[2][MTT_MAX_SPLIT_MEAS][2]; /* z_j - zhat_t */
    mtt_real pd;
    mtt_real scale;                       /* V, or 1/lambda */
    uint16_t m;
    uint8_t n;
    uint8_t parametric;                   /* 1: known clutter density lambda */
} mtt_split_assoc;

/** One track's split modes: mode probabilities μ_5 ("just split") and μ_6
 *  ("split"), and their updated stacked states (index 0: mode 5, 1: mode 6). */
typedef struct mtt_split_slot {
    mtt_real mu[2];
    mtt_split_state xs[2];
    mtt_split_cov Ps[2];
    uint8_t used;
} mtt_split_slot;

/** Work matrices of the split arithmetic (src/split/split.c), the caller's so
 *  that the stack stays small on a target: a 12-state stacked filter's
 *  matrices are 576 bytes each in float. */
typedef struct mtt_split_work {
    /* mtt_cov: innovation covariance (4 x 4 used) and its LDL' factor */
    mtt_real S[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];
    mtt_real L[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];
    mtt_real W[MTT_SPLIT_STATE][4];      /* gain of the mixed update (4: two targets x 2) */
    mtt_split_cov A;                     /* I - W H */
    mtt_split_cov AP;                    /* A Pp; mtt_split_predict's F^s Ps */
    mtt_split_cov Pq;                    /* model 5: its prediction at MTT_SPLIT_STATE stride */
    mtt_split_cov Ph[2];                 /* model 5: the halves' updated covariances */
    mtt_split_cov P12;                   /* model 5: their cross covariance */
    mtt_split_state xh[2];               /* model 5: the halves' updated states */
    mtt_real nu[MTT_MAX_SPLIT_MEAS][2];  /* model 5: innovations */
    mtt_real bn[MTT_MAX_SPLIT_MEAS];     /* model 5: betas renormalised per cluster */
    uint8_t cl[MTT_MAX_SPLIT_MEAS];      /* model 5: cluster of each measurement */
#if MTT_WITH_MEAS_COV
    /* a covariance per detection (ALGORITHMS.md §3.1, §14.3): the mixture
     * of the single-detection (single-event) updates */
    mtt_split_cov Pe;                    /* one detection's (event's) updated covariance */
    mtt_split_cov Pa;                    /* their weighted sum with the spread */
    mtt_split_cov Am[2];                 /* model 5: each half's weighted mean of I - W_j H */
    mtt_split_state xe;                  /* one detection's (event's) updated state */
    mtt_split_state da;                  /* the mean correction */
    mtt_split_cov Mr;                    /* a range rate's EKF step: I - K H (§3.2) */
#endif
} mtt_split_work;

/** Scratch of the split stage, one track at a time. */
typedef struct mtt_split_scratch {
    mtt_split_work wk;
    mtt_split_assoc as;
    mtt_real z[MTT_MAX_SPLIT_MEAS][2];   /* model 6's validated set */
    uint16_t zi[MTT_MAX_SPLIT_MEAS];     /* their measurement indices */
#if MTT_WITH_MEAS_COV
    const mtt_real *rz[MTT_MAX_SPLIT_MEAS]; /* their R: own, or meas_sigma's (§3.1) */
    uint16_t n_own;                      /* how many of them have their own R */
    const mtt_real *rr[MTT_MAX_SPLIT_MEAS]; /* their range rates and variances, or NULL (§3.2) */
    uint16_t n_rdot;                     /* how many of them have one */
#endif
    uint16_t owner[MTT_MAX_MEAS];        /* 1 + the confirmed track that holds measurement j, 0 */
    uint8_t reported[MTT_MAX_MEAS];      /* 1 when owner[j] reports measurement j */
    mtt_real beta[MTT_MAX_GATED];        /* model 5's input betas */
    mtt_real beta_n[MTT_MAX_GATED];
    uint8_t cluster[MTT_MAX_GATED];
    mtt_real P5p[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE]; /* mtt_cov: model 5's P̄_cv + Q_s */
    mtt_real F6[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];  /* mtt_cov: model 6's F per target */
    mtt_real Q6[MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];  /* mtt_cov: model 6's Q per target */
    mtt_real xd[2][MTT_MAX_STATE];                            /* decoupled: parent, child */
    mtt_real Pd[2][MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];
    mtt_split_state x5, x0, xp;
    mtt_split_cov P5, P0, Pp;
} mtt_split_scratch;
#endif

/** A gated (track, measurement) pair. */
typedef struct mtt_pair {
    uint16_t track;      /* index into the track table */
    uint16_t meas;       /* index into the frame's measurement store */
    mtt_real p;          /* gate-normalised likelihood N/PG (ALGORITHMS.md §4) */
    mtt_real w;          /* LM weight p * Pt / (1 - Pt) (ALGORITHMS.md §8.2) */
    mtt_real lam;        /* clutter density this track sees for this measurement */
    mtt_real beta;       /* association probability of the current row */
    mtt_real L;          /* IHPDA likelihood ratio L_j of the current row (ALGORITHMS.md §7.3;
                          * fixed point: lambda_j L_j, read through MTT_PAIR_L) */
    mtt_real g;          /* amplitude likelihood ratio g_eta (ALGORITHMS.md §7.6); 1 without */
} mtt_pair;

/** A measurement kept for this frame (or the previous one, for initiation). */
typedef struct mtt_mstore {
    mtt_real x, y, amp;
#if MTT_WITH_MEAS_COV
    mtt_real R[3];       /* its own covariance when has_R (ALGORITHMS.md §3.1) */
    mtt_real rng;        /* polar: its measured range (the clutter Jacobian 1/r, §3.2); else 0 */
    mtt_real rr[2];      /* polar with has_rdot: its range rate and that's variance (§3.2) */
    uint8_t has_rdot;
    uint8_t has_R;
#endif
    uint32_t src;        /* input index */
    uint8_t has_amp;
    uint8_t used;        /* assigned / selected / gated: not available for initiation */
} mtt_mstore;

/** One IHPDA candidate: p_j, lambda_j, amplitude (or its ratio g_j,
 *  ALGORITHMS.md §7.6), measurement index. */
typedef struct mtt_cand {
    mtt_real p, lam, amp;
    uint16_t idx;         /* measurement index (for the tie rules) */
} mtt_cand;

/** Per-row scratch of the association stages: a member of the tracker,
 *  not the stack, so mtt_tracker_step's stack stays small and bounded. */
typedef struct mtt_row_scratch {
    mtt_cand cand[MTT_MAX_GATED];
    uint16_t pair[MTT_MAX_GATED];
    mtt_real beta[MTT_MAX_GATED];
    mtt_real L[MTT_MAX_GATED];
    mtt_real nu[MTT_MAX_GATED][2];
    uint8_t rank[MTT_MAX_GATED];
#if MTT_WITH_IMM
    /* IMM split of one track (ALGORITHMS.md §14.2): p_i^j per pair and
     * model, and each model's betas. */
    mtt_real imm_e[MTT_MAX_GATED][MTT_MAX_MODELS];
    mtt_real imm_beta[MTT_MAX_MODELS][MTT_MAX_GATED];
#endif
#if MTT_WITH_MEAS_COV
    /* a row with detections of their own R (ALGORITHMS.md §3.1): each
     * one's R, and its single-detection state correction K_j nu_j */
    const mtt_real *rj[MTT_MAX_GATED];
    const mtt_real *rr[MTT_MAX_GATED]; /* each one's range rate and variance, or NULL (§3.2) */
    mtt_real dj[MTT_MAX_GATED][MTT_MAX_STATE];
#endif
} mtt_row_scratch;

/** Columns of the optimal 2-D assignment: the measurements one cluster can
 *  gate, plus one dummy ("unassigned") column per track. */
#define MTT_ASSIGN_COLS                                                             \
    (((MTT_MAX_ASSIGN_TRACKS * MTT_MAX_GATED) < MTT_MAX_MEAS ? (MTT_MAX_ASSIGN_TRACKS * MTT_MAX_GATED) \
                                                             : MTT_MAX_MEAS) + MTT_MAX_ASSIGN_TRACKS)

/** Scratch of the optimal 2-D assignment (ALGORITHMS.md §10.2), one cluster at a time. */
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

/** Scratch of the JPDA family (ALGORITHMS.md §13): per-frame weights, one dense
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

/** A track pair that passed the merge test (ALGORITHMS.md §12.3). */
typedef struct mtt_merge_cand {
    mtt_real d2;
    uint16_t a, b;       /* track indices, a < b */
} mtt_merge_cand;

/** The levels of the motion that max_accel derives (ALGORITHMS.md §2.2),
 *  each per unit of the scan interval: a frame's value is level x dT. */
typedef struct mtt_manoeuvre {
    uint8_t bits;                   /* MTT_DERIVE_*: which of par's values follow dT */
    mtt_real cv;                    /* process_psd = cv dT (cv = a^2) */
    mtt_real dv;                    /* split_dv = dv dT (dv = a) */
    mtt_real imm[MTT_MAX_MODELS];   /* imm_psd[j] = imm[j] dT (fixed point: the acceleration, imm_psd its square dT) */
    mtt_real rate[2];               /* switching rates 0 -> 1, 1 -> 0 of the two-model chain */
} mtt_manoeuvre;

/** The tracker: all state.  Allocate it, then call mtt_tracker_init. */
typedef struct mtt_tracker {
    uint32_t magic;                 /* init marker */
    mtt_params par;                 /* resolved (ALGORITHMS.md §2.2); the derived values at this frame's dT */
    mtt_manoeuvre lv;               /* the levels of the derived motion */
    mtt_real gamma;                 /* gate threshold from pg */
#ifdef MTT_REAL_FIXED
    int32_t gc[4];                  /* the gate's factors of gamma, pg and lambda (src/assoc/gate.c) */
#if MTT_WITH_IMM
    /* Q(dT) of each IMM model this frame (one dT and level per model: no contest scale) */
    mtt_real qm[MTT_MAX_MODELS][MTT_COV_ROWS(MTT_MAX_STATE)][MTT_MAX_STATE];
#endif
#endif
    mtt_real R[3];                  /* measurement covariance (sym) */
    mtt_real prank[(MTT_MAX_GATED * (MTT_MAX_GATED + 1)) / 2]; /* P_r(l|m), ALGORITHMS.md §7.2 */
    mtt_real time;
    mtt_real dt_last;               /* the last frame's interval (ALGORITHMS.md §12.4's lost rule) */
#if MTT_WITH_CONTEST
    mtt_real q_floor;               /* this frame's lowest process-noise scale (ALGORITHMS.md §2.1) */
    mtt_real nis_mean;              /* E[NIS] of a gated target detection, from PG: set once */
#endif
    uint8_t have_time;
    uint32_t next_id;
    uint16_t n_tracks;
    mtt_track tracks[MTT_MAX_TRACKS];
    mtt_track_frame tf[MTT_MAX_TRACKS];
    /* frame scratch */
    uint16_t n_meas;
    mtt_mstore meas[MTT_MAX_MEAS];
#if MTT_WITH_MEAS_COV
    uint16_t n_own_r;               /* kept detections with their own R this frame */
    mtt_real own_rmax[2];           /* their largest r_xx, r_yy: the gate windows' reach */
#endif
    uint32_t sel[MTT_MAX_MEAS];     /* overflow: heap of the strongest input indices */
    uint32_t sel_tmp[MTT_MAX_MEAS]; /* the canonical sort's merge buffer */
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
    /* previous frame's unused measurements (U_{k-1}, ALGORITHMS.md §12.1) */
    uint16_t n_prev;
    mtt_mstore prev[MTT_MAX_MEAS];
#if MTT_WITH_SPLIT
    mtt_split_slot split[MTT_MAX_SPLIT_TRACKS]; /* split = true: the pool (ALGORITHMS.md §14.3) */
    mtt_split_scratch split_scr;
#endif
    mtt_stats stats;
} mtt_tracker;

#ifdef __cplusplus
}
#endif

#endif /* MTT_STATE_H */
