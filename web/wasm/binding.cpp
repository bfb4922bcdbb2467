// web/wasm/binding.cpp: the page's one entry into scalcal's numeric core, a C function taking and returning
// JSON (nlohmann-json, as the CLI's --json): {"op": ..., ...} in, {"ok": true, ...} or {"ok": false, "error"} out.
//
// Each op runs the CLI's own code where it builds without Ipopt: calibrate, export and plan parse the CLI's
// options with the CLI's option tables (commands/*_table) and run commands::calibrate / export_calibration /
// plan, whose JSON is what `scalcal calibrate --json` / `export --json` / `plan --json` print. evaluate and random are
// rebuilt from the numeric calls commands/design/evaluate.cpp and commands/design/random.cpp make (those units also
// link region code that needs Ipopt); the browser test compares every number with the CLI's, so a drift fails it.
#include <sys/stat.h>
#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "commands/bench/export.hpp"
#include "commands/bench/plan.hpp"
#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibrate_json.hpp"
#include "commands/core/evaluation_json.hpp"
#include "commands/core/json.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/values.hpp"
#include "numeric/bench/registry.hpp"
#include "numeric/criteria/efficiency.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/export/export_format.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region_sampler.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal::web {
namespace {

using commands::Json;

// The page's inputs live in emscripten's in-memory file system, in the working folder under the bare names the
// CLI command shown on the page uses (cal.json, design.csv, the log's name), so messages naming them read as
// the CLI's run in the folder holding them.
std::string put_file(const std::string& name, const std::string& text) {
  static const bool folder = [] { return mkdir("/work", 0755) == 0 && chdir("/work") == 0; }();
  if (!folder) throw std::runtime_error("no working folder in the in-memory file system");
  const std::string base = name.substr(name.find_last_of('/') == std::string::npos ? 0 : name.find_last_of('/') + 1);
  if (base.empty() || base == "." || base == "..") throw std::runtime_error("a file needs a name, got '" + name + "'");
  std::ofstream(base, std::ios::binary) << text;
  return base;
}

// [["--option", "value"], ["--flag"], ...] into the command's Values, checked as the CLI checks them.
void set_args(commands::Values& values, const Json& args) {
  for (const Json& a : args) {
    const std::string option = a.at(0).get<std::string>();
    if (a.size() == 1)
      values.set_flag(option, true);
    else
      values.set(option, a.at(1).get<std::string>());
  }
}

Json warnings_json(const commands::Warnings& w) {
  Json out = Json::array();
  for (const auto& x : w) out.push_back({{"subject", x.subject}, {"message", x.message}});
  return out;
}

// The program of a catalogue name, or of CSV text (a design file the page wrote or the user gave).
Program program_of(const Json& in) {
  if (in.contains("csv")) return read_program_csv(put_file(in.value("name", "program.csv"), in.at("csv")));
  return resolve_program(in.at("program").get<std::string>());
}

// `scalcal evaluate PROGRAM --region sphere --json`: the criteria, and each one's efficiency against the
// proven sphere limit (numeric/criteria/efficiency.hpp: limit / value, D as its 9th root). A
// program file whose region line is not the sphere gets its criteria only: the limits on a region need Ipopt
// (and GiNaC for the closed forms on caps), so `scalcal evaluate design.csv` gives that efficiency.
Json evaluate_op(const Json& in) {
  const Program program = program_of(in);
  const ModelEvaluation ev = scalcal::evaluate(ModelKind::paper9, program);
  if (!ev.full_rank()) throw std::runtime_error("rank-deficient program: rank " + std::to_string(ev.rank) + " of 9");
  Json j = commands::evaluation_json(ev, program);
  commands::Warnings warnings;
  const std::vector<std::string> specs =
      in.contains("csv") ? program_region(in.at("csv")).specs : std::vector<std::string>{};
  const Region region = commands::resolve_region(specs, warnings);
  j["region"] = region.text();
  Json e = Json::object(), l = Json::object();
  for (auto c : kCriteria) {
    const std::string name(criterion_name(c));
    if (!has_limit(c) || !region.is_sphere()) {
      e[name] = nullptr;
      l[name] = nullptr;
      continue;
    }
    const auto limit = criterion_limit(c);
    e[name] = efficiency(c, limit.value, ev.value(c), ev.parameters);
    l[name] = {{"value", limit.value},
               {"status", "proven"},
               {"lower_bound", limit.value},
               {"exact", std::string(limit.exact)},
               {"theorem", std::string(limit.theorem)}};
  }
  j["efficiency"] = e;
  j["limits"] = l;
  std::ostringstream csv;
  write_program_csv(csv, program, {}, {specs, {}});
  j["csv"] = csv.str();
  return j;
}

// `scalcal random --positions N --count R --seed S --criterion C [--region SPEC]... --json`: the best of R
// uniform programs (on the region: numeric/region/region_sampler), one thread (the search gives the same answer
// on any thread count: numeric/synthesis/random_search.hpp); the CSV as `--out` writes it, region line included.
Json random_op(const Json& in) {
  const auto criterion = parse_criterion(in.value("criterion", std::string("D")));
  if (!criterion) throw std::runtime_error("unknown criterion");
  const std::vector<std::string> specs = in.value("regions", std::vector<std::string>{});
  commands::Warnings warnings;
  PositionSampler sampler;
  std::string region;
  if (!specs.empty()) {
    const Region r = commands::resolve_region(specs, warnings);
    if (!r.is_sphere()) {
      sampler = region_sampler(r);
      region = r.text();
    }
  }
  const RandomSearchResult r = random_search(in.at("positions").get<int>(), in.at("count").get<long long>(), *criterion,
                                             in.value("seed", 1ULL), 1, sampler);
  if (!std::isfinite(r.best)) throw std::runtime_error("no random program with a finite value: draw more");
  std::ostringstream csv;
  write_program_csv(csv, r.program, {}, {region.empty() ? std::vector<std::string>{} : specs, {}});
  Json j{{"best", r.best},       {"count", r.count}, {"program", commands::program_json(r.program)},
         {"seconds", r.seconds}, {"csv", csv.str()}, {"warnings", warnings_json(warnings)}};
  if (!region.empty()) j["region"] = region;
  return j;
}

// `scalcal calibrate --measurements NAME ARGS... --json --out cal.json`: the result's JSON and the calibration
// file's text, as the CLI writes it (commands::json_text, indent 2, one newline).
Json calibrate_op(const Json& in) {
  commands::Values v(commands::calibrate_table());
  v.set("--measurements", put_file(in.at("name"), in.at("log")));
  set_args(v, in.value("args", Json::array()));
  const commands::CalibrateResult r = commands::calibrate(commands::calibrate_request(v));
  return {{"result", commands::to_json(r)},
          {"calibration_file", commands::json_text(commands::calibration_file_json(r), 2) + "\n"},
          {"converged", r.converged()},
          {"warnings", warnings_json(r.warnings)}};
}

// `scalcal export cal.json --format F ARGS... [--json]`: the target's text, byte for byte the CLI's output.
Json export_op(const Json& in) {
  commands::Values v(commands::export_table());
  v.set("CALIBRATION", put_file(in.value("name", "cal.json"), in.at("calibration")));
  set_args(v, in.value("args", Json::array()));
  const commands::ExportResult r = commands::export_calibration(commands::export_request(v));
  return {{"text", r.output.text}, {"result", commands::to_json(r)}, {"warnings", warnings_json(r.warnings)}};
}

// `scalcal plan PROGRAM --bench SPEC ARGS... --json --out plan.csv`: the plan's JSON as the CLI prints it, the
// plan file as `--out plan.csv` writes it, and the bench's own names the page's sheet shows (its axes, its
// mountings' labels as the CLI's text prints them beside the values the JSON gives).
Json plan_op(const Json& in) {
  commands::Values v(commands::plan_table());
  v.set("PROGRAM", in.contains("csv") ? put_file(in.value("name", "design.csv"), in.at("csv"))
                                      : in.at("program").get<std::string>());
  set_args(v, in.value("args", Json::array()));
  const commands::PlanResult r = commands::plan(commands::plan_request(v));
  commands::PlanFile f = commands::plan_file(r);
  f.notes.region = commands::specs_written_to(f.notes.region, "plan.csv");
  std::ostringstream csv;
  write_program_csv(csv, f.program, f.columns, f.notes);
  Json axes = Json::array(), mountings = Json::array();
  for (const auto& a : r.bench.axes()) axes.push_back(a.name);
  for (const auto& m : r.bench.mountings()) mountings.push_back({{"value", m.value}, {"label", m.label}});
  return {{"result", commands::to_json(r)},
          {"csv", csv.str()},
          {"bench", {{"axes", axes}, {"mounting_key", std::string(r.bench.mounting_key())}, {"mountings", mountings}}},
          {"warnings", warnings_json(r.warnings)}};
}

// What the page offers: the catalogue's programs, the criteria and their limits, the export formats.
Json about_op() {
  Json programs = Json::array();
  for (const auto& c : catalogue()) programs.push_back({{"name", c.name}, {"positions", c.program.size()}});
  Json formats = Json::array();
  for (const auto& f : export_formats()) formats.push_back({{"name", f.name}, {"what", f.what}});
  Json criteria = Json::array();
  for (auto c : kCriteria) criteria.push_back(std::string(criterion_name(c)));
  return {{"programs", programs}, {"formats", formats}, {"criteria", criteria}, {"benches", bench_syntaxes()}};
}

Json dispatch(const Json& in) {
  const std::string op = in.at("op");
  if (op == "evaluate") return evaluate_op(in);
  if (op == "random") return random_op(in);
  if (op == "calibrate") return calibrate_op(in);
  if (op == "export") return export_op(in);
  if (op == "plan") return plan_op(in);
  if (op == "about") return about_op();
  throw std::runtime_error("unknown op '" + op + "'");
}

}  // namespace
}  // namespace scalcal::web

// The C entry: a malloc'd JSON text the caller frees with scalcal_free. Errors (the CLI's exit-2 messages,
// nlohmann's parse errors) come back as {"ok": false, "error": what()}, never as a trap.
extern "C" char* scalcal_call(const char* request) {
  scalcal::commands::Json out;
  setenv("SCALCAL_DATA", "/data", 0);  // the embedded Tables 1-3 (web/CMakeLists.txt), as the CLI's data/
  try {
    out = scalcal::web::dispatch(scalcal::commands::Json::parse(request));
    out["ok"] = true;
  } catch (const std::exception& e) {
    out = {{"ok", false}, {"error", e.what()}};
  }
  const std::string text = scalcal::commands::json_text(out, -1);
  char* p = static_cast<char*>(std::malloc(text.size() + 1));
  std::memcpy(p, text.c_str(), text.size() + 1);
  return p;
}

extern "C" void scalcal_free(char* p) { std::free(p); }
