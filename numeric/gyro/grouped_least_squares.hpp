// Weighted nonlinear least squares whose residuals fall in groups of different kinds (rotations
// between poses and the rests' mean outputs; a rate table's segments and its rests): each residual
// comes divided by its predicted noise, and each group's variance is then rescaled by its own
// chi-square per degree of freedom (variance components, never below the prediction), refitting
// until the scales settle. Levenberg-Marquardt with Marquardt's diagonal scaling. The covariance is
// the achieved one (with the scales), the predicted one beside it (without).
#pragma once
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "numeric/program/summary.hpp"

namespace scalcal::gyro {

struct GroupedProblem {
  int parameters = 0;
  std::vector<int> row_group;  // each residual's group, 0..groups-1
  int groups = 1;
  // Residuals divided by their predicted noise (row order of row_group) and, when J is given, their
  // Jacobian (rows x parameters).
  std::function<void(const Eigen::VectorXd& p, Eigen::VectorXd& r, Eigen::MatrixXd* J)> evaluate;
};

struct GroupedFit {
  Eigen::VectorXd p;
  Eigen::MatrixXd covariance;  // achieved
  Eigen::VectorXd standard_error, predicted_std;
  std::vector<double> scale;       // per group: achieved / predicted variance, >= 1
  std::vector<double> chi_square;  // per group, against the predicted noise
  std::vector<double> dof;         // per group: rows less its share of the hat matrix's trace
  double rank_condition = 0;       // the scaled normal matrix's condition number
  int iterations = 0;
  Summary summary;
};

GroupedFit fit_grouped(const GroupedProblem& problem, const Eigen::VectorXd& start, int max_iterations = 100);

}  // namespace scalcal::gyro
