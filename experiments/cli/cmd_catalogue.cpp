// `scalcal catalogue [--json]`: every named program with its source and criteria.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/options.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

int run(bool json) {
  const auto entries = catalogue();
  if (json) {
    Json all = Json::array();
    for (const auto& e : entries)
      all.push_back(Json{{"name", e.name},
                         {"description", e.description},
                         {"source", e.source},
                         {"evaluation", evaluation_json(evaluate(e.program))}});
    print_json(all);
    return 0;
  }
  int width = 16;  // the paper's names fit; the families' (jig:rhombic-triacontahedron) widen the column
  for (const auto& e : entries) width = std::max(width, static_cast<int>(e.name.size()));
  std::printf("%-*s %3s %4s %14s %9s %9s %9s %7s %7s %7s  %s\n", width, "program", "N", "rank", "D=N^9detK", "A", "E",
              "S", "th_b", "th_dk", "th_g", "source");
  for (const auto& e : entries) {
    const Evaluation ev = evaluate(e.program);
    if (!ev.full_rank()) {
      std::printf("%-*s %3d %4d  %s  %s\n", width, e.name.c_str(), ev.positions, ev.rank, rank_deficiency(ev).c_str(),
                  e.source.c_str());
      continue;
    }
    std::printf("%-*s %3d %4d %14.6g %9.4f %9.4f %9.4f %7.4f %7.4f %7.4f  %s\n", width, e.name.c_str(), ev.positions,
                ev.rank, ev.D, ev.A, ev.E, ev.S, ev.theta_bias, ev.theta_scale, ev.theta_nonorth, e.source.c_str());
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  add_switch(app, "--json", *json, "print a JSON array, one object per program");
  return [json] { return run(*json); };
}

const Registration reg({"catalogue", "catalogue [--json]",
                        "every named program (the paper's, the printable jigs, the families') with its source and criteria", 5, setup});

}  // namespace
}  // namespace scalcal::cli
