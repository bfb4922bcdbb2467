// The limit of a criterion over a region: the infimum over all measures on it (N -> infinity). Where a
// theorem gives it in closed form (numeric/region/cap_limits.hpp) it is that value, proven; elsewhere
// the value of an optimal measure found on candidates, and a lower bound certified by weak duality
// over the whole continuous region: value - lower_bound is then a proven gap.
#pragma once
#include <optional>
#include <string_view>
#include <vector>
#include "numeric/criteria/efficiency.hpp"

#include "numeric/criteria/registry.hpp"
#include "numeric/region/region.hpp"

namespace scalcal {

struct RegionLimit {
  double value = 0;                   // the criterion of the measure below (normalised, weights sum 1)
  Mat9 K = Mat9::Zero();              // the measure's inverse information matrix (its thetas: sqrt K(r,r))
  std::optional<double> lower_bound;  // certified; empty for a criterion without a dual bound
  std::vector<Vec3> support;          // positions of the measure with weight >= 1e-6
  std::vector<double> weights;        // their weights (the rest of the mass is below 1e-6 each)
  double equivalence_gap = 0;         // on the final candidates
  int candidates = 0;                 // how many the final measure was optimised over
  int refinements = 0;                // rounds that added positions found by the bound's search
  long boxes = 0;                     // interval boxes the certificates used
  std::string_view theorem;           // the proof of the closed form the value comes from ("": none)
};

// How many distinct positions the measure holds, robustly: support positions within 1e-3 degrees of each
// other are one (a refined candidate beside its first copy), and a position counts when it carries at least
// 1e-3 of the largest weight (so that weights near the solver's noise, which differ with the BLAS kernel,
// do not change the count).
int distinct_support(const RegionLimit& l);

// What stands behind a limit: a theorem's closed form (proven), a proven lower bound with an optimal
// measure's value (certified: the limit lies between them), or an optimal measure alone (numerical).
enum class LimitStatus { proven, certified, numerical };
std::string_view status_name(LimitStatus s);  // "proven", "certified", "numerical"
LimitStatus status_of(const RegionLimit& l);

struct RegionLimitOptions {
  double grid_step_deg = 4.0;  // the first candidates: rings this far apart
  int max_refinements = 6;
  bool certify = true;  // false: the value only (no interval search; lower_bound only the sphere's)
  // false: the solver's optimal measure and certified bound even where a theorem gives the closed form
  // (the tests compare the two).
  bool closed_forms = true;
};

RegionLimit region_limit(CriterionKind c, const Region& region, const RegionLimitOptions& options = {});

// One cap or band and nothing else: there D is one-dimensional and region_limit() takes it from
// numeric/region/zonal_d.hpp.
bool is_single_zone(const Region& region);

// The limit a program on the region is judged against, with what stands behind it: on the sphere the
// criterion's proven limit, on a region region_limit()'s (a closed form where a theorem gives one).
struct LimitStatement {
  double value = 0;
  std::optional<double> lower_bound;  // proven
  LimitStatus status = LimitStatus::numerical;
  std::string_view theorem;  // where status is proven
};
LimitStatement limit_statement(CriterionKind c, const Region& region);
double limit_value(CriterionKind c, const Region& region);
// efficiency(): numeric/criteria/efficiency.hpp (included above).

}  // namespace scalcal
