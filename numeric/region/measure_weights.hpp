// Optimal weights of a criterion on a small finite candidate set (its Hessian is dense in the
// weights), to Ipopt's tolerance: a smooth criterion directly (the multiplicative algorithm crawls
// once candidates crowd along a circle), the max-eigenvalue form as max s s.t. M(w) - s I = L L^T, the
// max-diagonal form as min t s.t. K(r,r)(w) <= t, with w >= 0 summing to 1. For the nonsmooth
// forms this removes the O(1/p) bias of the power-mean smoothing (optimal_measure.hpp) and returns
// the dual of the optimum (the eigenvalue form's Z, the diagonal form's row weights), which the
// region's certificate needs.
#pragma once
#include <optional>
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

struct ExactWeights {
  std::vector<double> weights;  // one per candidate, summing to 1
  Mat9 dual;                    // eigenvalue form: Z >= 0 with trace 1 (zero otherwise)
  std::vector<double> row_weights;  // diagonal form: one per row of the criterion, summing to 1
  bool converged = false;
};

// start: weights to begin from (the multiplicative algorithm's). Empty when Ipopt fails.
std::optional<ExactWeights> exact_weights(CriterionKind criterion, const std::vector<Vec3>& candidates,
                                          const std::vector<double>& start);

}  // namespace scalcal
