// Cross-check: every family's closed forms (symbolic/) against the numeric core (numeric
// evaluate on the program built by numeric/program.hpp), two independent derivations.
#include <gtest/gtest.h>

#include <cctype>
#include <ostream>
#include <string>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"

namespace sym = scalcal::symbolic;

namespace {

struct Case {
  std::string family;
  std::vector<std::string> params;
};

// Also read by gtest_discover_tests, which appends the printed parameter to each CTest name.
void PrintTo(const Case& c, std::ostream* os) {
  *os << c.family;
  for (const auto& p : c.params) *os << " " << p;
}

class FamilyVsNumeric : public ::testing::TestWithParam<Case> {};

TEST_P(FamilyVsNumeric, ClosedFormsMatchNumericEvaluation) {
  const auto& f = sym::find_family(GetParam().family);
  const auto p = sym::parse_params(f, GetParam().params);
  const auto inst = f.instance(p);
  const auto c = sym::exact_criteria(inst.M, inst.N);
  const auto program = f.numeric(p);
  ASSERT_TRUE(program.has_value());
  const auto ev = scalcal::evaluate(*program);
  ASSERT_TRUE(ev.full_rank());
  EXPECT_EQ(ev.positions, GiNaC::ex_to<GiNaC::numeric>(inst.N).to_int());
  const double tol = 1e-9;
  EXPECT_NEAR(c.at("D").number() / ev.value(scalcal::CriterionKind::D), 1.0, tol);
  EXPECT_NEAR(c.at("A").number() / ev.value(scalcal::CriterionKind::A), 1.0, tol);
  EXPECT_NEAR(c.at("E").number() / ev.value(scalcal::CriterionKind::E), 1.0, tol);
  EXPECT_NEAR(c.at("S").number() / ev.value(scalcal::CriterionKind::S), 1.0, tol);
  EXPECT_NEAR(c.theta_bias.number() / ev.theta_bias, 1.0, tol);
  EXPECT_NEAR(c.theta_scale.number() / ev.theta_scale, 1.0, tol);
  EXPECT_NEAR(c.theta_nonorth.number() / ev.theta_nonorth, 1.0, tol);
}

INSTANTIATE_TEST_SUITE_P(Families, FamilyVsNumeric,
                         ::testing::Values(Case{"octahedral", {}}, Case{"octahedral", {"axes=1", "edges=2"}},
                                           Case{"octahedral", {"axes=0", "edges=1", "diagonals=1"}},
                                           Case{"octahedral", {"axes=2", "edges=1", "diagonals=3"}},
                                           Case{"octahedral", {"axes=1", "edges=0", "diagonals=1"}},
                                           Case{"rotation", {"k=3"}}, Case{"rotation", {"k=3", "phase=10"}},
                                           Case{"rotation", {"k=4", "phase=10"}}, Case{"rotation", {"k=4", "phase=45"}},
                                           Case{"rotation", {"k=5", "phase=7"}}, Case{"rotation", {"k=6"}},
                                           Case{"rotation", {"k=11", "phase=30"}}, Case{"dodecahedral", {}},
                                           Case{"icosahedral", {}}),
                         // Names from the parameters: without them (and PrintTo) the names held the Case's bytes,
                         // heap pointers included, so CTest's test names changed on every discovery.
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.family;
                           for (const auto& p : info.param.params) name += "_" + p;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

// The octahedral closed form in symbolic multiplicities, evaluated at numbers, equals the exact
// criteria of the numeric-multiplicity member: the closed form is the function it claims to be.
TEST(FamilyClosedForm, OctahedralSymbolicFormSpecialises) {
  const auto& f = sym::find_family("octahedral");
  const auto p = sym::parse_params(f, {"axes=a", "edges=e", "diagonals=d"});
  const auto general = sym::exact_criteria(f.instance(p).M, f.instance(p).N);
  ASSERT_FALSE(general.at("D").resolved());
  const GiNaC::exmap at{{p.at("axes"), 2}, {p.at("edges"), 1}, {p.at("diagonals"), 3}};
  const auto q = sym::parse_params(f, {"axes=2", "edges=1", "diagonals=3"});
  const auto special = sym::exact_criteria(f.instance(q).M, f.instance(q).N);
  EXPECT_TRUE(sym::is_zero_exact(general.at("D").candidates[0].subs(at) - special.at("D").value()));
  EXPECT_TRUE(sym::is_zero_exact(general.at("A").candidates[0].subs(at) - special.at("A").value()));
}

// Hand derivation: octahedral(1, 1, 0) (N = 18) has b = 1/18, so M/N = diag(I/3, Q, I/18) with
// Q eigenvalues 1/3, 1/6, 1/6: D = 27 * 3 * 36 * 18^3 = 17006112, A = 9 + 3 + 12 + 54 = 78.
TEST(FamilyClosedForm, Classic18ByHand) {
  const auto& f = sym::find_family("octahedral");
  const auto in = f.instance(sym::parse_params(f, {}));
  const auto c = sym::exact_criteria(in.M, in.N);
  EXPECT_TRUE(c.at("D").value().is_equal(GiNaC::ex(17006112)));
  EXPECT_TRUE(c.at("A").value().is_equal(GiNaC::ex(78)));
  EXPECT_TRUE(c.at("E").value().is_equal(GiNaC::ex(18)));
}

// For k >= 5 the normalised criteria do not depend on k or the phase (ring sums of degree <= 4
// are exact for k >= 5): b = 1/24, D = 81 / ((5/24)^2 (1/24)^3) = 644972544/25.
TEST(FamilyClosedForm, RotationLargeKCoincide) {
  const auto& f = sym::find_family("rotation");
  for (const char* k : {"k=5", "k=8", "k=40"}) {
    const auto in = f.instance(sym::parse_params(f, {k, "phase=17"}));
    const auto c = sym::exact_criteria(in.M, in.N);
    EXPECT_TRUE(c.at("D").value().is_equal(GiNaC::ex(644972544) / 25)) << k;
    EXPECT_TRUE(c.at("E").value().is_equal(GiNaC::ex(24))) << k;
  }
  const auto k4 = f.instance(sym::parse_params(f, {"k=4", "phase=10"}));
  EXPECT_GT(sym::exact_criteria(k4.M, k4.N).at("D").number(), 644972544.0 / 25 * 1.01);
}

TEST(FamilyRegistry, BadInputIsAnInputError) {
  EXPECT_THROW(sym::find_family("snub"), scalcal::InputError);
  const auto& f = sym::find_family("rotation");
  EXPECT_THROW(sym::parse_params(f, {"kk=3"}), scalcal::InputError);
  EXPECT_THROW(sym::parse_params(f, {"k3"}), scalcal::InputError);
  EXPECT_THROW(f.instance(sym::parse_params(f, {"k=2"})), scalcal::InputError);
  EXPECT_THROW(f.instance(sym::parse_params(f, {"k=4", "phase=p"})), scalcal::InputError);
}

}  // namespace
