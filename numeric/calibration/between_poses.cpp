// REML for the between-pose variance, and the estimator's covariance under it (between_poses.hpp).
#include "numeric/calibration/between_poses.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace scalcal {

BetweenPoses between_poses(const std::vector<Eigen::VectorXd>& rows, const std::vector<double>& residual,
                           const std::vector<double>& samples, const std::vector<double>& weights, double within) {
  BetweenPoses out;
  out.within = within;
  const auto n = static_cast<Eigen::Index>(rows.size());
  const Eigen::Index P = rows.empty() ? 0 : rows[0].size();
  Eigen::MatrixXd H(n, P);
  Eigen::VectorXd J(n), v0(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    H.row(k) = rows[i].transpose();
    J(k) = residual[i];
    v0(k) = within / samples[i];
  }
  // Fisher scoring on the REML likelihood: with V = diag(s + v0), W = V^-1 and the projection
  // P = W - W H (H^T W H)^-1 H^T W, the score is (J^T P P J - tr P) / 2 and the information tr(P P) / 2.
  double s = std::max(0.0, J.squaredNorm() / static_cast<double>(n - P) - v0.mean());
  for (out.iterations = 1; out.iterations <= 100; ++out.iterations) {
    const Eigen::VectorXd w = (v0.array() + s).inverse();
    const Eigen::MatrixXd WH = w.asDiagonal() * H;
    const Eigen::MatrixXd M = (H.transpose() * WH).ldlt().solve(WH.transpose());  // (H^T W H)^-1 H^T W
    Eigen::MatrixXd Pm = -WH * M;
    Pm.diagonal() += w;
    const Eigen::VectorXd PJ = Pm * J;
    const double score = PJ.squaredNorm() - Pm.trace();
    const double information = Pm.cwiseProduct(Pm.transpose()).sum();
    const double next = std::max(0.0, s + score / information);
    const bool settled = std::abs(next - s) <= 1e-10 * std::max(next, v0.mean()) || (next == 0 && s == 0);
    s = next;
    if (settled) {
      out.converged = true;
      break;
    }
  }
  out.between = s;
  // The estimator's own weights w0: Cov = (H^T W0 H)^-1 H^T W0 V W0 H (H^T W0 H)^-1.
  Eigen::VectorXd w0(n), V = v0.array() + s;
  for (Eigen::Index k = 0; k < n; ++k) w0(k) = weights[static_cast<std::size_t>(k)];
  const Eigen::MatrixXd A = H.transpose() * w0.asDiagonal() * H;
  const Eigen::MatrixXd B = H.transpose() * (w0.array().square() * V.array()).matrix().asDiagonal() * H;
  const Eigen::LDLT<Eigen::MatrixXd> a(A);
  out.covariance = a.solve(a.solve(B).transpose());
  // Standardised residuals: J_k over sqrt(V_k (1 - leverage_k)) with the GLS leverage.
  const Eigen::VectorXd w = V.cwiseInverse();
  const Eigen::MatrixXd G = (H.transpose() * w.asDiagonal() * H).ldlt().solve(Eigen::MatrixXd::Identity(P, P));
  for (Eigen::Index k = 0; k < n; ++k) {
    const double leverage = std::min(w(k) * H.row(k).dot(G * H.row(k).transpose()), 1 - 1e-12);
    out.standardised.push_back(J(k) / std::sqrt(V(k) * (1 - leverage)));
  }
  return out;
}

}  // namespace scalcal
