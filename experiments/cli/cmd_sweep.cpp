// `scalcal sweep --positions 9..40 --criteria D,A,E,S [--model NAME] [--region SPEC]... [--starts K]
// [--seed S] [--threads T] [--out FILE] [--json] [--no-timing]`: the best program for every N and
// criterion with its ratio to the limit (commands/research/sweep.hpp), each row shown and saved as it is
// found. --no-timing leaves out the only columns that differ between runs. Started by mpirun, the
// tasks are spread over the ranks and rank 0 prints what a single process would.
#include <cstdlib>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "commands/research/sweep.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/mpi_ranks.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

using commands::Sweep;
using commands::SweepRow;
using commands::SweepTask;

std::string program_cell(const Program& p) {
  std::string s;
  for (std::size_t i = 0; i < p.positions.size(); ++i)
    s += fmt::format("{}{} {} {}", i ? ";" : "", p.positions[i](0), p.positions[i](1), p.positions[i](2));
  return s;
}

// One task's result as JSON between ranks (doubles print with 17 digits, so rank 0 reads back the same bits).
Json encode(std::size_t task, const SynthesisResult& r) {
  return Json{{"task", task},   {"value", r.value},       {"starts", r.starts},   {"stopping", r.stopping},
              {"hits", r.hits}, {"distinct", r.distinct}, {"seconds", r.seconds}, {"program", program_json(r.program)}};
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

std::string number_or(const std::optional<double>& v, double scale, const char* format) {
  return v ? fmt::format(fmt::runtime(format), scale / *v) : std::string("n/a");
}

// Shows and saves each row as it comes.
class RowSink {
 public:
  RowSink(const Sweep& sweep, const commands::Values& v)
      : sweep_(sweep), json_(v.flag("--json")), timing_(!v.flag("--no-timing")) {
    if (v.given("--out")) {
      file_.emplace(v.text("--out"));
      file_->stream() << "criterion,positions,value,limit,ratio,starts,hits,distinct," << (timing_ ? "seconds," : "")
                      << "program\n";
      file_->flush();  // an unwritable file fails now, not after hours of work
    }
    if (!json_)
      std::cout << "crit   N            value        ratio   hits/starts  distinct" << (timing_ ? "  seconds" : "")
                << "\n";
  }

  void add(const SweepRow& row) {
    const SynthesisResult& r = row.result;
    const std::string name(criterion_name(row.task.criterion));
    if (sweep_.restricted() && progress_enabled() && announced_ != row.task.criterion)
      std::cerr << "the " << name << " limit on " << sweep_.region()->text() << "\n";
    announced_ = row.task.criterion;
    if (json_)
      all_.push_back(commands::to_json(sweep_, row, timing_));
    else
      std::cout << fmt::format("{:>4}{:>4}{:>17.10g}{:>13}{:>7}/{:<6}{:>9}", name, row.task.positions, r.value,
                               number_or(row.limit, r.value, "{:.8g}"), r.hits, r.starts, r.distinct)
                << (timing_ ? fmt::format("{:>9.3g}", r.seconds) : "") << std::endl;
    if (file_) {
      file_->stream() << fmt::format("{},{},{},{},{},{},{},{},", name, row.task.positions, r.value,
                                     row.limit ? fmt::format("{}", *row.limit) : "",
                                     number_or(row.limit, r.value, "{}"), r.starts, r.hits, r.distinct)
                      << (timing_ ? fmt::format("{},", r.seconds) : "") << '"' << program_cell(r.program) << "\"\n";
      file_->flush();
    }
  }

  void close() {
    if (file_) file_->close();
    if (json_) print_json(all_);
  }

 private:
  const Sweep& sweep_;
  bool json_, timing_;
  std::optional<OutputFile> file_;
  std::optional<CriterionKind> announced_;
  Json all_ = Json::array();
};

SynthesisResult compute(const Sweep& sweep, const SweepTask& t, int threads) {
  // Fault injection for the test that a failing rank is reported (tests/mpi/sweep_ranks.sh).
  if (const char* fail = std::getenv("SCALCAL_SWEEP_FAIL");
      fail && fmt::format("{}:{}", criterion_name(t.criterion), t.positions) == fail)
    throw std::runtime_error("failure injected by SCALCAL_SWEEP_FAIL");
  return sweep.compute(t, threads);
}

// Task k runs on rank k mod size; rank 0 gathers and shows them in task order, so the output is the
// single-process run's. A task that throws is reported with its rank, never dropped silently.
int run_ranks(const Sweep& sweep, const Ranks& ranks, std::optional<RowSink>& sink) {
  const auto& tasks = sweep.tasks();
  const int threads = sweep.request().threads == 0 ? 1 : sweep.request().threads;  // ranks share the cores
  Json mine = Json::array();
  for (std::size_t k = ranks.rank(); k < tasks.size(); k += ranks.size()) {
    try {
      mine.push_back(encode(k, compute(sweep, tasks[k], threads)));
    } catch (const std::exception& e) {
      mine.push_back(Json{{"task", k}, {"error", e.what()}});
    }
    if (ranks.rank() == 0 && progress_enabled())
      std::cerr << "sweep: rank 0 finished " << criterion_name(tasks[k].criterion) << " N = " << tasks[k].positions
                << "\n";
  }
  const std::vector<std::string> texts = ranks.gather(json_text(mine));
  if (ranks.rank() != 0) return 0;
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
    if (results[k]) sink->add(sweep.row(tasks[k], *results[k]));
  for (const auto& f : failures) std::cerr << "scalcal sweep: " << f << "\n";
  return failures.empty() ? 0 : 1;
}

int run(const commands::Values& v) {
  const Sweep sweep(commands::sweep_request(v));
  print_warnings("sweep", sweep.warnings());
  const Ranks& ranks = Ranks::world();
  std::optional<RowSink> sink;
  if (ranks.rank() == 0) sink.emplace(sweep, v);
  int status = 0;
  if (ranks.size() == 1)
    for (const SweepTask& t : sweep.tasks()) sink->add(sweep.row(t, compute(sweep, t, sweep.request().threads)));
  else
    status = run_ranks(sweep, ranks, sink);
  if (sink) sink->close();
  return status;
}

const Registration reg(commands::sweep_table(), run);

}  // namespace
}  // namespace scalcal::cli
