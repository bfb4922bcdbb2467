// Progress of a `scalcal reproduce` run on stderr, with an estimate of the time left. The run is a
// list of stages whose weights are their measured share of the work; a stage may split its share
// into weighted parts (one per optimised N, one per region), and step() moves through a part.
#pragma once
#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace scalcal::reproduce {

enum class ProgressMode {
  off,       // --quiet: nothing on stderr
  lines,     // stderr is a log or a pipe: one line as each stage starts, no carriage returns
  terminal,  // stderr is a terminal: one line rewritten in place as the work moves
};

// What a command line asks for: off when quiet, else lines or terminal as stderr is or is not a terminal.
ProgressMode progress_mode(bool quiet, bool stderr_is_terminal);

class Progress {
 public:
  explicit Progress(ProgressMode mode, std::ostream* out = nullptr);  // out: std::cerr when null

  // The stages' names and weights (any positive scale: seconds measured on one machine), in order.
  void plan(std::vector<std::string> names, std::vector<double> weights);
  void begin_stage(std::size_t index);
  // Within the current stage: a part covering [start, start + share) of the stage's work (fractions
  // of the stage), and a label for it. A stage that never calls part() is one part.
  void part(double start, double share, const std::string& what);
  void step(long long done, long long total);  // within the current part
  void detail(const std::string& what);        // a new label for the current part (terminal only)
  void done();

  double fraction() const;  // of the whole run's work, 0 to 1
  // "about 1 min 05 s left" from the time so far and fraction(); "estimating" before any work is done.
  std::string remaining() const;

 private:
  void show(bool force);

  ProgressMode mode_;
  std::ostream& out_;
  std::vector<std::string> names_;
  std::vector<double> starts_, shares_;  // each stage's fraction of the run, cumulative and own
  std::size_t stage_ = 0;
  double part_start_ = 0, part_share_ = 1, in_part_ = 0;
  std::string what_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), shown_{};
};

// "1 min 05 s", "42 s".
std::string duration_text(double seconds);

}  // namespace scalcal::reproduce
