// Measuring and compensating with cubic12's meter (cubic_meter.hpp).
#include "numeric/model/cubic_meter.hpp"

#include <cmath>
#include <limits>

namespace scalcal {

using Vec12 = Eigen::Matrix<double, 12, 1>;

Vec3 CubicMeter::measure(const Vec3& I) const {
  const Vec3 a = linear.phi() * I;
  Vec3 y;
  for (int i = 0; i < 3; ++i) y(i) = linear.bias(i) + (1 + linear.scale_deviation(i)) * a(i) + cubic(i) * a(i) * a(i);
  return y;
}

Vec3 CubicMeter::compensate(const Vec3& measured) const {
  Vec3 a;
  for (int i = 0; i < 3; ++i) {
    const double r = measured(i) - linear.bias(i), g = 1 + linear.scale_deviation(i);
    const double disc = g * g + 4 * cubic(i) * r;
    // g a + c a^2 = r, the root that tends to r / g as c -> 0, in the form free of cancellation.
    a(i) = disc >= 0 ? 2 * r / (g + std::sqrt(disc)) : std::numeric_limits<double>::quiet_NaN();
  }
  return linear.phi().inverse() * a;
}

Vec12 CubicMeter::parameters(double magnitude) const {
  Vec12 X;
  X << linear.parameters(magnitude), cubic * magnitude;
  return X;
}

CubicMeter CubicMeter::from_parameters(const Vec12& X, double magnitude) {
  CubicMeter m;
  m.linear = Meter::from_parameters(X.head<9>(), magnitude);
  m.cubic = X.tail<3>() / magnitude;
  return m;
}

}  // namespace scalcal
