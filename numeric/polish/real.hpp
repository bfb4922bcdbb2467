// The polish's arithmetic: MPFR numbers at a precision set at run time (PrecisionGuard), and the
// dynamic Eigen types over them.
#pragma once
#include <Eigen/Core>
#include <boost/multiprecision/mpfr.hpp>

namespace scalcal::polish_detail {

using Real = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;
using VecX = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// Sets the process-wide MPFR default precision (decimal digits) for its lifetime.
class PrecisionGuard {
 public:
  explicit PrecisionGuard(unsigned digits) : saved_(Real::default_precision()) { Real::default_precision(digits); }
  ~PrecisionGuard() { Real::default_precision(saved_); }
  PrecisionGuard(const PrecisionGuard&) = delete;
  PrecisionGuard& operator=(const PrecisionGuard&) = delete;

 private:
  unsigned saved_;
};

}  // namespace scalcal::polish_detail
