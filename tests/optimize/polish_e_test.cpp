// The E polish against facts that do not come from it: the 12 edge positions have, by hand, moments
// a = E[x^4] = 1/6, b = E[x^2 y^2] = 1/12, so lambda_min(M/N) = min(1/3, a - b, b) = 1/12 and E = 12,
// which is also the limit over all programs (proofs/aes_limits.md); so wherever a polished program
// is at the limit, its digits must read 12.000... At N = 9 the limit is not reached: there the checks
// are agreement with the double optimum, the same digits from different double optima, and that
// the digits claimed before convergence are true.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/polish/real.hpp"
#include "numeric/polish/value_text.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal {
namespace {

using mp60 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<60>, boost::multiprecision::et_off>;

mp60 parsed(const PolishResult& p) { return mp60(p.value_digits); }

mp60 distance_from_twelve(const PolishResult& p) {
  using boost::multiprecision::abs;
  return abs(parsed(p) - mp60(12));
}

SynthesisResult e_optimum(int n, int starts, std::uint64_t seed) {
  SynthesisOptions o;
  o.positions = n;
  o.criterion = CriterionKind::E;
  o.starts = starts;
  o.seed = seed;
  return synthesize(o);
}

// The edge program moved off the limit by about 1e-6 per coordinate (a fixed, irregular pattern).
Program perturbed_edges() {
  Program p = Program::octahedral(0, 1, 0);
  for (int i = 0; i < p.size(); ++i) {
    Vec3& e = p.positions[static_cast<std::size_t>(i)];
    e += 1e-6 * Vec3(std::sin(i + 1.0), std::cos(2.0 * i + 1.0), std::sin(3.0 * i + 2.0));
    e.normalize();
  }
  return p;
}

TEST(PolishE, PerturbedEdgeProgramReturnsToTheLimit) {
  const Program start = perturbed_edges();
  ASSERT_GT(evaluate(start).value(CriterionKind::E) - 12.0, 1e-8);  // the perturbation really leaves the limit
  const PolishResult p = polish(start, CriterionKind::E, PolishOptions{50, 40});
  ASSERT_TRUE(p.converged());
  EXPECT_EQ(p.digits, 50);
  EXPECT_LT(p.residual, 1e-60);
  EXPECT_LT(distance_from_twelve(p), mp60("1e-45"));
  EXPECT_EQ(p.value_digits.substr(0, 43), "12." + std::string(40, '0'));
  // A local correction: the polished program is the perturbed one moved by about the perturbation.
  for (int i = 0; i < start.size(); ++i)
    EXPECT_LT((p.program.positions[static_cast<std::size_t>(i)] - start.positions[static_cast<std::size_t>(i)]).norm(),
              1e-4);
  EXPECT_NEAR(evaluate(p.program).value(CriterionKind::E), 12.0, 1e-12);
}

TEST(PolishE, EighteenOptimumShowsTheLimit) {
  const SynthesisResult r = e_optimum(18, 3, 3);
  ASSERT_NEAR(r.value, 12.0, 1e-6);
  const PolishResult p = polish(r.program, CriterionKind::E, PolishOptions{50, 40});
  ASSERT_TRUE(p.converged());
  EXPECT_EQ(p.digits, 50);
  EXPECT_LT(p.residual, 1e-60);
  EXPECT_LT(distance_from_twelve(p), mp60("1e-45"));
}

TEST(PolishE, NineIsAboveTheLimitAndTheSameFromTwoOptima) {
  const SynthesisResult a = e_optimum(9, 32, 5), b = e_optimum(9, 32, 9);
  ASSERT_NEAR(a.value / b.value, 1.0, 1e-8);                  // both multistarts reached the best value
  ASSERT_NE(a.program.positions[0], b.program.positions[0]);  // from different double programs
  const PolishResult pa = polish(a.program, CriterionKind::E, PolishOptions{50, 40});
  const PolishResult pb = polish(b.program, CriterionKind::E, PolishOptions{50, 40});
  ASSERT_TRUE(pa.converged());
  ASSERT_TRUE(pb.converged());
  EXPECT_LT(pa.residual, 1e-60);
  EXPECT_EQ(pa.digits, 50);
  EXPECT_GT(parsed(pa), mp60(12) + mp60("0.1"));  // N = 9 cannot reach the limit
  EXPECT_NEAR(std::stod(pa.value_digits) / a.value, 1.0, 1e-7);
  EXPECT_EQ(pa.value_digits, pb.value_digits);
  // More digits change none of the first 45.
  const PolishResult more = polish(pa.program, CriterionKind::E, PolishOptions{60, 40});
  ASSERT_TRUE(more.converged());
  EXPECT_EQ(more.value_digits.substr(0, 46), pa.value_digits.substr(0, 46));
  // Unpolished, the double optimum claims fewer digits, and those digits are true.
  const PolishResult raw = polish(a.program, CriterionKind::E, PolishOptions{50, 0});
  EXPECT_FALSE(raw.converged());
  EXPECT_EQ(raw.summary.iterations, 0);
  EXPECT_GE(raw.digits, 6);
  EXPECT_LT(raw.digits, 50);
  using boost::multiprecision::abs;
  EXPECT_LT(abs(parsed(raw) - parsed(pa)) / parsed(pa), pow(mp60(10), 1 - raw.digits));
}

TEST(PolishE, ResidualMeasuresTheFirstOrderConditions) {
  // Far from any optimum the conditions fail by a lot, and the digits say so.
  const PolishResult random = polish(Program::random(12, 7), CriterionKind::E, PolishOptions{50, 0});
  EXPECT_FALSE(random.converged());
  EXPECT_GT(random.residual, 1e-4);
  EXPECT_LE(random.digits, 3);
  // The edge program (its positions renormalised at working precision are the exact ones) satisfies
  // them with no Newton step at all.
  const PolishResult edges = polish(Program::octahedral(0, 1, 0), CriterionKind::E, PolishOptions{50, 0});
  EXPECT_TRUE(edges.converged());
  EXPECT_EQ(edges.summary.iterations, 0);
  EXPECT_LT(edges.residual, 1e-100);
  EXPECT_LT(distance_from_twelve(edges), mp60("1e-45"));
  // Perturbed, the residual falls with each step, and the digits claimed on the way are true.
  double previous = 1;
  for (int steps : {0, 1, 2}) {
    const PolishResult p = polish(perturbed_edges(), CriterionKind::E, PolishOptions{50, steps});
    EXPECT_FALSE(p.converged());
    EXPECT_LT(p.residual, previous / 1e3);
    EXPECT_LT(p.digits, 50);
    EXPECT_LT(distance_from_twelve(p), 12 * pow(mp60(10), 1 - p.digits));
    previous = p.residual;
  }
}

// value_digits's text in the polish's MPFR numbers, written by hand: the digits claimed, trailing zeros kept, no bare
// point (MPFR's showpoint alone writes 14.7 to 1 digit as "1.e+01" and 15 to 2 as "15.").
TEST(PolishE, ValueTextHasNoBarePoint) {
  const polish_detail::PrecisionGuard precision(50);
  using Real = polish_detail::Real;
  EXPECT_EQ(value_text(Real(14.7), 1), "1e+01");
  EXPECT_EQ(value_text(Real(15), 2), "15");
  EXPECT_EQ(value_text(Real(15), 5), "15.000");
  EXPECT_EQ(value_text(Real(12.187), 3), "12.2");
  EXPECT_EQ(value_text(Real(0.5), 3), "0.500");
  EXPECT_EQ(value_text(Real(123456), 3), "1.23e+05");
}

}  // namespace
}  // namespace scalcal
