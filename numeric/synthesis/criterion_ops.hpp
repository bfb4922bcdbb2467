// A criterion as the solvers of one model see it at run time: its form and the few functions that
// form needs, as plain function pointers. The solvers are compiled once per model instead of once
// per criterion and model: D and A (both SmoothForm) share Newton, L-BFGS and Ipopt, and a test
// criterion costs only these pointers. Each pointer is called once per step on P x P matrices, so
// the hot loops over the positions stay fixed-size and inline.
#pragma once
#include <optional>
#include <string_view>
#include <vector>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/criteria/starts.hpp"

namespace scalcal {

// d phi = tr(G dM), dG = c (A dM B + B dM A) of a smooth criterion, and its objective alone.
template <class Scalar, int P>
struct SmoothOps {
  using MatP = Eigen::Matrix<Scalar, P, P>;
  bool (*objective)(const MatP& M, int n, Scalar& out) = nullptr;
  bool (*derivatives)(const MatP& M, int n, MatrixDerivatives<Scalar, P>& d) = nullptr;
};

template <SmoothCriterion C, class Scalar, int P>
SmoothOps<Scalar, P> smooth_ops() {
  return {&C::template objective<Scalar, P>, &C::template derivatives<Scalar, P>};
}

enum class CriterionForm { Smooth, MaxDiagonal, MaxEigenvalue };

template <class Model>
struct CriterionOps {
  static constexpr int P = Model::kParameters;
  std::string_view name;
  CriterionForm form = CriterionForm::Smooth;
  ProgramSymmetry symmetry = ProgramSymmetry::SignedPermutations;
  std::optional<CriterionKind> kind;  // registered criteria only (the exchange takes a CriterionKind)
  int (*default_starts)(int positions) = nullptr;
  int (*minimum_starts)(int positions) = nullptr;
  // The normalised value from K (its eigenvalues ascending) and N.
  double (*value)(const InverseInformation<double, P>& k, double n) = nullptr;
  SmoothOps<double, P> smooth;  // SmoothForm
  std::vector<int> rows;        // MaxDiagonalForm: the rows r of N K(r,r)
};

namespace detail {
template <class C>
constexpr std::optional<CriterionKind> registered_kind() {
  if constexpr (detail::index_in<C>(RegisteredCriteria{}) >= 0)
    return CriterionKind::of<C>();
  else
    return std::nullopt;
}
}  // namespace detail

template <Criterion C, class Model = Paper9Model>
CriterionOps<Model> criterion_ops() {
  constexpr int P = Model::kParameters;
  CriterionOps<Model> ops;
  ops.name = C::name;
  ops.symmetry = C::symmetry;
  ops.kind = detail::registered_kind<C>();
  ops.default_starts = [](int n) { return C::default_starts(n); };
  ops.minimum_starts = [](int n) { return minimum_starts<C, Model>(n); };
  ops.value = [](const InverseInformation<double, P>& k, double n) { return C::template value<Model>(k, n); };
  if constexpr (SmoothCriterion<C>) {
    ops.form = CriterionForm::Smooth;
    ops.smooth = smooth_ops<C, double, P>();
  } else if constexpr (MaxDiagonalCriterion<C>) {
    ops.form = CriterionForm::MaxDiagonal;
    ops.rows = C::template rows<Model>();
  } else if constexpr (MaxEigenvalueCriterion<C>) {
    ops.form = CriterionForm::MaxEigenvalue;
  } else {
    static_assert(!kUnknownForm<C>, "a criterion needs one of the forms of criteria/criterion.hpp");
  }
  return ops;
}

// The normalised criterion of a program (+infinity when rank < P): criterion_value<C, Model>.
template <class Model>
double criterion_value(const CriterionOps<Model>& ops, const Program& program) {
  const EvaluationTpl<double, Model> ev = evaluate<Model>(program);
  if (!ev.full_rank()) return std::numeric_limits<double>::infinity();
  return ops.value(InverseInformation<double, Model::kParameters>{ev.K, ev.K_eigenvalues},
                   static_cast<double>(program.size()));
}

}  // namespace scalcal
