// Interval arithmetic for the region's proofs (Boost.Interval): outward rounding by the "opposite"
// trick (every bound rounded upward, a lower bound as -((-a) - b)), so the rounding mode is set once
// per proof instead of twice per operation (that switching was half of `limits --region`).
// Interval operations are valid only while a RoundingScope lives.
#pragma once
#include <boost/numeric/interval.hpp>

namespace scalcal {

namespace interval_detail {
namespace il = boost::numeric::interval_lib;
using Policies = il::policies<il::save_state<il::rounded_arith_opp<double>>, il::checking_strict<double>>;
using Protected = boost::numeric::interval<double, Policies>;
}  // namespace interval_detail

// Sets upward rounding for its lifetime and restores the caller's mode after.
using RoundingScope = interval_detail::Protected::traits_type::rounding;
// An interval whose operations assume a RoundingScope is alive.
using Interval = boost::numeric::interval_lib::unprotect<interval_detail::Protected>::type;

}  // namespace scalcal
