// A calibration as a user applies it: physical = matrix (raw - offset) (full_correction.hpp).
#include "numeric/calibration/full_correction.hpp"

#include <cmath>

#include <Eigen/Dense>

namespace scalcal {

FullCorrection correction_of(const Meter& meter) {
  FullCorrection c;
  c.offset = meter.bias;
  c.matrix = meter.gain().inverse();
  c.scale = Vec3::Ones() + meter.scale_deviation;
  c.phi = meter.phi();
  c.nonorthogonality = meter.nonorthogonality();
  return c;
}

std::optional<FullCorrection> canonical_correction(const Mat3& matrix, const Vec3& offset) {
  if (!(std::abs(matrix.determinant()) > 0)) return std::nullopt;
  const Mat3 S = matrix.inverse();   // raw - offset = S I
  const Mat3 W = S * S.transpose();  // what scalar calibration sees: lengths and cosines of the rows
  FullCorrection out;
  out.offset = offset;
  for (int i = 0; i < 3; ++i) out.scale(i) = std::sqrt(W(i, i));
  Mat3 cosines;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) cosines(i, j) = W(i, j) / (out.scale(i) * out.scale(j));
  // Unit rows with phi_kj = phi_jk and the given cosines: Newton on the three off-diagonal phis
  // from phi = cos / 2 (exact to first order).
  const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  Vec3 p(cosines(0, 1) / 2, cosines(1, 2) / 2, cosines(2, 0) / 2);
  const auto axes = [&](const Vec3& q) {
    Mat3 P = Mat3::Zero();
    for (int k = 0; k < 3; ++k) P(pairs[k][0], pairs[k][1]) = P(pairs[k][1], pairs[k][0]) = q(k);
    for (int r = 0; r < 3; ++r) P(r, r) = std::sqrt(std::max(0.0, 1.0 - P.row(r).squaredNorm()));
    return P;
  };
  const auto residual = [&](const Vec3& q) {
    const Mat3 P = axes(q);
    Vec3 f;
    for (int k = 0; k < 3; ++k) f(k) = P.row(pairs[k][0]).dot(P.row(pairs[k][1])) - cosines(pairs[k][0], pairs[k][1]);
    return f;
  };
  for (int it = 0; it < 50; ++it) {
    const Vec3 f = residual(p);
    if (f.cwiseAbs().maxCoeff() < 1e-15) break;
    Mat3 J;
    for (int k = 0; k < 3; ++k) {
      Vec3 q = p;
      const double h = 1e-7;
      q(k) += h;
      J.col(k) = (residual(q) - f) / h;
    }
    p -= J.fullPivLu().solve(f);
  }
  if (!(residual(p).cwiseAbs().maxCoeff() < 1e-12)) return std::nullopt;
  out.phi = axes(p);
  out.nonorthogonality = 2 * p;
  out.matrix = (out.scale.asDiagonal() * out.phi).inverse();
  return out;
}

std::optional<FullCorrection> fit_ellipsoid(const std::vector<Vec3>& means, double magnitude, EllipsoidShape shape) {
  const int n = static_cast<int>(means.size());
  if (n < 4) return std::nullopt;
  // Centred and scaled: raw counts near 32768 would make the normal equations useless.
  Vec3 centre = Vec3::Zero();
  for (const Vec3& m : means) centre += m;
  centre /= n;
  double spread = 0;
  for (const Vec3& m : means) spread += (m - centre).squaredNorm();
  spread = std::sqrt(spread / n);
  if (!(spread > 0)) return std::nullopt;
  std::vector<Vec3> u;
  for (const Vec3& m : means) u.push_back((m - centre) / spread);
  // u^T A u + b^T u = 1: general (a11 a22 a33 a12 a23 a13 b), axis-aligned (a11 a22 a33 b) or a
  // sphere (a b).
  std::vector<EllipsoidShape> tried = {shape};
  if (shape == EllipsoidShape::general) tried.push_back(EllipsoidShape::axis_aligned);
  for (const EllipsoidShape kind : tried) {
    const int k = kind == EllipsoidShape::general ? 9 : kind == EllipsoidShape::axis_aligned ? 6 : 4;
    if (n < k) continue;
    Eigen::MatrixXd X(n, k);
    for (int i = 0; i < n; ++i) {
      const Vec3& v = u[static_cast<std::size_t>(i)];
      if (kind == EllipsoidShape::general)
        X.row(i) << v(0) * v(0), v(1) * v(1), v(2) * v(2), 2 * v(0) * v(1), 2 * v(1) * v(2), 2 * v(0) * v(2), v(0),
            v(1), v(2);
      else if (kind == EllipsoidShape::axis_aligned)
        X.row(i) << v(0) * v(0), v(1) * v(1), v(2) * v(2), v(0), v(1), v(2);
      else
        X.row(i) << v.squaredNorm(), v(0), v(1), v(2);
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
    if (qr.rank() < k) continue;
    const Eigen::VectorXd a = qr.solve(Eigen::VectorXd::Ones(n));
    Mat3 A = Mat3::Zero();
    Vec3 b;
    if (kind == EllipsoidShape::general) {
      A.diagonal() << a(0), a(1), a(2);
      A(0, 1) = A(1, 0) = a(3);
      A(1, 2) = A(2, 1) = a(4);
      A(0, 2) = A(2, 0) = a(5);
      b << a(6), a(7), a(8);
    } else if (kind == EllipsoidShape::axis_aligned) {
      A.diagonal() << a(0), a(1), a(2);
      b << a(3), a(4), a(5);
    } else {
      A.diagonal().setConstant(a(0));
      b << a(1), a(2), a(3);
    }
    Eigen::LLT<Mat3> llt(A);
    if (llt.info() != Eigen::Success) continue;  // not an ellipsoid
    const Vec3 o = -0.5 * llt.solve(b);
    const double r = 1 + o.dot(A * o);  // (u - o)^T A (u - o) = r
    if (!(r > 0)) continue;
    // |L (u - o)| = 1 with L = (A / r)^(1/2), symmetric: the start adds no rotation of its own.
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(A / r);
    const Mat3 L = eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().asDiagonal() * eig.eigenvectors().transpose();
    FullCorrection out;
    out.offset = centre + spread * o;
    out.matrix = (magnitude / spread) * L;
    if (auto canonical = canonical_correction(out.matrix, out.offset)) return canonical;
  }
  return std::nullopt;
}

}  // namespace scalcal
