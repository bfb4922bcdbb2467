// Optimal designs for polynomial regression of degree k on [-1, 1] (rows f(tau) = (1, tau, ..., tau^k)):
// the temperature factor of a thermal model's optimal program (product_limits.hpp). D has a closed form
// for every k: equal weights on the roots of (1 - tau^2) P_k'(tau), P_k Legendre's polynomial (Hoel
// 1958, Guest 1958). A, E and S have closed forms for k = 1, 2, E and S for k = 3 on T_3's extrema
// (proofs/thermal_product.md, checked by proofs/checks/thermal_product.cpp); the others are found numerically among
// symmetric designs on k + 1 points including the ends (de la Garza's class, which holds an optimum of every criterion
// that prefers larger information), with a lower bound from the criterion's convexity.
#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "numeric/criteria/registry.hpp"

namespace scalcal {

struct IntervalDesign {
  int degree = 1;
  std::vector<double> points;   // tau, increasing, in [-1, 1]
  std::vector<double> weights;  // summing to 1
  double value = 0;             // the criterion of its normalised information matrix
  double lower_bound = 0;       // no design of degree k does better (equals value for a closed form)
  bool closed_form = false;     // proven optimal (the theorem in proofs/thermal_product.md)
};

// The normalised information matrix sum_i w_i f(t_i) f(t_i)^T of degree k.
Eigen::MatrixXd interval_information(int degree, const std::vector<double>& points, const std::vector<double>& weights);

// The optimal design for criterion c; nullopt for a criterion without a form (information_criteria.hpp).
std::optional<IntervalDesign> optimal_interval_design(CriterionKind c, int degree);

}  // namespace scalcal
