// A proven upper bound on sup |C h(x)|^2 over a zone or a finite set of directions, the quantity
// every dual certificate of numeric/region/dual_certificate.hpp needs. Branch and bound over the
// zone's own coordinates in interval arithmetic (outward rounding), so the bound holds for every
// direction of the zone, not only for sampled ones. Each box is bounded by a second-order Taylor
// form (the function, gradient and Hessian enclosed by interval jets), whose error is third order
// in the box size: the sensitivity function of an optimal measure peaks along whole circles, where
// a first-order form would need boxes far too small to count.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "numeric/region/zone.hpp"

namespace scalcal {

struct SupBound {
  double upper = 0;  // proven: |C h(x)|^2 <= upper on the whole zone (or set)
  double lower = 0;  // attained at argmax, so lower <= the true supremum
  Vec3 argmax{0, 0, 1};
  long boxes = 0;
};

// rel_tol: stop once upper - lower <= rel_tol * upper; box_budget bounds the work (the bound stays
// proven, only looser).
SupBound sup_norm2_over_zone(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const Zone& zone, double rel_tol = 1e-9,
                             long box_budget = 400000);
SupBound sup_norm2_over_points(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const std::vector<Vec3>& points);

}  // namespace scalcal
