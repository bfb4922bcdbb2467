// The efficiency against a limit (efficiency.hpp).
#include "numeric/criteria/efficiency.hpp"

#include <cmath>

namespace scalcal {

double efficiency(CriterionKind c, double limit, double value, int parameters) {
  const double e = limit / value;
  return visit_criterion(
      c, [e, parameters](auto C) { return kDeterminantOnly<decltype(C)> ? std::pow(e, 1.0 / parameters) : e; });
}

}  // namespace scalcal
