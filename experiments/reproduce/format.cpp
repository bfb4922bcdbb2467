// Numbers as REPORT.md and the pipeline's CSVs print them (format.hpp).
#include "experiments/reproduce/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "plots/figure.hpp"

namespace scalcal::reproduce {

std::string decimal(double x, int significant) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  // Up to 10 digits: a number that only agrees to 1e-12 at 11 or 12 digits is rounding, not a closed form.
  for (int p = 1; p <= 10; ++p) {
    const std::string s = ::fmt::format("{:.{}g}", x, p);
    if (std::abs(std::strtod(s.c_str(), nullptr) - x) <= 1e-12 * std::abs(x)) return s;
  }
  const int before_point = x == 0 ? 1 : static_cast<int>(std::floor(std::log10(std::abs(x)))) + 1;
  return ::fmt::format("{:.{}g}", x, std::max(significant, std::min(before_point, 15)));
}

// Values computed in double agree to about 1e-13 when they are equal: a smaller difference is
// rounding, not data, and is printed as agreement.
std::string pct(double ours, double theirs) {
  if (!std::isfinite(ours) || !std::isfinite(theirs) || theirs == 0) return "n/a";
  const double relative = (ours - theirs) / theirs;
  if (std::abs(relative) < 1e-10) return "0 (equal to 10 digits)";
  return ::fmt::format("{:+.3g} %", 100.0 * relative);
}

std::string seconds_text(double s) {
  if (!std::isfinite(s)) return "n/a";
  return s >= 100 ? ::fmt::format("{:.0f}", s) : ::fmt::format("{:.3g}", s);
}

std::string excess_text(double relative) {
  if (std::isfinite(relative) && std::abs(relative) < 1e-12) return "0 (to rounding)";
  return decimal(relative, 3);
}

std::string csv_num(double x) { return std::isfinite(x) ? ::fmt::format("{}", x) : std::string(); }

std::string exact_and_decimal(std::string_view exact, double value, int significant) {
  const std::string d = decimal(value, significant);
  return exact == d ? d : std::string(exact) + " = " + d;
}

std::string gp_power(double x, int significant) {
  if (!std::isfinite(x) || x == 0) return decimal(x, significant);
  const int e = static_cast<int>(std::floor(std::log10(std::abs(x))));
  const std::string mantissa = ::fmt::format("{:.{}g}", x / std::pow(10.0, e), significant);
  return e == 0 ? mantissa : mantissa + "·10" + plots::sup(std::to_string(e));
}

std::string math_text(std::string_view exact) {
  std::string out;
  for (std::size_t i = 0; i < exact.size();) {
    if (exact.substr(i, 5) == "sqrt(") {  // sqrt(2) -> √2
      const std::size_t close = exact.find(')', i);
      out += "√" + std::string(exact.substr(i + 5, close - i - 5));
      i = close == std::string_view::npos ? exact.size() : close + 1;
    } else if (exact[i] == '*') {  // 18*sqrt(2) -> 18√2: a product reads without its sign
      ++i;
    } else if (exact[i] == '+' || exact[i] == '-') {
      out += exact[i] == '+' ? " + " : " − ";
      ++i;
    } else {
      out += exact[i++];
    }
  }
  return out;
}

}  // namespace scalcal::reproduce
