/* SPDX-License-Identifier: BSD-3-Clause */
/* params_info.c - the settings keys as a public table (mtt_params_info,
 * mtt_params_find) and key-wise access to mtt_params (mtt_params_set,
 * mtt_params_get), for tools and bindings; docs/FORMATS.md "Settings".
 *
 * The rows are params_table.h's, the range test is params.c's
 * mtt_params_rule_ok: this file adds the texts and the conversion from and
 * to double.  Nothing in the tracker calls it, so a firmware image does not
 * link it (nor the double arithmetic it needs: tools/ci/ci-firmware.sh checks
 * that no double helper is linked).  In the fixed-point build the doubles
 * are the user's units, converted from and to each row's Q format
 * (MTT_FX_FRAC_<member>, docs/FIXED_POINT.md §3): rounded to nearest, a
 * value outside the format refused. */
#include <string.h>

#include "mtt_internal.h"
#include "params_table.h"

/* A public row and, for REAL rows, its rule in params.c. */
typedef struct info_row {
    mtt_param_info info;
    size_t rule;
#ifdef MTT_REAL_FIXED
    int frac; /* Q format of the values */
#endif
} info_row;

#ifdef MTT_REAL_FIXED
#define INFO_FRAC(member) , MTT_FX_FRAC_##member
#define INFO_NO_FRAC , 0
#else
#define INFO_FRAC(member)
#define INFO_NO_FRAC
#endif

#define INFO_REAL(key, member, count, lo, hi, flags, cross, tier, text)                                  \
    {{key, ((flags) & PF_MODELS) ? MTT_PARAM_MODELS : MTT_PARAM_REAL, count, (double)(lo), (double)(hi),    \
      ((flags) & PF_OPEN_LO) != 0, ((flags) & PF_OPEN_HI) != 0,                                     \
      ((flags) & PF_MODELS) ? mtt_model_names : NULL, ((flags) & PF_MODELS) ? 3 : 0,                 \
      ((flags) & PF_PER_MODEL2) ? 2 : (((flags) & PF_PER_MODEL) ? 1 : 0), cross, text,           \
      MTT_PARAM_TIER_##tier},              \
     MTT_RULE_##member INFO_FRAC(member)},
#define INFO_FLAG(key, member, tier, text)                                                         \
    {{key, MTT_PARAM_BOOL, 1, 0.0, 1.0, 0, 0, NULL, 0, 0, NULL, text, MTT_PARAM_TIER_##tier},        \
     MTT_RULE_COUNT INFO_NO_FRAC},
#define INFO_ENUM(key, member, type, n_names, names, tier, text)                                   \
    {{key, MTT_PARAM_ENUM, 1, 0.0, (double)((n_names) - 1), 0, 0, names, n_names, 0, NULL, text,    \
      MTT_PARAM_TIER_##tier},                                                                      \
     MTT_RULE_COUNT INFO_NO_FRAC},

static const info_row rows[] = {MTT_PARAM_ROWS(INFO_REAL, INFO_FLAG, INFO_ENUM)};

#define N_ROWS (sizeof rows / sizeof rows[0])

mtt_status mtt_params_info(size_t i, const mtt_param_info **info)
{
    if (info == NULL) {
        return MTT_ERR_NULL;
    }
    if (i >= N_ROWS) {
        return MTT_ERR_RANGE;
    }
    *info = &rows[i].info;
    return MTT_OK;
}

mtt_status mtt_params_find(const char *key, size_t *i)
{
    size_t k;
    if (key == NULL || i == NULL) {
        return MTT_ERR_NULL;
    }
    for (k = 0; k < N_ROWS; ++k) {
        if (strcmp(key, rows[k].info.key) == 0) {
            *i = k;
            return MTT_OK;
        }
    }
    return MTT_ERR_RANGE;
}

/* The arguments of mtt_params_set / get: *r the row of key, which must
 * have n values. */
static mtt_status row_of(const void *p, const char *key, const void *v, size_t n,
                         size_t params_size, uint32_t config_id, const info_row **r)
{
    size_t k;
    mtt_status st;
    if (p == NULL || v == NULL) {
        return MTT_ERR_NULL;
    }
    /* Before p or v is touched: the caller's mtt_params may have another
     * layout than ours (mtt/mtt.h, mtt_params_default). */
    if (params_size != sizeof(mtt_params) || config_id != (uint32_t)(MTT_CONFIG_ID)) {
        return MTT_ERR_CONFIG;
    }
    st = mtt_params_find(key, &k); /* MTT_ERR_NULL for a NULL key */
    if (st != MTT_OK) {
        return st;
    }
    if (n != ((rows[k].info.type == MTT_PARAM_MODELS) ? 1u + MTT_PARAM_MODEL_VALUES * (size_t)rows[k].info.count
                                                      : rows[k].info.count)) {
        return MTT_ERR_RANGE;
    }
    *r = &rows[k];
    return MTT_OK;
}

/* ENUM and BOOL rows: the member, as an int.  One case per row: the enum
 * members need not be int-sized (short enums on ARM EABI). */
#define GET_FLAG(name, member, tier, text)                                                                \
    if (strcmp(r->info.key, name) == 0) {                                                           \
        return p->member != 0;                                                                     \
    }
#define GET_ENUM(name, member, type, n_names, names, tier, text)                                          \
    if (strcmp(r->info.key, name) == 0) {                                                           \
        return (int)p->member;                                                                     \
    }
static int get_int(const mtt_params *p, const info_row *r)
{
    MTT_PARAM_ROWS(MTT_PARAM_NO_REAL, GET_FLAG, GET_ENUM)
    return 0;
}

#define SET_FLAG(name, member, tier, text)                                                                \
    if (strcmp(r->info.key, name) == 0) {                                                           \
        p->member = value;                                                                         \
    }
#define SET_ENUM(name, member, type, n_names, names, tier, text)                                          \
    if (strcmp(r->info.key, name) == 0) {                                                           \
        p->member = (type)value;                                                                   \
    }
static void set_int(mtt_params *p, const info_row *r, int value)
{
    MTT_PARAM_ROWS(MTT_PARAM_NO_REAL, SET_FLAG, SET_ENUM)
}

#ifdef MTT_REAL_FIXED
/* v (user's units) in Q frac, rounded to nearest; 0 when outside the
 * format (NaN included): the host boundary's one conversion (fx_double.c). */
static int to_real(double v, int frac, mtt_real *out)
{
    return mtt_fx_from_double(v, frac, out) == MTT_OK;
}
#define FROM_REAL(x, r) mtt_fx_to_double((x), (r)->frac)
#define ROW_FRAC(r) ((r)->frac)
#else
/* Beyond mtt_real's range the conversion is undefined: tested first. */
static int to_real(double v, int frac, mtt_real *out)
{
    (void)frac;
    if (!(v >= -(double)MTT_REAL_MAX && v <= (double)MTT_REAL_MAX)) {
        return 0;
    }
    *out = (mtt_real)v;
    return 1;
}
#define FROM_REAL(x, r) ((double)(x))
#define ROW_FRAC(r) 0
#endif

#if MTT_WITH_IMM
/* imm_models: v = r, then (model, psd, turn psd) per slot; slots from r on keep
 * their values.  A new r resets imm_transition and imm_initial to not given
 * (so a settings file that sets only imm_models is valid).  Every psd 0 is
 * imm_models not given (mtt_params_default's, ALGORITHMS.md §2.2), so a get
 * of the defaults sets back; some 0 and some not is an error. */
static mtt_status set_models(mtt_params *p, const info_row *r, const double *v)
{
    mtt_params q = *p;
    size_t k, m;
    if (!(v[0] >= 2.0 && v[0] <= (double)MTT_MAX_MODELS && v[0] == (double)(int)v[0])) {
        return MTT_ERR_PARAM;
    }
    m = (size_t)v[0];
    for (k = 0; k < m; ++k) {
        const double *s = v + 1 + MTT_PARAM_MODEL_VALUES * k;
        const double kind = s[0], psd = s[1], turn = s[2];
        if (!(kind >= 0.0 && kind < (double)r->info.n_names && kind == (double)(int)kind) ||
            !(psd > 0.0 && psd <= (double)MTT_REAL_MAX) || !(turn >= 0.0 && turn <= (double)MTT_REAL_MAX)) {
            if (!(psd == 0.0 && v[2] == 0.0 && turn == 0.0 && kind >= 0.0 && kind < (double)r->info.n_names)) {
                return MTT_ERR_PARAM; /* psd 0 only as "not given": the first slot's psd 0 too */
            }
        } else if (v[2] == 0.0) {
            return MTT_ERR_PARAM; /* the first slot not given, this one given */
        }
        q.imm_model[k] = (mtt_model_kind)(int)kind;
        if (!to_real(psd, ROW_FRAC(r), &q.imm_psd[k]) || !to_real(turn, ROW_FRAC(r), &q.imm_turn_psd[k])) {
            return MTT_ERR_PARAM; /* beyond the format of mtt_real */
        }
        if (v[2] != 0.0 && !(q.imm_psd[k] > MTT_ZERO)) {
            return MTT_ERR_PARAM; /* a psd that rounds to 0 in mtt_real */
        }
    }
    if (!mtt_params_rule_ok(&q, r->rule, 0)) {
        return MTT_ERR_PARAM;
    }
    for (k = 0; k < m; ++k) {
        /* turn psd: > 0 (not rounded to 0) for ct, 0 for the others */
        if ((q.imm_model[k] == MTT_MODEL_CT) != (q.imm_turn_psd[k] > MTT_ZERO)) {
            return MTT_ERR_PARAM;
        }
    }
    if (m != q.imm_n_models) {
        mtt_params_imm_reset(&q, (uint8_t)m);
    }
    *p = q;
    return MTT_OK;
}
#endif

mtt_status mtt_params_set_checked(mtt_params *p, const char *key, const double *v, size_t n,
                                  size_t params_size, uint32_t config_id)
{
    const info_row *r = NULL;
    mtt_params q;
    size_t k;
    mtt_status st = row_of(p, key, v, n, params_size, config_id, &r);
    if (st != MTT_OK) {
        return st;
    }
#if MTT_WITH_IMM
    if (r->info.type == MTT_PARAM_MODELS) {
        return set_models(p, r, v);
    }
#endif
    if (r->info.type != MTT_PARAM_REAL) {
        /* an index in [0, hi]: whole, and compared before the conversion */
        if (!(v[0] >= 0.0 && v[0] <= r->info.hi && v[0] == (double)(int)v[0])) {
            return MTT_ERR_PARAM;
        }
        set_int(p, r, (int)v[0]);
        return MTT_OK;
    }
    q = *p;
    for (k = 0; k < n; ++k) {
        if (!to_real(v[k], ROW_FRAC(r), &mtt_params_rule_at(&q, r->rule)[k])) {
            return MTT_ERR_PARAM;
        }
        if (v[k] != 0.0 && mtt_params_rule_at(&q, r->rule)[k] == MTT_ZERO) {
            return MTT_ERR_PARAM; /* rounds to 0, which means "not given" or "off" for several keys */
        }
    }
    if (!mtt_params_rule_ok(&q, r->rule, 0)) {
        return MTT_ERR_PARAM;
    }
    *p = q;
    return MTT_OK;
}

mtt_status mtt_params_get_checked(const mtt_params *p, const char *key, double *v, size_t n,
                                  size_t params_size, uint32_t config_id)
{
    const info_row *r = NULL;
    mtt_params q;
    size_t k;
    mtt_status st = row_of(p, key, v, n, params_size, config_id, &r);
    if (st != MTT_OK) {
        return st;
    }
    if (r->info.type == MTT_PARAM_MODELS) {
        v[0] = (double)p->imm_n_models;
        for (k = 0; k < MTT_MAX_MODELS; ++k) {
            const int used = k < p->imm_n_models;
            double *s = v + 1 + MTT_PARAM_MODEL_VALUES * k;
            s[0] = used ? (double)p->imm_model[k] : 0.0;
            s[1] = used ? FROM_REAL(p->imm_psd[k], r) : 0.0;
#if MTT_WITH_IMM
            s[2] = used ? FROM_REAL(p->imm_turn_psd[k], r) : 0.0;
#else
            s[2] = 0.0;
#endif
        }
        return MTT_OK;
    }
    if (r->info.type != MTT_PARAM_REAL) {
        v[0] = (double)get_int(p, r);
        return MTT_OK;
    }
    q = *p; /* mtt_params_rule_at addresses a writable mtt_params */
    for (k = 0; k < n; ++k) {
        v[k] = FROM_REAL(mtt_params_rule_at(&q, r->rule)[k], r);
    }
    return MTT_OK;
}
