// Thermal programs by Theorem 25's product (thermal_optimize.hpp).
#include "commands/design/thermal_optimize.hpp"

#include <cmath>
#include <string>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/thermal/information_criteria.hpp"

namespace scalcal::commands {
namespace {

struct Split {
  int repeats = 0;
  std::vector<int> counts;
  double efficiency = 0;  // the rounded set-points' criterion against the optimal weights'
};

// The best n dividing N (n >= the set-points, N / n >= the base's parameters) by the rounding's efficiency.
std::optional<Split> best_split(int N, int base_parameters, CriterionKind c, const IntervalDesign& d) {
  std::optional<Split> best;
  const int points = static_cast<int>(d.points.size());
  for (int n = points; n * base_parameters <= N; ++n) {
    if (N % n != 0) continue;
    Split s{n, efficient_rounding(d.weights, n), 0};
    std::vector<double> w;
    for (int count : s.counts) w.push_back(static_cast<double>(count) / n);
    const auto value = information_criterion(c, interval_information(d.degree, d.points, w));
    s.efficiency = value && std::isfinite(*value) ? d.value / *value : 0;
    if (!best || s.efficiency > best->efficiency * (1 + 1e-12)) best = s;
  }
  return best;
}

std::string nearest_splits(int N, int base_parameters, int points) {
  std::string out;
  for (int delta = 1; delta < N && out.size() < 40; ++delta)
    for (int m : {N - delta, N + delta})
      for (int n = points; n * base_parameters <= m; ++n)
        if (m % n == 0 && out.find(std::to_string(m) + " (") == std::string::npos) {
          out += (out.empty() ? "" : ", ") + std::to_string(m) + " (" + std::to_string(m / n) + " x " +
                 std::to_string(n) + ")";
          break;
        }
  return out;
}

}  // namespace

ThermalOptimizeResult thermal_optimize(const OptimizeRequest& q, const ThermalModel& model,
                                       const TemperatureRange& range, const Progress& progress) {
  if (!q.regions.empty() && !model_supports(model.base, ModelCapability::region_limits))
    throw region_limits_refusal("optimize", model.name());
  if (!q.from.empty() || q.start)
    throw UsageError(words("optimize: {from} does not apply to a thermal model (the program is a product)"));
  ThermalOptimizeResult r;
  r.criterion = q.synthesis.criterion;
  r.positions = q.synthesis.positions;
  const auto design = optimal_interval_design(r.criterion, model.degree);
  if (!design)
    throw UsageError("optimize: criterion " + std::string(criterion_name(r.criterion)) + " has no thermal form");
  r.design = *design;
  const int P = model.base_parameters(), points = static_cast<int>(design->points.size());
  const auto split = best_split(r.positions, P, r.criterion, *design);
  if (!split)
    throw UsageError(words("optimize: {positions} ") + std::to_string(r.positions) +
                     " is no product of a sphere program (" + std::to_string(P) + " positions at least) and " +
                     std::to_string(points) +
                     " set-points or more; nearest that are: " + nearest_splits(r.positions, P, points));
  r.counts = split->counts;
  r.sphere_positions = r.positions / split->repeats;
  OptimizeRequest sphere = q;
  sphere.synthesis.model = model.base;
  sphere.synthesis.positions = r.sphere_positions;
  r.sphere = optimize(sphere, progress);
  r.warnings = r.sphere.warnings;
  std::vector<Eigen::Vector3d> positions;
  for (const auto& e : r.sphere.program.positions) positions.emplace_back(e);
  const ThermalProgram p = product_program(positions, *design, r.counts, range);
  std::optional<Region> region;
  Warnings said;  // the sphere program's optimize said them already
  if (!q.regions.empty()) region = resolve_region(q.regions, said);
  r.evaluation = evaluate_thermal("the product program", p, model, range, region, progress);
  for (const auto& w : r.evaluation.warnings) r.warnings.push_back(w);
  return r;
}

Json to_json(const ThermalOptimizeResult& r) {
  Json j = to_json(r.evaluation);
  j["criterion"] = std::string(criterion_name(r.criterion));
  j["positions"] = r.positions;
  j["sphere_positions"] = r.sphere_positions;
  j["counts"] = r.counts;
  j["sphere"] = to_json(r.sphere);
  Json program = Json::array();
  for (int i = 0; i < r.evaluation.program.size(); ++i) {
    const auto& e = r.evaluation.program.positions[static_cast<std::size_t>(i)];
    program.push_back(Json{e(0), e(1), e(2), r.evaluation.program.celsius[static_cast<std::size_t>(i)]});
  }
  j["program"] = program;  // rows x, y, z, t_c
  return j;
}

}  // namespace scalcal::commands
