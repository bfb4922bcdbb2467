// Newton's method on first-order conditions in MPFR, for every form of the polish (newton_least_squares.hpp).
#include "numeric/polish/newton_least_squares.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "numeric/io/interrupt.hpp"

namespace scalcal::polish_detail {

Real newton_least_squares(const std::function<VecX(const VecX&)>& residual, VecX& z, int P, int max_iterations,
                          int& iterations, bool regularised) {
  const Real h = pow(Real(10), -(P + 15));
  const Real target = converged_residual(P);
  VecX F = residual(z);
  Real norm = F.norm();
  for (int it = 0; it < max_iterations && norm > target; ++it) {
    MatX J(F.size(), z.size());
    for (int j = 0; j < z.size(); ++j) {
      check_interrupt();  // a column costs two residuals: the finest unit of the polish's work
      VecX zp = z, zm = z;
      zp(j) += h;
      zm(j) -= h;
      J.col(j) = (residual(zp) - residual(zm)) / (Real(2) * h);
    }
    VecX step;
    if (regularised) {
      MatX A = MatX::Zero(J.cols(), J.cols());
      A.selfadjointView<Eigen::Lower>().rankUpdate(J.transpose());
      A.diagonal().array() += norm * norm;
      step = A.selfadjointView<Eigen::Lower>().llt().solve(-(J.transpose() * F));
    } else {
      Eigen::CompleteOrthogonalDecomposition<MatX> cod(J);
      cod.setThreshold(Real(1e-25));
      step = cod.solve(-F);
    }
    // Damping only as a safeguard: from a double optimum the full step is taken every time.
    Real lambda(1);
    VecX trial = z + step;
    VecX Ft = residual(trial);
    for (int k = 0; k < 8 && !(Ft.norm() < norm); ++k) {
      lambda /= 2;
      trial = z + lambda * step;
      Ft = residual(trial);
    }
    ++iterations;
    if (!(Ft.norm() < norm)) break;
    const bool stalled = regularised && !(Ft.norm() < norm / 2);
    z = trial;
    F = Ft;
    norm = F.norm();
    if (stalled) break;
  }
  return norm;
}

Real converged_residual(int P) { return pow(Real(10), -(P + 10)); }

int digits_left_by(const Real& residual, int P) {
  const double lost = residual > 0 ? -static_cast<double>(log10(residual)) - 2 : P;
  return std::max(1, std::min(P, static_cast<int>(std::floor(lost))));
}

}  // namespace scalcal::polish_detail
