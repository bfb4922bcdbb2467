// Theorem 23 (proofs/cap_attainment.md): which N <= 60 reach a cap's proven D, E or S limit, on the caps of
// fig12 (half-angles 10, 20, 30, 45, 60, 90, 120 and 133.6 degrees, where Theorems 8 and 19 apply).
// An attaining program's positions lie on the theorem's three circles with the theorem's weights (its
// moment matrix is optimal; the support and the weights follow), so N times each weight must be an
// integer. The weights: D pole 1/9, rim 8 alpha/9, circle 8 (1 - alpha)/9 (alpha from the quintic's root,
// enclosed in MPFI); E and S the closed forms of Theorem 19 (exact at c = 0 and 1/2, enclosed elsewhere).
#include <iostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>
#include <boost/math/constants/constants.hpp>

#include "numeric/certify/interval.hpp"
#include "numeric/region/cap_limits.hpp"
#include "proofs/checks/check.hpp"
#include "proofs/checks/sturm.hpp"
#include "symbolic/exact.hpp"

using scalcal::proofs::check;
using namespace scalcal::certify_detail;

namespace {

// cos of the half-angle written as a decimal ("133.6" is 1336/10 degrees, enclosed).
Interval cosine_deg(const std::string& deg) {
  return cos(Interval(deg) * boost::math::constants::pi<Interval>() / Interval(180));
}

Interval quintic(const Interval& c, const Interval& t) {  // P(c, t) of Theorem 8
  const Interval c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  const Interval k[6] = {-(c + 3) * (c + 3) * (c2 - 2),
                         Interval(-2) * c * (c + 3) * (Interval(8) * c2 - 13),
                         -(Interval(39) * c4 - Interval(6) * c3 - Interval(48) * c2 + Interval(18) * c + 29),
                         Interval(2) * (Interval(24) * c3 + Interval(3) * c2 - Interval(54) * c - 13),
                         Interval(39) * c2 + Interval(6) * c - 29,
                         Interval(10) * (Interval(3) * c + 1)};
  Interval out = k[5];
  for (int i = 4; i >= 0; --i) out = out * t + k[i];
  return out;
}

// alpha(c) of Theorem 8 enclosed: t between two points where P(c, .) has opposite proven signs (Theorem 8:
// one root in (c, 1)), then alpha from E2 = 0, linear in alpha, in interval arithmetic.
bool alpha_enclosure(const std::string& deg, Interval& alpha) {
  const Interval c = cosine_deg(deg);
  const auto form = scalcal::cap_closed_form(scalcal::CriterionKind::D, scalcal::parse_region({"cap:" + deg}));
  if (!form || form->sphere_limit) return false;
  const Real guess(form->heights[2]), step("1e-14");
  const Interval below = point(guess - step), above = point(guess + step);
  if (!(lo(quintic(c, below)) > 0 && hi(quintic(c, above)) < 0)) return false;
  const Interval t(lower(below), upper(above));
  const Interval t2 = t * t, t3 = t2 * t, t4 = t2 * t2, t5 = t4 * t, c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  const Interval r = (t - 1) * (t + 1);
  const Interval num = r * r * (Interval(10) * t2 + t - 3 - Interval(7) * c * t - c);
  const Interval den = (t - c) * (Interval(10) * t5 + t4 - Interval(23) * t3 - Interval(2) * t2 + Interval(10) * t +
                                  Interval(3) * c * t4 + Interval(3) * c2 * t3 + Interval(3) * c3 * t2 -
                                  Interval(9) * c * t2 + Interval(3) * c2 * t - Interval(3) * c4 * t - c4 -
                                  Interval(3) * c3 + Interval(2) * c2 + Interval(6) * c);
  if (lo(den) <= 0 && hi(den) >= 0) return false;
  alpha = num / den;
  return lo(alpha) > 0 && hi(alpha) < 1;
}

bool holds_integer(const Interval& x) { return floor(hi(x)) >= ceil(lo(x)); }

// The N in [1, 60] for which every weight times N may be an integer (its enclosure holds one).
std::vector<int> admissible(const std::vector<Interval>& weights) {
  std::vector<int> out;
  for (int n = 1; n <= 60; ++n) {
    bool all = true;
    for (const Interval& w : weights) all = all && holds_integer(w * Interval(n));
    if (all) out.push_back(n);
  }
  return out;
}

// Theorem 19's weights (rim, middle circle, pole) in intervals or exact rationals.
template <class T>
std::vector<T> e_weights(const T& c) {
  const T c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  const T q = T(3) * c4 + T(36) * c3 + T(194) * c2 + T(260) * c + T(147);
  return {(T(3) * c3 + T(31) * c2 + T(73) * c + T(53)) / q, T(4) * (T(3) * c3 + T(27) * c2 + T(33) * c + T(17)) / q,
          (T(3) * c4 + T(21) * c3 + T(55) * c2 + T(55) * c + T(26)) / q};
}

template <class T>
std::vector<T> s_weights(const T& c) {
  return {T(1) / (c + T(3)), T(4) * (c + T(1)) / ((c + T(3)) * (c + T(3))),
          (c * c + c + T(2)) / ((c + T(3)) * (c + T(3)))};
}

// The N in [1, 60] with every N w an integer, exactly.
std::vector<int> admissible_exact(const std::vector<GiNaC::numeric>& weights) {
  std::vector<int> out;
  for (int n = 1; n <= 60; ++n) {
    bool all = true;
    for (const GiNaC::numeric& w : weights) all = all && (w * n).is_integer();
    if (all) out.push_back(n);
  }
  return out;
}

std::string list(const std::vector<int>& v) {
  std::string s;
  for (int n : v) s += (s.empty() ? "" : " ") + std::to_string(n);
  return s.empty() ? "none" : s;
}

}  // namespace

int main() {
  const IntervalPrecision precision(50);
  // D: pole 1/9 forces 9 | N; the rim's 8 alpha N / 9 positions must be a whole number.
  bool d_none = true;
  for (const char* deg : {"10", "20", "30", "45", "60", "90", "120", "133.6"}) {
    Interval alpha;
    const bool enclosed = alpha_enclosure(deg, alpha);
    const std::vector<int> n = enclosed ? admissible({Interval(1) / 9, Interval(8) * alpha / 9}) : std::vector<int>{0};
    d_none = d_none && n.empty();
    std::cout << "  D on cap:" << deg << ": alpha in [" << lo(alpha).str(12) << ", " << hi(alpha).str(12)
              << "], admissible N <= 60: " << list(n) << "\n";
  }
  check(d_none, "D: on every fig12 cap below 133.62 degrees, no N <= 60 puts a whole number of positions on the rim");

  // E and S at the fig12 caps within their proven half-angles (110.38 and 99.88 degrees): exactly at
  // c = 0 and 1/2, in intervals at the irrational cosines.
  bool e_none = true, s_as_stated = true;
  for (const char* deg : {"10", "20", "30", "45", "60", "90"}) {
    std::vector<int> ne, ns;
    const std::string d(deg);
    if (d == "60" || d == "90") {
      const GiNaC::numeric c = d == "90" ? GiNaC::numeric(0) : GiNaC::numeric(1, 2);
      ne = admissible_exact(e_weights(c));
      ns = admissible_exact(s_weights(c));
    } else {
      ne = admissible(e_weights(cosine_deg(d)));
      ns = admissible(s_weights(cosine_deg(d)));
    }
    e_none = e_none && ne.empty();
    const std::vector<int> want_s = d == "90"   ? std::vector<int>{9, 18, 27, 36, 45, 54}
                                    : d == "60" ? std::vector<int>{49}
                                                : std::vector<int>{};
    s_as_stated = s_as_stated && ns == want_s;
    std::cout << "  cap:" << deg << ": E admissible N <= 60: " << list(ne) << "; S: " << list(ns) << "\n";
  }
  check(e_none, "E: on the fig12 caps up to 90 degrees, no N <= 60 has whole numbers of positions on the circles");
  check(s_as_stated,
        "S: only N = 9k on the hemisphere (rim 3k, 60-degree circle 4k, pole 2k) and N = 49 on the 60-degree cap "
        "(14, 24, 11) have whole numbers; none on the 10-45 degree caps");
  const std::vector<GiNaC::numeric> s0 = s_weights(GiNaC::numeric(0)), s60 = s_weights(GiNaC::numeric(1, 2));
  check(s0[0] == GiNaC::numeric(1, 3) && s0[1] == GiNaC::numeric(4, 9) && s0[2] == GiNaC::numeric(2, 9) &&
            s60[0] == GiNaC::numeric(2, 7) && s60[1] == GiNaC::numeric(24, 49) && s60[2] == GiNaC::numeric(11, 49),
        "S weights: (3, 4, 2)/9 at c = 0 and (14, 24, 11)/49 at c = 1/2, exactly");
  // The weight systems are regular on (-1, 1): E's is a Vandermonde system in (c, (1+c)/2, 1) with T2 = 1,
  // -1, 1; S's rows are E[T2 z] = 0, E[T2 (1 - z^2)] = 0 and the total mass.
  const GiNaC::symbol c("c");
  const GiNaC::ex m = (1 + c) / 2;
  const GiNaC::matrix E_system = {{1, -1, 1}, {c, -m, 1}, {c * c, -m * m, 1}};
  const GiNaC::matrix S_system = {{c, -m, 1}, {1 - c * c, -(1 - m * m), 0}, {1, 1, 1}};
  const GiNaC::ex dE = GiNaC::factor(GiNaC::expand(E_system.determinant()));
  const GiNaC::ex dS = GiNaC::factor(GiNaC::expand(S_system.determinant()));
  std::cout << "  (determinants: E " << dE << ", S " << dS << ")\n";
  check(scalcal::proofs::roots_in(dE, c, -1, GiNaC::numeric(999999, 1000000)) == 0 &&
            scalcal::proofs::roots_in(dS, c, -1, GiNaC::numeric(999999, 1000000)) == 0 && !dE.subs(c == 0).is_zero() &&
            !dS.subs(c == 0).is_zero(),
        "the E and S weight systems have determinants without roots in (-1, 1): the weights are forced");

  // The icosahedron with a face centre at -z lies in cap:150: every vertex (0, +-1, +-phi) (and cyclic shifts)
  // has cosine at most sqrt((5 + 2 sqrt 5)/15) < sqrt(3)/2 = cos 30 degrees to the face centre f = (1, 1, 1).
  const GiNaC::ex phi = (1 + GiNaC::sqrt(GiNaC::ex(5))) / 2, bound = (5 + 2 * GiNaC::sqrt(GiNaC::ex(5))) / 15;
  const Interval phi_i = (Interval(1) + sqrt(Interval(5))) / 2,
                 bound_i = (Interval(5) + Interval(2) * sqrt(Interval(5))) / 15;
  bool within = true, touched = false;
  // The 12 vertices are the cyclic shifts of (0, sy, sz phi); v.f, the sum of the coordinates, is the same
  // for the three shifts. The cosine to f is at most sqrt(bound) when v.f <= 0 or (v.f)^2 <= 3 |v|^2 bound.
  for (int sy : {1, -1})
    for (int sz : {1, -1}) {
      const GiNaC::ex dot = sy + sz * phi;
      const Interval d = Interval(sy) + Interval(sz) * phi_i;
      if (hi(d) < 0) continue;
      if (scalcal::symbolic::is_zero_exact(bound - dot * dot / (3 * (1 + phi * phi)))) {
        touched = true;  // the three vertices of the face about f
        continue;
      }
      within = within && hi(d * d / (Interval(3) * (Interval(1) + phi_i * phi_i))) < lo(bound_i);
    }
  check(within && touched && hi(bound_i) < 0.75,
        "the icosahedron's vertices are at least arccos sqrt((5+2 sqrt5)/15) = 37.38 degrees from a face centre "
        "(reached): turned with that face centre at -z it lies in cap:150 and attains D there at N = 12");
  // Control: the check finds the admissible N of a made-up weight 1/3, as it must.
  check(admissible({Interval(1) / 3}).size() == 20, "control: a weight 1/3 admits exactly the 20 multiples of 3");
  return scalcal::proofs::finish();
}
