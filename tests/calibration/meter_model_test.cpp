// Sign conventions of eq. (2) and the first-order expansion of the norm modulus (eq. 5).
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/calibration/meter_model.hpp"

namespace {

using scalcal::Meter;
using scalcal::Vec3;

TEST(MeterModel, RowsOfPhiAreTheSensitivityAxes) {
  Meter m;
  const double a = 0.01;
  m.misalignment(0, 1) = a;  // phi_xy: sensor x leans towards the y axis
  const Vec3 along_y = m.measure(Vec3(0, 1, 0));
  EXPECT_DOUBLE_EQ(along_y(0), a);                                      // sensor x sees a of a vector along y
  EXPECT_DOUBLE_EQ(along_y(1), 1.0);                                    // sensor y is untouched
  EXPECT_DOUBLE_EQ(m.measure(Vec3(1, 0, 0))(0), std::sqrt(1 - a * a));  // unit axis
  EXPECT_DOUBLE_EQ(m.nonorthogonality()(0), a);
}

TEST(MeterModel, ScaleDeviationIsExactForAUnitAxis) {
  Meter m;
  m.scale_deviation = Vec3(0.02, -0.03, 0.01);
  m.misalignment(2, 0) = 0.05;
  m.misalignment(2, 1) = -0.04;
  const Vec3 axis_z = m.phi().row(2).transpose();
  EXPECT_NEAR(axis_z.norm(), 1.0, 1e-15);
  EXPECT_NEAR(m.measure(axis_z)(2), 1.01, 1e-15);
}

TEST(MeterModel, CompensateInvertsMeasure) {
  Meter m;
  m.bias = Vec3(0.1, -0.2, 0.05);
  m.scale_deviation = Vec3(0.01, 0.02, -0.03);
  m.misalignment << 0, 0.01, -0.02, 0.03, 0, 0.005, -0.01, 0.02, 0;
  const Vec3 I(0.3, -0.5, 0.8);
  EXPECT_LT((m.compensate(m.measure(I)) - I).norm(), 1e-14);
}

// |(E + dK) Phi eta + Delta| - 1 = eta.Delta + sum dk_j eta_j^2 + sum_{k<j} gamma_kj eta_k eta_j
// + O(s^2), written out here by hand rather than through design_row.
TEST(MeterModel, NormModulusIsLinearInXToFirstOrder) {
  for (double s : {1e-3, 1e-4}) {
    Meter m;
    m.bias = s * Vec3(1.0, -2.0, 0.5);
    m.scale_deviation = s * Vec3(-1.5, 0.7, 1.2);
    m.misalignment << 0, 0.9, -0.3, 0.4, 0, 1.1, -0.8, 0.2, 0;
    m.misalignment *= s;
    const double gxy = m.misalignment(0, 1) + m.misalignment(1, 0);
    const double gyz = m.misalignment(1, 2) + m.misalignment(2, 1);
    const double gzx = m.misalignment(2, 0) + m.misalignment(0, 2);
    double worst = 0, typical = 0;
    for (const Vec3& e : {Vec3(1, 2, 3), Vec3(-1, 0.5, 2), Vec3(0.2, -1, -0.4), Vec3(3, -2, 1)}) {
      const Vec3 eta = e.normalized();
      const double x = eta(0), y = eta(1), z = eta(2);
      const double lin = x * m.bias(0) + y * m.bias(1) + z * m.bias(2) + m.scale_deviation(0) * x * x +
                         m.scale_deviation(1) * y * y + m.scale_deviation(2) * z * z + gxy * x * y + gyz * y * z +
                         gzx * z * x;
      const double exact = m.measure(eta).norm() - 1.0;
      worst = std::max(worst, std::abs(exact - lin));
      typical = std::max(typical, std::abs(lin));
    }
    EXPECT_LT(worst, 20 * s * s) << "s = " << s;
    EXPECT_GT(typical, 0.5 * s);  // the first-order part is really there
  }
}

TEST(MeterModel, FromParametersSplitsGammaSymmetrically) {
  scalcal::Vec9 X;
  X << 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 0.02, -0.04, 0.06;
  const Meter m = Meter::from_parameters(X, 9.8);
  EXPECT_DOUBLE_EQ(m.bias(2), 3e-3 * 9.8);
  EXPECT_DOUBLE_EQ(m.misalignment(0, 1), 0.01);
  EXPECT_DOUBLE_EQ(m.misalignment(1, 0), 0.01);
  EXPECT_DOUBLE_EQ(m.misalignment(0, 2), 0.03);  // gamma_zx shared by phi_zx and phi_xz
  EXPECT_LT((m.parameters(9.8) - X).norm(), 1e-17);
}

}  // namespace
