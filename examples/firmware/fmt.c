/* SPDX-License-Identifier: BSD-3-Clause */
/* fmt.c - integer, fixed-point and hex formatting for the firmware
 * example: no printf, no double, no division by non-constants (and in
 * the fixed-point build no float: fmt_q prints a Q value). */
#include "fw.h"

char *fmt_str(char *buf, const char *s)
{
    while (*s != '\0') {
        *buf++ = *s++;
    }
    *buf = '\0';
    return buf;
}

char *fmt_u32(char *buf, uint32_t v)
{
    char tmp[10];
    int n = 0;
    do {
        tmp[n++] = (char)('0' + (v % 10u));
        v /= 10u;
    } while (v != 0u);
    while (n > 0) {
        *buf++ = tmp[--n];
    }
    *buf = '\0';
    return buf;
}

char *fmt_i32(char *buf, int32_t v)
{
    if (v < 0) {
        *buf++ = '-';
        return fmt_u32(buf, 0u - (uint32_t)v);
    }
    return fmt_u32(buf, (uint32_t)v);
}

static const uint32_t iscale[7] = {1u, 10u, 100u, 1000u, 10000u, 100000u, 1000000u};

/* "-"ip.fp with `decimals` (1..6) digits of fp (< 10^decimals), or ip alone. */
static char *fmt_dec(char *buf, int neg, uint32_t ip, uint32_t fp, int decimals)
{
    uint32_t d;
    int i;
    if (neg) {
        *buf++ = '-';
    }
    buf = fmt_u32(buf, ip);
    if (decimals > 0) {
        *buf++ = '.';
        for (i = decimals - 1, d = iscale[decimals - 1]; i >= 0; --i, d /= 10u) {
            *buf++ = (char)('0' + (fp / d) % 10u);
        }
        *buf = '\0';
    }
    return buf;
}

#ifdef MTT_REAL_FIXED
char *fmt_q(char *buf, int32_t v, int frac, int decimals)
{
    uint32_t a = (v < 0) ? 0u - (uint32_t)v : (uint32_t)v;
    uint32_t ip, fr, fp;
    if (decimals < 0) {
        decimals = 0;
    }
    if (decimals > 6) {
        decimals = 6;
    }
    if (frac < 0) {
        frac = 0;
    }
    if (frac > 31) {
        frac = 31;
    }
    ip = (frac == 0) ? a : (a >> frac);
    fr = (frac == 0) ? 0u : (a & ((1u << frac) - 1u));
    /* fp = round(fr 10^decimals / 2^frac), in 64 bits (integer helpers
     * only: __aeabi_lmul, __aeabi_llsr) */
    fp = (frac == 0) ? 0u
                     : (uint32_t)(((uint64_t)fr * iscale[decimals] + ((uint64_t)1 << (frac - 1))) >> frac);
    if (fp >= iscale[decimals]) {
        ++ip;
        fp -= iscale[decimals];
    }
    return fmt_dec(buf, v < 0 && (ip != 0u || fp != 0u), ip, fp, decimals);
}

char *fmt_hex32(char *buf, uint32_t v)
{
    static const char digits[] = "0123456789abcdef";
    int i;
    for (i = 7; i >= 0; --i) {
        *buf++ = digits[(v >> (4 * i)) & 0xfu];
    }
    *buf = '\0';
    return buf;
}
#else
char *fmt_fixed(char *buf, float v, int decimals)
{
    static const float scale[7] = {1.0f, 10.0f, 100.0f, 1e3f, 1e4f, 1e5f, 1e6f};
    float a;
    uint32_t q;
    if (decimals < 0) {
        decimals = 0;
    }
    if (decimals > 6) {
        decimals = 6;
    }
    if (!(v == v)) {
        return fmt_str(buf, "nan");
    }
    a = (v < 0.0f) ? -v : v;
    a = a * scale[decimals] + 0.5f;
    if (!(a < 2.0e9f)) {
        return fmt_str(buf, "ovf");
    }
    q = (uint32_t)a;
    return fmt_dec(buf, v < 0.0f && q != 0u, q / iscale[decimals], q % iscale[decimals], decimals);
}

char *fmt_hex(char *buf, float v)
{
    static const char digits[] = "0123456789abcdef";
    union {
        float f;
        uint32_t u;
    } bits;
    int i;
    bits.f = v;
    for (i = 7; i >= 0; --i) {
        *buf++ = digits[(bits.u >> (4 * i)) & 0xfu];
    }
    *buf = '\0';
    return buf;
}
#endif /* MTT_REAL_FIXED */
