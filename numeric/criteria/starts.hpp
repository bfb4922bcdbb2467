// The default number of multistart starts: enough to find the global optimum for N <= 30 in every
// sweep so far (experiments/docs/sweep.md), growing by one per position beyond N = 12.
#pragma once

namespace scalcal {

constexpr int grown_starts(int base, int positions) { return positions <= 12 ? base : base + (positions - 12); }

// The starts that always run before the adaptive rule (synthesis/stopping_rule.hpp) may end a
// multistart under Model: C::minimum_starts<Model>(N) where the criterion knows a deceptive N, else none.
template <class C, class Model>
constexpr int minimum_starts(int positions) {
  if constexpr (requires { C::template minimum_starts<Model>(positions); })
    return C::template minimum_starts<Model>(positions);
  else
    return 0;
}

}  // namespace scalcal
