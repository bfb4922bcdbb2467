// Optimal weights of a criterion on a small finite candidate set (its Hessian is dense in the
// weights), to Ipopt's tolerance: a smooth criterion directly (the multiplicative algorithm crawls
// once candidates crowd along a circle), the max-eigenvalue form as max s s.t. M(w) - s I = L L^T, the
// max-diagonal form as min t s.t. K(r,r)(w) <= t, with w >= 0 summing to 1. For the nonsmooth
// forms this removes the O(1/p) bias of the power-mean smoothing (optimal_measure.hpp) and returns
// the dual of the optimum (the eigenvalue form's Z, the diagonal form's row weights), which the
// region's certificate needs.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "numeric/criteria/criterion.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal {

struct ExactWeights {
  std::vector<double> weights;      // one per candidate, summing to 1
  Mat9 dual;                        // eigenvalue form: Z >= 0 with trace 1 (zero otherwise)
  std::vector<double> row_weights;  // diagonal form: one per row of the criterion, summing to 1
  Summary summary;                  // converged: Ipopt solved the weights problem
  bool converged() const { return summary.converged(); }
};

enum class WeightForm { Smooth, Eigenvalue, Diagonal };

// A smooth criterion's phi(M) and its derivatives d phi = tr(G dM), dG = c (A dM B + B dM A);
// false where M is not positive definite.
using SmoothObjective = std::function<bool(const Mat9& M, MatrixDerivatives<double, 9>& d)>;

// The solve itself (measure_weights.cpp), for a form: `rows` of a diagonal form, `objective` of a
// smooth one. start: weights to begin from (the multiplicative algorithm's). Empty when Ipopt fails.
std::optional<ExactWeights> exact_weights(WeightForm form, const std::vector<Vec3>& candidates,
                                          const std::vector<double>& start, const std::vector<int>& rows,
                                          const SmoothObjective& objective);

// The same for a criterion type, registered or not.
template <Criterion Crit>
std::optional<ExactWeights> exact_weights(const std::vector<Vec3>& candidates, const std::vector<double>& start) {
  if constexpr (SmoothCriterion<Crit>) {
    return exact_weights(WeightForm::Smooth, candidates, start, {},
                         [](const Mat9& M, MatrixDerivatives<double, 9>& d) { return Crit::derivatives(M, 1, d); });
  } else if constexpr (MaxEigenvalueCriterion<Crit>) {
    return exact_weights(WeightForm::Eigenvalue, candidates, start, {}, {});
  } else {
    static_assert(MaxDiagonalCriterion<Crit>, "exact_weights: a criterion of an unknown form");
    return exact_weights(WeightForm::Diagonal, candidates, start, Crit::template rows<Paper9Model>(), {});
  }
}

}  // namespace scalcal
