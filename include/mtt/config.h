/* SPDX-License-Identifier: BSD-3-Clause */
/* mtt/config.h - compile-time bounds of the tracker.
 *
 * sizeof(mtt_tracker) follows from these numbers alone; there is no other
 * memory.  Override any of them with -D on the command line, or name a header
 * of your own in MTT_USER_CONFIG (it is included first), as littlefs and
 * mbedTLS do.  Every loop in the library is bounded by one of these.
 */
#ifndef MTT_CONFIG_H
#define MTT_CONFIG_H

#ifdef MTT_USER_CONFIG
#include MTT_USER_CONFIG
#endif

/* The fixed-point build (MTT_REAL_FIXED, docs/FIXED_POINT.md) covers the
 * firmware configuration: lm-ihpda, ihpda, lm-ipda, ipda with CV motion,
 * and with MTT_WITH_IMM 1 an IMM of cv models (the real-target default,
 * ALGORITHMS.md §2.2; ca and ct stay float).  The IMM defaults to 0 there;
 * the baselines, lm-ihpda's contest variant and the split models are 0
 * (their settings report MTT_ERR_UNSUPPORTED, as in any build without
 * them) and cannot be switched on (checked below). */
#ifdef MTT_REAL_FIXED
#ifndef MTT_WITH_IMM
#define MTT_WITH_IMM 0
#endif
#ifndef MTT_WITH_BASELINES
#define MTT_WITH_BASELINES 0
#endif
#ifndef MTT_WITH_CONTEST
#define MTT_WITH_CONTEST 0
#endif
#ifndef MTT_WITH_SPLIT
#define MTT_WITH_SPLIT 0
#endif
#endif

/* Live tracks, tentative and confirmed. */
#ifndef MTT_MAX_TRACKS
#define MTT_MAX_TRACKS 128
#endif

/* Measurements accepted per frame; beyond it the strongest amplitudes stay. */
#ifndef MTT_MAX_MEAS
#define MTT_MAX_MEAS 256
#endif

/* Gated (track, measurement) pairs per frame; beyond it the most likely stay. */
#ifndef MTT_MAX_PAIRS
#define MTT_MAX_PAIRS 1024
#endif

/* Measurements in one track's gate; beyond it the smallest d^2 stay. */
#ifndef MTT_MAX_GATED
#define MTT_MAX_GATED 32
#endif

/* Merge candidates (track pairs that pass the chi-square test) per frame;
 * beyond it the smallest d^2 stay. */
#ifndef MTT_MAX_MERGE_PAIRS
#define MTT_MAX_MERGE_PAIRS (2 * MTT_MAX_TRACKS)
#endif

/* Tracks of one cluster solved by the optimal 2-D assignment (ihpda-2d,
 * ALGORITHMS.md §10.2); larger clusters fall back to MMR (counted in the stats). */
#ifndef MTT_MAX_ASSIGN_TRACKS
#define MTT_MAX_ASSIGN_TRACKS 16
#endif

/* Exact JPDA enumeration (jpda, jipda, nnjpda, jpda-star and the §13.7 modes,
 * ALGORITHMS.md §13.1, §16): tracks and measurements of one cluster, and feasible
 * joint events.  Beyond any of them the cluster falls back (counted in the
 * stats): to Cheap JPDA, or to per-track IPDA in jipda. */
#ifndef MTT_MAX_JPDA_TRACKS
#define MTT_MAX_JPDA_TRACKS 8
#endif
#ifndef MTT_MAX_JPDA_MEAS
#define MTT_MAX_JPDA_MEAS 32
#endif
#ifndef MTT_MAX_JPDA_EVENTS
#define MTT_MAX_JPDA_EVENTS 2048
#endif

/* Interacting multiple models (ALGORITHMS.md §14).  MTT_WITH_IMM 1 builds
 * the IMM stages (src/imm/imm.c) and the extra motion models
 * (src/imm/motion_ca.c, src/imm/motion_ct.c); 0 leaves them out, so a
 * firmware build keeps one 4-state CV filter per track, its .text and its RAM, and motion = imm
 * reports MTT_ERR_UNSUPPORTED.  MTT_MAX_MODELS bounds the models of one
 * IMM track (r). */
#ifndef MTT_WITH_IMM
#define MTT_WITH_IMM 1
#endif
#ifndef MTT_MAX_MODELS
#if MTT_WITH_IMM
#define MTT_MAX_MODELS 3
#else
#define MTT_MAX_MODELS 1
#endif
#endif

/* Largest state of a motion model (the track table's x and P); the
 * constant-velocity model needs 4 (x, y, vx, vy), constant acceleration 6
 * (x, y, vx, vy, ax, ay), the coordinated turn 5 (x, y, vx, vy, omega).
 * Every model's first four components are [x y vx vy] (the common subspace
 * of the IMM mixing, ALGORITHMS.md §14.1).  The fixed-point IMM has cv
 * models only: 4. */
#ifndef MTT_MAX_STATE
#if MTT_WITH_IMM && !defined(MTT_REAL_FIXED)
#define MTT_MAX_STATE 6
#else
#define MTT_MAX_STATE 4
#endif
#endif

/* 1: build the comparison baselines (ihpda-2d, jipda, the JPDA family).
 * 0: leave them out -- their scratch (mostly the JPDA* event store) leaves
 * the tracker, and those modes report MTT_ERR_UNSUPPORTED.  For firmware
 * that runs only the LM-IHPDA / IHPDA / IPDA modes. */
#ifndef MTT_WITH_BASELINES
#define MTT_WITH_BASELINES 1
#endif

/* 1: build lm-ihpda's contest variant (lm_ihpda_variant contest: the
 * contest test and update of ALGORITHMS.md §10.4, the amplitude ratio of
 * §7.6).  0: leave it out -- lm_ihpda_variant contest reports
 * MTT_ERR_UNSUPPORTED; s0 ([S0]) is unchanged.  For firmware. */
#ifndef MTT_WITH_CONTEST
#define MTT_WITH_CONTEST 1
#endif

/* 1: gamma = -2 ln(1 - PG), the library's one logarithm (at init), by a
 * short series (src/assoc/gate.c) instead of libm's log: about 500 bytes less
 * .text on a firmware, gamma within a few ulp of libm's.  0: libm's log
 * (every host build, so host output is unchanged). */
#ifndef MTT_SMALL_LOG
#define MTT_SMALL_LOG 0
#endif

#if MTT_MAX_TRACKS < 1 || MTT_MAX_TRACKS > 4096
#error "MTT_MAX_TRACKS must be in [1, 4096]"
#endif
#if MTT_MAX_MEAS < 1 || MTT_MAX_MEAS > 16384
#error "MTT_MAX_MEAS must be in [1, 16384]"
#endif
#if MTT_MAX_PAIRS < 1 || MTT_MAX_PAIRS > 65535
#error "MTT_MAX_PAIRS must be in [1, 65535]"
#endif
#if MTT_MAX_GATED < 1 || MTT_MAX_GATED > 64
#error "MTT_MAX_GATED must be in [1, 64] (rank probabilities are verified to 64, ALGORITHMS.md §7.2)"
#endif
#if MTT_MAX_MERGE_PAIRS < 1 || MTT_MAX_MERGE_PAIRS > 65535
#error "MTT_MAX_MERGE_PAIRS must be in [1, 65535]"
#endif

#if MTT_MAX_STATE < 4 || MTT_MAX_STATE > 9
#error "MTT_MAX_STATE must be in [4, 9] (the CV model needs 4)"
#endif
#if MTT_WITH_IMM != 0 && MTT_WITH_IMM != 1
#error "MTT_WITH_IMM must be 0 or 1"
#endif
#if MTT_MAX_MODELS < 1 || MTT_MAX_MODELS > 8
#error "MTT_MAX_MODELS must be in [1, 8]"
#endif
#if MTT_WITH_IMM && MTT_MAX_MODELS < 2
#error "MTT_WITH_IMM needs MTT_MAX_MODELS >= 2"
#endif
#if MTT_WITH_IMM && MTT_MAX_STATE < 6 && !defined(MTT_REAL_FIXED)
#error "MTT_WITH_IMM needs MTT_MAX_STATE >= 6 (the constant-acceleration model)"
#endif
/* The ca and ct models (src/imm/motion_ca.c, motion_ct.c): float and double. */
#if MTT_WITH_IMM && !defined(MTT_REAL_FIXED)
#define MTT_WITH_IMM_CACT 1
#else
#define MTT_WITH_IMM_CACT 0
#endif
#if MTT_WITH_BASELINES != 0 && MTT_WITH_BASELINES != 1
#error "MTT_WITH_BASELINES must be 0 or 1"
#endif
#if MTT_WITH_CONTEST != 0 && MTT_WITH_CONTEST != 1
#error "MTT_WITH_CONTEST must be 0 or 1"
#endif
#if MTT_SMALL_LOG != 0 && MTT_SMALL_LOG != 1
#error "MTT_SMALL_LOG must be 0 or 1"
#endif

#if MTT_MAX_ASSIGN_TRACKS < 1 || MTT_MAX_ASSIGN_TRACKS > 255
#error "MTT_MAX_ASSIGN_TRACKS must be in [1, 255]"
#endif
#if MTT_MAX_JPDA_TRACKS < 1 || MTT_MAX_JPDA_TRACKS > 16
#error "MTT_MAX_JPDA_TRACKS must be in [1, 16] (detected-track bit mask)"
#endif
#if MTT_MAX_JPDA_MEAS < 1 || MTT_MAX_JPDA_MEAS > 32
#error "MTT_MAX_JPDA_MEAS must be in [1, 32] (used-measurement bit mask, ALGORITHMS.md §13.1)"
#endif
#if MTT_MAX_JPDA_EVENTS < 1 || MTT_MAX_JPDA_EVENTS > 65535
#error "MTT_MAX_JPDA_EVENTS must be in [1, 65535]"
#endif

/* ==== Split targets (ALGORITHMS.md §14.3): src/split/ =======================
 * MTT_WITH_SPLIT 1 builds the split-target models ("just split", "split"
 * with its joint events, the decoupling test); 0 leaves them out
 * (firmware).  MTT_MAX_SPLIT_MEAS bounds the validated measurements of one
 * split track (the union of its two targets' gates): the joint events are
 * the (m + 1)^2 pairs (measurement or none, per target), enumerated by
 * brute force.  The stacked two-target state has 2 x MTT_MAX_STATE
 * components (MTT_SPLIT_STATE, derived, not configurable).  The split
 * modes are modes of the IMM, so MTT_WITH_SPLIT follows MTT_WITH_IMM by
 * default (a firmware configuration, MTT_WITH_IMM 0, leaves both out).
 * MTT_MAX_SPLIT_TRACKS: tracks that carry the split modes at once (a pool
 * of stacked states in the tracker, src/split/split_track.c); a track whose split
 * probability is negligible needs none. */
#ifndef MTT_WITH_SPLIT
#define MTT_WITH_SPLIT MTT_WITH_IMM
#endif
#ifndef MTT_MAX_SPLIT_MEAS
#define MTT_MAX_SPLIT_MEAS (2 * MTT_MAX_GATED)
#endif
#ifndef MTT_MAX_SPLIT_TRACKS
#if MTT_WITH_SPLIT
#define MTT_MAX_SPLIT_TRACKS 8
#else
#define MTT_MAX_SPLIT_TRACKS 0
#endif
#endif
#define MTT_SPLIT_STATE (2 * MTT_MAX_STATE)
#if MTT_WITH_SPLIT != 0 && MTT_WITH_SPLIT != 1
#error "MTT_WITH_SPLIT must be 0 or 1"
#endif
#if MTT_WITH_SPLIT && !MTT_WITH_IMM
#error "MTT_WITH_SPLIT needs MTT_WITH_IMM (the split models are IMM modes, ALGORITHMS.md §14.3)"
#endif
#if MTT_WITH_SPLIT && (MTT_MAX_SPLIT_TRACKS < 1 || MTT_MAX_SPLIT_TRACKS > 254)
#error "MTT_MAX_SPLIT_TRACKS must be in [1, 254] with MTT_WITH_SPLIT"
#endif
#if MTT_MAX_SPLIT_MEAS < 2 || MTT_MAX_SPLIT_MEAS > 128
#error "MTT_MAX_SPLIT_MEAS must be in [2, 128] (model 5 needs 2 measurements)"
#endif

/* A covariance per detection (mtt_tracker_step_cov, ALGORITHMS.md §3.1): 1
 * builds it (the host default); with 0 the tracker refuses a detection that
 * carries one (MTT_ERR_UNSUPPORTED), and every detection has meas_sigma's R.
 * The firmware configurations leave it out; the fixed-point build holds
 * the Cartesian covariance (docs/FIXED_POINT.md §5) when it is set to 1
 * (configs/firmware_fixed_radar.h). */
#ifndef MTT_WITH_MEAS_COV
#ifdef MTT_REAL_FIXED
#define MTT_WITH_MEAS_COV 0
#else
#define MTT_WITH_MEAS_COV 1
#endif
#endif
#if MTT_WITH_MEAS_COV != 0 && MTT_WITH_MEAS_COV != 1
#error "MTT_WITH_MEAS_COV must be 0 or 1"
#endif
/* Polar detections (ALGORITHMS.md §3.2), derived, not configurable: they
 * need the covariance per detection, and the fixed-point build has no
 * polar conversion (its trigonometry and range rate), so there they stay
 * refused (measurement = polar is MTT_ERR_UNSUPPORTED). */
#if MTT_WITH_MEAS_COV && !defined(MTT_REAL_FIXED)
#define MTT_WITH_POLAR 1
#else
#define MTT_WITH_POLAR 0
#endif

#if defined(MTT_REAL_FIXED) && (MTT_WITH_BASELINES || MTT_WITH_CONTEST || MTT_WITH_SPLIT)
#error "MTT_REAL_FIXED covers the firmware configuration: MTT_WITH_BASELINES, MTT_WITH_CONTEST and MTT_WITH_SPLIT must be 0"
#endif

#endif /* MTT_CONFIG_H */
