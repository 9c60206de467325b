/* SPDX-License-Identifier: BSD-3-Clause */
/* main_host.c - the firmware example's scenario program on the host
 * (stdout, no tick counter), the reference for the target's output. */
#include <stdio.h>

#include "fw.h"

const mtt_cycle_fn fw_cycle_counter = NULL;

void fw_puts(const char *s)
{
    (void)fputs(s, stdout);
}

int main(void)
{
    return fw_app_run();
}
