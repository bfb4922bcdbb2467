// `scalcal catalogue` as a function: every named program (the paper's, the printable jigs', any
// family's listed ones) with its source and its evaluation.
#pragma once
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal::commands {

struct CatalogueEntryResult {
  std::string name, description, source;
  Evaluation evaluation;
};

struct CatalogueResult {
  std::vector<CatalogueEntryResult> entries;
  Warnings warnings;
};

const CommandTable& catalogue_table();  // [--json]
CatalogueResult catalogue();

Json to_json(const CatalogueResult& result);  // an array, one object per program

}  // namespace scalcal::commands
