// A sweep's result file as a run writes it (`sweep --results FILE`): the tasks a previous run of the
// same request finished are read back, a line a killed run left half-written is cut off, and each task
// finished now is appended and flushed at once, so a kill loses at most the task under way.
#pragma once
#include <fstream>
#include <optional>
#include <string>

#include "commands/research/sweep_shards.hpp"

namespace scalcal::cli {

class ResultAppender {
 public:
  // Throws InputError for a file of another sweep (naming what differs) or not a result file;
  // OutputError when it cannot be written.
  ResultAppender(const std::string& path, const commands::Sweep& sweep);
  std::optional<SynthesisResult> find(std::size_t task) const;
  void append(const std::string& line);  // one result_line; flushed and checked

 private:
  std::string path_;
  commands::ResultFile done_;
  std::ofstream out_;
};

}  // namespace scalcal::cli
