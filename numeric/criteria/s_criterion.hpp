// S: N max_r K(r,r), the largest single-parameter variance (the paper's Xi_sigma, Table 3's Xi_B).
#pragma once
#include <cmath>

#include "numeric/criteria/closed_form_kind.hpp"
#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/starts.hpp"

namespace scalcal {

struct SCriterion {
  static constexpr std::string_view name = "S";
  static constexpr std::string_view summary = "N max_r K(r,r)";
  static constexpr std::string_view label = "N max K(r,r)";
  static constexpr std::string_view raw_name = "max K(r,r)";
  static constexpr std::string_view raw_key = "max_diag_K";
  static constexpr ProgramSymmetry symmetry = ProgramSymmetry::SignedPermutations;
  using Form = MaxDiagonalForm;
  static constexpr ClosedFormKind closed_form = ClosedFormKind::LargestDiagonalOfK;  // symbolic/criteria.cpp
  static constexpr double scoring_seconds = 4.2e-7;  // CPU per program, paper9 at N = 12 (commands/core/work_bound)

  template <class Model>
  static std::vector<int> rows() {
    std::vector<int> all;
    for (int r = 0; r < Model::kParameters; ++r) all.push_back(r);
    return all;
  }

  template <class Model, InverseInformationView View, class Scalar>
  static Scalar value(const View& k, const Scalar& n) {
    return max_diagonal_value<SCriterion, Model>(k, n);
  }

  template <class Model, InverseInformationView View>
  static auto raw(const View& k) {
    auto out = k.diagonal(0);
    for (int r : rows<Model>())
      if (k.diagonal(r) > out) out = k.diagonal(r);
    return out;
  }

  static constexpr int default_starts(int positions) { return grown_starts(32, positions); }

  // N max K(r,r) >= 6 + 3 sqrt 3 (b = (2 - sqrt 3)/3; proofs/aes_limits.md).
  template <class Model, class Scalar>
  static std::optional<CriterionLimitTpl<Scalar>> limit() {
    using std::sqrt;
    if constexpr (std::is_same_v<Model, Paper9Model>) {
      const Scalar s3 = sqrt(Scalar(3));
      return CriterionLimitTpl<Scalar>{Scalar(6) + Scalar(3) * s3, (Scalar(2) - s3) / Scalar(3), "6+3*sqrt(3)",
                                       "proofs/aes_limits.md"};
    }
    return std::nullopt;
  }
};
static_assert(MaxDiagonalCriterion<SCriterion>);

}  // namespace scalcal
