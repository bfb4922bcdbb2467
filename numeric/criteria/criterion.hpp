// What a criterion is: a small value type with its name, its value from K, the symmetry it is
// invariant under, its form (which tells the solvers what else it must supply) and its limit.
// The solvers are written per form, never per criterion; a missing piece is a compile error.
// Adding one: numeric/criteria/ADDING_A_CRITERION.md.
#pragma once
#include <concepts>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

#include "numeric/criteria/inverse_information.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/program/program_symmetry.hpp"

namespace scalcal {

// The forms the solvers know:
//  SmoothForm:        phi(M) is smooth; the criterion gives objective() and derivatives()
//                     (d phi = tr(G dM), dG = c (A dM B + B dM A)); Newton, Ipopt and the polish use them.
//  MaxDiagonalForm:   max over rows r of N K(r,r), r in rows<Model>(): an epigraph for Ipopt and an
//                     active set for the polish.
//  MaxEigenvalueForm: N lambda_max(K) = N / lambda_min(M): an eigenvalue constraint M/N - sI = LL^T
//                     for Ipopt and the multiple-eigenvalue conditions for the polish.
struct SmoothForm {};
struct MaxDiagonalForm {};
struct MaxEigenvalueForm {};

// The exact N -> infinity limit of a normalised criterion (the infimum over all measures on the
// sphere; proofs/ proves each), with E[x^2 y^2] of an optimal symmetric measure.
template <class Scalar>
struct CriterionLimitTpl {
  Scalar value;
  Scalar moment_b;
  std::string_view exact;    // the value in closed form
  std::string_view theorem;  // the document that proves it
};

// d phi = tr(G dM) and dG = c (A dM B + B dM A): all a solver over the positions needs of a smooth
// criterion of the information matrix M.
template <class Scalar, int P>
struct MatrixDerivatives {
  Scalar value{};
  Eigen::Matrix<Scalar, P, P> G, A, B;
  Scalar c{};
  bool same_sides = false;  // A == B: the Hessian needs half the products
};

namespace criterion_check {
using View = InverseInformation<double, 9>;
using M9 = Eigen::Matrix<double, 9, 9>;
}  // namespace criterion_check

// A criterion names itself for every report: `name` ("D"), `summary` (one line for help texts),
// `label` (its normalised form in tables, "N^P det K" with P the model's parameter count) and its
// unnormalised value `raw` (det K) with `raw_name` ("det K") and `raw_key` (the JSON key, "det_K").
template <class C>
concept Criterion = requires(const criterion_check::View& k) {
  { C::name } -> std::convertible_to<std::string_view>;
  { C::summary } -> std::convertible_to<std::string_view>;
  { C::label } -> std::convertible_to<std::string_view>;
  { C::raw_name } -> std::convertible_to<std::string_view>;
  { C::raw_key } -> std::convertible_to<std::string_view>;
  { C::template raw<Paper9Model>(k) } -> std::convertible_to<double>;
  { C::symmetry } -> std::convertible_to<ProgramSymmetry>;
  typename C::Form;
  { C::template value<Paper9Model>(k, 18.0) } -> std::convertible_to<double>;
  { C::default_starts(18) } -> std::convertible_to<int>;
  { C::template limit<Paper9Model, double>() } -> std::same_as<std::optional<CriterionLimitTpl<double>>>;
};

template <class C>
concept SmoothCriterion = Criterion<C> && std::same_as<typename C::Form, SmoothForm> &&
    requires(const criterion_check::M9& M, double& f, MatrixDerivatives<double, 9>& d) {
  { C::objective(M, 18, f) } -> std::same_as<bool>;    // the solvers' objective (log D for D)
  { C::derivatives(M, 18, d) } -> std::same_as<bool>;  // false: M not positive definite
};

template <class C>
concept MaxDiagonalCriterion = Criterion<C> && std::same_as<typename C::Form, MaxDiagonalForm> && requires {
  { C::template rows<Paper9Model>() } -> std::same_as<std::vector<int>>;
};

// N max K(r,r) over the rows a MaxDiagonalForm criterion names: its value, written once.
template <class C, class Model, InverseInformationView View, class Scalar>
Scalar max_diagonal_value(const View& k, const Scalar& n) {
  const std::vector<int> rows = C::template rows<Model>();
  Scalar out = k.diagonal(rows.front());
  for (int r : rows)
    if (k.diagonal(r) > out) out = k.diagonal(r);
  return n * out;
}

template <class C>
concept MaxEigenvalueCriterion = Criterion<C> && std::same_as<typename C::Form, MaxEigenvalueForm>;

// A criterion whose value is N^P / det M may say so (static constexpr bool determinant_only = true)
// and gets random search's batched early-exit path.
template <class C>
inline constexpr bool kDeterminantOnly = requires {
  requires C::determinant_only;
};

template <class C>
inline constexpr bool kUnknownForm = !(SmoothCriterion<C> || MaxDiagonalCriterion<C> || MaxEigenvalueCriterion<C>);

}  // namespace scalcal
