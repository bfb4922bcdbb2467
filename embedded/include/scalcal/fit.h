/* The fit: a calibration from the per-pose sums of a pose set, as `scalcal calibrate` computes it
 * from a raw log's intervals (numeric/calibration/any_units.cpp, model_calibration.cpp): the model
 * the poses carry (condition of H^T H at most 1e4), a closed-form ellipsoid start when the data are
 * not within 10 % of the magnitude (or the magnitude is unknown), the paper's iterative least
 * squares on the pose means (Gauss-Newton with the exact derivative where the paper's step stops
 * descending, a halving line search), the correction in the paper's convention, and each
 * parameter's standard error (the host's between-pose error model where it applies, else the
 * larger of the noise-based and the residual-based). A result is
 * returned only with SCALCAL_OK: never one the host would not write. */
#ifndef SCALCAL_FIT_H
#define SCALCAL_FIT_H

#include "scalcal/calibration.h"
#include "scalcal/pose.h"

#ifdef __cplusplus
extern "C" {
#endif

struct scalcal_tumble; /* scalcal/tumble.h */

typedef struct {
  scalcal_model model;    /* SCALCAL_MODEL_AUTO (default): the richest of paper9, axis6, bias3 carried */
  scalcal_real magnitude; /* |I| in physical units (9.80665 for g); > 0 unless magnitude_auto */
  int magnitude_auto;     /* 1: the field's strength is unknown (a magnetometer): unit modulus */
  int weight_by_samples;  /* 0 (default): each pose counts once, as for a raw log; 1: by its samples */
  int max_iterations;     /* 50 */
  /* 0 (default): one sample's noise from the scatter within poses (to first order: see README.md);
   * > 0: that noise known beforehand (a long still period's, a datasheet's), in the units of
   * scalcal_calibration.noise, used in its place. */
  scalcal_real noise;
  /* Tumbling mode (scalcal/tumble.h): null (default) for still poses; else the accumulator that filled
   * the set with cells. Each cell is weighted by its samples, its mean modulus taken to second order
   * in its spread, the noise from the accumulator's second differences (`noise` ignored), no
   * between-pose error model, no SCALCAL_E_MOVING; dof and residual_rms count samples. */
  const struct scalcal_tumble* tumble;
} scalcal_fit_options;

/* How the iteration ended. */
typedef enum {
  SCALCAL_FIT_CONVERGED = 0,
  SCALCAL_FIT_ITERATION_LIMIT,
  SCALCAL_FIT_NO_DESCENT, /* no step along the Gauss-Newton direction lowers the residual */
  SCALCAL_FIT_MODEL_EDGE, /* the estimate runs to a parameter of 0.5 (far outside the linear model) */
  SCALCAL_FIT_NOT_FINITE  /* residuals not finite at the start */
} scalcal_termination;

/* What the fit says beyond the calibration: filled as far as the fit got, whatever the status. */
typedef struct {
  scalcal_model model;           /* the model fitted (the chosen one with AUTO) */
  scalcal_real condition;        /* condition number of H^T H of that model at the poses' directions */
  scalcal_real fitted_condition; /* the same at the fitted directions (the corrected means): at most 1e4 */
  int started;                   /* the ellipsoid start was used (data not in the field's units) */
  scalcal_termination termination;
  int iterations;
  int dof;                                            /* poses minus parameters */
  scalcal_real X[SCALCAL_MAX_PARAMETERS];             /* the estimator's parameters (bias / |I|, dk, gamma) */
  scalcal_real predicted_std[SCALCAL_MAX_PARAMETERS]; /* noise-based, reported units (bias raw, dk, rad) */
  scalcal_real achieved_std[SCALCAL_MAX_PARAMETERS];  /* residual-based; NaN when not estimable */
  /* The between-pose error model (README.md, "Standard errors"): with noise within poses and at
   * least 5 more poses than parameters, a pose's mean modulus varies by between_std (REML) besides
   * within_std / sqrt(n_k), and the calibration's standard errors are model_std; else error_model is
   * 0, these are NaN and the standard errors are the larger of predicted and achieved. */
  int error_model;
  int error_model_iterations;                     /* REML's Fisher steps */
  scalcal_real between_std, within_std;           /* units of scalcal_calibration.noise */
  scalcal_real model_std[SCALCAL_MAX_PARAMETERS]; /* reported units */
  scalcal_noise_source noise_source;
  scalcal_real chi_square; /* residuals against the noise within poses; NaN when not defined */
} scalcal_fit_report;

/* The defaults above. */
void scalcal_fit_options_default(scalcal_fit_options* options);

/* Fits `set` (at least as many poses as the model has parameters). SCALCAL_OK fills *cal; any other
 * status leaves *cal untouched and says why: SCALCAL_E_TOO_FEW_POSES, SCALCAL_E_NOT_IDENTIFIABLE,
 * SCALCAL_E_NO_START, SCALCAL_E_MAGNITUDE, SCALCAL_E_NOT_CONVERGED, SCALCAL_E_NOT_FINITE,
 * SCALCAL_E_DEGENERATE, SCALCAL_E_ARGUMENT, and SCALCAL_E_MOVING for a set filled by the detector
 * from a stream that moved in more than 3/4 of its windows (README.md, detector rule 8). report may
 * be null. Stack: about 3 KB in float. */
scalcal_status scalcal_fit(const scalcal_pose_set* set, const scalcal_fit_options* options, scalcal_calibration* cal,
                           scalcal_fit_report* report);

#ifdef __cplusplus
}
#endif

#endif
