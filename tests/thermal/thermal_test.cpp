// Thermal models (numeric/thermal, Theorem 25): rows, the interval's designs, the product limits and the
// CLI's `limits --model BASE+Tk`, against values derived by hand (k = 1, 2 closed forms; the Lobatto
// points +-1, +-1/sqrt5 for k = 3) and SciPy's (k = 3, A/E/S: Nelder-Mead over symmetric 4-point designs
// in a script independent of scalcal: A 37.5202591774521, E 25, S 16).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/thermal/information_criteria.hpp"
#include "numeric/thermal/interval_design.hpp"
#include "numeric/thermal/product_limits.hpp"
#include "numeric/thermal/thermal_program.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

const double kDs = 61509375.0 / 4;  // paper9's D limit on the sphere (Theorem 2)

TEST(ThermalModel, NamesAndRowsAreTheKroneckerProduct) {
  const auto m = parse_thermal_model("paper9+T2");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->name(), "paper9+T2");
  EXPECT_EQ(m->parameters(), 27);
  const auto names = m->parameter_names();
  EXPECT_EQ(names[9], "bias_x_T1");
  EXPECT_EQ(names[26], "nonorth_zx_T2");
  const Eigen::Vector3d e = Eigen::Vector3d(1, 2, 2) / 3;
  const Eigen::VectorXd h = m->row(e, 0.5);
  // By hand: x = 1/3, y = z = 2/3; the row's zx entry is 2/9, times tau^2 = 1/4 in the last place.
  EXPECT_NEAR(h(8), 2.0 / 9, 1e-15);
  EXPECT_NEAR(h(9), 1.0 / 3 * 0.5, 1e-15);
  EXPECT_NEAR(h(26), 2.0 / 9 * 0.25, 1e-15);
  const auto b = parse_thermal_model("paper9+bias:T3");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->parameters(), 18);
  EXPECT_TRUE(bias_rows_decoupled(*b));
  EXPECT_FALSE(bias_rows_decoupled(*parse_thermal_model("cubic12+bias:T1")));  // x^3 rows couple with x
  EXPECT_FALSE(parse_thermal_model("paper9"));
  EXPECT_THROW(parse_thermal_model("paper9+T9"), std::invalid_argument);
  EXPECT_THROW(parse_thermal_model("paper9+X3"), std::invalid_argument);
  EXPECT_THROW(parse_thermal_model("nosuch+T1"), std::invalid_argument);
}

TEST(ThermalModel, CriteriaAgreeWithTheRegisteredOnesOnTheBaseModel) {
  // The same program through the registered criteria (templated on paper9) and the dynamic ones.
  const Program p = *named_program("random-12-s3");
  const auto ev = evaluate<Paper9Model>(p);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(9, 9);
  for (const auto& e : p.positions) {
    const Eigen::VectorXd h = Paper9Model::row(e);
    m += h * h.transpose();
  }
  m /= p.size();
  for (CriterionKind c : {CriterionKind::D, CriterionKind::A, CriterionKind::E, CriterionKind::S})
    EXPECT_NEAR(*information_criterion(c, m) / ev.value(c), 1, 1e-10) << criterion_name(c);
}

TEST(IntervalDesign, ClosedFormsByHand) {
  const auto d3 = optimal_interval_design(CriterionKind::D, 3);
  ASSERT_TRUE(d3);
  ASSERT_EQ(d3->points.size(), 4u);
  EXPECT_NEAR(d3->points[1], -1 / std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(d3->points[2], 1 / std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(d3->value, 3125.0 / 16, 1e-9);
  EXPECT_NEAR(optimal_interval_design(CriterionKind::D, 2)->value, 27.0 / 4, 1e-12);
  EXPECT_NEAR(optimal_interval_design(CriterionKind::A, 2)->value, 8, 1e-12);
  EXPECT_NEAR(optimal_interval_design(CriterionKind::E, 2)->value, 5, 1e-12);
  EXPECT_NEAR(optimal_interval_design(CriterionKind::S, 2)->value, 4, 1e-12);
  EXPECT_NEAR(optimal_interval_design(CriterionKind::A, 1)->value, 2, 1e-12);
  // k = 3, E and S on T_3's extrema (proven in proofs/thermal_product.md; SciPy's optimiser found 25 and 16 too).
  for (const auto& [c, value] : {std::pair{CriterionKind::E, 25.0}, std::pair{CriterionKind::S, 16.0}}) {
    const auto d = optimal_interval_design(c, 3);
    ASSERT_TRUE(d);
    EXPECT_TRUE(d->closed_form);
    EXPECT_NEAR(d->value, value, 1e-12) << criterion_name(c);
    EXPECT_EQ(d->points, (std::vector<double>{-1, -0.5, 0.5, 1}));
  }
}

TEST(IntervalDesign, NumericalOnesAgreeWithSciPy) {
  const std::vector<std::pair<CriterionKind, double>> expected = {{CriterionKind::A, 37.5202591774521}};
  for (const auto& [c, value] : expected) {
    const auto d = optimal_interval_design(c, 3);
    ASSERT_TRUE(d);
    EXPECT_FALSE(d->closed_form);
    EXPECT_NEAR(d->value / value, 1, 1e-8) << criterion_name(c);
    EXPECT_LE(d->lower_bound, d->value * (1 + 1e-12)) << criterion_name(c);
    EXPECT_GT(d->lower_bound, value * (1 - 1e-3)) << criterion_name(c);  // the bound is near the value
  }
}

TEST(ThermalLimits, ProductOfTheIcosahedronAndTheLobattoPointsAttainsD) {
  const auto m = *parse_thermal_model("paper9+T3");
  const auto l = thermal_limit(CriterionKind::D, m, kDs);
  ASSERT_TRUE(l);
  EXPECT_NEAR(l->value / (std::pow(kDs, 4) * std::pow(3125.0 / 16, 9)), 1, 1e-12);
  const TemperatureRange range{-20, 60};
  const Program ico = *named_program("dodecahedral-12");
  const ThermalProgram p = product_program(ico.positions, l->temperature, {1, 1, 1, 1}, range);
  EXPECT_EQ(p.size(), 48);
  EXPECT_NEAR(p.celsius[0], -20, 1e-12);
  EXPECT_NEAR(p.celsius[12], 20 - 40 / std::sqrt(5.0), 1e-12);
  const double d = *information_criterion(CriterionKind::D, thermal_information(m, range, p));
  EXPECT_NEAR(d / l->value, 1, 1e-9);
  // Any other program does worse: the same positions at four evenly spaced set-points.
  const IntervalDesign even{3, {-1, -1.0 / 3, 1.0 / 3, 1}, {0.25, 0.25, 0.25, 0.25}};
  EXPECT_GT(
      *information_criterion(CriterionKind::D,
                             thermal_information(m, range, product_program(ico.positions, even, {1, 1, 1, 1}, range))),
      l->value * 1.01);
}

TEST(ThermalLimits, BiasOnlyHasDAndANotEAndS) {
  const auto m = *parse_thermal_model("paper9+bias:T1");
  const auto d = thermal_limit(CriterionKind::D, m, kDs);
  ASSERT_TRUE(d);
  EXPECT_NEAR(d->value / (kDs * 27), 1, 1e-12);  // D_1 = 1 for k = 1
  EXPECT_FALSE(thermal_limit(CriterionKind::E, m, 12));
  EXPECT_FALSE(thermal_limit(CriterionKind::S, m, 6 + 3 * std::sqrt(3.0)));
  // The product of the icosahedron (A's limit is not attained by it, but D's is) and +-1 reaches D's value.
  const Program ico = *named_program("dodecahedral-12");
  const TemperatureRange range{0, 40};
  const auto p = product_program(ico.positions, d->temperature, {1, 1}, range);
  EXPECT_NEAR(*information_criterion(CriterionKind::D, thermal_information(m, range, p)) / d->value, 1, 1e-9);
}

TEST(ThermalLimits, EfficientRoundingSumsAndFollowsTheWeights) {
  EXPECT_EQ(efficient_rounding({0.25, 0.5, 0.25}, 4), (std::vector<int>{1, 2, 1}));
  EXPECT_EQ(efficient_rounding({0.2, 0.6, 0.2}, 5), (std::vector<int>{1, 3, 1}));
  const auto n = efficient_rounding({0.15, 0.35, 0.35, 0.15}, 7);
  EXPECT_EQ(n[0] + n[1] + n[2] + n[3], 7);
}

TEST(ThermalCli, LimitsPrintsTheProvenProductAndTheSetPoints) {
  const CliResult r = run_cli({"limits", "--model", "paper9+T3", "--temperature", "-20..60", "--json"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "paper9+T3");
  EXPECT_EQ(j["parameters"], 36);
  EXPECT_EQ(j["D"]["status"], "proven");
  EXPECT_EQ(j["D"]["exact"], "(61509375/4)^4 * (3125/16)^9");
  EXPECT_NEAR(j["D"]["value"].get<double>() / (std::pow(kDs, 4) * std::pow(3125.0 / 16, 9)), 1, 1e-12);
  EXPECT_NEAR(j["D"]["setpoints"][1]["t_c"].get<double>(), 20 - 40 / std::sqrt(5.0), 1e-9);
  // A for k = 3: numerically, the sphere's 45 + 18 sqrt2 times SciPy's 37.5202591774521.
  EXPECT_EQ(j["A"]["status"], "numerical");
  EXPECT_NEAR(j["A"]["value"].get<double>() / ((45 + 18 * std::sqrt(2.0)) * 37.5202591774521), 1, 1e-8);
  const CliResult k2 = run_cli({"limits", "--model", "paper9+T2", "--temperature", "0..50", "--json"});
  ASSERT_EQ(k2.status, 0) << k2.err;
  const auto j2 = nlohmann::json::parse(k2.out);
  EXPECT_EQ(j2["E"]["status"], "proven");
  EXPECT_NEAR(j2["E"]["value"].get<double>(), 12 * 5, 1e-9);  // E_s = 12 (Theorem 4) times E_1 = 5
  EXPECT_NEAR(j2["S"]["value"].get<double>(), (6 + 3 * std::sqrt(3.0)) * 4, 1e-9);
}

TEST(ThermalCli, BadInputIsOneLineAndExitTwo) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"limits", "--model", "paper9+T3"},
        {"limits", "--model", "paper9+T3", "--temperature", "60..-20"},
        {"limits", "--model", "paper9+T9", "--temperature", "0..1"},
        {"limits", "--temperature", "0..40"},
        {"limits", "--model", "axis6+T1", "--temperature", "0..40", "--region", "cap:60"}}) {
    const CliResult r = run_cli(args);
    EXPECT_EQ(r.status, 2) << args[2];
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

}  // namespace
}  // namespace scalcal
