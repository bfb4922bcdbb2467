// One-sided Jacobi SVD of a design matrix (design_svd.hpp): the evaluation's rank, K and criteria
// come from it, never from H^T H, whose condition number is the square of H's.
#include "numeric/criteria/design_svd.hpp"

#include <Eigen/SVD>

namespace scalcal {

void design_svd(const Eigen::MatrixXd& H, Eigen::VectorXd& sigma, Eigen::MatrixXd& V) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(H, Eigen::ComputeFullV);
  sigma = svd.singularValues();
  V = svd.matrixV();
}

}  // namespace scalcal
