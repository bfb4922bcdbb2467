// Every derivative the optimiser is given is checked against central differences of the values.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "numeric/synthesis/ipopt_problems.hpp"

namespace scalcal {
namespace {

class Gradients : public ::testing::TestWithParam<CriterionKind> {};

TEST_P(Gradients, MatchCentralDifferences) {
  const int n = 11;
  const auto problem = make_problem(GetParam(), n);
  std::vector<double> x = problem->start(Program::random(n, 7));
  for (std::size_t i = 0; i < 3 * static_cast<std::size_t>(n); ++i)
    x[i] *= 1.0 + 0.01 * std::sin(double(i));  // off the sphere too
  const int nv = problem->variables(), m = problem->constraints();
  double f;
  std::vector<double> grad(static_cast<std::size_t>(nv), 0.0), jac(static_cast<std::size_t>(m * nv), 0.0),
      g(static_cast<std::size_t>(m));
  ASSERT_TRUE(problem->objective(x.data(), f, grad.data()));
  if (m > 0) {
    ASSERT_TRUE(problem->constraint_values(x.data(), g.data(), jac.data()));
  }
  const double h = 1e-6;
  for (int j = 0; j < nv; ++j) {
    std::vector<double> xp = x, xm = x;
    xp[static_cast<std::size_t>(j)] += h;
    xm[static_cast<std::size_t>(j)] -= h;
    double fp, fm;
    ASSERT_TRUE(problem->objective(xp.data(), fp, nullptr));
    ASSERT_TRUE(problem->objective(xm.data(), fm, nullptr));
    const double fd = (fp - fm) / (2 * h);
    EXPECT_NEAR(grad[static_cast<std::size_t>(j)], fd, 1e-6 * (1 + std::abs(fd))) << "objective, variable " << j;
    if (m == 0) continue;
    std::vector<double> gp(static_cast<std::size_t>(m)), gm(static_cast<std::size_t>(m));
    ASSERT_TRUE(problem->constraint_values(xp.data(), gp.data(), nullptr));
    ASSERT_TRUE(problem->constraint_values(xm.data(), gm.data(), nullptr));
    for (int r = 0; r < m; ++r) {
      const double fdr = (gp[static_cast<std::size_t>(r)] - gm[static_cast<std::size_t>(r)]) / (2 * h);
      EXPECT_NEAR(jac[static_cast<std::size_t>(r * nv + j)], fdr, 1e-6 * (1 + std::abs(fdr)))
          << "constraint " << r << ", variable " << j;
    }
  }
}

// The exact Lagrangian Hessians (obj_factor f + sum_r lambda_r g_r) against central differences
// of the exact gradient and constraint Jacobian.
class Hessians : public ::testing::TestWithParam<CriterionKind> {};

TEST_P(Hessians, MatchCentralDifferencesOfTheGradient) {
  const CriterionKind c = GetParam();
  const int n = 10;
  const auto problem = make_problem(c, n);
  std::vector<double> x = problem->start(Program::random(n, 5));
  for (std::size_t i = 0; i < x.size(); ++i) x[i] *= 1.0 + 0.01 * std::cos(double(i));
  const int nv = problem->variables(), m = problem->constraints();
  const double sigma = 0.7;
  std::vector<double> lambda(static_cast<std::size_t>(m));
  for (int r = 0; r < m; ++r) lambda[static_cast<std::size_t>(r)] = std::sin(1.0 + r);
  // grad of the Lagrangian at x
  auto lagrangian_gradient = [&](const std::vector<double>& at, std::vector<double>& out) {
    out.assign(static_cast<std::size_t>(nv), 0.0);
    double f;
    if (!problem->objective(at.data(), f, out.data())) return false;
    for (auto& v : out) v *= sigma;
    if (m == 0) return true;
    std::vector<double> g(static_cast<std::size_t>(m)), jac(static_cast<std::size_t>(m * nv), 0.0);
    if (!problem->constraint_values(at.data(), g.data(), jac.data())) return false;
    for (int r = 0; r < m; ++r)
      for (int j = 0; j < nv; ++j)
        out[static_cast<std::size_t>(j)] +=
            lambda[static_cast<std::size_t>(r)] * jac[static_cast<std::size_t>(r * nv + j)];
    return true;
  };
  {
    std::vector<double> lower(static_cast<std::size_t>(nv * (nv + 1) / 2));
    ASSERT_TRUE(problem->lagrangian_hessian(x.data(), sigma, lambda.data(), lower.data()));
    const double h = 1e-6;
    for (int j = 0; j < nv; ++j) {
      std::vector<double> xp = x, xm = x, gp, gm;
      xp[static_cast<std::size_t>(j)] += h;
      xm[static_cast<std::size_t>(j)] -= h;
      ASSERT_TRUE(lagrangian_gradient(xp, gp));
      ASSERT_TRUE(lagrangian_gradient(xm, gm));
      for (int r = 0; r < nv; ++r) {
        const double fd = (gp[static_cast<std::size_t>(r)] - gm[static_cast<std::size_t>(r)]) / (2 * h);
        const double exact = lower[static_cast<std::size_t>(r >= j ? r * (r + 1) / 2 + j : j * (j + 1) / 2 + r)];
        EXPECT_NEAR(exact, fd, 1e-5 * (1 + std::abs(fd))) << criterion_name(c) << " (" << r << ", " << j << ")";
      }
    }
  }
}

// An entry a problem declares unused is left out of Ipopt's KKT matrix, so it must be zero at every
// x and multiplier: checked at a perturbed random start with multipliers of both signs.
TEST_P(Hessians, DeclaredZerosAreZero) {
  const CriterionKind c = GetParam();
  const int n = 10;
  const auto problem = make_problem(c, n);
  std::vector<double> x = problem->start(Program::random(n, 7));
  for (std::size_t i = 0; i < x.size(); ++i) x[i] *= 1.0 + 0.01 * std::sin(double(i));
  const int nv = problem->variables(), m = problem->constraints();
  std::vector<double> lambda(static_cast<std::size_t>(m)), lower(static_cast<std::size_t>(nv * (nv + 1) / 2));
  for (int r = 0; r < m; ++r) lambda[static_cast<std::size_t>(r)] = std::cos(2.0 + 3 * r);
  ASSERT_TRUE(problem->lagrangian_hessian(x.data(), 0.7, lambda.data(), lower.data()));
  int unused = 0;
  for (int r = 0; r < nv; ++r)
    for (int col = 0; col <= r; ++col)
      if (!problem->hessian_entry_used(r, col)) {
        ++unused;
        EXPECT_EQ(lower[static_cast<std::size_t>(r * (r + 1) / 2 + col)], 0.0)
            << criterion_name(c) << " (" << r << ", " << col << ")";
      }
  // E's position blocks are 3 x 3 and L(a, m) meets only L(b, m): most entries are unused.
  if (c == CriterionKind::E) {
    EXPECT_GT(unused, nv * (nv + 1) / 2 * 3 / 4);
  }
}

INSTANTIATE_TEST_SUITE_P(AllCriteria, Hessians,
                         ::testing::Values(CriterionKind::D, CriterionKind::A, CriterionKind::E, CriterionKind::S));

TEST(Gradients, StartsAreFeasibleForTheReformulations) {
  // E: M/N - s I = L L^T must hold at the start; S: every N K(r,r) <= t.
  for (CriterionKind c : {CriterionKind::E, CriterionKind::S}) {
    const auto problem = make_problem(c, 14);
    const std::vector<double> x = problem->start(Program::random(14, 3));
    std::vector<double> g(static_cast<std::size_t>(problem->constraints()));
    ASSERT_TRUE(problem->constraint_values(x.data(), g.data(), nullptr));
    for (double v : g) {
      if (c == CriterionKind::E)
        EXPECT_NEAR(v, 0.0, 1e-12);
      else
        EXPECT_LE(v, 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllCriteria, Gradients,
                         ::testing::Values(CriterionKind::D, CriterionKind::A, CriterionKind::E, CriterionKind::S));

}  // namespace
}  // namespace scalcal
