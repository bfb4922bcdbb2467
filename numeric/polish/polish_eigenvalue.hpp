// Internal to the polish (not part of its interface): the MPFR Newton machinery that polish.cpp
// (D, A, S) and polish_e.cpp (E) share, and the E entry point that polish() hands E to.
#pragma once
#include <functional>

#include <boost/multiprecision/mpfr.hpp>
#include <Eigen/Core>

#include "numeric/polish/polish.hpp"

namespace scalcal::polish_detail {

using Real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
using VecX = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

class PrecisionGuard {
 public:
  explicit PrecisionGuard(unsigned digits) : saved_(Real::default_precision()) { Real::default_precision(digits); }
  ~PrecisionGuard() { Real::default_precision(saved_); }
  PrecisionGuard(const PrecisionGuard&) = delete;
  PrecisionGuard& operator=(const PrecisionGuard&) = delete;

 private:
  unsigned saved_;
};

// Newton on residual(z) = 0 from z (updated in place) until the 2-norm is at most 10^-(P+10) or
// max_iterations Jacobians have been formed; the Jacobian by central differences with step
// 10^-(P+15). Steps are minimum-norm least-squares solutions (rank cut at 1e-25), or, when
// `regularised`, Levenberg-Marquardt steps (J^T J + |F|^2 I) s = -J^T F: where the solutions form a
// manifold, the Jacobian near it has singular values of the order of the distance to it, which a
// fixed rank cut keeps and divides by; the |F|^2 shift keeps those steps small and is still
// quadratically convergent under a local error bound (Yamashita & Fukushima 2001). A regularised run
// also stops when a step fails to halve |F|: from a double optimum Newton gains far more per step,
// so slower progress means the conditions do not fit. Returns the final norm; `iterations` counts
// Jacobians.
Real newton_least_squares(const std::function<VecX(const VecX&)>& residual, VecX& z, int P, int max_iterations,
                          int& iterations, bool regularised = false);

// The residual at which all P digits are claimed: 10^-(P+10).
Real converged_residual(int P);

// A residual r moves the value by O(r) at most: the digits it leaves untouched, at most P.
int digits_left_by(const Real& residual, int P);

// polish() for E (polish_e.cpp); runs under polish()'s precision guard of W = 2P + 30 digits.
PolishResult polish_eigenvalue(const Program& program, const PolishOptions& options);

}  // namespace scalcal::polish_detail
