// The Riemannian Newton solver: its model (gradient, Hessian) against central differences of the
// criterion along the retraction, the rotation null space of the D Hessian, and convergence to
// the closed-form limits (D = 61509375/4, A = 45 + 18 sqrt 2, proofs/) in double and at 50 digits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "numeric/program/program.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/sphere_newton.hpp"

namespace scalcal {
namespace {

using Real = boost::multiprecision::cpp_bin_float_50;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
using RealVec = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using RealMat = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// The criterion at eta_i(t) = normalise(eta_i + B_i t_i), computed without the solver.
template <class Criterion>
Real pulled_back(const std::vector<Vec3T<Real>>& eta, const RealVec& t) {
  std::vector<Vec3T<Real>> moved(eta.size());
  for (std::size_t i = 0; i < eta.size(); ++i)
    moved[i] = (eta[i] + tangent_basis(eta[i]) * t.segment<2>(2 * static_cast<int>(i))).normalized();
  Real f = 0;
  EXPECT_TRUE(Criterion::objective(information_matrix(moved), static_cast<int>(eta.size()), f));
  return f;
}

// At 50 digits, central differences with h = 1e-15 are accurate to about 1e-28 (gradient) and
// 1e-18 (Hessian), so any error in the model's formulas shows. The program: three D steps from a
// random one, so K is moderately conditioned yet far from any optimum.
template <class Criterion>
void check_model(int n, std::uint64_t seed) {
  std::vector<Vec3> start = Program::random(n, seed).positions;
  SphereNewtonOptions few;
  few.max_iterations = 3;
  SphereNewton<DCriterion>(few).run(start);
  std::vector<Vec3T<Real>> eta;
  for (const auto& e : start) eta.push_back(e.cast<Real>().normalized());
  Real f = 0;
  RealVec g;
  RealMat H;
  ASSERT_TRUE((SphereNewton<Criterion, Paper9Model, Real>().local_model(eta, f, g, H)));
  EXPECT_LT(abs(f - pulled_back<Criterion>(eta, RealVec::Zero(2 * n))), Real(1e-45) * abs(f));
  const Real h("1e-15");
  for (int a = 0; a < 2 * n; ++a) {
    RealVec ea = RealVec::Zero(2 * n);
    ea(a) = h;
    const Real fp = pulled_back<Criterion>(eta, ea), fm = pulled_back<Criterion>(eta, -ea);
    EXPECT_LT(abs(g(a) - (fp - fm) / (2 * h)), Real(1e-20) * (1 + abs(g(a)))) << "gradient " << a;
    EXPECT_LT(abs(H(a, a) - (fp - 2 * f + fm) / (h * h)), Real(1e-12) * (1 + abs(H(a, a)))) << "Hessian " << a;
    for (int b = 0; b < a; ++b) {
      RealVec eb = RealVec::Zero(2 * n);
      eb(b) = h;
      const Real fd = (pulled_back<Criterion>(eta, ea + eb) - pulled_back<Criterion>(eta, ea - eb) -
                       pulled_back<Criterion>(eta, eb - ea) + pulled_back<Criterion>(eta, -ea - eb)) /
                      (4 * h * h);
      EXPECT_LT(abs(H(a, b) - fd), Real(1e-12) * (1 + abs(fd))) << "Hessian " << a << "," << b;
      EXPECT_EQ(H(a, b), H(b, a));
    }
  }
}

TEST(SphereNewton, LogDetModelMatchesDifferences) { check_model<DCriterion>(10, 3); }
TEST(SphereNewton, TraceModelMatchesDifferences) { check_model<ACriterion>(11, 4); }

const double kLimitD = 61509375.0 / 4.0;  // proofs/d_limit.md
const double kLimitA = 45.0 + 18.0 * std::sqrt(2.0);

TEST(SphereNewton, ReachesTheDLimitFromRandomStarts) {
  for (int n : {12, 18, 25})
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      Program p = Program::random(n, seed);
      const SphereNewtonResult r = SphereNewton<DCriterion>().run(p.positions);
      EXPECT_TRUE(r.converged()) << n << " " << seed;
      for (const auto& e : p.positions) EXPECT_NEAR(e.norm(), 1.0, 1e-14);
      EXPECT_NEAR(std::exp(r.value), kLimitD, 1e-9 * kLimitD) << n << " " << seed;
      EXPECT_NEAR(criterion_value(p, CriterionKind::D), kLimitD, 1e-9 * kLimitD);
    }
}

TEST(SphereNewton, ReachesTheALimit) {
  Program p = Program::random(18, 9);
  const SphereNewtonResult r = SphereNewton<ACriterion>().run(p.positions);
  EXPECT_TRUE(r.converged());
  EXPECT_NEAR(r.value, kLimitA, 1e-10 * kLimitA);
}

// D is invariant under rotations, so at a D optimum the three infinitesimal rotations
// eta_i -> w x eta_i are null vectors of the Hessian, and no direction has negative curvature.
TEST(SphereNewton, DHessianIsSingularAlongRotationsAtTheOptimum) {
  Program p = Program::random(13, 2);
  SphereNewton<DCriterion> solver;
  ASSERT_TRUE(solver.run(p.positions).converged());
  double f = 0;
  VecX g;
  MatX H;
  ASSERT_TRUE(solver.local_model(p.positions, f, g, H));
  for (int axis = 0; axis < 3; ++axis) {
    VecX t(2 * p.size());
    for (int i = 0; i < p.size(); ++i) {
      const Vec3& e = p.positions[static_cast<std::size_t>(i)];
      t.segment<2>(2 * i) = tangent_basis(e).transpose() * Vec3::Unit(axis).cross(e);
    }
    EXPECT_LT((H * t).norm(), 1e-6 * t.norm()) << "axis " << axis;
  }
  const Eigen::SelfAdjointEigenSolver<MatX> eig(H);
  EXPECT_GT(eig.eigenvalues()(0), -1e-7);
  EXPECT_GT(eig.eigenvalues()(3), 1e-4);  // N = 13 misses the limit: an isolated optimum up to rotation
}

// The same template at 50 digits: the D limit to 40 places (the double run gives the start).
TEST(SphereNewton, ReachesTheDLimitAt50Digits) {
  Program start = Program::random(12, 5);
  ASSERT_TRUE(SphereNewton<DCriterion>().run(start.positions).converged());
  std::vector<Vec3T<Real>> eta;
  for (const auto& e : start.positions) eta.push_back(e.cast<Real>());
  SphereNewtonOptions options;
  options.gradient_tolerance = 1e-45;
  options.max_iterations = 20;
  const SphereNewtonResult r = SphereNewton<DCriterion, Paper9Model, Real>(options).run(eta);
  EXPECT_TRUE(r.converged()) << r.gradient_norm << " after " << r.iterations << " steps";
  Real value;
  ASSERT_TRUE(DCriterion::objective(information_matrix(eta), 12, value));
  const Real limit = Real(61509375) / 4;
  EXPECT_LT(abs(exp(value) - limit) / limit, Real(1e-40));
}

TEST(SphereNewton, RankDeficientStartIsLeftAlone) {
  Program planar;
  for (int i = 0; i < 12; ++i) planar.positions.emplace_back(std::cos(0.5 * i), std::sin(0.5 * i), 0.0);
  const Program before = planar;
  const SphereNewtonResult r = SphereNewton<DCriterion>().run(planar.positions);
  EXPECT_FALSE(r.converged());
  EXPECT_EQ(r.iterations, 0);
  for (std::size_t i = 0; i < before.positions.size(); ++i)
    EXPECT_LT((planar.positions[i] - before.positions[i]).norm(), 1e-15);
}

}  // namespace
}  // namespace scalcal
