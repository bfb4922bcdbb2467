// The local-optimum certificates: a Krawczyk box about a critical point (D, A) or a KKT point (S:
// the active diagonal entries of K; E: the multiple smallest eigenvalue of M) and the second-order
// sufficient condition proven over the box, so the box holds a strict local minimum whose value is
// enclosed. The caller compares that enclosure with the limit; nothing here says "missed".
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "numeric/certify/certificate_tools.hpp"
#include "numeric/certify/target.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

struct LocalOutcome {
  bool certified = false;           // a strict local minimum is enclosed
  Interval value;                   // certified: its criterion value, normalised (N^9 det K, N tr K, ...)
  std::vector<IPoint> optimum;      // certified: its positions, enclosed
  std::optional<Program> polished;  // the critical or KKT point Newton reached near the program, if any
  int unknowns = 0;
  int equations = 0;
  std::string method;
  std::string reason;  // what the certificate proves, or why it does not apply
};

LocalOutcome local_optimum(const Program& program, const CertifyTarget& target, int digits);

}  // namespace scalcal::certify_detail
