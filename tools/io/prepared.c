/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/prepared.c - a prepared parameter set (mtt_prepared, mtt_params_prepare)
 * written as C: the constant a firmware compiles and hands to
 * mtt_tracker_load (docs/FIRMWARE.md, "Parameters prepared on the host").
 *
 * The text names every member of mtt_params (designated initializers), so
 * the target's compiler lays it out: the host's layout (pointer size, enum
 * size) never matters.  The members come from the library's table of
 * settings keys (src/core/params_table.h, the one list of them) plus the members
 * that are not keys in this build.  Values are exact: integers in the
 * fixed-point build, hexadecimal floating constants otherwise. */
#include "mtt_io.h"

#include <stdio.h>

#include "core/params_table.h"

static void put_real(FILE *f, mtt_real v)
{
#if defined(MTT_REAL_FIXED)
    if (v == INT32_MIN) {
        fputs("(-2147483647 - 1)", f);
    } else {
        fprintf(f, "%ld", (long)v);
    }
#elif defined(MTT_REAL_DOUBLE)
    fprintf(f, "%a", v);
#else
    fprintf(f, "%af", (double)v);
#endif
}

/* A member's n values: a scalar (rows 0), an array (rows 1) or a matrix of
 * rows of `rows` values (nested braces, as -Wmissing-braces asks). */
static void put_reals(FILE *f, const char *member, const mtt_real *v, size_t n, size_t rows)
{
    size_t k;
    fprintf(f, "        .%s = %s", member, rows == 0u ? "" : (rows > 1u ? "{{" : "{"));
    for (k = 0; k < n; ++k) {
        if (k > 0) {
            fputs((rows > 1u && k % rows == 0u) ? "}, {" : ", ", f);
        }
        put_real(f, v[k]);
    }
    fputs(rows == 0u ? ",\n" : (rows > 1u ? "}},\n" : "},\n"), f);
}

/* A REAL row: count values from the member (a scalar, or an array: count
 * above 1 or one slot per IMM model; the transition matrix by rows). */
#define PUT_REAL(key, member, count, lo, hi, flags, cross, tier, text)                               \
    put_reals(f, #member, (const mtt_real *)(const void *)&p->member, (size_t)(count),          \
              ((flags) & PF_PER_MODEL2) ? (MTT_MAX_MODELS > 1 ? (size_t)MTT_MAX_MODELS : 2u)                                  \
                                        : (((count) > 1 || ((flags) & (PF_PER_MODEL | PF_MODELS))) ? 1u : 0u));
#define PUT_FLAG(key, member, tier, text) fprintf(f, "        .%s = %d,\n", #member, p->member);
#define PUT_ENUM(key, member, type, n_names, names, tier, text)                                       \
    fprintf(f, "        .%s = (%s)%d,\n", #member, #type, (int)p->member);

int mtt_io_write_prepared(FILE *f, const mtt_prepared *pp, const char *name)
{
    const mtt_params *p;
    size_t i;
    if (f == NULL || pp == NULL || name == NULL || pp->mark != MTT_PREPARED_MARK) {
        return -1;
    }
    p = &pp->par;
    fprintf(f,
            "/* %s: an mtt_prepared written by mtt_io_write_prepared (mtt %s, configuration\n"
            " * 0x%08lx, mtt_real %s).  Compile it with the library's definitions and hand\n"
            " * it to mtt_tracker_load (docs/FIRMWARE.md). */\n",
            name, MTT_VERSION_STRING, (unsigned long)pp->config_id,
#if defined(MTT_REAL_FIXED)
            "int32_t (fixed point)"
#elif defined(MTT_REAL_DOUBLE)
            "double"
#else
            "float"
#endif
    );
    fprintf(f, "static const mtt_prepared %s = {\n    .mark = MTT_PREPARED_MARK,\n"
               "    .config_id = 0x%08lxu,\n    .par = {\n",
            name, (unsigned long)pp->config_id);
    MTT_PARAM_ROWS(PUT_REAL, PUT_FLAG, PUT_ENUM)
    /* the members that are not settings keys in this build */
    fprintf(f, "        .imm_n_models = %u,\n", (unsigned)p->imm_n_models);
    fputs("        .imm_model = {", f);
    for (i = 0; i < MTT_MAX_MODELS; ++i) {
        fprintf(f, "%s(mtt_model_kind)%d", i > 0 ? ", " : "", (int)p->imm_model[i]);
    }
    fputs("},\n", f);
#if MTT_WITH_IMM
    put_reals(f, "imm_turn_psd", p->imm_turn_psd, MTT_MAX_MODELS, 1);
#else
    put_reals(f, "imm_psd", p->imm_psd, MTT_MAX_MODELS, 1);
    put_reals(f, "imm_transition", &p->imm_transition[0][0], (size_t)MTT_MAX_MODELS * MTT_MAX_MODELS,
              MTT_MAX_MODELS > 1 ? (size_t)MTT_MAX_MODELS : 2u);
    put_reals(f, "imm_initial", p->imm_initial, MTT_MAX_MODELS, 1);
#endif
#if !MTT_WITH_SPLIT
    put_reals(f, "split_p25", &p->split_p25, 1, 0);
    put_reals(f, "split_p52", &p->split_p52, 1, 0);
    put_reals(f, "split_p62", &p->split_p62, 1, 0);
    put_reals(f, "split_dv", &p->split_dv, 1, 0);
#endif
    fputs("        .cycle_counter = NULL,\n        .cycle_ctx = NULL},\n    .gamma = ", f);
    put_real(f, pp->gamma);
    fputs("};\n", f);
    return ferror(f) ? -1 : 0;
}
