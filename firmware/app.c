/* app.c - the firmware example's scenario program, identical on host and
 * target: run the tracker over the built-in scene, print per frame
 *
 *   F <frame> meas <n> live <tracks> conf <confirmed tracks>
 *   C <frame> ticks <t> [stage ticks...]        (target only, with a tick counter)
 *
 * then every final track
 *
 *   T <id> conf <0|1> x <x> y <y> vx <vx> vy <vy> ex <existence> hex <8 hex digits x 5>
 *
 * (the hex words are the IEEE-754 bits of x, y, vx, vy, existence, for an
 * exact comparison), and "END ok" or "END fail <reason>". */
#include "fw.h"

/* The tracker's whole RAM cost; static, as firmware allocates it. */
static mtt_tracker trk;
static mtt_meas meas[SCN_MAX_MEAS];
static char line[192];

static int fail(const char *what)
{
    char *p = fmt_str(line, "END fail ");
    p = fmt_str(p, what);
    (void)fmt_str(p, "\n");
    fw_puts(line);
    return 1;
}

static void print_frame(int k, size_t n, size_t live, size_t conf)
{
    char *p = fmt_str(line, "F ");
    p = fmt_i32(p, (int32_t)k);
    p = fmt_str(p, " meas ");
    p = fmt_u32(p, (uint32_t)n);
    p = fmt_str(p, " live ");
    p = fmt_u32(p, (uint32_t)live);
    p = fmt_str(p, " conf ");
    p = fmt_u32(p, (uint32_t)conf);
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

static void print_ticks(int k, const mtt_stats *st)
{
    uint32_t total = 0;
    int s;
    char *p;
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        total += st->stage_cycles[s];
    }
    p = fmt_str(line, "C ");
    p = fmt_i32(p, (int32_t)k);
    p = fmt_str(p, " ticks ");
    p = fmt_u32(p, total);
    p = fmt_str(p, " stages");
    for (s = 0; s < MTT_STAGE_COUNT; ++s) {
        p = fmt_str(p, " ");
        p = fmt_u32(p, st->stage_cycles[s]);
    }
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

static void print_track(const mtt_track_view *v)
{
    const float val[5] = {v->x[0], v->x[1], v->x[2], v->x[3], v->existence};
    static const char *const name[5] = {" x ", " y ", " vx ", " vy ", " ex "};
    int i;
    char *p = fmt_str(line, "T ");
    p = fmt_u32(p, v->id);
    p = fmt_str(p, " conf ");
    p = fmt_u32(p, (uint32_t)(v->confirmed != 0));
    for (i = 0; i < 5; ++i) {
        p = fmt_str(p, name[i]);
        p = fmt_fixed(p, val[i], i < 4 ? 3 : 5);
    }
    p = fmt_str(p, " hex");
    for (i = 0; i < 5; ++i) {
        p = fmt_str(p, " ");
        p = fmt_hex(p, val[i]);
    }
    (void)fmt_str(p, "\n");
    fw_puts(line);
}

int fw_app_run(void)
{
    mtt_params par;
    mtt_stats st;
    mtt_track_view v;
    scn_state scn;
    size_t n, live, conf, i;
    int k;
    char *p;

    if (mtt_params_default(&par) != MTT_OK) {
        return fail("params");
    }
    par.clutter_density = SCN_CLUTTER_DENSITY;
    par.process_psd = 0.5f;
    par.vmax = 10.0f;
    par.cycle_counter = fw_cycle_counter; /* NULL on the host */
    if (mtt_tracker_init(&trk, &par) != MTT_OK) {
        return fail("init");
    }
    scn_init(&scn, 20240601u);

    p = fmt_str(line, "mtt firmware scenario: frames ");
    p = fmt_u32(p, SCN_FRAMES);
    p = fmt_str(p, " targets ");
    p = fmt_u32(p, SCN_TARGETS);
    p = fmt_str(p, " sizeof(mtt_tracker) ");
    p = fmt_u32(p, (uint32_t)sizeof(mtt_tracker));
    (void)fmt_str(p, "\n");
    fw_puts(line);

    for (k = 0; k < SCN_FRAMES; ++k) {
        n = scn_frame(&scn, k, meas);
        if (mtt_tracker_step(&trk, (float)k, meas, n) != MTT_OK) {
            return fail("step");
        }
        if (mtt_tracker_count(&trk, &live) != MTT_OK) {
            return fail("count");
        }
        conf = 0;
        for (i = 0; i < live; ++i) {
            if (mtt_tracker_track(&trk, i, &v) != MTT_OK) {
                return fail("track");
            }
            conf += (v.confirmed != 0) ? 1u : 0u;
        }
        print_frame(k, n, live, conf);
        if (fw_cycle_counter != NULL) {
            if (mtt_tracker_stats(&trk, &st) != MTT_OK) {
                return fail("stats");
            }
            print_ticks(k, &st);
        }
    }
    if (mtt_tracker_count(&trk, &live) != MTT_OK) {
        return fail("count");
    }
    for (i = 0; i < live; ++i) {
        if (mtt_tracker_track(&trk, i, &v) != MTT_OK) {
            return fail("track");
        }
        print_track(&v);
    }
    fw_puts("END ok\n");
    return 0;
}
