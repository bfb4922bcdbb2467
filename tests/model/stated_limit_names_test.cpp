// A model's stated limits must name registered criteria, each once (numeric/criteria/stated_limit_names.hpp): the
// check accepts the shipped models and refuses a misspelt name, an unregistered one and a repeated one.
#include <gtest/gtest.h>

#include <array>

#include "numeric/criteria/stated_limit_names.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {
namespace {

constexpr ModelLimit limit(std::string_view criterion) { return {criterion, 1.0, "1", "", "", "", 0.0, "", ""}; }

struct Misspelt {
  static constexpr std::array<ModelLimit, 2> limits = {limit("D"), limit("d")};
};
struct Unregistered {
  static constexpr std::array<ModelLimit, 1> limits = {limit("G")};
};
struct Repeated {
  static constexpr std::array<ModelLimit, 3> limits = {limit("A"), limit("E"), limit("A")};
};
struct AllFour {
  static constexpr std::array<ModelLimit, 4> limits = {limit("S"), limit("E"), limit("A"), limit("D")};
};

TEST(StatedLimitNames, TheShippedModelsNameTheirCriteria) {
  static_assert(stated_limits_name_criteria<Paper9Model>());  // states none: nothing to misname
  static_assert(stated_limits_name_criteria<Axis6Model>());
  static_assert(stated_limits_name_criteria<Bias3Model>());
  static_assert(stated_limits_name_criteria<Cubic12Model>());
  EXPECT_EQ(Cubic12Model::limits.size(), 4u);
}

TEST(StatedLimitNames, AWrongNameOrARepeatIsRefused) {
  static_assert(!stated_limits_name_criteria<Misspelt>());
  static_assert(!stated_limits_name_criteria<Unregistered>());
  static_assert(!stated_limits_name_criteria<Repeated>());
  static_assert(stated_limits_name_criteria<AllFour>());  // any order
  SUCCEED();
}

}  // namespace
}  // namespace scalcal
