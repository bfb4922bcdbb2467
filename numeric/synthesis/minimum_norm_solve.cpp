// The rank-revealing least-squares solve of the S refinement's KKT system (minimum_norm_solve.hpp).
#include "numeric/synthesis/minimum_norm_solve.hpp"

#include <Eigen/QR>

namespace scalcal {

Eigen::VectorXd minimum_norm_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double threshold) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod;
  if (threshold >= 0) cod.setThreshold(threshold);
  cod.compute(A);
  return cod.solve(b);
}

}  // namespace scalcal
