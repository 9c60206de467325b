/* SPDX-License-Identifier: BSD-3-Clause */
/* fw_params.c - the firmware example's tracker parameters, in one place
 * for the three programs that use them: the scenario program (app.c) on
 * the host, on the target (float builds), and the host step of the
 * fixed-point build (prepare_main.c), which prepares them once
 * (mtt_params_prepare) and writes fw_prepared.h for the target's
 * mtt_tracker_load (docs/FIRMWARE.md, "Parameters prepared on the host").
 *
 * FW_MAX_ACCEL 1 (e.g. MTT_EXTRA_DEFINITIONS=FW_MAX_ACCEL=1) runs the same
 * scene with the real-target default instead of process_psd: max_accel
 * sqrt(0.5) px/frame², which the firmware configurations (no IMM, no contest)
 * resolve to CV with q = a² ΔT = 0.5 at ΔT = 1 (ALGORITHMS.md §2.2;
 * docs/FIRMWARE.md, "The real-target default"). */
#include "fw.h"

int fw_params(mtt_params *par)
{
    if (mtt_params_default(par) != MTT_OK) {
        return 1;
    }
    par->clutter_density = SCN_CLUTTER_DENSITY;
#ifdef MTT_REAL_FIXED
    par->process_psd = MTT_FX_CONST(0.5, MTT_FX_VAR_FRAC);
    par->vmax = MTT_POS(10.0);
#else
    par->process_psd = 0.5f;
    par->vmax = 10.0f;
#endif
#if defined(FW_MAX_ACCEL) && FW_MAX_ACCEL
    par->process_psd = MTT_ZERO;
    par->max_accel = MTT_POS(0.70710678118654752);
#endif
    return 0;
}
