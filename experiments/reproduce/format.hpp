// Numbers as REPORT.md and the pipeline's CSVs print them. The report never shows rounding noise
// as a different number (15377343.75 stays 15377343.75, never 15377344), and the CSVs hold the
// shortest text that reads back to the same double.
#pragma once
#include <string>
#include <string_view>

namespace scalcal::reproduce {

// A value within a relative 1e-12 of a decimal of at most 10 significant digits prints as that
// decimal (an optimiser reached a closed form up to rounding); any other value is rounded to
// `significant` digits, but never to fewer digits than it has before the decimal point.
std::string decimal(double x, int significant = 6);

// Signed relative difference in percent, "+0.123 %".
std::string pct(double ours, double theirs);

// Seconds as a person reads a timing: three significant digits (0.00462, 27.3, 105), not the
// nine of the clock.
std::string seconds_text(double s);

// A relative excess over a limit; below 1e-12 in size it is the rounding of two equal values and
// prints as "0 (to rounding)" rather than as data such as -9.44e-15.
std::string excess_text(double relative);

// Shortest round-trip text; empty when not finite (gnuplot and CSV readers skip empty cells).
std::string csv_num(double x);

// "61509375/4 = 15377343.75", or just "12" when the closed form already is the decimal.
std::string exact_and_decimal(std::string_view exact, double value, int significant = 10);

// For figures (gnuplot enhanced text): x as "1.29·10^9" with a 7 pt exponent (plots::sup), and a
// closed form as the limits spell it ("45+18*sqrt(2)") written as mathematics ("45 + 18√2").
std::string gp_power(double x, int significant = 3);
std::string math_text(std::string_view exact);

}  // namespace scalcal::reproduce
