// The joint polish of augment's added positions (augment_polish.hpp).
#include "numeric/region/augment_polish.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>

#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/seeds.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

// K candidates drawn with replacement from the generator of (seed, k).
std::vector<Vec3> random_added(const std::vector<Vec3>& candidates, int count, std::uint64_t seed, int k) {
  std::mt19937_64 engine(start_seed(seed, static_cast<std::uint64_t>(k)));
  std::vector<Vec3> out;
  for (int i = 0; i < count; ++i) out.push_back(candidates[static_cast<std::size_t>(engine() % candidates.size())]);
  return out;
}

// One start: its exchange result, then the local optimisation with the given positions fixed and
// the added ones in their zones; the better of the two.
LocalResult one_start(const Region& region, const std::vector<Vec3>& given, const std::vector<Vec3>& start,
                      const std::function<double(const Program&)>& value_of, const LocalOptimiser& local) {
  LocalResult out;
  out.program.positions = start;
  out.value = value_of(out.program);
  if (region.zones.empty() || !std::isfinite(out.value)) return out;
  PositionBounds bounds = position_bounds(region, start);
  for (std::size_t i = 0; i < given.size(); ++i) bounds[i].kind = PositionBound::Kind::Fixed;
  LocalResult polished = local(out.program, bounds);
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    Vec3& x = polished.program.positions[i];
    if (bounds[i].kind == PositionBound::Kind::Fixed) x = start[i];  // bit for bit
    if (bounds[i].kind == PositionBound::Kind::Zone)
      x = clamp_to_zone(region.zones[static_cast<std::size_t>(region.deepest_zone(start[i]))], x);
  }
  polished.value = value_of(polished.program);
  return polished.value < out.value ? polished : out;
}

}  // namespace

PolishedAddition polish_added(CriterionKind criterion, ModelKind model, const Region& region,
                              const std::vector<Vec3>& given, const ExchangeResult& greedy,
                              const std::vector<Vec3>& candidates, const AugmentPolishOptions& options,
                              const std::function<double(const Program&)>& value_of, const LocalOptimiser& local) {
  const int count = static_cast<int>(greedy.positions.size() - given.size());
  const int starts = std::max(1, options.starts);
  const int workers =
      options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<LocalResult> results =
      run_in_workers(starts, workers, static_cast<int>(greedy.positions.size()), [&](int k) {
        std::vector<Vec3> start = greedy.positions;
        if (k > 0) {
          start = given;
          const auto added = random_added(candidates, count, options.seed, k);
          start.insert(start.end(), added.begin(), added.end());
          start = exchange(criterion, candidates, start, static_cast<int>(given.size()), 100, model).positions;
        }
        return one_start(region, given, start, value_of, local);
      });
  PolishedAddition out;
  out.starts = starts;
  out.value = INFINITY;
  for (int k = 0; k < starts; ++k) {
    const LocalResult& r = results[static_cast<std::size_t>(k)];
    // Recomputed here: the value crossed a pipe, the program is what counts.
    const double v = value_of(r.program);
    if (k == 0) out.value_greedy = v;
    if (v < out.value) {
      out.value = v;
      out.best_start = k;
      out.added.assign(r.program.positions.begin() + static_cast<std::ptrdiff_t>(given.size()),
                       r.program.positions.end());
    }
  }
  return out;
}

}  // namespace scalcal
