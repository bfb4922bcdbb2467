// A vertex exchange's O(1) criterion values (numeric/criteria/exchange_path.hpp) against the criterion
// computed afresh from M(a) = M + a (u u^T - v v^T) by a factorisation, for D and A: the Woodbury form
// and the direct one agree to rounding, and both refuse an M(a) that is not positive definite.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "numeric/criteria/a_criterion.hpp"
#include "numeric/criteria/d_criterion.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal {
namespace {

using Mat = Eigen::Matrix<double, 9, 9>;
using Vec = Eigen::Matrix<double, 9, 1>;

// A random measure's M (weights summing to 1 on 30 random directions), u and v two of its rows.
struct Case {
  Mat M;
  Vec u, v;
  double w_v;  // v's weight: M(a) stays positive definite for a < w_v
};

Case random_case(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> w01(0.1, 1.0);
  Case c;
  c.M.setZero();
  std::vector<Vec3> x(30);
  std::vector<double> w(30);
  double total = 0;
  for (int i = 0; i < 30; ++i) {
    x[i] = Vec3(g(rng), g(rng), g(rng)).normalized();
    total += w[i] = w01(rng);
  }
  for (int i = 0; i < 30; ++i) {
    const Vec h = Paper9Model::row(x[i]);
    c.M += w[i] / total * h * h.transpose();
  }
  c.u = Paper9Model::row(Vec3(g(rng), g(rng), g(rng)).normalized());
  c.v = Paper9Model::row(x[7]);
  c.w_v = w[7] / total;
  return c;
}

template <class C>
void check_against_factorisation(int seed) {
  std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
  for (int trial = 0; trial < 200; ++trial) {
    const Case c = random_case(rng);
    double at_zero = 0;
    ASSERT_TRUE(C::objective(c.M, 1, at_zero));
    const ExchangePath path = exchange_path<9>(Eigen::LLT<Mat>(c.M), c.u, c.v);
    for (double t : {0.0, 1e-6, 0.1, 0.5, 0.9, 0.999}) {
      const double a = t * c.w_v;
      const Mat Ma = c.M + a * (c.u * c.u.transpose() - c.v * c.v.transpose());
      double direct = 0, along = 0;
      ASSERT_TRUE(C::objective(Ma, 1, direct)) << trial << " " << t;
      ASSERT_TRUE(C::objective_along(path, 1, at_zero, a, along)) << trial << " " << t;
      EXPECT_NEAR(along, direct, 1e-9 * std::max(1.0, std::abs(direct))) << trial << " " << t;
    }
  }
}

TEST(ExchangePath, DeterminantAlongTheExchangeIsTheFactorisations) { check_against_factorisation<DCriterion>(1); }
TEST(ExchangePath, TraceAlongTheExchangeIsTheFactorisations) { check_against_factorisation<ACriterion>(2); }

// Past the point where M(a) loses definiteness (all of v's weight moved and more, with u = 0 so that
// nothing replaces it), both criteria refuse the value, as the factorisation does.
TEST(ExchangePath, RefusesAnIndefiniteM) {
  const Vec v = Vec::Unit(0), u = Vec::Zero();
  const Mat M = Mat::Identity();
  const ExchangePath path = exchange_path<9>(Eigen::LLT<Mat>(M), u, v);
  double out = 0;
  EXPECT_FALSE(DCriterion::objective_along(path, 1, 0.0, 1.5, out));
  EXPECT_FALSE(ACriterion::objective_along(path, 1, 9.0, 1.5, out));
  EXPECT_FALSE(ACriterion::objective(Mat(M - 1.5 * v * v.transpose()), 1, out));
  // Just before it, M(a) is definite and tr K(a) = 8 + 1 / (1 - a).
  ASSERT_TRUE(ACriterion::objective_along(path, 1, 9.0, 0.75, out));
  EXPECT_NEAR(out, 12.0, 1e-12);
  ASSERT_TRUE(DCriterion::objective_along(path, 1, 0.0, 0.75, out));
  EXPECT_NEAR(out, -std::log(0.25), 1e-12);
}

}  // namespace
}  // namespace scalcal
