// The singular values and right singular vectors of a design matrix H in double, for any model:
// compiled once (design_svd.cpp) instead of once per model's fixed column count, which cost some
// 7 s of compile time in every model's evaluation unit.
#pragma once
#include <Eigen/Core>

namespace scalcal {

// sigma: min(rows, cols) singular values, descending; V: the cols x cols right singular vectors.
void design_svd(const Eigen::MatrixXd& H, Eigen::VectorXd& sigma, Eigen::MatrixXd& V);

}  // namespace scalcal
