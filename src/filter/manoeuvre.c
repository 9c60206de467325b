/* SPDX-License-Identifier: BSD-3-Clause */
/* manoeuvre.c - the motion that the sensor's facts and max_accel derive
 * (ALGORITHMS.md §2.2): the resolution of the keys a user left out
 * (process_psd 0, motion auto, imm_models / imm_transition / imm_initial
 * not given, split_dv 0) into the levels the tracker runs with, and per
 * frame their values at this scan interval ΔT:
 *
 *   CV:  q = a² ΔT  (the velocity change over a scan of order a ΔT:
 *        Bar-Shalom, Li, Kirubarajan, Estimation with Applications to
 *        Tracking and Navigation, 2001, §6.2.2)
 *   IMM: a steady cv model with (a/10)² ΔT and a manoeuvring one with
 *        a² ΔT; switching as a two-state Markov chain in continuous time
 *        with the manoeuvre time τ = vmax/a (leaving the manoeuvre at rate
 *        1/τ, entering it at rate 1/(10 τ)): Π(ΔT) in closed form
 *   split_dv = a ΔT
 *
 * Explicit keys override each piece.  The fixed-point build (no split)
 * has a in the position format, a² in the variance format (MTT_VAR_OF;
 * mtt_params_check refuses an a whose square does not fit it) and q = a² ΔT
 * per frame with ΔT in Q16 frames, saturated; the IMM's levels are formed
 * from the accelerations with one rounding (var_dt), the rates in Q30 per
 * T0 and Π(ΔT) from mtt_fx_exp_neg (docs/FIXED_POINT.md §3). */
#include <string.h>

#include "mtt_internal.h"

/* [CHOICE, ALGORITHMS.md §2.2] the steady model's acceleration over the
 * manoeuvre's, and the manoeuvre's share of the time: a tenth each */
#define STEADY_FRACTION 0.1
#define ENTER_OVER_LEAVE 0.1
#define ADAPT_RISE_DERIVED 100.0

#ifdef MTT_REAL_FIXED
#define PSD_UNGIVEN MTT_FX_CONST_SAT(5.0, MTT_FX_VAR_FRAC)
#else
#define PSD_UNGIVEN MTT_R(5.0)
#endif

int mtt_manoeuvre_derived(const mtt_params *p)
{
    return p->process_psd == MTT_ZERO && p->max_accel > MTT_ZERO;
}

#if MTT_WITH_IMM
/* All of v[0..n) zero: the key was not given. */
static int all_zero(const mtt_real *v, size_t n)
{
    size_t k;
    for (k = 0; k < n; ++k) {
        if (v[k] != MTT_ZERO) {
            return 0;
        }
    }
    return 1;
}

#ifdef MTT_REAL_FIXED
/* Π(dt) of the two-state chain with rates l01 (0 -> 1) and l10 (1 -> 0),
 * Q30 per T0 (dt Q16 frames): Π01 = (l01 / s)(1 - e^(-s dt)), s = l01 + l10,
 * formed as the share l01 / s times the Q30 complement (no 1 / s that may
 * not fit); s dt beyond the kernel's 256 is the stationary chain. */
static void switch_matrix(mtt_real l01, mtt_real l10, mtt_real dt, mtt_real Pi[][MTT_MAX_MODELS])
{
    const int32_t s = mtt_fx_add(l01, l10);
    /* s dt in Q24: Q30 x Q16 >> 22 */
    const int32_t y = mtt_fx_mul(s, dt, MTT_FX_PROB_FRAC + MTT_FX_T_FRAC - MTT_FX_D2_FRAC);
    const int32_t g = MTT_P(1.0) - ((y >= 0 && y < MTT_FX_MAX) ? mtt_fx_exp_neg_q30((uint32_t)y) : 0);
    Pi[0][1] = (s > 0) ? MTT_MUL_PP(mtt_fx_div(l01, s, MTT_FX_PROB_FRAC), g) : 0;
    Pi[0][0] = MTT_P(1.0) - Pi[0][1];
    Pi[1][0] = (s > 0) ? MTT_MUL_PP(mtt_fx_div(l10, s, MTT_FX_PROB_FRAC), g) : 0;
    Pi[1][1] = MTT_P(1.0) - Pi[1][0];
}

/* round(b² dt) in the variance format for an acceleration b (position
 * format) and dt (Q16 frames): b² with VAR_G guard bits, then one more
 * rounding with dt, so that a small level (a steady model's (a/10)² ΔT of
 * a few units) is not rounded twice; a b² beyond the guarded format goes
 * the plain way (MTT_VAR_OF, then MTT_MUL_T). */
#define VAR_G ((2 * MTT_FX_POS_FRAC - MTT_FX_VAR_FRAC < 8) ? 2 * MTT_FX_POS_FRAC - MTT_FX_VAR_FRAC : 8)
static mtt_real var_dt(mtt_pos b, mtt_real dt)
{
#if 2 * MTT_FX_POS_FRAC - MTT_FX_VAR_FRAC > 0
    const int32_t f = mtt_fx_mul(b, b, 2 * MTT_FX_POS_FRAC - MTT_FX_VAR_FRAC - VAR_G);
    if (f < (MTT_FX_MAX >> 1)) {
        return mtt_fx_mul(f, dt, MTT_FX_T_FRAC + VAR_G);
    }
#endif
    return MTT_MUL_T(dt, MTT_VAR_OF(b));
}
#else
/* Π(dt) of the two-state chain with rates l01 (0 -> 1) and l10 (1 -> 0). */
static void switch_matrix(mtt_real l01, mtt_real l10, mtt_real dt, mtt_real Pi[][MTT_MAX_MODELS])
{
    const mtt_real s = l01 + l10;
    const mtt_real f = (MTT_R(1.0) - mtt_exp(-s * dt)) / s;
    Pi[0][1] = l01 * f;
    Pi[0][0] = MTT_R(1.0) - Pi[0][1];
    Pi[1][0] = l10 * f;
    Pi[1][1] = MTT_R(1.0) - Pi[1][0];
}
#endif
#endif

void mtt_manoeuvre_resolve(mtt_params *p, mtt_manoeuvre *lv)
{
    const int derive = mtt_manoeuvre_derived(p);
    memset(lv, 0, sizeof *lv);
    if (p->motion == MTT_MOTION_AUTO) {
        p->motion = (derive && MTT_WITH_IMM && mtt_modes[p->association].imm) ? MTT_MOTION_IMM : MTT_MOTION_CV;
    }
    if (p->process_psd == MTT_ZERO && !derive) {
        p->process_psd = PSD_UNGIVEN; /* neither given: docs/FORMATS.md's 5 */
    }
#if MTT_WITH_CONTEST
    if (p->adapt_s_max == MTT_ZERO) {
        /* [CHOICE, ALGORITHMS.md §2.1] a physical bound may be under-guessed:
         * the noise may rise 100-fold (the acceleration 10-fold); a tuned
         * process_psd is the upper level (the synthetic scenes regress
         * with a rise: docs/reports/MOTION.md) */
        p->adapt_s_max = derive ? MTT_R(ADAPT_RISE_DERIVED) : MTT_R(1.0);
    }
#endif
    if (derive) {
        lv->bits |= MTT_DERIVE_CV;
        lv->cv = MTT_VAR_OF(p->max_accel);
        p->process_psd = lv->cv; /* a placeholder at ΔT = 1 until the first frame */
    }
#ifndef MTT_REAL_FIXED
    if (p->split_dv == MTT_ZERO && p->max_accel > MTT_ZERO) {
        lv->bits |= MTT_DERIVE_DV;
        lv->dv = p->max_accel;
        p->split_dv = lv->dv;
    }
#endif
#if MTT_WITH_IMM
    {
        const uint8_t r = p->imm_n_models;
        uint8_t j;
        if (all_zero(p->imm_psd, MTT_MAX_MODELS)) {
            if (derive && MTT_MAX_MODELS >= 2) {
                /* two cv models, steady and manoeuvring (§2.2) */
#ifdef MTT_REAL_FIXED
                /* the accelerations; the levels var_dt of them each frame */
                const mtt_pos as = MTT_MUL_PP(MTT_P(STEADY_FRACTION), p->max_accel);
#else
                const mtt_real as = MTT_R(STEADY_FRACTION) * p->max_accel;
#endif
                p->imm_n_models = 2u;
                memset(p->imm_turn_psd, 0, sizeof p->imm_turn_psd);
                for (j = 0; j < MTT_MAX_MODELS; ++j) {
                    p->imm_model[j] = MTT_MODEL_CV;
#ifdef MTT_REAL_FIXED
                    lv->imm[j] = (j == 0u) ? as : p->max_accel;
                    /* at ΔT = 1 until the first frame; a level below the
                     * format's resolution is its unit (docs/FIXED_POINT.md §5) */
                    p->imm_psd[j] = var_dt(lv->imm[j], MTT_TIME(1.0));
                    p->imm_psd[j] = (p->imm_psd[j] > 0) ? p->imm_psd[j] : 1;
#else
                    lv->imm[j] = (j == 0u) ? as * as : lv->cv;
                    p->imm_psd[j] = lv->imm[j];
#endif
                }
                lv->bits |= MTT_DERIVE_MODELS;
            } else {
                for (j = 0; j < r && j < MTT_MAX_MODELS; ++j) {
                    p->imm_psd[j] = p->process_psd; /* docs/FORMATS.md: follows process_psd */
                }
                if (derive) {
                    lv->bits |= MTT_DERIVE_MODELS; /* followed the derived process_psd */
                    for (j = 0; j < MTT_MAX_MODELS; ++j) {
#ifdef MTT_REAL_FIXED
                        lv->imm[j] = p->max_accel; /* the acceleration: var_dt */
#else
                        lv->imm[j] = lv->cv;
#endif
                    }
                }
            }
        }
        if (all_zero(&p->imm_transition[0][0], (size_t)MTT_MAX_MODELS * (size_t)MTT_MAX_MODELS)) {
            if (derive && p->imm_n_models == 2u && (lv->bits & MTT_DERIVE_MODELS)) {
#ifdef MTT_REAL_FIXED
                lv->rate[1] = (p->vmax > 0) ? mtt_fx_div(p->max_accel, p->vmax, MTT_FX_PROB_FRAC) : MTT_FX_MAX; /* Q30 per T0 */
                lv->rate[0] = MTT_MUL_PP(MTT_P(ENTER_OVER_LEAVE), lv->rate[1]);
#else
                lv->rate[1] = p->max_accel / p->vmax; /* 1/τ: leaving the manoeuvre */
                lv->rate[0] = MTT_R(ENTER_OVER_LEAVE) * lv->rate[1];
#endif
                lv->bits |= MTT_DERIVE_PI;
                switch_matrix(lv->rate[0], lv->rate[1], MTT_TIME(1.0), p->imm_transition);
            } else {
                mtt_params_imm_pi_default(p);
            }
        }
        if (all_zero(p->imm_initial, MTT_MAX_MODELS)) {
            p->imm_initial[0] = MTT_P(1.0);
        }
    }
#endif
}

void mtt_manoeuvre_frame(mtt_tracker *trk, mtt_real dt)
{
    const mtt_manoeuvre *lv = &trk->lv;
    mtt_params *p = &trk->par;
    if (lv->bits & MTT_DERIVE_CV) {
        p->process_psd = MTT_MUL_T(dt, lv->cv);
    }
#ifndef MTT_REAL_FIXED
    if (lv->bits & MTT_DERIVE_DV) {
        p->split_dv = lv->dv * dt;
    }
#endif
#if MTT_WITH_IMM
    if (lv->bits & MTT_DERIVE_MODELS) {
        uint8_t j;
        for (j = 0; j < p->imm_n_models; ++j) {
#ifdef MTT_REAL_FIXED
            p->imm_psd[j] = var_dt(lv->imm[j], dt);
#else
            p->imm_psd[j] = lv->imm[j] * dt;
#endif
        }
    }
    if (lv->bits & MTT_DERIVE_PI) {
        switch_matrix(lv->rate[0], lv->rate[1], dt, p->imm_transition);
    }
#endif
}
