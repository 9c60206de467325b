/* SPDX-License-Identifier: BSD-3-Clause */
/* test/consumer/main.c - uses an installed mtt through its public header only.
 * Prints one line starting with "OK" on success. */
#include <stdio.h>

#include "mtt/mtt.h"

static mtt_tracker trk; /* the whole state, allocated statically as in firmware */

int main(void)
{
    mtt_params p;
    mtt_meas m[2];
    size_t n = 0;
    mtt_status s;

    s = mtt_params_default(&p);
    if (s != MTT_OK) {
        printf("FAIL: mtt_params_default returned %d\n", (int)s);
        return 1;
    }
    s = mtt_tracker_init(&trk, &p);
    if (s != MTT_OK) {
        printf("FAIL: mtt_tracker_init returned %d\n", (int)s);
        return 1;
    }
    m[0].x = MTT_R(10.0);
    m[0].y = MTT_R(20.0);
    m[0].amplitude = MTT_R(0.0);
    m[0].has_amplitude = 0;
    m[1].x = MTT_R(-5.0);
    m[1].y = MTT_R(3.0);
    m[1].amplitude = MTT_R(0.0);
    m[1].has_amplitude = 0;
    s = mtt_tracker_step(&trk, MTT_R(1.0), m, 2);
    if (s != MTT_OK) {
        printf("FAIL: mtt_tracker_step returned %d\n", (int)s);
        return 1;
    }
    s = mtt_tracker_count(&trk, &n);
    if (s != MTT_OK) {
        printf("FAIL: mtt_tracker_count returned %d\n", (int)s);
        return 1;
    }
    printf("OK mtt %s real=%s MTT_MAX_TRACKS=%d MTT_MAX_MEAS=%d sizeof(mtt_tracker)=%lu\n",
           MTT_VERSION_STRING, sizeof(mtt_real) == sizeof(double) ? "double" : "float",
           (int)MTT_MAX_TRACKS, (int)MTT_MAX_MEAS, (unsigned long)sizeof(mtt_tracker));
    return 0;
}
