// The limit a report judges a program against (evaluate's efficiency, optimize's report), with what
// stands behind it: the criterion's proven limit on the sphere, a model's stated limit, a theorem's
// closed form on a cap, or a region's certified or numerical limit.
#pragma once
#include <optional>
#include <string>

#include "commands/core/json.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::commands {

struct ReportedLimit {
  LimitStatement statement;  // value, proven lower bound, status, theorem
  std::string exact;         // the closed form where the status is proven ("" where not derived: no GiNaC)
};

// The limit of c on the region (none: the sphere), or a model's stated limit; nullopt where none is known.
std::optional<ReportedLimit> reported_limit(CriterionKind c, ModelKind model, const std::optional<Region>& region);

// {"value", "status", "lower_bound", and where proven "exact" (null where not derived) and "theorem"}.
Json to_json(const ReportedLimit& limit);

}  // namespace scalcal::commands
