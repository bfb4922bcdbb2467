// `scalcal limits` as a function: the N -> infinity limits of the normalised criteria, exact on the
// sphere (symbolic/limits.hpp) or for a model's stated limits, and certified bounds on a region.
// Shared by the CLI and the Python module.
#pragma once
#include <string>
#include <vector>

#include "experiments/cli/report.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::cli {

// regions: --region specs (none, or only "sphere": the sphere). Throws UsageError for regions
// under a model other than paper9, InputError for a bad region.
Report limits_report(ModelKind model, const std::vector<std::string>& regions);

}  // namespace scalcal::cli
