// The best N-position program a restricted bench can do (region_synthesis.hpp).
#include "numeric/region/region_synthesis.hpp"

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "numeric/program/program_equivalence.hpp"
#include "numeric/synthesis/exchange.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/seeds.hpp"
#include "numeric/synthesis/synthesize.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// N candidates drawn with replacement, from the generator of (seed, k).
std::vector<Vec3> random_candidates(const std::vector<Vec3>& candidates, int n, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(candidates[static_cast<std::size_t>(engine() % candidates.size())]);
  return out;
}

template <Criterion C>
LocalResult region_start(const Region& region, const std::vector<Vec3>& candidates, int n, std::uint64_t seed, int k) {
  const CriterionKind kind = CriterionKind::of<C>();
  const ExchangeResult ex =
      k == 0 ? greedy_exchange(kind, candidates, {}, n)
             : exchange(kind, candidates,
                        random_candidates(candidates, n, start_seed(seed, static_cast<std::uint64_t>(k))));
  LocalResult out;
  out.program.positions = ex.positions;
  out.value = criterion_value<C>(out.program);
  out.summary.termination = std::isfinite(out.value) ? Termination::converged : Termination::failed;
  out.summary.message = "exchange";
  if (region.zones.empty() || !std::isfinite(out.value)) return out;
  const PositionBounds bounds = position_bounds(region, ex.positions);
  LocalResult polished = optimize_with_ipopt<C>(out.program, zone_polish_options(SmoothCriterion<C>), &bounds);
  for (std::size_t i = 0; i < bounds.size(); ++i) {
    Vec3& x = polished.program.positions[i];
    if (bounds[i].kind == PositionBound::Kind::Fixed) x = ex.positions[i];
    if (bounds[i].kind == PositionBound::Kind::Zone)
      x = clamp_to_zone(region.zones[static_cast<std::size_t>(region.deepest_zone(ex.positions[i]))], x);
  }
  polished.value = criterion_value<C>(polished.program);
  if (polished.value < out.value) {
    polished.summary.iterations += ex.passes;
    return polished;
  }
  return out;
}

template <Criterion C>
SynthesisResult synthesize_region_with(const SynthesisOptions& options, const Region& region) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<Vec3> candidates = region.grid(region.grid_step_for(kRegionGridCandidates));
  const int starts = options.starts > 0 ? options.starts : kRegionStarts;
  const std::vector<LocalResult> results = run_in_workers(
      starts, thread_count(options.threads), options.positions,
      [&](int k) { return region_start<C>(region, candidates, options.positions, options.seed, k); }, options.progress);
  SynthesisResult out = best_of_starts(results);
  out.starts = starts;
  out.stopping = (options.starts > 0 ? "forced " : "cap ") + std::to_string(starts);
  out.local_solver = region.zones.empty() ? "exchange" : "exchange+ipopt";
  out.summary.message = out.summary.message == "exchange"
                            ? "the best start is an exchange optimum on the candidates"
                            : (out.summary.converged() ? "Ipopt converged from the best exchange program"
                                                       : "Ipopt did not converge from the best exchange program");
  count_hits(results, C::symmetry, out);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

PositionBounds position_bounds(const Region& region, const std::vector<Vec3>& positions) {
  PositionBounds out;
  for (const Vec3& x : positions) {
    PositionBound b;
    const int z = region.deepest_zone(x);
    if (z < 0) {
      b.kind = PositionBound::Kind::Fixed;
    } else {
      const Zone& zone = region.zones[static_cast<std::size_t>(z)];
      if (!zone.is_sphere()) {
        b.kind = PositionBound::Kind::Zone;
        b.axis = zone.axis;
        b.lower = std::cos(zone.max_tilt_deg * kDeg);
        b.upper = std::cos(zone.min_tilt_deg * kDeg);
      }
    }
    out.push_back(b);
  }
  return out;
}

Vec3 clamp_to_zone(const Zone& zone, const Vec3& x) {
  const double t = zone.tilt_deg(x);
  if (t >= zone.min_tilt_deg && t <= zone.max_tilt_deg) return x;
  const double target = std::clamp(t, zone.min_tilt_deg, zone.max_tilt_deg) * kDeg;
  Vec3 across = x - x.dot(zone.axis) * zone.axis;
  if (across.norm() < 1e-300) across = azimuth_frame(zone.axis).first;
  return std::cos(target) * zone.axis + std::sin(target) * across.normalized();
}

SynthesisResult synthesize_on_region(const SynthesisOptions& options, const Region& region) {
  if (options.positions < Paper9Model::kParameters)
    throw std::invalid_argument("synthesize_on_region: at least 9 positions are needed");
  return visit_criterion(options.criterion,
                         [&](auto C) { return synthesize_region_with<decltype(C)>(options, region); });
}

}  // namespace scalcal
