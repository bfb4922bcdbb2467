// The four criteria on a dynamic information matrix (information_criteria.hpp), from its eigenvalues
// (symmetric solver: no pivoting choices that depend on the BLAS kernel).
#include "numeric/thermal/information_criteria.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace scalcal {

std::optional<double> information_criterion(CriterionKind c, const Eigen::MatrixXd& mbar) {
  if (c != CriterionKind::D && c != CriterionKind::A && c != CriterionKind::E && c != CriterionKind::S)
    return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mbar);
  const Eigen::VectorXd& l = eig.eigenvalues();
  if (!(l(0) > 1e-12 * l(l.size() - 1))) return std::numeric_limits<double>::infinity();
  if (c == CriterionKind::D) return std::exp(-l.array().log().sum());
  if (c == CriterionKind::A) return l.cwiseInverse().sum();
  if (c == CriterionKind::E) return 1 / l(0);
  const Eigen::MatrixXd k = eig.eigenvectors() * l.cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
  return k.diagonal().maxCoeff();
}

}  // namespace scalcal
