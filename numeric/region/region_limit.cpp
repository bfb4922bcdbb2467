#include "numeric/region/region_limit.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/dual_certificate.hpp"
#include "numeric/region/optimal_measure.hpp"
#include "numeric/region/zone_sup.hpp"

namespace scalcal {
namespace {

using Model = Paper9Model;
constexpr int P = Model::kParameters;

// A position the bound's search found counts as new when no candidate is within this angle.
constexpr double kNewPositionDeg = 1e-3;
constexpr double kSupportWeight = 1e-6;

template <class Crit>
double criterion_value(const Mat9& K) {
  const Vec9 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat9>(K, Eigen::EigenvaluesOnly).eigenvalues();
  const InverseInformation<double, P> view{K, eigenvalues};
  return Crit::template value<Model>(view, 1.0);
}

bool is_new(const Vec3& x, const std::vector<Vec3>& candidates) {
  const double cos_tol = std::cos(kNewPositionDeg * M_PI / 180.0);
  return std::none_of(candidates.begin(), candidates.end(), [&](const Vec3& c) { return c.dot(x) >= cos_tol; });
}

template <class Crit>
RegionLimit limit_of(const Region& region, const RegionLimitOptions& options) {
  std::vector<Vec3> candidates = region.grid(options.grid_step_deg);
  std::vector<double> weights;
  RegionLimit out;
  for (int round = 0;; ++round) {
    const auto measure = optimal_measure<Crit, Model>(candidates, weights);
    weights = measure.weights;
    out.value = criterion_value<Crit>(measure.K);
    out.equivalence_gap = measure.equivalence_gap;
    const auto certificate = dual_certificate<Crit, Model>(measure.K, measure.sharpness);
    if (!certificate) break;
    double upper = 0;
    std::vector<Vec3> found;
    if (!region.candidates.empty()) {
      const SupBound b = sup_norm2_over_points(certificate->C, region.candidates);
      upper = std::max(upper, b.upper);
    }
    for (const Zone& z : region.zones) {
      const SupBound b = sup_norm2_over_zone(certificate->C, z);
      upper = std::max(upper, b.upper);
      out.boxes += b.boxes;
      found.insert(found.end(), b.near_maxima.begin(), b.near_maxima.end());
    }
    out.lower_bound = certificate->lower_bound(upper);
    if (round >= options.max_refinements || out.value - *out.lower_bound <= options.relative_gap * out.value) break;
    int added = 0;
    for (const Vec3& x : found)
      if (is_new(x, candidates)) {
        candidates.push_back(x);
        weights.push_back(1e-3 / static_cast<double>(candidates.size()));
        ++added;
      }
    if (added == 0) break;
    ++out.refinements;
  }
  out.candidates = static_cast<int>(candidates.size());
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return weights[a] > weights[b]; });
  for (std::size_t i : order)
    if (weights[i] >= kSupportWeight) {
      out.support.push_back(candidates[i]);
      out.weights.push_back(weights[i]);
    }
  return out;
}

}  // namespace

RegionLimit region_limit(CriterionKind c, const Region& region, const RegionLimitOptions& options) {
  return visit_criterion(c, [&](auto C) { return limit_of<decltype(C)>(region, options); });
}

}  // namespace scalcal
