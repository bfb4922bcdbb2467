// The integrated rotation and its exact derivative (rotation_integral.hpp).
#include "numeric/gyro/rotation_integral.hpp"

#include <cmath>

namespace scalcal::gyro {

Mat3 skew(const Vec3& v) {
  Mat3 S;
  S << 0, -v(2), v(1), v(2), 0, -v(0), -v(1), v(0), 0;
  return S;
}

Mat3 rotation_exp(const Vec3& phi) {
  const double th2 = phi.squaredNorm(), th = std::sqrt(th2);
  const Mat3 K = skew(phi);
  // Below 1e-4 rad the series to th^4 is exact in double.
  const double a = th < 1e-4 ? 1 - th2 / 6 : std::sin(th) / th;
  const double b = th < 1e-4 ? 0.5 - th2 / 24 : (1 - std::cos(th)) / th2;
  return Mat3::Identity() + a * K + b * K * K;
}

Mat3 right_jacobian(const Vec3& phi) {
  const double th2 = phi.squaredNorm(), th = std::sqrt(th2);
  const Mat3 K = skew(phi);
  const double a = th < 1e-4 ? 0.5 - th2 / 24 : (1 - std::cos(th)) / th2;
  const double b = th < 1e-4 ? 1.0 / 6 - th2 / 120 : (th - std::sin(th)) / (th2 * th);
  return Mat3::Identity() - a * K + b * K * K;
}

RotationIntegral integrate_rotation(const std::vector<Vec3>& raw, const std::vector<double>& t, int begin, int end,
                                    const Mat3& C, const Vec3& o, bool with_derivative) {
  RotationIntegral out;
  if (end <= begin) return out;
  const int steps = end - begin;
  std::vector<Vec3> phi(static_cast<std::size_t>(steps));
  for (int k = 0; k < steps; ++k) {
    const auto i = static_cast<std::size_t>(begin + k);
    const double dt = t[i + 1] - t[i];
    phi[static_cast<std::size_t>(k)] = 0.5 * dt * (C * (raw[i] - o) + C * (raw[i + 1] - o));
  }
  if (!with_derivative) {
    for (const Vec3& p : phi) out.R = out.R * rotation_exp(p);
    return out;
  }
  // Backwards: A = exp[phi_k+1] ... exp[phi_e-1]; step k's perturbation d phi_k moves the end by
  // A^T J_r(phi_k) d phi_k, and d phi_k = (dOmega_k + dOmega_k+1) dt_k / 2 with
  // dOmega_i = dC u_i - C do, u_i = w_i - o. G collects each sample's coefficient.
  Mat3 A = Mat3::Identity();
  Mat3 G_next = Mat3::Zero();  // sample k+1's coefficient from step k+1
  Mat3 G_sum = Mat3::Zero();
  Eigen::Matrix<double, 3, 9> T = Eigen::Matrix<double, 3, 9>::Zero();  // sum_i G_i(:, a) u_i(b) at column 3a + b
  auto add_sample = [&](int i, const Mat3& G) {
    const Vec3 u = raw[static_cast<std::size_t>(i)] - o;
    G_sum += G;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) T.col(3 * a + b) += G.col(a) * u(b);
  };
  for (int k = steps - 1; k >= 0; --k) {
    const auto i = static_cast<std::size_t>(begin + k);
    const double dt = t[i + 1] - t[i];
    const Mat3 B = 0.5 * dt * A.transpose() * right_jacobian(phi[static_cast<std::size_t>(k)]);
    add_sample(begin + k + 1, B + G_next);  // sample k+1 enters steps k and k+1
    G_next = B;
    const Mat3 E = rotation_exp(phi[static_cast<std::size_t>(k)]);
    A = E * A;
  }
  add_sample(begin, G_next);
  out.R = A;
  out.D.leftCols<9>() = T;
  out.D.rightCols<3>() = -G_sum * C;
  return out;
}

}  // namespace scalcal::gyro
