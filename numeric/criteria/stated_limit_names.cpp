// The registered models' stated limits name registered criteria, each once (stated_limit_names.hpp): checked when
// this unit compiles, so a model whose limit names no criterion stops the build.
#include "numeric/criteria/stated_limit_names.hpp"

#include "numeric/model/registry.hpp"

namespace scalcal {
namespace {

template <class... Ms>
consteval bool every_model_names_criteria(TypeList<Ms...>) {
  return (stated_limits_name_criteria<Ms>() && ...);
}
static_assert(every_model_names_criteria(RegisteredModels{}),
              "a registered model states a limit for a criterion that is not registered, or two for one");

}  // namespace
}  // namespace scalcal
