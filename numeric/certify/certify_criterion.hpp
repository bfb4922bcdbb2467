// certify() for any criterion type, registered or not (tests/common's I has no limit and gets
// NoKnownLimit): the target comes from the type (target.hpp), the work from certify.cpp.
#pragma once
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "numeric/certify/certify.hpp"
#include "numeric/certify/target.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal {

namespace certify_detail {
// The certificates for a program whose criterion value is `value`, at the current MPFI precision.
CertifyResult certify_target(const Program& program, double value, const CertifyTarget& target,
                             const CertifyOptions& options);
}  // namespace certify_detail

template <Criterion C>
CertifyResult certify(const Program& program, const CertifyOptions& options = {}) {
  if (!C::template limit<Paper9Model, double>()) throw NoKnownLimit(C::name);
  if (program.size() < 9) throw std::invalid_argument("certify: a program needs at least 9 positions");
  const double value = criterion_value<C>(program);
  if (!std::isfinite(value)) throw std::invalid_argument("certify: the program is singular (rank < 9)");
  const auto start = std::chrono::steady_clock::now();
  const certify_detail::IntervalPrecision precision(static_cast<unsigned>(options.digits));
  CertifyResult r = certify_detail::certify_target(program, value, certify_detail::target_of<C>(), options);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace scalcal
