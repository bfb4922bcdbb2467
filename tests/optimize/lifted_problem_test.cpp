// S's lifted program for Ipopt (numeric/synthesis/max_diagonal_lifted.hpp): its Jacobian and
// Lagrangian Hessian against central differences, its declared zeros, its direct Hessian entries
// against the dense lower triangle, a feasible start, and the same optimum as the epigraph over the
// positions from the same start.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/max_diagonal_lifted.hpp"
#include "numeric/synthesis/newton_local.hpp"

namespace scalcal {
namespace {

using Lifted = MaxDiagonalLiftedProblem<Paper9Model>;

std::vector<int> all_rows() { return SCriterion::rows<Paper9Model>(); }

std::vector<double> perturbed_start(const Lifted& problem, int n, std::uint64_t seed) {
  std::vector<double> x = problem.start(Program::random(n, seed));
  for (std::size_t i = 0; i < x.size(); ++i) x[i] *= 1.0 + 0.01 * std::sin(double(i));  // off the constraints
  return x;
}

TEST(LiftedMaxDiagonal, JacobianMatchesCentralDifferences) {
  const int n = 10;
  const Lifted problem(n, all_rows());
  const std::vector<double> x = perturbed_start(problem, n, 7);
  const int nv = problem.variables(), m = problem.constraints();
  std::vector<double> g(static_cast<std::size_t>(m)), jac(static_cast<std::size_t>(m * nv), 0.0);
  ASSERT_TRUE(problem.constraint_values(x.data(), g.data(), jac.data()));
  const double h = 1e-6;
  for (int j = 0; j < nv; ++j) {
    std::vector<double> xp = x, xm = x, gp(static_cast<std::size_t>(m)), gm(static_cast<std::size_t>(m));
    xp[static_cast<std::size_t>(j)] += h;
    xm[static_cast<std::size_t>(j)] -= h;
    ASSERT_TRUE(problem.constraint_values(xp.data(), gp.data(), nullptr));
    ASSERT_TRUE(problem.constraint_values(xm.data(), gm.data(), nullptr));
    for (int r = 0; r < m; ++r) {
      const double fd = (gp[static_cast<std::size_t>(r)] - gm[static_cast<std::size_t>(r)]) / (2 * h);
      EXPECT_NEAR(jac[static_cast<std::size_t>(r * nv + j)], fd, 1e-6 * (1 + std::abs(fd)))
          << "row " << r << ", variable " << j;
    }
  }
}

TEST(LiftedMaxDiagonal, LagrangianHessianMatchesCentralDifferencesAndItsPattern) {
  // Nine random positions give an information matrix that the 1 % perturbation may leave
  // indefinite (the lifted problem is defined only where Y is positive definite): ten, as above.
  const int n = 10;
  const Lifted problem(n, all_rows());
  const std::vector<double> x = perturbed_start(problem, n, 7);
  const int nv = problem.variables(), m = problem.constraints();
  std::vector<double> lambda(static_cast<std::size_t>(m));
  for (int r = 0; r < m; ++r) lambda[static_cast<std::size_t>(r)] = std::sin(1.0 + r);
  auto gradient = [&](const std::vector<double>& at) {
    std::vector<double> out(static_cast<std::size_t>(nv), 0.0), g(static_cast<std::size_t>(m)),
        jac(static_cast<std::size_t>(m * nv), 0.0);
    double f;
    EXPECT_TRUE(problem.objective(at.data(), f, out.data()));
    EXPECT_TRUE(problem.constraint_values(at.data(), g.data(), jac.data()));
    for (int r = 0; r < m; ++r)
      for (int j = 0; j < nv; ++j)
        out[static_cast<std::size_t>(j)] +=
            lambda[static_cast<std::size_t>(r)] * jac[static_cast<std::size_t>(r * nv + j)];
    return out;
  };
  std::vector<double> lower(static_cast<std::size_t>(nv * (nv + 1) / 2));
  ASSERT_TRUE(problem.lagrangian_hessian(x.data(), 1.0, lambda.data(), lower.data()));
  const double h = 1e-6;
  for (int j = 0; j < nv; ++j) {
    std::vector<double> xp = x, xm = x;
    xp[static_cast<std::size_t>(j)] += h;
    xm[static_cast<std::size_t>(j)] -= h;
    const std::vector<double> gp = gradient(xp), gm = gradient(xm);
    for (int r = 0; r < nv; ++r) {
      const double fd = (gp[static_cast<std::size_t>(r)] - gm[static_cast<std::size_t>(r)]) / (2 * h);
      const double exact = lower[static_cast<std::size_t>(r >= j ? r * (r + 1) / 2 + j : j * (j + 1) / 2 + r)];
      EXPECT_NEAR(exact, fd, 1e-5 * (1 + std::abs(fd))) << "(" << r << ", " << j << ")";
    }
  }
  // The entries written straight for Ipopt are the used entries of the dense triangle, in order,
  // and every entry left out is zero.
  std::vector<double> used;
  for (int r = 0; r < nv; ++r)
    for (int c = 0; c <= r; ++c) {
      const double v = lower[static_cast<std::size_t>(r * (r + 1) / 2 + c)];
      if ((r == c && r < 3 * n) || problem.hessian_entry_used(r, c))
        used.push_back(v);
      else
        EXPECT_EQ(v, 0.0) << "(" << r << ", " << c << ")";
    }
  std::vector<double> entries(used.size(), -1.0);
  ASSERT_TRUE(problem.lagrangian_hessian_entries(x.data(), 1.0, lambda.data(), entries.data()));
  EXPECT_EQ(entries, used);
}

TEST(LiftedMaxDiagonal, StartIsFeasible) {
  const int n = 14;
  const Lifted problem(n, all_rows());
  const std::vector<double> x = problem.start(Program::random(n, 3));
  std::vector<double> g(static_cast<std::size_t>(problem.constraints()));
  ASSERT_TRUE(problem.constraint_values(x.data(), g.data(), nullptr));
  for (int q = 0; q < Lifted::Q; ++q) EXPECT_NEAR(g[static_cast<std::size_t>(q)], 0.0, 1e-14);
  for (std::size_t r = Lifted::Q; r < g.size(); ++r) EXPECT_LT(g[r], 0.0);
}

// Both programs from the A optimum of the same random program: the same S to Ipopt's tolerance.
TEST(LiftedMaxDiagonal, SameOptimumAsTheEpigraph) {
  const int n = 24;
  const auto s = criterion_ops<SCriterion>();
  const Program start = optimize_with_newton<ACriterion>(Program::random(n, 9)).program;
  const auto value = [&](const Program& p) { return criterion_value(s, p); };
  const LocalResult lifted = run_ipopt(Lifted(n, all_rows()), start, {}, value);
  const LocalResult epigraph = run_ipopt(MaxDiagonalProblem<Paper9Model>(n, all_rows()), start, {}, value);
  ASSERT_TRUE(lifted.summary.converged()) << lifted.summary.message;
  ASSERT_TRUE(epigraph.summary.converged()) << epigraph.summary.message;
  EXPECT_NEAR(lifted.value / epigraph.value, 1.0, 1e-9);
  EXPECT_NEAR(lifted.value, 6 + 3 * std::sqrt(3.0), 1e-9);  // S's limit, attained at N = 24
}

}  // namespace
}  // namespace scalcal
