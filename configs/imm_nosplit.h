/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/imm_nosplit.h - the IMM without the split-target models
 * (MTT_WITH_SPLIT follows MTT_WITH_IMM by default, mtt/config.h): the
 * documented combination that no other preset builds.  Preset and workflow
 * test-imm-nosplit build it and run the unit tests. */
#ifndef MTT_CONFIGS_IMM_NOSPLIT_H
#define MTT_CONFIGS_IMM_NOSPLIT_H

#ifndef MTT_WITH_IMM
#define MTT_WITH_IMM 1
#endif
#ifndef MTT_WITH_SPLIT
#define MTT_WITH_SPLIT 0
#endif

#endif /* MTT_CONFIGS_IMM_NOSPLIT_H */
