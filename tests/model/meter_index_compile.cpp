// Compiled, not run, by tests/model/meter_index_compile.sh: a model's parameter is found among its meter's when
// the model is compiled (meter_index_of), so a name its meter does not know stops the build. SCALCAL_NAME is the
// second parameter's name; SCALCAL_EXPECTED its index among SCALCAL_METER::kParameters.
#include <array>
#include <string_view>

#include "numeric/calibration/model_calibration.hpp"

struct TwoParameterModel {
  static constexpr int kParameters = 2;
  using meter = scalcal::SCALCAL_METER;
  static constexpr std::array<std::string_view, 2> parameter_names = {"bias_y", SCALCAL_NAME};
};

constexpr auto kIndex = scalcal::meter_index_of<TwoParameterModel>();
static_assert(kIndex[0] == 1 && kIndex[1] == SCALCAL_EXPECTED);
