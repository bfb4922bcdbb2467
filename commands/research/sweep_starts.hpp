// One synthesis's starts split among MPI ranks: a task whose every run makes many starts (E at N = 9:
// 256, the criterion's minimum there) would hold one rank while the others idle, so its certain starts
// are run ahead in batches on whichever rank is free, exchanged as lines of text, and handed to the
// rank that finishes the task (SynthesisOptions::known_starts). Each start is a function of its index
// alone, so the result is the single process's, bit for bit.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "commands/research/sweep.hpp"

namespace scalcal::commands {

// Starts first .. first + count - 1 of task `task`.
struct StartRange {
  std::size_t task = 0;
  int first = 0, count = 0;
};

// The ranges worth running ahead: the certain starts of every task that has more than one batch of them
// (StoppingRule::batch), in ranges of one batch, tasks in order.
std::vector<StartRange> start_ranges(const Sweep& sweep);

// A range's results as one line (no newline): the range, then each start's termination, iterations,
// value and coordinates, doubles as hexadecimal floats (exact, infinities and NaN included). A start's
// message is not carried: the synthesis writes the best start's message itself.
std::string starts_line(const StartRange& range, const std::vector<LocalResult>& results);

struct StartsLine {
  StartRange range;
  std::vector<LocalResult> results;
};
// Throws std::invalid_argument naming what is wrong with the line (not a range of `sweep`'s tasks, a
// start cut short).
StartsLine read_starts_line(const Sweep& sweep, const std::string& line);

// Every task's known starts from the ranks' texts (lines of starts_line): for task k, the results of
// starts 0, 1, ... as far as its ranges run without a gap.
std::vector<std::vector<LocalResult>> known_starts(const Sweep& sweep, const std::vector<std::string>& texts);

}  // namespace scalcal::commands
