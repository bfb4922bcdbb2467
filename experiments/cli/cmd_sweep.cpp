// `scalcal sweep --positions 9..40 --criteria D,A,E,S [--model NAME] [--region SPEC]... [--starts K]
// [--seed S] [--threads T] [--out FILE] [--json] [--no-timing]`: the best program for every N and
// criterion, with its ratio to the N -> infinity limit (the region's on a restricted bench, the
// model's stated limit for a model other than the paper's). --no-timing
// leaves out the only columns that differ between runs. Started by mpirun, the tasks are spread over
// the ranks and rank 0 prints what a single process would.
#include <charconv>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/mpi_ranks.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::cli {
namespace {

constexpr int kMinN = 3, kMaxN = 1000;  // N >= the model's parameters is checked in run()

struct Options {
  std::string positions = "9..40", criteria = "D,A,E,S", out, model = "paper9";
  std::vector<std::string> regions;
  int starts = 0, threads = 0;
  std::uint64_t seed = 1;
  bool json = false, no_timing = false;
};

bool read_int(const std::string& s, int& x) {
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  return !s.empty() && ec == std::errc() && ptr == s.data() + s.size();
}

// "N" or "A..B" with kMinN <= A <= B <= kMaxN; nullopt otherwise.
std::optional<std::pair<int, int>> read_range(const std::string& s) {
  const auto dots = s.find("..");
  int lo = 0, hi = 0;
  if (dots == std::string::npos ? !read_int(s, lo) : !read_int(s.substr(0, dots), lo) || !read_int(s.substr(dots + 2), hi))
    return std::nullopt;
  if (dots == std::string::npos) hi = lo;
  if (lo < kMinN || hi < lo || hi > kMaxN) return std::nullopt;
  return std::make_pair(lo, hi);
}

std::vector<CriterionKind> read_criteria(const std::string& s) {
  std::vector<CriterionKind> out;
  std::stringstream list(s);
  for (std::string name; std::getline(list, name, ',');) {
    const auto c = parse_criterion(name);
    if (!c) return {};
    out.push_back(*c);
  }
  if (!s.empty() && s.back() == ',') return {};
  return out;
}

std::string program_cell(const Program& p) {
  std::string s;
  for (std::size_t i = 0; i < p.positions.size(); ++i)
    s += fmt::format("{}{} {} {}", i ? ";" : "", p.positions[i](0), p.positions[i](1), p.positions[i](2));
  return s;
}

struct Task {
  CriterionKind criterion;
  int positions;
};

// One task's result as JSON (doubles print with 17 digits, so rank 0 reads back the same bits).
Json encode(std::size_t task, const SynthesisResult& r) {
  return Json{{"task", task},   {"value", r.value},       {"starts", r.starts},   {"stopping", r.stopping}, {"hits", r.hits},
              {"distinct", r.distinct}, {"seconds", r.seconds}, {"program", program_json(r.program)}};
}

SynthesisResult decode(const Json& j) {
  SynthesisResult r;
  r.value = j.at("value").get<double>();
  r.starts = j.at("starts").get<int>();
  r.stopping = j.at("stopping").get<std::string>();
  r.hits = j.at("hits").get<int>();
  r.distinct = j.at("distinct").get<int>();
  r.seconds = j.at("seconds").get<double>();
  for (const auto& p : j.at("program"))
    r.program.positions.emplace_back(p.at(0).get<double>(), p.at(1).get<double>(), p.at(2).get<double>());
  return r;
}

int run(const Options& o) {
  const auto [lo, hi] = *read_range(o.positions);
  const auto criteria = read_criteria(o.criteria);
  const ModelKind model = model_of(o.model);
  const bool paper9 = model == ModelKind::paper9;
  require_positions("sweep", lo, model);
  if (!paper9 && !o.regions.empty())
    throw UsageError("sweep: --region works with the paper9 model only (got --model " + o.model + ")");
  const std::optional<Region> region =
      o.regions.empty() ? std::nullopt : std::optional<Region>(resolve_region(o.regions, "sweep"));
  const bool restricted = region && !region->is_sphere();
  const Ranks& ranks = Ranks::world();
  const bool root = ranks.rank() == 0;
  std::optional<OutputFile> file;
  if (!o.out.empty() && root) {
    file.emplace(o.out);
    file->stream() << "criterion,positions,value,limit,ratio,starts,hits,distinct," << (o.no_timing ? "" : "seconds,")
                   << "program\n";
    file->flush();  // an unwritable file fails now, not after hours of work
  }
  std::vector<Task> tasks;
  for (const CriterionKind c : criteria)
    for (int n = lo; n <= hi; ++n) tasks.push_back({c, n});

  auto limit_of = [&](CriterionKind c) {
    const std::optional<ModelLimit> stated = stated_limit(model, criterion_name(c));
    return restricted ? limit_value(c, *region)
           : paper9   ? criterion_limit(c).value
           : stated   ? stated->value
                      : std::numeric_limits<double>::quiet_NaN();
  };
  auto compute = [&](const Task& t) {
    // Fault injection for the test that a failing rank is reported (tests/mpi/sweep_ranks.sh).
    if (const char* fail = std::getenv("SCALCAL_SWEEP_FAIL");
        fail && fmt::format("{}:{}", criterion_name(t.criterion), t.positions) == fail)
      throw std::runtime_error("failure injected by SCALCAL_SWEEP_FAIL");
    SynthesisOptions opt;
    opt.positions = t.positions;
    opt.criterion = t.criterion;
    opt.starts = o.starts;
    opt.seed = o.seed;
    // Under MPI the ranks share the cores: one thread each unless --threads says otherwise.
    opt.threads = o.threads == 0 && ranks.size() > 1 ? 1 : o.threads;
    opt.model = model;
    return restricted ? synthesize_on_region(opt, *region) : synthesize(opt);
  };
  Json all = Json::array();
  if (!o.json && root)
    std::cout << "crit   N            value        ratio   hits/starts  distinct" << (o.no_timing ? "" : "  seconds")
              << "\n";
  std::optional<CriterionKind> announced;
  auto emit = [&](const Task& t, const SynthesisResult& r) {
    const CriterionKind c = t.criterion;
    const int n = t.positions;
    if (restricted && progress_enabled() && announced != c)
      std::cerr << "the " << criterion_name(c) << " limit on " << region->text() << "\n";
    announced = c;
    const double limit = limit_of(c);
    const std::string name(criterion_name(c));
    if (o.json) {
      Json j{{"positions", n},  {"criterion", name},       {"value", r.value},
             {"ratio", r.value / limit}, {"program", program_json(r.program)}, {"hits", r.hits},
             {"starts", r.starts}, {"stopping", r.stopping}, {"distinct", r.distinct}};
      if (!o.no_timing) j["seconds"] = r.seconds;
      if (!paper9) {
        j["model"] = std::string(model_name(model));
        j["limit"] = limit;
      }
      if (region) {
        j["region"] = region->text();
        j["limit"] = limit;
      }
      all.push_back(std::move(j));
    } else {
      std::cout << fmt::format("{:>4}{:>4}{:>17.10g}{:>13.8g}{:>7}/{:<6}{:>9}", name, n, r.value, r.value / limit,
                               r.hits, r.starts, r.distinct)
                << (o.no_timing ? "" : fmt::format("{:>9.3g}", r.seconds)) << std::endl;
    }
    if (file) {
      file->stream() << fmt::format("{},{},{},{},{},{},{},{},", name, n, r.value, limit, r.value / limit, r.starts,
                                    r.hits, r.distinct)
                     << (o.no_timing ? "" : fmt::format("{},", r.seconds)) << '"' << program_cell(r.program)
                     << "\"\n";
      file->flush();
    }
  };

  int status = 0;
  if (ranks.size() == 1) {
    for (const Task& t : tasks) emit(t, compute(t));
  } else {
    // Task k runs on rank k mod size; rank 0 gathers and prints in task order, so the output is the
    // single-process run's. A task that throws is reported with its rank, never dropped silently.
    Json mine = Json::array();
    for (std::size_t k = ranks.rank(); k < tasks.size(); k += ranks.size()) {
      try {
        mine.push_back(encode(k, compute(tasks[k])));
      } catch (const std::exception& e) {
        mine.push_back(Json{{"task", k}, {"error", e.what()}});
      }
      if (root && progress_enabled())
        std::cerr << "sweep: rank 0 finished " << criterion_name(tasks[k].criterion) << " N = " << tasks[k].positions
                  << "\n";
    }
    const std::vector<std::string> texts = ranks.gather(json_text(mine));
    if (!root) return 0;
    std::vector<std::optional<SynthesisResult>> results(tasks.size());
    std::vector<std::string> failures;
    for (std::size_t r = 0; r < texts.size(); ++r)
      for (const Json& j : Json::parse(texts[r])) {
        const std::size_t k = j.at("task").get<std::size_t>();
        if (j.contains("error"))
          failures.push_back(fmt::format("rank {} failed on {} N = {}: {}", r, criterion_name(tasks[k].criterion),
                                         tasks[k].positions, j.at("error").get<std::string>()));
        else
          results[k] = decode(j);
      }
    for (std::size_t k = 0; k < tasks.size(); ++k)
      if (results[k]) emit(tasks[k], *results[k]);
    for (const auto& f : failures) std::cerr << "scalcal sweep: " << f << "\n";
    if (!failures.empty()) status = 1;
  }
  if (file) file->close();
  if (o.json) print_json(all);
  return status;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_checked_text(app, "--positions", o->positions, "A..B", {"N or a range A..B of N", "positions"},
                   [](const std::string& s) -> std::string {
                     return read_range(s) ? ""
                                          : fmt::format("must be N or A..B with {} <= A <= B <= {} (and A at least "
                                                        "the model's parameters), got '{}'",
                                                        kMinN, kMaxN, s);
                   });
  add_checked_text(app, "--criteria", o->criteria, "LIST", {"comma-separated criteria"},
                   [](const std::string& s) -> std::string {
                     return read_criteria(s).empty() ? "must be a comma-separated list of D, A, E, S, got '" + s + "'"
                                                     : "";
                   });
  add_model(app, o->model);
  add_region_option(app, o->regions);
  add_starts(app, o->starts);
  add_seed(app, o->seed);
  add_threads(app, o->threads);
  add_text(app, "--out", o->out, "FILE", {"also write the results as CSV, one row per N and criterion", "file path"});
  add_switch(app, "--json", o->json, "print a JSON array, one object per N and criterion, instead of the table");
  add_switch(app, "--no-timing", o->no_timing, "leave out the seconds (output identical between runs)");
  return [o] { return run(*o); };
}

const Registration reg({"sweep",
                        "sweep --positions 9..40 --criteria D,A,E,S [--model NAME] [--region SPEC]... [--starts K] [--seed S] "
                        "[--threads T] [--out FILE] [--json] [--no-timing]",
                        "the best program for every N and criterion, and its ratio to the N -> infinity limit", 42,
                        setup});

}  // namespace
}  // namespace scalcal::cli
