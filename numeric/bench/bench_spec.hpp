// Reading the text of a --bench spec: its fields, numbers and meter axes, each defect an InputError
// naming --bench, the spec and the reason.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "numeric/model/model.hpp"

namespace scalcal {

// InputError("--bench", 0, "'SPEC': WHY").
[[noreturn]] void bench_error(std::string_view spec, const std::string& why);

std::vector<std::string> split_spec(std::string_view text, char separator);

// A finite number, the whole text; throws bench_error naming `what`.
double spec_number(std::string_view spec, const std::string& text, const std::string& what);

// "x", "+y", "-z": a meter axis as a unit vector; throws bench_error.
Vec3 spec_axis(std::string_view spec, const std::string& text);

// "x", "-z": the text of a unit coordinate axis.
std::string axis_text(const Vec3& axis);

}  // namespace scalcal
