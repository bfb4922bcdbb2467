// The structured Riemannian Hessian (numeric/synthesis/structured_hessian.hpp) against the dense one
// SphereNewton assembles (itself checked against finite differences in sphere_newton_test), its
// inertia against the eigenvalues of that dense matrix, and the confirmation built on it
// (smooth_optimum_check.hpp) at an optimum, off an optimum and at a saddle.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "numeric/synthesis/newton_local.hpp"
#include "numeric/synthesis/smooth_optimum_check.hpp"
#include "numeric/synthesis/sphere_newton.hpp"
#include "numeric/synthesis/structured_hessian.hpp"

namespace scalcal {
namespace {

template <class C>
void dense_model(const Program& p, StructuredHessian<Paper9Model>& H, Eigen::VectorXd& g, Eigen::MatrixXd& dense) {
  double f;
  ASSERT_TRUE(SphereNewton<C>().local_model(p.positions, f, g, dense));
  MatrixDerivatives<double, 9> d;
  ASSERT_TRUE(C::derivatives(information_matrix<Paper9Model>(p.positions), p.size(), d));
  H.assemble(p.positions, d);
}

template <class C>
void expect_same_as_dense(int n, std::uint64_t seed) {
  const Program p = Program::random(n, seed);
  StructuredHessian<Paper9Model> H;
  Eigen::VectorXd g;
  Eigen::MatrixXd dense;
  dense_model<C>(p, H, g, dense);
  EXPECT_LT((H.gradient() - g).norm(), 1e-12 * g.norm());
  EXPECT_LT((H.dense() - dense).norm(), 1e-12 * dense.norm());
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(2 * n, -1.0, 1.3);
  EXPECT_LT((H.apply(t) - dense * t).norm(), 1e-12 * (dense * t).norm());
  // The inertia of H + mu I, and its solves, for shifts on both sides of its smallest eigenvalues.
  const Eigen::VectorXd eig =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly).eigenvalues();
  for (double mu : {-eig(n) - 1e-3, -eig(0) * 0.5, 0.0, -eig(0) + 1e-3, 1.0}) {
    ASSERT_TRUE(H.factor(mu)) << mu;
    int negative = 0;
    for (int k = 0; k < eig.size(); ++k) negative += eig(k) + mu < 0;
    EXPECT_EQ(H.inertia().negative, negative) << "mu " << mu;
    const Eigen::MatrixXd shifted = dense + mu * Eigen::MatrixXd::Identity(2 * n, 2 * n);
    const Eigen::VectorXd x = H.solve(t);
    // Backward error, as for any stable solve: near an eigenvalue (mu = -lambda + 1e-3) the solution
    // is large and the residual scales with |H + mu I| |x|, not with |t|.
    EXPECT_LT((shifted * x - t).norm(), 1e-13 * (shifted.norm() * x.norm() + t.norm())) << "mu " << mu;
  }
}

TEST(StructuredHessian, EqualsSphereNewtonsDenseHessianForD) {
  expect_same_as_dense<DCriterion>(11, 3);
  expect_same_as_dense<DCriterion>(25, 4);
}

TEST(StructuredHessian, EqualsSphereNewtonsDenseHessianForA) {
  expect_same_as_dense<ACriterion>(12, 5);
  expect_same_as_dense<ACriterion>(30, 6);
}

TEST(SmoothOptimumCheck, PassesAtTheOptimaNewtonFinds) {
  for (int n : {12, 18, 30}) {
    const auto d = criterion_ops<DCriterion>();
    const LocalResult r = sphere_local<Paper9Model>(d, Program::random(n, 11), LocalSolver::Newton);
    const SmoothOptimumCheck c = check_smooth_optimum<Paper9Model>(d, r.program);
    EXPECT_TRUE(c.passed()) << n << ": gradient " << c.gradient_norm << " margin " << c.margin;
    const auto a = criterion_ops<ACriterion>();
    const LocalResult s = sphere_local<Paper9Model>(a, Program::random(n, 12), LocalSolver::Lbfgs);
    EXPECT_TRUE(check_smooth_optimum<Paper9Model>(a, s.program).passed()) << n;
  }
}

TEST(SmoothOptimumCheck, FailsOffAnOptimum) {
  const SmoothOptimumCheck c = check_smooth_optimum<Paper9Model>(criterion_ops<DCriterion>(), Program::random(20, 2));
  EXPECT_FALSE(c.first_order);
  EXPECT_FALSE(c.passed());
}

// The cuboctahedron (the 12 edge midpoints of the cube) is a critical point of D by its symmetry,
// above the limit the icosahedron attains at N = 12: a saddle, as the dense Hessian's eigenvalues show.
TEST(SmoothOptimumCheck, FailsAtASaddle) {
  const Program p = Program::octahedral(0, 1, 0);
  ASSERT_EQ(p.size(), 12);
  StructuredHessian<Paper9Model> H;
  Eigen::VectorXd g;
  Eigen::MatrixXd dense;
  dense_model<DCriterion>(p, H, g, dense);
  const double smallest =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly).eigenvalues()(0);
  ASSERT_LT(smallest, -1e-3 * H.mean_diagonal());  // a saddle indeed
  const SmoothOptimumCheck c = check_smooth_optimum<Paper9Model>(criterion_ops<DCriterion>(), p);
  EXPECT_TRUE(c.first_order) << c.gradient_norm;
  EXPECT_FALSE(c.second_order);
}

}  // namespace
}  // namespace scalcal
