// A sweep split over processes and time: `--shard I/N` runs the tasks k with k mod N = I, each finished
// task kept as one line of a keyed result file (its request on the first line), so a killed run resumes
// where it stopped and `scalcal merge` joins the shards into exactly what one process prints. Lines,
// not a whole JSON document, because a process killed mid-write leaves every earlier line whole; doubles
// are written with 17 significant digits, so what is read back is the same bits.
#pragma once
#include <cstddef>
#include <iosfwd>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "commands/core/option_table.hpp"
#include "commands/research/sweep.hpp"

namespace scalcal::commands {

struct Shard {
  int index = 0, count = 1;  // this process runs the tasks k with k mod count = index
};

// "I/N" with 0 <= I < N <= kMaxShards; nullopt otherwise.
inline constexpr int kMaxShards = 100000;
std::optional<Shard> read_shard(const std::string& text);

// The tasks of one shard, in task order.
std::vector<std::size_t> shard_tasks(const Sweep& sweep, const Shard& shard);

// The first line of a result file: the request (threads left out: the results do not depend on them).
std::string results_header(const SweepRequest& request);
// One finished task as one line (no newline), or one that failed (MPI ranks report it so).
std::string result_line(const Sweep& sweep, std::size_t task, const SynthesisResult& result);
std::string error_line(const Sweep& sweep, std::size_t task, const std::string& what);

struct TaskLine {
  std::size_t task = 0;
  std::optional<SynthesisResult> result;  // none: the task failed with `error`
  std::string error;
};
// Throws std::invalid_argument with the reason: not JSON, not a task of `sweep`, a result incomplete.
TaskLine read_task_line(const Sweep& sweep, const std::string& line);

struct ResultFile {
  std::string file;
  SweepRequest request;
  std::map<std::size_t, SynthesisResult> results;  // by task
  // The bytes up to the last whole line: a run killed mid-write leaves a partial last line, which a
  // resumed run cuts off before it appends.
  std::size_t whole_bytes = 0;
  bool partial_line = false;
};

// Reads a result file; throws InputError (file, line, reason) for a first line that is not a sweep's
// request, a line that is not a task of it, or one task recorded twice with different results.
ResultFile read_result_file(std::istream& in, const std::string& file);

// The same request, or the reason they differ ("--seed 1 against 2").
std::string request_difference(const SweepRequest& a, const SweepRequest& b);

// Every task's result in task order, from result files of one request; throws InputError naming the
// file of another request, a task recorded differently in two files, or the tasks no file holds (at
// most 10 listed, and how to run them).
std::vector<SynthesisResult> merge_results(const std::vector<ResultFile>& files, const Sweep& sweep);

// `merge --results FILE|FOLDER... [--out FILE] [--json] [--no-timing]`: the sweep the result files hold,
// printed as one process prints it (a folder: every *.jsonl in it).
const CommandTable& merge_table();

}  // namespace scalcal::commands
