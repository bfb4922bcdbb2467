// The measured program of `calibrate` under the chosen model: its criteria and efficiency, and the
// positions worth adding, never one twice.
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "commands/calibration/calibrate.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/augment.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/exchange.hpp"

namespace scalcal::commands {
namespace {

// Above this condition number of the region's uniform measure, K is not resolved in double precision.
constexpr double kBeyondDouble = 1e14;

// The region of the specs (the sphere when there are none), checked as the CLI's --region is.
Region region_of(const std::vector<std::string>& specs, Warnings& warnings) {
  Region region = parse_region(specs);
  if (specs.empty()) return region;
  const double condition = check_region_identifiable(region);
  std::ostringstream c;
  c << std::setprecision(3) << condition;
  if (condition > kBeyondDouble)
    throw InputError(option_word("region"), 0,
                     "'" + region.text() + "': even the uniform measure has condition number " + c.str() +
                         ", beyond what double precision resolves (1e14): bias and scale factor are confounded there "
                         "(a cap narrower than about 4 degrees)");
  if (condition > kIllConditioned)
    warnings.push_back({"--region", "on " + region.text() + " even the uniform measure has condition number " +
                                        c.str() + " (bias and scale factor are nearly confounded there)"});
  return region;
}

// Measured directions outside the region (beyond the tolerance): the data are what they are, so a
// warning naming up to ten of them (their order in the data), not a refusal. Returns whether any is
// outside: the region's limits then bound nothing about this program, and no efficiency is given.
bool warn_outside(const Program& measured, const Region& region, double tolerance_deg, Warnings& warnings) {
  std::vector<int> outside;
  for (int i = 0; i < measured.size(); ++i)
    if (!region.contains(measured.positions[static_cast<std::size_t>(i)], tolerance_deg)) outside.push_back(i + 1);
  if (outside.empty()) return false;
  std::string list;
  for (std::size_t k = 0; k < outside.size() && k < 10; ++k) list += (k ? ", " : "") + std::to_string(outside[k]);
  std::ostringstream t;
  t << tolerance_deg;
  warnings.push_back({"--region", std::to_string(outside.size()) + " of " + std::to_string(measured.size()) +
                                      " measured positions lie outside " + region.text() + " by more than " + t.str() +
                                      " degrees: " + list + (outside.size() > 10 ? ", ..." : "") +
                                      "; no efficiency on the region is given (its limits bound only programs "
                                      "inside it)"});
  return true;
}

// sqrt(max K(r,r)) over each group the model has, not normalised by N.
std::vector<double> group_errors(const ModelEvaluation& ev) {
  std::vector<double> out;
  const double root = std::sqrt(static_cast<double>(ev.positions));
  for (int g = 0; g < 4; ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) out.push_back(ev.theta[static_cast<std::size_t>(g)] / root);
  return out;
}

}  // namespace

// The positions to add, one at a time so that none repeats an earlier one: up to kPolishedAdvice
// measured positions the region's augmentation (a greedy exchange on its grid, then Ipopt moving
// the added position with the others held fixed); above, and whenever that lands on an earlier
// suggestion, the best point of the region's grid not yet suggested (a greedy step whose cost is
// linear in N; Ipopt's grows as N^2.4 with the fixed positions among its variables: 10,000 measured
// positions took over 300 s).
constexpr int kPolishedAdvice = 200;

std::vector<Vec3> positions_to_add(const Program& measured, int add, CriterionKind criterion, const Region& region,
                                   ModelKind model) {
  const std::vector<Vec3> grid = region.grid(region.grid_step_for(kRegionGridCandidates));
  Program given = measured;
  std::vector<Vec3> out;
  const auto repeats = [&](const Vec3& x) {
    for (const Vec3& y : out)
      if ((x - y).norm() < 1e-6) return true;
    return false;
  };
  for (int k = 0; k < add; ++k) {
    std::optional<Vec3> x;
    if (measured.size() <= kPolishedAdvice) {
      const AugmentedProgram a = augment_program(given, 1, criterion, region, model);
      if (!a.added.empty() && !repeats(a.added.front())) x = a.added.front();
    }
    if (!x) {
      std::vector<Vec3> candidates;
      for (const Vec3& c : grid)
        if (!repeats(c)) candidates.push_back(c);
      if (candidates.empty()) break;
      const ExchangeResult ex = greedy_exchange(criterion, candidates, given.positions, 1, model);
      if (static_cast<int>(ex.positions.size()) <= given.size()) break;
      x = ex.positions.back();
    }
    out.push_back(*x);
    given.positions.push_back(*x);
  }
  return out;
}

ProgramQuality program_quality(const CalibrateRequest& q, CalibrateResult& r, const Progress&) {
  ProgramQuality out;
  const bool paper9 = model_supports(r.model, ModelCapability::region_limits);
  if (!paper9 && !q.regions.empty())
    r.warnings.push_back({"--region", "ignored: the advice on a region works with " +
                                          models_supporting(ModelCapability::region_limits) +
                                          " only, and the model is " + std::string(model_name(r.model))});
  const Region region = region_of(paper9 ? q.regions : std::vector<std::string>{}, r.warnings);
  out.region = region.text();
  const Program measured{r.fit.directions};
  const bool outside = paper9 && !q.regions.empty() && warn_outside(measured, region, q.tolerance_deg, r.warnings);
  const int P = model_parameters(r.model);
  out.evaluation = evaluate(r.model, measured);
  for (CriterionKind c : kCriteria) {
    const double v = out.evaluation.value(c);
    double limit = NAN;
    if (paper9) {
      if (has_limit(c) && !outside)
        limit = limit_value(c, region);  // a registered criterion may have no known limit: NaN
    } else if (const auto stated = stated_limit(r.model, criterion_name(c))) {
      limit = stated->value;
    }
    out.efficiency.push_back(std::isfinite(limit) && std::isfinite(v) ? efficiency(c, limit, v, P) : NAN);
  }
  if (q.suggest > 0) {
    Program prefix = measured;
    for (const Vec3& x : positions_to_add(measured, q.suggest, q.criterion, region, r.model)) {
      prefix.positions.push_back(x);
      const ModelEvaluation ev = evaluate(r.model, prefix);
      out.suggested.push_back({x, ev.value(q.criterion), group_errors(ev)});
    }
  }
  return out;
}

}  // namespace scalcal::commands
