// `scalcal catalogue [--json]`: every named program with its source and criteria
// (commands/design/catalogue.hpp), one line each, a column per registered criterion.
#include <algorithm>
#include <cstdio>

#include "commands/design/catalogue.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "numeric/criteria/identifiability.hpp"

namespace scalcal::cli {
namespace {

void print_text(const commands::CatalogueResult& r) {
  int width = 16;  // the paper's names fit; the families' (jig:rhombic-triacontahedron) widen the column
  for (const auto& e : r.entries) width = std::max(width, static_cast<int>(e.name.size()));
  std::printf("%-*s %3s %4s", width, "program", "N", "rank");
  for (auto c : kCriteria) std::printf(" %12s", std::string(criterion_name(c)).c_str());
  std::printf(" %10s %11s %13s  %s\n", "theta_bias", "theta_scale", "theta_nonorth", "source");
  for (const auto& e : r.entries) {
    const Evaluation& ev = e.evaluation;
    if (!ev.full_rank()) {
      std::printf("%-*s %3d %4d  %s  %s\n", width, e.name.c_str(), ev.positions, ev.rank, rank_deficiency(ev).c_str(),
                  e.source.c_str());
      continue;
    }
    std::printf("%-*s %3d %4d", width, e.name.c_str(), ev.positions, ev.rank);
    for (auto c : kCriteria) std::printf(" %12.7g", ev.value(c));
    std::printf(" %10.6g %11.6g %13.6g  %s\n", ev.theta_bias, ev.theta_scale, ev.theta_nonorth, e.source.c_str());
  }
}

int run(const commands::Values& v) {
  const auto r = commands::catalogue();
  print_warnings("catalogue", r.warnings);
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else
    print_text(r);
  return 0;
}

const Registration reg(commands::catalogue_table(), run);

}  // namespace
}  // namespace scalcal::cli
