// The monomial models' rows, Jacobians and curvatures against finite differences and against the
// paper's hand-written model, and a model defined in this one file (a copy of paper9 written as a
// monomial table) running through evaluation and synthesis with no other edit.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {
namespace {

struct Paper9AsMonomials : MonomialModel<Paper9AsMonomials> {
  static constexpr int kParameters = 9;
  static constexpr std::string_view name = "paper9-monomials";
  using meter = Paper9Model::meter;
  static constexpr auto parameter_names = Paper9Model::parameter_names;
  static constexpr auto parameter_groups = Paper9Model::parameter_groups;
  static constexpr std::array<Exponents, 9> exponents = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}}};
};
static_assert(CalibrationModel<Paper9AsMonomials>);

template <class Model>
void expect_derivatives_match_differences(const Vec3& x) {
  const double h = 1e-5;
  const auto J = Model::jacobian(x);
  RowT<Model, double> w;
  for (int r = 0; r < Model::kParameters; ++r) w(r) = 0.3 + 0.1 * r * (r % 2 ? -1 : 1);
  const Mat3 T = Model::curvature(w, x);
  for (int j = 0; j < 3; ++j) {
    Vec3 e = Vec3::Zero();
    e(j) = h;
    const RowT<Model, double> d = (Model::row(Vec3(x + e)) - Model::row(Vec3(x - e))) / (2 * h);
    for (int r = 0; r < Model::kParameters; ++r) EXPECT_NEAR(J(r, j), d(r), 1e-8) << Model::name << " r " << r;
    // Row j of the curvature is the derivative of (w^T J) along x_j.
    const Eigen::Matrix<double, 1, 3> dg =
        (w.transpose() * Model::jacobian(Vec3(x + e)) - w.transpose() * Model::jacobian(Vec3(x - e))) / (2 * h);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(T(j, i), dg(i), 1e-7) << Model::name << " (" << j << "," << i << ")";
  }
}

TEST(MonomialModel, DerivativesAreThoseOfTheRow) {
  const Vec3 x(0.3, -0.5, 0.8);
  expect_derivatives_match_differences<Bias3Model>(x);
  expect_derivatives_match_differences<Axis6Model>(x);
  expect_derivatives_match_differences<Cubic12Model>(x);
  expect_derivatives_match_differences<Paper9AsMonomials>(x);
}

TEST(MonomialModel, CubicRowsAreWhatTheIssueNames) {
  const Vec3 x(0.2, 0.3, -0.4);
  const auto h = Cubic12Model::row(x);
  EXPECT_DOUBLE_EQ(h(9), 0.2 * 0.2 * 0.2);
  EXPECT_DOUBLE_EQ(h(11), -0.4 * 0.4 * 0.4);
  EXPECT_DOUBLE_EQ(h(6), 0.2 * 0.3);
  EXPECT_EQ(Cubic12Model::parameter_names[9], "cubic_x");
}

TEST(MonomialModel, AModelInOneFileMatchesThePapersModel) {
  const Program p = Program::classic18();
  const auto a = evaluate<Paper9AsMonomials>(p);
  const auto b = evaluate(p);
  EXPECT_NEAR(a.value(CriterionKind::D) / b.value(CriterionKind::D), 1.0, 1e-12);
  EXPECT_NEAR(a.value(CriterionKind::A), b.value(CriterionKind::A), 1e-10);
  EXPECT_NEAR(a.value(CriterionKind::S), b.value(CriterionKind::S), 1e-10);
  for (int r = 0; r < 9; ++r)
    EXPECT_EQ(Paper9AsMonomials::row(p.positions[3]).coeff(r), Paper9Model::row(p.positions[3]).coeff(r));
  SynthesisOptions o;
  o.positions = 12;
  o.starts = 2;
  o.threads = 1;
  const SynthesisResult r = (synthesize<DCriterion, Paper9AsMonomials>)(o);
  EXPECT_NEAR(r.value / (61509375.0 / 4), 1.0, 1e-7);  // N = 12 attains the D limit (proofs/d_equality.md)
}

TEST(ModelRegistry, NamesRoundTripAndCountParameters) {
  EXPECT_EQ(model_names(), "paper9|axis6|bias3|cubic12");
  for (int i = 0; i < kModelCount; ++i) EXPECT_EQ(parse_model(model_name(ModelKind(i)))->index(), i);
  EXPECT_FALSE(parse_model("paper10").has_value());
  EXPECT_EQ(model_parameters(*parse_model("cubic12")), 12);
  EXPECT_EQ(model_parameters(*parse_model("axis6")), 6);
}

}  // namespace
}  // namespace scalcal
