/* SPDX-License-Identifier: BSD-3-Clause */
/* prepare_main.c - the host step of the fixed-point firmware example
 * (docs/FIRMWARE.md, "Parameters prepared on the host"): prepares the
 * example's parameters (fw_params.c) with the library built for the host in
 * the target's configuration and writes them as C (fw_prepared.h, the
 * constant mtt_fw_prepared) for the target's mtt_tracker_load, so the
 * image links neither mtt_params_check nor the logarithm of the gate
 * threshold.  Usage: mtt-fw-prepare OUT.h */
#include <stdio.h>

#include "fw.h"
#include "mtt_io.h"

int main(int argc, char **argv)
{
    mtt_params par;
    mtt_prepared pp;
    FILE *f;
    int bad;
    if (argc != 2) {
        fputs("usage: mtt-fw-prepare OUT.h\n", stderr);
        return 2;
    }
    if (fw_params(&par) != 0 || mtt_params_prepare(&par, &pp) != MTT_OK) {
        fputs("mtt-fw-prepare: the example's parameters do not pass mtt_params_check\n", stderr);
        return 1;
    }
    f = fopen(argv[1], "w");
    if (f == NULL) {
        perror(argv[1]);
        return 1;
    }
    bad = mtt_io_write_prepared(f, &pp, "mtt_fw_prepared") != 0;
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "mtt-fw-prepare: %s: write failed\n", argv[1]);
        return 1;
    }
    return 0;
}
