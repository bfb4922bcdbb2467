// The error model of a still-pose calibration: a position's mean modulus residual J_k has variance
// sigma_b^2 + sigma_w^2 / n_k: the noise within the pose over its n_k samples, and a between-pose
// component sigma_b that no amount of averaging removes (a hand-held pose is never quite the same
// pose twice: tilt while settling, the sensor's slow drift, model errors of the linear model). Real
// logs have it (every public log's chi-square of the residuals against the noise alone was 1e-11 to
// 1e-42), so standard errors from the noise alone are too small and the residual-based ones ignore
// which poses were long. sigma_b^2 is estimated by restricted maximum likelihood (REML: Patterson and
// Thompson 1971, by Fisher scoring), and the estimator's covariance follows by the sandwich with the
// weights the estimator used.
#pragma once
#include <vector>

#include <Eigen/Core>

namespace scalcal {

struct BetweenPoses {
  double within = 0;   // sigma_w^2: one sample's variance (the estimator's units)
  double between = 0;  // sigma_b^2, REML, >= 0
  int iterations = 0;
  bool converged = false;
  Eigen::MatrixXd covariance;        // of the estimator's parameters under this error model (sandwich)
  std::vector<double> standardised;  // each residual over its standard deviation under the model
};

// rows: the model's rows at the positions; residual: J_k; samples: n_k; weights: the estimator's
// (1 per position, or n_k); within: sigma_w^2 from the scatter within positions. Needs more
// positions than parameters.
BetweenPoses between_poses(const std::vector<Eigen::VectorXd>& rows, const std::vector<double>& residual,
                           const std::vector<double>& samples, const std::vector<double>& weights, double within);

}  // namespace scalcal
