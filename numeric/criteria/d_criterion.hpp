// D: the generalised variance N^P det K. Smooth; solvers minimise log D = P log N - log det M,
// which is scale-free and invariant under every rotation and reflection of the program.
#pragma once
#include <cmath>

#include <Eigen/Cholesky>

#include "numeric/criteria/closed_form_kind.hpp"
#include "numeric/criteria/criterion.hpp"
#include "numeric/criteria/dual_kind.hpp"
#include "numeric/criteria/exchange_path.hpp"
#include "numeric/criteria/starts.hpp"

namespace scalcal {

struct DCriterion {
  static constexpr std::string_view name = "D";
  static constexpr std::string_view summary = "N^P det K";
  static constexpr std::string_view label = "N^P det K";
  static constexpr std::string_view raw_name = "det K";
  static constexpr std::string_view raw_key = "det_K";
  static constexpr ProgramSymmetry symmetry = ProgramSymmetry::Orthogonal;
  using Form = SmoothForm;
  static constexpr DualKind dual = DualKind::Determinant;                              // certified limits on regions
  static constexpr ClosedFormKind closed_form = ClosedFormKind::PowerOverDeterminant;  // symbolic/criteria.cpp
  static constexpr double scoring_seconds = 0.6e-7;  // CPU per program, paper9 at N = 12 (commands/core/work_bound)
  // Its value is N^P / det M: random search factors four programs side by side and stops early
  // when none can win (synthesis/random_search_kernel.hpp).
  static constexpr bool determinant_only = true;

  template <class Model, InverseInformationView View, class Scalar>
  static Scalar value(const View& k, const Scalar& n) {
    Scalar np(1);
    for (int i = 0; i < k.parameters(); ++i) np *= n;
    return np * k.det();
  }

  template <class Model, InverseInformationView View>
  static auto raw(const View& k) {
    return k.det();
  }

  static constexpr int default_starts(int positions) { return grown_starts(16, positions); }

  // N^9 det K >= 61509375/4 (uniform measure, b = 1/15; proofs/d_limit.md).
  template <class Model, class Scalar>
  static std::optional<CriterionLimitTpl<Scalar>> limit() {
    if constexpr (std::is_same_v<Model, Paper9Model>)
      return CriterionLimitTpl<Scalar>{Scalar(61509375) / Scalar(4), Scalar(1) / Scalar(15), "61509375/4",
                                       "proofs/d_limit.md"};
    return std::nullopt;
  }

  template <class Scalar, int P>
  static bool objective(const Eigen::Matrix<Scalar, P, P>& M, int n, Scalar& out) {
    Eigen::LLT<Eigen::Matrix<Scalar, P, P>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    out = log_d(llt, n);
    return true;
  }

  // objective() at M(a) on a vertex exchange's path from its value at a = 0: log det M(a) = log det M +
  // log det T(a) (exchange_path.hpp); false where M(a) is not positive definite.
  static bool objective_along(const ExchangePath& path, int, double at_zero, double a, double& out) {
    using std::log;
    const double r = path.determinant_ratio(a);
    if (!(r > 0)) return false;
    out = at_zero - log(r);
    return true;
  }

  // G = -K, dG = K dM K.
  template <class Scalar, int P>
  static bool derivatives(const Eigen::Matrix<Scalar, P, P>& M, int n, MatrixDerivatives<Scalar, P>& d) {
    Eigen::LLT<Eigen::Matrix<Scalar, P, P>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    d.value = log_d(llt, n);
    d.A = llt.solve(Eigen::Matrix<Scalar, P, P>::Identity());
    d.A = (d.A + d.A.transpose()).eval() / Scalar(2);
    d.B = d.A;
    d.G = -d.A;
    d.c = Scalar(1) / Scalar(2);
    d.same_sides = true;
    return true;
  }

 private:
  template <class Scalar, int P>
  static Scalar log_d(const Eigen::LLT<Eigen::Matrix<Scalar, P, P>>& llt, int n) {
    using std::log;
    Scalar logdet(0);
    for (int i = 0; i < P; ++i) logdet += log(llt.matrixLLT()(i, i));
    return Scalar(P) * log(Scalar(n)) - Scalar(2) * logdet;
  }
};
static_assert(SmoothCriterion<DCriterion>);

}  // namespace scalcal
