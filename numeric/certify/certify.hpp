// Certificates for one program and one criterion of the paper's model: that an exact program
// attaining the limit lies within a stated radius (Krawczyk on the moment equations), or that the
// program is within a stated radius of a strict local optimum whose value is enclosed above the
// limit (Krawczyk on the gradient or KKT system, interval Cholesky of the reduced Hessian). A local
// optimum whose enclosure holds the limit is never called a miss: the attainment certificate runs on
// it instead. Otherwise: numerical, with the reason.
#pragma once
#include <stdexcept>
#include <string>

#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

enum class CertifiedStatus { attained_proven, attained_numerical, missed_local_optimum, missed_numerical };

// "limit attained, proven", "limit attained, numerical", "missed, certified local optimum", "missed, numerical"
std::string_view status_text(CertifiedStatus s);

struct CertifyOptions {
  int digits = 60;                   // working precision of MPFR and MPFI
  double attained_tolerance = 1e-8;  // relative gap under which the attainment certificate is tried first
};

struct CertifyResult {
  CertifiedStatus status = CertifiedStatus::missed_numerical;
  double value = 0;  // the criterion of the given program (double)
  double limit = 0;
  std::string radius;        // attained, proven: an exact program attaining the limit lies within it;
                             // missed, certified: the strict local optimum does (inf-norm, chart coordinates)
  std::string enclosure_lo;  // a certified strict local optimum near the program has its value in [lo, hi]
  std::string enclosure_hi;  // (empty when none was certified)
  int enclosure_digits = 0;  // leading decimal digits that lo and hi share
  int unknowns = 0;          // coordinates solved for; the rest are held at their computed values
  int equations = 0;
  std::string method;  // which certificate ran
  std::string reason;  // why a claim stays numerical, or what the proof rests on
  double seconds = 0;
};

// No known limit: nothing to certify attainment against. The CLI reports it as bad input (exit 2).
class NoKnownLimit : public std::invalid_argument {
 public:
  explicit NoKnownLimit(std::string_view criterion)
      : std::invalid_argument("no known limit for criterion " + std::string(criterion)) {}
};

// Throws std::invalid_argument for a program with fewer than 9 positions or a singular one, and
// NoKnownLimit ("no known limit for criterion X") for a criterion without a known limit.
CertifyResult certify(const Program& program, CriterionKind criterion, const CertifyOptions& options = {});

}  // namespace scalcal
