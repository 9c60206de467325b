/* SPDX-License-Identifier: BSD-3-Clause */
/* test/consumer/mismatch.c - a program compiled with another configuration
 * than the libmtt.a it links (other bounds, the other mtt_real, the other
 * MTT_WITH_BASELINES; test/CMakeLists.txt builds one of each) must get
 * MTT_ERR_CONFIG from mtt_tracker_init and from every parameter call that
 * reads or writes an mtt_params (mtt_params_default, check, set, get,
 * prepare), with its tracker, parameters and outputs untouched; built with
 * the library's own configuration (MTT_EXPECT_MISMATCH 0) they all run.
 * Uses the public header only.  Prints one line starting with "OK". */
#include <stdio.h>
#include <string.h>

#include "mtt/mtt.h"

static mtt_tracker trk; /* this program's idea of the state's size */
static mtt_prepared prep;

#if MTT_EXPECT_MISMATCH
/* 1 when n bytes at a all equal v */
static int all_bytes(const void *a, size_t n, unsigned char v)
{
    const unsigned char *b = (const unsigned char *)a;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (b[i] != v) {
            return 0;
        }
    }
    return 1;
}

/* Each parameter call, mismatched: MTT_ERR_CONFIG, and its outputs (and p)
 * byte for byte as they were.  Returns 0, or 1 after printing the failure. */
static int params_refused(void)
{
    mtt_params p, p0;
    const char *bad = "untouched";
    const char *const bad0 = bad;
    double v[1] = {1234.5};
    mtt_status s;

    memset(&p, 0x5a, sizeof p);
    memcpy(&p0, &p, sizeof p);
    if ((s = mtt_params_default(&p)) != MTT_ERR_CONFIG || memcmp(&p, &p0, sizeof p) != 0) {
        printf("FAIL: mtt_params_default returned %d or wrote p\n", (int)s);
        return 1;
    }
    if ((s = mtt_params_check(&p, &bad)) != MTT_ERR_CONFIG || bad != bad0) {
        printf("FAIL: mtt_params_check returned %d or wrote bad_field\n", (int)s);
        return 1;
    }
    memset(&prep, 0xa5, sizeof prep);
    if ((s = mtt_params_prepare(&p, &prep)) != MTT_ERR_CONFIG || !all_bytes(&prep, sizeof prep, 0xa5u)) {
        printf("FAIL: mtt_params_prepare returned %d or wrote out\n", (int)s);
        return 1;
    }
    v[0] = 0.5;
    if ((s = mtt_params_set(&p, "pd", v, 1)) != MTT_ERR_CONFIG || memcmp(&p, &p0, sizeof p) != 0) {
        printf("FAIL: mtt_params_set returned %d or wrote p\n", (int)s);
        return 1;
    }
    v[0] = 1234.5;
    if ((s = mtt_params_get(&p, "pd", v, 1)) != MTT_ERR_CONFIG || v[0] != 1234.5) {
        printf("FAIL: mtt_params_get returned %d or wrote v\n", (int)s);
        return 1;
    }
    return 0;
}
#else
/* The same calls with the library's configuration: all accepted. */
static int params_accepted(void)
{
    mtt_params p;
    const char *bad = "x";
    double v[1] = {0.5};
    if (mtt_params_default(&p) != MTT_OK || mtt_params_check(&p, &bad) != MTT_OK || bad != NULL ||
        mtt_params_set(&p, "pd", v, 1) != MTT_OK || mtt_params_get(&p, "pd", v, 1) != MTT_OK ||
        mtt_params_prepare(&p, &prep) != MTT_OK) {
        printf("FAIL: a parameter call refused the library's own configuration\n");
        return 1;
    }
    return 0;
}
#endif

int main(void)
{
    mtt_params p;
    mtt_status s;
    const char *text = NULL;
    const unsigned char *b = (const unsigned char *)&trk;
    size_t i;

    /* Not mtt_params_default: with another mtt_real the library's
     * mtt_params is larger than ours.  A mismatch is refused before p is read. */
    memset(&p, 0, sizeof p);
    memset(&trk, 0xa5, sizeof trk);
#if MTT_EXPECT_MISMATCH
    s = mtt_tracker_init(&trk, &p);
    if (s != MTT_ERR_CONFIG) {
        printf("FAIL: mtt_tracker_init returned %d, expected MTT_ERR_CONFIG (%d)\n", (int)s,
               (int)MTT_ERR_CONFIG);
        return 1;
    }
    for (i = 0; i < sizeof trk; ++i) {
        if (b[i] != 0xa5u) {
            printf("FAIL: the refused init wrote byte %lu of the tracker\n", (unsigned long)i);
            return 1;
        }
    }
    if (params_refused() != 0) {
        return 1;
    }
    if (mtt_status_text(s, &text) != MTT_OK || text == NULL) {
        printf("FAIL: no text for MTT_ERR_CONFIG\n");
        return 1;
    }
    printf("OK: refused: %s (sizeof(mtt_tracker) %lu, sizeof(mtt_params) %lu here; the parameter calls too)\n",
           text, (unsigned long)sizeof trk, (unsigned long)sizeof(mtt_params));
#else
    (void)b;
    (void)i;
    (void)text;
    if (params_accepted() != 0) {
        return 1;
    }
    if (mtt_params_default(&p) != MTT_OK || (s = mtt_tracker_init(&trk, &p)) != MTT_OK) {
        printf("FAIL: the library's own configuration was refused\n");
        return 1;
    }
    if ((s = mtt_tracker_step(&trk, MTT_R(1.0), NULL, 0)) != MTT_OK) {
        printf("FAIL: mtt_tracker_step returned %d\n", (int)s);
        return 1;
    }
    printf("OK: same configuration accepted\n");
#endif
    return 0;
}
