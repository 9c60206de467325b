/* SPDX-License-Identifier: BSD-3-Clause */
/* examples/minimal/main.c - README.md's "Using the library" as a program.
 * The block from `#include "mtt/mtt.h"` to the end of tracker_frame is the
 * README's code verbatim (ctest tree.check compares them); main feeds it 20
 * frames of synthetic detections (one target at constant velocity, one
 * clutter point per frame) and prints the confirmed tracks of each frame.
 *
 * Exits 0 when the target's track is confirmed by the last frame, 1
 * otherwise (ctest example.minimal runs it).  stdio is the example's own:
 * the library uses none. */
#include <stdio.h>

#include "mtt/mtt.h"

static mtt_tracker trk;              /* all of the tracker's RAM: static in firmware */

int tracker_setup(void)
{
    mtt_params p;
    if (mtt_params_default(&p) != MTT_OK) return -1;
    p.pd = MTT_R(0.9);
    p.clutter_density = MTT_R(1e-4); /* per unit area; 0 estimates it per track */
    return mtt_tracker_init(&trk, &p) == MTT_OK ? 0 : -1;
}

void tracker_frame(mtt_real t, const mtt_meas *m, size_t n)   /* once per frame */
{
    size_t i, count;
    if (mtt_tracker_step(&trk, t, m, n) != MTT_OK) return;   /* t must increase */
    if (mtt_tracker_count(&trk, &count) != MTT_OK) return;
    for (i = 0; i < count; ++i) {
        mtt_track_view v;
        if (mtt_tracker_track(&trk, i, &v) == MTT_OK && v.confirmed) {
            /* v.id; v.x[0..3] = x, y, vx, vy; v.P; v.existence */
        }
    }
}

/* ---- the program around it: not the README's ---- */

/* Prints frame t's confirmed tracks; returns whether there was one. */
static int print_confirmed(mtt_real t)
{
    size_t i, count;
    int seen = 0;
    if (mtt_tracker_count(&trk, &count) != MTT_OK) return 0;
    for (i = 0; i < count; ++i) {
        mtt_track_view v;
        if (mtt_tracker_track(&trk, i, &v) == MTT_OK && v.confirmed) {
            printf("t=%4.1f confirmed track %u: x %7.2f y %6.2f vx %5.2f vy %5.2f existence %.3f\n",
                   (double)t, (unsigned)v.id, (double)v.x[0], (double)v.x[1], (double)v.x[2],
                   (double)v.x[3], (double)v.existence);
            seen = 1;
        }
    }
    return seen;
}

int main(void)
{
    int confirmed_seen = 0;
    unsigned lcg = 12345u; /* a fixed sequence: the same clutter every run */
    int k;
    if (tracker_setup() != 0) {
        fprintf(stderr, "minimal: tracker_setup failed\n");
        return 1;
    }
    for (k = 0; k < 20; ++k) {
        mtt_meas z[2];
        /* the target: x = 2 t, y = 5 (one scan per second, no amplitude) */
        z[0].x = MTT_R(2.0) * (mtt_real)k;
        z[0].y = MTT_R(5.0);
        z[0].amplitude = MTT_R(0.0);
        z[0].has_amplitude = 0;
        /* clutter: anywhere in [0, 100) x [20, 120), away from the target */
        lcg = lcg * 1103515245u + 12345u;
        z[1].x = (mtt_real)((lcg >> 16) % 100u);
        lcg = lcg * 1103515245u + 12345u;
        z[1].y = MTT_R(20.0) + (mtt_real)((lcg >> 16) % 100u);
        z[1].amplitude = MTT_R(0.0);
        z[1].has_amplitude = 0;
        tracker_frame((mtt_real)k, z, 2);
        confirmed_seen = print_confirmed((mtt_real)k); /* the last frame's tracks decide */
    }
    if (!confirmed_seen) {
        fprintf(stderr, "minimal: no confirmed track after 20 frames\n");
        return 1;
    }
    return 0;
}
