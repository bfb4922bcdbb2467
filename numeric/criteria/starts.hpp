// The default number of multistart starts: enough to find the global optimum for N <= 30 in every
// sweep so far (experiments/docs/sweep.md), growing by one per position beyond N = 12.
#pragma once

namespace scalcal {

constexpr int grown_starts(int base, int positions) { return positions <= 12 ? base : base + (positions - 12); }

}  // namespace scalcal
