// `scalcal sweep` as functions: the best program for every N in a range and every criterion asked,
// with its ratio to the N -> infinity limit (the region's on a restricted bench, the model's stated
// limit for another model; none when the criterion has no known limit). The rows come one task at
// a time, so a front end can show and save each as it is found, or spread the tasks over MPI ranks.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/region/region.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::commands {

inline constexpr int kSweepMinN = 3, kSweepMaxN = 1000;

struct SweepRequest {
  int lo = 9, hi = 40;
  std::vector<CriterionKind> criteria{kCriteria.begin(), kCriteria.end()};
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;
  int starts = 0, threads = 0;
  std::uint64_t seed = 1;
};

struct SweepTask {
  CriterionKind criterion;
  int positions;
};

struct SweepRow {
  SweepTask task;
  SynthesisResult result;
  std::optional<double> limit;  // none: no known limit for the criterion (no ratio)
};

// The checked request, its region and tasks (criteria outer, N inner), and the work of one task.
class Sweep {
 public:
  // Throws UsageError for N below the model's parameters or a region under another model.
  explicit Sweep(const SweepRequest& request);
  const SweepRequest& request() const { return request_; }
  const std::vector<SweepTask>& tasks() const { return tasks_; }
  const std::optional<Region>& region() const { return region_; }
  bool restricted() const { return region_ && !region_->is_sphere(); }
  const Warnings& warnings() const { return warnings_; }

  // The synthesis of one task; `threads` overrides the request's (MPI ranks share the cores). `known`:
  // results of its first starts, run ahead by starts() (on other ranks).
  SynthesisResult compute(const SweepTask& task, int threads, std::vector<LocalResult> known = {}) const;
  // The starts every synthesis of the task runs whatever their results (none on a region, whose
  // synthesis is not split), and starts first .. first + count - 1 of it.
  int certain_starts(const SweepTask& task) const;
  std::vector<LocalResult> starts(const SweepTask& task, int first, int count, int threads) const;
  std::optional<double> limit(CriterionKind c) const;  // computed once per criterion
  SweepRow row(const SweepTask& task, SynthesisResult result) const;

 private:
  SynthesisOptions options(const SweepTask& task, int threads) const;
  SweepRequest request_;
  std::optional<Region> region_;
  std::vector<SweepTask> tasks_;
  Warnings warnings_;
  mutable std::vector<std::optional<std::optional<double>>> limits_;
};

// --positions A..B --criteria LIST [--model NAME] [--region SPEC]... [--starts K] [--seed S] [--threads T]
// [--out FILE] [--json] [--no-timing] [--shard I/N] [--results FILE]
const CommandTable& sweep_table();
SweepRequest sweep_request(const Values& values);

// One row's JSON object; timing: with `seconds`.
Json to_json(const Sweep& sweep, const SweepRow& row, bool timing);

// "N" or "A..B" with kSweepMinN <= A <= B <= kSweepMaxN; nullopt otherwise.
std::optional<std::pair<int, int>> read_positions_range(const std::string& text);
// "D,A": registered names, comma-separated; empty when any is not one.
std::vector<CriterionKind> read_criteria_list(const std::string& text);

}  // namespace scalcal::commands
