// Random positions on a restricted bench, for `random --region`: uniform by area on the union of
// the region's zones (a zone drawn in proportion to its area, a point uniform on it by Archimedes'
// z uniform in the zone's heights, kept with probability 1 / (zones holding it) so that overlaps
// are not counted twice); uniform among the candidates of a region of candidates only; and, when a
// region has both, each position a candidate with probability 1/2.
#pragma once
#include "numeric/region/region.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal {

// The sampler random_search takes; the region is copied into it.
PositionSampler region_sampler(const Region& region);

}  // namespace scalcal
