// A bench set to its resolution: every angle a multiple of the resolution, the position it then
// measures inside the region. Rounding each angle to the nearest multiple can leave the region (a
// position on a cap's rim rounds outside half the time), so the grid settings within two steps of
// each angle are tried and the one measuring the position nearest the designed one, inside the
// region and within the bench's limits, is kept.
#pragma once
#include <optional>

#include "numeric/bench/registry.hpp"
#include "numeric/region/region.hpp"

namespace scalcal {

// A rounded position counts as inside the region within this angle (rounding error of the
// kinematics, about 1e-14 degrees, not the designed tolerance of evaluate --tolerance).
inline constexpr double kRoundedInsideDeg = 1e-9;

// `setting` with no free axis. nullopt when no grid setting within two steps qualifies;
// resolution_deg 0 returns the setting unchanged.
std::optional<BenchSetting> round_setting(const Bench& bench, const BenchSetting& setting, double resolution_deg,
                                          const Region& region);

}  // namespace scalcal
