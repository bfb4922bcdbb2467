// A polished value as the decimal text value_digits holds: the significant digits the polish vouches for.
#pragma once
#include <cstddef>
#include <ios>
#include <string>

namespace scalcal {

// Every digit claimed, trailing zeros included (15 to 5 digits is "15.000"), but no bare decimal point, which
// `showpoint` alone leaves when the digits end at it and reads as a typo: 15 to 2 digits is "15", not "15.",
// and 14.7 to 1 digit "1e+01", not "1.e+01" (a polish that did not converge can vouch for that few).
template <class Real>
std::string value_text(const Real& value, int digits) {
  std::string text = value.str(digits, std::ios_base::showpoint);
  const std::size_t exponent = text.find_first_of("eE");
  const std::size_t end = exponent == std::string::npos ? text.size() : exponent;
  if (end > 0 && text[end - 1] == '.') text.erase(end - 1, 1);
  return text;
}

}  // namespace scalcal
