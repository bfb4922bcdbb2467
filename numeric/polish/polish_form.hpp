// The polish for one criterion and model: the first-order conditions its form calls for
// (polish_kkt.hpp for the smooth and max-diagonal forms, polish_eigenvalue.hpp for the eigenvalue
// form), solved at W = 2P + 30 digits. The criterion comes in as a PolishOps (polish_ops.hpp), so
// the MPFR code is compiled once per model and form; for the paper's model in the library.
#pragma once
#include <stdexcept>
#include <string>

#include "numeric/criteria/identifiability.hpp"
#include "numeric/polish/polish_eigenvalue.hpp"
#include "numeric/polish/polish_kkt.hpp"

namespace scalcal {

// The polish of a criterion under the model, whatever its form.
template <class Model>
PolishResult polish_with(const polish_detail::PolishOps<Model>& criterion, const Program& program,
                         const PolishOptions& options) {
  if (options.digits < 1) throw std::invalid_argument("polish: the number of digits must be at least 1");
  if (program.size() < Model::kParameters)
    throw std::invalid_argument("polish: at least " + std::to_string(Model::kParameters) + " positions are needed");
  // Every form divides by the information matrix: a rank-deficient program has no first-order conditions.
  const EvaluationTpl<double, Model> ev = evaluate<Model>(program);
  if (!ev.full_rank())
    throw std::invalid_argument("polish: " + rank_deficiency(erase_model(ev, ModelKind(kModelIndex<Model>))));
  const unsigned W = static_cast<unsigned>(2 * options.digits + 30);
  polish_detail::PrecisionGuard guard(W);
  if (criterion.form == polish_detail::PolishForm::MaxEigenvalue)
    return polish_detail::polish_eigenvalue<Model>(criterion, program, options);
  return polish_detail::polish_kkt<Model>(criterion, program, options);
}

template <Criterion C, class Model = Paper9Model>
PolishResult polish(const Program& program, const PolishOptions& options) {
  return polish_with<Model>(polish_detail::polish_ops<C, Model>(), program, options);
}

}  // namespace scalcal
