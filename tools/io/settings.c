/* SPDX-License-Identifier: BSD-3-Clause */
/* tools/io/settings.c - the settings file (JSON) of docs/FORMATS.md, driven by the library's
 * parameter table (mtt_params_info): every key type- and range-checked, with
 * the JSON key path in the message; initial_tracks; and the table printed for
 * docs/FORMATS.md (mtt_io_list_settings).
 */
#include "mtt_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cJSON.h>

/* Every tracker key is a row of the library's table (mtt_params_info): its
 * type, element count and range come from there, and mtt_params_set does
 * the range check.  A dotted key ("intensity_gate.f1") is a member of a
 * JSON object ("intensity_gate").  initial_tracks is mtt-track's own key. */
#define SEEDS_KEY "initial_tracks"

/* Members of one initial_tracks entry. */
static const char *const seed_keys[] = {"x", "y", "vx", "vy", "P"};
#define N_SEED_KEYS (sizeof seed_keys / sizeof seed_keys[0])

#define KEY_MAX 160 /* longest key path in a message */
#ifdef MTT_REAL_FIXED
#include "core/params_table.h" /* MTT_FX_FRAC_<member>: private (src/) */
#define MTT_IO_FIXED 1
/* A value outside its row's Q format is refused too (docs/FIXED_POINT.md §3). */
#define FIXED_NOTE " within its fixed-point format"

/* Each REAL key's Q format, for the message that names the format's range. */
typedef struct key_frac {
    const char *key;
    int frac;
} key_frac;
#define KF_REAL(key, member, count, lo, hi, flags, cross, tier, text) {key, MTT_FX_FRAC_##member},
#define KF_FLAG(key, member, tier, text)
#define KF_ENUM(key, member, type, n_names, names, tier, text)
static const key_frac key_fracs[] = {MTT_PARAM_ROWS(KF_REAL, KF_FLAG, KF_ENUM)};
#undef KF_REAL
#undef KF_FLAG
#undef KF_ENUM

/* " (this build holds |v| < a, Q f)" for a REAL key, "" for another. */
static void format_range(const char *key, char *buf, size_t size)
{
    size_t k;
    buf[0] = '\0';
    for (k = 0; k < sizeof key_fracs / sizeof key_fracs[0]; ++k) {
        if (strcmp(key, key_fracs[k].key) == 0) {
            const double a = mtt_io_from_real(MTT_FX_MAX, key_fracs[k].frac);
            snprintf(buf, size, " (this build holds |v| < %.4g, Q%d)", a, key_fracs[k].frac);
            return;
        }
    }
}
#else
#define MTT_IO_FIXED 0
#define FIXED_NOTE ""
#endif
/* Values of one key through mtt_params_set/get: imm_transition's
 * MTT_MAX_MODELS^2 slots, imm_models' 1 + MTT_PARAM_MODEL_VALUES MTT_MAX_MODELS. */
#define VALS_MAX (MTT_MAX_MODELS * MTT_MAX_MODELS + MTT_PARAM_MODEL_VALUES * MTT_MAX_MODELS + 3)
/* Values of a key for mtt_params_get / set. */
#define N_VALUES(info) ((info)->type == MTT_PARAM_MODELS ? 1u + MTT_PARAM_MODEL_VALUES * (size_t)(info)->count : (size_t)(info)->count)

typedef struct sctx {
    const char *file;
    mtt_io_settings *s;
} sctx;

static const char *json_type(const cJSON *j)
{
    if (cJSON_IsNumber(j))
        return "a number";
    if (cJSON_IsString(j))
        return "a string";
    if (cJSON_IsBool(j))
        return "a boolean";
    if (cJSON_IsNull(j))
        return "null";
    if (cJSON_IsArray(j))
        return "an array";
    if (cJSON_IsObject(j))
        return "an object";
    return "an unknown value";
}

/* Levenshtein distance, for "did you mean"; large for long names. */
static size_t edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), i, j;
    size_t row[64], prev_diag, tmp;

    if (la >= 64 || lb >= 64)
        return (size_t)-1;
    for (j = 0; j <= lb; ++j)
        row[j] = j;
    for (i = 1; i <= la; ++i) {
        prev_diag = row[0];
        row[0] = i;
        for (j = 1; j <= lb; ++j) {
            size_t best = prev_diag + (a[i - 1] != b[j - 1]);
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            tmp = row[j];
            row[j] = best;
            prev_diag = tmp;
        }
    }
    return row[lb];
}

/* Keeps the closest candidate: at most 2 edits, and fewer than half the name. */
typedef struct suggestion {
    const char *name;
    size_t best_d;
    char best[KEY_MAX];
} suggestion;

static void consider(suggestion *sg, const char *cand, size_t len)
{
    char buf[KEY_MAX];
    size_t d;
    if (len >= sizeof buf)
        return;
    memcpy(buf, cand, len);
    buf[len] = '\0';
    d = edit_distance(sg->name, buf);
    if (d < sg->best_d && 2 * d < strlen(sg->name)) {
        sg->best_d = d;
        memcpy(sg->best, buf, len + 1);
    }
}

/* Is name (under prefix, "" or "intensity_gate.") a key of the table, a
 * group of keys (an object), or neither?  Also collects a suggestion among
 * the names at that level. */
enum { NAME_UNKNOWN, NAME_KEY, NAME_GROUP };
static int classify(const char *prefix, const char *name, size_t *row, suggestion *sg)
{
    const mtt_param_info *info;
    size_t i, plen = strlen(prefix), nlen = strlen(name);
    int kind = NAME_UNKNOWN;

    for (i = 0; mtt_params_info(i, &info) == MTT_OK; ++i) {
        const char *rest = info->key + plen, *dot;
        if (strncmp(info->key, prefix, plen) != 0)
            continue;
        dot = strchr(rest, '.');
        if (dot == NULL && strcmp(rest, name) == 0) {
            *row = i;
            kind = NAME_KEY;
        } else if (dot != NULL && (size_t)(dot - rest) == nlen && strncmp(rest, name, nlen) == 0) {
            kind = NAME_GROUP;
        }
        if (sg != NULL)
            consider(sg, rest, dot != NULL ? (size_t)(dot - rest) : strlen(rest));
    }
    if (sg != NULL && plen == 0)
        consider(sg, SEEDS_KEY, strlen(SEEDS_KEY));
    return kind;
}

static int unknown_key(const sctx *c, const char *key, const suggestion *sg)
{
    if (sg->best_d <= 2)
        mtt_io_error_key(c->file, key, "unknown key (did you mean '%s'?)", sg->best);
    else
        mtt_io_error_key(c->file, key, "unknown key");
    return MTT_IO_EINPUT;
}

/* A finite number that fits mtt_real (float, double; the fixed-point
 * build checks each value against its own format where it is converted:
 * mtt_params_set, seed_real). */
static int get_number(const sctx *c, const cJSON *j, const char *key, double *out)
{
    mtt_real r;
    if (!cJSON_IsNumber(j)) {
        mtt_io_error_key(c->file, key, "must be a number, found %s", json_type(j));
        return MTT_IO_EINPUT;
    }
    if (!isfinite(j->valuedouble)) {
        mtt_io_error_key(c->file, key, "must be a finite number");
        return MTT_IO_EINPUT;
    }
    if (!MTT_IO_FIXED && !mtt_io_to_real(j->valuedouble, 0, &r)) {
        mtt_io_error_key(c->file, key, "%g does not fit the tracker's real type (mtt_real="
                         MTT_IO_REAL_NAME ")", j->valuedouble);
        return MTT_IO_EINPUT;
    }
    *out = j->valuedouble;
    return MTT_IO_OK;
}

static int get_numbers(const sctx *c, const cJSON *j, const char *key, size_t n, double *out)
{
    char sub[KEY_MAX + 32];
    const cJSON *e;
    size_t i = 0;
    int rc;

    if (!cJSON_IsArray(j)) {
        mtt_io_error_key(c->file, key, "must be an array of %lu numbers, found %s",
                         (unsigned long)n, json_type(j));
        return MTT_IO_EINPUT;
    }
    if ((size_t)cJSON_GetArraySize(j) != n) {
        mtt_io_error_key(c->file, key, "must be an array of %lu numbers, found %d elements",
                         (unsigned long)n, cJSON_GetArraySize(j));
        return MTT_IO_EINPUT;
    }
    cJSON_ArrayForEach(e, j)
    {
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)i);
        if ((rc = get_number(c, e, sub, &out[i])) != MTT_IO_OK)
            return rc;
        ++i;
    }
    return MTT_IO_OK;
}

/* Value v of enum key `key` passes mtt_params_check with the other keys
 * as in *base. */
static int value_passes(const mtt_params *base, const char *key, double v)
{
    mtt_params q = *base;
    return mtt_params_set(&q, key, &v, 1) == MTT_OK && mtt_params_check(&q, NULL) == MTT_OK;
}

/* "lm-ihpda, ihpda, ..." for the values that pass mtt_params_check with the
 * defaults or with the other keys as in *base (the fixed-point build's
 * defaults pass none: no declared clutter density), or all of an enum
 * key's names (base NULL). */
static void name_list(char *buf, size_t size, const mtt_param_info *info, const mtt_params *base)
{
    mtt_params def;
    size_t a, len = 0;
    buf[0] = '\0';
    if (base != NULL && mtt_params_default(&def) != MTT_OK)
        return;
    for (a = 0; a < info->n_names; ++a) {
        if (base != NULL && !value_passes(&def, info->key, (double)a) &&
            !value_passes(base, info->key, (double)a))
            continue;
        if (len + strlen(info->names[a]) + 3 >= size)
            break;
        len += (size_t)snprintf(buf + len, size - len, "%s%s", len != 0 ? ", " : "",
                                info->names[a]);
    }
}

/* A bound as a person writes it: "0", "1e-9", "1e6". */
static void format_bound(double v, char *buf, size_t size)
{
    char tmp[32], *e, *d;
    snprintf(tmp, sizeof tmp, "%g", v);
    e = strchr(tmp, 'e');
    if (e != NULL) { /* "1e-09" -> "1e-9", "1e+06" -> "1e6" */
        d = e + 1;
        if (*d == '+')
            memmove(d, d + 1, strlen(d));
        else if (*d == '-')
            ++d;
        while (d[0] == '0' && d[1] != '\0')
            memmove(d, d + 1, strlen(d));
    }
    snprintf(buf, size, "%s", tmp);
}

/* A default value, with the fewest digits that read back as the same
 * mtt_real: the same text from the float and the double build. */
static void format_real(double v, char *buf, size_t size)
{
    int prec;
    for (prec = 1; prec < 17; ++prec) {
        snprintf(buf, size, "%.*g", prec, v);
#ifdef MTT_REAL_FIXED
        /* the decimal constant the default was written as: the Q formats
         * (at least 16 fraction bits, docs/FIXED_POINT.md §3) hold
         * defaults to better than 1e-4 relative */
        if (fabs(strtod(buf, NULL) - v) <= 1e-4 * fabs(v))
            break;
#else
        if ((mtt_real)strtod(buf, NULL) == (mtt_real)v)
            break;
#endif
    }
    format_bound(strtod(buf, NULL), buf, size);
}

/* The range of a REAL key's values: "in (0, 1]", "> 0", "finite". */
static void range_text(const mtt_param_info *info, char *buf, size_t size)
{
    char lo[32], hi[32];
    int has_lo = info->lo > -(double)MTT_REAL_MAX, has_hi = info->hi < (double)MTT_REAL_MAX;
    format_bound(info->lo, lo, sizeof lo);
    format_bound(info->hi, hi, sizeof hi);
    if (has_lo && has_hi)
        snprintf(buf, size, "in %c%s, %s%c", info->lo_open ? '(' : '[', lo, hi,
                 info->hi_open ? ')' : ']');
    else if (has_lo)
        snprintf(buf, size, "%s %s", info->lo_open ? ">" : ">=", lo);
    else if (has_hi)
        snprintf(buf, size, "%s %s", info->hi_open ? "<" : "<=", hi);
    else
        snprintf(buf, size, "finite");
}

/* "[a, b, c]" (n > 1) or "a", each as format_number writes it. */
static void values_text(const double *v, size_t n, void (*format_number)(double, char *, size_t),
                        char *buf, size_t size)
{
    char num[32];
    size_t i, len = 0;
    buf[0] = '\0';
    for (i = 0; i < n && len < size; ++i) {
        format_number(v[i], num, sizeof num);
        len += (size_t)snprintf(buf + len, size - len, "%s%s", i == 0 ? (n > 1 ? "[" : "") : ", ",
                                num);
    }
    if (n > 1 && len < size)
        snprintf(buf + len, size - len, "]");
}

/* mtt_params_set refused v for a REAL key: name the element that is out
 * of range on its own (with the others as they are), and the range. */
static int report_range(const sctx *c, const mtt_param_info *info, const char *key,
                        const double *v)
{
    char sub[KEY_MAX + 32], range[256], val[64];
    double w[VALS_MAX];
    size_t e;

    range_text(info, range, sizeof range);
#ifdef MTT_REAL_FIXED
    {
        char fr[128];
        format_range(info->key, fr, sizeof fr);
        strncat(range, FIXED_NOTE, sizeof range - strlen(range) - 1);
        strncat(range, fr, sizeof range - strlen(range) - 1);
    }
#endif
    for (e = 0; e < info->count && info->count > 1 && info->type == MTT_PARAM_REAL; ++e) {
        mtt_params q = c->s->params;
        if (mtt_params_get(&q, info->key, w, info->count) != MTT_OK)
            break;
        w[e] = v[e];
        if (mtt_params_set(&q, info->key, w, info->count) != MTT_OK) {
            snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)e);
            format_bound(v[e], val, sizeof val);
            mtt_io_error_key(c->file, sub, "must be %s, found %s", range, val);
            return MTT_IO_EINPUT;
        }
    }
    values_text(v, info->count, format_bound, val, sizeof val);
    mtt_io_error_key(c->file, key, "must be %s, found %s", range,
                     info->type == MTT_PARAM_MODELS ? "a model out of range" : val);
    return MTT_IO_EINPUT;
}

/* imm_models: a list of 2 to MTT_MAX_MODELS objects {"model": M, "process_psd": q}, with
 * "turn_psd": w (> 0) for M = ct and for ct only. */
static int parse_models(const sctx *c, const mtt_param_info *info, const cJSON *j, const char *key,
                        double *v)
{
    char sub[KEY_MAX + 48], list[64];
    const cJSON *e, *m;
    size_t i = 0, a;
    int rc, n = cJSON_IsArray(j) ? cJSON_GetArraySize(j) : -1;

    if (n < 2 || n > (int)info->count) {
        mtt_io_error_key(c->file, key, "must be a list of 2 to %u objects {\"model\": M, "
                         "\"process_psd\": q}, found %s", (unsigned)info->count,
                         n < 0 ? json_type(j) : (n < 2 ? "fewer" : "more"));
        return MTT_IO_EINPUT;
    }
    memset(v, 0, VALS_MAX * sizeof v[0]);
    v[0] = (double)n;
    cJSON_ArrayForEach(e, j)
    {
        double *s = v + 1 + MTT_PARAM_MODEL_VALUES * i;
        int ct;
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)i);
        if (!cJSON_IsObject(e)) {
            mtt_io_error_key(c->file, sub, "must be an object {\"model\": M, \"process_psd\": q}, "
                             "found %s", json_type(e));
            return MTT_IO_EINPUT;
        }
        cJSON_ArrayForEach(m, e)
        {
            if (strcmp(m->string, "model") != 0 && strcmp(m->string, "process_psd") != 0 &&
                strcmp(m->string, "turn_psd") != 0) {
                snprintf(sub, sizeof sub, "%s[%lu].%s", key, (unsigned long)i, m->string);
                mtt_io_error_key(c->file, sub, "unknown key (expected model, process_psd, turn_psd)");
                return MTT_IO_EINPUT;
            }
        }
        m = cJSON_GetObjectItemCaseSensitive(e, "model");
        snprintf(sub, sizeof sub, "%s[%lu].model", key, (unsigned long)i);
        name_list(list, sizeof list, info, NULL);
        if (!cJSON_IsString(m)) {
            mtt_io_error_key(c->file, sub, "must be one of: %s", list);
            return MTT_IO_EINPUT;
        }
        for (a = 0; a < info->n_names && strcmp(m->valuestring, info->names[a]) != 0; ++a)
            ;
        if (a == info->n_names) {
            mtt_io_error_key(c->file, sub, "unknown model '%s' (expected one of: %s)",
                             m->valuestring, list);
            return MTT_IO_EINPUT;
        }
        s[0] = (double)a;
        ct = strcmp(info->names[a], "ct") == 0;
        m = cJSON_GetObjectItemCaseSensitive(e, "process_psd");
        snprintf(sub, sizeof sub, "%s[%lu].process_psd", key, (unsigned long)i);
        if (m == NULL) {
            mtt_io_error_key(c->file, sub, "missing");
            return MTT_IO_EINPUT;
        }
        if ((rc = get_number(c, m, sub, &s[1])) != MTT_IO_OK)
            return rc;
        if (!(s[1] > 0.0)) {
            mtt_io_error_key(c->file, sub, "must be > 0, found %g", s[1]);
            return MTT_IO_EINPUT;
        }
        /* turn_psd: the turn rate's noise, required by ct, refused elsewhere */
        m = cJSON_GetObjectItemCaseSensitive(e, "turn_psd");
        snprintf(sub, sizeof sub, "%s[%lu].turn_psd", key, (unsigned long)i);
        if (m == NULL && ct) {
            mtt_io_error_key(c->file, sub, "missing (model ct needs its turn-rate noise)");
            return MTT_IO_EINPUT;
        }
        if (m != NULL && !ct) {
            mtt_io_error_key(c->file, sub, "only model ct has a turn rate");
            return MTT_IO_EINPUT;
        }
        if (m != NULL) {
            if ((rc = get_number(c, m, sub, &s[2])) != MTT_IO_OK)
                return rc;
            if (!(s[2] > 0.0)) {
                mtt_io_error_key(c->file, sub, "must be > 0, found %g", s[2]);
                return MTT_IO_EINPUT;
            }
        }
        ++i;
    }
    return MTT_IO_OK;
}

/* A per-model key: r numbers (per_model 1) or r rows of r numbers
 * (per_model 2), r <= MTT_MAX_MODELS, into the MTT_MAX_MODELS slots (the
 * rest 0); mtt_params_check then holds r against imm_models. */
static int parse_per_model(const sctx *c, const mtt_param_info *info, const cJSON *j,
                           const char *key, double *v)
{
    char sub[KEY_MAX + 32];
    const cJSON *e;
    size_t i = 0;
    int rc, n = cJSON_IsArray(j) ? cJSON_GetArraySize(j) : -1;

    if (n < 1 || n > MTT_MAX_MODELS) {
        mtt_io_error_key(c->file, key, "must be %s, one per model of imm_models (at most %d), "
                         "found %s", info->per_model == 2 ? "an array of rows" : "an array of numbers",
                         MTT_MAX_MODELS, n < 0 ? json_type(j) : "more");
        return MTT_IO_EINPUT;
    }
    memset(v, 0, VALS_MAX * sizeof v[0]);
    if (info->per_model == 1)
        return get_numbers(c, j, key, (size_t)n, v);
    cJSON_ArrayForEach(e, j)
    {
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)i);
        if ((rc = get_numbers(c, e, sub, (size_t)n, v + i * MTT_MAX_MODELS)) != MTT_IO_OK)
            return rc;
        ++i;
    }
    return MTT_IO_OK;
}

/* Read the value of table key `info` into the parameters. */
static int parse_param(const sctx *c, const mtt_param_info *info, const cJSON *j, const char *key)
{
    double v[VALS_MAX];
    size_t a, n = info->count;
    int rc;

    switch (info->type) {
    case MTT_PARAM_MODELS:
        if ((rc = parse_models(c, info, j, key, v)) != MTT_IO_OK)
            return rc;
        n = N_VALUES(info);
        break;
    case MTT_PARAM_REAL:
        if (info->per_model != 0)
            rc = parse_per_model(c, info, j, key, v);
        else
            rc = info->count == 1 ? get_number(c, j, key, v) : get_numbers(c, j, key, info->count, v);
        if (rc != MTT_IO_OK)
            return rc;
        break;
    case MTT_PARAM_BOOL:
        if (!cJSON_IsBool(j)) {
            mtt_io_error_key(c->file, key, "must be true or false, found %s", json_type(j));
            return MTT_IO_EINPUT;
        }
        v[0] = cJSON_IsTrue(j) ? 1.0 : 0.0;
        break;
    default: /* MTT_PARAM_ENUM */
        if (!cJSON_IsString(j)) {
            mtt_io_error_key(c->file, key, "must be a string, found %s", json_type(j));
            return MTT_IO_EINPUT;
        }
        for (a = 0; a < info->n_names && strcmp(j->valuestring, info->names[a]) != 0; ++a)
            ;
        if (a == info->n_names) {
            char list[512];
            name_list(list, sizeof list, info, NULL);
            mtt_io_error_key(c->file, key, "unknown %s '%s' (expected one of: %s)", key,
                             j->valuestring, list);
            return MTT_IO_EINPUT;
        }
        v[0] = (double)a;
        break;
    }
    if (mtt_params_set(&c->s->params, info->key, v, n) != MTT_OK)
        return report_range(c, info, key, v);
    return MTT_IO_OK;
}

/* P of an initial track: 16 numbers row-major, or 4 rows of 4. */
static int parse_cov(const sctx *c, const cJSON *j, const char *key, double P[16])
{
    char sub[KEY_MAX + 32];
    const cJSON *row;
    size_t r = 0;
    int rc;

    if (cJSON_IsArray(j) && cJSON_GetArraySize(j) == 16)
        return get_numbers(c, j, key, 16, P);
    if (!cJSON_IsArray(j) || cJSON_GetArraySize(j) != 4) {
        if (cJSON_IsArray(j))
            mtt_io_error_key(c->file, key,
                             "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), "
                             "found %d elements",
                             cJSON_GetArraySize(j));
        else
            mtt_io_error_key(c->file, key,
                             "must be a 4x4 covariance: 16 numbers row-major (or 4 rows of 4), "
                             "found %s",
                             json_type(j));
        return MTT_IO_EINPUT;
    }
    cJSON_ArrayForEach(row, j)
    {
        snprintf(sub, sizeof sub, "%s[%lu]", key, (unsigned long)r);
        if ((rc = get_numbers(c, row, sub, 4, &P[4 * r])) != MTT_IO_OK)
            return rc;
        ++r;
    }
    return MTT_IO_OK;
}

void mtt_io_seed_key(size_t i, const char *member, char *buf, size_t size)
{
    snprintf(buf, size, SEEDS_KEY "[%lu]%s%s", (unsigned long)i, member != NULL ? "." : "",
             member != NULL ? member : "");
}

/* Was a member named like j given before it in the same object? */
static int given_before(const cJSON *obj, const cJSON *j)
{
    const cJSON *q;
    for (q = obj->child; q != NULL && q != j; q = q->next)
        if (strcmp(q->string, j->string) == 0)
            return 1;
    return 0;
}

/* A seed's value into mtt_real of format fmt (get_number checked it). */
static int seed_real(const sctx *c, const char *key, double v, int fmt, mtt_real *out)
{
    if (mtt_io_to_real(v, fmt, out))
        return MTT_IO_OK;
#ifdef MTT_REAL_FIXED
    {
        mtt_io_error_key(c->file, key, "%g does not fit the tracker's real type (mtt_real="
                         MTT_IO_REAL_NAME ": this build holds |v| < %.4g, Q%d)", v,
                         mtt_io_from_real(MTT_FX_MAX, fmt), fmt);
    }
#else
    mtt_io_error_key(c->file, key, "%g does not fit the tracker's real type (mtt_real="
                     MTT_IO_REAL_NAME ")", v);
#endif
    return MTT_IO_EINPUT;
}

static int parse_tracks(const sctx *c, const cJSON *j, const char *key)
{
    char tkey[KEY_MAX], mkey[KEY_MAX];
    const cJSON *t, *m;
    size_t n, i = 0, k;
    int rc;

    if (!cJSON_IsArray(j)) {
        mtt_io_error_key(c->file, key, "must be an array of track objects, found %s",
                         json_type(j));
        return MTT_IO_EINPUT;
    }
    n = (size_t)cJSON_GetArraySize(j);
    free(c->s->seeds);
    c->s->seeds = NULL;
    c->s->n_seeds = 0;
    if (n == 0)
        return MTT_IO_OK;
    c->s->seeds = calloc(n, sizeof *c->s->seeds);
    if (c->s->seeds == NULL) {
        mtt_io_error("out of memory reading %s", c->file);
        return MTT_IO_ESYS;
    }
    c->s->n_seeds = n;
    cJSON_ArrayForEach(t, j)
    {
        mtt_io_seed *seed = &c->s->seeds[i];
        int seen[N_SEED_KEYS] = {0};
        double v[16];

        mtt_io_seed_key(i, NULL, tkey, sizeof tkey);
        if (!cJSON_IsObject(t)) {
            mtt_io_error_key(c->file, tkey,
                             "must be an object {\"x\", \"y\", \"vx\", \"vy\"[, \"P\"]}, found %s",
                             json_type(t));
            return MTT_IO_EINPUT;
        }
        cJSON_ArrayForEach(m, t)
        {
            mtt_io_seed_key(i, m->string, mkey, sizeof mkey);
            for (k = 0; k < N_SEED_KEYS; ++k)
                if (strcmp(m->string, seed_keys[k]) == 0)
                    break;
            if (k == N_SEED_KEYS) {
                suggestion sg = {m->string, (size_t)-1, ""};
                for (k = 0; k < N_SEED_KEYS; ++k)
                    consider(&sg, seed_keys[k], strlen(seed_keys[k]));
                return unknown_key(c, mkey, &sg);
            }
            if (seen[k]++) {
                mtt_io_error_key(c->file, mkey, "given twice");
                return MTT_IO_EINPUT;
            }
            if (k < 4) {
                if ((rc = get_number(c, m, mkey, v)) != MTT_IO_OK ||
                    (rc = seed_real(c, mkey, v[0], MTT_IO_POS, &seed->x[k])) != MTT_IO_OK)
                    return rc;
            } else {
                size_t e;
                if ((rc = parse_cov(c, m, mkey, v)) != MTT_IO_OK)
                    return rc;
                for (e = 0; e < 16; ++e)
                    if ((rc = seed_real(c, mkey, v[e], MTT_IO_VAR, &seed->P[e])) != MTT_IO_OK)
                        return rc;
            }
        }
        for (k = 0; k < 4; ++k) {
            if (!seen[k]) {
                mtt_io_seed_key(i, seed_keys[k], mkey, sizeof mkey);
                mtt_io_error_key(c->file, mkey,
                                 "missing: every initial track needs x, y, vx and vy");
                return MTT_IO_EINPUT;
            }
        }
        seed->has_P = seen[4];
        ++i;
    }
    return MTT_IO_OK;
}

/* Read every member of obj (the keys under prefix); each must be a key of
 * the table, a group of keys, or initial_tracks (top level), at most once. */
static int parse_object(const sctx *c, const cJSON *obj, const char *prefix)
{
    char key[KEY_MAX];
    const mtt_param_info *info;
    const cJSON *j;
    size_t row = 0;
    int rc;

    /* imm_models first: it sets r, and resets imm_transition and
     * imm_initial to their defaults for r models (whatever the key order). */
    j = prefix[0] == '\0' ? cJSON_GetObjectItemCaseSensitive(obj, "imm_models") : NULL;
    if (j != NULL && classify(prefix, j->string, &row, NULL) == NAME_KEY) {
        if (mtt_params_info(row, &info) != MTT_OK)
            return MTT_IO_ESYS;
        if ((rc = parse_param(c, info, j, j->string)) != MTT_IO_OK)
            return rc;
    }
    cJSON_ArrayForEach(j, obj)
    {
        suggestion sg = {j->string, (size_t)-1, ""};
        int kind = classify(prefix, j->string, &row, &sg);

        int seeds = prefix[0] == '\0' && strcmp(j->string, SEEDS_KEY) == 0;

        snprintf(key, sizeof key, "%s%s", prefix, j->string);
        if (kind == NAME_UNKNOWN && !seeds)
            return unknown_key(c, key, &sg);
        if (given_before(obj, j)) {
            mtt_io_error_key(c->file, key, "given twice");
            return MTT_IO_EINPUT;
        }
        if (seeds) {
            rc = parse_tracks(c, j, key);
        } else if (kind == NAME_KEY) {
            if (mtt_params_info(row, &info) != MTT_OK)
                return MTT_IO_ESYS;
            rc = (prefix[0] == '\0' && strcmp(j->string, "imm_models") == 0) ? MTT_IO_OK
                                                                           : parse_param(c, info, j, key);
        } else {
            char sub[KEY_MAX + 2], list[KEY_MAX * 2];
            size_t i, len = 0, plen;
            snprintf(sub, sizeof sub, "%s.", key);
            plen = strlen(sub);
            if (!cJSON_IsObject(j)) {
                list[0] = '\0';
                for (i = 0; mtt_params_info(i, &info) == MTT_OK && len < sizeof list; ++i)
                    if (strncmp(info->key, sub, plen) == 0)
                        len += (size_t)snprintf(list + len, sizeof list - len, "%s%s",
                                                len != 0 ? ", " : "", info->key + plen);
                mtt_io_error_key(c->file, key, "must be an object with the keys %s, found %s",
                                 list, json_type(j));
                return MTT_IO_EINPUT;
            }
            rc = parse_object(c, j, sub);
        }
        if (rc != MTT_IO_OK)
            return rc;
    }
    return MTT_IO_OK;
}

/* mtt_params_check judges the parameters together; every key passed
 * mtt_params_set, so a bad field breaks a rule between keys (its `cross`). */
/* The name of value v of enum key `key` (the library's table), "?" if none. */
static const char *enum_name(const char *key, int v)
{
    const mtt_param_info *info = NULL;
    size_t row;
    if (mtt_params_find(key, &row) != MTT_OK || mtt_params_info(row, &info) != MTT_OK ||
        info->names == NULL || v < 0 || v >= (int)info->n_names)
        return "?";
    return info->names[v];
}

static int check_params(const sctx *c)
{
    const char *bad = NULL, *text = "?";
    const mtt_param_info *info = NULL;
    char list[512], val[256], range[96];
    double v[VALS_MAX];
    size_t row;
    mtt_status st = mtt_params_check(&c->s->params, &bad);

    switch (st) {
    case MTT_OK:
        return MTT_IO_OK;
    case MTT_ERR_PARAM:
        if (bad == NULL || mtt_params_find(bad, &row) != MTT_OK ||
            mtt_params_info(row, &info) != MTT_OK ||
            mtt_params_get(&c->s->params, bad, v, N_VALUES(info)) != MTT_OK) {
            mtt_io_error_key(c->file, bad != NULL ? bad : "?", "rejected by mtt_params_check");
            return MTT_IO_EINPUT;
        }
        if (info->type == MTT_PARAM_MODELS || info->per_model != 0) {
            /* the IMM keys: r models, and the lists that must match them */
            mtt_io_error_key(c->file, bad, "must be %s (with %d models in imm_models)",
                             info->cross != NULL ? info->cross : "2 or more models",
                             (int)c->s->params.imm_n_models);
            return MTT_IO_EINPUT;
        }
        values_text(v, info->count, format_bound, val, sizeof val);
#ifdef MTT_REAL_FIXED
        if (strcmp(bad, "max_accel") == 0 || strcmp(bad, "meas_sigma") == 0) {
            /* params.c's var_fits: the square is a variance of its format */
            const int acc = strcmp(bad, "max_accel") == 0;
            mtt_io_error_key(c->file, bad, "%s is a variance of this fixed-point build's format (Q%d), "
                             "so it needs about %.4g <= v < %.4g (docs/FIXED_POINT.md §3), found %s",
                             acc ? "with process_psd not given, max_accel² (the process noise per unit of time)"
                                 : "meas_sigma² (R)",
                             MTT_FX_VAR_FRAC,
                             sqrt(0.5 * mtt_io_from_real(1, MTT_FX_VAR_FRAC)),
                             sqrt(mtt_io_from_real(MTT_FX_MAX, MTT_FX_VAR_FRAC)), val);
            return MTT_IO_EINPUT;
        }
#endif
        if (info->cross != NULL) {
            mtt_io_error_key(c->file, bad, "must be %s, found %s", info->cross, val);
        } else {
            range_text(info, range, sizeof range);
            mtt_io_error_key(c->file, bad, "must be %s, found %s", range, val);
        }
        return MTT_IO_EINPUT;
    case MTT_ERR_UNSUPPORTED:
        if (bad != NULL && strcmp(bad, "measurement") == 0) {
            mtt_io_error_key(c->file, bad, "measurement = polar needs a floating-point build with MTT_WITH_MEAS_COV (the "
                             "float and double host builds; not the fixed-point or firmware builds) "
                             "(docs/FIXED_POINT.md §5)");
            return MTT_IO_EINPUT;
        }
        if (bad != NULL && strcmp(bad, "imm_models") == 0) {
            /* params.c: the fixed-point IMM (docs/FIXED_POINT.md §5) */
            mtt_io_error_key(c->file, bad, "this fixed-point build's IMM has cv models only: ca and ct need a "
                             "floating-point build (docs/FIXED_POINT.md §5)");
            return MTT_IO_EINPUT;
        }
        if (bad != NULL && strcmp(bad, "split") == 0) {
            mtt_io_error_key(c->file, bad, "split = true needs motion = imm with a cv model in "
                             "imm_models, and a build with MTT_WITH_SPLIT (motion is %s)",
                             enum_name("motion", (int)c->s->params.motion));
            return MTT_IO_EINPUT;
        }
        if (bad == NULL || mtt_params_find(bad, &row) != MTT_OK ||
            mtt_params_info(row, &info) != MTT_OK ||
            mtt_params_get(&c->s->params, bad, v, 1) != MTT_OK || info->type != MTT_PARAM_ENUM ||
            !(v[0] >= 0.0 && v[0] < (double)info->n_names)) {
            mtt_io_error_key(c->file, bad != NULL ? bad : "?", "not supported by this version");
            return MTT_IO_EINPUT;
        }
        name_list(list, sizeof list, info, &c->s->params);
        if (strcmp(bad, "motion") == 0) {
            mtt_io_error_key(c->file, bad, "motion = imm needs an association other than ihpda-2d and "
                             "lm-ipda-all, and a build with MTT_WITH_IMM%s (association is %s)",
                             (MTT_IO_FIXED && !MTT_WITH_IMM)
                                 ? ", which this fixed-point build leaves out (configs/firmware_fixed_radar.h has it: "
                                   "docs/FIXED_POINT.md §5)"
                                 : "",
                             mtt_params_info(0, &info) == MTT_OK
                                 ? info->names[(size_t)c->s->params.association] : "?");
            return MTT_IO_EINPUT;
        }
        if (strcmp(bad, "lm_ihpda_variant") == 0) {
            mtt_io_error_key(c->file, bad, "lm_ihpda_variant '%s' needs a build with MTT_WITH_CONTEST%s "
                             "(available: %s)", info->names[(size_t)v[0]],
                             MTT_IO_FIXED ? ", which the fixed-point build leaves out with the adaptive "
                                            "process noise (docs/FIXED_POINT.md §5)" : "", list);
            return MTT_IO_EINPUT;
        }
        mtt_io_error_key(c->file, bad, "%s '%s' is not implemented in this version (available: %s)",
                         bad, info->names[(size_t)v[0]], list);
        return MTT_IO_EINPUT;
    default:
        if (mtt_status_text(st, &text) != MTT_OK)
            text = "?";
        mtt_io_error("%s: mtt_params_check failed: %s", c->file, text);
        return MTT_IO_ESYS;
    }
}

/* The settings table as docs/FORMATS.md shows it: one Markdown row per key. */
/* mtt_param_info.tier as docs/CONFIGURATION.md names it */
static const char *const tier_names[MTT_PARAM_TIER_COUNT] = {"sensor", "track", "tuning", "baseline"};

void mtt_io_list_settings(FILE *out)
{
    const mtt_param_info *info;
    mtt_params def;
    double v[VALS_MAX];
    char type[32], range[512], deflt[256];
    size_t i, k, len;

    if (mtt_params_default(&def) != MTT_OK)
        return;
    fputs("| key | type | range | default | meaning | tier |\n|---|---|---|---|---|---|\n", out);
    for (i = 0; mtt_params_info(i, &info) == MTT_OK; ++i) {
        if (mtt_params_get(&def, info->key, v, N_VALUES(info)) != MTT_OK)
            return;
        switch (info->type) {
        case MTT_PARAM_MODELS:
            snprintf(type, sizeof type, "list of objects");
            len = (size_t)snprintf(range, sizeof range, "2 to %u entries; `model` one of ",
                                   (unsigned)info->count);
            for (k = 0; k < info->n_names; ++k)
                len += (size_t)snprintf(range + len, sizeof range - len, "%s`%s`",
                                        k == 0 ? "" : ", ", info->names[k]);
            len += (size_t)snprintf(range + len, sizeof range - len, "; `process_psd` ");
            range_text(info, range + len, sizeof range - len);
            len = strlen(range);
            snprintf(range + len, sizeof range - len, "; `turn_psd` > 0, for `ct` only and required by it");
            len = 0;
            deflt[0] = '\0';
            for (k = 0; k < (size_t)v[0]; ++k) {
                const double *s = v + 1 + MTT_PARAM_MODEL_VALUES * k;
                char num[32], turn[48] = "";
                format_real(s[1], num, sizeof num);
                if (s[2] > 0.0) {
                    size_t t = (size_t)snprintf(turn, sizeof turn, ", \"turn_psd\": ");
                    format_real(s[2], turn + t, sizeof turn - t);
                }
                len += (size_t)snprintf(deflt + len, sizeof deflt - len,
                                        "%s{\"model\": \"%s\", \"process_psd\": %s%s}", k == 0 ? "`[" : ", ",
                                        info->names[(size_t)s[0]], num, turn);
            }
            snprintf(deflt + len, sizeof deflt - len, "]`");
            break;
        case MTT_PARAM_REAL:
            if (info->per_model != 0) {
                size_t r = def.imm_n_models, i2;
                snprintf(type, sizeof type, info->per_model == 2 ? "r rows of r numbers" : "r numbers");
                len = (size_t)snprintf(range, sizeof range, "each ");
                range_text(info, range + len, sizeof range - len);
                len = strlen(range);
                if (info->cross != NULL)
                    snprintf(range + len, sizeof range - len, "; %s", info->cross);
                if (info->per_model == 1) {
                    values_text(v, r, format_real, deflt, sizeof deflt);
                } else {
                    len = (size_t)snprintf(deflt, sizeof deflt, "[");
                    for (i2 = 0; i2 < r; ++i2) {
                        char rowt[96];
                        values_text(v + i2 * MTT_MAX_MODELS, r, format_real, rowt, sizeof rowt);
                        len += (size_t)snprintf(deflt + len, sizeof deflt - len, "%s%s",
                                                i2 == 0 ? "" : ", ", rowt);
                    }
                    snprintf(deflt + len, sizeof deflt - len, "]");
                }
                break;
            }
            if (info->count == 1)
                snprintf(type, sizeof type, "number");
            else
                snprintf(type, sizeof type, "%u numbers", (unsigned)info->count);
            len = (size_t)snprintf(range, sizeof range, "%s", info->count > 1 ? "each " : "");
            range_text(info, range + len, sizeof range - len);
            len = strlen(range);
            if (info->cross != NULL)
                snprintf(range + len, sizeof range - len, "; %s", info->cross);
            values_text(v, info->count, format_real, deflt, sizeof deflt);
            break;
        case MTT_PARAM_BOOL:
            snprintf(type, sizeof type, "boolean");
            snprintf(range, sizeof range, "`true`, `false`");
            snprintf(deflt, sizeof deflt, "`%s`", v[0] != 0.0 ? "true" : "false");
            break;
        default:
            snprintf(type, sizeof type, "name");
            len = 0;
            range[0] = '\0';
            for (k = 0; k < info->n_names; ++k)
                len += (size_t)snprintf(range + len, sizeof range - len, "%s`%s`",
                                        k == 0 ? "" : ", ", info->names[k]);
            snprintf(deflt, sizeof deflt, "`%s`", info->names[(size_t)v[0]]);
            break;
        }
        fprintf(out, "| `%s` | %s | %s | %s | %s | %s |\n", info->key, type, range, deflt, info->text,
                (unsigned)info->tier < MTT_PARAM_TIER_COUNT ? tier_names[info->tier] : "?");
    }
    fputs("| `" SEEDS_KEY "` | list | objects `{\"x\", \"y\", \"vx\", \"vy\"}`, each optionally "
          "with `\"P\"` (4x4 covariance: 16 numbers row-major, or 4 rows of 4) | none | tracks "
          "that exist from the first scan: confirmed, existence 1, identities 0, 1, ... in list "
          "order; without `\"P\"` the two-point covariance of the first scan interval | track |\n",
          out);
}

/* cJSON stops just past the offending token: report the line of the last
 * token before that point, and show that line. */
static void report_json_error(const char *path, const char *text, const char *at)
{
    const char *back, *ln, *q;
    long line = 1;
    int len;

    if (at == NULL || at < text || at > text + strlen(text))
        at = text;
    if (text[strspn(text, " \t\r\n")] == '\0') {
        mtt_io_error_at(path, 0, NULL, "empty file: expected a JSON object");
        return;
    }
    back = at;
    while (back > text && strchr(" \t\r\n", back[-1]) != NULL)
        --back;
    if (back > text)
        --back; /* the last character read */
    for (q = text; q < back; ++q)
        line += *q == '\n';
    for (ln = back; ln > text && ln[-1] != '\n';)
        --ln;
    ln += strspn(ln, " \t");
    len = (int)strcspn(ln, "\r\n");
    if (at[strspn(at, " \t\r\n")] == '\0')
        mtt_io_error_at(path, line, NULL, "malformed JSON: unexpected end of file after '%.*s'",
                        len < 40 ? len : 40, ln);
    else
        mtt_io_error_at(path, line, NULL, "malformed JSON near '%.*s'", len < 40 ? len : 40, ln);
}

void mtt_io_free_settings(mtt_io_settings *s)
{
    free(s->seeds);
    memset(s, 0, sizeof *s);
}

int mtt_io_read_settings(const char *path, mtt_io_settings *s)
{
    sctx c;
    char *text = NULL;
    size_t size = 0;
    const char *end = NULL, *p;
    cJSON *root;
    int rc;

    memset(s, 0, sizeof *s);
    if (mtt_params_default(&s->params) != MTT_OK) {
        mtt_io_error("mtt_params_default failed");
        return MTT_IO_ESYS;
    }
    if ((rc = mtt_io_read_text(path, &text, &size)) != MTT_IO_OK)
        return rc;
    if (strlen(text) != size) {
        mtt_io_error_at(path, 0, NULL, "contains a NUL byte: not a text file");
        free(text);
        return MTT_IO_EINPUT;
    }
    p = text;
    if ((unsigned char)p[0] == 0xEF && (unsigned char)p[1] == 0xBB && (unsigned char)p[2] == 0xBF)
        p += 3; /* UTF-8 byte order mark */
    root = cJSON_ParseWithOpts(p, &end, 1);
    if (root == NULL) {
        report_json_error(path, p, end != NULL ? end : cJSON_GetErrorPtr());
        free(text);
        return MTT_IO_EINPUT;
    }
    free(text);
    c.file = path;
    c.s = s;
    if (!cJSON_IsObject(root)) {
        mtt_io_error_key(path, NULL, "the settings must be a JSON object, found %s",
                         json_type(root));
        rc = MTT_IO_EINPUT;
    } else {
        rc = parse_object(&c, root, "");
        if (rc == MTT_IO_OK)
            rc = check_params(&c);
    }
    cJSON_Delete(root);
    if (rc != MTT_IO_OK)
        mtt_io_free_settings(s);
    return rc;
}
