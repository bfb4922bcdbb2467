// Which limits a jig reaches, decided exactly from its face normals (jig_limits.hpp).
#include "symbolic/jig_limits.hpp"

#include <stdexcept>

#include "symbolic/limits.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

namespace {

long double_factorial(int n) { return n <= 1 ? 1 : n * double_factorial(n - 2); }

ex total_weight(const std::vector<WeightedPoint>& points) {
  ex n = 0;
  for (const auto& w : points) n += w.weight;
  return GiNaC::expand(n);
}

}  // namespace

ex sphere_moment(int a, int b, int c) {
  if (a % 2 || b % 2 || c % 2) return 0;
  return ex(double_factorial(a - 1) * double_factorial(b - 1) * double_factorial(c - 1)) /
         ex(double_factorial(a + b + c + 1));
}

bool is_design(const std::vector<WeightedPoint>& points, int t) {
  const ex n = total_weight(points);
  const MomentFunction moment = point_moments(points);
  for (int d = 1; d <= t; ++d)
    for (int a = 0; a <= d; ++a)
      for (int b = 0; a + b <= d; ++b)
        if (!is_zero_exact(moment(a, b, d - a - b) - n * sphere_moment(a, b, d - a - b))) return false;
  return true;
}

ex fourth_moment_norm(const std::vector<WeightedPoint>& points) {
  const ex n = total_weight(points);
  ex sum = 0;
  for (const auto& u : points)
    for (const auto& v : points) {
      // Each normal carries one common radical factor at most (1/sqrt(1 + phi^2)), so the fourth power
      // of a dot product is free of nested radicals once expanded.
      const ex dot = u.eta[0] * v.eta[0] + u.eta[1] * v.eta[1] + u.eta[2] * v.eta[2];
      sum += u.weight * v.weight * GiNaC::expand(GiNaC::pow(dot, 4));
    }
  return canonical(sum / (n * n));
}

ex symmetric_fourth_moment_norm(const ex& b) { return GiNaC::expand(ex(1) / 3 - 4 * b + 30 * b * b); }

JigAnalysis analyse_jig(const std::vector<WeightedPoint>& normals) {
  JigAnalysis out;
  out.four_design = is_design(normals, 4);
  const ex n = total_weight(normals);
  try {
    out.at_default = exact_criteria(moment_matrix(normals), n);
  } catch (const std::invalid_argument&) {
    out.at_default.reset();
  }
  for (const CriterionKind c : kCriteria) {
    JigLimitClaim& claim = out.claim[static_cast<std::size_t>(c.index())];
    if (!out.at_default) {
      claim = {"never reached", true, "rank-deficient in every orientation: rank does not change under rotation"};
      continue;
    }
    if (!has_symbolic_limit(c)) {
      claim = {"not decided exactly", false, "no known limit for criterion " + std::string(criterion_name(c))};
      continue;
    }
    const ex limit = symbolic_limit(c).value;
    const ExactValue* v = out.at_default->of(c);
    const bool exact_value = v && v->exact && v->resolved();
    const bool equal = exact_value && is_zero_exact(v->value() - limit);
    if (out.four_design) {
      if (exact_value)
        claim =
            equal ? JigLimitClaim{"reached in every orientation", true,
                                  "a 4-design: the sphere's moments up to degree 4 in every orientation, "
                                  "and its exact value is the limit"}
                  : JigLimitClaim{"never reached", true,
                                  "a 4-design: the same value " + v->str() + " in every orientation, above the limit"};
      else
        claim = {"not decided exactly", false, "a 4-design, but the criterion has no closed form here"};
      continue;
    }
    if (c == CriterionKind::D) {
      claim = {"never reached", true,
               "not a 4-design, in any orientation (rotations keep designs); equality in D needs one"};
      continue;
    }
    if (equal) {
      claim = {"reached at the default mounting", true, "exact value at the default mounting equals the limit"};
      continue;
    }
    if (c == CriterionKind::A) {
      const ex target = symmetric_fourth_moment_norm(symbolic_limit(c).b);
      const ex own = fourth_moment_norm(normals);
      if (!is_zero_exact(own - target)) {
        claim = {"never reached", true,
                 "the A optimum's moment matrix is unique, and its fourth-moment norm " + canonical_text(target) +
                     " differs from the jig's " + canonical_text(own) + " in every orientation"};
        continue;
      }
    }
    claim = {"not decided exactly", false, "depends on the orientation; see the numerical best mounting"};
  }
  return out;
}

}  // namespace scalcal::symbolic
