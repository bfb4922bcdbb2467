// Measuring and compensating with the linear models' meter, axis by axis (linear_meter.hpp).
#include "numeric/model/linear_meter.hpp"

namespace scalcal {

Vec3 LinearMeter::measure(const Vec3& I) const {
  const Vec3 a = linear.phi() * I;
  Vec3 y;
  for (int i = 0; i < 3; ++i) y(i) = linear.bias(i) + (1 + linear.scale_deviation(i)) * a(i);
  return y;
}

Vec3 LinearMeter::compensate(const Vec3& measured) const {
  Vec3 a;
  for (int i = 0; i < 3; ++i) a(i) = (measured(i) - linear.bias(i)) / (1 + linear.scale_deviation(i));
  return linear.phi().inverse() * a;
}

}  // namespace scalcal
