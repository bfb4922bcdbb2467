// Evaluation under a model chosen at run time (model_evaluation.hpp).
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal {

bool ModelEvaluation::has_group(ParameterGroup g) const {
  for (ParameterGroup p : parameter_groups)
    if (p == g) return true;
  return false;
}

ModelEvaluation erase_model(const Evaluation& ev) { return erase_model<Paper9Model>(ev, ModelKind::paper9); }

ModelEvaluation evaluate(ModelKind model, const Program& program) {
  return visit_model(model, [&](auto M) {
    using Model = decltype(M);
    return erase_model<Model>(evaluate<Model>(program), model);
  });
}

}  // namespace scalcal
