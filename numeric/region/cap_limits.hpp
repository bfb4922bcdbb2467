// The proven closed forms of a cap's limits, where a theorem gives one: D on every cap
// (proofs/cap_d_limit.md: the pole with weight 1/9, the rim and one circle at the root of a quintic; the
// sphere's 61509375/4 from 133.62 degrees on), E and S on a cap about a coordinate axis up to 110.38 and
// 99.88 degrees (proofs/cap_es_limits.md: the rim, the middle circle and the pole with weights in closed
// form). There the limit is a theorem's value, not a numerical optimum with a certified bound.
#pragma once
#include <optional>
#include <string_view>
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/region/region.hpp"

namespace scalcal {

struct CapClosedForm {
  double half_angle_deg = 0;    // the cap z >= c about its axis, c = cos(half_angle)
  double cosine = 0;            // c
  double value = 0;             // the limit, evaluated from its closed form in long double
  std::vector<double> heights;  // an optimal measure: uniform circles at these heights (1: the pole)
  std::vector<double> weights;  // summing to 1
  std::string_view theorem;     // the document that proves the closed form
  bool sphere_limit = false;    // D on a cap of 133.62 degrees or more: the sphere's 61509375/4
};

// The half-angle of the region when it is one cap about one axis and nothing else (not the sphere).
std::optional<double> single_cap_angle(const Region& region);

// The closed form of criterion c on the region, when a theorem gives one; none elsewhere (a band, a
// union, E or S on a cap about another axis or beyond the proven half-angles, another criterion). A cap
// whose cosine is within 1e-12 of a theorem's threshold gets none: long double may not tell its side.
std::optional<CapClosedForm> cap_closed_form(CriterionKind c, const Region& region);

// The thresholds (cosines) of the theorems, to 40 digits: D reaches the sphere's limit for
// c <= -(1 + sqrt 6)/5 (133.62 degrees), E's closed form holds for c >= c_E, the root in (-0.35, 1) of
// 9c^7 + 231c^6 + 1973c^5 + 7275c^4 + 14459c^3 + 16181c^2 + 9287c + 1785 (110.38 degrees), S's for
// c >= -3 + 2 sqrt 2 (99.88 degrees).
inline constexpr long double kCapDSphereCosine = -0.6898979485566356196394568149411782783932L;
inline constexpr long double kCapEThreshold = -0.3481719291644396742282975452994025513794L;
inline constexpr long double kCapSThreshold = -0.1715728752538099023966225515806038428607L;

// The quintic P(c, t) of proofs/cap_d_limit.md whose root in (c, 1) is the inner circle's height.
long double cap_d_quintic(long double c, long double t);

}  // namespace scalcal
