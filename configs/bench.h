/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/bench.h - bounds large enough for 256 targets in clutter: the
 * benchmark build (preset bench, tools/bench/bench.sh, docs/PERFORMANCE.md). */
#ifndef MTT_CONFIGS_BENCH_H
#define MTT_CONFIGS_BENCH_H

#ifndef MTT_MAX_TRACKS
#define MTT_MAX_TRACKS 1024
#endif
#ifndef MTT_MAX_MEAS
#define MTT_MAX_MEAS 2048
#endif
#ifndef MTT_MAX_PAIRS
#define MTT_MAX_PAIRS 16384
#endif

#endif /* MTT_CONFIGS_BENCH_H */
