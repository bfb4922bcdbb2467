/* A gyro on a single-axis rate table (the host's `scalcal calibrate --instrument gyro --magnitude
 * RATE`, numeric/gyro/known_modulus.cpp and rate_segments.cpp): the table turns at a known rate, so
 * the gyro's output is constant over each segment and the still-pose detector closes a pose per
 * segment; between segments the table rests and the output is the bias alone. The poses are split as
 * the host splits its intervals: the largest group (at least two) of poses whose means coincide within
 * 30 standard errors of their difference are the rests, every other pose is a segment. The fit is the
 * host's: weighted least squares on |Omega_i| - rate of the segments (o, k, gamma: raw = o +
 * diag(k) Phi(gamma) Omega), the rests' means as observations of o, each group's variance rescaled by
 * its chi-square per degree of freedom (Levenberg-Marquardt, Jacobian by central differences). Its own
 * translation unit (rate_table.c): a build that does not call it does not link it. */
#ifndef SCALCAL_RATE_TABLE_H
#define SCALCAL_RATE_TABLE_H

#include "scalcal/calibration.h"
#include "scalcal/fit.h"
#include "scalcal/pose.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
  scalcal_model model; /* SCALCAL_MODEL_AUTO (default): the richest of paper9, axis6, bias3 carried */
  scalcal_real rate;   /* the table's rate in physical units (rad/s, deg/s): > 0 */
  int max_iterations;  /* 100 (per pass of the variance components, as the host) */
} scalcal_rate_table_options;

typedef struct {
  scalcal_model model;    /* the model fitted; bias3 frees o and one gain (4 unknowns) */
  scalcal_real condition; /* the model's information at the start's directions, rests included */
  uint32_t segments, rests;
  uint8_t rest[SCALCAL_MAX_POSES]; /* 1: pose i is a rest */
  scalcal_termination termination;
  int iterations;
  /* o (raw units), k (raw per physical unit), gamma (rad); NaN for what the model does not free */
  scalcal_real parameters[SCALCAL_MAX_PARAMETERS];
  scalcal_real standard_error[SCALCAL_MAX_PARAMETERS]; /* with the groups' variance scales */
  scalcal_real predicted_std[SCALCAL_MAX_PARAMETERS];  /* without */
  scalcal_real segment_scale, rest_scale;              /* achieved / predicted variance, >= 1 */
  scalcal_real segment_dof, rest_dof;
  scalcal_real normal_condition; /* of the normal matrix scaled to unit diagonal */
} scalcal_rate_table_report;

void scalcal_rate_table_options_default(scalcal_rate_table_options* options);

/* Fits a rate table's poses (at most SCALCAL_MAX_POSES). SCALCAL_OK fills *cal (offset o, matrix
 * physical = matrix (raw - offset), gain k, scale_deviation k - 1 with nominal_gain 1, magnitude the
 * rate, standard errors the host's achieved ones, noise the host's: the rests' median scatter through
 * the matrix); else *cal is untouched: SCALCAL_E_NO_RESTS (fewer than two poses coincide: the bias is
 * not observed; the host would fit without rests, the library does not), SCALCAL_E_TOO_FEW_POSES
 * (segments, with the rests counting 3, fewer than the model's unknowns), SCALCAL_E_MAGNITUDE (a
 * segment under half the rate at the start's gain: a rest not linked with the others, or a wrong
 * rate), SCALCAL_E_NOT_IDENTIFIABLE (condition above 1e4, also for a model asked for),
 * SCALCAL_E_NOT_CONVERGED, SCALCAL_E_NOT_FINITE, SCALCAL_E_DEGENERATE, SCALCAL_E_MOVING,
 * SCALCAL_E_ARGUMENT. report may be null. */
scalcal_status scalcal_fit_rate_table(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                                      scalcal_calibration* cal, scalcal_rate_table_report* report);

#ifdef __cplusplus
}
#endif

#endif
