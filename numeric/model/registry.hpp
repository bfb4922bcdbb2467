// The registered calibration models: one line each in RegisteredModels. A ModelKind is a runtime
// handle (an index into that list) for the CLI and for results; visit_model() turns it back into
// the model's type, the one place where the CLI's --model meets the templated core.
#pragma once
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "numeric/model/axis6.hpp"
#include "numeric/model/bias3.hpp"
#include "numeric/model/cubic12.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/model/type_list.hpp"

namespace scalcal {

// Every entry must be a CalibrationModel (model.hpp): a missing piece is a compile error here.
template <CalibrationModel... Ms>
using ModelList = TypeList<Ms...>;

using RegisteredModels = ModelList<Paper9Model, Axis6Model, Bias3Model, Cubic12Model>;

class ModelKind {
 public:
  constexpr explicit ModelKind(int index) : index_(index) {}
  constexpr int index() const { return index_; }
  constexpr bool operator==(const ModelKind&) const = default;
  static const ModelKind paper9;

 private:
  int index_;
};
inline constexpr ModelKind ModelKind::paper9 = ModelKind(0);

inline constexpr int kModelCount = RegisteredModels::size;

// The ModelKind index of a model type; -1 for a model that is not registered (one a test defines).
template <class M>
inline constexpr int kModelIndex = detail::index_in<M>(RegisteredModels{});

namespace detail {
template <int P, class First, class... Ms>
auto model_with_parameters(TypeList<First, Ms...>) {
  if constexpr (First::kParameters == P)
    return First{};
  else
    return model_with_parameters<P>(TypeList<Ms...>{});
}
}  // namespace detail

// The registered model with P parameters (each registered model has its own P).
template <int P>
using ModelWithParameters = decltype(detail::model_with_parameters<P>(RegisteredModels{}));

// f(M{}) for the model type M behind m; every registered model must give the same type.
template <class F>
auto visit_model(ModelKind m, F&& f) {
  return detail::visit_index(m.index(), std::forward<F>(f), "visit_model", RegisteredModels{});
}

inline std::string_view model_name(ModelKind m) {
  return visit_model(m, [](auto M) { return std::string_view(decltype(M)::name); });
}

inline int model_parameters(ModelKind m) {
  return visit_model(m, [](auto M) { return decltype(M)::kParameters; });
}

// What a fit under the model leaves out beyond the rotation no scalar calibration sees: its type's
// `not_estimated` sentence, empty when it has none (the paper's model estimates all it can).
inline std::string_view model_not_estimated(ModelKind m) {
  return visit_model(m, [](auto M) {
    if constexpr (requires { decltype(M)::not_estimated; }) return std::string_view(decltype(M)::not_estimated);
    return std::string_view();
  });
}

inline std::optional<ModelKind> parse_model(std::string_view s) {
  for (int i = 0; i < kModelCount; ++i)
    if (model_name(ModelKind(i)) == s) return ModelKind(i);
  return std::nullopt;
}

// "paper9|axis6|bias3|cubic12", for usage lines.
inline std::string model_names(std::string_view separator = "|") {
  std::string out;
  for (int i = 0; i < kModelCount; ++i)
    out += (i ? std::string(separator) : "") + std::string(model_name(ModelKind(i)));
  return out;
}

// The first registered model is the default (the paper's): results name a model only when it is another.
inline constexpr bool is_default_model(ModelKind m) { return m.index() == 0; }

// What a model supports beyond the CalibrationModel concept: a static constexpr bool of that name on its type,
// absent meaning no. criteria_native: the criteria's own kernels and exact sphere limits (symbolic/limits.hpp)
// are its (the paper's rows); region_limits: limits and synthesis on a region; polish_digits: the MPFR polish
// (optimize --digits); thermal_base: a thermal model BASE+Tk is calibrated, rehearsed, applied and exported over
// it (its meter drifts with temperature and must correct as a matrix and an offset, checked in numeric/thermal/);
// auto_choice: one of the linear models `--model auto` chooses among, the richest the positions carry.
enum class ModelCapability { criteria_native, region_limits, polish_digits, thermal_base, auto_choice };

template <class M>
constexpr bool model_supports(ModelCapability c) {
  switch (c) {
    case ModelCapability::criteria_native:
      if constexpr (requires { M::criteria_native; }) return M::criteria_native;
      return false;
    case ModelCapability::region_limits:
      if constexpr (requires { M::region_limits; }) return M::region_limits;
      return false;
    case ModelCapability::polish_digits:
      if constexpr (requires { M::polish_digits; }) return M::polish_digits;
      return false;
    case ModelCapability::thermal_base:
      if constexpr (requires { M::thermal_base; }) return M::thermal_base;
      return false;
    case ModelCapability::auto_choice:
      if constexpr (requires { M::auto_choice; }) return M::auto_choice;
      return false;
  }
  return false;
}

inline bool model_supports(ModelKind m, ModelCapability c) {
  return visit_model(m, [c](auto M) { return model_supports<decltype(M)>(c); });
}

// "paper9" (or "paper9, axis6"): the models with a capability, for messages saying which would do.
inline std::string models_supporting(ModelCapability c) {
  std::string out;
  for (int i = 0; i < kModelCount; ++i)
    if (model_supports(ModelKind(i), c)) out += (out.empty() ? "" : ", ") + std::string(model_name(ModelKind(i)));
  return out;
}

// The models `--model auto` chooses among, richest first (most parameters; registration order between equals).
inline std::vector<ModelKind> auto_choice_models() {
  std::vector<ModelKind> out;
  for (int i = 0; i < kModelCount; ++i)
    if (model_supports(ModelKind(i), ModelCapability::auto_choice)) out.push_back(ModelKind(i));
  std::stable_sort(out.begin(), out.end(),
                   [](ModelKind a, ModelKind b) { return model_parameters(a) > model_parameters(b); });
  return out;
}

// The model's own statement of its limit for a criterion named `criterion` (models other than the
// paper's give a table; the paper's limits come from the criteria and symbolic/limits.hpp).
template <class Model>
std::optional<ModelLimit> stated_limit(std::string_view criterion) {
  if constexpr (requires { Model::limits; }) {
    for (const ModelLimit& l : Model::limits)
      if (l.criterion == criterion) return l;
  }
  return std::nullopt;
}

inline std::optional<ModelLimit> stated_limit(ModelKind m, std::string_view criterion) {
  return visit_model(m, [criterion](auto M) { return stated_limit<decltype(M)>(criterion); });
}

}  // namespace scalcal
