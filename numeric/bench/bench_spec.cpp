// Reading --bench specs (bench_spec.hpp).
#include "numeric/bench/bench_spec.hpp"

#include <cmath>
#include <cstdlib>

#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {

void bench_error(std::string_view spec, const std::string& why) {
  throw InputError(option_word("bench"), 0, "'" + display_name(std::string(spec)) + "': " + why);
}

std::vector<std::string> split_spec(std::string_view text, char separator) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t at = text.find(separator, start);
    out.emplace_back(text.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start));
    if (at == std::string_view::npos) return out;
    start = at + 1;
  }
}

double spec_number(std::string_view spec, const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double v = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v))
    bench_error(spec, what + " must be a number, got '" + display_name(text) + "'");
  return v;
}

Vec3 spec_axis(std::string_view spec, const std::string& text) {
  std::string t = text;
  double sign = 1;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    sign = t[0] == '-' ? -1 : 1;
    t.erase(0, 1);
  }
  if (t == "x") return Vec3(sign, 0, 0);
  if (t == "y") return Vec3(0, sign, 0);
  if (t == "z") return Vec3(0, 0, sign);
  bench_error(spec,
              "an axis is one of the meter's axes x, y, z (optionally -x, ...), got '" + display_name(text) + "'");
}

std::string axis_text(const Vec3& a) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(a(k)) == 1) return std::string(a(k) < 0 ? "-" : "") + "xyz"[k];
  return "?";
}

}  // namespace scalcal
