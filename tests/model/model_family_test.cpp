// family --model: a model's exact moment matrix is built from the family's moments and the model's
// monomials. Checked against the paper's own H^T H (the table in symbolic/model_moments.cpp must
// reproduce design_row), against numeric evaluation of the same program, and against the exact
// values the cubic12 proof states for its attaining programs.
#include <gtest/gtest.h>

#include <ginac/ginac.h>

#include "numeric/criteria/model_evaluation.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/family.hpp"
#include "symbolic/model_moments.hpp"

namespace scalcal {
namespace {

namespace sym = scalcal::symbolic;

sym::FamilyInstance instance(const std::string& name, const std::vector<std::string>& settings) {
  const auto& f = sym::find_family(name);
  return f.instance(sym::parse_params(f, settings));
}

ModelKind model(const char* name) { return *parse_model(name); }

TEST(ModelFamily, Paper9MomentMatrixFromMomentsIsTheFamilysOwnHtH) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"octahedral", {"axes=2", "edges=1", "diagonals=3"}},
      {"octahedral", {"axes=a", "edges=e", "diagonals=d"}},
      {"rotation", {"k=4", "phase=30"}},
      {"rotation", {"k=7", "phase=p"}},
      {"dodecahedral", {}},
      {"icosahedral", {}}};
  for (const auto& [name, settings] : cases) {
    const auto in = instance(name, settings);
    const GiNaC::matrix M = sym::model_moment_matrix(ModelKind::paper9, in.moment);
    for (unsigned r = 0; r < 9; ++r)
      for (unsigned c = 0; c < 9; ++c)
        EXPECT_TRUE(sym::is_zero_exact(M(r, c) - in.M(r, c))) << name << " (" << r << "," << c << ")";
  }
}

TEST(ModelFamily, ExactCriteriaOfEveryModelMatchTheNumericEvaluation) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {"octahedral", {"axes=1", "edges=1", "diagonals=1"}}, {"rotation", {"k=5", "phase=10"}}, {"icosahedral", {}}};
  for (const char* m : {"axis6", "bias3", "cubic12"}) {
    for (const auto& [name, settings] : cases) {
      const auto& f = sym::find_family(name);
      const auto params = sym::parse_params(f, settings);
      const auto in = f.instance(params);
      const ModelKind kind = model(m);
      const auto exact = sym::exact_criteria(sym::model_moment_matrix(kind, in.moment), in.N, sym::model_groups(kind));
      const ModelEvaluation ev = evaluate(kind, *f.numeric(params));
      ASSERT_TRUE(ev.full_rank()) << m << " " << name;
      for (CriterionKind c : kCriteria)
        EXPECT_NEAR(exact.of(c)->number() / ev.value(c), 1.0, 1e-10) << m << " " << name << " " << criterion_name(c);
      EXPECT_EQ(exact.theta_cubic.candidates.empty(), std::string(m) != "cubic12") << m;
      EXPECT_EQ(exact.theta_nonorth.candidates.empty(), std::string(m) != "cubic12") << m;
    }
  }
}

// proofs/cubic12_limits.md: 10 per axis and 9 per cube diagonal attain D exactly, 4 and 3 attain S.
TEST(ModelFamily, Cubic12AttainingOctahedralProgramsGiveTheProvenLimitsExactly) {
  const ModelKind cubic = model("cubic12");
  const auto groups = sym::model_groups(cubic);
  const auto d = instance("octahedral", {"axes=10", "edges=0", "diagonals=9"});
  const auto cd = sym::exact_criteria(sym::model_moment_matrix(cubic, d.moment), d.N, groups);
  EXPECT_TRUE(sym::is_zero_exact(cd.at("D").value() - GiNaC::numeric(4093910627611872177L) / 12800000))
      << cd.at("D").str();
  const auto s = instance("octahedral", {"axes=4", "edges=0", "diagonals=3"});
  const auto cs = sym::exact_criteria(sym::model_moment_matrix(cubic, s.moment), s.N, groups);
  EXPECT_TRUE(sym::is_zero_exact(cs.at("S").value() - 27)) << cs.at("S").str();
}

TEST(ModelFamily, SingularProgramsOfAModelAreRefused) {
  // Six axis positions identify axis6 but not cubic12 (x^3 = x on the axes).
  const auto in = instance("octahedral", {"axes=1", "edges=0", "diagonals=0"});
  const ModelKind cubic = model("cubic12");
  EXPECT_THROW(sym::exact_criteria(sym::model_moment_matrix(cubic, in.moment), in.N, sym::model_groups(cubic)),
               std::invalid_argument);
  const ModelKind axis6 = model("axis6");
  const auto ok = sym::exact_criteria(sym::model_moment_matrix(axis6, in.moment), in.N, sym::model_groups(axis6));
  EXPECT_TRUE(sym::is_zero_exact(ok.at("D").value() - 729));  // the six-position test attains axis6's D limit
}

}  // namespace
}  // namespace scalcal
