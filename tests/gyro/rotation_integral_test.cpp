// The integrated rotation against closed forms (a constant rate is exp of rate times time; two
// constant rates one after the other compose) and its derivative against central differences.
#include <cmath>

#include <gtest/gtest.h>

#include "numeric/gyro/rotation_integral.hpp"

namespace scalcal::gyro {
namespace {

TEST(RotationIntegral, ConstantRateIsTheExponential) {
  // Rodrigues by hand: a quarter turn about z.
  const Mat3 Rz = rotation_exp(Vec3(0, 0, M_PI / 2));
  EXPECT_NEAR(Rz(0, 1), -1, 1e-15);
  EXPECT_NEAR(Rz(1, 0), 1, 1e-15);
  EXPECT_NEAR(Rz(2, 2), 1, 1e-15);
  // 101 samples at 0.5 rad/s about (1, 2, 2)/3 for 10 s, raw = 100 + 2000 Omega.
  const Vec3 axis = Vec3(1, 2, 2) / 3;
  std::vector<Vec3> raw;
  std::vector<double> t;
  for (int i = 0; i <= 100; ++i) {
    t.push_back(0.1 * i);
    raw.push_back(Vec3::Constant(100) + 2000 * 0.5 * axis);
  }
  const RotationIntegral I = integrate_rotation(raw, t, 0, 100, Mat3::Identity() / 2000, Vec3::Constant(100), false);
  // exp(5 [axis]) = I + sin 5 K + (1 - cos 5) K^2, K = [axis]x, written out.
  const Mat3 K = skew(axis);
  const Mat3 want = Mat3::Identity() + std::sin(5.0) * K + (1 - std::cos(5.0)) * K * K;
  EXPECT_LT((I.R - want).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(RotationIntegral, SuccessiveRatesCompose) {
  // 1 s about x at 1 rad/s, then 1 s about y at 2 rad/s (the step between carries the mean rate).
  std::vector<Vec3> raw;
  std::vector<double> t;
  for (int i = 0; i <= 10; ++i) t.push_back(0.1 * i), raw.push_back(Vec3(1, 0, 0));
  const Mat3 first = integrate_rotation(raw, t, 0, 10, Mat3::Identity(), Vec3::Zero(), false).R;
  EXPECT_LT((first - rotation_exp(Vec3(1, 0, 0))).cwiseAbs().maxCoeff(), 1e-14);
  std::vector<Vec3> both = raw;
  std::vector<double> tb = t;
  for (int i = 1; i <= 10; ++i) tb.push_back(1 + 0.1 * i), both.push_back(Vec3(0, 2, 0));
  both[10] = Vec3(1, 0, 0);
  // Inserting a zero-length step keeps each half a constant rate.
  tb.insert(tb.begin() + 11, 1.0);
  both.insert(both.begin() + 11, Vec3(0, 2, 0));
  const Mat3 R = integrate_rotation(both, tb, 0, 21, Mat3::Identity(), Vec3::Zero(), false).R;
  const Mat3 want = rotation_exp(Vec3(1, 0, 0)) * rotation_exp(Vec3(0, 2, 0));
  EXPECT_LT((R - want).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(RotationIntegral, DerivativeMatchesCentralDifferences) {
  std::vector<Vec3> raw;
  std::vector<double> t;
  for (int i = 0; i < 200; ++i) {
    const double s = 0.01 * i;
    t.push_back(s + 0.001 * std::sin(7.0 * i));  // uneven steps
    raw.push_back(Vec3(30000 + 3000 * std::sin(3 * s), 31000 + 2500 * std::cos(2 * s), 32000 - 4000 * s));
  }
  Mat3 C;
  C << 2.1e-4, 1e-6, -2e-6, 3e-6, 2.09e-4, 1e-6, -1e-6, 2e-6, 2.12e-4;
  const Vec3 o(31000, 31500, 31000);
  const RotationIntegral I = integrate_rotation(raw, t, 5, 190, C, o, true);
  for (int j = 0; j < kCorrectionParameters; ++j) {
    const double h = j < 9 ? 1e-9 : 1e-3;
    Mat3 Cp = C, Cm = C;
    Vec3 op = o, om = o;
    if (j < 9) {
      Cp(j / 3, j % 3) += h;
      Cm(j / 3, j % 3) -= h;
    } else {
      op(j - 9) += h;
      om(j - 9) -= h;
    }
    const Mat3 Rp = integrate_rotation(raw, t, 5, 190, Cp, op, false).R;
    const Mat3 Rm = integrate_rotation(raw, t, 5, 190, Cm, om, false).R;
    // R^T dR = [theta]x: read theta off the skew part.
    const Mat3 S = I.R.transpose() * (Rp - Rm) / (2 * h);
    const Vec3 theta(S(2, 1), S(0, 2), S(1, 0));
    EXPECT_LT((theta - I.D.col(j)).norm(), 1e-6 * (1 + I.D.col(j).norm())) << "parameter " << j;
  }
}

}  // namespace
}  // namespace scalcal::gyro
