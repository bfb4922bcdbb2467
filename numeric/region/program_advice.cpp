// What a measured program is worth and what to add to it (program_advice.hpp).
#include "numeric/region/program_advice.hpp"

#include <cmath>
#include <limits>

#include "numeric/region/augment.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal {

std::array<double, 3> rms_errors(const Evaluation& ev) {
  const double root = std::sqrt(static_cast<double>(ev.positions));
  return {ev.theta_bias / root, ev.theta_scale / root, ev.theta_nonorth / root};
}

ProgramAdvice advise_program(const Program& measured, const Region& region, CriterionKind criterion, int suggest) {
  ProgramAdvice out;
  out.evaluation = evaluate(measured);
  out.criterion = criterion;
  for (auto c : kCriteria) {
    const double v = out.evaluation.value(c);
    // A registered criterion may have no known limit (the test build's I): no efficiency, NaN (null in JSON).
    out.efficiency[static_cast<std::size_t>(c.index())] = !has_limit(c)      ? std::numeric_limits<double>::quiet_NaN()
                                                          : std::isfinite(v) ? efficiency(c, limit_value(c, region), v)
                                                                             : 0.0;
  }
  if (suggest <= 0) return out;
  const AugmentedProgram a = augment_program(measured, suggest, criterion, region);
  Program prefix = measured;
  for (const Vec3& x : a.added) {
    prefix.positions.push_back(x);
    const Evaluation ev = evaluate(prefix);
    out.suggested.push_back({x, ev.value(criterion), rms_errors(ev)});
  }
  return out;
}

}  // namespace scalcal
