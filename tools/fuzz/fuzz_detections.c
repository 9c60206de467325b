/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/fuzz/fuzz_detections.c - libFuzzer harness: the detections CSV reader of
 * mtt-track, mtt_io_read_detections (tools/io/detections.c), on arbitrary bytes.
 *
 * Beyond "no crash, no leak, no undefined behaviour" (ASan+UBSan), what the
 * reader accepts must be what docs/FORMATS.md promises and what the tracker
 * takes: scans in file order partition the detections, scan numbers never
 * decrease, times and tracker times strictly increase, every coordinate is
 * finite, every amplitude finite and >= 0 (polar: range > 0, bearing and
 * range rate finite); and stepping a default tracker (of the file's form)
 * over the first scans returns MTT_OK every time (as mtt-track does).
 * The read with MTT_IO_SKIP_OUT_OF_RANGE (mtt-track --skip-out-of-range)
 * accepts what the plain read accepts, the same detections, and where the
 * plain read fails it succeeds only with detections out of range, each
 * counted once by the reader and once by the tracker (meas_out_of_range;
 * none in float and double, whose range is the format's). */
#include "fuzz_io_common.h"

#include <stdint.h>

#include "mtt/mtt.h"
#include "real_ops.h" /* mtt_isfinite: private (src/) */
#include "mtt_io.h"

#define MAX_STEPPED_SCANS 64

static mtt_tracker trk;

/* A default tracker for the file's form: a polar file's has measurement
 * polar (ALGORITHMS.md §3.2); 0, or -1 where the build has no polar. */
static int init_for(const mtt_io_detections *d)
{
    mtt_params p;
    if (mtt_params_default(&p) != MTT_OK)
        abort();
    if (d->is_polar) {
        p.measurement = MTT_MEASUREMENT_POLAR;
        p.meas_sigma[1] = MTT_R(0.01); /* radians */
        p.range_rate_sigma = MTT_R(1.0);
        if (!MTT_WITH_MEAS_COV)
            return mtt_tracker_init(&trk, &p) == MTT_ERR_UNSUPPORTED ? -1 : (abort(), -1);
    }
    if (mtt_tracker_init(&trk, &p) != MTT_OK)
        abort();
    return 0;
}

/* Step scan sc of d as mtt-track does. */
static mtt_status step_scan(const mtt_io_detections *d, const mtt_io_scan *sc)
{
    if (d->is_polar)
        return mtt_tracker_step_polar(&trk, sc->rtime, sc->count != 0 ? &d->polar[sc->first] : NULL, sc->count);
    return mtt_tracker_step_cov(&trk, sc->rtime, sc->count != 0 ? &d->meas[sc->first] : NULL,
                                (d->cov != NULL && sc->count != 0) ? &d->cov[sc->first] : NULL, sc->count);
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    mtt_io_progname = "fuzz_detections";
    fuzz_io_setup();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    mtt_io_detections d, ds;
    int polar_ok;
    const char *path = fuzz_io_file(data, size);
    size_t k, next = 0;
    int rc = mtt_io_read_detections(path, &d);
    const int rc_skip = mtt_io_read_detections_opt(path, &ds, MTT_IO_SKIP_OUT_OF_RANGE);
    mtt_stats st_all;

    if (rc_skip == MTT_IO_OK) {
        if (rc == MTT_IO_OK && (ds.n_meas != d.n_meas || ds.n_scans != d.n_scans || ds.out_of_range != 0))
            FUZZ_FAIL("fuzz_detections", "the skipping read differs from the plain one (%zu, %zu)",
                      ds.n_meas, ds.out_of_range);
        if (rc != MTT_IO_OK && ds.out_of_range == 0)
            FUZZ_FAIL("fuzz_detections", "the skipping read accepts a file the plain read refuses");
#ifndef MTT_REAL_FIXED
        if (ds.out_of_range != 0)
            FUZZ_FAIL("fuzz_detections", "%zu detections out of range in float", ds.out_of_range);
#endif
        if (init_for(&ds) != 0)
            k = 0; /* no polar in this build: nothing stepped */
        else
            for (k = 0; k < ds.n_scans && k < MAX_STEPPED_SCANS; ++k)
                if (step_scan(&ds, &ds.scans[k]) != MTT_OK)
                    break;
        if (k == ds.n_scans && ds.n_scans != 0 && !ds.is_polar && (mtt_tracker_stats(&trk, &st_all) != MTT_OK ||
                                st_all.total.meas_out_of_range != (uint32_t)ds.out_of_range))
            FUZZ_FAIL("fuzz_detections", "the tracker counted %u of %zu detections out of range",
                      (unsigned)st_all.total.meas_out_of_range, ds.out_of_range);
        mtt_io_free_detections(&ds);
    } else if (rc == MTT_IO_OK) {
        FUZZ_FAIL("fuzz_detections", "the skipping read refuses a file the plain read accepts");
    }
    if (rc != MTT_IO_OK) {
        if (rc != MTT_IO_EINPUT)
            FUZZ_FAIL("fuzz_detections", "reader returned %d (not EINPUT) on bad input", rc);
        return 0;
    }
    for (k = 0; k < d.n_scans; ++k) {
        const mtt_io_scan *sc = &d.scans[k];
        size_t j;
        if (sc->first != next && sc->count != 0)
            FUZZ_FAIL("fuzz_detections", "scan %zu starts at %zu, expected %zu", k, sc->first, next);
        if (sc->first + sc->count > d.n_meas)
            FUZZ_FAIL("fuzz_detections", "scan %zu overruns the detections", k);
        next = sc->first + sc->count;
        if (k > 0) {
            const mtt_io_scan *pr = &d.scans[k - 1];
            if (sc->scan < pr->scan)
                FUZZ_FAIL("fuzz_detections", "scan numbers decrease at %zu", k);
            if (!(sc->time > pr->time) || !(sc->rtime > pr->rtime))
                FUZZ_FAIL("fuzz_detections", "times do not increase at scan %zu (%.17g, %.9g)",
                          k, sc->time, (double)sc->rtime);
        }
        if (!mtt_isfinite(sc->rtime) || sc->time != sc->time)
            FUZZ_FAIL("fuzz_detections", "scan %zu: time not finite", k);
        for (j = sc->first; j < sc->first + sc->count && d.is_polar; ++j) {
            const mtt_polar *q = &d.polar[j];
            if (!mtt_isfinite(q->range) || !(q->range > MTT_R(0.0)) || !mtt_isfinite(q->bearing) ||
                (q->has_range_rate && !mtt_isfinite(q->range_rate)))
                FUZZ_FAIL("fuzz_detections", "detection %zu: bad range or bearing accepted", j);
            if (q->has_amplitude && (!mtt_isfinite(q->amplitude) || !(q->amplitude >= MTT_R(0.0))))
                FUZZ_FAIL("fuzz_detections", "detection %zu: bad amplitude accepted", j);
        }
        for (j = sc->first; j < sc->first + sc->count && !d.is_polar; ++j) {
            const mtt_meas *m = &d.meas[j];
            if (!mtt_isfinite(m->x) || !mtt_isfinite(m->y))
                FUZZ_FAIL("fuzz_detections", "detection %zu: coordinate not finite", j);
            if (m->has_amplitude && (!mtt_isfinite(m->amplitude) || !(m->amplitude >= MTT_R(0.0))))
                FUZZ_FAIL("fuzz_detections", "detection %zu: bad amplitude accepted", j);
            if (d.cov != NULL) { /* all 0, or a finite positive definite covariance (fixed: inside the variance format) */
                const mtt_meas_cov *c = &d.cov[j];
                const int zero = c->r_xx == MTT_ZERO && c->r_xy == MTT_ZERO && c->r_yy == MTT_ZERO;
                if (!zero && !(mtt_isfinite(c->r_xx) && mtt_isfinite(c->r_xy) && mtt_isfinite(c->r_yy) &&
                               c->r_xx > MTT_ZERO && c->r_yy > MTT_ZERO))
                    FUZZ_FAIL("fuzz_detections", "detection %zu: bad covariance accepted", j);
            }
        }
    }
    if (next != d.n_meas)
        FUZZ_FAIL("fuzz_detections", "scans cover %zu of %zu detections", next, d.n_meas);
    polar_ok = init_for(&d) == 0;
    for (k = 0; k < d.n_scans && k < MAX_STEPPED_SCANS && polar_ok; ++k) {
        const mtt_io_scan *sc = &d.scans[k];
        const mtt_meas_cov *c = (d.cov != NULL && sc->count != 0) ? &d.cov[sc->first] : NULL;
        mtt_status st = step_scan(&d, sc);
        if (st == MTT_ERR_UNSUPPORTED && c != NULL && !MTT_WITH_MEAS_COV)
            continue; /* a build without a covariance per detection refuses them */
        if (st != MTT_OK)
            FUZZ_FAIL("fuzz_detections", "scan %zu: mtt_tracker_step returned %d", k, (int)st);
    }
    mtt_io_free_detections(&d);
    return 0;
}
