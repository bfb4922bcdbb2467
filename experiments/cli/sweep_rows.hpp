// The rows of a sweep as `scalcal sweep` shows and saves them: the table or JSON on standard output and
// the --out CSV, each row as it comes. `sweep` and `merge` share it, so a merged sweep prints what one
// process prints.
#pragma once
#include <optional>

#include "commands/research/sweep.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {

// Shows and saves each row as it comes (--json: all at close()).
class RowSink {
 public:
  RowSink(const commands::Sweep& sweep, const commands::Values& v);
  void add(const commands::SweepRow& row);
  void close();

 private:
  const commands::Sweep& sweep_;
  bool json_, timing_;
  std::optional<OutputFile> file_;
  std::optional<CriterionKind> announced_;
  commands::Json all_ = commands::Json::array();
};

}  // namespace scalcal::cli
