// The best N-position program a restricted bench can do (optimize --region): each start is an
// exchange on a fine candidate grid of the region (greedy for start 0, random candidates for the
// others), then a continuous polish by Ipopt with every position held in its zone (positions on
// finite candidates stay put). A plain multistart from random points stalls on such regions; the
// exchange finds the few circles or candidates optimal programs live on.
#pragma once
#include "numeric/region/region.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/position_bounds.hpp"

namespace scalcal {

// Default number of starts on a region (the greedy one and random ones).
inline constexpr int kRegionStarts = 8;
// Candidates of the exchange's grid (Region::grid_step_for).
inline constexpr int kRegionGridCandidates = 2500;

// Ipopt's options for a polish with positions held in zones: a smooth criterion's run stops once its
// objective has settled (LocalOptions::settle_tolerance; at cap:20, N = 9..17, 3-8x fewer iterations
// and the same D to 3e-12). Not for the epigraph forms (E, S): their objective, the bound t, can rest
// while the program still moves toward a better optimum (E at N = 9 on the sphere, settled to 1e-12:
// 12.3957 instead of 12.1872).
inline LocalOptions zone_polish_options(bool smooth_criterion) {
  LocalOptions o;
  if (smooth_criterion) o.settle_tolerance = 1e-9;
  return o;
}

// options.starts 0: kRegionStarts. options.local is ignored (Ipopt polishes every start).
// Throws std::invalid_argument when positions < 9.
SynthesisResult synthesize_on_region(const SynthesisOptions& options, const Region& region);

// How each position may move in a local optimisation on the region: within the zone it lies in
// most deeply, or fixed when it lies in no zone (a finite candidate).
PositionBounds position_bounds(const Region& region, const std::vector<Vec3>& positions);

// x moved onto its zone when a solver left it outside by rounding (tilt clamped to the zone).
Vec3 clamp_to_zone(const Zone& zone, const Vec3& x);

}  // namespace scalcal
