// web/wasm/charconv_compat.hpp: std::from_chars / std::to_chars for double, which the libc++ of Debian's
// emscripten 3.1.6 (LLVM 14) lacks; force-included (-include) only into the numeric units that call them
// (numeric/program/catalogue.cpp, program_csv.cpp), so the numeric sources build unchanged.
//
// Why this is safe to add to namespace std here: libc++ 14 declares no floating overloads at all (a double
// argument falls to its deleted bool overload), so these exact-match overloads are the only candidates.
// Semantics kept from the standard: from_chars takes no leading whitespace, '+' or hex (strtod would);
// to_chars gives the shortest text that reads back to the same double, fixed or scientific, whichever is
// shorter, fixed on a tie. musl's strtod and printf are correctly rounded, so the digits are the host's.
#pragma once
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

namespace std {

inline from_chars_result from_chars(const char* first, const char* last, double& value) {
  const char* p = first;
  if (p != last && *p == '-') ++p;
  // Reject what strtod accepts but from_chars does not: leading whitespace and '+'.
  if (p == last || isspace(static_cast<unsigned char>(*p)) || *p == '+') return {first, errc::invalid_argument};
  // A hex prefix is not read as hex: "0x10" is the number 0 followed by "x10", as libstdc++ reads it.
  const bool hex = last - p >= 2 && p[0] == '0' && (p[1] == 'x' || p[1] == 'X');
  const string text(first, hex ? p + 1 : last);  // strtod needs a terminated string
  char* end = nullptr;
  errno = 0;
  const double v = strtod(text.c_str(), &end);
  if (end == text.c_str()) return {first, errc::invalid_argument};
  const char* stop = first + (end - text.c_str());
  // Out of range is overflow or underflow to zero; musl also sets ERANGE for a subnormal, which from_chars
  // returns as it is. The value is then left unchanged, as the standard says.
  if (errno == ERANGE && (v == 0 || isinf(v))) return {stop, errc::result_out_of_range};
  value = *first == '-' && isnan(v) ? copysign(v, -1.0) : v;  // musl's strtod drops the sign of "-nan"
  return {stop, errc()};
}

namespace scalcal_web_detail {
// Fixed text of the digits d (no point) times 10^(e - len + 1), e the decimal exponent of the first digit.
inline string fixed_text(const string& d, int e) {
  const int n = static_cast<int>(d.size());
  if (e >= n - 1) return d + string(static_cast<size_t>(e - (n - 1)), '0');
  if (e >= 0) return d.substr(0, static_cast<size_t>(e + 1)) + "." + d.substr(static_cast<size_t>(e + 1));
  return "0." + string(static_cast<size_t>(-e - 1), '0') + d;
}
inline string scientific_text(const string& d, int e) {
  char exp[8];
  snprintf(exp, sizeof exp, "e%c%02d", e < 0 ? '-' : '+', e < 0 ? -e : e);
  return d.substr(0, 1) + (d.size() > 1 ? "." + d.substr(1) : string()) + exp;
}
}  // namespace scalcal_web_detail

inline to_chars_result to_chars(char* first, char* last, double value) {
  string out;
  if (isnan(value)) {
    out = signbit(value) ? "-nan" : "nan";
  } else if (isinf(value)) {
    out = value < 0 ? "-inf" : "inf";
  } else {
    if (signbit(value)) out = "-";
    const double a = fabs(value);
    if (a == 0) {
      out += "0";
    } else {
      // The fewest significant digits that read back exactly (at most 17 for a double).
      char buf[40];
      for (int p = 1; p <= 17; ++p) {
        snprintf(buf, sizeof buf, "%.*e", p - 1, a);
        if (strtod(buf, nullptr) == a) break;
      }
      const char* e = strchr(buf, 'e');
      string digits;
      for (const char* c = buf; c != e; ++c)
        if (*c != '.') digits += *c;
      while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
      const int exponent = atoi(e + 1);
      string f = scalcal_web_detail::fixed_text(digits, exponent);
      const string s = scalcal_web_detail::scientific_text(digits, exponent);
      // The length decides between the forms; a fixed integer is then printed exactly (%.0f), as the standard's
      // "as if by printf" asks: 503608089097202944, not the shortest digits padded with zeros.
      if (exponent >= static_cast<int>(digits.size()) - 1 && f.size() <= s.size()) {
        snprintf(buf, sizeof buf, "%.0f", a);
        f = buf;
      }
      out += f.size() <= s.size() ? f : s;
    }
  }
  if (out.size() > static_cast<size_t>(last - first)) return {last, errc::value_too_large};
  memcpy(first, out.data(), out.size());
  return {first + out.size(), errc()};
}

}  // namespace std
