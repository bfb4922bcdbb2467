// One registry: a family defined only here, in this test file (as a user's one small file would be),
// is found by every entry point that takes a program name, by the catalogue and by the synthesis.
#include <gtest/gtest.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/family.hpp"

namespace sym = scalcal::symbolic;

namespace {

// The cuboctahedral example of symbolic/ADDING_A_FAMILY.md, `copies` times over: the 6 axes and the
// 8 diagonals, each repeated.
sym::Family test_family() {
  sym::Family f;
  f.name = "testcubo";
  f.summary = "test-only: the cuboctahedron's 14 face normals, copies times";
  f.pattern = "testcubo-{copies}";
  f.params = {{"copies", "1", "how many times each face is used"}};
  f.points = [](const sym::ParamMap& p) {
    const GiNaC::ex m = p.at("copies");
    std::vector<sym::WeightedPoint> pts;
    for (int axis = 0; axis < 3; ++axis)
      for (int s : {1, -1}) {
        sym::Point v{0, 0, 0};
        v[axis] = s;
        pts.push_back({m, v});
      }
    const GiNaC::ex d = GiNaC::sqrt(GiNaC::ex(3)) / 3;
    for (int s1 : {1, -1})
      for (int s2 : {1, -1})
        for (int s3 : {1, -1}) pts.push_back({m, sym::Point{s1 * d, s2 * d, s3 * d}});
    return pts;
  };
  return f;
}

sym::Family literal_family() {
  sym::Family f = test_family();
  f.name = "testcubo-literal";
  f.pattern = "testcubo-fourteen";
  f.params = {{"copies", "1", "fixed"}};
  f.group = "jig";
  return f;
}

// A registrar as a plug-in's file would have it: registration at start-up, no edit elsewhere.
const bool registered = [] {
  sym::register_family(test_family());
  sym::register_family(literal_family());
  return true;
}();

TEST(TestOnlyFamily, FoundByNameEverywhere) {
  ASSERT_TRUE(registered);
  EXPECT_EQ(sym::find_family("testcubo").name, "testcubo");
  const auto p = scalcal::resolve_program("testcubo-2");
  EXPECT_EQ(p.size(), 28);
  // The hand values of ADDING_A_FAMILY.md (multiplicity does not change normalised criteria).
  const auto ev = scalcal::evaluate(p);
  EXPECT_NEAR(ev.value(scalcal::CriterionKind::D), 992436543.0 / 64, 1e-6);
  EXPECT_NEAR(ev.value(scalcal::CriterionKind::A), 293.0 / 4, 1e-12);
  EXPECT_NEAR(ev.value(scalcal::CriterionKind::E), 63.0 / 4, 1e-12);
  EXPECT_EQ(scalcal::resolve_program("testcubo-fourteen").size(), 14);
  EXPECT_EQ(scalcal::resolve_program("testcubo-1@copies=3").size(), 42);  // @ overrides the pattern's value
}

TEST(TestOnlyFamily, ListedInTheCatalogue) {
  bool literal = false, placeholder = false;
  for (const auto& e : scalcal::catalogue()) {
    literal = literal || e.name == "testcubo-fourteen";
    placeholder = placeholder || e.name.rfind("testcubo-{", 0) == 0;
  }
  EXPECT_TRUE(literal);
  EXPECT_FALSE(placeholder);  // a pattern with parameters has many members, none listed
}

TEST(TestOnlyFamily, ClosedFormsInASymbol) {
  const auto& f = sym::find_family("testcubo");
  const auto inst = f.instance(sym::parse_params(f, {"copies=m"}));
  EXPECT_EQ(sym::canonical_text(inst.N), "14*m");
  const auto c = sym::exact_criteria(inst.M, inst.N);
  EXPECT_EQ(c.at("D").str(), "992436543/64");
}

TEST(TestOnlyFamily, AStartOfTheSynthesis) {
  scalcal::SynthesisOptions o;
  o.positions = 14;
  o.criterion = scalcal::CriterionKind::D;
  o.starts = 1;
  o.threads = 1;
  o.first_start = scalcal::resolve_program("testcubo-1");
  const auto r = scalcal::synthesize(o);
  EXPECT_LE(r.value, 992436543.0 / 64 + 1e-6);  // a local descent from it never ends higher
  EXPECT_GE(r.value, 61509375.0 / 4 - 1e-6);
  o.first_start = scalcal::resolve_program("testcubo-2");
  EXPECT_THROW(scalcal::synthesize(o), std::invalid_argument);  // 28 positions for N = 14
}

TEST(TestOnlyFamily, BadNamesAndValues) {
  EXPECT_THROW(scalcal::resolve_program("testcubo-1@copies=-1"), scalcal::InputError);
  EXPECT_THROW(scalcal::resolve_program("testcubo-1@copies=1/2"), scalcal::InputError);
  EXPECT_THROW(scalcal::resolve_program("testcubo-1@copies=k"), scalcal::InputError);
  EXPECT_THROW(scalcal::resolve_program("testcubo-1@size=2"), scalcal::InputError);
  EXPECT_THROW(scalcal::resolve_program("testcubo-x"), scalcal::InputError);  // neither a name nor a file
  EXPECT_THROW(sym::register_family(test_family()), std::invalid_argument);   // the name is taken
}

}  // namespace
