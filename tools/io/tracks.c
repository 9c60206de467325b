/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/tracks.c - the tracks file (*.tracks.csv) of docs/FORMATS.md: one row
 * per live track after each scan, in the user's units (the fixed-point
 * build converts from its formats), with enough digits to read back the
 * same mtt_real.
 */
#include "mtt_io.h"

#include <inttypes.h>
#include <stdio.h>

#ifdef MTT_REAL_DOUBLE
#define REAL_FMT "%.17g" /* enough digits to read back the same double */
#else
#define REAL_FMT "%.9g" /* enough digits to read back the same float (or Q value) */
#endif
/* In the user's units (mtt_io_from_real: the fixed-point build's formats;
 * float and double: the value). */
#define POS(x) mtt_io_from_real((x), MTT_IO_POS)
#define VAR(x) mtt_io_from_real((x), MTT_IO_VAR)
#define PROB(x) mtt_io_from_real((x), MTT_IO_PROB)

mtt_status mtt_io_write_tracks(FILE *out, const mtt_tracker *trk, const mtt_io_scan *sc,
                               int confirmed_only, unsigned long *rows)
{
    char time_str[32];
    size_t n, i, k;
    mtt_status st;

    if ((st = mtt_tracker_count(trk, &n)) != MTT_OK)
        return st;
    mtt_io_format_double(sc->time, time_str, sizeof time_str); /* as the file gave it */
    for (i = 0; i < n; ++i) {
        mtt_track_view v;
        if ((st = mtt_tracker_track(trk, i, &v)) != MTT_OK)
            return st;
        if (confirmed_only && !v.confirmed)
            continue;
        fprintf(out,
                "%lu,%s,%" PRIu32 ",%s," REAL_FMT "," REAL_FMT "," REAL_FMT "," REAL_FMT
                "," REAL_FMT "," REAL_FMT "," REAL_FMT "," REAL_FMT,
                sc->scan, time_str, v.id, v.confirmed ? "confirmed" : "tentative", POS(v.x[0]),
                POS(v.x[1]), POS(v.x[2]), POS(v.x[3]), PROB(v.existence), VAR(v.P[0][0]),
                VAR(v.P[0][1]), VAR(v.P[1][1]));
        /* motion = imm: the model probabilities, imm_models order */
        for (k = 0; v.n_models > 1u && k < v.n_models; ++k)
            fprintf(out, "," REAL_FMT, PROB(v.mu[k]));
        /* split = true: P(split), then the parent's id (empty for none) */
        if (v.split) {
            fprintf(out, "," REAL_FMT ",", PROB(v.p_split));
            if (v.parent != MTT_NO_PARENT)
                fprintf(out, "%" PRIu32, v.parent);
        }
        fputc('\n', out);
        ++*rows;
    }
    return MTT_OK;
}

void mtt_io_write_tracks_header(FILE *out, const mtt_params *given)
{
    mtt_params r;
    const mtt_params *p = (mtt_params_resolve(given, &r) == MTT_OK) ? &r : given; /* motion auto */
    uint8_t k;
    fputs(MTT_IO_TRACKS_HEADER, out);
    for (k = 0; p->motion == MTT_MOTION_IMM && k < p->imm_n_models; ++k)
        fprintf(out, ",mu_%u", (unsigned)k);
    if (p->split)
        fputs(",p_split,parent", out);
    fputc('\n', out);
}
