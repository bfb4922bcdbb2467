// Names and groups of the nine calibration parameters X = (bias, scale-factor deviation,
// non-orthogonality), eq. (5) of Egorov, Kiryachenko, Popov (2022).
#pragma once
#include <array>
#include <string_view>

namespace scalcal {

inline constexpr std::array<std::string_view, 9> kParameterNames = {
    "bias_x",  "bias_y",  "bias_z",  "scale_x",   "scale_y",
    "scale_z", "nonorth_xy", "nonorth_yz", "nonorth_zx"};

enum class ParameterGroup { bias = 0, scale = 1, nonorth = 2 };

inline constexpr std::array<std::string_view, 3> kGroupNames = {"bias", "scale", "nonorth"};

// First index of a group's three parameters in X.
constexpr int group_offset(ParameterGroup g) { return 3 * static_cast<int>(g); }

}  // namespace scalcal
