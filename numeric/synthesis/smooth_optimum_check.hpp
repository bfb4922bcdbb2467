// The confirmation of the best Newton or L-BFGS program of a smooth criterion, in double and in O(N):
// its Riemannian gradient below the solvers' tolerance (first order), and its Riemannian Hessian
// positive semidefinite to a margin (second order): H + delta I positive definite, decided by the
// inertia of the structured Hessian (structured_hessian.hpp), delta = 1e-6 of the Hessian's mean
// diagonal or twice the gradient's norm, whichever is larger: a point a gradient g away from a manifold
// of optima (D at N = 1000: hundreds of flat directions) shows curvature of the order of |g| there
// (-3e-9 at |g| = 1.5e-8). Zero curvature along a symmetry (D's rotations) or a family of optima
// passes; a saddle with curvature below -delta does not. Ipopt's confirmation, which this replaces, was first-order
// only and factorised a dense 4N x 4N system (N = 1000: 17 s and 400 MB).
#pragma once
#include <algorithm>
#include <cmath>

#include "numeric/program/program.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/structured_hessian.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

struct SmoothOptimumCheck {
  bool first_order = false;
  bool second_order = false;
  double gradient_norm = 0;  // Riemannian, relative to max(1, |objective|)
  double margin = 0;         // delta, relative to the Hessian's mean diagonal (its scale)

  bool passed() const { return first_order && second_order; }
};

// The gradient tolerance a converged Newton or L-BFGS start meets (SphereNewtonOptions: 1e-9,
// and 100 times that where the value stalled at rounding).
inline constexpr double kConfirmGradient = 1e-7;
inline constexpr double kConfirmMargin = 1e-6;

template <class Model>
SmoothOptimumCheck check_smooth_optimum(const CriterionOps<Model>& criterion, const Program& program) {
  SmoothOptimumCheck out;
  std::vector<Vec3> eta = program.positions;
  for (auto& e : eta) e.normalize();
  MatrixDerivatives<double, Model::kParameters> d;
  if (!criterion.smooth.derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d)) return out;
  StructuredHessian<Model> H;
  H.assemble(eta, d);
  const double gradient = H.gradient().norm();
  out.gradient_norm = gradient / std::max(1.0, std::abs(d.value));
  out.first_order = out.gradient_norm <= kConfirmGradient;
  const double scale = std::max(H.mean_diagonal(), 1e-300);
  out.margin = std::max(kConfirmMargin, 2 * gradient / scale);
  // A margin at which a block or the Schur complement is singular to rounding is moved a little.
  for (int attempt = 0; attempt < 4; ++attempt, out.margin *= 1.7)
    if (H.factor(out.margin * scale)) {
      out.second_order = H.inertia().negative == 0;
      break;
    }
  return out;
}

#define SCALCAL_OPTIMUM_CHECK_INSTANCES(prefix, M) \
  prefix template SmoothOptimumCheck check_smooth_optimum<M>(const CriterionOps<M>&, const Program&);
#define SCALCAL_EXTERN_OPTIMUM_CHECK(M) SCALCAL_OPTIMUM_CHECK_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_OPTIMUM_CHECK)
#undef SCALCAL_EXTERN_OPTIMUM_CHECK

}  // namespace scalcal
