// `scalcal catalogue` (catalogue.hpp).
#include "commands/design/catalogue.hpp"

#include "commands/core/common_options.hpp"
#include "commands/core/evaluation_json.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::commands {

const CommandTable& catalogue_table() {
  static const CommandTable table{
      "catalogue",
      "every named program (the paper's, the printable jigs, the families') with its source and criteria",
      5,
      {json_option("print a JSON array, one object per program")}};
  return table;
}

CatalogueResult catalogue() {
  CatalogueResult r;
  for (const auto& e : scalcal::catalogue())
    r.entries.push_back({e.name, e.description, e.source, evaluate(e.program)});
  return r;
}

Json to_json(const CatalogueResult& r) {
  Json all = Json::array();
  for (const auto& e : r.entries)
    all.push_back(Json{{"name", e.name},
                       {"description", e.description},
                       {"source", e.source},
                       {"evaluation", evaluation_json(e.evaluation)}});
  return all;
}

}  // namespace scalcal::commands
