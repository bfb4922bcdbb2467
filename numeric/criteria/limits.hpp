// The N -> infinity limits of the normalised criteria: their infimum over all probability
// measures on the sphere, a lower bound for every finite program (proofs/ proves each one).
// By the 48-element symmetry of the axes an optimal measure is symmetric, so its moments up to
// order four are fixed by b = E[x^2 y^2] (with E[x^4] = 1/3 - 2b, odd moments zero).
#pragma once
#include <cmath>
#include <string_view>

#include "numeric/criteria/criterion_kind.hpp"

namespace scalcal {

template <class Scalar>
struct CriterionLimitTpl {
  Scalar value;          // infimum of the normalised criterion
  Scalar moment_b;       // E[x^2 y^2] of an optimal symmetric measure
  std::string_view exact;  // the value in closed form
};

// D: N^9 det K >= 61509375/4 (uniform measure, b = 1/15).
// A: N trace K >= 45 + 18 sqrt 2 (b = 1/(9 + 3 sqrt 2)).
// E: N lambda_max(K) >= 12 (b = 1/12).
// S: N max_r K(r,r) >= 6 + 3 sqrt 3 (b = (2 - sqrt 3)/3).
template <class Scalar>
CriterionLimitTpl<Scalar> criterion_limit(CriterionKind c) {
  using std::sqrt;
  const Scalar s2 = sqrt(Scalar(2)), s3 = sqrt(Scalar(3));
  switch (c) {
    case CriterionKind::D: return {Scalar(61509375) / Scalar(4), Scalar(1) / Scalar(15), "61509375/4"};
    case CriterionKind::A: return {Scalar(45) + Scalar(18) * s2, Scalar(1) / (Scalar(9) + Scalar(3) * s2), "45+18*sqrt(2)"};
    case CriterionKind::E: return {Scalar(12), Scalar(1) / Scalar(12), "12"};
    case CriterionKind::S: return {Scalar(6) + Scalar(3) * s3, (Scalar(2) - s3) / Scalar(3), "6+3*sqrt(3)"};
  }
  return {Scalar(0), Scalar(0), ""};
}

inline CriterionLimitTpl<double> criterion_limit(CriterionKind c) { return criterion_limit<double>(c); }

}  // namespace scalcal
