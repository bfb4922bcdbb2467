/* A calibration as firmware applies it: physical = matrix (raw - offset), the paper's convention
 * (the misalignment's rotation part zero: phi_kj = phi_jk = gamma_kj / 2), with the paper's
 * parameters and their standard errors. Produced by scalcal_fit (scalcal/fit.h), stored by
 * scalcal/record.h, or filled from the header `scalcal export --format c` writes. */
#ifndef SCALCAL_CALIBRATION_H
#define SCALCAL_CALIBRATION_H

#include <stdint.h>

#include "scalcal/real.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The models: the number is the count of parameters. AUTO asks the fit for the richest model the
 * poses carry. */
typedef enum {
  SCALCAL_MODEL_AUTO = 0,
  SCALCAL_MODEL_BIAS3 = 3,  /* offsets only (one common gain from the start) */
  SCALCAL_MODEL_AXIS6 = 6,  /* offsets and a gain per axis */
  SCALCAL_MODEL_PAPER9 = 9, /* offsets, gains and non-orthogonality (the paper's model) */
} scalcal_model;

/* Where the noise (and the noise-based standard errors) came from. */
typedef enum {
  SCALCAL_NOISE_NONE = 0,
  SCALCAL_NOISE_SCATTER,    /* the scatter of the samples within poses */
  SCALCAL_NOISE_RESIDUALS,  /* the residuals between poses (one sample per pose) */
  SCALCAL_NOISE_GIVEN,      /* scalcal_fit_options.noise */
  SCALCAL_NOISE_DIFFERENCES /* tumbling: the samples' second differences (scalcal/tumble.h) */
} scalcal_noise_source;

typedef struct {
  scalcal_model model;
  scalcal_real offset[3];           /* raw units (the bias Delta) */
  scalcal_real matrix[3][3];        /* physical per raw unit, by rows */
  scalcal_real magnitude;           /* |I| in physical units; 1 with magnitude auto (unit modulus) */
  int magnitude_auto;               /* the field's strength was unknown: the correction maps to unit modulus */
  scalcal_real nominal_gain;        /* raw units per physical unit the scale deviations are relative to */
  scalcal_real gain[3];             /* k_i: raw units per physical unit (the lengths of matrix^-1's rows) */
  scalcal_real scale_deviation[3];  /* gain / nominal_gain - 1 */
  scalcal_real nonorthogonality[3]; /* gamma_xy, gamma_yz, gamma_zx (radians) */
  /* Standard errors: the between-pose error model's where it applies (scalcal/fit.h), else the
   * larger of the noise-based and the residual-based (NaN: not estimable, and for the parameters the
   * model does not have). */
  scalcal_real bias_std[3], scale_deviation_std[3], nonorthogonality_std[3];
  scalcal_real gain_std[3], nominal_gain_std;
  scalcal_real noise;        /* std of one sample's modulus (physical units when started, else raw) */
  scalcal_real residual_rms; /* RMS over poses of |corrected mean| - |I| (same units as noise) */
  uint32_t positions, samples;
} scalcal_calibration;

/* physical = matrix (raw - offset). raw and physical may be the same array. */
void scalcal_correct(const scalcal_calibration* cal, const scalcal_real raw[3], scalcal_real physical[3]);

/* Fills a calibration from offset and matrix (9 values, by rows) alone, as `scalcal export --format c`
 * writes them, or from a datasheet's nominal values: the gains, scale deviations (relative to
 * nominal_gain) and non-orthogonality of the matrix's metric (a rotation of the matrix changes none
 * of them); standard errors NaN. SCALCAL_E_DEGENERATE when the matrix is singular or two axes are
 * nearly parallel. */
scalcal_status scalcal_calibration_from_matrix(scalcal_calibration* cal, scalcal_model model,
                                               const scalcal_real offset[3], const scalcal_real* matrix,
                                               scalcal_real magnitude, int magnitude_auto, scalcal_real nominal_gain);

#ifdef __cplusplus
}
#endif

#endif
