// The I criterion (numeric/criteria/integrated_variance.hpp) under the name the tests give it.
#pragma once
#include "numeric/criteria/integrated_variance.hpp"

namespace scalcal::testing {
using scalcal::IntegratedVarianceCriterion;
}  // namespace scalcal::testing
