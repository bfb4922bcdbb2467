// A criterion as the polish of one model sees it: its form, its derivatives in MPFR (smooth form),
// its rows (max-diagonal form) and its value from K, as plain data and function pointers. The MPFR
// templates are compiled once per model and form (for the paper's model in the library's own units)
// rather than once per criterion: D and A share the smooth KKT conditions, and a test criterion costs
// only these pointers.
#pragma once
#include <vector>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/real.hpp"

namespace scalcal::polish_detail {

enum class PolishForm { Smooth, MaxDiagonal, MaxEigenvalue };

template <class Model>
struct PolishOps {
  static constexpr int P = Model::kParameters;
  using MatP = Eigen::Matrix<Real, P, P>;
  PolishForm form = PolishForm::Smooth;
  bool (*derivatives)(const MatP& M, int n, MatrixDerivatives<Real, P>& d) = nullptr;  // smooth form
  std::vector<int> rows;                                                               // max-diagonal form
  Real (*value)(const InverseInformation<Real, P>& k, const Real& n) = nullptr;        // normalised, from K
};

template <Criterion C, class Model>
PolishOps<Model> polish_ops() {
  constexpr int P = Model::kParameters;
  PolishOps<Model> ops;
  ops.value = [](const InverseInformation<Real, P>& k, const Real& n) { return C::template value<Model>(k, n); };
  if constexpr (SmoothCriterion<C>) {
    ops.form = PolishForm::Smooth;
    ops.derivatives = &C::template derivatives<Real, P>;
  } else if constexpr (MaxDiagonalCriterion<C>) {
    ops.form = PolishForm::MaxDiagonal;
    ops.rows = C::template rows<Model>();
  } else if constexpr (MaxEigenvalueCriterion<C>) {
    ops.form = PolishForm::MaxEigenvalue;
  } else {
    static_assert(!kUnknownForm<C>, "a criterion needs one of the forms of criteria/criterion.hpp");
  }
  return ops;
}

// The normalised criterion of a program at the working precision (+infinity when rank < P).
template <class Model>
Real polish_value(const PolishOps<Model>& ops, const ProgramTpl<Real>& program) {
  const EvaluationTpl<Real, Model> ev = evaluate<Model>(program);
  if (!ev.full_rank()) return Real(INFINITY);
  return ops.value(InverseInformation<Real, Model::kParameters>{ev.K, ev.K_eigenvalues}, Real(program.size()));
}

}  // namespace scalcal::polish_detail

namespace scalcal {
// evaluate<Model> in MPFR (an SVD of H): compiled once for the paper's model, in polish_value.cpp.
extern template EvaluationTpl<polish_detail::Real, Paper9Model> evaluate<Paper9Model, polish_detail::Real>(
    const ProgramTpl<polish_detail::Real>&);
}  // namespace scalcal
