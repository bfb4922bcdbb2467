// `calibrate --model NAME` for a model other than the paper's: the paper's estimator with the
// model's row and meter (numeric/calibration/model_calibration.hpp), in the file's units as given,
// what scalar calibration at one magnitude cannot identify for that model, and the measured
// program judged by the model's criteria against its proven limits.
#pragma once
#include <string>
#include <vector>

#include "experiments/cli/report.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::cli {

struct ModelCalibrationRequest {
  std::string file, out;
  ModelKind model = ModelKind::paper9;
  Modulus modulus = Modulus::norm;
  double magnitude = 1;
  bool weight_by_samples = true;
};

// Status 0, or 1 when the iteration did not converge. Throws InputError for a program that cannot
// identify the model's parameters or data far from unit gain.
Report model_calibration_report(const ModelCalibrationRequest& request, const std::vector<PositionSamples>& data);

// What scalar calibration at one magnitude leaves out for the model, in one sentence.
std::string not_identifiable_text(ModelKind model);

}  // namespace scalcal::cli
