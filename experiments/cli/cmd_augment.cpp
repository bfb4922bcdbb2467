// `scalcal augment --program FILE --add K [--criterion C] [--model NAME] [--region SPEC]... [--out FILE]
// [--json]`: keeps the lab's positions and adds the K inside the bench's region that improve the
// criterion of the model most (numeric/region/augment.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/augment.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, criterion = "D", out, model = "paper9";
  std::vector<std::string> regions;
  int add = 0;
  bool json = false;
};

Json value_json(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string value_text(double v) {
  if (!std::isfinite(v)) return "rank-deficient";
  char s[32];
  std::snprintf(s, sizeof s, "%.10g", v);
  return s;
}

int run(const Options& o) {
  const Program given = resolve_program(o.program);
  const Region region = resolve_region(o.regions, "augment");
  const CriterionKind c = criterion_of(o.criterion);
  const ModelKind model = model_of(o.model);
  const AugmentedProgram a = augment_program(given, o.add, c, region, model);
  if (!o.out.empty()) write_program_file(o.out, a.program, region_columns(region, a.program));
  if (o.json) {
    Json added = Json::array();
    for (const Vec3& x : a.added) added.push_back(Json{x.x(), x.y(), x.z()});
    Json j{{"criterion", std::string(criterion_name(c))},
           {"region", region.text()},
           {"value_before", value_json(a.value_before)},
           {"value", value_json(a.value)},
           {"added", added},
           {"program", program_json(a.program)}};
    if (model != ModelKind::paper9) j["model"] = o.model;
    print_json(j);
    return 0;
  }
  if (model != ModelKind::paper9) std::cout << "model " << o.model << ", ";
  std::cout << criterion_name(c) << ": " << value_text(a.value_before) << " with the " << given.size()
            << " given positions, " << value_text(a.value) << " with " << a.added.size() << " added on "
            << region.text() << ":\n";
  for (const Vec3& x : a.added) {
    char line[96];
    std::snprintf(line, sizeof line, "  %.9f, %.9f, %.9f\n", x.x(), x.y(), x.z());
    std::cout << line;
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--program", o->program, "FILE",
           {"the program the lab has: a catalogue name or a CSV file", "file path", kRequired});
  add_integer(app, "--add", o->add, 1, 1000, {"how many positions to add", "positions", kRequired});
  add_criterion(app, o->criterion, "D");
  add_model(app, o->model);
  add_region_option(app, o->regions);
  add_text(app, "--out", o->out, "FILE", {"write the whole program (given, then added) as CSV", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"augment",
                        "augment --program FILE --add K [--criterion C] [--model NAME] [--region SPEC]... [--out FILE] "
                        "[--json]",
                        "add the K positions that improve a program most, inside the bench's region", 55, setup});

}  // namespace
}  // namespace scalcal::cli
