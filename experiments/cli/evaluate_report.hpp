// `scalcal evaluate` as a function: the criteria of one program under a model, and with regions its
// efficiency against the region's limits. Shared by the CLI and the Python module.
#pragma once
#include <string>
#include <vector>

#include "experiments/cli/report.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::cli {

struct EvaluateRequest {
  std::string name;  // the program's name in messages (a file, a catalogue name, "positions")
  Program program;
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;  // --region specs; none: the sphere
  std::string out;                   // also write the program as CSV here (empty: no file)
};

// Throws InputError for a rank-deficient program or one with positions outside the region, and
// UsageError for regions under a model other than paper9; warns on stderr when ill-conditioned.
Report evaluate_report(const EvaluateRequest& request);

}  // namespace scalcal::cli
