/* SPDX-License-Identifier: BSD-3-Clause */
// test/consumer/cxx.cpp - a C++ program using mtt through its public header
// only: every declaration must have C linkage (a C++ caller otherwise
// links mangled names that libmtt.a does not define), and the header must
// be valid C++.  Initialises a tracker, steps it with one detection and
// reads it back.  Prints one line starting with "OK".
#include <cstdio>
#include <cstring>

#include "mtt/mtt.h"

static mtt_tracker trk;

int main()
{
    mtt_params p;
    mtt_prepared prep;
    mtt_meas z;
    mtt_stats st;
    const char *bad = NULL;
    double v[1] = {0.9};
    double lambda[1] = {1e-4}; // a declared density: the fixed build estimates none
    std::size_t n = 0;

    std::memset(&z, 0, sizeof z);
    z.x = MTT_POS(10.0);
    z.y = MTT_POS(-5.0);
    if (mtt_params_default(&p) != MTT_OK || mtt_params_set(&p, "pd", v, 1) != MTT_OK ||
        mtt_params_set(&p, "clutter_density", lambda, 1) != MTT_OK ||
        mtt_params_get(&p, "pd", v, 1) != MTT_OK || mtt_params_check(&p, &bad) != MTT_OK ||
        mtt_params_prepare(&p, &prep) != MTT_OK) {
        std::printf("FAIL: parameters\n");
        return 1;
    }
    if (mtt_tracker_init(&trk, &p) != MTT_OK || mtt_tracker_step(&trk, MTT_TIME(1.0), &z, 1) != MTT_OK ||
        mtt_tracker_step(&trk, MTT_TIME(2.0), &z, 1) != MTT_OK ||
        mtt_tracker_count(&trk, &n) != MTT_OK || mtt_tracker_stats(&trk, &st) != MTT_OK ||
        st.total.frames != 2u || st.total.meas_in != 2u) {
        std::printf("FAIL: tracker\n");
        return 1;
    }
    if (mtt_tracker_load(&trk, &prep, NULL, NULL) != MTT_OK) {
        std::printf("FAIL: mtt_tracker_load\n");
        return 1;
    }
    std::printf("OK: C++ consumer, %lu track(s) after 2 frames\n", static_cast<unsigned long>(n));
    return 0;
}
