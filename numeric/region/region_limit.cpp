// A criterion's limit on a region with its certified lower bound (region_limit.hpp).
#include "numeric/region/region_limit.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/cap_limits.hpp"
#include "numeric/region/climb.hpp"
#include "numeric/region/dual_certificate.hpp"
#include "numeric/region/measure_weights.hpp"
#include "numeric/region/optimal_measure.hpp"
#include "numeric/region/zonal_d.hpp"
#include "numeric/region/zone_sup.hpp"

namespace scalcal {
namespace {

using Model = Paper9Model;
constexpr int P = Model::kParameters;

// A position the bound's search found counts as new when no candidate is within this angle.
constexpr double kNewPositionDeg = 1e-5;
constexpr double kSupportWeight = 1e-6;

template <class Crit>
double criterion_value(const Mat9& K) {  // of the measure whose M = K^-1 (weights summing to 1)
  const Vec9 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat9>(K, Eigen::EigenvaluesOnly).eigenvalues();
  const InverseInformation<double, P> view{K, eigenvalues};
  return Crit::template value<Model>(view, 1.0);
}

bool is_new(const Vec3& x, const std::vector<Vec3>& candidates) {
  const double cos_tol = std::cos(kNewPositionDeg * M_PI / 180.0);
  return std::none_of(candidates.begin(), candidates.end(), [&](const Vec3& c) { return c.dot(x) >= cos_tol; });
}

RegionLimit zonal_limit(const Zone& zone, const ZonalMeasure& m) {
  RegionLimit out;
  out.value = m.value;
  out.lower_bound = m.lower_bound;
  out.equivalence_gap = m.equivalence_gap;
  zonal_positions(zone, m, out.support, out.weights);
  out.candidates = static_cast<int>(out.support.size());
  Mat9 M = Mat9::Zero();
  for (std::size_t i = 0; i < out.support.size(); ++i) {
    const Vec9 h = Model::row(out.support[i]);
    M += out.weights[i] * h * h.transpose();
  }
  out.K = M.llt().solve(Mat9::Identity());
  return out;
}

// A theorem's closed form: its value is the limit (and so its own lower bound), its measure optimal.
// Each circle as 5 equally spaced positions reproduces the circle's moments to degree 4, which is
// all the information matrix holds, whatever the criterion.
RegionLimit closed_form_limit(const Zone& zone, const CapClosedForm& f) {
  ZonalMeasure m;
  m.heights = f.heights;
  m.weights = f.weights;
  m.value = f.value;
  m.lower_bound = f.value;
  RegionLimit out = zonal_limit(zone, m);
  out.theorem = f.theorem;
  return out;
}

// Candidates whose weight fell below a billionth of the largest are dropped between rounds (never
// by count: the heaviest few of a measure spread over a circle can be rank-deficient). Ipopt's
// exact weights, whose Hessian is dense in them, run only on at most kExactCandidates.
constexpr std::size_t kExactCandidates = 600;
// A rough measure within this of the sphere's limit: the region holds (nearly) the sphere's optimum.
constexpr double kNearSphereLimit = 1e-4;
// A final measure within this of it: the sphere's limit is the bound (gap at most this).
constexpr double kAtSphereLimit = 1e-10;
constexpr long kBoxBudget = 300000;
constexpr std::size_t kPeaksPerRound = 64;
constexpr int kExactRounds = 3;
constexpr int kExactStartIterations = 2000;
constexpr int kFinalIterations = 18000;

void keep_support(std::vector<Vec3>& candidates, std::vector<double>& weights) {
  const double top = *std::max_element(weights.begin(), weights.end());
  std::vector<Vec3> c;
  std::vector<double> w;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (weights[i] >= 1e-9 * top) {
      c.push_back(candidates[i]);
      w.push_back(weights[i]);
    }
  candidates = std::move(c);
  weights = std::move(w);
}

// Weights on the candidates by the multiplicative algorithm (smoothed for the nonsmooth forms).
template <class Crit>
Mat9 multiplicative_weights(const std::vector<Vec3>& candidates, std::vector<double>& weights, double& sharpness,
                            double& equivalence_gap, int iterations) {
  const auto measure = optimal_measure<Crit, Model>(candidates, weights, iterations, 1e-12);
  weights = measure.weights;
  sharpness = measure.sharpness;
  equivalence_gap = measure.equivalence_gap;
  return measure.K;
}

Mat9 information(const std::vector<Vec3>& candidates, const std::vector<double>& weights) {
  Mat9 M = Mat9::Zero();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const Vec9 h = Model::row(candidates[i]);
    M += weights[i] * h * h.transpose();
  }
  return M;
}

// Ipopt's weights on at most kExactCandidates replace the multiplicative algorithm's when they are no
// worse (Ipopt stopped short otherwise); whether they did. For a nonsmooth form its dual is kept also
// when its weights are worse by no more than kExactDualTolerance: the certificate is valid for any
// dual, and at Ipopt's own tolerance either measure may come out lower by the last digits (E on
// cap:90: 147.000000004 against 147.0000000018), but only the exact dual proves the limit to 1e-9
// (without it, the smoothed dual's bound was 2.5e-7 below).
constexpr double kExactDualTolerance = 1e-9;

template <class Crit>
bool exact_weights_of(const std::vector<Vec3>& candidates, std::vector<double>& weights, Mat9& K,
                      std::optional<ExactDual<P>>& dual) {
  if (candidates.size() > kExactCandidates) return false;
  const auto exact = exact_weights<Crit>(candidates, weights);
  if (!exact) return false;
  Eigen::LLT<Mat9> llt(information(candidates, exact->weights));
  const Mat9 Ke = llt.solve(Mat9::Identity());
  if (llt.info() != Eigen::Success) return false;
  const double exact_value = criterion_value<Crit>(Ke), value = criterion_value<Crit>(K);
  if constexpr (!SmoothCriterion<Crit>)
    if (exact_value <= value * (1 + kExactDualTolerance)) dual = ExactDual<P>{exact->dual, exact->row_weights};
  if (exact_value > value) return false;
  weights = exact->weights;
  K = Ke;
  return true;
}

// Where |C h|^2 peaks on the region, climbed from the support and from the grid positions where it
// is within 1e-3 of its largest grid value (a peak the measure has not found yet).
std::vector<Vec3> peaks(const Eigen::Matrix<double, Eigen::Dynamic, P>& C, const Region& region,
                        const std::vector<Vec3>& support, const std::vector<Vec3>& grid) {
  const auto f = [&](const Vec3& x) { return (C * Model::row(x)).squaredNorm(); };
  std::vector<Vec3> starts = support;
  double top = 0;
  for (const Vec3& x : grid) top = std::max(top, f(x));
  for (const Vec3& x : grid)
    if (f(x) >= (1 - 1e-3) * top) starts.push_back(x);
  // The highest starts first, at most kPeaksPerRound of them: on a ridge every grid point near it
  // is a start, and a few peaks per round refine the measure as well as all of them.
  std::stable_sort(starts.begin(), starts.end(), [&](const Vec3& a, const Vec3& b) { return f(a) > f(b); });
  if (starts.size() > kPeaksPerRound) starts.resize(kPeaksPerRound);
  std::vector<Vec3> out;
  for (const Vec3& x : starts) {
    const int z = region.deepest_zone(x);
    Vec3 peak = x;
    const std::vector<double> azimuths =
        z >= 0 ? region.meridians(region.zones[static_cast<std::size_t>(z)]) : std::vector<double>{};
    if (!azimuths.empty()) {
      // Stay on the nearest half-meridian the measure may live on (a pole stays put).
      const Zone& zone = region.zones[static_cast<std::size_t>(z)];
      const double tilt = zone.tilt_deg(x), a = azimuth_deg(zone, x);
      if (tilt > 1e-9 && tilt < 180 - 1e-9) {
        const auto gap = [a](double m) {
          const double d = std::fmod(std::abs(a - m), 360.0);
          return std::min(d, 360.0 - d);
        };
        const double azimuth =
            *std::min_element(azimuths.begin(), azimuths.end(), [&](double p, double q) { return gap(p) < gap(q); });
        peak = zone_position(zone, climb_meridian(f, zone, azimuth, tilt), azimuth);
      }
    } else if (z >= 0) {
      peak = climb(f, x, region);
    }
    if (is_new(peak, out)) out.push_back(peak);
  }
  return out;
}

// Adds the peaks of the certificate's function that are not candidates yet; how many.
int add_peaks(const Eigen::Matrix<double, Eigen::Dynamic, P>& C, const Region& region, const std::vector<Vec3>& grid,
              std::vector<Vec3>& candidates, std::vector<double>& weights) {
  int added = 0;
  for (const Vec3& x : peaks(C, region, candidates, grid))
    if (is_new(x, candidates)) {
      candidates.push_back(x);
      weights.push_back(1e-3 / static_cast<double>(candidates.size()));
      ++added;
    }
  return added;
}

template <class Crit>
RegionLimit limit_of(const Region& region, const RegionLimitOptions& options) {
  if constexpr (kDeterminantOnly<Crit>)
    if (is_single_zone(region)) return zonal_limit(region.zones.front(), zonal_d_limit(region.zones.front()));
  const std::vector<Vec3> grid = region.measure_grid(options.grid_step_deg);
  std::vector<Vec3> candidates = grid;
  std::vector<double> weights;
  RegionLimit out;
  double sharpness = 1;
  // A rough measure on the grid finds where the support is.
  Mat9 K = multiplicative_weights<Crit>(candidates, weights, sharpness, out.equivalence_gap, 400);
  // No region does better than the sphere (proofs/). A region that holds the sphere's optimum has a
  // flat sensitivity (any position is a peak): refining and searching it would cost much and prove
  // no more than the sphere's limit already does.
  const auto sphere = Crit::template limit<Model, double>();
  const bool near_sphere = sphere && criterion_value<Crit>(K) <= sphere->value * (1 + kNearSphereLimit);
  std::optional<ExactDual<P>> dual;
  if (!near_sphere) {
    // Each round moves candidates onto the peaks of the current certificate's function (where an
    // optimal measure sits) and re-weights.
    for (; out.refinements < options.max_refinements; ++out.refinements) {
      keep_support(candidates, weights);
      K = multiplicative_weights<Crit>(candidates, weights, sharpness, out.equivalence_gap, 3000);
      const auto certificate = dual_certificate<Crit, Model>(K, sharpness);
      if (!certificate || add_peaks(certificate->C, region, grid, candidates, weights) == 0) break;
    }
    // Then rounds with Ipopt's exact weights (and dual): the smoothed dual of a nonsmooth form
    // peaks a little away from where the exact one does.
    for (int round = 0; round < kExactRounds; ++round) {
      keep_support(candidates, weights);
      // The first round's weights are final when Ipopt's cannot replace them: then they get ten
      // times the work. Ipopt's start needs no more than the later rounds' (A on cap:90: 20000
      // iterations first were 60 % of its time, for the same limit to 5e-14).
      K = multiplicative_weights<Crit>(candidates, weights, sharpness, out.equivalence_gap, kExactStartIterations);
      if (!exact_weights_of<Crit>(candidates, weights, K, dual) && round == 0)
        K = multiplicative_weights<Crit>(candidates, weights, sharpness, out.equivalence_gap, kFinalIterations);
      const auto certificate = dual_certificate<Crit, Model>(K, sharpness, dual ? &*dual : nullptr);
      if (!certificate || round + 1 == kExactRounds ||
          add_peaks(certificate->C, region, grid, candidates, weights) == 0)
        break;
    }
  } else {
    keep_support(candidates, weights);
    K = multiplicative_weights<Crit>(candidates, weights, sharpness, out.equivalence_gap, 3000);
    exact_weights_of<Crit>(candidates, weights, K, dual);
  }
  out.value = criterion_value<Crit>(K);
  out.K = K;
  if (sphere) out.lower_bound = sphere->value;
  if (options.certify && !near_sphere && !(sphere && out.value <= sphere->value * (1 + kAtSphereLimit))) {
    if (const auto certificate = dual_certificate<Crit, Model>(K, sharpness, dual ? &*dual : nullptr)) {
      // The proof: weak duality with the sup of the certificate's function over the whole region.
      double upper = 0;
      if (!region.candidates.empty())
        upper = std::max(upper, sup_norm2_over_points(certificate->C, region.candidates).upper);
      // The box budget is shared by the zones, so that a union costs no more than one zone.
      const long budget = kBoxBudget / static_cast<long>(std::max<std::size_t>(1, region.zones.size()));
      for (const Zone& z : region.zones) {
        const SupBound b = sup_norm2_over_zone(certificate->C, z, 1e-9, budget);
        upper = std::max(upper, b.upper);
        out.boxes += b.boxes;
      }
      out.lower_bound = std::max(out.lower_bound.value_or(0.0), certificate->lower_bound(upper));
    }
  }
  // A measure's value below its proven bound is rounding (both at the sphere's limit, say).
  if (out.lower_bound && out.value < *out.lower_bound) out.value = *out.lower_bound;
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

bool is_single_zone(const Region& region) {
  return region.zones.size() == 1 && region.candidates.empty() && !region.is_sphere();
}

RegionLimit region_limit(CriterionKind c, const Region& region, const RegionLimitOptions& options) {
  if (options.closed_forms)
    if (const auto f = cap_closed_form(c, region)) return closed_form_limit(region.zones.front(), *f);
  return visit_criterion(c, [&](auto C) { return limit_of<decltype(C)>(region, options); });
}

int distinct_support(const RegionLimit& l) {
  const double same = std::cos(1e-3 * M_PI / 180.0);
  std::vector<Vec3> positions;
  std::vector<double> weights;
  for (std::size_t i = 0; i < l.support.size(); ++i) {
    std::size_t k = 0;
    while (k < positions.size() && positions[k].dot(l.support[i]) < same) ++k;
    if (k == positions.size()) {
      positions.push_back(l.support[i]);
      weights.push_back(0.0);
    }
    weights[k] += l.weights[i];
  }
  if (weights.empty()) return 0;
  const double top = *std::max_element(weights.begin(), weights.end());
  return static_cast<int>(std::count_if(weights.begin(), weights.end(), [top](double w) { return w >= 1e-3 * top; }));
}

std::string_view status_name(LimitStatus s) {
  switch (s) {
    case LimitStatus::proven:
      return "proven";
    case LimitStatus::certified:
      return "certified";
    case LimitStatus::numerical:
      break;
  }
  return "numerical";
}

LimitStatus status_of(const RegionLimit& l) {
  if (!l.theorem.empty()) return LimitStatus::proven;
  return l.lower_bound ? LimitStatus::certified : LimitStatus::numerical;
}

LimitStatement limit_statement(CriterionKind c, const Region& region) {
  if (region.is_sphere()) {
    const auto l = criterion_limit(c);  // throws where the criterion has no known limit
    return {l.value, l.value, LimitStatus::proven, l.theorem};
  }
  const RegionLimit l = region_limit(c, region);
  return {l.value, l.lower_bound, status_of(l), l.theorem};
}

double limit_value(CriterionKind c, const Region& region) { return limit_statement(c, region).value; }

}  // namespace scalcal
