// rotation: k positions equally spaced on a ring about each axis in turn (paper, Fig. 2), ring
// about z first: (cos t, sin t, 0), then (0, cos t, sin t), (sin t, 0, cos t), t = phase +
// 2 pi j / k (phase in degrees). The sums over a ring are done exactly for any k: with
// w = e^{it}, a monomial cos^a t sin^b t (any degree) is a Laurent polynomial in w, and
// sum_j w_j^n = k e^{i n phase} when k divides n and 0 otherwise. So for k >= 5 only n = 0
// survives in the degree-4 moments and every k >= 5 has the same normalised information matrix;
// k = 3 and 4 depend on the phase (and up to k = 6 for the degree-6 moments of --model cubic12).
#include "numeric/io/input_error.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

namespace {

// sum_{j<k} cos^a(t_j) sin^b(t_j), t_j = phi + 2 pi j / k, exactly.
ex ring_sum(int a, int b, int k, const ex& phi) {
  const GiNaC::symbol w("w");
  const ex c = (w + 1 / w) / 2, s = (w - 1 / w) / (2 * GiNaC::I);
  const ex poly = GiNaC::expand(GiNaC::pow(c, a) * GiNaC::pow(s, b));
  ex sum = 0;
  for (int n = -(a + b); n <= a + b; ++n) {
    if (n % k != 0) continue;
    const ex coeff = poly.coeff(w, n);
    sum += k * coeff * (GiNaC::cos(n * phi) + GiNaC::I * GiNaC::sin(n * phi));
  }
  return GiNaC::expand(sum);
}

// sum over the program of x^a y^b z^c, from ring sums (no coordinates are formed).
ex rotation_moment(int k, const ex& phi, const int (&e)[3]) {
  ex total = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const int a = (axis + 2) % 3, ic = (a + 1) % 3, is = (a + 2) % 3;  // cos and sin slots
    if (e[a] != 0) continue;                                           // the ring has coordinate a equal to 0
    total += ring_sum(e[ic], e[is], k, phi);
  }
  return canonical(total);
}

}  // namespace

// The information matrix of rotation(k, phase).
FamilyInstance rotation_instance(int k, const ex& phase_deg) {
  const ex phi = phase_deg * GiNaC::Pi / 180;
  // Exponents of (x, y, z) in h_r.
  static const int expo[9][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0},
                                 {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  GiNaC::matrix M(9, 9);
  for (int r = 0; r < 9; ++r)
    for (int c = r; c < 9; ++c) {
      int e[3];
      for (int i = 0; i < 3; ++i) e[i] = expo[r][i] + expo[c][i];
      M(r, c) = M(c, r) = rotation_moment(k, phi, e);
    }
  MomentFunction moment = [k, phi](int a, int b, int c) {
    const int e[3] = {a, b, c};
    return rotation_moment(k, phi, e);
  };
  return {3 * k, M, moment};
}

std::vector<Family> rotation_families() {
  Family f;
  f.name = "rotation";
  f.summary = "k positions per ring while rotating about each axis in turn (3k positions)";
  f.params = {{"k", "6", "positions per ring (k >= 3)"},
              {"phase", "0", "phase of the rings, degrees",
               // reduced exactly modulo 360 (1e20 degrees is 280 degrees, not what a double of it gives)
               [](const std::string& text, GiNaC::parser& reader) { return reduced_degrees(reader(text), text); }}};
  f.instance = [](const ParamMap& p) {
    const int k = integer_param(p, "k", 3, 100000);
    // For k = 3, 4 the criteria are rational functions of cos and sin of 3 or 4 phase, too
    // large to simplify in reasonable time; k >= 5 does not depend on the phase at all.
    if (k < 5 && !is_number(p.at("phase"))) throw InputError("--param", 0, "phase must be a number when k = 3 or 4");
    return rotation_instance(k, p.at("phase"));
  };
  f.numeric = [](const ParamMap& p) -> std::optional<Program> {
    if (!is_number(p.at("phase"))) return std::nullopt;
    const double phase = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(p.at("phase"))).to_double();
    return Program::rotation(integer_param(p, "k", 3, 100000), phase);
  };
  return {f};
}

}  // namespace scalcal::symbolic
