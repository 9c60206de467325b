/* test/consumer/mismatch.c - a program compiled with another configuration
 * than the libmtt.a it links (other bounds, the other mtt_real, the other
 * MTT_WITH_BASELINES; test/CMakeLists.txt builds one of each) must get
 * MTT_ERR_CONFIG from mtt_tracker_init, with its tracker untouched; built
 * with the library's own configuration (MTT_EXPECT_MISMATCH 0) it runs.
 * Uses the public header only.  Prints one line starting with "OK". */
#include <stdio.h>
#include <string.h>

#include "mtt/mtt.h"

static mtt_tracker trk; /* this program's idea of the state's size */

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
    if (mtt_status_text(s, &text) != MTT_OK || text == NULL) {
        printf("FAIL: no text for MTT_ERR_CONFIG\n");
        return 1;
    }
    printf("OK: refused: %s (sizeof(mtt_tracker) %lu here)\n", text, (unsigned long)sizeof trk);
#else
    (void)b;
    (void)i;
    (void)text;
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
