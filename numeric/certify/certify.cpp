// certify(): which certificate runs, and which label its outcome supports. "Missed" only when the
// lower end of a certified local optimum's value is above the limit's enclosure; a certified optimum
// whose enclosure holds the limit goes to the attainment certificate at that optimum.
#include "numeric/certify/certify.hpp"

#include <cmath>
#include <stdexcept>

#include "numeric/certify/attainment.hpp"
#include "numeric/certify/certify_criterion.hpp"
#include "numeric/certify/local_optimum.hpp"

namespace scalcal {

std::string_view status_text(CertifiedStatus s) {
  switch (s) {
    case CertifiedStatus::attained_proven:
      return "limit attained, proven";
    case CertifiedStatus::attained_numerical:
      return "limit attained, numerical";
    case CertifiedStatus::missed_local_optimum:
      return "missed, certified local optimum";
    case CertifiedStatus::missed_numerical:
      return "missed, numerical";
  }
  return "";
}

namespace certify_detail {

namespace {

void set_enclosure(const Interval& value, int digits, CertifyResult& r) {
  const Real lo_v = lo(value), hi_v = hi(value);
  using std::floor;
  using std::log10;
  r.enclosure_digits = static_cast<int>(floor(log10(abs(lo_v) / (hi_v - lo_v))));
  const int printed = std::min(r.enclosure_digits + 2, digits - 5);
  r.enclosure_lo = outward(lo_v, printed, false);
  r.enclosure_hi = outward(hi_v, printed, true);
}

// Claims "attained, proven" from an attainment outcome, with the radius measured from the given
// program (its own chart); false when the exact positions are not proven near its positions.
bool claim_attained(const SphereChart& own, const AttainmentOutcome& a, const std::string& prefix, CertifyResult& r) {
  const auto radius = chart_radius(own, a.exact);
  if (!radius) return false;
  r.status = CertifiedStatus::attained_proven;
  r.radius = sci(*radius);
  r.method = a.method;
  r.unknowns = a.unknowns;
  r.equations = a.equations;
  r.reason = prefix + a.reason;
  return true;
}

std::string relative_gap(double value, double limit) { return sci(Real(value / limit - 1)); }

}  // namespace

CertifyResult certify_target(const Program& program, double value, const CertifyTarget& t,
                             const CertifyOptions& options) {
  CertifyResult r;
  r.value = value;
  r.limit = static_cast<double>(mid(t.limit));
  const int digits = options.digits;
  const SphereChart own = SphereChart::of(program);
  const bool near = value / r.limit - 1 < options.attained_tolerance;
  AttainmentOutcome direct;
  if (near) {
    direct = attainment(program, t, digits);
    if (direct.proven && claim_attained(own, direct, "", r)) return r;
  }
  const LocalOutcome local = local_optimum(program, t, digits);
  r.method = local.method;
  r.unknowns = local.unknowns;
  r.equations = local.equations;
  if (local.certified) {
    set_enclosure(local.value, digits, r);
    const auto radius = chart_radius(own, local.optimum);
    if (radius && lo(local.value) > hi(t.limit)) {
      r.status = CertifiedStatus::missed_local_optimum;
      r.radius = sci(*radius);
      r.reason = local.reason + ", its value enclosed above the limit";
      return r;
    }
    if (hi(local.value) < lo(t.limit))
      throw std::logic_error("certify: a certified value below the proven limit of " + t.name);
  }
  // The optimum Newton reached may attain the limit though the program itself is not certified:
  // a certified optimum whose enclosure holds the limit, or an uncertified critical point.
  AttainmentOutcome at;
  if (local.polished) {
    at = attainment(*local.polished, t, digits);
    const std::string prefix = local.certified ? "the program is near a strict local minimum whose value enclosure "
                                                 "holds the limit; at that minimum: "
                                               : "Newton took the program to a critical point; at that point: ";
    if (at.proven && claim_attained(own, at, prefix, r)) return r;
  }
  if (local.certified) {
    r.status = CertifiedStatus::attained_numerical;
    r.reason = local.reason + ", its value enclosed in [" + r.enclosure_lo + ", " + r.enclosure_hi +
               "], which holds the limit; at that minimum the attainment certificate does not apply: " + at.reason;
    return r;
  }
  if (near) {
    r.status = CertifiedStatus::attained_numerical;
    r.method = direct.method;
    r.unknowns = direct.unknowns;
    r.equations = direct.equations;
    r.reason = direct.reason;
    return r;
  }
  r.status = CertifiedStatus::missed_numerical;
  r.reason = "its value is above the limit by a relative " + relative_gap(value, r.limit) +
             " and no certificate applies: " + local.reason;
  return r;
}

}  // namespace certify_detail

CertifyResult certify(const Program& program, CriterionKind criterion, const CertifyOptions& options) {
  return visit_criterion(criterion, [&](auto c) { return certify<decltype(c)>(program, options); });
}

}  // namespace scalcal
