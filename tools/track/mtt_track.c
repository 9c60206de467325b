/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/track/mtt_track.c - mtt-track: run the mtt tracker over a detections file.
 *
 *   mtt-track --config S.json --detections D.det.csv --tracks T.tracks.csv
 *   mtt-track --config S.json --prepared-c P.h
 *
 * Formats and settings keys: docs/FORMATS.md.  Both inputs are read and validated
 * whole before anything is written; the tracks go to T.tracks.csv.tmp.<pid>
 * next to the target and are renamed over it only when every scan ran, so a
 * failure (or a signal) never leaves a partial tracks file.  The tracker is
 * stepped with each scan's time minus the first scan's (it only uses
 * differences), which keeps epoch timestamps usable with a float mtt_real.
 *
 * Exit status: 0 success, 2 bad usage or input, 1 any other failure.
 */
#define _POSIX_C_SOURCE 200809L /* getpid, unlink, stat */

#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "mtt/mtt.h"
#include "mtt_io.h"

#define PROG "mtt-track"
#define EXIT_INPUT 2
#define EXIT_FAIL 1

static const char usage_text[] =
    "Usage: " PROG " --config SETTINGS.json --detections RUN.det.csv --tracks RUN.tracks.csv\n"
    "                 [--tentative | --confirmed-only] [--stats] [--skip-out-of-range]\n"
    "       " PROG " --config SETTINGS.json --prepared-c PARAMS.h\n"
    "       " PROG " --help | --version | --list-settings\n"
    "\n"
    "Run the mtt multi-target tracker over every scan of a detections file and\n"
    "write the live tracks after each scan.\n"
    "\n"
    "Required:\n"
    "  --config FILE       tracker settings: one JSON object; every key is optional\n"
    "                      and takes its default when missing; an unknown key, a\n"
    "                      value of the wrong type or out of range is an error\n"
    "  --detections FILE   detections CSV, header 'scan,time,x,y,amplitude'\n"
    "  --tracks FILE       tracks CSV to write, header\n"
    "                      'scan,time,track,status,x,y,vx,vy,existence,pxx,pxy,pyy'\n"
    "\n"
    "Options:\n"
    "  --tentative         write tentative and confirmed tracks (the default)\n"
    "  --confirmed-only    write confirmed tracks only\n"
    "  --stats             print a summary of the tracker's counters to stderr\n"
    "  --skip-out-of-range a detection outside this build's range (fixed point:\n"
    "                      position, amplitude, variance formats) is skipped and\n"
    "                      counted, the count printed on stderr; without it the\n"
    "                      first one is an error naming its line, value and range\n"
    "  --help              print this help and exit\n"
    "  --version           print the version and exit\n"
    "  --list-settings     print the settings keys (key, type, range, default,\n"
    "                      meaning, tier) as a Markdown table and exit\n"
    "  --prepared-c FILE   instead of running: write the settings, checked and\n"
    "                      prepared (mtt_params_prepare), as C for a firmware's\n"
    "                      mtt_tracker_load (a constant named mtt_fw_prepared)\n"
    "\n"
    "A value may also be given as --option=VALUE.  Each scan runs at its time\n"
    "counted from the first scan's (the tracker uses only time differences), so\n"
    "epoch timestamps keep their resolution; the tracks repeat the time as read.\n"
    "\n"
    "The file formats, the settings keys with their defaults and ranges, and\n"
    "this command line are specified in docs/FORMATS.md.\n"
    "\n"
    "Exit status: 0 on success; 2 for bad usage or bad input, with one line on\n"
    "stderr naming the file, the line (or JSON key) and the field; 1 for any\n"
    "other failure.  The tracks are written to FILE.tmp.<pid> and renamed to\n"
    "FILE at the end: on failure no partial tracks file is written and an\n"
    "existing FILE is left unchanged.\n";

typedef struct options {
    const char *config, *detections, *tracks, *prepared;
    int tentative, confirmed_only, stats, skip_out_of_range;
} options;

/* ---- the temporary output, removed on failure or signal ---------------- */

static char *g_tmp_path;                  /* set before the file exists */
static volatile sig_atomic_t g_tmp_live;  /* the file may exist */

static void on_signal(int sig)
{
    if (g_tmp_live)
        (void)unlink(g_tmp_path); /* async-signal-safe */
    signal(sig, SIG_DFL);
    raise(sig);
}

static void remove_tmp(void)
{
    if (g_tmp_live) {
        (void)remove(g_tmp_path);
        g_tmp_live = 0;
    }
}

/* ---- command line ------------------------------------------------------- */

static int usage_error(const char *fmt, ...) MTT_IO_PRINTF(1, 2);

static int usage_error(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", PROG);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, " (try '%s --help')\n", PROG);
    return EXIT_INPUT;
}

/* Returns 0 to run, -1 after --help / --version, or EXIT_INPUT. */
static int parse_args(int argc, char **argv, options *o)
{
    static const char *const valued[] = {"--config", "--detections", "--tracks", "--prepared-c"};
    int i;
    size_t k;

    memset(o, 0, sizeof *o);
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(usage_text, stdout);
            return -1;
        }
        if (strcmp(a, "--list-settings") == 0) {
            mtt_io_list_settings(stdout);
            return -1;
        }
        if (strcmp(a, "--version") == 0) {
            printf("%s %s (mtt_real=%s)\n", PROG, MTT_VERSION_STRING, MTT_IO_REAL_NAME);
            return -1;
        }
    }
    for (i = 1; i < argc; ++i) {
        const char *a = argv[i], *value = NULL;
        const char **dest[4];
        dest[0] = &o->config;
        dest[1] = &o->detections;
        dest[2] = &o->tracks;
        dest[3] = &o->prepared;
        for (k = 0; k < 4; ++k) {
            size_t len = strlen(valued[k]);
            if (strncmp(a, valued[k], len) == 0 && (a[len] == '\0' || a[len] == '='))
                break;
        }
        if (k < 4) {
            size_t len = strlen(valued[k]);
            if (a[len] == '=')
                value = a + len + 1;
            else if (i + 1 < argc)
                value = argv[++i];
            else
                return usage_error("option '%s' needs a file name", valued[k]);
            if (*value == '\0')
                return usage_error("option '%s' needs a file name", valued[k]);
            if (*dest[k] != NULL)
                return usage_error("option '%s' given twice", valued[k]);
            *dest[k] = value;
        } else if (strcmp(a, "--tentative") == 0) {
            o->tentative = 1;
        } else if (strcmp(a, "--confirmed-only") == 0) {
            o->confirmed_only = 1;
        } else if (strcmp(a, "--stats") == 0) {
            o->stats = 1;
        } else if (strcmp(a, "--skip-out-of-range") == 0) {
            o->skip_out_of_range = 1;
        } else if (a[0] == '-') {
            return usage_error("unknown option '%s'", a);
        } else {
            return usage_error("unexpected argument '%s'", a);
        }
    }
    if (o->tentative && o->confirmed_only)
        return usage_error("--tentative and --confirmed-only exclude each other");
    if (o->config == NULL)
        return usage_error("missing option '%s'", "--config");
    if (o->prepared != NULL) {
        if (o->detections != NULL || o->tracks != NULL || o->tentative || o->confirmed_only || o->stats ||
            o->skip_out_of_range)
            return usage_error("--prepared-c takes --config only");
        return 0;
    }
    if (o->detections == NULL)
        return usage_error("missing option '%s'", "--detections");
    if (o->tracks == NULL)
        return usage_error("missing option '%s'", "--tracks");
    return 0;
}

/* The output must not replace an input (rename would destroy it). */
static int check_distinct(const options *o)
{
    struct stat out, in;
    const char *inputs[2];
    const char *names[2] = {"--config", "--detections"};
    int k;

    inputs[0] = o->config;
    inputs[1] = o->detections;
    if (stat(o->tracks, &out) != 0)
        return 0; /* does not exist yet */
    for (k = 0; k < 2; ++k)
        if (stat(inputs[k], &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino) {
            fprintf(stderr, "%s: %s: --tracks is the same file as %s: refusing to overwrite it\n",
                    PROG, o->tracks, names[k]);
            return EXIT_INPUT;
        }
    return 0;
}

/* ---- running ------------------------------------------------------------ */

/* --prepared-c: the settings, checked and prepared, as C (docs/FIRMWARE.md). */
static int write_prepared(const options *o)
{
    mtt_io_settings settings;
    mtt_prepared pp;
    mtt_status st;
    FILE *f;
    int rc;

    if ((rc = mtt_io_read_settings(o->config, &settings)) != MTT_IO_OK)
        return rc;
    if ((st = mtt_params_prepare(&settings.params, &pp)) != MTT_OK) {
        /* mtt_params_check passed in the reader: this is not the input's fault */
        mtt_io_error("%s: mtt_params_prepare failed", o->config);
        return EXIT_FAIL;
    }
    if (settings.n_seeds > 0)
        fprintf(stderr, "%s: note: %s: initial_tracks are not part of a prepared set\n", PROG,
                o->config);
    f = mtt_io_open(o->prepared, "w");
    if (f == NULL)
        return EXIT_FAIL;
    rc = mtt_io_write_prepared(f, &pp, "mtt_fw_prepared") != 0;
    if (fclose(f) != 0 || rc) {
        mtt_io_error("%s: write failed", o->prepared);
        return EXIT_FAIL;
    }
    return 0;
}

static const char *status_text(mtt_status s)
{
    const char *t = "unknown status";
    if (mtt_status_text(s, &t) != MTT_OK)
        t = "unknown status";
    return t;
}

/* Add settings.initial_tracks before the first scan (identities 0, 1, ...). */
static int add_seeds(mtt_tracker *trk, const options *o, const mtt_io_settings *s,
                     const mtt_io_detections *d)
{
    mtt_real P2[4][4], P2flat[16], dt;
    char key[64];
    size_t i;
    mtt_status st;

    if (s->n_seeds == 0)
        return 0;
    (void)mtt_io_to_real(1.0, MTT_IO_TIME, &dt); /* one scan interval without a second scan */
    if (d->n_scans >= 2 && !mtt_io_to_real(d->scans[1].time - d->scans[0].time, MTT_IO_TIME, &dt)) {
        mtt_io_error("%s: the first scan interval is out of range", o->detections);
        return EXIT_INPUT;
    }
    for (i = 0; i < s->n_seeds && s->params.measurement == MTT_MEASUREMENT_POLAR; ++i) {
        if (!s->seeds[i].has_P) {
            /* the two-point P is of Cartesian sigmas: polar meas_sigma is range, bearing */
            mtt_io_seed_key(i, "P", key, sizeof key);
            mtt_io_error_key(o->config, key, "missing: with measurement polar an initial track needs its P");
            return EXIT_INPUT;
        }
    }
    st = mtt_init_two_point_cov(s->params.meas_sigma[0], s->params.meas_sigma[1], dt, P2);
    if (st != MTT_OK) {
        mtt_io_error("%s: two-point covariance for the initial tracks failed (first scan "
                     "interval %g): %s",
                     o->detections, mtt_io_from_real(dt, MTT_IO_TIME), status_text(st));
        return EXIT_INPUT;
    }
    memcpy(P2flat, P2, sizeof P2flat); /* row-major, as mtt_tracker_add_track takes it */
    for (i = 0; i < s->n_seeds; ++i) {
        const mtt_io_seed *seed = &s->seeds[i];
        uint32_t id;
        st = mtt_tracker_add_track(trk, seed->x, seed->has_P ? seed->P : P2flat, &id);
        switch (st) {
        case MTT_OK:
            continue;
        case MTT_ERR_VALUE:
            mtt_io_seed_key(i, seed->has_P ? "P" : NULL, key, sizeof key);
            mtt_io_error_key(o->config, key, "%s",
                             seed->has_P ? "must be a symmetric positive definite covariance"
                                         : "rejected: state not finite");
            return EXIT_INPUT;
        case MTT_ERR_FULL:
            mtt_io_seed_key(i, NULL, key, sizeof key);
            mtt_io_error_key(o->config, key,
                             "too many initial tracks: the track table holds %d "
                             "(MTT_MAX_TRACKS)",
                             MTT_MAX_TRACKS);
            return EXIT_INPUT;
        default:
            mtt_io_seed_key(i, NULL, key, sizeof key);
            mtt_io_error_key(o->config, key, "mtt_tracker_add_track failed: %s",
                             status_text(st));
            return EXIT_FAIL;
        }
    }
    return 0;
}

static void print_stats(const mtt_tracker *trk, size_t scans, unsigned long rows)
{
    mtt_stats s;
    const mtt_counts *t = &s.total;
    size_t live = 0;

    if (mtt_tracker_stats(trk, &s) != MTT_OK || mtt_tracker_count(trk, &live) != MTT_OK) {
        fprintf(stderr, "%s: stats unavailable\n", PROG);
        return;
    }
    fprintf(stderr,
            "%s: stats: %" PRIu32 " frames (%lu scans), %" PRIu32 " detections in, %" PRIu32
            " bad (skipped), %" PRIu32 " dropped (beyond MTT_MAX_MEAS=%d)\n",
            PROG, t->frames, (unsigned long)scans, t->meas_in, t->meas_bad, t->meas_dropped,
            MTT_MAX_MEAS);
    fprintf(stderr,
            "%s: stats: tracks: %" PRIu32 " births (%" PRIu32 " not born, table full), %" PRIu32
            " confirmations, %" PRIu32 " deletions (%" PRIu32 " numeric), %" PRIu32
            " merges, %lu live at the end\n",
            PROG, t->births, t->births_dropped, t->confirmations, t->deletions,
            t->numeric_deletions, t->merges, (unsigned long)live);
    fprintf(stderr,
            "%s: stats: dropped: %" PRIu32 " pairs (MTT_MAX_PAIRS), %" PRIu32
            " gated (MTT_MAX_GATED), %" PRIu32 " merge candidates; %lu rows written\n",
            PROG, t->pairs_dropped, t->gated_dropped, t->merge_dropped, rows);
    if (t->meas_out_of_range != 0) /* only with --skip-out-of-range; never in float */
        fprintf(stderr, "%s: stats: %" PRIu32 " detections outside this build's range (skipped)\n",
                PROG, t->meas_out_of_range);
}

static int run(const options *o)
{
    mtt_io_settings settings;
    mtt_io_detections det;
    mtt_tracker *trk = NULL;
    FILE *out = NULL;
    unsigned long rows = 0;
    size_t k;
    mtt_status st;
    int rc;

    memset(&det, 0, sizeof det);
    if ((rc = mtt_io_read_settings(o->config, &settings)) != MTT_IO_OK)
        return rc;
    if ((rc = mtt_io_read_detections_opt(o->detections, &det,
                                          o->skip_out_of_range ? MTT_IO_SKIP_OUT_OF_RANGE : 0u)) !=
        MTT_IO_OK)
        goto done;
    if ((rc = check_distinct(o)) != 0)
        goto done;

    trk = malloc(sizeof *trk);
    if (trk == NULL) {
        mtt_io_error("out of memory for the tracker (%lu bytes)", (unsigned long)sizeof *trk);
        rc = EXIT_FAIL;
        goto done;
    }
    /* the header names the form, the settings' measurement must agree (ALGORITHMS.md §3.2) */
    if (det.is_polar != (settings.params.measurement == MTT_MEASUREMENT_POLAR)) {
        mtt_io_error_at(o->detections, det.header_line, det.is_polar ? "range" : "x",
                        "the header is the %s form but %s has measurement \"%s\": set \"measurement\": \"%s\" "
                        "(and sensor_xy, meas_sigma [sigma_range, sigma_bearing]) or give %s detections",
                        det.is_polar ? "polar (range,bearing)" : "Cartesian (x,y)", o->config,
                        det.is_polar ? "cartesian" : "polar", det.is_polar ? "polar" : "cartesian",
                        det.is_polar ? "Cartesian" : "polar");
        rc = EXIT_INPUT;
        goto done;
    }
    if (det.has_range_rate && !(settings.params.range_rate_sigma > 0)) {
        mtt_io_error_key(o->config, "range_rate_sigma",
                         "missing: %s has range rates, which need their standard deviation (length/time)",
                         o->detections);
        rc = EXIT_INPUT;
        goto done;
    }
    if ((st = mtt_tracker_init(trk, &settings.params)) != MTT_OK) {
        /* mtt_params_check passed in the reader: this is not the input's fault */
        mtt_io_error("%s: mtt_tracker_init failed: %s", o->config, status_text(st));
        rc = EXIT_FAIL;
        goto done;
    }
    if ((rc = add_seeds(trk, o, &settings, &det)) != 0)
        goto done;

    /* The temporary output, next to the target so rename() stays atomic. */
    k = strlen(o->tracks) + 32;
    g_tmp_path = malloc(k);
    if (g_tmp_path == NULL) {
        mtt_io_error("out of memory");
        rc = EXIT_FAIL;
        goto done;
    }
    snprintf(g_tmp_path, k, "%s.tmp.%ld", o->tracks, (long)getpid());
    g_tmp_live = 1;
    out = fopen(g_tmp_path, "w");
    if (out == NULL) {
        g_tmp_live = 0;
        mtt_io_error("%s: cannot create the temporary file %s: %s", o->tracks, g_tmp_path,
                     strerror(errno));
        rc = EXIT_FAIL;
        goto done;
    }
    mtt_io_write_tracks_header(out, &settings.params);

    for (k = 0; k < det.n_scans; ++k) {
        const mtt_io_scan *sc = &det.scans[k];
        if (det.is_polar)
            st = mtt_tracker_step_polar(trk, sc->rtime, sc->count != 0 ? &det.polar[sc->first] : NULL, sc->count);
        else
            st = mtt_tracker_step_cov(trk, sc->rtime, sc->count != 0 ? &det.meas[sc->first] : NULL,
                                      (det.cov != NULL && sc->count != 0) ? &det.cov[sc->first] : NULL,
                                      sc->count);
        if (st == MTT_ERR_UNSUPPORTED && det.cov != NULL) {
            mtt_io_error_at(o->detections, sc->line, "r_xx",
                            "scan %lu: a covariance per detection is not available here (a build without "
                            "MTT_WITH_MEAS_COV): leave r_xx,r_xy,r_yy empty or drop the columns",
                            sc->scan);
            rc = EXIT_INPUT;
            goto done;
        }
        if (st != MTT_OK) {
            mtt_io_error_at(o->detections, sc->line, NULL, "scan %lu: mtt_tracker_step failed: %s",
                            sc->scan, status_text(st));
            rc = st == MTT_ERR_TIME ? EXIT_INPUT : EXIT_FAIL;
            goto done;
        }
        if ((st = mtt_io_write_tracks(out, trk, sc, o->confirmed_only, &rows)) != MTT_OK) {
            mtt_io_error("scan %lu: reading the tracks failed: %s", sc->scan, status_text(st));
            rc = EXIT_FAIL;
            goto done;
        }
    }

    if (ferror(out)) {
        mtt_io_error("%s: write error", g_tmp_path);
        rc = EXIT_FAIL;
        goto done;
    }
    rc = fclose(out);
    out = NULL;
    if (rc != 0) {
        mtt_io_error("%s: write error: %s", g_tmp_path, strerror(errno));
        rc = EXIT_FAIL;
        goto done;
    }
    if (rename(g_tmp_path, o->tracks) != 0) {
        mtt_io_error("%s: cannot rename to %s: %s", g_tmp_path, o->tracks, strerror(errno));
        rc = EXIT_FAIL;
        goto done;
    }
    g_tmp_live = 0;
    if (o->stats)
        print_stats(trk, det.n_scans, rows);
    if (o->skip_out_of_range) {
        mtt_stats s;
        if (mtt_tracker_stats(trk, &s) == MTT_OK)
            fprintf(stderr,
                    "%s: %s: %lu detections outside this build's range skipped (%" PRIu32
                    " counted by the tracker, meas_out_of_range)\n",
                    PROG, o->detections, (unsigned long)det.out_of_range,
                    s.total.meas_out_of_range);
    }
    rc = 0;
done:
    if (out != NULL)
        fclose(out);
    remove_tmp();
    free(g_tmp_path);
    g_tmp_path = NULL;
    free(trk);
    mtt_io_free_detections(&det);
    mtt_io_free_settings(&settings);
    return rc;
}

int main(int argc, char **argv)
{
    options o;
    int rc;

    mtt_io_progname = PROG;
    rc = parse_args(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? (fflush(stdout) == 0 ? 0 : EXIT_FAIL) : rc;
    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
#ifdef SIGHUP
    signal(SIGHUP, on_signal);
#endif
    return o.prepared != NULL ? write_prepared(&o) : run(&o);
}
