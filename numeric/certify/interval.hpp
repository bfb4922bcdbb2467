// The certificates' arithmetic: MPFI intervals (outward rounding) beside the MPFR points of the
// polish, at the same run-time precision, and the few interval predicates a Krawczyk test needs.
#pragma once
#include <Eigen/Core>
#include <boost/multiprecision/mpfi.hpp>

#include "numeric/polish/real.hpp"

namespace scalcal::certify_detail {

using polish_detail::MatX;
using polish_detail::Real;
using polish_detail::VecX;
using Interval =
    boost::multiprecision::number<boost::multiprecision::mpfi_float_backend<0>, boost::multiprecision::et_off>;
using IVecX = Eigen::Matrix<Interval, Eigen::Dynamic, 1>;
using IMatX = Eigen::Matrix<Interval, Eigen::Dynamic, Eigen::Dynamic>;

// Sets the MPFR and MPFI default precisions (decimal digits) together for its lifetime.
class IntervalPrecision {
 public:
  explicit IntervalPrecision(unsigned digits) : real_(digits), saved_(Interval::default_precision()) {
    Interval::default_precision(digits);
  }
  ~IntervalPrecision() { Interval::default_precision(saved_); }
  IntervalPrecision(const IntervalPrecision&) = delete;
  IntervalPrecision& operator=(const IntervalPrecision&) = delete;

 private:
  polish_detail::PrecisionGuard real_;
  unsigned saved_;
};

inline Interval point(const Real& x) { return Interval(x, x); }
inline Interval around(const Real& x, const Real& r) { return Interval(x - r, x + r); }
inline Real lo(const Interval& x) { return Real(lower(x)); }
inline Real hi(const Interval& x) { return Real(upper(x)); }
inline Real mid(const Interval& x) { return Real(median(x)); }
// max |x| over the interval.
inline Real mag(const Interval& x) {
  const Real a = abs(lo(x)), b = abs(hi(x));
  return a > b ? a : b;
}
// a lies in the interior of b.
inline bool interior(const Interval& a, const Interval& b) { return lo(a) > lo(b) && hi(a) < hi(b); }

inline IVecX points(const VecX& x) {
  IVecX out(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) out(i) = point(x(i));
  return out;
}
inline MatX midpoints(const IMatX& a) {
  MatX out(a.rows(), a.cols());
  for (Eigen::Index i = 0; i < a.rows(); ++i)
    for (Eigen::Index j = 0; j < a.cols(); ++j) out(i, j) = mid(a(i, j));
  return out;
}

}  // namespace scalcal::certify_detail
