// A proven upper bound on sup |C h(x)|^2 over a zone or a finite set of directions, the quantity
// every dual certificate of numeric/region/dual_certificate.hpp needs. Branch and bound over the
// zone's own coordinates in interval arithmetic (outward rounding), so the bound holds for every
// direction of the zone, not only for sampled ones.
#pragma once
#include <vector>

#include <Eigen/Core>

#include "numeric/region/zone.hpp"

namespace scalcal {

struct SupBound {
  double upper = 0;              // proven: |C h(x)|^2 <= upper on the whole zone (or set)
  double lower = 0;              // attained at argmax, so lower <= the true supremum
  Vec3 argmax{0, 0, 1};
  std::vector<Vec3> near_maxima;  // distinct directions where the value is near the largest, best first
  long boxes = 0;
};

// rel_tol: stop once upper - lower <= rel_tol * upper; box_budget bounds the work (the bound stays
// proven, only looser).
SupBound sup_norm2_over_zone(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const Zone& zone,
                             double rel_tol = 1e-7, long box_budget = 20000);
SupBound sup_norm2_over_points(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const std::vector<Vec3>& points);

}  // namespace scalcal
