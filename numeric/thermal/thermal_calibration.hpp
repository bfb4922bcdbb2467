// Calibration of a thermal log (issue 53): still poses, each with its mean output and mean temperature,
// fitted by Gauss-Newton to a thermal model BASE+Tk with BASE = paper9: the meter's nine parameters
// X(tau) = X_0 + sum_j X_j tau^j (only the biases drift under +bias:Tk), |compensate(w_i; X(tau_i))| = |I|
// at every pose. Standard errors from the residuals (sigma^2 (J^T J)^-1, n - p degrees of freedom). A fit
// whose poses cannot identify the model (fewer set-points than k + 1, too few poses, a singular or
// ill-conditioned J^T J) or that does not converge is returned with `problem` set, never as good.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/thermal/temperature_range.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal {

struct ThermalPose {
  Eigen::Vector3d mean;  // the pose's mean output, file units
  double celsius = 0;    // its mean temperature
  int samples = 0;
  double start = 0, stop = 0;  // seconds
};

struct ThermalFit {
  ThermalModel model;
  TemperatureRange range;                         // tau's interval: the poses' temperatures' span unless given
  double magnitude = 1;                           // |I| in file units
  Eigen::VectorXd coefficients, standard_errors;  // model.parameter_names() order, coefficients of tau^j
  std::vector<double> residuals;                  // per pose: |corrected| / |I| - 1
  double rms = 0;                                 // of the residuals
  double condition = 0;                           // of J^T J at the solution
  int iterations = 0;
  bool converged = false;
  std::string problem;  // "" for a fit that may be written; else what is wrong and what would work
};

// Throws std::invalid_argument for a base other than paper9.
ThermalFit fit_thermal(const std::vector<ThermalPose>& poses, const ThermalModel& model, const TemperatureRange& range,
                       double magnitude);

}  // namespace scalcal
