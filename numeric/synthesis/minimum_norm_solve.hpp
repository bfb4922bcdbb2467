// The minimum-norm least-squares solution of A x = b in double, by a complete orthogonal
// decomposition: compiled once (minimum_norm_solve.cpp) for every model's S refinement, where its
// instantiation cost some 2 s of compile time per model.
#pragma once
#include <Eigen/Core>

namespace scalcal {

// threshold: the relative pivot below which a column counts as dependent; negative for Eigen's default.
Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double threshold = -1);

}  // namespace scalcal
