// Evaluates the icosahedral jig (20 positions, a spherical 4-design) through the installed numeric
// library and derives the D limit through the installed symbolic one: both must give 61509375/4.
#include <cmath>
#include <iostream>

#include "scalcal/numeric/criteria/evaluation.hpp"
#include "scalcal/numeric/program/program.hpp"
#ifndef NUMERIC_ONLY
#include "scalcal/symbolic/exact.hpp"
#include "scalcal/symbolic/limits.hpp"
#endif

int main() {
  const scalcal::Program jig = scalcal::Program::icosahedral();
  const double d = scalcal::criterion_value(jig, *scalcal::parse_criterion("D"));
  std::cout << "D = " << d << "\n";
  if (std::abs(d / 15377343.75 - 1) > 1e-12) return 1;
#ifndef NUMERIC_ONLY
  const std::string exact =
      scalcal::symbolic::canonical_text(scalcal::symbolic::symbolic_limit(*scalcal::parse_criterion("D")).value);
  std::cout << "D limit = " << exact << "\n";
  if (exact != "61509375/4") return 1;
#endif
  return 0;
}
