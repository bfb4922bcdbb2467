// `scalcal sweep --positions 9..40 --criteria D,A,E,S [--model NAME] [--region SPEC]... [--starts K]
// [--seed S] [--threads T] [--out FILE] [--json] [--no-timing]`: the best program for every N and
// criterion with its ratio to the limit (commands/research/sweep.hpp), each row shown and saved as it is
// found. --no-timing leaves out the only columns that differ between runs. Started by mpirun, the
// tasks (and the certain starts of tasks that have many) are spread over the ranks and rank 0 prints
// what a single process would.
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "commands/research/sweep.hpp"
#include "commands/research/sweep_shards.hpp"
#include "commands/research/sweep_starts.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/mpi_ranks.hpp"
#include "experiments/cli/result_appender.hpp"
#include "experiments/cli/sweep_rows.hpp"

namespace scalcal::cli {
namespace {

using commands::Sweep;
using commands::SweepRow;
using commands::SweepTask;

SynthesisResult compute(const Sweep& sweep, const SweepTask& t, int threads, std::vector<LocalResult> known = {}) {
  // Fault injection for the test that a failing rank is reported (tests/mpi/sweep_ranks.sh).
  if (const char* fail = std::getenv("SCALCAL_SWEEP_FAIL");
      fail && fmt::format("{}:{}", criterion_name(t.criterion), t.positions) == fail)
    throw std::runtime_error("failure injected by SCALCAL_SWEEP_FAIL");
  return sweep.compute(t, threads, std::move(known));
}

// The certain starts of the tasks that have many (sweep_starts.hpp), in batches taken by the ranks as they
// free up, then every rank's results on every rank. A batch that fails is left to the task's own rank,
// which runs those starts again and reports the failure as its task's.
std::vector<std::vector<LocalResult>> run_starts_ahead(const Sweep& sweep, Ranks& ranks, int threads) {
  const std::vector<commands::StartRange> ranges = commands::start_ranges(sweep);
  if (ranges.empty()) return std::vector<std::vector<LocalResult>>(sweep.tasks().size());
  std::string mine;
  ranks.open_counter();
  for (auto i = static_cast<std::size_t>(ranks.next()); i < ranges.size(); i = static_cast<std::size_t>(ranks.next())) {
    const commands::StartRange& r = ranges[i];
    const SweepTask& t = sweep.tasks()[r.task];
    try {
      mine += commands::starts_line(r, sweep.starts(t, r.first, r.count, threads)) + "\n";
    } catch (const std::exception&) {
    }
    if (ranks.rank() == 0 && progress_enabled())
      std::cerr << "sweep: rank 0 ran starts " << r.first << ".." << r.first + r.count - 1 << " of "
                << criterion_name(t.criterion) << " N = " << t.positions << "\n";
  }
  ranks.close_counter();
  return commands::known_starts(sweep, ranks.all_gather(mine));
}

// Each rank takes the next task as it frees up (a shared counter: a slow synthesis no longer holds up
// the tasks dealt after it); rank 0 gathers and shows them in task order, so the output is the
// single-process run's. A task that throws is reported with its rank, never dropped silently. Results
// travel as the result file's lines (doubles with 17 digits: rank 0 reads back the same bits).
int run_ranks(const Sweep& sweep, Ranks& ranks, std::optional<RowSink>& sink) {
  const auto& tasks = sweep.tasks();
  const int threads = sweep.request().threads == 0 ? 1 : sweep.request().threads;  // ranks share the cores
  std::vector<std::vector<LocalResult>> known = run_starts_ahead(sweep, ranks, threads);
  std::string mine;
  ranks.open_counter();
  for (auto k = static_cast<std::size_t>(ranks.next()); k < tasks.size(); k = static_cast<std::size_t>(ranks.next())) {
    try {
      mine += commands::result_line(sweep, k, compute(sweep, tasks[k], threads, std::move(known[k]))) + "\n";
    } catch (const std::exception& e) {
      mine += commands::error_line(sweep, k, e.what()) + "\n";
    }
    if (ranks.rank() == 0 && progress_enabled())
      std::cerr << "sweep: rank 0 finished " << criterion_name(tasks[k].criterion) << " N = " << tasks[k].positions
                << "\n";
  }
  ranks.close_counter();
  const std::vector<std::string> texts = ranks.gather(mine);
  if (ranks.rank() != 0) return 0;
  std::vector<std::optional<SynthesisResult>> results(tasks.size());
  std::vector<std::string> failures;
  for (std::size_t r = 0; r < texts.size(); ++r) {
    std::istringstream lines(texts[r]);
    for (std::string line; std::getline(lines, line);) {
      const commands::TaskLine t = commands::read_task_line(sweep, line);
      if (t.result)
        results[t.task] = t.result;
      else
        failures.push_back(fmt::format("rank {} failed on {} N = {}: {}", r, criterion_name(tasks[t.task].criterion),
                                       tasks[t.task].positions, t.error));
    }
  }
  for (std::size_t k = 0; k < tasks.size(); ++k)
    if (results[k]) sink->add(sweep.row(tasks[k], *results[k]));
  for (const auto& f : failures) std::cerr << "scalcal sweep: " << f << "\n";
  return failures.empty() ? 0 : 1;
}

// The tasks of one shard (all of them without --shard), each appended to the --results file as it
// finishes; those the file already holds are shown from it, not run again (a killed run resumes).
int run_shard(const Sweep& sweep, const commands::Values& v, std::optional<ResultAppender>& results, RowSink& sink) {
  const commands::Shard shard = v.given("--shard") ? *commands::read_shard(v.text("--shard")) : commands::Shard{};
  int status = 0;
  for (const std::size_t k : commands::shard_tasks(sweep, shard)) {
    const SweepTask& t = sweep.tasks()[k];
    if (results) {
      if (const auto done = results->find(k)) {
        sink.add(sweep.row(t, *done));
        continue;
      }
    }
    SynthesisResult r;
    try {
      r = compute(sweep, t, sweep.request().threads);
    } catch (const std::runtime_error& e) {
      if (!results) throw;
      // A shard keeps what it finished; the failure is said and the next run of the shard retries it.
      std::cerr << "scalcal sweep: " << criterion_name(t.criterion) << " N = " << t.positions << ": " << e.what()
                << " (the results so far are in " << v.text("--results") << "; run again to resume)\n";
      status = 1;
      break;
    }
    if (results) results->append(commands::result_line(sweep, k, r));
    sink.add(sweep.row(t, std::move(r)));
  }
  return status;
}

int run(const commands::Values& v) {
  const Sweep sweep(commands::sweep_request(v));
  if (v.given("--shard") && !v.given("--results"))
    throw UsageError("sweep: --shard needs --results FILE (the shard's results, for `scalcal merge`)");
  print_warnings("sweep", sweep.warnings());
  Ranks& ranks = Ranks::world();
  if (ranks.size() > 1 && (v.given("--shard") || v.given("--results")))
    throw UsageError("sweep: --shard and --results are for single processes (an MPI run gathers on rank 0)");
  std::optional<RowSink> sink;
  // The result file first: one of another sweep, or unwritable, is said before any row is shown.
  std::optional<ResultAppender> results;
  if (v.given("--results")) results.emplace(v.text("--results"), sweep);
  if (ranks.rank() == 0) sink.emplace(sweep, v);
  const int status = ranks.size() == 1 ? run_shard(sweep, v, results, *sink) : run_ranks(sweep, ranks, sink);
  if (sink) sink->close();
  return status;
}

const Registration reg(commands::sweep_table(), run);

}  // namespace
}  // namespace scalcal::cli
