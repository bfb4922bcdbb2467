// `scalcal polish` as a function: Newton's method in MPFR on the first-order conditions of a
// criterion, from any program, with the second-order verdict of the interval certificate.
#pragma once
#include <string>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/certify/second_order.hpp"
#include "numeric/polish/polish.hpp"

namespace scalcal::commands {

struct PolishRequest {
  std::string name;  // the program's name in messages
  Program program;
  CriterionKind criterion = CriterionKind::D;
  int digits = 50;
};

struct PolishCommandResult {
  CriterionKind criterion = CriterionKind::D;
  int positions = 0;
  PolishResult polished;
  SecondOrder second_order;
  Warnings warnings;
};

// PROGRAM --criterion C [--digits P] [--out FILE] [--json]
const CommandTable& polish_table();
PolishRequest polish_request(const Values& values);

// Throws InputError for a rank-deficient program (every criterion divides by the information matrix).
// A polish that did not converge is a result (summary not converged) with a warning; the CLI exits 1.
PolishCommandResult polish(const PolishRequest& request, const Progress& progress = {});

Json to_json(const PolishCommandResult& result);

}  // namespace scalcal::commands
