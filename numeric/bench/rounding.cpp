// Rounding bench settings (rounding.hpp).
#include "numeric/bench/rounding.hpp"

#include <cmath>
#include <limits>

namespace scalcal {

std::optional<BenchSetting> round_setting(const Bench& bench, const BenchSetting& setting, double resolution_deg,
                                          const Region& region) {
  if (resolution_deg <= 0) return setting;
  const auto& axes = bench.axes();
  const std::size_t n = axes.size();
  const Vec3 designed = bench.position(setting);
  // Per axis the grid values within two steps of the angle and within the limits.
  std::vector<std::vector<double>> values(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double nearest = std::round(setting.angles[k] / resolution_deg);
    for (int step = -2; step <= 2; ++step) {
      const double v = (nearest + step) * resolution_deg;
      if (axes[k].continuous || (v >= axes[k].lo - 1e-12 && v <= axes[k].hi + 1e-12)) values[k].push_back(v);
    }
    if (values[k].empty()) return std::nullopt;
  }
  std::optional<BenchSetting> best;
  double best_angle = std::numeric_limits<double>::infinity(), best_move = best_angle;
  std::vector<std::size_t> at(n, 0);
  for (;;) {
    BenchSetting s{setting.mounting, std::vector<double>(n)};
    double move = 0;
    for (std::size_t k = 0; k < n; ++k) {
      s.angles[k] = values[k][at[k]];
      move += axis_travel(axes[k], setting.angles[k], s.angles[k]);
    }
    const Vec3 x = bench.position(s);
    if (region.contains(x, kRoundedInsideDeg)) {
      const double angle = std::atan2(designed.cross(x).norm(), designed.dot(x));
      // The nearest position first; among equal ones (a free azimuth at a pole) the least move.
      if (angle < best_angle - 1e-13 || (angle < best_angle + 1e-13 && move < best_move)) {
        best_angle = angle;
        best_move = move;
        best = s;
      }
    }
    std::size_t k = 0;
    while (k < n && ++at[k] == values[k].size()) at[k++] = 0;
    if (k == n) break;
  }
  return best;
}

}  // namespace scalcal
