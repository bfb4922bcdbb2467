// The D limit on one zone (a cap or a band about an axis), solved as the one-dimensional problem it
// is: D is invariant under every rotation and log det is concave, so an optimal measure is uniform
// in azimuth about the zone's axis and is a distribution of the height z = axis . x. Its
// information matrix splits into a 3x3 Hankel block in (1, z, z^2), two 2x2 blocks (1, z) weighted
// by 1 - z^2 and two 1x1 blocks (1 - z^2)^2; the sensitivity is a quartic in z, so the optimal
// measure sits on the zone's two rims and one inner circle (proofs/cap_d_limit.md), or attains the
// sphere's limit when the zone carries the moments of a 4-design. The lower bound is proven:
// weak duality with the sup of the quartic over the zone enclosed in interval arithmetic.
#pragma once
#include <optional>
#include <vector>

#include "numeric/region/zone.hpp"

namespace scalcal {

struct ZonalMeasure {
  std::vector<double> heights;  // z = axis . x of each support circle (z = +-1: a pole, one position)
  std::vector<double> weights;  // summing to 1
  double value = 0;             // D = 1 / det M of the measure
  double lower_bound = 0;       // proven: no measure on the zone has a smaller D
  double equivalence_gap = 0;   // sup of the sensitivity over the zone / 9 - 1 (proven upper bound)
  bool sphere_limit = false;    // the zone carries a 4-design's moments: D = 61509375/4 exactly
};

// The D-optimal rotation-invariant measure on the zone and its certificate. The sphere itself
// (0..180 degrees) is the sphere's limit.
ZonalMeasure zonal_d_limit(const Zone& zone);

// The measure's positions: each circle as 5 equally spaced positions (they reproduce the circle's
// moments up to degree 4, all the information matrix sees), a pole as one; weights split evenly.
void zonal_positions(const Zone& zone, const ZonalMeasure& measure, std::vector<Vec3>& positions,
                     std::vector<double>& weights);

// D = 1 / det M of a rotation-invariant measure on heights z_i with weights w_i (summing to 1).
double zonal_d_value(const std::vector<double>& heights, const std::vector<double>& weights);

}  // namespace scalcal
