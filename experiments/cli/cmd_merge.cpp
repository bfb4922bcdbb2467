// `scalcal merge --results FILE|FOLDER... [--out FILE] [--json] [--no-timing]`: the shards of a sweep
// (`sweep --shard I/N --results FILE`), joined and printed as one process prints the whole sweep, after
// checking that they are of one request and hold every task (commands/research/sweep_shards.hpp).
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "commands/research/sweep_shards.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/sweep_rows.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

// The files named, a folder's *.jsonl in name order.
std::vector<std::string> result_paths(const std::vector<std::string>& given) {
  std::vector<std::string> out;
  for (const auto& g : given) {
    if (!std::filesystem::is_directory(g)) {
      out.push_back(g);
      continue;
    }
    std::vector<std::string> inside;
    for (const auto& e : std::filesystem::directory_iterator(g))
      if (e.is_regular_file() && e.path().extension() == ".jsonl") inside.push_back(e.path().string());
    if (inside.empty()) throw InputError(g, 0, "a folder without result files (*.jsonl)");
    std::sort(inside.begin(), inside.end());
    out.insert(out.end(), inside.begin(), inside.end());
  }
  return out;
}

int run(const commands::Values& v) {
  std::vector<commands::ResultFile> files;
  for (const auto& path : result_paths(v.list("--results"))) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, "cannot be read");
    files.push_back(commands::read_result_file(in, path));
  }
  const commands::Sweep sweep(files.front().request);
  const std::vector<SynthesisResult> results = commands::merge_results(files, sweep);
  print_warnings("merge", sweep.warnings());
  RowSink sink(sweep, v);
  for (std::size_t k = 0; k < results.size(); ++k) sink.add(sweep.row(sweep.tasks()[k], results[k]));
  sink.close();
  return 0;
}

const Registration reg(commands::merge_table(), run);

}  // namespace
}  // namespace scalcal::cli
