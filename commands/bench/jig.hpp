// `scalcal jig` as a function: the best way to mount the meter in a printable jig (any family of
// group "jig"): the rotation of the meter in the jig that minimises the criterion, as the meter's
// axes in jig coordinates, with the criteria before and after. What the closed forms decide
// (symbolic/jig_limits.hpp) is proven; the rest is numerical.
#pragma once
#include <optional>
#include <string>

#include <Eigen/Core>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal::commands {

struct JigRequest {
  std::string name;  // with or without "jig:"
  CriterionKind criterion = CriterionKind::D;
  int starts = 64;
  std::uint64_t seed = 1;
  bool gyro = false;  // --instrument gyro: on a rate table, each face also turned the other way
};

struct JigResult {
  std::string jig;  // the family's name, "jig:cuboctahedron"
  CriterionKind criterion = CriterionKind::D;
  int faces = 0;
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  // the meter's axes (rows) in jig coordinates
  double value = 0, value_default = 0;
  Program program;                // the normals at the best mounting
  std::string status, method;     // "proven" or "numerical", and how
  bool invariant = false;         // the criterion is the same in every orientation
  int starts = 0, hits = 0;       // the search's, when there was one
  std::string exact;              // the exact value when known ("" otherwise)
  std::string orientation_exact;  // the exact rotation found near the numerical one ("" if none)
  bool at_limit = false;
  std::optional<double> limit;  // none: no known limit for the criterion
  std::string limit_exact;
  std::string claim_status, claim_reason;  // what the closed forms decide about reaching the limit
  bool claim_proven = false;
  std::string instrument = "accel", instrument_note;  // the gyro's reading of the answer
  Evaluation before, after;
  Warnings warnings;
};

// NAME [--criterion C] [--starts K] [--seed S] [--json]
const CommandTable& jig_table();
JigRequest jig_request(const Values& values);

// Throws InputError for an unknown jig or one rank-deficient in every orientation.
JigResult jig(const JigRequest& request, const Progress& progress = {});

Json to_json(const JigResult& result);

}  // namespace scalcal::commands
