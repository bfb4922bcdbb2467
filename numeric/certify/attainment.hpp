// The attainment certificate: an exact program whose moments of degree <= 4 equal those of the
// criterion's symmetric optimal measure (so whose criterion equals the limit exactly) lies near a
// given program. Krawczyk on 24 moment equations in 24 chart coordinates, or, where that system is
// overdetermined or degenerate, a fit to a family of exact designs (pentagonal_match.hpp).
#pragma once
#include <string>
#include <vector>

#include "numeric/certify/certificate_tools.hpp"
#include "numeric/certify/target.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

struct AttainmentOutcome {
  bool proven = false;
  std::vector<IPoint> exact;  // proven: the exact program's positions, enclosed, one per position
  int unknowns = 0;
  int equations = 0;
  double deviation = 0;  // inf-norm of the program's 24 moment residuals (double)
  std::string method;
  std::string reason;  // what the proof rests on, or why it does not apply
};

AttainmentOutcome attainment(const Program& program, const CertifyTarget& target, int digits);

}  // namespace scalcal::certify_detail
