/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/fuzz_settings.c - libFuzzer harness: the settings JSON reader of
 * mtt-track, mtt_io_read_settings (tools/io/settings.c), on arbitrary bytes.
 *
 * Beyond "no crash, no leak, no undefined behaviour" (ASan+UBSan), a
 * settings set the reader accepts must be usable as mtt-track uses it:
 * mtt_params_check passes, mtt_tracker_init succeeds, and every seeded
 * track with its own P is accepted by mtt_tracker_add_track while the
 * table has room.  A rejected input must leave nothing to free. */
#include "fuzz_io_common.h"

#include <stdint.h>

#include "mtt/mtt.h"
#include "real_ops.h" /* mtt_isfinite: private (src/) */
#include "mtt_io.h"

static mtt_tracker trk;

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    mtt_io_progname = "fuzz_settings";
    fuzz_io_setup();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    mtt_io_settings s;
    const char *path = fuzz_io_file(data, size);
    const char *bad = NULL;
    mtt_status st;
    mtt_real P2[4][4];
    size_t i;
    int rc = mtt_io_read_settings(path, &s);

    if (rc != MTT_IO_OK) {
        if (rc != MTT_IO_EINPUT)
            FUZZ_FAIL("fuzz_settings", "reader returned %d (not EINPUT) on bad input", rc);
        if (s.seeds != NULL || s.n_seeds != 0)
            FUZZ_FAIL("fuzz_settings", "a failed read left seeds behind");
        return 0;
    }
    st = mtt_params_check(&s.params, &bad);
    if (st != MTT_OK)
        FUZZ_FAIL("fuzz_settings", "accepted settings fail mtt_params_check (%d, %s)", (int)st,
                  bad != NULL ? bad : "?");
    if (s.n_seeds > 0 && s.seeds == NULL)
        FUZZ_FAIL("fuzz_settings", "%zu seeds but no array", s.n_seeds);
    st = mtt_tracker_init(&trk, &s.params);
    if (st != MTT_OK)
        FUZZ_FAIL("fuzz_settings", "mtt_tracker_init returned %d", (int)st);
    /* As mtt-track seeds them: a seed without P gets the two-point
     * covariance; the reader leaves the positive-definite test of a given
     * P to mtt_tracker_add_track, whose MTT_ERR_VALUE mtt-track reports. */
    if (mtt_init_two_point_cov(s.params.meas_sigma[0], s.params.meas_sigma[1], MTT_R(1.0), P2) !=
        MTT_OK)
        FUZZ_FAIL("fuzz_settings", "two-point covariance failed for valid sigmas");
    for (i = 0; i < s.n_seeds; ++i) {
        int a;
        for (a = 0; a < 4; ++a)
            if (!mtt_isfinite(s.seeds[i].x[a]))
                FUZZ_FAIL("fuzz_settings", "seed %zu: x[%d] not finite", i, a);
        st = mtt_tracker_add_track(&trk, s.seeds[i].x, s.seeds[i].has_P ? s.seeds[i].P : &P2[0][0],
                                   NULL);
        if (st == MTT_OK || st == MTT_ERR_FULL)
            continue;
        if (st == MTT_ERR_VALUE && s.seeds[i].has_P)
            continue; /* a P that is not symmetric positive definite: reported by mtt-track */
        FUZZ_FAIL("fuzz_settings", "seed %zu: mtt_tracker_add_track returned %d", i, (int)st);
    }
    mtt_io_free_settings(&s);
    return 0;
}
