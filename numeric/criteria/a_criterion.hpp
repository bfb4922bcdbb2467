// A: N trace K, the sum of the parameter variances. Smooth: G = -N K^2, dG = N (K dM K^2 + K^2 dM K).
#pragma once
#include <cmath>

#include <Eigen/Cholesky>

#include "numeric/criteria/closed_form_kind.hpp"
#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/dual_kind.hpp"
#include "numeric/criteria/exchange_path.hpp"
#include "numeric/criteria/starts.hpp"

namespace scalcal {

struct ACriterion {
  static constexpr std::string_view name = "A";
  static constexpr std::string_view summary = "N trace K";
  static constexpr std::string_view label = "N trace K";
  static constexpr std::string_view raw_name = "trace K";
  static constexpr std::string_view raw_key = "trace_K";
  static constexpr ProgramSymmetry symmetry = ProgramSymmetry::SignedPermutations;
  using Form = SmoothForm;
  static constexpr DualKind dual = DualKind::DiagonalSum;                  // certified limits on regions
  static constexpr ClosedFormKind closed_form = ClosedFormKind::TraceOfK;  // symbolic/criteria.cpp
  static constexpr double scoring_seconds = 3e-7;  // CPU per program, paper9 at N = 12 (commands/core/work_bound)

  template <class Model, InverseInformationView View, class Scalar>
  static Scalar value(const View& k, const Scalar& n) {
    return n * k.trace();
  }

  template <class Model, InverseInformationView View>
  static auto raw(const View& k) {
    return k.trace();
  }

  static constexpr int default_starts(int positions) { return grown_starts(32, positions); }

  // N trace K >= 45 + 18 sqrt 2 (b = 1/(9 + 3 sqrt 2); proofs/aes_limits.md).
  template <class Model, class Scalar>
  static std::optional<CriterionLimitTpl<Scalar>> limit() {
    using std::sqrt;
    if constexpr (std::is_same_v<Model, Paper9Model>) {
      const Scalar s2 = sqrt(Scalar(2));
      return CriterionLimitTpl<Scalar>{Scalar(45) + Scalar(18) * s2, Scalar(1) / (Scalar(9) + Scalar(3) * s2),
                                       "45+18*sqrt(2)", "proofs/aes_limits.md"};
    }
    return std::nullopt;
  }

  template <class Scalar, int P>
  static bool objective(const Eigen::Matrix<Scalar, P, P>& M, int n, Scalar& out) {
    Eigen::LLT<Eigen::Matrix<Scalar, P, P>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    out = Scalar(n) * llt.solve(Eigen::Matrix<Scalar, P, P>::Identity()).trace();
    return true;
  }

  // objective() at M(a) on a vertex exchange's path from its value at a = 0, in O(1)
  // (exchange_path.hpp); false where M(a) is not positive definite.
  static bool objective_along(const ExchangePath& path, int n, double at_zero, double a, double& out) {
    if (!(path.determinant_ratio(a) > 0)) return false;
    out = at_zero + n * path.trace_change(a);
    return out > 0;
  }

  template <class Scalar, int P>
  static bool derivatives(const Eigen::Matrix<Scalar, P, P>& M, int n, MatrixDerivatives<Scalar, P>& d) {
    Eigen::LLT<Eigen::Matrix<Scalar, P, P>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    d.A = llt.solve(Eigen::Matrix<Scalar, P, P>::Identity());
    d.A = (d.A + d.A.transpose()).eval() / Scalar(2);
    d.B = d.A * d.A;
    d.value = Scalar(n) * d.A.trace();
    d.G = Scalar(-n) * d.B;
    d.c = Scalar(n);
    d.same_sides = false;
    return true;
  }
};
static_assert(SmoothCriterion<ACriterion>);

}  // namespace scalcal
