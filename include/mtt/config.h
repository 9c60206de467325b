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
#error "MTT_MAX_GATED must be in [1, 64] (rank probabilities are verified to 64, spec 7.2)"
#endif
#if MTT_MAX_MERGE_PAIRS < 1 || MTT_MAX_MERGE_PAIRS > 65535
#error "MTT_MAX_MERGE_PAIRS must be in [1, 65535]"
#endif

#endif /* MTT_CONFIG_H */
