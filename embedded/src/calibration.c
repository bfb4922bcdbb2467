/* A calibration applied to a sample, filled from a matrix, and the status texts
 * (scalcal/calibration.h, scalcal/real.h). */
#include <string.h>

#include "fit_internal.h"

void scalcal_correct(const scalcal_calibration* cal, const scalcal_real raw[3], scalcal_real physical[3]) {
  const scalcal_real d[3] = {raw[0] - cal->offset[0], raw[1] - cal->offset[1], raw[2] - cal->offset[2]};
  int i;
  for (i = 0; i < 3; ++i) physical[i] = cal->matrix[i][0] * d[0] + cal->matrix[i][1] * d[1] + cal->matrix[i][2] * d[2];
}

scalcal_status scalcal_calibration_from_matrix(scalcal_calibration* cal, scalcal_model model,
                                               const scalcal_real offset[3], const scalcal_real* matrix,
                                               scalcal_real magnitude, int magnitude_auto, scalcal_real nominal_gain) {
  sc_correction c;
  const scalcal_real nan = (scalcal_real)NAN;
  int k;
  if (!cal || !offset || !matrix || !(nominal_gain > 0)) return SCALCAL_E_ARGUMENT;
  if (!sc_canonical(matrix, offset, &c)) return SCALCAL_E_DEGENERATE;
  memset(cal, 0, sizeof *cal);
  cal->model = model;
  memcpy(cal->offset, offset, sizeof cal->offset);
  memcpy(cal->matrix, matrix, sizeof cal->matrix); /* 9 values, by rows */
  cal->magnitude = magnitude;
  cal->magnitude_auto = magnitude_auto;
  cal->nominal_gain = nominal_gain;
  for (k = 0; k < 3; ++k) {
    cal->gain[k] = c.scale[k];
    cal->scale_deviation[k] = c.scale[k] / nominal_gain - 1;
    cal->nonorthogonality[k] = c.nonorthogonality[k];
    cal->bias_std[k] = cal->scale_deviation_std[k] = cal->nonorthogonality_std[k] = cal->gain_std[k] = nan;
  }
  cal->nominal_gain_std = cal->noise = cal->residual_rms = nan;
  return SCALCAL_OK;
}

const char* scalcal_status_text(scalcal_status status) {
  switch (status) {
    case SCALCAL_OK:
      return "ok";
    case SCALCAL_E_ARGUMENT:
      return "bad argument (null pointer, zero capacity or an option out of range)";
    case SCALCAL_E_TOO_FEW_POSES:
      return "too few poses for the model (bias3 3, axis6 6, paper9 9)";
    case SCALCAL_E_NOT_IDENTIFIABLE:
      return "the poses' directions do not identify the model (add poses)";
    case SCALCAL_E_NO_START:
      return "no ellipsoid passes near the pose means (too few or too flat)";
    case SCALCAL_E_MAGNITUDE:
      return "the poses' modulus is far from the magnitude (wrong magnitude or units?)";
    case SCALCAL_E_NOT_CONVERGED:
      return "the fit did not converge: not to be used";
    case SCALCAL_E_NOT_FINITE:
      return "a value that is not finite";
    case SCALCAL_E_DEGENERATE:
      return "the correction is degenerate or ill-conditioned (condition > 100)";
    case SCALCAL_E_FULL:
      return "the pose set is full";
    case SCALCAL_E_RECORD:
      return "the record's magic, version, size or checksum is wrong";
    case SCALCAL_E_MOVING:
      return "the poses are not still: the stream moves most of the time; a magnetometer turned continuously "
             "needs the tumbling mode (scalcal/tumble.h)";
    case SCALCAL_E_NO_RESTS:
      return "a rate table's log without two rests (table stopped): the bias is not observed";
  }
  return "unknown status";
}
