// One synthesis's starts as MPI ranks exchange them (commands/research/sweep_starts): which ranges are run
// ahead, a line that reads back as the same bits (infinities and NaN included), and known starts that stop
// at a gap. The ranks' own equality with one process is tests/mpi/sweep_ranks.sh.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "commands/research/sweep_starts.hpp"

namespace scalcal::commands {
namespace {

Sweep sweep_of(int lo, int hi, std::vector<CriterionKind> criteria, int starts = 0) {
  SweepRequest q;
  q.lo = lo;
  q.hi = hi;
  q.criteria = std::move(criteria);
  q.starts = starts;
  return Sweep(q);
}

LocalResult start(double value, int positions, double x) {
  LocalResult r;
  r.value = value;
  r.summary.termination = Termination::not_converged;
  r.summary.iterations = 17;
  for (int i = 0; i < positions; ++i) r.program.positions.emplace_back(x, -x / 3, 0.1 * i);
  return r;
}

// E at N = 9 runs 256 starts whatever they find (its trap), so they go ahead in 32 ranges of 8; D at
// N = 9, 10 and E at N = 10 make only their first batch of 8 for certain, which is their own rank's work.
TEST(SweepStarts, RangesAreTheCertainStartsBeyondOneBatch) {
  const Sweep sweep = sweep_of(9, 10, {CriterionKind::D, CriterionKind::E});
  const std::vector<StartRange> ranges = start_ranges(sweep);
  ASSERT_EQ(ranges.size(), 32u);
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    EXPECT_EQ(ranges[i].task, 2u);  // tasks: D 9, D 10, E 9, E 10
    EXPECT_EQ(ranges[i].first, static_cast<int>(8 * i));
    EXPECT_EQ(ranges[i].count, 8);
  }
  // Forced: 20 starts of every task, in ranges of 8, 8 and 4.
  const std::vector<StartRange> forced = start_ranges(sweep_of(9, 9, {CriterionKind::A}, 20));
  ASSERT_EQ(forced.size(), 3u);
  EXPECT_EQ(forced[2].first, 16);
  EXPECT_EQ(forced[2].count, 4);
}

TEST(SweepStarts, LinesReadBackAsTheSameBits) {
  const Sweep sweep = sweep_of(9, 10, {CriterionKind::D});
  const std::vector<LocalResult> results = {start(12.25, 10, 1.0 / 3),
                                            start(std::numeric_limits<double>::infinity(), 10, 0.1),
                                            start(std::nan(""), 10, -2.5e-300)};
  const StartsLine back = read_starts_line(sweep, starts_line({1, 16, 3}, results));
  EXPECT_EQ(back.range.task, 1u);
  EXPECT_EQ(back.range.first, 16);
  ASSERT_EQ(back.results.size(), 3u);
  EXPECT_EQ(back.results[0].value, 12.25);
  EXPECT_TRUE(std::isinf(back.results[1].value));
  EXPECT_TRUE(std::isnan(back.results[2].value));
  for (std::size_t s = 0; s < 3; ++s) {
    EXPECT_EQ(back.results[s].program.positions, results[s].program.positions);
    EXPECT_EQ(back.results[s].summary.iterations, 17);
    EXPECT_EQ(back.results[s].summary.termination, Termination::not_converged);
  }
  EXPECT_THROW(read_starts_line(sweep, "5 0 1 0 0 1.0"), std::invalid_argument);            // no task 5
  EXPECT_THROW(read_starts_line(sweep, "0 0 1 0 0 0x1p+0 0x1p+0"), std::invalid_argument);  // cut short
  const std::string line = starts_line({0, 0, 1}, {start(1.0, 9, 0.5)});
  EXPECT_THROW(read_starts_line(sweep, line + " 0x1p+0"), std::invalid_argument);  // one number too many
}

// Ranges of task 0 at 0 and 16 (8 missing: its rank failed) and of task 1 at 0: task 0 knows starts 0..7
// only, since the run would otherwise take start 16 as start 8.
TEST(SweepStarts, KnownStartsStopAtAGap) {
  const Sweep sweep = sweep_of(9, 10, {CriterionKind::D});
  std::vector<LocalResult> eight(8, start(3.0, 9, 0.5)), four(4, start(4.0, 10, 0.5));
  const std::string rank0 = starts_line({0, 16, 8}, eight) + "\n" + starts_line({1, 0, 4}, four) + "\n";
  const std::string rank1 = starts_line({0, 0, 8}, eight) + "\n";
  const auto known = known_starts(sweep, {rank0, rank1});
  ASSERT_EQ(known.size(), 2u);
  EXPECT_EQ(known[0].size(), 8u);
  EXPECT_EQ(known[1].size(), 4u);
  EXPECT_EQ(known[1][3].value, 4.0);
}

}  // namespace
}  // namespace scalcal::commands
