// The polish for one criterion type and model: the first-order conditions its form calls for
// (polish_kkt.hpp for the smooth and max-diagonal forms, polish_eigenvalue.hpp for the eigenvalue
// form), solved at W = 2P + 30 digits.
#pragma once
#include <stdexcept>
#include <string>

#include "numeric/criteria/identifiability.hpp"
#include "numeric/polish/polish_eigenvalue.hpp"
#include "numeric/polish/polish_kkt.hpp"

namespace scalcal {

template <Criterion C, class Model = Paper9Model>
PolishResult polish(const Program& program, const PolishOptions& options) {
  if (options.digits < 1) throw std::invalid_argument("polish: the number of digits must be at least 1");
  if (program.size() < Model::kParameters)
    throw std::invalid_argument("polish: at least " + std::to_string(Model::kParameters) + " positions are needed");
  // Every form divides by the information matrix: a rank-deficient program has no first-order conditions.
  const EvaluationTpl<double, Model> ev = evaluate<Model>(program);
  if (!ev.full_rank()) throw std::invalid_argument("polish: " + rank_deficiency(erase_model(ev, ModelKind(kModelIndex<Model>))));
  const unsigned W = static_cast<unsigned>(2 * options.digits + 30);
  polish_detail::PrecisionGuard guard(W);
  if constexpr (MaxEigenvalueCriterion<C>) return polish_detail::polish_eigenvalue<C, Model>(program, options);
  else if constexpr (SmoothCriterion<C> || MaxDiagonalCriterion<C>) return polish_detail::polish_kkt<C, Model>(program, options);
  else static_assert(!kUnknownForm<C>, "a criterion needs one of the forms of criteria/criterion.hpp");
}

}  // namespace scalcal
