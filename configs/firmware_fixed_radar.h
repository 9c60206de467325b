/* SPDX-License-Identifier: BSD-3-Clause */
/* configs/firmware_fixed_radar.h - the fixed-point build at a radar's scale
 * (preset host-fixed-radar; docs/FIXED_POINT.md §3, "Scales").
 *
 * Lengths in metres, time in the file's unit (seconds): positions to
 * +-2^(30-10) = +-1,048,576 m with a 1/1024 m LSB, variances at the API
 * to (11.6 km)^2 with a 1/16 m^2 LSB, and clutter densities from 2^-52
 * to 4.7e-7 per m^2 (1e-9 on 22 bits).  The host's default bounds (a
 * scan of 256 detections, 128 tracks: mtt/config.h) and the fixed
 * build's switches (lm-ihpda, ihpda, lm-ipda, ipda with CV motion or an
 * IMM of two cv models).  Each value is a default: a -D still overrides it.  The units
 * are part of MTT_REAL_KIND and so of MTT_CONFIG_ID. */
#ifndef MTT_CONFIGS_FIRMWARE_FIXED_RADAR_H
#define MTT_CONFIGS_FIRMWARE_FIXED_RADAR_H

#ifndef MTT_FX_POS_FRAC
#define MTT_FX_POS_FRAC 10
#endif
#ifndef MTT_FX_VAR_FRAC
#define MTT_FX_VAR_FRAC 4
#endif
#ifndef MTT_FX_DENS_FRAC
#define MTT_FX_DENS_FRAC 42
#endif
#ifndef MTT_FX_GATE_FRAC
#define MTT_FX_GATE_FRAC 24
#endif

/* A radar's detections carry their own covariance (ALGORITHMS.md §3.1):
 * the Cartesian r_xx, r_xy, r_yy in the variance format
 * (docs/FIXED_POINT.md §5); polar detections stay out of this build.  The
 * other firmware switches (IMM, baselines, contest, split all 0) are
 * mtt/config.h's defaults under MTT_REAL_FIXED, and the firmware
 * configurations (configs/firmware.h) keep MTT_WITH_MEAS_COV 0. */
#ifndef MTT_WITH_MEAS_COV
#define MTT_WITH_MEAS_COV 1
#endif

/* The real-target default (ALGORITHMS.md §2.2: max_accel's two cv models
 * and their switching) in fixed point: the IMM of cv models
 * (docs/FIXED_POINT.md §5). */
#ifndef MTT_WITH_IMM
#define MTT_WITH_IMM 1
#endif
#ifndef MTT_MAX_MODELS
#define MTT_MAX_MODELS 2
#endif

#endif /* MTT_CONFIGS_FIRMWARE_FIXED_RADAR_H */
