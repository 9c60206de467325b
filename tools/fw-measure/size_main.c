/* SPDX-License-Identifier: BSD-3-Clause */
/* size_main.c - the two images whose difference is the library's cost in
 * a firmware (docs/FIRMWARE.md, tools/ci/ci-firmware.sh):
 *
 *   fw-size-lib   references every public function of mtt;
 *   fw-size-base  the same program with the calls left out.
 *
 * Both hold the same static mtt_tracker (the caller's RAM, reported on its
 * own as sizeof(mtt_tracker)) and the same startup code, so
 * size(lib) - size(base) is what linking the library adds: its code and
 * constants, the libm / libc / libgcc routines it pulls in, and any static
 * data of its own.  Inputs come through volatile objects so the compiler
 * cannot fold the calls away.
 *
 * FW_PREPARED (the fixed-point build, docs/FIRMWARE.md "Parameters
 * prepared on the host"): the firmware initialises with mtt_tracker_load
 * from the constant the host prepared (fw_prepared.h), so fw-size-lib
 * references mtt_tracker_load instead of mtt_params_default,
 * mtt_params_check and mtt_tracker_init, the parameter-time functions a
 * host runs (mtt_params_prepare).  Both images hold that constant (the
 * caller's flash, as trk is the caller's RAM).  fw-size-params is
 * fw-size-lib with the on-target parameter path instead (FW_SIZE_PARAMS:
 * mtt_params_default, mtt_params_check, mtt_tracker_init), the figure of a
 * firmware that checks its parameters itself. */
#include <stdint.h>

#include "mtt/mtt.h"
#include "semihost.h"
#ifndef FW_PREPARED
#define FW_PREPARED 0
#endif
#if FW_PREPARED
#include "fw_prepared.h"
#endif

static mtt_tracker trk;
#ifdef MTT_REAL_FIXED
volatile mtt_real fw_in = 1; /* no float anywhere in the fixed-point image */
#else
volatile float fw_in = 1.0f;
#endif
volatile uint32_t fw_out;

int main(void)
{
#ifdef FW_SIZE_WITH_LIB
#if !FW_PREPARED || defined(FW_SIZE_PARAMS)
    mtt_params p;
#endif
    mtt_meas m = {0, 0, 0, 0};
    mtt_track_view v;
    mtt_stats st;
    mtt_real x[4] = {0, 0, 0, 0}, P[4][4], P16[16] = {0};
    const char *name = "";
    mtt_assoc a = MTT_ASSOC_LM_IHPDA;
    size_t n = 0;
    uint32_t id = 0, acc = 0;
    m.x = fw_in;
#if FW_PREPARED && !defined(FW_SIZE_PARAMS)
    acc += (uint32_t)mtt_tracker_load(&trk, &mtt_fw_prepared, NULL, NULL);
#else
    acc += (uint32_t)mtt_params_default(&p);
    acc += (uint32_t)mtt_params_check(&p, &name);
    acc += (uint32_t)mtt_tracker_init(&trk, &p);
#endif
    acc += (uint32_t)mtt_tracker_step(&trk, fw_in, &m, 1);
    acc += (uint32_t)mtt_tracker_add_track(&trk, x, P16, &id);
    acc += (uint32_t)mtt_tracker_count(&trk, &n);
    acc += (uint32_t)mtt_tracker_track(&trk, 0, &v);
    acc += (uint32_t)mtt_tracker_stats(&trk, &st);
    acc += (uint32_t)mtt_init_two_point_cov(fw_in, fw_in, fw_in, P);
    acc += (uint32_t)mtt_assoc_name(a, &name);
    acc += (uint32_t)mtt_assoc_parse(name, &a);
    acc += (uint32_t)mtt_status_text(MTT_OK, &name);
    fw_out = acc + (uint32_t)n + id + (uint32_t)v.x[0] + st.total.frames + (uint32_t)P[0][0];
#else
    /* The same static tracker, referenced, with no library call. */
    fw_out = (uint32_t)(uintptr_t)&trk + (uint32_t)fw_in;
#endif
#if FW_PREPARED
    fw_out += (uint32_t)(uintptr_t)&mtt_fw_prepared; /* in every image: the caller's constant */
#endif
    semihost_write0("size image\n");
    return 0;
}
