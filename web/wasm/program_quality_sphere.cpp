// web/wasm/program_quality_sphere.cpp: the web build's program_quality() (declared in
// commands/calibration/calibrate.hpp), standing in for commands/calibration/calibrate_program.cpp, which cannot be
// linked here: its region limits and the positions it suggests adding run Ipopt (numeric/region/augment, region_limit).
//
// What is kept, line for line with calibrate_program.cpp's sphere case: the measured program evaluated under
// the chosen model, and each criterion's efficiency against the proven sphere limit (paper9) or the model's
// stated limit. What is refused, with the CLI command that does it: a region (--region, --program, a log's
// region line) and --suggest K > 0. The browser test compares every number with the CLI's, so a drift between
// this file and calibrate_program.cpp fails it.
#include <cmath>
#include <string>

#include "commands/calibration/calibrate.hpp"
#include "numeric/criteria/efficiency.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
ProgramQuality program_quality(const CalibrateRequest& q, CalibrateResult& r, const Progress&) {
  if (!q.regions.empty())
    throw InputError("--region", 0,
                     "the web page judges a program on the sphere only: a region's limits need Ipopt; run `scalcal "
                     "calibrate ... --region " +
                         q.regions.front() + "` for the efficiency on it");
  if (q.suggest > 0)
    throw InputError("--suggest", 0,
                     "the web page suggests no positions (the augmentation runs Ipopt): use --suggest 0, or run "
                     "`scalcal calibrate ... --suggest " +
                         std::to_string(q.suggest) + "`");
  ProgramQuality out;
  const bool paper9 = model_supports(r.model, ModelCapability::criteria_native);
  out.region = "sphere";
  const Program measured{r.fit.directions};
  const int P = model_parameters(r.model);
  out.evaluation = evaluate(r.model, measured);
  for (CriterionKind c : kCriteria) {
    const double v = out.evaluation.value(c);
    double limit = NAN;
    if (paper9) {
      if (has_limit(c)) limit = criterion_limit(c).value;  // region_limit.cpp's limit_statement on the sphere
    } else if (const auto stated = stated_limit(r.model, criterion_name(c))) {
      limit = stated->value;
    }
    out.efficiency.push_back(std::isfinite(limit) && std::isfinite(v) ? efficiency(c, limit, v, P) : NAN);
  }
  return out;
}

}  // namespace scalcal::commands
