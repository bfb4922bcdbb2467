// A multistart's start from a model's proven optimal measure: where the model states it as weight w
// on the 6 axis directions and 1 - w on the 8 cube diagonals (ModelLimit::axis_weight), its efficient
// rounding to N positions (Pukelsheim and Rieder 1992), taken in antipodal pairs so that the odd
// moments stay zero as in the measure. For cubic12's S at N = 132 Ipopt polishes it to 27.0191 in
// 0.2 s, where 152 random starts reached 27.0779 in 637 s (their optima all differ). Where the model
// asks for them, randomised roundings are the further starts.
#pragma once
#include <cstdint>
#include <optional>
#include <string_view>

#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

// The rounded measure for `criterion` (a registered criterion's name) under `model` at `positions`,
// or nothing where the model states no such measure.
std::optional<Program> rounded_limit_measure(ModelKind model, std::string_view criterion, int positions);

// Whether the model asks for randomised roundings as further starts of `criterion`
// (ModelLimit::rounding_starts, with a stated axis weight).
bool asks_for_rounding_starts(ModelKind model, std::string_view criterion);

// A randomised rounding of the same measure over its 14 directions one by one (not in antipodal pairs),
// for a further start where the model asks for them, else nothing. Each direction gets floor(N w_i) or
// one more, by systematic sampling in a random order from a random offset, and each position a jitter of
// up to 5e-4 per coordinate, so that coincident positions can part. The same seed gives the same program.
std::optional<Program> randomised_rounding(ModelKind model, std::string_view criterion, int positions,
                                           std::uint64_t seed);

}  // namespace scalcal
